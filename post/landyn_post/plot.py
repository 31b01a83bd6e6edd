"""landyn-plot: standard figures of one LANDYN result file (and the --report PDF).

Figures (file names ``<stem>_<name>.<fmt>`` in OUTDIR). Curves that coincide or nearly coincide
(the symmetric gear pairs of a symmetric landing) are drawn so that every one stays visible
(dashed with markers on top of the first) and a note names them; legends stand outside the axes
and reference lines are named on the right-hand axis, off the data.

  strokes         stroke time history of every strut (paper Fig. 9)
  strut_forces    axial force of every strut over time
  force_stroke    force-stroke hysteresis of every strut
  crush_lengths   final crush length per gear and strut, stroke capacities marked (paper Fig. 8),
                  with the paper's Table 3 values for its load cases or a reference CSV
  footpad_forces  footpad normal and friction forces and penetration (paper Fig. 11)
  body            body velocity, attitude and tilt, overload
  footpad_paths   footpad paths on the ground, plan view and displacement from touchdown
  energy          energy audit stacked over time, residual
"""
from __future__ import annotations

import os
import sys
from dataclasses import dataclass, field

import numpy as np

from . import cli
from .schema import STRUT_LABELS, STRUTS, LandynPostError, Result, load, measure_number

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


@dataclass
class PlotOptions:
    """Options of the figures: CFC class of the acceleration channels, reference crush lengths
    (m by measure, with a label) and the success criteria of the report's verdict."""
    cfc: int | None = None
    crush_ref: dict = field(default_factory=dict)
    crush_ref_label: str = ""
    crush_ref2: dict = field(default_factory=dict)
    crush_ref2_label: str = ""
    min_stroke_margin: float = 0.0        # m
    max_overload: float | None = None     # g


#: marker and dash patterns given, in turn, to the later members of a group of coincident curves
_COINCIDENT_STYLES = (("--", "o"), (":", "s"), ("-.", "^"), ((0, (1, 3)), "v"))

#: curves closer than OVERLAP_REL of the axis span (about a line width) are drawn on top of each
#: other there; a curve that does so for at least OVERLAP_SHARE of the samples and never parts by
#: more than OVERLAP_MAX is styled as coincident with the first ("≈" in the note, with its largest
#: difference). LC-3's symmetric gears: >= 94 % of the samples within 1 %, apart by <= 5.4 %; the
#: other pairs: <= 73 % within 1 %, apart by >= 54 %.
OVERLAP_REL = 1e-2
OVERLAP_SHARE = 0.9
OVERLAP_MAX = 0.1


def _span(curves: list[np.ndarray]) -> float:
    allv = np.concatenate([np.ravel(c) for c in curves]) if curves else np.zeros(0)
    allv = allv[np.isfinite(allv)]
    return float(np.max(allv) - np.min(allv)) if allv.size else 0.0


def coincident_groups(curves: list[np.ndarray], rel: float = 2e-3) -> list[list[int]]:
    """Groups of curves that lie on top of each other: max |y_i - y_j| <= rel x the span of all
    curves (0.2 %: closer than a line width). Each group lists indices, first one first."""
    return [[i for i, _ in g] for g in overlap_groups(curves, rel, near=rel, share=1.0)]


def overlap_groups(curves: list[np.ndarray], rel: float = 2e-3, near: float = OVERLAP_REL,
                   share: float = OVERLAP_SHARE, most: float = OVERLAP_MAX) -> list[list[tuple[int, float]]]:
    """Groups of curves that hide each other: a curve joins the closest group whose first curve it
    follows within `rel` of the span of all curves everywhere (identical to the eye), or within
    `near` for at least `share` of the samples and within `most` everywhere (drawn under it most
    of the time, e.g. LC-3's symmetric gears that part by a few % late in the run). Each group
    lists (index, largest difference as a fraction of the span), the first curve first with 0."""
    if not curves:
        return []
    span = _span(curves)
    scale = span if span > 0 else 1e-12
    groups: list[list[tuple[int, float]]] = []
    for i, c in enumerate(curves):
        best, best_d = None, np.inf
        for g in groups:
            lead = curves[g[0][0]]
            if np.shape(lead) != np.shape(c):
                continue
            d = np.abs(np.asarray(c, float) - np.asarray(lead, float))
            d = np.where(np.isfinite(d), d, np.inf)
            dmax = float(np.max(d)) if d.size else 0.0
            hides = dmax <= rel * scale or (dmax <= most * scale and float(np.mean(d <= near * scale)) >= share)
            if hides and dmax < best_d:
                best, best_d = g, dmax
        if best is None:
            groups.append([(i, 0.0)])
        else:
            best.append((i, best_d / scale))
    return groups


