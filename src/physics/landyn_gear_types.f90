!> The gear-type registry: the one place that lists the gear types (&gears gear_type), their
!! factory and the input checks that depend on the type.
!!
!! Adding a gear type: write landyn_gear_type_<name>.f90 (a type extending gear_base_t of
!! landyn_gear_base, or an existing gear type, and a `build(b)` subroutine, b a gear_build_t, like
!! landyn_gear_type_tripod's), then add its ONE line to `walk` below:
!!   block; use landyn_gear_type_<name>, only: build; if (b%offered('<name>')) call build(b); end block
!! The factory, the input checks and gear_type_names() all walk the same lines, so the type is
!! reachable from a deck and named in the messages and in docs/input.
module landyn_gear_types
  use landyn_config, only: landyn_input_t
  use landyn_errors, only: input_errors_t
  use landyn_status, only: status_t
  use landyn_gear_base, only: gear_base_t
  use landyn_law_checks, only: law_build_t
  use landyn_gear_build, only: gear_build_t
  implicit none
  private

  public :: make_gear, check_gear_type_input, gear_type_names

contains

  !> Build gear i of the input, of the type &gears gear_type names (case-insensitive), in its gear
  !! frame. STAT_FAILED with its message for an unknown name or a gear that cannot be built (the
  !! first problem found; gear is then unallocated).
  subroutine make_gear(inp, i, gear, status)
    type(landyn_input_t), intent(in) :: inp                    !! resolved, validated input
    integer, intent(in) :: i                                   !! the gear, 1..n_gears [-]
    class(gear_base_t), allocatable, intent(out) :: gear       !! the gear
    type(status_t), intent(out) :: status                      !! STAT_OK, or STAT_FAILED with the reason [-]
    type(gear_build_t) :: b
    b%inp = inp
    b%i = i
    call b%make(walk, 'gears', inp%gears%gear_type, status, var='gear_type', noun='gear types')
    if (status%ok()) call move_alloc(b%gear, gear)
  end subroutine make_gear

  !> The checks that depend on the gear type, one message per problem in the input validation's
  !! format. Nothing for an unknown name (the input validation checks the name against
  !! gear_type_names()).
  subroutine check_gear_type_input(inp, pre, errors)
    type(landyn_input_t), intent(in) :: inp        !! resolved input
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    type(gear_build_t) :: b
    b%inp = inp
    call b%check(walk, 'gears', inp%gears%gear_type, pre, errors, var='gear_type', noun='gear types')
  end subroutine check_gear_type_input

  !> Names accepted in &gears gear_type, in the order of the registry, for messages and
  !! documentation: 'tripod, ...'.
  function gear_type_names() result(names)
    character(len=:), allocatable :: names         !! the registered names, ', '-separated [-]
    type(gear_build_t) :: b
    names = b%list(walk)
  end function gear_type_names

  !> The registry: every gear type, one line each, in the order of the documentation. A line
  !! offers its type's name; the type asked for is built, a listing collects the names.
  subroutine walk(lb)
    class(law_build_t), intent(inout) :: lb        !! the build (or the listing), a gear_build_t
    select type (b => lb)
    type is (gear_build_t)
    block; use landyn_gear_type_tripod, only: build; if (b%offered('tripod')) call build(b); end block
    end select
  end subroutine walk

end module landyn_gear_types
