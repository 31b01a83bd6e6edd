#!/usr/bin/env python3
"""The house rule on doc comments holds in src/: every module, procedure, derived type, abstract
interface, type component, type-bound procedure, dummy argument and module-level variable or
constant carries a FORD doc comment (`!>` on the lines before it, or `!!` on its own statement or
on the comment lines right after it). Local variables of procedures are left out (they are
commented where it helps; FORD does not publish them).

A fypp template src/<layer>/<name>.fypp (cmake/LandynFypp.cmake) is checked through the file it
generates, <build>/generated/<name>.f90 (--generated), the code that is compiled and that FORD reads;
a template whose generated file is missing is a problem (build first).

Exit 0 when every entity is documented, 1 with a list `file:line: <what> <name>` otherwise.

  check_doc_comments.py --src SOURCE_DIR [--generated BUILD_DIR/generated] [--max N]
"""
import argparse
import os
import re
import sys

DECL = re.compile(r"^\s*(real|integer|logical|character|complex|type\s*\(|class\s*\(|procedure\s*\()", re.I)
PROC_START = re.compile(
    r"^\s*((pure|elemental|impure|recursive|module|non_recursive)\s+)*"
    r"((real|integer|logical|character|complex|double\s+precision|type|class)(\s*\([^)]*\))?\s+)?"
    r"(subroutine|function)\s+(\w+)", re.I)
MODPROC_START = re.compile(r"^\s*module\s+procedure\s+(\w+)\s*$", re.I)
PROC_END = re.compile(r"^\s*end\s*(subroutine|function|procedure)\b", re.I)
TYPE_START = re.compile(r"^\s*type\s*(,[^:]*)?(::)?\s*(\w+)\s*$", re.I)
TYPE_END = re.compile(r"^\s*end\s*type\b", re.I)
IFACE_START = re.compile(r"^\s*(abstract\s+)?interface\b\s*(\w*)", re.I)
IFACE_END = re.compile(r"^\s*end\s*interface\b", re.I)
MODULE_START = re.compile(r"^\s*(module|submodule\s*\([^)]*\)|program)\s+(\w+)\s*$", re.I)
CONTAINS = re.compile(r"^\s*contains\s*$", re.I)
BINDING = re.compile(r"^\s*(procedure|generic|final)\b", re.I)


def code_and_comment(line):
    """Split a line into its code and its comment (a `!` outside quotes)."""
    quote = None
    for i, ch in enumerate(line):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "!":
            return line[:i], line[i:]
    return line, ""


def statements(lines):
    """Yield (first line number, code joined over continuations, comments of its lines, index of
    the last line) for each statement."""
    i = 0
    n = len(lines)
    while i < n:
        code, comment = code_and_comment(lines[i])
        if not code.strip():
            i += 1
            continue
        start = i
        codes = [code]
        comments = [comment]
        while codes[-1].rstrip().endswith("&") and i + 1 < n:
            i += 1
            c, m = code_and_comment(lines[i])
            codes.append(c.lstrip().lstrip("&"))
            comments.append(m)
        joined = " ".join(c.rstrip().rstrip("&") for c in codes)
        yield start, joined, comments, i
        i += 1


def documented(lines, start, comments, last):
    """A doc comment belongs to the statement: `!!` on it, `!!` lines right after it, or `!>`
    lines right before it."""
    if any(c.startswith("!!") for c in comments):
        return True
    j = last + 1
    if j < len(lines) and lines[j].lstrip().startswith("!!"):
        return True
    j = start - 1
    while j >= 0 and lines[j].lstrip().startswith("!!"):
        j -= 1
    return j >= 0 and lines[j].lstrip().startswith("!>")


