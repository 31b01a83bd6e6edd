!> Handles, probes and private plumbing of the HDF5 layer (see landyn_h5 for the conventions):
!! the file handle type, h5_is_open / h5_exists, and the helpers the writers (landyn_h5_write),
!! readers (landyn_h5_read) and file operations (landyn_h5_file) share: library initialisation,
!! datatypes, handle release, dataset and attribute open/close with error messages.
!!
!! Only the landyn_h5_* modules use the helpers; everything else uses landyn_h5.
module landyn_h5_base
  use landyn_kinds, only: wp, ip
  use landyn_status, only: status_t, STAT_OK, STAT_FAILED
  use landyn_strings, only: int_text
  use hdf5, only: hid_t, hsize_t, size_t, h5open_f, h5dont_atexit_f, h5eset_auto_f, h5iis_valid_f, h5iget_type_f, &
    h5kind_to_type, h5gclose_f, h5lexists_f, h5oopen_f, h5pcreate_f, h5pset_create_inter_group_f, &
    h5pclose_f, h5screate_f, h5screate_simple_f, h5sclose_f, h5sget_simple_extent_type_f, &
    h5sget_simple_extent_ndims_f, h5sget_simple_extent_dims_f, h5tcopy_f, h5tset_size_f, &
    h5tset_strpad_f, h5tget_size_f, h5tget_class_f, h5tis_variable_str_f, h5tclose_f, h5dcreate_f, &
    h5dopen_f, h5dget_type_f, h5dget_space_f, h5dclose_f, h5acreate_f, h5aopen_by_name_f, &
    h5aexists_f, h5adelete_f, h5awrite_f, h5aget_type_f, h5aget_space_f, h5aclose_f, &
    H5P_LINK_CREATE_F, H5S_SCALAR_F, H5T_NATIVE_DOUBLE, H5T_FORTRAN_S1, H5T_C_S1, H5T_FLOAT_F, &
    H5T_INTEGER_F, H5T_STRING_F, H5T_STR_NULLPAD_F, H5T_STR_SPACEPAD_F, H5_REAL_KIND, &
    H5_INTEGER_KIND, H5I_GROUP_F, H5I_DATATYPE_F, H5I_DATASPACE_F, H5I_DATASET_F, H5I_ATTR_F
  implicit none
  private

  public :: h5_file_t, h5_is_open, h5_exists
  public :: no_id, max_rank
  public :: init_library, real_type, int_type, make_lcpl, file_string_type, mem_string_type, fixed_string_length
  public :: release, check_writable, begin_dataset, end_dataset, open_dataset, end_read
  public :: open_object, close_object, new_attribute, put_attr_string, open_attribute, end_attr_read
  public :: fail, fail_file

  integer(hid_t), parameter :: no_id = -1_hid_t   !! marks an HDF5 handle that is not open
  integer, parameter :: max_rank = 3               !! highest array rank handled here
  integer, parameter :: vlen_string = -2           !! internal status: variable-length string found

  !> An HDF5 file opened by h5_create or h5_open_read. Treat the components as read-only.
  type :: h5_file_t
    integer(hid_t) :: id = no_id                 !! HDF5 file identifier; no_id (-1) when not open
    character(len=:), allocatable :: path        !! file name as given when opened (for messages)
    logical :: writable = .false.                !! opened by h5_create
  end type h5_file_t

