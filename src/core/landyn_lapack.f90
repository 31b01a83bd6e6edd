!> The one place where LANDYN calls LAPACK (and the small unblocked Cholesky of landyn_small_spd,
!! which replaces LAPACK's dpotf2 and BLAS dtrsv bit for bit at the orders of the time loop).
!! Each wrapper turns LAPACK's INFO into a status_t (code STAT_DIVERGED for a singular or not
!! positive-definite matrix, STAT_FAILED for an illegal argument, never INFO itself, whose values
!! would collide with the other STAT_* codes; INFO is in the message, which names the system; the
!! status is left alone on success). Arrays are overwritten as LAPACK does (factorisation in A,
!! solution in B). The matrix is passed with an explicit leading
!! dimension so that callers hand over a whole (contiguous) work array and no temporary copy is
!! made: no allocation in the time loop.
module landyn_lapack
  use landyn_kinds, only: wp
  use landyn_small_spd, only: small_upper_factor, small_upper_solve
  use landyn_status, only: status_t, STAT_DIVERGED, STAT_FAILED
  use landyn_strings, only: int_text
  implicit none
  private

  public :: solve_general, solve_spd, factor_spd, solve_spd_unblocked
  public :: factor_spd_unblocked

  character(len=*), parameter :: constraint_hint = '; constraints redundant or singular configuration'  !! [-]

  interface
    !> LAPACK dpotrf: blocked Cholesky factorisation A = U^T U.
    subroutine dpotrf(uplo, n, a, lda, info)
      import :: wp
      character(len=1), intent(in) :: uplo      !! 'U': upper triangle [-]
      integer, intent(in) :: n, lda             !! order, leading dimension [-]
      real(wp), intent(inout) :: a(lda, *)      !! matrix in, factor out [any]
      integer, intent(out) :: info              !! LAPACK INFO [-]
    end subroutine dpotrf
  end interface

  interface
    !> LAPACK dgesv: solves A X = B for a general A by LU factorisation with partial pivoting.
    subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: wp
      integer, intent(in) :: n, nrhs, lda, ldb         !! order, right-hand sides, leading dimensions [-]
      real(wp), intent(inout) :: a(lda, *), b(ldb, *)  !! matrix in, LU factors out; right-hand sides in, solutions out [any]
      integer, intent(out) :: ipiv(*)                  !! pivot indices (row i was swapped with ipiv(i)) [-]
      integer, intent(out) :: info                     !! LAPACK INFO: 0 ok, < 0 illegal argument, > 0 U(i,i) zero [-]
    end subroutine dgesv
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
  subroutine solve_general(n, a, lda, b, status, what)
    integer, intent(in) :: n                       !! order of the system [-]
    integer, intent(in) :: lda                     !! leading dimension of a (>= n) [-]
    real(wp), intent(inout) :: a(lda, n)           !! matrix in a(1:n,1:n); overwritten by its LU factors [any]
    real(wp), intent(inout) :: b(n)                !! right-hand side in, solution out [any]
    type(status_t), intent(inout) :: status        !! unchanged on success; STAT_DIVERGED or STAT_FAILED and message otherwise [-]
    character(len=*), intent(in) :: what           !! name of the system, for the message [-]
    integer :: ipiv(n), info
    call dgesv(n, 1, a, lda, ipiv, b, n, info)
    if (info > 0) then
      call status%fail(STAT_DIVERGED, trim(what)//': matrix is singular (LAPACK dgesv: U('//int_text(info)//','// &
        int_text(info)//') = 0)')
    else if (info < 0) then
      call illegal_argument(info, 'dgesv', what, status)
    end if
  end subroutine solve_general

  !> Solves A X = B for a symmetric positive-definite A by Cholesky (LAPACK dposv, upper triangle used).
  subroutine solve_spd(n, a, lda, b, status, what)
    integer, intent(in) :: n                       !! order of the system [-]
    integer, intent(in) :: lda                     !! leading dimension of a (>= n) [-]
    real(wp), intent(inout) :: a(lda, n)           !! SPD matrix in a(1:n,1:n) (upper triangle used);
                                                   !! overwritten by its factor [any]
    real(wp), intent(inout) :: b(n)                !! right-hand side in, solution out [any]
    type(status_t), intent(inout) :: status        !! unchanged on success; STAT_DIVERGED or STAT_FAILED and message otherwise [-]
    character(len=*), intent(in) :: what           !! name of the system, for the message [-]
    integer :: info
    call dposv('U', n, 1, a, lda, b, n, info)
    if (info /= 0) call spd_info(info, 'LAPACK dposv', what, constraint_hint, status)
  end subroutine solve_spd

  !> Solves A x = b for a small symmetric positive-definite A with the unblocked Cholesky factor and
  !! triangular solves of landyn_small_spd: bit-identical to LAPACK's dpotf2 and BLAS dtrsv, without
  !! their argument handling, which dominates at the sizes of a gear's DAE (order 6 to 9).
  subroutine solve_spd_unblocked(n, a, lda, b, status, what)
    integer, intent(in) :: n                       !! order of the system [-]
    integer, intent(in) :: lda                     !! leading dimension of a (>= n) [-]
    real(wp), intent(inout) :: a(lda, n)           !! SPD matrix (upper triangle used); overwritten by its factor [any]
    real(wp), intent(inout) :: b(n)                !! right-hand side in, solution out [any]
    type(status_t), intent(inout) :: status        !! unchanged on success; STAT_DIVERGED or STAT_FAILED and
                                                   !! message otherwise [-]
    character(len=*), intent(in) :: what           !! name of the system, for the message [-]
    integer :: info
    call cholesky(.true., n, a, lda, info, status, what, constraint_hint)
    if (info /= 0) return
    call small_upper_solve(n, a, lda, b, .true.)
    call small_upper_solve(n, a, lda, b, .false.)
  end subroutine solve_spd_unblocked

  !> Cholesky factorisation of a symmetric positive-definite A (LAPACK dpotrf, upper triangle),
  !! for repeated solves with landyn_small_spd's small_upper_solve_multi.
  subroutine factor_spd(n, a, lda, status, what)
    integer, intent(in) :: n                       !! order of the system [-]
    integer, intent(in) :: lda                     !! leading dimension of a (>= n) [-]
    real(wp), intent(inout) :: a(lda, n)           !! SPD matrix in, its Cholesky factor out [any]
    type(status_t), intent(inout) :: status        !! unchanged on success; STAT_DIVERGED or STAT_FAILED and message otherwise [-]
    character(len=*), intent(in) :: what           !! name of the system, for the message [-]
    integer :: info
    call cholesky(.false., n, a, lda, info, status, what, constraint_hint)
  end subroutine factor_spd

  !> Cholesky factorisation A = R^T R of a small symmetric positive-definite A, unblocked (upper
  !! triangle; landyn_small_spd's small_upper_factor, bit-identical to LAPACK's dpotf2), for the
  !! triangular solves of landyn_small_spd.
  subroutine factor_spd_unblocked(n, a, lda, status, what)
    integer, intent(in) :: n                       !! order of the system [-]
    integer, intent(in) :: lda                     !! leading dimension of a (>= n) [-]
    real(wp), intent(inout) :: a(lda, n)           !! SPD matrix in, its factor R out (upper triangle) [any]
    type(status_t), intent(inout) :: status        !! unchanged on success; STAT_DIVERGED or STAT_FAILED and
                                                   !! message otherwise [-]
    character(len=*), intent(in) :: what           !! name of the system, for the message [-]
    integer :: info
    call cholesky(.true., n, a, lda, info, status, what, '')
  end subroutine factor_spd_unblocked

  !> Upper Cholesky factor of A, unblocked (small_upper_factor, dpotf2's operations) or blocked
  !! (LAPACK dpotrf); info = INFO, and on failure the status (spd_info, `hint` after the minor's number).
  subroutine cholesky(unblocked, n, a, lda, info, status, what, hint)
    logical, intent(in) :: unblocked               !! small_upper_factor rather than dpotrf [-]
    integer, intent(in) :: n                       !! order of the system [-]
    integer, intent(in) :: lda                     !! leading dimension of a (>= n) [-]
    real(wp), intent(inout) :: a(lda, n)           !! SPD matrix in, R out (upper triangle) [any]
    integer, intent(out) :: info                   !! 0 on success, LAPACK INFO otherwise [-]
    type(status_t), intent(inout) :: status        !! unchanged on success; STAT_DIVERGED or STAT_FAILED and message otherwise [-]
    character(len=*), intent(in) :: what           !! name of the system [-]
    character(len=*), intent(in) :: hint           !! text after the minor's number in the message [-]
    if (unblocked) then
      call small_upper_factor(n, a, lda, info)
      if (info /= 0) call spd_info(info, 'unblocked Cholesky', what, hint, status)
    else
      call dpotrf('U', n, a, lda, info)
      if (info /= 0) call spd_info(info, 'LAPACK dpotrf', what, hint, status)
    end if
  end subroutine cholesky

  !> The status of a Cholesky routine's nonzero INFO: STAT_DIVERGED (STAT_FAILED when INFO < 0) and its message.
  subroutine spd_info(info, routine, what, hint, status)
    integer, intent(in) :: info                    !! LAPACK INFO, /= 0 [-]
    character(len=*), intent(in) :: routine        !! factorisation, e.g. 'LAPACK dpotrf' [-]
    character(len=*), intent(in) :: what           !! name of the system [-]
    character(len=*), intent(in) :: hint           !! text after the minor's number [-]
    type(status_t), intent(inout) :: status        !! receives code and message [-]
    if (info > 0) then
      call status%fail(STAT_DIVERGED, trim(what)//': matrix is not positive definite ('//routine//': leading minor '// &
        int_text(info)//' is not positive'//hint//')')
    else if (info < 0) then
      call illegal_argument(info, routine, what, status)
    end if
  end subroutine spd_info

  !> The status of a negative LAPACK INFO: STAT_FAILED and its message.
  subroutine illegal_argument(info, routine, what, status)
    integer, intent(in) :: info                    !! LAPACK INFO, < 0 [-]
    character(len=*), intent(in) :: routine        !! LAPACK routine [-]
    character(len=*), intent(in) :: what           !! name of the system [-]
    type(status_t), intent(inout) :: status        !! receives code and message [-]
    call status%fail(STAT_FAILED, trim(what)//': illegal argument '//int_text(-info)//' to LAPACK '//routine)
  end subroutine illegal_argument

end module landyn_lapack
