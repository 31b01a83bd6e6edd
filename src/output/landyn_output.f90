!> Writes a run's result file following the schema of docs/output.md, declared once in
!! landyn_output_schema: every dataset goes through schema_write, which writes it in the units the
!! schema declares and refuses one the schema does not declare with this kind and rank.
!! The file is written under a temporary name (<file>.partial) and renamed only when complete,
!! so a run that fails or is killed leaves nothing that looks like a result.
module landyn_output
  use landyn_status, only: status_t
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
  subroutine write_result_file(path, inp, res, command_line, status, health, program, input_time, &
                               input_force, input_moment)
    character(len=*), intent(in) :: path           !! result file name
    type(landyn_input_t), intent(in) :: inp        !! resolved input
    type(sim_result_t), intent(in) :: res          !! results
    character(len=*), intent(in) :: command_line   !! the command that ran LANDYN
    type(status_t), intent(out) :: status          !! STAT_OK, or the failure with its message [-]
    type(health_t), intent(in), optional :: health !! run-health checks [-]
    character(len=*), intent(in), optional :: program  !! producer's program name (default: the landyn program) [-]
    real(wp), intent(in), optional :: input_time(:)       !! (m) times the engine inputs were set [s]
    real(wp), intent(in), optional :: input_force(:, :)   !! (3, m) input force from then on, lander axes [N]
    real(wp), intent(in), optional :: input_moment(:, :)  !! (3, m) input moment from then on, lander axes [N m]
    type(h5_file_t) :: f

    call h5_create_partial(f, path, status)
    if (.not. status%ok()) return
    if (present(program)) then
      call write_all(f, inp, res, command_line, status, program)
    else
      call write_all(f, inp, res, command_line, status, '')
    end if
    if (status%ok() .and. present(health)) call write_health_group(f, health, status)
    if (status%ok() .and. present(input_time) .and. present(input_force) .and. present(input_moment)) &
      call write_api_inputs(f, input_time, input_force, input_moment, status)
    call h5_commit_partial(f, path, status)
  end subroutine write_result_file

  !> /api/inputs: the engine inputs a caller of the C API applied, each from its time on.
  subroutine write_api_inputs(f, t, force, moment, status)
    type(h5_file_t), intent(inout) :: f            !! open file
    real(wp), intent(in) :: t(:)                   !! (m) times the inputs were set [s]
    real(wp), intent(in) :: force(:, :)            !! (3, m) force at the &engine point, lander axes [N]
    real(wp), intent(in) :: moment(:, :)           !! (3, m) pure moment, lander axes [N m]
    type(status_t), intent(out) :: status          !! STAT_OK, or the failure with its message [-]
    call schema_write(f, '/api/inputs/time', t, status)
    if (.not. status%ok()) return
    call schema_write(f, '/api/inputs/force', force, status)
    if (.not. status%ok()) return
    call schema_write(f, '/api/inputs/moment', moment, status)
  end subroutine write_api_inputs

  !> Root attributes, /meta (write_meta and the run's deck), /model, /timeseries and /summary of a run.
  subroutine write_all(f, inp, res, command_line, status, program)
    type(h5_file_t), intent(inout) :: f            !! open file [-]
    type(landyn_input_t), intent(in) :: inp        !! resolved input [-]
    type(sim_result_t), intent(in) :: res          !! results [-]
    character(len=*), intent(in) :: command_line   !! command line [-]
    type(status_t), intent(out) :: status          !! STAT_OK, or the failure with its message [-]
    character(len=*), intent(in) :: program        !! producer's program name, blank for landyn [-]

    call write_root_and_meta(f, inp, command_line, status, program)
    if (.not. status%ok()) return
    call write_model_group(f, inp, res, status)
    if (.not. status%ok()) return
    call write_timeseries(f, res, status)
    if (.not. status%ok()) return
    call write_summary_crush(f, res, status)
    if (.not. status%ok()) return
    call write_summary_peaks(f, res, status)
    if (.not. status%ok()) return
    call write_summary_integration(f, res, status)
    if (.not. status%ok()) return
    call write_outcome_group(f, res, status)
  end subroutine write_all

  !> Root attributes (title, schema version) and /meta: provenance (write_meta) and the run's deck.
  subroutine write_root_and_meta(f, inp, command_line, status, program)
    type(h5_file_t), intent(inout) :: f            !! open file [-]
    type(landyn_input_t), intent(in) :: inp        !! resolved input [-]
    character(len=*), intent(in) :: command_line   !! command line [-]
    type(status_t), intent(out) :: status          !! STAT_OK, or the failure with its message [-]
    character(len=*), intent(in) :: program        !! producer's program name, blank for landyn [-]
    call h5_write_attr(f, '/', 'title', trim(inp%simulation%title), status); if (.not. status%ok()) return
    call h5_write_attr(f, '/', 'schema_version', schema_version, status); if (.not. status%ok()) return
    call write_meta(f, program, command_line, status); if (.not. status%ok()) return
    call schema_write(f, '/meta/deck_name', nonempty(inp%deck_name, '(built-in default)'), status); if (.not. status%ok()) return
    call schema_write(f, '/meta/deck_text', nonempty(inp%deck_text, '(none: built-in default input)'), status)
    if (.not. status%ok()) return
    call schema_write(f, '/meta/resolved_input', resolved_input_text(inp), status); if (.not. status%ok()) return
    call schema_write(f, '/meta/units', 'SI (m, kg, s, N, J); angles in deg; overload in g = 9.80665 m/s^2; '// &
                      'global frame z down', status)
    if (.not. status%ok()) return
  end subroutine write_root_and_meta

  !> /timeseries: the body's and the gears' histories, the energy audit's terms, the interface loads.
  subroutine write_timeseries(f, res, status)
    type(h5_file_t), intent(inout) :: f            !! open file [-]
    type(sim_result_t), intent(in) :: res          !! results [-]
    type(status_t), intent(out) :: status          !! STAT_OK, or the failure with its message [-]
    integer :: n, k
    n = res%n_out
    call schema_write(f, '/timeseries/time', res%t(1:n), status); if (.not. status%ok()) return
    call schema_write(f, '/timeseries/body/position', res%position(:, 1:n), status); if (.not. status%ok()) return
    call schema_write(f, '/timeseries/body/mass_centre_position', res%mc_position(:, 1:n), status); if (.not. status%ok()) return
    call schema_write(f, '/timeseries/body/velocity', res%velocity(:, 1:n), status); if (.not. status%ok()) return
    call schema_write(f, '/timeseries/body/euler_angles', res%euler(:, 1:n), status); if (.not. status%ok()) return
    call schema_write(f, '/timeseries/body/angular_rate', res%rate(:, 1:n), status); if (.not. status%ok()) return
    call schema_write(f, '/timeseries/body/overload', res%overload(:, 1:n), status); if (.not. status%ok()) return
    call schema_write(f, '/timeseries/body/overload_peak', res%overload_peak(1:n), status)
    if (.not. status%ok()) return
    call schema_write(f, '/timeseries/gears/strut_length', res%strut_length(:, :, 1:n), status); if (.not. status%ok()) return
    call schema_write(f, '/timeseries/gears/stroke', res%stroke(:, :, 1:n), status); if (.not. status%ok()) return
    call schema_write(f, '/timeseries/gears/strut_force', res%strut_force(:, :, 1:n), status); if (.not. status%ok()) return
    call schema_write(f, '/timeseries/gears/strut_force_peak', res%strut_force_peak(:, :, 1:n), status)
    if (.not. status%ok()) return
    call schema_write(f, '/timeseries/gears/footpad_position', res%footpad_position(:, :, 1:n), status)
    if (.not. status%ok()) return
    call schema_write(f, '/timeseries/gears/ground_force', res%ground_force(:, :, 1:n), status); if (.not. status%ok()) return
    call schema_write(f, '/timeseries/gears/normal_force', res%normal_force(:, 1:n), status); if (.not. status%ok()) return
    call schema_write(f, '/timeseries/gears/normal_force_peak', res%normal_force_peak(:, 1:n), status)
    if (.not. status%ok()) return
    call schema_write(f, '/timeseries/gears/friction_force', res%friction_force(:, 1:n), status); if (.not. status%ok()) return
    call schema_write(f, '/timeseries/gears/penetration', res%penetration(:, 1:n), status); if (.not. status%ok()) return
    call schema_write(f, '/timeseries/gears/slip_speed', res%slip_speed(:, 1:n), status); if (.not. status%ok()) return
    do k = 1, n_energy
      call schema_write(f, '/timeseries/energy/'//trim(energy_names(k)), res%energy(1:n, k), status)
      if (.not. status%ok()) return
    end do
    call write_interface_loads(f, res, status)
    if (.not. status%ok()) return
  end subroutine write_timeseries

  !> /summary: the struts' crush, strokes and crush-mode changes.
  subroutine write_summary_crush(f, res, status)
    type(h5_file_t), intent(inout) :: f            !! open file [-]
    type(sim_result_t), intent(in) :: res          !! results [-]
    type(status_t), intent(out) :: status          !! STAT_OK, or the failure with its message [-]
    call schema_write(f, '/summary/crush_length', res%crush_net, status)
    if (.not. status%ok()) return
    call schema_write(f, '/summary/crushed_positive', res%crush_pos, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/crushed_negative', res%crush_neg, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/stroke_final', res%stroke_final, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/stroke_margin', res%stroke_margin, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/bottomed_out', res%bottomed, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/crush_work', res%crush_work, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/mode_switches', res%mode_switches, status)
    if (.not. status%ok()) return
  end subroutine write_summary_crush

  !> /summary: peaks, the final state, the end reason and the energy audit.
  subroutine write_summary_peaks(f, res, status)
    type(h5_file_t), intent(inout) :: f            !! open file [-]
    type(sim_result_t), intent(in) :: res          !! results [-]
    type(status_t), intent(out) :: status          !! STAT_OK, or the failure with its message [-]
    integer :: n, k
    n = res%n_out
    call schema_write(f, '/summary/peak_strut_force', res%peak_strut_force, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/peak_overload', res%peak_overload, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/time_of_peak_overload', res%t_peak_overload, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/peak_penetration', res%peak_penetration, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/slide_distance', res%slide_distance, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/peak_normal_force', res%peak_normal_force, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/final_attitude', res%final_euler, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/final_tilt', res%final_tilt, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/max_tilt', res%max_tilt, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/tipped_over', res%tipped_over, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/at_rest', res%at_rest, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/end_reason', trim(res%end_reason), status); if (.not. status%ok()) return
    call schema_write(f, '/summary/energy_input', res%energy_input, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/energy_residual', res%energy_residual, status); if (.not. status%ok()) return
    do k = 1, n_energy
      call schema_write(f, '/summary/energy_audit/'//trim(energy_names(k)), res%energy(n, k), status)
      if (.not. status%ok()) return
    end do
  end subroutine write_summary_peaks

  !> /summary: constraint violations, time, steps, /summary/integrator and the wall time.
  subroutine write_summary_integration(f, res, status)
    type(h5_file_t), intent(inout) :: f            !! open file [-]
    type(sim_result_t), intent(in) :: res          !! results [-]
    type(status_t), intent(out) :: status          !! STAT_OK, or the failure with its message [-]
    call schema_write(f, '/summary/max_constraint_violation', res%max_violation, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/max_constraint_drift', res%max_drift, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/final_time', res%t_final, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/n_steps', res%n_steps, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/integrator/name', trim(res%integrator), status); if (.not. status%ok()) return
    call schema_write(f, '/summary/integrator/n_evaluations', res%n_evaluations, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/integrator/n_rejected', res%n_rejected, status)
    if (.not. status%ok()) return
    call schema_write(f, '/summary/integrator/n_events', res%n_events, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/integrator/n_forced', res%n_forced, status)
    if (.not. status%ok()) return
    call schema_write(f, '/summary/integrator/n_releases', res%n_releases, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/integrator/n_releases_after_lock', res%n_releases_after_lock, status)
    if (.not. status%ok()) return
    call schema_write(f, '/summary/integrator/dt_smallest', res%dt_smallest, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/integrator/dt_largest', res%dt_largest, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/wall_time', res%wall_time, status); if (.not. status%ok()) return
  end subroutine write_summary_integration

  !> The outcome under /summary/outcome (docs/output.md, "Outcome"; landyn_outcome).
  subroutine write_outcome_group(f, res, status)
    type(h5_file_t), intent(inout) :: f            !! open file
    type(sim_result_t), intent(in) :: res          !! classified results
    type(status_t), intent(out) :: status          !! STAT_OK, or the failure with its message [-]
    real(wp), allocatable :: ratio(:)
    call schema_write(f, '/summary/outcome/code', res%outcome, status)
    if (.not. status%ok()) return
    call schema_write(f, '/summary/outcome/name', outcome_name(res%outcome), status); if (.not. status%ok()) return
    call schema_write(f, '/summary/outcome/touched_down', res%touched, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/outcome/body_speed', res%end_motion%body_speed, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/outcome/angular_rate', res%end_motion%angular_rate*rad2deg, status)
    if (.not. status%ok()) return
    call schema_write(f, '/summary/outcome/slide_rate', res%end_motion%slide_rate, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/outcome/footpad_speed', res%end_motion%footpad_speed, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/outcome/stroke_rate', res%end_motion%stroke_rate, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/outcome/tipover_margin', res%tipover_margin, status); if (.not. status%ok()) return
    allocate (ratio(res%n_gears))
    ratio = 0.0_wp
    if (allocated(res%friction_ratio)) ratio = res%friction_ratio
    call schema_write(f, '/summary/outcome/friction_ratio', ratio, status)
  end subroutine write_outcome_group

  !> Interface loads (docs/output.md, "Interface loads"): per joint histories in lander axes and in
  !! each gear's axes, the gear's total force on the body, and the peak-load table.
  subroutine write_interface_loads(f, res, status)
    type(h5_file_t), intent(inout) :: f            !! open file
    type(sim_result_t), intent(in) :: res          !! results
    type(status_t), intent(out) :: status          !! STAT_OK, or the failure with its message [-]
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
      call schema_write(f, '/timeseries/gears/'//trim(name), v, status)
      if (.not. status%ok()) return
      call schema_write(f, '/timeseries/gears/gear_axes/'//trim(name), vg, status)
      if (.not. status%ok()) return
    end do
    call schema_write(f, '/timeseries/gears/interface_force', res%interface_force(:, :, 1:n), status)
    if (.not. status%ok()) return
    call schema_write(f, '/summary/peak_joint_load/value', res%load_peaks%value, status)
    if (.not. status%ok()) return
    call schema_write(f, '/summary/peak_joint_load/time', res%load_peaks%time, status); if (.not. status%ok()) return
    allocate (sim2(n_load, n_quantity*n_joint, ng))
    sim2 = reshape(res%load_peaks%simultaneous, [n_load, n_quantity*n_joint, ng])
    call schema_write(f, '/summary/peak_joint_load/simultaneous', sim2, status)
    if (.not. status%ok()) return
    call schema_write(f, '/summary/peak_joint_load/load_names', load_names, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/peak_joint_load/joint_names', joint_names, status); if (.not. status%ok()) return
    call schema_write(f, '/summary/peak_joint_load/quantity_names', quantity_names, status)
  end subroutine write_interface_loads

  !> The run-health checks under /summary/health (docs/health.md).
  subroutine write_health_group(f, h, status)
    type(h5_file_t), intent(inout) :: f            !! open file
    type(health_t), intent(in) :: h                !! run-health checks
    type(status_t), intent(out) :: status          !! STAT_OK, or the failure with its message [-]
    character(len=:), allocatable :: m
    call schema_write(f, '/summary/health/status', h%status(), status); if (.not. status%ok()) return
    call schema_write(f, '/summary/health/checks', check_names(1:n_checks), status); if (.not. status%ok()) return
    call schema_write(f, '/summary/health/results', h%result, status); if (.not. status%ok()) return
    m = 'none'
    if (allocated(h%messages)) then
      if (len(h%messages) > 0) m = h%messages
    end if
    call schema_write(f, '/summary/health/messages', m, status)
  end subroutine write_health_group

end module landyn_output
