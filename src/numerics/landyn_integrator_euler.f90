!> Throw-away demonstration: explicit (forward) Euler at the fixed step &simulation dt, written on
!! the model's operations (landyn_sim_state) only. Positions move with the velocities of the step's
!! start, velocities with the accelerations of the step's start.
module landyn_integrator_euler
  use landyn_kinds, only: wp, max_gears
  use landyn_status, only: STAT_OK, STAT_INPUT
  use landyn_config, only: landyn_input_t
  use landyn_sim_core, only: sim_t, sim_result_t, sim_eval_t, sim_evaluate, sim_book, sim_accept, finish, &
                            record_sample
  use landyn_sim_state, only: max_nv, sim_commit_evaluation, sim_moving, sim_gather_velocities, &
                              sim_scatter_velocities, sim_gather_accelerations, sim_arrest, sim_increment_positions, &
                              sim_project_positions, sim_project_velocities, sim_commit_discrete
  use landyn_integrator, only: integrator_t, integrator_build_t
  implicit none
  private

  public :: euler_integrator_t, build

  !> Forward Euler at a fixed step.
  type, extends(integrator_t) :: euler_integrator_t
    real(wp) :: dt = 0.0_wp    !! the step [s]
    type(sim_eval_t) :: ev     !! the step's evaluation
  contains
    procedure :: start => euler_start   !! the step from the deck
    procedure :: step => euler_step     !! one step
    procedure :: retarget => euler_retarget   !! no stop times but the end
    procedure :: sample => euler_sample       !! the sample of the current state
  end type euler_integrator_t

contains

  !> The registry's builder of 'euler' (landyn_integrators).
  subroutine build(b)
    type(integrator_build_t), intent(inout) :: b   !! the build
    allocate (euler_integrator_t :: b%integ)
  end subroutine build

  !> The step from the deck.
  subroutine euler_start(self, sim, inp, res, stat, errmsg)
    class(euler_integrator_t), intent(inout) :: self  !! integrator
    type(sim_t), intent(inout) :: sim                 !! simulation at t = 0
    type(landyn_input_t), intent(in) :: inp           !! resolved, validated input
    type(sim_result_t), intent(inout) :: res          !! result
    integer, intent(out) :: stat                      !! 0 on success
    character(len=*), intent(inout) :: errmsg         !! message on failure
    stat = STAT_OK
    self%dt = inp%simulation%dt
    sim%dt = self%dt
    res%integrator = 'euler'
    res%dt_smallest = self%dt
    res%dt_largest = self%dt
    if (.false.) errmsg = ''
  end subroutine euler_start

  !> x <- x + h v(t), v <- v + h a(t), then the projections.
  subroutine euler_step(self, sim, inp, res, done, stat, errmsg, progress_unit)
    class(euler_integrator_t), intent(inout) :: self  !! integrator
    type(sim_t), intent(inout) :: sim                 !! simulation, advanced by one step
    type(landyn_input_t), intent(in) :: inp           !! resolved, validated input
    type(sim_result_t), intent(inout) :: res          !! time series and summary
    logical, intent(out) :: done                      !! the run has ended
    integer, intent(out) :: stat                      !! 0 on success
    character(len=*), intent(inout) :: errmsg         !! diagnosis on failure
    integer, intent(in) :: progress_unit              !! unit for progress lines, < 0 for none
    real(wp) :: t, h, v0(max_nv), v1(max_nv), a(max_nv)
    logical :: moving(max_gears)
    integer :: nv
    done = .false.
    h = self%dt
    t = sim%loop%n*h
    call sim_evaluate(sim, inp, t, h, self%ev, stat, errmsg)
    res%n_evaluations = res%n_evaluations + 1
    if (stat /= STAT_OK) then
      call finish(sim%model, res, t); done = .true.; return
    end if
    call sim_book(sim, inp, res, self%ev, 0.0_wp, 0.5_wp*h)
    if (sim%loop%n == sim%nstep) then
      call finish(sim%model, res, t); done = .true.; return
    end if
    call sim_commit_evaluation(sim, self%ev)
    call sim_moving(sim, moving)
    call sim_gather_velocities(sim, v0, nv)
    call sim_gather_accelerations(sim, self%ev, moving, a)
    v1(1:nv) = v0(1:nv) + h*a(1:nv)
    call sim_arrest(sim, moving, v1)
    call sim_increment_positions(sim, moving, v0, h)
    call sim_scatter_velocities(sim, moving, v1)
    call sim_project_positions(sim, inp, moving, t + h, stat, errmsg)
    if (stat == STAT_OK) call sim_project_velocities(sim, inp, t + h, stat, errmsg)
    if (stat == STAT_OK) call sim_commit_discrete(sim, self%ev, t + h, stat, errmsg)
    if (stat /= STAT_OK) then
      call finish(sim%model, res, t + h); done = .true.; return
    end if
    call sim_accept(sim, inp, res, t + h, h, done, stat, errmsg, progress_unit, .false.)
  end subroutine euler_step

  !> No stop time before the end of the run (a throw-away integrator).
  subroutine euler_retarget(self, sim, inp, n_eval, stat, errmsg)
    class(euler_integrator_t), intent(inout) :: self  !! integrator
    type(sim_t), intent(inout) :: sim                 !! simulation
    type(landyn_input_t), intent(in) :: inp           !! resolved, validated input
    integer, intent(out) :: n_eval                    !! force evaluations made (none) [-]
    integer, intent(out) :: stat                      !! 0, or STAT_INPUT for a stop time before t_end
    character(len=*), intent(inout) :: errmsg         !! diagnosis on failure
    n_eval = 0
    stat = STAT_OK
    sim%ext_changed = .false.
    if (sim%t_stop < inp%simulation%t_end) then
      stat = STAT_INPUT
      errmsg = 'euler integrator: no stop times'
      if (.false.) self%dt = 0.0_wp
    end if
  end subroutine euler_retarget

  !> The sample of the current state.
  subroutine euler_sample(self, sim, inp, res, stat, errmsg)
    class(euler_integrator_t), intent(inout) :: self  !! integrator (its work record is used)
    type(sim_t), intent(inout) :: sim                 !! simulation
    type(landyn_input_t), intent(in) :: inp           !! resolved, validated input
    type(sim_result_t), intent(inout) :: res          !! result the sample is appended to
    integer, intent(out) :: stat                      !! 0 on success
    character(len=*), intent(inout) :: errmsg         !! diagnosis on failure
    call sim_evaluate(sim, inp, sim%loop%t, self%dt, self%ev, stat, errmsg)
    if (stat /= 0) return
    call record_sample(sim, inp, res, self%ev, self%dt)
  end subroutine euler_sample

end module landyn_integrator_euler
