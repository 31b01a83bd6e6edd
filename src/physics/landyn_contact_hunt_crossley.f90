!> Hertz contact + hysteresis damping (Hunt-Crossley, Table 4): K delta^n (1 + lambda delta_dot).
module landyn_contact_hunt_crossley
  use landyn_kinds, only: wp
  use landyn_contact_law, only: contact_build_t, contact_state_t, hertz_spring_t
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
    procedure :: normal_force => hunt_crossley_normal_force  !! K delta^n + chi delta^n delta_dot, clamped at 0 [N]
  end type hunt_crossley_t

contains

  !> The hunt_crossley law from the &contact input.
  subroutine build(b)
    type(contact_build_t), intent(inout) :: b  !! the &contact input, the messages and the law built
    if (.not. b%hertz_wanted(depth_needed=.false., damped=.false.)) return
    call b%require(b%cfg%restitution >= 0.0_wp .and. b%cfg%restitution <= 1.0_wp, 'restitution', &
                   b%cfg%restitution, '', '0 <= restitution <= 1')
    call b%require_nonnegative('hc_alpha', b%cfg%hc_alpha, 's/m')
    call b%require_positive('min_impact_speed', b%cfg%min_impact_speed, 'm/s')
    allocate (b%law, source=hunt_crossley(b%cfg%stiffness, b%cfg%exponent, b%cfg%restitution, b%cfg%hc_alpha, &
                                          b%cfg%min_impact_speed))
  end subroutine build

  !> hunt_crossley law with the given parameters (a fresh contact history).
  pure function hunt_crossley(stiffness, exponent, restitution, alpha, min_impact_speed) result(law)
    real(wp), intent(in) :: stiffness         !! K [N/m^exponent]
    real(wp), intent(in) :: exponent          !! n [-]
    real(wp), intent(in) :: restitution       !! e, used when alpha = 0 [-]
    real(wp), intent(in) :: alpha             !! alpha of c_r = 1 - alpha v_impact, 0: constant e [s/m]
    real(wp), intent(in) :: min_impact_speed  !! floor of the impact speed, > 0 [m/s]
    type(hunt_crossley_t) :: law              !! the law
    law = hunt_crossley_t(name='hunt_crossley', has_history=.true., stiffness=stiffness, exponent=exponent, &
                          restitution=restitution, alpha=alpha, min_impact_speed=min_impact_speed)
  end function hunt_crossley

  !> Normal force of the Hunt-Crossley law: max(0, K delta^n (1 + (chi/K) delta_dot)), chi from the
  !! impact velocity in the contact history (min_impact_speed without a state); 0 outside the ground.
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
