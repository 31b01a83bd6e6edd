!> Run-health checks: is a finished run physically meaningful? Checks of the resolved input
!! (body mass against leg mass, coincident gears) and of the finished result (initial
!! penetration, strut lengths within their geometry, energy audit, finite peaks), with the
!! thresholds of docs/health.md. Each check passes, warns (the result is doubtful; exit status
!! unchanged) or fails (the run is meaningless; landyn exits 6, landyn_study and landyn_batch mark
!! the run/case). Uses only the resolved input and the components of sim_result_t, not model
!! internals, so it is independent of the time integration.
!!
!! Library code: nothing here stops or prints, except into a unit the caller passes.
module landyn_health
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use landyn_kinds, only: wp
  use landyn_config, only: landyn_input_t
  use landyn_simulation, only: sim_result_t
  implicit none
  private

  public :: health_t, check_health, check_input_health, write_health, health_ok, health_warn, health_fail, n_checks, check_names
  public :: leg_mass_warn, leg_mass_fail, gear_separation_min, initial_penetration_max, residual_warn, &
            residual_fail, overload_warn

  integer, parameter :: health_ok = 0     !! check passed [-]
  integer, parameter :: health_warn = 1   !! result doubtful [-]
  integer, parameter :: health_fail = 2   !! run meaningless [-]

  integer, parameter :: n_checks = 6   !! number of health checks [-]
  !> Names of the health checks, in the order of health_t%result.
  character(len=24), parameter :: check_names(n_checks) = [character(len=24) :: &
    'leg_mass', 'gear_separation', 'initial_penetration', 'strut_length', 'energy_residual', 'finite_peaks']

  ! Thresholds (docs/health.md)
  real(wp), parameter :: leg_mass_warn = 0.25_wp            !! legs / total mass above this: warning [-]
  real(wp), parameter :: leg_mass_fail = 0.5_wp             !! legs / total mass at or above this: failure [-]
  real(wp), parameter :: gear_separation_min = 0.05_wp      !! closest two gears' joints a or d may come [m]
  real(wp), parameter :: initial_penetration_max = 1.0e-3_wp  !! deepest footpad below ground at t = 0 [m]
  real(wp), parameter :: residual_warn = 0.01_wp            !! |energy residual| above this: warning [-]
  real(wp), parameter :: residual_fail = 0.10_wp            !! |energy residual| above this: failure [-]
  real(wp), parameter :: overload_warn = 1000.0_wp          !! peak overload above this: warning [g]

  !> Outcome of every check.
  type :: health_t
    integer :: result(n_checks) = health_ok              !! per check: health_ok, health_warn or health_fail [-]
    character(len=:), allocatable :: messages            !! one line per check that did not pass, '' if none [-]
  contains
    procedure :: status => health_status   !! the worst level over all checks [-]
  end type health_t

