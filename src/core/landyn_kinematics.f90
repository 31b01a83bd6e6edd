!> Rigid-body and strut kinematics of LANDYN (paper sections 2.1-2.2 and 2.4, eqs. 2-5 and 10):
!! 3x3 algebra, rotations and attitude, gear frames and the nominal strut frames, a strut's
!! universal-joint kinematics, and the gear coordinate layout the gear geometry is stated in.
!!
!! Conventions (fixed for the whole code):
!!
!! * Frames. Global frame O_g: x, y horizontal, z DOWN, gravity along +z. Lander frame O_L
!!   (geometric centre of the lander), also z down. All lengths in m, angles in rad.
!! * Elementary rotations are the standard right-handed ones:
!!     rot_x(a) = [[1,0,0],[0,c,-s],[0,s,c]]
!!     rot_y(a) = [[c,0,s],[0,1,0],[-s,0,c]]
!!     rot_z(a) = [[c,-s,0],[s,c,0],[0,0,1]]
!!   The paper's printed R_y has the sign of sin(theta) transposed; we use the standard matrix.
!! * Attitude: Z-Y-X Euler angles (psi yaw, theta pitch, phi roll). The body-to-global rotation is
!!   R = rot_z(psi) rot_y(theta) rot_x(phi) (eq. 2 / Nomenclature): x_global = x_OL + R p_L.
!!   `euler_zyx_from_matrix` returns theta in [-pi/2, pi/2], psi and phi in (-pi, pi].
!! * Homogeneous transforms (eq. 2): T = [[R, p],[0, 1]] maps child coordinates to parent
!!   coordinates, x_parent = R x_child + p; composition is the matrix product.
!! * Euler-rate transform (eq. 10): [psi_dot, theta_dot, phi_dot] = E(theta, phi) [p, q, r], with
!!   p, q, r the body angular rates about the lander x, y, z axes. Derived from
!!   omega_body = rot_x^T rot_y^T [0,0,psi_dot] + rot_x^T [0,theta_dot,0] + [phi_dot,0,0]:
!!     E = [[0, sin(phi)/cos(theta), cos(phi)/cos(theta)],
!!          [0, cos(phi),            -sin(phi)          ],
!!          [1, sin(phi)tan(theta),  cos(phi)tan(theta) ]].
!!   Eq. 10 as printed lists these rows in (phi, theta, psi) order; the order here is (psi, theta,
!!   phi). E is singular at theta = +-pi/2 (callers must stay away; tip-over is far earlier).
!!   The translation block of eq. 10 is R itself (its printed (2,3) entry has a typo: s(theta)
!!   s(psi) c(phi) - s(phi) c(psi) is correct).
!! * Gear frame i: the lander frame rotated about lander z by rotation(i),
!!   R_gi = gear_rotation(rotation(i)) = rot_z(rotation(i)); p_L = R_gi p_g, p_g = R_gi^T p_L.
!!   The gear frame has the same origin O_L as the lander frame.
!! * Gear geometry: hard points a (primary upper universal joint), b, c (left / right secondary
!!   upper universal joints), d (footpad ball joint), e, f (left / right secondary lower ball
!!   joints on the primary's outer tube), given in the GEAR frame at the nominal, uncrushed
!!   configuration. Left secondary runs b -> e, right secondary c -> f (docs/model_conventions.md pairing).
!! * Strut frames. Each strut (upper joint P, lower end X) has a nominal frame R0 = [x0 y0 z0]
!!   (columns, in the gear frame): z0 = unit vector from P toward X at the nominal configuration,
!!   x0 = normalize(ey x z0) with ey = (0,1,0) of the gear frame (ex if z0 is nearly parallel to
!!   ey), y0 = z0 x x0. The strut orientation is R = R0 rot_x(t1) rot_y(t2) (universal joint: t1
!!   about the fixed x0 axis, then t2 about the rotated y axis), its unit axis
!!   u = R e_z = R0 (sin t2, -sin t1 cos t2, cos t1 cos t2), and its lower end is P + L u.
!! * Generalized coordinates of one gear (9):
!!     q = (d1, th1, th2, db1, thb1, thb2, dc1, thc1, thc2)
!!   primary length and universal-joint angles; left secondary (b -> e) length and angles; right
!!   secondary (c -> f) length and angles. Then
!!     d = a + d1 u_p,  e_pri = a + Rp e_loc,  f_pri = a + Rp f_loc,  Rp = R0p rot_x(th1) rot_y(th2)
!!     e_sec = b + db1 u_b,  f_sec = c + dc1 u_c
!!   with e_loc, f_loc the lugs' positions relative to a in the primary's nominal frame. At
!!   q0 = (L0,0,0, Lb0,0,0, Lc0,0,0) all points are the nominal hard points.
!! * Footpad Jacobian (eq. 7): footpad velocity in the gear frame = J (d1_dot, db1_dot, dc1_dot),
!!   J = J2 J3^{-1}, J2 = d(d)/d(d1,th1,th2), J3 = d(d1,db1,dc1)/d(d1,th1,th2) with
!!   db1 = |e_pri - b|, dc1 = |f_pri - c|.
!! * The tripod's constraints (eq. 6), their Jacobian and gamma (eq. 16) and the force maps of the
!!   virtual work (eq. 8) are in physics/landyn_tripod_kinematics.f90.
!!
!! Everything here is pure and allocation-free (fixed-size arrays) for use in the time-step loop.
module landyn_kinematics
  use landyn_kinds, only: wp
  use landyn_status, only: STAT_FAILED, status_t
  implicit none
  private

  ! --- small linear algebra
  public :: cross3, det3, inv3, solve3, mv3, mtv3
  ! --- rotations, attitude and transforms
  public :: rot_x, rot_y, rot_z, rot_zyx, euler_zyx_from_matrix
  public :: euler_rate_matrix
  public :: body_point_velocity
  ! --- gear frames and geometry
  public :: gear_geometry_t, build_gear_geometry, footpad_jacobians
  ! --- strut kinematics
  public :: strut_axis, strut_axis_derivs
  public :: joint_trig_t, joint_trig, strut_axis_derivs_trig, axis_derivs_t
  public :: strut_orientation_trig, strut_axis_trig, joint_rotation_derivs
  public :: strut_angles_from_point
  ! --- coordinate indices and sizes
  public :: n_gear_q, n_gear_phi
  public :: iq_d1, iq_th1, iq_th2, iq_db1, iq_thb1, iq_thb2, iq_dc1, iq_thc1, iq_thc2

  integer, parameter :: n_gear_q = 9     !! generalized coordinates per gear [-]
  integer, parameter :: n_gear_phi = 6   !! constraint equations per gear [-]
  ! Positions in q of:
  integer, parameter :: iq_d1 = 1        !! primary strut length [m]
  integer, parameter :: iq_th1 = 2       !! primary universal-joint angle about x0 [rad]
  integer, parameter :: iq_th2 = 3       !! primary universal-joint angle about the rotated y0 [rad]
  integer, parameter :: iq_db1 = 4       !! left secondary (b -> e) length [m]
  integer, parameter :: iq_thb1 = 5      !! left secondary angle 1 [rad]
  integer, parameter :: iq_thb2 = 6      !! left secondary angle 2 [rad]
  integer, parameter :: iq_dc1 = 7       !! right secondary (c -> f) length [m]
  integer, parameter :: iq_thc1 = 8      !! right secondary angle 1 [rad]
  integer, parameter :: iq_thc2 = 9      !! right secondary angle 2 [rad]

  !> A 3x3 matrix A is treated as singular when |det A| <= singular_tol * ||A||_F^3 (a crude,
  !! scale-free reciprocal condition number; it also catches a row that is zero up to round-off) [-].
  real(wp), parameter :: singular_tol = 1.0e-10_wp

  !> Relative tolerance for coincident hard points (times the largest hard-point distance) [-].
  real(wp), parameter :: coincident_tol = 1.0e-9_wp

  !> |ey x z0| below which ex replaces ey in building a nominal strut frame [-].
  real(wp), parameter :: parallel_tol = 1.0e-2_wp

  !> cos and sin of the two universal-joint angles of one strut at one configuration (`joint_trig`).
  !! Computed once and passed to the routines that need them (their `_trig` forms and the optional
  !! `trig` arguments): cos and sin give the same bits however often they are called, so every
  !! result is the same to the last bit as from the angles themselves.
  type :: joint_trig_t
    real(wp) :: c1 = 1.0_wp  !! cos t1 [-]
    real(wp) :: s1 = 0.0_wp  !! sin t1 [-]
    real(wp) :: c2 = 1.0_wp  !! cos t2 [-]
    real(wp) :: s2 = 0.0_wp  !! sin t2 [-]
  end type joint_trig_t

  !> A strut's unit axis and its partials with respect to its joint angles at one configuration
  !! (the outputs of `strut_axis_derivs`).
  type :: axis_derivs_t
    real(wp) :: u(3) = 0.0_wp     !! unit axis [-]
    real(wp) :: u1(3) = 0.0_wp    !! du/dt1 [1/rad]
    real(wp) :: u2(3) = 0.0_wp    !! du/dt2 [1/rad]
    real(wp) :: u11(3) = 0.0_wp   !! d2u/dt1^2 [1/rad^2]
    real(wp) :: u12(3) = 0.0_wp   !! d2u/dt1 dt2 [1/rad^2]
    real(wp) :: u22(3) = 0.0_wp   !! d2u/dt2^2 [1/rad^2]
  end type axis_derivs_t

  !> Geometry of one landing gear in its own gear frame, built once by `build_gear_geometry`.
  type :: gear_geometry_t
    real(wp) :: a(3) = 0.0_wp         !! primary strut upper universal joint, gear frame [m]
    real(wp) :: b(3) = 0.0_wp         !! left secondary upper universal joint, gear frame [m]
    real(wp) :: c(3) = 0.0_wp         !! right secondary upper universal joint, gear frame [m]
    real(wp) :: L0 = 0.0_wp           !! nominal primary length |d - a| [m]
    real(wp) :: Lb0 = 0.0_wp          !! nominal left secondary length |e - b| [m]
    real(wp) :: Lc0 = 0.0_wp          !! nominal right secondary length |f - c| [m]
    real(wp) :: R0p(3,3) = 0.0_wp     !! nominal frame of the primary strut (columns x0,y0,z0 in the gear frame) [-]
    real(wp) :: R0b(3,3) = 0.0_wp     !! nominal frame of the left secondary [-]
    real(wp) :: R0c(3,3) = 0.0_wp     !! nominal frame of the right secondary [-]
    real(wp) :: e_loc(3) = 0.0_wp     !! e - a in the primary's nominal frame (lug of the left secondary) [m]
    real(wp) :: f_loc(3) = 0.0_wp     !! f - a in the primary's nominal frame (lug of the right secondary) [m]
    real(wp) :: q0(n_gear_q) = 0.0_wp !! nominal generalized coordinates (L0,0,0, Lb0,0,0, Lc0,0,0) [m, rad]
  end type gear_geometry_t

contains

  ! =====================================================================================
  ! Small linear algebra
  ! =====================================================================================

  !> Cross product a x b.
  pure function cross3(a, b) result(c)
    real(wp), intent(in) :: a(3)  !! first vector [any unit]
    real(wp), intent(in) :: b(3)  !! second vector [any unit]
    real(wp) :: c(3)              !! a x b [unit(a) unit(b)]
    c(1) = a(2)*b(3) - a(3)*b(2)
    c(2) = a(3)*b(1) - a(1)*b(3)
    c(3) = a(1)*b(2) - a(2)*b(1)
  end function cross3

  !> Matrix-vector product a x for 3x3 a, written out (the inner loop calls it; gfortran would
  !! otherwise call its library matmul for component and transposed arguments).
  pure function mv3(a, x) result(y)
    real(wp), intent(in) :: a(3,3)  !! matrix [any unit]
    real(wp), intent(in) :: x(3)    !! vector [any unit]
    real(wp) :: y(3)                !! a x [unit(a) unit(x)]
    y(1) = a(1,1)*x(1) + a(1,2)*x(2) + a(1,3)*x(3)
    y(2) = a(2,1)*x(1) + a(2,2)*x(2) + a(2,3)*x(3)
    y(3) = a(3,1)*x(1) + a(3,2)*x(2) + a(3,3)*x(3)
  end function mv3

  !> Transposed matrix-vector product a^T x for 3x3 a, written out.
  pure function mtv3(a, x) result(y)
    real(wp), intent(in) :: a(3,3)  !! matrix [any unit]
    real(wp), intent(in) :: x(3)    !! vector [any unit]
    real(wp) :: y(3)                !! a^T x [unit(a) unit(x)]
    y(1) = a(1,1)*x(1) + a(2,1)*x(2) + a(3,1)*x(3)
    y(2) = a(1,2)*x(1) + a(2,2)*x(2) + a(3,2)*x(3)
    y(3) = a(1,3)*x(1) + a(2,3)*x(2) + a(3,3)*x(3)
  end function mtv3

  !> Euclidean norm of a 3-vector.
  pure function norm3(v) result(n)
    real(wp), intent(in) :: v(3)  !! vector [any unit]
    real(wp) :: n                 !! |v| [unit(v)]
    n = sqrt(v(1)**2 + v(2)**2 + v(3)**2)
  end function norm3

  !> Determinant of a 3x3 matrix.
  pure function det3(a) result(d)
    real(wp), intent(in) :: a(3,3)  !! matrix [any unit]
    real(wp) :: d                   !! det(a) [unit(a)^3]
    d = a(1,1)*(a(2,2)*a(3,3) - a(2,3)*a(3,2)) &
      - a(1,2)*(a(2,1)*a(3,3) - a(2,3)*a(3,1)) &
      + a(1,3)*(a(2,1)*a(3,2) - a(2,2)*a(3,1))
  end function det3

  !> Singularity test of a 3x3 matrix with determinant d: |d| <= singular_tol * ||a||_F^3.
  pure function is_singular3(a, d) result(yes)
    real(wp), intent(in) :: a(3,3)  !! matrix [any unit]
    real(wp), intent(in) :: d       !! its determinant [unit(a)^3]
    logical :: yes                  !! .true. when a is numerically singular
    real(wp) :: fro2
    fro2 = sum(a**2)
    yes = .not. (abs(d) > singular_tol*fro2*sqrt(fro2))
  end function is_singular3

  !> Inverse of a 3x3 matrix in closed form (adjugate / determinant), with a scale-free
  !! singularity check (see `singular_tol`).
  pure subroutine inv3(a, ainv, status)
    real(wp), intent(in) :: a(3,3)           !! matrix [any unit]
    real(wp), intent(out) :: ainv(3,3)       !! inverse of a [1/unit(a)]; zero when singular
    type(status_t), intent(out) :: status    !! STAT_OK, or STAT_FAILED when a is singular [-]
    real(wp) :: adj(3,3), d
    adj(1,1) = a(2,2)*a(3,3) - a(2,3)*a(3,2)
    adj(1,2) = a(1,3)*a(3,2) - a(1,2)*a(3,3)
    adj(1,3) = a(1,2)*a(2,3) - a(1,3)*a(2,2)
    adj(2,1) = a(2,3)*a(3,1) - a(2,1)*a(3,3)
    adj(2,2) = a(1,1)*a(3,3) - a(1,3)*a(3,1)
    adj(2,3) = a(1,3)*a(2,1) - a(1,1)*a(2,3)
    adj(3,1) = a(2,1)*a(3,2) - a(2,2)*a(3,1)
    adj(3,2) = a(1,2)*a(3,1) - a(1,1)*a(3,2)
    adj(3,3) = a(1,1)*a(2,2) - a(1,2)*a(2,1)
    d = a(1,1)*adj(1,1) + a(1,2)*adj(2,1) + a(1,3)*adj(3,1)
    if (is_singular3(a, d)) then
      ainv = 0.0_wp
      call status%fail(STAT_FAILED, 'inv3: singular 3x3 matrix')
      return
    end if
    ainv = adj/d
  end subroutine inv3

  !> Solve a x = rhs for a 3x3 matrix by Cramer's rule, with the singularity check of `inv3`.
  pure subroutine solve3(a, rhs, x, status)
    real(wp), intent(in) :: a(3,3)           !! matrix [any unit]
    real(wp), intent(in) :: rhs(3)           !! right-hand side [any unit]
    real(wp), intent(out) :: x(3)            !! solution [unit(rhs)/unit(a)]; zero when singular
    type(status_t), intent(out) :: status    !! STAT_OK, or STAT_FAILED when a is singular [-]
    real(wp) :: d, m(3,3)
    integer :: k
    d = det3(a)
    if (is_singular3(a, d)) then
      x = 0.0_wp
      call status%fail(STAT_FAILED, 'solve3: singular 3x3 matrix')
      return
    end if
    do k = 1, 3
      m = a
      m(:,k) = rhs
      x(k) = det3(m)/d
    end do
  end subroutine solve3

  ! =====================================================================================
  ! Rotations, attitude, transforms
  ! =====================================================================================

  !> cos and sin of an angle, with values within 4 ulp of zero set to exactly 0 (and the other
  !! to exactly +-1): rotations by multiples of 90 deg are then exact, so a lander built by
  !! rotating gear 1 is symmetric to the last bit and a symmetric landing stays symmetric.
  pure subroutine exact_sincos(ang, c, s)
    real(wp), intent(in) :: ang   !! angle [rad]
    real(wp), intent(out) :: c    !! cos(ang) [-]
    real(wp), intent(out) :: s    !! sin(ang) [-]
    real(wp), parameter :: tiny_trig = 4.0_wp*epsilon(1.0_wp)
    c = cos(ang); s = sin(ang)
    if (abs(c) < tiny_trig) then
      c = 0.0_wp
      s = sign(1.0_wp, s)
    else if (abs(s) < tiny_trig) then
      s = 0.0_wp
      c = sign(1.0_wp, c)
    end if
  end subroutine exact_sincos

  !> Elementary rotation about x: [[1,0,0],[0,c,-s],[0,s,c]].
  pure function rot_x(ang) result(r)
    real(wp), intent(in) :: ang  !! rotation angle [rad]
    real(wp) :: r(3,3)           !! rotation matrix [-]
    real(wp) :: c, s
    call exact_sincos(ang, c, s)
    r(1,1) = 1.0_wp; r(1,2) = 0.0_wp; r(1,3) = 0.0_wp
    r(2,1) = 0.0_wp; r(2,2) = c;      r(2,3) = -s
    r(3,1) = 0.0_wp; r(3,2) = s;      r(3,3) = c
  end function rot_x

  !> Elementary rotation about y: [[c,0,s],[0,1,0],[-s,0,c]] (standard right-handed; the paper's
  !! printed R_y has the sign of sin transposed).
  pure function rot_y(ang) result(r)
    real(wp), intent(in) :: ang  !! rotation angle [rad]
    real(wp) :: r(3,3)           !! rotation matrix [-]
    real(wp) :: c, s
    call exact_sincos(ang, c, s)
    r(1,1) = c;      r(1,2) = 0.0_wp; r(1,3) = s
    r(2,1) = 0.0_wp; r(2,2) = 1.0_wp; r(2,3) = 0.0_wp
    r(3,1) = -s;     r(3,2) = 0.0_wp; r(3,3) = c
  end function rot_y

  !> Elementary rotation about z: [[c,-s,0],[s,c,0],[0,0,1]].
  pure function rot_z(ang) result(r)
    real(wp), intent(in) :: ang  !! rotation angle [rad]
    real(wp) :: r(3,3)           !! rotation matrix [-]
    real(wp) :: c, s
    call exact_sincos(ang, c, s)
    r(1,1) = c;      r(1,2) = -s;     r(1,3) = 0.0_wp
    r(2,1) = s;      r(2,2) = c;      r(2,3) = 0.0_wp
    r(3,1) = 0.0_wp; r(3,2) = 0.0_wp; r(3,3) = 1.0_wp
  end function rot_z

  !> Body-to-global rotation of Z-Y-X Euler angles: R = rot_z(psi) rot_y(theta) rot_x(phi).
  pure function rot_zyx(psi, theta, phi) result(r)
    real(wp), intent(in) :: psi    !! yaw [rad]
    real(wp), intent(in) :: theta  !! pitch [rad]
    real(wp), intent(in) :: phi    !! roll [rad]
    real(wp) :: r(3,3)             !! body-to-global rotation [-]
    real(wp) :: cps, sps, cth, sth, cph, sph
    cps = cos(psi); sps = sin(psi)
    cth = cos(theta); sth = sin(theta)
    cph = cos(phi); sph = sin(phi)
    r(1,1) = cth*cps
    r(2,1) = cth*sps
    r(3,1) = -sth
    r(1,2) = sph*sth*cps - cph*sps
    r(2,2) = sph*sth*sps + cph*cps
    r(3,2) = sph*cth
    r(1,3) = cph*sth*cps + sph*sps
    r(2,3) = cph*sth*sps - sph*cps
    r(3,3) = cph*cth
  end function rot_zyx

  !> Z-Y-X Euler angles of a rotation matrix, R = rot_z(psi) rot_y(theta) rot_x(phi).
  !! theta in [-pi/2, pi/2]; at gimbal lock (cos theta = 0) phi is set to 0.
  pure subroutine euler_zyx_from_matrix(r, psi, theta, phi)
    real(wp), intent(in) :: r(3,3)   !! body-to-global rotation [-]
    real(wp), intent(out) :: psi     !! yaw in (-pi, pi] [rad]
    real(wp), intent(out) :: theta   !! pitch in [-pi/2, pi/2] [rad]
    real(wp), intent(out) :: phi     !! roll in (-pi, pi] [rad]
    real(wp) :: cth
    cth = sqrt(r(1,1)**2 + r(2,1)**2)
    theta = atan2(-r(3,1), cth)
    if (cth > 1.0e-12_wp) then
      psi = atan2(r(2,1), r(1,1))
      phi = atan2(r(3,2), r(3,3))
    else
      phi = 0.0_wp
      psi = atan2(-r(1,2), r(2,2))
    end if
  end subroutine euler_zyx_from_matrix

  !> Euler-rate matrix E (eq. 10): [psi_dot, theta_dot, phi_dot] = E [p, q, r].
  !! Requires cos(theta) /= 0.
  pure function euler_rate_matrix(theta, phi) result(e)
    real(wp), intent(in) :: theta  !! pitch [rad], |theta| < pi/2
    real(wp), intent(in) :: phi    !! roll [rad]
    real(wp) :: e(3,3)             !! Euler-rate matrix [-]
    real(wp) :: cth, sth, cph, sph
    cth = cos(theta); sth = sin(theta)
    cph = cos(phi); sph = sin(phi)
    e(1,1) = 0.0_wp; e(1,2) = sph/cth;     e(1,3) = cph/cth
    e(2,1) = 0.0_wp; e(2,2) = cph;         e(2,3) = -sph
    e(3,1) = 1.0_wp; e(3,2) = sph*sth/cth; e(3,3) = cph*sth/cth
  end function euler_rate_matrix

  !> Global velocity of a point fixed in the lander: v_O + R (omega_body x p_L).
  pure function body_point_velocity(v_o, r, omega_body, p_l) result(v)
    real(wp), intent(in) :: v_o(3)         !! velocity of O_L in the global frame [m/s]
    real(wp), intent(in) :: r(3,3)         !! body-to-global rotation [-]
    real(wp), intent(in) :: omega_body(3)  !! angular velocity (p, q, r) in lander axes [rad/s]
    real(wp), intent(in) :: p_l(3)         !! point in the lander frame [m]
    real(wp) :: v(3)                       !! velocity of the point in the global frame [m/s]
    real(wp) :: w(3)
    w = cross3(omega_body, p_l)
    v = v_o + matmul(r, w)
  end function body_point_velocity

  ! =====================================================================================
  ! Gear frames and geometry
  ! =====================================================================================

  !> Nominal frame of a strut from its unit axis z0 (see module header).
  pure function strut_frame(z0) result(r0)
    real(wp), intent(in) :: z0(3)  !! unit vector along the strut, upper -> lower joint [-]
    real(wp) :: r0(3,3)            !! nominal strut frame, columns x0, y0, z0 [-]
    real(wp), parameter :: ex(3) = [1.0_wp, 0.0_wp, 0.0_wp], ey(3) = [0.0_wp, 1.0_wp, 0.0_wp]
    real(wp) :: x0(3)
    x0 = cross3(ey, z0)
    if (norm3(x0) < parallel_tol) x0 = cross3(ex, z0)
    x0 = x0/norm3(x0)
    r0(:,1) = x0
    r0(:,2) = cross3(z0, x0)
    r0(:,3) = z0
  end function strut_frame

  !> Build the geometry of one gear from its six hard points, given in the GEAR frame at the
  !! nominal (uncrushed) configuration. Rejects zero-length struts, coincident points and a
  !! gear whose footpad Jacobian is singular at the nominal configuration.
  pure subroutine build_gear_geometry(a, b, c, d, e, f, geom, status)
    real(wp), intent(in) :: a(3)                  !! primary upper universal joint [m]
    real(wp), intent(in) :: b(3)                  !! left secondary upper universal joint [m]
    real(wp), intent(in) :: c(3)                  !! right secondary upper universal joint [m]
    real(wp), intent(in) :: d(3)                  !! footpad ball joint (primary lower end) [m]
    real(wp), intent(in) :: e(3)                  !! left secondary lower joint on the primary [m]
    real(wp), intent(in) :: f(3)                  !! right secondary lower joint on the primary [m]
    type(gear_geometry_t), intent(out) :: geom    !! gear geometry
    type(status_t), intent(out) :: status         !! STAT_OK, or STAT_FAILED on degenerate geometry [-]
    character(len=1), parameter :: names(6) = ['a', 'b', 'c', 'd', 'e', 'f']
    real(wp) :: pts(3,6), scale, tol, j2(3,3), j3(3,3), jj(3,3)
    integer :: i, k

    pts(:,1) = a; pts(:,2) = b; pts(:,3) = c
    pts(:,4) = d; pts(:,5) = e; pts(:,6) = f
    scale = 0.0_wp
    do i = 1, 5
      do k = i + 1, 6
        scale = max(scale, norm3(pts(:,k) - pts(:,i)))
      end do
    end do
    if (.not. (scale > 0.0_wp)) then
      call status%fail(STAT_FAILED, 'build_gear_geometry: all hard points coincide')
      return
    end if
    tol = coincident_tol*scale
    do i = 1, 5
      do k = i + 1, 6
        if (norm3(pts(:,k) - pts(:,i)) <= tol) then
          call status%fail(STAT_FAILED, 'build_gear_geometry: hard points ' // names(i) // ' and ' // names(k) // &
                           ' coincide (zero-length strut or degenerate gear)')
          return
        end if
      end do
    end do

    geom%a = a
    geom%b = b
    geom%c = c
    geom%L0 = norm3(d - a)
    geom%Lb0 = norm3(e - b)
    geom%Lc0 = norm3(f - c)
    geom%R0p = strut_frame((d - a)/geom%L0)
    geom%R0b = strut_frame((e - b)/geom%Lb0)
    geom%R0c = strut_frame((f - c)/geom%Lc0)
    geom%e_loc = matmul(transpose(geom%R0p), e - a)
    geom%f_loc = matmul(transpose(geom%R0p), f - a)
    geom%q0 = 0.0_wp
    geom%q0(iq_d1) = geom%L0
    geom%q0(iq_db1) = geom%Lb0
    geom%q0(iq_dc1) = geom%Lc0

    call footpad_jacobians(geom, geom%q0, j2, j3, jj, status)
    if (.not. status%ok()) then
      call status%fail(status%code, 'build_gear_geometry: the gear is not a rigid structure at the nominal ' // &
                       'configuration (singular footpad Jacobian)')
      return
    end if
  end subroutine build_gear_geometry

  !> Footpad Jacobians of eq. 7 at the primary coordinates (d1, th1, th2) of q (the secondary
  !! entries of q are not used): J2 = d(d)/d(d1,th1,th2), J3 = d(d1,db1,dc1)/d(d1,th1,th2) with
  !! db1 = |e_pri - b|, dc1 = |f_pri - c|, and J = J2 J3^{-1} (strut length rates -> footpad
  !! velocity, gear frame). STAT_FAILED when J3 or J2 is singular (J is then zero).
  pure subroutine footpad_jacobians(geom, q, j2, j3, j, status)
    type(gear_geometry_t), intent(in) :: geom  !! gear geometry
    real(wp), intent(in) :: q(n_gear_q)        !! generalized coordinates [m, rad]
    real(wp), intent(out) :: j2(3,3)           !! d(d)/d(d1,th1,th2) [-, m/rad]
    real(wp), intent(out) :: j3(3,3)           !! d(d1,db1,dc1)/d(d1,th1,th2) [-, m/rad]
    real(wp), intent(out) :: j(3,3)            !! J2 J3^{-1} [-]
    type(status_t), intent(out) :: status      !! STAT_OK, or STAT_FAILED when J2 or J3 is singular [-]
    real(wp) :: w(3,3), w1(3,3), w2(3,3), w11(3,3), w12(3,3), w22(3,3), rp(3,3)
    real(wp) :: u(3), u1(3), u2(3), u11(3), u12(3), u22(3)
    real(wp) :: r(3), lr, j3inv(3,3), d1
    type(joint_trig_t) :: tp

    d1 = q(iq_d1)
    tp = joint_trig(q(iq_th1), q(iq_th2))
    call strut_axis_derivs_trig(geom%R0p, tp, u, u1, u2, u11, u12, u22)
    j2(:,1) = u
    j2(:,2) = d1*u1
    j2(:,3) = d1*u2

    call joint_rotation_derivs(tp, w, w1, w2, w11, w12, w22)
    rp = matmul(geom%R0p, w)
    j3(1,:) = [1.0_wp, 0.0_wp, 0.0_wp]
    r = geom%a + matmul(rp, geom%e_loc) - geom%b
    lr = norm3(r)
    j3(2,1) = 0.0_wp
    j3(2,2) = dot_product(r, matmul(geom%R0p, matmul(w1, geom%e_loc)))/lr
    j3(2,3) = dot_product(r, matmul(geom%R0p, matmul(w2, geom%e_loc)))/lr
    r = geom%a + matmul(rp, geom%f_loc) - geom%c
    lr = norm3(r)
    j3(3,1) = 0.0_wp
    j3(3,2) = dot_product(r, matmul(geom%R0p, matmul(w1, geom%f_loc)))/lr
    j3(3,3) = dot_product(r, matmul(geom%R0p, matmul(w2, geom%f_loc)))/lr

    call inv3(j3, j3inv, status)
    if (.not. status%ok()) then
      j = 0.0_wp
      call status%fail(status%code, 'footpad_jacobians: J3 is singular (secondary struts cannot fix the primary)')
      return
    end if
    if (is_singular3(j2, det3(j2))) then
      j = 0.0_wp
      call status%fail(STAT_FAILED, 'footpad_jacobians: J2 is singular (zero primary length or th2 = +-pi/2)')
      return
    end if
    j = matmul(j2, j3inv)
  end subroutine footpad_jacobians

  ! =====================================================================================
  ! Strut kinematics
  ! =====================================================================================

  !> cos and sin of a strut's joint angles (t1, t2), for the `_trig` routines.
  pure function joint_trig(t1, t2) result(tr)
    real(wp), intent(in) :: t1       !! first joint angle (about x0) [rad]
    real(wp), intent(in) :: t2       !! second joint angle (about rotated y) [rad]
    type(joint_trig_t) :: tr         !! cos and sin of t1 and t2 [-]
    tr%c1 = cos(t1); tr%s1 = sin(t1); tr%c2 = cos(t2); tr%s2 = sin(t2)
  end function joint_trig

  !> Local universal-joint rotation W = rot_x(t1) rot_y(t2) and its first and second partials,
  !! from cos and sin of (t1, t2).
  pure subroutine joint_rotation_derivs(tr, w, w1, w2, w11, w12, w22)
    type(joint_trig_t), intent(in) :: tr  !! cos and sin of the joint angles [-]
    real(wp), intent(out) :: w(3,3)    !! rot_x(t1) rot_y(t2) [-]
    real(wp), intent(out) :: w1(3,3)   !! dW/dt1 [1/rad]
    real(wp), intent(out) :: w2(3,3)   !! dW/dt2 [1/rad]
    real(wp), intent(out) :: w11(3,3)  !! d2W/dt1^2 [1/rad^2]
    real(wp), intent(out) :: w12(3,3)  !! d2W/dt1dt2 [1/rad^2]
    real(wp), intent(out) :: w22(3,3)  !! d2W/dt2^2 [1/rad^2]
    real(wp) :: c1, s1, c2, s2
    c1 = tr%c1; s1 = tr%s1; c2 = tr%c2; s2 = tr%s2
    w(1,:) = [c2, 0.0_wp, s2]
    w(2,:) = [s1*s2, c1, -s1*c2]
    w(3,:) = [-c1*s2, s1, c1*c2]
    w1(1,:) = 0.0_wp
    w1(2,:) = [c1*s2, -s1, -c1*c2]
    w1(3,:) = [s1*s2, c1, -s1*c2]
    w2(1,:) = [-s2, 0.0_wp, c2]
    w2(2,:) = [s1*c2, 0.0_wp, s1*s2]
    w2(3,:) = [-c1*c2, 0.0_wp, -c1*s2]
    w11(1,:) = 0.0_wp
    w11(2,:) = -w(2,:)
    w11(3,:) = -w(3,:)
    w12(1,:) = 0.0_wp
    w12(2,:) = [c1*c2, 0.0_wp, c1*s2]
    w12(3,:) = [s1*c2, 0.0_wp, s1*s2]
    w22(1,:) = -w(1,:)
    w22(2,:) = [-s1*s2, 0.0_wp, s1*c2]
    w22(3,:) = [c1*s2, 0.0_wp, -c1*c2]
  end subroutine joint_rotation_derivs

  !> Orientation of a strut, R = R0 rot_x(t1) rot_y(t2), from cos and sin of its joint angles
  !! (joint_trig(t1, t2)).
  pure function strut_orientation_trig(r0, tr) result(r)
    real(wp), intent(in) :: r0(3,3)          !! nominal strut frame [-]
    type(joint_trig_t), intent(in) :: tr     !! cos and sin of the joint angles [-]
    real(wp) :: r(3,3)                       !! strut orientation in the gear frame [-]
    real(wp) :: w(3,3), c1, s1, c2, s2
    c1 = tr%c1; s1 = tr%s1; c2 = tr%c2; s2 = tr%s2
    w(1,:) = [c2, 0.0_wp, s2]
    w(2,:) = [s1*s2, c1, -s1*c2]
    w(3,:) = [-c1*s2, s1, c1*c2]
    r = matmul(r0, w)
  end function strut_orientation_trig

  !> Unit axis of a strut: u = R0 (sin t2, -sin t1 cos t2, cos t1 cos t2).
  pure function strut_axis(r0, t1, t2) result(u)
    real(wp), intent(in) :: r0(3,3)  !! nominal strut frame [-]
    real(wp), intent(in) :: t1       !! first joint angle [rad]
    real(wp), intent(in) :: t2       !! second joint angle [rad]
    real(wp) :: u(3)                 !! unit vector upper -> lower joint, gear frame [-]
    u = strut_axis_trig(r0, joint_trig(t1, t2))
  end function strut_axis

  !> strut_axis from cos and sin of the joint angles.
  pure function strut_axis_trig(r0, tr) result(u)
    real(wp), intent(in) :: r0(3,3)          !! nominal strut frame [-]
    type(joint_trig_t), intent(in) :: tr     !! cos and sin of the joint angles [-]
    real(wp) :: u(3)                         !! unit vector upper -> lower joint, gear frame [-]
    real(wp) :: c1, s1, c2, s2
    c1 = tr%c1; s1 = tr%s1; c2 = tr%c2; s2 = tr%s2
    u = matmul(r0, [s2, -s1*c2, c1*c2])
  end function strut_axis_trig

  !> Strut axis and its first and second partial derivatives with respect to (t1, t2).
  pure subroutine strut_axis_derivs(r0, t1, t2, u, u1, u2, u11, u12, u22)
    real(wp), intent(in) :: r0(3,3)   !! nominal strut frame [-]
    real(wp), intent(in) :: t1        !! first joint angle [rad]
    real(wp), intent(in) :: t2        !! second joint angle [rad]
    real(wp), intent(out) :: u(3)     !! unit axis [-]
    real(wp), intent(out) :: u1(3)    !! du/dt1 [1/rad]
    real(wp), intent(out) :: u2(3)    !! du/dt2 [1/rad]
    real(wp), intent(out) :: u11(3)   !! d2u/dt1^2 [1/rad^2]
    real(wp), intent(out) :: u12(3)   !! d2u/dt1dt2 [1/rad^2]
    real(wp), intent(out) :: u22(3)   !! d2u/dt2^2 (= -u) [1/rad^2]
    call strut_axis_derivs_trig(r0, joint_trig(t1, t2), u, u1, u2, u11, u12, u22)
  end subroutine strut_axis_derivs

  !> strut_axis_derivs from cos and sin of the joint angles (the same values, bit for bit).
  pure subroutine strut_axis_derivs_trig(r0, tr, u, u1, u2, u11, u12, u22)
    real(wp), intent(in) :: r0(3,3)          !! nominal strut frame [-]
    type(joint_trig_t), intent(in) :: tr     !! cos and sin of the joint angles [-]
    real(wp), intent(out) :: u(3)     !! unit axis [-]
    real(wp), intent(out) :: u1(3)    !! du/dt1 [1/rad]
    real(wp), intent(out) :: u2(3)    !! du/dt2 [1/rad]
    real(wp), intent(out) :: u11(3)   !! d2u/dt1^2 [1/rad^2]
    real(wp), intent(out) :: u12(3)   !! d2u/dt1dt2 [1/rad^2]
    real(wp), intent(out) :: u22(3)   !! d2u/dt2^2 (= -u) [1/rad^2]
    real(wp) :: c1, s1, c2, s2
    c1 = tr%c1; s1 = tr%s1; c2 = tr%c2; s2 = tr%s2
    u = matmul(r0, [s2, -s1*c2, c1*c2])
    u1 = matmul(r0, [0.0_wp, -c1*c2, -s1*c2])
    u2 = matmul(r0, [c2, s1*s2, -c1*s2])
    u11 = matmul(r0, [0.0_wp, s1*c2, -c1*c2])
    u12 = matmul(r0, [0.0_wp, c1*s2, s1*s2])
    u22 = -u
  end subroutine strut_axis_derivs_trig

  !> Length and joint angles of a strut from its upper joint P to a point X (closed form):
  !! L = |X - P|, u = R0^T (X - P)/L, t2 = asin(u1), t1 = atan2(-u2, u3). When X = P the
  !! angles are returned as 0.
  pure subroutine strut_angles_from_point(p, r0, x, length, t1, t2)
    real(wp), intent(in) :: p(3)      !! upper joint, gear frame [m]
    real(wp), intent(in) :: r0(3,3)   !! nominal strut frame [-]
    real(wp), intent(in) :: x(3)      !! lower end, gear frame [m]
    real(wp), intent(out) :: length   !! strut length [m]
    real(wp), intent(out) :: t1       !! first joint angle in (-pi, pi] [rad]
    real(wp), intent(out) :: t2       !! second joint angle in [-pi/2, pi/2] [rad]
    real(wp) :: v(3)
    v = x - p
    length = norm3(v)
    if (.not. (length > 0.0_wp)) then
      t1 = 0.0_wp
      t2 = 0.0_wp
      return
    end if
    v = matmul(transpose(r0), v)/length
    t2 = asin(max(-1.0_wp, min(1.0_wp, v(1))))
    t1 = atan2(-v(2), v(3))
  end subroutine strut_angles_from_point

end module landyn_kinematics
