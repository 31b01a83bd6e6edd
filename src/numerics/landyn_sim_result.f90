!> The result of one run: the time series (one column per output sample), the summary, the
!! energy audit's channels; their allocation, the recording of a sample and the summary at the end.
module landyn_sim_result
  use landyn_kinds, only: wp, rad2deg, max_struts
  use landyn_body, only: body_kinetic_energy
  use landyn_gear_base, only: strut_name_len
  use landyn_loads, only: n_load, load_peaks_t, gear_load_vector, load_peaks_init
  use landyn_terrain, only: slip_velocity
  use landyn_sim_model, only: model_t, sim_eval_t
  use landyn_rest, only: motion_t
  implicit none
  private

  public :: sim_result_t, allocate_result, record, finish

  integer, parameter :: level_name_len = 24   !! length of a crush level's name [-]
  integer, parameter :: max_levels = 16       !! crush levels asked of one strut [-]

  !> Time series (columns = output samples) and summary of one run. Per-strut arrays have as many
  !! rows as the gear with the most struts (3 for tripods); a gear's rows beyond its own count stay 0.
  type :: sim_result_t
    integer :: n_gears = 0                                 !! number of gears [-]
    integer, allocatable :: n_struts(:)                    !! (n_gears) struts of each gear [-]
    character(len=strut_name_len), allocatable :: strut_names(:, :)  !! (struts, n_gears) their names [-]
    real(wp), allocatable :: stroke_capacity(:, :, :)     !! (2, struts, n_gears) buffer capacity toward +s, -s
                                                           !! (buffer_capacity; 0: none), for /model [m]
    ! every strut's crush levels (crush_levels), one row per level in the order gear, strut, level
    integer, allocatable :: level_gear(:)                  !! (levels) gear of the level, 0-based [-]
    integer, allocatable :: level_strut(:)                 !! (levels) strut of the level, 0-based [-]
    real(wp), allocatable :: level_force(:)                !! (levels) axial force, compression + [N]
    character(len=level_name_len), allocatable :: level_name(:)  !! (levels) what the level is [-]
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
    logical :: tipped_over = .false.                       !! the tilt passed tipover_angle [-]
    logical :: at_rest = .false.                           !! the run ended with the lander at rest [-]
    character(len=64) :: end_reason = ''                   !! why the run ended (end time, at rest, tip-over, ...) [-]
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
    integer :: n_releases = 0                              !! strut releases (locked -> crushing or free) [-]
    integer :: n_releases_after_lock = 0                   !! of those, in the step after a strut locked [-]
    real(wp) :: dt_smallest = 0.0_wp                       !! smallest accepted step [s]
    real(wp) :: dt_largest = 0.0_wp                        !! largest accepted step [s]
    real(wp) :: wall_time = 0.0_wp                         !! [s]
    real(wp) :: initial_position(3) = 0.0_wp               !! O_L at t = 0 [m]
    ! ---- outcome (docs/output.md "Outcome"): the end state from the run (landyn_simulation), the
    ! classification and the stability figures from landyn_outcome
    logical :: touched = .false.                           !! a footpad touched the ground [-]
    type(motion_t) :: end_motion                           !! how fast the lander moved at t_final [m/s, rad/s]
    integer :: outcome = 0                                 !! outcome code (landyn_outcome); 0 not classified [-]
    real(wp) :: tipover_margin = 0.0_wp                    !! tip-over margin at t_final [deg]
    real(wp), allocatable :: friction_ratio(:)             !! (n_gears) |F_t|/(mu_s F_n) at t_final [-]
  end type sim_result_t

  integer, parameter, public :: n_energy = 11   !! terms of the energy audit [-]
  !> Names of the energy audit's terms (the columns of /timeseries/energy).
  character(len=24), parameter, public :: energy_names(n_energy) = [character(len=24) :: &
    'kinetic_body', 'kinetic_legs', 'potential_released', 'honeycomb_work', 'contact_damping', &
    'contact_elastic', 'friction', 'strut_impacts', 'thrust_work', 'input', 'residual']

