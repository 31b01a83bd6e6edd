!> Hertz contact + step damping (Kelvin-Voigt 1, Table 4): damping D only for delta <= d.
module landyn_contact_kelvin_voigt_step
  use landyn_kinds, only: wp
  use landyn_contact_law, only: contact_build_t, contact_state_t, hertz_damper_t
  implicit none
  private

  public :: kelvin_voigt_step_t, build

  !> Hertz contact + step damping (Kelvin-Voigt 1): damping D only for delta <= d (D = damping).
  type, extends(hertz_damper_t) :: kelvin_voigt_step_t
    real(wp) :: step_depth = 1.0e-4_wp             !! d: penetration beyond which the damping is off [m]
  contains
    procedure :: normal_force => kelvin_voigt_step_normal_force
  end type kelvin_voigt_step_t

contains

  !> The kelvin_voigt_step law from the &contact input (d = damping_depth > 0).
  subroutine build(b)
    type(contact_build_t), intent(inout) :: b  !! the &contact input, the messages and the law built
    if (b%hertz_wanted(depth_needed=.true., damped=.true.)) &
      allocate (b%law, source=kelvin_voigt_step_t(name='kelvin_voigt_step', stiffness=b%cfg%stiffness, &
                                                  exponent=b%cfg%exponent, damping=b%cfg%damping, step_depth=b%cfg%damping_depth))
  end subroutine build

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
      f = self%damped_force(delta, self%damping, delta_dot)
    else
      f = self%stiffness*delta**self%exponent
    end if
  end function kelvin_voigt_step_normal_force

end module landyn_contact_kelvin_voigt_step
