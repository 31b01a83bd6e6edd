"""landyn-animate: 3-D animation (or one still frame) of a LANDYN touchdown.

Drawn: a schematic body (prism over the upper joints, see geometry.body_outline), every strut
from its upper joint to its lower end (primary a -> footpad d, secondaries b -> e and c -> f with
the lugs e, f rebuilt exactly on the primary's outer tube, see geometry), the footpads, the
terrain plane(s) with their slope, and the footpad traces up to the current time.

Display frame: global x, y, z with z DOWN is shown rotated 180 deg about x (x, -y, -z), a proper
rotation, so elevation is up and the picture is not mirrored; the y tick labels show global y,
the vertical axis shows the height -z.
MP4 when ffmpeg is on PATH, GIF (pillow) otherwise; --still T writes one PNG at time T.
"""
from __future__ import annotations

import os
import shutil
import sys

import numpy as np

from . import cli
from .geometry import LanderGeometry, lander_geometry, terrain_z
from .schema import LandynPostError, Result, load

STRUT_COLORS = ("#1f4e9c", "#d9822b", "#2e9a4a")


def _disp(p: np.ndarray) -> np.ndarray:
    """Global (z down) -> display coordinates (x, -y, -z)."""
    p = np.asarray(p, dtype=float)
    return p * np.array([1.0, -1.0, -1.0])


class Scene:
    """Draws the lander at output sample k on a 3-D axes."""

    def __init__(self, res: Result, geom: LanderGeometry, elev: float, azim: float):
        self.res, self.geom, self.elev, self.azim = res, geom, elev, azim
        pts = np.concatenate([geom.upper.reshape(-1, 3), geom.footpad.reshape(-1, 3), geom.lug.reshape(-1, 3)])
        hull = self._body_faces(0)
        pts = np.concatenate([pts, np.concatenate(hull)])
        d = _disp(pts)
        lo, hi = d.min(axis=0), d.max(axis=0)
        centre, half = 0.5 * (lo + hi), 0.5 * (hi - lo).max() * 1.05
        self.lim = [(c - half, c + half) for c in centre]
        self.lim[2] = (lo[2] - 0.3, lo[2] - 0.3 + 2 * half)   # keep the ground in view
        self.terrain = res.terrain()

    def _body_faces(self, k: int) -> list[np.ndarray]:
        g = self.geom
        hull = g.body_hull
        z_top, z_bot = g.body_z
        top = g.to_global(np.column_stack([hull, np.full(len(hull), z_top)]), k)
        bot = g.to_global(np.column_stack([hull, np.full(len(hull), z_bot)]), k)
        sides = [np.array([top[i], top[(i + 1) % len(hull)], bot[(i + 1) % len(hull)], bot[i]])
                 for i in range(len(hull))]
        return [top, bot] + sides

    def _ground(self, ax) -> None:
        fp0 = self.geom.footpad[0]
        planes = self.terrain
        same = np.allclose(planes, planes[0])
        (x0, x1), (yd0, yd1), _ = self.lim
        if same:
            patches = [(planes[0], (x0, x1), (-yd1, -yd0))]
        else:
            patches = [(planes[i], (fp0[i, 0] - 1.2, fp0[i, 0] + 1.2), (fp0[i, 1] - 1.2, fp0[i, 1] + 1.2))
                       for i in range(len(planes))]
        for plane, (xa, xb), (ya, yb) in patches:
            xx, yy = np.meshgrid(np.linspace(xa, xb, 9), np.linspace(ya, yb, 9))
            zz = terrain_z(plane, xx, yy)
            ax.plot_surface(xx, -yy, -zz, color="#c8b89a", alpha=0.4, linewidth=0, shade=False)
            ax.plot_wireframe(xx, -yy, -zz, color="#8a7a5a", lw=0.3)   # the grid shows the slope

    def draw(self, ax, k: int) -> None:
        from mpl_toolkits.mplot3d.art3d import Poly3DCollection
        res, g = self.res, self.geom
        ax.cla()
        self._ground(ax)
        faces = [_disp(f) for f in self._body_faces(k)]
        ax.add_collection3d(Poly3DCollection(faces, facecolor="#b0b8c8", edgecolor="#505868", lw=0.5, alpha=0.35))
        for i in range(res.n_gears):
            a, b, c = g.upper[k, i]
            d = g.footpad[k, i]
            e, f = g.lug[k, i]
            for (p, q), col, lw in (((a, d), STRUT_COLORS[0], 3.0), ((b, e), STRUT_COLORS[1], 1.8),
                                    ((c, f), STRUT_COLORS[2], 1.8)):
                seg = _disp(np.array([p, q]))
                ax.plot(seg[:, 0], seg[:, 1], seg[:, 2], color=col, lw=lw, solid_capstyle="round")
            trace = _disp(g.footpad[: k + 1, i])
            ax.plot(trace[:, 0], trace[:, 1], trace[:, 2], color="k", lw=1.0)
            dd = _disp(d)
            ax.scatter([dd[0]], [dd[1]], [dd[2]], color="k", s=30, depthshade=False)
            ax.text(dd[0], dd[1], dd[2] - 0.45, f"{i + 1}", fontsize=8, ha="center")
        ax.set_xlim(*self.lim[0])
        ax.set_ylim(*self.lim[1])
        ax.set_zlim(*self.lim[2])
        ax.set_box_aspect((1, 1, 1))
        ax.view_init(elev=self.elev, azim=self.azim)
        from matplotlib.ticker import FuncFormatter
        ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{0.0 - v:g}"))
        ax.set_xlabel("x [m]", fontsize=8)
        ax.set_ylabel("y [m]", fontsize=8)
        ax.set_zlabel("height -z [m]", fontsize=8)
        ax.tick_params(labelsize=7)
        s = res.stroke[k] * 1e3
        ax.set_title(f"{res.title}\nt = {res.time[k]:.3f} s   primary strokes "
                     + ", ".join(f"{v:.0f}" for v in s[:, 0]) + " mm", fontsize=8)


