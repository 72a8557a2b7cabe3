// relgeo/boolean/internal/face_triangulation.h — one input triangle
// retriangulated in its own plane with the points and segments the other mesh
// puts on it: a constrained triangulation whose only predicate is the
// kernel's orientation of implicit points in a projection.
//
// Why not CGAL's Constrained_triangulation_2 with a traits class over these
// predicates: the Boolean runs under every kernel, and a naive kernel's
// predicates can be inconsistent; every loop here is bounded and a failure is
// reported instead of looping or tripping an assertion. The triangles are
// few per face (points arrive a handful at a time), so plain arrays and
// linear scans beat a general-purpose structure.
//
// Steps: the corners' triangle; interior points split the triangle
// containing them (in two when on an edge), in the lexicographic order of
// their approximations; points on its edges split the triangle on that side
// (before the interior points without the Delaunay flips: run);
// each constraint is made an edge by flipping the edges that cross it (Sloan,
// "A fast algorithm for generating constrained Delaunay triangulations",
// 1993), after being cut at the points lying on it; last,
// Lawson's flips make the triangulation constrained Delaunay in the face's
// plane, which removes the needles that the insertion order leaves and that
// rounding to doubles turns over (doc/boolean.md, "Retriangulation quality").
//
// What is certified and what is not. Every topological decision (where a
// point lies, which edges cross a constraint, whether a quadrilateral is
// strictly convex so that a flip keeps every triangle positive) is the
// kernel's exact orientation. Whether a flip improves the angles is a quality
// decision: it is taken on the points' approximations in doubles, in an
// orthonormal frame of the face's plane, and only when the in-circle test is
// clear by a wide margin; a wrong or skipped decision costs an angle, never
// validity, and a bound on the number of flips makes termination unconditional.
// The approximations also give each point an enclosing box, which lets the
// scans skip the orientation tests that the boxes already decide.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/certified_sort.h"
#include "relgeo/kernel/implicit_point.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::internal {

/// A map of the few keys of one face (its points, its constraint edges):
/// most faces have a handful, looked up by a scan of a vector that keeps
/// its memory from face to face; a face with many (a large face crossed by
/// many curves) moves them into a hash map. The hash maps alone allocated
/// a node per key: with the copies and the queue below, malloc and free
/// were an eighth of the retriangulation on CGAL's elephant.
template <class Key, class Value>
class Few_keys_map {
 public:
  void clear() {
    few_.clear();
    if (!many_.empty()) many_.clear();
  }
  const Value* find(Key k) const {
    if (!many_.empty()) {
      const auto it = many_.find(k);
      return it == many_.end() ? nullptr : &it->second;
    }
    for (const auto& [key, value] : few_)
      if (key == k) return &value;
    return nullptr;
  }
  /// \pre k is not in the map.
  void insert(Key k, Value v) {
    if (many_.empty()) {
      if (few_.size() < scan_limit) {
        few_.emplace_back(k, v);
        return;
      }
      for (const auto& [key, value] : few_) many_.emplace(key, value);
    }
    many_.emplace(k, v);
  }

 private:
  static constexpr std::size_t scan_limit = 32;
  std::vector<std::pair<Key, Value>> few_;
  std::unordered_map<Key, Value> many_;  // every key, once there are more than scan_limit
};

/// What lies on one face: its corners (as in the mesh), the points inside
/// each edge i (from corner i to corner i + 1, any order), the points inside
/// the face, and the segments that must become edges. All are indices into
/// the Boolean's point array.
struct Face_constraints {
  std::array<Index, 3> corners{};
  std::array<std::vector<Index>, 3> edge_points;
  std::vector<Index> interior_points;
  std::vector<std::array<Index, 2>> segments;
};

/// The triangles of a face (indices into the point array, oriented like the
/// face), or the reason they could not be built.
struct Face_triangulation {
  std::vector<Triangle> triangles;
  bool ok = true;
  std::string failure;
};

