!> Sensitivity studies (paper section 4, Tables 6, 9 and 10): one or more load-case decks run
!! with a list of law variants, the crush lengths gathered in one HDF5 file and one CSV table.
!!
!! A study deck is a namelist file (docs/study.md):
!!
!!   &study
!!     title = 'Contact models (paper Table 6)'
!!     base_deck = 'lc1.nml', 'lc2.nml'     ! load-case decks, relative to the study deck
!!     case_label = 'LC-1', 'LC-2'
!!     common = "&simulation t_end = 0.5 /" ! applied to every run (optional)
!!     output = 'study_contact.h5'          ! default: study deck base name + .h5
!!     csv = 'study_contact.csv'            ! default: study deck base name + .csv
!!     measure_case = ..., measure_gear = ..., measure_strut = ...   ! table rows (optional)
!!   /
!!   &variant label = 'Base result' /
!!   &variant label = 'Hertz', set = "&contact law = 'hertz' /" /
!!   &variant label = 'e = 0.3', set = "contact%law = 'hunt_crossley'", "contact%restitution = 0.3" /
!!
!! Each `set` entry is either namelist text ("&group name = value ... /") or a triplet
!! "group%variable = value"; they are applied, in order, on top of each load-case deck (after
!! `common`), with the same reader, messages and validation as the landyn program.
!!
!! Table rows ("measure options"): by default the nine options of the paper's Tables 6, 9 and 10
!! when the study has two load cases (LC-1 gear 1 primary, left, right; LC-2 primary of gears 1/4,
!! left secondary of gear 1, left secondary of gear 2, primary of gears 2/3, left secondaries of
!! gears 3 and 4), otherwise every strut of every gear of every case (Table 3's layout).
!!
!! Library code: returns a status_t; progress goes to a unit the caller passes.
module landyn_study
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  use landyn_kinds, only: wp, msg_len, max_gears
  use landyn_config, only: landyn_input_t, path_len
  use landyn_input, only: input_errors_t, read_text_or_report, read_input_file, apply_input_text, resolve_input, validate_input
  use landyn_simulation, only: sim_result_t
  use landyn_health, only: health_t
  use landyn_run, only: run_case, worse_status
  use landyn_output, only: write_result_file
  use landyn_strings, only: int_text, lower_case
  use landyn_status, only: status_t, STAT_OK, STAT_FAILED, STAT_INPUT, STAT_FILE, EXIT_OK, EXIT_INPUT, EXIT_DIVERGED, EXIT_HEALTH, &
                          EXIT_NO_TOUCHDOWN
  use landyn_files, only: base_name
  use landyn_tripod_gear, only: strut_names   ! the tripod's struts, in the order of the result file's strut axis
  use landyn_study_deck, only: study_deck_t, read_study_deck, max_cases, max_measures, label_len, set_len
  implicit none
  private

  public :: study_t, variant_t, run_record_t
  public :: read_study, prepare_study, run_study, group_name
  public :: label_len, set_len, strut_names
  public :: status_ok, status_failed, status_unhealthy, status_no_touchdown

  ! Run statuses, as landyn's exit statuses
  integer, parameter :: status_ok = EXIT_OK              !! run completed (a tip-over is a result)
  integer, parameter :: status_input = EXIT_INPUT        !! invalid input: not run
  integer, parameter :: status_failed = EXIT_DIVERGED    !! the simulation failed (diverged)
  integer, parameter :: status_unhealthy = EXIT_HEALTH   !! completed, but a run-health check failed (docs/health.md)
  integer, parameter :: status_no_touchdown = EXIT_NO_TOUCHDOWN  !! completed without touching the ground

  !> One law variant.
  type :: variant_t
    character(len=label_len) :: label = ''           !! label (table column) [-]
    character(len=:), allocatable :: overrides       !! deck text applied on top of each case [-]
  end type variant_t

  !> Result of one run (one variant on one load case).
  type :: run_record_t
    integer :: status = status_input                 !! status_ok, status_input or status_failed [-]
    character(len=msg_len) :: message = ''           !! diagnosis when status /= status_ok [-]
    character(len=64) :: end_reason = ''             !! how the run ended [-]
    integer :: n_gears = 0                           !! number of gears [-]
    real(wp), allocatable :: crush(:, :)             !! (n_struts, n_gears) signed net crush (Table 3 sense) [m]
    real(wp) :: energy_residual = 0.0_wp             !! energy audit residual / input energy [-]
    real(wp) :: peak_overload = 0.0_wp               !! [g]
    real(wp) :: max_tilt = 0.0_wp                    !! [deg]
    logical :: tipped_over = .false.                 !! [-]
    integer :: outcome = 0                           !! outcome code (landyn_outcome) [-]
    real(wp) :: tipover_margin = 0.0_wp              !! tip-over margin at the end [deg]
    real(wp) :: min_stroke_margin = 0.0_wp           !! smallest stroke margin of any strut [m]
    real(wp) :: t_final = 0.0_wp                     !! [s]
    real(wp) :: wall_time = 0.0_wp                   !! [s]
  end type run_record_t

  !> A study: load cases, variants, table layout and, after run_study, the results.
  type :: study_t
    character(len=256) :: title = ''                         !! study title [-]
    character(len=:), allocatable :: deck_name               !! study deck path [-]
    character(len=:), allocatable :: deck_text               !! study deck text [-]
    integer :: n_cases = 0                                   !! load cases [-]
    character(len=path_len) :: case_deck(max_cases) = ''     !! load-case deck paths (resolved) [-]
    character(len=label_len) :: case_label(max_cases) = ''   !! load-case labels [-]
    character(len=:), allocatable :: common                  !! deck text applied to every run [-]
    character(len=path_len) :: output = ''                   !! HDF5 file [-]
    character(len=path_len) :: csv = ''                      !! CSV file [-]
    logical :: keep_results = .false.                        !! also write every run's result file [-]
    integer :: n_variants = 0                                !! variants [-]
    type(variant_t), allocatable :: variant(:)               !! variants [-]
    integer :: n_measures = 0                                !! table rows [-]
    integer :: measure(3, max_measures) = 0                  !! (case, gear, strut) of each row [-]
    logical :: default_measures = .true.                     !! rows not given in the deck [-]
    type(landyn_input_t), allocatable :: inp(:, :)           !! (case, variant) resolved inputs [-]
    type(run_record_t), allocatable :: run(:, :)             !! (case, variant) results [-]
  end type study_t

contains

  ! ================================================================ reading

  !> Read a study deck (its groups through the input reader with the study-deck registry,
  !! landyn_study_deck). Problems are appended to `errors`; stat = STAT_OK, STAT_FAILED (errors in
  !! the deck) or STAT_INPUT (the file cannot be read).
  subroutine read_study(path, sd, errors, stat)
    character(len=*), intent(in) :: path            !! study deck [-]
    type(study_t), intent(out) :: sd                !! the study (not yet prepared) [-]
    type(input_errors_t), intent(inout) :: errors   !! problems found are appended here [-]
    integer, intent(out) :: stat                    !! STAT_OK, STAT_FAILED (deck errors), STAT_INPUT (unreadable) [-]
    character(len=:), allocatable :: text, dir
    type(study_deck_t) :: deck
    integer :: n0, i

    n0 = errors%count()
    stat = STAT_OK
    sd%deck_name = trim(path)
    call read_text_or_report(path, path//': cannot read the study deck: ', text, errors, stat)
    if (stat /= STAT_OK) return
    sd%deck_text = text
    dir = ''
    i = index(path, '/', back=.true.)
    if (i > 0) dir = path(1:i)
    call read_study_deck(path, text, deck, errors)
    call study_group(path, dir, deck, errors%count() > n0, sd, errors)
    call variants(path, deck, n0, sd, errors)
    stat = merge(STAT_OK, STAT_FAILED, errors%count() == n0)
  end subroutine read_study

  !> The &study group of a study deck into `sd`: title, load-case decks (relative to the deck's
  !! directory) and their labels, common overrides, output files, result files and table rows.
  subroutine study_group(path, dir, deck, bad_deck, sd, errors)
    character(len=*), intent(in) :: path            !! study deck, for messages [-]
    character(len=*), intent(in) :: dir             !! its directory ('' or ending in '/') [-]
    type(study_deck_t), intent(in) :: deck          !! the deck as read [-]
    logical, intent(in) :: bad_deck                 !! reading it found errors (a missing base_deck may be one) [-]
    type(study_t), intent(inout) :: sd              !! the study [-]
    type(input_errors_t), intent(inout) :: errors   !! problems found are appended here [-]
    integer :: i

    if (deck%n_study == 0) call errors%add(path//': no &study group (it names the load-case decks: base_deck = ...)')
    sd%title = deck%title
    sd%n_cases = count(len_trim(deck%base_deck) > 0)
    if (sd%n_cases == 0 .and. deck%n_study > 0 .and. .not. bad_deck) &
      call errors%add(trim(path)//': &study: base_deck is not given; '// &
                      "valid: one or more load-case decks, e.g. base_deck = 'lc1.nml'")
    if (any(len_trim(deck%base_deck(1:sd%n_cases)) == 0)) &
      call errors%add(trim(path)//': &study: base_deck has empty entries between given ones')
    do i = 1, sd%n_cases
      if (deck%base_deck(i)(1:1) == '/') then
        sd%case_deck(i) = deck%base_deck(i)
      else
        sd%case_deck(i) = dir//trim(deck%base_deck(i))
      end if
      sd%case_label(i) = deck%case_label(i)
      if (len_trim(deck%case_label(i)) == 0) sd%case_label(i) = default_case_label(deck%base_deck(i))
    end do
    do i = 2, sd%n_cases
      if (any(sd%case_label(1:i - 1) == sd%case_label(i))) &
        call errors%add(path//': &study: case_label '''//trim(sd%case_label(i))//''' is given twice; '// &
                        'valid: distinct labels (they name the runs and the rows of the table)')
    end do
    sd%common = ''
    call join_sets(deck%common, 'common', path, sd%common, errors)
    sd%output = deck%output
    if (len_trim(deck%output) == 0) sd%output = base_name(path, 'study')//'.h5'
    sd%csv = deck%csv
    if (len_trim(deck%csv) == 0) sd%csv = base_name(path, 'study')//'.csv'
    sd%keep_results = deck%keep_results
    call set_measures(sd, deck%measure_case, deck%measure_gear, deck%measure_strut, path, errors, 4)
  end subroutine study_group

  !> Every &variant group of a study deck, in order, into sd%variant (label and overrides); no
  !! variants (when the deck has no other error) and repeated labels are reported.
  subroutine variants(path, deck, n0, sd, errors)
    character(len=*), intent(in) :: path            !! study deck, for messages [-]
    type(study_deck_t), intent(in) :: deck          !! the deck as read [-]
    integer, intent(in) :: n0                       !! errors before the deck was read [-]
    type(study_t), intent(inout) :: sd              !! the study [-]
    type(input_errors_t), intent(inout) :: errors   !! problems found are appended here [-]
    character(len=:), allocatable :: ovr
    integer :: i, nv

    nv = deck%n_variants
    allocate (sd%variant(max(8, nv)))
    do i = 1, nv
      sd%variant(i)%label = deck%label(i)
      if (len_trim(deck%label(i)) == 0) write (sd%variant(i)%label, '(a,i0)') 'variant ', i
      ovr = ''
      call join_sets(deck%set(:, i), 'variant '//trim(sd%variant(i)%label)//': set', path, ovr, errors)
      sd%variant(i)%overrides = ovr
    end do
    sd%n_variants = nv
    if (nv == 0 .and. errors%count() == n0) call errors%add(trim(path)//': no &variant group; valid: one or '// &
                                                             "more, e.g. &variant label = 'Base result' /")
    do i = 2, nv
      if (any(sd%variant(1:i - 1)%label == sd%variant(i)%label)) &
        call errors%add(trim(path)//': &variant label '''//trim(sd%variant(i)%label)//''' is given twice')
    end do
  end subroutine variants

  !> Read, override, resolve and validate the input of every run (case x variant) before anything
  !! is run, so that a study with an invalid variant runs nothing. stat = STAT_OK when all are valid.
  subroutine prepare_study(study, errors, stat)
    type(study_t), intent(inout) :: study           !! study read by read_study
    type(input_errors_t), intent(inout) :: errors   !! problems found are appended here
    integer, intent(out) :: stat                    !! STAT_OK, STAT_FAILED (invalid input), STAT_INPUT (a deck is unreadable) [-]
    integer :: c, v, n0, st, m, n_gears
    n0 = errors%count()
    stat = STAT_OK
    if (allocated(study%inp)) deallocate (study%inp)
    if (allocated(study%run)) deallocate (study%run)
    allocate (study%inp(study%n_cases, study%n_variants), study%run(study%n_cases, study%n_variants))
    do v = 1, study%n_variants
      do c = 1, study%n_cases
        call read_input_file(trim(study%case_deck(c)), study%inp(c, v), errors, st)
        if (st == STAT_INPUT) then
          stat = STAT_INPUT
          cycle
        end if
        call apply_entries(study%common, trim(study%deck_name)//' (&study common', study%inp(c, v))
        call apply_entries(study%variant(v)%overrides, trim(study%deck_name)//' (&variant '// &
                           trim(study%variant(v)%label)//' set', study%inp(c, v))
        ! messages about the resolved input name the load case and the variant
        study%inp(c, v)%deck_name = trim(study%case_deck(c))//' with &variant '//trim(study%variant(v)%label)
        call resolve_input(study%inp(c, v), errors)
        call validate_input(study%inp(c, v), errors)
        if (study%keep_results) study%inp(c, v)%output%file = run_file_name(study, c, v)
      end do
    end do
    if (stat == STAT_OK .and. errors%count() > n0) stat = STAT_FAILED
    if (stat /= STAT_OK) return
    ! table rows against the landers' gears
    n_gears = minval(study%inp(:, 1)%gears%n_gears)
    if (study%default_measures .and. study%n_cases /= 2) then
      call set_measures(study, [0], [0], [0], trim(study%deck_name), errors, n_gears)
    end if
    do m = 1, study%n_measures
      c = study%measure(1, m)
      if (study%measure(2, m) > study%inp(c, 1)%gears%n_gears) then
        call errors%add(trim(study%deck_name)//': &study: measure option '//int_text(m)//' names gear '// &
                        int_text(study%measure(2, m))//' but load case '//trim(study%case_label(c))//' has '// &
                        int_text(study%inp(c, 1)%gears%n_gears)//' gears')
        stat = STAT_FAILED
      end if
    end do

  contains

    !> Apply each line of `text` (one `set` or `common` entry per line) as its own fragment, so
    !! that several entries may name the same group.
    subroutine apply_entries(text, name, inp)
      character(len=*), intent(in) :: text             !! entries, one per line [-]
      character(len=*), intent(in) :: name             !! fragment name for messages, without ')' [-]
      type(landyn_input_t), intent(inout) :: inp       !! input updated
      integer :: p0, p1, k, st_
      p0 = 1
      k = 0
      do while (p0 <= len(text))
        p1 = index(text(p0:), new_line('a'))
        if (p1 == 0) then
          p1 = len(text) + 1
        else
          p1 = p0 + p1 - 1
        end if
        if (len_trim(text(p0:p1 - 1)) > 0) then
          k = k + 1
          call apply_input_text(text(p0:p1 - 1), name//'('//int_text(k)//'))', inp, errors, st_)
        end if
        p0 = p1 + 1
      end do
    end subroutine apply_entries

  end subroutine prepare_study

  ! ================================================================ running

  !> Run every prepared (case, variant). `progress_unit` < 0 silences the progress lines.
  !! Two statuses of two kinds: `status`, the library status (landyn_status STAT_*): STAT_OK, or
  !! STAT_FILE when a kept result file could not be written (the study stops there); `worst`, a run
  !! status (the program kind, EXIT_* as landyn_run's run_case): the worst of the runs so far
  !! (landyn_run's worse_status: status_failed before status_unhealthy before status_no_touchdown
  !! before status_ok; the records say which runs).
  subroutine run_study(study, progress_unit, command_line, worst, status)
    type(study_t), intent(inout) :: study        !! prepared study; runs are filled in [-]
    integer, intent(in) :: progress_unit         !! unit for progress lines, < 0 for none [-]
    character(len=*), intent(in) :: command_line !! command line (stored in kept result files) [-]
    integer, intent(out) :: worst                !! worst run status: status_ok, status_failed, status_unhealthy
                                                 !! or status_no_touchdown (EXIT_* values) [-]
    type(status_t), intent(out) :: status        !! STAT_OK, or STAT_FILE with its message when a kept result file
                                                 !! is not written [-]
    type(sim_result_t) :: res
    type(health_t) :: health
    type(status_t) :: wst
    integer :: c, v, k, n, st
    logical :: ran
    character(len=msg_len) :: msg
    worst = status_ok
    k = 0
    n = study%n_cases*study%n_variants
    do v = 1, study%n_variants
      do c = 1, study%n_cases
        k = k + 1
        if (progress_unit >= 0) then
          write (progress_unit, '(a,i0,a,i0,a)') 'landyn_study: [', k, '/', n, '] '//trim(study%variant(v)%label)// &
            ' on '//trim(study%case_label(c))//' ...'
          flush (progress_unit)
        end if
        msg = ''
        ! interface loads only for the result files kept
        call run_case(study%inp(c, v), res, health, st, msg, -1, loads=study%keep_results, ran=ran)
        associate (r => study%run(c, v))
          r%message = ''
          if (.not. ran) then
            r%status = st
            r%message = msg
            if (st == status_unhealthy) r%message = 'run-health check failed: '//health%messages
            r%crush = reshape([ieee_value(1.0_wp, ieee_quiet_nan)], [1, 1])
            worst = worse_status(worst, st)
          else
            r%status = st
            worst = worse_status(worst, st)
            if (st == status_unhealthy) then
              r%message = 'run-health check failed: '//health%messages
            else if (st == status_no_touchdown) then
              r%message = 'no touchdown: no footpad touched the ground'
            end if
            r%outcome = res%outcome
            r%tipover_margin = res%tipover_margin
            r%n_gears = res%n_gears
            r%crush = res%crush_net
            r%energy_residual = res%energy_residual
            r%peak_overload = res%peak_overload
            r%max_tilt = res%max_tilt
            r%min_stroke_margin = minval(res%stroke_margin)
            r%tipped_over = res%tipped_over
            r%end_reason = res%end_reason
            r%t_final = res%t_final
            r%wall_time = res%wall_time
            if (study%keep_results) then
              call write_result_file(trim(study%inp(c, v)%output%file), study%inp(c, v), res, command_line, wst, &
                                     health)
              if (.not. wst%ok()) then
                call status%fail(STAT_FILE, 'cannot write '//trim(study%inp(c, v)%output%file)//': '//wst%text())
                return
              end if
            end if
          end if
          if (progress_unit >= 0) then
            if (r%status == status_unhealthy) write (progress_unit, '(a)') '  '//trim(r%message)
            if (r%n_gears > 0) then
              write (progress_unit, '(a,'//int_text(size(r%crush, 1))//'f8.1,a,f7.3,a,f7.2,a)') &
                '  gear 1 crush [mm]', 1000.0_wp*r%crush(:, 1), &
                ', energy residual', 100.0_wp*r%energy_residual, ' %, ', r%wall_time, ' s, '//trim(r%end_reason)
            else
              write (progress_unit, '(a)') '  FAILED: '//trim(r%message)
            end if
            flush (progress_unit)
          end if
        end associate
      end do
    end do
  end subroutine run_study

  ! ================================================================ helpers

  !> Table rows from the &study measure arrays, or the defaults (see the module documentation).
  subroutine set_measures(study, mc, mg, ms, path, errors, n_gears)
    type(study_t), intent(inout) :: study           !! study (n_cases set)
    integer, intent(in) :: mc(:)                    !! measure_case [-]
    integer, intent(in) :: mg(:)                    !! measure_gear [-]
    integer, intent(in) :: ms(:)                    !! measure_strut [-]
    character(len=*), intent(in) :: path            !! deck name for messages [-]
    type(input_errors_t), intent(inout) :: errors   !! problems found are appended here
    integer, intent(in) :: n_gears                  !! gears per lander for the default rows [-]
    integer, parameter :: paper(3, 9) = reshape([1, 1, 1, 1, 1, 2, 1, 1, 3, &
                                                 2, 1, 1, 2, 1, 2, 2, 2, 2, 2, 2, 1, 2, 3, 2, 2, 4, 2], [3, 9])
    integer :: n, m, c, gi, k
    n = count(mc > 0)
    study%default_measures = n == 0
    if (n > 0) then
      study%n_measures = n
      do m = 1, n
        study%measure(:, m) = [mc(m), mg(m), ms(m)]
        if (mc(m) < 1 .or. mc(m) > study%n_cases .or. mg(m) < 1 .or. mg(m) > max_gears .or. &
            ms(m) < 1 .or. ms(m) > size(strut_names)) &
          call errors%add(trim(path)//': &study: measure option '//int_text(m)//' = (case '//int_text(mc(m))// &
                          ', gear '//int_text(mg(m))//', strut '//int_text(ms(m))//') is invalid; valid: case 1..'// &
                          int_text(study%n_cases)//', gear 1..n_gears, strut 1..'// &
                          int_text(size(strut_names))//' (primary, left, right)')
      end do
      if (any(mc(1:n) < 1 .or. mc(1:n) > study%n_cases .or. mg(1:n) < 1 .or. mg(1:n) > max_gears .or. &
              ms(1:n) < 1 .or. ms(1:n) > size(strut_names))) study%n_measures = 0   ! reported; no table row may use them
    else if (study%n_cases == 2) then
      study%n_measures = 9
      study%measure(:, 1:9) = paper
    else
      m = 0
      do c = 1, study%n_cases
        do gi = 1, n_gears
          do k = 1, size(strut_names)
            m = m + 1
            study%measure(:, m) = [c, gi, k]
          end do
        end do
      end do
      study%n_measures = m
    end if
  end subroutine set_measures

  !> Join the non-blank `set` entries into deck text: namelist groups as given, triplets
  !! "group%variable = value" as "&group variable = value /".
  subroutine join_sets(entries, what, path, text, errors)
    character(len=*), intent(in) :: entries(:)      !! entries [-]
    character(len=*), intent(in) :: what            !! name for messages [-]
    character(len=*), intent(in) :: path            !! deck name for messages [-]
    character(len=:), allocatable, intent(inout) :: text  !! deck text [-]
    type(input_errors_t), intent(inout) :: errors   !! problems found are appended here
    integer :: i, p, q
    character(len=:), allocatable :: e
    text = ''
    do i = 1, size(entries)
      e = trim(adjustl(entries(i)))
      if (len(e) == 0) cycle
      if (e(1:1) == '&') then
        text = text//e//new_line('a')
        cycle
      end if
      p = index(e, '%')
      q = index(e, '=')
      if (p > 1 .and. q > p + 1) then
        text = text//'&'//e(1:p - 1)//' '//e(p + 1:)//' /'//new_line('a')
      else
        call errors%add(trim(path)//': '//what//'('//int_text(i)//') = "'//e//'" is invalid; valid: namelist '// &
                        "text such as ""&contact law = 'hertz' /"" or a triplet ""contact%law = 'hertz'""")
      end if
    end do
  end subroutine join_sets

  !> File name of a kept result: <output base>_<variant number>_<case label>.h5.
  function run_file_name(study, c, v) result(name)
    type(study_t), intent(in) :: study     !! study [-]
    integer, intent(in) :: c               !! case [-]
    integer, intent(in) :: v               !! variant [-]
    character(len=path_len) :: name        !! file name [-]
    character(len=:), allocatable :: b
    b = trim(study%output)
    if (len(b) > 3) then
      if (b(len(b) - 2:) == '.h5') b = b(1:len(b) - 3)
    end if
    name = b//'_'//int_text(v, 3)//'_'//group_name(study%case_label(c))//'.h5'
  end function run_file_name

  !> 'LC-1' from 'lc1.nml' (upper-case base name with a dash before a trailing number), else the base name.
  pure function default_case_label(deck) result(label)
    character(len=*), intent(in) :: deck   !! deck path [-]
    character(len=label_len) :: label      !! label [-]
    character(len=:), allocatable :: b
    b = base_name(deck, 'study')
    if (len(b) == 3 .and. lower_case(b(1:2)) == 'lc') then
      label = 'LC-'//b(3:3)
    else
      label = b
    end if
  end function default_case_label

  !> HDF5 group name from a label: letters, digits, '-', '_' kept, the rest '_'.
  pure function group_name(label) result(g)
    character(len=*), intent(in) :: label  !! label [-]
    character(len=:), allocatable :: g     !! group name [-]
    integer :: i
    g = trim(label)
    do i = 1, len(g)
      if (index('abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_', g(i:i)) == 0) g(i:i) = '_'
    end do
    if (len(g) == 0) g = '_'
  end function group_name

end module landyn_study
