!> Dataset and attribute readers of the HDF5 layer: the generic h5_read and h5_read_attr
!! (one specific procedure per type and rank; see landyn_h5 for the conventions).
module landyn_h5_read
  use landyn_kinds, only: wp, ip
  use landyn_strings, only: int_text
  use landyn_h5_base, only: no_id, max_rank, h5_file_t, real_type, int_type, mem_string_type, &
    fixed_string_length, release, open_dataset, end_read, open_attribute, end_attr_read, fail
  use hdf5, only: hid_t, hsize_t, h5dread_f, h5dget_type_f, h5aread_f, h5aget_type_f, H5T_FLOAT_F, &
    H5T_INTEGER_F, H5T_STRING_F
  implicit none
  private

  public :: h5_read, h5_read_attr

  !> Read a dataset; arrays are allocatable and take their shape from the file:
  !! `call h5_read(file, path, value, stat, errmsg)`.
  interface h5_read
    module procedure read_real_0d, read_real_1d, read_real_2d, read_real_3d  !! real(wp), rank 0 to 3
    module procedure read_int_0d, read_int_1d, read_int_2d, read_logical_0d  !! integer rank 0 to 2, logical
    module procedure read_string_0d, read_string_1d                         !! character, rank 0 and 1
  end interface h5_read

  !> Read a scalar attribute of a group or dataset:
  !! `call h5_read_attr(file, obj_path, name, value, stat, errmsg)`.
  interface h5_read_attr
    module procedure read_attr_string, read_attr_real, read_attr_int  !! character, real(wp), integer
  end interface h5_read_attr

contains

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
      call fail(stat, errmsg, 'h5_read', 'strings of '//int_text(nchar)//' characters do not fit in '// &
        'character(len='//int_text(len(value))//'), dataset', path, file)
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

end module landyn_h5_read
