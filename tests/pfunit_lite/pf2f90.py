#!/usr/bin/env python3
"""pf2f90 -- translate a LANDYN pFUnit test module (.pf) into plain Fortran.

This is the in-tree fallback used when the real pFUnit 4 is not installed.
It accepts exactly the subset of pFUnit 4 syntax that LANDYN's unit tests use
(see README.md beside this file) and rejects everything else with an error of
the form ``FILE:LINE: error: ...`` so that nobody drifts outside the subset.

Usage:
    pf2f90.py INPUT.pf --output OUT.F90 --driver DRIVER.F90

OUT.F90 holds the test module with every directive expanded (``#line``
markers keep compiler messages pointing at INPUT.pf); DRIVER.F90 holds a main
program that runs every ``@test`` procedure, with ``@before``/``@after``
around each, prints one line per test and a final ``N passed, N failed`` line,
and exits non-zero if any test failed.  Both are compiled against the runtime
module ``funit`` (funit.f90 beside this file).
"""

import argparse
import os
import re
import sys

# Directive (lower case) -> (Fortran routine in module funit, number of
# positional arguments, allowed keywords, required keywords).
ASSERTIONS = {
    "assertequal": ("assertEqual", 2, ("tolerance", "message"), ()),
    "assertrelativelyequal": ("assertRelativelyEqual", 2, ("tolerance", "message"), ("tolerance",)),
    "asserttrue": ("assertTrue", 1, ("message",), ()),
    "assertfalse": ("assertFalse", 1, ("message",), ()),
    "assertlessthan": ("assertLessThan", 2, ("message",), ()),
    "assertlessthanorequal": ("assertLessThanOrEqual", 2, ("message",), ()),
    "assertgreaterthan": ("assertGreaterThan", 2, ("message",), ()),
    "assertgreaterthanorequal": ("assertGreaterThanOrEqual", 2, ("message",), ()),
    "assertisfinite": ("assertIsFinite", 1, ("message",), ()),
}
MARKERS = ("test", "before", "after")
# Fortran free form: gfortran (as used by the real pFUnit's generated code) stops with
# "Line truncated" on a longer statement line.
MAX_COLUMNS = 132

RE_DIRECTIVE = re.compile(r"^\s*@(\w*)(.*)$", re.DOTALL)
RE_COMMENT_OR_BLANK = re.compile(r"^\s*(!.*)?$")
# Same form pFUnit accepts for the procedure that follows @test/@before/@after.
RE_SUBROUTINE = re.compile(r"^\s*subroutine\s+(\w+)\s*(\(\s*\))?\s*(!.*)?$", re.IGNORECASE)
RE_SUBROUTINE_ARGS = re.compile(r"^\s*subroutine\s+(\w+)\s*\(\s*\w", re.IGNORECASE)
RE_MODULE_START = re.compile(r"^\s*module\s+(?!(?:procedure|subroutine|function)\b)(\w+)\b(.*)$", re.IGNORECASE)
RE_END_MODULE = re.compile(r"^\s*end\s*module\b", re.IGNORECASE)
RE_USE_FUNIT = re.compile(r"^\s*use\s*(,\s*non_intrinsic\s*)?(::)?\s*funit\s*(!.*)?$", re.IGNORECASE)
RE_KEYWORD = re.compile(r"^\s*([A-Za-z]\w*)\s*=(?!=)(.*)$", re.DOTALL)


def pfunit_expansion(name, rest):
    """First line of the real pFUnit 4.14 expansion of the assertion '@NAME REST'.

    funitproc (bin/funit/pFUnitParser.py, class AtAssert) replaces the line by
    '  call assertX(ARGS, &' followed by short location lines, ARGS being the text
    between the outermost parentheses as written; that line reaches the compiler.
    """
    inner = rest.strip()
    if inner.startswith("(") and inner.endswith(")"):
        inner = inner[1:-1]
    return "  call " + name + "(" + inner + (", " if inner.strip() else "") + "&"


