"""landyn-calibrate: fit deck variables to reference crush lengths or time histories.

Each case is a LANDYN deck and a reference: a per-strut crush-length CSV (Table 3 layout, mm;
with a load case), another LANDYN result (.h5, its crush lengths), or a time-history CSV (with
--map, as landyn-compare --timeseries). The chosen variables (``group%name`` or
``group%name(i)``, bounds LO HI) are fitted by bounded nonlinear least squares
(scipy.optimize.least_squares, trust-region reflective) on variables scaled to [0, 1] by their
bounds. Residuals: crush lengths (LANDYN - reference) / --sigma-mm; a time history's deviation at
the reference samples / (its map tol=, else 1 % of the reference's range), divided by sqrt(n) so
that every channel weighs as its rms.

LANDYN runs in parallel processes (--jobs, default 2), each case of each evaluation in a fresh
directory; the Jacobian is a forward difference with step --diff-step (fraction of each
variable's range), its evaluations run in parallel too. Progress goes to stderr.

The report: the fit (cost, rms residual before and after), the residuals per case, each variable
with its standard error and 95 % confidence interval from the Jacobian at the optimum
(covariance s^2 (J^T J)^-1, s^2 = 2 cost / (m - n)), the correlation matrix, and the singular
values of the scaled Jacobian; a variable whose interval is wider than its bounds, or a pair
correlated beyond 0.95, is reported as not identifiable from these references. The calibrated
decks (each case's resolved input with the fitted values) go to --output-dir; an input file is
never overwritten.

Exit status: 0 fitted; 1 usage error; 2 invalid input; 3 a LANDYN run failed or the fit did not
converge; 4 an output file could not be written.
"""
from __future__ import annotations

import math
import os
import re
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field

import numpy as np

from . import cli
from .namelist import NamelistError, _expand
from .schema import LandynPostError, is_hdf5, load

MM = 1.0e3


class RunFailed(LandynPostError):
    """A LANDYN run of the calibration failed (exit status 3)."""


_VAR = re.compile(r"^\s*([A-Za-z_]\w*)%([A-Za-z_]\w*)(?:\((\d+|:)\))?\s*$")


@dataclass
class Variable:
    group: str
    name: str
    index: int | None        # 1-based element, None: every element
    lo: float
    hi: float
    x0: float = math.nan

    @property
    def label(self) -> str:
        return f"{self.group}%{self.name}" + (f"({self.index})" if self.index else "")


def parse_variable(text: str, lo: str, hi: str) -> Variable:
    m = _VAR.match(text)
    if not m:
        raise cli.LandynUsageError(f"--param {text!r}: expected group%name or group%name(i), e.g. "
                                   "primary_strut%inner_mass or primary_strut%stage_force(1)")
    try:
        lo_v, hi_v = float(lo), float(hi)
    except ValueError:
        raise cli.LandynUsageError(f"--param {text}: bounds {lo!r} {hi!r} are not numbers") from None
    if not (math.isfinite(lo_v) and math.isfinite(hi_v) and lo_v < hi_v):
        raise cli.LandynUsageError(f"--param {text}: needs LO < HI (got {lo} {hi})")
    idx = m.group(3)
    return Variable(m.group(1).lower(), m.group(2).lower(), int(idx) if idx and idx != ":" else None, lo_v, hi_v)


def _format(v) -> str:
    if isinstance(v, bool):
        return ".true." if v else ".false."
    if isinstance(v, str):
        return "'" + v.replace("'", "''") + "'"
    return repr(float(v)) if isinstance(v, float) else str(v)


def _find_line(lines: list[str], group: str, name: str) -> int:
    """Index of the line `name = ...` (no subscript) inside `&group` ... `/`."""
    inside = False
    for i, ln in enumerate(lines):
        s = ln.strip()
        if s.lower().startswith("&"):
            inside = s[1:].split()[0].lower() == group if s[1:].split() else False
        elif s == "/":
            inside = False
        elif inside and re.match(rf"^{name}\s*=", s, re.I):
            return i
    raise LandynPostError(f"the resolved input has no plain assignment of {group}%{name} "
                          "(array sections such as point_a(:, 1) cannot be calibrated)")


