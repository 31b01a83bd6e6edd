!> The serial tasks of landyn_batch (no MPI): check a campaign deck, list its cases, run some
!! cases into a small summary file of their own (`--case K`, for Slurm job arrays), and merge
!! summary files (`--merge OUT IN...`).
!!
!! Library code: reports go to the units the caller passes; results are exit codes
!! (0 ok, 1 usage, 2 invalid deck or files of different campaigns, 4 a file not written,
!! 5 written but incomplete).
module landyn_campaign_tasks
  use landyn_kinds, only: wp
  use landyn_input, only: input_errors_t
  use landyn_status, only: status_t, EXIT_OK, EXIT_USAGE, EXIT_INPUT, EXIT_FILE, EXIT_INCOMPLETE
  use landyn_campaign_text, only: int_text, ints_text, real_text_short, lower_case
  use landyn_campaign_deck, only: campaign_t, load_campaign, case_values, param_description, use_summary_file
  use landyn_campaign_case, only: case_row_t, run_case, rows_equal, status_ok, status_no_touchdown, n_criteria, criterion_name, &
                                  failed_criteria_names, failure_counts
  use landyn_campaign_store, only: summary_meta_t, meta_from_campaign, write_summary, read_summary, results_t, &
                                   results_init, results_add, results_missing, results_take_rows, success_probability
  implicit none
  private

  public :: load_or_report, check_campaign, list_cases, run_case_range, merge_summaries
  public :: report_probability, report_row

