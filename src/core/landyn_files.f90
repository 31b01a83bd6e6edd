!> Files as the three programs (landyn, landyn_study, landyn_batch) read and write them:
!!
!! * read_whole_file: a text file (deck, case list) whole, also when the system reports its size
!!   as 0 (pipes such as `<(cat deck.nml)`, /proc files): then it is read byte by byte to its end.
!!   Read errors are reported, never taken for an empty file. Line ends are normalised
!!   (CR LF and a lone CR become LF) and a UTF-8 byte-order mark is dropped.
!! * output_file_problem: the output-file policy of docs/files.md. An output file is written as
!!   `<name>.partial` and renamed when complete; before anything runs each program asks here
!!   whether `<name>` may be written, and refuses (exit status 4, nothing run) when
!!     - the name is empty, or its last component is too long for `<name>.partial`,
!!     - its directory does not exist,
!!     - it names an input of the same run (the deck, a base deck, a case list, another output),
!!     - it exists and is not a regular file (a directory, a device such as /dev/null, a fifo),
!!     - it exists and is read-only (no write permission bit, whoever runs the program),
!!     - it exists and is not an HDF5 file (for HDF5 outputs: a result never replaces a deck,
!!       a CSV or any other text).
!!   An existing writable result (HDF5, or a CSV table for landyn_study's --csv) is replaced; the
!!   programs say so on stderr.
!!
!! * lock_file / unlock_file: an exclusive advisory lock (flock(2)) on a lock file, held until
!!   unlock_file or the end of the process (also a killed one: the kernel releases it), so that two
!!   processes never work on one campaign at once.
!!
!! Library code: nothing here stops or prints.
module landyn_files
  use, intrinsic :: iso_c_binding, only: c_char, c_int, c_long_long, c_null_char
  use, intrinsic :: iso_fortran_env, only: iostat_end
  use landyn_status, only: status_t, STAT_FAILED
  implicit none
  private

  public :: read_whole_file, normalize_line_ends, file_kind, output_file_problem
  public :: kind_missing, kind_regular, kind_directory, kind_other, kind_unknown
  public :: base_name, lock_file, unlock_file

  integer, parameter :: kind_unknown = -1   !! cannot tell (permission denied on the way, ...)
  integer, parameter :: kind_missing = 0    !! no such file
  integer, parameter :: kind_regular = 1    !! regular file
  integer, parameter :: kind_directory = 2  !! directory
  integer, parameter :: kind_other = 3      !! device, fifo, socket
  integer, parameter :: max_name_component = 255   !! longest file-name component (Linux NAME_MAX) [-]
  integer, parameter :: max_text_bytes = 64*1024*1024   !! largest text file read [bytes]
  character(len=*), parameter :: partial_suffix = '.partial'  !! added to an output file's name until it is complete [-]

  interface
    !> stat(2) of a file (landyn_fileinfo.c): its kind, its identity (device, inode) and its write permission.
    subroutine c_file_info(path, kind, dev, ino, writable) bind(C, name='landyn_file_info')
      import :: c_char, c_int, c_long_long
      character(kind=c_char), dimension(*), intent(in) :: path   !! NUL-terminated file name [-]
      integer(c_int), intent(out) :: kind                        !! kind_* [-]
      integer(c_long_long), intent(out) :: dev, ino              !! device and inode: the file's identity [-]
      integer(c_int), intent(out) :: writable                    !! 1: a write permission bit is set [-]
    end subroutine c_file_info

    !> flock(2) of a lock file (landyn_fileinfo.c): 0 locked, 1 held by another process, -1 error.
    function c_lock_file(path, fd, holder) bind(C, name='landyn_lock_file') result(rc)
      import :: c_char, c_int, c_long_long
      character(kind=c_char), dimension(*), intent(in) :: path   !! NUL-terminated file name [-]
      integer(c_int), intent(out) :: fd                          !! descriptor holding the lock [-]
      integer(c_long_long), intent(out) :: holder                !! pid of the holder when busy, 0 unknown [-]
      integer(c_int) :: rc                                       !! 0, 1 or -1 [-]
    end function c_lock_file

    !> Remove the lock file and release its lock (landyn_fileinfo.c).
    subroutine c_unlock_file(path, fd) bind(C, name='landyn_unlock_file')
      import :: c_char, c_int
      character(kind=c_char), dimension(*), intent(in) :: path   !! NUL-terminated file name [-]
      integer(c_int), value :: fd                                !! descriptor holding the lock [-]
    end subroutine c_unlock_file
  end interface

contains

  !> Whole text file as one string, line ends normalised (see the module documentation).
  !! STAT_OK on success; otherwise STAT_FAILED and the message says why (cannot open, read error,
  !! too large).
  subroutine read_whole_file(path, text, status)
    character(len=*), intent(in) :: path                  !! file name [-]
    character(len=:), allocatable, intent(out) :: text    !! its text [-]
    type(status_t), intent(out) :: status                 !! STAT_OK, or STAT_FAILED with the reason [-]
    character(len=256) :: iomsg
    character(len=:), allocatable :: buf
    character(len=1) :: c
    integer :: u, nbytes, n, ios, k, kd
    integer(c_long_long) :: dev, ino
    character(len=*), parameter :: too_large = 'it is larger than 64 MiB; not a text deck'

    text = ''
    if (len(path) == 0) then
      call fail('empty file name')
      return
    end if
    call info(path, kd, dev, ino, k)
    if (kd == kind_directory) then
      call fail('it is a directory')
      return
    end if
    iomsg = ''
    open (newunit=u, file=path, access='stream', form='unformatted', action='read', status='old', &
          iostat=ios, iomsg=iomsg)
    if (ios /= 0) then
      call fail(trim(iomsg))
      return
    end if
    inquire (unit=u, size=nbytes)
    if (nbytes > max_text_bytes) then
      call fail(too_large, u)
      return
    end if
    if (nbytes > 0) then
      allocate (character(len=nbytes) :: buf)
      read (u, iostat=ios, iomsg=iomsg) buf
      if (ios /= 0) then
        call fail('read error: '//trim(iomsg), u)
        return
      end if
    else
      ! size 0 or unknown (pipe, /proc file, device): read to the end byte by byte
      allocate (character(len=4096) :: buf)
      n = 0
      do
        read (u, iostat=ios, iomsg=iomsg) c
        if (ios == iostat_end) exit
        if (ios /= 0) then
          call fail('read error: '//trim(iomsg), u)
          return
        end if
        if (n == len(buf)) then
          if (n >= max_text_bytes) then
            call fail(too_large, u)
            return
          end if
          buf = buf//repeat(' ', len(buf))
        end if
        n = n + 1
        buf(n:n) = c
      end do
      buf = buf(1:n)
    end if
    close (u)
    text = normalize_line_ends(buf)
  contains
    !> Record a failure: STAT_FAILED with the message `why`, after closing `unit` when given.
    subroutine fail(why, unit)
      character(len=*), intent(in) :: why        !! reason [-]
      integer, intent(in), optional :: unit      !! open unit to close [-]
      if (present(unit)) close (unit)
      call status%fail(STAT_FAILED, why)
    end subroutine fail
  end subroutine read_whole_file

  !> Text with CR LF and lone CR made LF, and a leading UTF-8 byte-order mark removed.
  pure function normalize_line_ends(t) result(s)
    character(len=*), intent(in) :: t     !! text [-]
    character(len=:), allocatable :: s    !! normalised text [-]
    character(len=*), parameter :: bom = char(239)//char(187)//char(191)
    integer :: i, n, i0
    allocate (character(len=len(t)) :: s)
    i0 = 1
    if (len(t) >= 3) then
      if (t(1:3) == bom) i0 = 4
    end if
    n = 0
    i = i0
    do while (i <= len(t))
      if (t(i:i) == achar(13)) then
        n = n + 1
        s(n:n) = achar(10)
        if (i < len(t)) then
          if (t(i + 1:i + 1) == achar(10)) i = i + 1
        end if
      else
        n = n + 1
        s(n:n) = t(i:i)
      end if
      i = i + 1
    end do
    s = s(1:n)
  end function normalize_line_ends

  !> Kind of the file `path`: kind_missing, kind_regular, kind_directory, kind_other or kind_unknown.
  function file_kind(path) result(k)
    character(len=*), intent(in) :: path   !! file name [-]
    integer :: k                           !! kind [-]
    integer(c_long_long) :: dev, ino
    integer :: w
    call info(path, k, dev, ino, w)
  end function file_kind

  !> True when `a` and `b` both exist and are the same file (also through links and other names).
  function same_file(a, b) result(yes)
    character(len=*), intent(in) :: a, b   !! file names [-]
    logical :: yes                         !! same file [-]
    integer(c_long_long) :: da, ia, db, ib
    integer :: ka, kb, w
    yes = .false.
    if (len(a) == 0 .or. len(b) == 0) return
    call info(a, ka, da, ia, w)
    if (ka <= 0) return
    call info(b, kb, db, ib, w)
    if (kb <= 0) return
    yes = da == db .and. ia == ib
  end function same_file

  !> True when the file starts with an HDF5 superblock: the 8-byte signature, then a superblock
  !! version 0 to 3 with sizes of offsets and lengths of 2, 4, 8 or 16 bytes (and, for versions 0
  !! and 1, the zero version and reserved bytes of the format specification, section II.A). Text
  !! that merely begins with the signature is refused. Written here rather than with the HDF5
  !! library because core/ does not use HDF5, and H5Fis_hdf5 checks the signature only.
  function is_hdf5_file(path) result(yes)
    character(len=*), intent(in) :: path   !! file name [-]
    logical :: yes                         !! HDF5 superblock found [-]
    character(len=16) :: head
    integer :: u, ios, version, so, sl, k
    yes = .false.
    open (newunit=u, file=path, access='stream', form='unformatted', action='read', status='old', iostat=ios)
    if (ios /= 0) return
    read (u, iostat=ios) head
    close (u)
    if (ios /= 0) return
    if (head(1:8) /= char(137)//'HDF'//achar(13)//achar(10)//achar(26)//achar(10)) return
    version = ichar(head(9:9))
    select case (version)
    case (0, 1)   ! free-space, root group, reserved, shared-header versions: 0; sizes at 14, 15
      if (any([(ichar(head(k:k)), k = 10, 13)] /= 0) .or. ichar(head(16:16)) /= 0) return
      so = ichar(head(14:14))
      sl = ichar(head(15:15))
    case (2, 3)   ! sizes at 10, 11; consistency flags below 8
      so = ichar(head(10:10))
      sl = ichar(head(11:11))
      if (ichar(head(12:12)) > 7) return
    case default
      return
    end select
    yes = any(so == [2, 4, 8, 16]) .and. any(sl == [2, 4, 8, 16])
  end function is_hdf5_file

  !> Directory part of a path ('.' when there is none).
  !> File name without its directory and its last extension ('a/b/mc.nml' -> 'mc'); `fallback`
  !! (default '') when nothing is left.
  pure function base_name(path, fallback) result(b)
    character(len=*), intent(in) :: path                !! file name [-]
    character(len=*), intent(in), optional :: fallback  !! returned for an empty base name [-]
    character(len=:), allocatable :: b                  !! base name [-]
    integer :: d
    b = trim(path(index(path, '/', back=.true.) + 1:))
    d = index(b, '.', back=.true.)
    if (d > 1) b = b(1:d - 1)
    if (len(b) == 0 .and. present(fallback)) b = fallback
  end function base_name

  !> Directory of a file name: '.' when it has none, '/' for a name directly under the root.
  pure function directory_of(path) result(d)
    character(len=*), intent(in) :: path   !! file name [-]
    character(len=:), allocatable :: d     !! its directory [-]
    integer :: p
    p = index(path, '/', back=.true.)
    if (p == 0) then
      d = '.'
    else if (p == 1) then
      d = '/'
    else
      d = path(1:p - 1)
    end if
  end function directory_of

  !> Why the output file `path` may not be written ('' when it may), following the policy of the
  !! module documentation. `what` names the file in messages (e.g. 'result file'); `inputs` are the
  !! files this run reads or writes otherwise; hdf5 = the file is an HDF5 result (an existing file
  !! must then be HDF5 to be replaced).
  function output_file_problem(path, what, inputs, hdf5) result(problem)
    character(len=*), intent(in) :: path          !! output file name [-]
    character(len=*), intent(in) :: what          !! its role, for messages [-]
    character(len=*), intent(in) :: inputs(:)     !! files of the run it must not replace (blank: none) [-]
    logical, intent(in) :: hdf5                   !! the output is an HDF5 file [-]
    character(len=:), allocatable :: problem      !! '' or the reason [-]
    character(len=:), allocatable :: dir, base
    integer(c_long_long) :: dev, ino
    integer :: k, w, i, p

    problem = ''
    if (len_trim(path) == 0) then
      problem = what//': empty file name'
      return
    end if
    if (path(len(path):) == ' ' .or. path(1:1) == ' ') then
      problem = what//' '''//path//''': a file name that begins or ends with a blank is not supported'
      return
    end if
    p = index(path, '/', back=.true.)
    base = path(p + 1:)
    if (len(base) == 0) then
      problem = what//' '''//path//''' names a directory, not a file'
      return
    end if
    if (len(base) + len(partial_suffix) > max_name_component) then
      problem = what//' name too long: its last component has '//itoa(len(base))//' characters; at most '// &
                itoa(max_name_component - len(partial_suffix))//' (the file is first written as <name>'// &
                partial_suffix//')'
      return
    end if
    dir = directory_of(path)
    k = file_kind(dir)
    if (k == kind_missing) then
      problem = what//' '''//path//''': the directory '''//dir//''' does not exist'
      return
    else if (k /= kind_directory .and. k /= kind_unknown) then
      problem = what//' '''//path//''': '''//dir//''' is not a directory'
      return
    end if
    call info(path, k, dev, ino, w)
    select case (k)
    case (kind_missing)
      return
    case (kind_directory)
      problem = what//' '''//path//''' is a directory'
      return
    case (kind_other)
      problem = what//' '''//path//''' exists and is not a regular file (a device, fifo or socket); '// &
                'results are written only to regular files'
      return
    case (kind_unknown)
      problem = what//' '''//path//''': cannot examine it (permission denied or invalid name)'
      return
    end select
    do i = 1, size(inputs)
      if (len_trim(inputs(i)) == 0) cycle
      if (same_file(path, trim(inputs(i)))) then
        problem = what//' '''//path//''' is the same file as '''//trim(inputs(i))// &
                  ''', which this run reads or writes; refusing to overwrite it'
        return
      end if
    end do
    if (w == 0) then
      problem = what//' '''//path//''' exists and is read-only; refusing to replace it'
      return
    end if
    if (hdf5) then
      if (.not. is_hdf5_file(path)) then
        problem = what//' '''//path//''' exists and is not an HDF5 file; refusing to replace it '// &
                  '(remove it or choose another name)'
        return
      end if
    end if
  end function output_file_problem

  !> Take the exclusive lock `path` (created if missing) without waiting. STAT_OK and `handle`
  !! on success; otherwise STAT_FAILED and the message says why: another process holds it (its pid
  !! when known), or the file cannot be created or locked.
  subroutine lock_file(path, handle, status)
    character(len=*), intent(in) :: path                  !! lock file name [-]
    integer, intent(out) :: handle                        !! lock handle for unlock_file [-]
    type(status_t), intent(out) :: status                 !! STAT_OK, or STAT_FAILED with the reason [-]
    integer(c_int) :: fd, rc
    integer(c_long_long) :: holder
    rc = c_lock_file(path//c_null_char, fd, holder)
    handle = int(fd)
    if (rc == 0) return
    if (rc == 1) then
      call status%fail(STAT_FAILED, 'it is locked by another process')
      if (holder > 0) status%message = status%message//' (pid '//itoa(int(holder))//')'
    else
      call status%fail(STAT_FAILED, 'cannot create or lock it (is its directory writable?)')
    end if
  end subroutine lock_file

  !> Remove the lock file `path` and release the lock `handle` of lock_file (nothing when handle < 0).
  subroutine unlock_file(path, handle)
    character(len=*), intent(in) :: path     !! lock file name [-]
    integer, intent(inout) :: handle         !! lock handle; -1 afterwards [-]
    if (handle < 0) return
    call c_unlock_file(path//c_null_char, int(handle, c_int))
    handle = -1
  end subroutine unlock_file

  !> c_file_info for a Fortran file name, with default integers.
  subroutine info(path, kind, dev, ino, writable)
    character(len=*), intent(in) :: path          !! file name [-]
    integer, intent(out) :: kind                  !! kind_* [-]
    integer(c_long_long), intent(out) :: dev, ino !! identity [-]
    integer, intent(out) :: writable              !! 1: a write permission bit is set [-]
    integer(c_int) :: k, w
    call c_file_info(path//c_null_char, k, dev, ino, w)
    kind = int(k)
    writable = int(w)
  end subroutine info

  !> Integer as decimal text.
  pure function itoa(i) result(s)
    integer, intent(in) :: i              !! integer [-]
    character(len=:), allocatable :: s    !! its decimal text [-]
    character(len=24) :: b
    write (b, '(i0)') i
    s = trim(b)
  end function itoa

end module landyn_files
