!> What a gear-type builder works on (`gear_build_t`, the build of the gear-type registry
!! landyn_gear_types): the resolved input, which gear is asked for, and the gear built.
!!
!! Every gear-type module has a builder `build(b)`. With b%check_only (the input validation) it
!! appends the checks that depend on the gear type, if any, and builds nothing; otherwise it
!! appends the same checks and allocates b%gear, gear b%i of the input in its gear frame
!! (&gears rotation(b%i)), from the input variables the type reads (the registry discards the gear
!! when a check failed).
module landyn_gear_build
  use landyn_config, only: landyn_input_t
  use landyn_law_checks, only: law_build_t
  use landyn_gear_base, only: gear_base_t
  implicit none
  private

  public :: gear_build_t

  !> A build of the gear-type registry: group 'gears', variable 'gear_type'.
  type, extends(law_build_t) :: gear_build_t
    type(landyn_input_t) :: inp                   !! resolved input
    integer :: i = 1                              !! the gear asked for, 1..n_gears [-]
    class(gear_base_t), allocatable :: gear       !! the gear built (also when a check failed)
  end type gear_build_t

end module landyn_gear_build
