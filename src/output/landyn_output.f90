!> Writes a run's result file following the schema of docs/output.md, declared once in
!! landyn_output_schema: every dataset goes through schema_write, which writes it in the units the
!! schema declares and refuses one the schema does not declare with this kind and rank.
!! The file is written under a temporary name (<file>.partial) and renamed only when complete,
!! so a run that fails or is killed leaves nothing that looks like a result.
module landyn_output
  use landyn_kinds, only: wp, rad2deg
  use landyn_config, only: landyn_input_t
  use landyn_strings, only: nonempty
  use landyn_provenance, only: write_meta
  use landyn_input, only: resolved_input_text
  use landyn_simulation, only: sim_result_t, n_energy, energy_names
  use landyn_health, only: health_t, check_names, n_checks
  use landyn_outcome, only: outcome_name
  use landyn_h5, only: h5_file_t, h5_create_partial, h5_commit_partial, h5_write_attr
  use landyn_output_schema, only: schema_version => result_schema_version
  use landyn_schema_write, only: schema_write
  use landyn_output_model, only: write_model_group
  use landyn_loads, only: n_load, n_joint, n_quantity, load_names, joint_names, quantity_names
  implicit none
  private

  public :: write_result_file, schema_version

contains

  !> Writes the result file `path` (via `path`.partial and a rename).
  !! With `health`, the run-health checks go to /summary/health (docs/output.md). A run driven
  !! through the C API (landyn_session) names itself in `program` and gives the engine inputs it
  !! applied (/api/inputs).
  subroutine write_result_file(path, inp, res, command_line, stat, errmsg, health, program, input_time, &
                               input_force, input_moment)
    character(len=*), intent(in) :: path           !! result file name
    type(landyn_input_t), intent(in) :: inp        !! resolved input
    type(sim_result_t), intent(in) :: res          !! results
    character(len=*), intent(in) :: command_line   !! the command that ran LANDYN
    integer, intent(out) :: stat                   !! 0 on success
    character(len=*), intent(inout) :: errmsg      !! message on failure
    type(health_t), intent(in), optional :: health !! run-health checks [-]
    character(len=*), intent(in), optional :: program  !! producer's program name (default: the landyn program) [-]
    real(wp), intent(in), optional :: input_time(:)       !! (m) times the engine inputs were set [s]
    real(wp), intent(in), optional :: input_force(:, :)   !! (3, m) input force from then on, lander axes [N]
    real(wp), intent(in), optional :: input_moment(:, :)  !! (3, m) input moment from then on, lander axes [N m]
    type(h5_file_t) :: f

    call h5_create_partial(f, path, stat, errmsg)
    if (stat /= 0) return
    if (present(program)) then
      call write_all(f, inp, res, command_line, stat, errmsg, program)
    else
      call write_all(f, inp, res, command_line, stat, errmsg, '')
    end if
    if (stat == 0 .and. present(health)) call write_health_group(f, health, stat, errmsg)
    if (stat == 0 .and. present(input_time) .and. present(input_force) .and. present(input_moment)) &
      call write_api_inputs(f, input_time, input_force, input_moment, stat, errmsg)
    call h5_commit_partial(f, path, stat, errmsg)
  end subroutine write_result_file

  !> /api/inputs: the engine inputs a caller of the C API applied, each from its time on.
  subroutine write_api_inputs(f, t, force, moment, stat, errmsg)
    type(h5_file_t), intent(inout) :: f            !! open file
    real(wp), intent(in) :: t(:)                   !! (m) times the inputs were set [s]
    real(wp), intent(in) :: force(:, :)            !! (3, m) force at the &engine point, lander axes [N]
    real(wp), intent(in) :: moment(:, :)           !! (3, m) pure moment, lander axes [N m]
    integer, intent(out) :: stat                   !! 0 on success
    character(len=*), intent(inout) :: errmsg      !! message on failure
    call schema_write(f, '/api/inputs/time', t, stat, errmsg)
    if (stat /= 0) return
    call schema_write(f, '/api/inputs/force', force, stat, errmsg)
    if (stat /= 0) return
    call schema_write(f, '/api/inputs/moment', moment, stat, errmsg)
  end subroutine write_api_inputs

  !> Root attributes, /meta (write_meta and the run's deck), /model, /timeseries and /summary of a run.
  subroutine write_all(f, inp, res, command_line, stat, errmsg, program)
    type(h5_file_t), intent(inout) :: f            !! open file [-]
    type(landyn_input_t), intent(in) :: inp        !! resolved input [-]
    type(sim_result_t), intent(in) :: res          !! results [-]
    character(len=*), intent(in) :: command_line   !! command line [-]
    integer, intent(out) :: stat                   !! 0 on success [-]
    character(len=*), intent(inout) :: errmsg      !! message [-]
    character(len=*), intent(in) :: program        !! producer's program name, blank for landyn [-]

    call write_root_and_meta(f, inp, command_line, stat, errmsg, program)
    if (stat /= 0) return
    call write_model_group(f, inp, res, stat, errmsg)
    if (stat /= 0) return
    call write_timeseries(f, res, stat, errmsg)
    if (stat /= 0) return
    call write_summary_crush(f, res, stat, errmsg)
    if (stat /= 0) return
    call write_summary_peaks(f, res, stat, errmsg)
    if (stat /= 0) return
    call write_summary_integration(f, res, stat, errmsg)
    if (stat /= 0) return
    call write_outcome_group(f, res, stat, errmsg)
  end subroutine write_all

  !> Root attributes (title, schema version) and /meta: provenance (write_meta) and the run's deck.
  subroutine write_root_and_meta(f, inp, command_line, stat, errmsg, program)
    type(h5_file_t), intent(inout) :: f            !! open file [-]
    type(landyn_input_t), intent(in) :: inp        !! resolved input [-]
    character(len=*), intent(in) :: command_line   !! command line [-]
    integer, intent(out) :: stat                   !! 0 on success [-]
    character(len=*), intent(inout) :: errmsg      !! message [-]
    character(len=*), intent(in) :: program        !! producer's program name, blank for landyn [-]
    call h5_write_attr(f, '/', 'title', trim(inp%simulation%title), stat, errmsg); if (stat /= 0) return
    call h5_write_attr(f, '/', 'schema_version', schema_version, stat, errmsg); if (stat /= 0) return
    call write_meta(f, program, command_line, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/meta/deck_name', nonempty(inp%deck_name, '(built-in default)'), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/meta/deck_text', nonempty(inp%deck_text, '(none: built-in default input)'), stat, errmsg)
    if (stat /= 0) return
    call schema_write(f, '/meta/resolved_input', resolved_input_text(inp), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/meta/units', 'SI (m, kg, s, N, J); angles in deg; overload in g = 9.80665 m/s^2; '// &
                      'global frame z down', stat, errmsg)
    if (stat /= 0) return
  end subroutine write_root_and_meta

  !> /timeseries: the body's and the gears' histories, the energy audit's terms, the interface loads.
  subroutine write_timeseries(f, res, stat, errmsg)
    type(h5_file_t), intent(inout) :: f            !! open file [-]
    type(sim_result_t), intent(in) :: res          !! results [-]
    integer, intent(out) :: stat                   !! 0 on success [-]
    character(len=*), intent(inout) :: errmsg      !! message [-]
    integer :: n, k
    n = res%n_out
    call schema_write(f, '/timeseries/time', res%t(1:n), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/timeseries/body/position', res%position(:, 1:n), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/timeseries/body/mass_centre_position', res%mc_position(:, 1:n), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/timeseries/body/velocity', res%velocity(:, 1:n), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/timeseries/body/euler_angles', res%euler(:, 1:n), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/timeseries/body/angular_rate', res%rate(:, 1:n), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/timeseries/body/overload', res%overload(:, 1:n), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/timeseries/body/overload_peak', res%overload_peak(1:n), stat, errmsg)
    if (stat /= 0) return
    call schema_write(f, '/timeseries/gears/strut_length', res%strut_length(:, :, 1:n), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/timeseries/gears/stroke', res%stroke(:, :, 1:n), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/timeseries/gears/strut_force', res%strut_force(:, :, 1:n), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/timeseries/gears/strut_force_peak', res%strut_force_peak(:, :, 1:n), stat, errmsg)
    if (stat /= 0) return
    call schema_write(f, '/timeseries/gears/footpad_position', res%footpad_position(:, :, 1:n), stat, errmsg)
    if (stat /= 0) return
    call schema_write(f, '/timeseries/gears/ground_force', res%ground_force(:, :, 1:n), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/timeseries/gears/normal_force', res%normal_force(:, 1:n), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/timeseries/gears/normal_force_peak', res%normal_force_peak(:, 1:n), stat, errmsg)
    if (stat /= 0) return
    call schema_write(f, '/timeseries/gears/friction_force', res%friction_force(:, 1:n), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/timeseries/gears/penetration', res%penetration(:, 1:n), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/timeseries/gears/slip_speed', res%slip_speed(:, 1:n), stat, errmsg); if (stat /= 0) return
    do k = 1, n_energy
      call schema_write(f, '/timeseries/energy/'//trim(energy_names(k)), res%energy(1:n, k), stat, errmsg)
      if (stat /= 0) return
    end do
    call write_interface_loads(f, res, stat, errmsg)
    if (stat /= 0) return
  end subroutine write_timeseries

  !> /summary: the struts' crush, strokes and crush-mode changes.
  subroutine write_summary_crush(f, res, stat, errmsg)
    type(h5_file_t), intent(inout) :: f            !! open file [-]
    type(sim_result_t), intent(in) :: res          !! results [-]
    integer, intent(out) :: stat                   !! 0 on success [-]
    character(len=*), intent(inout) :: errmsg      !! message [-]
    call schema_write(f, '/summary/crush_length', res%crush_net, stat, errmsg)
    if (stat /= 0) return
    call schema_write(f, '/summary/crushed_positive', res%crush_pos, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/crushed_negative', res%crush_neg, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/stroke_final', res%stroke_final, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/stroke_margin', res%stroke_margin, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/bottomed_out', res%bottomed, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/crush_work', res%crush_work, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/mode_switches', res%mode_switches, stat, errmsg)
    if (stat /= 0) return
  end subroutine write_summary_crush

  !> /summary: peaks, the final state, the end reason and the energy audit.
  subroutine write_summary_peaks(f, res, stat, errmsg)
    type(h5_file_t), intent(inout) :: f            !! open file [-]
    type(sim_result_t), intent(in) :: res          !! results [-]
    integer, intent(out) :: stat                   !! 0 on success [-]
    character(len=*), intent(inout) :: errmsg      !! message [-]
    integer :: n, k
    n = res%n_out
    call schema_write(f, '/summary/peak_strut_force', res%peak_strut_force, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/peak_overload', res%peak_overload, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/time_of_peak_overload', res%t_peak_overload, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/peak_penetration', res%peak_penetration, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/slide_distance', res%slide_distance, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/peak_normal_force', res%peak_normal_force, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/final_attitude', res%final_euler, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/final_tilt', res%final_tilt, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/max_tilt', res%max_tilt, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/tipped_over', res%tipped_over, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/at_rest', res%at_rest, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/end_reason', trim(res%end_reason), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/energy_input', res%energy_input, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/energy_residual', res%energy_residual, stat, errmsg); if (stat /= 0) return
    do k = 1, n_energy
      call schema_write(f, '/summary/energy_audit/'//trim(energy_names(k)), res%energy(n, k), stat, errmsg)
      if (stat /= 0) return
    end do
  end subroutine write_summary_peaks

  !> /summary: constraint violations, time, steps, /summary/integrator and the wall time.
  subroutine write_summary_integration(f, res, stat, errmsg)
    type(h5_file_t), intent(inout) :: f            !! open file [-]
    type(sim_result_t), intent(in) :: res          !! results [-]
    integer, intent(out) :: stat                   !! 0 on success [-]
    character(len=*), intent(inout) :: errmsg      !! message [-]
    call schema_write(f, '/summary/max_constraint_violation', res%max_violation, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/max_constraint_drift', res%max_drift, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/final_time', res%t_final, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/n_steps', res%n_steps, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/integrator/name', trim(res%integrator), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/integrator/n_evaluations', res%n_evaluations, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/integrator/n_rejected', res%n_rejected, stat, errmsg)
    if (stat /= 0) return
    call schema_write(f, '/summary/integrator/n_events', res%n_events, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/integrator/n_forced', res%n_forced, stat, errmsg)
    if (stat /= 0) return
    call schema_write(f, '/summary/integrator/n_releases', res%n_releases, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/integrator/n_releases_after_lock', res%n_releases_after_lock, stat, errmsg)
    if (stat /= 0) return
    call schema_write(f, '/summary/integrator/dt_smallest', res%dt_smallest, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/integrator/dt_largest', res%dt_largest, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/wall_time', res%wall_time, stat, errmsg); if (stat /= 0) return
  end subroutine write_summary_integration

  !> The outcome under /summary/outcome (docs/output.md, "Outcome"; landyn_outcome).
  subroutine write_outcome_group(f, res, stat, errmsg)
    type(h5_file_t), intent(inout) :: f            !! open file
    type(sim_result_t), intent(in) :: res          !! classified results
    integer, intent(out) :: stat                   !! 0 on success
    character(len=*), intent(inout) :: errmsg      !! message
    real(wp), allocatable :: ratio(:)
    call schema_write(f, '/summary/outcome/code', res%outcome, stat, errmsg)
    if (stat /= 0) return
    call schema_write(f, '/summary/outcome/name', outcome_name(res%outcome), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/outcome/touched_down', res%touched, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/outcome/body_speed', res%end_motion%body_speed, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/outcome/angular_rate', res%end_motion%angular_rate*rad2deg, stat, errmsg)
    if (stat /= 0) return
    call schema_write(f, '/summary/outcome/slide_rate', res%end_motion%slide_rate, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/outcome/footpad_speed', res%end_motion%footpad_speed, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/outcome/stroke_rate', res%end_motion%stroke_rate, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/outcome/tipover_margin', res%tipover_margin, stat, errmsg); if (stat /= 0) return
    allocate (ratio(res%n_gears))
    ratio = 0.0_wp
    if (allocated(res%friction_ratio)) ratio = res%friction_ratio
    call schema_write(f, '/summary/outcome/friction_ratio', ratio, stat, errmsg)
  end subroutine write_outcome_group

  !> Interface loads (docs/output.md, "Interface loads"): per joint histories in lander axes and in
  !! each gear's axes, the gear's total force on the body, and the peak-load table.
  subroutine write_interface_loads(f, res, stat, errmsg)
    type(h5_file_t), intent(inout) :: f            !! open file
    type(sim_result_t), intent(in) :: res          !! results
    integer, intent(out) :: stat                   !! 0 on success
    character(len=*), intent(inout) :: errmsg      !! message
    real(wp), allocatable :: v(:, :, :), vg(:, :, :), sim2(:, :, :)
    integer :: n, ng, j, i, k, c0
    character(len=20) :: name
    character(len=20), parameter :: block_names(7) = [character(len=20) :: 'joint_force_a', 'joint_force_b', &
      'joint_force_c', 'footpad_joint_force', 'joint_moment_a', 'joint_moment_b', 'joint_moment_c']
    n = res%n_out
    ng = res%n_gears
    allocate (v(3, ng, n), vg(3, ng, n))
    do j = 1, 7
      ! load-vector blocks: 1-3 forces of a, b, c; 4 footpad force at d; 5-7 moments of a, b, c
      c0 = 3*(j - 1)
      v = res%loads(c0 + 1:c0 + 3, 1:ng, 1:n)
      do k = 1, n
        do i = 1, ng
          vg(:, i, k) = matmul(transpose(res%gear_rot(:, :, i)), v(:, i, k))
        end do
      end do
      name = block_names(j)
      call schema_write(f, '/timeseries/gears/'//trim(name), v, stat, errmsg)
      if (stat /= 0) return
      call schema_write(f, '/timeseries/gears/gear_axes/'//trim(name), vg, stat, errmsg)
      if (stat /= 0) return
    end do
    call schema_write(f, '/timeseries/gears/interface_force', res%interface_force(:, :, 1:n), stat, errmsg)
    if (stat /= 0) return
    call schema_write(f, '/summary/peak_joint_load/value', res%load_peaks%value, stat, errmsg)
    if (stat /= 0) return
    call schema_write(f, '/summary/peak_joint_load/time', res%load_peaks%time, stat, errmsg); if (stat /= 0) return
    allocate (sim2(n_load, n_quantity*n_joint, ng))
    sim2 = reshape(res%load_peaks%simultaneous, [n_load, n_quantity*n_joint, ng])
    call schema_write(f, '/summary/peak_joint_load/simultaneous', sim2, stat, errmsg)
    if (stat /= 0) return
    call schema_write(f, '/summary/peak_joint_load/load_names', load_names, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/peak_joint_load/joint_names', joint_names, stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/peak_joint_load/quantity_names', quantity_names, stat, errmsg)
  end subroutine write_interface_loads

  !> The run-health checks under /summary/health (docs/health.md).
  subroutine write_health_group(f, h, stat, errmsg)
    type(h5_file_t), intent(inout) :: f            !! open file
    type(health_t), intent(in) :: h                !! run-health checks
    integer, intent(out) :: stat                   !! 0 on success
    character(len=*), intent(inout) :: errmsg      !! message
    character(len=:), allocatable :: m
    call schema_write(f, '/summary/health/status', h%status(), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/health/checks', check_names(1:n_checks), stat, errmsg); if (stat /= 0) return
    call schema_write(f, '/summary/health/results', h%result, stat, errmsg); if (stat /= 0) return
    m = 'none'
    if (allocated(h%messages)) then
      if (len(h%messages) > 0) m = h%messages
    end if
    call schema_write(f, '/summary/health/messages', m, stat, errmsg)
  end subroutine write_health_group

end module landyn_output
