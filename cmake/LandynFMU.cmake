# The FMI 2.0 co-simulation FMU (docs/api.md, "FMU"): the target landyn_fmu (part of ALL) writes
# ${CMAKE_BINARY_DIR}/landyn.fmu, a zip of
#   modelDescription.xml              written by landyn_fmu_describe (src/app/landyn_fmu_describe.f90)
#   binaries/linux64/landyn.so        src/api/fmu/landyn_fmi2.c, the generated table of variables
#                                     (landyn_fmu_vars.c, same walk as the description) and LANDYN's
#                                     library code (landyn_lib, position-independent, linked in)
# landyn.so needs nothing of the build tree; the system libraries (libgfortran, LAPACK/BLAS, HDF5)
# stay shared. Only the fmi2* functions are exported (--exclude-libs hides the library's symbols,
# so an FMU loaded next to liblandyn.so or another Fortran code does not interpose on them).
# The FMU tests (tests/fmu, label fmu) need FMPy in the Python environment (post/requirements.txt).
set(LANDYN_FMU_DIR ${CMAKE_BINARY_DIR}/fmu)

add_executable(landyn_fmu_describe ${CMAKE_SOURCE_DIR}/src/app/landyn_fmu_describe.f90)
target_link_libraries(landyn_fmu_describe PRIVATE landyn_lib)
landyn_set_flags(landyn_fmu_describe)

add_custom_command(OUTPUT ${LANDYN_FMU_DIR}/modelDescription.xml ${LANDYN_FMU_DIR}/landyn_fmu_vars.c
  COMMAND ${CMAKE_COMMAND} -E make_directory ${LANDYN_FMU_DIR}
  COMMAND landyn_fmu_describe ${LANDYN_FMU_DIR}
  DEPENDS landyn_fmu_describe
  COMMENT "Writing the FMU's modelDescription.xml and table of variables")

add_library(landyn_fmu_binary SHARED ${CMAKE_SOURCE_DIR}/src/api/fmu/landyn_fmi2.c
            ${LANDYN_FMU_DIR}/landyn_fmu_vars.c)
set_target_properties(landyn_fmu_binary PROPERTIES
  OUTPUT_NAME landyn PREFIX "" SUFFIX ".so"
  LIBRARY_OUTPUT_DIRECTORY ${LANDYN_FMU_DIR}/binaries/linux64
  C_STANDARD 99 C_STANDARD_REQUIRED ON C_VISIBILITY_PRESET hidden)
target_include_directories(landyn_fmu_binary PRIVATE ${CMAKE_SOURCE_DIR}/include
  ${CMAKE_SOURCE_DIR}/src/api/fmu ${CMAKE_SOURCE_DIR}/src/api/fmu/fmi2)
target_compile_options(landyn_fmu_binary PRIVATE -Wall -Wextra
  $<$<BOOL:${LANDYN_WERROR}>:-Werror>)
target_link_libraries(landyn_fmu_binary PRIVATE landyn_lib m)
target_link_options(landyn_fmu_binary PRIVATE -Wl,--exclude-libs,ALL -Wl,--no-undefined)

add_custom_command(OUTPUT ${CMAKE_BINARY_DIR}/landyn.fmu
  COMMAND ${CMAKE_COMMAND} -E rm -f ${CMAKE_BINARY_DIR}/landyn.fmu
  COMMAND ${CMAKE_COMMAND} -E tar cf ${CMAKE_BINARY_DIR}/landyn.fmu --format=zip
          modelDescription.xml binaries/linux64/landyn.so
  WORKING_DIRECTORY ${LANDYN_FMU_DIR}
  DEPENDS landyn_fmu_binary ${LANDYN_FMU_DIR}/modelDescription.xml
  COMMENT "Packing ${CMAKE_BINARY_DIR}/landyn.fmu")
add_custom_target(landyn_fmu ALL DEPENDS ${CMAKE_BINARY_DIR}/landyn.fmu)

add_subdirectory(${CMAKE_SOURCE_DIR}/tests/fmu ${CMAKE_BINARY_DIR}/tests/fmu)
