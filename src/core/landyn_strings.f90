!> Small ASCII text helpers shared by the input readers and the law factories: case folding,
!! character classes, integers and quoted text for messages, and the edit distance used for
!! "did you mean" hints.
!!
!! Library code: nothing here stops or prints; every procedure is pure.
module landyn_strings
  implicit none
  private

  public :: lower_case, is_blank_char, is_letter, is_digit, is_ident_char, edit_distance, int_text, quote_text, &
            nonempty

contains

  !> Text in lower case (ASCII letters only).
  elemental function lower_case(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=len(t)) :: s          !! t in lower case [-]
    integer :: i, c
    s = t
    do i = 1, len(t)
      c = iachar(t(i:i))
      if (c >= iachar('A') .and. c <= iachar('Z')) s(i:i) = achar(c + 32)
    end do
  end function lower_case

  !> Whether c is white space: blank, tab, line feed, carriage return or form feed.
  elemental function is_blank_char(c) result(yes)
    character(len=1), intent(in) :: c  !! character [-]
    logical :: yes                     !! space, tab, line end, carriage return or form feed [-]
    yes = c == ' ' .or. c == achar(9) .or. c == achar(10) .or. c == achar(13) .or. c == achar(12)
  end function is_blank_char

  !> Whether c is an ASCII letter.
  elemental function is_letter(c) result(yes)
    character(len=1), intent(in) :: c  !! character [-]
    logical :: yes                     !! an ASCII letter [-]
    yes = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z')
  end function is_letter

  !> Whether c is a decimal digit.
  elemental function is_digit(c) result(yes)
    character(len=1), intent(in) :: c  !! character [-]
    logical :: yes                     !! 0..9 [-]
    yes = c >= '0' .and. c <= '9'
  end function is_digit

  !> Whether c can be part of a name in a deck: a letter, a digit, '_' or '%'.
  elemental function is_ident_char(c) result(yes)
    character(len=1), intent(in) :: c  !! character [-]
    logical :: yes                     !! may appear in a Fortran name (or a % component reference) [-]
    yes = is_letter(c) .or. is_digit(c) .or. c == '_' .or. c == '%'
  end function is_ident_char

  !> Integer as text; with `width`, zero-padded to at least that many digits (1..9).
  pure function int_text(i, width) result(s)
    integer, intent(in) :: i               !! value [-]
    integer, intent(in), optional :: width !! zero-padded width [-]
    character(len=:), allocatable :: s     !! decimal text [-]
    character(len=16) :: buf
    if (present(width)) then
      write (buf, '(i0.'//achar(iachar('0') + min(max(width, 1), 9))//')') i
    else
      write (buf, '(i0)') i
    end if
    s = trim(buf)
  end function int_text

  !> `s`, or `fallback` ('(none)' when absent) when `s` is blank.
  pure function nonempty(s, fallback) result(r)
    character(len=*), intent(in) :: s                   !! text [-]
    character(len=*), intent(in), optional :: fallback  !! used when s is blank; default '(none)' [-]
    character(len=:), allocatable :: r                  !! s or the fallback [-]
    if (len_trim(s) > 0) then
      r = s
    else if (present(fallback)) then
      r = fallback
    else
      r = '(none)'
    end if
  end function nonempty

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

  !> Levenshtein distance between two strings.
  pure function edit_distance(a, b) result(d)
    character(len=*), intent(in) :: a, b  !! strings [-]
    integer :: d                          !! number of single-character edits [-]
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

end module landyn_strings
