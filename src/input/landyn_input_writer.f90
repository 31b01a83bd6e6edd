!> The resolved-deck writer: every group and variable of the registry written as a complete,
!! valid namelist deck (angles in degrees, units and meanings in `!` comments). Used by
!! `landyn --check`, stored as /input/resolved in every result file, and the base of every
!! campaign case deck. Reading the text back and resolving gives the same input, bit for bit.
!!
!! Library code: nothing here stops; output goes only to the unit the caller passes.
module landyn_input_writer
  use landyn_kinds, only: wp
  use landyn_config, only: landyn_input_t, is_set
  use landyn_strings, only: fmt_int => int_text, quoted => quote_text
  use landyn_namelist_text, only: one_line => one_line_text
  use landyn_input_registry, only: input_vars, n_groups, group_names, var_index, unit_text, k_int, k_logical, &
                                   k_string
  use landyn_input_access, only: input_value_t, access_var
  use landyn_input_format, only: fmt_real, fmt_angle, fmt_reals, fmt_angles, fmt_logical
  implicit none
  private

  public :: write_resolved_input, resolved_input_text, entry_text

  integer, parameter :: comment_col = 46            !! column of the `!` comments in written decks [-]

contains

  !> Write the input as a complete, valid namelist deck (every group and variable, angles in
  !! degrees, units in `!` comments) to a formatted unit. Reading it back and resolving gives
  !! the same input, bit for bit.
  subroutine write_resolved_input(unit, inp)
    integer, intent(in) :: unit               !! formatted output unit [-]
    type(landyn_input_t), intent(in) :: inp   !! input to write (normally resolved)
    character(len=:), allocatable :: text
    integer :: i0, i1
    text = resolved_input_text(inp)
    i0 = 1
    do while (i0 <= len(text))
      i1 = index(text(i0:), new_line('a'))
      if (i1 == 0) then
        write (unit, '(a)') text(i0:)
        exit
      end if
      write (unit, '(a)') text(i0:i0 + i1 - 2)
      i0 = i0 + i1
    end do
  end subroutine write_resolved_input

  !> The deck that write_resolved_input writes, as one string with new_line('a') line ends:
  !! the groups in registry order, each variable as `name = value ! meaning [unit]`. Entries
  !! marked partial write only their given elements; the 2-D entries of a group (columns are
  !! gears) are written column by column after the group's other variables.
  pure function resolved_input_text(inp) result(text)
    type(landyn_input_t), intent(in) :: inp   !! input to write (normally resolved)
    character(len=:), allocatable :: text     !! the deck [-]
    type(landyn_input_t) :: work
    type(input_value_t) :: v
    character(len=:), allocatable :: deck
    integer :: ig, iv
    logical :: columns_done

    deck = ''
    if (allocated(inp%deck_name)) deck = inp%deck_name
    text = ''
    call put(text, '! LANDYN resolved input: every variable of every group, defaults filled in.')
    if (len(deck) > 0) call put(text, '! Read from deck: '//one_line(deck))
    call put(text, '! Units: SI (m, kg, N, s); angles in degrees (converted to radians on input).')
    call put(text, '! Frames: global and lander z axes point down; gravity acts along global +z.')
    work = inp
    do ig = 1, n_groups
      call put(text, '')
      call put(text, '&'//trim(group_names(ig)))
      columns_done = .false.
      do iv = 1, size(input_vars)
        if (input_vars(iv)%group /= ig) cycle
        if (input_vars(iv)%n2 > 0) then
          if (.not. columns_done) call put_columns(text, work, ig)
          columns_done = .true.
          cycle
        end if
        call access_var(work, iv, v, .false.)
        if (input_vars(iv)%partial) then
          call put_partial(text, ig, trim(input_vars(iv)%name), v%r, 0, input_vars(iv)%angle)
        else
          call put_var(text, ig, trim(input_vars(iv)%name), entry_text(iv, v))
        end if
      end do
      call put(text, '/')
    end do
  end function resolved_input_text

  !> The deck text of the whole value of entry iv (angles in degrees).
  pure function entry_text(iv, v) result(s)
    integer, intent(in) :: iv                !! registry entry [-]
    type(input_value_t), intent(in) :: v     !! its value [storage unit]
    character(len=:), allocatable :: s       !! deck text [-]
    select case (input_vars(iv)%kind)
    case (k_string)
      s = quoted(trim(v%s))
    case (k_int)
      s = fmt_int(v%i)
    case (k_logical)
      s = fmt_logical(v%l)
    case default
      if (input_vars(iv)%angle) then
        if (input_vars(iv)%n1 > 0) then
          s = fmt_angles(v%r)
        else
          s = fmt_angle(v%r(1))
        end if
      else if (input_vars(iv)%n1 > 0) then
        s = fmt_reals(v%r)
      else
        s = fmt_real(v%r(1))
      end if
    end select
  end function entry_text

  !> The 2-D entries of group ig, column by column ("! gear i" before a column with given points).
  pure subroutine put_columns(text, work, ig)
    character(len=:), allocatable, intent(inout) :: text  !! deck being built [-]
    type(landyn_input_t), intent(inout) :: work           !! input (read only) [-]
    integer, intent(in) :: ig                             !! group index [-]
    type(input_value_t) :: v
    integer :: iv, i, n1, ncol
    logical :: any_set
    ncol = 0
    do iv = 1, size(input_vars)
      if (input_vars(iv)%group == ig .and. input_vars(iv)%n2 > 0) ncol = max(ncol, input_vars(iv)%n2)
    end do
    do i = 1, ncol
      any_set = .false.
      do iv = 1, size(input_vars)
        if (input_vars(iv)%group /= ig .or. input_vars(iv)%n2 < i) cycle
        call access_var(work, iv, v, .false.)
        n1 = input_vars(iv)%n1
        if (any(is_set(v%r((i - 1)*n1 + 1:i*n1)))) any_set = .true.
      end do
      if (any_set) call put(text, '  ! gear '//fmt_int(i))
      do iv = 1, size(input_vars)
        if (input_vars(iv)%group /= ig .or. input_vars(iv)%n2 < i) cycle
        call access_var(work, iv, v, .false.)
        n1 = input_vars(iv)%n1
        call put_partial(text, ig, trim(input_vars(iv)%name), v%r((i - 1)*n1 + 1:i*n1), i, input_vars(iv)%angle)
      end do
    end do
  end subroutine put_columns

  !> Append a line to text.
  pure subroutine put(text, line)
    character(len=:), allocatable, intent(inout) :: text  !! deck being built [-]
    character(len=*), intent(in) :: line                  !! line without line end [-]
    text = text//line//new_line('a')
  end subroutine put

  !> Append "  name = value   ! meaning [unit]".
  pure subroutine put_var(text, ig, name, value)
    character(len=:), allocatable, intent(inout) :: text  !! deck being built [-]
    integer, intent(in) :: ig                             !! group index [-]
    character(len=*), intent(in) :: name                  !! variable (with subscript) [-]
    character(len=*), intent(in) :: value                 !! value text [-]
    character(len=:), allocatable :: line, base
    integer :: iv, p
    base = name
    p = index(name, '(')
    if (p > 0) base = name(1:p - 1)
    iv = var_index(ig, base)
    line = '  '//name//' = '//value
    if (iv > 0) then
      if (len(line) < comment_col - 1) line = line//repeat(' ', comment_col - 1 - len(line))
      line = line//' ! '//trim(input_vars(iv)%meaning)
      line = line//unit_text(iv)
    end if
    call put(text, line)
  end subroutine put_var

  !> Append a vector that may be given only in part (unset elements are not written): the whole
  !! vector when all is set, name(1:k) for a leading run, element by element otherwise. col > 0
  !! writes column col of a 2-D array (name(:, col), name(j, col)).
  pure subroutine put_partial(text, ig, name, x, col, angle)
    character(len=:), allocatable, intent(inout) :: text  !! deck being built [-]
    integer, intent(in) :: ig                             !! group index [-]
    character(len=*), intent(in) :: name                  !! variable name [-]
    real(wp), intent(in) :: x(:)                          !! values [m or rad]
    integer, intent(in) :: col                            !! column of a 2-D array, 0 for a vector [-]
    logical, intent(in) :: angle                          !! x is an angle (written in degrees) [-]
    integer :: j, k
    character(len=:), allocatable :: c
    c = ''
    if (col > 0) c = ', '//fmt_int(col)
    if (all(is_set(x))) then
      if (col > 0) then
        call put_var(text, ig, name//'(:'//c//')', vals(x))
      else
        call put_var(text, ig, name, vals(x))
      end if
      return
    end if
    if (.not. any(is_set(x))) then
      if (col == 0 .and. name == 'position') &
        call put(text, '  ! position not given: the lowest footpad starts clearance above its surface')
      return
    end if
    k = 0
    do while (k < size(x))
      if (.not. is_set(x(k + 1))) exit
      k = k + 1
    end do
    if (k > 0 .and. .not. any(is_set(x(k + 1:)))) then
      call put_var(text, ig, name//'(1:'//fmt_int(k)//c//')', vals(x(1:k)))
      return
    end if
    do j = 1, size(x)
      if (is_set(x(j))) call put_var(text, ig, name//'('//fmt_int(j)//c//')', vals(x(j:j)))
    end do
  contains
    !> Deck text of values, in degrees when the variable is an angle.
    pure function vals(y) result(s)
      real(wp), intent(in) :: y(:)           !! values [m or rad]
      character(len=:), allocatable :: s     !! deck text [-]
      if (angle) then
        s = fmt_angles(y)
      else
        s = fmt_reals(y)
      end if
    end function vals
  end subroutine put_partial

end module landyn_input_writer
