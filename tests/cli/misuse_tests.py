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

    write(d, "unk.nml", "&simulation foo = 1, t_endd = 2 /\n")
    rc, out, err = run(L, ["--check", "unk.nml"], d)
    expect(rc, 2, "unknown &simulation variables are input errors", err)
    check("unk.nml:1: &simulation: unknown variable 'foo' (foo = 1); valid variables: title, integrator, dt, "
          in err and "t_end, gravity," in err, "an unknown variable with no close name: the group's variables listed")
    check("unk.nml:1: &simulation: unknown variable 't_endd' (t_endd = 2); did you mean 't_end'?\n" in err,
          "a misspelt variable: the hint alone, no list")

    rc, out, err = run(L, [""], d)
    expect(rc, 1, "landyn '' is a usage error, not the default run", err)
    check(files_in(d) == ["bare.nml", "unk.nml"], "no file written by the refused runs")

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
        ("&secondary_strut inner_mass = 0 /", "inner_mass", "inner_mass >="),
        # issue 25 item 6: valid-looking input that the Debug build's FP traps stopped
        ("&secondary_strut inner_mass = 5e-324 /", "inner_mass", "inner_mass >="),
        ("&primary_strut footpad_mass = 5e-324, inner_mass = 0 /", "footpad_mass + inner_mass", ">="),
        ("&primary_strut inner_cm = 1e30 /", "inner_cm", "100"),
        ("&primary_strut outer_cm = 1e30 /", "outer_cm", "100"),
        ("&simulation tolerance = 1e-320 /", "tolerance", "1.0e-20"),
    ]
    for i, (deck, var, valid) in enumerate(cases):
        name = "b%d.nml" % i
        write(d, name, deck + "\n")
        rc, out, err = run(L, ["-q", name], d)
        expect(rc, 2, "%s is invalid input" % deck, err)
        check(var in err and valid in err, "%s: the message names %s and the valid range (%s)" % (deck, var, valid))
        check("coincide" not in err, "%s: no misleading 'coincide' message" % deck)
    check(not any(f.endswith(".h5") or f.endswith(".partial") for f in files_in(d)), "no result file written")
    # a lander started at the ground (footpads deep in it) has a negative energy input: the audit
    # residual is a finite number (relative to the energies moved) and the health check says so
    write(d, "g.nml", "&simulation t_end = 0.02 /\n&initial_state velocity = 0,0,0, position = 0,0,0 /\n")
    rc, out, err = run(L, ["g.nml", "-o", "g.h5"], d)
    expect(rc, 6, "a lander started at the ground: run-health failure, not a crash", err)
    check("Infinity" not in out + err and "NaN" not in out + err, "no residual of Infinity or NaN reported")


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
    check("v2.nml:3: &variant 2: unknown variable 'foo' (foo = 1); valid variables: label, set" in err,
          "an unknown &variant variable with no close name: the group's variables listed")
    check(": : " not in err and "amelist" not in err.replace("namelist", ""), "the message is not garbled")

    # a study deck is read by the run decks' reader (its own registry, landyn_study_deck): the same
    # messages, hints and checks, each with its line
    write(d, "reg.nml", "&study base_deck = 'lc.nml', titel = 'x', keep_results = .true., keep_results = .false. /\n"
                        "&variant label = '%s' /\n&variant label = 'b', measure_case = 1 /\n" % ("x" * 65))
    rc, out, err = run(S, ["--check", "reg.nml"], d)
    expect(rc, 2, "study-deck items the registry rejects are input errors", err)
    check("reg.nml:1: &study: unknown variable 'titel' (titel = 'x'); did you mean 'title'?" in err,
          "an unknown &study variable: the reader's message and hint")
    check("reg.nml:1: &study: keep_results is given more than once" in err, "an item given twice")
    check("reg.nml:2: &variant 1: label is too long (65 characters); valid: at most 64 characters" in err,
          "an over-long label is an error, not truncated")
    check("reg.nml:3: &variant 2: unknown variable 'measure_case' (measure_case = 1); "
          "'measure_case' belongs to &study" in err, "a variable of the other group: where it belongs")

    write(d, "mc.nml", "&study base_deck = 'lc.nml', 'lc.nml', case_label = 'x', 'y', measure_case = 3 /\n"
                       "&variant label = 'a' /\n")
    rc, out, err = run(S, ["--check", "mc.nml"], d)
    expect(rc, 2, "measure_case = 3 with two cases is an input error", err)

    write(d, "two.nml", "&study base_deck = 'lc.nml' /\n&study base_deck = 'lc.nml' /\nstray text\n"
                        "&variant label = 'a' /\n")
    rc, out, err = run(S, ["--check", "two.nml"], d)
    expect(rc, 2, "a second &study and stray text are input errors", err)
    check("&study: group given a second time" in err and "outside any namelist group" in err, "both are reported")

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

    write(d, "u.nml", "&campaign base_deck = 'empty.nml', mode = 'grid', n_cases = 4 /\n"
                      "&parameter name = 'simulation%t_end', values = 0.005 /\n")
    rc, out, err = run(B, ["--check", "u.nml"], d)
    expect(rc, 2, "an unknown &campaign variable is an input error", err)
    check("u.nml:1: &campaign: unknown variable 'n_cases' (n_cases = 4); valid variables: title, base_deck, mode, "
          "n_samples, " in err, "an unknown variable with no close name: the group's variables listed")

    bad = [
        "&campaign base_deck = 'empty.nml', mode = 'grid', checkpoint_interval = nan /",
        "&campaign base_deck = 'empty.nml', mode = 'grid', checkpoint_interval = 1e400 /",
    ]
    for b in bad:
        write(d, "c.nml", b + "\n&parameter name = 'initial_state%velocity(1)', values = 0.0 /\n")
        rc, out, err = run(B, ["--check", "c.nml"], d)
        expect(rc, 2, b, err)
    mc = ["sd = 1, lo = -1e308, hi = 1e308", "sd = 1e308", "sd = 1, weights = 3*1e308"]
    for m in mc:
        write(d, "c.nml", "&campaign base_deck = 'empty.nml', mode = 'monte_carlo', n_samples = 2 /\n"
                          "&parameter name = 'initial_state%%velocity(1)', distribution = 'normal', mean = 0, "
                          "%s /\n" % m)
        rc, out, err = run(B, ["--check", "c.nml"], d)
        expect(rc, 2, "&parameter " + m, err)
        check("is out of range; valid: |value| < 1e31" in err, "&parameter %s: reported as out of range" % m)
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


