!> Footpad-ground friction laws (paper eq. 17, section 4.2, Tables 7-8; docs/model_conventions.md base friction).
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
!! steady sliding, the held force's direction at break-away), the anchor being dragged along
!! (z = -f/k); it sticks again when the trial force falls back inside the sliding force (a
!! reversal or stop of the slip). A footpad at rest
!! therefore stays at rest exactly (its anchor does not creep; the deflection is bounded by
!! mu_s N/k), and the switch happens on a force criterion, so nothing chatters.
!! coulomb_step, ty3 and ty6 are continuous through zero slip (regularised): the friction force
!! vanishes at zero slip, so a footpad on a slope creeps at the speed where mu(v) N equals the
!! downhill load (documented in docs/input/friction.md); they need no state.
!!
!! Adding a law: extend friction_law_t in this module, implement the deferred procedures (pure,
!! allocation-free), set has_stiction and mu_stick if it sticks, add its name to
!! friction_law_names and a `case` to make_friction_law.
module landyn_friction
  use landyn_kinds, only: wp
  use landyn_config, only: friction_cfg_t, name_len, is_set
  use landyn_strings, only: lower_case
  implicit none
  private

  public :: friction_law_t, friction_state_t
  public :: coulomb_step_t, coulomb_t, regularized_coulomb_t, stribeck_t, modified_stribeck_t
  public :: coulomb_step, coulomb, regularized_coulomb, stribeck, modified_stribeck, make_friction_law
  public :: adams_step, opposing_force, default_stribeck_speed
  public :: friction_law_names

  !> Names accepted in &friction law, for messages and documentation.
  character(len=*), parameter :: friction_law_names = 'coulomb_step, adams_step, ty1, ty2, ty3, ty4, ty5, ty6'

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
  contains
    procedure(friction_force_i), deferred :: friction_force
    procedure(coefficient_i), deferred :: coefficient
    procedure(max_coefficient_i), deferred :: max_coefficient
    procedure :: stick_slip_force
  end type friction_law_t

  abstract interface
    !> Tangential friction force on the slipping footpad, local surface frame (t1, t2).
    pure function friction_force_i(self, v_slip, f_normal) result(f_t)
      import :: friction_law_t, wp
      class(friction_law_t), intent(in) :: self  !! the law
      real(wp), intent(in) :: v_slip(2)          !! slip velocity of the footpad, local (t1, t2) [m/s]
      real(wp), intent(in) :: f_normal           !! normal force magnitude [N]
      real(wp) :: f_t(2)                         !! friction force on the footpad, local (t1, t2) [N]
    end function friction_force_i

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

  !> Regularised Coulomb friction as in MSC Adams contacts ('coulomb_step', alias 'adams_step'):
  !!   v >= v_d:        mu = mu_d
  !!   v_s <= v < v_d:  mu = STEP(v, v_s, mu_s, v_d, mu_d)
  !!   v < v_s:         mu = STEP(v, 0, 0, v_s, mu_s)
  !! with v = |v_slip| and f_t = -mu(v) N v_slip/|v_slip|.
  type, extends(friction_law_t) :: coulomb_step_t
    real(wp) :: mu_static = 0.4_wp   !! static coefficient mu_s [-]
    real(wp) :: mu_dynamic = 0.4_wp  !! dynamic coefficient mu_d [-]
    real(wp) :: v_static = 0.1_wp    !! stiction transition slip speed v_s [m/s]
    real(wp) :: v_dynamic = 1.0_wp   !! friction transition slip speed v_d [m/s]
  contains
    procedure :: friction_force => coulomb_step_force
    procedure :: coefficient => coulomb_step_coefficient
    procedure :: max_coefficient => coulomb_step_max_coefficient
  end type coulomb_step_t

  !> Coulomb friction with stiction (ty1, ty2, ty4): slides with mu_slide N + C_v |v|, sticks up
  !! to mu_stick N.
  type, extends(friction_law_t) :: coulomb_t
    real(wp) :: mu_slide = 0.4_wp    !! sliding coefficient (mu_s for ty1/ty2, mu_d for ty4) [-]
    real(wp) :: viscous = 0.0_wp     !! C_v [N s/m]
  contains
    procedure :: friction_force => coulomb_force
    procedure :: coefficient => coulomb_coefficient
    procedure :: max_coefficient => coulomb_max_coefficient
  end type coulomb_t

  !> Regularised Coulomb friction (ty3): mu_s (1 - exp(-3|v|/v0))/(1 - exp(-3)) below v0, mu_s beyond.
  type, extends(friction_law_t) :: regularized_coulomb_t
    real(wp) :: mu_static = 0.4_wp   !! mu_s [-]
    real(wp) :: v0 = 0.1_wp          !! regularisation speed v0 [m/s]
  contains
    procedure :: friction_force => regularized_coulomb_force
    procedure :: coefficient => regularized_coulomb_coefficient
    procedure :: max_coefficient => regularized_coulomb_max_coefficient
  end type regularized_coulomb_t

  !> Stiction + Stribeck + Coulomb + viscous (ty5): mu = mu_d + (mu_s - mu_d) exp(-(|v|/v_S)^delta),
  !! plus C_v |v|; sticks up to mu_s N.
  type, extends(friction_law_t) :: stribeck_t
    real(wp) :: mu_static = 0.4_wp   !! F_S / N [-]
    real(wp) :: mu_dynamic = 0.4_wp  !! F_D / N (Coulomb level) [-]
    real(wp) :: v_stribeck = 1.0_wp  !! v_S [m/s]
    real(wp) :: delta = 0.85_wp      !! Stribeck exponent [-]
    real(wp) :: viscous = 100.0_wp   !! C_v [N s/m]
  contains
    procedure :: friction_force => stribeck_force
    procedure :: coefficient => stribeck_coefficient
    procedure :: max_coefficient => stribeck_max_coefficient
  end type stribeck_t

  !> Stiction + modified Stribeck + Coulomb + viscous (ty6), regularised at zero slip:
  !!   |v| < v0:  mu = mu_s (1 - (|v| - v0)^2 / v0^2)
  !!   |v| >= v0: mu = mu_d + (mu_s - mu_d) exp(-eps (|v|/v_S)^delta)
  !! plus C_v |v|.
  type, extends(friction_law_t) :: modified_stribeck_t
    real(wp) :: mu_static = 0.4_wp   !! F_S / N [-]
    real(wp) :: mu_dynamic = 0.4_wp  !! F_C / N [-]
    real(wp) :: v0 = 0.1_wp          !! stiction velocity v0 [m/s]
    real(wp) :: v_stribeck = 0.1_wp  !! v_S [m/s]
    real(wp) :: eps = 0.85_wp        !! epsilon [-]
    real(wp) :: delta = 0.85_wp      !! Stribeck exponent [-]
    real(wp) :: viscous = 100.0_wp   !! C_v [N s/m]
  contains
    procedure :: friction_force => modified_stribeck_force
    procedure :: coefficient => modified_stribeck_coefficient
    procedure :: max_coefficient => modified_stribeck_max_coefficient
  end type modified_stribeck_t

