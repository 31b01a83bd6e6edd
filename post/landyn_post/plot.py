"""landyn-plot: standard figures of one LANDYN result file (and the --report PDF).

Figures (file names ``<stem>_<name>.<fmt>`` in OUTDIR):

  strokes         stroke time history of every strut (paper Fig. 9)
  crush_lengths   final crush length per gear and strut, stroke capacities marked (paper Fig. 8)
  footpad_forces  footpad normal and friction forces and penetration (paper Fig. 11)
  body            body velocity, attitude and tilt, overload
  footpad_paths   footpad paths on the ground, plan view and displacement from touchdown
  energy          energy audit stacked over time, residual
"""
from __future__ import annotations

import os
import sys

import numpy as np

from . import cli
from .schema import STRUT_LABELS, STRUTS, Result, load, measure_number

GEAR_COLORS = ("C0", "C1", "C2", "C3", "C4", "C5", "C6", "C7")
STRUT_STYLES = ("-", "--", ":")
STRUT_COLORS = ("#4c72b0", "#dd8452", "#55a868")
MM, KN = 1.0e3, 1.0e-3


def _plt():
    cli.use_agg()
    import matplotlib.pyplot as plt
    return plt


def _title(fig, res: Result, what: str) -> None:
    import textwrap
    fig.suptitle("\n".join([what] + textwrap.wrap(res.title, 90)), fontsize=10)


def _gear_color(i: int) -> str:
    return GEAR_COLORS[i % len(GEAR_COLORS)]


def _min_span(ax, span: float) -> None:
    """Widens the y range to at least `span` (so round-off noise does not fill the axes)."""
    lo, hi = ax.get_ylim()
    if hi - lo < span:
        mid = 0.5 * (lo + hi)
        ax.set_ylim(mid - span / 2, mid + span / 2)


def _tilt(res: Result) -> np.ndarray:
    """Angle between the lander z axis and the vertical, deg (R33 = cos(pitch) cos(roll))."""
    e = np.radians(res.euler_angles)
    return np.degrees(np.arccos(np.clip(np.cos(e[:, 1]) * np.cos(e[:, 2]), -1.0, 1.0)))


# ----------------------------------------------------------------------------------------- figures

def fig_strokes(res: Result):
    """Stroke of every strut over time (paper Fig. 9): primaries and secondaries, capacities marked."""
    plt = _plt()
    fig, axs = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    t = res.time
    cap = res.strut_capacity()
    for i in range(res.n_gears):
        axs[0].plot(t, res.stroke[:, i, 0] * MM, color=_gear_color(i), label=f"gear {i + 1}")
        for k in (1, 2):
            axs[1].plot(t, res.stroke[:, i, k] * MM, color=_gear_color(i), ls=STRUT_STYLES[k],
                        label=f"gear {i + 1} {STRUT_LABELS[STRUTS[k]].split()[1]}")
    for s_end in res.primary_stage_ends()[:-1]:
        axs[0].axhline(s_end * MM, color="0.5", lw=0.8, ls=":")
        axs[0].annotate("stage end", (t[0], s_end * MM), fontsize=7, color="0.4", va="bottom")
    _capacity_lines(axs[0], cap[:, 0, 0], None, t[0])
    _capacity_lines(axs[1], cap[:, 1, 0], cap[:, 1, 1], t[0])
    axs[0].set_ylabel("primary stroke [mm]\n(shortening +)")
    axs[1].set_ylabel("secondary stroke [mm]\n(lengthening +)")
    axs[1].set_xlabel("time [s]")
    axs[0].set_title("(a) primary struts", fontsize=9, loc="left")
    axs[1].set_title("(b) secondary struts: left dashed, right dotted", fontsize=9, loc="left")
    axs[0].legend(fontsize=7, ncol=4, loc="lower right")
    axs[1].legend(fontsize=6, ncol=4, loc="best")
    for ax in axs:
        ax.grid(True, alpha=0.3)
    _title(fig, res, "Strut strokes")
    fig.tight_layout()
    return fig


def _capacity_lines(ax, cap_pos, cap_neg, t0) -> None:
    for vals, va in ((cap_pos, "bottom"), (cap_neg, "top")):
        if vals is None or not np.all(np.isfinite(vals)):
            continue
        c = float(np.max(vals)) * MM * (1 if va == "bottom" else -1)
        ax.axhline(c, color="k", lw=1.0, ls="-.")
        ax.annotate("capacity", (t0, c), fontsize=7, va=va)


