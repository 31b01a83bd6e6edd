!> The resolved input of one LANDYN run, `landyn_input_t`: the deck variables (one derived type per
!! namelist group, generated from the input registry into landyn_input_groups, defaults included)
!! extended by what is not a deck variable (the deck's name and text), and the built-in default
!! input. Defaults are the paper's demonstration lander (Wang et al. 2023, Table 1) and load case
!! LC-1, read as in docs/model_conventions.md. Lengths in m, masses in kg, forces in N, times in s.
!! Angles are stored here in RADIANS (decks give degrees; the namelist reader converts).
module landyn_config
  use landyn_kinds, only: wp
  use landyn_input_limits, only: unset_real, is_set, max_stages, name_len, path_len, integrator_names
  use landyn_input_groups, only: input_groups_t, simulation_cfg_t, lander_cfg_t, engine_cfg_t, gears_cfg_t, &
                                 primary_cfg_t, secondary_cfg_t, contact_cfg_t, friction_cfg_t, terrain_cfg_t, &
                                 initial_cfg_t, output_cfg_t
  implicit none
  private

  public :: landyn_input_t
  public :: simulation_cfg_t, lander_cfg_t, engine_cfg_t, gears_cfg_t, primary_cfg_t, &
            secondary_cfg_t, contact_cfg_t, friction_cfg_t, terrain_cfg_t, initial_cfg_t, output_cfg_t
  public :: default_input, unset_real, is_set, max_stages, name_len, path_len, integrator_names

  !> The whole resolved input: the deck variables (`input_groups_t`, one component per group,
  !! e.g. `inp%simulation%dt`) and the deck itself.
  type, extends(input_groups_t) :: landyn_input_t
    character(len=:), allocatable :: deck_name  !! path of the deck as given ('' for the built-in default) [-]
    character(len=:), allocatable :: deck_text  !! the deck text as given [-]
  end type landyn_input_t

  !> Gear 1 hard points of the demonstration lander (Table 1 with the docs/model_conventions.md readings of e1, f1) [m].
  real(wp), parameter, public :: paper_a1(3) = [3.89_wp, 0.0_wp, -2.18_wp]
  real(wp), parameter, public :: paper_b1(3) = [3.37_wp, 1.23_wp, -1.01_wp]  !! secondary-strut upper joint b (left) [m]
  real(wp), parameter, public :: paper_c1(3) = [3.37_wp, -1.23_wp, -1.01_wp]  !! secondary-strut upper joint c (right) [m]
  real(wp), parameter, public :: paper_d1(3) = [5.48_wp, 0.0_wp, 0.94_wp]  !! footpad joint d [m]
  real(wp), parameter, public :: paper_e1(3) = [4.65_wp, 0.109_wp, -0.505_wp]  !! lug e on the outer tube (left secondary) [m]
  real(wp), parameter, public :: paper_f1(3) = [4.65_wp, -0.109_wp, -0.505_wp]  !! lug f on the outer tube (right secondary) [m]

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

end module landyn_config
