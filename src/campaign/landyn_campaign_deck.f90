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
!!
!! The parts: landyn_campaign_types (the data), landyn_campaign_params (&parameter, &criteria),
!! landyn_campaign_target (which run-deck inputs can vary, from the input registry),
!! landyn_campaign_attach (base deck, case list, final checks), landyn_campaign_case_deck (case values,
!! case decks, case inputs). This module reads the deck and is the campaign layer's entry point.
module landyn_campaign_deck
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use landyn_kinds, only: wp
  use landyn_status, only: STAT_OK, STAT_FAILED, STAT_INPUT
  use landyn_input, only: input_errors_t, read_text_or_report
  use landyn_files, only: base_name
  use landyn_campaign_nml, only: nml_group_t, nml_item_t, split_namelist, lower_case, int_text, &
                                 real_text_short, quote_text, close_name_hint, dir_of, join_path, &
                                 hint_and_list, name_list
  use landyn_campaign_types, only: campaign_t, param_t, criteria_t, raw_campaign_t, raw_parameter_t, &
                                   raw_criteria_t, max_values, max_saved, max_body_points, max_params, &
                                   label_len, max_cases
  use landyn_campaign_params, only: make_param, make_criteria
  use landyn_campaign_attach, only: attach_base_deck, attach_list, finish_campaign
  use landyn_campaign_case_deck, only: case_values, case_deck_text, case_input, param_description, &
                                       text_fingerprint
  use landyn_campaign_target, only: run_variable_table, default_deck_variables
  implicit none
  private

  public :: campaign_t, param_t, criteria_t
  public :: load_campaign, build_campaign, use_summary_file, case_values, case_deck_text, case_input, text_fingerprint
  public :: param_description, max_values, max_saved, max_body_points, max_params, label_len
  public :: run_variable_table, default_deck_variables

  ! Campaign-deck variables: group, name, what it takes (for messages).
  !> Variables of the &campaign group [-]
  character(len=*), parameter :: campaign_vars(*) = [character(len=20) :: 'title', 'base_deck', 'mode', &
    'n_samples', 'seed', 'summary_file', 'history_prefix', 'save_histories', 'list_file', 'checkpoint_interval']
  !> What each of campaign_vars takes, for messages [-]
  character(len=*), parameter :: campaign_takes(*) = [character(len=56) :: 'a quoted character string', &
    'a quoted file name', "'grid', 'monte_carlo' or 'list'", 'an integer', 'an integer', 'a quoted file name', &
    'a quoted file-name prefix', 'up to 1000 case ids', 'a quoted file name', 'a real number [s]']
  !> Variables of the &parameter group [-]
  character(len=*), parameter :: parameter_vars(*) = [character(len=20) :: 'name', 'label', 'values', 'start', &
    'stop', 'count', 'distribution', 'lo', 'hi', 'mean', 'sd', 'weights']
  !> What each of parameter_vars takes, for messages [-]
  character(len=*), parameter :: parameter_takes(*) = [character(len=56) :: &
    "a quoted input name, e.g. 'initial_state%velocity(1)'", 'a quoted column name', &
    'up to 1000 real numbers [deck unit]', 'a real number [deck unit]', 'a real number [deck unit]', &
    'an integer', "'uniform', 'normal' or 'discrete'", 'a real number [deck unit]', 'a real number [deck unit]', &
    'a real number [deck unit]', 'a real number [deck unit]', 'up to 1000 real numbers >= 0']
  !> Variables of the &criteria group [-]
  character(len=*), parameter :: criteria_vars(*) = [character(len=20) :: 'min_stroke_margin', 'max_overload', &
    'min_body_clearance', 'body_point', 'require_at_rest', 'failed_runs', 'min_tipover_margin', 'max_friction_ratio']
  !> What each of criteria_vars takes, for messages [-]
  character(len=*), parameter :: criteria_takes(*) = [character(len=56) :: 'a real number [m]', &
    'a real number [g]', 'a real number [m]', 'a 3 x 8 real array [m]; body_point(:, i) = x, y, z', &
    'a logical', "'count_as_failure' or 'exclude'", 'a real number [deg]', 'a real number [-]']

