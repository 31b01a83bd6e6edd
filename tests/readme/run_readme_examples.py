#!/usr/bin/env python3
"""Runs every documented example of README.md and post/README.md (CTest `readme_examples`).

    run_readme_examples.py --src SOURCE_DIR --build BUILD_DIR --python VENV_PYTHON --workdir DIR

Every line of the fenced ```sh blocks and every ```python block of the two files is run, in file
order, in one temporary directory laid out like a repository checkout after scripts/setup.sh:
build/release -> BUILD_DIR, input/, post/ and python/ -> the source tree, examples/ a copy of it,
.venv -> the virtual environment of VENV_PYTHON. PATH starts with .venv/bin (so `python3` and the
console scripts are the environment's) and PYTHONPATH with SOURCE_DIR/post and SOURCE_DIR/python, so
the console scripts, `python3 post/landyn_*.py` and `import landyn` run the landyn_post and the
landyn (Python API, its library from LANDYN_LIBRARY = BUILD_DIR/liblandyn.so) of the tree under test. A command passes
when it exits 0. Skipped (listed in SKIP with the reason, and printed):

  * set-up and test commands: scripts/setup.sh, scripts/test.sh, the pip installs, the pytest run
    (the environment is already set up, and they are the test suite this test belongs to);
  * the two long paper studies study_contact.nml (8 variants) and study_friction.nml (7 variants),
    about 30 s each on one core: study_tube.nml runs the same program and paths.

Shortened (the command as written, on a copy of its deck, for the 10-minute budget of the test
suite): examples/campaign/dispersion.nml runs with n_samples = 16 instead of 500 (500 cases take
about 3 minutes on 2 cores), examples/campaign/envelope.nml on a 3 x 3 grid instead of 7 x 7
(49 cases, 1.5 minutes on one loaded core); the plotting and export examples read those files.

A console script declared in SOURCE_DIR/post/pyproject.toml but missing from .venv/bin (an
environment installed before the script was added; `pip install -e post/` creates it) is
provided as an equivalent shim and reported. Exit status 0 pass, 1 fail.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import time

SKIP = {
    "bash scripts/setup.sh": "set-up: installs system packages and builds; the environment under test is set up",
    "bash scripts/test.sh": "runs the whole test suite, which this test is part of",
    "pip install -r post/requirements.txt": "set-up: the environment under test has the pinned packages",
    "pip install -e post/": "set-up: the console scripts are provided (shims for missing ones)",
    ".venv/bin/python -m pip install -e python/": "set-up: the landyn package of the tree is on PYTHONPATH",
    "LANDYN_EXE=build/release/landyn python3 -m pytest post/tests -q": "the post_pytest test itself",
    "build/release/landyn_study input/study_contact.nml": "long (8 variants x 2 load cases, ~30 s); "
                                                          "study_tube.nml runs the same program",
    "build/release/landyn_study input/study_friction.nml": "long (7 variants x 2 load cases, ~30 s); "
                                                           "study_tube.nml runs the same program",
}
SHORTEN = {"examples/campaign/dispersion.nml": [(r"(?m)^(\s*n_samples\s*=\s*)\d+", r"\g<1>16")],
           "examples/campaign/envelope.nml": [(r"(?m)^(\s*start = 0\.0, stop = 3\.0, count = )7", r"\g<1>3"),
                                              (r"(?m)^(\s*start = 0\.0, stop = 24\.0, count = )7", r"\g<1>3")]}


def blocks(path):
    """(kind, first line number, text) of every fenced sh/python block."""
    out, kind, start, buf = [], None, 0, []
    with open(path, encoding="utf-8") as fh:
        for n, line in enumerate(fh, 1):
            m = re.match(r"^```(\w*)\s*$", line)
            if m and kind is None:
                kind, start, buf = (m.group(1) or "text"), n + 1, []
            elif m and kind is not None:
                if kind in ("sh", "python"):
                    out.append((kind, start, "".join(buf)))
                kind = None
            elif kind is not None:
                buf.append(line)
    return out


def command_key(cmd):
    """The command without its trailing comment, for SKIP lookup."""
    return re.sub(r"\s+#.*$", "", cmd).strip()


def console_scripts(src):
    text = open(os.path.join(src, "post", "pyproject.toml"), encoding="utf-8").read()
    sect = text.split("[project.scripts]", 1)[1].split("\n[", 1)[0]
    return {n: (m, f) for n, m, f in re.findall(r'^\s*([\w-]+)\s*=\s*"([\w.]+):(\w+)"', sect, re.M)}


def setup_dir(a):
    if os.path.isdir(a.workdir):
        shutil.rmtree(a.workdir)
    os.makedirs(os.path.join(a.workdir, "build"))
    os.symlink(os.path.abspath(a.build), os.path.join(a.workdir, "build", "release"))
    for d in ("input", "post", "python"):
        os.symlink(os.path.join(a.src, d), os.path.join(a.workdir, d))
    shutil.copytree(os.path.join(a.src, "examples"), os.path.join(a.workdir, "examples"))
    for rel, subs in SHORTEN.items():
        p = os.path.join(a.workdir, rel)
        text = open(p).read()
        for pat, rep in subs:
            text, n = re.subn(pat, rep, text)
            assert n == 1, f"{rel}: the line to shorten ({pat}) was not found"
        open(p, "w").write(text)
        print(f"note: {rel} shortened for the test budget: {'; '.join(r for _, r in subs)}")
    # .venv: the environment's bin entries, plus shims for console scripts it lacks
    venv_real = os.path.dirname(os.path.dirname(os.path.abspath(a.python)))
    vdir = os.path.join(a.workdir, ".venv")
    vbin = os.path.join(vdir, "bin")
    os.makedirs(vbin)
    for name in os.listdir(venv_real):          # pyvenv.cfg, lib, ...: the interpreter finds its packages
        if name != "bin":
            os.symlink(os.path.join(venv_real, name), os.path.join(vdir, name))
    for name in os.listdir(os.path.join(venv_real, "bin")):
        os.symlink(os.path.join(venv_real, "bin", name), os.path.join(vbin, name))
    for name, (mod, func) in console_scripts(a.src).items():
        if not os.path.exists(os.path.join(vbin, name)):
            p = os.path.join(vbin, name)
            with open(p, "w") as fh:
                fh.write(f"#!{os.path.abspath(a.python)}\nimport sys\nfrom {mod} import {func}\nsys.exit({func}())\n")
            os.chmod(p, 0o755)
            print(f"note: .venv/bin/{name} missing (environment installed before it was added); using a shim "
                  f"equivalent to the console script {mod}:{func}")
    env = dict(os.environ)
    env["PATH"] = vbin + os.pathsep + env.get("PATH", "")
    env["PYTHONPATH"] = os.pathsep.join([os.path.join(a.src, "post"), os.path.join(a.src, "python")]
                                        + ([env["PYTHONPATH"]] if env.get("PYTHONPATH") else []))
    env["LANDYN_LIBRARY"] = os.path.join(os.path.abspath(a.build), "liblandyn.so")
    env.update(MPLBACKEND="Agg", OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    env.pop("LANDYN_EXE", None)
    return env


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--src", required=True)
    ap.add_argument("--build", required=True)
    ap.add_argument("--python", required=True)
    ap.add_argument("--workdir", required=True)
    a = ap.parse_args()
    a.src = os.path.abspath(a.src)
    env = setup_dir(a)
    failures, n_run, skipped = [], 0, []
    for doc in ("README.md", os.path.join("post", "README.md")):
        for kind, line0, text in blocks(os.path.join(a.src, doc)):
            if kind == "python":
                items = [(line0, text, [a.python, "-c", text])]
            else:
                items = [(line0 + i, ln, ["bash", "-c", ln]) for i, ln in enumerate(text.splitlines())
                         if ln.strip() and not ln.lstrip().startswith("#")]
            for ln_no, cmd, argv in items:
                where = f"{doc}:{ln_no}"
                key = command_key(cmd) if kind == "sh" else None
                if key in SKIP:
                    skipped.append(f"{where}: {key}  -- {SKIP[key]}")
                    continue
                t0 = time.time()
                try:
                    p = subprocess.run(argv, cwd=a.workdir, env=env, capture_output=True, text=True, timeout=900)
                    rc, out = p.returncode, p.stdout + p.stderr
                except subprocess.TimeoutExpired:
                    rc, out = "timeout", ""
                n_run += 1
                shown = cmd if kind == "sh" else f"python block ({len(cmd.splitlines())} lines)"
                print(f"[{'ok' if rc == 0 else 'FAIL'}] {where}: {shown}  ({time.time() - t0:.1f} s)", flush=True)
                if rc != 0:
                    failures.append(where)
                    print(f"  exit status {rc}; output (last 40 lines):")
                    print("\n".join("    " + s for s in out.splitlines()[-40:]))
    print(f"\n{n_run} documented commands run, {len(failures)} failed; {len(skipped)} skipped:")
    for s in skipped:
        print("  skipped " + s)
    if n_run == 0:
        print("no command was run")
        return 1
    if failures:
        print("FAILED: " + ", ".join(failures))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