# ----------------------------------------------------------------------------- issue 25

LONG_DECK = "&simulation t_end = 0.4, integrator = 'fixed', dt = 2.0e-5 /\n&output interval = 2.0e-5 /\n"


def small_filesystem(d, size="2m"):
    """A directory on a small tmpfs when the machine allows it (root), else None."""
    small = os.path.join(d, "small")
    os.mkdir(small)
    if os.geteuid() != 0:
        return None           # (main() re-runs this test in a user and mount namespace when it can)
    p = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=" + size, "tmpfs", small], capture_output=True)
    return small if p.returncode == 0 else None


def unmount(path):
    if path:
        subprocess.run(["umount", path], capture_output=True)


def fill(directory, leave):
    """Fill the file system of `directory` up to `leave` bytes (a file 'filler')."""
    st = os.statvfs(directory)
    free = st.f_bavail * st.f_frsize
    with open(os.path.join(directory, "filler"), "wb") as f:
        f.write(b"\0" * max(free - leave, 0))


def t_landyn_file_safety(x, d):
    """Issue 25 items 1, 2, 10: a stale <out>.partial link is not written through, a file that only
    begins with the HDF5 signature is not replaced, -o ' ' is refused before the run."""
    L = x.landyn
    deck_text = "&simulation t_end = 0.01 /\n"
    deck = write(d, "deck.nml", deck_text)
    os.symlink("deck.nml", os.path.join(d, "q.h5.partial"))
    rc, out, err = run(L, ["-q", "deck.nml", "-o", "q.h5"], d)
    expect(rc, 0, "a run whose <out>.partial is a stale symbolic link to the deck", err)
    check(open(deck, "rb").read() == deck_text.encode(), "the deck the stale .partial link pointed to is unchanged")
    q = os.path.join(d, "q.h5")
    check(os.path.isfile(q) and not os.path.islink(q), "q.h5 is a regular file, not a link to the deck")
    check(not os.path.lexists(q + ".partial"), "no .partial left")
    os.link(deck, os.path.join(d, "h.h5.partial"))          # a hard link: truncating it would destroy the deck
    rc, out, err = run(L, ["-q", "deck.nml", "-o", "h.h5"], d)
    expect(rc, 0, "a run whose <out>.partial is a hard link to the deck", err)
    check(open(deck, "rb").read() == deck_text.encode(), "the deck hard-linked as .partial is unchanged")
    os.symlink("no_such_target", os.path.join(d, "g.h5.partial"))
    rc, out, err = run(L, ["-q", "deck.nml", "-o", "g.h5"], d)
    expect(rc, 0, "a run whose <out>.partial is a dangling link", err)
    check(not os.path.lexists(os.path.join(d, "no_such_target")), "nothing created through the dangling link")

    for name, head in (("hdr.h5", b"\x89HDF\r\n\x1a\nprecious text\n"), ("hdr2.h5", b"\x89HDF\r\n\x1a\n"),
                       ("hdr3.h5", b"\x89HDF\r\n\x1a\n\x00\x00\x00\x00\x00\x41\x41\x00 more text\n")):
        write(d, name, head, "wb")
        rc, out, err = run(L, ["-q", "deck.nml", "-o", name], d)
        expect(rc, 4, "%r: a file that only begins with the HDF5 signature is not replaced" % head[:16], err)
        check(open(os.path.join(d, name), "rb").read() == head, "%s is unchanged" % name)
    rc, out, err = run(L, ["-q", "deck.nml", "-o", "q.h5"], d)
    expect(rc, 0, "a real HDF5 result is still replaced", err)

    for name in (" ", "   ", "q.h5 ", " q.h5"):
        rc, out, err = run(L, ["-q", "deck.nml", "-o", name], d)
        expect(rc, 4, "-o %r is refused before the run" % name, err)
        check("nothing was run" in err or "refus" in err or "empty" in err or "blank" in err,
              "-o %r: the message says why" % name)
    write(d, "blank.nml", "&simulation t_end = 0.01 /\n&output file = ' ' /\n")
    rc, out, err = run(L, ["-q", "blank.nml"], d)
    expect(rc, 0, "&output file = ' ' is the default name <deck>.h5 (docs/input)", err)
    check(os.path.isfile(os.path.join(d, "blank.h5")), "blank.h5 written")
    check(not any(f.endswith(".partial") for f in files_in(d)), "no temporary file left")

    S = x.study
    write(d, "lc.nml", "&simulation t_end = 0.005 /\n")
    write(d, "st.nml", "&study base_deck = 'lc.nml', output = 'st.h5', csv = 'st.csv' /\n&variant label = 'a' /\n")
    os.symlink("lc.nml", os.path.join(d, "st.csv.partial"))
    os.symlink("deck.nml", os.path.join(d, "st.h5.partial"))
    write(d, "deck.nml", deck_text)
    lc_text = open(os.path.join(d, "lc.nml")).read()
    rc, out, err = run(S, ["-q", "st.nml"], d)
    expect(rc, 0, "a study whose .partial names are stale links", err)
    check(open(os.path.join(d, "lc.nml"), "rb").read() == lc_text.encode() and
          open(deck, "rb").read() == deck_text.encode(),
          "the decks the stale links pointed to are unchanged")
    check(not os.path.islink(os.path.join(d, "st.csv")) and not os.path.islink(os.path.join(d, "st.h5")),
          "the study's table and result are regular files")