def check_columns(path, lineno, line, expansion=None):
    """Refuse a line longer than MAX_COLUMNS, as written or as pFUnit expands it."""
    width = len(line.rstrip("\r\n"))
    if width > MAX_COLUMNS:
        raise TranslationError(path, lineno,
                               f"line is {width} columns, over the {MAX_COLUMNS} of Fortran free form "
                               f"(the real pFUnit passes it on and the compiler stops with 'Line truncated')")
    if expansion is not None and len(expansion) > MAX_COLUMNS:
        raise TranslationError(path, lineno,
                               f"directive expands to a line of {len(expansion)} columns in the real pFUnit "
                               f"('{expansion[:40]}...'), over the {MAX_COLUMNS} of Fortran free form; "
                               f"shorten it (e.g. a local variable for an argument)")


class TranslationError(Exception):
    """A violation of the supported subset, reported as FILE:LINE: error: MSG."""

    def __init__(self, path, line, msg):
        super().__init__(f"{path}:{line}: error: {msg}")


def split_parenthesised(text, path, lineno):
    """Split '(a, b, c=d)   ' into its top-level arguments.

    ``text`` starts right after the directive name.  Returns the list of
    argument strings (stripped).  Raises for unbalanced parentheses,
    unterminated strings, continuation or trailing text (comments included).
    """
    s = text.rstrip("\r\n")
    i = 0
    while i < len(s) and s[i] in " \t":
        i += 1
    if i >= len(s) or s[i] != "(":
        raise TranslationError(path, lineno, "expected '(' after the assertion name")
    depth = 0
    quote = None
    args = []
    current = []
    j = i
    end = None
    while j < len(s):
        c = s[j]
        if quote:
            current.append(c)
            if c == quote:
                if j + 1 < len(s) and s[j + 1] == quote:  # doubled quote inside a string
                    current.append(s[j + 1])
                    j += 1
                else:
                    quote = None
        elif c in "'\"":
            quote = c
            current.append(c)
        elif c in "([":
            depth += 1
            if depth > 1:
                current.append(c)
        elif c in ")]":
            depth -= 1
            if depth == 0:
                if c != ")":
                    raise TranslationError(path, lineno, "unbalanced brackets in directive")
                args.append("".join(current))
                end = j
                break
            if depth < 0:
                raise TranslationError(path, lineno, "unbalanced parentheses in directive")
            current.append(c)
        elif c == "," and depth == 1:
            args.append("".join(current))
            current = []
        elif c == "!" :
            raise TranslationError(path, lineno,
                                   "comment inside a directive is not supported "
                                   "(one complete directive per line, nothing after it)")
        else:
            current.append(c)
        j += 1
    if quote:
        raise TranslationError(path, lineno, "unterminated character string in directive")
    if end is None:
        if s.rstrip().endswith("&"):
            raise TranslationError(path, lineno,
                                   "continuation lines ('&') are not supported in directives")
        raise TranslationError(path, lineno, "unbalanced parentheses in directive")
    rest = s[end + 1:]
    if rest.strip():
        if rest.strip().startswith("!"):
            raise TranslationError(path, lineno,
                                   "trailing comment after a directive is not supported "
                                   "(pFUnit would not recognise the directive)")
        if rest.strip().startswith("&"):
            raise TranslationError(path, lineno,
                                   "continuation lines ('&') are not supported in directives")
        raise TranslationError(path, lineno, f"unexpected text after directive: {rest.strip()!r}")
    args = [a.strip() for a in args]
    if len(args) == 1 and args[0] == "":
        return []
    if any(a == "" for a in args):
        raise TranslationError(path, lineno, "empty argument in directive")
    return args