/// Points: the Boolean's points, K's implicit points by global index
/// (points[i] for an Index i) and their approximations
/// (points.approximation(i), as K's approximate_point_3_object gives them).
template <class K, class Points>
class Face_triangulator {
 public:
  using IP = typename K::Implicit_point_3;

  Face_triangulator(const K& k, const Points& points)
      : points_(points), orient2_(k.implicit_orientation_2_object()), compare_(k.compare_xyz_3_object()) {}

  /// Lawson's flips to a constrained Delaunay triangulation after the
  /// constraints (on by default; off gives the triangulation of insertion).
  void set_delaunay(bool on) { delaunay_ = on; }

  Face_triangulation run(const Face_constraints& f, int axis) {
    reset(f, axis);
    Face_triangulation out;
    if (!is_certain(sigma_) || certainly(sigma_, Certified_sign::zero))
      return fail(out, "the face is degenerate in its projection");
    // Interior points before edge points, in order along each line: where
    // the other mesh is (nearly) planar the curve crosses the face on a
    // (nearly) straight line, and each interior point would otherwise be
    // located against an edge between two points of that line (the curve's
    // entry and exit on the face's edges, or two points inserted before it
    // on both sides): an orientation of three nearly collinear points, which
    // takes exact arithmetic. Located beyond the points before it on its
    // line, a point is decided by the filters (on CAD parts against moved
    // copies, the exact stage's calls per Boolean: rotor 706 -> 13, fandisk
    // 858 -> 0). Without the flips the insertion order is the result: edge
    // points first, interior points as given, the triangulation of the
    // engine before issue 28, whose needles are what
    // Boolean_options::delaunay_retriangulation = false is kept for (tests
    // and experiments where rounding must break a result).
    if (!delaunay_ && !insert_edge_points(f)) return fail(out, failure_);
    for (int p : interior_points_in_order(f))
      if (!insert_interior_point(p)) return fail(out, failure_);
    if (delaunay_ && !insert_edge_points(f)) return fail(out, failure_);
    for (const auto& s : f.segments)
      if (!insert_segment(local(s[0]), local(s[1]))) return fail(out, failure_);
    if (delaunay_) make_delaunay();
    for (const auto& t : tris_)
      if (t.alive) out.triangles.push_back({global_[t.v[0]], global_[t.v[1]], global_[t.v[2]]});
    return out;
  }

 private:
  struct Tri {
    std::array<int, 3> v{};   // local vertices, counter-clockwise in the face's orientation
    std::array<int, 3> nb{};  // neighbour across edge (v[i], v[i+1]); -1 on the face's boundary
    bool alive = true;
  };

  static Face_triangulation fail(Face_triangulation& out, std::string why) {
    out.ok = false;
    out.failure = std::move(why);
    out.triangles.clear();
    return out;
  }

  void reset(const Face_constraints& f, int axis) {
    axis_ = axis;
    global_.clear();
    local_of_.clear();
    box_.clear();
    plane_.clear();
    blur_.clear();
    tris_.clear();
    constrained_.clear();
    set_frame(f.corners);
    for (Index c : f.corners) local(c);
    tris_.push_back({{0, 1, 2}, {-1, -1, -1}, true});
    sigma_ = orient2_(points_[f.corners[0]], points_[f.corners[1]], points_[f.corners[2]], axis_);
  }

  int local(Index g) {
    if (const int* known = local_of_.find(g)) return *known;
    const int l = static_cast<int>(global_.size());
    local_of_.insert(g, l);
    const Approximate_point_3 a = points_.approximation(g);
    global_.push_back(g);
    box_.push_back(enclosure(a));
    plane_.push_back(in_frame(a.point));
    // The approximations of certified kernels are within a few ulps of
    // their points; 2^-40 of the largest coordinate bounds that with room
    // (and the rounding of in_frame), the same for every kernel.
    blur_.push_back(0x1p-40 * unit_ * std::max({std::abs(a.point.x), std::abs(a.point.y), std::abs(a.point.z)}));
    return l;
  }

  // ---- enclosing boxes --------------------------------------------------------------

