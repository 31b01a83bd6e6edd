!> The /model group of a result file (docs/output.md, "/model"): what a reader needs to draw and
!! judge the run without the deck, from the same code the simulation used: the gear and strut
!! counts and names, each gear's frame, every strut's joints and nominal frame (build_gear_geometry,
!! as the model is assembled), the buffers' stroke capacities (buffer_capacity, kept in the result
!! at allocation), the primary honeycomb's stage ends, every strut's crush levels (its buffer law's
!! crush_levels, through the gear's binding, kept in the result at allocation as the capacities
!! are: a new law reports its own), the mass centre, the mass, gravity, the friction coefficients,
!! the terrain planes and the touchdown state.
module landyn_output_model
  use landyn_kinds, only: wp, rad2deg
  use landyn_status, only: status_t, STAT_OK
  use landyn_strings, only: int_text
  use landyn_config, only: landyn_input_t
  use landyn_kinematics, only: rot_z, build_gear_geometry, gear_geometry_t
  use landyn_simulation, only: sim_result_t
  use landyn_h5, only: h5_file_t
  use landyn_schema_write, only: schema_write
  implicit none
  private

  public :: write_model_group

  integer, parameter :: tripod_struts = 3     !! struts of the gear the input describes [-]

contains

  !> Writes /model for the run `res` of the resolved input `inp`.
  subroutine write_model_group(f, inp, res, status)
    type(h5_file_t), intent(inout) :: f            !! open file [-]
    type(landyn_input_t), intent(in) :: inp        !! resolved input [-]
    type(sim_result_t), intent(in) :: res          !! results (gear and strut counts, capacities) [-]
    type(status_t), intent(out) :: status          !! STAT_OK, or the failure with its message [-]
    integer :: ng, ns, i, k, j
    real(wp), allocatable :: cap(:, :, :)
    character(len=len(res%strut_names)), allocatable :: names(:)

    ng = res%n_gears
    ns = size(res%strut_names, 1)
    allocate (names(ns), cap(2, ns, ng))
    names = ''
    do k = 1, ns                                   ! the name of strut row k: from a gear that has it
      do i = ng, 1, -1
        if (res%n_struts(i) >= k) names(k) = res%strut_names(k, i)
      end do
    end do
    cap = 0.0_wp
    if (allocated(res%stroke_capacity)) cap = res%stroke_capacity
    call schema_write(f, '/model/n_gears', ng, status); if (.not. status%ok()) return
    call schema_write(f, '/model/n_struts', res%n_struts, status); if (.not. status%ok()) return
    call schema_write(f, '/model/strut_names', names, status); if (.not. status%ok()) return
    call schema_write(f, '/model/mass_centre', inp%lander%mass_centre, status); if (.not. status%ok()) return
    call schema_write(f, '/model/gear_axes', res%gear_rot, status); if (.not. status%ok()) return
    call write_joints(f, inp, ng, ns, status); if (.not. status%ok()) return
    call schema_write(f, '/model/stroke_capacity', cap, status); if (.not. status%ok()) return
    j = max(0, min(inp%primary%n_stages, size(inp%primary%stage_end)))
    call schema_write(f, '/model/primary_stage_end', inp%primary%stage_end(1:j), status)
    if (.not. status%ok()) return
    call schema_write(f, '/model/terrain/height', inp%terrain%height(1:ng), status); if (.not. status%ok()) return
    call schema_write(f, '/model/terrain/slope', inp%terrain%slope(1:ng)*rad2deg, status)
    if (.not. status%ok()) return
    call schema_write(f, '/model/terrain/slope_direction', inp%terrain%slope_direction(1:ng)*rad2deg, &
status)
    if (.not. status%ok()) return
    call write_crush_levels(f, res, status); if (.not. status%ok()) return
    call write_conditions(f, inp, status)
  end subroutine write_model_group

  !> /model/crush_levels: the table of every strut's crush levels, as the result keeps them
  !! (gear_base_t%crush_levels of the run's own gears, at allocation), in the order gear, strut,
  !! level.
  subroutine write_crush_levels(f, res, status)
    type(h5_file_t), intent(inout) :: f            !! open file [-]
    type(sim_result_t), intent(in) :: res          !! results (the crush levels) [-]
    type(status_t), intent(out) :: status          !! STAT_OK, or the failure with its message [-]
    call schema_write(f, '/model/crush_levels/gear', res%level_gear, status); if (.not. status%ok()) return
    call schema_write(f, '/model/crush_levels/strut', res%level_strut, status); if (.not. status%ok()) return
    call schema_write(f, '/model/crush_levels/force', res%level_force, status); if (.not. status%ok()) return
    call schema_write(f, '/model/crush_levels/name', res%level_name, status)
  end subroutine write_crush_levels

  !> The run's conditions: mass, gravity, friction coefficients and the touchdown state.
  subroutine write_conditions(f, inp, status)
    type(h5_file_t), intent(inout) :: f            !! open file [-]
    type(landyn_input_t), intent(in) :: inp        !! resolved input [-]
    type(status_t), intent(out) :: status          !! STAT_OK, or the failure with its message [-]
    call schema_write(f, '/model/mass', inp%lander%mass, status); if (.not. status%ok()) return
    call schema_write(f, '/model/gravity', inp%simulation%gravity, status); if (.not. status%ok()) return
    call schema_write(f, '/model/friction/mu_static', inp%friction%mu_static, status); if (.not. status%ok()) return
    call schema_write(f, '/model/friction/mu_dynamic', inp%friction%mu_dynamic, status); if (.not. status%ok()) return
    call schema_write(f, '/model/touchdown/velocity', inp%initial%velocity, status); if (.not. status%ok()) return
    call schema_write(f, '/model/touchdown/attitude', inp%initial%attitude*rad2deg, status)
    if (.not. status%ok()) return
    call schema_write(f, '/model/touchdown/angular_rate', inp%initial%angular_rate*rad2deg, status)
    if (.not. status%ok()) return
    call schema_write(f, '/model/touchdown/clearance', inp%initial%clearance, status)
  end subroutine write_conditions

  !> /model/upper_joint, lower_joint and strut_frame: the tripods' hard points and the struts'
  !! nominal frames (build_gear_geometry in the gear frame, as setup_model builds the gears).
  subroutine write_joints(f, inp, ng, ns, status)
    type(h5_file_t), intent(inout) :: f            !! open file [-]
    type(landyn_input_t), intent(in) :: inp        !! resolved input [-]
    integer, intent(in) :: ng                      !! gears [-]
    integer, intent(in) :: ns                      !! strut rows [-]
    type(status_t), intent(out) :: status          !! STAT_OK, or the failure with its message [-]
    real(wp), allocatable :: upper(:, :, :), lower(:, :, :), frame(:, :, :, :)
    real(wp) :: rot(3, 3), pts(3, 6), r0(3, 3, 3)
    type(gear_geometry_t) :: geom
    character(len=1), parameter :: axis_names(3) = ['x', 'y', 'z']
    integer :: i, k, n3

    allocate (upper(3, ns, ng), lower(3, ns, ng), frame(3, ns, ng, 3))
    upper = 0.0_wp
    lower = 0.0_wp
    frame = 0.0_wp
    n3 = min(ns, tripod_struts)
    do i = 1, ng
      pts(:, 1) = inp%gears%point_a(:, i)
      pts(:, 2) = inp%gears%point_b(:, i)
      pts(:, 3) = inp%gears%point_c(:, i)
      pts(:, 4) = inp%gears%point_d(:, i)
      pts(:, 5) = inp%gears%point_e(:, i)
      pts(:, 6) = inp%gears%point_f(:, i)
      upper(:, 1:n3, i) = pts(:, 1:n3)
      lower(:, 1:n3, i) = pts(:, 4:3 + n3)
      rot = rot_z(inp%gears%rotation(i))
      pts = matmul(transpose(rot), pts)            ! lander frame -> gear frame
      call build_gear_geometry(pts(:, 1), pts(:, 2), pts(:, 3), pts(:, 4), pts(:, 5), pts(:, 6), geom, status)
      if (status%code /= STAT_OK) then
        call status%prefix('/model: gear '//int_text(i)//': ')
        return
      end if
      r0(:, :, 1) = matmul(rot, geom%R0p)          ! gear frame -> lander axes
      r0(:, :, 2) = matmul(rot, geom%R0b)
      r0(:, :, 3) = matmul(rot, geom%R0c)
      do k = 1, n3
        frame(:, k, i, :) = r0(:, :, k)
      end do
    end do
    call schema_write(f, '/model/upper_joint', upper, status); if (.not. status%ok()) return
    call schema_write(f, '/model/lower_joint', lower, status); if (.not. status%ok()) return
    do k = 1, 3
      call schema_write(f, '/model/strut_frame/'//axis_names(k), frame(:, :, :, k), status)
      if (.not. status%ok()) return
    end do
  end subroutine write_joints

end module landyn_output_model
