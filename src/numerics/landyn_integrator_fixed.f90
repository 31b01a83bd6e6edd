!> The paper's scheme (Fig. 6): semi-implicit Euler with the fixed step &simulation dt, every
!! step evaluated, advanced and committed (landyn_sim_core's sim_step). Kept for comparison with
!! the paper and with heritage fixed-step codes.
module landyn_integrator_fixed
  use landyn_kinds, only: wp
  use landyn_status, only: STAT_INPUT, status_t
  use landyn_config, only: landyn_input_t
  use landyn_sim_core, only: sim_t, sim_result_t, sim_eval_t, sim_step, sim_evaluate, record_sample
  use landyn_real_text, only: fmt_real
  use landyn_integrator, only: integrator_t, integrator_build_t
  implicit none
  private

  public :: fixed_integrator_t, build

  !> Fixed-step integrator (the step count lives in the simulation).
  type, extends(integrator_t) :: fixed_integrator_t
    real(wp) :: dt = 0.0_wp    !! the step [s]
    type(sim_eval_t) :: ev     !! work record of each step's evaluation
  contains
    procedure :: start => fixed_start   !! checks the simulation was set up with &simulation dt; t = 0 is left to the first step
    procedure :: step => fixed_step     !! one sim_step of dt (evaluate, advance, commit)
    procedure :: retarget => fixed_retarget   !! checks that a stop time is a whole number of steps
    procedure :: sample => fixed_sample       !! the sample of the current state, evaluated as the next step will
  end type fixed_integrator_t

contains

  !> The registry's builder of 'fixed' (landyn_integrators).
  subroutine build(b)
    type(integrator_build_t), intent(inout) :: b   !! the build
    allocate (fixed_integrator_t :: b%integ)
  end subroutine build

  !> Nothing to prepare: the first sim_step evaluates and records t = 0.
  subroutine fixed_start(self, sim, inp, res, st)
    class(fixed_integrator_t), intent(inout) :: self  !! integrator
    type(sim_t), intent(inout) :: sim                 !! simulation at t = 0
    type(landyn_input_t), intent(in) :: inp           !! resolved, validated input
    type(sim_result_t), intent(inout) :: res          !! result
    type(status_t), intent(out) :: st                 !! STAT_OK, STAT_INPUT with a message [-]
    self%dt = inp%simulation%dt
    if (.not. (self%dt > 0.0_wp .and. abs(sim%par%dt - self%dt) <= 0.0_wp)) then
      call st%fail(STAT_INPUT, 'fixed integrator: the simulation was not set up with &simulation dt')
      return
    end if
    res%integrator = 'fixed'
    res%dt_smallest = self%dt
    res%dt_largest = self%dt
  end subroutine fixed_start

  !> One step of the paper's scheme.
  subroutine fixed_step(self, sim, res, done, st, progress_unit)
    class(fixed_integrator_t), intent(inout) :: self  !! integrator
    type(sim_t), intent(inout) :: sim                 !! simulation, advanced by one step (of its dt, self%dt)
    type(sim_result_t), intent(inout) :: res          !! time series and summary
    logical, intent(out) :: done                      !! the run has ended
    type(status_t), intent(out) :: st                 !! STAT_OK, or the failure with its message [-]
    integer, intent(in) :: progress_unit              !! unit for progress lines, < 0 for none
    call sim_step(sim, res, done, st, progress_unit, self%ev)
    res%n_evaluations = res%n_evaluations + 1
  end subroutine fixed_step

  !> A stop time (sim%t_stop before t_end) must be a whole number of steps dt: the state after n
  !! steps is then the run's at n dt. Engine inputs need nothing: the state is evaluated at the
  !! start of the next step.
  subroutine fixed_retarget(self, sim, n_eval, st)
    class(fixed_integrator_t), intent(inout) :: self  !! integrator
    type(sim_t), intent(inout) :: sim                 !! simulation
    integer, intent(out) :: n_eval                    !! force evaluations made (none) [-]
    type(status_t), intent(out) :: st                 !! STAT_OK, or STAT_INPUT for a stop time between steps [-]
    real(wp) :: steps
    n_eval = 0
    sim%ext_changed = .false.
    if (sim%t_stop >= sim%par%t_end) return
    steps = sim%t_stop/self%dt
    if (abs(steps - anint(steps)) > 1.0e-9_wp*max(1.0_wp, steps)) then
      call st%fail(STAT_INPUT, 'fixed integrator: t = '//fmt_real(sim%t_stop)// &
                   ' s is not a whole number of steps &simulation dt = '//fmt_real(self%dt)//' s')
    end if
  end subroutine fixed_retarget

  !> The sample of the state after the last step, with the evaluation its next step makes.
  subroutine fixed_sample(self, sim, res, st)
    class(fixed_integrator_t), intent(inout) :: self  !! integrator (its work record is used)
    type(sim_t), intent(inout) :: sim                 !! simulation (velocities restored on return)
    type(sim_result_t), intent(inout) :: res          !! result the sample is appended to
    type(status_t), intent(out) :: st                 !! STAT_OK, or the evaluation's failure [-]
    call sim_evaluate(sim, sim%state%n*self%dt, self%dt, self%ev, st)
    if (.not. st%ok()) return
    call record_sample(sim, res, self%ev, self%dt)
  end subroutine fixed_sample

end module landyn_integrator_fixed
