"""The landyn-plot --report PDF: the touchdown conditions and a verdict against the success
criteria, summary tables and provenance on the first page, then every standard figure."""
from __future__ import annotations

import textwrap

import numpy as np

from .schema import STRUT_LABELS, STRUTS, Result, measure_number

MM = 1.0e3


def crush_table_lines(res: Result) -> list[str]:
    """Crush lengths in Table 3's layout (one row per measure) with margins and peak forces."""
    cap = res.strut_capacity()
    head = (f"{'No.':>3} {'gear':>4}  {'strut':<16}{'crush':>8}{'(+)':>8}{'(-)':>8}"
            f"{'capacity':>12}{'margin':>8}{'peak F':>8}{'work':>8}")
    units = f"{'':>3} {'':>4}  {'':<16}{'[mm]':>8}{'[mm]':>8}{'[mm]':>8}{'[mm]':>12}{'[mm]':>8}{'[kN]':>8}{'[kJ]':>8}"
    lines = [head, units, "-" * len(head)]
    for i in range(res.n_gears):
        for k in range(res.n_struts):
            c_pos, c_neg = cap[i, k]
            capt = f"+{c_pos * MM:.0f}" + (f"/-{c_neg * MM:.0f}" if np.isfinite(c_neg) else "")
            flag = " BOTTOMED" if res.bottomed_out[i, k] else ""
            lines.append(
                f"{measure_number(i + 1, k, res.n_struts):>3} {i + 1:>4}  {STRUT_LABELS[STRUTS[k]]:<16}"
                f"{res.crush_length[i, k] * MM:8.1f}{res.crushed_positive[i, k] * MM:8.1f}"
                f"{res.crushed_negative[i, k] * MM:8.1f}{capt:>12}{res.stroke_margin[i, k] * MM:8.1f}"
                f"{res.peak_strut_force[i, k] / 1e3:8.1f}{res.crush_work[i, k] / 1e3:8.2f}{flag}")
    return lines


def footpad_table_lines(res: Result) -> list[str]:
    """Per footpad: peak penetration, slide, peak normal force and (files with interface loads) the
    peak |force| the footpad puts on the primary at d, with a note when the two peaks differ."""
    pd = res.data.get("peak_joint_load/value")
    head = f"{'footpad':>7}{'peak penetration':>18}{'slide':>10}{'peak normal force':>19}"
    units = f"{'':>7}{'[mm]':>18}{'[mm]':>10}{'[kN]':>19}"
    if pd is not None:
        head += f"{'peak |force| at d':>19}"
        units += f"{'[kN]':>19}"
    lines = [head, units, "-" * len(head)]
    for i in range(res.n_gears):
        lines.append(f"{i + 1:>7}{res.peak_penetration[i] * MM:18.2f}{res.slide_distance[i] * MM:10.1f}"
                     f"{res.peak_normal_force[i] / 1e3:19.1f}" + (f"{pd[i, 3, 3] / 1e3:19.1f}" if pd is not None else ""))
    return lines + footpad_peak_notes(res)


def footpad_peak_notes(res: Result) -> list[str]:
    """Why the peak ground force can exceed the peak force at the footpad joint d: the footpad's
    own inertia takes the difference, largest in the short stiff-contact spikes of first contact."""
    pd = res.data.get("peak_joint_load/value")
    if pd is None:
        return []
    nf, fd = float(np.max(res.peak_normal_force)), float(np.max(pd[:, 3, 3]))
    if nf <= fd * 1.05:
        return []
    return textwrap.wrap(
        f"The peak ground normal force ({nf / 1e3:.1f} kN) exceeds the peak force at the footpad joint d "
        f"({fd / 1e3:.1f} kN): d carries the ground force less the footpad's own inertia (mass x acceleration), "
        "and the ground force peaks in short, stiff-contact spikes (touchdown and re-contacts, fractions of a "
        "millisecond) that mostly accelerate the footpad instead of loading the strut. Both are peaks over "
        "every time step; the strut and the body see the force at d.", 100)


def touchdown_lines(res: Result) -> list[str]:
    """Touchdown conditions (paper.touchdown_conditions: /model): velocity, attitude, slope, friction, mass."""
    from .paper import load_case_of, touchdown_conditions
    c = touchdown_conditions(res)
    lc = load_case_of(res)
    return [
        f"load case: {lc + ' of the paper (Table 2)' if lc else 'not one of the paper load cases'}",
        f"velocity: vertical {c['v_vertical']:.3f} m/s (down), horizontal {c['v_horizontal']:.3f} m/s "
        f"toward {c['v_direction']:.1f} deg from global +x",
        f"attitude (Z-Y-X): yaw {c['yaw']:.3f}, pitch {c['pitch']:.3f}, roll {c['roll']:.3f} deg",
        f"terrain: slope {c['slope']:.2f} deg, uphill toward {c['slope_direction']:.1f} deg"
        + ("" if c["slope_uniform"] == 1.0 else " (footpad 1; the footpads' planes differ)"),
        f"friction: mu_static {c['mu_static']:.3g}, mu_dynamic {c['mu_dynamic']:.3g}; "
        f"mass {c['mass']:.0f} kg, gravity {c['gravity']:.3g} m/s^2",
    ]


