#!/usr/bin/env python3
"""Tests of the `landyn` executable: what a user sees (exit status, messages, files).

Usage: cli_tests.py --exe PATH --src SOURCE_DIR TEST_NAME
Each TEST_NAME is one CTest test. Every test runs in its own temporary directory.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

FAILURES = []


def check(cond, what):
    if not cond:
        FAILURES.append(what)
        print("FAIL: " + what)
    else:
        print("ok:   " + what)


def run(exe, args, cwd, timeout=600):
    p = subprocess.run([exe] + args, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    return p.returncode, p.stdout, p.stderr


def files_in(d):
    return sorted(os.listdir(d))


def write(d, name, text):
    path = os.path.join(d, name)
    with open(path, "w") as f:
        f.write(text)
    return path


# ----------------------------------------------------------------------------- tests

def t_help_version(exe, src, d):
    rc, out, err = run(exe, ["--help"], d)
    check(rc == 0 and "usage: landyn" in out, "--help exits 0 and prints usage")
    rc, out, err = run(exe, ["--version"], d)
    check(rc == 0 and re.match(r"landyn \d+\.\d+\.\d+", out), "--version prints the version")
    rc, out, err = run(exe, ["--frobnicate"], d)
    check(rc == 1 and "unknown option --frobnicate" in err, "an unknown option is a usage error (exit 1)")
    check(files_in(d) == [], "no file written by --help/--version/bad option")


def t_default_run(exe, src, d):
    """The default run (no deck) writes landyn.h5 with the schema's groups, units and provenance."""
    import h5py
    rc, out, err = run(exe, [], d)
    check(rc == 0, "default run exits 0 (stderr: %s)" % err[-300:])
    check(files_in(d) == ["landyn.h5"], "exactly landyn.h5 is written, no temporary left: %s" % files_in(d))
    check("LANDYN summary" in out and "crush [mm]" in out, "a summary table is printed")
    check("landyn: t =" in err, "progress is reported on stderr")
    with h5py.File(os.path.join(d, "landyn.h5"), "r") as f:
        for g in ("meta", "timeseries", "summary", "timeseries/body", "timeseries/gears", "timeseries/energy"):
            check(g in f, "group /%s exists" % g)
        missing = []

        def visit(name, obj):
            if isinstance(obj, h5py.Dataset) and "units" not in obj.attrs:
                missing.append(name)
        f.visititems(visit)
        check(missing == [], "every dataset carries a units attribute (missing: %s)" % missing)
        for k in ("code_version", "git_revision", "compiler", "compiler_flags", "date", "deck_text",
                  "resolved_input", "units", "command_line"):
            check(k in f["meta"], "/meta/%s exists" % k)
        res = f["meta/resolved_input"][()].decode()
        check("&simulation" in res and "&initial_state" in res, "/meta/resolved_input holds the resolved deck")
        check(f["summary/crush_length"].shape == (4, 3), "/summary/crush_length has shape (n_gears, 3)")
        check(f["summary/crush_length"].attrs["units"] == b"m", "crush_length is in metres")
        n = f["timeseries/time"].shape[0]
        check(f["timeseries/gears/stroke"].shape == (n, 4, 3), "stroke time series has shape (n, n_gears, 3)")
        check(f["timeseries/body/overload"].attrs["units"] == b"g", "overload in g")
        check(f.attrs["schema_version"] == b"1.5", "schema_version attribute (1.5: /model/crush_levels, touchdown)")
        check(f["/model/crush_levels/force"].attrs["units"] == b"N" and f["/model/touchdown/velocity"].shape == (3,),
              "/model/crush_levels and /model/touchdown are written")
        check("/model/stroke_capacity" in f and f["/model/stroke_capacity"].shape[1:] == (3, 2),
              "/model/stroke_capacity has shape (n_gears, 3, 2)")


