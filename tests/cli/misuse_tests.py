#!/usr/bin/env python3
"""Misuse of the three programs (issue 10): every reproducer of the fuzzing campaign as a test.

Usage: misuse_tests.py --landyn EXE --study EXE [--batch EXE] --src SOURCE_DIR TEST_NAME
Each TEST_NAME is one CTest test, run on the Release and the Debug build (-fcheck=all, FP traps):
a crash, a wrong exit status or a destroyed file fails it. Exit statuses: docs/exit_status.md.
"""
import argparse
import os
import stat
import subprocess
import sys
import tempfile
import threading

FAILURES = []
CRASH_MARKS = ("Program received signal", "Fortran runtime error", "Backtrace for this error",
               "Floating-point exception", "Segmentation fault", "is not allocated")


def check(cond, what):
    if not cond:
        FAILURES.append(what)
        print("FAIL: " + what)
    else:
        print("ok:   " + what)


def run(exe, args, cwd, timeout=600, stdin_text=None):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    p = subprocess.run([exe] + args, cwd=cwd, capture_output=True, timeout=timeout, env=env,
                       input=stdin_text.encode() if stdin_text is not None else None)
    out = p.stdout.decode(errors="replace")
    err = p.stderr.decode(errors="replace")
    crashed = p.returncode < 0 or p.returncode >= 128 or any(m in err for m in CRASH_MARKS)
    check(not crashed, "%s %s: no crash (exit %d%s)" % (os.path.basename(exe), " ".join(a[:40] for a in args),
                                                          p.returncode, (", " + err[-300:]) if crashed else ""))
    return p.returncode, out, err


def write(d, name, text, mode="w"):
    path = os.path.join(d, name)
    with open(path, mode) as f:
        f.write(text)
    return path


def files_in(d):
    return sorted(os.listdir(d))


def expect(rc, want, what, err):
    check(rc == want, "%s: exit %d (got %d; stderr: %s)" % (what, want, rc, err.strip()[-400:]))


# ----------------------------------------------------------------------------- landyn: input

def t_landyn_input_reading(x, d):
    """Item 5: bare names, decks whose size is 0, read errors, '', CR line ends, BOM, bytes."""
    L = x.landyn
    write(d, "bare.nml", "&simulation t_end = 0.05, dt /\n")
    rc, out, err = run(L, ["--check", "bare.nml"], d)
    expect(rc, 2, "a bare name (&simulation t_end = 0.05, dt /) is an input error", err)
    check("'dt'" in err and "without a value" in err, "the message names the bare name dt")

    rc, out, err = run(L, ["--check", "/dev/stdin"], d, stdin_text="&simulation t_end = 0.05 /\n")
    expect(rc, 0, "a deck from a pipe (size reported as 0) is read", err)
    check("t_end = 0.05 " in out, "the piped deck's t_end = 0.05 is used, not the default")

    rc, out, err = run(L, ["--check", "/proc/self/status"], d)
    expect(rc, 2, "/proc/self/status (size 0) is read and rejected as a deck, not run as the default", err)
    check("text outside any namelist group" in err, "its text is reported")

    rc, out, err = run(L, ["--check", "/proc/self/mem"], d)
    expect(rc, 2, "a read error (/proc/self/mem) is reported", err)
    check("cannot open or read the input deck" in err, "the message says the deck cannot be read")

    rc, out, err = run(L, [""], d)
    expect(rc, 1, "landyn '' is a usage error, not the default run", err)
    check(files_in(d) == ["bare.nml"], "no file written by the refused runs")

    write(d, "cr.nml", "&simulation t_end = 0.05 /\r&lander mass = 15000.0 /\r")
    rc, out, err = run(L, ["--check", "cr.nml"], d)
    expect(rc, 0, "a deck with CR-only line ends is read", err)
    check("t_end = 0.05 " in out and "mass = 15000.0" in out, "both groups of the CR-only deck are read")
    write(d, "crlf.nml", "&simulation t_end = 0.05 /\r\n&lander mass = 15000.0 /\r\n")
    rc, out, err = run(L, ["--check", "crlf.nml"], d)
    check(rc == 0 and "mass = 15000.0" in out, "a deck with CR LF line ends is read")

    write(d, "bom.nml", b"\xef\xbb\xbf&simulation t_end = 0.05 /\n", "wb")
    rc, out, err = run(L, ["--check", "bom.nml"], d)
    expect(rc, 0, "a UTF-8 byte-order mark is accepted", err)
    check("t_end = 0.05 " in out, "the deck after the BOM is read")

    write(d, "ff.nml", b"&simulation title = 'a\xffb', t_end = 0.05 /\n", "wb")
    rc, out, err = run(L, ["--check", "ff.nml"], d)
    expect(rc, 2, "byte 0xFF in a title is an input error", err)
    check("0xFF" in err and "ASCII" in err, "the message names the byte 0xFF")
    write(d, "utf8.nml", "&simulation title = 'slope 10\u00b0' /\n".encode(), "wb")
    rc, out, err = run(L, ["--check", "utf8.nml"], d)
    check(rc == 0 and "10\u00b0" in out, "UTF-8 inside a quoted title is kept")

    write(d, "long.nml", "&output file = '%s.h5' /\n" % ("x" * 1100))
    rc, out, err = run(L, ["--check", "long.nml"], d)
    expect(rc, 2, "an &output file longer than 1024 characters is an input error, not truncated", err)
    check("too long" in err and "1024" in err, "the message gives the limit")


