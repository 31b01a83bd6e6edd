!> The footpad-ground friction law interface (paper eq. 17, section 4.2, Tables 7-8; docs/model_conventions.md base friction).
!!
!! Conventions
!! - v_slip is the 2-component tangential slip velocity of the footpad relative to the ground in
!!   the local surface frame (t1, t2) of landyn_terrain (use slip_velocity there).
!! - f_normal is the normal force magnitude F_Z (>= 0; negative values are treated as 0).
!! - friction_force returns the 2-component tangential force (t1, t2) the ground exerts on the
!!   footpad while it slips (Table 7's v /= 0 branch). It opposes the slip: f_t . v_slip <= 0, and
!!   it is exactly zero at zero slip and without contact.
!! - coefficient(speed) is the Coulomb part mu of the sliding force at slip speed |v_slip| >= 0;
!!   max_coefficient bounds it: |f_t| <= max_coefficient * f_normal + viscous * |v_slip|.
!!
!! Laws (chosen by &friction law, parameters from friction_cfg_t; Table 7 numbering):
!!   coulomb_step, adams_step  MSC Adams STEP regularised Coulomb (mu_s, mu_d, v_s, v_d): the base law
!!   ty1  static Coulomb: mu_s N, sticks up to mu_s N
!!   ty2  Coulomb + viscous: mu_s N + C_v |v|, sticks up to mu_s N
!!   ty3  regularised Coulomb: mu_s N (1 - exp(-3|v|/v0))/(1 - exp(-3)) below v0 = v_static
!!   ty4  stiction + dynamic Coulomb: slides with mu_d N, sticks up to mu_s N
!!   ty5  stiction + Stribeck + Coulomb + viscous: (mu_d + (mu_s - mu_d) exp(-(|v|/v_S)^delta)) N + C_v |v|
!!   ty6  modified Stribeck (+ viscous): mu_s N (1 - (|v| - v0)^2/v0^2) below v0, then
!!        (mu_d + (mu_s - mu_d) exp(-eps (|v|/v_S)^delta)) N; + C_v |v|
!!
!! Sticking. ty1, ty2, ty4 and ty5 jump at zero slip (sgn(v)); Table 7 states their stick branch
!! as min(F_e, mu_s N) with F_e the applied tangential force, which a footpad coupled to the legs
!! and the body cannot know. These laws set `has_stiction` and are evaluated with
!! stick_slip_force: an elastic-plastic "bristle" per footpad (a friction_state_t: z, the footpad's
!! tangential displacement from its stick anchor). The laws are immutable parameter objects; the
!! stick state belongs to the model state and is passed in, and the integrator works on a trial
!! copy of it that it commits with the step. While stuck the ground holds the footpad with the
!! spring-damper -k z - c v; when that force would exceed mu_s N the footpad slips with the law's
!! sliding force mu(|v|) N + C_v |v|, directed as that trial force (a return mapping: -v/|v| in
!! steady sliding, the held force's direction at break-away), the anchor being dragged along by
!! what the bristle cannot hold: spring and damper act on the bristle's deflection rate, the slip
!! velocity less the anchor's, so the deflection relaxes toward -f/k over c/k (implicit Euler over
!! the step h; at once without damping), and every state changes by O(h) in a step; it sticks
!! again when the trial force falls back inside the sliding force (a reversal or stop of the
!! slip). A footpad at rest
!! therefore stays at rest exactly (its anchor does not creep; the deflection is bounded by
!! mu_s N/k), and the switch happens on a force criterion, so nothing chatters.
!! coulomb_step, ty3 and ty6 are continuous through zero slip (regularised): the friction force
!! vanishes at zero slip, so a footpad on a slope creeps at the speed where mu(v) N equals the
!! downhill load (documented in docs/input/friction.md); they need no state.
!!
!! Building from the input. Every law module has a builder `build(b)` (ty1, ty2, ty4 share one
!! module: build_ty1, ...), b a friction_build_t holding the &friction input, the message prefix
!! and the messages so far. It appends the law-dependent checks (v_dynamic > v_static; the
!! stiction order mu_dynamic <= mu_static through b%wanted) and, unless b%check_only (b%wanted is
!! then .false.), the range checks of the parameters it uses (b%wanted), and allocates b%law (the
!! registry discards it when a check failed). With b%check_only that is the input validation
!! (check_friction_law_input), so deck validation and factory share one rule.
module landyn_friction_law
  use landyn_kinds, only: wp
  use landyn_config, only: friction_cfg_t, name_len, is_set
  use landyn_strings, only: quote_text
  use landyn_real_text, only: fmt_real
  use landyn_law_checks, only: law_build_t
  implicit none
  private

  public :: friction_law_t, friction_state_t, friction_build_t, two_coefficient_t, stribeck_curve_t
  public :: adams_step, opposing_force, default_stribeck_speed

  !> Stick state of one footpad (laws with has_stiction only).
  type :: friction_state_t
    real(wp) :: z(2) = 0.0_wp       !! bristle deflection: footpad displacement from its anchor, local (t1, t2) [m]
    logical :: stuck = .true.       !! in the stick state [-]
    integer :: n_transitions = 0    !! number of stick <-> slip switches so far [-]
  end type friction_state_t

  !> A footpad-ground friction law: immutable parameters (the stick state is a friction_state_t).
  type, abstract :: friction_law_t
    character(len=name_len) :: name = ''     !! law name as given in &friction law [-]
    logical :: has_stiction = .false.        !! discontinuous at zero slip: use stick_slip_force [-]
    real(wp) :: mu_stick = 0.0_wp            !! static coefficient bounding the stick force [-]
    real(wp) :: stick_stiffness = 1.0e8_wp   !! k of the stick spring [N/m]
    real(wp) :: stick_damping = 1.0e5_wp     !! c of the stick damper [N s/m]
    real(wp) :: viscous = 0.0_wp             !! C_v of the viscous term -C_v v_slip [N s/m]
  contains
    procedure :: friction_force                                !! sliding force mu(|v|) N + viscous, opposing the slip [N]
    procedure(coefficient_i), deferred :: coefficient          !! Coulomb part mu at a slip speed [-]
    procedure(max_coefficient_i), deferred :: max_coefficient  !! bound of mu over all slip speeds [-]
    procedure :: stick_slip_force                              !! force of a law with stiction, advancing its stick state [N]
  end type friction_law_t

  abstract interface
    !> Coulomb part of the friction coefficient at slip speed `speed`.
    pure function coefficient_i(self, speed) result(mu)
      import :: friction_law_t, wp
      class(friction_law_t), intent(in) :: self  !! the law
      real(wp), intent(in) :: speed              !! slip speed |v_slip| [m/s]
      real(wp) :: mu                             !! friction coefficient [-]
    end function coefficient_i

    !> Upper bound of the friction coefficient over all slip speeds (and of mu_stick).
    pure function max_coefficient_i(self) result(mu)
      import :: friction_law_t, wp
      class(friction_law_t), intent(in) :: self  !! the law
      real(wp) :: mu                             !! max coefficient [-]
    end function max_coefficient_i
  end interface

  !> What a friction law builder works on: the &friction input and the law it builds, besides the
  !! group, prefix, messages and check_only of law_build_t.
  type, extends(law_build_t) :: friction_build_t
    type(friction_cfg_t) :: cfg                    !! resolved &friction input
    class(friction_law_t), allocatable :: law      !! the law built (also when a check failed)
  contains
    procedure :: wanted => friction_wanted         !! the checks of a law in order; build the law?
  end type friction_build_t

  !> A law with a static and a dynamic coefficient (coulomb_step, ty5, ty6), bounded by the larger.
  type, abstract, extends(friction_law_t) :: two_coefficient_t
    real(wp) :: mu_static = 0.4_wp   !! static coefficient mu_s = F_S / N [-]
    real(wp) :: mu_dynamic = 0.4_wp  !! dynamic (Coulomb) coefficient mu_d = F_D / N [-]
  contains
    procedure :: max_coefficient => two_coefficient_max  !! max(mu_s, mu_d) [-]
  end type two_coefficient_t

  !> A two-coefficient law with a Stribeck curve exp(-(|v|/v_S)^delta) (ty5, ty6).
  type, abstract, extends(two_coefficient_t) :: stribeck_curve_t
    real(wp) :: v_stribeck = 1.0_wp  !! Stribeck speed v_S [m/s]
    real(wp) :: delta = 0.85_wp      !! Stribeck exponent [-]
  end type stribeck_curve_t

contains

  !> Table 8's Stribeck speed of a law: 0.1 m/s for ty6, 1 m/s otherwise (ty5).
  pure function default_stribeck_speed(law) result(v)
    character(len=*), intent(in) :: law  !! law name, lower case [-]
    real(wp) :: v                        !! v_S [m/s]
    if (trim(adjustl(law)) == 'ty6') then
      v = 0.1_wp
    else
      v = 1.0_wp
    end if
  end function default_stribeck_speed

  !> max(mu_s, mu_d).
  pure function two_coefficient_max(self) result(mu)
    class(two_coefficient_t), intent(in) :: self  !! the law
    real(wp) :: mu                                !! max(mu_s, mu_d) [-]
    mu = max(self%mu_static, self%mu_dynamic)
  end function two_coefficient_max

  ! ---------------------------------------------------------------- stick-slip (laws with stiction)

  !> Friction force of a law with stiction, advancing the footpad's stick state `state` by one step
  !! (the caller passes a trial copy and commits it with the step; the law is not changed).
  !! dx_slip is the footpad's tangential displacement since the previous call (the slip velocity
  !! times the step in a semi-implicit Euler scheme), made over the time h. See the module
  !! documentation.
  pure subroutine stick_slip_force(self, state, v_slip, dx_slip, h, f_normal, f_t, margin)
    class(friction_law_t), intent(in) :: self     !! the law
    type(friction_state_t), intent(inout) :: state  !! stick state of the footpad, advanced by the step
    real(wp), intent(in) :: v_slip(2)             !! slip velocity, local (t1, t2) [m/s]
    real(wp), intent(in) :: dx_slip(2)            !! tangential displacement since the last call, local [m]
    real(wp), intent(in) :: h                     !! time over which dx_slip was made (>= 0) [s]
    real(wp), intent(in) :: f_normal              !! normal force magnitude [N]
    real(wp), intent(out) :: f_t(2)               !! friction force on the footpad, local (t1, t2) [N]
    real(wp), intent(out), optional :: margin     !! switching function of the stick state: the yield limit of
                                                  !! the state passed in minus the trial force; the state
                                                  !! returned is stuck exactly when it is >= 0 (0 without
                                                  !! contact) [N]
    real(wp) :: z_tr(2), f_tr(2), n, lim, slide, fmag, speed, slid
    logical :: was_stuck

    n = max(f_normal, 0.0_wp)
    if (.not. (n > 0.0_wp)) then
      ! no contact: the next contact starts stuck, with an unloaded anchor where it touches down
      state%z = 0.0_wp
      state%stuck = .true.
      f_t = 0.0_wp
      if (present(margin)) margin = 0.0_wp
      return
    end if
    was_stuck = state%stuck
    z_tr = state%z + dx_slip
    f_tr = -self%stick_stiffness*z_tr - self%stick_damping*v_slip
    fmag = norm2(f_tr)
    ! magnitude of the law's sliding force at this slip speed, mu(|v|) N + C_v |v|
    speed = norm2(v_slip)
    if (speed > 0.0_wp) then
      slide = norm2(self%friction_force(v_slip, n))
    else
      slide = self%coefficient(0.0_wp)*n
    end if
    ! yield limit: static while stuck; while slipping the sliding force (inside it the slip has
    ! reversed or stopped)
    if (was_stuck) then
      lim = self%mu_stick*n
    else
      lim = slide
    end if
    if (present(margin)) margin = lim - fmag
    if (fmag <= lim) then
      state%stuck = .true.
      state%z = z_tr
      f_t = f_tr
    else
      ! slip: the sliding force, directed as the trial force (return mapping). In steady sliding
      ! that is -v_slip/|v_slip|; at break-away, when the slip velocity is still tiny and its
      ! direction meaningless, it is the direction of the force the footpad was held with.
      state%stuck = .false.
      f_t = (slide/fmag)*f_tr
      ! the anchor is dragged along by what the bristle (spring k and damper c in parallel)
      ! cannot hold: f = -k z - c (v - anchor rate) = f_tr - (k + c/h) slid (f_tr/fmag) gives the
      ! distance slid over h, (fmag - slide) h/(k h + c). Without damping z = -f_t/k.
      if (self%stick_damping > 0.0_wp) then
        slid = (fmag - slide)*max(h, 0.0_wp)/(self%stick_stiffness*max(h, 0.0_wp) + self%stick_damping)
      else
        slid = (fmag - slide)/self%stick_stiffness
      end if
      state%z = z_tr + (slid/fmag)*f_tr
    end if
    if (state%stuck .neqv. was_stuck) state%n_transitions = state%n_transitions + 1
  end subroutine stick_slip_force

  ! ---------------------------------------------------------------- helpers

  !> Force of magnitude mu*max(N,0) opposing v_slip; exactly zero when v_slip = 0.
  pure function opposing_force(mu, v_slip, f_normal) result(f_t)
    real(wp), intent(in) :: mu         !! friction coefficient [-]
    real(wp), intent(in) :: v_slip(2)  !! slip velocity [m/s]
    real(wp), intent(in) :: f_normal   !! normal force magnitude [N]
    real(wp) :: f_t(2)                 !! friction force [N]
    real(wp) :: speed

    speed = norm2(v_slip)
    if (speed > 0.0_wp) then
      f_t = (-mu*max(f_normal, 0.0_wp))*(v_slip/speed)   ! unit vector first: no overflow at tiny speed
    else
      f_t = 0.0_wp
    end if
  end function opposing_force

  !> Tangential friction force on the slipping footpad, local surface frame (t1, t2): the
  !! Coulomb part mu(|v_slip|) N opposing the slip plus the viscous term -C_v v_slip in contact.
  !! Laws without a viscous term may override it with opposing_force alone.
  pure function friction_force(self, v_slip, f_normal) result(f_t)
    class(friction_law_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: v_slip(2)          !! slip velocity of the footpad, local (t1, t2) [m/s]
    real(wp), intent(in) :: f_normal           !! normal force magnitude [N]
    real(wp) :: f_t(2)                         !! friction force on the footpad, local (t1, t2) [N]
    f_t = viscous_opposing_force(self%coefficient(norm2(v_slip)), self%viscous, v_slip, f_normal)
  end function friction_force

  !> opposing_force plus the viscous term -C_v v_slip, which acts only in contact (N > 0).
  pure function viscous_opposing_force(mu, c_v, v_slip, f_normal) result(f_t)
    real(wp), intent(in) :: mu         !! friction coefficient [-]
    real(wp), intent(in) :: c_v        !! viscous coefficient [N s/m]
    real(wp), intent(in) :: v_slip(2)  !! slip velocity [m/s]
    real(wp), intent(in) :: f_normal   !! normal force magnitude [N]
    real(wp) :: f_t(2)                 !! friction force [N]
    f_t = opposing_force(mu, v_slip, f_normal)
    if (f_normal > 0.0_wp) f_t = f_t - c_v*v_slip
  end function viscous_opposing_force

  !> MSC Adams STEP function: h0 + (h1 - h0) xi^2 (3 - 2 xi), xi = (x - x0)/(x1 - x0) clamped to [0, 1].
  !! Returns h0 for x <= x0 and h1 for x >= x1 (also when x1 <= x0, without dividing).
  elemental function adams_step(x, x0, h0, x1, h1) result(h)
    real(wp), intent(in) :: x   !! argument [any unit]
    real(wp), intent(in) :: x0  !! start of the transition [unit of x]
    real(wp), intent(in) :: h0  !! value at and below x0 [any unit]
    real(wp), intent(in) :: x1  !! end of the transition [unit of x]
    real(wp), intent(in) :: h1  !! value at and above x1 [unit of h0]
    real(wp) :: h               !! smoothed step value [unit of h0]
    real(wp) :: xi

    if (x <= x0) then
      h = h0
    else if (x >= x1) then
      h = h1
    else
      xi = (x - x0)/(x1 - x0)
      h = h0 + (h1 - h0)*xi*xi*(3.0_wp - 2.0_wp*xi)
    end if
  end function adams_step

  ! ---------------------------------------------------------------- checks of the &friction input

  !> The checks of a law, in this order: the stiction rule mu_dynamic <= mu_static (stiction_order:
  !! the law depends on it); then, when the law is to be built (not b%check_only; the result), the
  !! range checks every law makes (mu_static, mu_dynamic, v_static), the Stribeck parameters (when
  !! v_s is present: it returns the resolved Stribeck speed, stribeck_speed or the law's default),
  !! the stick spring-damper (stick) and the viscous term (stick or viscous). The builder may add
  !! its own checks, then allocates b%law.
  function friction_wanted(b, stiction_order, stick, viscous, v_s) result(go)
    class(friction_build_t), intent(inout) :: b      !! the build (input and messages)
    logical, intent(in), optional :: stiction_order  !! the law needs mu_dynamic <= mu_static [-]
    logical, intent(in), optional :: stick           !! the law sticks (checks k, c and C_v) [-]
    logical, intent(in), optional :: viscous         !! the law reads C_v [-]
    real(wp), intent(out), optional :: v_s           !! the law's Stribeck speed [m/s]
    logical :: go                                    !! build the law [-]
    if (flag(stiction_order)) &
      call b%require(b%cfg%mu_dynamic <= b%cfg%mu_static, 'mu_dynamic', b%cfg%mu_dynamic, '', &
                     'mu_dynamic <= mu_static = '//fmt_real(b%cfg%mu_static)//' for law '//quote_text(trim(b%cfg%law))// &
                        ' (stiction)')
    go = .not. b%check_only
    if (.not. go) return
    call b%require_nonnegative('mu_static', b%cfg%mu_static, '')
    call b%require_nonnegative('mu_dynamic', b%cfg%mu_dynamic, '')
    call b%require_positive('v_static', b%cfg%v_static, 'm/s')
    if (present(v_s)) then
      v_s = b%cfg%stribeck_speed
      if (.not. is_set(v_s)) v_s = default_stribeck_speed(b%key)
      call b%require_positive('stribeck_speed', v_s, 'm/s')
      call b%require_positive('stribeck_exponent', b%cfg%stribeck_exponent, '')
      call b%require_nonnegative('stribeck_decay', b%cfg%stribeck_decay, '')
    end if
    if (flag(stick)) then
      call b%require_positive('stick_stiffness', b%cfg%stick_stiffness, 'N/m')
      call b%require_nonnegative('stick_damping', b%cfg%stick_damping, 'N s/m')
    end if
    if (flag(stick) .or. flag(viscous)) call b%require_nonnegative('viscous', b%cfg%viscous, 'N s/m')
  end function friction_wanted

  !> An optional flag's value, .false. when absent.
  pure logical function flag(x)
    logical, intent(in), optional :: x  !! the flag [-]
    flag = .false.
    if (present(x)) flag = x
  end function flag

end module landyn_friction_law
