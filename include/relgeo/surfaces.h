// relgeo/surfaces.h — umbrella header of the surfaces area: B-spline/NURBS
// curves and surfaces generic over the number type, trimmed patches with the
// certified point-in-domain test, surface models (faces and shared edges).
// Optional parts have their own headers: relgeo/surfaces/surface_json.h
// (nlohmann-json), relgeo/surfaces/occt_conversion.h and occt_io.h
// (OpenCASCADE: link relgeo::occt).
#pragma once

#include "relgeo/surfaces/bspline_basis.h"
#include "relgeo/surfaces/nurbs_curve.h"
#include "relgeo/surfaces/nurbs_surface.h"
#include "relgeo/surfaces/surface_errors.h"
#include "relgeo/surfaces/surface_model.h"
#include "relgeo/surfaces/trimmed_surface.h"