contains

  !> Build the law named by cfg%law (case-insensitive) from the &friction input.
  !! stat /= 0 and errmsg set for an unknown name or invalid parameters (law is then unallocated).
  subroutine make_friction_law(cfg, law, stat, errmsg)
    type(friction_cfg_t), intent(in) :: cfg                      !! resolved &friction input
    class(friction_law_t), allocatable, intent(out) :: law       !! the law
    integer, intent(out) :: stat                                 !! 0 on success
    character(len=*), intent(out) :: errmsg                      !! reason of a failure, '' on success
    character(len=name_len) :: key
    real(wp) :: vs

    stat = 0
    errmsg = ''
    key = lower_case(trim(adjustl(cfg%law)))
    vs = cfg%stribeck_speed
    if (.not. is_set(vs)) vs = default_stribeck_speed(key)
    if (.not. (cfg%mu_static >= 0.0_wp .and. cfg%mu_static <= huge(1.0_wp))) then
      call fail('&friction mu_static must be a finite number >= 0')
    else if (.not. (cfg%mu_dynamic >= 0.0_wp .and. cfg%mu_dynamic <= huge(1.0_wp))) then
      call fail('&friction mu_dynamic must be a finite number >= 0')
    else if (.not. (cfg%v_static > 0.0_wp .and. cfg%v_static <= huge(1.0_wp))) then
      call fail('&friction v_static must be a finite number > 0')
    end if
    if (stat /= 0) return
    select case (key)
    case ('coulomb_step', 'adams_step')
      if (.not. (cfg%v_dynamic >= cfg%v_static .and. cfg%v_dynamic <= huge(1.0_wp))) then
        call fail('&friction v_dynamic must be a finite number >= v_static')
      else
        allocate (law, source=coulomb_step(cfg%mu_static, cfg%mu_dynamic, cfg%v_static, cfg%v_dynamic))
        law%name = key
      end if
    case ('ty3')
      allocate (law, source=regularized_coulomb(cfg%mu_static, cfg%v_static))
    case ('ty6')
      if (check_stribeck()) allocate (law, source=modified_stribeck(cfg%mu_static, cfg%mu_dynamic, cfg%v_static, &
                                                                     vs, cfg%stribeck_decay, cfg%stribeck_exponent, &
                                                                     cfg%viscous))
    case ('ty1', 'ty2', 'ty4', 'ty5')
      if (.not. (cfg%stick_stiffness > 0.0_wp .and. cfg%stick_stiffness <= huge(1.0_wp))) then
        call fail('&friction stick_stiffness must be a finite number > 0')
      else if (.not. (cfg%stick_damping >= 0.0_wp .and. cfg%stick_damping <= huge(1.0_wp))) then
        call fail('&friction stick_damping must be a finite number >= 0')
      else if (.not. (cfg%viscous >= 0.0_wp .and. cfg%viscous <= huge(1.0_wp))) then
        call fail('&friction viscous must be a finite number >= 0')
      end if
      if (stat /= 0) return
      select case (key)
      case ('ty1')
        allocate (law, source=coulomb(cfg%mu_static, cfg%mu_static, 0.0_wp, cfg%stick_stiffness, cfg%stick_damping))
      case ('ty2')
        allocate (law, source=coulomb(cfg%mu_static, cfg%mu_static, cfg%viscous, cfg%stick_stiffness, &
                                      cfg%stick_damping))
      case ('ty4')
        if (.not. (cfg%mu_dynamic <= cfg%mu_static)) then
          call fail('&friction mu_dynamic must be <= mu_static for ty4 (stiction)')
        else
          allocate (law, source=coulomb(cfg%mu_static, cfg%mu_dynamic, 0.0_wp, cfg%stick_stiffness, &
                                        cfg%stick_damping))
        end if
      case default   ! ty5
        if (check_stribeck()) allocate (law, source=stribeck(cfg%mu_static, cfg%mu_dynamic, vs, &
                                                             cfg%stribeck_exponent, cfg%viscous, &
                                                             cfg%stick_stiffness, cfg%stick_damping))
      end select
      if (allocated(law)) law%name = key
    case default
      call fail("&friction law = '"//trim(adjustl(cfg%law))//"' is not known; known laws: "//friction_law_names)
    end select

  contains

    subroutine fail(msg)
      character(len=*), intent(in) :: msg  !! error message
      stat = 1
      errmsg = msg
    end subroutine fail

    !> Checks the Stribeck parameters (ty5, ty6); .true. when valid.
    logical function check_stribeck()
      check_stribeck = .false.
      if (.not. (cfg%mu_dynamic <= cfg%mu_static)) then
        call fail('&friction mu_dynamic must be <= mu_static for '//trim(key)//' (stiction)')
      else if (.not. (vs > 0.0_wp .and. vs <= huge(1.0_wp))) then
        call fail('&friction stribeck_speed must be a finite number > 0')
      else if (.not. (cfg%stribeck_exponent > 0.0_wp .and. cfg%stribeck_exponent <= huge(1.0_wp))) then
        call fail('&friction stribeck_exponent must be a finite number > 0')
      else if (.not. (cfg%stribeck_decay >= 0.0_wp .and. cfg%stribeck_decay <= huge(1.0_wp))) then
        call fail('&friction stribeck_decay must be a finite number >= 0')
      else if (.not. (cfg%viscous >= 0.0_wp .and. cfg%viscous <= huge(1.0_wp))) then
        call fail('&friction viscous must be a finite number >= 0')
      else
        check_stribeck = .true.
      end if
    end function check_stribeck

  end subroutine make_friction_law

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

  ! ---------------------------------------------------------------- constructors

  !> coulomb_step law with the given parameters (0 < v_static <= v_dynamic expected).
  pure function coulomb_step(mu_static, mu_dynamic, v_static, v_dynamic) result(law)
    real(wp), intent(in) :: mu_static   !! mu_s [-]
    real(wp), intent(in) :: mu_dynamic  !! mu_d [-]
    real(wp), intent(in) :: v_static    !! v_s [m/s]
    real(wp), intent(in) :: v_dynamic   !! v_d [m/s]
    type(coulomb_step_t) :: law         !! the law
    law%name = 'coulomb_step'
    law%mu_static = mu_static
    law%mu_dynamic = mu_dynamic
    law%v_static = v_static
    law%v_dynamic = v_dynamic
  end function coulomb_step

  !> Coulomb law with stiction (name 'ty1'; the factory renames it ty2/ty4).
  pure function coulomb(mu_stick, mu_slide, viscous, stick_stiffness, stick_damping) result(law)
    real(wp), intent(in) :: mu_stick         !! static coefficient [-]
    real(wp), intent(in) :: mu_slide         !! sliding coefficient [-]
    real(wp), intent(in) :: viscous          !! C_v [N s/m]
    real(wp), intent(in) :: stick_stiffness  !! k, > 0 [N/m]
    real(wp), intent(in) :: stick_damping    !! c [N s/m]
    type(coulomb_t) :: law                   !! the law
    law%name = 'ty1'
    law%has_stiction = .true.
    law%mu_stick = mu_stick
    law%mu_slide = mu_slide
    law%viscous = viscous
    law%stick_stiffness = stick_stiffness
    law%stick_damping = stick_damping
  end function coulomb

  !> ty3 law with the given parameters.
  pure function regularized_coulomb(mu_static, v0) result(law)
    real(wp), intent(in) :: mu_static    !! mu_s [-]
    real(wp), intent(in) :: v0           !! regularisation speed, > 0 [m/s]
    type(regularized_coulomb_t) :: law   !! the law
    law%name = 'ty3'
    law%mu_static = mu_static
    law%v0 = v0
  end function regularized_coulomb

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
    law%name = 'ty5'
    law%has_stiction = .true.
    law%mu_stick = mu_static
    law%mu_static = mu_static
    law%mu_dynamic = mu_dynamic
    law%v_stribeck = v_stribeck
    law%delta = delta
    law%viscous = viscous
    law%stick_stiffness = stick_stiffness
    law%stick_damping = stick_damping
  end function stribeck

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
    law%name = 'ty6'
    law%mu_static = mu_static
    law%mu_dynamic = mu_dynamic
    law%v0 = v0
    law%v_stribeck = v_stribeck
    law%eps = eps
    law%delta = delta
    law%viscous = viscous
  end function modified_stribeck

  ! ---------------------------------------------------------------- stick-slip (laws with stiction)

  !> Friction force of a law with stiction, advancing the footpad's stick state `state` by one step
  !! (the caller passes a trial copy and commits it with the step; the law is not changed).
  !! dx_slip is the footpad's tangential displacement since the previous call (the slip velocity
  !! times the step in a semi-implicit Euler scheme). See the module documentation.
  pure subroutine stick_slip_force(self, state, v_slip, dx_slip, f_normal, f_t)
    class(friction_law_t), intent(in) :: self     !! the law
    type(friction_state_t), intent(inout) :: state  !! stick state of the footpad, advanced by the step
    real(wp), intent(in) :: v_slip(2)             !! slip velocity, local (t1, t2) [m/s]
    real(wp), intent(in) :: dx_slip(2)            !! tangential displacement since the last call, local [m]
    real(wp), intent(in) :: f_normal              !! normal force magnitude [N]
    real(wp), intent(out) :: f_t(2)               !! friction force on the footpad, local (t1, t2) [N]
    real(wp) :: z_tr(2), f_tr(2), n, lim, slide, fmag, speed
    logical :: was_stuck

    n = max(f_normal, 0.0_wp)
    if (.not. (n > 0.0_wp)) then
      ! no contact: the next contact starts stuck, with an unloaded anchor where it touches down
      state%z = 0.0_wp
      state%stuck = .true.
      f_t = 0.0_wp
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
      state%z = -f_t/self%stick_stiffness    ! the anchor is dragged along
    end if
    if (state%stuck .neqv. was_stuck) state%n_transitions = state%n_transitions + 1
  end subroutine stick_slip_force

  ! ---------------------------------------------------------------- coulomb_step

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

  pure function coulomb_step_max_coefficient(self) result(mu)
    class(coulomb_step_t), intent(in) :: self  !! the law
    real(wp) :: mu                             !! max(mu_s, mu_d) [-]
    mu = max(self%mu_static, self%mu_dynamic)
  end function coulomb_step_max_coefficient

  pure function coulomb_step_force(self, v_slip, f_normal) result(f_t)
    class(coulomb_step_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: v_slip(2)          !! slip velocity, local (t1, t2) [m/s]
    real(wp), intent(in) :: f_normal           !! normal force magnitude [N]
    real(wp) :: f_t(2)                         !! friction force, local (t1, t2) [N]
    f_t = opposing_force(self%coefficient(norm2(v_slip)), v_slip, f_normal)
  end function coulomb_step_force

  ! ---------------------------------------------------------------- ty1, ty2, ty4

  pure function coulomb_coefficient(self, speed) result(mu)
    class(coulomb_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: speed         !! slip speed (no effect) [m/s]
    real(wp) :: mu                        !! sliding coefficient [-]
    mu = self%mu_slide + 0.0_wp*speed     ! speed-independent (the product only reads speed)
  end function coulomb_coefficient

  pure function coulomb_max_coefficient(self) result(mu)
    class(coulomb_t), intent(in) :: self  !! the law
    real(wp) :: mu                        !! max(mu_stick, mu_slide) [-]
    mu = max(self%mu_stick, self%mu_slide)
  end function coulomb_max_coefficient

  pure function coulomb_force(self, v_slip, f_normal) result(f_t)
    class(coulomb_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: v_slip(2)     !! slip velocity [m/s]
    real(wp), intent(in) :: f_normal      !! normal force magnitude [N]
    real(wp) :: f_t(2)                    !! friction force [N]
    f_t = viscous_opposing_force(self%mu_slide, self%viscous, v_slip, f_normal)
  end function coulomb_force

  ! ---------------------------------------------------------------- ty3

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

  pure function regularized_coulomb_max_coefficient(self) result(mu)
    class(regularized_coulomb_t), intent(in) :: self  !! the law
    real(wp) :: mu                                    !! mu_s [-]
    mu = self%mu_static
  end function regularized_coulomb_max_coefficient

  pure function regularized_coulomb_force(self, v_slip, f_normal) result(f_t)
    class(regularized_coulomb_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: v_slip(2)                 !! slip velocity [m/s]
    real(wp), intent(in) :: f_normal                  !! normal force magnitude [N]
    real(wp) :: f_t(2)                                !! friction force [N]
    f_t = opposing_force(self%coefficient(norm2(v_slip)), v_slip, f_normal)
  end function regularized_coulomb_force

  ! ---------------------------------------------------------------- ty5

  pure function stribeck_coefficient(self, speed) result(mu)
    class(stribeck_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: speed          !! slip speed [m/s]
    real(wp) :: mu                         !! Coulomb + Stribeck coefficient [-]
    mu = self%mu_dynamic + (self%mu_static - self%mu_dynamic)*exp(-(abs(speed)/self%v_stribeck)**self%delta)
  end function stribeck_coefficient

  pure function stribeck_max_coefficient(self) result(mu)
    class(stribeck_t), intent(in) :: self  !! the law
    real(wp) :: mu                         !! max(mu_s, mu_d) [-]
    mu = max(self%mu_static, self%mu_dynamic)
  end function stribeck_max_coefficient

  pure function stribeck_force(self, v_slip, f_normal) result(f_t)
    class(stribeck_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: v_slip(2)      !! slip velocity [m/s]
    real(wp), intent(in) :: f_normal       !! normal force magnitude [N]
    real(wp) :: f_t(2)                     !! friction force [N]
    f_t = viscous_opposing_force(self%coefficient(norm2(v_slip)), self%viscous, v_slip, f_normal)
  end function stribeck_force

  ! ---------------------------------------------------------------- ty6

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

  pure function modified_stribeck_max_coefficient(self) result(mu)
    class(modified_stribeck_t), intent(in) :: self  !! the law
    real(wp) :: mu                                  !! max(mu_s, mu_d) [-]
    mu = max(self%mu_static, self%mu_dynamic)
  end function modified_stribeck_max_coefficient

  pure function modified_stribeck_force(self, v_slip, f_normal) result(f_t)
    class(modified_stribeck_t), intent(in) :: self  !! the law
    real(wp), intent(in) :: v_slip(2)               !! slip velocity [m/s]
    real(wp), intent(in) :: f_normal                !! normal force magnitude [N]
    real(wp) :: f_t(2)                              !! friction force [N]
    f_t = viscous_opposing_force(self%coefficient(norm2(v_slip)), self%viscous, v_slip, f_normal)
  end function modified_stribeck_force

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

end module landyn_friction
