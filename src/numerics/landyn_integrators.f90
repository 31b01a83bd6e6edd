!> The integrator registry: the one place that lists the time integrators (&simulation
!! integrator) and their factory.
!!
!! Adding an integrator: write landyn_integrator_<name>.f90 (a type extending integrator_t of
!! landyn_integrator, and a `build(b)` subroutine, b an integrator_build_t, that allocates b%integ,
!! like landyn_integrator_fixed's), then add its ONE line to `walk` below:
!!   block; use landyn_integrator_<name>, only: build; if (b%offered('<name>')) call build(b); end block
!! make_integrator and registered_integrators() walk these lines. The input layer, which validates
!! and documents &simulation integrator, may not use numerics/: cmake/LandynRegistries.cmake copies
!! the names these lines offer into the generated constant integrator_names (module
!! landyn_integrator_names) when CMake configures, again whenever this file changes; the unit test
!! test_registries checks the copy against the walk.
module landyn_integrators
  use landyn_status, only: STAT_INPUT, status_t
  use landyn_config, only: landyn_input_t
  use landyn_law_checks, only: law_build_t
  use landyn_integrator, only: integrator_t, integrator_build_t
  implicit none
  private

  public :: make_integrator, registered_integrators

contains

  !> The integrator named by &simulation integrator (case-insensitive). STAT_INPUT with a
  !! message naming the known integrators for an unknown name.
  subroutine make_integrator(inp, integ, status)
    type(landyn_input_t), intent(in) :: inp                    !! resolved, validated input
    class(integrator_t), allocatable, intent(out) :: integ     !! the integrator
    type(status_t), intent(out) :: status                      !! STAT_OK, or STAT_INPUT for an unknown name [-]
    type(integrator_build_t) :: b
    call b%make(walk, 'simulation', inp%simulation%integrator, status, var='integrator', noun='integrators')
    if (status%ok()) then
      call move_alloc(b%integ, integ)
    else
      call status%fail(STAT_INPUT, status%text())
    end if
  end subroutine make_integrator

  !> Names accepted in &simulation integrator, in the order of the registry: 'adaptive, ...'.
  function registered_integrators() result(names)
    character(len=:), allocatable :: names         !! the registered names, ', '-separated [-]
    type(integrator_build_t) :: b
    names = b%list(walk)
  end function registered_integrators

  !> The registry: every integrator, one line each, in the order of the documentation. A line
  !! offers its integrator's name; the one asked for is built, a listing collects the names.
  subroutine walk(lb)
    class(law_build_t), intent(inout) :: lb        !! the build (or the listing), an integrator_build_t
    select type (b => lb)
    type is (integrator_build_t)
    block; use landyn_integrator_adaptive, only: build; if (b%offered('adaptive')) call build(b); end block
    block; use landyn_integrator_fixed, only: build; if (b%offered('fixed')) call build(b); end block
    block; use landyn_integrator_imex, only: build; if (b%offered('imex')) call build(b); end block
    end select
  end subroutine walk

end module landyn_integrators