def t_landyn_input_bounds(x, d):
    """Items 2, 3, 4, 8: step count, t_end, body mass and inertia, contact exponent, hard points, inner_mass."""
    L = x.landyn
    cases = [
        ("&simulation dt = 1.0e-9, t_end = 3.2 /", "dt", "time steps"),
        ("&simulation dt = 1.0e-12, t_end = 4.295e-3 /", "dt", "time steps"),
        ("&simulation dt = 1.0e-300 /", "dt", "time steps"),
        ("&simulation t_end = 1.0e29 /", "t_end", "t_end <="),
        ("&lander mass = 1.0e-300 /", "mass", "mass >="),
        ("&lander izz = 1.0e-300 /", "izz", "izz >="),
        ("&contact exponent = 1.0e-300 /", "exponent", "<= exponent <="),
        ("&gears point_b(:, 1) = 1.0e29, 0.0, 0.0 /", "point_b", "out of range"),
        ("&secondary_strut inner_mass = 0 /", "inner_mass", "inner_mass > 0"),
    ]
    for i, (deck, var, valid) in enumerate(cases):
        name = "b%d.nml" % i
        write(d, name, deck + "\n")
        rc, out, err = run(L, ["-q", name], d)
        expect(rc, 2, "%s is invalid input" % deck, err)
        check(var in err and valid in err, "%s: the message names %s and the valid range (%s)" % (deck, var, valid))
        check("coincide" not in err, "%s: no misleading 'coincide' message" % deck)
    check(not any(f.endswith(".h5") or f.endswith(".partial") for f in files_in(d)), "no result file written")


