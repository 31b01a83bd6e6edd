"""landyn-compare: compare a LANDYN result with a reference and check tolerances.

References:
  * another LANDYN result file (.h5): crush lengths and time histories;
  * a per-strut crush-length CSV such as the paper's Table 3
    (post/landyn_post/data/table3_crush_lengths.csv), values in mm, rows identified by `measure`
    (1-3 = gear 1 primary, left, right; 4-6 = gear 2 ...) or by `gear` and `strut`;
  * a time-history CSV (--timeseries): a time column and named channels, mapped to LANDYN
    quantities by their landyn-export column names or by a --map file.

Nothing is dropped silently: every channel of a time-history reference is compared or the
comparison fails naming it (--allow-unmatched lists it instead); the share of the run and of its
touchdown phase that each reference channel covers is checked (--min-coverage,
--min-touchdown-coverage); every strut of the result without a reference value is listed (--strict
makes that a failure); and a comparison in which no check ran does not pass.

Both signals are treated alike (module correlation): the reference's time shifted (--align
touchdown | xcorr, or --shift), both CFC-filtered (--cfc), both resampled onto one uniform time
base; then per channel the deviation, peaks, Sprague & Geers M/P/C and ISO/TS 18571 ratings, any
of which can carry a limit. --report writes the validation report (module validation_report).

Deviation = RESULT - REFERENCE. Exit status (consistent with landyn's): 0 at least one check ran
and every check passed; 1 usage error; 2 invalid input (file missing or malformed, unknown
channel or unit); 3 a check failed (a tolerance or metric limit exceeded, a reference channel not
compared, a coverage under its minimum, or with --strict a strut not checked); 4 an output file could not be written; 5 nothing was
checked (no tolerance given, or no channel had one).
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
from .paper import load_case_in_title, load_case_of
from .schema import (STRUT_LABELS, STRUTS, LandynPostError, Result, is_hdf5, load, measure_gear_strut,
                     measure_number, strut_index)
from .correlation import Metrics, common_base, coverage, metrics, touchdown_time, xcorr_shift
from .correlation import RESAMPLING
from .filters import cfc_filter, cfc_label
from .units import engineering, known_units, parse_quantity, unit_factor

MM = 1.0e3

MAP_HELP = """\
map file (--map): one channel per line, '#' starts a comment:
  time = <time column> [* <factor> | unit=<unit>]     # optional; default: time_s/time/t or the first column
  <reference column> = <LANDYN channel> [* <factor> | unit=<unit>] [tol=<rms>[unit]] [rtol=<pct>%]
unit= names the reference column's unit (converted to the channel's unit); '* factor' is the
factor that turns the reference value into the channel's unit. tol= is an absolute rms
tolerance (in the unit given with it, else in unit=, else in the channel's unit), rtol= a
relative one in % of the reference's range (max - min); a channel passes when its rms deviation
<= tol + rtol/100 * range. Units: """ + known_units() + """
LANDYN channel units: m, N, m/s, deg, deg/s, g, J. Channels:
  stroke[gear=1,strut=primary]   strut_force[gear=2,strut=secondary_left]   strut_length[...]
  normal_force[gear=1]  friction_force[gear=1]  penetration[gear=1]  slip_speed[gear=1]
  footpad_position[gear=1,comp=x]  ground_force[gear=1,comp=z]
  velocity[comp=z]  position[comp=z]  mass_centre_position[comp=x]  euler_angles[comp=pitch]
  angular_rate[comp=q]  overload[comp=z]  energy/honeycomb_work
example (drop-test channels in mm and kN, time in ms):
  time      = t_ms unit=ms
  LG1_P_mm  = stroke[gear=1,strut=primary] unit=mm  tol=2mm
  LG1_FN_kN = normal_force[gear=1] unit=kN  tol=5kN rtol=2%
Without --map, reference columns named like landyn-export columns (gear1_primary_stroke_m ...)
are compared directly. A reference column that is neither mapped nor named like a channel fails
the comparison (--allow-unmatched lists it as not compared instead). Tables show each channel in
its map unit= (else mm, kN, g, deg, m/s); the --table-csv values are in the channel's unit."""


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
                   column: str | None = None, n_struts: int = len(STRUTS)) -> StrutReference:
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
                if measure_number(g_csv, k_csv, n_struts) != m:
                    raise LandynPostError(f"{path}: line {ln}: measure {m} is not gear {g_csv} {r[cols['strut']]}")
        else:
            g = int(_number(path, ln, "gear", r[cols["gear"]]))
            try:
                m = measure_number(g, strut_index(r[cols["strut"]]), n_struts)
            except LandynPostError as exc:
                raise LandynPostError(f"{path}: line {ln}: {exc}") from None
        if not 1 <= m <= n_struts * n_gears:
            raise LandynPostError(f"{path}: line {ln}: measure {m} outside 1..{n_struts * n_gears} "
                                  f"(the result has {n_gears} gears)")
        if m in values:
            raise LandynPostError(f"{path}: line {ln}: measure {m} appears twice")
        v = _number(path, ln, vcol, r[vi])
        if not math.isfinite(v):
            raise LandynPostError(f"{path}: line {ln}: {vcol} = {r[vi]!r} is not finite")
        values[m] = v / MM
    label = f"{os.path.basename(path)} (column {vcol}" + (f", load case {load_case})" if load_case else ")")
    return StrutReference(values, label)




# ----------------------------------------------------------------------------------------- time histories

@dataclass
class MapEntry:
    ref_column: str
    channel: str
    factor: float = 1.0
    unit: str | None = None
    tol: tuple[float, str | None] | None = None     # (value, unit or None)
    rtol_pct: float | None = None
    line: int = 0


_MAP_LINE = re.compile(r"^(?P<ref>[^=]+?)\s*=\s*(?P<chan>[A-Za-z_][\w/]*(?:\[[^\]]*\])?)"
                       r"(?:\s*\*\s*(?P<fac>[-+0-9.eEdD]+))?(?P<opts>(?:\s+[A-Za-z]+\s*=\s*\S+)*)\s*$")
_OPT = re.compile(r"([A-Za-z]+)\s*=\s*(\S+)")


