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
!!
!! Every sum is formed in one fixed order: from zero, in index order (over the system's rows gear
!! by gear, in row order), as gfortran forms sum, dot_product and matmul; the results depend on it
!! bit for bit (the fixed integrator reproduces the paper's scheme). The loops are arranged so that
!! the compiler can use vector instructions (independent sums side by side), never by reordering a
!! sum.
module landyn_impact
  use landyn_kinds, only: wp, max_gears, max_gear_q, max_gear_rows
  use landyn_body, only: body_t
  use landyn_gear_base, only: gear_base_t, gear_slot_t
  use landyn_kinematics, only: mv3
  use landyn_status, only: STAT_OK, status_t
  use landyn_lapack, only: factor_spd_unblocked
  use landyn_small_spd, only: small_upper_solve, small_upper_solve_rows, solve_rows_width
  implicit none
  private

  public :: system_velocity_projection

contains

  !> Coupling block C_i (6 x max_gear_q, zero beyond the gear's coordinates) of gear i: rows 1-3
  !! map qd_i to the legs' relative linear momentum in global axes, rows 4-6 to their relative
  !! angular momentum about the mass centre in lander axes. Written in place; the 3 x 3 products
  !! are landyn_kinematics' mv3 written out (the same operations in the same order).
  pure subroutine coupling_block(body, gear, nq, c)
    type(body_t), intent(in) :: body        !! body (attitude r, mass centre mc)
    class(gear_base_t), intent(in) :: gear  !! gear
    integer, intent(in) :: nq               !! its coordinate count [-]
    real(wp), intent(out) :: c(6, max_gear_q)  !! coupling [kg, kg m, kg m^2]
    real(wp) :: pm(3, max_gear_q), hm(3, max_gear_q), pl(3), hl(3), rot(3, 3)
    integer :: j
    call gear%momentum_maps(pm, hm)
    rot = gear%rotation()
    if (nq < max_gear_q) c = 0.0_wp      ! the columns beyond the gear's coordinates
    associate (r => body%r, mc => body%mc)
      do j = 1, nq
        pl(1) = rot(1, 1)*pm(1, j) + rot(1, 2)*pm(2, j) + rot(1, 3)*pm(3, j)
        pl(2) = rot(2, 1)*pm(1, j) + rot(2, 2)*pm(2, j) + rot(2, 3)*pm(3, j)
        pl(3) = rot(3, 1)*pm(1, j) + rot(3, 2)*pm(2, j) + rot(3, 3)*pm(3, j)
        hl(1) = rot(1, 1)*hm(1, j) + rot(1, 2)*hm(2, j) + rot(1, 3)*hm(3, j)
        hl(2) = rot(2, 1)*hm(1, j) + rot(2, 2)*hm(2, j) + rot(2, 3)*hm(3, j)
        hl(3) = rot(3, 1)*hm(1, j) + rot(3, 2)*hm(2, j) + rot(3, 3)*hm(3, j)
        c(1, j) = r(1, 1)*pl(1) + r(1, 2)*pl(2) + r(1, 3)*pl(3)
        c(2, j) = r(2, 1)*pl(1) + r(2, 2)*pl(2) + r(2, 3)*pl(3)
        c(3, j) = r(3, 1)*pl(1) + r(3, 2)*pl(2) + r(3, 3)*pl(3)
        c(4, j) = hl(1) - (mc(2)*pl(3) - mc(3)*pl(2))
        c(5, j) = hl(2) - (mc(3)*pl(1) - mc(1)*pl(3))
        c(6, j) = hl(3) - (mc(1)*pl(2) - mc(2)*pl(1))
      end do
    end associate
  end subroutine coupling_block

  !> One gear's blocks of the elimination: S -= C_i Mq_i^-1 C_i^T (upper triangle), U_i^T =
  !! C_i Mq_i^-1 A_i^T and D_i = A_i Mq_i^-1 A_i^T (upper triangle). Each entry is the sum over all
  !! max_gear_q columns m, from zero and in column order, of (x_m / Mq_m) y_m (the scaled rows are
  !! formed once); the six entries of a column of S or U_i^T are summed side by side.
  pure subroutine gear_blocks(n, a, minv, c, s, ut, d)
    integer, intent(in) :: n                               !! the gear's constraint rows [-]
    real(wp), intent(in) :: a(max_gear_rows, max_gear_q)   !! rows A_i [m/rad, -]
    real(wp), intent(in) :: minv(max_gear_q)               !! Mq_i^-1, 0 beyond the coordinates [1/kg, 1/(kg m^2)]
    real(wp), intent(in) :: c(6, max_gear_q)               !! coupling C_i [kg, kg m, kg m^2]
    real(wp), intent(inout) :: s(6, 6)                     !! body Schur complement [kg, kg m, kg m^2]
    real(wp), intent(out) :: ut(6, max_gear_rows)          !! U_i^T, columns 1 to n [A Mq^-1 C^T]
    real(wp), intent(out) :: d(max_gear_rows, max_gear_rows)  !! D_i, upper triangle of order n [A Mq^-1 A^T]
    real(wp) :: cm(6, max_gear_q), am(max_gear_rows, max_gear_q), t6(6), t
    integer :: ii, jj, k, m
    do m = 1, max_gear_q
      cm(:, m) = c(:, m)*minv(m)
    end do
    do jj = 1, 6
      t6 = 0.0_wp
      do m = 1, max_gear_q
        t6 = t6 + cm(:, m)*c(jj, m)
      end do
      s(1:jj, jj) = s(1:jj, jj) - t6(1:jj)
    end do
    do k = 1, n
      t6 = 0.0_wp
      do m = 1, max_gear_q
        am(k, m) = a(k, m)*minv(m)
        t6 = t6 + c(:, m)*am(k, m)
      end do
      ut(:, k) = t6
    end do
    do jj = 1, n
      do ii = 1, jj
        t = 0.0_wp
        do m = 1, max_gear_q
          t = t + am(ii, m)*a(jj, m)
        end do
        d(ii, jj) = t
      end do
    end do
  end subroutine gear_blocks

  !> Projects the velocities of the body and all non-rigid gears onto the gears' velocity
  !! constraints in the kinetic metric of the whole system (a plastic impact, see the module
  !! header). Nothing is done when every residual |A_i qd_i| is within `tol`.
  subroutine system_velocity_projection(body, gear, ng, tol, dissipated, status)
    type(body_t), intent(inout) :: body          !! body; v and omega are updated
    type(gear_slot_t), intent(inout) :: gear(:)  !! gears; qd of the non-rigid ones is updated
    integer, intent(in) :: ng                    !! number of gears [-]
    real(wp), intent(in) :: tol                  !! residual below which nothing is done [m/s, rad/s]
    real(wp), intent(out) :: dissipated          !! kinetic energy lost, >= 0 [J]
    type(status_t), intent(inout) :: status      !! STAT_OK on entry; the failure's code and diagnosis [-]
    real(wp) :: a(max_gear_rows, max_gear_q, max_gears), c(6, max_gear_q, max_gears), minv(max_gear_q, max_gears)
    real(wp) :: g(max_gear_rows, max_gears), ut(6, max_gear_rows, max_gears)
    real(wp) :: w(solve_rows_width, max_gear_rows, max_gears), d(max_gear_rows, max_gear_rows)
    real(wp) :: s(6, 6), kk(6, 6), rr(6), tk(6, 7), dq(max_gear_q), qd(max_gear_q), resid
    integer :: nrow(max_gears), nq(max_gears), act(max_gears), i, j, k, jj, n, n_act

    dissipated = 0.0_wp
    ! Active gears and their residuals g_i = A_i qd_i (the system's rows gear by gear).
    n_act = 0
    resid = 0.0_wp
    do i = 1, ng
      if (gear(i)%g%is_rigid()) cycle
      n_act = n_act + 1
      act(n_act) = i
      nq(n_act) = gear(i)%g%coordinate_count()
      ! (the gear may keep the rows, e.g. Phi_q at this configuration, for its next evaluation)
      call gear(i)%g%velocity_rows(a(:, :, n_act), nrow(n_act))
      ! (a gear with fewer coordinates than max_gear_q has zero columns and rates beyond them)
      if (nq(n_act) < max_gear_q) qd = 0.0_wp
      call gear(i)%g%rates(qd(1:nq(n_act)))
      do k = 1, nrow(n_act)
        g(k, n_act) = dot_product(a(k, :, n_act), qd)
      end do
      resid = max(resid, maxval(abs(g(1:nrow(n_act), n_act))))
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
      n = nrow(j)
      ! zero inverse masses beyond the gear's coordinates: those columns take no part
      if (nq(j) < max_gear_q) minv(:, j) = 0.0_wp
      call gear(i)%g%mass_diagonal(dq(1:nq(j)))
      minv(1:nq(j), j) = 1.0_wp/dq(1:nq(j))
      call coupling_block(body, gear(i)%g, nq(j), c(:, :, j))
      call gear_blocks(n, a(:, :, j), minv(:, j), c(:, :, j), s, ut(:, :, j), d)
      call factor_spd_unblocked(n, d, max_gear_rows, status, 'system velocity projection (A M^-1 A^T)')
      if (status%code /= STAT_OK) then
        call status%fail(status%code, status%text()//': redundant velocity constraints or a singular configuration')
        return
      end if
      ! [z_i, Z_i] = D_i^-1 [g_i, U_i], stored transposed (row 1 z_i^T, rows 2-7 Z_i^T, the rest zero)
      do k = 1, n
        w(1, k, j) = g(k, j)
        w(2:7, k, j) = ut(:, k, j)
        w(8:, k, j) = 0.0_wp
      end do
      call small_upper_solve_rows(n, d, max_gear_rows, w(:, :, j))
      ! K += U_i^T Z_i, r += U_i^T z_i (each entry summed over the gear's rows from zero)
      tk = 0.0_wp
      do k = 1, n
        do jj = 1, 7
          tk(:, jj) = tk(:, jj) + ut(:, k, j)*w(jj, k, j)
        end do
      end do
      rr = rr + tk(:, 1)
      do jj = 1, 6
        kk(1:jj, jj) = kk(1:jj, jj) + tk(1:jj, 1 + jj)
      end do
    end do
    kk = kk + s
    call factor_spd_unblocked(6, s, 6, status, 'system velocity projection (body Schur complement)')
    if (status%code /= STAT_OK) then
      call status%fail(status%code, status%text()//': the legs are too heavy for the body (kinetic energy not positive definite)')
      return
    end if
    call factor_spd_unblocked(6, kk, 6, status, 'system velocity projection (Woodbury capacitance)')
    if (status%code /= STAT_OK) return
    ! t = K^-1 r
    call small_upper_solve(6, kk, 6, rr, .true.)
    call small_upper_solve(6, kk, 6, rr, .false.)
    call apply_impulses(body, gear, n_act, act, nrow, nq, a, c, minv, g, ut, w, s, rr, dissipated)
  end subroutine system_velocity_projection

  !> The last steps of the projection, with t = K^-1 r at hand: lam = z - Z t, the energy lost
  !! 1/2 lam^T g, y = S^-1 U^T lam, dqd_i = -Mq_i^-1 (A_i^T lam_i + C_i^T y) and
  !! dv_b = -Mb^-1 sum C_i dqd_i. Every sum over the system's rows runs gear by gear in row order
  !! from zero, every other sum from zero in index order.
  subroutine apply_impulses(body, gear, n_act, act, nrow, nq, a, c, minv, g, ut, w, s, kr, dissipated)
    type(body_t), intent(inout) :: body            !! body; v and omega are updated
    type(gear_slot_t), intent(inout) :: gear(:)    !! gears; qd of the active ones is updated
    integer, intent(in) :: n_act                   !! number of active gears [-]
    integer, intent(in) :: act(max_gears)          !! their indices in gear [-]
    integer, intent(in) :: nrow(max_gears)         !! their constraint rows [-]
    integer, intent(in) :: nq(max_gears)           !! their coordinate counts [-]
    real(wp), intent(in) :: a(max_gear_rows, max_gear_q, max_gears)  !! rows A_i [m/rad, -]
    real(wp), intent(in) :: c(6, max_gear_q, max_gears)  !! couplings C_i [kg, kg m, kg m^2]
    real(wp), intent(in) :: minv(max_gear_q, max_gears)  !! Mq_i^-1 [1/kg, 1/(kg m^2)]
    real(wp), intent(in) :: g(max_gear_rows, max_gears)  !! residuals g_i = A_i qd_i [m/s, rad/s]
    real(wp), intent(in) :: ut(6, max_gear_rows, max_gears)  !! U_i^T [A Mq^-1 C^T]
    real(wp), intent(in) :: w(solve_rows_width, max_gear_rows, max_gears)  !! [z_i, Z_i]^T [D^-1 g, D^-1 U]
    real(wp), intent(in) :: s(6, 6)                !! Cholesky factor of S [kg^1/2, ...]
    real(wp), intent(in) :: kr(6)                  !! t = K^-1 r [m/s, rad/s]
    real(wp), intent(out) :: dissipated            !! kinetic energy lost [J]
    real(wp) :: lam(max_gear_rows, max_gears), y(6), dq(max_gear_q), qd(max_gear_q), db(6), r6(6), e, p
    integer :: i, j, k, ii, m
    y = 0.0_wp
    e = 0.0_wp
    do j = 1, n_act
      do k = 1, nrow(j)
        p = 0.0_wp
        do ii = 1, 6
          p = p + w(1 + ii, k, j)*kr(ii)
        end do
        lam(k, j) = w(1, k, j) - p
        e = e + lam(k, j)*g(k, j)
        y = y + lam(k, j)*ut(:, k, j)
      end do
    end do
    dissipated = 0.5_wp*e
    call small_upper_solve(6, s, 6, y, .true.)
    call small_upper_solve(6, s, 6, y, .false.)
    db = 0.0_wp
    do j = 1, n_act
      i = act(j)
      dq = 0.0_wp
      do k = 1, nrow(j)
        dq = dq + lam(k, j)*a(k, :, j)
      end do
      do m = 1, max_gear_q
        p = 0.0_wp
        do ii = 1, 6
          p = p + y(ii)*c(ii, m, j)
        end do
        dq(m) = -minv(m, j)*(dq(m) + p)
      end do
      call gear(i)%g%rates(qd(1:nq(j)))
      qd(1:nq(j)) = qd(1:nq(j)) + dq(1:nq(j))
      call gear(i)%g%set_rates(qd(1:nq(j)))
      r6 = 0.0_wp
      do m = 1, max_gear_q
        r6 = r6 + c(:, m, j)*dq(m)
      end do
      db = db + r6
    end do
    body%v = body%v - db(1:3)/body%mass
    body%omega = body%omega - mv3(body%inv_inertia, db(4:6))
  end subroutine apply_impulses

end module landyn_impact