def t_landyn_health(x, d):
    """Item 4: physically meaningless runs exit 6 with the reason in the summary and in /summary/health."""
    import h5py
    L = x.landyn
    # input-only checks: nothing runs
    for deck, check_name in (("&lander mass = 1.0 /", "leg_mass"), ("&gears rotation = 0, 0, 0, 0 /", "gear_separation")):
        write(d, "h.nml", deck + "\n&simulation t_end = 0.01 /\n")
        rc, out, err = run(L, ["-q", "h.nml", "-o", "h.h5"], d)
        expect(rc, 6, "%s: run-health failure (exit 6)" % deck, err)
        check(check_name in err and "FAILED" in err, "%s: the failed check %s is named" % (deck, check_name))
        check(not os.path.exists(os.path.join(d, "h.h5")), "%s: nothing run, no file" % deck)

    # result checks: the file is written with the verdict
    runs = [
        ("crush", "&primary_strut stage_end = 5.0, 10.0 /\n&initial_state velocity = 0.0, 0.0, 20.0 /\n"
                  "&simulation t_end = 0.4 /\n", "strut_length", 3),
        ("pen", "&initial_state position = 0.0, 0.0, -0.44 /\n&simulation dt = 1.0e-6, t_end = 0.005 /\n",
         "initial_penetration", 2),
    ]
    for name, deck, check_name, k in runs:
        write(d, name + ".nml", deck)
        rc, out, err = run(L, ["-q", name + ".nml"], d)
        expect(rc, 6, "%s: run-health failure (exit 6), not success" % name, err)
        check(("FAILED  " + check_name) in out, "%s: the summary shows the failed check %s" % (name, check_name))
        path = os.path.join(d, name + ".h5")
        check(os.path.exists(path), "%s: the result file is written for diagnosis" % name)
        if os.path.exists(path):
            with h5py.File(path, "r") as f:
                check(int(f["summary/health/status"][()]) == 2, "%s: /summary/health/status = 2" % name)
                names = [s.decode().strip() for s in f["summary/health/checks"][()]]
                res = list(f["summary/health/results"][()])
                check(names[k] == check_name and res[k] == 2, "%s: /summary/health/results flags %s" % (name, check_name))
                check(check_name in f["summary/health/messages"][()].decode(), "%s: the message is stored" % name)

    # a healthy run: status 0, all checks passed
    write(d, "ok.nml", "&simulation t_end = 0.01 /\n")
    rc, out, err = run(L, ["-q", "ok.nml"], d)
    expect(rc, 0, "a healthy run exits 0", err)
    with h5py.File(os.path.join(d, "ok.h5"), "r") as f:
        check(int(f["summary/health/status"][()]) == 0 and not any(f["summary/health/results"][()]),
              "a healthy run has /summary/health/status = 0")
        check(f["summary/health/messages"][()].decode() == "none", "and no health message")