def _map_options(path: str, lineno: int, raw: str, text: str) -> dict[str, str]:
    opts = {}
    for k, v in _OPT.findall(text or ""):
        k = k.lower()
        if k not in ("unit", "tol", "rtol"):
            raise LandynPostError(f"{path}: line {lineno}: unknown option {k!r} in {raw.strip()!r} "
                                  "(options: unit=, tol=, rtol=)")
        opts[k] = v
    return opts


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
            if re.match(r"^time\s*=", line, re.I):
                m = re.match(r"^time\s*=\s*(?P<col>[^*=\s]+)(?:\s*\*\s*(?P<fac>[-+0-9.eE]+))?"
                             r"(?P<opts>(?:\s+[A-Za-z]+\s*=\s*\S+)*)\s*$", line, re.I)
                if not m:
                    raise LandynPostError(f"{path}: line {lineno}: malformed time line {raw.strip()!r}")
                opts = _map_options(path, lineno, raw, m.group("opts"))
                fac = float(m.group("fac") or 1.0)
                if "unit" in opts:
                    if m.group("fac"):
                        raise LandynPostError(f"{path}: line {lineno}: give '* factor' or unit=, not both")
                    fac = unit_factor(opts["unit"], "s", f"{path}: line {lineno}: ")
                time_entry = MapEntry(m.group("col").strip(), "time", fac, opts.get("unit"), line=lineno)
                continue
            m = _MAP_LINE.match(line)
            if not m:
                raise LandynPostError(f"{path}: line {lineno}: expected '<column> = <channel> [* factor | unit=U] "
                                      f"[tol=X[U]] [rtol=P%]', got {raw.strip()!r}")
            opts = _map_options(path, lineno, raw, m.group("opts"))
            try:
                fac = float((m.group("fac") or "1").lower().replace("d", "e"))
                tol = parse_quantity(opts["tol"]) if "tol" in opts else None
                rtol = parse_quantity(opts["rtol"]) if "rtol" in opts else None
            except (ValueError, LandynPostError) as exc:
                raise LandynPostError(f"{path}: line {lineno}: {exc}") from None
            if m.group("fac") and "unit" in opts:
                raise LandynPostError(f"{path}: line {lineno}: give '* factor' or unit=, not both")
            if tol is not None and (tol[0] < 0 or tol[1] == "%"):
                raise LandynPostError(f"{path}: line {lineno}: tol= must be an absolute value >= 0 "
                                      "(relative tolerances go in rtol=P%)")
            if rtol is not None and (rtol[0] < 0 or rtol[1] not in (None, "%")):
                raise LandynPostError(f"{path}: line {lineno}: rtol= must be a percentage >= 0, e.g. rtol=2%")
            if any(e.ref_column == m.group("ref").strip() for e in entries):
                raise LandynPostError(f"{path}: line {lineno}: column {m.group('ref').strip()!r} is mapped twice")
            entries.append(MapEntry(m.group("ref").strip(), m.group("chan"), fac, opts.get("unit"), tol,
                                    rtol[0] if rtol else None, lineno))
    if not entries:
        raise LandynPostError(f"{path}: no channel lines")
    return time_entry, entries


@dataclass
class Series:
    """One channel to compare: LANDYN values and reference values on their own time bases, in the
    channel's unit; tolerances from the map (absolute in the channel's unit, relative in %)."""
    label: str
    units: str
    t: np.ndarray
    y: np.ndarray
    t_ref: np.ndarray
    y_ref: np.ndarray
    tol: float | None = None
    rtol_pct: float | None = None
    gear: int | None = None
    strut: int | None = None
    display_unit: str | None = None     # unit of tables and plots (the map's unit=), else engineering

    def display(self) -> tuple[str, float]:
        """(unit, factor: value in the channel's unit * factor = value in that unit)."""
        if self.display_unit:
            return self.display_unit, 1.0 / unit_factor(self.display_unit, self.units)
        return engineering(self.units)


@dataclass
class SeriesSet:
    series: list[Series]
    unmatched: list[str]           # reference columns not compared
    notes: list[str] = field(default_factory=list)


def is_mat(path: str) -> bool:
    """A MATLAB level-5 MAT file (by its header)."""
    try:
        with open(path, "rb") as fh:
            return fh.read(10) == b"MATLAB 5.0"
    except OSError:
        return False


def read_mat_table(path: str) -> tuple[list[str], np.ndarray]:
    """The numeric vectors of a flat MAT file (a heritage export: one variable per channel, all of
    one length) as (names, samples x channels). LandynPostError for anything else."""
    from scipy.io import loadmat
    try:
        mat = loadmat(path, squeeze_me=True)
    except Exception as exc:          # scipy raises several types for a malformed file
        raise LandynPostError(f"{path}: cannot be read as a MAT file ({exc})") from None
    names, cols, skipped = [], [], []
    for k, v in mat.items():
        if k.startswith("__"):
            continue
        a = np.asarray(v)
        if a.dtype.kind in "iuf" and a.ndim == 1:
            names.append(k)
            cols.append(a.astype(float))
        else:
            skipped.append(k)
    if not cols:
        raise LandynPostError(f"{path}: no numeric vector variables (a flat MAT file of one vector per channel "
                              f"is expected; found {', '.join(skipped) or 'nothing'})")
    n = {len(c) for c in cols}
    if len(n) != 1:
        raise LandynPostError(f"{path}: the vectors differ in length ({', '.join(f'{a}: {len(c)}' for a, c in zip(names, cols))})")
    if skipped:
        raise LandynPostError(f"{path}: variables that are not numeric vectors cannot be compared: {', '.join(skipped)}")
    return names, np.stack(cols, axis=1)


def read_timeseries_csv(path: str, res: Result, map_path: str | None, time_column: str | None,
                        time_factor: float) -> SeriesSet:
    """Reads a time-history CSV (or a flat MAT file) and pairs its channels with LANDYN channels;
    every other column is returned as unmatched."""
    if is_mat(path):
        header, data = read_mat_table(path)
    else:
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
            raise LandynPostError(f"{path}: no column is named like a LANDYN channel (e.g. gear1_primary_stroke_m; "
                                  f"columns: {_preview(header)}); give a --map file")
    out = []
    for e in entries:
        if e.ref_column not in header:
            raise LandynPostError(f"{path}: no column {e.ref_column!r} (named in the map, line {e.line}; "
                                  f"columns: {_preview(header)})")
        ch = res.channel(e.channel)
        fac = e.factor
        where = f"{map_path}: line {e.line}: " if map_path else ""
        if e.unit:
            fac = unit_factor(e.unit, ch.units, where)
        tol = None
        if e.tol is not None:
            v, u = e.tol
            u = u or e.unit
            tol = v * (unit_factor(u, ch.units, where) if u else 1.0)
        y_ref = data[:, header.index(e.ref_column)] * fac
        ok = np.isfinite(y_ref)
        if ok.sum() < 2:
            raise LandynPostError(f"{path}: column {e.ref_column!r} has fewer than two values")
        out.append(Series(f"{e.ref_column} -> {ch.label}", ch.units, res.time, ch.values, t_ref[ok], y_ref[ok],
                          tol, e.rtol_pct, ch.gear, ch.index if ch.key in ("stroke", "strut_force", "strut_length")
                          else None, e.unit))
    used = {e.ref_column for e in entries} | {time_column}
    unmatched = [c for c in header if c not in used]
    return SeriesSet(out, unmatched)


def h5_series(res: Result, ref: Result, channels: list[str] | None) -> SeriesSet:
    """Channels of two LANDYN results (default: strokes, strut forces, footpad forces, body motion)."""
    if ref.n_gears != res.n_gears:
        raise LandynPostError(f"{ref.path} has {ref.n_gears} gears, {res.path} has {res.n_gears}")
    if channels:
        pairs = [(res.channel(c), ref.channel(c)) for c in channels]
    else:
        keys = ("stroke", "strut_force", "normal_force", "friction_force", "velocity", "euler_angles", "overload")
        pairs = list(zip(res.channels(keys), ref.channels(keys)))
    out = [Series(a.label, a.units, res.time, a.values, ref.time, b.values, gear=a.gear,
                  strut=a.index if a.key in ("stroke", "strut_force", "strut_length") else None) for a, b in pairs]
    return SeriesSet(out, [])


