!> Landing-gear multibody dynamics (paper section 2.4, eqs. 12-16, Step 4 of section 3.1): the
!! public interface of the tripod gear. The types and the procedure interfaces are declared in
!! landyn_gear_model (gear_t and gear_state_t opaque); the bodies live in its submodules:
!!
!!   landyn_strut             one strut's mass model (strut_t: first moment and inertia of its length)
!!   landyn_gear_model        coordinates, gear_t and its state and evaluation records, interfaces
!!   landyn_gear_setup        set-up, footpad, mass matrix, strokes and the accessors of the state
!!   landyn_gear_inertia      generalized forces, relative momentum and inertia terms
!!   landyn_gear_dynamics     crush logic and the gear DAE at one instant (gear_evaluate/commit)
!!   landyn_gear_joint_loads  interface loads of the joints
!!   landyn_gear_constraints  the gear's step and its constraint-violation correction
!!
!! Users (the simulation, the impact projection, the tests) `use landyn_gear`.
module landyn_gear
  use landyn_strut, only: strut_mass_t, strut_t
  use landyn_gear_model, only: gear_t, buffer_slot_t, gear_state_t, gear_eval_t, gear_init, gear_footpad, &
                               gear_mass_matrix, gear_relative_kinetic_energy, gear_law_segments, gear_strokes, &
                               gear_strut_lengths, gear_leg_mass, gear_rotation, gear_rates, gear_set_rates, &
                               gear_led_rates, gear_locks, gear_strut_modes, strut_modes, gear_is_rigid, &
                               gear_cache_jacobian, gear_mass_diagonal, gear_crush_history, gear_crush_work, &
                               gear_violations, gear_buffer_capacity, gear_set_buffer, gear_save_state, &
                               gear_restore_state, gear_axial_forces, gear_body_load, gear_coordinates, &
                               gear_accelerations, gear_set_coordinates, gear_set_locks, gear_slide_directions, &
                               gear_set_crush_history, gear_set_axial_forces, gear_set_rigid, gear_tube_bound, &
                               gear_geometry, gear_strut, gear_nominal_lengths, &
                               gear_generalized_forces, gear_relative_inertia, gear_relative_momenta, &
                               gear_leg_momentum, gear_momentum_maps, gear_evaluate, gear_commit, gear_prepare, &
                               gear_dynamics, gear_integrate, gear_settle, gear_velocity_rows, GEAR_DRIFT, &
                               GEAR_NOT_CONVERGED, n_struts, strut_names, n_q, n_phi, max_rows, idx_len
  implicit none
  private

  public :: gear_t, strut_mass_t, strut_t, buffer_slot_t, gear_state_t, gear_eval_t
  public :: gear_init, gear_evaluate, gear_commit, gear_prepare, gear_dynamics, gear_integrate
  public :: gear_footpad, gear_mass_matrix, gear_generalized_forces
  public :: gear_relative_kinetic_energy, gear_relative_inertia, gear_leg_momentum
  public :: gear_relative_momenta, gear_velocity_rows, gear_momentum_maps, gear_settle, gear_law_segments
  public :: gear_strokes, gear_strut_lengths, gear_leg_mass, gear_rotation, gear_rates, gear_set_rates, gear_led_rates
  public :: gear_locks, gear_strut_modes, strut_modes, gear_is_rigid, gear_cache_jacobian, gear_mass_diagonal
  public :: gear_crush_history, gear_crush_work, gear_violations, gear_buffer_capacity, gear_set_buffer
  public :: gear_save_state, gear_restore_state, gear_axial_forces, gear_body_load
  public :: gear_coordinates, gear_accelerations, gear_set_coordinates, gear_set_locks, gear_slide_directions
  public :: gear_set_crush_history, gear_set_axial_forces, gear_set_rigid, gear_tube_bound, gear_geometry
  public :: gear_strut, gear_nominal_lengths
  public :: GEAR_DRIFT, GEAR_NOT_CONVERGED
  public :: max_rows, idx_len, n_struts, strut_names
  public :: n_q, n_phi

end module landyn_gear
