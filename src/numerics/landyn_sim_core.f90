!> The model and the building blocks of its time integration: set-up from the resolved input, the
!! evaluation of forces and accelerations, the step of the paper's scheme (Fig. 6, Steps 1-7), the
!! commit, snapshots, the energy audit and the summary. The integrators (landyn_integrator_*)
!! compose these; run_simulation (landyn_simulation) drives one landing. Library code: returns a
!! status and a message; progress goes to a unit the caller chooses.
!!
!! Per step (all forces from the state at t_n, then semi-implicit Euler):
!!   2. footpad positions and velocities (body kinematics + gear coordinates), penetration and
!!      ground force in each footpad's local surface frame (contact and friction laws);
!!   3.-4. per gear: crush logic and the gear DAE (landyn_gear), force transmitted to the body;
!!   6. body accelerations from gravity, thrust and the gear forces, then the body step;
!!   4. gear step with the direct constraint-violation correction.
module landyn_sim_core
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use landyn_kinds, only: wp, msg_len, max_gears, g_earth, rad2deg
  use landyn_config, only: landyn_input_t, is_set
  use landyn_kinematics, only: rot_z, build_gear_geometry, gear_geometry_t, cross3, mv3, mtv3
  use landyn_body, only: body_t, body_init, body_accelerations, body_step, body_point_position, &
                         body_point_velocity, body_point_acceleration, body_kinetic_energy, inertia_tensor
  use landyn_gear, only: gear_t, gear_state_t, gear_eval_t, strut_mass_t, gear_init, &
                         gear_evaluate, gear_commit, gear_prepare, gear_integrate, gear_footpad, &
                         gear_leg_momentum, gear_relative_momenta, gear_settle, gear_law_segments, n_q, idx_len
  use landyn_impact, only: system_velocity_projection
  use landyn_loads, only: n_load, load_peaks_t, gear_load_vector, load_peaks_init, load_peaks_update
  use landyn_buffer, only: primary_honeycomb_t, secondary_honeycomb_t
  use landyn_terrain, only: terrain_plane_t, make_terrain_planes, penetration, penetration_rate, slip_velocity, &
                            to_global
  use landyn_contact, only: contact_law_t, make_contact_law, advance_contact_state
  use landyn_friction, only: friction_law_t, make_friction_law
  use landyn_footpad_state, only: footpad_state_t
  use landyn_tube_friction, only: tube_friction_t, make_tube_friction
  implicit none
  private

  public :: sim_result_t, setup_model, model_t
  public :: sim_t, sim_snapshot_t, sim_eval_t, sim_init, sim_step, sim_save, sim_restore
  public :: sim_evaluate, sim_book, sim_advance, sim_accept, finish, body_is_finite

  !> Everything the time loop integrates.
  type :: model_t
    integer :: n_gears = 0
    type(body_t) :: body
    type(gear_t) :: gear(max_gears)
    type(terrain_plane_t) :: plane(max_gears)
    ! The laws are immutable parameter objects shared by all footpads; what evolves (contact
    ! history, stick state) is each footpad's footpad_state_t, changed only when a step is committed.
    class(contact_law_t), allocatable :: contact       !! normal contact law
    class(friction_law_t), allocatable :: friction     !! friction law
    type(footpad_state_t) :: footpad(max_gears)        !! ground-interaction state of footpad i
    real(wp) :: point_a(3, max_gears) = 0.0_wp  !! upper primary joints, lander frame [m]
    real(wp) :: g_vec(3) = 0.0_wp               !! gravity, global [m/s^2]
    real(wp) :: first_moment0(3, max_gears) = 0.0_wp  !! leg first moments of mass at t = 0, gear frame [kg m]
  end type model_t

  !> The integrator's own evolving state (accumulators of the fixed-step loop).
  type :: sim_loop_t
    integer :: n = 0                                   !! steps taken [-]
    real(wp) :: t_next_out = 0.0_wp                    !! next output time [s]
    integer :: next_progress = 1                       !! next progress report (in 5 % of the steps) [-]
    real(wp) :: w_normal = 0.0_wp                      !! work of the normal forces on the ground [J]
    real(wp) :: w_friction = 0.0_wp                    !! friction dissipation [J]
    real(wp) :: w_thrust = 0.0_wp                      !! thrust work [J]
    real(wp) :: w_impact = 0.0_wp                      !! energy dissipated in impacts [J]
    real(wp) :: xd_prev(3, max_gears) = 0.0_wp         !! footpad positions at the previous step [m]
    real(wp) :: delta_prev(max_gears) = 0.0_wp         !! penetrations at the previous step [m]
    real(wp) :: fn_prev(max_gears) = 0.0_wp            !! normal forces at the previous step [N]
    real(wp) :: fground_prev(3, max_gears) = 0.0_wp    !! ground forces at the previous step [N]
    real(wp) :: xt_prev(3) = 0.0_wp                    !! thrust point at the previous step [m]
    real(wp) :: thrust_prev(3) = 0.0_wp                !! thrust at the previous step, global [N]
    real(wp) :: rest_clock = 0.0_wp                    !! time spent below the rest speed [s]
    logical :: touched = .false.                       !! a footpad has touched the ground [-]
    integer :: mode(3, max_gears) = 0                  !! crush mode of each strut at the last step [-]
  end type sim_loop_t

  !> One simulation in progress: the model (parameters and evolving state) and the integrator.
  type :: sim_t
    type(model_t) :: model                             !! the model
    type(sim_loop_t) :: loop                           !! integrator state
    real(wp) :: dt = 0.0_wp                            !! time step [s]
    integer :: nstep = 0                               !! steps to the end time [-]
    real(wp) :: l_char = 0.0_wp                        !! largest mass-centre to footpad distance [m]
    real(wp) :: ke0 = 0.0_wp                           !! initial kinetic energy [J]
    real(wp) :: pe0 = 0.0_wp                           !! initial potential energy [J]
    logical :: loads = .true.                          !! compute and record the interface loads [-]
  end type sim_t

  !> One evaluation of forces and accelerations (sim_evaluate) of the state at t, for a step dt.
  type :: sim_eval_t
    real(wp) :: t = 0.0_wp                             !! time of the state [s]
    real(wp) :: xd(3, max_gears) = 0.0_wp              !! footpad positions, global [m]
    real(wp) :: vd(3, max_gears) = 0.0_wp              !! footpad velocities, global [m/s]
    real(wp) :: delta(max_gears) = 0.0_wp              !! penetrations [m]
    real(wp) :: fn(max_gears) = 0.0_wp                 !! normal forces [N]
    real(wp) :: fground(3, max_gears) = 0.0_wp         !! ground forces on the footpads, global [N]
    type(footpad_state_t) :: trial(max_gears)          !! footpad states advanced by this evaluation
    real(wp) :: thrust_g(3) = 0.0_wp                   !! thrust, global [N]
    real(wp) :: acc(3) = 0.0_wp                        !! mass-centre acceleration, global [m/s^2]
    real(wp) :: alpha(3) = 0.0_wp                      !! body angular acceleration, lander axes [rad/s^2]
    real(wp) :: ovl(3) = 0.0_wp                        !! overload (a - g)/g0, lander axes [g]
    type(gear_eval_t) :: gear(max_gears)               !! each gear's evaluation: accelerations, buffer
                                                       !! forces, lock decisions (committed by sim_advance)
    real(wp) :: qdd(n_q, max_gears) = 0.0_wp           !! gear accelerations [m/s^2, rad/s^2]
    real(wp) :: strut_len(3, max_gears) = 0.0_wp       !! strut lengths [m]
    logical :: locks_changed = .false.                 !! a strut locked or was released [-]
    ! discrete state after the evaluation: what an event changes
    integer :: mode(3, max_gears) = 0                  !! strut modes (strut_modes) [-]
    integer :: segment(3, max_gears) = 0               !! piece of each buffer law (stage, stop) [-]
    logical :: contact(max_gears) = .false.            !! footpad in contact [-]
    logical :: stuck(max_gears) = .false.              !! footpad in its friction law's stick state [-]
    real(wp) :: tilt = 0.0_wp                          !! tilt of the lander z axis from vertical [rad]
  end type sim_eval_t

  !> The stored velocities of body and gears, kept while lead_velocities has advanced them.
  type :: velocities_t
    real(wp) :: v(3) = 0.0_wp                          !! mass-centre velocity, global [m/s]
    real(wp) :: omega(3) = 0.0_wp                      !! body rates, lander axes [rad/s]
    real(wp) :: qd(n_q, max_gears) = 0.0_wp            !! gear rates [m/s, rad/s]
  end type velocities_t

  !> Everything of a simulation that evolves in time (see sim_save).
  type :: sim_snapshot_t
    type(body_t) :: body                               !! body state
    type(gear_state_t) :: gear(max_gears)              !! gear states
    type(footpad_state_t) :: footpad(max_gears)        !! footpad histories and stick states
    type(sim_loop_t) :: loop                           !! integrator state
  end type sim_snapshot_t

  !> Time series (columns = output samples) and summary of one run.
  type :: sim_result_t
    integer :: n_gears = 0
    integer :: n_out = 0                                   !! samples stored
    real(wp), allocatable :: t(:)                          !! [s]
    real(wp), allocatable :: position(:, :)                !! (3, n) lander origin O_L, global [m]
    real(wp), allocatable :: mc_position(:, :)             !! (3, n) mass centre, global [m]
    real(wp), allocatable :: velocity(:, :)                !! (3, n) mass-centre velocity, global [m/s]
    real(wp), allocatable :: euler(:, :)                   !! (3, n) yaw, pitch, roll [deg]
    real(wp), allocatable :: rate(:, :)                    !! (3, n) body rates p, q, r [deg/s]
    real(wp), allocatable :: overload(:, :)                !! (3, n) (a - g)/g0 in lander axes [g]
    real(wp), allocatable :: strut_length(:, :, :)         !! (3, n_gears, n) [m]
    real(wp), allocatable :: stroke(:, :, :)               !! (3, n_gears, n) Table-3 sense [m]
    real(wp), allocatable :: strut_force(:, :, :)          !! (3, n_gears, n) axial, compression positive [N]
    real(wp), allocatable :: footpad_position(:, :, :)     !! (3, n_gears, n) global [m]
    real(wp), allocatable :: ground_force(:, :, :)         !! (3, n_gears, n) on the footpad, global [N]
    real(wp), allocatable :: normal_force(:, :)            !! (n_gears, n) [N]
    real(wp), allocatable :: friction_force(:, :)          !! (n_gears, n) magnitude [N]
    real(wp), allocatable :: penetration(:, :)             !! (n_gears, n) [m]
    real(wp), allocatable :: slip_speed(:, :)              !! (n_gears, n) [m/s]
    real(wp), allocatable :: energy(:, :)                  !! (n, n_energy) audit channels, one column each [J]
    ! interface loads (landyn_loads): each gear's load vector (joint forces a, b, c on the body,
    ! footpad force at d, joint moments a, b, c), lander axes, and the gear's total force on the body
    ! from its momentum balance (the equilibrium reference of the joint forces)
    real(wp), allocatable :: loads(:, :, :)                !! (n_load, n_gears, n) [N, N m]
    real(wp), allocatable :: interface_force(:, :, :)      !! (3, n_gears, n) [N]
    real(wp), allocatable :: gear_rot(:, :, :)             !! (3, 3, n_gears) gear frame -> lander frame [-]
    type(load_peaks_t) :: load_peaks                       !! peak-load table over every accepted step
    ! Peaks over each output interval (every step since the previous sample, this one included),
    ! so that the stored histories keep the peaks the summary reports.
    real(wp), allocatable :: overload_peak(:)              !! (n) largest |a - g|/g0 [g]
    real(wp), allocatable :: normal_force_peak(:, :)       !! (n_gears, n) [N]
    real(wp), allocatable :: strut_force_peak(:, :, :)     !! (3, n_gears, n) largest |axial| [N]
    real(wp) :: acc_overload = 0.0_wp                      !! running interval peak [g]
    real(wp), allocatable :: acc_normal_force(:)           !! (n_gears) running interval peak [N]
    real(wp), allocatable :: acc_strut_force(:, :)         !! (3, n_gears) running interval peak [N]
    ! summary
    real(wp), allocatable :: crush_net(:, :)               !! (3, n_gears) signed net crush [m]
    real(wp), allocatable :: crush_pos(:, :)               !! (3, n_gears) crushed toward +s [m]
    real(wp), allocatable :: crush_neg(:, :)               !! (3, n_gears) crushed toward -s [m]
    real(wp), allocatable :: stroke_final(:, :)            !! (3, n_gears) [m]
    real(wp), allocatable :: stroke_margin(:, :)           !! (3, n_gears) capacity minus crushed, worst direction [m]
    real(wp), allocatable :: crush_work(:, :)              !! (3, n_gears) [J]
    integer, allocatable :: bottomed(:, :)                 !! (3, n_gears) 1 when a stroke exceeded capacity
    real(wp), allocatable :: peak_penetration(:)           !! (n_gears) [m]
    real(wp), allocatable :: slide_distance(:)             !! (n_gears) [m]
    real(wp), allocatable :: peak_normal_force(:)          !! (n_gears) [N]
    real(wp), allocatable :: peak_strut_force(:, :)        !! (3, n_gears) largest |axial| [N]
    integer, allocatable :: mode_switches(:, :)            !! (3, n_gears) crush-mode changes [-]
    real(wp) :: peak_overload = 0.0_wp                     !! largest |a - g|/g0 [g]
    real(wp) :: t_peak_overload = 0.0_wp                   !! [s]
    real(wp) :: final_euler(3) = 0.0_wp                    !! [deg]
    real(wp) :: final_tilt = 0.0_wp                        !! [deg]
    real(wp) :: max_tilt = 0.0_wp                          !! [deg]
    logical :: tipped_over = .false.
    logical :: at_rest = .false.
    character(len=64) :: end_reason = ''
    real(wp) :: energy_input = 0.0_wp                      !! initial KE + potential released + thrust work [J]
    real(wp) :: energy_residual = 0.0_wp                   !! final residual / energy_input [-]
    real(wp) :: max_violation = 0.0_wp                     !! after correction [m]
    real(wp) :: max_drift = 0.0_wp                         !! before correction [m]
    real(wp) :: t_final = 0.0_wp                           !! [s]
    integer :: n_steps = 0                                 !! accepted steps [-]
    character(len=16) :: integrator = ''                   !! integrator that produced the result
    integer :: n_evaluations = 0                           !! force evaluations, rejected steps included [-]
    integer :: n_rejected = 0                              !! rejected steps (error or event) [-]
    integer :: n_events = 0                                !! accepted steps that ended at a located event [-]
    integer :: n_forced = 0                                !! steps of event_resolution accepted above the tolerance [-]
    real(wp) :: dt_smallest = 0.0_wp                       !! smallest accepted step [s]
    real(wp) :: dt_largest = 0.0_wp                        !! largest accepted step [s]
    real(wp) :: wall_time = 0.0_wp                         !! [s]
    real(wp) :: initial_position(3) = 0.0_wp               !! O_L at t = 0 [m]
  end type sim_result_t

  integer, parameter, public :: n_energy = 11
  character(len=24), parameter, public :: energy_names(n_energy) = [character(len=24) :: &
    'kinetic_body', 'kinetic_legs', 'potential_released', 'honeycomb_work', 'contact_damping', &
    'contact_elastic', 'friction', 'strut_impacts', 'thrust_work', 'input', 'residual']