# ----------------------------------------------------------------------------------------- comparison

@dataclass
class CrushRow:
    measure: int
    gear: int
    strut: int
    value: float       # m
    ref: float         # m
    allowed_mm: float | None = None
    passed: bool | None = None

    @property
    def dev(self) -> float:
        return self.value - self.ref

    @property
    def pct(self) -> float:
        return 100.0 * self.dev / abs(self.ref) if abs(self.ref) > 1e-12 else math.nan


def crush_rows(res: Result, ref: StrutReference) -> list[CrushRow]:
    rows = []
    for m in sorted(ref.values):
        g, k = measure_gear_strut(m, res.n_struts)
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
    ref_range: float
    allowed: float | None = None
    passed: bool | None = None
    metrics: Metrics | None = None
    cov_run: float | None = None           # share (0..1) of the run the reference covers
    cov_td: float | None = None            # share of the touchdown phase
    metric_checks: list[tuple[str, float, float, bool, str]] = field(default_factory=list)  # name, value, limit, ok, op
    shift: float = 0.0                     # added to the reference's time [s]
    cfc: int | None = None                 # filter class applied to both signals


def resample(s: Series, shift: float = 0.0, cfc: int | None = None, iso: bool = False) -> SeriesStats:
    """Both signals treated alike: the reference's time shifted by `shift` [s], both CFC-filtered
    (each on its own samples) when `cfc` is given, then linearly interpolated onto one uniform time
    base over the overlap of their ranges (step: the finer of the two median sample intervals);
    the deviation statistics and the correlation metrics on that base."""
    t_ref = s.t_ref + shift
    y, y_ref = s.y, s.y_ref
    if cfc:
        y, y_ref = cfc_filter(s.t, y, cfc), cfc_filter(t_ref, y_ref, cfc)
    try:
        t = common_base(s.t, t_ref)
    except LandynPostError as exc:
        raise LandynPostError(f"{s.label}: {exc}") from None
    y, yr = np.interp(t, s.t, y), np.interp(t, t_ref, y_ref)
    d = y - yr
    k = int(np.argmax(np.abs(d)))
    return SeriesStats(s, t, y, yr, float(np.sqrt(np.mean(d * d))), float(abs(d[k])), float(t[k]),
                       float(np.ptp(s.y_ref)), metrics=metrics(t, y, yr, iso=iso), shift=shift, cfc=cfc)


@dataclass
class RmsTolerances:
    """Command-line rms tolerances: absolute values by channel unit (or one bare number), and a
    relative one in % of the reference range."""
    by_unit: dict[str, float] = field(default_factory=dict)   # channel unit -> value in that unit
    bare: float | None = None
    rtol_pct: float | None = None

    @classmethod
    def parse(cls, items: list[str] | None, rtol_pct: float | None) -> "RmsTolerances":
        t = cls(rtol_pct=rtol_pct)
        for it in items or []:
            v, u = parse_quantity(it)
            if v < 0:
                raise LandynPostError(f"--tol-rms {it}: must be >= 0")
            if u == "%":
                raise LandynPostError(f"--tol-rms {it}: relative tolerances go in --rtol-rms PCT")
            if u is None:
                if t.bare is not None:
                    raise LandynPostError("--tol-rms: more than one value without a unit")
                t.bare = v
                continue
            from .units import UNITS
            kind, fac = UNITS[u]
            if kind in t.by_unit:
                raise LandynPostError(f"--tol-rms: two values for channels in {kind}")
            t.by_unit[kind] = v * fac
        return t

    @property
    def given(self) -> bool:
        return bool(self.by_unit) or self.bare is not None or self.rtol_pct is not None

    def check_bare(self, stats: list["SeriesStats"]) -> None:
        units = sorted({st.series.units for st in stats if st.series.tol is None})
        if self.bare is not None and len(units) > 1:
            raise cli.LandynUsageError(f"--tol-rms {self.bare:g} has no unit, but the channels are in {', '.join(units)}: "
                                  "give one value per unit, e.g. --tol-rms 2mm 5kN 0.1g (or --rtol-rms PCT)")


@dataclass
class Checks:
    tol_mm: float | None = None
    tol_pct: float | None = None
    rms: RmsTolerances = field(default_factory=RmsTolerances)
    failures: list[str] = field(default_factory=list)
    n_checked: int = 0
    unchecked: list[str] = field(default_factory=list)     # compared, but no tolerance applied

    def crush_limit(self, ref_m: float) -> float | None:
        """Allowed |deviation| in mm: tol_mm + tol_pct % of |reference| (either alone if only one is given)."""
        if self.tol_mm is None and self.tol_pct is None:
            return None
        return (self.tol_mm or 0.0) + (self.tol_pct or 0.0) / 100.0 * abs(ref_m) * MM

    def check_crush(self, rows: list[CrushRow]) -> None:
        for r in rows:
            r.allowed_mm = self.crush_limit(r.ref)
            if r.allowed_mm is None:
                self.unchecked.append(f"crush No. {r.measure}")
                continue
            self.n_checked += 1
            r.passed = abs(r.dev) * MM <= r.allowed_mm
            if not r.passed:
                self.failures.append(f"crush No. {r.measure} (gear {r.gear} {STRUT_LABELS[STRUTS[r.strut]]}): "
                                     f"|deviation| {abs(r.dev) * MM:.2f} mm > allowed {r.allowed_mm:.2f} mm")

    def series_limit(self, st: SeriesStats) -> float | None:
        s = st.series
        if s.tol is not None or s.rtol_pct is not None:          # the map line decides
            return (s.tol or 0.0) + (s.rtol_pct or 0.0) / 100.0 * st.ref_range
        a = self.rms.by_unit.get(s.units, self.rms.bare)
        if a is None and self.rms.rtol_pct is None:
            return None
        return (a or 0.0) + (self.rms.rtol_pct or 0.0) / 100.0 * st.ref_range

    def check_series(self, stats: list[SeriesStats]) -> None:
        self.rms.check_bare(stats)
        for st in stats:
            st.allowed = self.series_limit(st)
            if st.allowed is None:
                self.unchecked.append(f"time history {st.series.label} (no tolerance for {st.series.units})")
                continue
            self.n_checked += 1
            st.passed = st.rms <= st.allowed
            if not st.passed:
                self.failures.append(f"time history {st.series.label}: rms deviation {st.rms:.4g} {st.series.units} "
                                     f"> allowed {st.allowed:.4g} {st.series.units}")


#: metrics that --limit can bound: name -> (description); errors are compared by their magnitude
METRIC_NAMES = ("rms", "peak_error_pct", "peak_time_error", "sg_m", "sg_p", "sg_c", "iso_corridor", "iso_phase",
                "iso_magnitude", "iso_slope", "iso_rating")


