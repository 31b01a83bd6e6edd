!> The provenance block every LANDYN HDF5 file carries: the root attribute `producer` and the
!! group /meta (code version, git revision, build type, compiler and flags, date, command line).
!!
!! The datasets are those of the output schema's /meta section (landyn_output_schema), written
!! with schema_write: their units and descriptions are the schema's.
!!
!! Written here and nowhere else: the result file of a run (landyn_output), the study file
!! (landyn_study) and the campaign summary (landyn_campaign_store) call write_meta and then add
!! what is particular to them (the run's deck and units, the study deck, ...).
!!
!! Library code: nothing here stops or prints.
module landyn_provenance
  use, intrinsic :: iso_fortran_env, only: compiler_version, compiler_options
  use landyn_version, only: landyn_version_string, landyn_git_revision, landyn_build_type, landyn_fflags
  use landyn_strings, only: nonempty
  use landyn_status, only: status_t, STAT_OK
  use landyn_h5, only: h5_file_t, h5_write_attr
  use landyn_schema_write, only: schema_write
  implicit none
  private

  public :: write_meta

contains

  !> Current date and time as ISO 8601 with the UTC offset.
  function iso_timestamp() result(ts)
    character(len=25) :: ts   !! e.g. 2026-11-22T10:15:00+00:00 [-]
    character(len=8) :: d
    character(len=10) :: t
    character(len=5) :: z
    call date_and_time(d, t, z)
    ts = d(1:4)//'-'//d(5:6)//'-'//d(7:8)//'T'//t(1:2)//':'//t(3:4)//':'//t(5:6)//z(1:3)//':'//z(4:5)
  end function iso_timestamp

  !> Write the root attribute `producer` ('LANDYN <version>[ <program>]') and the provenance
  !! datasets of /meta: code_version, git_revision, build_type, compiler, compiler_flags,
  !! compiler_options, date, command_line. With `run_git_revision` (a file that gathers results
  !! computed earlier, e.g. a campaign summary), /meta/git_revision is that revision and
  !! /meta/writer_git_revision the revision of the code writing the file.
  subroutine write_meta(f, program, command_line, status, run_git_revision)
    type(h5_file_t), intent(inout) :: f                        !! file open for writing [-]
    character(len=*), intent(in) :: program                    !! program name for `producer`; blank for landyn [-]
    character(len=*), intent(in) :: command_line               !! the command that wrote the file [-]
    type(status_t), intent(out) :: status                      !! STAT_OK, or the failure with its message [-]
    character(len=*), intent(in), optional :: run_git_revision !! revision of the code that computed the results [-]
    character(len=:), allocatable :: producer

    producer = 'LANDYN '//landyn_version_string
    if (len_trim(program) > 0) producer = producer//' '//trim(program)
    call h5_write_attr(f, '/', 'producer', producer, status); if (.not. status%ok()) return
    call schema_write(f, '/meta/code_version', landyn_version_string, status); if (.not. status%ok()) return
    if (present(run_git_revision)) then
      call schema_write(f, '/meta/git_revision', run_git_revision, status); if (.not. status%ok()) return
      call schema_write(f, '/meta/writer_git_revision', landyn_git_revision, status); if (.not. status%ok()) return
    else
      call schema_write(f, '/meta/git_revision', landyn_git_revision, status); if (.not. status%ok()) return
    end if
    call schema_write(f, '/meta/build_type', landyn_build_type, status); if (.not. status%ok()) return
    call schema_write(f, '/meta/compiler', compiler_version(), status); if (.not. status%ok()) return
    call schema_write(f, '/meta/compiler_flags', landyn_fflags, status); if (.not. status%ok()) return
    call schema_write(f, '/meta/compiler_options', compiler_options(), status); if (.not. status%ok()) return
    call schema_write(f, '/meta/date', iso_timestamp(), status); if (.not. status%ok()) return
    call schema_write(f, '/meta/command_line', nonempty(trim(command_line)), status)
  end subroutine write_meta

end module landyn_provenance
