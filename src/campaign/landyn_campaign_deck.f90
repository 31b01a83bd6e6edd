!> Campaign decks: reading, validation, and the inputs of every case.
!!
!! A campaign deck (docs/campaign.md) is a namelist text with the groups &campaign (once),
!! &parameter (once per varied input; not in list mode) and &criteria (optional). Each item is
!! read on its own, so every problem is reported, in the form `<deck>:<line>: &<group>: <what>`
!! (read errors) or `<deck>: &<group>: <what>` (checks across items), like run decks.
!!
!! Every case runs the base run deck with the case's overrides: `case_deck_text` writes the base
!! deck's items group by group, drops a base item whose name the case sets itself, and appends
!! the overrides as `name(subscript) = value` items in deck units (degrees where decks use
!! degrees) with 17 significant digits; `case_input` reads that text with the run-deck reader
!! (read_input_text, resolve_input, validate_input), so a case is validated exactly as a deck.
!! A campaign with no overrides reproduces the base deck bit for bit (checked when the base deck
!! is attached).
!!
!! Library code: nothing here stops or prints.
module landyn_campaign_deck
  use, intrinsic :: iso_fortran_env, only: int64
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use landyn_kinds, only: wp, max_gears
  use landyn_config, only: landyn_input_t, default_input, unset_real, is_set, max_stages, path_len
  use landyn_input, only: input_errors_t, read_input_text, resolve_input, validate_input, resolved_input_text
  use landyn_namelist_text, only: has_nonfinite_word, numbers_within
  use landyn_files, only: read_whole_file
  use landyn_campaign_nml, only: nml_group_t, nml_item_t, split_namelist, lower_case, int_text, real_text, &
                                 real_text_short, quote_text, close_name_hint, dir_of, join_path, base_name_no_ext
  use landyn_campaign_rng, only: case_uniform, case_truncated_normal, splitmix64_mix, add64
  implicit none
  private

  public :: campaign_t, param_t, criteria_t
  public :: load_campaign, build_campaign, use_summary_file, case_values, case_deck_text, case_input, text_fingerprint
  public :: param_description, max_values, max_saved, max_body_points, max_params, label_len
  public :: run_variable_table, default_deck_variable, default_deck_variables

  integer, parameter :: max_values = 1000       !! most values / weights of one &parameter [-]
  integer, parameter :: max_saved = 1000        !! most case ids in save_histories [-]
  integer, parameter :: max_body_points = 8     !! most body points of the clearance criterion [-]
  integer, parameter :: max_params = 64         !! most varied inputs [-]
  integer, parameter :: label_len = 64          !! longest parameter label [-]
  integer, parameter :: name_len = 128          !! longest parameter name [-]
  integer, parameter :: max_cases = 100000000   !! most cases of one campaign [-]
  integer, parameter :: max_normal_tries = 100000  !! rejection tries of a truncated normal [-]
  integer, parameter :: cell_len = 256          !! longest cell of the case list [-]
  real(wp), parameter :: min_truncated_mass = 1.0e-3_wp  !! least probability inside a truncation [-]

  !> One varied input.
  type :: param_t
    character(len=:), allocatable :: name     !! normalised 'group%variable(subscript)' [-]
    character(len=:), allocatable :: label    !! column name in the summary file [-]
    character(len=:), allocatable :: units    !! deck units ('-' if none) [-]
    character(len=:), allocatable :: group    !! run-deck group [-]
    character(len=:), allocatable :: lhs      !! item name written into the case deck, e.g. 'slope(:)' [-]
    integer :: n_elem = 1                     !! elements the override sets (repeat count) [-]
    character(len=:), allocatable :: var      !! run-deck variable [-]
    logical :: is_int = .false.               !! integer variable [-]
    integer, allocatable :: elems(:)          !! flat element indices set (for overlap checks) [-]
    integer :: line = 0                       !! line of the &parameter group [-]
    character(len=16) :: kind = ''            !! 'grid', 'uniform', 'normal', 'discrete' or 'list' [-]
    real(wp), allocatable :: values(:)        !! grid or discrete values [deck unit]
    real(wp), allocatable :: weights(:)       !! discrete weights, normalised cumulative [-]
    real(wp) :: lo = unset_real               !! uniform lower bound / normal truncation [deck unit]
    real(wp) :: hi = unset_real               !! uniform upper bound / normal truncation [deck unit]
    real(wp) :: mean = unset_real             !! normal mean [deck unit]
    real(wp) :: sd = unset_real               !! normal standard deviation [deck unit]
  end type param_t

  !> Success criteria of a landing.
  type :: criteria_t
    real(wp) :: min_stroke_margin = 0.0_wp          !! every stroke margin must be >= this [m]
    logical :: overload_applied = .false.           !! max_overload given [-]
    real(wp) :: max_overload = 0.0_wp               !! peak overload must be <= this [g]
    logical :: clearance_applied = .false.          !! min_body_clearance given [-]
    real(wp) :: min_body_clearance = 0.0_wp         !! body clearance must stay >= this [m]
    integer :: n_body_points = 1                    !! body points checked for clearance [-]
    real(wp) :: body_point(3, max_body_points) = 0.0_wp  !! body points, lander frame [m]
    logical :: require_at_rest = .false.            !! the lander must have come to rest [-]
    character(len=24) :: failed_runs = 'count_as_failure'  !! 'count_as_failure' or 'exclude' [-]
  end type criteria_t

  !> A campaign: its deck, the base run deck, the varied inputs and the criteria.
  type :: campaign_t
    character(len=:), allocatable :: deck_name       !! campaign deck path [-]
    character(len=:), allocatable :: deck_text       !! campaign deck text [-]
    character(len=:), allocatable :: title           !! campaign title [-]
    character(len=16) :: mode = ''                   !! 'grid', 'monte_carlo' or 'list' [-]
    character(len=:), allocatable :: base_path       !! base deck path (relative to the campaign deck's directory) [-]
    character(len=:), allocatable :: base_text       !! base deck text [-]
    character(len=:), allocatable :: list_path       !! case list path (list mode) [-]
    character(len=:), allocatable :: list_text       !! case list text [-]
    character(len=:), allocatable :: summary_file    !! summary file [-]
    character(len=:), allocatable :: history_prefix  !! history files are <prefix><id>.h5 [-]
    logical :: history_prefix_given = .false.         !! &campaign history_prefix was given [-]
    integer(int64) :: seed = 1_int64                 !! Monte Carlo seed [-]
    integer :: n_samples = 0                         !! Monte Carlo sample count [-]
    integer :: n_cases = 0                           !! number of cases [-]
    integer :: n_par = 0                             !! number of varied inputs [-]
    integer :: n_gears = 0                           !! gears of the base deck [-]
    real(wp) :: checkpoint_interval = 60.0_wp        !! time between summary rewrites while running [s]
    integer, allocatable :: save_histories(:)        !! case ids whose time histories are written [-]
    type(param_t), allocatable :: par(:)             !! varied inputs [-]
    integer, allocatable :: grid_n(:)                !! grid: number of values of each parameter [-]
    real(wp), allocatable :: table(:, :)             !! list: (n_par, n_cases) values [deck unit]
    type(criteria_t) :: crit                         !! success criteria [-]
    type(nml_group_t), allocatable :: base_groups(:) !! the base deck split into items [-]
    character(len=16) :: fingerprint = ''            !! hash of everything that defines the cases [-]
  end type campaign_t

  !> A run-deck variable that a campaign can vary.
  type :: tvar_t
    character(len=15) :: group        !! run-deck group [-]
    character(len=20) :: name         !! variable [-]
    character(len=8) :: unit          !! deck unit [-]
    integer :: n1 = 0                 !! first extent (0: scalar) [-]
    integer :: n2 = 0                 !! second extent (0: rank < 2) [-]
    logical :: is_int = .false.       !! integer variable [-]
  end type tvar_t

  type(tvar_t), parameter :: tvars(*) = [ &
    tvar_t('simulation', 'dt', 's'), tvar_t('simulation', 't_end', 's'), &
    tvar_t('simulation', 'gravity', 'm/s^2'), tvar_t('simulation', 'rest_speed', 'm/s'), &
    tvar_t('simulation', 'rest_time', 's'), tvar_t('simulation', 'tipover_angle', 'deg'), &
    tvar_t('simulation', 'constraint_tol', 'm, m/s'), tvar_t('simulation', 'max_correction_iter', '-', 0, 0, .true.), &
    tvar_t('simulation', 'max_constraint_drift', 'm'), &
    tvar_t('lander', 'mass', 'kg'), tvar_t('lander', 'ixx', 'kg m^2'), tvar_t('lander', 'iyy', 'kg m^2'), &
    tvar_t('lander', 'izz', 'kg m^2'), tvar_t('lander', 'ixy', 'kg m^2'), tvar_t('lander', 'ixz', 'kg m^2'), &
    tvar_t('lander', 'iyz', 'kg m^2'), tvar_t('lander', 'mass_centre', 'm', 3), &
    tvar_t('engine', 'thrust', 'N'), tvar_t('engine', 'direction', '-', 3), tvar_t('engine', 'point', 'm', 3), &
    tvar_t('engine', 'cutoff_time', 's'), &
    tvar_t('gears', 'rotation', 'deg', max_gears), &
    tvar_t('gears', 'point_a', 'm', 3, max_gears), tvar_t('gears', 'point_b', 'm', 3, max_gears), &
    tvar_t('gears', 'point_c', 'm', 3, max_gears), tvar_t('gears', 'point_d', 'm', 3, max_gears), &
    tvar_t('gears', 'point_e', 'm', 3, max_gears), tvar_t('gears', 'point_f', 'm', 3, max_gears), &
    tvar_t('primary_strut', 'n_stages', '-', 0, 0, .true.), tvar_t('primary_strut', 'stage_force', 'N', max_stages), &
    tvar_t('primary_strut', 'stage_end', 'm', max_stages), tvar_t('primary_strut', 'stop_stiffness', 'N/m'), &
    tvar_t('primary_strut', 'stop_damping', 'N s/m'), tvar_t('primary_strut', 'outer_mass', 'kg'), &
    tvar_t('primary_strut', 'outer_cm', 'm'), tvar_t('primary_strut', 'outer_inertia', 'kg m^2'), &
    tvar_t('primary_strut', 'inner_mass', 'kg'), tvar_t('primary_strut', 'inner_cm', 'm'), &
    tvar_t('primary_strut', 'inner_inertia', 'kg m^2'), tvar_t('primary_strut', 'footpad_mass', 'kg'), &
    tvar_t('secondary_strut', 'force_lengthening', 'N'), tvar_t('secondary_strut', 'force_shortening', 'N'), &
    tvar_t('secondary_strut', 'stroke_lengthening', 'm'), tvar_t('secondary_strut', 'stroke_shortening', 'm'), &
    tvar_t('secondary_strut', 'stop_stiffness', 'N/m'), tvar_t('secondary_strut', 'stop_damping', 'N s/m'), &
    tvar_t('secondary_strut', 'outer_mass', 'kg'), tvar_t('secondary_strut', 'outer_cm', 'm'), &
    tvar_t('secondary_strut', 'outer_inertia', 'kg m^2'), tvar_t('secondary_strut', 'inner_mass', 'kg'), &
    tvar_t('secondary_strut', 'inner_cm', 'm'), tvar_t('secondary_strut', 'inner_inertia', 'kg m^2'), &
    tvar_t('contact', 'stiffness', 'N/m^n'), tvar_t('contact', 'exponent', '-'), &
    tvar_t('contact', 'damping', 'N s/m'), tvar_t('contact', 'damping_depth', 'm'), &
    tvar_t('friction', 'mu_static', '-'), tvar_t('friction', 'mu_dynamic', '-'), &
    tvar_t('friction', 'v_static', 'm/s'), tvar_t('friction', 'v_dynamic', 'm/s'), &
    tvar_t('terrain', 'height', 'm', max_gears), tvar_t('terrain', 'slope', 'deg', max_gears), &
    tvar_t('terrain', 'slope_direction', 'deg', max_gears), &
    tvar_t('initial_state', 'position', 'm', 3), tvar_t('initial_state', 'clearance', 'm'), &
    tvar_t('initial_state', 'velocity', 'm/s', 3), tvar_t('initial_state', 'attitude', 'deg', 3), &
    tvar_t('initial_state', 'angular_rate', 'deg/s', 3), &
    tvar_t('output', 'interval', 's')]

  !> Run-deck variables that exist but cannot be varied, and why.
  character(len=*), parameter :: fixed_vars(*) = [character(len=40) :: &
    'simulation%title', 'simulation%stop_at_rest', 'gears%n_gears', 'contact%law', 'friction%law', 'output%file']
  character(len=*), parameter :: fixed_why(*) = [character(len=96) :: &
    'it is text, not a number', 'it is a logical, not a number', &
    'the summary has one column per gear and strut, so every case needs the same gears', &
    'it is text, not a number', 'it is text, not a number', 'history files are named by the campaign']

  character(len=*), parameter :: run_groups(*) = [character(len=15) :: 'simulation', 'lander', 'engine', 'gears', &
    'primary_strut', 'secondary_strut', 'contact', 'friction', 'terrain', 'initial_state', 'output']

  ! Campaign-deck variables: group, name, what it takes (for messages).
  character(len=*), parameter :: campaign_vars(*) = [character(len=20) :: 'title', 'base_deck', 'mode', &
    'n_samples', 'seed', 'summary_file', 'history_prefix', 'save_histories', 'list_file', 'checkpoint_interval']
  character(len=*), parameter :: campaign_takes(*) = [character(len=56) :: 'a quoted character string', &
    'a quoted file name', "'grid', 'monte_carlo' or 'list'", 'an integer', 'an integer', 'a quoted file name', &
    'a quoted file-name prefix', 'up to 1000 case ids', 'a quoted file name', 'a real number [s]']
  character(len=*), parameter :: parameter_vars(*) = [character(len=20) :: 'name', 'label', 'values', 'start', &
    'stop', 'count', 'distribution', 'lo', 'hi', 'mean', 'sd', 'weights']
  character(len=*), parameter :: parameter_takes(*) = [character(len=56) :: &
    "a quoted input name, e.g. 'initial_state%velocity(1)'", 'a quoted column name', &
    'up to 1000 real numbers [deck unit]', 'a real number [deck unit]', 'a real number [deck unit]', &
    'an integer', "'uniform', 'normal' or 'discrete'", 'a real number [deck unit]', 'a real number [deck unit]', &
    'a real number [deck unit]', 'a real number [deck unit]', 'up to 1000 real numbers >= 0']
  character(len=*), parameter :: criteria_vars(*) = [character(len=20) :: 'min_stroke_margin', 'max_overload', &
    'min_body_clearance', 'body_point', 'require_at_rest', 'failed_runs']
  character(len=*), parameter :: criteria_takes(*) = [character(len=56) :: 'a real number [m]', &
    'a real number [g]', 'a real number [m]', 'a 3 x 8 real array [m]; body_point(:, i) = x, y, z', &
    'a logical', "'count_as_failure' or 'exclude'"]

  !> Raw &campaign values as read.
  type :: raw_campaign_t
    character(len=256) :: title = ''
    character(len=path_len) :: base_deck = ''
    character(len=32) :: mode = ''
    integer :: n_samples = -1
    integer(int64) :: seed = 1_int64
    character(len=path_len) :: summary_file = ''
    character(len=path_len) :: history_prefix = ''
    integer :: save_histories(max_saved) = 0
    character(len=path_len) :: list_file = ''
    real(wp) :: checkpoint_interval = 60.0_wp
  end type raw_campaign_t

  !> Raw &parameter values as read.
  type :: raw_parameter_t
    character(len=name_len) :: name = ''
    character(len=label_len) :: label = ''
    real(wp) :: values(max_values) = unset_real
    real(wp) :: start = unset_real
    real(wp) :: stop = unset_real
    integer :: count = -1
    character(len=32) :: distribution = ''
    real(wp) :: lo = unset_real
    real(wp) :: hi = unset_real
    real(wp) :: mean = unset_real
    real(wp) :: sd = unset_real
    real(wp) :: weights(max_values) = unset_real
  end type raw_parameter_t

  !> Raw &criteria values as read.
  type :: raw_criteria_t
    real(wp) :: min_stroke_margin = 0.0_wp
    real(wp) :: max_overload = unset_real
    real(wp) :: min_body_clearance = unset_real
    real(wp) :: body_point(3, max_body_points) = unset_real
    logical :: require_at_rest = .false.
    character(len=32) :: failed_runs = 'count_as_failure'
  end type raw_criteria_t

contains

  ! ================================================================ loading

  !> Read a campaign deck and the files it names (base deck, case list) and build the campaign.
  !! stat = 0 ready, 1 problems in the decks (all in `errors`), 2 the campaign deck is unreadable.
  subroutine load_campaign(path, camp, errors, stat)
    character(len=*), intent(in) :: path           !! campaign deck file [-]
    type(campaign_t), intent(out) :: camp          !! the campaign [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    integer, intent(out) :: stat                   !! 0 ok, 1 deck errors, 2 deck unreadable [-]
    character(len=:), allocatable :: text, base_text, list_text, msg
    type(raw_campaign_t) :: rc
    type(campaign_t) :: probe
    type(input_errors_t) :: scratch
    integer :: st, n0

    n0 = errors%count()
    call read_text_file(path, text, st, msg)
    if (st /= 0) then
      call errors%add(path//': cannot read the campaign deck: '//msg)
      stat = 2
      return
    end if
    ! first pass: only to learn the file names (its messages come again in build_campaign)
    call parse_campaign_deck(text, path, probe, rc, scratch)
    base_text = ''
    list_text = ''
    if (len_trim(rc%base_deck) > 0) then
      call read_text_file(join_path(dir_of(path), rc%base_deck), base_text, st, msg)
      if (st /= 0) then
        call errors%add(path//': &campaign: base_deck = '//quote_text(trim(rc%base_deck))//': cannot read '// &
                        quote_text(join_path(dir_of(path), rc%base_deck))//': '//msg)
        base_text = ''
      end if
    end if
    if (len_trim(rc%list_file) > 0) then
      call read_text_file(join_path(dir_of(path), rc%list_file), list_text, st, msg)
      if (st /= 0) then
        call errors%add(path//': &campaign: list_file = '//quote_text(trim(rc%list_file))//': cannot read '// &
                        quote_text(join_path(dir_of(path), rc%list_file))//': '//msg)
        list_text = ''
      end if
    end if
    call build_campaign(path, text, base_text, list_text, camp, errors, st)
    stat = merge(0, 1, errors%count() == n0)
  end subroutine load_campaign

  !> With a summary file given on the command line (-o), the time-history files follow it
  !! (<summary without .h5>_case<id>.h5) unless the deck names history_prefix, so that two runs
  !! with different -o never overwrite each other's histories. Call on every rank after the
  !! campaign is built (camp%summary_file, the deck's, is left as it is).
  subroutine use_summary_file(camp, path)
    type(campaign_t), intent(inout) :: camp    !! campaign [-]
    character(len=*), intent(in) :: path       !! summary file from -o ('' keeps the deck's) [-]
    if (len(path) == 0) return
    if (.not. camp%history_prefix_given) camp%history_prefix = strip_h5(path)//'_case'
  end subroutine use_summary_file

  !> Build a campaign from the texts of its deck, base deck and case list ('' when absent).
  !! stat = 0 ready, 1 problems found (appended to `errors`).
  subroutine build_campaign(deck_name, deck_text, base_text, list_text, camp, errors, stat)
    character(len=*), intent(in) :: deck_name      !! campaign deck path [-]
    character(len=*), intent(in) :: deck_text      !! campaign deck text [-]
    character(len=*), intent(in) :: base_text      !! base run deck text ('' if unreadable) [-]
    character(len=*), intent(in) :: list_text      !! case list text ('' if none) [-]
    type(campaign_t), intent(out) :: camp          !! the campaign [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    integer, intent(out) :: stat                   !! 0 ok, 1 problems [-]
    type(raw_campaign_t) :: rc
    integer :: n0
    n0 = errors%count()
    call parse_campaign_deck(deck_text, deck_name, camp, rc, errors)
    camp%base_text = base_text
    camp%list_text = list_text
    ! an empty base deck is valid (the defaults); an empty case list is reported by attach_list
    if (len_trim(rc%base_deck) > 0) call attach_base_deck(camp, errors)
    if (camp%mode == 'list' .and. len_trim(rc%list_file) > 0) call attach_list(camp, errors)
    if (errors%count() == n0) call finish_campaign(camp, rc, errors)
    stat = merge(0, 1, errors%count() == n0)
  end subroutine build_campaign

  !> Whole file as one string.
  subroutine read_text_file(path, text, stat, msg)
    character(len=*), intent(in) :: path                 !! file name [-]
    character(len=:), allocatable, intent(out) :: text   !! contents [-]
    integer, intent(out) :: stat                         !! 0 ok [-]
    character(len=:), allocatable, intent(out) :: msg    !! reason on failure [-]
    call read_whole_file(path, text, stat, msg)
  end subroutine read_text_file

  ! ================================================================ deck parsing

  !> Read the campaign deck's groups item by item into `camp` (and the raw &campaign values).
  subroutine parse_campaign_deck(text, deck_name, camp, rc, errors)
    character(len=*), intent(in) :: text           !! deck text [-]
    character(len=*), intent(in) :: deck_name      !! deck path [-]
    type(campaign_t), intent(inout) :: camp        !! campaign filled from the deck [-]
    type(raw_campaign_t), intent(out) :: rc        !! raw &campaign values [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    type(nml_group_t), allocatable :: groups(:)
    type(raw_parameter_t), allocatable :: rp(:)
    type(raw_criteria_t) :: rcr
    character(len=20), allocatable :: given(:)
    integer :: ig, n_campaign, n_criteria, np, line_campaign, line_criteria
    integer, allocatable :: plines(:)

    camp%deck_name = deck_name
    camp%deck_text = text
    camp%title = ''
    call split_namelist(text, deck_name, groups, errors)
    n_campaign = 0
    n_criteria = 0
    line_campaign = 0
    line_criteria = 0
    allocate (rp(0), plines(0))
    do ig = 1, size(groups)
      associate (g => groups(ig))
        if (len(g%name) == 0) cycle
        select case (g%name)
        case ('campaign')
          n_campaign = n_campaign + 1
          if (n_campaign > 1) then
            call errors%add(deck_name//':'//int_text(g%line)//': &campaign: group given a second time (first at line '// &
                            int_text(line_campaign)//'); give it once')
            cycle
          end if
          line_campaign = g%line
          call read_campaign_group(g, deck_name, rc, errors)
        case ('parameter')
          rp = [rp, raw_parameter_t()]
          plines = [plines, g%line]
          call read_parameter_group(g, deck_name, rp(size(rp)), given, errors)
          if (len_trim(rp(size(rp))%name) == 0) call errors%add(deck_name//':'//int_text(g%line)// &
            ": &parameter: name is not given; valid: the input to vary, e.g. name = 'initial_state%velocity(1)'")
        case ('criteria')
          n_criteria = n_criteria + 1
          if (n_criteria > 1) then
            call errors%add(deck_name//':'//int_text(g%line)//': &criteria: group given a second time (first at line '// &
                            int_text(line_criteria)//'); give it once')
            cycle
          end if
          line_criteria = g%line
          call read_criteria_group(g, deck_name, rcr, errors)
        case default
          call errors%add(deck_name//':'//int_text(g%line)//": unknown namelist group '&"//g%name//"'"// &
                          close_name_hint(g%name, [character(len=9) :: 'campaign', 'parameter', 'criteria'])// &
                          '; valid groups in a campaign deck: &campaign, &parameter, &criteria')
        end select
      end associate
    end do
    if (n_campaign == 0) then
      call errors%add(deck_name//': no &campaign group; a campaign deck needs &campaign with at least '// &
                      'base_deck and mode')
      return
    end if

    ! ---- &campaign
    camp%title = trim(rc%title)
    camp%mode = lower_case(trim(adjustl(rc%mode)))
    camp%seed = rc%seed
    camp%checkpoint_interval = rc%checkpoint_interval
    camp%base_path = join_path(dir_of(deck_name), rc%base_deck)
    camp%list_path = join_path(dir_of(deck_name), rc%list_file)
    if (len_trim(rc%base_deck) == 0) call errors%add(deck_name// &
      ': &campaign: base_deck is not given; valid: the run deck (namelist) that every case starts from')
    select case (camp%mode)
    case ('grid', 'monte_carlo', 'list')
    case default
      call errors%add(deck_name//': &campaign: mode = '//quote_text(trim(rc%mode))// &
                      " is invalid; valid: 'grid', 'monte_carlo' or 'list'")
    end select
    if (camp%mode == 'monte_carlo') then
      if (rc%n_samples < 1) call errors%add(deck_name//': &campaign: n_samples = '//int_text(rc%n_samples)// &
        ' is invalid; valid: n_samples >= 1 (the number of Monte Carlo cases)')
      if (rc%n_samples > max_cases) call errors%add(deck_name//': &campaign: n_samples = '//int_text(rc%n_samples)// &
        ' is invalid; valid: n_samples <= '//int_text(max_cases))
      camp%n_samples = rc%n_samples
    else if (rc%n_samples /= -1 .and. len_trim(camp%mode) > 0) then
      call errors%add(deck_name//': &campaign: n_samples = '//int_text(rc%n_samples)//' is not used in mode '// &
                      quote_text(trim(camp%mode))//' (only in monte_carlo); remove it')
    end if
    if (camp%mode == 'list') then
      if (len_trim(rc%list_file) == 0) call errors%add(deck_name// &
        ': &campaign: list_file is not given; valid: a CSV file with one column per input and one row per case')
      if (size(rp) > 0) call errors%add(deck_name//':'//int_text(plines(1))// &
        ': &parameter: not used in list mode (the columns of list_file name the inputs); remove the &parameter groups')
    else if (len_trim(rc%list_file) > 0 .and. len_trim(camp%mode) > 0) then
      call errors%add(deck_name//': &campaign: list_file = '//quote_text(trim(rc%list_file))// &
                      " is only used in mode 'list'; remove it")
    end if
    if (.not. ieee_is_finite(rc%checkpoint_interval) .or. rc%checkpoint_interval < 0.0_wp) &
      call errors%add(deck_name//': &campaign: checkpoint_interval = '//real_text_short(rc%checkpoint_interval)// &
                      ' s is invalid; valid: checkpoint_interval >= 0 s')
    if (len_trim(rc%summary_file) > 0) then
      camp%summary_file = trim(rc%summary_file)
    else
      camp%summary_file = base_name_no_ext(deck_name)//'.h5'
    end if
    if (len_trim(rc%history_prefix) > 0) then
      camp%history_prefix = trim(rc%history_prefix)
      camp%history_prefix_given = .true.
    else
      camp%history_prefix = strip_h5(camp%summary_file)//'_case'
    end if
    camp%save_histories = pack(rc%save_histories, rc%save_histories /= 0)

    ! ---- &parameter
    if (camp%mode == 'grid' .or. camp%mode == 'monte_carlo') then
      if (size(rp) == 0) call errors%add(deck_name//': no &parameter group; mode '//quote_text(trim(camp%mode))// &
                                         ' needs one &parameter group per varied input')
      if (size(rp) > max_params) call errors%add(deck_name//': '//int_text(size(rp))// &
        ' &parameter groups; valid: at most '//int_text(max_params))
      allocate (camp%par(size(rp)))
      do np = 1, size(rp)
        call make_param(rp(np), plines(np), camp%mode, deck_name, camp%par(np), errors)
      end do
      camp%n_par = size(rp)
    else
      allocate (camp%par(0))
    end if

    ! ---- &criteria
    call make_criteria(rcr, deck_name, camp%crit, errors)
  end subroutine parse_campaign_deck

  !> Items of &campaign, each read on its own.
  subroutine read_campaign_group(g, deck_name, rc, errors)
    type(nml_group_t), intent(in) :: g             !! the group [-]
    character(len=*), intent(in) :: deck_name      !! deck path [-]
    type(raw_campaign_t), intent(inout) :: rc      !! values read [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    character(len=256) :: msg
    character(len=:), allocatable :: buffer
    integer :: k, ios, iv
    character(len=20), allocatable :: given(:)
    character(len=256) :: title
    character(len=path_len) :: base_deck, summary_file, history_prefix, list_file
    character(len=32) :: mode
    integer :: n_samples, save_histories(max_saved)
    integer(int64) :: seed
    real(wp) :: checkpoint_interval
    namelist /campaign/ title, base_deck, mode, n_samples, seed, summary_file, history_prefix, save_histories, &
      list_file, checkpoint_interval
    allocate (given(0))
    do k = 1, g%n_items
      associate (it => g%items(k))
        iv = check_item(it, 'campaign', campaign_vars, campaign_takes, deck_name, given, errors)
        if (iv == 0) cycle
        title = rc%title
        base_deck = rc%base_deck
        mode = rc%mode
        n_samples = rc%n_samples
        seed = rc%seed
        summary_file = rc%summary_file
        history_prefix = rc%history_prefix
        save_histories = rc%save_histories
        list_file = rc%list_file
        checkpoint_interval = rc%checkpoint_interval
        msg = ''
        buffer = '&campaign '//it%lhs//' = '//it%value//' /'
        read (buffer, nml=campaign, iostat=ios, iomsg=msg)
        if (ios /= 0) then
          call read_error(deck_name, it, 'campaign', campaign_takes(iv), msg, errors)
          cycle
        end if
        rc%title = title
        rc%base_deck = base_deck
        rc%mode = mode
        rc%n_samples = n_samples
        rc%seed = seed
        rc%summary_file = summary_file
        rc%history_prefix = history_prefix
        rc%save_histories = save_histories
        rc%list_file = list_file
        rc%checkpoint_interval = checkpoint_interval
      end associate
    end do
  end subroutine read_campaign_group

  !> Items of one &parameter, each read on its own; `given` lists the variables given.
  subroutine read_parameter_group(g, deck_name, rp, given, errors)
    type(nml_group_t), intent(in) :: g                      !! the group [-]
    character(len=*), intent(in) :: deck_name               !! deck path [-]
    type(raw_parameter_t), intent(inout) :: rp              !! values read [-]
    character(len=20), allocatable, intent(out) :: given(:) !! variables given [-]
    type(input_errors_t), intent(inout) :: errors           !! problems are appended here [-]
    character(len=256) :: msg
    character(len=:), allocatable :: buffer
    integer :: k, ios, iv
    character(len=name_len) :: name
    character(len=label_len) :: label
    real(wp) :: values(max_values), start, stop, lo, hi, mean, sd, weights(max_values)
    integer :: count
    character(len=32) :: distribution
    namelist /parameter/ name, label, values, start, stop, count, distribution, lo, hi, mean, sd, weights
    allocate (given(0))
    do k = 1, g%n_items
      associate (it => g%items(k))
        iv = check_item(it, 'parameter', parameter_vars, parameter_takes, deck_name, given, errors)
        if (iv == 0) cycle
        name = rp%name
        label = rp%label
        values = rp%values
        start = rp%start
        stop = rp%stop
        count = rp%count
        distribution = rp%distribution
        lo = rp%lo
        hi = rp%hi
        mean = rp%mean
        sd = rp%sd
        weights = rp%weights
        msg = ''
        buffer = '&parameter '//it%lhs//' = '//it%value//' /'
        read (buffer, nml=parameter, iostat=ios, iomsg=msg)
        if (ios == 0) then
          if (.not. all(ieee_is_finite([values, start, stop, lo, hi, mean, sd, weights]))) then
            ios = -1
            msg = 'not a finite number'
          end if
        end if
        if (ios /= 0) then
          call read_error(deck_name, it, 'parameter', parameter_takes(iv), msg, errors)
          cycle
        end if
        rp%name = name
        rp%label = label
        rp%values = values
        rp%start = start
        rp%stop = stop
        rp%count = count
        rp%distribution = distribution
        rp%lo = lo
        rp%hi = hi
        rp%mean = mean
        rp%sd = sd
        rp%weights = weights
      end associate
    end do
  end subroutine read_parameter_group

  !> Items of &criteria, each read on its own.
  subroutine read_criteria_group(g, deck_name, rcr, errors)
    type(nml_group_t), intent(in) :: g             !! the group [-]
    character(len=*), intent(in) :: deck_name      !! deck path [-]
    type(raw_criteria_t), intent(inout) :: rcr     !! values read [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    character(len=256) :: msg
    character(len=:), allocatable :: buffer
    character(len=20), allocatable :: given(:)
    integer :: k, ios, iv
    real(wp) :: min_stroke_margin, max_overload, min_body_clearance, body_point(3, max_body_points)
    logical :: require_at_rest
    character(len=32) :: failed_runs
    namelist /criteria/ min_stroke_margin, max_overload, min_body_clearance, body_point, require_at_rest, failed_runs
    allocate (given(0))
    do k = 1, g%n_items
      associate (it => g%items(k))
        iv = check_item(it, 'criteria', criteria_vars, criteria_takes, deck_name, given, errors)
        if (iv == 0) cycle
        min_stroke_margin = rcr%min_stroke_margin
        max_overload = rcr%max_overload
        min_body_clearance = rcr%min_body_clearance
        body_point = rcr%body_point
        require_at_rest = rcr%require_at_rest
        failed_runs = rcr%failed_runs
        msg = ''
        buffer = '&criteria '//it%lhs//' = '//it%value//' /'
        read (buffer, nml=criteria, iostat=ios, iomsg=msg)
        if (ios == 0) then
          if (.not. all(ieee_is_finite([min_stroke_margin, max_overload, min_body_clearance, body_point]))) then
            ios = -1
            msg = 'not a finite number'
          end if
        end if
        if (ios /= 0) then
          call read_error(deck_name, it, 'criteria', criteria_takes(iv), msg, errors)
          cycle
        end if
        rcr%min_stroke_margin = min_stroke_margin
        rcr%max_overload = max_overload
        rcr%min_body_clearance = min_body_clearance
        rcr%body_point = body_point
        rcr%require_at_rest = require_at_rest
        rcr%failed_runs = failed_runs
      end associate
    end do
  end subroutine read_criteria_group

  !> Checks an item's variable name (known, given once, has a value). Returns its index in
  !! `vars`, or 0 after reporting the problem.
  function check_item(it, group, vars, takes, deck_name, given, errors) result(iv)
    type(nml_item_t), intent(in) :: it                     !! the item [-]
    character(len=*), intent(in) :: group                  !! group name [-]
    character(len=*), intent(in) :: vars(:)                !! the group's variables [-]
    character(len=*), intent(in) :: takes(:)               !! what each variable takes [-]
    character(len=*), intent(in) :: deck_name              !! deck path [-]
    character(len=20), allocatable, intent(inout) :: given(:)  !! keys given so far [-]
    type(input_errors_t), intent(inout) :: errors          !! problems are appended here [-]
    integer :: iv                                          !! index in vars, 0 on a problem [-]
    character(len=:), allocatable :: pre
    pre = deck_name//':'//int_text(it%line)//': &'//group//': '
    do iv = 1, size(vars)
      if (trim(vars(iv)) == it%base) exit
    end do
    if (iv > size(vars)) then
      iv = 0
      call errors%add(pre//"unknown variable '"//it%lhs//"' ("//it%lhs//' = '//it%value//')'// &
                      hint_and_list(close_name_hint(it%base, vars), name_list(vars)))
      return
    end if
    if (any(given == it%key(1:min(len(it%key), 20)))) then
      call errors%add(pre//it%lhs//' is given more than once ('//it%lhs//' = '//it%value//'); give it once')
      iv = 0
      return
    end if
    given = [character(len=20) :: given, it%key(1:min(len(it%key), 20))]
    if (len_trim(it%value) == 0) then
      call errors%add(pre//'no value given for '//it%lhs//' ('//trim(vars(iv))//' takes '//trim(takes(iv))//')')
      iv = 0
    end if
  end function check_item

  subroutine read_error(deck_name, it, group, takes, msg, errors)
    character(len=*), intent(in) :: deck_name      !! deck path [-]
    type(nml_item_t), intent(in) :: it             !! the item [-]
    character(len=*), intent(in) :: group          !! group name [-]
    character(len=*), intent(in) :: takes          !! what the variable takes [-]
    character(len=*), intent(in) :: msg            !! iomsg [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    call errors%add(deck_name//':'//int_text(it%line)//': &'//group//': cannot read '//it%lhs//' = '// &
                    quote_text(it%value)//' ('//it%base//' takes '//trim(takes)//'): '//trim(msg))
  end subroutine read_error

  !> "; did you mean 'x'? (valid: a, b)" or "; valid: a, b".
  pure function hint_and_list(hint, list) result(s)
    character(len=*), intent(in) :: hint  !! '' or "; did you mean 'x'?" [-]
    character(len=*), intent(in) :: list  !! valid names [-]
    character(len=:), allocatable :: s    !! message tail [-]
    if (len(hint) > 0) then
      s = hint//' (valid: '//list//')'
    else
      s = '; valid: '//list
    end if
  end function hint_and_list

  pure function name_list(vars) result(s)
    character(len=*), intent(in) :: vars(:)  !! names [-]
    character(len=:), allocatable :: s       !! 'a, b, c' [-]
    integer :: i
    s = ''
    do i = 1, size(vars)
      if (i > 1) s = s//', '
      s = s//trim(vars(i))
    end do
  end function name_list

  ! ================================================================ parameters

  !> Turn a raw &parameter into a parameter of the campaign (mode-dependent checks).
  subroutine make_param(rp, line, mode, deck_name, p, errors)
    type(raw_parameter_t), intent(in) :: rp        !! values read [-]
    integer, intent(in) :: line                    !! line of the group [-]
    character(len=*), intent(in) :: mode           !! campaign mode [-]
    character(len=*), intent(in) :: deck_name      !! deck path [-]
    type(param_t), intent(out) :: p                !! the parameter [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    character(len=:), allocatable :: pre, msg, dist
    integer :: nv, nw, i
    real(wp) :: mass, a, b

    p%line = line
    pre = deck_name//':'//int_text(line)//': &parameter'
    if (len_trim(rp%name) == 0) return   ! reported already
    call parse_target(rp%name, p, msg)
    if (len(msg) > 0) then
      call errors%add(pre//': name = '//quote_text(trim(rp%name))//' is invalid: '//msg)
      return
    end if
    pre = pre//" '"//p%name//"'"
    if (len_trim(rp%label) > 0) then
      p%label = trim(rp%label)
      if (.not. valid_label(p%label)) call errors%add(pre//': label = '//quote_text(p%label)// &
        ' is invalid; valid: letters, digits, _ . - (at most 64, not starting with .)')
    end if
    call count_set(rp%values, nv, msg)
    if (len(msg) > 0) call errors%add(pre//': values '//msg)
    call count_set(rp%weights, nw, msg)
    if (len(msg) > 0) call errors%add(pre//': weights '//msg)
    dist = lower_case(trim(adjustl(rp%distribution)))

    select case (mode)
    case ('grid')
      p%kind = 'grid'
      if (len(dist) > 0) call errors%add(pre//': distribution = '//quote_text(dist)// &
        ' is not used in grid mode (grids take values, or start, stop and count); remove it')
      call not_given(is_set(rp%lo), 'lo')
      call not_given(is_set(rp%hi), 'hi')
      call not_given(is_set(rp%mean), 'mean')
      call not_given(is_set(rp%sd), 'sd')
      call not_given(nw > 0, 'weights')
      if (nv > 0) then
        if (is_set(rp%start) .or. is_set(rp%stop) .or. rp%count /= -1) then
          call errors%add(pre//': give either values or start, stop and count, not both')
        end if
        p%values = rp%values(1:nv)
      else if (rp%count /= -1 .or. is_set(rp%start) .or. is_set(rp%stop)) then
        if (rp%count < 1) then
          call errors%add(pre//': count = '//int_text(rp%count)//' is invalid; valid: count >= 1 (with start and stop)')
        else if (.not. is_set(rp%start)) then
          call errors%add(pre//': start is not given; valid: the first grid value (with stop and count)')
        else if (rp%count == 1) then
          p%values = [rp%start]
        else if (.not. is_set(rp%stop)) then
          call errors%add(pre//': stop is not given; valid: the last grid value (with start and count)')
        else if (rp%count > max_values) then
          call errors%add(pre//': count = '//int_text(rp%count)//' is invalid; valid: count <= '//int_text(max_values))
        else
          allocate (p%values(rp%count))
          do i = 1, rp%count
            p%values(i) = rp%start + (rp%stop - rp%start)*real(i - 1, wp)/real(rp%count - 1, wp)
          end do
          p%values(rp%count) = rp%stop
        end if
      else
        call errors%add(pre//': no grid values; valid: values = v1, v2, ... or start, stop and count')
      end if
      if (allocated(p%values)) call check_integral(p%values)

    case ('monte_carlo')
      call not_given(is_set(rp%start), 'start')
      call not_given(is_set(rp%stop), 'stop')
      call not_given(rp%count /= -1, 'count')
      select case (dist)
      case ('uniform')
        p%kind = 'uniform'
        call not_given(is_set(rp%mean), 'mean')
        call not_given(is_set(rp%sd), 'sd')
        call not_given(nv > 0, 'values')
        call not_given(nw > 0, 'weights')
        if (.not. (is_set(rp%lo) .and. is_set(rp%hi))) then
          call errors%add(pre//": distribution 'uniform' needs lo and hi")
        else if (.not. rp%lo < rp%hi) then
          call errors%add(pre//': lo = '//real_text_short(rp%lo)//', hi = '//real_text_short(rp%hi)// &
                          ' is invalid; valid: lo < hi')
        end if
        p%lo = rp%lo
        p%hi = rp%hi
        if (p%is_int) call errors%add(pre//": is an integer input; valid distribution: 'discrete'")
      case ('normal')
        p%kind = 'normal'
        call not_given(nv > 0, 'values')
        call not_given(nw > 0, 'weights')
        if (.not. (is_set(rp%mean) .and. is_set(rp%sd))) then
          call errors%add(pre//": distribution 'normal' needs mean and sd (lo and hi truncate it, optional)")
        else if (.not. rp%sd > 0.0_wp) then
          call errors%add(pre//': sd = '//real_text_short(rp%sd)//' is invalid; valid: sd > 0')
        else
          a = -huge(1.0_wp)
          b = huge(1.0_wp)
          if (is_set(rp%lo)) a = rp%lo
          if (is_set(rp%hi)) b = rp%hi
          if (.not. a < b) then
            call errors%add(pre//': lo = '//real_text_short(a)//', hi = '//real_text_short(b)// &
                            ' is invalid; valid: lo < hi')
          else
            mass = 0.5_wp*(erf(scaled(b)) - erf(scaled(a)))
            if (mass < min_truncated_mass) call errors%add(pre//': the truncation lo .. hi keeps only '// &
              real_text_short(mass)//' of the normal distribution; valid: at least 1e-3 (widen lo .. hi)')
          end if
        end if
        p%mean = rp%mean
        p%sd = rp%sd
        p%lo = rp%lo
        p%hi = rp%hi
        if (p%is_int) call errors%add(pre//": is an integer input; valid distribution: 'discrete'")
      case ('discrete')
        p%kind = 'discrete'
        call not_given(is_set(rp%lo), 'lo')
        call not_given(is_set(rp%hi), 'hi')
        call not_given(is_set(rp%mean), 'mean')
        call not_given(is_set(rp%sd), 'sd')
        if (nv == 0) then
          call errors%add(pre//": distribution 'discrete' needs values (and optional weights)")
        else
          p%values = rp%values(1:nv)
          call check_integral(p%values)
          if (nw == 0) then
            p%weights = [(real(i, wp)/real(nv, wp), i=1, nv)]
          else if (nw /= nv) then
            call errors%add(pre//': '//int_text(nw)//' weights for '//int_text(nv)// &
                            ' values; valid: one weight per value')
          else if (any(rp%weights(1:nw) < 0.0_wp) .or. .not. sum(rp%weights(1:nw)) > 0.0_wp) then
            call errors%add(pre//': weights are invalid; valid: weights >= 0 with a positive sum')
          else
            allocate (p%weights(nv))
            a = sum(rp%weights(1:nw))
            b = 0.0_wp
            do i = 1, nv
              b = b + rp%weights(i)
              p%weights(i) = b/a
            end do
            p%weights(nv) = 1.0_wp
          end if
        end if
      case ('')
        call errors%add(pre//": distribution is not given; valid: 'uniform' (lo, hi), 'normal' (mean, sd, "// &
                        "optional lo, hi) or 'discrete' (values, optional weights)")
      case default
        call errors%add(pre//': distribution = '//quote_text(dist)//" is invalid; valid: 'uniform', 'normal' "// &
                        "or 'discrete'")
      end select
    end select
    if (.not. allocated(p%values)) allocate (p%values(0))
    if (.not. allocated(p%weights)) allocate (p%weights(0))

  contains

    subroutine not_given(given, var)
      logical, intent(in) :: given          !! the variable was given [-]
      character(len=*), intent(in) :: var  !! its name [-]
      if (given) call errors%add(pre//': '//var//' is not used by '//describe_kind()//'; remove it')
    end subroutine not_given

    function describe_kind() result(s)
      character(len=:), allocatable :: s  !! e.g. "a grid", "distribution 'uniform'" [-]
      if (mode == 'grid') then
        s = 'a grid parameter'
      else
        s = "distribution '"//dist//"'"
      end if
    end function describe_kind

    subroutine check_integral(v)
      real(wp), intent(in) :: v(:)  !! values [-]
      integer :: j
      if (.not. p%is_int) return
      do j = 1, size(v)
        if (abs(v(j)) > 1.0e9_wp .or. abs(v(j) - anint(v(j))) > 0.0_wp) then
          call errors%add(pre//': value '//real_text_short(v(j))//' is invalid for an integer input; '// &
                          'valid: whole numbers')
          return
        end if
      end do
    end subroutine check_integral

    !> (x - mean)/(sqrt(2) sd), limited to +-6 (erf is +-1 to double precision there).
    elemental function scaled(x) result(y)
      real(wp), intent(in) :: x  !! truncation bound [deck unit]
      real(wp) :: y              !! scaled bound [-]
      real(wp), parameter :: ymax = 6.0_wp
      if (abs(x - rp%mean) >= ymax*sqrt(2.0_wp)*rp%sd) then
        y = sign(ymax, x - rp%mean)
      else
        y = (x - rp%mean)/(sqrt(2.0_wp)*rp%sd)
      end if
    end function scaled

  end subroutine make_param

  !> Number of leading set entries of an array read with unset defaults; msg /= '' on gaps.
  subroutine count_set(x, n, msg)
    real(wp), intent(in) :: x(:)                       !! array [any unit]
    integer, intent(out) :: n                          !! leading set entries [-]
    character(len=:), allocatable, intent(out) :: msg  !! problem, '' if none [-]
    integer :: i
    msg = ''
    n = 0
    do i = 1, size(x)
      if (.not. is_set(x(i))) exit
      n = i
    end do
    if (any(is_set(x(n + 1:)))) msg = 'have gaps (an element not given between given ones); give them in order from 1'
  end subroutine count_set

  !> Parse 'group%variable(subscript)' into `p` (name, group, lhs, units, elements);
  !! msg /= '' says what is wrong.
  subroutine parse_target(name_in, p, msg)
    character(len=*), intent(in) :: name_in            !! the input name as given [-]
    type(param_t), intent(inout) :: p                  !! parameter updated [-]
    character(len=:), allocatable, intent(out) :: msg  !! problem, '' if none [-]
    character(len=:), allocatable :: nm, grp, var, sub, part, rest, why
    character(len=20), allocatable :: names(:)
    type(tvar_t) :: tv
    integer :: pp, pq, iv, k, i, j, ext(2), lo(2), hi(2), nsub, rank
    msg = ''
    nm = ''
    do i = 1, len_trim(name_in)
      if (name_in(i:i) /= ' ') nm = nm//lower_case(name_in(i:i))
    end do
    pp = index(nm, '%')
    if (pp == 0) then
      msg = "valid: group%variable(index) as in the run decks, e.g. 'initial_state%velocity(1)' or 'terrain%slope(:)'"
      return
    end if
    grp = nm(1:pp - 1)
    if (.not. any(run_groups == grp)) then
      msg = "unknown run-deck group '"//grp//"'"//hint_and_list(close_name_hint(grp, run_groups), &
            name_list(run_groups))
      return
    end if
    pq = index(nm, '(')
    if (pq == 0) then
      var = nm(pp + 1:)
      sub = ''
    else
      var = nm(pp + 1:pq - 1)
      if (nm(len(nm):len(nm)) /= ')') then
        msg = "the subscript must end with ')'"
        return
      end if
      sub = nm(pq + 1:len(nm) - 1)
    end if
    do k = 1, size(fixed_vars)
      if (trim(fixed_vars(k)) == grp//'%'//var) then
        msg = grp//'%'//var//' cannot be varied by a campaign: '//trim(fixed_why(k))
        return
      end if
    end do
    iv = 0
    do k = 1, size(tvars)
      if (trim(tvars(k)%group) /= grp) cycle
      if (trim(tvars(k)%name) == var) iv = k
    end do
    if (iv > 0) then
      tv = tvars(iv)
    else
      ! not in the table: a variable the run decks gained later; learn it from the default deck
      call derive_target(grp, var, tv, names, why)
      if (len(why) > 0) then
        msg = grp//'%'//var//' cannot be varied by a campaign: '//why
        return
      end if
      if (len_trim(tv%name) == 0) then
        msg = "unknown variable '"//var//"' of &"//grp//hint_and_list(close_name_hint(var, names), name_list(names))
        return
      end if
    end if
    p%group = grp
    p%var = var
    p%units = trim(tv%unit)
    p%is_int = tv%is_int
    rank = 0
    if (tv%n1 > 0) rank = 1
    if (tv%n2 > 0) rank = 2
    ext = [max(tv%n1, 1), max(tv%n2, 1)]
    if (rank == 0) then
      if (len(sub) > 0) then
        msg = var//' is a scalar; give it without a subscript'
        return
      end if
      p%lhs = var
      p%n_elem = 1
      p%elems = [1]
      p%name = grp//'%'//var
      if (.not. allocated(p%label)) p%label = grp//'.'//var
      return
    end if
    if (len(sub) == 0) then
      if (rank == 1) then
        msg = var//' is an array of '//int_text(ext(1))//'; give an element, e.g. '//var//'(1), a range '//var// &
              '(1:2), or '//var//'(:) for all elements'
      else
        msg = var//' is a 3 x '//int_text(ext(2))//' array; give an element, e.g. '//var//'(3, 1), or a section, '// &
              'e.g. '//var//'(:, 1)'
      end if
      return
    end if
    ! subscripts
    rest = sub
    nsub = 0
    lo = 1
    hi = 1
    do
      pq = index(rest, ',')
      if (pq == 0) then
        part = rest
      else
        part = rest(1:pq - 1)
      end if
      nsub = nsub + 1
      if (nsub > rank) exit
      call parse_range(part, ext(nsub), lo(nsub), hi(nsub), msg)
      if (len(msg) > 0) then
        msg = 'subscript '//int_text(nsub)//" '"//part//"' of "//var//': '//msg
        return
      end if
      if (pq == 0) exit
      rest = rest(pq + 1:)
    end do
    if (nsub /= rank) then
      msg = var//' has '//int_text(rank)//' subscript(s); got '//int_text(nsub)//" in '("//sub//")'"
      return
    end if
    p%n_elem = (hi(1) - lo(1) + 1)*(hi(2) - lo(2) + 1)
    allocate (p%elems(p%n_elem))
    k = 0
    do j = lo(2), hi(2)
      do i = lo(1), hi(1)
        k = k + 1
        p%elems(k) = i + (j - 1)*ext(1)
      end do
    end do
    p%lhs = var//'('//sub//')'
    p%name = grp//'%'//var//'('//sub//')'
    if (.not. allocated(p%label)) then
      if (sub == ':' .and. rank == 1) then
        p%label = grp//'.'//var
      else
        p%label = grp//'.'//var//'_'//label_sub(sub)
      end if
    end if
  end subroutine parse_target

  !> A run-deck variable missing from the table `tvars`, learnt from the built-in default deck
  !! as resolved_input_text writes it ("  name = value   ! meaning [unit]"): scalars and vectors
  !! written whole are accepted, with the unit of the comment and the number of values as the
  !! extent (integer when the values have no decimal point or exponent). `tv%name` stays blank
  !! when the group has no such variable (`names` lists the group's variables then); `why` says
  !! why a variable that exists cannot be varied ('' otherwise).
  subroutine derive_target(grp, var, tv, names, why)
    character(len=*), intent(in) :: grp                    !! run-deck group [-]
    character(len=*), intent(in) :: var                    !! variable [-]
    type(tvar_t), intent(out) :: tv                        !! the variable's description [-]
    character(len=20), allocatable, intent(out) :: names(:)  !! the group's variables [-]
    character(len=:), allocatable, intent(out) :: why      !! why it cannot be varied, '' if it can [-]
    character(len=:), allocatable :: text, v, tok
    type(nml_group_t), allocatable :: groups(:)
    type(input_errors_t) :: errs
    integer :: ig, k, n, p, q, pb, ios, r, p0, p1, lineno
    type(landyn_input_t) :: probe
    why = ''
    tv = tvar_t('', '', '')
    allocate (names(0))
    text = resolved_input_text(default_input())
    call split_namelist(text, 'default deck', groups, errs)
    do ig = 1, size(groups)
      if (groups(ig)%name /= grp) cycle
      do k = 1, groups(ig)%n_items
        associate (it => groups(ig)%items(k))
          if (.not. any(names == it%base)) names = [character(len=20) :: names, it%base]
          if (it%base /= var .or. len_trim(tv%name) > 0 .or. len(why) > 0) cycle
          v = it%value
          if (it%key /= it%base) then
            why = 'it is a partly given or 2-D array that landyn_batch does not know yet; add it to the table '// &
                  'tvars in src/campaign/landyn_campaign_deck.f90'
          else if (v(1:1) == "'" .or. v(1:1) == '"') then
            why = 'it is text, not a number'
          else if (lower_case(v(1:min(len(v), 2))) == '.t' .or. lower_case(v(1:min(len(v), 2))) == '.f') then
            why = 'it is a logical, not a number'
          else
            ! count the values (r*value counts r) and see whether they are integers
            n = 0
            tv%is_int = .true.
            q = 1
            do while (q <= len(v))
              p = index(v(q:), ',')
              if (p == 0) then
                tok = trim(adjustl(v(q:)))
                q = len(v) + 1
              else
                tok = trim(adjustl(v(q:q + p - 2)))
                q = q + p
              end if
              r = 1
              pb = index(tok, '*')
              if (pb > 0) then
                read (tok(1:pb - 1), *, iostat=ios) r
                if (ios /= 0) r = 1
                tok = tok(pb + 1:)
              end if
              n = n + r
              if (scan(tok, '.eEdD') > 0) tv%is_int = .false.
            end do
            tv%group = grp
            tv%name = var
            tv%n1 = merge(0, n, n == 1)
            ! unit: the last [...] of the line's comment
            lineno = it%line
            call line_bounds(text, lineno, p0, p1)
            p = index(text(p0:p1), '!', back=.true.)
            tv%unit = '-'
            if (p > 0) then
              p = p0 + p - 1
              pb = index(text(p:p1), '[', back=.true.)
              q = index(text(p:p1), ']', back=.true.)
              if (pb > 0 .and. q > pb + 1) tv%unit = text(p + pb:p + q - 2)
            end if
          end if
        end associate
      end do
    end do
    if (len_trim(tv%name) == 0 .and. len(why) == 0) then
      ! not in the default deck (no default value): does the run-deck reader know it?
      n = errs%count()
      call read_input_text('&'//grp//' '//var//' = 1.0 /', '', probe, errs, ios)
      if (ios == 0 .and. errs%count() == n) why = 'landyn_batch does not know its unit and shape (it has no '// &
        'default value); add it to the table tvars in src/campaign/landyn_campaign_deck.f90'
    end if
  end subroutine derive_target

  !> The table of run-deck variables a campaign can vary (for the consistency test).
  subroutine run_variable_table(names, units, n1, n2, is_int)
    character(len=40), allocatable, intent(out) :: names(:)  !! 'group%variable' [-]
    character(len=8), allocatable, intent(out) :: units(:)   !! deck units [-]
    integer, allocatable, intent(out) :: n1(:), n2(:)        !! extents (0: none) [-]
    logical, allocatable, intent(out) :: is_int(:)           !! integer variables [-]
    integer :: k
    allocate (names(size(tvars)))
    do k = 1, size(tvars)
      names(k) = trim(tvars(k)%group)//'%'//trim(tvars(k)%name)
    end do
    units = tvars%unit
    n1 = tvars%n1
    n2 = tvars%n2
    is_int = tvars%is_int
  end subroutine run_variable_table

  !> A run-deck variable as the built-in default deck shows it (see derive_target).
  subroutine default_deck_variable(group, var, unit, n1, is_int, found, why)
    character(len=*), intent(in) :: group                !! run-deck group [-]
    character(len=*), intent(in) :: var                  !! variable [-]
    character(len=8), intent(out) :: unit                !! unit of its comment ('-' if none) [-]
    integer, intent(out) :: n1                           !! number of values (0: scalar) [-]
    logical, intent(out) :: is_int                       !! integer values [-]
    logical, intent(out) :: found                        !! written whole as a number [-]
    character(len=:), allocatable, intent(out) :: why    !! why it cannot be varied, '' if it can [-]
    type(tvar_t) :: tv
    character(len=20), allocatable :: names(:)
    call derive_target(group, var, tv, names, why)
    found = len_trim(tv%name) > 0
    unit = tv%unit
    n1 = tv%n1
    is_int = tv%is_int
  end subroutine default_deck_variable

  !> Every variable of the built-in default deck as 'group%variable' (once each).
  subroutine default_deck_variables(list)
    character(len=40), allocatable, intent(out) :: list(:)  !! variables [-]
    type(nml_group_t), allocatable :: groups(:)
    type(input_errors_t) :: errs
    character(len=40) :: nm
    integer :: ig, k
    allocate (list(0))
    call split_namelist(resolved_input_text(default_input()), 'default deck', groups, errs)
    do ig = 1, size(groups)
      do k = 1, groups(ig)%n_items
        nm = groups(ig)%name//'%'//groups(ig)%items(k)%base
        if (.not. any(list == nm)) list = [character(len=40) :: list, nm]
      end do
    end do
  end subroutine default_deck_variables

  !> Bounds text(p0:p1) of line number `line` (1-based) of a text.
  pure subroutine line_bounds(text, line, p0, p1)
    character(len=*), intent(in) :: text  !! text with new_line('a') line ends [-]
    integer, intent(in) :: line           !! line number [-]
    integer, intent(out) :: p0, p1        !! first and last position of the line [-]
    integer :: i, k
    p0 = 1
    p1 = len(text)
    k = 1
    do i = 1, len(text)
      if (text(i:i) /= new_line('a')) cycle
      if (k == line) then
        p1 = i - 1
        return
      end if
      k = k + 1
      p0 = i + 1
    end do
  end subroutine line_bounds

  !> One subscript: 'i', 'i:j', ':', 'i:' or ':j' within 1..ext.
  subroutine parse_range(part, ext, lo, hi, msg)
    character(len=*), intent(in) :: part               !! subscript text [-]
    integer, intent(in) :: ext                         !! extent of the dimension [-]
    integer, intent(out) :: lo, hi                     !! range [-]
    character(len=:), allocatable, intent(out) :: msg  !! problem, '' if none [-]
    integer :: pc, ios
    msg = ''
    lo = 1
    hi = ext
    pc = index(part, ':')
    ios = 0
    if (pc == 0) then
      read (part, *, iostat=ios) lo
      hi = lo
    else
      if (pc > 1) read (part(1:pc - 1), *, iostat=ios) lo
      if (ios == 0 .and. pc < len(part)) read (part(pc + 1:), *, iostat=ios) hi
    end if
    if (ios /= 0 .or. len(part) == 0 .or. verify(part, '0123456789:') /= 0) then
      msg = 'not an index or a range'
    else if (lo < 1 .or. hi > ext .or. lo > hi) then
      msg = 'out of range; valid: 1 .. '//int_text(ext)
    end if
  end subroutine parse_range

  !> Label suffix of a subscript: ':' -> 'all', 'i:j' -> 'i-j', ',' -> '_'.
  pure function label_sub(sub) result(s)
    character(len=*), intent(in) :: sub  !! subscript text [-]
    character(len=:), allocatable :: s   !! label suffix [-]
    character(len=:), allocatable :: part, rest
    integer :: pq
    s = ''
    rest = sub
    do
      pq = index(rest, ',')
      if (pq == 0) then
        part = rest
      else
        part = rest(1:pq - 1)
      end if
      if (len(s) > 0) s = s//'_'
      if (part == ':') then
        s = s//'all'
      else
        s = s//replace_char(part, ':', '-')
      end if
      if (pq == 0) exit
      rest = rest(pq + 1:)
    end do
  end function label_sub

  pure function replace_char(t, a, b) result(s)
    character(len=*), intent(in) :: t     !! text [-]
    character(len=1), intent(in) :: a, b  !! replace a by b [-]
    character(len=len(t)) :: s            !! result [-]
    integer :: i
    s = t
    do i = 1, len(s)
      if (s(i:i) == a) s(i:i) = b
    end do
  end function replace_char

  pure function valid_label(label) result(ok)
    character(len=*), intent(in) :: label  !! column name [-]
    logical :: ok                          !! letters, digits, _ . - ; not starting with '.' [-]
    ok = len(label) > 0 .and. len(label) <= label_len .and. &
         verify(label, 'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.-') == 0
    if (ok) ok = label(1:1) /= '.'
  end function valid_label

  !> &criteria values into the campaign.
  subroutine make_criteria(rcr, deck_name, crit, errors)
    type(raw_criteria_t), intent(in) :: rcr        !! values read [-]
    character(len=*), intent(in) :: deck_name      !! deck path [-]
    type(criteria_t), intent(out) :: crit          !! criteria [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    integer :: i, n
    crit%min_stroke_margin = rcr%min_stroke_margin
    crit%overload_applied = is_set(rcr%max_overload)
    if (crit%overload_applied) then
      crit%max_overload = rcr%max_overload
      if (.not. rcr%max_overload > 0.0_wp) call errors%add(deck_name//': &criteria: max_overload = '// &
        real_text_short(rcr%max_overload)//' g is invalid; valid: max_overload > 0 g')
    end if
    crit%clearance_applied = is_set(rcr%min_body_clearance)
    if (crit%clearance_applied) crit%min_body_clearance = rcr%min_body_clearance
    n = 0
    do i = 1, max_body_points
      if (all(is_set(rcr%body_point(:, i)))) then
        n = n + 1
        crit%body_point(:, n) = rcr%body_point(:, i)
      else if (any(is_set(rcr%body_point(:, i)))) then
        call errors%add(deck_name//': &criteria: body_point(:, '//int_text(i)// &
                        ') is given in part; valid: all three coordinates x, y, z')
      end if
    end do
    crit%n_body_points = n
    if (n == 0) then
      crit%n_body_points = 1
      crit%body_point(:, 1) = 0.0_wp
    end if
    crit%require_at_rest = rcr%require_at_rest
    crit%failed_runs = lower_case(trim(adjustl(rcr%failed_runs)))
    if (crit%failed_runs /= 'count_as_failure' .and. crit%failed_runs /= 'exclude') &
      call errors%add(deck_name//': &criteria: failed_runs = '//quote_text(trim(rcr%failed_runs))// &
                      " is invalid; valid: 'count_as_failure' or 'exclude'")
  end subroutine make_criteria

  ! ================================================================ base deck and case list

  !> Read, resolve and validate the base deck; split it for merging; check that a case without
  !! overrides reproduces it exactly.
  subroutine attach_base_deck(camp, errors)
    type(campaign_t), intent(inout) :: camp        !! campaign with base_path and base_text [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    type(landyn_input_t) :: inp, inp2
    type(input_errors_t) :: e1, e2
    type(campaign_t) :: probe
    integer :: st, i
    character(len=:), allocatable :: merged
    call read_input_text(camp%base_text, camp%base_path, inp, e1, st)
    call resolve_input(inp, e1)
    call validate_input(inp, e1)
    if (e1%count() > 0) then
      do i = 1, e1%count()
        call errors%add(e1%message(i))
      end do
      call errors%add(camp%deck_name//': &campaign: base_deck = '//quote_text(camp%base_path)// &
                      ' has '//int_text(e1%count())//' input error(s); every case starts from it')
      return
    end if
    camp%n_gears = inp%gears%n_gears
    call split_namelist(camp%base_text, camp%base_path, camp%base_groups, e2)
    if (e2%count() > 0) then
      call errors%add(camp%deck_name//': internal error: cannot split the base deck '//camp%base_path// &
                      ': '//e2%message(1))
      return
    end if
    probe%deck_name = camp%deck_name
    probe%base_path = camp%base_path
    probe%base_groups = camp%base_groups
    allocate (probe%par(0))
    merged = case_deck_text(probe, 0, [real(wp) ::])
    call read_input_text(merged, camp%base_path, inp2, e2, st)
    call resolve_input(inp2, e2)
    if (e2%count() > 0) then
      call errors%add(camp%deck_name//': internal error: the base deck rewritten for the cases does not read back: '// &
                      e2%message(1))
    else if (resolved_input_text(inp2) /= resolved_input_text(inp)) then
      call errors%add(camp%deck_name//': internal error: the base deck rewritten for the cases differs from '// &
                      camp%base_path)
    end if
  end subroutine attach_base_deck

  !> Read the case list (CSV: a header of input names, one row of numbers per case).
  subroutine attach_list(camp, errors)
    type(campaign_t), intent(inout) :: camp        !! campaign with list_path and list_text [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    character(len=:), allocatable :: line, msg, pre
    character(len=cell_len), allocatable :: cells(:), hdr(:)
    real(wp), allocatable :: rows(:, :), tmp(:, :)
    integer :: p0, p1, lineno, ncol, nrow, j, ios, n0, first
    logical :: header_done
    character(len=256) :: iomsg

    n0 = errors%count()
    header_done = .false.
    ncol = 0
    nrow = 0
    lineno = 0
    p0 = 1
    allocate (rows(0, 0))
    do while (p0 <= len(camp%list_text))
      p1 = index(camp%list_text(p0:), new_line('a'))
      if (p1 == 0) then
        line = camp%list_text(p0:)
        p0 = len(camp%list_text) + 1
      else
        line = camp%list_text(p0:p0 + p1 - 2)
        p0 = p0 + p1
      end if
      lineno = lineno + 1
      if (len(line) > 0) then
        if (line(len(line):len(line)) == achar(13)) line = line(1:len(line) - 1)
      end if
      if (len_trim(line) == 0) cycle
      first = verify(line, ' '//achar(9))
      if (line(first:first) == '#') cycle
      pre = camp%list_path//':'//int_text(lineno)//': '
      call split_csv(line, cells)
      if (.not. header_done) then
        header_done = .true.
        ncol = size(cells)
        hdr = cells
        if (allocated(camp%par)) deallocate (camp%par)
        allocate (camp%par(ncol))
        do j = 1, ncol
          camp%par(j)%kind = 'list'
          camp%par(j)%line = lineno
          call parse_target(trim(cells(j)), camp%par(j), msg)
          if (len(msg) > 0) call errors%add(pre//'column '//int_text(j)//' '//quote_text(trim(cells(j)))// &
                                            ' is not a campaign input: '//msg)
          allocate (camp%par(j)%values(0), camp%par(j)%weights(0))
        end do
        camp%n_par = ncol
        deallocate (rows)
        allocate (rows(ncol, 16))
        cycle
      end if
      if (size(cells) /= ncol) then
        call errors%add(pre//int_text(size(cells))//' values for '//int_text(ncol)//' columns; valid: one value '// &
                        'per column of the header')
        cycle
      end if
      nrow = nrow + 1
      if (nrow > size(rows, 2)) then
        allocate (tmp(ncol, 2*size(rows, 2)))
        tmp(:, 1:size(rows, 2)) = rows
        call move_alloc(tmp, rows)
      end if
      do j = 1, ncol
        iomsg = ''
        ios = 0
        ! one number per cell: no second value, separator or comment, nothing beyond |x| < 1e31
        if (scan(trim(adjustl(cells(j))), ' '//achar(9)//';#/*!') > 0 .or. &
            has_nonfinite_word(cells(j)) .or. .not. numbers_within(cells(j), 30) .or. &
            verify(trim(adjustl(cells(j))), '0123456789+-.eEdD') > 0) then
          ios = 1
        else
          read (cells(j), *, iostat=ios, iomsg=iomsg) rows(j, nrow)
        end if
        if (ios == 0) then
          if (.not. ieee_is_finite(rows(j, nrow))) ios = -1
        end if
        if (ios /= 0 .or. len_trim(cells(j)) == 0) then
          call errors%add(pre//'case '//int_text(nrow)//', column '//quote_text(trim(hdr(j)))//': '// &
                          quote_text(trim(cells(j)))//' is not a finite number (valid: one number per cell, |x| < 1e31)')
          rows(j, nrow) = 0.0_wp
        else if (camp%par(j)%is_int .and. abs(rows(j, nrow) - anint(rows(j, nrow))) > 0.0_wp) then
          call errors%add(pre//'case '//int_text(nrow)//', column '//quote_text(trim(hdr(j)))//': '// &
                          trim(cells(j))//' is invalid for an integer input; valid: whole numbers')
        end if
      end do
    end do
    if (.not. header_done) then
      call errors%add(camp%list_path//': the case list is empty; valid: a header line of input names, '// &
                      "e.g. 'initial_state%velocity(1), terrain%slope(:)', then one line of values per case")
      if (allocated(camp%par)) deallocate (camp%par)
      allocate (camp%par(0))
    else if (nrow == 0 .and. errors%count() == n0) then
      call errors%add(camp%list_path//': the case list has a header but no cases')
    end if
    camp%table = rows(:, 1:nrow)
    camp%n_cases = nrow
  end subroutine attach_list

  !> Split one CSV line on commas (no quoted commas); cells are trimmed, quotes removed.
  subroutine split_csv(line, cells)
    character(len=*), intent(in) :: line                         !! CSV line [-]
    character(len=cell_len), allocatable, intent(out) :: cells(:)  !! cells [-]
    integer :: n, i, p, q
    character(len=:), allocatable :: c
    n = 1
    do i = 1, len(line)
      if (line(i:i) == ',') n = n + 1
    end do
    allocate (cells(n))
    p = 1
    do i = 1, n
      q = index(line(p:), ',')
      if (q == 0) then
        c = trim(adjustl(line(p:)))
      else
        c = trim(adjustl(line(p:p + q - 2)))
        p = p + q
      end if
      if (len(c) >= 2) then
        if ((c(1:1) == '"' .or. c(1:1) == "'") .and. c(len(c):len(c)) == c(1:1)) c = c(2:len(c) - 1)
      end if
      cells(i) = c
    end do
  end subroutine split_csv

  !> Checks across the whole campaign; case count, defaults, fingerprint.
  subroutine finish_campaign(camp, rc, errors)
    type(campaign_t), intent(inout) :: camp        !! campaign [-]
    type(raw_campaign_t), intent(in) :: rc         !! raw &campaign values [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    integer :: i, j
    real(wp) :: ncase
    ! overlapping or duplicate targets and labels
    do i = 1, camp%n_par
      do j = 1, i - 1
        if (camp%par(i)%group == camp%par(j)%group .and. camp%par(i)%var == camp%par(j)%var) then
          if (overlap(camp%par(i)%elems, camp%par(j)%elems)) call errors%add(where_par(i)// &
            ': sets elements that '//quote_text(camp%par(j)%name)//' sets too; vary each element once')
        end if
        if (camp%par(i)%label == camp%par(j)%label) call errors%add(where_par(i)//': label '// &
          quote_text(camp%par(i)%label)//' is used by '//quote_text(camp%par(j)%name)//' too; labels must differ')
      end do
    end do
    select case (camp%mode)
    case ('grid')
      allocate (camp%grid_n(camp%n_par))
      ncase = 1.0_wp
      do i = 1, camp%n_par
        camp%grid_n(i) = size(camp%par(i)%values)
        ncase = ncase*real(camp%grid_n(i), wp)
      end do
      if (ncase > real(max_cases, wp)) then
        call errors%add(camp%deck_name//': the grid has '//real_text_short(ncase)//' cases; valid: at most '// &
                        int_text(max_cases))
      else
        camp%n_cases = product(camp%grid_n)
      end if
    case ('monte_carlo')
      camp%n_cases = camp%n_samples
    case ('list')
      continue   ! set by attach_list
    end select
    if (any(camp%save_histories < 1) .or. any(camp%save_histories > camp%n_cases)) then
      call errors%add(camp%deck_name//': &campaign: save_histories = '// &
                      ints_text(pack(camp%save_histories, camp%save_histories < 1 .or. &
                      camp%save_histories > camp%n_cases))//' is invalid; valid: case ids 1 .. '// &
                      int_text(camp%n_cases))
    end if
    if (len_trim(rc%summary_file) > 0 .and. camp%summary_file(len(camp%summary_file):) == '/') &
      call errors%add(camp%deck_name//': &campaign: summary_file = '//quote_text(camp%summary_file)// &
                      ' is invalid; valid: a file name')
    camp%fingerprint = text_fingerprint(fingerprint_text(camp))

  contains

    function where_par(k) result(s)
      integer, intent(in) :: k            !! parameter index [-]
      character(len=:), allocatable :: s  !! message prefix [-]
      if (camp%mode == 'list') then
        s = camp%list_path//': column '//int_text(k)//" '"//camp%par(k)%name//"'"
      else
        s = camp%deck_name//':'//int_text(camp%par(k)%line)//": &parameter '"//camp%par(k)%name//"'"
      end if
    end function where_par

  end subroutine finish_campaign

  pure function overlap(a, b) result(yes)
    integer, intent(in) :: a(:), b(:)  !! element index sets [-]
    logical :: yes                     !! they share an element [-]
    integer :: i
    yes = .false.
    do i = 1, size(a)
      if (any(b == a(i))) yes = .true.
    end do
  end function overlap

  pure function ints_text(v) result(s)
    integer, intent(in) :: v(:)         !! values [-]
    character(len=:), allocatable :: s  !! 'a, b, c' [-]
    integer :: i
    s = ''
    do i = 1, size(v)
      if (i > 1) s = s//', '
      s = s//int_text(v(i))
    end do
  end function ints_text

  pure function strip_h5(path) result(s)
    character(len=*), intent(in) :: path  !! file name [-]
    character(len=:), allocatable :: s    !! without a trailing '.h5' [-]
    s = trim(path)
    if (len(s) > 3) then
      if (lower_case(s(len(s) - 2:)) == '.h5') s = s(1:len(s) - 3)
    end if
  end function strip_h5

  !> Everything that determines the cases and their success (not n_samples: a Monte Carlo
  !! campaign may be extended on resume).
  function fingerprint_text(camp) result(s)
    type(campaign_t), intent(in) :: camp  !! campaign [-]
    character(len=:), allocatable :: s    !! canonical description [-]
    integer :: i, j
    character(len=24) :: buf
    write (buf, '(i0)') camp%seed
    s = 'mode='//trim(camp%mode)//';seed='//trim(buf)//';n_gears='//int_text(camp%n_gears)// &
        ';base='//camp%base_text//';list='//camp%list_text
    do i = 1, camp%n_par
      associate (p => camp%par(i))
        s = s//';par='//p%name//'|'//p%label//'|'//trim(p%kind)//'|'//real_text(p%lo)//'|'//real_text(p%hi)//'|'// &
            real_text(p%mean)//'|'//real_text(p%sd)//'|v'
        do j = 1, size(p%values)
          s = s//real_text(p%values(j))//','
        end do
        s = s//'|w'
        do j = 1, size(p%weights)
          s = s//real_text(p%weights(j))//','
        end do
      end associate
    end do
    associate (c => camp%crit)
      s = s//';crit='//real_text(c%min_stroke_margin)//'|'//merge('T', 'F', c%overload_applied)// &
          real_text(c%max_overload)//'|'//merge('T', 'F', c%clearance_applied)//real_text(c%min_body_clearance)// &
          '|'//merge('T', 'F', c%require_at_rest)//'|'//trim(c%failed_runs)//'|'
      do i = 1, c%n_body_points
        s = s//real_text(c%body_point(1, i))//real_text(c%body_point(2, i))//real_text(c%body_point(3, i))
      end do
    end associate
  end function fingerprint_text

  !> 64-bit hash of a text (SplitMix64 mixing of every byte), as 16 hex digits.
  function text_fingerprint(text) result(hex)
    character(len=*), intent(in) :: text  !! text [-]
    character(len=16) :: hex              !! hash [-]
    integer(int64) :: h
    integer :: i
    h = int(len(text), int64)
    do i = 1, len(text)
      h = splitmix64_mix(add64(ieor(h, int(iachar(text(i:i)), int64)), -7046029254386353131_int64))
    end do
    write (hex, '(z16.16)') h
  end function text_fingerprint

  ! ================================================================ cases

  !> The values of the varied inputs of case `id` (deck units). stat = 1 (with errmsg) when a
  !! truncated normal could not be sampled.
  subroutine case_values(camp, id, values, stat, errmsg)
    type(campaign_t), intent(in) :: camp               !! campaign [-]
    integer, intent(in) :: id                          !! case id, 1..n_cases [-]
    real(wp), intent(out) :: values(:)                 !! (n_par) values [deck unit]
    integer, intent(out) :: stat                       !! 0 ok [-]
    character(len=:), allocatable, intent(out) :: errmsg  !! problem [-]
    integer :: j, r, i
    real(wp) :: u, a, b
    stat = 0
    errmsg = ''
    select case (camp%mode)
    case ('grid')
      r = id - 1
      do j = 1, camp%n_par
        values(j) = camp%par(j)%values(mod(r, camp%grid_n(j)) + 1)
        r = r/camp%grid_n(j)
      end do
    case ('list')
      values = camp%table(:, id)
    case default
      do j = 1, camp%n_par
        associate (p => camp%par(j))
          select case (p%kind)
          case ('uniform')
            values(j) = p%lo + (p%hi - p%lo)*case_uniform(camp%seed, id, j, 0)
          case ('normal')
            a = -huge(1.0_wp)
            b = huge(1.0_wp)
            if (is_set(p%lo)) a = p%lo
            if (is_set(p%hi)) b = p%hi
            call case_truncated_normal(camp%seed, id, j, p%mean, p%sd, a, b, max_normal_tries, values(j), stat)
            if (stat /= 0) then
              errmsg = 'no normal sample of '//p%name//' fell inside lo .. hi in '//int_text(max_normal_tries)//' tries'
              return
            end if
          case default   ! discrete
            u = case_uniform(camp%seed, id, j, 0)
            values(j) = p%values(size(p%values))
            do i = 1, size(p%values)
              if (u < p%weights(i)) then
                values(j) = p%values(i)
                exit
              end if
            end do
          end select
        end associate
      end do
    end select
  end subroutine case_values

  !> The run deck of case `id`: the base deck's items with the case's overrides (module header).
  function case_deck_text(camp, id, values) result(text)
    type(campaign_t), intent(in) :: camp   !! campaign [-]
    integer, intent(in) :: id              !! case id (0: no case) [-]
    real(wp), intent(in) :: values(:)      !! (n_par) values [deck unit]
    character(len=:), allocatable :: text  !! namelist deck [-]
    integer :: ig, k, j
    logical, allocatable :: used(:)
    character(len=1), parameter :: nl = new_line('a')
    allocate (used(camp%n_par))
    used = .false.
    text = ''
    if (id > 0) text = '! campaign '//camp%deck_name//', case '//int_text(id)//': base deck '//camp%base_path// &
                       ' with the case''s inputs appended to their groups'//nl
    do ig = 1, size(camp%base_groups)
      associate (g => camp%base_groups(ig))
        text = text//'&'//g%name//nl
        do k = 1, g%n_items
          if (any([(camp%par(j)%group == g%name .and. lower_case(camp%par(j)%lhs) == g%items(k)%key, &
                    j=1, camp%n_par)])) cycle
          text = text//'  '//g%items(k)%lhs//' = '//g%items(k)%value//nl
        end do
        do j = 1, camp%n_par
          if (camp%par(j)%group /= g%name) cycle
          text = text//override_item(camp%par(j), values(j))//nl
          used(j) = .true.
        end do
        text = text//'/'//nl
      end associate
    end do
    do j = 1, camp%n_par
      if (used(j)) cycle
      text = text//'&'//camp%par(j)%group//nl
      do k = j, camp%n_par
        if (camp%par(k)%group /= camp%par(j)%group .or. used(k)) cycle
        text = text//override_item(camp%par(k), values(k))//nl
        used(k) = .true.
      end do
      text = text//'/'//nl
    end do
  end function case_deck_text

  !> '  name(sub) = n*value' for one parameter.
  function override_item(p, x) result(s)
    type(param_t), intent(in) :: p       !! parameter [-]
    real(wp), intent(in) :: x            !! value [deck unit]
    character(len=:), allocatable :: s   !! deck item [-]
    character(len=:), allocatable :: v
    if (p%is_int .and. abs(x) < 1.0e9_wp) then
      v = int_text(nint(x))
    else
      v = real_text(x)
    end if
    if (p%n_elem > 1) v = int_text(p%n_elem)//'*'//v
    s = '  '//p%lhs//' = '//v
  end function override_item

  !> The resolved, validated input of case `id` with values `values`, read through the run-deck
  !! reader. stat = 0 ready, 1 invalid (messages in `errors`).
  subroutine case_input(camp, id, values, inp, errors, stat)
    type(campaign_t), intent(in) :: camp           !! campaign [-]
    integer, intent(in) :: id                      !! case id [-]
    real(wp), intent(in) :: values(:)              !! (n_par) values [deck unit]
    type(landyn_input_t), intent(out) :: inp       !! input of the case [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    integer, intent(out) :: stat                   !! 0 ok, 1 invalid [-]
    integer :: n0, st
    n0 = errors%count()
    call read_input_text(case_deck_text(camp, id, values), camp%base_path//' (case '//int_text(id)//')', &
                         inp, errors, st)
    if (errors%count() == n0) then
      call resolve_input(inp, errors)
      call validate_input(inp, errors)
    end if
    if (errors%count() == n0 .and. inp%gears%n_gears /= camp%n_gears) &
      call errors%add('case '//int_text(id)//': n_gears = '//int_text(inp%gears%n_gears)// &
                      ' differs from the base deck''s '//int_text(camp%n_gears))
    stat = merge(0, 1, errors%count() == n0)
  end subroutine case_input

  !> One-line description of how a parameter is varied, e.g. "uniform(0, 2)".
  function param_description(p) result(s)
    type(param_t), intent(in) :: p      !! parameter [-]
    character(len=:), allocatable :: s  !! description [-]
    integer :: i
    select case (p%kind)
    case ('uniform')
      s = 'uniform(lo='//real_text_short(p%lo)//', hi='//real_text_short(p%hi)//')'
    case ('normal')
      s = 'normal(mean='//real_text_short(p%mean)//', sd='//real_text_short(p%sd)
      if (is_set(p%lo)) s = s//', lo='//real_text_short(p%lo)
      if (is_set(p%hi)) s = s//', hi='//real_text_short(p%hi)
      s = s//')'
    case ('discrete', 'grid')
      s = trim(p%kind)//'('
      do i = 1, min(size(p%values), 12)
        if (i > 1) s = s//', '
        s = s//real_text_short(p%values(i))
      end do
      if (size(p%values) > 12) s = s//', ... ('//int_text(size(p%values))//' values)'
      s = s//')'
    case default
      s = 'list'
    end select
    s = p%name//' ['//p%units//'] '//s
  end function param_description

end module landyn_campaign_deck
