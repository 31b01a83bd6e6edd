#!/usr/bin/env python3
"""No source line is longer than 132 columns (the house rule, Fortran's free-form limit, kept for
every language of the project so that files read side by side).

gfortran already refuses a long Fortran code line, but not a long comment, and nothing else checks
C, headers, fypp templates, pFUnit files or Python. This check reads every file with one of the
endings below under the project's source folders, and reports `file:line: N columns (max 132)`.

Left out, each with its reason:
- src/api/fmu/fmi2/: the FMI 2.0 standard's headers, kept verbatim (their licence and the
  standard's text; fmi2FunctionTypes.h line 207 has 141 columns).

Exit 0 when every line fits, 1 with the list otherwise. `--self-test` first checks that a line of
133 columns is reported and one of 132 is not.

  check_line_length.py --src SOURCE_DIR [--self-test]
"""
import argparse
import os
import sys
import tempfile

MAX_COLUMNS = 132
ENDINGS = (".f90", ".F90", ".pf", ".c", ".h", ".py", ".fypp", ".fypi", ".f90.in")
FOLDERS = ("src", "tests", "post", "python", "bench", "examples", "scripts", "include", "cmake")
SKIP_DIRS = {"__pycache__", ".venv", "build", ".pytest_cache"}
VERBATIM = (os.path.join("src", "api", "fmu", "fmi2"),)  # the FMI standard's headers


def long_lines(path):
    """[(line number, columns)] of the lines of path longer than MAX_COLUMNS (characters, not bytes)."""
    found = []
    with open(path, encoding="utf-8", errors="replace") as f:
        for number, line in enumerate(f, start=1):
            columns = len(line.rstrip("\r\n"))
            if columns > MAX_COLUMNS:
                found.append((number, columns))
    return found


def sources(src):
    """The files to check, relative to src, sorted."""
    out = []
    for folder in FOLDERS:
        top = os.path.join(src, folder)
        for root, dirs, files in os.walk(top):
            dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS and not d.startswith("build"))
            rel_root = os.path.relpath(root, src)
            if any(rel_root == v or rel_root.startswith(v + os.sep) for v in VERBATIM):
                continue
            out.extend(os.path.join(rel_root, name) for name in files if name.endswith(ENDINGS))
    return sorted(out)


def self_test():
    """The check reports a line of 133 columns and passes one of 132."""
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "probe.py")
        with open(path, "w", encoding="utf-8") as f:
            f.write("x" * 132 + "\n" + "y" * 133 + "\n")
        if long_lines(path) != [(2, 133)]:
            print("check_line_length self-test failed: %s" % long_lines(path))
            return False
    return True


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--src", required=True, help="the project's source directory")
    ap.add_argument("--self-test", action="store_true", help="check the check first")
    a = ap.parse_args()
    if a.self_test and not self_test():
        return 1
    files = sources(a.src)
    if not files:
        print("check_line_length: no source files under %s" % a.src)
        return 1
    problems = ["%s:%d: %d columns (max %d)" % (rel, n, c, MAX_COLUMNS)
                for rel in files for n, c in long_lines(os.path.join(a.src, rel))]
    for p in problems:
        print(p)
    print("check_line_length: %d files, %d lines over %d columns" % (len(files), len(problems), MAX_COLUMNS))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
