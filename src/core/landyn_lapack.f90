!> The one place where LANDYN calls LAPACK. Each wrapper turns LAPACK's INFO into a status
!! and a message. Arrays are overwritten as LAPACK does (factorisation in A, solution in B).
!! The matrix is passed with an explicit leading dimension so that callers hand over a whole
!! (contiguous) work array and no temporary copy is made: no allocation in the time loop.
module landyn_lapack
  use landyn_kinds, only: wp
  implicit none
  private

  public :: solve_general, solve_spd, factor_spd, solve_spd_unblocked
  public :: factor_spd_unblocked

  character(len=*), parameter :: constraint_hint = '; constraints redundant or singular configuration'  !! [-]

  abstract interface
    !> LAPACK's Cholesky factorisations (dpotrf blocked, dpotf2 unblocked) share one interface.
    subroutine cholesky_iface(uplo, n, a, lda, info)
      import :: wp
      character(len=1), intent(in) :: uplo      !! 'U': upper triangle [-]
      integer, intent(in) :: n, lda             !! order, leading dimension [-]
      real(wp), intent(inout) :: a(lda, *)      !! matrix in, factor out [any]
      integer, intent(out) :: info              !! LAPACK INFO [-]
    end subroutine cholesky_iface
  end interface

  !> LAPACK dpotrf (blocked) and dpotf2 (unblocked) Cholesky factorisations A = U^T U.
  procedure(cholesky_iface) :: dpotrf, dpotf2

  interface
    !> LAPACK dgesv: solves A X = B for a general A by LU factorisation with partial pivoting.
    subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: wp
      integer, intent(in) :: n, nrhs, lda, ldb         !! order, right-hand sides, leading dimensions [-]
      real(wp), intent(inout) :: a(lda, *), b(ldb, *)  !! matrix in, LU factors out; right-hand sides in, solutions out [any]
      integer, intent(out) :: ipiv(*)                  !! pivot indices (row i was swapped with ipiv(i)) [-]
      integer, intent(out) :: info                     !! LAPACK INFO: 0 ok, < 0 illegal argument, > 0 U(i,i) zero [-]
    end subroutine dgesv
    !> BLAS dtrsv: solves a triangular system A x = b or A^T x = b in place.
    subroutine dtrsv(uplo, trans, diag, n, a, lda, x, incx)
      import :: wp
      character(len=1), intent(in) :: uplo, trans, diag  !! 'U'|'L' triangle, 'N'|'T' transpose, 'N'|'U' unit diagonal [-]
      integer, intent(in) :: n, lda, incx                !! order, leading dimension, stride of x [-]
      real(wp), intent(in) :: a(lda, *)                  !! triangular matrix [any]
      real(wp), intent(inout) :: x(*)                    !! right-hand side in, solution out [any]
    end subroutine dtrsv
    !> LAPACK dposv: solves A X = B for a symmetric positive-definite A by Cholesky factorisation.
    subroutine dposv(uplo, n, nrhs, a, lda, b, ldb, info)
      import :: wp
      character(len=1), intent(in) :: uplo              !! triangle of A that is used, 'U' or 'L' [-]
      integer, intent(in) :: n, nrhs, lda, ldb          !! order, right-hand sides, leading dimensions [-]
      real(wp), intent(inout) :: a(lda, *), b(ldb, *)   !! matrix in, Cholesky factor out; right-hand sides in, solutions out [any]
      integer, intent(out) :: info                      !! LAPACK INFO: 0 ok, < 0 illegal argument, > 0 not positive definite [-]
    end subroutine dposv
  end interface

