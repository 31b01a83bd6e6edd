!> The tripod gear's kinematics (paper section 2.4, eqs. 6-8 and 16): the points of a gear at its
!! generalized coordinates, the lug constraints and their Jacobian and gamma, the footpad
!! Jacobian's force maps (the Jacobian itself, footpad_jacobians, is in core: build_gear_geometry
!! checks the nominal gear with it), the coordinates from a footpad position. The
!! coordinate layout (iq_*, n_gear_q), the gear geometry and the strut kinematics they are built
!! on are general and live in core/landyn_kinematics.f90 (whose header states the conventions).
!!
!! * Constraints (eq. 6): Phi(q) = [e_pri - e_sec; f_pri - f_sec] (6 rows). Phi does not depend
!!   on d1 (column 1 of Phi_q is zero): d1 is the primary stroke freedom. gamma = -(Phi_q qdot)_q
!!   qdot (eq. 16) is the right-hand side of the acceleration-level constraint Phi_q qddot = gamma.
!! * Virtual work (eq. 8): for a force F acting ON the footpad (gear frame), the strut-equivalent
!!   generalized forces are J^T F; component j is positive when F tends to LENGTHEN strut j.
!!   The footpad force equivalent to strut forces N (same sign convention) is J^{-T} N.
!!
!! Everything here is pure and allocation-free (fixed-size arrays) for use in the time-step loop.
module landyn_tripod_kinematics
  use landyn_kinds, only: wp
  use landyn_status, only: STAT_FAILED, status_t
  use landyn_kinematics, only: gear_geometry_t, joint_trig_t, axis_derivs_t, n_gear_q, n_gear_phi, &
                               iq_d1, iq_th1, iq_th2, iq_db1, iq_thb1, iq_thb2, iq_dc1, iq_thc1, iq_thc2, &
                               solve3, joint_trig, joint_rotation_derivs, strut_orientation_trig, &
                               strut_axis_trig, strut_axis_derivs_trig, strut_angles_from_point
  implicit none
  private

  public :: gear_trig, gear_points, gear_constraints, gear_constraint_jacobian, gear_constraint_gamma
  public :: strut_forces_from_footpad, footpad_force_from_struts
  public :: gear_coords_from_footpad

