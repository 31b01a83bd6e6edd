"""landyn-compare: compare a LANDYN result with a reference and check tolerances.

References:
  * another LANDYN result file (.h5): crush lengths and time histories;
  * a per-strut crush-length CSV such as the paper's Table 3 (reference/table3_crush_lengths.csv),
    values in mm, rows identified by `measure` (1-3 = gear 1 primary, left, right; 4-6 = gear 2 ...)
    or by `gear` and `strut`;
  * a time-history CSV (--timeseries): a time column and named channels, mapped to LANDYN
    quantities by their landyn-export column names or by a --map file.

Deviation = RESULT - REFERENCE. Exit status 0: all checks pass (or none requested); 1: a tolerance
is exceeded; 2: error (malformed CSV, missing dataset, not HDF5, bad option).
"""
from __future__ import annotations

import csv
import math
import os
import re
import sys
import textwrap
from dataclasses import dataclass, field

import numpy as np

from . import cli
from .schema import (STRUT_LABELS, STRUTS, LandynPostError, Result, is_hdf5, load, measure_gear_strut,
                     measure_number, strut_index)

MM = 1.0e3

MAP_HELP = """\
map file (--map): one channel per line, '#' starts a comment:
  time = <time column> [* <factor>]                 # optional; default: first column, factor 1
  <reference column> = <LANDYN channel> [* <factor>] [tol=<rms tolerance>]
reference value * factor = LANDYN value in SI units (m, N, m/s, deg, g, J). Channels:
  stroke[gear=1,strut=primary]   strut_force[gear=2,strut=secondary_left]   strut_length[...]
  normal_force[gear=1]  friction_force[gear=1]  penetration[gear=1]  slip_speed[gear=1]
  footpad_position[gear=1,comp=x]  ground_force[gear=1,comp=z]
  velocity[comp=z]  position[comp=z]  mass_centre_position[comp=x]  euler_angles[comp=pitch]
  angular_rate[comp=q]  overload[comp=z]  energy/honeycomb_work
example (drop-test channels in mm and kN, time in ms):
  time      = t_ms * 0.001
  LG1_P_mm  = stroke[gear=1,strut=primary] * 0.001
  LG1_FN_kN = normal_force[gear=1] * 1000  tol=5000
Without --map, reference columns named like landyn-export columns (gear1_primary_stroke_m ...)
are compared directly."""


# ----------------------------------------------------------------------------------------- CSV input

def _read_csv_rows(path: str) -> tuple[list[str], list[tuple[int, list[str]]]]:
    """Header and data rows (with line numbers) of a CSV file; '#' lines and blank lines skipped."""
    if not os.path.exists(path):
        raise LandynPostError(f"{path}: no such file")
    if is_hdf5(path):
        raise LandynPostError(f"{path}: is an HDF5 file, expected CSV")
    try:
        with open(path, newline="", encoding="utf-8-sig") as fh:
            text = fh.read()
    except UnicodeDecodeError:
        raise LandynPostError(f"{path}: not a text (CSV) file") from None
    if "\x00" in text:
        raise LandynPostError(f"{path}: not a text (CSV) file")
    header, rows = None, []
    for lineno, row in enumerate(csv.reader(text.splitlines()), 1):
        if not row or not "".join(row).strip() or row[0].lstrip().startswith("#"):
            continue
        row = [c.strip() for c in row]
        if header is None:
            header = row
            if len(set(header)) != len(header):
                raise LandynPostError(f"{path}: line {lineno}: duplicate column names in the header")
            continue
        if len(row) != len(header):
            raise LandynPostError(f"{path}: line {lineno}: {len(row)} fields, the header has {len(header)}")
        rows.append((lineno, row))
    if header is None:
        raise LandynPostError(f"{path}: no header line (empty CSV)")
    if not rows:
        raise LandynPostError(f"{path}: no data rows")
    return header, rows


def _preview(names: list[str], n: int = 8) -> str:
    """The first n names, comma-separated, and how many more."""
    more = f", ... ({len(names)} columns)" if len(names) > n else ""
    return ", ".join(names[:n]) + more