contains

  !> Worst result of all checks: health_ok, health_warn or health_fail.
  pure function health_status(self) result(s)
    class(health_t), intent(in) :: self   !! checks [-]
    integer :: s                          !! worst result [-]
    s = maxval(self%result)
  end function health_status

  !> The checks of the input alone (leg mass, gear separation): callable before the run.
  subroutine check_input_health(inp, h)
    type(landyn_input_t), intent(in) :: inp    !! resolved, validated input [-]
    type(health_t), intent(out) :: h           !! outcome [-]
    type(sim_result_t) :: none
    call check_health(inp, none, h)
  end subroutine check_input_health

  !> Run every check on the resolved input `inp` and the finished result `res` (a result with no
  !! stored sample: the input checks only).
  subroutine check_health(inp, res, h)
    type(landyn_input_t), intent(in) :: inp    !! resolved, validated input [-]
    type(sim_result_t), intent(in) :: res      !! finished run [-]
    type(health_t), intent(out) :: h           !! outcome [-]
    integer :: ng, n

    h%messages = ''
    ng = inp%gears%n_gears
    call check_leg_mass(inp, ng, h)
    call check_gear_separation(inp, ng, h)
    n = res%n_out
    call check_initial_penetration(res, ng, n, h)
    call check_strut_lengths(res, ng, n, h)
    if (n < 1) return   ! input checks only
    call check_energy_residual(res, h)
    call check_finite_peaks(res, h)
  end subroutine check_health

  !> Check 1: the legs' mass against the total mass.
  subroutine check_leg_mass(inp, ng, h)
    type(landyn_input_t), intent(in) :: inp    !! resolved, validated input [-]
    integer, intent(in) :: ng                  !! number of gears [-]
    type(health_t), intent(inout) :: h         !! outcome so far [-]
    real(wp) :: legs, ratio
    character(len=64) :: b1, b2

    legs = real(ng, wp)*(inp%primary%outer_mass + inp%primary%inner_mass + inp%primary%footpad_mass + &
                         2.0_wp*(inp%secondary%outer_mass + inp%secondary%inner_mass))
    ratio = legs/inp%lander%mass
    write (b1, '(es10.3)') legs
    write (b2, '(f0.1)') 100.0_wp*ratio
    if (ratio >= leg_mass_fail) then
      call put(h, 1, health_fail, 'the legs weigh '//trim(adjustl(b1))//' kg, '//trim(b2)//' % of &lander mass '// &
               '(which includes them); at least 50 % is meaningless for a body carried by legs')
    else if (ratio > leg_mass_warn) then
      call put(h, 1, health_warn, 'the legs weigh '//trim(adjustl(b1))//' kg, '//trim(b2)//' % of &lander mass; '// &
               'above 25 % the legs'' inertia dominates the body''s')
    end if
  end subroutine check_leg_mass

  !> Check 2: coincident or stacked gears (upper joints a or footpad joints d too close).
  subroutine check_gear_separation(inp, ng, h)
    type(landyn_input_t), intent(in) :: inp    !! resolved, validated input [-]
    integer, intent(in) :: ng                  !! number of gears [-]
    type(health_t), intent(inout) :: h         !! outcome so far [-]
    real(wp) :: d, worst
    integer :: i, j
    character(len=64) :: b1, b2

    worst = huge(1.0_wp)
    do i = 1, ng - 1
      do j = i + 1, ng
        d = min(norm2(inp%gears%point_a(:, i) - inp%gears%point_a(:, j)), &
                norm2(inp%gears%point_d(:, i) - inp%gears%point_d(:, j)))
        if (d < worst) then
          worst = d
          write (b1, '(i0,a,i0)') i, ' and ', j
        end if
      end do
    end do
    if (worst < gear_separation_min) then
      write (b2, '(es10.3)') worst
      call put(h, 2, health_fail, 'gears '//trim(b1)//' coincide (joints a or d '//trim(adjustl(b2))// &
               ' m apart; at least 0.05 m): stacked legs, check &gears rotation and points')
    end if
  end subroutine check_gear_separation

  !> Check 3: initial penetration (first stored sample).
  subroutine check_initial_penetration(res, ng, n, h)
    type(sim_result_t), intent(in) :: res      !! finished run [-]
    integer, intent(in) :: ng                  !! number of gears [-]
    integer, intent(in) :: n                   !! stored samples [-]
    type(health_t), intent(inout) :: h         !! outcome so far [-]
    real(wp) :: r
    character(len=64) :: b1

    if (n < 1 .or. .not. allocated(res%penetration)) return
    r = extreme(res%penetration(1:ng, 1), largest=.true.)
    if (r > initial_penetration_max) then
      write (b1, '(es10.3)') r
      call put(h, 3, health_fail, 'a footpad starts '//trim(adjustl(b1))//' m below the ground (at most 1 mm): '// &
               'check &initial_state position and &terrain')
    end if
  end subroutine check_initial_penetration

  !> Check 4: strut lengths within their geometry (positive and finite at every stored sample).
  subroutine check_strut_lengths(res, ng, n, h)
    type(sim_result_t), intent(in) :: res      !! finished run [-]
    integer, intent(in) :: ng                  !! number of gears [-]
    integer, intent(in) :: n                   !! stored samples [-]
    type(health_t), intent(inout) :: h         !! outcome so far [-]
    real(wp) :: r
    integer :: ig, k
    character(len=64) :: b1, b2

    if (n < 1 .or. .not. allocated(res%strut_length)) return
    do ig = 1, ng
      do k = 1, size(res%strut_length, 1)
        r = extreme(res%strut_length(k, ig, 1:n), largest=.false.)
        if (r <= 0.0_wp) then
          write (b1, '(es10.3)') r
          write (b2, '(i0,a,i0)') ig, ', strut ', k
          call put(h, 4, health_fail, 'gear '//trim(b2)//': strut length reaches '//trim(adjustl(b1))// &
                   ' m (must stay positive): the stroke exceeds the strut''s geometry; check &primary_strut '// &
                   'stage_end and &secondary_strut strokes')
        end if
      end do
    end do
  end subroutine check_strut_lengths

  !> maxval(x) (largest) or minval(x) (not largest), or huge / -huge when x holds a value that is
  !! not finite: the value a check compares with its threshold, a non-finite one failing it
  !! (finiteness first: comparing a NaN traps in Debug builds).
  pure real(wp) function extreme(x, largest) result(r)
    real(wp), intent(in) :: x(:)               !! values [any unit]
    logical, intent(in) :: largest             !! the largest (else the smallest) [-]
    if (all(ieee_is_finite(x))) then
      r = merge(maxval(x), minval(x), largest)
    else
      r = merge(huge(1.0_wp), -huge(1.0_wp), largest)
    end if
  end function extreme

  !> Check 5: the energy audit's residual.
  subroutine check_energy_residual(res, h)
    type(sim_result_t), intent(in) :: res      !! finished run [-]
    type(health_t), intent(inout) :: h         !! outcome so far [-]
    real(wp) :: r
    character(len=64) :: b1

    r = abs(res%energy_residual)
    if (.not. ieee_is_finite(res%energy_residual)) r = huge(1.0_wp)
    write (b1, '(es10.3)') 100.0_wp*res%energy_residual
    if (r > residual_fail) then
      call put(h, 5, health_fail, 'energy residual '//trim(adjustl(b1))//' % of the energy input (at most 10 %): '// &
               'the run does not conserve energy; reduce dt')
    else if (r > residual_warn) then
      call put(h, 5, health_warn, 'energy residual '//trim(adjustl(b1))//' % of the energy input (above 1 %); '// &
               'consider a smaller dt')
    end if
  end subroutine check_energy_residual

  !> Check 6: finite, plausible peaks.
  subroutine check_finite_peaks(res, h)
    type(sim_result_t), intent(in) :: res      !! finished run [-]
    type(health_t), intent(inout) :: h         !! outcome so far [-]
    character(len=64) :: b1

    if (.not. ieee_is_finite(res%peak_overload) .or. .not. ieee_is_finite(res%energy_input)) then
      call put(h, 6, health_fail, 'peak overload or energy input is not finite')
    else if (res%peak_overload > overload_warn) then
      write (b1, '(es10.3)') res%peak_overload
      call put(h, 6, health_warn, 'peak overload '//trim(adjustl(b1))//' g (above 1000 g): implausible for a lander')
    end if
  end subroutine check_finite_peaks

  !> Records a check that did not pass: its level and a message line.
  subroutine put(h, c, level, text)
    type(health_t), intent(inout) :: h     !! outcome so far [-]
    integer, intent(in) :: c               !! check index [-]
    integer, intent(in) :: level           !! health_warn or health_fail [-]
    character(len=*), intent(in) :: text   !! what is wrong [-]
    if (level < h%result(c)) return
    if (h%result(c) /= health_ok .and. level == h%result(c)) return   ! one message per check
    h%result(c) = level
    if (len(h%messages) > 0) h%messages = h%messages//new_line('a')
    h%messages = h%messages//merge('FAILED ', 'warning', level == health_fail)//' '//trim(check_names(c))// &
                 ': '//text
  end subroutine put

  !> The checks that did not pass, one line each with a prefix, on a unit (nothing when all pass).
  subroutine write_health(unit, prefix, h)
    integer, intent(in) :: unit             !! output unit [-]
    character(len=*), intent(in) :: prefix  !! e.g. 'landyn: ' [-]
    type(health_t), intent(in) :: h         !! checks [-]
    integer :: p, q
    if (len(h%messages) == 0) return
    p = 1
    do
      q = index(h%messages(p:), new_line('a'))
      if (q == 0) then
        write (unit, '(a)') prefix//'run health '//h%messages(p:)
        exit
      end if
      write (unit, '(a)') prefix//'run health '//h%messages(p:p + q - 2)
      p = p + q
    end do
  end subroutine write_health

end module landyn_health
