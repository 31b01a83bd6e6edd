# API documentation with FORD (docs/api/landyn.md): the target api_docs (not part of ALL) writes
# ${CMAKE_BINARY_DIR}/api_docs/index.html from the !> and !! comments of src/ (every layer,
# src/campaign and src/app included) and of the generated landyn_version.f90. It FAILS when FORD
# fails or prints a warning. The CTest test api_docs (label docs) builds it, so CI checks it.
# FORD is pinned in docs/api/requirements.txt (scripts/install_prereqs.sh installs it into .venv).

include(${CMAKE_CURRENT_LIST_DIR}/LandynVenvTools.cmake)
landyn_find_venv_tool(LANDYN_FORD ford)

if(LANDYN_FORD)
  add_custom_target(api_docs
    COMMAND ${CMAKE_COMMAND} -DFORD=${LANDYN_FORD} -DPROJECT_FILE=${CMAKE_SOURCE_DIR}/docs/api/landyn.md
            -DSRC_DIR=${CMAKE_SOURCE_DIR}/src -DGENERATED_DIR=${CMAKE_BINARY_DIR}/generated
            -DOUTPUT_DIR=${CMAKE_BINARY_DIR}/api_docs -P ${CMAKE_SOURCE_DIR}/cmake/LandynRunFord.cmake
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}
    COMMENT "LANDYN API documentation (FORD) -> ${CMAKE_BINARY_DIR}/api_docs/index.html"
    VERBATIM)
  add_test(NAME api_docs COMMAND ${CMAKE_COMMAND} --build ${CMAKE_BINARY_DIR} --target api_docs)
  set_tests_properties(api_docs PROPERTIES LABELS docs)
else()
  message(STATUS "LANDYN: FORD not found; no api_docs target (pip install -r docs/api/requirements.txt)")
endif()
