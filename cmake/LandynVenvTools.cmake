# landyn_find_venv_tool(<var> <name>): find_program(<var> <name>) looking first next to the configured
# Python (the directory of Python3_EXECUTABLE, normally a venv's bin/) and in the source tree's .venv/bin,
# then on the PATH. Like find_program, <var> is a cache variable: -D<var>=/path/to/tool overrides it, and
# <var> is <var>-NOTFOUND when the tool is nowhere. Used for fypp (LandynFypp.cmake) and FORD
# (LandynDocs.cmake), which scripts/install_prereqs.sh can install into .venv.

include_guard(GLOBAL)

function(landyn_find_venv_tool var name)
  set(_hints "")
  if(Python3_EXECUTABLE)
    get_filename_component(_py_dir "${Python3_EXECUTABLE}" DIRECTORY)
    list(APPEND _hints "${_py_dir}")
  endif()
  find_program(${var} ${name} HINTS ${_hints} ${CMAKE_SOURCE_DIR}/.venv/bin)
endfunction()
