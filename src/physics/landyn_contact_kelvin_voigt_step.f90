!> Hertz contact + step damping (Kelvin-Voigt 1, Table 4): damping D only for delta <= d.
module landyn_contact_kelvin_voigt_step
  use landyn_kinds, only: wp
  use landyn_contact_law, only: contact_build_t, damped_hertz_t
  implicit none
  private

  public :: kelvin_voigt_step_t, build

  !> Hertz contact + step damping (Kelvin-Voigt 1): damping D only for delta <= d (D = damping).
  type, extends(damped_hertz_t) :: kelvin_voigt_step_t
    real(wp) :: step_depth = 1.0e-4_wp             !! d: penetration beyond which the damping is off [m]
  contains
    procedure :: damping_coefficient => kelvin_voigt_step_damping  !! D for delta <= d, 0 beyond [N s/m]
  end type kelvin_voigt_step_t

contains

  !> The kelvin_voigt_step law from the &contact input (d = damping_depth > 0).
  subroutine build(b)
    type(contact_build_t), intent(inout) :: b  !! the &contact input, the messages and the law built
    if (b%hertz_wanted(depth_needed=.true., damped=.true.)) &
      allocate (b%law, source=kelvin_voigt_step_t(name='kelvin_voigt_step', stiffness=b%cfg%stiffness, &
                                                  exponent=b%cfg%exponent, damping=b%cfg%damping, step_depth=b%cfg%damping_depth))
  end subroutine build

  !> D up to the step depth d, 0 beyond (the spring alone: K delta^n + 0 is K delta^n exactly).
  pure function kelvin_voigt_step_damping(self, delta) result(c)
    class(kelvin_voigt_step_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta                   !! penetration, > 0 [m]
    real(wp) :: c                                   !! damping coefficient [N s/m]
    if (delta <= self%step_depth) then
      c = self%damping
    else
      c = 0.0_wp
    end if
  end function kelvin_voigt_step_damping

end module landyn_contact_kelvin_voigt_step
