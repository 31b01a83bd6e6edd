!> Landing-gear multibody dynamics (paper section 2.4, eqs. 12-16, Step 4 of section 3.1).
!!
!! Each gear has nine generalized coordinates q = (d1, th1, th2, db1, thb1, thb2, dc1, thc1, thc2),
!! measured in the gear frame, which is fixed to the lander body: per strut its length and the two
!! angles of its upper universal joint (parametrisation in landyn_kinematics). Six holonomic
!! constraints (eq. 6) tie the secondaries' lower ball joints to the lugs on the primary's outer
!! tube, leaving three degrees of freedom: the three strut lengths.
!!
!! Mass model (derived, see docs/theory.md): each strut is an upper part (mass m_o, centre at l_o
!! from the upper joint, transverse inertia I_o) pivoting with the strut, and a lower part (m_i,
!! centre at l_i from the lower joint, I_i) that also slides with the length; the primary carries
!! the footpad mass at its lower end. Spin inertia about the strut axis is neglected. With
!! u = R0 (sin t2, -sin t1 cos t2, cos t1 cos t2), |du/dt|^2 = cos^2 t2 t1dot^2 + t2dot^2, so the
!! kinetic energy of one strut is T = 1/2 m_s Ldot^2 + 1/2 J(L) (cos^2 t2 t1dot^2 + t2dot^2) with
!! m_s = m_i + m_end and J(L) = m_o l_o^2 + I_o + m_i (L - l_i)^2 + I_i + m_end L^2: the mass matrix
!! is diagonal and the velocity-coupling terms follow from Lagrange's equations.
!!
!! The gear frame accelerates with the body: the leg parts feel the uniform field
!! f = g - a_body(a_i) (gravity minus the acceleration of the upper primary joint), taken from the
!! previous step. Rotational (centrifugal, Coriolis) frame terms are neglected: the body rotates at
!! a few deg/s at most, and their effect on a leg of tens of kg is far below the crush levels.
!!
!! Crush logic (eqs. 12-13) as a complementarity with the buffer bounds of landyn_buffer: a strut
!! at rest is LOCKED (its length rate is constrained to zero; the multiplier of that constraint is
!! the equivalent dynamic force F of eq. 12). When F exceeds the buffer's bound in its direction,
!! the strut crushes: it is released and the buffer transmits N = bound, the excess F - N drives
!! the sliding coordinate (eq. 13). A crushing strut whose sliding speed reaches zero locks again.
!! This replaces the literal reading in which a strut keeps sliding with no force on it.
!!
!! The augmented system [[M, A^T], [A, 0]] [qdd; lambda] = [Q; b] (eqs. 14-16, A = Phi_q plus the
!! lock rows) is solved by block elimination with LAPACK's Cholesky (M is diagonal, so the Schur
!! complement A M^-1 A^T is small and SPD); `gear_solve_augmented_full` solves the unreduced
!! system with LU for cross-checking. After each semi-implicit Euler step the direct
!! constraint-violation correction of Step 4 is applied: positions dq = -A^+ Phi iterated to the
!! tolerance, then velocities dqdot = -A^+ A qdot, with A^+ = A^T (A A^T)^-1.
module landyn_gear
  use landyn_kinds, only: wp, msg_len
  use landyn_buffer, only: buffer_law_t, rigid_force
  use landyn_kinematics, only: gear_geometry_t, strut_axis_derivs, gear_constraints, gear_constraint_jacobian, &
                               gear_constraint_gamma, cross3
  use landyn_lapack, only: solve_spd_unblocked, solve_general, factor_spd
  use landyn_small_spd, only: small_spd_solve, small_upper_solve_multi
  use landyn_tube_friction, only: tube_friction_t, tube_friction_bound, add_tube_bound
  implicit none
  private

  public :: gear_t, strut_mass_t, buffer_slot_t, gear_state_t, gear_eval_t
  public :: gear_init, gear_evaluate, gear_commit, gear_prepare, gear_dynamics, gear_integrate
  public :: gear_footpad, gear_mass_matrix, gear_generalized_forces
  public :: gear_relative_kinetic_energy, gear_solve_augmented_full, gear_relative_inertia, gear_leg_momentum
  public :: gear_relative_momenta, gear_velocity_rows, gear_momentum_maps, gear_settle, gear_law_segments
  public :: max_rows, idx_len
  public :: n_q, n_phi

  integer, parameter :: n_q = 9      !! generalized coordinates per gear
  integer, parameter :: n_phi = 6    !! holonomic constraints per gear
  integer, parameter :: max_rows = n_phi + 3   !! constraint rows per gear at most (Phi_q and three locks)
  integer, parameter :: idx_len(3) = [1, 4, 7]   !! index of each strut's length in q

  !> Mass properties of one strut.
  type :: strut_mass_t
    real(wp) :: m_o = 0.0_wp    !! upper part mass [kg]
    real(wp) :: l_o = 0.0_wp    !! upper part centre from the upper joint [m]
    real(wp) :: i_o = 0.0_wp    !! upper part transverse inertia about its centre [kg m^2]
    real(wp) :: m_i = 0.0_wp    !! lower (sliding) part mass [kg]
    real(wp) :: l_i = 0.0_wp    !! lower part centre from the lower joint [m]
    real(wp) :: i_i = 0.0_wp    !! lower part transverse inertia about its centre [kg m^2]
    real(wp) :: m_end = 0.0_wp  !! point mass at the lower joint (footpad) [kg]
  end type strut_mass_t

  !> Holder for a polymorphic buffer law (one per strut).
  type :: buffer_slot_t
    class(buffer_law_t), allocatable :: law
  end type buffer_slot_t

  !> Kinematics of one strut at a configuration: upper joint, axis and its partials.
  type :: strut_kin_t
    real(wp) :: p(3) = 0.0_wp     !! upper joint, gear frame [m]
    real(wp) :: u(3) = 0.0_wp     !! unit axis [-]
    real(wp) :: u1(3) = 0.0_wp    !! du/dt1 [1/rad]
    real(wp) :: u2(3) = 0.0_wp    !! du/dt2 [1/rad]
    real(wp) :: u11(3) = 0.0_wp   !! d2u/dt1^2 [1/rad^2]
    real(wp) :: u12(3) = 0.0_wp   !! d2u/dt1 dt2 [1/rad^2]
    real(wp) :: u22(3) = 0.0_wp   !! d2u/dt2^2 [1/rad^2]
  end type strut_kin_t

  !> Everything of a gear that evolves in time (coordinates, rates, crush modes and history,
  !! accumulators) and the caches that depend on it: gear_t's component `st`. Copying it out and
  !! back restores the gear exactly, so that a step can be rejected or repeated (the geometry,
  !! masses and buffer laws are parameters and stay in gear_t).
  type :: gear_state_t
    real(wp) :: q(n_q) = 0.0_wp                   !! generalized coordinates [m, rad]
    real(wp) :: qd(n_q) = 0.0_wp                  !! generalized velocities [m/s, rad/s]
    real(wp) :: qdd(n_q) = 0.0_wp                 !! generalized accelerations [m/s^2, rad/s^2]
    logical :: locked(3) = .true.                 !! strut locked [-]
    integer :: dir(3) = 0                         !! sliding direction [-]
    real(wp) :: s_lock(3) = 0.0_wp                !! stroke held by a locked strut [m]
    real(wp) :: s_hismin(3) = 0.0_wp              !! most negative stroke reached [m]
    real(wp) :: s_hismax(3) = 0.0_wp              !! most positive stroke reached [m]
    real(wp) :: axial(3) = 0.0_wp                 !! axial buffer force [N]
    real(wp) :: f_body(3) = 0.0_wp                !! force on the body, gear frame [N]
    real(wp) :: m_body(3) = 0.0_wp                !! moment on the body about O_L, gear axes [N m]
    real(wp) :: work_crush(3) = 0.0_wp            !! energy absorbed by each buffer [J]
    real(wp) :: max_violation = 0.0_wp            !! largest violation after correction [m]
    real(wp) :: max_drift = 0.0_wp                !! largest violation before correction [m]
    integer :: n_correction_iter = 0              !! largest number of correction iterations [-]
    real(wp) :: tube_bound = 0.0_wp               !! tube-friction bound of this step [N]
    ! Rigid state: all three struts locked. The gear then has no degree of freedom: qd = qdd = 0
    ! exactly, q and the constraint matrix stay constant, and the Cholesky factor of A M^-1 A^T is
    ! computed once and reused until a strut breaks loose.
    logical :: rigid = .false.                    !! all struts locked and qd = 0 (set by gear_integrate;
                                                  !! changing locked or qd from outside requires rigid = .false.)
    logical :: rigid_cache = .false.              !! the caches below are valid
    type(strut_kin_t) :: sk_c(3)                  !! cached strut kinematics
    real(wp) :: mdiag_c(n_q) = 0.0_wp             !! cached mass matrix diagonal [kg, kg m^2]
    real(wp) :: a_c(max_rows, n_q) = 0.0_wp       !! cached constraint rows [-, m]
    real(wp) :: chol_c(max_rows, max_rows) = 0.0_wp  !! cached Cholesky factor
    logical :: phq_ok = .false.                   !! Phi_q cache valid [-]
    real(wp) :: phq(n_phi, n_q) = 0.0_wp          !! cached Phi_q [-, m]
    real(wp) :: phq_q(n_q) = 0.0_wp               !! its q [m, rad]
  end type gear_state_t

  !> What one evaluation of a gear decides and computes (gear_evaluate) from its committed state,
  !! without changing it; gear_commit makes it the gear's state.
  type :: gear_eval_t
    real(wp) :: qdd(n_q) = 0.0_wp                 !! generalized accelerations [m/s^2, rad/s^2]
    real(wp) :: axial(3) = 0.0_wp                 !! axial buffer force [N]
    real(wp) :: f_body(3) = 0.0_wp                !! force on the body, gear frame [N]
    real(wp) :: m_body(3) = 0.0_wp                !! moment on the body about O_L, gear axes [N m]
    logical :: locked(3) = .true.                 !! strut locked [-]
    integer :: dir(3) = 0                         !! sliding direction [-]
    real(wp) :: s_lock(3) = 0.0_wp                !! stroke held by a locked strut [m]
    real(wp) :: tube_bound = 0.0_wp               !! tube-friction bound of this step [N]
    logical :: rigid = .false.                    !! the gear stays rigid [-]
    ! interface loads (gear_joint_loads), gear frame: columns a, b, c are the forces the upper
    ! joints put on the body, column 4 the force the footpad puts on the primary at d
    real(wp) :: f_joint(3, 4) = 0.0_wp            !! joint forces [N]
    real(wp) :: m_joint(3, 3) = 0.0_wp            !! moments of a, b, c on the body (about the strut's
                                                  !! Hooke-joint axis: its spin is constrained) [N m]
    real(wp) :: f_interface(3) = 0.0_wp           !! the gear's total force on the body from the
                                                  !! leg's momentum balance (= sum of columns a-c) [N]
  end type gear_eval_t

  !> One landing gear: geometry, masses, buffers and state.
  type :: gear_t
    type(gear_geometry_t) :: geom                 !! hard points and nominal strut frames, gear frame
    real(wp) :: rot(3, 3) = 0.0_wp                !! gear frame -> lander frame rotation [-]
    type(strut_mass_t) :: mass(3)                 !! primary, left, right
    ! per-strut mass constants (set by gear_init): J(L) = j_0 + m_in (L - l_in)^2 + m_end L^2,
    ! S1(L) = m_in (L - l_in) + m_end L (sliding parts' first moment), S(L) = s_0 + S1(L)
    real(wp) :: m_s(3) = 0.0_wp                   !! sliding mass m_i + m_end [kg]
    real(wp) :: m_tot(3) = 0.0_wp                 !! strut mass [kg]
    real(wp) :: j_0(3) = 0.0_wp                   !! m_o l_o^2 + I_o + I_i [kg m^2]
    real(wp) :: s_0(3) = 0.0_wp                   !! m_o l_o [kg m]
    real(wp) :: m_in(3) = 0.0_wp                  !! m_i [kg]
    real(wp) :: l_in(3) = 0.0_wp                  !! l_i [m]
    real(wp) :: m_end(3) = 0.0_wp                 !! end mass [kg]
    real(wp) :: row_bound = 0.0_wp                !! bound on |A_ij| of the correction rows [m]
    type(buffer_slot_t) :: buffer(3)              !! primary, left, right buffer laws
    type(tube_friction_t) :: tube                 !! friction between the primary's tubes (eqs. 23-26)
    real(wp) :: sigma(3) = [-1.0_wp, 1.0_wp, 1.0_wp]  !! ds/dL: stroke sign convention per strut [-]
    real(wp) :: len0(3) = 0.0_wp                  !! nominal strut lengths [m]
    type(gear_state_t) :: st                      !! everything that evolves (a snapshot is a copy of it)
  end type gear_t

contains

  !> Sets up a gear at its nominal configuration, all struts locked and at rest.
  subroutine gear_init(gear, geom, rot, mass, stat, errmsg, tube)
    type(gear_t), intent(inout) :: gear          !! gear to initialise (buffers must already be allocated)
    type(gear_geometry_t), intent(in) :: geom    !! geometry in the gear frame
    real(wp), intent(in) :: rot(3, 3)            !! gear frame -> lander frame [-]
    type(strut_mass_t), intent(in) :: mass(3)    !! strut mass properties
    integer, intent(out) :: stat                 !! 0 on success
    character(len=*), intent(inout) :: errmsg    !! message on failure
    type(tube_friction_t), intent(in), optional :: tube  !! primary tube friction; absent: off
    integer :: k
    stat = 0
    gear%tube = tube_friction_t()
    if (present(tube)) gear%tube = tube
    gear%st%tube_bound = 0.0_wp
    gear%geom = geom
    gear%rot = rot
    gear%mass = mass
    do k = 1, 3
      gear%m_s(k) = mass(k)%m_i + mass(k)%m_end
      gear%m_tot(k) = mass(k)%m_o + gear%m_s(k)
      gear%j_0(k) = mass(k)%m_o*mass(k)%l_o**2 + mass(k)%i_o + mass(k)%i_i
      gear%s_0(k) = mass(k)%m_o*mass(k)%l_o
      gear%m_in(k) = mass(k)%m_i
      gear%l_in(k) = mass(k)%l_i
      gear%m_end(k) = mass(k)%m_end
    end do
    ! Phi_q entries are lug or strut lever arms (|dx/dtheta| <= distance to the joint) or unit
    ! vectors; lock rows are 1. Twice the longest such distance bounds every entry.
    gear%row_bound = 2.0_wp*max(1.0_wp, norm2(geom%e_loc), norm2(geom%f_loc), geom%L0, geom%Lb0, geom%Lc0)
    gear%len0 = [geom%L0, geom%Lb0, geom%Lc0]
    gear%st%q = 0.0_wp
    gear%st%q(idx_len) = gear%len0
    gear%st%qd = 0.0_wp
    gear%st%qdd = 0.0_wp
    gear%st%locked = .true.
    gear%st%phq_ok = .false.
    gear%st%rigid = .false.          ! entered by gear_integrate once all struts are locked
    gear%st%rigid_cache = .false.
    gear%st%dir = 0
    gear%st%s_lock = 0.0_wp
    gear%st%s_hismin = 0.0_wp
    gear%st%s_hismax = 0.0_wp
    gear%st%axial = 0.0_wp
    gear%st%f_body = 0.0_wp
    gear%st%m_body = 0.0_wp
    gear%st%work_crush = 0.0_wp
    gear%st%max_violation = 0.0_wp
    gear%st%max_drift = 0.0_wp
    gear%st%n_correction_iter = 0
    do k = 1, 3
      if (.not. allocated(gear%buffer(k)%law)) then
        stat = 1
        errmsg = 'gear_init: buffer law not set'
        return
      end if
      if (mass(k)%m_i + mass(k)%m_end <= 0.0_wp) then
        stat = 1
        errmsg = 'gear_init: a strut has no sliding mass'
        return
      end if
    end do
  end subroutine gear_init

  !> Footpad position and velocity in the gear frame.
  pure subroutine gear_footpad(gear, pos, vel, qd)
    type(gear_t), intent(in) :: gear     !! gear
    real(wp), intent(out) :: pos(3)      !! footpad joint position, gear frame [m]
    real(wp), intent(out) :: vel(3)      !! its velocity relative to the body, gear frame [m/s]
    real(wp), intent(in), optional :: qd(n_q)  !! generalized velocities to use; default the gear's [m/s, rad/s]
    real(wp) :: u(3), du1(3), du2(3), d11(3), d12(3), d22(3), v(n_q)
    call strut_axis_derivs(gear%geom%R0p, gear%st%q(2), gear%st%q(3), u, du1, du2, d11, d12, d22)
    if (present(qd)) then
      v = qd
    else
      v = gear%st%qd
    end if
    pos = gear%geom%a + gear%st%q(1)*u
    vel = v(1)*u + gear%st%q(1)*(du1*v(2) + du2*v(3))
  end subroutine gear_footpad

  !> Upper joint, axis and axis partials of each strut at q (computed once per use).
  pure subroutine strut_kinematics(gear, q, sk)
    type(gear_t), intent(in) :: gear        !! gear
    real(wp), intent(in) :: q(n_q)          !! coordinates [m, rad]
    type(strut_kin_t), intent(out) :: sk(3) !! per-strut kinematics
    sk(1)%p = gear%geom%a
    sk(2)%p = gear%geom%b
    sk(3)%p = gear%geom%c
    call strut_axis_derivs(gear%geom%R0p, q(2), q(3), sk(1)%u, sk(1)%u1, sk(1)%u2, sk(1)%u11, sk(1)%u12, sk(1)%u22)
    call strut_axis_derivs(gear%geom%R0b, q(5), q(6), sk(2)%u, sk(2)%u1, sk(2)%u2, sk(2)%u11, sk(2)%u12, sk(2)%u22)
    call strut_axis_derivs(gear%geom%R0c, q(8), q(9), sk(3)%u, sk(3)%u1, sk(3)%u2, sk(3)%u11, sk(3)%u12, sk(3)%u22)
  end subroutine strut_kinematics

  !> Diagonal of the mass matrix M(q).
  pure function gear_mass_matrix(gear, q) result(mdiag)
    type(gear_t), intent(in) :: gear   !! gear
    real(wp), intent(in) :: q(n_q)     !! generalized coordinates [m, rad]
    real(wp) :: mdiag(n_q)             !! diagonal of M [kg, kg m^2]
    integer :: k, i0
    real(wp) :: jr, c, len
    do k = 1, 3
      i0 = idx_len(k) - 1
      len = q(i0 + 1)
      jr = strut_inertia(gear, k, len)
      c = cos(q(i0 + 3))
      mdiag(i0 + 1) = gear%m_s(k)
      mdiag(i0 + 2) = jr*c*c
      mdiag(i0 + 3) = jr
    end do
  end function gear_mass_matrix

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
    call generalized_forces(gear, q, qd, sk, f_field, f_foot, q_ine, q_grv, q_ext)
  end subroutine gear_generalized_forces

  pure subroutine generalized_forces(gear, q, qd, sk, f_field, f_foot, q_ine, q_grv, q_ext)
    type(gear_t), intent(in) :: gear       !! gear
    real(wp), intent(in) :: q(n_q)         !! coordinates [m, rad]
    real(wp), intent(in) :: qd(n_q)        !! velocities [m/s, rad/s]
    type(strut_kin_t), intent(in) :: sk(3) !! strut kinematics at q
    real(wp), intent(in) :: f_field(3)     !! uniform field, gear frame [m/s^2]
    real(wp), intent(in) :: f_foot(3)      !! footpad force, gear frame [N]
    real(wp), intent(out) :: q_ine(n_q)    !! velocity coupling [N, N m]
    real(wp), intent(out) :: q_grv(n_q)    !! field [N, N m]
    real(wp), intent(out) :: q_ext(n_q)    !! footpad force [N, N m]
    integer :: k, i0
    real(wp) :: jr, jp, c, sn, len, lend, t1d, t2d, fm
    do k = 1, 3
      i0 = idx_len(k) - 1
      len = q(i0 + 1); lend = qd(i0 + 1); t1d = qd(i0 + 2); t2d = qd(i0 + 3)
      jr = strut_inertia(gear, k, len)
      jp = 2.0_wp*gear%m_in(k)*(len - gear%l_in(k)) + 2.0_wp*gear%m_end(k)*len
      c = cos(q(i0 + 3)); sn = sin(q(i0 + 3))
      q_ine(i0 + 1) = 0.5_wp*jp*(c*c*t1d*t1d + t2d*t2d)
      q_ine(i0 + 2) = -jp*lend*c*c*t1d + 2.0_wp*jr*c*sn*t1d*t2d
      q_ine(i0 + 3) = -jp*lend*t2d - jr*c*sn*t1d*t1d
      fm = strut_first_moment(gear, k, len)
      q_grv(i0 + 1) = gear%m_s(k)*dot_product(sk(k)%u, f_field)
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
    real(wp) :: len, sm, jr, pa(3)
    do k = 1, 3
      i0 = idx_len(k) - 1
      len = q(i0 + 1)
      sm = strut_first_moment(gear, k, len)
      jr = strut_inertia(gear, k, len)
      pa = sk(k)%p - gear%geom%a
      qa(i0 + 1) = -dot_product(alpha, gear%m_s(k)*cross3(pa, sk(k)%u))
      qa(i0 + 2) = -dot_product(alpha, sm*cross3(pa, sk(k)%u1) + jr*cross3(sk(k)%u, sk(k)%u1))
      qa(i0 + 3) = -dot_product(alpha, sm*cross3(pa, sk(k)%u2) + jr*cross3(sk(k)%u, sk(k)%u2))
    end do
  end function alpha_forces

  !> Relative kinetic energy of the leg parts, 1/2 qd^T M qd.
  pure function gear_relative_kinetic_energy(gear) result(t)
    type(gear_t), intent(in) :: gear   !! gear
    real(wp) :: t                      !! kinetic energy relative to the body [J]
    t = 0.5_wp*sum(gear_mass_matrix(gear, gear%st%q)*gear%st%qd**2)
  end function gear_relative_kinetic_energy

  !> Stroke and stroke rate of each strut (Table 3 sense).
  pure subroutine strokes(gear, qv, qdv, s, sd)
    type(gear_t), intent(in) :: gear   !! gear
    real(wp), intent(in) :: qv(n_q)    !! coordinates [m, rad]
    real(wp), intent(in) :: qdv(n_q)   !! velocities [m/s, rad/s]
    real(wp), intent(out) :: s(3)      !! strokes [m]
    real(wp), intent(out) :: sd(3)     !! stroke rates [m/s]
    s = gear%sigma*(qv(idx_len) - gear%len0)
    sd = gear%sigma*qdv(idx_len)
  end subroutine strokes

  !> First moment of mass of strut k about its upper joint, along its axis, at length len:
  !! S(L) = m_o l_o + m_i (L - l_i) + m_end L.
  pure real(wp) function strut_first_moment(gear, k, len) result(sm)
    type(gear_t), intent(in) :: gear   !! gear (strut masses)
    integer, intent(in) :: k           !! strut [-]
    real(wp), intent(in) :: len        !! strut length [m]
    sm = gear%s_0(k) + gear%m_in(k)*(len - gear%l_in(k)) + gear%m_end(k)*len
  end function strut_first_moment

  !> Transverse moment of inertia of strut k about its upper joint at length len:
  !! J(L) = j_0 + m_i (L - l_i)^2 + m_end L^2.
  pure real(wp) function strut_inertia(gear, k, len) result(jr)
    type(gear_t), intent(in) :: gear   !! gear (strut masses)
    integer, intent(in) :: k           !! strut [-]
    real(wp), intent(in) :: len        !! strut length [m]
    jr = gear%j_0(k) + gear%m_in(k)*(len - gear%l_in(k))**2 + gear%m_end(k)*len*len
  end function strut_inertia

  !> The piece of each strut's buffer law at the current strokes (buffer_law_t%segment): changes
  !! exactly at a stage end or where an end-of-stroke stop begins.
  pure function gear_law_segments(gear) result(seg)
    type(gear_t), intent(in) :: gear   !! gear
    integer :: seg(3)                  !! segment of primary, left, right [-]
    real(wp) :: s(3), sd(3)
    integer :: k
    call strokes(gear, gear%st%q, gear%st%qd, s, sd)
    do k = 1, 3
      seg(k) = gear%buffer(k)%law%segment(s(k))
    end do
  end function gear_law_segments

  !> Accelerations, buffer forces and the force on the body for the current state (Steps 2-4).
  !! f_foot is the ground force on the footpad and f_field the uniform field, both in the gear frame.
  !!
  !! With `dt` present the lock decision is made at velocity level over the coming step (Moreau's
  !! time-stepping reading of the complementarity): a crushing strut whose sliding speed would
  !! reverse within the step is locked now with the lock row demanding sd(t + dt) = 0, and it stays
  !! locked when the force that needs lies within the buffer's bounds. The strut then stops exactly
  !! at the end of the step instead of overshooting under its full crush force and being stopped by
  !! the velocity projection, which made the modes chatter (crushing -> locked -> free every few
  !! steps) and the projection dissipate energy that the crush work had not accounted for.
  !!
  !! `alpha` is the body's angular acceleration (gear axes). The uniform field f is the
  !! acceleration field at the upper primary joint a; the leg parts away from a also feel
  !! -alpha x (r - a), whose generalized force is -H_a^T alpha with H_a the map from qd to the
  !! legs' relative angular momentum about a. Without it the legs and the body disagree on the
  !! work of the angular acceleration during an impact (an energy audit error of ~0.2 % in
  !! landings with rotation). The remaining frame terms (centrifugal variation over the leg,
  !! Coriolis) are two orders smaller at the body rates of a landing and are neglected.
  subroutine gear_evaluate(gear, ge, f_foot, f_field, stat, errmsg, dt, alpha, loads)
    type(gear_t), intent(in) :: gear             !! gear with its committed state (unchanged)
    type(gear_eval_t), intent(out) :: ge         !! accelerations, buffer forces, lock decisions, body load
    real(wp), intent(in) :: f_foot(3)            !! ground force on the footpad, gear frame [N]
    real(wp), intent(in) :: f_field(3)           !! uniform field g - a_frame, gear frame [m/s^2]
    integer, intent(out) :: stat                 !! 0 on success
    character(len=*), intent(inout) :: errmsg    !! diagnosis on failure
    real(wp), intent(in), optional :: dt         !! coming time step: velocity-level locking [s]
    real(wp), intent(in), optional :: alpha(3)   !! body angular acceleration, gear axes [rad/s^2]
    logical, intent(in), optional :: loads       !! compute the interface loads (f_joint, m_joint,
                                                 !! f_interface); default .true. [-]
    real(wp) :: mdiag(n_q), q_ine(n_q), q_grv(n_q), q_ext(n_q), q_tot(n_q), q_buf(n_q), q_alp(n_q)
    real(wp) :: phq(n_phi, n_q), gam(n_phi)
    real(wp) :: a(max_rows, n_q), b(max_rows), lam(max_rows)
    real(wp) :: s(3), sd(3), fpos(3), fneg(3), demand
    real(wp) :: f_rel(3), m_rel(3), f_strut(3, 3), h_strut(3, 3)
    type(strut_kin_t) :: sk(3)
    integer :: k, iter, nrow, row_of(3)
    logical :: changed, done, tried(3), released(3), stop_hit(3), with_loads

    stat = 0
    with_loads = .true.
    if (present(loads)) with_loads = loads
    ! the evaluation starts from the committed decisions
    ge%qdd = gear%st%qdd
    ge%axial = gear%st%axial
    ge%f_body = gear%st%f_body
    ge%m_body = gear%st%m_body
    ge%locked = gear%st%locked
    ge%dir = gear%st%dir
    ge%s_lock = gear%st%s_lock
    ge%tube_bound = gear%st%tube_bound
    ge%rigid = gear%st%rigid
    ! Tube friction (eqs. 23-26): the primary's extra bound, explicit from the previous step's
    ! secondary forces (landyn_tube_friction). Off by default: then nothing here runs.
    if (gear%tube%on) ge%tube_bound = tube_bound_now(gear)
    q_alp = 0.0_wp
    stop_hit = .false.
    if (ge%rigid .and. all(ge%locked)) then
      call rigid_dynamics(gear, ge, f_foot, f_field, with_loads, done, stat, errmsg, alpha)
      if (stat /= 0 .or. done) return
    end if
    call strut_kinematics(gear, gear%st%q, sk)
    mdiag = gear_mass_matrix(gear, gear%st%q)
    call generalized_forces(gear, gear%st%q, gear%st%qd, sk, f_field, f_foot, q_ine, q_grv, q_ext)
    if (present(alpha)) q_alp = alpha_forces(gear, gear%st%q, sk, alpha)
    if (gear%st%phq_ok .and. maxval(abs(gear%st%q - gear%st%phq_q)) <= 0.0_wp) then
      phq = gear%st%phq
    else
      phq = gear_constraint_jacobian(gear%geom, gear%st%q)
    end if
    gam = gear_constraint_gamma(gear%geom, gear%st%q, gear%st%qd)
    call strokes(gear, gear%st%q, gear%st%qd, s, sd)
    do k = 1, 3
      call gear%buffer(k)%law%resistance(s(k), sd(k), gear%st%s_hismin(k), gear%st%s_hismax(k), fpos(k), fneg(k))
    end do
    if (gear%tube%on) call add_tube_bound(ge%tube_bound, fpos(1), fneg(1))   ! tube friction (eq. 24)
    ! Sliding struts transmit their bound against the direction of motion; a sliding strut that runs
    ! into a rigid stop is locked (plastic impact on the stop).
    do k = 1, 3
      if (.not. ge%locked(k)) then
        if (sd(k) > 0.0_wp) ge%dir(k) = 1
        if (sd(k) < 0.0_wp) ge%dir(k) = -1
        if (ge%dir(k) > 0) then
          ge%axial(k) = -gear%sigma(k)*fpos(k)
          if (fpos(k) >= rigid_force) ge%locked(k) = .true.
          if (fpos(k) >= rigid_force) stop_hit(k) = .true.
        else
          ge%axial(k) = gear%sigma(k)*fneg(k)
          if (fneg(k) >= rigid_force) ge%locked(k) = .true.
          if (fneg(k) >= rigid_force) stop_hit(k) = .true.
        end if
        if (ge%locked(k)) ge%s_lock(k) = s(k)
      end if
    end do

    tried = .false.
    released = .false.
    do iter = 1, 8
      ! Assemble A = [Phi_q; lock rows], b = [gamma; 0] and the generalized force.
      q_buf = 0.0_wp
      nrow = n_phi
      a(1:n_phi, :) = phq
      b(1:n_phi) = gam
      row_of = 0
      do k = 1, 3
        if (ge%locked(k)) then
          nrow = nrow + 1
          a(nrow, :) = 0.0_wp
          a(nrow, idx_len(k)) = 1.0_wp
          b(nrow) = 0.0_wp
          ! Velocity-level lock: stop at the end of the step. A strut that has just run into a
          ! rigid stop keeps its speed through the step instead (b = 0): stopping it is a plastic
          ! impact, done by the system velocity projection after the step, which books its loss.
          if (present(dt) .and. .not. stop_hit(k)) b(nrow) = -gear%st%qd(idx_len(k))/dt
          row_of(k) = nrow
        else
          q_buf(idx_len(k)) = ge%axial(k)
        end if
      end do
      q_tot = q_ine + q_grv + q_ext + q_buf + q_alp
      call solve_reduced(nrow, a, b, mdiag, q_tot, ge%qdd, lam, stat, errmsg)
      if (stat /= 0) return
      ! Check each lock: the force it carries (the equivalent dynamic force) against the bound.
      changed = .false.
      if (present(dt)) then
        ! A crushing strut (nonzero bound in its direction of motion) that would reverse within
        ! the step is locked for the step, to be checked against its bounds below.
        do k = 1, 3
          if (ge%locked(k) .or. released(k)) cycle
          if (ge%dir(k) > 0 .and. fpos(k) > 0.0_wp .and. sd(k) + gear%sigma(k)*ge%qdd(idx_len(k))*dt <= 0.0_wp &
              .or. ge%dir(k) < 0 .and. fneg(k) > 0.0_wp .and. sd(k) + gear%sigma(k)*ge%qdd(idx_len(k))*dt >= 0.0_wp) then
            ge%locked(k) = .true.
            ge%s_lock(k) = s(k)
            tried(k) = .true.
            changed = .true.
          end if
        end do
        if (changed) cycle
      end if
      do k = 1, 3
        if (.not. ge%locked(k)) cycle
        ge%axial(k) = -lam(row_of(k))
        ! Generalized force of the lock on the stroke s is sigma*axial: negative when it holds the
        ! strut against motion toward +s (bounded by f_pos), positive against -s (bounded by f_neg).
        demand = gear%sigma(k)*ge%axial(k)
        if (-demand > fpos(k)) then
          ge%locked(k) = .false.
          ge%dir(k) = 1
          ge%axial(k) = -gear%sigma(k)*fpos(k)
          changed = .true.
        else if (demand > fneg(k)) then
          ge%locked(k) = .false.
          ge%dir(k) = -1
          ge%axial(k) = gear%sigma(k)*fneg(k)
          changed = .true.
        end if
        if (.not. ge%locked(k) .and. tried(k)) released(k) = .true.
      end do
      if (.not. changed) exit
    end do

    ! Loads on the body: the leg's momentum balance. The body (which carries the total mass, legs
    ! included) receives the ground force minus the rate of the legs' relative momentum; in the
    ! massless-leg limit this is eq. 11's J^-T N applied at the footpad.
    call relative_inertia(gear, sk, ge%qdd, f_rel, m_rel, f_strut, h_strut)
    ge%f_body = f_foot - f_rel
    ge%m_body = cross3(gear%geom%a + gear%st%q(1)*sk(1)%u, f_foot) - m_rel
    if (with_loads) call joint_loads(gear, sk, gear%st%q, gear%st%qd, ge%qdd, f_strut, h_strut, lam(1:n_phi), f_foot, f_field, &
                     alpha_or_zero(alpha), ge%f_body, ge%f_joint, ge%m_joint, ge%f_interface)
  end subroutine gear_evaluate

  !> alpha when given, else zero.
  pure function alpha_or_zero(alpha) result(a)
    real(wp), intent(in), optional :: alpha(3)   !! [rad/s^2]
    real(wp) :: a(3)                             !! [rad/s^2]
    a = 0.0_wp
    if (present(alpha)) a = alpha
  end function alpha_or_zero

  !> Interface loads of a gear, gear frame: the force each upper joint a, b, c puts on the body and
  !! the force the footpad puts on the primary at its ball joint d (f_joint columns 1-4), and the
  !! gear's total force on the body (f_interface) from the leg's momentum balance.
  !!
  !! Each strut is a free body between its upper joint (no moment: universal joint, spin neglected)
  !! and its lower end: the ground force at the footpad and the lugs' reactions for the primary
  !! (-lambda_e, -lambda_f: the multipliers of Phi = [e_pri - e_sec; f_pri - f_sec], M qdd = Q -
  !! Phi_q^T lambda), +lambda_e, +lambda_f for the left and right secondaries. Its force balance in
  !! the body frame, with the frame field on all its parts (uniform g - a_frame and the angular
  !! part -alpha x (r - a)), gives the joint force: body on strut = f_k - F_field,k - F_lower,k,
  !! with f_k the rate of the strut's relative momentum; the joint's force on the body is its
  !! negative. The buffer and lock forces are internal to a strut. The footpad (the primary's end
  !! mass) puts f_foot - m_fp (d_rel'' - field at d) on the primary.
  !!
  !! The body of the model carries the legs' mass, so what it receives from a gear in its equations
  !! is f_body = f_foot - f_rel; the physical interface force adds the legs' weight and inertia in
  !! the moving frame: f_interface = f_body + m_leg f_field - alpha x (first moment of the legs
  !! about a). The sum of the three joint forces equals it (the lug reactions cancel).
  pure subroutine joint_loads(gear, sk, q, qd, qdd, f_strut, h_strut, lam_phi, f_foot, f_field, alpha, f_body, &
                              f_joint, m_joint, f_interface)
    type(gear_t), intent(in) :: gear             !! gear (geometry, masses)
    type(strut_kin_t), intent(in) :: sk(3)       !! strut kinematics at q
    real(wp), intent(in) :: q(n_q)               !! coordinates [m, rad]
    real(wp), intent(in) :: qd(n_q)              !! velocities [m/s, rad/s]
    real(wp), intent(in) :: qdd(n_q)             !! accelerations [m/s^2, rad/s^2]
    real(wp), intent(in) :: f_strut(3, 3)        !! rate of each strut's relative momentum [N]
    real(wp), intent(in) :: h_strut(3, 3)        !! rate of its relative angular momentum about its upper joint [N m]
    real(wp), intent(in) :: lam_phi(n_phi)       !! multipliers of the lug constraints [N]
    real(wp), intent(in) :: f_foot(3)            !! ground force on the footpad [N]
    real(wp), intent(in) :: f_field(3)           !! uniform field g - a_frame [m/s^2]
    real(wp), intent(in) :: alpha(3)             !! body angular acceleration, gear axes [rad/s^2]
    real(wp), intent(in) :: f_body(3)            !! the gear's load on the body in the model, f_foot - f_rel [N]
    real(wp), intent(out) :: f_joint(3, 4)       !! forces of a, b, c on the body; footpad on primary at d [N]
    real(wp), intent(out) :: m_joint(3, 3)       !! moments of a, b, c on the body [N m]
    real(wp), intent(out) :: f_interface(3)      !! the gear's total physical force on the body [N]
    real(wp) :: f_low(3, 3), f_fld(3), sm, len, ud(3), udd(3), dd(3), fm(3), m_leg, jr, tau(3), n(3), r0(3, 3)
    real(wp) :: d(3), e_pri(3), f_pri(3), e_sec(3), f_sec(3), rp(3, 3)
    integer :: k, i0
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
      len = q(idx_len(k))
      sm = strut_first_moment(gear, k, len)
      jr = strut_inertia(gear, k, len)
      ! force: body on strut = f_k - field - lower-end forces; the joint's force on the body is its negative
      f_fld = gear%m_tot(k)*f_field - cross3(alpha, gear%m_tot(k)*(sk(k)%p - gear%geom%a) + sm*sk(k)%u)
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
    f_joint(:, 4) = f_foot - gear%m_end(1)*(dd - f_field + cross3(alpha, q(i0 + 1)*sk(1)%u))
    ! the leg's momentum balance, with the legs' first moment as gear_leg_momentum takes it
    fm = leg_first_moment(gear, sk, q)
    m_leg = sum(gear%m_tot)
    f_interface = f_body + m_leg*f_field - cross3(alpha, fm - m_leg*gear%geom%a)
  end subroutine joint_loads

  !> The primary's tube-friction bound eta u_1 N_E/F for this step, from the current strut axes and
  !! the secondary axial forces of the previous step (explicit; landyn_tube_friction).
  pure real(wp) function tube_bound_now(gear) result(bound)
    type(gear_t), intent(in) :: gear       !! gear with its committed secondary forces
    type(strut_kin_t) :: sk(3)
    call strut_kinematics(gear, gear%st%q, sk)
    bound = tube_friction_bound(gear%tube, sk(1)%u, sk(2)%u, sk(3)%u, gear%st%axial(2), gear%st%axial(3))
  end function tube_bound_now

  !> gear_dynamics for a rigid gear (all struts locked, at rest relative to the body): only the
  !! lock forces are solved for, with the cached factor. done = .false. when a strut's demand
  !! exceeds its bound: the gear leaves the rigid state and the caller takes the general path.
  subroutine rigid_dynamics(gear, ge, f_foot, f_field, loads, done, stat, errmsg, alpha)
    type(gear_t), intent(in) :: gear             !! rigid gear (committed state)
    type(gear_eval_t), intent(inout) :: ge       !! its evaluation
    real(wp), intent(in) :: f_foot(3)            !! ground force on the footpad, gear frame [N]
    logical, intent(in) :: loads                 !! compute the interface loads [-]
    real(wp), intent(in) :: f_field(3)           !! uniform field, gear frame [m/s^2]
    logical, intent(out) :: done                 !! .true. when the gear stays rigid this step
    integer, intent(out) :: stat                 !! 0 on success
    character(len=*), intent(inout) :: errmsg    !! message
    real(wp), intent(in), optional :: alpha(3)   !! body angular acceleration, gear axes [rad/s^2]
    type(gear_state_t) :: c
    stat = 0
    done = .false.
    if (gear%st%rigid_cache) then
      call rigid_solve(gear, gear%st, ge, f_foot, f_field, loads, done, stat, alpha)
    else
      ! not prepared (gear_prepare): the cache of a copy, for this evaluation only
      c = gear%st
      call rigid_cache(gear, c, stat, errmsg)
      if (stat /= 0) return
      call rigid_solve(gear, c, ge, f_foot, f_field, loads, done, stat, alpha)
    end if
  end subroutine rigid_dynamics

  !> The rigid gear's caches (strut kinematics, mass matrix, constraint rows with the three lock rows
  !! and the Cholesky factor of A M^-1 A^T), computed from its coordinates.
  subroutine rigid_cache(gear, c, stat, errmsg)
    type(gear_t), intent(in) :: gear             !! gear (geometry, masses)
    type(gear_state_t), intent(inout) :: c       !! state whose caches are set
    integer, intent(out) :: stat                 !! 0 on success
    character(len=*), intent(inout) :: errmsg    !! message
    integer :: k, i, j, nrow
    nrow = n_phi + 3
    call strut_kinematics(gear, c%q, c%sk_c)
    c%mdiag_c = gear_mass_matrix(gear, c%q)
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
    call factor_spd(nrow, c%chol_c, max_rows, stat, errmsg, 'gear DAE, rigid (A M^-1 A^T)')
    if (stat /= 0) return
    c%rigid_cache = .true.
  end subroutine rigid_cache

  !> The lock forces of a rigid gear with its cached factor (rigid_dynamics).
  subroutine rigid_solve(gear, c, ge, f_foot, f_field, loads, done, stat, alpha)
    type(gear_t), intent(in) :: gear             !! rigid gear
    type(gear_state_t), intent(in) :: c          !! its state with valid caches
    type(gear_eval_t), intent(inout) :: ge       !! its evaluation
    real(wp), intent(in) :: f_foot(3)            !! ground force on the footpad, gear frame [N]
    real(wp), intent(in) :: f_field(3)           !! uniform field, gear frame [m/s^2]
    logical, intent(in) :: loads                 !! compute the interface loads [-]
    logical, intent(out) :: done                 !! .true. when the gear stays rigid this step
    integer, intent(out) :: stat                 !! 0 (the cached factor is regular)
    real(wp), intent(in), optional :: alpha(3)   !! body angular acceleration, gear axes [rad/s^2]
    real(wp) :: q_ine(n_q), q_grv(n_q), q_ext(n_q), qf(n_q), lam(max_rows), zero(n_q), f_strut(3, 3)
    real(wp) :: s(3), sd(3), fpos, fneg, demand
    integer :: k, i, nrow
    stat = 0
    done = .false.
    nrow = n_phi + 3
    zero = 0.0_wp
    call generalized_forces(gear, c%q, zero, c%sk_c, f_field, f_foot, q_ine, q_grv, q_ext)
    qf = q_grv + q_ext
    if (present(alpha)) qf = qf + alpha_forces(gear, c%q, c%sk_c, alpha)
    qf = qf/c%mdiag_c
    do i = 1, nrow
      lam(i) = dot_product(c%a_c(i, :), qf)
    end do
    ! the cached factor's solves in the order of operations of LAPACK's dpotrs (landyn_small_spd)
    call small_upper_solve_multi(nrow, 1, c%chol_c, max_rows, lam, max_rows)
    call strokes(gear, c%q, zero, s, sd)
    do k = 1, 3
      ge%axial(k) = -lam(n_phi + k)
      call gear%buffer(k)%law%resistance(s(k), 0.0_wp, c%s_hismin(k), c%s_hismax(k), fpos, fneg)
      if (k == 1 .and. gear%tube%on) call add_tube_bound(ge%tube_bound, fpos, fneg)   ! tube friction (eq. 24)
      demand = gear%sigma(k)*ge%axial(k)
      if (-demand > fpos .or. demand > fneg) then
        ge%rigid = .false.
        return
      end if
    end do
    ge%qdd = 0.0_wp
    ge%f_body = f_foot
    ge%m_body = cross3(gear%geom%a + c%q(1)*c%sk_c(1)%u, f_foot)
    f_strut = 0.0_wp
    if (loads) call joint_loads(gear, c%sk_c, c%q, zero, zero, f_strut, f_strut, lam(1:n_phi), f_foot, f_field, &
                                alpha_or_zero(alpha), ge%f_body, ge%f_joint, ge%m_joint, ge%f_interface)
    done = .true.
  end subroutine rigid_solve

  !> Evaluates the gear (gear_evaluate) and commits the result at once (gear_commit), preparing a
  !! rigid gear's caches first: the gear alone, as the unit tests drive it.
  subroutine gear_dynamics(gear, f_foot, f_field, stat, errmsg, dt, alpha)
    type(gear_t), intent(inout) :: gear          !! gear; qdd, axial, locked, f_body are updated
    real(wp), intent(in) :: f_foot(3)            !! ground force on the footpad, gear frame [N]
    real(wp), intent(in) :: f_field(3)           !! uniform field g - a_frame, gear frame [m/s^2]
    integer, intent(out) :: stat                 !! 0 on success
    character(len=*), intent(inout) :: errmsg    !! diagnosis on failure
    real(wp), intent(in), optional :: dt         !! coming time step: velocity-level locking [s]
    real(wp), intent(in), optional :: alpha(3)   !! body angular acceleration, gear axes [rad/s^2]
    type(gear_eval_t) :: ge
    call gear_prepare(gear, stat, errmsg)
    if (stat /= 0) return
    call gear_evaluate(gear, ge, f_foot, f_field, stat, errmsg, dt, alpha)
    if (stat /= 0) return
    call gear_commit(gear, ge)
  end subroutine gear_dynamics

  !> Makes an evaluation (gear_evaluate) the gear's state: accelerations, buffer forces, lock
  !! decisions, the load on the body; a gear that broke loose from the rigid state leaves it.
  pure subroutine gear_commit(gear, ge)
    type(gear_t), intent(inout) :: gear          !! gear
    type(gear_eval_t), intent(in) :: ge          !! its evaluation
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
  end subroutine gear_commit

  !> Computes the caches of a gear that has become rigid (gear_settle), so that evaluating it needs
  !! only the cached factor. Nothing is done for a gear that is not rigid or already prepared.
  subroutine gear_prepare(gear, stat, errmsg)
    type(gear_t), intent(inout) :: gear          !! gear
    integer, intent(out) :: stat                 !! 0 on success
    character(len=*), intent(inout) :: errmsg    !! diagnosis on failure
    stat = 0
    if (gear%st%rigid .and. .not. gear%st%rigid_cache) call rigid_cache(gear, gear%st, stat, errmsg)
  end subroutine gear_prepare

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
    real(wp) :: ud(3), udd(3), f(3), hd(3), len, ld, ldd, t1d, t2d, sm, s1, jr
    f_rel = 0.0_wp
    m_rel = 0.0_wp
    do k = 1, 3
      i0 = idx_len(k) - 1
      len = gear%st%q(i0 + 1); ld = gear%st%qd(i0 + 1); ldd = qdd(i0 + 1)
      t1d = gear%st%qd(i0 + 2); t2d = gear%st%qd(i0 + 3)
      ud = sk(k)%u1*t1d + sk(k)%u2*t2d
      udd = sk(k)%u1*qdd(i0 + 2) + sk(k)%u2*qdd(i0 + 3) + sk(k)%u11*t1d*t1d &
            + 2.0_wp*sk(k)%u12*t1d*t2d + sk(k)%u22*t2d*t2d
      s1 = gear%m_in(k)*(len - gear%l_in(k)) + gear%m_end(k)*len
      sm = gear%s_0(k) + s1
      jr = strut_inertia(gear, k, len)
      f = gear%m_s(k)*ldd*sk(k)%u + 2.0_wp*gear%m_s(k)*ld*ud + sm*udd
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
    real(wp) :: ud(3), p(3), len, sm, jr, c
    p_rel = 0.0_wp
    h_rel = 0.0_wp
    t_rel = 0.0_wp
    do k = 1, 3
      i0 = idx_len(k) - 1
      len = gear%st%q(i0 + 1)
      ud = sk(k)%u1*qd(i0 + 2) + sk(k)%u2*qd(i0 + 3)
      sm = strut_first_moment(gear, k, len)
      jr = strut_inertia(gear, k, len)
      p = gear%m_s(k)*qd(i0 + 1)*sk(k)%u + sm*ud
      p_rel = p_rel + p
      h_rel = h_rel + cross3(sk(k)%p, p) + jr*cross3(sk(k)%u, ud)
      c = cos(gear%st%q(i0 + 3))
      t_rel = t_rel + 0.5_wp*(gear%m_s(k)*qd(i0 + 1)**2 + jr*(c*c*qd(i0 + 2)**2 + qd(i0 + 3)**2))
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
    real(wp) :: ud(3), len, sm
    call strut_kinematics(gear, gear%st%q, sk)
    p_rel = 0.0_wp
    do k = 1, 3
      i0 = idx_len(k) - 1
      len = gear%st%q(i0 + 1)
      ud = sk(k)%u1*gear%st%qd(i0 + 2) + sk(k)%u2*gear%st%qd(i0 + 3)
      sm = strut_first_moment(gear, k, len)
      p_rel = p_rel + gear%m_s(k)*gear%st%qd(i0 + 1)*sk(k)%u + sm*ud
    end do
    first_moment = leg_first_moment(gear, sk, gear%st%q)
    leg_mass = sum(gear%m_tot)
  end subroutine gear_leg_momentum

  !> First moment of mass of the leg parts, sum m x, gear frame.
  pure function leg_first_moment(gear, sk, q) result(fm)
    type(gear_t), intent(in) :: gear         !! gear (masses)
    type(strut_kin_t), intent(in) :: sk(3)   !! strut kinematics at q
    real(wp), intent(in) :: q(n_q)           !! coordinates [m, rad]
    real(wp) :: fm(3)                        !! [kg m]
    integer :: k
    real(wp) :: len, sm
    fm = 0.0_wp
    do k = 1, 3
      len = q(idx_len(k))
      sm = strut_first_moment(gear, k, len)
      fm = fm + gear%m_tot(k)*sk(k)%p + sm*sk(k)%u
    end do
  end function leg_first_moment

  !> Solves M qdd + A^T lam = Q, A qdd = b by elimination: (A M^-1 A^T) lam = A M^-1 Q - b.
  subroutine solve_reduced(nrow, a, b, mdiag, qf, qdd, lam, stat, errmsg)
    integer, intent(in) :: nrow                  !! number of constraint rows
    real(wp), intent(in) :: a(:, :)              !! constraint rows (nrow x n_q)
    real(wp), intent(in) :: b(:)                 !! constraint right-hand side
    real(wp), intent(in) :: mdiag(n_q)           !! mass matrix diagonal
    real(wp), intent(in) :: qf(n_q)              !! generalized force
    real(wp), intent(out) :: qdd(n_q)            !! accelerations
    real(wp), intent(out) :: lam(:)              !! multipliers
    integer, intent(out) :: stat                 !! 0 on success
    character(len=*), intent(inout) :: errmsg    !! message
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
    call solve_spd_unblocked(nrow, s, max_rows, r, stat, errmsg, 'gear DAE (A M^-1 A^T)')
    if (stat /= 0) return
    lam(1:nrow) = r(1:nrow)
    qdd = qf
    do i = 1, nrow
      qdd = qdd - lam(i)*a(i, 1:n_q)
    end do
    qdd = qdd/mdiag
  end subroutine solve_reduced

  !> The unreduced augmented system [[M, A^T],[A, 0]] [qdd; lam] = [Q; b] solved by LU (for checks).
  subroutine gear_solve_augmented_full(nrow, a, b, mdiag, qf, qdd, lam, stat, errmsg)
    integer, intent(in) :: nrow                  !! number of constraint rows
    real(wp), intent(in) :: a(:, :)              !! constraint rows (nrow x n_q)
    real(wp), intent(in) :: b(:)                 !! constraint right-hand side
    real(wp), intent(in) :: mdiag(n_q)           !! mass matrix diagonal
    real(wp), intent(in) :: qf(n_q)              !! generalized force
    real(wp), intent(out) :: qdd(n_q)            !! accelerations
    real(wp), intent(out) :: lam(:)              !! multipliers
    integer, intent(out) :: stat                 !! 0 on success
    character(len=*), intent(inout) :: errmsg    !! message
    real(wp) :: big(n_q + max_rows, n_q + max_rows), rhs(n_q + max_rows)
    integer :: n, j
    n = n_q + nrow
    big = 0.0_wp
    do j = 1, n_q
      big(j, j) = mdiag(j)
    end do
    big(1:n_q, n_q + 1:n) = transpose(a(1:nrow, 1:n_q))
    big(n_q + 1:n, 1:n_q) = a(1:nrow, 1:n_q)
    rhs(1:n_q) = qf
    rhs(n_q + 1:n) = b(1:nrow)
    call solve_general(n, big, n_q + max_rows, rhs, stat, errmsg, 'gear DAE (augmented)')
    if (stat /= 0) return
    qdd = rhs(1:n_q)
    lam(1:nrow) = rhs(n_q + 1:n)
  end subroutine gear_solve_augmented_full

  !> Advances the gear one step (semi-implicit Euler), decides the crush modes at the end of the
  !! step, applies the direct position correction of Step 4 and updates the crush history and the
  !! absorbed work. The velocity correction (Step 4's second half) is a plastic impact of the whole
  !! system and is done by the caller for all gears and the body together (landyn_impact); for a
  !! gear alone, with the body held fixed, `velocity = .true.` projects here in the gear's own
  !! kinetic metric (used by the unit tests of a free gear).
  subroutine gear_integrate(gear, dt, tol, max_iter, max_drift, stat, errmsg, velocity, kick)
    type(gear_t), intent(inout) :: gear          !! gear
    real(wp), intent(in) :: dt                   !! time step [s]
    real(wp), intent(in) :: tol                  !! correction tolerance [m, m/s]
    integer, intent(in) :: max_iter              !! iteration cap of the position correction
    real(wp), intent(in) :: max_drift            !! violation before correction that means dt is too large [m]
    integer, intent(out) :: stat                 !! 0 on success
    character(len=*), intent(inout) :: errmsg    !! diagnosis on failure
    logical, intent(in), optional :: velocity    !! also project the velocities (gear alone) [-]; default .false.
    real(wp), intent(in), optional :: kick       !! velocity update length (variable-step leapfrog); default dt [s]
    real(wp) :: s0(3), sd0(3), s1(3), sd1(3), qd_new(n_q), hk
    real(wp) :: a(max_rows, n_q), r(max_rows), viol, fpos, fneg, mdiag(n_q), lam(max_rows), w(max_rows, max_rows)
    integer :: k, iter, nrow, i, j
    character(len=msg_len) :: buf

    stat = 0
    if (gear%st%rigid .and. all(gear%st%locked)) return   ! no degree of freedom: nothing moves
    gear%st%rigid = .false.
    call strokes(gear, gear%st%q, gear%st%qd, s0, sd0)
    hk = dt
    if (present(kick)) hk = kick
    qd_new = gear%st%qd + gear%st%qdd*hk
    call strokes(gear, gear%st%q, qd_new, s1, sd1)
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
    gear%st%qd = qd_new
    ! Crush work during this step: the buffer force times the stroke increment, for sliding struts.
    gear%st%q = gear%st%q + gear%st%qd*dt
    gear%st%phq_ok = .false.
    call strokes(gear, gear%st%q, gear%st%qd, s1, sd1)
    do k = 1, 3
      if (.not. gear%st%locked(k)) then
        gear%st%work_crush(k) = gear%st%work_crush(k) + gear%sigma(k)*gear%st%axial(k)*(s0(k) - s1(k))
      end if
    end do

    ! Position correction: Phi(q) = 0 and locked strokes held, dq = -A^T (A A^T)^-1 r. The rows A
    ! are built only when a correction is needed (a locked gear at rest needs none).
    nrow = n_phi + count(gear%st%locked)
    call position_residual(gear, gear%st%q, nrow, r)
    viol = maxval(abs(r(1:n_phi)))
    gear%st%max_drift = max(gear%st%max_drift, viol)
    if (viol > max_drift) then
      stat = 2
      write (buf, '(a,es10.3,a,es10.3,a)') 'constraint drift ', viol, ' m in one step exceeds ', max_drift, &
        ' m: the time step is too large for this landing (reduce &simulation dt)'
      errmsg = buf
      return
    end if
    do iter = 1, max_iter
      if (maxval(abs(r(1:nrow))) <= tol) exit
      call build_rows(gear, gear%st%q, a, nrow)
      call min_norm_correction(nrow, a, r, gear%st%q, stat, errmsg)
      if (stat /= 0) return
      call position_residual(gear, gear%st%q, nrow, r)
      gear%st%n_correction_iter = max(gear%st%n_correction_iter, iter)
    end do
    viol = maxval(abs(r(1:nrow)))
    if (viol > tol) then
      stat = 3
      write (buf, '(a,i0,a,es10.3,a,es10.3,a)') 'position constraint correction did not converge in ', max_iter, &
        ' iterations (violation ', viol, ' m, tolerance ', tol, ' m)'
      errmsg = buf
      return
    end if
    gear%st%max_violation = max(gear%st%max_violation, viol)
    ! Crush history (positions only).
    call strokes(gear, gear%st%q, gear%st%qd, s1, sd1)
    gear%st%s_hismax = max(gear%st%s_hismax, s1)
    gear%st%s_hismin = min(gear%st%s_hismin, s1)

    if (present(velocity)) then
      if (velocity) then
        ! Gear alone, body fixed: qd <- qd - M^-1 A^T (A M^-1 A^T)^-1 A qd (kinetic metric).
        call build_rows(gear, gear%st%q, a, nrow)
        call row_products(nrow, a, gear%st%qd, r)
        if (maxval(abs(r(1:nrow))) > 0.0_wp) then
          mdiag = gear_mass_matrix(gear, gear%st%q)
          do j = 1, nrow
            do i = 1, j
              w(i, j) = sum(a(i, :)*a(j, :)/mdiag)
            end do
          end do
          lam(1:nrow) = r(1:nrow)
          call solve_spd_unblocked(nrow, w, max_rows, lam, stat, errmsg, 'gear velocity projection')
          if (stat /= 0) return
          do i = 1, nrow
            gear%st%qd = gear%st%qd - lam(i)*a(i, :)/mdiag
          end do
        end if
        call gear_settle(gear)
      end if
    end if
  end subroutine gear_integrate

  !> After the velocity projection: a gear whose three struts are all locked has A (Phi_q and the
  !! three lock rows) square and regular, so A qd = 0 means qd = 0; it becomes rigid.
  pure subroutine gear_settle(gear)
    type(gear_t), intent(inout) :: gear    !! gear after the velocity projection
    if (all(gear%st%locked) .and. .not. gear%st%rigid) then
      gear%st%qd = 0.0_wp
      gear%st%qdd = 0.0_wp
      gear%st%rigid = .true.
      gear%st%rigid_cache = .false.
    end if
  end subroutine gear_settle

  !> Velocity constraint rows of the gear at its current configuration: Phi_q and one row per
  !! locked strut (its stroke rate held at zero). A qd = 0 is the velocity constraint.
  pure subroutine gear_velocity_rows(gear, a, nrow)
    type(gear_t), intent(in) :: gear           !! gear
    real(wp), intent(out) :: a(max_rows, n_q)  !! rows [m/rad, -]
    integer, intent(out) :: nrow               !! number of rows [-]
    call build_rows(gear, gear%st%q, a, nrow)
  end subroutine gear_velocity_rows

  !> Linear maps from the generalized velocities to the legs' relative linear momentum and their
  !! relative angular momentum about the lander origin, both in gear axes:
  !! p_rel = pm qd, h_rel = hm qd (the same quantities as gear_relative_momenta).
  pure subroutine gear_momentum_maps(gear, pm, hm)
    type(gear_t), intent(in) :: gear       !! gear
    real(wp), intent(out) :: pm(3, n_q)    !! d p_rel / d qd [kg, kg m]
    real(wp), intent(out) :: hm(3, n_q)    !! d h_rel / d qd [kg m, kg m^2]
    type(strut_kin_t) :: sk(3)
    integer :: k, i0
    real(wp) :: len, sm, jr
    call strut_kinematics(gear, gear%st%q, sk)
    do k = 1, 3
      i0 = idx_len(k) - 1
      len = gear%st%q(i0 + 1)
      sm = strut_first_moment(gear, k, len)
      jr = strut_inertia(gear, k, len)
      pm(:, i0 + 1) = gear%m_s(k)*sk(k)%u
      pm(:, i0 + 2) = sm*sk(k)%u1
      pm(:, i0 + 3) = sm*sk(k)%u2
      hm(:, i0 + 1) = cross3(sk(k)%p, pm(:, i0 + 1))
      hm(:, i0 + 2) = cross3(sk(k)%p, pm(:, i0 + 2)) + jr*cross3(sk(k)%u, sk(k)%u1)
      hm(:, i0 + 3) = cross3(sk(k)%p, pm(:, i0 + 3)) + jr*cross3(sk(k)%u, sk(k)%u2)
    end do
  end subroutine gear_momentum_maps

  !> Rows of the correction: Phi_q and one row per locked strut.
  pure subroutine build_rows(gear, qv, a, nrow)
    type(gear_t), intent(in) :: gear           !! gear
    real(wp), intent(in) :: qv(n_q)            !! coordinates
    real(wp), intent(out) :: a(max_rows, n_q)  !! rows
    integer, intent(out) :: nrow               !! number of rows
    integer :: k
    a(1:n_phi, :) = gear_constraint_jacobian(gear%geom, qv)
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
  subroutine position_residual(gear, qv, nrow, r)
    type(gear_t), intent(in) :: gear        !! gear
    real(wp), intent(in) :: qv(n_q)         !! coordinates
    integer, intent(in) :: nrow             !! number of rows
    real(wp), intent(out) :: r(max_rows)    !! residual
    integer :: k, row
    real(wp) :: s(3), sd(3)
    r(1:n_phi) = gear_constraints(gear%geom, qv)
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

  !> r = A x for the first nrow rows.
  pure subroutine row_products(nrow, a, x, r)
    integer, intent(in) :: nrow                  !! rows
    real(wp), intent(in) :: a(max_rows, n_q)     !! rows
    real(wp), intent(in) :: x(n_q)               !! vector
    real(wp), intent(out) :: r(max_rows)         !! products
    integer :: i
    do i = 1, nrow
      r(i) = dot_product(a(i, :), x)
    end do
  end subroutine row_products

  !> x <- x - A^T (A A^T)^-1 r (minimum-norm correction, Step 4).
  subroutine min_norm_correction(nrow, a, r, x, stat, errmsg)
    integer, intent(in) :: nrow                  !! rows
    real(wp), intent(in) :: a(:, :)              !! Jacobian rows
    real(wp), intent(in) :: r(:)                 !! residual
    real(wp), intent(inout) :: x(n_q)            !! vector to correct
    integer, intent(out) :: stat                 !! 0 on success
    character(len=*), intent(inout) :: errmsg    !! message
    real(wp) :: s(max_rows, max_rows), y(max_rows)
    integer :: i, j
    do j = 1, nrow
      do i = 1, j
        s(i, j) = dot_product(a(i, 1:n_q), a(j, 1:n_q))
      end do
    end do
    y(1:nrow) = r(1:nrow)
    call small_spd_solve(nrow, s, max_rows, y, stat)
    if (stat /= 0) then
      write (errmsg, '(a,i0,a)') 'constraint correction: Phi_q Phi_q^T is not positive definite (minor ', stat, &
        '): redundant constraints or a singular configuration'
      return
    end if
    do i = 1, nrow
      x = x - y(i)*a(i, 1:n_q)
    end do
  end subroutine min_norm_correction

end module landyn_gear