def t_full_disk(x, d):
    """Issue 25 item 3: a full output file system (a 2 MB tmpfs; as root, or in a user and mount
    namespace) gives exit 4 and a message, never a crash; the previous result is kept, no .partial."""
    L, S, B = x.landyn, x.study, x.batch
    write(d, "long.nml", LONG_DECK)
    write(d, "short.nml", "&simulation t_end = 0.01 /\n")
    small = small_filesystem(d)
    if not small:
        print("SKIPPED: no small file system can be mounted here (not root, no user namespace)")
        return
    try:
        out = os.path.join(small, "out.h5")
        rc, o, err = run(L, ["-q", "short.nml", "-o", out], d)
        expect(rc, 0, "a short result fits on the small file system", err)
        before = open(out, "rb").read()
        rc, o, err = run(L, ["-q", "long.nml", "-o", out], d)
        expect(rc, 4, "landyn: a result too large for the file system", err)
        check("cannot write" in err, "the message says what could not be written")
        check(open(out, "rb").read() == before, "the previous result is kept")
        check(files_in(small) == ["out.h5"], "no .partial left: %s" % files_in(small))

        write(d, "st.nml", "&study base_deck = 'short.nml' /\n&variant label = 'a' /\n")
        rc, o, err = run(S, ["-q", "st.nml", "-o", os.path.join(small, "k.h5"), "--csv", os.path.join(small, "k.csv")],
                         d)
        expect(rc, 0, "landyn_study: a study that fits", err)
        fill(small, 2048)
        rc, o, err = run(S, ["-q", "st.nml", "-o", os.path.join(small, "k2.h5"), "--csv",
                             os.path.join(small, "k2.csv")], d)
        expect(rc, 4, "landyn_study: a full file system", err)
        write(d, "keep.nml", "&study base_deck = 'long.nml', keep_results = .true. /\n&variant label = 'a' /\n")
        os.remove(os.path.join(small, "filler"))
        rc, o, err = run(S, ["-q", "keep.nml", "-o", os.path.join(small, "kk.h5")], d)
        expect(rc, 4, "landyn_study: kept run files beyond the small file system", err)
        if B:
            write(d, "c.nml", "&campaign base_deck = 'long.nml', mode = 'grid', save_histories = 1 /\n"
                              "&parameter name = 'initial_state%velocity(1)', values = 0.0, 0.5 /\n")
            rc, o, err = run(B, ["-q", "c.nml", "-o", os.path.join(small, "c.h5")], d)
            check(rc in (0, 4), "landyn_batch: history files beyond the small file system: exit 0 (the cases "
                  "are rows) or 4, not a crash (exit %d: %s)" % (rc, err.strip()[-200:]))
            fill(small, 4096)
            rc, o, err = run(B, ["-q", "c.nml", "-o", os.path.join(small, "c2.h5")], d)
            check(rc == 4, "landyn_batch: a summary on a full file system: exit 4 (got %d: %s)"
                  % (rc, err.strip()[-200:]))
            if os.path.exists(os.path.join(small, "c2.h5.journal")):   # the rows kept for --resume
                check("--resume" in err, "the message says the rows are kept for --resume")
                os.remove(os.path.join(small, "c2.h5.journal"))
            os.remove(os.path.join(small, "filler"))
        left = [f for f in files_in(small) if f.endswith(".partial") or f.endswith(".journal") or f.endswith(".lock")]
        check(not left, "no temporary file left on the small file system: %s" % files_in(small))
    finally:
        unmount(small)