contains

  !> Load a campaign deck; on problems write every message to err_u and return EXIT_INPUT.
  subroutine load_or_report(deck, camp, err_u, code)
    character(len=*), intent(in) :: deck      !! campaign deck [-]
    type(campaign_t), intent(out) :: camp     !! campaign [-]
    integer, intent(in) :: err_u              !! unit for messages [-]
    integer, intent(out) :: code              !! EXIT_OK or EXIT_INPUT [-]
    type(input_errors_t) :: errors
    integer :: st
    code = EXIT_OK
    call load_campaign(deck, camp, errors, st)
    if (st /= 0 .or. errors%count() > 0) then
      call errors%write(err_u)
      write (err_u, '(a,i0,a)') 'landyn_batch: ', errors%count(), &
        ' error(s) in the campaign; nothing was run and no file was written'
      code = EXIT_INPUT
    end if
  end subroutine load_or_report

  !> `--check`: validate a campaign deck and describe it.
  subroutine check_campaign(deck, out_u, err_u, code)
    character(len=*), intent(in) :: deck  !! campaign deck [-]
    integer, intent(in) :: out_u          !! unit for the description [-]
    integer, intent(in) :: err_u          !! unit for messages [-]
    integer, intent(out) :: code          !! exit code [-]
    type(campaign_t) :: camp
    integer :: j
    call load_or_report(deck, camp, err_u, code)
    if (code /= EXIT_OK) return
    write (out_u, '(a)') 'campaign '//deck//': '//trim(camp%mode)//', '//int_text(camp%n_cases)//' cases, base deck '// &
      camp%base_path//' ('//int_text(camp%n_gears)//' gears)'
    do j = 1, camp%n_par
      write (out_u, '(a)') '  '//camp%par(j)%label//': '//param_description(camp%par(j))
    end do
    write (out_u, '(a)') '  summary file '//camp%summary_file//', fingerprint '//camp%fingerprint
  end subroutine check_campaign

  !> `--list-cases`: the inputs of every case as CSV (case_id, one column per input).
  subroutine list_cases(deck, out_u, err_u, code)
    character(len=*), intent(in) :: deck  !! campaign deck [-]
    integer, intent(in) :: out_u          !! unit for the table [-]
    integer, intent(in) :: err_u          !! unit for messages [-]
    integer, intent(out) :: code          !! exit code [-]
    type(campaign_t) :: camp
    real(wp), allocatable :: v(:)
    character(len=:), allocatable :: line
    type(status_t) :: vst
    integer :: id, j
    character(len=32) :: buf
    call load_or_report(deck, camp, err_u, code)
    if (code /= EXIT_OK) return
    line = 'case_id'
    do j = 1, camp%n_par
      line = line//','//camp%par(j)%name
    end do
    write (out_u, '(a)') line
    allocate (v(camp%n_par))
    do id = 1, camp%n_cases
      call case_values(camp, id, v, vst)
      line = int_text(id)
      do j = 1, camp%n_par
        if (.not. vst%ok()) then
          line = line//',nan'
        else
          write (buf, '(es24.16e3)') v(j)
          line = line//','//trim(adjustl(buf))
        end if
      end do
      write (out_u, '(a)') line
    end do
  end subroutine list_cases

  !> Default file of `--case k1[:k2]`: <summary without .h5>.case<k1>[-<k2>].h5.
  function part_file_name(camp, k1, k2) result(path)
    type(campaign_t), intent(in) :: camp   !! campaign [-]
    integer, intent(in) :: k1, k2          !! case range [-]
    character(len=:), allocatable :: path  !! file name [-]
    character(len=16) :: b1, b2
    path = camp%summary_file
    if (len(path) > 3) then
      if (lower_case(path(len(path) - 2:)) == '.h5') path = path(1:len(path) - 3)
    end if
    write (b1, '(i6.6)') k1
    write (b2, '(i6.6)') k2
    if (k1 == k2) then
      path = path//'.case'//trim(b1)//'.h5'
    else
      path = path//'.cases'//trim(b1)//'-'//trim(b2)//'.h5'
    end if
  end function part_file_name

  !> `--case k1[:k2]`: run cases k1..k2 one after the other and write their rows to a summary
  !! file of their own (out_file, or part_file_name when empty); with `history` (`--history`)
  !! every one of them also writes its full time history (as if named in save_histories).
  subroutine run_case_range(deck, k1, k2, out_file, quiet, command_line, out_u, err_u, code, history)
    character(len=*), intent(in) :: deck          !! campaign deck [-]
    integer, intent(in) :: k1, k2                 !! case range [-]
    character(len=*), intent(in) :: out_file      !! output file ('' for the default) [-]
    logical, intent(in) :: quiet                  !! no progress lines [-]
    logical, intent(in), optional :: history      !! write every case's time history [-]
    character(len=*), intent(in) :: command_line  !! for the files written [-]
    integer, intent(in) :: out_u                  !! unit for the result lines [-]
    integer, intent(in) :: err_u                  !! unit for messages and progress [-]
    integer, intent(out) :: code                  !! exit code [-]
    type(campaign_t) :: camp
    type(case_row_t), allocatable :: rows(:)
    type(summary_meta_t) :: meta
    character(len=:), allocatable :: path
    integer :: id
    logical :: all_histories
    all_histories = .false.
    if (present(history)) all_histories = history
    call load_or_report(deck, camp, err_u, code)
    if (code /= EXIT_OK) return
    if (k1 < 1 .or. k2 > camp%n_cases .or. k1 > k2) then
      write (err_u, '(a)') 'landyn_batch: --case '//int_text(k1)//':'//int_text(k2)// &
        ' is out of range; the campaign has cases 1 .. '//int_text(camp%n_cases)
      code = EXIT_USAGE
      return
    end if
    path = out_file
    if (len_trim(path) == 0) path = part_file_name(camp, k1, k2)
    call use_summary_file(camp, out_file)   ! history files follow -o (issue 10)
    allocate (rows(k2 - k1 + 1))
    do id = k1, k2
      if (.not. quiet) write (err_u, '(a)') 'landyn_batch: running case '//int_text(id)//' of '//int_text(camp%n_cases)
      call run_case(camp, id, all_histories .or. any(camp%save_histories == id), command_line, rows(id - k1 + 1))
      call report_row(rows(id - k1 + 1), camp%n_cases, out_u)
      if (len(rows(id - k1 + 1)%history_file) > 0) write (out_u, '(a)') '  time history of case '//int_text(id)// &
        ' written to '//rows(id - k1 + 1)%history_file
      if (all_histories .and. len(rows(id - k1 + 1)%history_file) == 0) write (err_u, '(a)') &
        'landyn_batch: case '//int_text(id)//': no time history (the case did not run to a result)'
    end do
    meta = meta_from_campaign(camp)
    call write_rows(path, meta, rows, command_line, err_u, code)
    if (code /= EXIT_OK) return
    write (out_u, '(a)') 'Rows written to '//path
  end subroutine run_case_range

  !> Write the summary file `path` with `rows`; on failure say so on err_u and set code = EXIT_FILE.
  subroutine write_rows(path, meta, rows, command_line, err_u, code)
    character(len=*), intent(in) :: path          !! summary file [-]
    type(summary_meta_t), intent(in) :: meta      !! campaign meta data [-]
    type(case_row_t), intent(in) :: rows(:)       !! rows in case-id order [-]
    character(len=*), intent(in) :: command_line  !! command that writes the file [-]
    integer, intent(in) :: err_u                  !! unit for messages [-]
    integer, intent(inout) :: code                !! EXIT_FILE on failure, else unchanged [-]
    type(status_t) :: st
    call write_summary(path, meta, rows, command_line, st)
    if (.not. st%ok()) then
      write (err_u, '(a)') 'landyn_batch: cannot write '//path//': '//st%text()
      code = EXIT_FILE
    end if
  end subroutine write_rows

  !> One line about a finished case.
  subroutine report_row(row, n_cases, u)
    type(case_row_t), intent(in) :: row   !! row [-]
    integer, intent(in) :: n_cases        !! cases of the campaign [-]
    integer, intent(in) :: u              !! unit [-]
    character(len=:), allocatable :: s
    s = 'case '//int_text(row%case_id)//'/'//int_text(n_cases)//': '
    if (row%status == status_ok) then
      s = s//trim(row%end_reason)//', min margin '//real_text_short(1000.0_wp*row%min_margin)//' mm, peak '// &
          real_text_short(row%peak_overload)//' g, tilt '//real_text_short(row%final_tilt)//' deg, '// &
          merge('success', 'FAILURE', row%success == 1)
      if (row%success /= 1) s = s//' ('//failed_criteria_names(row%failed_criteria)//')'
    else
      s = s//'status '//int_text(row%status)//' ('//trim(row%end_reason)//'): '//row%message
    end if
    write (u, '(a)') s//' ['//real_text_short(row%wall_time)//' s]'
  end subroutine report_row

  !> Print the success probability of `rows` with its 95 % Wilson interval.
  subroutine report_probability(rows, failed_runs, u)
    type(case_row_t), intent(in) :: rows(:)      !! rows [-]
    character(len=*), intent(in) :: failed_runs  !! criteria%failed_runs [-]
    integer, intent(in) :: u                     !! unit [-]
    integer :: n_eval, n_succ, n_excl, n_inv, n_fail, n_inc, n_ran, k, counts(n_criteria)
    real(wp) :: p, lo, hi
    character(len=96) :: buf
    character(len=:), allocatable :: s
    call success_probability(rows, failed_runs, n_eval, n_succ, n_excl, p, lo, hi, n_inc)
    n_inv = count(rows%status == 2)
    n_fail = count(rows%status == 3 .or. rows%status == 6)
    n_ran = count(rows%status == status_ok .or. rows%status == status_no_touchdown)
    if (n_excl > 0) then
      write (u, '(a)') '  cases: '//int_text(size(rows))//' ('//int_text(n_ran)// &
        ' ran, '//int_text(n_inv)//' invalid input, '//int_text(n_fail)//' failed runs, left out of P)'
    else
      write (u, '(a)') '  cases: '//int_text(size(rows))//' ('//int_text(n_ran)// &
        ' ran, '//int_text(n_inv)//' invalid input, '//int_text(n_fail)//' failed runs)'
    end if
    write (buf, '(f6.4,a,f6.4,a,f6.4,a)') p, ', 95 % CI [', lo, ', ', hi, '] (Wilson score)'
    write (u, '(a)') '  successful landings: '//int_text(n_succ)//' of '//int_text(n_eval)//': P = '// &
      trim(adjustl(buf))
    if (n_inc > 0) then
      write (buf, '(f6.4,a,f6.4)') real(n_succ, wp)/real(n_eval, wp), ' (counted as failures) .. ', &
        real(n_succ + n_inc, wp)/real(n_eval, wp)
      write (u, '(a)') '  inconclusive (still moving at the end time, no other criterion failed): '// &
        int_text(n_inc)//' of '//int_text(n_eval)//'; P lies between '//trim(adjustl(buf))//' (counted as successes)'
    end if
    counts = failure_counts(rows)
    s = '  failures per criterion:'
    do k = 1, n_criteria
      s = s//' '//trim(criterion_name(k))//' '//int_text(counts(k))
      if (k < n_criteria) s = s//','
    end do
    write (u, '(a)') s
  end subroutine report_probability

  !> `--merge OUT IN...`: combine summary files of one campaign into OUT (rows by case id).
  subroutine merge_summaries(out_file, inputs, command_line, out_u, err_u, code)
    character(len=*), intent(in) :: out_file      !! merged file [-]
    character(len=*), intent(in) :: inputs(:)     !! files to merge [-]
    character(len=*), intent(in) :: command_line  !! for the file written [-]
    integer, intent(in) :: out_u                  !! unit for the result lines [-]
    integer, intent(in) :: err_u                  !! unit for messages [-]
    integer, intent(out) :: code                  !! exit code [-]
    type(summary_meta_t) :: meta, m
    type(case_row_t), allocatable :: rows(:)
    type(results_t) :: table
    type(status_t) :: st
    integer, allocatable :: missing(:)
    integer :: i, k, ndup
    logical :: added
    code = EXIT_OK
    ndup = 0
    do i = 1, size(inputs)
      if (i == 1) then
        call read_summary(trim(inputs(i)), meta, rows, st)
      else
        call read_summary(trim(inputs(i)), m, rows, st)
      end if
      if (.not. st%ok()) then
        write (err_u, '(a)') 'landyn_batch: --merge: '//st%text()
        code = EXIT_INPUT
        return
      end if
      if (i == 1) then
        call results_init(table, meta%n_cases)
      else if (m%fingerprint /= meta%fingerprint) then
        write (err_u, '(a)') 'landyn_batch: --merge: '//trim(inputs(i))//' belongs to another campaign '// &
          '(fingerprint '//m%fingerprint//') than '//trim(inputs(1))//' ('//meta%fingerprint//')'
        code = EXIT_INPUT
        return
      else
        meta%n_cases = max(meta%n_cases, m%n_cases)   ! a Monte Carlo campaign may have been extended
        if (m%git_revision /= meta%git_revision) write (err_u, '(a)') 'landyn_batch: --merge: warning: '// &
          trim(inputs(i))//' was computed by code revision '//m%git_revision//', '//trim(inputs(1))//' by '// &
          meta%git_revision
        if (m%n_cases > table%n_cases) call grow(table, m%n_cases)
      end if
      do k = 1, size(rows)
        if (rows(k)%case_id >= 1 .and. rows(k)%case_id <= table%n_cases) then
          if (table%have(rows(k)%case_id)) then
            if (.not. rows_equal(table%rows(rows(k)%case_id), rows(k))) then
              write (err_u, '(a)') 'landyn_batch: --merge: case '//int_text(rows(k)%case_id)//' of '// &
                trim(inputs(i))//' differs from the same case in an earlier file'
              code = EXIT_INPUT
              return
            end if
            ndup = ndup + 1
            cycle
          end if
        end if
        call results_add(table, rows(k), added)
        if (.not. added) write (err_u, '(a)') 'landyn_batch: --merge: case id '//int_text(rows(k)%case_id)// &
          ' of '//trim(inputs(i))//' is outside 1 .. '//int_text(table%n_cases)//'; ignored'
      end do
    end do
    if (allocated(rows)) deallocate (rows)
    call results_take_rows(table, rows)
    call write_rows(out_file, meta, rows, command_line, err_u, code)
    if (code /= EXIT_OK) return
    write (out_u, '(a)') 'Merged '//int_text(size(inputs))//' file(s), '//int_text(size(rows))//' of '// &
      int_text(meta%n_cases)//' cases ('//int_text(ndup)//' duplicate rows dropped) into '//out_file
    call report_probability(rows, meta%crit%failed_runs, out_u)
    call results_missing(table, missing)
    if (size(missing) > 0) then
      write (err_u, '(a)') 'landyn_batch: --merge: '//int_text(size(missing))//' case(s) missing, e.g. '// &
        ints_text(missing(1:min(20, size(missing))))
      code = EXIT_INCOMPLETE
    end if

  contains

    !> Enlarge the table to n cases, keeping its rows.
    subroutine grow(t, n)
      type(results_t), intent(inout) :: t   !! table [-]
      integer, intent(in) :: n              !! new case count [-]
      type(results_t) :: t2
      integer :: j
      call results_init(t2, n)
      do j = 1, t%n_cases
        if (t%have(j)) call results_add(t2, t%rows(j))
      end do
      t = t2
    end subroutine grow

  end subroutine merge_summaries

end module landyn_campaign_tasks
