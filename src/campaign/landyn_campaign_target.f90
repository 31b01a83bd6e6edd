!> The run-deck inputs a campaign can vary: `parse_target` turns 'group%variable(subscript)'
!! into a parameter's group, variable, deck units, shape and elements, from the input registry
!! (landyn_input_registry): every numeric variable of a run deck can be varied except those whose
!! registry entry says why not (text, logicals, n_gears, the output file).
!!
!! Library code: nothing here stops or prints.
module landyn_campaign_target
  use landyn_input_registry, only: input_var_t, input_vars, group_names, group_index, var_index, k_int, &
                                   k_logical, k_string
  use landyn_config, only: default_input
  use landyn_input, only: input_errors_t, resolved_input_text
  use landyn_namelist_items, only: nml_group_t, split_namelist
  use landyn_campaign_text, only: lower_case, int_text, close_name_hint, &
                                 hint_and_list, name_list
  use landyn_campaign_types, only: param_t
  implicit none
  private

  public :: parse_target, run_variable_table, default_deck_variables

contains

  !> Parse 'group%variable(subscript)' into `p` (name, group, lhs, units, elements);
  !! msg /= '' says what is wrong.
  subroutine parse_target(name_in, p, msg)
    character(len=*), intent(in) :: name_in            !! the input name as given [-]
    type(param_t), intent(inout) :: p                  !! parameter updated [-]
    character(len=:), allocatable, intent(out) :: msg  !! problem, '' if none [-]
    character(len=:), allocatable :: grp, var, sub
    integer :: iv, ext(2), rank
    type(input_var_t) :: e
    call split_target(name_in, grp, var, sub, iv, msg)
    if (len(msg) > 0) return
    p%group = grp
    p%var = var
    e = input_vars(iv)
    p%units = trim(e%unit)
    if (len(p%units) == 0) p%units = '-'
    p%is_int = e%kind == k_int
    rank = 0
    if (e%n1 > 0) rank = 1
    if (e%n2 > 0) rank = 2
    ext = [max(e%n1, 1), max(e%n2, 1)]
    if (rank == 0) then
      if (len(sub) > 0) then
        msg = var//' is a scalar; give it without a subscript'
        return
      end if
      p%lhs = var
      p%n_elem = 1
      p%elems = [1]
      p%name = grp//'%'//var
      if (.not. allocated(p%label)) p%label = grp//'.'//var
      return
    end if
    if (len(sub) == 0) then
      if (rank == 1) then
        msg = var//' is an array of '//int_text(ext(1))//'; give an element, e.g. '//var//'(1), a range '//var// &
              '(1:2), or '//var//'(:) for all elements'
      else
        msg = var//' is a 3 x '//int_text(ext(2))//' array; give an element, e.g. '//var//'(3, 1), or a section, '// &
              'e.g. '//var//'(:, 1)'
      end if
      return
    end if
    call target_elements(var, sub, rank, ext, p, msg)
    if (len(msg) > 0) return
    p%lhs = var//'('//sub//')'
    p%name = grp//'%'//var//'('//sub//')'
    if (.not. allocated(p%label)) then
      if (sub == ':' .and. rank == 1) then
        p%label = grp//'.'//var
      else
        p%label = grp//'.'//var//'_'//label_sub(sub)
      end if
    end if
  end subroutine parse_target

  !> Split an input name 'group%variable(subscript)' (blanks dropped, lower case) into its group,
  !! variable and subscript text, and find the variable in the input registry; msg /= '' when the
  !! name is malformed, the group or variable unknown, or the variable one a campaign cannot vary.
  subroutine split_target(name_in, grp, var, sub, iv, msg)
    character(len=*), intent(in) :: name_in            !! the input name as given [-]
    character(len=:), allocatable, intent(out) :: grp  !! run-deck group [-]
    character(len=:), allocatable, intent(out) :: var  !! variable [-]
    character(len=:), allocatable, intent(out) :: sub  !! subscript text without parentheses, '' if none [-]
    integer, intent(out) :: iv                         !! index of the variable in input_vars [-]
    character(len=:), allocatable, intent(out) :: msg  !! problem, '' if none [-]
    character(len=:), allocatable :: nm, why
    integer :: pp, pq, ig, i
    msg = ''
    iv = 0
    nm = ''
    do i = 1, len_trim(name_in)
      if (name_in(i:i) /= ' ') nm = nm//lower_case(name_in(i:i))
    end do
    pp = index(nm, '%')
    if (pp == 0) then
      msg = "valid: group%variable(index) as in the run decks, e.g. 'initial_state%velocity(1)' or 'terrain%slope(:)'"
      return
    end if
    grp = nm(1:pp - 1)
    ig = group_index(grp)
    if (ig == 0) then
      msg = "unknown run-deck group '"//grp//"'"//hint_and_list(close_name_hint(grp, group_names), &
            name_list(group_names))
      return
    end if
    pq = index(nm, '(')
    if (pq == 0) then
      var = nm(pp + 1:)
      sub = ''
    else
      var = nm(pp + 1:pq - 1)
      if (nm(len(nm):len(nm)) /= ')') then
        msg = "the subscript must end with ')'"
        return
      end if
      sub = nm(pq + 1:len(nm) - 1)
    end if
    iv = var_index(ig, var)
    if (iv == 0) then
      msg = "unknown variable '"//var//"' of &"//grp//hint_and_list(close_name_hint(var, group_vars(ig)), &
            name_list(group_vars(ig)))
      return
    end if
    why = fixed_reason(iv)
    if (len(why) > 0) msg = grp//'%'//var//' cannot be varied by a campaign: '//why
  end subroutine split_target

  !> The elements of an array variable that a subscript text selects (each subscript an index, a
  !! range lo:hi or ':'), as column-major element numbers in p%elems; msg /= '' when a subscript
  !! is invalid or their number is not the variable's rank.
  subroutine target_elements(var, sub, rank, ext, p, msg)
    character(len=*), intent(in) :: var                !! variable, for messages [-]
    character(len=*), intent(in) :: sub                !! subscript text without parentheses [-]
    integer, intent(in) :: rank                        !! the variable's rank (1 or 2) [-]
    integer, intent(in) :: ext(2)                      !! its extents (1 for a missing dimension) [-]
    type(param_t), intent(inout) :: p                  !! parameter: n_elem, elems set [-]
    character(len=:), allocatable, intent(out) :: msg  !! problem, '' if none [-]
    character(len=:), allocatable :: part, rest
    integer :: k, i, j, lo(2), hi(2), nsub
    logical :: last
    msg = ''
    rest = sub
    nsub = 0
    lo = 1
    hi = 1
    do
      call next_part(rest, part, last)
      nsub = nsub + 1
      if (nsub > rank) exit
      call parse_range(part, ext(nsub), lo(nsub), hi(nsub), msg)
      if (len(msg) > 0) then
        msg = 'subscript '//int_text(nsub)//" '"//part//"' of "//var//': '//msg
        return
      end if
      if (last) exit
    end do
    if (nsub /= rank) then
      msg = var//' has '//int_text(rank)//' subscript(s); got '//int_text(nsub)//" in '("//sub//")'"
      return
    end if
    p%n_elem = (hi(1) - lo(1) + 1)*(hi(2) - lo(2) + 1)
    allocate (p%elems(p%n_elem))
    k = 0
    do j = lo(2), hi(2)
      do i = lo(1), hi(1)
        k = k + 1
        p%elems(k) = i + (j - 1)*ext(1)
      end do
    end do
  end subroutine target_elements

  !> Every variable of the built-in default deck as 'group%variable' (once each).
  subroutine default_deck_variables(list)
    character(len=40), allocatable, intent(out) :: list(:)  !! variables [-]
    type(nml_group_t), allocatable :: groups(:)
    type(input_errors_t) :: errs
    character(len=40) :: nm
    integer :: ig, k
    allocate (list(0))
    call split_namelist(resolved_input_text(default_input()), 'default deck', groups, errs)
    do ig = 1, size(groups)
      do k = 1, groups(ig)%n_items
        nm = groups(ig)%name//'%'//groups(ig)%items(k)%base
        if (.not. any(list == nm)) list = [character(len=40) :: list, nm]
      end do
    end do
  end subroutine default_deck_variables

  !> One subscript: 'i', 'i:j', ':', 'i:' or ':j' within 1..ext.
  subroutine parse_range(part, ext, lo, hi, msg)
    character(len=*), intent(in) :: part               !! subscript text [-]
    integer, intent(in) :: ext                         !! extent of the dimension [-]
    integer, intent(out) :: lo, hi                     !! range [-]
    character(len=:), allocatable, intent(out) :: msg  !! problem, '' if none [-]
    integer :: pc, ios
    msg = ''
    lo = 1
    hi = ext
    pc = index(part, ':')
    ios = 0
    if (pc == 0) then
      read (part, *, iostat=ios) lo
      hi = lo
    else
      if (pc > 1) read (part(1:pc - 1), *, iostat=ios) lo
      if (ios == 0 .and. pc < len(part)) read (part(pc + 1:), *, iostat=ios) hi
    end if
    if (ios /= 0 .or. len(part) == 0 .or. verify(part, '0123456789:') /= 0) then
      msg = 'not an index or a range'
    else if (lo < 1 .or. hi > ext .or. lo > hi) then
      msg = 'out of range; valid: 1 .. '//int_text(ext)
    end if
  end subroutine parse_range

  !> Label suffix of a subscript: ':' -> 'all', 'i:j' -> 'i-j', ',' -> '_'.
  pure function label_sub(sub) result(s)
    character(len=*), intent(in) :: sub  !! subscript text [-]
    character(len=:), allocatable :: s   !! label suffix [-]
    character(len=:), allocatable :: part, rest
    logical :: last
    s = ''
    rest = sub
    do
      call next_part(rest, part, last)
      if (len(s) > 0) s = s//'_'
      if (part == ':') then
        s = s//'all'
      else
        s = s//replace_char(part, ':', '-')
      end if
      if (last) exit
    end do
  end function label_sub

  !> Split off the text before the first comma of `rest` (all of it when there is none).
  pure subroutine next_part(rest, part, last)
    character(len=:), allocatable, intent(inout) :: rest  !! text; what follows the comma on return [-]
    character(len=:), allocatable, intent(out) :: part    !! text before the comma [-]
    logical, intent(out) :: last                          !! there was no comma [-]
    integer :: pq
    pq = index(rest, ',')
    last = pq == 0
    if (last) then
      part = rest
    else
      part = rest(1:pq - 1)
      rest = rest(pq + 1:)
    end if
  end subroutine next_part

  !> Copy of t with every character a replaced by b (builds the label of a subscript range).
  pure function replace_char(t, a, b) result(s)
    character(len=*), intent(in) :: t     !! text [-]
    character(len=1), intent(in) :: a, b  !! replace a by b [-]
    character(len=len(t)) :: s            !! result [-]
    integer :: i
    s = t
    do i = 1, len(s)
      if (s(i:i) == a) s(i:i) = b
    end do
  end function replace_char

  !> The variable names of run-deck group ig, in registry order.
  pure function group_vars(ig) result(names)
    integer, intent(in) :: ig                     !! group index [-]
    character(len=24), allocatable :: names(:)    !! names [-]
    names = pack(input_vars%name, input_vars%group == ig)
  end function group_vars

  !> Why entry iv cannot be varied by a campaign ('' when it can).
  pure function fixed_reason(iv) result(why)
    integer, intent(in) :: iv                   !! registry entry [-]
    character(len=:), allocatable :: why        !! reason [-]
    why = trim(input_vars(iv)%fixed)
    if (len(why) > 0) return
    select case (input_vars(iv)%kind)
    case (k_string)
      why = 'it is text, not a number'
    case (k_logical)
      why = 'it is a logical, not a number'
    end select
  end function fixed_reason

  !> The table of run-deck variables a campaign can vary, from the registry (for the consistency test).
  subroutine run_variable_table(names, units, n1, n2, is_int)
    character(len=40), allocatable, intent(out) :: names(:)  !! 'group%variable' [-]
    character(len=10), allocatable, intent(out) :: units(:)  !! deck units ('-' if none) [-]
    integer, allocatable, intent(out) :: n1(:), n2(:)        !! extents (0: none) [-]
    logical, allocatable, intent(out) :: is_int(:)           !! integer variables [-]
    integer :: iv
    type(input_var_t) :: e
    allocate (names(0), units(0), n1(0), n2(0), is_int(0))
    do iv = 1, size(input_vars)
      if (len(fixed_reason(iv)) > 0) cycle
      e = input_vars(iv)
      names = [character(len=40) :: names, trim(group_names(e%group))//'%'//trim(e%name)]
      units = [character(len=10) :: units, merge(e%unit, '-         ', len_trim(e%unit) > 0)]
      n1 = [n1, e%n1]
      n2 = [n2, e%n2]
      is_int = [is_int, e%kind == k_int]
    end do
  end subroutine run_variable_table

end module landyn_campaign_target
