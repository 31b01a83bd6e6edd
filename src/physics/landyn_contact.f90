!> Footpad-ground normal contact laws (paper eqs. 1, 17-18, section 4.1, Tables 4-5).
!!
!! Conventions
!! - delta is the penetration of the footpad into the ground along the local surface normal
!!   (landyn_terrain: delta > 0 inside the ground), delta_dot = d(delta)/dt (> 0 when moving deeper).
!! - normal_force returns the magnitude F_Z >= 0 of the force the ground exerts on the footpad
!!   along the OUTWARD normal n. It is zero for delta <= 0 and never pulls (every law is clamped
!!   at 0, also where the printed formula would pull).
!! - elastic_energy is the energy stored in the conservative (spring) part, E(delta) with
!!   dE/d(delta) = spring_force(delta). dissipation_power = F_Z delta_dot - dE/dt is the power the
!!   contact removes from the mechanical system, so that
!!       integral(F_Z * delta_dot dt) = E(delta) + integral(dissipation_power dt)
!!   (the work done on the ground) closes the energy audit. For laws whose spring part depends on
!!   delta only, dissipation_power = (F_Z - spring_force) * delta_dot.
!!
!! Laws (chosen by &contact law, parameters from contact_cfg_t; K = stiffness, n = exponent):
!!   base                  K delta^n + kappa C delta_dot, kappa = min(delta/D1, 1)        (eq. 18)
!!   adams_impact          K delta^n + STEP(delta, 0, 0, d_max, C) delta_dot  (MSC Adams IMPACT)
!!   hertz                 K delta^n                                                  (Table 4)
!!   kelvin_voigt          K delta^n + D delta_dot                                    (Table 4)
!!   kelvin_voigt_step     K delta^n + D delta_dot for delta <= d, K delta^n beyond   (Table 4)
!!   kelvin_voigt_bilinear K delta^n + D1 delta_dot + D2 delta_dot |delta_dot|          (Table 4)
!!   hunt_crossley         K delta^n (1 + lambda delta_dot), lambda = chi/K           (Table 4)
!!   regolith              K_b z^n_b + alpha v^2 while sinking deeper, stiff elastic
!!                         unloading/reloading below the deepest sinkage               (eq. 1)
!! with d_max = d = D1 = damping_depth, C = D = D1 = damping, D2 = damping2.
!!
!! History. Hunt-Crossley needs the impact velocity of the current contact and the regolith law
!! the deepest sinkage reached: such laws set `has_history` and read a `contact_state_t`, the
!! contact history of one footpad, passed to every evaluation. The laws themselves are immutable
!! parameter objects (one instance serves all footpads): the state belongs to the model state, and
!! `advance_contact_state(state, delta, delta_dot)` moves it on, called by the integrator only when
!! it commits a step; laws without history ignore the state, so their cost is unchanged. Every
!! evaluation is a pure function of (delta, delta_dot, state) and the law. Without a state the
!! history laws evaluate as on a fresh contact (no recorded impact, no deeper crater).
!!
!! Adding a law: extend contact_law_t (or hertz_spring_t) in this module, implement the deferred
!! procedures (pure, allocation-free), add its name to contact_law_names and a `case` to
!! make_contact_law.
module landyn_contact
  use landyn_kinds, only: wp
  use landyn_config, only: contact_cfg_t, name_len
  use landyn_friction, only: adams_step
  use landyn_strings, only: lower_case
  implicit none
  private

  public :: contact_law_t, contact_state_t, hertz_spring_t
  public :: base_contact_t, adams_impact_t, hertz_contact_t, kelvin_voigt_t, kelvin_voigt_step_t, &
            kelvin_voigt_bilinear_t, hunt_crossley_t, regolith_t
  public :: base_contact, adams_impact, hertz_contact, kelvin_voigt, kelvin_voigt_step, kelvin_voigt_bilinear, &
            hunt_crossley, regolith
  public :: make_contact_law, advance_contact_state
  public :: contact_law_names

  !> Names accepted in &contact law, for messages and documentation.
  character(len=*), parameter :: contact_law_names = 'base, adams_impact, hertz, kelvin_voigt, kelvin_voigt_step, '// &
                                                     'kelvin_voigt_bilinear, hunt_crossley, regolith'

  !> Contact history of one footpad (used by laws with has_history only).
  type :: contact_state_t
    logical :: touching = .false.     !! in contact (delta > 0) at the last update [-]
    real(wp) :: v_impact = 0.0_wp     !! penetration rate at the first step of the current contact [m/s]
    real(wp) :: delta_max = 0.0_wp    !! deepest penetration reached so far; kept after lift-off [m]
  end type contact_state_t

  !> A footpad-ground normal contact law: immutable parameters (the history is a contact_state_t).
  type, abstract :: contact_law_t
    character(len=name_len) :: name = ''  !! law name as given in &contact law [-]
    logical :: has_history = .false.      !! the law reads a contact_state_t: advance it once per step [-]
  contains
    procedure(normal_force_i), deferred :: normal_force
    procedure(spring_force_i), deferred :: spring_force
    procedure(elastic_energy_i), deferred :: elastic_energy
    procedure :: dissipation_power
  end type contact_law_t

  abstract interface
    !> Normal force magnitude F_Z >= 0 along the outward surface normal.
    pure function normal_force_i(self, delta, delta_dot, state) result(f)
      import :: contact_law_t, contact_state_t, wp
      class(contact_law_t), intent(in) :: self  !! the law
      real(wp), intent(in) :: delta             !! penetration, > 0 inside the ground [m]
      real(wp), intent(in) :: delta_dot         !! penetration rate, > 0 moving deeper [m/s]
      type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
      real(wp) :: f                             !! normal force, >= 0 [N]
    end function normal_force_i

    !> Conservative (spring) part of the normal force, dE/d(delta).
    pure function spring_force_i(self, delta, state) result(f)
      import :: contact_law_t, contact_state_t, wp
      class(contact_law_t), intent(in) :: self  !! the law
      real(wp), intent(in) :: delta             !! penetration [m]
      type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
      real(wp) :: f                             !! spring force [N]
    end function spring_force_i

    !> Energy stored in the spring part at penetration delta (0 for delta <= 0).
    pure function elastic_energy_i(self, delta, state) result(e)
      import :: contact_law_t, contact_state_t, wp
      class(contact_law_t), intent(in) :: self  !! the law
      real(wp), intent(in) :: delta             !! penetration [m]
      type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
      real(wp) :: e                             !! stored elastic energy [J]
    end function elastic_energy_i
  end interface

  !> Laws whose spring part is K delta^n (all but regolith).
  type, abstract, extends(contact_law_t) :: hertz_spring_t
    real(wp) :: stiffness = 3.16227766016838e9_wp  !! K [N/m^exponent]
    real(wp) :: exponent = 1.5_wp                  !! n [-]
  contains
    procedure :: spring_force => hertz_spring_force
    procedure :: elastic_energy => hertz_elastic_energy
  end type hertz_spring_t

  !> Base law of the paper (eq. 18): F_Z = K delta^n + kappa C delta_dot, kappa = min(delta/D1, 1),
  !! F_Z = 0 for delta <= 0, clamped at 0 (never pulls).
  type, extends(hertz_spring_t) :: base_contact_t
    real(wp) :: damping = 1.0e4_wp                 !! C_g [N s/m]
    real(wp) :: damping_depth = 1.0e-4_wp          !! D1: penetration at which full damping applies [m]; 0: no ramp
  contains
    procedure :: normal_force => base_normal_force
  end type base_contact_t

  !> MSC Adams IMPACT: F = K delta^n + STEP(delta, 0, 0, d_max, C) delta_dot (cubic damping ramp).
  type, extends(hertz_spring_t) :: adams_impact_t
    real(wp) :: damping = 1.0e4_wp                 !! C, full damping [N s/m]
    real(wp) :: penetration = 1.0e-4_wp            !! d_max: penetration of full damping [m]
  contains
    procedure :: normal_force => adams_impact_normal_force
  end type adams_impact_t

  !> Hertz contact: F = K delta^n (Table 4).
  type, extends(hertz_spring_t) :: hertz_contact_t
  contains
    procedure :: normal_force => hertz_normal_force
  end type hertz_contact_t

  !> Hertz contact + linear damping (Kelvin-Voigt): F = K delta^n + D delta_dot.
  type, extends(hertz_spring_t) :: kelvin_voigt_t
    real(wp) :: damping = 1.0e4_wp                 !! D [N s/m]
  contains
    procedure :: normal_force => kelvin_voigt_normal_force
  end type kelvin_voigt_t

  !> Hertz contact + step damping (Kelvin-Voigt 1): damping D only for delta <= d.
  type, extends(hertz_spring_t) :: kelvin_voigt_step_t
    real(wp) :: damping = 1.0e4_wp                 !! D [N s/m]
    real(wp) :: step_depth = 1.0e-4_wp             !! d: penetration beyond which the damping is off [m]
  contains
    procedure :: normal_force => kelvin_voigt_step_normal_force
  end type kelvin_voigt_step_t

  !> Hertz contact + bilinear damping (Kelvin-Voigt 2): F = K delta^n + D1 delta_dot + D2 delta_dot |delta_dot|.
  type, extends(hertz_spring_t) :: kelvin_voigt_bilinear_t
    real(wp) :: damping = 1.0e4_wp                 !! D1 [N s/m]
    real(wp) :: damping2 = 1.0e4_wp                !! D2 [N s^2/m^2]
  contains
    procedure :: normal_force => kelvin_voigt_bilinear_normal_force
  end type kelvin_voigt_bilinear_t

  !> Hertz contact + hysteresis damping (Hunt-Crossley): F = K delta^n + chi delta^n delta_dot.
  !! chi = 3 K (1 - e) / (2 v), v = max(v_impact, min_impact_speed); with alpha > 0 (the paper's
  !! Table 4 footnote) e = max(0, 1 - alpha v), i.e. chi = 1.5 alpha K while alpha v <= 1.
  type, extends(hertz_spring_t) :: hunt_crossley_t
    real(wp) :: restitution = 0.5_wp               !! e, used when alpha = 0 [-]
    real(wp) :: alpha = 0.0_wp                     !! alpha of c_r = 1 - alpha v_impact; 0: constant e [s/m]
    real(wp) :: min_impact_speed = 0.1_wp          !! floor of the impact speed in chi [m/s]
  contains
    procedure :: normal_force => hunt_crossley_normal_force
  end type hunt_crossley_t

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
    procedure :: normal_force => regolith_normal_force
    procedure :: spring_force => regolith_spring_force
    procedure :: elastic_energy => regolith_elastic_energy
    procedure :: dissipation_power => regolith_dissipation_power
  end type regolith_t

