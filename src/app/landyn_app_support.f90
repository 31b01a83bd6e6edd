!> What the three programs (landyn, landyn_study, landyn_batch) share on their command line: the
!! walk over the arguments, the -h/--help, -V/--version and -q/--quiet options, options that take
!! a file name, the positional argument, and the ways a program stops on a usage error or a
!! refused output file (docs/exit_status.md).
!!
!! Part of the library (not a main program), so that every program links it; only programs use
!! it, since its procedures stop the program.
module landyn_app_support
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use landyn_status, only: EXIT_OK, EXIT_USAGE, EXIT_FILE
  use landyn_process, only: terminate
  use landyn_cli, only: get_arg, write_version, write_usage_error, positional_arg_problem
  implicit none
  private

  public :: app_t

  !> A program's name, its one-line usage and its --help text, and the walk over its arguments.
  type :: app_t
    character(len=:), allocatable :: name        !! program name, the prefix of its messages [-]
    character(len=:), allocatable :: usage_line  !! usage line shown after a usage error [-]
    character(len=:), allocatable :: help(:)     !! lines of the --help text [-]
    integer :: i = 0                             !! index of the argument read last [-]
    integer :: n = 0                             !! number of arguments [-]
    logical :: quiet = .false.                   !! -q/--quiet was given: no progress messages [-]
  contains
    procedure :: start         !! name, usage line and help; the walk starts before argument 1
    procedure :: next_arg      !! the next argument a program handles itself
    procedure :: info_option   !! -h/--help and -V/--version
    procedure :: option_value  !! the file name after an option
    procedure :: positional    !! the positional argument (a deck)
    procedure :: die_usage     !! stop on a usage error
    procedure :: die_files     !! stop on a refused output file
  end type app_t

contains

  !> Set up the program: its name, usage line and --help text; the argument walk starts.
  subroutine start(app, name, usage_line, help)
    class(app_t), intent(inout) :: app             !! the program [-]
    character(len=*), intent(in) :: name           !! program name [-]
    character(len=*), intent(in) :: usage_line     !! usage line shown after a usage error [-]
    character(len=*), intent(in) :: help(:)        !! lines of the --help text [-]
    app%name = name
    app%usage_line = usage_line
    app%help = help
    app%i = 0
    app%n = command_argument_count()
    app%quiet = .false.
  end subroutine start

  !> The next command-line argument in arg, .false. after the last one. -h/--help and -V/--version
  !! stop the program here (info_option); -q/--quiet sets app%quiet and is passed over.
  function next_arg(app, arg) result(more)
    class(app_t), intent(inout) :: app                 !! the program [-]
    character(len=:), allocatable, intent(out) :: arg  !! the argument [-]
    logical :: more                                    !! an argument was read [-]
    more = .false.
    do while (app%i < app%n)
      app%i = app%i + 1
      arg = get_arg(app%i)
      call app%info_option(arg)
      if (arg /= '-q' .and. arg /= '--quiet') then
        more = .true.
        return
      end if
      app%quiet = .true.
    end do
  end function next_arg

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

  !> The value that follows option `arg` (the next argument, which the walk passes over). A missing
  !! value is a usage error: "option <arg> needs a file name", or `missing`; so is an empty one,
  !! unless `missing` is given (the caller checks the value).
  function option_value(app, arg, missing) result(value)
    class(app_t), intent(inout) :: app                !! the program [-]
    character(len=*), intent(in) :: arg               !! the option as given [-]
    character(len=*), intent(in), optional :: missing !! message for a missing value, if not a file name [-]
    character(len=:), allocatable :: value            !! the value [-]
    if (app%i == app%n) then
      if (present(missing)) call app%die_usage(missing)
      call app%die_usage('option '//arg//' needs a file name')
    end if
    app%i = app%i + 1
    value = get_arg(app%i)
    if (len(value) == 0 .and. .not. present(missing)) call app%die_usage('option '//arg//' needs a non-empty file name')
  end function option_value

  !> A positional argument arg becomes `current` (named `what` in messages, e.g. 'deck'); an
  !! unknown option, an empty or a second one is a usage error (positional_arg_problem).
  subroutine positional(app, arg, current, what)
    class(app_t), intent(in) :: app                          !! the program [-]
    character(len=*), intent(in) :: arg                      !! the argument [-]
    character(len=:), allocatable, intent(inout) :: current  !! the positional argument so far, '' if none [-]
    character(len=*), intent(in) :: what                     !! its name in messages [-]
    character(len=:), allocatable :: problem
    problem = positional_arg_problem(arg, current, what)
    if (len(problem) > 0) call app%die_usage(problem)
    current = arg
  end subroutine positional

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
