// relgeo/mesh/face_bvh.h — a bounding-volume hierarchy over the faces of a
// triangle mesh: the broad phase of the self-intersection test and of the
// mesh Booleans.
//
// Design. Each face gets an axis-aligned box of doubles that certainly
// contains it (its coordinates' lower and upper double bounds: exact for
// double coordinates, rounded outward for rationals, MPFR numbers and
// intervals). The hierarchy is a binary tree built top down until at most
// `leaf_size` faces remain, splitting by default where the Morton codes of
// the box centres differ (radix sort, O(n)), or at the median centre along
// the longest axis (Face_bvh_split; no per-node allocation); with clusters
// (Face_bvh_options::clusters) the Morton order is taken within each
// cluster, the clusters one after the other. Nodes live in one
// flat array, the two children of a node next to each other; the faces'
// boxes are stored in leaf order, so a leaf reads one contiguous block.
//
// Queries. Pairs of faces whose (closed) boxes overlap, between two
// hierarchies (simultaneous descent of both trees, always splitting the
// larger node) or within one (a node against itself: its children against
// themselves and against each other); the faces whose box meets a query box,
// segment or ray (slab test in interval arithmetic: a face is never missed
// because of rounding). Pair searches first expand the top of the traversal
// into a fixed list of independent node pairs, then run them one after the
// other or, with TBB (RELGEO_HAS_TBB), in parallel; results are concatenated
// in list order, so the output — pairs and their order — does not depend on
// the number of threads.
//
// The floating-point environment. The boxes are decided by comparisons, a
// min/max per node and a rounding of doubles to floats; under
// denormals-are-zero a comparison reads two different subnormals as equal
// (so a node's min could keep the larger of two subnormal bounds), and under
// flush-to-zero a double rounded to a float subnormal comes out as 0 or below
// it. Either made a box miss a face it must contain (found: two crossing
// cubes of side 2^-134 passed as disjoint). So every entry point (building,
// face_boxes, each query) holds a Default_fp_environment: the hierarchy and
// every answer are the same whatever environment the caller set. Callbacks
// run in that scope too (the default environment, also on TBB's workers,
// whose arenas take the settings of the thread that creates them).
//
// Measured against CGAL's box_intersection_d and AABB_tree in
// benchmark/mesh/face_bvh_benchmark.cpp (doc/mesh.md, "Self-intersection and
// solid validation").
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/core/internal/radix_sort.h"
#include "relgeo/core/interval.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/kernel/point.h"
#include "relgeo/kernel/point_access.h"
#include "relgeo/mesh/face_pair.h"
#include "relgeo/mesh/internal/parallel.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// A closed axis-aligned box [lo, hi] in doubles. Default: empty (lo = +inf,
/// hi = -inf), the neutral element of extend().
struct Box_3 {
  std::array<double, 3> lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::infinity()};
  std::array<double, 3> hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()};

  bool is_empty() const { return !(lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2]); }
  void extend(const Box_3& b) {
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], b.lo[k]), hi[k] = std::max(hi[k], b.hi[k]);
  }
  void extend(double x, double y, double z) {
    lo[0] = std::min(lo[0], x), lo[1] = std::min(lo[1], y), lo[2] = std::min(lo[2], z);
    hi[0] = std::max(hi[0], x), hi[1] = std::max(hi[1], y), hi[2] = std::max(hi[2], z);
  }
  friend bool operator==(const Box_3&, const Box_3&) = default;
};

namespace detail {
/// Whether two closed boxes with members lo[3], hi[3] share a point, for any
/// mix of coordinate types (the hierarchy's float nodes, double face boxes).
/// Non-short-circuit: six comparisons and no unpredictable branch. Always
/// inlined: a call per box in the searches' innermost loops cost the
/// rounding repair's box queries a third of their time where GCC chose one.
template <class BoxA, class BoxB>
[[gnu::always_inline]] inline bool closed_boxes_overlap(const BoxA& a, const BoxB& b) {
  return bool(int(a.lo[0] <= b.hi[0]) & int(b.lo[0] <= a.hi[0]) & int(a.lo[1] <= b.hi[1]) &
              int(b.lo[1] <= a.hi[1]) & int(a.lo[2] <= b.hi[2]) & int(b.lo[2] <= a.hi[2]));
}
}  // namespace detail

/// Whether two closed boxes share a point (touching counts).
[[gnu::always_inline]] inline bool do_overlap(const Box_3& a, const Box_3& b) {
  return detail::closed_boxes_overlap(a, b);
}

/// The box of face `t` of `m`, as face_boxes forms it. \pre valid indices
/// and finite coordinates; the default floating-point environment (min and
/// max of subnormal bounds: see the file comment).
template <class P>
Box_3 face_box(const Triangle_mesh<P>& m, const Triangle& t) {
  using A = internal::Point_access<P>;
  Box_3 b;
  for (Index v : t) {
    const P& p = m.vertices[v];
    if constexpr (std::is_same_v<typename A::FT, double>) {
      b.extend(A::x(p), A::y(p), A::z(p));
    } else {
      b.extend(lower_double(A::x(p)), lower_double(A::y(p)), lower_double(A::z(p)));
      b.extend(upper_double(A::x(p)), upper_double(A::y(p)), upper_double(A::z(p)));
    }
  }
  return b;
}

