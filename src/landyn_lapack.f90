!> The one place where LANDYN calls LAPACK. Each wrapper turns LAPACK's INFO into a status
!! and a message. Arrays are overwritten as LAPACK does (factorisation in A, solution in B).
!! The matrix is passed with an explicit leading dimension so that callers hand over a whole
!! (contiguous) work array and no temporary copy is made: no allocation in the time loop.
module landyn_lapack
  use landyn_kinds, only: wp
  implicit none
  private

  public :: solve_general, solve_spd

  interface
    subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: wp
      integer, intent(in) :: n, nrhs, lda, ldb
      real(wp), intent(inout) :: a(lda, *), b(ldb, *)
      integer, intent(out) :: ipiv(*)
      integer, intent(out) :: info
    end subroutine dgesv
    subroutine dposv(uplo, n, nrhs, a, lda, b, ldb, info)
      import :: wp
      character(len=1), intent(in) :: uplo
      integer, intent(in) :: n, nrhs, lda, ldb
      real(wp), intent(inout) :: a(lda, *), b(ldb, *)
      integer, intent(out) :: info
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
      write (errmsg, '(a,a,i0,a)') trim(what), ': illegal argument ', -info, ' to LAPACK dgesv'
    end if
  end subroutine solve_general

  !> Solves A X = B for a symmetric positive-definite A by Cholesky (LAPACK dposv, upper triangle used).
  subroutine solve_spd(n, a, lda, b, stat, errmsg, what)
    integer, intent(in) :: n                       !! order of the system [-]
    integer, intent(in) :: lda                     !! leading dimension of a (>= n) [-]
    real(wp), intent(inout) :: a(lda, n)           !! SPD matrix in a(1:n,1:n) (upper triangle used); overwritten by its factor [any]
    real(wp), intent(inout) :: b(n)                !! right-hand side in, solution out [any]
    integer, intent(out) :: stat                   !! 0 on success, LAPACK INFO otherwise [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    character(len=*), intent(in) :: what           !! name of the system, for the message [-]
    integer :: info
    call dposv('U', n, 1, a, lda, b, n, info)
    stat = info
    if (info > 0) then
      write (errmsg, '(a,a,i0,a)') trim(what), ': matrix is not positive definite (LAPACK dposv: leading minor ', &
        info, ' is not positive; constraints redundant or singular configuration)'
    else if (info < 0) then
      write (errmsg, '(a,a,i0,a)') trim(what), ': illegal argument ', -info, ' to LAPACK dposv'
    end if
  end subroutine solve_spd

end module landyn_lapack
