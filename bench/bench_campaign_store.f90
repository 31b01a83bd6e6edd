!> Costs of rank 0's bookkeeping in a campaign (issue 12, item 2 and 3), on synthetic rows of
!! the shape of bench/campaign_mc.nml (8 varied inputs, 4 gears):
!!
!!   bench_campaign_store checkpoint N1[,N2,...]   time of a summary-file checkpoint (write_summary
!!                                                 of N rows, via .partial and a rename), of reading
!!                                                 it back (read_summary, --resume and --merge), and
!!                                                 of one journal line (journal_append, unflushed
!!                                                 and flushed), per N
!!   bench_campaign_store parts DIR NFILES ROWS    write NFILES summary files of ROWS rows each, the
!!                                                 parts of one campaign of NFILES*ROWS cases (input
!!                                                 of landyn_batch --merge DIR/part_*.h5)
!!
!! Prints one line per measurement; files go to the current directory (checkpoint) or DIR.
program bench_campaign_store
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, int64
  use landyn_kinds, only: wp
  use landyn_status, only: status_t
  use landyn_h5, only: delete_file
  use landyn_campaign_case, only: case_row_t, new_row, status_ok
  use landyn_campaign_store, only: summary_meta_t, write_summary, read_summary
  use landyn_campaign_journal, only: journal_open, journal_append, journal_flush
  implicit none

  integer, parameter :: n_par = 8, n_gears = 4
  character(len=4096) :: arg, dir
  type(status_t) :: ss
  type(summary_meta_t) :: meta
  type(case_row_t), allocatable :: rows(:), back(:)
  type(summary_meta_t) :: meta_back
  integer, allocatable :: counts(:)
  integer :: i, k, n, nfiles, nrows, ju, n_journal
  real(wp) :: t0, t1, t2, t3, t4, t_write, t_read

  if (command_argument_count() < 2) call usage()
  call get_command_argument(1, arg)
  select case (trim(arg))
  case ('checkpoint')
    call get_command_argument(2, arg)
    call parse_counts(trim(arg), counts)
    do i = 1, size(counts)
      n = counts(i)
      meta = synthetic_meta(n)
      rows = synthetic_rows(1, n)
      t0 = now()
      call write_summary('bench_checkpoint.h5', meta, rows, 'bench_campaign_store', ss)
      t1 = now()
      if (.not. ss%ok()) call fail(ss%text())
      call read_summary('bench_checkpoint.h5', meta_back, back, ss)
      t2 = now()
      if (.not. ss%ok()) call fail(ss%text())
      if (size(back) /= n) call fail('read_summary gave a different number of rows')
      t_write = t1 - t0
      t_read = t2 - t1
      deallocate (back)
      call delete_file('bench_checkpoint.h5')
      ! journal lines: unflushed (batched flushes) and flushed one by one
      n_journal = min(n, 20000)
      call delete_file('bench_checkpoint.journal')
      call journal_open('bench_checkpoint.journal', meta, ju, ss)
      if (.not. ss%ok()) call fail(ss%text())
      t2 = now()
      do k = 1, n_journal
        call journal_append(ju, rows(k), ss, flush_now=.false.)
      end do
      call journal_flush(ju, ss)
      t3 = now()
      do k = 1, n_journal
        call journal_append(ju, rows(k), ss)
      end do
      t4 = now()
      close (ju, status='delete')
      write (output_unit, '(a,i0,a,f10.4,a,f10.4,a,f8.2,a,f8.2,a)') 'checkpoint rows=', n, ' write_s=', t_write, &
        ' read_s=', t_read, ' journal_line_us=', 1.0e6_wp*(t3 - t2)/n_journal, &
        ' journal_line_flushed_us=', 1.0e6_wp*(t4 - t3)/n_journal, ''
      deallocate (rows)
    end do
  case ('parts')
    if (command_argument_count() < 4) call usage()
    call get_command_argument(2, dir)
    call get_command_argument(3, arg)
    read (arg, *) nfiles
    call get_command_argument(4, arg)
    read (arg, *) nrows
    meta = synthetic_meta(nfiles*nrows)
    t0 = now()
    do i = 1, nfiles
      rows = synthetic_rows((i - 1)*nrows + 1, nrows)
      write (arg, '(a,a,i6.6,a)') trim(dir), '/part_', i, '.h5'
      call write_summary(trim(arg), meta, rows, 'bench_campaign_store parts', ss)
      if (.not. ss%ok()) call fail(ss%text())
    end do
    t1 = now()
    write (output_unit, '(a,i0,a,i0,a,f10.3)') 'parts files=', nfiles, ' rows_each=', nrows, ' write_s=', t1 - t0
  case default
    call usage()
  end select

