#!/usr/bin/env python3
"""Campaign scaling benchmark (issue 12, "Campaigns that scale"; docs/campaign.md, "Scaling").

  bench_campaign_scaling.py --batch build/release/landyn_batch --store build/release/bench/bench_campaign_store
                            --src . [--cases 200] [--repeats 2] [--mpiexec=mpiexec,--oversubscribe] [--np-flag=-n]
                            [--trivial-cases 3000] [--ckpt-rows 1000,10000,100000,1000000]
                            [--merge-files 1000] [--merge-rows 1000] [--skip PART,...]

Parts (each prints its figures; --skip efficiency,capacity,store,merge leaves parts out):

 efficiency  the Monte Carlo campaign bench/campaign_mc.nml with n_samples = --cases on 1 and on
             2 ranks, interleaved and repeated (1, 2, 2, 1, ...), so that a change of machine load
             hits both alike. Per run: wall time of the whole mpirun, cases per core-hour
             (cases x 3600 / (wall x ranks)), and landyn_batch's own time account (fraction of each
             rank's time in run_simulation, per-case time outside it). Speed-up = 1-rank wall /
             2-rank wall (median over the repeats); efficiency = speed-up / 2. The summaries of the
             1- and 2-rank runs must be identical row for row (tests/campaign/compare_summaries.py).
 capacity    trivial cases (the same campaign with t_end = 10 dt): 1 rank (per-case cost outside the
             time loop: case input, run_simulation's own set-up, metrics) and 8 and 16 ranks with a
             dedicated rank 0 on this machine (oversubscribed): rank 0's cost per row and the rows
             it can accept per second (its hand-out capacity).
 store       checkpoint (summary-file rewrite) and journal-line costs against the number of rows
             (bench_campaign_store checkpoint, synthetic rows of the campaign's shape); a linear fit.
 merge       --merge of --merge-files part files of --merge-rows rows each (bench_campaign_store
             parts): wall time and peak memory (maximum resident set) of landyn_batch --merge.

At the end the scaling model of docs/campaign.md is evaluated with the measured inputs: predicted
efficiency of a 10^6-case campaign on 64, 1,024 and 8,192 ranks for today's case cost and for a
5x cheaper case. The machine load (os.getloadavg) is printed before and after each part.
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def load():
    a, b, c = os.getloadavg()
    return "load average %.2f %.2f %.2f on %d cores" % (a, b, c, os.cpu_count() or 0)


def parse_account(text):
    """landyn_batch's time-account line -> (rank0 dict, all-ranks dict)."""
    m = re.search(r"time account \[s\] \(rank 0 \| all ranks\): (.*) \| (.*)", text)
    if not m:
        raise SystemExit("no time account in landyn_batch's output:\n" + text)

    def d(s):
        return {k: float(v) for k, v in re.findall(r"(\w+)=([-+0-9.Ee]+)", s)}
    return d(m.group(1)), d(m.group(2))


class Runner:
    def __init__(self, a, workdir):
        self.a = a
        self.dir = workdir
        self.env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                        OMPI_MCA_rmaps_base_oversubscribe="1")
        self.launcher = [x for x in a.mpiexec.split(",") if x]

    def batch(self, ranks, deck, out, extra=()):
        cmd = (self.launcher + [self.a.np_flag, str(ranks), self.a.batch, deck, "-q", "--verbose", "--force", "-o", out]
               + list(extra))
        t0 = time.perf_counter()
        p = subprocess.run(cmd, cwd=self.dir, env=self.env, capture_output=True, text=True)
        wall = time.perf_counter() - t0
        if p.returncode != 0:
            print(p.stdout, p.stderr)
            raise SystemExit("landyn_batch failed (exit status %d): %s" % (p.returncode, " ".join(cmd)))
        r0, tot = parse_account(p.stderr)      # the time account is on stderr with --verbose
        return wall, r0, tot, p.stderr


