!> Hertz contact + step damping (Kelvin-Voigt 1, Table 4): damping D only for delta <= d.
!! Registered in landyn_contact; the interface and conventions are in landyn_contact_law.
module landyn_contact_kelvin_voigt_step
  use landyn_kinds, only: wp
  use landyn_config, only: contact_cfg_t
  use landyn_errors, only: input_errors_t
  use landyn_contact_law, only: contact_law_t, contact_state_t, hertz_spring_t, check_hertz_spring, check_damping, &
                                check_damping_depth
  implicit none
  private

  public :: kelvin_voigt_step_t, build

  !> Hertz contact + step damping (Kelvin-Voigt 1): damping D only for delta <= d.
  type, extends(hertz_spring_t) :: kelvin_voigt_step_t
    real(wp) :: damping = 1.0e4_wp                 !! D [N s/m]
    real(wp) :: step_depth = 1.0e-4_wp             !! d: penetration beyond which the damping is off [m]
  contains
    procedure :: normal_force => kelvin_voigt_step_normal_force
  end type kelvin_voigt_step_t

contains

  !> The kelvin_voigt_step law from the &contact input (d = damping_depth > 0).
  !! Without `law`: only the law-dependent checks (see landyn_contact_law).
  subroutine build(cfg, pre, errors, law)
    type(contact_cfg_t), intent(in) :: cfg                            !! resolved &contact input
    character(len=*), intent(in) :: pre                               !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors                     !! problems found are appended here
    class(contact_law_t), allocatable, intent(out), optional :: law   !! the law (also when a check failed)
    call check_damping_depth(cfg, pre, errors, needed=.true.)
    if (.not. present(law)) return
    call check_hertz_spring(cfg, pre, errors)
    call check_damping(cfg, pre, errors)
    allocate (law, source=kelvin_voigt_step_t(name='kelvin_voigt_step', stiffness=cfg%stiffness, exponent=cfg%exponent, &
                                              damping=cfg%damping, step_depth=cfg%damping_depth))
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
