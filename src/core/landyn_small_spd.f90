!> Cholesky solve of small symmetric positive-definite systems (order <= 16), for the constraint
!! projections of Step 4 that run several times per gear and time step. At these sizes the
!! reference LAPACK dposv spends most of its ~5,000 instructions per call on blocking and argument
!! handling; this unblocked version needs a few hundred. It is checked against LAPACK in
!! tests/unit/test_small_spd.pf. The gear DAE itself (eq. 14) is solved with LAPACK.
!!
!! small_upper_solve, small_upper_solve_multi and small_upper_solve_rows are the triangular solves
!! with a Cholesky factor from LAPACK (landyn_lapack's factor_spd_unblocked) for the whole-system
!! velocity projection, which runs at every step (small_upper_solve, small_upper_solve_rows), and
!! the gear's cached constraint factor (small_upper_solve_multi): the reference BLAS dtrsm/dtrsv
!! spend most of their time on argument checks at orders <= 9. They do the same operations in the same order as
!! dtrsv/dtrsm (upper, non-unit; the BLAS skip a column whose pivot entry is zero, which changes at
!! most the sign of a zero), so that results are bit-identical to LAPACK's dpotrs.
!! small_upper_solve_rows takes solve_rows_width right-hand sides stored as rows, so that their
!! operations run side by side in vector instructions (the projection's D_i^-1 [g_i, U_i]).
!!
!! small_upper_factor is the Cholesky factorisation in the order of operations of the reference
!! LAPACK dpotf2 (upper; its ddot, dgemv and dscal with unit or row stride): bit-identical to it,
!! at a fraction of the cost at these orders (the reference routines' argument checks, lsame and
!! disnan calls cost ~15 % of a run). Why not a library: no maintained Fortran library offers
!! an unblocked small-matrix Cholesky that is bit-identical to the LAPACK factor it replaces.
!!
!! The scalar loops of runtime length (a few passes at these orders) carry `!GCC$ unroll 1`: the
!! Release build's -funroll-loops would give each a remainder dispatch that costs more than the
!! loop (13 % of small_upper_factor's instructions). A comment to other compilers; it changes no
!! operation or its order.
module landyn_small_spd
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  use landyn_kinds, only: wp
  implicit none
  private

  public :: small_spd_solve, small_upper_solve, small_upper_solve_multi, small_upper_solve_rows, small_upper_factor

  integer, parameter, public :: solve_rows_width = 8  !! right-hand sides of one small_upper_solve_rows call

contains

  !> Solves A x = b for SPD A (upper triangle used; A is overwritten by its Cholesky factor U,
  !! A = U^T U). stat = k > 0 when the leading minor of order k is not positive.
  pure subroutine small_spd_solve(n, a, lda, b, stat)
    integer, intent(in) :: n               !! order [-]
    integer, intent(in) :: lda             !! leading dimension of a [-]
    real(wp), intent(inout) :: a(lda, n)   !! matrix in, factor out [any]
    real(wp), intent(inout) :: b(n)        !! right-hand side in, solution out [any]
    integer, intent(out) :: stat           !! 0 on success [-]
    integer :: i, j, k
    real(wp) :: s
    stat = 0
    do j = 1, n
      s = a(j, j)
      do k = 1, j - 1
        s = s - a(k, j)*a(k, j)
      end do
      if (.not. (s > 0.0_wp)) then
        stat = j
        return
      end if
      a(j, j) = sqrt(s)
      do i = j + 1, n
        s = a(j, i)
        do k = 1, j - 1
          s = s - a(k, j)*a(k, i)
        end do
        a(j, i) = s/a(j, j)
      end do
    end do
    ! U^T y = b
    call small_upper_solve(n, a, lda, b, .true.)
    ! U x = y
    do i = n, 1, -1
      s = b(i)
      do k = i + 1, n
        s = s - a(i, k)*b(k)
      end do
      b(i) = s/a(i, i)
    end do
  end subroutine small_spd_solve

  !> Cholesky factor A = U^T U of an SPD matrix, upper triangle (A's strict lower triangle is not
  !! touched), in the order of operations of the reference LAPACK dpotf2 ('U'): bit-identical to it.
  !! stat = j > 0 when the leading minor of order j is not positive (or NaN); then a(j, j) holds the
  !! non-positive pivot and the factor stops there, as in dpotf2.
  pure subroutine small_upper_factor(n, a, lda, stat)
    integer, intent(in) :: n               !! order [-]
    integer, intent(in) :: lda             !! leading dimension of a [-]
    real(wp), intent(inout) :: a(lda, n)   !! matrix in, factor U out (upper triangle) [any]
    integer, intent(out) :: stat           !! 0 on success, else the order of the failing minor [-]
    integer :: i, j, k
    real(wp) :: ajj, r, s
    stat = 0
    do j = 1, n
      ! dpotf2: ajj = a(j, j) - ddot(j - 1, a(1, j), 1, a(1, j), 1); ddot sums from zero, in order
      s = 0.0_wp
      !GCC$ unroll 1
      do k = 1, j - 1
        s = s + a(k, j)*a(k, j)
      end do
      ajj = a(j, j) - s
      if (ajj <= 0.0_wp .or. ieee_is_nan(ajj)) then
        a(j, j) = ajj
        stat = j
        return
      end if
      ajj = sqrt(ajj)
      a(j, j) = ajj
      ! dgemv('T', j - 1, n - j, -1, a(1, j + 1), lda, a(1, j), 1, 1, a(j, j + 1), lda), then
      ! dscal(n - j, 1/ajj, a(j, j + 1), lda)
      r = 1.0_wp/ajj
      !GCC$ unroll 1
      do i = j + 1, n
        s = 0.0_wp
        !GCC$ unroll 1
        do k = 1, j - 1
          s = s + a(k, i)*a(k, j)
        end do
        a(j, i) = r*(a(j, i) - s)
      end do
    end do
  end subroutine small_upper_factor

  !> x <- U^-T x (transposed) or x <- U^-1 x for an upper triangular U (BLAS dtrsv 'U', 'T'|'N', 'N'
  !! with unit stride, same order of operations).
  pure subroutine small_upper_solve(n, u, ldu, x, transposed)
    integer, intent(in) :: n               !! order [-]
    integer, intent(in) :: ldu             !! leading dimension of u [-]
    real(wp), intent(in) :: u(ldu, n)      !! upper triangular factor [any]
    real(wp), intent(inout) :: x(n)        !! right-hand side in, solution out [any]
    logical, intent(in) :: transposed      !! solve with U^T instead of U [-]
    integer :: i, j
    real(wp) :: s
    if (transposed) then
      do j = 1, n
        s = x(j)
        !GCC$ unroll 1
        do i = 1, j - 1
          s = s - u(i, j)*x(i)
        end do
        x(j) = s/u(j, j)
      end do
    else
      do j = n, 1, -1
        x(j) = x(j)/u(j, j)
        s = x(j)
        !GCC$ unroll 1
        do i = j - 1, 1, -1
          x(i) = x(i) - s*u(i, j)
        end do
      end do
    end if
  end subroutine small_upper_solve

  !> B <- (U^T U)^-1 B for the Cholesky factor U of an SPD matrix and several right-hand sides,
  !! column by column (LAPACK dpotrs 'U': dtrsm with U^T, then with U, does the same operations on
  !! each column in the same order).
  pure subroutine small_upper_solve_multi(n, nrhs, u, ldu, b, ldb)
    integer, intent(in) :: n               !! order [-]
    integer, intent(in) :: nrhs            !! number of right-hand sides [-]
    integer, intent(in) :: ldu             !! leading dimension of u [-]
    real(wp), intent(in) :: u(ldu, n)      !! upper triangular Cholesky factor [any]
    integer, intent(in) :: ldb             !! leading dimension of b [-]
    real(wp), intent(inout) :: b(ldb, nrhs)  !! right-hand sides in, solutions out [any]
    integer :: j
    do j = 1, nrhs
      call small_upper_solve(n, u, ldu, b(1:n, j), .true.)
      call small_upper_solve(n, u, ldu, b(1:n, j), .false.)
    end do
  end subroutine small_upper_solve_multi

  !> X <- (U^T U)^-1 X for the Cholesky factor U of an SPD matrix and solve_rows_width right-hand
  !! sides stored as rows: x(:, i) holds component i of each. Each right-hand side gets the
  !! operations of small_upper_solve (U^T, then U) in their order; the eight are done side by side
  !! in fixed-length row operations, which the compiler turns into vector instructions (each lane
  !! the same IEEE operation as the scalar one).
  pure subroutine small_upper_solve_rows(n, u, ldu, x)
    integer, intent(in) :: n               !! order [-]
    integer, intent(in) :: ldu             !! leading dimension of u [-]
    real(wp), intent(in) :: u(ldu, n)      !! upper triangular Cholesky factor [any]
    real(wp), intent(inout) :: x(solve_rows_width, n)  !! right-hand sides in, solutions out [any]
    real(wp) :: s(solve_rows_width)
    integer :: i, j
    ! U^T y = b
    do j = 1, n
      s = x(:, j)
      do i = 1, j - 1
        s = s - u(i, j)*x(:, i)
      end do
      x(:, j) = s/u(j, j)
    end do
    ! U x = y by rows: component i gets small_upper_solve's updates x(i) - x(j) u(i, j) in its order
    ! (j = n down to i + 1), then the division
    do i = n, 1, -1
      s = x(:, i)
      do j = n, i + 1, -1
        s = s - x(:, j)*u(i, j)
      end do
      x(:, i) = s/u(i, i)
    end do
  end subroutine small_upper_solve_rows

end module landyn_small_spd
