# The meshes of CGAL's data set for tests and benchmarks, extracted into
# ${PROJECT_BINARY_DIR}/cgal_data/data/meshes (RELGEO_CGAL_MESH_DIR).
# Debian ships the set as /usr/share/doc/libcgal-dev/data.tar.gz in the
# libcgal-demo package; scripts/relgeo.sh unpacks that package without its GUI
# dependencies and passes the archive as RELGEO_CGAL_DATA_ARCHIVE.
set(RELGEO_CGAL_DATA_ARCHIVE /usr/share/doc/libcgal-dev/data.tar.gz
    CACHE FILEPATH "CGAL's data.tar.gz (package libcgal-demo)")
set(RELGEO_CGAL_MESH_DIR ${PROJECT_BINARY_DIR}/cgal_data/data/meshes)
if(EXISTS ${RELGEO_CGAL_DATA_ARCHIVE} AND NOT EXISTS ${RELGEO_CGAL_MESH_DIR}/armadillo.off)
  file(ARCHIVE_EXTRACT INPUT ${RELGEO_CGAL_DATA_ARCHIVE} DESTINATION ${PROJECT_BINARY_DIR}/cgal_data
       PATTERNS data/meshes)
endif()
if(NOT EXISTS ${RELGEO_CGAL_MESH_DIR}/fandisk.off)
  message(WARNING "relgeo: CGAL's data set not found (${RELGEO_CGAL_DATA_ARCHIVE}); "
                  "the tests and benchmarks on CGAL's meshes will be skipped")
endif()
