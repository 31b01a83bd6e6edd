# The result file's schema declared once (src/output/landyn_output_schema.f90, docs/output.md).
#
# Included from the top-level CMakeLists.txt after the landyn executable. Builds
#   landyn_schema                 src/app/landyn_schema.f90: prints the schema as a JSON manifest;
#   landyn_output_schema.json     the manifest of this build, in the build directory (part of ALL).
# landyn_post ships a copy as package data (post/landyn_post/data/output_schema.json, so that it works
# without a build); tests/docs/check_output_schema.py keeps the three in step:
#   output_schema_manifest  the shipped copy equals this build's manifest
#                           (update: python tests/docs/check_output_schema.py --manifest build/... --write)
#   output_schema_docs      every dataset table row of docs/output.md equals the manifest's, and every
#                           dataset of the manifest has its row (the same --write rewrites the rows)

add_executable(landyn_schema src/app/landyn_schema.f90)
target_link_libraries(landyn_schema PRIVATE landyn_lib)
landyn_set_flags(landyn_schema)

set(LANDYN_SCHEMA_MANIFEST ${CMAKE_BINARY_DIR}/landyn_output_schema.json)
add_custom_command(OUTPUT ${LANDYN_SCHEMA_MANIFEST}
  COMMAND landyn_schema ${LANDYN_SCHEMA_MANIFEST}
  DEPENDS landyn_schema
  COMMENT "Writing the result-file schema manifest landyn_output_schema.json"
  VERBATIM)
add_custom_target(landyn_schema_manifest ALL DEPENDS ${LANDYN_SCHEMA_MANIFEST})

add_test(NAME output_schema_manifest
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/docs/check_output_schema.py
                 --manifest ${LANDYN_SCHEMA_MANIFEST} --src ${CMAKE_SOURCE_DIR} --check manifest)
add_test(NAME output_schema_docs
         COMMAND ${Python3_EXECUTABLE} ${CMAKE_SOURCE_DIR}/tests/docs/check_output_schema.py
                 --manifest ${LANDYN_SCHEMA_MANIFEST} --src ${CMAKE_SOURCE_DIR} --check docs)
set_tests_properties(output_schema_manifest output_schema_docs PROPERTIES LABELS "docs")

# Installed next to the decks, for readers other than landyn_post.
install(FILES ${LANDYN_SCHEMA_MANIFEST} DESTINATION ${CMAKE_INSTALL_DATADIR}/landyn)
