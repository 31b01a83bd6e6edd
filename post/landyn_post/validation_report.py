"""The landyn-compare --report PDF: one validation report of a comparison.

Page 1: the verdict, the summary table (per channel: deviation, allowed, peak error, Sprague &
Geers C, ISO/TS 18571 rating and grade, coverage, pass/fail), every failure, and the provenance
of both files and the options used (alignment, filter, resampling). Then one page per channel:
the overlay, the deviation and the metrics; a crush-length page when crush lengths were compared.
"""
from __future__ import annotations

import datetime
import hashlib
import os
import shlex
import textwrap

import numpy as np

from . import cli
from .schema import Result

MM = 1.0e3


def file_provenance(path: str) -> list[tuple[str, str]]:
    """(label, value): absolute path, size, modification time (UTC) and SHA-256 of a file."""
    st = os.stat(path)
    h = hashlib.sha256()
    with open(path, "rb") as fh:
        for block in iter(lambda: fh.read(1 << 20), b""):
            h.update(block)
    when = datetime.datetime.fromtimestamp(st.st_mtime, datetime.timezone.utc).strftime("%Y-%m-%d %H:%M:%S UTC")
    return [("file", os.path.abspath(path)), ("size", f"{st.st_size} bytes"), ("modified", when),
            ("sha256", h.hexdigest())]


def _verdict(checks) -> str:
    if checks.failures:
        return f"FAIL: {len(checks.failures)} of the checks failed"
    if checks.n_checked == 0:
        return "NOTHING CHECKED: no tolerance applied; the deviations are not a verdict"
    return f"PASS: all {checks.n_checked} checks passed"


def _summary_rows(stats) -> list[list[str]]:
    rows = []
    for st in stats:
        u, f = st.series.display()
        m = st.metrics
        iso = m.iso
        rows.append([st.series.label.split(" -> ")[0], u, f"{st.rms * f:.4g}",
                     "-" if st.allowed is None else f"{st.allowed * f:.4g}",
                     f"{m.peak_error_pct:+.2f}" if np.isfinite(m.peak_error_pct) else "-",
                     f"{m.sg_c:.3f}" if np.isfinite(m.sg_c) else "-",
                     f"{iso.overall:.3f}" if iso else "-", iso.grade if iso else "-",
                     "-" if st.cov_run is None else f"{100 * st.cov_run:.0f}/{100 * st.cov_td:.0f}",
                     _channel_verdict(st)])
    return rows


def _channel_verdict(st) -> str:
    oks = ([st.passed] if st.passed is not None else []) + [c[3] for c in st.metric_checks]
    return "-" if not oks else ("pass" if all(oks) else "FAIL")


def _text_block(ax, lines: list[str], size: float = 7.0) -> None:
    ax.axis("off")
    ax.text(0.0, 1.0, "\n".join(lines), va="top", ha="left", family="monospace", fontsize=size,
            transform=ax.transAxes)


