!> Namelist input of LANDYN: reads a deck into a `landyn_input_t`, resolves the derived
!! defaults, validates the physics, and writes the resolved input back as a deck.
!!
!! A deck is a sequence of namelist groups (&simulation, &lander, &engine, &gears,
!! &primary_strut, &secondary_strut, &contact, &friction, &terrain, &initial_state, &output),
!! each optional and each given at most once; a group states only what differs from the
!! defaults in landyn_config. Angles are DEGREES in decks and RADIANS in landyn_input_t; the
!! conversion happens here and nowhere else.
!!
!! Every problem is collected, not only the first: each group is split into its
!! `name = value` items, and each item is read on its own through an internal-file namelist
!! read, so that each unknown variable or unreadable value gets its own message. Messages
!! have the form `<deck>:<line>: &<group>: <what>` (read errors) or `<deck>: &<group>: <what>`
!! (resolve/validate errors); see docs/input/README.md.
!!
!! Library code: nothing here stops or prints, except into a unit the caller passes.
module landyn_input
  use, intrinsic :: iso_fortran_env, only: int64
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use landyn_kinds, only: wp, deg2rad, rad2deg, max_gears
  use landyn_errors, only: input_errors_t
  use landyn_contact, only: contact_law_names
  use landyn_friction, only: friction_law_names, default_stribeck_speed
  use landyn_kinematics, only: rot_z
  use landyn_config, only: landyn_input_t, simulation_cfg_t, lander_cfg_t, engine_cfg_t, gears_cfg_t, &
                           primary_cfg_t, secondary_cfg_t, contact_cfg_t, friction_cfg_t, terrain_cfg_t, &
                           initial_cfg_t, output_cfg_t, default_input, unset_real, is_set, max_stages, &
                           name_len, path_len, integrator_names
  use landyn_strings, only: lower => lower_case, is_blank => is_blank_char, is_digit, edit_distance, &
                            fmt_int => int_text, quoted => quote_text
  use landyn_files, only: read_whole_file
  use landyn_namelist_text, only: strip_comments, next_group, &
                                  find_item_names, line_of, first_nonblank, one_line => one_line_text, &
                                  strip_commas => separators_to_blanks, remove_blanks, mask_non_ascii, &
                                  bare_name_in_value, numbers_within
  implicit none
  private

  public :: input_errors_t
  public :: read_input_file, read_input_text, apply_input_text, resolve_input, validate_input, load_input
  public :: write_resolved_input, resolved_input_text


  ! Group indices.
  ! Bounds of docs/input (physically motivated, and far from floating-point trouble)
  real(wp), parameter :: max_steps = 1.0e9_wp          !! most time steps of a run, t_end/dt [-]
  real(wp), parameter :: max_samples = 1.0e6_wp        !! most stored output samples, t_end/interval [-]
  real(wp), parameter :: max_t_end = 3600.0_wp         !! longest simulated time [s]
  real(wp), parameter :: min_body_mass = 1.0_wp        !! lightest lander [kg]
  real(wp), parameter :: min_body_inertia = 1.0e-3_wp  !! smallest principal moment of inertia [kg m^2]
  real(wp), parameter :: min_contact_exponent = 0.5_wp !! smallest contact penetration exponent [-]
  real(wp), parameter :: max_contact_exponent = 4.0_wp !! largest contact penetration exponent [-]
  real(wp), parameter :: max_hard_point = 100.0_wp     !! largest |coordinate| of a gear hard point [m]
  integer, parameter :: g_simulation = 1, g_lander = 2, g_engine = 3, g_gears = 4, g_primary = 5, &
                        g_secondary = 6, g_contact = 7, g_friction = 8, g_terrain = 9, g_initial = 10, &
                        g_output = 11, n_groups = 11
  character(len=*), parameter :: group_names(n_groups) = [character(len=15) :: &
    'simulation', 'lander', 'engine', 'gears', 'primary_strut', 'secondary_strut', 'contact', &
    'friction', 'terrain', 'initial_state', 'output']

  integer, parameter :: ios_implausible = -12345    !! our own iostat: non-finite or absurdly large value
  real(wp), parameter :: max_magnitude = 1.0e30_wp  !! largest accepted |value| of a real input [any unit]
  integer, parameter :: max_decimal_exponent = 300  !! numbers beyond 1e300 are rejected before reading
  real(wp), parameter :: coincide_tol = 1.0e-6_wp   !! hard points closer than this coincide [m]
  integer, parameter :: snippet_len = 100           !! longest deck excerpt quoted in a message [-]
  integer, parameter :: key_len = 128               !! longest variable reference compared for duplicates [-]
  integer, parameter :: comment_col = 46            !! column of the `!` comments in written decks [-]
  integer, parameter :: short_digits = 3           !! digit counts tried one by one before bisection [-]
  !> ES formats with 1..17 significant digits and a 3-digit exponent (es_text)
  character(len=*), parameter :: es_formats(17) = [character(len=12) :: '(es30.0e3)', '(es30.1e3)', &
    '(es30.2e3)', '(es30.3e3)', '(es30.4e3)', '(es30.5e3)', '(es30.6e3)', '(es30.7e3)', '(es30.8e3)', &
    '(es30.9e3)', '(es30.10e3)', '(es30.11e3)', '(es30.12e3)', '(es30.13e3)', '(es30.14e3)', '(es30.15e3)', &
    '(es30.16e3)']

  !> Description of one namelist variable: the single source for names, units and hints.
  type :: var_t
    integer :: group                !! group index [-]
    character(len=24) :: name       !! namelist variable name [-]
    character(len=10) :: unit       !! unit in the deck ('' if none) [-]
    character(len=56) :: takes      !! what the variable takes [-]
    character(len=72) :: meaning    !! one-line meaning (comment in written decks) [-]
  end type var_t

  type(var_t), parameter :: vars_simulation(*) = [ &
    var_t(g_simulation, 'title', '', 'a quoted character string', 'run title'), &
    var_t(g_simulation, 'integrator', '', 'a quoted character string', "time integrator: 'adaptive' or 'fixed'"), &
    var_t(g_simulation, 'dt', 's', 'a real number', 'fixed: the time step; adaptive: the first step tried'), &
    var_t(g_simulation, 'tolerance', 'm/s', 'a real number', 'adaptive: local velocity error allowed per step'), &
    var_t(g_simulation, 'dt_max', 's', 'a real number', 'adaptive: largest step'), &
    var_t(g_simulation, 'dt_min', 's', 'a real number', 'adaptive: smallest step'), &
    var_t(g_simulation, 'event_resolution', 's', 'a real number', 'adaptive: events located to within this time'), &
    var_t(g_simulation, 't_end', 's', 'a real number', 'end time'), &
    var_t(g_simulation, 'gravity', 'm/s^2', 'a real number', 'gravitational acceleration, along global +z (down)'), &
    var_t(g_simulation, 'stop_at_rest', '', 'a logical (.true. or .false.)', 'end the run early once at rest'), &
    var_t(g_simulation, 'rest_speed', 'm/s', 'a real number', 'body speed below which the lander is at rest'), &
    var_t(g_simulation, 'rest_time', 's', 'a real number', 'time the speed must stay below rest_speed'), &
    var_t(g_simulation, 'tipover_angle', 'deg', 'a real number', 'tilt of lander z from vertical counted as tip-over'), &
    var_t(g_simulation, 'constraint_tol', 'm, m/s', 'a real number', 'tolerance of the constraint correction'), &
    var_t(g_simulation, 'max_correction_iter', '', 'an integer', 'iteration cap of the constraint correction'), &
    var_t(g_simulation, 'max_constraint_drift', 'm', 'a real number', 'violation above this means dt is too large')]
  type(var_t), parameter :: vars_lander(*) = [ &
    var_t(g_lander, 'mass', 'kg', 'a real number', 'total lander mass, legs included'), &
    var_t(g_lander, 'ixx', 'kg m^2', 'a real number', 'moment of inertia about x_L through the mass centre'), &
    var_t(g_lander, 'iyy', 'kg m^2', 'a real number', 'moment of inertia about y_L through the mass centre'), &
    var_t(g_lander, 'izz', 'kg m^2', 'a real number', 'moment of inertia about z_L through the mass centre'), &
    var_t(g_lander, 'ixy', 'kg m^2', 'a real number', 'product of inertia integral(x y dm); tensor element -ixy'), &
    var_t(g_lander, 'ixz', 'kg m^2', 'a real number', 'product of inertia integral(x z dm); tensor element -ixz'), &
    var_t(g_lander, 'iyz', 'kg m^2', 'a real number', 'product of inertia integral(y z dm); tensor element -iyz'), &
    var_t(g_lander, 'mass_centre', 'm', '3 real numbers x, y, z', 'mass centre in the lander frame')]
  type(var_t), parameter :: vars_engine(*) = [ &
    var_t(g_engine, 'thrust', 'N', 'a real number', 'thrust magnitude'), &
    var_t(g_engine, 'direction', '-', '3 real numbers x, y, z', 'thrust direction, lander frame (normalised)'), &
    var_t(g_engine, 'point', 'm', '3 real numbers x, y, z', 'point of application, lander frame'), &
    var_t(g_engine, 'cutoff_time', 's', 'a real number', 'thrust acts for 0 <= t < cutoff_time')]
  type(var_t), parameter :: vars_gears(*) = [ &
    var_t(g_gears, 'n_gears', '', 'an integer', 'number of landing gears'), &
    var_t(g_gears, 'rotation', 'deg', 'up to 8 real numbers, one per gear', 'rotation of gear i from gear 1 about lander z'), &
    var_t(g_gears, 'point_a', 'm', 'a 3 x 8 real array; point_a(:, i) = x, y, z', 'primary strut upper universal joint'), &
    var_t(g_gears, 'point_b', 'm', 'a 3 x 8 real array; point_b(:, i) = x, y, z', 'left secondary upper universal joint'), &
    var_t(g_gears, 'point_c', 'm', 'a 3 x 8 real array; point_c(:, i) = x, y, z', 'right secondary upper universal joint'), &
    var_t(g_gears, 'point_d', 'm', 'a 3 x 8 real array; point_d(:, i) = x, y, z', 'footpad ball joint (primary lower end)'), &
    var_t(g_gears, 'point_e', 'm', 'a 3 x 8 real array; point_e(:, i) = x, y, z', 'left secondary lower ball joint'), &
    var_t(g_gears, 'point_f', 'm', 'a 3 x 8 real array; point_f(:, i) = x, y, z', 'right secondary lower ball joint')]
  type(var_t), parameter :: vars_primary(*) = [ &
    var_t(g_primary, 'n_stages', '', 'an integer', 'number of honeycomb stages'), &
    var_t(g_primary, 'stage_force', 'N', 'up to 5 real numbers, one per stage', 'crush force of each stage'), &
    var_t(g_primary, 'stage_end', 'm', 'up to 5 real numbers, one per stage', 'stroke at which each stage ends'), &
    var_t(g_primary, 'stop_stiffness', 'N/m', 'a real number', 'stiffness of the end-of-stroke stop'), &
    var_t(g_primary, 'stop_damping', 'N s/m', 'a real number', 'damping of the end-of-stroke stop'), &
    var_t(g_primary, 'outer_mass', 'kg', 'a real number', 'outer tube with lugs'), &
    var_t(g_primary, 'outer_cm', 'm', 'a real number', 'outer tube mass centre from the upper joint'), &
    var_t(g_primary, 'outer_inertia', 'kg m^2', 'a real number', 'outer tube transverse inertia about its mass centre'), &
    var_t(g_primary, 'inner_mass', 'kg', 'a real number', 'inner tube'), &
    var_t(g_primary, 'inner_cm', 'm', 'a real number', 'inner tube mass centre from the footpad joint'), &
    var_t(g_primary, 'inner_inertia', 'kg m^2', 'a real number', 'inner tube transverse inertia about its mass centre'), &
    var_t(g_primary, 'footpad_mass', 'kg', 'a real number', 'footpad, lumped at the footpad joint'), &
    var_t(g_primary, 'tube_friction', '', 'a logical (.true. or .false.)', 'friction between the tubes (eqs. 23-26)'), &
    var_t(g_primary, 'mu_tube', '-', 'a real number', 'tube friction coefficient u_1'), &
    var_t(g_primary, 'tube_outer_length', 'm', 'a real number', 'L_O: outer tube, upper joint to its lower end'), &
    var_t(g_primary, 'tube_inner_length', 'm', 'a real number', 'L_I: inner tube, footpad joint to its upper end'), &
    var_t(g_primary, 'tube_leg_length', 'm', 'a real number', 'L_L: primary length at which the overlap is taken'), &
    var_t(g_primary, 'tube_lever', 'm', 'a real number', 'L_O1: lever arm of the lateral load (exposed inner tube)')]
  type(var_t), parameter :: vars_secondary(*) = [ &
    var_t(g_secondary, 'force_lengthening', 'N', 'a real number', 'crush force resisting lengthening (F_com)'), &
    var_t(g_secondary, 'force_shortening', 'N', 'a real number', 'crush force resisting shortening (F_ten)'), &
    var_t(g_secondary, 'stroke_lengthening', 'm', 'a real number', 'stroke available in lengthening'), &
    var_t(g_secondary, 'stroke_shortening', 'm', 'a real number', 'stroke available in shortening'), &
    var_t(g_secondary, 'stop_stiffness', 'N/m', 'a real number', 'stiffness of the end-of-stroke stops'), &
    var_t(g_secondary, 'stop_damping', 'N s/m', 'a real number', 'damping of the end-of-stroke stops'), &
    var_t(g_secondary, 'outer_mass', 'kg', 'a real number', 'upper part'), &
    var_t(g_secondary, 'outer_cm', 'm', 'a real number', 'upper part mass centre from the upper joint'), &
    var_t(g_secondary, 'outer_inertia', 'kg m^2', 'a real number', 'upper part transverse inertia about its mass centre'), &
    var_t(g_secondary, 'inner_mass', 'kg', 'a real number', 'lower part'), &
    var_t(g_secondary, 'inner_cm', 'm', 'a real number', 'lower part mass centre from the lower joint'), &
    var_t(g_secondary, 'inner_inertia', 'kg m^2', 'a real number', 'lower part transverse inertia about its mass centre')]
  type(var_t), parameter :: vars_contact(*) = [ &
    var_t(g_contact, 'law', '', 'a quoted character string', 'normal contact law'), &
    var_t(g_contact, 'stiffness', 'N/m^n', 'a real number', 'K_g'), &
    var_t(g_contact, 'exponent', '-', 'a real number', 'penetration exponent n'), &
    var_t(g_contact, 'damping', 'N s/m', 'a real number', 'C_g'), &
    var_t(g_contact, 'damping_depth', 'm', 'a real number', 'D1 (base), d_max (adams_impact), d (kelvin_voigt_step)'), &
    var_t(g_contact, 'damping2', 'N s^2/m^2', 'a real number', 'D2 of kelvin_voigt_bilinear'), &
    var_t(g_contact, 'restitution', '-', 'a real number', 'e of hunt_crossley (when hc_alpha = 0)'), &
    var_t(g_contact, 'hc_alpha', 's/m', 'a real number', 'hunt_crossley c_r = 1 - alpha v_impact; 0: use e'), &
    var_t(g_contact, 'min_impact_speed', 'm/s', 'a real number', 'floor of the impact speed in hunt_crossley'), &
    var_t(g_contact, 'soil_stiffness', 'N/m^n_b', 'a real number', 'K_b of regolith, F_p = K_b z^n_b'), &
    var_t(g_contact, 'soil_exponent', '-', 'a real number', 'n_b of regolith'), &
    var_t(g_contact, 'soil_drag', 'kg/m', 'a real number', 'alpha of regolith, drag alpha v^2 (eq. 1)'), &
    var_t(g_contact, 'soil_unload_stiffness', 'N/m', 'a real number', 'regolith unloading/reloading stiffness')]
  type(var_t), parameter :: vars_friction(*) = [ &
    var_t(g_friction, 'law', '', 'a quoted character string', 'friction law'), &
    var_t(g_friction, 'mu_static', '-', 'a real number', 'static friction coefficient'), &
    var_t(g_friction, 'mu_dynamic', '-', 'a real number', 'dynamic friction coefficient'), &
    var_t(g_friction, 'v_static', 'm/s', 'a real number', 'stiction transition slip speed'), &
    var_t(g_friction, 'v_dynamic', 'm/s', 'a real number', 'friction transition slip speed'), &
    var_t(g_friction, 'viscous', 'N s/m', 'a real number', 'C_v of ty2, ty5, ty6'), &
    var_t(g_friction, 'stribeck_speed', 'm/s', 'a real number', 'v_S of ty5, ty6 (default 1.0 for ty5, 0.1 for ty6)'), &
    var_t(g_friction, 'stribeck_exponent', '-', 'a real number', 'delta of ty5, ty6'), &
    var_t(g_friction, 'stribeck_decay', '-', 'a real number', 'epsilon of ty6'), &
    var_t(g_friction, 'stick_stiffness', 'N/m', 'a real number', 'tangential stiffness of the stick state'), &
    var_t(g_friction, 'stick_damping', 'N s/m', 'a real number', 'tangential damping of the stick state')]
  type(var_t), parameter :: vars_terrain(*) = [ &
    var_t(g_terrain, 'height', 'm', 'up to 8 real numbers, one per footpad', 'surface elevation at the global origin (up +)'), &
    var_t(g_terrain, 'slope', 'deg', 'up to 8 real numbers, one per footpad', 'slope angle'), &
    var_t(g_terrain, 'slope_direction', 'deg', 'up to 8 real numbers, one per footpad', 'azimuth of uphill, from +x toward +y')]
  type(var_t), parameter :: vars_initial(*) = [ &
    var_t(g_initial, 'position', 'm', '3 real numbers x, y, z', 'lander-frame origin in the global frame'), &
    var_t(g_initial, 'clearance', 'm', 'a real number', 'gap of the lowest footpad when position is not given'), &
    var_t(g_initial, 'velocity', 'm/s', '3 real numbers x, y, z', 'mass-centre velocity, global frame (z down)'), &
    var_t(g_initial, 'attitude', 'deg', '3 real numbers yaw, pitch, roll', 'Z-Y-X Euler angles, R = Rz(yaw) Ry(pitch) Rx(roll)'), &
    var_t(g_initial, 'angular_rate', 'deg/s', '3 real numbers p, q, r', 'body angular rate in lander axes')]
  type(var_t), parameter :: vars_output(*) = [ &
    var_t(g_output, 'file', '', 'a quoted character string', 'result file (HDF5)'), &
    var_t(g_output, 'interval', 's', 'a real number', 'output sampling interval')]
  type(var_t), parameter :: all_vars(*) = [vars_simulation, vars_lander, vars_engine, vars_gears, vars_primary, &
    vars_secondary, vars_contact, vars_friction, vars_terrain, vars_initial, vars_output]

