# The integrators are the files src/numerics/landyn_integrator_<name>.f90: each defines the module
# landyn_integrator_<name> with the type <name>_integrator_t extending integrator_t, and '<name>'
# is its value of &simulation integrator. From that list this file writes, at configure time, into
# ${CMAKE_BINARY_DIR}/generated:
#   landyn_integrator_names.f90  the names (the input registry's choices for &simulation integrator)
#   landyn_integrators.f90       make_integrator, one case per integrator
# so adding an integrator is adding one file to src/numerics/ (docs/ARCHITECTURE.md, "Add an
# integrator"). Not committed; CMake re-configures when a file is added (CONFIGURE_DEPENDS).
file(GLOB _landyn_integrator_files CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/numerics/landyn_integrator_*.f90)
list(SORT _landyn_integrator_files)
set(_names "")
set(LANDYN_INTEGRATOR_USES "")
set(LANDYN_INTEGRATOR_CASES "")
foreach(_file IN LISTS _landyn_integrator_files)
  get_filename_component(_name ${_file} NAME_WE)
  string(REPLACE "landyn_integrator_" "" _name ${_name})
  list(APPEND _names "${_name}")
  string(APPEND LANDYN_INTEGRATOR_USES "  use landyn_integrator_${_name}, only: ${_name}_integrator_t\n")
  string(APPEND LANDYN_INTEGRATOR_CASES "    case ('${_name}')\n      allocate (${_name}_integrator_t :: integ)\n")
endforeach()
list(JOIN _names ", " LANDYN_INTEGRATOR_NAMES)
configure_file(${CMAKE_SOURCE_DIR}/cmake/landyn_integrator_names.f90.in
               ${CMAKE_BINARY_DIR}/generated/landyn_integrator_names.f90 @ONLY)
configure_file(${CMAKE_SOURCE_DIR}/cmake/landyn_integrators.f90.in
               ${CMAKE_BINARY_DIR}/generated/landyn_integrators.f90 @ONLY)
# The names belong to the layer config (the input types' choices), make_integrator to numerics.
set(LANDYN_INTEGRATOR_NAMES_SOURCE ${CMAKE_BINARY_DIR}/generated/landyn_integrator_names.f90)
set(LANDYN_INTEGRATOR_FACTORY_SOURCE ${CMAKE_BINARY_DIR}/generated/landyn_integrators.f90)
