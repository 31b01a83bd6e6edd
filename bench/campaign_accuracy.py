#!/usr/bin/env python3
"""Campaign accuracy against cost (issue "Integrators that own the time step").

Runs cases 1..N of the campaign example examples/campaign/dispersion.nml (2 s per case) on one
rank (`landyn_batch DECK --case 1:N`) with each scheme to compare, the schemes interleaved round by
round (the machine is noisy: every scheme sees the same load), and a converged reference: the
fixed scheme at --ref-dt (default 1.25e-6 s), checked against the same scheme at half that step on
the first --check-cases cases. For each scheme it prints cases per core-hour (cases * 3600 / wall
time of the best round, one rank), the largest crush-length error over all struts and cases, the
share of cases within 0.1 mm in every crush length and the number beyond 0.5 mm, the mean
number of steps per case (the energy residuals are bench/integrator_study.py's: campaign rows do
not store them), and the largest difference of the crush lengths' 5/50/95 % quantiles over the
cases from the reference's (what a Monte Carlo campaign reports).

  campaign_accuracy.py --batch build/release/landyn_batch --src . [--cases 200] [--rounds 2]
                       [--schemes "fixed:dt=4e-5" "adaptive" "adaptive:tolerance=1e-6"]
                       [--ref-dt 1.25e-6] [--check-cases 5] [--ref-cache DIR] [--t-end 2]
                       [--per-case] [--energy] [--sensitivity 1e-6 [--sens-dt 5e-6]]

--per-case prints every case's largest crush-length error and steps per scheme; --sensitivity DV
runs every case again with its vertical touchdown velocity changed by +DV and -DV (a case list made
from `landyn_batch --list-cases`, fixed scheme at --sens-dt) and counts the cases whose crush
lengths move by more than 0.1 mm under it: for those the inputs do not decide the crush lengths to
0.1 mm, and the criterion is reported apart over the others. --energy runs
every scheme once more, untimed, with the cases' histories (landyn_batch --history) and prints
each case's energy residual [%] from them.

A scheme is NAME[:var=value,...][@BATCH]: &simulation integrator = NAME with those &simulation
variables, run by the landyn_batch BATCH when given (to compare builds in one interleaved run).
The reference is expensive (about 7 s per case); --ref-cache keeps it between runs (keyed by the
case count, the reference step and the base deck's text).
"""
import argparse
import csv
import hashlib
import io
import os
import re
import shutil
import subprocess
import tempfile
import time

import h5py
import numpy as np


def split_batch(spec, default):
    """The scheme part of a spec and the landyn_batch that runs it."""
    scheme, _, batch = spec.partition("@")
    return scheme, os.path.abspath(batch) if batch else default


def scheme_text(spec):
    name, _, rest = spec.partition(":")
    items = ["integrator = '%s'" % name]
    for kv in filter(None, rest.split(",")):
        k, v = kv.split("=")
        items.append("%s = %s" % (k.strip(), v.strip()))
    return ", ".join(items)


def make_dir(src, workdir, tag, spec, cases, t_end=None):
    """A copy of the campaign example whose base deck runs `spec` (and t_end when given)."""
    d = os.path.join(workdir, tag)
    os.makedirs(d)
    ex = os.path.join(src, "examples", "campaign")
    base = open(os.path.join(ex, "lander.nml")).read()
    # the scheme replaces the deck's integrator, dt and tolerance settings
    base = re.sub(r"(?m)^\s*(integrator|dt|tolerance)\s*=.*$", "", base)
    extra = scheme_text(spec) + ("" if t_end is None else ", t_end = %r" % t_end)
    if t_end is not None:
        base = re.sub(r"(?m)^\s*t_end\s*=.*$", "", base)
    base, n = re.subn(r"(?mi)^&simulation\b", "&simulation " + extra + ",", base)
    assert n == 1, "lander.nml must have one &simulation group"
    open(os.path.join(d, "lander.nml"), "w").write(base)
    deck = open(os.path.join(ex, "dispersion.nml")).read()
    deck = re.sub(r"(?m)^(\s*summary_file\s*=\s*).*$", r"\1'%s.h5'" % tag, deck)
    deck = re.sub(r"(?m)^\s*save_histories\s*=.*$", "", deck)
    open(os.path.join(d, "dispersion.nml"), "w").write(deck)
    return d