def t_quiet(exe, src, d):
    deck = write(d, "short.nml", "&simulation t_end = 0.05 /\n")
    rc, out, err = run(exe, ["short.nml", "--quiet", "-o", "q.h5"], d)
    check(rc == 0, "quiet run exits 0")
    check(err.strip() == "", "--quiet leaves stderr empty (got %r)" % err[:200])
    check(sorted(files_in(d)) == ["q.h5", "short.nml"], "-o names the output file")
    rc, out, err = run(exe, ["short.nml"], d)
    check(rc == 0 and "short.h5" in files_in(d), "default output name is the deck base name + .h5")


def t_check_lc3(exe, src, d):
    rc, out, err = run(exe, ["--check", os.path.join(src, "input", "lc3.nml")], d)
    check(rc == 0, "--check lc3 exits 0")
    check(files_in(d) == [], "--check writes no file")
    for pat in (r"&simulation", r"slope\s*=\s*4\*8\.0", r"attitude\s*=\s*45\.0698", r"velocity\s*=\s*1\.0,\s*0\.0,\s*4\.0",
                r"&primary_strut", r"point_a"):
        check(re.search(pat, out) is not None, "resolved LC-3 input shows %s" % pat)


def t_default_deck_equals_builtin(exe, src, d):
    rc1, builtin, _ = run(exe, ["--check"], d)
    rc2, deck, _ = run(exe, ["--check", os.path.join(src, "input", "default.nml")], d)

    def body(text):   # drop comment lines naming the source and the output file name (deck-dependent)
        lines = [l for l in text.splitlines() if not l.startswith("!") and not re.match(r"\s*file\s*=", l)]
        return "\n".join(lines)
    check(rc1 == 0 and rc2 == 0, "both --check runs succeed")
    check(body(builtin) == body(deck), "input/default.nml resolves to the built-in default")
    # "written out in full": every variable of the resolved input stands in the deck, set or, where
    # its default depends on other values (rotation, stribeck_speed, the output file), named in a
    # comment line of its group
    with open(os.path.join(src, "input", "default.nml")) as fh:
        written = deck_variables(fh.read(), commented=True)
    missing = sorted(deck_variables(builtin) - written)
    check(len(deck_variables(builtin)) > 100 and not missing,
          "input/default.nml names every variable of the resolved input (missing: %s)" % missing)


def deck_variables(text, commented=False):
    """{(group, variable)} assigned in a namelist text; with commented, also '! name =' or
    '! name:' comment lines inside a group."""
    group, found = None, set()
    for line in text.splitlines():
        s = line.strip()
        if commented and s.startswith("!"):
            m = re.match(r"(\w+)\s*(\(.*?\))?\s*[=:]", s.lstrip("! "))
            if not m:
                continue
            s = m.group(1) + " ="
        s = s.split("!")[0].strip()
        m = re.match(r"&(\w+)", s)
        if m:
            group = m.group(1).lower()
            continue
        if s.startswith("/"):
            group = None
            continue
        m = re.match(r"(\w+)\s*(\(|=)", s)
        if group and m:
            found.add((group, m.group(1).lower()))
    return found


BAD_DECKS = {
    # name: (deck text, [patterns each message must match], expected number of messages)
    "unknown_variable": ("&lander mas = 1.6e4 /\n", [r"&lander.*mas"], 1),
    "type_error": ("&simulation dt = 'abc' /\n", [r"&simulation.*dt.*abc"], 1),
    "negative_mass": ("&lander mass = -5 /\n", [r"&lander.*mass.*-5"], 1),
    "inertia_not_pd": ("&lander ixx = 1.0e4, iyy = 1.0e4, izz = 5.0e4 /\n", [r"&lander.*(inertia|ixx|izz)"], 1),
    # dt > t_end also puts the default output interval (1 ms) below dt: two messages
    "dt_gt_tend": ("&simulation dt = 2.0, t_end = 1.0 /\n", [r"&simulation.*dt = 2\.0", r"&output.*interval"], 2),
    "unknown_integrator": ("&simulation integrator = 'rk45' /\n", [r"&simulation.*integrator.*rk45.*adaptive"], 1),
    "adaptive_settings": ("&simulation tolerance = 0, dt_min = 1e-3, dt_max = 1e-4, event_resolution = -1 /\n",
                          [r"&simulation.*tolerance = 0", r"&simulation.*dt_max.*dt_min",
                           r"&simulation.*event_resolution = -1"], 3),
    "event_resolution_range": ("&simulation event_resolution = 1e-2, t_end = 1.0 /\n",
                               [r"&simulation.*event_resolution = 0?\.?0?1.*dt_min <= event_resolution <= dt_max"], 1),
    "stroke_zero": ("&secondary_strut stroke_lengthening = 0 /\n", [r"&secondary_strut.*stroke_lengthening"], 1),
    "unknown_group": ("&simulaton dt = 1e-5 /\n", [r"simulaton"], 1),
    "three_mistakes": ("&lander mas = 1.6e4 /\n&simulation dt = -1, t_end = 'x' /\n",
                       [r"&lander.*mas", r"&simulation.*dt", r"&simulation.*t_end"], 3),
}


