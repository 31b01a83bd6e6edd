!> The varied inputs and criteria of a campaign deck: a raw &parameter becomes a `param_t`
!! (mode-dependent checks of its values, bounds and distribution), raw &criteria become `criteria_t`.
!!
!! Library code: nothing here stops or prints.
module landyn_campaign_params
  use landyn_kinds, only: wp
  use landyn_config, only: is_set
  use landyn_input, only: input_errors_t
  use landyn_campaign_text, only: lower_case, int_text, real_text_short, quote_text
  use landyn_campaign_types, only: param_t, criteria_t, raw_parameter_t, raw_criteria_t, max_values, &
                                   max_body_points, label_len, min_truncated_mass
  use landyn_campaign_target, only: parse_target
  implicit none
  private

  public :: make_param, make_criteria

  !> The &parameter variables that some kinds of parameter do not use, in the order of make_param's masks [-]
  character(len=*), parameter :: param_vars(*) = [character(len=7) :: 'start', 'stop', 'count', 'lo', 'hi', 'mean', &
    'sd', 'values', 'weights']
  !> Which of param_vars a grid parameter uses [-]
  logical, parameter :: grid_uses(*) = [.true., .true., .true., .false., .false., .false., .false., .true., .false.]
  !> Which of param_vars distribution 'uniform' uses [-]
  logical, parameter :: uniform_uses(*) = [.false., .false., .false., .true., .true., .false., .false., .false., .false.]
  !> Which of param_vars distribution 'normal' uses [-]
  logical, parameter :: normal_uses(*) = [.false., .false., .false., .true., .true., .true., .true., .false., .false.]
  !> Which of param_vars distribution 'discrete' uses [-]
  logical, parameter :: discrete_uses(*) = [.false., .false., .false., .false., .false., .false., .false., .true., .true.]
  !> Which of param_vars a Monte Carlo parameter without a valid distribution may use: all but start, stop
  !! and count [-]
  logical, parameter :: any_mc_uses(*) = [.false., .false., .false., .true., .true., .true., .true., .true., .true.]