def t_study_model_variants(x, d):
    """Issue 25 item 4: a variant that changes gears%n_gears: the table follows the model (NaN where a
    variant's lander has no such gear), no uninitialised numbers, no crash, no .partial."""
    import csv
    import math
    S = x.study
    write(d, "lc.nml", "&simulation t_end = 0.05 /\n")
    write(d, "g.nml", "&study base_deck = 'lc.nml', case_label = 'LC-1', output = 'o.h5', csv = 'o.csv' /\n"
                      "&variant label = 'a' /\n&variant label = 'b', set = \"gears%n_gears = 3\" /\n")
    rc, out, err = run(S, ["-q", "g.nml"], d)
    expect(rc, 0, "a study whose variant has 3 gears instead of 4", err)
    check(not any(f.endswith(".partial") for f in files_in(d)), "no .partial left")
    if rc != 0:
        return
    rows = list(csv.reader(open(os.path.join(d, "o.csv"))))
    head, body = rows[0], rows[1:]
    ib = head.index("b [mm]")
    g4 = [r for r in body if r[2] == "4"]
    g1 = [r for r in body if r[2] == "1"]
    check(len(g4) == 3 and all(r[ib].lower() == "nan" for r in g4),
          "gear 4 rows: variant b (3 gears) is nan: %s" % g4)
    check(all(math.isfinite(float(r[ib])) and abs(float(r[ib])) < 1000 for r in g1), "gear 1 rows are numbers: %s" % g1)
    try:
        import h5py
    except ImportError:
        return
    with h5py.File(os.path.join(d, "o.h5"), "r") as f:
        tab = f["/table/crush_length"][()]
        gear = f["/table/gear"][()]
    col = tab[:, 1] if tab.shape[0] == len(gear) else tab[1, :]
    check(all(math.isnan(v) for v, g in zip(col, gear) if g == 4), "/table/crush_length: NaN for gear 4 of b")
    check(all(math.isfinite(v) and abs(v) < 1.0 for v, g in zip(col, gear) if g != 4),
          "/table/crush_length: the other rows of b are crush lengths (no 1e-320, 1e41): %s" % list(col))


