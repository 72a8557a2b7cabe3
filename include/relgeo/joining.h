// relgeo/joining.h — umbrella header of the joining area (thesis Ch. 4):
// projection onto NURBS faces, error measures and certified checks in
// (u,v), the Whitney extension with its floating-point guarantees, the
// joiner (cases 1 and 2), naive midpoint sewing as the baseline, the
// library-made test inputs. Needs CGAL (relgeo::cgal: Mesh_2) and Eigen
// (relgeo::eigen). Optional parts have their own headers:
// relgeo/joining/join_report_json.h and join_command.h (nlohmann-json),
// relgeo/joining/occt_sewing.h (OpenCASCADE: relgeo::occt).
// The surfaces themselves: relgeo/surfaces.h.
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
#include "relgeo/joining/test_models.h"
#include "relgeo/joining/whitney_extension.h"
#include "relgeo/surfaces.h"