contains

  !> True when `file` holds an open HDF5 file.
  pure logical function h5_is_open(file)
    type(h5_file_t), intent(in) :: file  !! file handle
    h5_is_open = file%id >= 0
  end function h5_is_open

  ! ============================================================== groups and links

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



  !> Initialise the HDF5 Fortran interface unless it is already (the Fortran predefined datatype
  !! ids are live exactly when h5open_f has run and h5close_f has not), then silence the
  !! automatic error-stack printing. Calling h5open_f again would leak its datatype copies.
  !! First, before any other HDF5 call initialises the C library, h5dont_atexit_f: HDF5 then
  !! registers no exit handler. Every file is closed explicitly (h5_close, h5_commit_partial);
  !! the handler only mattered after a close that failed (a full disk: the file's data could not
  !! be flushed), when HDF5 1.10's H5F__close_cb retried at exit and crashed with SIGSEGV instead
  !! of the documented exit status 4 (issue 25). On later calls it fails harmlessly.
  subroutine init_library(hdferr)
    integer, intent(out) :: hdferr  !! 0 on success, negative on failure
    logical :: ready

    call h5dont_atexit_f(hdferr)
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
    call string_type(H5T_C_S1, H5T_STR_NULLPAD_F, nchar, ftype, hdferr)
  end subroutine file_string_type

  !> Memory datatype of a Fortran character(len=nchar) variable: blank-padded, at least 1
  !! character. HDF5's conversion to and from the file type drops trailing blanks on writing and
  !! blank-pads on reading.
  subroutine mem_string_type(nchar, mtype, hdferr)
    integer, intent(in) :: nchar          !! length of the Fortran variable
    integer(hid_t), intent(out) :: mtype  !! new datatype (no_id on failure)
    integer, intent(out) :: hdferr        !! negative on failure
    call string_type(H5T_FORTRAN_S1, H5T_STR_SPACEPAD_F, nchar, mtype, hdferr)
  end subroutine mem_string_type

  !> A copy of the string datatype `base` with `nchar` characters (at least 1) and padding `pad`.
  subroutine string_type(base, pad, nchar, tid, hdferr)
    integer(hid_t), intent(in) :: base    !! predefined string datatype (H5T_C_S1, H5T_FORTRAN_S1)
    integer, intent(in) :: pad            !! H5T_STR_NULLPAD_F or H5T_STR_SPACEPAD_F
    integer, intent(in) :: nchar          !! characters per element
    integer(hid_t), intent(out) :: tid    !! new datatype (no_id on failure)
    integer, intent(out) :: hdferr        !! negative on failure
    logical :: ok

    call h5tcopy_f(base, tid, hdferr)
    if (hdferr < 0) then
      tid = no_id
      return
    end if
    call h5tset_size_f(tid, int(max(1, nchar), size_t), hdferr)
    if (hdferr >= 0) call h5tset_strpad_f(tid, pad, hdferr)
    if (hdferr < 0) then
      ok = .true.
      call release(tid, ok)
    end if
  end subroutine string_type

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
  subroutine check_writable(file, op, path, status)
    type(h5_file_t), intent(in) :: file        !! file handle
    character(len=*), intent(in) :: op         !! public operation name
    character(len=*), intent(in) :: path       !! object path
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    if (.not. h5_is_open(file)) then
      call status%fail(STAT_FAILED, op//": no file is open (object '"//trim(path)//"')")
    else if (.not. file%writable) then
      call fail(status, op, 'file is open read-only, cannot write', path, file)
    end if
  end subroutine check_writable

  !> Create the dataset `path` (missing groups included) with file datatype `ftype` and
  !! dimensions `dims` (Fortran order; size(dims) = 0 makes a scalar).
  subroutine begin_dataset(file, path, ftype, dims, dset, status)
    type(h5_file_t), intent(in) :: file        !! file open for writing
    character(len=*), intent(in) :: path       !! dataset path
    integer(hid_t), intent(in) :: ftype        !! file datatype
    integer(hsize_t), intent(in) :: dims(:)    !! extent, Fortran order
    integer(hid_t), intent(out) :: dset        !! new dataset (no_id on failure)
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    character(len=*), parameter :: op = 'h5_write'
    integer(hid_t) :: space, lcpl
    integer :: hdferr
    logical :: ok

    dset = no_id
    call check_writable(file, op, path, status)
    if (.not. status%ok()) return
    space = no_id
    lcpl = no_id
    steps: block
      if (h5_exists(file, path)) then
        call fail(status, op, 'an object already exists at', path, file)
        exit steps
      end if
      if (size(dims) == 0) then
        call h5screate_f(H5S_SCALAR_F, space, hdferr)
      else
        call h5screate_simple_f(size(dims), dims, space, hdferr)
      end if
      if (hdferr >= 0) call make_lcpl(lcpl, hdferr)
      if (hdferr < 0) then
        call fail(status, op, 'cannot make the dataspace for', path, file)
        exit steps
      end if
      call h5dcreate_f(file%id, trim(path), ftype, space, dset, hdferr, lcpl_id=lcpl)
      if (hdferr < 0) then
        dset = no_id
        call fail(status, op, 'cannot create dataset (is a parent a dataset?)', path, file)
      end if
    end block steps
    ok = .true.
    call release(space, ok)
    call release(lcpl, ok)
    if (status%ok() .and. .not. ok) &
      call fail(status, op, 'cannot release HDF5 handles of', path, file)
    if (.not. status%ok()) call release(dset, ok)
  end subroutine begin_dataset

  !> Finish a dataset begun by begin_dataset: check the data write (`hdferr`), add the units and
  !! description attributes and close it.
  subroutine end_dataset(file, path, dset, hdferr, units, description, status)
    type(h5_file_t), intent(in) :: file        !! file open for writing
    character(len=*), intent(in) :: path       !! dataset path
    integer(hid_t), intent(inout) :: dset      !! dataset; closed on return
    integer, intent(in) :: hdferr              !! status of the data write
    character(len=*), intent(in) :: units      !! units attribute
    character(len=*), intent(in), optional :: description  !! description attribute
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    character(len=*), parameter :: op = 'h5_write'
    integer :: err
    logical :: ok

    if (hdferr < 0) then
      call fail(status, op, 'cannot write the data of', path, file)
    else
      call put_attr_string(dset, 'units', units, err)
      if (err >= 0 .and. present(description)) call put_attr_string(dset, 'description', description, err)
      if (err < 0) call fail(status, op, 'cannot write the units/description attributes of', path, file)
    end if
    ok = .true.
    call release(dset, ok)
    if (status%ok() .and. .not. ok) call fail(status, op, 'cannot close dataset', path, file)
  end subroutine end_dataset

  !> Open the dataset `path` for reading and check its type class and rank.
  subroutine open_dataset(file, path, want_class, want_rank, dset, dims, status)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: path       !! dataset path
    integer, intent(in) :: want_class          !! H5T_FLOAT_F, H5T_INTEGER_F or H5T_STRING_F
    integer, intent(in) :: want_rank           !! expected rank (0 = scalar)
    integer(hid_t), intent(out) :: dset        !! open dataset (no_id on failure)
    integer(hsize_t), intent(out) :: dims(max_rank)  !! extent, Fortran order (first want_rank used)
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    character(len=*), parameter :: op = 'h5_read'
    integer(hid_t) :: tid, space
    integer :: hdferr, type_class, rank
    logical :: ok

    dset = no_id
    dims = 0
    if (.not. h5_is_open(file)) then
      call status%fail(STAT_FAILED, op//": no file is open (dataset '"//trim(path)//"')")
      return
    end if
    tid = no_id
    space = no_id
    steps: block
      if (.not. h5_exists(file, path)) then
        call fail(status, op, 'no dataset', path, file)
        exit steps
      end if
      call h5dopen_f(file%id, trim(path), dset, hdferr)
      if (hdferr < 0) then
        dset = no_id
        call fail(status, op, 'not a dataset:', path, file)
        exit steps
      end if
      call h5dget_type_f(dset, tid, hdferr)
      if (hdferr >= 0) call h5tget_class_f(tid, type_class, hdferr)
      if (hdferr >= 0) call h5dget_space_f(dset, space, hdferr)
      if (hdferr >= 0) call query_extent(space, rank, dims, hdferr)
      if (hdferr < 0) then
        call fail(status, op, 'cannot query the datatype or dataspace of', path, file)
      else if (type_class /= want_class) then
        call fail(status, op, 'wrong datatype (expected '//class_name(want_class)// &
          ', found '//class_name(type_class)//') for', path, file)
      else if (rank /= want_rank) then
        call fail(status, op, 'wrong rank (expected '//int_text(want_rank)//', found '// &
          int_text(rank)//') for', path, file)
      end if
    end block steps
    ok = .true.
    call release(tid, ok)
    call release(space, ok)
    if (.not. status%ok()) call release(dset, ok)
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

  !> Finish a dataset read: check `hdferr` and close the dataset (finish_read).
  subroutine end_read(file, path, dset, hdferr, status)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: path       !! dataset path
    integer(hid_t), intent(inout) :: dset      !! dataset; closed on return
    integer, intent(in) :: hdferr              !! status of the read
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    call finish_read(file, 'h5_read', 'dataset', 'cannot read the data of', path, dset, hdferr, status)
  end subroutine end_read

  !> Finish the read of a dataset or attribute `obj` (named `label` in messages): fail when the
  !! read reported a variable-length string or an error (`hdferr`), then close it.
  subroutine finish_read(file, op, noun, read_failed, label, obj, hdferr, status)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: op         !! public operation name, for messages [-]
    character(len=*), intent(in) :: noun       !! 'dataset' or 'attribute' [-]
    character(len=*), intent(in) :: read_failed  !! message of a failed read [-]
    character(len=*), intent(in) :: label      !! dataset path or attribute label [-]
    integer(hid_t), intent(inout) :: obj       !! dataset or attribute; closed on return
    integer, intent(in) :: hdferr              !! status of the read
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    logical :: ok

    if (hdferr == vlen_string) then
      call fail(status, op, 'variable-length strings are not supported, '//noun, label, file)
    else if (hdferr < 0) then
      call fail(status, op, read_failed, label, file)
    end if
    ok = .true.
    call release(obj, ok)
    if (status%ok() .and. .not. ok) call fail(status, op, 'cannot close '//noun, label, file)
  end subroutine finish_read

  !> Open the group or dataset `obj_path` to write the attribute `name` on it.
  subroutine open_object(file, obj_path, name, obj, status)
    type(h5_file_t), intent(in) :: file        !! file open for writing
    character(len=*), intent(in) :: obj_path   !! group or dataset path
    character(len=*), intent(in) :: name       !! attribute name (for messages)
    integer(hid_t), intent(out) :: obj         !! open object (no_id on failure)
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    integer :: hdferr

    obj = no_id
    call check_writable(file, 'h5_write_attr', attr_label(obj_path, name), status)
    if (.not. status%ok()) return
    if (.not. h5_exists(file, obj_path)) then
      call fail(status, 'h5_write_attr', 'no group or dataset for attribute', &
        attr_label(obj_path, name), file)
      return
    end if
    call h5oopen_f(file%id, trim(obj_path), obj, hdferr)
    if (hdferr < 0) then
      obj = no_id
      call fail(status, 'h5_write_attr', 'cannot open the object of attribute', &
        attr_label(obj_path, name), file)
    end if
  end subroutine open_object

  !> Close the object opened by open_object after an attribute write with status `hdferr`.
  subroutine close_object(file, obj_path, name, obj, hdferr, status)
    type(h5_file_t), intent(in) :: file        !! file open for writing
    character(len=*), intent(in) :: obj_path   !! group or dataset path
    character(len=*), intent(in) :: name       !! attribute name
    integer(hid_t), intent(inout) :: obj       !! object; closed on return
    integer, intent(in) :: hdferr              !! status of the attribute write
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    logical :: ok

    if (hdferr < 0) call fail(status, 'h5_write_attr', 'cannot write attribute', &
      attr_label(obj_path, name), file)
    ok = .true.
    call release(obj, ok)
    if (status%ok() .and. .not. ok) call fail(status, 'h5_write_attr', &
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
  subroutine open_attribute(file, obj_path, name, want_class, attr, status)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: obj_path   !! group or dataset path
    character(len=*), intent(in) :: name       !! attribute name
    integer, intent(in) :: want_class          !! H5T_FLOAT_F, H5T_INTEGER_F or H5T_STRING_F
    integer(hid_t), intent(out) :: attr        !! open attribute (no_id on failure)
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    character(len=*), parameter :: op = 'h5_read_attr'
    integer(hid_t) :: tid, space
    integer(hsize_t) :: dims(max_rank)
    integer :: hdferr, type_class, rank
    logical :: ok

    attr = no_id
    if (.not. h5_is_open(file)) then
      call status%fail(STAT_FAILED, op//": no file is open (attribute '"//attr_label(obj_path, name)//"')")
      return
    end if
    if (.not. h5_exists(file, obj_path)) then
      call fail(status, op, 'no group or dataset for attribute', attr_label(obj_path, name), file)
      return
    end if
    tid = no_id
    space = no_id
    steps: block
      call h5aopen_by_name_f(file%id, trim(obj_path), trim(name), attr, hdferr)
      if (hdferr < 0) then
        attr = no_id
        call fail(status, op, 'no attribute', attr_label(obj_path, name), file)
        exit steps
      end if
      call h5aget_type_f(attr, tid, hdferr)
      if (hdferr >= 0) call h5tget_class_f(tid, type_class, hdferr)
      if (hdferr >= 0) call h5aget_space_f(attr, space, hdferr)
      if (hdferr >= 0) call query_extent(space, rank, dims, hdferr)
      if (hdferr < 0) then
        call fail(status, op, 'cannot query the datatype or dataspace of attribute', &
          attr_label(obj_path, name), file)
      else if (type_class /= want_class) then
        call fail(status, op, 'wrong datatype (expected '//class_name(want_class)// &
          ', found '//class_name(type_class)//') for attribute', attr_label(obj_path, name), file)
      else if (rank /= 0) then
        call fail(status, op, 'not a scalar attribute:', attr_label(obj_path, name), file)
      end if
    end block steps
    ok = .true.
    call release(tid, ok)
    call release(space, ok)
    if (.not. status%ok()) call release(attr, ok)
  end subroutine open_attribute

  !> Finish an attribute read: check `hdferr` and close the attribute (finish_read).
  subroutine end_attr_read(file, obj_path, name, attr, hdferr, status)
    type(h5_file_t), intent(in) :: file        !! open file
    character(len=*), intent(in) :: obj_path   !! group or dataset path
    character(len=*), intent(in) :: name       !! attribute name
    integer(hid_t), intent(inout) :: attr      !! attribute; closed on return
    integer, intent(in) :: hdferr              !! status of the read
    type(status_t), intent(out) :: status      !! STAT_OK, or the failure with its message [-]
    call finish_read(file, 'h5_read_attr', 'attribute', 'cannot read attribute', attr_label(obj_path, name), attr, &
                     hdferr, status)
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


  !> Fail with STAT_FAILED and the message "op: what 'path' in file 'file'".
  subroutine fail(status, op, what, path, file)
    type(status_t), intent(out) :: status      !! set to STAT_FAILED with the message [-]
    character(len=*), intent(in) :: op        !! public operation name
    character(len=*), intent(in) :: what      !! what went wrong
    character(len=*), intent(in) :: path      !! object path (or attribute label)
    type(h5_file_t), intent(in) :: file       !! file
    if (allocated(file%path)) then
      call status%fail(STAT_FAILED, op//': '//what//" '"//trim(path)//"' in file '"//file%path//"'")
    else
      call status%fail(STAT_FAILED, op//': '//what//" '"//trim(path)//"'")
    end if
  end subroutine fail

  !> Fail with STAT_FAILED and the message "op: what 'path'[hint]" for file-level failures.
  subroutine fail_file(status, op, what, path, hint)
    type(status_t), intent(out) :: status      !! set to STAT_FAILED with the message [-]
    character(len=*), intent(in) :: op        !! public operation name
    character(len=*), intent(in) :: what      !! what went wrong
    character(len=*), intent(in) :: path      !! file name
    character(len=*), intent(in), optional :: hint  !! appended to the message
    if (present(hint)) then
      call status%fail(STAT_FAILED, op//': '//what//" '"//trim(path)//"'"//hint)
    else
      call status%fail(STAT_FAILED, op//': '//what//" '"//trim(path)//"'")
    end if
  end subroutine fail_file


end module landyn_h5_base