/// \brief The box of every face: the smallest box of doubles containing its
/// three corners (lower_double / upper_double of each coordinate, so exact
/// for double coordinates and rounded outward otherwise).
/// \throws Invalid_mesh (index_out_of_range, non_finite_coordinate; every
/// offending face or vertex, at most 100 listed) when a box cannot be formed.
template <class P>
std::vector<Box_3> face_boxes(const Triangle_mesh<P>& m) {
  const Default_fp_environment environment;  // min/max of subnormal bounds (see the file comment)
  using A = internal::Point_access<P>;
  using FT = typename A::FT;
  const std::size_t nv = m.vertices.size();
  std::vector<Mesh_issue> issues;
  std::vector<Box_3> vertex_boxes;
  constexpr bool is_double = std::is_same_v<FT, double>;
  if constexpr (!is_double) vertex_boxes.resize(nv);
  for (Index v = 0; v < nv; ++v) {
    const P& p = m.vertices[v];
    if (!internal::point_is_finite(p)) {
      if (issues.size() < 100) issues.push_back({Mesh_defect::non_finite_coordinate, {v, invalid_index}});
      continue;
    }
    if constexpr (!is_double) {
      vertex_boxes[v].lo = {lower_double(A::x(p)), lower_double(A::y(p)), lower_double(A::z(p))};
      vertex_boxes[v].hi = {upper_double(A::x(p)), upper_double(A::y(p)), upper_double(A::z(p))};
    }
  }
  std::vector<Box_3> boxes(m.faces.size());
  for (Index f = 0; f < m.faces.size(); ++f) {
    Box_3& b = boxes[f];
    for (Index v : m.faces[f]) {
      if (v >= nv) {
        if (issues.size() < 100) issues.push_back({Mesh_defect::index_out_of_range, {f, v}});
        continue;
      }
      if constexpr (is_double) b.extend(A::x(m.vertices[v]), A::y(m.vertices[v]), A::z(m.vertices[v]));
      else b.extend(vertex_boxes[v]);
    }
  }
  if (!issues.empty()) throw Invalid_mesh("face_boxes", std::move(issues));
  return boxes;
}

/// How Face_bvh orders and splits the faces.
enum class Face_bvh_split {
  /// Sort the box centres along a Morton (Z-order) curve of 10 bits per
  /// axis (radix sort, O(n)), then split each range where the first bit
  /// of the codes differs (an octree cell in two), at the middle when all
  /// codes are equal. Measured fastest overall (the build is most of a pair
  /// search: doc/mesh.md).
  morton,
  /// Split at the median centre along the longest axis of the centres'
  /// box (std::nth_element per level, O(n log n)): tighter boxes, slower
  /// build.
  median
};

/// Options of Face_bvh.
struct Face_bvh_options {
  /// Most faces in a leaf (1..64). 16: a leaf pair costs more box tests
  /// (branch-free masks, cheap) and the search descends fewer node pairs;
  /// the pair searches ran 4-14% faster than with 8 and the Booleans 1-4%
  /// (doc/boolean.md, "Leaves of 16 faces").
  int leaf_size = 16;
  Face_bvh_split split = Face_bvh_split::morton;
  /// Threads for the build (1: serial; 0: every hardware thread; more than
  /// one only with TBB, see internal/parallel.h).
  int threads = 1;
  /// Empty, or one cluster number per face: the hierarchy then keeps the
  /// faces of each cluster in subtrees of their own (its top levels split
  /// clusters apart, the levels below each cluster by Morton code), and
  /// the faces of cluster 0 together like any other. Given the groups of a
  /// search between groups (collect_overlapping_pairs_between_groups), whole
  /// subtrees then hold one group and the search skips them (check_solid's
  /// search among projected patches: 25-30% faster on CGAL's elephant and
  /// armadillo, doc/mesh.md, "Self-intersection"). Searches between two
  /// hierarchies are slower on clustered ones. Read during the build only;
  /// needs the Morton split.
  std::span<const std::uint16_t> clusters{};
};

/// \brief Bounding-volume hierarchy over face boxes (see the file comment).
///
/// Faces are named by their index in the box list (the mesh's face index
/// when built from a mesh). Immutable after construction (movable, not
/// copyable); queries are const and may run concurrently.
class Face_bvh {
 public:
  Face_bvh() = default;

  /// From one box per face. \throws Precondition_violation when a box is
  /// empty or not finite (NaN, infinite). Complexity O(n log n).
  explicit Face_bvh(std::span<const Box_3> boxes, const Face_bvh_options& options = {}) {
    const Default_fp_environment environment;
    build_tree(boxes, options);
    boxes_.resize(size_);
    for (std::size_t i = 0; i < size_; ++i) boxes_[i] = boxes[faces_[i]];
    form_node_boxes();
  }
  /// From the boxes of the mesh's faces (face_boxes: throws Invalid_mesh for
  /// bad indices or non-finite coordinates).
  template <class P>
  explicit Face_bvh(const Triangle_mesh<P>& m, const Face_bvh_options& options = {}) {
    const Default_fp_environment environment;
    std::vector<Box_3> boxes = face_boxes(m);
    build_tree(boxes, options);
    // The boxes put in leaf order where they are: one array of them at a
    // time (peak memory).
    gather_in_place(boxes);
    boxes_ = std::move(boxes);
    form_node_boxes();
  }

  /// Number of faces.
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  /// The box of all faces (empty for no face).
  const Box_3& bounds() const { return bounds_; }
  /// Number of nodes (for statistics).
  std::size_t number_of_nodes() const { return node_count_; }

  // ---- pairs --------------------------------------------------------------

  /// f(face of this, face of other) for every pair whose boxes overlap,
  /// serially, each pair once, in the deterministic order described in the
  /// file comment.
  template <class F>
  void for_each_overlapping_pair(const Face_bvh& other, F&& f) const {
    const Default_fp_environment environment;
    traverse_items<false>(other, [&](Index a, Index b) { f(a, b); });
  }
  /// f(f, g), f < g, for every pair of faces of this hierarchy whose boxes
  /// overlap (a face is not paired with itself).
  template <class F>
  void for_each_overlapping_pair(F&& f) const {
    const Default_fp_environment environment;
    traverse_items<true>(*this, [&](Index a, Index b) { f(a, b); });
  }

