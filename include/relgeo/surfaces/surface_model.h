// relgeo/surfaces/surface_model.h — a set of trimmed faces and the edges
// they share: the part of a B-rep that joining needs.
//
// An edge is where faces meet. It may carry its 3D curve b(t) (a NURBS curve
// or a polyline; what STEP and IGES files give, thesis Sec. 4.3.2, case 1) or
// none (case 2: the joiner builds a surrogate from the meshes). Faces refer to
// edges from their trim curves (Trim_curve::edge); a trim curve's natural
// direction (before its `reversed` flag) is the direction of its edge's 3D
// curve, as for OpenCASCADE's p-curves.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/kernel/point.h"
#include "relgeo/surfaces/nurbs_curve.h"
#include "relgeo/surfaces/trimmed_surface.h"

namespace relgeo {

/// A model edge: optionally its 3D curve, as a NURBS curve or a polyline.
struct Model_edge {
  std::optional<Nurbs_curve_3<double>> curve;
  /// Used when `curve` is empty; empty too for an edge without 3D geometry.
  std::vector<Point_3<double>> polyline;
  bool has_geometry() const { return curve.has_value() || polyline.size() >= 2; }
};

/// One use of an edge by a face: which face, loop (0 = outer) and curve.
struct Edge_use {
  std::size_t face = 0, loop = 0, curve = 0;
};

/// Trimmed faces and their edges.
struct Surface_model {
  std::vector<Trimmed_surface> faces;
  std::vector<Model_edge> edges;

  /// The trim loops of face f: [0] outer, then inner.
  static const Trim_loop& loop(const Trimmed_surface& f, std::size_t l) {
    return l == 0 ? f.outer_loop() : f.inner_loops()[l - 1];
  }
  /// For each edge, the trim curves that lie on it (two for an edge where
  /// two faces meet, one for a free edge).
  /// \throws Invalid_input when a trim curve names an edge that does not exist.
  std::vector<std::vector<Edge_use>> edge_uses() const {
    std::vector<std::vector<Edge_use>> uses(edges.size());
    for (std::size_t f = 0; f < faces.size(); ++f)
      for (std::size_t l = 0; l <= faces[f].inner_loops().size(); ++l) {
        const Trim_loop& tl = loop(faces[f], l);
        for (std::size_t c = 0; c < tl.curves.size(); ++c) {
          const int e = tl.curves[c].edge;
          if (e < 0) continue;
          if (static_cast<std::size_t>(e) >= edges.size())
            throw Invalid_input("surface model: face " + std::to_string(f) + " names edge " + std::to_string(e) +
                                " of " + std::to_string(edges.size()));
          uses[static_cast<std::size_t>(e)].push_back({f, l, c});
        }
      }
    return uses;
  }
};

}  // namespace relgeo
