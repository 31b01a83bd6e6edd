!> Hertz contact + linear damping (Kelvin-Voigt, Table 4): K delta^n + D delta_dot.
module landyn_contact_kelvin_voigt
  use landyn_kinds, only: wp
  use landyn_contact_law, only: contact_build_t, damped_hertz_t
  implicit none
  private

  public :: kelvin_voigt_t, build

  !> Hertz contact + linear damping (Kelvin-Voigt): F = K delta^n + D delta_dot (D = damping).
  type, extends(damped_hertz_t) :: kelvin_voigt_t
  contains
    procedure :: damping_coefficient => kelvin_voigt_damping  !! the constant D [N s/m]
  end type kelvin_voigt_t

contains

  !> The kelvin_voigt law from the &contact input.
  subroutine build(b)
    type(contact_build_t), intent(inout) :: b  !! the &contact input, the messages and the law built
    if (b%hertz_wanted(depth_needed=.false., damped=.true.)) &
      allocate (b%law, source=kelvin_voigt_t(name='kelvin_voigt', stiffness=b%cfg%stiffness, exponent=b%cfg%exponent, &
                                             damping=b%cfg%damping))
  end subroutine build

  !> The constant D.
  pure function kelvin_voigt_damping(self, delta) result(c)
    class(kelvin_voigt_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta              !! penetration, > 0 (no effect) [m]
    real(wp) :: c                              !! damping coefficient [N s/m]
    c = self%damping + 0.0_wp*delta   ! penetration-independent (the product only reads delta)
  end function kelvin_voigt_damping

end module landyn_contact_kelvin_voigt
