// relgeo/mesh/internal/projected_patches.h — patches of faces that a
// projection along a coordinate axis maps one to one: the
// self-intersection test's certificate for every pair of faces inside one.
//
// embedded_stars.h certifies the faces around one vertex, but the broad
// phase still meets each such pair (about six per face) only to drop it. A
// patch certifies thousands of faces at once, and the hierarchy's search
// does not descend into pairs of nodes that hold faces of one patch only
// (Face_bvh::collect_overlapping_pairs_between_groups).
//
// Certificate. Let R be a set of faces of a consistently oriented
// 2-manifold mesh whose projections to one coordinate plane all have the
// same strict orientation (say positive), and let R's boundary (its edges
// with one face in R, each run as in that face) form closed loops whose
// projections are simple polygons, pairwise disjoint, at most one of them
// counterclockwise (an outer loop and holes). Then the projection maps R
// one to one:
//  - a point q of the plane off every projected edge lies in as many
//    projected faces as the projected loops wind around it in all (a
//    positive triangle winds once around its inner points, and the two
//    faces of an inner edge run it in opposite directions, so their
//    boundaries add up to R's); a simple loop winds once around its inner
//    points in its direction, so the sum is at most 1: no such point is
//    covered twice;
//  - near a point inside a face, on an inner edge (whose faces project to
//    its two sides) or at a vertex whose star is in R (its faces' angles add
//    up to a positive multiple of 2 pi: one turn, since no point near it is
//    covered twice), the projection is one to one; two points of R with one
//    image, one of them off the boundary, would make points near that image
//    covered twice;
//  - two boundary points with one image would make the loops not simple or
//    not disjoint.
// A map that stays one to one after a projection is one to one: two faces of
// R meet only in what they share. (internal/limit_embedding.h makes the
// same degree argument for a region of a limit surface.)
//
// Patches grow across edges among faces whose normal (in doubles: a choice,
// not part of the certificate) is closest to one axis, with one sign, never
// taking a face that would touch the patch at a vertex only (so each vertex
// has one fan of the patch's faces, and the boundary edges chain into loops
// without choice). What the certificate uses is decided by the kernel: the
// faces' projected orientations (projected_orientations), and the loops'
// simplicity and direction, from orientations and comparisons of projected
// vertices. A patch that fails (loops that cross or touch, two loops
// turning like the faces, a sign the kernel cannot decide) is tried again in
// pieces of bounded size grown inside it; a piece that fails certifies
// nothing, and its pairs are tested one by one.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/kernel/point_access.h"
#include "relgeo/mesh/internal/embedded_stars.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::internal {

/// Sizes of the patches tried (in faces). Smaller pieces certify more of a
/// curved model and leave more boundary: on CGAL's armadillo 66% of the
/// faces end in patches with pieces of 1024, 89% with these sizes, and the
/// test's candidate pairs drop from 154K to 93K (of 335K without patches).
struct Projected_patch_sizes {
  /// Smaller patches are not tried: their pairs cost the broad phase little.
  std::size_t smallest = 32;
  /// Patches are grown up to this size (a larger one that fails costs more
  /// to try, and its pieces are grown again).
  std::size_t largest = 2048;
  /// The pieces a failed patch is tried again in.
  std::size_t piece = 256;
};

template <class K, class Points>
class Projected_patch_finder {
 public:
  using Point_2 = typename K::Point_2;

  Projected_patch_finder(const K& k, const Points& point, const std::vector<Triangle>& faces,
                         const std::vector<std::array<Certified_sign, 3>>& projected,
                         const std::vector<unsigned char>& skip, const Mesh_topology& t, Projected_patch_sizes sizes)
      : k_(k),
        point_(point),
        faces_(faces),
        t_(t),
        sizes_(sizes),
        key_(faces.size(), 0),
        admits_(faces.size(), 0),
        patch_(faces.size(), unassigned),
        out_(t.number_of_vertices(), invalid_index),
        touched_(t.number_of_vertices(), unassigned) {
    for (std::size_t f = 0; f < faces.size(); ++f)
      if (!skip[f]) classify(f, projected[f]);
  }

