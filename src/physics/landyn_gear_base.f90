!> The interface every landing-gear type offers: a gear is a set of struts between the body and
!! one footpad, with its own generalized coordinates, and what the rest of the code needs from it
!! is listed here as deferred bindings. The simulation (landyn_sim_model, landyn_sim_core,
!! landyn_impact) holds its gears as gear_slot_t and calls them only through these bindings, so a
!! gear type with another strut set is an extension of gear_base_t, not an edit: the tripod of the
!! paper (landyn_gear, landyn_tripod_gear) is one extension, test_gear_types and test_gear_landing
!! define a single telescopic strut with a footpad and land it.
!!
!! Sign conventions shared by all gear types: gear frame fixed to the body; forces in newtons in
!! the gear frame; strokes in each strut's Table-3 sense; axial forces compression positive.
!! Per-strut arrays have strut_count() entries, per-coordinate arrays coordinate_count(), at most
!! max_struts and max_gear_q (landyn_kinds), the capacities the simulation's records are sized by.
module landyn_gear_base
  use landyn_kinds, only: wp, max_struts, max_gear_q, max_gear_rows
  use landyn_status, only: STAT_OK, STAT_FAILED, status_t
  implicit none
  private

  public :: gear_base_t, gear_eval_t, gear_snapshot_t, gear_slot_t, gear_snapshot_slot_t, strut_name_len, strut_mode, &
            strut_mode_after

  integer, parameter :: strut_name_len = 15     !! length of a strut's name [-]

  !> What one evaluation of a gear decides and computes (evaluate) from its committed state,
  !! without changing it; commit makes it the gear's state. The same record for every gear type:
  !! entries beyond the gear's strut and coordinate counts are unused.
  type :: gear_eval_t
    real(wp) :: qdd(max_gear_q) = 0.0_wp          !! generalized accelerations [m/s^2, rad/s^2]
    real(wp) :: axial(max_struts) = 0.0_wp        !! axial buffer force [N]
    real(wp) :: f_body(3) = 0.0_wp                !! force on the body, gear frame [N]
    real(wp) :: m_body(3) = 0.0_wp                !! moment on the body about O_L, gear axes [N m]
    logical :: locked(max_struts) = .true.        !! strut locked [-]
    integer :: dir(max_struts) = 0                !! sliding direction [-]
    real(wp) :: s_lock(max_struts) = 0.0_wp       !! stroke held by a locked strut [m]
    real(wp) :: tube_bound = 0.0_wp               !! tube-friction bound of this step [N]
    logical :: rigid = .false.                    !! the gear stays rigid [-]
    ! interface loads, gear frame: column k (k <= strut count) is the force the upper joint of
    ! strut k puts on the body, column max_struts + 1 the force the footpad puts on its strut
    real(wp) :: f_joint(3, max_struts + 1) = 0.0_wp  !! joint forces [N]
    real(wp) :: m_joint(3, max_struts) = 0.0_wp   !! moments of the upper joints on the body (about the
                                                  !! strut's Hooke-joint axis: its spin is constrained) [N m]
    real(wp) :: f_interface(3) = 0.0_wp           !! the gear's total force on the body from the
                                                  !! leg's momentum balance (= sum of the upper joints') [N]
    ! Switching functions of the strut modes (strut_mode), for event location: each is >= 0 while
    ! its mode holds and changes sign where the crush logic leaves it. margin_out is the function
    ! of the mode the evaluation decided, margin_in that of the mode it started from (the committed
    ! one), both at the evaluated state. 0 where a gear type does not provide them (the integrator
    ! then halves the step). Units by mode: locked, the force left before the lock gives way [N];
    ! crushing, the stroke rate in its direction after the step's velocity update [m/s]; free, the
    ! stroke left to the nearer end of the free range [m].
    ! A strut stopped within the step by its lock row (velocity level) is locked for the step
    ! (locked, axial, s_lock above: the stopping force); the mode it leaves the step in is decided
    ! by the force that holds it once stopped (docs/theory.md, "Mode switches"): dir_after = 0 when
    ! it stays locked (and for every strut not stopped in the step), +1 / -1 when it leaves sliding
    ! toward +s / -s with the bound of that side as its axial force, axial_after.
    integer :: dir_after(max_struts) = 0          !! direction a stopped strut leaves the step in, 0: none [-]
    real(wp) :: axial_after(max_struts) = 0.0_wp  !! its axial buffer force after the step [N]
    real(wp) :: margin_in(max_struts) = 0.0_wp    !! switching function of the entry mode [N, m/s, m]
    real(wp) :: margin_out(max_struts) = 0.0_wp   !! switching function of the decided mode [N, m/s, m]
    real(wp) :: stroke(max_struts) = 0.0_wp       !! strokes of the evaluated state (event location) [m]
    real(wp) :: free_lo(max_struts) = 0.0_wp      !! lower end of each buffer's free range (buffer_law_t%free_range) [m]
    real(wp) :: free_hi(max_struts) = 0.0_wp      !! upper end [m]
  end type gear_eval_t

  !> A landing gear: struts, footpad and their state. Its layout (strut and coordinate counts,
  !! rotation) is set once by the gear type's set-up (set_layout) and read through non-overridable
  !! bindings; the rest in two parts:
  !!
  !! - the dynamics (deferred): what the simulation calls per step (landyn_sim_core, landyn_sim_state,
  !!   landyn_impact, the integrators) and to set up and save its model (landyn_sim_model);
  !! - the reports (defaults a simple gear inherits; a gear type overrides what it knows better):
  !!   what the recorder, the summary and the health checks read (landyn_sim_result), the error
  !!   weights and law segments the adaptive integrator compares, and the rigid gear's caches.
  !!   strut_lengths and violations have no sensible default and stay deferred.
  type, abstract :: gear_base_t
    private
    integer :: layout_struts = 0                  !! number of struts (set_layout) [-]
    integer :: layout_coordinates = 0             !! number of generalized coordinates (set_layout) [-]
    real(wp) :: layout_rot(3, 3) = reshape([1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0_wp], &
                                           [3, 3])  !! gear frame -> lander frame (set_layout) [-]
  contains
    ! ---- the layout, set once by the gear type's set-up
    ! (not non_overridable: gfortran 12 with -flto miscompiled its direct call from the tripod's
    ! set-up, a segfault in test_impact's Release build; an extension cannot reach the components)
    procedure :: set_layout                                            !! sets the counts and the rotation
    procedure, non_overridable :: strut_count                          !! number of struts [-]
    procedure, non_overridable :: coordinate_count                     !! number of generalized coordinates [-]
    procedure, non_overridable :: rotation                             !! gear frame -> lander frame rotation [-]
    ! ---- the dynamics
    procedure(footpad_iface), deferred :: footpad                      !! footpad position and velocity, gear frame [m, m/s]
    procedure(evaluate_iface), deferred :: evaluate                    !! crush logic and accelerations into a gear_eval_t
    procedure(commit_iface), deferred :: commit                        !! makes an evaluation the committed state
    procedure(arrest_iface), deferred :: arrest                        !! crush modes at the end of a step
    procedure(increment_iface), deferred :: increment                  !! q <- q + qd h, with the crush work
    procedure(correct_iface), deferred :: correct_positions            !! position projection onto the constraints
    procedure(settle_iface), deferred :: settle                        !! all struts locked: the gear becomes rigid
    procedure(rigid_iface), deferred :: is_rigid                       !! all struts locked and at rest
    procedure(locks_iface), deferred :: locks                          !! which struts are locked [-]
    procedure(per_strut_pair_iface), deferred :: strokes               !! strokes and stroke rates [m, m/s]
    procedure(vector_iface), deferred :: rates                         !! generalized velocities [m/s, rad/s]
    procedure(set_vector_iface), deferred :: set_rates                 !! replaces the generalized velocities
    procedure(vector_iface), deferred :: accelerations                 !! committed generalized accelerations [m/s^2, rad/s^2]
    procedure(rows_iface), deferred :: velocity_rows                   !! velocity constraint rows (A qd = 0)
    procedure(vector_iface), deferred :: mass_diagonal                 !! mass matrix diagonal [kg, kg m^2]
    procedure(maps_iface), deferred :: momentum_maps                   !! maps from qd to the legs' momenta
    procedure(momenta_iface), deferred :: relative_momenta             !! legs' relative momenta and kinetic energy
    procedure(leg_momentum_iface), deferred :: leg_momentum            !! legs' momentum, first moment and mass
    procedure(new_snapshot_iface), deferred :: new_snapshot            !! allocates a snapshot of the gear's type
    procedure(save_iface), deferred :: save_state                      !! copies the evolving state out
    procedure(restore_iface), deferred :: restore_state                !! puts a saved state back
    ! ---- the reports (strut_lengths and violations deferred, the others with defaults)
    procedure(vector_iface), deferred :: strut_lengths                 !! strut lengths [m]
    procedure(violations_iface), deferred :: violations                !! largest constraint violations [m]
    procedure :: strut_name                                            !! name of strut k (reports)
    procedure :: strut_modes                                           !! crush mode of each strut [-]
    procedure :: axial_forces => not_reported                          !! axial buffer forces [N]
    procedure :: crush_history                                         !! most negative and positive strokes reached [m]
    procedure :: crush_work => not_reported                            !! energy absorbed by each buffer [J]
    procedure :: buffer_capacity                                       !! stroke capacity of strut k's buffer [m]
    procedure :: crush_levels                                          !! constant crush forces of strut k's buffer [N]
    procedure :: law_segments                                          !! piece of each buffer law [-]
    procedure :: coordinate_weights                                    !! error-norm weights of the coordinates [-]
    procedure :: prepare                                               !! caches for the next evaluation of a rigid gear
    procedure :: footpad_response                                      !! response to a footpad force [m/s^2/N, ...]
  end type gear_base_t

  !> The evolving state of a gear (save_state, restore_state): each gear type extends it.
  type, abstract :: gear_snapshot_t
  end type gear_snapshot_t

  !> Holder of one gear of any type (the simulation's gears).
  type :: gear_slot_t
    class(gear_base_t), allocatable :: g          !! the gear
  end type gear_slot_t

  !> Holder of one gear's snapshot (allocated once by the gear's new_snapshot).
  type :: gear_snapshot_slot_t
    class(gear_snapshot_t), allocatable :: s      !! the snapshot
  end type gear_snapshot_slot_t

  abstract interface
    !> Footpad joint position and its velocity relative to the body, gear frame.
    pure subroutine footpad_iface(gear, pos, vel, rates)
      import :: gear_base_t, wp
      class(gear_base_t), intent(in) :: gear      !! gear
      real(wp), intent(out) :: pos(3)             !! position [m]
      real(wp), intent(out) :: vel(3)             !! velocity [m/s]
      real(wp), intent(in), optional :: rates(:)  !! generalized velocities to take it with; default the
                                                  !! stored ones [m/s, rad/s]
    end subroutine footpad_iface

    !> Crush logic and accelerations of the committed state for a footpad force and the uniform
    !! field, into an evaluation record (every component set anew); the gear is not changed
    !! (commit makes it its state).
    subroutine evaluate_iface(gear, ge, f_foot, f_field, status, dt, alpha, loads)
      import :: gear_base_t, gear_eval_t, wp, status_t
      class(gear_base_t), intent(in) :: gear      !! gear (unchanged)
      ! inout, not out: the gear type resets the record itself (once, not once per layer)
      type(gear_eval_t), intent(inout) :: ge      !! the evaluation (previous contents replaced)
      real(wp), intent(in) :: f_foot(3)           !! ground force on the footpad, gear frame [N]
      real(wp), intent(in) :: f_field(3)          !! uniform field g - a_frame, gear frame [m/s^2]
      ! inout, not out: called per step; STAT_OK on entry, left alone on success
      type(status_t), intent(inout) :: status     !! STAT_OK on entry; the failure's code and diagnosis [-]
      real(wp), intent(in), optional :: dt        !! coming time step (velocity-level locking) [s]
      real(wp), intent(in), optional :: alpha(3)  !! body angular acceleration, gear axes [rad/s^2]
      logical, intent(in), optional :: loads      !! compute the interface loads; default .true. [-]
    end subroutine evaluate_iface

    !> Makes an evaluation the gear's committed state (accelerations, forces, lock decisions).
    pure subroutine commit_iface(gear, ge)
      import :: gear_base_t, gear_eval_t
      class(gear_base_t), intent(inout) :: gear   !! gear
      type(gear_eval_t), intent(in) :: ge         !! its evaluation
    end subroutine commit_iface

    !> The crush law's decision over a step: a crushing strut whose stroke rate would reverse between
    !! the committed rates and the integrator's end-of-step rates locks at its present stroke. A gear
    !! that moves leaves the rigid state.
    pure subroutine arrest_iface(gear, qd_end)
      import :: gear_base_t, wp
      class(gear_base_t), intent(inout) :: gear   !! gear
      real(wp), intent(in) :: qd_end(:)           !! end-of-step generalized velocities [m/s, rad/s]
    end subroutine arrest_iface

    !> Moves the coordinates by qd h and books the crush work of the committed buffer forces over
    !! the stroke increment of every strut that is not locked.
    pure subroutine increment_iface(gear, qd, h)
      import :: gear_base_t, wp
      class(gear_base_t), intent(inout) :: gear   !! gear
      real(wp), intent(in) :: qd(:)               !! velocity the coordinates move with [m/s, rad/s]
      real(wp), intent(in) :: h                   !! duration of the move [s]
    end subroutine increment_iface

    !> Projects the coordinates onto the position constraints (holonomic ones and locked strokes)
    !! and updates the crush history.
    subroutine correct_iface(gear, tol, max_iter, max_drift, status)
      import :: gear_base_t, wp, status_t
      class(gear_base_t), intent(inout) :: gear   !! gear
      real(wp), intent(in) :: tol                 !! correction tolerance [m]
      integer, intent(in) :: max_iter             !! iteration cap of the correction [-]
      real(wp), intent(in) :: max_drift           !! violation before correction that means the step is too large [m]
      type(status_t), intent(inout) :: status     !! STAT_OK on entry; the failure's code and diagnosis [-]
    end subroutine correct_iface

    !> After the system's velocity projection: a gear with all struts locked becomes rigid.
    pure subroutine settle_iface(gear)
      import :: gear_base_t
      class(gear_base_t), intent(inout) :: gear   !! gear
    end subroutine settle_iface

    !> Two per-strut quantities (strokes and their rates, or the crush history: most negative and
    !! most positive stroke reached).
    pure subroutine per_strut_pair_iface(gear, s, sd)
      import :: gear_base_t, wp
      class(gear_base_t), intent(in) :: gear      !! gear
      real(wp), intent(out) :: s(:)               !! strokes, or most negative strokes [m]
      real(wp), intent(out) :: sd(:)              !! stroke rates [m/s], or most positive strokes [m]
    end subroutine per_strut_pair_iface

    !> One per-strut or per-coordinate quantity of the committed state.
    pure subroutine vector_iface(gear, v)
      import :: gear_base_t, wp
      class(gear_base_t), intent(in) :: gear      !! gear
      real(wp), intent(out) :: v(:)               !! per strut or per coordinate [N, J, m, kg, m/s, rad/s or -]
    end subroutine vector_iface

    !> Replaces a per-coordinate quantity (the generalized velocities).
    pure subroutine set_vector_iface(gear, v)
      import :: gear_base_t, wp
      class(gear_base_t), intent(inout) :: gear   !! gear
      real(wp), intent(in) :: v(:)                !! per coordinate [m/s, rad/s]
    end subroutine set_vector_iface

    !> Which struts are locked (committed state).
    pure subroutine locks_iface(gear, locked)
      import :: gear_base_t
      class(gear_base_t), intent(in) :: gear      !! gear
      logical, intent(out) :: locked(:)           !! per strut [-]
    end subroutine locks_iface

    !> Largest constraint violation after and before the correction so far.
    pure subroutine violations_iface(gear, violation, drift)
      import :: gear_base_t, wp
      class(gear_base_t), intent(in) :: gear      !! gear
      real(wp), intent(out) :: violation          !! after correction [m]
      real(wp), intent(out) :: drift              !! before correction [m]
    end subroutine violations_iface

    !> The gear is rigid: all struts locked and at rest relative to the body (no part in the
    !! velocity projection).
    pure logical function rigid_iface(gear)
      import :: gear_base_t
      class(gear_base_t), intent(in) :: gear      !! gear
    end function rigid_iface

    !> Velocity constraint rows at the current configuration (A qd = 0; the columns beyond the
    !! coordinate count zero); the gear may keep what it computed for its next evaluation at the
    !! same configuration.
    pure subroutine rows_iface(gear, a, nrow)
      import :: gear_base_t, wp, max_gear_rows, max_gear_q
      class(gear_base_t), intent(inout) :: gear   !! gear
      real(wp), intent(out) :: a(max_gear_rows, max_gear_q)  !! rows (nrow x coordinate_count()) [m/rad, -]
      integer, intent(out) :: nrow                !! number of rows [-]
    end subroutine rows_iface

    !> Maps from the generalized velocities to the legs' relative linear momentum and their
    !! relative angular momentum about the lander origin, gear axes.
    pure subroutine maps_iface(gear, pm, hm)
      import :: gear_base_t, wp, max_gear_q
      class(gear_base_t), intent(in) :: gear      !! gear
      real(wp), intent(out) :: pm(3, max_gear_q)  !! d p_rel / d qd [kg, kg m]
      real(wp), intent(out) :: hm(3, max_gear_q)  !! d h_rel / d qd [kg m, kg m^2]
    end subroutine maps_iface

    !> The legs' relative momenta and relative kinetic energy, gear frame.
    pure subroutine momenta_iface(gear, p_rel, h_rel, t_rel)
      import :: gear_base_t, wp
      class(gear_base_t), intent(in) :: gear      !! gear
      real(wp), intent(out) :: p_rel(3)           !! sum m v_rel [kg m/s]
      real(wp), intent(out) :: h_rel(3)           !! relative angular momentum about O_L [kg m^2/s]
      real(wp), intent(out) :: t_rel              !! relative kinetic energy [J]
    end subroutine momenta_iface

    !> The legs' relative linear momentum, first moment of mass and mass, gear frame.
    pure subroutine leg_momentum_iface(gear, p_rel, first_moment, leg_mass)
      import :: gear_base_t, wp
      class(gear_base_t), intent(in) :: gear      !! gear
      real(wp), intent(out) :: p_rel(3)           !! sum m v_rel [kg m/s]
      real(wp), intent(out) :: first_moment(3)    !! sum m x [kg m]
      real(wp), intent(out) :: leg_mass           !! sum m [kg]
    end subroutine leg_momentum_iface

    !> Allocates a snapshot record of the gear's type (once, before the time loop).
    subroutine new_snapshot_iface(gear, snap)
      import :: gear_base_t, gear_snapshot_t
      class(gear_base_t), intent(in) :: gear      !! gear
      class(gear_snapshot_t), allocatable, intent(inout) :: snap  !! the record
    end subroutine new_snapshot_iface

    !> Copies the gear's evolving state out (restoring it repeats the gear bit for bit).
    pure subroutine save_iface(gear, snap)
      import :: gear_base_t, gear_snapshot_t
      class(gear_base_t), intent(in) :: gear      !! gear
      class(gear_snapshot_t), intent(inout) :: snap  !! record from new_snapshot (contents replaced)
    end subroutine save_iface

    !> Puts a state from save_state back.
    pure subroutine restore_iface(gear, snap)
      import :: gear_base_t, gear_snapshot_t
      class(gear_base_t), intent(inout) :: gear   !! gear
      class(gear_snapshot_t), intent(in) :: snap  !! saved state
    end subroutine restore_iface
  end interface

contains

  ! ---- the layout

  !> Sets the gear's strut and coordinate counts and its rotation, once, in the gear type's set-up
  !! (strut_count, coordinate_count and rotation return them; before it: no struts, no coordinates,
  !! the identity). STAT_FAILED, nothing set, for a count below 1 or beyond the capacities the
  !! simulation's records are sized by (max_struts, max_gear_q).
  pure subroutine set_layout(gear, n_struts, n_coordinates, rot, status)
    class(gear_base_t), intent(inout) :: gear   !! gear
    integer, intent(in) :: n_struts             !! number of struts, 1..max_struts [-]
    integer, intent(in) :: n_coordinates        !! number of generalized coordinates, 1..max_gear_q [-]
    real(wp), intent(in) :: rot(3, 3)           !! gear frame -> lander frame rotation [-]
    type(status_t), intent(out) :: status       !! STAT_OK, or STAT_FAILED with the diagnosis [-]
    character(len=160) :: text
    if (n_struts < 1 .or. n_struts > max_struts .or. n_coordinates < 1 .or. n_coordinates > max_gear_q) then
      write (text, '(a,i0,a,i0,a,i0,a,i0,a)') 'gear layout: ', n_struts, ' struts, ', n_coordinates, &
        ' coordinates; valid: 1..', max_struts, ', 1..', max_gear_q, ' (max_struts, max_gear_q)'
      call status%fail(STAT_FAILED, trim(text))
      return
    end if
    gear%layout_struts = n_struts
    gear%layout_coordinates = n_coordinates
    gear%layout_rot = rot
  end subroutine set_layout

  !> Number of struts (set_layout; the size of the per-strut arrays).
  pure integer function strut_count(gear) result(n)
    class(gear_base_t), intent(in) :: gear      !! gear
    n = gear%layout_struts
  end function strut_count

  !> Number of generalized coordinates (set_layout; the size of the per-coordinate arrays).
  pure integer function coordinate_count(gear) result(n)
    class(gear_base_t), intent(in) :: gear      !! gear
    n = gear%layout_coordinates
  end function coordinate_count

  !> Gear frame -> lander frame rotation (set_layout).
  pure function rotation(gear) result(rot)
    class(gear_base_t), intent(in) :: gear      !! gear
    real(wp) :: rot(3, 3)                       !! [-]
    rot = gear%layout_rot
  end function rotation

  !> The gear's linear response to a footpad force along `dir` at the decisions of an evaluation:
  !! with the body's frame held (the same field), the changes of the generalized accelerations and of
  !! the load on the body per newton of footpad force, and whether the decisions (locks, sliding
  !! directions, rigid) stay those of `ge`. Default for every gear type: the difference of a second
  !! evaluation with the footpad force increased by df = max(1 N, 1e-4 |f_foot|) (the DAE is linear
  !! in the footpad force at fixed decisions; a gear type may override it with one more solve of its
  !! factorised system). ok = .false. (and the responses 0) when the decisions differ.
  subroutine footpad_response(gear, ge, f_foot, f_field, dir, qdd_u, f_body_u, m_body_u, ok, status, dt, alpha)
    class(gear_base_t), intent(in) :: gear      !! gear (unchanged)
    type(gear_eval_t), intent(in) :: ge         !! its evaluation at f_foot and f_field
    real(wp), intent(in) :: f_foot(3)           !! ground force on the footpad, gear frame [N]
    real(wp), intent(in) :: f_field(3)          !! uniform field g - a_frame of that evaluation, gear frame [m/s^2]
    real(wp), intent(in) :: dir(3)              !! unit direction of the added force, gear frame [-]
    real(wp), intent(out) :: qdd_u(max_gear_q)  !! d qdd / dF [m/s^2/N, rad/s^2/N]
    real(wp), intent(out) :: f_body_u(3)        !! d f_body / dF, gear frame [-]
    real(wp), intent(out) :: m_body_u(3)        !! d m_body / dF, gear axes [m]
    logical, intent(out) :: ok                  !! the decisions did not change [-]
    type(status_t), intent(inout) :: status     !! STAT_OK on entry; the failure's code and diagnosis [-]
    real(wp), intent(in), optional :: dt        !! the step of that evaluation (velocity-level locking) [s]
    real(wp), intent(in), optional :: alpha(3)  !! its body angular acceleration, gear axes [rad/s^2]
    type(gear_eval_t) :: g2
    real(wp) :: df
    integer :: ns
    df = max(1.0_wp, 1.0e-4_wp*norm2(f_foot))
    call gear%evaluate(g2, f_foot + df*dir, f_field, status, dt, alpha, .false.)
    qdd_u = 0.0_wp
    f_body_u = 0.0_wp
    m_body_u = 0.0_wp
    ok = .false.
    if (status%code /= STAT_OK) return
    ns = gear%strut_count()
    ok = all(g2%locked(1:ns) .eqv. ge%locked(1:ns)) .and. all(g2%dir(1:ns) == ge%dir(1:ns)) &
         .and. (g2%rigid .eqv. ge%rigid)
    if (.not. ok) return
    qdd_u = (g2%qdd - ge%qdd)/df
    f_body_u = (g2%f_body - ge%f_body)/df
    m_body_u = (g2%m_body - ge%m_body)/df
  end subroutine footpad_response

  ! ---- the reports' defaults

  !> Default name of strut k: 'strut <k>' ('(none)' beyond the gear's struts).
  pure function strut_name(gear, k) result(name)
    class(gear_base_t), intent(in) :: gear      !! gear
    integer, intent(in) :: k                    !! strut [-]
    character(len=strut_name_len) :: name       !! its name [-]
    if (k < 1 .or. k > gear%strut_count()) then
      name = '(none)'
    else
      write (name, '(a,i0)') 'strut ', k
    end if
  end function strut_name

  !> Crush mode of each strut (strut_mode; 0 locked, +1/-1 crushing toward +s/-s, 2 free) of an
  !! evaluation (the mode it leaves the step in, strut_mode_after), or of the committed state.
  !! Default for the committed state: from locks and axial_forces, a sliding strut crushing in
  !! the direction of its axial force (true of a rigid-plastic buffer, whose force is the bound of
  !! the side it slides toward).
  pure subroutine strut_modes(gear, m, ge)
    class(gear_base_t), intent(in) :: gear      !! gear
    integer, intent(out) :: m(:)                !! per strut [-]
    type(gear_eval_t), intent(in), optional :: ge  !! the evaluation; default the committed state
    logical :: locked(max_struts)
    real(wp) :: axial(max_struts)
    integer :: ns
    ns = gear%strut_count()
    if (present(ge)) then
      m(1:ns) = strut_mode_after(ge%locked(1:ns), ge%axial(1:ns), ge%dir(1:ns), ge%dir_after(1:ns), &
                                 ge%axial_after(1:ns))
    else
      call gear%locks(locked(1:ns))
      call gear%axial_forces(axial(1:ns))
      m(1:ns) = strut_mode(locked(1:ns), axial(1:ns), merge(1, -1, axial(1:ns) >= 0.0_wp))
    end if
  end subroutine strut_modes

  !> Default of the per-strut reports a gear type may not keep, 0 for every strut: axial_forces
  !! (axial buffer forces of the committed state [N]) and crush_work (energy absorbed by each
  !! buffer so far [J]).
  pure subroutine not_reported(gear, v)
    class(gear_base_t), intent(in) :: gear      !! gear
    real(wp), intent(out) :: v(:)               !! per strut [N or J]
    v(1:gear%strut_count()) = 0.0_wp
  end subroutine not_reported

  !> Most negative and most positive stroke reached by each strut. Default: what the present
  !! strokes show (min(0, s), max(0, s)), for a gear type that keeps no history.
  pure subroutine crush_history(gear, s_min, s_max)
    class(gear_base_t), intent(in) :: gear      !! gear
    real(wp), intent(out) :: s_min(:)           !! most negative strokes [m]
    real(wp), intent(out) :: s_max(:)           !! most positive strokes [m]
    real(wp) :: s(max_struts), sd(max_struts)
    integer :: ns
    ns = gear%strut_count()
    call gear%strokes(s(1:ns), sd(1:ns))
    s_min(1:ns) = min(0.0_wp, s(1:ns))
    s_max(1:ns) = max(0.0_wp, s(1:ns))
  end subroutine crush_history

  !> Stroke capacity of strut k's buffer in each direction. Default: unlimited toward +s, none
  !! toward -s (no stroke margin to report); 0 beyond the gear's struts.
  subroutine buffer_capacity(gear, k, cap_pos, cap_neg)
    class(gear_base_t), intent(in) :: gear      !! gear
    integer, intent(in) :: k                    !! strut [-]
    real(wp), intent(out) :: cap_pos            !! toward +s [m]
    real(wp), intent(out) :: cap_neg            !! toward -s (0: none) [m]
    cap_pos = merge(huge(1.0_wp), 0.0_wp, k >= 1 .and. k <= gear%strut_count())
    cap_neg = 0.0_wp
  end subroutine buffer_capacity

  !> The constant crush forces of strut k's buffer law as axial forces (compression +), what
  !! reports draw as its levels (/model/crush_levels): force(j), named name(j), j <= n. Default:
  !! none (n = 0), a gear type that does not report its buffers' levels.
  subroutine crush_levels(gear, k, force, name, n)
    class(gear_base_t), intent(in) :: gear      !! gear
    integer, intent(in) :: k                    !! strut [-]
    real(wp), intent(out) :: force(:)           !! axial force of each level, compression + [N]
    character(len=*), intent(out) :: name(:)    !! what each level is [-]
    integer, intent(out) :: n                   !! number of levels [-]
    force = 0.0_wp
    name = ''
    n = 0
    if (k < 1 .or. k > gear%strut_count()) return  ! no strut k: no levels either
  end subroutine crush_levels

  !> The piece of each strut's buffer law at the current strokes (the adaptive integrator bisects
  !! a step in which one changes). Default: 1, one piece.
  pure subroutine law_segments(gear, v)
    class(gear_base_t), intent(in) :: gear      !! gear
    integer, intent(out) :: v(:)                !! per strut [-]
    v(1:gear%strut_count()) = 1
  end subroutine law_segments

  !> Error-norm weights of the coordinates (the adaptive integrator's error norm). Default: 1.
  pure subroutine coordinate_weights(gear, v)
    class(gear_base_t), intent(in) :: gear      !! gear
    real(wp), intent(out) :: v(:)               !! per coordinate [-]
    v(1:gear%coordinate_count()) = 1.0_wp
  end subroutine coordinate_weights

  !> Prepares what the next evaluation of a gear that has become rigid (settle) needs, its caches.
  !! Default, for a gear type without caches: checks that a rigid gear is at rest (the contract of
  !! settle and set_rates).
  subroutine prepare(gear, status)
    class(gear_base_t), intent(inout) :: gear   !! gear
    type(status_t), intent(inout) :: status     !! STAT_OK on entry; the failure's code and diagnosis [-]
    real(wp) :: qd(max_gear_q)
    integer :: nq
    if (.not. gear%is_rigid()) return
    nq = gear%coordinate_count()
    call gear%rates(qd(1:nq))
    if (any(abs(qd(1:nq)) > 0.0_wp)) call status%fail(STAT_FAILED, 'a rigid gear is not at rest')
  end subroutine prepare

  !> The crush mode a strut has after the step of an evaluation (strut_mode of the mode it leaves the
  !! step in: a strut stopped in the step and leaving it sliding, gear_eval_t%dir_after /= 0, is not
  !! locked after it).
  elemental integer function strut_mode_after(locked, axial, dir, dir_after, axial_after) result(m)
    logical, intent(in) :: locked       !! strut locked for the step [-]
    real(wp), intent(in) :: axial       !! axial buffer force of the step [N]
    integer, intent(in) :: dir          !! sliding direction of the step [-]
    integer, intent(in) :: dir_after    !! direction it leaves a stop in, 0: none [-]
    real(wp), intent(in) :: axial_after !! axial buffer force after the stop [N]
    if (dir_after /= 0) then
      m = strut_mode(.false., axial_after, dir_after)
    else
      m = strut_mode(locked, axial, dir)
    end if
  end function strut_mode_after

  !> Crush mode of a strut, the same codes for every gear type (the simulation counts their
  !! switches): 0 locked, +1 crushing toward +s, -1 crushing toward -s (sliding against a nonzero
  !! bound), 2 sliding freely inside the crushed range (no force; its direction is not a mode).
  elemental integer function strut_mode(locked, axial, dir) result(m)
    logical, intent(in) :: locked     !! strut locked [-]
    real(wp), intent(in) :: axial     !! axial buffer force [N]
    integer, intent(in) :: dir        !! sliding direction [-]
    if (locked) then
      m = 0
    else if (abs(axial) > tiny(1.0_wp)) then
      m = sign(1, dir)
    else
      m = 2
    end if
  end function strut_mode

end module landyn_gear_base