  /// \brief The pairs (face of this, face of other) whose boxes overlap,
  /// each mapped by f(a, b, out) to zero or more results appended to `out`:
  /// the filter-and-test loop of a narrow phase, on up to `threads` threads
  /// (f must then be safe to call concurrently). The result and its order do
  /// not depend on `threads`. `overlapping`, when given, receives the
  /// number of pairs f was called on.
  template <class R, class F>
  std::vector<R> collect_overlapping_pairs(const Face_bvh& other, F&& f, int threads = 1,
                                           std::size_t* overlapping = nullptr) const {
    return collect<false, R>(other, f, threads, overlapping);
  }
  /// The same within this hierarchy (f(f, g, out) with f < g).
  template <class R, class F>
  std::vector<R> collect_overlapping_pairs(F&& f, int threads = 1, std::size_t* overlapping = nullptr) const {
    return collect<true, R>(*this, f, threads, overlapping);
  }

  /// \brief The same within this hierarchy, leaving out the pairs of two
  /// faces of one group (`group[f]`: face f's group, 0 for none): they are
  /// neither passed to f nor counted, and the descent stops at pairs of
  /// nodes that hold faces of one group only. For a certificate that decides
  /// such pairs: applying it costs nothing per pair. \pre one group per face.
  template <class R, class F>
  std::vector<R> collect_overlapping_pairs_between_groups(std::span<const std::uint16_t> group, F&& f, int threads = 1,
                                                          std::size_t* overlapping = nullptr) const {
    const Groups groups = grouped(group);
    return collect<true, R>(*this, f, threads, overlapping, &groups);
  }

  /// Every pair (face of this, face of other) whose boxes overlap.
  std::vector<Face_pair> overlapping_pairs(const Face_bvh& other, int threads = 1) const {
    return collect_overlapping_pairs<Face_pair>(
        other, [](Index a, Index b, std::vector<Face_pair>& out) { out.push_back({a, b}); }, threads);
  }
  /// \brief overlapping_pairs(other) in the order of
  /// other.overlapping_pairs_with_boxes(the face boxes of this hierarchy):
  /// by face of this, then as other's hierarchy meets the faces. The search
  /// of two hierarchies with the order of one query per box, for a caller
  /// who has both hierarchies: the descent is shared among neighbouring
  /// faces, where each query starts at the root (on CGAL's armadillo against
  /// a 20K sphere 0.5 ms against 3.9, plus a radix sort of the pairs). The
  /// order within one face depends on other's shape (sorted_overlapping_pairs
  /// does not).
  std::vector<Face_pair> overlapping_pairs_in_query_order(const Face_bvh& other, int threads = 1) const {
    // The descent meets the pairs of one face of this in other's slot order,
    // the query's: it splits a pair of nodes into its children in order, so
    // every pair under other's first child comes before those under its
    // second (and the threads' parts join in the descent's order). A stable
    // sort by this face alone then gives the queries' order.
    return radix_sorted_pairs(other, threads, /*by_both=*/false);
  }
  /// \brief overlapping_pairs(other) sorted by (first, second): an order
  /// that depends on neither hierarchy's shape (leaf size, split, clusters),
  /// for a caller whose results depend on the order (the mesh Boolean
  /// numbers its new points by it) and whose hierarchies may be built in
  /// more than one way. One radix sort of the pairs after the search.
  std::vector<Face_pair> sorted_overlapping_pairs(const Face_bvh& other, int threads = 1) const {
    return radix_sorted_pairs(other, threads, /*by_both=*/true);
  }
  /// Every pair of faces of this hierarchy (first < second) whose boxes overlap.
  std::vector<Face_pair> overlapping_pairs(int threads = 1) const {
    return collect_overlapping_pairs<Face_pair>(
        [](Index a, Index b, std::vector<Face_pair>& out) { out.push_back({a, b}); }, threads);
  }
  /// \brief Every pair (i, face of this) such that box `queries[i]`
  /// overlaps the face's box, ordered by i, then as the hierarchy meets the
  /// faces; on up to `threads` threads (the result does not depend on them).
  /// The broad phase against boxes that have no hierarchy of their own:
  /// it saves building one (about 70 bytes a face) and costs about as much
  /// time as building it and searching the two (less on large sets, a
  /// little more on small ones: doc/mesh.md, "Broad phase").
  /// \pre no box is NaN (an empty box meets nothing).
  std::vector<Face_pair> overlapping_pairs_with_boxes(std::span<const Box_3> queries, int threads = 1) const {
    const Default_fp_environment environment;
    const auto search = [&](std::size_t begin, std::size_t end, std::vector<Face_pair>& out) {
      for (std::size_t i = begin; i < end; ++i)
        if (do_overlap(queries[i], bounds_)) {
          auto emit = [&](Index f) { out.push_back({static_cast<Index>(i), f}); };
          query([&](const Box_3& b) { return do_overlap(b, queries[i]); }, emit);
        }
    };
    std::vector<Face_pair> result;
    if (internal::thread_count(threads) <= 1) {
      search(0, queries.size(), result);
      return result;
    }
    // Fixed chunks, whatever the thread count: the same pairs in the same order.
    constexpr std::size_t chunk = 4096;
    std::vector<std::vector<Face_pair>> parts((queries.size() + chunk - 1) / chunk);
    internal::parallel_for_each_index(parts.size(), threads, [&](std::size_t c) {
      search(c * chunk, std::min(queries.size(), (c + 1) * chunk), parts[c]);
    });
    return concatenated(parts);
  }

  // ---- single queries -----------------------------------------------------

