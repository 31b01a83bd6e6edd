#!/usr/bin/env python3
"""Error against cost of integrator settings on the paper's load cases LC-1..LC-4 (1 s each).

  lc_accuracy.py --exe build/release/landyn --src . [--schemes "adaptive" "imex:tolerance=1e-6"]
                 [--rounds 1] [--ref-dt 1.25e-6] [--ref-cache DIR]

A scheme is NAME[:var=value,...] as in campaign_accuracy.py (&simulation integrator = NAME and
those &simulation variables). The reference is the fixed scheme at --ref-dt, cached in --ref-cache
(keyed by the deck text and the step). The schemes run interleaved (case by case, round by round);
per scheme and case it prints the accepted steps, the time loop's wall time (/summary/wall_time,
best round), the largest crush-length error against the reference over all struts [mm] and the
energy residual [%], then the largest error, mean steps and mean loop time over the cases.
"""
import argparse
import hashlib
import os
import re
import subprocess
import tempfile

import h5py
import numpy as np

from campaign_accuracy import scheme_text


def deck_text(src, lc, spec):
    text = open(os.path.join(src, "input", "lc%d.nml" % lc)).read()
    text = re.sub(r"(?m)^\s*(integrator|dt|tolerance)\s*=.*$", "", text)
    items = scheme_text(spec)
    if not spec.startswith("fixed") and "dt =" not in items:
        items += ", dt = 5e-6"
    text, n = re.subn(r"(?mi)^&simulation\b", "&simulation " + items + ",", text)
    assert n == 1
    return text


def run(exe, d, tag, text):
    deck = os.path.join(d, tag + ".nml")
    out = os.path.join(d, tag + ".h5")
    open(deck, "w").write(text)
    p = subprocess.run([exe, deck, "-o", out, "-q"], capture_output=True, text=True)
    if p.returncode not in (0, 6):
        raise SystemExit("%s: landyn exit %d\n%s%s" % (tag, p.returncode, p.stdout, p.stderr))
    with h5py.File(out, "r") as f:
        s = f["summary"]
        return (s["crush_length"][()], int(s["n_steps"][()]), float(s["wall_time"][()]),
                100.0 * float(s["energy_residual"][()]))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", required=True)
    ap.add_argument("--src", required=True)
    ap.add_argument("--schemes", nargs="+", default=["adaptive"])
    ap.add_argument("--rounds", type=int, default=1)
    ap.add_argument("--ref-dt", type=float, default=1.25e-6)
    ap.add_argument("--ref-cache", default=None)
    a = ap.parse_args()
    exe = os.path.abspath(a.exe)
    with tempfile.TemporaryDirectory(prefix="landyn_lc_accuracy_") as w:
        refs = {}
        for lc in range(1, 5):
            text = deck_text(a.src, lc, "fixed:dt=%r" % a.ref_dt)
            key = hashlib.sha1(text.encode()).hexdigest()[:12]
            cached = os.path.join(a.ref_cache, "lcref_%s.npy" % key) if a.ref_cache else None
            if cached and os.path.exists(cached):
                refs[lc] = np.load(cached)
            else:
                refs[lc] = run(exe, w, "ref%d" % lc, text)[0]
                if cached:
                    os.makedirs(a.ref_cache, exist_ok=True)
                    np.save(cached, refs[lc])
        res = {}
        for r in range(a.rounds):
            for lc in range(1, 5):
                for i, s in enumerate(a.schemes):
                    crush, steps, wall, resid = run(exe, w, "s%d_lc%d" % (i, lc), deck_text(a.src, lc, s))
                    err = 1e3 * np.max(np.abs(crush - refs[lc]))
                    old = res.get((s, lc))
                    res[(s, lc)] = (err, steps, wall if old is None else min(wall, old[2]), resid)
        print("%-28s %4s %10s %9s %10s %12s" % ("scheme", "case", "steps", "loop [s]", "error", "residual"))
        for s in a.schemes:
            for lc in range(1, 5):
                err, steps, wall, resid = res[(s, lc)]
                print("%-28s LC-%d %10d %9.3f %7.3f mm %10.4f %%" % (s, lc, steps, wall, err, resid))
        print("%-28s %12s %10s %12s %14s" % ("scheme", "largest", "mean steps", "mean loop", "largest |res|"))
        for s in a.schemes:
            v = [res[(s, lc)] for lc in range(1, 5)]
            print("%-28s %9.3f mm %10.0f %10.3f s %12.4f %%" % (s, max(x[0] for x in v), np.mean([x[1] for x in v]),
                                                              np.mean([x[2] for x in v]), max(abs(x[3]) for x in v)))


if __name__ == "__main__":
    main()