  /// Each face's patch (1, 2, ...; 0: in none certified).
  std::vector<std::uint16_t> patches() {
    std::vector<std::uint16_t> label(faces_.size(), 0);
    std::vector<Candidate> todo;
    for (Index seed = 0; seed < faces_.size(); ++seed) {
      if (!key_[seed] || patch_[seed] != unassigned) continue;
      todo.push_back({key_[seed], true, {}});
      grow(
          seed, key_[seed], [](Index) { return true; }, sizes_.largest, todo.back().members);
      while (!todo.empty()) {
        Candidate c = std::move(todo.back());
        todo.pop_back();
        if (c.members.size() < sizes_.smallest) continue;
        if (certify(c)) {
          if (!name(c.members, label)) return label;
        } else if (c.may_split) {
          split(c, todo);
        }
      }
    }
    return label;
  }

 private:
  static constexpr std::uint32_t unassigned = 0xFFFFFFFFu, retry = 0xFFFFFFFEu;
  static constexpr Index traced = invalid_index - 1;  // out_ of a vertex whose loop is traced

  // A patch to try: its faces (marked with one tentative number), its key,
  // and whether it may still be cut in pieces.
  struct Candidate {
    unsigned char key;
    bool may_split;
    std::vector<Index> members;
  };
  static unsigned char bit(unsigned char key) { return static_cast<unsigned char>(1u << (key - 1)); }
  static int plane_of(unsigned char key) { return ((key - 1) / 2 + 1) % 3; }

  // Keys are 1 + 2 axis + (negative ? 1 : 0); axis a's normal component is
  // the orientation in plane (a + 1) % 3 (xy: z). A face's key is that of
  // the largest component of its normal, when the kernel's sign there is
  // strict; it admits every key whose component is at least half the
  // largest with a strict sign (so a patch grows past faces slightly
  // steeper than 45 degrees, leaving fewer holes and pinches).
  void classify(std::size_t f, const std::array<Certified_sign, 3>& s) {
    using A = Point_access<typename K::Point_3>;
    std::array<std::array<double, 3>, 3> c;
    for (int i = 0; i < 3; ++i) {
      const auto& p = point_[faces_[f][i]];
      c[i] = {nearest_double(A::x(p)), nearest_double(A::y(p)), nearest_double(A::z(p))};
    }
    const std::array<double, 3> u{c[1][0] - c[0][0], c[1][1] - c[0][1], c[1][2] - c[0][2]};
    const std::array<double, 3> v{c[2][0] - c[0][0], c[2][1] - c[0][1], c[2][2] - c[0][2]};
    const std::array<double, 3> n{std::abs(u[1] * v[2] - u[2] * v[1]), std::abs(u[2] * v[0] - u[0] * v[2]),
                                  std::abs(u[0] * v[1] - u[1] * v[0])};
    // Without branches: the normal's direction and the signs follow no
    // pattern from face to face (with branches on them the patches took 5%
    // longer on CGAL's elephant and armadillo).
    const int largest = n[1] > n[0] ? (n[2] > n[1] ? 2 : 1) : (n[2] > n[0] ? 2 : 0);
    unsigned char key = 0, admits = 0;
    for (int a = 0; a < 3; ++a) {
      const Certified_sign sign = s[(a + 1) % 3];
      const bool positive = certainly(sign, Certified_sign::positive);
      const bool strict = positive | certainly(sign, Certified_sign::negative);
      const auto a_key = static_cast<unsigned char>(1 + 2 * a + !positive);
      key = (a == largest) & strict ? a_key : key;
      admits |= static_cast<unsigned char>((strict & (2 * n[a] >= n[largest])) * bit(a_key));
    }
    key_[f] = key;
    admits_[f] = admits;
  }

