!> What the three programs (landyn, landyn_study, landyn_batch) share on their command line: the
!! -h/--help and -V/--version options, options that take a file name, and the ways a program
!! stops on a usage error or a refused output file (docs/exit_status.md).
!!
!! Part of the library (not a main program), so that every program links it; only programs use
!! it, since its procedures stop the program.
module landyn_app_support
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use landyn_status, only: EXIT_OK, EXIT_USAGE, EXIT_FILE
  use landyn_process, only: terminate
  use landyn_cli, only: get_arg, write_version, write_usage_error
  implicit none
  private

  public :: app_t

  !> A program's name, its one-line usage and its --help text.
  type :: app_t
    character(len=:), allocatable :: name        !! program name, the prefix of its messages [-]
    character(len=:), allocatable :: usage_line  !! usage line shown after a usage error [-]
    character(len=:), allocatable :: help(:)     !! lines of the --help text [-]
  contains
    procedure :: info_option   !! -h/--help and -V/--version
    procedure :: option_value  !! the file name after an option
    procedure :: die_usage     !! stop on a usage error
    procedure :: die_files     !! stop on a refused output file
  end type app_t

contains

  !> -h/--help: print the help text and stop with EXIT_OK; -V/--version: print the version and
  !! stop with EXIT_OK; any other argument: return.
  subroutine info_option(app, arg)
    class(app_t), intent(in) :: app      !! the program [-]
    character(len=*), intent(in) :: arg  !! command-line argument [-]
    integer :: k
    select case (arg)
    case ('-h', '--help')
      do k = 1, size(app%help)
        write (output_unit, '(a)') trim(app%help(k))
      end do
      call terminate(EXIT_OK)
    case ('-V', '--version')
      call write_version(output_unit, app%name)
      call terminate(EXIT_OK)
    end select
  end subroutine info_option

  !> The file name that follows option `arg` (argument i + 1; i is advanced to it). A missing or
  !! empty name is a usage error.
  function option_value(app, i, n, arg) result(value)
    class(app_t), intent(in) :: app        !! the program [-]
    integer, intent(inout) :: i            !! index of the option; of its value on return [-]
    integer, intent(in) :: n               !! number of arguments [-]
    character(len=*), intent(in) :: arg    !! the option as given [-]
    character(len=:), allocatable :: value !! the file name [-]
    if (i == n) call app%die_usage('option '//arg//' needs a file name')
    i = i + 1
    value = get_arg(i)
    if (len(value) == 0) call app%die_usage('option '//arg//' needs a non-empty file name')
  end function option_value

  !> Report a usage error (with the usage line) and stop with EXIT_USAGE.
  subroutine die_usage(app, text)
    class(app_t), intent(in) :: app        !! the program [-]
    character(len=*), intent(in) :: text   !! what is wrong [-]
    call write_usage_error(error_unit, app%name, text, app%usage_line)
    call terminate(EXIT_USAGE)
  end subroutine die_usage

  !> Report an output file refused before anything ran and stop with EXIT_FILE.
  subroutine die_files(app, text)
    class(app_t), intent(in) :: app        !! the program [-]
    character(len=*), intent(in) :: text   !! what is wrong [-]
    write (error_unit, '(a)') app%name//': '//text
    write (error_unit, '(a)') app%name//': nothing was run and no file was written'
    call terminate(EXIT_FILE)
  end subroutine die_files

end module landyn_app_support
