!> The one accessor of the input registry: copies the value of a registry entry between its
!! component of `landyn_input_t` and a storage-class holder (`input_value_t`). Every generic
!! consumer of the registry (reader, writer, range checks, docs) goes through `access_var`.
!! Values are in STORAGE units (angles in radians).
module landyn_input_access
  use landyn_kinds, only: wp
  use landyn_config, only: landyn_input_t
  use landyn_input_registry, only: var_key
  implicit none
  private

  public :: input_value_t, access_var, get_var

  !> The value of one entry: the part matching the entry's storage class is used.
  type :: input_value_t
    real(wp), allocatable :: r(:)          !! real values, column-major [storage unit]
    integer :: i = 0                       !! integer value [-]
    logical :: l = .false.                 !! logical value [-]
    character(len=:), allocatable :: s     !! string value (blank-padded as stored) [-]
  end type input_value_t

  interface move
    module procedure move_real, move_reals, move_real2, move_int, move_logical, move_string
  end interface move

contains

  !> Copy entry iv between inp (store false: inp -> v; store true: v -> inp).
  pure subroutine access_var(inp, iv, v, store)
    type(landyn_input_t), intent(inout) :: inp  !! input [-]
    integer, intent(in) :: iv                   !! registry entry [-]
    type(input_value_t), intent(inout) :: v     !! value holder [storage unit]
    logical, intent(in) :: store                !! .true.: v -> inp; .false.: inp -> v [-]
    select case (var_key(iv))
    case ('simulation%title')
      call move(inp%simulation%title, v, store)
    case ('simulation%integrator')
      call move(inp%simulation%integrator, v, store)
    case ('simulation%dt')
      call move(inp%simulation%dt, v, store)
    case ('simulation%tolerance')
      call move(inp%simulation%tolerance, v, store)
    case ('simulation%dt_max')
      call move(inp%simulation%dt_max, v, store)
    case ('simulation%dt_min')
      call move(inp%simulation%dt_min, v, store)
    case ('simulation%event_resolution')
      call move(inp%simulation%event_resolution, v, store)
    case ('simulation%t_end')
      call move(inp%simulation%t_end, v, store)
    case ('simulation%gravity')
      call move(inp%simulation%gravity, v, store)
    case ('simulation%stop_at_rest')
      call move(inp%simulation%stop_at_rest, v, store)
    case ('simulation%rest_speed')
      call move(inp%simulation%rest_speed, v, store)
    case ('simulation%rest_time')
      call move(inp%simulation%rest_time, v, store)
    case ('simulation%tipover_angle')
      call move(inp%simulation%tipover_angle, v, store)
    case ('simulation%constraint_tol')
      call move(inp%simulation%constraint_tol, v, store)
    case ('simulation%max_correction_iter')
      call move(inp%simulation%max_correction_iter, v, store)
    case ('simulation%max_constraint_drift')
      call move(inp%simulation%max_constraint_drift, v, store)
    case ('lander%mass')
      call move(inp%lander%mass, v, store)
    case ('lander%ixx')
      call move(inp%lander%ixx, v, store)
    case ('lander%iyy')
      call move(inp%lander%iyy, v, store)
    case ('lander%izz')
      call move(inp%lander%izz, v, store)
    case ('lander%ixy')
      call move(inp%lander%ixy, v, store)
    case ('lander%ixz')
      call move(inp%lander%ixz, v, store)
    case ('lander%iyz')
      call move(inp%lander%iyz, v, store)
    case ('lander%mass_centre')
      call move(inp%lander%mass_centre, v, store)
    case ('engine%thrust')
      call move(inp%engine%thrust, v, store)
    case ('engine%direction')
      call move(inp%engine%direction, v, store)
    case ('engine%point')
      call move(inp%engine%point, v, store)
    case ('engine%cutoff_time')
      call move(inp%engine%cutoff_time, v, store)
    case ('gears%n_gears')
      call move(inp%gears%n_gears, v, store)
    case ('gears%rotation')
      call move(inp%gears%rotation, v, store)
    case ('gears%point_a')
      call move(inp%gears%point_a, v, store)
    case ('gears%point_b')
      call move(inp%gears%point_b, v, store)
    case ('gears%point_c')
      call move(inp%gears%point_c, v, store)
    case ('gears%point_d')
      call move(inp%gears%point_d, v, store)
    case ('gears%point_e')
      call move(inp%gears%point_e, v, store)
    case ('gears%point_f')
      call move(inp%gears%point_f, v, store)
    case ('primary_strut%n_stages')
      call move(inp%primary%n_stages, v, store)
    case ('primary_strut%stage_force')
      call move(inp%primary%stage_force, v, store)
    case ('primary_strut%stage_end')
      call move(inp%primary%stage_end, v, store)
    case ('primary_strut%stop_stiffness')
      call move(inp%primary%stop_stiffness, v, store)
    case ('primary_strut%stop_damping')
      call move(inp%primary%stop_damping, v, store)
    case ('primary_strut%outer_mass')
      call move(inp%primary%outer_mass, v, store)
    case ('primary_strut%outer_cm')
      call move(inp%primary%outer_cm, v, store)
    case ('primary_strut%outer_inertia')
      call move(inp%primary%outer_inertia, v, store)
    case ('primary_strut%inner_mass')
      call move(inp%primary%inner_mass, v, store)
    case ('primary_strut%inner_cm')
      call move(inp%primary%inner_cm, v, store)
    case ('primary_strut%inner_inertia')
      call move(inp%primary%inner_inertia, v, store)
    case ('primary_strut%footpad_mass')
      call move(inp%primary%footpad_mass, v, store)
    case ('primary_strut%tube_friction')
      call move(inp%primary%tube_friction, v, store)
    case ('primary_strut%mu_tube')
      call move(inp%primary%mu_tube, v, store)
    case ('primary_strut%tube_outer_length')
      call move(inp%primary%tube_outer_length, v, store)
    case ('primary_strut%tube_inner_length')
      call move(inp%primary%tube_inner_length, v, store)
    case ('primary_strut%tube_leg_length')
      call move(inp%primary%tube_leg_length, v, store)
    case ('primary_strut%tube_lever')
      call move(inp%primary%tube_lever, v, store)
    case ('secondary_strut%force_lengthening')
      call move(inp%secondary%force_lengthening, v, store)
    case ('secondary_strut%force_shortening')
      call move(inp%secondary%force_shortening, v, store)
    case ('secondary_strut%stroke_lengthening')
      call move(inp%secondary%stroke_lengthening, v, store)
    case ('secondary_strut%stroke_shortening')
      call move(inp%secondary%stroke_shortening, v, store)
    case ('secondary_strut%stop_stiffness')
      call move(inp%secondary%stop_stiffness, v, store)
    case ('secondary_strut%stop_damping')
      call move(inp%secondary%stop_damping, v, store)
    case ('secondary_strut%outer_mass')
      call move(inp%secondary%outer_mass, v, store)
    case ('secondary_strut%outer_cm')
      call move(inp%secondary%outer_cm, v, store)
    case ('secondary_strut%outer_inertia')
      call move(inp%secondary%outer_inertia, v, store)
    case ('secondary_strut%inner_mass')
      call move(inp%secondary%inner_mass, v, store)
    case ('secondary_strut%inner_cm')
      call move(inp%secondary%inner_cm, v, store)
    case ('secondary_strut%inner_inertia')
      call move(inp%secondary%inner_inertia, v, store)
    case ('contact%law')
      call move(inp%contact%law, v, store)
    case ('contact%stiffness')
      call move(inp%contact%stiffness, v, store)
    case ('contact%exponent')
      call move(inp%contact%exponent, v, store)
    case ('contact%damping')
      call move(inp%contact%damping, v, store)
    case ('contact%damping_depth')
      call move(inp%contact%damping_depth, v, store)
    case ('contact%damping2')
      call move(inp%contact%damping2, v, store)
    case ('contact%restitution')
      call move(inp%contact%restitution, v, store)
    case ('contact%hc_alpha')
      call move(inp%contact%hc_alpha, v, store)
    case ('contact%min_impact_speed')
      call move(inp%contact%min_impact_speed, v, store)
    case ('contact%soil_stiffness')
      call move(inp%contact%soil_stiffness, v, store)
    case ('contact%soil_exponent')
      call move(inp%contact%soil_exponent, v, store)
    case ('contact%soil_drag')
      call move(inp%contact%soil_drag, v, store)
    case ('contact%soil_unload_stiffness')
      call move(inp%contact%soil_unload_stiffness, v, store)
    case ('friction%law')
      call move(inp%friction%law, v, store)
    case ('friction%mu_static')
      call move(inp%friction%mu_static, v, store)
    case ('friction%mu_dynamic')
      call move(inp%friction%mu_dynamic, v, store)
    case ('friction%v_static')
      call move(inp%friction%v_static, v, store)
    case ('friction%v_dynamic')
      call move(inp%friction%v_dynamic, v, store)
    case ('friction%viscous')
      call move(inp%friction%viscous, v, store)
    case ('friction%stribeck_speed')
      call move(inp%friction%stribeck_speed, v, store)
    case ('friction%stribeck_exponent')
      call move(inp%friction%stribeck_exponent, v, store)
    case ('friction%stribeck_decay')
      call move(inp%friction%stribeck_decay, v, store)
    case ('friction%stick_stiffness')
      call move(inp%friction%stick_stiffness, v, store)
    case ('friction%stick_damping')
      call move(inp%friction%stick_damping, v, store)
    case ('terrain%height')
      call move(inp%terrain%height, v, store)
    case ('terrain%slope')
      call move(inp%terrain%slope, v, store)
    case ('terrain%slope_direction')
      call move(inp%terrain%slope_direction, v, store)
    case ('initial_state%position')
      call move(inp%initial%position, v, store)
    case ('initial_state%clearance')
      call move(inp%initial%clearance, v, store)
    case ('initial_state%velocity')
      call move(inp%initial%velocity, v, store)
    case ('initial_state%attitude')
      call move(inp%initial%attitude, v, store)
    case ('initial_state%angular_rate')
      call move(inp%initial%angular_rate, v, store)
    case ('output%file')
      call move(inp%output%file, v, store)
    case ('output%interval')
      call move(inp%output%interval, v, store)
    case default
      continue   ! every entry has a case (checked by test_input_registry)
    end select
  end subroutine access_var

  !> The value of entry iv of inp.
  pure function get_var(inp, iv) result(v)
    type(landyn_input_t), intent(in) :: inp  !! input [-]
    integer, intent(in) :: iv                !! registry entry [-]
    type(input_value_t) :: v                 !! its value [storage unit]
    type(landyn_input_t) :: work
    work = inp
    call access_var(work, iv, v, .false.)
  end function get_var

  pure subroutine move_real(x, v, store)
    real(wp), intent(inout) :: x             !! component [storage unit]
    type(input_value_t), intent(inout) :: v  !! holder [storage unit]
    logical, intent(in) :: store             !! direction [-]
    if (store) then
      x = v%r(1)
    else
      v%r = [x]
    end if
  end subroutine move_real

  pure subroutine move_reals(x, v, store)
    real(wp), intent(inout) :: x(:)          !! component [storage unit]
    type(input_value_t), intent(inout) :: v  !! holder [storage unit]
    logical, intent(in) :: store             !! direction [-]
    if (store) then
      x = v%r
    else
      v%r = x
    end if
  end subroutine move_reals

  pure subroutine move_real2(x, v, store)
    real(wp), intent(inout) :: x(:, :)       !! component [storage unit]
    type(input_value_t), intent(inout) :: v  !! holder [storage unit]
    logical, intent(in) :: store             !! direction [-]
    if (store) then
      x = reshape(v%r, shape(x))
    else
      v%r = reshape(x, [size(x)])
    end if
  end subroutine move_real2

  pure subroutine move_int(x, v, store)
    integer, intent(inout) :: x              !! component [-]
    type(input_value_t), intent(inout) :: v  !! holder [-]
    logical, intent(in) :: store             !! direction [-]
    if (store) then
      x = v%i
    else
      v%i = x
    end if
  end subroutine move_int

  pure subroutine move_logical(x, v, store)
    logical, intent(inout) :: x              !! component [-]
    type(input_value_t), intent(inout) :: v  !! holder [-]
    logical, intent(in) :: store             !! direction [-]
    if (store) then
      x = v%l
    else
      v%l = x
    end if
  end subroutine move_logical

  pure subroutine move_string(x, v, store)
    character(len=*), intent(inout) :: x     !! component [-]
    type(input_value_t), intent(inout) :: v  !! holder [-]
    logical, intent(in) :: store             !! direction [-]
    if (store) then
      x = v%s
    else
      v%s = x
    end if
  end subroutine move_string

end module landyn_input_access
