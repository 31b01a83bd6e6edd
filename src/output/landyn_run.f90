!> One way to run a case, for landyn, landyn_study and landyn_batch alike: the input health
!! checks, the simulation, the result health checks and the outcome, with one status whose meaning
!! is the same everywhere (docs/exit_status.md):
!!   0 (EXIT_OK)            the run touched down and ended with an outcome (landyn_outcome): at
!!                          rest, tipped over, or still moving at t_end. Not by itself a success:
!!                          still moving is inconclusive, and the outcome says which;
!!   3 (EXIT_DIVERGED)      the simulation failed (no result);
!!   6 (EXIT_HEALTH)        a run-health check failed (input: not run; result: physically meaningless);
!!   7 (EXIT_NO_TOUCHDOWN)  no footpad touched the ground by t_end.
!! The first that applies, in the order 3, 6, 7. Writing files is the caller's.
!!
!! Library code: nothing here stops or prints, except progress into the unit the caller passes.
module landyn_run
  use landyn_config, only: landyn_input_t
  use landyn_status, only: EXIT_OK, EXIT_DIVERGED, EXIT_HEALTH, EXIT_NO_TOUCHDOWN, status_t
  use landyn_simulation, only: sim_result_t, run_simulation
  use landyn_health, only: health_t, check_health, check_input_health, health_fail
  use landyn_outcome, only: classify_outcome, outcome_no_touchdown
  implicit none
  private

  public :: run_case, case_status_meaning, input_unhealthy, worse_status

contains

  !> Runs one case: input health, simulation, result health, outcome; status as the module doc.
  !! `res` holds the result whenever the simulation ran (status 0, 6 after the run, 7), and what
  !! there is of it after a failure (status 3); `ran` says whether the simulation ran.
  subroutine run_case(inp, res, health, status, msg, progress_unit, loads, ran)
    type(landyn_input_t), intent(in) :: inp       !! resolved, validated input [-]
    type(sim_result_t), intent(out) :: res        !! the result [-]
    type(health_t), intent(out) :: health         !! run-health checks (input only when not run) [-]
    integer, intent(out) :: status                !! 0, 3, 6 or 7 (module doc) [-]
    character(len=*), intent(inout) :: msg        !! the simulation's diagnosis on status 3 [-]
    integer, intent(in) :: progress_unit          !! unit for progress lines, < 0 for none [-]
    logical, intent(in), optional :: loads        !! compute the interface loads (run_simulation) [-]
    logical, intent(out), optional :: ran         !! the simulation ran to an end (a file can be written) [-]
    type(status_t) :: st
    if (present(ran)) ran = .false.
    call check_input_health(inp, health)
    if (health%status() == health_fail) then
      status = EXIT_HEALTH
      return
    end if
    call run_simulation(inp, res, st, progress_unit, loads)
    if (.not. st%ok()) then
      msg = st%text()
      status = EXIT_DIVERGED
      return
    end if
    if (present(ran)) ran = .true.
    call check_health(inp, res, health)
    call classify_outcome(inp, res)
    if (health%status() == health_fail) then
      status = EXIT_HEALTH
    else if (res%outcome == outcome_no_touchdown) then
      status = EXIT_NO_TOUCHDOWN
    else
      status = EXIT_OK
    end if
  end subroutine run_case

  !> A run's input failed its health checks (status 6 without a result).
  pure function input_unhealthy(status, ran) result(yes)
    integer, intent(in) :: status   !! run_case's status [-]
    logical, intent(in) :: ran      !! run_case's ran [-]
    logical :: yes                  !! nothing was run because the input is meaningless [-]
    yes = status == EXIT_HEALTH .and. .not. ran
  end function input_unhealthy

  !> The worse of two run_case statuses, for a program that runs several: 3 before 6 before 7
  !! before 0 (any other non-zero status counts as 3).
  elemental function worse_status(a, b) result(w)
    integer, intent(in) :: a   !! a status [-]
    integer, intent(in) :: b   !! another [-]
    integer :: w               !! the worse [-]
    w = merge(a, b, rank_of(a) >= rank_of(b))
  end function worse_status

  !> Severity of a status for worse_status.
  elemental function rank_of(s) result(r)
    integer, intent(in) :: s   !! status [-]
    integer :: r               !! severity [-]
    select case (s)
    case (EXIT_OK)
      r = 0
    case (EXIT_NO_TOUCHDOWN)
      r = 1
    case (EXIT_HEALTH)
      r = 2
    case default
      r = 3
    end select
  end function rank_of

  !> One line saying what a run_case status means.
  pure function case_status_meaning(status) result(text)
    integer, intent(in) :: status           !! run_case's status [-]
    character(len=:), allocatable :: text   !! its meaning [-]
    select case (status)
    case (EXIT_OK)
      text = 'completed: the outcome says at rest, tipped over or still moving (inconclusive)'
    case (EXIT_DIVERGED)
      text = 'the simulation failed'
    case (EXIT_HEALTH)
      text = 'a run-health check failed: physically meaningless'
    case (EXIT_NO_TOUCHDOWN)
      text = 'no touchdown: no footpad touched the ground'
    case default
      text = 'unknown status'
    end select
  end function case_status_meaning

end module landyn_run