def _number(path: str, lineno: int, col: str, text: str) -> float:
    try:
        v = float(text)
    except ValueError:
        raise LandynPostError(f"{path}: line {lineno}: {col} = {text!r} is not a number") from None
    return v


@dataclass
class StrutReference:
    """Per-strut crush lengths of a reference, m, keyed by Table 3 measure number."""
    values: dict[int, float]
    label: str


def read_strut_csv(path: str, n_gears: int, load_case: str | None = None,
                   column: str | None = None) -> StrutReference:
    """Reads a per-strut crush-length CSV (values in mm), see the module documentation.

    Value column: --column NAME (NAME or NAME_mm); default crush_mm if present, else the only column
    that is not load_case/measure/gear/strut.
    """
    header, rows = _read_csv_rows(path)
    cols = {c.lower(): i for i, c in enumerate(header)}
    keys = {"load_case", "measure", "gear", "strut"}
    if "measure" not in cols and not {"gear", "strut"} <= set(cols):
        hint = ("; it looks like a time-history CSV: add --timeseries"
                if {"time_s", "time", "t"} & set(cols) else "")
        raise LandynPostError(f"{path}: needs a 'measure' column or 'gear' and 'strut' columns "
                              f"(header: {_preview(header)}){hint}")
    value_cols = [c for c in header if c.lower() not in keys]
    if column:
        cands = [c for c in header if c.lower() in (column.lower(), column.lower() + "_mm")]
        if not cands:
            raise LandynPostError(f"{path}: no column {column!r} (value columns: {', '.join(value_cols)})")
        vcol = cands[0]
    elif any(c.lower() == "crush_mm" for c in header):
        vcol = next(c for c in header if c.lower() == "crush_mm")
    elif len(value_cols) == 1:
        vcol = value_cols[0]
    else:
        raise LandynPostError(f"{path}: several value columns ({', '.join(value_cols)}): choose one with --column")
    vi = header.index(vcol)
    if "load_case" in cols:
        cases = sorted({r[cols["load_case"]] for _, r in rows})
        if load_case is None:
            if len(cases) > 1:
                raise LandynPostError(f"{path}: several load cases ({', '.join(cases)}): choose one with --load-case")
            load_case = cases[0]
        sel = [(ln, r) for ln, r in rows if r[cols["load_case"]].lower() == load_case.lower()]
        if not sel:
            raise LandynPostError(f"{path}: no rows for load case {load_case!r} (has {', '.join(cases)})")
        rows = sel
    elif load_case is not None:
        raise LandynPostError(f"{path}: --load-case given but the file has no load_case column")
    values: dict[int, float] = {}
    for ln, r in rows:
        if "measure" in cols:
            m = _number(path, ln, "measure", r[cols["measure"]])
            if m != int(m):
                raise LandynPostError(f"{path}: line {ln}: measure {r[cols['measure']]!r} is not an integer")
            m = int(m)
            if "gear" in cols and "strut" in cols:
                g_csv = int(_number(path, ln, "gear", r[cols["gear"]]))
                try:
                    k_csv = strut_index(r[cols["strut"]])
                except LandynPostError as exc:
                    raise LandynPostError(f"{path}: line {ln}: {exc}") from None
                if measure_number(g_csv, k_csv) != m:
                    raise LandynPostError(f"{path}: line {ln}: measure {m} is not gear {g_csv} {r[cols['strut']]}")
        else:
            g = int(_number(path, ln, "gear", r[cols["gear"]]))
            try:
                m = measure_number(g, strut_index(r[cols["strut"]]))
            except LandynPostError as exc:
                raise LandynPostError(f"{path}: line {ln}: {exc}") from None
        if not 1 <= m <= 3 * n_gears:
            raise LandynPostError(f"{path}: line {ln}: measure {m} outside 1..{3 * n_gears} "
                                  f"(the result has {n_gears} gears)")
        if m in values:
            raise LandynPostError(f"{path}: line {ln}: measure {m} appears twice")
        v = _number(path, ln, vcol, r[vi])
        if not math.isfinite(v):
            raise LandynPostError(f"{path}: line {ln}: {vcol} = {r[vi]!r} is not finite")
        values[m] = v / MM
    label = f"{os.path.basename(path)} (column {vcol}" + (f", load case {load_case})" if load_case else ")")
    return StrutReference(values, label)


