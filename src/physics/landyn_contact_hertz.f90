!> Hertz contact (Table 4): K delta^n.
module landyn_contact_hertz
  use landyn_kinds, only: wp
  use landyn_contact_law, only: contact_build_t, contact_state_t, hertz_spring_t
  implicit none
  private

  public :: hertz_contact_t, build

  !> Hertz contact: F = K delta^n (Table 4).
  type, extends(hertz_spring_t) :: hertz_contact_t
  contains
    procedure :: normal_force => hertz_normal_force  !! K delta^n, rate-independent [N]
  end type hertz_contact_t

contains

  !> The hertz law from the &contact input.
  subroutine build(b)
    type(contact_build_t), intent(inout) :: b  !! the &contact input, the messages and the law built
    if (b%hertz_wanted(depth_needed=.false., damped=.false.)) &
      allocate (b%law, source=hertz_contact_t(name='hertz', stiffness=b%cfg%stiffness, exponent=b%cfg%exponent))
  end subroutine build

  !> Normal force of the Hertz law: the spring alone, K delta^n (0 outside the ground).
  pure function hertz_normal_force(self, delta, delta_dot, state) result(f)
    class(hertz_contact_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta               !! penetration [m]
    real(wp), intent(in) :: delta_dot           !! penetration rate (no effect) [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history of the footpad
    real(wp) :: f                               !! K delta^n [N]
    f = self%spring_force(delta, state) + 0.0_wp*delta_dot   ! rate-independent (the product only reads delta_dot)
  end function hertz_normal_force

end module landyn_contact_hertz
