!> Named status values: what library routines return in `stat` and what the programs exit with.
!!
!! Library code never stops; it returns one of the STAT_* values with a message (errmsg or an
!! error collector). Every library status is named here, each with its own value (no two STAT_*
!! are equal). The main programs (src/app/) turn a status into one of the EXIT_* values
!! documented in docs/exit_status.md. The two sets share their numbers where the meaning is the
!! same (bad input, numerical failure, file not written), so a program can pass those on; the
!! library statuses without a program counterpart (the finer numerical failures) take numbers no
!! exit status uses, and a program reports them as EXIT_DIVERGED.
!!
!! A run's status (landyn_run's run_case, the studies' and campaigns' per-run records) is of the
!! program kind: an EXIT_* value, the one landyn would exit with for that run.
module landyn_status
  implicit none
  private

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
end module landyn_status
