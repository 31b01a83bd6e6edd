!> Process termination for the main programs: end with an exit status and no compiler message.
!! Fortran 2008's STOP/ERROR STOP print the stop code (and gfortran a backtrace) on stderr; a
!! batch tool's exit status should speak for itself, so the main programs end through C's exit()
!! after flushing the standard units. Library code never calls this.
module landyn_process
  use, intrinsic :: iso_c_binding, only: c_int
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  implicit none
  private

  public :: terminate

  interface
    !> C's exit(3): ends the process with an exit status, without a Fortran stop message.
    subroutine c_exit(status) bind(C, name='exit')
      import :: c_int
      integer(c_int), value :: status  !! exit status [-]
    end subroutine c_exit
  end interface

contains

  !> Flushes stdout and stderr and ends the process with the given exit status.
  subroutine terminate(status)
    integer, intent(in) :: status   !! exit status (0 = success) [-]
    flush (output_unit)
    flush (error_unit)
    call c_exit(int(status, c_int))
  end subroutine terminate

end module landyn_process
