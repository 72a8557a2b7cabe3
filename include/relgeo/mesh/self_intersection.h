// relgeo/mesh/self_intersection.h — the exact self-intersection test of a
// triangle mesh under any relgeo kernel, and check_solid: every check of
// check_mesh plus this one.
//
// Broad phase: the pairs of faces whose boxes overlap (Face_bvh). Narrow
// phase: each pair is decided from the kernel's orientation predicates by
// what the two faces share (internal/face_pair_predicates.h: no vertex ->
// an edge of one meets the other; a vertex -> the opposite edges against
// the other face; an edge -> folded onto each other; all three -> identical).
// check_solid, which has the mesh's topology, first certifies patches of
// faces (internal/projected_patches.h) and the vertices whose star
// (internal/embedded_stars.h) a projection along a coordinate axis maps one
// to one: the pairs of faces within such a patch, which the search leaves
// out, and around such a vertex, nearly all candidate pairs of a smooth
// mesh, need no further predicate.
// Under Filtered_exact_kernel (the default for double coordinates) and
// Exact_kernel every pair is decided exactly; a fail-safe or interval
// kernel lists the pairs it cannot decide instead of guessing. It decides
// what CGAL::Polygon_mesh_processing::self_intersections decides over an
// exact kernel (test/mesh/solid_validation_cgal_test.cpp: CGAL's data set
// against Epeck), without CGAL and faster than it over Epick
// (benchmark/mesh, doc/mesh.md).
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/kernel/compiled_kernels.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/exact_kernel.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/kernel/kernel_for_number.h"
#include "relgeo/kernel/point_access.h"
#include "relgeo/mesh/face_bvh.h"
#include "relgeo/mesh/internal/diagonal_separation.h"
#include "relgeo/mesh/internal/embedded_stars.h"
#include "relgeo/mesh/internal/face_pair_predicates.h"
#include "relgeo/mesh/internal/kernel_points.h"
#include "relgeo/mesh/internal/parallel.h"
#include "relgeo/mesh/internal/projected_patches.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/mesh/validity.h"

namespace relgeo {

/// Options of find_self_intersections.
struct Self_intersection_options {
  /// Threads for the broad and narrow phases (1: serial; 0: every hardware
  /// thread; more than one only with TBB). The result does not depend on it.
  int threads = 1;
};

/// What find_self_intersections found.
struct Self_intersections {
  /// Pairs (f < g, sorted) that certainly meet other than in a shared
  /// vertex or edge.
  std::vector<Face_pair> pairs;
  /// Pairs the kernel could not decide (fail-safe and interval kernels).
  std::vector<Face_pair> undecided;
  /// Faces not tested: a vertex repeated, or three collinear corners (as
  /// the kernel decides it; `undecided_faces` when it cannot).
  std::vector<Index> degenerate_faces;
  std::vector<Index> undecided_faces;
  /// Pairs of faces whose boxes overlap (the narrow phase's work).
  std::size_t candidate_pairs = 0;
  /// The kernel's points are the mesh's coordinates exactly (false when
  /// they were rounded to the kernel's number type).
  bool coordinates_exact = true;