  /// f(face) for every face whose box overlaps q.
  template <class F>
  void for_each_face_in_box(const Box_3& q, F&& f) const {
    const Default_fp_environment environment;
    query([&](const Box_3& b) { return do_overlap(b, q); }, f);
  }
  /// f(face) for every face whose box the segment [p, q] may meet: every
  /// face whose box it meets is reported (interval slab test), and a few
  /// whose box it misses by less than the rounding of the test may be.
  /// With `slack` > 0 the boxes are first enlarged by it on every side (a
  /// segment whose true ends are known to within slack of p and q).
  /// \pre finite coordinates, slack >= 0.
  template <class F>
  void for_each_face_on_segment(const Point_3<double>& p, const Point_3<double>& q, F&& f, double slack = 0) const {
    const Default_fp_environment environment;  // interval slab test
    Linear_query s = linear_query(p, {q.x, q.y, q.z}, true, 1.0);
    s.slack = slack;
    query([&](const Box_3& b) { return s.may_meet(b); }, f);
  }
  /// The same for the ray from `origin` along `direction` (not 0).
  template <class F>
  void for_each_face_on_ray(const Point_3<double>& origin, const Point_3<double>& direction, F&& f) const {
    const Default_fp_environment environment;
    const Linear_query s =
        linear_query(origin, {direction.x, direction.y, direction.z}, false, std::numeric_limits<double>::infinity());
    query([&](const Box_3& b) { return s.may_meet(b); }, f);
  }
  /// \brief The face nearest to p and its squared distance, by
  /// `squared_distance(f)` (the caller's squared distance from p to face f,
  /// never below the distance to f's box): branch and bound, nodes visited
  /// nearest box first and skipped once their box is farther than the best
  /// face so far. {invalid_index, infinity} without faces. Its cost does not
  /// grow with p's distance to the mesh, unlike growing box queries.
  template <class F>
  std::pair<Index, double> nearest_face(const Point_3<double>& p, F&& squared_distance) const {
    const Default_fp_environment environment;  // the box distances are rounded down a little
    std::pair<Index, double> best{invalid_index, std::numeric_limits<double>::infinity()};
    if (size_ == 0) return best;
    const double q[3] = {p.x, p.y, p.z};
    // Squared distance from p to a box, rounded down a little: a measurement
    // whose rounding must not skip the nearest face.
    const auto box_distance = [&](const auto& b) {
      double d = 0;
      for (int k = 0; k < 3; ++k) {
        const double gap = std::max({double(b.lo[k]) - q[k], q[k] - double(b.hi[k]), 0.0});
        d += gap * gap;
      }
      return d * (1 - 0x1p-40);
    };
    struct Entry {
      Index node;
      double distance;
    };
    std::vector<Entry> stack{{0, box_distance(nodes_[0])}};
    while (!stack.empty()) {
      const Entry e = stack.back();
      stack.pop_back();
      if (e.distance > best.second) continue;
      const Node& n = nodes_[e.node];
      if (n.is_leaf()) {
        for (Index s = n.first; s < n.first + n.count; ++s) {
          if (box_distance(boxes_[s]) > best.second) continue;
          const double d = squared_distance(faces_[s]);
          if (d < best.second) best = {faces_[s], d};
        }
        continue;
      }
      const Entry l{n.first, box_distance(nodes_[n.first])}, r{n.first + 1, box_distance(nodes_[n.first + 1])};
      // The nearer child on top.
      if (l.distance <= r.distance) stack.push_back(r), stack.push_back(l);
      else stack.push_back(l), stack.push_back(r);
    }
    return best;
  }


 private:
  // A node's box in floats, rounded outward from the doubles it encloses:
  // half the memory of doubles, and as sound for pruning (the faces' own
  // boxes, tested at the leaves, stay in doubles).
  struct Node {
    float lo[3], hi[3];
    Index first;  // leaf: first face slot; inner node: left child (the right one is first + 1)
    Index count;  // leaf: number of faces (> 0); inner node: 0
    bool is_leaf() const { return count != 0; }
  };
  struct Node_pair {
    Index a, b;
  };
  struct Build_item {
    float c[3];
    Index face;
  };

  static float round_down(double v) {
    if (v > double(std::numeric_limits<float>::max())) return std::numeric_limits<float>::max();
    if (v < -double(std::numeric_limits<float>::max())) return -std::numeric_limits<float>::infinity();
    const float f = static_cast<float>(v);
    if (double(f) <= v) return f;
    // The next float down, from the bits (from -0: the negative smallest
    // subnormal; from +0 it cannot be needed, +0 <= v when v rounds to it).
    const auto bits = std::bit_cast<std::uint32_t>(f);
    return std::bit_cast<float>(f > 0 ? bits - 1 : bits + 1);
  }
  static float round_up(double v) { return -round_down(-v); }

  static Box_3 node_box(const Node& n) {
    Box_3 b;
    for (int k = 0; k < 3; ++k) b.lo[k] = n.lo[k], b.hi[k] = n.hi[k];
    return b;
  }

  // ---- build ----------------------------------------------------------------

