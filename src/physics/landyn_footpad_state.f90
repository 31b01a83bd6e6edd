!> The evolving state of one footpad's ground interaction: its contact history (impact speed,
!! deepest sinkage) and its friction stick state. The contact and friction laws are immutable
!! parameter objects; this record belongs to the model state, is read by every force evaluation
!! and is changed only when the integrator commits a step (landyn_simulation).
module landyn_footpad_state
  use landyn_contact, only: contact_state_t
  use landyn_friction, only: friction_state_t
  implicit none
  private

  public :: footpad_state_t

  !> Ground-interaction state of one footpad.
  type :: footpad_state_t
    type(contact_state_t) :: contact     !! contact history (laws with has_history)
    type(friction_state_t) :: friction   !! stick state (laws with has_stiction)
  end type footpad_state_t

end module landyn_footpad_state