def make_decks(a, d, cases, trivial_cases):
    for f in ("campaign_base.nml", "campaign_mc.nml"):
        shutil.copy(os.path.join(a.src, "bench", f), d)
    text = open(os.path.join(d, "campaign_mc.nml")).read()
    text, n = re.subn(r"(?m)^(\s*n_samples\s*=\s*)\d+", lambda m: m.group(1) + str(cases), text)
    assert n == 1, "campaign_mc.nml must set n_samples once"
    open(os.path.join(d, "scaling.nml"), "w").write(text)
    base = open(os.path.join(d, "campaign_base.nml")).read()
    dt = float(re.search(r"(?m)^\s*dt\s*=\s*([0-9.eE+-]+)", base).group(1))
    # trivial cases: the same campaign, 10 time steps per case (constant overrides)
    t = re.sub(r"(?m)^(\s*n_samples\s*=\s*)\d+", lambda m: m.group(1) + str(trivial_cases), open(
        os.path.join(d, "campaign_mc.nml")).read())
    t += ("\n&parameter name = 'simulation%%t_end', distribution = 'discrete', values = %.17g /\n"
          "&parameter name = 'output%%interval', distribution = 'discrete', values = %.17g /\n") % (10 * dt, dt)
    open(os.path.join(d, "trivial.nml"), "w").write(t)
    return dt


def part_efficiency(a, run, res):
    print("\n== efficiency: %d cases of bench/campaign_mc.nml on 1 and 2 ranks, interleaved, %d repeat(s)"
          % (a.cases, a.repeats))
    print("   before: " + load())
    rows = []
    walls = {1: [], 2: []}
    accts = {1: [], 2: []}
    for r in range(a.repeats):
        for ranks in ((1, 2) if r % 2 == 0 else (2, 1)):
            out = "eff_%d_%d.h5" % (ranks, r)
            wall, r0, tot, out_text = run.batch(ranks, "scaling.nml", out)
            if ranks == 2:
                last2 = out_text
            walls[ranks].append(wall)
            accts[ranks].append((r0, tot))
            rate = a.cases * 3600.0 / (wall * ranks)
            sim = tot["sim"] / tot["loop"]
            print("   run %d, %d rank(s): wall %7.2f s (driver loop %7.2f s), %7.0f cases per core-hour, "
                  "simulating %.2f %% of rank time, waiting %.2f %% [%s]"
                  % (r + 1, ranks, wall, r0["loop"], rate, 100 * sim, 100 * tot["wait"] / tot["loop"], load()))
            rows.append((ranks, wall))
    # bit-identical results across rank counts
    sys.path.insert(0, os.path.join(a.src, "tests", "campaign"))
    import compare_summaries  # noqa: E402
    saved = sys.argv
    sys.argv = ["compare_summaries.py", os.path.join(run.dir, "eff_1_0.h5"), os.path.join(run.dir, "eff_2_0.h5")]
    try:
        rc = compare_summaries.main()
    except SystemExit as e:
        rc = e.code
    sys.argv = saved
    same = rc in (0, None)
    w1 = statistics.median(walls[1])
    w2 = statistics.median(walls[2])
    speedup = w1 / w2
    r1 = a.cases * 3600.0 / w1
    r2 = a.cases * 3600.0 / (2 * w2)
    # per-case costs from the 1-rank runs (all ranks' accounts)
    tots = [t for _, t in accts[1]]
    n = sum(t["cases"] for t in tots)
    c_sim = sum(t["sim"] for t in tots) / n
    c_in = sum(t["input"] for t in tots) / n
    c_after = sum(t["after"] for t in tots) / n
    steps = sum(t["steps"] for t in tots) / n
    r0_row = sum(r0["comm"] + r0["record"] for r0, _ in accts[1]) / sum(r0["rows"] for r0, _ in accts[1])
    startup = statistics.median([w - r0["loop"] for w, (r0, _) in zip(walls[1] + walls[2], accts[1] + accts[2])])
    sim2 = [t["sim"] / t["loop"] for _, t in accts[2]]
    sim2_r0 = [r0["sim"] / r0["loop"] for r0, _ in accts[2]]
    print("   1 rank : %8.0f cases per core-hour (median wall %.2f s)" % (r1, w1))
    print("   2 ranks: %8.0f cases per core-hour (median wall %.2f s)" % (r2, w2))
    print("   speed-up 2 ranks / 1 rank: %.3f x (target >= 1.9 x: %s); efficiency %.1f %%"
          % (speedup, "MET" if speedup >= 1.9 else "MISSED", 50.0 * speedup))
    print("   2 ranks: simulating %.2f %% of all ranks' time (rank 0: %.2f %%), median over repeats"
          % (100 * statistics.median(sim2), 100 * statistics.median(sim2_r0)))
    print("   per case: run_simulation %.4f s (%.0f steps, %.2f us per step); outside it %.0f us "
          "(case input %.0f us, metrics %.0f us) = %.3f %% of the case; rank 0 per row %.0f us; "
          "start-up and end of mpirun %.2f s"
          % (c_sim, steps, 1e6 * c_sim / steps, 1e6 * (c_in + c_after), 1e6 * c_in, 1e6 * c_after,
             100 * (c_in + c_after) / (c_sim + c_in + c_after), 1e6 * r0_row, startup))
    print("   results of 1 and 2 ranks identical row for row: %s" % ("yes" if same else "NO"))
    print("   landyn_batch's report of the last 2-rank run:")
    for line in last2.splitlines():
        if re.match(r"\s*(landyn_batch: this run|rank time|per case):", line):
            print("   " + line)
    print("   after: " + load())
    res.update(c_sim=c_sim, c_in=c_in, c_after=c_after, steps=steps, step=c_sim / steps, speedup=speedup,
               startup=startup, same=same)


