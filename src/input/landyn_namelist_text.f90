!> Namelist text splitting shared by the deck reader (landyn_input_reader) and the item splitter
!! (landyn_namelist_items): comment stripping, quote-aware scanning for groups and their ends,
!! finding the `name =` of each item, and the small position/blank helpers they need.
!! Rules as in docs/input/README.md: `!` starts a comment outside quotes, a group is `&name ... /`
!! (or `... &end`), items are `name = value` separated by commas, blanks or line ends.
!!
!! Library code: nothing here stops or prints; every procedure is pure.
module landyn_namelist_text
  use landyn_strings, only: lower_case, is_blank_char, is_letter, is_ident_char, is_digit
  implicit none
  private

  public :: strip_comments, find_item_names
  public :: next_group
  public :: line_of, first_nonblank, one_line_text, separators_to_blanks, remove_blanks, without_trailing_separators, shortened
  public :: mask_non_ascii, bare_name_in_value, numbers_within, has_nonfinite_word, leading_text

contains

  !> Copy of text with `!` comments (outside quotes) blanked; line ends kept. qpos > 0 is the
  !! position of an opening quote that is never closed.
  pure subroutine strip_comments(text, work, qpos)
    character(len=*), intent(in) :: text             !! namelist text [-]
    character(len=len(text)), intent(out) :: work    !! text without comments [-]
    integer, intent(out) :: qpos                     !! unterminated quote position, 0 if none [-]
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

  !> The next namelist group of the comment-free text at or after p, for the deck readers (run,
  !! study and campaign decks). Blanks are skipped; text before the next '&' that belongs to no
  !! group is returned as work(s0:s1) (s0 = 0 when there is none) for the caller to report. Then
  !! the group: its '&' at g (g = 0 when the text has ended), its name work(g+1:q-1), its body
  !! work(q:e-1), terminated as find_group_end says; scanning goes on at next_p.
  pure subroutine next_group(work, p, s0, s1, g, q, e, terminated, next_p)
    character(len=*), intent(in) :: work  !! comment-free text [-]
    integer, intent(in) :: p              !! start position [-]
    integer, intent(out) :: s0, s1        !! stray text before the group, s0 = 0 if none [-]
    integer, intent(out) :: g             !! position of the group's '&', 0 at the end [-]
    integer, intent(out) :: q             !! first position after the group name [-]
    integer, intent(out) :: e             !! position after the body [-]
    logical, intent(out) :: terminated    !! the group ends with '/' or '&end' [-]
    integer, intent(out) :: next_p        !! where scanning continues [-]
    integer :: k
    s0 = 0
    s1 = 0
    g = 0
    q = 0
    e = 0
    terminated = .false.
    next_p = len(work) + 1
    k = p
    do while (k <= len(work))
      if (.not. is_blank_char(work(k:k))) exit
      k = k + 1
    end do
    if (k > len(work)) return
    if (work(k:k) /= '&') then
      s0 = k
      k = next_ampersand(work, k)
      s1 = k - 1
      if (k > len(work)) return
    end if
    g = k
    q = group_name_end(work, g)
    call find_group_end(work, q, e, terminated, next_p)
  end subroutine next_group

  !> Position after the group name of the '&' at p: the name is work(p+1:q-1) (empty if none).
  pure function group_name_end(work, p) result(q)
    character(len=*), intent(in) :: work  !! comment-free text [-]
    integer, intent(in) :: p              !! position of the '&' [-]
    integer :: q                          !! first position after the name [-]
    q = p + 1
    do while (q <= len(work))
      if (.not. is_ident_char(work(q:q))) exit
      q = q + 1
    end do
  end function group_name_end

  !> Find the end of a group body starting at position q: the first '/' outside quotes, or
  !! '&end' (terminated), or the next '&' or the end of the text (not terminated).
  pure subroutine find_group_end(work, q, e, terminated, next_p)
    character(len=*), intent(in) :: work  !! comment-free text [-]
    integer, intent(in) :: q              !! first position of the body [-]
    integer, intent(out) :: e             !! position after the body (terminator or next group) [-]
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
            if (e + 4 > n) then
              terminated = .true.
            else
              terminated = .not. is_ident_char(work(e + 4:e + 4))
            end if
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

  !> Every '=' outside quotes in the group body work(b0:b1) (with skip_parens, only those outside
  !! parentheses too) and the start of the variable name before it (see name_start).
  pure subroutine find_item_names(work, b0, b1, skip_parens, starts, eqs)
    character(len=*), intent(in) :: work              !! comment-free text [-]
    integer, intent(in) :: b0, b1                     !! the body is work(b0:b1) [-]
    logical, intent(in) :: skip_parens                !! ignore '=' inside parentheses [-]
    integer, allocatable, intent(out) :: starts(:)    !! start of each item's name (= eqs when none) [-]
    integer, allocatable, intent(out) :: eqs(:)       !! position of each item's '=' [-]
    character(len=1) :: quote
    integer :: p, s, depth
    allocate (starts(0), eqs(0))
    quote = ' '
    depth = 0
    do p = b0, b1
      if (quote /= ' ') then
        if (work(p:p) == quote) quote = ' '
      else if (work(p:p) == '"' .or. work(p:p) == "'") then
        quote = work(p:p)
      else if (skip_parens .and. work(p:p) == '(') then
        depth = depth + 1
      else if (skip_parens .and. work(p:p) == ')') then
        depth = max(0, depth - 1)
      else if (work(p:p) == '=' .and. depth == 0) then
        s = name_start(work, b0, p)
        starts = [starts, s]
        eqs = [eqs, p]
      end if
    end do
  end subroutine find_item_names

  !> Start of the variable name (with optional subscript) that ends just before the '=' at eq.
  !! Returns eq itself when there is no name.
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

  !> Line number (1-based) of position p.
  pure function line_of(work, p) result(line)
    character(len=*), intent(in) :: work  !! text [-]
    integer, intent(in) :: p              !! position [-]
    integer :: line                       !! 1-based line number [-]
    integer :: i
    line = 1
    do i = 1, min(p, len(work) + 1) - 1
      if (work(i:i) == new_line('a')) line = line + 1
    end do
  end function line_of

  !> Position of the first non-blank character at or after p.
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

  !> Text on one line: every blank character (tab, line end, ...) made a space.
  pure function one_line_text(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=len(t)) :: s          !! same length, blanks normalised [-]
    integer :: i
    s = t
    do i = 1, len(s)
      if (is_blank_char(s(i:i))) s(i:i) = ' '
    end do
  end function one_line_text

  !> t, or its first n - 3 characters and '...' when it is longer than n (an excerpt in a message).
  pure function shortened(t, n) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    integer, intent(in) :: n            !! longest result [characters]
    character(len=:), allocatable :: s  !! t, shortened to n characters [-]
    if (len(t) > n) then
      s = t(1:n - 3)//'...'
    else
      s = t
    end if
  end function shortened

  !> t without its trailing blanks and commas.
  pure function without_trailing_separators(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=:), allocatable :: s  !! t up to its last character that is neither ' ' nor ',' [-]
    integer :: n
    n = len(t)
    do while (n > 0)
      if (t(n:n) /= ' ' .and. t(n:n) /= ',') exit
      n = n - 1
    end do
    s = t(1:n)
  end function without_trailing_separators

  !> The text on one line with commas and blank characters made spaces.
  pure function separators_to_blanks(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=len(t)) :: s          !! t with commas and blank characters made spaces [-]
    integer :: i
    s = one_line_text(t)
    do i = 1, len(s)
      if (s(i:i) == ',') s(i:i) = ' '
    end do
  end function separators_to_blanks

  !> The text without its blank characters.
  pure function remove_blanks(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=:), allocatable :: s  !! t without blank characters [-]
    character(len=len(t)) :: buf
    integer :: i, n
    n = 0   ! into a buffer: linear in len(t), also for a name padded with a million blanks
    do i = 1, len(t)
      if (.not. is_blank_char(t(i:i))) then
        n = n + 1
        buf(n:n) = t(i:i)
      end if
    end do
    s = buf(1:n)
  end function remove_blanks

  !> Blank every byte of `work` that is not printable ASCII (nor tab, line end or form feed) and
  !! return the position of the first such byte of each line that has one. Decks are ASCII text;
  !! inside quoted strings valid UTF-8 is accepted too (a title with a degree sign); other bytes
  !! are allowed only in comments (strip them first).
  pure subroutine mask_non_ascii(work, first_bad)
    character(len=*), intent(inout) :: work            !! comment-free text [-]
    integer, allocatable, intent(out) :: first_bad(:)  !! one position per offending line [-]
    integer :: p, c, last_line_reported, line, nc, k
    character(len=1) :: quote
    allocate (first_bad(0))
    last_line_reported = 0
    line = 1
    quote = ' '
    p = 0
    do while (p < len(work))
      p = p + 1
      c = ichar(work(p:p))
      if (c == 10) then
        line = line + 1
        cycle
      end if
      if (c == 9 .or. c == 12 .or. (c >= 32 .and. c <= 126)) then
        if (quote /= ' ') then
          if (work(p:p) == quote) quote = ' '
        else if (work(p:p) == '"' .or. work(p:p) == "'") then
          quote = work(p:p)
        end if
        cycle
      end if
      if (quote /= ' ') then
        ! a complete UTF-8 sequence inside a string is kept
        nc = 0
        if (c >= 194 .and. c <= 223) nc = 1
        if (c >= 224 .and. c <= 239) nc = 2
        if (c >= 240 .and. c <= 244) nc = 3
        if (nc > 0 .and. p + nc <= len(work)) then
          if (all([(ichar(work(k:k)) >= 128 .and. ichar(work(k:k)) <= 191, k = p + 1, p + nc)])) then
            p = p + nc
            cycle
          end if
        end if
      end if
      if (line /= last_line_reported) then
        first_bad = [first_bad, p]
        last_line_reported = line
      end if
      work(p:p) = ' '
    end do
  end subroutine mask_non_ascii

  !> First name without '= value' in the value text of an item (outside quotes), e.g. `dt` in
  !! `t_end = 0.05, dt`; '' when there is none. Logical constants (t, f, .true., false, ...) and
  !! nan/inf are values, not names.
  pure function bare_name_in_value(value) result(name)
    character(len=*), intent(in) :: value   !! text after the item's '=' [-]
    character(len=:), allocatable :: name   !! the bare name, '' if none [-]
    character(len=:), allocatable :: tok
    integer :: p, a, b
    name = ''
    p = 1
    do
      call next_word(value, p, .false., a, b)
      if (a == 0) return
      tok = lower_case(value(a:b))
      if (tok(1:1) == '+' .or. tok(1:1) == '-') tok = tok(2:)
      if (len(tok) > 0) then
        if (is_letter(tok(1:1)) .and. .not. value_word(tok)) then
          name = value(a:b)
          return
        end if
      end if
      p = b + 1
    end do
  contains
    !> True for a token that is a namelist value word (logical, NaN, infinity), not a name.
    pure logical function value_word(t)
      character(len=*), intent(in) :: t   !! token in lower case [-]
      select case (t)
      case ('t', 'f', 'true', 'false', '.t.', '.f.', '.true.', '.false.', 'nan', 'inf', 'infinity')
        value_word = .true.
      case default
        value_word = .false.
      end select
    end function value_word
  end function bare_name_in_value

  !> False when a number in the value text has a decimal exponent above max_decimal_exponent, found
  !! before the text is read
  !! (reading them would overflow, which traps in Debug builds).
  pure function numbers_within(value, max_decimal_exponent) result(ok)
    character(len=*), intent(in) :: value  !! value text of one item [-]
    integer, intent(in) :: max_decimal_exponent  !! largest decimal exponent accepted [-]
    logical :: ok                          !! no number is too large [-]
    integer :: p, n, nint_digits, expo, esign, mag
    logical :: in_mantissa_digits, seen_point, lead
    character(len=1) :: quote, c
    ok = .true.
    n = len(value)
    quote = ' '
    p = 1
    do while (p <= n)
      c = value(p:p)
      if (quote /= ' ') then
        if (c == quote) quote = ' '
        p = p + 1
        cycle
      end if
      if (c == '"' .or. c == "'") then
        quote = c
        p = p + 1
        cycle
      end if
      if (.not. (is_digit(c) .or. c == '.')) then
        p = p + 1
        cycle
      end if
      ! A number starts here: count significant integer digits, then read the exponent.
      nint_digits = 0
      seen_point = .false.
      lead = .true.
      in_mantissa_digits = .true.
      do while (p <= n .and. in_mantissa_digits)
        c = value(p:p)
        if (is_digit(c)) then
          if (.not. seen_point) then
            if (.not. (lead .and. c == '0')) then
              nint_digits = nint_digits + 1
              lead = .false.
            end if
          end if
          p = p + 1
        else if (c == '.' .and. .not. seen_point) then
          seen_point = .true.
          p = p + 1
        else
          in_mantissa_digits = .false.
        end if
      end do
      expo = 0
      if (p <= n) then
        c = lower_case(value(p:p))
        if (c == 'e' .or. c == 'd' .or. c == 'q') p = p + 1
        esign = 1
        if (p <= n) then
          if (value(p:p) == '+' .or. value(p:p) == '-') then
            if (value(p:p) == '-') esign = -1
            p = p + 1
          end if
        end if
        do while (p <= n)
          if (.not. is_digit(value(p:p))) exit
          if (expo < 100000) expo = 10*expo + (iachar(value(p:p)) - iachar('0'))
          p = p + 1
        end do
        expo = esign*expo
      end if
      mag = nint_digits - 1 + expo
      if (nint_digits > 0 .and. mag > max_decimal_exponent) ok = .false.
      if (nint_digits == 0 .and. expo > max_decimal_exponent) ok = .false.
    end do
  end function numbers_within
  !> True when the value text (outside quotes) holds nan, inf or infinity as a word.
  pure function has_nonfinite_word(value) result(yes)
    character(len=*), intent(in) :: value   !! value text [-]
    logical :: yes                          !! a non-finite word was found [-]
    character(len=:), allocatable :: tok
    integer :: p, a, b
    yes = .false.
    p = 1
    do
      call next_word(value, p, .true., a, b)
      if (a == 0) return
      tok = lower_case(value(a:b))
      if (tok == 'nan' .or. tok == 'inf' .or. tok == 'infinity') then
        yes = .true.
        return
      end if
      p = b + 1
    end do
  end function has_nonfinite_word

  !> The next word of a value text at or after p, outside quoted strings: value(first:last),
  !! first = 0 when there is none. With ident, a word is a letter followed by identifier
  !! characters; otherwise any run of characters other than blanks, commas, '*' and quotes.
  pure subroutine next_word(value, p, ident, first, last)
    character(len=*), intent(in) :: value   !! value text [-]
    integer, intent(in) :: p                !! start position [-]
    logical, intent(in) :: ident            !! words are identifiers [-]
    integer, intent(out) :: first, last     !! the word, first = 0 if none [-]
    character(len=1) :: quote, c
    integer :: k
    quote = ' '
    first = 0
    last = 0
    do k = p, len(value)
      c = value(k:k)
      if (quote /= ' ') then
        if (c == quote) quote = ' '
      else if (c == '"' .or. c == "'") then
        quote = c
      else if (in_word(c, .true.)) then
        first = k
        exit
      end if
    end do
    if (first == 0) return
    last = first
    do while (last < len(value))
      if (.not. in_word(value(last + 1:last + 1), .false.)) exit
      last = last + 1
    end do
  contains
    !> True when ch belongs to (or, with starts, may begin) the word being scanned.
    pure logical function in_word(ch, starts)
      character(len=1), intent(in) :: ch   !! character [-]
      logical, intent(in) :: starts        !! ch would start the word [-]
      if (ident) then
        if (starts) then
          in_word = is_letter(ch)
        else
          in_word = is_ident_char(ch)
        end if
      else
        in_word = .not. (is_blank_char(ch) .or. ch == ',' .or. ch == '*' .or. ch == '"' .or. ch == "'")
      end if
    end function in_word
  end subroutine next_word

  !> The text of a group body work(b0:b1) before its first item (starts(1), or the whole body
  !! without items): `what` says what is wrong with it ('' when it is only separators), and
  !! work(b0:t1) is the text to quote.
  pure subroutine leading_text(work, b0, b1, starts, what, t1)
    character(len=*), intent(in) :: work               !! comment-free text [-]
    integer, intent(in) :: b0, b1                      !! the body is work(b0:b1) [-]
    integer, intent(in) :: starts(:)                   !! starts of the item names [-]
    character(len=:), allocatable, intent(out) :: what !! problem text before the quote, '' if none [-]
    integer, intent(out) :: t1                         !! end of the leading text [-]
    t1 = b1
    if (size(starts) > 0) t1 = starts(1) - 1
    what = ''
    if (len_trim(separators_to_blanks(work(b0:t1))) == 0) return
    if (size(starts) > 0) then
      what = 'text without a variable name: '
    else
      what = "no 'name = value' item in: "
    end if
  end subroutine leading_text

end module landyn_namelist_text
