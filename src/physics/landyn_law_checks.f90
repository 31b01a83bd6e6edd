!> Parameter checks shared by the contact and friction law modules. Every problem is one message
!! in the format of the input validation,
!!   pre//'&'//group//': '//var//' = '//value//' is invalid; valid: '//requirement
!! appended to an error collector, so the law factories and the input validation report alike.
module landyn_law_checks
  use landyn_kinds, only: wp
  use landyn_errors, only: input_errors_t
  use landyn_real_text, only: fmt_real
  implicit none
  private

  public :: require_real, positive, nonnegative

contains

  !> Append "&group: var = x unit is invalid; valid: requirement" unless ok.
  subroutine require_real(errors, ok, pre, group, var, x, unit, valid)
    type(input_errors_t), intent(inout) :: errors  !! error list
    logical, intent(in) :: ok                      !! the requirement holds [-]
    character(len=*), intent(in) :: pre            !! message prefix (deck name or '') [-]
    character(len=*), intent(in) :: group          !! namelist group without '&' [-]
    character(len=*), intent(in) :: var            !! variable name [-]
    real(wp), intent(in) :: x                      !! its value [unit]
    character(len=*), intent(in) :: unit           !! unit text, '' for none [-]
    character(len=*), intent(in) :: valid          !! the requirement, e.g. 'damping >= 0 N s/m' [-]
    character(len=:), allocatable :: value
    if (ok) return
    value = fmt_real(x)
    if (len(unit) > 0) value = value//' '//unit
    call errors%add(pre//'&'//group//': '//var//' = '//value//' is invalid; valid: '//valid)
  end subroutine require_real

  !> x is a finite number > 0.
  elemental function positive(x) result(ok)
    real(wp), intent(in) :: x  !! value [any unit]
    logical :: ok              !! 0 < x <= huge [-]
    ok = x > 0.0_wp .and. x <= huge(1.0_wp)
  end function positive

  !> x is a finite number >= 0.
  elemental function nonnegative(x) result(ok)
    real(wp), intent(in) :: x  !! value [any unit]
    logical :: ok              !! 0 <= x <= huge [-]
    ok = x >= 0.0_wp .and. x <= huge(1.0_wp)
  end function nonnegative

end module landyn_law_checks