def _summary_page(pdf, plt, res: Result, ref_path: str, rows, stats, checks, al, td_phase, opts, argv) -> None:
    fig = plt.figure(figsize=(8.27, 11.69))
    verdict = _verdict(checks)
    fig.text(0.06, 0.965, "LANDYN validation report", fontsize=15, weight="bold")
    fig.text(0.06, 0.94, textwrap.shorten(f"{os.path.basename(res.path)} ({res.title}) vs "
                                          f"{os.path.basename(ref_path)}", 110), fontsize=8.5)
    fig.text(0.06, 0.915, verdict, fontsize=11, weight="bold",
             color="tab:red" if checks.failures else ("0.3" if checks.n_checked == 0 else "tab:green"))
    y = 0.895
    if stats:
        ax = fig.add_axes([0.04, y - 0.03 - 0.022 * (len(stats) + 1), 0.92, 0.022 * (len(stats) + 1)])
        ax.axis("off")
        tab = ax.table(cellText=_summary_rows(stats),
                       colLabels=["channel", "unit", "rms dev", "allowed", "peak err %", "S&G C", "ISO R", "grade",
                                  "cov % run/td", "result"], loc="upper center", cellLoc="center")
        tab.auto_set_font_size(False)
        tab.set_fontsize(7)
        for (r, c), cell in tab.get_celld().items():
            if r > 0 and c == 9:
                cell.set_text_props(color="tab:red" if cell.get_text().get_text() == "FAIL" else "k", weight="bold")
        y -= 0.035 + 0.022 * (len(stats) + 1)
    lines = []
    if rows:
        from .compare import crush_table
        lines += crush_table(rows, "Crush lengths (Table 3 layout; primary shortening, secondary lengthening +)"
                             ).splitlines() + [""]
    if checks.failures:
        lines += ["Failures:"] + ["  " + textwrap.shorten(f, 116) for f in checks.failures[:25]]
        if len(checks.failures) > 25:
            lines.append(f"  ... and {len(checks.failures) - 25} more (see the console report)")
        lines.append("")
    if stats:
        lines += ["Treatment of both signals:",
                  *textwrap.wrap(f"alignment: {al.detail}", 112, initial_indent="  ", subsequent_indent="    "),
                  f"  shift added to the reference's time: {al.shift:+.6f} s",
                  "  filter: " + ("CFC %d (SAE J211-1, phaseless 4-pole Butterworth), both signals" % opts.cfc
                                   if opts.cfc else "none"),
                  "  resampling: linear interpolation onto one uniform time base over the common range",
                  "  metrics: Sprague & Geers (2004) M, P, C; ISO/TS 18571:2014 at 10 kHz (corridor, phase, "
                  "magnitude, slope)"]
    if td_phase:
        lines.append(f"  touchdown phase of the result: {td_phase[0]:.4f} .. {td_phase[1]:.4f} s; minimum coverage "
                     f"{opts.min_coverage:g} % of the run, {opts.min_touchdown_coverage:g} % of the touchdown phase")
    lines += ["", "Result (LANDYN):"] + ["  " + textwrap.shorten(f"{k}: {v}", 116) for k, v in res.provenance()]
    lines += ["", "Reference:"] + ["  " + textwrap.shorten(f"{k}: {v}", 116) for k, v in file_provenance(ref_path)]
    if opts.map:
        lines += ["  map: " + textwrap.shorten(os.path.abspath(opts.map), 110)]
    cmd = "landyn-compare " + " ".join(shlex.quote(str(x)) for x in (argv if argv is not None else []))
    lines += ["", "Options:"] + ["  " + ln for ln in textwrap.wrap(cmd, 112)]
    lines += ["", f"written {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M UTC} by landyn-compare"]
    ax = fig.add_axes([0.06, 0.03, 0.9, y - 0.03])
    _text_block(ax, lines, 6.6)
    pdf.savefig(fig)
    plt.close(fig)


def _channel_page(pdf, plt, st, res_label: str, ref_label: str, shift: float) -> None:
    s, m = st.series, st.metrics
    u, f = s.display()
    fig = plt.figure(figsize=(8.27, 11.69))
    ax = fig.add_axes([0.11, 0.58, 0.84, 0.34])
    ax2 = fig.add_axes([0.11, 0.36, 0.84, 0.17], sharex=ax)
    if st.allowed is not None:
        ax.fill_between(st.t, (st.y_ref - st.allowed) * f, (st.y_ref + st.allowed) * f, color="0.88",
                        label=f"reference ± allowed rms {st.allowed * f:.3g} {u}")
    # LANDYN wide and light underneath, the reference dashed on top: both stay visible where they agree
    ax.plot(st.t, st.y * f, color="#4c72b0", lw=2.6, alpha=0.55, label=f"LANDYN: {res_label}", zorder=2)
    ax.plot(st.t, st.y_ref * f, color="#c44e52", lw=1.1, ls="--", label=f"reference: {ref_label}", zorder=3)
    ax.plot([m.t_peak], [m.peak * f], "o", color="#4c72b0", ms=7, mfc="none", zorder=4, label="peak LANDYN")
    ax.plot([m.t_peak_ref], [m.peak_ref * f], "x", color="#c44e52", ms=6, zorder=5, label="peak reference")
    ax.set_ylabel(f"{s.label.split(' -> ')[-1]} [{u}]", fontsize=8)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    ax.set_title("\n".join(textwrap.wrap(s.label, 90)) + f"   ({_channel_verdict(st)})", fontsize=9)
    plt.setp(ax.get_xticklabels(), visible=False)
    d = (st.y - st.y_ref) * f
    ax2.plot(st.t, d, color="k", lw=1.0, label="LANDYN − reference")
    if st.allowed is not None:
        ax2.axhspan(-st.allowed * f, st.allowed * f, color="0.88", label="± allowed rms")
    ax2.axhline(0, color="0.5", lw=0.6)
    ax2.set_ylabel(f"deviation [{u}]", fontsize=8)
    ax2.set_xlabel(f"time [s] (reference shifted by {shift:+.4f} s)", fontsize=8)
    ax2.grid(True, alpha=0.3)
    ax2.legend(fontsize=7, loc="best")
    iso = m.iso
    lines = ["Metrics", f"  peak LANDYN     {m.peak * f:11.4g} {u} at {m.t_peak:.4f} s",
             f"  peak reference  {m.peak_ref * f:11.4g} {u} at {m.t_peak_ref:.4f} s",
             f"  peak error      {m.peak_error_pct:+11.2f} %,  time-of-peak error {m.peak_time_error:+.4f} s",
             f"  rms deviation   {st.rms * f:11.4g} {u},  max |deviation| {st.max_abs * f:.4g} {u} at {st.t_max:.4f} s",
             f"  Sprague & Geers M {m.sg_m:+.4f}  P {m.sg_p:.4f}  C {m.sg_c:.4f}"]
    if iso:
        lines.append(f"  ISO/TS 18571    corridor {iso.corridor:.3f}  phase {iso.phase:.3f} (shift {iso.shift:+.4f} s)  "
                     f"magnitude {iso.magnitude:.3f}  slope {iso.slope:.3f}")
        lines.append(f"                  overall R {iso.overall:.3f}: {iso.grade}")
    elif m.iso_note:
        lines.append(f"  ISO/TS 18571    not rated: {m.iso_note}")
    if st.cov_run is not None:
        lines.append(f"  coverage        {100 * st.cov_run:.1f} % of the run, {100 * st.cov_td:.1f} % of the touchdown phase")
    lines.append(f"  samples         {len(st.t)} on the common base {st.t[0]:.4f} .. {st.t[-1]:.4f} s")
    lines.append("")
    lines.append("Checks")
    if st.allowed is not None:
        lines.append(f"  rms deviation <= {st.allowed * f:.4g} {u}: {'pass' if st.passed else 'FAIL'}")
    for name, v, lim, ok, rel in st.metric_checks:
        lines.append(f"  {name} {v:.4g} {rel} {lim:.4g}: {'pass' if ok else 'FAIL'}")
    if st.allowed is None and not st.metric_checks:
        lines.append("  none (no tolerance for this channel)")
    _text_block(fig.add_axes([0.08, 0.04, 0.88, 0.27]), lines, 8)
    pdf.savefig(fig)
    plt.close(fig)


