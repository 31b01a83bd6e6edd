#!/usr/bin/env python3
"""Time-step study behind the campaign benchmark's dt (bench/campaign_base.nml).

Runs the paper's load cases LC-1 .. LC-4 (input/lc1.nml .. lc4.nml, 1 s simulated) at
dt = 5e-6 s (the paper's step, the reference) and at coarser steps, and prints for each the
largest deviation of /summary/crush_length (all gears and struts) from the reference, the
deviation of the primary struts alone, the peak overload change and the wall time per run.
A campaign may use a dt whose crush lengths stay within 0.5 mm of the reference.

  campaign_dt_study.py --exe build/landyn --src . [--dts 1e-5,2e-5,4e-5] [--cases 1,2,3,4]
"""
import argparse
import os
import re
import subprocess
import tempfile
import time

import h5py
import numpy as np

REF_DT = 5.0e-6
TOL_MM = 0.5


def run(exe, deck_text, dt, workdir, tag):
    # the fixed scheme is stated: the decks follow the default integrator (adaptive) otherwise
    text, n = re.subn(r"(?m)^(\s*)dt\s*=\s*[0-9.eE+-]+", lambda m: "%sintegrator = 'fixed', dt = %r" % (m.group(1), dt),
                      deck_text)
    assert n == 1, "the deck must set dt on a line of its own"
    deck = os.path.join(workdir, tag + ".nml")
    out = os.path.join(workdir, tag + ".h5")
    with open(deck, "w") as f:
        f.write(text)
    t0 = time.perf_counter()
    subprocess.run([exe, deck, "-q", "-o", out], check=True, capture_output=True)
    wall = time.perf_counter() - t0
    with h5py.File(out, "r") as f:
        return {"crush": f["summary/crush_length"][()], "peak_g": float(f["summary/peak_overload"][()]),
                "wall": wall, "loop": float(f["summary/wall_time"][()]), "end": f["summary/end_reason"][()].decode()}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", required=True, help="landyn executable (Release build)")
    ap.add_argument("--src", required=True, help="source tree (for input/lc*.nml)")
    ap.add_argument("--dts", default="1e-5,2e-5,4e-5", help="time steps to compare with 5e-6 s")
    ap.add_argument("--cases", default="1,2,3,4", help="load cases")
    a = ap.parse_args()
    dts = [float(x) for x in a.dts.split(",")]
    worst = {dt: 0.0 for dt in dts}
    print("LANDYN time-step study: max |crush_length(dt) - crush_length(5e-6 s)| over all gears and struts")
    print("%-5s %9s %12s %14s %12s %10s  %s" % ("case", "dt [s]", "all [mm]", "primary [mm]", "dpeak [g]",
                                                 "loop [s]", "end"))
    with tempfile.TemporaryDirectory(prefix="landyn_dt_") as d:
        for lc in [int(x) for x in a.cases.split(",")]:
            text = open(os.path.join(a.src, "input", "lc%d.nml" % lc)).read()
            ref = run(a.exe, text, REF_DT, d, "lc%d_ref" % lc)
            print("LC-%d  %9.1e %12s %14s %12s %10.2f  %s" % (lc, REF_DT, "(ref)", "(ref)", "(ref)", ref["loop"],
                                                             ref["end"]))
            for dt in dts:
                r = run(a.exe, text, dt, d, "lc%d_%g" % (lc, dt))
                dev = 1e3 * np.abs(r["crush"] - ref["crush"])
                worst[dt] = max(worst[dt], dev.max())
                print("LC-%d  %9.1e %12.3f %14.3f %12.3f %10.2f  %s" % (lc, dt, dev.max(), dev[:, 0].max(),
                                                                       r["peak_g"] - ref["peak_g"], r["loop"],
                                                                       r["end"]))
    print("worst deviation over the load cases:")
    for dt in dts:
        print("  dt = %.1e s: %.3f mm  (%s 0.5 mm)" % (dt, worst[dt], "within" if worst[dt] <= TOL_MM else "beyond"))


if __name__ == "__main__":
    main()