def perturb_dir(batch, src, workdir, tag, spec, cases, t_end, dv):
    """A copy of the campaign example as a case list (the Monte Carlo cases 1..cases as
    `landyn_batch --list-cases` lists them) with DV [m/s] added to every case's vertical touchdown
    velocity: the same landings, perturbed far below any measurement of them."""
    d = make_dir(src, workdir, tag, spec, cases, t_end)
    p = subprocess.run([batch, "dispersion.nml", "--list-cases"], cwd=d, capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit("%s: landyn_batch --list-cases exit %d\n%s" % (tag, p.returncode, p.stderr))
    rows = list(csv.reader(io.StringIO(p.stdout)))
    head, rows = rows[0], rows[1:cases + 1]
    col = head.index("initial_state%velocity(3)")
    with open(os.path.join(d, "cases.csv"), "w") as f:
        f.write(",".join(head[1:]) + "\n")   # a case list has no case_id column
        for r in rows:
            r[col] = repr(float(r[col]) + dv)
            f.write(",".join(r[1:]) + "\n")
    deck = open(os.path.join(d, "dispersion.nml")).read()
    deck = re.sub(r"(?ms)^&parameter\b.*?^/\s*$\n?", "", deck)
    deck = re.sub(r"(?m)^\s*(n_samples|seed)\s*=.*$", "", deck)
    deck, n = re.subn(r"(?m)^\s*mode\s*=.*$", "  mode = 'list'\n  list_file = 'cases.csv'", deck)
    assert n == 1, "dispersion.nml must set mode once"
    open(os.path.join(d, "dispersion.nml"), "w").write(deck)
    return d


def run(batch, d, tag, cases):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    out = os.path.join(d, tag + ".h5")
    if os.path.exists(out):
        os.remove(out)
    t0 = time.perf_counter()
    p = subprocess.run([batch, "dispersion.nml", "--case", "1:%d" % cases, "-o", out, "-q"], cwd=d, env=env,
                       capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode not in (0, 5):   # 5: some case failed its criteria (a result, not an error)
        raise SystemExit("%s: landyn_batch exit %d\n%s%s" % (tag, p.returncode, p.stdout, p.stderr))
    with h5py.File(out, "r") as f:
        crush = f["cases/crush_length"][()]
        ids = f["cases/case_id"][()] if "cases/case_id" in f else np.arange(1, crush.shape[0] + 1)
        steps = f["cases/n_steps"][()]
    order = np.argsort(ids)
    return wall, crush[order], steps[order]


def energy_residuals(batch, d, tag, cases):
    """Each case's /summary/energy_residual [%] from a run with the cases' histories."""
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    out = os.path.join(d, tag + "_e.h5")
    p = subprocess.run([batch, "dispersion.nml", "--case", "1:%d" % cases, "--history", "-o", out, "-q"], cwd=d,
                       env=env, capture_output=True, text=True)
    if p.returncode not in (0, 5):
        raise SystemExit("%s: landyn_batch exit %d\n%s%s" % (tag, p.returncode, p.stdout, p.stderr))
    res = []
    for k in range(1, cases + 1):
        with h5py.File(os.path.join(d, "%s_e_case%06d.h5" % (tag, k)), "r") as f:
            res.append(100.0 * float(f["summary/energy_residual"][()]))
    return res


def sensitivity(a, batch, src, w, ref):
    """Each case's largest crush-length change [mm] when its vertical touchdown velocity changes by
    +-a.sensitivity, run with the fixed scheme at a.sens_dt (against the same scheme unperturbed;
    that is the reference when a.sens_dt is --ref-dt). Cached in a.ref_cache."""
    dt = a.sens_dt or a.ref_dt
    key = hashlib.sha1((open(os.path.join(src, "examples/campaign/lander.nml")).read()
                        + open(os.path.join(src, "examples/campaign/dispersion.nml")).read()
                        + "%d %r %r %r" % (a.cases, dt, a.t_end, a.sensitivity)).encode()).hexdigest()[:12]
    cached = os.path.join(a.ref_cache, "sens_%s.npz" % key) if a.ref_cache else None
    if cached and os.path.exists(cached):
        return np.load(cached)["spread"]
    spec = "fixed:dt=%r" % dt
    runs = []
    for k, dv in enumerate((0.0, a.sensitivity, -a.sensitivity)):
        if dv == 0.0 and dt == a.ref_dt:
            runs.append(ref)
            continue
        d = perturb_dir(batch, src, w, "sens%d" % k, spec, a.cases, a.t_end, dv)
        runs.append(run(batch, d, "sens%d" % k, a.cases)[1])
    spread = 1e3 * np.max(np.abs(np.stack(runs[1:]) - runs[0]).reshape(2, a.cases, -1), axis=(0, 2))
    if cached:
        os.makedirs(a.ref_cache, exist_ok=True)
        np.savez(cached, spread=spread)
    return spread


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--batch", required=True, help="landyn_batch executable")
    ap.add_argument("--src", required=True, help="source tree")
    ap.add_argument("--cases", type=int, default=200)
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--schemes", nargs="+", default=["fixed:dt=4e-5", "adaptive"])
    ap.add_argument("--ref-dt", type=float, default=1.25e-6)
    ap.add_argument("--check-cases", type=int, default=5)
    ap.add_argument("--ref-cache", help="folder keeping the reference between runs")
    ap.add_argument("--t-end", type=float, help="simulated time per case [s] (default: the example's)")
    ap.add_argument("--per-case", action="store_true", help="print each case's error and steps")
    ap.add_argument("--energy", action="store_true", help="print each case's energy residual (untimed extra run)")
    ap.add_argument("--sensitivity", type=float, metavar="DV",
                    help="also run every case with its vertical touchdown velocity +-DV [m/s] (e.g. 1e-6)")
    ap.add_argument("--sens-dt", type=float, help="fixed step of the sensitivity runs [s] (default: --ref-dt)")
    a = ap.parse_args()
    batch = os.path.abspath(a.batch)
    src = os.path.abspath(a.src)
    with tempfile.TemporaryDirectory(prefix="landyn_campaign_accuracy_") as w:
        key = hashlib.sha1((open(os.path.join(src, "examples/campaign/lander.nml")).read()
                            + open(os.path.join(src, "examples/campaign/dispersion.nml")).read()
                            + "%d %r %r" % (a.cases, a.ref_dt, a.t_end)).encode()).hexdigest()[:12]
        cached = os.path.join(a.ref_cache, "ref_%s.npz" % key) if a.ref_cache else None
        if cached and os.path.exists(cached):
            z = np.load(cached)
            ref, ref_check = z["ref"], z["check"]
        else:
            d = make_dir(src, w, "ref", "fixed:dt=%r" % a.ref_dt, a.cases, a.t_end)
            _, ref, _ = run(batch, d, "ref", a.cases)
            if a.check_cases > 0:
                d = make_dir(src, w, "check", "fixed:dt=%r" % (a.ref_dt / 2), a.check_cases, a.t_end)
                _, ref_check, _ = run(batch, d, "check", a.check_cases)
            else:
                ref_check = ref[:0]
            if cached:
                os.makedirs(a.ref_cache, exist_ok=True)
                np.savez(cached, ref=ref, check=ref_check)
        n_chk = len(ref_check)   # the cases checked (a cached reference keeps the check it was made with)
        if n_chk == 0:
            per, conv = np.zeros(0), float("nan")
            print("reference: fixed dt = %.3g s; NOT checked against dt/2 (--check-cases 0): its convergence is "
                  "unknown" % a.ref_dt)
        else:
            per = 1e3 * np.max(np.abs(ref_check - ref[:n_chk]).reshape(n_chk, -1), axis=1)
            conv = per.max()
            print("reference: fixed dt = %.3g s; against dt/2 on cases 1..%d: largest crush-length difference %.4f mm"
                  % (a.ref_dt, n_chk, conv))
        if conv > 0.1:
            # errors below 0.1 mm cannot be told apart from the reference's own error on those cases
            print("WARNING: the reference is not converged to 0.1 mm on %d of the %d cases checked "
                  "(per case: %s mm); the errors below are against an uncertain reference"
                  % (np.sum(per > 0.1), n_chk, ", ".join("%.3f" % x for x in per)))
        spread = sensitivity(a, batch, src, w, ref) if a.sensitivity else None
        dirs = {s: make_dir(src, w, "s%d" % i, split_batch(s, batch)[0], a.cases, a.t_end)
                for i, s in enumerate(a.schemes)}
        best, results = {}, {}
        for r in range(a.rounds):
            for i, s in enumerate(a.schemes):
                wall, crush, res = run(split_batch(s, batch)[1], dirs[s], "s%d" % i, a.cases)
                best[s] = min(best.get(s, wall), wall)
                results[s] = (crush, res)
        print("%-34s %10s %11s %12s %8s %11s" % ("scheme", "cases/c-h", "largest", "<=0.1 mm", ">0.5 mm", "steps/case"))
        for s in a.schemes:
            crush, steps = results[s]
            err = 1e3 * np.max(np.abs(crush - ref).reshape(a.cases, -1), axis=1)
            print("%-34s %10.0f %8.3f mm %7d of %d %8d %11.0f" % (
                s, a.cases * 3600.0 / best[s], err.max(), np.sum(err <= 0.1), a.cases, np.sum(err > 0.5),
                np.mean(steps)))
        q = (5, 50, 95)
        print("distribution: largest difference of a crush length's %s %% quantiles over the cases, "
              "against the reference" % "/".join(str(x) for x in q))
        for s in a.schemes:
            crush = results[s][0].reshape(a.cases, -1)
            dq = 1e3 * np.abs(np.percentile(crush, q, axis=0) - np.percentile(ref.reshape(a.cases, -1), q, axis=0))
            print("%-34s %8.3f mm" % (s, dq.max()))
        if spread is not None:
            well = spread <= 0.1
            print("cases whose crush lengths the inputs decide to 0.1 mm (change <= 0.1 mm for a vertical touchdown"
                  " velocity +-%g m/s): %d of %d; the others: %s"
                  % (a.sensitivity, np.sum(well), a.cases,
                     " ".join(str(c + 1) for c in np.flatnonzero(~well)) or "none"))
            for s in a.schemes:
                err = 1e3 * np.max(np.abs(results[s][0] - ref).reshape(a.cases, -1), axis=1)
                print("%-34s on those %d: largest %.3f mm, within 0.1 mm %d, beyond 0.5 mm %d" % (
                    s, np.sum(well), err[well].max() if well.any() else 0.0, np.sum(err[well] <= 0.1),
                    np.sum(err[well] > 0.5)))
        if a.per_case:
            print("case " + " ".join("%17s" % ("s%d err/steps" % i) for i in range(len(a.schemes)))
                  + ("  spread" if spread is not None else ""))
            errs = {s: 1e3 * np.max(np.abs(results[s][0] - ref).reshape(a.cases, -1), axis=1) for s in a.schemes}
            for c in range(a.cases):
                print("%4d " % (c + 1) + " ".join("%8.3f %8d" % (errs[s][c], results[s][1][c]) for s in a.schemes)
                      + ("  %6.3f" % spread[c] if spread is not None else ""))
        if a.energy:
            for i, s in enumerate(a.schemes):
                print("%-34s residual [%%] %s" % (s, " ".join("%8.4f" % r for r in energy_residuals(
                    split_batch(s, batch)[1], dirs[s], "s%d" % i, a.cases))))


if __name__ == "__main__":
    main()
