!> A namelist text split into its groups (`&name ... /`) and each group into its `name = value`
!! items, with the line of each, without reading any value (`split_namelist`). Campaigns use it to
!! merge a case's overrides into the base run deck item by item (landyn_campaign_case_deck) and to
!! list the variables of the default deck (landyn_campaign_target); decks themselves are read by
!! landyn_input_reader. Rules as for run decks (docs/input/README.md): `!` starts a comment outside
!! quotes, a group ends with `/` (or `&end`), items are separated by commas, blanks or line ends.
!!
!! Library code: nothing here stops or prints.
module landyn_namelist_items
  use landyn_errors, only: input_errors_t
  use landyn_strings, only: lower_case, int_text
  use landyn_namelist_text, only: strip_comments, next_group, find_item_names, line_of, first_nonblank, &
                                  one_line_text, remove_blanks, leading_text, without_trailing_separators, &
                                  shortened
  implicit none
  private

  public :: nml_item_t, nml_group_t, split_namelist

  !> One `name = value` item of a group.
  type :: nml_item_t
    character(len=:), allocatable :: lhs    !! the name as written, with its subscript, blanks removed [-]
    character(len=:), allocatable :: key    !! lhs in lower case [-]
    character(len=:), allocatable :: base   !! the variable name alone, lower case [-]
    character(len=:), allocatable :: value  !! value text on one line, trailing separators removed [-]
    integer :: line = 0                     !! line of the name in the text [-]
  end type nml_item_t

  !> One namelist group.
  type :: nml_group_t
    character(len=:), allocatable :: name   !! group name, lower case [-]
    integer :: line = 0                     !! line of the '&' [-]
    logical :: terminated = .false.         !! ended by '/' or '&end' [-]
    integer :: n_items = 0                  !! number of items [-]
    type(nml_item_t), allocatable :: items(:)  !! items 1..n_items [-]
  end type nml_group_t

  integer, parameter :: snippet_len = 80  !! longest text excerpt quoted in a message [-]

contains

  !> Split `text` into namelist groups. Structural problems (text outside groups, a group
  !! without '/', an unterminated string, an item without a name) are appended to `errors` as
  !! "<deck_name>:<line>: <what>"; the groups found are returned all the same.
  subroutine split_namelist(text, deck_name, groups, errors)
    character(len=*), intent(in) :: text                        !! namelist text, lines separated by new_line('a') [-]
    character(len=*), intent(in) :: deck_name                   !! name used in messages [-]
    type(nml_group_t), allocatable, intent(out) :: groups(:)    !! groups in text order [-]
    type(input_errors_t), intent(inout) :: errors               !! problems are appended here [-]
    character(len=:), allocatable :: work
    type(nml_group_t), allocatable :: tmp(:)
    integer :: p, q, e, next_p, ng, qpos, s0, s1, g
    logical :: terminated

    allocate (character(len=len(text)) :: work)
    call strip_comments(text, work, qpos)
    if (qpos > 0) then
      call errors%add(deck_name//':'//int_text(line_of(work, qpos))//': unterminated character string '// &
                      '(no closing quote): '//snippet(work(qpos:)))
      work(qpos:) = repeat(' ', len(work) - qpos + 1)
    end if
    allocate (groups(0))
    ng = 0
    p = 1
    do
      call next_group(work, p, s0, s1, g, q, e, terminated, next_p)
      if (s0 > 0) call errors%add(deck_name//':'//int_text(line_of(work, s0))//': text outside any namelist '// &
                                  "group: '"//snippet(work(s0:s1))//"' (groups start with &name and end with /)")
      if (g == 0) exit
      p = g
      allocate (tmp(ng + 1))
      if (ng > 0) tmp(1:ng) = groups
      call move_alloc(tmp, groups)
      ng = ng + 1
      groups(ng)%name = lower_case(work(p + 1:q - 1))
      groups(ng)%line = line_of(work, p)
      groups(ng)%terminated = terminated
      if (len(groups(ng)%name) == 0) then
        call errors%add(deck_name//':'//int_text(groups(ng)%line)//": '&' without a group name: "// &
                        snippet(work(p:e - 1)))
      else
        if (.not. terminated) call errors%add(deck_name//':'//int_text(groups(ng)%line)//': &'// &
                                              groups(ng)%name//": group is not terminated by '/'")
        call split_items(work, q, e - 1, deck_name, groups(ng), errors)
      end if
      p = next_p
    end do
  end subroutine split_namelist

  !> Split a group body work(b0:b1) into items.
  subroutine split_items(work, b0, b1, deck_name, group, errors)
    character(len=*), intent(in) :: work             !! comment-free text [-]
    integer, intent(in) :: b0, b1                    !! the body is work(b0:b1) [-]
    character(len=*), intent(in) :: deck_name        !! name used in messages [-]
    type(nml_group_t), intent(inout) :: group        !! group whose items are filled [-]
    type(input_errors_t), intent(inout) :: errors    !! problems are appended here [-]
    integer, allocatable :: starts(:), eqs(:)
    integer :: p, k, nitems, item_end, nvalid
    character(len=:), allocatable :: what

    call find_item_names(work, b0, b1, .true., starts, eqs)
    nitems = size(starts)
    call leading_text(work, b0, b1, starts, what, item_end)
    if (len(what) > 0) call errors%add(deck_name//':'//int_text(line_of(work, first_nonblank(work, b0)))//': &'// &
                                       group%name//': '//what//snippet(work(b0:item_end)))
    allocate (group%items(nitems))
    nvalid = 0
    do k = 1, nitems
      item_end = b1
      if (k < nitems) item_end = starts(k + 1) - 1
      if (starts(k) == eqs(k)) then
        call errors%add(deck_name//':'//int_text(line_of(work, eqs(k)))//': &'//group%name// &
                        ": '=' without a variable name: "//snippet(work(eqs(k):item_end)))
        cycle
      end if
      nvalid = nvalid + 1
      associate (it => group%items(nvalid))
        it%lhs = remove_blanks(work(starts(k):eqs(k) - 1))
        it%key = lower_case(it%lhs)
        p = scan(it%key, '(%')
        it%base = it%key
        if (p > 0) it%base = it%key(1:p - 1)
        it%value = trim_value(work(eqs(k) + 1:item_end))
        it%line = line_of(work, starts(k))
      end associate
    end do
    group%n_items = nvalid
  end subroutine split_items

  !> Value text: on one line, blanks collapsed outside quotes, trailing commas and blanks removed.
  pure function trim_value(t) result(s)
    character(len=*), intent(in) :: t   !! raw value text [-]
    character(len=:), allocatable :: s  !! cleaned value [-]
    s = without_trailing_separators(trim(adjustl(one_line_text(t))))
  end function trim_value

  !> Compact excerpt for messages.
  pure function snippet(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=:), allocatable :: s  !! excerpt [-]
    s = shortened(trim_value(t), snippet_len)
  end function snippet

end module landyn_namelist_items
