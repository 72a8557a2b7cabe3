// relgeo/curves.h — umbrella header of the curves area (thesis Sec. 3.4.1):
// planar Bezier curves, closed Bezier contours, the rotation of 3D input to
// the plane, exact convex-hull separations, and the certified well-formedness
// check of extruded objects. (The contours the tests and the manual use are
// fixtures, not library: fixtures/relgeo_fixtures/curves/test_contours.h.)
#pragma once

#include "relgeo/curves/bezier_curve.h"
#include "relgeo/curves/contour.h"
#include "relgeo/curves/convex_separation.h"
#include "relgeo/curves/extrusion.h"
