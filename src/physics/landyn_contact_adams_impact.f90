!> MSC Adams IMPACT contact: K delta^n + STEP(delta, 0, 0, d_max, C) delta_dot.
module landyn_contact_adams_impact
  use landyn_kinds, only: wp
  use landyn_contact_law, only: contact_build_t, damped_hertz_t
  use landyn_friction_law, only: adams_step
  implicit none
  private

  public :: adams_impact_t, build

  !> MSC Adams IMPACT: F = K delta^n + STEP(delta, 0, 0, d_max, C) delta_dot (cubic damping ramp;
  !! C = damping, full damping).
  type, extends(damped_hertz_t) :: adams_impact_t
    real(wp) :: penetration = 1.0e-4_wp            !! d_max: penetration of full damping [m]
  contains
    procedure :: damping_coefficient => adams_impact_damping  !! STEP(delta, 0, 0, d_max, C) [N s/m]
  end type adams_impact_t

contains

  !> The adams_impact law from the &contact input (d_max = damping_depth > 0).
  subroutine build(b)
    type(contact_build_t), intent(inout) :: b  !! the &contact input, the messages and the law built
    if (b%hertz_wanted(depth_needed=.true., damped=.true.)) &
      allocate (b%law, source=adams_impact_t(name='adams_impact', stiffness=b%cfg%stiffness, exponent=b%cfg%exponent, &
                                             damping=b%cfg%damping, penetration=b%cfg%damping_depth))
  end subroutine build

  !> STEP(delta, 0, 0, d_max, C): the cubic ramp to the full damping at d_max.
  pure function adams_impact_damping(self, delta) result(c)
    class(adams_impact_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta              !! penetration, > 0 [m]
    real(wp) :: c                              !! damping coefficient [N s/m]
    c = adams_step(delta, 0.0_wp, 0.0_wp, self%penetration, self%damping)
  end function adams_impact_damping

end module landyn_contact_adams_impact
