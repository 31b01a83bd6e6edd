!> Coulomb friction with stiction (ty1 static Coulomb, ty2 + viscous, ty4 stiction + dynamic Coulomb).
module landyn_friction_coulomb
  use landyn_kinds, only: wp
  use landyn_friction_law, only: friction_law_t, friction_build_t
  implicit none
  private

  public :: coulomb_t, build_ty1, build_ty2, build_ty4

  !> Coulomb friction with stiction (ty1, ty2, ty4): slides with mu_slide N + C_v |v|, sticks up
  !! to mu_stick N.
  type, extends(friction_law_t) :: coulomb_t
    real(wp) :: mu_slide = 0.4_wp    !! sliding coefficient (mu_s for ty1/ty2, mu_d for ty4) [-]
  contains
    procedure :: coefficient => coulomb_coefficient          !! mu_slide at every slip speed [-]
    procedure :: max_coefficient => coulomb_max_coefficient  !! max(mu_stick, mu_slide) [-]
  end type coulomb_t

contains

  !> The ty1 law (static Coulomb: mu_s N, sticks up to mu_s N) from the &friction input.
  subroutine build_ty1(b)
    type(friction_build_t), intent(inout) :: b  !! the &friction input, the messages and the law built
    call build_coulomb(b, b%cfg%mu_static, 0.0_wp, stiction_order=.false.)
  end subroutine build_ty1

  !> The ty2 law (Coulomb + viscous: mu_s N + C_v |v|, sticks up to mu_s N) from the &friction input.
  subroutine build_ty2(b)
    type(friction_build_t), intent(inout) :: b  !! the &friction input, the messages and the law built
    call build_coulomb(b, b%cfg%mu_static, b%cfg%viscous, stiction_order=.false.)
  end subroutine build_ty2

  !> The ty4 law (slides with mu_d N, sticks up to mu_s N; mu_dynamic <= mu_static) from the &friction input.
  subroutine build_ty4(b)
    type(friction_build_t), intent(inout) :: b  !! the &friction input, the messages and the law built
    call build_coulomb(b, b%cfg%mu_dynamic, 0.0_wp, stiction_order=.true.)
  end subroutine build_ty4

  !> A Coulomb law with stiction (sticks up to mu_s N) sliding with mu_slide N + C_v |v|.
  subroutine build_coulomb(b, mu_slide, viscous, stiction_order)
    type(friction_build_t), intent(inout) :: b  !! the &friction input, the messages and the law built
    real(wp), intent(in) :: mu_slide            !! sliding coefficient [-]
    real(wp), intent(in) :: viscous             !! C_v [N s/m]
    logical, intent(in) :: stiction_order       !! the law needs mu_dynamic <= mu_static [-]
    if (b%wanted(stiction_order=stiction_order, stick=.true.)) &
      allocate (b%law, source=coulomb(b%cfg%mu_static, mu_slide, viscous, b%cfg%stick_stiffness, b%cfg%stick_damping))
  end subroutine build_coulomb

  !> Coulomb law with stiction (name 'ty1'; the factory renames it ty2/ty4).
  pure function coulomb(mu_stick, mu_slide, viscous, stick_stiffness, stick_damping) result(law)
    real(wp), intent(in) :: mu_stick         !! static coefficient [-]
    real(wp), intent(in) :: mu_slide         !! sliding coefficient [-]
    real(wp), intent(in) :: viscous          !! C_v [N s/m]
    real(wp), intent(in) :: stick_stiffness  !! k, > 0 [N/m]
    real(wp), intent(in) :: stick_damping    !! c [N s/m]
    type(coulomb_t) :: law                   !! the law
    law = coulomb_t(name='ty1', has_stiction=.true., mu_stick=mu_stick, mu_slide=mu_slide, viscous=viscous, &
                    stick_stiffness=stick_stiffness, stick_damping=stick_damping)
  end function coulomb

  ! ---------------------------------------------------------------- ty1, ty2, ty4

  !> The sliding coefficient mu_slide, independent of the slip speed.
  pure function coulomb_coefficient(self, speed) result(mu)
    class(coulomb_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: speed         !! slip speed (no effect) [m/s]
    real(wp) :: mu                        !! sliding coefficient [-]
    mu = self%mu_slide + 0.0_wp*speed     ! speed-independent (the product only reads speed)
  end function coulomb_coefficient

  !> The larger of the stick and sliding coefficients, max(mu_stick, mu_slide).
  pure function coulomb_max_coefficient(self) result(mu)
    class(coulomb_t), intent(in) :: self  !! the law
    real(wp) :: mu                        !! max(mu_stick, mu_slide) [-]
    mu = max(self%mu_stick, self%mu_slide)
  end function coulomb_max_coefficient

end module landyn_friction_coulomb
