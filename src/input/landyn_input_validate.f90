!> Validation of a resolved input, in one path (`validate_input`): the generic checks of the
!! registry (the valid range or list of choices of each variable), then the hand-written checks
!! that relate several variables (step counts, stage order, inertia plausibility, hard points)
!! and the law-dependent checks of &contact and &friction (`validate_laws`). Each problem is
!! appended to the error collector as `<deck>: &<group>: <var> = <value> is invalid; valid: <range>`.
!!
!! Library code: nothing here stops or prints.
module landyn_input_validate
  use landyn_kinds, only: wp, max_gears
  use landyn_errors, only: input_errors_t
  use landyn_contact, only: check_contact_law_input
  use landyn_friction, only: check_friction_law_input
  use landyn_buffer_laws, only: check_buffer_law_input
  use landyn_gear_types, only: check_gear_type_input
  use landyn_input_choices, only: choice_list
  use landyn_kinematics, only: det3
  use landyn_config, only: landyn_input_t, simulation_cfg_t, lander_cfg_t, gears_cfg_t, primary_cfg_t, &
                           secondary_cfg_t, terrain_cfg_t, initial_cfg_t, output_cfg_t, is_set, max_stages
  use landyn_strings, only: lower => lower_case, fmt_int => int_text, quoted => quote_text
  use landyn_input_registry, only: input_var_t, input_vars, group_names, range_text, k_int, k_string
  use landyn_input_access, only: input_value_t, access_var
  use landyn_input_format, only: fmt_real, fmt_angle, fmt_reals, deg_to_rad, msg_prefix
  implicit none
  private

  public :: validate_input

  ! Bounds of docs/input that relate variables (the single-variable ranges are in the registry)
  real(wp), parameter :: max_steps = 1.0e9_wp          !! most time steps of a run, t_end/dt [-]
  real(wp), parameter :: max_samples = 1.0e6_wp        !! most stored output samples, t_end/interval [-]
  real(wp), parameter :: max_t_end = 3600.0_wp         !! longest simulated time [s]
  real(wp), parameter :: min_body_inertia = 1.0e-3_wp  !! smallest principal moment of inertia [kg m^2] (registry: ixx >= 0.001)
  real(wp), parameter :: max_hard_point = 100.0_wp     !! largest |coordinate| of a gear hard point [m]
  real(wp), parameter :: coincide_tol = 1.0e-6_wp      !! hard points closer than this coincide [m]
  real(wp), parameter :: min_node_mass = 1.0e-6_wp     !! lightest strut node (footpad, secondary lower part) [kg]: lighter
                                                       !! ones (5e-324) overflow the mass-matrix scaling

