// src/compiled/mesh_io.cpp — relgeo::compiled: read_mesh's and write_mesh's
// calls into CGAL's polygon-soup IO (OBJ, PLY, STL), made once;
// relgeo/mesh/internal/cgal_soup_io.h declares them for the clients.
#define RELGEO_DEFINE_CGAL_SOUP_IO 1
#include "relgeo/mesh/internal/cgal_soup_io.h"
