!> The input registry: every variable of a run deck declared once, with its group, type, shape,
!! default, deck unit, what it takes, its meaning, whether it is an angle (degrees in decks, radians
!! in landyn_input_t), its valid range or list of choices, and whether a campaign may vary it.
!!
!! From this table come the per-group types of landyn_input_t with their defaults and the
!! entry-to-component accessor (landyn_input_groups and landyn_input_access, written into the build
!! tree by the generator src/input/codegen/landyn_input_codegen.f90), the deck reader
!! (landyn_input_reader: names, hints, value reading), the resolved-deck writer
!! (landyn_input_writer), the generic range checks (landyn_input_validate), the campaign's table of
!! variable inputs (landyn_campaign_target) and the variable tables of docs/input/*.md
!! (landyn_input_docs).
!!
!! To add a variable: one entry here (its `default` is the component initialiser, in storage
!! units); then rewrite the docs pages (target input_docs) and add a reader test.
module landyn_input_registry
  use landyn_kinds, only: max_gears
  use landyn_input_limits, only: max_stages
  use landyn_strings, only: edit_distance
  implicit none
  private

  public :: input_var_t, input_vars, n_groups, group_names, group_components, group_docs, k_real, k_int, k_logical, k_string
  public :: k_int64
  public :: g_simulation, g_contact
  public :: group_index, var_index, unit_text, group_list, group_hint, var_hint, range_text, closest_name
  public :: table_group_index, table_var_index, entry_unit_text, table_group_list, table_group_hint, table_var_hint

  integer, parameter :: g_simulation = 1, g_lander = 2, g_engine = 3, g_gears = 4, g_primary = 5, &
                        g_secondary = 6, g_contact = 7, g_friction = 8, g_terrain = 9, g_initial = 10, &
                        g_output = 11, n_groups = 11  !! group indices [-]
  !> Namelist group names, in deck order.
  character(len=*), parameter :: group_names(n_groups) = [character(len=15) :: &
    'simulation', 'lander', 'engine', 'gears', 'primary_strut', 'secondary_strut', 'contact', &
    'friction', 'terrain', 'initial_state', 'output']
  !> Component of landyn_input_t holding each group; its type is <component>_cfg_t.
  character(len=*), parameter :: group_components(n_groups) = [character(len=10) :: &
    'simulation', 'lander', 'engine', 'gears', 'primary', 'secondary', 'contact', &
    'friction', 'terrain', 'initial', 'output']
  !> The doc comment of each group's type (FORD; the generator wraps it).
  character(len=*), parameter :: group_docs(n_groups) = [character(len=232) :: &
    '&simulation: time stepping and termination.', &
    '&lander: rigid body (total mass, inertia about the mass centre in lander axes).', &
    '&engine: optional descent-engine thrust.', &
    '&gears: number of gears and their hard points in the lander frame. Column i of each point array is '// &
      'gear i. Columns the deck does not give are gear 1''s points rotated about the lander z axis by rotation(i).', &
    '&primary_strut: multi-stage honeycomb, part masses and tube friction (eqs. 23-26, landyn_tube_friction).', &
    '&secondary_strut: two-direction honeycomb (levels named by the motion they resist) and part masses.', &
    '&contact: footpad-ground normal law (eqs. 17-18).', &
    '&friction: footpad-ground friction.', &
    '&terrain: one plane per footpad (column/entry i is footpad i). Plane i passes through the global point '// &
      '(0, 0, -height(i)) and rises with slope(i) toward the horizontal direction at azimuth slope_direction(i).', &
    '&initial_state: state at t = 0.', &
    '&output: result file and sampling.']

  integer, parameter :: k_real = 1, k_int = 2, k_logical = 3, k_string = 4  !! storage classes [-]
  integer, parameter :: k_int64 = 5   !! 64-bit integer scalar (campaign seeds; no run-deck variable has it) [-]

  !> One run-deck variable.
  type :: input_var_t
    integer :: group = 0                !! group index [-]
    character(len=24) :: name = ''      !! namelist variable name [-]
    integer :: kind = k_real            !! storage class: k_real, k_int, k_logical, k_string or k_int64 [-]
    character(len=56) :: default = ''   !! the component's Fortran initialiser, in storage units (radians) [-]
    character(len=16) :: length = ''    !! k_string only: the component's length (a number or a limit's name) [-]
    integer :: n1 = 0                   !! first extent (0: scalar) [-]
    integer :: n2 = 0                   !! second extent (0: rank < 2) [-]
    character(len=10) :: unit = ''      !! unit in the deck ('' if none, '-' dimensionless) [-]
    character(len=56) :: takes = ''     !! what the variable takes (messages, docs) [-]
    character(len=72) :: meaning = ''   !! one-line meaning (comment in written decks, docs) [-]
    logical :: angle = .false.          !! degrees in decks, radians in landyn_input_t [-]
    logical :: partial = .false.        !! may be given in part; unset elements are not written [-]
    character(len=2) :: lo_op = ''      !! lower bound: '>', '>=' or '' (none) [-]
    character(len=8) :: lo = ''         !! lower bound as written in messages [deck unit]
    character(len=2) :: hi_op = ''      !! upper bound: '<', '<=' or '' (none) [-]
    character(len=8) :: hi = ''         !! upper bound as written in messages [deck unit]
    integer :: msg_unit = 1             !! unit in range messages: 1 value and range, 2 value only, 0 none [-]
    character(len=16) :: choices = ''   !! registry of the valid names ('integrator', 'contact_law', 'friction_law',
                                        !! 'buffer_law', 'gear_type'; landyn_input_choices) [-]
    character(len=96) :: fixed = ''     !! why a campaign cannot vary it ('' : derived from the kind) [-]
    character(len=248) :: doc = ''      !! meaning as docs/input writes it (markdown) [-]
    character(len=136) :: doc_valid = '' !! valid range as docs/input writes it, when more than the range [-]
    character(len=48) :: doc_default = '' !! default as docs/input writes it, when derived at resolve time [-]
  end type input_var_t

  !> The registry entries of &simulation.
  type(input_var_t), parameter :: vars_simulation(*) = [ &
    input_var_t(g_simulation, 'title', k_string, default="'LANDYN demonstration lander, load case LC-1'", &
      length='256', takes='a quoted character string', meaning='run title', &
      doc='run title, stored in the result file'), &
    input_var_t(g_simulation, 'integrator', k_string, default="'adaptive'", &
      length='name_len', takes='a quoted character string', &
      meaning="time integrator, one of those built in (the default 'adaptive', 'fixed')", choices='integrator', &
      doc='time integrator ([theory](../theory.md#time-integrators)): `''adaptive''`, steps from `tolerance`, '// &
      'events located; `''fixed''`, the paper''s scheme with step `dt`; `''imex''` (an experiment), '// &
      '`''adaptive''` with linearly implicit footpad contact'), &
    input_var_t(g_simulation, 'dt', k_real, default="5.0e-6_wp", unit='s', takes='a real number', &
      meaning='fixed: the time step; adaptive: the first step tried', lo_op='>', lo='0', &
      doc='`''fixed''`: the integration time step (the paper used 5e-6 s); `''adaptive''`: the first step tried', &
      doc_valid='`0 < dt <= t_end`, and `t_end/dt <= 1e9` (at most 10⁹ steps)'), &
    input_var_t(g_simulation, 'tolerance', k_real, default="1.0e-7_wp", unit='m/s', takes='a real number', &
      meaning='adaptive: local velocity error allowed per step', lo_op='>=', lo='1.0e-20', &
      doc='`''adaptive''`: local velocity error allowed per step (body velocities, angular ones times the lander'// &
      '''s size, strut stroke rates, leg angle rates times the strut length)', &
      doc_valid='`>= 1e-20` (smaller ones are far below the round-off of any velocity)'), &
    input_var_t(g_simulation, 'dt_max', k_real, default="1.0e-3_wp", &
      unit='s', takes='a real number', meaning='adaptive: largest step', &
      doc='`''adaptive''`: largest step (also never longer than `&output interval`)', doc_valid='`>= dt_min`'), &
    input_var_t(g_simulation, 'dt_min', k_real, default="1.0e-9_wp", &
      unit='s', takes='a real number', meaning='adaptive: smallest step', &
      lo_op='>', lo='0', &
      doc='`''adaptive''`: smallest step, reached only when a step''s constraint correction fails or the state bec'// &
      'omes non-finite; below it the run stops with exit status 3'), &
    input_var_t(g_simulation, 'event_resolution', k_real, default="1.0e-6_wp", unit='s', takes='a real number', &
      meaning='adaptive: events located to within this time', lo_op='>', lo='0', &
      doc='`''adaptive''`: events (a strut locking, crushing or freed; a footpad touching down or lifting off; a s'// &
      'tick state changing; the tilt passing `tipover_angle`) are located to within this time; a discontinuity is '// &
      'crossed in one step of this length', &
      doc_valid='`dt_min <= event_resolution <= dt_max`, and `t_end/event_resolution <= 1e9`'), &
    input_var_t(g_simulation, 't_end', k_real, default="1.0_wp", &
      unit='s', takes='a real number', meaning='end time', lo_op='>', lo='0', &
      doc='end time of the run', doc_valid='`0 < t_end <= 3600`'), &
    input_var_t(g_simulation, 'gravity', k_real, default="1.62_wp", unit='m/s^2', takes='a real number', &
      meaning='gravitational acceleration, along global +z (down)', lo_op='>=', lo='0', &
      doc='gravitational acceleration, along global +z (down); lunar by default'), &
    input_var_t(g_simulation, 'stop_at_rest', k_logical, default=".true.", takes='a logical (.true. or .false.)', &
      meaning='end the run early once at rest', doc='end the run early once the lander has come to rest'), &
    input_var_t(g_simulation, 'rest_speed', k_real, default="1.0e-3_wp", unit='m/s', takes='a real number', &
      meaning='speed below which the lander is at rest', lo_op='>', lo='0', &
      doc='speed below which the lander counts as at rest: the body, the rotation at the footpads, every footpad '// &
      'and every strut stroke rate (docs/output.md, Outcome)'), &
    input_var_t(g_simulation, 'rest_time', k_real, default="0.1_wp", unit='s', takes='a real number', &
      meaning='time every speed must stay below rest_speed', lo_op='>=', lo='0', &
      doc='time every speed must stay below `rest_speed` to count as at rest; longer than one period of the '// &
      'settled lander''s vibration on the soil (docs/output.md, Outcome)'), &
    input_var_t(g_simulation, 'tipover_angle', k_real, default="45.0_wp*pi/180.0_wp", unit='deg', takes='a real number', &
      meaning='tilt of lander z from vertical counted as tip-over', angle=.true., lo_op='>', lo='0', &
      hi_op='<=', hi='180', doc='tilt of the lander z axis from the vertical that counts as tipped over'), &
    input_var_t(g_simulation, 'constraint_tol', k_real, default="1.0e-10_wp", unit='m, m/s', takes='a real number', &
      meaning='tolerance of the constraint correction', lo_op='>', lo='0', msg_unit=0, &
      doc='tolerance of the constraint-violation correction'), &
    input_var_t(g_simulation, 'frame_field_passes', k_int, default="0", takes='an integer', &
      meaning='gear passes per force evaluation (frame field from the previous pass)', &
      lo_op='>=', lo='0', hi_op='<=', hi='5', &
      doc='1: the legs'' frame field is the last evaluation''s body acceleration (the paper''s scheme); '// &
      '2 to 5: again in the previous pass''s field; 0: ''adaptive'' predicts it, a 2nd pass where a lock '// &
      'changed; 1 otherwise ([theory](../theory.md#frame-field))'), &
    input_var_t(g_simulation, 'max_correction_iter', k_int, default="20", takes='an integer', &
      meaning='iteration cap of the constraint correction', lo_op='>=', lo='1', doc='iteration cap of the correction'), &
    input_var_t(g_simulation, 'max_constraint_drift', k_real, default="1.0e-6_wp", unit='m', takes='a real number', &
      meaning='violation above this means dt is too large', lo_op='>', lo='0', &
      doc='a constraint violation above this before correction means `dt` is too large')]
  !> The registry entries of &lander.
  type(input_var_t), parameter :: vars_lander(*) = [ &
    input_var_t(g_lander, 'mass', k_real, default="1.6e4_wp", unit='kg', takes='a real number', &
      meaning='total lander mass, legs included', lo_op='>=', lo='1.0', doc='total lander mass, legs included', &
      doc_valid='`>= 1` (and the legs below 50 % of it: [run health](../health.md))'), &
    input_var_t(g_lander, 'ixx', k_real, default="8.18e4_wp", unit='kg m^2', takes='a real number', &
      meaning='moment of inertia about x_L through the mass centre', lo_op='>=', lo='0.001', &
      doc='moment of inertia about x_L through the mass centre', doc_valid='`>= 1e-3`, see below'), &
    input_var_t(g_lander, 'iyy', k_real, default="8.18e4_wp", unit='kg m^2', takes='a real number', &
      meaning='moment of inertia about y_L through the mass centre', lo_op='>=', lo='0.001', &
      doc='moment of inertia about y_L through the mass centre', doc_valid='`>= 1e-3`, see below'), &
    input_var_t(g_lander, 'izz', k_real, default="8.17e4_wp", unit='kg m^2', takes='a real number', &
      meaning='moment of inertia about z_L through the mass centre', lo_op='>=', lo='0.001', &
      doc='moment of inertia about z_L through the mass centre', doc_valid='`>= 1e-3`, see below'), &
    input_var_t(g_lander, 'ixy', k_real, default="0.0_wp", unit='kg m^2', takes='a real number', &
      meaning='product of inertia integral(x y dm); tensor element -ixy', &
      doc='product of inertia ∫ x y dm (the tensor element is −ixy)', doc_valid='see below'), &
    input_var_t(g_lander, 'ixz', k_real, default="0.0_wp", unit='kg m^2', takes='a real number', &
      meaning='product of inertia integral(x z dm); tensor element -ixz', &
      doc='product of inertia ∫ x z dm (tensor element −ixz)', doc_valid='see below'), &
    input_var_t(g_lander, 'iyz', k_real, default="0.0_wp", unit='kg m^2', takes='a real number', &
      meaning='product of inertia integral(y z dm); tensor element -iyz', &
      doc='product of inertia ∫ y z dm (tensor element −iyz)', doc_valid='see below'), &
    input_var_t(g_lander, 'mass_centre', k_real, default="[0.0_wp, 0.0_wp, -3.818_wp]", &
      n1=3, unit='m', takes='3 real numbers x, y, z', &
      meaning='mass centre in the lander frame', doc='mass centre in the lander frame (z down: −3.818 is above O_L)')]
  !> The registry entries of &engine.
  type(input_var_t), parameter :: vars_engine(*) = [ &
    input_var_t(g_engine, 'thrust', k_real, default="0.0_wp", unit='N', takes='a real number', meaning='thrust magnitude', &
      lo_op='>=', lo='0', doc='thrust magnitude'), &
    input_var_t(g_engine, 'direction', k_real, default="[0.0_wp, 0.0_wp, -1.0_wp]", &
      n1=3, unit='-', takes='3 real numbers x, y, z', &
      meaning='thrust direction, lander frame (normalised)', &
      doc='direction of the thrust force in the lander frame; normalised on input (−z is upward, z being down)', &
      doc_valid='non-zero length'), &
    input_var_t(g_engine, 'point', k_real, default="[0.0_wp, 0.0_wp, -3.818_wp]", &
      n1=3, unit='m', takes='3 real numbers x, y, z', &
      meaning='point of application, lander frame', doc='point of application in the lander frame'), &
    input_var_t(g_engine, 'cutoff_time', k_real, default="0.0_wp", unit='s', takes='a real number', &
      meaning='thrust acts for 0 <= t < cutoff_time', lo_op='>=', lo='0', &
      doc='the thrust acts for `0 <= t < cutoff_time`')]
  !> The registry entries of &gears.
  type(input_var_t), parameter :: vars_gears(*) = [ &
    input_var_t(g_gears, 'gear_type', k_string, default="'tripod'", &
      length='name_len', takes='a quoted character string', meaning='type of every landing gear', &
      choices='gear_type', doc='type of every landing gear (case-insensitive; the gear types above)'), &
    input_var_t(g_gears, 'n_gears', k_int, default="4", &
      takes='an integer', meaning='number of landing gears', lo_op='>=', lo='3', &
      hi_op='<=', hi='8', fixed='the summary has one column per gear and strut, so every case needs the same gears', &
      doc='number of landing gears (legs)'), &
    input_var_t(g_gears, 'rotation', k_real, default="unset_real", &
      n1=max_gears, unit='deg', takes='up to 8 real numbers, one per gear', &
      meaning='rotation of gear i from gear 1 about lander z', angle=.true., partial=.true., &
      doc='rotation of gear i from gear 1 about the lander z axis (right-handed)', doc_valid='`rotation(1) = 0`', &
      doc_default='`(i-1)*360/n_gears`'), &
    input_var_t(g_gears, 'point_a', k_real, default="unset_real", n1=3, n2=max_gears, unit='m', &
      takes='a 3 x 8 real array; point_a(:, i) = x, y, z', meaning='primary strut upper universal joint', &
      partial=.true., doc='primary strut upper universal joint', &
      doc_valid='distinct points, every coordinate within ±100 m (all six points)', &
      doc_default='gear 1: `3.89, 0, -2.18`'), &
    input_var_t(g_gears, 'point_b', k_real, default="unset_real", n1=3, n2=max_gears, unit='m', &
      takes='a 3 x 8 real array; point_b(:, i) = x, y, z', meaning='left secondary upper universal joint', &
      partial=.true., doc='left secondary strut upper universal joint (left = toward gear i+1)', &
      doc_valid='distinct points', doc_default='gear 1: `3.37, 1.23, -1.01`'), &
    input_var_t(g_gears, 'point_c', k_real, default="unset_real", n1=3, n2=max_gears, unit='m', &
      takes='a 3 x 8 real array; point_c(:, i) = x, y, z', meaning='right secondary upper universal joint', &
      partial=.true., doc='right secondary strut upper universal joint', doc_valid='distinct points', &
      doc_default='gear 1: `3.37, -1.23, -1.01`'), &
    input_var_t(g_gears, 'point_d', k_real, default="unset_real", n1=3, n2=max_gears, unit='m', &
      takes='a 3 x 8 real array; point_d(:, i) = x, y, z', meaning='footpad ball joint (primary lower end)', &
      partial=.true., doc='footpad ball joint at the primary strut''s lower end', doc_valid='distinct points', &
      doc_default='gear 1: `5.48, 0, 0.94`'), &
    input_var_t(g_gears, 'point_e', k_real, default="unset_real", n1=3, n2=max_gears, unit='m', &
      takes='a 3 x 8 real array; point_e(:, i) = x, y, z', meaning='left secondary lower ball joint', partial=.true., &
      doc='left secondary lower ball joint, on the primary outer tube', doc_valid='distinct points', &
      doc_default='gear 1: `4.65, 0.109, -0.505`'), &
    input_var_t(g_gears, 'point_f', k_real, default="unset_real", n1=3, n2=max_gears, unit='m', &
      takes='a 3 x 8 real array; point_f(:, i) = x, y, z', meaning='right secondary lower ball joint', partial=.true., &
      doc='right secondary lower ball joint, on the primary outer tube', doc_valid='distinct points', &
      doc_default='gear 1: `4.65, -0.109, -0.505`')]
  !> The registry entries of &primary_strut.
  type(input_var_t), parameter :: vars_primary(*) = [ &
    input_var_t(g_primary, 'buffer_law', k_string, default="'honeycomb'", &
      length='name_len', takes='a quoted character string', meaning='buffer (crush) law of the primary strut', &
      choices='buffer_law', doc='buffer (crush) law of the primary strut (case-insensitive; the laws above)'), &
    input_var_t(g_primary, 'n_stages', k_int, default="2", takes='an integer', meaning='number of honeycomb stages', &
      lo_op='>=', lo='1', hi_op='<=', hi='5', doc='number of honeycomb stages'), &
    input_var_t(g_primary, 'stage_force', k_real, default="[78000.0_wp, 156000.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]", &
      n1=max_stages, unit='N', &
      takes='up to 5 real numbers, one per stage', meaning='crush force of each stage', &
      doc='crush force of each stage (Table 1: F1, F2)', doc_valid='stages 1..n: `> 0`, non-decreasing'), &
    input_var_t(g_primary, 'stage_end', k_real, default="[0.2_wp, 0.475_wp, 0.0_wp, 0.0_wp, 0.0_wp]", &
      n1=max_stages, unit='m', takes='up to 5 real numbers, one per stage', &
      meaning='stroke at which each stage ends', &
      doc='stroke at which each stage ends; the last is the stroke capacity (Table 1: s1, s2)', &
      doc_valid='stages 1..n: `> 0`, strictly increasing'), &
    input_var_t(g_primary, 'stop_stiffness', k_real, default="1.0e9_wp", unit='N/m', takes='a real number', &
      meaning='stiffness of the end-of-stroke stop', lo_op='>', lo='0', doc='stiffness of the end-of-stroke stop'), &
    input_var_t(g_primary, 'stop_damping', k_real, default="1.0e5_wp", unit='N s/m', takes='a real number', &
      meaning='damping of the end-of-stroke stop', lo_op='>=', lo='0', doc='damping of the end-of-stroke stop'), &
    input_var_t(g_primary, 'outer_mass', k_real, default="25.0_wp", &
      unit='kg', takes='a real number', meaning='outer tube with lugs', &
      lo_op='>=', lo='0', doc='outer tube with its lugs'), &
    input_var_t(g_primary, 'outer_cm', k_real, default="1.0_wp", unit='m', takes='a real number', &
      meaning='outer tube mass centre from the upper joint', lo_op='>=', lo='0', hi_op='<=', hi='100', &
      doc='distance of the outer tube''s mass centre from the upper joint a', &
      doc_valid='`0 <= outer_cm <= 100` (hard points lie within 100 m)'), &
    input_var_t(g_primary, 'outer_inertia', k_real, default="8.3_wp", unit='kg m^2', takes='a real number', &
      meaning='outer tube transverse inertia about its mass centre', lo_op='>=', lo='0', &
      doc='transverse inertia of the outer tube about its mass centre'), &
    input_var_t(g_primary, 'inner_mass', k_real, default="15.0_wp", unit='kg', takes='a real number', meaning='inner tube', &
      lo_op='>=', lo='0', doc='inner tube'), &
    input_var_t(g_primary, 'inner_cm', k_real, default="0.9_wp", unit='m', takes='a real number', &
      meaning='inner tube mass centre from the footpad joint', lo_op='>=', lo='0', hi_op='<=', hi='100', &
      doc='distance of the inner tube''s mass centre from the footpad joint d', &
      doc_valid='`0 <= inner_cm <= 100` (hard points lie within 100 m)'), &
    input_var_t(g_primary, 'inner_inertia', k_real, default="4.05_wp", unit='kg m^2', takes='a real number', &
      meaning='inner tube transverse inertia about its mass centre', lo_op='>=', lo='0', &
      doc='transverse inertia of the inner tube about its mass centre'), &
    input_var_t(g_primary, 'footpad_mass', k_real, default="15.0_wp", unit='kg', takes='a real number', &
      meaning='footpad, lumped at the footpad joint', lo_op='>=', lo='0', &
      doc='footpad, lumped at the footpad joint d', doc_valid='`>= 0`, and `footpad_mass + inner_mass >= 1e-6`'), &
    input_var_t(g_primary, 'tube_friction', k_logical, default=".false.", takes='a logical (.true. or .false.)', &
      meaning='friction between the tubes (eqs. 23-26)', &
      doc='friction between the outer and inner tubes (eqs. 23-26), below'), &
    input_var_t(g_primary, 'mu_tube', k_real, default="0.1_wp", unit='-', takes='a real number', &
      meaning='tube friction coefficient u_1', lo_op='>=', lo='0', doc='u_1, tube friction coefficient (Table 1)'), &
    input_var_t(g_primary, 'tube_outer_length', k_real, default="2.0_wp", unit='m', takes='a real number', &
      meaning='L_O: outer tube, upper joint to its lower end', lo_op='>', lo='0', &
      doc='L_O: outer tube, from the upper joint a to its lower end'), &
    input_var_t(g_primary, 'tube_inner_length', k_real, default="2.8_wp", unit='m', takes='a real number', &
      meaning='L_I: inner tube, footpad joint to its upper end', lo_op='>', lo='0', &
      doc='L_I: inner tube, from the footpad joint d to its upper end'), &
    input_var_t(g_primary, 'tube_leg_length', k_real, default="3.5018_wp", unit='m', takes='a real number', &
      meaning='L_L: primary length at which the overlap is taken', lo_op='>', lo='0', &
      doc='L_L: primary length a-d at which the tubes'' overlap L_O + L_I − L_L is taken', &
      doc_valid='`> 0`, `< L_O + L_I`'), &
    input_var_t(g_primary, 'tube_lever', k_real, default="1.5_wp", unit='m', takes='a real number', &
      meaning='L_O1: lever arm of the lateral load (exposed inner tube)', lo_op='>=', lo='0', &
      doc='L_O1: lever arm of the lateral load about the nearest tube bearing (the inner tube''s length below the '// &
      'outer tube)')]
  !> The registry entries of &secondary_strut.
  type(input_var_t), parameter :: vars_secondary(*) = [ &
    input_var_t(g_secondary, 'buffer_law', k_string, default="'honeycomb'", &
      length='name_len', takes='a quoted character string', meaning='buffer (crush) law of the secondary struts', &
      choices='buffer_law', doc='buffer (crush) law of both secondary struts (case-insensitive; the laws above)'), &
    input_var_t(g_secondary, 'force_lengthening', k_real, default="43000.0_wp", unit='N', takes='a real number', &
      meaning='crush force resisting lengthening (F_com)', lo_op='>', lo='0', &
      doc='crush force resisting lengthening (Table 1 F_com)'), &
    input_var_t(g_secondary, 'force_shortening', k_real, default="30000.0_wp", unit='N', takes='a real number', &
      meaning='crush force resisting shortening (F_ten)', lo_op='>', lo='0', &
      doc='crush force resisting shortening (Table 1 F_ten)'), &
    input_var_t(g_secondary, 'stroke_lengthening', k_real, default="0.27_wp", unit='m', takes='a real number', &
      meaning='stroke available in lengthening', lo_op='>', lo='0', doc='stroke available in lengthening'), &
    input_var_t(g_secondary, 'stroke_shortening', k_real, default="0.27_wp", unit='m', takes='a real number', &
      meaning='stroke available in shortening', lo_op='>', lo='0', doc='stroke available in shortening'), &
    input_var_t(g_secondary, 'stop_stiffness', k_real, default="1.0e9_wp", unit='N/m', takes='a real number', &
      meaning='stiffness of the end-of-stroke stops', lo_op='>', lo='0', doc='stiffness of the end-of-stroke stops'), &
    input_var_t(g_secondary, 'stop_damping', k_real, default="1.0e5_wp", unit='N s/m', takes='a real number', &
      meaning='damping of the end-of-stroke stops', lo_op='>=', lo='0', doc='damping of the end-of-stroke stops'), &
    input_var_t(g_secondary, 'outer_mass', k_real, default="6.0_wp", unit='kg', takes='a real number', meaning='upper part', &
      lo_op='>=', lo='0', doc='upper part'), &
    input_var_t(g_secondary, 'outer_cm', k_real, default="0.45_wp", unit='m', takes='a real number', &
      meaning='upper part mass centre from the upper joint', lo_op='>=', lo='0', hi_op='<=', hi='100', &
      doc='distance of the upper part''s mass centre from the upper joint', &
      doc_valid='`0 <= outer_cm <= 100` (hard points lie within 100 m)'), &
    input_var_t(g_secondary, 'outer_inertia', k_real, default="0.405_wp", unit='kg m^2', takes='a real number', &
      meaning='upper part transverse inertia about its mass centre', lo_op='>=', lo='0', &
      doc='transverse inertia of the upper part about its mass centre'), &
    input_var_t(g_secondary, 'inner_mass', k_real, default="4.0_wp", unit='kg', takes='a real number', meaning='lower part', &
      lo_op='>=', lo='0', doc='lower part', doc_valid='`>= 1e-6` (the sliding lower part needs mass)'), &
    input_var_t(g_secondary, 'inner_cm', k_real, default="0.45_wp", unit='m', takes='a real number', &
      meaning='lower part mass centre from the lower joint', lo_op='>=', lo='0', hi_op='<=', hi='100', &
      doc='distance of the lower part''s mass centre from the lower joint', &
      doc_valid='`0 <= inner_cm <= 100` (hard points lie within 100 m)'), &
    input_var_t(g_secondary, 'inner_inertia', k_real, default="0.27_wp", unit='kg m^2', takes='a real number', &
      meaning='lower part transverse inertia about its mass centre', lo_op='>=', lo='0', &
      doc='transverse inertia of the lower part about its mass centre')]
  !> The registry entries of &contact.
  type(input_var_t), parameter :: vars_contact(*) = [ &
    input_var_t(g_contact, 'law', k_string, default="'base'", &
      length='name_len', takes='a quoted character string', meaning='normal contact law', &
      choices='contact_law', doc='contact law (case-insensitive)', doc_valid='one of the names above'), &
    input_var_t(g_contact, 'stiffness', k_real, default="3.16227766016838e9_wp", &
      unit='N/m^n', takes='a real number', meaning='K_g', lo_op='>', lo='0', &
      msg_unit=2, doc='K = 1000^1.5 · 1e5 (MSC Adams default; Tables 1 and 5)'), &
    input_var_t(g_contact, 'exponent', k_real, default="1.5_wp", &
      unit='-', takes='a real number', meaning='penetration exponent n', &
      lo_op='>=', lo='0.5', hi_op='<=', hi='4.0', msg_unit=0, doc='penetration exponent n (Tables 1 and 5)', &
      doc_valid='`0.5 <= exponent <= 4`'), &
    input_var_t(g_contact, 'damping', k_real, default="1.0e4_wp", &
      unit='N s/m', takes='a real number', meaning='C_g', lo_op='>=', lo='0', &
      doc='C (base, adams_impact), D (kelvin_voigt, kelvin_voigt_step), D1 (kelvin_voigt_bilinear), C on the regol'// &
      'ith''s unloading line; Table 5: D = D1 = 10 × 1000'), &
    input_var_t(g_contact, 'damping_depth', k_real, default="1.0e-4_wp", unit='m', takes='a real number', &
      meaning='D1 (base), d_max (adams_impact), d (kelvin_voigt_step)', &
      doc='D1 (base: penetration of full damping), d_max (adams_impact), d (kelvin_voigt_step: damping only for δ '// &
      '<= d)', &
      doc_valid='`> 0` for adams_impact and kelvin_voigt_step; `>= 0` for the other laws (base: 0 = no ramp, '// &
        'full damping at once)'), &
    input_var_t(g_contact, 'damping2', k_real, default="1.0e4_wp", unit='N s^2/m^2', takes='a real number', &
      meaning='D2 of kelvin_voigt_bilinear', lo_op='>=', lo='0', &
      doc='D2 of kelvin_voigt_bilinear (Table 5: 10 × 1000)'), &
    input_var_t(g_contact, 'restitution', k_real, default="0.5_wp", unit='-', takes='a real number', &
      meaning='e of hunt_crossley (when hc_alpha = 0)', lo_op='>=', lo='0', hi_op='<=', hi='1', msg_unit=0, &
      doc='coefficient of restitution e of hunt_crossley (used when `hc_alpha = 0`)', doc_valid='`0 <= e <= 1`'), &
    input_var_t(g_contact, 'hc_alpha', k_real, default="0.0_wp", unit='s/m', takes='a real number', &
      meaning='hunt_crossley c_r = 1 - alpha v_impact; 0: use e', lo_op='>=', lo='0', &
      doc='hunt_crossley in the paper''s form c_r = 1 − α v (Table 4 footnote, α between 0.008 and 0.32); 0: use `'// &
      'restitution`'), &
    input_var_t(g_contact, 'min_impact_speed', k_real, default="0.1_wp", unit='m/s', takes='a real number', &
      meaning='floor of the impact speed in hunt_crossley', lo_op='>', lo='0', &
      doc='floor of the impact speed v in hunt_crossley''s χ'), &
    input_var_t(g_contact, 'soil_stiffness', k_real, default="5.24e5_wp", unit='N/m^n_b', takes='a real number', &
      meaning='K_b of regolith, F_p = K_b z^n_b', lo_op='>', lo='0', msg_unit=0, &
      doc='K_b of regolith, F_p = K_b z^n_b'), &
    input_var_t(g_contact, 'soil_exponent', k_real, default="1.0_wp", &
      unit='-', takes='a real number', meaning='n_b of regolith', &
      lo_op='>', lo='0', msg_unit=0, doc='n_b of regolith'), &
    input_var_t(g_contact, 'soil_drag', k_real, default="1.0e3_wp", unit='kg/m', takes='a real number', &
      meaning='alpha of regolith, drag alpha v^2 (eq. 1)', lo_op='>=', lo='0', &
      doc='α of regolith, the inertial drag α v² of eq. 1'), &
    input_var_t(g_contact, 'soil_unload_stiffness', k_real, default="1.0e8_wp", unit='N/m', takes='a real number', &
      meaning='regolith unloading/reloading stiffness', lo_op='>', lo='0', &
      doc='k_u, regolith unloading/reloading stiffness')]
  !> The registry entries of &friction.
  type(input_var_t), parameter :: vars_friction(*) = [ &
    input_var_t(g_friction, 'law', k_string, default="'coulomb_step'", &
      length='name_len', takes='a quoted character string', meaning='friction law', &
      choices='friction_law', doc='friction law (case-insensitive)', doc_valid='one of the names above'), &
    input_var_t(g_friction, 'mu_static', k_real, default="0.4_wp", unit='-', takes='a real number', &
      meaning='static friction coefficient', lo_op='>=', lo='0', doc='μ_s (F_S/N)'), &
    input_var_t(g_friction, 'mu_dynamic', k_real, default="0.4_wp", unit='-', takes='a real number', &
      meaning='dynamic friction coefficient', lo_op='>=', lo='0', doc='μ_d (F_D/N, F_C/N)', &
      doc_valid='`>= 0`; `<= mu_static` for ty4, ty5, ty6'), &
    input_var_t(g_friction, 'v_static', k_real, default="0.1_wp", unit='m/s', takes='a real number', &
      meaning='stiction transition slip speed', lo_op='>', lo='0', &
      doc='v_s of coulomb_step; the regularisation / stiction speed v0 of ty3 and ty6 (Table 8: 0.1)'), &
    input_var_t(g_friction, 'v_dynamic', k_real, default="1.0_wp", unit='m/s', takes='a real number', &
      meaning='friction transition slip speed', doc='v_d of coulomb_step', &
      doc_valid='`> v_static` for coulomb_step and adams_step (the laws that use it)'), &
    input_var_t(g_friction, 'viscous', k_real, default="100.0_wp", &
      unit='N s/m', takes='a real number', meaning='C_v of ty2, ty5, ty6', &
      lo_op='>=', lo='0', doc='C_v of ty2, ty5, ty6 (Table 8 TY-2)'), &
    input_var_t(g_friction, 'stribeck_speed', k_real, default="unset_real", unit='m/s', takes='a real number', &
      meaning='v_S of ty5, ty6 (default 1.0 for ty5, 0.1 for ty6)', partial=.true., lo_op='>', lo='0', &
      doc='v_S of ty5 and ty6 (Table 8); resolved from `law` when not given', &
      doc_default='`1.0` for ty5, `0.1` for ty6'), &
    input_var_t(g_friction, 'stribeck_exponent', k_real, default="0.85_wp", &
      unit='-', takes='a real number', meaning='delta of ty5, t'// &
      'y6', lo_op='>', lo='0', doc='δ of ty5 and ty6 (Table 8)'), &
    input_var_t(g_friction, 'stribeck_decay', k_real, default="0.85_wp", &
      unit='-', takes='a real number', meaning='epsilon of ty6', &
      lo_op='>=', lo='0', doc='ε of ty6 (Table 8)'), &
    input_var_t(g_friction, 'stick_stiffness', k_real, default="1.0e8_wp", unit='N/m', takes='a real number', &
      meaning='tangential stiffness of the stick state', lo_op='>', lo='0', &
      doc='k of the stick state (ty1, ty2, ty4, ty5)'), &
    input_var_t(g_friction, 'stick_damping', k_real, default="1.0e5_wp", unit='N s/m', takes='a real number', &
      meaning='tangential damping of the stick state', lo_op='>=', lo='0', &
      doc='c of the stick state (ty1, ty2, ty4, ty5)')]
  !> The registry entries of &terrain.
  type(input_var_t), parameter :: vars_terrain(*) = [ &
    input_var_t(g_terrain, 'height', k_real, default="0.0_wp", &
      n1=max_gears, unit='m', takes='up to 8 real numbers, one per footpad', &
      meaning='surface elevation at the global origin (up +)', &
      doc='surface elevation at the global origin, up positive'), &
    input_var_t(g_terrain, 'slope', k_real, default="0.0_wp", &
      n1=max_gears, unit='deg', takes='up to 8 real numbers, one per footpad', &
      meaning='slope angle', angle=.true., doc='slope angle', doc_valid='`0 <= slope < 60` (footpads 1..n_gears)'), &
    input_var_t(g_terrain, 'slope_direction', k_real, default="0.0_wp", n1=max_gears, unit='deg', &
      takes='up to 8 real numbers, one per footpad', meaning='azimuth of uphill, from +x toward +y', angle=.true., &
      doc='azimuth of the uphill direction, from global +x toward +y')]
  !> The registry entries of &initial_state.
  type(input_var_t), parameter :: vars_initial(*) = [ &
    input_var_t(g_initial, 'position', k_real, default="unset_real", n1=3, unit='m', takes='3 real numbers x, y, z', &
      meaning='lander-frame origin in the global frame', partial=.true., &
      doc='lander-frame origin O_L in the global frame', doc_valid='all three or none', doc_default='not given'), &
    input_var_t(g_initial, 'clearance', k_real, default="0.0_wp", unit='m', takes='a real number', &
      meaning='gap of the lowest footpad when position is not given', lo_op='>=', lo='0', &
      doc='when `position` is not given: gap between the lowest footpad and its surface (0 = just touching)'), &
    input_var_t(g_initial, 'velocity', k_real, default="[0.0_wp, 0.0_wp, 4.0_wp]", &
      n1=3, unit='m/s', takes='3 real numbers x, y, z', &
      meaning='mass-centre velocity, global frame (z down)', &
      doc='velocity of the mass centre in the global frame (z down: +4 is a 4 m/s descent)'), &
    input_var_t(g_initial, 'attitude', k_real, default="0.0_wp", n1=3, unit='deg', takes='3 real numbers yaw, pitch, roll', &
      meaning='Z-Y-X Euler angles, R = Rz(yaw) Ry(pitch) Rx(roll)', angle=.true., &
      doc='Z-Y-X Euler angles yaw, pitch, roll: R = Rz(yaw) Ry(pitch) Rx(roll)', &
      doc_valid='pitch: `-90 < attitude(2) < 90`'), &
    input_var_t(g_initial, 'angular_rate', k_real, default="0.0_wp", n1=3, unit='deg/s', takes='3 real numbers p, q, r', &
      meaning='body angular rate in lander axes', angle=.true., doc='body angular rate p, q, r in lander axes')]
  !> The registry entries of &output.
  type(input_var_t), parameter :: vars_output(*) = [ &
    input_var_t(g_output, 'file', k_string, default="''", &
      length='path_len', takes='a quoted character string', meaning='result file (HDF5)', &
      fixed='history files are named by the campaign', &
      doc='HDF5 result file. Empty: the deck''s base name with `.h5` (`input/lc3.nml` -> `lc3.h5`) in the current '// &
      'directory; `landyn.h5` without a deck', &
      doc_valid='non-empty after resolving; at most 1024 characters (longer is an error, never truncated); the [ou'// &
      'tput-file policy](../files.md) applies'), &
    input_var_t(g_output, 'interval', k_real, default="1.0e-3_wp", &
      unit='s', takes='a real number', meaning='output sampling interval', &
      doc='output sampling interval', &
      doc_valid='`dt <= interval <= t_end`, and `t_end/interval <= 1e6` (at most 10⁶ stored samples)')]
  !> The registry: every run-deck variable, in deck order. Cross-variable and law-dependent checks
  !! are in landyn_input_validate.
  type(input_var_t), parameter :: input_vars(*) = [vars_simulation, vars_lander, vars_engine, vars_gears, vars_primary, &
    vars_secondary, vars_contact, vars_friction, vars_terrain, vars_initial, vars_output]

contains

  !> Index of a group name, 0 if unknown (run decks; table_group_index for any table).
  pure function group_index(name) result(ig)
    character(len=*), intent(in) :: name  !! lower-case group name [-]
    integer :: ig                         !! index, 0 if unknown [-]
    ig = table_group_index(group_names, name)
  end function group_index

  !> Index of a variable of group ig in input_vars, 0 if the group has no such variable.
  pure function var_index(ig, name) result(iv)
    integer, intent(in) :: ig             !! group index [-]
    character(len=*), intent(in) :: name  !! lower-case variable name [-]
    integer :: iv                         !! index into input_vars, 0 if not in group ig [-]
    iv = table_var_index(input_vars, ig, name)
  end function var_index

  !> ' [unit]' of entry iv, or '' for none or '-'.
  pure function unit_text(iv) result(s)
    integer, intent(in) :: iv             !! index into input_vars [-]
    character(len=:), allocatable :: s    !! ' [unit]' or '' [-]
    s = entry_unit_text(input_vars(iv))
  end function unit_text

  !> Index of a group name in a table's groups, 0 if unknown.
  pure function table_group_index(groups, name) result(ig)
    character(len=*), intent(in) :: groups(:)  !! the table's group names [-]
    character(len=*), intent(in) :: name       !! lower-case group name [-]
    integer :: ig                              !! index, 0 if unknown [-]
    do ig = 1, size(groups)
      if (trim(groups(ig)) == name) return
    end do
    ig = 0
  end function table_group_index

  !> Index of a variable of group ig in a table's entries, 0 if the group has no such variable.
  pure function table_var_index(vars, ig, name) result(iv)
    type(input_var_t), intent(in) :: vars(:)  !! the table's entries [-]
    integer, intent(in) :: ig                 !! group index [-]
    character(len=*), intent(in) :: name      !! lower-case variable name [-]
    integer :: iv                             !! index into vars, 0 if not in group ig [-]
    do iv = 1, size(vars)
      if (vars(iv)%group == ig .and. trim(vars(iv)%name) == name) return
    end do
    iv = 0
  end function table_var_index

  !> ' [unit]' of an entry, or '' for none or '-'.
  pure function entry_unit_text(v) result(s)
    type(input_var_t), intent(in) :: v    !! the entry [-]
    character(len=:), allocatable :: s    !! ' [unit]' or '' [-]
    s = ''
    if (len_trim(v%unit) > 0 .and. v%unit /= '-') s = ' ['//trim(v%unit)//']'
  end function entry_unit_text

  !> The valid range of entry iv as messages and docs write it, e.g. 'dt > 0 s', '0 <= restitution <= 1'
  !! ('' when the entry has no range). With show_unit false the unit is left out.
  pure function range_text(iv, show_unit) result(s)
    integer, intent(in) :: iv             !! index into input_vars [-]
    logical, intent(in) :: show_unit      !! append the unit [-]
    character(len=:), allocatable :: s    !! range [-]
    character(len=:), allocatable :: flipped
    type(input_var_t) :: v
    v = input_vars(iv)
    s = ''
    if (len_trim(v%lo_op) == 0) return
    if (len_trim(v%hi_op) > 0) then
      flipped = '<'
      if (v%lo_op == '>=') flipped = '<='
      s = trim(v%lo)//' '//flipped//' '//trim(v%name)//' '//trim(v%hi_op)//' '//trim(v%hi)
    else
      s = trim(v%name)//' '//trim(v%lo_op)//' '//trim(v%lo)
    end if
    if (show_unit .and. v%msg_unit == 1 .and. len_trim(v%unit) > 0 .and. v%unit /= '-') s = s//' '//trim(v%unit)
  end function range_text

  !> "&simulation, &lander, ...".
  pure function group_list() result(s)
    character(len=:), allocatable :: s  !! group names [-]
    s = table_group_list(group_names)
  end function group_list

  !> "&first, &second, ..." of a table's groups.
  pure function table_group_list(groups) result(s)
    character(len=*), intent(in) :: groups(:)  !! the table's group names [-]
    character(len=:), allocatable :: s         !! group names [-]
    integer :: ig
    s = ''
    do ig = 1, size(groups)
      if (ig > 1) s = s//', '
      s = s//'&'//trim(groups(ig))
    end do
  end function table_group_list

  !> The closest of `names` to `name` by edit distance when close enough (at most max(2, len/3)
  !! edits), else ''. The one rule of every "did you mean" hint.
  pure function closest_name(name, names) result(best_name)
    character(len=*), intent(in) :: name       !! unknown name [-]
    character(len=*), intent(in) :: names(:)   !! known names [-]
    character(len=:), allocatable :: best_name !! closest known name, '' if none is close [-]
    integer :: i, d, best, best_d
    best = 0
    best_d = huge(1)
    do i = 1, size(names)
      d = edit_distance(name, trim(names(i)))
      if (d < best_d) then
        best_d = d
        best = i
      end if
    end do
    best_name = ''
    if (best > 0 .and. best_d <= max(2, len(name)/3)) best_name = trim(names(best))
  end function closest_name

  !> " (did you mean '&xxx'?)" for a close group name, else ''.
  pure function group_hint(name) result(s)
    character(len=*), intent(in) :: name  !! unknown group name [-]
    character(len=:), allocatable :: s    !! hint [-]
    s = table_group_hint(group_names, name)
  end function group_hint

  !> "; did you mean 'xxx'?" for a close name in the group, or where the variable belongs, else the
  !! group's valid variables.
  pure function var_hint(ig, name) result(s)
    integer, intent(in) :: ig             !! group index [-]
    character(len=*), intent(in) :: name  !! unknown variable name [-]
    character(len=:), allocatable :: s    !! hint [-]
    s = table_var_hint(input_vars, group_names, ig, name)
  end function var_hint

  !> " (did you mean '&xxx'?)" for a name close to one of a table's groups, else ''.
  pure function table_group_hint(groups, name) result(s)
    character(len=*), intent(in) :: groups(:)  !! the table's group names [-]
    character(len=*), intent(in) :: name       !! unknown group name [-]
    character(len=:), allocatable :: s         !! hint [-]
    s = closest_name(name, groups)
    if (len(s) > 0) s = " (did you mean '&"//s//"'?)"
  end function table_group_hint

  !> "; did you mean 'xxx'?" for a close name in group ig of a table, or the group of the table the
  !! variable belongs to, else "; valid variables: a, b, ..." (the group's variables, in table order).
  pure function table_var_hint(vars, groups, ig, name) result(s)
    type(input_var_t), intent(in) :: vars(:)   !! the table's entries [-]
    character(len=*), intent(in) :: groups(:)  !! the table's group names [-]
    integer, intent(in) :: ig                  !! group index [-]
    character(len=*), intent(in) :: name       !! unknown variable name [-]
    character(len=:), allocatable :: s         !! hint [-]
    integer :: iv
    do iv = 1, size(vars)
      if (vars(iv)%group /= ig .and. trim(vars(iv)%name) == name) then
        s = "; '"//name//"' belongs to &"//trim(groups(vars(iv)%group))
        return
      end if
    end do
    s = closest_name(name, pack(vars%name, vars%group == ig))
    if (len(s) > 0) then
      s = "; did you mean '"//s//"'?"
    else if (any(vars%group == ig)) then
      s = '; valid variables: '//var_list(vars, ig)
    end if
  end function table_var_hint

  !> "a, b, ..." of the variables of group ig of a table, in table order.
  pure function var_list(vars, ig) result(s)
    type(input_var_t), intent(in) :: vars(:)  !! the table's entries [-]
    integer, intent(in) :: ig                 !! group index [-]
    character(len=:), allocatable :: s        !! variable names [-]
    integer :: iv
    s = ''
    do iv = 1, size(vars)
      if (vars(iv)%group /= ig) cycle
      if (len(s) > 0) s = s//', '
      s = s//trim(vars(iv)%name)
    end do
  end function var_list

end module landyn_input_registry
