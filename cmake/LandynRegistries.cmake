# The registries of interchangeable parts: contact laws, friction laws, buffer laws, gear types and
# integrators (docs/ARCHITECTURE.md, "Registries"). Each is Fortran source, a subroutine walk(b)
# with one registration line per part,
#   block; use <module>, only: build; if (b%offered('<name>')) call build(b); end block
# so nothing about them is generated from file names. One thing is generated here, at configure
# time: the input layer validates and documents &simulation integrator but may not use numerics/,
# where the integrators and their registry live. So the names the registration lines of
# src/numerics/landyn_integrators.f90 offer are copied into
#   ${CMAKE_BINARY_DIR}/generated/landyn_integrator_names.f90  (module landyn_integrator_names,
#                                                               constant integrator_names)
# which landyn_lib and landyn_input_codegen compile. CMake re-configures whenever the registry file
# changes; tests/unit/test_registries.pf checks the copy against the registry's walk. Not committed.

# landyn_registry_names(<registry source> <template> <output>): the names offered by the
# registration lines of <registry source> (', '-separated, in their order) as @LANDYN_REGISTRY_NAMES@
# of <template>, written to <output>.
function(landyn_registry_names registry template output)
  file(STRINGS ${registry} _lines REGEX "^ *block; *use .*b%offered\\('[a-z0-9_]+'\\)")
  set(_names "")
  foreach(_line IN LISTS _lines)
    string(REGEX MATCH "b%offered\\('([a-z0-9_]+)'\\)" _match "${_line}")
    list(APPEND _names "${CMAKE_MATCH_1}")
  endforeach()
  if(NOT _names)
    message(FATAL_ERROR "${registry}: no registration lines (block; use ...; if (b%offered('<name>')) ...)")
  endif()
  list(JOIN _names ", " LANDYN_REGISTRY_NAMES)
  configure_file(${template} ${output} @ONLY)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${registry})
endfunction()

landyn_registry_names(${CMAKE_SOURCE_DIR}/src/numerics/landyn_integrators.f90
                      ${CMAKE_SOURCE_DIR}/cmake/landyn_integrator_names.f90.in
                      ${CMAKE_BINARY_DIR}/generated/landyn_integrator_names.f90)
set(LANDYN_INTEGRATOR_NAMES_SOURCE ${CMAKE_BINARY_DIR}/generated/landyn_integrator_names.f90)
