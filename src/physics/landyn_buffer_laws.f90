!> The buffer-law registry: the one place that lists the struts' buffer (crush) laws
!! (&primary_strut buffer_law, &secondary_strut buffer_law), their factory and the input checks
!! that depend on the law.
!!
!! Adding a law: write landyn_buffer_<law>.f90 (a type extending buffer_law_t of landyn_buffer
!! with pure, allocation-free procedures, and a `build(b)` subroutine, b a buffer_build_t, like
!! landyn_buffer_honeycomb's), then add its ONE line to `walk` below:
!!   block; use landyn_buffer_<law>, only: build; if (b%offered('<law>')) call build(b); end block
!! The factory, the input checks and buffer_law_names() all walk the same lines, so the law is
!! reachable from a deck and named in the messages and in docs/input.
module landyn_buffer_laws
  use landyn_config, only: primary_cfg_t, secondary_cfg_t
  use landyn_errors, only: input_errors_t
  use landyn_status, only: status_t
  use landyn_buffer, only: buffer_law_t
  use landyn_buffer_build, only: buffer_build_t
  use landyn_law_checks, only: law_build_t
  implicit none
  private

  public :: make_buffer_law, check_buffer_law_input, buffer_law_names

contains

  !> Build the buffer law of the primary strut (primary) or of the secondary struts, named by
  !! pri%buffer_law or sec%buffer_law (case-insensitive). STAT_FAILED with its message for an
  !! unknown name or invalid parameters (the first problem found; law is then unallocated).
  subroutine make_buffer_law(pri, sec, primary, law, status)
    type(primary_cfg_t), intent(in) :: pri                     !! resolved &primary_strut input
    type(secondary_cfg_t), intent(in) :: sec                   !! resolved &secondary_strut input
    logical, intent(in) :: primary                             !! the primary's law (else the secondaries') [-]
    class(buffer_law_t), allocatable, intent(out) :: law       !! the law
    type(status_t), intent(out) :: status                      !! STAT_OK, or STAT_FAILED with the reason [-]
    type(buffer_build_t) :: b
    call carry(b, pri, sec, primary)
    call b%make(walk, strut_group(primary), chosen(pri, sec, primary), status, var='buffer_law', &
                noun='buffer laws')
    if (status%ok()) call move_alloc(b%law, law)
  end subroutine make_buffer_law

  !> The law-dependent checks of &primary_strut and &secondary_strut, one message per problem in
  !! the input validation's format. Nothing for an unknown law name (the input validation checks the
  !! names against buffer_law_names()).
  subroutine check_buffer_law_input(pri, sec, pre, errors)
    type(primary_cfg_t), intent(in) :: pri         !! resolved &primary_strut input
    type(secondary_cfg_t), intent(in) :: sec       !! resolved &secondary_strut input
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    integer :: k
    do k = 1, 2   ! the primary's law, then the secondaries'
      block
        type(buffer_build_t) :: b
        call carry(b, pri, sec, k == 1)
        call b%check(walk, strut_group(k == 1), chosen(pri, sec, k == 1), pre, errors, var='buffer_law', &
                     noun='buffer laws')
      end block
    end do
  end subroutine check_buffer_law_input

  !> Names accepted in buffer_law, in the order of the registry, for messages and documentation:
  !! 'honeycomb, ...'.
  function buffer_law_names() result(names)
    character(len=:), allocatable :: names         !! the registered names, ', '-separated [-]
    type(buffer_build_t) :: b
    names = b%list(walk)
  end function buffer_law_names

  !> The registry: every buffer law, one line each, in the order of the documentation. A line
  !! offers its law's name; the law asked for is built, a listing collects the names.
  subroutine walk(lb)
    class(law_build_t), intent(inout) :: lb        !! the build (or the listing), a buffer_build_t
    select type (b => lb)
    type is (buffer_build_t)
    block; use landyn_buffer_honeycomb, only: build; if (b%offered('honeycomb')) call build(b); end block
    end select
  end subroutine walk

  !> The input a build of the primary's or the secondaries' law carries.
  subroutine carry(b, pri, sec, primary)
    type(buffer_build_t), intent(inout) :: b       !! the build
    type(primary_cfg_t), intent(in) :: pri         !! resolved &primary_strut input
    type(secondary_cfg_t), intent(in) :: sec       !! resolved &secondary_strut input
    logical, intent(in) :: primary                 !! the primary's law (else the secondaries') [-]
    b%primary = primary
    b%pri = pri
    b%sec = sec
  end subroutine carry

  !> The namelist group of the primary's (primary) or the secondaries' law.
  pure function strut_group(primary) result(group)
    logical, intent(in) :: primary                 !! the primary's law (else the secondaries') [-]
    character(len=:), allocatable :: group         !! 'primary_strut' or 'secondary_strut' [-]
    group = trim(merge('primary_strut  ', 'secondary_strut', primary))
  end function strut_group

  !> The law name the input chooses for the primary (primary) or the secondaries.
  function chosen(pri, sec, primary) result(name)
    type(primary_cfg_t), intent(in) :: pri         !! resolved &primary_strut input
    type(secondary_cfg_t), intent(in) :: sec       !! resolved &secondary_strut input
    logical, intent(in) :: primary                 !! the primary's law (else the secondaries') [-]
    character(len=:), allocatable :: name          !! the name as given [-]
    if (primary) then
      name = trim(pri%buffer_law)
    else
      name = trim(sec%buffer_law)
    end if
  end function chosen

end module landyn_buffer_laws