contains

  !> Turn a raw &parameter into a parameter of the campaign (mode-dependent checks).
  subroutine make_param(rp, line, mode, deck_name, p, errors)
    type(raw_parameter_t), intent(in) :: rp        !! values read [-]
    integer, intent(in) :: line                    !! line of the group [-]
    character(len=*), intent(in) :: mode           !! campaign mode [-]
    character(len=*), intent(in) :: deck_name      !! deck path [-]
    type(param_t), intent(out) :: p                !! the parameter [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    character(len=:), allocatable :: pre, msg, dist, what
    integer :: nv, nw
    logical :: given(size(param_vars))

    p%line = line
    pre = deck_name//':'//int_text(line)//': &parameter'
    if (len_trim(rp%name) == 0) return   ! reported already
    call parse_target(rp%name, p, msg)
    if (len(msg) > 0) then
      call errors%add(pre//': name = '//quote_text(trim(rp%name))//' is invalid: '//msg)
      return
    end if
    pre = pre//" '"//p%name//"'"
    if (len_trim(rp%label) > 0) then
      p%label = trim(rp%label)
      if (.not. valid_label(p%label)) call errors%add(pre//': label = '//quote_text(p%label)// &
        ' is invalid; valid: letters, digits, _ . - (at most 64, not starting with .)')
    end if
    call count_set(rp%values, nv, msg)
    if (len(msg) > 0) call errors%add(pre//': values '//msg)
    call count_set(rp%weights, nw, msg)
    if (len(msg) > 0) call errors%add(pre//': weights '//msg)
    dist = lower_case(trim(adjustl(rp%distribution)))

    if (mode == 'grid') then
      what = 'a grid parameter'
    else
      what = "distribution '"//dist//"'"
    end if
    given = [is_set(rp%start), is_set(rp%stop), rp%count /= -1, is_set(rp%lo), is_set(rp%hi), is_set(rp%mean), &
             is_set(rp%sd), nv > 0, nw > 0]
    select case (mode)
    case ('grid')
      p%kind = 'grid'
      call report_unused(given .and. .not. grid_uses, pre, what, errors)
      call grid_param(rp, nv, dist, pre, p, errors)
    case ('monte_carlo')
      if (any(dist == [character(len=8) :: 'uniform', 'normal', 'discrete'])) p%kind = dist
      select case (dist)
      case ('uniform')
        call report_unused(given .and. .not. uniform_uses, pre, what, errors)
        call uniform_param(rp, pre, p, errors)
      case ('normal')
        call report_unused(given .and. .not. normal_uses, pre, what, errors)
        call normal_param(rp, pre, p, errors)
      case ('discrete')
        call report_unused(given .and. .not. discrete_uses, pre, what, errors)
        call discrete_param(rp, nv, nw, pre, p, errors)
      case ('')
        call report_unused(given .and. .not. any_mc_uses, pre, what, errors)
        call errors%add(pre//": distribution is not given; valid: 'uniform' (lo, hi), 'normal' (mean, sd, "// &
                        "optional lo, hi) or 'discrete' (values, optional weights)")
      case default
        call report_unused(given .and. .not. any_mc_uses, pre, what, errors)
        call errors%add(pre//': distribution = '//quote_text(dist)//" is invalid; valid: 'uniform', 'normal' "// &
                        "or 'discrete'")
      end select
    end select
    if (.not. allocated(p%values)) allocate (p%values(0))
    if (.not. allocated(p%weights)) allocate (p%weights(0))
  end subroutine make_param

  !> A grid parameter: its values, given as values or as start, stop and count (evenly spaced, the
  !! last exactly stop); the distribution variables must not be given.
  subroutine grid_param(rp, nv, dist, pre, p, errors)
    type(raw_parameter_t), intent(in) :: rp        !! values read [-]
    integer, intent(in) :: nv                      !! values given [-]
    character(len=*), intent(in) :: dist           !! distribution given (must be empty) [-]
    character(len=*), intent(in) :: pre            !! message prefix: deck, line, group, name [-]
    type(param_t), intent(inout) :: p              !! the parameter [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    integer :: i
    if (len(dist) > 0) call errors%add(pre//': distribution = '//quote_text(dist)// &
      ' is not used in grid mode (grids take values, or start, stop and count); remove it')
    if (nv > 0) then
      if (is_set(rp%start) .or. is_set(rp%stop) .or. rp%count /= -1) then
        call errors%add(pre//': give either values or start, stop and count, not both')
      end if
      p%values = rp%values(1:nv)
    else if (rp%count /= -1 .or. is_set(rp%start) .or. is_set(rp%stop)) then
      if (rp%count < 1) then
        call errors%add(pre//': count = '//int_text(rp%count)//' is invalid; valid: count >= 1 (with start and stop)')
      else if (.not. is_set(rp%start)) then
        call errors%add(pre//': start is not given; valid: the first grid value (with stop and count)')
      else if (rp%count == 1) then
        p%values = [rp%start]
      else if (.not. is_set(rp%stop)) then
        call errors%add(pre//': stop is not given; valid: the last grid value (with start and count)')
      else if (rp%count > max_values) then
        call errors%add(pre//': count = '//int_text(rp%count)//' is invalid; valid: count <= '//int_text(max_values))
      else
        allocate (p%values(rp%count))
        do i = 1, rp%count
          p%values(i) = rp%start + (rp%stop - rp%start)*real(i - 1, wp)/real(rp%count - 1, wp)
        end do
        p%values(rp%count) = rp%stop
      end if
    else
      call errors%add(pre//': no grid values; valid: values = v1, v2, ... or start, stop and count')
    end if
    if (allocated(p%values)) call check_integral(p, pre, errors)

  end subroutine grid_param

  !> A Monte Carlo parameter of distribution 'uniform' on lo .. hi.
  subroutine uniform_param(rp, pre, p, errors)
    type(raw_parameter_t), intent(in) :: rp        !! values read [-]
    character(len=*), intent(in) :: pre            !! message prefix: deck, line, group, name [-]
    type(param_t), intent(inout) :: p              !! the parameter [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    if (.not. (is_set(rp%lo) .and. is_set(rp%hi))) then
      call errors%add(pre//": distribution 'uniform' needs lo and hi")
    else if (.not. rp%lo < rp%hi) then
      call errors%add(pre//': lo = '//real_text_short(rp%lo)//', hi = '//real_text_short(rp%hi)// &
                      ' is invalid; valid: lo < hi')
    end if
    p%lo = rp%lo
    p%hi = rp%hi
    if (p%is_int) call errors%add(pre//": is an integer input; valid distribution: 'discrete'")
  end subroutine uniform_param

  !> A Monte Carlo parameter of distribution 'normal' (mean, sd), optionally truncated to lo .. hi, which
  !! must keep at least min_truncated_mass of it.
  subroutine normal_param(rp, pre, p, errors)
    type(raw_parameter_t), intent(in) :: rp        !! values read [-]
    character(len=*), intent(in) :: pre            !! message prefix: deck, line, group, name [-]
    type(param_t), intent(inout) :: p              !! the parameter [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    real(wp) :: mass, a, b
    if (.not. (is_set(rp%mean) .and. is_set(rp%sd))) then
      call errors%add(pre//": distribution 'normal' needs mean and sd (lo and hi truncate it, optional)")
    else if (.not. rp%sd > 0.0_wp) then
      call errors%add(pre//': sd = '//real_text_short(rp%sd)//' is invalid; valid: sd > 0')
    else
      a = -huge(1.0_wp)
      b = huge(1.0_wp)
      if (is_set(rp%lo)) a = rp%lo
      if (is_set(rp%hi)) b = rp%hi
      if (.not. a < b) then
        call errors%add(pre//': lo = '//real_text_short(a)//', hi = '//real_text_short(b)// &
                        ' is invalid; valid: lo < hi')
      else
        mass = 0.5_wp*(erf(scaled(b, rp%mean, rp%sd)) - erf(scaled(a, rp%mean, rp%sd)))
        if (mass < min_truncated_mass) call errors%add(pre//': the truncation lo .. hi keeps only '// &
          real_text_short(mass)//' of the normal distribution; valid: at least 1e-3 (widen lo .. hi)')
      end if
    end if
    p%mean = rp%mean
    p%sd = rp%sd
    p%lo = rp%lo
    p%hi = rp%hi
    if (p%is_int) call errors%add(pre//": is an integer input; valid distribution: 'discrete'")
  end subroutine normal_param

  !> A Monte Carlo parameter of distribution 'discrete': values and their cumulative weights (equal
  !! weights when none are given).
  subroutine discrete_param(rp, nv, nw, pre, p, errors)
    type(raw_parameter_t), intent(in) :: rp        !! values read [-]
    integer, intent(in) :: nv                      !! values given [-]
    integer, intent(in) :: nw                      !! weights given [-]
    character(len=*), intent(in) :: pre            !! message prefix: deck, line, group, name [-]
    type(param_t), intent(inout) :: p              !! the parameter [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    real(wp) :: a, b
    integer :: i
    if (nv == 0) then
      call errors%add(pre//": distribution 'discrete' needs values (and optional weights)")
    else
      p%values = rp%values(1:nv)
      call check_integral(p, pre, errors)
      if (nw == 0) then
        p%weights = [(real(i, wp)/real(nv, wp), i=1, nv)]
      else if (nw /= nv) then
        call errors%add(pre//': '//int_text(nw)//' weights for '//int_text(nv)// &
                        ' values; valid: one weight per value')
      else if (any(rp%weights(1:nw) < 0.0_wp) .or. .not. sum(rp%weights(1:nw)) > 0.0_wp) then
        call errors%add(pre//': weights are invalid; valid: weights >= 0 with a positive sum')
      else
        allocate (p%weights(nv))
        a = sum(rp%weights(1:nw))
        b = 0.0_wp
        do i = 1, nv
          b = b + rp%weights(i)
          p%weights(i) = b/a
        end do
        p%weights(nv) = 1.0_wp
      end if
    end if
  end subroutine discrete_param

  !> Report the variables given in the group that this kind of parameter does not use.
  subroutine report_unused(unused, pre, what, errors)
    logical, intent(in) :: unused(:)               !! per param_vars entry: given but not used [-]
    character(len=*), intent(in) :: pre            !! message prefix: deck, line, group, name [-]
    character(len=*), intent(in) :: what           !! the parameter's kind: 'a grid parameter' or "distribution '<name>'" [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    integer :: k
    do k = 1, size(unused)
      if (unused(k)) call errors%add(pre//': '//trim(param_vars(k))//' is not used by '//what//'; remove it')
    end do
  end subroutine report_unused

  !> For an integer input, report the first value that is not a whole number (or exceeds 1e9).
  subroutine check_integral(p, pre, errors)
    type(param_t), intent(in) :: p                 !! the parameter, with its values [deck unit]
    character(len=*), intent(in) :: pre            !! message prefix: deck, line, group, name [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    integer :: j
    if (.not. p%is_int) return
    do j = 1, size(p%values)
      if (abs(p%values(j)) > 1.0e9_wp .or. abs(p%values(j) - anint(p%values(j))) > 0.0_wp) then
        call errors%add(pre//': value '//real_text_short(p%values(j))//' is invalid for an integer input; '// &
                        'valid: whole numbers')
        return
      end if
    end do
  end subroutine check_integral

  !> (x - mean)/(sqrt(2) sd), limited to +-6 (erf is +-1 to double precision there).
  elemental function scaled(x, mean, sd) result(y)
    real(wp), intent(in) :: x                      !! truncation bound [deck unit]
    real(wp), intent(in) :: mean                   !! mean of the normal distribution [deck unit]
    real(wp), intent(in) :: sd                     !! its standard deviation [deck unit]
    real(wp) :: y                                  !! scaled bound [-]
    real(wp), parameter :: ymax = 6.0_wp
    if (abs(x - mean) >= ymax*sqrt(2.0_wp)*sd) then
      y = sign(ymax, x - mean)
    else
      y = (x - mean)/(sqrt(2.0_wp)*sd)
    end if
  end function scaled

  !> Number of leading set entries of an array read with unset defaults; msg /= '' on gaps.
  subroutine count_set(x, n, msg)
    real(wp), intent(in) :: x(:)                       !! array [any unit]
    integer, intent(out) :: n                          !! leading set entries [-]
    character(len=:), allocatable, intent(out) :: msg  !! problem, '' if none [-]
    integer :: i
    msg = ''
    n = 0
    do i = 1, size(x)
      if (.not. is_set(x(i))) exit
      n = i
    end do
    if (any(is_set(x(n + 1:)))) msg = 'have gaps (an element not given between given ones); give them in order from 1'
  end subroutine count_set

  !> Whether a label can be a summary-file column name (at most label_len characters).
  pure function valid_label(label) result(ok)
    character(len=*), intent(in) :: label  !! column name [-]
    logical :: ok                          !! letters, digits, _ . - ; not starting with '.' [-]
    ok = len(label) > 0 .and. len(label) <= label_len .and. &
         verify(label, 'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.-') == 0
    if (ok) ok = label(1:1) /= '.'
  end function valid_label

  !> &criteria values into the campaign.
  subroutine make_criteria(rcr, deck_name, crit, errors)
    type(raw_criteria_t), intent(in) :: rcr        !! values read [-]
    character(len=*), intent(in) :: deck_name      !! deck path [-]
    type(criteria_t), intent(out) :: crit          !! criteria [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    integer :: i, n
    crit%min_stroke_margin = rcr%min_stroke_margin
    call positive_limit(rcr%max_overload, 'max_overload', ' g', deck_name, crit%overload_applied, crit%max_overload, &
                        errors)
    crit%clearance_applied = is_set(rcr%min_body_clearance)
    if (crit%clearance_applied) crit%min_body_clearance = rcr%min_body_clearance
    n = 0
    do i = 1, max_body_points
      if (all(is_set(rcr%body_point(:, i)))) then
        n = n + 1
        crit%body_point(:, n) = rcr%body_point(:, i)
      else if (any(is_set(rcr%body_point(:, i)))) then
        call errors%add(deck_name//': &criteria: body_point(:, '//int_text(i)// &
                        ') is given in part; valid: all three coordinates x, y, z')
      end if
    end do
    crit%n_body_points = n
    if (n == 0) then
      crit%n_body_points = 1
      crit%body_point(:, 1) = 0.0_wp
    end if
    crit%require_at_rest = rcr%require_at_rest
    crit%tipover_applied = is_set(rcr%min_tipover_margin)
    if (crit%tipover_applied) crit%min_tipover_margin = rcr%min_tipover_margin
    call positive_limit(rcr%max_friction_ratio, 'max_friction_ratio', '', deck_name, crit%friction_applied, &
                        crit%max_friction_ratio, errors)
    crit%failed_runs = lower_case(trim(adjustl(rcr%failed_runs)))
    if (crit%failed_runs /= 'count_as_failure' .and. crit%failed_runs /= 'exclude') &
      call errors%add(deck_name//': &criteria: failed_runs = '//quote_text(trim(rcr%failed_runs))// &
                      " is invalid; valid: 'count_as_failure' or 'exclude'")
  end subroutine make_criteria

  !> A &criteria limit applied only when given, and then > 0.
  subroutine positive_limit(raw, name, unit, deck_name, applied, x, errors)
    real(wp), intent(in) :: raw                    !! value read, unset_real when not given [unit]
    character(len=*), intent(in) :: name           !! variable [-]
    character(len=*), intent(in) :: unit           !! ' <unit>' in messages, '' if none [-]
    character(len=*), intent(in) :: deck_name      !! deck path [-]
    logical, intent(out) :: applied                !! the limit was given [-]
    real(wp), intent(inout) :: x                   !! the limit, set when given [unit]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    applied = is_set(raw)
    if (.not. applied) return
    x = raw
    if (.not. raw > 0.0_wp) call errors%add(deck_name//': &criteria: '//name//' = '//real_text_short(raw)//unit// &
                                           ' is invalid; valid: '//name//' > 0'//unit)
  end subroutine positive_limit

end module landyn_campaign_params
