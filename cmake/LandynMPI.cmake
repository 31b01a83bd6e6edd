# MPI campaigns: the landyn_batch program (docs/campaign.md).
#
# Included from the top-level CMakeLists.txt after the landyn executable. Builds
#   landyn_campaign_lib  the campaign modules of src/campaign/ (deck, cases, summary file, MPI driver;
#                        the layer landyn_layer_campaign), linked with landyn_lib and MPI; the serial
#                        landyn_lib does not depend on MPI;
#   landyn_batch         src/app/landyn_batch.f90.
# LANDYN_WITH_MPI (default ON when an MPI with the Fortran mpi_f08 module is found) switches it on.
# For the campaign tests it sets LANDYN_MPIEXEC (launcher and flags as a list) and
# LANDYN_MPIEXEC_ENV (environment needed to launch, e.g. as root under Open MPI).

find_package(MPI COMPONENTS Fortran)
set(_landyn_mpi_default OFF)
if(MPI_Fortran_FOUND AND MPI_Fortran_HAVE_F08_MODULE)
  set(_landyn_mpi_default ON)
endif()
option(LANDYN_WITH_MPI "Build landyn_batch, the MPI campaign program (needs MPI with mpi_f08)" ${_landyn_mpi_default})

if(LANDYN_WITH_MPI)
  if(NOT MPI_Fortran_FOUND)
    message(FATAL_ERROR "LANDYN_WITH_MPI is ON but no MPI for Fortran was found (install e.g. libopenmpi-dev, "
                        "or configure with -DLANDYN_WITH_MPI=OFF)")
  endif()
  if(NOT MPI_Fortran_HAVE_F08_MODULE)
    message(FATAL_ERROR "LANDYN_WITH_MPI is ON but the MPI found has no Fortran mpi_f08 module")
  endif()
  message(STATUS "LANDYN campaigns: landyn_batch with MPI ${MPI_Fortran_VERSION} (${MPIEXEC_EXECUTABLE})")

  # The layer campaign (src/campaign/*.f90; module directory mod/campaign), then its static library
  # of the layer's objects, linked with landyn_lib for the layers below.
  landyn_layer(campaign USES core config physics input numerics output)
  target_link_libraries(landyn_layer_campaign PUBLIC MPI::MPI_Fortran)
  add_library(landyn_campaign_lib STATIC)
  set_target_properties(landyn_campaign_lib PROPERTIES OUTPUT_NAME landyn_campaign LINKER_LANGUAGE Fortran)
  target_link_libraries(landyn_campaign_lib PUBLIC landyn_layer_campaign landyn_lib MPI::MPI_Fortran)
  landyn_forget_stale_modules(landyn_campaign_lib)

  add_executable(landyn_batch src/app/landyn_batch.f90)
  target_link_libraries(landyn_batch PRIVATE landyn_campaign_lib)
  landyn_set_flags(landyn_batch)

  install(TARGETS landyn_batch RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(PROGRAMS post/landyn_envelope.py post/landyn_dispersion.py
          DESTINATION ${CMAKE_INSTALL_DATADIR}/landyn/post)
  install(DIRECTORY examples/ DESTINATION ${CMAKE_INSTALL_DATADIR}/landyn/examples)

  # Launcher for the campaign tests and benchmark. Open MPI refuses to start as root and to
  # start more ranks than cores without these (CI containers run as root on 2 cores).
  set(LANDYN_MPIEXEC ${MPIEXEC_EXECUTABLE})
  set(LANDYN_MPIEXEC_ENV "")
  execute_process(COMMAND ${MPIEXEC_EXECUTABLE} --version OUTPUT_VARIABLE _landyn_mpiexec_version
                  ERROR_QUIET RESULT_VARIABLE _landyn_mpiexec_rc)
  if(_landyn_mpiexec_rc EQUAL 0 AND _landyn_mpiexec_version MATCHES "Open MPI|OpenRTE")
    list(APPEND LANDYN_MPIEXEC --oversubscribe)
    set(LANDYN_MPIEXEC_ENV "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_rmaps_base_oversubscribe=1")
  endif()
  list(APPEND LANDYN_MPIEXEC ${MPIEXEC_PREFLAGS})
endif()
