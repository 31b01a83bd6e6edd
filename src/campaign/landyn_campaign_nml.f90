!> Namelist text splitting and small text helpers for campaigns.
!!
!! `split_namelist` cuts a namelist text into groups (`&name ... /`) and each group into its
!! `name = value` items, with the line of each, without reading any value. The campaign deck
!! reader uses it to read every item on its own (so that every problem is reported, as for run
!! decks), and the case builder uses it to merge a campaign case's overrides into the base
!! deck. Rules as for run decks (docs/input/README.md): `!` starts a comment outside quotes,
!! a group ends with `/` (or `&end`), items are separated by commas, blanks or line ends.
!!
!! Library code: nothing here stops or prints.
module landyn_campaign_nml
  use landyn_kinds, only: wp
  use landyn_input, only: input_errors_t
  implicit none
  private

  public :: nml_item_t, nml_group_t, split_namelist
  public :: lower_case, int_text, real_text, real_text_short, edit_distance, is_blank_char, one_line_text
  public :: quote_text, close_name_hint, dir_of, join_path, base_name_no_ext

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
    integer :: n, p, q, e, next_p, ng, qpos
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
    n = len(work)
    p = 1
    do while (p <= n)
      if (is_blank_char(work(p:p))) then
        p = p + 1
        cycle
      end if
      if (work(p:p) /= '&') then
        e = next_ampersand(work, p)
        call errors%add(deck_name//':'//int_text(line_of(work, p))//': text outside any namelist group: '''// &
                        snippet(work(p:e - 1))//''' (groups start with &name and end with /)')
        p = e
        cycle
      end if
      q = p + 1
      do while (q <= n)
        if (.not. is_ident_char(work(q:q))) exit
        q = q + 1
      end do
      call find_group_end(work, q, e, terminated, next_p)
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
    character(len=1) :: quote
    integer :: p, k, s, nitems, item_end, depth, nvalid

    allocate (starts(0), eqs(0))
    quote = ' '
    depth = 0
    do p = b0, b1
      if (quote /= ' ') then
        if (work(p:p) == quote) quote = ' '
      else if (work(p:p) == '"' .or. work(p:p) == "'") then
        quote = work(p:p)
      else if (work(p:p) == '(') then
        depth = depth + 1
      else if (work(p:p) == ')') then
        depth = max(0, depth - 1)
      else if (work(p:p) == '=' .and. depth == 0) then
        s = name_start(work, b0, p)
        starts = [starts, s]
        eqs = [eqs, p]
      end if
    end do
    nitems = size(starts)
    item_end = b1
    if (nitems > 0) item_end = starts(1) - 1
    if (len_trim(separators_to_blanks(work(b0:item_end))) > 0) then
      if (nitems > 0) then
        call errors%add(deck_name//':'//int_text(line_of(work, first_nonblank(work, b0)))//': &'//group%name// &
                        ': text without a variable name: '//snippet(work(b0:item_end)))
      else
        call errors%add(deck_name//':'//int_text(line_of(work, first_nonblank(work, b0)))//': &'//group%name// &
                        ": no 'name = value' item in: "//snippet(work(b0:item_end)))
      end if
    end if
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

  !> Start of the variable name (with optional subscript) that ends just before the '=' at eq;
  !! eq itself when there is no name.
  pure function name_start(work, b0, eq) result(s)
    character(len=*), intent(in) :: work  !! comment-free text [-]
    integer, intent(in) :: b0             !! first position of the group body [-]
    integer, intent(in) :: eq             !! position of the '=' [-]
    integer :: s                          !! start of the name [-]
    integer :: p, depth
    p = eq - 1
    do while (p >= b0)
      if (.not. is_blank_char(work(p:p))) exit
      p = p - 1
    end do
    if (p >= b0) then
      if (work(p:p) == ')') then
        depth = 0
        do while (p >= b0)
          if (work(p:p) == ')') depth = depth + 1
          if (work(p:p) == '(') depth = depth - 1
          if (depth == 0) exit
          p = p - 1
        end do
        p = p - 1
        do while (p >= b0)
          if (.not. is_blank_char(work(p:p))) exit
          p = p - 1
        end do
      end if
    end if
    s = p + 1
    do while (p >= b0)
      if (.not. is_ident_char(work(p:p))) exit
      s = p
      p = p - 1
    end do
    if (s > eq - 1) then
      s = eq
    else if (.not. is_letter(work(s:s))) then
      s = eq
    end if
  end function name_start

  !> Copy of text with `!` comments outside quotes blanked; qpos > 0 marks an unclosed quote.
  pure subroutine strip_comments(text, work, qpos)
    character(len=*), intent(in) :: text             !! text [-]
    character(len=len(text)), intent(out) :: work    !! text without comments [-]
    integer, intent(out) :: qpos                     !! position of an unclosed quote, 0 if none [-]
    character(len=1) :: quote
    integer :: p
    logical :: in_comment
    work = text
    quote = ' '
    qpos = 0
    in_comment = .false.
    do p = 1, len(text)
      if (in_comment) then
        if (text(p:p) == new_line('a')) then
          in_comment = .false.
        else
          work(p:p) = ' '
        end if
      else if (quote /= ' ') then
        if (text(p:p) == quote) quote = ' '
      else if (text(p:p) == '!') then
        in_comment = .true.
        work(p:p) = ' '
      else if (text(p:p) == '"' .or. text(p:p) == "'") then
        quote = text(p:p)
        qpos = p
      end if
    end do
    if (quote == ' ') qpos = 0
  end subroutine strip_comments

  !> Position of the next '&' outside quotes at or after p (len+1 if none).
  pure function next_ampersand(work, p) result(e)
    character(len=*), intent(in) :: work  !! comment-free text [-]
    integer, intent(in) :: p              !! start position [-]
    integer :: e                          !! position [-]
    character(len=1) :: quote
    quote = ' '
    do e = p, len(work)
      if (quote /= ' ') then
        if (work(e:e) == quote) quote = ' '
      else if (work(e:e) == '"' .or. work(e:e) == "'") then
        quote = work(e:e)
      else if (work(e:e) == '&') then
        return
      end if
    end do
    e = len(work) + 1
  end function next_ampersand

  !> End of a group body starting at q: the first '/' outside quotes or '&end' (terminated), or
  !! the next '&' or the end of the text (not terminated).
  pure subroutine find_group_end(work, q, e, terminated, next_p)
    character(len=*), intent(in) :: work  !! comment-free text [-]
    integer, intent(in) :: q              !! first position of the body [-]
    integer, intent(out) :: e             !! position after the body [-]
    logical, intent(out) :: terminated    !! a terminator was found [-]
    integer, intent(out) :: next_p        !! where scanning continues [-]
    character(len=1) :: quote
    integer :: n
    n = len(work)
    quote = ' '
    e = q
    terminated = .false.
    next_p = n + 1
    do while (e <= n)
      if (quote /= ' ') then
        if (work(e:e) == quote) quote = ' '
      else if (work(e:e) == '"' .or. work(e:e) == "'") then
        quote = work(e:e)
      else if (work(e:e) == '/') then
        terminated = .true.
        next_p = e + 1
        return
      else if (work(e:e) == '&') then
        if (e + 3 <= n) then
          if (lower_case(work(e + 1:e + 3)) == 'end') then
            terminated = .true.
            if (e + 4 <= n) terminated = .not. is_ident_char(work(e + 4:e + 4))
            if (terminated) then
              next_p = e + 4
              return
            end if
          end if
        end if
        next_p = e
        return
      end if
      e = e + 1
    end do
    e = n + 1
  end subroutine find_group_end

  ! ================================================================ small text helpers

  !> Line number (1-based) of position p.
  pure function line_of(work, p) result(line)
    character(len=*), intent(in) :: work  !! text [-]
    integer, intent(in) :: p              !! position [-]
    integer :: line                       !! line number [-]
    integer :: i
    line = 1
    do i = 1, min(p, len(work) + 1) - 1
      if (work(i:i) == new_line('a')) line = line + 1
    end do
  end function line_of

  pure function first_nonblank(work, p) result(q)
    character(len=*), intent(in) :: work  !! text [-]
    integer, intent(in) :: p              !! start position [-]
    integer :: q                          !! first non-blank position at or after p [-]
    q = p
    do while (q < len(work))
      if (.not. is_blank_char(work(q:q))) exit
      q = q + 1
    end do
  end function first_nonblank

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

  !> Text with every blank character (tab, line end, ...) made a space.
  pure function one_line_text(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=len(t)) :: s          !! same length, blanks normalised [-]
    integer :: i
    s = t
    do i = 1, len(s)
      if (is_blank_char(s(i:i))) s(i:i) = ' '
    end do
  end function one_line_text

  pure function separators_to_blanks(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=len(t)) :: s          !! commas and blank characters made spaces [-]
    integer :: i
    s = one_line_text(t)
    do i = 1, len(s)
      if (s(i:i) == ',') s(i:i) = ' '
    end do
  end function separators_to_blanks

  pure function remove_blanks(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=:), allocatable :: s  !! t without blank characters [-]
    integer :: i
    s = ''
    do i = 1, len(t)
      if (.not. is_blank_char(t(i:i))) s = s//t(i:i)
    end do
  end function remove_blanks

  !> Compact excerpt for messages.
  pure function snippet(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=:), allocatable :: s  !! excerpt [-]
    s = trim_value(t)
    if (len(s) > snippet_len) s = s(1:snippet_len - 3)//'...'
  end function snippet

  !> Text in lower case (ASCII).
  pure function lower_case(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=len(t)) :: s          !! lower-case copy [-]
    integer :: i, c
    s = t
    do i = 1, len(t)
      c = iachar(t(i:i))
      if (c >= iachar('A') .and. c <= iachar('Z')) s(i:i) = achar(c + 32)
    end do
  end function lower_case

  !> Integer as text.
  pure function int_text(i) result(s)
    integer, intent(in) :: i            !! value [-]
    character(len=:), allocatable :: s  !! decimal text [-]
    character(len=12) :: buf
    write (buf, '(i0)') i
    s = trim(buf)
  end function int_text

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

  !> Text in single quotes, inner quotes doubled.
  pure function quote_text(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=:), allocatable :: s  !! 'text' [-]
    integer :: i
    s = "'"
    do i = 1, len(t)
      if (t(i:i) == "'") then
        s = s//"''"
      else
        s = s//t(i:i)
      end if
    end do
    s = s//"'"
  end function quote_text

  !> Levenshtein distance.
  pure function edit_distance(a, b) result(d)
    character(len=*), intent(in) :: a, b  !! strings [-]
    integer :: d                          !! single-character edits [-]
    integer :: prev(0:len(b)), cur(0:len(b)), i, j
    prev = [(j, j = 0, len(b))]
    do i = 1, len(a)
      cur(0) = i
      do j = 1, len(b)
        cur(j) = min(prev(j) + 1, cur(j - 1) + 1, prev(j - 1) + merge(0, 1, a(i:i) == b(j:j)))
      end do
      prev = cur
    end do
    d = prev(len(b))
  end function edit_distance

  !> "; did you mean 'xxx'?" for the closest of `names` when close enough, else ''.
  pure function close_name_hint(name, names) result(s)
    character(len=*), intent(in) :: name      !! unknown name [-]
    character(len=*), intent(in) :: names(:)  !! known names [-]
    character(len=:), allocatable :: s        !! hint [-]
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
    s = ''
    if (best > 0 .and. best_d <= max(2, len(name)/3)) s = "; did you mean '"//trim(names(best))//"'?"
  end function close_name_hint

  elemental function is_blank_char(c) result(yes)
    character(len=1), intent(in) :: c  !! character [-]
    logical :: yes                     !! space, tab, line end, carriage return or form feed [-]
    yes = c == ' ' .or. c == achar(9) .or. c == achar(10) .or. c == achar(13) .or. c == achar(12)
  end function is_blank_char

  elemental function is_letter(c) result(yes)
    character(len=1), intent(in) :: c  !! character [-]
    logical :: yes                     !! an ASCII letter [-]
    yes = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z')
  end function is_letter

  elemental function is_ident_char(c) result(yes)
    character(len=1), intent(in) :: c  !! character [-]
    logical :: yes                     !! letter, digit, '_' or '%' [-]
    yes = is_letter(c) .or. (c >= '0' .and. c <= '9') .or. c == '_' .or. c == '%'
  end function is_ident_char

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

  !> File name without directory and without its last extension: 'a/b/mc.nml' -> 'mc'.
  pure function base_name_no_ext(path) result(s)
    character(len=*), intent(in) :: path  !! file name [-]
    character(len=:), allocatable :: s    !! base name [-]
    integer :: p
    s = trim(path(index(path, '/', back=.true.) + 1:))
    p = index(s, '.', back=.true.)
    if (p > 1) s = s(1:p - 1)
  end function base_name_no_ext

end module landyn_campaign_nml
