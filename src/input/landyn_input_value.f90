!> The value of one input-registry entry in a storage-class holder (`input_value_t`), and `move`,
!! which copies it to or from a component of any registry shape. The generated accessor
!! (landyn_input_access, written from the registry by landyn_input_codegen) calls `move` once
!! per entry. Values are in STORAGE units (angles in radians).
module landyn_input_value
  use, intrinsic :: iso_fortran_env, only: int64
  use landyn_kinds, only: wp
  use landyn_input_limits, only: path_len
  implicit none
  private

  public :: input_value_t, move

  !> The value of one entry: the part matching the entry's storage class is used.
  type :: input_value_t
    real(wp), allocatable :: r(:)          !! real values, column-major [storage unit]
    integer :: i = 0                       !! integer value [-]
    integer(int64) :: i8 = 0               !! 64-bit integer value [-]
    logical :: l = .false.                 !! logical value [-]
    character(len=:), allocatable :: s     !! string value (blank-padded as stored) [-]
    integer, allocatable :: ia(:)          !! integer values of an integer array [-]
    character(len=path_len), allocatable :: sa(:)  !! string values of a string array (blank-padded) [-]
    integer :: sa_len = 0                  !! length of the strings of the array component [characters]
  end type input_value_t

  !> Copy between a component (scalar, vector or matrix of any storage class) and a holder.
  interface move
    module procedure move_real, move_reals, move_real2, move_int, move_logical, move_string
    module procedure move_ints, move_strings
  end interface move

contains

  !> move for a real scalar.
  pure subroutine move_real(x, v, store)
    real(wp), intent(inout) :: x             !! component [storage unit]
    type(input_value_t), intent(inout) :: v  !! holder [storage unit]
    logical, intent(in) :: store             !! direction [-]
    if (store) then
      x = v%r(1)
    else
      v%r = [x]
    end if
  end subroutine move_real

  !> move for a real vector.
  pure subroutine move_reals(x, v, store)
    real(wp), intent(inout) :: x(:)          !! component [storage unit]
    type(input_value_t), intent(inout) :: v  !! holder [storage unit]
    logical, intent(in) :: store             !! direction [-]
    if (store) then
      x = v%r
    else
      v%r = x
    end if
  end subroutine move_reals

  !> move for a real matrix (column-major in the holder).
  pure subroutine move_real2(x, v, store)
    real(wp), intent(inout) :: x(:, :)       !! component [storage unit]
    type(input_value_t), intent(inout) :: v  !! holder [storage unit]
    logical, intent(in) :: store             !! direction [-]
    if (store) then
      x = reshape(v%r, shape(x))
    else
      v%r = reshape(x, [size(x)])
    end if
  end subroutine move_real2

  !> move for an integer.
  pure subroutine move_int(x, v, store)
    integer, intent(inout) :: x              !! component [-]
    type(input_value_t), intent(inout) :: v  !! holder [-]
    logical, intent(in) :: store             !! direction [-]
    if (store) then
      x = v%i
    else
      v%i = x
    end if
  end subroutine move_int

  !> move for a logical.
  pure subroutine move_logical(x, v, store)
    logical, intent(inout) :: x              !! component [-]
    type(input_value_t), intent(inout) :: v  !! holder [-]
    logical, intent(in) :: store             !! direction [-]
    if (store) then
      x = v%l
    else
      v%l = x
    end if
  end subroutine move_logical

  !> move for a string.
  pure subroutine move_string(x, v, store)
    character(len=*), intent(inout) :: x     !! component [-]
    type(input_value_t), intent(inout) :: v  !! holder [-]
    logical, intent(in) :: store             !! direction [-]
    if (store) then
      x = v%s
    else
      v%s = x
    end if
  end subroutine move_string

  !> move for an integer array.
  pure subroutine move_ints(x, v, store)
    integer, intent(inout) :: x(:)           !! component [-]
    type(input_value_t), intent(inout) :: v  !! holder [-]
    logical, intent(in) :: store             !! direction [-]
    if (store) then
      x = v%ia
    else
      v%ia = x
    end if
  end subroutine move_ints

  !> move for a string array (its strings at most path_len characters long).
  pure subroutine move_strings(x, v, store)
    character(len=*), intent(inout) :: x(:)  !! component [-]
    type(input_value_t), intent(inout) :: v  !! holder [-]
    logical, intent(in) :: store             !! direction [-]
    if (store) then
      x = v%sa
    else
      v%sa = x
      v%sa_len = len(x)
    end if
  end subroutine move_strings

end module landyn_input_value
