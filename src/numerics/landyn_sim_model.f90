!> The simulation's model and state: the model assembled from the resolved input (its parameters,
!! model_params_t: terrain, contact and friction laws, gear counts, frames and joints; its state:
!! body, gears, footpads) placed at t = 0, the run's parameters (sim_params_t, built
!! once from the input), the simulation record with the integrator's state (step_state_t) and the
!! recorder's accounts (sim_recorder_t), the evaluation record, snapshots (save/restore) and the
!! legs' energy for the audit. The time integration that works on them is landyn_sim_core.
module landyn_sim_model
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use landyn_kinds, only: wp, max_gears, max_struts, max_gear_q
  use landyn_strings, only: int_text
  use landyn_config, only: landyn_input_t, is_set
  use landyn_kinematics, only: cross3, mv3
  use landyn_body, only: body_t, body_init, body_point_position, inertia_tensor
  use landyn_gear_base, only: gear_eval_t, gear_slot_t, gear_snapshot_slot_t
  use landyn_gear_types, only: make_gear
  use landyn_terrain, only: terrain_plane_t, make_terrain_planes, penetration
  use landyn_contact, only: contact_law_t, make_contact_law
  use landyn_friction, only: friction_law_t, make_friction_law
  use landyn_footpad_state, only: footpad_state_t
  use landyn_engine, only: engine_t
  use landyn_status, only: STAT_OK, STAT_INPUT, status_t
  use landyn_engine, only: make_engine
  implicit none
  private

  public :: model_t, model_params_t, sim_params_t, step_state_t, sim_recorder_t, sim_t, sim_eval_t, velocities_t, sim_snapshot_t
  public :: sim_params, setup_model, leg_energy, sim_save, sim_restore, lead_velocities, restore_velocities, body_is_finite
  public :: max_primary_stroke

  !> The model's parameters (the lander's; the run's settings are sim_params_t): what setup_model
  !! builds once from the input and no procedure changes during the run (the procedures of a step
  !! only read them). Not part of a snapshot: sim_save and sim_restore leave them alone. The gears'
  !! own parameters live in their gear objects (model_t%gear).
  type :: model_params_t
    integer :: n_gears = 0                      !! number of gears [-]
    integer :: n_struts(max_gears) = 0          !! struts of gear i (its strut_count()) [-]
    integer :: n_q(max_gears) = 0               !! generalized coordinates of gear i (its coordinate_count()) [-]
    type(terrain_plane_t) :: plane(max_gears)         !! the terrain plane under footpad i
    ! The laws are immutable parameter objects shared by all footpads; what evolves (contact
    ! history, stick state) is each footpad's footpad_state_t, changed only when a step is committed.
    class(contact_law_t), allocatable :: contact       !! normal contact law
    class(friction_law_t), allocatable :: friction     !! friction law
    real(wp) :: point_a(3, max_gears) = 0.0_wp  !! upper primary joints, lander frame [m]
    real(wp) :: rot(3, 3, max_gears) = 0.0_wp   !! gear frame -> lander frame of each gear (gear_rotation,
                                                !! set at assembly) [-]
    real(wp) :: g_vec(3) = 0.0_wp               !! gravity, global [m/s^2]
    real(wp) :: first_moment0(3, max_gears) = 0.0_wp  !! leg first moments of mass at t = 0, gear frame [kg m]
  end type model_params_t

  !> The model: the lander's parameters `par` (fixed at assembly) and its evolving physical state.
  !! The gears are held through gear_base_t (any gear type); their strut and coordinate counts are
  !! cached in `par` at assembly.
  !!
  !! State (what sim_save/sim_restore copy): body, footpad, and each gear's state (its
  !! save_state/restore_state; a gear object also holds its own parameters, which are not copied).
  type :: model_t
    type(model_params_t) :: par                 !! the parameters (set by setup_model, immutable during the run)
    ! ---- state
    type(body_t) :: body                        !! the lander body
    type(gear_slot_t) :: gear(max_gears)        !! the gears (their parameters and state)
    type(footpad_state_t) :: footpad(max_gears)        !! ground-interaction state of footpad i
  end type model_t

  !> The run's parameters: every setting the step needs, taken from the input once (sim_params,
  !! called by sim_init) and not changed during the run. The procedures of a step read these, never
  !! the input deck.
  type :: sim_params_t
    real(wp) :: dt = 0.0_wp                    !! &simulation dt: the fixed step, the first adaptive one [s]
    integer :: nstep = 0                       !! fixed steps to the end time [-]
    real(wp) :: t_end = 0.0_wp                 !! end time [s]
    real(wp) :: out_interval = 0.0_wp          !! output interval [s]
    real(wp) :: gravity = 0.0_wp               !! gravitational acceleration along global +z [m/s^2]
    real(wp) :: tipover_angle = 0.0_wp         !! tilt counted as a tip-over [rad]
    real(wp) :: rest_speed = 0.0_wp            !! speed below which the lander is still [m/s]
    real(wp) :: rest_time = 0.0_wp             !! time it must stay still to be at rest [s]
    logical :: stop_at_rest = .true.           !! end the run once at rest [-]
    real(wp) :: constraint_tol = 0.0_wp        !! tolerance of the constraint correction [m, m/s]
    integer :: max_correction_iter = 0         !! iteration cap of the constraint correction [-]
    real(wp) :: max_constraint_drift = 0.0_wp  !! violation above this fails the step [m]
    integer :: frame_field_passes = 0          !! gear passes per force evaluation [-]
    real(wp) :: l_char = 0.0_wp                !! largest mass-centre to footpad distance [m]
    logical :: loads = .true.                  !! compute and record the interface loads [-]
    type(engine_t) :: engine                   !! the descent engine (&engine)
  end type sim_params_t

  !> The integrator's evolving state beside the model's: what a snapshot restores so that a step
  !! is taken again exactly (step count, time, the stick states' reference, strut modes of the last
  !! step, the rest clock).
  type :: step_state_t
    integer :: n = 0                                   !! steps taken [-]
    real(wp) :: t = 0.0_wp                             !! time of the last accepted state (sim_accept) [s]
    real(wp) :: xd_stick(3, max_gears) = 0.0_wp        !! footpad positions of the evaluation whose footpad states
                                                       !! were committed last (the stick states' reference) [m]
    real(wp) :: t_stick = 0.0_wp                       !! time of that evaluation [s]
    real(wp) :: rest_clock = 0.0_wp                    !! time spent below the rest speed [s]
    logical :: touched = .false.                       !! a footpad has touched the ground [-]
    integer :: mode(max_struts, max_gears) = 0         !! crush mode of each strut at the last step [-]
    logical :: locked_last = .false.                   !! a strut locked in the last accepted step [-]
  end type step_state_t

  !> The recorder's accounts: energy references and work sums, the previous booked evaluation's
  !! values the trapezoids need, the next output time and the progress counter. Booked by sim_book
  !! (w_impact by the velocity projection of each step: a snapshot therefore keeps the accounts
  !! too, so that a rejected step's impact loss is taken back).
  type :: sim_recorder_t
    real(wp) :: ke0 = 0.0_wp                           !! initial kinetic energy [J]
    real(wp) :: pe0 = 0.0_wp                           !! initial potential energy [J]
    real(wp) :: t_next_out = 0.0_wp                    !! next output time [s]
    integer :: next_progress = 1                       !! next progress report (in 5 % of the run) [-]
    real(wp) :: w_normal = 0.0_wp                      !! work of the normal forces on the ground [J]
    real(wp) :: w_friction = 0.0_wp                    !! friction dissipation [J]
    real(wp) :: w_thrust = 0.0_wp                      !! thrust work [J]
    real(wp) :: w_impact = 0.0_wp                      !! energy dissipated in impacts [J]
    real(wp) :: xd_prev(3, max_gears) = 0.0_wp         !! footpad positions at the previous booked step [m]
    real(wp) :: delta_prev(max_gears) = 0.0_wp         !! penetrations at the previous booked step [m]
    real(wp) :: fn_prev(max_gears) = 0.0_wp            !! normal forces at the previous booked step [N]
    real(wp) :: fground_prev(3, max_gears) = 0.0_wp    !! ground forces at the previous booked step [N]
    real(wp) :: xt_prev(3) = 0.0_wp                    !! thrust point at the previous booked step [m]
    real(wp) :: thrust_prev(3) = 0.0_wp                !! thrust at the previous booked step, global [N]
    real(wp) :: moment_prev(3) = 0.0_wp                !! input moment at the previous step (ext_on), lander axes [N m]
  end type sim_recorder_t

  !> One simulation in progress (in the manner of OpenFAST's parameter, state and misc types): the
  !! run's parameters, the model, the integrator's state, the recorder's accounts, and a driving
  !! caller's inputs.
  type :: sim_t
    type(sim_params_t) :: par                          !! the run's parameters
    type(model_t) :: model                             !! the model
    type(step_state_t) :: state                        !! integrator state
    type(sim_recorder_t) :: rec                        !! recorder accounts
    ! a caller that drives the simulation (the C API's session, landyn_session): where a step must
    ! end, and engine inputs added to the deck's thrust. Their defaults leave a run untouched.
    real(wp) :: t_stop = huge(1.0_wp)                  !! the adaptive integrators end a step exactly here [s]
    logical :: ext_on = .false.                        !! the engine inputs below are applied [-]
    logical :: ext_changed = .false.                   !! they changed since the integrator's retarget [-]
    real(wp) :: ext_force(3) = 0.0_wp                  !! input force at the &engine point, lander axes [N]
    real(wp) :: ext_moment(3) = 0.0_wp                 !! input pure moment, lander axes [N m]
  end type sim_t

  !> One evaluation of forces and accelerations (sim_evaluate) of the state at t, for a step dt.
  type :: sim_eval_t
    real(wp) :: t = 0.0_wp                             !! time of the state [s]
    real(wp) :: dt = 0.0_wp                            !! the step it was made for (lock decisions) [s]
    real(wp) :: acc_field(3) = 0.0_wp                  !! body acceleration the gears were evaluated in (the
                                                       !! legs' frame field, last pass), global [m/s^2]
    real(wp) :: alpha_field(3) = 0.0_wp                !! its angular acceleration, lander axes [rad/s^2]
    real(wp) :: xd(3, max_gears) = 0.0_wp              !! footpad positions, global [m]
    real(wp) :: vd(3, max_gears) = 0.0_wp              !! footpad velocities, global [m/s]
    real(wp) :: delta(max_gears) = 0.0_wp              !! penetrations [m]
    real(wp) :: fn(max_gears) = 0.0_wp                 !! normal forces [N]
    real(wp) :: fground(3, max_gears) = 0.0_wp         !! ground forces on the footpads, global [N]
    type(footpad_state_t) :: trial(max_gears)          !! footpad states advanced by this evaluation
    real(wp) :: thrust_g(3) = 0.0_wp                   !! thrust (with the input force when ext_on), global [N]
    real(wp) :: ext_moment(3) = 0.0_wp                 !! input pure moment applied (ext_on), lander axes [N m]
    real(wp) :: acc(3) = 0.0_wp                        !! mass-centre acceleration, global [m/s^2]
    real(wp) :: alpha(3) = 0.0_wp                      !! body angular acceleration, lander axes [rad/s^2]
    real(wp) :: ovl(3) = 0.0_wp                        !! overload (a - g)/g0, lander axes [g]
    type(gear_eval_t) :: gear(max_gears)               !! each gear's evaluation: accelerations, buffer
                                                       !! forces, lock decisions (committed by the step)
    real(wp) :: qdd(max_gear_q, max_gears) = 0.0_wp    !! gear accelerations [m/s^2, rad/s^2]
    real(wp) :: q_weight(max_gear_q, max_gears) = 0.0_wp  !! error weights of the gear accelerations (the
                                                       !! gear's coordinate_weights) [-, m]
    logical :: locks_changed = .false.                 !! a strut locked or was released [-]
    ! discrete state after the evaluation: what an event changes
    integer :: mode(max_struts, max_gears) = 0         !! strut modes (the gears' strut_modes) [-]
    integer :: segment(max_struts, max_gears) = 0      !! piece of each buffer law (stage, stop) [-]
    logical :: contact(max_gears) = .false.            !! footpad in contact [-]
    logical :: stuck(max_gears) = .false.              !! footpad in its friction law's stick state [-]
    real(wp) :: stick_margin(max_gears) = 0.0_wp       !! switching function of the stick state: stuck exactly
                                                       !! where >= 0 (friction_law_t%stick_slip_force) [N]
    real(wp) :: tilt = 0.0_wp                          !! tilt of the lander z axis from vertical [rad]
  end type sim_eval_t

  !> The stored velocities of body and gears, kept while lead_velocities has advanced them.
  type :: velocities_t
    real(wp) :: v(3) = 0.0_wp                          !! mass-centre velocity, global [m/s]
    real(wp) :: omega(3) = 0.0_wp                      !! body rates, lander axes [rad/s]
    real(wp) :: qd(max_gear_q, max_gears) = 0.0_wp     !! gear rates [m/s, rad/s]
  end type velocities_t

  !> Everything of a simulation that evolves in time (see sim_save).
  type :: sim_snapshot_t
    type(body_t) :: body                               !! body state
    type(gear_snapshot_slot_t) :: gear(max_gears)      !! gear states (allocated by the first sim_save)
    type(footpad_state_t) :: footpad(max_gears)        !! footpad histories and stick states
    type(step_state_t) :: state                        !! integrator state
    type(sim_recorder_t) :: rec                        !! recorder accounts (w_impact is booked during a step)
  end type sim_snapshot_t

contains

  !> Builds the model (body, gears, terrain, laws) and places it at t = 0. The input's gears are of
  !! the type &gears gear_type names (landyn_gear_types); gears given in `gears` take the place of
  !! the input's (in the gear frames the input defines), before the lander is placed.
  subroutine setup_model(inp, model, st, gears)
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input [-]
    type(model_t), intent(out) :: model         !! model at t = 0 [-]
    type(status_t), intent(out) :: st           !! STAT_OK, STAT_INPUT when a gear exceeds the capacities, or
                                                !! a law's or gear's failure, with its message [-]
    type(gear_slot_t), intent(in), optional :: gears(:)  !! gear i (where allocated) replaces the input's gear i [-]

    model%par%n_gears = inp%gears%n_gears
    model%par%g_vec = [0.0_wp, 0.0_wp, inp%simulation%gravity]
    call make_laws(inp, model, st)
    if (.not. st%ok()) return
    call build_gears(inp, model, st)
    if (.not. st%ok()) return
    if (present(gears)) call replace_gears(gears, model)
    call check_gear_capacities(model%par, st)
    if (.not. st%ok()) return
    call place_lander(inp, model, st)
  end subroutine setup_model

  !> The run's parameters from the resolved input: the settings of &simulation, &output interval
  !! and &engine the step reads, the step count of the fixed scheme and l_char (the largest
  !! mass-centre to footpad-joint distance).
  function sim_params(inp) result(par)
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input [-]
    type(sim_params_t) :: par                   !! the parameters [-]
    integer :: i
    par%dt = inp%simulation%dt
    par%nstep = nint(inp%simulation%t_end/par%dt)
    par%t_end = inp%simulation%t_end
    par%out_interval = inp%output%interval
    par%gravity = inp%simulation%gravity
    par%tipover_angle = inp%simulation%tipover_angle
    par%rest_speed = inp%simulation%rest_speed
    par%rest_time = inp%simulation%rest_time
    par%stop_at_rest = inp%simulation%stop_at_rest
    par%constraint_tol = inp%simulation%constraint_tol
    par%max_correction_iter = inp%simulation%max_correction_iter
    par%max_constraint_drift = inp%simulation%max_constraint_drift
    par%frame_field_passes = inp%simulation%frame_field_passes
    par%l_char = 0.0_wp
    do i = 1, inp%gears%n_gears
      par%l_char = max(par%l_char, norm2(inp%gears%point_d(:, i) - inp%lander%mass_centre))
    end do
    par%engine = make_engine(inp%engine)
  end function sim_params

  !> The laws of the model (contact, friction, terrain planes) and its footpad states at rest. The
  !! gears' own laws (buffers, tube friction) are their gear type's (build_gears).
  subroutine make_laws(inp, model, st)
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input [-]
    type(model_t), intent(inout) :: model       !! model with n_gears set; its laws, planes, footpads are set [-]
    type(status_t), intent(inout) :: st         !! STAT_OK, or a law's failure with its message [-]

    call make_contact_law(inp%contact, model%par%contact, st)
    if (.not. st%ok()) return
    call make_friction_law(inp%friction, model%par%friction, st)
    if (.not. st%ok()) return
    model%footpad = footpad_state_t()
    call make_terrain_planes(inp%terrain, model%par%plane(1:model%par%n_gears), st)
    if (.not. st%ok()) return
  end subroutine make_laws

  !> The input's gears, of the type &gears gear_type names (made by the gear-type registry,
  !! landyn_gear_types), in the model with their counts cached.
  subroutine build_gears(inp, model, st)
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input [-]
    type(model_t), intent(inout) :: model       !! model with n_gears set; its gears are set [-]
    type(status_t), intent(inout) :: st         !! STAT_OK, or the gear type's failure with its message [-]
    integer :: i

    do i = 1, model%par%n_gears
      model%par%point_a(:, i) = inp%gears%point_a(:, i)
      call make_gear(inp, i, model%gear(i)%g, st)
      if (.not. st%ok()) return
      call gear_counts(model, i)
    end do
  end subroutine build_gears

  !> Gear i of `gears`, where allocated, takes the place of the model's gear i.
  subroutine replace_gears(gears, model)
    type(gear_slot_t), intent(in) :: gears(:)   !! replacing gears [-]
    type(model_t), intent(inout) :: model       !! model with its gears set [-]
    integer :: i
    do i = 1, min(model%par%n_gears, size(gears))
      if (.not. allocated(gears(i)%g)) cycle
      deallocate (model%gear(i)%g)
      allocate (model%gear(i)%g, source=gears(i)%g)
      call gear_counts(model, i)
    end do
  end subroutine replace_gears

  !> STAT_INPUT when a gear has more struts or coordinates than the evaluation records hold.
  subroutine check_gear_capacities(par, st)
    type(model_params_t), intent(in) :: par     !! model parameters with the gears' counts set [-]
    type(status_t), intent(inout) :: st         !! STAT_OK when all fit, STAT_INPUT with a message otherwise [-]
    integer :: i
    do i = 1, par%n_gears
      if (par%n_struts(i) > max_struts .or. par%n_q(i) > max_gear_q) then
        call st%fail(STAT_INPUT, 'gear '//int_text(i)//': '//int_text(par%n_struts(i))//' struts and ' &
                     //int_text(par%n_q(i))//' coordinates exceed the capacities max_struts and max_gear_q (landyn_kinds)')
        return
      end if
    end do
  end subroutine check_gear_capacities

  !> Places the lander at t = 0: at the given position, or with the lowest footpad at `clearance`
  !! above its surface; free fall, and the legs' first moments at rest.
  subroutine place_lander(inp, model, st)
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input [-]
    type(model_t), intent(inout) :: model       !! model with its gears and planes set; its body is set [-]
    type(status_t), intent(inout) :: st         !! STAT_OK, or the body's failure with its message [-]
    real(wp) :: x_ol(3), dz, xd(3), pos(3), vel(3)
    integer :: i

    if (all(is_set(inp%initial%position))) then
      x_ol = inp%initial%position
    else
      x_ol = 0.0_wp
    end if
    call body_init(model%body, inp%lander%mass, &
      inertia_tensor(inp%lander%ixx, inp%lander%iyy, inp%lander%izz, inp%lander%ixy, inp%lander%ixz, inp%lander%iyz), &
      inp%lander%mass_centre, x_ol, inp%initial%velocity, inp%initial%attitude, inp%initial%angular_rate, st)
    if (.not. st%ok()) return
    if (.not. all(is_set(inp%initial%position))) then
      dz = huge(1.0_wp)
      do i = 1, model%par%n_gears
        call model%gear(i)%g%footpad(pos, vel)
        xd = body_point_position(model%body, matmul(model%par%rot(:, :, i), pos))
        ! moving the body down by dz raises the penetration by dz * (-n_z) = dz cos(slope)
        dz = min(dz, (-inp%initial%clearance - penetration(model%par%plane(i), xd))/cos(inp%terrain%slope(i)))
      end do
      x_ol = [0.0_wp, 0.0_wp, dz]
      call body_init(model%body, inp%lander%mass, &
        inertia_tensor(inp%lander%ixx, inp%lander%iyy, inp%lander%izz, inp%lander%ixy, inp%lander%ixz, inp%lander%iyz), &
        inp%lander%mass_centre, x_ol, inp%initial%velocity, inp%initial%attitude, inp%initial%angular_rate, st)
      if (.not. st%ok()) return
    end if
    model%body%acc = model%par%g_vec     ! free fall before touchdown
    do i = 1, model%par%n_gears
      call model%gear(i)%g%leg_momentum(pos, model%par%first_moment0(:, i), dz)
    end do
  end subroutine place_lander

  !> Caches gear i's rotation, strut and coordinate counts in the model (after the gear is set or
  !! replaced; before its first evaluation).
  subroutine gear_counts(model, i)
    type(model_t), intent(inout) :: model       !! model with gear i allocated
    integer, intent(in) :: i                    !! gear [-]
    model%par%rot(:, :, i) = model%gear(i)%g%rotation()
    model%par%n_struts(i) = model%gear(i)%g%strut_count()
    model%par%n_q(i) = model%gear(i)%g%coordinate_count()
  end subroutine gear_counts

  !> Energy of the legs' motion relative to the body: relative kinetic energy, the cross terms
  !! V . p_rel + w . h_rel(mass centre) of the kinetic energy (the body carries the total mass; the
  !! same quadratic form as landyn_impact's kinetic metric), and the potential energy of the legs'
  !! relative displacement.
  function leg_energy(model, gravity) result(e)
    type(model_t), intent(in) :: model   !! model
    real(wp), intent(in) :: gravity      !! [m/s^2]
    real(wp) :: e                        !! [J]
    integer :: i
    real(wp) :: p_rel(3), h_rel(3), t_rel, fm(3), mleg, rg(3, 3), rot(3, 3), pl(3), hl(3), p_dummy(3)
    e = 0.0_wp
    do i = 1, model%par%n_gears
      call model%gear(i)%g%relative_momenta(p_rel, h_rel, t_rel)
      call model%gear(i)%g%leg_momentum(p_dummy, fm, mleg)
      rot = model%par%rot(:, :, i)
      rg = matmul(model%body%r, rot)
      pl = mv3(rot, p_rel)
      hl = mv3(rot, h_rel) - cross3(model%body%mc, pl)
      e = e + t_rel + dot_product(model%body%v, mv3(model%body%r, pl)) + dot_product(model%body%omega, hl) &
            - gravity*dot_product([0.0_wp, 0.0_wp, 1.0_wp], matmul(rg, fm - model%par%first_moment0(:, i)))
    end do
  end function leg_energy

  !> Snapshot of everything that evolves in a simulation: body, gears (coordinates, rates, crush
  !! modes and history, caches), footpad histories and stick states, and the integrator's
  !! state and the recorder's accounts. Restoring it makes the simulation continue exactly as from the moment it was
  !! taken (bit for bit): the basis of rejected steps and event location.
  subroutine sim_save(sim, snap)
    type(sim_t), intent(in) :: sim              !! simulation
    ! inout, not out: intent(out) would first reset the whole snapshot (max_gears gear states)
    ! to its default values, a cost of the same order as the copy itself, at every step
    type(sim_snapshot_t), intent(inout) :: snap !! its evolving state (previous contents replaced)
    integer :: i
    snap%body = sim%model%body
    do i = 1, sim%model%par%n_gears
      associate (g => sim%model%gear(i)%g)
        if (.not. allocated(snap%gear(i)%s)) call g%new_snapshot(snap%gear(i)%s)
        call g%save_state(snap%gear(i)%s)
      end associate
    end do
    snap%footpad = sim%model%footpad
    snap%state = sim%state
    snap%rec = sim%rec
  end subroutine sim_save

  !> Puts a snapshot from sim_save back.
  subroutine sim_restore(sim, snap)
    type(sim_t), intent(inout) :: sim           !! simulation
    type(sim_snapshot_t), intent(in) :: snap    !! snapshot
    integer :: i
    sim%model%body = snap%body
    do i = 1, sim%model%par%n_gears
      call sim%model%gear(i)%g%restore_state(snap%gear(i)%s)
    end do
    sim%model%footpad = snap%footpad
    sim%state = snap%state
    sim%rec = snap%rec
  end subroutine sim_restore

  !> Advances the stored velocities of body and gears by `lead` times the accelerations of an
  !! evaluation, keeping the stored ones in `kept` (restore_velocities puts them back). The
  !! semi-implicit Euler step is the leapfrog: its positions belong to t and its stored velocities
  !! to t - h/2, so lead = h/2 with the accelerations at t gives the velocities at t.
  pure subroutine lead_velocities(model, lead, ev, kept)
    type(model_t), intent(inout) :: model       !! model
    real(wp), intent(in) :: lead                !! [s]
    type(sim_eval_t), intent(in) :: ev          !! evaluation with the accelerations
    type(velocities_t), intent(out) :: kept     !! the stored velocities
    integer :: i, nq
    kept%v = model%body%v
    kept%omega = model%body%omega
    model%body%v = kept%v + lead*ev%acc
    model%body%omega = kept%omega + lead*ev%alpha
    do i = 1, model%par%n_gears
      nq = model%par%n_q(i)
      call model%gear(i)%g%rates(kept%qd(1:nq, i))
      call model%gear(i)%g%set_rates(kept%qd(1:nq, i) + lead*ev%gear(i)%qdd(1:nq))
    end do
  end subroutine lead_velocities

  !> Puts back the velocities kept by lead_velocities.
  pure subroutine restore_velocities(model, kept)
    type(model_t), intent(inout) :: model       !! model
    type(velocities_t), intent(in) :: kept      !! the stored velocities
    integer :: i
    model%body%v = kept%v
    model%body%omega = kept%omega
    do i = 1, model%par%n_gears
      call model%gear(i)%g%set_rates(kept%qd(1:model%par%n_q(i), i))
    end do
  end subroutine restore_velocities

  !> The body's state is finite (no NaN or Inf in position, velocity, attitude, rates).
  pure logical function body_is_finite(body) result(ok)
    type(body_t), intent(in) :: body   !! body
    ok = all(ieee_is_finite(body%x)) .and. all(ieee_is_finite(body%v)) .and. &
         all(ieee_is_finite(body%euler)) .and. all(ieee_is_finite(body%omega))
  end function body_is_finite

  !> The largest stroke of a primary strut (each gear's first) reached by any gear (progress lines).
  pure real(wp) function max_primary_stroke(model, ng) result(s)
    type(model_t), intent(in) :: model          !! model
    integer, intent(in) :: ng                   !! number of gears [-]
    real(wp) :: s_min(max_struts), s_max(max_struts), v(ng)
    integer :: i
    do i = 1, ng
      call model%gear(i)%g%crush_history(s_min(1:model%par%n_struts(i)), s_max(1:model%par%n_struts(i)))
      v(i) = s_max(1)
    end do
    s = maxval(v)
  end function max_primary_stroke

end module landyn_sim_model