def metric_value(m: Metrics, name: str) -> float:
    """The value of a METRIC_NAMES metric (|.| of the signed errors; NaN when not computed)."""
    if name.startswith("iso_"):
        if m.iso is None:
            return math.nan
        return {"iso_corridor": m.iso.corridor, "iso_phase": m.iso.phase, "iso_magnitude": m.iso.magnitude,
                "iso_slope": m.iso.slope, "iso_rating": m.iso.overall}[name]
    return abs({"rms": m.rms, "peak_error_pct": m.peak_error_pct, "peak_time_error": m.peak_time_error,
                "sg_m": m.sg_m, "sg_p": m.sg_p, "sg_c": m.sg_c}[name])


@dataclass
class MetricLimits:
    """Command-line limits on the correlation metrics (None: not checked)."""
    max_peak_error: float | None = None        # |peak error| [%]
    max_peak_time_error: float | None = None   # |time-of-peak error| [s]
    max_sg_c: float | None = None              # Sprague & Geers comprehensive error [-]
    min_iso_rating: float | None = None        # ISO/TS 18571 overall rating [-]
    extra: list[tuple[str, str, float]] = field(default_factory=list)   # --limit NAME<=X / NAME>=X

    @property
    def given(self) -> bool:
        return bool(self.extra) or any(v is not None for k, v in vars(self).items() if k != "extra")

    @staticmethod
    def parse_limit(text: str) -> tuple[str, str, float]:
        """'sg_m<=0.1' -> ('sg_m', '<=', 0.1); the names are METRIC_NAMES."""
        m = re.match(r"^\s*([a-z_]+)\s*(<=|>=)\s*([-+0-9.eE]+)\s*$", text)
        if not m or m.group(1) not in METRIC_NAMES:
            raise cli.LandynUsageError(f"--limit {text!r}: expected NAME<=X or NAME>=X with NAME one of "
                                       f"{', '.join(METRIC_NAMES)}")
        try:
            return m.group(1), m.group(2), float(m.group(3))
        except ValueError:
            raise cli.LandynUsageError(f"--limit {text!r}: {m.group(3)!r} is not a number") from None

    def check(self, stats: list[SeriesStats], checks: "Checks") -> None:
        """Adds one check per channel and limit to `checks` (a NaN metric fails)."""
        for st in stats:
            m = st.metrics
            items = [("peak error [%]", abs(m.peak_error_pct), self.max_peak_error, False),
                     ("time-of-peak error [s]", abs(m.peak_time_error), self.max_peak_time_error, False),
                     ("Sprague-Geers C", m.sg_c, self.max_sg_c, False),
                     ("ISO 18571 rating", m.iso.overall if m.iso else math.nan, self.min_iso_rating, True)]
            for key, op, limit in self.extra:
                items.append((key, metric_value(m, key), limit, op == ">="))
            for name, value, limit, at_least in items:
                if limit is None:
                    continue
                ok = bool(value >= limit if at_least else value <= limit)    # NaN -> False
                st.metric_checks.append((name, value, limit, ok, ">=" if at_least else "<="))
                checks.n_checked += 1
                if not ok:
                    rel = ">=" if at_least else "<="
                    checks.failures.append(f"time history {st.series.label}: {name} {value:.4g}, required {rel} "
                                           f"{limit:.4g}" + (f" ({m.iso_note})" if name.startswith("ISO") and
                                                             m.iso_note else ""))


@dataclass
class Alignment:
    """The shift added to the reference's time [s] and how it was found."""
    mode: str
    shift: float = 0.0
    detail: str = ""


def _alignment_series(series: list[Series], name: str | None) -> Series:
    if not series:
        raise LandynPostError("alignment: no channel is compared")
    if name is None:
        return series[0]
    for s in series:
        if name in (s.label, s.label.split(" -> ")[0], s.label.split(" -> ")[-1]):
            return s
    raise LandynPostError(f"--align-channel {name!r}: not a compared channel "
                          f"({', '.join(s.label.split(' -> ')[0] for s in series)})")


def align(series: list[Series], mode: str, shift: float | None, max_shift: float, channel: str | None) -> Alignment:
    """One shift for all channels of a reference (they share its clock): given, or from the
    touchdown instants or the cross-correlation of the alignment channel."""
    if shift is not None:
        return Alignment("given", shift, f"given shift {shift:+.6g} s")
    if mode == "none":
        return Alignment("none", 0.0, "none")
    s = _alignment_series(series, channel)
    if mode == "touchdown":
        t_res, t_ref = touchdown_time(s.t, s.y), touchdown_time(s.t_ref, s.y_ref)
        return Alignment("touchdown", t_res - t_ref,
                         f"touchdown of {s.label}: LANDYN {t_res:.6f} s, reference {t_ref:.6f} s (first |y - y(t0)| "
                         f">= 5 % of its largest value)")
    sh = xcorr_shift(s.t, s.y, s.t_ref, s.y_ref, max_shift)
    return Alignment("xcorr", sh, f"largest cross-correlation of {s.label} within +-{max_shift:g} s")


def touchdown_phase(res: Result) -> tuple[float, float]:
    """The result's touchdown phase [s]: from the first footpad contact (a normal force > 0) to
    the instant the honeycomb work reaches 99 % of its final value (the end of crushing); the last
    contact instant when nothing crushes."""
    t = res.time
    contact = np.any(np.asarray(res.normal_force).reshape(len(t), -1) > 0, axis=1)
    if not contact.any():
        return float(t[0]), float(t[-1])
    t0 = float(t[int(np.argmax(contact))])
    w = np.asarray(res.energy["honeycomb_work"])
    if w[-1] > 0:
        t1 = float(t[int(np.argmax(w >= 0.99 * w[-1]))])
    else:
        t1 = float(t[len(t) - 1 - int(np.argmax(contact[::-1]))])
    return t0, max(t0, t1)


def check_coverage(stats: list[SeriesStats], res: Result, shift: float, min_run: float, min_td: float,
                   checks: "Checks") -> tuple[float, float]:
    """Shares of the run and of its touchdown phase covered by each reference channel; a failure
    under min_run / min_td [%]. Returns the touchdown phase [s]."""
    td0, td1 = touchdown_phase(res)
    for st in stats:
        tr = st.series.t_ref + shift
        st.cov_run = coverage(tr, float(res.time[0]), float(res.time[-1]))
        st.cov_td = coverage(tr, td0, td1)
        for what, v, lim in (("the run", st.cov_run, min_run), ("the touchdown phase", st.cov_td, min_td)):
            if 100.0 * v < lim - 1e-9:
                checks.failures.append(f"coverage: {st.series.label}: the reference covers {100 * v:.1f} % of "
                                       f"{what}, required {lim:g} % (--min-coverage / --min-touchdown-coverage)")
    return td0, td1


# ----------------------------------------------------------------------------------------- output

def _verdict(passed: bool | None) -> str:
    return "-" if passed is None else ("pass" if passed else "FAIL")