  /// No pair meets and every face and pair was decided.
  bool is_certainly_free() const { return pairs.empty() && undecided.empty() && undecided_faces.empty(); }
};

namespace internal {

/// A pair of faces that meet (decided) or that the kernel could not decide.
struct Self_intersection_hit {
  Face_pair pair;
  bool decided;  // false: undecided
};

/// The narrow phase on one candidate pair (f, g) of testable faces: a hit
/// appended to `found` when they meet beyond what they share, or when K
/// cannot decide.
template <Kernel K, class Points>
void test_face_pair(const K& k, const Points& point, const std::vector<Triangle>& faces, Index f, Index g,
                    std::vector<Self_intersection_hit>& found) {
  const Maybe meet = faces_meet_beyond_shared(k, point, faces[f], faces[g]);
  if (!meet) found.push_back({{f, g}, false});
  else if (*meet) found.push_back({{f, g}, true});
}

inline void sort_hits(const std::vector<Self_intersection_hit>& hits, Self_intersections& out) {
  for (const Self_intersection_hit& h : hits) (h.decided ? out.pairs : out.undecided).push_back(h.pair);
  std::sort(out.pairs.begin(), out.pairs.end());
  std::sort(out.undecided.begin(), out.undecided.end());
}

/// The narrow phase on candidate pairs from `bvh`, for points already in K
/// and faces flagged degenerate (1), undecided (2) or testable (0). Pairs
/// sharing a vertex flagged in `embedded` (embedded_star_flags) are decided
/// by that certificate, and pairs of faces in one nonzero `group` (a
/// projected patch, projected_patches.h) by theirs: the search leaves them
/// out.
template <Kernel K, class Points>
void find_self_intersections(const K& k, const Points& point, const std::vector<Triangle>& faces,
                             const std::vector<unsigned char>& skip, const Face_bvh& bvh, int threads,
                             Self_intersections& out, const std::vector<unsigned char>* embedded = nullptr,
                             const std::vector<std::uint16_t>* group = nullptr) {
  const auto test = [&](Index f, Index g, std::vector<Self_intersection_hit>& found) {
    if (skip[f] || skip[g]) return;
    if (embedded && share_embedded_star(faces[f], faces[g], *embedded)) return;
    test_face_pair(k, point, faces, f, g, found);
  };
  const std::vector<Self_intersection_hit> hits =
      group ? bvh.collect_overlapping_pairs_between_groups<Self_intersection_hit>(*group, test, threads,
                                                                                  &out.candidate_pairs)
            : bvh.collect_overlapping_pairs<Self_intersection_hit>(test, threads, &out.candidate_pairs);
  sort_hits(hits, out);
}

/// What a caller knows of a mesh made of pieces of certified meshes (the
/// Boolean's output, mesh_boolean.h): `group[f]` is 1 + m when face f is,
/// unchanged, a face of mesh m whose exact self-intersection test passed
/// (the same points, and two such faces of m share in this mesh what they
/// share in m), 0 for any other face; `cross_pairs` (f < g) are all pairs
/// of such faces of two different meshes whose boxes overlap (the caller's
/// broad phase found them).
struct Certified_faces {
  std::vector<std::uint8_t> group;
  std::vector<Face_pair> cross_pairs;
};

/// The narrow phase on what the certificates leave open: every pair with a
/// face outside the groups (an open face) whose boxes overlap, and the
/// cross pairs. Two faces of one group meet only where they share a vertex
/// or an edge, as in their certified mesh; pairs sharing a vertex flagged in
/// `embedded` are decided by that certificate. The open faces get a
/// hierarchy of their own: its self search gives the pairs of two open
/// faces, each certified face's box queried in it the pairs of a certified
/// and an open face. (A hierarchy of all the faces, whose descent stops at
/// pairs of certified nodes, finds the same pairs; building it was most of
/// the search, the open faces being a few percent of a Boolean's output:
/// doc/boolean.md, "The validation's search from the open faces".)
/// \pre valid indices and finite coordinates.
template <Kernel K, class P, class Points>
void find_self_intersections(const K& k, const Triangle_mesh<P>& m, const Points& point,
                             const std::vector<unsigned char>& skip, const Certified_faces& certified, int threads,
                             Self_intersections& out, const std::vector<unsigned char>* embedded = nullptr) {
  const Default_fp_environment environment;  // the boxes (face_box)
  const std::vector<Triangle>& faces = m.faces;
  const std::vector<std::uint8_t>& group = certified.group;
  const auto test = [&](Index f, Index g, std::vector<Self_intersection_hit>& found) {
    if (skip[f] || skip[g]) return;
    if (embedded && share_embedded_star(faces[f], faces[g], *embedded)) return;
    test_face_pair(k, point, faces, f, g, found);
  };
  std::vector<Index> open;  // increasing: faces i < j of its hierarchy are open[i] < open[j]
  for (Index f = 0; f < faces.size(); ++f)
    if (!group[f]) open.push_back(f);
  std::vector<Box_3> open_boxes(open.size());
  for (std::size_t i = 0; i < open.size(); ++i) open_boxes[i] = face_box(m, faces[open[i]]);
  const Face_bvh open_bvh(std::span<const Box_3>(open_boxes), Face_bvh_options{.threads = threads});
  std::vector<Box_3>().swap(open_boxes);  // the hierarchy holds its copy

  // Each open face's diagonal extents (internal/diagonal_separation.h), and
  // a certified face's when its box first meets an open one: pairs they
  // separate need no test. Only where the kernel's points are doubles.
  constexpr bool doubles = std::is_same_v<std::remove_cvref_t<decltype(point[Index{0}])>, Point_3<double>>;
  std::vector<Diagonal_extents> open_extents(doubles ? open.size() : 0);
  if constexpr (doubles)
    parallel_for_each_index((open.size() + 1023) / 1024, threads, [&](std::size_t c) {
      for (std::size_t i = c * 1024; i < std::min(open.size(), (c + 1) * 1024); ++i)
        open_extents[i] = diagonal_extents(point, faces[open[i]]);
    });

  std::size_t open_pairs = 0;
  std::vector<Self_intersection_hit> hits = open_bvh.collect_overlapping_pairs<Self_intersection_hit>(
      [&](Index i, Index j, std::vector<Self_intersection_hit>& found) {
        if constexpr (doubles)
          if (diagonally_separated(open_extents[i], open_extents[j])) return;
        test(open[i], open[j], found);
      },
      threads, &open_pairs);
  // The certified faces' queries and the cross pairs, in fixed chunks: the
  // same hits whatever the thread count.
  const std::vector<Face_pair>& cross = certified.cross_pairs;
  constexpr std::size_t chunk = 1024;
  const std::size_t query_chunks = (faces.size() + chunk - 1) / chunk;
  const std::size_t cross_chunks = (cross.size() + chunk - 1) / chunk;
  std::vector<std::vector<Self_intersection_hit>> parts(query_chunks + cross_chunks);
  std::vector<std::size_t> queried_pairs(query_chunks, 0);
  parallel_for_each_index(parts.size(), threads, [&](std::size_t c) {
    if (c < query_chunks) {
      for (Index f = static_cast<Index>(c * chunk); f < std::min(faces.size(), (c + 1) * chunk); ++f) {
        if (!group[f]) continue;
        std::optional<Diagonal_extents> f_extents;
        open_bvh.for_each_face_in_box(face_box(m, faces[f]), [&](Index i) {
          ++queried_pairs[c];
          if constexpr (doubles) {
            if (!f_extents) f_extents = diagonal_extents(point, faces[f]);
            if (diagonally_separated(*f_extents, open_extents[i])) return;
          }
          test(std::min(f, open[i]), std::max(f, open[i]), parts[c]);
        });
      }
      return;
    }
    const std::size_t first = (c - query_chunks) * chunk;
    for (std::size_t i = first; i < std::min(cross.size(), first + chunk); ++i)
      test(cross[i].first, cross[i].second, parts[c]);
  });
  out.candidate_pairs += open_pairs + cross.size();
  for (std::size_t n : queried_pairs) out.candidate_pairs += n;
  for (const auto& part : parts) hits.insert(hits.end(), part.begin(), part.end());
  sort_hits(hits, out);
}

/// Flags degenerate faces (1: repeated vertex or collinear; 2: undecided)
/// from their projected orientations. Three points are collinear iff their
/// orientation is zero in each of the three coordinate planes (the
/// components of the normal): one definite nonzero projection decides, so a
/// kernel that doubts one projection (a nearly vertical face seen from
/// above) still decides through another.
inline std::vector<unsigned char> degenerate_face_flags(const std::vector<std::array<Certified_sign, 3>>& projected) {
  std::vector<unsigned char> flag(projected.size(), 0);
  for (std::size_t f = 0; f < projected.size(); ++f) {
    bool strict = false, uncertain = false;
    for (Certified_sign s : projected[f]) {
      strict = strict || certainly(s, Certified_sign::positive) || certainly(s, Certified_sign::negative);
      uncertain = uncertain || !is_certain(s);
    }
    flag[f] = strict ? 0 : uncertain ? 2 : 1;
  }
  return flag;
}
template <Kernel K, class Points>
std::vector<unsigned char> degenerate_face_flags(const K& k, const Points& point, const std::vector<Triangle>& faces) {
  return degenerate_face_flags(projected_orientations(k, point, faces, /*every_plane=*/false));
}

/// The whole test in two steps: the constructor decides what needs no
/// hierarchy (the kernel's points, the degenerate faces and, with the
/// topology `t` of a manifold, consistently oriented mesh, the
/// certificates: projected patches and embedded stars, whose pairs the
/// search leaves out), `run` searches a face hierarchy of the mesh. The
/// topology is not read after the constructor, so a caller can free it
/// before it builds the hierarchy (check_solid: a topology and a hierarchy
/// are never held together).
template <Kernel K, class P>
class Self_intersection_test {
 public:
  Self_intersection_test(const Triangle_mesh<P>& m, const K& k, const Mesh_topology* t)
      : m_(m), k_(k), point_(m.vertices, k) {
    out_.coordinates_exact = point_.exact();
    // Every plane only when the certificates need them (the first strict
    // sign decides degeneracy).
    const std::vector<std::array<Certified_sign, 3>> projected =
        projected_orientations(k, point_, m.faces, /*every_plane=*/t != nullptr);
    skip_ = degenerate_face_flags(projected);
    for (Index f = 0; f < skip_.size(); ++f)
      if (skip_[f]) (skip_[f] == 1 ? out_.degenerate_faces : out_.undecided_faces).push_back(f);
    if (!t) return;
    patch_ = projected_patches(k, point_, m.faces, projected, skip_, *t);
    embedded_ = embedded_star_flags(k, point_, m.faces, projected, skip_, *t, &patch_);
    certified_ = true;
  }
  /// Each face's projected patch (1, 2, ...; 0: none), empty without the
  /// topology: the clusters of a hierarchy the search is fastest on
  /// (Face_bvh_options::clusters).
  const std::vector<std::uint16_t>& patches() const { return patch_; }
  Self_intersections run(const Face_bvh& bvh, int threads) && {
    if (certified_)
      find_self_intersections(k_, point_, m_.faces, skip_, bvh, threads, out_, &embedded_, &patch_);
    else
      find_self_intersections(k_, point_, m_.faces, skip_, bvh, threads, out_);
    return std::move(out_);
  }

