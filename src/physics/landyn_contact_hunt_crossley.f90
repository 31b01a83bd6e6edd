!> Hertz contact + hysteresis damping (Hunt-Crossley, Table 4): K delta^n (1 + lambda delta_dot).
!! Registered in landyn_contact; the interface and conventions are in landyn_contact_law.
module landyn_contact_hunt_crossley
  use landyn_kinds, only: wp
  use landyn_config, only: contact_cfg_t
  use landyn_errors, only: input_errors_t
  use landyn_contact_law, only: contact_law_t, contact_state_t, hertz_spring_t, check_hertz_spring, check_damping_depth
  use landyn_law_checks, only: require_real, positive, nonnegative
  implicit none
  private

  public :: hunt_crossley_t, hunt_crossley, build

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

contains

  !> The hunt_crossley law from the &contact input.
  !! Without `law`: only the law-dependent checks (see landyn_contact_law).
  subroutine build(cfg, pre, errors, law)
    type(contact_cfg_t), intent(in) :: cfg                            !! resolved &contact input
    character(len=*), intent(in) :: pre                               !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors                     !! problems found are appended here
    class(contact_law_t), allocatable, intent(out), optional :: law   !! the law (also when a check failed)
    call check_damping_depth(cfg, pre, errors, needed=.false.)
    if (.not. present(law)) return
    call check_hertz_spring(cfg, pre, errors)
    call require_real(errors, cfg%restitution >= 0.0_wp .and. cfg%restitution <= 1.0_wp, pre, 'contact', 'restitution', &
                      cfg%restitution, '', '0 <= restitution <= 1')
    call require_real(errors, nonnegative(cfg%hc_alpha), pre, 'contact', 'hc_alpha', cfg%hc_alpha, 's/m', 'hc_alpha >= 0 s/m')
    call require_real(errors, positive(cfg%min_impact_speed), pre, 'contact', 'min_impact_speed', cfg%min_impact_speed, &
                      'm/s', 'min_impact_speed > 0 m/s')
    allocate (law, source=hunt_crossley(cfg%stiffness, cfg%exponent, cfg%restitution, cfg%hc_alpha, cfg%min_impact_speed))
  end subroutine build

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

end module landyn_contact_hunt_crossley
