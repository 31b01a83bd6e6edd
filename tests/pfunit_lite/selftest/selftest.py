#!/usr/bin/env python3
"""Self-tests of the in-tree pFUnit subset (run by CTest, see ../CMakeLists.txt).

  selftest.py translator PF2F90 WORKDIR
      Runs pf2f90.py on small .pf files written to WORKDIR: each invalid one must
      be rejected with exit status 1 and "FILE:LINE: error: ..." naming the right
      line; each valid one must translate.

  selftest.py failing EXE PF_FILE
      Runs the deliberately failing test executable built from PF_FILE and checks
      its report against the "! EXPECT-FAIL: text" / "! NOT-REACHED" comments
      in PF_FILE (see pfunit_lite_failing.pf).

Prints "N passed, N failed" and exits non-zero on any failed check.
"""

import os
import re
import subprocess
import sys

HEADER = "module {name}\n   use funit\n   implicit none\ncontains\n"
FOOTER = "end module {name}\n"
GOOD_TEST = "   @test\n   subroutine test_ok()\n      @assertTrue(.true.)\n   end subroutine test_ok\n"


def body(name, text, with_test=True):
    """A complete module NAME whose contains-part is TEXT (plus one good test)."""
    return HEADER.format(name=name) + text + (GOOD_TEST if with_test else "") + FOOTER.format(name=name)


# (case name, file text, expected bad line, fragment of the error message);
# bad line None = must translate without error.
def cases():
    def t(text):  # a test procedure around one line of body text
        return "   @test\n   subroutine test_x()\n" + text + "   end subroutine test_x\n"
    # Line numbers: HEADER is 4 lines, so the first line of TEXT is line 5;
    # inside t(...) the body line is line 7.
    return [
        ("unsupported_assert_all", body("c", t("      @assertAll([.true.])\n")), 7, "unsupported directive '@assertAll'"),
        ("unsupported_assert_not_equal", body("c", t("      @assertNotEqual(1, 2)\n")), 7, "unsupported directive"),
        ("unsupported_assert_associated", body("c", t("      @assertAssociated(p)\n")), 7, "unsupported directive"),
        ("unsupported_mpitest",
         body("c", "   @mpitest(npes=[1])\n   subroutine test_m()\n   end subroutine test_m\n"), 5,
         "unsupported directive '@mpitest'"),
        ("unsupported_testcase", body("c", "   @testCase\n"), 5, "unsupported directive '@testCase'"),
        ("unsupported_disable", body("c", "   @disable\n"), 5, "unsupported directive '@disable'"),
        ("test_with_options",
         body("c", "   @test(ifdef=FOO)\n   subroutine test_o()\n   end subroutine test_o\n"), 5, "takes no options"),
        ("trailing_comment", body("c", t("      @assertTrue(.true.) ! why not\n")), 7, "trailing comment"),
        ("continuation", body("c", t("      @assertEqual(1, &\n         1)\n")), 7, "continuation"),
        ("positional_tolerance", body("c", t("      @assertEqual(1.0, 1.0, 0.1)\n")), 7, "tolerance=..."),
        ("unknown_keyword", body("c", t("      @assertEqual(1, 1, whitespace=IGNORE_ALL)\n")), 7, "'whitespace=' is not supported"),
        ("relative_needs_tolerance", body("c", t("      @assertRelativelyEqual(1.0, 1.0)\n")), 7, "requires tolerance="),
        ("tolerance_on_ordering",
         body("c", t("      @assertLessThan(1.0, 2.0, tolerance=0.1)\n")), 7, "'tolerance=' is not supported"),
        ("too_few_args", body("c", t("      @assertEqual(1)\n")), 7, "takes 2 positional arguments, got 1"),
        ("unbalanced", body("c", t("      @assertTrue((1 > 0)\n")), 7, "unbalanced"),
        ("test_not_followed_by_subroutine",
         body("c", "   @test\n   function f()\n"), 6, "must be followed by a plain 'subroutine NAME'"),
        ("test_with_argument", body("c", "   @test\n   subroutine test_a(this)\n"), 6, "must not take arguments"),
        ("two_befores",
         body("c", "   @before\n   subroutine s1()\n   end subroutine s1\n"
                   "   @before\n   subroutine s2()\n   end subroutine s2\n"), 8, "second @before"),
        ("directive_after_directive",
         body("c", "   @test\n   @test\n   subroutine test_d()\n   end subroutine test_d\n"), 6,
         "must be followed by its 'subroutine'"),
        ("module_name_mismatch", body("other", ""), 1, "does not match file name"),
        ("module_trailing_comment",
         "module c ! comment\n   use funit\ncontains\n" + GOOD_TEST + "end module c\n", 1, "alone on its line"),
        ("no_use_funit", "module c\n   implicit none\ncontains\n" + GOOD_TEST + "end module c\n", 1, "must 'use funit'"),
        ("no_tests", body("c", "", with_test=False), 5, "no @test procedure found"),
        ("directive_before_module", "@test\n" + body("c", ""), 1, "before the module statement"),
        # Fortran free form ends at column 132: pFUnit passes longer lines on and gfortran
        # stops with "Line truncated"; a directive counts as the line pFUnit expands it to.
        ("line_133_columns", body("c", t("      x = 1" + " " * 119 + "+ 1\n")), 7, "line is 133 columns"),
        ("comment_133_columns", body("c", "   ! " + "c" * 128 + "\n"), 5, "line is 133 columns"),
        ("directive_133_columns", body("c", t("      @assertTrue(" + "a" * 110 + " > 0)\n")), 7, "line is 133 columns"),
        ("directive_expands_over_132", body("c", t("    @assertEqual(" + "a" * 91 + ", 1.0, tolerance=0.1)\n")), 7,
         "expands to a line of 133 columns"),
        # valid forms
        ("valid_all_forms", body("c",
            "   @before\n   subroutine setup()\n   end subroutine setup\n"
            "   @after\n\n   ! comment between marker and procedure\n"
            "   subroutine teardown() ! trailing comment allowed here\n   end subroutine teardown\n"
            + t("      @assertEqual(1, 1)\n      @assertEqual(1.0d0, 1.0d0, tolerance=0.1d0, message='a, b')\n"
                "      @AssertRelativelyEqual(2.0d0, 2.0d0, tolerance=1d-3)\n      @assertTrue(any([.true., .false.]))\n"
                "      @assertFalse(.false., message=\"it's (fine)\")\n      @assertLessThan(f(1, 2), 3)\n"
                "      @assertLessThanOrEqual(1, 1)\n      @assertGreaterThan(2, 1)\n      @assertGreaterThanOrEqual(a(1:2), b)\n"
                "      @assertIsFinite(x)\n      @assertEqual('x!y', 'x!y')\n")), None, None),
        ("valid_132_columns", body("c", "   ! " + "c" * 127 + "\n" + t("      x = 1" + " " * 118 + "+ 1\n"
                                                                  "        @assertEqual(" + "a" * 90 + ", 1.0, tolerance=0.1)\n")),
         None, None),
    ]


