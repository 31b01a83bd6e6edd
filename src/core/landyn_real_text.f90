!> Real numbers as the shortest decimal text that reads back exactly: fmt_real, fmt_angle (an
!! angle in radians written in degrees), and value lists with repeat counts (fmt_reals,
!! fmt_angles). The value text of input messages, written decks and the law checks' messages.
module landyn_real_text
  use, intrinsic :: iso_fortran_env, only: int64
  use landyn_kinds, only: wp, deg2rad, rad2deg
  use landyn_strings, only: fmt_int => int_text
  implicit none
  private

  public :: fmt_real, fmt_angle, fmt_reals, fmt_angles

  integer, parameter :: short_digits = 3           !! digit counts tried one by one before bisection [-]
  !> ES formats with 1..17 significant digits and a 3-digit exponent (es_text)
  character(len=*), parameter :: es_formats(17) = [character(len=12) :: '(es30.0e3)', '(es30.1e3)', &
    '(es30.2e3)', '(es30.3e3)', '(es30.4e3)', '(es30.5e3)', '(es30.6e3)', '(es30.7e3)', '(es30.8e3)', &
    '(es30.9e3)', '(es30.10e3)', '(es30.11e3)', '(es30.12e3)', '(es30.13e3)', '(es30.14e3)', '(es30.15e3)', &
    '(es30.16e3)']

