// relgeo/surfaces/surface_errors.h — the typed errors of parametric curves,
// surfaces and trimmed patches (all relgeo::Invalid_input: bad input).
//
// Channel (core/errors.h): constructors and readers validate their input and
// throw one of these; evaluation never throws for input it accepted, except
// Degenerate_surface where a normal is asked for at a point where the surface
// has none (Su x Sv = 0).
#pragma once

#include <string>

#include "relgeo/core/errors.h"

namespace relgeo {

/// A B-spline/NURBS curve or surface whose data is inconsistent: degree out
/// of range, knot vector of the wrong size, decreasing or with a multiplicity
/// above the degree (inside) or degree + 1 (ends), non-positive or non-finite
/// weights, a control net of the wrong size.
class Invalid_spline : public Invalid_input {
 public:
  explicit Invalid_spline(const std::string& what) : Invalid_input(what) {}
};

/// A surface without a tangent plane where one is needed: all control points
/// collinear (nowhere a normal), or Su x Sv = 0 at an evaluated point (a pole
/// of a sphere, a collapsed edge).
class Degenerate_surface : public Invalid_input {
 public:
  explicit Degenerate_surface(const std::string& what) : Invalid_input(what) {}
};

/// A trim loop that is not a closed curve in the (u,v) domain (consecutive
/// curves do not meet, the last does not return to the first), or with fewer
/// than three distinct points.
class Open_trim_loop : public Invalid_input {
 public:
  explicit Open_trim_loop(const std::string& what) : Invalid_input(what) {}
};

}  // namespace relgeo
