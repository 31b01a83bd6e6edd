!> Error-controlled variable-step integration with the footpads' normal contact forces linearly
!! implicit (&simulation integrator = 'imex', opt-in; docs/theory.md, "Stiff candidate: linearly
!! implicit footpad contact"). The step-size control, event location, retries and output cuts are
!! those of landyn_integrator_adaptive (with its discrete_change); the step is landyn_scheme_imex's
!! instead of the leapfrog: implicit Euler in each footpad's penetration, so that the stiff
!! footpad-soil oscillation is damped rather than resolved. The local error estimate is the
!! adaptive one's (second divided difference of the accelerations, or the first-order one after an
!! event) with the part of the acceleration change that the footpads' normal-force change explains
!! through their unit responses removed: the stiff footpad-normal mode is the implicit scheme's,
!! not the error control's. The integrator keeps, for each evaluation record, the body
!! accelerations its gears were evaluated in and the step it was made for (the footpads' unit
!! responses are taken at them).
module landyn_integrator_imex
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use landyn_kinds, only: wp, msg_len, max_gears, max_gear_q
  use landyn_config, only: landyn_input_t
  use landyn_sim_core, only: sim_t, sim_result_t, sim_eval_t, sim_snapshot_t, sim_save, sim_restore, &
                             sim_evaluate, sim_book, sim_accept, finish, body_is_finite
  use landyn_integrator, only: integrator_t
  use landyn_integrator_adaptive, only: discrete_change
  use landyn_scheme_imex, only: imex_advance, imex_responses, imex_response_t
  implicit none
  private

  public :: imex_integrator_t

  integer, parameter :: NO_STEP = 4   !! from imex_step when no step down to dt_min succeeds (the value sim_accept
                                      !! gives a non-finite state, SIM_NON_FINITE) [-]

  !> The imex integrator and its state between steps (the adaptive one's, and the fields of its evaluations).
  type, extends(integrator_t) :: imex_integrator_t
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
    real(wp) :: fld_acc(3, 3) = 0.0_wp     !! body acceleration each record's gears were evaluated in, global [m/s^2]
    real(wp) :: fld_alpha(3, 3) = 0.0_wp   !! its angular acceleration, lander axes [rad/s^2]
    real(wp) :: dt_ev(3) = 0.0_wp          !! the step each record was made for [s]
    type(imex_response_t) :: rsp           !! the footpads' responses at the current state
  contains
    procedure :: start => imex_start   !! evaluates and records the state at t = 0
    procedure :: step => imex_step     !! one accepted step (retries and event location inside)
  end type imex_integrator_t

contains

  !> Reads the settings, evaluates and records t = 0; the first step tried is &simulation dt.
  subroutine imex_start(self, sim, inp, res, stat, errmsg)
    class(imex_integrator_t), intent(inout) :: self  !! integrator
    type(sim_t), intent(inout) :: sim                    !! simulation at t = 0
    type(landyn_input_t), intent(in) :: inp              !! resolved, validated input
    type(sim_result_t), intent(inout) :: res             !! result
    integer, intent(out) :: stat                         !! 0 on success
    character(len=*), intent(inout) :: errmsg            !! diagnosis on failure
    self%tol = inp%simulation%tolerance
    self%h_max = min(inp%simulation%dt_max, inp%output%interval)
    self%h_min = min(inp%simulation%dt_min, self%h_max)
    self%h_event = max(inp%simulation%event_resolution, self%h_min)
    self%t_end = inp%simulation%t_end
    self%slack = 1.0e-12_wp*max(1.0_wp, self%t_end)
    self%t = 0.0_wp
    self%h = clip(self, sim, 0.0_wp, max(self%h_min, min(inp%simulation%dt, self%h_max)))
    res%integrator = 'imex'
    res%dt_smallest = huge(1.0_wp)
    res%dt_largest = 0.0_wp
    self%ip = 1
    call sim_save(sim, self%snap(1))
    self%h_last = 0.0_wp
    call sim_evaluate(sim, inp, 0.0_wp, kick(self, self%h), self%evs(self%i_cur), stat, errmsg)
    call note_field(self, sim, self%i_cur, kick(self, self%h))
    res%n_evaluations = res%n_evaluations + 1
    if (stat /= 0) then
      call finish(sim%model, res, 0.0_wp)
      return
    end if
    call sim_book(sim, inp, res, self%evs(self%i_cur), 0.0_wp, self%slack)
    self%snap(1)%loop = sim%loop    ! a rejected first step returns to t = 0 as booked
  end subroutine imex_start

  !> One accepted step: tries the step h, estimates its error from the accelerations at both ends,
  !! looks for events, and retries shorter until the step is accepted; then books the new state,
  !! runs the checks and chooses the next step.
  subroutine imex_step(self, sim, inp, res, done, stat, errmsg, progress_unit)
    class(imex_integrator_t), intent(inout) :: self  !! integrator
    type(sim_t), intent(inout) :: sim                    !! simulation, advanced by one step
    type(landyn_input_t), intent(in) :: inp              !! resolved, validated input
    type(sim_result_t), intent(inout) :: res             !! time series and summary
    logical, intent(out) :: done                         !! the run has ended
    integer, intent(out) :: stat                         !! 0 on success
    character(len=*), intent(inout) :: errmsg            !! diagnosis on failure
    integer, intent(in) :: progress_unit                 !! unit for progress lines, < 0 for none
    real(wp) :: h, h_g, t_new, err, fac, acc_t(3), alpha_t(3)
    integer :: k
    logical :: ok, event, rejected
    character(len=msg_len) :: m2

    done = .false.
    rejected = .false.
    do
      h = self%h
      h_g = h
      t_new = self%t + h
      if (t_new >= self%t_end - self%slack) t_new = self%t_end
      err = 0.0_wp
      event = .false.
      call imex_responses(sim, self%evs(self%i_cur), self%fld_acc(:, self%i_cur), self%fld_alpha(:, self%i_cur), &
                          self%dt_ev(self%i_cur), self%rsp, stat, m2)
      if (stat == 0) call imex_advance(sim, inp, self%evs(self%i_cur), self%rsp, h, kick(self, h), stat, m2)
      ok = stat == 0
      if (ok) ok = body_is_finite(sim%model%body)
      if (ok) then
        h_g = clip(self, sim, t_new, h)
        call sim_save(sim, self%snap(3 - self%ip))
        call sim_evaluate(sim, inp, t_new, 0.5_wp*(h + h_g), self%evs(self%i_new), stat, m2, v_lead=0.5_wp*h)
        call note_field(self, sim, self%i_new, 0.5_wp*(h + h_g))
        res%n_evaluations = res%n_evaluations + 1
        ok = stat == 0
      end if
      if (ok) then
        err = stiff_free_error(self, sim, h)
        event = discrete_change(self%evs(self%i_cur), self%evs(self%i_new), sim%model%n_gears, &
                                inp%simulation%tipover_angle)
      end if
      if ((.not. ok .and. h > self%h_min) .or. &
          (ok .and. h > self%h_event*(1.0_wp + 1.0e-9_wp) .and. (err > 1.0_wp .or. event))) then
        ! reject: back to the state at t, retry shorter
        call sim_restore(sim, self%snap(self%ip))
        if (.not. ok) then
          h = 0.25_wp*h
        else if (err > 1.0_wp) then
          h = h*max(0.1_wp, step_factor(err, self%smooth))
          if (event) h = min(h, 0.5_wp*self%h)
        else
          h = 0.5_wp*h
        end if
        if (ok) then
          self%h = clip(self, sim, self%t, max(h, self%h_event))
        else
          self%h = clip(self, sim, self%t, max(h, self%h_min))
        end if
        res%n_rejected = res%n_rejected + 1
        rejected = .true.
        ! the body's accelerations at t are known from the first evaluation of t (copied: ev is
        ! intent(out) of sim_evaluate)
        acc_t = self%evs(self%i_cur)%acc
        alpha_t = self%evs(self%i_cur)%alpha
        call sim_evaluate(sim, inp, self%t, kick(self, self%h), self%evs(self%i_cur), stat, m2, acc_field=acc_t, &
                          alpha_field=alpha_t, &
                          v_lead=0.5_wp*self%h_last)
        self%fld_acc(:, self%i_cur) = acc_t
        self%fld_alpha(:, self%i_cur) = alpha_t
        self%dt_ev(self%i_cur) = kick(self, self%h)
        res%n_evaluations = res%n_evaluations + 1
        if (stat /= 0) then
          errmsg = m2
          exit
        end if
        cycle
      end if
      if (.not. ok) then
        stat = max(stat, NO_STEP)
        write (errmsg, '(a,es10.3,a,es12.5,a,a)') 'imex integrator: no step down to dt_min = ', self%h_min, &
          ' s succeeds at t = ', self%t, ' s: ', trim(m2)
      end if
      exit
    end do
    if (stat /= 0) then   ! failed: the re-evaluation of t, or no step down to dt_min
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
    call sim_book(sim, inp, res, self%evs(self%i_new), h, self%slack)
    call sim_accept(sim, inp, res, t_new, h, done, stat, errmsg, progress_unit, &
                    t_new >= sim%loop%next_progress*self%t_end/20.0_wp, self%evs(self%i_new))
    if (done) return
    if (t_new >= self%t_end) then
      res%at_rest = sim%loop%rest_clock >= inp%simulation%rest_time
      call finish(sim%model, res, self%t_end)
      done = .true.
      return
    end if
    ! next step: the usual controller (err ~ h^3 for the second-difference estimate, ~ h^2 for the
    ! first-order one), growth at most 2, none right after a rejection
    fac = 2.0_wp
    if (err > 0.0_wp) fac = min(2.0_wp, step_factor(err, self%smooth))
    if (rejected) fac = min(fac, 1.0_wp)
    h = clip(self, sim, t_new, max(self%h_event, min(self%h_max, h*max(0.2_wp, fac))))
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
    self%snap(self%ip)%loop = sim%loop    ! a rejected step returns to this state as booked and checked
  end subroutine imex_step

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
    class(imex_integrator_t), intent(in) :: self  !! integrator
    real(wp), intent(in) :: h                         !! step to take [s]
    kick = 0.5_wp*(self%h_last + h)
  end function kick

  !> A step proposal from t cut so that steps end exactly on the next output time and on t_end
  !! (equal steps up to it rather than a sliver at its end; a proposal that reaches it to within
  !! 1e-9 of its length goes all the way).
  function clip(self, sim, t, h) result(hc)
    class(imex_integrator_t), intent(in) :: self  !! integrator
    type(sim_t), intent(in) :: sim                    !! simulation (next output time)
    real(wp), intent(in) :: t                         !! time of the state [s]
    real(wp), intent(in) :: h                         !! proposed step [s]
    real(wp) :: hc                                    !! step to take [s]
    real(wp) :: t_stop, gap
    integer :: n
    t_stop = min(sim%loop%t_next_out, self%t_end)
    gap = t_stop - t
    hc = h
    if (gap <= self%slack) return
    if (gap/h > 1.0e6_wp) return
    ! the output times accumulate round-off: a gap that exceeds h by a few ulps is one step, not two
    n = max(1, ceiling(gap/h*(1.0_wp - 1.0e-9_wp)))
    hc = gap/real(n, wp)                ! never longer than proposed but for those ulps
  end function clip

  !> Records the field an evaluation in slot k was made in (the committed body accelerations, as
  !! sim_evaluate takes them without acc_field) and its step.
  pure subroutine note_field(self, sim, k, dt)
    class(imex_integrator_t), intent(inout) :: self   !! integrator
    type(sim_t), intent(in) :: sim                    !! simulation as evaluated
    integer, intent(in) :: k                          !! slot [-]
    real(wp), intent(in) :: dt                        !! the step the evaluation was made for [s]
    self%fld_acc(:, k) = sim%model%body%acc
    self%fld_alpha(:, k) = sim%model%body%alpha
    self%dt_ev(k) = dt
  end subroutine note_field

  !> The local error of the step h just tried over the tolerance: the adaptive integrator's estimate
  !! (h^3/24 |a''| from the second divided difference of the accelerations of the last three
  !! evaluations; h/2 |a(t+h) - a(t)| right after an event) of the accelerations less their part
  !! explained by the footpads' normal forces through the unit responses at t (for every footpad
  !! with a response: in contact and its decisions unchanged), weighted as landyn_integrator_adaptive.
  function stiff_free_error(self, sim, h) result(err)
    class(imex_integrator_t), intent(in) :: self  !! integrator (records, responses)
    type(sim_t), intent(in) :: sim                !! simulation (counts, size)
    real(wp), intent(in) :: h                     !! step tried [s]
    real(wp) :: err                               !! error / tolerance [-]
    real(wp) :: d_acc(3), d_alpha(3), d_qdd(max_gear_q, max_gears), dfn, c0, c1
    integer :: i, ng, nq
    ng = sim%model%n_gears
    associate (ep => self%evs(self%i_prev), e0 => self%evs(self%i_cur), e1 => self%evs(self%i_new), r => self%rsp)
      if (self%smooth) then
        c1 = 1.0_wp/h
        c0 = 1.0_wp/self%h_last
        d_acc = (e1%acc - e0%acc)*c1 - (e0%acc - ep%acc)*c0
        d_alpha = (e1%alpha - e0%alpha)*c1 - (e0%alpha - ep%alpha)*c0
        d_qdd(:, 1:ng) = (e1%qdd(:, 1:ng) - e0%qdd(:, 1:ng))*c1 - (e0%qdd(:, 1:ng) - ep%qdd(:, 1:ng))*c0
      else
        d_acc = e1%acc - e0%acc
        d_alpha = e1%alpha - e0%alpha
        d_qdd(:, 1:ng) = e1%qdd(:, 1:ng) - e0%qdd(:, 1:ng)
      end if
      do i = 1, ng
        if (.not. r%on(i)) cycle
        if (self%smooth) then
          dfn = (e1%fn(i) - e0%fn(i))*c1 - (e0%fn(i) - ep%fn(i))*c0
        else
          dfn = e1%fn(i) - e0%fn(i)
        end if
        nq = sim%model%n_q(i)
        d_acc = d_acc - dfn*r%acc_u(:, i)
        d_alpha = d_alpha - dfn*r%alpha_u(:, i)
        d_qdd(1:nq, i) = d_qdd(1:nq, i) - dfn*r%qdd_u(1:nq, i)
      end do
      err = weighted_max(d_acc, d_alpha, d_qdd(:, 1:ng), e0%q_weight, sim%l_char, ng)/self%tol
      if (self%smooth) then
        err = err*h**3/24.0_wp*2.0_wp/(h + self%h_last)
      else
        err = err*0.5_wp*h
      end if
    end associate
    if (.not. ieee_is_finite(err)) err = huge(1.0_wp)
  end function stiff_free_error

  !> Largest weighted component of a set of body and gear acceleration differences (as
  !! landyn_integrator_adaptive's): the body's linear ones, its angular ones times l_char, each gear
  !! coordinate's times its weight.
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

end module landyn_integrator_imex