def check_assert_args(name, args, path, lineno):
    routine, npos, allowed, required = ASSERTIONS[name]
    positional = []
    keywords = []
    for a in args:
        m = RE_KEYWORD.match(a)
        if m:
            kw = m.group(1).lower()
            if kw not in allowed:
                raise TranslationError(
                    path, lineno,
                    f"@{routine}: keyword '{m.group(1)}=' is not supported "
                    f"(allowed: {', '.join(k + '=' for k in allowed)})")
            if kw in (k for k, _ in keywords):
                raise TranslationError(path, lineno, f"@{routine}: keyword '{kw}=' given twice")
            if not m.group(2).strip():
                raise TranslationError(path, lineno, f"@{routine}: keyword '{kw}=' has no value")
            keywords.append((kw, a))
        else:
            if keywords:
                raise TranslationError(path, lineno,
                                       f"@{routine}: positional argument after a keyword argument")
            positional.append(a)
    if len(positional) != npos:
        extra = ""
        if len(positional) > npos:
            extra = " (tolerance and message must be given as tolerance=... and message=...)"
        raise TranslationError(
            path, lineno,
            f"@{routine} takes {npos} positional argument{'s' if npos > 1 else ''}, "
            f"got {len(positional)}{extra}")
    for r in required:
        if r not in (k for k, _ in keywords):
            raise TranslationError(path, lineno, f"@{routine} requires {r}=")
    return routine, args


def fortran_string(s):
    return "'" + s.replace("'", "''") + "'"


def translate(path, lines):
    """Return (module_text, module_name, tests, before, after)."""
    base = os.path.splitext(os.path.basename(path))[0]
    out = [f'#line 1 "{path}"\n']
    module_name = None
    module_ended = False
    uses_funit = False
    pending = None          # (kind, line of the marker) awaiting its subroutine
    tests = []              # (name, line)
    before = None
    after = None
    seen = {}

    for lineno, line in enumerate(lines, start=1):
        if not line.endswith("\n"):
            line += "\n"
        check_columns(path, lineno, line)
        m = RE_DIRECTIVE.match(line)
        if m:
            name = m.group(1)
            lname = name.lower()
            if module_name is None:
                raise TranslationError(path, lineno, f"directive @{name} before the module statement")
            if module_ended:
                raise TranslationError(path, lineno, f"directive @{name} after 'end module'")
            if pending:
                raise TranslationError(path, lineno,
                                       f"@{pending[0]} (line {pending[1]}) must be followed by "
                                       f"its 'subroutine' statement, found another directive")
            if lname in MARKERS:
                if m.group(2).strip():
                    raise TranslationError(
                        path, lineno,
                        f"@{name} takes no options or trailing text in the supported subset "
                        f"(found {m.group(2).strip()!r})")
                if lname == "before" and before:
                    raise TranslationError(path, lineno, f"second @before (first one: line {before[1]})")
                if lname == "after" and after:
                    raise TranslationError(path, lineno, f"second @after (first one: line {after[1]})")
                pending = (lname, lineno)
                out.append(re.sub("@", "!@", line, count=1))
                continue
            if lname in ASSERTIONS:
                args = split_parenthesised(m.group(2), path, lineno)
                routine, args = check_assert_args(lname, args, path, lineno)
                check_columns(path, lineno, line, pfunit_expansion(name, m.group(2)))
                indent = re.match(r"^\s*", line).group(0)
                out.append(f'#line {lineno} "{path}"\n')
                out.append(f"{indent}call {routine}( &\n")
                for a in args:
                    out.append(f"{indent}   {a}, &\n")
                out.append(f"{indent}   location=SourceLocation({fortran_string(os.path.basename(path))}, {lineno}))\n")
                out.append(f"{indent}if (anyExceptions()) return\n")
                out.append(f'#line {lineno + 1} "{path}"\n')
                continue
            supported = ", ".join("@" + k for k in MARKERS) + ", " + \
                ", ".join("@" + v[0] for v in ASSERTIONS.values())
            raise TranslationError(
                path, lineno,
                f"unsupported directive '@{name}' (the in-tree pFUnit subset supports only: {supported})")

        if pending and not RE_COMMENT_OR_BLANK.match(line):
            sm = RE_SUBROUTINE.match(line)
            if not sm:
                if RE_SUBROUTINE_ARGS.match(line):
                    raise TranslationError(path, lineno,
                                           f"procedure marked @{pending[0]} (line {pending[1]}) "
                                           f"must not take arguments")
                raise TranslationError(path, lineno,
                                       f"@{pending[0]} (line {pending[1]}) must be followed by a plain "
                                       f"'subroutine NAME' or 'subroutine NAME()' statement")
            pname = sm.group(1)
            if pname.lower() in seen:
                raise TranslationError(path, lineno,
                                       f"'{pname}' is already marked @{seen[pname.lower()]}")
            seen[pname.lower()] = pending[0]
            if pending[0] == "test":
                tests.append((pname, lineno))
            elif pending[0] == "before":
                before = (pname, lineno)
            else:
                after = (pname, lineno)
            pending = None

        if module_name is None:
            mm = RE_MODULE_START.match(line)
            if mm:
                if mm.group(2).strip():
                    raise TranslationError(path, lineno,
                                           "the module statement must be alone on its line "
                                           "('module NAME', no trailing comment), as pFUnit requires")
                module_name = mm.group(1)
                if module_name.lower() != base.lower():
                    raise TranslationError(path, lineno,
                                           f"module name '{module_name}' does not match file name '{base}'")
        elif not module_ended:
            if RE_END_MODULE.match(line):
                module_ended = True
            elif RE_USE_FUNIT.match(line):
                uses_funit = True
        out.append(line)

    nlines = len(lines)
    if pending:
        raise TranslationError(path, pending[1], f"@{pending[0]} is not followed by a subroutine")
    if module_name is None:
        raise TranslationError(path, 1, f"no 'module {base}' statement found")
    if not uses_funit:
        raise TranslationError(path, 1, f"module {module_name} must 'use funit' (plain, without only:)")
    if not tests:
        raise TranslationError(path, nlines or 1, "no @test procedure found")
    return "".join(out), module_name, tests, before, after


