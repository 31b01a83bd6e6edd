!> MPI execution of a campaign (mpi_f08).
!!
!! Rank 0 reads and checks the campaign deck, prepares the summary file (or resumes it), sends
!! the deck texts to the other ranks and hands out case ids dynamically: each worker holds up
!! to `depth` ids (so that it never waits for rank 0) and gets the next id when it returns a
!! row. Rank 0 also runs cases itself when the world is small (at most 16 ranks, unless
!! --dedicated-master), checking for returned rows between its own cases. With one rank, rank 0
!! runs every case. A case that fails is a row with its status and message; the campaign goes on.
!!
!! Rank 0 appends every row to the journal at once (flushed) and rewrites the summary file every
!! checkpoint_interval seconds and at the end (landyn_campaign_store); at the end the journal
!! is deleted. Case inputs depend only on (seed, case id), never on the rank or the order.
!!
!! Messages (all on MPI_COMM_WORLD): rank 0 -> worker, tag_work: one integer, the case id
!! (0: stop). Worker -> rank 0: tag_row_i (integers), tag_row_r (reals), tag_row_t (text) of
!! one row, in that order.
!!
!! Library code: reports go to the units the caller passes; the result is an exit code.
module landyn_campaign_parallel
  use mpi_f08, only: MPI_Init, MPI_Finalize, MPI_Comm_rank, MPI_Comm_size, MPI_Bcast, MPI_Send, MPI_Recv, &
                     MPI_Probe, MPI_Iprobe, MPI_Abort, MPI_Wtime, MPI_Status, MPI_COMM_WORLD, MPI_INTEGER, &
                     MPI_DOUBLE_PRECISION, MPI_CHARACTER, MPI_ANY_SOURCE
  use landyn_kinds, only: wp, msg_len
  use landyn_input, only: input_errors_t
  use landyn_h5, only: delete_file
  use landyn_campaign_nml, only: int_text, real_text_short
  use landyn_campaign_deck, only: campaign_t, build_campaign, use_summary_file
  use landyn_campaign_case, only: case_row_t, run_case, pack_row, unpack_row, row_int_count, row_real_count, &
                                  status_ok
  use landyn_campaign_store, only: summary_meta_t, meta_from_campaign, write_summary, read_summary, journal_open, &
                                   journal_append, journal_read, results_t, results_init, results_add, &
                                   results_rows, results_missing
  use landyn_campaign_tasks, only: exit_ok, exit_usage, exit_invalid, exit_write, exit_incomplete, load_or_report, &
                                   report_probability, report_row
  implicit none
  private

  public :: batch_options_t, run_campaign

  !> Options of a campaign run (from the command line).
  type :: batch_options_t
    logical :: resume = .false.                    !! continue from the summary file and journal [-]
    logical :: force = .false.                     !! overwrite an existing summary file [-]
    integer :: stop_after = 0                      !! stop (as if killed) after this many rows; 0: never [-]
    logical :: quiet = .false.                     !! no progress lines [-]
    logical :: dedicated_master = .false.          !! rank 0 only hands out cases [-]
    character(len=:), allocatable :: summary_file  !! summary file ('' : the deck's) [-]
    character(len=:), allocatable :: command_line  !! the command line, recorded in the files [-]
  end type batch_options_t

  integer, parameter :: tag_work = 11, tag_row_i = 12, tag_row_r = 13, tag_row_t = 14
  integer, parameter :: master_works_max_ranks = 16  !! rank 0 runs cases too up to this many ranks [-]

contains

  !> Run the campaign of `deck` on all ranks of MPI_COMM_WORLD (initialises and finalises MPI).
  !! `code` is the exit code on rank 0 and exit_ok on the other ranks.
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
    character(len=:), allocatable :: deck_name, deck_text, base_text, list_text, summary, journal
    integer :: rank, nranks, st, ju, n_session
    logical :: stopped
    real(wp) :: t0, t1

    call MPI_Init()
    call MPI_Comm_rank(MPI_COMM_WORLD, rank)
    call MPI_Comm_size(MPI_COMM_WORLD, nranks)
    code = exit_ok
    ju = -1
    if (rank == 0) then
      call load_or_report(deck, camp, err_u, code)
      if (code == exit_ok) then
        summary = opts%summary_file
        if (len(summary) == 0) summary = camp%summary_file
        journal = summary//'.journal'
        meta = meta_from_campaign(camp)
        call prepare_output(camp, meta, opts, summary, journal, table, ju, err_u, code)
      end if
    end if
    call MPI_Bcast(code, 1, MPI_INTEGER, 0, MPI_COMM_WORLD)
    if (code /= exit_ok) then
      call MPI_Finalize()
      if (rank /= 0) code = exit_ok
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
        call MPI_Abort(MPI_COMM_WORLD, exit_invalid)
      end if
    end if
    call use_summary_file(camp, opts%summary_file)   ! history files follow -o (issue 10)

    t0 = MPI_Wtime()
    if (rank == 0) then
      if (.not. opts%quiet) write (err_u, '(a)') 'landyn_batch: campaign '//deck//': '//trim(camp%mode)//', '// &
        int_text(camp%n_cases)//' cases ('//int_text(camp%n_cases - table%n_have)//' to run) on '// &
        int_text(nranks)//' rank(s) -> '//summary
      call master_loop(camp, opts, nranks, table, meta, summary, ju, err_u, n_session, stopped)
    else
      call worker_loop(camp, opts%command_line)
    end if
    t1 = MPI_Wtime()

    if (rank == 0) call finish(code)
    call MPI_Finalize()
    if (rank /= 0) code = exit_ok

  contains

    subroutine finish(code_)
      integer, intent(out) :: code_   !! exit code [-]
      type(case_row_t), allocatable :: rows(:)
      character(len=msg_len) :: msg
      integer :: st2
      code_ = exit_ok
      close (ju)
      if (stopped) then
        write (err_u, '(a)') 'landyn_batch: stopped after '//int_text(n_session)//' case(s) (--stop-after); '// &
          int_text(table%n_have)//' of '//int_text(camp%n_cases)//' cases are in '//journal// &
          '; continue with --resume'
        code_ = exit_incomplete
        return
      end if
      rows = results_rows(table)
      msg = ''
      call write_summary(summary, meta, rows, opts%command_line, st2, msg)
      if (st2 /= 0) then
        write (err_u, '(a)') 'landyn_batch: cannot write the summary file: '//trim(msg)
        write (err_u, '(a)') 'landyn_batch: the rows are kept in '//journal//'; fix the problem and run with --resume'
        code_ = exit_write
        return
      end if
      call delete_file(journal, st2, msg)
      write (out_u, '(a)') 'LANDYN campaign '//deck//' ('//trim(camp%mode)//'): '//int_text(size(rows))//' of '// &
        int_text(camp%n_cases)//' cases in '//summary
      call report_probability(rows, camp%crit%failed_runs, out_u)
      if (n_session > 0 .and. t1 > t0) write (out_u, '(a)') '  this run: '//int_text(n_session)//' cases in '// &
        real_text_short(t1 - t0)//' s on '//int_text(nranks)//' rank(s) = '// &
        int_text(nint(real(n_session, wp)*3600.0_wp/((t1 - t0)*real(nranks, wp))))//' cases per core-hour'
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
    code = exit_ok
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
        code = exit_usage
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
          code = exit_invalid
          return
        end if
        if (m%fingerprint /= camp%fingerprint) then
          write (err_u, '(a)') 'landyn_batch: --resume: '//summary//' belongs to another campaign (fingerprint '// &
            m%fingerprint//'; this deck: '//camp%fingerprint//'); give another summary_file or use --force'
          code = exit_invalid
          return
        end if
        do k = 1, size(rows)
          call results_add(table, rows(k), added)
          if (added) then
            n_s = n_s + 1
          else
            n_out = n_out + 1
          end if
        end do
      end if
      if (ex_j) then
        call journal_read(journal, meta, rows, n_bad, st, msg)
        if (st /= 0) then
          write (err_u, '(a)') 'landyn_batch: --resume: '//trim(msg)
          code = exit_invalid
          return
        end if
        do k = 1, size(rows)
          call results_add(table, rows(k), added)
          if (added) then
            n_j = n_j + 1
          else
            n_out = n_out + 1
          end if
        end do
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
      code = exit_write
    end if
  end subroutine prepare_output

  !> Rank 0: hand out cases, run some itself, record every row.
  subroutine master_loop(camp, opts, nranks, table, meta, summary, ju, err_u, n_session, stopped)
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
    integer, allocatable :: pend(:), inflight(:)
    logical, allocatable :: active(:)
    logical :: master_works, flag, journal_ok
    integer :: nw, w, depth, next, id, every
    type(MPI_Status) :: status
    type(case_row_t) :: row
    real(wp) :: t_ckpt

    call results_missing(table, pend)
    next = 1
    n_session = 0
    stopped = .false.
    journal_ok = .true.
    t_ckpt = MPI_Wtime()
    every = max(1, camp%n_cases/100)
    if (camp%n_cases <= 200) every = 1
    nw = nranks - 1
    master_works = nranks == 1 .or. (nranks <= master_works_max_ranks .and. .not. opts%dedicated_master)
    depth = merge(3, 2, master_works)
    allocate (inflight(nw), active(nw))
    inflight = 0
    active = .true.
    do w = 1, nw
      call top_up(w)
      if (inflight(w) == 0) then
        call send_id(0, w)
        active(w) = .false.
      end if
    end do

    do
      if (master_works .and. .not. stopped .and. next <= size(pend)) then
        do
          call MPI_Iprobe(MPI_ANY_SOURCE, tag_row_i, MPI_COMM_WORLD, flag, status)
          if (.not. flag) exit
          call handle(status%MPI_SOURCE)
        end do
        if (stopped .or. next > size(pend)) cycle
        id = pend(next)
        next = next + 1
        call run_case(camp, id, any(camp%save_histories == id), opts%command_line, row)
        call record(row, 0)
      else
        if (.not. any(active)) exit
        call MPI_Probe(MPI_ANY_SOURCE, tag_row_i, MPI_COMM_WORLD, status)
        call handle(status%MPI_SOURCE)
      end if
    end do

  contains

    !> Receive a row from worker w and give it its next case.
    subroutine handle(w_)
      integer, intent(in) :: w_    !! worker rank [-]
      integer :: ibuf(row_int_count), st
      real(wp) :: rbuf(row_real_count(camp%n_par, camp%n_gears))
      character(len=:), allocatable :: text
      type(MPI_Status) :: stat_
      call MPI_Recv(ibuf, row_int_count, MPI_INTEGER, w_, tag_row_i, MPI_COMM_WORLD, stat_)
      call MPI_Recv(rbuf, size(rbuf), MPI_DOUBLE_PRECISION, w_, tag_row_r, MPI_COMM_WORLD, stat_)
      allocate (character(len=max(0, sum(ibuf(9:11)))) :: text)
      call MPI_Recv(text, len(text), MPI_CHARACTER, w_, tag_row_t, MPI_COMM_WORLD, stat_)
      inflight(w_) = inflight(w_) - 1
      if (.not. stopped) then
        call unpack_row(ibuf, rbuf, text, camp%n_par, camp%n_gears, row, st)
        if (st /= 0) then
          write (err_u, '(a,i0)') 'landyn_batch: internal error: malformed row from rank ', w_
          call MPI_Abort(MPI_COMM_WORLD, 3)
        end if
        call record(row, w_)
      end if
      call top_up(w_)
      if (inflight(w_) == 0) then
        call send_id(0, w_)
        active(w_) = .false.
      end if
    end subroutine handle

    !> Give worker w_ cases until it holds `depth` of them (one at a time near the end, so that
    !! the last cases spread over all ranks).
    subroutine top_up(w_)
      integer, intent(in) :: w_    !! worker rank [-]
      integer :: target
      target = 1
      if (size(pend) - next + 1 >= depth*nranks) target = depth
      do while (inflight(w_) < target .and. next <= size(pend) .and. .not. stopped)
        call send_id(pend(next), w_)
        next = next + 1
        inflight(w_) = inflight(w_) + 1
      end do
    end subroutine top_up

    !> Keep a finished row: table, journal, progress, checkpoint, --stop-after.
    subroutine record(r, from)
      type(case_row_t), intent(in) :: r   !! row [-]
      integer, intent(in) :: from         !! rank that ran it [-]
      character(len=msg_len) :: msg
      integer :: st
      call results_add(table, r)
      msg = ''
      call journal_append(ju, r, st, msg)
      if (st /= 0 .and. journal_ok) then
        write (err_u, '(a)') 'landyn_batch: warning: '//trim(msg)//' (rows are kept in memory and written at the end)'
        journal_ok = .false.
      end if
      n_session = n_session + 1
      if (.not. opts%quiet .and. (mod(n_session, every) == 0 .or. r%status /= status_ok .or. &
                                  next > size(pend))) then
        write (err_u, '(a)', advance='no') 'landyn_batch: ['//int_text(table%n_have)//'/'//int_text(camp%n_cases)// &
          ', rank '//int_text(from)//'] '
        call report_row(r, camp%n_cases, err_u)
      end if
      if (MPI_Wtime() - t_ckpt >= camp%checkpoint_interval .and. table%n_have < table%n_cases) then
        msg = ''
        call write_summary(summary, meta, results_rows(table), opts%command_line, st, msg)
        if (st /= 0) write (err_u, '(a)') 'landyn_batch: warning: checkpoint not written: '//trim(msg)
        t_ckpt = MPI_Wtime()
      end if
      if (opts%stop_after > 0 .and. n_session >= opts%stop_after) stopped = .true.
    end subroutine record

  end subroutine master_loop

  !> Send a case id (0: stop) to a worker.
  subroutine send_id(id, w)
    integer, intent(in) :: id   !! case id, 0 to stop [-]
    integer, intent(in) :: w    !! worker rank [-]
    call MPI_Send(id, 1, MPI_INTEGER, w, tag_work, MPI_COMM_WORLD)
  end subroutine send_id

  !> Worker: run the cases rank 0 sends until it sends 0.
  subroutine worker_loop(camp, command_line)
    type(campaign_t), intent(in) :: camp          !! campaign [-]
    character(len=*), intent(in) :: command_line  !! for history files [-]
    integer :: id, ibuf(row_int_count)
    real(wp), allocatable :: rbuf(:)
    character(len=:), allocatable :: text
    type(case_row_t) :: row
    type(MPI_Status) :: status
    do
      call MPI_Recv(id, 1, MPI_INTEGER, 0, tag_work, MPI_COMM_WORLD, status)
      if (id <= 0) exit
      call run_case(camp, id, any(camp%save_histories == id), command_line, row)
      call pack_row(row, ibuf, rbuf, text)
      call MPI_Send(ibuf, row_int_count, MPI_INTEGER, 0, tag_row_i, MPI_COMM_WORLD)
      call MPI_Send(rbuf, size(rbuf), MPI_DOUBLE_PRECISION, 0, tag_row_r, MPI_COMM_WORLD)
      call MPI_Send(text, len(text), MPI_CHARACTER, 0, tag_row_t, MPI_COMM_WORLD)
    end do
  end subroutine worker_loop

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