#: the outcome classes of /summary/outcome (docs/output.md, "Outcome")
OUTCOMES = {1: "no_touchdown", 2: "at_rest", 3: "still_moving", 4: "tipped_over"}


def outcome_lines(res: Result) -> list[str]:
    """The outcome block: the class, the end state's speeds and the stability figures (schema 1.3;
    an older file has none: said so)."""
    code = res.data.get("outcome/code")
    if code is None:
        return ["no outcome in this file (schema before 1.3): rest and touchdown not decided"]
    name = OUTCOMES.get(int(code), "not classified")
    lines = [f"outcome: {name.replace('_', ' ')} at t = {res.final_time:.3f} s"]
    if name == "still_moving":
        lines.append("  inconclusive: neither at rest nor tipped over at the end time; run longer (t_end) to decide")
    lines.append(f"end state: body speed {res.data['outcome/body_speed']:.3g} m/s, angular rate "
                 f"{res.data['outcome/angular_rate']:.3g} deg/s,")
    lines.append(f"           slide rate {res.data['outcome/slide_rate']:.3g} m/s, "
                 f"stroke rate {res.data['outcome/stroke_rate']:.3g} m/s")
    if name != "no_touchdown":
        ratio = np.atleast_1d(res.data["outcome/friction_ratio"])
        lines.append(f"tip-over margin {res.data['outcome/tipover_margin']:.2f} deg (final state)")
        lines.append("static friction ratio |F_t|/(mu_s F_n) per footpad: " + ", ".join(f"{r:.2f}" for r in ratio))
    return lines


def verdict(res: Result, min_stroke_margin: float = 0.0, max_overload: float | None = None) -> tuple[bool, list[str]]:
    """(success, lines): the run against the success criteria of a campaign's &criteria: it touched
    down and came to rest (outcome at_rest; schema 1.3), did not tip over, every stroke margin >=
    min_stroke_margin (m), and (when given) peak overload <= max_overload (g). A run still moving at
    its end is inconclusive, never a success; one that never touched down is no landing."""
    lines, ok = [], True

    def crit(good: bool, text: str):
        nonlocal ok
        ok &= good
        lines.append(f"  [{'met' if good else 'FAILED'}] {text}")

    code = res.data.get("outcome/code")
    name = OUTCOMES.get(int(code), "not classified") if code is not None else None
    if name == "no_touchdown":
        crit(False, "touchdown (no footpad touched the ground)")
        return False, (["NO TOUCHDOWN: the lander never touched the ground"] + lines
                       + [f"  run ended: {res.end_reason} at {res.final_time:.3f} s"])
    crit(not res.tipped_over, f"no tip-over (largest tilt {res.max_tilt:.2f} deg)")
    m = float(np.min(res.stroke_margin))
    i, k = np.unravel_index(int(np.argmin(res.stroke_margin)), res.stroke_margin.shape)
    crit(m >= min_stroke_margin, f"every stroke margin >= {min_stroke_margin * MM:.1f} mm (smallest {m * MM:.1f} mm, "
         f"No. {measure_number(i + 1, k, res.n_struts)} gear {i + 1} {STRUT_LABELS[STRUTS[k]]}"
         + (f"; {int(np.sum(res.bottomed_out))} bottomed out)" if np.any(res.bottomed_out) else ")"))
    if max_overload is not None:
        crit(res.peak_overload <= max_overload, f"peak overload <= {max_overload:g} g "
             f"({res.peak_overload:.2f} g)")
    decided = True
    if name is None:
        crit(False, "at rest: not decided (file before schema 1.3 has no outcome)")
        decided = False
    elif not res.tipped_over:
        decided = name == "at_rest"
        crit(decided, "came to rest" + ("" if decided else
                                       f" (still moving at {res.final_time:.3f} s: body speed "
                                       f"{res.data['outcome/body_speed']:.3g} m/s)"))
    if ok:
        head = "SUCCESSFUL LANDING: at rest, every criterion met"
    elif not decided and sum("[FAILED]" in ln for ln in lines) == 1:
        head = "INCONCLUSIVE: still moving at the end time, not a success"
    else:
        head = "NOT A SUCCESSFUL LANDING: criteria failed"
    return ok, [head] + lines + [f"  run ended: {res.end_reason} at {res.final_time:.3f} s"]