def fig_crush_lengths(res: Result):
    """Final crush length of every strut as bars (paper Fig. 8), capacities and crushed lengths marked."""
    plt = _plt()
    g = res.n_gears
    fig, ax = plt.subplots(figsize=(max(8, 0.6 * 3 * g + 2), 5.5))
    cap = res.strut_capacity()
    x = np.arange(1, 3 * g + 1)
    net = res.crush_length.reshape(-1) * MM
    colors = [STRUT_COLORS[k] for _ in range(g) for k in range(3)]
    bars = ax.bar(x, net, color=colors, edgecolor="k", lw=0.5, zorder=2)
    low = -res.crushed_negative.reshape(-1) * MM
    for b, v, lo in zip(bars, net, low):
        y = v if v >= 0 else min(v, lo)          # below the "crushed toward -" marker
        ax.annotate(f"{v:.1f}", (b.get_x() + b.get_width() / 2, y), ha="center",
                    va="bottom" if v >= 0 else "top", fontsize=7, xytext=(0, 2 if v >= 0 else -5),
                    textcoords="offset points")
    cp = cap[:, :, 0].reshape(-1) * MM
    cn = -cap[:, :, 1].reshape(-1) * MM
    ax.hlines(cp, x - 0.4, x + 0.4, colors="k", lw=2, zorder=3, label="stroke capacity")
    ok = np.isfinite(cn)
    ax.hlines(cn[ok], x[ok] - 0.4, x[ok] + 0.4, colors="k", lw=2, zorder=3)
    both = (res.crushed_positive.reshape(-1) > 0) & (res.crushed_negative.reshape(-1) > 0)
    if np.any(both):
        ax.scatter(x[both], res.crushed_positive.reshape(-1)[both] * MM, marker="^", color="k", s=18, zorder=4,
                   label="crushed toward + / -")
        ax.scatter(x[both], -res.crushed_negative.reshape(-1)[both] * MM, marker="v", color="k", s=18, zorder=4)
    bo = res.bottomed_out.reshape(-1) > 0
    if np.any(bo):
        ax.scatter(x[bo], net[bo], marker="X", color="red", s=60, zorder=5, label="bottomed out")
    ax.axhline(0, color="k", lw=0.6)
    ax.set_xticks(x)
    ax.set_xticklabels([f"{measure_number(i + 1, k)}\nG{i + 1}{'PLR'[k]}" for i in range(g) for k in range(3)],
                       fontsize=7)
    ax.set_xlabel("measure (Table 3): G = gear, P primary, L secondary left, R secondary right")
    ax.set_ylabel("crush length [mm]\n(primary shortening, secondary lengthening +)")
    from matplotlib.patches import Patch
    handles = [Patch(color=STRUT_COLORS[k], label=STRUT_LABELS[STRUTS[k]]) for k in range(3)]
    h2, _ = ax.get_legend_handles_labels()
    ax.legend(handles=handles + h2, fontsize=7, ncol=6, loc="upper center", bbox_to_anchor=(0.5, -0.17))
    ax.grid(True, axis="y", alpha=0.3, zorder=0)
    _title(fig, res, "Crush length of each honeycomb buffer after touchdown")
    fig.tight_layout()
    return fig


def fig_footpad_forces(res: Result):
    """Footpad normal and friction forces and penetration over time (paper Fig. 11)."""
    plt = _plt()
    fig, axs = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    t = res.time
    for i in range(res.n_gears):
        c = _gear_color(i)
        axs[0].plot(t, res.normal_force[:, i] * KN, color=c, label=f"footpad {i + 1}")
        axs[1].plot(t, res.friction_force[:, i] * KN, color=c)
        axs[2].plot(t, res.penetration[:, i] * MM, color=c)
    axs[0].set_ylabel("normal force [kN]")
    axs[1].set_ylabel("friction force [kN]\n(magnitude)")
    axs[2].set_ylabel("penetration [mm]\n(> 0 in the ground)")
    peak = max(0.5, float(np.max(res.penetration)) * MM)
    axs[2].set_ylim(-0.25 * peak, 1.15 * peak)   # before touchdown the footpads are far above
    axs[2].set_xlabel("time [s]")
    axs[0].legend(fontsize=7, ncol=4)
    for ax in axs:
        ax.grid(True, alpha=0.3)
    _title(fig, res, "Footpad-ground contact forces")
    fig.tight_layout()
    return fig