def t_bad_decks(exe, src, d):
    for name, (text, patterns, nmsg) in BAD_DECKS.items():
        sub = os.path.join(d, name)
        os.mkdir(sub)
        write(sub, "bad.nml", text)
        rc, out, err = run(exe, ["bad.nml"], sub)
        check(rc == 2, "%s: exit status 2 (got %d)" % (name, rc))
        check(files_in(sub) == ["bad.nml"], "%s: no output file (dir has %s)" % (name, files_in(sub)))
        for p in patterns:
            check(re.search(p, err) is not None, "%s: a message matches %r" % (name, p))
        m = re.search(r"landyn: (\d+) input error", err)
        check(m is not None and int(m.group(1)) == nmsg,
              "%s: %d error(s) counted (stderr: %s)" % (name, nmsg, err.strip()[-400:]))


def t_missing_deck(exe, src, d):
    rc, out, err = run(exe, ["nonexistent.nml"], d)
    check(rc == 2 and "nonexistent.nml" in err, "a missing deck is reported by name, exit 2")
    check(files_in(d) == [], "no file for a missing deck")


def t_unwritable_output(exe, src, d):
    write(d, "short.nml", "&simulation t_end = 0.01 /\n")
    rc, out, err = run(exe, ["short.nml", "-q", "-o", os.path.join(d, "no_such_dir", "x.h5")], d)
    check(rc == 4 and "no_such_dir" in err, "an unwritable result path gives exit 4 and names the path")
    check(files_in(d) == ["short.nml"], "nothing left behind")


def t_divergence(exe, src, d):
    """A fixed time step far too large for the contact stiffness stops with a diagnosis and no
    file; the adaptive integrator, given the same step as its first try, shortens it and succeeds."""
    write(d, "coarse.nml", "&simulation integrator = 'fixed', dt = 2.0e-3, t_end = 0.5 /\n&output interval = 2.0e-3 /\n")
    rc, out, err = run(exe, ["coarse.nml", "-q"], d)
    check(rc == 3, "a diverging run exits 3 (got %d)" % rc)
    check("simulation failed" in err and ("dt" in err or "time step" in err),
          "the diagnosis points at the time step: %s" % err.strip()[-300:])
    check(files_in(d) == ["coarse.nml"], "no result file for a failed run (%s)" % files_in(d))
    write(d, "coarse_adaptive.nml",
          "&simulation integrator = 'adaptive', dt = 2.0e-3, t_end = 0.5 /\n&output interval = 2.0e-3 /\n")
    rc, out, err = run(exe, ["coarse_adaptive.nml", "-q", "-o", "adaptive.h5"], d)
    check(rc == 0 and "adaptive.h5" in files_in(d), "the adaptive integrator recovers from dt = 2e-3 s (got %d: %s)"
          % (rc, err.strip()[-300:]))


TESTS = {name[2:]: fn for name, fn in globals().items() if name.startswith("t_")}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--src", required=True)
    ap.add_argument("test", choices=sorted(TESTS))
    a = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="landyn_cli_") as d:
        TESTS[a.test](os.path.abspath(a.exe), os.path.abspath(a.src), d)
    print("%d failed" % len(FAILURES))
    sys.exit(1 if FAILURES else 0)


if __name__ == "__main__":
    main()
