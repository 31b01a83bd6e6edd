#!/usr/bin/env python3
"""Seeded fuzz test of landyn, landyn_study and landyn_batch (issue 10).

Usage: fuzz_tests.py --landyn EXE --study EXE [--batch EXE] [--seed S] [--n N] [--keep DIR]

N mutated decks per program (random.Random(seed): the same decks every time), each run in a
directory of its own. For every run it asserts:
  - no crash: no signal, no exit status >= 128, no Fortran run-time error or backtrace;
  - no hang: every run ends within its timeout;
  - the exit status is one of the program's documented statuses (docs/exit_status.md);
  - no file left on error: no <name>.partial or .journal ever, and no new file at all when the
    status says nothing was written (usage error, invalid input, file refused, run failed).
Mutants that pass --check are run for real when they are short (landyn: at most 4000 steps);
landyn_batch mutants are checked, and run with --case 1 (no MPI) when they pass.
A failing mutant is printed with its text, so it can be reproduced by hand.
"""
import argparse
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

CRASH_MARKS = ("Program received signal", "Fortran runtime error", "Backtrace for this error",
               "Floating-point exception", "Segmentation fault", "is not allocated", "Error termination")

# documented exit statuses (docs/exit_status.md); deck-driven runs never see 1 (usage) except '' names
# 7: no touchdown (a mutated velocity or clearance), with a result file (docs/exit_status.md)
ALLOWED = {"landyn": {0, 2, 3, 4, 6, 7}, "study": {0, 2, 3, 4, 6, 7}, "batch": {0, 2, 3, 4, 5}}
# statuses after which no new file may exist
NOTHING_WRITTEN = {"landyn": {1, 2, 4}, "study": {1, 2, 4}, "batch": {1, 2, 4}}

EXTREMES = ["nan", "inf", "-inf", "1e400", "-1e400", "1e308", "-1e308", "1e-300", "0", "-1", "1e29", "-1e29",
            "2147483648", "-0.0", "1e-12", "3*1e308", "huge", ".true.", "'x'", "1.0e-9", "5.0", "10.0", "0.44",
            "-0.44", "1e31", "1e30", "4*0", "4*10.0", "1,2,3,4,5,6,7,8,9", ""]
TOKENS = ["&", "/", "'", '"', "!", "=", ",", "\r", "\udcff", "\ufeff", "&end", "&simulation", "*", "(", ")", "%",
          " dt ", " bogus = 1 ", "\t", "\n", "&variant", "&study", "&campaign", "&parameter", " ; ", " # ",
          "\x00", "0.5 0.7", "1.0;2.0"]

LANDYN_DECK = """! fuzz base deck: a short landing
&simulation title = 'fuzz', t_end = 0.002, dt = 5.0e-6, tipover_angle = 60.0 /
&lander mass = 1.6e4, izz = 8.17e4 /
&gears rotation = 0.0, 90.0, 180.0, 270.0 /
&primary_strut stage_force = 2.0e4, 3.0e4, stage_end = 0.3, 0.5 /
&secondary_strut inner_mass = 4.0 /
&contact law = 'hertz', exponent = 1.5 /
&friction mu_static = 0.3 /
&terrain slope = 4*0.0 /
&initial_state velocity = 0.5, 0.0, 4.0, position = 0.0, 0.0, -0.05 /
&output interval = 1.0e-4 /
"""

BASE_DECK = "&simulation t_end = 0.002, dt = 5.0e-6 /\n&output interval = 1.0e-3 /\n"

STUDY_DECK = """! fuzz study
&study title = 'fuzz', base_deck = 'lc.nml', case_label = 'LC', output = 'st.h5', csv = 'st.csv',
  measure_case = 1, measure_gear = 1, measure_strut = 1 /
&variant label = 'base' /
&variant label = 'hertz', set = "contact%law = 'hertz'" /
"""