def t_landyn_output_policy(x, d):
    """Items 6, 7: no input, device, read-only or non-HDF5 file is replaced; names checked before the run."""
    L = x.landyn
    deck_text = "&simulation t_end = 0.01 /\n"
    deck = write(d, "deck.nml", deck_text)

    def unchanged(path, text, what):
        with open(path) as f:
            check(f.read() == text, what + ": the file is unchanged")

    rc, out, err = run(L, ["-q", "deck.nml", "-o", "deck.nml"], d)
    expect(rc, 4, "-o naming the deck is refused", err)
    unchanged(deck, deck_text, "-o deck.nml")
    rc, out, err = run(L, ["-q", "deck.nml", "-o", "./deck.nml"], d)
    expect(rc, 4, "-o naming the deck by another path is refused", err)
    unchanged(deck, deck_text, "-o ./deck.nml")

    self_text = "&simulation t_end = 0.01 /\n&output file = 'self.nml' /\n"
    self_deck = write(d, "self.nml", self_text)
    rc, out, err = run(L, ["-q", "self.nml"], d)
    expect(rc, 4, "&output file naming the deck is refused", err)
    unchanged(self_deck, self_text, "&output file = deck")

    notes = write(d, "notes.txt", "my notes\n")
    rc, out, err = run(L, ["-q", "deck.nml", "-o", "notes.txt"], d)
    expect(rc, 4, "an existing file that is not HDF5 is not replaced", err)
    unchanged(notes, "my notes\n", "-o notes.txt")

    rc, out, err = run(L, ["-q", "deck.nml", "-o", "ro.h5"], d)
    expect(rc, 0, "a fresh result file is written", err)
    os.chmod(os.path.join(d, "ro.h5"), 0o444)
    before = open(os.path.join(d, "ro.h5"), "rb").read()
    rc, out, err = run(L, ["-q", "deck.nml", "-o", "ro.h5"], d)
    expect(rc, 4, "a read-only result file is not replaced (also as root)", err)
    check(open(os.path.join(d, "ro.h5"), "rb").read() == before, "the read-only file is unchanged")
    os.chmod(os.path.join(d, "ro.h5"), 0o644)
    rc, out, err = run(L, ["deck.nml", "-o", "ro.h5"], d)
    expect(rc, 0, "an existing writable result file is replaced", err)
    check("will be replaced" in err, "and the replacement is announced on stderr")

    os.mkfifo(os.path.join(d, "fifo"))
    rc, out, err = run(L, ["-q", "deck.nml", "-o", "fifo"], d, timeout=60)
    expect(rc, 4, "a non-regular file (fifo; a device the same) is refused", err)
    check(stat.S_ISFIFO(os.stat(os.path.join(d, "fifo")).st_mode), "the fifo is still a fifo")
    rc, out, err = run(L, ["-q", "deck.nml", "-o", "/dev/null"], d)
    expect(rc, 4, "-o /dev/null is refused", err)
    check(stat.S_ISCHR(os.stat("/dev/null").st_mode), "/dev/null is still a device")

    rc, out, err = run(L, ["-q", "deck.nml", "-o", "a" * 250 + ".h5"], d)
    expect(rc, 4, "a name whose <name>.partial exceeds 255 characters is refused before the run", err)
    check("too long" in err and "directory" not in err, "the message blames the name, not the directory")

    rc, out, err = run(L, ["-q", "deck.nml", "-o", "no_such_dir/x.h5"], d)
    expect(rc, 4, "a missing output directory is refused before the run", err)
    check("does not exist" in err and "nothing was run" in err, "the message names the missing directory")

    rc, out, err = run(L, ["-q", "deck.nml", "-o", ""], d)
    expect(rc, 1, "-o '' is a usage error", err)
    check(not any(f.endswith(".partial") for f in files_in(d)), "no temporary file left")


# ----------------------------------------------------------------------------- landyn_study