@dataclass
class MapEntry:
    ref_column: str
    channel: str
    factor: float = 1.0
    tol: float | None = None


_MAP_LINE = re.compile(r"^(?P<ref>[^=]+?)\s*=\s*(?P<chan>[A-Za-z_][\w/]*(?:\[[^\]]*\])?)"
                       r"(?:\s*\*\s*(?P<fac>[-+0-9.eEdD]+))?(?:\s+tol\s*=\s*(?P<tol>[-+0-9.eE]+))?\s*$")


def read_map(path: str) -> tuple[MapEntry | None, list[MapEntry]]:
    """Reads a --map file (see MAP_HELP): (time entry or None, channel entries)."""
    if not os.path.exists(path):
        raise LandynPostError(f"{path}: no such file")
    time_entry, entries = None, []
    with open(path, encoding="utf-8") as fh:
        for lineno, raw in enumerate(fh, 1):
            line = raw.split("#", 1)[0].strip()
            if not line:
                continue
            if line.lower().startswith("time") and re.match(r"^time\s*=", line, re.I):
                m = re.match(r"^time\s*=\s*(?P<col>[^*]+?)(?:\s*\*\s*(?P<fac>[-+0-9.eE]+))?\s*$", line, re.I)
                if not m:
                    raise LandynPostError(f"{path}: line {lineno}: malformed time line {raw.strip()!r}")
                time_entry = MapEntry(m.group("col").strip(), "time", float(m.group("fac") or 1.0))
                continue
            m = _MAP_LINE.match(line)
            if not m:
                raise LandynPostError(f"{path}: line {lineno}: expected '<column> = <channel> [* factor] [tol=X]', "
                                      f"got {raw.strip()!r}")
            try:
                fac = float((m.group("fac") or "1").lower().replace("d", "e"))
                tol = float(m.group("tol")) if m.group("tol") else None
            except ValueError:
                raise LandynPostError(f"{path}: line {lineno}: malformed number in {raw.strip()!r}") from None
            entries.append(MapEntry(m.group("ref").strip(), m.group("chan"), fac, tol))
    if not entries:
        raise LandynPostError(f"{path}: no channel lines")
    return time_entry, entries


@dataclass
class Series:
    """One channel to compare: LANDYN values and reference values on their own time bases (SI)."""
    label: str
    units: str
    t: np.ndarray
    y: np.ndarray
    t_ref: np.ndarray
    y_ref: np.ndarray
    tol: float | None = None


def read_timeseries_csv(path: str, res: Result, map_path: str | None, time_column: str | None,
                        time_factor: float) -> list[Series]:
    """Reads a time-history CSV and pairs its channels with LANDYN channels."""
    header, rows = _read_csv_rows(path)
    data = np.empty((len(rows), len(header)))
    for k, (ln, r) in enumerate(rows):
        for j, (c, v) in enumerate(zip(header, r)):
            data[k, j] = _number(path, ln, c, v) if v != "" else np.nan
    time_entry, entries = (None, None)
    if map_path:
        time_entry, entries = read_map(map_path)
    if time_column is None:
        if time_entry is not None:
            time_column, time_factor = time_entry.ref_column, time_entry.factor
        else:
            low = [c.lower() for c in header]
            time_column = next((header[low.index(c)] for c in ("time_s", "time", "t") if c in low), header[0])
    if time_column not in header:
        raise LandynPostError(f"{path}: no time column {time_column!r} (columns: {_preview(header)})")
    t_ref = data[:, header.index(time_column)] * time_factor
    if not np.all(np.isfinite(t_ref)) or np.any(np.diff(t_ref) <= 0):
        raise LandynPostError(f"{path}: time column {time_column!r} is not strictly increasing")
    if entries is None:
        by_col = res.channel_by_column()
        entries = [MapEntry(c, by_col[c].label) for c in header if c in by_col and c != time_column]
        if not entries:
            raise LandynPostError(f"{path}: no column is named like a LANDYN channel (e.g. gear1_primary_stroke_m); "
                                  "give a --map file")
    out = []
    for e in entries:
        if e.ref_column not in header:
            raise LandynPostError(f"{path}: no column {e.ref_column!r} (named in the map; columns: {_preview(header)})")
        ch = res.channel(e.channel)
        y_ref = data[:, header.index(e.ref_column)] * e.factor
        ok = np.isfinite(y_ref)
        out.append(Series(f"{e.ref_column} -> {ch.label}", ch.units, res.time, ch.values, t_ref[ok], y_ref[ok], e.tol))
    return out


