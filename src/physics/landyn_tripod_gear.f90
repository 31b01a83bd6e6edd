!> The paper's tripod gear (landyn_gear: a primary strut with the footpad and two secondaries) as
!! an extension of gear_base_t: each binding is one of landyn_gear's public procedures, so the
!! simulation, which holds its gears through gear_base_t, runs the tripod exactly as landyn_gear
!! defines it. tripod_init builds one from its geometry, strut masses and buffer laws.
module landyn_tripod_gear
  use landyn_kinds, only: wp, max_gear_rows, max_gear_q
  use landyn_gear_base, only: gear_base_t, gear_eval_t, gear_snapshot_t, strut_name_len, strut_mode_after
  use landyn_kinematics, only: gear_geometry_t
  use landyn_buffer, only: buffer_law_t
  use landyn_tube_friction, only: tube_friction_t
  use landyn_gear, only: gear_t, gear_state_t, strut_mass_t, gear_init, gear_set_buffer, gear_footpad, gear_evaluate, &
                         gear_commit, gear_arrest, gear_increment, gear_correct_positions, &
                         gear_settle, gear_prepare, gear_strokes, &
                         gear_crush_history, gear_axial_forces, gear_crush_work, gear_strut_lengths, gear_law_segments, &
                         gear_locks, gear_strut_modes, strut_modes, gear_buffer_capacity, gear_violations, gear_rates, &
                         gear_set_rates, gear_accelerations, gear_is_rigid, gear_velocity_rows, &
                         gear_cache_jacobian, &
                         gear_mass_diagonal, gear_momentum_maps, gear_relative_momenta, gear_leg_momentum, &
                         gear_rotation, gear_save_state, &
                         gear_restore_state, n_struts, n_q, n_phi, strut_names, idx_len
  implicit none
  private

  public :: tripod_gear_t, tripod_init

  !> The tripod gear behind the gear-type interface.
  type, extends(gear_base_t) :: tripod_gear_t
    type(gear_t) :: gear                            !! the tripod (landyn_gear)
  contains
    procedure :: strut_count => tripod_strut_count                     !! number of struts [-]
    procedure :: coordinate_count => tripod_coordinate_count           !! number of generalized coordinates [-]
    procedure :: strut_name => tripod_strut_name                       !! name of strut k (reports)
    procedure :: rotation => tripod_rotation                           !! gear frame -> lander frame rotation [-]
    procedure :: footpad => tripod_footpad                             !! footpad position and velocity, gear frame [m, m/s]
    procedure :: evaluate => tripod_evaluate                           !! crush logic and accelerations into a gear_eval_t
    procedure :: commit => tripod_commit                               !! makes an evaluation the committed state
    procedure :: arrest => tripod_arrest                               !! crush modes at the end of a step
    procedure :: increment => tripod_increment                         !! q <- q + qd h, with the crush work
    procedure :: correct_positions => tripod_correct_positions         !! position projection onto the constraints
    procedure :: settle => tripod_settle                               !! all struts locked: the gear becomes rigid
    procedure :: prepare => tripod_prepare                             !! caches for the next evaluation of a rigid gear
    procedure :: strokes => tripod_strokes                             !! strokes and stroke rates [m, m/s]
    procedure :: crush_history => tripod_crush_history                 !! most negative and positive strokes reached [m]
    procedure :: axial_forces => tripod_axial_forces                   !! axial buffer forces [N]
    procedure :: crush_work => tripod_crush_work                       !! energy absorbed by each buffer [J]
    procedure :: strut_lengths => tripod_strut_lengths                 !! strut lengths [m]
    procedure :: law_segments => tripod_law_segments                   !! piece of each buffer law [-]
    procedure :: locks => tripod_locks                                 !! which struts are locked [-]
    procedure :: strut_modes => tripod_strut_modes                     !! crush mode of each strut [-]
    procedure :: buffer_capacity => tripod_buffer_capacity             !! stroke capacity of strut k's buffer [m]
    procedure :: violations => tripod_violations                       !! largest constraint violations [m]
    procedure :: coordinate_weights => tripod_coordinate_weights       !! error-norm weights of the coordinates [-]
    procedure :: rates => tripod_rates                                 !! generalized velocities [m/s, rad/s]
    procedure :: accelerations => tripod_accelerations                 !! committed accelerations [m/s^2, rad/s^2]
    procedure :: set_rates => tripod_set_rates                         !! replaces the generalized velocities
    procedure :: is_rigid => tripod_is_rigid                           !! all struts locked and at rest
    procedure :: velocity_rows => tripod_velocity_rows                 !! velocity constraint rows (A qd = 0)
    procedure :: mass_diagonal => tripod_mass_diagonal                 !! mass matrix diagonal [kg, kg m^2]
    procedure :: momentum_maps => tripod_momentum_maps                 !! maps from qd to the legs' momenta
    procedure :: relative_momenta => tripod_relative_momenta           !! legs' relative momenta and kinetic energy
    procedure :: leg_momentum => tripod_leg_momentum                   !! legs' momentum, first moment and mass
    procedure :: new_snapshot => tripod_new_snapshot                   !! allocates a snapshot of the gear's type
    procedure :: save_state => tripod_save_state                       !! copies the evolving state out
    procedure :: restore_state => tripod_restore_state                 !! puts a saved state back
  end type tripod_gear_t

  !> The tripod's evolving state (gear_state_t).
  type, extends(gear_snapshot_t) :: tripod_snapshot_t
    type(gear_state_t) :: st                        !! the saved state
  end type tripod_snapshot_t

