#!/usr/bin/env python3
"""Campaign benchmark (issue "Campaigns on clusters", item 8): the Monte Carlo campaign
bench/campaign_mc.nml (demonstration lander, 1 s simulated per case at the dt chosen in
bench/campaign_base.nml) on 2 MPI ranks, Release build. Prints cases per core-hour
(= cases * 3600 / (wall time * ranks), wall time of the whole mpirun). Target: >= 10,000.

  bench_campaign.py --batch build/landyn_batch --src . [--cases 1000] [--ranks 2]
                    [--mpiexec=mpiexec,--oversubscribe] [--np-flag=-n]

--cases N runs a copy of the deck with n_samples = N (default 1000, the documented size).
"""
import argparse
import os
import re
import shutil
import subprocess
import tempfile
import time

import h5py
import numpy as np

TARGET = 10000.0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--batch", required=True, help="landyn_batch executable")
    ap.add_argument("--src", required=True, help="source tree (for bench/campaign_*.nml)")
    ap.add_argument("--cases", type=int, default=1000, help="Monte Carlo cases (default 1000)")
    ap.add_argument("--ranks", type=int, default=2, help="MPI ranks (default 2)")
    ap.add_argument("--mpiexec", default="mpiexec", help="launcher and its flags, comma-separated")
    ap.add_argument("--np-flag", default="-n", help="launcher flag for the number of ranks")
    ap.add_argument("--keep", help="copy the summary file here")
    a = ap.parse_args()
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    with tempfile.TemporaryDirectory(prefix="landyn_bench_campaign_") as d:
        for f in ("campaign_base.nml", "campaign_mc.nml"):
            shutil.copy(os.path.join(a.src, "bench", f), d)
        deck = os.path.join(d, "campaign_mc.nml")
        text = open(deck).read()
        text, n = re.subn(r"(?m)^(\s*n_samples\s*=\s*)\d+", lambda m: m.group(1) + str(a.cases), text)
        assert n == 1, "campaign_mc.nml must set n_samples once"
        open(deck, "w").write(text)
        dt = re.search(r"(?m)^\s*dt\s*=\s*([0-9.eE+-]+)", open(os.path.join(d, "campaign_base.nml")).read()).group(1)
        cmd = [x for x in a.mpiexec.split(",") if x] + [a.np_flag, str(a.ranks), a.batch, "campaign_mc.nml", "-q"]
        t0 = time.perf_counter()
        p = subprocess.run(cmd, cwd=d, env=env, capture_output=True, text=True)
        wall = time.perf_counter() - t0
        if p.returncode != 0:
            print(p.stdout, p.stderr)
            raise SystemExit("landyn_batch failed with exit status %d" % p.returncode)
        with h5py.File(os.path.join(d, "bench_campaign.h5"), "r") as f:
            status = f["cases/status"][()]
            case_wall = f["cases/wall_time"][()]
            steps = f["cases/n_steps"][()]
            p_s = float(f["probability/p_success"][()])
            lo = float(f["probability/ci95_low"][()])
            hi = float(f["probability/ci95_high"][()])
        if a.keep:
            shutil.copy(os.path.join(d, "bench_campaign.h5"), a.keep)
    rate = a.cases * 3600.0 / (wall * a.ranks)
    print("LANDYN campaign benchmark: %d Monte Carlo cases of the demonstration lander, 1 s simulated each, "
          "dt = %s s, %d ranks" % (a.cases, dt, a.ranks))
    print("  cases: %d ran, %d invalid input, %d failed runs" % ((status == 0).sum(), (status == 2).sum(),
                                                                (status == 3).sum()))
    print("  P(successful landing) = %.4f, 95 %% CI [%.4f, %.4f]" % (p_s, lo, hi))
    print("  wall time (whole mpirun)       %9.2f s" % wall)
    print("  per case: mean %.3f s, max %.3f s, %.0f steps; sum over cases %.1f s (%.0f %% of %d x wall)"
          % (case_wall.mean(), case_wall.max(), steps.mean(), case_wall.sum(), 100.0 * case_wall.sum() / (wall * a.ranks),
             a.ranks))
    print("  cases per core-hour            %9.0f" % rate)
    print("  target >= %d cases per core-hour: %s" % (TARGET, "MET" if rate >= TARGET else
                                                    "MISSED by %.0f %%" % (100.0 * (TARGET - rate) / TARGET)))


if __name__ == "__main__":
    main()