def fig_body(res: Result):
    """Body velocity, attitude (and tilt) and overload over time."""
    plt = _plt()
    fig, axs = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    t = res.time
    for k, lab in enumerate(("x", "y", "z (down)")):
        axs[0].plot(t, res.velocity[:, k], label=f"v{lab}")
    for k, lab in enumerate(("yaw", "pitch", "roll")):
        axs[1].plot(t, res.euler_angles[:, k], label=lab)
    axs[1].plot(t, _tilt(res), color="k", ls="--", label="tilt")
    for k, lab in enumerate(("x", "y", "z")):
        axs[2].plot(t, res.overload[:, k], label=f"n{lab}")
    axs[2].plot(t, np.linalg.norm(res.overload, axis=1), color="k", ls="--", label="|n|")
    axs[2].set_title(f"peak |n| {res.peak_overload:.2f} g at {res.time_of_peak_overload:.4f} s "
                     "(every time step; the curves show the output samples)", fontsize=8, loc="left")
    _min_span(axs[1], 2.0)
    axs[0].set_ylabel("mass-centre velocity [m/s]\n(global, z down)")
    axs[1].set_ylabel("attitude [deg]\n(Z-Y-X Euler)")
    axs[2].set_ylabel("overload [g]\n(lander axes)")
    axs[2].set_xlabel("time [s]")
    for ax in axs:
        ax.legend(fontsize=7, ncol=4, loc="best")
        ax.grid(True, alpha=0.3)
    _title(fig, res, "Body motion")
    fig.tight_layout()
    return fig


