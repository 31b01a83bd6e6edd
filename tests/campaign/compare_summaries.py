#!/usr/bin/env python3
"""Compare two LANDYN campaign summary files (docs/campaign.md) row for row.

Every dataset under /cases, /parameters, /criteria and /probability must be identical bit for
bit (NaN included), except /cases/wall_time (and /cases/history_file unless --history), and the
root attributes fingerprint, n_cases, n_rows, complete and p_success* must agree. Provenance
(/meta, /campaign/deck_name, command lines, dates) is not compared.

Exit status: 0 identical, 1 different, 2 a file cannot be read.
"""
import argparse
import sys

try:
    import h5py
    import numpy as np
except ImportError as exc:  # pragma: no cover
    print(f"compare_summaries: needs numpy and h5py ({exc})", file=sys.stderr)
    sys.exit(77)

GROUPS = ("cases", "parameters", "criteria", "probability")
SKIP = {"cases/wall_time"}
ATTRS = ("fingerprint", "n_cases", "n_rows", "complete", "p_success", "p_success_ci95_low", "p_success_ci95_high")


def datasets(f):
    out = {}

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset) and name.split("/")[0] in GROUPS:
            out[name] = obj[()]

    f.visititems(visit)
    return out


def same(a, b):
    a = np.asarray(a)
    b = np.asarray(b)
    if a.shape != b.shape or a.dtype.kind != b.dtype.kind:
        return False
    if a.dtype.kind in "SUO":
        return a.tolist() == b.tolist()
    return a.tobytes() == b.astype(a.dtype).tobytes()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("a", help="first summary file")
    ap.add_argument("b", help="second summary file")
    ap.add_argument("--history", action="store_true", help="compare /cases/history_file too")
    ap.add_argument("--min-rows", type=int, default=1, help="fail unless the files have at least this many rows")
    args = ap.parse_args()
    skip = set(SKIP)
    if not args.history:
        skip.add("cases/history_file")
    try:
        fa = h5py.File(args.a, "r")
        fb = h5py.File(args.b, "r")
    except OSError as exc:
        print(f"compare_summaries: {exc}", file=sys.stderr)
        return 2
    da, db = datasets(fa), datasets(fb)
    problems = []
    for name in sorted(set(da) | set(db)):
        if name in skip:
            continue
        if name not in da or name not in db:
            problems.append(f"{name}: only in {args.a if name in da else args.b}")
        elif not same(da[name], db[name]):
            problems.append(f"{name}: differs\n  {args.a}: {da[name]!r}\n  {args.b}: {db[name]!r}")
    for attr in ATTRS:
        va, vb = fa.attrs.get(attr), fb.attrs.get(attr)
        if va is None or vb is None or not same(va, vb):
            problems.append(f"attribute {attr}: {va!r} vs {vb!r}")
    n = len(da.get("cases/case_id", []))
    if n < args.min_rows:
        problems.append(f"only {n} rows (expected at least {args.min_rows})")
    if problems:
        print(f"compare_summaries: {args.a} and {args.b} differ:", file=sys.stderr)
        for p in problems:
            print("  " + p, file=sys.stderr)
        return 1
    print(f"compare_summaries: {args.a} and {args.b} agree ({n} rows, wall times aside)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
