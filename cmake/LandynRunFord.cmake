# Runs FORD for the api_docs target (cmake/LandynDocs.cmake) and fails on any warning.
# Variables: FORD, PROJECT_FILE, SRC_DIR, GENERATED_DIR, OUTPUT_DIR.
execute_process(
  COMMAND ${FORD} ${PROJECT_FILE} --src_dir ${SRC_DIR} --src_dir ${GENERATED_DIR} --output_dir ${OUTPUT_DIR}
  OUTPUT_VARIABLE _out ERROR_VARIABLE _err RESULT_VARIABLE _rc)
set(_all "${_out}${_err}")
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "api_docs: FORD failed (exit status ${_rc}):\n${_all}")
endif()
string(TOLOWER "${_all}" _lower)
if(_lower MATCHES "warning")
  message(FATAL_ERROR "api_docs: FORD printed warnings (fix the comments they name):\n${_all}")
endif()
message(STATUS "api_docs: ${OUTPUT_DIR}/index.html")
