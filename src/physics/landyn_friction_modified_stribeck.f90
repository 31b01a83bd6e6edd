!> Stiction + modified Stribeck + Coulomb + viscous friction (ty6), regularised at zero slip.
module landyn_friction_modified_stribeck
  use landyn_kinds, only: wp
  use landyn_friction_law, only: stribeck_curve_t, friction_build_t
  implicit none
  private

  public :: modified_stribeck_t, build

  !> Stiction + modified Stribeck + Coulomb + viscous (ty6), regularised at zero slip:
  !!   |v| < v0:  mu = mu_s (1 - (|v| - v0)^2 / v0^2)
  !!   |v| >= v0: mu = mu_d + (mu_s - mu_d) exp(-eps (|v|/v_S)^delta)
  !! plus C_v |v|.
  type, extends(stribeck_curve_t) :: modified_stribeck_t
    real(wp) :: v0 = 0.1_wp          !! stiction velocity v0 [m/s]
    real(wp) :: eps = 0.85_wp        !! epsilon [-]
  contains
    procedure :: coefficient => modified_stribeck_coefficient  !! parabola below v0, Stribeck curve beyond [-]
  end type modified_stribeck_t

contains

  !> The ty6 law from the &friction input (mu_dynamic <= mu_static).
  subroutine build(b)
    type(friction_build_t), intent(inout) :: b  !! the &friction input, the messages and the law built
    real(wp) :: v_s
    if (b%wanted(stiction_order=.true., viscous=.true., v_s=v_s)) &
      allocate (b%law, source=modified_stribeck(b%cfg%mu_static, b%cfg%mu_dynamic, b%cfg%v_static, v_s, b%cfg%stribeck_decay, &
                                                b%cfg%stribeck_exponent, b%cfg%viscous))
  end subroutine build

  !> ty6 law with the given parameters.
  pure function modified_stribeck(mu_static, mu_dynamic, v0, v_stribeck, eps, delta, viscous) result(law)
    real(wp), intent(in) :: mu_static    !! F_S/N [-]
    real(wp), intent(in) :: mu_dynamic   !! F_C/N [-]
    real(wp), intent(in) :: v0           !! stiction velocity, > 0 [m/s]
    real(wp), intent(in) :: v_stribeck   !! v_S, > 0 [m/s]
    real(wp), intent(in) :: eps          !! epsilon [-]
    real(wp), intent(in) :: delta        !! exponent [-]
    real(wp), intent(in) :: viscous      !! C_v [N s/m]
    type(modified_stribeck_t) :: law     !! the law
    law = modified_stribeck_t(name='ty6', mu_static=mu_static, mu_dynamic=mu_dynamic, v0=v0, v_stribeck=v_stribeck, eps=eps, &
                              delta=delta, viscous=viscous)
  end function modified_stribeck

  ! ---------------------------------------------------------------- ty6

  !> mu(|v|) of ty6: mu_s (1 - (|v| - v0)^2/v0^2) below v0, mu_d + (mu_s - mu_d) exp(-eps (|v|/v_S)^delta) beyond.
  pure function modified_stribeck_coefficient(self, speed) result(mu)
    class(modified_stribeck_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: speed                   !! slip speed [m/s]
    real(wp) :: mu                                  !! friction coefficient [-]
    real(wp) :: v
    v = abs(speed)
    if (v < self%v0) then
      mu = self%mu_static*(1.0_wp - ((v - self%v0)/self%v0)**2)
    else
      mu = self%mu_dynamic + (self%mu_static - self%mu_dynamic)*exp(-self%eps*(v/self%v_stribeck)**self%delta)
    end if
  end function modified_stribeck_coefficient

end module landyn_friction_modified_stribeck
