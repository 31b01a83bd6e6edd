# pFUnit glue for LANDYN unit tests (tests/unit/test_*.pf).
#
# Defines landyn_add_pfunit_test(name pf_file).  Two back ends:
#   * the real pFUnit 4 (find_package(PFUNIT)), through add_pfunit_ctest();
#   * otherwise the in-tree "pfunit_lite": tests/pfunit_lite/pf2f90.py translates
#     the .pf at build time and the result is linked with the small runtime
#     module funit (tests/pfunit_lite/funit.f90).  It accepts only the subset of
#     pFUnit syntax documented in tests/pfunit_lite/README.md.
#
# LANDYN_USE_PFUNIT = AUTO (real pFUnit if found, else in-tree), ON (real pFUnit
# required) or OFF (always in-tree).  Point CMake at an installed pFUnit with
# -DCMAKE_PREFIX_PATH=<pfunit prefix> (or -DPFUNIT_DIR=<...>/PFUNIT-4.x/cmake).

set(LANDYN_USE_PFUNIT AUTO CACHE STRING "Use the real pFUnit for unit tests: AUTO, ON or OFF")
set_property(CACHE LANDYN_USE_PFUNIT PROPERTY STRINGS AUTO ON OFF)
string(TOUPPER "${LANDYN_USE_PFUNIT}" _landyn_use_pfunit)

set(LANDYN_PFUNIT_LITE_DIR ${CMAKE_CURRENT_LIST_DIR}/../tests/pfunit_lite)
get_filename_component(LANDYN_PFUNIT_LITE_DIR ${LANDYN_PFUNIT_LITE_DIR} ABSOLUTE)

set(LANDYN_HAVE_REAL_PFUNIT FALSE)
if(_landyn_use_pfunit STREQUAL "ON")
  find_package(PFUNIT REQUIRED)
  set(LANDYN_HAVE_REAL_PFUNIT TRUE)
elseif(_landyn_use_pfunit STREQUAL "AUTO")
  find_package(PFUNIT QUIET)
  if(PFUNIT_FOUND)
    set(LANDYN_HAVE_REAL_PFUNIT TRUE)
  endif()
elseif(NOT _landyn_use_pfunit STREQUAL "OFF")
  message(FATAL_ERROR "LANDYN_USE_PFUNIT must be AUTO, ON or OFF (got '${LANDYN_USE_PFUNIT}')")
endif()

if(LANDYN_HAVE_REAL_PFUNIT)
  message(STATUS "LANDYN unit tests: real pFUnit ${PFUNIT_VERSION} (${PFUNIT_DIR})")
else()
  if(NOT Python3_Interpreter_FOUND)
    find_package(Python3 COMPONENTS Interpreter)
  endif()
  if(NOT Python3_Interpreter_FOUND)
    message(FATAL_ERROR "LANDYN unit tests need either pFUnit 4 or python3 (for the in-tree translator tests/pfunit_lite/pf2f90.py)")
  endif()
  message(STATUS "LANDYN unit tests: in-tree pFUnit subset (tests/pfunit_lite), real pFUnit not used")

  # The runtime module `funit`, built once.  Its .mod goes to its own directory so
  # it can never be confused with a real pFUnit installation's funit.mod.
  add_library(landyn_funit_lite STATIC ${LANDYN_PFUNIT_LITE_DIR}/funit.f90)
  set_target_properties(landyn_funit_lite PROPERTIES
    Fortran_MODULE_DIRECTORY ${CMAKE_BINARY_DIR}/mod_funit_lite)
  target_include_directories(landyn_funit_lite PUBLIC ${CMAKE_BINARY_DIR}/mod_funit_lite)
  landyn_set_flags(landyn_funit_lite)
endif()