def part_capacity(a, run, res):
    print("\n== capacity: %d trivial cases (10 time steps each)" % a.trivial_cases)
    print("   before: " + load())
    wall, r0, tot, _ = run.batch(1, "trivial.nml", "triv_1.h5")
    n = tot["cases"]
    sim_setup = tot["sim"] / n - 10 * res.get("step", 0.0)
    print("   1 rank: %.0f us per trivial case in run_case: input %.0f us, run_simulation %.0f us (of which "
          "set-up %.0f us, 10 steps %.0f us), metrics %.0f us; rank 0 per row %.0f us"
          % (1e6 * (tot["input"] + tot["sim"] + tot["after"]) / n, 1e6 * tot["input"] / n, 1e6 * tot["sim"] / n,
             1e6 * sim_setup, 1e6 * 10 * res.get("step", 0.0), 1e6 * tot["after"] / n,
             1e6 * (r0["comm"] + r0["record"]) / r0["rows"]))
    res.update(triv_in=tot["input"] / n, triv_after=tot["after"] / n, sim_setup=max(sim_setup, 0.0))
    caps = []
    for ranks in a.capacity_ranks:
        wall, r0, tot, _ = run.batch(ranks, "trivial.nml", "triv_%d.h5" % ranks, ["--dedicated-master"])
        h_wall = (r0["comm"] + r0["record"]) / r0["rows"]
        h = r0["book_cpu"] / r0["rows"]
        busy = 1.0 - r0["wait"] / r0["loop"]
        print("   %2d ranks, dedicated rank 0: %.0f rows in %.2f s = %.0f rows/s observed (the cores are shared by "
              "all ranks); rank 0 per row %.1f us CPU (%.1f us wall: messages %.1f, journal and table %.1f) -> "
              "capacity 1/h = %.0f rows/s [%s]"
              % (ranks, r0["rows"], r0["loop"], r0["rows"] / r0["loop"], 1e6 * h, 1e6 * h_wall,
                 1e6 * r0["comm"] / r0["rows"], 1e6 * r0["record"] / r0["rows"], 1.0 / h, load()))
        caps.append(h)
    res.update(h=max(caps))
    print("   after: " + load())


