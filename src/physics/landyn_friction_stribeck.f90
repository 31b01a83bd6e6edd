!> Stiction + Stribeck + Coulomb + viscous friction (ty5).
module landyn_friction_stribeck
  use landyn_kinds, only: wp
  use landyn_friction_law, only: stribeck_curve_t, friction_build_t
  implicit none
  private

  public :: stribeck_t, build

  !> Stiction + Stribeck + Coulomb + viscous (ty5): mu = mu_d + (mu_s - mu_d) exp(-(|v|/v_S)^delta),
  !! plus C_v |v|; sticks up to mu_s N.
  type, extends(stribeck_curve_t) :: stribeck_t
  contains
    procedure :: coefficient => stribeck_coefficient  !! mu_d + (mu_s - mu_d) exp(-(|v|/v_S)^delta) [-]
  end type stribeck_t

contains

  !> The ty5 law from the &friction input (mu_dynamic <= mu_static).
  subroutine build(b)
    type(friction_build_t), intent(inout) :: b  !! the &friction input, the messages and the law built
    real(wp) :: v_s
    if (b%wanted(stiction_order=.true., stick=.true., v_s=v_s)) &
      allocate (b%law, source=stribeck(b%cfg%mu_static, b%cfg%mu_dynamic, v_s, b%cfg%stribeck_exponent, b%cfg%viscous, &
                                       b%cfg%stick_stiffness, b%cfg%stick_damping))
  end subroutine build

  !> ty5 law with the given parameters.
  pure function stribeck(mu_static, mu_dynamic, v_stribeck, delta, viscous, stick_stiffness, stick_damping) result(law)
    real(wp), intent(in) :: mu_static        !! F_S/N [-]
    real(wp), intent(in) :: mu_dynamic       !! F_D/N [-]
    real(wp), intent(in) :: v_stribeck       !! v_S, > 0 [m/s]
    real(wp), intent(in) :: delta            !! exponent [-]
    real(wp), intent(in) :: viscous          !! C_v [N s/m]
    real(wp), intent(in) :: stick_stiffness  !! k, > 0 [N/m]
    real(wp), intent(in) :: stick_damping    !! c [N s/m]
    type(stribeck_t) :: law                  !! the law
    law = stribeck_t(name='ty5', has_stiction=.true., mu_stick=mu_static, mu_static=mu_static, mu_dynamic=mu_dynamic, &
                     v_stribeck=v_stribeck, delta=delta, viscous=viscous, stick_stiffness=stick_stiffness, &
                     stick_damping=stick_damping)
  end function stribeck

  ! ---------------------------------------------------------------- ty5

  !> mu(|v|) of ty5: mu_d + (mu_s - mu_d) exp(-(|v|/v_S)^delta).
  pure function stribeck_coefficient(self, speed) result(mu)
    class(stribeck_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: speed          !! slip speed [m/s]
    real(wp) :: mu                         !! Coulomb + Stribeck coefficient [-]
    mu = self%mu_dynamic + (self%mu_static - self%mu_dynamic)*exp(-(abs(speed)/self%v_stribeck)**self%delta)
  end function stribeck_coefficient

end module landyn_friction_stribeck