def crush_table(rows: list[CrushRow], title: str) -> str:
    head = (f"{'No.':>4} {'gear':>4}  {'strut':<16}{'LANDYN':>10}{'reference':>11}{'dev':>9}{'dev':>9}"
            f"{'allowed':>9}{'result':>8}")
    lines = [title, head, f"{'':>4} {'':>4}  {'':<16}{'[mm]':>10}{'[mm]':>11}{'[mm]':>9}{'[%]':>9}{'[mm]':>9}",
             "-" * len(head)]
    for r in rows:
        pct = f"{r.pct:9.2f}" if math.isfinite(r.pct) else f"{'-':>9}"
        allowed = f"{r.allowed_mm:9.2f}" if r.allowed_mm is not None else f"{'-':>9}"
        lines.append(f"{r.measure:>4} {r.gear:>4}  {STRUT_LABELS[STRUTS[r.strut]]:<16}{r.value * MM:10.1f}"
                     f"{r.ref * MM:11.1f}{r.dev * MM:9.2f}{pct}{allowed}{_verdict(r.passed):>8}")
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
    """Deviations in each channel's display unit (the map's unit=, else mm, kN, ...)."""
    w = max([len(s.series.label) for s in stats] + [7])
    head = (f"{'channel':<{w}}  {'units':<6}{'rms dev':>12}{'max |dev|':>12}{'at t [s]':>10}{'ref range':>12}"
            f"{'allowed':>12}{'result':>8}{'samples':>9}")
    lines = ["Time histories (LANDYN - reference on one time base; allowed = rms tolerance)", head, "-" * len(head)]
    for s in stats:
        u, f = s.series.display()
        allowed = f"{s.allowed * f:12.4g}" if s.allowed is not None else f"{'-':>12}"
        lines.append(f"{s.series.label:<{w}}  {u:<6}{s.rms * f:12.4g}{s.max_abs * f:12.4g}{s.t_max:10.4f}"
                     f"{s.ref_range * f:12.4g}{allowed}{_verdict(s.passed):>8}{len(s.t):9d}")
    return "\n".join(lines)


def _f(v: float | None, fmt: str, width: int) -> str:
    return f"{'-':>{width}}" if v is None or not math.isfinite(v) else f"{v:{width}{fmt}}"


def metrics_table(stats: list[SeriesStats]) -> str:
    """Peaks (display units), Sprague & Geers, ISO/TS 18571 and coverage per channel."""
    w = max([len(s.series.label.split(" -> ")[0]) for s in stats] + [7])
    head = (f"{'channel':<{w}} {'unit':<5}{'peak':>9}{'t [s]':>8}{'ref peak':>9}{'t [s]':>8}{'err %':>7}"
            f"{'SG M':>7}{'SG P':>7}{'SG C':>7}{'ISO Z':>7}{'E_P':>6}{'E_M':>6}{'E_S':>6}{'R':>6}  {'grade':<9}"
            f"{'cov run':>8}{'cov td':>7}")
    lines = ["Correlation metrics (Sprague & Geers errors; ISO/TS 18571 ratings 0..1; coverage in %)", head,
             "-" * len(head)]
    for s in stats:
        m, (u, f) = s.metrics, s.series.display()
        iso = m.iso
        lines.append(f"{s.series.label.split(' -> ')[0]:<{w}} {u:<5}{m.peak * f:9.4g}{m.t_peak:8.4f}"
                     f"{m.peak_ref * f:9.4g}{m.t_peak_ref:8.4f}{_f(m.peak_error_pct, '.2f', 7)}"
                     f"{_f(m.sg_m, '.3f', 7)}{_f(m.sg_p, '.3f', 7)}{_f(m.sg_c, '.3f', 7)}"
                     f"{_f(iso.corridor if iso else None, '.3f', 7)}{_f(iso.phase if iso else None, '.3f', 6)}"
                     f"{_f(iso.magnitude if iso else None, '.3f', 6)}{_f(iso.slope if iso else None, '.3f', 6)}"
                     f"{_f(iso.overall if iso else None, '.3f', 6)}  {(iso.grade if iso else '-'):<9}"
                     f"{_f(None if s.cov_run is None else 100 * s.cov_run, '.1f', 8)}"
                     f"{_f(None if s.cov_td is None else 100 * s.cov_td, '.1f', 7)}")
    return "\n".join(lines)


def write_table_csv(path: str, rows: list[CrushRow]) -> str:
    with cli.atomic_output(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["measure", "gear", "strut", "landyn_mm", "reference_mm", "deviation_mm", "deviation_pct",
                    "allowed_mm", "result"])
        for r in rows:
            w.writerow([r.measure, r.gear, STRUTS[r.strut], f"{r.value * MM:.6f}", f"{r.ref * MM:.6f}",
                        f"{r.dev * MM:.6f}", f"{r.pct:.6f}" if math.isfinite(r.pct) else "",
                        f"{r.allowed_mm:.6f}" if r.allowed_mm is not None else "", _verdict(r.passed)])
    return path


def write_series_csv(path: str, stats: list[SeriesStats]) -> str:
    with cli.atomic_output(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["channel", "units", "rms_deviation", "max_abs_deviation", "time_of_max_s", "reference_range",
                    "allowed_rms", "result", "samples", "peak", "time_of_peak_s", "reference_peak",
                    "reference_time_of_peak_s", "peak_error_pct", "sprague_geers_m", "sprague_geers_p",
                    "sprague_geers_c", "iso18571_corridor", "iso18571_phase", "iso18571_magnitude", "iso18571_slope",
                    "iso18571_rating", "iso18571_grade", "coverage_run_pct", "coverage_touchdown_pct",
                    "reference_shift_s", "cfc"])
        for s in stats:
            m = s.metrics
            iso = [m.iso.corridor, m.iso.phase, m.iso.magnitude, m.iso.slope, m.iso.overall] if m.iso else [None] * 5

            def g(v):
                return "" if v is None or not math.isfinite(v) else f"{v:.9g}"
            w.writerow([s.series.label, s.series.units, f"{s.rms:.9g}", f"{s.max_abs:.9g}", f"{s.t_max:.9g}",
                        f"{s.ref_range:.9g}", f"{s.allowed:.9g}" if s.allowed is not None else "",
                        _verdict(s.passed), len(s.t), g(m.peak), g(m.t_peak), g(m.peak_ref), g(m.t_peak_ref),
                        g(m.peak_error_pct), g(m.sg_m), g(m.sg_p), g(m.sg_c), *[g(v) for v in iso],
                        m.iso.grade if m.iso else "", g(None if s.cov_run is None else 100 * s.cov_run),
                        g(None if s.cov_td is None else 100 * s.cov_td), f"{s.shift:.9g}", s.cfc or ""])
    return path


