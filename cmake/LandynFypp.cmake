# Fortran sources generated with fypp (https://fypp.readthedocs.io; Debian package fypp, installed by
# scripts/install_prereqs.sh): every template src/output/<name>.fypp becomes
# ${CMAKE_BINARY_DIR}/generated/<name>.f90 at build time, again whenever the template or an include
# file src/output/*.fypi changes. The list of generated files is LANDYN_FYPP_GENERATED, which the
# library's sources take. Used for the HDF5 layer's per-type and per-rank wrappers
# (landyn_h5_write, landyn_h5_read). Not committed; FORD documents them (GENERATED_DIR), and the
# CTest checks doc_comments and procedure_length read the generated files.
#
# Included from CMakeLists.txt it sets up the generation; run as a script
#   cmake -DFYPP=... -DIN=<template> -DOUT=<file.f90> -P LandynFypp.cmake
# it runs fypp on one template and fails when a generated line is longer than 132 characters
# (the house rule; gfortran rejects long code lines but not long comments).

if(CMAKE_SCRIPT_MODE_FILE)
  get_filename_component(_dir "${IN}" DIRECTORY)
  execute_process(COMMAND ${FYPP} --no-folding -I ${_dir} ${IN} ${OUT}.tmp
    RESULT_VARIABLE _rc ERROR_VARIABLE _err)
  if(NOT _rc EQUAL 0)
    file(REMOVE ${OUT}.tmp)
    message(FATAL_ERROR "fypp failed on ${IN}:\n${_err}")
  endif()
  file(READ ${OUT}.tmp _text)
  string(REPEAT "[^\n]" 133 _long)
  string(REGEX MATCH "${_long}[^\n]*" _line "${_text}")
  if(_line)
    file(REMOVE ${OUT}.tmp)
    message(FATAL_ERROR "${IN}: a line generated into ${OUT} is longer than 132 characters:\n${_line}")
  endif()
  file(RENAME ${OUT}.tmp ${OUT})
  return()
endif()

include(${CMAKE_CURRENT_LIST_DIR}/LandynVenvTools.cmake)
landyn_find_venv_tool(LANDYN_FYPP fypp)
if(NOT LANDYN_FYPP)
  message(FATAL_ERROR "LANDYN: fypp not found. It generates the HDF5 wrappers from src/output/*.fypp. "
    "Install it with scripts/install_prereqs.sh (Debian: apt-get install fypp; or pip install fypp), "
    "or name it with -DLANDYN_FYPP=/path/to/fypp.")
endif()

file(GLOB _landyn_fypp_templates CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/output/*.fypp)
file(GLOB _landyn_fypp_includes CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/output/*.fypi)
list(SORT _landyn_fypp_templates)
set(LANDYN_FYPP_GENERATED "")
foreach(_template IN LISTS _landyn_fypp_templates)
  get_filename_component(_name ${_template} NAME_WE)
  set(_out ${CMAKE_BINARY_DIR}/generated/${_name}.f90)
  add_custom_command(OUTPUT ${_out}
    COMMAND ${CMAKE_COMMAND} -DFYPP=${LANDYN_FYPP} -DIN=${_template} -DOUT=${_out}
            -P ${CMAKE_SOURCE_DIR}/cmake/LandynFypp.cmake
    DEPENDS ${_template} ${_landyn_fypp_includes} ${CMAKE_SOURCE_DIR}/cmake/LandynFypp.cmake
    COMMENT "Generating ${_name}.f90 from src/output/${_name}.fypp (fypp)"
    VERBATIM)
  list(APPEND LANDYN_FYPP_GENERATED ${_out})
endforeach()
