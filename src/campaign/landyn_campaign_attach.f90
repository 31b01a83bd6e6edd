!> Attaching the files a campaign deck names and finishing the campaign: the base run deck
!! (read, resolved, validated, split for merging, and checked to reproduce itself with no
!! overrides), the case list of list mode, and the cross-parameter checks, case count and
!! fingerprint.
!!
!! Library code: nothing here stops or prints.
module landyn_campaign_attach
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use landyn_kinds, only: wp
  use landyn_config, only: landyn_input_t
  use landyn_input, only: input_errors_t, read_input_text, resolve_input, validate_input, resolved_input_text
  use landyn_namelist_text, only: has_nonfinite_word, numbers_within
  use landyn_namelist_items, only: split_namelist
  use landyn_campaign_text, only: int_text, real_text_short, quote_text, ints_text
  use landyn_campaign_types, only: campaign_t, raw_campaign_t, max_cases, cell_len
  use landyn_campaign_target, only: parse_target
  use landyn_campaign_case_deck, only: case_deck_text, fingerprint_text, text_fingerprint
  implicit none
  private

  public :: attach_base_deck, attach_list, finish_campaign

contains

  !> Read, resolve and validate the base deck; split it for merging; check that a case without
  !! overrides reproduces it exactly.
  subroutine attach_base_deck(camp, errors)
    type(campaign_t), intent(inout) :: camp        !! campaign with base_path and base_text [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    type(landyn_input_t) :: inp, inp2
    type(input_errors_t) :: e1, e2
    type(campaign_t) :: probe
    integer :: st, i
    character(len=:), allocatable :: merged
    call read_input_text(camp%base_text, camp%base_path, inp, e1, st)
    call resolve_input(inp, e1)
    call validate_input(inp, e1)
    if (e1%count() > 0) then
      do i = 1, e1%count()
        call errors%add(e1%message(i))
      end do
      call errors%add(camp%deck_name//': &campaign: base_deck = '//quote_text(camp%base_path)// &
                      ' has '//int_text(e1%count())//' input error(s); every case starts from it')
      return
    end if
    camp%n_gears = inp%gears%n_gears
    call split_namelist(camp%base_text, camp%base_path, camp%base_groups, e2)
    if (e2%count() > 0) then
      call errors%add(camp%deck_name//': internal error: cannot split the base deck '//camp%base_path// &
                      ': '//e2%message(1))
      return
    end if
    probe%deck_name = camp%deck_name
    probe%base_path = camp%base_path
    probe%base_groups = camp%base_groups
    allocate (probe%par(0))
    merged = case_deck_text(probe, 0, [real(wp) ::])
    call read_input_text(merged, camp%base_path, inp2, e2, st)
    call resolve_input(inp2, e2)
    if (e2%count() > 0) then
      call errors%add(camp%deck_name//': internal error: the base deck rewritten for the cases does not read back: '// &
                      e2%message(1))
    else if (resolved_input_text(inp2) /= resolved_input_text(inp)) then
      call errors%add(camp%deck_name//': internal error: the base deck rewritten for the cases differs from '// &
                      camp%base_path)
    end if
  end subroutine attach_base_deck

  !> Read the case list (CSV: a header of input names, one row of numbers per case).
  subroutine attach_list(camp, errors)
    type(campaign_t), intent(inout) :: camp        !! campaign with list_path and list_text [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    character(len=:), allocatable :: line, msg, pre
    character(len=cell_len), allocatable :: cells(:), hdr(:)
    real(wp), allocatable :: rows(:, :), tmp(:, :)
    integer :: p0, p1, lineno, ncol, nrow, j, ios, n0, first
    logical :: header_done
    character(len=256) :: iomsg

    n0 = errors%count()
    header_done = .false.
    ncol = 0
    nrow = 0
    lineno = 0
    p0 = 1
    allocate (rows(0, 0))
    do while (p0 <= len(camp%list_text))
      p1 = index(camp%list_text(p0:), new_line('a'))
      if (p1 == 0) then
        line = camp%list_text(p0:)
        p0 = len(camp%list_text) + 1
      else
        line = camp%list_text(p0:p0 + p1 - 2)
        p0 = p0 + p1
      end if
      lineno = lineno + 1
      if (len(line) > 0) then
        if (line(len(line):len(line)) == achar(13)) line = line(1:len(line) - 1)
      end if
      if (len_trim(line) == 0) cycle
      first = verify(line, ' '//achar(9))
      if (line(first:first) == '#') cycle
      pre = camp%list_path//':'//int_text(lineno)//': '
      call split_csv(line, cells)
      if (.not. header_done) then
        header_done = .true.
        ncol = size(cells)
        hdr = cells
        if (allocated(camp%par)) deallocate (camp%par)
        allocate (camp%par(ncol))
        do j = 1, ncol
          camp%par(j)%kind = 'list'
          camp%par(j)%line = lineno
          call parse_target(trim(cells(j)), camp%par(j), msg)
          if (len(msg) > 0) call errors%add(pre//'column '//int_text(j)//' '//quote_text(trim(cells(j)))// &
                                            ' is not a campaign input: '//msg)
          allocate (camp%par(j)%values(0), camp%par(j)%weights(0))
        end do
        camp%n_par = ncol
        deallocate (rows)
        allocate (rows(ncol, 16))
        cycle
      end if
      if (size(cells) /= ncol) then
        call errors%add(pre//int_text(size(cells))//' values for '//int_text(ncol)//' columns; valid: one value '// &
                        'per column of the header')
        cycle
      end if
      nrow = nrow + 1
      if (nrow > size(rows, 2)) then
        allocate (tmp(ncol, 2*size(rows, 2)))
        tmp(:, 1:size(rows, 2)) = rows
        call move_alloc(tmp, rows)
      end if
      do j = 1, ncol
        iomsg = ''
        ios = 0
        ! one number per cell: no second value, separator or comment, nothing beyond |x| < 1e31
        if (scan(trim(adjustl(cells(j))), ' '//achar(9)//';#/*!') > 0 .or. &
            has_nonfinite_word(cells(j)) .or. .not. numbers_within(cells(j), 30) .or. &
            verify(trim(adjustl(cells(j))), '0123456789+-.eEdD') > 0) then
          ios = 1
        else
          read (cells(j), *, iostat=ios, iomsg=iomsg) rows(j, nrow)
        end if
        if (ios == 0) then
          if (.not. ieee_is_finite(rows(j, nrow))) ios = -1
        end if
        if (ios /= 0 .or. len_trim(cells(j)) == 0) then
          call errors%add(pre//'case '//int_text(nrow)//', column '//quote_text(trim(hdr(j)))//': '// &
                          quote_text(trim(cells(j)))//' is not a finite number (valid: one number per cell, |x| < 1e31)')
          rows(j, nrow) = 0.0_wp
        else if (camp%par(j)%is_int .and. abs(rows(j, nrow) - anint(rows(j, nrow))) > 0.0_wp) then
          call errors%add(pre//'case '//int_text(nrow)//', column '//quote_text(trim(hdr(j)))//': '// &
                          trim(cells(j))//' is invalid for an integer input; valid: whole numbers')
        end if
      end do
    end do
    if (.not. header_done) then
      call errors%add(camp%list_path//': the case list is empty; valid: a header line of input names, '// &
                      "e.g. 'initial_state%velocity(1), terrain%slope(:)', then one line of values per case")
      if (allocated(camp%par)) deallocate (camp%par)
      allocate (camp%par(0))
    else if (nrow == 0 .and. errors%count() == n0) then
      call errors%add(camp%list_path//': the case list has a header but no cases')
    end if
    camp%table = rows(:, 1:nrow)
    camp%n_cases = nrow
  end subroutine attach_list

  !> Split one CSV line on commas (no quoted commas); cells are trimmed, quotes removed.
  subroutine split_csv(line, cells)
    character(len=*), intent(in) :: line                         !! CSV line [-]
    character(len=cell_len), allocatable, intent(out) :: cells(:)  !! cells [-]
    integer :: n, i, p, q
    character(len=:), allocatable :: c
    n = 1
    do i = 1, len(line)
      if (line(i:i) == ',') n = n + 1
    end do
    allocate (cells(n))
    p = 1
    do i = 1, n
      q = index(line(p:), ',')
      if (q == 0) then
        c = trim(adjustl(line(p:)))
      else
        c = trim(adjustl(line(p:p + q - 2)))
        p = p + q
      end if
      if (len(c) >= 2) then
        if ((c(1:1) == '"' .or. c(1:1) == "'") .and. c(len(c):len(c)) == c(1:1)) c = c(2:len(c) - 1)
      end if
      cells(i) = c
    end do
  end subroutine split_csv

  !> Checks across the whole campaign; case count, defaults, fingerprint.
  subroutine finish_campaign(camp, rc, errors)
    type(campaign_t), intent(inout) :: camp        !! campaign [-]
    type(raw_campaign_t), intent(in) :: rc         !! raw &campaign values [-]
    type(input_errors_t), intent(inout) :: errors  !! problems are appended here [-]
    integer :: i, j
    real(wp) :: ncase
    ! overlapping or duplicate targets and labels
    do i = 1, camp%n_par
      do j = 1, i - 1
        if (camp%par(i)%group == camp%par(j)%group .and. camp%par(i)%var == camp%par(j)%var) then
          if (overlap(camp%par(i)%elems, camp%par(j)%elems)) call errors%add(where_par(i)// &
            ': sets elements that '//quote_text(camp%par(j)%name)//' sets too; vary each element once')
        end if
        if (camp%par(i)%label == camp%par(j)%label) call errors%add(where_par(i)//': label '// &
          quote_text(camp%par(i)%label)//' is used by '//quote_text(camp%par(j)%name)//' too; labels must differ')
      end do
    end do
    select case (camp%mode)
    case ('grid')
      allocate (camp%grid_n(camp%n_par))
      ncase = 1.0_wp
      do i = 1, camp%n_par
        camp%grid_n(i) = size(camp%par(i)%values)
        ncase = ncase*real(camp%grid_n(i), wp)
      end do
      if (ncase > real(max_cases, wp)) then
        call errors%add(camp%deck_name//': the grid has '//real_text_short(ncase)//' cases; valid: at most '// &
                        int_text(max_cases))
      else
        camp%n_cases = product(camp%grid_n)
      end if
    case ('monte_carlo')
      camp%n_cases = camp%n_samples
    case ('list')
      continue   ! set by attach_list
    end select
    if (any(camp%save_histories < 1) .or. any(camp%save_histories > camp%n_cases)) then
      call errors%add(camp%deck_name//': &campaign: save_histories = '// &
                      ints_text(pack(camp%save_histories, camp%save_histories < 1 .or. &
                      camp%save_histories > camp%n_cases))//' is invalid; valid: case ids 1 .. '// &
                      int_text(camp%n_cases))
    end if
    if (len_trim(rc%summary_file) > 0 .and. camp%summary_file(len(camp%summary_file):) == '/') &
      call errors%add(camp%deck_name//': &campaign: summary_file = '//quote_text(camp%summary_file)// &
                      ' is invalid; valid: a file name')
    camp%fingerprint = text_fingerprint(fingerprint_text(camp))

  contains

    !> Where parameter k comes from, for messages: its &parameter line, or its column of the case list.
    function where_par(k) result(s)
      integer, intent(in) :: k            !! parameter index [-]
      character(len=:), allocatable :: s  !! message prefix [-]
      if (camp%mode == 'list') then
        s = camp%list_path//': column '//int_text(k)//" '"//camp%par(k)%name//"'"
      else
        s = camp%deck_name//':'//int_text(camp%par(k)%line)//": &parameter '"//camp%par(k)%name//"'"
      end if
    end function where_par

  end subroutine finish_campaign

  !> Whether two sets of element indices share an element (two parameters setting one element).
  pure function overlap(a, b) result(yes)
    integer, intent(in) :: a(:), b(:)  !! element index sets [-]
    logical :: yes                     !! they share an element [-]
    integer :: i
    yes = .false.
    do i = 1, size(a)
      if (any(b == a(i))) yes = .true.
    end do
  end function overlap

end module landyn_campaign_attach
