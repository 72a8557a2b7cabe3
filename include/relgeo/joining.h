// relgeo/joining.h — umbrella header of the joining area (thesis Ch. 4):
// projection onto NURBS faces, error measures and certified checks in
// (u,v), the Whitney extension with its floating-point guarantees, the
// joiner (cases 1 and 2), naive midpoint sewing as the baseline. Needs CGAL
// (relgeo::cgal) and Eigen (relgeo::eigen): the joiner triangulates the
// external regions with CGAL's Mesh_2 (Ruppert refinement of a constrained
// Delaunay triangulation, relgeo/joining/domain_mesher.h). A client that only
// projects, measures or extends includes projection.h, error_measures.h or
// whitney_extension.h and needs no CGAL. Optional parts have their own
// headers: relgeo/joining/join_report_json.h (nlohmann-json: relgeo::io),
// relgeo/joining/occt_sewing.h (OpenCASCADE: relgeo::occt). The surfaces
// themselves: relgeo/surfaces.h. Files in, files out is the tool's job
// (`relgeo join`, tools/relgeo/commands/join/); the joining inputs the tests
// use are fixtures (fixtures/relgeo_fixtures/joining/test_models.h).
#pragma once

#include "relgeo/joining/boundary_chains.h"
#include "relgeo/joining/central_mesh.h"
#include "relgeo/joining/domain_mesher.h"
#include "relgeo/joining/error_measures.h"
#include "relgeo/joining/join_report.h"
#include "relgeo/joining/joiner.h"
#include "relgeo/joining/joining_errors.h"
#include "relgeo/joining/naive_sewing.h"
#include "relgeo/joining/projection.h"
#include "relgeo/joining/whitney_extension.h"
#include "relgeo/surfaces.h"
