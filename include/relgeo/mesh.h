// relgeo/mesh.h — umbrella header of the mesh area: the triangle mesh type,
// its topology, validity checks and polygon soups (no CGAL, no Eigen needed).
// CGAL-based parts have their own headers: relgeo/mesh/mesh_io.h (files),
// relgeo/mesh/cgal_conversion.h (Surface_mesh, FaceGraph),
// relgeo/mesh/self_intersection.h (exact self-intersection test,
// check_solid); Eigen: relgeo/mesh/eigen_io.h.
#pragma once

#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/polygon_soup.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/mesh/validity.h"
