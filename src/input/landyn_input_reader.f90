!> The run-deck reader: splits a deck into groups and `name = value` items and reads each item
!! on its own through an internal-file namelist read into a scratch variable of the registry
!! entry's storage class and shape (so subscripts, array sections, repeat counts and null values
!! keep their Fortran namelist meaning), then stores it through landyn_input_access. Every
!! problem is collected, each with its line: unknown groups and variables (with suggestions),
!! repeated items, missing or unreadable values, non-ASCII bytes, over-long strings. Angles are
!! read in degrees and stored in radians; only the elements an item gives are converted.
!!
!! One reader for every kind of deck: read_deck takes a registry instance (landyn_deck_registry's
!! deck_registry_t: the groups and their entries) and a target (deck_target_t: where the values
!! go). parse_deck reads a run deck (the registry of landyn_input_registry into landyn_input_t);
!! landyn_study_deck and landyn_campaign_table read study and campaign decks with their own tables.
!! A group marked repeatable may be given more than once; its messages then name it with its number
!! ('&variant 2: ...') unless the registry is not `numbered` (campaign decks: '&parameter: ...'). The
!! registry also sets the limits of numbers (`max_exponent` before reading, `max_magnitude` after).
!!
!! Library code: nothing here stops or prints.
module landyn_input_reader
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use, intrinsic :: iso_fortran_env, only: int64
  use landyn_kinds, only: wp
  use landyn_errors, only: input_errors_t
  use landyn_config, only: landyn_input_t, unset_real, is_set, path_len
  use landyn_strings, only: lower => lower_case, is_blank => is_blank_char, fmt_int => int_text, &
                            quoted => quote_text
  use landyn_namelist_text, only: strip_comments, next_group, find_item_names, line_of, first_nonblank, &
                                  one_line => one_line_text, strip_commas => separators_to_blanks, &
                                  remove_blanks, mask_non_ascii, bare_name_in_value, numbers_within, leading_text, &
                                  without_trailing_separators, shortened
  use landyn_input_registry, only: input_var_t, k_int, k_logical, k_string, k_int64
  use landyn_input_access, only: input_value_t, access_var
  use landyn_deck_registry, only: deck_registry_t, deck_target_t, run_deck_registry
  use landyn_input_format, only: deg_to_rad
  implicit none
  private

  public :: parse_deck, read_deck

  !> The target of a run deck: its values go into a landyn_input_t.
  type, extends(deck_target_t) :: run_target_t
    type(landyn_input_t) :: inp   !! the input read [-]
  contains
    procedure :: access => run_access  !! entry <-> component of inp (landyn_input_access)
  end type run_target_t

  integer, parameter :: ios_implausible = -12345    !! our own iostat: non-finite or absurdly large value
  integer, parameter :: snippet_len = 100           !! longest deck excerpt quoted in a message [-]
  integer, parameter :: key_len = 128               !! longest variable reference compared for duplicates [-]

