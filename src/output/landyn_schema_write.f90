!> The one way the result file's datasets are written: `schema_write` looks the dataset up in the
!! output schema (landyn_output_schema), refuses it (stat /= 0 and a message naming the dataset)
!! when the schema has no such path or declares other units, another kind or another rank, and
!! writes it with h5_write and the schema's meaning as its `description` attribute.
module landyn_schema_write
  use landyn_kinds, only: wp
  use landyn_status, only: STAT_OK, STAT_FAILED
  use landyn_h5, only: h5_file_t, h5_write
  use landyn_output_schema, only: dataset_spec_t, output_datasets, find_dataset, spec_rank
  implicit none
  private

  public :: schema_write, schema_check

  !> Writes a dataset of the output schema (units given by the writer, checked against the schema).
  interface schema_write
    module procedure write_real_0d, write_real_1d, write_real_2d, write_real_3d  !! real(wp), rank 0 to 3
    module procedure write_int_0d, write_int_1d, write_int_2d, write_logical_0d  !! integer rank 0 to 2, logical
    module procedure write_string_0d, write_string_1d                           !! character, rank 0 and 1
  end interface schema_write

contains

  !> The index of dataset `path` in the schema, or stat /= 0 with a message when the schema has no
  !! such dataset or declares other units, another kind or another rank.
  subroutine schema_check(path, units, kind, rank, k, stat, errmsg)
    character(len=*), intent(in) :: path           !! dataset path [-]
    character(len=*), intent(in) :: units          !! units the writer gives [-]
    character(len=*), intent(in) :: kind           !! real, int, bool or text [-]
    integer, intent(in) :: rank                    !! rank of the value [-]
    integer, intent(out) :: k                      !! index in output_datasets, 0 on failure [-]
    integer, intent(out) :: stat                   !! STAT_OK when the schema declares it so [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    character(len=12) :: r1, r2
    type(dataset_spec_t) :: spec
    stat = STAT_FAILED
    k = find_dataset(path)
    if (k == 0) then
      errmsg = 'schema_write: dataset '//path//' is not in the output schema (src/output/landyn_output_schema.f90)'
      return
    end if
    spec = output_datasets(k)
    k = 0
    if (trim(spec%units) /= units) then
      errmsg = 'schema_write: '//path//' written in units '''//units//''', the output schema says '''// &
               trim(spec%units)//''''
    else if (trim(spec%kind) /= kind) then
      errmsg = 'schema_write: '//path//' written as '//kind//', the output schema says '//trim(spec%kind)
    else if (spec_rank(spec) /= rank) then
      write (r1, '(i0)') rank
      write (r2, '(i0)') spec_rank(spec)
      errmsg = 'schema_write: '//path//' written with rank '//trim(r1)//', the output schema says '//trim(r2)// &
               ' ('//trim(spec%shape)//')'
    else
      stat = STAT_OK
      k = find_dataset(path)
    end if
  end subroutine schema_check

  !> schema_write of a real value of rank 0.
  subroutine write_real_0d(f, path, value, units, stat, errmsg)
    type(h5_file_t), intent(in) :: f               !! file open for writing [-]
    character(len=*), intent(in) :: path           !! dataset path [-]
    real(wp), intent(in) :: value                  !! value [units]
    character(len=*), intent(in) :: units          !! its units, as the schema declares them [-]
    integer, intent(out) :: stat                   !! 0 on success [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    integer :: k
    call schema_check(path, units, 'real', 0, k, stat, errmsg)
    if (stat /= STAT_OK) return
    call h5_write(f, path, value, units, stat, errmsg, description=trim(output_datasets(k)%meaning))
  end subroutine write_real_0d

  !> schema_write of a real value of rank 1.
  subroutine write_real_1d(f, path, value, units, stat, errmsg)
    type(h5_file_t), intent(in) :: f               !! file open for writing [-]
    character(len=*), intent(in) :: path           !! dataset path [-]
    real(wp), intent(in) :: value(:)               !! values [units]
    character(len=*), intent(in) :: units          !! its units, as the schema declares them [-]
    integer, intent(out) :: stat                   !! 0 on success [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    integer :: k
    call schema_check(path, units, 'real', 1, k, stat, errmsg)
    if (stat /= STAT_OK) return
    call h5_write(f, path, value, units, stat, errmsg, description=trim(output_datasets(k)%meaning))
  end subroutine write_real_1d

  !> schema_write of a real value of rank 2.
  subroutine write_real_2d(f, path, value, units, stat, errmsg)
    type(h5_file_t), intent(in) :: f               !! file open for writing [-]
    character(len=*), intent(in) :: path           !! dataset path [-]
    real(wp), intent(in) :: value(:, :)            !! values [units]
    character(len=*), intent(in) :: units          !! its units, as the schema declares them [-]
    integer, intent(out) :: stat                   !! 0 on success [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    integer :: k
    call schema_check(path, units, 'real', 2, k, stat, errmsg)
    if (stat /= STAT_OK) return
    call h5_write(f, path, value, units, stat, errmsg, description=trim(output_datasets(k)%meaning))
  end subroutine write_real_2d

  !> schema_write of a real value of rank 3.
  subroutine write_real_3d(f, path, value, units, stat, errmsg)
    type(h5_file_t), intent(in) :: f               !! file open for writing [-]
    character(len=*), intent(in) :: path           !! dataset path [-]
    real(wp), intent(in) :: value(:, :, :)         !! values [units]
    character(len=*), intent(in) :: units          !! its units, as the schema declares them [-]
    integer, intent(out) :: stat                   !! 0 on success [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    integer :: k
    call schema_check(path, units, 'real', 3, k, stat, errmsg)
    if (stat /= STAT_OK) return
    call h5_write(f, path, value, units, stat, errmsg, description=trim(output_datasets(k)%meaning))
  end subroutine write_real_3d

  !> schema_write of a int value of rank 0.
  subroutine write_int_0d(f, path, value, units, stat, errmsg)
    type(h5_file_t), intent(in) :: f               !! file open for writing [-]
    character(len=*), intent(in) :: path           !! dataset path [-]
    integer, intent(in) :: value                   !! value [-]
    character(len=*), intent(in) :: units          !! its units, as the schema declares them [-]
    integer, intent(out) :: stat                   !! 0 on success [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    integer :: k
    call schema_check(path, units, 'int', 0, k, stat, errmsg)
    if (stat /= STAT_OK) return
    call h5_write(f, path, value, units, stat, errmsg, description=trim(output_datasets(k)%meaning))
  end subroutine write_int_0d

  !> schema_write of a int value of rank 1.
  subroutine write_int_1d(f, path, value, units, stat, errmsg)
    type(h5_file_t), intent(in) :: f               !! file open for writing [-]
    character(len=*), intent(in) :: path           !! dataset path [-]
    integer, intent(in) :: value(:)                !! values [-]
    character(len=*), intent(in) :: units          !! its units, as the schema declares them [-]
    integer, intent(out) :: stat                   !! 0 on success [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    integer :: k
    call schema_check(path, units, 'int', 1, k, stat, errmsg)
    if (stat /= STAT_OK) return
    call h5_write(f, path, value, units, stat, errmsg, description=trim(output_datasets(k)%meaning))
  end subroutine write_int_1d

  !> schema_write of a int value of rank 2.
  subroutine write_int_2d(f, path, value, units, stat, errmsg)
    type(h5_file_t), intent(in) :: f               !! file open for writing [-]
    character(len=*), intent(in) :: path           !! dataset path [-]
    integer, intent(in) :: value(:, :)             !! values [-]
    character(len=*), intent(in) :: units          !! its units, as the schema declares them [-]
    integer, intent(out) :: stat                   !! 0 on success [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    integer :: k
    call schema_check(path, units, 'int', 2, k, stat, errmsg)
    if (stat /= STAT_OK) return
    call h5_write(f, path, value, units, stat, errmsg, description=trim(output_datasets(k)%meaning))
  end subroutine write_int_2d

  !> schema_write of a bool value of rank 0.
  subroutine write_logical_0d(f, path, value, units, stat, errmsg)
    type(h5_file_t), intent(in) :: f               !! file open for writing [-]
    character(len=*), intent(in) :: path           !! dataset path [-]
    logical, intent(in) :: value                   !! value [-]
    character(len=*), intent(in) :: units          !! its units, as the schema declares them [-]
    integer, intent(out) :: stat                   !! 0 on success [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    integer :: k
    call schema_check(path, units, 'bool', 0, k, stat, errmsg)
    if (stat /= STAT_OK) return
    call h5_write(f, path, value, units, stat, errmsg, description=trim(output_datasets(k)%meaning))
  end subroutine write_logical_0d

  !> schema_write of a text value of rank 0.
  subroutine write_string_0d(f, path, value, units, stat, errmsg)
    type(h5_file_t), intent(in) :: f               !! file open for writing [-]
    character(len=*), intent(in) :: path           !! dataset path [-]
    character(len=*), intent(in) :: value          !! text [-]
    character(len=*), intent(in) :: units          !! its units, as the schema declares them [-]
    integer, intent(out) :: stat                   !! 0 on success [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    integer :: k
    call schema_check(path, units, 'text', 0, k, stat, errmsg)
    if (stat /= STAT_OK) return
    call h5_write(f, path, value, units, stat, errmsg, description=trim(output_datasets(k)%meaning))
  end subroutine write_string_0d

  !> schema_write of a text value of rank 1.
  subroutine write_string_1d(f, path, value, units, stat, errmsg)
    type(h5_file_t), intent(in) :: f               !! file open for writing [-]
    character(len=*), intent(in) :: path           !! dataset path [-]
    character(len=*), intent(in) :: value(:)       !! texts [-]
    character(len=*), intent(in) :: units          !! its units, as the schema declares them [-]
    integer, intent(out) :: stat                   !! 0 on success [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    integer :: k
    call schema_check(path, units, 'text', 1, k, stat, errmsg)
    if (stat /= STAT_OK) return
    call h5_write(f, path, value, units, stat, errmsg, description=trim(output_datasets(k)%meaning))
  end subroutine write_string_1d

end module landyn_schema_write
