!> The sizes and markers of the run-deck types that the input registry, the generated group types
!! (landyn_input_groups) and their users share: the unset marker of reals, the largest number of
!! primary stages, the lengths of law names and file names, and the integrator names (re-exported
!! from landyn_integrator_names, which CMake generates from the integrator registry
!! src/numerics/landyn_integrators.f90).
!! Hand-written, used by the registry (so the registry does not depend on the types generated from it).
module landyn_input_limits
  use landyn_kinds, only: wp
  use landyn_integrator_names, only: integrator_names
  implicit none
  private

  public :: unset_real, is_set, max_stages, name_len, path_len, integrator_names

  real(wp), parameter :: unset_real = -huge(1.0_wp)   !! marks a real input the deck did not give [-]
  integer, parameter :: max_stages = 5                !! largest number of primary honeycomb stages [-]
  integer, parameter :: name_len = 32                 !! length of law names [-]
  integer, parameter :: path_len = 1024               !! length of file names [-]

contains

  !> True when a real input was given (is not the unset marker).
  elemental function is_set(x) result(yes)
    real(wp), intent(in) :: x  !! value to test [any unit]
    logical :: yes             !! .true. when x was set
    yes = x > unset_real
  end function is_set

end module landyn_input_limits
