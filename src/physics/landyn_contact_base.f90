!> Base contact law of the paper (eq. 18): K delta^n + kappa C delta_dot, kappa = min(delta/D1, 1).
module landyn_contact_base
  use landyn_kinds, only: wp
  use landyn_contact_law, only: contact_build_t, damped_hertz_t
  implicit none
  private

  public :: base_contact_t, base_contact, build

  !> Base law of the paper (eq. 18): F_Z = K delta^n + kappa C delta_dot, kappa = min(delta/D1, 1),
  !! F_Z = 0 for delta <= 0, clamped at 0 (never pulls). C = damping (C_g).
  type, extends(damped_hertz_t) :: base_contact_t
    real(wp) :: damping_depth = 1.0e-4_wp          !! D1: penetration at which full damping applies [m]; 0: no ramp
  contains
    procedure :: damping_coefficient => base_damping  !! kappa C, kappa = min(delta/D1, 1) [N s/m]
  end type base_contact_t

contains

  !> The base law from the &contact input (damping_depth = D1; 0: no ramp, full damping at once).
  subroutine build(b)
    type(contact_build_t), intent(inout) :: b  !! the &contact input, the messages and the law built
    if (b%hertz_wanted(depth_needed=.false., damped=.true.)) &
      allocate (b%law, source=base_contact(b%cfg%stiffness, b%cfg%exponent, b%cfg%damping, b%cfg%damping_depth))
  end subroutine build

  !> Base law with the given parameters.
  pure function base_contact(stiffness, exponent, damping, damping_depth) result(law)
    real(wp), intent(in) :: stiffness      !! K_g [N/m^exponent]
    real(wp), intent(in) :: exponent       !! n [-]
    real(wp), intent(in) :: damping        !! C_g [N s/m]
    real(wp), intent(in) :: damping_depth  !! D1 [m]
    type(base_contact_t) :: law            !! the law
    law = base_contact_t(name='base', stiffness=stiffness, exponent=exponent, damping=damping, damping_depth=damping_depth)
  end function base_contact

  !> kappa C, kappa = min(delta/D1, 1) (D1 = 0: no ramp).
  pure function base_damping(self, delta) result(c)
    class(base_contact_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta              !! penetration, > 0 [m]
    real(wp) :: c                              !! damping coefficient [N s/m]
    if (delta < self%damping_depth) then
      c = (delta/self%damping_depth)*self%damping
    else
      c = self%damping
    end if
  end function base_damping

end module landyn_contact_base
