!> Opening, closing and publishing HDF5 files, groups, and the plain-file operations (rename,
!! delete) used to publish a file written under a temporary name (see landyn_h5).
module landyn_h5_file
  use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
  use landyn_status, only: status_t, STAT_OK, STAT_FAILED
  use landyn_files, only: file_kind, kind_regular
  use landyn_h5_base, only: no_id, h5_file_t, h5_is_open, h5_exists, init_library, make_lcpl, &
    release, check_writable, fail, fail_file
  use hdf5, only: hid_t, h5fcreate_f, h5fopen_f, h5fclose_f, h5fis_hdf5_f, h5gcreate_f, h5gopen_f, &
    H5F_ACC_TRUNC_F, H5F_ACC_EXCL_F, H5F_ACC_RDONLY_F
  implicit none
  private

  public :: h5_create, h5_open_read, h5_close, h5_create_group
  public :: rename_file, delete_file, h5_create_partial, h5_commit_partial

  !> The C library's rename(3) and remove(3).
  interface
    !> C library rename(3): 0 on success.
    function c_rename(old_name, new_name) bind(C, name='rename') result(rc)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: old_name(*)  !! null-terminated source name
      character(kind=c_char), intent(in) :: new_name(*)  !! null-terminated target name
      integer(c_int) :: rc                               !! 0 on success, -1 on failure
    end function c_rename

    !> C library remove(3): 0 on success.
    function c_remove(file_name) bind(C, name='remove') result(rc)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: file_name(*) !! null-terminated file name
      integer(c_int) :: rc                               !! 0 on success, -1 on failure
    end function c_remove
  end interface

