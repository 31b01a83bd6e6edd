#!/usr/bin/env python3
"""A result file written through the C API before the run reached t_end (test_api_misuse's
stopped.h5: a lander 1 m up, stopped at 0.0105 s before touchdown) claims no verdict it has not
reached: end reason "stopped by the caller at t = 0.0105 s", outcome still_moving (not
no_touchdown), the last sample and t_final at the stop, the producer and /api/inputs of the C API.

  check_stopped.py FILE
"""
import sys

import h5py


def text(x):
    return x.decode() if isinstance(x, bytes) else str(x)


def main():
    problems = []
    with h5py.File(sys.argv[1], "r") as f:
        reason = text(f["/summary/end_reason"][()])
        outcome = text(f["/summary/outcome/name"][()])
        t = f["/timeseries/time"][()]
        t_final = float(f["/summary/final_time"][()])
        producer = text(f.attrs["producer"])
        inputs = f["/api/inputs/force"][()]
        print("end reason %r, outcome %r, last sample %.6g s, t_final %.6g s, producer %r, inputs %s"
              % (reason, outcome, t[-1], t_final, producer, inputs.tolist()))
    if reason != "stopped by the caller at t = 0.0105 s":
        problems.append("end reason")
    if outcome != "still_moving":
        problems.append("outcome")
    if t[-1] != 0.0105 or t_final != 0.0105:
        problems.append("last sample or t_final not at the stop")
    if not producer.endswith("C API"):
        problems.append("producer")
    if inputs.shape != (1, 3) or inputs[0][2] != -1000.0:
        problems.append("/api/inputs")
    for p in problems:
        print("FAIL: " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
