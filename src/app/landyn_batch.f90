!> The landyn_batch program runs campaigns of LANDYN runs (grids, Monte Carlo dispersions, case lists) on
!! one or many MPI ranks, and the serial pieces for Slurm job arrays. See docs/campaign.md.
!!
!!   mpirun -np N landyn_batch DECK [--resume] [--force] [--stop-after N] [-o FILE] [--dedicated-master] [-q]
!!   landyn_batch DECK --case K[:L] [-o FILE] [-q]     (no MPI: rows of cases K..L to a file of their own)
!!   landyn_batch --merge OUT IN...                    (no MPI: combine summary files)
!!   landyn_batch DECK --check | --list-cases          (no MPI)
!!
!! Exit status: 0 success (failed cases are results, not errors); 1 usage error; 2 invalid
!! campaign (deck, base deck, case list) or files of another campaign; 4 a file cannot be
!! written (or is refused before anything runs: an input, a device, a read-only or non-HDF5
!! file; docs/files.md); 5 stopped early (--stop-after) or merged summary incomplete.
program landyn_batch
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use landyn_cli, only: get_arg, command_line
  use landyn_status, only: EXIT_OK, EXIT_USAGE, EXIT_INPUT, EXIT_DIVERGED, EXIT_FILE, EXIT_INCOMPLETE
  use landyn_app_support, only: app_t
  use landyn_campaign_tasks, only: check_campaign, list_cases, run_case_range, merge_summaries
  use landyn_campaign_parallel, only: batch_options_t, run_campaign
  use landyn_process, only: terminate
  use landyn_input, only: input_errors_t
  use landyn_campaign_deck, only: campaign_t, load_campaign
  use landyn_files, only: output_file_problem
  implicit none

  !> --help text
  character(len=120), parameter :: help_text(*) = [character(len=120) :: &
      'usage: mpirun -np N landyn_batch DECK [--resume | --force] [--stop-after N] [-o FILE]', &
      '                                      [--dedicated-master] [-q]', &
      '       landyn_batch DECK --case K[:L] [--history] [-o FILE] [-q]', &
      '       landyn_batch --merge OUT IN...', &
      '       landyn_batch DECK --check | --list-cases', &
      '', &
      'Runs a LANDYN campaign (grid, Monte Carlo dispersion or case list; docs/campaign.md): every case', &
      'is the campaign''s base run deck with the case''s inputs, run exactly as landyn runs it.', &
      'Rank 0 hands out the cases; all rows go to one HDF5 summary file.', &
      '', &
      '  DECK                campaign deck (&campaign, &parameter, &criteria)', &
      '  -o, --output F      summary file (default: &campaign summary_file, or DECK''s base name + .h5);', &
      '                      with --case: the file of the cases'' rows; with --merge: see below', &
      '  --resume            continue the campaign of the summary file and its journal, skipping', &
      '                      finished cases; the result equals an uninterrupted run', &
      '  --force             overwrite an existing summary file and journal', &
      '  --stop-after N      stop after N rows are written, as if killed (to test --resume)', &
      '  --dedicated-master  rank 0 only hands out cases (default: it runs cases too up to 16 ranks)', &
      '  --case K[:L]        without MPI: run cases K..L and write their rows to their own file', &
      '                      (default <summary>.case<K>.h5); for Slurm job arrays', &
      '  --history           with --case: also write each case''s full time history (a landyn result', &
      '                      file, <summary stem>_case<K, 6 digits>.h5), e.g. to re-run an outlier:', &
      '                      landyn_batch DECK --case 137 --history -o outlier.h5', &
      '  --merge OUT IN...   without MPI: combine summary files of one campaign into OUT', &
      '  --check             validate the deck and describe the campaign; run nothing', &
      '  --list-cases        print every case''s inputs as CSV; run nothing', &
      '  -q, --quiet         no progress messages on stderr', &
      '  -v, --verbose       also the time account on stderr (where each rank''s time went, per-case', &
      '                      overhead; docs/campaign.md, "Scaling")', &
      '  -V, --version       print the version', &
      '  -h, --help          print this help', &
      '', &
      'Exit status: 0 success (failed cases are results), 1 usage error, 2 invalid campaign or files of', &
      'another campaign, 4 a file not written (or refused: docs/files.md), 5 stopped early (--stop-after)', &
      'or merged summary incomplete.']

  type(app_t) :: app
  type(batch_options_t) :: opts
  character(len=:), allocatable :: deck, arg, out_file, task, range_text
  character(len=1024), allocatable :: inputs(:)
  integer :: code, k1, k2, ios, p
  logical :: history = .false.

  call app%start('landyn_batch', 'usage: landyn_batch DECK [options] | DECK --case K[:L] | --merge OUT IN... '// &
                 '(landyn_batch --help)', help_text)
  deck = ''
  out_file = ''
  task = 'campaign'
  range_text = ''
  opts%summary_file = ''
  opts%command_line = command_line()
  do while (app%next_arg(arg))
    select case (arg)
    case ('--resume')
      opts%resume = .true.
    case ('--force')
      opts%force = .true.
    case ('--dedicated-master')
      opts%dedicated_master = .true.
    case ('-v', '--verbose')
      opts%verbose = .true.
    case ('--history')
      history = .true.
    case ('--check')
      call set_task('check')
    case ('--list-cases')
      call set_task('list')
    case ('--stop-after')
      arg = app%option_value(arg, missing='option --stop-after needs a number of cases')
      read (arg, *, iostat=ios) opts%stop_after
      if (ios /= 0 .or. opts%stop_after < 1) call app%die_usage('--stop-after needs a positive number, got '//arg)
    case ('-o', '--output')
      out_file = app%option_value(arg)
    case ('--case')
      range_text = app%option_value(arg, missing='option --case needs a case id K or a range K:L')
      call set_task('case')
    case ('--merge')
      call set_task('merge')
      if (app%n - app%i < 2) call app%die_usage('--merge needs an output file and at least one input file')
      out_file = get_arg(app%i + 1)
      if (len(out_file) == 0) call app%die_usage('--merge needs a non-empty output file name')
      allocate (inputs(app%n - app%i - 1))
      do p = 1, size(inputs)
        inputs(p) = get_arg(app%i + 1 + p)
        if (len(get_arg(app%i + 1 + p)) > len(inputs(p))) call app%die_usage('file name too long: '//get_arg(app%i + 1 + p))
      end do
      app%i = app%n
    case default
      call app%positional(arg, deck, 'deck')
    end select
  end do
  opts%quiet = app%quiet

  code = EXIT_OK
  if (history .and. task /= 'case') call app%die_usage('--history goes with --case K[:L] (the cases to re-run '// &
                                                      'with their time histories)')
  call check_output_file()
  select case (task)
  case ('merge')
    if (len(deck) > 0) call app%die_usage('--merge takes no deck: landyn_batch --merge OUT IN...')
    call merge_summaries(out_file, inputs, opts%command_line, output_unit, error_unit, code)
  case ('check')
    call need_deck()
    call check_campaign(deck, output_unit, error_unit, code)
  case ('list')
    call need_deck()
    call list_cases(deck, output_unit, error_unit, code)
  case ('case')
    call need_deck()
    p = index(range_text, ':')
    if (p == 0) then
      read (range_text, *, iostat=ios) k1
      k2 = k1
    else
      read (range_text(1:p - 1), *, iostat=ios) k1
      if (ios == 0) read (range_text(p + 1:), *, iostat=ios) k2
    end if
    if (ios /= 0 .or. verify(range_text, '0123456789:') /= 0) &
      call app%die_usage('--case needs a case id K or a range K:L, got '//range_text)
    call run_case_range(deck, k1, k2, out_file, opts%quiet, opts%command_line, output_unit, error_unit, code, history)
  case default
    call need_deck()
    opts%summary_file = out_file
    if (opts%resume .and. opts%force) call app%die_usage('--resume and --force exclude each other')
    call run_campaign(deck, opts, output_unit, error_unit, code)
  end select

  select case (code)
  case (EXIT_OK)
    continue
  case (EXIT_USAGE, EXIT_INPUT, EXIT_FILE)
    call terminate(code)
  case (EXIT_INCOMPLETE)
    call terminate(code)   ! not an error: the summary is incomplete (--stop-after, or --merge with cases missing)
  case default
    call terminate(EXIT_DIVERGED)
  end select

contains

  !> Select the task; two different task options are a usage error.
  subroutine set_task(t)
    character(len=*), intent(in) :: t      !! task name
    if (task /= 'campaign' .and. task /= t) call app%die_usage('--check, --list-cases, --case and --merge exclude '// &
                                                          'each other')
    task = t
  end subroutine set_task

  !> The output-file policy (docs/files.md), before anything runs: the summary file (or the file of
  !! --case / --merge) is never an input of the campaign, a device, a directory, read-only or a
  !! file other than HDF5. A campaign that does not load is left to the task, which reports it.
  subroutine check_output_file()
    type(campaign_t) :: camp
    type(input_errors_t) :: errors
    character(len=:), allocatable :: path, why
    character(len=4096), allocatable :: files(:)
    integer :: st, k
    select case (task)
    case ('merge')
      allocate (files(size(inputs)))
      files = inputs
      path = out_file
    case ('campaign', 'case')
      if (len(deck) == 0) return
      call load_campaign(deck, camp, errors, st)
      if (st /= 0) return
      path = out_file
      if (len(path) == 0 .and. task == 'campaign') path = camp%summary_file
      if (len(path) == 0) return
      allocate (files(3))
      files(1) = deck
      files(2) = ''
      files(3) = ''
      if (allocated(camp%base_path)) files(2) = camp%base_path
      if (allocated(camp%list_path)) files(3) = camp%list_path
    case default
      return
    end select
    do k = 1, size(files)
      if (len_trim(files(k)) > 0 .and. trim(files(k)) == path) then
        write (error_unit, '(a)') 'landyn_batch: output file '''//path//''' is an input of this run; refusing '// &
          'to overwrite it'
        call terminate(EXIT_FILE)
      end if
    end do
    why = output_file_problem(path, 'output file', files, .true.)
    if (len(why) > 0) call app%die_files(why)
  end subroutine check_output_file

  !> A usage error unless a campaign deck was given.
  subroutine need_deck()
    if (len(deck) == 0) call app%die_usage('no campaign deck given')
  end subroutine need_deck



end program landyn_batch
