!> One touchdown simulation: builds the model (landyn_sim_core), makes the integrator chosen in
!! &simulation (make_integrator of the integrator registry landyn_integrators) and steps it to the
!! end of the run. Re-exports the model and result types the callers use.
module landyn_simulation
  use, intrinsic :: iso_fortran_env, only: int64
  use landyn_kinds, only: wp
  use landyn_config, only: landyn_input_t
  use landyn_sim_core, only: sim_result_t, sim_t, sim_snapshot_t, sim_init, sim_step, &
                             sim_save, sim_restore, n_energy, energy_names
  use landyn_integrator, only: integrator_t
  use landyn_integrators, only: make_integrator
  use landyn_rest, only: measure_motion
  implicit none
  private

  public :: sim_result_t, run_simulation
  public :: sim_t, sim_snapshot_t, sim_init, sim_step, sim_save, sim_restore
  public :: n_energy, energy_names

contains

  !> Runs one landing. `progress_unit` < 0 silences progress reports.
  subroutine run_simulation(inp, res, stat, errmsg, progress_unit, loads)
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input
    type(sim_result_t), intent(out) :: res      !! time series and summary
    integer, intent(out) :: stat                !! 0 on success (also for a tip-over); /= 0 on divergence
    character(len=*), intent(inout) :: errmsg   !! diagnosis on failure
    integer, intent(in) :: progress_unit        !! unit for progress lines, < 0 for none
    logical, intent(in), optional :: loads      !! compute the interface loads (default .true.; a caller
                                                !! that keeps only summary metrics saves ~10 % of the time
                                                !! with .false.; their histories and peaks are then zero) [-]
    type(sim_t) :: sim
    class(integrator_t), allocatable :: integ
    logical :: done
    integer(int64) :: c0, c1, crate

    call system_clock(c0, crate)
    call sim_init(inp, sim, res, stat, errmsg)
    if (stat /= 0) return
    if (present(loads)) sim%loads = loads
    call make_integrator(inp, integ, stat, errmsg)
    if (stat /= 0) return
    call integ%start(sim, inp, res, stat, errmsg)
    if (stat /= 0) return
    do
      call integ%step(sim, inp, res, done, stat, errmsg, progress_unit)
      if (stat /= 0 .or. done) exit
    end do
    ! ---- the end state for the outcome (landyn_outcome classifies it)
    res%touched = sim%loop%touched
    res%end_motion = measure_motion(sim%model)
    call system_clock(c1)
    res%wall_time = real(c1 - c0, wp)/real(crate, wp)
  end subroutine run_simulation

end module landyn_simulation
