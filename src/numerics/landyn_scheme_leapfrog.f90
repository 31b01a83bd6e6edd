!> The leapfrog (semi-implicit Euler) update of the paper's scheme, Fig. 6 Steps 4 and 6, written
!! on the model's integrator operations (landyn_sim_state): the scheme of the 'fixed' and
!! 'adaptive' integrators. With positions at t and the stored velocities half a step behind:
!!
!!   v <- v + kick a(t)             (kick = h for the fixed scheme, (h_last + h)/2 for variable steps)
!!   crush decisions over the step  (a crushing strut whose rate reverses locks: sim_arrest)
!!   x <- x + h v                   (rotations through the Euler-angle rates)
!!   x projected onto the gears' constraints, v onto the system's (a plastic impact)
!!   discrete state committed (footpad histories, rigid gears)
module landyn_scheme_leapfrog
  use landyn_kinds, only: wp, max_gears
  use landyn_status, only: status_t
  use landyn_sim_model, only: sim_t, sim_eval_t
  use landyn_sim_state, only: max_nv, sim_commit_evaluation, sim_moving, sim_gather_velocities, &
                              sim_scatter_velocities, sim_gather_accelerations, sim_arrest, sim_increment_positions, &
                              sim_project_positions, sim_project_velocities, sim_commit_discrete
  implicit none
  private

  public :: leapfrog_advance, leapfrog_move

contains

  !> One leapfrog step of length h from the state evaluated in `ev`. stat /= 0 (drift, no
  !! convergence, projection failure) leaves the simulation in an unusable state: restore a
  !! snapshot or stop.
  subroutine leapfrog_advance(sim, ev, h, st, kick)
    type(sim_t), intent(inout) :: sim           !! simulation, advanced to ev%t + h
    type(sim_eval_t), intent(in) :: ev          !! evaluation of the state at t (sim_evaluate)
    real(wp), intent(in) :: h                   !! step [s]
    type(status_t), intent(out) :: st           !! STAT_OK, or the failure with its context [-]
    real(wp), intent(in), optional :: kick      !! velocity update length (variable-step leapfrog, the
                                                !! step the evaluation was made for); default h [s]
    real(wp) :: v(max_nv), a(max_nv), hk
    logical :: moving(max_gears)
    integer :: nv

    hk = h
    if (present(kick)) hk = kick
    call sim_commit_evaluation(sim, ev)
    call sim_moving(sim, moving)
    call sim_gather_velocities(sim, v, nv)
    call sim_gather_accelerations(sim, ev, moving, a)
    v(1:nv) = v(1:nv) + a(1:nv)*hk
    call leapfrog_move(sim, ev, moving, v, h, st)
  end subroutine leapfrog_advance

  !> The rest of a leapfrog step once the end-of-step velocities v are known (every scheme written
  !! on the leapfrog shares it): the crush decisions over the step, positions moved with v for h,
  !! projected onto the constraints (positions, then velocities), the discrete state committed.
  subroutine leapfrog_move(sim, ev, moving, v, h, st)
    type(sim_t), intent(inout) :: sim           !! simulation with ev committed, advanced to ev%t + h
    type(sim_eval_t), intent(in) :: ev          !! evaluation the step is taken with
    logical, intent(in) :: moving(max_gears)    !! gear i moves [-]
    real(wp), intent(in) :: v(max_nv)           !! end-of-step velocities [m/s, rad/s]
    real(wp), intent(in) :: h                   !! step [s]
    type(status_t), intent(out) :: st           !! STAT_OK, or the failure with its context [-]
    call sim_arrest(sim, moving, v)
    call sim_scatter_velocities(sim, moving, v)
    call sim_increment_positions(sim, moving, v, h)
    call sim_project_positions(sim, moving, ev%t + h, st)
    if (.not. st%ok()) return
    call sim_project_velocities(sim, ev%t + h, st)
    if (.not. st%ok()) return
    call sim_commit_discrete(sim, ev, ev%t + h, st)
  end subroutine leapfrog_move

end module landyn_scheme_leapfrog