def part_store(a, run, res):
    print("\n== store: checkpoint and journal costs, rows %s (synthetic)" % a.ckpt_rows)
    print("   before: " + load())
    p = subprocess.run([a.store, "checkpoint", a.ckpt_rows], cwd=run.dir, capture_output=True, text=True)
    if p.returncode != 0:
        print(p.stdout, p.stderr)
        raise SystemExit("bench_campaign_store failed")
    pts = []
    for line in p.stdout.splitlines():
        d = {k: float(v) for k, v in re.findall(r"(\w+)=\s*([-+0-9.Ee]+)", line)}
        pts.append(d)
        print("   %8d rows: checkpoint %8.3f s (%.2f us/row), read back %8.3f s, journal line %.1f us "
              "(flushed each %.1f us)" % (d["rows"], d["write_s"], 1e6 * d["write_s"] / d["rows"], d["read_s"],
                                          d["journal_line_us"], d["journal_line_flushed_us"]))
    # least-squares fit k(n) = k0 + k1 n
    xs = [d["rows"] for d in pts]
    ys = [d["write_s"] for d in pts]
    if len(xs) >= 2:
        mx = sum(xs) / len(xs)
        my = sum(ys) / len(ys)
        k1 = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
        k0 = max(my - k1 * mx, 0.0)
    else:
        k0, k1 = 0.0, ys[0] / xs[0]
    print("   fit: checkpoint(n) = %.4f s + %.3f us x n" % (k0, 1e6 * k1))
    res.update(k0=k0, k1=k1)
    print("   after: " + load())