def set_value(text: str, var: Variable, value: float) -> str:
    """The deck text with `var` set to `value` (one element, or every element)."""
    lines = text.splitlines()
    i = _find_line(lines, var.group, var.name)
    head, rest = lines[i].split("=", 1)
    body, comment = rest, ""
    k = _comment_at(rest)
    if k is not None:
        body, comment = rest[:k], "  " + rest[k:]
    try:
        vals = _expand(body)
    except NamelistError as exc:
        raise LandynPostError(f"{var.label}: {exc}") from None
    if var.index is None:
        vals = [value] * len(vals)
    elif not 1 <= var.index <= len(vals):
        raise LandynPostError(f"{var.label}: index outside 1..{len(vals)}")
    else:
        vals[var.index - 1] = value
    lines[i] = f"{head.rstrip()} = {', '.join(_format(v) for v in vals)}{comment}"
    return "\n".join(lines) + "\n"


def get_value(text: str, var: Variable) -> float:
    lines = text.splitlines()
    rest = lines[_find_line(lines, var.group, var.name)].split("=", 1)[1]
    k = _comment_at(rest)
    vals = _expand(rest[:k] if k is not None else rest)
    v = vals[(var.index or 1) - 1] if (var.index or 1) <= len(vals) else None
    if not isinstance(v, (int, float)) or isinstance(v, bool):
        raise LandynPostError(f"{var.label}: not a number in the deck ({v!r})")
    return float(v)


def _comment_at(text: str) -> int | None:
    quote = None
    for i, ch in enumerate(text):
        if quote:
            quote = None if ch == quote else quote
        elif ch in "'\"":
            quote = ch
        elif ch == "!":
            return i
    return None


# ------------------------------------------------------------------------------ cases and residuals

@dataclass
class Case:
    deck: str
    reference: str
    load_case: str | None
    resolved: str = ""
    kind: str = "crush"              # crush | h5 | timeseries
    ref_mm: dict[int, float] = field(default_factory=dict)    # measure -> crush length [mm]
    labels: list[str] = field(default_factory=list)


def resolve_deck(exe: str, deck: str, overrides: list[tuple[Variable, float]]) -> str:
    """`landyn DECK --check`: the fully resolved input, with the fixed overrides applied."""
    p = subprocess.run([exe, deck, "--check", "--quiet"], capture_output=True, text=True)
    if p.returncode != 0:
        raise LandynPostError(f"{deck}: landyn --check failed (exit {p.returncode}): "
                              f"{(p.stderr or p.stdout).strip().splitlines()[-1:]}")
    text = p.stdout
    if "&simulation" not in text:
        raise LandynPostError(f"{deck}: landyn --check printed no resolved input")
    for var, v in overrides:
        text = set_value(text, var, v)
    return text


def load_reference(case: Case, column: str | None, timeseries: bool) -> None:
    from .compare import is_mat, read_strut_csv
    if is_hdf5(case.reference):
        ref = load(case.reference)
        case.kind = "h5"
        case.ref_mm = {g * ref.n_struts + k + 1: float(ref.crush_length[g, k]) * MM
                       for g in range(ref.n_gears) for k in range(ref.n_struts)}
    elif timeseries or is_mat(case.reference):
        case.kind = "timeseries"
    else:
        sref = read_strut_csv(case.reference, 99, case.load_case, column)    # gears checked against the result
        case.ref_mm = {m: v * MM for m, v in sref.values.items()}


def residuals_of(case: Case, result_path: str, sigma_mm: float, map_path: str | None) -> tuple[np.ndarray, list[str]]:
    """Scaled residuals of one case's result, and their labels."""
    res = load(result_path)
    if case.kind != "timeseries":
        out, labels = [], []
        for m in sorted(case.ref_mm):
            g, k = divmod(m - 1, res.n_struts)
            if g >= res.n_gears:
                raise LandynPostError(f"{case.reference}: measure {m} but the result has {res.n_gears} gears")
            out.append((float(res.crush_length[g, k]) * MM - case.ref_mm[m]) / sigma_mm)
            labels.append(f"No. {m}")
        return np.array(out), labels
    from .compare import read_timeseries_csv
    sset = read_timeseries_csv(case.reference, res, map_path, None, 1.0)
    out, labels = [], []
    for s in sset.series:
        ok = (s.t_ref >= s.t[0]) & (s.t_ref <= s.t[-1])
        d = np.interp(s.t_ref[ok], s.t, s.y) - s.y_ref[ok]
        scale = s.tol if s.tol else 0.01 * float(np.ptp(s.y_ref)) or 1.0
        out.append(d / scale / math.sqrt(max(len(d), 1)))
        labels += [s.label.split(" -> ")[0]] * len(d)
    return np.concatenate(out), labels