def _crush_page(pdf, plt, rows) -> None:
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(8.27, 11.69), gridspec_kw={"height_ratios": [2, 1]})
    x = np.array([r.measure for r in rows])
    ax.bar(x - 0.2, [r.value * MM for r in rows], 0.4, label="LANDYN", color="#4c72b0")
    ax.bar(x + 0.2, [r.ref * MM for r in rows], 0.4, label="reference", color="#c44e52")
    ax.set_ylabel("crush length [mm]")
    ax.legend(fontsize=8)
    ax.grid(True, axis="y", alpha=0.3)
    ax.set_title("Crush lengths (Table 3 layout)")
    ax2.bar(x, [r.dev * MM for r in rows], 0.5,
            color=["0.4" if r.passed is None else ("tab:green" if r.passed else "tab:red") for r in rows])
    ax2.axhline(0, color="k", lw=0.6)
    ax2.set_ylabel("deviation [mm]")
    ax2.set_xticks(x)
    ax2.set_xticklabels([f"{r.measure}\nG{r.gear}{'PLR'[r.strut]}" for r in rows], fontsize=7)
    ax2.set_xlabel("measure: G = gear, P primary, L secondary left, R secondary right")
    ax2.grid(True, axis="y", alpha=0.3)
    fig.tight_layout()
    pdf.savefig(fig)
    plt.close(fig)


def write_report(path: str, res: Result, ref_path: str, rows, stats, checks, al, td_phase, opts, argv) -> str:
    """Writes the report PDF to `path` (never over an input file) and returns the path."""
    cli.refuse_overwrite(path, [res.path, ref_path, getattr(opts, "map", None)])
    cli.use_agg()
    import matplotlib.pyplot as plt
    from matplotlib.backends.backend_pdf import PdfPages
    res_label = textwrap.shorten(f"{os.path.basename(res.path)}: {res.title}", 60)
    ref_label = os.path.basename(ref_path)
    with cli.atomic_output(path, mode=None) as tmp:
        with PdfPages(tmp) as pdf:
            _summary_page(pdf, plt, res, ref_path, rows, stats, checks, al, td_phase, opts, argv)
            if rows:
                _crush_page(pdf, plt, rows)
            for st in stats:
                _channel_page(pdf, plt, st, res_label, ref_label, al.shift)
            info = pdf.infodict()
            info["Title"] = f"LANDYN validation report: {os.path.basename(res.path)} vs {ref_label}"
            info["Creator"] = "landyn-compare"
    return path
