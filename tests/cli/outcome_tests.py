#!/usr/bin/env python3
"""Every outcome class (docs/output.md, "Outcome") on landyn, landyn_study and landyn_batch, run the
one way they all run a case (src/output/landyn_run.f90), with the same status meaning
(docs/exit_status.md):

  no_touchdown  an upward velocity: landyn exits 7, the study run and the campaign row have status 7;
  at_rest       a slow landing on damped regolith with sticking friction: comes to rest at ~0.6 s;
  still_moving  LC-1 cut at 0.1 s: touched down, still crushing: inconclusive, never a success;
  tipped_over   a lander pitched 30 deg and pitching at 90 deg/s: tips over.

Usage: outcome_tests.py --landyn EXE --study EXE [--batch EXE] TEST_NAME
"""
import argparse
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

FAILURES = []

#: the four decks, each small enough for the Debug build
DECKS = {
    "no_touchdown": "&simulation t_end = 0.3 /\n&initial_state velocity = 1.0, 0.0, -3.0 /\n",
    "at_rest": ("&simulation t_end = 3.0 /\n&contact law = 'regolith', damping = 1.0e5 /\n"
                "&friction law = 'ty4', mu_static = 0.5, mu_dynamic = 0.4 /\n"
                "&initial_state velocity = 0.0, 0.0, 0.5 /\n"),
    "still_moving": "&simulation t_end = 0.1 /\n",
    "tipped_over": ("&simulation t_end = 3.0 /\n"
                    "&initial_state velocity = 0.0, 0.0, 1.0, attitude = 0.0, 30.0, 0.0, "
                    "angular_rate = 0.0, 90.0, 0.0 /\n"),
}
CODES = {"no_touchdown": 1, "at_rest": 2, "still_moving": 3, "tipped_over": 4}
#: landyn's exit status (and a study run's, a campaign row's status) for each class
STATUS = {"no_touchdown": 7, "at_rest": 0, "still_moving": 0, "tipped_over": 0}
#: the campaign's failed criteria for each class (success only at rest)
CRITERIA = {"no_touchdown": "no_touchdown", "at_rest": "", "still_moving": "not_at_rest",
            "tipped_over": "tipped_over"}


def check(cond, what):
    print(("ok:   " if cond else "FAIL: ") + what)
    if not cond:
        FAILURES.append(what)


def run(cmd, cwd):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=900, env=env)
    return p.returncode, p.stdout, p.stderr


def text(v):
    v = v[()] if isinstance(v, h5py.Dataset) else v
    return (v.decode() if isinstance(v, bytes) else str(v)).strip()


def t_landyn(a, d):
    for name, deck in DECKS.items():
        with open(os.path.join(d, name + ".nml"), "w") as f:
            f.write(deck)
        rc, out, err = run([a.landyn, name + ".nml", "-q", "-o", name + ".h5"], d)
        check(rc == STATUS[name], f"landyn {name}: exit {STATUS[name]} (got {rc}: {err.strip()[-200:]})")
        check(os.path.isfile(os.path.join(d, name + ".h5")), f"landyn {name}: the result file is written")
        check("outcome: " + {"no_touchdown": "NO TOUCHDOWN", "at_rest": "AT REST", "still_moving": "STILL MOVING",
                             "tipped_over": "TIPPED OVER"}[name] in out, f"landyn {name}: the outcome is printed")
        if name == "no_touchdown":
            check("no touchdown" in err and "exit status 7" in err, "landyn no_touchdown: stderr says why it exits 7")
        if name == "still_moving":
            check("inconclusive" in out, "landyn still_moving: printed as inconclusive")
        with h5py.File(os.path.join(d, name + ".h5"), "r") as f:
            check(int(f["/summary/outcome/code"][()]) == CODES[name], f"landyn {name}: /summary/outcome/code")
            check(text(f["/summary/outcome/name"]) == name, f"landyn {name}: /summary/outcome/name")
            check(bool(f["/summary/outcome/touched_down"][()]) == (name != "no_touchdown"),
                  f"landyn {name}: touched_down")
            speed = float(f["/summary/outcome/body_speed"][()])
            if name == "at_rest":
                check(speed < 1.0e-3, f"landyn at_rest: body speed {speed:.3g} m/s below rest_speed")
                margin = float(f["/summary/outcome/tipover_margin"][()])
                # four footpads on a square of half-diagonal r around the mass centre at height h:
                # the margin is atan(r cos 45 / h), well above 0 on level ground
                check(20.0 < margin < 60.0, f"landyn at_rest: tip-over margin {margin:.2f} deg plausible")
                ratio = f["/summary/outcome/friction_ratio"][()]
                check(ratio.shape == (4,) and np.all(ratio < 0.05),
                      f"landyn at_rest: level ground needs almost no friction ({ratio})")
            if name == "still_moving":
                check(speed > 1.0e-3, f"landyn still_moving: body speed {speed:.3g} m/s at the end is reported")


