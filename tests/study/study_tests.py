#!/usr/bin/env python3
"""Tests of landyn_study (docs/study.md), one per call:

  study_tests.py --study-exe LANDYN_STUDY --exe LANDYN --src SOURCE_DIR small_study
  study_tests.py --study-exe LANDYN_STUDY --exe LANDYN --src SOURCE_DIR check_and_errors
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

FAILS = []
T_END = 0.05   # s: the first touchdown and the start of the crush, a few seconds in all


def check(cond, what):
    print(("ok:   " if cond else "FAIL: ") + what)
    if not cond:
        FAILS.append(what)


def run(cmd, cwd):
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def study_deck(src):
    inp = os.path.join(src, "input")
    return f"""! small test study
&study
  title = 'test study'
  base_deck = '{inp}/lc1.nml', '{inp}/lc2.nml'
  case_label = 'LC-1', 'LC-2'
  common = "&simulation t_end = {T_END} /"
  output = 'small.h5'
  csv = 'small.csv'
/
&variant label = 'Base result' /
&variant label = 'Hertz', set = "&contact law = 'hertz' /" /
&variant label = 'TY-1, stick', set = "friction%law = 'ty1'", "friction%stick_damping = 2.0e5" /
&variant label = 'eta', set = "&primary_strut tube_friction = .true. /" /
"""


# the paper's nine measure options: (case, gear, strut), strut 0 primary, 1 left, 2 right
PAPER_OPTIONS = [(0, 0, 0), (0, 0, 1), (0, 0, 2), (1, 0, 0), (1, 0, 1), (1, 1, 1), (1, 1, 0), (1, 2, 1), (1, 3, 1)]


def t_small_study(study_exe, exe, src, d):
    with open(os.path.join(d, "small.nml"), "w") as f:
        f.write(study_deck(src))
    rc, out, err = run([study_exe, "small.nml"], d)
    check(rc == 0, "landyn_study exits 0 (got %d; stderr %s)" % (rc, err[-500:]))
    check(os.path.exists(os.path.join(d, "small.h5")) and os.path.exists(os.path.join(d, "small.csv")),
          "the HDF5 file and the CSV are written")
    check("[8/8]" in err, "progress names each of the 8 runs")
    check("Crush lengths [mm]" in out, "the table is printed")
    outcome = [ln for ln in out.splitlines() if ln.startswith("  LC-") and "end time reached" in ln]
    check("Run outcomes: peak overload" in out and len(outcome) == 8,
          "the outcome of each of the 8 runs (overload, tilt, residual, end) is printed (%d lines)" % len(outcome))
    # from the right: margin [mm], residual [%], outcome, 'end time reached'
    cols = [ln.split() for ln in outcome]
    check(all(c[-4] == "still_moving" for c in cols),
          "each run's outcome is named (still_moving: the 0.3 s runs end moving): %s" % [c[-4] for c in cols])
    check(all(0.0 < float(c[-6]) < 500.0 for c in cols),
          "each run's smallest stroke margin is printed in mm: %s" % [c[-6] for c in cols])
    if FAILS:
        return
    labels = ["Base result", "Hertz", "TY-1, stick", "eta"]
    with open(os.path.join(d, "small.csv"), newline="") as f:
        rows = list(csv.reader(f))
    head = rows[0]
    check(head[:4] == ["load_case", "option", "gear", "strut"], "CSV header starts with the row description")
    check(head[4:8] == [l + " [mm]" for l in labels], "one crush column per variant, quoted when needed: %s" % head[4:8])
    check(head[8:] == [l + " dev [%]" for l in labels[1:]], "deviation columns for the further variants")
    check(len(rows) == 10, "nine measure options (got %d rows)" % (len(rows) - 1))
    check([r[0] for r in rows[1:]] == ["LC-1"] * 3 + ["LC-2"] * 6, "options 1-3 from LC-1, 4-9 from LC-2")
    check([r[3] for r in rows[1:4]] == ["primary", "secondary left", "secondary right"], "LC-1 gear 1 struts")
    check([r[2] for r in rows[4:]] == ["1", "1", "2", "2", "3", "4"], "LC-2 gears of the paper's options 4-9")
    h = h5py.File(os.path.join(d, "small.h5"), "r")
    tab = h["table/crush_length"][()]
    check(tab.shape == (9, 4), "/table/crush_length has shape (options, variants) = (9, 4), got %s" % (tab.shape,))
    check(h["table/crush_length"].attrs["units"] == b"m", "table in m")
    check(np.all(h["summary/status"][()] == 0), "every run completed (status 0)")
    check([x.decode() for x in h["study/variant_label"][()]] == labels, "variant labels stored")
    check(b"hertz" in h["variants/002/overrides"][()], "variant overrides stored")
    csv_mm = np.array([[float(x) for x in r[4:8]] for r in rows[1:]])
    check(np.allclose(csv_mm, 1000.0 * tab, atol=0.006), "CSV values are the HDF5 table in mm (2 decimals)")
    for m, (c, g, s) in enumerate(PAPER_OPTIONS):
        for v in range(4):
            cl = h["variants/%03d/%s/crush_length" % (v + 1, ["LC-1", "LC-2"][c])][()]
            if cl[g, s] != tab[m, v]:
                check(False, "table option %d variant %d is /variants/.../crush_length[%d, %d]" % (m + 1, v + 1, g, s))
    res = h["variants/001/LC-1/energy_residual"][()]
    check(abs(res) < 5e-3, "energy residual stored and small (%.2e)" % res)
    # deviations
    dev = np.array([[float(x) for x in r[8:]] for r in rows[1:]])
    with np.errstate(divide="ignore", invalid="ignore"):
        want = np.where(tab[:, :1] != 0.0, 100.0 * (tab[:, 1:] - tab[:, :1]) / np.abs(tab[:, :1]), np.nan)
    check(np.allclose(dev, want, atol=0.006, equal_nan=True), "dev [%] is the deviation from the first variant")
    # the variants change the results, the base variant is a plain landyn run
    check(not np.allclose(tab[:, 1], tab[:, 0]), "the Hertz variant changes the crush lengths")
    check(tab[0, 3] < tab[0, 0], "tube friction reduces the primary's crush in LC-1")
    with open(os.path.join(d, "lc1_short.nml"), "w") as f:
        f.write(open(os.path.join(src, "input", "lc1.nml")).read().replace("t_end = 1.0", "t_end = %s" % T_END))
    rc, out, err = run([exe, "lc1_short.nml", "-q", "-o", "plain.h5"], d)
    check(rc == 0, "plain landyn run of LC-1")
    plain = h5py.File(os.path.join(d, "plain.h5"), "r")["summary/crush_length"][()]
    check(np.array_equal(plain, h["variants/001/LC-1/crush_length"][()]),
          "the base variant on LC-1 equals landyn lc1.nml, bit for bit")


def t_check_and_errors(study_exe, exe, src, d):
    with open(os.path.join(d, "small.nml"), "w") as f:
        f.write(study_deck(src))
    rc, out, err = run([study_exe, "--check", "small.nml"], d)
    check(rc == 0, "--check exits 0")
    check(sorted(os.listdir(d)) == ["small.nml"], "--check writes no file")
    check("TY-1, stick on LC-2" in out and "friction 'ty1'" in out, "--check lists the runs with their laws")
    bad = study_deck(src) + "&variant label = 'bad', set = \"&contact law = 'hertzz' /\", \"friction%mu_statik = 1\" /\n"
    with open(os.path.join(d, "bad.nml"), "w") as f:
        f.write(bad)
    rc, out, err = run([study_exe, "bad.nml"], d)
    check(rc == 2, "an invalid variant: exit 2 (got %d)" % rc)
    check("hertzz" in err and "mu_statik" in err and "variant bad" in err, "each problem is reported, naming the variant")
    check(not os.path.exists(os.path.join(d, "small.h5")), "nothing is run or written")
    rc, out, err = run([study_exe], d)
    check(rc == 1, "no deck: usage error, exit 1")
    rc, out, err = run([study_exe, "--help"], d)
    check(rc == 0 and "landyn_study STUDY.nml" in out, "--help")
    rc, out, err = run([study_exe, "missing.nml"], d)
    check(rc == 2 and "missing.nml" in err, "a missing deck: exit 2 with its name")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--study-exe", required=True)
    ap.add_argument("--exe", required=True)
    ap.add_argument("--src", required=True)
    ap.add_argument("test", choices=["small_study", "check_and_errors"])
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as d:
        globals()["t_" + a.test](os.path.abspath(a.study_exe), os.path.abspath(a.exe), os.path.abspath(a.src), d)
    if FAILS:
        print("%d check(s) failed" % len(FAILS))
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
