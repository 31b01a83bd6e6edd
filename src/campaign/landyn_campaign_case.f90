!> One case of a campaign: its summary row, how it is run, and how a row travels (MPI
!! messages, journal lines) as integer, real and text parts.
!!
!! A case runs exactly what `landyn` runs: the case's input (landyn_campaign_deck%case_input,
!! read through the run-deck reader) goes to landyn_run's run_case (input health, simulation,
!! result health, outcome; the status has landyn's exit-status meaning), and a saved time history
!! is written with write_result_file. The row holds the case's varied inputs, the single-run
!! summary metrics, the outcome, the success verdict against the campaign's criteria, the status
!! and error message. A case is a success only when it came to rest (outcome at_rest) and met
!! every criterion; one still moving at its end time with no other criterion failed is
!! inconclusive (criterion not_at_rest alone), counted apart in the summary.
!!
!! Library code: nothing here stops or prints.
module landyn_campaign_case
  use, intrinsic :: iso_fortran_env, only: int64
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use landyn_kinds, only: wp, msg_len, max_gears, deg2rad
  use landyn_status, only: status_t, STAT_FAILED, STAT_OK, EXIT_OK, EXIT_INPUT, EXIT_DIVERGED, EXIT_HEALTH, EXIT_NO_TOUCHDOWN
  use landyn_config, only: landyn_input_t
  use landyn_input, only: input_errors_t
  use landyn_simulation, only: sim_result_t
  use landyn_health, only: health_t
  use landyn_run, only: run_case_once => run_case
  use landyn_outcome, only: outcome_at_rest
  use landyn_output, only: write_result_file
  use landyn_terrain, only: terrain_plane_t, make_terrain_planes, penetration
  use landyn_kinematics, only: rot_zyx
  use landyn_campaign_deck, only: campaign_t, criteria_t, case_values, case_input
  implicit none
  private

  public :: case_row_t, run_case, new_row
  public :: row_int_count, row_real_count, pack_row, unpack_row, rows_equal
  public :: status_ok, status_failed, status_unhealthy, status_no_touchdown, inconclusive
  public :: n_criteria, criterion_name, failed_criteria_names, failure_counts

  integer, parameter :: status_not_run = -1        !! row not filled [-]
  integer, parameter :: status_ok = EXIT_OK                 !! the simulation ran to its end (a tip-over is a result) [-]
  integer, parameter :: status_invalid_input = EXIT_INPUT   !! the case's input is invalid (as landyn's exit status) [-]
  integer, parameter :: status_failed = EXIT_DIVERGED       !! the simulation failed, e.g. diverged (as landyn's exit status) [-]
  integer, parameter :: status_unhealthy = EXIT_HEALTH      !! a run-health check failed: meaningless (as landyn's) [-]
  integer, parameter :: status_no_touchdown = EXIT_NO_TOUCHDOWN  !! no footpad touched the ground (as landyn's) [-]

  ! Bits of failed_criteria.
  integer, parameter :: fail_tipped_over = 1       !! tipped over [-]
  integer, parameter :: fail_stroke_margin = 2     !! a stroke margin below min_stroke_margin [-]
  integer, parameter :: fail_overload = 4          !! peak overload above max_overload [-]
  integer, parameter :: fail_clearance = 8         !! body clearance below min_body_clearance [-]
  integer, parameter :: fail_not_at_rest = 16      !! not at rest at the end time: inconclusive [-]
  integer, parameter :: fail_run = 32              !! no result (invalid input, failed run, failed health check) [-]
  integer, parameter :: fail_no_touchdown = 64     !! never touched the ground [-]
  integer, parameter :: fail_tipover_margin = 128  !! final tip-over margin below min_tipover_margin [-]
  integer, parameter :: fail_friction_ratio = 256  !! a final friction ratio above max_friction_ratio [-]

  integer, parameter :: n_criteria = 9             !! number of fail_* bits [-]
  !> The fail_* bits in order, and their names (summary-file column failed_criteria_names,
  !! /probability/failure_criterion; docs/campaign.md).
  integer, parameter :: criterion_bit(n_criteria) = [fail_tipped_over, fail_stroke_margin, fail_overload, &
                                                      fail_clearance, fail_not_at_rest, fail_run, &
                                                      fail_no_touchdown, fail_tipover_margin, fail_friction_ratio]  !! [-]
  character(len=14), parameter :: criterion_name(n_criteria) = [character(len=14) :: 'tipped_over', &
    'stroke_margin', 'overload', 'body_clearance', 'not_at_rest', 'no_result', 'no_touchdown', 'tipover_margin', &
    'friction_ratio']  !! [-]

  integer, parameter :: row_int_count = 12         !! integer part of a packed row [-]
  integer, parameter :: max_message = 2000         !! longest error message kept [-]

  !> The summary row of one case.
  type :: case_row_t
    integer :: case_id = 0                      !! case id, 1..n_cases [-]
    integer :: status = status_not_run          !! status_ok, status_invalid_input or status_failed [-]
    integer :: success = 0                      !! 1 when every criterion holds [-]
    integer :: tipped_over = 0                  !! 1 when the lander tipped over [-]
    integer :: at_rest = 0                      !! 1 when the lander came to rest [-]
    integer :: bottomed_out = 0                 !! 1 when a stroke exceeded its capacity [-]
    integer :: failed_criteria = 0              !! bit set of fail_* [-]
    integer :: n_steps = 0                      !! time steps taken [-]
    integer :: outcome = 0                      !! outcome code (landyn_outcome; 0 none) [-]
    real(wp), allocatable :: inputs(:)          !! (n_par) varied inputs [deck unit]
    real(wp), allocatable :: crush(:, :)        !! (3, n_gears) signed net crush [m]
    real(wp), allocatable :: margin(:, :)       !! (3, n_gears) stroke margin [m]
    real(wp) :: min_margin = 0.0_wp             !! smallest stroke margin [m]
    real(wp) :: peak_overload = 0.0_wp          !! peak overload at the mass centre [g]
    real(wp) :: peak_penetration = 0.0_wp       !! largest footpad penetration [m]
    real(wp) :: max_slide = 0.0_wp              !! largest footpad slide distance [m]
    real(wp) :: final_tilt = 0.0_wp             !! tilt at the end [deg]
    real(wp) :: max_tilt = 0.0_wp               !! largest tilt [deg]
    real(wp) :: min_clearance = 0.0_wp          !! smallest body-point clearance above the terrain [m]
    real(wp) :: final_time = 0.0_wp            !! simulated end time [s]
    real(wp) :: wall_time = 0.0_wp              !! wall-clock time of the case [s]
    real(wp) :: tipover_margin = 0.0_wp         !! tip-over margin at the end (landyn_outcome) [deg]
    real(wp) :: max_friction_ratio = 0.0_wp     !! largest footpad |F_t|/(mu_s F_n) at the end [-]
    character(len=:), allocatable :: message    !! error message ('' when none) [-]
    character(len=:), allocatable :: end_reason !! why the run ended [-]
    character(len=:), allocatable :: history_file  !! time-history file written ('' when none) [-]
  end type case_row_t

contains

  !> Real part length of a packed row.
  pure function row_real_count(n_par, n_gears) result(n)
    integer, intent(in) :: n_par    !! varied inputs [-]
    integer, intent(in) :: n_gears  !! gears [-]
    integer :: n                    !! reals [-]
    n = n_par + 6*n_gears + 11
  end function row_real_count

  !> An empty row (metrics NaN) for case `id`.
  function new_row(id, n_par, n_gears) result(row)
    integer, intent(in) :: id        !! case id [-]
    integer, intent(in) :: n_par     !! varied inputs [-]
    integer, intent(in) :: n_gears   !! gears [-]
    type(case_row_t) :: row          !! the row [-]
    real(wp) :: r(row_real_count(n_par, n_gears))
    row%case_id = id
    allocate (row%inputs(n_par), row%crush(3, n_gears), row%margin(3, n_gears))
    r = ieee_value(1.0_wp, ieee_quiet_nan)
    r(size(r)) = 0.0_wp   ! the wall time
    call set_reals(row, r, n_par, n_gears)
    row%message = ''
    row%end_reason = ''
    row%history_file = ''
  end function new_row

  !> Time-history file of case `id`: <history_prefix><id, at least 6 digits>.h5.
  function history_file_name(camp, id) result(path)
    type(campaign_t), intent(in) :: camp   !! campaign [-]
    integer, intent(in) :: id              !! case id [-]
    character(len=:), allocatable :: path  !! file name [-]
    character(len=16) :: buf
    write (buf, '(i6.6)') id
    path = camp%history_prefix//trim(buf)//'.h5'
  end function history_file_name

  !> Run case `id`: build its input, run the simulation, evaluate the criteria, and write its
  !! time history when `save_history`. Never fails: problems go into the row's status and message.
  !! `timing`, when present, gets the wall-clock split of the case: (1) input (case values, case
  !! deck, reading, checks), (2) run_simulation, (3) the rest (metrics, criteria, history file).
  subroutine run_case(camp, id, save_history, command_line, row, timing)
    type(campaign_t), intent(in) :: camp          !! campaign [-]
    integer, intent(in) :: id                     !! case id [-]
    logical, intent(in) :: save_history          !! write the time-history file [-]
    character(len=*), intent(in) :: command_line  !! recorded in the history file [-]
    type(case_row_t), intent(out) :: row          !! the case's row [-]
    real(wp), intent(out), optional :: timing(3)  !! input, simulation, rest [s]
    type(landyn_input_t) :: inp
    type(input_errors_t) :: errors
    type(sim_result_t) :: res
    type(health_t) :: health
    real(wp) :: values(camp%n_par)
    character(len=:), allocatable :: path
    character(len=msg_len) :: msg
    type(status_t) :: wst
    integer :: st
    logical :: ran
    integer(int64) :: c0, crate, c_in, c_sim

    call system_clock(c0, crate)
    c_in = -1
    c_sim = -1
    row = new_row(id, camp%n_par, camp%n_gears)
    call case_values(camp, id, values, wst)
    if (.not. wst%ok()) then
      row%status = status_invalid_input
      row%message = wst%text()
      row%end_reason = 'invalid input'
      call finish_row(row, camp%crit, c0, c_in, c_sim, crate, timing)
      return
    end if
    row%inputs = values
    call case_input(camp, id, values, inp, errors, st)
    if (st /= 0) then
      row%status = status_invalid_input
      row%message = joined_messages(errors)
      row%end_reason = 'invalid input'
      call finish_row(row, camp%crit, c0, c_in, c_sim, crate, timing)
      return
    end if
    msg = ''
    call system_clock(c_in)
    call run_case_once(inp, res, health, st, msg, -1, loads=save_history, ran=ran)   ! loads only for saved histories
    call system_clock(c_sim)
    row%status = st
    if (.not. ran) then
      row%message = trim(msg)
      row%end_reason = 'simulation failed'
      if (st == status_unhealthy) then
        row%message = 'run-health check of the input failed: '//health%messages
        row%end_reason = 'not run'
      end if
      row%n_steps = res%n_steps
      call finish_row(row, camp%crit, c0, c_in, c_sim, crate, timing)
      return
    end if
    ! physically meaningless (docs/health.md): status 6, its numbers kept
    if (st == status_unhealthy) row%message = 'run-health check failed: '//health%messages
    if (st == status_no_touchdown) row%message = 'no touchdown: no footpad touched the ground'
    call fill_row_results(inp, res, camp%crit, row)
    if (save_history) then
      path = history_file_name(camp, id)
      inp%output%file = path
      call write_result_file(path, inp, res, command_line, wst, health)
      if (wst%ok()) then
        row%history_file = path
      else
        row%message = 'time-history file not written: '//wst%text()
      end if
    end if
    call finish_row(row, camp%crit, c0, c_in, c_sim, crate, timing)
  end subroutine run_case

  !> The results of a case's run into its row: outcome, tip-over margin, friction ratio, crush and
  !! stroke margins, loads, penetration, slide, tilt, flags, time, steps, end reason and the body
  !! points' clearance.
  subroutine fill_row_results(inp, res, crit, row)
    type(landyn_input_t), intent(in) :: inp       !! case input [-]
    type(sim_result_t), intent(in) :: res         !! its run's result [-]
    type(criteria_t), intent(in) :: crit          !! success criteria (body points) [-]
    type(case_row_t), intent(inout) :: row        !! the case's row [-]
    row%outcome = res%outcome
    row%tipover_margin = res%tipover_margin
    row%max_friction_ratio = maxval(res%friction_ratio)
    row%crush = res%crush_net
    row%margin = res%stroke_margin
    row%min_margin = minval(res%stroke_margin)
    row%peak_overload = res%peak_overload
    row%peak_penetration = maxval(res%peak_penetration)
    row%max_slide = maxval(res%slide_distance)
    row%final_tilt = res%final_tilt
    row%max_tilt = res%max_tilt
    row%tipped_over = merge(1, 0, res%tipped_over)
    row%at_rest = merge(1, 0, res%at_rest)
    row%bottomed_out = merge(1, 0, any(res%bottomed == 1))
    row%final_time = res%t_final
    row%n_steps = res%n_steps
    row%end_reason = trim(res%end_reason)
    row%min_clearance = body_clearance(inp, res, crit)
  end subroutine fill_row_results

  !> A case's input errors as one message, separated by ' | '.
  function joined_messages(errors) result(m)
    type(input_errors_t), intent(in) :: errors    !! input errors of the case [-]
    character(len=:), allocatable :: m           !! their messages [-]
    integer :: i
    m = ''
    do i = 1, errors%count()
      if (i > 1) m = m//' | '
      m = m//errors%message(i)
    end do
  end function joined_messages

  !> Finish a case's row: evaluate the success criteria, clean its message, and set its wall time
  !! and (when `timing` is present) the split of that time; a phase not reached takes no time.
  subroutine finish_row(row, crit, c0, c_in, c_sim, crate, timing)
    type(case_row_t), intent(inout) :: row        !! the case's row [-]
    type(criteria_t), intent(in) :: crit          !! success criteria [-]
    integer(int64), intent(in) :: c0              !! clock at the case's start [clock counts]
    integer(int64), intent(in) :: c_in            !! clock after its input, -1 if not reached [clock counts]
    integer(int64), intent(in) :: c_sim           !! clock after its run, -1 if not reached [clock counts]
    integer(int64), intent(in) :: crate           !! clock counts per second [1/s]
    real(wp), intent(out), optional :: timing(3)  !! input, simulation, rest [s]
    integer(int64) :: c1, c_in_, c_sim_
    call evaluate_criteria(row, crit)
    row%message = sanitize(row%message)
    call system_clock(c1)
    row%wall_time = real(c1 - c0, wp)/real(crate, wp)
    if (present(timing)) then
      c_in_ = c_in
      c_sim_ = c_sim
      if (c_in_ < 0) c_in_ = c1
      if (c_sim_ < 0) c_sim_ = c_in_
      timing = real([c_in_ - c0, c_sim_ - c_in_, c1 - c_sim_], wp)/real(crate, wp)
    end if
  end subroutine finish_row

  !> Smallest clearance of the criteria's body points above the terrain over the output samples:
  !! minimum over samples, points and the footpads' terrain planes of the height of the point
  !! above the plane along its normal [m].
  function body_clearance(inp, res, crit) result(clear)
    type(landyn_input_t), intent(in) :: inp  !! case input [-]
    type(sim_result_t), intent(in) :: res    !! case result [-]
    type(criteria_t), intent(in) :: crit     !! criteria with the body points [-]
    real(wp) :: clear                        !! clearance [m]
    type(terrain_plane_t) :: planes(max_gears)
    real(wp) :: r(3, 3), x(3)
    integer :: k, i, j, ng
    type(status_t) :: tst
    ng = inp%gears%n_gears
    call make_terrain_planes(inp%terrain, planes(1:ng), tst)
    clear = huge(1.0_wp)
    if (.not. tst%ok()) return
    do k = 1, res%n_out
      r = rot_zyx(res%euler(1, k)*deg2rad, res%euler(2, k)*deg2rad, res%euler(3, k)*deg2rad)
      do j = 1, crit%n_body_points
        x = res%position(:, k) + matmul(r, crit%body_point(:, j))
        do i = 1, ng
          clear = min(clear, -penetration(planes(i), x))
        end do
      end do
    end do
  end function body_clearance

  !> Set failed_criteria and success of a row from its metrics and the criteria.
  subroutine evaluate_criteria(row, crit)
    type(case_row_t), intent(inout) :: row  !! row [-]
    type(criteria_t), intent(in) :: crit    !! criteria [-]
    integer :: fc
    if (row%status == status_no_touchdown) then
      fc = fail_no_touchdown
    else if (row%status /= status_ok) then
      fc = fail_run
    else
      fc = 0
      if (row%tipped_over == 1) fc = ior(fc, fail_tipped_over)
      if (row%min_margin < crit%min_stroke_margin) fc = ior(fc, fail_stroke_margin)
      if (crit%overload_applied) then
        if (row%peak_overload > crit%max_overload) fc = ior(fc, fail_overload)
      end if
      if (crit%clearance_applied) then
        if (row%min_clearance < crit%min_body_clearance) fc = ior(fc, fail_clearance)
      end if
      ! the stability figures of the state at rest (a moving case is undecided: not_at_rest below)
      if (crit%tipover_applied .and. row%outcome == outcome_at_rest) then
        if (row%tipover_margin < crit%min_tipover_margin) fc = ior(fc, fail_tipover_margin)
      end if
      if (crit%friction_applied .and. row%outcome == outcome_at_rest) then
        if (row%max_friction_ratio > crit%max_friction_ratio) fc = ior(fc, fail_friction_ratio)
      end if
      ! a case still moving at its end time is undecided, whatever require_at_rest says
      if (row%outcome /= outcome_at_rest .and. row%tipped_over == 0) fc = ior(fc, fail_not_at_rest)
    end if
    row%failed_criteria = fc
    row%success = merge(1, 0, fc == 0)
  end subroutine evaluate_criteria

  !> The case is inconclusive: still moving at its end time, and no criterion but not_at_rest
  !! failed (it could still turn out either way).
  elemental function inconclusive(row) result(yes)
    type(case_row_t), intent(in) :: row     !! row [-]
    logical :: yes                          !! inconclusive [-]
    yes = row%failed_criteria == fail_not_at_rest
  end function inconclusive

  !> Names of the criteria a bit set of fail_* says failed, comma-separated in criterion_bit
  !! order ('' when none), e.g. 'tipped_over,stroke_margin'.
  pure function failed_criteria_names(fc) result(s)
    integer, intent(in) :: fc           !! bit set of fail_* [-]
    character(len=:), allocatable :: s  !! names [-]
    integer :: k
    s = ''
    do k = 1, n_criteria
      if (iand(fc, criterion_bit(k)) == 0) cycle
      if (len(s) > 0) s = s//','
      s = s//trim(criterion_name(k))
    end do
  end function failed_criteria_names

  !> Number of rows that failed each criterion (criterion_bit order); a row may fail several.
  pure function failure_counts(rows) result(counts)
    type(case_row_t), intent(in) :: rows(:)  !! rows [-]
    integer :: counts(n_criteria)            !! rows failing each criterion [-]
    integer :: k
    do k = 1, n_criteria
      counts(k) = count(iand(rows%failed_criteria, criterion_bit(k)) /= 0)
    end do
  end function failure_counts

  !> Message on one line, at most max_message characters.
  pure function sanitize(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=:), allocatable :: s  !! cleaned text [-]
    integer :: i
    s = trim(t)
    do i = 1, len(s)
      if (iachar(s(i:i)) < 32) s(i:i) = ' '
    end do
    if (len(s) > max_message) s = s(1:max_message - 3)//'...'
  end function sanitize

  !> A row as integer, real and text parts (MPI messages, journal lines).
  subroutine pack_row(row, ibuf, rbuf, text)
    type(case_row_t), intent(in) :: row                 !! row [-]
    integer, intent(out) :: ibuf(row_int_count)         !! integer part [-]
    real(wp), allocatable, intent(out) :: rbuf(:)       !! real part [mixed units]
    character(len=:), allocatable, intent(out) :: text  !! text part: message, end reason, history file [-]
    ibuf = [row%case_id, row%status, row%success, row%tipped_over, row%at_rest, row%bottomed_out, &
            row%failed_criteria, row%n_steps, len(row%message), len(row%end_reason), len(row%history_file), row%outcome]
    rbuf = [row%inputs, reshape(row%crush, [size(row%crush)]), reshape(row%margin, [size(row%margin)]), &
            row%min_margin, row%peak_overload, row%peak_penetration, row%max_slide, row%final_tilt, row%max_tilt, &
            row%min_clearance, row%final_time, row%tipover_margin, row%max_friction_ratio, row%wall_time]
    text = row%message//row%end_reason//row%history_file
  end subroutine pack_row

  !> The real part of a row from its packed form (pack_row's rbuf; the row's arrays allocated).
  pure subroutine set_reals(row, rbuf, n_par, n_gears)
    type(case_row_t), intent(inout) :: row  !! row [-]
    real(wp), intent(in) :: rbuf(:)         !! real part, row_real_count(n_par, n_gears) values [mixed units]
    integer, intent(in) :: n_par            !! varied inputs [-]
    integer, intent(in) :: n_gears          !! gears [-]
    integer :: k
    row%inputs = rbuf(1:n_par)
    k = n_par
    row%crush = reshape(rbuf(k + 1:k + 3*n_gears), [3, n_gears])
    k = k + 3*n_gears
    row%margin = reshape(rbuf(k + 1:k + 3*n_gears), [3, n_gears])
    k = k + 3*n_gears
    row%min_margin = rbuf(k + 1)
    row%peak_overload = rbuf(k + 2)
    row%peak_penetration = rbuf(k + 3)
    row%max_slide = rbuf(k + 4)
    row%final_tilt = rbuf(k + 5)
    row%max_tilt = rbuf(k + 6)
    row%min_clearance = rbuf(k + 7)
    row%final_time = rbuf(k + 8)
    row%tipover_margin = rbuf(k + 9)
    row%max_friction_ratio = rbuf(k + 10)
    row%wall_time = rbuf(k + 11)
  end subroutine set_reals

  !> True when two rows are identical bit for bit, wall time aside.
  function rows_equal(a, b) result(same)
    type(case_row_t), intent(in) :: a, b  !! rows [-]
    logical :: same                       !! identical except wall_time [-]
    integer :: ia(row_int_count), ib(row_int_count), k
    real(wp), allocatable :: ra(:), rb(:)
    character(len=:), allocatable :: ta, tb
    call pack_row(a, ia, ra, ta)
    call pack_row(b, ib, rb, tb)
    same = all(ia == ib) .and. size(ra) == size(rb) .and. ta == tb .and. len(ta) == len(tb)
    if (.not. same) return
    do k = 1, size(ra) - 1   ! the last real is the wall time
      if (transfer(ra(k), 0_int64) /= transfer(rb(k), 0_int64)) same = .false.
    end do
  end function rows_equal

  !> The row packed by pack_row. stat = 1 when the parts do not fit together.
  subroutine unpack_row(ibuf, rbuf, text, n_par, n_gears, row, stat)
    integer, intent(in) :: ibuf(:)          !! integer part [-]
    real(wp), intent(in) :: rbuf(:)         !! real part [mixed units]
    character(len=*), intent(in) :: text    !! text part [-]
    integer, intent(in) :: n_par            !! varied inputs [-]
    integer, intent(in) :: n_gears          !! gears [-]
    type(case_row_t), intent(out) :: row    !! row [-]
    integer, intent(out) :: stat            !! 0 ok, 1 inconsistent parts [-]
    integer :: l1, l2, l3
    stat = STAT_FAILED
    if (size(ibuf) /= row_int_count .or. size(rbuf) /= row_real_count(n_par, n_gears)) return
    l1 = ibuf(9)
    l2 = ibuf(10)
    l3 = ibuf(11)
    if (min(l1, l2, l3) < 0 .or. l1 + l2 + l3 /= len(text)) return
    row = new_row(ibuf(1), n_par, n_gears)
    row%status = ibuf(2)
    row%success = ibuf(3)
    row%tipped_over = ibuf(4)
    row%at_rest = ibuf(5)
    row%bottomed_out = ibuf(6)
    row%failed_criteria = ibuf(7)
    row%n_steps = ibuf(8)
    row%outcome = ibuf(12)
    call set_reals(row, rbuf, n_par, n_gears)
    row%message = text(1:l1)
    row%end_reason = text(l1 + 1:l1 + l2)
    row%history_file = text(l1 + l2 + 1:l1 + l2 + l3)
    stat = STAT_OK
  end subroutine unpack_row

end module landyn_campaign_case
