#!/usr/bin/env python3
"""No procedure of src/ is longer than 100 lines (the house rule "procedures aim <= 100 lines"), apart
from the explicit allow-list below, each entry with its file, its name and the reason it remains.

A procedure's length counts its lines from its first statement (`subroutine`, `function`, with any
prefixes such as `pure`, `module`, `recursive`, a type; or a submodule's `module procedure NAME`) to
its end statement (`end subroutine`, `endfunction`, `end procedure NAME`, or a bare `end`), comment
and blank lines included. Interface blocks declare procedures and are not counted; an internal
procedure is counted on its own and its lines also count for its host. The C sources of src/ are
counted too: a function body from its signature to its closing brace.

Exit 0 when every procedure (outside the allow-list) has at most --max lines, 1 with a list
`file:line: name has N lines (max M)` otherwise; an allow-list entry that names no procedure over the
limit is reported as well (stale entries must go).

A fypp template (src/<layer>/<name>.fypp) is counted in the file it generates,
<build>/generated/<name>.f90 (--generated), as check_doc_comments does.

  check_procedure_length.py --src SOURCE_DIR [--generated BUILD_DIR/generated] [--max N] [--list]
"""
import argparse
import os
import re
import sys

MAX_LINES = 100

# (file relative to src/, procedure name) -> the reason it remains over the limit
ALLOWED = {}   # none since issue 27: every procedure of src/ has at most MAX_LINES lines

# the Fortran statement patterns and comment splitting of the doc-comment check (one reading of a source)
from check_doc_comments import IFACE_END, IFACE_START, MODPROC_START, PROC_END, PROC_START, code_and_comment  # noqa: E402
from check_doc_comments import source_files  # noqa: E402

BARE_END = re.compile(r"^\s*end\s*$", re.I)
UNIT_START = re.compile(r"^\s*(module|submodule\s*\([^)]*\)|program|block\s*data)\s+(\w+)\s*$", re.I)
UNIT_END = re.compile(r"^\s*end\s*(module|submodule|program|block\s*data)\b", re.I)


def code_of(line):
    """The code of a line: up to a `!` outside quotes."""
    return code_and_comment(line)[0]


def statements(lines):
    """Yield (first line index, last line index, code joined over `&` continuations) per statement
    (a `;` separates statements of one line)."""
    i = 0
    n = len(lines)
    while i < n:
        code = code_of(lines[i])
        if not code.strip():
            i += 1
            continue
        start = i
        codes = [code]
        while codes[-1].rstrip().endswith("&") and i + 1 < n:
            i += 1
            codes.append(code_of(lines[i]).lstrip().lstrip("&"))
        joined = " ".join(c.rstrip().rstrip("&") for c in codes)
        for part in joined.split(";"):
            if part.strip():
                yield start, i, part
        i += 1


def fortran_procedures(lines):
    """Yield (name, first line number, number of lines) of every procedure body of a Fortran file."""
    stack = []  # open scopes: ("proc", name, start) or ("unit", name, start)
    in_interface = 0
    for start, last, code in statements(lines):
        if IFACE_START.match(code):
            in_interface += 1
            continue
        if IFACE_END.match(code):
            in_interface -= 1
            continue
        if in_interface:
            continue  # interface bodies declare, they are not procedures
        m = PROC_START.match(code)
        if m and not PROC_END.match(code):
            stack.append(("proc", m.group(7), start))
            continue
        m = MODPROC_START.match(code)
        if m:
            stack.append(("proc", m.group(1), start))
            continue
        m = UNIT_START.match(code)
        if m and not UNIT_END.match(code) and not m.group(1).lower().startswith("module procedure"):
            stack.append(("unit", m.group(2), start))
            continue
        if PROC_END.match(code) or BARE_END.match(code) or UNIT_END.match(code):
            if not stack:
                continue
            kind, name, first = stack.pop()
            if kind == "proc":
                yield name, first + 1, last - first + 1


C_FUNC = re.compile(r"(\w+)\s*\([^;{}]*\)\s*$", re.S)


