!> Command-line helpers shared by the main programs (landyn, landyn_study, landyn_batch):
!! reading arguments, the version line, usage errors and the input-error report. Nothing here
!! stops: the programs end themselves (landyn_process's terminate, or error stop) after calling
!! these.
module landyn_cli
  use landyn_version, only: landyn_version_string, landyn_git_revision
  use landyn_input, only: input_errors_t
  implicit none
  private

  public :: get_arg, command_line, write_version, write_usage_error, positional_arg_problem
  public :: write_input_errors

contains

  !> Command-line argument k, of its full length.
  function get_arg(k) result(a)
    integer, intent(in) :: k               !! argument index [-]
    character(len=:), allocatable :: a     !! the argument [-]
    integer :: l
    call get_command_argument(k, length=l)
    allocate (character(len=l) :: a)
    if (l > 0) call get_command_argument(k, a)
  end function get_arg

  !> The whole command line, of its full length.
  function command_line() result(c)
    character(len=:), allocatable :: c     !! the command line [-]
    integer :: l
    call get_command(length=l)
    allocate (character(len=l) :: c)
    if (l > 0) call get_command(c)
  end function command_line

  !> "<program> <version> (<git revision>)" on a unit.
  subroutine write_version(unit, program)
    integer, intent(in) :: unit                !! output unit [-]
    character(len=*), intent(in) :: program    !! program name [-]
    write (unit, '(a)') program//' '//landyn_version_string//' ('//landyn_git_revision//')'
  end subroutine write_version

  !> "<program>: <text>" and the short usage line on a unit (the caller then ends with status 1).
  subroutine write_usage_error(unit, program, text, usage_line)
    integer, intent(in) :: unit                !! output unit (stderr) [-]
    character(len=*), intent(in) :: program    !! program name [-]
    character(len=*), intent(in) :: text       !! what is wrong [-]
    character(len=*), intent(in) :: usage_line !! short usage line [-]
    write (unit, '(a)') program//': '//text
    write (unit, '(a)') usage_line
  end subroutine write_usage_error

  !> What is wrong with a positional argument `arg` when `current` (maybe '') was given before:
  !! an unknown option (starts with '-'), a second <what>, or '' when it is acceptable.
  pure function positional_arg_problem(arg, current, what) result(problem)
    character(len=*), intent(in) :: arg        !! the argument [-]
    character(len=*), intent(in) :: current    !! the positional argument given before, '' if none [-]
    character(len=*), intent(in) :: what       !! its name in messages, e.g. 'deck' [-]
    character(len=:), allocatable :: problem   !! message, '' if none [-]
    problem = ''
    if (len(arg) == 0) then
      problem = 'empty '//what//' name ('''')'
      return
    end if
    if (len(arg) > 0) then
      if (arg(1:1) == '-') then
        problem = 'unknown option '//arg
        return
      end if
    end if
    if (len(current) > 0) problem = 'more than one '//what//' given ('//current//', '//arg//')'
  end function positional_arg_problem

  !> Every input error, then "<program>: N input error(s); nothing was run and no file was written".
  subroutine write_input_errors(unit, program, errors)
    integer, intent(in) :: unit                  !! output unit (stderr) [-]
    character(len=*), intent(in) :: program      !! program name [-]
    type(input_errors_t), intent(in) :: errors   !! the errors [-]
    call errors%write(unit)
    write (unit, '(a,i0,a)') program//': ', errors%count(), ' input error(s); nothing was run and no file was written'
  end subroutine write_input_errors

end module landyn_cli