def driver_text(path, module_name, tests, before, after):
    names = [t for t, _ in tests]
    only = names + [p[0] for p in (before, after) if p]
    lines = [
        f"! Generated by pf2f90.py from {os.path.basename(path)} -- do not edit.\n",
        f"program {module_name}_driver\n",
        "   use funit, only: funit_begin_suite, funit_run_test, funit_end_suite\n",
    ]
    use = f"   use {module_name}, only: "
    lines.append(use + ", &\n      ".join(only) + "\n")
    lines.append("   implicit none\n")
    lines.append("   integer :: nfailed\n\n")
    lines.append(f"   call funit_begin_suite({fortran_string(module_name)})\n")
    for t in names:
        extra = ""
        if before:
            extra += f", before={before[0]}"
        if after:
            extra += f", after={after[0]}"
        lines.append(f"   call funit_run_test({fortran_string(t)}, {t}{extra})\n")
    lines.append("   call funit_end_suite(nfailed)\n")
    lines.append("   if (nfailed > 0) stop 1\n")
    lines.append(f"end program {module_name}_driver\n")
    return "".join(lines)


def write_text(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("input", help="test module, e.g. tests/unit/test_foo.pf")
    ap.add_argument("--output", "-o", required=True, help="translated module (.F90)")
    ap.add_argument("--driver", "-d", required=True, help="generated main program (.F90)")
    args = ap.parse_args(argv)

    path = os.path.abspath(args.input)
    try:
        with open(path, encoding="utf-8") as f:
            lines = f.readlines()
    except OSError as e:
        print(f"{args.input}: error: {e.strerror}", file=sys.stderr)
        return 2
    try:
        module_text, module_name, tests, before, after = translate(path, lines)
    except TranslationError as e:
        print(e, file=sys.stderr)
        return 1
    write_text(args.output, module_text)
    write_text(args.driver, driver_text(path, module_name, tests, before, after))
    return 0


if __name__ == "__main__":
    sys.exit(main())
