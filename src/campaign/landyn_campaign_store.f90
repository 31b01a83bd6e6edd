!> Campaign results on disk: the summary file (HDF5, one row per case; docs/campaign.md), the
!! table of rows of a campaign, and the success probability with its Wilson score interval.
!! The journal (one text line per finished case) is in landyn_campaign_journal.
!!
!! The summary file is always written whole, under <file>.partial and renamed, so a file named
!! <file> is always complete and valid; while a campaign runs it is rewritten every
!! checkpoint_interval seconds and at the end. `--resume` reads the rows of both the summary
!! file and the journal.
!!
!! Library code: nothing here stops or prints.
module landyn_campaign_store
  use landyn_kinds, only: wp, ip
  use landyn_version, only: landyn_git_revision
  use landyn_strings, only: nonempty, int_text
  use landyn_status, only: status_t, STAT_OK, STAT_FAILED
  use landyn_provenance, only: write_meta
  use landyn_h5, only: h5_file_t, h5_create_partial, h5_commit_partial, h5_open_read, h5_close, h5_write, &
                       h5_write_attr, h5_read, h5_read_attr, h5_exists
  use landyn_campaign_deck, only: campaign_t, criteria_t, param_description, max_body_points
  use landyn_campaign_case, only: case_row_t, status_ok, status_no_touchdown, criterion_name, failed_criteria_names, &
                                 failure_counts, inconclusive
  ! the one definition of the summary file's layout version (docs/campaign.md)
  use landyn_output_schema, only: schema_version => campaign_schema_version
  implicit none
  private

  public :: summary_meta_t, meta_from_campaign, write_summary, read_summary
  public :: success_probability, wilson_interval, schema_version
  public :: results_t, results_init, results_add, results_rows, results_missing, results_take_rows

  real(wp), parameter :: z95 = 1.959963984540054_wp   !! two-sided 95 % normal quantile [-]
  integer, parameter :: text_len = 2048               !! longest stored string of a row [-]

  !> Everything a summary file says about its campaign besides the rows (enough to merge
  !! summary files without the deck).
  type :: summary_meta_t
    character(len=:), allocatable :: title          !! campaign title [-]
    character(len=:), allocatable :: mode           !! 'grid', 'monte_carlo' or 'list' [-]
    character(len=:), allocatable :: seed           !! seed as decimal text [-]
    character(len=:), allocatable :: fingerprint    !! campaign fingerprint (16 hex) [-]
    character(len=:), allocatable :: deck_name      !! campaign deck [-]
    character(len=:), allocatable :: deck_text      !! campaign deck text [-]
    character(len=:), allocatable :: base_name      !! base run deck [-]
    character(len=:), allocatable :: base_text      !! base run deck text [-]
    character(len=:), allocatable :: list_name      !! case list ('' if none) [-]
    character(len=:), allocatable :: list_text      !! case list text [-]
    character(len=:), allocatable :: git_revision   !! git revision of the code that ran the cases [-]
    integer :: n_cases = 0                          !! cases of the campaign [-]
    integer :: n_par = 0                            !! varied inputs [-]
    integer :: n_gears = 0                          !! gears [-]
    character(len=128), allocatable :: par_name(:)  !! input names [-]
    character(len=64), allocatable :: par_label(:)  !! column names [-]
    character(len=16), allocatable :: par_units(:)  !! deck units [-]
    character(len=256), allocatable :: par_desc(:)  !! how each input is varied [-]
    type(criteria_t) :: crit                        !! success criteria [-]
  end type summary_meta_t

  !> The rows of a campaign, indexed by case id.
  type :: results_t
    integer :: n_cases = 0                       !! cases of the campaign [-]
    integer :: n_have = 0                        !! rows present [-]
    logical, allocatable :: have(:)              !! (n_cases) row present [-]
    type(case_row_t), allocatable :: rows(:)     !! (n_cases) rows [-]
  end type results_t

