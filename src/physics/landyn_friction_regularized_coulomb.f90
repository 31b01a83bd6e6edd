!> Regularised Coulomb friction (ty3): mu_s (1 - exp(-3|v|/v0))/(1 - exp(-3)) below v0 = v_static.
module landyn_friction_regularized_coulomb
  use landyn_kinds, only: wp
  use landyn_friction_law, only: friction_law_t, friction_build_t, opposing_force
  implicit none
  private

  public :: regularized_coulomb_t, build

  !> Regularised Coulomb friction (ty3): mu_s (1 - exp(-3|v|/v0))/(1 - exp(-3)) below v0, mu_s beyond.
  type, extends(friction_law_t) :: regularized_coulomb_t
    real(wp) :: mu_static = 0.4_wp   !! mu_s [-]
    real(wp) :: v0 = 0.1_wp          !! regularisation speed v0 [m/s]
  contains
    procedure :: friction_force => regularized_coulomb_force                !! mu(|v|) N opposing the slip, no viscous term [N]
    procedure :: coefficient => regularized_coulomb_coefficient             !! exponential ramp to mu_s at v0 [-]
    procedure :: max_coefficient => regularized_coulomb_max_coefficient     !! mu_s [-]
  end type regularized_coulomb_t

contains

  !> The ty3 law from the &friction input.
  subroutine build(b)
    type(friction_build_t), intent(inout) :: b  !! the &friction input, the messages and the law built
    if (b%wanted()) allocate (b%law, source=regularized_coulomb(b%cfg%mu_static, b%cfg%v_static))
  end subroutine build

  !> ty3 law with the given parameters.
  pure function regularized_coulomb(mu_static, v0) result(law)
    real(wp), intent(in) :: mu_static    !! mu_s [-]
    real(wp), intent(in) :: v0           !! regularisation speed, > 0 [m/s]
    type(regularized_coulomb_t) :: law   !! the law
    law = regularized_coulomb_t(name='ty3', mu_static=mu_static, v0=v0)
  end function regularized_coulomb

  ! ---------------------------------------------------------------- ty3

  !> mu(|v|) of ty3: mu_s (1 - exp(-3|v|/v0))/(1 - exp(-3)) up to v0, mu_s beyond.
  pure function regularized_coulomb_coefficient(self, speed) result(mu)
    class(regularized_coulomb_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: speed                     !! slip speed [m/s]
    real(wp) :: mu                                    !! friction coefficient [-]
    real(wp) :: v
    v = abs(speed)
    if (v > self%v0) then
      mu = self%mu_static
    else
      mu = self%mu_static*(1.0_wp - exp(-3.0_wp*v/self%v0))/(1.0_wp - exp(-3.0_wp))
    end if
  end function regularized_coulomb_coefficient

  !> The bound of ty3's coefficient, mu_s (reached at v0).
  pure function regularized_coulomb_max_coefficient(self) result(mu)
    class(regularized_coulomb_t), intent(in) :: self  !! the law
    real(wp) :: mu                                    !! mu_s [-]
    mu = self%mu_static
  end function regularized_coulomb_max_coefficient

  !> Friction force of ty3: mu(|v_slip|) N opposing the slip (no viscous term), 0 at zero slip.
  pure function regularized_coulomb_force(self, v_slip, f_normal) result(f_t)
    class(regularized_coulomb_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: v_slip(2)                 !! slip velocity [m/s]
    real(wp), intent(in) :: f_normal                  !! normal force magnitude [N]
    real(wp) :: f_t(2)                                !! friction force [N]
    f_t = opposing_force(self%coefficient(norm2(v_slip)), v_slip, f_normal)
  end function regularized_coulomb_force

end module landyn_friction_regularized_coulomb