contains

  ! ================================================================ public procedures

  !> Read a namelist deck file into `inp`, starting from `default_input()`. Every problem found
  !! is appended to `errors`. `inp%deck_name` is `path`, `inp%deck_text` the file's text.
  !! stat = 0 when the deck was read without error, 1 when the deck has errors, 2 when the file
  !! cannot be opened or read. Call resolve_input and validate_input next (or use load_input).
  subroutine read_input_file(path, inp, errors, stat)
    character(len=*), intent(in) :: path           !! deck file name [-]
    type(landyn_input_t), intent(out) :: inp       !! input read (defaults where the deck is silent)
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    integer, intent(out) :: stat                   !! 0 ok, 1 errors in the deck, 2 file not readable [-]
    character(len=:), allocatable :: text, msg

    inp = default_input()
    inp%deck_name = path
    if (len(path) == 0) then
      call errors%add("'': cannot read the input deck: empty file name")
      stat = 2
      return
    end if
    call read_whole_file(path, text, stat, msg)
    if (stat /= 0) then
      call errors%add(path//': cannot open or read the input deck: '//msg)
      stat = 2
      return
    end if
    call read_input_text(text, path, inp, errors, stat)
  end subroutine read_input_file

  !> Read a deck held in a string (lines separated by new_line('a')) into `inp`, starting from
  !! `default_input()`. `deck_name` is used in messages and stored in inp%deck_name ('' for none).
  !! stat = 0 when no error was found, 1 otherwise.
  subroutine read_input_text(text, deck_name, inp, errors, stat)
    character(len=*), intent(in) :: text           !! deck text [-]
    character(len=*), intent(in) :: deck_name      !! name for messages, usually the file name [-]
    type(landyn_input_t), intent(out) :: inp       !! input read (defaults where the deck is silent)
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    integer, intent(out) :: stat                   !! 0 ok, 1 errors found [-]
    integer :: n0
    n0 = errors%count()
    inp = default_input()
    inp%deck_name = deck_name
    inp%deck_text = text
    call parse_deck(text, deck_name, inp, errors)
    stat = merge(0, 1, errors%count() == n0)
  end subroutine read_input_text

  !> Apply a deck fragment on top of an input already read (not yet resolved): only the variables
  !! the fragment names change, and a group may be given again. Used for study variants.
  !! The fragment is appended to inp%deck_text after a comment naming `fragment_name`.
  !! stat = 0 when no error was found, 1 otherwise.
  subroutine apply_input_text(text, fragment_name, inp, errors, stat)
    character(len=*), intent(in) :: text           !! deck fragment (namelist groups) [-]
    character(len=*), intent(in) :: fragment_name  !! name for messages [-]
    type(landyn_input_t), intent(inout) :: inp     !! input updated item by item
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    integer, intent(out) :: stat                   !! 0 ok, 1 errors found [-]
    integer :: n0
    n0 = errors%count()
    call parse_deck(text, fragment_name, inp, errors)
    if (.not. allocated(inp%deck_text)) inp%deck_text = ''
    inp%deck_text = inp%deck_text//new_line('a')//'! ---- applied on top: '//trim(fragment_name)//new_line('a')//text
    stat = merge(0, 1, errors%count() == n0)
  end subroutine apply_input_text

  !> Read, resolve and validate a deck in one call. stat = 0 when the input is ready to run,
  !! 1 when `errors` holds problems of the deck, 2 when the file cannot be opened or read.
  subroutine load_input(path, inp, errors, stat)
    character(len=*), intent(in) :: path           !! deck file name [-]
    type(landyn_input_t), intent(out) :: inp       !! resolved, validated input
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    integer, intent(out) :: stat                   !! 0 ok, 1 errors in the deck, 2 file not readable [-]
    integer :: n0
    n0 = errors%count()
    call read_input_file(path, inp, errors, stat)
    if (stat == 2) return
    call resolve_input(inp, errors)
    call validate_input(inp, errors)
    stat = merge(0, 1, errors%count() == n0)
  end subroutine load_input

  !> Fill the derived defaults: gears%rotation(i) unset -> (i-1)*360/n_gears deg; point columns
  !! 2..n_gears that the deck does not give -> gear 1's points rotated by rotation(i) about the
  !! lander z axis (a gear given in part is an error); engine%direction normalised; law names in
  !! lower case; output%file empty -> deck base name + '.h5' ('landyn.h5' without a deck).
  !! Idempotent: resolving a resolved input changes nothing.
  subroutine resolve_input(inp, errors)
    type(landyn_input_t), intent(inout) :: inp     !! input to resolve in place
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    character(len=:), allocatable :: pre
    real(wp) :: nrm
    pre = msg_prefix(inp)
    call resolve_gears(inp%gears, pre, errors)
    nrm = norm2(inp%engine%direction)
    if (nrm < tiny(1.0_wp)) then
      call errors%add(pre//'&engine: direction = '//fmt_reals(inp%engine%direction)// &
                      ' is invalid; valid: a vector of non-zero length')
    else if (abs(nrm - 1.0_wp) > 4.0_wp*epsilon(1.0_wp)) then
      inp%engine%direction = inp%engine%direction/nrm
    end if
    inp%contact%law = lower(adjustl(inp%contact%law))
    inp%simulation%integrator = lower(adjustl(inp%simulation%integrator))
    inp%friction%law = lower(adjustl(inp%friction%law))
    if (.not. is_set(inp%friction%stribeck_speed)) &
      inp%friction%stribeck_speed = default_stribeck_speed(inp%friction%law)
    if (len_trim(inp%output%file) == 0) then
      if (allocated(inp%deck_name)) then
        inp%output%file = default_output_file(inp%deck_name)
      else
        inp%output%file = default_output_file('')
      end if
    end if
  end subroutine resolve_input

  !> Check a resolved input for physically invalid values. Each problem is appended to `errors`
  !! naming the group, the variable, its value (in deck units: angles in degrees) and the valid range.
  subroutine validate_input(inp, errors)
    type(landyn_input_t), intent(in) :: inp        !! resolved input
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    character(len=:), allocatable :: pre
    pre = msg_prefix(inp)
    call validate_simulation(inp%simulation, inp%output, pre, errors)
    call validate_lander(inp%lander, pre, errors)
    call validate_engine(inp%engine, pre, errors)
    call validate_gears(inp%gears, pre, errors)
    call validate_primary(inp%primary, pre, errors)
    call validate_secondary(inp%secondary, pre, errors)
    call validate_contact_friction(inp%contact, inp%friction, pre, errors)
    call validate_terrain_initial(inp%terrain, inp%initial, inp%gears%n_gears, pre, errors)
  end subroutine validate_input

  !> Write the input as a complete, valid namelist deck (every group and variable, angles in
  !! degrees, units in `!` comments) to a formatted unit. Reading it back and resolving gives
  !! the same input, bit for bit.
  subroutine write_resolved_input(unit, inp)
    integer, intent(in) :: unit               !! formatted output unit [-]
    type(landyn_input_t), intent(in) :: inp   !! input to write (normally resolved)
    character(len=:), allocatable :: text
    integer :: i0, i1
    text = resolved_input_text(inp)
    i0 = 1
    do while (i0 <= len(text))
      i1 = index(text(i0:), new_line('a'))
      if (i1 == 0) then
        write (unit, '(a)') text(i0:)
        exit
      end if
      write (unit, '(a)') text(i0:i0 + i1 - 2)
      i0 = i0 + i1
    end do
  end subroutine write_resolved_input

  !> The deck that write_resolved_input writes, as one string with new_line('a') line ends.
  pure function resolved_input_text(inp) result(text)
    type(landyn_input_t), intent(in) :: inp   !! input to write (normally resolved)
    character(len=:), allocatable :: text     !! the deck [-]
    integer :: i
    character(len=:), allocatable :: deck

    deck = ''
    if (allocated(inp%deck_name)) deck = inp%deck_name
    text = ''
    call put(text, '! LANDYN resolved input: every variable of every group, defaults filled in.')
    if (len(deck) > 0) call put(text, '! Read from deck: '//one_line(deck))
    call put(text, '! Units: SI (m, kg, N, s); angles in degrees (converted to radians on input).')
    call put(text, '! Frames: global and lander z axes point down; gravity acts along global +z.')

    associate (s => inp%simulation)
      call group_begin(text, g_simulation)
      call put_var(text, g_simulation, 'title', quoted(trim(s%title)))
      call put_var(text, g_simulation, 'integrator', quoted(trim(s%integrator)))
      call put_var(text, g_simulation, 'dt', fmt_real(s%dt))
      call put_var(text, g_simulation, 'tolerance', fmt_real(s%tolerance))
      call put_var(text, g_simulation, 'dt_max', fmt_real(s%dt_max))
      call put_var(text, g_simulation, 'dt_min', fmt_real(s%dt_min))
      call put_var(text, g_simulation, 'event_resolution', fmt_real(s%event_resolution))
      call put_var(text, g_simulation, 't_end', fmt_real(s%t_end))
      call put_var(text, g_simulation, 'gravity', fmt_real(s%gravity))
      call put_var(text, g_simulation, 'stop_at_rest', fmt_logical(s%stop_at_rest))
      call put_var(text, g_simulation, 'rest_speed', fmt_real(s%rest_speed))
      call put_var(text, g_simulation, 'rest_time', fmt_real(s%rest_time))
      call put_var(text, g_simulation, 'tipover_angle', fmt_angle(s%tipover_angle))
      call put_var(text, g_simulation, 'constraint_tol', fmt_real(s%constraint_tol))
      call put_var(text, g_simulation, 'max_correction_iter', fmt_int(s%max_correction_iter))
      call put_var(text, g_simulation, 'max_constraint_drift', fmt_real(s%max_constraint_drift))
      call put(text, '/')
    end associate

    associate (l => inp%lander)
      call group_begin(text, g_lander)
      call put_var(text, g_lander, 'mass', fmt_real(l%mass))
      call put_var(text, g_lander, 'ixx', fmt_real(l%ixx))
      call put_var(text, g_lander, 'iyy', fmt_real(l%iyy))
      call put_var(text, g_lander, 'izz', fmt_real(l%izz))
      call put_var(text, g_lander, 'ixy', fmt_real(l%ixy))
      call put_var(text, g_lander, 'ixz', fmt_real(l%ixz))
      call put_var(text, g_lander, 'iyz', fmt_real(l%iyz))
      call put_var(text, g_lander, 'mass_centre', fmt_reals(l%mass_centre))
      call put(text, '/')
    end associate

    associate (e => inp%engine)
      call group_begin(text, g_engine)
      call put_var(text, g_engine, 'thrust', fmt_real(e%thrust))
      call put_var(text, g_engine, 'direction', fmt_reals(e%direction))
      call put_var(text, g_engine, 'point', fmt_reals(e%point))
      call put_var(text, g_engine, 'cutoff_time', fmt_real(e%cutoff_time))
      call put(text, '/')
    end associate

    associate (g => inp%gears)
      call group_begin(text, g_gears)
      call put_var(text, g_gears, 'n_gears', fmt_int(g%n_gears))
      call put_partial(text, g_gears, 'rotation', g%rotation, 0, .true.)
      do i = 1, max_gears
        if (any(is_set(g%point_a(:, i))) .or. any(is_set(g%point_b(:, i))) .or. any(is_set(g%point_c(:, i))) .or. &
            any(is_set(g%point_d(:, i))) .or. any(is_set(g%point_e(:, i))) .or. any(is_set(g%point_f(:, i)))) &
          call put(text, '  ! gear '//fmt_int(i))
        call put_partial(text, g_gears, 'point_a', g%point_a(:, i), i, .false.)
        call put_partial(text, g_gears, 'point_b', g%point_b(:, i), i, .false.)
        call put_partial(text, g_gears, 'point_c', g%point_c(:, i), i, .false.)
        call put_partial(text, g_gears, 'point_d', g%point_d(:, i), i, .false.)
        call put_partial(text, g_gears, 'point_e', g%point_e(:, i), i, .false.)
        call put_partial(text, g_gears, 'point_f', g%point_f(:, i), i, .false.)
      end do
      call put(text, '/')
    end associate

    associate (p => inp%primary)
      call group_begin(text, g_primary)
      call put_var(text, g_primary, 'n_stages', fmt_int(p%n_stages))
      call put_var(text, g_primary, 'stage_force', fmt_reals(p%stage_force))
      call put_var(text, g_primary, 'stage_end', fmt_reals(p%stage_end))
      call put_var(text, g_primary, 'stop_stiffness', fmt_real(p%stop_stiffness))
      call put_var(text, g_primary, 'stop_damping', fmt_real(p%stop_damping))
      call put_var(text, g_primary, 'outer_mass', fmt_real(p%outer_mass))
      call put_var(text, g_primary, 'outer_cm', fmt_real(p%outer_cm))
      call put_var(text, g_primary, 'outer_inertia', fmt_real(p%outer_inertia))
      call put_var(text, g_primary, 'inner_mass', fmt_real(p%inner_mass))
      call put_var(text, g_primary, 'inner_cm', fmt_real(p%inner_cm))
      call put_var(text, g_primary, 'inner_inertia', fmt_real(p%inner_inertia))
      call put_var(text, g_primary, 'footpad_mass', fmt_real(p%footpad_mass))
      call put_var(text, g_primary, 'tube_friction', fmt_logical(p%tube_friction))
      call put_var(text, g_primary, 'mu_tube', fmt_real(p%mu_tube))
      call put_var(text, g_primary, 'tube_outer_length', fmt_real(p%tube_outer_length))
      call put_var(text, g_primary, 'tube_inner_length', fmt_real(p%tube_inner_length))
      call put_var(text, g_primary, 'tube_leg_length', fmt_real(p%tube_leg_length))
      call put_var(text, g_primary, 'tube_lever', fmt_real(p%tube_lever))
      call put(text, '/')
    end associate

    associate (s => inp%secondary)
      call group_begin(text, g_secondary)
      call put_var(text, g_secondary, 'force_lengthening', fmt_real(s%force_lengthening))
      call put_var(text, g_secondary, 'force_shortening', fmt_real(s%force_shortening))
      call put_var(text, g_secondary, 'stroke_lengthening', fmt_real(s%stroke_lengthening))
      call put_var(text, g_secondary, 'stroke_shortening', fmt_real(s%stroke_shortening))
      call put_var(text, g_secondary, 'stop_stiffness', fmt_real(s%stop_stiffness))
      call put_var(text, g_secondary, 'stop_damping', fmt_real(s%stop_damping))
      call put_var(text, g_secondary, 'outer_mass', fmt_real(s%outer_mass))
      call put_var(text, g_secondary, 'outer_cm', fmt_real(s%outer_cm))
      call put_var(text, g_secondary, 'outer_inertia', fmt_real(s%outer_inertia))
      call put_var(text, g_secondary, 'inner_mass', fmt_real(s%inner_mass))
      call put_var(text, g_secondary, 'inner_cm', fmt_real(s%inner_cm))
      call put_var(text, g_secondary, 'inner_inertia', fmt_real(s%inner_inertia))
      call put(text, '/')
    end associate

    associate (c => inp%contact)
      call group_begin(text, g_contact)
      call put_var(text, g_contact, 'law', quoted(trim(c%law)))
      call put_var(text, g_contact, 'stiffness', fmt_real(c%stiffness))
      call put_var(text, g_contact, 'exponent', fmt_real(c%exponent))
      call put_var(text, g_contact, 'damping', fmt_real(c%damping))
      call put_var(text, g_contact, 'damping_depth', fmt_real(c%damping_depth))
      call put_var(text, g_contact, 'damping2', fmt_real(c%damping2))
      call put_var(text, g_contact, 'restitution', fmt_real(c%restitution))
      call put_var(text, g_contact, 'hc_alpha', fmt_real(c%hc_alpha))
      call put_var(text, g_contact, 'min_impact_speed', fmt_real(c%min_impact_speed))
      call put_var(text, g_contact, 'soil_stiffness', fmt_real(c%soil_stiffness))
      call put_var(text, g_contact, 'soil_exponent', fmt_real(c%soil_exponent))
      call put_var(text, g_contact, 'soil_drag', fmt_real(c%soil_drag))
      call put_var(text, g_contact, 'soil_unload_stiffness', fmt_real(c%soil_unload_stiffness))
      call put(text, '/')
    end associate

    associate (f => inp%friction)
      call group_begin(text, g_friction)
      call put_var(text, g_friction, 'law', quoted(trim(f%law)))
      call put_var(text, g_friction, 'mu_static', fmt_real(f%mu_static))
      call put_var(text, g_friction, 'mu_dynamic', fmt_real(f%mu_dynamic))
      call put_var(text, g_friction, 'v_static', fmt_real(f%v_static))
      call put_var(text, g_friction, 'v_dynamic', fmt_real(f%v_dynamic))
      call put_var(text, g_friction, 'viscous', fmt_real(f%viscous))
      call put_partial(text, g_friction, 'stribeck_speed', [f%stribeck_speed], 0, .false.)
      call put_var(text, g_friction, 'stribeck_exponent', fmt_real(f%stribeck_exponent))
      call put_var(text, g_friction, 'stribeck_decay', fmt_real(f%stribeck_decay))
      call put_var(text, g_friction, 'stick_stiffness', fmt_real(f%stick_stiffness))
      call put_var(text, g_friction, 'stick_damping', fmt_real(f%stick_damping))
      call put(text, '/')
    end associate

    associate (t => inp%terrain)
      call group_begin(text, g_terrain)
      call put_var(text, g_terrain, 'height', fmt_reals(t%height))
      call put_var(text, g_terrain, 'slope', fmt_angles(t%slope))
      call put_var(text, g_terrain, 'slope_direction', fmt_angles(t%slope_direction))
      call put(text, '/')
    end associate

    associate (s => inp%initial)
      call group_begin(text, g_initial)
      call put_partial(text, g_initial, 'position', s%position, 0, .false.)
      call put_var(text, g_initial, 'clearance', fmt_real(s%clearance))
      call put_var(text, g_initial, 'velocity', fmt_reals(s%velocity))
      call put_var(text, g_initial, 'attitude', fmt_angles(s%attitude))
      call put_var(text, g_initial, 'angular_rate', fmt_angles(s%angular_rate))
      call put(text, '/')
    end associate

    associate (o => inp%output)
      call group_begin(text, g_output)
      call put_var(text, g_output, 'file', quoted(trim(o%file)))
      call put_var(text, g_output, 'interval', fmt_real(o%interval))
      call put(text, '/')
    end associate
  end function resolved_input_text

  ! ================================================================ deck parsing

  !> Split the deck into groups and read each group's items; see the module documentation.
  subroutine parse_deck(text, deck_name, inp, errors)
    character(len=*), intent(in) :: text           !! deck text [-]
    character(len=*), intent(in) :: deck_name      !! name for messages [-]
    type(landyn_input_t), intent(inout) :: inp     !! input updated item by item
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    character(len=:), allocatable :: work, gname
    integer :: seen(n_groups)
    integer, allocatable :: bad(:)
    integer :: p, q, e, ig, qpos, next_p, line, k, s0, s1, g
    logical :: terminated

    allocate (character(len=len(text)) :: work)
    call strip_comments(text, work, qpos)
    if (qpos > 0) then
      call errors%add(loc(deck_name, work, qpos)//'unterminated character string (no closing quote): '// &
                      snippet(work(qpos:)))
      work(qpos:) = repeat(' ', len(work) - qpos + 1)
    end if
    call mask_non_ascii(work, bad)
    do k = 1, size(bad)
      call errors%add(loc(deck_name, work, bad(k))//'byte '//hex_byte(text(bad(k):bad(k)))// &
                      ' is not ASCII text; decks are ASCII text (UTF-8 only inside quoted strings and ! comments)')
    end do
    seen = 0
    p = 1
    do
      call next_group(work, p, s0, s1, g, q, e, terminated, next_p)
      ! text outside any group: the run up to the next '&', reported once
      if (s0 > 0) call errors%add(loc(deck_name, work, s0)//'text outside any namelist group: '''// &
                                  snippet(work(s0:s1))//''' (groups start with &name and end with /)')
      if (g == 0) exit
      p = g
      line = line_of(work, p)
      gname = lower(work(p + 1:q - 1))
      if (len(gname) == 0) then
        call errors%add(loc(deck_name, work, p)//"'&' without a group name: "//snippet(work(p:e - 1)))
        p = next_p
        cycle
      end if
      ig = group_index(gname)
      if (ig == 0) then
        call errors%add(loc(deck_name, work, p)//"unknown namelist group '&"//gname//"'"// &
                        group_hint(gname)//'; valid groups: '//group_list())
      else if (seen(ig) > 0) then
        call errors%add(loc(deck_name, work, p)//'&'//gname//': group given a second time (first at line '// &
                        fmt_int(seen(ig))//'); give each group once')
      else
        seen(ig) = line
        if (.not. terminated) call errors%add(loc(deck_name, work, p)//'&'//gname// &
                                              ": group is not terminated by '/'")
        call read_group(ig, work, q, e - 1, deck_name, inp, errors)
      end if
      p = next_p
    end do
  end subroutine parse_deck

  !> Split one group body into `name = value` items and read each on its own.
  subroutine read_group(ig, work, b0, b1, deck_name, inp, errors)
    integer, intent(in) :: ig                      !! group index [-]
    character(len=*), intent(in) :: work           !! comment-free deck text [-]
    integer, intent(in) :: b0, b1                  !! body is work(b0:b1) [-]
    character(len=*), intent(in) :: deck_name      !! name for messages [-]
    type(landyn_input_t), intent(inout) :: inp     !! input updated item by item
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    integer, allocatable :: starts(:), eqs(:)
    character(len=:), allocatable :: gname, item, lhs, base, value
    character(len=key_len), allocatable :: keys(:)
    character(len=512) :: msg
    integer :: p, k, nitems, item_end, ios, iv, nkeys
    logical :: ok

    gname = trim(group_names(ig))
    ! Find every '=' outside quotes and the start of the name before it.
    call find_item_names(work, b0, b1, .false., starts, eqs)
    nitems = size(starts)
    item_end = b1
    if (nitems > 0) item_end = starts(1) - 1
    if (len_trim(strip_commas(work(b0:item_end))) > 0) then
      if (nitems > 0) then
        call errors%add(loc(deck_name, work, first_nonblank(work, b0))//'&'//gname// &
                        ': text without a variable name: '//snippet(work(b0:item_end)))
      else
        call errors%add(loc(deck_name, work, first_nonblank(work, b0))//'&'//gname// &
                        ": no 'name = value' item in: "//snippet(work(b0:item_end)))
      end if
    end if

    allocate (keys(nitems))
    nkeys = 0
    do k = 1, nitems
      item_end = b1
      if (k < nitems) item_end = starts(k + 1) - 1
      item = one_line(work(starts(k):item_end))
      if (starts(k) == eqs(k)) then
        call errors%add(loc(deck_name, work, eqs(k))//'&'//gname//": '=' without a variable name: "// &
                        snippet(item))
        cycle
      end if
      lhs = lower(remove_blanks(work(starts(k):eqs(k) - 1)))
      base = lhs
      p = scan(lhs, '(%')
      if (p > 0) base = lhs(1:p - 1)
      value = work(eqs(k) + 1:item_end)
      iv = var_index(ig, base)
      if (iv == 0) then
        call errors%add(loc(deck_name, work, starts(k))//'&'//gname//": unknown variable '"// &
                        trim(adjustl(work(starts(k):eqs(k) - 1)))//"' ("//snippet(item)//')'//var_hint(ig, base))
        cycle
      end if
      if (any(keys(1:nkeys) == lhs)) then
        call errors%add(loc(deck_name, work, starts(k))//'&'//gname//': '//lhs// &
                        ' is given more than once ('//snippet(item)//'); give it once')
        cycle
      end if
      nkeys = nkeys + 1
      keys(nkeys) = lhs   ! (a name longer than key_len is compared by its start)
      if (len_trim(strip_commas(value)) == 0) then
        call errors%add(loc(deck_name, work, starts(k))//'&'//gname//': no value given for '//lhs// &
                        ' ('//trim(base)//' takes '//trim(all_vars(iv)%takes)//unit_text(iv)//')')
        cycle
      end if
      if (len(bare_name_in_value(value)) > 0) then
        call errors%add(loc(deck_name, work, starts(k))//'&'//gname//": '"//bare_name_in_value(value)// &
                        "' after "//lhs//' = ... is a name without a value ('//snippet(item)// &
                        "); give it as 'name = value' or remove it")
        cycle
      end if
      if (longest_string(value) > string_limit(ig, base)) then
        call errors%add(loc(deck_name, work, starts(k))//'&'//gname//': '//lhs//' is too long ('// &
                        fmt_int(longest_string(value))//' characters); valid: at most '// &
                        fmt_int(string_limit(ig, base))//' characters')
        cycle
      end if
      ok = numbers_within(value, max_decimal_exponent)
      if (.not. ok) then
        call errors%add(loc(deck_name, work, starts(k))//'&'//gname//': '//lhs//' = '// &
                        snippet(value)//' is out of range; valid: |value| <= 1e30')
        cycle
      end if
      msg = ''
      call read_item(ig, '&'//gname//' '//item//' /', inp, ios, msg)
      if (ios == ios_implausible) then
        call errors%add(loc(deck_name, work, starts(k))//'&'//gname//': '//lhs//' = '// &
                        snippet(value)//' is invalid; valid: finite numbers with |value| <= 1e30')
      else if (ios /= 0) then
        call errors%add(loc(deck_name, work, starts(k))//'&'//gname//': cannot read '//lhs//' = '// &
                        quoted(snippet_raw(value))//' ('//trim(base)//' takes '//trim(all_vars(iv)%takes)// &
                        unit_text(iv)//'): '//trim(msg))
      end if
    end do
  end subroutine read_group

  !> Length of the longest quoted string in a value text (0 if none); doubled quotes count once.
  pure function longest_string(value) result(n)
    character(len=*), intent(in) :: value  !! value text [-]
    integer :: n                           !! longest quoted string [characters]
    character(len=1) :: quote
    integer :: p, cur
    n = 0
    cur = 0
    quote = ' '
    p = 1
    do while (p <= len(value))
      if (quote /= ' ') then
        if (value(p:p) == quote) then
          if (p < len(value)) then
            if (value(p + 1:p + 1) == quote) then
              cur = cur + 1
              p = p + 2
              cycle
            end if
          end if
          quote = ' '
          n = max(n, cur)
        else
          cur = cur + 1
        end if
      else if (value(p:p) == '"' .or. value(p:p) == "'") then
        quote = value(p:p)
        cur = 0
      end if
      p = p + 1
    end do
    if (quote /= ' ') n = max(n, cur)
  end function longest_string

  !> Longest character value a variable holds (huge for non-character variables).
  pure function string_limit(ig, base) result(n)
    integer, intent(in) :: ig               !! group index [-]
    character(len=*), intent(in) :: base    !! variable name in lower case [-]
    integer :: n                            !! limit [characters]
    type(simulation_cfg_t) :: sdef
    n = huge(1)
    if (ig == g_output .and. base == 'file') n = path_len
    if (ig == g_simulation .and. base == 'title') n = len(sdef%title)
    if (base == 'law' .or. base == 'integrator') n = name_len
  end function string_limit

  !> A byte as "0xHH".
  pure function hex_byte(c) result(h)
    character(len=1), intent(in) :: c   !! byte [-]
    character(len=4) :: h               !! its hexadecimal text [-]
    character(len=16), parameter :: digits = '0123456789ABCDEF'
    integer :: b
    b = iachar(c)
    if (b < 0) b = b + 256
    h = '0x'//digits(b/16 + 1:b/16 + 1)//digits(mod(b, 16) + 1:mod(b, 16) + 1)
  end function hex_byte


  !> Read one item (buffer "&group name = value /") into the group's part of `inp`.
  subroutine read_item(ig, buffer, inp, ios, msg)
    integer, intent(in) :: ig                   !! group index [-]
    character(len=*), intent(in) :: buffer      !! one-item namelist record [-]
    type(landyn_input_t), intent(inout) :: inp  !! updated only when the read succeeds
    integer, intent(out) :: ios                 !! 0, a Fortran iostat, or ios_implausible [-]
    character(len=*), intent(inout) :: msg      !! iomsg of a failed read [-]
    select case (ig)
    case (g_simulation)
      call read_simulation(buffer, inp%simulation, ios, msg)
    case (g_lander)
      call read_lander(buffer, inp%lander, ios, msg)
    case (g_engine)
      call read_engine(buffer, inp%engine, ios, msg)
    case (g_gears)
      call read_gears(buffer, inp%gears, ios, msg)
    case (g_primary)
      call read_primary(buffer, inp%primary, ios, msg)
    case (g_secondary)
      call read_secondary(buffer, inp%secondary, ios, msg)
    case (g_contact)
      call read_contact(buffer, inp%contact, ios, msg)
    case (g_friction)
      call read_friction(buffer, inp%friction, ios, msg)
    case (g_terrain)
      call read_terrain(buffer, inp%terrain, ios, msg)
    case (g_initial)
      call read_initial(buffer, inp%initial, ios, msg)
    case default
      call read_output(buffer, inp%output, ios, msg)
    end select
  end subroutine read_item

  ! ---------------------------------------------------------------- one reader per group
  ! Each copies the group into local variables named as in the deck, reads the one-item
  ! record, checks the reals, and copies back. Angles are read in degrees into locals that
  ! start unset, so only the elements the item gives are converted.

  subroutine read_simulation(buffer, cfg, ios, msg)
    character(len=*), intent(in) :: buffer          !! one-item record [-]
    type(simulation_cfg_t), intent(inout) :: cfg    !! updated on success
    integer, intent(out) :: ios                     !! iostat [-]
    character(len=*), intent(inout) :: msg          !! iomsg [-]
    character(len=len(cfg%title)) :: title
    character(len=name_len) :: integrator
    real(wp) :: dt, t_end, gravity, rest_speed, rest_time, tipover_angle, constraint_tol, max_constraint_drift
    real(wp) :: tolerance, dt_max, dt_min, event_resolution
    logical :: stop_at_rest
    integer :: max_correction_iter
    namelist /simulation/ title, integrator, dt, tolerance, dt_max, dt_min, event_resolution, t_end, gravity, &
      stop_at_rest, rest_speed, rest_time, tipover_angle, constraint_tol, max_correction_iter, max_constraint_drift
    title = cfg%title
    integrator = cfg%integrator
    dt = cfg%dt
    tolerance = cfg%tolerance
    dt_max = cfg%dt_max
    dt_min = cfg%dt_min
    event_resolution = cfg%event_resolution
    t_end = cfg%t_end
    gravity = cfg%gravity
    stop_at_rest = cfg%stop_at_rest
    rest_speed = cfg%rest_speed
    rest_time = cfg%rest_time
    tipover_angle = unset_real
    constraint_tol = cfg%constraint_tol
    max_correction_iter = cfg%max_correction_iter
    max_constraint_drift = cfg%max_constraint_drift
    read (buffer, nml=simulation, iostat=ios, iomsg=msg)
    if (ios /= 0) return
    if (.not. plausible([dt, t_end, gravity, rest_speed, rest_time, tipover_angle, constraint_tol, &
                         max_constraint_drift, tolerance, dt_max, dt_min, event_resolution])) then
      ios = ios_implausible
      return
    end if
    cfg%title = title
    cfg%integrator = integrator
    cfg%dt = dt
    cfg%tolerance = tolerance
    cfg%dt_max = dt_max
    cfg%dt_min = dt_min
    cfg%event_resolution = event_resolution
    cfg%t_end = t_end
    cfg%gravity = gravity
    cfg%stop_at_rest = stop_at_rest
    cfg%rest_speed = rest_speed
    cfg%rest_time = rest_time
    if (is_set(tipover_angle)) cfg%tipover_angle = deg_to_rad(tipover_angle)
    cfg%constraint_tol = constraint_tol
    cfg%max_correction_iter = max_correction_iter
    cfg%max_constraint_drift = max_constraint_drift
  end subroutine read_simulation

  subroutine read_lander(buffer, cfg, ios, msg)
    character(len=*), intent(in) :: buffer       !! one-item record [-]
    type(lander_cfg_t), intent(inout) :: cfg     !! updated on success
    integer, intent(out) :: ios                  !! iostat [-]
    character(len=*), intent(inout) :: msg       !! iomsg [-]
    real(wp) :: mass, ixx, iyy, izz, ixy, ixz, iyz, mass_centre(3)
    namelist /lander/ mass, ixx, iyy, izz, ixy, ixz, iyz, mass_centre
    mass = cfg%mass
    ixx = cfg%ixx
    iyy = cfg%iyy
    izz = cfg%izz
    ixy = cfg%ixy
    ixz = cfg%ixz
    iyz = cfg%iyz
    mass_centre = cfg%mass_centre
    read (buffer, nml=lander, iostat=ios, iomsg=msg)
    if (ios /= 0) return
    if (.not. plausible([mass, ixx, iyy, izz, ixy, ixz, iyz, mass_centre])) then
      ios = ios_implausible
      return
    end if
    cfg%mass = mass
    cfg%ixx = ixx
    cfg%iyy = iyy
    cfg%izz = izz
    cfg%ixy = ixy
    cfg%ixz = ixz
    cfg%iyz = iyz
    cfg%mass_centre = mass_centre
  end subroutine read_lander

  subroutine read_engine(buffer, cfg, ios, msg)
    character(len=*), intent(in) :: buffer       !! one-item record [-]
    type(engine_cfg_t), intent(inout) :: cfg     !! updated on success
    integer, intent(out) :: ios                  !! iostat [-]
    character(len=*), intent(inout) :: msg       !! iomsg [-]
    real(wp) :: thrust, direction(3), point(3), cutoff_time
    namelist /engine/ thrust, direction, point, cutoff_time
    thrust = cfg%thrust
    direction = cfg%direction
    point = cfg%point
    cutoff_time = cfg%cutoff_time
    read (buffer, nml=engine, iostat=ios, iomsg=msg)
    if (ios /= 0) return
    if (.not. plausible([thrust, direction, point, cutoff_time])) then
      ios = ios_implausible
      return
    end if
    cfg%thrust = thrust
    cfg%direction = direction
    cfg%point = point
    cfg%cutoff_time = cutoff_time
  end subroutine read_engine

  subroutine read_gears(buffer, cfg, ios, msg)
    character(len=*), intent(in) :: buffer       !! one-item record [-]
    type(gears_cfg_t), intent(inout) :: cfg      !! updated on success
    integer, intent(out) :: ios                  !! iostat [-]
    character(len=*), intent(inout) :: msg       !! iomsg [-]
    integer :: n_gears
    real(wp) :: rotation(max_gears)
    real(wp), dimension(3, max_gears) :: point_a, point_b, point_c, point_d, point_e, point_f
    namelist /gears/ n_gears, rotation, point_a, point_b, point_c, point_d, point_e, point_f
    n_gears = cfg%n_gears
    rotation = unset_real
    point_a = cfg%point_a
    point_b = cfg%point_b
    point_c = cfg%point_c
    point_d = cfg%point_d
    point_e = cfg%point_e
    point_f = cfg%point_f
    read (buffer, nml=gears, iostat=ios, iomsg=msg)
    if (ios /= 0) return
    if (.not. plausible([rotation, point_a, point_b, point_c, point_d, point_e, point_f])) then
      ios = ios_implausible
      return
    end if
    cfg%n_gears = n_gears
    where (is_set(rotation)) cfg%rotation = deg_to_rad(rotation)
    cfg%point_a = point_a
    cfg%point_b = point_b
    cfg%point_c = point_c
    cfg%point_d = point_d
    cfg%point_e = point_e
    cfg%point_f = point_f
  end subroutine read_gears

  subroutine read_primary(buffer, cfg, ios, msg)
    character(len=*), intent(in) :: buffer       !! one-item record [-]
    type(primary_cfg_t), intent(inout) :: cfg    !! updated on success
    integer, intent(out) :: ios                  !! iostat [-]
    character(len=*), intent(inout) :: msg       !! iomsg [-]
    integer :: n_stages
    real(wp) :: stage_force(max_stages), stage_end(max_stages)
    real(wp) :: stop_stiffness, stop_damping, outer_mass, outer_cm, outer_inertia, inner_mass, inner_cm, &
                inner_inertia, footpad_mass, mu_tube, tube_outer_length, tube_inner_length, tube_leg_length, tube_lever
    logical :: tube_friction
    namelist /primary_strut/ n_stages, stage_force, stage_end, stop_stiffness, stop_damping, outer_mass, &
      outer_cm, outer_inertia, inner_mass, inner_cm, inner_inertia, footpad_mass, tube_friction, mu_tube, &
      tube_outer_length, tube_inner_length, tube_leg_length, tube_lever
    n_stages = cfg%n_stages
    stage_force = cfg%stage_force
    stage_end = cfg%stage_end
    stop_stiffness = cfg%stop_stiffness
    stop_damping = cfg%stop_damping
    outer_mass = cfg%outer_mass
    outer_cm = cfg%outer_cm
    outer_inertia = cfg%outer_inertia
    inner_mass = cfg%inner_mass
    inner_cm = cfg%inner_cm
    inner_inertia = cfg%inner_inertia
    footpad_mass = cfg%footpad_mass
    tube_friction = cfg%tube_friction
    mu_tube = cfg%mu_tube
    tube_outer_length = cfg%tube_outer_length
    tube_inner_length = cfg%tube_inner_length
    tube_leg_length = cfg%tube_leg_length
    tube_lever = cfg%tube_lever
    read (buffer, nml=primary_strut, iostat=ios, iomsg=msg)
    if (ios /= 0) return
    if (.not. plausible([stage_force, stage_end, stop_stiffness, stop_damping, outer_mass, outer_cm, &
                         outer_inertia, inner_mass, inner_cm, inner_inertia, footpad_mass, mu_tube, &
                         tube_outer_length, tube_inner_length, tube_leg_length, tube_lever])) then
      ios = ios_implausible
      return
    end if
    cfg%n_stages = n_stages
    cfg%stage_force = stage_force
    cfg%stage_end = stage_end
    cfg%stop_stiffness = stop_stiffness
    cfg%stop_damping = stop_damping
    cfg%outer_mass = outer_mass
    cfg%outer_cm = outer_cm
    cfg%outer_inertia = outer_inertia
    cfg%inner_mass = inner_mass
    cfg%inner_cm = inner_cm
    cfg%inner_inertia = inner_inertia
    cfg%footpad_mass = footpad_mass
    cfg%tube_friction = tube_friction
    cfg%mu_tube = mu_tube
    cfg%tube_outer_length = tube_outer_length
    cfg%tube_inner_length = tube_inner_length
    cfg%tube_leg_length = tube_leg_length
    cfg%tube_lever = tube_lever
  end subroutine read_primary

  subroutine read_secondary(buffer, cfg, ios, msg)
    character(len=*), intent(in) :: buffer        !! one-item record [-]
    type(secondary_cfg_t), intent(inout) :: cfg   !! updated on success
    integer, intent(out) :: ios                   !! iostat [-]
    character(len=*), intent(inout) :: msg        !! iomsg [-]
    real(wp) :: force_lengthening, force_shortening, stroke_lengthening, stroke_shortening, stop_stiffness, &
                stop_damping, outer_mass, outer_cm, outer_inertia, inner_mass, inner_cm, inner_inertia
    namelist /secondary_strut/ force_lengthening, force_shortening, stroke_lengthening, stroke_shortening, &
      stop_stiffness, stop_damping, outer_mass, outer_cm, outer_inertia, inner_mass, inner_cm, inner_inertia
    force_lengthening = cfg%force_lengthening
    force_shortening = cfg%force_shortening
    stroke_lengthening = cfg%stroke_lengthening
    stroke_shortening = cfg%stroke_shortening
    stop_stiffness = cfg%stop_stiffness
    stop_damping = cfg%stop_damping
    outer_mass = cfg%outer_mass
    outer_cm = cfg%outer_cm
    outer_inertia = cfg%outer_inertia
    inner_mass = cfg%inner_mass
    inner_cm = cfg%inner_cm
    inner_inertia = cfg%inner_inertia
    read (buffer, nml=secondary_strut, iostat=ios, iomsg=msg)
    if (ios /= 0) return
    if (.not. plausible([force_lengthening, force_shortening, stroke_lengthening, stroke_shortening, &
                         stop_stiffness, stop_damping, outer_mass, outer_cm, outer_inertia, inner_mass, &
                         inner_cm, inner_inertia])) then
      ios = ios_implausible
      return
    end if
    cfg%force_lengthening = force_lengthening
    cfg%force_shortening = force_shortening
    cfg%stroke_lengthening = stroke_lengthening
    cfg%stroke_shortening = stroke_shortening
    cfg%stop_stiffness = stop_stiffness
    cfg%stop_damping = stop_damping
    cfg%outer_mass = outer_mass
    cfg%outer_cm = outer_cm
    cfg%outer_inertia = outer_inertia
    cfg%inner_mass = inner_mass
    cfg%inner_cm = inner_cm
    cfg%inner_inertia = inner_inertia
  end subroutine read_secondary

  subroutine read_contact(buffer, cfg, ios, msg)
    character(len=*), intent(in) :: buffer       !! one-item record [-]
    type(contact_cfg_t), intent(inout) :: cfg    !! updated on success
    integer, intent(out) :: ios                  !! iostat [-]
    character(len=*), intent(inout) :: msg       !! iomsg [-]
    character(len=name_len) :: law
    real(wp) :: stiffness, exponent, damping, damping_depth, damping2, restitution, hc_alpha, min_impact_speed, &
                soil_stiffness, soil_exponent, soil_drag, soil_unload_stiffness
    namelist /contact/ law, stiffness, exponent, damping, damping_depth, damping2, restitution, hc_alpha, &
      min_impact_speed, soil_stiffness, soil_exponent, soil_drag, soil_unload_stiffness
    law = cfg%law
    stiffness = cfg%stiffness
    exponent = cfg%exponent
    damping = cfg%damping
    damping_depth = cfg%damping_depth
    damping2 = cfg%damping2
    restitution = cfg%restitution
    hc_alpha = cfg%hc_alpha
    min_impact_speed = cfg%min_impact_speed
    soil_stiffness = cfg%soil_stiffness
    soil_exponent = cfg%soil_exponent
    soil_drag = cfg%soil_drag
    soil_unload_stiffness = cfg%soil_unload_stiffness
    read (buffer, nml=contact, iostat=ios, iomsg=msg)
    if (ios /= 0) return
    if (.not. plausible([stiffness, exponent, damping, damping_depth, damping2, restitution, hc_alpha, &
                         min_impact_speed, soil_stiffness, soil_exponent, soil_drag, soil_unload_stiffness])) then
      ios = ios_implausible
      return
    end if
    cfg%law = law
    cfg%stiffness = stiffness
    cfg%exponent = exponent
    cfg%damping = damping
    cfg%damping_depth = damping_depth
    cfg%damping2 = damping2
    cfg%restitution = restitution
    cfg%hc_alpha = hc_alpha
    cfg%min_impact_speed = min_impact_speed
    cfg%soil_stiffness = soil_stiffness
    cfg%soil_exponent = soil_exponent
    cfg%soil_drag = soil_drag
    cfg%soil_unload_stiffness = soil_unload_stiffness
  end subroutine read_contact

  subroutine read_friction(buffer, cfg, ios, msg)
    character(len=*), intent(in) :: buffer       !! one-item record [-]
    type(friction_cfg_t), intent(inout) :: cfg   !! updated on success
    integer, intent(out) :: ios                  !! iostat [-]
    character(len=*), intent(inout) :: msg       !! iomsg [-]
    character(len=name_len) :: law
    real(wp) :: mu_static, mu_dynamic, v_static, v_dynamic, viscous, stribeck_speed, stribeck_exponent, &
                stribeck_decay, stick_stiffness, stick_damping
    namelist /friction/ law, mu_static, mu_dynamic, v_static, v_dynamic, viscous, stribeck_speed, &
      stribeck_exponent, stribeck_decay, stick_stiffness, stick_damping
    law = cfg%law
    mu_static = cfg%mu_static
    mu_dynamic = cfg%mu_dynamic
    v_static = cfg%v_static
    v_dynamic = cfg%v_dynamic
    viscous = cfg%viscous
    stribeck_speed = cfg%stribeck_speed
    stribeck_exponent = cfg%stribeck_exponent
    stribeck_decay = cfg%stribeck_decay
    stick_stiffness = cfg%stick_stiffness
    stick_damping = cfg%stick_damping
    read (buffer, nml=friction, iostat=ios, iomsg=msg)
    if (ios /= 0) return
    if (.not. plausible([mu_static, mu_dynamic, v_static, v_dynamic, viscous, stribeck_speed, stribeck_exponent, &
                         stribeck_decay, stick_stiffness, stick_damping])) then
      ios = ios_implausible
      return
    end if
    cfg%law = law
    cfg%mu_static = mu_static
    cfg%mu_dynamic = mu_dynamic
    cfg%v_static = v_static
    cfg%v_dynamic = v_dynamic
    cfg%viscous = viscous
    cfg%stribeck_speed = stribeck_speed
    cfg%stribeck_exponent = stribeck_exponent
    cfg%stribeck_decay = stribeck_decay
    cfg%stick_stiffness = stick_stiffness
    cfg%stick_damping = stick_damping
  end subroutine read_friction

  subroutine read_terrain(buffer, cfg, ios, msg)
    character(len=*), intent(in) :: buffer       !! one-item record [-]
    type(terrain_cfg_t), intent(inout) :: cfg    !! updated on success
    integer, intent(out) :: ios                  !! iostat [-]
    character(len=*), intent(inout) :: msg       !! iomsg [-]
    real(wp), dimension(max_gears) :: height, slope, slope_direction
    namelist /terrain/ height, slope, slope_direction
    height = cfg%height
    slope = unset_real
    slope_direction = unset_real
    read (buffer, nml=terrain, iostat=ios, iomsg=msg)
    if (ios /= 0) return
    if (.not. plausible([height, slope, slope_direction])) then
      ios = ios_implausible
      return
    end if
    cfg%height = height
    where (is_set(slope)) cfg%slope = deg_to_rad(slope)
    where (is_set(slope_direction)) cfg%slope_direction = deg_to_rad(slope_direction)
  end subroutine read_terrain

  subroutine read_initial(buffer, cfg, ios, msg)
    character(len=*), intent(in) :: buffer       !! one-item record [-]
    type(initial_cfg_t), intent(inout) :: cfg    !! updated on success
    integer, intent(out) :: ios                  !! iostat [-]
    character(len=*), intent(inout) :: msg       !! iomsg [-]
    real(wp) :: position(3), clearance, velocity(3), attitude(3), angular_rate(3)
    namelist /initial_state/ position, clearance, velocity, attitude, angular_rate
    position = cfg%position
    clearance = cfg%clearance
    velocity = cfg%velocity
    attitude = unset_real
    angular_rate = unset_real
    read (buffer, nml=initial_state, iostat=ios, iomsg=msg)
    if (ios /= 0) return
    if (.not. plausible([position, clearance, velocity, attitude, angular_rate])) then
      ios = ios_implausible
      return
    end if
    cfg%position = position
    cfg%clearance = clearance
    cfg%velocity = velocity
    where (is_set(attitude)) cfg%attitude = deg_to_rad(attitude)
    where (is_set(angular_rate)) cfg%angular_rate = deg_to_rad(angular_rate)
  end subroutine read_initial

  subroutine read_output(buffer, cfg, ios, msg)
    character(len=*), intent(in) :: buffer       !! one-item record [-]
    type(output_cfg_t), intent(inout) :: cfg     !! updated on success
    integer, intent(out) :: ios                  !! iostat [-]
    character(len=*), intent(inout) :: msg       !! iomsg [-]
    character(len=path_len) :: file
    real(wp) :: interval
    namelist /output/ file, interval
    file = cfg%file
    interval = cfg%interval
    read (buffer, nml=output, iostat=ios, iomsg=msg)
    if (ios /= 0) return
    if (.not. plausible([interval])) then
      ios = ios_implausible
      return
    end if
    cfg%file = file
    cfg%interval = interval
  end subroutine read_output

  !> True when every set value is finite with |x| <= max_magnitude (unset markers are skipped).
  pure function plausible(x) result(ok)
    real(wp), intent(in) :: x(:)  !! values [any unit]
    logical :: ok                 !! all plausible [-]
    integer :: i
    ok = .true.
    do i = 1, size(x)
      if (.not. ieee_is_finite(x(i))) then
        ok = .false.
      else if (is_set(x(i))) then
        if (abs(x(i)) > max_magnitude) ok = .false.
      end if
    end do
  end function plausible

  ! ================================================================ resolve helpers

  !> Resolve gear rotations and hard points; see resolve_input.
  subroutine resolve_gears(g, pre, errors)
    type(gears_cfg_t), intent(inout) :: g          !! gears to resolve in place
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    real(wp) :: r(3, 3)
    integer :: i, n, nset
    character(len=:), allocatable :: missing
    n = g%n_gears
    if (n < 1 .or. n > max_gears) return   ! reported by validate_input
    do i = 1, n
      if (.not. is_set(g%rotation(i))) g%rotation(i) = deg_to_rad(real(i - 1, wp)*360.0_wp/real(n, wp))
    end do
    do i = 1, max_gears
      nset = count(is_set(g%point_a(:, i))) + count(is_set(g%point_b(:, i))) + count(is_set(g%point_c(:, i))) + &
             count(is_set(g%point_d(:, i))) + count(is_set(g%point_e(:, i))) + count(is_set(g%point_f(:, i)))
      if (i > n) then
        if (nset > 0 .or. is_set(g%rotation(i))) &
          call errors%add(pre//'&gears: gear '//fmt_int(i)//' is given (rotation or points) but n_gears = '// &
                          fmt_int(n)//'; valid: give gears 1..n_gears only')
        cycle
      end if
      if (nset == 18) cycle
      if (nset == 0 .and. i > 1) then
        r = rot_z(g%rotation(i))
        g%point_a(:, i) = matmul(r, g%point_a(:, 1))
        g%point_b(:, i) = matmul(r, g%point_b(:, 1))
        g%point_c(:, i) = matmul(r, g%point_c(:, 1))
        g%point_d(:, i) = matmul(r, g%point_d(:, 1))
        g%point_e(:, i) = matmul(r, g%point_e(:, 1))
        g%point_f(:, i) = matmul(r, g%point_f(:, 1))
        cycle
      end if
      missing = missing_list(g, i)
      call errors%add(pre//'&gears: gear '//fmt_int(i)//' is given only in part (missing: '//missing// &
                      '); valid: all six points point_a(:, '//fmt_int(i)//') .. point_f(:, '//fmt_int(i)// &
                      '), or none to rotate gear 1 by rotation('//fmt_int(i)//')')
    end do
  end subroutine resolve_gears

  !> The names of the points of gear i that are not (fully) given.
  function missing_list(g, i) result(list)
    type(gears_cfg_t), intent(in) :: g       !! gears
    integer, intent(in) :: i                 !! gear index [-]
    character(len=:), allocatable :: list    !! e.g. "point_b(:, 3), point_f(:, 3)" [-]
    list = ''
    if (.not. all(is_set(g%point_a(:, i)))) call append(list, 'point_a')
    if (.not. all(is_set(g%point_b(:, i)))) call append(list, 'point_b')
    if (.not. all(is_set(g%point_c(:, i)))) call append(list, 'point_c')
    if (.not. all(is_set(g%point_d(:, i)))) call append(list, 'point_d')
    if (.not. all(is_set(g%point_e(:, i)))) call append(list, 'point_e')
    if (.not. all(is_set(g%point_f(:, i)))) call append(list, 'point_f')
  contains
    subroutine append(l, name)
      character(len=:), allocatable, intent(inout) :: l  !! list [-]
      character(len=*), intent(in) :: name               !! point name [-]
      if (len(l) > 0) l = l//', '
      l = l//name//'(:, '//fmt_int(i)//')'
    end subroutine append
  end function missing_list

  !> Base name of the deck (no directory, no extension) + '.h5'; 'landyn.h5' without a deck.
  pure function default_output_file(deck) result(file)
    character(len=*), intent(in) :: deck     !! deck path ('' for none) [-]
    character(len=:), allocatable :: file    !! result file name [-]
    integer :: s, d
    s = index(deck, '/', back=.true.)
    file = trim(deck(s + 1:))
    d = index(file, '.', back=.true.)
    if (d > 1) file = file(1:d - 1)
    if (len(file) == 0) file = 'landyn'
    file = file//'.h5'
  end function default_output_file

  ! ================================================================ validation

  subroutine validate_simulation(s, o, pre, errors)
    type(simulation_cfg_t), intent(in) :: s        !! &simulation
    type(output_cfg_t), intent(in) :: o            !! &output
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    character(len=*), parameter :: g = 'simulation'
    call require(errors, s%dt > 0.0_wp, pre, g, 'dt', fmt_real(s%dt)//' s', 'dt > 0 s')
    call require(errors, s%t_end > 0.0_wp, pre, g, 't_end', fmt_real(s%t_end)//' s', 't_end > 0 s')
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
    call require(errors, in_name_list(s%integrator, integrator_names), pre, g, 'integrator', &
                 quoted(trim(s%integrator)), 'one of '//quoted_list(integrator_names))
    call require(errors, s%tolerance > 0.0_wp, pre, g, 'tolerance', fmt_real(s%tolerance)//' m/s', 'tolerance > 0 m/s')
    call require(errors, s%dt_min > 0.0_wp, pre, g, 'dt_min', fmt_real(s%dt_min)//' s', 'dt_min > 0 s')
    call require(errors, s%dt_max >= s%dt_min, pre, g, 'dt_max', fmt_real(s%dt_max)//' s', &
                 'dt_max >= dt_min = '//fmt_real(s%dt_min)//' s')
    call require(errors, s%event_resolution > 0.0_wp, pre, g, 'event_resolution', &
                 fmt_real(s%event_resolution)//' s', 'event_resolution > 0 s')
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
    call require(errors, s%gravity >= 0.0_wp, pre, g, 'gravity', fmt_real(s%gravity)//' m/s^2', 'gravity >= 0 m/s^2')
    call require(errors, s%rest_speed > 0.0_wp, pre, g, 'rest_speed', fmt_real(s%rest_speed)//' m/s', &
                 'rest_speed > 0 m/s')
    call require(errors, s%rest_time >= 0.0_wp, pre, g, 'rest_time', fmt_real(s%rest_time)//' s', 'rest_time >= 0 s')
    call require(errors, s%tipover_angle > 0.0_wp .and. s%tipover_angle <= deg_to_rad(180.0_wp), pre, g, &
                 'tipover_angle', fmt_angle(s%tipover_angle)//' deg', '0 < tipover_angle <= 180 deg')
    call require(errors, s%constraint_tol > 0.0_wp, pre, g, 'constraint_tol', fmt_real(s%constraint_tol), &
                 'constraint_tol > 0')
    call require(errors, s%max_correction_iter >= 1, pre, g, 'max_correction_iter', fmt_int(s%max_correction_iter), &
                 'max_correction_iter >= 1')
    call require(errors, s%max_constraint_drift > 0.0_wp, pre, g, 'max_constraint_drift', &
                 fmt_real(s%max_constraint_drift)//' m', 'max_constraint_drift > 0 m')
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

  subroutine validate_lander(l, pre, errors)
    type(lander_cfg_t), intent(in) :: l            !! &lander
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    character(len=*), parameter :: g = 'lander', u = ' kg m^2'
    real(wp) :: t(3, 3), m1, m2, m3
    logical :: positive_diagonal
    call require(errors, l%mass >= min_body_mass, pre, g, 'mass', fmt_real(l%mass)//' kg', &
                 'mass >= '//fmt_real(min_body_mass)//' kg')
    call require(errors, l%ixx >= min_body_inertia, pre, g, 'ixx', fmt_real(l%ixx)//u, &
                 'ixx >= '//fmt_real(min_body_inertia)//u)
    call require(errors, l%iyy >= min_body_inertia, pre, g, 'iyy', fmt_real(l%iyy)//u, &
                 'iyy >= '//fmt_real(min_body_inertia)//u)
    call require(errors, l%izz >= min_body_inertia, pre, g, 'izz', fmt_real(l%izz)//u, &
                 'izz >= '//fmt_real(min_body_inertia)//u)
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
    subroutine triangle(a, b, c, sum_name, c_name)
      real(wp), intent(in) :: a, b, c                   !! moments of inertia [kg m^2]
      character(len=*), intent(in) :: sum_name, c_name  !! names for the message [-]
      if (a + b < c*(1.0_wp - 1.0e-12_wp)) &
        call errors%add(pre//'&lander: '//sum_name//' = '//fmt_real(a + b)//' < '//c_name//' = '//fmt_real(c)//u// &
                        ' violates the triangle inequality of moments of inertia; valid: '//sum_name//' >= '//c_name)
    end subroutine triangle
  end subroutine validate_lander

  subroutine validate_engine(e, pre, errors)
    type(engine_cfg_t), intent(in) :: e            !! &engine
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    call require(errors, e%thrust >= 0.0_wp, pre, 'engine', 'thrust', fmt_real(e%thrust)//' N', 'thrust >= 0 N')
    call require(errors, e%cutoff_time >= 0.0_wp, pre, 'engine', 'cutoff_time', fmt_real(e%cutoff_time)//' s', &
                 'cutoff_time >= 0 s')
  end subroutine validate_engine

  subroutine validate_gears(g, pre, errors)
    type(gears_cfg_t), intent(in) :: g             !! &gears (resolved)
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    real(wp) :: pts(3, 6)
    character(len=1), parameter :: letters(6) = ['a', 'b', 'c', 'd', 'e', 'f']
    integer :: i, j, k
    call require(errors, g%n_gears >= 3 .and. g%n_gears <= max_gears, pre, 'gears', 'n_gears', fmt_int(g%n_gears), &
                 '3 <= n_gears <= '//fmt_int(max_gears))
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

  subroutine validate_primary(p, pre, errors)
    type(primary_cfg_t), intent(in) :: p           !! &primary_strut
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    character(len=*), parameter :: g = 'primary_strut'
    call require(errors, p%n_stages >= 1 .and. p%n_stages <= max_stages, pre, g, 'n_stages', fmt_int(p%n_stages), &
                 '1 <= n_stages <= '//fmt_int(max_stages))
    if (p%n_stages >= 1 .and. p%n_stages <= max_stages) call check_stages()
    call require(errors, p%stop_stiffness > 0.0_wp, pre, g, 'stop_stiffness', fmt_real(p%stop_stiffness)//' N/m', &
                 'stop_stiffness > 0 N/m')
    call require(errors, p%stop_damping >= 0.0_wp, pre, g, 'stop_damping', fmt_real(p%stop_damping)//' N s/m', &
                 'stop_damping >= 0 N s/m')
    call part(p%outer_mass, p%outer_cm, p%outer_inertia, 'outer')
    call part(p%inner_mass, p%inner_cm, p%inner_inertia, 'inner')
    call require(errors, p%footpad_mass >= 0.0_wp, pre, g, 'footpad_mass', fmt_real(p%footpad_mass)//' kg', &
                 'footpad_mass >= 0 kg')
    if (p%footpad_mass >= 0.0_wp .and. p%inner_mass >= 0.0_wp) &
      call require(errors, p%footpad_mass + p%inner_mass > 0.0_wp, pre, g, 'footpad_mass + inner_mass', &
                   fmt_real(p%footpad_mass + p%inner_mass)//' kg', 'footpad_mass + inner_mass > 0 kg '// &
                   '(the footpad node needs mass)')
    call require(errors, p%mu_tube >= 0.0_wp, pre, g, 'mu_tube', fmt_real(p%mu_tube), 'mu_tube >= 0')
    call require(errors, p%tube_outer_length > 0.0_wp, pre, g, 'tube_outer_length', &
                 fmt_real(p%tube_outer_length)//' m', 'tube_outer_length > 0 m')
    call require(errors, p%tube_inner_length > 0.0_wp, pre, g, 'tube_inner_length', &
                 fmt_real(p%tube_inner_length)//' m', 'tube_inner_length > 0 m')
    call require(errors, p%tube_leg_length > 0.0_wp, pre, g, 'tube_leg_length', &
                 fmt_real(p%tube_leg_length)//' m', 'tube_leg_length > 0 m')
    call require(errors, p%tube_lever >= 0.0_wp, pre, g, 'tube_lever', fmt_real(p%tube_lever)//' m', &
                 'tube_lever >= 0 m')
    if (p%tube_outer_length > 0.0_wp .and. p%tube_inner_length > 0.0_wp .and. p%tube_leg_length > 0.0_wp) &
      call require(errors, p%tube_outer_length + p%tube_inner_length > p%tube_leg_length, pre, g, &
                   'tube_leg_length', fmt_real(p%tube_leg_length)//' m', 'tube_leg_length < tube_outer_length + '// &
                   'tube_inner_length = '//fmt_real(p%tube_outer_length + p%tube_inner_length)//' m (the tubes overlap)')
  contains
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
    subroutine part(m, cm, j, which)
      real(wp), intent(in) :: m, cm, j              !! mass [kg], mass-centre distance [m], inertia [kg m^2]
      character(len=*), intent(in) :: which         !! 'outer' or 'inner' [-]
      call require(errors, m >= 0.0_wp, pre, g, which//'_mass', fmt_real(m)//' kg', which//'_mass >= 0 kg')
      call require(errors, cm >= 0.0_wp, pre, g, which//'_cm', fmt_real(cm)//' m', which//'_cm >= 0 m')
      call require(errors, j >= 0.0_wp, pre, g, which//'_inertia', fmt_real(j)//' kg m^2', which//'_inertia >= 0 kg m^2')
    end subroutine part
  end subroutine validate_primary

  subroutine validate_secondary(s, pre, errors)
    type(secondary_cfg_t), intent(in) :: s         !! &secondary_strut
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    character(len=*), parameter :: g = 'secondary_strut'
    call require(errors, s%force_lengthening > 0.0_wp, pre, g, 'force_lengthening', &
                 fmt_real(s%force_lengthening)//' N', 'force_lengthening > 0 N')
    call require(errors, s%force_shortening > 0.0_wp, pre, g, 'force_shortening', &
                 fmt_real(s%force_shortening)//' N', 'force_shortening > 0 N')
    call require(errors, s%stroke_lengthening > 0.0_wp, pre, g, 'stroke_lengthening', &
                 fmt_real(s%stroke_lengthening)//' m', 'stroke_lengthening > 0 m')
    call require(errors, s%stroke_shortening > 0.0_wp, pre, g, 'stroke_shortening', &
                 fmt_real(s%stroke_shortening)//' m', 'stroke_shortening > 0 m')
    call require(errors, s%stop_stiffness > 0.0_wp, pre, g, 'stop_stiffness', fmt_real(s%stop_stiffness)//' N/m', &
                 'stop_stiffness > 0 N/m')
    call require(errors, s%stop_damping >= 0.0_wp, pre, g, 'stop_damping', fmt_real(s%stop_damping)//' N s/m', &
                 'stop_damping >= 0 N s/m')
    call part(s%outer_mass, s%outer_cm, s%outer_inertia, 'outer')
    call part(s%inner_mass, s%inner_cm, s%inner_inertia, 'inner')
    if (s%inner_mass >= 0.0_wp) &
      call require(errors, s%inner_mass > 0.0_wp, pre, g, 'inner_mass', fmt_real(s%inner_mass)//' kg', &
                   'inner_mass > 0 kg (the sliding lower part of a secondary strut needs mass)')
  contains
    subroutine part(m, cm, j, which)
      real(wp), intent(in) :: m, cm, j              !! mass [kg], mass-centre distance [m], inertia [kg m^2]
      character(len=*), intent(in) :: which         !! 'outer' or 'inner' [-]
      call require(errors, m >= 0.0_wp, pre, g, which//'_mass', fmt_real(m)//' kg', which//'_mass >= 0 kg')
      call require(errors, cm >= 0.0_wp, pre, g, which//'_cm', fmt_real(cm)//' m', which//'_cm >= 0 m')
      call require(errors, j >= 0.0_wp, pre, g, which//'_inertia', fmt_real(j)//' kg m^2', which//'_inertia >= 0 kg m^2')
    end subroutine part
  end subroutine validate_secondary

  subroutine validate_contact_friction(c, f, pre, errors)
    type(contact_cfg_t), intent(in) :: c           !! &contact
    type(friction_cfg_t), intent(in) :: f          !! &friction
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    call require(errors, in_name_list(c%law, contact_law_names), pre, 'contact', 'law', quoted(trim(c%law)), &
                 'one of '//quoted_list(contact_law_names))
    call require(errors, c%stiffness > 0.0_wp, pre, 'contact', 'stiffness', fmt_real(c%stiffness)//' N/m^n', &
                 'stiffness > 0')
    call require(errors, c%exponent >= min_contact_exponent .and. c%exponent <= max_contact_exponent, pre, &
                 'contact', 'exponent', fmt_real(c%exponent), fmt_real(min_contact_exponent)//' <= exponent <= '// &
                 fmt_real(max_contact_exponent))
    call require(errors, c%damping >= 0.0_wp, pre, 'contact', 'damping', fmt_real(c%damping)//' N s/m', &
                 'damping >= 0 N s/m')
    call require(errors, c%damping_depth > 0.0_wp, pre, 'contact', 'damping_depth', &
                 fmt_real(c%damping_depth)//' m', 'damping_depth > 0 m')
    call require(errors, c%damping2 >= 0.0_wp, pre, 'contact', 'damping2', fmt_real(c%damping2)//' N s^2/m^2', &
                 'damping2 >= 0 N s^2/m^2')
    call require(errors, c%restitution >= 0.0_wp .and. c%restitution <= 1.0_wp, pre, 'contact', 'restitution', &
                 fmt_real(c%restitution), '0 <= restitution <= 1')
    call require(errors, c%hc_alpha >= 0.0_wp, pre, 'contact', 'hc_alpha', fmt_real(c%hc_alpha)//' s/m', &
                 'hc_alpha >= 0 s/m')
    call require(errors, c%min_impact_speed > 0.0_wp, pre, 'contact', 'min_impact_speed', &
                 fmt_real(c%min_impact_speed)//' m/s', 'min_impact_speed > 0 m/s')
    call require(errors, c%soil_stiffness > 0.0_wp, pre, 'contact', 'soil_stiffness', fmt_real(c%soil_stiffness), &
                 'soil_stiffness > 0')
    call require(errors, c%soil_exponent > 0.0_wp, pre, 'contact', 'soil_exponent', fmt_real(c%soil_exponent), &
                 'soil_exponent > 0')
    call require(errors, c%soil_drag >= 0.0_wp, pre, 'contact', 'soil_drag', fmt_real(c%soil_drag)//' kg/m', &
                 'soil_drag >= 0 kg/m')
    call require(errors, c%soil_unload_stiffness > 0.0_wp, pre, 'contact', 'soil_unload_stiffness', &
                 fmt_real(c%soil_unload_stiffness)//' N/m', 'soil_unload_stiffness > 0 N/m')
    call require(errors, in_name_list(f%law, friction_law_names), pre, 'friction', 'law', &
                 quoted(trim(f%law)), 'one of '//quoted_list(friction_law_names))
    call require(errors, f%mu_static >= 0.0_wp, pre, 'friction', 'mu_static', fmt_real(f%mu_static), &
                 'mu_static >= 0')
    call require(errors, f%mu_dynamic >= 0.0_wp, pre, 'friction', 'mu_dynamic', fmt_real(f%mu_dynamic), &
                 'mu_dynamic >= 0')
    call require(errors, f%v_static > 0.0_wp, pre, 'friction', 'v_static', fmt_real(f%v_static)//' m/s', &
                 'v_static > 0 m/s')
    call require(errors, f%v_dynamic > f%v_static, pre, 'friction', 'v_dynamic', fmt_real(f%v_dynamic)//' m/s', &
                 'v_dynamic > v_static = '//fmt_real(f%v_static)//' m/s')
    call require(errors, f%viscous >= 0.0_wp, pre, 'friction', 'viscous', fmt_real(f%viscous)//' N s/m', &
                 'viscous >= 0 N s/m')
    if (is_set(f%stribeck_speed)) &
      call require(errors, f%stribeck_speed > 0.0_wp, pre, 'friction', 'stribeck_speed', &
                   fmt_real(f%stribeck_speed)//' m/s', 'stribeck_speed > 0 m/s')
    call require(errors, f%stribeck_exponent > 0.0_wp, pre, 'friction', 'stribeck_exponent', &
                 fmt_real(f%stribeck_exponent), 'stribeck_exponent > 0')
    call require(errors, f%stribeck_decay >= 0.0_wp, pre, 'friction', 'stribeck_decay', fmt_real(f%stribeck_decay), &
                 'stribeck_decay >= 0')
    call require(errors, f%stick_stiffness > 0.0_wp, pre, 'friction', 'stick_stiffness', &
                 fmt_real(f%stick_stiffness)//' N/m', 'stick_stiffness > 0 N/m')
    call require(errors, f%stick_damping >= 0.0_wp, pre, 'friction', 'stick_damping', &
                 fmt_real(f%stick_damping)//' N s/m', 'stick_damping >= 0 N s/m')
    if (in_name_list(f%law, 'ty4, ty5, ty6')) &
      call require(errors, f%mu_dynamic <= f%mu_static, pre, 'friction', 'mu_dynamic', fmt_real(f%mu_dynamic), &
                   'mu_dynamic <= mu_static = '//fmt_real(f%mu_static)//' for law '//quoted(trim(f%law))// &
                   ' (stiction)')
  end subroutine validate_contact_friction

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
    call require(errors, s%clearance >= 0.0_wp, pre, 'initial_state', 'clearance', fmt_real(s%clearance)//' m', &
                 'clearance >= 0 m')
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

  !> Determinant of a 3 x 3 matrix.
  pure function det3(a) result(d)
    real(wp), intent(in) :: a(3, 3)  !! matrix [any unit]
    real(wp) :: d                    !! determinant [unit^3]
    d = a(1, 1)*(a(2, 2)*a(3, 3) - a(2, 3)*a(3, 2)) - a(1, 2)*(a(2, 1)*a(3, 3) - a(2, 3)*a(3, 1)) + &
        a(1, 3)*(a(2, 1)*a(3, 2) - a(2, 2)*a(3, 1))
  end function det3

  ! ================================================================ deck writing helpers

  !> Append a line to text.
  pure subroutine put(text, line)
    character(len=:), allocatable, intent(inout) :: text  !! deck being built [-]
    character(len=*), intent(in) :: line                  !! line without line end [-]
    text = text//line//new_line('a')
  end subroutine put

  !> Append the opening of group ig, preceded by a blank line.
  pure subroutine group_begin(text, ig)
    character(len=:), allocatable, intent(inout) :: text  !! deck being built [-]
    integer, intent(in) :: ig                             !! group index [-]
    call put(text, '')
    call put(text, '&'//trim(group_names(ig)))
  end subroutine group_begin

  !> Append "  name = value   ! meaning [unit]".
  pure subroutine put_var(text, ig, name, value)
    character(len=:), allocatable, intent(inout) :: text  !! deck being built [-]
    integer, intent(in) :: ig                             !! group index [-]
    character(len=*), intent(in) :: name                  !! variable (with subscript) [-]
    character(len=*), intent(in) :: value                 !! value text [-]
    character(len=:), allocatable :: line, base
    integer :: iv, p
    base = name
    p = index(name, '(')
    if (p > 0) base = name(1:p - 1)
    iv = var_index(ig, base)
    line = '  '//name//' = '//value
    if (iv > 0) then
      if (len(line) < comment_col - 1) line = line//repeat(' ', comment_col - 1 - len(line))
      line = line//' ! '//trim(all_vars(iv)%meaning)
      if (len_trim(all_vars(iv)%unit) > 0 .and. all_vars(iv)%unit /= '-') line = line//' ['//trim(all_vars(iv)%unit)//']'
    end if
    call put(text, line)
  end subroutine put_var

  !> Append a vector that may be given only in part (unset elements are not written): the whole
  !! vector when all is set, name(1:k) for a leading run, element by element otherwise. col > 0
  !! writes column col of a 2-D array (name(:, col), name(j, col)).
  pure subroutine put_partial(text, ig, name, x, col, angle)
    character(len=:), allocatable, intent(inout) :: text  !! deck being built [-]
    integer, intent(in) :: ig                             !! group index [-]
    character(len=*), intent(in) :: name                  !! variable name [-]
    real(wp), intent(in) :: x(:)                          !! values [m or rad]
    integer, intent(in) :: col                            !! column of a 2-D array, 0 for a vector [-]
    logical, intent(in) :: angle                          !! x is an angle (written in degrees) [-]
    integer :: j, k
    character(len=:), allocatable :: c
    c = ''
    if (col > 0) c = ', '//fmt_int(col)
    if (all(is_set(x))) then
      if (col > 0) then
        call put_var(text, ig, name//'(:'//c//')', vals(x))
      else
        call put_var(text, ig, name, vals(x))
      end if
      return
    end if
    if (.not. any(is_set(x))) then
      if (col == 0 .and. name == 'position') &
        call put(text, '  ! position not given: the lowest footpad starts clearance above its surface')
      return
    end if
    k = 0
    do while (k < size(x))
      if (.not. is_set(x(k + 1))) exit
      k = k + 1
    end do
    if (k > 0 .and. .not. any(is_set(x(k + 1:)))) then
      call put_var(text, ig, name//'(1:'//fmt_int(k)//c//')', vals(x(1:k)))
      return
    end if
    do j = 1, size(x)
      if (is_set(x(j))) call put_var(text, ig, name//'('//fmt_int(j)//c//')', vals(x(j:j)))
    end do
  contains
    pure function vals(y) result(s)
      real(wp), intent(in) :: y(:)           !! values [m or rad]
      character(len=:), allocatable :: s     !! deck text [-]
      if (angle) then
        s = fmt_angles(y)
      else
        s = fmt_reals(y)
      end if
    end function vals
  end subroutine put_partial

  !> Shortest decimal text that reads back as exactly x. Reading back is monotone in the number
  !! of digits d (the d+1-digit rounding is at least as close to x as the d-digit one), so after
  !! the short texts (d <= 3, the usual deck values) the shortest d is found by bisection: a
  !! random 17-digit value costs 7 conversions instead of 17 (validation formats every value,
  !! once per campaign case).
  pure function fmt_real(x) result(s)
    real(wp), intent(in) :: x              !! value [any unit]
    character(len=:), allocatable :: s     !! e.g. '5.0e-6', '0.475', '16000.0' [-]
    integer :: d, lo, hi, mid, d_lo
    logical :: whole
    call whole_number_text(x, s, whole)
    if (whole) return
    d_lo = fewest_digits(x)
    do d = d_lo, short_digits
      if (real_ok(d)) then
        s = pretty(es_text(x, d))
        return
      end if
    end do
    lo = max(short_digits, d_lo - 1)   ! fails
    hi = 17                            ! 17 digits always read back exactly
    do while (hi - lo > 1)
      mid = (lo + hi)/2
      if (real_ok(mid)) then
        hi = mid
      else
        lo = mid
      end if
    end do
    s = pretty(es_text(x, hi))
  contains
    pure logical function real_ok(dd)
      integer, intent(in) :: dd   !! significant digits [-]
      real(wp) :: y
      character(len=40) :: b
      b = es_text(x, dd)
      read (b, *) y
      real_ok = same_real(x, y)
    end function real_ok
  end function fmt_real

  !> A lower bound of the digits fmt_real and fmt_angle can need, found with arithmetic only: the
  !! fewest significant digits d for which x lies within a relative 1e-12 of a d-digit decimal.
  !! A text that converts back to x (or, for fmt_angle, to an angle within a few ulps of x*rad2deg)
  !! lies within a relative 1e-15 of x, so no shorter text can work. 1 when x is zero or too
  !! large or small for exact powers of ten.
  pure function fewest_digits(x) result(d)
    real(wp), intent(in) :: x   !! value [any unit]
    integer :: d                !! digits, 1..17 [-]
    real(wp) :: a, r
    integer :: e, k, dd
    d = 1
    a = abs(x)
    if (.not. (a >= 1.0e-250_wp .and. a <= 1.0e250_wp)) return
    e = floor(log10(a))
    if (e > -22 .and. e < 22) then
      if (a < 10.0_wp**e) e = e - 1   ! never too large: a too small e only makes the test milder
    end if
    do dd = 1, 17
      k = dd - 1 - e                  ! a*10^k has dd digits before the point
      if (abs(k) > 22) return         ! 10^|k| not exact: no bound (d = 1)
      if (k >= 0) then
        r = a*10.0_wp**k
      else
        r = a/10.0_wp**(-k)
      end if
      if (abs(r - anint(r)) <= 1.0e-12_wp*r) then
        d = dd
        return
      end if
    end do
    d = 17
  end function fewest_digits

  !> The text fmt_real gives for a whole number 1 <= |x| < 1e7 or a positive zero ('16000.0',
  !! '-3.0', '0.0'), made without formatted I/O; .false. for any other x.
  pure subroutine whole_number_text(x, s, done)
    real(wp), intent(in) :: x                        !! value [any unit]
    character(len=:), allocatable, intent(inout) :: s  !! text when done [-]
    logical, intent(out) :: done                     !! x was such a number [-]
    integer :: n
    done = .false.
    if (same_real(x, 0.0_wp)) then
      s = '0.0'
      done = .true.
      return
    end if
    if (.not. (abs(x) >= 1.0_wp .and. abs(x) < 1.0e7_wp)) return
    if (.not. same_real(aint(x), x)) return
    n = nint(abs(x))
    s = '.0'
    do
      s = achar(iachar('0') + mod(n, 10))//s
      n = n/10
      if (n == 0) exit
    end do
    if (x < 0.0_wp) s = '-'//s
    done = .true.
  end subroutine whole_number_text

  !> Shortest decimal degrees that deg_to_rad converts back to exactly x: the candidates are
  !! x*rad2deg and its neighbours (+-1, +-2 ulp), tried digit count by digit count, the first
  !! that works wins. As in fmt_real, short texts (d <= 3) are tried one by one and longer ones
  !! by bisection over d, so the text always converts back to x; it is the shortest one except
  !! where a non-exact neighbour happens to work at fewer digits than the exact candidates.
  pure function fmt_angle(x) result(s)
    real(wp), intent(in) :: x              !! angle [rad]
    character(len=:), allocatable :: s     !! angle in degrees [-]
    real(wp) :: cand(5)
    integer :: d, k, lo, hi, mid, d_lo
    cand(1) = x*rad2deg
    if (.not. abs(x) >= tiny(1.0_wp)) then   ! zero (or subnormal): no neighbours to try
      s = fmt_real(cand(1))
      return
    end if
    cand(2) = nearest(cand(1), 1.0_wp)
    cand(3) = nearest(cand(1), -1.0_wp)
    cand(4) = nearest(cand(2), 1.0_wp)
    cand(5) = nearest(cand(3), -1.0_wp)
    d_lo = fewest_digits(cand(1))
    do d = d_lo, short_digits
      k = first_ok(d)
      if (k > 0) then
        s = pretty(es_text(cand(k), d))
        return
      end if
    end do
    if (first_ok(17) == 0) then
      s = pretty(es_text(cand(1), 17))
      return
    end if
    lo = max(short_digits, d_lo - 1)
    hi = 17
    do while (hi - lo > 1)
      mid = (lo + hi)/2
      if (first_ok(mid) > 0) then
        hi = mid
      else
        lo = mid
      end if
    end do
    s = pretty(es_text(cand(first_ok(hi)), hi))
  contains
    !> First candidate whose dd-digit text converts back to x (0: none).
    pure integer function first_ok(dd)
      integer, intent(in) :: dd   !! significant digits [-]
      real(wp) :: y
      character(len=40) :: b
      integer :: kk
      first_ok = 0
      do kk = 1, size(cand)
        b = es_text(cand(kk), dd)
        read (b, *) y
        if (same_real(deg_to_rad(y), x)) then
          first_ok = kk
          return
        end if
      end do
    end function first_ok
  end function fmt_angle

  !> Values joined with ', ', runs of four or more equal values written as r*value.
  pure function fmt_reals(x) result(s)
    real(wp), intent(in) :: x(:)           !! values [any unit]
    character(len=:), allocatable :: s     !! deck text [-]
    integer :: i
    character(len=40) :: items(size(x))
    do i = 1, size(x)
      items(i) = fmt_real(x(i))
    end do
    s = join_runs(items)
  end function fmt_reals

  !> Angles [rad] in degrees, joined as fmt_reals does.
  pure function fmt_angles(x) result(s)
    real(wp), intent(in) :: x(:)           !! angles [rad]
    character(len=:), allocatable :: s     !! deck text in degrees [-]
    integer :: i
    character(len=40) :: items(size(x))
    do i = 1, size(x)
      items(i) = fmt_angle(x(i))
    end do
    s = join_runs(items)
  end function fmt_angles

  pure function join_runs(items) result(s)
    character(len=*), intent(in) :: items(:)  !! formatted values [-]
    character(len=:), allocatable :: s        !! joined text [-]
    integer :: i, j
    s = ''
    i = 1
    do while (i <= size(items))
      j = i
      do while (j < size(items))
        if (items(j + 1) /= items(i)) exit
        j = j + 1
      end do
      if (len(s) > 0) s = s//', '
      if (j - i + 1 >= 4) then
        s = s//fmt_int(j - i + 1)//'*'//trim(items(i))
        i = j + 1
      else
        s = s//trim(items(i))
        i = i + 1
      end if
    end do
  end function join_runs

  !> x in ES format with d significant digits and a 3-digit exponent.
  pure function es_text(x, d) result(buf)
    real(wp), intent(in) :: x     !! value [any unit]
    integer, intent(in) :: d      !! significant digits, 1..17 [-]
    character(len=40) :: buf      !! e.g. ' 5.0E-006' [-]
    write (buf, es_formats(min(max(d, 1), 17))) x
    buf = adjustl(buf)
  end function es_text

  !> Rewrite ES text "m.mmmE+eee" as plain decimal for moderate exponents, else "m.mmme<exp>".
  !! Pure string manipulation, so the value is unchanged.
  pure function pretty(es) result(s)
    character(len=*), intent(in) :: es     !! ES text from es_text [-]
    character(len=:), allocatable :: s     !! e.g. '16000.0', '0.475', '5.0e-6' [-]
    character(len=:), allocatable :: sgn, digits, intpart, frac
    integer :: pe, expo, p
    s = trim(adjustl(es))
    pe = scan(s, 'Ee')
    if (pe == 0) return
    read (s(pe + 1:), *) expo
    sgn = ''
    if (s(1:1) == '-') sgn = '-'
    digits = s(len(sgn) + 1:pe - 1)
    p = index(digits, '.')
    digits = digits(1:p - 1)//digits(p + 1:)
    ! strip trailing zeros but keep one digit
    do while (len(digits) > 1)
      if (digits(len(digits):len(digits)) /= '0') exit
      digits = digits(1:len(digits) - 1)
    end do
    if (verify(digits, '0') == 0) then
      s = sgn//'0.0'
      return
    end if
    if (expo >= 0 .and. expo <= 6) then
      if (len(digits) > expo + 1) then
        intpart = digits(1:expo + 1)
        frac = digits(expo + 2:)
      else
        intpart = digits//repeat('0', expo + 1 - len(digits))
        frac = '0'
      end if
      s = sgn//intpart//'.'//frac
    else if (expo < 0 .and. expo >= -4) then
      s = sgn//'0.'//repeat('0', -expo - 1)//digits
    else
      frac = digits(2:)
      if (len(frac) == 0) frac = '0'
      s = sgn//digits(1:1)//'.'//frac//'e'//fmt_int(expo)
    end if
  end function pretty

  !> Logical as namelist text.
  pure function fmt_logical(l) result(s)
    logical, intent(in) :: l               !! value [-]
    character(len=:), allocatable :: s     !! '.true.' or '.false.' [-]
    if (l) then
      s = '.true.'
    else
      s = '.false.'
    end if
  end function fmt_logical

  !> Exact equality of two reals (bit patterns), without a floating-point comparison.
  elemental function same_real(a, b) result(same)
    real(wp), intent(in) :: a, b  !! values [any unit]
    logical :: same               !! identical [-]
    same = transfer(a, 0_int64) == transfer(b, 0_int64)
  end function same_real

  !> Degrees to radians: the one conversion used for every angle read from a deck.
  elemental function deg_to_rad(x) result(r)
    real(wp), intent(in) :: x  !! angle [deg] (or rate [deg/s])
    real(wp) :: r              !! angle [rad] (or rate [rad/s])
    r = x*deg2rad
  end function deg_to_rad

  ! ================================================================ text helpers

  !> "deck:line: " (or "line N: " without a deck name) for position p.
  pure function loc(deck_name, work, p) result(s)
    character(len=*), intent(in) :: deck_name  !! deck name [-]
    character(len=*), intent(in) :: work       !! deck text [-]
    integer, intent(in) :: p                   !! position [-]
    character(len=:), allocatable :: s         !! location prefix [-]
    if (len_trim(deck_name) > 0) then
      s = trim(deck_name)//':'//fmt_int(line_of(work, p))//': '
    else
      s = 'line '//fmt_int(line_of(work, p))//': '
    end if
  end function loc

  !> "deck: " or '' for messages about resolved values.
  pure function msg_prefix(inp) result(s)
    type(landyn_input_t), intent(in) :: inp  !! input [-]
    character(len=:), allocatable :: s       !! prefix [-]
    s = ''
    if (allocated(inp%deck_name)) then
      if (len_trim(inp%deck_name) > 0) s = trim(inp%deck_name)//': '
    end if
  end function msg_prefix

  !> Compact excerpt of deck text for messages: blanks collapsed, trailing commas dropped, shortened.
  pure function snippet(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=:), allocatable :: s  !! excerpt [-]
    s = snippet_raw(t)
    if (len(s) > snippet_len) s = s(1:snippet_len - 3)//'...'
  end function snippet

  pure function snippet_raw(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=:), allocatable :: s  !! text with blanks collapsed and trailing commas dropped [-]
    integer :: i
    logical :: prev_blank
    s = ''
    prev_blank = .true.
    do i = 1, len(t)
      if (is_blank(t(i:i))) then
        if (.not. prev_blank) s = s//' '
        prev_blank = .true.
      else
        s = s//t(i:i)
        prev_blank = .false.
      end if
    end do
    do while (len(s) > 0)
      if (s(len(s):len(s)) /= ' ' .and. s(len(s):len(s)) /= ',') exit
      s = s(1:len(s) - 1)
    end do
    if (len(s) > 4*snippet_len) s = s(1:4*snippet_len - 3)//'...'
  end function snippet_raw

  ! ================================================================ names and hints

  pure function group_index(name) result(ig)
    character(len=*), intent(in) :: name  !! lower-case group name [-]
    integer :: ig                         !! index, 0 if unknown [-]
    do ig = 1, n_groups
      if (trim(group_names(ig)) == name) return
    end do
    ig = 0
  end function group_index

  pure function var_index(ig, name) result(iv)
    integer, intent(in) :: ig             !! group index [-]
    character(len=*), intent(in) :: name  !! lower-case variable name [-]
    integer :: iv                         !! index into all_vars, 0 if not in group ig [-]
    do iv = 1, size(all_vars)
      if (all_vars(iv)%group == ig .and. trim(all_vars(iv)%name) == name) return
    end do
    iv = 0
  end function var_index

  pure function unit_text(iv) result(s)
    integer, intent(in) :: iv             !! index into all_vars [-]
    character(len=:), allocatable :: s    !! ' [unit]' or '' [-]
    s = ''
    if (len_trim(all_vars(iv)%unit) > 0 .and. all_vars(iv)%unit /= '-') s = ' ['//trim(all_vars(iv)%unit)//']'
  end function unit_text

  pure function group_list() result(s)
    character(len=:), allocatable :: s  !! "&simulation, &lander, ..." [-]
    integer :: ig
    s = ''
    do ig = 1, n_groups
      if (ig > 1) s = s//', '
      s = s//'&'//trim(group_names(ig))
    end do
  end function group_list

  !> "; did you mean '&xxx'?" for a close group name, else ''.
  pure function group_hint(name) result(s)
    character(len=*), intent(in) :: name  !! unknown group name [-]
    character(len=:), allocatable :: s    !! hint [-]
    integer :: ig, d, best, best_d
    best = 0
    best_d = huge(1)
    do ig = 1, n_groups
      d = edit_distance(name, trim(group_names(ig)))
      if (d < best_d) then
        best_d = d
        best = ig
      end if
    end do
    s = ''
    if (best > 0 .and. best_d <= max(2, len(name)/3)) s = " (did you mean '&"//trim(group_names(best))//"'?)"
  end function group_hint

  !> "; did you mean 'xxx'?" for a close name in the group, or where the variable belongs, else ''.
  pure function var_hint(ig, name) result(s)
    integer, intent(in) :: ig             !! group index [-]
    character(len=*), intent(in) :: name  !! unknown variable name [-]
    character(len=:), allocatable :: s    !! hint [-]
    integer :: iv, d, best, best_d
    s = ''
    do iv = 1, size(all_vars)
      if (all_vars(iv)%group /= ig .and. trim(all_vars(iv)%name) == name) then
        s = "; '"//name//"' belongs to &"//trim(group_names(all_vars(iv)%group))
        return
      end if
    end do
    best = 0
    best_d = huge(1)
    do iv = 1, size(all_vars)
      if (all_vars(iv)%group /= ig) cycle
      d = edit_distance(name, trim(all_vars(iv)%name))
      if (d < best_d) then
        best_d = d
        best = iv
      end if
    end do
    if (best > 0 .and. best_d <= max(2, len(name)/3)) s = "; did you mean '"//trim(all_vars(best)%name)//"'?"
  end function var_hint

end module landyn_input
