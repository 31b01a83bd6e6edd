!> Named status values: what library routines return (in a status_t) and what the programs exit with.
!!
!! Library code never stops; it returns one of the STAT_* values with a message (a status_t, or
!! the input layer's error collector). Every library status is named here, each with its own value (no two STAT_*
!! are equal). The main programs (src/app/) turn a status into one of the EXIT_* values
!! documented in docs/exit_status.md. The two sets share their numbers where the meaning is the
!! same (bad input, numerical failure, file not written), so a program can pass those on; the
!! library statuses without a program counterpart (the finer numerical failures) take numbers no
!! exit status uses, and a program reports them as EXIT_DIVERGED.
!!
!! A run's status (landyn_run's run_case, the studies' and campaigns' per-run records) is of the
!! program kind: an EXIT_* value, the one landyn would exit with for that run.
!!
!! status_t carries a library status and its message together (every layer: the simulation path,
!! physics, core's kinematics and LAPACK wrappers, the I/O of output, study and campaign): `fail`
!! sets both, `add_context` puts where and when in front of the message ("gear 2 at t =
!! 1.23450E-01 s: ..."), formatting the numbers in one place, so that no caller writes a context
!! by hand.
module landyn_status
  use landyn_kinds, only: wp
  implicit none
  private

  public :: status_t, time_text

  ! ---- library status (stat arguments)
  integer, parameter, public :: STAT_OK = 0        !! success
  integer, parameter, public :: STAT_FAILED = 1    !! failure without a more specific class (the message says what)
  integer, parameter, public :: STAT_INPUT = 2     !! the input (deck, option, parameter) is invalid or unreadable
  integer, parameter, public :: STAT_DIVERGED = 3  !! numerical failure: no convergence, constraint drift, non-finite state
  integer, parameter, public :: STAT_FILE = 4      !! a file could not be written (or was refused)
  integer, parameter, public :: STAT_NON_FINITE = 8  !! numerical failure: the solution became non-finite (an
                                                     !! accepted step, sim_accept)
  integer, parameter, public :: STAT_NO_STEP = 9     !! numerical failure: no step down to the adaptive
                                                     !! integrator's dt_min succeeds (adaptive_step)

  ! ---- program exit statuses (docs/exit_status.md)
  integer, parameter, public :: EXIT_OK = 0          !! success
  integer, parameter, public :: EXIT_USAGE = 1       !! wrong command line
  integer, parameter, public :: EXIT_INPUT = 2       !! invalid input deck
  integer, parameter, public :: EXIT_DIVERGED = 3    !! the simulation diverged or a comparison failed
  integer, parameter, public :: EXIT_FILE = 4        !! a file was not written (or refused)
  integer, parameter, public :: EXIT_INCOMPLETE = 5  !! stopped early; the summary is incomplete (campaigns)
  integer, parameter, public :: EXIT_HEALTH = 6      !! the run finished but failed a health check
  integer, parameter, public :: EXIT_NO_TOUCHDOWN = 7  !! the run finished without touching the ground

  !> A status with its message: STAT_OK and no message until `fail`.
  type :: status_t
    integer :: code = STAT_OK                      !! one of the STAT_* values [-]
    character(len=:), allocatable :: message       !! what failed, with its context (set by fail) [-]
  contains
    procedure :: ok => status_ok                   !! the status is STAT_OK
    procedure :: fail => status_fail               !! sets the code and the message (and its context)
    procedure :: add_context => status_add_context !! puts "<what> [i] at t = <t> s: " in front of the message
    procedure :: prefix => status_prefix           !! puts a text in front of the message
    procedure :: text => status_text               !! the message ('' when none)
  end type status_t

contains

  !> The status is STAT_OK.
  elemental logical function status_ok(self) result(yes)
    class(status_t), intent(in) :: self    !! status [-]
    yes = self%code == STAT_OK
  end function status_ok

  !> Sets the status: its code and its message, with where and when in front of it when `what`
  !! and `t` are given (as add_context puts them: "gear 2 at t =  1.23450E-01 s: <message>").
  pure subroutine status_fail(self, code, message, what, t, index)
    class(status_t), intent(inout) :: self     !! status [-]
    integer, intent(in) :: code                !! one of the STAT_* values [-]
    character(len=*), intent(in) :: message    !! what failed [-]
    character(len=*), intent(in), optional :: what  !! where: e.g. 'gear' or 'velocity projection' [-]
    real(wp), intent(in), optional :: t        !! time of the state (with what) [s]
    integer, intent(in), optional :: index     !! number of the part (gear) (with what) [-]
    self%code = code
    self%message = message
    if (present(what) .and. present(t)) call self%add_context(what, t, index)
  end subroutine status_fail

  !> Puts a text in front of the message (a message is made if there is none).
  pure subroutine status_prefix(self, text)
    class(status_t), intent(inout) :: self     !! status [-]
    character(len=*), intent(in) :: text       !! text put in front [-]
    if (allocated(self%message)) then
      self%message = text//self%message
    else
      self%message = text
    end if
  end subroutine status_prefix

  !> Puts where and when in front of the message: "<what> at t = <t> s: ", with " <index>" after
  !! `what` when an index is given ("gear 2 at t =  1.23450E-01 s: "; t as time_text writes it).
  pure subroutine status_add_context(self, what, t, index)
    class(status_t), intent(inout) :: self     !! status [-]
    character(len=*), intent(in) :: what       !! what failed, e.g. 'gear' or 'velocity projection' [-]
    real(wp), intent(in) :: t                 !! time of the state [s]
    integer, intent(in), optional :: index     !! number of the part (gear) [-]
    character(len=16) :: num
    if (present(index)) then
      write (num, '(i0)') index
      call self%prefix(what//' '//trim(num)//' at t = '//time_text(t)//' s: ')
    else
      call self%prefix(what//' at t = '//time_text(t)//' s: ')
    end if
  end subroutine status_add_context

  !> The message, '' when there is none.
  pure function status_text(self) result(text)
    class(status_t), intent(in) :: self        !! status [-]
    character(len=:), allocatable :: text      !! the message [-]
    if (allocated(self%message)) then
      text = self%message
    else
      text = ''
    end if
  end function status_text

  !> A time or step as the simulation's messages write it: es<digits+7>.<digits> (the default five
  !! digits: es12.5, with its leading blank for t >= 0, ' 1.23450E-01').
  pure function time_text(t, digits) result(text)
    real(wp), intent(in) :: t                 !! time [s]
    integer, intent(in), optional :: digits    !! digits after the point, default 5 [-]
    character(len=:), allocatable :: text      !! the text [-]
    character(len=32) :: buf
    character(len=16) :: fm
    integer :: d
    d = 5
    if (present(digits)) d = digits
    write (fm, '(a,i0,a,i0,a)') '(es', d + 7, '.', d, ')'
    write (buf, fm) t
    text = buf(1:d + 7)
  end function time_text
end module landyn_status
