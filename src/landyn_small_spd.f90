!> Cholesky solve of small symmetric positive-definite systems (order <= 16), for the constraint
!! projections of Step 4 that run several times per gear and time step. At these sizes the
!! reference LAPACK dposv spends most of its ~5,000 instructions per call on blocking and argument
!! handling; this unblocked version needs a few hundred. It is checked against LAPACK in
!! tests/unit/test_small_spd.pf. The gear DAE itself (eq. 14) is solved with LAPACK.
module landyn_small_spd
  use landyn_kinds, only: wp
  implicit none
  private

  public :: small_spd_solve

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
    do i = 1, n
      s = b(i)
      do k = 1, i - 1
        s = s - a(k, i)*b(k)
      end do
      b(i) = s/a(i, i)
    end do
    ! U x = y
    do i = n, 1, -1
      s = b(i)
      do k = i + 1, n
        s = s - a(i, k)*b(k)
      end do
      b(i) = s/a(i, i)
    end do
  end subroutine small_spd_solve

end module landyn_small_spd