def t_study_misuse(x, d):
    """Items 2, 5, 6, 7, 8 for landyn_study."""
    S = x.study
    write(d, "lc.nml", "&simulation t_end = 0.005 /\n")
    write(d, "v2.nml", "&study base_deck = 'lc.nml' /\n&variant label = 'a', sett = 'x' /\n"
                       "&variant label = 'b', foo = 1 /\n")
    rc, out, err = run(S, ["--check", "v2.nml"], d)
    expect(rc, 2, "bad &variant items are input errors", err)
    check("&variant 1" in err and "&variant 2" in err, "both bad variants are reported")
    check(": : " not in err and "amelist" not in err.replace("namelist", ""), "the message is not garbled")

    write(d, "mc.nml", "&study base_deck = 'lc.nml', 'lc.nml', case_label = 'x', 'y', measure_case = 3 /\n"
                       "&variant label = 'a' /\n")
    rc, out, err = run(S, ["--check", "mc.nml"], d)
    expect(rc, 2, "measure_case = 3 with two cases is an input error", err)

    write(d, "two.nml", "&study base_deck = 'lc.nml' /\n&study base_deck = 'lc.nml' /\nstray text\n"
                        "&variant label = 'a' /\n")
    rc, out, err = run(S, ["--check", "two.nml"], d)
    expect(rc, 2, "a second &study and stray text are input errors", err)
    check("second &study" in err and "outside any namelist group" in err, "both are reported")

    write(d, "dup.nml", "&study base_deck = 'lc.nml', 'lc.nml', case_label = 'x', 'x' /\n&variant label = 'a' /\n")
    rc, out, err = run(S, ["-q", "dup.nml"], d)
    expect(rc, 2, "duplicate case labels are found before running", err)

    lc_text = open(os.path.join(d, "lc.nml")).read()
    write(d, "ow.nml", "&study base_deck = 'lc.nml', output = 'lc.nml' /\n&variant label = 'a' /\n")
    rc, out, err = run(S, ["-q", "ow.nml"], d)
    expect(rc, 4, "output naming the base deck is refused", err)
    check(open(os.path.join(d, "lc.nml")).read() == lc_text, "the base deck is unchanged")

    write(d, "same.nml", "&study base_deck = 'lc.nml', output = 's.h5', csv = 's.h5' /\n&variant label = 'a' /\n")
    rc, out, err = run(S, ["-q", "same.nml"], d)
    expect(rc, 4, "csv equal to output is refused", err)

    write(d, "nodir.nml", "&study base_deck = 'lc.nml', output = 'no_dir/s.h5' /\n&variant label = 'a' /\n")
    rc, out, err = run(S, ["-q", "nodir.nml"], d)
    expect(rc, 4, "a missing output directory is found before running", err)
    check("does not exist" in err, "the message names it")

    rc, out, err = run(S, ["-q", "same.nml", "-o", ""], d)
    expect(rc, 1, "-o '' is a usage error", err)

    before = set(files_in(d))
    write(d, "keep.nml", "&study base_deck = 'lc.nml', keep_results = .true. /\n&variant label = 'a' /\n")
    rc, out, err = run(S, ["-q", "keep.nml", "-o", "other.h5", "--csv", "other.csv"], d)
    expect(rc, 0, "a study with kept run files runs", err)
    new = sorted(set(files_in(d)) - before - {"keep.nml"})
    check(all(f.startswith("other") for f in new) and len(new) == 3,
          "kept run files follow -o (two runs with different -o do not collide): %s" % new)


# ----------------------------------------------------------------------------- landyn_batch

