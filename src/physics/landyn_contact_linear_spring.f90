!> Linear spring contact (a throw-away example of adding a law): F = K delta, no damping.
!! Registered in landyn_contact; the interface and conventions are in landyn_contact_law.
module landyn_contact_linear_spring
  use landyn_kinds, only: wp
  use landyn_contact_law, only: contact_law_t, contact_build_t, contact_state_t
  implicit none
  private

  public :: linear_spring_t, build

  !> F = K delta inside the ground, 0 outside.
  type, extends(contact_law_t) :: linear_spring_t
    real(wp) :: stiffness = 1.0e6_wp  !! K [N/m]
  contains
    procedure :: normal_force => linear_spring_force
    procedure :: spring_force => linear_spring_force_only
    procedure :: elastic_energy => linear_spring_energy
  end type linear_spring_t

contains

  !> The linear_spring law from the &contact input (K = stiffness).
  !! With b%check_only: only the law-dependent checks (see landyn_contact_law).
  subroutine build(b)
    type(contact_build_t), intent(inout) :: b  !! the &contact input, the messages and the law built
    if (.not. b%wanted(depth_needed=.false.)) return
    call b%require_positive('stiffness', b%cfg%stiffness, 'N/m')
    allocate (b%law, source=linear_spring_t(name='linear_spring', stiffness=b%cfg%stiffness))
  end subroutine build

  pure function linear_spring_force(self, delta, delta_dot, state) result(f)
    class(linear_spring_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta               !! penetration [m]
    real(wp), intent(in) :: delta_dot           !! penetration rate (no effect) [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history (not used)
    real(wp) :: f                               !! K delta, >= 0 [N]
    f = self%spring_force(delta, state) + 0.0_wp*delta_dot
  end function linear_spring_force

  pure function linear_spring_force_only(self, delta, state) result(f)
    class(linear_spring_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta               !! penetration [m]
    type(contact_state_t), intent(in), optional :: state  !! contact history (not used)
    real(wp) :: f                               !! K delta, 0 for delta <= 0 [N]
    if (present(state)) f = 0.0_wp
    f = self%stiffness*max(delta, 0.0_wp)
  end function linear_spring_force_only

  pure function linear_spring_energy(self, delta, state) result(e)
    class(linear_spring_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta               !! penetration [m]
    type(contact_state_t), intent(in), optional :: state  !! contact history (not used)
    real(wp) :: e                               !! K delta^2 / 2 [J]
    if (present(state)) e = 0.0_wp
    e = 0.5_wp*self%stiffness*max(delta, 0.0_wp)**2
  end function linear_spring_energy

end module landyn_contact_linear_spring
