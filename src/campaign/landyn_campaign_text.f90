!> Small text helpers of the campaign modules: reals in messages and in case decks, name hints
!! and lists, paths relative to the campaign deck; lower_case, edit_distance, is_blank_char,
!! int_text, quote_text (landyn_strings) and one_line_text (landyn_namelist_text) re-exported.
!!
!! Library code: nothing here stops or prints.
module landyn_campaign_text
  use landyn_kinds, only: wp
  use landyn_input_registry, only: closest_name
  use landyn_strings, only: lower_case, is_blank_char, edit_distance, int_text, quote_text
  use landyn_namelist_text, only: one_line_text
  implicit none
  private

  public :: lower_case, int_text, real_text, real_text_short, edit_distance, is_blank_char, one_line_text
  public :: quote_text, close_name_hint, dir_of, join_path, hint_and_list, name_list, ints_text

contains

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

end module landyn_campaign_text
