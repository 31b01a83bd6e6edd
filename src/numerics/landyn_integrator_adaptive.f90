!> Error-controlled variable-step integration with event location (&simulation integrator =
!! 'adaptive', the default). Each step is the paper's semi-implicit Euler step with the crush
!! logic, correction and plastic-impact projection of landyn_sim_core, over a step size chosen as
!! follows (docs/theory.md, "Adaptive integrator"):
!!
!! * Local error: the step is the leapfrog, whose velocity update (the kick) is the midpoint rule
!!   with local error h^3/24 |a''|. a'' is estimated from the second divided difference of the
!!   accelerations at t - h_last, t and t + h: of the body (angular ones times the lander's size)
!!   and of every gear coordinate (times the gear's weight: angles times their strut's length). That estimate is held below
!!   `tolerance` [m/s] per step. Right after an event (where a'' is undefined) and at the first
!!   step the first-order estimate h/2 |a(t+h) - a(t)| is used instead. The accelerations at t + h
!!   are those the next step needs anyway: one force evaluation per accepted step.
!! * Events: a change of the discrete state over a step (a strut's mode: locked, crushing either
!!   way or free; a stage end or end-of-stroke stop of its buffer law; a footpad touching down or
!!   lifting off; a stick state; the tilt passing the tip-over angle) is located as the zero of its
!!   switching function (landyn_event_locator) by regula falsi with the Illinois modification on a
!!   bracket of steps: the step that found it is its end, each retry from the current state aims
!!   half of `event_resolution` [s] before the estimated zero (a rejected retry moves the end),
!!   each accepted one is followed by a step aimed half of it past the zero, until the step that
!!   contains the change is no longer than `event_resolution`; then the step that found the event
!!   is tried again. Changes without a switching function (buffer-law segments) are bisected.
!! * A step whose correction drifts or fails, or whose state is not finite, is retried at a
!!   quarter of its length.
!! * Steps end exactly on the output times and on t_end.
!! * Variable steps need the variable-step leapfrog: the stored velocities belong to the middle of
!!   each step, so the velocity update between steps h_last and h is (h_last + h)/2 times the
!!   accelerations (the fixed scheme's h when the steps are equal). Updating by h instead makes an
!!   error a (h_last - h)/2 at every change of step, first order and outside the error estimate.
module landyn_integrator_adaptive
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use landyn_kinds, only: wp
  use landyn_config, only: landyn_input_t
  use landyn_sim_core, only: sim_t, sim_result_t, sim_eval_t, sim_snapshot_t, sim_save, sim_restore, &
                             sim_evaluate, sim_book, sim_accept, finish, body_is_finite, record_sample
  use landyn_status, only: STAT_FAILED, STAT_NO_STEP, status_t, time_text
  use landyn_integrator, only: integrator_t, integrator_build_t
  use landyn_scheme_leapfrog, only: leapfrog_advance
  use landyn_event_locator, only: event_fraction
  implicit none
  private

  public :: adaptive_integrator_t, build, error_norm, error_norm2, discrete_change, weighted_max, predicted_field

  !> Adaptive integrator and its state between steps.
  type, extends(integrator_t) :: adaptive_integrator_t
    real(wp) :: tol = 1.0e-3_wp            !! local velocity error per step [m/s]
    real(wp) :: h_min = 1.0e-9_wp          !! smallest step [s]
    real(wp) :: h_max = 1.0e-3_wp          !! largest step [s]
    real(wp) :: h_event = 1.0e-6_wp        !! event resolution [s]
    real(wp) :: t_end = 0.0_wp             !! end time [s]
    real(wp) :: slack = 0.0_wp             !! times this close count as equal [s]
    real(wp) :: t = 0.0_wp                 !! time of the current state [s]
    real(wp) :: h = 0.0_wp                 !! step to take next [s]
    real(wp) :: h_last = 0.0_wp            !! last accepted step (0 at t = 0) [s]
    ! Three evaluation records, used in rotation (no copies on acceptance): evs(i_cur) is the
    ! evaluation of the current state, made for the step h; evs(i_prev) that of the previous
    ! accepted state; evs(i_new) the work record of the evaluation at the end of the step tried.
    type(sim_eval_t) :: evs(3)             !! evaluation records
    integer :: i_cur = 1                   !! slot of the current state's evaluation [-]
    integer :: i_prev = 2                  !! slot of the previous accepted state's [-]
    integer :: i_new = 3                   !! slot of the step tried [-]
    logical :: smooth = .false.            !! no event between the previous and the current evaluation:
                                           !! second differences apply
    type(sim_snapshot_t) :: snap(2)        !! snap(ip): the current state before that evaluation;
                                           !! the other slot takes the next state (no copy on acceptance)
    integer :: ip = 1                      !! slot of the current state's snapshot [-]
    ! Event bracket: an event lies between the current state and t_r, the end of a step tried from an
    ! earlier state of this approach that contained it, evaluated in ev_r.
    logical :: bracket = .false.           !! an event is being located [-]
    real(wp) :: t_r = 0.0_wp               !! end of the bracket [s]
    type(sim_eval_t) :: ev_r               !! evaluation at t_r [-]
    integer :: side = 0                    !! the bracket's last move: +1 its end (a rejection), -1 its start [-]
    integer :: n_same = 0                  !! moves of the same end in a row (Illinois) [-]
    real(wp) :: h_resume = 0.0_wp          !! step tried when the event was found, taken again after it [s]
  contains
    procedure :: start => adaptive_start   !! evaluates and records the state at t = 0
    procedure :: step => adaptive_step     !! one accepted step (retries and event location inside)
    procedure :: retarget => adaptive_retarget  !! the next step cut to sim%t_stop, the state evaluated again
    procedure :: sample => adaptive_sample      !! the sample of the current state from its evaluation
    ! the two parts a scheme on this step control replaces (landyn_integrator_imex)
    procedure :: advance => adaptive_advance          !! the update formula: the step h from the current state
    procedure :: local_error => adaptive_local_error  !! error / tolerance of the step just tried
    procedure, non_overridable :: kick                !! velocity update length of a step [s]
  end type adaptive_integrator_t

contains

  !> The registry's builder of 'adaptive' (landyn_integrators).
  subroutine build(b)
    type(integrator_build_t), intent(inout) :: b   !! the build
    allocate (adaptive_integrator_t :: b%integ)
  end subroutine build

  !> Reads the settings, evaluates and records t = 0; the first step tried is &simulation dt.
  subroutine adaptive_start(self, sim, inp, res, st)
    class(adaptive_integrator_t), intent(inout) :: self  !! integrator
    type(sim_t), intent(inout) :: sim                    !! simulation at t = 0
    type(landyn_input_t), intent(in) :: inp              !! resolved, validated input (the integrator's settings)
    type(sim_result_t), intent(inout) :: res             !! result
    type(status_t), intent(out) :: st                    !! STAT_OK, or the evaluation's failure [-]
    self%tol = inp%simulation%tolerance
    self%h_max = min(inp%simulation%dt_max, inp%output%interval)
    self%h_min = min(inp%simulation%dt_min, self%h_max)
    self%h_event = max(inp%simulation%event_resolution, self%h_min)
    self%t_end = inp%simulation%t_end
    self%slack = 1.0e-12_wp*max(1.0_wp, self%t_end)
    self%t = 0.0_wp
    self%h = clip(self, sim, 0.0_wp, max(self%h_min, min(inp%simulation%dt, self%h_max)))
    res%integrator = 'adaptive'
    res%dt_smallest = huge(1.0_wp)
    res%dt_largest = 0.0_wp
    self%ip = 1
    call sim_save(sim, self%snap(1))
    self%h_last = 0.0_wp
    call sim_evaluate(sim, 0.0_wp, self%kick(self%h), self%evs(self%i_cur), st)
    res%n_evaluations = res%n_evaluations + 1
    if (.not. st%ok()) then
      call finish(sim%model, res, 0.0_wp)
      return
    end if
    call sim_book(sim, res, self%evs(self%i_cur), 0.0_wp, self%slack)
    self%snap(1)%state = sim%state   ! a rejected first step returns to t = 0 as booked
    self%snap(1)%rec = sim%rec
  end subroutine adaptive_start

  !> One accepted step: tries the step h, estimates its error from the accelerations at both ends,
  !! looks for events, and retries shorter until the step is accepted; then books the new state,
  !! runs the checks and chooses the next step.
  subroutine adaptive_step(self, sim, res, done, st, progress_unit)
    class(adaptive_integrator_t), intent(inout) :: self  !! integrator
    type(sim_t), intent(inout) :: sim                    !! simulation, advanced by one step
    type(sim_result_t), intent(inout) :: res             !! time series and summary
    logical, intent(out) :: done                         !! the run has ended
    type(status_t), intent(out) :: st                    !! STAT_OK, or the failure with its context [-]
    integer, intent(in) :: progress_unit                 !! unit for progress lines, < 0 for none
    real(wp) :: h, h_g, t_new, err
    logical :: ok, event, rejected
    type(status_t) :: s_try

    done = .false.
    rejected = .false.
    do
      h = self%h
      h_g = h
      t_new = self%t + h
      if (t_new >= self%t_end - self%slack) then
        t_new = self%t_end
      else if (t_new >= sim%t_stop - self%slack) then
        t_new = sim%t_stop      ! a caller's stop time (landyn_session), reached exactly
      end if
      err = 0.0_wp
      event = .false.
      call self%advance(sim, h, s_try)
      ok = s_try%ok()
      if (ok) ok = body_is_finite(sim%model%body)
      if (ok) then
        h_g = clip(self, sim, t_new, h)
        call sim_save(sim, self%snap(3 - self%ip))
        call evaluate_end(self, sim, t_new, h, h_g, s_try)
        res%n_evaluations = res%n_evaluations + 1
        ok = s_try%ok()
      end if
      if (ok) then
        err = self%local_error(sim, h)
        event = discrete_change(self%evs(self%i_cur), self%evs(self%i_new), sim%model%par%n_gears, &
                                sim%par%tipover_angle)
      end if
      if ((.not. ok .and. h > self%h_min) .or. &
          (ok .and. h > self%h_event*(1.0_wp + 1.0e-9_wp) .and. (err > 1.0_wp .or. event))) then
        call retry(self, sim, res, h, ok, err, event, st)
        rejected = .true.
        if (.not. st%ok()) exit
        cycle
      end if
      if (.not. ok) then
        call st%fail(STAT_NO_STEP, s_try%text())
        call st%add_context(trim(res%integrator)//' integrator: no step down to dt_min = '//time_text(self%h_min, 3) &
                            //' s succeeds', self%t)
      end if
      exit
    end do
    if (.not. st%ok()) then   ! failed: the re-evaluation of t, or no step down to dt_min
      call finish(sim%model, res, self%t)
      done = .true.
      return
    end if

    ! accepted
    if (err > 1.0_wp) res%n_forced = res%n_forced + 1
    if (event) res%n_events = res%n_events + 1
    res%dt_smallest = min(res%dt_smallest, h)
    res%dt_largest = max(res%dt_largest, h)
    self%t = t_new
    self%h_last = h
    call sim_book(sim, res, self%evs(self%i_new), h, self%slack)
    call sim_accept(sim, res, t_new, h, done, st, progress_unit, &
                    t_new >= sim%rec%next_progress*self%t_end/20.0_wp, self%evs(self%i_new))
    if (done) return
    if (t_new >= self%t_end) then
      res%at_rest = sim%state%rest_clock >= sim%par%rest_time
      call finish(sim%model, res, self%t_end)
      done = .true.
      return
    end if
    call next_step(self, sim, t_new, h, h_g, err, event, rejected)
  end subroutine adaptive_step

  !> The evaluation at the end t_new of the step h just taken, made for the step h_g to follow. With
  !! the adaptive integrator's own frame field (frame_field_passes = 0) the legs' field is predicted
  !! from the last two accepted evaluations when no event lies between them (a second pass of the
  !! gears follows only where a lock changed); otherwise it is sim_evaluate's default.
  subroutine evaluate_end(self, sim, t_new, h, h_g, st)
    class(adaptive_integrator_t), intent(inout) :: self  !! integrator (its work record is filled)
    type(sim_t), intent(in) :: sim                       !! simulation at t_new
    real(wp), intent(in) :: t_new                        !! time of the state [s]
    real(wp), intent(in) :: h                            !! the step just taken [s]
    real(wp), intent(in) :: h_g                          !! the step the evaluation is made for [s]
    type(status_t), intent(out) :: st                    !! STAT_OK, or the evaluation's failure [-]
    real(wp) :: acc(3), alpha(3)
    if (sim%par%frame_field_passes == 0 .and. self%smooth .and. self%h_last > 0.0_wp) then
      associate (e1 => self%evs(self%i_cur), e0 => self%evs(self%i_prev))
        acc = predicted_field(e1%acc, e0%acc, h, self%h_last)
        alpha = predicted_field(e1%alpha, e0%alpha, h, self%h_last)
      end associate
      call sim_evaluate(sim, t_new, 0.5_wp*(h + h_g), self%evs(self%i_new), st, acc_field=acc, &
                        alpha_field=alpha, v_lead=0.5_wp*h)
    else
      call sim_evaluate(sim, t_new, 0.5_wp*(h + h_g), self%evs(self%i_new), st, v_lead=0.5_wp*h)
    end if
  end subroutine evaluate_end

  !> Linear extrapolation of a body acceleration h past the current evaluation (value a1) from it
  !! and the previous accepted one (a0, h_last before it): the frame field the adaptive integrator
  !! predicts for the evaluation at the end of its step, with an error O(h h_last) instead of the
  !! lagged field's O(h).
  pure function predicted_field(a1, a0, h, h_last) result(a)
    real(wp), intent(in) :: a1(3)       !! acceleration at the current state [m/s^2 or rad/s^2]
    real(wp), intent(in) :: a0(3)       !! acceleration at the previous accepted state [m/s^2 or rad/s^2]
    real(wp), intent(in) :: h           !! step from the current state [s]
    real(wp), intent(in) :: h_last      !! step from the previous state to the current one, > 0 [s]
    real(wp) :: a(3)                    !! predicted acceleration at the end of h [m/s^2 or rad/s^2]
    a = a1 + (h/h_last)*(a1 - a0)
  end function predicted_field

  !> A rejected step h: back to the state at t, the step to retry (a quarter after a failure, aimed
  !! at the event's zero after an event, from the error estimate otherwise), and the state at t
  !! evaluated again for it (in the field of the body accelerations of its first evaluation).
  subroutine retry(self, sim, res, h, ok, err, event, st)
    class(adaptive_integrator_t), intent(inout) :: self  !! integrator
    type(sim_t), intent(inout) :: sim                    !! simulation, back at t
    type(sim_result_t), intent(inout) :: res             !! counters
    real(wp), intent(in) :: h                            !! the rejected step [s]
    logical, intent(in) :: ok                            !! the step itself succeeded [-]
    real(wp), intent(in) :: err                          !! its error / tolerance [-]
    logical, intent(in) :: event                         !! it contained an event [-]
    type(status_t), intent(out) :: st                    !! STAT_OK, or the re-evaluation's failure [-]
    real(wp) :: hn, acc_t(3), alpha_t(3)
    call sim_restore(sim, self%snap(self%ip))
    if (.not. ok) then
      hn = 0.25_wp*h
    else if (event) then
      hn = aim_before(self, h, self%evs(self%i_cur), self%evs(self%i_new), sim%model%par%n_gears, &
                      sim%par%tipover_angle)
    else
      hn = h*max(0.1_wp, step_factor(err, self%smooth))
    end if
    if (ok) then
      self%h = clip(self, sim, self%t, max(hn, self%h_event))
    else
      self%h = clip(self, sim, self%t, max(hn, self%h_min))
    end if
    res%n_rejected = res%n_rejected + 1
    ! the body's accelerations at t are known from the first evaluation of t (copied: ev is
    ! intent(out) of sim_evaluate)
    acc_t = self%evs(self%i_cur)%acc
    alpha_t = self%evs(self%i_cur)%alpha
    call sim_evaluate(sim, self%t, self%kick(self%h), self%evs(self%i_cur), st, acc_field=acc_t, &
                      alpha_field=alpha_t, v_lead=0.5_wp*self%h_last)
    res%n_evaluations = res%n_evaluations + 1
  end subroutine retry

  !> After an accepted step h to t_new: the next step (the usual controller, err ~ h^3 for the
  !! second-difference estimate and ~ h^2 for the first-order one, growth at most 2 and none right
  !! after a rejection; within an event bracket the step aimed past the event's zero, after the
  !! located event the step that found it), then the records rotated.
  subroutine next_step(self, sim, t_new, h_step, h_g, err, event, rejected)
    class(adaptive_integrator_t), intent(inout) :: self  !! integrator
    type(sim_t), intent(inout) :: sim                    !! simulation at t_new
    real(wp), intent(in) :: t_new                        !! time reached [s]
    real(wp), intent(in) :: h_step                       !! the accepted step [s]
    real(wp), intent(in) :: h_g                          !! the step the evaluation at t_new was made for [s]
    real(wp), intent(in) :: err                          !! its error / tolerance [-]
    logical, intent(in) :: event                         !! it contained an event [-]
    logical, intent(in) :: rejected                      !! a step was rejected before it [-]
    real(wp) :: h, fac
    integer :: k
    fac = 2.0_wp
    if (err > 0.0_wp) fac = min(2.0_wp, step_factor(err, self%smooth))
    if (rejected) fac = min(fac, 1.0_wp)
    h = max(self%h_event, min(self%h_max, h_step*max(0.2_wp, fac)))
    if (event .and. self%bracket) then
      ! the located event is behind: back to the step that found it
      self%bracket = .false.
      h = max(h, min(self%h_resume, self%h_max))
    else if (self%bracket) then
      h = min(h, aim_after(self, t_new, self%evs(self%i_new), sim%model%par%n_gears, sim%par%tipover_angle))
    end if
    h = clip(self, sim, t_new, h)
    ! the evaluation at t_new decided its locks for h_g: keep h_g when a lock changed in it
    if (self%evs(self%i_new)%locks_changed) h = h_g
    self%h = h
    ! rotate the records: current -> previous, new -> current, the old previous is the next work record
    k = self%i_prev
    self%i_prev = self%i_cur
    self%i_cur = self%i_new
    self%i_new = k
    self%smooth = .not. event
    self%ip = 3 - self%ip
    self%snap(self%ip)%state = sim%state    ! a rejected step returns to this state as booked and checked
    self%snap(self%ip)%rec = sim%rec
  end subroutine next_step

  !> The step to retry after the step h from the current state (evaluated in e0) was rejected for
  !! an event (found in e1): it becomes the end of the bracket, and the retry aims half the event
  !! resolution before the zero of the switching functions (event_fraction; Illinois weight on e0
  !! when the end moved twice in a row), so that an accepted retry leaves the event within reach
  !! of one step of the event resolution. Half the step where the event cannot be located.
  function aim_before(self, h, e0, e1, ng, tip) result(hn)
    class(adaptive_integrator_t), intent(inout) :: self  !! integrator (its bracket is set)
    real(wp), intent(in) :: h                            !! the rejected step [s]
    type(sim_eval_t), intent(in) :: e0                   !! evaluation of the current state
    type(sim_eval_t), intent(in) :: e1                   !! evaluation at the end of the rejected step
    integer, intent(in) :: ng                            !! number of gears [-]
    real(wp), intent(in) :: tip                          !! tip-over angle [rad]
    real(wp) :: hn                                       !! step to retry [s]
    real(wp) :: theta
    logical :: located
    if (.not. self%bracket) then
      self%h_resume = h
      self%side = 0
    end if
    self%bracket = .true.
    self%t_r = self%t + h
    self%ev_r = e1
    if (self%side == 1) then
      self%n_same = self%n_same + 1
    else
      self%n_same = 1
    end if
    self%side = 1
    call event_fraction(e0, e1, ng, tip, 0.5_wp**(self%n_same - 1), 1.0_wp, theta, located)
    if (located) then
      hn = min(theta*h - 0.5_wp*self%h_event, 0.5_wp*(h + theta*h))
    else
      hn = 0.5_wp*h
    end if
  end function aim_before

  !> The next step after an accepted one that ended inside the bracket (the current state, evaluated
  !! in e0): aimed half the event resolution past the zero of the switching functions between e0
  !! and the bracket's end (Illinois weight on the end when the start moved twice in a row), never
  !! beyond that end. The bracket is dropped when the state has reached its end or no longer
  !! differs from it (the event did not happen on this path).
  function aim_after(self, t, e0, ng, tip) result(hn)
    class(adaptive_integrator_t), intent(inout) :: self  !! integrator with its bracket
    real(wp), intent(in) :: t                            !! time of the current state [s]
    type(sim_eval_t), intent(in) :: e0                   !! evaluation of the current state
    integer, intent(in) :: ng                            !! number of gears [-]
    real(wp), intent(in) :: tip                          !! tip-over angle [rad]
    real(wp) :: hn                                       !! largest next step [s]
    real(wp) :: theta, span
    logical :: located
    hn = huge(1.0_wp)
    span = self%t_r - t
    if (span <= self%slack .or. .not. discrete_change(e0, self%ev_r, ng, tip)) then
      self%bracket = .false.
      return
    end if
    if (self%side == -1) then
      self%n_same = self%n_same + 1
    else
      self%n_same = 1
    end if
    self%side = -1
    call event_fraction(e0, self%ev_r, ng, tip, 1.0_wp, 0.5_wp**(self%n_same - 1), theta, located)
    if (located) then
      hn = min(span, theta*span + 0.5_wp*self%h_event)
    else
      hn = 0.5_wp*span
    end if
    hn = max(hn, self%h_event)
  end function aim_after

  !> The leapfrog step h from the current state (evaluated in evs(i_cur)), with the variable-step kick.
  subroutine adaptive_advance(self, sim, h, st)
    class(adaptive_integrator_t), intent(inout) :: self  !! integrator
    type(sim_t), intent(inout) :: sim                    !! simulation, advanced by h
    real(wp), intent(in) :: h                            !! step [s]
    type(status_t), intent(out) :: st                    !! STAT_OK, or the step's failure with its context [-]
    call leapfrog_advance(sim, self%evs(self%i_cur), h, st, kick=self%kick(h))
  end subroutine adaptive_advance

  !> The local error of the step h just tried (evaluated in evs(i_new)) over the tolerance:
  !! error_norm2 from the last three evaluations, error_norm right after an event.
  function adaptive_local_error(self, sim, h) result(err)
    class(adaptive_integrator_t), intent(in) :: self     !! integrator (records)
    type(sim_t), intent(in) :: sim                       !! simulation (counts, size)
    real(wp), intent(in) :: h                            !! step tried [s]
    real(wp) :: err                                      !! error / tolerance [-]
    if (self%smooth) then
      err = error_norm2(self%evs(self%i_prev), self%evs(self%i_cur), self%evs(self%i_new), self%h_last, h, &
                        sim%par%l_char, self%tol, sim%model%par%n_gears)
    else
      err = error_norm(self%evs(self%i_cur), self%evs(self%i_new), h, sim%par%l_char, self%tol, sim%model%par%n_gears)
    end if
  end function adaptive_local_error

  !> A new stop time or new engine inputs from the caller: the step to take next cut to end on the
  !! stop time (clip), and where it changed or the inputs did, the current state evaluated again for
  !! it (as a retry does; at t = 0 as adaptive_start does), its thrust and input moment the start of
  !! the next step's work. A change of the inputs is an event: the next error estimate is the
  !! first-order one.
  subroutine adaptive_retarget(self, sim, n_eval, st)
    class(adaptive_integrator_t), intent(inout) :: self  !! integrator
    type(sim_t), intent(inout) :: sim                    !! simulation at self%t
    integer, intent(out) :: n_eval                       !! force evaluations made [-]
    type(status_t), intent(out) :: st                    !! STAT_OK, or the evaluation's failure [-]
    real(wp) :: hc, acc_t(3), alpha_t(3)
    logical :: changed
    n_eval = 0
    changed = sim%ext_changed
    sim%ext_changed = .false.
    hc = clip(self, sim, self%t, self%h)
    if (.not. changed .and. .not. (abs(hc - self%h) > 0.0_wp)) return
    self%h = hc
    if (changed) self%smooth = .false.
    if (self%h_last > 0.0_wp) then
      acc_t = self%evs(self%i_cur)%acc
      alpha_t = self%evs(self%i_cur)%alpha
      call sim_evaluate(sim, self%t, self%kick(self%h), self%evs(self%i_cur), st, acc_field=acc_t, &
                        alpha_field=alpha_t, v_lead=0.5_wp*self%h_last)
    else
      call sim_evaluate(sim, self%t, self%kick(self%h), self%evs(self%i_cur), st)
    end if
    n_eval = 1
    if (.not. st%ok()) return
    sim%rec%thrust_prev = self%evs(self%i_cur)%thrust_g
    sim%rec%moment_prev = self%evs(self%i_cur)%ext_moment
    self%snap(self%ip)%state = sim%state
    self%snap(self%ip)%rec = sim%rec
  end subroutine adaptive_retarget

  !> The sample of the current state from the evaluation the next step is taken with (the one
  !! sim_book recorded when the state was reached, or its re-evaluation by adaptive_retarget).
  subroutine adaptive_sample(self, sim, res, st)
    class(adaptive_integrator_t), intent(inout) :: self  !! integrator
    type(sim_t), intent(inout) :: sim                    !! simulation at self%t (velocities restored on return)
    type(sim_result_t), intent(inout) :: res             !! result the sample is appended to
    type(status_t), intent(out) :: st                    !! STAT_OK, or STAT_FAILED with a message [-]
    if (abs(self%evs(self%i_cur)%t - self%t) > 0.0_wp) then
      call st%fail(STAT_FAILED, trim(res%integrator)//' integrator: the current state has no evaluation')
      return
    end if
    call record_sample(sim, res, self%evs(self%i_cur), self%h_last)
  end subroutine adaptive_sample

  !> The usual step-size factor 0.9 err^(-1/p): p = 3 for the second-difference estimate (error
  !! ~ h^3), 2 for the first-order one (~ h^2).
  pure real(wp) function step_factor(err, second_order)
    real(wp), intent(in) :: err             !! error / tolerance, > 0 [-]
    logical, intent(in) :: second_order     !! the estimate was error_norm2 [-]
    if (second_order) then
      step_factor = 0.9_wp/err**(1.0_wp/3.0_wp)
    else
      step_factor = 0.9_wp/sqrt(err)
    end if
  end function step_factor

  !> Length of the velocity update of a step h after the last accepted step: the variable-step
  !! leapfrog's (h_last + h)/2, whose velocities belong to the middle of each step (h/2 for the
  !! first step, from the exact initial velocity).
  pure real(wp) function kick(self, h)
    class(adaptive_integrator_t), intent(in) :: self  !! integrator
    real(wp), intent(in) :: h                         !! step to take [s]
    kick = 0.5_wp*(self%h_last + h)
  end function kick

  !> A step proposal from t cut so that steps end exactly on the next output time and on t_end
  !! (equal steps up to it rather than a sliver at its end; a proposal that reaches it to within
  !! 1e-9 of its length goes all the way), and on a caller's stop time sim%t_stop.
  function clip(self, sim, t, h) result(hc)
    class(adaptive_integrator_t), intent(in) :: self  !! integrator
    type(sim_t), intent(in) :: sim                    !! simulation (next output time)
    real(wp), intent(in) :: t                         !! time of the state [s]
    real(wp), intent(in) :: h                         !! proposed step [s]
    real(wp) :: hc                                    !! step to take [s]
    real(wp) :: t_stop, gap
    integer :: n
    t_stop = min(sim%rec%t_next_out, self%t_end, sim%t_stop)
    gap = t_stop - t
    hc = h
    if (gap <= self%slack) return
    if (gap/h > 1.0e6_wp) return
    ! the output times accumulate round-off: a gap that exceeds h by a few ulps is one step, not two
    n = max(1, ceiling(gap/h*(1.0_wp - 1.0e-9_wp)))
    hc = gap/real(n, wp)                ! never longer than proposed but for those ulps
  end function clip

  !> Weighted local error of one semi-implicit Euler step of length h: h/2 |a(t+h) - a(t)| / tol
  !! (first-order estimate, see weighted_max for the weights).
  pure function error_norm(e0, e1, h, l_char, tol, ng) result(err)
    type(sim_eval_t), intent(in) :: e0      !! evaluation at the start of the step
    type(sim_eval_t), intent(in) :: e1      !! evaluation at its end
    real(wp), intent(in) :: h               !! step [s]
    real(wp), intent(in) :: l_char          !! lever of the body's angular accelerations [m]
    real(wp), intent(in) :: tol             !! velocity tolerance [m/s]
    integer, intent(in) :: ng               !! number of gears [-]
    real(wp) :: err                         !! error / tolerance [-]
    err = 0.5_wp*h*weighted_max(e1%acc - e0%acc, e1%alpha - e0%alpha, e1%qdd - e0%qdd, e0%q_weight, l_char, ng)/tol
    if (.not. ieee_is_finite(err)) err = huge(1.0_wp)
  end function error_norm

  !> Weighted local error of one leapfrog step of length h after a step h_prev: the kick is the
  !! midpoint rule for the velocity, whose local error is h^3/24 |a''|, with a'' from the second
  !! divided difference of the accelerations at t - h_prev, t and t + h; weights as error_norm.
  pure function error_norm2(ep, e0, e1, h_prev, h, l_char, tol, ng) result(err)
    type(sim_eval_t), intent(in) :: ep      !! evaluation at t - h_prev
    type(sim_eval_t), intent(in) :: e0      !! evaluation at t
    type(sim_eval_t), intent(in) :: e1      !! evaluation at t + h
    real(wp), intent(in) :: h_prev          !! previous step [s]
    real(wp), intent(in) :: h               !! step [s]
    real(wp), intent(in) :: l_char          !! lever of the body's angular accelerations [m]
    real(wp), intent(in) :: tol             !! velocity tolerance [m/s]
    integer, intent(in) :: ng               !! number of gears [-]
    real(wp) :: err                         !! error / tolerance [-]
    err = h**3/24.0_wp*2.0_wp/(h + h_prev)*weighted_max((e1%acc - e0%acc)/h - (e0%acc - ep%acc)/h_prev, &
      (e1%alpha - e0%alpha)/h - (e0%alpha - ep%alpha)/h_prev, (e1%qdd - e0%qdd)/h - (e0%qdd - ep%qdd)/h_prev, &
      e0%q_weight, l_char, ng)/tol
    if (.not. ieee_is_finite(err)) err = huge(1.0_wp)
  end function error_norm2

  !> Largest weighted component of a set of body and gear accelerations (or their differences): the
  !! body's linear ones as they are, its angular ones times l_char, each gear coordinate's times its
  !! weight from the gear (a strut length's 1, a leg angle's its strut's length; all then in
  !! velocity units at the footpad scale once multiplied by a time). Coordinates beyond a gear's
  !! count have weight 0.
  pure function weighted_max(d_acc, d_alpha, d_qdd, q_weight, l_char, ng) result(w)
    real(wp), intent(in) :: d_acc(3)           !! body linear [m/s^2]
    real(wp), intent(in) :: d_alpha(3)         !! body angular [rad/s^2]
    real(wp), intent(in) :: d_qdd(:, :)        !! (max_gear_q, >= ng) gear coordinates [m/s^2, rad/s^2]
    real(wp), intent(in) :: q_weight(:, :)     !! (max_gear_q, >= ng) their weights [-, m]
    real(wp), intent(in) :: l_char             !! lever of the angular ones [m]
    integer, intent(in) :: ng                  !! number of gears [-]
    real(wp) :: w                              !! [m/s^2]
    integer :: i, j
    w = max(maxval(abs(d_acc)), l_char*maxval(abs(d_alpha)))
    do i = 1, ng
      do j = 1, size(d_qdd, 1)
        if (q_weight(j, i) > 0.0_wp) w = max(w, q_weight(j, i)*abs(d_qdd(j, i)))
      end do
    end do
  end function weighted_max

  !> The discrete state changed between two evaluations: a strut mode, the piece of a buffer law
  !! (a stage end or an end-of-stroke stop crossed), a footpad contact, a stick state, or the tilt
  !! crossed the tip-over angle.
  pure logical function discrete_change(e0, e1, ng, tip) result(changed)
    type(sim_eval_t), intent(in) :: e0      !! evaluation at the start of the step
    type(sim_eval_t), intent(in) :: e1      !! evaluation at its end
    integer, intent(in) :: ng               !! number of gears [-]
    real(wp), intent(in) :: tip             !! tip-over angle [rad]
    changed = any(e0%mode(:, 1:ng) /= e1%mode(:, 1:ng)) .or. any(e0%segment(:, 1:ng) /= e1%segment(:, 1:ng)) &
              .or. any(e0%contact(1:ng) .neqv. e1%contact(1:ng)) &
              .or. any(e0%stuck(1:ng) .neqv. e1%stuck(1:ng)) .or. ((e0%tilt > tip) .neqv. (e1%tilt > tip))
  end function discrete_change

end module landyn_integrator_adaptive