# ------------------------------------------------------------------------------ running LANDYN

class Runner:
    """Runs every case for parameter vectors, `jobs` LANDYN processes at a time; caches by x."""

    def __init__(self, exe: str, cases: list[Case], variables: list[Variable], workdir: str, jobs: int,
                 sigma_mm: float, map_path: str | None, quiet: bool):
        self.exe, self.cases, self.vars, self.workdir = exe, cases, variables, workdir
        self.jobs, self.sigma_mm, self.map_path, self.quiet = jobs, sigma_mm, map_path, quiet
        self.cache: dict[tuple, np.ndarray] = {}
        self.n_runs = 0
        self.n_eval = 0

    def deck_text(self, case: Case, x: np.ndarray) -> str:
        text = case.resolved
        for var, v in zip(self.vars, x):
            text = set_value(text, var, float(v))
        return text

    def _run_case(self, key: int, case_no: int, x: np.ndarray) -> np.ndarray:
        case = self.cases[case_no]
        d = os.path.join(self.workdir, f"eval{key:04d}_case{case_no + 1}")
        os.makedirs(d, exist_ok=True)
        deck = os.path.join(d, "deck.nml")
        with open(deck, "w", encoding="utf-8") as fh:
            fh.write(self.deck_text(case, x))
        out = os.path.join(d, "result.h5")
        p = subprocess.run([self.exe, deck, "-o", out, "--quiet"], capture_output=True, text=True, cwd=d)
        if p.returncode != 0:
            raise RunFailed(f"LANDYN failed (exit {p.returncode}) for case {case_no + 1} ({case.deck}) at "
                                  + ", ".join(f"{v.label} = {xv:.6g}" for v, xv in zip(self.vars, x))
                                  + f": {(p.stderr or p.stdout).strip().splitlines()[-1:]}")
        r, case.labels = residuals_of(case, out, self.sigma_mm, self.map_path)
        for fn in os.listdir(d):
            os.remove(os.path.join(d, fn))
        os.rmdir(d)
        return r

    def evaluate(self, xs: list[np.ndarray], what: str) -> list[np.ndarray]:
        """Residual vectors for several parameter vectors, every case of each in parallel."""
        todo = [x for x in xs if tuple(x) not in self.cache]
        tasks = []
        for x in todo:
            self.n_eval += 1
            tasks += [(self.n_eval, c, x) for c in range(len(self.cases))]
        if tasks:
            with ThreadPoolExecutor(max_workers=self.jobs) as pool:
                parts = list(pool.map(lambda t: self._run_case(*t), tasks))
            self.n_runs += len(tasks)
            nc = len(self.cases)
            for i, x in enumerate(todo):
                self.cache[tuple(x)] = np.concatenate(parts[i * nc:(i + 1) * nc])
        out = [self.cache[tuple(x)] for x in xs]
        if not self.quiet and tasks:
            r = out[0]
            print(f"landyn-calibrate: {what}: {len(tasks)} runs ({self.n_runs} so far); "
                  + ", ".join(f"{v.label} = {xv:.6g}" for v, xv in zip(self.vars, xs[0]))
                  + f"; rms residual {math.sqrt(np.mean(r * r)):.4g}", file=sys.stderr, flush=True)
        return out


# ------------------------------------------------------------------------------ the fit

@dataclass
class Fit:
    x: np.ndarray
    x0: np.ndarray
    r0: np.ndarray
    r: np.ndarray
    jac: np.ndarray             # d r / d x (physical units)
    se: np.ndarray              # standard errors
    corr: np.ndarray
    sv: np.ndarray              # singular values of the Jacobian scaled by the bounds
    status: str
    success: bool
    n_runs: int
    notes: list[str] = field(default_factory=list)