contains

  !> Shortest decimal text that reads back as exactly x. Reading back is monotone in the number
  !! of digits d (the d+1-digit rounding is at least as close to x as the d-digit one), so after
  !! the short texts (d <= 3, the usual deck values) the shortest d is found by bisection: a
  !! random 17-digit value costs 7 conversions instead of 17 (validation formats every value,
  !! once per campaign case).
  pure function fmt_real(x) result(s)
    real(wp), intent(in) :: x              !! value [any unit]
    character(len=:), allocatable :: s     !! e.g. '5.0e-6', '0.475', '16000.0' [-]
    integer :: d, lo, hi, mid, d_lo
    logical :: whole
    call whole_number_text(x, s, whole)
    if (whole) return
    d_lo = fewest_digits(x)
    do d = d_lo, short_digits
      if (real_ok(d)) then
        s = pretty(es_text(x, d))
        return
      end if
    end do
    lo = max(short_digits, d_lo - 1)   ! fails
    hi = 17                            ! 17 digits always read back exactly
    do while (hi - lo > 1)
      mid = (lo + hi)/2
      if (real_ok(mid)) then
        hi = mid
      else
        lo = mid
      end if
    end do
    s = pretty(es_text(x, hi))
  contains
    !> Whether x written with dd significant digits reads back as exactly x.
    pure logical function real_ok(dd)
      integer, intent(in) :: dd   !! significant digits [-]
      real(wp) :: y
      character(len=40) :: b
      b = es_text(x, dd)
      read (b, *) y
      real_ok = same_real(x, y)
    end function real_ok
  end function fmt_real

  !> A lower bound of the digits fmt_real and fmt_angle can need, found with arithmetic only: the
  !! fewest significant digits d for which x lies within a relative 1e-12 of a d-digit decimal.
  !! A text that converts back to x (or, for fmt_angle, to an angle within a few ulps of x*rad2deg)
  !! lies within a relative 1e-15 of x, so no shorter text can work. 1 when x is zero or too
  !! large or small for exact powers of ten.
  pure function fewest_digits(x) result(d)
    real(wp), intent(in) :: x   !! value [any unit]
    integer :: d                !! digits, 1..17 [-]
    real(wp) :: a, r
    integer :: e, k, dd
    d = 1
    a = abs(x)
    if (.not. (a >= 1.0e-250_wp .and. a <= 1.0e250_wp)) return
    e = floor(log10(a))
    if (e > -22 .and. e < 22) then
      if (a < 10.0_wp**e) e = e - 1   ! never too large: a too small e only makes the test milder
    end if
    do dd = 1, 17
      k = dd - 1 - e                  ! a*10^k has dd digits before the point
      if (abs(k) > 22) return         ! 10^|k| not exact: no bound (d = 1)
      if (k >= 0) then
        r = a*10.0_wp**k
      else
        r = a/10.0_wp**(-k)
      end if
      if (abs(r - anint(r)) <= 1.0e-12_wp*r) then
        d = dd
        return
      end if
    end do
    d = 17
  end function fewest_digits

  !> The text fmt_real gives for a whole number 1 <= |x| < 1e7 or a positive zero ('16000.0',
  !! '-3.0', '0.0'), made without formatted I/O; .false. for any other x.
  pure subroutine whole_number_text(x, s, done)
    real(wp), intent(in) :: x                        !! value [any unit]
    character(len=:), allocatable, intent(inout) :: s  !! text when done [-]
    logical, intent(out) :: done                     !! x was such a number [-]
    integer :: n
    done = .false.
    if (same_real(x, 0.0_wp)) then
      s = '0.0'
      done = .true.
      return
    end if
    if (.not. (abs(x) >= 1.0_wp .and. abs(x) < 1.0e7_wp)) return
    if (.not. same_real(aint(x), x)) return
    n = nint(abs(x))
    s = '.0'
    do
      s = achar(iachar('0') + mod(n, 10))//s
      n = n/10
      if (n == 0) exit
    end do
    if (x < 0.0_wp) s = '-'//s
    done = .true.
  end subroutine whole_number_text

  !> Shortest decimal degrees that deg_to_rad converts back to exactly x: the candidates are
  !! x*rad2deg and its neighbours (+-1, +-2 ulp), tried digit count by digit count, the first
  !! that works wins. As in fmt_real, short texts (d <= 3) are tried one by one and longer ones
  !! by bisection over d, so the text always converts back to x; it is the shortest one except
  !! where a non-exact neighbour happens to work at fewer digits than the exact candidates.
  pure function fmt_angle(x) result(s)
    real(wp), intent(in) :: x              !! angle [rad]
    character(len=:), allocatable :: s     !! angle in degrees [-]
    real(wp) :: cand(5)
    integer :: d, k, lo, hi, mid, d_lo
    cand(1) = x*rad2deg
    if (.not. abs(x) >= tiny(1.0_wp)) then   ! zero (or subnormal): no neighbours to try
      s = fmt_real(cand(1))
      return
    end if
    cand(2) = nearest(cand(1), 1.0_wp)
    cand(3) = nearest(cand(1), -1.0_wp)
    cand(4) = nearest(cand(2), 1.0_wp)
    cand(5) = nearest(cand(3), -1.0_wp)
    d_lo = fewest_digits(cand(1))
    do d = d_lo, short_digits
      k = first_ok(d)
      if (k > 0) then
        s = pretty(es_text(cand(k), d))
        return
      end if
    end do
    if (first_ok(17) == 0) then
      s = pretty(es_text(cand(1), 17))
      return
    end if
    lo = max(short_digits, d_lo - 1)
    hi = 17
    do while (hi - lo > 1)
      mid = (lo + hi)/2
      if (first_ok(mid) > 0) then
        hi = mid
      else
        lo = mid
      end if
    end do
    s = pretty(es_text(cand(first_ok(hi)), hi))
  contains
    !> First candidate whose dd-digit text converts back to x (0: none).
    pure integer function first_ok(dd)
      integer, intent(in) :: dd   !! significant digits [-]
      real(wp) :: y
      character(len=40) :: b
      integer :: kk
      first_ok = 0
      do kk = 1, size(cand)
        b = es_text(cand(kk), dd)
        read (b, *) y
        if (same_real(y*deg2rad, x)) then
          first_ok = kk
          return
        end if
      end do
    end function first_ok
  end function fmt_angle

  !> Values joined with ', ', runs of four or more equal values written as r*value.
  pure function fmt_reals(x) result(s)
    real(wp), intent(in) :: x(:)           !! values [any unit]
    character(len=:), allocatable :: s     !! deck text [-]
    s = fmt_list(x, .false.)
  end function fmt_reals

  !> Angles [rad] in degrees, joined as fmt_reals does.
  pure function fmt_angles(x) result(s)
    real(wp), intent(in) :: x(:)           !! angles [rad]
    character(len=:), allocatable :: s     !! deck text in degrees [-]
    s = fmt_list(x, .true.)
  end function fmt_angles

  !> fmt_real (or fmt_angle) of each value, joined by join_runs.
  pure function fmt_list(x, angle) result(s)
    real(wp), intent(in) :: x(:)           !! values [any unit, or rad]
    logical, intent(in) :: angle           !! write angles in degrees [-]
    character(len=:), allocatable :: s     !! deck text [-]
    integer :: i
    character(len=40) :: items(size(x))
    do i = 1, size(x)
      if (angle) then
        items(i) = fmt_angle(x(i))
      else
        items(i) = fmt_real(x(i))
      end if
    end do
    s = join_runs(items)
  end function fmt_list

  !> Values joined by ', ', a run of 4 or more equal values written with a repeat count ('4*0.0').
  pure function join_runs(items) result(s)
    character(len=*), intent(in) :: items(:)  !! formatted values [-]
    character(len=:), allocatable :: s        !! joined text [-]
    integer :: i, j
    s = ''
    i = 1
    do while (i <= size(items))
      j = i
      do while (j < size(items))
        if (items(j + 1) /= items(i)) exit
        j = j + 1
      end do
      if (len(s) > 0) s = s//', '
      if (j - i + 1 >= 4) then
        s = s//fmt_int(j - i + 1)//'*'//trim(items(i))
        i = j + 1
      else
        s = s//trim(items(i))
        i = i + 1
      end if
    end do
  end function join_runs

  !> x in ES format with d significant digits and a 3-digit exponent.
  pure function es_text(x, d) result(buf)
    real(wp), intent(in) :: x     !! value [any unit]
    integer, intent(in) :: d      !! significant digits, 1..17 [-]
    character(len=40) :: buf      !! e.g. ' 5.0E-006' [-]
    write (buf, es_formats(min(max(d, 1), 17))) x
    buf = adjustl(buf)
  end function es_text

  !> Rewrite ES text "m.mmmE+eee" as plain decimal for moderate exponents, else "m.mmme<exp>".
  !! Pure string manipulation, so the value is unchanged.
  pure function pretty(es) result(s)
    character(len=*), intent(in) :: es     !! ES text from es_text [-]
    character(len=:), allocatable :: s     !! e.g. '16000.0', '0.475', '5.0e-6' [-]
    character(len=:), allocatable :: sgn, digits, intpart, frac
    integer :: pe, expo, p
    s = trim(adjustl(es))
    pe = scan(s, 'Ee')
    if (pe == 0) return
    read (s(pe + 1:), *) expo
    sgn = ''
    if (s(1:1) == '-') sgn = '-'
    digits = s(len(sgn) + 1:pe - 1)
    p = index(digits, '.')
    digits = digits(1:p - 1)//digits(p + 1:)
    ! strip trailing zeros but keep one digit
    do while (len(digits) > 1)
      if (digits(len(digits):len(digits)) /= '0') exit
      digits = digits(1:len(digits) - 1)
    end do
    if (verify(digits, '0') == 0) then
      s = sgn//'0.0'
      return
    end if
    if (expo >= 0 .and. expo <= 6) then
      if (len(digits) > expo + 1) then
        intpart = digits(1:expo + 1)
        frac = digits(expo + 2:)
      else
        intpart = digits//repeat('0', expo + 1 - len(digits))
        frac = '0'
      end if
      s = sgn//intpart//'.'//frac
    else if (expo < 0 .and. expo >= -4) then
      s = sgn//'0.'//repeat('0', -expo - 1)//digits
    else
      frac = digits(2:)
      if (len(frac) == 0) frac = '0'
      s = sgn//digits(1:1)//'.'//frac//'e'//fmt_int(expo)
    end if
  end function pretty

  !> Exact equality of two reals (bit patterns), without a floating-point comparison.
  elemental function same_real(a, b) result(same)
    real(wp), intent(in) :: a, b  !! values [any unit]
    logical :: same               !! identical [-]
    same = transfer(a, 0_int64) == transfer(b, 0_int64)
  end function same_real

end module landyn_real_text
