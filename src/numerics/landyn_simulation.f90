!> One touchdown simulation: builds the model (landyn_sim_core), makes the integrator chosen in
!! &simulation (make_integrator of the integrator registry landyn_integrators) and steps it to the
!! end of the run. Re-exports the model and result types the callers use.
module landyn_simulation
  use, intrinsic :: iso_fortran_env, only: int64
  use landyn_kinds, only: wp
  use landyn_config, only: landyn_input_t
  use landyn_status, only: status_t
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
  subroutine run_simulation(inp, res, st, progress_unit, loads)
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input
    type(sim_result_t), intent(out) :: res      !! time series and summary
    type(status_t), intent(out) :: st           !! STAT_OK (also for a tip-over); the failure with its message [-]
    integer, intent(in) :: progress_unit        !! unit for progress lines, < 0 for none
    logical, intent(in), optional :: loads      !! compute the interface loads (default .true.; a caller
                                                !! that keeps only summary metrics saves ~10 % of the time
                                                !! with .false.; their histories and peaks are then zero) [-]
    type(sim_t) :: sim
    class(integrator_t), allocatable :: integ
    logical :: done
    integer(int64) :: c0, c1, crate

    call system_clock(c0, crate)
    call sim_init(inp, sim, res, st)
    if (.not. st%ok()) return
    if (present(loads)) sim%par%loads = loads
    call make_integrator(inp, integ, st)
    if (.not. st%ok()) return
    call integ%start(sim, inp, res, st)
    if (.not. st%ok()) return
    do
      call integ%step(sim, res, done, st, progress_unit)
      if (.not. st%ok() .or. done) exit
    end do
    ! ---- the end state for the outcome (landyn_outcome classifies it)
    res%touched = sim%state%touched
    res%end_motion = measure_motion(sim%model)
    call system_clock(c1)
    res%wall_time = real(c1 - c0, wp)/real(crate, wp)
  end subroutine run_simulation

end module landyn_simulation
