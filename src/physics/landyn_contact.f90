!> The contact law registry: the one place that lists the footpad-ground normal contact laws
!! (&contact law), their factory and the input checks that depend on the law.
!!
!! Adding a law: write landyn_contact_<law>.f90 (a type extending contact_law_t, hertz_spring_t
!! or damped_hertz_t of landyn_contact_law with pure, allocation-free procedures, and a
!! `build(b)` subroutine like the other laws'), then register it here: its name in `registered`
!! (contact_law_names follows from it) and its `case` line in `built`. Fortran has no
!! procedure-valued constants, so the constant name list and the dispatch are the two lines of a
!! registration.
module landyn_contact
  use landyn_config, only: contact_cfg_t, name_len
  use landyn_errors, only: input_errors_t
  use landyn_status, only: STAT_OK
  use landyn_strings, only: lower_case
  use landyn_contact_law, only: contact_law_t, contact_build_t, contact_state_t, advance_contact_state
  use landyn_contact_base, only: base_contact_t, base_contact
  use landyn_contact_hunt_crossley, only: hunt_crossley_t, hunt_crossley
  use landyn_contact_regolith, only: regolith_t, regolith
  implicit none
  private

  public :: contact_law_t, contact_state_t, advance_contact_state
  public :: base_contact_t, base_contact, hunt_crossley_t, hunt_crossley, regolith_t, regolith
  public :: make_contact_law, check_contact_law_input, contact_law_names

  ! ---- registered laws (1/2): their names, in the order of the documentation (one per line)
  character(len=name_len), parameter :: registered(*) = [character(len=name_len) :: &
    'base' &
    , 'adams_impact' &
    , 'hertz' &
    , 'kelvin_voigt' &
    , 'kelvin_voigt_step' &
    , 'kelvin_voigt_bilinear' &
    , 'hunt_crossley' &
    , 'regolith' &
    ]

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
    type(contact_cfg_t), intent(in) :: cfg                      !! resolved &contact input
    class(contact_law_t), allocatable, intent(out) :: law       !! the law
    integer, intent(out) :: stat                                 !! STAT_OK on success
    character(len=*), intent(out) :: errmsg                      !! reason of a failure, '' on success
    type(contact_build_t) :: b
    character(len=name_len) :: key
    logical :: known

    key = lower_case(trim(adjustl(cfg%law)))
    b%group = 'contact'
    b%cfg = cfg
    b%pre = ''
    known = built(key, b)
    call b%outcome(known, cfg%law, contact_law_names, stat, errmsg)
    if (stat == STAT_OK) then
      call move_alloc(b%law, law)
      law%name = key
    end if
  end subroutine make_contact_law

  !> The law-dependent checks of the &contact input, one message per problem in the input
  !! validation's format. Nothing for an unknown law name (the input validation checks the name
  !! against contact_law_names).
  subroutine check_contact_law_input(cfg, pre, errors)
    type(contact_cfg_t), intent(in) :: cfg        !! resolved &contact input
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    type(contact_build_t) :: b
    b%group = 'contact'
    b%cfg = cfg
    b%pre = pre
    b%check_only = .true.
    if (built(lower_case(trim(adjustl(cfg%law))), b)) call b%pass_on(errors)
  end subroutine check_contact_law_input

  !> Runs the builder of the law named key (lower case) on b; .false. when key is not registered.
  function built(key, b) result(known)
    character(len=*), intent(in) :: key            !! law name, lower case [-]
    type(contact_build_t), intent(inout) :: b      !! the build: input, messages, law
    logical :: known                               !! key is a registered law [-]
    known = .true.
    select case (key)
    ! ---- registered laws (2/2): their builders
    case ('base'); block; use landyn_contact_base, only: build; call build(b); end block
    case ('adams_impact'); block; use landyn_contact_adams_impact, only: build; call build(b); end block
    case ('hertz'); block; use landyn_contact_hertz, only: build; call build(b); end block
    case ('kelvin_voigt'); block; use landyn_contact_kelvin_voigt, only: build; call build(b); end block
    case ('kelvin_voigt_step'); block; use landyn_contact_kelvin_voigt_step, only: build; call build(b); end block
    case ('kelvin_voigt_bilinear'); block; use landyn_contact_kelvin_voigt_bilinear, only: build; call build(b); end block
    case ('hunt_crossley'); block; use landyn_contact_hunt_crossley, only: build; call build(b); end block
    case ('regolith'); block; use landyn_contact_regolith, only: build; call build(b); end block
    case default
      known = .false.
    end select
  end function built

end module landyn_contact
