!> The building blocks of the time integration: the evaluation of forces and accelerations, the
!! step of the paper's scheme (Fig. 6, Steps 1-7), the commit, the booking of work and peaks, the
!! end checks. The model, its state and snapshots are landyn_sim_model's, the result and its
!! recording landyn_sim_result's (both re-exported here). The integrators (landyn_integrator_*)
!! compose these; run_simulation (landyn_simulation) drives one landing. Only sim_init reads the
!! input deck: it builds the run's parameters (sim_params_t) that every later procedure reads.
!! The footpads' ground forces and the engine's thrust are the physics layer's
!! (landyn_footpad_ground, landyn_engine). Library code: returns a status_t (code and message
!! with its context); progress goes to a unit the caller chooses.
!!
!! Per step (all forces from the state at t_n, then semi-implicit Euler):
!!   2. footpad positions and velocities (body kinematics + gear coordinates), penetration and
!!      ground force in each footpad's local surface frame (contact and friction laws);
!!   3.-4. per gear: crush logic and the gear DAE (the gear type's evaluate; the tripod's: landyn_tripod_gear),
!!      force transmitted to the body;
!!   6. body accelerations from gravity, thrust and the gear forces, then the body step;
!!   4. gear step with the direct constraint-violation correction.
module landyn_sim_core
  use landyn_kinds, only: wp, max_gears, max_struts, max_gear_q, g_earth, rad2deg
  use landyn_config, only: landyn_input_t
  use landyn_kinematics, only: cross3, mv3, mtv3
  use landyn_body, only: body_t, body_accelerations, body_point_position, body_point_velocity, &
                         body_point_acceleration, body_kinetic_energy
  use landyn_gear_base, only: gear_slot_t
  use landyn_loads, only: n_load, gear_load_vector, load_peaks_update
  use landyn_terrain, only: slip_velocity
  use landyn_footpad_ground, only: footpad_ground_force
  use landyn_status, only: STAT_OK, STAT_NON_FINITE, status_t
  use landyn_sim_model, only: model_t, sim_t, sim_eval_t, sim_snapshot_t, velocities_t, setup_model, sim_params, leg_energy, &
                              sim_save, sim_restore, lead_velocities, restore_velocities, body_is_finite, &
                              max_primary_stroke
  use landyn_scheme_leapfrog, only: leapfrog_advance
  use landyn_sim_result, only: sim_result_t, allocate_result, record, finish, n_energy, energy_names
  use landyn_rest, only: at_rest_now
  implicit none
  private

  public :: sim_result_t
  public :: sim_t, sim_snapshot_t, sim_eval_t, sim_init, sim_step, sim_save, sim_restore
  public :: sim_evaluate, sim_book, sim_accept, finish, body_is_finite, record_sample
  public :: n_energy, energy_names

