// relgeo/mesh.h — umbrella header of the mesh area: the triangle mesh type,
// its topology, validity checks, the face BVH, the exact self-intersection
// test, the solid validation report and polygon soups (no CGAL, no Eigen
// needed; threads with oneTBB when the target links relgeo::tbb).
// CGAL-based parts have their own headers: relgeo/mesh/mesh_io.h (files),
// relgeo/mesh/cgal_conversion.h (Surface_mesh, FaceGraph); Eigen:
// relgeo/mesh/eigen_io.h.
#pragma once

#include "relgeo/mesh/face_bvh.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/polygon_soup.h"
#include "relgeo/mesh/self_intersection.h"
#include "relgeo/mesh/solid_validation.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/mesh/validity.h"
