!> Namelist text splitting and small text helpers for campaigns.
!!
!! `split_namelist` cuts a namelist text into groups (`&name ... /`) and each group into its
!! `name = value` items, with the line of each, without reading any value. The campaign deck
!! reader uses it to read every item on its own (so that every problem is reported, as for run
!! decks), and the case builder uses it to merge a campaign case's overrides into the base
!! deck. Rules as for run decks (docs/input/README.md): `!` starts a comment outside quotes,
!! a group ends with `/` (or `&end`), items are separated by commas, blanks or line ends.
!!
!! The comment stripping, group and item scanning are those of the run-deck reader
!! (landyn_namelist_text); lower_case, edit_distance, is_blank_char, int_text, quote_text and
!! one_line_text are re-exported from landyn_strings and landyn_namelist_text for the campaign
!! modules.
!!
!! Library code: nothing here stops or prints.
module landyn_campaign_nml
  use landyn_kinds, only: wp
  use landyn_input, only: input_errors_t
  use landyn_input_registry, only: closest_name
  use landyn_strings, only: lower_case, is_blank_char, edit_distance, int_text, quote_text
  use landyn_namelist_text, only: strip_comments, next_group, &
                                  find_item_names, line_of, first_nonblank, one_line_text, &
                                  remove_blanks, has_nonfinite_word, numbers_within, leading_text
  implicit none
  integer, parameter :: max_value_exponent = 30   !! campaign values beyond 1e31 are rejected before reading
  private

  public :: nml_item_t, nml_group_t, split_namelist
  public :: lower_case, int_text, real_text, real_text_short, edit_distance, is_blank_char, one_line_text
  public :: quote_text, close_name_hint, dir_of, join_path, hint_and_list, name_list, ints_text

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
      if (has_nonfinite_word(work(eqs(k) + 1:item_end)) .or. &
          .not. numbers_within(work(eqs(k) + 1:item_end), max_value_exponent)) then
        call errors%add(deck_name//':'//int_text(line_of(work, starts(k)))//': &'//group%name//': '// &
                        remove_blanks(work(starts(k):eqs(k) - 1))//' = '//snippet(trim_value(work(eqs(k) + 1:item_end)))// &
                        ' is invalid; valid: finite numbers with |value| < 1e31')
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

  ! ================================================================ small text helpers

  !> Value text: on one line, blanks collapsed outside quotes, trailing commas and blanks removed.
  pure function trim_value(t) result(s)
    character(len=*), intent(in) :: t   !! raw value text [-]
    character(len=:), allocatable :: s  !! cleaned value [-]
    s = trim(adjustl(one_line_text(t)))
    do while (len(s) > 0)
      if (s(len(s):len(s)) /= ',' .and. s(len(s):len(s)) /= ' ') exit
      s = s(1:len(s) - 1)
    end do
  end function trim_value

  !> Compact excerpt for messages.
  pure function snippet(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=:), allocatable :: s  !! excerpt [-]
    s = trim_value(t)
    if (len(s) > snippet_len) s = s(1:snippet_len - 3)//'...'
  end function snippet

  !> Real with 17 significant digits: reading it back gives the same binary value.
  pure function real_text(x) result(s)
    real(wp), intent(in) :: x           !! value [any unit]
    character(len=:), allocatable :: s  !! e.g. '7.35120000000000003E-01' [-]
    character(len=32) :: buf
    write (buf, '(es26.17e3)') x
    s = trim(adjustl(buf))
  end function real_text

  !> Real in a short form for messages: 5 significant digits, trailing zeros dropped.
  pure function real_text_short(x) result(s)
    real(wp), intent(in) :: x           !! value [any unit]
    character(len=:), allocatable :: s  !! e.g. '0.73512', '188.67', '1.5e5' [-]
    character(len=32) :: buf
    character(len=:), allocatable :: mant
    integer :: pe, ex
    if (abs(x) < tiny(1.0_wp)) then
      s = '0'
      return
    end if
    if (abs(x) >= 0.1_wp .and. abs(x) < 1.0e4_wp) then
      write (buf, '(g0.5)') x
    else if (abs(x) >= 1.0e-4_wp .and. abs(x) < 0.1_wp) then
      write (buf, '(f0.8)') x
    else
      write (buf, '(es12.4e3)') x
    end if
    s = trim(adjustl(buf))
    pe = scan(s, 'Ee')
    if (pe > 0) then
      ! 1.5000E+005 -> 1.5e5
      mant = s(1:pe - 1)
      do while (len(mant) > 1)
        if (mant(len(mant):len(mant)) /= '0') exit
        mant = mant(1:len(mant) - 1)
      end do
      if (mant(len(mant):len(mant)) == '.') mant = mant(1:len(mant) - 1)
      read (s(pe + 1:), *) ex
      write (buf, '(i0)') ex
      s = mant//'e'//trim(buf)
      return
    end if
    if (index(s, '.') == 0) return
    do while (len(s) > 1)
      if (s(len(s):len(s)) /= '0') exit
      s = s(1:len(s) - 1)
    end do
    if (s(len(s):len(s)) == '.') s = s(1:len(s) - 1)
    if (s(1:1) == '.') s = '0'//s
    if (len(s) > 1) then
      if (s(1:2) == '-.') s = '-0'//s(2:)
    end if
  end function real_text_short

  !> "; did you mean 'xxx'?" for the closest of `names` when close enough, else ''.
  pure function close_name_hint(name, names) result(s)
    character(len=*), intent(in) :: name      !! unknown name [-]
    character(len=*), intent(in) :: names(:)  !! known names [-]
    character(len=:), allocatable :: s        !! hint [-]
    s = closest_name(name, names)
    if (len(s) > 0) s = "; did you mean '"//s//"'?"
  end function close_name_hint

  ! ================================================================ paths

  !> Directory part of a path including the trailing '/', '' when there is none.
  pure function dir_of(path) result(d)
    character(len=*), intent(in) :: path  !! file name [-]
    character(len=:), allocatable :: d    !! directory with trailing '/' [-]
    integer :: p
    p = index(path, '/', back=.true.)
    d = path(1:p)
  end function dir_of

  !> `file` relative to directory `dir` (with trailing '/'), unchanged when absolute.
  pure function join_path(dir, file) result(s)
    character(len=*), intent(in) :: dir   !! directory, '' or ending in '/' [-]
    character(len=*), intent(in) :: file  !! file name [-]
    character(len=:), allocatable :: s    !! joined path [-]
    s = trim(file)
    if (len(s) == 0) return
    if (s(1:1) == '/') return
    s = dir//s
  end function join_path

  ! ================================================================ lists in messages

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

  !> 'a, b, c' from names (trailing blanks dropped).
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

  !> 'a, b, c' from integers.
  pure function ints_text(v) result(s)
    integer, intent(in) :: v(:)         !! values [-]
    character(len=:), allocatable :: s  !! 'a, b, c' [-]
    character(len=12) :: items(size(v))
    integer :: i
    do i = 1, size(v)
      items(i) = int_text(v(i))
    end do
    s = name_list(items)
  end function ints_text

end module landyn_campaign_nml
