# OpenCASCADE 7.6 or later (Debian 12: libocct-*-dev) as relgeo's optional
# target relgeo::occt: STEP/IGES input of trimmed NURBS faces
# (relgeo/surfaces/occt_io.h) and OCC's sewing and meshing as a peer
# (relgeo/joining/occt_sewing.h). Included by relgeo's CMakeLists.txt and by the
# installed relgeoConfig.cmake. Sets RELGEO_OCCT_LIBRARIES when found.
#
# Debian's OpenCASCADEConfigVersion.cmake accepts only its exact version, so
# the version is checked here. The data-exchange targets name the
# visualization and application-framework libraries, so those components are
# loaded too (libocct-data-exchange-dev depends on their -dev packages).
if(NOT DEFINED RELGEO_OCCT_LIBRARIES)
  # OpenCASCADE's config appends its build's definitions (HAVE_TBB, HAVE_TK
  # ...) to the including directory's COMPILE_DEFINITIONS: keep them out of
  # every other target (and out of clients).
  get_directory_property(relgeo_saved_definitions COMPILE_DEFINITIONS)
  find_package(OpenCASCADE CONFIG QUIET
    COMPONENTS FoundationClasses ModelingData ModelingAlgorithms Visualization ApplicationFramework DataExchange)
  set_directory_properties(PROPERTIES COMPILE_DEFINITIONS "${relgeo_saved_definitions}")
  if(OpenCASCADE_FOUND AND "${OpenCASCADE_MAJOR_VERSION}.${OpenCASCADE_MINOR_VERSION}" VERSION_GREATER_EQUAL 7.6)
    set(RELGEO_OCCT_LIBRARIES
      TKernel TKMath TKG2d TKG3d TKGeomBase TKBRep TKGeomAlgo TKTopAlgo TKPrim TKShHealing TKMesh
      TKXSBase TKSTEP TKSTEPBase TKIGES)
    set(RELGEO_OCCT_INCLUDE_DIR ${OpenCASCADE_INCLUDE_DIR})
  endif()
endif()
