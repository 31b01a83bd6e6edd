#!/usr/bin/env python3
"""Runs a deck with the landyn program and through the C API (test_api_run) and compares the two
result files: --mode same: every dataset identical (provenance /meta, wall time and /api excluded);
--mode close: the strokes and crush lengths within --tol metres (step placement of many
landyn_advance_to calls, docs/api.md). Prints the largest differences; exit 0 when they pass.

  check_api_runs.py --landyn EXE --driver EXE --deck DECK --t-end T --step S --mode same|close
                    [--tol M] --workdir DIR
"""
import argparse
import os
import subprocess
import sys

import h5py
import numpy as np


def datasets(path):
    out = {}
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                out[name] = obj[()]
        f.visititems(visit)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--landyn", required=True)
    ap.add_argument("--driver", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--t-end", required=True)
    ap.add_argument("--step", default="0")
    ap.add_argument("--mode", choices=("same", "close"), required=True)
    ap.add_argument("--tol", type=float, default=0.0)
    ap.add_argument("--workdir", required=True)
    a = ap.parse_args()
    os.makedirs(a.workdir, exist_ok=True)
    tag = os.path.splitext(os.path.basename(a.deck))[0] + "_" + a.step.replace(".", "p")
    prog = os.path.join(a.workdir, tag + "_program.h5")
    api = os.path.join(a.workdir, tag + "_api.h5")
    for p in (prog, api):
        if os.path.exists(p):
            os.remove(p)
    subprocess.run([a.landyn, a.deck, "-o", prog, "-q"], check=True, stdout=subprocess.DEVNULL)
    subprocess.run([a.driver, a.deck, a.t_end, a.step, api], check=True)
    x, y = datasets(prog), datasets(api)
    with h5py.File(api, "r") as f:
        producer = f.attrs["producer"]
        producer = producer.decode() if isinstance(producer, bytes) else producer
    if "C API" not in producer:
        print("FAIL: the producer does not name the C API: %r" % producer)
        return 1
    skip = ("meta/", "wall_time", "api/")
    bad = []
    if a.mode == "same":
        for k in sorted(set(x) | set(y)):
            if any(s in k for s in skip):
                continue
            if k not in x or k not in y:
                bad.append((k, "missing"))
                continue
            u, v = x[k], y[k]
            same = np.array_equal(u, v) if u.dtype.kind != "f" else np.array_equal(u, v, equal_nan=True)
            if not same:
                bad.append((k, "differs"))
        print("%d datasets compared, %d differ" % (len(x), len(bad)))
    else:
        for k in ("summary/crush_length", "summary/stroke_final", "summary/crushed_positive",
                  "summary/crushed_negative"):
            d = float(np.max(np.abs(np.asarray(x[k]) - np.asarray(y[k]))))
            print("%-28s largest difference %.3e m (tolerance %.1e m)" % (k, d, a.tol))
            if not d <= a.tol:
                bad.append((k, d))
        n = min(len(x["timeseries/time"]), len(y["timeseries/time"]))
        d = float(np.max(np.abs(x["timeseries/gears/stroke"][:n] - y["timeseries/gears/stroke"][:n])))
        print("%-28s largest difference %.3e m (tolerance %.1e m)" % ("timeseries/gears/stroke", d, a.tol))
        if not d <= a.tol:
            bad.append(("timeseries/gears/stroke", d))
    for k, d in bad[:20]:
        print("FAIL: %s: %s" % (k, d))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
