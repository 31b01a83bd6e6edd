!> The gear's dynamics at one instant: crush logic, the augmented DAE and the load on the body
!! (paper eqs. 12-16, Steps 2-4 of section 3.1).
!!
!! Crush logic (eqs. 12-13) as a complementarity with the buffer bounds of landyn_buffer: a strut
!! at rest is LOCKED (its length rate is constrained to zero; the multiplier of that constraint is
!! the equivalent dynamic force F of eq. 12). When F exceeds the buffer's bound in its direction,
!! the strut crushes: it is released and the buffer transmits N = bound, the excess F - N drives
!! the sliding coordinate (eq. 13). A crushing strut whose sliding speed reaches zero within a step
!! is stopped by a lock row for that step; the mode it leaves the step in (locked again, or sliding
!! toward its holding force when that exceeds a bound) is decided by the force that holds it once
!! stopped (after_stop; docs/theory.md, "The mode after a stop"). This replaces the literal
!! reading in which a strut keeps sliding with no force on it.
!!
!! The augmented system [[M, A^T], [A, 0]] [qdd; lambda] = [Q; b] (eqs. 14-16, A = Phi_q plus the
!! lock rows) is solved by block elimination with LAPACK's Cholesky (M is diagonal, so the Schur
!! complement A M^-1 A^T is small and SPD); test_gear solves the unreduced system with LU for
!! cross-checking.
submodule (landyn_tripod_gear) landyn_tripod_dynamics
  use landyn_buffer, only: rigid_force
  use landyn_kinematics, only: cross3, axis_derivs_t
  use landyn_tripod_kinematics, only: gear_constraint_jacobian, gear_constraint_gamma
  use landyn_lapack, only: solve_spd_unblocked, factor_spd
  use landyn_small_spd, only: small_upper_solve_multi
  use landyn_status, only: STAT_OK, status_t
  use landyn_tube_friction, only: tube_friction_bound, add_tube_bound
  implicit none

  !> Work of one gear evaluation (gear_evaluate): the terms of the augmented system at the committed
  !! state, the struts' strokes and bounds, the system of the current locks and the crush logic's flags,
  !! shared by the steps of the evaluation.
  type :: eval_work_t
    type(strut_kin_t) :: sk(3)                   !! strut kinematics at the committed state
    real(wp) :: mdiag(n_q)                       !! mass matrix diagonal [kg, kg m^2]
    real(wp) :: q_ine(n_q)                       !! inertial (velocity-dependent) generalized force [N, N m]
    real(wp) :: q_grv(n_q)                       !! generalized force of the uniform field [N, N m]
    real(wp) :: q_ext(n_q)                       !! generalized force of the footpad's ground force [N, N m]
    real(wp) :: q_alp(n_q)                       !! generalized force of the body's angular acceleration [N, N m]
    real(wp) :: q_tot(n_q)                       !! total generalized force of the current locks [N, N m]
    real(wp) :: phq(n_phi, n_q)                  !! constraint Jacobian Phi_q [-, m]
    real(wp) :: gam(n_phi)                       !! constraint right-hand side gamma [m/s^2, rad/s^2]
    real(wp) :: a(max_rows, n_q)                 !! rows of the augmented system, [Phi_q; lock rows] [-, m]
    real(wp) :: b(max_rows)                      !! its right-hand side [m/s^2, rad/s^2]
    real(wp) :: lam(max_rows)                    !! its multipliers [N, N m]
    real(wp) :: s(3)                             !! strokes [m]
    real(wp) :: sd(3)                            !! stroke rates [m/s]
    real(wp) :: fpos(3)                          !! bounds against motion toward +s [N]
    real(wp) :: fneg(3)                          !! bounds against motion toward -s [N]
    real(wp) :: h_look                           !! look-ahead of the entry margins (dt, or 0) [s]
    integer :: nrow                              !! rows of the augmented system [-]
    integer :: row_of(3)                         !! row of each locked strut, 0 if none [-]
    integer :: m_entry(3)                        !! each strut's mode at entry (strut_mode) [-]
    logical :: stop_hit(3)                       !! strut ran into a rigid stop in this evaluation [-]
    logical :: tried(3)                          !! strut locked for the step because it would reverse [-]
    logical :: released(3)                       !! such a lock gave way again [-]
    logical :: got_in(3)                         !! entry margin of a strut that entered locked is set [-]
    logical :: changed                           !! the last pass of the crush logic changed a mode [-]
  end type eval_work_t

