!> Interface loads of a gear: the forces and moments of the upper joints on the body and of the
!! footpad on the primary, from each strut's free-body balance (landyn_loads collects them).
submodule (landyn_tripod_gear) landyn_tripod_joint_loads
  use landyn_kinematics, only: cross3
  implicit none

contains

  module procedure joint_loads
    real(wp) :: f_low(3, 3), f_fld(3), sm, ud(3), udd(3), dd(3), fm(3), m_leg, jr, tau(3), n(3), r0(3, 3)
    real(wp) :: d(3), e_pri(3), f_pri(3), e_sec(3), f_sec(3), rp(3, 3)
    integer :: k, i0
    type(strut_mass_functions_t) :: mf
    f_low(:, 1) = f_foot - lam_phi(1:3) - lam_phi(4:6)
    f_low(:, 2) = lam_phi(1:3)
    f_low(:, 3) = lam_phi(4:6)
    ! Lower ends and lugs. No trigonometry: the primary's orientation R0 Rx(t1) Ry(t2) has the
    ! columns u2 = du/dt2, u x u2 and u.
    rp(:, 1) = sk(1)%u2
    rp(:, 2) = cross3(sk(1)%u, sk(1)%u2)
    rp(:, 3) = sk(1)%u
    d = sk(1)%p + q(idx_len(1))*sk(1)%u
    e_pri = sk(1)%p + matmul(rp, gear%geom%e_loc)
    f_pri = sk(1)%p + matmul(rp, gear%geom%f_loc)
    e_sec = sk(2)%p + q(idx_len(2))*sk(2)%u
    f_sec = sk(3)%p + q(idx_len(3))*sk(3)%u
    do k = 1, 3
      mf = sk(k)%mf
      sm = mf%s
      jr = mf%j
      ! force: body on strut = f_k - field - lower-end forces; the joint's force on the body is its negative
      f_fld = mf%m_tot*f_field - cross3(alpha, mf%m_tot*(sk(k)%p - gear%geom%a) + sm*sk(k)%u)
      f_joint(:, k) = f_fld + f_low(:, k) - f_strut(:, k)
      ! Moment. A universal joint with pins along w1 = R0 e_x (body) and w2 = R0 Rx(t1) e_y = u x u2
      ! (strut) transmits a moment about n = w1 x w2, the direction the strut's two angle equations
      ! leave free (its spin is not a degree of freedom): the joint supplies the n-component of (rate
      ! of angular momentum about the joint - moment of the other forces on the strut). The primary's
      ! lugs lie off its axis, so the primary's joint a carries a torque.
      select case (k)
      case (1)
        tau = cross3(d - sk(1)%p, f_foot) - cross3(e_pri - sk(1)%p, lam_phi(1:3)) - cross3(f_pri - sk(1)%p, lam_phi(4:6))
        r0 = gear%geom%R0p
      case (2)
        tau = cross3(e_sec - sk(2)%p, lam_phi(1:3))
        r0 = gear%geom%R0b
      case default
        tau = cross3(f_sec - sk(3)%p, lam_phi(4:6))
        r0 = gear%geom%R0c
      end select
      tau = tau + cross3(sm*sk(k)%u, f_field) - cross3(sm*sk(k)%u, cross3(alpha, sk(k)%p - gear%geom%a)) &
            - jr*cross3(sk(k)%u, cross3(alpha, sk(k)%u))
      n = cross3(r0(:, 1), cross3(sk(k)%u, sk(k)%u2))
      m_joint(:, k) = -dot_product(h_strut(:, k) - tau, n)*n
    end do
    ! footpad ball joint d = a + L u of the primary: its acceleration relative to the body
    i0 = idx_len(1) - 1
    ud = sk(1)%u1*qd(i0 + 2) + sk(1)%u2*qd(i0 + 3)
    udd = sk(1)%u1*qdd(i0 + 2) + sk(1)%u2*qdd(i0 + 3) + sk(1)%u11*qd(i0 + 2)**2 &
          + 2.0_wp*sk(1)%u12*qd(i0 + 2)*qd(i0 + 3) + sk(1)%u22*qd(i0 + 3)**2
    dd = qdd(i0 + 1)*sk(1)%u + 2.0_wp*qd(i0 + 1)*ud + q(i0 + 1)*udd
    f_joint(:, 4) = f_foot - gear%strut(1)%end_mass()*(dd - f_field + cross3(alpha, q(i0 + 1)*sk(1)%u))
    ! the leg's momentum balance, with the legs' first moment as gear_leg_momentum takes it
    fm = leg_first_moment(sk, q)
    m_leg = gear%leg_mass
    f_interface = f_body + m_leg*f_field - cross3(alpha, fm - m_leg*gear%geom%a)
  end procedure joint_loads

end submodule landyn_tripod_joint_loads
