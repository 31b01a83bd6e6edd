!> Event location by switching functions (docs/theory.md, "Events by switching functions"). An
!! event is a change of the discrete state between two evaluations (discrete_change); each kind of
!! change has a switching function of the state, >= 0 on one side and < 0 on the other:
!!
!! * a footpad's contact: its penetration (in contact exactly where > 0);
!! * a footpad's stick state: the friction law's yield limit minus the trial force (stuck exactly
!!   where >= 0; friction_law_t%stick_slip_force); a sliding footpad whose normal force vanishes
!!   becomes stuck with the margin 0 of zero load, a jump rather than a zero, and is not located;
!! * a strut's crush mode: the mode's margin (gear_eval_t%margin_out at the start of the step,
!!   margin_in, the same function, at its end): the force left before a lock gives way, the stroke
!!   rate in the crush direction; for a free strut the stroke left to the nearer end of its free
!!   range as it was at the start of the step (the range grows with a crushing stroke, so at the
!!   end of the step the stroke is measured against the start's range);
!! * the tilt passing the tip-over angle: tilt minus that angle.
!!
!! event_fraction interpolates each changed component's switching function linearly between the
!! two ends of a step (regula falsi; the Illinois weights scale an end that was kept twice) and
!! returns the earliest zero as a fraction of the step. A change without such a function (a stage
!! end or stop of a buffer law, a gear type without mode margins, a function without a sign change)
!! is not located: the integrator halves the step instead.
module landyn_event_locator
  use landyn_kinds, only: wp
  use landyn_sim_model, only: sim_eval_t
  implicit none
  private

  public :: event_fraction

contains

  !> Fraction of the step from e0 to e1 at which the first changed component's switching function
  !! crosses zero, by linear interpolation of w0 g(e0) and w1 g(e1).
  pure subroutine event_fraction(e0, e1, ng, tip, w0, w1, theta, located)
    type(sim_eval_t), intent(in) :: e0       !! evaluation at the start of the step
    type(sim_eval_t), intent(in) :: e1       !! evaluation at its end
    integer, intent(in) :: ng                !! number of gears [-]
    real(wp), intent(in) :: tip              !! tip-over angle [rad]
    real(wp), intent(in) :: w0               !! weight of the start values (Illinois; 1 otherwise) [-]
    real(wp), intent(in) :: w1               !! weight of the end values [-]
    real(wp), intent(out) :: theta           !! fraction of the step, in [0, 1] [-]
    logical, intent(out) :: located          !! some component changed and every changed one has a switching
                                             !! function with a sign change over the step [-]
    integer :: i, k, n_changed

    theta = 1.0_wp
    located = .true.
    n_changed = 0
    do i = 1, ng
      if (e0%contact(i) .neqv. e1%contact(i)) then
        call crossing(e0%delta(i), e1%delta(i), w0, w1, theta, located, n_changed)
      else if (e0%stuck(i) .neqv. e1%stuck(i)) then
        if (e1%stuck(i) .and. .not. (abs(e1%stick_margin(i)) > 0.0_wp)) then
          ! stuck at the end because the normal force vanished (stick_slip_force: margin 0 at zero
          ! load): the margin jumps from the sliding value to 0 and has no zero to interpolate
          n_changed = n_changed + 1
          located = .false.
        else
          call crossing(e0%stick_margin(i), e1%stick_margin(i), w0, w1, theta, located, n_changed)
        end if
      end if
      do k = 1, size(e0%mode, 1)
        if (e0%segment(k, i) /= e1%segment(k, i)) then
          n_changed = n_changed + 1
          located = .false.
        else if (e0%mode(k, i) == 2) then
          ! free: the stroke left to the nearer end of e0's free range (e1's has moved with the stroke)
          if (e0%mode(k, i) /= e1%mode(k, i)) then
            associate (g0 => e0%gear(i), s1 => e1%gear(i)%stroke(k))
              call crossing(g0%margin_out(k), min(g0%free_hi(k) - s1, s1 - g0%free_lo(k)), w0, w1, theta, located, &
                            n_changed)
            end associate
          end if
        else if (e0%mode(k, i) /= e1%mode(k, i)) then
          call crossing(e0%gear(i)%margin_out(k), e1%gear(i)%margin_in(k), w0, w1, theta, located, n_changed)
        end if
      end do
    end do
    if ((e0%tilt > tip) .neqv. (e1%tilt > tip)) then
      call crossing(e0%tilt - tip, e1%tilt - tip, w0, w1, theta, located, n_changed)
    end if
    located = located .and. n_changed > 0
  end subroutine event_fraction

  !> One changed component with start and end values g0, g1: its zero as a fraction of the step
  !! (theta, the earliest so far), if the weighted values differ in sign; else located is cleared.
  pure subroutine crossing(g0, g1, w0, w1, theta, located, n_changed)
    real(wp), intent(in) :: g0          !! value at the start [any]
    real(wp), intent(in) :: g1          !! value at the end [same]
    real(wp), intent(in) :: w0          !! weight of the start value [-]
    real(wp), intent(in) :: w1          !! weight of the end value [-]
    real(wp), intent(inout) :: theta    !! earliest zero so far, fraction of the step [-]
    logical, intent(inout) :: located   !! every changed component so far had a zero [-]
    integer, intent(inout) :: n_changed !! changed components so far [-]
    real(wp) :: a, b
    n_changed = n_changed + 1
    a = w0*g0
    b = w1*g1
    if (((a >= 0.0_wp) .neqv. (b >= 0.0_wp)) .or. (a <= 0.0_wp .and. b > 0.0_wp)) then
      theta = min(theta, max(0.0_wp, min(1.0_wp, a/(a - b))))
    else
      located = .false.
    end if
  end subroutine crossing

end module landyn_event_locator
