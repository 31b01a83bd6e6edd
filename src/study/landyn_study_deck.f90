!> The registry of study decks (docs/study.md): the groups &study (once) and &variant (once per
!! variant) with their variables, as input_var_t entries of their own table, and the target they
!! are read into (study_deck_t). The run-deck reader reads them (landyn_input_reader's read_deck),
!! so a study deck's unknown groups and variables, repeated items and values that cannot be read get
!! the run decks' messages and hints; what a study makes of the values is landyn_study's.
!!
!! Library code: nothing here stops or prints.
module landyn_study_deck
  use landyn_input_limits, only: path_len
  use landyn_input_registry, only: input_var_t, k_int, k_logical, k_string
  use landyn_input_value, only: input_value_t, move
  use landyn_deck_registry, only: deck_registry_t, deck_target_t, new_deck_registry
  use landyn_input_reader, only: read_deck
  use landyn_errors, only: input_errors_t
  implicit none
  private

  public :: study_deck_t, study_registry, read_study_deck
  public :: max_cases, max_sets, max_measures, label_len, set_len

  integer, parameter :: max_cases = 8        !! load cases per study [-]
  integer, parameter :: max_sets = 32        !! `set` / `common` entries per group [-]
  integer, parameter :: max_measures = 96    !! table rows [-]
  integer, parameter :: label_len = 64       !! length of labels [characters]
  integer, parameter :: set_len = 512        !! length of one `set` entry [characters]

  integer, parameter :: g_study = 1, g_variant = 2   !! group indices of the study-deck registry [-]

  !> The study-deck registry: &study and &variant, in deck order.
  type(input_var_t), parameter :: study_vars(*) = [ &
    input_var_t(g_study, 'title', k_string, default="''", length='256', takes='a quoted character string', &
      meaning='study title', doc='study title, stored in the study file'), &
    input_var_t(g_study, 'base_deck', k_string, default="''", length='path_len', n1=max_cases, &
      takes='up to 8 quoted file names', meaning='load-case decks, relative to the study deck', &
      doc='load-case decks (run decks), relative to the study deck; at least one'), &
    input_var_t(g_study, 'case_label', k_string, default="''", length='64', n1=max_cases, &
      takes='up to 8 quoted labels', meaning='load-case labels', &
      doc='load-case labels, distinct (they name the runs and the rows of the table)', &
      doc_default='LC-n for lcn.nml, else the base name'), &
    input_var_t(g_study, 'common', k_string, default="''", length='512', n1=max_sets, &
      takes='up to 32 quoted deck fragments', meaning='applied to every run before the variant', &
      doc='deck fragments applied to every run before the variant: namelist text or `group%variable = value`'), &
    input_var_t(g_study, 'output', k_string, default="''", length='path_len', takes='a quoted file name', &
      meaning='study HDF5 file', doc='study HDF5 file', doc_default='the study deck''s base name + .h5'), &
    input_var_t(g_study, 'csv', k_string, default="''", length='path_len', takes='a quoted file name', &
      meaning='study CSV table', doc='study CSV table', doc_default='the study deck''s base name + .csv'), &
    input_var_t(g_study, 'measure_case', k_int, default="0", n1=max_measures, takes='up to 96 integers', &
      meaning='table rows: load case of each row', doc='table rows: the load case of each row (1..n_cases)'), &
    input_var_t(g_study, 'measure_gear', k_int, default="0", n1=max_measures, takes='up to 96 integers', &
      meaning='table rows: gear of each row', doc='table rows: the gear of each row'), &
    input_var_t(g_study, 'measure_strut', k_int, default="0", n1=max_measures, takes='up to 96 integers', &
      meaning='table rows: strut of each row (1 primary, 2 left, 3 right)', &
      doc='table rows: the strut of each row (1 primary, 2 left, 3 right secondary)'), &
    input_var_t(g_study, 'keep_results', k_logical, default=".false.", takes='a logical (.true. or .false.)', &
      meaning='also write every run''s result file', doc='also write every run''s result file'), &
    input_var_t(g_variant, 'label', k_string, default="''", length='64', takes='a quoted label', &
      meaning='variant label (table column)', doc='variant label (a column of the table), distinct', &
      doc_default='variant n'), &
    input_var_t(g_variant, 'set', k_string, default="''", length='512', n1=max_sets, &
      takes='up to 32 quoted deck fragments', meaning='applied to every load case, in order', &
      doc='deck fragments applied on top of each load-case deck, in order: namelist text or '// &
      '`group%variable = value`')]

  !> The values of a study deck as read (defaults where the deck gives none).
  type, extends(deck_target_t) :: study_deck_t
    integer :: n_study = 0                                      !! &study groups read (0 or 1) [-]
    character(len=256) :: title = ''                            !! &study title [-]
    character(len=path_len) :: base_deck(max_cases) = ''        !! &study base_deck [-]
    character(len=label_len) :: case_label(max_cases) = ''      !! &study case_label [-]
    character(len=set_len) :: common(max_sets) = ''             !! &study common [-]
    character(len=path_len) :: output = ''                      !! &study output [-]
    character(len=path_len) :: csv = ''                         !! &study csv [-]
    integer :: measure_case(max_measures) = 0                   !! &study measure_case [-]
    integer :: measure_gear(max_measures) = 0                   !! &study measure_gear [-]
    integer :: measure_strut(max_measures) = 0                  !! &study measure_strut [-]
    logical :: keep_results = .false.                           !! &study keep_results [-]
    integer :: n_variants = 0                                   !! &variant groups read [-]
    character(len=label_len), allocatable :: label(:)           !! &variant label of each variant [-]
    character(len=set_len), allocatable :: set(:, :)            !! &variant set (max_sets, variant) [-]
  contains
    procedure :: access => study_access         !! registry entry <-> component
    procedure :: begin_group => study_begin     !! a &study or &variant group starts
  end type study_deck_t

contains

  !> The study-deck registry: groups &study (once) and &variant (repeatable).
  function study_registry() result(reg)
    type(deck_registry_t) :: reg  !! the registry [-]
    reg = new_deck_registry(study_vars, [character(len=8) :: 'study', 'variant'], [.false., .true.])
  end function study_registry

  !> Read the study deck `text` (named `path` in messages) into `deck`; problems are appended to `errors`.
  subroutine read_study_deck(path, text, deck, errors)
    character(len=*), intent(in) :: path           !! study deck, for messages [-]
    character(len=*), intent(in) :: text           !! its text [-]
    type(study_deck_t), intent(out) :: deck        !! its values [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here [-]
    allocate (deck%label(0), deck%set(max_sets, 0))
    call read_deck(study_registry(), text, path, deck, errors)
  end subroutine read_study_deck

  !> A group starts: a &variant adds a variant (label and set empty).
  subroutine study_begin(this, ig, instance)
    class(study_deck_t), intent(inout) :: this  !! the deck's values [-]
    integer, intent(in) :: ig                   !! group index [-]
    integer, intent(in) :: instance             !! how many times the group has started [-]
    character(len=label_len), allocatable :: label(:)
    character(len=set_len), allocatable :: set(:, :)
    this%group = ig
    this%instance = instance
    if (ig == g_study) then
      this%n_study = instance
      return
    end if
    this%n_variants = instance
    allocate (label(instance), set(max_sets, instance))
    label = ''
    set = ''
    label(1:instance - 1) = this%label(1:instance - 1)
    set(:, 1:instance - 1) = this%set(:, 1:instance - 1)
    call move_alloc(label, this%label)
    call move_alloc(set, this%set)
  end subroutine study_begin

  !> Registry entry iv <-> its component (for &variant: of the variant being read).
  subroutine study_access(this, iv, v, store)
    class(study_deck_t), intent(inout) :: this   !! the deck's values [-]
    integer, intent(in) :: iv                    !! entry of the study-deck registry [-]
    type(input_value_t), intent(inout) :: v      !! value holder [-]
    logical, intent(in) :: store                 !! direction: true stores v into the deck [-]
    select case (trim(study_vars(iv)%name))
    case ('title')
      call move(this%title, v, store)
    case ('base_deck')
      call move(this%base_deck, v, store)
    case ('case_label')
      call move(this%case_label, v, store)
    case ('common')
      call move(this%common, v, store)
    case ('output')
      call move(this%output, v, store)
    case ('csv')
      call move(this%csv, v, store)
    case ('measure_case')
      call move(this%measure_case, v, store)
    case ('measure_gear')
      call move(this%measure_gear, v, store)
    case ('measure_strut')
      call move(this%measure_strut, v, store)
    case ('keep_results')
      call move(this%keep_results, v, store)
    case ('label')
      call move(this%label(this%n_variants), v, store)
    case ('set')
      call move(this%set(:, this%n_variants), v, store)
    end select
  end subroutine study_access

end module landyn_study_deck
