#!/usr/bin/env python3
"""Campaign tests of landyn_batch (registered by tests/campaign/CMakeLists.txt).

    run_campaign_tests.py TEST --batch landyn_batch --landyn landyn --mpiexec=mpiexec,--oversubscribe
                          --np-flag=-n --src tests/campaign --workdir DIR

TEST is one of: grid, monte_carlo, resume, failing, case_merge, bad_deck. Each copies the decks of
tests/campaign into DIR (emptied first), runs landyn_batch and checks the summary files with
compare_summaries.py. Exit status 0 pass, 1 fail, 77 skipped (numpy or h5py missing).
"""
import argparse
import math
import os
import shutil
import subprocess
import sys

try:
    import h5py
    import numpy as np
except ImportError as exc:  # pragma: no cover
    print(f"skipped: needs numpy and h5py ({exc})")
    sys.exit(77)

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, HERE)
import compare_summaries  # noqa: E402

DECKS = ("base.nml", "grid.nml", "mc.nml", "fail.nml", "cases.csv", "bad.nml")


class Failure(Exception):
    pass


def check(cond, what):
    if not cond:
        raise Failure(what)
    print(f"  ok: {what}")


class Env:
    def __init__(self, args):
        self.batch = args.batch
        self.landyn = args.landyn
        self.mpiexec = [a for a in args.mpiexec.split(",") if a]
        self.np_flag = args.np_flag
        self.dir = args.workdir
        if os.path.isdir(self.dir):
            shutil.rmtree(self.dir)
        os.makedirs(self.dir)
        for f in DECKS:
            shutil.copy(os.path.join(args.src, f), self.dir)

    def run(self, cmd, expect=0):
        print("$ " + " ".join(cmd), flush=True)
        p = subprocess.run(cmd, cwd=self.dir, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                           timeout=300)
        sys.stdout.write(p.stdout)
        sys.stdout.write(p.stderr)
        if expect is not None and p.returncode != expect:
            raise Failure(f"exit status {p.returncode}, expected {expect}: {' '.join(cmd)}")
        return p

    def mpi(self, np_, *args, expect=0):
        return self.run(self.mpiexec + [self.np_flag, str(np_), self.batch] + list(args), expect=expect)

    def serial(self, *args, expect=0):
        return self.run([self.batch] + list(args), expect=expect)

    def path(self, name):
        return os.path.join(self.dir, name)

    def same(self, a, b, **kw):
        argv = [self.path(a), self.path(b)]
        if kw.get("history"):
            argv.append("--history")
        saved = sys.argv
        sys.argv = ["compare_summaries.py"] + argv
        try:
            rc = compare_summaries.main()
        finally:
            sys.argv = saved
        check(rc == 0, f"{a} and {b} have the same rows")


def wilson(k, n, z=1.959963984540054):
    if n == 0:
        return 0.0, 1.0
    p = k / n
    d = 1 + z * z / n
    c = (p + z * z / (2 * n)) / d
    h = z / d * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    return (0.0 if k == 0 else c - h), (1.0 if k == n else c + h)


# ------------------------------------------------------------------ tests

def test_grid(env):
    """2 x 2 grid on 1 and 2 ranks: identical; saved history = what landyn computes."""
    env.mpi(1, "grid.nml", "-o", "grid_np1.h5")
    env.mpi(2, "grid.nml", "-o", "grid_np2.h5")
    # history files follow -o (issue 10): grid_np1_case*.h5 and grid_np2_case*.h5, never shared
    env.same("grid_np1.h5", "grid_np2.h5")
    check(os.path.exists(env.path("grid_np1_case000002.h5")) and os.path.exists(env.path("grid_np2_case000002.h5")),
          "each run's history files are named after its summary file (-o)")
    f = h5py.File(env.path("grid_np2.h5"), "r")
    check(list(f["cases/case_id"][()]) == [1, 2, 3, 4], "rows ordered by case id")
    check(f.attrs["complete"] == 1 and f.attrs["n_rows"] == 4, "summary complete")
    v = f["cases/inputs/initial_state.velocity_1"]
    s = f["cases/inputs/terrain.slope"]
    check(list(v[()]) == [0.0, 1.5, 0.0, 1.5] and list(s[()]) == [0.0, 0.0, 8.0, 8.0],
          "grid order: first parameter fastest")
    check(v.attrs["units"] == b"m/s" and s.attrs["units"] == b"deg", "input columns carry deck units")
    check(f["cases/crush_length"].shape == (4, 4, 3), "crush_length shape (cases, gears, struts)")
    check(all(f["cases/status"][()] == 0), "all cases ran")
    hist = f["cases/history_file"][()][1].decode()
    check(hist == "grid_np2_case000002.h5" and os.path.exists(env.path(hist)), "history of case 2 written")
    h = h5py.File(env.path(hist), "r")
    check(np.array_equal(h["summary/crush_length"][()], f["cases/crush_length"][1]),
          "history file and summary row agree")
    # the case's deck, run by landyn itself, gives the same numbers bit for bit
    with open(env.path("case2.nml"), "w") as out:
        out.write(h["meta/deck_text"][()].decode())
    env.run([env.landyn, "case2.nml", "-q", "-o", "case2_landyn.h5"])
    ref = h5py.File(env.path("case2_landyn.h5"), "r")
    for name in ("crush_length", "stroke_margin", "peak_overload", "final_tilt"):
        check(ref[f"summary/{name}"][()].tobytes() == h[f"summary/{name}"][()].tobytes(),
              f"landyn on the case deck: identical /summary/{name}")


