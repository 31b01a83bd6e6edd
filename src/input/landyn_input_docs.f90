!> The variable tables of docs/input/<group>.md, generated from the input registry: one row per
!! variable with its type and shape, deck unit, default (from landyn_config's defaults through
!! the registry accessor), valid range and meaning. In the pages the table stands between the
!! marker comments `table_begin` and `table_end`; the prose around it is hand-written. The
!! generator program and the currency test are in tests/input.
!!
!! Library code; pure but for the two that list a choice variable's names, which ask its registry.
module landyn_input_docs
  use landyn_config, only: landyn_input_t, default_input
  use landyn_input_choices, only: choice_list
  use landyn_strings, only: fmt_int => int_text
  use landyn_input_registry, only: input_var_t, input_vars, range_text, k_int, k_logical, k_string
  use landyn_input_access, only: input_value_t, access_var
  use landyn_input_writer, only: entry_text
  implicit none
  private

  public :: docs_table, replace_table

  character(len=*), parameter :: table_begin = '<!-- begin: variable table generated from src/input/'// &
    'landyn_input_registry.f90 by landyn_input_docs (tests/input); do not edit -->'  !! opening marker [-]
  character(len=*), parameter :: table_end = '<!-- end: variable table -->'          !! closing marker [-]

contains

  !> The markdown table of group ig (with a trailing line end, without the markers).
  function docs_table(ig) result(md)
    integer, intent(in) :: ig              !! group index [-]
    character(len=:), allocatable :: md    !! table [-]
    type(landyn_input_t) :: inp
    type(input_value_t) :: v
    type(input_var_t) :: e
    integer :: iv
    character(len=:), allocatable :: kind, default, valid, unit
    character(len=1) :: lf
    lf = new_line('a')
    inp = default_input()
    md = '| Variable | Type | Units | Default | Valid range | Meaning |'//lf//'|---|---|---|---|---|---|'//lf
    do iv = 1, size(input_vars)
      e = input_vars(iv)
      if (e%group /= ig) cycle
      call access_var(inp, iv, v, .false.)
      select case (e%kind)
      case (k_string)
        kind = 'character('//fmt_int(len(v%s))//'), quoted'
      case (k_int)
        kind = 'integer'
      case (k_logical)
        kind = 'logical'
      case default
        kind = 'real'
        if (e%n2 > 0) then
          kind = 'real('//fmt_int(e%n1)//', '//fmt_int(e%n2)//')'
        else if (e%n1 > 0) then
          kind = 'real('//fmt_int(e%n1)//')'
        end if
      end select
      unit = trim(e%unit)
      if (len(unit) == 0) unit = '-'
      if (e%angle) unit = '**'//unit//'**'   ! angles: degrees in decks, radians inside
      default = trim(e%doc_default)
      if (len(default) == 0) default = '`'//entry_text(iv, v)//'`'
      valid = trim(e%doc_valid)
      if (len(valid) == 0) then
        if (len_trim(e%choices) > 0) then
          valid = quoted_list(choice_list(e%choices))   ! the names of the choice's registry
        else if (len_trim(e%hi_op) > 0) then
          valid = '`'//range_text(iv, .false.)//'`'
        else if (len_trim(e%lo_op) > 0) then
          valid = '`'//trim(e%lo_op)//' '//trim(e%lo)//'`'
        else
          valid = 'any'
        end if
      end if
      md = md//'| `'//trim(e%name)//'` | '//kind//' | '//unit//' | '//default//' | '//valid//' | '// &
           either(e%doc, e%meaning)//' |'//lf
    end do
  contains
    !> 'a, b, c' as '`'a'`, `'b'`, `'c'`'.
    pure function quoted_list(names) result(t)
      character(len=*), intent(in) :: names  !! comma-separated names [-]
      character(len=:), allocatable :: t     !! the names quoted for Markdown [-]
      integer :: a, b
      t = ''
      a = 1
      do while (a <= len(names))
        b = index(names(a:), ',')
        if (b == 0) then
          b = len(names) + 1
        else
          b = a + b - 1
        end if
        if (len(t) > 0) t = t//', '
        t = t//"`'"//trim(adjustl(names(a:b - 1)))//"'`"
        a = b + 1
      end do
    end function quoted_list

    !> a trimmed, or b trimmed when a is blank.
    pure function either(a, b) result(t)
      character(len=*), intent(in) :: a, b   !! texts [-]
      character(len=:), allocatable :: t     !! text [-]
      if (len_trim(a) > 0) then
        t = trim(a)
      else
        t = trim(b)
      end if
    end function either
  end function docs_table

  !> The page text with the table of group ig between the markers (inserted in place of the first
  !! table whose header starts with '| Variable |' when the page has no markers yet). ok is false
  !! when the page has neither.
  subroutine replace_table(page, ig, new_page, ok)
    character(len=*), intent(in) :: page                  !! page text [-]
    integer, intent(in) :: ig                             !! group index [-]
    character(len=:), allocatable, intent(out) :: new_page  !! page with the current table [-]
    logical, intent(out) :: ok                            !! the table's place was found [-]
    integer :: a, b, p
    character(len=1) :: lf
    lf = new_line('a')
    ok = .false.
    new_page = page
    a = index(page, table_begin)
    if (a > 0) then
      b = index(page, table_end)
      if (b < a) return
      b = b + len(table_end)
    else
      a = index(page, '| Variable |')
      if (a == 0) return
      ! the table ends at the first line that does not start with '|'
      b = a
      do
        p = index(page(b:), lf)
        if (p == 0) then
          b = len(page) + 1
          exit
        end if
        b = b + p
        if (b > len(page)) exit
        if (page(b:b) /= '|') exit
      end do
      b = b - 1   ! keep the line end before the next line
    end if
    new_page = page(1:a - 1)//table_begin//lf//docs_table(ig)//table_end//page(b:)
    ok = .true.
  end subroutine replace_table

end module landyn_input_docs
