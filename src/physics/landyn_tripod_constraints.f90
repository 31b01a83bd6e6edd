!> What a time integrator needs of the gear besides its evaluation (Step 4 of section 3.1): the
!! crush modes at the end of a step (gear_arrest), a position increment with its crush work
!! (gear_increment), the direct position correction dq = -A^+ Phi iterated to the tolerance
!! (A^+ = A^T (A A^T)^-1) with the crush history, the velocity rows A of the system velocity
!! projection (landyn_impact) and the projection of a gear alone. No update formula: that is the
!! integrator's (numerics/).
submodule (landyn_tripod_gear) landyn_tripod_constraints
  use landyn_kinds, only: msg_len
  use landyn_tripod_kinematics, only: gear_constraints, gear_constraint_jacobian, gear_trig
  use landyn_lapack, only: solve_spd_unblocked
  use landyn_small_spd, only: small_spd_solve
  use landyn_status, only: STAT_OK, STAT_DIVERGED, status_t
  use landyn_strings, only: int_text
  use landyn_tube_friction, only: add_tube_bound
  implicit none

contains

  module procedure gear_arrest
    real(wp) :: s0(3), sd0(3), s1(3), sd1(3), fpos, fneg
    integer :: k
    gear%st%rigid = .false.
    call strokes(gear, gear%st%q, gear%st%qd, s0, sd0)
    call strokes(gear, gear%st%q, qd_end, s1, sd1)
    ! A crushing strut whose sliding speed reaches zero locks (it cannot be driven back by its own
    ! buffer force); a free strut (bound 0 in its direction of motion) keeps moving.
    do k = 1, 3
      if (gear%st%locked(k)) cycle
      call gear%buffer(k)%law%resistance(s0(k), sd0(k), gear%st%s_hismin(k), gear%st%s_hismax(k), fpos, fneg)
      if (k == 1 .and. gear%tube%on) call add_tube_bound(gear%st%tube_bound, fpos, fneg)   ! tube friction sticks too
      if (gear%st%dir(k) > 0 .and. sd1(k) <= 0.0_wp .and. fpos > 0.0_wp) gear%st%locked(k) = .true.
      if (gear%st%dir(k) < 0 .and. sd1(k) >= 0.0_wp .and. fneg > 0.0_wp) gear%st%locked(k) = .true.
      if (gear%st%locked(k)) gear%st%s_lock(k) = s0(k)
    end do
  end procedure gear_arrest

  module procedure gear_increment
    real(wp) :: s0(3), sd0(3), s1(3), sd1(3)
    integer :: k
    call strokes(gear, gear%st%q, gear%st%qd, s0, sd0)
    gear%st%q = gear%st%q + qd*h
    gear%st%phq_ok = .false.
    call strokes(gear, gear%st%q, gear%st%qd, s1, sd1)
    ! crush work of the committed buffer force over the stroke increment, for sliding struts
    do k = 1, 3
      if (.not. gear%st%locked(k)) then
        gear%st%work_crush(k) = gear%st%work_crush(k) + gear%sigma(k)*gear%st%axial(k)*(s0(k) - s1(k))
      end if
    end do
  end procedure gear_increment

  module procedure gear_correct_positions
    real(wp) :: s1(3), sd1(3), a(max_rows, n_q), r(max_rows), viol
    integer :: iter, nrow
    character(len=msg_len) :: buf
    type(joint_trig_t) :: tr(3)

    ! Phi(q) = 0 and locked strokes held, dq = -A^T (A A^T)^-1 r. The rows A are built only when a
    ! correction is needed (a locked gear at rest needs none).
    nrow = n_phi + count(gear%st%locked)
    call position_residual(gear, gear%st%q, nrow, r, tr)
    viol = maxval(abs(r(1:n_phi)))
    gear%st%max_drift = max(gear%st%max_drift, viol)
    if (viol > max_drift) then
      write (buf, '(a,es10.3,a,es10.3,a)') 'constraint drift ', viol, ' m in one step exceeds ', max_drift, &
        ' m: the time step is too large for this landing (reduce &simulation dt)'
      call status%fail(STAT_DIVERGED, trim(buf))
      return
    end if
    do iter = 1, max_iter
      if (maxval(abs(r(1:nrow))) <= tol) exit
      call build_rows(gear, gear%st%q, a, nrow, tr)
      call min_norm_correction(nrow, a, r, gear%st%q, status)
      if (status%code /= STAT_OK) return
      call position_residual(gear, gear%st%q, nrow, r, tr)
      gear%st%n_correction_iter = max(gear%st%n_correction_iter, iter)
    end do
    viol = maxval(abs(r(1:nrow)))
    if (viol > tol) then
      write (buf, '(a,i0,a,es10.3,a,es10.3,a)') 'position constraint correction did not converge in ', max_iter, &
        ' iterations (violation ', viol, ' m, tolerance ', tol, ' m)'
      call status%fail(STAT_DIVERGED, trim(buf))
      return
    end if
    gear%st%max_violation = max(gear%st%max_violation, viol)
    ! The strut kinematics and Phi_q at the corrected coordinates, for the velocity projection and
    ! the next evaluation, from the joint trigonometry the last residual computed there.
    call cache_corrected(gear, tr)
    ! Crush history (positions only).
    call strokes(gear, gear%st%q, gear%st%qd, s1, sd1)
    gear%st%s_hismax = max(gear%st%s_hismax, s1)
    gear%st%s_hismin = min(gear%st%s_hismin, s1)
  end procedure gear_correct_positions

  module procedure gear_project_alone
    real(wp) :: a(max_rows, n_q), r(max_rows), mdiag(n_q), lam(max_rows), w(max_rows, max_rows)
    integer :: nrow, i, j
    call build_rows(gear, gear%st%q, a, nrow)
    do i = 1, nrow
      r(i) = dot_product(a(i, :), gear%st%qd)
    end do
    if (maxval(abs(r(1:nrow))) > 0.0_wp) then
      mdiag = gear_mass_matrix(gear, gear%st%q)
      do j = 1, nrow
        do i = 1, j
          w(i, j) = sum(a(i, :)*a(j, :)/mdiag)
        end do
      end do
      lam(1:nrow) = r(1:nrow)
      call solve_spd_unblocked(nrow, w, max_rows, lam, status, 'gear velocity projection')
      if (.not. status%ok()) return
      do i = 1, nrow
        gear%st%qd = gear%st%qd - lam(i)*a(i, :)/mdiag
      end do
    end if
    call gear_settle(gear)
  end procedure gear_project_alone

  !> x <- x - A^T (A A^T)^-1 r (minimum-norm correction, Step 4).
  subroutine min_norm_correction(nrow, a, r, x, status)
    integer, intent(in) :: nrow                  !! rows [-]
    real(wp), intent(in) :: a(:, :)              !! Jacobian rows [m/m, m/rad]
    real(wp), intent(in) :: r(:)                 !! residual [m]
    real(wp), intent(inout) :: x(n_q)            !! vector to correct [m, rad]
    type(status_t), intent(inout) :: status      !! STAT_OK on entry; STAT_DIVERGED with the diagnosis [-]
    real(wp) :: s(max_rows, max_rows), y(max_rows)
    integer :: i, j, minor
    do j = 1, nrow
      do i = 1, j
        s(i, j) = dot_product(a(i, 1:n_q), a(j, 1:n_q))
      end do
    end do
    y(1:nrow) = r(1:nrow)
    call small_spd_solve(nrow, s, max_rows, y, minor)
    if (minor /= 0) then
      call status%fail(STAT_DIVERGED, 'constraint correction: Phi_q Phi_q^T is not positive definite (minor '// &
        int_text(minor)//'): redundant constraints or a singular configuration')
      return
    end if
    do i = 1, nrow
      x = x - y(i)*a(i, 1:n_q)
    end do
  end subroutine min_norm_correction

  module procedure gear_settle
    integer :: k
    ! A strut stopped in the step by its lock row leaves it in the mode its holding force decided
    ! (gear_evaluate): at rest (the rate the lock row held at zero, up to round-off, is set to zero,
    ! so that its sliding direction is the decided one and not the sign of a round-off).
    do k = 1, 3
      if (gear%st%dir_after(k) /= 0) then
        gear%st%locked(k) = .false.
        gear%st%dir(k) = gear%st%dir_after(k)
        gear%st%axial(k) = gear%st%axial_after(k)
        gear%st%qd(idx_len(k)) = 0.0_wp
        gear%st%dir_after(k) = 0
      end if
    end do
    if (all(gear%st%locked) .and. .not. gear%st%rigid) then
      gear%st%qd = 0.0_wp
      gear%st%qdd = 0.0_wp
      gear%st%rigid = .true.
      gear%st%rigid_cache = .false.
    end if
  end procedure gear_settle

  module procedure gear_velocity_rows
    call build_rows(gear, gear%st%q, a, nrow)
  end procedure gear_velocity_rows

  module procedure tripod_velocity_rows
    call gear_velocity_rows(gear, a, nrow)
    call gear_cache_jacobian(gear, a(1:n_phi, :))
  end procedure tripod_velocity_rows

  !> The kinematics cache (what cache_kinematics stores), the Phi_q cache and the trigonometry
  !! cache at the current coordinates, from their joint trigonometry tr: the same values as from
  !! the angles.
  pure subroutine cache_corrected(gear, tr)
    type(tripod_gear_t), intent(inout) :: gear          !! gear
    type(joint_trig_t), intent(in) :: tr(3)      !! gear_trig(gear%st%q) [-]
    call kinematics_at(gear%geom, gear%strut, gear%st%q, gear%st%kin, tr)
    gear%st%kin_q = gear%st%q
    gear%st%kin_ok = .true.
    call gear_cache_jacobian(gear, gear_constraint_jacobian(gear%geom, gear%st%q, tr, secondary_axes_of(gear%st%kin)))
    gear%st%trig = tr
    gear%st%trig_q = gear%st%q
    gear%st%trig_ok = .true.
  end subroutine cache_corrected

  !> Rows of the correction: Phi_q and one row per locked strut. Phi_q is the cached one when it
  !! is at qv bit for bit (gear_correct_positions caches it at the corrected coordinates), else
  !! computed, from the joint trigonometry tr when given.
  pure subroutine build_rows(gear, qv, a, nrow, tr)
    type(tripod_gear_t), intent(in) :: gear           !! gear
    real(wp), intent(in) :: qv(n_q)            !! coordinates
    real(wp), intent(out) :: a(max_rows, n_q)  !! rows
    integer, intent(out) :: nrow               !! number of rows
    type(joint_trig_t), intent(in), optional :: tr(3)  !! gear_trig(qv), when at hand [-]
    integer :: k
    if (gear%st%phq_ok .and. same_coordinates(qv, gear%st%phq_q)) then
      a(1:n_phi, :) = gear%st%phq
    else
      a(1:n_phi, :) = gear_constraint_jacobian(gear%geom, qv, tr)
    end if
    nrow = n_phi
    do k = 1, 3
      if (gear%st%locked(k)) then
        nrow = nrow + 1
        a(nrow, :) = 0.0_wp
        a(nrow, idx_len(k)) = gear%sigma(k)
      end if
    end do
  end subroutine build_rows

  !> Position residual: Phi(q) and the locked strokes' departure from their held values.
  subroutine position_residual(gear, qv, nrow, r, tr)
    type(tripod_gear_t), intent(in) :: gear        !! gear
    real(wp), intent(in) :: qv(n_q)         !! coordinates
    integer, intent(in) :: nrow             !! number of rows
    real(wp), intent(out) :: r(max_rows)    !! residual
    type(joint_trig_t), intent(out) :: tr(3)  !! joint trigonometry at qv (gear_trig) [-]
    integer :: k, row
    real(wp) :: s(3), sd(3)
    tr = gear_trig(qv)
    r(1:n_phi) = gear_constraints(gear%geom, qv, tr)
    call strokes(gear, qv, gear%st%qd, s, sd)
    row = n_phi
    do k = 1, 3
      if (gear%st%locked(k)) then
        row = row + 1
        r(row) = s(k) - gear%st%s_lock(k)
      end if
    end do
    if (row /= nrow) r(row + 1:) = 0.0_wp
  end subroutine position_residual

end submodule landyn_tripod_constraints
