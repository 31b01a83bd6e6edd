!> The contact law registry: the one place that lists the footpad-ground normal contact laws
!! (&contact law), their factory and the input checks that depend on the law.
!!
!! Adding a law: write landyn_contact_<law>.f90 (a type extending contact_law_t, hertz_spring_t
!! or damped_hertz_t of landyn_contact_law with pure, allocation-free procedures, and a
!! `build(b)` subroutine like the other laws'), then add its ONE line to `walk` below:
!!   block; use landyn_contact_<law>, only: build; if (b%offered('<law>')) call build(b); end block
!! The factory, the input checks and contact_law_names() all walk the same lines, so the law is
!! reachable from a deck (&contact law = '<law>') and named in the messages.
module landyn_contact
  use landyn_config, only: contact_cfg_t
  use landyn_errors, only: input_errors_t
  use landyn_status, only: status_t
  use landyn_law_checks, only: law_build_t
  use landyn_contact_law, only: contact_law_t, contact_build_t, contact_state_t, advance_contact_state
  use landyn_contact_base, only: base_contact_t, base_contact
  use landyn_contact_hunt_crossley, only: hunt_crossley_t, hunt_crossley
  use landyn_contact_regolith, only: regolith_t, regolith
  implicit none
  private

  public :: contact_law_t, contact_state_t, advance_contact_state
  public :: base_contact_t, base_contact, hunt_crossley_t, hunt_crossley, regolith_t, regolith
  public :: make_contact_law, check_contact_law_input, contact_law_names

contains

  !> Build the law named by cfg%law (case-insensitive) from the &contact input.
  !! STAT_FAILED with its message for an unknown name or invalid parameters (the first problem
  !! found; law is then unallocated).
  subroutine make_contact_law(cfg, law, status)
    type(contact_cfg_t), intent(in) :: cfg                      !! resolved &contact input
    class(contact_law_t), allocatable, intent(out) :: law       !! the law
    type(status_t), intent(out) :: status                        !! STAT_OK, or STAT_FAILED with the reason [-]
    type(contact_build_t) :: b
    b%cfg = cfg
    call b%make(walk, 'contact', cfg%law, status)
    if (status%ok()) then
      call move_alloc(b%law, law)
      law%name = b%key
    end if
  end subroutine make_contact_law

  !> The law-dependent checks of the &contact input, one message per problem in the input
  !! validation's format. Nothing for an unknown law name (the input validation checks the name
  !! against contact_law_names()).
  subroutine check_contact_law_input(cfg, pre, errors)
    type(contact_cfg_t), intent(in) :: cfg        !! resolved &contact input
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    type(contact_build_t) :: b
    b%cfg = cfg
    call b%check(walk, 'contact', cfg%law, pre, errors)
  end subroutine check_contact_law_input

  !> Names accepted in &contact law, in the order of the registry, for messages and documentation:
  !! 'base, ...'.
  function contact_law_names() result(names)
    character(len=:), allocatable :: names         !! the registered names, ', '-separated [-]
    type(contact_build_t) :: b
    names = b%list(walk)
  end function contact_law_names

  !> The registry: every contact law, one line each, in the order of the documentation. A line
  !! offers its law's name; the law asked for is built, a listing collects the names.
  subroutine walk(lb)
    class(law_build_t), intent(inout) :: lb        !! the build (or the listing), a contact_build_t
    select type (b => lb)
    type is (contact_build_t)
    block; use landyn_contact_base, only: build; if (b%offered('base')) call build(b); end block
    block; use landyn_contact_adams_impact, only: build; if (b%offered('adams_impact')) call build(b); end block
    block; use landyn_contact_hertz, only: build; if (b%offered('hertz')) call build(b); end block
    block; use landyn_contact_kelvin_voigt, only: build; if (b%offered('kelvin_voigt')) call build(b); end block
    block; use landyn_contact_kelvin_voigt_step, only: build; if (b%offered('kelvin_voigt_step')) call build(b); end block
    block; use landyn_contact_kelvin_voigt_bilinear, only: build; if (b%offered('kelvin_voigt_bilinear')) call build(b); end block
    block; use landyn_contact_hunt_crossley, only: build; if (b%offered('hunt_crossley')) call build(b); end block
    block; use landyn_contact_regolith, only: build; if (b%offered('regolith')) call build(b); end block
    end select
  end subroutine walk

end module landyn_contact