def h5_series(res: Result, ref: Result, channels: list[str] | None) -> list[Series]:
    """Channels of two LANDYN results (default: strokes, strut forces, footpad forces, body motion)."""
    if ref.n_gears != res.n_gears:
        raise LandynPostError(f"{ref.path} has {ref.n_gears} gears, {res.path} has {res.n_gears}")
    if channels:
        pairs = [(res.channel(c), ref.channel(c)) for c in channels]
    else:
        keys = ("stroke", "strut_force", "normal_force", "friction_force", "velocity", "euler_angles", "overload")
        pairs = list(zip(res.channels(keys), ref.channels(keys)))
    return [Series(a.label, a.units, res.time, a.values, ref.time, b.values) for a, b in pairs]


# ----------------------------------------------------------------------------------------- comparison

@dataclass
class CrushRow:
    measure: int
    gear: int
    strut: int
    value: float       # m
    ref: float         # m

    @property
    def dev(self) -> float:
        return self.value - self.ref

    @property
    def pct(self) -> float:
        return 100.0 * self.dev / abs(self.ref) if abs(self.ref) > 1e-12 else math.nan


def crush_rows(res: Result, ref: StrutReference) -> list[CrushRow]:
    rows = []
    for m in sorted(ref.values):
        g, k = measure_gear_strut(m)
        rows.append(CrushRow(m, g, k, float(res.crush_length[g - 1, k]), ref.values[m]))
    return rows


@dataclass
class SeriesStats:
    series: Series
    t: np.ndarray          # common time base
    y: np.ndarray
    y_ref: np.ndarray
    rms: float
    max_abs: float
    t_max: float


def resample(s: Series) -> SeriesStats:
    """Both signals linearly interpolated on a uniform time base over the overlap of their ranges
    (step: the finer of the two median sample intervals)."""
    t0, t1 = max(s.t[0], s.t_ref[0]), min(s.t[-1], s.t_ref[-1])
    if not t1 > t0:
        raise LandynPostError(f"{s.label}: the time ranges do not overlap "
                              f"(result {s.t[0]:g}..{s.t[-1]:g} s, reference {s.t_ref[0]:g}..{s.t_ref[-1]:g} s)")
    dt = min(np.median(np.diff(s.t)), np.median(np.diff(s.t_ref)))
    n = int(round((t1 - t0) / dt)) + 1
    t = np.linspace(t0, t1, max(n, 2))
    y, yr = np.interp(t, s.t, s.y), np.interp(t, s.t_ref, s.y_ref)
    d = y - yr
    k = int(np.argmax(np.abs(d)))
    return SeriesStats(s, t, y, yr, float(np.sqrt(np.mean(d * d))), float(abs(d[k])), float(t[k]))


