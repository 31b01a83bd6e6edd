!> The outputs of the C API (and of the Python package and the FMU built on it), defined once: their
!! names, units and meanings in a fixed order (api_output_list) and their values in the same order
!! from an output sample of a result (api_output_values). The values are what the result file
!! records (docs/output.md); the list depends only on the gears and their struts. docs/api.md has
!! the table.
module landyn_api_outputs
  use landyn_kinds, only: wp, deg2rad, rad2deg
  use landyn_tripod_gear, only: strut_names
  use landyn_loads, only: n_load, load_names
  use landyn_sim_result, only: sim_result_t
  use landyn_strings, only: int_text
  implicit none
  private

  public :: api_output_t, api_output_list, api_output_count, api_output_values
  public :: api_outcome_running, api_outcome_no_touchdown, api_outcome_at_rest, api_outcome_tipped_over, &
            api_outcome_moving, api_outcome_failed

  !> One output: its name (as landyn_get_output takes it), unit and one-line meaning.
  type, public :: api_output_t
    character(len=48) :: name = ''      !! e.g. 'gear1.strut2.stroke' [-]
    character(len=8) :: unit = ''       !! SI unit as docs/output.md has it, '-' when dimensionless [-]
    character(len=96) :: meaning = ''   !! one line [-]
  end type api_output_t

  ! the outcome codes of include/landyn.h (LANDYN_OUTCOME_*); 1 to 4 are the result file's
  ! /summary/outcome codes (landyn_outcome), 0 and 5 the API's own
  integer, parameter :: api_outcome_running = 0        !! the run has not ended [-]
  integer, parameter :: api_outcome_no_touchdown = 1   !! ended at t_end without touchdown [-]
  integer, parameter :: api_outcome_at_rest = 2        !! came to rest [-]
  integer, parameter :: api_outcome_moving = 3         !! still moving at t_end: inconclusive [-]
  integer, parameter :: api_outcome_tipped_over = 4    !! tipped over [-]
  integer, parameter :: api_outcome_failed = 5         !! the simulation failed [-]

  integer, parameter :: n_body = 22        !! outputs before the gears [-]
  integer, parameter :: n_footpad = 11     !! outputs of a gear's footpad [-]
  integer, parameter :: n_strut = 3        !! outputs of a strut [-]
  character(len=1), parameter :: xyz(3) = ['x', 'y', 'z']  !! the components of a vector [-]

