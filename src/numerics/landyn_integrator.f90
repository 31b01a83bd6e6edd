!> The time-integrator interface: an integrator advances a simulation (landyn_sim_core's sim_t)
!! by one accepted step at a time, from the state sim_init built to the end of the run. The
!! implementations are chosen in &simulation integrator from the integrator registry
!! (landyn_integrators); each integrator module has a builder `build(b)`, b an integrator_build_t,
!! that allocates b%integ.
!!
!! A caller that drives a simulation to times of its own (landyn_session, the C API) sets
!! sim%t_stop and the engine inputs, calls `retarget`, steps until sim%state%t reaches t_stop, and
!! reads the state's output sample with `sample`.
module landyn_integrator
  use landyn_config, only: landyn_input_t
  use landyn_status, only: status_t
  use landyn_sim_core, only: sim_t, sim_result_t
  use landyn_law_checks, only: law_build_t
  implicit none
  private

  public :: integrator_t, integrator_build_t

  !> An integrator: start once after sim_init, then step until done.
  type, abstract :: integrator_t
  contains
    procedure(start_iface), deferred :: start   !! first evaluation and output sample at t = 0
    procedure(step_iface), deferred :: step     !! one accepted step (or the end of the run)
    procedure(retarget_iface), deferred :: retarget  !! takes a new sim%t_stop or changed engine inputs into account
    procedure(sample_iface), deferred :: sample      !! the output sample of the current state
  end type integrator_t

  !> A build of the integrator registry (landyn_integrators): group 'simulation', variable
  !! 'integrator'.
  type, extends(law_build_t) :: integrator_build_t
    class(integrator_t), allocatable :: integ     !! the integrator built
  end type integrator_build_t

  abstract interface
    !> Prepares the integrator once after sim_init (step settings from the input; the adaptive one also
    !! evaluates and records t = 0, the fixed one leaves that to its first step).
    subroutine start_iface(self, sim, inp, res, st)
      import :: integrator_t, sim_t, landyn_input_t, sim_result_t, status_t
      class(integrator_t), intent(inout) :: self   !! integrator
      type(sim_t), intent(inout) :: sim            !! simulation at t = 0 (from sim_init)
      type(landyn_input_t), intent(in) :: inp      !! resolved, validated input (the integrator's settings)
      type(sim_result_t), intent(inout) :: res     !! result
      type(status_t), intent(out) :: st            !! STAT_OK, or the failure with its message [-]
    end subroutine start_iface

    !> Advances the simulation by one accepted step, records output, and says when the run has ended.
    subroutine step_iface(self, sim, res, done, st, progress_unit)
      import :: integrator_t, sim_t, sim_result_t, status_t
      class(integrator_t), intent(inout) :: self   !! integrator
      type(sim_t), intent(inout) :: sim            !! simulation, advanced by one step
      type(sim_result_t), intent(inout) :: res     !! time series and summary
      logical, intent(out) :: done                 !! the run has ended (end time, rest, tip-over, failure)
      type(status_t), intent(out) :: st            !! STAT_OK (also for a tip-over), else the failure [-]
      integer, intent(in) :: progress_unit         !! unit for progress lines, < 0 for none
    end subroutine step_iface

    !> After the caller set sim%t_stop or changed the engine inputs (sim%ext_changed, cleared here):
    !! checks the stop time and makes the next step end on it, the current state evaluated with the
    !! inputs now applied.
    subroutine retarget_iface(self, sim, n_eval, st)
      import :: integrator_t, sim_t, status_t
      class(integrator_t), intent(inout) :: self   !! integrator
      type(sim_t), intent(inout) :: sim            !! simulation at its current state
      integer, intent(out) :: n_eval               !! force evaluations made [-]
      type(status_t), intent(out) :: st            !! STAT_OK; STAT_INPUT for a stop time the integrator
                                                   !! cannot end a step on; else the failure [-]
    end subroutine retarget_iface

    !> Appends to `res` the output sample the result file would hold for the current state (its
    !! evaluation as the integrator's next step uses it); the simulation is left as it was.
    subroutine sample_iface(self, sim, res, st)
      import :: integrator_t, sim_t, sim_result_t, status_t
      class(integrator_t), intent(inout) :: self   !! integrator
      type(sim_t), intent(inout) :: sim            !! simulation (velocities restored on return)
      type(sim_result_t), intent(inout) :: res     !! result the sample is appended to
      type(status_t), intent(out) :: st            !! STAT_OK, or the failure with its message [-]
    end subroutine sample_iface
  end interface

end module landyn_integrator