@dataclass
class Checks:
    tol_mm: float | None = None
    tol_pct: float | None = None
    tol_rms: float | None = None
    failures: list[str] = field(default_factory=list)

    def crush_limit(self, ref_m: float) -> float | None:
        """Allowed |deviation| in mm: tol_mm + tol_pct % of |reference| (either alone if only one is given)."""
        if self.tol_mm is None and self.tol_pct is None:
            return None
        return (self.tol_mm or 0.0) + (self.tol_pct or 0.0) / 100.0 * abs(ref_m) * MM

    def check_crush(self, rows: list[CrushRow]) -> None:
        for r in rows:
            lim = self.crush_limit(r.ref)
            if lim is not None and abs(r.dev) * MM > lim:
                self.failures.append(f"crush No. {r.measure} (gear {r.gear} {STRUT_LABELS[STRUTS[r.strut]]}): "
                                     f"|deviation| {abs(r.dev) * MM:.2f} mm > allowed {lim:.2f} mm")

    def check_series(self, stats: list[SeriesStats]) -> None:
        for st in stats:
            tol = st.series.tol if st.series.tol is not None else self.tol_rms
            if tol is not None and st.rms > tol:
                self.failures.append(f"time history {st.series.label}: rms deviation {st.rms:.4g} {st.series.units} "
                                     f"> tolerance {tol:g}")


# ----------------------------------------------------------------------------------------- output

def crush_table(rows: list[CrushRow], title: str) -> str:
    head = f"{'No.':>4} {'gear':>4}  {'strut':<16}{'LANDYN':>10}{'reference':>11}{'dev':>9}{'dev':>9}"
    lines = [title, head, f"{'':>4} {'':>4}  {'':<16}{'[mm]':>10}{'[mm]':>11}{'[mm]':>9}{'[%]':>9}", "-" * len(head)]
    for r in rows:
        pct = f"{r.pct:9.2f}" if math.isfinite(r.pct) else f"{'-':>9}"
        lines.append(f"{r.measure:>4} {r.gear:>4}  {STRUT_LABELS[STRUTS[r.strut]]:<16}{r.value * MM:10.1f}"
                     f"{r.ref * MM:11.1f}{r.dev * MM:9.2f}{pct}")
    if rows:
        dev = np.array([r.dev for r in rows]) * MM
        pct = np.array([r.pct for r in rows])
        k = int(np.argmax(np.abs(dev)))
        line = f"max |dev| {abs(dev[k]):.2f} mm (No. {rows[k].measure}), rms dev {np.sqrt(np.mean(dev ** 2)):.2f} mm"
        if np.any(np.isfinite(pct)):
            kp = int(np.nanargmax(np.abs(pct)))
            line += f", max |dev| {abs(pct[kp]):.2f} % (No. {rows[kp].measure})"
        lines.append(line)
    return "\n".join(lines)


def series_table(stats: list[SeriesStats]) -> str:
    w = max([len(s.series.label) for s in stats] + [7])
    head = f"{'channel':<{w}}  {'units':<6}{'rms dev':>12}{'max |dev|':>12}{'at t [s]':>10}{'ref range':>12}{'samples':>9}"
    lines = ["Time histories (LANDYN - reference, linear interpolation on the common time range)", head,
             "-" * len(head)]
    for s in stats:
        rng = float(np.ptp(s.y_ref))
        lines.append(f"{s.series.label:<{w}}  {s.series.units:<6}{s.rms:12.4g}{s.max_abs:12.4g}{s.t_max:10.4f}"
                     f"{rng:12.4g}{len(s.t):9d}")
    return "\n".join(lines)


def write_table_csv(path: str, rows: list[CrushRow]) -> None:
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["measure", "gear", "strut", "landyn_mm", "reference_mm", "deviation_mm", "deviation_pct"])
        for r in rows:
            w.writerow([r.measure, r.gear, STRUTS[r.strut], f"{r.value * MM:.6f}", f"{r.ref * MM:.6f}",
                        f"{r.dev * MM:.6f}", f"{r.pct:.6f}" if math.isfinite(r.pct) else ""])


