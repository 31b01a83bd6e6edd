!> The model as a time integrator sees it, in the manner of Project Chrono's ChIntegrableIIorder:
!! the integrator owns the update formula, the model offers the operations any scheme needs.
!!
!! * gather and scatter the velocities (the body's mass-centre velocity and rates, every moving
!!   gear's generalized velocities) and gather the accelerations of an evaluation, as one vector
!!   laid out as vel_layout says;
!! * increment the positions along a velocity vector (rotations through the Euler-angle rates);
!! * the discrete decision of the rigid-plastic crush law over a step (sim_arrest);
!! * project positions (each gear's constraints and locked strokes) and velocities (the plastic
!!   impact of the whole constrained system, landyn_impact) onto the constraints;
!! * commit an evaluation (the forces and decisions a step is taken with) and, after the step, the
!!   discrete state (footpad histories and stick states, rigid gears).
!!
!! The evaluation itself is sim_evaluate (landyn_sim_core). A gear whose struts are all locked and
!! at rest (rigid) does not move: it has no entries to scatter and is skipped by the increments and
!! projections (`moving`).
module landyn_sim_state
  use landyn_kinds, only: wp, max_gears, max_gear_q, max_struts
  use landyn_status, only: STAT_OK, status_t
  use landyn_body, only: body_increment
  use landyn_impact, only: system_velocity_projection
  use landyn_sim_model, only: sim_t, sim_eval_t
  implicit none
  private

  public :: max_nv, vel_layout, sim_commit_evaluation, sim_moving, sim_gather_velocities, sim_scatter_velocities
  public :: sim_gather_accelerations, sim_arrest, sim_increment_positions, sim_project_positions
  public :: sim_project_velocities, sim_commit_discrete

  integer, parameter :: max_nv = 6 + max_gears*max_gear_q   !! length of the largest velocity vector [-]

contains

  !> Where each part sits in a velocity vector: 1:3 the mass-centre velocity (global), 4:6 the
  !! body rates (lander axes), then gear i's generalized velocities at first(i) : first(i) + n_q(i) - 1.
  pure subroutine vel_layout(sim, first, nv)
    type(sim_t), intent(in) :: sim              !! simulation
    integer, intent(out) :: first(max_gears)    !! first entry of each gear [-]
    integer, intent(out) :: nv                  !! length of the vector [-]
    integer :: i
    nv = 6
    first = nv + 1
    do i = 1, sim%model%par%n_gears
      first(i) = nv + 1
      nv = nv + sim%model%par%n_q(i)
    end do
  end subroutine vel_layout

  !> Makes the evaluation the step is taken with the committed state: the body's accelerations,
  !! each gear's strut decisions, buffer forces and accelerations.
  subroutine sim_commit_evaluation(sim, ev)
    type(sim_t), intent(inout) :: sim           !! simulation
    type(sim_eval_t), intent(in) :: ev          !! evaluation of the present state (sim_evaluate)
    integer :: i
    sim%model%body%acc = ev%acc
    sim%model%body%alpha = ev%alpha
    do i = 1, sim%model%par%n_gears
      call sim%model%gear(i)%g%commit(ev%gear(i))
    end do
  end subroutine sim_commit_evaluation

  !> Which gears move: all but those rigid with every strut locked.
  subroutine sim_moving(sim, moving)
    type(sim_t), intent(in) :: sim              !! simulation (committed state)
    logical, intent(out) :: moving(max_gears)   !! gear i moves [-]
    logical :: locked(max_struts)
    integer :: i, ns
    moving = .false.
    do i = 1, sim%model%par%n_gears
      ns = sim%model%par%n_struts(i)
      call sim%model%gear(i)%g%locks(locked(1:ns))
      moving(i) = .not. (sim%model%gear(i)%g%is_rigid() .and. all(locked(1:ns)))
    end do
  end subroutine sim_moving

  !> The velocity vector of the state (vel_layout).
  subroutine sim_gather_velocities(sim, v, nv)
    type(sim_t), intent(in) :: sim              !! simulation
    real(wp), intent(out) :: v(max_nv)          !! velocities [m/s, rad/s]
    integer, intent(out) :: nv                  !! length [-]
    integer :: first(max_gears), i
    call vel_layout(sim, first, nv)
    v(1:3) = sim%model%body%v
    v(4:6) = sim%model%body%omega
    do i = 1, sim%model%par%n_gears
      call sim%model%gear(i)%g%rates(v(first(i):first(i) + sim%model%par%n_q(i) - 1))
    end do
  end subroutine sim_gather_velocities

  !> Puts a velocity vector into the state: the body's and the moving gears' (a rigid gear stays
  !! at rest).
  subroutine sim_scatter_velocities(sim, moving, v)
    type(sim_t), intent(inout) :: sim           !! simulation
    logical, intent(in) :: moving(max_gears)    !! gear i moves [-]
    real(wp), intent(in) :: v(max_nv)           !! velocities [m/s, rad/s]
    integer :: first(max_gears), nv, i
    call vel_layout(sim, first, nv)
    sim%model%body%v = v(1:3)
    sim%model%body%omega = v(4:6)
    do i = 1, sim%model%par%n_gears
      if (moving(i)) call sim%model%gear(i)%g%set_rates(v(first(i):first(i) + sim%model%par%n_q(i) - 1))
    end do
  end subroutine sim_scatter_velocities

  !> The accelerations of an evaluation as a vector (vel_layout); zero for gears that do not move.
  pure subroutine sim_gather_accelerations(sim, ev, moving, a)
    type(sim_t), intent(in) :: sim              !! simulation
    type(sim_eval_t), intent(in) :: ev          !! evaluation
    logical, intent(in) :: moving(max_gears)    !! gear i moves [-]
    real(wp), intent(out) :: a(max_nv)          !! accelerations [m/s^2, rad/s^2]
    integer :: first(max_gears), nv, i, nq
    call vel_layout(sim, first, nv)
    a(1:3) = ev%acc
    a(4:6) = ev%alpha
    do i = 1, sim%model%par%n_gears
      nq = sim%model%par%n_q(i)
      if (moving(i)) then
        a(first(i):first(i) + nq - 1) = ev%gear(i)%qdd(1:nq)
      else
        a(first(i):first(i) + nq - 1) = 0.0_wp
      end if
    end do
  end subroutine sim_gather_accelerations

  !> The crush law's decision over the step: each moving gear locks the crushing struts whose
  !! stroke rate reverses between the committed velocities and the end-of-step velocities v_end.
  subroutine sim_arrest(sim, moving, v_end)
    type(sim_t), intent(inout) :: sim           !! simulation (committed state of the step's start)
    logical, intent(in) :: moving(max_gears)    !! gear i moves [-]
    real(wp), intent(in) :: v_end(max_nv)       !! end-of-step velocities [m/s, rad/s]
    integer :: first(max_gears), nv, i
    call vel_layout(sim, first, nv)
    do i = 1, sim%model%par%n_gears
      if (moving(i)) call sim%model%gear(i)%g%arrest(v_end(first(i):first(i) + sim%model%par%n_q(i) - 1))
    end do
  end subroutine sim_arrest

  !> Moves the positions along the velocity vector v for h: the body (attitude through the Euler
  !! rates) and every moving gear (with its crush work). The stored velocities are not changed.
  subroutine sim_increment_positions(sim, moving, v, h)
    type(sim_t), intent(inout) :: sim           !! simulation
    logical, intent(in) :: moving(max_gears)    !! gear i moves [-]
    real(wp), intent(in) :: v(max_nv)           !! velocities to move with [m/s, rad/s]
    real(wp), intent(in) :: h                   !! duration [s]
    integer :: first(max_gears), nv, i
    call vel_layout(sim, first, nv)
    call body_increment(sim%model%body, v(1:3), v(4:6), h)
    do i = 1, sim%model%par%n_gears
      if (moving(i)) call sim%model%gear(i)%g%increment(v(first(i):first(i) + sim%model%par%n_q(i) - 1), h)
    end do
  end subroutine sim_increment_positions

  !> Projects each moving gear's coordinates onto its constraints (Step 4's position half).
  subroutine sim_project_positions(sim, moving, t, st)
    type(sim_t), intent(inout) :: sim           !! simulation (tolerances from its parameters)
    logical, intent(in) :: moving(max_gears)    !! gear i moves [-]
    real(wp), intent(in) :: t                   !! time of the state (messages) [s]
    type(status_t), intent(out) :: st           !! STAT_OK, or the gear's failure with its context [-]
    integer :: i
    do i = 1, sim%model%par%n_gears
      if (.not. moving(i)) cycle
      call sim%model%gear(i)%g%correct_positions(sim%par%constraint_tol, sim%par%max_correction_iter, &
                                                 sim%par%max_constraint_drift, st)
      if (st%code /= STAT_OK) then
        call st%add_context('gear', t, i)
        return
      end if
    end do
  end subroutine sim_project_positions

  !> Projects the velocities of body and gears onto the velocity constraints in the kinetic
  !! metric of the whole model (a plastic impact of the constrained system); its loss is booked
  !! in the recorder's w_impact.
  subroutine sim_project_velocities(sim, t, st)
    type(sim_t), intent(inout) :: sim           !! simulation (tolerance from its parameters)
    real(wp), intent(in) :: t                   !! time of the state (messages) [s]
    type(status_t), intent(out) :: st           !! STAT_OK, or the projection's failure with its context [-]
    real(wp) :: e_imp
    call system_velocity_projection(sim%model%body, sim%model%gear, sim%model%par%n_gears, &
                                    sim%par%constraint_tol, e_imp, st)
    if (st%code /= STAT_OK) then
      call st%add_context('velocity projection', t)
      return
    end if
    sim%rec%w_impact = sim%rec%w_impact + e_imp
  end subroutine sim_project_velocities

  !> After the step: the footpad histories and stick states of the evaluation it was taken with,
  !! gears whose struts are all locked become rigid (with their caches), the step is counted.
  subroutine sim_commit_discrete(sim, ev, t, st)
    type(sim_t), intent(inout) :: sim           !! simulation after the step
    type(sim_eval_t), intent(in) :: ev          !! the evaluation the step was taken with
    real(wp), intent(in) :: t                   !! time reached (messages) [s]
    type(status_t), intent(out) :: st           !! STAT_OK, or the gear's failure with its context [-]
    integer :: i, ng
    ng = sim%model%par%n_gears
    sim%model%footpad(1:ng) = ev%trial(1:ng)
    sim%state%xd_stick(:, 1:ng) = ev%xd(:, 1:ng)   ! the positions those stick states belong to
    sim%state%t_stick = ev%t                       ! and their time
    do i = 1, ng
      call sim%model%gear(i)%g%settle()
      call sim%model%gear(i)%g%prepare(st)
      if (st%code /= STAT_OK) then
        call st%add_context('gear', t, i)
        return
      end if
    end do
    sim%state%n = sim%state%n + 1
  end subroutine sim_commit_discrete

end module landyn_sim_state