def fit(runner: Runner, x0: np.ndarray, diff_step: float, max_evals: int) -> Fit:
    """Bounded least squares on u = (x - lo) / (hi - lo) with a parallel forward-difference Jacobian."""
    from scipy.optimize import least_squares
    lo = np.array([v.lo for v in runner.vars])
    hi = np.array([v.hi for v in runner.vars])
    span = hi - lo

    def to_x(u):
        return lo + np.asarray(u, float) * span

    def fun(u):
        return runner.evaluate([to_x(u)], "evaluation")[0]

    def jac(u, *_):
        u = np.asarray(u, float)
        steps = [diff_step if u[i] + diff_step <= 1.0 else -diff_step for i in range(len(u))]
        pts = [u] + [u + steps[i] * np.eye(len(u))[i] for i in range(len(u))]
        rs = runner.evaluate([to_x(p) for p in pts], "Jacobian")
        return np.stack([(rs[i + 1] - rs[0]) / steps[i] for i in range(len(u))], axis=1)

    u0 = (x0 - lo) / span
    r0 = fun(u0)
    sol = least_squares(fun, u0, jac=jac, bounds=(0.0, 1.0), method="trf", x_scale=1.0, max_nfev=max_evals,
                        xtol=1e-6, ftol=1e-8)
    x = to_x(sol.x)
    r = fun(sol.x)
    ju = jac(sol.x)
    return _statistics(runner, x0, x, r0, r, ju, span, sol)


def _statistics(runner, x0, x, r0, r, ju, span, sol) -> Fit:
    m, n = ju.shape
    notes = []
    _, sv, vt = np.linalg.svd(ju, full_matrices=False)
    dof = m - n
    s2 = float(r @ r) / dof if dof > 0 else math.nan
    if dof <= 0:
        notes.append(f"{m} residuals for {n} variables: no degrees of freedom left, no confidence intervals")
    # covariance s^2 (J^T J)^-1 = s^2 V diag(1/sv^2) V^T; a direction with a (numerically) zero singular
    # value has infinite variance, and so has every variable with a share in it
    with np.errstate(divide="ignore", invalid="ignore"):
        inv = np.where(sv > 1e-10 * max(sv[0], 1e-300), 1.0 / sv ** 2, math.inf)
        v = vt.T
        share = v ** 2 * inv
        var_u = s2 * np.where(v ** 2 > 1e-12, share, 0.0).sum(axis=1)
        finite = np.isfinite(inv)
        cov_u = s2 * (v[:, finite] * inv[finite]) @ v[:, finite].T
        d = np.sqrt(np.abs(np.diag(cov_u)))
        corr = cov_u / np.outer(d, d)
    se = np.sqrt(np.abs(var_u)) * span
    if not np.isfinite(sv[-1]) or sv[-1] <= 1e-12 * max(sv[0], 1e-300):
        notes.append("the Jacobian is singular: some combination of the variables does not change the residuals")
    for i, v in enumerate(runner.vars):
        if not np.isfinite(se[i]) or 2 * 1.96 * se[i] > v.hi - v.lo:
            notes.append(f"{v.label}: NOT identifiable from these references (95 % interval wider than its bounds)")
        if abs(sol.x[i]) < 1e-9 or abs(sol.x[i] - 1) < 1e-9:
            notes.append(f"{v.label}: at its bound {x[i]:.6g}: the optimum may lie outside the bounds")
    for i in range(n):
        for j in range(i + 1, n):
            if np.isfinite(corr[i, j]) and abs(corr[i, j]) > 0.95:
                notes.append(f"{runner.vars[i].label} and {runner.vars[j].label} correlated {corr[i, j]:+.3f}: "
                             "only a combination of them is identifiable")
    return Fit(x, x0, r0, r, ju / span, se, corr, sv, sol.message, bool(sol.success), runner.n_runs, notes)


