#!/usr/bin/env python3
"""The energy audit of a run with engine inputs (test_api_inputs' moment.h5): the relative residual
/summary/energy_residual within --max, the inputs' work (/summary/energy_audit/thrust_work) more
than --work-factor times the residual in joules (the audit counts the moment's work: without it
the residual would be that work), and the inputs recorded in /api/inputs.

  check_energy.py FILE --max R --work-factor F
"""
import argparse
import sys

import h5py
import numpy as np


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file")
    ap.add_argument("--max", type=float, required=True)
    ap.add_argument("--work-factor", type=float, required=True)
    a = ap.parse_args()
    with h5py.File(a.file, "r") as f:
        rel = float(f["/summary/energy_residual"][()])
        res_j = float(f["/summary/energy_audit/residual"][()])
        work = float(f["/summary/energy_audit/thrust_work"][()])
        n_inputs = len(f["/api/inputs/time"][()])
        moment = np.asarray(f["/api/inputs/moment"][()])
        reason = f["/summary/end_reason"][()]
    print("energy residual %.3e (relative), %.3e J; work of the inputs %.3e J; %d inputs recorded"
          % (rel, res_j, work, n_inputs))
    ok = True
    if not abs(rel) <= a.max:
        print("FAIL: |residual| %.3e > %.3e" % (abs(rel), a.max))
        ok = False
    if not abs(work) > a.work_factor * abs(res_j):
        print("FAIL: the inputs' work %.3e J is not %g times the residual %.3e J" % (work, a.work_factor, res_j))
        ok = False
    if n_inputs < 1 or moment.shape[-1] != 3:
        print("FAIL: /api/inputs does not hold the inputs (shape %s)" % (moment.shape,))
        ok = False
    print("end reason:", reason)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
