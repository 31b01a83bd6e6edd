!> Static stability figures of a lander standing on its footpads, as touchdown-stability studies
!! report them: the tip-over margin (the further rotation about the nearest edge of the footpad
!! support polygon that brings the gravity line through the mass centre onto that edge) and each
!! footpad's static friction ratio |F_t|/(mu_s F_n) (below 1 the footpad holds by static friction).
!! Pure functions of positions and forces; global axes, any orientation of gravity.
!!
!! Written here rather than taken from a library: a convex hull of at most max_gears points and a
!! few vector products; the geometry libraries available (none in Fortran) would cost more than they
!! save.
module landyn_stability
  use landyn_kinds, only: wp, pi
  use landyn_kinematics, only: cross3
  implicit none
  private

  public :: tipover_margin, friction_ratio

contains

  !> Tip-over margin: the smallest, over the edges of the support polygon (the convex hull of the
  !! footpads in contact, seen along gravity), of the angle through which the lander must turn
  !! about that edge (the 3D line through its two footpads) until the mass centre lies in the
  !! vertical plane through the edge. Positive: the gravity line through the mass centre falls
  !! inside the polygon; negative: outside (the lander tips). Fewer than 3 footpads in contact, or
  !! all on one line, support no polygon: the margin is then 0 (not statically stable) [rad].
  pure function tipover_margin(foot, contact, mc, g_vec) result(margin)
    real(wp), intent(in) :: foot(:, :)    !! (3, n) footpad positions, global [m]
    logical, intent(in) :: contact(:)     !! (n) footpad in contact with the ground [-]
    real(wp), intent(in) :: mc(3)         !! mass centre, global [m]
    real(wp), intent(in) :: g_vec(3)      !! gravity, global (direction only) [m/s^2]
    real(wp) :: margin                    !! tip-over margin [rad]
    real(wp) :: p(3, size(foot, 2)), down(3), centroid(3)
    integer :: hull(size(foot, 2)), m, nh, k
    margin = 0.0_wp
    m = 0
    do k = 1, size(foot, 2)
      if (.not. contact(k)) cycle
      m = m + 1
      p(:, m) = foot(:, k)
    end do
    if (m < 3 .or. norm2(g_vec) <= 0.0_wp) return
    down = g_vec/norm2(g_vec)
    call convex_hull(p(:, 1:m), down, hull, nh)
    if (nh < 3) return
    centroid = sum(p(:, hull(1:nh)), dim=2)/real(nh, wp)
    margin = huge(1.0_wp)
    do k = 1, nh
      margin = min(margin, edge_margin(p(:, hull(k)), p(:, hull(mod(k, nh) + 1)), centroid, mc, down))
    end do
  end function tipover_margin

  !> The rotation about the edge a-b that brings the mass centre into the vertical plane through
  !! the edge: positive when the mass centre lies on the polygon's side of that plane [rad].
  pure function edge_margin(a, b, inside, mc, down) result(angle)
    real(wp), intent(in) :: a(3)        !! first footpad of the edge, global [m]
    real(wp), intent(in) :: b(3)        !! second footpad of the edge, global [m]
    real(wp), intent(in) :: inside(3)   !! a point inside the polygon, global [m]
    real(wp), intent(in) :: mc(3)       !! mass centre, global [m]
    real(wp), intent(in) :: down(3)     !! unit gravity direction [-]
    real(wp) :: angle                   !! rotation to the edge [rad]
    real(wp) :: e(3), u(3), w(3), r(3)
    e = (b - a)/norm2(b - a)
    u = -(down - dot_product(down, e)*e)      ! up, perpendicular to the edge
    if (norm2(u) <= 1.0e-12_wp) then          ! edge along gravity: no tipping about it
      angle = pi
      return
    end if
    u = u/norm2(u)
    w = cross3(e, u)                           ! horizontal, perpendicular to the edge
    if (dot_product(w, inside - a) < 0.0_wp) w = -w
    r = mc - a
    angle = atan2(dot_product(r, w), dot_product(r, u))
  end function edge_margin

  !> Convex hull (gift wrapping) of points seen along `down`: the indices of its vertices in order
  !! around it; collinear points on an edge are left out.
  pure subroutine convex_hull(p, down, hull, nh)
    real(wp), intent(in) :: p(:, :)      !! (3, m) points, global [m]
    real(wp), intent(in) :: down(3)      !! unit viewing direction [-]
    integer, intent(out) :: hull(:)      !! (m) hull vertices, the first nh used [-]
    integer, intent(out) :: nh           !! number of hull vertices [-]
    real(wp) :: e1(3), e2(3), q(2, size(p, 2)), c, scale
    integer :: m, k, start, cur, nxt
    m = size(p, 2)
    e1 = cross3(down, [1.0_wp, 0.0_wp, 0.0_wp])
    if (norm2(e1) < 0.5_wp) e1 = cross3(down, [0.0_wp, 1.0_wp, 0.0_wp])
    e1 = e1/norm2(e1)
    e2 = cross3(down, e1)
    do k = 1, m
      q(:, k) = [dot_product(p(:, k), e1), dot_product(p(:, k), e2)]
    end do
    scale = max(maxval(abs(q)), tiny(1.0_wp))
    start = minloc(q(1, :), dim=1)
    nh = 0
    cur = start
    do
      nh = nh + 1
      hull(nh) = cur
      nxt = merge(1, 2, cur /= 1)
      do k = 1, m
        if (k == cur) cycle
        c = cross2(q(:, nxt) - q(:, cur), q(:, k) - q(:, cur))
        ! k is to the right of cur -> nxt, or on that line but further: take it
        if (c < -1.0e-12_wp*scale**2 .or. (abs(c) <= 1.0e-12_wp*scale**2 .and. &
            norm2(q(:, k) - q(:, cur)) > norm2(q(:, nxt) - q(:, cur)))) nxt = k
      end do
      cur = nxt
      if (cur == start .or. nh == m) exit
    end do
  end subroutine convex_hull

  !> Static friction ratio |F_t|/(mu_s F_n) of a footpad: below 1 the footpad can hold by static
  !! friction, at 1 or above it slides. A footpad off the ground (F_n <= 0) carries no friction: 0.
  elemental function friction_ratio(ft, fn, mu_s) result(ratio)
    real(wp), intent(in) :: ft     !! tangential ground force magnitude [N]
    real(wp), intent(in) :: fn     !! normal ground force [N]
    real(wp), intent(in) :: mu_s   !! static friction coefficient [-]
    real(wp) :: ratio              !! |F_t|/(mu_s F_n) [-]
    ratio = 0.0_wp
    if (fn > 0.0_wp .and. mu_s > 0.0_wp) ratio = abs(ft)/(mu_s*fn)
  end function friction_ratio

  !> z component of the 2D cross product a x b.
  pure function cross2(a, b) result(c)
    real(wp), intent(in) :: a(2)   !! first vector [any]
    real(wp), intent(in) :: b(2)   !! second vector [any]
    real(wp) :: c                  !! a1 b2 - a2 b1 [any]
    c = a(1)*b(2) - a(2)*b(1)
  end function cross2

end module landyn_stability
