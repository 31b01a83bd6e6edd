!> The journal of a campaign: one text line per finished case, flushed at once, so a killed
!! campaign loses only the cases in flight; `--resume` reads it back (with the summary file of
!! landyn_campaign_store).
!!
!! Journal lines: a header `LANDYN campaign journal v1 fingerprint=<16 hex> n_par=<n> n_gears=<n>`,
!! then per case `R`, the row's integers (i11 each), its reals as IEEE bit patterns (z16 each),
!! the text part (message, end reason, history file, lengths among the integers) and ` $`.
!! A line that does not parse (a torn last line) is ignored.
!!
!! Library code: nothing here stops or prints.
module landyn_campaign_journal
  use, intrinsic :: iso_fortran_env, only: int64
  use landyn_kinds, only: wp
  use landyn_strings, only: int_text
  use landyn_status, only: status_t, STAT_FAILED
  use landyn_campaign_case, only: case_row_t, row_int_count, row_real_count, pack_row, unpack_row
  use landyn_campaign_store, only: summary_meta_t
  implicit none
  private

  public :: journal_open, journal_append, journal_flush, journal_read, journal_line

  character(len=*), parameter :: journal_magic = 'LANDYN campaign journal v1'  !! first words of the header [-]

contains

  !> Open the journal for appending: create it with its header, or check the header of an
  !! existing one against `meta`. STAT_FAILED on a different campaign or an unwritable file.
  subroutine journal_open(path, meta, unit, status)
    character(len=*), intent(in) :: path        !! journal file [-]
    type(summary_meta_t), intent(in) :: meta    !! campaign meta data [-]
    integer, intent(out) :: unit                !! open unit [-]
    type(status_t), intent(out) :: status       !! STAT_OK, or STAT_FAILED with its message [-]
    logical :: exists
    character(len=256) :: iomsg
    integer :: ios
    iomsg = ''
    inquire (file=path, exist=exists)
    if (exists) then
      call end_with_newline(path, ios, iomsg)
      if (ios == 0) open (newunit=unit, file=path, status='old', action='write', position='append', &
                          form='formatted', iostat=ios, iomsg=iomsg)
    else
      open (newunit=unit, file=path, status='new', action='write', form='formatted', iostat=ios, iomsg=iomsg)
      if (ios == 0) then
        write (unit, '(a)', iostat=ios, iomsg=iomsg) journal_header(meta)
        if (ios == 0) flush (unit)
      end if
    end if
    if (ios /= 0) call status%fail(STAT_FAILED, 'cannot open the journal '//path//': '//trim(iomsg))
  end subroutine journal_open

  !> Append a line end to a file whose last line is unterminated (a torn journal line), so
  !! that new lines start on a line of their own.
  subroutine end_with_newline(path, ios, iomsg)
    character(len=*), intent(in) :: path        !! file [-]
    integer, intent(out) :: ios                 !! iostat: 0 ok [-]
    character(len=*), intent(inout) :: iomsg    !! message on failure [-]
    integer :: u, nbytes
    character(len=1) :: last
    open (newunit=u, file=path, access='stream', form='unformatted', action='readwrite', status='old', &
          iostat=ios, iomsg=iomsg)
    if (ios /= 0) return
    inquire (unit=u, size=nbytes)
    if (nbytes > 0) then
      read (u, pos=nbytes, iostat=ios, iomsg=iomsg) last
      if (ios == 0 .and. last /= new_line('a')) write (u, pos=nbytes + 1, iostat=ios, iomsg=iomsg) new_line('a')
    end if
    close (u)
  end subroutine end_with_newline

  !> The header line of the journal of the campaign `meta` describes.
  function journal_header(meta) result(s)
    type(summary_meta_t), intent(in) :: meta  !! meta data [-]
    character(len=:), allocatable :: s        !! header line [-]
    s = journal_magic//' fingerprint='//meta%fingerprint//' n_par='//int_text(meta%n_par)//' n_gears='// &
        int_text(meta%n_gears)
  end function journal_header

  !> Append one row to the journal and flush it (unless `flush_now` is .false.: the caller then
  !! flushes with journal_flush before it waits or computes, so that a kill loses only rows
  !! received in the last moments).
  subroutine journal_append(unit, row, status, flush_now)
    integer, intent(in) :: unit                 !! journal unit [-]
    type(case_row_t), intent(in) :: row         !! row [-]
    type(status_t), intent(out) :: status       !! STAT_OK, or STAT_FAILED with its message [-]
    logical, intent(in), optional :: flush_now  !! flush at once (default .true.) [-]
    integer :: ibuf(row_int_count), ios
    real(wp), allocatable :: rbuf(:)
    character(len=:), allocatable :: text
    character(len=256) :: iomsg
    iomsg = ''
    call pack_row(row, ibuf, rbuf, text)
    write (unit, '(a)', iostat=ios, iomsg=iomsg) journal_line(ibuf, rbuf, text)
    if (present(flush_now)) then
      if (ios == 0 .and. flush_now) flush (unit, iostat=ios, iomsg=iomsg)
    else
      if (ios == 0) flush (unit, iostat=ios, iomsg=iomsg)
    end if
    if (ios /= 0) call status%fail(STAT_FAILED, 'cannot write to the journal: '//trim(iomsg))
  end subroutine journal_append

  !> The journal line of a packed row: 'R', the integers as (1x,i11), the reals' bit patterns
  !! as (1x,z16.16), then ' ', the text and ' $'; made without formatted output, which cost
  !! rank 0 most of its time per row (the text is the same, byte for byte).
  pure function journal_line(ibuf, rbuf, text) result(line)
    integer, intent(in) :: ibuf(:)         !! integer part [-]
    real(wp), intent(in) :: rbuf(:)        !! real part [mixed units]
    character(len=*), intent(in) :: text   !! text part [-]
    character(len=:), allocatable :: line  !! journal line without its end [-]
    character(len=16), parameter :: hex = '0123456789ABCDEF'
    integer :: k, j, p
    integer(int64) :: v
    logical :: negative
    allocate (character(len=1 + 12*size(ibuf) + 17*size(rbuf) + 1 + len(text) + 2) :: line)
    line(:) = ' '
    line(1:1) = 'R'
    p = 1
    do k = 1, size(ibuf)   ! (1x,i11): right-justified, '-' before the digits
      v = abs(int(ibuf(k), int64))
      negative = ibuf(k) < 0
      j = p + 12
      do
        line(j:j) = achar(iachar('0') + int(mod(v, 10_int64)))
        v = v/10_int64
        j = j - 1
        if (v == 0_int64) exit
      end do
      if (negative) line(j:j) = '-'
      p = p + 12
    end do
    do k = 1, size(rbuf)   ! (1x,z16.16): the 64 bits, most significant hexadecimal digit first
      v = transfer(rbuf(k), 0_int64)
      do j = p + 17, p + 2, -1
        line(j:j) = hex(int(iand(v, 15_int64)) + 1:int(iand(v, 15_int64)) + 1)
        v = ishft(v, -4)
      end do
      p = p + 17
    end do
    line(p + 2:) = text//' $'
  end function journal_line

  !> Flush the journal's lines to the operating system.
  subroutine journal_flush(unit, status)
    integer, intent(in) :: unit                 !! journal unit [-]
    type(status_t), intent(out) :: status       !! STAT_OK, or STAT_FAILED with its message [-]
    character(len=256) :: iomsg
    integer :: ios
    iomsg = ''
    flush (unit, iostat=ios, iomsg=iomsg)
    if (ios /= 0) call status%fail(STAT_FAILED, 'cannot write to the journal: '//trim(iomsg))
  end subroutine journal_flush

  !> Rows of a journal (in file order). STAT_FAILED when the file cannot be opened or is not a
  !! journal of the campaign `meta` describes; n_bad counts lines that did not parse (a torn last line).
  subroutine journal_read(path, meta, rows, n_bad, status)
    character(len=*), intent(in) :: path                   !! journal file [-]
    type(summary_meta_t), intent(in) :: meta               !! campaign meta data [-]
    type(case_row_t), allocatable, intent(out) :: rows(:)  !! rows [-]
    integer, intent(out) :: n_bad                          !! unparsable lines [-]
    type(status_t), intent(out) :: status                  !! STAT_OK, or STAT_FAILED with its message [-]
    integer :: u, ios, nr, nfix, k, k2, st, n
    character(len=:), allocatable :: line
    character(len=32) :: fmt
    character(len=1) :: tag
    integer :: ibuf(row_int_count)
    integer(int64), allocatable :: hex(:)
    real(wp), allocatable :: rbuf(:)
    type(case_row_t) :: row
    type(case_row_t), allocatable :: tmp(:)
    character(len=256) :: iomsg

    n_bad = 0
    allocate (rows(0))
    iomsg = ''
    open (newunit=u, file=path, status='old', action='read', form='formatted', iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      call status%fail(STAT_FAILED, 'cannot open the journal '//path//': '//trim(iomsg))
      return
    end if
    call read_line(u, line, ios)
    if (ios /= 0 .or. line /= journal_header(meta)) then
      if (ios == 0 .and. index(line, journal_magic) == 1) then
        call status%fail(STAT_FAILED, path//' is the journal of a different campaign ('// &
                         trim(line(len(journal_magic) + 2:))//'; this campaign has fingerprint='//meta%fingerprint//')')
      else
        call status%fail(STAT_FAILED, path//' is not a LANDYN campaign journal')
      end if
      close (u)
      return
    end if
    nr = row_real_count(meta%n_par, meta%n_gears)
    allocate (hex(nr), rbuf(nr))
    nfix = 1 + 12*row_int_count + 17*nr
    write (fmt, '(a,i0,a,i0,a)') '(a1,', row_int_count, '(1x,i11),', max(nr, 1), '(1x,z16))'
    n = 0
    do
      call read_line(u, line, ios)
      if (ios /= 0) exit
      st = 1
      if (len(line) >= nfix + 3) then
        read (line(1:nfix), fmt, iostat=ios) tag, ibuf, hex
        if (ios == 0 .and. tag == 'R') then
          k = sum(ibuf(9:11))
          if (ibuf(9) >= 0 .and. ibuf(10) >= 0 .and. ibuf(11) >= 0 .and. len(line) == nfix + 1 + k + 2) then
            if (line(nfix + 2 + k:) == ' $') then
              rbuf = [(transfer(hex(k2), 1.0_wp), k2=1, nr)]
              call unpack_row(ibuf, rbuf, line(nfix + 2:nfix + 1 + k), meta%n_par, meta%n_gears, row, st)
            end if
          end if
        end if
      end if
      if (st /= 0) then
        n_bad = n_bad + 1
        cycle
      end if
      if (n == size(rows)) then
        allocate (tmp(max(16, 2*n)))
        tmp(1:n) = rows(1:n)
        call move_alloc(tmp, rows)
      end if
      n = n + 1
      rows(n) = row
    end do
    close (u)
    rows = rows(1:n)
  end subroutine journal_read

  !> One whole line of a formatted sequential file, any length.
  subroutine read_line(u, line, ios)
    integer, intent(in) :: u                              !! open unit [-]
    character(len=:), allocatable, intent(out) :: line    !! the line without its end [-]
    integer, intent(out) :: ios                           !! 0 ok, < 0 end of file, > 0 error [-]
    character(len=4096) :: buf
    integer :: nread
    line = ''
    do
      read (u, '(a)', advance='no', iostat=ios, size=nread) buf
      line = line//buf(1:nread)
      if (ios /= 0) exit
    end do
    if (is_iostat_eor(ios)) ios = 0
  end subroutine read_line

end module landyn_campaign_journal
