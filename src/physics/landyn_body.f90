!> Six-degree-of-freedom rigid lander body with mass-centre offset (paper section 2.3, eqs. 9-11).
!!
!! State: mass-centre position and velocity in the global frame (z down), Z-Y-X Euler angles
!! (psi, theta, phi) and body angular rates (p, q, r) about the lander axes. Translation is
!! integrated in the global frame, which is eq. 9's body-frame form (u, v, w with the omega x v
!! terms) transformed by eq. 10's R; rotation uses Euler's equations with the full inertia tensor
!! about the mass centre, I omega_dot = M - omega x (I omega) (eq. 9, lower half), and the Euler
!! angles advance with eq. 10's rate transform. Integration is semi-implicit Euler (velocities
!! first, then positions with the new velocities), the "direct integration" of the paper.
module landyn_body
  use landyn_kinds, only: wp
  use landyn_kinematics, only: rot_zyx, euler_rate_matrix, cross3, mv3, mtv3, det3, inv3
  use landyn_status, only: STAT_FAILED, status_t
  implicit none
  private

  public :: body_t, body_init, body_accelerations, body_increment
  public :: body_point_position, body_point_velocity, body_point_acceleration
  public :: body_kinetic_energy, inertia_tensor

  !> The lander body.
  type :: body_t
    real(wp) :: mass = 0.0_wp              !! total mass [kg]
    real(wp) :: inertia(3, 3) = 0.0_wp     !! inertia tensor about the mass centre, lander axes [kg m^2]
    real(wp) :: inv_inertia(3, 3) = 0.0_wp !! its inverse [1/(kg m^2)]
    real(wp) :: mc(3) = 0.0_wp             !! mass centre in the lander frame [m]
    real(wp) :: x(3) = 0.0_wp              !! mass-centre position, global [m]
    real(wp) :: v(3) = 0.0_wp              !! mass-centre velocity, global [m/s]
    real(wp) :: euler(3) = 0.0_wp          !! Z-Y-X Euler angles psi, theta, phi [rad]
    real(wp) :: omega(3) = 0.0_wp          !! body angular rate p, q, r (lander axes) [rad/s]
    real(wp) :: acc(3) = 0.0_wp            !! mass-centre acceleration, global [m/s^2]
    real(wp) :: alpha(3) = 0.0_wp          !! angular acceleration, lander axes [rad/s^2]
    real(wp) :: r(3, 3) = 0.0_wp           !! lander -> global rotation for the current attitude [-]
  end type body_t