def _safe(name: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", name).strip("_")[:80]


def write_plots(outdir: str, rows: list[CrushRow], stats: list[SeriesStats], res_label: str, ref_label: str,
                res: Result) -> list[str]:
    """Crush-length bars with the deviation and the allowed band, and one figure per time history:
    overlay in engineering units with the tolerance band around the reference, and the deviation."""
    cli.use_agg()
    import matplotlib.pyplot as plt
    written = []
    if rows:
        fig, (ax, ax2) = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True, gridspec_kw={"height_ratios": [2, 1]})
        x = np.array([r.measure for r in rows])
        ax.bar(x - 0.2, [r.value * MM for r in rows], 0.4, label=res_label, color="#4c72b0")
        ax.bar(x + 0.2, [r.ref * MM for r in rows], 0.4, label=ref_label, color="#c44e52")
        ax.axhline(0, color="k", lw=0.6)
        ax.set_ylabel("crush length [mm]")
        ax.legend(fontsize=7)
        ax.grid(True, axis="y", alpha=0.3)
        colors = ["0.4" if r.passed is None else ("tab:green" if r.passed else "tab:red") for r in rows]
        ax2.bar(x, [r.dev * MM for r in rows], 0.5, color=colors)
        lim = [r.allowed_mm for r in rows]
        if any(v is not None for v in lim):
            for xi, v in zip(x, lim):
                if v is not None:
                    ax2.fill_between([xi - 0.4, xi + 0.4], -v, v, color="0.85", zorder=0)
            ax2.plot([], [], color="0.85", lw=6, label="allowed deviation")
            ax2.legend(fontsize=7, loc="best")
        ax2.axhline(0, color="k", lw=0.6)
        ax2.set_ylabel("deviation [mm]\n(LANDYN - reference)")
        ax2.set_xticks(x)
        ax2.set_xticklabels([f"{r.measure}\nG{r.gear}{'PLR'[r.strut]}" for r in rows], fontsize=7)
        ax2.set_xlabel("measure (Table 3): G = gear, P primary, L secondary left, R secondary right")
        ax2.grid(True, axis="y", alpha=0.3)
        fig.suptitle("\n".join(textwrap.wrap(f"Crush lengths: {res_label}", 100) + [f"vs {ref_label}"]), fontsize=9)
        fig.tight_layout()
        written.append(cli.savefig(fig, os.path.join(outdir, "compare_crush_lengths.png"), dpi=110))
        plt.close(fig)
    for i, st in enumerate(stats, 1):
        s = st.series
        eu, f = s.display()
        fig, (ax, ax2) = plt.subplots(2, 1, figsize=(8, 5.5), sharex=True, gridspec_kw={"height_ratios": [2, 1]})
        if st.allowed is not None:
            ax.fill_between(st.t, (st.y_ref - st.allowed) * f, (st.y_ref + st.allowed) * f, color="0.85",
                            label=f"reference ± allowed rms {st.allowed * f:.3g} {eu}")
        # the compared signals: the reference shifted and both filtered as stated, on the common time base
        ax.plot(st.t, st.y * f, color="#4c72b0", lw=2.4, alpha=0.55, label=res_label, zorder=2)
        shift = f" (shifted {st.shift:+.4g} s)" if st.shift else ""
        ax.plot(st.t, st.y_ref * f, color="#c44e52", lw=1.0, ls="--", label=ref_label + shift, zorder=3)
        ax.set_xlim(st.t[0], st.t[-1])
        ax.set_ylabel(f"[{eu}]")
        ax.legend(fontsize=7, loc="best")
        ax.grid(True, alpha=0.3)
        d = (st.y - st.y_ref) * f
        ax2.plot(st.t, d, color="k", lw=1.0, label="deviation")
        if st.allowed is not None:
            ax2.axhspan(-st.allowed * f, st.allowed * f, color="0.85", label="± allowed rms")
        ax2.axhline(0, color="0.5", lw=0.6)
        ax2.set_ylabel(f"LANDYN - ref [{eu}]")
        ax2.set_xlabel("time [s]")
        ax2.grid(True, alpha=0.3)
        ax2.legend(fontsize=7, loc="best")
        verdict = {None: "not checked", True: "PASS", False: "FAIL"}[st.passed]
        allowed = f", allowed {st.allowed * f:.3g}" if st.allowed is not None else ""
        ax.set_title(f"{s.label}\nrms dev {st.rms * f:.3g} {eu}{allowed}, max |dev| {st.max_abs * f:.3g} {eu} "
                     f"at {st.t_max:.3f} s: {verdict}", fontsize=8)
        fig.tight_layout()
        written.append(cli.savefig(fig, os.path.join(outdir, f"compare_{i:02d}_{_safe(s.label.split(' -> ')[-1])}.png"),
                                   dpi=100))
        plt.close(fig)
    return written


# ----------------------------------------------------------------------------------------- main

def _run_label(path: str, title: str = "") -> str:
    base = os.path.basename(path)
    return f"{base}: {textwrap.shorten(title, 50)}" if title else base


def _load_case_warnings(res: Result, selected: str | None, ref_title: str | None = None,
                        ref: Result | None = None) -> list[str]:
    out = []
    lc = load_case_of(res)
    lc_title = load_case_in_title(res.title)
    if selected:
        sel = selected.upper()
        if lc is not None and lc != sel:
            out.append(f"the result was run for {lc} (its touchdown conditions), but the reference rows are "
                       f"{selected}")
        elif lc is None:
            out.append(f"the result's touchdown conditions match none of the paper's load cases, but the reference "
                       f"rows are {selected}")
        if lc_title is not None and lc_title != sel:
            out.append(f"the result's title names {lc_title} ({res.title!r}), but the reference rows are {selected}")
    if ref is not None:
        lc_ref = load_case_of(ref)
        if lc != lc_ref and (lc or lc_ref):
            out.append(f"the result was run for {lc or 'no paper load case'}, the reference for "
                       f"{lc_ref or 'no paper load case'}")
        if res.title != ref.title:
            out.append(f"the titles differ: result {res.title!r}, reference {ref.title!r}")
    elif ref_title is not None:
        lc_ref = load_case_in_title(ref_title)
        if lc_ref and lc and lc_ref != lc:
            out.append(f"the result was run for {lc}, the reference names {lc_ref}")
    return out


def _not_checked_struts(res: Result, rows: list[CrushRow], series: list[Series], crush_ref: bool) -> list[str]:
    """Struts of the result without a compared crush length (crush references) or without any
    compared stroke/force/length history (time-history references)."""
    out = []
    if crush_ref:
        have = {r.measure for r in rows}
        for g in range(1, res.n_gears + 1):
            for k in range(res.n_struts):
                if measure_number(g, k, res.n_struts) not in have:
                    out.append(f"No. {measure_number(g, k, res.n_struts)} gear {g} {STRUT_LABELS[STRUTS[k]]}")
    else:
        have = {(s.gear, s.strut) for s in series if s.strut is not None}
        for g in range(1, res.n_gears + 1):
            for k in range(res.n_struts):
                if (g, k) not in have:
                    out.append(f"gear {g} {STRUT_LABELS[STRUTS[k]]}")
    return out


