!> The registry of campaign decks (docs/campaign.md): the groups &campaign (once), &parameter
!! (once per varied input) and &criteria (once, optional) with their variables, as input_var_t
!! entries of their own table, and the target they are read into (campaign_deck_t: the raw records
!! of landyn_campaign_types). The run-deck reader reads them (landyn_input_reader's read_deck), so a
!! campaign deck's unknown groups and variables, repeated items and values that cannot be read get
!! the run decks' messages and hints. Campaign numbers are finite with |value| < 1e31; &parameter
!! groups are named without their number in messages (`&parameter: ...`, with the group's line).
!! What a campaign makes of the values is landyn_campaign_deck's and landyn_campaign_params'.
!!
!! Library code: nothing here stops or prints.
module landyn_campaign_table
  use landyn_kinds, only: wp
  use landyn_input_registry, only: input_var_t, k_real, k_int, k_logical, k_string, k_int64
  use landyn_input_value, only: input_value_t, move
  use landyn_deck_registry, only: deck_registry_t, deck_target_t, new_deck_registry
  use landyn_campaign_types, only: raw_campaign_t, raw_parameter_t, raw_criteria_t, max_values, max_saved, &
                                   max_body_points
  implicit none
  private

  public :: campaign_deck_t, campaign_registry, campaign_vars

  integer, parameter :: g_campaign = 1, g_parameter = 2, g_criteria = 3   !! group indices of the registry [-]
  character(len=*), parameter :: deck_unit = 'deck unit'   !! unit of a varied input's values [-]

  !> The campaign-deck registry: &campaign, &parameter and &criteria, in deck order. `default` is
  !! the raw record's initialiser (landyn_campaign_types), `doc_default` what it means.
  type(input_var_t), parameter :: campaign_vars(*) = [ &
    input_var_t(g_campaign, 'title', k_string, default="''", length='256', takes='a quoted character string', &
      meaning='campaign title', doc='campaign title (summary file attribute)'), &
    input_var_t(g_campaign, 'base_deck', k_string, default="''", length='path_len', takes='a quoted file name', &
      meaning='the run deck every case starts from', doc_default='(required)', &
      doc='the run deck every case starts from; a path relative to the campaign deck''s directory (or absolute)'), &
    input_var_t(g_campaign, 'mode', k_string, default="''", length='32', takes="'grid', 'monte_carlo' or 'list'", &
      meaning='how the cases are made', doc_default='(required)', &
      doc='`''grid''` (full factorial of the `&parameter` values), `''monte_carlo''` (`n_samples` random cases) '// &
      'or `''list''` (one case per row of `list_file`)'), &
    input_var_t(g_campaign, 'n_samples', k_int, default="-1", takes='an integer', &
      meaning='number of Monte Carlo cases', doc='number of Monte Carlo cases (`monte_carlo` only)', doc_default='-'), &
    input_var_t(g_campaign, 'seed', k_int64, default="1_int64", takes='an integer', &
      meaning='seed of the Monte Carlo random numbers', doc='64-bit integer seed of the Monte Carlo random numbers'), &
    input_var_t(g_campaign, 'summary_file', k_string, default="''", length='path_len', takes='a quoted file name', &
      meaning='summary file', doc='the summary file, relative to the current directory', &
      doc_default='deck base name + `.h5`'), &
    input_var_t(g_campaign, 'history_prefix', k_string, default="''", length='path_len', &
      takes='a quoted file-name prefix', meaning='prefix of the time-history files', &
      doc='history files are `<prefix><id, 6 digits>.h5`', doc_default='summary file without `.h5` + `_case`'), &
    input_var_t(g_campaign, 'save_histories', k_int, default="0", n1=max_saved, takes='up to 1000 case ids', &
      meaning='cases whose time histories are written', &
      doc='up to 1000 case ids whose full time histories are written (`landyn` result files)', doc_default='none'), &
    input_var_t(g_campaign, 'list_file', k_string, default="''", length='path_len', takes='a quoted file name', &
      meaning='CSV case list (list mode)', doc='`list` mode: CSV file of the cases, relative to the deck''s directory', &
      doc_default='-'), &
    input_var_t(g_campaign, 'checkpoint_interval', k_real, default="60.0_wp", unit='s', takes='a real number', &
      meaning='time between rewrites of the summary file', &
      doc='seconds between rewrites of the summary file while running; `0` rewrites it after every case'), &
    input_var_t(g_parameter, 'name', k_string, default="''", length='128', meaning='the input to vary', &
      takes="a quoted input name, e.g. 'initial_state%velocity(1)'", doc='the input, as `''group%variable(subscript)''`'), &
    input_var_t(g_parameter, 'label', k_string, default="''", length='64', takes='a quoted column name', &
      meaning='column name in the summary file', doc='column name in the summary file', doc_default='derived from `name`'), &
    input_var_t(g_parameter, 'values', k_real, default="unset_real", n1=max_values, unit=deck_unit, &
      takes='up to 1000 real numbers', meaning='grid or discrete values', doc='grid or discrete values'), &
    input_var_t(g_parameter, 'start', k_real, default="unset_real", unit=deck_unit, takes='a real number', &
      meaning='first grid value', doc='first of `count` equally spaced grid values'), &
    input_var_t(g_parameter, 'stop', k_real, default="unset_real", unit=deck_unit, takes='a real number', &
      meaning='last grid value', doc='last of `count` equally spaced grid values'), &
    input_var_t(g_parameter, 'count', k_int, default="-1", takes='an integer', meaning='number of grid values', &
      doc='number of grid values from `start` to `stop`'), &
    input_var_t(g_parameter, 'distribution', k_string, default="''", length='32', &
      takes="'uniform', 'normal' or 'discrete'", meaning='Monte Carlo distribution', doc='Monte Carlo distribution'), &
    input_var_t(g_parameter, 'lo', k_real, default="unset_real", unit=deck_unit, takes='a real number', &
      meaning='uniform lower bound, normal lower truncation', doc='uniform lower bound, normal lower truncation'), &
    input_var_t(g_parameter, 'hi', k_real, default="unset_real", unit=deck_unit, takes='a real number', &
      meaning='uniform upper bound, normal upper truncation', doc='uniform upper bound, normal upper truncation'), &
    input_var_t(g_parameter, 'mean', k_real, default="unset_real", unit=deck_unit, takes='a real number', &
      meaning='normal mean', doc='normal mean'), &
    input_var_t(g_parameter, 'sd', k_real, default="unset_real", unit=deck_unit, takes='a real number', &
      meaning='normal standard deviation', doc='normal standard deviation'), &
    input_var_t(g_parameter, 'weights', k_real, default="unset_real", n1=max_values, unit='-', &
      takes='up to 1000 real numbers >= 0', meaning='discrete weights, one per value', &
      doc='discrete weights, one per value', doc_default='equal'), &
    input_var_t(g_criteria, 'min_stroke_margin', k_real, default="0.0_wp", unit='m', takes='a real number', &
      meaning='least stroke margin of a success', doc='every stroke margin is >= this: no strut bottoms out'), &
    input_var_t(g_criteria, 'max_overload', k_real, default="unset_real", unit='g', takes='a real number', &
      meaning='largest peak overload of a success', doc='the peak overload at the mass centre is <= this', &
      doc_default='not applied'), &
    input_var_t(g_criteria, 'min_body_clearance', k_real, default="unset_real", unit='m', takes='a real number', &
      meaning='least body clearance of a success', doc='the clearance of the body points stays >= this', &
      doc_default='not applied'), &
    input_var_t(g_criteria, 'body_point', k_real, default="unset_real", n1=3, n2=max_body_points, unit='m', &
      takes='a 3 x 8 real array; body_point(:, i) = x, y, z', meaning='lander-frame points of the clearance', &
      doc='up to 8 lander-frame points whose clearance is computed', doc_default='0, 0, 0'), &
    input_var_t(g_criteria, 'require_at_rest', k_logical, default=".false.", takes='a logical', &
      meaning='kept for older decks', doc='kept for older decks: a success must be at rest whatever it says'), &
    input_var_t(g_criteria, 'failed_runs', k_string, default="'count_as_failure'", length='32', &
      takes="'count_as_failure' or 'exclude'", meaning='how cases without a result enter the probability', &
      doc='how cases without a result enter the probability: as unsuccessful landings, or `''exclude''`d'), &
    input_var_t(g_criteria, 'min_tipover_margin', k_real, default="unset_real", unit='deg', takes='a real number', &
      meaning='least tip-over margin at rest of a success', doc='the tip-over margin at rest is >= this', &
      doc_default='not applied'), &
    input_var_t(g_criteria, 'max_friction_ratio', k_real, default="unset_real", unit='-', takes='a real number', &
      meaning='largest static friction ratio at rest of a success', &
      doc='every footpad''s static friction ratio at rest is <= this', doc_default='not applied')]

  !> The values of a campaign deck as read (the raw records' defaults where the deck gives none);
  !! rp and plines are allocated (empty) before the deck is read into it.
  type, extends(deck_target_t) :: campaign_deck_t
    integer :: n_campaign = 0                          !! &campaign groups read (0 or 1) [-]
    type(raw_campaign_t) :: rc                         !! &campaign values [-]
    type(raw_parameter_t), allocatable :: rp(:)        !! &parameter values, in deck order [-]
    integer, allocatable :: plines(:)                  !! line of each &parameter group [-]
    type(raw_criteria_t) :: rcr                        !! &criteria values [-]
  contains
    procedure :: access => campaign_access         !! registry entry <-> component
    procedure :: begin_group => campaign_begin     !! a group starts; a &parameter adds a record
  end type campaign_deck_t

contains

  !> The campaign-deck registry: &campaign and &criteria once, &parameter repeatable and named
  !! without its number; numbers finite with |value| < 1e31.
  function campaign_registry() result(reg)
    type(deck_registry_t) :: reg  !! the registry [-]
    reg = new_deck_registry(campaign_vars, [character(len=9) :: 'campaign', 'parameter', 'criteria'], &
                            [.false., .true., .false.])
    reg%numbered = .false.
    reg%max_exponent = 30
    reg%max_magnitude = 1.0e31_wp
    reg%limit_text = '|value| < 1e31'
  end function campaign_registry

  !> A group starts: &campaign is counted, a &parameter adds a record (defaults) with its line.
  subroutine campaign_begin(this, ig, instance)
    class(campaign_deck_t), intent(inout) :: this  !! the deck's values [-]
    integer, intent(in) :: ig                      !! group index [-]
    integer, intent(in) :: instance                !! how many times the group has started [-]
    this%group = ig
    this%instance = instance
    if (ig == g_campaign) this%n_campaign = instance
    if (ig /= g_parameter) return
    this%rp = [this%rp, raw_parameter_t()]
    this%plines = [this%plines, this%line]
  end subroutine campaign_begin

  !> Registry entry iv <-> its component (for &parameter: of the group being read).
  subroutine campaign_access(this, iv, v, store)
    class(campaign_deck_t), intent(inout) :: this  !! the deck's values [-]
    integer, intent(in) :: iv                      !! entry of the campaign-deck registry [-]
    type(input_value_t), intent(inout) :: v        !! value holder [deck unit]
    logical, intent(in) :: store                   !! direction: true stores v into the deck [-]
    integer :: np
    np = size(this%rp)   ! the &parameter being read (used only in its cases)
    select case (trim(campaign_vars(iv)%name))
    case ('title')
      call move(this%rc%title, v, store)
    case ('base_deck')
      call move(this%rc%base_deck, v, store)
    case ('mode')
      call move(this%rc%mode, v, store)
    case ('n_samples')
      call move(this%rc%n_samples, v, store)
    case ('seed')   ! (64-bit: the one entry of its kind, moved here)
      if (store) this%rc%seed = v%i8
      if (.not. store) v%i8 = this%rc%seed
    case ('summary_file')
      call move(this%rc%summary_file, v, store)
    case ('history_prefix')
      call move(this%rc%history_prefix, v, store)
    case ('save_histories')
      call move(this%rc%save_histories, v, store)
    case ('list_file')
      call move(this%rc%list_file, v, store)
    case ('checkpoint_interval')
      call move(this%rc%checkpoint_interval, v, store)
    case ('name')
      call move(this%rp(np)%name, v, store)
    case ('label')
      call move(this%rp(np)%label, v, store)
    case ('values')
      call move(this%rp(np)%values, v, store)
    case ('start')
      call move(this%rp(np)%start, v, store)
    case ('stop')
      call move(this%rp(np)%stop, v, store)
    case ('count')
      call move(this%rp(np)%count, v, store)
    case ('distribution')
      call move(this%rp(np)%distribution, v, store)
    case ('lo')
      call move(this%rp(np)%lo, v, store)
    case ('hi')
      call move(this%rp(np)%hi, v, store)
    case ('mean')
      call move(this%rp(np)%mean, v, store)
    case ('sd')
      call move(this%rp(np)%sd, v, store)
    case ('weights')
      call move(this%rp(np)%weights, v, store)
    case ('min_stroke_margin')
      call move(this%rcr%min_stroke_margin, v, store)
    case ('max_overload')
      call move(this%rcr%max_overload, v, store)
    case ('min_body_clearance')
      call move(this%rcr%min_body_clearance, v, store)
    case ('body_point')
      call move(this%rcr%body_point, v, store)
    case ('require_at_rest')
      call move(this%rcr%require_at_rest, v, store)
    case ('failed_runs')
      call move(this%rcr%failed_runs, v, store)
    case ('min_tipover_margin')
      call move(this%rcr%min_tipover_margin, v, store)
    case ('max_friction_ratio')
      call move(this%rcr%max_friction_ratio, v, store)
    end select
  end subroutine campaign_access

end module landyn_campaign_table
