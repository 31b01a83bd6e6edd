!> A simulation driven by a caller (the C API, landyn_capi): created from deck text and overrides
!! with every input check of the landyn program, advanced to the times the caller chooses with
!! engine inputs held between calls, read through the outputs of landyn_api_outputs, and written
!! as the result file of what was run so far. The landyn program's own path (landyn_run's run_case,
!! run_simulation) is not used and not changed: an advance to t_end without inputs takes the same
!! steps as run_simulation, and its result is the program's.
!!
!! Statuses are those of include/landyn.h (api_ok ... api_ended). Library code: nothing here stops
!! or prints; every problem is a status and a message.
module landyn_session
  use, intrinsic :: iso_fortran_env, only: int64
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use landyn_kinds, only: wp, msg_len
  use landyn_status, only: STAT_INPUT, status_t
  use landyn_errors, only: input_errors_t
  use landyn_real_text, only: fmt_real
  use landyn_strings, only: edit_distance
  use landyn_config, only: landyn_input_t, default_input
  use landyn_input, only: read_input_text, apply_input_text, resolve_input, validate_input
  use landyn_sim_core, only: sim_t, sim_result_t, sim_init, finish
  use landyn_sim_result, only: allocate_result
  use landyn_integrator, only: integrator_t
  use landyn_integrators, only: make_integrator
  use landyn_rest, only: measure_motion
  use landyn_health, only: health_t, check_health, check_input_health, health_fail
  use landyn_outcome, only: classify_outcome, outcome_no_touchdown, outcome_at_rest, outcome_still_moving, &
                            outcome_tipped_over
  use landyn_files, only: output_file_problem
  use landyn_output, only: write_result_file
  use landyn_api_outputs, only: api_output_t, api_output_list, api_output_values, api_outcome_running, &
                                api_outcome_no_touchdown, api_outcome_at_rest, api_outcome_tipped_over, &
                                api_outcome_moving, api_outcome_failed
  implicit none
  private

  public :: session_t, session_create, session_set_input, session_advance_to, session_output_index, &
            session_result, session_write

  ! ---- the statuses of include/landyn.h
  integer, parameter, public :: api_ok = 0           !! success [-]
  integer, parameter, public :: api_err_input = 1    !! invalid deck text or argument [-]
  integer, parameter, public :: api_err_handle = 2   !! NULL, freed or foreign handle [-]
  integer, parameter, public :: api_err_order = 3    !! call out of order [-]
  integer, parameter, public :: api_err_failed = 4   !! the simulation failed [-]
  integer, parameter, public :: api_err_file = 5     !! the result file could not be written [-]
  integer, parameter, public :: api_ended = 6        !! the run ended before the requested time [-]

  integer, parameter :: state_running = 0   !! the run goes on [-]
  integer, parameter :: state_ended = 1     !! the run ended (t_end, at rest, tipped over) [-]
  integer, parameter :: state_failed = 2    !! the simulation failed [-]

  !> One simulation driven by a caller.
  type :: session_t
    type(landyn_input_t) :: inp                        !! resolved, validated input
    type(sim_t) :: sim                                 !! the simulation
    class(integrator_t), allocatable :: integ          !! the integrator of &simulation
    type(sim_result_t) :: res                          !! the run's result so far
    type(sim_result_t) :: now                          !! one sample: the current state's
    type(health_t) :: health                           !! run-health checks (input; result once ended)
    integer :: state = state_running                   !! state_* [-]
    character(len=msg_len) :: failure = ''             !! the simulation's diagnosis when it failed [-]
    real(wp) :: t = 0.0_wp                             !! time of the current state [s]
    real(wp) :: slack = 0.0_wp                         !! times this close count as equal [s]
    real(wp) :: wall = 0.0_wp                          !! wall time spent in the simulation [s]
    integer :: n_inputs = 0                            !! engine inputs set [-]
    real(wp), allocatable :: input_t(:)                !! (capacity) times they were set [s]
    real(wp), allocatable :: input_force(:, :)         !! (3, capacity) forces, lander axes [N]
    real(wp), allocatable :: input_moment(:, :)        !! (3, capacity) moments, lander axes [N m]
    type(api_output_t), allocatable :: outputs(:)      !! the outputs (landyn_api_outputs) [-]
    real(wp), allocatable :: values(:)                 !! their values at the current state [units of outputs]
  end type session_t