contains

  function now() result(t)
    real(wp) :: t                 !! wall-clock time [s]
    integer(int64) :: c, r
    call system_clock(c, r)
    t = real(c, wp)/real(r, wp)
  end function now

  subroutine usage()
    write (error_unit, '(a)') 'usage: bench_campaign_store checkpoint N1[,N2,...] | parts DIR NFILES ROWS'
    stop 1
  end subroutine usage

  subroutine fail(text)
    character(len=*), intent(in) :: text   !! what went wrong [-]
    write (error_unit, '(a)') 'bench_campaign_store: '//trim(text)
    stop 1
  end subroutine fail

  subroutine parse_counts(text, v)
    character(len=*), intent(in) :: text          !! comma-separated counts [-]
    integer, allocatable, intent(out) :: v(:)     !! counts [-]
    integer :: p, q, x
    allocate (v(0))
    p = 1
    do while (p <= len(text))
      q = index(text(p:), ',')
      if (q == 0) then
        q = len(text) + 1
      else
        q = p + q - 1
      end if
      read (text(p:q - 1), *) x
      v = [v, x]
      p = q + 1
    end do
  end subroutine parse_counts

  !> Meta data of a synthetic Monte Carlo campaign of n cases.
  function synthetic_meta(n) result(m)
    integer, intent(in) :: n          !! cases [-]
    type(summary_meta_t) :: m         !! meta data [-]
    integer :: j
    m%title = 'synthetic campaign (bench_campaign_store)'
    m%mode = 'monte_carlo'
    m%seed = '12'
    m%fingerprint = '0123456789abcdef'
    m%deck_name = 'synthetic.nml'
    m%deck_text = '&campaign /'
    m%base_name = 'base.nml'
    m%base_text = '&simulation /'
    m%list_name = ''
    m%list_text = ''
    m%git_revision = 'bench'
    m%n_cases = n
    m%n_par = n_par
    m%n_gears = n_gears
    allocate (m%par_name(n_par), m%par_label(n_par), m%par_units(n_par), m%par_desc(n_par))
    do j = 1, n_par
      write (m%par_name(j), '(a,i0,a)') 'initial_state%velocity(', j, ')'
      write (m%par_label(j), '(a,i0)') 'input_', j
      m%par_units(j) = 'm/s'
      m%par_desc(j) = 'uniform(lo=0, hi=1)'
    end do
  end function synthetic_meta

  !> n rows with ids first.. and deterministic pseudo-random metrics.
  function synthetic_rows(first, n) result(r)
    integer, intent(in) :: first      !! first case id [-]
    integer, intent(in) :: n          !! rows [-]
    type(case_row_t), allocatable :: r(:)   !! rows [-]
    integer :: k, id, k2
    allocate (r(n))
    do k = 1, n
      id = first + k - 1
      r(k) = new_row(id, n_par, n_gears)
      r(k)%status = status_ok
      r(k)%success = mod(id, 7)/6
      r(k)%n_steps = 50000
      r(k)%inputs = [(frac(id, k2), k2=1, n_par)]
      r(k)%crush = reshape([(0.1_wp*frac(id, 10 + k2), k2=1, 3*n_gears)], [3, n_gears])
      r(k)%margin = reshape([(0.2_wp*frac(id, 30 + k2), k2=1, 3*n_gears)], [3, n_gears])
      r(k)%min_margin = minval(r(k)%margin)
      r(k)%peak_overload = 3.0_wp*frac(id, 50)
      r(k)%peak_penetration = 0.01_wp*frac(id, 51)
      r(k)%max_slide = 0.1_wp*frac(id, 52)
      r(k)%final_tilt = 5.0_wp*frac(id, 53)
      r(k)%max_tilt = 6.0_wp*frac(id, 54)
      r(k)%min_clearance = 0.5_wp*frac(id, 55)
      r(k)%final_time = 2.0_wp
      r(k)%wall_time = 0.2_wp
      r(k)%end_reason = 'end time reached'
    end do
  end function synthetic_rows

  !> A deterministic number in [0, 1) from two integers.
  pure function frac(a, b) result(x)
    integer, intent(in) :: a, b   !! seeds [-]
    real(wp) :: x                 !! in [0, 1) [-]
    x = modulo(real(a, wp)*0.6180339887498949_wp + real(b, wp)*0.4142135623730951_wp, 1.0_wp)
  end function frac

end program bench_campaign_store
