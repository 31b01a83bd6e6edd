!> The tripod landing gear's model: its coordinates, types, set-up, mass matrix and strokes
!! (paper section 2.4). The dynamics (landyn_gear_dynamics), the constraint correction
!! (landyn_gear_constraints), the momentum and inertia terms (landyn_gear_inertia) and the joint
!! loads (landyn_gear_joint_loads) work on the types defined here; landyn_gear collects the
!! public interface.
!!
!! Each gear has nine generalized coordinates q = (d1, th1, th2, db1, thb1, thb2, dc1, thc1, thc2),
!! measured in the gear frame, which is fixed to the lander body: per strut its length and the two
!! angles of its upper universal joint (parametrisation in landyn_kinematics). Six holonomic
!! constraints (eq. 6) tie the secondaries' lower ball joints to the lugs on the primary's outer
!! tube, leaving three degrees of freedom: the three strut lengths. Strut k's coordinates are
!! q(idx_len(k)) (length), q(idx_len(k) + 1) and q(idx_len(k) + 2) (angles); the layout itself is
!! defined once, by landyn_kinematics' iq_* indices.
!!
!! Mass model (derived, see docs/theory.md): each strut is a landyn_strut strut_t (upper part
!! pivoting with the strut, lower part sliding with its length, the primary carrying the footpad
!! mass at its lower end). With u = R0 (sin t2, -sin t1 cos t2, cos t1 cos t2),
!! |du/dt|^2 = cos^2 t2 t1dot^2 + t2dot^2, so the kinetic energy of one strut is
!! T = 1/2 m_s Ldot^2 + 1/2 J(L) (cos^2 t2 t1dot^2 + t2dot^2): the mass matrix is diagonal and the
!! velocity-coupling terms follow from Lagrange's equations.
module landyn_gear_model
  use landyn_kinds, only: wp
  use landyn_buffer, only: buffer_law_t
  use landyn_gear_base, only: gear_eval_t   ! the evaluation record of every gear type
  use landyn_kinematics, only: gear_geometry_t, strut_axis_derivs, n_gear_q, n_gear_phi, iq_d1, iq_db1, iq_dc1
  use landyn_status, only: STAT_OK, STAT_FAILED
  use landyn_strut, only: strut_mass_t, strut_t, strut_from_mass, strut_mass_functions_t
  use landyn_tube_friction, only: tube_friction_t
  implicit none
  private

  public :: gear_t, buffer_slot_t, gear_state_t, gear_eval_t, strut_kin_t, strut_mass_t
  public :: gear_init, gear_footpad, gear_mass_matrix, gear_relative_kinetic_energy, gear_law_segments
  public :: gear_strokes, gear_strut_lengths, gear_leg_mass, gear_rotation, gear_rates, gear_set_rates, gear_led_rates
  public :: gear_locks, gear_strut_modes, strut_modes, gear_is_rigid, gear_cache_jacobian, gear_mass_diagonal
  public :: gear_crush_history, gear_crush_work, gear_violations, gear_buffer_capacity, gear_set_buffer
  public :: gear_save_state, gear_restore_state, gear_axial_forces, gear_body_load
  public :: strut_kinematics, strokes, leg_first_moment
  public :: n_struts, strut_names, n_q, n_phi, max_rows, idx_len

  integer, parameter :: n_struts = 3                      !! struts per gear (primary, left, right) [-]
  character(len=*), parameter :: strut_names(n_struts) = [character(len=15) :: 'primary', 'secondary left', &
                                                          'secondary right']   !! names of the struts [-]
  integer, parameter :: n_q = n_gear_q                    !! generalized coordinates per gear (landyn_kinematics) [-]
  integer, parameter :: n_phi = n_gear_phi                !! holonomic constraints per gear (landyn_kinematics) [-]
  integer, parameter :: max_rows = n_phi + n_struts       !! constraint rows per gear at most (Phi_q and the locks) [-]
  integer, parameter :: idx_len(n_struts) = [iq_d1, iq_db1, iq_dc1]   !! index of each strut's length in q [-]

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
    type(strut_mass_functions_t) :: mf  !! mass functions at the strut's length [kg, kg m, kg m^2]
  end type strut_kin_t

  !> Everything of a gear that evolves in time (coordinates, rates, crush modes and history,
  !! accumulators) and the caches that depend on it: gear_t's component `st`. Copying it out and
  !! back restores the gear exactly, so that a step can be rejected or repeated (the geometry,
  !! masses and buffer laws are parameters and stay in gear_t).
  type :: gear_state_t
    real(wp) :: q(n_q) = 0.0_wp                   !! generalized coordinates [m, rad]
    real(wp) :: qd(n_q) = 0.0_wp                  !! generalized velocities [m/s, rad/s]
    real(wp) :: qdd(n_q) = 0.0_wp                 !! generalized accelerations [m/s^2, rad/s^2]
    logical :: locked(n_struts) = .true.                 !! strut locked [-]
    integer :: dir(n_struts) = 0                         !! sliding direction [-]
    real(wp) :: s_lock(n_struts) = 0.0_wp                !! stroke held by a locked strut [m]
    real(wp) :: s_hismin(n_struts) = 0.0_wp              !! most negative stroke reached [m]
    real(wp) :: s_hismax(n_struts) = 0.0_wp              !! most positive stroke reached [m]
    real(wp) :: axial(n_struts) = 0.0_wp                 !! axial buffer force [N]
    real(wp) :: f_body(3) = 0.0_wp                !! force on the body, gear frame [N]
    real(wp) :: m_body(3) = 0.0_wp                !! moment on the body about O_L, gear axes [N m]
    real(wp) :: work_crush(n_struts) = 0.0_wp            !! energy absorbed by each buffer [J]
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
    type(strut_kin_t) :: sk_c(n_struts)                  !! cached strut kinematics
    real(wp) :: mdiag_c(n_q) = 0.0_wp             !! cached mass matrix diagonal [kg, kg m^2]
    real(wp) :: a_c(max_rows, n_q) = 0.0_wp       !! cached constraint rows [-, m]
    real(wp) :: chol_c(max_rows, max_rows) = 0.0_wp  !! cached Cholesky factor
    logical :: phq_ok = .false.                   !! Phi_q cache valid [-]
    real(wp) :: phq(n_phi, n_q) = 0.0_wp          !! cached Phi_q [-, m]
    real(wp) :: phq_q(n_q) = 0.0_wp               !! its q [m, rad]
  end type gear_state_t

  !> One landing gear: geometry, masses, buffers and state.
  type :: gear_t
    type(gear_geometry_t) :: geom                 !! hard points and nominal strut frames, gear frame
    real(wp) :: rot(3, 3) = 0.0_wp                !! gear frame -> lander frame rotation [-]
    type(strut_t) :: strut(n_struts)              !! primary, left, right: mass models (landyn_strut)
    real(wp) :: leg_mass = 0.0_wp                 !! sum of the strut masses (set by gear_init) [kg]
    real(wp) :: row_bound = 0.0_wp                !! bound on |A_ij| of the correction rows [m]
    type(buffer_slot_t) :: buffer(n_struts)              !! primary, left, right buffer laws
    type(tube_friction_t) :: tube                 !! friction between the primary's tubes (eqs. 23-26)
    real(wp) :: sigma(n_struts) = [-1.0_wp, 1.0_wp, 1.0_wp]  !! ds/dL: stroke sign convention per strut [-]
    real(wp) :: len0(n_struts) = 0.0_wp                  !! nominal strut lengths [m]
    type(gear_state_t) :: st                      !! everything that evolves (a snapshot is a copy of it)
  end type gear_t