contains

  module procedure gear_evaluate
    type(eval_work_t) :: w
    logical :: with_loads, done, stopped(3)
    real(wp) :: demand0(3), f_rel(3), m_rel(3), f_strut(3, 3), h_strut(3, 3)

    ge = gear_eval_t()      ! every component anew (ge is inout: reset here, once)
    with_loads = .true.
    if (present(loads)) with_loads = loads
    call evaluation_start(gear, ge)
    w%q_alp = 0.0_wp
    w%stop_hit = .false.
    if (ge%rigid .and. all(ge%locked)) then
      call rigid_dynamics(gear, ge, f_foot, f_field, with_loads, done, status, alpha)
      if (status%code /= STAT_OK .or. done) return
    end if
    call system_terms(gear, f_foot, f_field, w, alpha)
    call strut_bounds(gear, ge, w)
    w%h_look = 0.0_wp
    if (present(dt)) w%h_look = dt
    w%m_entry = strut_mode(gear%st%locked, gear%st%axial, gear%st%dir)
    w%got_in = .false.
    call slide_against_motion(gear, ge, w)
    call settle_modes(gear, ge, w, status, dt)
    if (status%code /= STAT_OK) return
    ! A strut this step's lock row stops (a crushing strut locked for the step, not one on a rigid
    ! stop) leaves the step in the mode decided by the force that holds it once stopped.
    stopped = w%tried .and. ge%locked(1:3) .and. .not. w%stop_hit .and. .not. w%changed
    demand0 = 0.0_wp
    if (any(stopped)) then
      call after_stop(gear, w, stopped, ge, demand0, status)
      if (status%code /= STAT_OK) return
    end if
    call margins_out(gear, w, stopped, demand0, ge)

    ! Loads on the body: the leg's momentum balance. The body (which carries the total mass, legs
    ! included) receives the ground force minus the rate of the legs' relative momentum; in the
    ! massless-leg limit this is eq. 11's J^-T N applied at the footpad.
    call relative_inertia(gear, w%sk, ge%qdd, f_rel, m_rel, f_strut, h_strut)
    ge%f_body = f_foot - f_rel
    ge%m_body = cross3(gear%geom%a + gear%st%q(1)*w%sk(1)%u, f_foot) - m_rel
    if (with_loads) call joint_loads(gear, w%sk, gear%st%q, gear%st%qd, ge%qdd, f_strut, h_strut, w%lam(1:n_phi), &
                     f_foot, f_field, alpha_or_zero(alpha), ge%f_body, ge%f_joint, ge%m_joint, ge%f_interface)
  end procedure gear_evaluate

  !> The evaluation's start: the committed decisions of the gear (accelerations, axial forces, locks,
  !! directions, lock strokes, tube bound, rigid state), no margins and no mode after a stop yet.
  !! With tube friction on, the primary's tube bound of this step (eqs. 23-26).
  subroutine evaluation_start(gear, ge)
    type(tripod_gear_t), intent(in) :: gear             !! gear with its committed state [-]
    type(gear_eval_t), intent(inout) :: ge       !! evaluation to start [-]
    ge%qdd = gear%st%qdd
    ge%axial = gear%st%axial
    ge%f_body = gear%st%f_body
    ge%m_body = gear%st%m_body
    ge%locked = gear%st%locked
    ge%dir = gear%st%dir
    ge%s_lock = gear%st%s_lock
    ge%tube_bound = gear%st%tube_bound
    ge%rigid = gear%st%rigid
    ge%margin_in = 0.0_wp
    ge%margin_out = 0.0_wp
    ge%dir_after = 0
    ge%axial_after = 0.0_wp
    ! Tube friction (eqs. 23-26): the primary's extra bound, explicit from the previous step's
    ! secondary forces (landyn_tube_friction). Off by default: then nothing here runs.
    if (gear%tube%on) ge%tube_bound = tube_bound_now(gear)
  end subroutine evaluation_start

  !> The terms of the augmented system at the committed state: strut kinematics, mass diagonal, the
  !! generalized forces (inertial, field, footpad, and the body's angular acceleration when given),
  !! the constraint Jacobian Phi_q and the constraint right-hand side gamma (from the caches where
  !! they hold for the committed coordinates).
  subroutine system_terms(gear, f_foot, f_field, w, alpha)
    type(tripod_gear_t), intent(in) :: gear             !! gear with its committed state [-]
    real(wp), intent(in) :: f_foot(3)            !! ground force on the footpad, gear frame [N]
    real(wp), intent(in) :: f_field(3)           !! uniform field, gear frame [m/s^2]
    type(eval_work_t), intent(inout) :: w        !! work: sk, mdiag, q_ine, q_grv, q_ext, q_alp, phq, gam set [-]
    real(wp), intent(in), optional :: alpha(3)   !! body angular acceleration, gear axes [rad/s^2]
    type(axis_derivs_t) :: axes(2)
    logical :: have_trig
    call strut_kinematics(gear, gear%st%q, w%sk)
    w%mdiag = mass_diagonal(w%sk, gear%st%q)
    have_trig = gear%st%trig_ok
    if (have_trig) have_trig = same_coordinates(gear%st%q, gear%st%trig_q)
    if (have_trig) then
      call generalized_forces(gear%st%q, gear%st%qd, w%sk, f_field, f_foot, w%q_ine, w%q_grv, w%q_ext, gear%st%trig)
    else
      call generalized_forces(gear%st%q, gear%st%qd, w%sk, f_field, f_foot, w%q_ine, w%q_grv, w%q_ext)
    end if
    if (present(alpha)) w%q_alp = alpha_forces(gear, gear%st%q, w%sk, alpha)
    if (gear%st%phq_ok .and. same_coordinates(gear%st%q, gear%st%phq_q)) then
      w%phq = gear%st%phq
    else
      w%phq = gear_constraint_jacobian(gear%geom, gear%st%q)
    end if
    ! the secondaries' axis partials of sk are those gear_constraint_gamma would compute at q
    axes = secondary_axes_of(w%sk)
    if (have_trig) then
      w%gam = gear_constraint_gamma(gear%geom, gear%st%q, gear%st%qd, gear%st%trig, axes)
    else
      w%gam = gear_constraint_gamma(gear%geom, gear%st%q, gear%st%qd, axes=axes)
    end if
  end subroutine system_terms

  !> The struts' strokes and rates and their buffers' bounds at the committed state: the free
  !! (crushed) range and the resistance toward +s and -s, the primary's with its tube-friction bound
  !! (eq. 24).
  subroutine strut_bounds(gear, ge, w)
    type(tripod_gear_t), intent(in) :: gear             !! gear with its committed state [-]
    type(gear_eval_t), intent(inout) :: ge       !! evaluation: stroke, free_lo, free_hi set [-]
    type(eval_work_t), intent(inout) :: w        !! work: s, sd, fpos, fneg set [-]
    integer :: k
    call strokes(gear, gear%st%q, gear%st%qd, w%s, w%sd)
    ge%stroke(1:3) = w%s
    do k = 1, 3
      call gear%buffer(k)%law%free_range(gear%st%s_hismin(k), gear%st%s_hismax(k), ge%free_lo(k), ge%free_hi(k))
      call gear%buffer(k)%law%resistance(w%s(k), w%sd(k), gear%st%s_hismin(k), gear%st%s_hismax(k), &
                                         w%fpos(k), w%fneg(k))
    end do
    if (gear%tube%on) call add_tube_bound(ge%tube_bound, w%fpos(1), w%fneg(1))   ! tube friction (eq. 24)
  end subroutine strut_bounds

  !> Sliding struts transmit their bound against the direction of motion; a sliding strut that runs
  !! into a rigid stop is locked (plastic impact on the stop; stop_hit).
  subroutine slide_against_motion(gear, ge, w)
    type(tripod_gear_t), intent(in) :: gear             !! gear with its committed state [-]
    type(gear_eval_t), intent(inout) :: ge       !! evaluation: dir, axial, locked, s_lock of sliding struts [-]
    type(eval_work_t), intent(inout) :: w        !! work: stop_hit set [-]
    integer :: k
    do k = 1, 3
      if (.not. ge%locked(k)) then
        if (w%sd(k) > 0.0_wp) ge%dir(k) = 1
        if (w%sd(k) < 0.0_wp) ge%dir(k) = -1
        if (ge%dir(k) > 0) then
          ge%axial(k) = -gear%sigma(k)*w%fpos(k)
          if (w%fpos(k) >= rigid_force) ge%locked(k) = .true.
          if (w%fpos(k) >= rigid_force) w%stop_hit(k) = .true.
        else
          ge%axial(k) = gear%sigma(k)*w%fneg(k)
          if (w%fneg(k) >= rigid_force) ge%locked(k) = .true.
          if (w%fneg(k) >= rigid_force) w%stop_hit(k) = .true.
        end if
        if (ge%locked(k)) ge%s_lock(k) = w%s(k)
      end if
    end do
  end subroutine slide_against_motion

  !> The crush logic's fixed point (eqs. 12-13): solve the augmented system with the current locks,
  !! then lock crushing struts that would reverse within the step, release locks whose force exceeds
  !! the bound, and repeat (at most 8 passes) until no mode changes (changed = .false.).
  subroutine settle_modes(gear, ge, w, status, dt)
    type(tripod_gear_t), intent(in) :: gear             !! gear with its committed state [-]
    type(gear_eval_t), intent(inout) :: ge       !! evaluation: qdd, axial, locks, dir, margin_in [-]
    type(eval_work_t), intent(inout) :: w        !! work: the last pass's system, multipliers and flags [-]
    type(status_t), intent(inout) :: status      !! STAT_OK on entry; the failure's code and diagnosis [-]
    real(wp), intent(in), optional :: dt         !! step the decisions are for [s]
    integer :: k, iter
    w%tried = .false.
    w%released = .false.
    do iter = 1, 8
      call assemble_system(gear, ge, w, dt)
      call solve_reduced(w%nrow, w%a, w%b, w%mdiag, w%q_tot, ge%qdd, w%lam, status)
      if (status%code /= STAT_OK) return
      if (iter == 1) then
        do k = 1, 3
          if (w%m_entry(k) /= 0) ge%margin_in(k) = mode_margin(w%m_entry(k), gear%st%dir(k), w%s(k), &
            w%sd(k) + gear%sigma(k)*ge%qdd(idx_len(k))*w%h_look, ge%free_lo(k), ge%free_hi(k), 0.0_wp, 0.0_wp, 0.0_wp)
        end do
      end if
      ! Check each lock: the force it carries (the equivalent dynamic force) against the bound.
      w%changed = .false.
      if (present(dt)) then
        call lock_reversing(gear, ge, w, dt)
        if (w%changed) cycle
      end if
      call release_locks(gear, ge, w)
      if (.not. w%changed) exit
    end do
  end subroutine settle_modes

  !> The augmented system of the current locks: A = [Phi_q; lock rows], b = [gamma; lock rates] and
  !! the generalized force with the sliding struts' axial forces.
  subroutine assemble_system(gear, ge, w, dt)
    type(tripod_gear_t), intent(in) :: gear             !! gear with its committed state [-]
    type(gear_eval_t), intent(in) :: ge          !! evaluation: locks and axial forces [-]
    type(eval_work_t), intent(inout) :: w        !! work: nrow, a, b, row_of, q_tot set [-]
    real(wp), intent(in), optional :: dt         !! step the decisions are for [s]
    real(wp) :: q_buf(n_q)
    integer :: k
    q_buf = 0.0_wp
    w%nrow = n_phi
    w%a(1:n_phi, :) = w%phq
    w%b(1:n_phi) = w%gam
    w%row_of = 0
    do k = 1, 3
      if (ge%locked(k)) then
        w%nrow = w%nrow + 1
        w%a(w%nrow, :) = 0.0_wp
        w%a(w%nrow, idx_len(k)) = 1.0_wp
        w%b(w%nrow) = 0.0_wp
        ! Velocity-level lock: stop at the end of the step. A strut that has just run into a
        ! rigid stop keeps its speed through the step instead (b = 0): stopping it is a plastic
        ! impact, done by the system velocity projection after the step, which books its loss.
        if (present(dt) .and. .not. w%stop_hit(k)) w%b(w%nrow) = -gear%st%qd(idx_len(k))/dt
        w%row_of(k) = w%nrow
      else
        q_buf(idx_len(k)) = ge%axial(k)
      end if
    end do
    w%q_tot = w%q_ine + w%q_grv + w%q_ext + q_buf + w%q_alp
  end subroutine assemble_system

  !> A crushing strut (nonzero bound in its direction of motion) that would reverse within the step
  !! is locked for the step (tried), to be checked against its bounds by release_locks.
  subroutine lock_reversing(gear, ge, w, dt)
    type(tripod_gear_t), intent(in) :: gear             !! gear with its committed state [-]
    type(gear_eval_t), intent(inout) :: ge       !! evaluation: locked, s_lock [-]
    type(eval_work_t), intent(inout) :: w        !! work: tried, changed set [-]
    real(wp), intent(in) :: dt                   !! step the decisions are for [s]
    integer :: k
    do k = 1, 3
      if (ge%locked(k) .or. w%released(k)) cycle
      if (ge%dir(k) > 0 .and. w%fpos(k) > 0.0_wp .and. w%sd(k) + gear%sigma(k)*ge%qdd(idx_len(k))*dt <= 0.0_wp &
          .or. ge%dir(k) < 0 .and. w%fneg(k) > 0.0_wp .and. w%sd(k) + gear%sigma(k)*ge%qdd(idx_len(k))*dt >= 0.0_wp) then
        ge%locked(k) = .true.
        ge%s_lock(k) = w%s(k)
        w%tried(k) = .true.
        w%changed = .true.
      end if
    end do
  end subroutine lock_reversing

  !> Each lock's force (its multiplier, the equivalent dynamic force) against its bounds: a lock
  !! beyond a bound gives way and its strut slides with that bound (changed). Sets the entry margin
  !! of struts that entered locked.
  subroutine release_locks(gear, ge, w)
    type(tripod_gear_t), intent(in) :: gear             !! gear with its committed state [-]
    type(gear_eval_t), intent(inout) :: ge       !! evaluation: axial, locked, dir, margin_in [-]
    type(eval_work_t), intent(inout) :: w        !! work: got_in, released, changed [-]
    real(wp) :: demand, axial_go
    integer :: k, dir_go
    do k = 1, 3
      if (.not. ge%locked(k)) cycle
      ge%axial(k) = -w%lam(w%row_of(k))
      ! Generalized force of the lock on the stroke s is sigma*axial: negative when it holds the
      ! strut against motion toward +s (bounded by f_pos), positive against -s (bounded by f_neg).
      demand = gear%sigma(k)*ge%axial(k)
      if (w%m_entry(k) == 0 .and. .not. w%got_in(k)) then
        ge%margin_in(k) = mode_margin(0, 0, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, w%fpos(k), w%fneg(k), demand)
        w%got_in(k) = .true.
      end if
      call lock_gives_way(demand, w%fpos(k), w%fneg(k), gear%sigma(k), dir_go, axial_go)
      if (dir_go /= 0) then
        ge%locked(k) = .false.
        ge%dir(k) = dir_go
        ge%axial(k) = axial_go
        w%changed = .true.
      end if
      if (.not. ge%locked(k) .and. w%tried(k)) w%released(k) = .true.
    end do
  end subroutine release_locks

  !> The primary's tube-friction bound eta u_1 N_E/F for this step, from the current strut axes and
  !! the secondary axial forces of the previous step (explicit; landyn_tube_friction).
  pure real(wp) function tube_bound_now(gear) result(bound)
    type(tripod_gear_t), intent(in) :: gear       !! gear with its committed secondary forces [-]
    type(strut_kin_t) :: sk(3)
    call strut_kinematics(gear, gear%st%q, sk)
    bound = tube_friction_bound(gear%tube, sk(1)%u, sk(2)%u, sk(3)%u, gear%st%axial(2), gear%st%axial(3))
  end function tube_bound_now

  !> The mode each strut stopped by its lock row leaves the step in (docs/theory.md, "Mode
  !! switches"). The lock row demands sd(t + dt) = 0: its force holds the strut and, on top, stops
  !! it within the step (b = -sd/dt). Once stopped, only the holding force is needed: the same
  !! system with every lock row at acceleration level (b = 0). Within the bounds, -f_pos <=
  !! -demand0 and demand0 <= f_neg, the strut stays locked; beyond one it leaves the step sliding
  !! toward that side with the bound as its force (into its free crushed range where that bound is 0).
  subroutine after_stop(gear, w, stopped, ge, demand0, status)
    type(tripod_gear_t), intent(in) :: gear             !! gear with its committed state [-]
    type(eval_work_t), intent(in) :: w           !! work: the step's system (nrow, a, b, row_of, mdiag, q_tot) and bounds [-]
    logical, intent(in) :: stopped(3)            !! strut stopped by its lock row in this step [-]
    type(gear_eval_t), intent(inout) :: ge       !! evaluation: dir_after, axial_after set [-]
    real(wp), intent(out) :: demand0(3)          !! holding force of each stopped strut's lock on s [N]
    type(status_t), intent(inout) :: status      !! STAT_OK on entry; the failure's code and diagnosis [-]
    real(wp) :: b0(max_rows), lam0(max_rows), qdd0(n_q)
    integer :: j
    b0(1:w%nrow) = w%b(1:w%nrow)
    do j = 1, 3
      if (w%row_of(j) > 0) b0(w%row_of(j)) = 0.0_wp
    end do
    call solve_reduced(w%nrow, w%a, b0, w%mdiag, w%q_tot, qdd0, lam0, status)
    if (status%code /= STAT_OK) return
    demand0 = 0.0_wp
    do j = 1, 3
      if (.not. stopped(j)) cycle
      demand0(j) = -gear%sigma(j)*lam0(w%row_of(j))
      call lock_gives_way(demand0(j), w%fpos(j), w%fneg(j), gear%sigma(j), ge%dir_after(j), ge%axial_after(j))
    end do
  end subroutine after_stop

  !> The switching functions of the modes decided (margin_out): a strut stopped in the step by its
  !! lock row has those of the mode it leaves the step in, at rest (a lock's with its holding force
  !! demand0, not the stopping force; a sliding mode's with the rate zero it leaves the step with).
  subroutine margins_out(gear, w, stopped, demand0, ge)
    type(tripod_gear_t), intent(in) :: gear             !! gear with its committed state [-]
    type(eval_work_t), intent(in) :: w           !! work: strokes, rates, bounds, look-ahead [-]
    logical, intent(in) :: stopped(3)            !! strut stopped by its lock row in this step [-]
    real(wp), intent(in) :: demand0(3)           !! their holding forces on s [N]
    type(gear_eval_t), intent(inout) :: ge       !! evaluation: margin_out set [-]
    integer :: j
    do j = 1, 3
      if (stopped(j) .and. ge%dir_after(j) /= 0) then
        ge%margin_out(j) = mode_margin(strut_mode(.false., ge%axial_after(j), ge%dir_after(j)), ge%dir_after(j), &
          w%s(j), 0.0_wp, ge%free_lo(j), ge%free_hi(j), w%fpos(j), w%fneg(j), gear%sigma(j)*ge%axial_after(j))
      else if (stopped(j)) then
        ge%margin_out(j) = mode_margin(0, 0, w%s(j), 0.0_wp, ge%free_lo(j), ge%free_hi(j), w%fpos(j), w%fneg(j), &
                                       demand0(j))
      else
        ge%margin_out(j) = mode_margin(strut_mode(ge%locked(j), ge%axial(j), ge%dir(j)), ge%dir(j), w%s(j), &
          w%sd(j) + gear%sigma(j)*ge%qdd(idx_len(j))*w%h_look, ge%free_lo(j), ge%free_hi(j), w%fpos(j), w%fneg(j), &
          gear%sigma(j)*ge%axial(j))
      end if
    end do
  end subroutine margins_out

  !> Solves M qdd + A^T lam = Q, A qdd = b by elimination: (A M^-1 A^T) lam = A M^-1 Q - b.
  subroutine solve_reduced(nrow, a, b, mdiag, qf, qdd, lam, status)
    integer, intent(in) :: nrow                  !! number of constraint rows [-]
    real(wp), intent(in) :: a(:, :)              !! constraint rows (nrow x n_q) [-, m]
    real(wp), intent(in) :: b(:)                 !! constraint right-hand side [m/s^2, rad/s^2]
    real(wp), intent(in) :: mdiag(n_q)           !! mass matrix diagonal [kg, kg m^2]
    real(wp), intent(in) :: qf(n_q)              !! generalized force [N, N m]
    real(wp), intent(out) :: qdd(n_q)            !! accelerations [m/s^2, rad/s^2]
    real(wp), intent(out) :: lam(:)              !! multipliers [N, N m]
    type(status_t), intent(inout) :: status      !! STAT_OK on entry; the solver's failure [-]
    real(wp) :: s(max_rows, max_rows), aw(max_rows, n_q), r(max_rows)
    integer :: i, j
    do j = 1, n_q
      aw(1:nrow, j) = a(1:nrow, j)/mdiag(j)
    end do
    do j = 1, nrow
      do i = 1, j
        s(i, j) = dot_product(aw(i, :), a(j, 1:n_q))
      end do
    end do
    do i = 1, nrow
      r(i) = dot_product(aw(i, :), qf) - b(i)
    end do
    call solve_spd_unblocked(nrow, s, max_rows, r, status, 'gear DAE (A M^-1 A^T)')
    if (status%code /= STAT_OK) return
    lam(1:nrow) = r(1:nrow)
    qdd = qf
    do i = 1, nrow
      qdd = qdd - lam(i)*a(i, 1:n_q)
    end do
    qdd = qdd/mdiag
  end subroutine solve_reduced

  !> gear_dynamics for a rigid gear (all struts locked, at rest relative to the body): only the
  !! lock forces are solved for, with the cached factor. done = .false. when a strut's demand
  !! exceeds its bound: the gear leaves the rigid state and the caller takes the general path.
  subroutine rigid_dynamics(gear, ge, f_foot, f_field, loads, done, status, alpha)
    type(tripod_gear_t), intent(in) :: gear             !! rigid gear (committed state) [-]
    type(gear_eval_t), intent(inout) :: ge       !! its evaluation [-]
    real(wp), intent(in) :: f_foot(3)            !! ground force on the footpad, gear frame [N]
    logical, intent(in) :: loads                 !! compute the interface loads [-]
    real(wp), intent(in) :: f_field(3)           !! uniform field, gear frame [m/s^2]
    logical, intent(out) :: done                 !! .true. when the gear stays rigid this step
    type(status_t), intent(inout) :: status      !! STAT_OK on entry; the failure's code and diagnosis [-]
    real(wp), intent(in), optional :: alpha(3)   !! body angular acceleration, gear axes [rad/s^2]
    type(gear_state_t) :: c
    done = .false.
    if (gear%st%rigid_cache) then
      call rigid_solve(gear, gear%st, ge, f_foot, f_field, loads, done, alpha)
    else
      ! not prepared (gear_prepare): the cache of a copy, for this evaluation only
      c = gear%st
      call rigid_cache(gear, c, status)
      if (status%code /= STAT_OK) return
      call rigid_solve(gear, c, ge, f_foot, f_field, loads, done, alpha)
    end if
  end subroutine rigid_dynamics

  !> Whether a lock that holds its strut with the generalized force demand on the stroke gives way:
  !! beyond f_pos it slides toward +s, beyond f_neg toward -s, with that bound as its axial force;
  !! dir = 0 (axial 0) while the lock holds.
  pure subroutine lock_gives_way(demand, fpos, fneg, sigma, dir, axial)
    real(wp), intent(in) :: demand       !! generalized force of the lock on the stroke (sigma * axial) [N]
    real(wp), intent(in) :: fpos         !! bound against motion toward +s [N]
    real(wp), intent(in) :: fneg         !! bound against motion toward -s [N]
    real(wp), intent(in) :: sigma        !! ds/dL, the stroke sign convention of the strut [-]
    integer, intent(out) :: dir          !! direction it slides in, 0: the lock holds [-]
    real(wp), intent(out) :: axial       !! its axial buffer force when it slides, else 0 [N]
    dir = 0
    axial = 0.0_wp
    if (-demand > fpos) then
      dir = 1
      axial = -sigma*fpos
    else if (demand > fneg) then
      dir = -1
      axial = sigma*fneg
    end if
  end subroutine lock_gives_way

  !> The switching function of a strut's crush mode (gear_eval_t%margin_in, margin_out): >= 0
  !! while the mode holds. Locked (mode 0): the force left before the lock gives way in either
  !! direction, min(f_pos + demand, f_neg - demand); crushing (+1, -1): the stroke rate in the
  !! crush direction after the step's velocity update (the crush logic locks the strut where it
  !! reverses); free (2): the stroke left to the nearer end of the free range (either way: a free
  !! strut's direction is not a mode).
  pure real(wp) function mode_margin(mode, dir, s, sd_after, lo, hi, fpos, fneg, demand) result(g)
    integer, intent(in) :: mode          !! strut_mode code [-]
    integer, intent(in) :: dir           !! sliding direction [-]
    real(wp), intent(in) :: s            !! stroke [m]
    real(wp), intent(in) :: sd_after     !! stroke rate after the step's velocity update [m/s]
    real(wp), intent(in) :: lo           !! lower end of the free range [m]
    real(wp), intent(in) :: hi           !! upper end of the free range [m]
    real(wp), intent(in) :: fpos         !! bound against motion toward +s [N]
    real(wp), intent(in) :: fneg         !! bound against motion toward -s [N]
    real(wp), intent(in) :: demand       !! generalized force of the lock on the stroke (sigma * axial) [N]
    select case (mode)
    case (0)
      g = min(fpos + demand, fneg - demand)
    case (1, -1)
      g = real(dir, wp)*sd_after
    case default
      g = min(hi - s, s - lo)
    end select
  end function mode_margin

  !> alpha when given, else zero.
  pure function alpha_or_zero(alpha) result(a)
    real(wp), intent(in), optional :: alpha(3)   !! [rad/s^2]
    real(wp) :: a(3)                             !! [rad/s^2]
    a = 0.0_wp
    if (present(alpha)) a = alpha
  end function alpha_or_zero

  !> The rigid gear's caches (strut kinematics, mass matrix, constraint rows with the three lock rows
  !! and the Cholesky factor of A M^-1 A^T), computed from its coordinates.
  subroutine rigid_cache(gear, c, status)
    type(tripod_gear_t), intent(in) :: gear             !! gear (geometry, masses)
    type(gear_state_t), intent(inout) :: c       !! state whose caches are set
    type(status_t), intent(inout) :: status      !! STAT_OK on entry; the factorisation's failure [-]
    integer :: k, i, j, nrow
    nrow = n_phi + 3
    ! afresh, not strut_kinematics: c may be gear%st, whose kinematics cache this must not read
    call kinematics_at(gear%geom, gear%strut, c%q, c%sk_c)
    c%mdiag_c = mass_diagonal(c%sk_c, c%q)
    c%a_c(1:n_phi, :) = gear_constraint_jacobian(gear%geom, c%q)
    do k = 1, 3
      c%a_c(n_phi + k, :) = 0.0_wp
      c%a_c(n_phi + k, idx_len(k)) = 1.0_wp
    end do
    do j = 1, nrow
      do i = 1, j
        c%chol_c(i, j) = sum(c%a_c(i, :)*c%a_c(j, :)/c%mdiag_c)
      end do
    end do
    call factor_spd(nrow, c%chol_c, max_rows, status, 'gear DAE, rigid (A M^-1 A^T)')
    if (status%code /= STAT_OK) return
    c%rigid_cache = .true.
  end subroutine rigid_cache

  !> The lock forces of a rigid gear with its cached factor (rigid_dynamics).
  subroutine rigid_solve(gear, c, ge, f_foot, f_field, loads, done, alpha)
    type(tripod_gear_t), intent(in) :: gear             !! rigid gear
    type(gear_state_t), intent(in) :: c          !! its state with valid caches
    type(gear_eval_t), intent(inout) :: ge       !! its evaluation
    real(wp), intent(in) :: f_foot(3)            !! ground force on the footpad, gear frame [N]
    real(wp), intent(in) :: f_field(3)           !! uniform field, gear frame [m/s^2]
    logical, intent(in) :: loads                 !! compute the interface loads [-]
    logical, intent(out) :: done                 !! .true. when the gear stays rigid this step
    real(wp), intent(in), optional :: alpha(3)   !! body angular acceleration, gear axes [rad/s^2]
    real(wp) :: q_ine(n_q), q_grv(n_q), q_ext(n_q), qf(n_q), lam(max_rows), zero(n_q), f_strut(3, 3)
    real(wp) :: s(3), sd(3), fpos, fneg, demand
    integer :: k, i, nrow
    done = .false.
    nrow = n_phi + 3
    zero = 0.0_wp
    call generalized_forces(c%q, zero, c%sk_c, f_field, f_foot, q_ine, q_grv, q_ext)
    qf = q_grv + q_ext
    if (present(alpha)) qf = qf + alpha_forces(gear, c%q, c%sk_c, alpha)
    qf = qf/c%mdiag_c
    do i = 1, nrow
      lam(i) = dot_product(c%a_c(i, :), qf)
    end do
    ! the cached factor's solves in the order of operations of LAPACK's dpotrs (landyn_small_spd)
    call small_upper_solve_multi(nrow, 1, c%chol_c, max_rows, lam, max_rows)
    call strokes(gear, c%q, zero, s, sd)
    ge%stroke(1:3) = s
    do k = 1, 3
      ge%axial(k) = -lam(n_phi + k)
      call gear%buffer(k)%law%resistance(s(k), 0.0_wp, c%s_hismin(k), c%s_hismax(k), fpos, fneg)
      if (k == 1 .and. gear%tube%on) call add_tube_bound(ge%tube_bound, fpos, fneg)   ! tube friction (eq. 24)
      demand = gear%sigma(k)*ge%axial(k)
      if (-demand > fpos .or. demand > fneg) then
        ge%rigid = .false.
        return
      end if
      ge%margin_in(k) = mode_margin(0, 0, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, fpos, fneg, demand)
      ge%margin_out(k) = ge%margin_in(k)
    end do
    ge%qdd = 0.0_wp
    ge%f_body = f_foot
    ge%m_body = cross3(gear%geom%a + c%q(1)*c%sk_c(1)%u, f_foot)
    f_strut = 0.0_wp
    if (loads) call joint_loads(gear, c%sk_c, c%q, zero, zero, f_strut, f_strut, lam(1:n_phi), f_foot, f_field, &
                                alpha_or_zero(alpha), ge%f_body, ge%f_joint, ge%m_joint, ge%f_interface)
    done = .true.
  end subroutine rigid_solve

  module procedure gear_dynamics
    type(gear_eval_t) :: ge
    call gear_prepare(gear, status)
    if (status%code /= STAT_OK) return
    call gear_evaluate(gear, ge, f_foot, f_field, status, dt, alpha)
    if (status%code /= STAT_OK) return
    call gear_commit(gear, ge)
  end procedure gear_dynamics

  module procedure gear_commit
    gear%st%dir_after = ge%dir_after(1:n_struts)
    gear%st%axial_after = ge%axial_after(1:n_struts)
    gear%st%qdd = ge%qdd
    gear%st%axial = ge%axial
    gear%st%f_body = ge%f_body
    gear%st%m_body = ge%m_body
    gear%st%locked = ge%locked
    gear%st%dir = ge%dir
    gear%st%s_lock = ge%s_lock
    gear%st%tube_bound = ge%tube_bound
    if (gear%st%rigid .and. .not. ge%rigid) then
      gear%st%rigid = .false.
      gear%st%rigid_cache = .false.
    end if
  end procedure gear_commit

  module procedure gear_prepare
    if (gear%st%rigid .and. .not. gear%st%rigid_cache) call rigid_cache(gear, gear%st, status)
  end procedure gear_prepare

end submodule landyn_tripod_dynamics