CAMPAIGN_DECKS = ["""! fuzz grid
&campaign title = 'fuzz', base_deck = 'lc.nml', mode = 'grid', summary_file = 'c.h5', checkpoint_interval = 0.0 /
&parameter name = 'initial_state%velocity(1)', values = 0.0, 1.0 /
&parameter name = 'terrain%slope(:)', start = 0.0, stop = 8.0, count = 2 /
&criteria min_stroke_margin = 0.0, max_overload = 10.0 /
""", """! fuzz Monte Carlo
&campaign base_deck = 'lc.nml', mode = 'monte_carlo', n_samples = 3, seed = 7 /
&parameter name = 'initial_state%velocity(3)', distribution = 'normal', mean = 4.0, sd = 0.3, lo = 3.0, hi = 5.0 /
&parameter name = 'friction%mu_static', distribution = 'discrete', values = 0.2, 0.4, weights = 1.0, 3.0 /
""", """! fuzz list
&campaign base_deck = 'lc.nml', mode = 'list', list_file = 'cases.csv' /
"""]
CASES_CSV = "initial_state%velocity(1), terrain%slope(:)\n0.5, 0.0\n1.0, 4.0\n"

NUMBER = re.compile(r"(?<![A-Za-z_%(])[-+]?\d+\.?\d*(?:[eEdD][-+]?\d+)?")


def mutate(text, rng):
    """One to three random edits of a deck's text."""
    for _ in range(rng.randint(1, 3)):
        op = rng.randrange(9)
        lines = text.split("\n")
        if op <= 2:   # a number made extreme (the most productive edit)
            nums = list(NUMBER.finditer(text))
            if nums:
                m = rng.choice(nums)
                text = text[:m.start()] + rng.choice(EXTREMES) + text[m.end():]
        elif op == 3:
            p = rng.randrange(len(text) + 1)
            text = text[:p] + text[p + rng.randint(1, 10):]
        elif op == 4:
            p = rng.randrange(len(text) + 1)
            text = text[:p] + rng.choice(TOKENS) + text[p:]
        elif op == 5 and lines:
            i = rng.randrange(len(lines))
            lines.insert(i, lines[i])
            text = "\n".join(lines)
        elif op == 6 and lines:
            del lines[rng.randrange(len(lines))]
            text = "\n".join(lines)
        elif op == 7:
            text = text[:rng.randrange(len(text) + 1)]
        else:
            text = rng.choice(["", " \n", "\r", text.replace("\n", "\r"), text.replace("\n", "\r\n")])
    return text


