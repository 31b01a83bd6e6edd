!> Number and text formatting of the input layer: logicals, the one degrees-to-radians
!! conversion of deck angles, the message prefix of a deck, and (re-exported from
!! landyn_real_text) the shortest decimal text of reals, angles and value lists.
!!
!! Library code: every procedure is pure.
module landyn_input_format
  use landyn_kinds, only: wp, deg2rad
  use landyn_config, only: landyn_input_t
  use landyn_real_text, only: fmt_real, fmt_angle, fmt_reals, fmt_angles
  implicit none
  private

  public :: fmt_real, fmt_angle, fmt_reals, fmt_angles, fmt_logical, deg_to_rad, msg_prefix

contains

  !> Logical as namelist text.
  pure function fmt_logical(l) result(s)
    logical, intent(in) :: l               !! value [-]
    character(len=:), allocatable :: s     !! '.true.' or '.false.' [-]
    if (l) then
      s = '.true.'
    else
      s = '.false.'
    end if
  end function fmt_logical

  !> Degrees to radians: the one conversion used for every angle read from a deck.
  elemental function deg_to_rad(x) result(r)
    real(wp), intent(in) :: x  !! angle [deg] (or rate [deg/s])
    real(wp) :: r              !! angle [rad] (or rate [rad/s])
    r = x*deg2rad
  end function deg_to_rad

  !> "deck: " or '' for messages about resolved values.
  pure function msg_prefix(inp) result(s)
    type(landyn_input_t), intent(in) :: inp  !! input [-]
    character(len=:), allocatable :: s       !! prefix [-]
    s = ''
    if (allocated(inp%deck_name)) then
      if (len_trim(inp%deck_name) > 0) s = trim(inp%deck_name)//': '
    end if
  end function msg_prefix

end module landyn_input_format
