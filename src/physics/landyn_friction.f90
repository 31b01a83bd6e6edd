!> The friction law registry: the one place that lists the footpad-ground friction laws
!! (&friction law), their factory and the input checks that depend on the law.
!!
!! Adding a law: write landyn_friction_<law>.f90 (a type extending friction_law_t of
!! landyn_friction_law with pure, allocation-free procedures, has_stiction and mu_stick if it
!! sticks, and a `build(b)` subroutine like the other laws'), then add its ONE line to `walk`:
!!   block; use landyn_friction_<law>, only: build; if (b%offered('<law>')) call build(b); end block
!! The factory, the input checks and friction_law_names() all walk the same lines.
module landyn_friction
  use landyn_config, only: friction_cfg_t
  use landyn_errors, only: input_errors_t
  use landyn_status, only: status_t
  use landyn_law_checks, only: law_build_t
  use landyn_friction_law, only: friction_law_t, friction_build_t, friction_state_t, adams_step, opposing_force, &
                                 default_stribeck_speed
  use landyn_friction_coulomb_step, only: coulomb_step_t, coulomb_step
  implicit none
  private

  public :: friction_law_t, friction_state_t, coulomb_step_t, coulomb_step
  public :: adams_step, opposing_force, default_stribeck_speed
  public :: make_friction_law, check_friction_law_input, friction_law_names

contains

  !> Build the law named by cfg%law (case-insensitive) from the &friction input.
  !! STAT_FAILED with its message for an unknown name or invalid parameters (the first problem
  !! found; law is then unallocated).
  subroutine make_friction_law(cfg, law, status)
    type(friction_cfg_t), intent(in) :: cfg                      !! resolved &friction input
    class(friction_law_t), allocatable, intent(out) :: law       !! the law
    type(status_t), intent(out) :: status                        !! STAT_OK, or STAT_FAILED with the reason [-]
    type(friction_build_t) :: b
    b%cfg = cfg
    call b%make(walk, 'friction', cfg%law, status)
    if (status%ok()) then
      call move_alloc(b%law, law)
      law%name = b%key
    end if
  end subroutine make_friction_law

  !> The law-dependent checks of the &friction input, one message per problem in the input
  !! validation's format. Nothing for an unknown law name (the input validation checks the name
  !! against friction_law_names()).
  subroutine check_friction_law_input(cfg, pre, errors)
    type(friction_cfg_t), intent(in) :: cfg        !! resolved &friction input
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    type(friction_build_t) :: b
    b%cfg = cfg
    call b%check(walk, 'friction', cfg%law, pre, errors)
  end subroutine check_friction_law_input

  !> Names accepted in &friction law, in the order of the registry, for messages and documentation:
  !! 'coulomb_step, ...'.
  function friction_law_names() result(names)
    character(len=:), allocatable :: names         !! the registered names, ', '-separated [-]
    type(friction_build_t) :: b
    names = b%list(walk)
  end function friction_law_names

  !> The registry: every friction law, one line each, in the order of the documentation. A line
  !! offers its law's name; the law asked for is built, a listing collects the names.
  subroutine walk(lb)
    class(law_build_t), intent(inout) :: lb        !! the build (or the listing), a friction_build_t
    select type (b => lb)
    type is (friction_build_t)
    block; use landyn_friction_coulomb_step, only: build; if (b%offered('coulomb_step')) call build(b); end block
    block; use landyn_friction_coulomb_step, only: build; if (b%offered('adams_step')) call build(b); end block
    block; use landyn_friction_coulomb, only: build => build_ty1; if (b%offered('ty1')) call build(b); end block
    block; use landyn_friction_coulomb, only: build => build_ty2; if (b%offered('ty2')) call build(b); end block
    block; use landyn_friction_regularized_coulomb, only: build; if (b%offered('ty3')) call build(b); end block
    block; use landyn_friction_coulomb, only: build => build_ty4; if (b%offered('ty4')) call build(b); end block
    block; use landyn_friction_stribeck, only: build; if (b%offered('ty5')) call build(b); end block
    block; use landyn_friction_modified_stribeck, only: build; if (b%offered('ty6')) call build(b); end block
    end select
  end subroutine walk

end module landyn_friction
