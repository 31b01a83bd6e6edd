!> The one place where LANDYN calls LAPACK. Each wrapper turns LAPACK's INFO into a status
!! and a message. Arrays are overwritten as LAPACK does (factorisation in A, solution in B).
!! No allocation: the pivot workspace is an automatic array of the (small) system size.
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
  subroutine solve_general(n, a, b, stat, errmsg, what)
    integer, intent(in) :: n                       !! order of the system [-]
    real(wp), intent(inout) :: a(:, :)             !! n x n matrix; overwritten by its LU factors [any]
    real(wp), intent(inout) :: b(:)                !! right-hand side in, solution out [any]
    integer, intent(out) :: stat                   !! 0 on success, LAPACK INFO otherwise [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    character(len=*), intent(in) :: what           !! name of the system, for the message [-]
    integer :: ipiv(n), info
    call dgesv(n, 1, a, size(a, 1), ipiv, b, size(b), info)
    stat = info
    if (info > 0) then
      write (errmsg, '(a,a,i0,a,i0,a)') trim(what), ': matrix is singular (LAPACK dgesv: U(', info, ',', &
        info, ') = 0)'
    else if (info < 0) then
      write (errmsg, '(a,a,i0,a)') trim(what), ': illegal argument ', -info, ' to LAPACK dgesv'
    end if
  end subroutine solve_general

  !> Solves A X = B for a symmetric positive-definite A by Cholesky (LAPACK dposv, upper triangle used).
  subroutine solve_spd(n, a, b, stat, errmsg, what)
    integer, intent(in) :: n                       !! order of the system [-]
    real(wp), intent(inout) :: a(:, :)             !! n x n SPD matrix; overwritten by its factor [any]
    real(wp), intent(inout) :: b(:)                !! right-hand side in, solution out [any]
    integer, intent(out) :: stat                   !! 0 on success, LAPACK INFO otherwise [-]
    character(len=*), intent(inout) :: errmsg      !! message on failure [-]
    character(len=*), intent(in) :: what           !! name of the system, for the message [-]
    integer :: info
    call dposv('U', n, 1, a, size(a, 1), b, size(b), info)
    stat = info
    if (info > 0) then
      write (errmsg, '(a,a,i0,a)') trim(what), ': matrix is not positive definite (LAPACK dposv: leading minor ', &
        info, ' is not positive; constraints redundant or singular configuration)'
    else if (info < 0) then
      write (errmsg, '(a,a,i0,a)') trim(what), ': illegal argument ', -info, ' to LAPACK dposv'
    end if
  end subroutine solve_spd

end module landyn_lapack
