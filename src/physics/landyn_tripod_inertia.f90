!> The gear's inertia and momentum terms (paper section 2.4): generalized forces of the velocity
!! coupling, of the uniform frame field, of the footpad force and of the frame's angular
!! acceleration; the rates and values of the legs' relative linear and angular momentum; the maps
!! from the generalized velocities to them (used by the system velocity projection).
!!
!! The gear frame accelerates with the body: the leg parts feel the uniform field
!! f = g - a_body(a_i) (gravity minus the acceleration of the upper primary joint), taken from the
!! previous step. Rotational (centrifugal, Coriolis) frame terms are neglected: the body rotates at
!! a few deg/s at most, and their effect on a leg of tens of kg is far below the crush levels.
submodule (landyn_tripod_gear) landyn_tripod_inertia
  use landyn_kinematics, only: cross3
  implicit none

contains

  module procedure gear_generalized_forces
    type(strut_kin_t) :: sk(3)
    call strut_kinematics(gear, q, sk)
    call generalized_forces(q, qd, sk, f_field, f_foot, q_ine, q_grv, q_ext)
  end procedure gear_generalized_forces

  module procedure generalized_forces
    integer :: k, i0
    type(strut_mass_functions_t) :: mf
    real(wp) :: jr, jp, c, sn, lend, t1d, t2d, fm
    do k = 1, 3
      i0 = idx_len(k) - 1
      lend = qd(i0 + 1); t1d = qd(i0 + 2); t2d = qd(i0 + 3)
      mf = sk(k)%mf
      jr = mf%j
      jp = mf%dj
      if (present(trig)) then
        c = trig(k)%c2; sn = trig(k)%s2      ! cos and sin of q(i0 + 3)
      else
        c = cos(q(i0 + 3)); sn = sin(q(i0 + 3))
      end if
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
  end procedure generalized_forces

  module procedure alpha_forces
    integer :: k, i0
    type(strut_mass_functions_t) :: mf
    real(wp) :: sm, jr, pa(3)
    do k = 1, 3
      i0 = idx_len(k) - 1
      mf = sk(k)%mf
      sm = mf%s
      jr = mf%j
      pa = sk(k)%p - gear%geom%a
      qa(i0 + 1) = -dot_product(alpha, mf%m_s*cross3(pa, sk(k)%u))
      qa(i0 + 2) = -dot_product(alpha, sm*cross3(pa, sk(k)%u1) + jr*cross3(sk(k)%u, sk(k)%u1))
      qa(i0 + 3) = -dot_product(alpha, sm*cross3(pa, sk(k)%u2) + jr*cross3(sk(k)%u, sk(k)%u2))
    end do
  end procedure alpha_forces


  module procedure relative_inertia
    integer :: k, i0
    type(strut_mass_functions_t) :: mf
    real(wp) :: ud(3), udd(3), f(3), hd(3), ld, ldd, t1d, t2d, sm, s1, jr
    f_rel = 0.0_wp
    m_rel = 0.0_wp
    do k = 1, 3
      i0 = idx_len(k) - 1
      ld = gear%st%qd(i0 + 1); ldd = qdd(i0 + 1)
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
  end procedure relative_inertia

  module procedure gear_relative_momenta
    type(strut_kin_t) :: sk(3)
    call strut_kinematics(gear, gear%st%q, sk)
    call momenta(gear, sk, gear%st%qd, p_rel, h_rel, t_rel)
  end procedure gear_relative_momenta

  !> The legs' relative linear and angular momentum and kinetic energy at rates qd.
  pure subroutine momenta(gear, sk, qd, p_rel, h_rel, t_rel)
    type(tripod_gear_t), intent(in) :: gear       !! gear (configuration gear%st%q)
    type(strut_kin_t), intent(in) :: sk(3) !! strut kinematics at gear%st%q
    real(wp), intent(in) :: qd(n_q)        !! generalized velocities [m/s, rad/s]
    real(wp), intent(out) :: p_rel(3)      !! sum m v_rel, gear frame [kg m/s]
    real(wp), intent(out) :: h_rel(3)      !! relative angular momentum about O_L [kg m^2/s]
    real(wp), intent(out) :: t_rel         !! relative kinetic energy [J]
    integer :: k, i0
    type(strut_mass_functions_t) :: mf
    real(wp) :: ud(3), p(3), sm, jr, c
    p_rel = 0.0_wp
    h_rel = 0.0_wp
    t_rel = 0.0_wp
    do k = 1, 3
      i0 = idx_len(k) - 1
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

  module procedure gear_leg_momentum
    type(strut_kin_t) :: sk(3)
    integer :: k, i0
    type(strut_mass_functions_t) :: mf
    real(wp) :: ud(3), sm
    call strut_kinematics(gear, gear%st%q, sk)
    p_rel = 0.0_wp
    do k = 1, 3
      i0 = idx_len(k) - 1
      mf = sk(k)%mf
      ud = sk(k)%u1*gear%st%qd(i0 + 2) + sk(k)%u2*gear%st%qd(i0 + 3)
      sm = mf%s
      p_rel = p_rel + mf%m_s*gear%st%qd(i0 + 1)*sk(k)%u + sm*ud
    end do
    first_moment = leg_first_moment(sk, gear%st%q)
    leg_mass = gear%leg_mass
  end procedure gear_leg_momentum

  module procedure gear_momentum_maps
    type(strut_kin_t) :: sk(3)
    integer :: k, i0
    type(strut_mass_functions_t) :: mf
    real(wp) :: sm, jr
    call strut_kinematics(gear, gear%st%q, sk)
    do k = 1, 3
      i0 = idx_len(k) - 1
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
  end procedure gear_momentum_maps

end submodule landyn_tripod_inertia