contains

  !> Allocates the result arrays (once, before the time loop) for the gears of a model.
  subroutine allocate_result(res, model, n_cap)
    type(sim_result_t), intent(inout) :: res  !! result
    type(model_t), intent(in) :: model        !! model with its gears
    integer, intent(in) :: n_cap              !! capacity in samples
    integer :: ng, n_struts, i, k
    ng = model%par%n_gears
    n_struts = maxval(model%par%n_struts(1:ng))
    res%n_gears = ng
    allocate (res%n_struts(ng), res%strut_names(n_struts, ng), res%stroke_capacity(2, n_struts, ng))
    res%n_struts = model%par%n_struts(1:ng)
    res%strut_names = ''
    res%stroke_capacity = 0.0_wp
    do i = 1, ng
      do k = 1, res%n_struts(i)
        res%strut_names(k, i) = model%gear(i)%g%strut_name(k)
        call model%gear(i)%g%buffer_capacity(k, res%stroke_capacity(1, k, i), res%stroke_capacity(2, k, i))
      end do
    end do
    call keep_crush_levels(res, model)
    allocate (res%t(n_cap), res%position(3, n_cap), res%mc_position(3, n_cap), res%velocity(3, n_cap), &
              res%euler(3, n_cap), res%rate(3, n_cap), res%overload(3, n_cap))
    allocate (res%strut_length(n_struts, ng, n_cap), res%stroke(n_struts, ng, n_cap), res%strut_force(n_struts, ng, n_cap), &
              res%footpad_position(3, ng, n_cap), res%ground_force(3, ng, n_cap))
    allocate (res%normal_force(ng, n_cap), res%friction_force(ng, n_cap), res%penetration(ng, n_cap), &
              res%slip_speed(ng, n_cap), res%energy(n_cap, n_energy))
    allocate (res%overload_peak(n_cap), res%normal_force_peak(ng, n_cap), res%strut_force_peak(n_struts, ng, n_cap), &
              res%acc_normal_force(ng), res%acc_strut_force(n_struts, ng))
    res%acc_overload = 0.0_wp
    res%acc_normal_force = 0.0_wp
    res%acc_strut_force = 0.0_wp
    allocate (res%crush_net(n_struts, ng), res%crush_pos(n_struts, ng), res%crush_neg(n_struts, ng), &
              res%stroke_final(n_struts, ng), res%stroke_margin(n_struts, ng), res%crush_work(n_struts, ng), &
              res%bottomed(n_struts, ng), res%peak_strut_force(n_struts, ng))
    allocate (res%peak_penetration(ng), res%slide_distance(ng), res%peak_normal_force(ng))
    res%peak_penetration = 0.0_wp
    res%slide_distance = 0.0_wp
    res%peak_normal_force = 0.0_wp
    res%peak_strut_force = 0.0_wp
    allocate (res%mode_switches(n_struts, ng))
    res%mode_switches = 0
    allocate (res%loads(n_load, ng, n_cap), res%interface_force(3, ng, n_cap), res%gear_rot(3, 3, ng))
    res%loads = 0.0_wp                 ! stays zero when the interface loads are not computed
    res%interface_force = 0.0_wp
    res%strut_length = 0.0_wp          ! the rows beyond a gear's strut count stay zero
    res%stroke = 0.0_wp
    res%strut_force = 0.0_wp
    res%strut_force_peak = 0.0_wp
    res%crush_net = 0.0_wp
    res%crush_pos = 0.0_wp
    res%crush_neg = 0.0_wp
    res%stroke_final = 0.0_wp
    res%stroke_margin = 0.0_wp
    res%crush_work = 0.0_wp
    res%bottomed = 0
    call load_peaks_init(res%load_peaks, ng)
    res%gear_rot = model%par%rot(:, :, 1:ng)
    res%n_out = 0
  end subroutine allocate_result

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
    integer :: k, i, ns
    real(wp) :: s(max_struts), sd(max_struts), w(max_struts), rot(3, 3), pe, ke, crush, e_in
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
      ns = model%par%n_struts(i)
      associate (g => model%gear(i)%g)
        rot = model%par%rot(:, :, i)
        call g%strut_lengths(s(1:ns))
        res%strut_length(1:ns, i, k) = s(1:ns)
        call g%strokes(s(1:ns), sd(1:ns))
        res%stroke(1:ns, i, k) = s(1:ns)
        res%strut_force(1:ns, i, k) = ev%gear(i)%axial(1:ns)
        res%loads(:, i, k) = gear_load_vector(rot, ev%gear(i))
        res%interface_force(:, i, k) = matmul(rot, ev%gear(i)%f_interface)
        call g%crush_work(w(1:ns))
        crush = crush + sum(w(1:ns))
      end associate
      res%footpad_position(:, i, k) = ev%xd(:, i)
      res%ground_force(:, i, k) = ev%fground(:, i)
      res%normal_force(i, k) = ev%fn(i)
      res%friction_force(i, k) = sqrt(max(0.0_wp, dot_product(ev%fground(:, i), ev%fground(:, i)) - ev%fn(i)**2))
      res%penetration(i, k) = ev%delta(i)
      res%slip_speed(i, k) = norm2(slip_velocity(model%par%plane(i), ev%vd(:, i)))
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
    ! relative to the input, or to the energies moved when the input is (nearly) nothing: a lander
    ! pushed up by its initial penetration has a negative input (issue 25: residual Infinity)
    res%energy_residual = res%energy(k, 11)/max(res%energy_input, 1.0e-3_wp*(ke + ke_legs + abs(crush) + &
                          abs(w_normal) + abs(w_friction) + abs(w_impact)))
  end subroutine record

  !> Fills the summary from the final model state.
  subroutine finish(model, res, t)
    type(model_t), intent(in) :: model         !! model
    type(sim_result_t), intent(inout) :: res   !! result
    real(wp), intent(in) :: t                  !! final time [s]
    integer :: i, k, ns
    real(wp) :: s(max_struts), sd(max_struts), s_min(max_struts), s_max(max_struts), cap_pos, cap_neg, mpos, mneg, viol, drift
    res%t_final = t
    do i = 1, res%n_gears
      ns = model%par%n_struts(i)
      associate (g => model%gear(i)%g)
        call g%strokes(s(1:ns), sd(1:ns))
        call g%crush_history(s_min(1:ns), s_max(1:ns))
        res%stroke_final(1:ns, i) = s(1:ns)
        res%crush_pos(1:ns, i) = s_max(1:ns)
        res%crush_neg(1:ns, i) = 0.0_wp - s_min(1:ns)
        res%crush_net(1:ns, i) = s_max(1:ns) + s_min(1:ns)
        call g%crush_work(s(1:ns))
        res%crush_work(1:ns, i) = s(1:ns)
        do k = 1, ns
          call g%buffer_capacity(k, cap_pos, cap_neg)
          mpos = cap_pos - s_max(k)
          mneg = huge(1.0_wp)
          if (cap_neg > 0.0_wp) mneg = cap_neg + s_min(k)
          res%stroke_margin(k, i) = min(mpos, mneg)
          res%bottomed(k, i) = merge(1, 0, res%stroke_margin(k, i) < 0.0_wp)
        end do
        call g%violations(viol, drift)
        res%max_violation = max(res%max_violation, viol)
        res%max_drift = max(res%max_drift, drift)
      end associate
    end do
    res%final_euler = model%body%euler*rad2deg
    res%final_tilt = acos(max(-1.0_wp, min(1.0_wp, model%body%r(3, 3))))*rad2deg
  end subroutine finish

  !> Keeps every strut's crush levels (the gear's crush_levels, from its buffer laws) in the result,
  !! for /model/crush_levels: one row per level, in the order gear, strut, level.
  subroutine keep_crush_levels(res, model)
    type(sim_result_t), intent(inout) :: res  !! result (n_struts set) [-]
    type(model_t), intent(in) :: model        !! model with its gears [-]
    real(wp) :: force(max_levels)
    character(len=level_name_len) :: name(max_levels)
    integer :: i, k, n, m
    allocate (res%level_gear(0), res%level_strut(0), res%level_force(0), res%level_name(0))
    m = 0
    do i = 1, res%n_gears
      do k = 1, res%n_struts(i)
        call model%gear(i)%g%crush_levels(k, force, name, n)
        n = min(n, max_levels)
        res%level_gear = [res%level_gear(1:m), spread(i - 1, 1, n)]
        res%level_strut = [res%level_strut(1:m), spread(k - 1, 1, n)]
        res%level_force = [res%level_force(1:m), force(1:n)]
        res%level_name = [character(len=level_name_len) :: res%level_name(1:m), name(1:n)]
        m = m + n
      end do
    end do
  end subroutine keep_crush_levels

end module landyn_sim_result