  // The faces reached from `seed` across edges through faces that admit
  // `key`, that `open` admits and no patch holds, breadth first, at most
  // `most`; each marked with a fresh tentative patch number. A face is not
  // taken where it would touch the patch at a vertex only (its third vertex
  // on the patch, neither edge there shared with it): the faces of a patch
  // around each of its vertices stay one fan, never two meeting in a point.
  template <class Open>
  void grow(Index seed, unsigned char key, Open&& open, std::size_t most, std::vector<Index>& members) {
    members.clear();
    const std::uint32_t id = next_id_++;
    const auto take = [&](Index f) {
      patch_[f] = id;
      members.push_back(f);
      for (Index v : faces_[f]) touched_[v] = id;
    };
    const auto in_patch = [&](Index h) {
      const Index o = t_.opposite(h);
      return o != invalid_index && patch_[Mesh_topology::face(o)] == id;
    };
    take(seed);
    for (std::size_t i = 0; i < members.size() && members.size() < most; ++i) {
      const Index f = members[i];
      for (Index h = 3 * f; h < 3 * f + 3 && members.size() < most; ++h) {
        const Index o = t_.opposite(h);
        if (o == invalid_index) continue;
        const Index g = Mesh_topology::face(o);
        if (!(admits_[g] & bit(key)) || !open(g) || (patch_[g] != unassigned && patch_[g] != retry)) continue;
        // o runs along the shared edge; its face's third vertex is the
        // target of next(o), reached by the edges next(o) and prev(o).
        const Index w = t_.target(Mesh_topology::next(o));
        if (touched_[w] == id && !in_patch(Mesh_topology::next(o)) && !in_patch(Mesh_topology::prev(o))) continue;
        take(g);
      }
    }
  }

  // A patch that failed, in pieces of bounded size (not cut again).
  void split(const Candidate& c, std::vector<Candidate>& todo) {
    for (Index f : c.members) patch_[f] = retry;
    for (Index f : c.members) {
      if (patch_[f] != retry) continue;
      todo.push_back({c.key, false, {}});
      grow(
          f, c.key, [&](Index g) { return patch_[g] == retry; }, sizes_.piece, todo.back().members);
    }
  }

  // Gives the certified patch `members` the next label; false when labels
  // have run out (the rest stay in none).
  bool name(const std::vector<Index>& members, std::vector<std::uint16_t>& label) {
    if (labels_ == 0xFFFF) return false;
    ++labels_;
    for (Index f : members) label[f] = static_cast<std::uint16_t>(labels_);
    return true;
  }

  // Whether the patch's boundary projects to disjoint simple loops, at
  // most one of which turns like its faces (file comment).
  bool certify(const Candidate& c) {
    const std::uint32_t id = patch_[c.members.front()];
    std::vector<Index> boundary;
    bool pinched = false;  // two boundary edges leave a vertex (grow prevents it)
    for (Index f : c.members)
      for (Index h = 3 * f; h < 3 * f + 3; ++h) {
        const Index o = t_.opposite(h);
        if (o != invalid_index && patch_[Mesh_topology::face(o)] == id) continue;
        boundary.push_back(h);
        Index& out = out_[t_.source(h)];
        pinched = pinched || out != invalid_index;
        out = h;
      }
    // The loops, one after the other in `ring` (loop l: ring[start[l]] to
    // ring[start[l + 1] - 1]).
    std::vector<Index> ring;
    std::vector<std::size_t> start;
    bool closed = !pinched && !boundary.empty();
    for (std::size_t i = 0; closed && i < boundary.size(); ++i) {
      if (out_[t_.source(boundary[i])] == traced) continue;
      start.push_back(ring.size());
      Index h = boundary[i];
      for (;;) {
        const Index v = t_.source(h), next = out_[t_.target(h)];
        ring.push_back(v);
        out_[v] = traced;
        if (next == traced) {
          closed = t_.target(h) == ring[start.back()];
          break;
        }
        if (next == invalid_index) {
          closed = false;
          break;
        }
        h = next;
      }
    }
    start.push_back(ring.size());
    for (Index h : boundary) out_[t_.source(h)] = invalid_index;
    return closed && simple_disjoint_loops(ring, start, plane_of(c.key), (c.key - 1) % 2 == 0);
  }