def check_file(path, rel):
    lines = open(path, encoding="utf-8").read().splitlines()
    problems = []
    stack = []          # contexts: 'module', 'type', 'type-contains', 'proc', 'iface', 'iface-proc'
    dummies = []        # dummy-argument names of the enclosing procedures
    for start, code, comments, last in statements(lines):
        low = code.strip().lower()
        where = "%s:%d" % (rel, start + 1)
        ctx = stack[-1] if stack else None

        def need(what, name):
            if not documented(lines, start, comments, last):
                problems.append("%s: %s %s" % (where, what, name))

        m = MODULE_START.match(code)
        if m and not low.startswith("module procedure") and not low.startswith("module subroutine") \
                and not low.startswith("module function"):
            need(m.group(1).split("(")[0].strip().lower(), m.group(2))
            stack.append("program" if m.group(1).lower() == "program" else "module")
            continue
        if re.match(r"^\s*end\s*(module|submodule|program)\b", low):
            stack.clear()
            continue
        if IFACE_END.match(code):
            while stack and stack[-1] != "iface":
                stack.pop()
            if stack:
                stack.pop()
            continue
        m = IFACE_START.match(code)
        if m and ctx in ("module", "proc", None):
            stack.append("iface")
            continue
        if TYPE_END.match(code):
            while stack and stack[-1] not in ("type", "type-contains"):
                stack.pop()
            if stack:
                stack.pop()
            continue
        m = TYPE_START.match(code)
        if m and ctx in ("module", None) and not low.startswith("type("):
            need("type", m.group(3))
            stack.append("type")
            continue
        if PROC_END.match(code):
            if stack and stack[-1] in ("proc", "iface-proc"):
                stack.pop()
                if dummies:
                    dummies.pop()
            continue
        m = PROC_START.match(code)
        mp = MODPROC_START.match(code)
        if (m or mp) and ctx != "iface" or (m and ctx == "iface"):
            # a program's own variables are locals: only its internal procedures are checked
            name = (m.group(7) if m else mp.group(1))
            if ctx == "iface":
                need("interface", name)
                stack.append("iface-proc")
            else:
                if m:   # a `module procedure` body is documented at its interface in the parent module
                    need("procedure", name)
                stack.append("proc")
            args = []
            if m:
                am = re.search(r"\(([^)]*)\)", code[m.end():])
                if am:
                    args = [a.strip().lower() for a in am.group(1).split(",") if a.strip()]
                rm = re.search(r"result\s*\(\s*(\w+)\s*\)", code, re.I)
                if rm:
                    args.append(rm.group(1).lower())
                elif "function" in m.group(6).lower():
                    args.append(name.lower())
            dummies.append(set(args))
            continue
        if ctx == "iface" and mp:
            continue
        if CONTAINS.match(code):
            if ctx == "type":
                stack[-1] = "type-contains"
            continue
        if ctx == "type-contains" and BINDING.match(code):
            bm = re.search(r"::\s*(\w+)", code)
            need("type-bound procedure", bm.group(1) if bm else low)
            continue
        if ctx == "type" and "::" in code and DECL.match(code):
            need("component", code.split("::", 1)[1].strip().split("=")[0].split("(")[0].strip())
            continue
        if ctx in ("proc", "iface-proc") and "::" in code and DECL.match(code):
            names = [n.strip().split("(")[0].split("=")[0].strip().lower()
                     for n in re.split(r",(?![^()]*\))", code.split("::", 1)[1])]
            if dummies and any(n in dummies[-1] for n in names):
                need("argument", ", ".join(n for n in names if n in dummies[-1]))
            continue
        if ctx == "module" and "::" in code and DECL.match(code):
            need("module variable", code.split("::", 1)[1].strip().split("=")[0].split("(")[0].strip())
            continue
    return problems


def source_files(root, generated, suffixes):
    """The sources below `root` (src/) to check: (path to read, name relative to `root` for messages)
    of every file ending in one of `suffixes`, and for every fypp template `<name>.fypp` the file
    `<generated>/<name>.f90` it generates. Also a list of problems: templates whose generated file
    is missing."""
    files, problems = [], []
    for dirpath, _, names in sorted(os.walk(root)):
        for name in sorted(names):
            path = os.path.join(dirpath, name)
            rel = os.path.relpath(path, root).replace(os.sep, "/")
            if name.endswith(suffixes):
                files.append((path, rel))
            elif name.endswith(".fypp"):
                out = os.path.join(generated or "", name[:-len(".fypp")] + ".f90")
                if generated and os.path.isfile(out):
                    files.append((out, "%s (generated %s)" % (rel, os.path.basename(out))))
                else:
                    problems.append("%s: its generated file %s is missing (build first; pass --generated "
                                    "<build>/generated)" % (rel, out if generated else name[:-len(".fypp")] + ".f90"))
    return files, problems


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--src", required=True, help="the project's root")
    ap.add_argument("--generated", help="the build's generated/ folder (the fypp templates' output)")
    ap.add_argument("--max", type=int, default=200, help="list at most this many problems")
    a = ap.parse_args()
    files, problems = source_files(os.path.join(a.src, "src"), a.generated, (".f90", ".F90", ".f90.in"))
    for path, rel in files:
        problems += check_file(path, "src/" + rel)
    for p in problems[:a.max]:
        print(p)
    if problems:
        print("%d undocumented entities (the house rule: `!>` before or `!!` on each; see docs/DEVELOPING.md)"
              % len(problems))
        return 1
    print("every module, procedure, type, component, binding, argument and module variable is documented")
    return 0


if __name__ == "__main__":
    sys.exit(main())
