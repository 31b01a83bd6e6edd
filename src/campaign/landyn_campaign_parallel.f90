!> MPI execution of a campaign (mpi_f08).
!!
!! Rank 0 reads and checks the campaign deck, prepares the summary file (or resumes it), sends
!! the deck texts to the other ranks and hands out case ids dynamically: each worker holds up
!! to `depth` ids (so that it never waits for rank 0) and gets the next id when it returns a
!! row. Rank 0 also runs cases itself when the world is small (at most 16 ranks, unless
!! --dedicated-master), checking for returned rows between its own cases; a worker then holds
!! at least two ids until the last ones are handed out, so that it has work while rank 0 runs a
!! case. With one rank, rank 0 runs every case. A case that fails is a row with its status and
!! message; the campaign goes on.
!!
!! A rank that waits (a worker for its next id, rank 0 for rows) does not spin in a blocking MPI
!! call: it tests for the message and naps between tests (1 us, doubling up to max_nap_us), so
!! that waiting ranks leave the cores to the ranks that compute (shared or oversubscribed nodes).
!!
!! Rank 0 appends every row to the journal at once and flushes the journal whenever no further
!! row is waiting (at the latest every flush_interval seconds), rewrites the summary file every
!! checkpoint_interval seconds (but at most once per ckpt_cost_factor times the duration of the
!! last rewrite, so that checkpoints of large campaigns stay a small part of rank 0's time) and
!! at the end (landyn_campaign_store); at the end the journal is deleted. Case inputs depend only
!! on (seed, case id), never on the rank or the order.
!!
!! Every rank accounts for its time (simulation, case input, metrics, waiting, messages,
!! journal and table, checkpoints); rank 0 gathers the accounts and prints them after the
!! result (docs/campaign.md, "Scaling").
!!
!! Messages (all on MPI_COMM_WORLD): rank 0 -> worker, tag_work: one integer, the case id
!! (0: stop). Worker -> rank 0, tag_row: one row as one message of bytes (its integer and real
!! parts' bit patterns and its text; row_message). Both sides send without blocking (MPI_Isend,
!! completed before the buffer is used again): a blocking send of a worker waited, on shared
!! memory, until rank 0 came back from its own case to receive it (issue 12: 14 % of a worker's
!! time on 2 ranks).
!!
!! Library code: reports go to the units the caller passes; the result is an exit code.
module landyn_campaign_parallel
  use, intrinsic :: iso_c_binding, only: c_int, c_long
  use mpi_f08, only: MPI_Init, MPI_Finalize, MPI_Comm_rank, MPI_Comm_size, MPI_Bcast, MPI_Recv, MPI_Isend, &
                     MPI_Irecv, MPI_Test, MPI_Wait, MPI_Iprobe, MPI_Get_count, MPI_Abort, MPI_Wtime, MPI_Gather, &
                     MPI_Status, MPI_Request, MPI_REQUEST_NULL, MPI_STATUS_IGNORE, MPI_COMM_WORLD, MPI_INTEGER, &
                     MPI_DOUBLE_PRECISION, MPI_CHARACTER, MPI_ANY_SOURCE
  use landyn_kinds, only: wp
  use landyn_input, only: input_errors_t
  use landyn_h5, only: delete_file
  use landyn_campaign_text, only: int_text, real_text_short
  use landyn_campaign_deck, only: campaign_t, build_campaign, use_summary_file
  use landyn_campaign_case, only: case_row_t, run_case, pack_row, unpack_row, row_int_count, row_real_count, &
                                  status_ok
  use landyn_campaign_store, only: summary_meta_t, meta_from_campaign, write_summary, read_summary, results_t, &
                                   results_init, results_add, results_rows, results_missing, &
                                   results_take_rows
  use landyn_campaign_journal, only: journal_open, journal_append, journal_flush, journal_read
  use landyn_files, only: lock_file, unlock_file
  use landyn_status, only: status_t, STAT_FAILED, EXIT_OK, EXIT_USAGE, EXIT_INPUT, EXIT_FILE, EXIT_INCOMPLETE
  use landyn_campaign_tasks, only: load_or_report, report_probability, report_row
  implicit none
  private

  public :: batch_options_t, run_campaign

  !> Options of a campaign run (from the command line).
  type :: batch_options_t
    logical :: resume = .false.                    !! continue from the summary file and journal [-]
    logical :: force = .false.                     !! overwrite an existing summary file [-]
    integer :: stop_after = 0                      !! stop (as if killed) after this many rows; 0: never [-]
    logical :: quiet = .false.                     !! no progress lines [-]
    logical :: verbose = .false.                   !! the time account on the message unit [-]
    logical :: dedicated_master = .false.          !! rank 0 only hands out cases [-]
    character(len=:), allocatable :: summary_file  !! summary file ('' : the deck's) [-]
    character(len=:), allocatable :: command_line  !! the command line, recorded in the files [-]
  end type batch_options_t

  integer, parameter :: tag_work = 11, tag_row = 12  !! message tags: case ids to workers, rows to rank 0 [-]
  integer, parameter :: master_works_max_ranks = 16  !! rank 0 runs cases too up to this many ranks [-]
  integer, parameter :: depth_master_works = 4       !! ids a worker holds when rank 0 runs cases too [-]
  integer, parameter :: depth_dedicated = 2          !! ids a worker holds with a dedicated rank 0 [-]
  integer, parameter :: max_nap_us = 200             !! longest nap of a waiting rank between tests [us]
  real(wp), parameter :: flush_interval = 0.05_wp    !! journal lines wait at most this long for a flush [s]
  real(wp), parameter :: ckpt_cost_factor = 50.0_wp  !! checkpoints at most once per this many times their duration [-]

  ! Slots of a rank's time account (prof(:)): times [s] and counts [-].
  integer, parameter :: p_loop = 1      !! time in the master or worker loop [s]
  integer, parameter :: p_input = 2     !! case input: values, case deck, reading, checks [s]
  integer, parameter :: p_sim = 3       !! run_simulation [s]
  integer, parameter :: p_after = 4     !! metrics, criteria, history file [s]
  integer, parameter :: p_wait = 5      !! waiting for ids (worker) or rows (rank 0) [s]
  integer, parameter :: p_comm = 6      !! messages: packing, sending, receiving, unpacking [s]
  integer, parameter :: p_record = 7    !! rank 0: table, journal, progress lines [s]
  integer, parameter :: p_ckpt = 8      !! rank 0: summary-file checkpoints [s]
  integer, parameter :: p_cases = 9     !! cases run by the rank [-]
  integer, parameter :: p_steps = 10    !! time steps of those cases [-]
  integer, parameter :: p_rows = 11     !! rank 0: rows recorded [-]
  integer, parameter :: p_nckpt = 12    !! rank 0: checkpoints written [-]
  integer, parameter :: p_ckpt_max = 13 !! rank 0: longest checkpoint [s]
  integer, parameter :: p_book_cpu = 14 !! rank 0: CPU time of messages, journal and table (unlike the wall
                                        !! times above, not inflated when the rank shares its core) [s]
  integer, parameter :: n_prof = 14     !! slots [-]

  integer, parameter :: row_slots = depth_master_works + 2  !! send buffers of a worker's rows [-]

  !> Rank 0's state in master_loop: the cases to hand out, each worker's ids in flight and their
  !! send buffers, the journal's flush state, the checkpoint clock and the session's count.
  type :: master_t
    integer, allocatable :: pend(:)                  !! cases to run, in order [-]
    integer :: next = 1                              !! index in pend of the next case to hand out [-]
    integer :: nranks = 1                            !! ranks [-]
    integer :: nw = 0                                !! workers (ranks 1 .. nw) [-]
    integer :: depth = depth_dedicated               !! ids a worker holds at most [-]
    logical :: master_works = .true.                 !! rank 0 runs cases too [-]
    integer, allocatable :: inflight(:)              !! ids each worker holds [-]
    logical, allocatable :: active(:)                !! worker not yet sent its stop [-]
    integer, allocatable :: n_sent(:)                !! ids sent to each worker [-]
    integer, allocatable :: id_buf(:, :)             !! send buffers of the ids (slot, worker) [-]
    type(MPI_Request), allocatable :: id_req(:, :)   !! their send requests [-]
    integer :: every = 1                             !! a progress line every this many rows [-]
    integer :: n_unflushed = 0                       !! journal lines not yet flushed [-]
    logical :: journal_ok = .true.                   !! no journal operation has failed [-]
    real(wp) :: t_flush = 0.0_wp                     !! time of the last journal flush (MPI_Wtime) [s]
    real(wp) :: t_next_ckpt = 0.0_wp                 !! time of the next checkpoint (MPI_Wtime) [s]
    integer :: n_session = 0                         !! rows recorded in this run [-]
    logical :: stopped = .false.                     !! stopped by --stop-after [-]
  end type master_t

  !> Rank 0's units: the journal and the messages.
  type :: master_sink_t
    integer :: ju = -1                               !! journal unit [-]
    integer :: err_u = 0                             !! unit for messages and progress [-]
  end type master_sink_t

  !> Rank 0's account of this run of a campaign (for finish_campaign).
  type :: session_t
    integer :: nranks = 1                            !! ranks [-]
    integer :: n_session = 0                         !! rows recorded in this run [-]
    logical :: stopped = .false.                     !! stopped by --stop-after [-]
    real(wp) :: t0 = 0.0_wp                          !! start of the loops (MPI_Wtime) [s]
    real(wp) :: t1 = 0.0_wp                          !! their end (MPI_Wtime) [s]
  end type session_t

  !> A message buffer.
  type :: row_buffer_t
    character(len=:), allocatable :: b   !! message [bytes]
  end type row_buffer_t

  !> struct timespec of nanosleep(2)
  type, bind(c) :: timespec_t
    integer(c_long) :: sec = 0_c_long   !! seconds [s]
    integer(c_long) :: nsec = 0_c_long  !! nanoseconds [ns]
  end type timespec_t

  !> POSIX nanosleep(2), for the master's short waits.
  interface
    !> POSIX nanosleep(2)
    function c_nanosleep(req, rem) bind(c, name='nanosleep') result(r)
      import :: c_int, timespec_t
      type(timespec_t), intent(in) :: req    !! time to sleep [-]
      type(timespec_t), intent(out) :: rem   !! time left when interrupted [-]
      integer(c_int) :: r                    !! 0 or -1 [-]
    end function c_nanosleep
  end interface

contains

  !> Run the campaign of `deck` on all ranks of MPI_COMM_WORLD (initialises and finalises MPI).
  !! `code` is the exit code on rank 0 and EXIT_OK on the other ranks.
  subroutine run_campaign(deck, opts, out_u, err_u, code)
    character(len=*), intent(in) :: deck          !! campaign deck [-]
    type(batch_options_t), intent(in) :: opts     !! options [-]
    integer, intent(in) :: out_u                  !! unit for results (rank 0) [-]
    integer, intent(in) :: err_u                  !! unit for messages and progress (rank 0) [-]
    integer, intent(out) :: code                  !! exit code [-]
    type(campaign_t) :: camp
    type(results_t) :: table
    type(summary_meta_t) :: meta
    type(session_t) :: ses
    character(len=:), allocatable :: summary, journal
    integer :: rank, nranks, ju, lock
    real(wp) :: prof(n_prof)
    real(wp), allocatable :: prof_all(:, :)

    call MPI_Init()
    call MPI_Comm_rank(MPI_COMM_WORLD, rank)
    call MPI_Comm_size(MPI_COMM_WORLD, nranks)
    code = EXIT_OK
    ju = -1
    lock = -1
    if (rank == 0) call open_campaign(deck, opts, err_u, camp, meta, summary, journal, table, ju, lock, code)
    call MPI_Bcast(code, 1, MPI_INTEGER, 0, MPI_COMM_WORLD)
    if (code /= EXIT_OK) then
      call MPI_Finalize()
      if (rank /= 0) code = EXIT_OK
      return
    end if
    call share_campaign(rank, err_u, camp)
    call use_summary_file(camp, opts%summary_file)   ! history files follow -o (issue 10)

    prof = 0.0_wp
    ses%nranks = nranks
    ses%t0 = MPI_Wtime()
    if (rank == 0) then
      if (.not. opts%quiet) write (err_u, '(a)') 'landyn_batch: campaign '//deck//': '//trim(camp%mode)//', '// &
        int_text(camp%n_cases)//' cases ('//int_text(camp%n_cases - table%n_have)//' to run) on '// &
        int_text(nranks)//' rank(s) -> '//summary
      call master_loop(camp, opts, nranks, table, meta, summary, ju, err_u, ses%n_session, ses%stopped, prof)
    else
      call worker_loop(camp, opts%command_line, prof)
    end if
    ses%t1 = MPI_Wtime()
    prof(p_loop) = ses%t1 - ses%t0
    allocate (prof_all(n_prof, merge(nranks, 1, rank == 0)))
    call MPI_Gather(prof, n_prof, MPI_DOUBLE_PRECISION, prof_all, n_prof, MPI_DOUBLE_PRECISION, 0, MPI_COMM_WORLD)

    if (rank == 0) then
      close (ju)
      call finish_campaign(deck, opts, camp, meta, summary, journal, table, ses, prof_all, out_u, err_u, code)
      call unlock_file(summary//'.lock', lock)
    end if
    call MPI_Finalize()
    if (rank /= 0) code = EXIT_OK
  end subroutine run_campaign

  !> Rank 0: read and check the campaign deck, take the campaign's lock and prepare its summary
  !! file and journal (or resume them). On failure `code` says why and no lock is held.
  subroutine open_campaign(deck, opts, err_u, camp, meta, summary, journal, table, ju, lock, code)
    character(len=*), intent(in) :: deck          !! campaign deck [-]
    type(batch_options_t), intent(in) :: opts     !! options [-]
    integer, intent(in) :: err_u                  !! unit for messages [-]
    type(campaign_t), intent(out) :: camp         !! the campaign [-]
    type(summary_meta_t), intent(out) :: meta     !! its meta data [-]
    character(len=:), allocatable, intent(out) :: summary   !! summary file [-]
    character(len=:), allocatable, intent(out) :: journal   !! journal file [-]
    type(results_t), intent(out) :: table         !! rows already done [-]
    integer, intent(inout) :: ju                  !! journal unit [-]
    integer, intent(inout) :: lock                !! lock of the campaign (lock_file) [-]
    integer, intent(out) :: code                  !! exit code [-]
    type(status_t) :: lock_st
    call load_or_report(deck, camp, err_u, code)
    if (code /= EXIT_OK) return
    summary = opts%summary_file
    if (len(summary) == 0) summary = camp%summary_file
    journal = summary//'.journal'
    meta = meta_from_campaign(camp)
    ! one process per campaign: two resumes of one journal would both append to it and
    ! both write the summary file (the kernel releases the lock when the process ends)
    call lock_file(summary//'.lock', lock, lock_st)
    if (.not. lock_st%ok()) then
      write (err_u, '(a)') 'landyn_batch: the campaign of '//summary//' is in use: '//summary//'.lock: '// &
        lock_st%text()//'; wait for that run to end (a killed run leaves no lock held)'
      code = EXIT_FILE
    else
      call prepare_output(camp, meta, opts, summary, journal, table, ju, err_u, code)
      if (code /= EXIT_OK) call unlock_file(summary//'.lock', lock)
    end if
  end subroutine open_campaign

  !> Every rank builds the same campaign from rank 0's texts (deck name, deck, base deck, case
  !! list); a rank where it does not build aborts the run.
  subroutine share_campaign(rank, err_u, camp)
    integer, intent(in) :: rank                   !! this rank [-]
    integer, intent(in) :: err_u                  !! unit for messages [-]
    type(campaign_t), intent(inout) :: camp       !! campaign: read on rank 0, built on the others [-]
    type(input_errors_t) :: errors
    character(len=:), allocatable :: deck_name, deck_text, base_text, list_text
    integer :: st
    if (rank == 0) then
      call bcast_text(camp%deck_name, rank)
      call bcast_text(camp%deck_text, rank)
      call bcast_text(camp%base_text, rank)
      call bcast_text(camp%list_text, rank)
    else
      call bcast_text(deck_name, rank)
      call bcast_text(deck_text, rank)
      call bcast_text(base_text, rank)
      call bcast_text(list_text, rank)
      call build_campaign(deck_name, deck_text, base_text, list_text, camp, errors, st)
      if (st /= 0) then
        write (err_u, '(a,i0,a)') 'landyn_batch: rank ', rank, ': the campaign read on rank 0 does not build here: '// &
          errors%message(1)
        call MPI_Abort(MPI_COMM_WORLD, EXIT_INPUT)
      end if
    end if
  end subroutine share_campaign

  !> Rank 0, after the loop: write the final summary file, delete the journal and report the
  !! campaign (or, stopped by --stop-after, say how to continue).
  subroutine finish_campaign(deck, opts, camp, meta, summary, journal, table, ses, prof_all, out_u, err_u, code)
    character(len=*), intent(in) :: deck          !! campaign deck [-]
    type(batch_options_t), intent(in) :: opts     !! options [-]
    type(campaign_t), intent(in) :: camp          !! campaign [-]
    type(summary_meta_t), intent(in) :: meta      !! its meta data [-]
    character(len=*), intent(in) :: summary       !! summary file [-]
    character(len=*), intent(in) :: journal       !! journal file [-]
    type(results_t), intent(inout) :: table       !! rows (taken) [-]
    type(session_t), intent(in) :: ses            !! this run's account [-]
    real(wp), intent(in) :: prof_all(:, :)        !! time accounts of all ranks (slots p_*, rank) [s, -]
    integer, intent(in) :: out_u                  !! unit for results [-]
    integer, intent(in) :: err_u                  !! unit for messages [-]
    integer, intent(out) :: code                  !! exit code [-]
    type(case_row_t), allocatable :: rows(:)
    type(status_t) :: st
    real(wp) :: dt
    code = EXIT_OK
    if (ses%stopped) then
      write (err_u, '(a)') 'landyn_batch: stopped after '//int_text(ses%n_session)//' case(s) (--stop-after); '// &
        int_text(table%n_have)//' of '//int_text(camp%n_cases)//' cases are in '//journal// &
        '; continue with --resume'
      code = EXIT_INCOMPLETE
      return
    end if
    call results_take_rows(table, rows)
    call write_summary(summary, meta, rows, opts%command_line, st)
    if (.not. st%ok()) then
      write (err_u, '(a)') 'landyn_batch: cannot write the summary file: '//st%text()
      write (err_u, '(a)') 'landyn_batch: the rows are kept in '//journal//'; fix the problem and run with --resume'
      code = EXIT_FILE
      return
    end if
    call delete_file(journal)
    ! speed and (--verbose) the time account are diagnostics: on the message unit, before the
    ! result on out_u, whose final line counts the failures per criterion
    dt = ses%t1 - ses%t0
    if (ses%n_session > 0 .and. ses%t1 > ses%t0 .and. (opts%verbose .or. .not. opts%quiet)) write (err_u, '(a)') &
      'landyn_batch: this run: '//int_text(ses%n_session)//' cases in '//real_text_short(dt)//' s on '// &
      int_text(ses%nranks)//' rank(s) = '// &
      int_text(nint(real(ses%n_session, wp)*3600.0_wp/(dt*real(ses%nranks, wp))))//' cases per core-hour'
    if (ses%n_session > 0 .and. opts%verbose) call report_profile(prof_all, err_u)
    write (out_u, '(a)') 'LANDYN campaign '//deck//' ('//trim(camp%mode)//'): '//int_text(size(rows))//' of '// &
      int_text(camp%n_cases)//' cases in '//summary
    call report_probability(rows, camp%crit%failed_runs, out_u)
  end subroutine finish_campaign

  !> Rank 0: existing files, resume, journal.
  subroutine prepare_output(camp, meta, opts, summary, journal, table, ju, err_u, code)
    type(campaign_t), intent(in) :: camp          !! campaign [-]
    type(summary_meta_t), intent(in) :: meta      !! its meta data [-]
    type(batch_options_t), intent(in) :: opts     !! options [-]
    character(len=*), intent(in) :: summary       !! summary file [-]
    character(len=*), intent(in) :: journal       !! journal file [-]
    type(results_t), intent(out) :: table         !! rows already done [-]
    integer, intent(out) :: ju                    !! journal unit [-]
    integer, intent(in) :: err_u                  !! unit for messages [-]
    integer, intent(out) :: code                  !! exit code [-]
    logical :: ex_s, ex_j
    type(status_t) :: jst
    code = EXIT_OK
    ju = -1
    call results_init(table, camp%n_cases)
    inquire (file=summary, exist=ex_s)
    inquire (file=journal, exist=ex_j)
    if (.not. opts%resume) then
      if ((ex_s .or. ex_j) .and. .not. opts%force) then
        if (ex_s) then
          write (err_u, '(a)') 'landyn_batch: '//summary//' exists; run with --resume to continue that campaign, '// &
            'or --force to start it afresh'
        else
          write (err_u, '(a)') 'landyn_batch: '//journal//' exists; run with --resume to continue that campaign, '// &
            'or --force to start it afresh'
        end if
        code = EXIT_USAGE
        return
      end if
      call delete_file(summary)
      call delete_file(journal)
    else
      call resume_rows(camp, meta, opts, summary, journal, ex_s, ex_j, table, err_u, code)
      if (code /= EXIT_OK) return
    end if
    call journal_open(journal, meta, ju, jst)
    if (.not. jst%ok()) then
      write (err_u, '(a)') 'landyn_batch: '//jst%text()
      code = EXIT_FILE
    end if
  end subroutine prepare_output

  !> Rank 0, --resume: the rows already done, from the summary file (which must belong to this
  !! campaign) and the journal, into the table; reports what was taken and ignored.
  subroutine resume_rows(camp, meta, opts, summary, journal, ex_s, ex_j, table, err_u, code)
    type(campaign_t), intent(in) :: camp          !! campaign [-]
    type(summary_meta_t), intent(in) :: meta      !! its meta data [-]
    type(batch_options_t), intent(in) :: opts     !! options [-]
    character(len=*), intent(in) :: summary       !! summary file [-]
    character(len=*), intent(in) :: journal       !! journal file [-]
    logical, intent(in) :: ex_s                   !! the summary file exists [-]
    logical, intent(in) :: ex_j                   !! the journal exists [-]
    type(results_t), intent(inout) :: table       !! rows already done [-]
    integer, intent(in) :: err_u                  !! unit for messages [-]
    integer, intent(out) :: code                  !! exit code [-]
    type(summary_meta_t) :: m
    type(case_row_t), allocatable :: rows(:)
    type(status_t) :: rs
    integer :: n_s, n_j, n_bad, n_out
    code = EXIT_OK
    n_s = 0
    n_j = 0
    n_bad = 0
    n_out = 0
    if (ex_s) then
      call read_summary(summary, m, rows, rs)
      if (.not. rs%ok()) then
        write (err_u, '(a)') 'landyn_batch: --resume: '//rs%text()
        code = EXIT_INPUT
        return
      end if
      if (m%fingerprint /= camp%fingerprint) then
        write (err_u, '(a)') 'landyn_batch: --resume: '//summary//' belongs to another campaign (fingerprint '// &
          m%fingerprint//'; this deck: '//camp%fingerprint//'); give another summary_file or use --force'
        code = EXIT_INPUT
        return
      end if
      call add_rows(table, rows, n_s, n_out)
    end if
    if (ex_j) then
      call journal_read(journal, meta, rows, n_bad, rs)
      if (.not. rs%ok()) then
        write (err_u, '(a)') 'landyn_batch: --resume: '//rs%text()
        code = EXIT_INPUT
        return
      end if
      call add_rows(table, rows, n_j, n_out)
    end if
    if (opts%quiet) return
    if (ex_s .or. ex_j) then
      write (err_u, '(a)') 'landyn_batch: resuming: '//int_text(table%n_have)//' of '//int_text(camp%n_cases)// &
        ' cases done ('//int_text(n_s)//' rows from '//summary//', '//int_text(n_j)//' from '//journal//')'
    else
      write (err_u, '(a)') 'landyn_batch: --resume: neither '//summary//' nor '//journal// &
        ' exists; starting the campaign'
    end if
    if (n_bad > 0) write (err_u, '(a)') 'landyn_batch: --resume: ignored '//int_text(n_bad)// &
      ' incomplete journal line(s) (cases in flight when the campaign stopped); they are run again'
    if (n_out > 0) write (err_u, '(a)') 'landyn_batch: --resume: ignored '//int_text(n_out)// &
      ' row(s) of cases beyond the '//int_text(camp%n_cases)//' cases of the deck'
  end subroutine resume_rows

  !> Put `rows` into the table: n_added counts the rows taken, n_out those of cases beyond the deck's.
  subroutine add_rows(table, rows, n_added, n_out)
    type(results_t), intent(inout) :: table       !! rows already done [-]
    type(case_row_t), intent(in) :: rows(:)       !! rows to add [-]
    integer, intent(inout) :: n_added             !! rows taken so far [-]
    integer, intent(inout) :: n_out               !! rows of cases beyond the deck's so far [-]
    logical :: added
    integer :: k
    do k = 1, size(rows)
      call results_add(table, rows(k), added)
      if (added) then
        n_added = n_added + 1
      else
        n_out = n_out + 1
      end if
    end do
  end subroutine add_rows

  !> Rank 0: hand out cases, run some itself, record every row.
  subroutine master_loop(camp, opts, nranks, table, meta, summary, ju, err_u, n_session, stopped, prof)
    type(campaign_t), intent(in) :: camp          !! campaign [-]
    type(batch_options_t), intent(in) :: opts     !! options [-]
    integer, intent(in) :: nranks                 !! ranks [-]
    type(results_t), intent(inout) :: table       !! rows [-]
    type(summary_meta_t), intent(in) :: meta      !! meta data [-]
    character(len=*), intent(in) :: summary       !! summary file [-]
    integer, intent(in) :: ju                     !! journal unit [-]
    integer, intent(in) :: err_u                  !! unit for progress [-]
    integer, intent(out) :: n_session             !! rows recorded in this run [-]
    logical, intent(out) :: stopped               !! stopped by --stop-after [-]
    real(wp), intent(inout) :: prof(n_prof)       !! time account of rank 0 (slots p_*) [s, -]
    type(master_t), asynchronous :: ms
    type(master_sink_t) :: sink
    logical :: flag
    integer :: id, k, w
    type(MPI_Status) :: status
    type(case_row_t) :: row
    real(wp) :: t, tm(3)

    call master_start(camp, opts, nranks, table, ms, prof)
    sink = master_sink_t(ju, err_u)
    do
      ! every row that has arrived
      do
        call MPI_Iprobe(MPI_ANY_SOURCE, tag_row, MPI_COMM_WORLD, flag, status)
        if (.not. flag) exit
        call receive_row(camp, status, ms, sink, row, prof)
        if (.not. ms%stopped) call record_row(camp, opts, meta, summary, sink, row, status%MPI_SOURCE, table, ms, prof)
      end do
      call flush_journal(ms, sink, .true., prof)
      if (ms%master_works .and. .not. ms%stopped .and. ms%next <= size(ms%pend)) then
        id = ms%pend(ms%next)
        ms%next = ms%next + 1
        call run_case(camp, id, any(camp%save_histories == id), opts%command_line, row, tm)
        prof(p_input:p_after) = prof(p_input:p_after) + tm
        prof(p_cases) = prof(p_cases) + 1.0_wp
        prof(p_steps) = prof(p_steps) + real(row%n_steps, wp)
        call record_row(camp, opts, meta, summary, sink, row, 0, table, ms, prof)
      else
        if (.not. any(ms%active)) exit
        call wait_for_row(prof)
      end if
    end do
    call flush_journal(ms, sink, .true., prof)
    t = MPI_Wtime()
    do w = 1, ms%nw
      do k = 1, size(ms%id_req, 1)
        call MPI_Wait(ms%id_req(k, w), MPI_STATUS_IGNORE)
      end do
    end do
    prof(p_comm) = prof(p_comm) + (MPI_Wtime() - t)
    n_session = ms%n_session
    stopped = ms%stopped
  end subroutine master_loop

  !> Rank 0's start: the cases to run, the workers' depth, the clocks of journal flushes and
  !! checkpoints, and each worker's first ids (or its stop when there is nothing to run).
  subroutine master_start(camp, opts, nranks, table, ms, prof)
    type(campaign_t), intent(in) :: camp          !! campaign [-]
    type(batch_options_t), intent(in) :: opts     !! options [-]
    integer, intent(in) :: nranks                 !! ranks [-]
    type(results_t), intent(in) :: table          !! rows already done [-]
    type(master_t), intent(inout), asynchronous :: ms  !! rank 0's state, set up [-]
    real(wp), intent(inout) :: prof(n_prof)       !! time account of rank 0 (slots p_*) [s, -]
    integer :: w
    real(wp) :: t
    call results_missing(table, ms%pend)
    ms%next = 1
    ms%n_session = 0
    ms%stopped = .false.
    ms%journal_ok = .true.
    ms%n_unflushed = 0
    ms%t_flush = MPI_Wtime()
    ms%t_next_ckpt = MPI_Wtime() + camp%checkpoint_interval
    ms%every = max(1, camp%n_cases/100)
    if (camp%n_cases <= 200) ms%every = 1
    ms%nranks = nranks
    ms%nw = nranks - 1
    ms%master_works = nranks == 1 .or. (nranks <= master_works_max_ranks .and. .not. opts%dedicated_master)
    ms%depth = merge(depth_master_works, depth_dedicated, ms%master_works)
    allocate (ms%inflight(ms%nw), ms%active(ms%nw), ms%n_sent(ms%nw), ms%id_buf(ms%depth + 2, ms%nw), &
              ms%id_req(ms%depth + 2, ms%nw))
    ms%inflight = 0
    ms%active = .true.
    ms%n_sent = 0
    ms%id_buf = 0
    ms%id_req = MPI_REQUEST_NULL
    t = MPI_Wtime()
    do w = 1, ms%nw
      call top_up(ms, w)
    end do
    prof(p_comm) = prof(p_comm) + (MPI_Wtime() - t)
  end subroutine master_start

  !> Rank 0 waits for the next row without spinning: test, nap, test ...
  subroutine wait_for_row(prof)
    real(wp), intent(inout) :: prof(n_prof)       !! time account of rank 0 (slots p_*) [s, -]
    type(MPI_Status) :: status
    logical :: flag
    integer :: nap_us
    real(wp) :: t
    t = MPI_Wtime()
    nap_us = 1
    do
      call MPI_Iprobe(MPI_ANY_SOURCE, tag_row, MPI_COMM_WORLD, flag, status)
      if (flag) exit
      call nap(nap_us)
      nap_us = min(2*nap_us, max_nap_us)
    end do
    prof(p_wait) = prof(p_wait) + (MPI_Wtime() - t)
  end subroutine wait_for_row

  !> Receive the row that `status` announces and give its worker its next case (or its stop).
  !! The row is unpacked unless the campaign has stopped.
  subroutine receive_row(camp, status, ms, sink, row, prof)
    type(campaign_t), intent(in) :: camp          !! campaign [-]
    type(MPI_Status), intent(in) :: status        !! status of the probe that found the row [-]
    type(master_t), intent(inout), asynchronous :: ms  !! rank 0's state [-]
    type(master_sink_t), intent(in) :: sink       !! rank 0's units [-]
    type(case_row_t), intent(inout) :: row        !! the row received [-]
    real(wp), intent(inout) :: prof(n_prof)       !! time account of rank 0 (slots p_*) [s, -]
    integer :: st, n, w
    character(len=:), allocatable :: buf
    real(wp) :: t, c0, c1
    call cpu_time(c0)
    t = MPI_Wtime()
    w = status%MPI_SOURCE
    call MPI_Get_count(status, MPI_CHARACTER, n)
    allocate (character(len=n) :: buf)
    call MPI_Recv(buf, n, MPI_CHARACTER, w, tag_row, MPI_COMM_WORLD, MPI_STATUS_IGNORE)
    ms%inflight(w) = ms%inflight(w) - 1
    if (.not. ms%stopped) then
      call row_from_message(buf, camp%n_par, camp%n_gears, row, st)
      if (st /= 0) then
        write (sink%err_u, '(a,i0)') 'landyn_batch: internal error: malformed row from rank ', w
        call MPI_Abort(MPI_COMM_WORLD, 3)
      end if
    end if
    call top_up(ms, w)
    prof(p_comm) = prof(p_comm) + (MPI_Wtime() - t)
    call cpu_time(c1)
    prof(p_book_cpu) = prof(p_book_cpu) + (c1 - c0)
  end subroutine receive_row

  !> Give worker w cases until it holds its share: `depth` ids while many cases are left, then
  !! its part of what is left (at least two while rank 0 runs cases itself, so that the worker
  !! has work until rank 0 looks again; one with a dedicated rank 0). A worker left with none is
  !! sent its stop.
  subroutine top_up(ms, w)
    type(master_t), intent(inout), asynchronous :: ms  !! rank 0's state [-]
    integer, intent(in) :: w                      !! worker rank [-]
    integer :: target, left
    left = size(ms%pend) - ms%next + 1 + sum(ms%inflight)
    if (ms%master_works) then
      target = min(ms%depth, max(2, (left + ms%nranks - 1)/ms%nranks))
    else
      target = min(ms%depth, max(1, (left + ms%nw - 1)/ms%nw))
    end if
    do while (ms%inflight(w) < target .and. ms%next <= size(ms%pend) .and. .not. ms%stopped)
      call send_id(ms, ms%pend(ms%next), w)
      ms%next = ms%next + 1
      ms%inflight(w) = ms%inflight(w) + 1
    end do
    if (ms%inflight(w) == 0) then
      call send_id(ms, 0, w)
      ms%active(w) = .false.
    end if
  end subroutine top_up

  !> Send a case id (0: stop) to worker w without blocking. The worker holds at most `depth`
  !! ids, so a buffer slot is reused only after its send has been matched.
  subroutine send_id(ms, id, w)
    type(master_t), intent(inout), asynchronous :: ms  !! rank 0's state: the worker's send buffers [-]
    integer, intent(in) :: id                     !! case id, 0 to stop [-]
    integer, intent(in) :: w                      !! worker rank [-]
    integer :: slot
    slot = mod(ms%n_sent(w), size(ms%id_buf, 1)) + 1
    call MPI_Wait(ms%id_req(slot, w), MPI_STATUS_IGNORE)
    ms%id_buf(slot, w) = id
    call MPI_Isend(ms%id_buf(slot, w), 1, MPI_INTEGER, w, tag_work, MPI_COMM_WORLD, ms%id_req(slot, w))
    ms%n_sent(w) = ms%n_sent(w) + 1
  end subroutine send_id

  !> Flush the journal when lines are waiting (always when `now`, else after flush_interval).
  subroutine flush_journal(ms, sink, now, prof)
    type(master_t), intent(inout), asynchronous :: ms  !! rank 0's state: the journal's flush state [-]
    type(master_sink_t), intent(in) :: sink       !! rank 0's units [-]
    logical, intent(in) :: now                    !! flush whatever the time [-]
    real(wp), intent(inout) :: prof(n_prof)       !! time account of rank 0 (slots p_*) [s, -]
    type(status_t) :: st
    real(wp) :: t
    if (ms%n_unflushed == 0) return
    t = MPI_Wtime()
    if (.not. now .and. t - ms%t_flush < flush_interval) return
    call journal_flush(sink%ju, st)
    call journal_problem(ms, sink, st)
    ms%n_unflushed = 0
    ms%t_flush = MPI_Wtime()
    prof(p_record) = prof(p_record) + (ms%t_flush - t)
  end subroutine flush_journal

  !> Report the first journal operation that failed (the rows are then kept in memory only).
  subroutine journal_problem(ms, sink, st)
    type(master_t), intent(inout), asynchronous :: ms  !! rank 0's state: journal_ok [-]
    type(master_sink_t), intent(in) :: sink       !! rank 0's units [-]
    type(status_t), intent(in) :: st              !! status of the journal operation, with its message [-]
    if (.not. st%ok() .and. ms%journal_ok) then
      write (sink%err_u, '(a)') 'landyn_batch: warning: '//st%text()// &
        ' (rows are kept in memory and written at the end)'
      ms%journal_ok = .false.
    end if
  end subroutine journal_problem

  !> Keep a finished row: table, journal, progress line, checkpoint, --stop-after.
  subroutine record_row(camp, opts, meta, summary, sink, r, from, table, ms, prof)
    type(campaign_t), intent(in) :: camp          !! campaign [-]
    type(batch_options_t), intent(in) :: opts     !! options [-]
    type(summary_meta_t), intent(in) :: meta      !! meta data [-]
    character(len=*), intent(in) :: summary       !! summary file [-]
    type(master_sink_t), intent(in) :: sink       !! rank 0's units [-]
    type(case_row_t), intent(in) :: r             !! row [-]
    integer, intent(in) :: from                   !! rank that ran it [-]
    type(results_t), intent(inout) :: table       !! rows [-]
    type(master_t), intent(inout), asynchronous :: ms  !! rank 0's state [-]
    real(wp), intent(inout) :: prof(n_prof)       !! time account of rank 0 (slots p_*) [s, -]
    type(status_t) :: st
    real(wp) :: t, t2, c0, c1
    call cpu_time(c0)
    t = MPI_Wtime()
    call results_add(table, r)
    call journal_append(sink%ju, r, st, flush_now=.false.)
    call journal_problem(ms, sink, st)
    ms%n_unflushed = ms%n_unflushed + 1
    ms%n_session = ms%n_session + 1
    prof(p_rows) = prof(p_rows) + 1.0_wp
    if (.not. opts%quiet .and. (mod(ms%n_session, ms%every) == 0 .or. r%status /= status_ok .or. &
                                ms%next > size(ms%pend))) then
      write (sink%err_u, '(a)', advance='no') 'landyn_batch: ['//int_text(table%n_have)//'/'// &
        int_text(camp%n_cases)//', rank '//int_text(from)//'] '
      call report_row(r, camp%n_cases, sink%err_u)
    end if
    call flush_journal(ms, sink, .false., prof)
    t2 = MPI_Wtime()
    prof(p_record) = prof(p_record) + (t2 - t)
    call cpu_time(c1)
    prof(p_book_cpu) = prof(p_book_cpu) + (c1 - c0)
    if (t2 >= ms%t_next_ckpt .and. table%n_have < table%n_cases) then
      call flush_journal(ms, sink, .true., prof)
      call checkpoint(camp, opts, meta, summary, sink, table, ms, prof)
    end if
    if (opts%stop_after > 0 .and. ms%n_session >= opts%stop_after) ms%stopped = .true.
  end subroutine record_row

  !> Rewrite the summary file with the rows so far and set the time of the next checkpoint: after
  !! checkpoint_interval, but at least ckpt_cost_factor times this rewrite's duration later.
  subroutine checkpoint(camp, opts, meta, summary, sink, table, ms, prof)
    type(campaign_t), intent(in) :: camp          !! campaign [-]
    type(batch_options_t), intent(in) :: opts     !! options [-]
    type(summary_meta_t), intent(in) :: meta      !! meta data [-]
    character(len=*), intent(in) :: summary       !! summary file [-]
    type(master_sink_t), intent(in) :: sink       !! rank 0's units [-]
    type(results_t), intent(in) :: table          !! rows [-]
    type(master_t), intent(inout), asynchronous :: ms  !! rank 0's state: t_next_ckpt [-]
    real(wp), intent(inout) :: prof(n_prof)       !! time account of rank 0 (slots p_*) [s, -]
    type(status_t) :: st
    real(wp) :: t, t2
    t = MPI_Wtime()
    call write_summary(summary, meta, results_rows(table), opts%command_line, st)
    if (.not. st%ok()) write (sink%err_u, '(a)') 'landyn_batch: warning: checkpoint not written: '//st%text()
    t2 = MPI_Wtime()
    prof(p_ckpt) = prof(p_ckpt) + (t2 - t)
    prof(p_nckpt) = prof(p_nckpt) + 1.0_wp
    prof(p_ckpt_max) = max(prof(p_ckpt_max), t2 - t)
    if (camp%checkpoint_interval > 0.0_wp) then
      ms%t_next_ckpt = t2 + max(camp%checkpoint_interval, ckpt_cost_factor*(t2 - t))
    else
      ms%t_next_ckpt = t2   ! checkpoint_interval = 0: after every case, as asked
    end if
  end subroutine checkpoint

  !> A row as one message: the bit patterns of its integer and real parts (pack_row), then its
  !! text part.
  function row_message(row) result(buf)
    type(case_row_t), intent(in) :: row    !! row [-]
    character(len=:), allocatable :: buf   !! message [bytes]
    integer :: ibuf(row_int_count)
    real(wp), allocatable :: rbuf(:)
    character(len=:), allocatable :: text
    call pack_row(row, ibuf, rbuf, text)
    buf = transfer(ibuf, repeat(' ', size(ibuf)*storage_size(ibuf)/8))// &
          transfer(rbuf, repeat(' ', size(rbuf)*storage_size(rbuf)/8))//text
  end function row_message

  !> The row of a message made by row_message. stat = 1 when the message does not fit.
  subroutine row_from_message(buf, n_par, n_gears, row, stat)
    character(len=*), intent(in) :: buf     !! message [bytes]
    integer, intent(in) :: n_par            !! varied inputs [-]
    integer, intent(in) :: n_gears          !! gears [-]
    type(case_row_t), intent(out) :: row    !! row [-]
    integer, intent(out) :: stat            !! 0 ok, 1 malformed [-]
    integer :: ibuf(row_int_count), ni, nr
    real(wp) :: rbuf(row_real_count(n_par, n_gears))
    stat = STAT_FAILED
    ni = size(ibuf)*storage_size(ibuf)/8
    nr = size(rbuf)*storage_size(rbuf)/8
    if (len(buf) < ni + nr) return
    ibuf = transfer(buf(1:ni), ibuf)
    rbuf = transfer(buf(ni + 1:ni + nr), rbuf)
    call unpack_row(ibuf, rbuf, buf(ni + nr + 1:), n_par, n_gears, row, stat)
  end subroutine row_from_message

  !> Worker: run the cases rank 0 sends until it sends 0.
  subroutine worker_loop(camp, command_line, prof)
    type(campaign_t), intent(in) :: camp          !! campaign [-]
    character(len=*), intent(in) :: command_line  !! for history files [-]
    real(wp), intent(inout) :: prof(n_prof)       !! time account of this rank (slots p_*) [s, -]
    integer, asynchronous :: id
    integer :: nap_us, n_rows, slot
    type(row_buffer_t), asynchronous :: buf(row_slots)
    type(case_row_t) :: row
    type(MPI_Status) :: status
    type(MPI_Request) :: req, send_req(row_slots)
    logical :: done
    real(wp) :: t, tm(3)
    send_req = MPI_REQUEST_NULL
    n_rows = 0
    do
      ! the next id (usually there already); wait for it without spinning
      t = MPI_Wtime()
      call MPI_Irecv(id, 1, MPI_INTEGER, 0, tag_work, MPI_COMM_WORLD, req)
      nap_us = 1
      do
        call MPI_Test(req, done, status)
        if (done) exit
        call nap(nap_us)
        nap_us = min(2*nap_us, max_nap_us)
      end do
      prof(p_wait) = prof(p_wait) + (MPI_Wtime() - t)
      if (id <= 0) exit
      call run_case(camp, id, any(camp%save_histories == id), command_line, row, tm)
      prof(p_input:p_after) = prof(p_input:p_after) + tm
      prof(p_cases) = prof(p_cases) + 1.0_wp
      prof(p_steps) = prof(p_steps) + real(row%n_steps, wp)
      t = MPI_Wtime()
      ! a slot's previous row was received by rank 0 before this id was sent (a worker holds
      ! at most depth < row_slots ids), so the wait returns at once
      slot = mod(n_rows, row_slots) + 1
      call MPI_Wait(send_req(slot), MPI_STATUS_IGNORE)
      buf(slot)%b = row_message(row)
      call MPI_Isend(buf(slot)%b, len(buf(slot)%b), MPI_CHARACTER, 0, tag_row, MPI_COMM_WORLD, send_req(slot))
      n_rows = n_rows + 1
      prof(p_comm) = prof(p_comm) + (MPI_Wtime() - t)
    end do
    do slot = 1, row_slots
      call MPI_Wait(send_req(slot), MPI_STATUS_IGNORE)
    end do
  end subroutine worker_loop

  !> Sleep for `us` microseconds (a waiting rank between two tests for its message).
  subroutine nap(us)
    integer, intent(in) :: us   !! duration [us]
    type(timespec_t) :: req, rem
    integer(c_int) :: r
    req%sec = 0_c_long
    req%nsec = int(us, c_long)*1000_c_long
    r = c_nanosleep(req, rem)
  end subroutine nap

  !> The time accounts of all ranks, before the result lines: where the ranks' time went, and
  !! the per-case overhead outside run_simulation (docs/campaign.md, "Scaling").
  subroutine report_profile(pa, u)
    real(wp), intent(in) :: pa(:, :)   !! (n_prof, ranks) time accounts [s, -]
    integer, intent(in) :: u           !! unit [-]
    real(wp) :: tot, sim_frac(size(pa, 2)), cases, per_case_out, per_case_sim, steps
    character(len=:), allocatable :: s
    integer :: nr
    nr = size(pa, 2)
    tot = max(sum(pa(p_loop, :)), tiny(1.0_wp))
    sim_frac = pa(p_sim, :)/max(pa(p_loop, :), tiny(1.0_wp))
    cases = max(sum(pa(p_cases, :)), 1.0_wp)
    steps = sum(pa(p_steps, :))
    per_case_sim = sum(pa(p_sim, :))/cases
    per_case_out = sum(pa(p_input, :) + pa(p_after, :))/cases
    s = '  rank time: simulating '//pct(sum(pa(p_sim, :))/tot)//' (rank 0 '//pct(sim_frac(1))
    if (nr > 1) s = s//', other ranks '//pct(sum(pa(p_sim, 2:))/max(sum(pa(p_loop, 2:)), tiny(1.0_wp)))// &
                    ', lowest '//pct(minval(sim_frac(2:)))
    s = s//'), case input '//pct(sum(pa(p_input, :))/tot)//', metrics '//pct(sum(pa(p_after, :))/tot)// &
        ', waiting '//pct(sum(pa(p_wait, :))/tot)//', messages '//pct(sum(pa(p_comm, :))/tot)// &
        ', journal '//pct(sum(pa(p_record, :))/tot)//', checkpoints '//pct(sum(pa(p_ckpt, :))/tot)
    write (u, '(a)') s
    s = '  per case: run_simulation '//real_text_short(per_case_sim)//' s ('// &
        int_text(nint(steps/cases))//' steps); outside it '//int_text(nint(1.0e6_wp*per_case_out))//' us = '// &
        pct(per_case_out/max(per_case_sim, tiny(1.0_wp)))//' of it (input '// &
        int_text(nint(1.0e6_wp*sum(pa(p_input, :))/cases))//' us, metrics '// &
        int_text(nint(1.0e6_wp*sum(pa(p_after, :))/cases))//' us); rank 0 per row '// &
        int_text(nint(1.0e6_wp*(pa(p_comm, 1) + pa(p_record, 1))/max(pa(p_rows, 1), 1.0_wp)))//' us; '// &
        int_text(nint(pa(p_nckpt, 1)))//' checkpoint(s), longest '//real_text_short(pa(p_ckpt_max, 1))//' s'
    write (u, '(a)') s
    write (u, '(a)') '  time account [s] (rank 0 | all ranks): '//acct(pa(:, 1))//' | '//acct(sum(pa, dim=2))

  contains

    !> A fraction as a percentage text.
    function pct(x) result(t)
      real(wp), intent(in) :: x            !! fraction [-]
      character(len=:), allocatable :: t  !! percentage text [-]
      character(len=16) :: b
      write (b, '(f9.2)') 100.0_wp*x
      t = trim(adjustl(b))//' %'
    end function pct

    !> One time account as text.
    function acct(p) result(t)
      real(wp), intent(in) :: p(n_prof)    !! one account [s, -]
      character(len=:), allocatable :: t  !! text [-]
      t = 'loop='//g(p(p_loop))//' input='//g(p(p_input))//' sim='//g(p(p_sim))//' after='//g(p(p_after))// &
          ' wait='//g(p(p_wait))//' comm='//g(p(p_comm))//' record='//g(p(p_record))//' ckpt='//g(p(p_ckpt))// &
          ' cases='//int_text(nint(p(p_cases)))//' steps='//int_text(nint(p(p_steps)))//' rows='// &
          int_text(nint(p(p_rows)))//' book_cpu='//g(p(p_book_cpu))
    end function acct

    !> A time as text.
    function g(x) result(t)
      real(wp), intent(in) :: x            !! time [s]
      character(len=:), allocatable :: t  !! text [-]
      character(len=24) :: b
      write (b, '(es12.5)') x
      t = trim(adjustl(b))
    end function g

  end subroutine report_profile

  !> Broadcast a string from rank 0.
  subroutine bcast_text(text, rank)
    character(len=:), allocatable, intent(inout) :: text  !! string (set on rank 0) [-]
    integer, intent(in) :: rank                           !! this rank [-]
    integer :: n
    n = 0
    if (rank == 0) n = len(text)
    call MPI_Bcast(n, 1, MPI_INTEGER, 0, MPI_COMM_WORLD)
    if (rank /= 0) then
      if (allocated(text)) deallocate (text)
      allocate (character(len=n) :: text)
    end if
    if (n > 0) call MPI_Bcast(text, n, MPI_CHARACTER, 0, MPI_COMM_WORLD)
  end subroutine bcast_text

end module landyn_campaign_parallel