class Fuzzer:
    def __init__(self, args):
        self.args = args
        self.failures = []
        self.runs = 0
        self.stats = {}

    def fail(self, prog, what, deck_files):
        self.failures.append(what)
        print("FAIL [%s]: %s" % (prog, what))
        for name, text in deck_files.items():
            print("  --- %s ---\n%s" % (name, text))

    def run(self, prog, exe, args, cwd, deck_files, timeout=60):
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        self.runs += 1
        try:
            p = subprocess.run([exe] + args, cwd=cwd, capture_output=True, timeout=timeout, env=env)
        except subprocess.TimeoutExpired:
            self.fail(prog, "hang: %s %s did not end within %d s" % (os.path.basename(exe), " ".join(args), timeout),
                      deck_files)
            return None, ""
        err = p.stderr.decode(errors="replace")
        rc = p.returncode
        self.stats.setdefault(prog, {}).setdefault(rc, 0)
        self.stats[prog][rc] += 1
        if rc < 0 or rc >= 128 or any(m in err for m in CRASH_MARKS):
            self.fail(prog, "crash: %s %s -> exit %d: %s" % (os.path.basename(exe), " ".join(args), rc, err[-500:]),
                      deck_files)
        elif rc not in ALLOWED[prog]:
            self.fail(prog, "exit status %d not documented for %s (%s): %s" % (rc, prog, " ".join(args), err[-300:]),
                      deck_files)
        return rc, p.stdout.decode(errors="replace")

    def check_files(self, prog, rc, cwd, inputs, deck_files):
        files = set(os.listdir(cwd))
        left = [f for f in files if f.endswith(".partial") or f.endswith(".journal")]
        if left:
            self.fail(prog, "temporary files left after exit %s: %s" % (rc, left), deck_files)
        if rc in NOTHING_WRITTEN[prog]:
            new = sorted(files - set(inputs))
            if new:
                self.fail(prog, "exit %d but files were written: %s" % (rc, new), deck_files)

    def case_dir(self, root, files):
        d = tempfile.mkdtemp(dir=root)
        for name, text in files.items():
            with open(os.path.join(d, name), "wb") as f:
                f.write(text.encode("utf-8", errors="surrogateescape"))
        return d

    # ------------------------------------------------------------------ one program each
    def fuzz_landyn(self, rng, root):
        exe = self.args.landyn
        for _ in range(self.args.n):
            files = {"deck.nml": mutate(LANDYN_DECK, rng)}
            d = self.case_dir(root, files)
            rc, out = self.run("landyn", exe, ["--check", "deck.nml"], d, files)
            self.check_files("landyn", rc, d, files, files)
            if rc == 0 and self.short_run(out):
                rc, out = self.run("landyn", exe, ["-q", "deck.nml", "-o", "r.h5"], d, files)
                self.check_files("landyn", rc, d, list(files) + (["r.h5"] if rc in (0, 6, 7) else []), files)
            shutil.rmtree(d)

    @staticmethod
    def short_run(resolved):
        """At most 4000 steps (the fuzz test stays fast; the step bound itself is tested on --check)."""
        t = re.search(r"^\s*t_end = (\S+)", resolved, re.M)
        dt = re.search(r"^\s*dt = (\S+)", resolved, re.M)
        try:
            return float(t.group(1)) / float(dt.group(1)) <= 4000
        except (AttributeError, ValueError, ZeroDivisionError):
            return False

    def fuzz_study(self, rng, root):
        exe = self.args.study
        for _ in range(self.args.n):
            files = {"s.nml": mutate(STUDY_DECK, rng), "lc.nml": BASE_DECK}
            if rng.random() < 0.2:
                files["lc.nml"] = mutate(BASE_DECK, rng)
            d = self.case_dir(root, files)
            rc, out = self.run("study", exe, ["--check", "s.nml"], d, files)
            self.check_files("study", rc, d, files, files)
            if rc == 0 and rng.random() < 0.3 and self.short_run_study(files["lc.nml"]):
                rc, out = self.run("study", exe, ["-q", "s.nml"], d, files)
                written = [f for f in os.listdir(d) if f not in files]
                self.check_files("study", rc, d, list(files) + (written if rc in (0, 3, 6, 7) else []), files)
            shutil.rmtree(d)

    @staticmethod
    def short_run_study(base):
        return base == BASE_DECK

    def fuzz_batch(self, rng, root):
        exe = self.args.batch
        for _ in range(self.args.n):
            deck = rng.choice(CAMPAIGN_DECKS)
            files = {"c.nml": deck, "lc.nml": BASE_DECK, "cases.csv": CASES_CSV}
            target = rng.choice(["c.nml", "c.nml", "c.nml", "lc.nml", "cases.csv"])
            files[target] = mutate(files[target], rng)
            d = self.case_dir(root, files)
            rc, out = self.run("batch", exe, ["--check", "c.nml"], d, files)
            self.check_files("batch", rc, d, files, files)
            if rc == 0 and rng.random() < 0.3 and files["lc.nml"] == BASE_DECK:
                rc, out = self.run("batch", exe, ["c.nml", "--case", "1", "-q", "-o", "case.h5"], d, files)
                written = ["case.h5"] if rc == 0 else []
                self.check_files("batch", rc, d, list(files) + written + [f for f in os.listdir(d)
                                                                         if f.startswith("c_case")], files)
            shutil.rmtree(d)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--landyn", required=True)
    ap.add_argument("--study", required=True)
    ap.add_argument("--batch", default="")
    ap.add_argument("--seed", type=int, default=10)
    ap.add_argument("--n", type=int, default=300, help="mutated decks per program")
    a = ap.parse_args()
    for k in ("landyn", "study", "batch"):
        if getattr(a, k):
            setattr(a, k, os.path.abspath(getattr(a, k)))
    fz = Fuzzer(a)
    t0 = time.time()
    with tempfile.TemporaryDirectory() as root:
        progs = [("landyn", fz.fuzz_landyn), ("study", fz.fuzz_study)]
        if a.batch:
            progs.append(("batch", fz.fuzz_batch))
        for i, (name, fn) in enumerate(progs):
            t1 = time.time()
            fn(random.Random(a.seed * 1000 + i), root)
            print("%s: %d mutated decks in %.1f s, exit statuses %s" % (name, a.n, time.time() - t1,
                                                                        dict(sorted(fz.stats.get(name, {}).items()))))
    print("%d runs in %.1f s" % (fz.runs, time.time() - t0))
    if fz.failures:
        print("%d failure(s)" % len(fz.failures))
        sys.exit(1)
    print("no crash, no hang, documented exit statuses only, no file left on error")


if __name__ == "__main__":
    main()