contains

  !> Builds the model, allocates the result and sets the integrator's state at t = 0. The gears are
  !! the gears of the input's &gears gear_type unless `gears` gives others (setup_model).
  subroutine sim_init(inp, sim, res, st, gears)
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input [-]
    type(sim_t), intent(out) :: sim             !! simulation at t = 0, its parameters set [-]
    type(sim_result_t), intent(out) :: res      !! result, allocated [-]
    type(status_t), intent(out) :: st           !! STAT_OK, or the set-up's failure with its message [-]
    type(gear_slot_t), intent(in), optional :: gears(:)  !! gear i (where allocated) replaces the input's gear i [-]
    integer :: n_cap
    call setup_model(inp, sim%model, st, gears)
    if (.not. st%ok()) return
    sim%par = sim_params(inp)
    res%initial_position = sim%model%body%x - matmul(sim%model%body%r, sim%model%body%mc)
    n_cap = int(inp%simulation%t_end/inp%output%interval + 1.0e-9_wp) + 2
    call allocate_result(res, sim%model, n_cap)
    sim%rec%ke0 = body_kinetic_energy(sim%model%body)
    sim%rec%pe0 = -sim%model%body%mass*sim%par%gravity*sim%model%body%x(3)
    sim%rec%xt_prev = body_point_position(sim%model%body, sim%par%engine%point)
    sim%state%n = 0
    res%end_reason = 'end time reached'
  end subroutine sim_init

  !> One pass of the fixed-step scheme (paper Fig. 6): forces and accelerations at t_n = n dt, the
  !! output sample of t_n, then (unless t_n is the end time) the step to t_n+1 and its commit
  !! (footpad histories, strut modes), followed by the divergence, tip-over and rest checks.
  !! done = .true. when the run has ended (end time, rest, tip-over or failure).
  subroutine sim_step(sim, res, done, st, progress_unit, ev)
    type(sim_t), intent(inout) :: sim           !! simulation, advanced by one step
    type(sim_result_t), intent(inout) :: res    !! time series and summary
    logical, intent(out) :: done                !! the run has ended
    type(status_t), intent(out) :: st           !! STAT_OK (also for a tip-over), the failure otherwise [-]
    integer, intent(in) :: progress_unit        !! unit for progress lines, < 0 for none
    type(sim_eval_t), intent(inout) :: ev       !! work record for the step's evaluation (the caller's, so
                                                !! that it is not set up afresh at every step)
    real(wp) :: t, dt

    done = .false.
    dt = sim%par%dt
    t = sim%state%n*dt
    call sim_evaluate(sim, t, dt, ev, st)
    if (.not. st%ok()) then
      call finish(sim%model, res, t)
      done = .true.
      return
    end if
    call sim_book(sim, res, ev, dt, 0.5_wp*dt)
    if (sim%state%n == sim%par%nstep) then
      res%at_rest = sim%state%rest_clock >= sim%par%rest_time
      call finish(sim%model, res, sim%par%nstep*dt)
      done = .true.
      return
    end if
    call leapfrog_advance(sim, ev, dt, st)
    if (.not. st%ok()) then
      call finish(sim%model, res, t + dt)
      done = .true.
      return
    end if
    call sim_accept(sim, res, t + dt, dt, done, st, progress_unit, &
                    sim%state%n >= sim%rec%next_progress*sim%par%nstep/20)
  end subroutine sim_step

  !> Forces and accelerations of the state at time t for a step of dt to come (Steps 2, 3-4 and 6
  !! of Fig. 6): footpad positions and velocities, ground forces from a trial copy of the footpad
  !! states, each gear's crush logic and DAE (dt enters only the velocity-level lock decisions),
  !! the loads on the body and its accelerations. The simulation is not changed (intent(in)):
  !! the accelerations, strut forces, lock decisions and footpad states are the evaluation's, and
  !! the step (landyn_scheme_leapfrog) commits the evaluation it is taken with.
  subroutine sim_evaluate(sim, t, dt, ev, st, acc_field, alpha_field, v_lead)
    type(sim_t), intent(in) :: sim              !! simulation (unchanged)
    real(wp), intent(in) :: t                   !! time of the state [s]
    real(wp), intent(in) :: dt                  !! step to come [s]
    ! inout, not out: every component an evaluation defines is set below (for gears 1..n_gears);
    ! intent(out) would reset the whole record, max_gears gears of it, at every evaluation
    type(sim_eval_t), intent(inout) :: ev       !! the evaluation (previous contents replaced)
    type(status_t), intent(out) :: st           !! STAT_OK, or a gear's failure with its context [-]
    real(wp), intent(in), optional :: acc_field(3)    !! body acceleration for the legs' frame field, global;
                                                      !! default: the committed (last step's) one; with
                                                      !! frame_field_passes = 0 a prediction, evaluated again
                                                      !! only where the first pass changed a lock [m/s^2]
    real(wp), intent(in), optional :: alpha_field(3)  !! body angular acceleration for it, lander axes;
                                                      !! default: the committed one [rad/s^2]
    real(wp), intent(in), optional :: v_lead          !! the footpad velocities (contact damping, friction) are
                                                      !! taken with the stored velocities advanced by v_lead
                                                      !! times the committed accelerations (the leapfrog's
                                                      !! velocities lag the positions by half a step); default 0 [s]
    integer :: pass, n_pass
    logical :: on_demand, thrusting
    type(body_t) :: body
    real(wp) :: thrust_l(3)

    ev%t = t
    ev%dt = dt
    ! the body as this evaluation sees it: its velocities led for the footpads, then its
    ! accelerations for the legs' frame field and the new ones
    body = sim%model%body
    if (present(v_lead)) then
      body%v = sim%model%body%v + v_lead*sim%model%body%acc
      body%omega = sim%model%body%omega + v_lead*sim%model%body%alpha
    end if
    ! ---- Step 2: footpads and ground forces
    call ground_forces(sim, t, body, ev, v_lead)
    body%v = sim%model%body%v
    body%omega = sim%model%body%omega
    call engine_thrust(sim, t, ev, thrusting, thrust_l)

    ! ---- Steps 3-4: gear dynamics and crush logic. The legs' frame moves with the body, whose
    ! acceleration at t is not known before the gears' loads are: the paper's scheme takes the last
    ! evaluation's, an integrator may pass a better estimate.
    if (present(acc_field)) body%acc = acc_field
    if (present(alpha_field)) body%alpha = alpha_field
    ! With frame_field_passes > 1 the gears are evaluated again in the field of the body
    ! acceleration the previous pass gave (a fixed-point iteration of the body-leg coupling,
    ! contracting by about the legs' mass over the body's), so that a lock's stopping force
    ! reaches the other legs in the step it acts (docs/theory.md, "Frame field"). With 0 (the
    ! adaptive integrator's own field) the field passed in is a prediction: a second pass only
    ! where the first changed a lock; without one, two passes.
    n_pass = sim%par%frame_field_passes
    on_demand = n_pass == 0 .and. present(acc_field)
    if (n_pass == 0) n_pass = 2
    do pass = 1, n_pass
      if (on_demand .and. pass == 2) then
        if (.not. ev%locks_changed) exit
      end if
      call frame_field_pass(sim, t, dt, thrusting, thrust_l, sim%par%loads .and. (pass == n_pass .or. on_demand), &
                            body, ev, st)
      if (.not. st%ok()) return
    end do
    ev%acc = body%acc
    ev%alpha = body%alpha
    ev%ovl = mtv3(sim%model%body%r, body%acc - sim%model%par%g_vec)/g_earth
    ev%tilt = acos(max(-1.0_wp, min(1.0_wp, sim%model%body%r(3, 3))))
  end subroutine sim_evaluate

  !> Step 2 of an evaluation: per footpad its position and velocity, then its penetration, trial
  !! footpad state (committed with the step, sim_commit_discrete) and ground force in the global
  !! frame (landyn_footpad_ground, physics).
  subroutine ground_forces(sim, t, body, ev, v_lead)
    type(sim_t), intent(in) :: sim              !! simulation (unchanged) [-]
    real(wp), intent(in) :: t                   !! time of the state [s]
    type(body_t), intent(in) :: body            !! the body, its velocities led by v_lead [-]
    type(sim_eval_t), intent(inout) :: ev       !! the evaluation: footpads and ground forces set [-]
    real(wp), intent(in), optional :: v_lead    !! the gears' velocities are led by v_lead times the committed
                                                !! accelerations (as sim_evaluate's); default 0 [s]
    integer :: i, nq
    real(wp) :: qd_led(max_gear_q), qdd_c(max_gear_q)
    real(wp) :: r(3, 3), rg(3, 3), pos_g(3), vel_g(3), d_l(3)

    associate (model => sim%model)
      r = model%body%r
      do i = 1, model%par%n_gears
        rg = model%par%rot(:, :, i)
        if (present(v_lead)) then
          nq = model%par%n_q(i)
          call model%gear(i)%g%rates(qd_led(1:nq))
          call model%gear(i)%g%accelerations(qdd_c(1:nq))
          call model%gear(i)%g%footpad(pos_g, vel_g, qd_led(1:nq) + v_lead*qdd_c(1:nq))
        else
          call model%gear(i)%g%footpad(pos_g, vel_g)
        end if
        d_l = mv3(rg, pos_g)
        ev%xd(:, i) = body_point_position(body, d_l)
        ev%vd(:, i) = body_point_velocity(body, d_l) + mv3(r, mv3(rg, vel_g))
        ! trial footpad state of this step: committed with the step (sim_commit_discrete)
        ev%trial(i) = model%footpad(i)
        call footpad_ground_force(model%par%plane(i), model%par%contact, model%par%friction, ev%xd(:, i), ev%vd(:, i), &
                                  sim%state%n > 0, sim%state%xd_stick(:, i), t - sim%state%t_stick, ev%trial(i), &
                                  ev%delta(i), ev%fn(i), ev%stick_margin(i), ev%fground(:, i))
      end do
    end associate
  end subroutine ground_forces

  !> The engine's thrust at t, lander axes (landyn_engine, physics), and the global thrust force
  !! with a caller's engine inputs (landyn_session) added to the deck's.
  subroutine engine_thrust(sim, t, ev, thrusting, thrust_l)
    type(sim_t), intent(in) :: sim              !! simulation (unchanged) [-]
    real(wp), intent(in) :: t                   !! time of the state [s]
    type(sim_eval_t), intent(inout) :: ev       !! the evaluation: thrust_g (and ext_moment) set [-]
    logical, intent(out) :: thrusting           !! the deck's engine thrusts at t [-]
    real(wp), intent(out) :: thrust_l(3)        !! the deck's thrust at t, lander axes [N]

    thrusting = sim%par%engine%thrusting(t)
    thrust_l = sim%par%engine%thrust_at(t)
    if (sim%ext_on) then
      ! a caller's engine inputs (landyn_session): added to the deck's thrust
      ev%thrust_g = mv3(sim%model%body%r, thrust_l + sim%ext_force)
      ev%ext_moment = sim%ext_moment
    else
      ev%thrust_g = mv3(sim%model%body%r, thrust_l)
    end if
  end subroutine engine_thrust

  !> One pass of Steps 3-4 and 6: every gear's crush logic and DAE in the frame field of the body's
  !! present accelerations, the loads on the body (gears, gravity, thrust, a caller's inputs) and
  !! the body's new accelerations.
  subroutine frame_field_pass(sim, t, dt, thrusting, thrust_l, loads, body, ev, st)
    type(sim_t), intent(in) :: sim              !! simulation (unchanged) [-]
    real(wp), intent(in) :: t                   !! time of the state [s]
    real(wp), intent(in) :: dt                  !! step to come [s]
    logical, intent(in) :: thrusting            !! the deck's engine thrusts at t [-]
    real(wp), intent(in) :: thrust_l(3)         !! the deck's thrust at t, lander axes [N]
    logical, intent(in) :: loads                !! the gears record their interface loads [-]
    type(body_t), intent(inout) :: body         !! the body: its accelerations, the field in, the new ones out [-]
    type(sim_eval_t), intent(inout) :: ev       !! the evaluation: the gears' part and the field set [-]
    type(status_t), intent(inout) :: st         !! STAT_OK on entry; a gear's failure with its context [-]
    integer :: ng, i, ns, nq
    logical :: locked(max_struts)
    real(wp) :: r(3, 3), rg(3, 3), field(3), ffoot(3), force(3), moment(3), fb_l(3), gf(3, max_gears), gm(3, max_gears)

    ng = sim%model%par%n_gears
    associate (model => sim%model)
      r = model%body%r
      force = model%body%mass*model%par%g_vec
      moment = 0.0_wp
      ev%locks_changed = .false.
      ev%acc_field = body%acc
      ev%alpha_field = body%alpha
      do i = 1, ng
        rg = model%par%rot(:, :, i)
        field = mtv3(rg, mtv3(r, model%par%g_vec) - body_point_acceleration(body, model%par%point_a(:, i)))
        ffoot = mtv3(rg, mtv3(r, ev%fground(:, i)))
        call model%gear(i)%g%evaluate(ev%gear(i), ffoot, field, st, dt, mtv3(rg, body%alpha), loads)
        if (st%code /= STAT_OK) then
          call st%add_context('gear', t, i)
          return
        end if
        ns = model%par%n_struts(i)
        nq = model%par%n_q(i)
        associate (ge => ev%gear(i), g => model%gear(i)%g)
          call g%locks(locked(1:ns))
          if (any(locked(1:ns) .neqv. ge%locked(1:ns))) ev%locks_changed = .true.
          gf(:, i) = mv3(rg, ge%f_body)
          gm(:, i) = mv3(rg, ge%m_body)
          ev%qdd(1:nq, i) = ge%qdd(1:nq)
          call g%strut_modes(ev%mode(1:ns, i), ge)
          call g%coordinate_weights(ev%q_weight(1:nq, i))
          call g%law_segments(ev%segment(1:ns, i))
        end associate
        ev%contact(i) = ev%delta(i) > 0.0_wp
        ev%stuck(i) = model%par%friction%has_stiction .and. ev%trial(i)%friction%stuck
      end do
      fb_l = symmetric_sum(gf, ng)
      force = force + mv3(r, fb_l)
      moment = symmetric_sum(gm, ng) - cross3(model%body%mc, fb_l)
      ! engine thrust (computed with the footpad forces above)
      if (thrusting) then
        moment = moment + sim%par%engine%moment_about(model%body%mc, thrust_l)
      end if
      if (sim%ext_on) moment = moment + sim%par%engine%moment_about(model%body%mc, sim%ext_force) + sim%ext_moment
      force = force + ev%thrust_g
      ! ---- Step 6: body accelerations
      call body_accelerations(body, force, moment)
    end associate
  end subroutine frame_field_pass

  !> Books an accepted evaluation: the work of the ground forces and the thrust since the previous
  !! booked evaluation (trapezoidal rule: the scheme is the leapfrog, positions at t, stored
  !! velocities half a step behind, whose synchronised kinetic energy changes by exactly that to
  !! second order), the slide distance, the peaks of every step, and the output sample when one is
  !! due (within `slack` of its time).
  subroutine sim_book(sim, res, ev, h_sync, slack)
    type(sim_t), intent(inout) :: sim           !! simulation (recorder accounts updated)
    type(sim_result_t), intent(inout) :: res    !! time series and summary
    type(sim_eval_t), intent(in) :: ev          !! evaluation of the current state
    real(wp), intent(in) :: h_sync              !! the step just taken: the stored velocities lag the positions
                                                !! by h_sync/2 [s]
    real(wp), intent(in) :: slack               !! a sample is due this close before its time [s]
    integer :: ng, i, ns
    real(wp) :: fnm, xt(3)

    ng = sim%model%par%n_gears
    associate (model => sim%model)
      if (any(ev%delta(1:ng) > 0.0_wp)) sim%state%touched = .true.
      if (sim%state%n > 0) then
        do i = 1, ng
          fnm = 0.5_wp*(sim%rec%fn_prev(i) + ev%fn(i))
          sim%rec%w_normal = sim%rec%w_normal + fnm*(ev%delta(i) - sim%rec%delta_prev(i))
          sim%rec%w_friction = sim%rec%w_friction &
            - dot_product(0.5_wp*(sim%rec%fground_prev(:, i) + ev%fground(:, i)), ev%xd(:, i) - sim%rec%xd_prev(:, i)) &
            - fnm*(ev%delta(i) - sim%rec%delta_prev(i))
          if (sim%rec%fn_prev(i) > 0.0_wp) res%slide_distance(i) = res%slide_distance(i) &
            + norm2(slip_velocity(model%par%plane(i), ev%xd(:, i) - sim%rec%xd_prev(:, i)))
        end do
        xt = body_point_position(model%body, sim%par%engine%point)
        sim%rec%w_thrust = sim%rec%w_thrust + dot_product(0.5_wp*(sim%rec%thrust_prev + ev%thrust_g), xt - sim%rec%xt_prev)
        sim%rec%xt_prev = xt
        ! a caller's pure moment: the trapezoid of its power M . omega over the step (the stored
        ! rates belong to the middle of the step, as the displacement of the thrust point above)
        if (sim%ext_on) sim%rec%w_thrust = sim%rec%w_thrust &
          + dot_product(0.5_wp*(sim%rec%moment_prev + ev%ext_moment), model%body%omega)*h_sync
      end if
      if (sim%ext_on) sim%rec%moment_prev = ev%ext_moment
      do i = 1, ng
        res%peak_penetration(i) = max(res%peak_penetration(i), ev%delta(i))
        res%peak_normal_force(i) = max(res%peak_normal_force(i), ev%fn(i))
      end do
      sim%rec%xd_prev = ev%xd; sim%rec%delta_prev = ev%delta; sim%rec%fn_prev = ev%fn
      sim%rec%fground_prev = ev%fground
      sim%rec%thrust_prev = ev%thrust_g

      if (norm2(ev%ovl) > res%peak_overload) then
        res%peak_overload = norm2(ev%ovl)
        res%t_peak_overload = ev%t
      end if
      ! peaks of every step, for the summary and the interval-peak channels
      res%acc_overload = max(res%acc_overload, norm2(ev%ovl))
      if (sim%par%loads) call load_peaks_update(res%load_peaks, ev%t, eval_loads(model, ev), ng)
      do i = 1, ng
        ns = model%par%n_struts(i)
        res%acc_normal_force(i) = max(res%acc_normal_force(i), ev%fn(i))
        res%acc_strut_force(1:ns, i) = max(res%acc_strut_force(1:ns, i), abs(ev%gear(i)%axial(1:ns)))
        res%peak_strut_force(1:ns, i) = max(res%peak_strut_force(1:ns, i), abs(ev%gear(i)%axial(1:ns)))
      end do

      ! ---- output sample (state at t with the forces at t)
      if (ev%t >= sim%rec%t_next_out - slack) then
        call record_sample(sim, res, ev, h_sync)
        sim%rec%t_next_out = sim%rec%t_next_out + sim%par%out_interval
      end if
    end associate
  end subroutine sim_book

  !> Records the output sample of the state at ev%t with the forces of its evaluation ev: its
  !! velocities (and the audit's kinetic energies) synchronised to ev%t, i.e. the stored ones, half
  !! a step behind, plus half a step (h_sync) of the accelerations just computed.
  subroutine record_sample(sim, res, ev, h_sync)
    type(sim_t), intent(inout) :: sim           !! simulation at ev%t (velocities restored on return)
    type(sim_result_t), intent(inout) :: res    !! time series
    type(sim_eval_t), intent(in) :: ev          !! evaluation of the state
    real(wp), intent(in) :: h_sync              !! step the stored velocities lag by twice [s]
    type(velocities_t) :: kept
    real(wp) :: ke_legs, e_el
    integer :: i
    call lead_velocities(sim%model, 0.5_wp*h_sync, ev, kept)
    ke_legs = leg_energy(sim%model, sim%par%gravity)
    e_el = 0.0_wp
    do i = 1, sim%model%par%n_gears
      if (ev%delta(i) > 0.0_wp) e_el = e_el + sim%model%par%contact%elastic_energy(ev%delta(i), ev%trial(i)%contact)
    end do
    call record(res, sim%model, ev, sim%rec%w_normal, &
                sim%rec%w_friction, sim%rec%w_thrust, sim%rec%w_impact, sim%rec%ke0, sim%rec%pe0, ke_legs, e_el, &
                sim%par%gravity)
    call restore_velocities(sim%model, kept)
  end subroutine record_sample

  !> After an accepted step to t: mode-switch counts, divergence, tip-over and rest checks, progress.
  !! done = .true. when the run ends here (tip-over, rest, non-finite state: STAT_NON_FINITE).
  subroutine sim_accept(sim, res, t, dt, done, st, progress_unit, progress_due, ev)
    type(sim_t), intent(inout) :: sim           !! simulation after the step
    type(sim_result_t), intent(inout) :: res    !! time series and summary
    real(wp), intent(in) :: t                   !! time reached [s]
    real(wp), intent(in) :: dt                  !! the step just taken [s]
    logical, intent(out) :: done                !! the run has ended
    type(status_t), intent(out) :: st           !! STAT_OK (also for a tip-over and rest), else the failure [-]
    integer, intent(in) :: progress_unit        !! unit for progress lines, < 0 for none
    logical, intent(in) :: progress_due         !! a progress line is due [-]
    type(sim_eval_t), intent(in), optional :: ev  !! evaluation of the state reached, when the integrator
                                                  !! has made it: its strut modes are counted; default
                                                  !! the committed modes of the step just taken
    integer :: ng, i, ns, m(max_struts), n_rel
    logical :: locked_now
    real(wp) :: tilt

    done = .false.
    ng = sim%model%par%n_gears
    locked_now = .false.
    associate (model => sim%model)
      do i = 1, ng
        ns = model%par%n_struts(i)
        if (present(ev)) then
          m(1:ns) = ev%mode(1:ns, i)
        else
          call model%gear(i)%g%strut_modes(m(1:ns))
        end if
        ! strut releases (locked -> not locked), and those in the step after a lock anywhere
        ! (docs/theory.md, "Mode switches": a lock's stopping force reaches the legs a step late)
        n_rel = count(sim%state%mode(1:ns, i) == 0 .and. m(1:ns) /= 0)
        res%n_releases = res%n_releases + n_rel
        if (sim%state%locked_last) res%n_releases_after_lock = res%n_releases_after_lock + n_rel
        if (any(sim%state%mode(1:ns, i) /= 0 .and. m(1:ns) == 0)) locked_now = .true.
        call count_mode_switches(m(1:ns), sim%state%mode(1:ns, i), res%mode_switches(1:ns, i))
      end do
      sim%state%locked_last = locked_now
      res%n_steps = sim%state%n
      sim%state%t = t

      ! ---- divergence, tip-over and rest checks
      if (.not. body_is_finite(model%body)) then
        call st%fail(STAT_NON_FINITE, 'the integration diverged (reduce &simulation dt or check the input)', &
                     'the solution became non-finite', t)
        call finish(model, res, t)
        done = .true.
        return
      end if
      tilt = acos(max(-1.0_wp, min(1.0_wp, model%body%r(3, 3))))
      res%max_tilt = max(res%max_tilt, tilt*rad2deg)
      if (tilt > sim%par%tipover_angle) then
        res%tipped_over = .true.
        call end_early(sim, res, t, dt, 'tipped over')
        done = .true.
        return
      end if
      ! rest (landyn_rest, the outcome's definition): decided from the accepted state
      if (sim%state%touched .and. at_rest_now(model, sim%par%rest_speed, sim%par%l_char)) then
        sim%state%rest_clock = sim%state%rest_clock + dt
      else
        sim%state%rest_clock = 0.0_wp
      end if
      if (sim%par%stop_at_rest .and. sim%state%rest_clock >= sim%par%rest_time) then
        res%at_rest = .true.
        call end_early(sim, res, t, dt, 'at rest')
        done = .true.
        return
      end if
      if (progress_unit >= 0 .and. progress_due) then
        write (progress_unit, '(a,f8.4,a,f8.4,a,i3,a,f9.2,a)') 'landyn: t = ', t, ' s of ', &
          sim%par%t_end, ' s (', 5*sim%rec%next_progress, ' %), max primary stroke ', &
          1000.0_wp*max_primary_stroke(model, ng), ' mm'
        flush (progress_unit)
        sim%rec%next_progress = sim%rec%next_progress + 1
      end if
    end associate
  end subroutine sim_accept

  !> Ends the run before t_end: the reason, a final sample of the state at t (unless one was just
  !! recorded) with the forces of an evaluation of that state, the summary.
  subroutine end_early(sim, res, t, h_last, reason)
    type(sim_t), intent(in) :: sim              !! simulation at t
    type(sim_result_t), intent(inout) :: res    !! time series and summary
    real(wp), intent(in) :: t                   !! time [s]
    real(wp), intent(in) :: h_last              !! the step that reached t [s]
    character(len=*), intent(in) :: reason      !! end reason [-]
    type(sim_t) :: work
    type(sim_eval_t) :: ev
    type(status_t) :: st
    res%end_reason = reason
    if (res%n_out > 0) then
      if (res%t(res%n_out) >= t - 1.0e-12_wp) then
        call finish(sim%model, res, t)
        return
      end if
    end if
    ! the sample leads the velocities by half a step in place: on a copy of the final state
    work = sim
    call sim_evaluate(sim, t, h_last, ev, st)
    if (st%ok()) call record_sample(work, res, ev, h_last)
    call finish(sim%model, res, t)
  end subroutine end_early

  !> Sum of the gears' loads, adding diametrically opposed gears (i, i + n/2) first when n is even:
  !! for a lander symmetric under rotation by 360/n deg their contributions then cancel exactly in
  !! floating point, so a symmetric landing stays symmetric to the last bit instead of drifting by
  !! round-off that the crush logic's discrete events would amplify.
  pure function symmetric_sum(v, n) result(total)
    real(wp), intent(in) :: v(:, :)   !! (3, >= n) vectors [any]
    integer, intent(in) :: n          !! number of gears [-]
    real(wp) :: total(3)              !! their sum [any]
    integer :: i, h
    total = 0.0_wp
    if (mod(n, 2) == 0) then
      h = n/2
      do i = 1, h
        total = total + (v(:, i) + v(:, i + h))
      end do
    else
      do i = 1, n
        total = total + v(:, i)
      end do
    end if
  end function symmetric_sum

  !> The load vectors (landyn_loads) of all gears of an evaluation, lander axes.
  pure function eval_loads(model, ev) result(v)
    type(model_t), intent(in) :: model          !! model (gear rotations)
    type(sim_eval_t), intent(in) :: ev          !! evaluation
    real(wp) :: v(n_load, max_gears)            !! [N, N m]
    integer :: i
    v = 0.0_wp
    do i = 1, model%par%n_gears
      v(:, i) = gear_load_vector(model%par%rot(:, :, i), ev%gear(i))
    end do
  end function eval_loads

  !> Counts the changes of each strut's crush mode (strut_modes), i.e. the switches of the buffer
  !! force law.
  pure subroutine count_mode_switches(m, mode, switches)
    integer, intent(in) :: m(:)               !! modes after the step [-]
    integer, intent(inout) :: mode(:)         !! mode at the previous step, updated [-]
    integer, intent(inout) :: switches(:)     !! mode changes so far [-]
    where (m /= mode) switches = switches + 1
    mode = m
  end subroutine count_mode_switches

end module landyn_sim_core
