// relgeo/mesh/point_mesh_distance.h — the distance from points to a
// triangle mesh in doubles, through the faces' bounding-volume hierarchy:
// the measuring tool of sampled (Hausdorff) distances between surfaces.
//
// A measurement, not a certified bound: the closest point on a triangle is
// computed in double (Ericson, Real-Time Collision Detection, 5.1.5), so the
// distance carries a relative error of a few units in the last place.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "relgeo/kernel/point.h"
#include "relgeo/kernel/vector_3.h"
#include "relgeo/mesh/face_bvh.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// The squared distance from p to the triangle (a, b, c) (doubles).
inline double squared_distance_to_triangle(const Point_3<double>& p, const Point_3<double>& a,
                                           const Point_3<double>& b, const Point_3<double>& c) {
  using internal::dot;
  const auto sub = internal::difference<double>;
  const auto at = [&](const Point_3<double>& o, const Point_3<double>& e1, double s, const Point_3<double>& e2, double t) {
    const Point_3<double> q{o.x + s * e1.x + t * e2.x, o.y + s * e1.y + t * e2.y, o.z + s * e1.z + t * e2.z};
    const Point_3<double> d = sub(p, q);
    return dot(d, d);
  };
  // Voronoi regions of the vertices, edges and face of the triangle.
  const Point_3<double> ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return dot(ap, ap);
  const Point_3<double> bp = sub(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return dot(bp, bp);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return at(a, ab, d1 / (d1 - d3), ac, 0);
  const Point_3<double> cp = sub(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return dot(cp, cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return at(a, ab, 0, ac, d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return at(b, sub(c, b), w, ab, 0);
  }
  const double denom = va + vb + vc;
  if (!(denom > 0)) {  // degenerate triangle: its three edges
    const auto segment = [&](const Point_3<double>& u, const Point_3<double>& v) {
      const Point_3<double> e = sub(v, u), up = sub(p, u);
      const double ee = dot(e, e);
      const double t = ee > 0 ? std::clamp(dot(up, e) / ee, 0.0, 1.0) : 0.0;
      return at(u, e, t, e, 0);
    };
    return std::min({segment(a, b), segment(b, c), segment(c, a)});
  }
  return at(a, ab, vb / denom, ac, vc / denom);
}

/// \brief Distances from points to a triangle mesh (the mesh is kept by
/// reference: it must outlive this object).
class Point_mesh_distance {
 public:
  explicit Point_mesh_distance(const Triangle_mesh<Point_3<double>>& m) : mesh_(&m), bvh_(m) {}

  /// The distance from p to the mesh (infinity for a mesh without faces):
  /// the nearest face by Face_bvh::nearest_face.
  double operator()(const Point_3<double>& p) const {
    const double squared = bvh_.nearest_face(p, [&](Index f) {
      const Triangle& t = mesh_->faces[f];
      return squared_distance_to_triangle(p, mesh_->vertices[t[0]], mesh_->vertices[t[1]], mesh_->vertices[t[2]]);
    }).second;
    return std::sqrt(squared);
  }

 private:
  const Triangle_mesh<Point_3<double>>* mesh_;
  Face_bvh bvh_;
};

}  // namespace relgeo
