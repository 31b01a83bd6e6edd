!> The ground's force on one footpad (docs/model_conventions.md, "Footpad-ground contact and
!! friction"): from the footpad's global position and velocity, the penetration into its terrain
!! plane and its rate, the trial footpad state (contact history advanced), the normal force of the
!! contact law, the friction force of the friction law (stick/slip for laws with stiction, from
!! the footpad's displacement since its stick reference) and the force in the global frame. The
!! laws and the plane are parameters; the footpad state given in is the committed one, and the
!! trial state returned is committed by the integrator with the step.
module landyn_footpad_ground
  use landyn_kinds, only: wp
  use landyn_terrain, only: terrain_plane_t, penetration, penetration_rate, slip_velocity, to_global
  use landyn_contact, only: contact_law_t, advance_contact_state
  use landyn_friction, only: friction_law_t
  use landyn_footpad_state, only: footpad_state_t
  implicit none
  private

  public :: footpad_ground_force

contains

  !> The ground force on a footpad at position xd with velocity vd (both global). With stiction
  !! the stick state advances with the footpad's tangential displacement since x_ref (the position
  !! of the evaluation whose footpad states were committed) over h_ref; without a reference
  !! (has_ref false: nothing committed yet) from zero displacement over zero time.
  subroutine footpad_ground_force(plane, contact, friction, xd, vd, has_ref, x_ref, h_ref, trial, delta, fn, &
                                  stick_margin, fground)
    type(terrain_plane_t), intent(in) :: plane      !! terrain plane under the footpad [-]
    class(contact_law_t), intent(in) :: contact     !! normal contact law [-]
    class(friction_law_t), intent(in) :: friction   !! friction law [-]
    real(wp), intent(in) :: xd(3)                   !! footpad position, global [m]
    real(wp), intent(in) :: vd(3)                   !! footpad velocity, global [m/s]
    logical, intent(in) :: has_ref                  !! x_ref and h_ref apply [-]
    real(wp), intent(in) :: x_ref(3)                !! footpad position the stick state belongs to, global [m]
    real(wp), intent(in) :: h_ref                   !! time since that position [s]
    type(footpad_state_t), intent(inout) :: trial   !! the committed footpad state in, the trial state out [-]
    real(wp), intent(out) :: delta                  !! penetration [m]
    real(wp), intent(out) :: fn                     !! normal force [N]
    real(wp), intent(out) :: stick_margin           !! stick switching function (0 without stiction) [N]
    real(wp), intent(out) :: fground(3)             !! ground force on the footpad, global [N]
    real(wp) :: delta_dot, ft(2), vslip(2), dslip(2), hslip

    delta = penetration(plane, xd)
    delta_dot = penetration_rate(plane, vd)
    if (contact%has_history) call advance_contact_state(trial%contact, delta, delta_dot)
    if (delta > 0.0_wp) then
      fn = contact%normal_force(delta, delta_dot, trial%contact)
    else
      fn = 0.0_wp
    end if
    vslip = slip_velocity(plane, vd)
    if (friction%has_stiction) then
      ! stick state: advanced with the footpad's tangential displacement since the evaluation
      ! whose footpad states were committed (not since the last booked one: after a rejected
      ! step the state at t is evaluated again, and its committed stick state is still t - h's)
      dslip = 0.0_wp
      hslip = 0.0_wp
      if (has_ref) then
        dslip = slip_velocity(plane, xd - x_ref)
        hslip = h_ref
      end if
      call friction%stick_slip_force(trial%friction, vslip, dslip, hslip, fn, ft, stick_margin)
    else
      stick_margin = 0.0_wp
      ft = friction%friction_force(vslip, fn)
    end if
    fground = to_global(plane, [ft(1), ft(2), fn])
  end subroutine footpad_ground_force

end module landyn_footpad_ground
