!> Kinds and physical/mathematical constants used throughout LANDYN.
module landyn_kinds
  use, intrinsic :: iso_fortran_env, only: real64, int32
  implicit none
  private

  integer, parameter, public :: wp = real64   !! working real kind
  integer, parameter, public :: ip = int32    !! default integer kind

  real(wp), parameter, public :: pi = 3.141592653589793238462643383279503_wp
  real(wp), parameter, public :: deg2rad = pi/180.0_wp  !! degrees -> radians
  real(wp), parameter, public :: rad2deg = 180.0_wp/pi  !! radians -> degrees
  real(wp), parameter, public :: g_earth = 9.80665_wp   !! standard gravity [m/s^2], for loads in g

  integer, parameter, public :: msg_len = 512           !! length of error/status messages
  integer, parameter, public :: max_gears = 8           !! largest number of landing gears
end module landyn_kinds