contains

  !> Sets up a gear at its nominal configuration, all struts locked and at rest.
  subroutine gear_init(gear, geom, rot, mass, stat, errmsg, tube)
    type(gear_t), intent(inout) :: gear          !! gear to initialise (buffers must already be allocated)
    type(gear_geometry_t), intent(in) :: geom    !! geometry in the gear frame
    real(wp), intent(in) :: rot(3, 3)            !! gear frame -> lander frame [-]
    type(strut_mass_t), intent(in) :: mass(n_struts)    !! strut mass properties
    integer, intent(out) :: stat                 !! STAT_OK, or STAT_FAILED (a buffer law or sliding mass missing)
    character(len=*), intent(inout) :: errmsg    !! message on failure
    type(tube_friction_t), intent(in), optional :: tube  !! primary tube friction; absent: off
    integer :: k
    stat = STAT_OK
    gear%tube = tube_friction_t()
    if (present(tube)) gear%tube = tube
    gear%st%tube_bound = 0.0_wp
    gear%geom = geom
    gear%rot = rot
    gear%leg_mass = 0.0_wp
    do k = 1, n_struts
      gear%strut(k) = strut_from_mass(mass(k))
      gear%leg_mass = gear%leg_mass + gear%strut(k)%total_mass()
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
    do k = 1, n_struts
      if (.not. allocated(gear%buffer(k)%law)) then
        stat = STAT_FAILED
        errmsg = 'gear_init: buffer law not set'
        return
      end if
      if (mass(k)%m_i + mass(k)%m_end <= 0.0_wp) then
        stat = STAT_FAILED
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

  !> Upper joint, axis and axis partials of each strut at q, and its mass functions at its length
  !! (computed once per use).
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
    sk(1)%mf = gear%strut(1)%at(q(idx_len(1)))
    sk(2)%mf = gear%strut(2)%at(q(idx_len(2)))
    sk(3)%mf = gear%strut(3)%at(q(idx_len(3)))
  end subroutine strut_kinematics

  !> Diagonal of the mass matrix M(q).
  pure function gear_mass_matrix(gear, q) result(mdiag)
    type(gear_t), intent(in) :: gear   !! gear
    real(wp), intent(in) :: q(n_q)     !! generalized coordinates [m, rad]
    real(wp) :: mdiag(n_q)             !! diagonal of M [kg, kg m^2]
    integer :: k, i0
    type(strut_mass_functions_t) :: mf
    real(wp) :: jr, c, len
    do k = 1, 3
      i0 = idx_len(k) - 1
      len = q(i0 + 1)
      mf = gear%strut(k)%at(len)
      jr = mf%j
      c = cos(q(i0 + 3))
      mdiag(i0 + 1) = mf%m_s
      mdiag(i0 + 2) = jr*c*c
      mdiag(i0 + 3) = jr
    end do
  end function gear_mass_matrix

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

  !> First moment of mass of the leg parts, sum m x, gear frame.
  pure function leg_first_moment(sk, q) result(fm)
    type(strut_kin_t), intent(in) :: sk(3)   !! strut kinematics at q
    real(wp), intent(in) :: q(n_q)           !! coordinates [m, rad]
    real(wp) :: fm(3)                        !! [kg m]
    integer :: k
    type(strut_mass_functions_t) :: mf
    real(wp) :: len, sm
    fm = 0.0_wp
    do k = 1, 3
      len = q(idx_len(k))
      mf = sk(k)%mf
      sm = mf%s
      fm = fm + mf%m_tot*sk(k)%p + sm*sk(k)%u
    end do
  end function leg_first_moment

  !> Stroke and stroke rate of each strut at the gear's current state (Table 3 sense).
  pure subroutine gear_strokes(gear, s, sd)
    type(gear_t), intent(in) :: gear        !! gear
    real(wp), intent(out) :: s(n_struts)    !! strokes [m]
    real(wp), intent(out) :: sd(n_struts)   !! stroke rates [m/s]
    call strokes(gear, gear%st%q, gear%st%qd, s, sd)
  end subroutine gear_strokes

  !> Strut lengths at the gear's current state.
  pure function gear_strut_lengths(gear) result(len)
    type(gear_t), intent(in) :: gear        !! gear
    real(wp) :: len(n_struts)               !! strut lengths [m]
    len = gear%st%q(idx_len)
  end function gear_strut_lengths

  !> Mass of the leg parts, the sum of the strut masses.
  pure real(wp) function gear_leg_mass(gear) result(m)
    type(gear_t), intent(in) :: gear        !! gear
    m = gear%leg_mass
  end function gear_leg_mass

  !> Gear frame -> lander frame rotation.
  pure function gear_rotation(gear) result(rot)
    type(gear_t), intent(in) :: gear        !! gear
    real(wp) :: rot(3, 3)                   !! [-]
    rot = gear%rot
  end function gear_rotation

  !> Generalized velocities (the stored ones: half a step behind the coordinates in the leapfrog).
  pure function gear_rates(gear) result(qd)
    type(gear_t), intent(in) :: gear        !! gear
    real(wp) :: qd(n_q)                     !! [m/s, rad/s]
    qd = gear%st%qd
  end function gear_rates

  !> Replaces the generalized velocities (the system velocity projection; leading the stored
  !! velocities for an output sample, undone afterwards). A rigid gear must stay at rest.
  pure subroutine gear_set_rates(gear, qd)
    type(gear_t), intent(inout) :: gear     !! gear
    real(wp), intent(in) :: qd(n_q)         !! [m/s, rad/s]
    gear%st%qd = qd
  end subroutine gear_set_rates

  !> The generalized velocities led by `lead` times the committed accelerations, qd + lead qdd.
  pure function gear_led_rates(gear, lead) result(qd)
    type(gear_t), intent(in) :: gear        !! gear
    real(wp), intent(in) :: lead            !! [s]
    real(wp) :: qd(n_q)                     !! [m/s, rad/s]
    qd = gear%st%qd + lead*gear%st%qdd
  end function gear_led_rates

  !> Which struts are locked (committed state).
  pure function gear_locks(gear) result(locked)
    type(gear_t), intent(in) :: gear        !! gear
    logical :: locked(n_struts)             !! [-]
    locked = gear%st%locked
  end function gear_locks

  !> Crush mode of each strut of the committed state (strut_modes).
  pure function gear_strut_modes(gear) result(m)
    type(gear_t), intent(in) :: gear        !! gear
    integer :: m(n_struts)                  !! [-]
    m = strut_modes(gear%st%locked, gear%st%axial, gear%st%dir)
  end function gear_strut_modes

  !> Crush mode of each strut: 0 locked, +1 crushing toward +s, -1 crushing toward -s (sliding
  !! against a nonzero bound), 2 sliding freely inside the crushed range (no force; its direction
  !! of motion is not a mode).
  pure function strut_modes(locked, axial, dir) result(m)
    logical, intent(in) :: locked(n_struts)   !! struts locked [-]
    real(wp), intent(in) :: axial(n_struts)   !! axial buffer forces [N]
    integer, intent(in) :: dir(n_struts)      !! sliding directions [-]
    integer :: m(n_struts)                    !! modes [-]
    integer :: k
    do k = 1, n_struts
      if (locked(k)) then
        m(k) = 0
      else if (abs(axial(k)) > tiny(1.0_wp)) then
        m(k) = sign(1, dir(k))
      else
        m(k) = 2
      end if
    end do
  end function strut_modes

  !> The gear is rigid: all struts locked and at rest relative to the body.
  pure logical function gear_is_rigid(gear) result(rigid)
    type(gear_t), intent(in) :: gear        !! gear
    rigid = gear%st%rigid
  end function gear_is_rigid

  !> Caches Phi_q at the current coordinates for the next evaluation (it was computed for the
  !! velocity projection at the same configuration).
  pure subroutine gear_cache_jacobian(gear, phq)
    type(gear_t), intent(inout) :: gear     !! gear
    real(wp), intent(in) :: phq(:, :)       !! Phi_q at gear%st%q, n_phi x n_q [-, m]
    gear%st%phq = phq
    gear%st%phq_q = gear%st%q
    gear%st%phq_ok = .true.
  end subroutine gear_cache_jacobian

  !> Diagonal of the mass matrix at the current coordinates.
  pure function gear_mass_diagonal(gear) result(mdiag)
    type(gear_t), intent(in) :: gear        !! gear
    real(wp) :: mdiag(n_q)                  !! [kg, kg m^2]
    mdiag = gear_mass_matrix(gear, gear%st%q)
  end function gear_mass_diagonal

  !> Most negative and most positive stroke reached by each strut.
  pure subroutine gear_crush_history(gear, s_min, s_max)
    type(gear_t), intent(in) :: gear          !! gear
    real(wp), intent(out) :: s_min(n_struts)  !! [m]
    real(wp), intent(out) :: s_max(n_struts)  !! [m]
    s_min = gear%st%s_hismin
    s_max = gear%st%s_hismax
  end subroutine gear_crush_history

  !> Energy absorbed by each buffer so far.
  pure function gear_crush_work(gear) result(w)
    type(gear_t), intent(in) :: gear        !! gear
    real(wp) :: w(n_struts)                 !! [J]
    w = gear%st%work_crush
  end function gear_crush_work

  !> Largest constraint violation after and before the correction so far.
  pure subroutine gear_violations(gear, violation, drift)
    type(gear_t), intent(in) :: gear        !! gear
    real(wp), intent(out) :: violation      !! after correction [m]
    real(wp), intent(out) :: drift          !! before correction [m]
    violation = gear%st%max_violation
    drift = gear%st%max_drift
  end subroutine gear_violations

  !> Stroke capacity of strut k's buffer in each direction (buffer_law_t%capacity).
  subroutine gear_buffer_capacity(gear, k, cap_pos, cap_neg)
    type(gear_t), intent(in) :: gear        !! gear
    integer, intent(in) :: k                !! strut [-]
    real(wp), intent(out) :: cap_pos        !! toward +s [m]
    real(wp), intent(out) :: cap_neg        !! toward -s (0: none) [m]
    call gear%buffer(k)%law%capacity(cap_pos, cap_neg)
  end subroutine gear_buffer_capacity

  !> Sets strut k's buffer law (before gear_init).
  subroutine gear_set_buffer(gear, k, law)
    type(gear_t), intent(inout) :: gear     !! gear
    integer, intent(in) :: k                !! strut [-]
    class(buffer_law_t), intent(in) :: law  !! buffer law
    if (allocated(gear%buffer(k)%law)) deallocate (gear%buffer(k)%law)
    allocate (gear%buffer(k)%law, source=law)
  end subroutine gear_set_buffer

  !> Copies the gear's evolving state out (a snapshot: restoring it repeats the gear bit for bit).
  pure subroutine gear_save_state(gear, st)
    type(gear_t), intent(in) :: gear        !! gear
    ! inout, not out: intent(out) would first reset the record to its defaults at every save
    type(gear_state_t), intent(inout) :: st !! its state (previous contents replaced)
    st = gear%st
  end subroutine gear_save_state

  !> Puts a state from gear_save_state back.
  pure subroutine gear_restore_state(gear, st)
    type(gear_t), intent(inout) :: gear     !! gear
    type(gear_state_t), intent(in) :: st    !! saved state
    gear%st = st
  end subroutine gear_restore_state

  !> Axial buffer forces of the committed state (compression positive for the primary, the
  !! Table-3 sense of each strut).
  pure function gear_axial_forces(gear) result(axial)
    type(gear_t), intent(in) :: gear        !! gear
    real(wp) :: axial(n_struts)             !! [N]
    axial = gear%st%axial
  end function gear_axial_forces

  !> The committed load on the body: force and moment about the lander origin, gear frame.
  pure subroutine gear_body_load(gear, f_body, m_body)
    type(gear_t), intent(in) :: gear        !! gear
    real(wp), intent(out) :: f_body(3)      !! [N]
    real(wp), intent(out) :: m_body(3)      !! [N m]
    f_body = gear%st%f_body
    m_body = gear%st%m_body
  end subroutine gear_body_load

end module landyn_gear_model