contains

  !> Inertia tensor from moments and products of inertia (products are integral(x y dm) etc.).
  pure function inertia_tensor(ixx, iyy, izz, ixy, ixz, iyz) result(t)
    real(wp), intent(in) :: ixx, iyy, izz   !! moments of inertia [kg m^2]
    real(wp), intent(in) :: ixy, ixz, iyz   !! products of inertia [kg m^2]
    real(wp) :: t(3, 3)                     !! tensor [kg m^2]
    t = reshape([ixx, -ixy, -ixz, -ixy, iyy, -iyz, -ixz, -iyz, izz], [3, 3])
  end function inertia_tensor

  !> Initialises the body. x_ol is the lander-frame origin in the global frame; v is the
  !! mass-centre velocity.
  subroutine body_init(body, mass, inertia, mc, x_ol, v, euler, omega, status)
    type(body_t), intent(out) :: body          !! body
    real(wp), intent(in) :: mass               !! mass [kg]
    real(wp), intent(in) :: inertia(3, 3)      !! inertia tensor about the mass centre [kg m^2]
    real(wp), intent(in) :: mc(3)              !! mass centre, lander frame [m]
    real(wp), intent(in) :: x_ol(3)            !! lander origin, global [m]
    real(wp), intent(in) :: v(3)               !! mass-centre velocity, global [m/s]
    real(wp), intent(in) :: euler(3)           !! Z-Y-X Euler angles [rad]
    real(wp), intent(in) :: omega(3)           !! body rates [rad/s]
    type(status_t), intent(out) :: status      !! STAT_OK, or STAT_FAILED with the reason [-]
    real(wp) :: det, t(3, 3)
    type(status_t) :: ist
    body%mass = mass
    body%inertia = inertia
    body%mc = mc
    t = inertia
    det = det3(t)
    if (det <= 0.0_wp) then
      call status%fail(STAT_FAILED, 'body_init: inertia tensor is singular')
      return
    end if
    call inv3(t, body%inv_inertia, ist)
    if (.not. ist%ok()) then
      call status%fail(STAT_FAILED, 'body_init: inertia tensor is singular')
      return
    end if
    body%euler = euler
    body%omega = omega
    body%r = rot_zyx(euler(1), euler(2), euler(3))
    body%x = x_ol + matmul(body%r, mc)
    body%v = v
    body%acc = 0.0_wp
    body%alpha = 0.0_wp
  end subroutine body_init

  !> Accelerations for a total force (global) and a moment about the mass centre (lander axes).
  pure subroutine body_accelerations(body, force, moment)
    type(body_t), intent(inout) :: body   !! body; acc and alpha are set
    real(wp), intent(in) :: force(3)      !! total force, global [N]
    real(wp), intent(in) :: moment(3)     !! total moment about the mass centre, lander axes [N m]
    real(wp) :: h(3)
    body%acc = force/body%mass
    h = mv3(body%inertia, body%omega)
    body%alpha = mv3(body%inv_inertia, moment - cross3(body%omega, h))
  end subroutine body_accelerations

  !> Moves the body along the velocities v (mass centre, global) and omega (lander axes) for h:
  !! x <- x + v h, Euler angles by their rates at the present attitude (E(theta) omega h), the
  !! rotation matrix with them. The update formula of a step is the integrator's (numerics/); this
  !! is the position increment it asks for. The body's stored velocities are not changed.
  pure subroutine body_increment(body, v, omega, h)
    type(body_t), intent(inout) :: body   !! body
    real(wp), intent(in) :: v(3)          !! mass-centre velocity to move with, global [m/s]
    real(wp), intent(in) :: omega(3)      !! body rates to turn with, lander axes [rad/s]
    real(wp), intent(in) :: h             !! duration of the move [s]
    real(wp) :: e(3, 3)
    body%x = body%x + v*h
    e = euler_rate_matrix(body%euler(2), body%euler(3))
    body%euler = body%euler + mv3(e, omega)*h
    body%r = rot_zyx(body%euler(1), body%euler(2), body%euler(3))
  end subroutine body_increment

  !> Global position of a point given in the lander frame.
  pure function body_point_position(body, p) result(x)
    type(body_t), intent(in) :: body  !! body
    real(wp), intent(in) :: p(3)      !! point, lander frame [m]
    real(wp) :: x(3)                  !! point, global [m]
    x = body%x + mv3(body%r, p - body%mc)
  end function body_point_position

  !> Global velocity of a body-fixed point given in the lander frame.
  pure function body_point_velocity(body, p) result(v)
    type(body_t), intent(in) :: body  !! body
    real(wp), intent(in) :: p(3)      !! point, lander frame [m]
    real(wp) :: v(3)                  !! velocity, global [m/s]
    real(wp) :: w(3)
    w = cross3(body%omega, p - body%mc)
    v = body%v + mv3(body%r, w)
  end function body_point_velocity

  !> Acceleration of a body-fixed point, in lander axes.
  pure function body_point_acceleration(body, p) result(a)
    type(body_t), intent(in) :: body  !! body
    real(wp), intent(in) :: p(3)      !! point, lander frame [m]
    real(wp) :: a(3)                  !! acceleration, lander axes [m/s^2]
    real(wp) :: rr(3)
    rr = p - body%mc
    a = mtv3(body%r, body%acc) + cross3(body%alpha, rr) + cross3(body%omega, cross3(body%omega, rr))
  end function body_point_acceleration

  !> Kinetic energy of the body.
  pure function body_kinetic_energy(body) result(t)
    type(body_t), intent(in) :: body  !! body
    real(wp) :: t                     !! kinetic energy [J]
    t = 0.5_wp*body%mass*dot_product(body%v, body%v) &
      + 0.5_wp*dot_product(body%omega, matmul(body%inertia, body%omega))
  end function body_kinetic_energy

end module landyn_body
