!> Velocity projection of the whole lander as a plastic impact of the constrained system.
!!
!! State velocities v = (V, w, qd_1 ... qd_n): mass-centre velocity V (global), body rate w (lander
!! axes) and each gear's generalized velocities. The kinetic energy of the model is the quadratic
!! form T = 1/2 v^T M v with
!!   M = [[Mb, C], [C^T, Mq]],  Mb = diag(m, m, m, I),  Mq = blockdiag(M_i)  (M_i diagonal),
!!   C_i = [R R_i P_i ; R_i H_i - [mc]x R_i P_i],
!! where P_i and H_i map qd_i to the legs' relative linear momentum and relative angular momentum
!! about the lander origin (gear axes, the gear's momentum_maps), R_i is gear -> lander and R
!! lander -> global. The gears are of any type (gear_base_t), each with its own coordinate count.
!! The first block row of M v is the system's linear momentum and its angular momentum about the
!! mass centre: the exact cross terms V . p_rel + w . h_rel(mc) of the kinetic energy of a body
!! carrying the total mass with legs moving relative to it.
!!
!! After a step the gears' velocity constraints G v = 0 (G = [0, blockdiag(A_i)], A_i = Phi_q and
!! the lock rows) are violated: routinely by the integration error, and at an impact (a strut that
!! locks, meets its stop, a footpad that lands) by a finite amount. The new velocity is the
!! kinetic-metric projection
!!   v+ = v- - M^-1 G^T lam,  (G M^-1 G^T) lam = G v-,
!! i.e. the velocity of a perfectly plastic impact of the constrained system (Gauss's principle of
!! least constraint for impulses). Then Mb dv_b + C dqd = 0: linear and angular momentum are
!! conserved exactly (the impulses are internal), and T+ = T- - 1/2 lam^T G v- with
!! lam^T G v- = (G v-)^T W^-1 (G v-) >= 0: the projection never creates energy. The energy lost is
!! returned for the audit channel `strut_impacts`.
!!
!! Solution by block elimination (Mq diagonal): S = Mb - C Mq^-1 C^T (6 x 6, the body's inertia
!! as seen through the free legs), W = D + U S^-1 U^T with D = G Mq^-1 G^T block diagonal (one
!! block of at most max_gear_rows square per gear) and U = G Mq^-1 C^T; W is solved with the Woodbury identity,
!! so that only the blocks D_i and two 6 x 6 matrices are factored (LAPACK's unblocked Cholesky).
!! Gears that are rigid (all struts locked, qd = 0) take no part: their square regular A_i holds
!! qd_i = 0.
module landyn_impact
  use landyn_kinds, only: wp, msg_len, max_gears, max_gear_q, max_gear_rows
  use landyn_body, only: body_t
  use landyn_gear_base, only: gear_base_t, gear_slot_t
  use landyn_kinematics, only: mv3
  use landyn_status, only: STAT_OK
  use landyn_lapack, only: factor_spd_unblocked
  use landyn_small_spd, only: small_upper_solve, small_upper_solve_multi
  implicit none
  private

  public :: system_velocity_projection

  integer, parameter :: max_sys_rows = max_gear_rows*max_gears   !! constraint rows of all gears at most

contains

  !> Coupling block C_i (6 x coordinate count, in a 6 x max_gear_q array) of gear i: rows 1-3 map
  !! qd_i to the legs' relative linear momentum in global axes, rows 4-6 to their relative angular
  !! momentum about the mass centre in lander axes.
  pure function coupling_matrix(body, gear, nq) result(c)
    type(body_t), intent(in) :: body     !! body (attitude r, mass centre mc)
    class(gear_base_t), intent(in) :: gear  !! gear
    integer, intent(in) :: nq            !! its coordinate count [-]
    real(wp) :: c(6, max_gear_q)         !! coupling [kg, kg m, kg m^2]
    real(wp) :: pm(3, max_gear_q), hm(3, max_gear_q), pl(3), hl(3), rot(3, 3)
    integer :: j
    call gear%momentum_maps(pm, hm)
    rot = gear%rotation()
    if (nq < max_gear_q) c = 0.0_wp      ! the columns beyond the gear's coordinates
    do j = 1, nq
      pl = mv3(rot, pm(:, j))
      hl = mv3(rot, hm(:, j))
      c(1:3, j) = mv3(body%r, pl)
      c(4:6, j) = hl - [body%mc(2)*pl(3) - body%mc(3)*pl(2), body%mc(3)*pl(1) - body%mc(1)*pl(3), &
                        body%mc(1)*pl(2) - body%mc(2)*pl(1)]
    end do
  end function coupling_matrix

  !> Projects the velocities of the body and all non-rigid gears onto the gears' velocity
  !! constraints in the kinetic metric of the whole system (a plastic impact, see the module
  !! header). Nothing is done when every residual |A_i qd_i| is within `tol`.
  subroutine system_velocity_projection(body, gear, ng, tol, dissipated, stat, errmsg)
    type(body_t), intent(inout) :: body          !! body; v and omega are updated
    type(gear_slot_t), intent(inout) :: gear(:)  !! gears; qd of the non-rigid ones is updated
    integer, intent(in) :: ng                    !! number of gears [-]
    real(wp), intent(in) :: tol                  !! residual below which nothing is done [m/s, rad/s]
    real(wp), intent(out) :: dissipated          !! kinetic energy lost, >= 0 [J]
    integer, intent(out) :: stat                 !! 0 on success
    character(len=*), intent(inout) :: errmsg    !! message on failure
    real(wp) :: a(max_gear_rows, max_gear_q, max_gears), c(6, max_gear_q, max_gears), minv(max_gear_q, max_gears)
    real(wp) :: g(max_sys_rows), lam(max_sys_rows), u(max_sys_rows, 6), z(max_sys_rows), zz(max_sys_rows, 6)
    real(wp) :: d(max_gear_rows, max_gear_rows, max_gears), s(6, 6), kk(6, 6), rr(6), y(6), dq(max_gear_q), qd(max_gear_q)
    real(wp) :: db(6), resid, rhs(max_gear_rows, 7)
    integer :: nrow(max_gears), off(max_gears), nq(max_gears), i, j, k, ii, jj, nr, n_act
    integer :: act(max_gears)
    character(len=msg_len) :: m2

    stat = STAT_OK
    dissipated = 0.0_wp
    ! Active gears and their residuals.
    n_act = 0
    nr = 0
    resid = 0.0_wp
    do i = 1, ng
      if (gear(i)%g%is_rigid()) cycle
      n_act = n_act + 1
      act(n_act) = i
      nq(n_act) = gear(i)%g%coordinate_count()
      ! (the gear may keep the rows, e.g. Phi_q at this configuration, for its next evaluation)
      call gear(i)%g%velocity_rows(a(:, :, n_act), nrow(n_act))
      off(n_act) = nr
      ! (a gear with fewer coordinates than max_gear_q has zero columns and rates beyond them)
      if (nq(n_act) < max_gear_q) qd = 0.0_wp
      call gear(i)%g%rates(qd(1:nq(n_act)))
      do k = 1, nrow(n_act)
        g(nr + k) = dot_product(a(k, :, n_act), qd)
      end do
      resid = max(resid, maxval(abs(g(nr + 1:nr + nrow(n_act)))))
      nr = nr + nrow(n_act)
    end do
    if (n_act == 0 .or. resid <= tol) return

    ! S = Mb - sum C_i Mq_i^-1 C_i^T, U_i = A_i Mq_i^-1 C_i^T, D_i = A_i Mq_i^-1 A_i^T.
    ! W = D + U S^-1 U^T is solved with the Woodbury identity, so that only the per-gear blocks
    ! D_i (at most max_gear_rows square) and two 6 x 6 systems are factored:
    !   W^-1 g = D^-1 g - D^-1 U K^-1 U^T D^-1 g,  K = S + U^T D^-1 U.
    s = 0.0_wp
    do k = 1, 3
      s(k, k) = body%mass
    end do
    s(4:6, 4:6) = body%inertia
    kk = 0.0_wp
    rr = 0.0_wp
    do j = 1, n_act
      i = act(j)
      ! zero inverse masses beyond the gear's coordinates: those columns take no part
      if (nq(j) < max_gear_q) minv(:, j) = 0.0_wp
      call gear(i)%g%mass_diagonal(dq(1:nq(j)))
      minv(1:nq(j), j) = 1.0_wp/dq(1:nq(j))
      c(:, :, j) = coupling_matrix(body, gear(i)%g, nq(j))
      do jj = 1, 6
        do ii = 1, jj
          s(ii, jj) = s(ii, jj) - sum(c(ii, :, j)*minv(:, j)*c(jj, :, j))
        end do
      end do
      associate (n => nrow(j), o => off(j))
        do k = 1, n
          do ii = 1, 6
            u(o + k, ii) = sum(a(k, :, j)*minv(:, j)*c(ii, :, j))
          end do
        end do
        do jj = 1, n
          do ii = 1, jj
            d(ii, jj, j) = sum(a(ii, :, j)*minv(:, j)*a(jj, :, j))
          end do
        end do
        call factor_spd_unblocked(n, d(:, :, j), max_gear_rows, stat, m2, 'system velocity projection (A M^-1 A^T)')
        if (stat /= 0) then
          errmsg = trim(m2)//': redundant velocity constraints or a singular configuration'
          return
        end if
        ! [z, Z] = D_i^-1 [g_i, U_i] (one multi-column solve)
        rhs(1:n, 1) = g(o + 1:o + n)
        rhs(1:n, 2:7) = u(o + 1:o + n, :)
        call small_upper_solve_multi(n, 7, d(:, :, j), max_gear_rows, rhs, max_gear_rows)
        z(o + 1:o + n) = rhs(1:n, 1)
        zz(o + 1:o + n, :) = rhs(1:n, 2:7)
        ! K += U_i^T Z_i, r += U_i^T z_i
        do jj = 1, 6
          do ii = 1, jj
            kk(ii, jj) = kk(ii, jj) + dot_product(u(o + 1:o + n, ii), zz(o + 1:o + n, jj))
          end do
          rr(jj) = rr(jj) + dot_product(u(o + 1:o + n, jj), z(o + 1:o + n))
        end do
      end associate
    end do
    kk = kk + s
    call factor_spd_unblocked(6, s, 6, stat, m2, 'system velocity projection (body Schur complement)')
    if (stat /= 0) then
      errmsg = trim(m2)//': the legs are too heavy for the body (kinetic energy not positive definite)'
      return
    end if
    call factor_spd_unblocked(6, kk, 6, stat, m2, 'system velocity projection (Woodbury capacitance)')
    if (stat /= 0) then; errmsg = m2; return; end if
    ! t = K^-1 r;  lam = z - Z t
    call small_upper_solve(6, kk, 6, rr, .true.)
    call small_upper_solve(6, kk, 6, rr, .false.)
    lam(1:nr) = z(1:nr) - matmul(zz(1:nr, :), rr)
    dissipated = 0.5_wp*dot_product(lam(1:nr), g(1:nr))
    ! y = S^-1 U^T lam;  dqd_i = -Mq_i^-1 (A_i^T lam_i + C_i^T y);  dv_b = -Mb^-1 sum C_i dqd_i.
    y = matmul(lam(1:nr), u(1:nr, :))
    call small_upper_solve(6, s, 6, y, .true.)
    call small_upper_solve(6, s, 6, y, .false.)
    db = 0.0_wp
    do j = 1, n_act
      i = act(j)
      dq = matmul(lam(off(j) + 1:off(j) + nrow(j)), a(1:nrow(j), :, j)) + matmul(y, c(:, :, j))
      dq = -minv(:, j)*dq
      associate (m => nq(j))
        call gear(i)%g%rates(qd(1:m))
        call gear(i)%g%set_rates(qd(1:m) + dq(1:m))
      end associate
      db = db + matmul(c(:, :, j), dq)
    end do
    body%v = body%v - db(1:3)/body%mass
    body%omega = body%omega - mv3(body%inv_inertia, db(4:6))
  end subroutine system_velocity_projection

end module landyn_impact
