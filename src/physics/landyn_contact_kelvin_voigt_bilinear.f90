!> Hertz contact + bilinear damping (Kelvin-Voigt 2, Table 4): K delta^n + D1 delta_dot + D2 delta_dot |delta_dot|.
module landyn_contact_kelvin_voigt_bilinear
  use landyn_kinds, only: wp
  use landyn_contact_law, only: contact_build_t, contact_state_t, hertz_damper_t
  implicit none
  private

  public :: kelvin_voigt_bilinear_t, build

  !> Hertz contact + bilinear damping (Kelvin-Voigt 2): F = K delta^n + D1 delta_dot + D2 delta_dot |delta_dot|
  !! (D1 = damping).
  type, extends(hertz_damper_t) :: kelvin_voigt_bilinear_t
    real(wp) :: damping2 = 1.0e4_wp                !! D2 [N s^2/m^2]
  contains
    procedure :: normal_force => kelvin_voigt_bilinear_normal_force  !! K delta^n + D1 delta_dot + D2 delta_dot |delta_dot| [N]
  end type kelvin_voigt_bilinear_t

contains

  !> The kelvin_voigt_bilinear law from the &contact input.
  subroutine build(b)
    type(contact_build_t), intent(inout) :: b  !! the &contact input, the messages and the law built
    if (.not. b%hertz_wanted(depth_needed=.false., damped=.true.)) return
    call b%require_nonnegative('damping2', b%cfg%damping2, 'N s^2/m^2')
    allocate (b%law, source=kelvin_voigt_bilinear_t(name='kelvin_voigt_bilinear', stiffness=b%cfg%stiffness, &
                                                    exponent=b%cfg%exponent, damping=b%cfg%damping, damping2=b%cfg%damping2))
  end subroutine build

  !> Normal force of the bilinear Kelvin-Voigt law: max(0, K delta^n + D1 delta_dot + D2 delta_dot |delta_dot|)
  !! inside the ground, 0 outside.
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

end module landyn_contact_kelvin_voigt_bilinear