def part_merge(a, run, res):
    print("\n== merge: %d part files of %d rows each" % (a.merge_files, a.merge_rows))
    print("   before: " + load())
    pdir = os.path.join(run.dir, "parts")
    os.makedirs(pdir, exist_ok=True)
    p = subprocess.run([a.store, "parts", pdir, str(a.merge_files), str(a.merge_rows)], capture_output=True, text=True)
    if p.returncode != 0:
        print(p.stdout, p.stderr)
        raise SystemExit("bench_campaign_store parts failed")
    print("   " + p.stdout.strip())
    files = sorted(os.path.join("parts", f) for f in os.listdir(pdir))
    t0 = time.perf_counter()
    proc = subprocess.Popen([a.batch, "--merge", "merged.h5"] + files, cwd=run.dir, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    _, status, ru = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    out = proc.stdout.read()
    err = proc.stderr.read()
    code = os.waitstatus_to_exitcode(status)
    if code != 0:
        print(out, err)
        raise SystemExit("landyn_batch --merge failed with exit status %d" % code)
    size = os.path.getsize(os.path.join(run.dir, "merged.h5"))
    print("   landyn_batch --merge: %.2f s wall, %.2f s CPU, peak memory %.0f MB, merged file %.0f MB "
          "(%.0f bytes/row in memory at peak) [%s]"
          % (wall, ru.ru_utime + ru.ru_stime, ru.ru_maxrss / 1024.0, size / 1e6,
             ru.ru_maxrss * 1024.0 / (a.merge_files * a.merge_rows), load()))
    print("   " + out.strip().splitlines()[0])
    res.update(merge_wall=wall, merge_rss=ru.ru_maxrss * 1024.0)


def model(res, a):
    """Efficiency of N cases on P ranks (docs/campaign.md, "Scaling")."""
    need = ("c_sim", "c_in", "c_after", "h", "k0", "k1")
    if not all(k in res for k in need):
        print("\n(scaling model left out: it needs the efficiency, capacity and store parts)")
        return
    print("\n== scaling model: 10^6 cases (docs/campaign.md, \"Scaling\"); inputs measured above")
    over = res["c_in"] + res["c_after"] + res.get("sim_setup", 0.0)
    h = res["h"]
    depth = 2
    print("   per-case overhead outside the time loop o = %.0f us (input, run_simulation set-up, metrics); rank 0 "
          "per row h = %.1f us; checkpoint k(n) = %.3f s + %.3f us n; start-up S = %.1f s (this machine)"
          % (1e6 * over, 1e6 * h, res["k0"], 1e6 * res["k1"], res.get("startup", 0.0)))
    N = 1.0e6
    for label, loop in (("today's case", res["c_sim"]), ("5x cheaper case", res["c_sim"] / 5.0)):
        c = loop + over
        print("   %s: time loop %.3f s + overhead %.0f us = %.4f s per case; rank 0 saturates at P* = c/h = %.0f "
              "workers" % (label, loop, 1e6 * over, c, c / h))
        for P in (64, 1024, 8192):
            E, parts = efficiency(N, P, loop, over, h, res["k0"], res["k1"], res.get("startup", 0.0), depth)
            print("     P = %5d: efficiency %5.1f %%  (%s)" % (P, 100 * E, parts))


def efficiency(N, P, loop, over, h, k0, k1, S, depth, ckpt_interval=60.0, factor=50.0):
    c = loop + over
    master_works = P <= 16
    workers = P if master_works else P - 1
    t_work = N * c / workers                       # the workers' share
    t_master = N * h                               # rank 0's bookkeeping, one row at a time
    k = k0 + k1 * N / 2                            # a checkpoint in the middle of the campaign
    cadence = max(ckpt_interval, factor * k)
    t_master *= 1.0 + k / cadence                  # rank 0's time spent in checkpoints
    # workers stall during a checkpoint once their queued ids run out
    stall = max(0.0, k - (depth - 1) * c) / cadence
    t_run = max(t_work * (1.0 + stall), t_master)
    tail = 0.5 * c                                  # the last cases end unevenly
    wall = S + t_run + tail
    E = N * loop / (P * wall)
    bound = "rank 0 bound" if t_master > t_work else "workers bound"
    return E, ("%s; run %.0f s, rank 0 busy %.0f %%, checkpoint %.1f s every %.0f s"
               % (bound, wall, 100 * min(1.0, t_master / t_run), k, cadence))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--batch", required=True, help="landyn_batch executable")
    ap.add_argument("--store", required=True, help="bench_campaign_store executable")
    ap.add_argument("--src", required=True, help="source tree")
    ap.add_argument("--cases", type=int, default=200, help="cases of the efficiency runs (default 200)")
    ap.add_argument("--repeats", type=int, default=2, help="repeats of the 1- and 2-rank runs (default 2)")
    ap.add_argument("--trivial-cases", type=int, default=3000, help="trivial cases of the capacity runs")
    ap.add_argument("--capacity-ranks", default="8,16", help="rank counts of the capacity runs")
    ap.add_argument("--ckpt-rows", default="1000,10000,100000,1000000", help="row counts of the checkpoint costs")
    ap.add_argument("--merge-files", type=int, default=1000)
    ap.add_argument("--merge-rows", type=int, default=1000)
    ap.add_argument("--skip", default="", help="parts left out: efficiency,capacity,store,merge")
    ap.add_argument("--mpiexec", default="mpiexec", help="launcher and its flags, comma-separated")
    ap.add_argument("--np-flag", default="-n", help="launcher flag for the number of ranks")
    ap.add_argument("--keep", help="keep the work directory here")
    a = ap.parse_args()
    a.capacity_ranks = [int(x) for x in a.capacity_ranks.split(",") if x]
    skip = set(x for x in a.skip.split(",") if x)
    print("LANDYN campaign scaling benchmark (bench/bench_campaign_scaling.py); " + load())
    res = {}
    d = a.keep or tempfile.mkdtemp(prefix="landyn_bench_scaling_")
    os.makedirs(d, exist_ok=True)
    try:
        dt = make_decks(a, d, a.cases, a.trivial_cases)
        print("deck bench/campaign_mc.nml (Monte Carlo, dt = %g s, 1 s simulated per case)" % dt)
        run = Runner(a, d)
        if "efficiency" not in skip:
            part_efficiency(a, run, res)
        if "capacity" not in skip:
            part_capacity(a, run, res)
        if "store" not in skip:
            part_store(a, run, res)
        if "merge" not in skip:
            part_merge(a, run, res)
        model(res, a)
    finally:
        if not a.keep:
            shutil.rmtree(d, ignore_errors=True)
    if "same" in res and not res["same"]:
        raise SystemExit("results differ between 1 and 2 ranks")


if __name__ == "__main__":
    main()
