!> MSC Adams IMPACT contact: K delta^n + STEP(delta, 0, 0, d_max, C) delta_dot.
!! Registered in landyn_contact; the interface and conventions are in landyn_contact_law.
module landyn_contact_adams_impact
  use landyn_kinds, only: wp
  use landyn_contact_law, only: contact_build_t, contact_state_t, hertz_spring_t, check_hertz_spring, check_damping, &
                                check_damping_depth
  use landyn_friction_law, only: adams_step
  implicit none
  private

  public :: adams_impact_t, build

  !> MSC Adams IMPACT: F = K delta^n + STEP(delta, 0, 0, d_max, C) delta_dot (cubic damping ramp).
  type, extends(hertz_spring_t) :: adams_impact_t
    real(wp) :: damping = 1.0e4_wp                 !! C, full damping [N s/m]
    real(wp) :: penetration = 1.0e-4_wp            !! d_max: penetration of full damping [m]
  contains
    procedure :: normal_force => adams_impact_normal_force
  end type adams_impact_t

contains

  !> The adams_impact law from the &contact input (d_max = damping_depth > 0).
  !! With b%check_only: only the law-dependent checks (see landyn_contact_law).
  subroutine build(b)
    type(contact_build_t), intent(inout) :: b  !! the &contact input, the messages and the law built
    call check_damping_depth(b, needed=.true.)
    if (b%check_only) return
    call check_hertz_spring(b)
    call check_damping(b)
    allocate (b%law, source=adams_impact_t(name='adams_impact', stiffness=b%cfg%stiffness, exponent=b%cfg%exponent, &
                                           damping=b%cfg%damping, penetration=b%cfg%damping_depth))
  end subroutine build

  pure function adams_impact_normal_force(self, delta, delta_dot, state) result(f)
    class(adams_impact_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta              !! penetration [m]
    real(wp), intent(in) :: delta_dot          !! penetration rate [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history (not used by this law)
    real(wp) :: f                              !! normal force, >= 0 [N]
    if (present(state)) f = 0.0_wp   ! the law has no history
    if (delta <= 0.0_wp) then
      f = 0.0_wp
      return
    end if
    f = self%damped_force(delta, adams_step(delta, 0.0_wp, 0.0_wp, self%penetration, self%damping), delta_dot)
  end function adams_impact_normal_force

end module landyn_contact_adams_impact
