!> Base contact law of the paper (eq. 18): K delta^n + kappa C delta_dot, kappa = min(delta/D1, 1).
!! Registered in landyn_contact; the interface and conventions are in landyn_contact_law.
module landyn_contact_base
  use landyn_kinds, only: wp
  use landyn_contact_law, only: contact_build_t, contact_state_t, hertz_spring_t, check_hertz_spring, check_damping, &
                                check_damping_depth
  implicit none
  private

  public :: base_contact_t, base_contact, build

  !> Base law of the paper (eq. 18): F_Z = K delta^n + kappa C delta_dot, kappa = min(delta/D1, 1),
  !! F_Z = 0 for delta <= 0, clamped at 0 (never pulls).
  type, extends(hertz_spring_t) :: base_contact_t
    real(wp) :: damping = 1.0e4_wp                 !! C_g [N s/m]
    real(wp) :: damping_depth = 1.0e-4_wp          !! D1: penetration at which full damping applies [m]; 0: no ramp
  contains
    procedure :: normal_force => base_normal_force
  end type base_contact_t

contains

  !> The base law from the &contact input (damping_depth = D1; 0: no ramp, full damping at once).
  !! With b%check_only: only the law-dependent checks (see landyn_contact_law).
  subroutine build(b)
    type(contact_build_t), intent(inout) :: b  !! the &contact input, the messages and the law built
    call check_damping_depth(b, needed=.false.)
    if (b%check_only) return
    call check_hertz_spring(b)
    call check_damping(b)
    allocate (b%law, source=base_contact(b%cfg%stiffness, b%cfg%exponent, b%cfg%damping, b%cfg%damping_depth))
  end subroutine build

  !> Base law with the given parameters.
  pure function base_contact(stiffness, exponent, damping, damping_depth) result(law)
    real(wp), intent(in) :: stiffness      !! K_g [N/m^exponent]
    real(wp), intent(in) :: exponent       !! n [-]
    real(wp), intent(in) :: damping        !! C_g [N s/m]
    real(wp), intent(in) :: damping_depth  !! D1 [m]
    type(base_contact_t) :: law            !! the law
    law%name = 'base'
    law%stiffness = stiffness
    law%exponent = exponent
    law%damping = damping
    law%damping_depth = damping_depth
  end function base_contact

  pure function base_normal_force(self, delta, delta_dot, state) result(f)
    class(base_contact_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: delta              !! penetration, > 0 inside the ground [m]
    real(wp), intent(in) :: delta_dot          !! penetration rate, > 0 moving deeper [m/s]
    type(contact_state_t), intent(in), optional :: state  !! contact history (not used by this law)
    real(wp) :: f                              !! normal force, >= 0 [N]
    real(wp) :: kappa
    if (present(state)) f = 0.0_wp   ! the law has no history

    if (delta <= 0.0_wp) then
      f = 0.0_wp
      return
    end if
    if (delta < self%damping_depth) then
      kappa = delta/self%damping_depth
    else
      kappa = 1.0_wp
    end if
    f = self%damped_force(delta, kappa*self%damping, delta_dot)
  end function base_normal_force

end module landyn_contact_base
