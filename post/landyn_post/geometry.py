"""Lander geometry rebuilt from a result file, for drawing (landyn-animate, plan views).

The result file stores the body motion, the footpad positions and the strut lengths over time, and
in /model (schema 1.4) the lander as the run built it: every strut's upper joint and nominal lower
end and its nominal frame, computed by LANDYN's own kinematics (src/core/landyn_kinematics.f90).
Nothing is derived from the deck here:

* body-to-global rotation R = Rz(yaw) Ry(pitch) Rx(roll) (standard right-handed matrices, frames
  z down), global point = position + R p_L (position = lander origin O_L);
* upper joints a, b, c are fixed to the body;
* the primary strut's outer tube hangs from a on a universal joint: with its nominal frame
  R0 = [x0 y0 z0] (/model/strut_frame, lander axes) its orientation is R0 rot_x(t1) rot_y(t2). Its
  axis follows from the stored footpad position d; t1, t2 follow from the axis; the lugs e, f
  (lower ends of the secondaries) are rigid on the outer tube: e = a + R0 rot_x(t1) rot_y(t2) R0^T
  (e_nom - a). This is exact, not an approximation; the distances |e - b| and |f - c| reproduce
  the stored secondary strut lengths (checked by :func:`lug_length_error`).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .schema import Result

__all__ = ["rot_x", "rot_y", "rot_z", "rot_zyx", "LanderGeometry", "lander_geometry", "terrain_z",
           "lug_length_error", "body_outline"]


def rot_x(a):
    c, s = np.cos(a), np.sin(a)
    o, z = np.ones_like(c), np.zeros_like(c)
    return np.moveaxis(np.array([[o, z, z], [z, c, -s], [z, s, c]]), (0, 1), (-2, -1))


def rot_y(a):
    c, s = np.cos(a), np.sin(a)
    o, z = np.ones_like(c), np.zeros_like(c)
    return np.moveaxis(np.array([[c, z, s], [z, o, z], [-s, z, c]]), (0, 1), (-2, -1))


def rot_z(a):
    c, s = np.cos(a), np.sin(a)
    o, z = np.ones_like(c), np.zeros_like(c)
    return np.moveaxis(np.array([[c, -s, z], [s, c, z], [z, z, o]]), (0, 1), (-2, -1))


def rot_zyx(euler_deg: np.ndarray) -> np.ndarray:
    """R = Rz(yaw) Ry(pitch) Rx(roll) for Euler angles (..., 3) in degrees -> (..., 3, 3)."""
    e = np.radians(np.asarray(euler_deg, dtype=float))
    return rot_z(e[..., 0]) @ rot_y(e[..., 1]) @ rot_x(e[..., 2])


@dataclass
class LanderGeometry:
    """Joint positions over time, global frame (z down), m.

    upper: (n, g, 3, 3) upper joints a, b, c; footpad: (n, g, 3) d; lug: (n, g, 2, 3) e, f;
    body_hull: (k, 3) lander-frame outline polygon (plan view of the upper joints) with
    body_z: (z_top, z_bottom) in the lander frame; rotation: (n, 3, 3); position: (n, 3).
    """
    upper: np.ndarray
    footpad: np.ndarray
    lug: np.ndarray
    body_hull: np.ndarray
    body_z: tuple[float, float]
    rotation: np.ndarray
    position: np.ndarray
    mass_centre: np.ndarray

    def to_global(self, p_lander: np.ndarray, k: int | slice = slice(None)) -> np.ndarray:
        """Lander-frame points (..., 3) to global at sample(s) k."""
        r = self.rotation[k]
        x = self.position[k]
        return np.einsum("...ij,...kj->...ki", r, np.atleast_2d(p_lander)) + np.asarray(x)[..., None, :]


def _convex_hull_2d(pts: np.ndarray) -> np.ndarray:
    """Monotone-chain convex hull of 2-D points, counter-clockwise."""
    p = sorted(set(map(tuple, np.round(pts, 9))))
    if len(p) < 3:
        return np.array(p)

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for q in p:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], q) <= 0:
            lower.pop()
        lower.append(q)
    for q in reversed(p):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], q) <= 0:
            upper.pop()
        upper.append(q)
    return np.array(lower[:-1] + upper[:-1])


def body_outline(hp: dict[str, np.ndarray]) -> tuple[np.ndarray, tuple[float, float]]:
    """A schematic body: the prism over the convex hull (plan view) of the upper joints a, b, c,
    from their lowest z down to the mirror of that level about the mass centre (so the mass
    centre sits at mid-height). Returns (hull (k, 2), (z_top, z_bottom)) in the lander frame."""
    upper = np.concatenate([hp["a"], hp["b"], hp["c"]])
    hull = _convex_hull_2d(upper[:, :2])
    z_bottom = float(np.max(upper[:, 2]))
    mc_z = float(hp["mass_centre"][2])
    z_top = 2.0 * mc_z - z_bottom if mc_z < z_bottom else float(np.min(upper[:, 2])) - 1.0
    return hull, (z_top, z_bottom)


def lander_geometry(res: Result) -> LanderGeometry:
    """Rebuilds the joint positions of every gear over the whole run (see the module doc); a file
    without /model (older than schema 1.4) raises LandynFileError naming the group."""
    hp = res.hard_points()
    g, n = res.n_gears, res.n_samples
    rot = rot_zyx(res.euler_angles)                        # (n, 3, 3) lander -> global
    pos = res.position                                     # (n, 3)
    upper = np.empty((n, g, 3, 3))
    lug = np.empty((n, g, 2, 3))
    d_glob = res.footpad_position                          # (n, g, 3)
    for i in range(g):
        for j, p in enumerate("abc"):
            upper[:, i, j] = pos + rot @ hp[p][i]
        a, e, f = hp["a"][i], hp["e"][i], hp["f"][i]       # nominal geometry, lander frame
        r0 = hp["strut_frame"][i, 0]                       # primary's nominal frame, lander axes
        e_loc, f_loc = r0.T @ (e - a), r0.T @ (f - a)
        # current primary axis in the lander frame
        u_glob = d_glob[:, i] - upper[:, i, 0]
        u_glob /= np.linalg.norm(u_glob, axis=1)[:, None]
        u_l = np.einsum("nji,nj->ni", rot, u_glob)        # R^T u
        v = u_l @ r0                                       # R0^T u
        t2 = np.arcsin(np.clip(v[:, 0], -1.0, 1.0))
        t1 = np.arctan2(-v[:, 1], v[:, 2])
        rp = r0 @ rot_x(t1) @ rot_y(t2)                    # (n, 3, 3) primary orientation, lander axes
        for j, loc in enumerate((e_loc, f_loc)):
            lug[:, i, j] = pos + np.einsum("nij,nj->ni", rot, a + rp @ loc)
    hull, zz = body_outline(hp)
    return LanderGeometry(upper, d_glob, lug, hull, zz, rot, pos, hp["mass_centre"])


def lug_length_error(res: Result, geom: LanderGeometry) -> float:
    """Largest |(|e - b| or |f - c|) - stored secondary strut length| over the run, m."""
    lb = np.linalg.norm(geom.lug[:, :, 0] - geom.upper[:, :, 1], axis=-1)
    lc = np.linalg.norm(geom.lug[:, :, 1] - geom.upper[:, :, 2], axis=-1)
    return float(max(np.max(np.abs(lb - res.strut_length[:, :, 1])), np.max(np.abs(lc - res.strut_length[:, :, 2]))))


def terrain_z(plane: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Global z (down) of the terrain plane (elevation h, slope deg, uphill azimuth deg) at (x, y)."""
    h, slope, azim = plane
    elev = h + np.tan(np.radians(slope)) * (x * np.cos(np.radians(azim)) + y * np.sin(np.radians(azim)))
    return -elev