  // Everything but the boxes in leaf order (boxes_) and the nodes' boxes.
  void build_tree(std::span<const Box_3> boxes, const Face_bvh_options& o) {
    const std::size_t n = boxes.size();
    if (n >= invalid_index / 2) throw Invalid_input("Face_bvh: too many faces for 32-bit indices");
    for (std::size_t f = 0; f < n; ++f) {
      const Box_3& b = boxes[f];
      for (int k = 0; k < 3; ++k)
        if (!(std::isfinite(b.lo[k]) && std::isfinite(b.hi[k]) && b.lo[k] <= b.hi[k]))
          throw Precondition_violation("Face_bvh: box of face " + std::to_string(f) +
                                       " is empty or not finite");
      bounds_.extend(b);
    }
    if (!o.clusters.empty() && o.clusters.size() != n)
      throw Precondition_violation("Face_bvh: " + std::to_string(o.clusters.size()) + " clusters for " +
                                   std::to_string(n) + " faces");
    if (!o.clusters.empty() && o.split != Face_bvh_split::morton)
      throw Precondition_violation("Face_bvh: clusters need the Morton split");
    if (n == 0) return;
    leaf_size_ = static_cast<Index>(std::clamp(o.leaf_size, 1, 64));
    std::atomic<Index> next{1};
    const bool parallel = internal::thread_count(o.threads) > 1;
    // Uninitialised storage: pages are touched once, when written.
    nodes_ = std::make_unique_for_overwrite<Node[]>(2 * n);  // a binary tree with at most n leaves
    faces_ = std::make_unique_for_overwrite<Index[]>(n);
    if (o.split == Face_bvh_split::median) {
      std::vector<Build_item> items(n);
      for (std::size_t f = 0; f < n; ++f) {
        for (int k = 0; k < 3; ++k) items[f].c[k] = static_cast<float>(0.5 * boxes[f].lo[k] + 0.5 * boxes[f].hi[k]);
        items[f].face = static_cast<Index>(f);
      }
      internal::in_thread_arena(o.threads,
                                [&] { split_median(items, 0, static_cast<Index>(n), 0, next, parallel); });
      for (std::size_t i = 0; i < n; ++i) faces_[i] = items[i].face;
    } else {
      const std::vector<std::uint64_t> codes = sorted_codes(boxes, o.clusters, faces_.get());
      internal::in_thread_arena(o.threads,
                                [&] { split_morton(codes, 0, static_cast<Index>(n), 0, next, parallel); });
    }
    size_ = n;
    node_count_ = next.load();
  }
  // boxes[i] := boxes[faces_[i]] for every slot i, following the cycles of
  // the permutation.
  void gather_in_place(std::vector<Box_3>& boxes) const {
    std::vector<bool> done(size_, false);
    for (std::size_t start = 0; start < size_; ++start) {
      if (done[start]) continue;
      const Box_3 first = boxes[start];
      std::size_t i = start;
      for (;;) {
        done[i] = true;
        const std::size_t from = faces_[i];
        if (from == start) {
          boxes[i] = first;
          break;
        }
        boxes[i] = boxes[from];
        i = from;
      }
    }
  }
  // Children are allocated after their parent: one backward pass forms
  // every box from its children's.
  void form_node_boxes() {
    for (std::size_t i = node_count_; i-- > 0;) {
      Node& node = nodes_[i];
      if (node.is_leaf()) {
        Box_3 b;
        for (Index s = node.first; s < node.first + node.count; ++s) b.extend(boxes_[s]);
        for (int k = 0; k < 3; ++k) node.lo[k] = round_down(b.lo[k]), node.hi[k] = round_up(b.hi[k]);
      } else {
        const Node& l = nodes_[node.first];
        const Node& r = nodes_[node.first + 1];
        for (int k = 0; k < 3; ++k) node.lo[k] = std::min(l.lo[k], r.lo[k]), node.hi[k] = std::max(l.hi[k], r.hi[k]);
      }
    }
  }

