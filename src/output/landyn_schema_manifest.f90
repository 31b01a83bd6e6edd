!> The output schema (landyn_output_schema) as a JSON manifest: the result-file and campaign schema
!! versions and one object per dataset (path, units, shape, kind, components, since, written,
!! meaning), one dataset per line. `landyn_schema` prints it; landyn_post ships a copy
!! (post/landyn_post/data/output_schema.json) that CTest `output_schema_manifest` compares with it.
module landyn_schema_manifest
  use landyn_output_schema, only: dataset_spec_t, output_datasets, result_schema_version, campaign_schema_version
  implicit none
  private

  public :: write_schema_manifest

contains

  !> Writes the manifest on an open formatted unit.
  subroutine write_schema_manifest(unit)
    integer, intent(in) :: unit                    !! output unit [-]
    integer :: k
    write (unit, '(a)') '{'
    write (unit, '(a)') '  "schema_version": '//json_string(result_schema_version)//','
    write (unit, '(a)') '  "campaign_schema": '//json_string(campaign_schema_version)//','
    write (unit, '(a)') '  "shape_symbols": {"n": "output samples", "g": "gears", "s": "struts per gear", '// &
                        '"m": "rows of /api/inputs", "k": "primary honeycomb stages"},'
    write (unit, '(a)') '  "datasets": ['
    do k = 1, size(output_datasets)
      write (unit, '(a)') '    '//dataset_json(output_datasets(k))//trim(merge(',', ' ', k < size(output_datasets)))
    end do
    write (unit, '(a)') '  ]'
    write (unit, '(a)') '}'
  end subroutine write_schema_manifest

  !> One dataset as a JSON object on one line.
  function dataset_json(d) result(s)
    type(dataset_spec_t), intent(in) :: d          !! dataset [-]
    character(len=:), allocatable :: s             !! JSON object [-]
    s = '{"path": '//json_string(trim(d%path))//', "units": '//json_string(trim(d%units))// &
        ', "shape": '//json_list(trim(d%shape), .true.)//', "kind": '//json_string(trim(d%kind))// &
        ', "components": '//json_list(trim(d%components), .false.)//', "since": '//json_string(trim(d%since))// &
        ', "written": '//json_string(trim(d%written))//', "meaning": '//json_string(trim(d%meaning))//'}'
  end function dataset_json

  !> A comma-separated list as a JSON array; with `numbers`, all-digit items as JSON numbers.
  function json_list(text, numbers) result(s)
    character(len=*), intent(in) :: text           !! items separated by commas, '' for none [-]
    logical, intent(in) :: numbers                 !! write all-digit items as numbers [-]
    character(len=:), allocatable :: s             !! JSON array [-]
    integer :: i0, i
    character(len=:), allocatable :: item
    s = '['
    i0 = 1
    do i = 1, len(text) + 1
      if (i <= len(text)) then
        if (text(i:i) /= ',') cycle
      end if
      if (i > i0) then
        item = text(i0:i - 1)
        if (len(s) > 1) s = s//', '
        if (numbers .and. verify(item, '0123456789') == 0) then
          s = s//item
        else
          s = s//json_string(item)
        end if
      end if
      i0 = i + 1
    end do
    s = s//']'
  end function json_list

  !> A JSON string literal: the text quoted, with '"' and '\' escaped.
  pure function json_string(text) result(s)
    character(len=*), intent(in) :: text           !! text (ASCII) [-]
    character(len=:), allocatable :: s             !! quoted [-]
    integer :: i
    s = '"'
    do i = 1, len(text)
      if (text(i:i) == '"' .or. text(i:i) == '\') s = s//'\'
      s = s//text(i:i)
    end do
    s = s//'"'
  end function json_string

end module landyn_schema_manifest
