!> The landyn program runs one touchdown simulation of a legged lander.
!!
!!   landyn [DECK.nml] [-o FILE] [--check] [--quiet] [--help] [--version]
!!
!! Exit status: 0 the run touched down and ended with an outcome: at rest, tipped over, or still
!! moving at t_end (inconclusive; the printed outcome and /summary/outcome say which); 1 usage
!! error; 2 invalid input; 3 the simulation failed (diverged); 4 the result file cannot be written
!! (checked before the run where possible, docs/files.md); 6 the run completed but a run-health
!! check failed: the result is physically meaningless (file written, /summary/health says why;
!! docs/health.md); 7 no touchdown (file written; docs/exit_status.md).
program landyn
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use landyn_kinds, only: msg_len
  use landyn_config, only: landyn_input_t, default_input
  use landyn_input, only: input_errors_t, load_input, resolve_input, validate_input, write_resolved_input
  use landyn_simulation, only: sim_result_t
  use landyn_run, only: run_case, input_unhealthy, case_status_meaning
  use landyn_outcome, only: write_outcome
  use landyn_output, only: write_result_file
  use landyn_report, only: write_summary_table
  use landyn_health, only: health_t, write_health
  use landyn_files, only: output_file_problem, file_kind, kind_regular
  use landyn_process, only: terminate
  use landyn_status, only: status_t, STAT_OK, STAT_FAILED, EXIT_OK, EXIT_INPUT, EXIT_DIVERGED, EXIT_FILE, EXIT_HEALTH
  use landyn_cli, only: command_line, write_input_errors
  use landyn_app_support, only: app_t
  implicit none

  !> --help text
  character(len=120), parameter :: help_text(*) = [character(len=120) :: &
      'usage: landyn [DECK.nml] [-o FILE] [--check] [--quiet] [--help] [--version]', &
      '', &
      'Simulates the touchdown of a legged planetary lander (Wang et al., Aerospace 2023, 10, 811).', &
      'Without a deck, runs the built-in default: the paper''s 16 t lunar lander, load case LC-1.', &
      '', &
      '  DECK.nml        namelist input deck (see docs/input/); groups not given keep their defaults', &
      '  -o, --output F  result file (HDF5, docs/output.md); default: the deck''s base name + .h5', &
      '                  in the current directory, or &output file', &
      '  --check         validate the deck and print the fully resolved input; run nothing', &
      '  -q, --quiet     no progress messages on stderr', &
      '  -V, --version   print the version', &
      '  -h, --help      print this help', &
      '', &
      'Exit status: 0 touched down, outcome printed (at rest, tipped over, or still moving:', &
      'inconclusive), 1 usage error, 2 invalid input, 3 simulation failed (diverged),', &
      '4 result file not written (or refused: docs/files.md), 6 run-health check failed: result', &
      'physically meaningless (docs/health.md), 7 no touchdown (docs/exit_status.md).']

  type(app_t) :: app
  type(landyn_input_t) :: inp
  type(input_errors_t) :: errors
  type(sim_result_t) :: res
  type(health_t) :: health
  character(len=:), allocatable :: deck, out_file, arg, cmd, problem
  logical :: check_only
  integer :: stat, status, progress
  logical :: ran
  character(len=msg_len) :: msg
  type(status_t) :: write_status

  call app%start('landyn', trim(help_text(1)), help_text)
  deck = ''
  out_file = ''
  check_only = .false.
  do while (app%next_arg(arg))
    select case (arg)
    case ('--check')
      check_only = .true.
    case ('-o', '--output')
      out_file = app%option_value(arg)
    case default
      call app%positional(arg, deck, 'deck')
    end select
  end do

  ! ---- input: the deck, or the built-in default (the paper's lander, load case LC-1)
  if (len(deck) > 0) then
    call load_input(deck, inp, errors, stat)
  else
    inp = default_input()
    call resolve_input(inp, errors)
    call validate_input(inp, errors)
    stat = merge(STAT_OK, STAT_FAILED, errors%count() == 0)
  end if
  if (stat /= 0 .or. errors%count() > 0) then
    call write_input_errors(error_unit, 'landyn', errors)
    call terminate(EXIT_INPUT)
  end if
  if (check_only) then
    call write_resolved_input(output_unit, inp)
    call terminate(EXIT_OK)
  end if
  if (len(out_file) == 0) out_file = trim(inp%output%file)

  ! ---- the result file may be written (docs/files.md): checked before the run
  problem = output_file_problem(out_file, 'result file', [character(len=len(deck)) :: deck], .true.)
  if (len(problem) > 0) call app%die_files(problem)
  if (file_kind(out_file) == kind_regular .and. .not. app%quiet) &
    write (error_unit, '(a)') 'landyn: '//out_file//' exists and will be replaced'

  ! ---- run: input health, simulation, result health, outcome (landyn_run, as landyn_study and
  ! landyn_batch run a case)
  progress = error_unit
  if (app%quiet) progress = -1
  if (.not. app%quiet) then
    if (len(deck) > 0) then
      write (error_unit, '(a)') 'landyn: running '//deck//' -> '//out_file
    else
      write (error_unit, '(a)') 'landyn: running the built-in default (paper lander, LC-1) -> '//out_file
    end if
  end if
  msg = ''
  call run_case(inp, res, health, status, msg, progress, ran=ran)
  if (input_unhealthy(status, ran)) then
    call write_health(error_unit, 'landyn: ', health)
    write (error_unit, '(a)') 'landyn: a run-health check of the input failed: the run would be physically '// &
      'meaningless; nothing was run and no file was written (exit status 6)'
    call terminate(EXIT_HEALTH)
  end if
  if (.not. ran) then
    write (error_unit, '(a)') 'landyn: simulation failed: '//trim(msg)
    write (error_unit, '(a)') 'landyn: no result file was written'
    call terminate(EXIT_DIVERGED)
  end if

  ! ---- result file
  cmd = command_line()
  call write_result_file(out_file, inp, res, cmd, write_status, health)
  if (.not. write_status%ok()) then
    write (error_unit, '(a)') 'landyn: cannot write the result file: '//write_status%text()
    call terminate(EXIT_FILE)
  end if
  call write_summary_table(output_unit, inp, res)
  call write_outcome(output_unit, res)
  call write_health(output_unit, '', health)
  write (output_unit, '(a)') 'Results written to '//out_file
  if (status == EXIT_HEALTH) then
    call write_health(error_unit, 'landyn: ', health)
    write (error_unit, '(a)') 'landyn: a run-health check failed: the result is physically meaningless '// &
      '(exit status 6; /summary/health in '//out_file//')'
  else if (status /= EXIT_OK) then
    write (error_unit, '(a,i0,a)') 'landyn: '//case_status_meaning(status)//' (exit status ', status, &
      '; /summary/outcome in '//out_file//')'
  end if
  call terminate(status)

end program landyn
