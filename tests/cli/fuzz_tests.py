#!/usr/bin/env python3
"""Seeded fuzz test of landyn, landyn_study and landyn_batch (issue 10).

Usage: fuzz_tests.py --landyn EXE --study EXE [--batch EXE] [--post DIR] [--seed S] [--n N]

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

Issue 25 generators (seeded as well), after the mutated decks:
  - outputs that are links and special files: a stale <out>.partial that is a symbolic, hard or
    dangling link, an output that is a link, a fifo, /dev/null, a directory, a file that only begins
    with the HDF5 signature, blank names: the deck is never changed, nothing is written through a
    link, nothing is left behind;
  - a full output directory (a small tmpfs, when the machine lets us mount one): exit 0 or 4, the
    previous result kept, no .partial;
  - concurrent resumes of one campaign: never two writers (one is refused with exit 4), the summary
    complete;
  - study variants that change the model (gears%n_gears): the table has numbers or nan, never
    uninitialised values;
  - long lines (up to a million characters of commas, blanks, digits): read in linear time;
  - damaged HDF5 files for every post tool (--post): truncated, bytes flipped, a dataset made text
    or NaN, a group removed: one `error:` line and a documented status, never a traceback.
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

    # ------------------------------------------------------------------ issue 25 generators
    def deck_unchanged(self, prog, d, files, what):
        for name, text in files.items():
            p = os.path.join(d, name)
            if not os.path.isfile(p) or open(p, "rb").read() != text.encode("utf-8", errors="surrogateescape"):
                self.fail(prog, "%s: input %s was changed or replaced" % (what, name), files)

    def fuzz_special_outputs(self, rng, root):
        exe = self.args.landyn
        deck = "&simulation t_end = 0.002 /\n"
        kinds = ["symlink_partial", "hardlink_partial", "dangling_partial", "link_output", "fifo", "devnull",
                 "directory", "hdf5_signature", "blank", "padded"]
        for _ in range(max(10, self.args.n // 15)):
            kind = rng.choice(kinds)
            files = {"deck.nml": deck}
            d = self.case_dir(root, files)
            out = "o.h5"
            if kind == "symlink_partial":
                os.symlink("deck.nml", os.path.join(d, "o.h5.partial"))
            elif kind == "hardlink_partial":
                os.link(os.path.join(d, "deck.nml"), os.path.join(d, "o.h5.partial"))
            elif kind == "dangling_partial":
                os.symlink("nowhere", os.path.join(d, "o.h5.partial"))
            elif kind == "link_output":
                os.symlink("deck.nml", os.path.join(d, "o.h5"))
            elif kind == "fifo":
                os.mkfifo(os.path.join(d, "o.h5"))
            elif kind == "devnull":
                out = "/dev/null"
            elif kind == "directory":
                os.mkdir(os.path.join(d, "o.h5"))
            elif kind == "hdf5_signature":
                with open(os.path.join(d, "o.h5"), "wb") as f:
                    f.write(b"\x89HDF\r\n\x1a\n" + bytes(rng.randrange(256) for _ in range(rng.randint(0, 40))))
            elif kind == "blank":
                out = " " * rng.randint(1, 3)
            else:
                out = rng.choice([" o.h5", "o.h5 ", " o.h5 "])
            before = {f: os.lstat(os.path.join(d, f)) for f in os.listdir(d)}
            sig = open(os.path.join(d, "o.h5"), "rb").read() if kind == "hdf5_signature" else None
            rc, _ = self.run("landyn", exe, ["-q", "deck.nml", "-o", out], d, files)
            self.deck_unchanged("landyn", d, files, "output %s (%r)" % (kind, out))
            left = [f for f in os.listdir(d) if f.endswith(".partial")]
            if left:
                self.fail("landyn", "output %s: .partial left: %s" % (kind, left), files)
            if kind in ("symlink_partial", "hardlink_partial", "dangling_partial") and rc != 0:
                self.fail("landyn", "output %s: a stale .partial stopped the run (exit %s)" % (kind, rc), files)
            if kind in ("link_output", "fifo", "devnull", "directory", "hdf5_signature", "blank", "padded") \
                    and rc != 4:
                self.fail("landyn", "output %s (%r): exit %s, expected 4 (refused)" % (kind, out, rc), files)
            if sig is not None and open(os.path.join(d, "o.h5"), "rb").read() != sig:
                self.fail("landyn", "a file that only begins with the HDF5 signature was replaced", files)
            if kind == "dangling_partial" and os.path.lexists(os.path.join(d, "nowhere")):
                self.fail("landyn", "a file was created through a dangling .partial link", files)
            del before
            shutil.rmtree(d)

    def fuzz_full_disk(self, rng, root):
        small = os.path.join(root, "small")
        os.mkdir(small)
        if os.geteuid() != 0 or subprocess.run(["mount", "-t", "tmpfs", "-o", "size=2m", "tmpfs", small],
                                               capture_output=True).returncode != 0:
            print("full disk: SKIPPED (no small file system can be mounted here)")
            return
        try:
            files = {"deck.nml": "&simulation t_end = 0.01 /\n"}
            d = self.case_dir(root, files)
            out = os.path.join(small, "o.h5")
            rc, _ = self.run("landyn", self.args.landyn, ["-q", "deck.nml", "-o", out], d, files)
            prev = open(out, "rb").read() if rc == 0 else None
            for _ in range(max(4, self.args.n // 50)):
                free = os.statvfs(small).f_bavail * os.statvfs(small).f_frsize
                leave = rng.choice([0, 512, 4096, 65536, 300000])
                with open(os.path.join(small, "filler"), "wb") as f:
                    f.write(b"\0" * max(free - leave, 0))
                t_end = rng.choice([0.002, 0.05, 0.4])
                files = {"deck.nml": "&simulation t_end = %g, integrator = 'fixed', dt = 2e-5 /\n"
                                     "&output interval = 2e-5 /\n" % t_end}
                d = self.case_dir(root, files)
                rc, _ = self.run("landyn", self.args.landyn, ["-q", "deck.nml", "-o", out], d, files)
                if rc not in (0, 4, None):
                    self.fail("landyn", "full disk (%d bytes free, t_end %g): exit %s" % (leave, t_end, rc), files)
                if rc == 4 and prev is not None and open(out, "rb").read() != prev:
                    self.fail("landyn", "full disk: the previous result was not kept", files)
                if rc == 0:
                    prev = open(out, "rb").read()
                left = [f for f in os.listdir(small) if f.endswith(".partial")]
                if left:
                    self.fail("landyn", "full disk: .partial left: %s" % left, files)
                os.remove(os.path.join(small, "filler"))
        finally:
            subprocess.run(["umount", small], capture_output=True)

    def fuzz_concurrent_resume(self, rng, root):
        exe = self.args.batch
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        for _ in range(max(2, self.args.n // 150)):
            n = rng.randint(3, 6)
            files = {"lc.nml": "&simulation t_end = %g /\n" % rng.choice([0.03, 0.08]),
                     "c.nml": "&campaign base_deck = 'lc.nml', mode = 'grid' /\n&parameter name = "
                              "'initial_state%%velocity(1)', values = %s /\n" % ", ".join(
                                  "%.2f" % (0.2 * k) for k in range(n))}
            d = self.case_dir(root, files)
            self.run("batch", exe, ["-q", "c.nml", "--stop-after", str(rng.randint(1, n - 1))], d, files)
            procs = [subprocess.Popen([exe, "-q", "c.nml", "--resume"], cwd=d, env=env, stdout=subprocess.PIPE,
                                      stderr=subprocess.PIPE) for _ in range(rng.randint(2, 3))]
            res = [p.communicate(timeout=600) + (p.returncode,) for p in procs]
            self.runs += len(procs)
            rcs = [r[2] for r in res]
            if any(rc not in (0, 4) for rc in rcs) or rcs.count(0) < 1:
                self.fail("batch", "concurrent resumes: exit statuses %s: %s" % (rcs, [r[1][-200:] for r in res]),
                          files)
            for (o, e, rc) in res:
                if rc == 4 and b"in use" not in e:
                    self.fail("batch", "a refused resume does not say the campaign is in use: %s" % e[-200:], files)
            left = sorted(f for f in os.listdir(d) if f not in files)
            if left != ["c.h5"]:
                self.fail("batch", "concurrent resumes left %s" % left, files)
            else:
                rc, out = self.run("batch", exe, ["c.nml", "--resume"], d, files)
                if rc != 0:
                    self.fail("batch", "the campaign is not complete after concurrent resumes (exit %s)" % rc, files)
            shutil.rmtree(d)

    def fuzz_model_variants(self, rng, root):
        exe = self.args.study
        for _ in range(max(3, self.args.n // 60)):
            ng = [rng.choice([3, 4, 5, 6]) for _ in range(rng.randint(1, 3))]
            variants = "&variant label = 'base' /\n" + "".join(
                "&variant label = 'v%d', set = \"gears%%n_gears = %d\" /\n" % (k, g) for k, g in enumerate(ng))
            files = {"lc.nml": "&simulation t_end = 0.01 /\n&gears n_gears = %d /\n" % rng.choice([3, 4]),
                     "s.nml": "&study base_deck = 'lc.nml', output = 's.h5', csv = 's.csv' /\n" + variants}
            d = self.case_dir(root, files)
            rc, _ = self.run("study", exe, ["-q", "s.nml"], d, files)
            written = [f for f in os.listdir(d) if f not in files]
            self.check_files("study", rc, d, list(files) + (written if rc in (0, 3, 6) else []), files)
            if rc in (0, 3, 6):
                for row in open(os.path.join(d, "s.csv")).read().splitlines()[1:]:
                    for cell in row.split(",")[4:]:
                        try:
                            x = float(cell)
                        except ValueError:
                            self.fail("study", "table cell %r is not a number" % cell, files)
                            continue
                        if x == x and abs(x) > 1.0e5:
                            self.fail("study", "table cell %r is absurd (uninitialised?)" % cell, files)
            shutil.rmtree(d)

    def fuzz_long_lines(self, rng, root):
        exe = self.args.landyn
        for _ in range(max(4, self.args.n // 40)):
            n = rng.choice([1 << 16, 1 << 18, 1 << 20])
            filler = rng.choice([",", " ", ", ", "0", "1,", "\t"])
            where = rng.choice(["value", "name", "group", "comment"])
            body = filler * (n // len(filler))
            text = {"value": "&simulation t_end = 0.05" + body + " /\n",
                    "name": "&simulation t_end" + body + "= 0.05 /\n",
                    "group": "&simulation" + body + "/\n",
                    "comment": "&simulation t_end = 0.05 / !" + body + "\n"}[where]
            files = {"deck.nml": text}
            d = self.case_dir(root, files)
            t0 = time.time()
            rc, _ = self.run("landyn", exe, ["--check", "deck.nml"], d, {"deck.nml": text[:200] + "..."},
                             timeout=60)
            dt = time.time() - t0
            if dt > 15.0:
                self.fail("landyn", "a %d-character line (%r in the %s) took %.1f s" % (len(text), filler, where, dt),
                          {"deck.nml": text[:200] + "..."})
            shutil.rmtree(d)

    def fuzz_post_tools(self, rng, root):
        """Damaged HDF5 files for every post tool."""
        post = self.args.post
        files = {"deck.nml": "&simulation t_end = 0.05 /\n"}
        d = self.case_dir(root, files)
        rc, _ = self.run("landyn", self.args.landyn, ["-q", "deck.nml", "-o", "r.h5"], d, files)
        sources = {"r.h5": ["plot", "animate", "export", "compare"]}
        if self.args.batch:
            with open(os.path.join(d, "c.nml"), "w") as f:
                f.write("&campaign base_deck = 'deck.nml', mode = 'grid' /\n&parameter name = "
                        "'initial_state%velocity(1)', values = 0.0, 0.5 /\n&parameter name = 'terrain%slope(:)', "
                        "values = 0.0, 4.0 /\n")
            rc, _ = self.run("batch", self.args.batch, ["-q", "c.nml", "-o", "c.h5"], d, files)
            if rc == 0:
                sources["c.h5"] = ["envelope", "dispersion", "export"]
        try:
            import h5py
            import numpy as np
        except ImportError:
            h5py = None
        env = dict(os.environ, MPLBACKEND="Agg")
        allowed = {0, 1, 2, 3, 4, 5}
        for k in range(max(4, self.args.n // 75)):     # each tool run starts Python and matplotlib: ~2 s
            src = sorted(sources)[k % len(sources)]      # every tool sees damaged files
            data = open(os.path.join(d, src), "rb").read()
            how = rng.choice(["truncate", "flip", "text", "nan", "delete"] if h5py else ["truncate", "flip"])
            bad = os.path.join(d, "bad.h5")
            if how == "truncate":
                open(bad, "wb").write(data[:rng.randrange(8, len(data))])
            elif how == "flip":
                b = bytearray(data)
                for _k in range(rng.randint(1, 64)):
                    b[rng.randrange(96, len(b))] ^= rng.randrange(1, 256)
                open(bad, "wb").write(bytes(b))
            else:
                open(bad, "wb").write(data)
                with h5py.File(bad, "a") as f:
                    names = []
                    f.visit(lambda n: names.append(n) if isinstance(f[n], h5py.Dataset) else None)
                    name = rng.choice(sorted(names))
                    if how == "delete":
                        del f[name]
                    elif how == "text":
                        shape = f[name].shape
                        del f[name]
                        f[name] = np.full(shape, b"x", dtype="S1")
                    elif f[name].dtype.kind == "f":
                        f[name][...] = np.nan
            for tool in sources[src]:
                args = [os.path.join(post, "landyn_%s.py" % tool), bad]
                if tool == "compare":
                    args += [os.path.join(d, "r.h5"), "--tol-mm", "1"]
                if tool == "animate":
                    args += ["--still", "0.01"]
                self.runs += 1
                try:
                    p = subprocess.run([sys.executable] + args, cwd=d, capture_output=True, timeout=300, env=env)
                except subprocess.TimeoutExpired:
                    self.fail("post", "hang: %s on a %s file" % (tool, how), {})
                    continue
                err = p.stderr.decode(errors="replace")
                self.stats.setdefault("post", {}).setdefault(p.returncode, 0)
                self.stats["post"][p.returncode] += 1
                if "Traceback" in err or p.returncode not in allowed:
                    self.fail("post", "landyn-%s on %s (%s): exit %d: %s" % (tool, src, how, p.returncode, err[-400:]),
                              {})
                elif p.returncode != 0 and len([ln for ln in err.splitlines() if "error:" in ln]) != 1:
                    self.fail("post", "landyn-%s on %s (%s): not one error line: %s" % (tool, src, how, err[-400:]), {})
        shutil.rmtree(d)

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
    ap.add_argument("--post", default="", help="post/ directory: damaged HDF5 files for every post tool")
    ap.add_argument("--seed", type=int, default=10)
    ap.add_argument("--n", type=int, default=300, help="mutated decks per program")
    a = ap.parse_args()
    for k in ("landyn", "study", "batch", "post"):
        if getattr(a, k):
            setattr(a, k, os.path.abspath(getattr(a, k)))
    fz = Fuzzer(a)
    t0 = time.time()
    with tempfile.TemporaryDirectory() as root:
        progs = [("landyn", fz.fuzz_landyn), ("study", fz.fuzz_study)]
        if a.batch:
            progs.append(("batch", fz.fuzz_batch))
        # issue 25
        progs += [("special outputs", fz.fuzz_special_outputs), ("full disk", fz.fuzz_full_disk),
                  ("model-changing variants", fz.fuzz_model_variants), ("long lines", fz.fuzz_long_lines)]
        if a.batch:
            progs.append(("concurrent resumes", fz.fuzz_concurrent_resume))
        if a.post:
            progs.append(("damaged files for the post tools", fz.fuzz_post_tools))
        for i, (name, fn) in enumerate(progs):
            t1 = time.time()
            fn(random.Random(a.seed * 1000 + i), root)
            what = "%d mutated decks" % a.n if name in ("landyn", "study", "batch") else "generated cases"
            print("%s: %s in %.1f s, exit statuses %s" % (name, what, time.time() - t1,
                                                                        dict(sorted(fz.stats.get(name, {}).items()))))
    print("%d runs in %.1f s" % (fz.runs, time.time() - t0))
    if fz.failures:
        print("%d failure(s)" % len(fz.failures))
        sys.exit(1)
    print("no crash, no hang, documented exit statuses only, no file left on error")


if __name__ == "__main__":
    main()
