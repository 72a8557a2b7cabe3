// relgeo/joining/joining_errors.h — the typed errors of the joining area.
//
// Bad input (Invalid_input): a point whose projection onto a surface is not
// unique, leaves the surface's domain or does not converge
// (Projection_error); meshes and surface models that do not fit together
// (Joining_input_error). A failure the joiner detects in its own work
// (Joining_failure, computation_failure): e.g. the central mesh vanished.
// The spline and trim errors are in surfaces/surface_errors.h.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <string_view>

#include "relgeo/core/errors.h"

namespace relgeo {

/// Why a point could not be projected onto a surface.
enum class Projection_failure {
  not_unique,      ///< two closest points (almost) equally far, or the point is near a focal point
  outside_domain,  ///< the closest point lies beyond the parameter domain (plus the allowed extrapolation)
  no_convergence   ///< the closest-point iteration did not converge
};

constexpr std::string_view to_string(Projection_failure f) noexcept {
  switch (f) {
    case Projection_failure::not_unique: return "not_unique";
    case Projection_failure::outside_domain: return "outside_domain";
    case Projection_failure::no_convergence: return "no_convergence";
  }
  return "unknown";
}

/// A point (mesh vertex, boundary sample) has no well-defined projection.
class Projection_error : public Invalid_input {
 public:
  Projection_error(Projection_failure failure, const std::string& what,
                   std::size_t index = std::numeric_limits<std::size_t>::max())
      : Invalid_input(what), failure_(failure), index_(index) {}
  Projection_failure failure() const noexcept { return failure_; }
  /// Index of the offending point in the caller's sequence (max() if none).
  std::size_t index() const noexcept { return index_; }

 private:
  Projection_failure failure_;
  std::size_t index_;
};

/// Meshes and surfaces that do not fit together (a mesh without faces, a
/// mesh patch without boundary, a face without a mesh, an edge shared by more
/// than two faces ...).
class Joining_input_error : public Invalid_input {
 public:
  explicit Joining_input_error(const std::string& what) : Invalid_input(what) {}
};

/// The joiner detected a failure of its own steps (it never returns a
/// result it knows to be wrong).
class Joining_failure : public Error {
 public:
  explicit Joining_failure(const std::string& what) : Error(Error_code::computation_failure, what) {}
};

}  // namespace relgeo