contains

  ! ============================================================== files

  !> What opening a file on handle `file` begins with (h5_create, h5_open_read): fails when the
  !! handle is still open, or the HDF5 library cannot be initialised.
  subroutine begin_open(file, op, path, status)
    type(h5_file_t), intent(in) :: file        !! the handle, must not be open
    character(len=*), intent(in) :: op         !! public operation name, for messages [-]
    character(len=*), intent(in) :: path       !! file name
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    integer :: hdferr
    if (h5_is_open(file)) then
      call fail_file(status, op, 'the handle is still open on file', file%path)
      return
    end if
    call init_library(hdferr)
    if (hdferr < 0) call fail_file(status, op, 'cannot initialise the HDF5 library for file', path)
  end subroutine begin_open

  !> Create (truncate) an HDF5 file for writing; with exclusive = .true., fail instead when a file
  !! (or a link, also a dangling one) of that name exists, so nothing is written through a link.
  subroutine h5_create(file, path, status, exclusive)
    type(h5_file_t), intent(inout) :: file     !! must not be open
    character(len=*), intent(in) :: path       !! file name
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    logical, intent(in), optional :: exclusive !! fail when `path` exists (default .false.) [-]
    integer :: hdferr, mode

    call begin_open(file, 'h5_create', path, status)
    if (.not. status%ok()) return
    mode = H5F_ACC_TRUNC_F
    if (present(exclusive)) then
      if (exclusive) mode = H5F_ACC_EXCL_F
    end if
    call h5fcreate_f(trim(path), mode, file%id, hdferr)
    if (hdferr < 0) then
      file%id = no_id
      call fail_file(status, 'h5_create', 'cannot create file', path, &
        ' (does its directory exist and is it writable? is a file of that name in the way?)')
      return
    end if
    file%path = trim(path)
    file%writable = .true.
  end subroutine h5_create

  !> Open an existing HDF5 file read-only.
  subroutine h5_open_read(file, path, status)
    type(h5_file_t), intent(inout) :: file     !! must not be open
    character(len=*), intent(in) :: path       !! file name
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    integer :: hdferr
    logical :: exists, is_hdf5

    inquire(file=trim(path), exist=exists)
    if (.not. exists .and. .not. h5_is_open(file)) then  ! (begin_open reports a handle still open)
      call fail_file(status, 'h5_open_read', 'no such file', path)
      return
    end if
    call begin_open(file, 'h5_open_read', path, status)
    if (.not. status%ok()) return
    call h5fis_hdf5_f(trim(path), is_hdf5, hdferr)
    if (hdferr < 0 .or. .not. is_hdf5) then
      call fail_file(status, 'h5_open_read', 'not an HDF5 file (or not readable):', path)
      return
    end if
    call h5fopen_f(trim(path), H5F_ACC_RDONLY_F, file%id, hdferr)
    if (hdferr < 0) then
      file%id = no_id
      call fail_file(status, 'h5_open_read', 'cannot open HDF5 file', path)
      return
    end if
    file%path = trim(path)
    file%writable = .false.
  end subroutine h5_open_read

  !> Close a file (flushing it). Closing a handle that is not open does nothing and succeeds.
  subroutine h5_close(file, status)
    type(h5_file_t), intent(inout) :: file     !! not open afterwards, whatever the outcome
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    integer :: hdferr

    if (.not. h5_is_open(file)) return
    call h5fclose_f(file%id, hdferr)
    file%id = no_id
    file%writable = .false.
    if (hdferr < 0) call fail_file(status, 'h5_close', 'cannot close file', file%path, ' (data may be lost)')
  end subroutine h5_close

  !> Create a group and any missing intermediate groups. An existing group is not an error.
  subroutine h5_create_group(file, path, status)
    type(h5_file_t), intent(in) :: file        !! file open for writing
    character(len=*), intent(in) :: path       !! group path, e.g. '/gears/gear_1'
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    character(len=*), parameter :: op = 'h5_create_group'
    integer(hid_t) :: lcpl, gid
    integer :: hdferr
    logical :: ok

    call check_writable(file, op, path, status)
    if (.not. status%ok()) return
    lcpl = no_id
    gid = no_id
    steps: block
      if (h5_exists(file, path)) then
        call h5gopen_f(file%id, trim(path), gid, hdferr)
        if (hdferr < 0) call fail(status, op, 'an object that is not a group exists at', path, file)
        exit steps
      end if
      call make_lcpl(lcpl, hdferr)
      if (hdferr < 0) then
        call fail(status, op, 'cannot make a link-creation property list for', path, file)
        exit steps
      end if
      call h5gcreate_f(file%id, trim(path), gid, hdferr, lcpl_id=lcpl)
      if (hdferr < 0) call fail(status, op, 'cannot create group', path, file)
    end block steps
    ok = .true.
    call release(gid, ok)
    call release(lcpl, ok)
    if (status%ok() .and. .not. ok) call fail(status, op, 'cannot release HDF5 handles of', path, file)
  end subroutine h5_create_group


  ! ============================================================== plain files

  !> Rename (move) a file with C rename(3): atomic within one file system, replaces an existing
  !! `to`; fails across file systems. Use it to publish a result file written under a temporary
  !! name in the same directory.
  subroutine rename_file(from, to, status)
    character(len=*), intent(in) :: from       !! existing file name
    character(len=*), intent(in) :: to         !! new file name
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    logical :: exists

    if (c_rename(trim(from)//c_null_char, trim(to)//c_null_char) == 0_c_int) return
    inquire(file=from, exist=exists)
    if (exists) then
      call status%fail(STAT_FAILED, "rename_file: cannot rename '"//trim(from)//"' to '"//trim(to)// &
        "' (target directory missing or not writable, or another file system?)")
    else
      call status%fail(STAT_FAILED, "rename_file: cannot rename '"//trim(from)//"' to '"//trim(to)//"': no such file")
    end if
  end subroutine rename_file

  !> Delete a file with C remove(3). A file that does not exist is not an error. A symbolic link
  !! is removed itself (also a dangling one), never the file it points to.
  subroutine delete_file(path, status)
    character(len=*), intent(in) :: path                 !! file name
    type(status_t), intent(out), optional :: status      !! STAT_OK, or the failure with its message [-]
    logical :: exists

    if (c_remove(trim(path)//c_null_char) == 0_c_int) return
    inquire(file=path, exist=exists)
    if (.not. exists) return
    if (present(status)) call status%fail(STAT_FAILED, "delete_file: cannot delete '"//trim(path)//"'")
  end subroutine delete_file

  ! ============================================================== files published whole

  !> Create `path`.partial for writing. Write the contents, then call h5_commit_partial with
  !! their status: the file appears under `path` only when it is complete, so a write that
  !! fails or is killed leaves nothing that looks like a result.
  !! A `path`.partial left by a killed run is removed first, by name: when it is a symbolic or a
  !! hard link, the link goes and the file it points to is untouched; the new one is then created
  !! exclusively, so nothing is ever written through a link of that name.
  subroutine h5_create_partial(file, path, status)
    type(h5_file_t), intent(inout) :: file     !! must not be open; open on `path`.partial afterwards
    character(len=*), intent(in) :: path       !! final file name
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    type(status_t) :: st2
    call delete_file(trim(path)//'.partial', st2)   ! its failure shows in the exclusive create
    call h5_create(file, trim(path)//'.partial', status, exclusive=.true.)
    ! a create that failed after making the file (a full disk: no room for the superblock) leaves
    ! it empty; a regular file there now is that one (the stale one went above)
    if (.not. status%ok()) then
      if (file_kind(trim(path)//'.partial') == kind_regular) call delete_file(trim(path)//'.partial', st2)
    end if
  end subroutine h5_create_partial

  !> Finish a file begun with h5_create_partial: with a status STAT_OK on entry (contents written),
  !! close it and rename `path`.partial to `path`; otherwise (or when closing or renaming fails)
  !! close it and delete `path`.partial, keeping the caller's status and message.
  subroutine h5_commit_partial(file, path, status)
    type(h5_file_t), intent(inout) :: file     !! opened by h5_create_partial; closed afterwards
    character(len=*), intent(in) :: path       !! final file name, as given to h5_create_partial
    type(status_t), intent(inout) :: status    !! in: status of writing the contents; out: STAT_OK when published [-]
    character(len=:), allocatable :: tmp
    type(status_t) :: st2
    tmp = trim(path)//'.partial'
    if (.not. status%ok()) then
      call h5_close(file, st2)
      call delete_file(tmp, st2)
      return
    end if
    call h5_close(file, status)
    if (.not. status%ok()) then
      call delete_file(tmp, st2)
      return
    end if
    call rename_file(tmp, trim(path), status)
    if (.not. status%ok()) call delete_file(tmp, st2)
  end subroutine h5_commit_partial

  ! ============================================================== private helpers

end module landyn_h5_file
