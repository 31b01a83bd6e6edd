!> The walk of a registry and the parameter checks its builders share. Every registry of
!! interchangeable parts (contact laws, friction laws, buffer laws, gear types, integrators) is a
!! subroutine `walk(b)` with one line per part,
!!   block; use <module>, only: build; if (b%offered('<name>')) call build(b); end block
!! and b extends law_build_t: the factory (b%make), the input checks (b%check) and the list of
!! names (b%list: messages, the input registry's choices, docs/input) walk the same lines, and
!! each registry's entry points only say which input its build carries. A walk takes the
!! registry_walk interface (class(law_build_t)) and selects its own build type:
!!   select type (b => lb); type is (contact_build_t); <the lines>; end select
!! Every problem is one message
!! in the format of the input validation,
!!   pre//'&'//group//': '//var//' = '//value//' is invalid; valid: '//requirement
!! appended to an error collector, so the factories and the input validation report alike.
module landyn_law_checks
  use landyn_kinds, only: wp
  use landyn_errors, only: input_errors_t
  use landyn_real_text, only: fmt_real
  use landyn_status, only: STAT_FAILED, status_t
  use landyn_strings, only: lower_case
  implicit none
  private

  public :: law_build_t, registry_walk, positive

  !> What a builder works on besides the input and the part it builds (extended by each registry's
  !! build type: contact_build_t, friction_build_t, buffer_build_t, gear_build_t,
  !! integrator_build_t): the namelist group and variable of the choice, the message prefix, the
  !! messages so far, and whether only the choice-dependent checks run (the input validation) or
  !! the part is built (the factory).
  type :: law_build_t
    character(len=16) :: group = ''                 !! namelist group without '&': 'contact', 'friction' [-]
    character(len=16) :: var = 'law'                !! the variable naming the choice: 'law', 'gear_type' [-]
    character(len=16) :: noun = 'laws'              !! what the registry holds, in messages: 'laws', 'gear types' [-]
    character(len=:), allocatable :: pre            !! message prefix (deck name or '') [-]
    type(input_errors_t) :: errors                  !! problems found so far
    logical :: check_only = .false.                 !! only the law-dependent checks, build nothing [-]
    character(len=:), allocatable :: key            !! the law asked for, lower case [-]
    logical :: listing = .false.                    !! walk the registry to list the names, build nothing [-]
    character(len=:), allocatable :: names          !! with listing: the registered names, ', '-separated [-]
    logical :: found = .false.                      !! a registered law answered to key [-]
  contains
    procedure :: start => build_start               !! set up a build, a check or a listing
    procedure :: offered => build_offered           !! a registry line: is this law the one asked for?
    procedure :: require => build_require           !! append a message unless a requirement holds
    procedure :: require_positive => build_require_positive        !! "var > 0 unit" unless it holds
    procedure :: require_nonnegative => build_require_nonnegative  !! "var >= 0 unit" unless it holds
    procedure :: outcome => build_outcome           !! the factory's status
    procedure :: pass_on => build_pass_on           !! append the messages to another collector
    procedure :: make => build_make                 !! the factory's walk: build the part asked for
    procedure :: check => build_check               !! the input checks' walk: messages of the part asked for
    procedure :: list => build_list                 !! the listing walk: the registered names
  end type law_build_t

  abstract interface
    !> A registry's walk, one line per part (module comment); lb is the registry's build type.
    subroutine registry_walk(lb)
      import :: law_build_t
      class(law_build_t), intent(inout) :: lb       !! the build (or the listing)
    end subroutine registry_walk
  end interface

contains

  !> Append "&group: var = x unit is invalid; valid: requirement" unless ok.
  subroutine require_real(errors, ok, pre, group, var, x, unit, valid)
    type(input_errors_t), intent(inout) :: errors  !! error list
    logical, intent(in) :: ok                      !! the requirement holds [-]
    character(len=*), intent(in) :: pre            !! message prefix (deck name or '') [-]
    character(len=*), intent(in) :: group          !! namelist group without '&' [-]
    character(len=*), intent(in) :: var            !! variable name [-]
    real(wp), intent(in) :: x                      !! its value [unit]
    character(len=*), intent(in) :: unit           !! unit text, '' for none [-]
    character(len=*), intent(in) :: valid          !! the requirement, e.g. 'damping >= 0 N s/m' [-]
    character(len=:), allocatable :: value
    if (ok) return
    value = fmt_real(x)//unit_suffix(unit)
    call errors%add(pre//'&'//group//': '//var//' = '//value//' is invalid; valid: '//valid)
  end subroutine require_real

  !> Append "&group: var = x unit is invalid; valid: requirement" unless ok.
  subroutine build_require(self, ok, var, x, unit, valid)
    class(law_build_t), intent(inout) :: self      !! the build
    logical, intent(in) :: ok                      !! the requirement holds [-]
    character(len=*), intent(in) :: var            !! variable name [-]
    real(wp), intent(in) :: x                      !! its value [unit]
    character(len=*), intent(in) :: unit           !! unit text, '' for none [-]
    character(len=*), intent(in) :: valid          !! the requirement [-]
    call require_real(self%errors, ok, self%pre, trim(self%group), var, x, unit, valid)
  end subroutine build_require

  !> Append "&group: var = x unit is invalid; valid: var > 0 unit" unless x is a finite number > 0.
  subroutine build_require_positive(self, var, x, unit)
    class(law_build_t), intent(inout) :: self      !! the build
    character(len=*), intent(in) :: var            !! variable name [-]
    real(wp), intent(in) :: x                      !! its value [unit]
    character(len=*), intent(in) :: unit           !! unit text, '' for none [-]
    call self%require(positive(x), var, x, unit, var//' > 0'//unit_suffix(unit))
  end subroutine build_require_positive

  !> Append "&group: var = x unit is invalid; valid: var >= 0 unit" unless x is a finite number >= 0.
  subroutine build_require_nonnegative(self, var, x, unit)
    class(law_build_t), intent(inout) :: self      !! the build
    character(len=*), intent(in) :: var            !! variable name [-]
    real(wp), intent(in) :: x                      !! its value [unit]
    character(len=*), intent(in) :: unit           !! unit text, '' for none [-]
    call self%require(nonnegative(x), var, x, unit, var//' >= 0'//unit_suffix(unit))
  end subroutine build_require_nonnegative

  !> ' '//unit, or '' without a unit.
  pure function unit_suffix(unit) result(s)
    character(len=*), intent(in) :: unit           !! unit text, '' for none [-]
    character(len=:), allocatable :: s             !! the suffix [-]
    s = ''
    if (len(unit) > 0) s = ' '//unit
  end function unit_suffix

  !> The factory's result: STAT_OK, or STAT_FAILED with the first message (an unknown name first
  !! adds "&group var = 'name' is not known; known noun: names", e.g. "&contact law = 'x' is not
  !! known; known laws: base, ...").
  subroutine build_outcome(self, law, names, status)
    class(law_build_t), intent(inout) :: self      !! the build, after the registry walk
    character(len=*), intent(in) :: law           !! law name as given [-]
    character(len=*), intent(in) :: names          !! the registered names, for the message [-]
    type(status_t), intent(out) :: status          !! STAT_OK, or STAT_FAILED with the first problem [-]
    if (.not. self%found) call self%errors%add('&'//trim(self%group)//' '//trim(self%var)//" = '"// &
                                               trim(adjustl(law))//"' is not known; known "//trim(self%noun)//': '//names)
    if (self%errors%count() > 0) call status%fail(STAT_FAILED, self%errors%message(1))
  end subroutine build_outcome

  !> Set up a walk of the registry: build (or, with check_only, only check) the part named `law`
  !! (case-insensitive, blanks ignored) of namelist group `group`, messages prefixed by `pre`; with
  !! `listing`, collect the registered names instead. `var` and `noun` name the choice in messages
  !! (default 'law' and 'laws').
  subroutine build_start(self, group, law, pre, check_only, listing, var, noun)
    class(law_build_t), intent(inout) :: self      !! the build
    character(len=*), intent(in) :: group          !! namelist group without '&' [-]
    character(len=*), intent(in) :: law            !! law name as given ('' for a listing) [-]
    character(len=*), intent(in) :: pre            !! message prefix (deck name or '') [-]
    logical, intent(in), optional :: check_only    !! only the law-dependent checks [-]
    logical, intent(in), optional :: listing       !! list the registered names [-]
    character(len=*), intent(in), optional :: var  !! the variable naming the choice (default 'law') [-]
    character(len=*), intent(in), optional :: noun !! what the registry holds, plural (default 'laws') [-]
    self%group = group
    self%var = 'law'
    if (present(var)) self%var = var
    self%noun = 'laws'
    if (present(noun)) self%noun = noun
    self%key = lower_case(trim(adjustl(law)))
    self%pre = pre
    self%found = .false.
    self%check_only = .false.
    if (present(check_only)) self%check_only = check_only
    self%listing = .false.
    if (present(listing)) self%listing = listing
    self%names = ''
  end subroutine build_start

  !> One registry line offers the law `name`: .true. when it is the one asked for (b%key), so
  !! the line builds it; with b%listing, the name is appended to b%names and nothing is built.
  function build_offered(self, name) result(chosen)
    class(law_build_t), intent(inout) :: self      !! the build (or the listing)
    character(len=*), intent(in) :: name           !! a registered law name, lower case [-]
    logical :: chosen                              !! build this law now [-]
    chosen = .false.
    if (self%listing) then
      if (.not. allocated(self%names)) self%names = ''
      if (len(self%names) > 0) self%names = self%names//', '
      self%names = self%names//name
    else if (allocated(self%key)) then
      chosen = self%key == name .and. .not. self%found
      if (chosen) self%found = .true.
    end if
  end function build_offered

  !> The factory's walk: build the part `name` (case-insensitive) of namelist group `group` into
  !! the build (the registry's entry point takes it from there), the status as outcome gives it;
  !! the known names (a listing walk) only when none answered. `var` and `noun` as in start.
  subroutine build_make(self, walk, group, name, status, var, noun)
    class(law_build_t), intent(inout) :: self      !! the build, its input set
    procedure(registry_walk) :: walk               !! the registry's walk
    character(len=*), intent(in) :: group          !! namelist group without '&' [-]
    character(len=*), intent(in) :: name           !! name of the part as given [-]
    type(status_t), intent(out) :: status          !! STAT_OK, or STAT_FAILED with the first problem [-]
    character(len=*), intent(in), optional :: var  !! the variable naming the choice (default 'law') [-]
    character(len=*), intent(in), optional :: noun !! what the registry holds, plural (default 'laws') [-]
    call self%start(group, name, '', var=var, noun=noun)
    call walk(self)
    if (self%found) then
      call self%outcome(name, '', status)
    else
      call self%outcome(name, self%list(walk), status)
    end if
  end subroutine build_make

  !> The input checks' walk: the checks of the part `name` of group `group` (nothing built), their
  !! messages, prefixed by `pre`, appended to errors. Nothing for an unknown name (the input
  !! validation checks the name against the registry's names).
  subroutine build_check(self, walk, group, name, pre, errors, var, noun)
    class(law_build_t), intent(inout) :: self      !! the build, its input set
    procedure(registry_walk) :: walk               !! the registry's walk
    character(len=*), intent(in) :: group          !! namelist group without '&' [-]
    character(len=*), intent(in) :: name           !! name of the part as given [-]
    character(len=*), intent(in) :: pre            !! message prefix (deck name or '') [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    character(len=*), intent(in), optional :: var  !! the variable naming the choice (default 'law') [-]
    character(len=*), intent(in), optional :: noun !! what the registry holds, plural (default 'laws') [-]
    call self%start(group, name, pre, check_only=.true., var=var, noun=noun)
    call walk(self)
    if (self%found) call self%pass_on(errors)
  end subroutine build_check

  !> The names the registry's lines offer, in their order, ', '-separated: a listing walk with a
  !! fresh build of self's type (self itself is not changed).
  function build_list(self, walk) result(names)
    class(law_build_t), intent(in) :: self         !! a build of the registry's type
    procedure(registry_walk) :: walk               !! the registry's walk
    character(len=:), allocatable :: names         !! the registered names [-]
    class(law_build_t), allocatable :: listing
    allocate (listing, mold=self)
    call listing%start('', '', '', listing=.true.)
    call walk(listing)
    names = listing%names
  end function build_list

  !> Append the build's messages to errors.
  subroutine build_pass_on(self, errors)
    class(law_build_t), intent(in) :: self         !! the build
    type(input_errors_t), intent(inout) :: errors  !! receives the messages
    integer :: i
    do i = 1, self%errors%count()
      call errors%add(self%errors%message(i))
    end do
  end subroutine build_pass_on

  !> x is a finite number > 0.
  elemental function positive(x) result(ok)
    real(wp), intent(in) :: x  !! value [any unit]
    logical :: ok              !! 0 < x <= huge [-]
    ok = x > 0.0_wp .and. x <= huge(1.0_wp)
  end function positive

  !> x is a finite number >= 0.
  elemental function nonnegative(x) result(ok)
    real(wp), intent(in) :: x  !! value [any unit]
    logical :: ok              !! 0 <= x <= huge [-]
    ok = x >= 0.0_wp .and. x <= huge(1.0_wp)
  end function nonnegative

end module landyn_law_checks