def _main(argv=None) -> int:
    p = cli.make_parser(
        "landyn-compare",
        "Compare a LANDYN result with a reference: another LANDYN result (.h5), a per-strut crush-length\n"
        "CSV (Table 3 layout, mm) or a time-history CSV (--timeseries). Deviation = RESULT - REFERENCE.\n"
        "Every reference channel is compared or listed as not compared; every strut not checked is named.",
        epilog="tolerances:\n"
               "  a crush length fails when |dev| > tol_mm + tol_pct/100 * |reference| (numpy.isclose style;\n"
               "  with only one of --tol-mm / --tol-pct given, that one alone); a time history fails when its\n"
               "  rms deviation exceeds tol + rtol/100 * (reference max - min), tol and rtol from its map line or\n"
               "  else from --tol-rms (one value per unit, e.g. 2mm 5kN 0.1g 0.5deg) and --rtol-rms; the metric\n"
               "  limits (--max-peak-error, --max-peak-time-error, --max-sg-c, --min-iso-rating) apply to every\n"
               "  compared channel; a time-history reference fails when it covers less than --min-coverage %\n"
               "  of the run or --min-touchdown-coverage % of the touchdown phase (first footpad contact to\n"
               "  99 % of the final honeycomb work).\n\n"
               "alignment (one shift for all channels of a reference, reported and stored in the report):\n"
               "  --align touchdown: the touchdown instant of the alignment channel (--align-channel, default the\n"
               "  first) in both signals, the first time |y - y(t0)| reaches 5 % of its largest value;\n"
               "  --align xcorr: largest correlation within --max-shift; --shift S: given.\n\n"
               "exit status (as landyn's): 0 at least one check ran and all passed; 1 usage error; 2 invalid\n"
               "  input; 3 a check failed (a tolerance or metric limit exceeded, a reference channel not\n"
               "  compared, a coverage under its minimum, or with --strict a strut not checked); 4 an output\n"
               "  file could not be written; 5 nothing was checked (no tolerance).\n\n"
               "examples:\n"
               "  landyn-compare lc1.h5 post/landyn_post/data/table3_crush_lengths.csv --load-case LC-1 --column theory"
               " --tol-pct 3\n"
               "  landyn-compare new.h5 baseline.h5 --tol-mm 0.1 --tol-rms 1mm 2kN 0.05g 0.1deg 0.01m/s\n"
               "  landyn-compare lc1.h5 droptest.csv --timeseries --map droptest.map --strict --plots cmp\n"
               "  landyn-compare lc1.h5 droptest.csv --timeseries --map droptest.map --align touchdown --cfc 60 \\\n"
               "      --min-iso-rating 0.8 --report validation.pdf\n\n" + MAP_HELP)
    p.add_argument("result", metavar="RESULT", help="LANDYN result file (.h5)")
    p.add_argument("reference", metavar="REFERENCE", help="LANDYN result (.h5) or CSV")
    p.add_argument("--load-case", metavar="NAME", help="rows of this load_case (per-strut CSV), e.g. LC-1")
    p.add_argument("--column", metavar="NAME", help="value column of a per-strut CSV, e.g. theory (-> theory_mm)")
    p.add_argument("--timeseries", action="store_true",
                   help="REFERENCE is a time-history CSV (a MAT file is always one: one vector per channel)")
    p.add_argument("--map", metavar="MAPFILE", help="channel map for --timeseries (format below)")
    p.add_argument("--time-column", metavar="NAME", help="time column of a time-history CSV (default: see map/first)")
    p.add_argument("--time-factor", type=float, default=1.0, metavar="F", help="time column * F = seconds (default 1)")
    p.add_argument("--channels", nargs="+", metavar="CHANNEL",
                   help="channels compared between two .h5 files, e.g. 'stroke[gear=1,strut=primary]'")
    p.add_argument("--tol-mm", type=float, metavar="X", help="crush-length tolerance [mm]")
    p.add_argument("--tol-pct", type=float, metavar="Y", help="crush-length tolerance [%% of |reference|]")
    p.add_argument("--tol-rms", nargs="+", metavar="X[UNIT]",
                   help="absolute rms tolerance of the time histories, one per unit: 2mm 5kN 0.1g 0.5deg "
                        "(a bare number only when every channel has the same unit)")
    p.add_argument("--rtol-rms", type=float, metavar="PCT",
                   help="relative rms tolerance of the time histories [%% of the reference's range]")
    p.add_argument("--strict", action="store_true",
                   help="also fail (exit 3) when a strut of the result is not checked (a reference channel not "
                        "compared always fails, see --allow-unmatched)")
    p.add_argument("--allow-unmatched", action="store_true",
                   help="list reference channels that are not compared instead of failing on them")
    p.add_argument("--min-coverage", type=float, default=50.0, metavar="PCT",
                   help="least share of the run a time-history reference must cover [%%] (default 50)")
    p.add_argument("--min-touchdown-coverage", type=float, default=95.0, metavar="PCT",
                   help="least share of the touchdown phase it must cover [%%] (default 95)")
    p.add_argument("--align", choices=("none", "touchdown", "xcorr"), default="none",
                   help="shift the reference's time: touchdown instants matched, or largest cross-correlation")
    p.add_argument("--shift", type=float, metavar="S", help="add S seconds to the reference's time (given alignment)")
    p.add_argument("--max-shift", type=float, default=0.05, metavar="S",
                   help="bound of the cross-correlation search [s] (default 0.05)")
    p.add_argument("--align-channel", metavar="NAME", help="channel that sets the alignment (default: the first)")
    p.add_argument("--cfc", type=int, choices=(60, 180, 600), metavar="CLASS",
                   help="filter both signals with this SAE J211 channel frequency class (60, 180, 600)")
    p.add_argument("--iso", action="store_true",
                   help="ISO/TS 18571 ratings for every channel (default: mapped channels of a --map, or with "
                        "--min-iso-rating or --report; about 0.3 s per channel and second of signal)")
    p.add_argument("--max-peak-error", type=float, metavar="PCT", help="limit on |peak error| [%%] per channel")
    p.add_argument("--max-peak-time-error", type=float, metavar="S", help="limit on |time-of-peak error| [s]")
    p.add_argument("--max-sg-c", type=float, metavar="X", help="limit on the Sprague & Geers comprehensive error")
    p.add_argument("--min-iso-rating", type=float, metavar="R", help="least ISO/TS 18571 overall rating (0..1)")
    p.add_argument("--limit", nargs="+", default=[], metavar="NAME<=X",
                   help="limits on any metric, e.g. 'sg_m<=0.1' 'iso_slope>=0.5' (names: "
                        + ", ".join(METRIC_NAMES) + "; errors by magnitude; rms in the channel's unit)")
    p.add_argument("--report", metavar="PDF", help="write the validation report (PDF)")
    p.add_argument("--plots", metavar="DIR", help="write overlay plots to DIR")
    p.add_argument("--table-csv", metavar="FILE",
                   help="write the deviation table as CSV (crush lengths; time histories to FILE or <stem>_timeseries.csv)")
    a = p.parse_args(argv)
    for name in ("tol_mm", "tol_pct", "rtol_rms", "min_coverage", "min_touchdown_coverage", "max_shift",
                 "max_peak_error", "max_peak_time_error", "max_sg_c", "min_iso_rating"):
        v = getattr(a, name)
        if v is not None and not v >= 0:
            p.error(f"--{name.replace('_', '-')} must be >= 0")
    try:
        rms_tol = RmsTolerances.parse(a.tol_rms, a.rtol_rms)
    except LandynPostError as exc:
        p.error(str(exc))
    # the output-file policy (docs/files.md) before any work: never replace an input
    inputs = [a.result, a.reference, a.map]
    if a.table_csv:
        stem_, ext_ = os.path.splitext(a.table_csv)
        for out in (a.table_csv, stem_ + "_timeseries" + (ext_ or ".csv")):
            cli.refuse_overwrite(out, inputs)
    if a.plots and not os.path.isdir(a.plots):
        cli.refuse_overwrite(a.plots, inputs)

    res = load(a.result)
    rows: list[CrushRow] = []
    sset = SeriesSet([], [])
    ref_path = a.reference
    if not os.path.exists(ref_path):
        raise LandynPostError(f"{ref_path}: no such file")
    warnings: list[str] = []
    res_label = _run_label(a.result, res.title)
    crush_ref = False
    if is_hdf5(ref_path):
        if a.timeseries or a.map or a.column or a.load_case:
            p.error("--timeseries, --map, --column and --load-case apply to CSV references only")
        ref = load(ref_path)
        ref_label = _run_label(ref_path, ref.title)
        if ref_label == res_label:
            res_label, ref_label = "result " + res_label, "reference " + ref_label
        crush_ref = True
        rows = crush_rows(res, StrutReference(
            {measure_number(g + 1, k, ref.n_struts): float(ref.crush_length[g, k])
             for g in range(ref.n_gears) for k in range(ref.n_struts)},
            ref_label))
        sset = h5_series(res, ref, a.channels)
        warnings += _load_case_warnings(res, None, ref=ref)
    elif a.channels:
        p.error("--channels applies to .h5 references (a CSV's channels come from its columns or --map)")
    elif a.timeseries or is_mat(ref_path):
        a.timeseries = True
        if a.column or a.load_case:
            p.error("--column and --load-case apply to per-strut crush-length CSVs, not to --timeseries")
        sset = read_timeseries_csv(ref_path, res, a.map, a.time_column, a.time_factor)
        ref_label = os.path.basename(ref_path)
        warnings += _load_case_warnings(res, None, ref_title=ref_label)
    else:
        if a.map:
            p.error("--map needs --timeseries")
        sref = read_strut_csv(ref_path, res.n_gears, a.load_case, a.column, res.n_struts)
        rows = crush_rows(res, sref)
        ref_label = sref.label
        crush_ref = True
        sel = a.load_case
        if sel is None:
            m = re.search(r"load case ([^)]+)\)", sref.label)
            sel = m.group(1) if m else None
        warnings += _load_case_warnings(res, sel)

    checks = Checks(a.tol_mm, a.tol_pct, rms_tol)
    print(f"LANDYN result: {res.path} ({res.title})")
    print(f"reference:     {ref_label}")
    for w in warnings:
        print(f"landyn-compare: warning: {w}", file=sys.stderr)
        print(f"WARNING: {w}")
    print()
    if rows:
        checks.check_crush(rows)
        print(crush_table(rows, "Crush lengths (Table 3 layout; primary shortening, secondary lengthening +)"))
    external = bool(a.timeseries)
    limits = MetricLimits(a.max_peak_error, a.max_peak_time_error, a.max_sg_c, a.min_iso_rating,
                          [MetricLimits.parse_limit(x) for x in a.limit])
    want_iso = (bool(a.map) or a.iso or a.min_iso_rating is not None or a.report is not None
                or any(k.startswith("iso_") for k, _, _ in limits.extra))
    al = align(sset.series, a.align, a.shift, a.max_shift, a.align_channel) if sset.series else Alignment("none")
    stats = [resample(s, al.shift, a.cfc, want_iso) for s in sset.series]
    td_phase = None
    if stats:
        if external:
            td_phase = check_coverage(stats, res, al.shift, a.min_coverage, a.min_touchdown_coverage, checks)
        checks.check_series(stats)
        limits.check(stats, checks)
        print()
        print(f"alignment: {al.detail}; shift added to the reference's time: {al.shift:+.6f} s")
        print(f"filter: {cfc_label(a.cfc) + ', both signals' if a.cfc else 'none'}; resampling: {RESAMPLING}")
        if td_phase:
            print(f"touchdown phase of the result (for coverage): {td_phase[0]:.4f} .. {td_phase[1]:.4f} s")
        print(series_table(stats))
        print()
        print(metrics_table(stats))
    if a.table_csv:
        if rows:
            print(write_table_csv(a.table_csv, rows))
        if stats:
            stem, ext = os.path.splitext(a.table_csv)
            print(write_series_csv(stem + "_timeseries" + (ext or ".csv") if rows else a.table_csv, stats))
    if a.plots:
        for fn in write_plots(cli.output_dir(a.plots), rows, stats, res_label, ref_label, res):
            print(fn)
    print()
    # ---- what was not compared
    strict_fail = []
    if sset.unmatched:
        print(f"Reference channels NOT compared ({len(sset.unmatched)}): {', '.join(sset.unmatched)}")
        if not a.map:
            print("  (not named like a LANDYN channel; give a --map file that maps them)")
        else:
            print("  (not listed in the map)")
        strict_fail += [f"reference channel {c!r} not compared" for c in sset.unmatched]
    not_checked = _not_checked_struts(res, rows, sset.series, crush_ref)
    if not_checked and (rows or sset.series):
        n_all = res.n_struts * res.n_gears
        what = "crush length" if crush_ref else "stroke, force or length history"
        print(f"Struts NOT checked ({len(not_checked)} of {n_all}, no reference {what}): {', '.join(not_checked)}")
        if crush_ref:
            strict_fail += [f"strut {s} not checked" for s in not_checked]
    if checks.unchecked:
        print(f"Compared without a tolerance ({len(checks.unchecked)}): "
              + ", ".join(checks.unchecked[:12]) + (" ..." if len(checks.unchecked) > 12 else ""))
    if sset.unmatched and not a.allow_unmatched:
        checks.failures += [f"reference channel {c!r} not compared (--allow-unmatched lists it instead)"
                            for c in sset.unmatched]
        strict_fail = [f for f in strict_fail if not f.startswith("reference channel")]
    if a.strict:
        checks.failures += [f"--strict: {s}" for s in strict_fail]
    elif strict_fail:
        print("  (--strict makes these a failure)")
    if a.report:
        from .validation_report import write_report
        print(write_report(a.report, res, ref_path, rows, stats, checks, al, td_phase, a,
                           sys.argv[1:] if argv is None else argv))
    if checks.failures:
        for f in checks.failures:
            print("FAILED: " + f)
        print(f"landyn-compare: {len(checks.failures)} check(s) failed, {checks.n_checked} tolerance check(s) ran")
        return cli.EXIT_CHECK_FAILED
    if checks.n_checked == 0:
        why = ("no tolerance was given (--tol-mm, --tol-pct, --tol-rms, --rtol-rms or tol= in the map)"
               if not (a.tol_mm is not None or a.tol_pct is not None or rms_tol.given)
               else "no compared channel had a tolerance")
        print(f"landyn-compare: NOTHING CHECKED: {why}; the deviations above are not a verdict")
        return cli.EXIT_NOTHING_CHECKED
    print(f"landyn-compare: all {checks.n_checked} checks passed"
          + (f" ({len(checks.unchecked)} compared without a tolerance)" if checks.unchecked else ""))
    return cli.EXIT_OK


def main(argv=None) -> int:
    return cli.run("landyn-compare", _main, argv)


if __name__ == "__main__":
    sys.exit(main())