contains

  !> cos and sin of the joint angles of the three struts of a gear at coordinates q.
  pure function gear_trig(q) result(tr)
    real(wp), intent(in) :: q(n_gear_q)    !! generalized coordinates [m, rad]
    type(joint_trig_t) :: tr(3)            !! primary, left and right secondary [-]
    tr(1) = joint_trig(q(iq_th1), q(iq_th2))
    tr(2) = joint_trig(q(iq_thb1), q(iq_thb2))
    tr(3) = joint_trig(q(iq_thc1), q(iq_thc2))
  end function gear_trig

  ! =====================================================================================
  ! Gear kinematics, constraints and Jacobians
  ! =====================================================================================

  !> Points of a gear (gear frame) at generalized coordinates q.
  pure subroutine gear_points(geom, q, d, e_pri, f_pri, e_sec, f_sec, trig)
    type(gear_geometry_t), intent(in) :: geom  !! gear geometry
    real(wp), intent(in) :: q(n_gear_q)        !! generalized coordinates [m, rad]
    real(wp), intent(out) :: d(3)              !! footpad joint a + d1 u_p [m]
    real(wp), intent(out) :: e_pri(3)          !! left lug on the primary, a + Rp e_loc [m]
    real(wp), intent(out) :: f_pri(3)          !! right lug on the primary, a + Rp f_loc [m]
    real(wp), intent(out) :: e_sec(3)          !! lower end of the left secondary, b + db1 u_b [m]
    real(wp), intent(out) :: f_sec(3)          !! lower end of the right secondary, c + dc1 u_c [m]
    type(joint_trig_t), intent(in), optional :: trig(3)  !! gear_trig(q), when already at hand [-]
    real(wp) :: rp(3,3)
    type(joint_trig_t) :: tr(3)
    call trig_of(q, tr, trig)
    rp = strut_orientation_trig(geom%R0p, tr(1))
    d = geom%a + q(iq_d1)*rp(:,3)
    e_pri = geom%a + matmul(rp, geom%e_loc)
    f_pri = geom%a + matmul(rp, geom%f_loc)
    e_sec = geom%b + q(iq_db1)*strut_axis_trig(geom%R0b, tr(2))
    f_sec = geom%c + q(iq_dc1)*strut_axis_trig(geom%R0c, tr(3))
  end subroutine gear_points

  !> The joint trigonometry of a gear at q: trig when given (it must be gear_trig(q)), else
  !! gear_trig(q).
  pure subroutine trig_of(q, tr, trig)
    real(wp), intent(in) :: q(n_gear_q)                  !! generalized coordinates [m, rad]
    type(joint_trig_t), intent(out) :: tr(3)             !! gear_trig(q) [-]
    type(joint_trig_t), intent(in), optional :: trig(3)  !! gear_trig(q), when already at hand [-]
    if (present(trig)) then
      tr = trig
    else
      tr = gear_trig(q)
    end if
  end subroutine trig_of

  !> Constraint residual (eq. 6): Phi = [e_pri - e_sec; f_pri - f_sec].
  pure function gear_constraints(geom, q, trig) result(phi)
    type(gear_geometry_t), intent(in) :: geom  !! gear geometry
    real(wp), intent(in) :: q(n_gear_q)        !! generalized coordinates [m, rad]
    type(joint_trig_t), intent(in), optional :: trig(3)  !! gear_trig(q), when already at hand [-]
    real(wp) :: phi(n_gear_phi)                !! constraint residual [m]
    real(wp) :: d(3), e_pri(3), f_pri(3), e_sec(3), f_sec(3)
    call gear_points(geom, q, d, e_pri, f_pri, e_sec, f_sec, trig)
    phi(1:3) = e_pri - e_sec
    phi(4:6) = f_pri - f_sec
  end function gear_constraints

  !> Constraint Jacobian Phi_q (6x9), analytic. Column iq_d1 is zero. The secondaries' axis
  !! partials are taken from axes when given (strut_axis_derivs of the left and right secondary at
  !! q), and the joint trigonometry from trig.
  pure function gear_constraint_jacobian(geom, q, trig, axes) result(phi_q)
    type(gear_geometry_t), intent(in) :: geom  !! gear geometry
    real(wp), intent(in) :: q(n_gear_q)        !! generalized coordinates [m, rad]
    type(joint_trig_t), intent(in), optional :: trig(3)  !! gear_trig(q), when already at hand [-]
    type(axis_derivs_t), intent(in), optional :: axes(2) !! left, right secondary axes at q, when at hand [-, 1/rad, 1/rad^2]
    real(wp) :: phi_q(n_gear_phi, n_gear_q)    !! dPhi/dq [m/m = -, m/rad]
    real(wp) :: w(3,3), w1(3,3), w2(3,3), w11(3,3), w12(3,3), w22(3,3)
    type(joint_trig_t) :: tp
    type(axis_derivs_t) :: ab, ac
    call secondary_axes(geom, q, tp, ab, ac, trig, axes)
    phi_q = 0.0_wp
    call joint_rotation_derivs(tp, w, w1, w2, w11, w12, w22)
    phi_q(1:3, iq_th1) = matmul(geom%R0p, matmul(w1, geom%e_loc))
    phi_q(1:3, iq_th2) = matmul(geom%R0p, matmul(w2, geom%e_loc))
    phi_q(4:6, iq_th1) = matmul(geom%R0p, matmul(w1, geom%f_loc))
    phi_q(4:6, iq_th2) = matmul(geom%R0p, matmul(w2, geom%f_loc))
    phi_q(1:3, iq_db1) = -ab%u
    phi_q(1:3, iq_thb1) = -q(iq_db1)*ab%u1
    phi_q(1:3, iq_thb2) = -q(iq_db1)*ab%u2
    phi_q(4:6, iq_dc1) = -ac%u
    phi_q(4:6, iq_thc1) = -q(iq_dc1)*ac%u1
    phi_q(4:6, iq_thc2) = -q(iq_dc1)*ac%u2
  end function gear_constraint_jacobian

  !> The primary's joint trigonometry and the secondaries' axis partials at q: from trig and axes
  !! when given, else computed (the same values).
  pure subroutine secondary_axes(geom, q, tp, ab, ac, trig, axes)
    type(gear_geometry_t), intent(in) :: geom  !! gear geometry
    real(wp), intent(in) :: q(n_gear_q)        !! generalized coordinates [m, rad]
    type(joint_trig_t), intent(out) :: tp      !! the primary's joint trigonometry [-]
    type(axis_derivs_t), intent(out) :: ab     !! left secondary's axis partials [-, 1/rad, 1/rad^2]
    type(axis_derivs_t), intent(out) :: ac     !! right secondary's axis partials [-, 1/rad, 1/rad^2]
    type(joint_trig_t), intent(in), optional :: trig(3)  !! gear_trig(q), when already at hand [-]
    type(axis_derivs_t), intent(in), optional :: axes(2) !! left, right secondary axes at q, when at hand [-, 1/rad, 1/rad^2]
    type(joint_trig_t) :: tr(3)
    if (present(axes)) then
      if (present(trig)) then
        tp = trig(1)
      else
        tp = joint_trig(q(iq_th1), q(iq_th2))
      end if
      ab = axes(1)
      ac = axes(2)
    else
      call trig_of(q, tr, trig)
      tp = tr(1)
      call strut_axis_derivs_trig(geom%R0b, tr(2), ab%u, ab%u1, ab%u2, ab%u11, ab%u12, ab%u22)
      call strut_axis_derivs_trig(geom%R0c, tr(3), ac%u, ac%u1, ac%u2, ac%u11, ac%u12, ac%u22)
    end if
  end subroutine secondary_axes

  !> Acceleration right-hand side of eq. 16: gamma = -(Phi_q qdot)_q qdot, i.e. minus the
  !! second time derivative of Phi along the motion at qddot = 0 (Phi_q qddot = gamma). The
  !! secondaries' axis partials are taken from axes when given (they must be strut_axis_derivs
  !! of the left and right secondary at q), and the joint trigonometry from trig.
  pure function gear_constraint_gamma(geom, q, qdot, trig, axes) result(gamma)
    type(gear_geometry_t), intent(in) :: geom  !! gear geometry
    real(wp), intent(in) :: q(n_gear_q)        !! generalized coordinates [m, rad]
    real(wp), intent(in) :: qdot(n_gear_q)     !! generalized velocities [m/s, rad/s]
    type(joint_trig_t), intent(in), optional :: trig(3)  !! gear_trig(q), when already at hand [-]
    type(axis_derivs_t), intent(in), optional :: axes(2) !! left, right secondary axes at q, when at hand [-, 1/rad, 1/rad^2]
    real(wp) :: gamma(n_gear_phi)              !! convective term [m/s^2]
    real(wp) :: w(3,3), w1(3,3), w2(3,3), w11(3,3), w12(3,3), w22(3,3), wdd(3,3)
    real(wp) :: a1, a2, l, ldot
    type(joint_trig_t) :: tp
    type(axis_derivs_t) :: ab, ac
    call secondary_axes(geom, q, tp, ab, ac, trig, axes)
    call joint_rotation_derivs(tp, w, w1, w2, w11, w12, w22)
    a1 = qdot(iq_th1); a2 = qdot(iq_th2)
    wdd = a1*a1*w11 + 2.0_wp*a1*a2*w12 + a2*a2*w22
    gamma(1:3) = -matmul(geom%R0p, matmul(wdd, geom%e_loc))
    gamma(4:6) = -matmul(geom%R0p, matmul(wdd, geom%f_loc))

    a1 = qdot(iq_thb1); a2 = qdot(iq_thb2); l = q(iq_db1); ldot = qdot(iq_db1)
    gamma(1:3) = gamma(1:3) + 2.0_wp*ldot*(a1*ab%u1 + a2*ab%u2) &
                 + l*(a1*a1*ab%u11 + 2.0_wp*a1*a2*ab%u12 + a2*a2*ab%u22)
    a1 = qdot(iq_thc1); a2 = qdot(iq_thc2); l = q(iq_dc1); ldot = qdot(iq_dc1)
    gamma(4:6) = gamma(4:6) + 2.0_wp*ldot*(a1*ac%u1 + a2*ac%u2) &
                 + l*(a1*a1*ac%u11 + 2.0_wp*a1*a2*ac%u12 + a2*a2*ac%u22)
  end function gear_constraint_gamma

  !> Strut-equivalent generalized forces of a footpad force (eq. 8): J^T F. Component k is the
  !! generalized force along strut length k (primary, left, right), positive tending to LENGTHEN.
  pure function strut_forces_from_footpad(j, f) result(n)
    real(wp), intent(in) :: j(3,3)  !! footpad Jacobian J = J2 J3^{-1} [-]
    real(wp), intent(in) :: f(3)    !! force acting on the footpad, gear frame [N]
    real(wp) :: n(3)                !! strut generalized forces [N]
    n(1) = j(1,1)*f(1) + j(2,1)*f(2) + j(3,1)*f(3)
    n(2) = j(1,2)*f(1) + j(2,2)*f(2) + j(3,2)*f(3)
    n(3) = j(1,3)*f(1) + j(2,3)*f(2) + j(3,3)*f(3)
  end function strut_forces_from_footpad

  !> Footpad force equivalent to strut forces: F = J^{-T} N (solves J^T F = N by Cramer's rule).
  pure subroutine footpad_force_from_struts(j, n, f, status)
    real(wp), intent(in) :: j(3,3)           !! footpad Jacobian J = J2 J3^{-1} [-]
    real(wp), intent(in) :: n(3)             !! strut forces, positive tending to lengthen [N]
    real(wp), intent(out) :: f(3)            !! equivalent force on the footpad, gear frame [N]
    type(status_t), intent(out) :: status    !! STAT_OK, or STAT_FAILED when J is singular [-]
    real(wp) :: jt(3,3)
    jt = transpose(j)
    call solve3(jt, n, f, status)
    if (.not. status%ok()) call status%fail(status%code, 'footpad_force_from_struts: singular footpad Jacobian')
  end subroutine footpad_force_from_struts

  !> Consistent generalized coordinates for a footpad position: the primary from d, the lugs
  !! e_pri, f_pri from (th1, th2), the secondaries from the lugs. The result satisfies Phi = 0.
  pure subroutine gear_coords_from_footpad(geom, d, q, status)
    type(gear_geometry_t), intent(in) :: geom  !! gear geometry
    real(wp), intent(in) :: d(3)               !! footpad joint position, gear frame [m]
    real(wp), intent(out) :: q(n_gear_q)       !! generalized coordinates [m, rad]
    type(status_t), intent(out) :: status      !! STAT_OK, or STAT_FAILED on a zero-length strut [-]
    real(wp) :: rp(3,3), e_pri(3), f_pri(3)
    call strut_angles_from_point(geom%a, geom%R0p, d, q(iq_d1), q(iq_th1), q(iq_th2))
    rp = strut_orientation_trig(geom%R0p, joint_trig(q(iq_th1), q(iq_th2)))
    e_pri = geom%a + matmul(rp, geom%e_loc)
    f_pri = geom%a + matmul(rp, geom%f_loc)
    call strut_angles_from_point(geom%b, geom%R0b, e_pri, q(iq_db1), q(iq_thb1), q(iq_thb2))
    call strut_angles_from_point(geom%c, geom%R0c, f_pri, q(iq_dc1), q(iq_thc1), q(iq_thc2))
    if (.not. (q(iq_d1) > 0.0_wp .and. q(iq_db1) > 0.0_wp .and. q(iq_dc1) > 0.0_wp)) then
      call status%fail(STAT_FAILED, 'gear_coords_from_footpad: zero-length strut')
      return
    end if
  end subroutine gear_coords_from_footpad

end module landyn_tripod_kinematics