  // A box that contains the exact point whatever the rounding mode: the
  // approximation's error bound widened by more than the few ulps that
  // computing the bounds can lose; unbounded when the kernel does not know
  // its error (naive kernels) or the approximation is not finite.
  struct Box {
    std::array<double, 3> lo, hi;
  };
  static Box enclosure(const Approximate_point_3& a) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const std::array<double, 3> c{a.point.x, a.point.y, a.point.z};
    Box b{{-inf, -inf, -inf}, {inf, inf, inf}};
    if (!std::isfinite(a.error) || !std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2])) return b;
    for (int i = 0; i < 3; ++i) {
      const double pad = (a.error + std::abs(c[i]) * 0x1p-50 + 0x1p-1000) * (1 + 0x1p-40);
      b.lo[i] = c[i] - pad;
      b.hi[i] = c[i] + pad;
    }
    return b;
  }
  // Whether the boxes of the points `a` and of the points `b` are certainly
  // apart (then no point of one lies on the hull of the other).
  template <std::size_t N, std::size_t M>
  bool apart(const std::array<int, N>& a, const std::array<int, M>& b) const {
    for (int i = 0; i < 3; ++i) {
      double a_lo = box_[a[0]].lo[i], a_hi = box_[a[0]].hi[i], b_lo = box_[b[0]].lo[i], b_hi = box_[b[0]].hi[i];
      for (std::size_t j = 1; j < N; ++j) a_lo = std::min(a_lo, box_[a[j]].lo[i]), a_hi = std::max(a_hi, box_[a[j]].hi[i]);
      for (std::size_t j = 1; j < M; ++j) b_lo = std::min(b_lo, box_[b[j]].lo[i]), b_hi = std::max(b_hi, box_[b[j]].hi[i]);
      if (a_hi < b_lo || b_hi < a_lo) return true;
    }
    return false;
  }

  // Orientation in the face's own orientation (positive: counter-clockwise).
  Certified_sign orient(int a, int b, int c) const {
    const Certified_sign o = orient2_(points_[global_[a]], points_[global_[b]], points_[global_[c]], axis_);
    return certainly(sigma_, Certified_sign::negative) ? -o : o;
  }

  // ---- points on the face's edges -------------------------------------------

  bool insert_edge_points(const Face_constraints& f) {
    for (int e = 0; e < 3; ++e) {
      std::vector<Index>& pts = edge_points_;
      pts.assign(f.edge_points[e].begin(), f.edge_points[e].end());
      const Index from = f.corners[e], to = f.corners[(e + 1) % 3];
      // Along the edge from `from` to `to`: compare_xyz orders a line's points
      // monotonically, increasing or decreasing with the direction.
      const Certified_sign dir = compare_(points_[from], points_[to]);
      if (!is_certain(dir)) return failed("undecided direction of a face edge");
      if (certainly(dir, Certified_sign::zero)) return failed("a face edge is degenerate");
      const auto along_edge = [&](Index a, Index b) {
        const Certified_sign c = compare_(points_[a], points_[b]);
        return certainly(dir, Certified_sign::negative) ? c : -c;
      };
      if (!certified_sort(pts.begin(), pts.end(), along_edge)) return failed("undecided order of points on an edge");
      pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
      int a = e;  // local index of `from`
      for (Index g : pts) {
        const int p = local(g);
        const int next = e == 2 ? 0 : e + 1;
        if (!split_boundary_edge(a, next, p)) return false;
        a = p;
      }
    }
    return true;
  }

  // Splits the triangle on boundary edge (a, b) at p (on that edge).
  bool split_boundary_edge(int a, int b, int p) {
    for (std::size_t i = 0; i < tris_.size(); ++i) {
      Tri& t = tris_[i];
      if (!t.alive) continue;
      for (int k = 0; k < 3; ++k)
        if (t.v[k] == a && t.v[(k + 1) % 3] == b && t.nb[k] == -1) {
          split_edge_of(static_cast<int>(i), k, p);
          return true;
        }
    }
    return failed("a boundary edge to split was not found");
  }

  // Splits triangle ti at point p on its edge k (and the neighbour across it).
  void split_edge_of(int ti, int k, int p) {
    const Tri t = tris_[ti];
    const int a = t.v[k], b = t.v[(k + 1) % 3], c = t.v[(k + 2) % 3];
    const int nb_bc = t.nb[(k + 1) % 3], nb_ca = t.nb[(k + 2) % 3], other = t.nb[k];
    // ti becomes (a, p, c); a new triangle (p, b, c).
    const int tn = add({p, b, c}, {-1, nb_bc, ti});
    tris_[ti].v = {a, p, c};
    tris_[ti].nb = {-1, tn, nb_ca};
    relink(nb_bc, ti, tn);
    if (other >= 0) {  // the neighbour (b, a, d) becomes (b, p, d) and (p, a, d)
      const Tri o = tris_[other];
      const int j = edge_index(o, b, a);
      const int d = o.v[(j + 2) % 3];
      const int nb_ad = o.nb[(j + 1) % 3], nb_db = o.nb[(j + 2) % 3];
      const int on = add({p, a, d}, {ti, nb_ad, other});
      tris_[other].v = {b, p, d};
      tris_[other].nb = {tn, on, nb_db};
      relink(nb_ad, other, on);
      tris_[ti].nb[0] = on;
      tris_[tn].nb[0] = other;
    }
  }

  // ---- interior points ----------------------------------------------------------

  // The face's interior points (local indices), sorted by their
  // approximations in the face's frame (x, then y); in the given order
  // without the flips (run) or when an approximation is not finite (a kernel
  // that cannot bound its points).
  const std::vector<int>& interior_points_in_order(const Face_constraints& f) {
    std::vector<int>& order = interior_order_;
    order.clear();
    bool finite = true;
    for (Index g : f.interior_points) {
      const int p = local(g);
      order.push_back(p);
      finite = finite && std::isfinite(plane_[p][0]) && std::isfinite(plane_[p][1]);
    }
    if (delaunay_ && finite) std::sort(order.begin(), order.end(), [&](int x, int y) { return plane_[x] < plane_[y]; });
    return order;
  }

  bool insert_interior_point(int p) {
    for (std::size_t i = 0; i < tris_.size(); ++i) {
      const Tri& t = tris_[i];
      if (!t.alive || apart(t.v, std::array<int, 1>{p})) continue;
      // The edge p is most clearly outside of first: a certified negative
      // there rejects the triangle before a test that is exactly zero (p on
      // the line of another edge), which costs exact arithmetic.
      std::array<int, 3> order{0, 1, 2};
      std::array<double, 3> approx;
      for (int k = 0; k < 3; ++k) {
        const double o = approximate_orientation(t.v[k], t.v[(k + 1) % 3], p);
        approx[k] = std::isnan(o) ? 0 : o;
      }
      std::sort(order.begin(), order.end(), [&](int x, int y) { return approx[x] < approx[y]; });
      std::array<Certified_sign, 3> s{};
      bool outside = false;
      for (int k : order) {
        s[k] = orient(t.v[k], t.v[(k + 1) % 3], p);
        if (!is_certain(s[k])) return failed("undecided location of a point in a face");
        if ((outside = certainly(s[k], Certified_sign::negative))) break;
      }
      if (outside) continue;
      const int zeros = (certainly(s[0], Certified_sign::zero)) + (certainly(s[1], Certified_sign::zero)) +
                        (certainly(s[2], Certified_sign::zero));
      if (zeros >= 2) return true;  // on a vertex: the point is already there (equal points share an index)
      if (zeros == 1) {
        const int k = certainly(s[0], Certified_sign::zero) ? 0 : (certainly(s[1], Certified_sign::zero) ? 1 : 2);
        if (tris_[i].nb[k] == -1) return failed("an interior point lies on the face's boundary");
        split_edge_of(static_cast<int>(i), k, p);
        return true;
      }
      split_inside(static_cast<int>(i), p);
      return true;
    }
    return failed("an interior point lies in no triangle of its face");
  }

  void split_inside(int ti, int p) {
    const Tri t = tris_[ti];
    const int a = t.v[0], b = t.v[1], c = t.v[2];
    const int t1 = add({b, c, p}, {t.nb[1], -1, ti});
    const int t2 = add({c, a, p}, {t.nb[2], ti, t1});
    tris_[t1].nb[1] = t2;
    tris_[ti].v = {a, b, p};
    tris_[ti].nb = {t.nb[0], t1, t2};
    relink(t.nb[1], ti, t1);
    relink(t.nb[2], ti, t2);
  }

  // ---- constraints ----------------------------------------------------------------

  bool insert_segment(int a, int b) {
    if (a == b) return true;
    // Points of the face on the segment cut it (collinear and strictly
    // between); only a point whose box meets the segment's can be one. The
    // side of a point against ab is computed when first needed and kept: an
    // edge crosses ab only if its ends lie on opposite sides.
    side_.assign(global_.size(), Certified_sign::uncertain);
    for (int p = 0; p < static_cast<int>(global_.size()); ++p) {
      if (p == a || p == b || apart(std::array<int, 2>{a, b}, std::array<int, 1>{p})) continue;
      const Certified_sign o = side(a, b, p);
      if (!is_certain(o)) return failed("undecided position of a point against a segment");
      if (!certainly(o, Certified_sign::zero)) continue;
      const int between = strictly_between(a, b, p);
      if (between < 0) return failed("undecided order of points on a segment");
      if (between == 1) return insert_segment(a, p) && insert_segment(p, b);
    }
    // Sloan's queue: the edges crossing ab; an edge whose quadrilateral is
    // not convex goes to the back, a flipped one whose new diagonal still
    // crosses ab too (so no edge is flipped back and forth). Bounded for safety.
    // (A member: the recursive calls above return before it is used.)
    std::deque<std::array<int, 2>>& crossing = crossing_;
    crossing.clear();
    for (const Tri& t : tris_) {
      if (!t.alive) continue;
      for (int k = 0; k < 3; ++k) {
        const int x = t.v[k], y = t.v[(k + 1) % 3];
        if (x > y || apart(std::array<int, 2>{a, b}, std::array<int, 2>{x, y})) continue;
        const int c = crosses(a, b, x, y);
        if (c < 0) return false;
        if (c == 0) continue;
        if (is_constrained(x, y)) return failed("two constraint segments cross (self-intersecting input)");
        crossing.push_back({x, y});
      }
    }
    const std::size_t limit = 64 * (crossing.size() + 1) * (crossing.size() + 1) + 64;
    for (std::size_t iteration = 0; !crossing.empty(); ++iteration) {
      if (iteration > limit) return failed("constraint insertion did not terminate");
      const auto [x, y] = crossing.front();
      crossing.pop_front();
      int ti = -1, k = -1;
      if (!find_edge(x, y, ti, k)) return failed("a crossing edge disappeared");
      const int f = flip_if_convex(ti, k);
      if (f < 0) return false;
      if (f == 0) {
        crossing.push_back({x, y});
        continue;
      }
      // The new diagonal is edge 2 of ti after the flip: (q, p).
      const int p = tris_[ti].v[0], q = tris_[ti].v[2];
      const int c = crosses(a, b, p, q);
      if (c < 0) return false;
      if (c == 1) crossing.push_back({std::min(p, q), std::max(p, q)});
    }
    if (!has_edge(a, b)) return failed("no flip makes a constraint segment an edge");
    if (!is_constrained(a, b)) constrained_.insert(edge_key(a, b), true);
    return true;
  }

  // The side of p against ab (kept in side_ for the segment being inserted).
  Certified_sign side(int a, int b, int p) {
    if (!is_certain(side_[p])) side_[p] = orient(a, b, p);
    return side_[p];
  }

  // ---- constrained Delaunay -------------------------------------------------------

  // Lawson's flips: every interior edge that is not a constraint and whose
  // opposite vertex lies clearly inside the circumcircle of the triangle on
  // the other side is flipped (when its quadrilateral is strictly convex,
  // which the kernel decides), and the four edges around it are looked at
  // again. The flips are bounded: past the bound the triangulation is kept
  // as it is (valid, only not Delaunay everywhere). Never fails.
  void make_delaunay() {
    if (tris_.size() < 2) return;
    std::vector<std::array<int, 4>> todo;  // triangle, edge index, its two vertices
    for (int i = 0; i < static_cast<int>(tris_.size()); ++i)
      for (int k = 0; k < 3; ++k)
        if (tris_[i].nb[k] > i) todo.push_back({i, k, tris_[i].v[k], tris_[i].v[(k + 1) % 3]});
    const std::size_t limit = 16 * tris_.size() * tris_.size() + 64;
    for (std::size_t flips = 0; !todo.empty() && flips < limit;) {
      const auto [ti, k, x, y] = todo.back();
      todo.pop_back();
      const Tri& t = tris_[ti];
      if (t.v[k] != x || t.v[(k + 1) % 3] != y) continue;  // flipped away since: its successors are queued
      const int tj = t.nb[k];
      if (tj < 0 || is_constrained(x, y)) continue;
      const int p = t.v[(k + 2) % 3];
      const int q = tris_[tj].v[(edge_index(tris_[tj], y, x) + 2) % 3];
      if (!clearly_in_circle(x, y, p, q)) continue;
      // Not strictly convex, or undecided (a kernel that can be uncertain):
      // no flip; the triangulation stays valid as it is.
      if (flip_if_convex(ti, k) != 1) continue;
      ++flips;
      // ti is now (p, x, q), tj (q, y, p): their outer edges are 0 and 1.
      for (const int u : {ti, tj})
        for (int e = 0; e < 2; ++e) todo.push_back({u, e, tris_[u].v[e], tris_[u].v[e + 1]});
    }
  }

  // ---- the face's frame (quality decisions and test order only) ----------------

  // An orthonormal frame (e1, e2) of the face's plane from its corners'
  // approximations, oriented like the face (e1 x e2 along its normal), its
  // lengths scaled by a power of two that makes the face's size about 1 (so
  // the in-circle determinant neither underflows nor overflows, and operands
  // scaled by a power of two get the same decisions).
  void set_frame(const std::array<Index, 3>& corners) {
    std::array<Point_3<double>, 3> c;
    for (int i = 0; i < 3; ++i) c[i] = points_.approximation(corners[i]).point;
    std::array<double, 3> u{c[1].x - c[0].x, c[1].y - c[0].y, c[1].z - c[0].z};
    std::array<double, 3> w{c[2].x - c[0].x, c[2].y - c[0].y, c[2].z - c[0].z};
    int exponent = 0;
    std::frexp(std::max({std::abs(u[0]), std::abs(u[1]), std::abs(u[2]), std::abs(w[0]), std::abs(w[1]), std::abs(w[2])}),
               &exponent);
    unit_ = std::ldexp(1.0, -exponent);
    if (!std::isfinite(unit_) || unit_ == 0) unit_ = 1;
    for (int i = 0; i < 3; ++i) u[i] *= unit_, w[i] *= unit_;  // exact: a power of two
    const std::array<double, 3> n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const std::array<double, 3> v{n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
    const double lu = std::hypot(u[0], u[1], u[2]), lv = std::hypot(v[0], v[1], v[2]);
    origin_ = c[0];
    for (int i = 0; i < 3; ++i) e1_[i] = u[i] / lu, e2_[i] = v[i] / lv;  // NaN for a degenerate face: no decision
  }
  std::array<double, 2> in_frame(const Point_3<double>& p) const {
    const double d[3] = {p.x - origin_.x, p.y - origin_.y, p.z - origin_.z};
    return {unit_ * (d[0] * e1_[0] + d[1] * e1_[1] + d[2] * e1_[2]),
            unit_ * (d[0] * e2_[0] + d[1] * e2_[1] + d[2] * e2_[2])};
  }
  // The orientation of a, b, c in the frame, in doubles (for ordering tests).
  double approximate_orientation(int a, int b, int c) const {
    return (plane_[b][0] - plane_[a][0]) * (plane_[c][1] - plane_[a][1]) -
           (plane_[b][1] - plane_[a][1]) * (plane_[c][0] - plane_[a][0]);
  }

  // Whether q lies inside the circle through x, y, p (counter-clockwise in
  // the face's orientation) by a margin far above the error of the
  // approximations; false when in doubt or not finite. Two margins: relative
  // to the determinant's permanent (rounding), and against the points' blur
  // (moving a point by b changes the determinant by at most about 8 b L^3,
  // L the largest distance from q): points closer together than their
  // approximations can resolve give no decision, whatever the kernel.
  bool clearly_in_circle(int x, int y, int p, int q) const {
    const auto& d = plane_[q];
    const double ax = plane_[x][0] - d[0], ay = plane_[x][1] - d[1];
    const double bx = plane_[y][0] - d[0], by = plane_[y][1] - d[1];
    const double cx = plane_[p][0] - d[0], cy = plane_[p][1] - d[1];
    const double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    const double det = a2 * (bx * cy - cx * by) + b2 * (cx * ay - ax * cy) + c2 * (ax * by - bx * ay);
    const double scale = a2 * (std::abs(bx * cy) + std::abs(cx * by)) + b2 * (std::abs(cx * ay) + std::abs(ax * cy)) +
                         c2 * (std::abs(ax * by) + std::abs(bx * ay));
    const double blur = std::max({blur_[x], blur_[y], blur_[p], blur_[q]});
    const double reach = std::sqrt(std::max({a2, b2, c2}));
    return det > 0x1p-30 * scale && det > 64 * blur * reach * reach * reach;  // NaN compares false
  }

  // The triangle and its edge index holding edge {x, y} (either direction).
  bool find_edge(int x, int y, int& ti, int& k) const {
    for (std::size_t i = 0; i < tris_.size(); ++i) {
      if (!tris_[i].alive) continue;
      for (int j = 0; j < 3; ++j) {
        const int u = tris_[i].v[j], v = tris_[i].v[(j + 1) % 3];
        if ((u == x && v == y) || (u == y && v == x)) {
          ti = static_cast<int>(i), k = j;
          return tris_[i].nb[j] >= 0;
        }
      }
    }
    return false;
  }

  // Whether p (collinear with a and b) lies strictly between them: 1 yes,
  // 0 no, -1 undecided.
  int strictly_between(int a, int b, int p) {
    const Certified_sign ap = compare_(points_[global_[a]], points_[global_[p]]);
    const Certified_sign pb = compare_(points_[global_[p]], points_[global_[b]]);
    if (!is_certain(ap) || !is_certain(pb)) return -1;
    return !certainly(ap, Certified_sign::zero) && ap == pb ? 1 : 0;
  }

  // 1 if segment xy crosses segment ab in both interiors, 0 if not, -1
  // undecided.
  int crosses(int a, int b, int x, int y) {
    if (x == a || x == b || y == a || y == b) return 0;
    // a and b against the line xy first: a point x on the line ab but off
    // the segment (an exact zero, which costs exact arithmetic) has a and b
    // on one side of xy, so the pair is rejected before its side is asked.
    const Certified_sign sa = orient(x, y, a), sb = is_certain(sa) ? orient(x, y, b) : sa;
    if (!is_certain(sa) || !is_certain(sb)) {
      failed("undecided crossing of a constraint");
      return -1;
    }
    if (!certainly(sa * sb, Certified_sign::negative)) return 0;
    const Certified_sign sx = side(a, b, x), sy = is_certain(sx) ? side(a, b, y) : sx;
    if (!is_certain(sx) || !is_certain(sy)) {
      failed("undecided position of a point against a segment");
      return -1;
    }
    return certainly(sx * sy, Certified_sign::negative) ? 1 : 0;
  }

  // Flips the edge k of triangle ti when its quadrilateral is strictly convex:
  // 1 flipped, 0 not convex, -1 undecided.
  int flip_if_convex(int ti, int k) {
    const int tj = tris_[ti].nb[k];
    const Tri t = tris_[ti], u = tris_[tj];
    const int x = t.v[k], y = t.v[(k + 1) % 3], p = t.v[(k + 2) % 3];
    const int j = edge_index(u, y, x);
    const int q = u.v[(j + 2) % 3];
    const Certified_sign s1 = orient(p, q, y), s2 = orient(p, q, x);
    if (!is_certain(s1) || !is_certain(s2)) {
      failed("undecided flip");
      return -1;
    }
    // The quadrilateral x, q, y, p (counter-clockwise) is strictly convex when
    // its diagonal pq separates y (left) from x (right).
    if (!certainly(s1, Certified_sign::positive) || !certainly(s2, Certified_sign::negative)) return 0;
    const int n_yp = t.nb[(k + 1) % 3], n_px = t.nb[(k + 2) % 3];
    const int n_xq = u.nb[(j + 1) % 3], n_qy = u.nb[(j + 2) % 3];
    tris_[ti].v = {p, x, q};
    tris_[ti].nb = {n_px, n_xq, tj};
    tris_[tj].v = {q, y, p};
    tris_[tj].nb = {n_qy, n_yp, ti};
    relink(n_xq, tj, ti);
    relink(n_yp, ti, tj);
    return 1;
  }

  bool has_edge(int a, int b) const {
    for (const Tri& t : tris_)
      if (t.alive)
        for (int k = 0; k < 3; ++k)
          if ((t.v[k] == a && t.v[(k + 1) % 3] == b) || (t.v[k] == b && t.v[(k + 1) % 3] == a)) return true;
    return false;
  }
  static std::uint64_t edge_key(int x, int y) {
    return (std::uint64_t(std::uint32_t(std::min(x, y))) << 32) | std::uint32_t(std::max(x, y));
  }
  bool is_constrained(int x, int y) const { return constrained_.find(edge_key(x, y)) != nullptr; }

  // ---- bookkeeping --------------------------------------------------------------

  int add(std::array<int, 3> v, std::array<int, 3> nb) {
    tris_.push_back({v, nb, true});
    return static_cast<int>(tris_.size() - 1);
  }
  // In triangle n (if any), the neighbour `from` is now `to`.
  void relink(int n, int from, int to) {
    if (n < 0) return;
    for (int& x : tris_[n].nb)
      if (x == from) {
        x = to;
        return;
      }
  }
  static int edge_index(const Tri& t, int a, int b) {
    for (int k = 0; k < 3; ++k)
      if (t.v[k] == a && t.v[(k + 1) % 3] == b) return k;
    return 0;
  }
  bool failed(const char* why) {
    failure_ = why;
    return false;
  }

  const Points& points_;
  typename K::Implicit_orientation_2 orient2_;
  typename K::Compare_xyz_3 compare_;
  bool delaunay_ = true;
  int axis_ = 2;
  Certified_sign sigma_ = Certified_sign::zero;
  std::vector<Index> global_;                  // local -> the Boolean's index
  Few_keys_map<Index, int> local_of_;          // the Boolean's index -> local
  std::vector<Box> box_;                       // of each local point
  std::vector<std::array<double, 2>> plane_;   // of each local point, in the face's frame
  std::vector<double> blur_;                   // of each local point: how far its approximation may be off, in the frame
  Point_3<double> origin_;
  std::array<double, 3> e1_{}, e2_{};
  double unit_ = 1;                            // the frame's length scale (a power of two)
  std::vector<Certified_sign> side_;           // against the segment being inserted (uncertain: not computed)
  std::vector<Tri> tris_;
  Few_keys_map<std::uint64_t, bool> constrained_;  // the constraint edges inserted (edge_key)
  std::string failure_;
  // Working memory of one face, kept from face to face.
  std::vector<Index> edge_points_;
  std::vector<int> interior_order_;
  std::deque<std::array<int, 2>> crossing_;
};

}  // namespace relgeo::internal