contains

  !> Build the law named by cfg%law (case-insensitive) from the &contact input.
  !! stat /= 0 and errmsg set for an unknown name or invalid parameters (law is then unallocated).
  subroutine make_contact_law(cfg, law, stat, errmsg)
    type(contact_cfg_t), intent(in) :: cfg                       !! resolved &contact input
    class(contact_law_t), allocatable, intent(out) :: law        !! the law
    integer, intent(out) :: stat                                 !! 0 on success
    character(len=*), intent(out) :: errmsg                      !! reason of a failure, '' on success
    character(len=name_len) :: key

    stat = 0
    errmsg = ''
    key = lower_case(trim(adjustl(cfg%law)))
    select case (key)
    case ('base', 'adams_impact', 'hertz', 'kelvin_voigt', 'kelvin_voigt_step', 'kelvin_voigt_bilinear', &
          'hunt_crossley')
      if (.not. (cfg%stiffness > 0.0_wp .and. cfg%stiffness <= huge(1.0_wp))) then
        call fail('&contact stiffness must be a finite number > 0')
      else if (.not. (cfg%exponent > 0.0_wp .and. cfg%exponent <= huge(1.0_wp))) then
        call fail('&contact exponent must be a finite number > 0')
      else if (.not. (cfg%damping >= 0.0_wp .and. cfg%damping <= huge(1.0_wp))) then
        call fail('&contact damping must be a finite number >= 0')
      else if (.not. (cfg%damping_depth >= 0.0_wp .and. cfg%damping_depth <= huge(1.0_wp))) then
        call fail('&contact damping_depth must be a finite number >= 0')
      end if
      if (stat /= 0) return
      select case (key)
      case ('base')
        allocate (law, source=base_contact(cfg%stiffness, cfg%exponent, cfg%damping, cfg%damping_depth))
      case ('adams_impact')
        if (.not. (cfg%damping_depth > 0.0_wp)) then
          call fail('&contact damping_depth (d_max of adams_impact) must be > 0')
        else
          allocate (law, source=adams_impact(cfg%stiffness, cfg%exponent, cfg%damping, cfg%damping_depth))
        end if
      case ('hertz')
        allocate (law, source=hertz_contact(cfg%stiffness, cfg%exponent))
      case ('kelvin_voigt')
        allocate (law, source=kelvin_voigt(cfg%stiffness, cfg%exponent, cfg%damping))
      case ('kelvin_voigt_step')
        allocate (law, source=kelvin_voigt_step(cfg%stiffness, cfg%exponent, cfg%damping, cfg%damping_depth))
      case ('kelvin_voigt_bilinear')
        if (.not. (cfg%damping2 >= 0.0_wp .and. cfg%damping2 <= huge(1.0_wp))) then
          call fail('&contact damping2 must be a finite number >= 0')
        else
          allocate (law, source=kelvin_voigt_bilinear(cfg%stiffness, cfg%exponent, cfg%damping, cfg%damping2))
        end if
      case default   ! hunt_crossley
        if (.not. (cfg%restitution >= 0.0_wp .and. cfg%restitution <= 1.0_wp)) then
          call fail('&contact restitution must lie in [0, 1]')
        else if (.not. (cfg%hc_alpha >= 0.0_wp .and. cfg%hc_alpha <= huge(1.0_wp))) then
          call fail('&contact hc_alpha must be a finite number >= 0')
        else if (.not. (cfg%min_impact_speed > 0.0_wp .and. cfg%min_impact_speed <= huge(1.0_wp))) then
          call fail('&contact min_impact_speed must be a finite number > 0')
        else
          allocate (law, source=hunt_crossley(cfg%stiffness, cfg%exponent, cfg%restitution, cfg%hc_alpha, &
                                              cfg%min_impact_speed))
        end if
      end select
    case ('regolith')
      if (.not. (cfg%soil_stiffness > 0.0_wp .and. cfg%soil_stiffness <= huge(1.0_wp))) then
        call fail('&contact soil_stiffness must be a finite number > 0')
      else if (.not. (cfg%soil_exponent > 0.0_wp .and. cfg%soil_exponent <= huge(1.0_wp))) then
        call fail('&contact soil_exponent must be a finite number > 0')
      else if (.not. (cfg%soil_drag >= 0.0_wp .and. cfg%soil_drag <= huge(1.0_wp))) then
        call fail('&contact soil_drag must be a finite number >= 0')
      else if (.not. (cfg%soil_unload_stiffness > 0.0_wp .and. cfg%soil_unload_stiffness <= huge(1.0_wp))) then
        call fail('&contact soil_unload_stiffness must be a finite number > 0')
      else if (.not. (cfg%damping >= 0.0_wp .and. cfg%damping <= huge(1.0_wp))) then
        call fail('&contact damping must be a finite number >= 0')
      else
        allocate (law, source=regolith(cfg%soil_stiffness, cfg%soil_exponent, cfg%soil_drag, &
                                       cfg%soil_unload_stiffness, cfg%damping))
      end if
    case default
      call fail("&contact law = '"//trim(adjustl(cfg%law))//"' is not known; known laws: "//contact_law_names)
    end select

  contains

    subroutine fail(msg)
      character(len=*), intent(in) :: msg  !! error message
      stat = 1
      errmsg = msg
    end subroutine fail

  end subroutine make_contact_law

  ! ---------------------------------------------------------------- constructors

  !> Base law with the given parameters.
  pure function base_contact(stiffness, exponent, damping, damping_depth) result(law)
    real(wp), intent(in) :: stiffness      !! K_g [N/m^exponent]
    real(wp), intent(in) :: exponent       !! n [-]
    real(wp), intent(in) :: damping        !! C_g [N s/m]
    real(wp), intent(in) :: damping_depth  !! D1 [m]
    type(base_contact_t) :: law            !! the law
    law%name = 'base'
    law%stiffness = stiffness
    law%exponent = exponent
    law%damping = damping
    law%damping_depth = damping_depth
  end function base_contact

  !> adams_impact law with the given parameters (penetration > 0).
  pure function adams_impact(stiffness, exponent, damping, penetration) result(law)
    real(wp), intent(in) :: stiffness      !! K [N/m^exponent]
    real(wp), intent(in) :: exponent       !! n [-]
    real(wp), intent(in) :: damping        !! C [N s/m]
    real(wp), intent(in) :: penetration    !! d_max [m]
    type(adams_impact_t) :: law            !! the law
    law%name = 'adams_impact'
    law%stiffness = stiffness
    law%exponent = exponent
    law%damping = damping
    law%penetration = penetration
  end function adams_impact

  !> hertz law with the given parameters.
  pure function hertz_contact(stiffness, exponent) result(law)
    real(wp), intent(in) :: stiffness      !! K [N/m^exponent]
    real(wp), intent(in) :: exponent       !! n [-]
    type(hertz_contact_t) :: law           !! the law
    law%name = 'hertz'
    law%stiffness = stiffness
    law%exponent = exponent
  end function hertz_contact

  !> kelvin_voigt law with the given parameters.
  pure function kelvin_voigt(stiffness, exponent, damping) result(law)
    real(wp), intent(in) :: stiffness      !! K [N/m^exponent]
    real(wp), intent(in) :: exponent       !! n [-]
    real(wp), intent(in) :: damping        !! D [N s/m]
    type(kelvin_voigt_t) :: law            !! the law
    law%name = 'kelvin_voigt'
    law%stiffness = stiffness
    law%exponent = exponent
    law%damping = damping
  end function kelvin_voigt

  !> kelvin_voigt_step law with the given parameters.
  pure function kelvin_voigt_step(stiffness, exponent, damping, step_depth) result(law)
    real(wp), intent(in) :: stiffness      !! K [N/m^exponent]
    real(wp), intent(in) :: exponent       !! n [-]
    real(wp), intent(in) :: damping        !! D [N s/m]
    real(wp), intent(in) :: step_depth     !! d [m]
    type(kelvin_voigt_step_t) :: law       !! the law
    law%name = 'kelvin_voigt_step'
    law%stiffness = stiffness
    law%exponent = exponent
    law%damping = damping
    law%step_depth = step_depth
  end function kelvin_voigt_step

  !> kelvin_voigt_bilinear law with the given parameters.
  pure function kelvin_voigt_bilinear(stiffness, exponent, damping, damping2) result(law)
    real(wp), intent(in) :: stiffness      !! K [N/m^exponent]
    real(wp), intent(in) :: exponent       !! n [-]
    real(wp), intent(in) :: damping        !! D1 [N s/m]
    real(wp), intent(in) :: damping2       !! D2 [N s^2/m^2]
    type(kelvin_voigt_bilinear_t) :: law   !! the law
    law%name = 'kelvin_voigt_bilinear'
    law%stiffness = stiffness
    law%exponent = exponent
    law%damping = damping
    law%damping2 = damping2
  end function kelvin_voigt_bilinear

  !> hunt_crossley law with the given parameters (a fresh contact history).
  pure function hunt_crossley(stiffness, exponent, restitution, alpha, min_impact_speed) result(law)
    real(wp), intent(in) :: stiffness         !! K [N/m^exponent]
    real(wp), intent(in) :: exponent          !! n [-]
    real(wp), intent(in) :: restitution       !! e, used when alpha = 0 [-]
    real(wp), intent(in) :: alpha             !! alpha of c_r = 1 - alpha v_impact, 0: constant e [s/m]
    real(wp), intent(in) :: min_impact_speed  !! floor of the impact speed, > 0 [m/s]
    type(hunt_crossley_t) :: law              !! the law
    law%name = 'hunt_crossley'
    law%has_history = .true.
    law%stiffness = stiffness
    law%exponent = exponent
    law%restitution = restitution
    law%alpha = alpha
    law%min_impact_speed = min_impact_speed
  end function hunt_crossley

  !> regolith law with the given parameters (undisturbed soil).
  pure function regolith(soil_stiffness, soil_exponent, drag, unload_stiffness, damping) result(law)
    real(wp), intent(in) :: soil_stiffness    !! K_b [N/m^soil_exponent]
    real(wp), intent(in) :: soil_exponent     !! n_b [-]
    real(wp), intent(in) :: drag              !! alpha [kg/m]
    real(wp), intent(in) :: unload_stiffness  !! k_u, > 0 [N/m]
    real(wp), intent(in) :: damping           !! C [N s/m]
    type(regolith_t) :: law                   !! the law
    law%name = 'regolith'
    law%has_history = .true.
    law%soil_stiffness = soil_stiffness
    law%soil_exponent = soil_exponent
    law%drag = drag
    law%unload_stiffness = unload_stiffness
    law%damping = damping
  end function regolith

  ! ---------------------------------------------------------------- common procedures

  !> Advances one footpad's contact history to the penetration delta (laws with has_history; done
  !! before the forces are evaluated at that penetration, and committed with the step).
  !! A contact starts at the first advance with delta > 0: its penetration rate is the impact
  !! velocity. delta <= 0 ends the contact; the deepest penetration is kept (a crater stays).
  pure subroutine advance_contact_state(state, delta, delta_dot)
    type(contact_state_t), intent(inout) :: state  !! contact history of one footpad
    real(wp), intent(in) :: delta                  !! penetration [m]
    real(wp), intent(in) :: delta_dot              !! penetration rate [m/s]
    if (delta > 0.0_wp) then
      if (.not. state%touching) then
        state%touching = .true.
        state%v_impact = max(delta_dot, 0.0_wp)
      end if
      state%delta_max = max(state%delta_max, delta)
    else
      state%touching = .false.
    end if
  end subroutine advance_contact_state

  !> Power removed from the mechanical system by the contact: (F_Z - spring_force) * delta_dot.
  !! Includes the spring energy lost when the clamp F_Z >= 0 is active during fast unloading.
  pure function dissipation_power(self, delta, delta_dot, state) result(p)
    class(contact_law_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta             !! penetration [m]
    real(wp), intent(in) :: delta_dot         !! penetration rate [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
    real(wp) :: p                             !! dissipated power [W]
    p = (self%normal_force(delta, delta_dot, state) - self%spring_force(delta, state))*delta_dot
  end function dissipation_power

  pure function hertz_spring_force(self, delta, state) result(f)
    class(hertz_spring_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta              !! penetration [m]
    type(contact_state_t), intent(in), optional :: state  !! contact history (not used by this law)
    real(wp) :: f                              !! K delta^n, 0 for delta <= 0 [N]
    if (present(state)) f = 0.0_wp   ! the law has no history
    if (delta > 0.0_wp) then
      f = self%stiffness*delta**self%exponent
    else
      f = 0.0_wp
    end if
  end function hertz_spring_force

  pure function hertz_elastic_energy(self, delta, state) result(e)
    class(hertz_spring_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta              !! penetration [m]
    type(contact_state_t), intent(in), optional :: state  !! contact history (not used by this law)
    real(wp) :: e                              !! K delta^(n+1)/(n+1), 0 for delta <= 0 [J]
    if (present(state)) e = 0.0_wp   ! the law has no history
    if (delta > 0.0_wp) then
      e = self%stiffness*delta**(self%exponent + 1.0_wp)/(self%exponent + 1.0_wp)
    else
      e = 0.0_wp
    end if
  end function hertz_elastic_energy

  ! ---------------------------------------------------------------- normal forces

  pure function base_normal_force(self, delta, delta_dot, state) result(f)
    class(base_contact_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta              !! penetration, > 0 inside the ground [m]
    real(wp), intent(in) :: delta_dot          !! penetration rate, > 0 moving deeper [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history (not used by this law)
    real(wp) :: f                              !! normal force, >= 0 [N]
    real(wp) :: kappa
    if (present(state)) f = 0.0_wp   ! the law has no history

    if (delta <= 0.0_wp) then
      f = 0.0_wp
      return
    end if
    if (delta < self%damping_depth) then
      kappa = delta/self%damping_depth
    else
      kappa = 1.0_wp
    end if
    f = max(0.0_wp, self%stiffness*delta**self%exponent + kappa*self%damping*delta_dot)
  end function base_normal_force

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
    f = max(0.0_wp, self%stiffness*delta**self%exponent &
                    + adams_step(delta, 0.0_wp, 0.0_wp, self%penetration, self%damping)*delta_dot)
  end function adams_impact_normal_force

  pure function hertz_normal_force(self, delta, delta_dot, state) result(f)
    class(hertz_contact_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta               !! penetration [m]
    real(wp), intent(in) :: delta_dot           !! penetration rate (no effect) [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
    real(wp) :: f                               !! K delta^n [N]
    f = self%spring_force(delta, state) + 0.0_wp*delta_dot   ! rate-independent (the product only reads delta_dot)
  end function hertz_normal_force

  pure function kelvin_voigt_normal_force(self, delta, delta_dot, state) result(f)
    class(kelvin_voigt_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta              !! penetration [m]
    real(wp), intent(in) :: delta_dot          !! penetration rate [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history (not used by this law)
    real(wp) :: f                              !! normal force, >= 0 [N]
    if (present(state)) f = 0.0_wp   ! the law has no history
    if (delta <= 0.0_wp) then
      f = 0.0_wp
      return
    end if
    f = max(0.0_wp, self%stiffness*delta**self%exponent + self%damping*delta_dot)
  end function kelvin_voigt_normal_force

  pure function kelvin_voigt_step_normal_force(self, delta, delta_dot, state) result(f)
    class(kelvin_voigt_step_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta                   !! penetration [m]
    real(wp), intent(in) :: delta_dot               !! penetration rate [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history (not used by this law)
    real(wp) :: f                                   !! normal force, >= 0 [N]
    if (present(state)) f = 0.0_wp   ! the law has no history
    if (delta <= 0.0_wp) then
      f = 0.0_wp
    else if (delta <= self%step_depth) then
      f = max(0.0_wp, self%stiffness*delta**self%exponent + self%damping*delta_dot)
    else
      f = self%stiffness*delta**self%exponent
    end if
  end function kelvin_voigt_step_normal_force

  pure function kelvin_voigt_bilinear_normal_force(self, delta, delta_dot, state) result(f)
    class(kelvin_voigt_bilinear_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta                       !! penetration [m]
    real(wp), intent(in) :: delta_dot                   !! penetration rate [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history (not used by this law)
    real(wp) :: f                                       !! normal force, >= 0 [N]
    if (present(state)) f = 0.0_wp   ! the law has no history
    if (delta <= 0.0_wp) then
      f = 0.0_wp
      return
    end if
    f = max(0.0_wp, self%stiffness*delta**self%exponent + self%damping*delta_dot &
                    + self%damping2*delta_dot*abs(delta_dot))
  end function kelvin_voigt_bilinear_normal_force

  pure function hunt_crossley_normal_force(self, delta, delta_dot, state) result(f)
    class(hunt_crossley_t), intent(in) :: self  !! the law (the state holds the impact velocity)
    real(wp), intent(in) :: delta               !! penetration [m]
    real(wp), intent(in) :: delta_dot           !! penetration rate [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
    real(wp) :: f                               !! normal force, >= 0 [N]
    real(wp) :: v, lambda
    if (delta <= 0.0_wp) then
      f = 0.0_wp
      return
    end if
    v = self%min_impact_speed
    if (present(state)) v = max(state%v_impact, self%min_impact_speed)
    if (self%alpha > 0.0_wp) then
      lambda = 1.5_wp*min(self%alpha, 1.0_wp/v)          ! e = max(0, 1 - alpha v)
    else
      lambda = 1.5_wp*(1.0_wp - self%restitution)/v      ! chi/K = 3 (1 - e) / (2 v)
    end if
    f = max(0.0_wp, self%stiffness*delta**self%exponent*(1.0_wp + lambda*delta_dot))
  end function hunt_crossley_normal_force

  ! ---------------------------------------------------------------- regolith

  !> Deepest sinkage for the evaluation at delta (robust when update was not called).
  pure function regolith_zmax(delta, state) result(zm)
    real(wp), intent(in) :: delta          !! penetration [m]
    type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
    real(wp) :: zm                         !! max(state%delta_max, delta); delta without a state [m]
    zm = delta
    if (present(state)) zm = max(state%delta_max, delta)
  end function regolith_zmax

  pure function regolith_normal_force(self, delta, delta_dot, state) result(f)
    class(regolith_t), intent(in) :: self  !! the law (the state holds the deepest sinkage)
    real(wp), intent(in) :: delta          !! penetration (sinkage) [m]
    real(wp), intent(in) :: delta_dot      !! penetration rate [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
    real(wp) :: f                          !! normal force, >= 0 [N]
    real(wp) :: zm
    if (delta <= 0.0_wp) then
      f = 0.0_wp
      return
    end if
    zm = regolith_zmax(delta, state)
    if (delta >= zm) then
      f = self%soil_stiffness*delta**self%soil_exponent + self%drag*max(delta_dot, 0.0_wp)**2
    else
      f = max(0.0_wp, self%soil_stiffness*zm**self%soil_exponent - self%unload_stiffness*(zm - delta) &
                      + self%damping*delta_dot)
    end if
  end function regolith_normal_force

  !> Elastic part: the virgin curve at the deepest sinkage, the unloading line below it.
  pure function regolith_spring_force(self, delta, state) result(f)
    class(regolith_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta          !! penetration [m]
    type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
    real(wp) :: f                          !! elastic force [N]
    real(wp) :: zm
    if (delta <= 0.0_wp) then
      f = 0.0_wp
      return
    end if
    zm = regolith_zmax(delta, state)
    f = max(0.0_wp, self%soil_stiffness*zm**self%soil_exponent - self%unload_stiffness*(zm - delta))
  end function regolith_spring_force

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

end module landyn_contact
