!> The rest definition (docs/output.md, "Outcome"): how fast the lander still moves after an
!! accepted step, and whether that counts as still. Decided from the state the integrator has
!! accepted, outside the step formula: the integrators call at_rest_now after each accepted step
!! (through sim_accept), and the rest clock that must reach &simulation rest_time lives with the
!! loop's accumulators.
!!
!! Still means, all at once (one speed threshold, &simulation rest_speed, for every part):
!!   - the mass-centre speed |v| < rest_speed;
!!   - the rotation: |omega| l_char < rest_speed (l_char: the largest mass-centre to footpad
!!     distance, so the footpads' speed from the rotation alone);
!!   - every footpad's speed (sliding and sinking into the soil) < rest_speed;
!!   - every strut's stroke rate < rest_speed (no honeycomb crushing, no strut sliding).
module landyn_rest
  use landyn_kinds, only: wp, max_struts
  use landyn_kinematics, only: mv3
  use landyn_body, only: body_point_velocity
  use landyn_terrain, only: slip_velocity
  use landyn_sim_model, only: model_t
  implicit none
  private

  public :: motion_t, measure_motion, at_rest_now

  !> How fast the lander moves.
  type :: motion_t
    real(wp) :: body_speed = 0.0_wp       !! mass-centre speed [m/s]
    real(wp) :: angular_rate = 0.0_wp     !! |omega| [rad/s]
    real(wp) :: footpad_speed = 0.0_wp    !! largest footpad speed (slide and sink) [m/s]
    real(wp) :: slide_rate = 0.0_wp       !! largest footpad speed along the terrain [m/s]
    real(wp) :: stroke_rate = 0.0_wp      !! largest |stroke rate| of any strut [m/s]
  end type motion_t

contains

  !> The motion of the model's current state (stored velocities).
  pure function measure_motion(model) result(mo)
    type(model_t), intent(in) :: model   !! model after an accepted step
    type(motion_t) :: mo                 !! its motion
    real(wp) :: pos(3), vel(3), vd(3), s(max_struts), sd(max_struts)
    integer :: i, ns
    mo%body_speed = norm2(model%body%v)
    mo%angular_rate = norm2(model%body%omega)
    do i = 1, model%par%n_gears
      call model%gear(i)%g%footpad(pos, vel)
      vd = body_point_velocity(model%body, mv3(model%par%rot(:, :, i), pos)) + &
           mv3(model%body%r, mv3(model%par%rot(:, :, i), vel))
      mo%footpad_speed = max(mo%footpad_speed, norm2(vd))
      mo%slide_rate = max(mo%slide_rate, norm2(slip_velocity(model%par%plane(i), vd)))
      ns = model%par%n_struts(i)
      call model%gear(i)%g%strokes(s(1:ns), sd(1:ns))
      mo%stroke_rate = max(mo%stroke_rate, maxval(abs(sd(1:ns))))
    end do
  end function measure_motion

  !> The state is still (module doc): every speed below rest_speed. The cheap body test first,
  !! so that a moving lander costs two norms per step.
  pure function at_rest_now(model, rest_speed, l_char) result(still)
    type(model_t), intent(in) :: model     !! model after an accepted step
    real(wp), intent(in) :: rest_speed     !! &simulation rest_speed [m/s]
    real(wp), intent(in) :: l_char         !! largest mass-centre to footpad distance [m]
    logical :: still                       !! the state counts as still [-]
    type(motion_t) :: mo
    still = norm2(model%body%v) < rest_speed .and. norm2(model%body%omega)*l_char < rest_speed
    if (.not. still) return
    mo = measure_motion(model)
    still = mo%footpad_speed < rest_speed .and. mo%stroke_rate < rest_speed
  end function at_rest_now

end module landyn_rest