contains

  !> Creates a simulation at t = 0 from deck text (blank: the built-in default) and overrides
  !! applied on top (blank: none), with the landyn program's checks: reader, registry ranges,
  !! cross-variable rules, input health. On failure `msg` lists every problem.
  subroutine session_create(s, deck_text, overrides, stat, msg, deck_name)
    type(session_t), intent(inout) :: s             !! new session (fresh)
    character(len=*), intent(in) :: deck_text       !! deck as a file holds it [-]
    character(len=*), intent(in) :: overrides       !! deck text applied on top [-]
    integer, intent(out) :: stat                    !! api_ok or api_err_input (api_err_failed: set-up failed) [-]
    character(len=:), allocatable, intent(out) :: msg  !! the problems, one per line [-]
    character(len=*), intent(in), optional :: deck_name  !! the deck's name in messages and provenance (its file),
                                                         !! default '(deck text)' [-]
    type(input_errors_t) :: errors
    integer :: st, i
    type(status_t) :: ss
    msg = ''
    if (len_trim(deck_text) == 0) then
      s%inp = default_input()
    else
      call read_input_text(deck_text, name_of_deck(deck_name), s%inp, errors, st)
    end if
    if (len_trim(overrides) > 0) call apply_input_text(overrides, '(overrides)', s%inp, errors, st)
    call resolve_input(s%inp, errors)
    call validate_input(s%inp, errors)
    if (errors%count() > 0) then
      do i = 1, errors%count()
        if (i > 1) msg = msg//new_line('a')
        msg = msg//errors%message(i)
      end do
      stat = api_err_input
      return
    end if
    call check_input_health(s%inp, s%health)
    if (s%health%status() == health_fail) then
      msg = 'a run-health check of the input failed: the run would be physically meaningless: '//s%health%messages
      stat = api_err_input
      return
    end if
    call sim_init(s%inp, s%sim, s%res, ss)
    if (ss%ok()) call make_integrator(s%inp, s%integ, ss)
    if (ss%ok()) call s%integ%start(s%sim, s%inp, s%res, ss)
    if (.not. ss%ok()) then
      msg = ss%text()
      stat = api_err_failed
      return
    end if
    call allocate_result(s%now, s%sim%model, 1)
    s%slack = 1.0e-12_wp*max(1.0_wp, s%inp%simulation%t_end)
    s%outputs = api_output_list(s%sim%model%par%n_gears, s%sim%model%par%n_struts)
    allocate (s%values(size(s%outputs)), s%input_t(8), s%input_force(3, 8), s%input_moment(3, 8))
    call update_values(s, stat, msg)
  end subroutine session_create

  !> The name a deck read from text goes by: the caller's (its file), or '(deck text)'.
  pure function name_of_deck(deck_name) result(name)
    character(len=*), intent(in), optional :: deck_name  !! the caller's name for the deck, may be blank [-]
    character(len=:), allocatable :: name                 !! the name [-]
    name = '(deck text)'
    if (present(deck_name)) then
      if (len_trim(deck_name) > 0) name = trim(deck_name)
    end if
  end function name_of_deck

  !> Sets the engine inputs held from now on: a force at the &engine point and a pure moment,
  !! lander axes, added to the deck's thrust. Recorded with the time for the result file.
  subroutine session_set_input(s, force, moment, stat, msg)
    type(session_t), intent(inout) :: s             !! session
    real(wp), intent(in) :: force(3)                !! force, lander axes [N]
    real(wp), intent(in) :: moment(3)               !! pure moment, lander axes [N m]
    integer, intent(out) :: stat                    !! api_ok, api_err_input, api_err_order, api_err_failed [-]
    character(len=:), allocatable, intent(out) :: msg  !! diagnosis [-]
    integer :: n_eval, i
    type(status_t) :: ss
    msg = ''
    if (s%state /= state_running) then
      stat = api_err_order
      msg = 'landyn_set_input: the run has '//trim(merge('ended ', 'failed', s%state == state_ended))//' at t = '// &
            fmt_real(s%t)//' s; no input can be applied'
      return
    end if
    do i = 1, 3
      if (.not. ieee_is_finite(force(i))) then
        stat = api_err_input
        msg = 'landyn_set_input: force('//achar(iachar('0') + i)//') is not finite'
        return
      end if
      if (.not. ieee_is_finite(moment(i))) then
        stat = api_err_input
        msg = 'landyn_set_input: moment('//achar(iachar('0') + i)//') is not finite'
        return
      end if
    end do
    call remember_input(s, force, moment)
    stat = api_ok
    if (.not. (any(abs(force - s%sim%ext_force) > 0.0_wp) .or. any(abs(moment - s%sim%ext_moment) > 0.0_wp))) return
    s%sim%ext_force = force
    s%sim%ext_moment = moment
    s%sim%ext_on = .true.
    s%sim%ext_changed = .true.
    call s%integ%retarget(s%sim, n_eval, ss)
    s%res%n_evaluations = s%res%n_evaluations + n_eval
    if (.not. ss%ok()) then
      call fail(s, ss%text(), stat, msg)
      return
    end if
    call update_values(s, stat, msg)
  end subroutine session_set_input

  !> Appends one row to the history of the engine inputs.
  pure subroutine remember_input(s, force, moment)
    type(session_t), intent(inout) :: s             !! session
    real(wp), intent(in) :: force(3)                !! force, lander axes [N]
    real(wp), intent(in) :: moment(3)               !! pure moment, lander axes [N m]
    real(wp), allocatable :: t(:), f(:, :), m(:, :)
    integer :: n
    n = s%n_inputs
    if (n == size(s%input_t)) then
      allocate (t(2*n), f(3, 2*n), m(3, 2*n))
      t(1:n) = s%input_t
      f(:, 1:n) = s%input_force
      m(:, 1:n) = s%input_moment
      call move_alloc(t, s%input_t)
      call move_alloc(f, s%input_force)
      call move_alloc(m, s%input_moment)
    end if
    n = n + 1
    s%input_t(n) = s%t
    s%input_force(:, n) = force
    s%input_moment(:, n) = moment
    s%n_inputs = n
  end subroutine remember_input

  !> Advances to time t (now <= t <= t_end): the integrator's own steps, the last ending exactly
  !! on t ('fixed': t a whole number of steps). api_ended when the run ended before t (at rest,
  !! tipped over), api_err_failed when it failed.
  subroutine session_advance_to(s, t, stat, msg)
    type(session_t), intent(inout) :: s             !! session
    real(wp), intent(in) :: t                       !! time to reach [s]
    integer, intent(out) :: stat                    !! api_ok, api_ended or an error [-]
    character(len=:), allocatable, intent(out) :: msg  !! diagnosis [-]
    real(wp) :: target, t_end
    integer :: n_eval, st
    logical :: done
    integer(int64) :: c0, c1, crate
    type(status_t) :: ss
    msg = ''
    stat = api_ok
    t_end = s%inp%simulation%t_end
    if (.not. ieee_is_finite(t)) then
      stat = api_err_input
      msg = 'landyn_advance_to: the time is not finite'
      return
    else if (s%state == state_failed) then
      stat = api_err_order
      msg = 'landyn_advance_to: the simulation failed at t = '//fmt_real(s%t)//' s: '//trim(s%failure)
      return
    else if (t < s%t - s%slack) then
      stat = api_err_order
      msg = 'landyn_advance_to: t = '//fmt_real(t)//' s is before the simulation time '//fmt_real(s%t)// &
            ' s (time cannot go backwards)'
      return
    else if (t > t_end + s%slack) then
      stat = api_err_order
      msg = 'landyn_advance_to: t = '//fmt_real(t)//' s is past the end of the run, &simulation t_end = '// &
            fmt_real(t_end)//' s'
      return
    end if
    if (t <= s%t + s%slack) return
    if (s%state == state_ended) then
      stat = api_ended
      msg = 'the run ended at t = '//fmt_real(s%t)//' s: '//trim(s%res%end_reason)
      return
    end if
    target = t
    if (target >= t_end - s%slack) target = t_end
    call system_clock(c0, crate)
    s%sim%t_stop = target
    call s%integ%retarget(s%sim, n_eval, ss)
    s%res%n_evaluations = s%res%n_evaluations + n_eval
    if (ss%code == STAT_INPUT) then
      stat = api_err_input
      msg = 'landyn_advance_to: '//ss%text()
      return
    else if (.not. ss%ok()) then
      call fail(s, ss%text(), stat, msg)
      return
    end if
    done = .false.
    do
      if (target < t_end .and. s%sim%state%t >= target - s%slack) exit
      call s%integ%step(s%sim, s%res, done, ss, -1)
      if (.not. ss%ok() .or. done) exit
    end do
    call system_clock(c1)
    s%wall = s%wall + real(c1 - c0, wp)/real(crate, wp)
    if (.not. ss%ok()) then
      s%t = s%res%t_final
      call fail(s, ss%text(), stat, msg)
      return
    end if
    if (done) then
      s%t = s%res%t_final
      call end_run(s)
      if (s%t < target - s%slack) then
        stat = api_ended
        msg = 'the run ended at t = '//fmt_real(s%t)//' s: '//trim(s%res%end_reason)
      end if
    else
      s%t = target
    end if
    call update_values(s, st, msg)
    if (st /= api_ok) stat = st
  end subroutine session_advance_to

  !> The simulation failed: the state, the message, the values of its last sample.
  subroutine fail(s, why, stat, msg)
    type(session_t), intent(inout) :: s             !! session
    character(len=*), intent(in) :: why             !! the simulation's diagnosis [-]
    integer, intent(out) :: stat                    !! api_err_failed [-]
    character(len=:), allocatable, intent(out) :: msg  !! diagnosis [-]
    integer :: st
    character(len=:), allocatable :: m2
    s%state = state_failed
    s%failure = why
    s%res%end_reason = 'simulation failed'
    msg = 'the simulation failed: '//trim(why)
    stat = api_err_failed
    call update_values(s, st, m2)
  end subroutine fail

  !> The run ended (end time, at rest, tipped over): its end state, result health and outcome, as
  !! landyn_run's run_case finishes a run.
  subroutine end_run(s)
    type(session_t), intent(inout) :: s             !! session whose integrator said done
    s%state = state_ended
    s%res%touched = s%sim%state%touched
    s%res%end_motion = measure_motion(s%sim%model)
    s%res%wall_time = s%wall
    call check_health(s%inp, s%res, s%health)
    call classify_outcome(s%inp, s%res)
  end subroutine end_run

  !> The output values of the current state: while running, the sample the result file would hold
  !! for it (the integrator's sample); once ended or failed, the result's last sample.
  subroutine update_values(s, stat, msg)
    type(session_t), intent(inout) :: s             !! session
    integer, intent(out) :: stat                    !! api_ok or api_err_failed [-]
    character(len=:), allocatable, intent(inout) :: msg  !! diagnosis appended on failure [-]
    type(status_t) :: ss
    stat = api_ok
    select case (s%state)
    case (state_running)
      s%now%n_out = 0
      call s%integ%sample(s%sim, s%now, ss)
      if (.not. ss%ok() .or. s%now%n_out < 1) then
        s%values = 0.0_wp
        s%values(1) = s%t
        stat = api_err_failed
        msg = msg//'the output sample of t = '//fmt_real(s%t)//' s failed: '//ss%text()
        return
      end if
      call api_output_values(s%now, 1, api_outcome_running, s%sim%state%touched, s%values)
    case default
      if (s%res%n_out < 1) then
        s%values = 0.0_wp
        s%values(1) = s%t
        s%values(2) = real(api_outcome_failed, wp)
        return
      end if
      call api_output_values(s%res, s%res%n_out, outcome_code(s), s%sim%state%touched, s%values)
    end select
  end subroutine update_values

  !> The outcome code of include/landyn.h of a session.
  pure function outcome_code(s) result(code)
    type(session_t), intent(in) :: s                !! session
    integer :: code                                 !! LANDYN_OUTCOME_* [-]
    code = api_outcome_running
    if (s%state == state_failed) then
      code = api_outcome_failed
    else if (s%state == state_ended) then
      select case (s%res%outcome)
      case (outcome_no_touchdown)
        code = api_outcome_no_touchdown
      case (outcome_at_rest)
        code = api_outcome_at_rest
      case (outcome_tipped_over)
        code = api_outcome_tipped_over
      case (outcome_still_moving)
        code = api_outcome_moving
      end select
    end if
  end function outcome_code

  !> Index of the output `name` in s%outputs (0 when unknown) and, for an unknown name, the
  !! closest known one.
  pure subroutine session_output_index(s, name, k, closest)
    type(session_t), intent(in) :: s                !! session
    character(len=*), intent(in) :: name            !! output name [-]
    integer, intent(out) :: k                       !! its index, 0 when unknown [-]
    character(len=:), allocatable, intent(out) :: closest  !! the closest name ('' when found) [-]
    integer :: i, d, best
    k = 0
    closest = ''
    best = huge(1)
    do i = 1, size(s%outputs)
      if (trim(s%outputs(i)%name) == trim(name)) then
        k = i
        return
      end if
      d = edit_distance(trim(name), trim(s%outputs(i)%name))
      if (d < best) then
        best = d
        closest = trim(s%outputs(i)%name)
      end if
    end do
  end subroutine session_output_index

  !> The result of what was run so far, as the result file holds it: a finished run's result; for a
  !! run the caller has not advanced to its end, the samples so far and one of the current state,
  !! the summary of the current state, the end reason "stopped by the caller at t" and the outcome
  !! still moving (inconclusive: it claims nothing the run has not reached); a failed run's result
  !! without health checks (has_health false).
  subroutine session_result(s, out, health, has_health)
    type(session_t), intent(inout) :: s             !! session (its state is not changed)
    type(sim_result_t), intent(out) :: out          !! the result [-]
    type(health_t), intent(out) :: health          !! its run-health checks [-]
    logical, intent(out) :: has_health              !! health holds checks of the result [-]
    type(status_t) :: ss
    out = s%res
    has_health = s%state /= state_failed
    if (s%state /= state_running) then
      health = s%health
      return
    end if
    if (out%n_out > 0) then
      if (out%t(out%n_out) < s%t - s%slack) call s%integ%sample(s%sim, out, ss)
    else
      call s%integ%sample(s%sim, out, ss)
    end if
    call finish(s%sim%model, out, s%t)
    out%end_reason = 'stopped by the caller at t = '//fmt_real(s%t)//' s'
    out%touched = s%sim%state%touched
    out%end_motion = measure_motion(s%sim%model)
    out%wall_time = s%wall
    call check_health(s%inp, out, health)
    call classify_outcome(s%inp, out)
    out%outcome = outcome_still_moving
  end subroutine session_result

  !> Writes the result file of what was run so far (session_result) with the applied inputs
  !! (/api/inputs), under the landyn program's output-file policy (docs/files.md).
  subroutine session_write(s, path, stat, msg)
    type(session_t), intent(inout) :: s             !! session
    character(len=*), intent(in) :: path            !! result file name [-]
    integer, intent(out) :: stat                    !! api_ok or api_err_file [-]
    character(len=:), allocatable, intent(out) :: msg  !! diagnosis [-]
    type(sim_result_t) :: out
    type(health_t) :: health
    logical :: has_health
    integer :: n
    type(status_t) :: st
    character(len=*), parameter :: cmd = 'landyn_write_result (LANDYN C API)'
    stat = api_ok
    msg = output_file_problem(path, 'result file', [' '], .true.)
    if (len(msg) > 0) then
      stat = api_err_file
      return
    end if
    call session_result(s, out, health, has_health)
    n = s%n_inputs
    if (has_health .and. n > 0) then
      call write_result_file(path, s%inp, out, cmd, st, health, 'C API', s%input_t(1:n), &
                             s%input_force(:, 1:n), s%input_moment(:, 1:n))
    else if (has_health) then
      call write_result_file(path, s%inp, out, cmd, st, health, 'C API')
    else if (n > 0) then
      call write_result_file(path, s%inp, out, cmd, st, program='C API', input_time=s%input_t(1:n), &
                             input_force=s%input_force(:, 1:n), input_moment=s%input_moment(:, 1:n))
    else
      call write_result_file(path, s%inp, out, cmd, st, program='C API')
    end if
    if (.not. st%ok()) then
      stat = api_err_file
      msg = 'cannot write the result file: '//st%text()
    end if
  end subroutine session_write

end module landyn_session
