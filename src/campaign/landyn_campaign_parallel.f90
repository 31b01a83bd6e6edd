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
  use landyn_kinds, only: wp, msg_len
  use landyn_input, only: input_errors_t
  use landyn_h5, only: delete_file
  use landyn_campaign_nml, only: int_text, real_text_short
  use landyn_campaign_deck, only: campaign_t, build_campaign, use_summary_file
  use landyn_campaign_case, only: case_row_t, run_case, pack_row, unpack_row, row_int_count, row_real_count, &
                                  status_ok
  use landyn_campaign_store, only: summary_meta_t, meta_from_campaign, write_summary, read_summary, results_t, &
                                   results_init, results_add, results_rows, results_missing, &
                                   results_take_rows
  use landyn_campaign_journal, only: journal_open, journal_append, journal_flush, journal_read
  use landyn_files, only: lock_file, unlock_file
  use landyn_status, only: STAT_OK, STAT_FAILED, EXIT_OK, EXIT_USAGE, EXIT_INPUT, EXIT_FILE, EXIT_INCOMPLETE
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
    type(input_errors_t) :: errors
    type(results_t) :: table
    type(summary_meta_t) :: meta
    character(len=:), allocatable :: deck_name, deck_text, base_text, list_text, summary, journal, lock_why
    integer :: rank, nranks, st, ju, n_session, lock
    logical :: stopped
    real(wp) :: t0, t1
    real(wp) :: prof(n_prof)
    real(wp), allocatable :: prof_all(:, :)

    call MPI_Init()
    call MPI_Comm_rank(MPI_COMM_WORLD, rank)
    call MPI_Comm_size(MPI_COMM_WORLD, nranks)
    code = EXIT_OK
    ju = -1
    lock = -1
    if (rank == 0) then
      call load_or_report(deck, camp, err_u, code)
      if (code == EXIT_OK) then
        summary = opts%summary_file
        if (len(summary) == 0) summary = camp%summary_file
        journal = summary//'.journal'
        meta = meta_from_campaign(camp)
        ! one process per campaign: two resumes of one journal would both append to it and
        ! both write the summary file (the kernel releases the lock when the process ends)
        call lock_file(summary//'.lock', lock, st, lock_why)
        if (st /= STAT_OK) then
          write (err_u, '(a)') 'landyn_batch: the campaign of '//summary//' is in use: '//summary//'.lock: '// &
            lock_why//'; wait for that run to end (a killed run leaves no lock held)'
          code = EXIT_FILE
        else
          call prepare_output(camp, meta, opts, summary, journal, table, ju, err_u, code)
          if (code /= EXIT_OK) call unlock_file(summary//'.lock', lock)
        end if
      end if
    end if
    call MPI_Bcast(code, 1, MPI_INTEGER, 0, MPI_COMM_WORLD)
    if (code /= EXIT_OK) then
      call MPI_Finalize()
      if (rank /= 0) code = EXIT_OK
      return
    end if

    ! ---- every rank builds the same campaign from rank 0's texts
    if (rank == 0) then
      deck_name = camp%deck_name
      deck_text = camp%deck_text
      base_text = camp%base_text
      list_text = camp%list_text
    end if
    call bcast_text(deck_name, rank)
    call bcast_text(deck_text, rank)
    call bcast_text(base_text, rank)
    call bcast_text(list_text, rank)
    if (rank /= 0) then
      call build_campaign(deck_name, deck_text, base_text, list_text, camp, errors, st)
      if (st /= 0) then
        write (err_u, '(a,i0,a)') 'landyn_batch: rank ', rank, ': the campaign read on rank 0 does not build here: '// &
          errors%message(1)
        call MPI_Abort(MPI_COMM_WORLD, EXIT_INPUT)
      end if
    end if
    call use_summary_file(camp, opts%summary_file)   ! history files follow -o (issue 10)

    prof = 0.0_wp
    t0 = MPI_Wtime()
    if (rank == 0) then
      if (.not. opts%quiet) write (err_u, '(a)') 'landyn_batch: campaign '//deck//': '//trim(camp%mode)//', '// &
        int_text(camp%n_cases)//' cases ('//int_text(camp%n_cases - table%n_have)//' to run) on '// &
        int_text(nranks)//' rank(s) -> '//summary
      call master_loop(camp, opts, nranks, table, meta, summary, ju, err_u, n_session, stopped, prof)
    else
      call worker_loop(camp, opts%command_line, prof)
    end if
    t1 = MPI_Wtime()
    prof(p_loop) = t1 - t0
    allocate (prof_all(n_prof, merge(nranks, 1, rank == 0)))
    call MPI_Gather(prof, n_prof, MPI_DOUBLE_PRECISION, prof_all, n_prof, MPI_DOUBLE_PRECISION, 0, MPI_COMM_WORLD)

    if (rank == 0) then
      call finish(code)
      call unlock_file(summary//'.lock', lock)
    end if
    call MPI_Finalize()
    if (rank /= 0) code = EXIT_OK

  contains

    !> Write the final summary file, delete the journal and report the campaign.
    subroutine finish(code_)
      integer, intent(out) :: code_   !! exit code [-]
      type(case_row_t), allocatable :: rows(:)
      character(len=msg_len) :: msg
      integer :: st2
      code_ = EXIT_OK
      close (ju)
      if (stopped) then
        write (err_u, '(a)') 'landyn_batch: stopped after '//int_text(n_session)//' case(s) (--stop-after); '// &
          int_text(table%n_have)//' of '//int_text(camp%n_cases)//' cases are in '//journal// &
          '; continue with --resume'
        code_ = EXIT_INCOMPLETE
        return
      end if
      call results_take_rows(table, rows)
      msg = ''
      call write_summary(summary, meta, rows, opts%command_line, st2, msg)
      if (st2 /= 0) then
        write (err_u, '(a)') 'landyn_batch: cannot write the summary file: '//trim(msg)
        write (err_u, '(a)') 'landyn_batch: the rows are kept in '//journal//'; fix the problem and run with --resume'
        code_ = EXIT_FILE
        return
      end if
      call delete_file(journal, st2, msg)
      ! speed and (--verbose) the time account are diagnostics: on the message unit, before the
      ! result on out_u, whose final line counts the failures per criterion
      if (n_session > 0 .and. t1 > t0 .and. (opts%verbose .or. .not. opts%quiet)) write (err_u, '(a)') &
        'landyn_batch: this run: '//int_text(n_session)//' cases in '//real_text_short(t1 - t0)//' s on '// &
        int_text(nranks)//' rank(s) = '//int_text(nint(real(n_session, wp)*3600.0_wp/((t1 - t0)*real(nranks, wp))))// &
        ' cases per core-hour'
      if (n_session > 0 .and. opts%verbose) call report_profile(prof_all, err_u)
      write (out_u, '(a)') 'LANDYN campaign '//deck//' ('//trim(camp%mode)//'): '//int_text(size(rows))//' of '// &
        int_text(camp%n_cases)//' cases in '//summary
      call report_probability(rows, camp%crit%failed_runs, out_u)
    end subroutine finish

  end subroutine run_campaign

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
    type(summary_meta_t) :: m
    type(case_row_t), allocatable :: rows(:)
    character(len=msg_len) :: msg
    logical :: ex_s, ex_j, added
    integer :: st, k, n_s, n_j, n_bad, n_out
    code = EXIT_OK
    ju = -1
    call results_init(table, camp%n_cases)
    inquire (file=summary, exist=ex_s)
    inquire (file=journal, exist=ex_j)
    msg = ''
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
      call delete_file(summary, st, msg)
      call delete_file(journal, st, msg)
    else
      n_s = 0
      n_j = 0
      n_bad = 0
      n_out = 0
      if (ex_s) then
        call read_summary(summary, m, rows, st, msg)
        if (st /= 0) then
          write (err_u, '(a)') 'landyn_batch: --resume: '//trim(msg)
          code = EXIT_INPUT
          return
        end if
        if (m%fingerprint /= camp%fingerprint) then
          write (err_u, '(a)') 'landyn_batch: --resume: '//summary//' belongs to another campaign (fingerprint '// &
            m%fingerprint//'; this deck: '//camp%fingerprint//'); give another summary_file or use --force'
          code = EXIT_INPUT
          return
        end if
        call add_rows(n_s)
      end if
      if (ex_j) then
        call journal_read(journal, meta, rows, n_bad, st, msg)
        if (st /= 0) then
          write (err_u, '(a)') 'landyn_batch: --resume: '//trim(msg)
          code = EXIT_INPUT
          return
        end if
        call add_rows(n_j)
      end if
      if (.not. opts%quiet) then
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
      end if
    end if
    call journal_open(journal, meta, ju, st, msg)
    if (st /= 0) then
      write (err_u, '(a)') 'landyn_batch: '//trim(msg)
      code = EXIT_FILE
    end if

  contains

    !> Put `rows` into the table: n_added counts the rows taken, n_out those of cases beyond the deck's.
    subroutine add_rows(n_added)
      integer, intent(inout) :: n_added   !! rows taken so far [-]
      do k = 1, size(rows)
        call results_add(table, rows(k), added)
        if (added) then
          n_added = n_added + 1
        else
          n_out = n_out + 1
        end if
      end do
    end subroutine add_rows

  end subroutine prepare_output

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
    integer, allocatable :: pend(:), inflight(:), n_sent(:)
    integer, allocatable, asynchronous :: id_buf(:, :)
    type(MPI_Request), allocatable :: id_req(:, :)
    logical, allocatable :: active(:)
    logical :: master_works, flag, journal_ok
    integer :: nw, w, depth, next, id, every, n_unflushed, nap_us, k
    type(MPI_Status) :: status
    type(case_row_t) :: row
    real(wp) :: t_next_ckpt, t_flush, t, tm(3)

    call results_missing(table, pend)
    next = 1
    n_session = 0
    stopped = .false.
    journal_ok = .true.
    n_unflushed = 0
    t_flush = MPI_Wtime()
    t_next_ckpt = MPI_Wtime() + camp%checkpoint_interval
    every = max(1, camp%n_cases/100)
    if (camp%n_cases <= 200) every = 1
    nw = nranks - 1
    master_works = nranks == 1 .or. (nranks <= master_works_max_ranks .and. .not. opts%dedicated_master)
    depth = merge(depth_master_works, depth_dedicated, master_works)
    allocate (inflight(nw), active(nw), n_sent(nw), id_buf(depth + 2, nw), id_req(depth + 2, nw))
    inflight = 0
    active = .true.
    n_sent = 0
    id_buf = 0
    id_req = MPI_REQUEST_NULL
    t = MPI_Wtime()
    do w = 1, nw
      call top_up(w)
      if (inflight(w) == 0) then
        call send_id(0, w)
        active(w) = .false.
      end if
    end do
    prof(p_comm) = prof(p_comm) + (MPI_Wtime() - t)

    do
      ! every row that has arrived
      do
        call MPI_Iprobe(MPI_ANY_SOURCE, tag_row, MPI_COMM_WORLD, flag, status)
        if (.not. flag) exit
        call handle(status)
      end do
      call flush_journal(.true.)
      if (master_works .and. .not. stopped .and. next <= size(pend)) then
        id = pend(next)
        next = next + 1
        call run_case(camp, id, any(camp%save_histories == id), opts%command_line, row, tm)
        prof(p_input:p_after) = prof(p_input:p_after) + tm
        prof(p_cases) = prof(p_cases) + 1.0_wp
        prof(p_steps) = prof(p_steps) + real(row%n_steps, wp)
        call record(row, 0)
      else
        if (.not. any(active)) exit
        ! wait for the next row without spinning: test, nap, test ...
        t = MPI_Wtime()
        nap_us = 1
        do
          call MPI_Iprobe(MPI_ANY_SOURCE, tag_row, MPI_COMM_WORLD, flag, status)
          if (flag) exit
          call nap(nap_us)
          nap_us = min(2*nap_us, max_nap_us)
        end do
        prof(p_wait) = prof(p_wait) + (MPI_Wtime() - t)
      end if
    end do
    call flush_journal(.true.)
    t = MPI_Wtime()
    do w = 1, nw
      do k = 1, size(id_req, 1)
        call MPI_Wait(id_req(k, w), MPI_STATUS_IGNORE)
      end do
    end do
    prof(p_comm) = prof(p_comm) + (MPI_Wtime() - t)

  contains

    !> Receive the row that `st_` announces and give its worker its next case.
    subroutine handle(st_)
      type(MPI_Status), intent(in) :: st_    !! status of the probe that found the row [-]
      integer :: st, n, w_
      character(len=:), allocatable :: buf
      real(wp) :: t_, c0, c1
      call cpu_time(c0)
      t_ = MPI_Wtime()
      w_ = st_%MPI_SOURCE
      call MPI_Get_count(st_, MPI_CHARACTER, n)
      allocate (character(len=n) :: buf)
      call MPI_Recv(buf, n, MPI_CHARACTER, w_, tag_row, MPI_COMM_WORLD, MPI_STATUS_IGNORE)
      inflight(w_) = inflight(w_) - 1
      if (.not. stopped) then
        call row_from_message(buf, camp%n_par, camp%n_gears, row, st)
        if (st /= 0) then
          write (err_u, '(a,i0)') 'landyn_batch: internal error: malformed row from rank ', w_
          call MPI_Abort(MPI_COMM_WORLD, 3)
        end if
      end if
      call top_up(w_)
      if (inflight(w_) == 0) then
        call send_id(0, w_)
        active(w_) = .false.
      end if
      prof(p_comm) = prof(p_comm) + (MPI_Wtime() - t_)
      call cpu_time(c1)
      prof(p_book_cpu) = prof(p_book_cpu) + (c1 - c0)
      if (.not. stopped) call record(row, w_)
    end subroutine handle

    !> Give worker w_ cases until it holds its share: `depth` ids while many cases are left, then
    !! its part of what is left (at least two while rank 0 runs cases itself, so that the worker
    !! has work until rank 0 looks again; one with a dedicated rank 0).
    subroutine top_up(w_)
      integer, intent(in) :: w_    !! worker rank [-]
      integer :: target, left
      left = size(pend) - next + 1 + sum(inflight)
      if (master_works) then
        target = min(depth, max(2, (left + nranks - 1)/nranks))
      else
        target = min(depth, max(1, (left + nw - 1)/nw))
      end if
      do while (inflight(w_) < target .and. next <= size(pend) .and. .not. stopped)
        call send_id(pend(next), w_)
        next = next + 1
        inflight(w_) = inflight(w_) + 1
      end do
    end subroutine top_up

    !> Send a case id (0: stop) to worker w_ without blocking. The worker holds at most `depth`
    !! ids, so a buffer slot is reused only after its send has been matched.
    subroutine send_id(id_, w_)
      integer, intent(in) :: id_   !! case id, 0 to stop [-]
      integer, intent(in) :: w_    !! worker rank [-]
      integer :: slot
      slot = mod(n_sent(w_), size(id_buf, 1)) + 1
      call MPI_Wait(id_req(slot, w_), MPI_STATUS_IGNORE)
      id_buf(slot, w_) = id_
      call MPI_Isend(id_buf(slot, w_), 1, MPI_INTEGER, w_, tag_work, MPI_COMM_WORLD, id_req(slot, w_))
      n_sent(w_) = n_sent(w_) + 1
    end subroutine send_id

    !> Flush the journal when lines are waiting (always when `now`, else after flush_interval).
    subroutine flush_journal(now)
      logical, intent(in) :: now   !! flush whatever the time [-]
      character(len=msg_len) :: msg
      integer :: st
      real(wp) :: t_
      if (n_unflushed == 0) return
      t_ = MPI_Wtime()
      if (.not. now .and. t_ - t_flush < flush_interval) return
      msg = ''
      call journal_flush(ju, st, msg)
      call journal_problem(st, msg)
      n_unflushed = 0
      t_flush = MPI_Wtime()
      prof(p_record) = prof(p_record) + (t_flush - t_)
    end subroutine flush_journal

    !> Report a journal operation that failed.
    subroutine journal_problem(st, msg)
      integer, intent(in) :: st             !! status of the journal operation [-]
      character(len=*), intent(in) :: msg   !! its message [-]
      if (st /= 0 .and. journal_ok) then
        write (err_u, '(a)') 'landyn_batch: warning: '//trim(msg)//' (rows are kept in memory and written at the end)'
        journal_ok = .false.
      end if
    end subroutine journal_problem

    !> Keep a finished row: table, journal, progress, checkpoint, --stop-after.
    subroutine record(r, from)
      type(case_row_t), intent(in) :: r   !! row [-]
      integer, intent(in) :: from         !! rank that ran it [-]
      character(len=msg_len) :: msg
      integer :: st
      real(wp) :: t_, t2, c0, c1
      call cpu_time(c0)
      t_ = MPI_Wtime()
      call results_add(table, r)
      msg = ''
      call journal_append(ju, r, st, msg, flush_now=.false.)
      call journal_problem(st, msg)
      n_unflushed = n_unflushed + 1
      n_session = n_session + 1
      prof(p_rows) = prof(p_rows) + 1.0_wp
      if (.not. opts%quiet .and. (mod(n_session, every) == 0 .or. r%status /= status_ok .or. &
                                  next > size(pend))) then
        write (err_u, '(a)', advance='no') 'landyn_batch: ['//int_text(table%n_have)//'/'//int_text(camp%n_cases)// &
          ', rank '//int_text(from)//'] '
        call report_row(r, camp%n_cases, err_u)
      end if
      call flush_journal(.false.)
      t2 = MPI_Wtime()
      prof(p_record) = prof(p_record) + (t2 - t_)
      call cpu_time(c1)
      prof(p_book_cpu) = prof(p_book_cpu) + (c1 - c0)
      if (t2 >= t_next_ckpt .and. table%n_have < table%n_cases) then
        call flush_journal(.true.)
        t_ = MPI_Wtime()
        msg = ''
        call write_summary(summary, meta, results_rows(table), opts%command_line, st, msg)
        if (st /= 0) write (err_u, '(a)') 'landyn_batch: warning: checkpoint not written: '//trim(msg)
        t2 = MPI_Wtime()
        prof(p_ckpt) = prof(p_ckpt) + (t2 - t_)
        prof(p_nckpt) = prof(p_nckpt) + 1.0_wp
        prof(p_ckpt_max) = max(prof(p_ckpt_max), t2 - t_)
        if (camp%checkpoint_interval > 0.0_wp) then
          t_next_ckpt = t2 + max(camp%checkpoint_interval, ckpt_cost_factor*(t2 - t_))
        else
          t_next_ckpt = t2   ! checkpoint_interval = 0: after every case, as asked
        end if
      end if
      if (opts%stop_after > 0 .and. n_session >= opts%stop_after) stopped = .true.
    end subroutine record

  end subroutine master_loop

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