# landyn_add_pfunit_test(<name> <pf_file> [LINK_LIBRARIES libs...] [LABELS labels...] [WILL_FAIL])
#   Builds executable <name> from the pFUnit test module <pf_file> (module name =
#   file name), links it with landyn_lib (default) and registers CTest test <name>
#   with label "unit" (default).  WILL_FAIL is for the in-tree self-test only.
function(landyn_add_pfunit_test name pf_file)
  cmake_parse_arguments(PARSE_ARGV 2 ARG "WILL_FAIL" "" "LINK_LIBRARIES;LABELS")
  if(NOT ARG_LINK_LIBRARIES)
    set(ARG_LINK_LIBRARIES landyn_lib)
  endif()
  if(NOT ARG_LABELS)
    set(ARG_LABELS unit)
  endif()
  get_filename_component(pf_file ${pf_file} ABSOLUTE)

  if(LANDYN_HAVE_REAL_PFUNIT)
    # add_pfunit_ctest() writes the generated .F90 next to an absolute-path .pf
    # (it assumes such files are in the build tree), so hand it a path relative
    # to the current source directory, or a build-tree copy of an outside file.
    file(RELATIVE_PATH pf_rel ${CMAKE_CURRENT_SOURCE_DIR} ${pf_file})
    if(pf_rel MATCHES "^\\.\\./" OR IS_ABSOLUTE "${pf_rel}")
      set(pf_rel ${CMAKE_CURRENT_BINARY_DIR}/pfunit_real/${name}/${name}.pf)
      add_custom_command(OUTPUT ${pf_rel}
        COMMAND ${CMAKE_COMMAND} -E copy ${pf_file} ${pf_rel}
        DEPENDS ${pf_file} VERBATIM)
    endif()
    add_pfunit_ctest(${name}
      TEST_SOURCES ${pf_rel}
      LINK_LIBRARIES ${ARG_LINK_LIBRARIES}
      LABELS ${ARG_LABELS})
    # Same flags as the library.  The test module pFUnit generates from the .pf
    # compiles cleanly with them; pFUnit's own driver program calls the suite
    # function and funit_main without explicit interfaces, so only that generated
    # file is relieved of -Wimplicit-interface.
    landyn_set_flags(${name})
    set_source_files_properties(${CMAKE_CURRENT_BINARY_DIR}/${name}_driver.F90
      PROPERTIES COMPILE_OPTIONS -Wno-implicit-interface)
  else()
    set(gen_dir ${CMAKE_CURRENT_BINARY_DIR}/pfunit_lite/${name})
    set(gen_module ${gen_dir}/${name}.F90)
    set(gen_driver ${gen_dir}/${name}_driver.F90)
    file(MAKE_DIRECTORY ${gen_dir})
    add_custom_command(
      OUTPUT ${gen_module} ${gen_driver}
      COMMAND ${Python3_EXECUTABLE} ${LANDYN_PFUNIT_LITE_DIR}/pf2f90.py ${pf_file}
              --output ${gen_module} --driver ${gen_driver}
      DEPENDS ${pf_file} ${LANDYN_PFUNIT_LITE_DIR}/pf2f90.py
      COMMENT "pf2f90: translating ${name}.pf"
      VERBATIM)
    add_executable(${name} ${gen_module} ${gen_driver})
    set_target_properties(${name} PROPERTIES
      Fortran_MODULE_DIRECTORY ${gen_dir}/mod)
    target_link_libraries(${name} PRIVATE landyn_funit_lite ${ARG_LINK_LIBRARIES})
    landyn_set_flags(${name})
    add_test(NAME ${name} COMMAND ${name} WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
    set_tests_properties(${name} PROPERTIES LABELS "${ARG_LABELS}")
    if(ARG_WILL_FAIL)
      set_tests_properties(${name} PROPERTIES WILL_FAIL TRUE)
    endif()
  endif()
  # Tests that read shipped files (input decks) find the source tree through this variable.
  set_tests_properties(${name} PROPERTIES ENVIRONMENT "LANDYN_SOURCE_DIR=${CMAKE_SOURCE_DIR}")
endfunction()

# Self-tests of the in-tree translator/runtime (only meaningful without real pFUnit).
if(NOT LANDYN_HAVE_REAL_PFUNIT)
  add_subdirectory(${LANDYN_PFUNIT_LITE_DIR} ${CMAKE_BINARY_DIR}/tests/pfunit_lite_selftest)
endif()