contains

  !> Number of outputs of a lander with these gears.
  pure function api_output_count(n_gears, n_struts) result(n)
    integer, intent(in) :: n_gears       !! number of gears [-]
    integer, intent(in) :: n_struts(:)   !! struts of each gear (>= n_gears entries) [-]
    integer :: n                         !! outputs [-]
    n = n_body + n_gears*(n_footpad + n_load) + n_strut*sum(n_struts(1:n_gears))
  end function api_output_count

  !> The outputs of a lander with these gears, in the order of api_output_values.
  pure function api_output_list(n_gears, n_struts) result(list)
    integer, intent(in) :: n_gears                  !! number of gears [-]
    integer, intent(in) :: n_struts(:)              !! struts of each gear (>= n_gears entries) [-]
    type(api_output_t), allocatable :: list(:)      !! the outputs [-]
    integer :: k, g, s, j
    character(len=:), allocatable :: gp, sp
    allocate (list(api_output_count(n_gears, n_struts)))
    k = 0
    call put(list, k, 'time', 's', 'simulation time')
    call put(list, k, 'outcome', '-', &
             'LANDYN_OUTCOME_*: 0 running, 1 no touchdown, 2 at rest, 3 moving, 4 tipped over, 5 failed')
    call put(list, k, 'touched', '-', '1 once a footpad has touched the ground, else 0')
    call put3(list, k, 'position', 'm', 'lander-frame origin O_L, global frame (z down)')
    call put3(list, k, 'mc_position', 'm', 'mass centre, global frame (z down)')
    call put3(list, k, 'velocity', 'm/s', 'mass-centre velocity, global frame (z down)')
    call put(list, k, 'euler.yaw', 'deg', 'Z-Y-X Euler angle yaw')
    call put(list, k, 'euler.pitch', 'deg', 'Z-Y-X Euler angle pitch')
    call put(list, k, 'euler.roll', 'deg', 'Z-Y-X Euler angle roll')
    call put(list, k, 'rate.p', 'deg/s', 'body rate about the lander x axis')
    call put(list, k, 'rate.q', 'deg/s', 'body rate about the lander y axis')
    call put(list, k, 'rate.r', 'deg/s', 'body rate about the lander z axis')
    call put3(list, k, 'overload', 'g', '(a - g)/9.80665 at the mass centre, lander axes')
    call put(list, k, 'tilt', 'deg', 'angle of the lander z axis from the vertical')
    do g = 1, n_gears
      gp = 'gear'//int_text(g)//'.'
      call put(list, k, gp//'footpad.contact', '-', '1 when the footpad is below its terrain plane, else 0')
      call put3(list, k, gp//'footpad.position', 'm', 'footpad ball joint d, global frame (z down)')
      call put3(list, k, gp//'footpad.force', 'N', 'ground force on the footpad (normal + friction), global frame')
      call put(list, k, gp//'footpad.normal_force', 'N', 'normal contact force on the footpad, >= 0')
      call put(list, k, gp//'footpad.friction_force', 'N', 'magnitude of the friction force on the footpad')
      call put(list, k, gp//'footpad.penetration', 'm', 'depth of the footpad below its terrain plane (negative above)')
      call put(list, k, gp//'footpad.slip_speed', 'm/s', 'footpad speed tangential to its terrain plane')
      do s = 1, n_struts(g)
        sp = gp//'strut'//int_text(s)//'.'
        call put(list, k, sp//'stroke', 'm', &
                 trim(strut_name(s))//' strut: stroke (primary shortening +, secondaries lengthening +)')
        call put(list, k, sp//'length', 'm', trim(strut_name(s))//' strut: joint-to-joint length')
        call put(list, k, sp//'force', 'N', trim(strut_name(s))//' strut: axial buffer force, compression positive')
      end do
      do j = 1, n_load
        if (j <= 12) then
          call put(list, k, gp//'load.'//trim(load_names(j)), 'N', load_meaning(j))
        else
          call put(list, k, gp//'load.'//trim(load_names(j)), 'N m', load_meaning(j))
        end if
      end do
    end do
  end function api_output_list

  !> A strut's name (landyn_tripod_gear's strut_names; 'strut <s>' beyond them).
  pure function strut_name(s) result(name)
    integer, intent(in) :: s                  !! strut number [-]
    character(len=:), allocatable :: name     !! its name [-]
    if (s >= 1 .and. s <= size(strut_names)) then
      name = trim(strut_names(s))
    else
      name = 'strut '//int_text(s)
    end if
  end function strut_name

  !> Meaning of value j of a gear's load vector (landyn_loads).
  pure function load_meaning(j) result(text)
    integer, intent(in) :: j                  !! index in the load vector [-]
    character(len=:), allocatable :: text     !! its meaning [-]
    character(len=1), parameter :: joint(4) = ['a', 'b', 'c', 'd']
    integer :: c
    c = mod(j - 1, 3) + 1
    if (j <= 9) then
      text = 'force of joint '//joint((j - 1)/3 + 1)//' on the body, lander axes, '//xyz(c)
    else if (j <= 12) then
      text = 'force of the footpad on the primary at d, lander axes, '//xyz(c)
    else
      text = 'moment of joint '//joint((j - 13)/3 + 1)//' on the body, lander axes, '//xyz(c)
    end if
  end function load_meaning

  !> The values of the outputs (order of api_output_list) from output sample k of a result.
  pure subroutine api_output_values(res, k, outcome, touched, values)
    type(sim_result_t), intent(in) :: res     !! result with at least k samples
    integer, intent(in) :: k                  !! the sample [-]
    integer, intent(in) :: outcome            !! outcome code (api_outcome_*) [-]
    logical, intent(in) :: touched            !! a footpad has touched the ground [-]
    real(wp), intent(out) :: values(:)        !! (api_output_count) values [units of the list]
    integer :: n, g, s
    real(wp) :: c33
    n = 0
    call putv(values, n, res%t(k))
    call putv(values, n, real(outcome, wp))
    call putv(values, n, merge(1.0_wp, 0.0_wp, touched))
    call putv3(values, n, res%position(:, k))
    call putv3(values, n, res%mc_position(:, k))
    call putv3(values, n, res%velocity(:, k))
    call putv3(values, n, res%euler(:, k))
    call putv3(values, n, res%rate(:, k))
    call putv3(values, n, res%overload(:, k))
    ! R(3,3) of the Z-Y-X rotation: cos(pitch) cos(roll)
    c33 = cos(res%euler(2, k)*deg2rad)*cos(res%euler(3, k)*deg2rad)
    call putv(values, n, acos(max(-1.0_wp, min(1.0_wp, c33)))*rad2deg)
    do g = 1, res%n_gears
      call putv(values, n, merge(1.0_wp, 0.0_wp, res%penetration(g, k) > 0.0_wp))
      call putv3(values, n, res%footpad_position(:, g, k))
      call putv3(values, n, res%ground_force(:, g, k))
      call putv(values, n, res%normal_force(g, k))
      call putv(values, n, res%friction_force(g, k))
      call putv(values, n, res%penetration(g, k))
      call putv(values, n, res%slip_speed(g, k))
      do s = 1, res%n_struts(g)
        call putv(values, n, res%stroke(s, g, k))
        call putv(values, n, res%strut_length(s, g, k))
        call putv(values, n, res%strut_force(s, g, k))
      end do
      values(n + 1:n + n_load) = res%loads(:, g, k)
      n = n + n_load
    end do
  end subroutine api_output_values

  !> Appends one output to a list.
  pure subroutine put(list, k, name, unit, meaning)
    type(api_output_t), intent(inout) :: list(:)   !! the list [-]
    integer, intent(inout) :: k                    !! entries filled, incremented [-]
    character(len=*), intent(in) :: name           !! output name [-]
    character(len=*), intent(in) :: unit           !! its unit [-]
    character(len=*), intent(in) :: meaning        !! its meaning [-]
    k = k + 1
    list(k) = api_output_t(name, unit, meaning)
  end subroutine put

  !> Appends the x, y, z components of a vector output to a list.
  pure subroutine put3(list, k, name, unit, meaning)
    type(api_output_t), intent(inout) :: list(:)   !! the list [-]
    integer, intent(inout) :: k                    !! entries filled, incremented [-]
    character(len=*), intent(in) :: name           !! output name without the component [-]
    character(len=*), intent(in) :: unit           !! its unit [-]
    character(len=*), intent(in) :: meaning        !! its meaning [-]
    integer :: i
    do i = 1, 3
      call put(list, k, name//'.'//xyz(i), unit, meaning//', '//xyz(i))
    end do
  end subroutine put3

  !> Appends one value.
  pure subroutine putv(values, n, x)
    real(wp), intent(inout) :: values(:)   !! values [units of the outputs]
    integer, intent(inout) :: n            !! entries filled, incremented [-]
    real(wp), intent(in) :: x              !! value [unit of the output]
    n = n + 1
    values(n) = x
  end subroutine putv

  !> Appends three values.
  pure subroutine putv3(values, n, x)
    real(wp), intent(inout) :: values(:)   !! values [units of the outputs]
    integer, intent(inout) :: n            !! entries filled, incremented by 3 [-]
    real(wp), intent(in) :: x(3)           !! values [unit of the output]
    values(n + 1:n + 3) = x
    n = n + 3
  end subroutine putv3

end module landyn_api_outputs
