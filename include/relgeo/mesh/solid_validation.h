// relgeo/mesh/solid_validation.h — the validation report of a triangle mesh
// as the boundary of a solid (thesis Sec. 5.4.2): every check with its
// status (pass, fail, undecided, not checked), where it fails (capped lists
// of faces, edges, vertices or face pairs, with the full count) and, where
// it means something, by what margin (the volume); plus Euler
// characteristic, components, genus and the exact signed volume.
//
// It wraps what exists: check_mesh (validity.h) finds the combinatorial
// defects, find_self_intersections (self_intersection.h) the exact
// self-intersections, both under the caller's kernel; this header adds the
// volume (internal/exact_volume.h: exact for double and rational
// coordinates), the topology (internal/mesh_components.h) and the
// orientation test (internal/component_winding.h: every component's volume
// sign against its nesting, decided exactly). The report is a plain
// aggregate (strings, numbers, vectors) so that the tool can print it as
// JSON field by field.
//
// What depends on what: the geometric checks (degenerate faces beyond a
// repeated index, self-intersection, volume, orientation) need valid
// indices and finite coordinates; the orientation test needs a closed,
// manifold, consistently oriented, non-degenerate mesh without
// self-intersection; the genus a closed, manifold, consistently oriented
// one. A check whose preconditions fail is `not_checked`, and its note says
// why.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "relgeo/core/certified_sign.h"
#include "relgeo/kernel/compiled_kernels.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/mesh/face_bvh.h"
#include "relgeo/mesh/internal/component_winding.h"
#include "relgeo/mesh/internal/embedded_stars.h"
#include "relgeo/mesh/internal/exact_volume.h"
#include "relgeo/mesh/internal/kernel_points.h"
#include "relgeo/mesh/internal/mesh_components.h"
#include "relgeo/mesh/internal/projected_patches.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/self_intersection.h"
#include "relgeo/mesh/solid_report.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/mesh/validity.h"