def t_batch_concurrent_resume(x, d):
    """Issue 25 item 5: two landyn_batch --resume of one journal at once: one runs, the other is
    refused at once (exit 4, 'in use'); the summary is complete and equal to an uninterrupted run's."""
    import time
    B = x.batch
    write(d, "lc.nml", "&simulation t_end = 0.1 /\n")
    write(d, "c.nml", "&campaign base_deck = 'lc.nml', mode = 'grid' /\n"
                      "&parameter name = 'initial_state%velocity(1)', values = 0.0, 0.2, 0.4, 0.6, 0.8, 1.0 /\n")
    rc, out, err = run(B, ["-q", "c.nml", "-o", "c.h5", "--stop-after", "1"], d)
    expect(rc, 5, "a campaign stopped after one case", err)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    p1 = subprocess.Popen([B, "-q", "c.nml", "-o", "c.h5", "--resume"], cwd=d, env=env,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    t0 = time.time()
    while not os.path.exists(os.path.join(d, "c.h5.lock")) and time.time() - t0 < 60 and p1.poll() is None:
        time.sleep(0.02)          # the first one holds the campaign
    p2 = subprocess.Popen([B, "-q", "c.nml", "-o", "c.h5", "--resume"], cwd=d, env=env,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    o2, e2 = p2.communicate(timeout=600)
    o1, e1 = p1.communicate(timeout=600)
    rcs = sorted([p1.returncode, p2.returncode])
    e2 = e2.decode(errors="replace")
    check(p1.returncode == 0, "the first resume completes (exit %d: %s)" % (p1.returncode, e1.decode()[-300:]))
    check(p2.returncode == 4 and "in use" in e2, "the second, concurrent resume is refused: exit %d: %s"
          % (p2.returncode, e2.strip()[-300:]))
    check(files_in(d) == ["c.h5", "c.nml", "lc.nml"], "no journal, lock or .partial left: %s" % files_in(d))
    rc, out, err = run(B, ["-q", "c.nml", "-o", "ref.h5"], d)
    expect(rc, 0, "the uninterrupted campaign", err)
    try:
        import h5py
        import numpy as np
    except ImportError:
        return
    with h5py.File(os.path.join(d, "c.h5"), "r") as a, h5py.File(os.path.join(d, "ref.h5"), "r") as b:
        check(a.attrs.get("complete", b.attrs.get("complete")) == b.attrs.get("complete"), "complete flag equal")
        for name in ("status", "case_id", "min_stroke_margin"):
            check(np.array_equal(a["/cases/" + name][()], b["/cases/" + name][()]),
                  "/cases/%s equal to the uninterrupted run's" % name)
        for k in a["/campaign"]:
            va, vb = a["/campaign/" + k][()], b["/campaign/" + k][()]
            check(np.array_equal(va, vb) or k in ("wall_time",), "/campaign/%s equal (%r vs %r)" % (k, va, vb))
    # a killed holder leaves no lock held: kill -9 a running campaign, then resume
    p = subprocess.Popen([B, "-q", "c.nml", "-o", "k.h5"], cwd=d, env=env, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE)
    time.sleep(1.5)
    p.kill()
    p.communicate()
    rc, out, err = run(B, ["-q", "c.nml", "-o", "k.h5", "--resume"], d)
    expect(rc, 0, "a resume after a killed run is not refused", err)


def t_landyn_long_lines(x, d):
    """Issue 25 item 7: parsing time linear in the line length: 1 M commas within seconds."""
    import time
    L = x.landyn
    times = {}
    for n in (1 << 18, 1 << 20):
        write(d, "long.nml", "&simulation t_end = 0.05" + "," * n + " /\n")
        t0 = time.time()
        try:
            rc, out, err = run(L, ["--check", "long.nml"], d, timeout=120)
        except subprocess.TimeoutExpired:
            check(False, "%d commas: read within 120 s" % n)
            return
        times[n] = time.time() - t0
        check(rc in (0, 2), "%d commas: exit 0 or 2 (got %d: %s)" % (n, rc, err.strip()[-200:]))
    check(times[1 << 20] < 10.0, "1 M commas are read in under 10 s (%.1f s)" % times[1 << 20])
    check(times[1 << 20] < 8 * times[1 << 18] + 1.0,
          "4 x the line length takes at most ~4 x the time (%.2f s vs %.2f s)" % (times[1 << 20], times[1 << 18]))


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
    if a.test == "full_disk" and os.geteuid() != 0 and not os.environ.get("LANDYN_TEST_USERNS"):
        # a user and mount namespace lets an unprivileged user mount the small tmpfs
        env = dict(os.environ, LANDYN_TEST_USERNS="1")
        try:
            sys.exit(subprocess.run(["unshare", "--user", "--map-root-user", "--mount", sys.executable] + sys.argv,
                                    env=env).returncode)
        except OSError:
            pass
    with tempfile.TemporaryDirectory() as d:
        TESTS[a.test](a, d)
    if FAILURES:
        print("%d check(s) failed" % len(FAILURES))
        sys.exit(1)
    print("all checks passed")