contains

  !> Solves A X = B for a general square A by LU with partial pivoting (LAPACK dgesv).
  subroutine solve_general(n, a, lda, b, stat, errmsg, what)
    integer, intent(in) :: n                       !! order of the system [-]
    integer, intent(in) :: lda                     !! leading dimension of a (>= n) [-]
    real(wp), intent(inout) :: a(lda, n)           !! matrix in a(1:n,1:n); overwritten by its LU factors [any]
    real(wp), intent(inout) :: b(n)                !! right-hand side in, solution out [any]
    integer, intent(out) :: stat                   !! 0 on success, LAPACK INFO otherwise [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    character(len=*), intent(in) :: what           !! name of the system, for the message [-]
    integer :: ipiv(n), info
    call dgesv(n, 1, a, lda, ipiv, b, n, info)
    stat = info
    if (info > 0) then
      write (errmsg, '(a,a,i0,a,i0,a)') trim(what), ': matrix is singular (LAPACK dgesv: U(', info, ',', &
        info, ') = 0)'
    else if (info < 0) then
      call illegal_argument(info, 'dgesv', what, errmsg)
    end if
  end subroutine solve_general

  !> Solves A X = B for a symmetric positive-definite A by Cholesky (LAPACK dposv, upper triangle used).
  subroutine solve_spd(n, a, lda, b, stat, errmsg, what)
    integer, intent(in) :: n                       !! order of the system [-]
    integer, intent(in) :: lda                     !! leading dimension of a (>= n) [-]
    real(wp), intent(inout) :: a(lda, n)           !! SPD matrix in a(1:n,1:n) (upper triangle used);
                                                   !! overwritten by its factor [any]
    real(wp), intent(inout) :: b(n)                !! right-hand side in, solution out [any]
    integer, intent(out) :: stat                   !! 0 on success, LAPACK INFO otherwise [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    character(len=*), intent(in) :: what           !! name of the system, for the message [-]
    integer :: info
    call dposv('U', n, 1, a, lda, b, n, info)
    stat = info
    call spd_info(info, 'dposv', what, constraint_hint, errmsg)
  end subroutine solve_spd

  !> Solves A x = b for a small symmetric positive-definite A with LAPACK's unblocked Cholesky
  !! (dpotf2) and two BLAS triangular solves (dtrsv): the same arithmetic as dposv without the
  !! blocking machinery, about half the cost at the sizes of a gear's DAE (order 6 to 9).
  subroutine solve_spd_unblocked(n, a, lda, b, stat, errmsg, what)
    integer, intent(in) :: n                       !! order of the system [-]
    integer, intent(in) :: lda                     !! leading dimension of a (>= n) [-]
    real(wp), intent(inout) :: a(lda, n)           !! SPD matrix (upper triangle used); overwritten by its factor [any]
    real(wp), intent(inout) :: b(n)                !! right-hand side in, solution out [any]
    integer, intent(out) :: stat                   !! 0 on success, LAPACK INFO otherwise [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    character(len=*), intent(in) :: what           !! name of the system, for the message [-]
    call cholesky(.true., n, a, lda, stat, errmsg, what, constraint_hint)
    if (stat /= 0) return
    call dtrsv('U', 'T', 'N', n, a, lda, b, 1)
    call dtrsv('U', 'N', 'N', n, a, lda, b, 1)
  end subroutine solve_spd_unblocked

  !> Cholesky factorisation of a symmetric positive-definite A (LAPACK dpotrf, upper triangle),
  !! for repeated solves with landyn_small_spd's small_upper_solve_multi.
  subroutine factor_spd(n, a, lda, stat, errmsg, what)
    integer, intent(in) :: n                       !! order of the system [-]
    integer, intent(in) :: lda                     !! leading dimension of a (>= n) [-]
    real(wp), intent(inout) :: a(lda, n)           !! SPD matrix in, its Cholesky factor out [any]
    integer, intent(out) :: stat                   !! 0 on success, LAPACK INFO otherwise [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    character(len=*), intent(in) :: what           !! name of the system, for the message [-]
    call cholesky(.false., n, a, lda, stat, errmsg, what, constraint_hint)
  end subroutine factor_spd

  !> Cholesky factorisation A = R^T R of a small symmetric positive-definite A with LAPACK's
  !! unblocked dpotf2 (upper triangle), for the triangular solves of landyn_small_spd.
  subroutine factor_spd_unblocked(n, a, lda, stat, errmsg, what)
    integer, intent(in) :: n                       !! order of the system [-]
    integer, intent(in) :: lda                     !! leading dimension of a (>= n) [-]
    real(wp), intent(inout) :: a(lda, n)           !! SPD matrix in, its factor R out (upper triangle) [any]
    integer, intent(out) :: stat                   !! 0 on success, LAPACK INFO otherwise [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    character(len=*), intent(in) :: what           !! name of the system, for the message [-]
    call cholesky(.true., n, a, lda, stat, errmsg, what, '')
  end subroutine factor_spd_unblocked

  !> Upper Cholesky factor of A with LAPACK's dpotf2 (unblocked) or dpotrf (blocked); stat =
  !! INFO and its message (spd_info, `hint` after the minor's number).
  subroutine cholesky(unblocked, n, a, lda, stat, errmsg, what, hint)
    logical, intent(in) :: unblocked               !! dpotf2 rather than dpotrf [-]
    integer, intent(in) :: n                       !! order of the system [-]
    integer, intent(in) :: lda                     !! leading dimension of a (>= n) [-]
    real(wp), intent(inout) :: a(lda, n)           !! SPD matrix in, R out (upper triangle) [any]
    integer, intent(out) :: stat                   !! 0 on success, LAPACK INFO otherwise [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    character(len=*), intent(in) :: what           !! name of the system [-]
    character(len=*), intent(in) :: hint           !! text after the minor's number in the message [-]
    if (unblocked) then
      call dpotf2('U', n, a, lda, stat)
      if (stat /= 0) call spd_info(stat, 'dpotf2', what, hint, errmsg)
    else
      call dpotrf('U', n, a, lda, stat)
      if (stat /= 0) call spd_info(stat, 'dpotrf', what, hint, errmsg)
    end if
  end subroutine cholesky

  !> The message of a Cholesky routine's INFO (nothing for INFO = 0).
  subroutine spd_info(info, routine, what, hint, errmsg)
    integer, intent(in) :: info                    !! LAPACK INFO [-]
    character(len=*), intent(in) :: routine        !! LAPACK routine [-]
    character(len=*), intent(in) :: what           !! name of the system [-]
    character(len=*), intent(in) :: hint           !! text after the minor's number [-]
    character(len=*), intent(inout) :: errmsg      !! message [-]
    if (info > 0) then
      write (errmsg, '(a,a,a,a,i0,a,a,a)') trim(what), ': matrix is not positive definite (LAPACK ', routine, &
        ': leading minor ', info, ' is not positive', hint, ')'
    else if (info < 0) then
      call illegal_argument(info, routine, what, errmsg)
    end if
  end subroutine spd_info

  !> The message of a negative LAPACK INFO.
  subroutine illegal_argument(info, routine, what, errmsg)
    integer, intent(in) :: info                    !! LAPACK INFO, < 0 [-]
    character(len=*), intent(in) :: routine        !! LAPACK routine [-]
    character(len=*), intent(in) :: what           !! name of the system [-]
    character(len=*), intent(inout) :: errmsg      !! message [-]
    write (errmsg, '(a,a,i0,a,a)') trim(what), ': illegal argument ', -info, ' to LAPACK ', routine
  end subroutine illegal_argument

end module landyn_lapack