contains

  ! ================================================================ deck parsing

  !> Read a run deck into `inp`: read_deck with the run-deck registry.
  subroutine parse_deck(text, deck_name, inp, errors)
    character(len=*), intent(in) :: text           !! deck text [-]
    character(len=*), intent(in) :: deck_name      !! name for messages [-]
    type(landyn_input_t), intent(inout) :: inp     !! input updated item by item
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    type(run_target_t) :: target
    target%inp = inp
    call read_deck(run_deck_registry(), text, deck_name, target, errors)
    inp = target%inp
  end subroutine parse_deck

  !> run_target_t's access: registry entry iv <-> its component of the landyn_input_t.
  subroutine run_access(this, iv, v, store)
    class(run_target_t), intent(inout) :: this   !! the run deck's values [-]
    integer, intent(in) :: iv                    !! registry entry [-]
    type(input_value_t), intent(inout) :: v      !! value holder [storage unit]
    logical, intent(in) :: store                 !! direction: true stores v into inp [-]
    call access_var(this%inp, iv, v, store)
  end subroutine run_access

  !> Split the deck into the groups of registry `reg` and read each group's items into `target`;
  !! see the module documentation.
  subroutine read_deck(reg, text, deck_name, target, errors)
    type(deck_registry_t), intent(in) :: reg       !! the deck's registry [-]
    character(len=*), intent(in) :: text           !! deck text [-]
    character(len=*), intent(in) :: deck_name      !! name for messages [-]
    class(deck_target_t), intent(inout) :: target  !! values updated item by item [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    character(len=:), allocatable :: work, gname, glabel
    integer :: seen(size(reg%groups)), times(size(reg%groups))
    integer, allocatable :: bad(:)
    integer :: p, q, e, ig, qpos, next_p, line, k, s0, s1, g
    logical :: terminated

    allocate (character(len=len(text)) :: work)
    call strip_comments(text, work, qpos)
    if (qpos > 0) then
      call errors%add(loc(deck_name, work, qpos)//'unterminated character string (no closing quote): '// &
                      snippet(work(qpos:)))
      work(qpos:) = repeat(' ', len(work) - qpos + 1)
    end if
    call mask_non_ascii(work, bad)
    do k = 1, size(bad)
      call errors%add(loc(deck_name, work, bad(k))//'byte '//hex_byte(text(bad(k):bad(k)))// &
                      ' is not ASCII text; decks are ASCII text (UTF-8 only inside quoted strings and ! comments)')
    end do
    seen = 0
    times = 0
    p = 1
    do
      call next_group(work, p, s0, s1, g, q, e, terminated, next_p)
      ! text outside any group: the run up to the next '&', reported once
      if (s0 > 0) call errors%add(loc(deck_name, work, s0)//'text outside any namelist group: '''// &
                                  snippet(work(s0:s1))//''' (groups start with &name and end with /)')
      if (g == 0) exit
      p = g
      line = line_of(work, p)
      gname = lower(work(p + 1:q - 1))
      if (len(gname) == 0) then
        call errors%add(loc(deck_name, work, p)//"'&' without a group name: "//snippet(work(p:e - 1)))
        p = next_p
        cycle
      end if
      ig = reg%group_index(gname)
      if (ig == 0) then
        call errors%add(loc(deck_name, work, p)//"unknown namelist group '&"//gname//"'"// &
                        reg%group_hint(gname)//'; valid groups: '//reg%group_list())
      else if (seen(ig) > 0 .and. .not. reg%repeatable(ig)) then
        call errors%add(loc(deck_name, work, p)//'&'//gname//': group given a second time (first at line '// &
                        fmt_int(seen(ig))//'); give each group once')
      else
        seen(ig) = line
        times(ig) = times(ig) + 1
        glabel = gname
        if (reg%repeatable(ig) .and. reg%numbered) glabel = gname//' '//fmt_int(times(ig))
        if (.not. terminated) call errors%add(loc(deck_name, work, p)//'&'//glabel// &
                                              ": group is not terminated by '/'")
        target%line = line
        call target%begin_group(ig, times(ig))
        call read_group(reg, ig, glabel, work, q, e - 1, deck_name, target, errors)
      end if
      p = next_p
    end do
  end subroutine read_deck

  !> Split one group body into `name = value` items and read each on its own.
  subroutine read_group(reg, ig, gname, work, b0, b1, deck_name, target, errors)
    type(deck_registry_t), intent(in) :: reg       !! the deck's registry [-]
    integer, intent(in) :: ig                      !! group index [-]
    character(len=*), intent(in) :: gname          !! the group in messages: its name (and number if repeatable) [-]
    character(len=*), intent(in) :: work           !! comment-free deck text [-]
    integer, intent(in) :: b0, b1                  !! body is work(b0:b1) [-]
    character(len=*), intent(in) :: deck_name      !! name for messages [-]
    class(deck_target_t), intent(inout) :: target  !! values updated item by item [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    integer, allocatable :: starts(:), eqs(:)
    character(len=:), allocatable :: item, lhs, base, value, what
    character(len=key_len), allocatable :: keys(:)
    character(len=512) :: msg
    integer :: p, k, nitems, item_end, ios, iv, nkeys
    logical :: ok

    ! Find every '=' outside quotes and the start of the name before it.
    call find_item_names(work, b0, b1, .false., starts, eqs)
    nitems = size(starts)
    call leading_text(work, b0, b1, starts, what, item_end)
    if (len(what) > 0) call errors%add(loc(deck_name, work, first_nonblank(work, b0))//'&'//gname//': '//what// &
                                       snippet(work(b0:item_end)))

    allocate (keys(nitems))
    nkeys = 0
    do k = 1, nitems
      item_end = b1
      if (k < nitems) item_end = starts(k + 1) - 1
      item = one_line(work(starts(k):item_end))
      if (starts(k) == eqs(k)) then
        call errors%add(loc(deck_name, work, eqs(k))//'&'//gname//": '=' without a variable name: "// &
                        snippet(item))
        cycle
      end if
      lhs = lower(remove_blanks(work(starts(k):eqs(k) - 1)))
      base = lhs
      p = scan(lhs, '(%')
      if (p > 0) base = lhs(1:p - 1)
      value = work(eqs(k) + 1:item_end)
      iv = reg%var_index(ig, base)
      if (iv == 0) then
        call errors%add(loc(deck_name, work, starts(k))//'&'//gname//": unknown variable '"// &
                        trim(adjustl(work(starts(k):eqs(k) - 1)))//"' ("//snippet(item)//')'//reg%var_hint(ig, base))
        cycle
      end if
      if (any(keys(1:nkeys) == lhs)) then
        call errors%add(loc(deck_name, work, starts(k))//'&'//gname//': '//lhs// &
                        ' is given more than once ('//snippet(item)//'); give it once')
        cycle
      end if
      nkeys = nkeys + 1
      keys(nkeys) = lhs   ! (a name longer than key_len is compared by its start)
      if (len_trim(strip_commas(value)) == 0) then
        call errors%add(loc(deck_name, work, starts(k))//'&'//gname//': no value given for '//lhs// &
                        ' ('//trim(base)//' takes '//trim(reg%vars(iv)%takes)//reg%unit_text(iv)//')')
        cycle
      end if
      if (len(bare_name_in_value(value)) > 0) then
        call errors%add(loc(deck_name, work, starts(k))//'&'//gname//": '"//bare_name_in_value(value)// &
                        "' after "//lhs//' = ... is a name without a value ('//snippet(item)// &
                        "); give it as 'name = value' or remove it")
        cycle
      end if
      if (longest_string(value) > string_limit(reg%vars(iv), iv, target)) then
        call errors%add(loc(deck_name, work, starts(k))//'&'//gname//': '//lhs//' is too long ('// &
                        fmt_int(longest_string(value))//' characters); valid: at most '// &
                        fmt_int(string_limit(reg%vars(iv), iv, target))//' characters')
        cycle
      end if
      ok = numbers_within(value, reg%max_exponent)
      if (.not. ok) then
        call errors%add(loc(deck_name, work, starts(k))//'&'//gname//': '//lhs//' = '// &
                        snippet(value)//' is out of range; valid: '//trim(reg%limit_text))
        cycle
      end if
      msg = ''
      call read_item(reg%vars(iv), iv, item, len(base), reg%max_magnitude, target, ios, msg)
      if (ios == ios_implausible) then
        call errors%add(loc(deck_name, work, starts(k))//'&'//gname//': '//lhs//' = '// &
                        snippet(value)//' is invalid; valid: finite numbers with '//trim(reg%limit_text))
      else if (ios /= 0) then
        call errors%add(loc(deck_name, work, starts(k))//'&'//gname//': cannot read '//lhs//' = '// &
                        quoted(snippet_raw(value))//' ('//trim(base)//' takes '//trim(reg%vars(iv)%takes)// &
                        reg%unit_text(iv)//'): '//trim(msg))
      end if
    end do
  end subroutine read_group

  !> Length of the longest quoted string in a value text (0 if none); doubled quotes count once.
  pure function longest_string(value) result(n)
    character(len=*), intent(in) :: value  !! value text [-]
    integer :: n                           !! longest quoted string [characters]
    character(len=1) :: quote
    integer :: p, cur
    n = 0
    cur = 0
    quote = ' '
    p = 1
    do while (p <= len(value))
      if (quote /= ' ') then
        if (value(p:p) == quote) then
          if (p < len(value)) then
            if (value(p + 1:p + 1) == quote) then
              cur = cur + 1
              p = p + 2
              cycle
            end if
          end if
          quote = ' '
          n = max(n, cur)
        else
          cur = cur + 1
        end if
      else if (value(p:p) == '"' .or. value(p:p) == "'") then
        quote = value(p:p)
        cur = 0
      end if
      p = p + 1
    end do
    if (quote /= ' ') n = max(n, cur)
  end function longest_string

  !> Longest character value entry iv (registry entry e) holds (huge for non-character variables).
  function string_limit(e, iv, target) result(n)
    type(input_var_t), intent(in) :: e             !! registry entry [-]
    integer, intent(in) :: iv                      !! its index [-]
    class(deck_target_t), intent(inout) :: target  !! values (for the component's length; unchanged) [-]
    integer :: n                                   !! limit [characters]
    type(input_value_t) :: v
    n = huge(1)
    if (e%kind /= k_string) return
    call target%access(iv, v, .false.)
    if (e%n1 > 0) then
      n = v%sa_len
    else
      n = len(v%s)
    end if
  end function string_limit

  !> A byte as "0xHH".
  pure function hex_byte(c) result(h)
    character(len=1), intent(in) :: c   !! byte [-]
    character(len=4) :: h               !! its hexadecimal text [-]
    character(len=16), parameter :: digits = '0123456789ABCDEF'
    integer :: b
    b = iachar(c)
    if (b < 0) b = b + 256
    h = '0x'//digits(b/16 + 1:b/16 + 1)//digits(mod(b, 16) + 1:mod(b, 16) + 1)
  end function hex_byte

  !> Read one item into entry iv of `target`: `item` starts with the variable name (nbase characters),
  !! the rest is the subscript and `= value`. The name is replaced by a scratch variable of the
  !! entry's class and shape, read as a one-item namelist record; iomsg names the variable again.
  subroutine read_item(e, iv, item, nbase, max_magnitude, target, ios, msg)
    type(input_var_t), intent(in) :: e             !! registry entry [-]
    integer, intent(in) :: iv                      !! its index [-]
    character(len=*), intent(in) :: item           !! 'name(sub) = value' as given [-]
    integer, intent(in) :: nbase                   !! length of the name at the start of item [-]
    real(wp), intent(in) :: max_magnitude          !! largest |value| of a real [any unit]
    class(deck_target_t), intent(inout) :: target  !! updated only when the read succeeds [-]
    integer, intent(out) :: ios                    !! 0, a Fortran iostat, or ios_implausible [-]
    character(len=*), intent(inout) :: msg         !! iomsg of a failed read [-]
    type(input_value_t) :: v
    real(wp) :: lv_real
    real(wp), allocatable :: lv_reals(:), lv_matrix(:, :)
    integer :: lv_int
    integer(int64) :: lv_int64
    integer, allocatable :: lv_ints(:)
    logical :: lv_logical
    character(len=path_len) :: lv_string
    character(len=path_len), allocatable :: lv_strings(:)
    character(len=:), allocatable :: rest, scratch, buffer, cls
    namelist /nl_real/ lv_real
    namelist /nl_reals/ lv_reals
    namelist /nl_matrix/ lv_matrix
    namelist /nl_int/ lv_int
    namelist /nl_int64/ lv_int64
    namelist /nl_ints/ lv_ints
    namelist /nl_logical/ lv_logical
    namelist /nl_string/ lv_string
    namelist /nl_strings/ lv_strings
    rest = item(nbase + 1:)//' /'
    call target%access(iv, v, .false.)
    cls = scratch_class(e)
    scratch = 'lv_'//cls
    buffer = '&nl_'//cls//' '//scratch//rest
    select case (cls)
    case ('int')
      lv_int = v%i
      read (buffer, nml=nl_int, iostat=ios, iomsg=msg)
      v%i = lv_int
    case ('ints')
      allocate (lv_ints(size(v%ia)))   ! (allocated explicitly: gfortran -O0 warns on the implicit allocation)
      lv_ints = v%ia
      read (buffer, nml=nl_ints, iostat=ios, iomsg=msg)
      v%ia = lv_ints
    case ('logical')
      lv_logical = v%l
      read (buffer, nml=nl_logical, iostat=ios, iomsg=msg)
      v%l = lv_logical
    case ('string')
      lv_string = v%s
      read (buffer, nml=nl_string, iostat=ios, iomsg=msg)
      v%s = lv_string
    case ('strings')
      allocate (lv_strings(size(v%sa)))
      lv_strings = v%sa
      read (buffer, nml=nl_strings, iostat=ios, iomsg=msg)
      v%sa = lv_strings
    case ('int64')   ! (the campaign's seed)
      lv_int64 = v%i8
      read (buffer, nml=nl_int64, iostat=ios, iomsg=msg)
      v%i8 = lv_int64
    case default
      call read_reals()
    end select
    if (ios /= 0) then
      msg = renamed(msg, scratch, trim(e%name))
      return
    end if
    call target%access(iv, v, .true.)
  contains
    !> Read a real entry; angles start unset so only the given elements are converted.
    subroutine read_reals()
      real(wp), allocatable :: x(:)
      allocate (x, source=v%r)
      if (e%angle) x = unset_real
      if (e%n2 > 0) then
        lv_matrix = reshape(x, [e%n1, e%n2])
        read (buffer, nml=nl_matrix, iostat=ios, iomsg=msg)
        x = reshape(lv_matrix, [size(x)])
      else if (e%n1 > 0) then
        lv_reals = x
        read (buffer, nml=nl_reals, iostat=ios, iomsg=msg)
        x = lv_reals
      else
        lv_real = x(1)
        read (buffer, nml=nl_real, iostat=ios, iomsg=msg)
        x = [lv_real]
      end if
      if (ios /= 0) return
      if (.not. plausible(x, max_magnitude)) then
        ios = ios_implausible
        return
      end if
      if (e%angle) then
        where (is_set(x)) v%r = deg_to_rad(x)
      else
        v%r = x
      end if
    end subroutine read_reals
  end subroutine read_item

  !> The scratch variable of entry e, without its 'lv_' prefix: its namelist group is 'nl_' and the
  !! same word (one group per class and shape, so an item can name no other scratch variable).
  pure function scratch_class(e) result(s)
    type(input_var_t), intent(in) :: e   !! registry entry [-]
    character(len=:), allocatable :: s   !! 'int', 'ints', 'int64', 'logical', 'string', 'strings', 'matrix', 'reals', 'real' [-]
    select case (e%kind)
    case (k_int)
      s = 'int'
      if (e%n1 > 0) s = 'ints'
    case (k_int64)
      s = 'int64'
    case (k_logical)
      s = 'logical'
    case (k_string)
      s = 'string'
      if (e%n1 > 0) s = 'strings'
    case default
      s = 'real'
      if (e%n1 > 0) s = 'reals'
      if (e%n2 > 0) s = 'matrix'
    end select
  end function scratch_class

  !> msg with every occurrence of the scratch name replaced by the variable name.
  pure function renamed(msg, scratch, name) result(s)
    character(len=*), intent(in) :: msg      !! iomsg [-]
    character(len=*), intent(in) :: scratch  !! scratch variable name [-]
    character(len=*), intent(in) :: name     !! deck variable name [-]
    character(len=len(msg)) :: s             !! message [-]
    character(len=:), allocatable :: t
    integer :: p
    t = trim(msg)
    do
      p = index(t, scratch)
      if (p == 0) exit
      t = t(1:p - 1)//name//t(p + len(scratch):)
    end do
    s = t
  end function renamed

  !> True when every set value is finite with |x| <= max_magnitude (unset markers are skipped).
  pure function plausible(x, max_magnitude) result(ok)
    real(wp), intent(in) :: x(:)            !! values [any unit]
    real(wp), intent(in) :: max_magnitude   !! largest |value| accepted [any unit]
    logical :: ok                           !! all plausible [-]
    integer :: i
    ok = .true.
    do i = 1, size(x)
      if (.not. ieee_is_finite(x(i))) then
        ok = .false.
      else if (is_set(x(i))) then
        if (abs(x(i)) > max_magnitude) ok = .false.
      end if
    end do
  end function plausible

  ! ================================================================ text helpers

  !> "deck:line: " (or "line N: " without a deck name) for position p.
  pure function loc(deck_name, work, p) result(s)
    character(len=*), intent(in) :: deck_name  !! deck name [-]
    character(len=*), intent(in) :: work       !! deck text [-]
    integer, intent(in) :: p                   !! position [-]
    character(len=:), allocatable :: s         !! location prefix [-]
    if (len_trim(deck_name) > 0) then
      s = trim(deck_name)//':'//fmt_int(line_of(work, p))//': '
    else
      s = 'line '//fmt_int(line_of(work, p))//': '
    end if
  end function loc

  !> Compact excerpt of deck text for messages: blanks collapsed, trailing commas dropped, shortened.
  pure function snippet(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=:), allocatable :: s  !! excerpt [-]
    s = shortened(snippet_raw(t), snippet_len)
  end function snippet

  !> The text of a deck fragment on one line: blanks collapsed, trailing commas dropped.
  pure function snippet_raw(t) result(s)
    character(len=*), intent(in) :: t   !! text [-]
    character(len=:), allocatable :: s  !! text with blanks collapsed and trailing commas dropped [-]
    character(len=len(t)) :: buf
    integer :: i, n
    logical :: prev_blank
    ! one pass into a buffer of the text's length: linear in len(t) (a line of a million commas
    ! took minutes when the result grew character by character)
    n = 0
    prev_blank = .true.
    do i = 1, len(t)
      if (is_blank(t(i:i))) then
        if (.not. prev_blank) then
          n = n + 1
          buf(n:n) = ' '
        end if
        prev_blank = .true.
      else
        n = n + 1
        buf(n:n) = t(i:i)
        prev_blank = .false.
      end if
    end do
    s = shortened(without_trailing_separators(buf(1:n)), 4*snippet_len)
  end function snippet_raw

end module landyn_input_reader
