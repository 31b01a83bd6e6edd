!> The one thin layer through which LANDYN writes (and, for tests and post-processing, reads) HDF5.
!!
!! Nothing else in LANDYN calls the HDF5 library directly. Every public procedure returns
!! `stat` (0 = success, nonzero = failure) and `errmsg`; it never stops and never prints.
!!
!! ## Error handling
!! - `errmsg` is `character(len=*), intent(inout)` everywhere (callers use `character(len=msg_len)`
!!   from landyn_kinds). Like Fortran's own ERRMSG= specifier, it is assigned only when `stat /= 0`
!!   and left untouched on success. The message names the operation (the public procedure), the
!!   object path inside the file and the file name, e.g.
!!   `h5_read: no dataset '/gear_1/stroke' in file 'run.h5'`. It is truncated to len(errmsg).
!! - The HDF5 library's automatic error-stack printing is switched off (h5eset_auto_f(0)) whenever
!!   a file is created or opened, so expected failures (a missing file, a probe of a missing
!!   object) write nothing to stderr.
!! - On failure every HDF5 handle the call opened is released; nothing leaks.
!!
!! ## Shape convention (the output schema depends on it)
!! Arrays are stored in the natural HDF5 layout of Fortran memory: HDF5 lists dimensions in C order
!! (slowest varying first), Fortran's first index varies fastest, so the dimensions appear REVERSED
!! to C/Python readers. A Fortran array a(n1, n2) is read by h5py / h5dump as shape (n2, n1), and
!! a(i, j) is h5py's a[j-1, i-1]. Example: a time series held in Fortran as x(3, nt) (one column
!! per time step) appears in h5py as shape (nt, 3): one row per time step. A(n1, n2, n3) appears
!! as (n3, n2, n1). The readers here undo the reversal: what was written as a(n1, n2) comes back
!! as a(n1, n2). Zero-size arrays are stored as datasets with a zero extent.
!!
!! ## Stored types
!! - real(wp) -> 64-bit IEEE little-endian float (H5T_IEEE_F64LE); integer(ip) -> 32-bit
!!   little-endian signed integer (H5T_STD_I32LE). (landyn_kinds fixes wp = real64, ip = int32.)
!! - logical (scalar) -> integer 0/1 with an extra string attribute "type" = "logical".
!! - character -> fixed-length ASCII strings, null-padded (what h5py and NumPy use for 'S' data),
!!   as long as the longest trimmed value (at least 1). Trailing blanks are not stored; the
!!   readers return values without trailing blanks. Variable-length strings (h5py's default for
!!   Python str) cannot be read by this module.
!! - Every dataset carries a string attribute "units" (mandatory; use '-' for dimensionless,
!!   e.g. 'm', 'N', 'rad', 's') and optionally "description".
!!
!! ## Paths and groups
!! Object paths are absolute ('/gear_1/stroke') or relative to the root group ('gear_1/stroke').
!! Trailing blanks of file names, paths and attribute names are ignored (fixed-length variables
!! may be passed as they are).
!! Writing a dataset creates any missing intermediate groups (like `mkdir -p`). Writing a dataset
!! whose path already exists is an error (results are written once; nothing is overwritten).
!! Writing an attribute that already exists replaces it.
!!
!! ## Library initialisation
!! h5_create / h5_open_read initialise the HDF5 Fortran interface (h5open_f) only when it is not
!! already initialised, which is detected from HDF5's own state (whether the Fortran predefined
!! datatype ids are live), so this module keeps no global state of its own and repeated
!! open/close cycles in one process are fine. h5close_f is never called: the C library releases
!! its resources at program exit.
module landyn_h5
  use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
  use landyn_kinds, only: wp, ip, msg_len
  use hdf5, only: hid_t, hsize_t, size_t, &
    h5open_f, h5eset_auto_f, h5iis_valid_f, h5iget_type_f, h5kind_to_type, &
    h5fcreate_f, h5fopen_f, h5fclose_f, h5fis_hdf5_f, &
    h5gcreate_f, h5gopen_f, h5gclose_f, h5lexists_f, h5oopen_f, &
    h5pcreate_f, h5pset_create_inter_group_f, h5pclose_f, &
    h5screate_f, h5screate_simple_f, h5sclose_f, h5sget_simple_extent_type_f, &
    h5sget_simple_extent_ndims_f, h5sget_simple_extent_dims_f, &
    h5tcopy_f, h5tset_size_f, h5tset_strpad_f, h5tget_size_f, h5tget_class_f, &
    h5tis_variable_str_f, h5tclose_f, &
    h5dcreate_f, h5dopen_f, h5dwrite_f, h5dread_f, h5dget_type_f, h5dget_space_f, h5dclose_f, &
    h5acreate_f, h5aopen_by_name_f, h5aexists_f, h5adelete_f, h5awrite_f, h5aread_f, &
    h5aget_type_f, h5aget_space_f, h5aclose_f, &
    H5F_ACC_TRUNC_F, H5F_ACC_RDONLY_F, H5P_LINK_CREATE_F, H5S_SCALAR_F, &
    H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, H5T_STD_I32LE, H5T_FORTRAN_S1, H5T_C_S1, &
    H5T_FLOAT_F, H5T_INTEGER_F, H5T_STRING_F, H5T_STR_NULLPAD_F, H5T_STR_SPACEPAD_F, &
    H5_REAL_KIND, H5_INTEGER_KIND, &
    H5I_GROUP_F, H5I_DATATYPE_F, H5I_DATASPACE_F, H5I_DATASET_F, H5I_ATTR_F
  implicit none
  private

  public :: h5_file_t
  public :: h5_create, h5_open_read, h5_close, h5_is_open
  public :: h5_create_group, h5_exists
  public :: h5_write, h5_write_attr
  public :: h5_read, h5_read_attr
  public :: rename_file, delete_file
  public :: h5_create_partial, h5_commit_partial

  integer(hid_t), parameter :: no_id = -1_hid_t   !! marks an HDF5 handle that is not open
  integer, parameter :: max_rank = 3               !! highest array rank handled here
  integer, parameter :: vlen_string = -2           !! internal status: variable-length string found

  !> An HDF5 file opened by h5_create or h5_open_read. Treat the components as read-only.
  type :: h5_file_t
    integer(hid_t) :: id = no_id                 !! HDF5 file identifier; no_id (-1) when not open
    character(len=:), allocatable :: path        !! file name as given when opened (for messages)
    logical :: writable = .false.                !! opened by h5_create
  end type h5_file_t

  !> Write a dataset with a mandatory "units" and an optional "description" attribute:
  !! `call h5_write(file, path, value, units, stat, errmsg [, description])`.
  interface h5_write
    module procedure write_real_0d, write_real_1d, write_real_2d, write_real_3d
    module procedure write_int_0d, write_int_1d, write_int_2d, write_logical_0d
    module procedure write_string_0d, write_string_1d
  end interface h5_write

  !> Write (or replace) a scalar attribute on a group or dataset:
  !! `call h5_write_attr(file, obj_path, name, value, stat, errmsg)`.
  interface h5_write_attr
    module procedure write_attr_string, write_attr_real, write_attr_int
  end interface h5_write_attr

  !> Read a dataset; arrays are allocatable and take their shape from the file:
  !! `call h5_read(file, path, value, stat, errmsg)`.
  interface h5_read
    module procedure read_real_0d, read_real_1d, read_real_2d, read_real_3d
    module procedure read_int_0d, read_int_1d, read_int_2d, read_logical_0d
    module procedure read_string_0d, read_string_1d
  end interface h5_read

  !> Read a scalar attribute of a group or dataset:
  !! `call h5_read_attr(file, obj_path, name, value, stat, errmsg)`.
  interface h5_read_attr
    module procedure read_attr_string, read_attr_real, read_attr_int
  end interface h5_read_attr

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

  !> Create (truncate) an HDF5 file for writing.
  subroutine h5_create(file, path, stat, errmsg)
    type(h5_file_t), intent(inout) :: file     !! must not be open
    character(len=*), intent(in) :: path       !! file name
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer :: hdferr

    stat = 0
    if (h5_is_open(file)) then
      call fail_file(stat, errmsg, 'h5_create', 'the handle is still open on file', file%path)
      return
    end if
    call init_library(hdferr)
    if (hdferr < 0) then
      call fail_file(stat, errmsg, 'h5_create', 'cannot initialise the HDF5 library for file', path)
      return
    end if
    call h5fcreate_f(trim(path), H5F_ACC_TRUNC_F, file%id, hdferr)
    if (hdferr < 0) then
      file%id = no_id
      call fail_file(stat, errmsg, 'h5_create', 'cannot create file', path, &
        ' (does its directory exist and is it writable?)')
      return
    end if
    file%path = trim(path)
    file%writable = .true.
  end subroutine h5_create

  !> Open an existing HDF5 file read-only.
  subroutine h5_open_read(file, path, stat, errmsg)
    type(h5_file_t), intent(inout) :: file     !! must not be open
    character(len=*), intent(in) :: path       !! file name
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer :: hdferr
    logical :: exists, is_hdf5

    stat = 0
    if (h5_is_open(file)) then
      call fail_file(stat, errmsg, 'h5_open_read', 'the handle is still open on file', file%path)
      return
    end if
    inquire(file=trim(path), exist=exists)
    if (.not. exists) then
      call fail_file(stat, errmsg, 'h5_open_read', 'no such file', path)
      return
    end if
    call init_library(hdferr)
    if (hdferr < 0) then
      call fail_file(stat, errmsg, 'h5_open_read', 'cannot initialise the HDF5 library for file', path)
      return
    end if
    call h5fis_hdf5_f(trim(path), is_hdf5, hdferr)
    if (hdferr < 0 .or. .not. is_hdf5) then
      call fail_file(stat, errmsg, 'h5_open_read', 'not an HDF5 file (or not readable):', path)
      return
    end if
    call h5fopen_f(trim(path), H5F_ACC_RDONLY_F, file%id, hdferr)
    if (hdferr < 0) then
      file%id = no_id
      call fail_file(stat, errmsg, 'h5_open_read', 'cannot open HDF5 file', path)
      return
    end if
    file%path = trim(path)
    file%writable = .false.
  end subroutine h5_open_read

  !> Close a file (flushing it). Closing a handle that is not open does nothing and succeeds.
  subroutine h5_close(file, stat, errmsg)
    type(h5_file_t), intent(inout) :: file     !! not open afterwards, whatever the outcome
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer :: hdferr

    stat = 0
    if (.not. h5_is_open(file)) return
    call h5fclose_f(file%id, hdferr)
    file%id = no_id
    file%writable = .false.
    if (hdferr < 0) call fail_file(stat, errmsg, 'h5_close', 'cannot close file', file%path, ' (data may be lost)')
  end subroutine h5_close

  !> True when `file` holds an open HDF5 file.
  pure logical function h5_is_open(file)
    type(h5_file_t), intent(in) :: file  !! file handle
    h5_is_open = file%id >= 0
  end function h5_is_open

  ! ============================================================== groups and links

  !> Create a group and any missing intermediate groups. An existing group is not an error.
  subroutine h5_create_group(file, path, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! file open for writing
    character(len=*), intent(in) :: path       !! group path, e.g. '/gears/gear_1'
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    character(len=*), parameter :: op = 'h5_create_group'
    integer(hid_t) :: lcpl, gid
    integer :: hdferr
    logical :: ok

    call check_writable(file, op, path, stat, errmsg)
    if (stat /= 0) return
    lcpl = no_id
    gid = no_id
    steps: block
      if (h5_exists(file, path)) then
        call h5gopen_f(file%id, trim(path), gid, hdferr)
        if (hdferr < 0) call fail(stat, errmsg, op, 'an object that is not a group exists at', path, file)
        exit steps
      end if
      call make_lcpl(lcpl, hdferr)
      if (hdferr < 0) then
        call fail(stat, errmsg, op, 'cannot make a link-creation property list for', path, file)
        exit steps
      end if
      call h5gcreate_f(file%id, trim(path), gid, hdferr, lcpl_id=lcpl)
      if (hdferr < 0) call fail(stat, errmsg, op, 'cannot create group', path, file)
    end block steps
    ok = .true.
    call release(gid, ok)
    call release(lcpl, ok)
    if (stat == 0 .and. .not. ok) call fail(stat, errmsg, op, 'cannot release HDF5 handles of', path, file)
  end subroutine h5_create_group

  !> True when a link `path` exists in the file. Every component of the path is probed in turn,
  !! so a missing parent gives .false. rather than an error. The root ('/' or '') always exists.
  !! False when the file is not open.
  logical function h5_exists(file, path)
    type(h5_file_t), intent(in) :: file   !! open file
    character(len=*), intent(in) :: path  !! object path, absolute or relative to the root
    integer :: first, last, pos, k, hdferr
    logical :: found

    h5_exists = .false.
    if (.not. h5_is_open(file)) return
    last = len_trim(path)
    do while (last > 0)                          ! drop trailing slashes
      if (path(last:last) /= '/') exit
      last = last - 1
    end do
    h5_exists = .true.
    if (last == 0) return                        ! the root group
    first = verify(path(1:last), '/')            ! first character after leading slashes
    pos = first
    do                                           ! parents 'a', 'a/b' of 'a/b/c'
      k = index(path(pos:last), '/')
      if (k == 0) exit
      if (k > 1) then                            ! skip empty components ('a//b')
        call h5lexists_f(file%id, path(first:pos+k-2), found, hdferr)
        if (hdferr < 0 .or. .not. found) then
          h5_exists = .false.
          return
        end if
      end if
      pos = pos + k
    end do
    call h5lexists_f(file%id, path(first:last), found, hdferr)
    h5_exists = hdferr >= 0 .and. found
  end function h5_exists

  ! ============================================================== dataset writers

  !> Write a real scalar.
  subroutine write_real_0d(file, path, value, units, stat, errmsg, description)
    type(h5_file_t), intent(in) :: file                 !! file open for writing
    character(len=*), intent(in) :: path                !! dataset path
    real(wp), intent(in) :: value                       !! value [units]
    character(len=*), intent(in) :: units               !! units attribute, '-' if dimensionless
    integer, intent(out) :: stat                        !! 0 on success
    character(len=*), intent(inout) :: errmsg           !! set on failure
    character(len=*), intent(in), optional :: description  !! description attribute
    integer(hsize_t) :: dims(0)
    integer(hid_t) :: dset
    integer :: hdferr

    call begin_dataset(file, path, H5T_IEEE_F64LE, dims, dset, stat, errmsg)
    if (stat /= 0) return
    call h5dwrite_f(dset, real_type(), value, [1_hsize_t], hdferr)
    call end_dataset(file, path, dset, hdferr, units, description, stat, errmsg)
  end subroutine write_real_0d

  !> Write a real 1-D array.
  subroutine write_real_1d(file, path, value, units, stat, errmsg, description)
    type(h5_file_t), intent(in) :: file                 !! file open for writing
    character(len=*), intent(in) :: path                !! dataset path
    real(wp), intent(in) :: value(:)                    !! values [units]
    character(len=*), intent(in) :: units               !! units attribute, '-' if dimensionless
    integer, intent(out) :: stat                        !! 0 on success
    character(len=*), intent(inout) :: errmsg           !! set on failure
    character(len=*), intent(in), optional :: description  !! description attribute
    integer(hsize_t) :: dims(1)
    integer(hid_t) :: dset
    integer :: hdferr

    dims = shape(value, kind=hsize_t)
    call begin_dataset(file, path, H5T_IEEE_F64LE, dims, dset, stat, errmsg)
    if (stat /= 0) return
    hdferr = 0
    if (size(value) > 0) call h5dwrite_f(dset, real_type(), value, dims, hdferr)
    call end_dataset(file, path, dset, hdferr, units, description, stat, errmsg)
  end subroutine write_real_1d

  !> Write a real 2-D array a(n1, n2); h5py sees shape (n2, n1).
  subroutine write_real_2d(file, path, value, units, stat, errmsg, description)
    type(h5_file_t), intent(in) :: file                 !! file open for writing
    character(len=*), intent(in) :: path                !! dataset path
    real(wp), intent(in) :: value(:, :)                 !! values [units]
    character(len=*), intent(in) :: units               !! units attribute, '-' if dimensionless
    integer, intent(out) :: stat                        !! 0 on success
    character(len=*), intent(inout) :: errmsg           !! set on failure
    character(len=*), intent(in), optional :: description  !! description attribute
    integer(hsize_t) :: dims(2)
    integer(hid_t) :: dset
    integer :: hdferr

    dims = shape(value, kind=hsize_t)
    call begin_dataset(file, path, H5T_IEEE_F64LE, dims, dset, stat, errmsg)
    if (stat /= 0) return
    hdferr = 0
    if (size(value) > 0) call h5dwrite_f(dset, real_type(), value, dims, hdferr)
    call end_dataset(file, path, dset, hdferr, units, description, stat, errmsg)
  end subroutine write_real_2d

  !> Write a real 3-D array a(n1, n2, n3); h5py sees shape (n3, n2, n1).
  subroutine write_real_3d(file, path, value, units, stat, errmsg, description)
    type(h5_file_t), intent(in) :: file                 !! file open for writing
    character(len=*), intent(in) :: path                !! dataset path
    real(wp), intent(in) :: value(:, :, :)              !! values [units]
    character(len=*), intent(in) :: units               !! units attribute, '-' if dimensionless
    integer, intent(out) :: stat                        !! 0 on success
    character(len=*), intent(inout) :: errmsg           !! set on failure
    character(len=*), intent(in), optional :: description  !! description attribute
    integer(hsize_t) :: dims(3)
    integer(hid_t) :: dset
    integer :: hdferr

    dims = shape(value, kind=hsize_t)
    call begin_dataset(file, path, H5T_IEEE_F64LE, dims, dset, stat, errmsg)
    if (stat /= 0) return
    hdferr = 0
    if (size(value) > 0) call h5dwrite_f(dset, real_type(), value, dims, hdferr)
    call end_dataset(file, path, dset, hdferr, units, description, stat, errmsg)
  end subroutine write_real_3d

  !> Write an integer scalar.
  subroutine write_int_0d(file, path, value, units, stat, errmsg, description)
    type(h5_file_t), intent(in) :: file                 !! file open for writing
    character(len=*), intent(in) :: path                !! dataset path
    integer(ip), intent(in) :: value                    !! value [units]
    character(len=*), intent(in) :: units               !! units attribute, '-' if dimensionless
    integer, intent(out) :: stat                        !! 0 on success
    character(len=*), intent(inout) :: errmsg           !! set on failure
    character(len=*), intent(in), optional :: description  !! description attribute
    integer(hsize_t) :: dims(0)
    integer(hid_t) :: dset
    integer :: hdferr

    call begin_dataset(file, path, H5T_STD_I32LE, dims, dset, stat, errmsg)
    if (stat /= 0) return
    call h5dwrite_f(dset, int_type(), value, [1_hsize_t], hdferr)
    call end_dataset(file, path, dset, hdferr, units, description, stat, errmsg)
  end subroutine write_int_0d

  !> Write an integer 1-D array.
  subroutine write_int_1d(file, path, value, units, stat, errmsg, description)
    type(h5_file_t), intent(in) :: file                 !! file open for writing
    character(len=*), intent(in) :: path                !! dataset path
    integer(ip), intent(in) :: value(:)                 !! values [units]
    character(len=*), intent(in) :: units               !! units attribute, '-' if dimensionless
    integer, intent(out) :: stat                        !! 0 on success
    character(len=*), intent(inout) :: errmsg           !! set on failure
    character(len=*), intent(in), optional :: description  !! description attribute
    integer(hsize_t) :: dims(1)
    integer(hid_t) :: dset
    integer :: hdferr

    dims = shape(value, kind=hsize_t)
    call begin_dataset(file, path, H5T_STD_I32LE, dims, dset, stat, errmsg)
    if (stat /= 0) return
    hdferr = 0
    if (size(value) > 0) call h5dwrite_f(dset, int_type(), value, dims, hdferr)
    call end_dataset(file, path, dset, hdferr, units, description, stat, errmsg)
  end subroutine write_int_1d

  !> Write an integer 2-D array a(n1, n2); h5py sees shape (n2, n1).
  subroutine write_int_2d(file, path, value, units, stat, errmsg, description)
    type(h5_file_t), intent(in) :: file                 !! file open for writing
    character(len=*), intent(in) :: path                !! dataset path
    integer(ip), intent(in) :: value(:, :)              !! values [units]
    character(len=*), intent(in) :: units               !! units attribute, '-' if dimensionless
    integer, intent(out) :: stat                        !! 0 on success
    character(len=*), intent(inout) :: errmsg           !! set on failure
    character(len=*), intent(in), optional :: description  !! description attribute
    integer(hsize_t) :: dims(2)
    integer(hid_t) :: dset
    integer :: hdferr

    dims = shape(value, kind=hsize_t)
    call begin_dataset(file, path, H5T_STD_I32LE, dims, dset, stat, errmsg)
    if (stat /= 0) return
    hdferr = 0
    if (size(value) > 0) call h5dwrite_f(dset, int_type(), value, dims, hdferr)
    call end_dataset(file, path, dset, hdferr, units, description, stat, errmsg)
  end subroutine write_int_2d

  !> Write a logical scalar as integer 0/1 with the attribute "type" = "logical".
  subroutine write_logical_0d(file, path, value, units, stat, errmsg, description)
    type(h5_file_t), intent(in) :: file                 !! file open for writing
    character(len=*), intent(in) :: path                !! dataset path
    logical, intent(in) :: value                        !! value
    character(len=*), intent(in) :: units               !! units attribute, normally '-'
    integer, intent(out) :: stat                        !! 0 on success
    character(len=*), intent(inout) :: errmsg           !! set on failure
    character(len=*), intent(in), optional :: description  !! description attribute

    call write_int_0d(file, path, merge(1_ip, 0_ip, value), units, stat, errmsg, description)
    if (stat /= 0) return
    call write_attr_string(file, path, 'type', 'logical', stat, errmsg)
  end subroutine write_logical_0d

  !> Write a string scalar (fixed length, trailing blanks dropped).
  subroutine write_string_0d(file, path, value, units, stat, errmsg, description)
    type(h5_file_t), intent(in) :: file                 !! file open for writing
    character(len=*), intent(in) :: path                !! dataset path
    character(len=*), intent(in) :: value               !! value
    character(len=*), intent(in) :: units               !! units attribute, normally '-'
    integer, intent(out) :: stat                        !! 0 on success
    character(len=*), intent(inout) :: errmsg           !! set on failure
    character(len=*), intent(in), optional :: description  !! description attribute
    integer(hsize_t) :: dims(0)
    integer(hid_t) :: dset, ftype, mtype
    integer :: hdferr
    logical :: ok

    stat = 0
    ftype = no_id
    mtype = no_id
    call file_string_type(len_trim(value), ftype, hdferr)
    if (hdferr >= 0) call mem_string_type(len(value), mtype, hdferr)
    if (hdferr < 0) then
      call fail(stat, errmsg, 'h5_write', 'cannot make a string datatype for', path, file)
    else
      call begin_dataset(file, path, ftype, dims, dset, stat, errmsg)
      if (stat == 0) then
        if (len(value) > 0) then
          call h5dwrite_f(dset, mtype, value, [1_hsize_t], hdferr)
        else
          call h5dwrite_f(dset, mtype, ' ', [1_hsize_t], hdferr)
        end if
        call end_dataset(file, path, dset, hdferr, units, description, stat, errmsg)
      end if
    end if
    ok = .true.
    call release(ftype, ok)
    call release(mtype, ok)
    if (stat == 0 .and. .not. ok) call fail(stat, errmsg, 'h5_write', 'cannot release the string datatypes of', &
      path, file)
  end subroutine write_string_0d

  !> Write a 1-D array of strings (fixed length = longest trimmed value, trailing blanks dropped).
  subroutine write_string_1d(file, path, value, units, stat, errmsg, description)
    type(h5_file_t), intent(in) :: file                 !! file open for writing
    character(len=*), intent(in) :: path                !! dataset path
    character(len=*), intent(in) :: value(:)            !! values
    character(len=*), intent(in) :: units               !! units attribute, normally '-'
    integer, intent(out) :: stat                        !! 0 on success
    character(len=*), intent(inout) :: errmsg           !! set on failure
    character(len=*), intent(in), optional :: description  !! description attribute
    integer(hsize_t) :: dims(1)
    integer(hid_t) :: dset, ftype, mtype
    integer :: hdferr
    logical :: ok
    character(len=1) :: blanks(size(value))

    stat = 0
    ftype = no_id
    mtype = no_id
    dims = shape(value, kind=hsize_t)
    call file_string_type(maxval(len_trim(value)), ftype, hdferr)
    if (hdferr >= 0) call mem_string_type(len(value), mtype, hdferr)
    if (hdferr < 0) then
      call fail(stat, errmsg, 'h5_write', 'cannot make a string datatype for', path, file)
    else
      call begin_dataset(file, path, ftype, dims, dset, stat, errmsg)
      if (stat == 0) then
        hdferr = 0
        if (size(value) > 0 .and. len(value) > 0) then
          call h5dwrite_f(dset, mtype, value, dims, hdferr)
        else if (size(value) > 0) then
          blanks = ' '
          call h5dwrite_f(dset, mtype, blanks, dims, hdferr)
        end if
        call end_dataset(file, path, dset, hdferr, units, description, stat, errmsg)
      end if
    end if
    ok = .true.
    call release(ftype, ok)
    call release(mtype, ok)
    if (stat == 0 .and. .not. ok) call fail(stat, errmsg, 'h5_write', 'cannot release the string datatypes of', &
      path, file)
  end subroutine write_string_1d

  ! ============================================================== attribute writers

  !> Write (or replace) a string attribute on the group or dataset `obj_path`.
  subroutine write_attr_string(file, obj_path, name, value, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! file open for writing
    character(len=*), intent(in) :: obj_path   !! group or dataset path ('/' for the root group)
    character(len=*), intent(in) :: name       !! attribute name
    character(len=*), intent(in) :: value      !! attribute value
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer(hid_t) :: obj
    integer :: hdferr

    call open_object(file, obj_path, name, obj, stat, errmsg)
    if (stat /= 0) return
    call put_attr_string(obj, name, value, hdferr)
    call close_object(file, obj_path, name, obj, hdferr, stat, errmsg)
  end subroutine write_attr_string

  !> Write (or replace) a real scalar attribute on the group or dataset `obj_path`.
  subroutine write_attr_real(file, obj_path, name, value, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! file open for writing
    character(len=*), intent(in) :: obj_path   !! group or dataset path ('/' for the root group)
    character(len=*), intent(in) :: name       !! attribute name
    real(wp), intent(in) :: value              !! attribute value [as documented by the caller]
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer(hid_t) :: obj, space, attr
    integer :: hdferr
    logical :: ok

    call open_object(file, obj_path, name, obj, stat, errmsg)
    if (stat /= 0) return
    space = no_id
    attr = no_id
    call new_attribute(obj, name, H5T_IEEE_F64LE, space, attr, hdferr)
    if (hdferr >= 0) call h5awrite_f(attr, real_type(), value, [1_hsize_t], hdferr)
    ok = .true.
    call release(attr, ok)
    call release(space, ok)
    if (.not. ok .and. hdferr >= 0) hdferr = -1
    call close_object(file, obj_path, name, obj, hdferr, stat, errmsg)
  end subroutine write_attr_real

  !> Write (or replace) an integer scalar attribute on the group or dataset `obj_path`.
  subroutine write_attr_int(file, obj_path, name, value, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! file open for writing
    character(len=*), intent(in) :: obj_path   !! group or dataset path ('/' for the root group)
    character(len=*), intent(in) :: name       !! attribute name
    integer(ip), intent(in) :: value           !! attribute value
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer(hid_t) :: obj, space, attr
    integer :: hdferr
    logical :: ok

    call open_object(file, obj_path, name, obj, stat, errmsg)
    if (stat /= 0) return
    space = no_id
    attr = no_id
    call new_attribute(obj, name, H5T_STD_I32LE, space, attr, hdferr)
    if (hdferr >= 0) call h5awrite_f(attr, int_type(), value, [1_hsize_t], hdferr)
    ok = .true.
    call release(attr, ok)
    call release(space, ok)
    if (.not. ok .and. hdferr >= 0) hdferr = -1
    call close_object(file, obj_path, name, obj, hdferr, stat, errmsg)
  end subroutine write_attr_int

  ! ============================================================== dataset readers

  !> Read a real scalar dataset.
  subroutine read_real_0d(file, path, value, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: path       !! dataset path
    real(wp), intent(out) :: value             !! value [units attribute]
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer(hid_t) :: dset
    integer(hsize_t) :: dims(max_rank)
    integer :: hdferr

    value = 0.0_wp
    call open_dataset(file, path, H5T_FLOAT_F, 0, dset, dims, stat, errmsg)
    if (stat /= 0) return
    call h5dread_f(dset, real_type(), value, [1_hsize_t], hdferr)
    call end_read(file, path, dset, hdferr, stat, errmsg)
  end subroutine read_real_0d

  !> Read a real 1-D dataset.
  subroutine read_real_1d(file, path, value, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: path       !! dataset path
    real(wp), allocatable, intent(out) :: value(:)  !! values, shape from the file [units attribute]
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer(hid_t) :: dset
    integer(hsize_t) :: dims(max_rank)
    integer :: hdferr

    call open_dataset(file, path, H5T_FLOAT_F, 1, dset, dims, stat, errmsg)
    if (stat /= 0) return
    allocate(value(dims(1)))
    hdferr = 0
    if (size(value) > 0) call h5dread_f(dset, real_type(), value, dims, hdferr)
    call end_read(file, path, dset, hdferr, stat, errmsg)
  end subroutine read_real_1d

  !> Read a real 2-D dataset (h5py shape (n2, n1) comes back as value(n1, n2)).
  subroutine read_real_2d(file, path, value, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: path       !! dataset path
    real(wp), allocatable, intent(out) :: value(:, :)  !! values, shape from the file [units attribute]
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer(hid_t) :: dset
    integer(hsize_t) :: dims(max_rank)
    integer :: hdferr

    call open_dataset(file, path, H5T_FLOAT_F, 2, dset, dims, stat, errmsg)
    if (stat /= 0) return
    allocate(value(dims(1), dims(2)))
    hdferr = 0
    if (size(value) > 0) call h5dread_f(dset, real_type(), value, dims, hdferr)
    call end_read(file, path, dset, hdferr, stat, errmsg)
  end subroutine read_real_2d

  !> Read a real 3-D dataset (h5py shape (n3, n2, n1) comes back as value(n1, n2, n3)).
  subroutine read_real_3d(file, path, value, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: path       !! dataset path
    real(wp), allocatable, intent(out) :: value(:, :, :)  !! values, shape from the file [units attribute]
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer(hid_t) :: dset
    integer(hsize_t) :: dims(max_rank)
    integer :: hdferr

    call open_dataset(file, path, H5T_FLOAT_F, 3, dset, dims, stat, errmsg)
    if (stat /= 0) return
    allocate(value(dims(1), dims(2), dims(3)))
    hdferr = 0
    if (size(value) > 0) call h5dread_f(dset, real_type(), value, dims, hdferr)
    call end_read(file, path, dset, hdferr, stat, errmsg)
  end subroutine read_real_3d

  !> Read an integer scalar dataset.
  subroutine read_int_0d(file, path, value, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: path       !! dataset path
    integer(ip), intent(out) :: value          !! value [units attribute]
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer(hid_t) :: dset
    integer(hsize_t) :: dims(max_rank)
    integer :: hdferr

    value = 0_ip
    call open_dataset(file, path, H5T_INTEGER_F, 0, dset, dims, stat, errmsg)
    if (stat /= 0) return
    call h5dread_f(dset, int_type(), value, [1_hsize_t], hdferr)
    call end_read(file, path, dset, hdferr, stat, errmsg)
  end subroutine read_int_0d

  !> Read an integer 1-D dataset.
  subroutine read_int_1d(file, path, value, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: path       !! dataset path
    integer(ip), allocatable, intent(out) :: value(:)  !! values, shape from the file [units attribute]
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer(hid_t) :: dset
    integer(hsize_t) :: dims(max_rank)
    integer :: hdferr

    call open_dataset(file, path, H5T_INTEGER_F, 1, dset, dims, stat, errmsg)
    if (stat /= 0) return
    allocate(value(dims(1)))
    hdferr = 0
    if (size(value) > 0) call h5dread_f(dset, int_type(), value, dims, hdferr)
    call end_read(file, path, dset, hdferr, stat, errmsg)
  end subroutine read_int_1d

  !> Read an integer 2-D dataset (h5py shape (n2, n1) comes back as value(n1, n2)).
  subroutine read_int_2d(file, path, value, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: path       !! dataset path
    integer(ip), allocatable, intent(out) :: value(:, :)  !! values, shape from the file [units attribute]
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer(hid_t) :: dset
    integer(hsize_t) :: dims(max_rank)
    integer :: hdferr

    call open_dataset(file, path, H5T_INTEGER_F, 2, dset, dims, stat, errmsg)
    if (stat /= 0) return
    allocate(value(dims(1), dims(2)))
    hdferr = 0
    if (size(value) > 0) call h5dread_f(dset, int_type(), value, dims, hdferr)
    call end_read(file, path, dset, hdferr, stat, errmsg)
  end subroutine read_int_2d

  !> Read a logical scalar (an integer scalar dataset; nonzero is .true.).
  subroutine read_logical_0d(file, path, value, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: path       !! dataset path
    logical, intent(out) :: value              !! value
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer(ip) :: ivalue

    call read_int_0d(file, path, ivalue, stat, errmsg)
    value = ivalue /= 0_ip
  end subroutine read_logical_0d

  !> Read a fixed-length string scalar dataset; trailing blanks are removed.
  subroutine read_string_0d(file, path, value, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: path       !! dataset path
    character(len=:), allocatable, intent(out) :: value  !! value
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer(hid_t) :: dset, ftype, mtype
    integer(hsize_t) :: dims(max_rank)
    integer :: hdferr, nchar
    logical :: ok

    value = ''
    call open_dataset(file, path, H5T_STRING_F, 0, dset, dims, stat, errmsg)
    if (stat /= 0) return
    ftype = no_id
    mtype = no_id
    call h5dget_type_f(dset, ftype, hdferr)
    if (hdferr >= 0) call fixed_string_length(ftype, nchar, hdferr)
    if (hdferr >= 0) call mem_string_type(nchar, mtype, hdferr)
    if (hdferr >= 0) then
      deallocate(value)
      allocate(character(len=nchar) :: value)
      call h5dread_f(dset, mtype, value, [1_hsize_t], hdferr)
      value = trim(value)
    end if
    ok = .true.
    call release(ftype, ok)
    call release(mtype, ok)
    if (.not. ok .and. hdferr >= 0) hdferr = -1
    call end_read(file, path, dset, hdferr, stat, errmsg)
  end subroutine read_string_0d

  !> Read a 1-D fixed-length string dataset into the caller's `character(len=L), allocatable ::
  !! value(:)`; values come back blank-padded to L. Fails (no silent truncation) if a stored
  !! value is longer than L. (A fixed length, rather than character(len=:), because gfortran 12
  !! warns spuriously at every call with a deferred-length allocatable array.)
  subroutine read_string_1d(file, path, value, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: path       !! dataset path
    character(len=*), allocatable, intent(out) :: value(:)  !! values, blank-padded
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer(hid_t) :: dset, ftype, mtype
    integer(hsize_t) :: dims(max_rank)
    integer :: hdferr, nchar
    logical :: ok

    call open_dataset(file, path, H5T_STRING_F, 1, dset, dims, stat, errmsg)
    if (stat /= 0) return
    ftype = no_id
    mtype = no_id
    call h5dget_type_f(dset, ftype, hdferr)
    if (hdferr >= 0) call fixed_string_length(ftype, nchar, hdferr)
    if (hdferr >= 0 .and. nchar > len(value)) then
      call fail(stat, errmsg, 'h5_read', 'strings of '//int_str(nchar)//' characters do not fit in '// &
        'character(len='//int_str(len(value))//'), dataset', path, file)
    else
      if (hdferr >= 0) call mem_string_type(len(value), mtype, hdferr)
      if (hdferr >= 0) then
        allocate(value(dims(1)))
        if (size(value) > 0) call h5dread_f(dset, mtype, value, dims, hdferr)
      end if
    end if
    ok = .true.
    call release(ftype, ok)
    call release(mtype, ok)
    if (stat /= 0) then
      call release(dset, ok)
      return
    end if
    if (.not. ok .and. hdferr >= 0) hdferr = -1
    call end_read(file, path, dset, hdferr, stat, errmsg)
  end subroutine read_string_1d

  ! ============================================================== attribute readers

  !> Read a fixed-length string attribute; trailing blanks are removed.
  subroutine read_attr_string(file, obj_path, name, value, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: obj_path   !! group or dataset path
    character(len=*), intent(in) :: name       !! attribute name
    character(len=:), allocatable, intent(out) :: value  !! value
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer(hid_t) :: attr, ftype, mtype
    integer :: hdferr, nchar
    logical :: ok

    value = ''
    call open_attribute(file, obj_path, name, H5T_STRING_F, attr, stat, errmsg)
    if (stat /= 0) return
    ftype = no_id
    mtype = no_id
    call h5aget_type_f(attr, ftype, hdferr)
    if (hdferr >= 0) call fixed_string_length(ftype, nchar, hdferr)
    if (hdferr >= 0) call mem_string_type(nchar, mtype, hdferr)
    if (hdferr >= 0) then
      deallocate(value)
      allocate(character(len=nchar) :: value)
      call h5aread_f(attr, mtype, value, [1_hsize_t], hdferr)
      value = trim(value)
    end if
    ok = .true.
    call release(ftype, ok)
    call release(mtype, ok)
    if (.not. ok .and. hdferr >= 0) hdferr = -1
    call end_attr_read(file, obj_path, name, attr, hdferr, stat, errmsg)
  end subroutine read_attr_string

  !> Read a real scalar attribute.
  subroutine read_attr_real(file, obj_path, name, value, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: obj_path   !! group or dataset path
    character(len=*), intent(in) :: name       !! attribute name
    real(wp), intent(out) :: value             !! value
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer(hid_t) :: attr
    integer :: hdferr

    value = 0.0_wp
    call open_attribute(file, obj_path, name, H5T_FLOAT_F, attr, stat, errmsg)
    if (stat /= 0) return
    call h5aread_f(attr, real_type(), value, [1_hsize_t], hdferr)
    call end_attr_read(file, obj_path, name, attr, hdferr, stat, errmsg)
  end subroutine read_attr_real

  !> Read an integer scalar attribute.
  subroutine read_attr_int(file, obj_path, name, value, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: obj_path   !! group or dataset path
    character(len=*), intent(in) :: name       !! attribute name
    integer(ip), intent(out) :: value          !! value
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer(hid_t) :: attr
    integer :: hdferr

    value = 0_ip
    call open_attribute(file, obj_path, name, H5T_INTEGER_F, attr, stat, errmsg)
    if (stat /= 0) return
    call h5aread_f(attr, int_type(), value, [1_hsize_t], hdferr)
    call end_attr_read(file, obj_path, name, attr, hdferr, stat, errmsg)
  end subroutine read_attr_int

  ! ============================================================== plain files

  !> Rename (move) a file with C rename(3): atomic within one file system, replaces an existing
  !! `to`; fails across file systems. Use it to publish a result file written under a temporary
  !! name in the same directory.
  subroutine rename_file(from, to, stat, errmsg)
    character(len=*), intent(in) :: from       !! existing file name
    character(len=*), intent(in) :: to         !! new file name
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    logical :: exists

    stat = 0
    if (c_rename(trim(from)//c_null_char, trim(to)//c_null_char) == 0_c_int) return
    stat = 1
    inquire(file=from, exist=exists)
    if (exists) then
      errmsg = "rename_file: cannot rename '"//trim(from)//"' to '"//trim(to)// &
        "' (target directory missing or not writable, or another file system?)"
    else
      errmsg = "rename_file: cannot rename '"//trim(from)//"' to '"//trim(to)//"': no such file"
    end if
  end subroutine rename_file

  !> Delete a file with C remove(3). A file that does not exist is not an error.
  subroutine delete_file(path, stat, errmsg)
    character(len=*), intent(in) :: path                 !! file name
    integer, intent(out) :: stat                         !! 0 on success
    character(len=*), intent(inout), optional :: errmsg  !! set on failure
    logical :: exists

    stat = 0
    inquire(file=path, exist=exists)
    if (.not. exists) return
    if (c_remove(trim(path)//c_null_char) == 0_c_int) return
    stat = 1
    if (present(errmsg)) errmsg = "delete_file: cannot delete '"//trim(path)//"'"
  end subroutine delete_file

  ! ============================================================== files published whole

  !> Create `path`.partial for writing. Write the contents, then call h5_commit_partial with
  !! their status: the file appears under `path` only when it is complete, so a write that
  !! fails or is killed leaves nothing that looks like a result.
  subroutine h5_create_partial(file, path, stat, errmsg)
    type(h5_file_t), intent(inout) :: file     !! must not be open; open on `path`.partial afterwards
    character(len=*), intent(in) :: path       !! final file name
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    call h5_create(file, trim(path)//'.partial', stat, errmsg)
  end subroutine h5_create_partial

  !> Finish a file begun with h5_create_partial: with stat = 0 on entry (contents written), close
  !! it and rename `path`.partial to `path`; otherwise (or when closing or renaming fails) close
  !! it and delete `path`.partial, keeping the caller's stat and errmsg.
  subroutine h5_commit_partial(file, path, stat, errmsg)
    type(h5_file_t), intent(inout) :: file     !! opened by h5_create_partial; closed afterwards
    character(len=*), intent(in) :: path       !! final file name, as given to h5_create_partial
    integer, intent(inout) :: stat             !! in: status of writing the contents; out: 0 when published
    character(len=*), intent(inout) :: errmsg  !! set on failure (kept when stat /= 0 on entry)
    character(len=:), allocatable :: tmp
    integer :: st2
    character(len=msg_len) :: m2
    tmp = trim(path)//'.partial'
    if (stat /= 0) then
      call h5_close(file, st2, m2)
      call delete_file(tmp, st2, m2)
      return
    end if
    call h5_close(file, stat, errmsg)
    if (stat /= 0) then
      call delete_file(tmp, st2, m2)
      return
    end if
    call rename_file(tmp, trim(path), stat, errmsg)
    if (stat /= 0) call delete_file(tmp, st2, m2)
  end subroutine h5_commit_partial

  ! ============================================================== private helpers

  !> Initialise the HDF5 Fortran interface unless it is already (the Fortran predefined datatype
  !! ids are live exactly when h5open_f has run and h5close_f has not), then silence the
  !! automatic error-stack printing. Calling h5open_f again would leak its datatype copies.
  subroutine init_library(hdferr)
    integer, intent(out) :: hdferr  !! 0 on success, negative on failure
    logical :: ready

    call h5iis_valid_f(H5T_NATIVE_DOUBLE, ready, hdferr)
    if (hdferr < 0 .or. .not. ready) call h5open_f(hdferr)
    if (hdferr < 0) return
    call h5eset_auto_f(0, hdferr)
  end subroutine init_library

  !> Memory datatype of real(wp).
  integer(hid_t) function real_type()
    real_type = h5kind_to_type(wp, H5_REAL_KIND)
  end function real_type

  !> Memory datatype of integer(ip).
  integer(hid_t) function int_type()
    int_type = h5kind_to_type(ip, H5_INTEGER_KIND)
  end function int_type

  !> Link-creation property list that creates missing intermediate groups.
  subroutine make_lcpl(lcpl, hdferr)
    integer(hid_t), intent(out) :: lcpl  !! new property list (no_id on failure)
    integer, intent(out) :: hdferr       !! negative on failure
    logical :: ok

    call h5pcreate_f(H5P_LINK_CREATE_F, lcpl, hdferr)
    if (hdferr < 0) then
      lcpl = no_id
      return
    end if
    call h5pset_create_inter_group_f(lcpl, 1, hdferr)
    if (hdferr < 0) then
      ok = .true.
      call release(lcpl, ok)
    end if
  end subroutine make_lcpl

  !> File datatype of a fixed-length string: ASCII, null-padded (as h5py/NumPy write 'S' data),
  !! `nchar` characters (at least 1).
  subroutine file_string_type(nchar, ftype, hdferr)
    integer, intent(in) :: nchar          !! characters stored per element
    integer(hid_t), intent(out) :: ftype  !! new datatype (no_id on failure)
    integer, intent(out) :: hdferr        !! negative on failure
    logical :: ok

    call h5tcopy_f(H5T_C_S1, ftype, hdferr)
    if (hdferr < 0) then
      ftype = no_id
      return
    end if
    call h5tset_size_f(ftype, int(max(1, nchar), size_t), hdferr)
    if (hdferr >= 0) call h5tset_strpad_f(ftype, H5T_STR_NULLPAD_F, hdferr)
    if (hdferr < 0) then
      ok = .true.
      call release(ftype, ok)
    end if
  end subroutine file_string_type

  !> Memory datatype of a Fortran character(len=nchar) variable: blank-padded, at least 1
  !! character. HDF5's conversion to and from the file type drops trailing blanks on writing and
  !! blank-pads on reading.
  subroutine mem_string_type(nchar, mtype, hdferr)
    integer, intent(in) :: nchar          !! length of the Fortran variable
    integer(hid_t), intent(out) :: mtype  !! new datatype (no_id on failure)
    integer, intent(out) :: hdferr        !! negative on failure
    logical :: ok

    call h5tcopy_f(H5T_FORTRAN_S1, mtype, hdferr)
    if (hdferr < 0) then
      mtype = no_id
      return
    end if
    call h5tset_size_f(mtype, int(max(1, nchar), size_t), hdferr)
    if (hdferr >= 0) call h5tset_strpad_f(mtype, H5T_STR_SPACEPAD_F, hdferr)
    if (hdferr < 0) then
      ok = .true.
      call release(mtype, ok)
    end if
  end subroutine mem_string_type

  !> Length of a fixed-length string datatype; hdferr = vlen_string for variable-length strings.
  subroutine fixed_string_length(tid, nchar, hdferr)
    integer(hid_t), intent(in) :: tid  !! string datatype
    integer, intent(out) :: nchar      !! characters per element
    integer, intent(out) :: hdferr     !! negative on failure, vlen_string for variable length
    logical :: is_vlen
    integer(size_t) :: nbytes

    nchar = 0
    call h5tis_variable_str_f(tid, is_vlen, hdferr)
    if (hdferr < 0) return
    if (is_vlen) then
      hdferr = vlen_string
      return
    end if
    call h5tget_size_f(tid, nbytes, hdferr)
    if (hdferr >= 0) nchar = int(nbytes)
  end subroutine fixed_string_length

  !> Close an HDF5 handle this module opened, whatever its kind, and mark it closed.
  !! Does nothing for no_id. `ok` becomes .false. if closing failed.
  subroutine release(id, ok)
    integer(hid_t), intent(inout) :: id  !! handle; no_id afterwards
    logical, intent(inout) :: ok         !! cleared on failure
    integer :: id_type, hdferr

    if (id == no_id) return
    call h5iget_type_f(id, id_type, hdferr)
    if (hdferr >= 0) then
      if (id_type == H5I_DATASET_F) then
        call h5dclose_f(id, hdferr)
      else if (id_type == H5I_DATASPACE_F) then
        call h5sclose_f(id, hdferr)
      else if (id_type == H5I_DATATYPE_F) then
        call h5tclose_f(id, hdferr)
      else if (id_type == H5I_ATTR_F) then
        call h5aclose_f(id, hdferr)
      else if (id_type == H5I_GROUP_F) then
        call h5gclose_f(id, hdferr)
      else
        ! The only other handles made here are property lists. (Not tested against
        ! H5I_GENPROP_LST_F: the HDF5 1.10 Fortran interface leaves that constant 0.)
        call h5pclose_f(id, hdferr)
      end if
    end if
    if (hdferr < 0) ok = .false.
    id = no_id
  end subroutine release

  !> Fail unless `file` is open for writing.
  subroutine check_writable(file, op, path, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! file handle
    character(len=*), intent(in) :: op         !! public operation name
    character(len=*), intent(in) :: path       !! object path
    integer, intent(out) :: stat               !! 0 if writable
    character(len=*), intent(inout) :: errmsg  !! set on failure
    stat = 0
    if (.not. h5_is_open(file)) then
      stat = 1
      errmsg = op//": no file is open (object '"//trim(path)//"')"
    else if (.not. file%writable) then
      call fail(stat, errmsg, op, 'file is open read-only, cannot write', path, file)
    end if
  end subroutine check_writable

  !> Create the dataset `path` (missing groups included) with file datatype `ftype` and
  !! dimensions `dims` (Fortran order; size(dims) = 0 makes a scalar).
  subroutine begin_dataset(file, path, ftype, dims, dset, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! file open for writing
    character(len=*), intent(in) :: path       !! dataset path
    integer(hid_t), intent(in) :: ftype        !! file datatype
    integer(hsize_t), intent(in) :: dims(:)    !! extent, Fortran order
    integer(hid_t), intent(out) :: dset        !! new dataset (no_id on failure)
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    character(len=*), parameter :: op = 'h5_write'
    integer(hid_t) :: space, lcpl
    integer :: hdferr
    logical :: ok

    dset = no_id
    call check_writable(file, op, path, stat, errmsg)
    if (stat /= 0) return
    space = no_id
    lcpl = no_id
    steps: block
      if (h5_exists(file, path)) then
        call fail(stat, errmsg, op, 'an object already exists at', path, file)
        exit steps
      end if
      if (size(dims) == 0) then
        call h5screate_f(H5S_SCALAR_F, space, hdferr)
      else
        call h5screate_simple_f(size(dims), dims, space, hdferr)
      end if
      if (hdferr >= 0) call make_lcpl(lcpl, hdferr)
      if (hdferr < 0) then
        call fail(stat, errmsg, op, 'cannot make the dataspace for', path, file)
        exit steps
      end if
      call h5dcreate_f(file%id, trim(path), ftype, space, dset, hdferr, lcpl_id=lcpl)
      if (hdferr < 0) then
        dset = no_id
        call fail(stat, errmsg, op, 'cannot create dataset (is a parent a dataset?)', path, file)
      end if
    end block steps
    ok = .true.
    call release(space, ok)
    call release(lcpl, ok)
    if (stat == 0 .and. .not. ok) &
      call fail(stat, errmsg, op, 'cannot release HDF5 handles of', path, file)
    if (stat /= 0) call release(dset, ok)
  end subroutine begin_dataset

  !> Finish a dataset begun by begin_dataset: check the data write (`hdferr`), add the units and
  !! description attributes and close it.
  subroutine end_dataset(file, path, dset, hdferr, units, description, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! file open for writing
    character(len=*), intent(in) :: path       !! dataset path
    integer(hid_t), intent(inout) :: dset      !! dataset; closed on return
    integer, intent(in) :: hdferr              !! status of the data write
    character(len=*), intent(in) :: units      !! units attribute
    character(len=*), intent(in), optional :: description  !! description attribute
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    character(len=*), parameter :: op = 'h5_write'
    integer :: err
    logical :: ok

    stat = 0
    if (hdferr < 0) then
      call fail(stat, errmsg, op, 'cannot write the data of', path, file)
    else
      call put_attr_string(dset, 'units', units, err)
      if (err >= 0 .and. present(description)) call put_attr_string(dset, 'description', description, err)
      if (err < 0) call fail(stat, errmsg, op, 'cannot write the units/description attributes of', path, file)
    end if
    ok = .true.
    call release(dset, ok)
    if (stat == 0 .and. .not. ok) call fail(stat, errmsg, op, 'cannot close dataset', path, file)
  end subroutine end_dataset

  !> Open the dataset `path` for reading and check its type class and rank.
  subroutine open_dataset(file, path, want_class, want_rank, dset, dims, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: path       !! dataset path
    integer, intent(in) :: want_class          !! H5T_FLOAT_F, H5T_INTEGER_F or H5T_STRING_F
    integer, intent(in) :: want_rank           !! expected rank (0 = scalar)
    integer(hid_t), intent(out) :: dset        !! open dataset (no_id on failure)
    integer(hsize_t), intent(out) :: dims(max_rank)  !! extent, Fortran order (first want_rank used)
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    character(len=*), parameter :: op = 'h5_read'
    integer(hid_t) :: tid, space
    integer :: hdferr, type_class, rank
    logical :: ok

    stat = 0
    dset = no_id
    dims = 0
    if (.not. h5_is_open(file)) then
      stat = 1
      errmsg = op//": no file is open (dataset '"//trim(path)//"')"
      return
    end if
    tid = no_id
    space = no_id
    steps: block
      if (.not. h5_exists(file, path)) then
        call fail(stat, errmsg, op, 'no dataset', path, file)
        exit steps
      end if
      call h5dopen_f(file%id, trim(path), dset, hdferr)
      if (hdferr < 0) then
        dset = no_id
        call fail(stat, errmsg, op, 'not a dataset:', path, file)
        exit steps
      end if
      call h5dget_type_f(dset, tid, hdferr)
      if (hdferr >= 0) call h5tget_class_f(tid, type_class, hdferr)
      if (hdferr >= 0) call h5dget_space_f(dset, space, hdferr)
      if (hdferr >= 0) call query_extent(space, rank, dims, hdferr)
      if (hdferr < 0) then
        call fail(stat, errmsg, op, 'cannot query the datatype or dataspace of', path, file)
      else if (type_class /= want_class) then
        call fail(stat, errmsg, op, 'wrong datatype (expected '//class_name(want_class)// &
          ', found '//class_name(type_class)//') for', path, file)
      else if (rank /= want_rank) then
        call fail(stat, errmsg, op, 'wrong rank (expected '//int_str(want_rank)//', found '// &
          int_str(rank)//') for', path, file)
      end if
    end block steps
    ok = .true.
    call release(tid, ok)
    call release(space, ok)
    if (stat /= 0) call release(dset, ok)
  end subroutine open_dataset

  !> Rank and extent (Fortran order) of a dataspace; a scalar has rank 0, a null dataspace -1.
  subroutine query_extent(space, rank, dims, hdferr)
    integer(hid_t), intent(in) :: space              !! dataspace
    integer, intent(out) :: rank                     !! rank (0 scalar, -1 null)
    integer(hsize_t), intent(out) :: dims(max_rank)  !! extent, Fortran order
    integer, intent(out) :: hdferr                   !! negative on failure
    integer :: space_class
    integer(hsize_t) :: d(32), maxd(32)

    dims = 0
    rank = -1
    call h5sget_simple_extent_type_f(space, space_class, hdferr)
    if (hdferr < 0) return
    if (space_class == H5S_SCALAR_F) then
      rank = 0
      return
    end if
    call h5sget_simple_extent_ndims_f(space, rank, hdferr)
    if (hdferr < 0 .or. rank < 1 .or. rank > size(d)) return
    call h5sget_simple_extent_dims_f(space, d(1:rank), maxd(1:rank), hdferr)  ! hdferr = rank on success
    if (hdferr < 0) return
    hdferr = 0
    dims(1:min(rank, max_rank)) = d(1:min(rank, max_rank))
  end subroutine query_extent

  !> Finish a dataset read: check `hdferr` and close the dataset.
  subroutine end_read(file, path, dset, hdferr, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: path       !! dataset path
    integer(hid_t), intent(inout) :: dset      !! dataset; closed on return
    integer, intent(in) :: hdferr              !! status of the read
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    logical :: ok

    stat = 0
    if (hdferr == vlen_string) then
      call fail(stat, errmsg, 'h5_read', 'variable-length strings are not supported, dataset', path, file)
    else if (hdferr < 0) then
      call fail(stat, errmsg, 'h5_read', 'cannot read the data of', path, file)
    end if
    ok = .true.
    call release(dset, ok)
    if (stat == 0 .and. .not. ok) call fail(stat, errmsg, 'h5_read', 'cannot close dataset', path, file)
  end subroutine end_read

  !> Open the group or dataset `obj_path` to write the attribute `name` on it.
  subroutine open_object(file, obj_path, name, obj, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! file open for writing
    character(len=*), intent(in) :: obj_path   !! group or dataset path
    character(len=*), intent(in) :: name       !! attribute name (for messages)
    integer(hid_t), intent(out) :: obj         !! open object (no_id on failure)
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    integer :: hdferr

    obj = no_id
    call check_writable(file, 'h5_write_attr', attr_label(obj_path, name), stat, errmsg)
    if (stat /= 0) return
    if (.not. h5_exists(file, obj_path)) then
      call fail(stat, errmsg, 'h5_write_attr', 'no group or dataset for attribute', &
        attr_label(obj_path, name), file)
      return
    end if
    call h5oopen_f(file%id, trim(obj_path), obj, hdferr)
    if (hdferr < 0) then
      obj = no_id
      call fail(stat, errmsg, 'h5_write_attr', 'cannot open the object of attribute', &
        attr_label(obj_path, name), file)
    end if
  end subroutine open_object

  !> Close the object opened by open_object after an attribute write with status `hdferr`.
  subroutine close_object(file, obj_path, name, obj, hdferr, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! file open for writing
    character(len=*), intent(in) :: obj_path   !! group or dataset path
    character(len=*), intent(in) :: name       !! attribute name
    integer(hid_t), intent(inout) :: obj       !! object; closed on return
    integer, intent(in) :: hdferr              !! status of the attribute write
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    logical :: ok

    stat = 0
    if (hdferr < 0) call fail(stat, errmsg, 'h5_write_attr', 'cannot write attribute', &
      attr_label(obj_path, name), file)
    ok = .true.
    call release(obj, ok)
    if (stat == 0 .and. .not. ok) call fail(stat, errmsg, 'h5_write_attr', &
      'cannot close the object of attribute', attr_label(obj_path, name), file)
  end subroutine close_object

  !> Create the scalar attribute `name` of file type `ftype` on `obj`, deleting an existing one.
  subroutine new_attribute(obj, name, ftype, space, attr, hdferr)
    integer(hid_t), intent(in) :: obj       !! group or dataset
    character(len=*), intent(in) :: name    !! attribute name
    integer(hid_t), intent(in) :: ftype     !! file datatype
    integer(hid_t), intent(inout) :: space  !! new scalar dataspace (caller releases)
    integer(hid_t), intent(inout) :: attr   !! new attribute (caller releases)
    integer, intent(out) :: hdferr          !! negative on failure
    logical :: exists

    call h5aexists_f(obj, trim(name), exists, hdferr)
    if (hdferr < 0) return
    if (exists) call h5adelete_f(obj, trim(name), hdferr)
    if (hdferr < 0) return
    call h5screate_f(H5S_SCALAR_F, space, hdferr)
    if (hdferr < 0) then
      space = no_id
      return
    end if
    call h5acreate_f(obj, trim(name), ftype, space, attr, hdferr)
    if (hdferr < 0) attr = no_id
  end subroutine new_attribute

  !> Write (or replace) the string attribute `name` on the open object `obj`.
  subroutine put_attr_string(obj, name, value, hdferr)
    integer(hid_t), intent(in) :: obj      !! group or dataset
    character(len=*), intent(in) :: name   !! attribute name
    character(len=*), intent(in) :: value  !! attribute value
    integer, intent(out) :: hdferr         !! negative on failure
    integer(hid_t) :: ftype, mtype, space, attr
    logical :: ok

    ftype = no_id
    mtype = no_id
    space = no_id
    attr = no_id
    call file_string_type(len_trim(value), ftype, hdferr)
    if (hdferr >= 0) call mem_string_type(len(value), mtype, hdferr)
    if (hdferr >= 0) call new_attribute(obj, name, ftype, space, attr, hdferr)
    if (hdferr >= 0) then
      if (len(value) > 0) then
        call h5awrite_f(attr, mtype, value, [1_hsize_t], hdferr)
      else
        call h5awrite_f(attr, mtype, ' ', [1_hsize_t], hdferr)
      end if
    end if
    ok = .true.
    call release(attr, ok)
    call release(space, ok)
    call release(mtype, ok)
    call release(ftype, ok)
    if (.not. ok .and. hdferr >= 0) hdferr = -1
  end subroutine put_attr_string

  !> Open the scalar attribute `name` of `obj_path` for reading and check its type class.
  subroutine open_attribute(file, obj_path, name, want_class, attr, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: obj_path   !! group or dataset path
    character(len=*), intent(in) :: name       !! attribute name
    integer, intent(in) :: want_class          !! H5T_FLOAT_F, H5T_INTEGER_F or H5T_STRING_F
    integer(hid_t), intent(out) :: attr        !! open attribute (no_id on failure)
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    character(len=*), parameter :: op = 'h5_read_attr'
    integer(hid_t) :: tid, space
    integer(hsize_t) :: dims(max_rank)
    integer :: hdferr, type_class, rank
    logical :: ok

    stat = 0
    attr = no_id
    if (.not. h5_is_open(file)) then
      stat = 1
      errmsg = op//": no file is open (attribute '"//attr_label(obj_path, name)//"')"
      return
    end if
    if (.not. h5_exists(file, obj_path)) then
      call fail(stat, errmsg, op, 'no group or dataset for attribute', attr_label(obj_path, name), file)
      return
    end if
    tid = no_id
    space = no_id
    steps: block
      call h5aopen_by_name_f(file%id, trim(obj_path), trim(name), attr, hdferr)
      if (hdferr < 0) then
        attr = no_id
        call fail(stat, errmsg, op, 'no attribute', attr_label(obj_path, name), file)
        exit steps
      end if
      call h5aget_type_f(attr, tid, hdferr)
      if (hdferr >= 0) call h5tget_class_f(tid, type_class, hdferr)
      if (hdferr >= 0) call h5aget_space_f(attr, space, hdferr)
      if (hdferr >= 0) call query_extent(space, rank, dims, hdferr)
      if (hdferr < 0) then
        call fail(stat, errmsg, op, 'cannot query the datatype or dataspace of attribute', &
          attr_label(obj_path, name), file)
      else if (type_class /= want_class) then
        call fail(stat, errmsg, op, 'wrong datatype (expected '//class_name(want_class)// &
          ', found '//class_name(type_class)//') for attribute', attr_label(obj_path, name), file)
      else if (rank /= 0) then
        call fail(stat, errmsg, op, 'not a scalar attribute:', attr_label(obj_path, name), file)
      end if
    end block steps
    ok = .true.
    call release(tid, ok)
    call release(space, ok)
    if (stat /= 0) call release(attr, ok)
  end subroutine open_attribute

  !> Finish an attribute read: check `hdferr` and close the attribute.
  subroutine end_attr_read(file, obj_path, name, attr, hdferr, stat, errmsg)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: obj_path   !! group or dataset path
    character(len=*), intent(in) :: name       !! attribute name
    integer(hid_t), intent(inout) :: attr      !! attribute; closed on return
    integer, intent(in) :: hdferr              !! status of the read
    integer, intent(out) :: stat               !! 0 on success
    character(len=*), intent(inout) :: errmsg  !! set on failure
    logical :: ok

    stat = 0
    if (hdferr == vlen_string) then
      call fail(stat, errmsg, 'h5_read_attr', 'variable-length strings are not supported, attribute', &
        attr_label(obj_path, name), file)
    else if (hdferr < 0) then
      call fail(stat, errmsg, 'h5_read_attr', 'cannot read attribute', attr_label(obj_path, name), file)
    end if
    ok = .true.
    call release(attr, ok)
    if (stat == 0 .and. .not. ok) call fail(stat, errmsg, 'h5_read_attr', 'cannot close attribute', &
      attr_label(obj_path, name), file)
  end subroutine end_attr_read

  !> 'obj_path@name', how attributes are named in messages.
  pure function attr_label(obj_path, name) result(label)
    character(len=*), intent(in) :: obj_path  !! object path
    character(len=*), intent(in) :: name      !! attribute name
    character(len=:), allocatable :: label    !! label
    label = trim(obj_path)//'@'//trim(name)
  end function attr_label

  !> Name of an HDF5 datatype class, for messages.
  pure function class_name(type_class) result(name)
    integer, intent(in) :: type_class     !! H5T_*_F class
    character(len=:), allocatable :: name !! 'float', 'integer', 'string' or 'other'
    if (type_class == H5T_FLOAT_F) then
      name = 'float'
    else if (type_class == H5T_INTEGER_F) then
      name = 'integer'
    else if (type_class == H5T_STRING_F) then
      name = 'string'
    else
      name = 'other'
    end if
  end function class_name

  !> Decimal representation of an integer, for messages.
  pure function int_str(i) result(s)
    integer, intent(in) :: i             !! value
    character(len=:), allocatable :: s   !! digits
    character(len=12) :: buf
    write(buf, '(i0)') i
    s = trim(buf)
  end function int_str

  !> Set stat = 1 and errmsg = "op: what 'path' in file 'file'".
  subroutine fail(stat, errmsg, op, what, path, file)
    integer, intent(out) :: stat               !! set to 1
    character(len=*), intent(inout) :: errmsg  !! message
    character(len=*), intent(in) :: op        !! public operation name
    character(len=*), intent(in) :: what      !! what went wrong
    character(len=*), intent(in) :: path      !! object path (or attribute label)
    type(h5_file_t), intent(in) :: file       !! file
    stat = 1
    if (allocated(file%path)) then
      errmsg = op//': '//what//" '"//trim(path)//"' in file '"//file%path//"'"
    else
      errmsg = op//': '//what//" '"//trim(path)//"'"
    end if
  end subroutine fail

  !> Set stat = 1 and errmsg = "op: what 'path'[hint]" for file-level failures.
  subroutine fail_file(stat, errmsg, op, what, path, hint)
    integer, intent(out) :: stat               !! set to 1
    character(len=*), intent(inout) :: errmsg  !! message
    character(len=*), intent(in) :: op        !! public operation name
    character(len=*), intent(in) :: what      !! what went wrong
    character(len=*), intent(in) :: path      !! file name
    character(len=*), intent(in), optional :: hint  !! appended to the message
    stat = 1
    errmsg = op//': '//what//" '"//trim(path)//"'"
    if (present(hint)) errmsg = trim(errmsg)//hint
  end subroutine fail_file

end module landyn_h5