def run_translator(pf2f90, workdir):
    os.makedirs(workdir, exist_ok=True)
    passed = failed = 0
    for name, text, bad_line, fragment in cases():
        case_dir = os.path.join(workdir, name)
        os.makedirs(case_dir, exist_ok=True)
        pf = os.path.join(case_dir, "c.pf")
        with open(pf, "w", encoding="utf-8") as f:
            f.write(text)
        proc = subprocess.run([sys.executable, pf2f90, pf, "--output", os.path.join(case_dir, "c.F90"),
                               "--driver", os.path.join(case_dir, "c_driver.F90")],
                              capture_output=True, text=True)
        problem = None
        if bad_line is None:
            if proc.returncode != 0:
                problem = f"valid input rejected: {proc.stderr.strip()}"
        else:
            expected_prefix = f"{os.path.abspath(pf)}:{bad_line}: error: "
            if proc.returncode != 1:
                problem = f"expected exit status 1, got {proc.returncode}"
            elif not proc.stderr.startswith(expected_prefix):
                problem = f"expected error at line {bad_line}, got: {proc.stderr.strip()}"
            elif fragment not in proc.stderr:
                problem = f"error message lacks {fragment!r}: {proc.stderr.strip()}"
        if problem:
            failed += 1
            print(f"[ FAIL ] {name}: {problem}")
        else:
            passed += 1
            print(f"[  OK  ] {name}" + ("" if bad_line is None else f": {proc.stderr.strip()}"))
    return passed, failed


def run_failing(exe, pf_file):
    expect = []        # (line, text)
    not_reached = []   # line numbers
    with open(pf_file, encoding="utf-8") as f:
        lines = f.readlines()
    for i, line in enumerate(lines, start=1):
        m = re.match(r"^\s*! EXPECT-FAIL:\s*(.*?)\s*$", line)
        if m:
            expect.append((i + 1, m.group(1)))
        if re.match(r"^\s*! NOT-REACHED\s*$", line):
            not_reached.append(i + 1)
    base = os.path.basename(pf_file)
    proc = subprocess.run([exe], capture_output=True, text=True)
    out = proc.stdout + proc.stderr
    print(out)
    checks = []
    checks.append(("non-zero exit status", proc.returncode != 0))
    checks.append((f"summary '1 passed, {len(expect)} failed'",
                   re.search(rf"^1 passed, {len(expect)} failed$", out, re.M) is not None))
    checks.append((f"@after ran {len(expect) + 1} times",
                   f"teardown ran: {len(expect) + 1}" in out))
    for line, text in expect:
        m = re.search(rf"^{re.escape(base)}:{line}: .*$", out, re.M)
        ok = m is not None
        if ok and text:
            # the text must occur in this failure's report (up to the next test marker)
            report = out[m.start():]
            nxt = re.search(r"^\[ (FAIL|  OK|RUN ) \]", report, re.M)
            ok = text in (report[:nxt.start()] if nxt else report)
        checks.append((f"failure reported at {base}:{line} with {text!r}", ok))
    for line in not_reached:
        checks.append((f"nothing reported at {base}:{line} (after a failure)",
                       f"{base}:{line}:" not in out))
    passed = failed = 0
    for what, ok in checks:
        print(("[  OK  ] " if ok else "[ FAIL ] ") + what)
        passed += ok
        failed += not ok
    return passed, failed


def main(argv):
    if len(argv) == 3 and argv[0] == "translator":
        passed, failed = run_translator(argv[1], argv[2])
    elif len(argv) == 3 and argv[0] == "failing":
        passed, failed = run_failing(argv[1], argv[2])
    else:
        print(__doc__, file=sys.stderr)
        return 2
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
