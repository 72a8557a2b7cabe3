// relgeo/mesh/validity.h — validity checks with a typed report (thesis Sec.
// 5.4.2; SPEC Sec. 5 step 5): closed, 2-manifold, consistently oriented, no
// degenerate faces, finite coordinates, valid tags. Self-intersection is
// added by self_intersection.h (check_solid); the structured report with
// orientation, volume and topology is solid_validation.h (validate_solid).
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "relgeo/core/certified_sign.h"
#include "relgeo/kernel/compiled_kernels.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/kernel_for_number.h"
#include "relgeo/kernel/point_access.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/mesh_report.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

namespace internal {

/// Every check of check_mesh except the collinearity test (which needs a
/// kernel): indices, repeated vertices, edges and vertices, boundary,
/// isolated vertices, tags, non-finite coordinates. Never throws for bad
/// input; O(V + F). The topology it builds (Mesh_topology::build_checked) is
/// left in `t` for callers that go on working on the mesh.
template <class P>
Mesh_report combinatorial_mesh_report(const Triangle_mesh<P>& m, const Mesh_check_options& options,
                                      Mesh_topology& t) {
  Mesh_report r;
  const std::size_t nv = m.vertices.size();
  for (Index v = 0; v < nv; ++v)
    if (!internal::point_is_finite(m.vertices[v]))
      r.issues.push_back({Mesh_defect::non_finite_coordinate, {v, invalid_index}});
  t = Mesh_topology::build_checked(nv, m.faces, r.issues);
  // An edge whose other side failed to pair (non-manifold / misoriented) is
  // already reported; report true boundary edges only (looked up in the
  // sorted reported edges: linear in the number of edges).
  std::vector<Edge> reported;
  for (const Mesh_issue& i : r.issues)
    if (i.defect == Mesh_defect::non_manifold_edge || i.defect == Mesh_defect::inconsistent_orientation)
      reported.push_back({i.elements[0], i.elements[1]});
  std::sort(reported.begin(), reported.end());
  for (Index e = 0; e < t.number_of_edges(); ++e)
    if (options.require_closed && t.is_boundary_edge(e)) {
      const Edge ab = t.edge_vertices(e);
      const Index h = t.edge_halfedge(e);
      if (t.find_halfedge(t.target(h), t.source(h)) == invalid_index &&
          !std::binary_search(reported.begin(), reported.end(), ab))
        r.issues.push_back({Mesh_defect::boundary_edge, {ab.a, ab.b}});
    }
  if (options.report_isolated_vertices) {
    std::vector<char> used(nv, 0);
    for (const Triangle& f : m.faces)
      for (Index v : f)
        if (v < nv) used[v] = 1;
    for (Index v = 0; v < nv; ++v)
      if (!used[v]) r.issues.push_back({Mesh_defect::isolated_vertex, {v, invalid_index}});
  }
  for (const Edge& c : m.tags.creases())
    if (c.a >= nv || c.b >= nv || t.find_edge(c.a, c.b) == invalid_index)
      r.issues.push_back({Mesh_defect::invalid_tag, {c.a, c.b}});
  for (Index v : m.tags.corners())
    if (v >= nv) r.issues.push_back({Mesh_defect::invalid_tag, {v, invalid_index}});
  return r;
}
template <class P>
Mesh_report combinatorial_mesh_report(const Triangle_mesh<P>& m, const Mesh_check_options& options) {
  Mesh_topology t;
  return combinatorial_mesh_report(m, options, t);
}

/// check_mesh under kernel K, leaving the mesh's topology in `t`.
template <Kernel K, class P>
Mesh_report check_mesh(const Triangle_mesh<P>& m, const Mesh_check_options& options, Mesh_topology& t) {
  using A = internal::Point_access<P>;
  Mesh_report r = internal::combinatorial_mesh_report(m, options, t);
  const std::size_t nv = m.vertices.size();
  if (options.check_collinear_faces) {
    const K k{};
    const auto collinear = k.coplanar_orientation_3_object();
    for (Index f = 0; f < m.faces.size(); ++f) {
      const Triangle& tr = m.faces[f];
      if (tr[0] >= nv || tr[1] >= nv || tr[2] >= nv) continue;
      if (tr[0] == tr[1] || tr[1] == tr[2] || tr[0] == tr[2]) continue;  // reported as repeated
      const P& a = m.vertices[tr[0]];
      const P& b = m.vertices[tr[1]];
      const P& c = m.vertices[tr[2]];
      if (!internal::point_is_finite(a) || !internal::point_is_finite(b) || !internal::point_is_finite(c))
        continue;
      using KP = typename K::Point_3;
      const auto cv = [](const P& p) {
        if constexpr (std::is_same_v<KP, P>) return p;
        else return internal::Point_access<KP>::make(A::x(p), A::y(p), A::z(p));
      };
      const Certified_sign s = collinear(cv(a), cv(b), cv(c));
      if (certainly(s, Certified_sign::zero))
        r.issues.push_back({Mesh_defect::collinear_face, {f, invalid_index}});
      else if (!is_certain(s))
        r.issues.push_back({Mesh_defect::undecided, {f, invalid_index}});
    }
  }
  return r;
}

}  // namespace internal

/// \brief Checks a triangle mesh and lists every defect with its location.
///
/// Combinatorial checks (exact by nature): indices in range, repeated
/// vertices in a face, edges with more than two faces, edges traversed twice
/// in the same direction, vertices whose faces form several fans, boundary
/// edges (when options.require_closed), isolated vertices, invalid tags.
/// Geometric checks: non-finite coordinates; collinear faces through K's
/// coplanar_orientation_3 (an `uncertain` answer gives an `undecided` issue).
/// Never throws for bad input. Complexity O(V + F). K: by default
/// Predicate_kernel_for_number of the coordinate type (exact predicates for
/// double and rationals).
template <KernelOrDefault K = void, class P>
Mesh_report check_mesh(const Triangle_mesh<P>& m, const Mesh_check_options& options = {}) {
  using Kernel = Kernel_or_default<K, Predicate_kernel_for_number, P>;
  Mesh_topology t;
  return internal::check_mesh<Kernel>(m, options, t);
}

/// Throws Invalid_mesh with every issue of check_mesh (context names the
/// caller in the message); returns normally for a valid mesh.
template <KernelOrDefault K = void, class P>
void require_valid_mesh(const Triangle_mesh<P>& m, const Mesh_check_options& options = {},
                        const std::string& context = "require_valid_mesh") {
  Mesh_report r = check_mesh<K>(m, options);
  if (!r.is_valid()) throw Invalid_mesh(context, std::move(r.issues));
}

// The instances relgeo::compiled makes (src/compiled/mesh_checks.cpp).
#define RELGEO_CHECK_MESH_INSTANCE(PREFIX, K)                                                     \
  PREFIX Mesh_report internal::check_mesh<K, Point_3<double>>(const Triangle_mesh<Point_3<double>>&, \
                                                              const Mesh_check_options&, Mesh_topology&);
#if RELGEO_LINKS_COMPILED
RELGEO_COMPILED_KERNELS(RELGEO_CHECK_MESH_INSTANCE, extern template)
#endif

}  // namespace relgeo
