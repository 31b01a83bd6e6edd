!> Namelist input of LANDYN: reads a deck into a `landyn_input_t`, resolves the derived
!! defaults, validates the physics, and writes the resolved input back as a deck.
!!
!! A deck is a sequence of namelist groups (&simulation, &lander, &engine, &gears,
!! &primary_strut, &secondary_strut, &contact, &friction, &terrain, &initial_state, &output),
!! each optional and each given at most once; a group states only what differs from the
!! defaults in landyn_config. Angles are DEGREES in decks and RADIANS in landyn_input_t.
!!
!! This module is the entry point of the input layer; the parts are: the variable registry
!! (landyn_input_registry, with its accessor landyn_input_access), the reader
!! (landyn_input_reader), the validation (landyn_input_validate), the resolved-deck writer
!! (landyn_input_writer) and the number formatting (landyn_input_format). Messages have the form
!! `<deck>:<line>: &<group>: <what>` (read errors) or `<deck>: &<group>: <what>` (resolve/validate
!! errors); see docs/input/README.md.
!!
!! Library code: nothing here stops or prints, except into a unit the caller passes.
module landyn_input
  use landyn_kinds, only: wp, max_gears
  use landyn_status, only: status_t, STAT_OK, STAT_FAILED, STAT_INPUT
  use landyn_errors, only: input_errors_t
  use landyn_friction, only: default_stribeck_speed
  use landyn_kinematics, only: rot_z
  use landyn_config, only: landyn_input_t, gears_cfg_t, default_input, is_set
  use landyn_strings, only: lower => lower_case, fmt_int => int_text
  use landyn_files, only: read_whole_file, base_name
  use landyn_input_reader, only: parse_deck
  use landyn_input_validate, only: validate_input
  use landyn_input_writer, only: write_resolved_input, resolved_input_text
  use landyn_input_format, only: fmt_reals, deg_to_rad, msg_prefix
  implicit none
  private

  public :: input_errors_t
  public :: read_input_file, read_input_text, apply_input_text, resolve_input, validate_input, load_input
  public :: write_resolved_input, resolved_input_text, read_text_or_report

