!> The gear's inertia and momentum terms (paper section 2.4): generalized forces of the velocity
!! coupling, of the uniform frame field, of the footpad force and of the frame's angular
!! acceleration; the rates and values of the legs' relative linear and angular momentum; the maps
!! from the generalized velocities to them (used by the system velocity projection).
!!
!! The gear frame accelerates with the body: the leg parts feel the uniform field
!! f = g - a_body(a_i) (gravity minus the acceleration of the upper primary joint), taken from the
!! previous step. Rotational (centrifugal, Coriolis) frame terms are neglected: the body rotates at
!! a few deg/s at most, and their effect on a leg of tens of kg is far below the crush levels.
module landyn_gear_inertia
  use landyn_kinds, only: wp
  use landyn_strut, only: strut_mass_functions_t
  use landyn_kinematics, only: cross3
  use landyn_gear_model, only: gear_t, strut_kin_t, n_q, n_struts, idx_len, strut_kinematics, leg_first_moment
  implicit none
  private

  public :: gear_generalized_forces, generalized_forces, alpha_forces
  public :: gear_relative_inertia, relative_inertia, gear_relative_momenta, gear_leg_momentum, gear_momentum_maps

contains

  !> Generalized forces: velocity coupling (Q_ine), the uniform field (Q_grv) and the footpad force.
  pure subroutine gear_generalized_forces(gear, q, qd, f_field, f_foot, q_ine, q_grv, q_ext)
    type(gear_t), intent(in) :: gear     !! gear
    real(wp), intent(in) :: q(n_q)       !! coordinates [m, rad]
    real(wp), intent(in) :: qd(n_q)      !! velocities [m/s, rad/s]
    real(wp), intent(in) :: f_field(3)   !! uniform acceleration field (gravity - frame acceleration), gear frame [m/s^2]
    real(wp), intent(in) :: f_foot(3)    !! force on the footpad, gear frame [N]
    real(wp), intent(out) :: q_ine(n_q)  !! velocity-coupling generalized force [N, N m]
    real(wp), intent(out) :: q_grv(n_q)  !! field generalized force [N, N m]
    real(wp), intent(out) :: q_ext(n_q)  !! footpad-force generalized force [N, N m]
    type(strut_kin_t) :: sk(3)
    call strut_kinematics(gear, q, sk)
    call generalized_forces(q, qd, sk, f_field, f_foot, q_ine, q_grv, q_ext)
  end subroutine gear_generalized_forces

  !> generalized_forces with the strut kinematics and mass functions at q given.
  pure subroutine generalized_forces(q, qd, sk, f_field, f_foot, q_ine, q_grv, q_ext)
    real(wp), intent(in) :: q(n_q)         !! coordinates [m, rad]
    real(wp), intent(in) :: qd(n_q)        !! velocities [m/s, rad/s]
    type(strut_kin_t), intent(in) :: sk(3) !! strut kinematics at q
    real(wp), intent(in) :: f_field(3)     !! uniform field, gear frame [m/s^2]
    real(wp), intent(in) :: f_foot(3)      !! footpad force, gear frame [N]
    real(wp), intent(out) :: q_ine(n_q)    !! velocity coupling [N, N m]
    real(wp), intent(out) :: q_grv(n_q)    !! field [N, N m]
    real(wp), intent(out) :: q_ext(n_q)    !! footpad force [N, N m]
    integer :: k, i0
    type(strut_mass_functions_t) :: mf
    real(wp) :: jr, jp, c, sn, len, lend, t1d, t2d, fm
    do k = 1, 3
      i0 = idx_len(k) - 1
      len = q(i0 + 1); lend = qd(i0 + 1); t1d = qd(i0 + 2); t2d = qd(i0 + 3)
      mf = sk(k)%mf
      jr = mf%j
      jp = mf%dj
      c = cos(q(i0 + 3)); sn = sin(q(i0 + 3))
      q_ine(i0 + 1) = 0.5_wp*jp*(c*c*t1d*t1d + t2d*t2d)
      q_ine(i0 + 2) = -jp*lend*c*c*t1d + 2.0_wp*jr*c*sn*t1d*t2d
      q_ine(i0 + 3) = -jp*lend*t2d - jr*c*sn*t1d*t1d
      fm = mf%s
      q_grv(i0 + 1) = mf%m_s*dot_product(sk(k)%u, f_field)
      q_grv(i0 + 2) = fm*dot_product(sk(k)%u1, f_field)
      q_grv(i0 + 3) = fm*dot_product(sk(k)%u2, f_field)
    end do
    q_ext = 0.0_wp
    q_ext(1) = dot_product(sk(1)%u, f_foot)
    q_ext(2) = q(1)*dot_product(sk(1)%u1, f_foot)
    q_ext(3) = q(1)*dot_product(sk(1)%u2, f_foot)
  end subroutine generalized_forces

  !> Generalized force -H_a^T alpha of the non-uniform part of the frame's angular-acceleration
  !! field, -alpha x (r - a) on every leg part (r - a measured from the upper primary joint a):
  !! per strut, with P its upper joint, the columns of H_a are those of the relative angular
  !! momentum about a, (P - a) x p_j + J u x u_j (see gear_momentum_maps).
  pure function alpha_forces(gear, q, sk, alpha) result(qa)
    type(gear_t), intent(in) :: gear       !! gear
    real(wp), intent(in) :: q(n_q)         !! coordinates [m, rad]
    type(strut_kin_t), intent(in) :: sk(3) !! strut kinematics at q
    real(wp), intent(in) :: alpha(3)       !! angular acceleration, gear axes [rad/s^2]
    real(wp) :: qa(n_q)                    !! generalized force [N, N m]
    integer :: k, i0
    type(strut_mass_functions_t) :: mf
    real(wp) :: len, sm, jr, pa(3)
    do k = 1, 3
      i0 = idx_len(k) - 1
      len = q(i0 + 1)
      mf = sk(k)%mf
      sm = mf%s
      jr = mf%j
      pa = sk(k)%p - gear%geom%a
      qa(i0 + 1) = -dot_product(alpha, mf%m_s*cross3(pa, sk(k)%u))
      qa(i0 + 2) = -dot_product(alpha, sm*cross3(pa, sk(k)%u1) + jr*cross3(sk(k)%u, sk(k)%u1))
      qa(i0 + 3) = -dot_product(alpha, sm*cross3(pa, sk(k)%u2) + jr*cross3(sk(k)%u, sk(k)%u2))
    end do
  end function alpha_forces

  !> Rate of the legs' relative linear momentum (f_rel) and of their relative angular momentum
  !! about the lander origin (m_rel), from q, qd, qdd. Per strut, with S = sum m r, S1 = sum over
  !! the sliding parts of m r and J(L) as in the mass matrix:
  !!   f = m_s Ldd u + 2 m_s Ld udot + S uddot,
  !!   H_dot about the upper joint P = u x (2 S1 Ld udot + J uddot), m = P x f + H_dot.
  pure subroutine gear_relative_inertia(gear, f_rel, m_rel)
    type(gear_t), intent(in) :: gear    !! gear with qdd set
    real(wp), intent(out) :: f_rel(3)   !! relative momentum rate, gear frame [N]
    real(wp), intent(out) :: m_rel(3)   !! relative angular momentum rate about O_L, gear axes [N m]
    type(strut_kin_t) :: sk(3)
    call strut_kinematics(gear, gear%st%q, sk)
    call relative_inertia(gear, sk, gear%st%qdd, f_rel, m_rel)
  end subroutine gear_relative_inertia

  pure subroutine relative_inertia(gear, sk, qdd, f_rel, m_rel, f_strut, h_strut)
    type(gear_t), intent(in) :: gear       !! gear (q, qd)
    type(strut_kin_t), intent(in) :: sk(3) !! strut kinematics at gear%st%q
    real(wp), intent(in) :: qdd(n_q)       !! generalized accelerations [m/s^2, rad/s^2]
    real(wp), intent(out) :: f_rel(3)      !! relative momentum rate, gear frame [N]
    real(wp), intent(out) :: m_rel(3)      !! relative angular momentum rate about O_L [N m]
    real(wp), intent(out), optional :: f_strut(3, 3)  !! each strut's share of f_rel [N]
    real(wp), intent(out), optional :: h_strut(3, 3)  !! rate of each strut's relative angular momentum
                                                      !! about its upper joint [N m]
    integer :: k, i0
    type(strut_mass_functions_t) :: mf
    real(wp) :: ud(3), udd(3), f(3), hd(3), len, ld, ldd, t1d, t2d, sm, s1, jr
    f_rel = 0.0_wp
    m_rel = 0.0_wp
    do k = 1, 3
      i0 = idx_len(k) - 1
      len = gear%st%q(i0 + 1); ld = gear%st%qd(i0 + 1); ldd = qdd(i0 + 1)
      mf = sk(k)%mf
      t1d = gear%st%qd(i0 + 2); t2d = gear%st%qd(i0 + 3)
      ud = sk(k)%u1*t1d + sk(k)%u2*t2d
      udd = sk(k)%u1*qdd(i0 + 2) + sk(k)%u2*qdd(i0 + 3) + sk(k)%u11*t1d*t1d &
            + 2.0_wp*sk(k)%u12*t1d*t2d + sk(k)%u22*t2d*t2d
      s1 = mf%s1
      sm = mf%s0 + s1
      jr = mf%j
      f = mf%m_s*ldd*sk(k)%u + 2.0_wp*mf%m_s*ld*ud + sm*udd
      if (present(f_strut)) f_strut(:, k) = f
      f_rel = f_rel + f
      hd = cross3(sk(k)%u, 2.0_wp*s1*ld*ud + jr*udd)
      if (present(h_strut)) h_strut(:, k) = hd
      m_rel = m_rel + cross3(sk(k)%p, f) + hd
    end do
  end subroutine relative_inertia

  !> Relative linear momentum, relative angular momentum about the lander origin and relative
  !! kinetic energy of the leg parts: per strut p = m_s Ld u + S udot and
  !! h = P x p + J(L) u x udot (spin about the axis neglected, as in the mass matrix).
  pure subroutine gear_relative_momenta(gear, p_rel, h_rel, t_rel)
    type(gear_t), intent(in) :: gear      !! gear
    real(wp), intent(out) :: p_rel(3)     !! sum m v_rel, gear frame [kg m/s]
    real(wp), intent(out) :: h_rel(3)     !! relative angular momentum about O_L, gear axes [kg m^2/s]
    real(wp), intent(out) :: t_rel        !! relative kinetic energy 1/2 qd^T M qd [J]
    type(strut_kin_t) :: sk(3)
    call strut_kinematics(gear, gear%st%q, sk)
    call momenta(gear, sk, gear%st%qd, p_rel, h_rel, t_rel)
  end subroutine gear_relative_momenta

  pure subroutine momenta(gear, sk, qd, p_rel, h_rel, t_rel)
    type(gear_t), intent(in) :: gear       !! gear (configuration gear%st%q)
    type(strut_kin_t), intent(in) :: sk(3) !! strut kinematics at gear%st%q
    real(wp), intent(in) :: qd(n_q)        !! generalized velocities [m/s, rad/s]
    real(wp), intent(out) :: p_rel(3)      !! sum m v_rel, gear frame [kg m/s]
    real(wp), intent(out) :: h_rel(3)      !! relative angular momentum about O_L [kg m^2/s]
    real(wp), intent(out) :: t_rel         !! relative kinetic energy [J]
    integer :: k, i0
    type(strut_mass_functions_t) :: mf
    real(wp) :: ud(3), p(3), len, sm, jr, c
    p_rel = 0.0_wp
    h_rel = 0.0_wp
    t_rel = 0.0_wp
    do k = 1, 3
      i0 = idx_len(k) - 1
      len = gear%st%q(i0 + 1)
      mf = sk(k)%mf
      ud = sk(k)%u1*qd(i0 + 2) + sk(k)%u2*qd(i0 + 3)
      sm = mf%s
      jr = mf%j
      p = mf%m_s*qd(i0 + 1)*sk(k)%u + sm*ud
      p_rel = p_rel + p
      h_rel = h_rel + cross3(sk(k)%p, p) + jr*cross3(sk(k)%u, ud)
      c = cos(gear%st%q(i0 + 3))
      t_rel = t_rel + 0.5_wp*(mf%m_s*qd(i0 + 1)**2 + jr*(c*c*qd(i0 + 2)**2 + qd(i0 + 3)**2))
    end do
  end subroutine momenta

  !> Relative linear momentum and first moment of mass of the leg parts (for the energy audit).
  pure subroutine gear_leg_momentum(gear, p_rel, first_moment, leg_mass)
    type(gear_t), intent(in) :: gear         !! gear
    real(wp), intent(out) :: p_rel(3)        !! sum m v_rel, gear frame [kg m/s]
    real(wp), intent(out) :: first_moment(3) !! sum m x, gear frame [kg m]
    real(wp), intent(out) :: leg_mass        !! sum m [kg]
    type(strut_kin_t) :: sk(3)
    integer :: k, i0
    type(strut_mass_functions_t) :: mf
    real(wp) :: ud(3), len, sm
    call strut_kinematics(gear, gear%st%q, sk)
    p_rel = 0.0_wp
    do k = 1, 3
      i0 = idx_len(k) - 1
      len = gear%st%q(i0 + 1)
      mf = sk(k)%mf
      ud = sk(k)%u1*gear%st%qd(i0 + 2) + sk(k)%u2*gear%st%qd(i0 + 3)
      sm = mf%s
      p_rel = p_rel + mf%m_s*gear%st%qd(i0 + 1)*sk(k)%u + sm*ud
    end do
    first_moment = leg_first_moment(sk, gear%st%q)
    leg_mass = gear%leg_mass
  end subroutine gear_leg_momentum

  !> Linear maps from the generalized velocities to the legs' relative linear momentum and their
  !! relative angular momentum about the lander origin, both in gear axes:
  !! p_rel = pm qd, h_rel = hm qd (the same quantities as gear_relative_momenta).
  pure subroutine gear_momentum_maps(gear, pm, hm)
    type(gear_t), intent(in) :: gear       !! gear
    real(wp), intent(out) :: pm(3, n_q)    !! d p_rel / d qd [kg, kg m]
    real(wp), intent(out) :: hm(3, n_q)    !! d h_rel / d qd [kg m, kg m^2]
    type(strut_kin_t) :: sk(3)
    integer :: k, i0
    type(strut_mass_functions_t) :: mf
    real(wp) :: len, sm, jr
    call strut_kinematics(gear, gear%st%q, sk)
    do k = 1, 3
      i0 = idx_len(k) - 1
      len = gear%st%q(i0 + 1)
      mf = sk(k)%mf
      sm = mf%s
      jr = mf%j
      pm(:, i0 + 1) = mf%m_s*sk(k)%u
      pm(:, i0 + 2) = sm*sk(k)%u1
      pm(:, i0 + 3) = sm*sk(k)%u2
      hm(:, i0 + 1) = cross3(sk(k)%p, pm(:, i0 + 1))
      hm(:, i0 + 2) = cross3(sk(k)%p, pm(:, i0 + 2)) + jr*cross3(sk(k)%u, sk(k)%u1)
      hm(:, i0 + 3) = cross3(sk(k)%p, pm(:, i0 + 3)) + jr*cross3(sk(k)%u, sk(k)%u2)
    end do
  end subroutine gear_momentum_maps

end module landyn_gear_inertia
