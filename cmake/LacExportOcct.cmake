# The optional component lac_export_occt (alias lac::export): STEP and IGES export of the B-splines
# of export/ through OpenCASCADE (export/occt/). LAC_WITH_OCCT is ON by default when OpenCASCADE
# is found; without it the library and the `lac` tool build as before and `--export` to .step or
# .iges says that this build has no OpenCASCADE. Linked toolkits: only those the writers and the
# read-back tests use. Not installed with the package (the installed lac needs no OpenCASCADE).
# Without COMPONENTS: Debian's DataExchange component names visualization toolkits (TKXCAF) that
# are not installed, which would fail the component request; the toolkits below are checked one by one.
find_package(OpenCASCADE CONFIG QUIET)
set(LAC_OCCT_TOOLKITS TKernel TKMath TKG3d TKGeomBase TKBRep TKTopAlgo TKGeomAlgo TKXSBase TKSTEP TKIGES)
set(LAC_OCCT_DEFAULT OFF)
set(LAC_OCCT_USABLE ${OpenCASCADE_FOUND})
foreach(tk IN LISTS LAC_OCCT_TOOLKITS)
  if(NOT TARGET ${tk})
    set(LAC_OCCT_USABLE OFF)
  endif()
endforeach()
if(LAC_OCCT_USABLE)
  set(LAC_OCCT_DEFAULT ON)
endif()
option(LAC_WITH_OCCT "Build lac::export, the STEP and IGES writers through OpenCASCADE" ${LAC_OCCT_DEFAULT})
if(LAC_WITH_OCCT)
  if(NOT LAC_OCCT_USABLE)
    message(FATAL_ERROR "LAC_WITH_OCCT is ON but OpenCASCADE or one of its toolkits ${LAC_OCCT_TOOLKITS} was not found (scripts/setup.sh installs them)")
  endif()
  file(GLOB LAC_OCCT_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/export/occt/*.cpp)
  add_library(lac_export_occt STATIC ${LAC_OCCT_SOURCES})
  add_library(lac::export ALIAS lac_export_occt)
  set_target_properties(lac_export_occt PROPERTIES POSITION_INDEPENDENT_CODE ON)
  target_include_directories(lac_export_occt SYSTEM PUBLIC ${OpenCASCADE_INCLUDE_DIR})
  target_link_libraries(lac_export_occt PUBLIC lac::lac ${LAC_OCCT_TOOLKITS})
  target_compile_definitions(lac_export_occt PUBLIC LAC_WITH_OCCT=1)
  message(STATUS "lac: STEP/IGES export through OpenCASCADE ${OpenCASCADE_VERSION}")
else()
  message(STATUS "lac: no OpenCASCADE: STEP/IGES export disabled (DXF and SVG remain)")
endif()