def fig_footpad_paths(res: Result):
    """Footpad paths on the ground: plan view (x up, y right, seen from above; z down) and each
    footpad's horizontal displacement from its touchdown point in mm."""
    plt = _plt()
    from .geometry import lander_geometry
    from .schema import LandynFileError
    fig, axs = plt.subplots(1, 2, figsize=(11, 5.5))
    fp = res.footpad_position
    try:
        geom = lander_geometry(res)
    except LandynFileError:
        geom = None
    ax = axs[0]
    if geom is not None:
        for k, ls in ((0, ":"), (res.n_samples - 1, "-")):
            hull = np.column_stack([geom.body_hull, np.full(len(geom.body_hull), geom.body_z[1])])
            pts = geom.to_global(hull, k)
            pts = np.vstack([pts, pts[:1]])
            ax.plot(pts[:, 1], pts[:, 0], color="0.5", ls=ls, lw=1,
                    label="body outline " + ("start" if k == 0 else "end"))
    for i in range(res.n_gears):
        c = _gear_color(i)
        ax.plot(fp[:, i, 1], fp[:, i, 0], color=c, lw=2)
        ax.plot(fp[0, i, 1], fp[0, i, 0], "o", color=c, mfc="none")
        ax.plot(fp[-1, i, 1], fp[-1, i, 0], "o", color=c)
        ax.annotate(f"  {i + 1}", (fp[-1, i, 1], fp[-1, i, 0]), color=c, fontsize=9)
    pos = res.position
    ax.plot(pos[:, 1], pos[:, 0], color="k", lw=1, label="lander origin O_L")
    try:
        terr = res.terrain()
    except LandynFileError:   # the uphill arrow is decoration only
        terr = np.zeros((res.n_gears, 3))
    if terr[0, 1] != 0:
        az = np.radians(terr[0, 2] + (180.0 if terr[0, 1] < 0 else 0.0))
        span = float(np.ptp(fp[0, :, 0])) or 5.0
        tip = np.array([np.sin(az), np.cos(az)]) * 0.25 * span     # (y, x) in the plan view
        ax.annotate("", xy=tuple(tip), xytext=(0, 0), arrowprops=dict(arrowstyle="->", color="saddlebrown"))
        note = "" if np.allclose(terr, terr[0]) else " (footpad 1's plane)"
        ax.annotate(f"uphill {abs(terr[0, 1]):.1f} deg{note}", tuple(tip * 1.08), color="saddlebrown", fontsize=8)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("global y [m]")
    ax.set_ylabel("global x [m]")
    ax.set_title("plan view from above (x up, y right, z down)\nopen: start, filled: end", fontsize=9)
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=3)
    ax.grid(True, alpha=0.3)

    ax = axs[1]
    for i in range(res.n_gears):
        touch = np.nonzero(res.normal_force[:, i] > 0)[0]
        k0 = int(touch[0]) if touch.size else 0
        dx = (fp[k0:, i, 0] - fp[k0, i, 0]) * MM
        dy = (fp[k0:, i, 1] - fp[k0, i, 1]) * MM
        ax.plot(dy, dx, color=_gear_color(i), label=f"footpad {i + 1}: slide {res.slide_distance[i] * MM:.1f} mm")
        ax.plot(dy[-1], dx[-1], "o", color=_gear_color(i))
    ax.plot(0, 0, "k+", ms=10)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("displacement y [mm]")
    ax.set_ylabel("displacement x [mm]")
    ax.set_title("horizontal footpad displacement since its first contact\n(includes motion after a lift-off)",
                 fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(True, alpha=0.3)
    _title(fig, res, "Footpad paths on the ground")
    fig.tight_layout()
    return fig


ENERGY_STACK = (("kinetic_body", "body kinetic"), ("kinetic_legs", "legs (relative)"),
                ("honeycomb_work", "honeycomb crush"), ("contact_damping", "contact damping"),
                ("contact_elastic", "contact elastic"), ("friction", "friction"),
                ("strut_impacts", "strut impacts"))


def fig_energy(res: Result):
    """Energy audit: where the input energy went, stacked over time, and the residual."""
    plt = _plt()
    fig, axs = plt.subplots(2, 1, figsize=(8, 7), sharex=True, gridspec_kw={"height_ratios": [3, 1]})
    t, e = res.time, res.energy
    axs[0].stackplot(t, *[e[k] / 1e3 for k, _ in ENERGY_STACK], labels=[lab for _, lab in ENERGY_STACK], alpha=0.8)
    axs[0].plot(t, e["input"] / 1e3, color="k", lw=1.5, label="input (KE0 + potential + thrust)")
    axs[0].set_ylabel("energy [kJ]")
    axs[0].legend(fontsize=7, loc="center right")
    e_in = max(abs(res.energy_input), 1e-30)
    axs[1].plot(t, e["residual"] / e_in * 100, color="k")
    axs[1].axhline(0, color="0.5", lw=0.6)
    axs[1].set_ylabel("residual [% of input]")
    axs[1].set_xlabel("time [s]")
    axs[1].annotate(f"final residual {res.energy_residual * 100:.3f} %", (0.01, 0.9), xycoords="axes fraction",
                    fontsize=8, va="top")
    for ax in axs:
        ax.grid(True, alpha=0.3)
    _title(fig, res, "Energy audit")
    fig.tight_layout()
    return fig


#: (name, function, caption) of every standard figure, in report order
FIGURES = (
    ("strokes", fig_strokes, "stroke time history of every strut (paper Fig. 9)"),
    ("crush_lengths", fig_crush_lengths, "final crush length per gear and strut with capacities (paper Fig. 8)"),
    ("footpad_forces", fig_footpad_forces, "footpad normal and friction forces, penetration (paper Fig. 11)"),
    ("body", fig_body, "body velocity, attitude and overload"),
    ("footpad_paths", fig_footpad_paths, "footpad paths on the ground"),
    ("energy", fig_energy, "energy audit stacked over time"),
)


def write_figures(res: Result, outdir: str, formats=("png",), dpi: int = 120, only=None) -> list[str]:
    """Writes the standard figures; returns the file names."""
    plt = _plt()
    written = []
    base = os.path.splitext(os.path.basename(res.path))[0]
    for name, func, _ in FIGURES:
        if only and name not in only:
            continue
        fig = func(res)
        for fmt in formats:
            fn = os.path.join(outdir, f"{base}_{name}.{fmt}")
            fig.savefig(fn, dpi=dpi)
            written.append(fn)
        plt.close(fig)
    return written


def _main(argv=None) -> int:
    p = cli.make_parser(
        "landyn-plot", "Standard figures of a LANDYN result file (PNG and/or PDF), optionally a report PDF.",
        epilog="figures:\n" + "\n".join(f"  {n:15s} {c}" for n, _, c in FIGURES)
        + "\n\nexample:\n  landyn-plot landyn.h5 -o plots --format png pdf --report")
    p.add_argument("file", metavar="FILE", help="LANDYN result file (.h5)")
    p.add_argument("-o", "--outdir", metavar="OUTDIR", help="output directory (default: <FILE stem>_plots)")
    p.add_argument("--format", nargs="+", choices=("png", "pdf"), default=["png"], metavar="{png,pdf}",
                   help="figure format(s), e.g. --format png pdf (default png)")
    p.add_argument("--dpi", type=int, default=120, help="PNG resolution (default 120)")
    p.add_argument("--only", nargs="+", choices=[n for n, _, _ in FIGURES], metavar="NAME",
                   help="write only these figures")
    p.add_argument("--report", action="store_true",
                   help="also write <stem>_report.pdf: summary table and provenance first, then every figure")
    a = p.parse_args(argv)
    res = load(a.file)
    outdir = cli.output_dir(a.outdir or cli.stem(a.file) + "_plots")
    for fn in write_figures(res, outdir, a.format, a.dpi, a.only):
        print(fn)
    if a.report:
        from .report import write_report
        print(write_report(res, os.path.join(outdir, cli.stem(a.file) + "_report.pdf")))
    return cli.EXIT_OK


def main(argv=None) -> int:
    return cli.run("landyn-plot", _main, argv)


if __name__ == "__main__":
    sys.exit(main())
