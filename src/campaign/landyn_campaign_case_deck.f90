!> The cases of a campaign: the values of the varied inputs of case `id` (grid, Monte Carlo or
!! list), the case deck (the base deck's items with the case's overrides appended in deck
!! units, 17 significant digits), the case input read from it with the run-deck reader (so a case
!! is validated exactly as a deck), and the fingerprint of everything that defines the cases.
!!
!! Library code: nothing here stops or prints.
module landyn_campaign_case_deck
  use, intrinsic :: iso_fortran_env, only: int64
  use landyn_kinds, only: wp
  use landyn_status, only: status_t, STAT_OK, STAT_FAILED
  use landyn_config, only: landyn_input_t, is_set
  use landyn_input, only: input_errors_t, read_input_text, resolve_input, validate_input
  use landyn_campaign_text, only: lower_case, int_text, real_text, real_text_short
  use landyn_campaign_rng, only: case_uniform, case_truncated_normal, splitmix64_mix, add64
  use landyn_campaign_types, only: campaign_t, param_t, max_normal_tries
  implicit none
  private

  public :: case_values, case_deck_text, case_input, param_description, fingerprint_text, text_fingerprint

contains

  !> Everything that determines the cases and their success (not n_samples: a Monte Carlo
  !! campaign may be extended on resume).
  function fingerprint_text(camp) result(s)
    type(campaign_t), intent(in) :: camp  !! campaign [-]
    character(len=:), allocatable :: s    !! canonical description [-]
    integer :: i, j
    character(len=24) :: buf
    write (buf, '(i0)') camp%seed
    s = 'mode='//trim(camp%mode)//';seed='//trim(buf)//';n_gears='//int_text(camp%n_gears)// &
        ';base='//camp%base_text//';list='//camp%list_text
    do i = 1, camp%n_par
      associate (p => camp%par(i))
        s = s//';par='//p%name//'|'//p%label//'|'//trim(p%kind)//'|'//real_text(p%lo)//'|'//real_text(p%hi)//'|'// &
            real_text(p%mean)//'|'//real_text(p%sd)//'|v'
        do j = 1, size(p%values)
          s = s//real_text(p%values(j))//','
        end do
        s = s//'|w'
        do j = 1, size(p%weights)
          s = s//real_text(p%weights(j))//','
        end do
      end associate
    end do
    associate (c => camp%crit)
      s = s//';crit='//real_text(c%min_stroke_margin)//'|'//merge('T', 'F', c%overload_applied)// &
          real_text(c%max_overload)//'|'//merge('T', 'F', c%clearance_applied)//real_text(c%min_body_clearance)// &
          '|'//merge('T', 'F', c%require_at_rest)//'|'//trim(c%failed_runs)//'|'// &
          merge('T', 'F', c%tipover_applied)//real_text(c%min_tipover_margin)//'|'// &
          merge('T', 'F', c%friction_applied)//real_text(c%max_friction_ratio)//'|'
      do i = 1, c%n_body_points
        s = s//real_text(c%body_point(1, i))//real_text(c%body_point(2, i))//real_text(c%body_point(3, i))
      end do
    end associate
  end function fingerprint_text

  !> 64-bit hash of a text (SplitMix64 mixing of every byte), as 16 hex digits.
  function text_fingerprint(text) result(hex)
    character(len=*), intent(in) :: text  !! text [-]
    character(len=16) :: hex              !! hash [-]
    integer(int64) :: h
    integer :: i
    h = int(len(text), int64)
    do i = 1, len(text)
      h = splitmix64_mix(add64(ieor(h, int(iachar(text(i:i)), int64)), -7046029254386353131_int64))
    end do
    write (hex, '(z16.16)') h
  end function text_fingerprint

  !> The values of the varied inputs of case `id` (deck units). STAT_FAILED (with its message)
  !! when a truncated normal could not be sampled.
  subroutine case_values(camp, id, values, status)
    type(campaign_t), intent(in) :: camp               !! campaign [-]
    integer, intent(in) :: id                          !! case id, 1..n_cases [-]
    real(wp), intent(out) :: values(:)                 !! (n_par) values [deck unit]
    type(status_t), intent(out) :: status              !! STAT_OK, or STAT_FAILED with its message [-]
    integer :: j, r, i, st
    real(wp) :: u, a, b
    select case (camp%mode)
    case ('grid')
      r = id - 1
      do j = 1, camp%n_par
        values(j) = camp%par(j)%values(mod(r, camp%grid_n(j)) + 1)
        r = r/camp%grid_n(j)
      end do
    case ('list')
      values = camp%table(:, id)
    case default
      do j = 1, camp%n_par
        associate (p => camp%par(j))
          select case (p%kind)
          case ('uniform')
            values(j) = p%lo + (p%hi - p%lo)*case_uniform(camp%seed, id, j, 0)
          case ('normal')
            a = -huge(1.0_wp)
            b = huge(1.0_wp)
            if (is_set(p%lo)) a = p%lo
            if (is_set(p%hi)) b = p%hi
            call case_truncated_normal(camp%seed, id, j, p%mean, p%sd, a, b, max_normal_tries, values(j), st)
            if (st /= STAT_OK) then
              call status%fail(STAT_FAILED, 'no normal sample of '//p%name//' fell inside lo .. hi in '// &
                               int_text(max_normal_tries)//' tries')
              return
            end if
          case default   ! discrete
            u = case_uniform(camp%seed, id, j, 0)
            values(j) = p%values(size(p%values))
            do i = 1, size(p%values)
              if (u < p%weights(i)) then
                values(j) = p%values(i)
                exit
              end if
            end do
          end select
        end associate
      end do
    end select
  end subroutine case_values

  !> The run deck of case `id`: the base deck's items with the case's overrides (module header).
  function case_deck_text(camp, id, values) result(text)
    type(campaign_t), intent(in) :: camp   !! campaign [-]
    integer, intent(in) :: id              !! case id (0: no case) [-]
    real(wp), intent(in) :: values(:)      !! (n_par) values [deck unit]
    character(len=:), allocatable :: text  !! namelist deck [-]
    integer :: ig, k, j
    logical, allocatable :: used(:)
    character(len=1), parameter :: nl = new_line('a')
    allocate (used(camp%n_par))
    used = .false.
    text = ''
    if (id > 0) text = '! campaign '//camp%deck_name//', case '//int_text(id)//': base deck '//camp%base_path// &
                       ' with the case''s inputs appended to their groups'//nl
    do ig = 1, size(camp%base_groups)
      associate (g => camp%base_groups(ig))
        text = text//'&'//g%name//nl
        do k = 1, g%n_items
          if (any([(camp%par(j)%group == g%name .and. lower_case(camp%par(j)%lhs) == g%items(k)%key, &
                    j=1, camp%n_par)])) cycle
          text = text//'  '//g%items(k)%lhs//' = '//g%items(k)%value//nl
        end do
        do j = 1, camp%n_par
          if (camp%par(j)%group /= g%name) cycle
          text = text//override_item(camp%par(j), values(j))//nl
          used(j) = .true.
        end do
        text = text//'/'//nl
      end associate
    end do
    do j = 1, camp%n_par
      if (used(j)) cycle
      text = text//'&'//camp%par(j)%group//nl
      do k = j, camp%n_par
        if (camp%par(k)%group /= camp%par(j)%group .or. used(k)) cycle
        text = text//override_item(camp%par(k), values(k))//nl
        used(k) = .true.
      end do
      text = text//'/'//nl
    end do
  end function case_deck_text

  !> '  name(sub) = n*value' for one parameter.
  function override_item(p, x) result(s)
    type(param_t), intent(in) :: p       !! parameter [-]
    real(wp), intent(in) :: x            !! value [deck unit]
    character(len=:), allocatable :: s   !! deck item [-]
    character(len=:), allocatable :: v
    if (p%is_int .and. abs(x) < 1.0e9_wp) then
      v = int_text(nint(x))
    else
      v = real_text(x)
    end if
    if (p%n_elem > 1) v = int_text(p%n_elem)//'*'//v
    s = '  '//p%lhs//' = '//v
  end function override_item

  !> The resolved, validated input of case `id` with values `values`, read through the run-deck
  !! reader. stat = STAT_OK ready, STAT_FAILED invalid (messages in `errors`).
  subroutine case_input(camp, id, values, inp, errors, stat)
    type(campaign_t), intent(in) :: camp           !! campaign [-]
    integer, intent(in) :: id                      !! case id [-]
    real(wp), intent(in) :: values(:)              !! (n_par) values [deck unit]
    type(landyn_input_t), intent(out) :: inp       !! input of the case [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    integer, intent(out) :: stat                   !! 0 ok, 1 invalid [-]
    integer :: n0, st
    n0 = errors%count()
    call read_input_text(case_deck_text(camp, id, values), camp%base_path//' (case '//int_text(id)//')', &
                         inp, errors, st)
    if (errors%count() == n0) then
      call resolve_input(inp, errors)
      call validate_input(inp, errors)
    end if
    if (errors%count() == n0 .and. inp%gears%n_gears /= camp%n_gears) &
      call errors%add('case '//int_text(id)//': n_gears = '//int_text(inp%gears%n_gears)// &
                      ' differs from the base deck''s '//int_text(camp%n_gears))
    stat = merge(STAT_OK, STAT_FAILED, errors%count() == n0)
  end subroutine case_input

  !> One-line description of how a parameter is varied, e.g. "uniform(0, 2)".
  function param_description(p) result(s)
    type(param_t), intent(in) :: p      !! parameter [-]
    character(len=:), allocatable :: s  !! description [-]
    integer :: i
    select case (p%kind)
    case ('uniform')
      s = 'uniform(lo='//real_text_short(p%lo)//', hi='//real_text_short(p%hi)//')'
    case ('normal')
      s = 'normal(mean='//real_text_short(p%mean)//', sd='//real_text_short(p%sd)
      if (is_set(p%lo)) s = s//', lo='//real_text_short(p%lo)
      if (is_set(p%hi)) s = s//', hi='//real_text_short(p%hi)
      s = s//')'
    case ('discrete', 'grid')
      s = trim(p%kind)//'('
      do i = 1, min(size(p%values), 12)
        if (i > 1) s = s//', '
        s = s//real_text_short(p%values(i))
      end do
      if (size(p%values) > 12) s = s//', ... ('//int_text(size(p%values))//' values)'
      s = s//')'
    case default
      s = 'list'
    end select
    s = p%name//' ['//p%units//'] '//s
  end function param_description

end module landyn_campaign_case_deck
