!> Runtime of LANDYN's in-tree pFUnit subset ("pfunit_lite").
!>
!> Used only when the real pFUnit 4 is not installed: tests/pfunit_lite/pf2f90.py
!> turns each tests/unit/test_*.pf into plain Fortran that calls the procedures
!> below, with the same names and argument conventions as pFUnit 4's module
!> funit (assertEqual, ..., SourceLocation, anyExceptions), so one .pf file
!> builds against either.  The pass/fail rules are those of pFUnit 4:
!>
!>   assertEqual(e, a)                      a == e (reals: exactly equal)
!>   assertEqual(e, a, tolerance=t)         a == e  or  |e - a| <= t
!>   assertRelativelyEqual(e, a, tolerance=t)  |e - a| <= t*|e|; fails if any e == 0
!>   assertLessThan(l, r) ...               l < r, l <= r, l > r, l >= r
!>   assertEqual(c1, c2) for strings        equal after removing leading and
!>                                          trailing blanks and tabs
!>
!> Array forms compare element by element (expected may be a scalar, otherwise
!> it must have the shape of actual) and report the first failing index.
!> See README.md beside this file for the whole subset.
!>
!> The run state below (current test, counters) is module data by necessity:
!> this is test infrastructure, not library code.
module funit
   use, intrinsic :: iso_fortran_env, only: real64, output_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
   implicit none
   private

   public :: SourceLocation
   public :: assertEqual, assertRelativelyEqual
   public :: assertTrue, assertFalse, assertIsFinite
   public :: assertLessThan, assertLessThanOrEqual
   public :: assertGreaterThan, assertGreaterThanOrEqual
   public :: anyExceptions
   public :: funit_begin_suite, funit_run_test, funit_end_suite

   !> Where an assertion sits in the .pf file (same name and layout as pFUnit's).
   type :: SourceLocation
      character(len=256) :: fileName = '<unknown file>'  !! base name of the .pf file
      integer :: lineNumber = -1                          !! line of the directive
   end type SourceLocation

   abstract interface
      subroutine funit_procedure()
      end subroutine funit_procedure
   end interface

   integer, parameter :: OP_EQ = 1, OP_REL = 2, OP_LT = 3, OP_LE = 4, OP_GT = 5, OP_GE = 6
   character(len=*), parameter :: OP_NAME(6) = [character(len=24) :: 'AssertEqual', &
        'AssertRelativelyEqual', 'AssertLessThan', 'AssertLessThanOrEqual', &
        'AssertGreaterThan', 'AssertGreaterThanOrEqual']
   character(len=*), parameter :: OP_TEXT(3:6) = [character(len=24) :: 'less than', &
        'less than or equal to', 'greater than', 'greater than or equal to']

   character(len=:), allocatable :: suite_name   !! module under test
   character(len=:), allocatable :: test_name    !! test procedure now running
   logical :: test_failed = .false.              !! current test has a failed assertion
   integer :: n_passed = 0                       !! tests passed so far
   integer :: n_failed = 0                       !! tests failed so far

   interface assertEqual
      module procedure eq_i0_i0, eq_i0_i1, eq_i1_i1, eq_i0_i2
      module procedure eq_i2_i2, eq_l0_l0, eq_l0_l1, eq_l1_l1
      module procedure eq_l0_l2, eq_l2_l2, eq_i0_r0, eq_i0_r1
      module procedure eq_i1_r1, eq_i0_r2, eq_i2_r2, eq_i0_r0_tol
      module procedure eq_i0_r1_tol, eq_i1_r1_tol, eq_i0_r2_tol, eq_i2_r2_tol
      module procedure eq_r0_r0, eq_r0_r1, eq_r1_r1, eq_r0_r2
      module procedure eq_r2_r2, eq_r0_r0_tol, eq_r0_r1_tol, eq_r1_r1_tol
      module procedure eq_r0_r2_tol, eq_r2_r2_tol, eq_c0_c0
   end interface assertEqual

   interface assertRelativelyEqual
      module procedure rel_i0_r0_tol, rel_i0_r1_tol, rel_i1_r1_tol, rel_i0_r2_tol
      module procedure rel_i2_r2_tol, rel_r0_r0_tol, rel_r0_r1_tol, rel_r1_r1_tol
      module procedure rel_r0_r2_tol, rel_r2_r2_tol
   end interface assertRelativelyEqual

   interface assertLessThan
      module procedure lt_i0_i0, lt_i0_r0, lt_r0_r0
   end interface assertLessThan

   interface assertLessThanOrEqual
      module procedure le_i0_i0, le_i0_r0, le_r0_r0
   end interface assertLessThanOrEqual

   interface assertGreaterThan
      module procedure gt_i0_i0, gt_i0_r0, gt_r0_r0
   end interface assertGreaterThan

   interface assertGreaterThanOrEqual
      module procedure ge_i0_i0, ge_i0_r0, ge_r0_r0
   end interface assertGreaterThanOrEqual

   interface assertTrue
      module procedure assert_true_0, assert_true_1
   end interface assertTrue

   interface assertFalse
      module procedure assert_false_0, assert_false_1
   end interface assertFalse

   interface assertIsFinite
      module procedure assert_is_finite
   end interface assertIsFinite

contains

   ! ------------------------------------------------------------------ driver side

   !> Start a run of the tests of one .pf module.
   subroutine funit_begin_suite(name)
      character(len=*), intent(in) :: name  !! module name of the .pf file
      suite_name = name
      n_passed = 0
      n_failed = 0
      write(output_unit, '(a)') 'Running ' // name
      flush(output_unit)
   end subroutine funit_begin_suite

   !> Run one test procedure with optional set-up and tear-down, pFUnit style:
   !> the test body is skipped if set-up failed; tear-down always runs.
   subroutine funit_run_test(name, test, before, after)
      character(len=*), intent(in) :: name              !! test procedure name
      procedure(funit_procedure) :: test                 !! the @test procedure
      procedure(funit_procedure), optional :: before     !! the @before procedure
      procedure(funit_procedure), optional :: after      !! the @after procedure

      test_name = name
      test_failed = .false.
      write(output_unit, '(a)') '[ RUN  ] ' // suite_name // '.' // name
      flush(output_unit)
      if (present(before)) call before()
      if (.not. test_failed) call test()
      if (present(after)) call after()
      if (test_failed) then
         n_failed = n_failed + 1
         write(output_unit, '(a)') '[ FAIL ] ' // suite_name // '.' // name
      else
         n_passed = n_passed + 1
         write(output_unit, '(a)') '[  OK  ] ' // suite_name // '.' // name
      end if
      flush(output_unit)
      test_name = ''
   end subroutine funit_run_test

   !> Print the summary line "N passed, N failed" and return the failure count.
   subroutine funit_end_suite(nfailed)
      integer, intent(out) :: nfailed  !! number of failed tests
      character(len=24) :: np, nf
      write(np, '(i0)') n_passed
      write(nf, '(i0)') n_failed
      write(output_unit, '(a)') trim(np) // ' passed, ' // trim(nf) // ' failed'
      flush(output_unit)
      nfailed = n_failed
   end subroutine funit_end_suite

   !> True once an assertion of the running test has failed (the translator
   !> emits "if (anyExceptions()) return" after every assertion, like pFUnit).
   logical function anyExceptions()
      anyExceptions = test_failed
   end function anyExceptions

   ! ------------------------------------------------------------------ failure report

   subroutine report_failure(what, details, message, location)
      character(len=*), intent(in) :: what        !! e.g. 'AssertEqual'
      character(len=*), intent(in) :: details     !! lines after the header (may be empty)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      character(len=:), allocatable :: where, who
      character(len=24) :: lstr

      where = '<unknown location>'
      if (present(location)) then
         write(lstr, '(i0)') location%lineNumber
         where = trim(location%fileName) // ':' // trim(lstr)
      end if
      who = '<no test>'
      if (allocated(test_name)) then
         if (len(test_name) > 0) who = test_name
      end if
      test_failed = .true.
      write(output_unit, '(a)') where // ': ' // what // ' failure in ' // who
      if (present(message)) then
         if (len_trim(message) > 0) write(output_unit, '(a)') '       Message: ' // trim(message)
      end if
      if (len(details) > 0) write(output_unit, '(a)') details
      flush(output_unit)
   end subroutine report_failure

   function str_int(i) result(s)
      integer, intent(in) :: i
      character(len=:), allocatable :: s
      character(len=24) :: buf
      write(buf, '(i0)') i
      s = trim(buf)
   end function str_int

   function str_real(x) result(s)
      real(real64), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=48) :: buf
      write(buf, '(g0)') x
      s = trim(adjustl(buf))
   end function str_real

   function str_logical(x) result(s)
      logical, intent(in) :: x
      character(len=:), allocatable :: s
      s = merge('.true. ', '.false.', x)
      s = trim(s)
   end function str_logical

   !> "[i]" or "[i, j]" of element k (1-based, array element order) of an array of shape sh.
   function index_text(k, sh) result(s)
      integer, intent(in) :: k, sh(:)
      character(len=:), allocatable :: s
      integer :: r, rest, stride

      s = ''
      if (size(sh) == 0) return
      rest = k - 1
      s = NEW_LINE('a') // '      at index: ['
      do r = 1, size(sh)
         stride = max(sh(r), 1)
         if (r > 1) s = s // ', '
         s = s // str_int(mod(rest, stride) + 1)
         rest = rest / stride
      end do
      s = s // ']'
   end function index_text

   !> Shapes must be equal, or expected a scalar (pFUnit's "conformable").
   logical function check_conformable(what, shape_e, shape_a, message, location)
      character(len=*), intent(in) :: what
      integer, intent(in) :: shape_e(:), shape_a(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: r
      character(len=:), allocatable :: se, sa

      check_conformable = size(shape_e) == 0
      if (.not. check_conformable) then
         check_conformable = size(shape_e) == size(shape_a)
         if (check_conformable) check_conformable = all(shape_e == shape_a)
      end if
      if (check_conformable) return
      se = '['
      do r = 1, size(shape_e)
         if (r > 1) se = se // ', '
         se = se // str_int(shape_e(r))
      end do
      sa = '['
      do r = 1, size(shape_a)
         if (r > 1) sa = sa // ', '
         sa = sa // str_int(shape_a(r))
      end do
      call report_failure(what, '    Arrays not conformable' // NEW_LINE('a') // &
                          '    Expected shape: ' // se // ']' // NEW_LINE('a') // &
                          '      Actual shape: ' // sa // ']', message, location)
   end function check_conformable

   ! ------------------------------------------------------------------ comparisons

   subroutine compare_integer(op, e, a, shape_e, shape_a, message, location)
      integer, intent(in) :: op            !! OP_EQ, OP_LT, OP_LE, OP_GT or OP_GE
      integer, intent(in) :: e(:), a(:)    !! expected (or lhs) / actual (or rhs), flattened
      integer, intent(in) :: shape_e(:), shape_a(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k, ke
      logical :: ok

      if (.not. check_conformable(trim(OP_NAME(op)), shape_e, shape_a, message, location)) return
      do k = 1, size(a)
         ke = merge(1, k, size(shape_e) == 0)
         select case (op)
         case (OP_EQ); ok = e(ke) == a(k)
         case (OP_LT); ok = e(ke) < a(k)
         case (OP_LE); ok = e(ke) <= a(k)
         case (OP_GT); ok = e(ke) > a(k)
         case default; ok = e(ke) >= a(k)
         end select
         if (ok) cycle
         if (op == OP_EQ) then
            call report_failure(trim(OP_NAME(op)), &
                 '      Expected: <' // str_int(e(ke)) // '>' // NEW_LINE('a') // &
                 '        Actual: <' // str_int(a(k)) // '>' // NEW_LINE('a') // &
                 '    Difference: <' // str_int(a(k) - e(ke)) // '>' // index_text(k, shape_a), &
                 message, location)
         else
            call report_failure(trim(OP_NAME(op)), ordering_text(op, str_int(e(ke)), str_int(a(k))) // &
                 index_text(k, shape_a), message, location)
         end if
         return
      end do
   end subroutine compare_integer

   subroutine compare_logical(e, a, shape_e, shape_a, message, location)
      logical, intent(in) :: e(:), a(:)    !! expected / actual, flattened
      integer, intent(in) :: shape_e(:), shape_a(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k, ke

      if (.not. check_conformable('AssertEqual', shape_e, shape_a, message, location)) return
      do k = 1, size(a)
         ke = merge(1, k, size(shape_e) == 0)
         if (e(ke) .eqv. a(k)) cycle
         call report_failure('AssertEqual', &
              '      Expected: <' // str_logical(e(ke)) // '>' // NEW_LINE('a') // &
              '        Actual: <' // str_logical(a(k)) // '>' // index_text(k, shape_a), &
              message, location)
         return
      end do
   end subroutine compare_logical

   !> Real comparisons.  NaN never compares (the assertion fails, as in pFUnit);
   !> the code avoids ordered comparisons on NaN so that it also works under
   !> -ffpe-trap=invalid.
   subroutine compare_real(op, e, a, tol, shape_e, shape_a, message, location)
      integer, intent(in) :: op                  !! OP_EQ, OP_REL, OP_LT, OP_LE, OP_GT or OP_GE
      real(real64), intent(in) :: e(:), a(:)     !! expected (or lhs) / actual (or rhs), flattened
      real(real64), intent(in) :: tol            !! tolerance (OP_EQ: absolute, OP_REL: relative)
      integer, intent(in) :: shape_e(:), shape_a(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k, ke
      logical :: ok
      real(real64) :: ev, av

      if (.not. check_conformable(trim(OP_NAME(op)), shape_e, shape_a, message, location)) return
      if (op == OP_REL) then
         do k = 1, size(e)
            if (ieee_is_nan(e(k))) cycle
            if (abs(e(k)) <= 0.0_real64) then
               call report_failure(trim(OP_NAME(op)), &
                    '    Zero denominator detected in AssertRelativelyEqual.', message, location)
               return
            end if
         end do
      end if
      do k = 1, size(a)
         ke = merge(1, k, size(shape_e) == 0)
         ev = e(ke)
         av = a(k)
         if (ieee_is_nan(ev) .or. ieee_is_nan(av)) then
            ok = .false.
         else
            select case (op)
            case (OP_EQ)
               ok = av >= ev .and. av <= ev                   ! exact equality (also for +-Inf)
               if (.not. ok .and. .not. ieee_is_nan(tol)) ok = abs(av - ev) <= tol
            case (OP_REL)
               ok = ieee_is_finite(ev) .and. ieee_is_finite(av) .and. .not. ieee_is_nan(tol)
               if (ok) ok = abs(av - ev) <= tol * abs(ev)
            case (OP_LT); ok = ev < av
            case (OP_LE); ok = ev <= av
            case (OP_GT); ok = ev > av
            case default; ok = ev >= av
            end select
         end if
         if (ok) cycle
         select case (op)
         case (OP_EQ)
            call report_failure(trim(OP_NAME(op)), &
                 '      Expected: <' // str_real(ev) // '>' // NEW_LINE('a') // &
                 '        Actual: <' // str_real(av) // '>' // NEW_LINE('a') // &
                 '    Difference: <' // diff_text(av, ev) // '> (greater than tolerance of ' // &
                 str_real(tol) // ')' // index_text(k, shape_a), message, location)
         case (OP_REL)
            call report_failure(trim(OP_NAME(op)), &
                 '      Expected: <' // str_real(ev) // '>' // NEW_LINE('a') // &
                 '        Actual: <' // str_real(av) // '>' // NEW_LINE('a') // &
                 '    Relative difference: <' // rel_diff_text(av, ev) // &
                 '> (greater than tolerance of ' // str_real(tol) // ')' // index_text(k, shape_a), &
                 message, location)
         case default
            call report_failure(trim(OP_NAME(op)), ordering_text(op, str_real(ev), str_real(av)) // &
                 index_text(k, shape_a), message, location)
         end select
         return
      end do
   end subroutine compare_real

   !> pFUnit's layout: "LHS: <l>" over "not less than: <r>", right-aligned.
   function ordering_text(op, lhs, rhs) result(s)
      integer, intent(in) :: op
      character(len=*), intent(in) :: lhs, rhs
      character(len=:), allocatable :: s
      character(len=:), allocatable :: label
      label = 'not ' // trim(OP_TEXT(op)) // ': '
      s = repeat(' ', 4 + len(label) - 5) // 'LHS: <' // lhs // '>' // NEW_LINE('a') // &
          '    ' // label // '<' // rhs // '>'
   end function ordering_text

   function diff_text(a, e) result(s)
      real(real64), intent(in) :: a, e
      character(len=:), allocatable :: s
      if (ieee_is_finite(a) .and. ieee_is_finite(e)) then
         s = str_real(a - e)
      else
         s = 'n/a'
      end if
   end function diff_text

   function rel_diff_text(a, e) result(s)
      real(real64), intent(in) :: a, e
      character(len=:), allocatable :: s
      if (ieee_is_finite(a) .and. ieee_is_finite(e)) then
         s = str_real((a - e) / e)
      else
         s = 'n/a'
      end if
   end function rel_diff_text

   ! ------------------------------------------------------------------ assertTrue / assertFalse / assertIsFinite

   subroutine assert_true_0(condition, message, location)
      logical, intent(in) :: condition
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (.not. condition) call report_failure('AssertTrue', '', message, location)
   end subroutine assert_true_0

   subroutine assert_true_1(condition, message, location)
      logical, intent(in) :: condition(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (.not. all(condition)) call report_failure('AssertTrue', '', message, location)
   end subroutine assert_true_1

   subroutine assert_false_0(condition, message, location)
      logical, intent(in) :: condition
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (condition) call report_failure('AssertFalse', '', message, location)
   end subroutine assert_false_0

   subroutine assert_false_1(condition, message, location)
      logical, intent(in) :: condition(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (any(condition)) call report_failure('AssertFalse', '', message, location)
   end subroutine assert_false_1

   subroutine assert_is_finite(x, message, location)
      real(real64), intent(in) :: x
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      if (.not. ieee_is_finite(x)) call report_failure('AssertIsFinite', &
           '    Value: <' // str_real(x) // '>', message, location)
   end subroutine assert_is_finite

   ! ------------------------------------------------------------------ strings

   !> pFUnit's default for strings: leading and trailing blanks and tabs do not count.
   function trim_all(s) result(t)
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: t
      integer :: i, j
      i = 1
      j = len(s)
      do while (i <= j)
         if (s(i:i) /= ' ' .and. s(i:i) /= achar(9)) exit
         i = i + 1
      end do
      do while (j >= i)
         if (s(j:j) /= ' ' .and. s(j:j) /= achar(9)) exit
         j = j - 1
      end do
      t = s(i:j)
   end function trim_all

   subroutine eq_c0_c0(expected, actual, message, location)
      character(len=*), intent(in) :: expected
      character(len=*), intent(in) :: actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      character(len=:), allocatable :: e, a
      e = trim_all(expected)
      a = trim_all(actual)
      if (len(e) == len(a)) then
         if (e == a) return
      end if
      call report_failure('AssertEqual', &
           '      Expected: <"' // e // '">' // NEW_LINE('a') // &
           '        Actual: <"' // a // '">', message, location)
   end subroutine eq_c0_c0

   ! ------------------------------------------------------------------ generic specifics
   ! One thin wrapper per (expected, actual[, tolerance]) type/rank combination that
   ! pFUnit 4 also accepts; all forward to compare_integer/_logical/_real above.

   subroutine eq_i0_i0(expected, actual, message, location)
      integer, intent(in) :: expected
      integer, intent(in) :: actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_integer(OP_EQ, [expected], [actual], shape(expected), shape(actual), message, location)
   end subroutine eq_i0_i0

   subroutine eq_i0_i1(expected, actual, message, location)
      integer, intent(in) :: expected
      integer, intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_integer(OP_EQ, [expected], [actual], shape(expected), shape(actual), message, location)
   end subroutine eq_i0_i1

   subroutine eq_i1_i1(expected, actual, message, location)
      integer, intent(in) :: expected(:)
      integer, intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_integer(OP_EQ, [expected], [actual], shape(expected), shape(actual), message, location)
   end subroutine eq_i1_i1

   subroutine eq_i0_i2(expected, actual, message, location)
      integer, intent(in) :: expected
      integer, intent(in) :: actual(:,:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_integer(OP_EQ, [expected], [actual], shape(expected), shape(actual), message, location)
   end subroutine eq_i0_i2

   subroutine eq_i2_i2(expected, actual, message, location)
      integer, intent(in) :: expected(:,:)
      integer, intent(in) :: actual(:,:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_integer(OP_EQ, [expected], [actual], shape(expected), shape(actual), message, location)
   end subroutine eq_i2_i2

   subroutine lt_i0_i0(lhs, rhs, message, location)
      integer, intent(in) :: lhs
      integer, intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_integer(OP_LT, [lhs], [rhs], shape(lhs), shape(rhs), message, location)
   end subroutine lt_i0_i0

   subroutine le_i0_i0(lhs, rhs, message, location)
      integer, intent(in) :: lhs
      integer, intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_integer(OP_LE, [lhs], [rhs], shape(lhs), shape(rhs), message, location)
   end subroutine le_i0_i0

   subroutine gt_i0_i0(lhs, rhs, message, location)
      integer, intent(in) :: lhs
      integer, intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_integer(OP_GT, [lhs], [rhs], shape(lhs), shape(rhs), message, location)
   end subroutine gt_i0_i0

   subroutine ge_i0_i0(lhs, rhs, message, location)
      integer, intent(in) :: lhs
      integer, intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_integer(OP_GE, [lhs], [rhs], shape(lhs), shape(rhs), message, location)
   end subroutine ge_i0_i0

   subroutine eq_l0_l0(expected, actual, message, location)
      logical, intent(in) :: expected
      logical, intent(in) :: actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_logical([expected], [actual], shape(expected), shape(actual), message, location)
   end subroutine eq_l0_l0

   subroutine eq_l0_l1(expected, actual, message, location)
      logical, intent(in) :: expected
      logical, intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_logical([expected], [actual], shape(expected), shape(actual), message, location)
   end subroutine eq_l0_l1

   subroutine eq_l1_l1(expected, actual, message, location)
      logical, intent(in) :: expected(:)
      logical, intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_logical([expected], [actual], shape(expected), shape(actual), message, location)
   end subroutine eq_l1_l1

   subroutine eq_l0_l2(expected, actual, message, location)
      logical, intent(in) :: expected
      logical, intent(in) :: actual(:,:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_logical([expected], [actual], shape(expected), shape(actual), message, location)
   end subroutine eq_l0_l2

   subroutine eq_l2_l2(expected, actual, message, location)
      logical, intent(in) :: expected(:,:)
      logical, intent(in) :: actual(:,:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_logical([expected], [actual], shape(expected), shape(actual), message, location)
   end subroutine eq_l2_l2

   subroutine eq_i0_r0(expected, actual, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, real([expected], real64), [actual], 0.0_real64, shape(expected), shape(actual), message, location)
   end subroutine eq_i0_r0

   subroutine eq_i0_r1(expected, actual, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, real([expected], real64), [actual], 0.0_real64, shape(expected), shape(actual), message, location)
   end subroutine eq_i0_r1

   subroutine eq_i1_r1(expected, actual, message, location)
      integer, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, real([expected], real64), [actual], 0.0_real64, shape(expected), shape(actual), message, location)
   end subroutine eq_i1_r1

   subroutine eq_i0_r2(expected, actual, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:,:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, real([expected], real64), [actual], 0.0_real64, shape(expected), shape(actual), message, location)
   end subroutine eq_i0_r2

   subroutine eq_i2_r2(expected, actual, message, location)
      integer, intent(in) :: expected(:,:)
      real(real64), intent(in) :: actual(:,:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, real([expected], real64), [actual], 0.0_real64, shape(expected), shape(actual), message, location)
   end subroutine eq_i2_r2

   subroutine eq_i0_r0_tol(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, real([expected], real64), [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine eq_i0_r0_tol

   subroutine eq_i0_r1_tol(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, real([expected], real64), [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine eq_i0_r1_tol

   subroutine eq_i1_r1_tol(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, real([expected], real64), [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine eq_i1_r1_tol

   subroutine eq_i0_r2_tol(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:,:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, real([expected], real64), [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine eq_i0_r2_tol

   subroutine eq_i2_r2_tol(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected(:,:)
      real(real64), intent(in) :: actual(:,:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, real([expected], real64), [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine eq_i2_r2_tol

   subroutine eq_r0_r0(expected, actual, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, [expected], [actual], 0.0_real64, shape(expected), shape(actual), message, location)
   end subroutine eq_r0_r0

   subroutine eq_r0_r1(expected, actual, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, [expected], [actual], 0.0_real64, shape(expected), shape(actual), message, location)
   end subroutine eq_r0_r1

   subroutine eq_r1_r1(expected, actual, message, location)
      real(real64), intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, [expected], [actual], 0.0_real64, shape(expected), shape(actual), message, location)
   end subroutine eq_r1_r1

   subroutine eq_r0_r2(expected, actual, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:,:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, [expected], [actual], 0.0_real64, shape(expected), shape(actual), message, location)
   end subroutine eq_r0_r2

   subroutine eq_r2_r2(expected, actual, message, location)
      real(real64), intent(in) :: expected(:,:)
      real(real64), intent(in) :: actual(:,:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, [expected], [actual], 0.0_real64, shape(expected), shape(actual), message, location)
   end subroutine eq_r2_r2

   subroutine eq_r0_r0_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, [expected], [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine eq_r0_r0_tol

   subroutine eq_r0_r1_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, [expected], [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine eq_r0_r1_tol

   subroutine eq_r1_r1_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, [expected], [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine eq_r1_r1_tol

   subroutine eq_r0_r2_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:,:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, [expected], [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine eq_r0_r2_tol

   subroutine eq_r2_r2_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:,:)
      real(real64), intent(in) :: actual(:,:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_EQ, [expected], [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine eq_r2_r2_tol

   subroutine rel_i0_r0_tol(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_REL, real([expected], real64), [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine rel_i0_r0_tol

   subroutine rel_i0_r1_tol(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_REL, real([expected], real64), [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine rel_i0_r1_tol

   subroutine rel_i1_r1_tol(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_REL, real([expected], real64), [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine rel_i1_r1_tol

   subroutine rel_i0_r2_tol(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:,:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_REL, real([expected], real64), [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine rel_i0_r2_tol

   subroutine rel_i2_r2_tol(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected(:,:)
      real(real64), intent(in) :: actual(:,:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_REL, real([expected], real64), [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine rel_i2_r2_tol

   subroutine rel_r0_r0_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_REL, [expected], [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine rel_r0_r0_tol

   subroutine rel_r0_r1_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_REL, [expected], [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine rel_r0_r1_tol

   subroutine rel_r1_r1_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_REL, [expected], [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine rel_r1_r1_tol

   subroutine rel_r0_r2_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:,:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_REL, [expected], [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine rel_r0_r2_tol

   subroutine rel_r2_r2_tol(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:,:)
      real(real64), intent(in) :: actual(:,:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_REL, [expected], [actual], tolerance, shape(expected), shape(actual), message, location)
   end subroutine rel_r2_r2_tol

   subroutine lt_i0_r0(lhs, rhs, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_LT, real([lhs], real64), [rhs], 0.0_real64, shape(lhs), shape(rhs), message, location)
   end subroutine lt_i0_r0

   subroutine lt_r0_r0(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_LT, [lhs], [rhs], 0.0_real64, shape(lhs), shape(rhs), message, location)
   end subroutine lt_r0_r0

   subroutine le_i0_r0(lhs, rhs, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_LE, real([lhs], real64), [rhs], 0.0_real64, shape(lhs), shape(rhs), message, location)
   end subroutine le_i0_r0

   subroutine le_r0_r0(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_LE, [lhs], [rhs], 0.0_real64, shape(lhs), shape(rhs), message, location)
   end subroutine le_r0_r0

   subroutine gt_i0_r0(lhs, rhs, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_GT, real([lhs], real64), [rhs], 0.0_real64, shape(lhs), shape(rhs), message, location)
   end subroutine gt_i0_r0

   subroutine gt_r0_r0(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_GT, [lhs], [rhs], 0.0_real64, shape(lhs), shape(rhs), message, location)
   end subroutine gt_r0_r0

   subroutine ge_i0_r0(lhs, rhs, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_GE, real([lhs], real64), [rhs], 0.0_real64, shape(lhs), shape(rhs), message, location)
   end subroutine ge_i0_r0

   subroutine ge_r0_r0(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      call compare_real(OP_GE, [lhs], [rhs], 0.0_real64, shape(lhs), shape(rhs), message, location)
   end subroutine ge_r0_r0

end module funit
