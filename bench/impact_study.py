#!/usr/bin/env python3
"""Energy audit, crush-mode switches and time-step convergence over a seeded dispersion.

  impact_study.py --exe build/release/landyn [--cases 30] [--seed 9] [--dt 5e-6] [--dt-ref 1.25e-6]

Runs the two decks of the issue "Non-smooth time integration done right" (A: shallow slope,
tilted, nearly flat-footed; B: pitched and rolled vertical landing) and a seeded dispersion of
`--cases` landings (vertical 2-5 m/s, horizontal 0-1.5 m/s in any direction, yaw 0-90 deg,
pitch and roll +-5 deg, slope 0-10 deg at any azimuth, 1 s each) at `--dt` and at the reference
step `--dt-ref`, two runs at a time, and prints per case: the energy-audit residual, the largest
number of mode switches of a strut, the largest crush-length difference to the reference and the
wall time of each run. Exit status 0; this is a study, not a test (docs/validation.md records
its figures).
"""
import argparse
import concurrent.futures as cf
import os
import subprocess
import tempfile
import time

import numpy as np
import h5py

DECK_A = ("&simulation t_end = 1.0 /\n&terrain slope = 4*0.44, slope_direction = 4*0.0 /\n"
          "&initial_state clearance = 0.0, velocity = 0.6, 0.0, 2.36, attitude = 2.83, -2.65, -4.72 /\n")
DECK_B = "&simulation t_end = 1.0 /\n&initial_state velocity = 0, 0, 2.4, attitude = 0, -3, -5 /\n"


def dispersion(n, seed):
    rng = np.random.default_rng(seed)
    decks = []
    for _ in range(n):
        vz = rng.uniform(2.0, 5.0)
        vh = rng.uniform(0.0, 1.5)
        az = rng.uniform(0.0, 2 * np.pi)
        yaw = rng.uniform(0.0, 90.0)
        pitch, roll = rng.uniform(-5.0, 5.0, 2)
        slope = rng.uniform(0.0, 10.0)
        sdir = rng.uniform(0.0, 360.0)
        decks.append("&simulation t_end = 1.0 /\n"
                     "&terrain slope = 4*%.4f, slope_direction = 4*%.3f /\n"
                     "&initial_state velocity = %.4f, %.4f, %.4f, attitude = %.3f, %.3f, %.3f /\n"
                     % (slope, sdir, vh * np.cos(az), vh * np.sin(az), vz, yaw, pitch, roll))
    return decks


def run(exe, d, name, deck, dt):
    path = os.path.join(d, "%s_%g.nml" % (name, dt))
    with open(path, "w") as f:
        f.write(deck.replace("&simulation t_end = 1.0 /", "&simulation integrator = 'fixed', t_end = 1.0, dt = %.6e /" % dt))
    out = path[:-4] + ".h5"
    t0 = time.perf_counter()
    p = subprocess.run([exe, path, "-q", "-o", out], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        return name, dt, None, wall, p.stdout[-300:] + p.stderr[-300:]
    with h5py.File(out, "r") as h:
        r = dict(crush=h["summary/crush_length"][()], residual=h["summary/energy_residual"][()],
                 switches=h["summary/mode_switches"][()], impacts=h["summary/energy_audit/strut_impacts"][()])
    os.remove(out)
    return name, dt, r, wall, ""


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", required=True)
    ap.add_argument("--cases", type=int, default=30)
    ap.add_argument("--seed", type=int, default=9)
    ap.add_argument("--dt", type=float, default=5.0e-6)
    ap.add_argument("--dt-ref", type=float, default=1.25e-6)
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    cases = [("A", DECK_A), ("B", DECK_B)] + [("d%02d" % (i + 1), t) for i, t in enumerate(dispersion(a.cases, a.seed))]
    res = {}
    with tempfile.TemporaryDirectory(prefix="landyn_impact_") as d, cf.ThreadPoolExecutor(a.jobs) as ex:
        futs = [ex.submit(run, os.path.abspath(a.exe), d, n, t, dt) for n, t in cases for dt in (a.dt, a.dt_ref)]
        for f in cf.as_completed(futs):
            name, dt, r, wall, err = f.result()
            res[(name, dt)] = (r, wall, err)
    print("case  residual[%%] (dt, ref)   max switches   impacts [J]   max |crush - ref| [mm]   wall [s] (dt, ref)")
    worst_res, worst_dc, worst_sw = 0.0, 0.0, 0
    for name, _ in cases:
        r1, w1, e1 = res[(name, a.dt)]
        r2, w2, e2 = res[(name, a.dt_ref)]
        if r1 is None or r2 is None:
            print("%-4s  FAILED: %s %s" % (name, e1, e2))
            continue
        dc = 1000 * np.max(np.abs(r1["crush"] - r2["crush"]))
        sw = int(r1["switches"].max())
        worst_res = max(worst_res, abs(r1["residual"]), abs(r2["residual"]))
        worst_dc = max(worst_dc, dc)
        worst_sw = max(worst_sw, sw)
        print("%-4s  %8.4f %8.4f   %12d   %11.2f   %22.4f   %6.2f %6.2f"
              % (name, 100 * r1["residual"], 100 * r2["residual"], sw, r1["impacts"], dc, w1, w2))
    print("largest |residual| %.4f %%, largest crush difference to dt = %g s: %.4f mm, most switches %d"
          % (100 * worst_res, a.dt_ref, worst_dc, worst_sw))


if __name__ == "__main__":
    main()
