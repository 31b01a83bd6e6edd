!> The paper's tripod gear (section 2.4, eqs. 12-16, Step 4 of section 3.1), a primary strut with
!! the footpad and two secondaries, as one gear type: tripod_gear_t extends gear_base_t, and its
!! bindings are its own procedures, so the simulation runs it through gear_base_t exactly as
!! defined here. This module declares its coordinates, its types and the interfaces of every
!! procedure of the gear; tripod_gear_t and gear_state_t are opaque (private components): the
!! bodies live in the submodules of this module, which see the components, and everyone else goes
!! through the bindings and, for what only tests set or read, the public procedures
!! (gear_set_coordinates, gear_body_load, gear_dynamics, ...). tripod_init builds one from its
!! geometry, strut masses and buffer laws.
!!
!!   landyn_tripod_setup        set-up, footpad, strut kinematics, mass matrix, strokes, accessors,
!!                              the bindings' accessors and snapshots
!!   landyn_tripod_inertia      generalized forces, relative momentum and inertia terms
!!   landyn_tripod_dynamics     crush logic and the gear DAE at one instant (gear_evaluate/commit)
!!   landyn_tripod_joint_loads  interface loads of the joints
!!   landyn_tripod_constraints  the gear's step, its velocity rows and constraint-violation correction
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
module landyn_tripod_gear
  use landyn_kinds, only: wp, max_gear_rows, max_gear_q
  use landyn_buffer, only: buffer_law_t
  use landyn_gear_base, only: gear_base_t, gear_eval_t, gear_snapshot_t, strut_name_len, strut_mode, strut_mode_after
  use landyn_kinematics, only: gear_geometry_t, n_gear_q, n_gear_phi, iq_d1, iq_db1, iq_dc1, joint_trig_t, axis_derivs_t
  use landyn_strut, only: strut_mass_t, strut_t, strut_mass_functions_t
  use landyn_tube_friction, only: tube_friction_t
  use landyn_status, only: status_t
  implicit none
  private

  public :: tripod_gear_t, tripod_init, gear_state_t, gear_eval_t, strut_mass_t, strut_t
  public :: gear_init, gear_footpad, gear_mass_matrix, gear_relative_kinetic_energy
  public :: gear_strokes, gear_rates, gear_set_rates
  public :: gear_locks, gear_strut_modes, strut_modes, gear_is_rigid, gear_cache_jacobian
  public :: gear_crush_history, gear_crush_work, gear_violations, gear_buffer_capacity, gear_set_buffer
  public :: gear_axial_forces, gear_body_load
  public :: gear_coordinates, gear_accelerations, gear_set_coordinates, gear_set_locks, gear_slide_directions
  public :: gear_set_crush_history, gear_set_axial_forces, gear_set_rigid, gear_tube_bound, gear_geometry
  public :: gear_strut, gear_nominal_lengths
  public :: gear_generalized_forces, gear_relative_momenta, gear_leg_momentum, gear_momentum_maps
  public :: gear_evaluate, gear_commit, gear_prepare, gear_dynamics
  public :: gear_arrest, gear_increment, gear_correct_positions, gear_project_alone, gear_settle, gear_velocity_rows
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
    class(buffer_law_t), allocatable :: law   !! the strut's buffer law (landyn_buffer)
  end type buffer_slot_t

  !> Kinematics of one strut at a configuration: its axis and the axis's partials (axis_derivs_t:
  !! u, u1, u2, u11, u12, u22), upper joint and mass functions.
  type, extends(axis_derivs_t) :: strut_kin_t
    real(wp) :: p(3) = 0.0_wp     !! upper joint, gear frame [m]
    type(strut_mass_functions_t) :: mf  !! mass functions at the strut's length [kg, kg m, kg m^2]
  end type strut_kin_t

  !> Everything of a gear that evolves in time (coordinates, rates, crush modes and history,
  !! accumulators) and the caches that depend on it: gear_t's component `st`. An opaque snapshot:
  !! copying it out (tripod_save_state) and back (tripod_restore_state) restores the gear exactly, so
  !! that a step can be rejected or repeated (the geometry, masses and buffer laws are parameters
  !! and stay in gear_t).
  type :: gear_state_t
    private
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
    ! A strut stopped in this step by its lock row leaves it in the mode its holding force decided
    ! (gear_eval_t%dir_after): applied by gear_settle after the step's projections
    integer :: dir_after(n_struts) = 0                   !! direction it leaves the step in, 0: none [-]
    real(wp) :: axial_after(n_struts) = 0.0_wp           !! its axial buffer force after the step [N]
    ! Rigid state: all three struts locked. The gear then has no degree of freedom: qd = qdd = 0
    ! exactly, q and the constraint matrix stay constant, and the Cholesky factor of A M^-1 A^T is
    ! computed once and reused until a strut breaks loose.
    logical :: rigid = .false.                    !! all struts locked and qd = 0 (set by gear_settle;
                                                  !! changing locked or qd from outside requires rigid = .false.)
    logical :: rigid_cache = .false.              !! the caches below are valid
    type(strut_kin_t) :: sk_c(n_struts)                  !! cached strut kinematics
    real(wp) :: mdiag_c(n_q) = 0.0_wp             !! cached mass matrix diagonal [kg, kg m^2]
    real(wp) :: a_c(max_rows, n_q) = 0.0_wp       !! cached constraint rows [-, m]
    real(wp) :: chol_c(max_rows, max_rows) = 0.0_wp  !! cached Cholesky factor
    logical :: phq_ok = .false.                   !! Phi_q cache valid [-]
    real(wp) :: phq(n_phi, n_q) = 0.0_wp          !! cached Phi_q [-, m]
    real(wp) :: phq_q(n_q) = 0.0_wp               !! its q [m, rad]
    ! The strut kinematics and mass functions at the current coordinates (strut_kinematics),
    ! computed once per step (gear_correct_positions) and reused by every evaluation at the same q (the
    ! dynamics, the velocity projection's momentum maps and mass matrix, the energy audit).
    logical :: kin_ok = .false.                   !! kin is valid for the coordinates kin_q [-]
    real(wp) :: kin_q(n_q) = 0.0_wp               !! coordinates of the cached kinematics [m, rad]
    type(strut_kin_t) :: kin(n_struts)            !! cached strut kinematics at kin_q
    ! The joint trigonometry (gear_trig) at the corrected coordinates (gear_correct_positions), for
    ! the evaluations at the same q: the velocity coupling and gamma.
    logical :: trig_ok = .false.                  !! trig is valid for the coordinates trig_q [-]
    real(wp) :: trig_q(n_q) = 0.0_wp              !! coordinates of the cached trigonometry [m, rad]
    type(joint_trig_t) :: trig(n_struts)          !! cos and sin of each strut's joint angles at trig_q [-]
  end type gear_state_t

  !> The tripod landing gear: geometry, masses, buffers and state; the gear_base_t bindings are
  !! its own procedures (bodies in the submodules).
  type, extends(gear_base_t) :: tripod_gear_t
    private
    type(gear_geometry_t) :: geom                 !! hard points and nominal strut frames, gear frame
    type(strut_t) :: strut(n_struts)              !! primary, left, right: mass models (landyn_strut)
    real(wp) :: leg_mass = 0.0_wp                 !! sum of the strut masses (set by gear_init) [kg]
    real(wp) :: row_bound = 0.0_wp                !! bound on |A_ij| of the correction rows [m]
    type(buffer_slot_t) :: buffer(n_struts)              !! primary, left, right buffer laws
    type(tube_friction_t) :: tube                 !! friction between the primary's tubes (eqs. 23-26)
    real(wp) :: sigma(n_struts) = [-1.0_wp, 1.0_wp, 1.0_wp]  !! ds/dL: stroke sign convention per strut [-]
    real(wp) :: len0(n_struts) = 0.0_wp                  !! nominal strut lengths [m]
    type(gear_state_t) :: st                      !! everything that evolves (a snapshot is a copy of it)
  contains
    ! ---- the dynamics (gear_base_t)
    procedure :: footpad => gear_footpad                               !! footpad position and velocity [m, m/s]
    procedure :: evaluate => gear_evaluate                             !! crush logic and accelerations
    procedure :: commit => gear_commit                                 !! makes an evaluation the committed state
    procedure :: arrest => gear_arrest                                 !! crush modes at the end of a step
    procedure :: increment => gear_increment                           !! q <- q + qd h, with the crush work
    procedure :: correct_positions => gear_correct_positions           !! position projection onto the constraints
    procedure :: settle => gear_settle                                 !! all struts locked: the gear becomes rigid
    procedure :: is_rigid => gear_is_rigid                             !! all struts locked and at rest
    procedure :: locks => tripod_locks                                 !! which struts are locked [-]
    procedure :: strokes => gear_strokes                               !! strokes and stroke rates [m, m/s]
    procedure :: rates => tripod_rates                                 !! generalized velocities [m/s, rad/s]
    procedure :: set_rates => gear_set_rates                           !! replaces the generalized velocities
    procedure :: accelerations => tripod_accelerations                 !! committed accelerations [m/s^2, rad/s^2]
    procedure :: velocity_rows => tripod_velocity_rows                 !! velocity constraint rows, Phi_q cached
    procedure :: mass_diagonal => tripod_mass_diagonal                 !! mass matrix diagonal [kg, kg m^2]
    procedure :: momentum_maps => gear_momentum_maps                   !! maps from qd to the legs' momenta
    procedure :: relative_momenta => gear_relative_momenta             !! legs' relative momenta and kinetic energy
    procedure :: leg_momentum => gear_leg_momentum                     !! legs' momentum, first moment and mass
    procedure :: new_snapshot => tripod_new_snapshot                   !! a tripod_snapshot_t
    procedure :: save_state => tripod_save_state                       !! copies the evolving state out
    procedure :: restore_state => tripod_restore_state                 !! puts a saved state back
    ! ---- the reports (gear_base_t)
    procedure :: strut_lengths => tripod_strut_lengths                 !! strut lengths [m]
    procedure :: violations => gear_violations                         !! largest constraint violations [m]
    procedure :: strut_name => tripod_strut_name                       !! primary, secondary left, secondary right
    procedure :: strut_modes => tripod_strut_modes                     !! crush mode of each strut [-]
    procedure :: axial_forces => tripod_axial_forces                   !! axial buffer forces [N]
    procedure :: crush_history => gear_crush_history                   !! most negative and positive strokes [m]
    procedure :: crush_work => tripod_crush_work                       !! energy absorbed by each buffer [J]
    procedure :: buffer_capacity => gear_buffer_capacity               !! stroke capacity of strut k's buffer [m]
    procedure :: crush_levels => tripod_crush_levels                   !! strut k's buffer levels, axial [N]
    procedure :: law_segments => gear_law_segments                     !! piece of each buffer law [-]
    procedure :: coordinate_weights => tripod_coordinate_weights       !! error-norm weights of the coordinates [-]
    procedure :: prepare => gear_prepare                               !! caches of a rigid gear
  end type tripod_gear_t

  !> The tripod's evolving state (gear_state_t) as a gear_base_t snapshot.
  type, extends(gear_snapshot_t) :: tripod_snapshot_t
    type(gear_state_t) :: st                      !! the saved state
  end type tripod_snapshot_t

  interface
    ! ---- set-up, footpad, strut kinematics, mass matrix, strokes and accessors (landyn_tripod_setup)

    !> Sets up a gear at its nominal configuration, all struts locked and at rest.
    module subroutine gear_init(gear, geom, rot, mass, status, tube)
      class(tripod_gear_t), intent(inout) :: gear          !! gear to initialise (buffers must already be allocated)
      type(gear_geometry_t), intent(in) :: geom    !! geometry in the gear frame
      real(wp), intent(in) :: rot(3, 3)            !! gear frame -> lander frame [-]
      type(strut_mass_t), intent(in) :: mass(n_struts)    !! strut mass properties
      type(status_t), intent(out) :: status        !! STAT_OK, or STAT_FAILED (a buffer law or sliding mass missing) [-]
      type(tube_friction_t), intent(in), optional :: tube  !! primary tube friction; absent: off
    end subroutine gear_init

    !> Footpad position and velocity in the gear frame.
    module pure subroutine gear_footpad(gear, pos, vel, rates)
      class(tripod_gear_t), intent(in) :: gear     !! gear
      real(wp), intent(out) :: pos(3)      !! footpad joint position, gear frame [m]
      real(wp), intent(out) :: vel(3)      !! its velocity relative to the body, gear frame [m/s]
      real(wp), intent(in), optional :: rates(:)  !! generalized velocities to use (n_q); default the gear's [m/s, rad/s]
    end subroutine gear_footpad

    !> Upper joint, axis and axis partials of each strut at q, and its mass functions at its length
    !! (the cached ones when q is the configuration they were computed at: the same values).
    module pure subroutine strut_kinematics(gear, q, sk)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp), intent(in) :: q(n_q)          !! coordinates [m, rad]
      type(strut_kin_t), intent(inout) :: sk(3) !! per-strut kinematics (every component set; inout so
                                                !! that the record is not reset before it is overwritten)
    end subroutine strut_kinematics

    !> The strut kinematics computed afresh from the geometry and the struts alone (never from the
    !! gear's state: a caller may be writing that state while it asks).
    module pure subroutine kinematics_at(geom, strut, q, sk, trig)
      type(gear_geometry_t), intent(in) :: geom     !! hard points and nominal strut frames, gear frame
      type(strut_t), intent(in) :: strut(n_struts)  !! the struts' mass models
      real(wp), intent(in) :: q(n_q)                !! coordinates [m, rad]
      type(strut_kin_t), intent(inout) :: sk(3)     !! per-strut kinematics (every component set)
      type(joint_trig_t), intent(in), optional :: trig(n_struts)  !! gear_trig(q), when at hand [-]
    end subroutine kinematics_at

    !> The secondaries' axis and its partials from their strut kinematics (for the constraint
    !! Jacobian and gamma, which would compute the same values at the same coordinates).
    module pure function secondary_axes_of(sk) result(axes)
      type(strut_kin_t), intent(in) :: sk(n_struts)  !! strut kinematics
      type(axis_derivs_t) :: axes(2)                 !! left and right secondary [-, 1/rad, 1/rad^2]
    end function secondary_axes_of

    !> Diagonal of the mass matrix M(q).
    module pure function gear_mass_matrix(gear, q) result(mdiag)
      class(tripod_gear_t), intent(in) :: gear   !! gear
      real(wp), intent(in) :: q(n_q)     !! generalized coordinates [m, rad]
      real(wp) :: mdiag(n_q)             !! diagonal of M [kg, kg m^2]
    end function gear_mass_matrix

    !> Diagonal of the mass matrix at q from the struts' mass functions at their lengths q(idx_len).
    module pure function mass_diagonal(sk, q) result(mdiag)
      type(strut_kin_t), intent(in) :: sk(:)  !! strut kinematics with the mass functions [kg, kg m, kg m^2]
      real(wp), intent(in) :: q(n_q)     !! generalized coordinates [m, rad]
      real(wp) :: mdiag(n_q)             !! diagonal of M [kg, kg m^2]
    end function mass_diagonal

    !> Caches the strut kinematics at the current coordinates (after they changed).
    module pure subroutine cache_kinematics(gear)
      class(tripod_gear_t), intent(inout) :: gear   !! gear
    end subroutine cache_kinematics

    !> Relative kinetic energy of the leg parts, 1/2 qd^T M qd.
    module pure function gear_relative_kinetic_energy(gear) result(t)
      class(tripod_gear_t), intent(in) :: gear   !! gear
      real(wp) :: t                      !! kinetic energy relative to the body [J]
    end function gear_relative_kinetic_energy

    !> Stroke and stroke rate of each strut (Table 3 sense).
    module pure subroutine strokes(gear, qv, qdv, s, sd)
      class(tripod_gear_t), intent(in) :: gear   !! gear
      real(wp), intent(in) :: qv(n_q)    !! coordinates [m, rad]
      real(wp), intent(in) :: qdv(n_q)   !! velocities [m/s, rad/s]
      real(wp), intent(out) :: s(3)      !! strokes [m]
      real(wp), intent(out) :: sd(3)     !! stroke rates [m/s]
    end subroutine strokes

    !> The piece of each strut's buffer law at the current strokes (buffer_law_t%segment): changes
    !! exactly at a stage end or where an end-of-stroke stop begins.
    module pure subroutine gear_law_segments(gear, v)
      class(tripod_gear_t), intent(in) :: gear   !! gear
      integer, intent(out) :: v(:)       !! segment of primary, left, right [-]
    end subroutine gear_law_segments

    !> First moment of mass of the leg parts, sum m x, gear frame.
    module pure function leg_first_moment(sk, q) result(fm)
      type(strut_kin_t), intent(in) :: sk(3)   !! strut kinematics at q
      real(wp), intent(in) :: q(n_q)           !! coordinates [m, rad]
      real(wp) :: fm(3)                        !! [kg m]
    end function leg_first_moment

    !> Stroke and stroke rate of each strut at the gear's current state (Table 3 sense).
    module pure subroutine gear_strokes(gear, s, sd)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp), intent(out) :: s(:)           !! strokes (n_struts) [m]
      real(wp), intent(out) :: sd(:)          !! stroke rates (n_struts) [m/s]
    end subroutine gear_strokes


    !> Generalized velocities (the stored ones: half a step behind the coordinates in the leapfrog).
    module pure function gear_rates(gear) result(qd)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp) :: qd(n_q)                     !! [m/s, rad/s]
    end function gear_rates

    !> Replaces the generalized velocities (the system velocity projection; leading the stored
    !! velocities for an output sample, undone afterwards). A rigid gear must stay at rest.
    module pure subroutine gear_set_rates(gear, v)
      class(tripod_gear_t), intent(inout) :: gear     !! gear
      real(wp), intent(in) :: v(:)            !! generalized velocities (n_q) [m/s, rad/s]
    end subroutine gear_set_rates

    !> Which struts are locked (committed state).
    module pure function gear_locks(gear) result(locked)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      logical :: locked(n_struts)             !! [-]
    end function gear_locks

    !> Crush mode of each strut of the committed state (strut_modes).
    module pure function gear_strut_modes(gear) result(m)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      integer :: m(n_struts)                  !! [-]
    end function gear_strut_modes

    !> Crush mode of each strut (landyn_gear_base's strut_mode).
    module pure function strut_modes(locked, axial, dir) result(m)
      logical, intent(in) :: locked(n_struts)   !! struts locked [-]
      real(wp), intent(in) :: axial(n_struts)   !! axial buffer forces [N]
      integer, intent(in) :: dir(n_struts)      !! sliding directions [-]
      integer :: m(n_struts)                    !! modes [-]
    end function strut_modes

    !> The gear is rigid: all struts locked and at rest relative to the body.
    module pure logical function gear_is_rigid(gear) result(rigid)
      class(tripod_gear_t), intent(in) :: gear        !! gear
    end function gear_is_rigid

    !> Caches Phi_q at the current coordinates for the next evaluation (it was computed for the
    !! velocity projection at the same configuration; gear_correct_positions also caches it there).
    module pure subroutine gear_cache_jacobian(gear, phq)
      class(tripod_gear_t), intent(inout) :: gear     !! gear
      real(wp), intent(in) :: phq(:, :)       !! Phi_q at gear%st%q, n_phi x n_q [-, m]
    end subroutine gear_cache_jacobian


    !> Most negative and most positive stroke reached by each strut.
    module pure subroutine gear_crush_history(gear, s_min, s_max)
      class(tripod_gear_t), intent(in) :: gear          !! gear
      real(wp), intent(out) :: s_min(:)         !! most negative strokes (n_struts) [m]
      real(wp), intent(out) :: s_max(:)         !! most positive strokes (n_struts) [m]
    end subroutine gear_crush_history

    !> Energy absorbed by each buffer so far.
    module pure function gear_crush_work(gear) result(w)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp) :: w(n_struts)                 !! [J]
    end function gear_crush_work

    !> Largest constraint violation after and before the correction so far.
    module pure subroutine gear_violations(gear, violation, drift)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp), intent(out) :: violation      !! after correction [m]
      real(wp), intent(out) :: drift          !! before correction [m]
    end subroutine gear_violations

    !> Stroke capacity of strut k's buffer in each direction (buffer_law_t%capacity).
    module subroutine gear_buffer_capacity(gear, k, cap_pos, cap_neg)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      integer, intent(in) :: k                !! strut [-]
      real(wp), intent(out) :: cap_pos        !! toward +s [m]
      real(wp), intent(out) :: cap_neg        !! toward -s (0: none) [m]
    end subroutine gear_buffer_capacity

    !> Strut k's crush levels as axial forces, compression + (buffer_law_t%crush_levels, its
    !! bound toward +s or -s turned into the axial sense by the stroke convention sigma).
    module subroutine tripod_crush_levels(gear, k, force, name, n)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      integer, intent(in) :: k                !! strut [-]
      real(wp), intent(out) :: force(:)       !! axial force of each level, compression + [N]
      character(len=*), intent(out) :: name(:) !! what each level is [-]
      integer, intent(out) :: n               !! number of levels [-]
    end subroutine tripod_crush_levels

    !> Sets strut k's buffer law (before gear_init).
    module subroutine gear_set_buffer(gear, k, law)
      class(tripod_gear_t), intent(inout) :: gear     !! gear
      integer, intent(in) :: k                !! strut [-]
      class(buffer_law_t), intent(in) :: law  !! buffer law
    end subroutine gear_set_buffer


    !> Axial buffer forces of the committed state (compression positive for the primary, the
    !! Table-3 sense of each strut).
    module pure function gear_axial_forces(gear) result(axial)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp) :: axial(n_struts)             !! [N]
    end function gear_axial_forces

    !> The committed load on the body: force and moment about the lander origin, gear frame.
    module pure subroutine gear_body_load(gear, f_body, m_body)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp), intent(out) :: f_body(3)      !! [N]
      real(wp), intent(out) :: m_body(3)      !! [N m]
    end subroutine gear_body_load

    !> Generalized coordinates of the gear's current state.
    pure module function gear_coordinates(gear) result(q)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp) :: q(n_q)                      !! [m, rad]
    end function gear_coordinates

    !> Generalized accelerations of the committed state.
    pure module function gear_accelerations(gear) result(qdd)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp) :: qdd(n_q)                    !! [m/s^2, rad/s^2]
    end function gear_accelerations

    !> Replaces the generalized coordinates and, when given, the velocities (a state set up by hand,
    !! as the unit tests do; nothing else changes: a rigid gear must be released with gear_set_rigid).
    pure module subroutine gear_set_coordinates(gear, q, qd)
      class(tripod_gear_t), intent(inout) :: gear     !! gear
      real(wp), intent(in) :: q(n_q)          !! coordinates [m, rad]
      real(wp), intent(in), optional :: qd(n_q)  !! velocities [m/s, rad/s]
    end subroutine gear_set_coordinates

    !> Sets which struts are locked and, when given, the strokes the locked ones hold.
    pure module subroutine gear_set_locks(gear, locked, s_lock)
      class(tripod_gear_t), intent(inout) :: gear     !! gear
      logical, intent(in) :: locked(n_struts) !! struts locked [-]
      real(wp), intent(in), optional :: s_lock(n_struts)  !! strokes held by locked struts [m]
    end subroutine gear_set_locks

    !> Sliding direction of each strut of the committed state (+1 toward +s, -1 toward -s, 0 never slid).
    pure module function gear_slide_directions(gear) result(dir)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      integer :: dir(n_struts)                !! [-]
    end function gear_slide_directions

    !> Sets the most negative and most positive stroke reached by each strut (gear_crush_history).
    pure module subroutine gear_set_crush_history(gear, s_min, s_max)
      class(tripod_gear_t), intent(inout) :: gear       !! gear
      real(wp), intent(in) :: s_min(n_struts)   !! [m]
      real(wp), intent(in) :: s_max(n_struts)   !! [m]
    end subroutine gear_set_crush_history

    !> Sets the committed axial buffer forces (gear_axial_forces), e.g. the secondaries' forces
    !! of a previous step, from which the tube friction of the next one follows.
    pure module subroutine gear_set_axial_forces(gear, axial)
      class(tripod_gear_t), intent(inout) :: gear       !! gear
      real(wp), intent(in) :: axial(n_struts)   !! [N]
    end subroutine gear_set_axial_forces

    !> Puts the gear into or out of the rigid state (gear_is_rigid); its rigid caches are dropped
    !! (recomputed by gear_prepare). A rigid gear must have all struts locked and qd = 0.
    pure module subroutine gear_set_rigid(gear, rigid)
      class(tripod_gear_t), intent(inout) :: gear       !! gear
      logical, intent(in) :: rigid              !! rigid [-]
    end subroutine gear_set_rigid

    !> The primary's tube-friction bound of the committed step (0 when tube friction is off).
    pure module function gear_tube_bound(gear) result(bound)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp) :: bound                       !! [N]
    end function gear_tube_bound

    !> The gear's geometry: hard points and nominal strut frames in the gear frame.
    pure module function gear_geometry(gear) result(geom)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      type(gear_geometry_t) :: geom           !! geometry [m, -]
    end function gear_geometry

    !> Strut k's mass model (landyn_strut).
    pure module function gear_strut(gear, k) result(strut)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      integer, intent(in) :: k                !! strut: 1 primary, 2 left, 3 right [-]
      type(strut_t) :: strut                  !! its mass model [kg, m, kg m^2]
    end function gear_strut

    !> Nominal strut lengths (zero stroke).
    pure module function gear_nominal_lengths(gear) result(len0)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp) :: len0(n_struts)              !! [m]
    end function gear_nominal_lengths

    ! ---- generalized forces, momentum and inertia terms (landyn_tripod_inertia)

    !> Generalized forces: velocity coupling (Q_ine), the uniform field (Q_grv) and the footpad force.
    module pure subroutine gear_generalized_forces(gear, q, qd, f_field, f_foot, q_ine, q_grv, q_ext)
      class(tripod_gear_t), intent(in) :: gear     !! gear
      real(wp), intent(in) :: q(n_q)       !! coordinates [m, rad]
      real(wp), intent(in) :: qd(n_q)      !! velocities [m/s, rad/s]
      real(wp), intent(in) :: f_field(3)   !! uniform acceleration field (gravity - frame acceleration), gear frame [m/s^2]
      real(wp), intent(in) :: f_foot(3)    !! force on the footpad, gear frame [N]
      real(wp), intent(out) :: q_ine(n_q)  !! velocity-coupling generalized force [N, N m]
      real(wp), intent(out) :: q_grv(n_q)  !! field generalized force [N, N m]
      real(wp), intent(out) :: q_ext(n_q)  !! footpad-force generalized force [N, N m]
    end subroutine gear_generalized_forces

    !> generalized_forces with the strut kinematics and mass functions at q given (and the joint
    !! trigonometry, when at hand).
    module pure subroutine generalized_forces(q, qd, sk, f_field, f_foot, q_ine, q_grv, q_ext, trig)
      real(wp), intent(in) :: q(n_q)         !! coordinates [m, rad]
      real(wp), intent(in) :: qd(n_q)        !! velocities [m/s, rad/s]
      type(strut_kin_t), intent(in) :: sk(3) !! strut kinematics at q
      real(wp), intent(in) :: f_field(3)     !! uniform field, gear frame [m/s^2]
      real(wp), intent(in) :: f_foot(3)      !! footpad force, gear frame [N]
      real(wp), intent(out) :: q_ine(n_q)    !! velocity coupling [N, N m]
      real(wp), intent(out) :: q_grv(n_q)    !! field [N, N m]
      real(wp), intent(out) :: q_ext(n_q)    !! footpad force [N, N m]
      type(joint_trig_t), intent(in), optional :: trig(n_struts)  !! gear_trig(q), when at hand [-]
    end subroutine generalized_forces

    !> a and b are the same coordinates, bit for bit (so that a cache keyed on them gives exactly
    !! what computing afresh would).
    module pure logical function same_coordinates(a, b) result(same)
      real(wp), intent(in) :: a(n_q)          !! coordinates [m, rad]
      real(wp), intent(in) :: b(n_q)          !! coordinates [m, rad]
    end function same_coordinates

    !> Generalized force -H_a^T alpha of the non-uniform part of the frame's angular-acceleration
    !! field, -alpha x (r - a) on every leg part (r - a measured from the upper primary joint a):
    !! per strut, with P its upper joint, the columns of H_a are those of the relative angular
    !! momentum about a, (P - a) x p_j + J u x u_j (see gear_momentum_maps).
    module pure function alpha_forces(gear, q, sk, alpha) result(qa)
      class(tripod_gear_t), intent(in) :: gear       !! gear
      real(wp), intent(in) :: q(n_q)         !! coordinates [m, rad]
      type(strut_kin_t), intent(in) :: sk(3) !! strut kinematics at q
      real(wp), intent(in) :: alpha(3)       !! angular acceleration, gear axes [rad/s^2]
      real(wp) :: qa(n_q)                    !! generalized force [N, N m]
    end function alpha_forces


    !> The legs' relative momentum and angular-momentum rates for given strut kinematics and
    !! accelerations, in total and per strut (the gear DAE, the joint loads). Per strut, with
    !! S = sum m r, S1 = sum over the sliding parts of m r and J(L) as in the mass matrix:
    !!   f = m_s Ldd u + 2 m_s Ld udot + S uddot,
    !!   H_dot about the upper joint P = u x (2 S1 Ld udot + J uddot), m = P x f + H_dot.
    module pure subroutine relative_inertia(gear, sk, qdd, f_rel, m_rel, f_strut, h_strut)
      class(tripod_gear_t), intent(in) :: gear       !! gear (q, qd)
      type(strut_kin_t), intent(in) :: sk(3) !! strut kinematics at gear%st%q
      real(wp), intent(in) :: qdd(n_q)       !! generalized accelerations [m/s^2, rad/s^2]
      real(wp), intent(out) :: f_rel(3)      !! relative momentum rate, gear frame [N]
      real(wp), intent(out) :: m_rel(3)      !! relative angular momentum rate about O_L [N m]
      real(wp), intent(out), optional :: f_strut(3, 3)  !! each strut's share of f_rel [N]
      real(wp), intent(out), optional :: h_strut(3, 3)  !! rate of each strut's relative angular momentum
                                                        !! about its upper joint [N m]
    end subroutine relative_inertia

    !> Relative linear momentum, relative angular momentum about the lander origin and relative
    !! kinetic energy of the leg parts: per strut p = m_s Ld u + S udot and
    !! h = P x p + J(L) u x udot (spin about the axis neglected, as in the mass matrix).
    module pure subroutine gear_relative_momenta(gear, p_rel, h_rel, t_rel)
      class(tripod_gear_t), intent(in) :: gear      !! gear
      real(wp), intent(out) :: p_rel(3)     !! sum m v_rel, gear frame [kg m/s]
      real(wp), intent(out) :: h_rel(3)     !! relative angular momentum about O_L, gear axes [kg m^2/s]
      real(wp), intent(out) :: t_rel        !! relative kinetic energy 1/2 qd^T M qd [J]
    end subroutine gear_relative_momenta

    !> Relative linear momentum and first moment of mass of the leg parts (for the energy audit).
    module pure subroutine gear_leg_momentum(gear, p_rel, first_moment, leg_mass)
      class(tripod_gear_t), intent(in) :: gear         !! gear
      real(wp), intent(out) :: p_rel(3)        !! sum m v_rel, gear frame [kg m/s]
      real(wp), intent(out) :: first_moment(3) !! sum m x, gear frame [kg m]
      real(wp), intent(out) :: leg_mass        !! sum m [kg]
    end subroutine gear_leg_momentum

    !> Linear maps from the generalized velocities to the legs' relative linear momentum and their
    !! relative angular momentum about the lander origin, both in gear axes:
    !! p_rel = pm qd, h_rel = hm qd (the same quantities as gear_relative_momenta).
    module pure subroutine gear_momentum_maps(gear, pm, hm)
      class(tripod_gear_t), intent(in) :: gear       !! gear
      real(wp), intent(out) :: pm(3, n_q)    !! d p_rel / d qd [kg, kg m]
      real(wp), intent(out) :: hm(3, n_q)    !! d h_rel / d qd [kg m, kg m^2]
    end subroutine gear_momentum_maps

    ! ---- crush logic and the DAE at one instant (landyn_tripod_dynamics)

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
    module subroutine gear_evaluate(gear, ge, f_foot, f_field, status, dt, alpha, loads)
      class(tripod_gear_t), intent(in) :: gear             !! gear with its committed state (unchanged)
      type(gear_eval_t), intent(inout) :: ge       !! accelerations, buffer forces, lock decisions, body load
                                                   !! (previous contents replaced)
      real(wp), intent(in) :: f_foot(3)            !! ground force on the footpad, gear frame [N]
      real(wp), intent(in) :: f_field(3)           !! uniform field g - a_frame, gear frame [m/s^2]
      type(status_t), intent(inout) :: status      !! STAT_OK on entry; the failure's code and diagnosis [-]
      real(wp), intent(in), optional :: dt         !! coming time step: velocity-level locking [s]
      real(wp), intent(in), optional :: alpha(3)   !! body angular acceleration, gear axes [rad/s^2]
      logical, intent(in), optional :: loads       !! compute the interface loads (f_joint, m_joint,
                                                   !! f_interface); default .true. [-]
    end subroutine gear_evaluate

    !> Evaluates the gear (gear_evaluate) and commits the result at once (gear_commit), preparing a
    !! rigid gear's caches first: the gear alone, as the unit tests drive it.
    module subroutine gear_dynamics(gear, f_foot, f_field, status, dt, alpha)
      class(tripod_gear_t), intent(inout) :: gear          !! gear; qdd, axial, locked, f_body are updated
      real(wp), intent(in) :: f_foot(3)            !! ground force on the footpad, gear frame [N]
      real(wp), intent(in) :: f_field(3)           !! uniform field g - a_frame, gear frame [m/s^2]
      type(status_t), intent(inout) :: status      !! STAT_OK on entry; the failure's code and diagnosis [-]
      real(wp), intent(in), optional :: dt         !! coming time step: velocity-level locking [s]
      real(wp), intent(in), optional :: alpha(3)   !! body angular acceleration, gear axes [rad/s^2]
    end subroutine gear_dynamics

    !> Makes an evaluation (gear_evaluate) the gear's state: accelerations, buffer forces, lock
    !! decisions, the load on the body; a gear that broke loose from the rigid state leaves it.
    module pure subroutine gear_commit(gear, ge)
      class(tripod_gear_t), intent(inout) :: gear          !! gear
      type(gear_eval_t), intent(in) :: ge          !! its evaluation
    end subroutine gear_commit

    !> Computes the caches of a gear that has become rigid (gear_settle), so that evaluating it needs
    !! only the cached factor. Nothing is done for a gear that is not rigid or already prepared.
    module subroutine gear_prepare(gear, status)
      class(tripod_gear_t), intent(inout) :: gear          !! gear
      type(status_t), intent(inout) :: status      !! STAT_OK on entry; the failure's code and diagnosis [-]
    end subroutine gear_prepare

    ! ---- interface loads of the joints (landyn_tripod_joint_loads)

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
    module pure subroutine joint_loads(gear, sk, q, qd, qdd, f_strut, h_strut, lam_phi, f_foot, f_field, alpha, f_body, &
                                f_joint, m_joint, f_interface)
      class(tripod_gear_t), intent(in) :: gear             !! gear (geometry, masses)
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
    end subroutine joint_loads

    ! ---- what a time integrator needs of the gear besides its evaluation (landyn_tripod_constraints):
    ! the discrete decision at the end of a step, a position increment, the position projection.
    ! The update formula itself is the integrator's (numerics/).

    !> The rigid-plastic crush law's decision over a step: a crushing strut whose stroke rate would
    !! reverse between the committed rates and the end-of-step rates `qd_end` (the integrator's
    !! candidate) while its buffer resists in its direction of motion locks at its present stroke.
    !! Leaves the rigid state (a gear that moves is not rigid).
    module pure subroutine gear_arrest(gear, qd_end)
      class(tripod_gear_t), intent(inout) :: gear          !! gear (committed state of the step's start)
      real(wp), intent(in) :: qd_end(:)            !! end-of-step generalized velocities (n_q) [m/s, rad/s]
    end subroutine gear_arrest

    !> Moves the coordinates by qd h (q <- q + qd h) and books the crush work of the committed
    !! buffer forces over the stroke increment of every strut that is not locked.
    module pure subroutine gear_increment(gear, qd, h)
      class(tripod_gear_t), intent(inout) :: gear          !! gear
      real(wp), intent(in) :: qd(:)                !! velocity the coordinates move with (n_q) [m/s, rad/s]
      real(wp), intent(in) :: h                    !! duration of the move [s]
    end subroutine gear_increment

    !> Step 4's position half: the direct correction dq = -A^+ Phi (A^+ = A^T (A A^T)^-1) of the
    !! holonomic constraints and the locked strokes, iterated to `tol`; then the crush history.
    !! The velocity half is a plastic impact of the whole system (landyn_impact), or, for a gear
    !! alone with the body held fixed, gear_project_alone.
    module subroutine gear_correct_positions(gear, tol, max_iter, max_drift, status)
      class(tripod_gear_t), intent(inout) :: gear          !! gear
      real(wp), intent(in) :: tol                  !! correction tolerance [m]
      integer, intent(in) :: max_iter              !! iteration cap of the position correction [-]
      real(wp), intent(in) :: max_drift            !! violation before correction that means the step is too large [m]
      type(status_t), intent(inout) :: status      !! STAT_OK on entry; STAT_DIVERGED on drift or no convergence [-]
    end subroutine gear_correct_positions

    !> The velocity projection of a gear alone, the body held fixed: qd <- qd - M^-1 A^T (A M^-1 A^T)^-1 A qd
    !! in the gear's kinetic metric, then gear_settle (the unit tests of a free gear).
    module subroutine gear_project_alone(gear, status)
      class(tripod_gear_t), intent(inout) :: gear          !! gear
      type(status_t), intent(inout) :: status      !! STAT_OK on entry; the failure's code and diagnosis [-]
    end subroutine gear_project_alone

    !> After the velocity projection: a gear whose three struts are all locked has A (Phi_q and the
    !! three lock rows) square and regular, so A qd = 0 means qd = 0; it becomes rigid.
    module pure subroutine gear_settle(gear)
      class(tripod_gear_t), intent(inout) :: gear    !! gear after the velocity projection
    end subroutine gear_settle

    !> Velocity constraint rows of the gear at its current configuration: Phi_q and one row per
    !! locked strut (its stroke rate held at zero). A qd = 0 is the velocity constraint.
    module pure subroutine gear_velocity_rows(gear, a, nrow)
      class(tripod_gear_t), intent(in) :: gear           !! gear
      real(wp), intent(out) :: a(max_rows, n_q)  !! rows [m/rad, -]
      integer, intent(out) :: nrow               !! number of rows [-]
    end subroutine gear_velocity_rows

    ! ---- the gear_base_t bindings that are not procedures above (landyn_tripod_setup, velocity_rows
    ! in landyn_tripod_constraints)

    !> Sets up a tripod at its nominal configuration, all struts locked and at rest (its buffer laws,
    !! then gear_init).
    module subroutine tripod_init(self, geom, rot, mass, primary, secondary, status, tube)
      type(tripod_gear_t), intent(inout) :: self      !! gear
      type(gear_geometry_t), intent(in) :: geom       !! geometry in the gear frame
      real(wp), intent(in) :: rot(3, 3)               !! gear frame -> lander frame [-]
      type(strut_mass_t), intent(in) :: mass(n_struts)  !! strut mass properties (primary, left, right)
      class(buffer_law_t), intent(in) :: primary      !! the primary's buffer law
      class(buffer_law_t), intent(in) :: secondary    !! both secondaries' buffer law
      type(status_t), intent(out) :: status           !! STAT_OK, or STAT_FAILED with the diagnosis [-]
      type(tube_friction_t), intent(in), optional :: tube  !! primary tube friction; absent: off
    end subroutine tripod_init

    !> Primary, secondary left, secondary right (strut_names).
    module pure function tripod_strut_name(gear, k) result(name)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      integer, intent(in) :: k                        !! strut [-]
      character(len=strut_name_len) :: name           !! [-]
    end function tripod_strut_name

    !> Which struts are locked (committed state).
    module pure subroutine tripod_locks(gear, locked)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      logical, intent(out) :: locked(:)               !! per strut [-]
    end subroutine tripod_locks

    !> Generalized velocities (gear_rates).
    module pure subroutine tripod_rates(gear, v)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp), intent(out) :: v(:)                   !! [m/s, rad/s]
    end subroutine tripod_rates

    !> Committed generalized accelerations (gear_accelerations).
    module pure subroutine tripod_accelerations(gear, v)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp), intent(out) :: v(:)                   !! [m/s^2, rad/s^2]
    end subroutine tripod_accelerations

    !> Diagonal of the mass matrix at the current coordinates.
    module pure subroutine tripod_mass_diagonal(gear, v)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp), intent(out) :: v(:)                   !! [kg, kg m^2]
    end subroutine tripod_mass_diagonal

    !> Strut lengths.
    module pure subroutine tripod_strut_lengths(gear, v)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp), intent(out) :: v(:)                   !! [m]
    end subroutine tripod_strut_lengths

    !> Axial buffer forces of the committed state (gear_axial_forces).
    module pure subroutine tripod_axial_forces(gear, v)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp), intent(out) :: v(:)                   !! [N]
    end subroutine tripod_axial_forces

    !> Energy absorbed by each buffer (gear_crush_work).
    module pure subroutine tripod_crush_work(gear, v)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp), intent(out) :: v(:)                   !! [J]
    end subroutine tripod_crush_work

    !> Crush modes: of an evaluation (the mode each strut leaves the step in), of the committed state from its
    !! sliding directions (gear_strut_modes).
    module pure subroutine tripod_strut_modes(gear, m, ge)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      integer, intent(out) :: m(:)                    !! per strut [-]
      type(gear_eval_t), intent(in), optional :: ge   !! the evaluation; default the committed state
    end subroutine tripod_strut_modes

    !> Error weights of the coordinates: 1 for a strut length, the strut's length for its angles.
    module pure subroutine tripod_coordinate_weights(gear, v)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      real(wp), intent(out) :: v(:)                   !! [-, m]
    end subroutine tripod_coordinate_weights

    !> gear_velocity_rows; Phi_q (the first n_phi rows) is cached for the next evaluation.
    module pure subroutine tripod_velocity_rows(gear, a, nrow)
      class(tripod_gear_t), intent(inout) :: gear     !! gear
      real(wp), intent(out) :: a(max_gear_rows, max_gear_q)  !! rows [m/rad, -]
      integer, intent(out) :: nrow                    !! [-]
    end subroutine tripod_velocity_rows

    !> A tripod_snapshot_t.
    module subroutine tripod_new_snapshot(gear, snap)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      class(gear_snapshot_t), allocatable, intent(inout) :: snap  !! the record
    end subroutine tripod_new_snapshot

    !> Copies the evolving state into a tripod_snapshot_t (another record is left unchanged).
    module pure subroutine tripod_save_state(gear, snap)
      class(tripod_gear_t), intent(in) :: gear        !! gear
      class(gear_snapshot_t), intent(inout) :: snap   !! record from new_snapshot
    end subroutine tripod_save_state

    !> Puts the evolving state back from a tripod_snapshot_t (another record is ignored).
    module pure subroutine tripod_restore_state(gear, snap)
      class(tripod_gear_t), intent(inout) :: gear     !! gear
      class(gear_snapshot_t), intent(in) :: snap      !! saved state
    end subroutine tripod_restore_state
  end interface


end module landyn_tripod_gear
