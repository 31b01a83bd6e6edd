!> The `landyn_schema` program prints the result file's schema (src/output/landyn_output_schema.f90) as a
!! JSON manifest on standard output, or writes it to FILE.
!!
!!   landyn_schema [FILE]
!!
!! The build runs it (cmake/LandynSchema.cmake) to make build/landyn_output_schema.json, which
!! CTest compares with the copy landyn_post ships (post/landyn_post/data/output_schema.json).
program landyn_schema
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use landyn_cli, only: get_arg
  use landyn_schema_manifest, only: write_schema_manifest
  implicit none
  integer :: u, ios
  character(len=:), allocatable :: path
  character(len=256) :: msg

  if (command_argument_count() > 1) then
    write (error_unit, '(a)') 'landyn_schema: too many arguments'
    write (error_unit, '(a)') 'usage: landyn_schema [FILE]'
    error stop 1
  end if
  if (command_argument_count() == 0) then
    call write_schema_manifest(output_unit)
    stop
  end if
  path = get_arg(1)
  if (path == '-h' .or. path == '--help') then
    write (output_unit, '(a)') 'usage: landyn_schema [FILE]'
    write (output_unit, '(a)') 'Prints the result-file schema as a JSON manifest (or writes it to FILE).'
    stop
  end if
  open (newunit=u, file=path, status='replace', action='write', iostat=ios, iomsg=msg)
  if (ios /= 0) then
    write (error_unit, '(a)') 'landyn_schema: cannot write '//path//': '//trim(msg)
    error stop 4
  end if
  call write_schema_manifest(u)
  close (u)
end program landyn_schema
