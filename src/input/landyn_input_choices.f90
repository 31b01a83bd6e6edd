!> The valid names of the input registry's choice variables (input_var_t%choices), each list from
!! its registry: the contact, friction and buffer laws and the gear types from their registries'
!! walks (physics/), the integrators from the copy of the integrator registry's names that
!! cmake/LandynRegistries.cmake generates (the input layer may not use numerics/). The input
!! validation checks a deck's choice against these lists and quotes them in its message;
!! docs/input lists them.
module landyn_input_choices
  use landyn_config, only: integrator_names
  use landyn_contact, only: contact_law_names
  use landyn_friction, only: friction_law_names
  use landyn_buffer_laws, only: buffer_law_names
  use landyn_gear_types, only: gear_type_names
  implicit none
  private

  public :: choice_list

contains

  !> The valid names of a registry choice list, ', '-separated in the registry's order ('' for an
  !! unknown list).
  function choice_list(which) result(list)
    character(len=*), intent(in) :: which   !! 'integrator', 'contact_law', 'friction_law', 'buffer_law', 'gear_type' [-]
    character(len=:), allocatable :: list   !! comma-separated names [-]
    select case (trim(which))
    case ('contact_law')
      list = contact_law_names()
    case ('friction_law')
      list = friction_law_names()
    case ('buffer_law')
      list = buffer_law_names()
    case ('gear_type')
      list = gear_type_names()
    case ('integrator')
      list = integrator_names
    case default
      list = ''
    end select
  end function choice_list

end module landyn_input_choices
