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
// Steps: the corners' triangle; points on its edges split the triangle on
// that side; interior points split the triangle containing them (in two when
// on an edge); each constraint is made an edge by flipping the edges that
// cross it (Sloan, "A fast algorithm for generating constrained Delaunay
// triangulations", 1993, without the Delaunay part), after being cut at the
// points lying on it.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/certified_sort.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo::internal {

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
/// (points[i] for an Index i).
template <class K, class Points>
class Face_triangulator {
 public:
  using IP = typename K::Implicit_point_3;

  Face_triangulator(const K& k, const Points& points)
      : points_(points), orient2_(k.implicit_orientation_2_object()), compare_(k.compare_xyz_3_object()) {}

  Face_triangulation run(const Face_constraints& f, int axis) {
    reset(f, axis);
    Face_triangulation out;
    if (!is_certain(sigma_) || sigma_ == Certified_sign::zero) return fail(out, "the face is degenerate in its projection");
    if (!insert_edge_points(f)) return fail(out, failure_);
    for (Index p : f.interior_points)
      if (!insert_interior_point(local(p))) return fail(out, failure_);
    for (const auto& s : f.segments)
      if (!insert_segment(local(s[0]), local(s[1]))) return fail(out, failure_);
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
    global_.assign(f.corners.begin(), f.corners.end());
    tris_.clear();
    constrained_.clear();
    tris_.push_back({{0, 1, 2}, {-1, -1, -1}, true});
    sigma_ = orient2_(points_[f.corners[0]], points_[f.corners[1]], points_[f.corners[2]], axis_);
  }

  int local(Index g) {
    for (std::size_t i = 0; i < global_.size(); ++i)
      if (global_[i] == g) return static_cast<int>(i);
    global_.push_back(g);
    return static_cast<int>(global_.size() - 1);
  }

  // Orientation in the face's own orientation (positive: counter-clockwise).
  Certified_sign orient(int a, int b, int c) const {
    const Certified_sign o = orient2_(points_[global_[a]], points_[global_[b]], points_[global_[c]], axis_);
    return sigma_ == Certified_sign::negative ? -o : o;
  }

  // ---- points on the face's edges -------------------------------------------

  bool insert_edge_points(const Face_constraints& f) {
    for (int e = 0; e < 3; ++e) {
      std::vector<Index> pts = f.edge_points[e];
      const Index from = f.corners[e], to = f.corners[(e + 1) % 3];
      // Along the edge from `from` to `to`: compare_xyz orders a line's points
      // monotonically, increasing or decreasing with the direction.
      const Certified_sign dir = compare_(points_[from], points_[to]);
      if (!is_certain(dir)) return failed("undecided direction of a face edge");
      if (dir == Certified_sign::zero) return failed("a face edge is degenerate");
      const auto along_edge = [&](Index a, Index b) {
        const Certified_sign c = compare_(points_[a], points_[b]);
        return dir == Certified_sign::negative ? c : -c;
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

  bool insert_interior_point(int p) {
    for (std::size_t i = 0; i < tris_.size(); ++i) {
      const Tri& t = tris_[i];
      if (!t.alive) continue;
      std::array<Certified_sign, 3> s;
      bool outside = false;
      for (int k = 0; k < 3 && !outside; ++k) {
        s[k] = orient(t.v[k], t.v[(k + 1) % 3], p);
        if (!is_certain(s[k])) return failed("undecided location of a point in a face");
        outside = s[k] == Certified_sign::negative;
      }
      if (outside) continue;
      const int zeros = (s[0] == Certified_sign::zero) + (s[1] == Certified_sign::zero) + (s[2] == Certified_sign::zero);
      if (zeros >= 2) return true;  // on a vertex: the point is already there (equal points share an index)
      if (zeros == 1) {
        const int k = s[0] == Certified_sign::zero ? 0 : (s[1] == Certified_sign::zero ? 1 : 2);
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
    // between). The side of every point is kept: an edge crosses ab only if
    // its ends lie on opposite sides.
    side_.assign(global_.size(), Certified_sign::zero);
    for (int p = 0; p < static_cast<int>(global_.size()); ++p) {
      if (p == a || p == b) continue;
      const Certified_sign o = orient(a, b, p);
      if (!is_certain(o)) return failed("undecided position of a point against a segment");
      side_[p] = o;
      if (o != Certified_sign::zero) continue;
      const int between = strictly_between(a, b, p);
      if (between < 0) return failed("undecided order of points on a segment");
      if (between == 1) return insert_segment(a, p) && insert_segment(p, b);
    }
    // Sloan's queue: the edges crossing ab; an edge whose quadrilateral is
    // not convex goes to the back, a flipped one whose new diagonal still
    // crosses ab too (so no edge is flipped back and forth). Bounded for safety.
    std::deque<std::array<int, 2>> crossing;
    for (const Tri& t : tris_) {
      if (!t.alive) continue;
      for (int k = 0; k < 3; ++k) {
        const int x = t.v[k], y = t.v[(k + 1) % 3];
        if (x > y) continue;
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
    constrained_.push_back({std::min(a, b), std::max(a, b)});
    return true;
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
    return ap != Certified_sign::zero && ap == pb ? 1 : 0;
  }

  // 1 if segment xy crosses segment ab in both interiors, 0 if not, -1
  // undecided; the sides of x and y against ab are side_'s.
  int crosses(int a, int b, int x, int y) {
    if (x == a || x == b || y == a || y == b) return 0;
    if (side_[x] * side_[y] != Certified_sign::negative) return 0;
    const Certified_sign sa = orient(x, y, a), sb = orient(x, y, b);
    if (!is_certain(sa) || !is_certain(sb)) {
      failed("undecided crossing of a constraint");
      return -1;
    }
    return sa * sb == Certified_sign::negative ? 1 : 0;
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
    if (s1 != Certified_sign::positive || s2 != Certified_sign::negative) return 0;
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
  bool is_constrained(int x, int y) const {
    const std::array<int, 2> e{std::min(x, y), std::max(x, y)};
    return std::find(constrained_.begin(), constrained_.end(), e) != constrained_.end();
  }

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
  int axis_ = 2;
  Certified_sign sigma_ = Certified_sign::zero;
  std::vector<Index> global_;
  std::vector<Certified_sign> side_;  // of each point against the segment being inserted
  std::vector<Tri> tris_;
  std::vector<std::array<int, 2>> constrained_;
  std::string failure_;
};

}  // namespace relgeo::internal