contains

  !> An empty table for n_cases cases.
  subroutine results_init(res, n_cases)
    type(results_t), intent(out) :: res   !! table [-]
    integer, intent(in) :: n_cases        !! cases [-]
    res%n_cases = n_cases
    allocate (res%have(n_cases), res%rows(n_cases))
    res%have = .false.
    res%n_have = 0
  end subroutine results_init

  !> Put a row into the table (replacing a row of the same case). Rows with ids outside
  !! 1..n_cases are ignored (added = .false.).
  subroutine results_add(res, row, added)
    type(results_t), intent(inout) :: res        !! table [-]
    type(case_row_t), intent(in) :: row          !! row [-]
    logical, intent(out), optional :: added      !! the row was stored [-]
    if (present(added)) added = .false.
    if (row%case_id < 1 .or. row%case_id > res%n_cases) return
    if (.not. res%have(row%case_id)) res%n_have = res%n_have + 1
    res%have(row%case_id) = .true.
    res%rows(row%case_id) = row
    if (present(added)) added = .true.
  end subroutine results_add

  !> The rows present, in case-id order.
  function results_rows(res) result(rows)
    type(results_t), intent(in) :: res            !! table [-]
    type(case_row_t), allocatable :: rows(:)      !! rows [-]
    integer :: i, k
    allocate (rows(res%n_have))
    k = 0
    do i = 1, res%n_cases
      if (.not. res%have(i)) cycle
      k = k + 1
      rows(k) = res%rows(i)
    end do
  end function results_rows

  !> The rows present, in case-id order, taken from the table: moved without a copy when every
  !! case has its row (the table's rows are gone afterwards; n_have and the flags stay).
  subroutine results_take_rows(res, rows)
    type(results_t), intent(inout) :: res                  !! table [-]
    type(case_row_t), allocatable, intent(out) :: rows(:)  !! rows [-]
    if (res%n_have == res%n_cases) then
      call move_alloc(res%rows, rows)
    else
      rows = results_rows(res)
    end if
  end subroutine results_take_rows

  !> Ids of the cases without a row.
  subroutine results_missing(res, ids)
    type(results_t), intent(in) :: res                !! table [-]
    integer, allocatable, intent(out) :: ids(:)       !! missing case ids, ascending [-]
    integer :: i, k
    allocate (ids(res%n_cases - res%n_have))
    k = 0
    do i = 1, res%n_cases
      if (res%have(i)) cycle
      k = k + 1
      ids(k) = i
    end do
  end subroutine results_missing

  !> The meta data of a campaign.
  function meta_from_campaign(camp) result(meta)
    type(campaign_t), intent(in) :: camp  !! campaign [-]
    type(summary_meta_t) :: meta          !! meta data [-]
    integer :: j
    character(len=24) :: buf
    meta%title = camp%title
    meta%mode = trim(camp%mode)
    write (buf, '(i0)') camp%seed
    meta%seed = trim(buf)
    meta%fingerprint = camp%fingerprint
    meta%deck_name = camp%deck_name
    meta%deck_text = camp%deck_text
    meta%base_name = camp%base_path
    meta%base_text = camp%base_text
    meta%list_name = ''
    meta%list_text = ''
    if (camp%mode == 'list') then
      meta%list_name = camp%list_path
      meta%list_text = camp%list_text
    end if
    meta%git_revision = landyn_git_revision
    meta%n_cases = camp%n_cases
    meta%n_par = camp%n_par
    meta%n_gears = camp%n_gears
    allocate (meta%par_name(camp%n_par), meta%par_label(camp%n_par), meta%par_units(camp%n_par), &
              meta%par_desc(camp%n_par))
    do j = 1, camp%n_par
      meta%par_name(j) = camp%par(j)%name
      meta%par_label(j) = camp%par(j)%label
      meta%par_units(j) = camp%par(j)%units
      meta%par_desc(j) = param_description(camp%par(j))
    end do
    meta%crit = camp%crit
  end function meta_from_campaign

  ! ================================================================ probability

  !> Wilson score interval of k successes in n trials at normal quantile z; [0, 1] when n = 0.
  pure subroutine wilson_interval(k, n, z, lo, hi)
    integer, intent(in) :: k      !! successes [-]
    integer, intent(in) :: n      !! trials [-]
    real(wp), intent(in) :: z     !! normal quantile (1.96 for 95 %) [-]
    real(wp), intent(out) :: lo   !! lower bound [-]
    real(wp), intent(out) :: hi   !! upper bound [-]
    real(wp) :: p, den, centre, half, rn
    if (n <= 0) then
      lo = 0.0_wp
      hi = 1.0_wp
      return
    end if
    rn = real(n, wp)
    p = real(k, wp)/rn
    den = 1.0_wp + z**2/rn
    centre = (p + z**2/(2.0_wp*rn))/den
    half = z/den*sqrt(p*(1.0_wp - p)/rn + z**2/(4.0_wp*rn**2))
    lo = max(0.0_wp, centre - half)
    hi = min(1.0_wp, centre + half)
    if (k == 0) lo = 0.0_wp
    if (k == n) hi = 1.0_wp
  end subroutine wilson_interval

  !> Probability of a successful landing over `rows` with its 95 % Wilson interval. Cases
  !! whose run failed count as unsuccessful, or are left out when failed_runs = 'exclude' (a case
  !! that never touched down is a result: counted, a failure). Inconclusive cases (still moving at
  !! their end time, no other criterion failed) count as failures in p; `n_inconclusive` of them
  !! bound P from above: (n_success + n_inconclusive) / n_eval.
  subroutine success_probability(rows, failed_runs, n_eval, n_success, n_excluded, p, lo, hi, n_inconclusive)
    type(case_row_t), intent(in) :: rows(:)       !! rows [-]
    character(len=*), intent(in) :: failed_runs   !! 'count_as_failure' or 'exclude' [-]
    integer, intent(out) :: n_eval                !! cases counted [-]
    integer, intent(out) :: n_success             !! successful cases [-]
    integer, intent(out) :: n_excluded            !! failed runs left out [-]
    real(wp), intent(out) :: p                    !! n_success / n_eval (0 when n_eval = 0) [-]
    real(wp), intent(out) :: lo, hi               !! 95 % Wilson score interval [-]
    integer, intent(out), optional :: n_inconclusive  !! counted cases that are inconclusive [-]
    integer :: i, n_inc
    n_inc = 0
    n_eval = 0
    n_success = 0
    n_excluded = 0
    do i = 1, size(rows)
      if (rows(i)%status /= status_ok .and. rows(i)%status /= status_no_touchdown .and. &
          trim(failed_runs) == 'exclude') then
        n_excluded = n_excluded + 1
        cycle
      end if
      n_eval = n_eval + 1
      if (rows(i)%success == 1) n_success = n_success + 1
      if (inconclusive(rows(i))) n_inc = n_inc + 1
    end do
    if (present(n_inconclusive)) n_inconclusive = n_inc
    p = 0.0_wp
    if (n_eval > 0) p = real(n_success, wp)/real(n_eval, wp)
    call wilson_interval(n_success, n_eval, z95, lo, hi)
  end subroutine success_probability

  ! ================================================================ summary file

  !> Write the summary file `path` (via `path`.partial and a rename) with `rows` (sorted by case id).
  subroutine write_summary(path, meta, rows, command_line, status)
    character(len=*), intent(in) :: path          !! summary file [-]
    type(summary_meta_t), intent(in) :: meta      !! campaign meta data [-]
    type(case_row_t), intent(in) :: rows(:)       !! rows in case-id order [-]
    character(len=*), intent(in) :: command_line  !! command that wrote the file [-]
    type(status_t), intent(out) :: status         !! STAT_OK, or the failure with its message [-]
    type(h5_file_t) :: f
    call h5_create_partial(f, path, status)
    if (.not. status%ok()) return
    call write_contents(f, meta, rows, command_line, status)
    call h5_commit_partial(f, path, status)
  end subroutine write_summary

  !> The contents of a summary file: attributes, /meta, /campaign, /parameters, /criteria, /cases, /probability.
  subroutine write_contents(f, meta, rows, command_line, status)
    type(h5_file_t), intent(inout) :: f           !! open file [-]
    type(summary_meta_t), intent(in) :: meta      !! meta data [-]
    type(case_row_t), intent(in) :: rows(:)       !! rows [-]
    character(len=*), intent(in) :: command_line  !! command line [-]
    type(status_t), intent(out) :: status         !! STAT_OK, or the failure with its message [-]
    integer :: n, n_eval, n_succ, n_excl, n_inc, complete
    real(wp) :: p, lo, hi

    n = size(rows)
    complete = 0
    if (n == meta%n_cases) then
      if (n == 0) then
        complete = 1
      else if (rows(1)%case_id == 1 .and. rows(n)%case_id == n) then
        complete = 1
      end if
    end if
    call success_probability(rows, meta%crit%failed_runs, n_eval, n_succ, n_excl, p, lo, hi, n_inc)

    ! ---- root attributes
    call h5_write_attr(f, '/', 'schema_version', schema_version, status); if (.not. status%ok()) return
    call h5_write_attr(f, '/', 'title', nonempty(meta%title), status); if (.not. status%ok()) return
    call h5_write_attr(f, '/', 'mode', meta%mode, status); if (.not. status%ok()) return
    call h5_write_attr(f, '/', 'fingerprint', meta%fingerprint, status); if (.not. status%ok()) return
    call h5_write_attr(f, '/', 'n_cases', int(meta%n_cases, ip), status); if (.not. status%ok()) return
    call h5_write_attr(f, '/', 'n_rows', int(n, ip), status); if (.not. status%ok()) return
    call h5_write_attr(f, '/', 'complete', int(complete, ip), status); if (.not. status%ok()) return
    call h5_write_attr(f, '/', 'p_success', p, status); if (.not. status%ok()) return
    call h5_write_attr(f, '/', 'p_success_ci95_low', lo, status); if (.not. status%ok()) return
    call h5_write_attr(f, '/', 'p_success_ci95_high', hi, status); if (.not. status%ok()) return

    ! ---- root attribute producer, /meta
    call write_meta(f, 'landyn_batch', command_line, status, run_git_revision=meta%git_revision)
    if (.not. status%ok()) return

    call write_campaign_group(f, meta, status); if (.not. status%ok()) return
    call write_criteria_group(f, meta%crit, status); if (.not. status%ok()) return
    call write_case_inputs(f, meta, rows, status); if (.not. status%ok()) return
    call write_case_results(f, meta, rows, status); if (.not. status%ok()) return
    call write_probability_group(f, rows, n_eval, n_succ, n_excl, n_inc, p, lo, hi, status)
  end subroutine write_contents

  !> /campaign (the decks and how the cases are made) and /parameters (the varied inputs) of a summary file.
  subroutine write_campaign_group(f, meta, status)
    type(h5_file_t), intent(inout) :: f           !! open file [-]
    type(summary_meta_t), intent(in) :: meta      !! meta data [-]
    type(status_t), intent(out) :: status         !! STAT_OK, or the failure with its message [-]
    ! ---- /campaign
    call h5_write(f, '/campaign/deck_name', nonempty(meta%deck_name), '-', status); if (.not. status%ok()) return
    call h5_write(f, '/campaign/deck_text', nonempty(meta%deck_text), '-', status, &
                  description='the campaign deck as given'); if (.not. status%ok()) return
    call h5_write(f, '/campaign/base_deck_name', nonempty(meta%base_name), '-', status); if (.not. status%ok()) return
    call h5_write(f, '/campaign/base_deck_text', nonempty(meta%base_text), '-', status, &
                  description='the base run deck every case starts from'); if (.not. status%ok()) return
    call h5_write(f, '/campaign/list_file_name', nonempty(meta%list_name), '-', status); if (.not. status%ok()) return
    call h5_write(f, '/campaign/list_file_text', nonempty(meta%list_text), '-', status); if (.not. status%ok()) return
    call h5_write(f, '/campaign/mode', meta%mode, '-', status); if (.not. status%ok()) return
    call h5_write(f, '/campaign/seed', meta%seed, '-', status, &
                  description='Monte Carlo seed (64-bit integer as text)'); if (.not. status%ok()) return
    call h5_write(f, '/campaign/n_cases', int(meta%n_cases, ip), '-', status); if (.not. status%ok()) return
    call h5_write(f, '/campaign/n_gears', int(meta%n_gears, ip), '-', status); if (.not. status%ok()) return
    call h5_write(f, '/campaign/fingerprint', meta%fingerprint, '-', status, &
                  description='64-bit hash of everything that defines the cases and their success'); if (.not. status%ok()) return

    ! ---- /parameters
    call h5_write(f, '/parameters/name', meta%par_name, '-', status, &
                  description='varied inputs as group%variable(subscript)'); if (.not. status%ok()) return
    call h5_write(f, '/parameters/label', meta%par_label, '-', status, &
                  description='dataset name of each input under /cases/inputs'); if (.not. status%ok()) return
    call h5_write(f, '/parameters/units', meta%par_units, '-', status, &
                  description='deck units (angles in degrees)'); if (.not. status%ok()) return
    call h5_write(f, '/parameters/description', meta%par_desc, '-', status); if (.not. status%ok()) return

  end subroutine write_campaign_group

  !> /criteria of a summary file: the success criteria and whether each is applied.
  subroutine write_criteria_group(f, c, status)
    type(h5_file_t), intent(inout) :: f           !! open file [-]
    type(criteria_t), intent(in) :: c             !! success criteria [-]
    type(status_t), intent(out) :: status         !! STAT_OK, or the failure with its message [-]
    call h5_write(f, '/criteria/min_stroke_margin', c%min_stroke_margin, 'm', status, &
                  description='every stroke margin must be >= this'); if (.not. status%ok()) return
    call h5_write(f, '/criteria/max_overload_applied', merge(1_ip, 0_ip, c%overload_applied), '-', status)
    if (.not. status%ok()) return
    call h5_write(f, '/criteria/max_overload', c%max_overload, 'g', status, &
                  description='peak overload must be <= this (when applied)'); if (.not. status%ok()) return
    call h5_write(f, '/criteria/min_tipover_margin_applied', merge(1_ip, 0_ip, c%tipover_applied), '-', status)
    if (.not. status%ok()) return
    call h5_write(f, '/criteria/min_tipover_margin', c%min_tipover_margin, 'deg', status, &
                  description='final tip-over margin must be >= this (when applied)'); if (.not. status%ok()) return
    call h5_write(f, '/criteria/max_friction_ratio_applied', merge(1_ip, 0_ip, c%friction_applied), '-', status)
    if (.not. status%ok()) return
    call h5_write(f, '/criteria/max_friction_ratio', c%max_friction_ratio, '-', status, &
                  description='every final |F_t|/(mu_s F_n) must be <= this (when applied)'); if (.not. status%ok()) return
    call h5_write(f, '/criteria/min_body_clearance_applied', merge(1_ip, 0_ip, c%clearance_applied), '-', &
                  status); if (.not. status%ok()) return
    call h5_write(f, '/criteria/min_body_clearance', c%min_body_clearance, 'm', status, &
                  description='body-point clearance must stay >= this (when applied)'); if (.not. status%ok()) return
    call h5_write(f, '/criteria/body_points', c%body_point(:, 1:c%n_body_points), 'm', status, &
                  description='lander-frame points whose clearance is reported, shape (n, 3)'); if (.not. status%ok()) return
    call h5_write(f, '/criteria/require_at_rest', merge(1_ip, 0_ip, c%require_at_rest), '-', status)
    if (.not. status%ok()) return
    call h5_write(f, '/criteria/failed_runs', trim(c%failed_runs), '-', status, &
                  description='how cases without a result enter the probability'); if (.not. status%ok()) return
  end subroutine write_criteria_group

  !> /cases, first part: each row's identity, status, outcome, messages and inputs.
  subroutine write_case_inputs(f, meta, rows, status)
    type(h5_file_t), intent(inout) :: f           !! open file [-]
    type(summary_meta_t), intent(in) :: meta      !! meta data [-]
    type(case_row_t), intent(in) :: rows(:)       !! rows [-]
    type(status_t), intent(out) :: status         !! STAT_OK, or the failure with its message [-]
    integer :: n, i, j

    n = size(rows)
    call h5_write(f, '/cases/case_id', [(int(rows(i)%case_id, ip), i=1, n)], '-', status); if (.not. status%ok()) return
    call h5_write(f, '/cases/status', [(int(rows(i)%status, ip), i=1, n)], '-', status, &
      description='as landyn exit codes: 0 ran to its end (the outcome says how), 2 invalid input, 3 simulation '// &
                  'failed, 6 run-health check failed, 7 no touchdown'); if (.not. status%ok()) return
    call h5_write(f, '/cases/outcome', [(int(rows(i)%outcome, ip), i=1, n)], '-', status, &
      description='0 none (no result), 1 no_touchdown, 2 at_rest, 3 still_moving (inconclusive), 4 tipped_over')
    if (.not. status%ok()) return
    call h5_write(f, '/cases/tipover_margin', [(rows(i)%tipover_margin, i=1, n)], 'deg', status, &
      description='tip-over margin of the final state (docs/output.md, Outcome)'); if (.not. status%ok()) return
    call h5_write(f, '/cases/max_friction_ratio', [(rows(i)%max_friction_ratio, i=1, n)], '-', status, &
      description='largest footpad |F_t|/(mu_s F_n) of the final state'); if (.not. status%ok()) return
    call h5_write(f, '/cases/error_message', text_column(rows, 1), '-', status); if (.not. status%ok()) return
    call h5_write(f, '/cases/end_reason', text_column(rows, 2), '-', status); if (.not. status%ok()) return
    call h5_write(f, '/cases/history_file', text_column(rows, 3), '-', status, &
                  description='time-history file of the case, empty when none'); if (.not. status%ok()) return
    do j = 1, meta%n_par
      call h5_write(f, '/cases/inputs/'//trim(meta%par_label(j)), [(rows(i)%inputs(j), i=1, n)], &
                    trim(meta%par_units(j)), status, description=trim(meta%par_desc(j)))
      if (.not. status%ok()) return
    end do
  end subroutine write_case_inputs

  !> /cases, second part: each row's results (crush, margins, loads, motion, timing) and its verdict
  !! (flags, success, failed criteria).
  subroutine write_case_results(f, meta, rows, status)
    type(h5_file_t), intent(inout) :: f           !! open file [-]
    type(summary_meta_t), intent(in) :: meta      !! meta data [-]
    type(case_row_t), intent(in) :: rows(:)       !! rows [-]
    type(status_t), intent(out) :: status         !! STAT_OK, or the failure with its message [-]
    real(wp), allocatable :: a3(:, :, :)
    integer :: n, i

    n = size(rows)
    allocate (a3(3, meta%n_gears, n))
    do i = 1, n
      a3(:, :, i) = rows(i)%crush
    end do
    call h5_write(f, '/cases/crush_length', a3, 'm', status, &
      description='signed net crush, shape (n, n_gears, 3): primary, secondary left, secondary right')
    if (.not. status%ok()) return
    do i = 1, n
      a3(:, :, i) = rows(i)%margin
    end do
    call h5_write(f, '/cases/stroke_margin', a3, 'm', status, &
      description='stroke capacity minus crushed length, worst direction, shape (n, n_gears, 3)'); if (.not. status%ok()) return
    call h5_write(f, '/cases/min_stroke_margin', [(rows(i)%min_margin, i=1, n)], 'm', status); if (.not. status%ok()) return
    call h5_write(f, '/cases/peak_overload', [(rows(i)%peak_overload, i=1, n)], 'g', status); if (.not. status%ok()) return
    call h5_write(f, '/cases/peak_penetration', [(rows(i)%peak_penetration, i=1, n)], 'm', status, &
                  description='largest footpad penetration'); if (.not. status%ok()) return
    call h5_write(f, '/cases/max_slide_distance', [(rows(i)%max_slide, i=1, n)], 'm', status, &
                  description='largest footpad slide distance'); if (.not. status%ok()) return
    call h5_write(f, '/cases/final_tilt', [(rows(i)%final_tilt, i=1, n)], 'deg', status); if (.not. status%ok()) return
    call h5_write(f, '/cases/max_tilt', [(rows(i)%max_tilt, i=1, n)], 'deg', status); if (.not. status%ok()) return
    call h5_write(f, '/cases/min_body_clearance', [(rows(i)%min_clearance, i=1, n)], 'm', status, &
      description='smallest height of the body points above the terrain planes, at the output samples')
    if (.not. status%ok()) return
    call h5_write(f, '/cases/final_time', [(rows(i)%final_time, i=1, n)], 's', status); if (.not. status%ok()) return
    call h5_write(f, '/cases/n_steps', [(int(rows(i)%n_steps, ip), i=1, n)], '-', status); if (.not. status%ok()) return
    call h5_write(f, '/cases/wall_time', [(rows(i)%wall_time, i=1, n)], 's', status, &
                  description='wall-clock time of the case (input, run, history file)'); if (.not. status%ok()) return
    call h5_write(f, '/cases/tipped_over', [(int(rows(i)%tipped_over, ip), i=1, n)], '-', status)
    if (.not. status%ok()) return
    call h5_write(f, '/cases/at_rest', [(int(rows(i)%at_rest, ip), i=1, n)], '-', status); if (.not. status%ok()) return
    call h5_write(f, '/cases/bottomed_out', [(int(rows(i)%bottomed_out, ip), i=1, n)], '-', status)
    if (.not. status%ok()) return
    call h5_write(f, '/cases/success', [(int(rows(i)%success, ip), i=1, n)], '-', status, &
                  description='1 when every criterion of /criteria holds'); if (.not. status%ok()) return
    call h5_write(f, '/cases/failed_criteria', [(int(rows(i)%failed_criteria, ip), i=1, n)], '-', status, &
      description='bits: 1 tipped over, 2 stroke margin, 4 overload, 8 body clearance, 16 not at rest, 32 no result, '// &
                  '64 no touchdown, 128 tip-over margin, 256 friction ratio')
    if (.not. status%ok()) return
    call h5_write(f, '/cases/failed_criteria_names', text_column(rows, 4), '-', status, &
      description='the criteria the case failed, comma-separated (names of /probability/failure_criterion)')
    if (.not. status%ok()) return
  end subroutine write_case_results

  !> /probability of a summary file: the success probability of the rows, its Wilson interval and the
  !! failures per criterion (from success_probability and failure_counts).
  subroutine write_probability_group(f, rows, n_eval, n_succ, n_excl, n_inc, p, lo, hi, status)
    type(h5_file_t), intent(inout) :: f           !! open file [-]
    type(case_row_t), intent(in) :: rows(:)       !! rows [-]
    integer, intent(in) :: n_eval                 !! cases counted in the probability [-]
    integer, intent(in) :: n_succ                 !! successful cases among them [-]
    integer, intent(in) :: n_excl                 !! failed runs left out [-]
    integer, intent(in) :: n_inc                  !! inconclusive cases among the evaluated [-]
    real(wp), intent(in) :: p                     !! success probability [-]
    real(wp), intent(in) :: lo                    !! lower end of its 95 % interval [-]
    real(wp), intent(in) :: hi                    !! upper end of its 95 % interval [-]
    type(status_t), intent(out) :: status         !! STAT_OK, or the failure with its message [-]
    call h5_write(f, '/probability/n_evaluated', int(n_eval, ip), '-', status, &
                  description='cases counted in the probability'); if (.not. status%ok()) return
    call h5_write(f, '/probability/n_success', int(n_succ, ip), '-', status); if (.not. status%ok()) return
    call h5_write(f, '/probability/n_excluded', int(n_excl, ip), '-', status, &
                  description="failed runs left out (failed_runs = 'exclude')"); if (.not. status%ok()) return
    call h5_write(f, '/probability/p_success', p, '-', status, &
                  description='n_success / n_evaluated (0 when nothing was evaluated); inconclusive cases count as '// &
                  'failures'); if (.not. status%ok()) return
    call h5_write(f, '/probability/n_inconclusive', int(n_inc, ip), '-', status, &
                  description='evaluated cases still moving at their end time with no other criterion failed')
    if (.not. status%ok()) return
    call h5_write(f, '/probability/p_success_upper', merge(real(n_succ + n_inc, wp)/real(max(n_eval, 1), wp), 0.0_wp, &
                  n_eval > 0), '-', status, &
                  description='(n_success + n_inconclusive) / n_evaluated: P if every inconclusive case succeeded')
    if (.not. status%ok()) return
    call h5_write(f, '/probability/ci95_low', lo, '-', status); if (.not. status%ok()) return
    call h5_write(f, '/probability/ci95_high', hi, '-', status); if (.not. status%ok()) return
    call h5_write(f, '/probability/confidence', 0.95_wp, '-', status); if (.not. status%ok()) return
    call h5_write(f, '/probability/method', 'Wilson score interval, z = 1.959963984540054', '-', status)
    if (.not. status%ok()) return
    call h5_write(f, '/probability/failure_criterion', criterion_name, '-', status, &
                  description='criteria in the order of failure_count (bits 1, 2, ..., 256 of failed_criteria)')
    if (.not. status%ok()) return
    call h5_write(f, '/probability/failure_count', int(failure_counts(rows), ip), '-', status, &
                  description='cases failing each criterion (a case may fail several)')
  end subroutine write_probability_group

  !> A text column of the rows as a fixed-length string array.
  function text_column(rows, which) result(col)
    type(case_row_t), intent(in) :: rows(:)      !! rows [-]
    integer, intent(in) :: which                 !! 1 message, 2 end reason, 3 history file, 4 failed criteria [-]
    character(len=:), allocatable :: col(:)      !! column [-]
    integer :: k, l, n
    n = size(rows)
    l = 1
    do k = 1, n
      select case (which)
      case (1)
        l = max(l, len(rows(k)%message))
      case (2)
        l = max(l, len(rows(k)%end_reason))
      case (3)
        l = max(l, len(rows(k)%history_file))
      case default
        l = max(l, len(failed_criteria_names(rows(k)%failed_criteria)))
      end select
    end do
    allocate (character(len=l) :: col(n))
    do k = 1, n
      select case (which)
      case (1)
        col(k) = rows(k)%message
      case (2)
        col(k) = rows(k)%end_reason
      case (3)
        col(k) = rows(k)%history_file
      case default
        col(k) = failed_criteria_names(rows(k)%failed_criteria)
      end select
    end do
  end function text_column

  !> '' for the '(none)' that nonempty stores for blank text, else `s`.
  pure function from_nonempty(s) result(r)
    character(len=*), intent(in) :: s    !! stored text [-]
    character(len=:), allocatable :: r   !! '' for '(none)' [-]
    if (s == '(none)') then
      r = ''
    else
      r = s
    end if
  end function from_nonempty

  !> Read a summary file written by write_summary: its meta data and rows (in file order).
  subroutine read_summary(path, meta, rows, status)
    character(len=*), intent(in) :: path                 !! summary file [-]
    type(summary_meta_t), intent(out) :: meta            !! meta data [-]
    type(case_row_t), allocatable, intent(out) :: rows(:)  !! rows [-]
    type(status_t), intent(out) :: status                !! STAT_OK, or the failure with its message [-]
    type(h5_file_t) :: f
    type(status_t) :: st2
    call h5_open_read(f, path, status)
    if (.not. status%ok()) return
    call read_contents(f, meta, rows, status)
    call h5_close(f, st2)
  end subroutine read_summary

  !> Meta data and rows of an open summary file.
  subroutine read_contents(f, meta, rows, status)
    type(h5_file_t), intent(in) :: f                     !! open file [-]
    type(summary_meta_t), intent(out) :: meta            !! meta data [-]
    type(case_row_t), allocatable, intent(out) :: rows(:)  !! rows [-]
    type(status_t), intent(out) :: status                !! STAT_OK, or the failure with its message [-]
    character(len=:), allocatable :: schema

    call h5_read_attr(f, '/', 'schema_version', schema, status); if (.not. status%ok()) return
    if (schema /= schema_version) then
      call status%fail(STAT_FAILED, trim(f%path)//': not a LANDYN campaign summary of schema '//schema_version// &
                       ' (schema '//schema//')')
      return
    end if
    call read_campaign_group(f, meta, status); if (.not. status%ok()) return
    call read_parameters_group(f, meta, status); if (.not. status%ok()) return
    call read_criteria_group(f, meta%crit, status); if (.not. status%ok()) return
    call read_case_flags(f, meta, rows, status); if (.not. status%ok()) return
    call read_case_texts(f, rows, status); if (.not. status%ok()) return
    call read_case_numbers(f, meta, rows, status)
  end subroutine read_contents

  !> The root title, /campaign and /meta/git_revision of a summary file into `meta`.
  subroutine read_campaign_group(f, meta, status)
    type(h5_file_t), intent(in) :: f                     !! open file [-]
    type(summary_meta_t), intent(inout) :: meta          !! meta data [-]
    type(status_t), intent(out) :: status                !! STAT_OK, or the failure with its message [-]
    character(len=:), allocatable :: s
    integer(ip) :: ival

    call h5_read_attr(f, '/', 'title', s, status); if (.not. status%ok()) return
    meta%title = from_nonempty(s)
    call h5_read(f, '/campaign/mode', meta%mode, status); if (.not. status%ok()) return
    call h5_read(f, '/campaign/seed', meta%seed, status); if (.not. status%ok()) return
    call h5_read(f, '/campaign/fingerprint', meta%fingerprint, status); if (.not. status%ok()) return
    call h5_read(f, '/campaign/deck_name', s, status); if (.not. status%ok()) return
    meta%deck_name = from_nonempty(s)
    call h5_read(f, '/campaign/deck_text', s, status); if (.not. status%ok()) return
    meta%deck_text = from_nonempty(s)
    call h5_read(f, '/campaign/base_deck_name', s, status); if (.not. status%ok()) return
    meta%base_name = from_nonempty(s)
    call h5_read(f, '/campaign/base_deck_text', s, status); if (.not. status%ok()) return
    meta%base_text = from_nonempty(s)
    call h5_read(f, '/campaign/list_file_name', s, status); if (.not. status%ok()) return
    meta%list_name = from_nonempty(s)
    call h5_read(f, '/campaign/list_file_text', s, status); if (.not. status%ok()) return
    meta%list_text = from_nonempty(s)
    call h5_read(f, '/meta/git_revision', meta%git_revision, status); if (.not. status%ok()) return
    call h5_read(f, '/campaign/n_cases', ival, status); if (.not. status%ok()) return
    meta%n_cases = ival
    call h5_read(f, '/campaign/n_gears', ival, status); if (.not. status%ok()) return
    meta%n_gears = ival
  end subroutine read_campaign_group

  !> /parameters of a summary file into `meta` (n_par and the columns, which must agree in length).
  subroutine read_parameters_group(f, meta, status)
    type(h5_file_t), intent(in) :: f                     !! open file [-]
    type(summary_meta_t), intent(inout) :: meta          !! meta data [-]
    type(status_t), intent(out) :: status                !! STAT_OK, or the failure with its message [-]
    character(len=128), allocatable :: names(:)

    call h5_read(f, '/parameters/name', names, status); if (.not. status%ok()) return
    meta%n_par = size(names)
    meta%par_name = names
    deallocate (names)
    call h5_read(f, '/parameters/label', meta%par_label, status); if (.not. status%ok()) return
    call h5_read(f, '/parameters/units', meta%par_units, status); if (.not. status%ok()) return
    call h5_read(f, '/parameters/description', meta%par_desc, status); if (.not. status%ok()) return
    if (size(meta%par_label) /= meta%n_par .or. size(meta%par_units) /= meta%n_par .or. &
        size(meta%par_desc) /= meta%n_par) then
      call status%fail(STAT_FAILED, trim(f%path)//': /parameters/* have different lengths')
      return
    end if
  end subroutine read_parameters_group

  !> /criteria of a summary file.
  subroutine read_criteria_group(f, c, status)
    type(h5_file_t), intent(in) :: f                     !! open file [-]
    type(criteria_t), intent(inout) :: c                 !! success criteria [-]
    type(status_t), intent(out) :: status                !! STAT_OK, or the failure with its message [-]
    character(len=:), allocatable :: s
    integer(ip) :: ival
    real(wp), allocatable :: bp(:, :)

    call h5_read(f, '/criteria/min_stroke_margin', c%min_stroke_margin, status); if (.not. status%ok()) return
    call read_applied(f, 'max_overload', c%overload_applied, c%max_overload, status); if (.not. status%ok()) return
    call read_applied(f, 'min_tipover_margin', c%tipover_applied, c%min_tipover_margin, status)
    if (.not. status%ok()) return
    call read_applied(f, 'max_friction_ratio', c%friction_applied, c%max_friction_ratio, status)
    if (.not. status%ok()) return
    call read_applied(f, 'min_body_clearance', c%clearance_applied, c%min_body_clearance, status)
    if (.not. status%ok()) return
    call h5_read(f, '/criteria/body_points', bp, status); if (.not. status%ok()) return
    c%n_body_points = min(size(bp, 2), max_body_points)
    c%body_point(:, 1:c%n_body_points) = bp(:, 1:c%n_body_points)
    call h5_read(f, '/criteria/require_at_rest', ival, status); if (.not. status%ok()) return
    c%require_at_rest = ival /= 0
    call h5_read(f, '/criteria/failed_runs', s, status); if (.not. status%ok()) return
    c%failed_runs = s
  end subroutine read_criteria_group

  !> A criterion applied only when given: /criteria/<name>_applied and /criteria/<name>.
  subroutine read_applied(f, name, applied, x, status)
    type(h5_file_t), intent(in) :: f                     !! open file [-]
    character(len=*), intent(in) :: name                 !! the criterion's dataset name [-]
    logical, intent(inout) :: applied                    !! the criterion is applied [-]
    real(wp), intent(inout) :: x                         !! its limit [unit of the criterion]
    type(status_t), intent(out) :: status                !! STAT_OK, or the failure with its message [-]
    integer(ip) :: ival
    call h5_read(f, '/criteria/'//name//'_applied', ival, status)
    if (.not. status%ok()) return
    applied = ival /= 0
    call h5_read(f, '/criteria/'//name, x, status)
  end subroutine read_applied

  !> The rows of a summary file, allocated from /cases/case_id, with their integer columns (status,
  !! flags, failed criteria, steps, outcome).
  subroutine read_case_flags(f, meta, rows, status)
    type(h5_file_t), intent(in) :: f                     !! open file [-]
    type(summary_meta_t), intent(in) :: meta             !! meta data [-]
    type(case_row_t), allocatable, intent(out) :: rows(:)  !! rows [-]
    type(status_t), intent(out) :: status                !! STAT_OK, or the failure with its message [-]
    integer(ip), allocatable :: iv(:)
    integer :: n, i

    call h5_read(f, '/cases/case_id', iv, status); if (.not. status%ok()) return
    n = size(iv)
    allocate (rows(n))
    do i = 1, n
      rows(i)%case_id = iv(i)
      allocate (rows(i)%inputs(meta%n_par), rows(i)%crush(3, meta%n_gears), rows(i)%margin(3, meta%n_gears))
    end do
    call int_column(f, '/cases/status', n, iv, status); if (.not. status%ok()) return
    rows%status = iv
    call int_column(f, '/cases/success', n, iv, status); if (.not. status%ok()) return
    rows%success = iv
    call int_column(f, '/cases/tipped_over', n, iv, status); if (.not. status%ok()) return
    rows%tipped_over = iv
    call int_column(f, '/cases/at_rest', n, iv, status); if (.not. status%ok()) return
    rows%at_rest = iv
    call int_column(f, '/cases/bottomed_out', n, iv, status); if (.not. status%ok()) return
    rows%bottomed_out = iv
    call int_column(f, '/cases/failed_criteria', n, iv, status); if (.not. status%ok()) return
    rows%failed_criteria = iv
    call int_column(f, '/cases/n_steps', n, iv, status); if (.not. status%ok()) return
    rows%n_steps = iv
    call int_column(f, '/cases/outcome', n, iv, status); if (.not. status%ok()) return
    rows%outcome = iv
  end subroutine read_case_flags

  !> The text columns of the rows of a summary file: message, end reason, history file.
  subroutine read_case_texts(f, rows, status)
    type(h5_file_t), intent(in) :: f                     !! open file [-]
    type(case_row_t), intent(inout) :: rows(:)           !! rows [-]
    type(status_t), intent(out) :: status                !! STAT_OK, or the failure with its message [-]
    character(len=text_len), allocatable :: sv(:)
    integer :: n, i

    n = size(rows)

    call h5_read(f, '/cases/error_message', sv, status); if (.not. status%ok()) return
    if (.not. sized(f, size(sv), n, '/cases/error_message', status)) return
    do i = 1, n
      rows(i)%message = trim(sv(i))
    end do
    call h5_read(f, '/cases/end_reason', sv, status); if (.not. status%ok()) return
    if (.not. sized(f, size(sv), n, '/cases/end_reason', status)) return
    do i = 1, n
      rows(i)%end_reason = trim(sv(i))
    end do
    call h5_read(f, '/cases/history_file', sv, status); if (.not. status%ok()) return
    if (.not. sized(f, size(sv), n, '/cases/history_file', status)) return
    do i = 1, n
      rows(i)%history_file = trim(sv(i))
    end do
  end subroutine read_case_texts

  !> The real columns of the rows of a summary file: inputs, crush and margins per strut, the
  !! results and the wall time.
  subroutine read_case_numbers(f, meta, rows, status)
    type(h5_file_t), intent(in) :: f                     !! open file [-]
    type(summary_meta_t), intent(in) :: meta             !! meta data [-]
    type(case_row_t), intent(inout) :: rows(:)           !! rows [-]
    type(status_t), intent(out) :: status                !! STAT_OK, or the failure with its message [-]
    real(wp), allocatable :: rv(:), a3(:, :, :)
    integer :: n, i, j, ng

    n = size(rows)
    ng = meta%n_gears

    do j = 1, meta%n_par
      call h5_read(f, '/cases/inputs/'//trim(meta%par_label(j)), rv, status); if (.not. status%ok()) return
      if (.not. sized(f, size(rv), n, '/cases/inputs/'//trim(meta%par_label(j)), status)) return
      do i = 1, n
        rows(i)%inputs(j) = rv(i)
      end do
    end do
    call h5_read(f, '/cases/crush_length', a3, status); if (.not. status%ok()) return
    if (.not. sized(f, size(a3), 3*ng*n, '/cases/crush_length', status)) return
    do i = 1, n
      rows(i)%crush = a3(:, :, i)
    end do
    call h5_read(f, '/cases/stroke_margin', a3, status); if (.not. status%ok()) return
    if (.not. sized(f, size(a3), 3*ng*n, '/cases/stroke_margin', status)) return
    do i = 1, n
      rows(i)%margin = a3(:, :, i)
    end do
    call real_column(f, '/cases/min_stroke_margin', n, rv, status); if (.not. status%ok()) return
    rows%min_margin = rv
    call real_column(f, '/cases/peak_overload', n, rv, status); if (.not. status%ok()) return
    rows%peak_overload = rv
    call real_column(f, '/cases/peak_penetration', n, rv, status); if (.not. status%ok()) return
    rows%peak_penetration = rv
    call real_column(f, '/cases/max_slide_distance', n, rv, status); if (.not. status%ok()) return
    rows%max_slide = rv
    call real_column(f, '/cases/final_tilt', n, rv, status); if (.not. status%ok()) return
    rows%final_tilt = rv
    call real_column(f, '/cases/max_tilt', n, rv, status); if (.not. status%ok()) return
    rows%max_tilt = rv
    call real_column(f, '/cases/min_body_clearance', n, rv, status); if (.not. status%ok()) return
    rows%min_clearance = rv
    call real_column(f, '/cases/final_time', n, rv, status); if (.not. status%ok()) return
    rows%final_time = rv
    call real_column(f, '/cases/tipover_margin', n, rv, status); if (.not. status%ok()) return
    rows%tipover_margin = rv
    call real_column(f, '/cases/max_friction_ratio', n, rv, status); if (.not. status%ok()) return
    rows%max_friction_ratio = rv
    call real_column(f, '/cases/wall_time', n, rv, status); if (.not. status%ok()) return
    rows%wall_time = rv
  end subroutine read_case_numbers

  !> True when a column of the summary file f has `expected` entries (found: m); else the status
  !! is set.
  logical function sized(f, m, expected, what, status)
    type(h5_file_t), intent(in) :: f                     !! open file [-]
    integer, intent(in) :: m                             !! size found [-]
    integer, intent(in) :: expected                      !! size expected [-]
    character(len=*), intent(in) :: what                 !! dataset [-]
    type(status_t), intent(inout) :: status              !! STAT_FAILED when not sized; the message on failure [-]
    sized = m == expected
    if (.not. sized) then
      call status%fail(STAT_FAILED, trim(f%path)//': '//what//' has '//int_text(m)//' entries; expected '//int_text(expected))
    end if
  end function sized

  !> iv = the integer column `path` of the summary file f, of n entries.
  subroutine int_column(f, path, n, iv, status)
    type(h5_file_t), intent(in) :: f                     !! open file [-]
    character(len=*), intent(in) :: path                 !! dataset [-]
    integer, intent(in) :: n                             !! entries expected (rows) [-]
    integer(ip), allocatable, intent(inout) :: iv(:)     !! the column [-]
    type(status_t), intent(out) :: status                !! STAT_OK, or the failure with its message [-]
    call h5_read(f, path, iv, status)
    if (status%ok()) then
      if (.not. sized(f, size(iv), n, path, status)) return
    end if
  end subroutine int_column

  !> rv = the real column `path` of the summary file f, of n entries.
  subroutine real_column(f, path, n, rv, status)
    type(h5_file_t), intent(in) :: f                     !! open file [-]
    character(len=*), intent(in) :: path                 !! dataset [-]
    integer, intent(in) :: n                             !! entries expected (rows) [-]
    real(wp), allocatable, intent(inout) :: rv(:)        !! the column [units of the dataset]
    type(status_t), intent(out) :: status                !! STAT_OK, or the failure with its message [-]
    call h5_read(f, path, rv, status)
    if (status%ok()) then
      if (.not. sized(f, size(rv), n, path, status)) return
    end if
  end subroutine real_column

end module landyn_campaign_store
