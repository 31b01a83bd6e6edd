!> Regularised Coulomb friction as in MSC Adams contacts (coulomb_step, alias adams_step): the base law.
module landyn_friction_coulomb_step
  use landyn_kinds, only: wp
  use landyn_friction_law, only: two_coefficient_t, friction_build_t, adams_step, opposing_force
  use landyn_real_text, only: fmt_real
  implicit none
  private

  public :: coulomb_step_t, coulomb_step, build

  !> Regularised Coulomb friction as in MSC Adams contacts ('coulomb_step', alias 'adams_step'):
  !!   v >= v_d:        mu = mu_d
  !!   v_s <= v < v_d:  mu = STEP(v, v_s, mu_s, v_d, mu_d)
  !!   v < v_s:         mu = STEP(v, 0, 0, v_s, mu_s)
  !! with v = |v_slip| and f_t = -mu(v) N v_slip/|v_slip|.
  type, extends(two_coefficient_t) :: coulomb_step_t
    real(wp) :: v_static = 0.1_wp    !! stiction transition slip speed v_s [m/s]
    real(wp) :: v_dynamic = 1.0_wp   !! friction transition slip speed v_d [m/s]
  contains
    procedure :: friction_force => coulomb_step_force       !! -mu(|v|) N v_slip/|v_slip|, no viscous term [N]
    procedure :: coefficient => coulomb_step_coefficient    !! the two STEP ramps, mu_d beyond v_d [-]
  end type coulomb_step_t

contains

  !> The coulomb_step law from the &friction input (v_dynamic > v_static).
  subroutine build(b)
    type(friction_build_t), intent(inout) :: b  !! the &friction input, the messages and the law built
    call b%require(b%cfg%v_dynamic > b%cfg%v_static .and. b%cfg%v_dynamic <= huge(1.0_wp), &
                   'v_dynamic', b%cfg%v_dynamic, 'm/s', 'v_dynamic > v_static = '//fmt_real(b%cfg%v_static)//' m/s')
    if (b%wanted()) allocate (b%law, source=coulomb_step(b%cfg%mu_static, b%cfg%mu_dynamic, b%cfg%v_static, b%cfg%v_dynamic))
  end subroutine build

  !> coulomb_step law with the given parameters (0 < v_static <= v_dynamic expected).
  pure function coulomb_step(mu_static, mu_dynamic, v_static, v_dynamic) result(law)
    real(wp), intent(in) :: mu_static   !! mu_s [-]
    real(wp), intent(in) :: mu_dynamic  !! mu_d [-]
    real(wp), intent(in) :: v_static    !! v_s [m/s]
    real(wp), intent(in) :: v_dynamic   !! v_d [m/s]
    type(coulomb_step_t) :: law         !! the law
    law = coulomb_step_t(name='coulomb_step', mu_static=mu_static, mu_dynamic=mu_dynamic, v_static=v_static, &
                         v_dynamic=v_dynamic)
  end function coulomb_step

  ! ---------------------------------------------------------------- coulomb_step

  !> The coefficient mu(|v|) = STEP(v, 0, 0, v_s, mu_s) below v_s, STEP(v, v_s, mu_s, v_d, mu_d) up to v_d, mu_d beyond.
  pure function coulomb_step_coefficient(self, speed) result(mu)
    class(coulomb_step_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: speed              !! slip speed (its magnitude is used) [m/s]
    real(wp) :: mu                             !! friction coefficient [-]
    real(wp) :: v

    v = abs(speed)
    if (v >= self%v_dynamic) then
      mu = self%mu_dynamic
    else if (v >= self%v_static) then
      mu = adams_step(v, self%v_static, self%mu_static, self%v_dynamic, self%mu_dynamic)
    else
      mu = adams_step(v, 0.0_wp, 0.0_wp, self%v_static, self%mu_static)
    end if
  end function coulomb_step_coefficient

  !> Friction force of coulomb_step: mu(|v_slip|) N opposing the slip (no viscous term), 0 at zero slip.
  pure function coulomb_step_force(self, v_slip, f_normal) result(f_t)
    class(coulomb_step_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: v_slip(2)          !! slip velocity, local (t1, t2) [m/s]
    real(wp), intent(in) :: f_normal           !! normal force magnitude [N]
    real(wp) :: f_t(2)                         !! friction force, local (t1, t2) [N]
    f_t = opposing_force(self%coefficient(norm2(v_slip)), v_slip, f_normal)
  end function coulomb_step_force

end module landyn_friction_coulomb_step
