!> Dataset and attribute writers of the HDF5 layer: the generic h5_write and h5_write_attr
!! (one specific procedure per type and rank; see landyn_h5 for the conventions).
module landyn_h5_write
  use landyn_kinds, only: wp, ip
  use landyn_status, only: STAT_OK
  use landyn_h5_base, only: no_id, h5_file_t, real_type, int_type, file_string_type, &
    mem_string_type, release, begin_dataset, end_dataset, open_object, close_object, new_attribute, &
    put_attr_string, fail
  use hdf5, only: hid_t, hsize_t, h5dwrite_f, h5awrite_f, H5T_IEEE_F64LE, H5T_STD_I32LE
  implicit none
  private

  public :: h5_write, h5_write_attr

  !> Write a dataset with a mandatory "units" and an optional "description" attribute:
  !! `call h5_write(file, path, value, units, stat, errmsg [, description])`.
  interface h5_write
    module procedure write_real_0d, write_real_1d, write_real_2d, write_real_3d  !! real(wp), rank 0 to 3
    module procedure write_int_0d, write_int_1d, write_int_2d, write_logical_0d  !! integer rank 0 to 2, logical
    module procedure write_string_0d, write_string_1d                           !! character, rank 0 and 1
  end interface h5_write

  !> Write (or replace) a scalar attribute on a group or dataset:
  !! `call h5_write_attr(file, obj_path, name, value, stat, errmsg)`.
  interface h5_write_attr
    module procedure write_attr_string, write_attr_real, write_attr_int  !! character, real(wp), integer
  end interface h5_write_attr

contains

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

    stat = STAT_OK
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

    stat = STAT_OK
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

end module landyn_h5_write
