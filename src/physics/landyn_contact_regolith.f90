!> Granular soil (regolith, eq. 1): Bekker-type sinkage with drag, stiff elastic unloading below the crater.
module landyn_contact_regolith
  use landyn_kinds, only: wp
  use landyn_contact_law, only: contact_law_t, contact_build_t, contact_state_t
  implicit none
  private

  public :: regolith_t, regolith, build

  !> Granular soil (eq. 1 with a Bekker-type static part). With z the penetration (sinkage) and
  !! z_max the deepest sinkage so far (state%delta_max):
  !!   virgin loading (z >= z_max):  F = K_b z^n_b + alpha max(z_dot, 0)^2
  !!   below z_max:                  F = max(0, K_b z_max^n_b - k_u (z_max - z) + C z_dot)
  !! (the soil does not spring back: unloading and reloading follow a stiff elastic line; C damps it).
  !! The crater is kept after lift-off (the footpad is assumed to come back to the same spot).
  type, extends(contact_law_t) :: regolith_t
    real(wp) :: soil_stiffness = 5.24e5_wp         !! K_b [N/m^soil_exponent]
    real(wp) :: soil_exponent = 1.0_wp             !! n_b [-]
    real(wp) :: drag = 1.0e3_wp                    !! alpha, inertial drag coefficient [kg/m]
    real(wp) :: unload_stiffness = 1.0e8_wp        !! k_u [N/m]
    real(wp) :: damping = 1.0e4_wp                 !! C on the unloading/reloading line [N s/m]
  contains
    procedure :: normal_force => regolith_normal_force            !! virgin curve with drag, or the unloading line [N]
    procedure :: spring_force => regolith_spring_force            !! elastic part, the line K_b z_max^n_b - k_u (z_max - z) >= 0 [N]
    procedure :: elastic_energy => regolith_elastic_energy        !! energy the unloading line gives back [J]
    procedure :: dissipation_power => regolith_dissipation_power  !! sinkage work, drag and damping power [W]
  end type regolith_t

contains

  !> The regolith law from the &contact input.
  subroutine build(b)
    type(contact_build_t), intent(inout) :: b  !! the &contact input, the messages and the law built
    if (.not. b%wanted(depth_needed=.false.)) return
    call b%require_positive('soil_stiffness', b%cfg%soil_stiffness, '')
    call b%require_positive('soil_exponent', b%cfg%soil_exponent, '')
    call b%require_nonnegative('soil_drag', b%cfg%soil_drag, 'kg/m')
    call b%require_positive('soil_unload_stiffness', b%cfg%soil_unload_stiffness, 'N/m')
    call b%require_nonnegative('damping', b%cfg%damping, 'N s/m')
    allocate (b%law, source=regolith(b%cfg%soil_stiffness, b%cfg%soil_exponent, b%cfg%soil_drag, b%cfg%soil_unload_stiffness, &
                                     b%cfg%damping))
  end subroutine build

  !> regolith law with the given parameters (undisturbed soil).
  pure function regolith(soil_stiffness, soil_exponent, drag, unload_stiffness, damping) result(law)
    real(wp), intent(in) :: soil_stiffness    !! K_b [N/m^soil_exponent]
    real(wp), intent(in) :: soil_exponent     !! n_b [-]
    real(wp), intent(in) :: drag              !! alpha [kg/m]
    real(wp), intent(in) :: unload_stiffness  !! k_u, > 0 [N/m]
    real(wp), intent(in) :: damping           !! C [N s/m]
    type(regolith_t) :: law                   !! the law
    law = regolith_t(name='regolith', has_history=.true., soil_stiffness=soil_stiffness, soil_exponent=soil_exponent, &
                     drag=drag, unload_stiffness=unload_stiffness, damping=damping)
  end function regolith

  ! ---------------------------------------------------------------- regolith

  !> Deepest sinkage for the evaluation at delta (robust when update was not called).
  pure function regolith_zmax(delta, state) result(zm)
    real(wp), intent(in) :: delta          !! penetration [m]
    type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
    real(wp) :: zm                         !! max(state%delta_max, delta); delta without a state [m]
    zm = delta
    if (present(state)) zm = max(state%delta_max, delta)
  end function regolith_zmax

  !> Normal force of the regolith law: K_b z^n_b + alpha max(z_dot, 0)^2 on the virgin curve (z >= z_max),
  !! max(0, unloading line + C z_dot) below the deepest sinkage; 0 outside the ground.
  pure function regolith_normal_force(self, delta, delta_dot, state) result(f)
    class(regolith_t), intent(in) :: self  !! the law (the state holds the deepest sinkage)
    real(wp), intent(in) :: delta          !! penetration (sinkage) [m]
    real(wp), intent(in) :: delta_dot      !! penetration rate [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
    real(wp) :: f                          !! normal force, >= 0 [N]
    real(wp) :: zm
    f = 0.0_wp
    if (delta <= 0.0_wp) return
    zm = regolith_zmax(delta, state)
    if (delta >= zm) then
      f = self%soil_stiffness*delta**self%soil_exponent + self%drag*max(delta_dot, 0.0_wp)**2
    else
      f = max(0.0_wp, unloading_line(self, delta, zm) + self%damping*delta_dot)
    end if
  end function regolith_normal_force

  !> Elastic part: the virgin curve at the deepest sinkage, the unloading line below it.
  pure function regolith_spring_force(self, delta, state) result(f)
    class(regolith_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta          !! penetration [m]
    type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
    real(wp) :: f                          !! elastic force [N]
    f = 0.0_wp
    if (delta > 0.0_wp) f = max(0.0_wp, unloading_line(self, delta, regolith_zmax(delta, state)))
  end function regolith_spring_force

  !> The stiff elastic line below the deepest sinkage: K_b z_max^n_b - k_u (z_max - z).
  pure function unloading_line(self, delta, zm) result(f)
    class(regolith_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta          !! penetration, > 0 [m]
    real(wp), intent(in) :: zm             !! deepest sinkage, >= delta [m]
    real(wp) :: f                          !! elastic force on the line, may be < 0 [N]
    f = self%soil_stiffness*zm**self%soil_exponent - self%unload_stiffness*(zm - delta)
  end function unloading_line

  !> Energy the unloading line would give back: f_el^2 / (2 k_u).
  pure function regolith_elastic_energy(self, delta, state) result(e)
    class(regolith_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta          !! penetration [m]
    type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
    real(wp) :: e                          !! recoverable elastic energy [J]
    e = self%spring_force(delta, state)**2/(2.0_wp*self%unload_stiffness)
  end function regolith_elastic_energy

  !> F delta_dot - dE/dt: plastic sinkage work and drag on the virgin curve, damping below it.
  pure function regolith_dissipation_power(self, delta, delta_dot, state) result(p)
    class(regolith_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta          !! penetration [m]
    real(wp), intent(in) :: delta_dot      !! penetration rate [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
    real(wp) :: p                          !! dissipated power [W]
    real(wp) :: f_el, de_dt, zm
    f_el = self%spring_force(delta, state)
    zm = regolith_zmax(delta, state)
    if (delta <= 0.0_wp) then
      de_dt = 0.0_wp
    else if (delta >= zm) then
      ! E = F_p(z)^2 / (2 k_u) along the virgin curve
      de_dt = f_el*self%soil_stiffness*self%soil_exponent*delta**(self%soil_exponent - 1.0_wp)*delta_dot &
              /self%unload_stiffness
    else
      de_dt = f_el*delta_dot
    end if
    p = self%normal_force(delta, delta_dot, state)*delta_dot - de_dt
  end function regolith_dissipation_power

end module landyn_contact_regolith
