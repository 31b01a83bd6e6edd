"""The landyn-plot --report PDF: summary tables and provenance, then every standard figure."""
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
        for k in range(3):
            c_pos, c_neg = cap[i, k]
            capt = f"+{c_pos * MM:.0f}" + (f"/-{c_neg * MM:.0f}" if np.isfinite(c_neg) else "")
            flag = " BOTTOMED" if res.bottomed_out[i, k] else ""
            lines.append(
                f"{measure_number(i + 1, k):>3} {i + 1:>4}  {STRUT_LABELS[STRUTS[k]]:<16}"
                f"{res.crush_length[i, k] * MM:8.1f}{res.crushed_positive[i, k] * MM:8.1f}"
                f"{res.crushed_negative[i, k] * MM:8.1f}{capt:>12}{res.stroke_margin[i, k] * MM:8.1f}"
                f"{res.peak_strut_force[i, k] / 1e3:8.1f}{res.crush_work[i, k] / 1e3:8.2f}{flag}")
    return lines


def footpad_table_lines(res: Result) -> list[str]:
    head = f"{'footpad':>7}{'peak penetration':>18}{'slide':>10}{'peak normal force':>19}"
    lines = [head, f"{'':>7}{'[mm]':>18}{'[mm]':>10}{'[kN]':>19}", "-" * len(head)]
    for i in range(res.n_gears):
        lines.append(f"{i + 1:>7}{res.peak_penetration[i] * MM:18.2f}{res.slide_distance[i] * MM:10.1f}"
                     f"{res.peak_normal_force[i] / 1e3:19.1f}")
    return lines


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


def _text_page(pdf, title: str, blocks: list[tuple[str, list[str]]]) -> None:
    import matplotlib.pyplot as plt
    fig = plt.figure(figsize=(8.27, 11.69))   # A4 portrait
    title_lines = textwrap.wrap(title, 75)
    fig.text(0.06, 0.965, "\n".join(title_lines), fontsize=12, weight="bold", va="top", linespacing=1.3)
    y = 0.94 - 0.02 * len(title_lines)
    for heading, lines in blocks:
        fig.text(0.06, y, heading, fontsize=10, weight="bold", va="top")
        y -= 0.022
        size = 7.5 if max((len(s) for s in lines), default=0) <= 100 else 6.5
        for line in lines:
            fig.text(0.06, y, line, fontsize=size, family="monospace", va="top")
            y -= 0.0135 * size / 7.5
        y -= 0.012
    pdf.savefig(fig)
    plt.close(fig)


def write_report(res: Result, path: str) -> str:
    """Writes the multi-page report PDF; returns its path."""
    from . import cli
    cli.use_agg()
    from matplotlib.backends.backend_pdf import PdfPages

    from .plot import FIGURES
    import matplotlib.pyplot as plt

    prov = []
    for label, value in res.provenance():
        wrapped = textwrap.wrap(str(value), 84) or [""]
        prov.append(f"{label + ':':<16}{wrapped[0]}")
        prov += [" " * 16 + w for w in wrapped[1:]]
    blocks = [
        ("Crush lengths (Table 3 layout; primary shortening and secondary lengthening positive)",
         crush_table_lines(res)),
        ("Footpads", footpad_table_lines(res)),
        ("Run", run_summary_lines(res)),
        ("Provenance", prov),
    ]
    with PdfPages(path, metadata={"Title": f"LANDYN report: {res.title}", "Creator": "landyn-plot"}) as pdf:
        _text_page(pdf, f"LANDYN result: {res.title}", blocks)
        for _, func, _ in FIGURES:
            fig = func(res)
            pdf.savefig(fig)
            plt.close(fig)
    return path