def report(f: Fit, runner: Runner, sigma_mm: float) -> str:
    """The fit as text: variables with confidence intervals, correlations, residuals per case."""
    vs = runner.vars
    lines = ["Calibration (scipy.optimize.least_squares, trust-region reflective, variables scaled to their bounds)",
             f"  status: {f.status} ({'converged' if f.success else 'NOT converged'}); {f.n_runs} LANDYN runs",
             f"  rms residual: start {math.sqrt(np.mean(f.r0 ** 2)):.4g}, fitted {math.sqrt(np.mean(f.r ** 2)):.4g}"
             + (f" (crush lengths: x {sigma_mm:g} mm)" if any(c.kind != 'timeseries' for c in runner.cases) else ""),
             "", f"{'variable':<32}{'start':>12}{'fitted':>12}{'std err':>11}{'95 % interval':>27}{'bounds':>22}"]
    for i, v in enumerate(vs):
        ci = (f"{f.x[i] - 1.96 * f.se[i]:.5g} .. {f.x[i] + 1.96 * f.se[i]:.5g}" if np.isfinite(f.se[i]) else "-")
        lines.append(f"{v.label:<32}{f.x0[i]:12.6g}{f.x[i]:12.6g}{f.se[i]:11.3g}{ci:>27}"
                     f"{f'{v.lo:g} .. {v.hi:g}':>22}")
    if len(vs) > 1:
        lines += ["", "correlation of the estimates:"]
        for i, v in enumerate(vs):
            lines.append(f"  {v.label:<32}" + "".join(f"{c:+8.3f}" for c in f.corr[i]))
    lines += ["", "singular values of the Jacobian (variables scaled to their bounds): "
              + ", ".join(f"{s:.4g}" for s in f.sv)]
    lines += ["", "identifiability: " + ("every variable identifiable from these references" if not f.notes
                                         else "")] + [f"  {n}" for n in f.notes]
    lines += ["", "residuals per case (LANDYN - reference; crush lengths in mm):"]
    k = 0
    for c in runner.cases:
        n = len(c.labels)
        rr, r0 = f.r[k:k + n], f.r0[k:k + n]
        unit = sigma_mm if c.kind != "timeseries" else 1.0
        lines.append(f"  {c.deck} vs {os.path.basename(c.reference)}" + (f" {c.load_case}" if c.load_case else "")
                     + f": rms start {math.sqrt(np.mean(r0 ** 2)) * unit:.3g}, fitted "
                     f"{math.sqrt(np.mean(rr ** 2)) * unit:.3g}")
        if c.kind != "timeseries":
            lines.append("    " + "  ".join(f"{lab} {v * unit:+.1f}" for lab, v in zip(c.labels, rr)))
        k += n
    return "\n".join(lines)


def write_decks(runner: Runner, x: np.ndarray, outdir: str, inputs: list[str]) -> list[str]:
    """Each case's resolved input with the fitted values, as <outdir>/<deck stem>_calibrated.nml."""
    written = []
    cli.output_dir(outdir)
    for c in runner.cases:
        path = os.path.join(outdir, cli.stem(c.deck) + "_calibrated.nml")
        cli.refuse_overwrite(path, inputs)
        head = ("! LANDYN deck calibrated by landyn-calibrate from " + c.deck + "\n! fitted: "
                + ", ".join(f"{v.label} = {xv:.8g}" for v, xv in zip(runner.vars, x)) + "\n")
        with cli.atomic_output(path) as fh:
            fh.write(head + runner.deck_text(c, x))
        written.append(path)
    return written


def _find_exe(given: str | None) -> str:
    import glob
    import shutil
    if given:
        if not (os.path.isfile(given) and os.access(given, os.X_OK)):
            raise LandynPostError(f"--landyn {given}: not an executable file")
        return given
    env = os.environ.get("LANDYN_EXE")
    if env and os.path.isfile(env):
        return env
    here = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    cands = sorted(glob.glob(os.path.join(here, "build", "release", "landyn")) + ([shutil.which("landyn")]
                                                                                  if shutil.which("landyn") else []))
    if not cands:
        raise LandynPostError("landyn executable not found: give --landyn PATH or set LANDYN_EXE")
    return cands[0]