def test_monte_carlo(env):
    """6 Monte Carlo samples on 1 and 2 ranks: identical; inputs from the counter-based RNG."""
    env.mpi(2, "mc.nml", "-o", "mc_np2.h5")
    env.mpi(1, "mc.nml", "-o", "mc_np1.h5", "--dedicated-master")
    env.same("mc_np1.h5", "mc_np2.h5")
    f = h5py.File(env.path("mc_np2.h5"), "r")
    # uniform(0, 2) of case 1 = 2 * u(seed 20240611, case 1, parameter 1, draw 0), see test_campaign_rng
    check(f["cases/inputs/initial_state.velocity_1"][0] == 2.0 * 0.8017950731460525,
          "case 1 input from (seed, case id) as documented")
    listed = env.serial("mc.nml", "--list-cases").stdout.strip().splitlines()
    table = np.array([[float(x) for x in line.split(",")] for line in listed[1:]])
    check(np.array_equal(table[:, 2], f["cases/inputs/initial_state.velocity_3"][()]),
          "--list-cases gives the inputs the campaign ran")
    vz = table[:, 2]
    check(np.all((vz >= 3.0) & (vz <= 5.0)), "truncated normal within lo .. hi")
    check(set(table[:, 4]) <= {0.0, 4.0, 8.0}, "discrete values only")
    k = int(f["probability/n_success"][()])
    n = int(f["probability/n_evaluated"][()])
    lo, hi = wilson(k, n)
    check(n == 6 and k == int(f["cases/success"][()].sum()), "probability counts every case")
    check(abs(f["probability/ci95_low"][()] - lo) < 1e-12 and abs(f["probability/ci95_high"][()] - hi) < 1e-12,
          f"Wilson interval [{lo:.4f}, {hi:.4f}]")
    check(abs(f.attrs["p_success"] - k / n) < 1e-15, "p_success attribute")
    # every success verdict follows the criteria
    crit_margin = f["criteria/min_stroke_margin"][()]
    # (a success must have come to rest: outcome 2; issue 28)
    ok = ((f["cases/tipped_over"][()] == 0) & (f["cases/min_stroke_margin"][()] >= crit_margin)
          & (f["cases/peak_overload"][()] <= f["criteria/max_overload"][()])
          & (f["cases/min_body_clearance"][()] >= f["criteria/min_body_clearance"][()])
          & (f["cases/outcome"][()] == 2))
    check(np.array_equal(ok.astype(int), f["cases/success"][()]), "success = criteria of &criteria")
    # which criteria failed, per case and counted per criterion (stdout's last result line)
    names = [x.decode() for x in f["probability/failure_criterion"][()]]
    check(names == ["tipped_over", "stroke_margin", "overload", "body_clearance", "not_at_rest", "no_result",
                     "no_touchdown", "tipover_margin", "friction_ratio"], "failure criteria named in bit order")
    fc = f["cases/failed_criteria"][()]
    expect_fc = (np.where(f["cases/tipped_over"][()] == 1, 1, 0)
                 + np.where(f["cases/min_stroke_margin"][()] < crit_margin, 2, 0)
                 + np.where(f["cases/peak_overload"][()] > f["criteria/max_overload"][()], 4, 0)
                 + np.where(f["cases/min_body_clearance"][()] < f["criteria/min_body_clearance"][()], 8, 0)
                 + np.where((f["cases/outcome"][()] != 2) & (f["cases/tipped_over"][()] == 0), 16, 0))
    check(np.array_equal(fc, expect_fc), f"failed_criteria bits {list(fc)} from the metrics")
    per_case = [x.decode().strip() for x in f["cases/failed_criteria_names"][()]]
    bits = tuple(1 << k for k in range(9))
    check(per_case == [",".join(nm for b, nm in zip(bits, names) if v & b) for v in fc],
          f"failed_criteria_names {per_case} spell the bits")
    counts = f["probability/failure_count"][()]
    check(list(counts) == [int(np.sum((fc & b) != 0)) for b in bits],
          f"failure_count {list(counts)} per criterion")
    check(int(np.sum(f["cases/success"][()] == 0)) > 0, "the sample has failed cases to count")
    p = env.serial("mc.nml", "--case", "1:6", "-o", "all6.h5")
    case_lines = p.stdout.splitlines()
    p = env.serial("--merge", "merged6.h5", "all6.h5")
    lines = [ln for ln in p.stdout.splitlines() if ln.strip()]
    want = "  failures per criterion: " + ", ".join(f"{nm} {c}" for nm, c in zip(names, counts))
    check(lines[-1] == want, f"last line counts failures per criterion: {lines[-1]!r}")
    p = env.mpi(2, "mc.nml", "-o", "mc_again.h5", "-q")
    mpi_lines = [ln for ln in p.stdout.splitlines() if ln.strip()]
    check(mpi_lines[-1] == want, f"the MPI run's last line is the same count: {mpi_lines[-1]!r}")
    lines = case_lines
    fail_lines = [ln for ln in lines if "FAILURE" in ln]
    check(len(fail_lines) == int(np.sum(fc != 0)) and all("FAILURE (" in ln for ln in fail_lines),
          "every FAILURE line names its criteria")


