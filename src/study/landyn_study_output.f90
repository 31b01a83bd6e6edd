!> Output of a sensitivity study (landyn_study): the crush-length table as CSV and the study's
!! HDF5 file (docs/study.md), both written whole under <file>.partial and renamed.
!!
!! Library code: returns a status (status_t); nothing here stops or prints.
module landyn_study_output
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
  use landyn_kinds, only: wp, msg_len
  use landyn_strings, only: int_text, nonempty
  use landyn_status, only: status_t, STAT_OK, STAT_FILE
  use landyn_provenance, only: write_meta
  use landyn_h5, only: h5_file_t, h5_create_partial, h5_commit_partial, h5_write, h5_write_attr, rename_file, delete_file
  use landyn_study, only: study_t, label_len, set_len, strut_names, status_ok, group_name
  implicit none
  private

  public :: write_study_csv, write_study_h5, table_value

contains

  ! ================================================================ writing

  !> Crush length of table row m for variant v [m]: NaN when that run did not complete, or when
  !! the variant's lander has no such gear (a variant may change gears%n_gears; the rows follow
  !! the first variant's landers).
  pure function table_value(study, m, v) result(x)
    type(study_t), intent(in) :: study  !! study with results
    integer, intent(in) :: m            !! table row [-]
    integer, intent(in) :: v            !! variant [-]
    real(wp) :: x                       !! crush length [m]
    logical :: has_gear
    associate (r => study%run(study%measure(1, m), v))
      has_gear = .false.
      if (allocated(r%crush)) has_gear = study%measure(2, m) <= min(r%n_gears, size(r%crush, 2)) .and. &
                                         study%measure(3, m) <= size(r%crush, 1)
      if (r%status == status_ok .and. has_gear) then
        x = r%crush(study%measure(3, m), study%measure(2, m))
      else
        x = ieee_value(1.0_wp, ieee_quiet_nan)
      end if
    end associate
  end function table_value

  !> Write the crush-length table (rows = measure options, one column per variant in mm, then the
  !! deviation of each further variant from the first in %) as CSV, through <path>.partial.
  subroutine write_study_csv(study, path, status)
    type(study_t), intent(in) :: study          !! study with results
    character(len=*), intent(in) :: path        !! CSV file [-]
    type(status_t), intent(out) :: status       !! STAT_OK, or the failure with its message [-]
    integer :: u, m, v, ios
    character(len=msg_len) :: msg
    character(len=:), allocatable :: line, tmp
    real(wp) :: x, x0

    tmp = trim(path)//'.partial'
    ! a <path>.partial left by a killed run goes by name (a link: the link, never its target), and
    ! the new one is created exclusively, so nothing is written through a link
    call delete_file(tmp)
    open (newunit=u, file=tmp, status='new', action='write', iostat=ios, iomsg=msg)
    if (ios /= 0) then
      call status%fail(STAT_FILE, 'cannot write '//trim(path)//': '//trim(msg))
      return
    end if
    line = 'load_case,option,gear,strut'
    do v = 1, study%n_variants
      line = line//','//csv_text(trim(study%variant(v)%label)//' [mm]')
    end do
    do v = 2, study%n_variants
      line = line//','//csv_text(trim(study%variant(v)%label)//' dev [%]')
    end do
    write (u, '(a)', iostat=ios) line
    do m = 1, study%n_measures
      line = csv_text(trim(study%case_label(study%measure(1, m))))//','//int_text(m)//','// &
             int_text(study%measure(2, m))//','//trim(strut_names(study%measure(3, m)))
      do v = 1, study%n_variants
        line = line//','//real_text(1000.0_wp*table_value(study, m, v), 2)
      end do
      x0 = table_value(study, m, 1)
      do v = 2, study%n_variants
        x = table_value(study, m, v)
        if (abs(x0) > 0.0_wp) then
          line = line//','//real_text(100.0_wp*(x - x0)/abs(x0), 2)
        else
          line = line//',nan'
        end if
      end do
      if (ios == 0) write (u, '(a)', iostat=ios) line
    end do
    close (u)
    if (ios /= 0) then
      call status%fail(STAT_FILE, 'cannot write '//trim(path))
      call delete_file(tmp)
      return
    end if
    call rename_file(tmp, trim(path), status)
    if (.not. status%ok()) then
      call delete_file(tmp)
      status%code = STAT_FILE
    end if
  end subroutine write_study_csv

  !> Write the study's HDF5 file (docs/study.md), through <path>.partial.
  subroutine write_study_h5(study, path, command_line, status)
    type(study_t), intent(in) :: study           !! study with results
    character(len=*), intent(in) :: path         !! HDF5 file [-]
    character(len=*), intent(in) :: command_line !! command line [-]
    type(status_t), intent(out) :: status        !! STAT_OK, or STAT_FILE with the message [-]
    type(h5_file_t) :: f
    call h5_create_partial(f, path, status)
    if (.not. status%ok()) then
      status%code = STAT_FILE
      return
    end if
    call write_h5_all(f, study, command_line, status)
    call h5_commit_partial(f, path, status)
    if (.not. status%ok()) status%code = STAT_FILE
  end subroutine write_study_h5

  !> The contents of the study's HDF5 file: provenance, study, table, summary and per-run groups.
  subroutine write_h5_all(f, study, command_line, status)
    type(h5_file_t), intent(inout) :: f          !! open file
    type(study_t), intent(in) :: study           !! study with results
    character(len=*), intent(in) :: command_line !! command line [-]
    type(status_t), intent(out) :: status        !! STAT_OK, or the failure with its message [-]
    integer :: c, v, m, nc, nv, nm
    character(len=label_len) :: labels(study%n_variants), info(study%n_measures), struts(study%n_measures)
    character(len=4*set_len) :: ovr(study%n_variants)
    real(wp) :: tab(study%n_variants, study%n_measures), resid(study%n_variants, study%n_cases)
    integer :: st(study%n_variants, study%n_cases)
    character(len=:), allocatable :: g, gc

    nc = study%n_cases
    nv = study%n_variants
    nm = study%n_measures
    call h5_write_attr(f, '/', 'title', trim(study%title), status); if (.not. status%ok()) return
    call write_meta(f, 'landyn_study', command_line, status); if (.not. status%ok()) return
    call h5_write(f, '/meta/study_deck', study%deck_name, '-', status); if (.not. status%ok()) return
    call h5_write(f, '/meta/study_deck_text', nonempty(study%deck_text), '-', status, &
                  description='the study deck as given'); if (.not. status%ok()) return
    call h5_write(f, '/study/case_label', study%case_label(1:nc), '-', status); if (.not. status%ok()) return
    call h5_write(f, '/study/case_deck', study%case_deck(1:nc), '-', status); if (.not. status%ok()) return
    call h5_write(f, '/study/common', nonempty(study%common), '-', status, &
                  description='deck text applied to every run before the variant'); if (.not. status%ok()) return
    do v = 1, nv
      labels(v) = study%variant(v)%label
      ovr(v) = study%variant(v)%overrides
    end do
    call h5_write(f, '/study/variant_label', labels, '-', status); if (.not. status%ok()) return
    call h5_write(f, '/study/variant_overrides', ovr, '-', status, &
                  description='deck text each variant applies on top of the load-case deck'); if (.not. status%ok()) return

    ! ---- the table of the paper (rows = measure options, columns = variants)
    do m = 1, nm
      info(m) = study%case_label(study%measure(1, m))
      struts(m) = strut_names(study%measure(3, m))
      do v = 1, nv
        tab(v, m) = table_value(study, m, v)
      end do
    end do
    call h5_write(f, '/table/crush_length', tab, 'm', status, description='shape (n_options, n_variants): '// &
                  'signed net crush of each measure option (Table 3 sense) for each variant; NaN: run failed, '// &
                  'or that variant''s lander has no such gear')
    if (.not. status%ok()) return
    call h5_write(f, '/table/load_case', info, '-', status); if (.not. status%ok()) return
    call h5_write(f, '/table/gear', study%measure(2, 1:nm), '-', status); if (.not. status%ok()) return
    call h5_write(f, '/table/strut', struts, '-', status); if (.not. status%ok()) return
    call h5_write(f, '/table/variant', labels, '-', status); if (.not. status%ok()) return

    ! ---- per variant and load case
    do c = 1, nc
      do v = 1, nv
        resid(v, c) = study%run(c, v)%energy_residual
        st(v, c) = study%run(c, v)%status
      end do
    end do
    call h5_write(f, '/summary/status', st, '-', status, description='shape (n_cases, n_variants): '// &
                  '0 completed, 3 simulation failed'); if (.not. status%ok()) return
    call h5_write(f, '/summary/energy_residual', resid, '-', status, &
                  description='shape (n_cases, n_variants)'); if (.not. status%ok()) return
    do v = 1, nv
      g = '/variants/'//int_text(v, 3)
      call h5_write(f, g//'/label', trim(study%variant(v)%label), '-', status); if (.not. status%ok()) return
      call h5_write(f, g//'/overrides', nonempty(study%variant(v)%overrides), '-', status); if (.not. status%ok()) return
      do c = 1, nc
        gc = g//'/'//group_name(study%case_label(c))
        associate (r => study%run(c, v))
          call h5_write(f, gc//'/status', r%status, '-', status); if (.not. status%ok()) return
          call h5_write(f, gc//'/message', nonempty(trim(r%message)), '-', status); if (.not. status%ok()) return
          call h5_write(f, gc//'/end_reason', nonempty(trim(r%end_reason)), '-', status); if (.not. status%ok()) return
          if (r%status == status_ok) then
            call h5_write(f, gc//'/crush_length', r%crush, 'm', status, &
                          description='/summary/crush_length of the run: shape (n_gears, n_struts)'); if (.not. status%ok()) return
          end if
          call h5_write(f, gc//'/energy_residual', r%energy_residual, '-', status); if (.not. status%ok()) return
          call h5_write(f, gc//'/peak_overload', r%peak_overload, 'g', status); if (.not. status%ok()) return
          call h5_write(f, gc//'/max_tilt', r%max_tilt, 'deg', status); if (.not. status%ok()) return
          call h5_write(f, gc//'/tipped_over', r%tipped_over, '-', status); if (.not. status%ok()) return
          call h5_write(f, gc//'/final_time', r%t_final, 's', status); if (.not. status%ok()) return
          call h5_write(f, gc//'/wall_time', r%wall_time, 's', status); if (.not. status%ok()) return
        end associate
      end do
    end do
  end subroutine write_h5_all

  ! ================================================================ helpers

  !> CSV field: quoted when it holds a comma or a quote.
  pure function csv_text(s) result(t)
    character(len=*), intent(in) :: s      !! text [-]
    character(len=:), allocatable :: t     !! CSV field [-]
    integer :: i
    if (scan(s, ',"') == 0) then
      t = s
      return
    end if
    t = '"'
    do i = 1, len(s)
      if (s(i:i) == '"') then
        t = t//'""'
      else
        t = t//s(i:i)
      end if
    end do
    t = t//'"'
  end function csv_text

  !> A real as text with `d` decimals ('nan' for NaN), with a leading zero.
  pure function real_text(x, d) result(s)
    real(wp), intent(in) :: x              !! value [any unit]
    integer, intent(in) :: d               !! decimals [-]
    character(len=:), allocatable :: s     !! text, 'nan' for NaN [-]
    character(len=40) :: buf
    character(len=16) :: fmt
    if (ieee_is_nan(x)) then
      s = 'nan'
      return
    end if
    write (fmt, '(a,i0,a)') '(f0.', d, ')'
    write (buf, fmt) x
    s = trim(adjustl(buf))
    if (s(1:1) == '.') s = '0'//s
    if (len(s) > 1) then
      if (s(1:2) == '-.') s = '-0'//s(2:)
    end if
  end function real_text

end module landyn_study_output
