!> The contact law registry: the one place that lists the footpad-ground normal contact laws
!! (&contact law), their factory and the input checks that depend on the law.
!!
!! Adding a law: write landyn_contact_<law>.f90 (a type extending contact_law_t or hertz_spring_t
!! of landyn_contact_law, pure allocation-free deferred procedures, and a `build` subroutine with
!! the interface of the others), then register it below: its `use` line, its name in
!! `registered`, its `case` line in build_law (Fortran has no procedure-valued constants, so the
!! name list, which must be a constant, and the dispatch are written side by side here).
module landyn_contact
  use landyn_config, only: contact_cfg_t, name_len
  use landyn_errors, only: input_errors_t
  use landyn_status, only: STAT_OK, STAT_FAILED
  use landyn_strings, only: lower_case
  use landyn_contact_law, only: contact_law_t, contact_state_t, advance_contact_state
  ! ---- registered laws (1/3): their modules
  use landyn_contact_base, only: base_contact_t, base_contact, build_base => build
  use landyn_contact_adams_impact, only: build_adams_impact => build
  use landyn_contact_hertz, only: build_hertz => build
  use landyn_contact_kelvin_voigt, only: build_kelvin_voigt => build
  use landyn_contact_kelvin_voigt_step, only: build_kelvin_voigt_step => build
  use landyn_contact_kelvin_voigt_bilinear, only: build_kelvin_voigt_bilinear => build
  use landyn_contact_hunt_crossley, only: hunt_crossley_t, hunt_crossley, build_hunt_crossley => build
  use landyn_contact_regolith, only: regolith_t, regolith, build_regolith => build
  implicit none
  private

  public :: contact_law_t, contact_state_t, advance_contact_state
  public :: base_contact_t, base_contact, hunt_crossley_t, hunt_crossley, regolith_t, regolith
  public :: make_contact_law, check_contact_law_input, contact_law_names

  ! ---- registered laws (2/3): their names, in the order of the documentation
  character(len=name_len), parameter :: registered(*) = [character(len=name_len) :: &
    'base', &
    'adams_impact', &
    'hertz', &
    'kelvin_voigt', &
    'kelvin_voigt_step', &
    'kelvin_voigt_bilinear', &
    'hunt_crossley', &
    'regolith']

  ! contact_law_names = the registered names joined by ', ' (a constant: cells of name + ', ',
  ! keep every non-blank character and the separators, drop the last separator)
  integer, parameter :: n_laws = size(registered)
  character(len=1), parameter :: cells(name_len + 2, n_laws) = &
    reshape(transfer(registered//', ', 'a', (name_len + 2)*n_laws), [name_len + 2, n_laws])
  logical, parameter :: keep(name_len + 2, n_laws) = cells /= ' ' .or. &
    spread(transfer(repeat('x', name_len)//', ', 'a', name_len + 2) /= 'x', 2, n_laws)
  integer, parameter :: names_len = count(keep) - 2

  !> Names accepted in &contact law, for messages and documentation: 'base, adams_impact, ...'.
  character(len=names_len), parameter :: contact_law_names = transfer(pack(cells, keep), repeat(' ', names_len))

contains

  !> Build the law named by cfg%law (case-insensitive) from the &contact input.
  !! stat = STAT_FAILED and errmsg set for an unknown name or invalid parameters (the first
  !! problem found; law is then unallocated).
  subroutine make_contact_law(cfg, law, stat, errmsg)
    type(contact_cfg_t), intent(in) :: cfg                       !! resolved &contact input
    class(contact_law_t), allocatable, intent(out) :: law        !! the law
    integer, intent(out) :: stat                                 !! STAT_OK on success
    character(len=*), intent(out) :: errmsg                      !! reason of a failure, '' on success
    type(input_errors_t) :: errors
    character(len=name_len) :: key
    logical :: known

    stat = STAT_OK
    errmsg = ''
    key = lower_case(trim(adjustl(cfg%law)))
    call build_law(key, cfg, '', errors, known, law)
    if (.not. known) then
      call errors%add("&contact law = '"//trim(adjustl(cfg%law))//"' is not known; known laws: "//contact_law_names)
    end if
    if (errors%count() > 0) then
      stat = STAT_FAILED
      errmsg = errors%message(1)
      if (allocated(law)) deallocate (law)
    else
      law%name = key
    end if
  end subroutine make_contact_law

  !> The law-dependent checks of the &contact input (e.g. the damping_depth rule of the law), one
  !! message per problem in the input validation's format. Nothing for an unknown law name (the
  !! name itself is checked against contact_law_names by the input validation).
  subroutine check_contact_law_input(cfg, pre, errors)
    type(contact_cfg_t), intent(in) :: cfg         !! resolved &contact input
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    logical :: known
    call build_law(lower_case(trim(adjustl(cfg%law))), cfg, pre, errors, known)
  end subroutine check_contact_law_input

  !> Calls the builder of the law named key (lower case): the checks, and the law when present.
  subroutine build_law(key, cfg, pre, errors, known, law)
    character(len=*), intent(in) :: key                               !! law name, lower case [-]
    type(contact_cfg_t), intent(in) :: cfg                            !! resolved &contact input
    character(len=*), intent(in) :: pre                               !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors                     !! problems found are appended here
    logical, intent(out) :: known                                     !! key is a registered law [-]
    class(contact_law_t), allocatable, intent(out), optional :: law   !! the law
    known = .true.
    select case (key)
    ! ---- registered laws (3/3): their builders
    case ('base'); call build_base(cfg, pre, errors, law)
    case ('adams_impact'); call build_adams_impact(cfg, pre, errors, law)
    case ('hertz'); call build_hertz(cfg, pre, errors, law)
    case ('kelvin_voigt'); call build_kelvin_voigt(cfg, pre, errors, law)
    case ('kelvin_voigt_step'); call build_kelvin_voigt_step(cfg, pre, errors, law)
    case ('kelvin_voigt_bilinear'); call build_kelvin_voigt_bilinear(cfg, pre, errors, law)
    case ('hunt_crossley'); call build_hunt_crossley(cfg, pre, errors, law)
    case ('regolith'); call build_regolith(cfg, pre, errors, law)
    case default
      known = .false.
    end select
  end subroutine build_law

end module landyn_contact