contains

  !> Builds the model (body, gears, terrain, laws) and places it at t = 0.
  subroutine setup_model(inp, model, stat, errmsg)
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input
    type(model_t), intent(out) :: model         !! model at t = 0
    integer, intent(out) :: stat                !! 0 on success
    character(len=*), intent(inout) :: errmsg   !! message on failure
    type(gear_geometry_t) :: geom
    type(strut_mass_t) :: sm(3)
    type(tube_friction_t) :: tube
    real(wp) :: rot(3, 3), pts(3, 6), x_ol(3), dz, xd(3), pos(3), vel(3)
    integer :: i, k
    character(len=msg_len) :: m2

    stat = 0
    model%n_gears = inp%gears%n_gears
    model%g_vec = [0.0_wp, 0.0_wp, inp%simulation%gravity]
    call make_contact_law(inp%contact, model%contact, stat, m2)
    if (stat /= 0) then; errmsg = m2; return; end if
    call make_friction_law(inp%friction, model%friction, stat, m2)
    if (stat /= 0) then; errmsg = m2; return; end if
    model%footpad = footpad_state_t()
    call make_tube_friction(inp%primary%tube_friction, inp%primary%mu_tube, inp%primary%tube_outer_length, &
                            inp%primary%tube_inner_length, inp%primary%tube_leg_length, inp%primary%tube_lever, &
                            tube, stat, m2)
    if (stat /= 0) then; errmsg = m2; return; end if
    call make_terrain_planes(inp%terrain, model%plane(1:model%n_gears), stat, m2)
    if (stat /= 0) then; errmsg = m2; return; end if

    sm(1) = strut_mass_t(inp%primary%outer_mass, inp%primary%outer_cm, inp%primary%outer_inertia, &
                         inp%primary%inner_mass, inp%primary%inner_cm, inp%primary%inner_inertia, &
                         inp%primary%footpad_mass)
    sm(2) = strut_mass_t(inp%secondary%outer_mass, inp%secondary%outer_cm, inp%secondary%outer_inertia, &
                         inp%secondary%inner_mass, inp%secondary%inner_cm, inp%secondary%inner_inertia, 0.0_wp)
    sm(3) = sm(2)
    do i = 1, model%n_gears
      rot = rot_z(inp%gears%rotation(i))
      pts(:, 1) = inp%gears%point_a(:, i)
      pts(:, 2) = inp%gears%point_b(:, i)
      pts(:, 3) = inp%gears%point_c(:, i)
      pts(:, 4) = inp%gears%point_d(:, i)
      pts(:, 5) = inp%gears%point_e(:, i)
      pts(:, 6) = inp%gears%point_f(:, i)
      model%point_a(:, i) = pts(:, 1)
      pts = matmul(transpose(rot), pts)          ! lander frame -> gear frame
      call build_gear_geometry(pts(:, 1), pts(:, 2), pts(:, 3), pts(:, 4), pts(:, 5), pts(:, 6), geom, stat, m2)
      if (stat /= 0) then
        write (errmsg, '(a,i0,a,a)') '&gears: gear ', i, ': ', trim(m2)
        return
      end if
      allocate (model%gear(i)%buffer(1)%law, source=primary_honeycomb_t(n_stages=inp%primary%n_stages, &
        stage_force=inp%primary%stage_force, stage_end=inp%primary%stage_end, &
        k_stop=inp%primary%stop_stiffness, c_stop=inp%primary%stop_damping))
      do k = 2, 3
        allocate (model%gear(i)%buffer(k)%law, source=secondary_honeycomb_t( &
          f_lengthening=inp%secondary%force_lengthening, f_shortening=inp%secondary%force_shortening, &
          stroke_lengthening=inp%secondary%stroke_lengthening, stroke_shortening=inp%secondary%stroke_shortening, &
          k_stop=inp%secondary%stop_stiffness, c_stop=inp%secondary%stop_damping))
      end do
      call gear_init(model%gear(i), geom, rot, sm, stat, m2, tube)
      if (stat /= 0) then; errmsg = m2; return; end if
    end do

    ! Placement: the given position, or the lowest footpad at `clearance` above its surface.
    if (all(is_set(inp%initial%position))) then
      x_ol = inp%initial%position
    else
      x_ol = 0.0_wp
    end if
    call body_init(model%body, inp%lander%mass, &
      inertia_tensor(inp%lander%ixx, inp%lander%iyy, inp%lander%izz, inp%lander%ixy, inp%lander%ixz, inp%lander%iyz), &
      inp%lander%mass_centre, x_ol, inp%initial%velocity, inp%initial%attitude, inp%initial%angular_rate, stat, m2)
    if (stat /= 0) then; errmsg = m2; return; end if
    if (.not. all(is_set(inp%initial%position))) then
      dz = huge(1.0_wp)
      do i = 1, model%n_gears
        call gear_footpad(model%gear(i), pos, vel)
        xd = body_point_position(model%body, matmul(model%gear(i)%rot, pos))
        ! moving the body down by dz raises the penetration by dz * (-n_z) = dz cos(slope)
        dz = min(dz, (-inp%initial%clearance - penetration(model%plane(i), xd))/cos(inp%terrain%slope(i)))
      end do
      x_ol = [0.0_wp, 0.0_wp, dz]
      call body_init(model%body, inp%lander%mass, &
        inertia_tensor(inp%lander%ixx, inp%lander%iyy, inp%lander%izz, inp%lander%ixy, inp%lander%ixz, inp%lander%iyz), &
        inp%lander%mass_centre, x_ol, inp%initial%velocity, inp%initial%attitude, inp%initial%angular_rate, stat, m2)
      if (stat /= 0) then; errmsg = m2; return; end if
    end if
    model%body%acc = model%g_vec     ! free fall before touchdown
    do i = 1, model%n_gears
      call gear_leg_momentum(model%gear(i), pos, model%first_moment0(:, i), dz)
    end do
  end subroutine setup_model

  !> Energy of the legs' motion relative to the body: relative kinetic energy, the cross terms
  !! V . p_rel + w . h_rel(mass centre) of the kinetic energy (the body carries the total mass; the
  !! same quadratic form as landyn_impact's kinetic metric), and the potential energy of the legs'
  !! relative displacement.
  function leg_energy(model, gravity) result(e)
    type(model_t), intent(in) :: model   !! model
    real(wp), intent(in) :: gravity      !! [m/s^2]
    real(wp) :: e                        !! [J]
    integer :: i
    real(wp) :: p_rel(3), h_rel(3), t_rel, fm(3), mleg, rg(3, 3), pl(3), hl(3), p_dummy(3)
    e = 0.0_wp
    do i = 1, model%n_gears
      call gear_relative_momenta(model%gear(i), p_rel, h_rel, t_rel)
      call gear_leg_momentum(model%gear(i), p_dummy, fm, mleg)
      rg = matmul(model%body%r, model%gear(i)%rot)
      pl = mv3(model%gear(i)%rot, p_rel)
      hl = mv3(model%gear(i)%rot, h_rel) - cross3(model%body%mc, pl)
      e = e + t_rel + dot_product(model%body%v, mv3(model%body%r, pl)) + dot_product(model%body%omega, hl) &
            - gravity*dot_product([0.0_wp, 0.0_wp, 1.0_wp], matmul(rg, fm - model%first_moment0(:, i)))
    end do
  end function leg_energy

  !> Builds the model, allocates the result and sets the integrator's state at t = 0.
  subroutine sim_init(inp, sim, res, stat, errmsg)
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input
    type(sim_t), intent(out) :: sim             !! simulation at t = 0
    type(sim_result_t), intent(out) :: res      !! result, allocated
    integer, intent(out) :: stat                !! 0 on success
    character(len=*), intent(inout) :: errmsg   !! message on failure
    integer :: i, ng, n_cap
    stat = 0
    ng = inp%gears%n_gears
    res%n_gears = ng
    call setup_model(inp, sim%model, stat, errmsg)
    if (stat /= 0) return
    res%initial_position = sim%model%body%x - matmul(sim%model%body%r, sim%model%body%mc)
    sim%dt = inp%simulation%dt
    sim%nstep = nint(inp%simulation%t_end/sim%dt)
    n_cap = int(inp%simulation%t_end/inp%output%interval + 1.0e-9_wp) + 2
    call allocate_result(res, ng, n_cap)
    do i = 1, ng
      res%gear_rot(:, :, i) = sim%model%gear(i)%rot
    end do
    sim%l_char = 0.0_wp
    do i = 1, ng
      sim%l_char = max(sim%l_char, norm2(inp%gears%point_d(:, i) - inp%lander%mass_centre))
    end do
    sim%ke0 = body_kinetic_energy(sim%model%body)
    sim%pe0 = -sim%model%body%mass*inp%simulation%gravity*sim%model%body%x(3)
    sim%loop%xt_prev = body_point_position(sim%model%body, inp%engine%point)
    sim%loop%n = 0
    res%end_reason = 'end time reached'
  end subroutine sim_init

  !> One pass of the fixed-step scheme (paper Fig. 6): forces and accelerations at t_n = n dt, the
  !! output sample of t_n, then (unless t_n is the end time) the step to t_n+1 and its commit
  !! (footpad histories, strut modes), followed by the divergence, tip-over and rest checks.
  !! done = .true. when the run has ended (end time, rest, tip-over or failure).
  subroutine sim_step(sim, inp, res, done, stat, errmsg, progress_unit, ev)
    type(sim_t), intent(inout) :: sim           !! simulation, advanced by one step
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input
    type(sim_result_t), intent(inout) :: res    !! time series and summary
    logical, intent(out) :: done                !! the run has ended
    integer, intent(out) :: stat                !! 0 on success (also for a tip-over); /= 0 on divergence
    character(len=*), intent(inout) :: errmsg   !! diagnosis on failure
    integer, intent(in) :: progress_unit        !! unit for progress lines, < 0 for none
    type(sim_eval_t), intent(inout) :: ev       !! work record for the step's evaluation (the caller's, so
                                                !! that it is not set up afresh at every step)
    real(wp) :: t, dt

    done = .false.
    dt = sim%dt
    t = sim%loop%n*dt
    call sim_evaluate(sim, inp, t, dt, ev, stat, errmsg)
    if (stat /= 0) then
      call finish(sim%model, res, t)
      done = .true.
      return
    end if
    call sim_book(sim, inp, res, ev, dt, 0.5_wp*dt)
    if (sim%loop%n == sim%nstep) then
      res%at_rest = sim%loop%rest_clock >= inp%simulation%rest_time
      call finish(sim%model, res, sim%nstep*dt)
      done = .true.
      return
    end if
    call sim_advance(sim, inp, ev, dt, stat, errmsg)
    if (stat /= 0) then
      call finish(sim%model, res, t + dt)
      done = .true.
      return
    end if
    call sim_accept(sim, inp, res, t + dt, dt, done, stat, errmsg, progress_unit, &
                    sim%loop%n >= sim%loop%next_progress*sim%nstep/20)
  end subroutine sim_step

  !> Forces and accelerations of the state at time t for a step of dt to come (Steps 2, 3-4 and 6
  !! of Fig. 6): footpad positions and velocities, ground forces from a trial copy of the footpad
  !! states, each gear's crush logic and DAE (dt enters only the velocity-level lock decisions),
  !! the loads on the body and its accelerations. The simulation is not changed (intent(in)):
  !! the accelerations, strut forces, lock decisions and footpad states are the evaluation's, and
  !! sim_advance commits the evaluation the step is taken with.
  subroutine sim_evaluate(sim, inp, t, dt, ev, stat, errmsg, acc_field, alpha_field, v_lead)
    type(sim_t), intent(in) :: sim              !! simulation (unchanged)
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input
    real(wp), intent(in) :: t                   !! time of the state [s]
    real(wp), intent(in) :: dt                  !! step to come [s]
    ! inout, not out: every component an evaluation defines is set below (for gears 1..n_gears);
    ! intent(out) would reset the whole record, max_gears gears of it, at every evaluation
    type(sim_eval_t), intent(inout) :: ev       !! the evaluation (previous contents replaced)
    integer, intent(out) :: stat                !! 0 on success
    character(len=*), intent(inout) :: errmsg   !! diagnosis on failure
    real(wp), intent(in), optional :: acc_field(3)    !! body acceleration for the legs' frame field, global;
                                                      !! default: the committed (last step's) one [m/s^2]
    real(wp), intent(in), optional :: alpha_field(3)  !! body angular acceleration for it, lander axes;
                                                      !! default: the committed one [rad/s^2]
    real(wp), intent(in), optional :: v_lead          !! the footpad velocities (contact damping, friction) are
                                                      !! taken with the stored velocities advanced by v_lead
                                                      !! times the committed accelerations (the leapfrog's
                                                      !! velocities lag the positions by half a step); default 0 [s]
    integer :: ng, i
    type(body_t) :: body
    logical :: thrusting
    real(wp) :: r(3, 3), pos_g(3), vel_g(3), d_l(3), delta_dot(max_gears), ft(2), vslip(2), dslip(2), qd_l(n_q)
    real(wp) :: field(3), ffoot(3), force(3), moment(3), fb_l(3), thrust_l(3), gf(3, max_gears), gm(3, max_gears)
    character(len=msg_len) :: m2

    stat = 0
    ng = sim%model%n_gears
    ev%t = t
    associate (model => sim%model)
      r = model%body%r
      ! the body as this evaluation sees it: its velocities led for the footpads, then its
      ! accelerations for the legs' frame field and the new ones
      body = model%body
      if (present(v_lead)) then
        body%v = model%body%v + v_lead*model%body%acc
        body%omega = model%body%omega + v_lead*model%body%alpha
      end if
      ! ---- Step 2: footpads and ground forces
      do i = 1, ng
        if (present(v_lead)) then
          qd_l = model%gear(i)%st%qd + v_lead*model%gear(i)%st%qdd
          call gear_footpad(model%gear(i), pos_g, vel_g, qd_l)
        else
          call gear_footpad(model%gear(i), pos_g, vel_g)
        end if
        d_l = mv3(model%gear(i)%rot, pos_g)
        ev%xd(:, i) = body_point_position(body, d_l)
        ev%vd(:, i) = body_point_velocity(body, d_l) + mv3(r, mv3(model%gear(i)%rot, vel_g))
        ev%delta(i) = penetration(model%plane(i), ev%xd(:, i))
        delta_dot(i) = penetration_rate(model%plane(i), ev%vd(:, i))
        ! trial footpad state of this step: committed with the step (sim_advance)
        ev%trial(i) = model%footpad(i)
        if (model%contact%has_history) call advance_contact_state(ev%trial(i)%contact, ev%delta(i), delta_dot(i))
        if (ev%delta(i) > 0.0_wp) then
          ev%fn(i) = model%contact%normal_force(ev%delta(i), delta_dot(i), ev%trial(i)%contact)
        else
          ev%fn(i) = 0.0_wp
        end if
        vslip = slip_velocity(model%plane(i), ev%vd(:, i))
        if (model%friction%has_stiction) then
          ! stick state: advanced with the footpad's tangential displacement over the last step
          dslip = 0.0_wp
          if (sim%loop%n > 0) dslip = slip_velocity(model%plane(i), ev%xd(:, i) - sim%loop%xd_prev(:, i))
          call model%friction%stick_slip_force(ev%trial(i)%friction, vslip, dslip, ev%fn(i), ft)
        else
          ft = model%friction%friction_force(vslip, ev%fn(i))
        end if
        ev%fground(:, i) = to_global(model%plane(i), [ft(1), ft(2), ev%fn(i)])
      end do
      body%v = model%body%v
      body%omega = model%body%omega
      thrusting = inp%engine%thrust > 0.0_wp .and. t < inp%engine%cutoff_time
      thrust_l = 0.0_wp
      if (thrusting) thrust_l = inp%engine%thrust*inp%engine%direction
      ev%thrust_g = mv3(r, thrust_l)

      ! ---- Steps 3-4: gear dynamics and crush logic. The legs' frame moves with the body, whose
      ! acceleration at t is not known before the gears' loads are: the paper's scheme takes the last
      ! evaluation's, an integrator may pass a better estimate.
      if (present(acc_field)) body%acc = acc_field
      if (present(alpha_field)) body%alpha = alpha_field
      force = model%body%mass*model%g_vec
      moment = 0.0_wp
      ev%locks_changed = .false.
      do i = 1, ng
        field = mtv3(model%gear(i)%rot, mtv3(r, model%g_vec) - body_point_acceleration(body, model%point_a(:, i)))
        ffoot = mtv3(model%gear(i)%rot, mtv3(r, ev%fground(:, i)))
        call gear_evaluate(model%gear(i), ev%gear(i), ffoot, field, stat, m2, dt, mtv3(model%gear(i)%rot, body%alpha), &
                           sim%loads)
        if (stat /= 0) then
          write (errmsg, '(a,i0,a,es12.5,a,a)') 'gear ', i, ' at t = ', t, ' s: ', trim(m2)
          return
        end if
        associate (ge => ev%gear(i))
          if (any(model%gear(i)%st%locked .neqv. ge%locked)) ev%locks_changed = .true.
          gf(:, i) = mv3(model%gear(i)%rot, ge%f_body)
          gm(:, i) = mv3(model%gear(i)%rot, ge%m_body)
          ev%qdd(:, i) = ge%qdd
          ev%mode(:, i) = strut_modes(ge%locked, ge%axial, ge%dir)
        end associate
        ev%strut_len(:, i) = model%gear(i)%st%q(idx_len)
        ev%segment(:, i) = gear_law_segments(model%gear(i))
        ev%contact(i) = ev%delta(i) > 0.0_wp
        ev%stuck(i) = model%friction%has_stiction .and. ev%trial(i)%friction%stuck
      end do
      fb_l = symmetric_sum(gf, ng)
      force = force + mv3(r, fb_l)
      moment = symmetric_sum(gm, ng) - cross3(model%body%mc, fb_l)
      ! engine thrust (computed with the footpad forces above)
      if (thrusting) then
        moment = moment + cross3(inp%engine%point - model%body%mc, thrust_l)
      end if
      force = force + ev%thrust_g
      ! ---- Step 6: body accelerations
      call body_accelerations(body, force, moment)
      ev%acc = body%acc
      ev%alpha = body%alpha
      ev%ovl = mtv3(r, body%acc - model%g_vec)/g_earth
      ev%tilt = acos(max(-1.0_wp, min(1.0_wp, r(3, 3))))
    end associate
  end subroutine sim_evaluate

  !> Books an accepted evaluation: the work of the ground forces and the thrust since the previous
  !! booked evaluation (trapezoidal rule: the scheme is the leapfrog, positions at t, stored
  !! velocities half a step behind, whose synchronised kinetic energy changes by exactly that to
  !! second order), the slide distance, the peaks of every step, and the output sample when one is
  !! due (within `slack` of its time).
  subroutine sim_book(sim, inp, res, ev, h_sync, slack)
    type(sim_t), intent(inout) :: sim           !! simulation (accumulators updated)
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input
    type(sim_result_t), intent(inout) :: res    !! time series and summary
    type(sim_eval_t), intent(in) :: ev          !! evaluation of the current state
    real(wp), intent(in) :: h_sync              !! the stored velocities lag the positions by h_sync/2 [s]
    real(wp), intent(in) :: slack               !! a sample is due this close before its time [s]
    integer :: ng, i
    real(wp) :: fnm, xt(3)

    ng = sim%model%n_gears
    associate (model => sim%model)
      if (any(ev%delta(1:ng) > 0.0_wp)) sim%loop%touched = .true.
      if (sim%loop%n > 0) then
        do i = 1, ng
          fnm = 0.5_wp*(sim%loop%fn_prev(i) + ev%fn(i))
          sim%loop%w_normal = sim%loop%w_normal + fnm*(ev%delta(i) - sim%loop%delta_prev(i))
          sim%loop%w_friction = sim%loop%w_friction &
            - dot_product(0.5_wp*(sim%loop%fground_prev(:, i) + ev%fground(:, i)), ev%xd(:, i) - sim%loop%xd_prev(:, i)) &
            - fnm*(ev%delta(i) - sim%loop%delta_prev(i))
          if (sim%loop%fn_prev(i) > 0.0_wp) res%slide_distance(i) = res%slide_distance(i) &
            + norm2(slip_velocity(model%plane(i), ev%xd(:, i) - sim%loop%xd_prev(:, i)))
        end do
        xt = body_point_position(model%body, inp%engine%point)
        sim%loop%w_thrust = sim%loop%w_thrust + dot_product(0.5_wp*(sim%loop%thrust_prev + ev%thrust_g), xt - sim%loop%xt_prev)
        sim%loop%xt_prev = xt
      end if
      do i = 1, ng
        res%peak_penetration(i) = max(res%peak_penetration(i), ev%delta(i))
        res%peak_normal_force(i) = max(res%peak_normal_force(i), ev%fn(i))
      end do
      sim%loop%xd_prev = ev%xd; sim%loop%delta_prev = ev%delta; sim%loop%fn_prev = ev%fn
      sim%loop%fground_prev = ev%fground
      sim%loop%thrust_prev = ev%thrust_g

      if (norm2(ev%ovl) > res%peak_overload) then
        res%peak_overload = norm2(ev%ovl)
        res%t_peak_overload = ev%t
      end if
      ! peaks of every step, for the summary and the interval-peak channels
      res%acc_overload = max(res%acc_overload, norm2(ev%ovl))
      if (sim%loads) call load_peaks_update(res%load_peaks, ev%t, eval_loads(model, ev), ng)
      do i = 1, ng
        res%acc_normal_force(i) = max(res%acc_normal_force(i), ev%fn(i))
        res%acc_strut_force(:, i) = max(res%acc_strut_force(:, i), abs(ev%gear(i)%axial))
        res%peak_strut_force(:, i) = max(res%peak_strut_force(:, i), abs(ev%gear(i)%axial))
      end do

      ! ---- output sample (state at t with the forces at t)
      if (ev%t >= sim%loop%t_next_out - slack) then
        call record_sample(sim, inp, res, ev, h_sync)
        sim%loop%t_next_out = sim%loop%t_next_out + inp%output%interval
      end if
    end associate
  end subroutine sim_book

  !> Records the output sample of the state at ev%t with the forces of its evaluation ev: its
  !! velocities (and the audit's kinetic energies) synchronised to ev%t, i.e. the stored ones, half
  !! a step behind, plus half a step (h_sync) of the accelerations just computed.
  subroutine record_sample(sim, inp, res, ev, h_sync)
    type(sim_t), intent(inout) :: sim           !! simulation at ev%t (velocities restored on return)
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input
    type(sim_result_t), intent(inout) :: res    !! time series
    type(sim_eval_t), intent(in) :: ev          !! evaluation of the state
    real(wp), intent(in) :: h_sync              !! step the stored velocities lag by twice [s]
    type(velocities_t) :: kept
    real(wp) :: ke_legs, e_el
    integer :: i
    call lead_velocities(sim%model, 0.5_wp*h_sync, ev, kept)
    ke_legs = leg_energy(sim%model, inp%simulation%gravity)
    e_el = 0.0_wp
    do i = 1, sim%model%n_gears
      if (ev%delta(i) > 0.0_wp) e_el = e_el + sim%model%contact%elastic_energy(ev%delta(i), ev%trial(i)%contact)
    end do
    call record(res, sim%model, ev, sim%loop%w_normal, &
                sim%loop%w_friction, sim%loop%w_thrust, sim%loop%w_impact, sim%ke0, sim%pe0, ke_legs, e_el, &
                inp%simulation%gravity)
    call restore_velocities(sim%model, kept)
  end subroutine record_sample

  !> Steps 4 and 6: semi-implicit Euler over dt for the body and the gears with the accelerations
  !! of the evaluation `ev`, the gears' constraint-violation correction, the velocity projection of
  !! the whole system (plastic impacts, booked in w_impact), then the commit: footpad histories and
  !! stick states from the evaluation's trial copy, rigid gears settled. stat /= 0 (drift, no
  !! convergence, projection failure) leaves the simulation in an unusable state: restore a
  !! snapshot or stop.
  subroutine sim_advance(sim, inp, ev, dt, stat, errmsg, kick)
    type(sim_t), intent(inout) :: sim           !! simulation, advanced to t + dt
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input
    type(sim_eval_t), intent(in) :: ev          !! evaluation of the state at t (sim_evaluate)
    real(wp), intent(in) :: dt                  !! step [s]
    integer, intent(out) :: stat                !! 0 on success
    character(len=*), intent(inout) :: errmsg   !! diagnosis on failure
    real(wp), intent(in), optional :: kick      !! velocity update length (variable-step leapfrog, the
                                                !! step the evaluation was made for); default dt [s]
    integer :: ng, i
    real(wp) :: e_imp
    character(len=msg_len) :: m2

    ng = sim%model%n_gears
    associate (model => sim%model)
      ! ---- commit the evaluation the step is taken with: accelerations, strut forces and modes
      model%body%acc = ev%acc
      model%body%alpha = ev%alpha
      do i = 1, ng
        call gear_commit(model%gear(i), ev%gear(i))
      end do
      call body_step(model%body, dt, kick)
      do i = 1, ng
        call gear_integrate(model%gear(i), dt, inp%simulation%constraint_tol, inp%simulation%max_correction_iter, &
                            inp%simulation%max_constraint_drift, stat, m2, kick=kick)
        if (stat /= 0) then
          write (errmsg, '(a,i0,a,es12.5,a,a)') 'gear ', i, ' at t = ', ev%t + dt, ' s: ', trim(m2)
          return
        end if
      end do
      call system_velocity_projection(model%body, model%gear, ng, inp%simulation%constraint_tol, e_imp, stat, m2)
      if (stat /= 0) then
        write (errmsg, '(a,es12.5,a,a)') 'velocity projection at t = ', ev%t + dt, ' s: ', trim(m2)
        return
      end if
      sim%loop%w_impact = sim%loop%w_impact + e_imp
      ! ---- commit: footpad histories and stick states, strut modes
      model%footpad(1:ng) = ev%trial(1:ng)
      do i = 1, ng
        call gear_settle(model%gear(i))
        call gear_prepare(model%gear(i), stat, m2)
        if (stat /= 0) then
          write (errmsg, '(a,i0,a,es12.5,a,a)') 'gear ', i, ' at t = ', ev%t + dt, ' s: ', trim(m2)
          return
        end if
      end do
      sim%loop%n = sim%loop%n + 1
    end associate
  end subroutine sim_advance

  !> After an accepted step to t: mode-switch counts, divergence, tip-over and rest checks, progress.
  !! done = .true. when the run ends here (tip-over, rest, non-finite state: stat = 4).
  subroutine sim_accept(sim, inp, res, t, dt, done, stat, errmsg, progress_unit, progress_due, ev)
    type(sim_t), intent(inout) :: sim           !! simulation after the step
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input
    type(sim_result_t), intent(inout) :: res    !! time series and summary
    real(wp), intent(in) :: t                   !! time reached [s]
    real(wp), intent(in) :: dt                  !! the step just taken [s]
    logical, intent(out) :: done                !! the run has ended
    integer, intent(out) :: stat                !! 0 on success (also for a tip-over and rest)
    character(len=*), intent(inout) :: errmsg   !! diagnosis on failure
    integer, intent(in) :: progress_unit        !! unit for progress lines, < 0 for none
    logical, intent(in) :: progress_due         !! a progress line is due [-]
    type(sim_eval_t), intent(in), optional :: ev  !! evaluation of the state reached, when the integrator
                                                  !! has made it: its strut modes are counted; default
                                                  !! the committed modes of the step just taken
    integer :: ng, i
    real(wp) :: tilt, speed_char

    stat = 0
    done = .false.
    ng = sim%model%n_gears
    associate (model => sim%model)
      do i = 1, ng
        if (present(ev)) then
          call count_mode_switches(ev%mode(:, i), sim%loop%mode(:, i), res%mode_switches(:, i))
        else
          associate (st => model%gear(i)%st)
            call count_mode_switches(strut_modes(st%locked, st%axial, st%dir), sim%loop%mode(:, i), &
                                     res%mode_switches(:, i))
          end associate
        end if
      end do
      res%n_steps = sim%loop%n

      ! ---- divergence, tip-over and rest checks
      if (.not. body_is_finite(model%body)) then
        stat = 4
        write (errmsg, '(a,es12.5,a)') 'the solution became non-finite at t = ', t, &
          ' s: the integration diverged (reduce &simulation dt or check the input)'
        call finish(model, res, t)
        done = .true.
        return
      end if
      tilt = acos(max(-1.0_wp, min(1.0_wp, model%body%r(3, 3))))
      res%max_tilt = max(res%max_tilt, tilt*rad2deg)
      if (tilt > inp%simulation%tipover_angle) then
        res%tipped_over = .true.
        call end_early(sim, inp, res, t, dt, 'tipped over')
        done = .true.
        return
      end if
      speed_char = norm2(model%body%v) + norm2(model%body%omega)*sim%l_char
      if (sim%loop%touched .and. speed_char < inp%simulation%rest_speed) then
        sim%loop%rest_clock = sim%loop%rest_clock + dt
      else
        sim%loop%rest_clock = 0.0_wp
      end if
      if (inp%simulation%stop_at_rest .and. sim%loop%rest_clock >= inp%simulation%rest_time) then
        res%at_rest = .true.
        call end_early(sim, inp, res, t, dt, 'at rest')
        done = .true.
        return
      end if
      if (progress_unit >= 0 .and. progress_due) then
        write (progress_unit, '(a,f8.4,a,f8.4,a,i3,a,f9.2,a)') 'landyn: t = ', t, ' s of ', &
          inp%simulation%t_end, ' s (', 5*sim%loop%next_progress, ' %), max primary stroke ', &
          1000.0_wp*maxval([(model%gear(i)%st%s_hismax(1), i=1, ng)]), ' mm'
        flush (progress_unit)
        sim%loop%next_progress = sim%loop%next_progress + 1
      end if
    end associate
  end subroutine sim_accept

  !> The body's state is finite (no NaN or Inf in position, velocity, attitude, rates).
  pure logical function body_is_finite(body) result(ok)
    type(body_t), intent(in) :: body   !! body
    ok = all(ieee_is_finite(body%x)) .and. all(ieee_is_finite(body%v)) .and. &
         all(ieee_is_finite(body%euler)) .and. all(ieee_is_finite(body%omega))
  end function body_is_finite

  !> Ends the run before t_end: the reason, a final sample of the state at t (unless one was just
  !! recorded) with the forces of an evaluation of that state, the summary.
  subroutine end_early(sim, inp, res, t, h_last, reason)
    type(sim_t), intent(in) :: sim              !! simulation at t
    type(landyn_input_t), intent(in) :: inp     !! resolved, validated input
    type(sim_result_t), intent(inout) :: res    !! time series and summary
    real(wp), intent(in) :: t                   !! time [s]
    real(wp), intent(in) :: h_last              !! the step that reached t [s]
    character(len=*), intent(in) :: reason      !! end reason [-]
    type(sim_t) :: work
    type(sim_eval_t) :: ev
    integer :: stat
    character(len=msg_len) :: m2
    res%end_reason = reason
    if (res%n_out > 0) then
      if (res%t(res%n_out) >= t - 1.0e-12_wp) then
        call finish(sim%model, res, t)
        return
      end if
    end if
    ! the sample leads the velocities by half a step in place: on a copy of the final state
    work = sim
    m2 = ''
    call sim_evaluate(sim, inp, t, h_last, ev, stat, m2)
    if (stat == 0) call record_sample(work, inp, res, ev, h_last)
    call finish(sim%model, res, t)
  end subroutine end_early

  !> Snapshot of everything that evolves in a simulation: body, gears (coordinates, rates, crush
  !! modes and history, caches), footpad histories and stick states, and the integrator's
  !! accumulators. Restoring it makes the simulation continue exactly as from the moment it was
  !! taken (bit for bit): the basis of rejected steps and event location.
  subroutine sim_save(sim, snap)
    type(sim_t), intent(in) :: sim              !! simulation
    ! inout, not out: intent(out) would first reset the whole snapshot (max_gears gear states)
    ! to its default values, a cost of the same order as the copy itself, at every step
    type(sim_snapshot_t), intent(inout) :: snap !! its evolving state (previous contents replaced)
    integer :: i
    snap%body = sim%model%body
    do i = 1, sim%model%n_gears
      snap%gear(i) = sim%model%gear(i)%st
    end do
    snap%footpad = sim%model%footpad
    snap%loop = sim%loop
  end subroutine sim_save

  !> Puts a snapshot from sim_save back.
  subroutine sim_restore(sim, snap)
    type(sim_t), intent(inout) :: sim           !! simulation
    type(sim_snapshot_t), intent(in) :: snap    !! snapshot
    integer :: i
    sim%model%body = snap%body
    do i = 1, sim%model%n_gears
      sim%model%gear(i)%st = snap%gear(i)
    end do
    sim%model%footpad = snap%footpad
    sim%loop = snap%loop
  end subroutine sim_restore

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
    do i = 1, model%n_gears
      v(:, i) = gear_load_vector(model%gear(i)%rot, ev%gear(i))
    end do
  end function eval_loads

  !> Crush mode of each strut: 0 locked, +1 crushing toward +s, -1 crushing toward -s (sliding
  !! against a nonzero bound), 2 sliding freely inside the crushed range (no force; its direction
  !! of motion is not a mode).
  pure function strut_modes(locked, axial, dir) result(m)
    logical, intent(in) :: locked(3)          !! struts locked [-]
    real(wp), intent(in) :: axial(3)          !! axial buffer forces [N]
    integer, intent(in) :: dir(3)             !! sliding directions [-]
    integer :: m(3)                           !! modes [-]
    integer :: k
    do k = 1, 3
      if (locked(k)) then
        m(k) = 0
      else if (abs(axial(k)) > tiny(1.0_wp)) then
        m(k) = sign(1, dir(k))
      else
        m(k) = 2
      end if
    end do
  end function strut_modes

  !> Counts the changes of each strut's crush mode (strut_modes), i.e. the switches of the buffer
  !! force law.
  pure subroutine count_mode_switches(m, mode, switches)
    integer, intent(in) :: m(3)               !! modes after the step [-]
    integer, intent(inout) :: mode(3)         !! mode at the previous step, updated [-]
    integer, intent(inout) :: switches(3)     !! mode changes so far [-]
    where (m /= mode) switches = switches + 1
    mode = m
  end subroutine count_mode_switches

  !> Advances the stored velocities of body and gears by `lead` times the accelerations of an
  !! evaluation, keeping the stored ones in `kept` (restore_velocities puts them back). The
  !! semi-implicit Euler step is the leapfrog: its positions belong to t and its stored velocities
  !! to t - h/2, so lead = h/2 with the accelerations at t gives the velocities at t.
  pure subroutine lead_velocities(model, lead, ev, kept)
    type(model_t), intent(inout) :: model       !! model
    real(wp), intent(in) :: lead                !! [s]
    type(sim_eval_t), intent(in) :: ev          !! evaluation with the accelerations
    type(velocities_t), intent(out) :: kept     !! the stored velocities
    integer :: i
    kept%v = model%body%v
    kept%omega = model%body%omega
    model%body%v = kept%v + lead*ev%acc
    model%body%omega = kept%omega + lead*ev%alpha
    do i = 1, model%n_gears
      kept%qd(:, i) = model%gear(i)%st%qd
      model%gear(i)%st%qd = kept%qd(:, i) + lead*ev%gear(i)%qdd
    end do
  end subroutine lead_velocities

  !> Puts back the velocities kept by lead_velocities.
  pure subroutine restore_velocities(model, kept)
    type(model_t), intent(inout) :: model       !! model
    type(velocities_t), intent(in) :: kept      !! the stored velocities
    integer :: i
    model%body%v = kept%v
    model%body%omega = kept%omega
    do i = 1, model%n_gears
      model%gear(i)%st%qd = kept%qd(:, i)
    end do
  end subroutine restore_velocities

  !> Records one output sample.
  subroutine record(res, model, ev, w_normal, w_friction, w_thrust, w_impact, &
                    ke0, pe0, ke_legs, e_el, gravity)
    type(sim_result_t), intent(inout) :: res      !! result
    type(model_t), intent(in) :: model            !! model at ev%t (velocities synchronised)
    type(sim_eval_t), intent(in) :: ev            !! its evaluation (forces, footpads, overload)
    real(wp), intent(in) :: w_normal              !! work into the ground (normal) [J]
    real(wp), intent(in) :: w_friction            !! friction dissipation [J]
    real(wp), intent(in) :: w_thrust              !! thrust work [J]
    real(wp), intent(in) :: w_impact              !! energy dissipated in strut impacts [J]
    real(wp), intent(in) :: ke0                   !! initial kinetic energy [J]
    real(wp), intent(in) :: pe0                   !! initial potential energy [J]
    real(wp), intent(in) :: ke_legs               !! leg relative kinetic energy [J]
    real(wp), intent(in) :: e_el                  !! contact elastic energy [J]
    real(wp), intent(in) :: gravity               !! [m/s^2]
    integer :: k, i
    real(wp) :: s(3), pe, ke, crush, e_in
    if (res%n_out >= size(res%t)) return
    res%n_out = res%n_out + 1
    k = res%n_out
    res%t(k) = ev%t
    res%mc_position(:, k) = model%body%x
    res%position(:, k) = model%body%x - matmul(model%body%r, model%body%mc)
    res%velocity(:, k) = model%body%v
    res%euler(:, k) = model%body%euler*rad2deg
    res%rate(:, k) = model%body%omega*rad2deg
    res%overload(:, k) = ev%ovl
    crush = 0.0_wp
    do i = 1, res%n_gears
      associate (g => model%gear(i))
        res%strut_length(:, i, k) = g%st%q(idx_len)
        s = g%sigma*(g%st%q(idx_len) - g%len0)
        res%stroke(:, i, k) = s
        res%strut_force(:, i, k) = ev%gear(i)%axial
        res%loads(:, i, k) = gear_load_vector(g%rot, ev%gear(i))
        res%interface_force(:, i, k) = matmul(g%rot, ev%gear(i)%f_interface)
        crush = crush + sum(g%st%work_crush)
      end associate
      res%footpad_position(:, i, k) = ev%xd(:, i)
      res%ground_force(:, i, k) = ev%fground(:, i)
      res%normal_force(i, k) = ev%fn(i)
      res%friction_force(i, k) = sqrt(max(0.0_wp, dot_product(ev%fground(:, i), ev%fground(:, i)) - ev%fn(i)**2))
      res%penetration(i, k) = ev%delta(i)
      res%slip_speed(i, k) = norm2(slip_velocity(model%plane(i), ev%vd(:, i)))
    end do
    res%overload_peak(k) = max(res%acc_overload, norm2(ev%ovl))
    res%normal_force_peak(:, k) = max(res%acc_normal_force, ev%fn(1:res%n_gears))
    res%strut_force_peak(:, :, k) = res%acc_strut_force
    res%acc_overload = 0.0_wp
    res%acc_normal_force = 0.0_wp
    res%acc_strut_force = 0.0_wp
    ke = body_kinetic_energy(model%body)
    pe = -model%body%mass*gravity*model%body%x(3)
    e_in = ke0 + (pe0 - pe) + w_thrust
    res%energy(k, 1) = ke
    res%energy(k, 2) = ke_legs
    res%energy(k, 3) = pe0 - pe
    res%energy(k, 4) = crush
    res%energy(k, 5) = w_normal - e_el
    res%energy(k, 6) = e_el
    res%energy(k, 7) = w_friction
    res%energy(k, 8) = w_impact
    res%energy(k, 9) = w_thrust
    res%energy(k, 10) = ke0 + (pe0 - pe) + w_thrust
    res%energy(k, 11) = e_in - (ke + ke_legs + crush + w_normal + w_friction + w_impact)
    res%energy_input = max(ke0 + (pe0 - pe) + w_thrust, tiny(1.0_wp))
    res%energy_residual = res%energy(k, 11)/res%energy_input
  end subroutine record

  !> Fills the summary from the final model state.
  subroutine finish(model, res, t)
    type(model_t), intent(in) :: model         !! model
    type(sim_result_t), intent(inout) :: res   !! result
    real(wp), intent(in) :: t                  !! final time [s]
    integer :: i, k
    real(wp) :: s(3), cap_pos, cap_neg, mpos, mneg
    res%t_final = t
    do i = 1, res%n_gears
      associate (g => model%gear(i))
        s = g%sigma*(g%st%q(idx_len) - g%len0)
        res%stroke_final(:, i) = s
        res%crush_pos(:, i) = g%st%s_hismax
        res%crush_neg(:, i) = 0.0_wp - g%st%s_hismin
        res%crush_net(:, i) = g%st%s_hismax + g%st%s_hismin
        res%crush_work(:, i) = g%st%work_crush
        do k = 1, 3
          call g%buffer(k)%law%capacity(cap_pos, cap_neg)
          mpos = cap_pos - g%st%s_hismax(k)
          mneg = huge(1.0_wp)
          if (cap_neg > 0.0_wp) mneg = cap_neg + g%st%s_hismin(k)
          res%stroke_margin(k, i) = min(mpos, mneg)
          res%bottomed(k, i) = merge(1, 0, res%stroke_margin(k, i) < 0.0_wp)
        end do
        res%max_violation = max(res%max_violation, g%st%max_violation)
        res%max_drift = max(res%max_drift, g%st%max_drift)
      end associate
    end do
    res%final_euler = model%body%euler*rad2deg
    res%final_tilt = acos(max(-1.0_wp, min(1.0_wp, model%body%r(3, 3))))*rad2deg
  end subroutine finish

  !> Allocates the result arrays (once, before the time loop).
  subroutine allocate_result(res, ng, n_cap)
    type(sim_result_t), intent(inout) :: res  !! result
    integer, intent(in) :: ng                 !! number of gears
    integer, intent(in) :: n_cap              !! capacity in samples
    allocate (res%t(n_cap), res%position(3, n_cap), res%mc_position(3, n_cap), res%velocity(3, n_cap), &
              res%euler(3, n_cap), res%rate(3, n_cap), res%overload(3, n_cap))
    allocate (res%strut_length(3, ng, n_cap), res%stroke(3, ng, n_cap), res%strut_force(3, ng, n_cap), &
              res%footpad_position(3, ng, n_cap), res%ground_force(3, ng, n_cap))
    allocate (res%normal_force(ng, n_cap), res%friction_force(ng, n_cap), res%penetration(ng, n_cap), &
              res%slip_speed(ng, n_cap), res%energy(n_cap, n_energy))
    allocate (res%overload_peak(n_cap), res%normal_force_peak(ng, n_cap), res%strut_force_peak(3, ng, n_cap), &
              res%acc_normal_force(ng), res%acc_strut_force(3, ng))
    res%acc_overload = 0.0_wp
    res%acc_normal_force = 0.0_wp
    res%acc_strut_force = 0.0_wp
    allocate (res%crush_net(3, ng), res%crush_pos(3, ng), res%crush_neg(3, ng), res%stroke_final(3, ng), &
              res%stroke_margin(3, ng), res%crush_work(3, ng), res%bottomed(3, ng), res%peak_strut_force(3, ng))
    allocate (res%peak_penetration(ng), res%slide_distance(ng), res%peak_normal_force(ng))
    res%peak_penetration = 0.0_wp
    res%slide_distance = 0.0_wp
    res%peak_normal_force = 0.0_wp
    res%peak_strut_force = 0.0_wp
    allocate (res%mode_switches(3, ng))
    res%mode_switches = 0
    allocate (res%loads(n_load, ng, n_cap), res%interface_force(3, ng, n_cap), res%gear_rot(3, 3, ng))
    res%loads = 0.0_wp                 ! stays zero when the interface loads are not computed
    res%interface_force = 0.0_wp
    call load_peaks_init(res%load_peaks, ng)
    res%n_out = 0
  end subroutine allocate_result

end module landyn_sim_core