def write_plots(outdir: str, rows: list[CrushRow], stats: list[SeriesStats], ref_label: str, res: Result) -> list[str]:
    """Overlay plots: crush lengths (bars, with the deviation) and time histories (6 per page)."""
    cli.use_agg()
    import matplotlib.pyplot as plt
    written = []
    if rows:
        fig, (ax, ax2) = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True, gridspec_kw={"height_ratios": [2, 1]})
        x = np.array([r.measure for r in rows])
        ax.bar(x - 0.2, [r.value * MM for r in rows], 0.4, label="LANDYN", color="#4c72b0")
        ax.bar(x + 0.2, [r.ref * MM for r in rows], 0.4, label="reference", color="#c44e52")
        ax.axhline(0, color="k", lw=0.6)
        ax.set_ylabel("crush length [mm]")
        ax.legend(fontsize=8)
        ax.grid(True, axis="y", alpha=0.3)
        ax2.bar(x, [r.dev * MM for r in rows], 0.5, color="0.4")
        ax2.axhline(0, color="k", lw=0.6)
        ax2.set_ylabel("deviation [mm]")
        ax2.set_xticks(x)
        ax2.set_xticklabels([f"{r.measure}\nG{r.gear}{'PLR'[r.strut]}" for r in rows], fontsize=7)
        ax2.set_xlabel("measure (Table 3)")
        ax2.grid(True, axis="y", alpha=0.3)
        fig.suptitle("\n".join(textwrap.wrap(f"Crush lengths: {res.title}", 100) + [f"vs {ref_label}"]), fontsize=9)
        fig.tight_layout()
        fn = os.path.join(outdir, "compare_crush_lengths.png")
        fig.savefig(fn, dpi=110)
        plt.close(fig)
        written.append(fn)
    per_page = 6
    for p in range(0, len(stats), per_page):
        chunk = stats[p:p + per_page]
        fig, axs = plt.subplots(3, 2, figsize=(11, 8.5), squeeze=False)
        for ax, st in zip(axs.flat, chunk):
            s = st.series
            ax.plot(s.t, s.y, label="LANDYN", lw=1.2)
            ax.plot(s.t_ref, s.y_ref, label="reference", lw=1.0, ls="--")
            ax.set_title(f"{s.label}\nrms dev {st.rms:.3g}, max {st.max_abs:.3g} {s.units}", fontsize=7)
            ax.set_ylabel(s.units, fontsize=8)
            ax.tick_params(labelsize=7)
            ax.grid(True, alpha=0.3)
            ax.legend(fontsize=6)
        for ax in list(axs.flat)[len(chunk):]:
            ax.set_visible(False)
        for ax in axs[-1]:
            ax.set_xlabel("time [s]", fontsize=8)
        fig.tight_layout()
        fn = os.path.join(outdir, f"compare_timeseries_{p // per_page + 1:02d}.png")
        fig.savefig(fn, dpi=100)
        plt.close(fig)
        written.append(fn)
    return written


# ----------------------------------------------------------------------------------------- main