def draw_curves(ax, t, curves: list[tuple[str, np.ndarray, dict]], rel: float = 2e-3) -> str:
    """Plots (label, y, style) curves so that curves hiding each other stay visible: the first
    curve of an overlapping group is drawn wider and paler, the later ones on top with markers
    (offset from each other) and, where their own line style is the first one's, a dashed or
    dotted style. Returns a note naming them ('' when none), for the figure's footnote (see
    _footnote): 'gear 1 = gear 4' within `rel` of the axis span everywhere, 'gear 1 ≈ gear 4 (up
    to 2.5 %)' when they overlap most of the run but part by more somewhere."""
    groups = overlap_groups([c[1] for c in curves], rel)
    style_of: dict[int, dict] = {}
    notes = []
    n = len(t)
    every = max(1, n // 12)
    for g in groups:
        if len(g) < 2:
            continue
        lead = curves[g[0][0]][0]
        if all(d <= rel for _, d in g):
            notes.append(" = ".join(curves[i][0] for i, _ in g))
        else:
            notes.append(" ≈ ".join([lead] + [f"{curves[i][0]} (up to {100 * d:.1f} %)" if d > rel
                                              else curves[i][0] for i, d in g[1:]]))
        style_of[g[0][0]] = dict(lw=2.6, alpha=0.6)
        lead_ls = curves[g[0][0]][2].get("ls", "-")
        for rank, (i, _) in enumerate(g[1:]):
            ls, mk = _COINCIDENT_STYLES[rank % len(_COINCIDENT_STYLES)]
            st = dict(marker=mk, ms=4, mfc="none", markevery=(every * (rank + 1) // len(g), every), lw=1.2)
            if curves[i][2].get("ls", "-") == lead_ls:
                st["ls"] = ls
            style_of[i] = st
    for i, (label, y, style) in enumerate(curves):
        st = dict(style)
        st.update(style_of.get(i, {}))
        ax.plot(t, y, label=label, **st)
    return "; ".join(notes)


FOOTNOTE_WIDTH = 150   #: characters per footnote line (6.5 pt on an 8-9.5 in wide figure)


def _wrap_items(head: str, items: list[str], width: int) -> list[str]:
    """Lines of `head` followed by the items separated by '; ', broken only between items (a
    curve's name such as 'footpad 3' is never split over two lines)."""
    lines, cur = [], head
    for k, item in enumerate(items):
        piece = item + (";" if k < len(items) - 1 else "")
        if len(cur) + 1 + len(piece) > width and cur.strip():
            lines.append(cur)
            cur = "    " + piece
        else:
            cur = f"{cur} {piece}" if cur else piece
    lines.append(cur)
    return lines


def _footnote(fig, notes: list[tuple[str, str]]) -> float:
    """Writes the notes on curves drawn on top of each other under the figure; returns the bottom
    margin to keep free."""
    lines = []
    for where, note in notes:
        if note:
            lines += _wrap_items(f"{where}:", note.split("; "), FOOTNOTE_WIDTH)
    if not lines:
        return 0.0
    lines.insert(0, "Curves on top of each other (later ones with markers; = within 0.2 % of the axis span "
                    "everywhere, ≈ within 1 % for most of the run, largest difference in % of the span):")
    fig.text(0.01, 0.005, "\n".join(lines), fontsize=6.5, color="0.2", va="bottom", ha="left")
    return 0.012 + 0.016 * len(lines)


def _level_labels(ax, levels: list[tuple[float, str]]):
    """Names horizontal reference lines (crush levels, capacities, stage ends) on a secondary
    axis at the right edge, off the data and off the lines: a label on the line itself is struck
    through by it and by the curves that run along it. Returns the secondary axis (or None)."""
    if not levels:
        return None
    sax = ax.secondary_yaxis("right")
    vals = [v for v, _ in levels]
    sax.set_yticks(vals, labels=[lab for _, lab in levels])
    sax.tick_params(labelsize=7, colors="0.3", length=3)
    return sax


def _legend_right(fig, ax, sax=None, **kw):
    """Legend outside the axes on the right, beyond the reference-line labels of `sax` if any, so
    that it covers neither data nor labels."""
    from matplotlib.transforms import offset_copy
    kw.setdefault("fontsize", 7)
    width_pt = 4.0
    if sax is not None:
        fig.canvas.draw()
        box = sax.get_tightbbox(fig.canvas.get_renderer())
        width_pt += (box.x1 - ax.get_window_extent().x1) * 72.0 / fig.dpi
    return ax.legend(loc="upper left", bbox_to_anchor=(1.0, 1.0), borderaxespad=0.0,
                     bbox_transform=offset_copy(ax.transAxes, fig=fig, x=width_pt, y=0.0, units="points"), **kw)


def _tilt(res: Result) -> np.ndarray:
    """Angle between the lander z axis and the vertical, deg (R33 = cos(pitch) cos(roll))."""
    e = np.radians(res.euler_angles)
    return np.degrees(np.arccos(np.clip(np.cos(e[:, 1]) * np.cos(e[:, 2]), -1.0, 1.0)))


# ----------------------------------------------------------------------------------------- figures

def fig_strokes(res: Result, opts: PlotOptions | None = None):
    """Stroke of every strut over time (paper Fig. 9): primaries and secondaries, capacities marked."""
    plt = _plt()
    fig, axs = plt.subplots(2, 1, figsize=(9.5, 7), sharex=True)
    t = res.time
    cap = res.strut_capacity()
    notes = [("(a) primaries", draw_curves(axs[0], t, [(f"gear {i + 1}", res.stroke[:, i, 0] * MM,
                                                         dict(color=_gear_color(i))) for i in range(res.n_gears)])),
             ("(b) secondaries", draw_curves(axs[1], t, [(f"gear {i + 1} {STRUT_LABELS[STRUTS[k]].split()[1]}",
                                                         res.stroke[:, i, k] * MM,
                                                         dict(color=_gear_color(i), ls=STRUT_STYLES[k]))
                                                        for i in range(res.n_gears) for k in (1, 2)]))]
    lv0 = []
    for k, s_end in enumerate(res.primary_stage_ends()[:-1]):
        axs[0].axhline(s_end * MM, color="0.5", lw=0.8, ls=":")
        lv0.append((s_end * MM, f"stage {k + 1} end"))
    lv0 += _capacity_lines(axs[0], cap[:, 0, 0], None)
    lv1 = _capacity_lines(axs[1], cap[:, 1, 0], cap[:, 1, 1])
    axs[0].set_ylabel("primary stroke [mm]\n(shortening +)")
    axs[1].set_ylabel("secondary stroke [mm]\n(lengthening +)")
    axs[1].set_xlabel("time [s]")
    axs[0].set_title("(a) primary struts", fontsize=9, loc="left")
    axs[1].set_title("(b) secondary struts: left dashed, right dotted", fontsize=9, loc="left")
    for ax in axs:
        ax.grid(True, alpha=0.3)
    _legend_right(fig, axs[0], _level_labels(axs[0], lv0))
    _legend_right(fig, axs[1], _level_labels(axs[1], lv1), fontsize=6.5)
    _title(fig, res, "Strut strokes")
    fig.tight_layout(rect=(0, _footnote(fig, notes), 1, 1))
    return fig


def fig_strut_forces(res: Result, opts: PlotOptions | None = None):
    """Axial force of every strut over time (compression +), primaries and secondaries, with the
    honeycomb crush levels."""
    plt = _plt()
    fig, axs = plt.subplots(2, 1, figsize=(9.5, 7), sharex=True)
    t = res.time
    notes = [("(a) primaries", draw_curves(axs[0], t, [(f"gear {i + 1}", res.strut_force[:, i, 0] * KN,
                                                         dict(color=_gear_color(i))) for i in range(res.n_gears)])),
             ("(b) secondaries", draw_curves(axs[1], t, [(f"gear {i + 1} {STRUT_LABELS[STRUTS[k]].split()[1]}",
                                                         res.strut_force[:, i, k] * KN,
                                                         dict(color=_gear_color(i), ls=STRUT_STYLES[k]))
                                                        for i in range(res.n_gears) for k in (1, 2)]))]
    levels = _crush_levels(res)
    for ax, lv in ((axs[0], levels["primary"]), (axs[1], levels["secondary"])):
        for v, _ in lv:
            ax.axhline(v * KN, color="0.5", lw=0.8, ls=":")
    pk = res.peak_strut_force
    axs[0].set_title(f"(a) primary struts; peak {np.max(pk[:, 0]) * KN:.1f} kN (every step)", fontsize=9, loc="left")
    axs[1].set_title(f"(b) secondary struts, left dashed, right dotted; peak {np.max(pk[:, 1:]) * KN:.1f} kN",
                     fontsize=9, loc="left")
    axs[0].set_ylabel("primary axial force [kN]\n(compression +)")
    axs[1].set_ylabel("secondary axial force [kN]\n(compression +)")
    axs[1].set_xlabel("time [s]")
    for ax in axs:
        ax.grid(True, alpha=0.3)
    _legend_right(fig, axs[0], _level_labels(axs[0], [(v * KN, w) for v, w in levels["primary"]]))
    _legend_right(fig, axs[1], _level_labels(axs[1], [(v * KN, w) for v, w in levels["secondary"]]), fontsize=6.5)
    _title(fig, res, "Strut axial forces")
    fig.tight_layout(rect=(0, _footnote(fig, notes), 1, 1))
    return fig


def _crush_levels(res: Result) -> dict[str, list[tuple[float, str]]]:
    """Crush levels to draw (N, signed as the axial force: compression +, with their labels): the
    primary panel's from strut 0, the secondary panel's from the others, each level once
    (Result.crush_levels: /model/crush_levels, the resolved input for a file older than 1.5)."""
    out: dict[str, list[tuple[float, str]]] = {"primary": [], "secondary": []}
    seen: set[tuple[str, float, str]] = set()
    for _, k, f, name in res.crush_levels():
        panel = "primary" if k == 0 else "secondary"
        if (panel, f, name) not in seen:
            seen.add((panel, f, name))
            out[panel].append((f, f"{name} {abs(f) * KN:.0f} kN"))
    return out


def fig_force_stroke(res: Result, opts: PlotOptions | None = None):
    """Force-stroke hysteresis of every strut: axial force (compression +) over stroke (Table 3
    sense), one panel per strut, the start and end marked; the area is the work of the strut."""
    plt = _plt()
    g = res.n_gears
    ns = res.n_struts
    fig, axs = plt.subplots(g, ns, figsize=(10, 2.3 * g + 1.2), squeeze=False)
    for i in range(g):
        for k in range(ns):
            ax = axs[i, k]
            x = res.stroke[:, i, k] * MM
            y = res.strut_force[:, i, k] * KN
            ax.plot(x, y, color=STRUT_COLORS[k], lw=1.0)
            ax.plot(x[0], y[0], "o", color="k", ms=3, mfc="none")
            ax.plot(x[-1], y[-1], "o", color="k", ms=3)
            ax.set_title(f"No. {measure_number(i + 1, k, ns)}: gear {i + 1} {STRUT_LABELS[STRUTS[k]]}, "
                         f"work {res.crush_work[i, k] / 1e3:.1f} kJ", fontsize=7)
            ax.tick_params(labelsize=6)
            ax.grid(True, alpha=0.3)
            if i == g - 1:
                ax.set_xlabel("stroke [mm]" + ("\n(shortening +)" if k == 0 else "\n(lengthening +)"), fontsize=7)
            if k == 0:
                ax.set_ylabel("axial force [kN]\n(compression +)", fontsize=7)
    fig.text(0.5, 0.005, "open circle: start, filled: end", ha="center", fontsize=7)
    _title(fig, res, "Force-stroke hysteresis of every strut")
    fig.tight_layout(rect=(0, 0.015, 1, 1))
    return fig


def _capacity_lines(ax, cap_pos, cap_neg) -> list[tuple[float, str]]:
    """Draws the stroke capacities (+ and -) as lines; returns (value mm, label) for _level_labels."""
    out = []
    for vals, sign in ((cap_pos, 1), (cap_neg, -1)):
        if vals is None or not np.all(np.isfinite(vals)):
            continue
        c = float(np.max(vals)) * MM * sign
        ax.axhline(c, color="k", lw=1.0, ls="-.")
        out.append((c, f"capacity {c:+.0f} mm"))
    return out


def fig_crush_lengths(res: Result, opts: PlotOptions | None = None):
    """Final crush length of every strut as bars (paper Fig. 8), capacities and crushed lengths
    marked, and reference values (the paper's Table 3 for its load cases, or a reference CSV)."""
    plt = _plt()
    g, ns = res.n_gears, res.n_struts
    fig, ax = plt.subplots(figsize=(max(8, 0.6 * ns * g + 2), 5.5))
    cap = res.strut_capacity()
    x = np.arange(1, ns * g + 1)
    net = res.crush_length.reshape(-1) * MM
    colors = [STRUT_COLORS[k] for _ in range(g) for k in range(ns)]
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
    opts = opts or PlotOptions()
    for ref, lab, mk in ((opts.crush_ref, opts.crush_ref_label, "D"), (opts.crush_ref2, opts.crush_ref2_label, "P")):
        if ref:
            xm = np.array(sorted(ref))
            ax.scatter(xm, [ref[m] * MM for m in xm], marker=mk, s=28, color="white", edgecolor="k", zorder=6,
                       label=lab)
    ax.axhline(0, color="k", lw=0.6)
    ax.set_xticks(x)
    ax.set_xticklabels([f"{measure_number(i + 1, k, ns)}\nG{i + 1}{'PLR'[k]}" for i in range(g) for k in range(ns)],
                       fontsize=7)
    ax.set_xlabel("measure (Table 3): G = gear, P primary, L secondary left, R secondary right")
    ax.set_ylabel("crush length [mm]\n(primary shortening, secondary lengthening +)")
    from matplotlib.patches import Patch
    handles = [Patch(color=STRUT_COLORS[k], label=STRUT_LABELS[STRUTS[k]]) for k in range(ns)]
    h2, _ = ax.get_legend_handles_labels()
    ax.legend(handles=handles + h2, fontsize=7, ncol=6, loc="upper center", bbox_to_anchor=(0.5, -0.17))
    ax.grid(True, axis="y", alpha=0.3, zorder=0)
    _title(fig, res, "Crush length of each honeycomb buffer after touchdown")
    fig.tight_layout()
    return fig


def fig_footpad_forces(res: Result, opts: PlotOptions | None = None):
    """Footpad normal and friction forces and penetration over time (paper Fig. 11)."""
    plt = _plt()
    fig, axs = plt.subplots(3, 1, figsize=(9, 8), sharex=True)
    t = res.time
    notes = []
    for ax, data, scale, what in ((axs[0], res.normal_force, KN, "normal force"),
                                  (axs[1], res.friction_force, KN, "friction"), (axs[2], res.penetration, MM,
                                                                                 "penetration")):
        notes.append((what, draw_curves(ax, t, [(f"footpad {i + 1}", data[:, i] * scale, dict(color=_gear_color(i)))
                                                for i in range(res.n_gears)])))
    axs[0].set_ylabel("normal force [kN]")
    axs[1].set_ylabel("friction force [kN]\n(magnitude)")
    axs[2].set_ylabel("penetration [mm]\n(> 0 in the ground)")
    peak = max(0.5, float(np.max(res.penetration)) * MM)
    axs[2].set_ylim(-0.25 * peak, 1.15 * peak)   # before touchdown the footpads are far above
    axs[2].set_xlabel("time [s]")
    _legend_right(fig, axs[0])
    for ax in axs:
        ax.grid(True, alpha=0.3)
    _title(fig, res, "Footpad-ground contact forces")
    fig.tight_layout(rect=(0, _footnote(fig, notes), 1, 1))
    return fig


def fig_body(res: Result, opts: PlotOptions | None = None):
    """Body velocity, attitude (and tilt) and overload over time; the overload optionally filtered
    with a CFC class (SAE J211 / ISO 6487), the class named in the panel."""
    plt = _plt()
    opts = opts or PlotOptions()
    fig, axs = plt.subplots(3, 1, figsize=(9, 8.5), sharex=True)
    t = res.time
    notes = [("velocity", draw_curves(axs[0], t, [(f"v{lab}", res.velocity[:, k], dict(color=f"C{k}"))
                                                  for k, lab in enumerate(("x", "y", "z (down)"))])),
             ("attitude", draw_curves(axs[1], t, [(lab, res.euler_angles[:, k], dict(color=f"C{k}"))
                                                  for k, lab in enumerate(("yaw", "pitch", "roll"))]
                                      + [("tilt", _tilt(res), dict(color="k", ls="--"))]))]
    n = res.overload
    note = "unfiltered output samples"
    if opts.cfc:
        from .filters import cfc_filter, cfc_label, cfc_warning
        for k in range(3):
            axs[2].plot(t, n[:, k], color=f"C{k}", lw=0.6, alpha=0.35)
        n = cfc_filter(t, n, opts.cfc)
        note = f"filtered {cfc_label(opts.cfc)}; raw samples faint"
        warn = cfc_warning(t, opts.cfc)
        if warn:
            note += f"\n{warn}"
    notes.append(("overload", draw_curves(axs[2], t, [(f"n{lab}", n[:, k], dict(color=f"C{k}"))
                                                      for k, lab in enumerate(("x", "y", "z"))]
                                          + [("|n|", np.linalg.norm(n, axis=1), dict(color="k", ls="--"))])))
    peak_f = float(np.max(np.linalg.norm(n, axis=1)))
    title = (f"overload: {note}\npeak |n| of the curves {peak_f:.2f} g; unfiltered peak over every time step "
             f"{res.peak_overload:.2f} g at {res.time_of_peak_overload:.4f} s")
    if opts.cfc and peak_f > res.peak_overload:
        title += ("\nthe filtered peak exceeds the unfiltered: the Butterworth filter overshoots (rings) at the "
                  "steps of the crush forces, as every J211 filter does")
    axs[2].set_title(title, fontsize=7.5, loc="left")
    _min_span(axs[1], 2.0)
    axs[0].set_ylabel("mass-centre velocity [m/s]\n(global, z down)")
    axs[1].set_ylabel("attitude [deg]\n(Z-Y-X Euler)")
    axs[2].set_ylabel("overload [g]\n(lander axes)" + (f"\nCFC {opts.cfc}" if opts.cfc else ""))
    axs[2].set_xlabel("time [s]")
    for ax in axs:
        _legend_right(fig, ax)
        ax.grid(True, alpha=0.3)
    _title(fig, res, "Body motion")
    fig.tight_layout(rect=(0, _footnote(fig, notes), 1, 1))
    return fig


def fig_footpad_paths(res: Result, opts: PlotOptions | None = None):
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


def fig_interface_loads(res: Result, opts: PlotOptions | None = None):
    """Interface loads: magnitude of the force each hard point a, b, c puts on the body and of the
    footpad force at d, per gear, over time; the peak of every step (/summary/peak_joint_load) is
    marked, since the stored samples may miss it. None for files without interface loads (< 1.2)."""
    if res.data.get("joint_force_a") is None:
        return None
    plt = _plt()
    fig, axs = plt.subplots(4, 1, figsize=(9, 10), sharex=True)
    t = res.time
    notes = []
    blocks = (("a", res.joint_force_a, "joint a (primary, upper)"), ("b", res.joint_force_b, "joint b (left secondary)"),
              ("c", res.joint_force_c, "joint c (right secondary)"), ("d", res.footpad_joint_force, "footpad joint d"))
    peak = res.data.get("peak_joint_load/value")
    tpk = res.data.get("peak_joint_load/time")
    for j, (ax, (name, f, what)) in enumerate(zip(axs, blocks)):
        mag = np.linalg.norm(f, axis=2) * KN
        notes.append((what, draw_curves(ax, t, [(f"gear {i + 1}", mag[:, i], dict(color=_gear_color(i)))
                                               for i in range(res.n_gears)])))
        if peak is not None:
            for i in range(res.n_gears):
                ax.plot(tpk[i, j, 3], peak[i, j, 3] * KN, marker="v", ms=6, color=_gear_color(i), ls="none",
                        label="peak (every step)" if i == 0 else None)
        ax.set_ylabel(f"|force| at {name} [kN]")
        ax.set_title(what, fontsize=9, loc="left")
        ax.grid(True, alpha=0.3)
    _legend_right(fig, axs[0])
    axs[-1].set_xlabel("time [s]")
    _title(fig, res, "Interface loads on the body (a, b, c) and at the footpad (d)")
    fig.tight_layout(rect=(0, _footnote(fig, notes), 1, 1))
    return fig


def fig_energy(res: Result, opts: PlotOptions | None = None):
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
    # two significant digits (a residual of 2.4e-4 % is not "0.000 %"), on a white box above the curve
    axs[1].annotate(f"final residual {res.energy_residual * 100:.2g} %", (0.01, 0.9), xycoords="axes fraction",
                    fontsize=8, va="top", zorder=5, bbox=dict(facecolor="white", alpha=0.85, edgecolor="none", pad=1.5))
    for ax in axs:
        ax.grid(True, alpha=0.3)
    _title(fig, res, "Energy audit")
    fig.tight_layout()
    return fig


#: (name, function, caption) of every standard figure, in report order
FIGURES = (
    ("strokes", fig_strokes, "stroke time history of every strut (paper Fig. 9)"),
    ("strut_forces", fig_strut_forces, "axial force of every strut over time, crush levels marked"),
    ("force_stroke", fig_force_stroke, "force-stroke hysteresis of every strut"),
    ("crush_lengths", fig_crush_lengths, "final crush length per gear and strut with capacities (paper Fig. 8), "
                                         "Table 3 / reference values"),
    ("footpad_forces", fig_footpad_forces, "footpad normal and friction forces, penetration (paper Fig. 11)"),
    ("body", fig_body, "body velocity, attitude and overload (optionally CFC-filtered)"),
    ("footpad_paths", fig_footpad_paths, "footpad paths on the ground"),
    ("interface_loads", fig_interface_loads, "forces at the hard points a, b, c and the footpad joint d, per gear"),
    ("energy", fig_energy, "energy audit stacked over time"),
)


def write_figures(res: Result, outdir: str, formats=("png",), dpi: int = 120, only=None,
                  opts: PlotOptions | None = None) -> list[str]:
    """Writes the standard figures (each through a temporary file); returns the file names."""
    plt = _plt()
    written = []
    base = os.path.splitext(os.path.basename(res.path))[0]
    for name, func, _ in FIGURES:
        if only and name not in only:
            continue
        fig = func(res, opts)
        if fig is None:           # nothing to draw in this file (e.g. an older schema)
            continue
        for fmt in formats:
            written.append(cli.savefig(fig, os.path.join(outdir, f"{base}_{name}.{fmt}"), dpi=dpi))
        plt.close(fig)
    return written


def plot_options(a, res: Result) -> PlotOptions:
    """PlotOptions from the command line: the reference crush lengths are the paper's Table 3
    (theory and Adams) when the result is one of its load cases, or --reference CSV."""
    from .paper import load_case_of, table3
    o = PlotOptions(cfc=a.cfc, min_stroke_margin=a.min_stroke_margin / 1e3, max_overload=a.max_overload)
    if a.cfc:
        from .filters import cfc_filter
        cfc_filter(res.time, res.overload[:, 2], a.cfc)   # fails early, with its message, on a too-slow rate
    if a.reference:
        from .compare import read_strut_csv
        ref = read_strut_csv(a.reference, res.n_gears, a.load_case, a.ref_column)
        o.crush_ref, o.crush_ref_label = ref.values, ref.label
    else:
        lc = a.load_case or load_case_of(res)
        if lc:
            try:
                o.crush_ref, o.crush_ref_label = table3(lc, "theory"), f"paper Table 3, {lc}, theory"
                o.crush_ref2, o.crush_ref2_label = table3(lc, "adams"), f"paper Table 3, {lc}, MSC Adams"
            except KeyError:
                raise LandynPostError(f"--load-case {lc}: not one of the paper's load cases (LC-1 .. LC-4)") from None
    return o


def _main(argv=None) -> int:
    p = cli.make_parser(
        "landyn-plot", "Standard figures of a LANDYN result file (PNG and/or PDF), optionally a report PDF;\n"
        "for a landyn_study file the crush length per measure option and variant (<stem>_study.png).",
        epilog="figures:\n" + "\n".join(f"  {n:15s} {c}" for n, _, c in FIGURES)
        + "\n\nThe crush-length figure shows the paper's Table 3 (theory, MSC Adams) when the result's touchdown\n"
          "conditions are one of its load cases (or --load-case), or the values of --reference CSV.\n"
          "\nexample:\n  landyn-plot landyn.h5 -o plots --format png pdf --report --cfc 60")
    p.add_argument("file", metavar="FILE", help="LANDYN result file (.h5)")
    p.add_argument("-o", "--outdir", metavar="OUTDIR", help="output directory (default: <FILE stem>_plots)")
    p.add_argument("--format", nargs="+", choices=("png", "pdf"), default=["png"], metavar="{png,pdf}",
                   help="figure format(s), e.g. --format png pdf (default png)")
    p.add_argument("--dpi", type=cli.positive_int, default=120, help="PNG resolution (default 120)")
    p.add_argument("--only", nargs="+", choices=[n for n, _, _ in FIGURES], metavar="NAME",
                   help="write only these figures")
    p.add_argument("--report", action="store_true",
                   help="also write <stem>_report.pdf: touchdown conditions, verdict, tables and provenance "
                        "first, then every figure")
    p.add_argument("--cfc", type=int, choices=(60, 180, 600), metavar="{60,180,600}",
                   help="filter the overload (acceleration) with this SAE J211 / ISO 6487 channel frequency class")
    p.add_argument("--reference", metavar="CSV", help="reference crush lengths (mm) for the crush-length figure, "
                   "in landyn-compare's per-strut CSV layout")
    p.add_argument("--ref-column", metavar="NAME", help="value column of --reference (e.g. theory)")
    p.add_argument("--load-case", metavar="LC", help="the paper's load case whose Table 3 values are shown "
                   "(default: recognised from the touchdown conditions); with --reference: its rows")
    p.add_argument("--min-stroke-margin", type=float, default=0.0, metavar="MM",
                   help="verdict criterion: every stroke margin >= MM (default 0: no strut bottoms out)")
    p.add_argument("--max-overload", type=float, metavar="G", help="verdict criterion: peak overload <= G")
    a = p.parse_args(argv)
    from .exchange import file_kind
    kind = file_kind(a.file)
    if kind == "study":
        from .study import write_study_figures
        for fn in write_study_figures(a.file, cli.output_dir(a.outdir or cli.stem(a.file) + "_plots"), a.format, a.dpi):
            print(fn)
        return cli.EXIT_OK
    if kind == "campaign":
        raise LandynPostError(f"{a.file}: a campaign summary: plot it with landyn-dispersion (Monte Carlo: histograms, "
                              "failure causes, --sensitivity) or landyn-envelope (grid: stability envelope)")
    res = load(a.file)
    opts = plot_options(a, res)
    outdir = cli.output_dir(a.outdir or cli.stem(a.file) + "_plots")
    for fn in write_figures(res, outdir, a.format, a.dpi, a.only, opts):
        print(fn)
    if a.report:
        from .report import write_report
        print(write_report(res, os.path.join(outdir, cli.stem(a.file) + "_report.pdf"), opts))
    return cli.EXIT_OK


def main(argv=None) -> int:
    return cli.run("landyn-plot", _main, argv)


if __name__ == "__main__":
    sys.exit(main())