  void split_median(std::vector<Build_item>& items, Index begin, Index end, Index node, std::atomic<Index>& next,
                    bool parallel) {
    while (end - begin > leaf_size_) {
      float lo[3] = {items[begin].c[0], items[begin].c[1], items[begin].c[2]};
      float hi[3] = {lo[0], lo[1], lo[2]};
      for (Index i = begin + 1; i < end; ++i)
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], items[i].c[k]), hi[k] = std::max(hi[k], items[i].c[k]);
      int axis = 0;
      for (int k = 1; k < 3; ++k)
        if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
      const Index mid = begin + (end - begin) / 2;
      std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                       [axis](const Build_item& x, const Build_item& y) { return x.c[axis] < y.c[axis]; });
      const Index children = inner(node, next);
      if (parallel && end - begin > 8192) {
        internal::invoke_both(
            true, [&, begin, mid, children] { split_median(items, begin, mid, children, next, true); },
            [&, mid, end, children] { split_median(items, mid, end, children + 1, next, true); });
        return;
      }
      split_median(items, begin, mid, children, next, false);
      begin = mid, node = children + 1;  // the right half in this frame
    }
    leaf(node, begin, end);
  }

  // Makes `node` an inner node; returns its first child.
  Index inner(Index node, std::atomic<Index>& next) {
    const Index children = next.fetch_add(2, std::memory_order_relaxed);
    nodes_[node].first = children;
    nodes_[node].count = 0;
    return children;
  }
  void leaf(Index node, Index begin, Index end) {
    nodes_[node].first = begin;
    nodes_[node].count = end - begin;
  }

  // 10 bits per axis, interleaved (x in the lowest bit of each triple).
  static std::uint32_t spread_bits(std::uint32_t v) {
    v = (v | (v << 16)) & 0x030000FFu;
    v = (v | (v << 8)) & 0x0300F00Fu;
    v = (v | (v << 4)) & 0x030C30C3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
  }

  // The Morton codes of the box centres in the box of all centres, sorted
  // (LSD radix sort, stable: equal codes keep the face order), each as
  // code << 32 | face.
  static std::vector<std::uint64_t> sorted_morton_codes(std::span<const Box_3> boxes) {
    const std::size_t n = boxes.size();
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) lo[k] = hi[k] = 0.5 * boxes[0].lo[k] + 0.5 * boxes[0].hi[k];
    for (const Box_3& b : boxes)
      for (int k = 0; k < 3; ++k) {
        const double c = 0.5 * b.lo[k] + 0.5 * b.hi[k];
        lo[k] = std::min(lo[k], c), hi[k] = std::max(hi[k], c);
      }
    double scale[3];
    for (int k = 0; k < 3; ++k) {
      // A spread below 1023 / DBL_MAX (subnormal) gives an infinite scale,
      // and 0 * inf = NaN: such an axis gets no Morton digits.
      scale[k] = hi[k] > lo[k] ? 1023.0 / (hi[k] - lo[k]) : 0.0;
      if (!std::isfinite(scale[k])) scale[k] = 0.0;
    }
    std::vector<std::uint64_t> keys(n), tmp;
    for (std::size_t f = 0; f < n; ++f) {
      std::uint32_t code = 0;
      for (int k = 0; k < 3; ++k) {
        const double c = 0.5 * boxes[f].lo[k] + 0.5 * boxes[f].hi[k];
        const double v = (c - lo[k]) * scale[k] + 0.5;
        // !(v >= 0) also catches a NaN (a box with infinite ends), which
        // std::clamp would pass through to an undefined conversion.
        const auto q = static_cast<std::uint32_t>(!(v >= 0.0) ? 0.0 : std::min(v, 1023.0));
        code |= spread_bits(q) << k;
      }
      keys[f] = (std::uint64_t{code} << 32) | f;
    }
    internal::radix_sort_bits(keys, tmp, 32, 30, 10);  // three 10-bit digits of the 30-bit code
    return keys;
  }

  // The faces in the hierarchy's order (into `order`) and their sort keys:
  // the Morton code, below the cluster number when there are clusters
  // (a stable counting sort by cluster after the sort by code).
  static std::vector<std::uint64_t> sorted_codes(std::span<const Box_3> boxes, std::span<const std::uint16_t> clusters,
                                                 Index* order) {
    std::vector<std::uint64_t> keys = sorted_morton_codes(boxes);
    const std::size_t n = keys.size();
    if (clusters.empty()) {
      for (std::size_t i = 0; i < n; ++i) {
        order[i] = static_cast<Index>(keys[i] & 0xFFFFFFFFu);
        keys[i] >>= 32;
      }
      return keys;
    }
    std::vector<std::uint64_t> codes(n);
    const std::uint16_t most = *std::max_element(clusters.begin(), clusters.end());
    std::vector<std::size_t> start(std::size_t{most} + 2, 0);
    for (std::uint16_t c : clusters) ++start[std::size_t{c} + 1];
    for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    for (std::uint64_t key : keys) {
      const auto face = static_cast<Index>(key & 0xFFFFFFFFu);
      const std::size_t i = start[clusters[face]]++;
      codes[i] = (std::uint64_t{clusters[face]} << 32) | (key >> 32);
      order[i] = face;
    }
    return codes;
  }

  void split_morton(const std::vector<std::uint64_t>& codes, Index begin, Index end, Index node,
                    std::atomic<Index>& next, bool parallel) {
    while (end - begin > leaf_size_) {
      Index mid = begin + (end - begin) / 2;
      const std::uint64_t first = codes[begin], last = codes[end - 1];
      if (first != last) {  // the first index whose code has the highest differing bit set
        const std::uint64_t bit = std::uint64_t{1} << (63 - std::countl_zero(first ^ last));
        mid = static_cast<Index>(std::partition_point(codes.begin() + begin, codes.begin() + end,
                                                      [bit](std::uint64_t c) { return (c & bit) == 0; }) -
                                 codes.begin());
      }
      const Index children = inner(node, next);
      if (parallel && end - begin > 8192) {
        internal::invoke_both(
            true, [&, begin, mid, children] { split_morton(codes, begin, mid, children, next, true); },
            [&, mid, end, children] { split_morton(codes, mid, end, children + 1, next, true); });
        return;
      }
      split_morton(codes, begin, mid, children, next, false);
      begin = mid, node = children + 1;
    }
    leaf(node, begin, end);
  }

  // The pairs with other, each packed in a word (this face above other's),
  // radix sorted (stably) by this face, or by both faces (`by_both`).
  std::vector<Face_pair> radix_sorted_pairs(const Face_bvh& other, int threads, bool by_both) const {
    const int shift = by_both ? static_cast<int>(std::bit_width(std::uint64_t{other.size_})) : 32;
    std::vector<std::uint64_t> word = collect_overlapping_pairs<std::uint64_t>(
        other,
        [shift](Index a, Index b, std::vector<std::uint64_t>& out) { out.push_back((std::uint64_t{a} << shift) | b); },
        threads);
    const int this_bits = static_cast<int>(std::bit_width(std::uint64_t{size_}));
    std::vector<std::uint64_t> scratch;
    internal::radix_sort_bits(word, scratch, by_both ? 0 : shift, by_both ? shift + this_bits : this_bits);
    std::vector<std::uint64_t>().swap(scratch);  // freed before the pairs take its room
    const std::uint64_t mask = (std::uint64_t{1} << shift) - 1;
    std::vector<Face_pair> pairs(word.size());
    for (std::size_t i = 0; i < word.size(); ++i)
      pairs[i] = {static_cast<Index>(word[i] >> shift), static_cast<Index>(word[i] & mask)};
    return pairs;
  }

  // ---- pair traversal -------------------------------------------------------

  static float extent(const Node& b) { return (b.hi[0] - b.lo[0]) + (b.hi[1] - b.lo[1]) + (b.hi[2] - b.lo[2]); }

  // The groups of a self search (collect_overlapping_pairs_between_groups):
  // of each slot's face, and of each node (its faces' common group, 0 when
  // they have none).
  struct Groups {
    std::vector<std::uint16_t> slot, node;
    // Two slots or two nodes whose pairs are all within one group.
    static bool same(std::uint16_t a, std::uint16_t b) { return a != 0 && a == b; }
  };
  Groups grouped(std::span<const std::uint16_t> group) const {
    if (group.size() != size_) throw Precondition_violation("Face_bvh: one group per face expected");
    Groups g;
    g.slot.resize(size_);
    for (std::size_t s = 0; s < size_; ++s) g.slot[s] = group[faces_[s]];
    g.node.resize(node_count_);
    for (std::size_t i = node_count_; i-- > 0;) {  // children after their parent
      const Node& n = nodes_[i];
      if (n.is_leaf()) {
        std::uint16_t common = g.slot[n.first];
        for (Index s = n.first + 1; s < n.first + n.count; ++s)
          if (g.slot[s] != common) common = 0;
        g.node[i] = common;
      } else {
        g.node[i] = g.node[n.first] == g.node[n.first + 1] ? g.node[n.first] : 0;
      }
    }
    return g;
  }

  // Bit i set: box b overlaps the box of slot first + i (i < count <= 64).
  // Without a branch per box: whether two boxes of neighbouring leaves
  // overlap is a coin toss the branch predictor loses.
  static std::uint64_t overlap_mask(const Box_3& b, const std::vector<Box_3>& boxes, Index first, Index count) {
    std::uint64_t mask = 0;
    for (Index i = 0; i < count; ++i) mask |= std::uint64_t{do_overlap(b, boxes[first + i])} << i;
    return mask;
  }
  // Faces of leaves x (this) and y (other) whose boxes overlap, but those
  // of one group.
  template <bool Self, class Emit>
  void leaf_pairs(const Node& x, const Face_bvh& other, const Node& y, Emit& emit, const Groups* groups) const {
    for (Index s = x.first; s < x.first + x.count; ++s) {
      const Box_3& bs = boxes_[s];
      if (!detail::closed_boxes_overlap(bs, y)) continue;
      for (std::uint64_t m = overlap_mask(bs, other.boxes_, y.first, y.count); m != 0; m &= m - 1) {
        const Index t = y.first + static_cast<Index>(std::countr_zero(m));
        if constexpr (Self) {
          if (groups && Groups::same(groups->slot[s], groups->slot[t])) continue;
          emit(std::min(faces_[s], other.faces_[t]), std::max(faces_[s], other.faces_[t]));
        } else {
          emit(faces_[s], other.faces_[t]);
        }
      }
    }
  }
  template <class Emit>
  void leaf_self_pairs(const Node& x, Emit& emit, const Groups* groups) const {
    for (Index s = x.first; s + 1 < x.first + x.count; ++s)
      for (std::uint64_t m = overlap_mask(boxes_[s], boxes_, s + 1, x.first + x.count - s - 1); m != 0; m &= m - 1) {
        const Index t = s + 1 + static_cast<Index>(std::countr_zero(m));
        if (!(groups && Groups::same(groups->slot[s], groups->slot[t])))
          emit(std::min(faces_[s], faces_[t]), std::max(faces_[s], faces_[t]));
      }
  }

  // One step of the descent from pair p (whose boxes overlap): its child
  // pairs whose boxes overlap, in order, by push(child pair); false when p is
  // a pair of leaves (or a leaf with itself) and cannot be split.
  // Pairs of nodes `groups` leaves out (nodes of this hierarchy: a self
  // search).
  static bool left_out(const Groups* groups, Index a, Index b) {
    return groups && Groups::same(groups->node[a], groups->node[b]);
  }
  template <bool Self, class Push>
  bool split_pair(const Face_bvh& other, Node_pair p, Push&& push, const Groups* groups) const {
    const Node& x = nodes_[p.a];
    const Node& y = other.nodes_[p.b];
    if constexpr (Self) {
      if (p.a == p.b) {
        if (x.is_leaf()) return false;
        const Index l = x.first, r = x.first + 1;
        if (!left_out(groups, l, l)) push(Node_pair{l, l});
        if (detail::closed_boxes_overlap(nodes_[l], nodes_[r]) && !left_out(groups, l, r)) push(Node_pair{l, r});
        if (!left_out(groups, r, r)) push(Node_pair{r, r});
        return true;
      }
    }
    if (x.is_leaf() && y.is_leaf()) return false;
    if (y.is_leaf() || (!x.is_leaf() && extent(x) >= extent(y))) {
      for (Index c = x.first; c < x.first + 2; ++c)
        if (detail::closed_boxes_overlap(nodes_[c], y) && !left_out(groups, c, p.b)) push(Node_pair{c, p.b});
    } else {
      for (Index c = y.first; c < y.first + 2; ++c)
        if (detail::closed_boxes_overlap(x, other.nodes_[c]) && !left_out(groups, p.a, c)) push(Node_pair{p.a, c});
    }
    return true;
  }

  // The pairs under node pair `start`, depth first.
  template <bool Self, class Emit>
  void traverse(const Face_bvh& other, Node_pair start, Emit& emit, std::vector<Node_pair>& stack,
                const Groups* groups = nullptr) const {
    stack.clear();
    stack.push_back(start);
    std::array<Node_pair, 3> children;
    while (!stack.empty()) {
      const Node_pair p = stack.back();
      stack.pop_back();
      int k = 0;
      const bool split = split_pair<Self>(
          other, p, [&](Node_pair c) { children[k++] = c; }, groups);
      if (!split) {
        if (Self && p.a == p.b)
          leaf_self_pairs(nodes_[p.a], emit, groups);
        else
          leaf_pairs<Self>(nodes_[p.a], other, other.nodes_[p.b], emit, groups);
        continue;
      }
      while (k > 0) stack.push_back(children[--k]);  // first child on top
    }
  }

  // The top of the descent as a list of independent node pairs (breadth
  // first until there are enough or none can be split): the same list for
  // every thread count.
  template <bool Self>
  std::vector<Node_pair> frontier(const Face_bvh& other, const Groups* groups = nullptr) const {
    std::vector<Node_pair> items;
    if (size_ == 0 || other.size_ == 0 || !detail::closed_boxes_overlap(nodes_[0], other.nodes_[0]) ||
        left_out(groups, 0, 0))
      return items;
    items.push_back({0, 0});
    constexpr std::size_t target = 256;
    while (items.size() < target) {
      std::vector<Node_pair> next;
      bool split_any = false;
      for (const Node_pair& p : items)
        if (split_pair<Self>(
                other, p, [&](Node_pair c) { next.push_back(c); }, groups))
          split_any = true;
        else next.push_back(p);
      items = std::move(next);
      if (!split_any) break;
    }
    return items;
  }

  template <bool Self, class Emit>
  void traverse_items(const Face_bvh& other, Emit&& emit) const {
    std::vector<Node_pair> stack;
    for (const Node_pair& p : frontier<Self>(other)) traverse<Self>(other, p, emit, stack);
  }

  template <bool Self, class R, class F>
  std::vector<R> collect(const Face_bvh& other, F& f, int threads, std::size_t* overlapping,
                         const Groups* groups = nullptr) const {
    const Default_fp_environment environment;
    const std::vector<Node_pair> items = frontier<Self>(other, groups);
    std::vector<R> result;
    if (internal::thread_count(threads) <= 1) {
      std::vector<Node_pair> stack;
      std::size_t calls = 0;
      auto emit = [&](Index a, Index b) { ++calls, f(a, b, result); };
      for (const Node_pair& p : items) traverse<Self>(other, p, emit, stack, groups);
      if (overlapping) *overlapping = calls;
      return result;
    }
    std::vector<std::vector<R>> parts(items.size());
    std::vector<std::size_t> calls(items.size(), 0);
    internal::parallel_for_each_index(items.size(), threads, [&](std::size_t i) {
      std::vector<Node_pair> stack;
      std::size_t n = 0;
      auto emit = [&](Index a, Index b) { ++n, f(a, b, parts[i]); };
      traverse<Self>(other, items[i], emit, stack, groups);
      calls[i] = n;
    });
    if (overlapping) {
      *overlapping = 0;
      for (std::size_t n : calls) *overlapping += n;
    }
    return concatenated(parts);
  }
  // The parallel parts, in order, in one vector.
  template <class R>
  static std::vector<R> concatenated(std::vector<std::vector<R>>& parts) {
    std::size_t total = 0;
    for (const auto& part : parts) total += part.size();
    std::vector<R> result;
    result.reserve(total);
    for (auto& part : parts)
      result.insert(result.end(), std::make_move_iterator(part.begin()), std::make_move_iterator(part.end()));
    return result;
  }

  // ---- single queries -------------------------------------------------------

  template <class Meets, class F>
  void query(Meets&& meets, F& f) const {
    if (size_ == 0) return;
    Index stack[128];
    int top = 0;
    if (meets(node_box(nodes_[0]))) stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (n.is_leaf()) {
        for (Index s = n.first; s < n.first + n.count; ++s)
          if (meets(boxes_[s])) f(faces_[s]);
        continue;
      }
      for (Index c = n.first + 2; c-- > n.first;)
        if (meets(node_box(nodes_[c]))) stack[top++] = c;  // one per level: depth < 64
    }
  }

  // p + t d, t in [0, t_max]: the slab test with every quotient enclosed by
  // intervals, so the computed entry is never later and the exit never
  // earlier than the exact ones.
  struct Linear_query {
    std::array<double, 3> p;
    std::array<Interval, 3> d;
    std::array<bool, 3> constant;
    double t_max;
    double slack = 0;
    bool may_meet(const Box_3& b) const {
      double enter = 0, leave = t_max;
      for (int k = 0; k < 3; ++k) {
        const double lo = slack > 0 ? sub_down(b.lo[k], slack) : b.lo[k];
        const double hi = slack > 0 ? add_up(b.hi[k], slack) : b.hi[k];
        if (constant[k]) {
          if (p[k] < lo || p[k] > hi) return false;
          continue;
        }
        const Interval t0 = (Interval(lo) - Interval(p[k])) / d[k];
        const Interval t1 = (Interval(hi) - Interval(p[k])) / d[k];
        enter = std::max(enter, std::min(t0.inf(), t1.inf()));
        leave = std::min(leave, std::max(t0.sup(), t1.sup()));
        if (enter > leave) return false;
      }
      return true;
    }
  };
  // `end_is_point`: v is the segment's other end (d = v - p, enclosed);
  // otherwise v is the direction itself.
  static Linear_query linear_query(const Point_3<double>& p, std::array<double, 3> v, bool end_is_point,
                                   double t_max) {
    Linear_query s;
    s.p = {p.x, p.y, p.z};
    s.t_max = t_max;
    bool any = false;
    for (int k = 0; k < 3; ++k) {
      if (!std::isfinite(s.p[k]) || !std::isfinite(v[k]))
        throw Precondition_violation("Face_bvh: segment or ray with a non-finite coordinate");
      s.d[k] = end_is_point ? Interval(v[k]) - Interval(s.p[k]) : Interval(v[k]);
      s.constant[k] = end_is_point ? v[k] == s.p[k] : v[k] == 0;
      any = any || !s.constant[k];
    }
    if (!any && !end_is_point) throw Precondition_violation("Face_bvh: ray with direction 0");
    return s;
  }

  std::unique_ptr<Node[]> nodes_;
  std::vector<Box_3> boxes_;  // in leaf order
  std::unique_ptr<Index[]> faces_;  // face of each slot
  std::size_t size_ = 0, node_count_ = 0;
  Box_3 bounds_;
  Index leaf_size_ = static_cast<Index>(Face_bvh_options{}.leaf_size);  // set by build_tree
};

}  // namespace relgeo