namespace relgeo {

namespace internal {

inline void record(Solid_check& c, const Mesh_issue& i, std::size_t cap) {
  ++c.count;
  if (c.where.size() < cap) c.where.push_back(i);
}
inline void conclude(Solid_check& c, bool undecided = false) {
  c.status = c.count == 0 ? Check_status::pass : (undecided ? Check_status::undecided : Check_status::fail);
}
inline void not_checked(Solid_check& c, std::string why) {
  c = Solid_check{};
  c.note = std::move(why);
}

// check_mesh's issues sorted into the report's checks.
inline void sort_mesh_issues(const Mesh_report& mr, const Solid_validation_options& o, Solid_report& r) {
  const std::size_t cap = o.max_listed;
  for (const Mesh_issue& i : mr.issues) {
    switch (i.defect) {
      case Mesh_defect::index_out_of_range: record(r.valid_indices, i, cap); break;
      case Mesh_defect::non_finite_coordinate: record(r.finite_coordinates, i, cap); break;
      case Mesh_defect::repeated_vertex_in_face: record(r.non_degenerate_faces, i, cap); break;
      case Mesh_defect::isolated_vertex: record(r.no_isolated_vertices, i, cap); break;
      case Mesh_defect::invalid_tag: record(r.valid_tags, i, cap); break;
      case Mesh_defect::boundary_edge: record(r.closed, i, cap); break;
      case Mesh_defect::non_manifold_edge: record(r.edge_manifold, i, cap); break;
      case Mesh_defect::non_manifold_vertex: record(r.vertex_manifold, i, cap); break;
      case Mesh_defect::inconsistent_orientation: record(r.consistently_oriented, i, cap); break;
      default: break;  // geometric defects: not asked of check_mesh
    }
  }
  for (Solid_check* c : {&r.valid_indices, &r.finite_coordinates, &r.valid_tags, &r.edge_manifold,
                         &r.vertex_manifold, &r.consistently_oriented})
    conclude(*c);
  if (o.mesh.report_isolated_vertices) conclude(r.no_isolated_vertices);
  else not_checked(r.no_isolated_vertices, "turned off (Mesh_check_options::report_isolated_vertices)");
  if (o.mesh.require_closed) conclude(r.closed);
  else not_checked(r.closed, "turned off (Mesh_check_options::require_closed)");
}

// Components, Euler characteristic, genus. \pre valid indices, `t` the
// faces' topology (combinatorial_mesh_report's).
template <class P>
Face_components report_topology(const Triangle_mesh<P>& m, const Mesh_topology& t, const Solid_validation_options& o,
                                Solid_report& r) {
  Face_components comps = face_components(m.faces, m.vertices.size());
  std::optional<std::vector<Euler_counts>> from_topology;
  if (r.edge_manifold.passed() && r.consistently_oriented.passed())
    from_topology = euler_counts(m.faces, m.vertices.size(), comps, t);
  const std::vector<Euler_counts> counts =
      from_topology ? std::move(*from_topology) : euler_counts(m.faces, m.vertices.size(), comps);
  const bool surface = r.closed.passed() && r.edge_manifold.passed() && r.vertex_manifold.passed() &&
                       r.consistently_oriented.passed() && r.non_degenerate_faces.count == 0;
  Euler_counts all;
  long long genus = 0;
  for (std::size_t c = 0; c < comps.size(); ++c) {
    all.vertices += counts[c].vertices, all.edges += counts[c].edges, all.faces += counts[c].faces;
    genus += (2 - counts[c].characteristic()) / 2;
    if (r.component_list.size() < o.max_listed) {
      Solid_component sc;
      sc.first_face = comps.first_face[c];
      sc.vertices = counts[c].vertices, sc.edges = counts[c].edges, sc.faces = counts[c].faces;
      sc.euler_characteristic = counts[c].characteristic();
      if (surface) sc.genus = (2 - sc.euler_characteristic) / 2;
      r.component_list.push_back(sc);
    }
  }
  r.components = comps.size();
  r.edges = all.edges;
  r.euler_characteristic = all.characteristic();
  if (surface) r.genus = genus;
  return comps;
}

template <class P>
Signed_volumes report_volume(const Triangle_mesh<P>& m, const Face_components& comps,
                             const Solid_validation_options& o, Solid_report& r) {
  Signed_volumes v = signed_volumes(m, comps.component, comps.size(), r.component_list.size());
  r.volume.computed = true;
  r.volume.exact = v.exact;
  r.volume.lower = v.total_lower, r.volume.upper = v.total_upper;
  if (v.exact) {
    r.volume.value = round_rational<double>(v.total, Rounding::to_nearest);
    if (o.exact_volume_string) r.volume.exact_value = v.total.get_str();
  } else {
    r.volume.value = 0.5 * v.total_lower + 0.5 * v.total_upper;
  }
  for (std::size_t c = 0; c < r.component_list.size(); ++c) r.component_list[c].volume = v.value[c];
  return v;
}

// The orientation test (internal/component_winding.h).
template <Kernel K, class P, class Points>
void report_orientation(const K& k, const Triangle_mesh<P>& m, const Points& point, const Face_bvh& bvh,
                        const Face_components& comps, const Signed_volumes& v, const Solid_validation_options& o,
                        Solid_report& r) {
  const std::vector<std::optional<int>> winding = component_windings(k, m, point, bvh, comps);
  bool undecided = false;
  for (std::size_t c = 0; c < comps.size(); ++c) {
    if (c < r.component_list.size()) r.component_list[c].winding = winding[c];
    const Certified_sign s = v.sign[c];
    if (!winding[c] || !is_certain(s)) {
      undecided = true;
      record(r.outward_oriented, {Mesh_defect::undecided, {comps.first_face[c], static_cast<Index>(c)}},
             o.max_listed);
      continue;
    }
    const bool shell = *winding[c] == 0 && certainly(s, Certified_sign::positive);
    const bool cavity = *winding[c] == 1 && certainly(s, Certified_sign::negative);
    if (!shell && !cavity)
      record(r.outward_oriented, {Mesh_defect::misoriented_component, {comps.first_face[c], static_cast<Index>(c)}},
             o.max_listed);
  }
  // Failures first: undecided only when nothing failed.
  bool failed = false;
  for (const Mesh_issue& i : r.outward_oriented.where) failed = failed || i.defect == Mesh_defect::misoriented_component;
  conclude(r.outward_oriented, undecided && !failed);
}

}  // namespace internal

namespace internal {

/// 1 for every face sharing a vertex with a face outside the certified
/// groups (Certified_faces): the faces whose stars the test can use.
template <class P>
std::vector<unsigned char> faces_around_open_faces(const Triangle_mesh<P>& m, const std::vector<std::uint8_t>& group) {
  std::vector<unsigned char> open_vertex(m.vertices.size(), 0), around(m.faces.size(), 0);
  for (Index f = 0; f < m.faces.size(); ++f)
    if (!group[f])
      for (Index v : m.faces[f]) open_vertex[v] = 1;
  for (Index f = 0; f < m.faces.size(); ++f)
    for (Index v : m.faces[f]) around[f] |= open_vertex[v];
  return around;
}

/// validate_solid, except that the self-intersection test leaves to the
/// caller's certificates what they decide (Certified_faces: pairs of faces
/// kept unchanged from one certified mesh). nullptr: every pair is tested.
/// `opposites_out` (when not nullptr) receives the half-edge opposites of
/// the mesh's topology (Mesh_topology::opposite; empty when the indices are
/// bad or the coordinates not finite): the Boolean keeps those of a valid
/// output for its next use.
template <Kernel K, class P>
Solid_report validate_solid(const Triangle_mesh<P>& m, const K& k, const Solid_validation_options& o,
                            const Certified_faces* certified, std::vector<Index>* opposites_out = nullptr) {
  Solid_report r;
  r.kernel = K::name();
  r.vertices = m.vertices.size(), r.faces = m.faces.size();
  // check_mesh's checks but the collinearity test, decided below under K on
  // K's points (with the degenerate faces the self-intersection test skips).
  Mesh_topology topology;
  const Mesh_report mr = internal::combinatorial_mesh_report(m, o.mesh, topology);
  internal::sort_mesh_issues(mr, o, r);

  const bool indices_ok = r.valid_indices.passed();
  const bool finite = r.finite_coordinates.passed();
  if (!indices_ok || !finite) {
    const std::string why = !indices_ok ? "indices out of range" : "non-finite coordinates";
    internal::conclude(r.non_degenerate_faces);
    r.non_degenerate_faces.note = "collinearity not checked: " + why;
    internal::not_checked(r.self_intersection_free, why);
    internal::not_checked(r.outward_oriented, why);
    if (indices_ok) (void)internal::report_topology(m, topology, o, r);
    return r;
  }
  // Degenerate faces under K (repeated indices are already recorded).
  const internal::Kernel_points<K, P> point(m.vertices, k);
  r.coordinates_exact = point.exact();
  // On a manifold, consistently oriented mesh the self-intersection test
  // certifies the pairs around each vertex whose star a projection embeds
  // (internal/embedded_stars.h, as check_solid does): that needs every
  // projection of the faces around it, the degeneracy test only the first
  // strict one. With certificates only the stars of the faces left to test
  // matter.
  const bool stars = o.check_self_intersections && r.edge_manifold.passed() && r.vertex_manifold.passed() &&
                     r.consistently_oriented.passed();
  std::vector<unsigned char> around_open;
  if (stars && certified) around_open = internal::faces_around_open_faces(m, certified->group);
  const std::vector<std::array<Certified_sign, 3>> projected = internal::projected_orientations(
      k, point, m.faces, /*every_plane=*/stars, certified && stars ? &around_open : nullptr);
  const std::vector<unsigned char> skip = internal::degenerate_face_flags(projected);
  bool undecided_face = false;
  for (Index f = 0; f < skip.size(); ++f) {
    const Triangle& t = m.faces[f];
    const bool repeated = t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
    if (skip[f] == 1 && !repeated) internal::record(r.non_degenerate_faces, {Mesh_defect::collinear_face, {f, invalid_index}}, o.max_listed);
    if (skip[f] == 2) {
      internal::record(r.non_degenerate_faces, {Mesh_defect::undecided, {f, invalid_index}}, o.max_listed);
      undecided_face = true;
    }
  }
  {
    bool failed = false;
    for (const Mesh_issue& i : r.non_degenerate_faces.where) failed = failed || i.defect != Mesh_defect::undecided;
    internal::conclude(r.non_degenerate_faces, undecided_face && !failed);
  }

  const internal::Face_components comps = internal::report_topology(m, topology, o, r);
  const internal::Signed_volumes volumes = internal::report_volume(m, comps, o, r);

  if (!o.check_self_intersections) {
    internal::not_checked(r.self_intersection_free, "turned off (Solid_validation_options::check_self_intersections)");
    internal::not_checked(r.outward_oriented, "needs the self-intersection test");
    return r;
  }
  Self_intersections si;
  const auto kept = certified ? static_cast<std::size_t>(std::count_if(certified->group.begin(), certified->group.end(),
                                                                       [](std::uint8_t g) { return g != 0; }))
                              : std::size_t{0};
  // The groups whose pairs a certificate decides: the caller's certified
  // meshes, or else projected patches (internal/projected_patches.h). A
  // vertex whose faces are all in one group needs no star.
  std::vector<std::uint16_t> group;
  if (certified)
    group.assign(certified->group.begin(), certified->group.end());
  else if (stars)
    group = internal::projected_patches(k, point, m.faces, projected, skip, topology);
  std::vector<unsigned char> embedded;
  if (stars) embedded = internal::embedded_star_flags(k, point, m.faces, projected, skip, topology, &group);
  const std::vector<unsigned char>* star_flags = stars ? &embedded : nullptr;
  // Nothing below reads the topology: it is freed (all but the opposites the
  // caller asked for) before the hierarchy is built, whose memory it would
  // add to (on a 6 x 10^5-face output, 35 MB and 41 MB).
  if (opposites_out)
    *opposites_out = std::move(topology).take_opposites();
  else
    topology = Mesh_topology();
  // A hierarchy of all the faces for the search without certificates; with
  // them the search builds one of the open faces only.
  std::optional<Face_bvh> bvh;
  if (certified) {
    internal::find_self_intersections(k, m, point, skip, *certified, o.threads, si, star_flags);
  } else {
    bvh.emplace(m, Face_bvh_options{.threads = o.threads, .clusters = group});
    internal::find_self_intersections(k, point, m.faces, skip, *bvh, o.threads, si, star_flags,
                                      stars ? &group : nullptr);
  }
  r.candidate_pairs = si.candidate_pairs;
  for (const Face_pair& p : si.pairs)
    internal::record(r.self_intersection_free, {Mesh_defect::self_intersection, {p.first, p.second}}, o.max_listed);
  for (const Face_pair& p : si.undecided)
    internal::record(r.self_intersection_free, {Mesh_defect::undecided, {p.first, p.second}}, o.max_listed);
  internal::conclude(r.self_intersection_free, si.pairs.empty());
  const std::size_t untested = r.non_degenerate_faces.count;
  if (untested) r.self_intersection_free.note = std::to_string(untested) + " degenerate or undecided faces not tested";
  if (kept) {
    if (!r.self_intersection_free.note.empty()) r.self_intersection_free.note += "; ";
    r.self_intersection_free.note += "pairs among the " + std::to_string(kept) +
                                     " faces kept unchanged from one certified mesh decided by its certificate";
  }
  if (undecided_face && r.self_intersection_free.passed()) r.self_intersection_free.status = Check_status::undecided;

  if (!o.check_orientation) {
    internal::not_checked(r.outward_oriented, "turned off (Solid_validation_options::check_orientation)");
    return r;
  }
  std::string missing;
  const auto need = [&](const Solid_check& c, const char* name) {
    if (!c.passed()) missing += (missing.empty() ? "" : ", ") + std::string(name);
  };
  need(r.closed, "closed"), need(r.edge_manifold, "edge_manifold"), need(r.vertex_manifold, "vertex_manifold");
  need(r.consistently_oriented, "consistently_oriented"), need(r.non_degenerate_faces, "non_degenerate_faces");
  need(r.self_intersection_free, "self_intersection_free");
  if (!missing.empty()) {
    internal::not_checked(r.outward_oriented, "needs " + missing);
    return r;
  }
  if (m.faces.empty()) {
    internal::not_checked(r.outward_oriented, "no faces: no solid");
    return r;
  }
  // The orientation test reads the hierarchy only for several components
  // (internal/component_winding.h).
  if (!bvh) bvh = comps.size() > 1 ? Face_bvh(m, Face_bvh_options{.threads = o.threads}) : Face_bvh();
  internal::report_orientation(k, m, point, *bvh, comps, volumes, o, r);
  return r;
}

}  // namespace internal

/// \brief The validation report of `m` as the boundary of a solid, under
/// kernel K (by default Certified_kernel_for_number of the coordinates: exact
/// predicates — Filtered_exact_kernel on double coordinates, Exact_kernel on
/// rationals; any relgeo or CGAL-adapter kernel works, a fail-safe or
/// interval kernel reports `undecided` where it cannot decide, never a
/// wrong pass or fail).
///
/// Never throws for bad input (every defect is reported); works on any
/// triangle soup. Complexity O(n log n + k) for n faces and k pairs of
/// overlapping face boxes, plus one segment query per component when there
/// are several.
template <Kernel K, class P>
Solid_report validate_solid(const Triangle_mesh<P>& m, const K& k, const Solid_validation_options& o = {}) {
  return internal::validate_solid(m, k, o, nullptr);
}

/// validate_solid with K's default object (K: by default
/// Certified_kernel_for_number of the coordinate type).
template <KernelOrDefault K = void, class P>
Solid_report validate_solid(const Triangle_mesh<P>& m, const Solid_validation_options& o = {}) {
  using Kernel = Kernel_or_default<K, Certified_kernel_for_number, P>;
  return validate_solid(m, Kernel{}, o);
}

/// \throws Invalid_mesh naming every listed defect (context: the caller)
/// unless validate_solid finds a valid solid (every check passes; an
/// undecided check refuses too).
template <KernelOrDefault K = void, class P>
void require_valid_solid(const Triangle_mesh<P>& m, const Solid_validation_options& o = {},
                         const std::string& context = "require_valid_solid") {
  const Solid_report r = validate_solid<K>(m, o);
  if (r.is_valid_solid()) return;
  std::vector<Mesh_issue> issues = r.issues();
  if (issues.empty()) issues.push_back({Mesh_defect::undecided, {invalid_index, invalid_index}});  // a not-checked check
  throw Invalid_mesh(context + " (" + r.summary() + ")", std::move(issues));
}

// The instances relgeo::compiled makes (src/compiled/mesh_checks.cpp).
#define RELGEO_VALIDATE_SOLID_INSTANCE(PREFIX, K)                                       \
  PREFIX Solid_report internal::validate_solid<K, Point_3<double>>(                     \
      const Triangle_mesh<Point_3<double>>&, const K&, const Solid_validation_options&, \
      const internal::Certified_faces*, std::vector<Index>*);
#if RELGEO_LINKS_COMPILED
RELGEO_COMPILED_KERNELS(RELGEO_VALIDATE_SOLID_INSTANCE, extern template)
#endif

}  // namespace relgeo
