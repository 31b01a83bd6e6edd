!> The data of a campaign (docs/campaign.md): the varied inputs (`param_t`), the success
!! criteria (`criteria_t`), the campaign itself (`campaign_t`) and the raw values of the campaign
!! deck's groups as read (before their checks), with the size limits of campaign decks.
module landyn_campaign_types
  use, intrinsic :: iso_fortran_env, only: int64
  use landyn_kinds, only: wp
  use landyn_config, only: unset_real, path_len
  use landyn_namelist_items, only: nml_group_t
  implicit none
  private

  public :: campaign_t, param_t, criteria_t, raw_campaign_t, raw_parameter_t, raw_criteria_t
  public :: max_values, max_saved, max_body_points, max_params, label_len, name_len, max_cases, max_normal_tries, &
            cell_len, min_truncated_mass

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
    logical :: require_at_rest = .false.            !! kept for old decks: a success must be at rest anyway [-]
    logical :: tipover_applied = .false.            !! min_tipover_margin given [-]
    real(wp) :: min_tipover_margin = 0.0_wp         !! final tip-over margin must be >= this [deg]
    logical :: friction_applied = .false.           !! max_friction_ratio given [-]
    real(wp) :: max_friction_ratio = 0.0_wp         !! every final |F_t|/(mu_s F_n) must be <= this [-]
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

  !> Raw &campaign values as read.
  type :: raw_campaign_t
    character(len=256) :: title = ''                 !! campaign title (summary file attribute) [-]
    character(len=path_len) :: base_deck = ''        !! base run deck, relative to the campaign deck's directory; '' not given [-]
    character(len=32) :: mode = ''                   !! 'grid', 'monte_carlo' or 'list' as written (case not yet folded) [-]
    integer :: n_samples = -1                        !! number of Monte Carlo cases; -1 not given [-]
    integer(int64) :: seed = 1_int64                 !! 64-bit seed of the Monte Carlo random numbers [-]
    character(len=path_len) :: summary_file = ''     !! summary file, relative to the working directory; '' deck base name + .h5 [-]
    character(len=path_len) :: history_prefix = ''   !! prefix of the time-history files; '' derived from the summary [-]
    integer :: save_histories(max_saved) = 0         !! case ids whose time histories are written; 0 unused entry [-]
    character(len=path_len) :: list_file = ''        !! CSV case list (list mode), relative to the deck's directory [-]
    real(wp) :: checkpoint_interval = 60.0_wp        !! time between rewrites of the summary file; 0 after every case [s]
  end type raw_campaign_t

  !> Raw &parameter values as read.
  type :: raw_parameter_t
    character(len=name_len) :: name = ''             !! the input, 'group%variable(subscript)' as written [-]
    character(len=label_len) :: label = ''           !! summary-file column name; '' derived from the name [-]
    real(wp) :: values(max_values) = unset_real      !! grid or discrete values; unset_real past the last one given [deck unit]
    real(wp) :: start = unset_real                   !! first of count equally spaced grid values [deck unit]
    real(wp) :: stop = unset_real                    !! last of count equally spaced grid values [deck unit]
    integer :: count = -1                            !! number of grid values from start to stop; -1 not given [-]
    character(len=32) :: distribution = ''           !! 'uniform', 'normal' or 'discrete' as written (Monte Carlo) [-]
    real(wp) :: lo = unset_real                      !! uniform lower bound / normal lower truncation [deck unit]
    real(wp) :: hi = unset_real                      !! uniform upper bound / normal upper truncation [deck unit]
    real(wp) :: mean = unset_real                    !! normal mean [deck unit]
    real(wp) :: sd = unset_real                      !! normal standard deviation [deck unit]
    real(wp) :: weights(max_values) = unset_real     !! discrete weights, one per value (none: equal) [-]
  end type raw_parameter_t

  !> Raw &criteria values as read.
  type :: raw_criteria_t
    real(wp) :: min_stroke_margin = 0.0_wp           !! every stroke margin must be >= this [m]
    real(wp) :: max_overload = unset_real            !! peak overload must be <= this; unset_real not applied [g]
    real(wp) :: min_body_clearance = unset_real      !! body clearance must stay >= this; unset_real not applied [m]
    real(wp) :: body_point(3, max_body_points) = unset_real  !! lander-frame points (x, y, z) of the clearance [m]
    logical :: require_at_rest = .false.             !! kept for old decks: a success must be at rest anyway [-]
    real(wp) :: min_tipover_margin = unset_real      !! final tip-over margin must be >= this; unset_real not applied [deg]
    real(wp) :: max_friction_ratio = unset_real      !! final friction ratios must be <= this; unset_real not applied [-]
    character(len=32) :: failed_runs = 'count_as_failure'  !! 'count_as_failure' or 'exclude' as written [-]
  end type raw_criteria_t

end module landyn_campaign_types