def test_resume(env):
    """A campaign stopped after 2 rows (and once more with a torn journal line) and resumed
    equals an uninterrupted one."""
    env.mpi(2, "mc.nml", "-o", "full.h5")
    env.mpi(2, "mc.nml", "-o", "part.h5", "--stop-after", "2", expect=5)
    check(os.path.exists(env.path("part.h5.journal")), "journal kept after the stop")
    env.mpi(2, "mc.nml", "-o", "part.h5", expect=1)   # no --resume: refuses to overwrite
    env.mpi(2, "mc.nml", "-o", "part.h5", "--resume", "--stop-after", "1", expect=5)
    # a kill in the middle of a write: torn last line, and the summary checkpoint lost
    with open(env.path("part.h5.journal")) as j:
        line = j.read().splitlines()[1]
    with open(env.path("part.h5.journal"), "a") as j:
        j.write(line[:len(line) // 2])
    os.remove(env.path("part.h5"))
    p = env.mpi(2, "mc.nml", "-o", "part.h5", "--resume")
    check("3 of 6 cases done" in p.stderr and "ignored 1 incomplete journal line" in p.stderr,
          "resume found 3 finished cases and the torn line")
    check(not os.path.exists(env.path("part.h5.journal")), "journal removed when complete")
    env.same("full.h5", "part.h5")
    # resuming a finished campaign runs nothing and changes nothing
    env.mpi(1, "mc.nml", "-o", "part.h5", "--resume")
    env.same("full.h5", "part.h5")


def test_failing(env):
    """Invalid input (case 2) and a failed run (case 3) are rows; the campaign goes on."""
    env.mpi(2, "fail.nml")
    f = h5py.File(env.path("fail.h5"), "r")
    status = list(f["cases/status"][()])
    check(status == [0, 2, 3, 0], f"statuses {status} = [0, 2, 3, 0]")
    msg = [m.decode() for m in f["cases/error_message"][()]]
    check("&terrain: slope(1) = 75.0 deg is invalid" in msg[1], "case 2 message names group/variable/value")
    check("time step is too large" in msg[2], "case 3 message from the simulation")
    check(msg[0] == "" and msg[3] == "", "no message for good cases")
    check(all(np.isnan(f["cases/peak_overload"][()][1:3])), "no metrics for failed cases")
    check(int(f["probability/n_excluded"][()]) == 2 and int(f["probability/n_evaluated"][()]) == 2,
          "failed_runs = 'exclude' leaves them out of P")
    check(list(f["cases/failed_criteria"][()][1:3]) == [32, 32], "failed_criteria bit 32 = no result")
    check([x.decode().strip() for x in f["cases/failed_criteria_names"][()]][1:3] == ["no_result"] * 2,
          "failed_criteria_names: no_result")
    check(int(f["probability/failure_count"][()][5]) == 2, "failure_count counts the two cases without a result")


def test_case_merge(env):
    """--case K (serial, as in a job array) + --merge equals the MPI run."""
    env.mpi(2, "mc.nml", "-o", "mpi.h5")
    env.serial("mc.nml", "--case", "1:2", "-q")
    env.serial("mc.nml", "--case", "3", "-q")
    env.serial("mc.nml", "--case", "4", "-q", "-o", "part4.h5")
    p = env.serial("--merge", "partial.h5", "mc.cases000001-000002.h5", "mc.case000003.h5", expect=5)
    check("3 case(s) missing" in p.stderr, "incomplete merge reports the missing cases")
    env.serial("mc.nml", "--case", "5:6", "-q")
    env.serial("--merge", "merged.h5", "partial.h5", "mc.cases000001-000002.h5", "part4.h5",
               "mc.cases000005-000006.h5")
    env.same("mpi.h5", "merged.h5")
    env.serial("grid.nml", "--case", "1", "-q", "-o", "g1.h5")
    p = env.serial("--merge", "x.h5", "mpi.h5", "g1.h5", expect=2)
    check("belongs to another campaign" in p.stderr and not os.path.exists(env.path("x.h5")),
          "files of another campaign are refused")
    env.serial("mc.nml", "--case", "7", expect=1)
    # --history: re-run one case with its full time history, as landyn would (issue 24)
    p = env.serial("mc.nml", "--case", "4", "--history", "-q", "-o", "again4.h5")
    check("time history of case 4 written to again4_case000004.h5" in p.stdout
          and os.path.isfile(env.path("again4_case000004.h5")), "--case 4 --history writes case 4's time history")
    with h5py.File(env.path("again4_case000004.h5"), "r") as f, h5py.File(env.path("mpi.h5"), "r") as m:
        k = list(m["cases/case_id"][()]).index(4)
        check(f["summary/peak_overload"][()] == m["cases/peak_overload"][k],
              "the re-run's history has the campaign row's peak overload")
    env.serial("mc.nml", "--history", expect=1)


def test_bad_deck(env):
    """Every problem of a bad deck is reported with group/variable/value; exit 2; no file."""
    p = env.mpi(2, "bad.nml", expect=2)
    for text in ("bad.nml:8: &campaign: unknown variable 'sead'", "did you mean 'seed'",
                 "&campaign: n_samples = 0 is invalid",
                 "name = 'initial_state%velocity(4)' is invalid", "did you mean 'slope'",
                 "'friction%mu_dynamic': lo = 0.5, hi = 0.3 is invalid",
                 "gears%n_gears cannot be varied", "distribution = 'gaussian' is invalid",
                 "&criteria: max_overload = -1 g is invalid", "failed_runs = 'ignore' is invalid",
                 "9 error(s) in the campaign"):
        check(text in p.stderr, f"reports: {text}")
    check(not any(n.startswith("bad.h5") for n in os.listdir(env.dir)), "no output file")
    # a bad base deck and a bad case list are reported the same way
    with open(env.path("badbase.nml"), "w") as f:
        f.write("&simulation dt = -1.0, t_end = 0.3 /\n&terain slope = 4*0.0 /\n")
    with open(env.path("bad2.nml"), "w") as f:
        f.write("&campaign base_deck = 'badbase.nml', mode = 'list', list_file = 'bad.csv' /\n")
    with open(env.path("bad.csv"), "w") as f:
        f.write("initial_state%velocity(1), terrain%slope\n0.5, 1.0\nfast, 2.0\n")
    p = env.serial("bad2.nml", "--check", expect=2)
    for text in ("unknown namelist group '&terain'", "&simulation: dt", "base_deck = 'badbase.nml' has",
                 "column 2 'terrain%slope' is not a campaign input", "'fast' is not a finite number"):
        check(text in p.stderr, f"reports: {text}")
    p = env.serial("missing.nml", expect=2)
    check("cannot read the campaign deck" in p.stderr, "unreadable deck")
    # an empty base deck is the defaults (issue 10, item 1: it crashed landyn_batch), on 2 ranks too
    open(env.path("empty.nml"), "w").close()
    with open(env.path("e2.nml"), "w") as f:
        f.write("&campaign base_deck = 'empty.nml', mode = 'grid' /\n"
                "&parameter name = 'simulation%t_end', values = 0.005, 0.006, 0.007 /\n")
    env.mpi(2, "e2.nml", "-o", "e2.h5", "-q")
    left = sorted(n for n in os.listdir(env.dir) if n.startswith("e2.h5"))
    check(left == ["e2.h5"], f"2 ranks on an empty base deck: summary written, no journal left ({left})")
    with h5py.File(env.path("e2.h5"), "r") as f:
        check(len(f["cases/case_id"][()]) == 3, "all three cases recorded")


def test_time_account(env):
    """The time accounts printed before the result (issue 12) add up and count every case and step."""
    import re
    for ranks, extra in ((1, []), (2, []), (3, ["--dedicated-master"])):
        out = f"acct_np{ranks}.h5"
        p = env.mpi(ranks, "mc.nml", "-o", out, "-q", "--verbose", *extra)
        check("time account" not in p.stdout and "book_cpu" not in p.stdout,
              f"{ranks} rank(s): the time account is not in the result on stdout")
        m = re.search(r"time account \[s\] \(rank 0 \| all ranks\): (.*) \| (.*)", p.stderr)
        check(m is not None, f"{ranks} rank(s): time account printed")
        r0, tot = ({k: float(v) for k, v in re.findall(r"(\w+)=([-+0-9.Ee]+)", g)} for g in m.groups())
        f = h5py.File(env.path(out), "r")
        n = len(f["cases/case_id"])
        check(tot["cases"] == n and r0["rows"] == n, f"{ranks} rank(s): every case run once and recorded once")
        check(tot["steps"] == int(f["cases/n_steps"][()].sum()), f"{ranks} rank(s): steps = sum of /cases/n_steps")
        for name, acc in (("rank 0", r0), ("all ranks", tot)):
            parts = sum(acc[k] for k in ("input", "sim", "after", "wait", "comm", "record", "ckpt"))
            check((name == "rank 0" or acc["sim"] > 0.0) and parts <= acc["loop"] * 1.001 + 1e-3,
                  f"{ranks} rank(s), {name}: the parts ({parts:.4f} s) fit into the loop ({acc['loop']:.4f} s)")
        if "--dedicated-master" in extra:
            check(r0["cases"] == 0 and r0["sim"] == 0.0, "a dedicated rank 0 runs no case")
        check(re.search(r"rank time: simulating [0-9.]+ %", p.stderr) is not None, f"{ranks} rank(s): rank time line")
    env.same("acct_np1.h5", "acct_np3.h5")
    p = env.mpi(1, "mc.nml", "-o", "acct_quiet.h5", "-q")
    check("time account" not in p.stdout + p.stderr, "without --verbose: no time account")


TESTS = {"grid": test_grid, "monte_carlo": test_monte_carlo, "resume": test_resume, "failing": test_failing,
         "case_merge": test_case_merge, "bad_deck": test_bad_deck, "time_account": test_time_account}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("test", choices=sorted(TESTS))
    ap.add_argument("--batch", required=True, help="landyn_batch executable")
    ap.add_argument("--landyn", required=True, help="landyn executable")
    ap.add_argument("--mpiexec", required=True, help="launcher and its flags, comma-separated")
    ap.add_argument("--np-flag", default="-n", help="launcher flag for the number of ranks")
    ap.add_argument("--src", default=HERE, help="directory of the test decks")
    ap.add_argument("--workdir", required=True, help="scratch directory (emptied)")
    args = ap.parse_args()
    env = Env(args)
    print(f"campaign test {args.test}: {TESTS[args.test].__doc__.strip()}")
    try:
        TESTS[args.test](env)
    except (Failure, subprocess.TimeoutExpired) as exc:
        print(f"FAILED: {exc}")
        return 1
    print("PASSED")
    return 0


if __name__ == "__main__":
    sys.exit(main())
