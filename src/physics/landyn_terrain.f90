!> Planar terrain under each footpad (docs/model_conventions.md, "Footpad-ground contact and friction").
!!
!! Conventions
!! - Global frame O_g: x, y horizontal, z DOWN. "Elevation" is measured up (= -z).
!! - A plane is given by its elevation h at the global origin, its slope angle alpha and the
!!   azimuth beta of its uphill direction (from global +x toward +y). It passes through the
!!   global point (0, 0, -h) and its elevation at horizontal (x, y) is
!!       e(x, y) = h + tan(alpha) * (x cos(beta) + y sin(beta)),   z_surface = -e(x, y).
!! - The unit normal n points OUT of the ground (up, so n(3) < 0 for |alpha| < 90 deg):
!!       n  = (-sin(alpha) cos(beta), -sin(alpha) sin(beta), -cos(alpha)).
!! - Local surface frame O_si (eqs. 17-18 are written in it): right-handed orthonormal axes
!!       t1 = uphill direction along the surface = (cos(alpha) cos(beta), cos(alpha) sin(beta), -sin(alpha)),
!!       t2 = n x t1   (so t1 x t2 = n),
!!       n  = outward normal.
!!   The 3x3 matrix `surface_frame(plane)` holds t1, t2, n as its COLUMNS, in global
!!   coordinates: v_global = O v_local and v_local = O^T v_global; det(O) = +1.
!!   For flat ground (alpha = beta = 0): t1 = +x, t2 = -y, n = -z.
!! - Penetration delta of a point p is its depth below the plane measured along the normal:
!!       delta = (p0 - p) . n,  p0 = (0, 0, -h);   delta > 0 inside the ground.
!!   A point a vertical distance dz below the surface has delta = dz cos(alpha).
!!   Its rate (positive when penetrating deeper) for a point velocity v is -v . n.
!!
!! All procedures are pure and allocation-free (they run in the inner time-step loop).
module landyn_terrain
  use landyn_kinds, only: wp, max_gears, pi
  use landyn_config, only: terrain_cfg_t
  use landyn_kinematics, only: cross3
  use landyn_status, only: STAT_FAILED, status_t
  implicit none
  private

  public :: terrain_plane_t
  public :: terrain_plane, make_terrain_planes
  public :: penetration, penetration_rate, slip_velocity
  public :: surface_frame, surface_normal, surface_height_z
  public :: to_local, to_global

  !> One planar terrain patch (one per footpad). Default-initialised: flat ground at elevation 0.
  type :: terrain_plane_t
    private
    real(wp) :: height = 0.0_wp           !! elevation of the plane at the global origin (up positive) [m]
    real(wp) :: slope = 0.0_wp            !! slope angle alpha [rad]
    real(wp) :: azimuth = 0.0_wp          !! uphill azimuth beta, from global +x toward +y [rad]
    real(wp) :: tan_slope = 0.0_wp        !! tan(alpha) [-]
    real(wp) :: origin(3) = [0.0_wp, 0.0_wp, 0.0_wp]   !! reference point (0, 0, -h), global frame [m]
    real(wp) :: frame(3, 3) = reshape([1.0_wp, 0.0_wp, 0.0_wp, &
                                       0.0_wp, -1.0_wp, 0.0_wp, &
                                       0.0_wp, 0.0_wp, -1.0_wp], [3, 3])  !! columns t1, t2, n in global coordinates [-]
  end type terrain_plane_t