def _parser():
    p = cli.make_parser(
        "landyn-calibrate",
        "Fit LANDYN deck variables to reference crush lengths (Table 3 layout CSV, or a LANDYN .h5) or\n"
        "time histories (--timeseries with --map) by bounded least squares, with confidence intervals\n"
        "and correlations from the Jacobian; writes the calibrated decks.",
        epilog="examples:\n"
               "  landyn-calibrate --case input/lc3.nml post/landyn_post/data/table3_crush_lengths.csv LC-3 \\\n"
               "      --column theory --param primary_strut%inner_mass 5 60 --output-dir calibrated\n\n"
               "exit status: 0 fitted; 1 usage error; 2 invalid input; 3 a LANDYN run failed or the fit did not\n"
               "  converge; 4 an output file could not be written.")
    p.add_argument("--case", nargs="+", action="append", required=True, metavar="ARG",
                   help="DECK REFERENCE [LOAD_CASE]: a deck and its reference (repeat for several cases)")
    p.add_argument("--param", nargs=3, action="append", required=True, metavar=("NAME", "LO", "HI"),
                   help="a variable to fit, group%%name or group%%name(i), with its bounds")
    p.add_argument("--set", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"),
                   help="a fixed value for every case, e.g. --set simulation%%t_end 0.3")
    p.add_argument("--column", metavar="NAME", help="value column of crush-length CSVs, e.g. theory")
    p.add_argument("--timeseries", action="store_true", help="the CSV references are time histories (needs --map)")
    p.add_argument("--map", metavar="MAPFILE", help="channel map of the time-history references")
    p.add_argument("--sigma-mm", type=float, default=1.0, metavar="MM",
                   help="crush-length residual scale [mm] (default 1): residual = deviation / sigma")
    p.add_argument("--diff-step", type=float, default=0.02, metavar="F",
                   help="Jacobian step, fraction of each variable's range (default 0.02)")
    p.add_argument("--max-evals", type=int, default=30, metavar="N", help="most function evaluations (default 30)")
    p.add_argument("--jobs", type=int, default=2, metavar="N", help="LANDYN processes at a time (default 2)")
    p.add_argument("--landyn", metavar="EXE", help="the landyn executable (default: $LANDYN_EXE, build/release)")
    p.add_argument("--output-dir", metavar="DIR", help="write <deck>_calibrated.nml for every case to DIR")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress on stderr")
    return p


def _cases(a, p, exe: str, fixed) -> list[Case]:
    cases = []
    for items in a.case:
        if len(items) not in (2, 3):
            p.error(f"--case {' '.join(items)}: expected DECK REFERENCE [LOAD_CASE]")
        for f in items[:2]:
            if not os.path.isfile(f):
                raise LandynPostError(f"{f}: no such file")
        c = Case(items[0], items[1], items[2] if len(items) == 3 else None)
        load_reference(c, a.column, a.timeseries)
        c.resolved = resolve_deck(exe, c.deck, fixed)
        cases.append(c)
    return cases


def _main(argv=None) -> int:
    p = _parser()
    a = p.parse_args(argv)
    if a.jobs < 1 or not 0 < a.diff_step < 0.5 or a.max_evals < 1 or not a.sigma_mm > 0:
        p.error("--jobs >= 1, 0 < --diff-step < 0.5, --max-evals >= 1 and --sigma-mm > 0 are required")
    if a.timeseries and not a.map:
        p.error("--timeseries needs --map")
    variables = [parse_variable(*t) for t in a.param]
    if len({v.label for v in variables}) != len(variables):
        p.error("a variable is given twice in --param")
    fixed = []
    for name, value in a.set:
        v = parse_variable(name, "0", "1")
        try:
            fixed.append((v, float(value)))
        except ValueError:
            p.error(f"--set {name} {value}: not a number")
    exe = _find_exe(a.landyn)
    cases = _cases(a, p, exe, fixed)
    x0 = np.array([get_value(cases[0].resolved, v) for v in variables])
    for v, x in zip(variables, x0):
        if not v.lo <= x <= v.hi:
            raise cli.LandynUsageError(f"{v.label}: the deck's value {x:g} is outside the bounds {v.lo:g} .. {v.hi:g}")
    inputs = [c.deck for c in cases] + [c.reference for c in cases] + ([a.map] if a.map else [])
    with tempfile.TemporaryDirectory(prefix="landyn_calibrate_") as work:
        runner = Runner(exe, cases, variables, work, a.jobs, a.sigma_mm, a.map, a.quiet)
        try:
            f = fit(runner, x0, a.diff_step, a.max_evals)
        except RunFailed as exc:
            print(f"landyn-calibrate: error: {exc}", file=sys.stderr)
            return cli.EXIT_CHECK_FAILED
    print(report(f, runner, a.sigma_mm))
    if a.output_dir:
        for fn in write_decks(runner, f.x, a.output_dir, inputs):
            print(fn)
    if not f.success:
        print("landyn-calibrate: the fit did NOT converge; the decks hold the last iterate")
        return cli.EXIT_CHECK_FAILED
    return cli.EXIT_OK


def main(argv=None) -> int:
    return cli.run("landyn-calibrate", _main, argv)


if __name__ == "__main__":
    sys.exit(main())
