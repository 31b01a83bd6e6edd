!> Hertz contact (Table 4): K delta^n.
!! Registered in landyn_contact; the interface and conventions are in landyn_contact_law.
module landyn_contact_hertz
  use landyn_kinds, only: wp
  use landyn_config, only: contact_cfg_t
  use landyn_errors, only: input_errors_t
  use landyn_contact_law, only: contact_law_t, contact_state_t, hertz_spring_t, check_hertz_spring, check_damping_depth
  implicit none
  private

  public :: hertz_contact_t, build

  !> Hertz contact: F = K delta^n (Table 4).
  type, extends(hertz_spring_t) :: hertz_contact_t
  contains
    procedure :: normal_force => hertz_normal_force
  end type hertz_contact_t

contains

  !> The hertz law from the &contact input.
  !! Without `law`: only the law-dependent checks (see landyn_contact_law).
  subroutine build(cfg, pre, errors, law)
    type(contact_cfg_t), intent(in) :: cfg                            !! resolved &contact input
    character(len=*), intent(in) :: pre                               !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors                     !! problems found are appended here
    class(contact_law_t), allocatable, intent(out), optional :: law   !! the law (also when a check failed)
    call check_damping_depth(cfg, pre, errors, needed=.false.)
    if (.not. present(law)) return
    call check_hertz_spring(cfg, pre, errors)
    allocate (law, source=hertz_contact_t(name='hertz', stiffness=cfg%stiffness, exponent=cfg%exponent))
  end subroutine build

  pure function hertz_normal_force(self, delta, delta_dot, state) result(f)
    class(hertz_contact_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta               !! penetration [m]
    real(wp), intent(in) :: delta_dot           !! penetration rate (no effect) [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
    real(wp) :: f                               !! K delta^n [N]
    f = self%spring_force(delta, state) + 0.0_wp*delta_dot   ! rate-independent (the product only reads delta_dot)
  end function hertz_normal_force

end module landyn_contact_hertz