contains

  !> Build the plane of elevation h at the global origin, slope alpha, uphill azimuth beta.
  !! The caller guarantees |alpha| < pi/2 (checked by make_terrain_planes).
  pure function terrain_plane(h, alpha, beta) result(plane)
    real(wp), intent(in) :: h       !! elevation at the global origin, up positive [m]
    real(wp), intent(in) :: alpha   !! slope angle [rad]
    real(wp), intent(in) :: beta    !! azimuth of the uphill direction, from +x toward +y [rad]
    type(terrain_plane_t) :: plane  !! the plane
    real(wp) :: ca, sa, cb, sb, t1(3), t2(3), n(3)

    ca = cos(alpha)
    sa = sin(alpha)
    cb = cos(beta)
    sb = sin(beta)
    n = [-sa*cb, -sa*sb, -ca]
    t1 = [ca*cb, ca*sb, -sa]
    t2 = cross3(n, t1)   ! = (sb, -cb, 0): horizontal, to the right of the uphill direction seen from above
    plane%height = h
    plane%slope = alpha
    plane%azimuth = beta
    plane%tan_slope = tan(alpha)
    plane%origin = [0.0_wp, 0.0_wp, -h]
    plane%frame(:, 1) = t1
    plane%frame(:, 2) = t2
    plane%frame(:, 3) = n
  end function terrain_plane

  !> Build planes(i) from entry i of the &terrain input, for i = 1..size(planes).
  !! Fails (STAT_FAILED with its message) when size(planes) exceeds max_gears or a slope is not in (-90, 90) deg
  !! or an entry is not finite.
  pure subroutine make_terrain_planes(cfg, planes, status)
    type(terrain_cfg_t), intent(in) :: cfg                 !! resolved &terrain input (angles in rad, heights in m)
    type(terrain_plane_t), intent(out) :: planes(:)        !! one plane per footpad
    type(status_t), intent(out) :: status                  !! STAT_OK, or STAT_FAILED with the reason [-]
    integer :: i
    character(len=16) :: buf

    if (size(planes) > max_gears) then
      write (buf, '(i0)') max_gears
      call status%fail(STAT_FAILED, '&terrain: more footpads than max_gears = '//trim(buf))
      return
    end if
    do i = 1, size(planes)
      write (buf, '(i0)') i
      if (.not. is_finite(cfg%height(i)) .or. .not. is_finite(cfg%slope_direction(i))) then
        call status%fail(STAT_FAILED, '&terrain: height or slope_direction of footpad '//trim(buf)//' is not a finite number')
        return
      end if
      if (.not. (abs(cfg%slope(i)) < 0.5_wp*pi)) then
        call status%fail(STAT_FAILED, '&terrain: slope of footpad '//trim(buf)//' must lie strictly between -90 and 90 deg')
        return
      end if
      planes(i) = terrain_plane(cfg%height(i), cfg%slope(i), cfg%slope_direction(i))
    end do
  end subroutine make_terrain_planes

  !> Depth of point p below the surface along the normal: > 0 inside the ground, < 0 above it.
  pure function penetration(plane, p) result(delta)
    type(terrain_plane_t), intent(in) :: plane  !! terrain plane
    real(wp), intent(in) :: p(3)                !! point, global frame (z down) [m]
    real(wp) :: delta                           !! penetration [m]
    delta = dot_product(plane%origin - p, plane%frame(:, 3))
  end function penetration

  !> Rate of penetration of a point moving with velocity v (positive when moving deeper / toward the ground).
  pure function penetration_rate(plane, v) result(delta_dot)
    type(terrain_plane_t), intent(in) :: plane  !! terrain plane
    real(wp), intent(in) :: v(3)                !! point velocity, global frame [m/s]
    real(wp) :: delta_dot                       !! d(delta)/dt [m/s]
    delta_dot = -dot_product(v, plane%frame(:, 3))
  end function penetration_rate

  !> Tangential (slip) components of a global vector in the local surface frame: (v . t1, v . t2).
  pure function slip_velocity(plane, v) result(v_slip)
    type(terrain_plane_t), intent(in) :: plane  !! terrain plane
    real(wp), intent(in) :: v(3)                !! velocity, global frame [m/s]
    real(wp) :: v_slip(2)                       !! components along t1, t2 [m/s]
    v_slip(1) = dot_product(v, plane%frame(:, 1))
    v_slip(2) = dot_product(v, plane%frame(:, 2))
  end function slip_velocity

  !> Local surface frame O_si: columns t1 (uphill), t2 = n x t1, n (outward normal), global coordinates.
  pure function surface_frame(plane) result(o)
    type(terrain_plane_t), intent(in) :: plane  !! terrain plane
    real(wp) :: o(3, 3)                         !! rotation local -> global [-]
    o = plane%frame
  end function surface_frame

  !> Unit normal pointing out of the ground (up: negative z component), global frame.
  pure function surface_normal(plane) result(n)
    type(terrain_plane_t), intent(in) :: plane  !! terrain plane
    real(wp) :: n(3)                            !! outward unit normal [-]
    n = plane%frame(:, 3)
  end function surface_normal

  !> Global z coordinate (z down) of the surface above/below horizontal position (x, y).
  elemental function surface_height_z(plane, x, y) result(z)
    type(terrain_plane_t), intent(in) :: plane  !! terrain plane
    real(wp), intent(in) :: x                   !! global x [m]
    real(wp), intent(in) :: y                   !! global y [m]
    real(wp) :: z                               !! surface z, global frame (z down) [m]
    z = -(plane%height + plane%tan_slope*(x*cos(plane%azimuth) + y*sin(plane%azimuth)))
  end function surface_height_z

  !> Components of a global vector in the local surface frame (t1, t2, n): O^T v.
  pure function to_local(plane, v) result(w)
    type(terrain_plane_t), intent(in) :: plane  !! terrain plane
    real(wp), intent(in) :: v(3)                !! vector, global frame [any unit]
    real(wp) :: w(3)                            !! same vector, local frame [same unit]
    w = matmul(v, plane%frame)
  end function to_local

  !> Global components of a vector given in the local surface frame (t1, t2, n): O w.
  pure function to_global(plane, w) result(v)
    type(terrain_plane_t), intent(in) :: plane  !! terrain plane
    real(wp), intent(in) :: w(3)                !! vector, local frame [any unit]
    real(wp) :: v(3)                            !! same vector, global frame [same unit]
    v = matmul(plane%frame, w)
  end function to_global

  !> True when x is a finite number (neither NaN nor infinite); checks the &terrain heights and directions.
  elemental function is_finite(x) result(yes)
    real(wp), intent(in) :: x  !! value [any unit]
    logical :: yes             !! .true. when x is neither NaN nor infinite
    yes = abs(x) <= huge(x)
  end function is_finite

end module landyn_terrain
