!> The resolved input of one LANDYN run: one derived type per namelist group, gathered in
!! `landyn_input_t`. Defaults are the paper's demonstration lander (Wang et al. 2023, Table 1)
!! and load case LC-1, read as in docs/model_conventions.md. Lengths in m, masses in kg, forces in N,
!! times in s. Angles are stored here in RADIANS (decks give degrees; the namelist reader converts).
module landyn_config
  use landyn_kinds, only: wp, max_gears, pi
  implicit none
  private

  public :: landyn_input_t
  public :: simulation_cfg_t, lander_cfg_t, engine_cfg_t, gears_cfg_t, primary_cfg_t, &
            secondary_cfg_t, contact_cfg_t, friction_cfg_t, terrain_cfg_t, initial_cfg_t, output_cfg_t
  public :: default_input, unset_real, is_set, max_stages, name_len, path_len, integrator_names

  real(wp), parameter :: unset_real = -huge(1.0_wp)   !! marks a real input the deck did not give
  integer, parameter :: max_stages = 5                !! largest number of primary honeycomb stages
  integer, parameter :: name_len = 32                 !! length of law names
  character(len=*), parameter :: integrator_names = 'fixed, adaptive'  !! values of &simulation integrator
  integer, parameter :: path_len = 1024               !! length of file names

  !> &simulation: time stepping and termination.
  type :: simulation_cfg_t
    character(len=256) :: title = 'LANDYN demonstration lander, load case LC-1'
    character(len=name_len) :: integrator = 'adaptive'  !! time integrator: 'adaptive' or 'fixed'
    real(wp) :: dt = 5.0e-6_wp              !! fixed integrator: the time step; adaptive: the first step tried [s]
    real(wp) :: tolerance = 1.0e-7_wp       !! adaptive: local velocity error allowed per step [m/s]
    real(wp) :: dt_max = 1.0e-3_wp          !! adaptive: largest step [s]
    real(wp) :: dt_min = 1.0e-9_wp          !! adaptive: smallest step [s]
    real(wp) :: event_resolution = 1.0e-6_wp !! adaptive: events are located to within this time [s]
    real(wp) :: t_end = 1.0_wp              !! end time [s]
    real(wp) :: gravity = 1.62_wp           !! gravitational acceleration, along global +z (down) [m/s^2]
    logical  :: stop_at_rest = .true.       !! end the run early when the lander has come to rest
    real(wp) :: rest_speed = 1.0e-3_wp      !! body speed below which the lander is at rest [m/s]
    real(wp) :: rest_time = 0.05_wp         !! time the speed must stay below rest_speed [s]
    real(wp) :: tipover_angle = 45.0_wp*pi/180.0_wp  !! tilt of the lander z axis from vertical that counts as tipped over [rad]
    real(wp) :: constraint_tol = 1.0e-10_wp !! tolerance of the constraint-violation correction [m, m/s]
    integer  :: max_correction_iter = 20    !! iteration cap of the correction
    real(wp) :: max_constraint_drift = 1.0e-6_wp !! a violation above this before correction means dt is too large [m]
  end type simulation_cfg_t

  !> &lander: rigid body (total mass, inertia about the mass centre in lander axes).
  type :: lander_cfg_t
    real(wp) :: mass = 1.6e4_wp             !! total lander mass, legs included [kg]
    real(wp) :: ixx = 8.18e4_wp             !! moment of inertia about x_L through the mass centre [kg m^2]
    real(wp) :: iyy = 8.18e4_wp             !! [kg m^2]
    real(wp) :: izz = 8.17e4_wp             !! [kg m^2]
    real(wp) :: ixy = 0.0_wp                !! product of inertia  integral(x y dm) [kg m^2]; tensor element is -ixy
    real(wp) :: ixz = 0.0_wp                !! product of inertia  integral(x z dm) [kg m^2]
    real(wp) :: iyz = 0.0_wp                !! product of inertia  integral(y z dm) [kg m^2]
    real(wp) :: mass_centre(3) = [0.0_wp, 0.0_wp, -3.818_wp]  !! mass centre in the lander frame [m]
  end type lander_cfg_t

  !> &engine: optional descent-engine thrust.
  type :: engine_cfg_t
    real(wp) :: thrust = 0.0_wp             !! thrust magnitude [N]
    real(wp) :: direction(3) = [0.0_wp, 0.0_wp, -1.0_wp]  !! thrust direction in the lander frame (normalised at input) [-]
    real(wp) :: point(3) = [0.0_wp, 0.0_wp, -3.818_wp]    !! point of application in the lander frame [m]
    real(wp) :: cutoff_time = 0.0_wp        !! thrust acts for 0 <= t < cutoff_time [s]
  end type engine_cfg_t

  !> &gears: number of gears and their hard points in the lander frame.
  !! Column i of each point array is gear i. Columns the deck does not give are gear 1's points
  !! rotated about the lander z axis by rotation(i).
  type :: gears_cfg_t
    integer  :: n_gears = 4
    real(wp) :: rotation(max_gears) = unset_real  !! rotation of gear i about lander z [rad]; default (i-1)*2*pi/n_gears
    real(wp) :: point_a(3, max_gears) = unset_real  !! primary strut upper universal joint [m]
    real(wp) :: point_b(3, max_gears) = unset_real  !! left secondary upper universal joint [m]
    real(wp) :: point_c(3, max_gears) = unset_real  !! right secondary upper universal joint [m]
    real(wp) :: point_d(3, max_gears) = unset_real  !! footpad ball joint (primary lower end) [m]
    real(wp) :: point_e(3, max_gears) = unset_real  !! left secondary lower ball joint on the primary outer tube [m]
    real(wp) :: point_f(3, max_gears) = unset_real  !! right secondary lower ball joint on the primary outer tube [m]
  end type gears_cfg_t

  !> &primary_strut: multi-stage honeycomb and part masses.
  type :: primary_cfg_t
    integer  :: n_stages = 2
    real(wp) :: stage_force(max_stages) = [78000.0_wp, 156000.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]  !! crush force of each stage [N]
    real(wp) :: stage_end(max_stages) = [0.2_wp, 0.475_wp, 0.0_wp, 0.0_wp, 0.0_wp]  !! stroke at which each stage ends [m]; the last is the stroke capacity
    real(wp) :: stop_stiffness = 1.0e9_wp   !! stiffness of the end-of-stroke stop [N/m]
    real(wp) :: stop_damping = 1.0e5_wp     !! damping of the end-of-stroke stop [N s/m]
    real(wp) :: outer_mass = 25.0_wp        !! outer tube with lugs [kg]
    real(wp) :: outer_cm = 1.0_wp           !! distance of the outer tube's mass centre from the upper joint [m]
    real(wp) :: outer_inertia = 8.3_wp      !! transverse inertia of the outer tube about its mass centre [kg m^2]
    real(wp) :: inner_mass = 15.0_wp        !! inner tube [kg]
    real(wp) :: inner_cm = 0.9_wp           !! distance of the inner tube's mass centre from the footpad joint [m]
    real(wp) :: inner_inertia = 4.05_wp     !! transverse inertia of the inner tube about its mass centre [kg m^2]
    real(wp) :: footpad_mass = 15.0_wp      !! footpad, lumped at the footpad joint [kg]
    ! Tube friction between the outer and inner tubes (eqs. 23-26, landyn_tube_friction). Default
    ! lengths from the Table 1 geometry, see docs/input/primary_strut.md.
    logical  :: tube_friction = .false.     !! add eta u_1 N_E/F to the primary's crush bounds
    real(wp) :: mu_tube = 0.1_wp            !! tube friction coefficient u_1 (Table 1) [-]
    real(wp) :: tube_outer_length = 2.0_wp  !! L_O: outer tube, upper joint a to its lower end [m]
    real(wp) :: tube_inner_length = 2.8_wp  !! L_I: inner tube, footpad joint d to its upper end [m]
    real(wp) :: tube_leg_length = 3.5018_wp !! L_L: primary length a-d at which the overlap is taken [m]
    real(wp) :: tube_lever = 1.5_wp         !! L_O1: inner tube exposed below the outer tube (load to nearest bearing) [m]
  end type primary_cfg_t

  !> &secondary_strut: two-direction honeycomb (levels named by the motion they resist) and part masses.
  type :: secondary_cfg_t
    real(wp) :: force_lengthening = 43000.0_wp  !! crush force resisting lengthening (Table 1 F_com) [N]
    real(wp) :: force_shortening = 30000.0_wp   !! crush force resisting shortening (Table 1 F_ten) [N]
    real(wp) :: stroke_lengthening = 0.27_wp    !! stroke available in lengthening [m]
    real(wp) :: stroke_shortening = 0.27_wp     !! stroke available in shortening [m]
    real(wp) :: stop_stiffness = 1.0e9_wp       !! stiffness of the end-of-stroke stops [N/m]
    real(wp) :: stop_damping = 1.0e5_wp         !! damping of the end-of-stroke stops [N s/m]
    real(wp) :: outer_mass = 6.0_wp             !! upper part [kg]
    real(wp) :: outer_cm = 0.45_wp              !! distance of the upper part's mass centre from the upper joint [m]
    real(wp) :: outer_inertia = 0.405_wp        !! transverse inertia of the upper part about its mass centre [kg m^2]
    real(wp) :: inner_mass = 4.0_wp             !! lower part [kg]
    real(wp) :: inner_cm = 0.45_wp              !! distance of the lower part's mass centre from the lower joint [m]
    real(wp) :: inner_inertia = 0.27_wp         !! transverse inertia of the lower part about its mass centre [kg m^2]
  end type secondary_cfg_t

  !> &contact: footpad-ground normal law (eqs. 17-18).
  type :: contact_cfg_t
    character(len=name_len) :: law = 'base'
    real(wp) :: stiffness = 3.16227766016838e9_wp  !! K_g [N/m^exponent]
    real(wp) :: exponent = 1.5_wp                  !! n [-]
    real(wp) :: damping = 1.0e4_wp                 !! C_g [N s/m]
    real(wp) :: damping_depth = 1.0e-4_wp          !! D1 (base), d_max (adams_impact), d (kelvin_voigt_step) [m]
    real(wp) :: damping2 = 1.0e4_wp                !! D2 of kelvin_voigt_bilinear (Table 5) [N s^2/m^2]
    real(wp) :: restitution = 0.5_wp               !! e of hunt_crossley (used when hc_alpha = 0) [-]
    real(wp) :: hc_alpha = 0.0_wp                  !! alpha of hunt_crossley's c_r = 1 - alpha v_impact; 0: use restitution [s/m]
    real(wp) :: min_impact_speed = 0.1_wp          !! floor of the impact speed in hunt_crossley's chi [m/s]
    real(wp) :: soil_stiffness = 5.24e5_wp         !! K_b of regolith, F_p = K_b z^n_b [N/m^soil_exponent]
    real(wp) :: soil_exponent = 1.0_wp             !! n_b of regolith [-]
    real(wp) :: soil_drag = 1.0e3_wp               !! alpha of regolith's inertial drag alpha v^2 (eq. 1) [kg/m]
    real(wp) :: soil_unload_stiffness = 1.0e8_wp   !! regolith unloading/reloading stiffness [N/m]
  end type contact_cfg_t

  !> &friction: footpad-ground friction.
  type :: friction_cfg_t
    character(len=name_len) :: law = 'coulomb_step'
    real(wp) :: mu_static = 0.4_wp          !! static coefficient [-]
    real(wp) :: mu_dynamic = 0.4_wp         !! dynamic coefficient [-]
    real(wp) :: v_static = 0.1_wp           !! stiction transition slip speed [m/s]
    real(wp) :: v_dynamic = 1.0_wp          !! friction transition slip speed [m/s]
    real(wp) :: viscous = 100.0_wp          !! C_v of ty2, ty5, ty6 (Table 8 TY-2) [N s/m]
    real(wp) :: stribeck_speed = unset_real !! v_S of ty5/ty6; unset: 1.0 for ty5, 0.1 for ty6 (Table 8) [m/s]
    real(wp) :: stribeck_exponent = 0.85_wp !! delta of ty5/ty6 (Table 8) [-]
    real(wp) :: stribeck_decay = 0.85_wp    !! epsilon of ty6 (Table 8) [-]
    real(wp) :: stick_stiffness = 1.0e8_wp  !! tangential stiffness of the stick state (stiction laws) [N/m]
    real(wp) :: stick_damping = 1.0e5_wp    !! tangential damping of the stick state (stiction laws) [N s/m]
  end type friction_cfg_t

  !> &terrain: one plane per footpad (column/entry i is footpad i). Plane i passes through the
  !! global point (0, 0, -height(i)) and rises with slope(i) toward the horizontal direction at
  !! azimuth slope_direction(i) (from global +x toward +y).
  type :: terrain_cfg_t
    real(wp) :: height(max_gears) = 0.0_wp          !! surface elevation at the global origin [m] (up positive)
    real(wp) :: slope(max_gears) = 0.0_wp           !! slope angle [rad]
    real(wp) :: slope_direction(max_gears) = 0.0_wp !! azimuth of the uphill direction [rad]
  end type terrain_cfg_t

  !> &initial_state: state at t = 0.
  type :: initial_cfg_t
    real(wp) :: position(3) = unset_real    !! lander-frame origin O_L in the global frame [m]; unset: placed by clearance
    real(wp) :: clearance = 0.0_wp          !! gap of the lowest footpad above its surface when position is unset [m]
    real(wp) :: velocity(3) = [0.0_wp, 0.0_wp, 4.0_wp]   !! velocity of the mass centre, global frame (z down) [m/s]
    real(wp) :: attitude(3) = 0.0_wp        !! Z-Y-X Euler angles yaw, pitch, roll [rad]
    real(wp) :: angular_rate(3) = 0.0_wp    !! body angular rate p, q, r in lander axes [rad/s]
  end type initial_cfg_t

  !> &output: result file and sampling.
  type :: output_cfg_t
    character(len=path_len) :: file = ''   !! result file; empty: deck base name + .h5 (landyn.h5 without a deck)
    real(wp) :: interval = 1.0e-3_wp        !! output sampling interval [s]
  end type output_cfg_t

  !> The whole resolved input.
  type :: landyn_input_t
    type(simulation_cfg_t) :: simulation
    type(lander_cfg_t)     :: lander
    type(engine_cfg_t)     :: engine
    type(gears_cfg_t)      :: gears
    type(primary_cfg_t)    :: primary
    type(secondary_cfg_t)  :: secondary
    type(contact_cfg_t)    :: contact
    type(friction_cfg_t)   :: friction
    type(terrain_cfg_t)    :: terrain
    type(initial_cfg_t)    :: initial
    type(output_cfg_t)     :: output
    character(len=:), allocatable :: deck_name  !! path of the deck as given ('' for the built-in default)
    character(len=:), allocatable :: deck_text  !! the deck text as given
  end type landyn_input_t

  !> Gear 1 hard points of the demonstration lander (Table 1 with the docs/model_conventions.md readings of e1, f1) [m].
  real(wp), parameter, public :: paper_a1(3) = [3.89_wp, 0.0_wp, -2.18_wp]
  real(wp), parameter, public :: paper_b1(3) = [3.37_wp, 1.23_wp, -1.01_wp]
  real(wp), parameter, public :: paper_c1(3) = [3.37_wp, -1.23_wp, -1.01_wp]
  real(wp), parameter, public :: paper_d1(3) = [5.48_wp, 0.0_wp, 0.94_wp]
  real(wp), parameter, public :: paper_e1(3) = [4.65_wp, 0.109_wp, -0.505_wp]
  real(wp), parameter, public :: paper_f1(3) = [4.65_wp, -0.109_wp, -0.505_wp]

contains

  !> The built-in default input: the paper's lander, load case LC-1, with every gear's
  !! points and rotation resolved.
  pure function default_input() result(inp)
    type(landyn_input_t) :: inp  !! resolved default input
    inp%gears%point_a(:, 1) = paper_a1
    inp%gears%point_b(:, 1) = paper_b1
    inp%gears%point_c(:, 1) = paper_c1
    inp%gears%point_d(:, 1) = paper_d1
    inp%gears%point_e(:, 1) = paper_e1
    inp%gears%point_f(:, 1) = paper_f1
    inp%deck_name = ''
    inp%deck_text = ''
  end function default_input

  !> True when a real input was given (is not the unset marker).
  elemental function is_set(x) result(yes)
    real(wp), intent(in) :: x  !! value to test [any unit]
    logical :: yes             !! .true. when x was set
    yes = x > unset_real
  end function is_set

end module landyn_config