contains

  !> Read a namelist deck file into `inp`, starting from `default_input()`. Every problem found
  !! is appended to `errors`. `inp%deck_name` is `path`, `inp%deck_text` the file's text.
  !! stat = 0 when the deck was read without error, 1 when the deck has errors, 2 when the file
  !! cannot be opened or read. Call resolve_input and validate_input next (or use load_input).
  subroutine read_input_file(path, inp, errors, stat)
    character(len=*), intent(in) :: path           !! deck file name [-]
    type(landyn_input_t), intent(out) :: inp       !! input read (defaults where the deck is silent)
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    integer, intent(out) :: stat                   !! STAT_OK, STAT_FAILED (errors in the deck), STAT_INPUT (file not readable) [-]
    character(len=:), allocatable :: text

    inp = default_input()
    inp%deck_name = path
    if (len(path) == 0) then
      call errors%add("'': cannot read the input deck: empty file name")
      stat = STAT_INPUT
      return
    end if
    call read_text_or_report(path, path//': cannot open or read the input deck: ', text, errors, stat)
    if (stat /= STAT_OK) return
    call read_input_text(text, path, inp, errors, stat)
  end subroutine read_input_file

  !> Read a whole text file; when it cannot be read, append `prefix` followed by the reason to
  !! `errors` and return STAT_INPUT (text is then ''). The one "read a deck or report it" step of
  !! the run, campaign and study deck readers.
  subroutine read_text_or_report(path, prefix, text, errors, stat)
    character(len=*), intent(in) :: path                 !! file name [-]
    character(len=*), intent(in) :: prefix               !! message before the reason [-]
    character(len=:), allocatable, intent(out) :: text   !! file contents ('' when unreadable) [-]
    type(input_errors_t), intent(inout) :: errors        !! the problem is appended here [-]
    integer, intent(out) :: stat                         !! STAT_OK or STAT_INPUT [-]
    type(status_t) :: st
    stat = STAT_OK
    call read_whole_file(path, text, st)
    if (st%ok()) return
    call errors%add(prefix//st%text())
    text = ''
    stat = STAT_INPUT
  end subroutine read_text_or_report

  !> Read a deck held in a string (lines separated by new_line('a')) into `inp`, starting from
  !! `default_input()`. `deck_name` is used in messages and stored in inp%deck_name ('' for none).
  !! stat = 0 when no error was found, 1 otherwise.
  subroutine read_input_text(text, deck_name, inp, errors, stat)
    character(len=*), intent(in) :: text           !! deck text [-]
    character(len=*), intent(in) :: deck_name      !! name for messages, usually the file name [-]
    type(landyn_input_t), intent(out) :: inp       !! input read (defaults where the deck is silent)
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    integer, intent(out) :: stat                   !! STAT_OK, STAT_FAILED (errors found) [-]
    integer :: n0
    n0 = errors%count()
    inp = default_input()
    inp%deck_name = deck_name
    inp%deck_text = text
    call parse_deck(text, deck_name, inp, errors)
    stat = merge(STAT_OK, STAT_FAILED, errors%count() == n0)
  end subroutine read_input_text

  !> Apply a deck fragment on top of an input already read (not yet resolved): only the variables
  !! the fragment names change, and a group may be given again. Used for study variants.
  !! The fragment is appended to inp%deck_text after a comment naming `fragment_name`.
  !! stat = 0 when no error was found, 1 otherwise.
  subroutine apply_input_text(text, fragment_name, inp, errors, stat)
    character(len=*), intent(in) :: text           !! deck fragment (namelist groups) [-]
    character(len=*), intent(in) :: fragment_name  !! name for messages [-]
    type(landyn_input_t), intent(inout) :: inp     !! input updated item by item
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    integer, intent(out) :: stat                   !! STAT_OK, STAT_FAILED (errors found) [-]
    integer :: n0
    n0 = errors%count()
    call parse_deck(text, fragment_name, inp, errors)
    if (.not. allocated(inp%deck_text)) inp%deck_text = ''
    inp%deck_text = inp%deck_text//new_line('a')//'! ---- applied on top: '//trim(fragment_name)//new_line('a')//text
    stat = merge(STAT_OK, STAT_FAILED, errors%count() == n0)
  end subroutine apply_input_text

  !> Read, resolve and validate a deck in one call. stat = 0 when the input is ready to run,
  !! 1 when `errors` holds problems of the deck, 2 when the file cannot be opened or read.
  subroutine load_input(path, inp, errors, stat)
    character(len=*), intent(in) :: path           !! deck file name [-]
    type(landyn_input_t), intent(out) :: inp       !! resolved, validated input
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    integer, intent(out) :: stat                   !! STAT_OK, STAT_FAILED (errors in the deck), STAT_INPUT (file not readable) [-]
    integer :: n0
    n0 = errors%count()
    call read_input_file(path, inp, errors, stat)
    if (stat == STAT_INPUT) return
    call resolve_input(inp, errors)
    call validate_input(inp, errors)
    stat = merge(STAT_OK, STAT_FAILED, errors%count() == n0)
  end subroutine load_input

  !> Fill the derived defaults: gears%rotation(i) unset -> (i-1)*360/n_gears deg; point columns
  !! 2..n_gears that the deck does not give -> gear 1's points rotated by rotation(i) about the
  !! lander z axis (a gear given in part is an error); engine%direction normalised; law names in
  !! lower case; output%file empty -> deck base name + '.h5' ('landyn.h5' without a deck).
  !! Idempotent: resolving a resolved input changes nothing.
  subroutine resolve_input(inp, errors)
    type(landyn_input_t), intent(inout) :: inp     !! input to resolve in place
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    character(len=:), allocatable :: pre
    real(wp) :: nrm
    pre = msg_prefix(inp)
    call resolve_gears(inp%gears, pre, errors)
    nrm = norm2(inp%engine%direction)
    if (nrm < tiny(1.0_wp)) then
      call errors%add(pre//'&engine: direction = '//fmt_reals(inp%engine%direction)// &
                      ' is invalid; valid: a vector of non-zero length')
    else if (abs(nrm - 1.0_wp) > 4.0_wp*epsilon(1.0_wp)) then
      inp%engine%direction = inp%engine%direction/nrm
    end if
    inp%contact%law = lower(adjustl(inp%contact%law))
    inp%simulation%integrator = lower(adjustl(inp%simulation%integrator))
    inp%friction%law = lower(adjustl(inp%friction%law))
    if (.not. is_set(inp%friction%stribeck_speed)) &
      inp%friction%stribeck_speed = default_stribeck_speed(inp%friction%law)
    ! the legs' frame field: the adaptive integrator's own (0: predicted, a second pass where a lock
    ! changed), the paper's lagged one for the others: its scheme 'fixed' and 'imex', measured with it
    ! (docs/theory.md, "Frame field passes")
    if (inp%simulation%frame_field_passes == 0 .and. inp%simulation%integrator /= 'adaptive') &
      inp%simulation%frame_field_passes = 1
    if (len_trim(inp%output%file) == 0) then
      if (allocated(inp%deck_name)) then
        inp%output%file = default_output_file(inp%deck_name)
      else
        inp%output%file = default_output_file('')
      end if
    end if
  end subroutine resolve_input

  ! ================================================================ resolve helpers

  !> Resolve gear rotations and hard points; see resolve_input.
  subroutine resolve_gears(g, pre, errors)
    type(gears_cfg_t), intent(inout) :: g          !! gears to resolve in place
    character(len=*), intent(in) :: pre            !! message prefix [-]
    type(input_errors_t), intent(inout) :: errors  !! problems found are appended here
    real(wp) :: r(3, 3)
    integer :: i, n, nset
    character(len=:), allocatable :: missing
    n = g%n_gears
    if (n < 1 .or. n > max_gears) return   ! reported by validate_input
    do i = 1, n
      if (.not. is_set(g%rotation(i))) g%rotation(i) = deg_to_rad(real(i - 1, wp)*360.0_wp/real(n, wp))
    end do
    do i = 1, max_gears
      nset = count(is_set(g%point_a(:, i))) + count(is_set(g%point_b(:, i))) + count(is_set(g%point_c(:, i))) + &
             count(is_set(g%point_d(:, i))) + count(is_set(g%point_e(:, i))) + count(is_set(g%point_f(:, i)))
      if (i > n) then
        if (nset > 0 .or. is_set(g%rotation(i))) &
          call errors%add(pre//'&gears: gear '//fmt_int(i)//' is given (rotation or points) but n_gears = '// &
                          fmt_int(n)//'; valid: give gears 1..n_gears only')
        cycle
      end if
      if (nset == 18) cycle
      if (nset == 0 .and. i > 1) then
        r = rot_z(g%rotation(i))
        g%point_a(:, i) = matmul(r, g%point_a(:, 1))
        g%point_b(:, i) = matmul(r, g%point_b(:, 1))
        g%point_c(:, i) = matmul(r, g%point_c(:, 1))
        g%point_d(:, i) = matmul(r, g%point_d(:, 1))
        g%point_e(:, i) = matmul(r, g%point_e(:, 1))
        g%point_f(:, i) = matmul(r, g%point_f(:, 1))
        cycle
      end if
      missing = missing_list(g, i)
      call errors%add(pre//'&gears: gear '//fmt_int(i)//' is given only in part (missing: '//missing// &
                      '); valid: all six points point_a(:, '//fmt_int(i)//') .. point_f(:, '//fmt_int(i)// &
                      '), or none to rotate gear 1 by rotation('//fmt_int(i)//')')
    end do
  end subroutine resolve_gears

  !> The names of the points of gear i that are not (fully) given.
  function missing_list(g, i) result(list)
    type(gears_cfg_t), intent(in) :: g       !! gears
    integer, intent(in) :: i                 !! gear index [-]
    character(len=:), allocatable :: list    !! e.g. "point_b(:, 3), point_f(:, 3)" [-]
    list = ''
    if (.not. all(is_set(g%point_a(:, i)))) call append(list, 'point_a')
    if (.not. all(is_set(g%point_b(:, i)))) call append(list, 'point_b')
    if (.not. all(is_set(g%point_c(:, i)))) call append(list, 'point_c')
    if (.not. all(is_set(g%point_d(:, i)))) call append(list, 'point_d')
    if (.not. all(is_set(g%point_e(:, i)))) call append(list, 'point_e')
    if (.not. all(is_set(g%point_f(:, i)))) call append(list, 'point_f')
  contains
    !> Appends a point name of gear i to the list of missing points.
    subroutine append(l, name)
      character(len=:), allocatable, intent(inout) :: l  !! list [-]
      character(len=*), intent(in) :: name               !! point name [-]
      if (len(l) > 0) l = l//', '
      l = l//name//'(:, '//fmt_int(i)//')'
    end subroutine append
  end function missing_list

  !> Base name of the deck (no directory, no extension) + '.h5'; 'landyn.h5' without a deck.
  pure function default_output_file(deck) result(file)
    character(len=*), intent(in) :: deck     !! deck path ('' for none) [-]
    character(len=:), allocatable :: file    !! result file name [-]
    file = base_name(deck, 'landyn')//'.h5'
  end function default_output_file

end module landyn_input
