!> Footpad-ground friction laws (paper eq. 17, section 4.2, Tables 7-8; MODEL_NOTES base friction).
!!
!! Conventions
!! - v_slip is the 2-component tangential slip velocity of the footpad relative to the ground in
!!   the local surface frame (t1, t2) of landyn_terrain (use slip_velocity there).
!! - f_normal is the normal force magnitude F_Z (>= 0; negative values are treated as 0).
!! - friction_force returns the 2-component tangential force (t1, t2) the ground exerts on the
!!   footpad. It opposes the slip: f_t . v_slip <= 0, and it is exactly zero at zero slip.
!! - coefficient(speed) is the friction coefficient mu at slip speed |v_slip| >= 0;
!!   max_coefficient bounds it: |f_t| <= max_coefficient * f_normal.
!!
!! Adding a law: extend friction_law_t in this module, implement the deferred procedures
!! (pure, allocation-free) and add a `case` to make_friction_law. Laws of the form
!! f_t = -mu(|v|) N v/|v| can use `opposing_force`.
module landyn_friction
  use landyn_kinds, only: wp
  use landyn_config, only: friction_cfg_t, name_len
  implicit none
  private

  public :: friction_law_t, coulomb_step_t
  public :: coulomb_step, make_friction_law
  public :: adams_step, opposing_force
  public :: friction_law_names

  !> Names accepted in &friction law, for messages and documentation.
  character(len=*), parameter :: friction_law_names = 'coulomb_step'

  !> A footpad-ground friction law.
  type, abstract :: friction_law_t
    character(len=name_len) :: name = ''  !! law name as given in &friction law [-]
  contains
    procedure(friction_force_i), deferred :: friction_force
    procedure(coefficient_i), deferred :: coefficient
    procedure(max_coefficient_i), deferred :: max_coefficient
  end type friction_law_t

  abstract interface
    !> Tangential friction force on the footpad, local surface frame (t1, t2).
    pure function friction_force_i(self, v_slip, f_normal) result(f_t)
      import :: friction_law_t, wp
      class(friction_law_t), intent(in) :: self  !! the law
      real(wp), intent(in) :: v_slip(2)          !! slip velocity of the footpad, local (t1, t2) [m/s]
      real(wp), intent(in) :: f_normal           !! normal force magnitude [N]
      real(wp) :: f_t(2)                         !! friction force on the footpad, local (t1, t2) [N]
    end function friction_force_i

    !> Friction coefficient at slip speed `speed`.
    pure function coefficient_i(self, speed) result(mu)
      import :: friction_law_t, wp
      class(friction_law_t), intent(in) :: self  !! the law
      real(wp), intent(in) :: speed              !! slip speed |v_slip| [m/s]
      real(wp) :: mu                             !! friction coefficient [-]
    end function coefficient_i

    !> Upper bound of the friction coefficient over all slip speeds.
    pure function max_coefficient_i(self) result(mu)
      import :: friction_law_t, wp
      class(friction_law_t), intent(in) :: self  !! the law
      real(wp) :: mu                             !! max coefficient [-]
    end function max_coefficient_i
  end interface

  !> Regularised Coulomb friction as in MSC Adams contacts ('coulomb_step'):
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

contains

  !> Build the law named by cfg%law (case-insensitive) from the &friction input.
  !! stat /= 0 and errmsg set for an unknown name or invalid parameters (law is then unallocated).
  subroutine make_friction_law(cfg, law, stat, errmsg)
    type(friction_cfg_t), intent(in) :: cfg                      !! resolved &friction input
    class(friction_law_t), allocatable, intent(out) :: law       !! the law
    integer, intent(out) :: stat                                 !! 0 on success
    character(len=*), intent(out) :: errmsg                      !! reason of a failure, '' on success

    stat = 0
    errmsg = ''
    select case (lower(trim(adjustl(cfg%law))))
    case ('coulomb_step')
      if (.not. (cfg%mu_static >= 0.0_wp .and. cfg%mu_static <= huge(1.0_wp))) then
        call fail('&friction mu_static must be a finite number >= 0')
      else if (.not. (cfg%mu_dynamic >= 0.0_wp .and. cfg%mu_dynamic <= huge(1.0_wp))) then
        call fail('&friction mu_dynamic must be a finite number >= 0')
      else if (.not. (cfg%v_static > 0.0_wp .and. cfg%v_static <= huge(1.0_wp))) then
        call fail('&friction v_static must be a finite number > 0')
      else if (.not. (cfg%v_dynamic >= cfg%v_static .and. cfg%v_dynamic <= huge(1.0_wp))) then
        call fail('&friction v_dynamic must be a finite number >= v_static')
      else
        allocate (law, source=coulomb_step(cfg%mu_static, cfg%mu_dynamic, cfg%v_static, cfg%v_dynamic))
      end if
    case default
      call fail("&friction law = '"//trim(adjustl(cfg%law))//"' is not known; known laws: "//friction_law_names)
    end select

  contains

    subroutine fail(msg)
      character(len=*), intent(in) :: msg  !! error message
      stat = 1
      errmsg = msg
    end subroutine fail

  end subroutine make_friction_law

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

  pure function lower(s) result(t)
    character(len=*), intent(in) :: s  !! text
    character(len=len(s)) :: t         !! s in lower case
    integer :: i, c
    t = s
    do i = 1, len(s)
      c = iachar(s(i:i))
      if (c >= iachar('A') .and. c <= iachar('Z')) t(i:i) = achar(c + 32)
    end do
  end function lower

end module landyn_friction
