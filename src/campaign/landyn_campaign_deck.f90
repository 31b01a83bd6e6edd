!> Campaign decks: reading, validation, and the inputs of every case.
!!
!! A campaign deck (docs/campaign.md) is a namelist text with the groups &campaign (once),
!! &parameter (once per varied input; not in list mode) and &criteria (optional), read by the
!! run-deck reader with the campaign-deck registry (landyn_campaign_table), so every problem is
!! reported, in the form `<deck>:<line>: &<group>: <what>` (read errors) or `<deck>: &<group>: <what>`
!! (checks across items), like run decks.
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
!! The parts: landyn_campaign_types (the data), landyn_campaign_table (the deck's variables),
!! landyn_campaign_params (&parameter, &criteria),
!! landyn_campaign_target (which run-deck inputs can vary, from the input registry),
!! landyn_campaign_attach (base deck, case list, final checks), landyn_campaign_case_deck (case values,
!! case decks, case inputs). This module reads the deck and is the campaign layer's entry point.
module landyn_campaign_deck
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use landyn_kinds, only: wp
  use landyn_status, only: STAT_OK, STAT_FAILED, STAT_INPUT
  use landyn_input, only: input_errors_t, read_text_or_report
  use landyn_files, only: base_name
  use landyn_campaign_text, only: lower_case, int_text, real_text_short, quote_text, dir_of, join_path
  use landyn_campaign_types, only: campaign_t, param_t, criteria_t, raw_campaign_t, max_values, max_saved, &
                                   max_body_points, max_params, label_len, max_cases
  use landyn_campaign_table, only: campaign_deck_t, campaign_registry
  use landyn_input_reader, only: read_deck
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

  !> Read the campaign deck (landyn_campaign_table: the run-deck reader with the campaign-deck
  !! registry) into `camp` (and the raw &campaign values), then check the values of each group.
  subroutine parse_campaign_deck(text, deck_name, camp, rc, errors)
    character(len=*), intent(in) :: text           !! deck text [-]
    character(len=*), intent(in) :: deck_name      !! deck path [-]
    type(campaign_t), intent(inout) :: camp        !! campaign filled from the deck [-]
    type(raw_campaign_t), intent(out) :: rc        !! raw &campaign values [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    type(campaign_deck_t) :: deck
    integer :: np

    camp%deck_name = deck_name
    camp%deck_text = text
    camp%title = ''
    allocate (deck%rp(0), deck%plines(0))
    call read_deck(campaign_registry(), text, deck_name, deck, errors)
    rc = deck%rc
    do np = 1, size(deck%rp)
      if (len_trim(deck%rp(np)%name) == 0) call errors%add(deck_name//':'//int_text(deck%plines(np))// &
        ": &parameter: name is not given; valid: the input to vary, e.g. name = 'initial_state%velocity(1)'")
    end do
    if (deck%n_campaign == 0) then
      call errors%add(deck_name//': no &campaign group; a campaign deck needs &campaign with at least '// &
                      'base_deck and mode')
      return
    end if

    ! ---- &campaign
    call apply_campaign_group(rc, deck_name, deck%plines, camp, errors)

    ! ---- &parameter
    if (camp%mode == 'grid' .or. camp%mode == 'monte_carlo') then
      if (size(deck%rp) == 0) call errors%add(deck_name//': no &parameter group; mode '// &
                                              quote_text(trim(camp%mode))//' needs one &parameter group per varied input')
      if (size(deck%rp) > max_params) call errors%add(deck_name//': '//int_text(size(deck%rp))// &
        ' &parameter groups; valid: at most '//int_text(max_params))
      allocate (camp%par(size(deck%rp)))
      do np = 1, size(deck%rp)
        call make_param(deck%rp(np), deck%plines(np), camp%mode, deck_name, camp%par(np), errors)
      end do
      camp%n_par = size(deck%rp)
    else
      allocate (camp%par(0))
    end if

    ! ---- &criteria
    call make_criteria(deck%rcr, deck_name, camp%crit, errors)
  end subroutine parse_campaign_deck

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

end module landyn_campaign_deck
