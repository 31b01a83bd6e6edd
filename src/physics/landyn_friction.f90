!> The friction law registry: the one place that lists the footpad-ground friction laws
!! (&friction law), their factory and the input checks that depend on the law.
!!
!! Adding a law: write landyn_friction_<law>.f90 (a type extending friction_law_t of
!! landyn_friction_law with pure, allocation-free procedures, has_stiction and mu_stick if it
!! sticks, and a `build(b)` subroutine like the other laws'), then register it here: its name in
!! `registered` (friction_law_names follows from it) and its `case` line in `built`. Fortran has
!! no procedure-valued constants, so the constant name list and the dispatch are the two lines of
!! a registration.
module landyn_friction
  use landyn_config, only: friction_cfg_t, name_len
  use landyn_errors, only: input_errors_t
  use landyn_status, only: STAT_OK
  use landyn_strings, only: lower_case
  use landyn_friction_law, only: friction_law_t, friction_build_t, friction_state_t, adams_step, opposing_force, &
                                 default_stribeck_speed
  use landyn_friction_coulomb_step, only: coulomb_step_t, coulomb_step
  implicit none
  private

  public :: friction_law_t, friction_state_t, coulomb_step_t, coulomb_step
  public :: adams_step, opposing_force, default_stribeck_speed
  public :: make_friction_law, check_friction_law_input, friction_law_names

  ! ---- registered laws (1/2): their names, in the order of the documentation (one per line)
  character(len=name_len), parameter :: registered(*) = [character(len=name_len) :: &
    'coulomb_step' &
    , 'adams_step' &
    , 'ty1' &
    , 'ty2' &
    , 'ty3' &
    , 'ty4' &
    , 'ty5' &
    , 'ty6' &
    ]

  ! friction_law_names = the registered names joined by ', ' (as contact_law_names in landyn_contact)
  integer, parameter :: n_laws = size(registered)
  character(len=1), parameter :: cells(name_len + 2, n_laws) = &
    reshape(transfer(registered//', ', 'a', (name_len + 2)*n_laws), [name_len + 2, n_laws])
  logical, parameter :: keep(name_len + 2, n_laws) = cells /= ' ' .or. &
    spread(transfer(repeat('x', name_len)//', ', 'a', name_len + 2) /= 'x', 2, n_laws)
  integer, parameter :: names_len = count(keep) - 2

  !> Names accepted in &friction law, for messages and documentation: 'coulomb_step, adams_step, ...'.
  character(len=names_len), parameter :: friction_law_names = transfer(pack(cells, keep), repeat(' ', names_len))

contains

  !> Build the law named by cfg%law (case-insensitive) from the &friction input.
  !! stat = STAT_FAILED and errmsg set for an unknown name or invalid parameters (the first
  !! problem found; law is then unallocated).
  subroutine make_friction_law(cfg, law, stat, errmsg)
    type(friction_cfg_t), intent(in) :: cfg                      !! resolved &friction input
    class(friction_law_t), allocatable, intent(out) :: law       !! the law
    integer, intent(out) :: stat                                 !! STAT_OK on success
    character(len=*), intent(out) :: errmsg                      !! reason of a failure, '' on success
    type(friction_build_t) :: b
    character(len=name_len) :: key
    logical :: known

    key = lower_case(trim(adjustl(cfg%law)))
    b%group = 'friction'
    b%cfg = cfg
    b%pre = ''
    known = built(key, b)
    call b%outcome(known, cfg%law, friction_law_names, stat, errmsg)
    if (stat == STAT_OK) then
      call move_alloc(b%law, law)
      law%name = key
    end if
  end subroutine make_friction_law

  !> The law-dependent checks of the &friction input, one message per problem in the input
  !! validation's format. Nothing for an unknown law name (the input validation checks the name
  !! against friction_law_names).
  subroutine check_friction_law_input(cfg, pre, errors)
    type(friction_cfg_t), intent(in) :: cfg        !! resolved &friction input
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    type(friction_build_t) :: b
    b%group = 'friction'
    b%cfg = cfg
    b%pre = pre
    b%check_only = .true.
    if (built(lower_case(trim(adjustl(cfg%law))), b)) call b%pass_on(errors)
  end subroutine check_friction_law_input

  !> Runs the builder of the law named key (lower case) on b; .false. when key is not registered.
  function built(key, b) result(known)
    character(len=*), intent(in) :: key            !! law name, lower case [-]
    type(friction_build_t), intent(inout) :: b     !! the build: input, messages, law
    logical :: known                               !! key is a registered law [-]
    known = .true.
    select case (key)
    ! ---- registered laws (2/2): their builders
    case ('coulomb_step', 'adams_step'); block; use landyn_friction_coulomb_step, only: build; call build(b); end block
    case ('ty1'); block; use landyn_friction_coulomb, only: build_ty1; call build_ty1(b); end block
    case ('ty2'); block; use landyn_friction_coulomb, only: build_ty2; call build_ty2(b); end block
    case ('ty3'); block; use landyn_friction_regularized_coulomb, only: build; call build(b); end block
    case ('ty4'); block; use landyn_friction_coulomb, only: build_ty4; call build_ty4(b); end block
    case ('ty5'); block; use landyn_friction_stribeck, only: build; call build(b); end block
    case ('ty6'); block; use landyn_friction_modified_stribeck, only: build; call build(b); end block
    case default
      known = .false.
    end select
  end function built

end module landyn_friction