def t_batch_misuse(x, d):
    """Items 1, 2, 5, 6 for landyn_batch."""
    B = x.batch
    write(d, "empty.nml", "")
    write(d, "e.nml", "&campaign base_deck = 'empty.nml', mode = 'grid' /\n"
                      "&parameter name = 'simulation%t_end', values = 0.005 /\n")
    rc, out, err = run(B, ["-q", "e.nml"], d)
    expect(rc, 0, "a campaign on an empty base deck (the defaults) runs", err)
    check(files_in(d) == ["e.h5", "e.nml", "empty.nml"], "summary written, no journal left: %s" % files_in(d))
    write(d, "n.nml", "&campaign base_deck = '/dev/null', mode = 'grid' /\n"
                      "&parameter name = 'simulation%t_end', values = 0.005 /\n")
    rc, out, err = run(B, ["-q", "n.nml"], d)
    expect(rc, 0, "a campaign on base deck /dev/null runs", err)

    bad = [
        "&campaign base_deck = 'empty.nml', mode = 'grid', checkpoint_interval = nan /",
        "&campaign base_deck = 'empty.nml', mode = 'grid', checkpoint_interval = 1e400 /",
    ]
    for b in bad:
        write(d, "c.nml", b + "\n&parameter name = 'initial_state%velocity(1)', values = 0.0 /\n")
        rc, out, err = run(B, ["--check", "c.nml"], d)
        expect(rc, 2, b, err)
    mc = ["lo = -1e308, hi = 1e308", "sd = 1e308", "weights = 3*1e308"]
    for m in mc:
        write(d, "c.nml", "&campaign base_deck = 'empty.nml', mode = 'monte_carlo', n_samples = 2 /\n"
                          "&parameter name = 'initial_state%%velocity(1)', distribution = 'normal', mean = 0, "
                          "sd = 1, %s /\n" % m)
        rc, out, err = run(B, ["--check", "c.nml"], d)
        expect(rc, 2, "&parameter " + m, err)
        check("is invalid" in err, "&parameter %s: reported as invalid" % m)
    write(d, "c.nml", "&campaign base_deck = 'empty.nml', mode = 'grid' /\n"
                      "&parameter name = 'initial_state%velocity(1)', start = -1e308, stop = 1e308, count = 3 /\n"
                      "&criteria min_stroke_margin = -1e400 /\n")
    rc, out, err = run(B, ["--check", "c.nml"], d)
    expect(rc, 2, "start/stop = +-1e308 and min_stroke_margin = -1e400", err)

    write(d, "l.nml", "&campaign base_deck = 'empty.nml', mode = 'list', list_file = 'l.csv' /\n")
    for cell in ("0.5 0.7", "1.0;2.0", "0.5 # note", "1e400", "nan"):
        write(d, "l.csv", "initial_state%%velocity(1)\n%s\n" % cell)
        rc, out, err = run(B, ["--check", "l.nml"], d)
        expect(rc, 2, "CSV cell %r is not read as its first number" % cell, err)
    write(d, "l.csv", "")
    rc, out, err = run(B, ["--check", "l.nml"], d)
    expect(rc, 2, "an empty case list is an error, not a 0-case campaign", err)

    rc, out, err = run(B, ["e.nml", "-o", ""], d)
    expect(rc, 1, "landyn_batch -o '' is a usage error", err)

    write(d, "h.nml", "&campaign base_deck = 'empty.nml', mode = 'grid', save_histories = 1 /\n"
                      "&parameter name = 'simulation%t_end', values = 0.005 /\n")
    rc1, out, err1 = run(B, ["-q", "h.nml", "-o", "one.h5"], d)
    rc2, out, err2 = run(B, ["-q", "h.nml", "-o", "two.h5"], d)
    check(rc1 == 0 and rc2 == 0, "two campaigns with different -o run (%s %s)" % (err1[-200:], err2[-200:]))
    check(os.path.exists(os.path.join(d, "one_case000001.h5")) and os.path.exists(os.path.join(d, "two_case000001.h5")),
          "their history files follow -o and do not overwrite each other: %s" % files_in(d))
    rc, out, err = run(B, ["h.nml", "--case", "1", "-q", "-o", "three.h5"], d)
    check(rc == 0 and os.path.exists(os.path.join(d, "three_case000001.h5")), "--case -o: history files follow -o")

    text = open(os.path.join(d, "e.nml")).read()
    rc, out, err = run(B, ["-q", "e.nml", "-o", "e.nml", "--force"], d)
    expect(rc, 4, "the summary file may not be the campaign deck, even with --force", err)
    check(open(os.path.join(d, "e.nml")).read() == text, "the deck is unchanged")
    rc, out, err = run(B, ["-q", "e.nml", "-o", "empty.nml", "--force"], d)
    expect(rc, 4, "the summary file may not be the base deck", err)
    rc, out, err = run(B, ["-q", "e.nml", "-o", "/dev/null", "--force"], d)
    expect(rc, 4, "the summary file may not be a device", err)
    check(not any(f.endswith(".partial") or f.endswith(".journal") for f in files_in(d)), "no temporary file left")


TESTS = {name[2:]: fn for name, fn in globals().items() if name.startswith("t_")}

if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("--landyn", required=True)
    ap.add_argument("--study", required=True)
    ap.add_argument("--batch", default="")
    ap.add_argument("--src", required=True)
    ap.add_argument("test", choices=sorted(TESTS))
    a = ap.parse_args()
    for k in ("landyn", "study", "batch"):
        if getattr(a, k):
            setattr(a, k, os.path.abspath(getattr(a, k)))
    with tempfile.TemporaryDirectory() as d:
        TESTS[a.test](a, d)
    if FAILURES:
        print("%d check(s) failed" % len(FAILURES))
        sys.exit(1)
    print("all checks passed")