  // Whether the closed polygons of `ring` and `start` (certify) projected
  // to `plane` are simple and disjoint: consecutive edges of a loop meet
  // only in their common vertex, other edges not at all (closed segments);
  // and at most one of them turns counterclockwise (clockwise when not
  // `counterclockwise`). Candidate pairs by a sweep over the edges' boxes;
  // every answer from the kernel, an uncertain one a failure.
  bool simple_disjoint_loops(const std::vector<Index>& ring, const std::vector<std::size_t>& start, int plane,
                             bool counterclockwise) const {
    const std::size_t n = ring.size();
    std::vector<std::size_t> succ(n), pred(n);  // along each loop
    for (std::size_t l = 0; l + 1 < start.size(); ++l) {
      if (start[l + 1] - start[l] < 3) return false;
      for (std::size_t i = start[l]; i < start[l + 1]; ++i) {
        succ[i] = i + 1 < start[l + 1] ? i + 1 : start[l];
        pred[succ[i]] = i;
      }
    }
    std::vector<Point_2> q;
    q.reserve(n);
    for (Index v : ring) q.push_back(project_to_plane<K>(point_[v], plane));
    // The box of each vertex in the plane's two coordinates (u: the first),
    // then of each edge (i, succ[i]): lo_u, hi_u, lo_v, hi_v.
    using A = Point_access<typename K::Point_3>;
    std::vector<std::array<double, 4>> corner(n), box(n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto& p = point_[ring[i]];
      const std::array<double, 3> lo{lower_double(A::x(p)), lower_double(A::y(p)), lower_double(A::z(p))};
      const std::array<double, 3> hi{upper_double(A::x(p)), upper_double(A::y(p)), upper_double(A::z(p))};
      const int u = plane, v = (plane + 1) % 3;  // xy, yz, zx (project_to_plane)
      corner[i] = {lo[u], hi[u], lo[v], hi[v]};
    }
    for (std::size_t i = 0; i < n; ++i) {
      const std::array<double, 4>&a = corner[i], &b = corner[succ[i]];
      box[i] = {std::min(a[0], b[0]), std::max(a[1], b[1]), std::min(a[2], b[2]), std::max(a[3], b[3])};
    }
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return box[i][0] < box[j][0]; });
    for (std::size_t a = 0; a < n; ++a) {
      const std::size_t i = order[a];
      for (std::size_t b = a + 1; b < n && box[order[b]][0] <= box[i][1]; ++b) {
        const std::size_t j = order[b];
        if (box[j][2] > box[i][3] || box[i][2] > box[j][3]) continue;
        if (succ[i] == j || succ[j] == i) {
          const std::size_t first = succ[i] == j ? i : j;  // edges (u, w) and (w, x)
          if (!meet_only_at_shared(q[first], q[succ[first]], q[succ[succ[first]]])) return false;
        } else if (!certainly_disjoint(q[i], q[succ[i]], q[j], q[succ[j]])) {
          return false;
        }
      }
    }
    // Each loop's turn at its lowest vertex (lexicographically), where a
    // simple polygon is convex and its two edges are not on one line.
    const auto compare = k_.compare_xy_2_object();
    int turning_like_faces = 0;
    for (std::size_t l = 0; l + 1 < start.size(); ++l) {
      std::size_t lowest = start[l];
      for (std::size_t i = start[l] + 1; i < start[l + 1]; ++i) {
        const Certified_sign c = compare(q[i], q[lowest]);
        if (!is_certain(c)) return false;
        if (certainly(c, Certified_sign::negative)) lowest = i;
      }
      const Certified_sign turn = k_.orientation_2_object()(q[pred[lowest]], q[lowest], q[succ[lowest]]);
      if (!is_certain(turn)) return false;
      turning_like_faces += certainly(turn, counterclockwise ? Certified_sign::positive : Certified_sign::negative);
    }
    return turning_like_faces <= 1;
  }

  // Segments uw and wx meet only in w (w differs from u and x: the faces
  // are not degenerate in this plane).
  bool meet_only_at_shared(const Point_2& u, const Point_2& w, const Point_2& x) const {
    const Certified_sign turn = k_.orientation_2_object()(u, w, x);
    if (!is_certain(turn)) return false;
    if (!certainly(turn, Certified_sign::zero)) return true;
    // On one line: they meet only in w when u and x lie on opposite sides
    // of it.
    const auto compare = k_.compare_xy_2_object();
    return opposite_strict_signs(compare(u, w), compare(x, w));
  }

  // Closed segments ab and cd certainly share no point.
  bool certainly_disjoint(const Point_2& a, const Point_2& b, const Point_2& c, const Point_2& d) const {
    const auto orient = k_.orientation_2_object();
    const Certified_sign c_side = orient(a, b, c), d_side = orient(a, b, d);
    if (!is_certain(c_side) || !is_certain(d_side)) return false;
    if (strictly_same_side(c_side, d_side)) return true;
    const Certified_sign a_side = orient(c, d, a), b_side = orient(c, d, b);
    if (!is_certain(a_side) || !is_certain(b_side)) return false;
    if (strictly_same_side(a_side, b_side)) return true;
    const bool collinear = certainly(c_side, Certified_sign::zero) && certainly(d_side, Certified_sign::zero);
    if (!collinear) return false;  // each line separates the other segment's ends, or touches one
    // On one line: disjoint when one segment ends before the other begins
    // (lexicographic order along the line).
    const auto compare = k_.compare_xy_2_object();
    const Certified_sign ab = compare(a, b), cd = compare(c, d);
    if (!is_certain(ab) || !is_certain(cd)) return false;
    const bool ab_rises = certainly(ab, Certified_sign::negative), cd_rises = certainly(cd, Certified_sign::negative);
    const Point_2 &ab_low = ab_rises ? a : b, &ab_high = ab_rises ? b : a;
    const Point_2 &cd_low = cd_rises ? c : d, &cd_high = cd_rises ? d : c;
    return certainly(compare(ab_high, cd_low), Certified_sign::negative) ||
           certainly(compare(cd_high, ab_low), Certified_sign::negative);
  }
  static bool strictly_same_side(Certified_sign x, Certified_sign y) {
    return (certainly(x, Certified_sign::positive) && certainly(y, Certified_sign::positive)) ||
           (certainly(x, Certified_sign::negative) && certainly(y, Certified_sign::negative));
  }
  static bool opposite_strict_signs(Certified_sign x, Certified_sign y) {
    return (certainly(x, Certified_sign::positive) && certainly(y, Certified_sign::negative)) ||
           (certainly(x, Certified_sign::negative) && certainly(y, Certified_sign::positive));
  }

  const K& k_;
  const Points& point_;
  const std::vector<Triangle>& faces_;
  const Mesh_topology& t_;
  Projected_patch_sizes sizes_;
  std::vector<unsigned char> key_, admits_;  // of each face (classify)
  std::vector<std::uint32_t> patch_;         // tentative patch of each face
  std::vector<Index> out_;                   // the boundary half-edge leaving each vertex (scratch)
  std::vector<std::uint32_t> touched_;       // the last tentative patch at each vertex
  std::uint32_t next_id_ = 0;
  std::uint32_t labels_ = 0;
};

/// Each face's patch (1, 2, ...; 0: in none) among patches that a projection
/// along a coordinate axis maps one to one (file comment): two faces of one
/// patch meet only in what they share. `projected`: every plane's
/// orientation of each face (projected_orientations); `skip`: faces left out
/// of the test (in no patch).
/// \pre `t` is the topology of `faces`, an edge- and vertex-manifold,
/// consistently oriented mesh.
template <class K, class Points>
std::vector<std::uint16_t> projected_patches(const K& k, const Points& point, const std::vector<Triangle>& faces,
                                             const std::vector<std::array<Certified_sign, 3>>& projected,
                                             const std::vector<unsigned char>& skip, const Mesh_topology& t,
                                             Projected_patch_sizes sizes = {}) {
  // The normals in doubles that choose the patches, in the default
  // environment: the same patches (and report) whatever the caller's.
  const Default_fp_environment environment;
  return Projected_patch_finder<K, Points>(k, point, faces, projected, skip, t, sizes).patches();
}

}  // namespace relgeo::internal