 private:
  const Triangle_mesh<P>& m_;
  const K& k_;
  const Kernel_points<K, P> point_;
  Self_intersections out_;
  std::vector<unsigned char> skip_, embedded_;
  std::vector<std::uint16_t> patch_;
  bool certified_ = false;
};

/// The whole test on a mesh whose face hierarchy `bvh` is built; with its
/// topology `t` (a manifold, consistently oriented mesh) the pairs within a
/// projected patch and around vertices with an embedded star are decided by
/// those certificates.
template <Kernel K, class P>
Self_intersections find_self_intersections(const Triangle_mesh<P>& m, const K& k, const Face_bvh& bvh,
                                           int threads, const Mesh_topology* t = nullptr) {
  return Self_intersection_test<K, P>(m, k, t).run(bvh, threads);
}

}  // namespace internal

/// \brief Every pair of faces (f < g) of `m` that meet other than in a
/// shared vertex or a shared edge, decided with K's predicates (see the
/// file comment), with the pairs K could not decide and the degenerate
/// faces that were not tested.
///
/// Works on any triangle soup with valid indices (manifold or not: faces
/// share what their vertex indices say they share; two vertices at one
/// position are different vertices, so faces meeting there intersect).
/// Requires a Kernel (every IntersectionKernel_3 is one). \throws
/// Invalid_mesh for an index out of range or a non-finite coordinate.
/// Complexity O(n log n + k) for n faces and k overlapping box pairs.
template <Kernel K, class P>
Self_intersections find_self_intersections(const Triangle_mesh<P>& m, const K& k,
                                           const Self_intersection_options& options) {
  const Face_bvh bvh(m, {.threads = options.threads});  // throws for bad indices and NaN
  return internal::find_self_intersections(m, k, bvh, options.threads);
}
/// The same with K's default object (K: by default
/// Certified_kernel_for_number of the coordinate type).
template <KernelOrDefault K = void, class P>
Self_intersections find_self_intersections(const Triangle_mesh<P>& m, const Self_intersection_options& options = {}) {
  using Kernel = Kernel_or_default<K, Certified_kernel_for_number, P>;
  return find_self_intersections(m, Kernel{}, options);
}

/// \brief The pairs of faces (f < g, sorted) that intersect other than in a
/// shared vertex or a shared edge, decided exactly (K: by default
/// Filtered_exact_kernel on double coordinates — other coordinates are
/// rounded to double first, which a certificate must state — or
/// Exact_kernel on rationals). Degenerate faces are not tested (check_mesh
/// reports them).
/// \pre The mesh is edge- and vertex-manifold with finite coordinates
/// (\throws Invalid_mesh otherwise; find_self_intersections has no such
/// precondition). \throws Error (computation_failure) when K leaves a pair
/// undecided: use find_self_intersections with such kernels.
template <KernelOrDefault K = void, class P>
std::vector<std::pair<Index, Index>> self_intersections(const Triangle_mesh<P>& m) {
  (void)Mesh_topology::build(m);  // throws Invalid_mesh for non-manifold input
  const Self_intersections r = find_self_intersections<K>(m);
  if (!r.undecided.empty() || !r.undecided_faces.empty())
    throw Error(Error_code::computation_failure,
                "self_intersections: the kernel left " + std::to_string(r.undecided.size()) + " pairs and " +
                    std::to_string(r.undecided_faces.size()) + " faces undecided");
  std::vector<std::pair<Index, Index>> out;
  out.reserve(r.pairs.size());
  for (const Face_pair& p : r.pairs) out.emplace_back(p.first, p.second);
  return out;
}

namespace internal {

/// What the checks of a mesh leave behind for a caller that goes on with the
/// mesh (the Boolean): its half-edge opposites (Mesh_topology::opposite;
/// to be read only when the report is valid) and, when the
/// self-intersection test ran, its face hierarchy.
struct Checked_mesh {
  std::vector<Index> opposites;
  std::optional<Face_bvh> bvh;
};

/// check_solid under kernel K, leaving what it built in `checked`; the test
/// on `threads` threads (Self_intersection_options). Of the topology only
/// the opposites are kept, before the hierarchy is built: the peak memory
/// is a topology or a hierarchy, not both (a caller holding another mesh's
/// hierarchy, the Boolean, adds this one's to it).
template <Kernel K, class P>
Mesh_report check_solid(const Triangle_mesh<P>& m, const Mesh_check_options& options, Checked_mesh& checked,
                        int threads = 1) {
  Mesh_topology topology;
  Mesh_report r = internal::check_mesh<K>(m, options, topology);
  const bool can = !r.has(Mesh_defect::index_out_of_range) && !r.has(Mesh_defect::repeated_vertex_in_face) &&
                   r.is_manifold() && r.is_consistently_oriented() &&
                   !r.has(Mesh_defect::non_finite_coordinate);
  if (!can) {
    checked.opposites = std::move(topology).take_opposites();
    return r;
  }
  using Test_kernel = typename Kernel_for_point<Certified_kernel_for_number, P>::type;
  const Test_kernel k{};
  Self_intersection_test<Test_kernel, P> test(m, k, &topology);
  checked.opposites = std::move(topology).take_opposites();
  const Face_bvh& bvh = checked.bvh.emplace(m, Face_bvh_options{.threads = threads, .clusters = test.patches()});
  const Self_intersections found = std::move(test).run(bvh, threads);
  if (!found.undecided.empty() || !found.undecided_faces.empty())
    throw Error(Error_code::computation_failure,
                "check_solid: the kernel left " + std::to_string(found.undecided.size()) + " pairs and " +
                    std::to_string(found.undecided_faces.size()) + " faces undecided");
  for (const auto& [f, g] : found.pairs) r.issues.push_back({Mesh_defect::self_intersection, {f, g}});
  r.self_intersections_checked = true;
  return r;
}

}  // namespace internal

/// check_mesh plus the self-intersection test (run only when the mesh is
/// manifold with finite coordinates; otherwise self_intersections_checked
/// stays false). A valid report certifies a closed (when required), 2-manifold,
/// consistently oriented, non-degenerate, self-intersection-free triangle
/// mesh. validate_solid (solid_validation.h) adds orientation, volume and
/// topology in a structured report.
template <KernelOrDefault K = void, class P>
Mesh_report check_solid(const Triangle_mesh<P>& m, const Mesh_check_options& options = {}) {
  internal::Checked_mesh checked;
  return internal::check_solid<Kernel_or_default<K, Predicate_kernel_for_number, P>>(m, options, checked);
}

// The instances relgeo::compiled makes (src/compiled/mesh_checks.cpp).
#define RELGEO_SELF_INTERSECTION_INSTANCE(PREFIX, K)                                                             \
  PREFIX Self_intersections find_self_intersections<K, Point_3<double>>(const Triangle_mesh<Point_3<double>>&,    \
                                                                        const K&, const Self_intersection_options&); \
  PREFIX Mesh_report internal::check_solid<K, Point_3<double>>(const Triangle_mesh<Point_3<double>>&,               \
                                                               const Mesh_check_options&, internal::Checked_mesh&, \
                                                               int);
#if RELGEO_LINKS_COMPILED
RELGEO_COMPILED_KERNELS(RELGEO_SELF_INTERSECTION_INSTANCE, extern template)
#endif

}  // namespace relgeo
