// relgeo/boolean/internal/broad_phase.h — the face pairs of two meshes whose
// bounding boxes overlap (closed boxes: touching counts), by a sweep along x
// over boxes sorted by their lower x (the one-way scan of Zomorodian and
// Edelsbrunner, as CGAL's box_intersection_d does it without its recursion).
// Coordinates are doubles, so the boxes are exact.
#pragma once

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "relgeo/kernel/point.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::internal {

struct Face_box {
  std::array<double, 3> lo, hi;
  Index face;
};

inline std::vector<Face_box> face_boxes(const Triangle_mesh<Point_3<double>>& m) {
  std::vector<Face_box> out;
  out.reserve(m.faces.size());
  for (Index f = 0; f < m.faces.size(); ++f) {
    Face_box b{{m.vertices[m.faces[f][0]].x, m.vertices[m.faces[f][0]].y, m.vertices[m.faces[f][0]].z}, {}, f};
    b.hi = b.lo;
    for (int k = 1; k < 3; ++k) {
      const Point_3<double>& p = m.vertices[m.faces[f][k]];
      const double c[3] = {p.x, p.y, p.z};
      for (int i = 0; i < 3; ++i) b.lo[i] = std::min(b.lo[i], c[i]), b.hi[i] = std::max(b.hi[i], c[i]);
    }
    out.push_back(b);
  }
  return out;
}

/// Calls report(face of a, face of b) for every pair of overlapping boxes.
template <class Report>
void for_each_overlapping_pair(std::vector<Face_box> a, std::vector<Face_box> b, Report&& report) {
  const auto by_lo_x = [](const Face_box& x, const Face_box& y) { return x.lo[0] < y.lo[0]; };
  std::sort(a.begin(), a.end(), by_lo_x);
  std::sort(b.begin(), b.end(), by_lo_x);
  const auto overlap_yz = [](const Face_box& x, const Face_box& y) {
    return x.lo[1] <= y.hi[1] && y.lo[1] <= x.hi[1] && x.lo[2] <= y.hi[2] && y.lo[2] <= x.hi[2];
  };
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (a[i].lo[0] <= b[j].lo[0]) {
      for (std::size_t k = j; k < b.size() && b[k].lo[0] <= a[i].hi[0]; ++k)
        if (overlap_yz(a[i], b[k])) report(a[i].face, b[k].face);
      ++i;
    } else {
      for (std::size_t k = i; k < a.size() && a[k].lo[0] <= b[j].hi[0]; ++k)
        if (overlap_yz(a[k], b[j])) report(a[k].face, b[j].face);
      ++j;
    }
  }
}

}  // namespace relgeo::internal
