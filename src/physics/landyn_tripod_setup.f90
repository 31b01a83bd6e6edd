!> The gear's set-up (gear_init), footpad, strut kinematics, mass matrix and strokes, and the
!! accessors through which the other layers and the tests read and set its (private) state.
submodule (landyn_tripod_gear) landyn_tripod_setup
  use, intrinsic :: iso_fortran_env, only: int64
  use landyn_kinematics, only: strut_axis_derivs, strut_axis_derivs_trig
  use landyn_tripod_kinematics, only: gear_trig
  use landyn_status, only: STAT_OK, STAT_FAILED
  use landyn_strut, only: strut_from_mass
  implicit none

contains

  module procedure gear_init
    integer :: k
    call gear%set_layout(n_struts, n_q, rot, status)
    if (.not. status%ok()) return
    gear%tube = tube_friction_t()
    if (present(tube)) gear%tube = tube
    gear%st%tube_bound = 0.0_wp
    gear%geom = geom
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
    call cache_kinematics(gear)
    gear%st%qd = 0.0_wp
    gear%st%qdd = 0.0_wp
    gear%st%locked = .true.
    gear%st%phq_ok = .false.
    gear%st%rigid = .false.          ! entered by gear_settle once all struts are locked
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
        call status%fail(STAT_FAILED, 'gear_init: buffer law not set')
        return
      end if
      if (mass(k)%m_i + mass(k)%m_end <= 0.0_wp) then
        call status%fail(STAT_FAILED, 'gear_init: a strut has no sliding mass')
        return
      end if
    end do
  end procedure gear_init

  module procedure gear_footpad
    real(wp) :: u(3), du1(3), du2(3), d11(3), d12(3), d22(3), v(n_q)
    ! the primary's axis from the kinematics cache when it holds the current coordinates (it does
    ! after every step): the same values strut_axis_derivs gives
    if (gear%st%kin_ok .and. same_coordinates(gear%st%q, gear%st%kin_q)) then
      u = gear%st%kin(1)%u
      du1 = gear%st%kin(1)%u1
      du2 = gear%st%kin(1)%u2
    else
      call strut_axis_derivs(gear%geom%R0p, gear%st%q(2), gear%st%q(3), u, du1, du2, d11, d12, d22)
    end if
    if (present(rates)) then
      v = rates(1:n_q)
    else
      v = gear%st%qd
    end if
    pos = gear%geom%a + gear%st%q(1)*u
    vel = v(1)*u + gear%st%q(1)*(du1*v(2) + du2*v(3))
  end procedure gear_footpad

  module procedure strut_kinematics
    if (gear%st%kin_ok) then
      if (same_coordinates(q, gear%st%kin_q)) then
        sk = gear%st%kin
        return
      end if
    end if
    call kinematics_at(gear%geom, gear%strut, q, sk)
  end procedure strut_kinematics

  module procedure kinematics_at
    type(joint_trig_t) :: tr(n_struts)
    ! cos and sin of the joint angles once (gear_trig), or those the caller already has
    if (present(trig)) then
      tr = trig
    else
      tr = gear_trig(q)
    end if
    sk(1)%p = geom%a
    sk(2)%p = geom%b
    sk(3)%p = geom%c
    call strut_axis_derivs_trig(geom%R0p, tr(1), sk(1)%u, sk(1)%u1, sk(1)%u2, sk(1)%u11, sk(1)%u12, sk(1)%u22)
    call strut_axis_derivs_trig(geom%R0b, tr(2), sk(2)%u, sk(2)%u1, sk(2)%u2, sk(2)%u11, sk(2)%u12, sk(2)%u22)
    call strut_axis_derivs_trig(geom%R0c, tr(3), sk(3)%u, sk(3)%u1, sk(3)%u2, sk(3)%u11, sk(3)%u12, sk(3)%u22)
    sk(1)%mf = strut(1)%at(q(idx_len(1)))
    sk(2)%mf = strut(2)%at(q(idx_len(2)))
    sk(3)%mf = strut(3)%at(q(idx_len(3)))
  end procedure kinematics_at

  module procedure secondary_axes_of
    integer :: k
    do k = 2, 3
      axes(k - 1) = sk(k)%axis_derivs_t
    end do
  end procedure secondary_axes_of

  module procedure same_coordinates
    integer :: i
    ! element by element (an array transfer would allocate a temporary)
    same = .false.
    do i = 1, n_q
      if (transfer(a(i), 0_int64) /= transfer(b(i), 0_int64)) return
    end do
    same = .true.
  end procedure same_coordinates

  module procedure cache_kinematics
    call kinematics_at(gear%geom, gear%strut, gear%st%q, gear%st%kin)
    gear%st%kin_q = gear%st%q
    gear%st%kin_ok = .true.
  end procedure cache_kinematics

  module procedure gear_mass_matrix
    type(strut_kin_t) :: sk(n_struts)
    integer :: k
    if (gear%st%kin_ok) then
      if (same_coordinates(q, gear%st%kin_q)) then
        mdiag = mass_diagonal(gear%st%kin, q)
        return
      end if
    end if
    do k = 1, n_struts
      sk(k)%mf = gear%strut(k)%at(q(idx_len(k)))
    end do
    mdiag = mass_diagonal(sk, q)
  end procedure gear_mass_matrix

  module procedure mass_diagonal
    integer :: k, i0
    real(wp) :: jr, c
    do k = 1, 3
      i0 = idx_len(k) - 1
      jr = sk(k)%mf%j
      c = cos(q(i0 + 3))
      mdiag(i0 + 1) = sk(k)%mf%m_s
      mdiag(i0 + 2) = jr*c*c
      mdiag(i0 + 3) = jr
    end do
  end procedure mass_diagonal

  module procedure gear_relative_kinetic_energy
    t = 0.5_wp*sum(gear_mass_matrix(gear, gear%st%q)*gear%st%qd**2)
  end procedure gear_relative_kinetic_energy

  module procedure strokes
    s = gear%sigma*(qv(idx_len) - gear%len0)
    sd = gear%sigma*qdv(idx_len)
  end procedure strokes

  module procedure gear_law_segments
    real(wp) :: s(3), sd(3)
    integer :: k
    call strokes(gear, gear%st%q, gear%st%qd, s, sd)
    do k = 1, 3
      v(k) = gear%buffer(k)%law%segment(s(k))
    end do
  end procedure gear_law_segments

  module procedure leg_first_moment
    integer :: k
    type(strut_mass_functions_t) :: mf
    real(wp) :: sm
    fm = 0.0_wp
    do k = 1, 3
      mf = sk(k)%mf
      sm = mf%s
      fm = fm + mf%m_tot*sk(k)%p + sm*sk(k)%u
    end do
  end procedure leg_first_moment

  module procedure gear_strokes
    call strokes(gear, gear%st%q, gear%st%qd, s, sd)
  end procedure gear_strokes


  module procedure gear_rates
    qd = gear%st%qd
  end procedure gear_rates

  module procedure gear_set_rates
    gear%st%qd = v(1:n_q)
  end procedure gear_set_rates

  module procedure gear_locks
    locked = gear%st%locked
  end procedure gear_locks

  module procedure gear_strut_modes
    m = strut_modes(gear%st%locked, gear%st%axial, gear%st%dir)
  end procedure gear_strut_modes

  module procedure strut_modes
    m = strut_mode(locked, axial, dir)
  end procedure strut_modes

  module procedure gear_is_rigid
    rigid = gear%st%rigid
  end procedure gear_is_rigid

  module procedure gear_cache_jacobian
    gear%st%phq = phq
    gear%st%phq_q = gear%st%q
    gear%st%phq_ok = .true.
  end procedure gear_cache_jacobian

  module procedure gear_crush_history
    s_min(1:n_struts) = gear%st%s_hismin
    s_max(1:n_struts) = gear%st%s_hismax
  end procedure gear_crush_history

  module procedure gear_crush_work
    w = gear%st%work_crush
  end procedure gear_crush_work

  module procedure gear_violations
    violation = gear%st%max_violation
    drift = gear%st%max_drift
  end procedure gear_violations

  module procedure gear_buffer_capacity
    call gear%buffer(k)%law%capacity(cap_pos, cap_neg)
  end procedure gear_buffer_capacity

  module procedure gear_set_buffer
    if (allocated(gear%buffer(k)%law)) deallocate (gear%buffer(k)%law)
    allocate (gear%buffer(k)%law, source=law)
  end procedure gear_set_buffer

  module procedure gear_axial_forces
    axial = gear%st%axial
  end procedure gear_axial_forces

  module procedure gear_body_load
    f_body = gear%st%f_body
    m_body = gear%st%m_body
  end procedure gear_body_load

  module procedure gear_coordinates
    q = gear%st%q
  end procedure gear_coordinates

  module procedure gear_accelerations
    qdd = gear%st%qdd
  end procedure gear_accelerations

  module procedure gear_set_coordinates
    gear%st%q = q
    call cache_kinematics(gear)
    if (present(qd)) gear%st%qd = qd
  end procedure gear_set_coordinates

  module procedure gear_set_locks
    gear%st%locked = locked
    if (present(s_lock)) gear%st%s_lock = s_lock
  end procedure gear_set_locks

  module procedure gear_slide_directions
    dir = gear%st%dir
  end procedure gear_slide_directions

  module procedure gear_set_crush_history
    gear%st%s_hismin = s_min
    gear%st%s_hismax = s_max
  end procedure gear_set_crush_history

  module procedure gear_set_axial_forces
    gear%st%axial = axial
  end procedure gear_set_axial_forces

  module procedure gear_set_rigid
    gear%st%rigid = rigid
    gear%st%rigid_cache = .false.
  end procedure gear_set_rigid

  module procedure gear_tube_bound
    bound = gear%st%tube_bound
  end procedure gear_tube_bound

  module procedure gear_geometry
    geom = gear%geom
  end procedure gear_geometry

  module procedure gear_strut
    strut = gear%strut(k)
  end procedure gear_strut

  module procedure gear_nominal_lengths
    len0 = gear%len0
  end procedure gear_nominal_lengths

  ! ---- the gear_base_t bindings

  module procedure tripod_init
    integer :: k
    call gear_set_buffer(self, 1, primary)
    do k = 2, n_struts
      call gear_set_buffer(self, k, secondary)
    end do
    call gear_init(self, geom, rot, mass, status, tube)
  end procedure tripod_init

  module procedure tripod_strut_name
    name = strut_names(max(1, min(k, size(gear%len0))))
  end procedure tripod_strut_name

  module procedure tripod_locks
    locked(1:n_struts) = gear%st%locked
  end procedure tripod_locks

  module procedure tripod_rates
    v(1:n_q) = gear%st%qd
  end procedure tripod_rates

  module procedure tripod_accelerations
    v(1:n_q) = gear%st%qdd
  end procedure tripod_accelerations

  module procedure tripod_mass_diagonal
    v(1:n_q) = gear_mass_matrix(gear, gear%st%q)
  end procedure tripod_mass_diagonal

  module procedure tripod_strut_lengths
    v(1:n_struts) = gear%st%q(idx_len)
  end procedure tripod_strut_lengths

  module procedure tripod_axial_forces
    v(1:n_struts) = gear%st%axial
  end procedure tripod_axial_forces

  module procedure tripod_crush_work
    v(1:n_struts) = gear%st%work_crush
  end procedure tripod_crush_work

  module procedure tripod_strut_modes
    if (present(ge)) then
      ! the mode each strut leaves the step in (a strut stopped by its lock row may leave it sliding)
      m(1:n_struts) = strut_mode_after(ge%locked(1:n_struts), ge%axial(1:n_struts), ge%dir(1:n_struts), &
                                       ge%dir_after(1:n_struts), ge%axial_after(1:n_struts))
    else
      m(1:n_struts) = strut_modes(gear%st%locked, gear%st%axial, gear%st%dir)
    end if
  end procedure tripod_strut_modes

  module procedure tripod_coordinate_weights
    integer :: k
    do k = 1, n_struts
      v(idx_len(k)) = 1.0_wp
      v(idx_len(k) + 1:idx_len(k) + 2) = gear%st%q(idx_len(k))
    end do
  end procedure tripod_coordinate_weights

  module procedure tripod_new_snapshot
    type(tripod_snapshot_t) :: mold
    if (allocated(snap)) deallocate (snap)
    mold%st = gear%st
    allocate (snap, source=mold)
  end procedure tripod_new_snapshot

  module procedure tripod_save_state
    select type (snap)
    type is (tripod_snapshot_t)
      snap%st = gear%st
    end select
  end procedure tripod_save_state

  module procedure tripod_restore_state
    select type (snap)
    type is (tripod_snapshot_t)
      gear%st = snap%st
    end select
  end procedure tripod_restore_state

  ! ---- crush levels (reports: /model/crush_levels)

  module procedure tripod_crush_levels
    integer :: toward(size(force))
    force = 0.0_wp
    name = ''
    n = 0
    if (k < 1 .or. k > n_struts) return
    call gear%buffer(k)%law%crush_levels(force, toward, name, n)
    ! a bound against motion toward +s (toward = +1) resists dL = sigma ds: compression when
    ! the strut shortens toward +s (sigma = -1), tension when it lengthens
    force(1:n) = -gear%sigma(k)*real(toward(1:n), wp)*force(1:n)
  end procedure tripod_crush_levels

end submodule landyn_tripod_setup
