!> The outcome of a finished run (docs/output.md, "Outcome"): what a landing-gear engineer takes
!! from it. Classified from the result alone, after the run:
!!   no_touchdown   no footpad ever touched the ground;
!!   at_rest        the lander came to rest (landyn_rest: every speed below &simulation rest_speed
!!                  for rest_time) and did not tip over;
!!   still_moving   it touched down but was neither at rest nor tipped over at t_final: undecided,
!!                  inconclusive, never a success (body speed, angular rate, slide rate reported);
!!   tipped_over    the tilt passed &simulation tipover_angle.
!! and the stability figures of the final state: the tip-over margin (landyn_stability, from the
!! footpads in contact, the mass centre and gravity of the last sample) and each footpad's static
!! friction ratio |F_t|/(mu_s F_n) with mu_s = &friction mu_static.
!!
!! Library code: nothing here stops; printing goes to a unit the caller passes.
module landyn_outcome
  use landyn_kinds, only: wp, rad2deg
  use landyn_config, only: landyn_input_t
  use landyn_simulation, only: sim_result_t
  use landyn_stability, only: tipover_margin, friction_ratio
  implicit none
  private

  public :: classify_outcome, outcome_name, write_outcome, n_outcomes
  public :: outcome_none, outcome_no_touchdown, outcome_at_rest, outcome_still_moving, outcome_tipped_over

  integer, parameter :: outcome_none = 0           !! not classified (the run failed) [-]
  integer, parameter :: outcome_no_touchdown = 1   !! never touched the ground [-]
  integer, parameter :: outcome_at_rest = 2        !! at rest, not tipped [-]
  integer, parameter :: outcome_still_moving = 3   !! still moving at t_final: inconclusive [-]
  integer, parameter :: outcome_tipped_over = 4    !! tipped over [-]
  integer, parameter :: n_outcomes = 4             !! outcome codes 1..n_outcomes [-]

  !> Names of the outcomes (/summary/outcome_name, campaign column outcome_name), index = code.
  character(len=14), parameter :: names(0:n_outcomes) = [character(len=14) :: 'none', 'no_touchdown', &
    'at_rest', 'still_moving', 'tipped_over']

contains

  !> Name of an outcome code ('none' for an unknown one).
  pure function outcome_name(code) result(name)
    integer, intent(in) :: code             !! outcome code [-]
    character(len=:), allocatable :: name   !! its name [-]
    if (code < 0 .or. code > n_outcomes) then
      name = 'none'
    else
      name = trim(names(code))
    end if
  end function outcome_name

  !> Sets res%outcome, res%tipover_margin and res%friction_ratio from a finished run.
  subroutine classify_outcome(inp, res)
    type(landyn_input_t), intent(in) :: inp    !! resolved input [-]
    type(sim_result_t), intent(inout) :: res   !! finished run [-]
    integer :: ng, n
    ng = res%n_gears
    if (res%tipped_over) then
      res%outcome = outcome_tipped_over
    else if (.not. res%touched) then
      res%outcome = outcome_no_touchdown
    else if (res%at_rest) then
      res%outcome = outcome_at_rest
    else
      res%outcome = outcome_still_moving
    end if
    if (allocated(res%friction_ratio)) deallocate (res%friction_ratio)
    allocate (res%friction_ratio(ng))
    res%friction_ratio = 0.0_wp
    res%tipover_margin = 0.0_wp
    n = res%n_out
    if (n < 1) return
    res%tipover_margin = rad2deg*tipover_margin(res%footpad_position(:, 1:ng, n), res%normal_force(1:ng, n) > 0.0_wp, &
                                                res%mc_position(:, n), [0.0_wp, 0.0_wp, inp%simulation%gravity])
    res%friction_ratio = friction_ratio(res%friction_force(1:ng, n), res%normal_force(1:ng, n), inp%friction%mu_static)
  end subroutine classify_outcome

  !> The outcome as printed lines: the class, what it means, and the end state.
  subroutine write_outcome(u, res)
    integer, intent(in) :: u                    !! formatted output unit [-]
    type(sim_result_t), intent(in) :: res       !! classified run [-]
    character(len=:), allocatable :: text
    character(len=12) :: tbuf
    select case (res%outcome)
    case (outcome_no_touchdown)
      text = 'NO TOUCHDOWN: no footpad touched the ground by t = '
    case (outcome_at_rest)
      text = 'AT REST at t = '
    case (outcome_still_moving)
      text = 'STILL MOVING (inconclusive: neither at rest nor tipped over) at t = '
    case (outcome_tipped_over)
      text = 'TIPPED OVER at t = '
    case default
      text = 'NOT CLASSIFIED at t = '
    end select
    write (tbuf, '(f12.4)') res%t_final
    write (u, '(a)') '  outcome: '//text//trim(adjustl(tbuf))//' s'
    write (u, '(a,es10.3,a,es10.3,a,es10.3,a,es10.3,a)') '  end state: body speed ', res%end_motion%body_speed, &
      ' m/s, angular rate ', res%end_motion%angular_rate*rad2deg, ' deg/s, slide rate ', res%end_motion%slide_rate, &
      ' m/s, stroke rate ', res%end_motion%stroke_rate, ' m/s'
    if (res%touched .and. allocated(res%friction_ratio)) then
      write (u, '(a,f8.3,a)') '  tip-over margin ', res%tipover_margin, &
        ' deg (further tilt about the nearest support-polygon edge; <= 0: not statically stable)'
      write (u, '(a,*(f7.3))') '  static friction ratio |F_t|/(mu_s F_n) per footpad:', res%friction_ratio
    end if
  end subroutine write_outcome

end module landyn_outcome