contains

  ! ================================================================ loading

  !> Read a campaign deck and the files it names (base deck, case list) and build the campaign.
  !! stat = STAT_OK (0) ready, STAT_FAILED (1) problems in the decks (all in `errors`), STAT_INPUT (2) the
  !! campaign deck is unreadable.
  subroutine load_campaign(path, camp, errors, stat)
    character(len=*), intent(in) :: path           !! campaign deck file [-]
    type(campaign_t), intent(out) :: camp          !! the campaign [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    integer, intent(out) :: stat                   !! 0 ok, 1 deck errors, 2 deck unreadable [-]
    character(len=:), allocatable :: text, base_text, list_text
    type(raw_campaign_t) :: rc
    type(campaign_t) :: probe
    type(input_errors_t) :: scratch
    integer :: st, n0

    n0 = errors%count()
    call read_text_or_report(path, path//': cannot read the campaign deck: ', text, errors, stat)
    if (stat /= STAT_OK) return
    ! first pass: only to learn the file names (its messages come again in build_campaign)
    call parse_campaign_deck(text, path, probe, rc, scratch)
    base_text = ''
    list_text = ''
    if (len_trim(rc%base_deck) > 0) then
      call read_text_or_report(join_path(dir_of(path), rc%base_deck), path//': &campaign: base_deck = '// &
                               quote_text(trim(rc%base_deck))//': cannot read '// &
                               quote_text(join_path(dir_of(path), rc%base_deck))//': ', base_text, errors, st)
    end if
    if (len_trim(rc%list_file) > 0) then
      call read_text_or_report(join_path(dir_of(path), rc%list_file), path//': &campaign: list_file = '// &
                               quote_text(trim(rc%list_file))//': cannot read '// &
                               quote_text(join_path(dir_of(path), rc%list_file))//': ', list_text, errors, st)
    end if
    call build_campaign(path, text, base_text, list_text, camp, errors, st)
    stat = merge(STAT_OK, STAT_FAILED, errors%count() == n0)
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
  !! stat = STAT_OK ready, STAT_FAILED problems found (appended to `errors`).
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
    stat = merge(STAT_OK, STAT_FAILED, errors%count() == n0)
  end subroutine build_campaign

  !> The file name without a trailing '.h5' (any case), e.g. the stem of the history-file prefix.
  pure function strip_h5(path) result(s)
    character(len=*), intent(in) :: path  !! file name [-]
    character(len=:), allocatable :: s    !! without a trailing '.h5' [-]
    s = trim(path)
    if (len(s) > 3) then
      if (lower_case(s(len(s) - 2:)) == '.h5') s = s(1:len(s) - 3)
    end if
  end function strip_h5

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
    integer :: np, n_campaign
    integer, allocatable :: plines(:)

    camp%deck_name = deck_name
    camp%deck_text = text
    camp%title = ''
    call split_namelist(text, deck_name, groups, errors)
    call read_deck_groups(groups, deck_name, rc, rp, plines, rcr, n_campaign, errors)
    if (n_campaign == 0) then
      call errors%add(deck_name//': no &campaign group; a campaign deck needs &campaign with at least '// &
                      'base_deck and mode')
      return
    end if

    ! ---- &campaign
    call apply_campaign_group(rc, deck_name, plines, camp, errors)

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

  !> The groups of a campaign deck read into their raw records: &campaign (once), every &parameter
  !! (with its line) and &criteria (once); other groups and repeated ones are reported.
  subroutine read_deck_groups(groups, deck_name, rc, rp, plines, rcr, n_campaign, errors)
    type(nml_group_t), intent(in) :: groups(:)     !! the deck's groups [-]
    character(len=*), intent(in) :: deck_name      !! deck path [-]
    type(raw_campaign_t), intent(inout) :: rc      !! raw &campaign values [-]
    type(raw_parameter_t), allocatable, intent(out) :: rp(:)  !! raw &parameter values, in deck order [-]
    integer, allocatable, intent(out) :: plines(:) !! line of each &parameter group [-]
    type(raw_criteria_t), intent(out) :: rcr       !! raw &criteria values [-]
    integer, intent(out) :: n_campaign             !! &campaign groups found [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    type(raw_campaign_t) :: rc_unused      ! read_items takes the three records; one is read
    type(raw_parameter_t) :: rp_unused
    type(raw_criteria_t) :: rcr_unused
    character(len=20), allocatable :: given(:)
    integer :: ig, n_criteria, line_campaign, line_criteria
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
          call read_items(g, deck_name, campaign_vars, campaign_takes, given, errors, rc, rp_unused, rcr_unused)
        case ('parameter')
          rp = [rp, raw_parameter_t()]
          plines = [plines, g%line]
          call read_items(g, deck_name, parameter_vars, parameter_takes, given, errors, rc_unused, rp(size(rp)), &
                          rcr_unused)
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
          call read_items(g, deck_name, criteria_vars, criteria_takes, given, errors, rc_unused, rp_unused, rcr)
        case default
          call errors%add(deck_name//':'//int_text(g%line)//": unknown namelist group '&"//g%name//"'"// &
                          close_name_hint(g%name, [character(len=9) :: 'campaign', 'parameter', 'criteria'])// &
                          '; valid groups in a campaign deck: &campaign, &parameter, &criteria')
        end select
      end associate
    end do
  end subroutine read_deck_groups

  !> The &campaign values checked and set in `camp`: title, mode, seed, checkpoint interval, base
  !! deck and case list paths, n_samples (monte_carlo), list_file (list), summary file, history
  !! prefix and the cases whose histories are saved.
  subroutine apply_campaign_group(rc, deck_name, plines, camp, errors)
    type(raw_campaign_t), intent(in) :: rc         !! raw &campaign values [-]
    character(len=*), intent(in) :: deck_name      !! deck path [-]
    integer, intent(in) :: plines(:)               !! line of each &parameter group [-]
    type(campaign_t), intent(inout) :: camp        !! campaign filled from the deck [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
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
      if (size(plines) > 0) call errors%add(deck_name//':'//int_text(plines(1))// &
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
      camp%summary_file = base_name(deck_name)//'.h5'
    end if
    if (len_trim(rc%history_prefix) > 0) then
      camp%history_prefix = trim(rc%history_prefix)
      camp%history_prefix_given = .true.
    else
      camp%history_prefix = strip_h5(camp%summary_file)//'_case'
    end if
    camp%save_histories = pack(rc%save_histories, rc%save_histories /= 0)
  end subroutine apply_campaign_group

  !> Read every item of group g (&campaign, &parameter or &criteria) on its own into the group's
  !! raw record: the item is read as a one-item namelist record naming the record's component
  !! (`<group>_%<item>`), so subscripts and repeat counts keep their namelist meaning; a record
  !! is changed only by an item read without error, with finite values.
  subroutine read_items(g, deck_name, vars, takes, given, errors, campaign_, parameter_, criteria_)
    type(nml_group_t), intent(in) :: g                      !! the group [-]
    character(len=*), intent(in) :: deck_name               !! deck path [-]
    character(len=*), intent(in) :: vars(:)                 !! the group's variables [-]
    character(len=*), intent(in) :: takes(:)                !! what each takes [-]
    character(len=20), allocatable, intent(out) :: given(:) !! variables given [-]
    type(input_errors_t), intent(inout) :: errors           !! problems are appended here [-]
    type(raw_campaign_t), intent(inout) :: campaign_        !! &campaign values [-]
    type(raw_parameter_t), intent(inout) :: parameter_      !! &parameter values [-]
    type(raw_criteria_t), intent(inout) :: criteria_        !! &criteria values [-]
    type(raw_campaign_t) :: c0
    type(raw_parameter_t) :: p0
    type(raw_criteria_t) :: r0
    character(len=256) :: msg
    character(len=:), allocatable :: buffer, prefix
    integer :: k, ios, iv, p
    namelist /campaign/ campaign_
    namelist /parameter/ parameter_
    namelist /criteria/ criteria_
    allocate (given(0))
    buffer = ''
    prefix = g%name//'_%'
    do k = 1, g%n_items
      associate (it => g%items(k))
        iv = check_item(it, g%name, vars, takes, deck_name, given, errors)
        if (iv == 0) cycle
        c0 = campaign_
        p0 = parameter_
        r0 = criteria_
        msg = ''
        buffer = '&'//g%name//' '//prefix//it%lhs//' = '//it%value//' /'
        select case (g%name)
        case ('campaign')
          read (buffer, nml=campaign, iostat=ios, iomsg=msg)
        case ('parameter')
          read (buffer, nml=parameter, iostat=ios, iomsg=msg)
          if (ios == 0 .and. .not. all(ieee_is_finite([parameter_%values, parameter_%start, parameter_%stop, &
              parameter_%lo, parameter_%hi, parameter_%mean, parameter_%sd, parameter_%weights]))) ios = -1
        case default
          read (buffer, nml=criteria, iostat=ios, iomsg=msg)
          if (ios == 0 .and. .not. all(ieee_is_finite([criteria_%min_stroke_margin, criteria_%max_overload, &
              criteria_%min_body_clearance, criteria_%body_point, criteria_%min_tipover_margin, &
              criteria_%max_friction_ratio]))) ios = -1
        end select
        if (ios == 0) cycle
        campaign_ = c0
        parameter_ = p0
        criteria_ = r0
        if (ios == -1) msg = 'not a finite number'
        do   ! the record's name is ours, not the deck's
          p = index(msg, prefix)
          if (p == 0) exit
          msg = msg(1:p - 1)//msg(p + len(prefix):)
        end do
        call read_error(deck_name, it, g%name, takes(iv), msg, errors)
      end associate
    end do
  end subroutine read_items

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

  !> Append the message for an item whose value cannot be read: where, the item, what it takes, the iomsg.
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

end module landyn_campaign_deck