contains

  !> Sets up a tripod at its nominal configuration, all struts locked and at rest (gear_init).
  subroutine tripod_init(self, geom, rot, mass, primary, secondary, stat, errmsg, tube)
    type(tripod_gear_t), intent(inout) :: self      !! gear
    type(gear_geometry_t), intent(in) :: geom       !! geometry in the gear frame
    real(wp), intent(in) :: rot(3, 3)               !! gear frame -> lander frame [-]
    type(strut_mass_t), intent(in) :: mass(n_struts)  !! strut mass properties (primary, left, right)
    class(buffer_law_t), intent(in) :: primary      !! the primary's buffer law
    class(buffer_law_t), intent(in) :: secondary    !! both secondaries' buffer law
    integer, intent(out) :: stat                    !! STAT_OK on success
    character(len=*), intent(inout) :: errmsg       !! diagnosis on failure
    type(tube_friction_t), intent(in), optional :: tube  !! primary tube friction; absent: off
    integer :: k
    call gear_set_buffer(self%gear, 1, primary)
    do k = 2, n_struts
      call gear_set_buffer(self%gear, k, secondary)
    end do
    call gear_init(self%gear, geom, rot, mass, stat, errmsg, tube)
  end subroutine tripod_init

  !> Three struts.
  pure integer function tripod_strut_count(self) result(n)
    class(tripod_gear_t), intent(in) :: self        !! gear
    n = n_struts + 0*storage_size(self)   ! a constant of the type (the product only reads self)
  end function tripod_strut_count

  !> Nine generalized coordinates.
  pure integer function tripod_coordinate_count(self) result(n)
    class(tripod_gear_t), intent(in) :: self        !! gear
    n = n_q + 0*storage_size(self)        ! a constant of the type (the product only reads self)
  end function tripod_coordinate_count

  !> Primary, secondary left, secondary right.
  pure function tripod_strut_name(self, k) result(name)
    class(tripod_gear_t), intent(in) :: self        !! gear
    integer, intent(in) :: k                        !! strut [-]
    character(len=strut_name_len) :: name           !! [-]
    name = strut_names(min(k, tripod_strut_count(self)))
  end function tripod_strut_name

  !> gear_rotation.
  pure function tripod_rotation(self) result(rot)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp) :: rot(3, 3)                           !! [-]
    rot = gear_rotation(self%gear)
  end function tripod_rotation

  !> Footpad position and velocity, gear frame (gear_footpad, with the given rates when given).
  pure subroutine tripod_footpad(self, pos, vel, rates)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: pos(3)                 !! [m]
    real(wp), intent(out) :: vel(3)                 !! [m/s]
    real(wp), intent(in), optional :: rates(:)      !! generalized velocities to use [m/s, rad/s]
    if (present(rates)) then
      call gear_footpad(self%gear, pos, vel, rates(1:n_q))
    else
      call gear_footpad(self%gear, pos, vel)
    end if
  end subroutine tripod_footpad

  !> gear_evaluate.
  subroutine tripod_evaluate(self, ge, f_foot, f_field, stat, errmsg, dt, alpha, loads)
    class(tripod_gear_t), intent(in) :: self        !! gear (unchanged)
    type(gear_eval_t), intent(inout) :: ge          !! the evaluation (reset by gear_evaluate)
    real(wp), intent(in) :: f_foot(3)               !! ground force on the footpad, gear frame [N]
    real(wp), intent(in) :: f_field(3)              !! uniform field, gear frame [m/s^2]
    integer, intent(out) :: stat                    !! STAT_OK on success
    character(len=*), intent(inout) :: errmsg       !! diagnosis on failure
    real(wp), intent(in), optional :: dt            !! coming time step [s]
    real(wp), intent(in), optional :: alpha(3)      !! body angular acceleration, gear axes [rad/s^2]
    logical, intent(in), optional :: loads          !! compute the interface loads [-]
    call gear_evaluate(self%gear, ge, f_foot, f_field, stat, errmsg, dt, alpha, loads)
  end subroutine tripod_evaluate

  !> gear_commit.
  pure subroutine tripod_commit(self, ge)
    class(tripod_gear_t), intent(inout) :: self     !! gear
    type(gear_eval_t), intent(in) :: ge             !! its evaluation
    call gear_commit(self%gear, ge)
  end subroutine tripod_commit

  !> gear_arrest.
  pure subroutine tripod_arrest(self, qd_end)
    class(tripod_gear_t), intent(inout) :: self     !! gear
    real(wp), intent(in) :: qd_end(:)               !! end-of-step generalized velocities [m/s, rad/s]
    call gear_arrest(self%gear, qd_end(1:n_q))
  end subroutine tripod_arrest

  !> gear_increment.
  pure subroutine tripod_increment(self, qd, h)
    class(tripod_gear_t), intent(inout) :: self     !! gear
    real(wp), intent(in) :: qd(:)                   !! velocity the coordinates move with [m/s, rad/s]
    real(wp), intent(in) :: h                       !! duration [s]
    call gear_increment(self%gear, qd(1:n_q), h)
  end subroutine tripod_increment

  !> gear_correct_positions.
  subroutine tripod_correct_positions(self, tol, max_iter, max_drift, stat, errmsg)
    class(tripod_gear_t), intent(inout) :: self     !! gear
    real(wp), intent(in) :: tol                     !! correction tolerance [m]
    integer, intent(in) :: max_iter                 !! iteration cap [-]
    real(wp), intent(in) :: max_drift               !! largest violation before correction [m]
    integer, intent(out) :: stat                    !! STAT_OK on success
    character(len=*), intent(inout) :: errmsg       !! diagnosis on failure
    call gear_correct_positions(self%gear, tol, max_iter, max_drift, stat, errmsg)
  end subroutine tripod_correct_positions

  !> gear_settle.
  pure subroutine tripod_settle(self)
    class(tripod_gear_t), intent(inout) :: self     !! gear
    call gear_settle(self%gear)
  end subroutine tripod_settle

  !> gear_prepare.
  subroutine tripod_prepare(self, stat, errmsg)
    class(tripod_gear_t), intent(inout) :: self     !! gear
    integer, intent(out) :: stat                    !! STAT_OK on success
    character(len=*), intent(inout) :: errmsg       !! diagnosis on failure
    call gear_prepare(self%gear, stat, errmsg)
  end subroutine tripod_prepare

  !> Strokes and stroke rates (gear_strokes).
  pure subroutine tripod_strokes(self, s, sd)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: s(:)                   !! strokes [m]
    real(wp), intent(out) :: sd(:)                  !! stroke rates [m/s]
    real(wp) :: s3(n_struts), sd3(n_struts)
    call gear_strokes(self%gear, s3, sd3)
    s(1:n_struts) = s3
    sd(1:n_struts) = sd3
  end subroutine tripod_strokes

  !> Most negative and most positive strokes reached (gear_crush_history).
  pure subroutine tripod_crush_history(self, s_min, s_max)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: s_min(:)                   !! most negative strokes [m]
    real(wp), intent(out) :: s_max(:)                  !! most positive strokes [m]
    real(wp) :: s3(n_struts), sd3(n_struts)
    call gear_crush_history(self%gear, s3, sd3)
    s_min(1:n_struts) = s3
    s_max(1:n_struts) = sd3
  end subroutine tripod_crush_history

  !> Axial buffer forces.
  pure subroutine tripod_axial_forces(self, v)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: v(:)                   !! [N]
    v(1:n_struts) = gear_axial_forces(self%gear)
  end subroutine tripod_axial_forces

  !> Energy absorbed by each buffer.
  pure subroutine tripod_crush_work(self, v)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: v(:)                   !! [J]
    v(1:n_struts) = gear_crush_work(self%gear)
  end subroutine tripod_crush_work

  !> Strut lengths.
  pure subroutine tripod_strut_lengths(self, v)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: v(:)                   !! [m]
    v(1:n_struts) = gear_strut_lengths(self%gear)
  end subroutine tripod_strut_lengths

  !> gear_law_segments.
  pure subroutine tripod_law_segments(self, v)
    class(tripod_gear_t), intent(in) :: self        !! gear
    integer, intent(out) :: v(:)                    !! [-]
    v(1:n_struts) = gear_law_segments(self%gear)
  end subroutine tripod_law_segments

  !> gear_locks.
  pure subroutine tripod_locks(self, locked)
    class(tripod_gear_t), intent(in) :: self        !! gear
    logical, intent(out) :: locked(:)               !! [-]
    locked(1:n_struts) = gear_locks(self%gear)
  end subroutine tripod_locks

  !> strut_modes of an evaluation, gear_strut_modes of the committed state.
  pure subroutine tripod_strut_modes(self, m, ge)
    class(tripod_gear_t), intent(in) :: self        !! gear
    integer, intent(out) :: m(:)                    !! [-]
    type(gear_eval_t), intent(in), optional :: ge   !! the evaluation
    if (present(ge)) then
      ! the mode each strut leaves the step in (a strut stopped by its lock row may leave it sliding)
      m(1:n_struts) = strut_mode_after(ge%locked(1:n_struts), ge%axial(1:n_struts), ge%dir(1:n_struts), &
                                       ge%dir_after(1:n_struts), ge%axial_after(1:n_struts))
    else
      m(1:n_struts) = gear_strut_modes(self%gear)
    end if
  end subroutine tripod_strut_modes

  !> gear_buffer_capacity.
  subroutine tripod_buffer_capacity(self, k, cap_pos, cap_neg)
    class(tripod_gear_t), intent(in) :: self        !! gear
    integer, intent(in) :: k                        !! strut [-]
    real(wp), intent(out) :: cap_pos                !! [m]
    real(wp), intent(out) :: cap_neg                !! [m]
    call gear_buffer_capacity(self%gear, k, cap_pos, cap_neg)
  end subroutine tripod_buffer_capacity

  !> gear_violations.
  pure subroutine tripod_violations(self, violation, drift)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: violation              !! [m]
    real(wp), intent(out) :: drift                  !! [m]
    call gear_violations(self%gear, violation, drift)
  end subroutine tripod_violations

  !> Error weights of the coordinates: 1 for a strut length, the strut's length for its angles.
  pure subroutine tripod_coordinate_weights(self, v)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: v(:)                   !! [-, m]
    real(wp) :: len(n_struts)
    integer :: k
    len = gear_strut_lengths(self%gear)
    do k = 1, n_struts
      v(idx_len(k)) = 1.0_wp
      v(idx_len(k) + 1:idx_len(k) + 2) = len(k)
    end do
  end subroutine tripod_coordinate_weights

  !> gear_rates.
  pure subroutine tripod_rates(self, v)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: v(:)                   !! [m/s, rad/s]
    v(1:n_q) = gear_rates(self%gear)
  end subroutine tripod_rates

  !> gear_accelerations.
  pure subroutine tripod_accelerations(self, v)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: v(:)                   !! [m/s^2, rad/s^2]
    v(1:n_q) = gear_accelerations(self%gear)
  end subroutine tripod_accelerations

  !> gear_set_rates.
  pure subroutine tripod_set_rates(self, v)
    class(tripod_gear_t), intent(inout) :: self     !! gear
    real(wp), intent(in) :: v(:)                    !! [m/s, rad/s]
    call gear_set_rates(self%gear, v(1:n_q))
  end subroutine tripod_set_rates

  !> gear_is_rigid.
  pure logical function tripod_is_rigid(self) result(rigid)
    class(tripod_gear_t), intent(in) :: self        !! gear
    rigid = gear_is_rigid(self%gear)
  end function tripod_is_rigid

  !> gear_velocity_rows; Phi_q (the first n_phi rows) is cached for the next evaluation.
  pure subroutine tripod_velocity_rows(self, a, nrow)
    class(tripod_gear_t), intent(inout) :: self     !! gear
    real(wp), intent(out) :: a(max_gear_rows, max_gear_q)  !! rows [m/rad, -]
    integer, intent(out) :: nrow                    !! [-]
    call gear_velocity_rows(self%gear, a, nrow)
    call gear_cache_jacobian(self%gear, a(1:n_phi, :))
  end subroutine tripod_velocity_rows

  !> gear_mass_diagonal.
  pure subroutine tripod_mass_diagonal(self, v)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: v(:)                   !! [kg, kg m^2]
    v(1:n_q) = gear_mass_diagonal(self%gear)
  end subroutine tripod_mass_diagonal

  !> gear_momentum_maps.
  pure subroutine tripod_momentum_maps(self, pm, hm)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: pm(3, max_gear_q)      !! [kg, kg m]
    real(wp), intent(out) :: hm(3, max_gear_q)      !! [kg m, kg m^2]
    call gear_momentum_maps(self%gear, pm, hm)
  end subroutine tripod_momentum_maps

  !> gear_relative_momenta.
  pure subroutine tripod_relative_momenta(self, p_rel, h_rel, t_rel)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: p_rel(3)               !! [kg m/s]
    real(wp), intent(out) :: h_rel(3)               !! [kg m^2/s]
    real(wp), intent(out) :: t_rel                  !! [J]
    call gear_relative_momenta(self%gear, p_rel, h_rel, t_rel)
  end subroutine tripod_relative_momenta

  !> gear_leg_momentum.
  pure subroutine tripod_leg_momentum(self, p_rel, first_moment, leg_mass)
    class(tripod_gear_t), intent(in) :: self        !! gear
    real(wp), intent(out) :: p_rel(3)               !! [kg m/s]
    real(wp), intent(out) :: first_moment(3)        !! [kg m]
    real(wp), intent(out) :: leg_mass               !! [kg]
    call gear_leg_momentum(self%gear, p_rel, first_moment, leg_mass)
  end subroutine tripod_leg_momentum

  !> A tripod_snapshot_t.
  subroutine tripod_new_snapshot(self, snap)
    class(tripod_gear_t), intent(in) :: self        !! gear
    class(gear_snapshot_t), allocatable, intent(inout) :: snap  !! the record
    type(tripod_snapshot_t) :: mold
    if (allocated(snap)) deallocate (snap)
    call gear_save_state(self%gear, mold%st)
    allocate (snap, source=mold)
  end subroutine tripod_new_snapshot

  !> gear_save_state into a tripod_snapshot_t (another record is left unchanged).
  pure subroutine tripod_save_state(self, snap)
    class(tripod_gear_t), intent(in) :: self        !! gear
    class(gear_snapshot_t), intent(inout) :: snap   !! record from new_snapshot
    select type (snap)
    type is (tripod_snapshot_t)
      call gear_save_state(self%gear, snap%st)
    end select
  end subroutine tripod_save_state

  !> gear_restore_state from a tripod_snapshot_t (another record is ignored).
  pure subroutine tripod_restore_state(self, snap)
    class(tripod_gear_t), intent(inout) :: self     !! gear
    class(gear_snapshot_t), intent(in) :: snap      !! saved state
    select type (snap)
    type is (tripod_snapshot_t)
      call gear_restore_state(self%gear, snap%st)
    end select
  end subroutine tripod_restore_state

end module landyn_tripod_gear