def t_study(a, d):
    for name, deck in DECKS.items():
        with open(os.path.join(d, name + ".nml"), "w") as f:
            f.write(deck)
    labels = list(DECKS)
    with open(os.path.join(d, "s.nml"), "w") as f:
        f.write("&study\n  title = 'outcomes'\n  base_deck = " + ", ".join(f"'{n}.nml'" for n in labels) + "\n"
                "  case_label = " + ", ".join(f"'{n}'" for n in labels) + "\n"
                "  output = 's.h5'\n  csv = 's.csv'\n/\n&variant label = 'base' /\n")
    rc, out, err = run([a.study, "s.nml", "-q"], d)
    check(rc == 7, f"landyn_study: a run that never touched down makes the study exit 7 (got {rc}: {err[-300:]})")
    with h5py.File(os.path.join(d, "s.h5"), "r") as f:
        st = f["/summary/status"][()].reshape(-1)
        check(list(st) == [STATUS[n] for n in labels], f"landyn_study: run statuses {list(st)} as landyn's exit statuses")


def t_batch(a, d):
    if not a.batch:
        print("landyn_batch not built (no MPI): skipped")
        return
    names = list(DECKS)
    # a list campaign: one base deck (damped regolith, sticking friction), each case sets the end
    # time and the touchdown state of its class
    with open(os.path.join(d, "base.nml"), "w") as f:
        f.write("&simulation t_end = 3.0 /\n&contact law = 'regolith', damping = 1.0e5 /\n"
                "&friction law = 'ty4', mu_static = 0.5, mu_dynamic = 0.4 /\n")
    rows = {  # t_end, vz, pitch, pitch rate
        "no_touchdown": (0.3, -3.0, 0.0, 0.0),
        "at_rest": (3.0, 0.5, 0.0, 0.0),
        "still_moving": (0.1, 4.0, 0.0, 0.0),
        "tipped_over": (3.0, 1.0, 30.0, 90.0),
    }
    with open(os.path.join(d, "cases.csv"), "w") as f:
        f.write("simulation%t_end,initial_state%velocity(3),initial_state%attitude(2),initial_state%angular_rate(2)\n")
        for n in names:
            f.write(",".join(str(x) for x in rows[n]) + "\n")
    with open(os.path.join(d, "c.nml"), "w") as f:
        f.write("&campaign title = 'outcomes', base_deck = 'base.nml', mode = 'list', list_file = 'cases.csv',\n"
                "  summary_file = 'c.h5' /\n")
    rc, out, err = run([a.batch, "c.nml"], d)
    check(rc == 0, f"landyn_batch: the campaign completes (got {rc}: {err[-300:]})")
    with h5py.File(os.path.join(d, "c.h5"), "r") as f:
        st = list(f["/cases/status"][()])
        oc = list(f["/cases/outcome"][()])
        fc = [text(x) for x in f["/cases/failed_criteria_names"][()]]
        succ = list(f["/cases/success"][()])
        n_inc = int(f["/probability/n_inconclusive"][()])
        p, pu = float(f["/probability/p_success"][()]), float(f["/probability/p_success_upper"][()])
    check(st == [STATUS[n] for n in names], f"landyn_batch: row statuses {st} as landyn's exit statuses")
    check(oc == [CODES[n] for n in names], f"landyn_batch: outcomes {oc}")
    check(fc == [CRITERIA[n] for n in names], f"landyn_batch: failed criteria {fc}")
    check(succ == [0, 1, 0, 0], f"landyn_batch: only the case at rest is a success ({succ})")
    check(n_inc == 1 and p == 0.25 and pu == 0.5,
          f"landyn_batch: one inconclusive case bounds P between 0.25 and 0.5 (got {n_inc}, {p}, {pu})")
    check("inconclusive" in out and "0.2500" in out and "0.5000" in out,
          "landyn_batch: the printed summary reports the inconclusive case and the bounds on P")


TESTS = {name[2:]: fn for name, fn in globals().items() if name.startswith("t_")}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--landyn", required=True)
    ap.add_argument("--study", required=True)
    ap.add_argument("--batch")
    ap.add_argument("test", choices=sorted(TESTS))
    a = ap.parse_args()
    for k in ("landyn", "study", "batch"):
        if getattr(a, k):
            setattr(a, k, os.path.abspath(getattr(a, k)))
    with tempfile.TemporaryDirectory(prefix="landyn_outcome_") as d:
        TESTS[a.test](a, d)
    print("%d failed" % len(FAILURES))
    sys.exit(1 if FAILURES else 0)


if __name__ == "__main__":
    main()
