#!/usr/bin/env python3
"""Accuracy against cost of the time integrators ('fixed', 'adaptive' and 'imex'), issues 9 and 22.

  integrator_study.py --exe build/release/landyn --src . [--cases 30] [--seed 9]
                      [--tolerances 1e-5,1e-6,1e-7] [--imex-tolerances 1e-5,1e-6,1e-7]
                      [--fixed-dts 8e-5,4e-5,2e-5,1e-5,5e-6]
                      [--adaptive-extra 'event_resolution = 5e-6'] [--jobs 2] [--cache DIR] [--csv OUT.csv] [--plot OUT.png]

Cases: the paper's load cases input/lc1.nml .. lc4.nml, decks A and B of impact_study.py and
its seeded dispersion of `--cases` landings (vertical 2-5 m/s, horizontal 0-1.5 m/s in any
direction, yaw 0-90 deg, pitch/roll +-5 deg, slope 0-10 deg at any azimuth; 1 s each).

For every case the reference is the fixed scheme at dt = 1.25e-6 s (`--dt-ref`); its results
are cached in `--cache DIR` (default: a temporary directory, i.e. no reuse), keyed by the deck
text, so a rerun against a changed adaptive integrator does not repeat them. Then every case
runs with the fixed scheme at each of `--fixed-dts` and with the adaptive scheme at each of
`--tolerances` (m/s; the deck's dt is only the first step tried), and with the linearly implicit
'imex' scheme at each of `--imex-tolerances` (none when empty). All runs are made in one
invocation, `--jobs` at a time, the two schemes interleaved within each case so that machine
noise affects both alike.

Per run: the largest |crush_length - reference| over all struts [mm], the energy residual [%],
the largest mode_switches of a strut, the accepted steps (/summary/n_steps), the force evaluations
(/summary/integrator/n_evaluations: rejected steps and event retries included), the wall time of
the whole process and of the time loop (/summary/wall_time).

Prints (1) a per-case table for LC-1..4, A and B, (2) a summary per scheme setting: over
LC-1..4 the largest crush error and the mean loop time; over the dispersion the largest crush
error, the number of cases above 0.1 mm, the largest |energy residual|, the mean steps and the
mean wall times. `--plot` draws error against cost (mean force evaluations and mean loop time per
1 s run, log-log), one line per scheme, separate markers for LC-1..4 and for the dispersion.
`--csv` writes one row per run. Exit status 0; this is a study, not a test.
"""
import argparse
import concurrent.futures as cf
import csv
import hashlib
import json
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy as np
import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from impact_study import DECK_A, DECK_B, dispersion  # noqa: E402

THRESHOLD_MM = 0.1          # dispersion cases above this crush error are counted
PLOT_FLOOR_MM = 1e-6        # zero errors drawn at this value on the log axis


ERROR_CONTROLLED = ("adaptive", "imex")   # schemes set by a tolerance, not a step


def settings_text(scheme, value, extra=""):
    if scheme in ERROR_CONTROLLED:
        return "integrator = '%s', tolerance = %.6e" % (scheme, value) + (", " + extra if extra else "")
    return "integrator = 'fixed', dt = %.6e" % value


def make_deck(text, scheme, value, extra=""):
    """The deck with its &simulation group set to `scheme` at `value` (dt or tolerance).

    A `dt = ...` assignment in &simulation is replaced by the settings (so the fixed step is
    never stated twice); otherwise the settings are put right after `&simulation`. For the
    adaptive scheme the deck's own dt (the first step tried) is kept."""
    m = re.search(r"^[ \t]*&simulation\b(.*?)(^\s*/|/\s*$|\s/)", text, re.S | re.M | re.I)
    if m is None:
        raise ValueError("deck has no &simulation group")
    body = m.group(1)
    dt_re = re.compile(r"(?<![\w%])dt\s*=\s*[-+0-9.eEdD]+", re.I)
    new = settings_text(scheme, value, extra)
    if scheme == "fixed" and dt_re.search(body):
        body = dt_re.sub(new, body, count=1)
    elif scheme in ERROR_CONTROLLED and dt_re.search(body):
        body = dt_re.sub(lambda mm: mm.group(0) + ", " + new, body, count=1)
    else:
        body = " " + new + "," + body if body.strip() else " " + new + body
    return text[:m.start(1)] + body + text[m.end(1):]