def c_procedures(lines):
    """Yield (name, first line number, number of lines) of every function of a C file (its signature,
    from the line after the previous top-level `}`, `;` or preprocessor line, to its closing brace)."""
    depth = 0
    sig_start = 0
    sig = ""
    open_line = None
    name = None
    in_comment = False
    for i, line in enumerate(lines):
        text = line
        if in_comment:
            if "*/" not in text:
                continue
            text = text.split("*/", 1)[1]
            in_comment = False
        text = re.sub(r"/\*.*?\*/", "", text)
        if "/*" in text:
            text, in_comment = text.split("/*", 1)[0], True
        text = re.sub(r"//.*", "", text)
        text = re.sub(r'"(\\.|[^"\\])*"', '""', text)
        if depth == 0 and text.lstrip().startswith("#"):
            sig, sig_start = "", i + 1
            continue
        for ch in text:
            if ch == "{":
                if depth == 0:
                    m = C_FUNC.search(sig)
                    name = m.group(1) if m else None
                    open_line = sig_start
                depth += 1
            elif ch == "}":
                depth -= 1
                if depth == 0:
                    if name:
                        yield name, open_line + 1, i - open_line + 1
                    sig, sig_start, name = "", i + 1, None
            elif depth == 0:
                if ch == ";":
                    sig, sig_start = "", i + 1
                else:
                    if not sig.strip() and not ch.isspace():
                        sig_start = i
                    sig += ch
        if depth == 0:
            sig += "\n"


def procedures(path):
    """The procedures of one source file: (name, first line number, number of lines)."""
    lines = open(path, encoding="utf-8").read().splitlines()
    if path.endswith(".c"):
        return list(c_procedures(lines))
    return list(fortran_procedures(lines))


def self_test():
    """The counter on a sample of every form it must handle (prefixes, `end` variants, a submodule's
    `module procedure`, interface bodies, an internal procedure); a list of what it got wrong."""
    body = ["    x = x + 1.0"] * 99
    sample = (["module m", "  implicit none", "contains",
               "  subroutine a(x)", "    real, intent(inout) :: x"] + body + ["  endsubroutine a",
               "  pure real(wp) function b(x) result(y)", "    y = x", "  end",
               "  subroutine c(x)", "    interface", "      subroutine ext(a)", "      end subroutine ext",
               "    end interface", "    call d()", "  contains", "    subroutine d()", "    end subroutine",
               "  end subroutine c", "end module m",
               "submodule (m) s", "contains", "  module procedure e", "    if (x > 0) then"] + body +
              ["    end if", "  end procedure e", "  module subroutine f(x)", "    real :: x; x = 1.0",
               "  end subroutine f", "end submodule s"])
    got = [(n, k) for n, _, k in fortran_procedures(sample)]
    want = [("a", 102), ("b", 3), ("d", 2), ("c", 10), ("e", 103), ("f", 3)]
    problems = []
    if got != want:
        problems.append("self-test: the counter found %s in its sample; expected %s" % (got, want))
    c_sample = ["/* f */", "static int f(int a,", "             int b)", "{", "  if (a) { return b; }",
                "  return 0;", "}", "int g(void) { return 1; }"]
    got = [(n, k) for n, _, k in c_procedures(c_sample)]
    if got != [("f", 6), ("g", 1)]:
        problems.append("self-test: the C counter found %s in its sample; expected [('f', 6), ('g', 1)]" % got)
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--src", required=True, help="the source tree (holding src/)")
    ap.add_argument("--max", type=int, default=MAX_LINES, help="the longest procedure allowed [lines]")
    ap.add_argument("--list", action="store_true", help="print every procedure over --max, allowed or not")
    ap.add_argument("--generated", help="the build's generated/ folder (the fypp templates' output)")
    a = ap.parse_args()
    root = os.path.join(a.src, "src")
    problems = self_test()
    allowed_seen = set()
    count = 0
    files, missing = source_files(root, a.generated, (".f90", ".F90", ".f90.in", ".c"))
    problems += missing
    for path, rel in files:
        for name, line, n in procedures(path):
            count += 1
            if n <= a.max:
                continue
            key = (rel, name.lower())
            if a.list:
                print("%s:%d: %s has %d lines%s" % (rel, line, name, n,
                                                    " (allowed)" if key in ALLOWED else ""))
            if key in ALLOWED:
                allowed_seen.add(key)
                continue
            problems.append("src/%s:%d: %s has %d lines (max %d); split it into named pieces"
                            % (rel, line, name, n, a.max))
    if a.max == MAX_LINES:
        for key in sorted(set(ALLOWED) - allowed_seen):
            problems.append("allow-list entry %s %s names no procedure over %d lines: remove it"
                            % (key[0], key[1], a.max))
    for p in problems:
        print("FAIL: " + p)
    print("%d procedures, %d allowed over %d lines, %d problems" % (count, len(allowed_seen), a.max, len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
