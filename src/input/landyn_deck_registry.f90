!> A registry instance: the table of one kind of deck (its groups and their variables, each an
!! input_var_t entry as in landyn_input_registry), and the abstract target a deck is read into.
!! The deck reader (landyn_input_reader's read_deck) takes both, so run decks (the registry of
!! landyn_input_registry, read into landyn_input_t) and study decks (landyn_study_deck) are read by
!! one reader with one set of messages: unknown groups and variables with their hints, repeated
!! groups and items, values that cannot be read, over-long strings.
!!
!! Library code: nothing here stops or prints.
module landyn_deck_registry
  use landyn_kinds, only: wp
  use landyn_input_registry, only: input_var_t, input_vars, group_names, table_group_index, table_var_index, &
                                   entry_unit_text, table_group_list, table_group_hint, table_var_hint
  use landyn_input_value, only: input_value_t
  implicit none
  private

  public :: deck_registry_t, deck_target_t, group_name_len, run_deck_registry, new_deck_registry

  integer, parameter :: group_name_len = 24   !! longest group name [-]

  !> The table of one kind of deck. Entry i of `vars` names its group by its index in `groups`.
  type :: deck_registry_t
    type(input_var_t), allocatable :: vars(:)                     !! the variables, in deck order [-]
    character(len=group_name_len), allocatable :: groups(:)      !! group names, in deck order [-]
    logical, allocatable :: repeatable(:)                         !! a group that may be given more than once [-]
    logical :: numbered = .true.        !! messages name a repeatable group with its number ('&variant 2') [-]
    integer :: max_exponent = 300       !! a number beyond 10**max_exponent is out of range (checked before reading) [-]
    real(wp) :: max_magnitude = 1.0e30_wp  !! largest |value| of a real read [any unit]
    character(len=16) :: limit_text = '|value| <= 1e30'  !! that limit in messages [-]
  contains
    procedure :: group_index      !! index of a group name
    procedure :: var_index        !! index of a variable of a group
    procedure :: unit_text        !! ' [unit]' of an entry
    procedure :: group_list       !! "&a, &b, ..."
    procedure :: group_hint       !! " (did you mean '&x'?)"
    procedure :: var_hint         !! "; did you mean 'x'?", where the variable belongs, or the valid variables
  end type deck_registry_t

  !> Where a deck's values go: one implementation per kind of deck.
  type, abstract :: deck_target_t
    integer :: group = 0      !! the group being read (set by begin_group) [-]
    integer :: instance = 0   !! how many times that group has started, this one included [-]
    integer :: line = 0       !! line of the group's '&' in the deck (set by the reader before begin_group) [-]
  contains
    procedure(access_i), deferred :: access  !! copy entry iv to or from the holder
    procedure :: begin_group                 !! a group starts: records it in group and instance
  end type deck_target_t

  abstract interface
    !> Copy the value of registry entry `iv` from the target into `v` (store false) or from `v`
    !! into the target (store true).
    subroutine access_i(this, iv, v, store)
      import :: deck_target_t, input_value_t
      class(deck_target_t), intent(inout) :: this  !! the deck's values [-]
      integer, intent(in) :: iv                    !! registry entry [-]
      type(input_value_t), intent(inout) :: v      !! value holder [storage unit]
      logical, intent(in) :: store                 !! direction: true stores v into the target [-]
    end subroutine access_i
  end interface

contains

  !> The registry of run decks (landyn_input_registry): its groups, none repeatable.
  function run_deck_registry() result(reg)
    type(deck_registry_t) :: reg  !! the run-deck registry [-]
    integer :: ig
    reg = new_deck_registry(input_vars, group_names, [(.false., ig = 1, size(group_names))])
  end function run_deck_registry

  !> A registry of the table `vars` whose entries name their group by its index in `groups`; the
  !! other settings (numbered, limits) keep their defaults.
  function new_deck_registry(vars, groups, repeatable) result(reg)
    type(input_var_t), intent(in) :: vars(:)     !! the entries, in deck order [-]
    character(len=*), intent(in) :: groups(:)    !! group names, in deck order [-]
    logical, intent(in) :: repeatable(:)         !! per group: may be given more than once [-]
    type(deck_registry_t) :: reg                 !! the registry [-]
    allocate (reg%vars(size(vars)), reg%groups(size(groups)), reg%repeatable(size(groups)))
    reg%vars = vars
    reg%groups = groups
    reg%repeatable = repeatable
  end function new_deck_registry

  !> Called by the reader when group `ig` starts (its `instance`-th time in the deck), before its items.
  subroutine begin_group(this, ig, instance)
    class(deck_target_t), intent(inout) :: this  !! the deck's values [-]
    integer, intent(in) :: ig                    !! group index [-]
    integer, intent(in) :: instance              !! how many times the group has started, this one included [-]
    this%group = ig
    this%instance = instance
  end subroutine begin_group

  !> Index of a group name, 0 if unknown.
  pure function group_index(this, name) result(ig)
    class(deck_registry_t), intent(in) :: this  !! registry [-]
    character(len=*), intent(in) :: name        !! lower-case group name [-]
    integer :: ig                               !! index, 0 if unknown [-]
    ig = table_group_index(this%groups, name)
  end function group_index

  !> Index of a variable of group ig in the table, 0 if the group has no such variable.
  pure function var_index(this, ig, name) result(iv)
    class(deck_registry_t), intent(in) :: this  !! registry [-]
    integer, intent(in) :: ig                   !! group index [-]
    character(len=*), intent(in) :: name        !! lower-case variable name [-]
    integer :: iv                               !! index into vars, 0 if not in group ig [-]
    iv = table_var_index(this%vars, ig, name)
  end function var_index

  !> ' [unit]' of entry iv, or '' for none or '-'.
  pure function unit_text(this, iv) result(s)
    class(deck_registry_t), intent(in) :: this  !! registry [-]
    integer, intent(in) :: iv                   !! index into vars [-]
    character(len=:), allocatable :: s          !! ' [unit]' or '' [-]
    s = entry_unit_text(this%vars(iv))
  end function unit_text

  !> "&first, &second, ...".
  pure function group_list(this) result(s)
    class(deck_registry_t), intent(in) :: this  !! registry [-]
    character(len=:), allocatable :: s          !! group names [-]
    s = table_group_list(this%groups)
  end function group_list

  !> " (did you mean '&xxx'?)" for a close group name, else ''.
  pure function group_hint(this, name) result(s)
    class(deck_registry_t), intent(in) :: this  !! registry [-]
    character(len=*), intent(in) :: name        !! unknown group name [-]
    character(len=:), allocatable :: s          !! hint [-]
    s = table_group_hint(this%groups, name)
  end function group_hint

  !> "; did you mean 'xxx'?" for a close name in the group, or where the variable belongs, else the
  !! group's valid variables ("; valid variables: a, b, ...").
  pure function var_hint(this, ig, name) result(s)
    class(deck_registry_t), intent(in) :: this  !! registry [-]
    integer, intent(in) :: ig                   !! group index [-]
    character(len=*), intent(in) :: name        !! unknown variable name [-]
    character(len=:), allocatable :: s          !! hint [-]
    s = table_var_hint(this%vars, this%groups, ig, name)
  end function var_hint

end module landyn_deck_registry