def read_result(out):
    with h5py.File(out, "r") as h:
        s = h["summary"]
        return dict(crush=np.asarray(s["crush_length"][()], dtype=float),
                    residual=float(s["energy_residual"][()]),
                    switches=int(np.max(s["mode_switches"][()])),
                    steps=int(s["n_steps"][()]),
                    evals=int(s["integrator/n_evaluations"][()]),
                    loop=float(s["wall_time"][()]),
                    t_final=float(s["final_time"][()]) if "final_time" in s else float("nan"))


def run(exe, workdir, tag, deck):
    """One landing; returns (result dict or None, process wall [s], error text)."""
    path = os.path.join(workdir, tag + ".nml")
    with open(path, "w") as f:
        f.write(deck)
    out = path[:-4] + ".h5"
    t0 = time.perf_counter()
    p = subprocess.run([exe, path, "-q", "-o", out], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0 or not os.path.exists(out):
        return None, wall, ("exit %d: " % p.returncode) + (p.stdout[-300:] + p.stderr[-300:]).strip()
    try:
        r = read_result(out)
    except (OSError, KeyError) as e:
        return None, wall, "unreadable result: %s" % e
    finally:
        os.remove(out)
        os.remove(path)
    r["proc"] = wall
    r["crush"] = r["crush"].tolist()
    return r, wall, ""


def cache_key(deck):
    return hashlib.sha1(deck.encode()).hexdigest()[:16]


def run_reference(exe, workdir, cache, name, deck):
    key = os.path.join(cache, "ref_%s_%s.json" % (name, cache_key(deck)))
    if os.path.exists(key):
        with open(key) as f:
            return json.load(f), 0.0, "", True
    r, wall, err = run(exe, workdir, "ref_" + name, deck)
    if r is not None:
        tmp = key + ".tmp%d" % os.getpid()
        with open(tmp, "w") as f:
            json.dump(r, f)
        os.replace(tmp, key)
    return r, wall, err, False


def fmt_setting(scheme, value):
    if scheme == "fixed":
        return "fixed dt=%-8.3g" % value
    return ("adapt tol=%-7.3g" if scheme == "adaptive" else "imex tol=%-8.3g") % value


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", required=True)
    ap.add_argument("--src", required=True)
    ap.add_argument("--cases", type=int, default=30)
    ap.add_argument("--seed", type=int, default=9)
    ap.add_argument("--tolerances", default="1e-5,1e-6,1e-7")
    ap.add_argument("--imex-tolerances", default="1e-5,1e-6,1e-7")
    ap.add_argument("--fixed-dts", default="8e-5,4e-5,2e-5,1e-5,5e-6")
    ap.add_argument("--adaptive-extra", default="",
                    help="further &simulation settings of the adaptive runs, e.g. 'event_resolution = 5e-6'")
    ap.add_argument("--dt-ref", type=float, default=1.25e-6)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--cache", default=None, help="directory for the cached references (default: a temporary one)")
    ap.add_argument("--csv", default=None)
    ap.add_argument("--plot", default=None)
    a = ap.parse_args()
    exe = os.path.abspath(a.exe)
    tols = [float(x) for x in a.tolerances.split(",") if x.strip()]
    itols = [float(x) for x in a.imex_tolerances.split(",") if x.strip()]
    dts = [float(x) for x in a.fixed_dts.split(",") if x.strip()]

    lc = []
    for k in range(1, 5):
        text = open(os.path.join(a.src, "input", "lc%d.nml" % k)).read()
        assert re.search(r"^\s*t_end\s*=\s*1\.0\b", text, re.M), "lc%d.nml must state t_end = 1.0" % k
        lc.append(("LC-%d" % k, text))
    cases = lc + [("A", DECK_A), ("B", DECK_B)] + \
        [("d%02d" % (i + 1), t) for i, t in enumerate(dispersion(a.cases, a.seed))]
    disp_names = [n for n, _ in cases[6:]]
    lc_names = [n for n, _ in cases[:4]]

    # Interleaved settings: fixed coarsest, adaptive loosest, imex loosest, fixed next, ...
    settings = []
    for i in range(max(len(dts), len(tols), len(itols))):
        for scheme, values in (("fixed", dts), ("adaptive", tols), ("imex", itols)):
            if i < len(values):
                settings.append((scheme, values[i]))

    own_tmp = a.cache is None
    cache = a.cache or tempfile.mkdtemp(prefix="landyn_istudy_cache_")
    os.makedirs(cache, exist_ok=True)
    refs, res, cached_refs = {}, {}, set()
    t_start = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="landyn_istudy_") as d, cf.ThreadPoolExecutor(a.jobs) as ex:
        futs = {}
        for name, text in cases:   # references first (the longest runs), then case by case
            futs[ex.submit(run_reference, exe, d, cache, name, make_deck(text, "fixed", a.dt_ref))] = ("ref", name)
        for name, text in cases:
            for k, (scheme, v) in enumerate(settings):
                tag = "%s_%s_%g" % (name, scheme, v)
                futs[ex.submit(run, exe, d, tag, make_deck(text, scheme, v, a.adaptive_extra))] = ((scheme, v), name)
        n_ref_cached = 0
        for f in cf.as_completed(futs):
            what, name = futs[f]
            if what == "ref":
                r, wall, err, cached = f.result()
                n_ref_cached += cached
                if cached:
                    cached_refs.add(name)
                refs[name] = (r, err)
            else:
                r, wall, err = f.result()
                res[(name, what)] = (r, wall, err)
    t_total = time.perf_counter() - t_start
    if own_tmp:
        for fn in os.listdir(cache):
            os.remove(os.path.join(cache, fn))
        os.rmdir(cache)

    # Errors against the reference.
    rows = []
    for name, _ in cases:
        ref, rerr = refs[name]
        for scheme, v in settings:
            r, wall, err = res[(name, (scheme, v))]
            row = dict(case=name, scheme=scheme, value=v, status="ok", err_mm=float("nan"),
                       residual_pct=float("nan"), switches=-1, steps=-1, evals=-1, proc_s=wall, loop_s=float("nan"),
                       t_final=float("nan"))
            if r is None:
                row["status"] = "FAILED " + err.replace("\n", " ")
            else:
                row.update(residual_pct=100 * r["residual"], switches=r["switches"], steps=r["steps"],
                           evals=r["evals"], loop_s=r["loop"], t_final=r["t_final"])
                if ref is None:
                    row["status"] = "no reference: " + rerr.replace("\n", " ")
                else:
                    row["err_mm"] = 1000 * float(np.max(np.abs(np.asarray(r["crush"]) - np.asarray(ref["crush"]))))
                if not (r["t_final"] >= 1.0 - 1e-9):
                    row["status"] = "ended early at t = %.6g s" % r["t_final"]
            rows.append(row)
    by = {(rw["case"], rw["scheme"], rw["value"]): rw for rw in rows}

    print("LANDYN integrator study: %d cases (LC-1..4, A, B, %d dispersion, seed %d), reference fixed dt = %g s "
          "(%d of %d from cache %s), %d runs, %.0f s, %d jobs"
          % (len(cases), a.cases, a.seed, a.dt_ref, n_ref_cached, len(cases), a.cache or "(temporary)",
             len(rows) + len(cases) - n_ref_cached, t_total, a.jobs))
    bad_refs = [(n, refs[n][1]) for n, _ in cases if refs[n][0] is None]
    for n, e in bad_refs:
        print("  reference FAILED for %s: %s" % (n, e))

    # (1) Per-case table.
    print("\n(1) Per case: max over struts |crush - ref| [mm], energy residual [%], most mode switches, "
          "accepted steps, force evaluations, wall [s] (process, loop)")
    hdr = "%-5s %-20s %12s %12s %6s %9s %9s %8s %8s  %s" % ("case", "setting", "|dcrush| mm", "residual %",
                                                            "switch", "steps", "evals", "proc s", "loop s", "status")
    print(hdr)
    print("-" * len(hdr))
    for name in lc_names + ["A", "B"]:
        ref = refs[name][0]
        if ref is not None:
            print("%-5s %-20s %12s %12.4f %6d %9d %9d %8.3f %8.3f  %s"
                  % (name, "ref fixed dt=%g" % a.dt_ref, "-", 100 * ref["residual"], ref["switches"],
                     ref["steps"], ref.get("evals", -1), ref["proc"], ref["loop"], "reference"))
        for scheme, v in settings:
            rw = by[(name, scheme, v)]
            print("%-5s %-20s %12.5f %12.4f %6d %9d %9d %8.3f %8.3f  %s"
                  % (name, fmt_setting(scheme, v), rw["err_mm"], rw["residual_pct"], rw["switches"], rw["steps"],
                     rw["evals"], rw["proc_s"], rw["loop_s"], rw["status"] if rw["status"] != "ok" else ""))
        print()

    # (2) Summary per scheme setting.
    def agg(names, scheme, v):
        rr = [by[(n, scheme, v)] for n in names]
        ok = [r for r in rr if r["status"] == "ok"]
        e = np.array([r["err_mm"] for r in ok]) if ok else np.array([np.nan])
        return dict(n_bad=len(rr) - len(ok),
                    max_err=float(np.nanmax(e)) if ok else float("nan"),
                    n_above=int(np.sum(e > THRESHOLD_MM)) if ok else 0,
                    max_res=max((abs(r["residual_pct"]) for r in ok), default=float("nan")),
                    mean_steps=float(np.mean([r["steps"] for r in ok])) if ok else float("nan"),
                    mean_evals=float(np.mean([r["evals"] for r in ok])) if ok else float("nan"),
                    mean_loop=float(np.mean([r["loop_s"] for r in ok])) if ok else float("nan"),
                    mean_proc=float(np.mean([r["proc_s"] for r in ok])) if ok else float("nan"),
                    max_sw=max((r["switches"] for r in ok), default=-1))

    print("(2) Summary per setting. LC = LC-1..4; disp = the %d dispersion cases; errors in mm against fixed dt = %g s"
          % (len(disp_names), a.dt_ref))
    hdr = ("%-20s | %10s %9s %9s | %10s %6s %9s %7s %9s %8s %8s %5s"
           % ("setting", "LC maxerr", "LC evals", "LC loop", "disp maxerr", ">%.1fmm" % THRESHOLD_MM, "max|res|%",
              "max sw", "mean ev", "loop s", "proc s", "fail"))
    print(hdr)
    print("-" * len(hdr))
    summary = []
    for scheme in ("fixed", "adaptive", "imex"):
        for scheme2, v in settings:
            if scheme2 != scheme:
                continue
            L, D = agg(lc_names, scheme, v), agg(disp_names, scheme, v)
            summary.append((scheme, v, L, D))
            print("%-20s | %10.5f %9.0f %9.4f | %11.5f %6d %9.4f %7d %9.0f %8.4f %8.4f %5d"
                  % (fmt_setting(scheme, v), L["max_err"], L["mean_evals"], L["mean_loop"], D["max_err"], D["n_above"],
                     D["max_res"], D["max_sw"], D["mean_evals"], D["mean_loop"], D["mean_proc"],
                     L["n_bad"] + D["n_bad"]))
    ref_ok = [refs[n][0] for n in disp_names if refs[n][0] is not None]
    ref_lc = [refs[n][0] for n in lc_names if refs[n][0] is not None]
    if ref_ok and ref_lc:   # timings of cached references are those of the run that made them
        print("%-20s | %10s %9.0f %9.4f | %11s %6s %9.4f %7d %9.0f %8.4f %8.4f%s"
              % ("ref fixed dt=%g" % a.dt_ref, "-", np.mean([r.get("evals", r["steps"]) for r in ref_lc]),
                 np.mean([r["loop"] for r in ref_lc]), "-", "-", max(abs(100 * r["residual"]) for r in ref_ok),
                 max(r["switches"] for r in ref_ok), np.mean([r.get("evals", r["steps"]) for r in ref_ok]),
                 np.mean([r["loop"] for r in ref_ok]), np.mean([r["proc"] for r in ref_ok]),
                 "  (cached)" if n_ref_cached else ""))
    # A and B worst case, for completeness
    ab = ", ".join("%s %.4f" % (fmt_setting(s, v).strip(), agg(["A", "B"], s, v)["max_err"]) for s, v in settings)
    print("decks A, B max |dcrush| mm: " + ab)

    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["case", "scheme", "setting", "max_abs_dcrush_mm", "energy_residual_pct", "max_mode_switches",
                        "n_steps", "n_evaluations", "wall_process_s", "wall_loop_s", "t_final", "status"])
            for name, _ in cases:
                ref = refs[name][0]
                if ref is not None:
                    w.writerow([name, "reference", "%g" % a.dt_ref, 0.0, "%.6g" % (100 * ref["residual"]),
                                ref["switches"], ref["steps"], ref.get("evals", ref["steps"]), "%.4f" % ref["proc"],
                                "%.4f" % ref["loop"],
                                "%.6g" % ref["t_final"], "reference (cached)" if name in cached_refs else "reference"])
                for scheme, v in settings:
                    rw = by[(name, scheme, v)]
                    w.writerow([name, scheme, "%g" % v, "%.6g" % rw["err_mm"], "%.6g" % rw["residual_pct"],
                                rw["switches"], rw["steps"], rw["evals"], "%.4f" % rw["proc_s"], "%.4f" % rw["loop_s"],
                                "%.6g" % rw["t_final"], rw["status"]])
        print("CSV: %s" % a.csv)

    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, 2, figsize=(12, 5))
        from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter
        colors = {"fixed": "tab:blue", "adaptive": "tab:red", "imex": "tab:green"}
        # label offsets per scheme [points], so that the labels of nearby points do not overlap
        offsets = {"fixed": (-14, 7), "adaptive": (6, -3), "imex": (2, -13)}
        for ax, xkey, xlabel in ((axes[0], "mean_evals", "mean force evaluations per 1 s run"),
                                 (axes[1], "mean_loop", "mean time-loop wall time per 1 s run [s]")):
            for scheme in ("fixed", "adaptive", "imex"):
                pts = [(v, L, D) for s, v, L, D in summary if s == scheme]
                if not pts:
                    continue
                for which, marker, ls, lab in ((1, "s", "-", "LC-1..4"), (2, "o", "--", "dispersion (%d)" % len(disp_names))):
                    xs = [p[which][xkey] for p in pts]
                    ys = [max(p[which]["max_err"], PLOT_FLOOR_MM) for p in pts]
                    ax.loglog(xs, ys, marker=marker, ls=ls, color=colors[scheme], label="%s, %s" % (scheme, lab))
                    if which == 2:
                        for (v, _, _), x, y in zip(pts, xs, ys):
                            ax.annotate("%g" % v, (x, y), textcoords="offset points", xytext=offsets[scheme],
                                        fontsize=7, color=colors[scheme])
            ax.axhline(THRESHOLD_MM, color="grey", lw=0.8, ls=":")
            ax.set_xlabel(xlabel)
            ax.set_ylabel("max |crush length - reference| [mm]")
            ax.grid(True, which="both", alpha=0.3)
            # ticks at 1, 2, 5 x 10^k as plain numbers: the default minor labels of a short log axis collide
            ax.xaxis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
            ax.xaxis.set_major_formatter(FuncFormatter(lambda x, _: "%g" % x))
            ax.xaxis.set_minor_formatter(NullFormatter())
        axes[0].legend(fontsize=8)
        fig.suptitle("LANDYN integrators: error vs cost (reference: fixed dt = %g s; labels on the dispersion points: "
                     "dt [s] or tolerance [m/s])" % a.dt_ref, fontsize=10)
        fig.tight_layout()
        fig.savefig(a.plot, dpi=120)
        print("plot: %s" % a.plot)
    return 0


if __name__ == "__main__":
    sys.exit(main())