def run_summary_lines(res: Result) -> list[str]:
    fa = res.final_attitude
    return [
        f"end: {res.end_reason} at t = {res.final_time:.4f} s after {res.n_steps} steps "
        f"(wall time {res.wall_time:.2f} s)",
        f"peak overload at the mass centre: {res.peak_overload:.3f} g at t = {res.time_of_peak_overload:.4f} s",
        f"final attitude (yaw, pitch, roll): {fa[0]:.3f}, {fa[1]:.3f}, {fa[2]:.3f} deg",
        f"tilt: final {res.final_tilt:.3f} deg, largest {res.max_tilt:.3f} deg; "
        + ("TIPPED OVER" if res.tipped_over else "did not tip over")
        + ("; at rest" if res.at_rest else ""),
        f"energy: input {res.energy_input / 1e3:.2f} kJ, audit residual {res.energy_residual * 100:.4f} %",
        f"constraint violation after correction {res.max_constraint_violation:.3e} m, "
        f"drift per step {res.max_constraint_drift:.3e} m",
        f"strokes: {int(np.sum(res.bottomed_out))} strut(s) bottomed out; smallest margin "
        f"{np.min(res.stroke_margin) * MM:.1f} mm",
    ]


def _text_page(pdf, title: str, blocks: list[tuple[str, list[str]]], banner: tuple[str, bool] | None = None) -> None:
    """The text pages: title, verdict banner and blocks of lines; a block that does not fit on the
    page continues on the next one (nothing is cut at the page's foot)."""
    import matplotlib.pyplot as plt
    bottom = 0.035
    fig = plt.figure(figsize=(8.27, 11.69))   # A4 portrait
    title_lines = textwrap.wrap(title, 75)
    fig.text(0.06, 0.965, "\n".join(title_lines), fontsize=12, weight="bold", va="top", linespacing=1.3)
    y = 0.94 - 0.02 * len(title_lines)
    if banner is not None:
        text, ok = banner
        fig.text(0.06, y, text, fontsize=13, weight="bold", va="top", color="white",
                 bbox=dict(boxstyle="round,pad=0.4", ec="none",
                           fc={True: "#2e7d32", False: "#c62828"}.get(ok, "#b26a00")))
        y -= 0.04

    def new_page(heading: str):
        nonlocal fig, y
        pdf.savefig(fig)
        plt.close(fig)
        fig = plt.figure(figsize=(8.27, 11.69))
        fig.text(0.06, 0.965, f"{textwrap.shorten(title, 70)} (continued)", fontsize=9, color="0.4", va="top")
        y = 0.935
        if heading:
            fig.text(0.06, y, heading + " (continued)", fontsize=10, weight="bold", va="top")
            y -= 0.022

    for heading, lines in blocks:
        if y - 0.022 - 0.0135 * min(len(lines), 3) < bottom:
            new_page("")
        fig.text(0.06, y, heading, fontsize=10, weight="bold", va="top")
        y -= 0.022
        size = 7.5 if max((len(s) for s in lines), default=0) <= 100 else 6.5
        for line in lines:
            if y - 0.0135 * size / 7.5 < bottom:
                new_page(heading)
            fig.text(0.06, y, line, fontsize=size, family="monospace", va="top")
            y -= 0.0135 * size / 7.5
        y -= 0.012
    pdf.savefig(fig)
    plt.close(fig)


def write_report(res: Result, path: str, opts=None) -> str:
    """Writes the multi-page report PDF (through a temporary file); returns its path."""
    from . import cli
    cli.use_agg()
    from matplotlib.backends.backend_pdf import PdfPages

    from .plot import FIGURES, PlotOptions
    import matplotlib.pyplot as plt

    opts = opts or PlotOptions()
    prov = []
    for label, value in res.provenance():
        wrapped = textwrap.wrap(str(value), 84) or [""]
        prov.append(f"{label + ':':<16}{wrapped[0]}")
        prov += [" " * 16 + w for w in wrapped[1:]]
    ok, verdict_lines = verdict(res, opts.min_stroke_margin, opts.max_overload)
    blocks = [
        ("Touchdown conditions", touchdown_lines(res)),
        ("Outcome", outcome_lines(res)),
        ("Verdict against the success criteria", verdict_lines[1:]),
        ("Crush lengths (Table 3 layout; primary shortening and secondary lengthening positive)",
         crush_table_lines(res)),
        ("Footpads", footpad_table_lines(res)),
        ("Run", run_summary_lines(res)),
        ("Provenance", prov),
    ]
    with cli.atomic_output(path, mode=None) as tmp:
        with PdfPages(tmp, metadata={"Title": f"LANDYN report: {res.title}", "Creator": "landyn-plot"}) as pdf:
            # green: success; amber: inconclusive (still moving); red: failed
            state = None if verdict_lines[0].startswith("INCONCLUSIVE") else ok
            _text_page(pdf, f"LANDYN result: {res.title}", blocks, (verdict_lines[0], state))
            for _, func, _ in FIGURES:
                fig = func(res, opts)
                if fig is None:       # nothing to draw in this file (e.g. an older schema)
                    continue
                pdf.savefig(fig)
                plt.close(fig)
    return path
