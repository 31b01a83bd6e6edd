!> The landyn_study program runs a sensitivity study (the paper's section 4: contact laws, friction laws,
!! tube friction) and writes one HDF5 file and one CSV table of crush lengths.
!!
!!   landyn_study STUDY.nml [-o FILE.h5] [--csv FILE.csv] [--check] [--quiet] [--help] [--version]
!!
!! Exit status: 0 every run completed (a tip-over is a result); 1 usage error; 2 invalid study
!! deck or run input (nothing is run); 3 some runs failed (diverged; the files are written, their
!! status says which); 4 an output file cannot be written (refused before anything runs where
!! possible, docs/files.md); 6 no run failed but a run-health check failed for some (status 6);
!! 7 every run completed and was healthy, but some never touched the ground (status 7). Each run
!! is run as landyn runs it (landyn_run): its status in the result file has landyn's meaning.
program landyn_study_main
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  use landyn_kinds, only: wp
  use landyn_input, only: input_errors_t
  use landyn_study, only: study_t, read_study, prepare_study, run_study, status_ok, status_failed, status_unhealthy, &
                          status_no_touchdown, strut_names
  use landyn_study_output, only: write_study_csv, write_study_h5, table_value
  use landyn_outcome, only: outcome_name
  use landyn_files, only: output_file_problem, file_kind, kind_regular
  use landyn_process, only: terminate
  use landyn_status, only: status_t, STAT_INPUT, STAT_OK, STAT_FILE, EXIT_OK, EXIT_INPUT, EXIT_DIVERGED, EXIT_FILE, EXIT_HEALTH, &
                          EXIT_NO_TOUCHDOWN
  use landyn_cli, only: command_line, write_input_errors
  use landyn_app_support, only: app_t
  implicit none

  !> --help text
  character(len=120), parameter :: help_text(*) = [character(len=120) :: &
      'usage: landyn_study STUDY.nml [-o FILE.h5] [--csv FILE.csv] [--check] [--quiet] [--help] [--version]', &
      '', &
      'Runs a sensitivity study: each &variant of the study deck (contact, friction or tube-friction', &
      'laws, or any other input) on each load-case deck of &study base_deck, and writes the crush', &
      'lengths in the layout of the paper''s Tables 6, 9 and 10 (docs/study.md).', &
      '', &
      '  STUDY.nml       study deck (&study and &variant groups); decks for the paper''s studies:', &
      '                  input/study_contact.nml, input/study_friction.nml, input/study_tube.nml', &
      '  -o, --output F  HDF5 file; default: &study output, or the study deck''s base name + .h5', &
      '  --csv F         CSV table; default: &study csv, or the study deck''s base name + .csv', &
      '  --check         validate the study and every run''s input, list the runs; run nothing', &
      '  -q, --quiet     no progress messages on stderr', &
      '  -V, --version   print the version', &
      '  -h, --help      print this help', &
      '', &
      'Exit status: 0 success, 1 usage error, 2 invalid input (nothing run), 3 some runs failed,', &
      '4 a file cannot be written (or is refused: docs/files.md), 6 a run-health check failed for', &
      'some runs (docs/health.md), 7 some runs never touched down (docs/exit_status.md).']

  type(app_t) :: app
  type(study_t) :: study
  type(input_errors_t) :: errors
  character(len=:), allocatable :: deck, h5_file, csv_file, arg, cmd, problem
  logical :: check_only
  integer :: i, stat, run_stat, c, v, progress
  type(status_t) :: file_status
  character(len=4096), allocatable :: inputs(:)

  call app%start('landyn_study', 'usage: landyn_study STUDY.nml [-o FILE.h5] [--csv FILE.csv] [--check] [--quiet]', &
                 help_text)
  deck = ''
  h5_file = ''
  csv_file = ''
  check_only = .false.
  do while (app%next_arg(arg))
    select case (arg)
    case ('-o', '--output')
      h5_file = app%option_value(arg)
    case ('--csv')
      csv_file = app%option_value(arg)
    case ('--check')
      check_only = .true.
    case default
      call app%positional(arg, deck, 'study deck')
    end select
  end do
  if (len(deck) == 0) call app%die_usage('no study deck given')

  ! ---- the study deck and every run's input, all checked before anything runs
  call read_study(deck, study, errors, stat)
  if (len(h5_file) > 0) study%output = h5_file   ! kept run files are named after the result file
  ! prepared also after errors in the study deck, to report every problem at once
  if (stat /= STAT_INPUT .and. study%n_cases > 0 .and. study%n_variants > 0) call prepare_study(study, errors, i)
  if (stat /= STAT_OK .or. errors%count() > 0) then
    call write_input_errors(error_unit, 'landyn_study', errors)
    call terminate(EXIT_INPUT)
  end if
  if (len(h5_file) == 0) h5_file = trim(study%output)
  if (len(csv_file) == 0) csv_file = trim(study%csv)
  if (check_only) then
    write (output_unit, '(a)') 'landyn_study: '//trim(study%title)
    do v = 1, study%n_variants
      do c = 1, study%n_cases
        write (output_unit, '(a)') '  '//trim(study%variant(v)%label)//' on '//trim(study%case_label(c))//' ('// &
          trim(study%case_deck(c))//'): contact '''//trim(study%inp(c, v)%contact%law)//''', friction '''// &
          trim(study%inp(c, v)%friction%law)//''', tube friction '//merge('on ', 'off', &
          study%inp(c, v)%primary%tube_friction)
      end do
    end do
    write (output_unit, '(a)') '  results would go to '//h5_file//' and '//csv_file
    call terminate(EXIT_OK)
  end if

  ! ---- the output files may be written (docs/files.md): checked before anything runs
  if (h5_file == csv_file) call app%die_files('the result file and the table are the same file ('//h5_file//')')
  allocate (inputs(study%n_cases + 2))
  inputs(1) = deck
  do c = 1, study%n_cases
    inputs(c + 1) = study%case_deck(c)
  end do
  inputs(study%n_cases + 2) = csv_file
  problem = output_file_problem(h5_file, 'result file', inputs, .true.)
  if (len(problem) > 0) call app%die_files(problem)
  inputs(study%n_cases + 2) = h5_file
  problem = output_file_problem(csv_file, 'table', inputs, .false.)
  if (len(problem) > 0) call app%die_files(problem)
  if (study%keep_results) then
    inputs(study%n_cases + 2) = ''
    do v = 1, study%n_variants
      do c = 1, study%n_cases
        problem = output_file_problem(trim(study%inp(c, v)%output%file), 'run result file', inputs, .true.)
        if (len(problem) > 0) call app%die_files(problem)
      end do
    end do
  end if
  if (.not. app%quiet) then
    if (file_kind(h5_file) == kind_regular) write (error_unit, '(a)') 'landyn_study: '//h5_file//' will be replaced'
    if (file_kind(csv_file) == kind_regular) write (error_unit, '(a)') 'landyn_study: '//csv_file//' will be replaced'
  end if

  ! ---- run
  progress = error_unit
  if (app%quiet) progress = -1
  cmd = command_line()
  call run_study(study, progress, cmd, run_stat, file_status)
  if (file_status%code == STAT_FILE) then
    write (error_unit, '(a)') 'landyn_study: '//file_status%text()
    call terminate(EXIT_FILE)
  end if

  ! ---- files
  call write_study_h5(study, h5_file, cmd, file_status)
  if (.not. file_status%ok()) then
    write (error_unit, '(a)') 'landyn_study: cannot write the result file: '//file_status%text()
    call terminate(EXIT_FILE)
  end if
  call write_study_csv(study, csv_file, file_status)
  if (.not. file_status%ok()) then
    write (error_unit, '(a)') 'landyn_study: cannot write the table: '//file_status%text()
    call terminate(EXIT_FILE)
  end if
  call write_table(output_unit)
  call write_outcomes(output_unit)
  write (output_unit, '(a)') 'Results written to '//h5_file//' and '//csv_file
  if (run_stat == status_failed) then
    write (error_unit, '(a)') 'landyn_study: some runs failed (status 3 in the result file)'
    call terminate(EXIT_DIVERGED)
  end if
  if (run_stat == status_unhealthy) then
    write (error_unit, '(a)') 'landyn_study: a run-health check failed for some runs: their results are '// &
      'physically meaningless (status 6 in the result file; docs/health.md)'
    call terminate(EXIT_HEALTH)
  end if
  if (run_stat == status_no_touchdown) then
    write (error_unit, '(a)') 'landyn_study: some runs never touched the ground (status 7 in the result file)'
    call terminate(EXIT_NO_TOUCHDOWN)
  end if
  call terminate(EXIT_OK)

contains

  !> The crush-length table on a unit (mm), as in the CSV.
  subroutine write_table(u)
    integer, intent(in) :: u               !! output unit
    integer :: m, vv
    write (u, '(a)') ''
    write (u, '(a)') 'Crush lengths [mm]: '//trim(study%title)
    write (u, '(a)', advance='no') '  opt  case        gear strut          '
    do vv = 1, study%n_variants
      write (u, '(1x,a14)', advance='no') adjustr(study%variant(vv)%label(1:min(14, len_trim(study%variant(vv)%label))))
    end do
    write (u, '(a)') ''
    do m = 1, study%n_measures
      write (u, '(2x,i3,2x,a12,i4,1x,a15)', advance='no') m, study%case_label(study%measure(1, m)), &
        study%measure(2, m), strut_names(study%measure(3, m))
      do vv = 1, study%n_variants
        associate (r => study%run(study%measure(1, m), vv))
          if (r%status /= status_ok) then
            write (u, '(a15)', advance='no') 'failed'
          else if (ieee_is_nan(table_value(study, m, vv))) then
            write (u, '(a15)', advance='no') 'no such gear'   ! a variant that changes gears%n_gears
          else
            write (u, '(f15.1)', advance='no') 1000.0_wp*table_value(study, m, vv)
          end if
        end associate
      end do
      write (u, '(a)') ''
    end do
  end subroutine write_table

  !> The outcome of every run on a unit: peak overload, largest tilt, smallest stroke margin,
  !! energy residual, the outcome and how the run ended (the figures the CSV and the result file hold besides the crush lengths).
  subroutine write_outcomes(u)
    integer, intent(in) :: u               !! output unit
    integer :: c, vv
    character(len=24) :: lab
    character(len=16) :: oname
    write (u, '(a)') ''
    write (u, '(a)') 'Run outcomes: peak overload at the mass centre [g], largest tilt [deg], smallest stroke margin of any'
    write (u, '(a)') 'strut [mm], energy audit residual [%], outcome (landyn_outcome) and how the run ended'
    write (u, '(a)') '  case         variant                   overload [g]  max tilt [deg]  margin [mm]  residual [%]  '// &
      'outcome         end'
    do c = 1, study%n_cases
      do vv = 1, study%n_variants
        lab = study%variant(vv)%label(1:min(24, len_trim(study%variant(vv)%label)))
        associate (r => study%run(c, vv))
          if (r%status == status_failed) then
            write (u, '(2x,a12,1x,a24,a)') study%case_label(c), lab, '        failed: '//trim(r%message)
          else
            oname = outcome_name(r%outcome)
            write (u, '(2x,a12,1x,a24,f15.3,f16.2,f13.1,f14.3,2x,a16,a)') study%case_label(c), lab, r%peak_overload, &
              r%max_tilt, 1000.0_wp*r%min_stroke_margin, 100.0_wp*r%energy_residual, oname, &
              trim(r%end_reason)//trim(merge(', TIPPED OVER', '             ', r%tipped_over))
          end if
        end associate
      end do
    end do
  end subroutine write_outcomes




end program landyn_study_main