def _main(argv=None) -> int:
    p = cli.make_parser(
        "landyn-compare",
        "Compare a LANDYN result with a reference: another LANDYN result (.h5), a per-strut crush-length\n"
        "CSV (Table 3 layout, mm) or a time-history CSV (--timeseries). Deviation = RESULT - REFERENCE.",
        epilog="tolerances (exit status 1 when exceeded, 2 on errors):\n"
               "  a crush length fails when |dev| > tol_mm + tol_pct/100 * |reference| (numpy.isclose style;\n"
               "  with only one of --tol-mm / --tol-pct given, that one alone); a time history fails when its\n"
               "  rms deviation exceeds --tol-rms (channel units: SI) or the map line's tol=.\n\n"
               "examples:\n"
               "  landyn-compare lc1.h5 table3_crush_lengths.csv --load-case LC-1 --column theory --tol-pct 3\n"
               "  landyn-compare new.h5 baseline.h5 --tol-mm 0.1 --tol-rms 1e-3\n"
               "  landyn-compare lc1.h5 droptest.csv --timeseries --map droptest.map --plots cmp\n\n" + MAP_HELP)
    p.add_argument("result", metavar="RESULT", help="LANDYN result file (.h5)")
    p.add_argument("reference", metavar="REFERENCE", help="LANDYN result (.h5) or CSV")
    p.add_argument("--load-case", metavar="NAME", help="rows of this load_case (per-strut CSV), e.g. LC-1")
    p.add_argument("--column", metavar="NAME", help="value column of a per-strut CSV, e.g. theory (-> theory_mm)")
    p.add_argument("--timeseries", action="store_true", help="REFERENCE is a time-history CSV")
    p.add_argument("--map", metavar="MAPFILE", help="channel map for --timeseries (format below)")
    p.add_argument("--time-column", metavar="NAME", help="time column of a time-history CSV (default: see map/first)")
    p.add_argument("--time-factor", type=float, default=1.0, metavar="F", help="time column * F = seconds (default 1)")
    p.add_argument("--channels", nargs="+", metavar="CHANNEL",
                   help="channels compared between two .h5 files, e.g. 'stroke[gear=1,strut=primary]'")
    p.add_argument("--tol-mm", type=float, metavar="X", help="crush-length tolerance [mm]")
    p.add_argument("--tol-pct", type=float, metavar="Y", help="crush-length tolerance [%% of |reference|]")
    p.add_argument("--tol-rms", type=float, metavar="X", help="rms tolerance of every time history [SI units]")
    p.add_argument("--plots", metavar="DIR", help="write overlay plots to DIR")
    p.add_argument("--table-csv", metavar="FILE", help="write the crush-length deviation table as CSV")
    a = p.parse_args(argv)
    for name in ("tol_mm", "tol_pct", "tol_rms"):
        v = getattr(a, name)
        if v is not None and not v >= 0:
            p.error(f"--{name.replace('_', '-')} must be >= 0")

    res = load(a.result)
    rows: list[CrushRow] = []
    series: list[Series] = []
    ref_path = a.reference
    if not os.path.exists(ref_path):
        raise LandynPostError(f"{ref_path}: no such file")
    if is_hdf5(ref_path):
        if a.timeseries or a.map or a.column or a.load_case:
            p.error("--timeseries, --map, --column and --load-case apply to CSV references only")
        ref = load(ref_path)
        ref_label = os.path.basename(ref_path)
        rows = crush_rows(res, StrutReference(
            {measure_number(g + 1, k): float(ref.crush_length[g, k]) for g in range(ref.n_gears) for k in range(3)},
            ref_label)) if ref.n_gears == res.n_gears else []
        series = h5_series(res, ref, a.channels)
    elif a.channels:
        p.error("--channels applies to .h5 references (a CSV's channels come from its columns or --map)")
    elif a.timeseries:
        series = read_timeseries_csv(ref_path, res, a.map, a.time_column, a.time_factor)
        ref_label = os.path.basename(ref_path)
    else:
        if a.map:
            p.error("--map needs --timeseries")
        sref = read_strut_csv(ref_path, res.n_gears, a.load_case, a.column)
        rows = crush_rows(res, sref)
        ref_label = sref.label

    checks = Checks(a.tol_mm, a.tol_pct, a.tol_rms)
    print(f"LANDYN result: {res.path} ({res.title})")
    print(f"reference:     {ref_label}\n")
    if rows:
        print(crush_table(rows, "Crush lengths (Table 3 layout; primary shortening, secondary lengthening +)"))
        checks.check_crush(rows)
        if a.table_csv:
            write_table_csv(a.table_csv, rows)
    stats = [resample(s) for s in series]
    if stats:
        print()
        print(series_table(stats))
        checks.check_series(stats)
    if a.plots:
        for fn in write_plots(cli.output_dir(a.plots), rows, stats, ref_label, res):
            print(fn)
    print()
    if checks.failures:
        for f in checks.failures:
            print("FAILED: " + f)
        print(f"landyn-compare: {len(checks.failures)} check(s) failed")
        return cli.EXIT_CHECK_FAILED
    if any(v is not None for v in (a.tol_mm, a.tol_pct, a.tol_rms)):
        print("landyn-compare: all checks passed")
    return cli.EXIT_OK


def main(argv=None) -> int:
    return cli.run("landyn-compare", _main, argv)


if __name__ == "__main__":
    sys.exit(main())
