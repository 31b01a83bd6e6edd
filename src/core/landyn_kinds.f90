!> Kinds and physical/mathematical constants used throughout LANDYN.
module landyn_kinds
  use, intrinsic :: iso_fortran_env, only: real64, int32
  implicit none
  private

  integer, parameter, public :: wp = real64   !! working real kind
  integer, parameter, public :: ip = int32    !! default integer kind

  real(wp), parameter, public :: pi = 3.141592653589793238462643383279503_wp  !! the circle constant [-]
  real(wp), parameter, public :: deg2rad = pi/180.0_wp  !! degrees -> radians
  real(wp), parameter, public :: rad2deg = 180.0_wp/pi  !! radians -> degrees
  real(wp), parameter, public :: g_earth = 9.80665_wp   !! standard gravity [m/s^2], for loads in g

  integer, parameter, public :: msg_len = 512           !! length of error/status messages
  integer, parameter, public :: max_gears = 8           !! largest number of landing gears
  ! Capacities of a gear type (landyn_gear_base): the per-gear records of the simulation are sized
  ! by them; each gear reports its own counts (strut_count, coordinate_count).
  integer, parameter, public :: max_struts = 3          !! largest number of struts per gear
  integer, parameter, public :: max_gear_q = 9          !! largest number of generalized coordinates per gear
  integer, parameter, public :: max_gear_rows = 9       !! largest number of velocity constraint rows per gear
end module landyn_kinds