def _frames(res: Result, n_frames: int) -> np.ndarray:
    n = res.n_samples
    return np.unique(np.linspace(0, n - 1, max(2, min(n_frames, n))).round().astype(int))


def write_still(res: Result, t: float, out: str, elev: float, azim: float, dpi: int) -> str:
    cli.use_agg()
    import matplotlib.pyplot as plt
    if not res.time[0] - 1e-9 <= t <= res.time[-1] + 1e-9:
        raise LandynPostError(f"--still {t:g}: outside the run ({res.time[0]:g} .. {res.time[-1]:g} s)")
    k = int(np.argmin(np.abs(res.time - t)))
    scene = Scene(res, lander_geometry(res), elev, azim)
    fig = plt.figure(figsize=(7, 6.5))
    ax = fig.add_subplot(projection="3d")
    scene.draw(ax, k)
    fig.tight_layout()
    fig.savefig(out, dpi=dpi)
    plt.close(fig)
    return out


def write_animation(res: Result, out: str, n_frames: int, fps: float, elev: float, azim: float, dpi: int) -> str:
    cli.use_agg()
    import matplotlib.pyplot as plt
    from matplotlib import animation
    ext = os.path.splitext(out)[1].lower()
    if ext == ".mp4":
        if not shutil.which("ffmpeg"):
            raise LandynPostError("MP4 output needs ffmpeg on PATH (not found); write a .gif instead")
        writer = animation.FFMpegWriter(fps=fps, bitrate=2400)
    elif ext == ".gif":
        writer = animation.PillowWriter(fps=fps)
    else:
        raise LandynPostError(f"{out}: unsupported animation format {ext or '(none)'} (use .gif or .mp4)")
    scene = Scene(res, lander_geometry(res), elev, azim)
    frames = _frames(res, n_frames)
    fig = plt.figure(figsize=(7, 6.5))
    ax = fig.add_subplot(projection="3d")
    anim = animation.FuncAnimation(fig, lambda k: scene.draw(ax, int(k)), frames=frames, interval=1000 / fps)
    anim.save(out, writer=writer, dpi=dpi)
    plt.close(fig)
    return out


def _main(argv=None) -> int:
    p = cli.make_parser(
        "landyn-animate", "3-D animation of a LANDYN touchdown (MP4 with ffmpeg, else GIF), or one still PNG.",
        epilog="examples:\n  landyn-animate lc3.h5                  # lc3_animation.mp4 or .gif\n"
               "  landyn-animate lc3.h5 --still 0.3 -o lc3_0300ms.png\n"
               "  landyn-animate lc3.h5 --frames 60 --fps 15 --azim -30")
    p.add_argument("file", metavar="FILE", help="LANDYN result file (.h5)")
    p.add_argument("-o", "--output", metavar="OUT",
                   help="output file (.mp4, .gif; .png with --still); default <stem>_animation.mp4/.gif "
                        "or <stem>_t<T>.png")
    p.add_argument("--still", type=float, metavar="T", help="write one PNG frame at time T [s] instead")
    p.add_argument("--frames", type=cli.positive_int, default=100, help="number of frames (default 100, spread over the run)")
    p.add_argument("--fps", type=cli.positive_float, default=20.0, help="frames per second (default 20)")
    p.add_argument("--elev", type=float, default=18.0, help="camera elevation [deg] (default 18)")
    p.add_argument("--azim", type=float, default=-55.0, help="camera azimuth [deg] (default -55)")
    p.add_argument("--dpi", type=cli.positive_int, default=None, help="resolution (default 100 still, 72 animation)")
    a = p.parse_args(argv)
    if a.frames < 2:
        p.error("--frames must be >= 2")
    if not a.fps > 0:
        p.error("--fps must be > 0")
    res = load(a.file)
    base = cli.stem(a.file)
    if a.still is not None:
        out = a.output or f"{base}_t{a.still:.3f}.png"
        cli.figure_format(out)
        cli.refuse_overwrite(out, [a.file])
        print(write_still(res, a.still, out, a.elev, a.azim, a.dpi or 100))
    else:
        out = a.output or base + ("_animation.mp4" if shutil.which("ffmpeg") else "_animation.gif")
        cli.refuse_overwrite(out, [a.file])
        print(write_animation(res, out, a.frames, a.fps, a.elev, a.azim, a.dpi or 72))
    return cli.EXIT_OK


def main(argv=None) -> int:
    return cli.run("landyn-animate", _main, argv)


if __name__ == "__main__":
    sys.exit(main())