contains

  !> Check a resolved input for physically invalid values. Each problem is appended to `errors`
  !! naming the group, the variable, its value (in deck units: angles in degrees) and the valid range.
  subroutine validate_input(inp, errors)
    type(landyn_input_t), intent(in) :: inp        !! resolved input
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    character(len=:), allocatable :: pre
    pre = msg_prefix(inp)
    call check_registry_ranges(inp, pre, errors)
    call validate_simulation(inp%simulation, inp%output, pre, errors)
    call validate_lander(inp%lander, pre, errors)
    call validate_gears(inp%gears, pre, errors)
    call validate_primary(inp%primary, pre, errors)
    call validate_secondary(inp%secondary, pre, errors)
    call validate_laws(inp, pre, errors)
    call validate_terrain_initial(inp%terrain, inp%initial, inp%gears%n_gears, pre, errors)
  end subroutine validate_input

  !> The checks that depend on a registry's choice: the law-dependent checks of &contact and
  !! &friction (those that depend on the law name or compare two variables of those groups), of the
  !! struts' buffer laws and of the gear type: the registries' checks, the same code their factories
  !! run, so a deck is accepted exactly when its laws and gears can be built.
  subroutine validate_laws(inp, pre, errors)
    type(landyn_input_t), intent(in) :: inp        !! resolved input
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    call check_contact_law_input(inp%contact, pre, errors)
    call check_friction_law_input(inp%friction, pre, errors)
    call check_buffer_law_input(inp%primary, inp%secondary, pre, errors)
    call check_gear_type_input(inp, pre, errors)
  end subroutine validate_laws

  !> The generic checks of the registry: each scalar with a range (real values that are set),
  !! each string with a list of choices.
  subroutine check_registry_ranges(inp, pre, errors)
    type(landyn_input_t), intent(in) :: inp        !! resolved input
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    type(landyn_input_t) :: work
    type(input_value_t) :: v
    type(input_var_t) :: e
    character(len=:), allocatable :: list, value, unit
    real(wp) :: x
    integer :: iv
    logical :: ok
    work = inp
    do iv = 1, size(input_vars)
      e = input_vars(iv)
      if (len_trim(e%choices) == 0 .and. len_trim(e%lo_op) == 0) cycle
      call access_var(work, iv, v, .false.)
      if (e%kind == k_string) then
        list = choice_list(e%choices)
        call require(errors, in_name_list(v%s, list), pre, trim(group_names(e%group)), trim(e%name), &
                     quoted(trim(v%s)), 'one of '//quoted_list(list))
        cycle
      end if
      unit = ''
      if (e%msg_unit > 0 .and. len_trim(e%unit) > 0 .and. e%unit /= '-') unit = ' '//trim(e%unit)
      if (e%kind == k_int) then
        x = real(v%i, wp)
        value = fmt_int(v%i)
      else
        x = v%r(1)
        if (.not. is_set(x)) cycle
        value = real_text(x, e%angle)//unit
      end if
      ok = holds(x, e%lo_op, bound(e%lo, e%angle)) .and. holds(x, e%hi_op, bound(e%hi, e%angle))
      call require(errors, ok, pre, trim(group_names(e%group)), trim(e%name), value, range_text(iv, .true.))
    end do
  contains
    !> x in deck units (degrees for angles).
    pure function real_text(y, angle) result(t)
      real(wp), intent(in) :: y             !! value [storage unit]
      logical, intent(in) :: angle          !! y is an angle [-]
      character(len=:), allocatable :: t    !! text [deck unit]
      if (angle) then
        t = fmt_angle(y)
      else
        t = fmt_real(y)
      end if
    end function real_text
    !> A bound text as a value in storage units (0 when blank).
    pure function bound(text, angle) result(b)
      character(len=*), intent(in) :: text  !! bound as written [deck unit]
      logical, intent(in) :: angle          !! degrees in the deck [-]
      real(wp) :: b                         !! bound [storage unit]
      b = 0.0_wp
      if (len_trim(text) > 0) read (text, *) b
      if (angle) b = deg_to_rad(b)
    end function bound
    !> x op b ('' holds always).
    pure logical function holds(x, op, b)
      real(wp), intent(in) :: x, b          !! value and bound [storage unit]
      character(len=*), intent(in) :: op    !! '>', '>=', '<', '<=' or '' [-]
      select case (trim(op))
      case ('>')
        holds = x > b
      case ('>=')
        holds = x >= b
      case ('<')
        holds = x < b
      case ('<=')
        holds = x <= b
      case default
        holds = .true.
      end select
    end function holds
  end subroutine check_registry_ranges

  !> Cross-variable checks of &simulation (and its relation to &output).
  subroutine validate_simulation(s, o, pre, errors)
    type(simulation_cfg_t), intent(in) :: s        !! &simulation
    type(output_cfg_t), intent(in) :: o            !! &output
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    character(len=*), parameter :: g = 'simulation'
    call require(errors, s%t_end <= max_t_end, pre, g, 't_end', fmt_real(s%t_end)//' s', &
                 't_end <= '//fmt_real(max_t_end)//' s')
    if (s%dt > 0.0_wp .and. s%t_end > 0.0_wp) then
      call require(errors, s%dt <= s%t_end, pre, g, 'dt', fmt_real(s%dt)//' s', &
                   'dt <= t_end = '//fmt_real(s%t_end)//' s')
      ! t_end/dt is compared as dt >= t_end/max_steps: no overflow for any finite dt
      call require(errors, s%dt >= s%t_end/max_steps, pre, g, 'dt', fmt_real(s%dt)//' s', &
                   'dt >= t_end/'//fmt_real(max_steps)//' = '//fmt_real(s%t_end/max_steps)// &
                   ' s (at most '//fmt_real(max_steps)//' time steps)')
    end if
    call require(errors, s%dt_max >= s%dt_min, pre, g, 'dt_max', fmt_real(s%dt_max)//' s', &
                 'dt_max >= dt_min = '//fmt_real(s%dt_min)//' s')
    if (s%event_resolution > 0.0_wp .and. s%dt_min > 0.0_wp .and. s%dt_max >= s%dt_min) then
      call require(errors, s%event_resolution >= s%dt_min .and. s%event_resolution <= s%dt_max, pre, g, &
                   'event_resolution', fmt_real(s%event_resolution)//' s', 'dt_min <= event_resolution <= dt_max, here '// &
                   fmt_real(s%dt_min)//' s .. '//fmt_real(s%dt_max)//' s')
      ! the adaptive steps are no shorter than event_resolution (but for failed corrections): this
      ! bounds their number as dt bounds the fixed scheme's
      if (s%t_end > 0.0_wp) call require(errors, s%event_resolution >= s%t_end/max_steps, pre, g, 'event_resolution', &
                   fmt_real(s%event_resolution)//' s', 'event_resolution >= t_end/'//fmt_real(max_steps)//' = '// &
                   fmt_real(s%t_end/max_steps)//' s (at most '//fmt_real(max_steps)//' time steps)')
    end if
    if (s%dt > 0.0_wp .and. s%t_end > 0.0_wp) then
      call require(errors, o%interval >= s%dt .and. o%interval <= s%t_end, pre, 'output', 'interval', &
                   fmt_real(o%interval)//' s', 'dt <= interval <= t_end, here '//fmt_real(s%dt)//' s .. '// &
                   fmt_real(s%t_end)//' s')
      if (o%interval > 0.0_wp) &
        call require(errors, o%interval >= s%t_end/max_samples, pre, 'output', 'interval', &
                     fmt_real(o%interval)//' s', 'interval >= t_end/'//fmt_real(max_samples)//' = '// &
                     fmt_real(s%t_end/max_samples)//' s (at most '//fmt_real(max_samples)//' stored samples)')
    else
      call require(errors, o%interval > 0.0_wp, pre, 'output', 'interval', fmt_real(o%interval)//' s', &
                   'dt <= interval <= t_end')
    end if
    call require(errors, len_trim(o%file) > 0, pre, 'output', 'file', "''", 'a non-empty file name')
  end subroutine validate_simulation

  !> Checks of &lander: a physical inertia tensor (positive definite, triangle inequalities).
  subroutine validate_lander(l, pre, errors)
    type(lander_cfg_t), intent(in) :: l            !! &lander
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    character(len=*), parameter :: u = ' kg m^2'
    real(wp) :: t(3, 3), m1, m2, m3
    logical :: positive_diagonal
    positive_diagonal = l%ixx >= min_body_inertia .and. l%iyy >= min_body_inertia .and. l%izz >= min_body_inertia
    if (.not. positive_diagonal) return
    t = reshape([l%ixx, -l%ixy, -l%ixz, -l%ixy, l%iyy, -l%iyz, -l%ixz, -l%iyz, l%izz], [3, 3])
    m1 = t(1, 1)
    m2 = t(1, 1)*t(2, 2) - t(1, 2)*t(2, 1)
    m3 = det3(t)
    if (.not. (m1 > 0.0_wp .and. m2 > 0.0_wp .and. m3 > 0.0_wp)) then
      call errors%add(pre//'&lander: the inertia tensor [[ixx, -ixy, -ixz], [-ixy, iyy, -iyz], [-ixz, -iyz, izz]]'// &
                      ' is not positive definite (ixx = '//fmt_real(l%ixx)//', iyy = '//fmt_real(l%iyy)// &
                      ', izz = '//fmt_real(l%izz)//', ixy = '//fmt_real(l%ixy)//', ixz = '//fmt_real(l%ixz)// &
                      ', iyz = '//fmt_real(l%iyz)//u//'); valid: a positive definite tensor '// &
                      '(products of inertia small enough against the moments)')
    end if
    call triangle(l%ixx, l%iyy, l%izz, 'ixx + iyy', 'izz')
    call triangle(l%iyy, l%izz, l%ixx, 'iyy + izz', 'ixx')
    call triangle(l%izz, l%ixx, l%iyy, 'izz + ixx', 'iyy')
  contains
    !> Reports a + b < c, a violated triangle inequality of principal moments.
    subroutine triangle(a, b, c, sum_name, c_name)
      real(wp), intent(in) :: a, b, c                   !! moments of inertia [kg m^2]
      character(len=*), intent(in) :: sum_name, c_name  !! names for the message [-]
      if (a + b < c*(1.0_wp - 1.0e-12_wp)) &
        call errors%add(pre//'&lander: '//sum_name//' = '//fmt_real(a + b)//' < '//c_name//' = '//fmt_real(c)//u// &
                        ' violates the triangle inequality of moments of inertia; valid: '//sum_name//' >= '//c_name)
    end subroutine triangle
  end subroutine validate_lander

  !> Checks of the resolved &gears: rotation(1) = 0, hard points in range and distinct.
  subroutine validate_gears(g, pre, errors)
    type(gears_cfg_t), intent(in) :: g             !! &gears (resolved)
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    real(wp) :: pts(3, 6)
    character(len=1), parameter :: letters(6) = ['a', 'b', 'c', 'd', 'e', 'f']
    integer :: i, j, k
    if (g%n_gears < 1 .or. g%n_gears > max_gears) return
    if (is_set(g%rotation(1))) &
      call require(errors, .not. (abs(g%rotation(1)) > 0.0_wp), pre, 'gears', 'rotation(1)', &
                   fmt_angle(g%rotation(1))//' deg', 'rotation(1) = 0 deg (rotations are measured from gear 1)')
    do i = 1, g%n_gears
      pts = reshape([g%point_a(:, i), g%point_b(:, i), g%point_c(:, i), g%point_d(:, i), g%point_e(:, i), &
                     g%point_f(:, i)], [3, 6])
      if (.not. all(is_set(pts))) cycle   ! reported by resolve_input
      if (any(abs(pts) > max_hard_point)) then
        do j = 1, 6
          if (any(abs(pts(:, j)) > max_hard_point)) &
            call errors%add(pre//'&gears: point_'//letters(j)//'(:, '//fmt_int(i)//') = ('//fmt_reals(pts(:, j))// &
                            ') m is out of range; valid: every coordinate within +-'//fmt_real(max_hard_point)//' m')
        end do
        cycle
      end if
      do j = 1, 5
        do k = j + 1, 6
          if (norm2(pts(:, j) - pts(:, k)) < coincide_tol) &
            call errors%add(pre//'&gears: point_'//letters(j)//'(:, '//fmt_int(i)//') and point_'//letters(k)// &
                            '(:, '//fmt_int(i)//') coincide at ('//fmt_reals(pts(:, j))//') m; valid: distinct '// &
                            'hard points (more than 1e-6 m apart)')
        end do
      end do
    end do
  end subroutine validate_gears

  !> Checks of &primary_strut: the honeycomb stages and the tube geometry.
  subroutine validate_primary(p, pre, errors)
    type(primary_cfg_t), intent(in) :: p           !! &primary_strut
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    character(len=*), parameter :: g = 'primary_strut'
    if (p%n_stages >= 1 .and. p%n_stages <= max_stages) call check_stages()
    if (p%footpad_mass >= 0.0_wp .and. p%inner_mass >= 0.0_wp) &
      call require(errors, p%footpad_mass + p%inner_mass >= min_node_mass, pre, g, 'footpad_mass + inner_mass', &
                   fmt_real(p%footpad_mass + p%inner_mass)//' kg', 'footpad_mass + inner_mass >= '// &
                   fmt_real(min_node_mass)//' kg (the footpad node needs mass)')
    if (p%tube_outer_length > 0.0_wp .and. p%tube_inner_length > 0.0_wp .and. p%tube_leg_length > 0.0_wp) &
      call require(errors, p%tube_outer_length + p%tube_inner_length > p%tube_leg_length, pre, g, &
                   'tube_leg_length', fmt_real(p%tube_leg_length)//' m', 'tube_leg_length < tube_outer_length + '// &
                   'tube_inner_length = '//fmt_real(p%tube_outer_length + p%tube_inner_length)//' m (the tubes overlap)')
  contains
    !> Stage forces positive and non-decreasing, stage ends positive and increasing.
    subroutine check_stages()
      integer :: i
      character(len=:), allocatable :: si
      do i = 1, p%n_stages
        si = '('//fmt_int(i)//')'
        call require(errors, p%stage_force(i) > 0.0_wp, pre, g, 'stage_force'//si, fmt_real(p%stage_force(i))//' N', &
                     'stage_force'//si//' > 0 N')
        call require(errors, p%stage_end(i) > 0.0_wp, pre, g, 'stage_end'//si, fmt_real(p%stage_end(i))//' m', &
                     'stage_end'//si//' > 0 m')
      end do
      do i = 2, p%n_stages
        si = '('//fmt_int(i)//')'
        call require(errors, p%stage_force(i) >= p%stage_force(i - 1), pre, g, 'stage_force'//si, &
                     fmt_real(p%stage_force(i))//' N', 'stage_force'//si//' >= stage_force('//fmt_int(i - 1)// &
                     ') = '//fmt_real(p%stage_force(i - 1))//' N (non-decreasing)')
        call require(errors, p%stage_end(i) > p%stage_end(i - 1), pre, g, 'stage_end'//si, &
                     fmt_real(p%stage_end(i))//' m', 'stage_end'//si//' > stage_end('//fmt_int(i - 1)// &
                     ') = '//fmt_real(p%stage_end(i - 1))//' m (strictly increasing)')
      end do
    end subroutine check_stages
  end subroutine validate_primary

  !> Checks of &secondary_strut that involve more than one variable.
  subroutine validate_secondary(s, pre, errors)
    type(secondary_cfg_t), intent(in) :: s         !! &secondary_strut
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    character(len=*), parameter :: g = 'secondary_strut'
    if (s%inner_mass >= 0.0_wp) &
      call require(errors, s%inner_mass >= min_node_mass, pre, g, 'inner_mass', fmt_real(s%inner_mass)//' kg', &
                   'inner_mass >= '//fmt_real(min_node_mass)//' kg (the sliding lower part of a secondary strut '// &
                   'needs mass)')
  end subroutine validate_secondary

  !> Checks of &terrain and &initial_state against the number of gears.
  subroutine validate_terrain_initial(t, s, n_gears, pre, errors)
    type(terrain_cfg_t), intent(in) :: t           !! &terrain
    type(initial_cfg_t), intent(in) :: s           !! &initial_state
    integer, intent(in) :: n_gears                 !! number of gears (footpads) [-]
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    integer :: i
    character(len=:), allocatable :: si
    do i = 1, min(max(n_gears, 0), max_gears)
      si = '('//fmt_int(i)//')'
      call require(errors, t%slope(i) >= 0.0_wp .and. t%slope(i) < deg_to_rad(60.0_wp), pre, 'terrain', 'slope'//si, &
                   fmt_angle(t%slope(i))//' deg', '0 <= slope < 60 deg')
    end do
    call require(errors, abs(s%attitude(2)) < deg_to_rad(90.0_wp), pre, 'initial_state', 'attitude(2)', &
                 fmt_angle(s%attitude(2))//' deg', '-90 < pitch < 90 deg')
    i = count(is_set(s%position))
    if (i /= 0 .and. i /= 3) &
      call errors%add(pre//'&initial_state: position is given in part ('//given_elements(s%position)// &
                      '); valid: all three components, or none to place the lander by clearance')
  end subroutine validate_terrain_initial

  !> "position(1) = 3.0, position(3) = -2.0": the set elements of a partly given vector [m].
  pure function given_elements(x) result(s)
    real(wp), intent(in) :: x(:)           !! vector with unset elements [m]
    character(len=:), allocatable :: s     !! text [-]
    integer :: j
    s = ''
    do j = 1, size(x)
      if (.not. is_set(x(j))) cycle
      if (len(s) > 0) s = s//', '
      s = s//'position('//fmt_int(j)//') = '//fmt_real(x(j))
    end do
  end function given_elements

  !> True when name (case-insensitive) is one of the comma- or blank-separated names in list.
  pure function in_name_list(name, list) result(yes)
    character(len=*), intent(in) :: name  !! law name as given [-]
    character(len=*), intent(in) :: list  !! e.g. 'base' or 'a, b' [-]
    logical :: yes                        !! name is in the list [-]
    character(len=:), allocatable :: key, rest
    integer :: p
    key = lower(trim(adjustl(name)))
    rest = lower(list)
    yes = .false.
    do while (len_trim(rest) > 0)
      rest = adjustl(rest)
      p = scan(rest, ', ')
      if (p == 0) p = len(rest) + 1
      if (rest(1:p - 1) == key .and. len(key) > 0) yes = .true.
      if (p > len(rest)) exit
      rest = rest(p + 1:)
    end do
  end function in_name_list

  !> "'a', 'b'" from the list 'a, b'.
  pure function quoted_list(list) result(s)
    character(len=*), intent(in) :: list  !! comma- or blank-separated names [-]
    character(len=:), allocatable :: s    !! quoted names [-]
    character(len=:), allocatable :: rest
    integer :: p
    s = ''
    rest = list
    do while (len_trim(rest) > 0)
      rest = adjustl(rest)
      p = scan(rest, ', ')
      if (p == 0) p = len(rest) + 1
      if (p > 1) then
        if (len(s) > 0) s = s//', '
        s = s//quoted(rest(1:p - 1))
      end if
      if (p > len(rest)) exit
      rest = rest(p + 1:)
    end do
  end function quoted_list

  !> Append "&group: var = value is invalid; valid: condition" unless ok.
  subroutine require(errors, ok, pre, group, var, value, valid)
    type(input_errors_t), intent(inout) :: errors  !! error list
    logical, intent(in) :: ok                      !! the condition holds [-]
    character(len=*), intent(in) :: pre            !! message prefix [-]
    character(len=*), intent(in) :: group          !! group name without '&' [-]
    character(len=*), intent(in) :: var            !! variable (with subscript) [-]
    character(len=*), intent(in) :: value          !! value with unit [-]
    character(len=*), intent(in) :: valid          !! valid range [-]
    if (.not. ok) call errors%add(pre//'&'//group//': '//var//' = '//value//' is invalid; valid: '//valid)
  end subroutine require

end module landyn_input_validate
