// relgeo/intersection/triangle_intersection.h — the intersection of two
// triangles in space, classified, with exact implicit points, under any
// IntersectionKernel_3.
//
// Following Guigue and Devillers ("Fast and robust triangle-triangle overlap
// test using orientation predicates", J. Graphics Tools 8, 2003), everything
// is decided by signs: the orientations of each triangle's vertices against
// the other's plane separate most pairs; otherwise each triangle cuts the
// other's plane along a segment of the common line L, whose ends are input
// vertices or LPI points (an edge crossing the other plane), and the two
// segments are intersected along L (points on a line are ordered along it by
// compare_xyz). Coplanar triangles are clipped against each other in a
// projection where they do not degenerate; their edge crossings are LPI
// points of one edge's line and the plane through the other edge and a point
// off the common plane. Under an exact kernel every configuration is decided
// exactly and no point is perturbed.
//
// Under Failsafe_kernel (thesis Sec. 5.3, eq. 5.3), a vertex whose side is
// `uncertain` lies in the ambiguity zone of the other plane; it is moved in
// its own triangle's plane, away from its opposite edge, by rho greater than
// twice the zone's width, and the test is run again on the moved triangle:
// the result reports every such perturbation (triangle, vertex, rho), so a
// caller can state the backward error. When that does not settle it (or for
// an interval kernel, which has no such rule) the result is `undecided`.
// Naive kernels answer with their plain signs and never crash; what they
// answer may be wrong.
#pragma once

#include <boost/container/static_vector.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <type_traits>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/errors.h"
#include "relgeo/core/number_traits.h"
#include "relgeo/intersection/internal/cut_overlap.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/implicit_point.h"
#include "relgeo/kernel/internal/orientation_against.h"
#include "relgeo/kernel/point_access.h"
#include "relgeo/kernel/vector_3.h"

namespace relgeo {

/// Where a point of an intersection lies on one of the two triangles.
struct Triangle_location {
  enum class Kind : std::uint8_t { vertex, edge, interior };
  Kind kind = Kind::interior;
  std::uint8_t index = 0;  ///< vertex i, or edge i (from vertex i to vertex (i + 1) % 3)
  friend bool operator==(const Triangle_location&, const Triangle_location&) = default;
};

/// The shape of the intersection of two triangles.
enum class Triangle_intersection_kind : std::uint8_t {
  disjoint,          ///< no common point
  vertex_touch,      ///< one common point, a vertex of at least one triangle
  point_touch,       ///< one common point on edges of both (no vertex)
  edge_touch,        ///< a segment lying on an edge of at least one triangle
  crossing,          ///< a segment through the interior of both triangles
  coplanar_overlap,  ///< coplanar triangles sharing a convex polygon of positive area
  undecided          ///< the kernel could not decide (failsafe, interval)
};

constexpr const char* to_string(Triangle_intersection_kind k) {
  switch (k) {
    case Triangle_intersection_kind::disjoint: return "disjoint";
    case Triangle_intersection_kind::vertex_touch: return "vertex-touch";
    case Triangle_intersection_kind::point_touch: return "point-touch";
    case Triangle_intersection_kind::edge_touch: return "edge-touch";
    case Triangle_intersection_kind::crossing: return "crossing";
    case Triangle_intersection_kind::coplanar_overlap: return "coplanar-overlap";
    case Triangle_intersection_kind::undecided: return "undecided";
  }
  return "?";
}

/// A vertex moved by the fail-safe rule: `triangle` 0 or 1, `vertex` 0..2,
/// by `rho` (in coordinate units) to `moved_to`.
template <class Point>
struct Triangle_perturbation {
  int triangle = 0;
  int vertex = 0;
  double rho = 0;
  Point moved_to{};
};

/// Options of intersect_triangles.
struct Triangle_intersection_options {
  /// Apply the fail-safe perturbation (thesis eq. 5.3) to vertices in an
  /// ambiguity zone. Only kernels with an a-priori orientation_3 bound
  /// (Failsafe_kernel) can; the others report `undecided`.
  bool perturb_ambiguous_vertices = true;
  /// How many times rho is doubled before giving up.
  int perturbation_attempts = 4;
};

/// The intersection of two triangles: its kind, its points (1 for a point,
/// 2 for a segment, the vertices of the convex polygon in order for a
/// coplanar overlap; input vertices are explicit points, others LPI points),
/// where each point lies on each triangle, and the perturbations applied.
template <IntersectionKernel_3 K>
struct Triangle_intersection {
  using Point = typename K::Implicit_point_3;
  Triangle_intersection_kind kind = Triangle_intersection_kind::undecided;
  boost::container::static_vector<Point, 6> points;
  boost::container::static_vector<std::array<Triangle_location, 2>, 6> locations;  ///< on the first, second triangle
  boost::container::static_vector<Triangle_perturbation<typename K::Point_3>, 6> perturbations;
  bool coplanar = false;
};

namespace internal {

template <IntersectionKernel_3 K>
class Triangle_intersector {
 public:
  using P = typename K::Point_3;
  using IP = typename K::Implicit_point_3;
  using Triangle = std::array<P, 3>;
  using Result = Triangle_intersection<K>;

  Triangle_intersector(const K& k, const Triangle_intersection_options& o)
      : k_(k), o_(o), orient3_(k.orientation_3_object()), make_(k.construct_implicit_point_3_object()),
        compare_(k.compare_xyz_3_object()), orient2_(k.implicit_orientation_2_object()) {}

  /// After run(): the kernel decided that a triangle is degenerate (the
  /// result is then `undecided`). A broken precondition of
  /// intersect_triangles, which throws; the mesh Boolean reports it as its
  /// failure instead.
  bool degenerate_input() const { return degenerate_input_; }

  Result run(Triangle a, Triangle b) {
    Result r;
    degenerate_input_ = false;
    for (int attempt = 0;; ++attempt) {
      std::array<Certified_sign, 3> sa, sb;
      // A triangle strictly on one side of the other's plane: disjoint,
      // whatever the other signs are (decided or not). Tested for a first:
      // most pairs of a broad phase end after its three orientations.
      const auto against_b = internal::orientation_against(k_, b[0], b[1], b[2]);
      for (int i = 0; i < 3; ++i) sa[i] = against_b(a[i]);
      if (separated(sa)) {
        r.kind = Triangle_intersection_kind::disjoint;
        return r;
      }
      const auto against_a = internal::orientation_against(k_, a[0], a[1], a[2]);
      for (int i = 0; i < 3; ++i) sb[i] = against_a(b[i]);
      if (separated(sb)) {
        r.kind = Triangle_intersection_kind::disjoint;
        return r;
      }
      const int ambiguous = first_uncertain(sa) >= 0 ? 0 : (first_uncertain(sb) >= 0 ? 1 : -1);
      if (ambiguous < 0) {
        run_decided(a, b, sa, sb, r);
        return r;
      }
      if (!can_perturb() || attempt >= o_.perturbation_attempts || r.perturbations.size() == 6) {
        r.kind = Triangle_intersection_kind::undecided;
        return r;
      }
      Triangle& t = ambiguous == 0 ? a : b;
      const int v = first_uncertain(ambiguous == 0 ? sa : sb);
      const auto moved = perturbed(t, v, ambiguous == 0 ? b : a, attempt);
      if (!moved) {
        r.kind = Triangle_intersection_kind::undecided;
        return r;
      }
      t[v] = moved->moved_to;
      auto p = *moved;
      p.triangle = ambiguous;
      r.perturbations.push_back(p);
    }
  }

 private:
  static int first_uncertain(const std::array<Certified_sign, 3>& s) {
    for (int i = 0; i < 3; ++i)
      if (!is_certain(s[i])) return i;
    return -1;
  }
  // All three vertices strictly on one side of the other plane.
  static bool separated(const std::array<Certified_sign, 3>& s) {
    return (s[0] == s[1] && s[1] == s[2]) &&
           (certainly(s[0], Certified_sign::positive) || certainly(s[0], Certified_sign::negative));
  }

  static constexpr bool can_perturb() {
    if constexpr (std::is_floating_point_v<typename K::FT> && K::is_certified && !K::has_exact_predicates)
      return K::orientation_3_error_bound.has_value();
    else
      return false;
  }

  // The fail-safe move of vertex v of t, in t's plane, away from the
  // opposite edge, by rho = 4 * 2^attempt times the width of the other
  // plane's ambiguity zone at that point.
  std::optional<Triangle_perturbation<P>> perturbed(const Triangle& t, int v, const Triangle& other,
                                                    int attempt) const {
    if constexpr (!can_perturb()) {
      return std::nullopt;
    } else {
      using T = typename K::FT;
      const auto sub = [](const P& x, const P& y) { return std::array<double, 3>{double(x.x) - double(y.x), double(x.y) - double(y.y), double(x.z) - double(y.z)}; };
      const auto norm = [](const std::array<double, 3>& x) { return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]); };
      // Width of the zone: |det| <= eps Mx My Mz with the largest differences
      // to other[0]; divided by |normal of the other plane|.
      double m[3] = {0, 0, 0};
      const std::array<P, 3> pts{other[1], other[2], t[v]};
      for (const P& q : pts) {
        const auto d = sub(q, other[0]);
        for (int i = 0; i < 3; ++i) m[i] = std::max(m[i], std::abs(d[i]));
      }
      const double normal = norm(cross(sub(other[1], other[0]), sub(other[2], other[0])));
      if (!(normal > 0)) return std::nullopt;
      const double width = *K::orientation_3_error_bound * m[0] * m[1] * m[2] / normal;
      // Direction: in t's plane, orthogonal to the opposite edge, away from it.
      const P& e0 = t[(v + 1) % 3];
      const P& e1 = t[(v + 2) % 3];
      const auto edge = sub(e1, e0);
      const auto to_v = sub(t[v], e0);
      const double el2 = edge[0] * edge[0] + edge[1] * edge[1] + edge[2] * edge[2];
      if (!(el2 > 0)) return std::nullopt;
      const double along = (to_v[0] * edge[0] + to_v[1] * edge[1] + to_v[2] * edge[2]) / el2;
      std::array<double, 3> dir{to_v[0] - along * edge[0], to_v[1] - along * edge[1], to_v[2] - along * edge[2]};
      const double len = norm(dir);
      if (!(len > 0) || !std::isfinite(width)) return std::nullopt;
      const double rho = 4 * std::ldexp(std::max(width, std::numeric_limits<double>::min()), attempt);
      Triangle_perturbation<P> p;
      p.vertex = v;
      p.rho = rho;
      p.moved_to = P{T(double(t[v].x) + rho * dir[0] / len), T(double(t[v].y) + rho * dir[1] / len),
                     T(double(t[v].z) + rho * dir[2] / len)};
      return p;
    }
  }

  // ---- the decided case ----------------------------------------------------

  // One end of a triangle's cut of the other plane: the point and where it
  // lies on its own triangle.
  struct Cut_point {
    IP point;
    Triangle_location location;
  };
  struct Cut {
    boost::container::static_vector<Cut_point, 2> ends;  // ordered along L by compare_xyz
    bool along_edge = false;                             // two vertices in the plane: the cut is that edge
    std::uint8_t edge = 0;
  };

  // \pre every sign certain, neither triangle separated by the other's plane (run).
  void run_decided(const Triangle& a, const Triangle& b, const std::array<Certified_sign, 3>& sa,
                   const std::array<Certified_sign, 3>& sb, Result& r) {
    if (all_zero(sa) || all_zero(sb)) {
      r.coplanar = true;
      coplanar(a, b, r);
      return;
    }
    // Most pairs that reach here are disjoint (in the Boolean of CGAL's gear
    // pinion.off with a moved copy, 19,382 of 21,162): two orientations
    // decide those before any point is built.
    const std::optional<bool> meet = cuts_overlap(orient3_, a, sa, b, sb);
    if (meet && !*meet) {
      r.kind = Triangle_intersection_kind::disjoint;
      return;
    }
    const auto ca = cut(a, sa, b), cb = cut(b, sb, a);
    if (!ca || !cb) {  // an LPI point the kernel could not build, or ends it could not order
      r.kind = Triangle_intersection_kind::undecided;
      return;
    }
    overlap(*ca, *cb, r);
  }

  // The cut of triangle t (signs s against the other plane, through o);
  // nullopt when the kernel cannot build or order its ends.
  std::optional<Cut> cut(const Triangle& t, const std::array<Certified_sign, 3>& s, const Triangle& o) const {
    Cut c;
    int zeros = 0;
    for (int i = 0; i < 3; ++i)
      if (certainly(s[i], Certified_sign::zero)) {
        c.ends.push_back({make_(t[i]), {Triangle_location::Kind::vertex, static_cast<std::uint8_t>(i)}});
        ++zeros;
      }
    if (zeros == 2) {
      c.along_edge = true;
      const int missing = !certainly(s[0], Certified_sign::zero) ? 0 : (!certainly(s[1], Certified_sign::zero) ? 1 : 2);
      c.edge = static_cast<std::uint8_t>((missing + 1) % 3);
    }
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      if (!certainly(s[i] * s[j], Certified_sign::negative)) continue;
      auto p = make_(t[i], t[j], o[0], o[1], o[2]);
      if (!p) return std::nullopt;
      c.ends.push_back({*p, {Triangle_location::Kind::edge, static_cast<std::uint8_t>(i)}});
    }
    if (c.ends.size() == 2) {
      const Certified_sign order = compare_(c.ends[0].point, c.ends[1].point);
      if (!is_certain(order)) return std::nullopt;  // overlap() needs the ends in order along L
      if (certainly(order, Certified_sign::positive)) std::swap(c.ends[0], c.ends[1]);
    }
    return c;
  }

  // Location on the other triangle of a point strictly inside its cut.
  static Triangle_location inside(const Cut& c) {
    if (c.along_edge) return {Triangle_location::Kind::edge, c.edge};
    return {Triangle_location::Kind::interior, 0};
  }

  // The common part of the two cuts along L.
  void overlap(const Cut& ca, const Cut& cb, Result& r) {
    const Cut_point& a0 = ca.ends.front();
    const Cut_point& a1 = ca.ends.back();
    const Cut_point& b0 = cb.ends.front();
    const Cut_point& b1 = cb.ends.back();
    // Start: the larger start; end: the smaller end.
    const Certified_sign s = compare_(a0.point, b0.point);
    const Certified_sign e = compare_(a1.point, b1.point);
    if (!is_certain(s) || !is_certain(e)) {
      r.kind = Triangle_intersection_kind::undecided;
      return;
    }
    const auto merged = [&](const Cut_point& pa, const Cut_point& pb, Certified_sign c,
                            bool start) -> std::pair<IP, std::array<Triangle_location, 2>> {
      if (certainly(c, Certified_sign::zero)) return {prefer(pa.point, pb.point), {pa.location, pb.location}};
      const bool take_a = start ? certainly(c, Certified_sign::positive) : certainly(c, Certified_sign::negative);
      if (take_a) return {pa.point, {pa.location, inside(cb)}};
      return {pb.point, {inside(ca), pb.location}};
    };
    const auto [start, start_loc] = merged(a0, b0, s, true);
    const auto [end, end_loc] = merged(a1, b1, e, false);
    const Certified_sign length = compare_(start, end);
    if (!is_certain(length)) {
      r.kind = Triangle_intersection_kind::undecided;
      return;
    }
    if (certainly(length, Certified_sign::positive)) {
      r.kind = Triangle_intersection_kind::disjoint;
      return;
    }
    if (certainly(length, Certified_sign::zero)) {  // one point: where it lies is the more specific of both records
      const std::array<Triangle_location, 2> loc{more_specific(start_loc[0], end_loc[0]),
                                                 more_specific(start_loc[1], end_loc[1])};
      r.points.push_back(prefer(start, end));
      r.locations.push_back(loc);
      r.kind = is_vertex(loc) ? Triangle_intersection_kind::vertex_touch : Triangle_intersection_kind::point_touch;
      return;
    }
    r.points.push_back(start);
    r.locations.push_back(start_loc);
    r.points.push_back(end);
    r.locations.push_back(end_loc);
    r.kind = on_one_edge(start_loc[0], end_loc[0]) || on_one_edge(start_loc[1], end_loc[1])
                 ? Triangle_intersection_kind::edge_touch
                 : Triangle_intersection_kind::crossing;
  }

  // Of two representations of one point, the input vertex (explicit) if any.
  const IP& prefer(const IP& a, const IP& b) const {
    return (a.kind != Implicit_point_kind::explicit_point && b.kind == Implicit_point_kind::explicit_point) ? b : a;
  }
  static Triangle_location more_specific(const Triangle_location& x, const Triangle_location& y) {
    return static_cast<int>(x.kind) <= static_cast<int>(y.kind) ? x : y;  // vertex < edge < interior
  }
  static bool is_vertex(const std::array<Triangle_location, 2>& l) {
    return l[0].kind == Triangle_location::Kind::vertex || l[1].kind == Triangle_location::Kind::vertex;
  }
  // Whether two locations on one triangle lie on one closed edge.
  static bool on_one_edge(const Triangle_location& x, const Triangle_location& y) {
    const auto edges = [](const Triangle_location& l) -> unsigned {  // bit i: on closed edge i
      switch (l.kind) {
        case Triangle_location::Kind::vertex: return (1u << l.index) | (1u << ((l.index + 2) % 3));
        case Triangle_location::Kind::edge: return 1u << l.index;
        default: return 0;
      }
    };
    return (edges(x) & edges(y)) != 0;
  }

  // ---- coplanar triangles -------------------------------------------------

  struct Polygon_vertex {
    IP point;
    int support = -1;  // the polygon edge from this vertex lies on: 0..2 edges of a, 3..5 edges of b
  };

  void coplanar(const Triangle& a, const Triangle& b, Result& r) {
    // A projection in which a does not degenerate (exists: a is a triangle).
    int axis = -1;
    Certified_sign sigma = Certified_sign::zero;
    const std::array<IP, 3> A{make_(a[0]), make_(a[1]), make_(a[2])};
    const std::array<IP, 3> B{make_(b[0]), make_(b[1]), make_(b[2])};
    for (int k = 2; k >= 0 && certainly(sigma, Certified_sign::zero); --k) {
      sigma = orient2_(A[0], A[1], A[2], k);
      axis = k;
    }
    if (!is_certain(sigma) || certainly(sigma, Certified_sign::zero)) {
      degenerate_input_ = certainly(sigma, Certified_sign::zero);
      r.kind = Triangle_intersection_kind::undecided;
      return;
    }
    const Certified_sign sigma_b = orient2_(B[0], B[1], B[2], axis);
    if (!is_certain(sigma_b) || certainly(sigma_b, Certified_sign::zero)) {
      degenerate_input_ = certainly(sigma_b, Certified_sign::zero);
      r.kind = Triangle_intersection_kind::undecided;
      return;
    }
    // b's vertices in counter-clockwise order of the projection, then clipped
    // by a's three edge lines (a's interior on the left after orienting by sigma).
    boost::container::static_vector<Polygon_vertex, 9> poly;
    const bool reverse_b = certainly(sigma_b, Certified_sign::negative);
    for (int i = 0; i < 3; ++i) {
      const int j = reverse_b ? (3 - i) % 3 : i;                    // vertex order
      const int edge = reverse_b ? (j + 2) % 3 : j;                 // edge from vertex j to the next in order
      poly.push_back({B[j], 3 + edge});
    }
    for (int e = 0; e < 3 && !poly.empty(); ++e) {
      const int i0 = e, i1 = (e + 1) % 3;
      const bool undecided = !clip(poly, A[i0], A[i1], e, sigma, a, b, axis);
      if (undecided) {
        r.kind = Triangle_intersection_kind::undecided;
        return;
      }
    }
    finish_coplanar(poly, A, B, sigma, sigma_b, axis, r);
  }

  // Side of p against the directed line (e0, e1) in the projection, with
  // the sign fixed so that the inside of a is positive.
  Certified_sign side(const IP& e0, const IP& e1, const IP& p, Certified_sign sigma, int axis) const {
    const Certified_sign o = orient2_(e0, e1, p, axis);
    return certainly(sigma, Certified_sign::negative) ? -o : o;
  }

  // Sutherland-Hodgman against one closed half-plane of a. False if undecided.
  bool clip(boost::container::static_vector<Polygon_vertex, 9>& poly, const IP& e0, const IP& e1, int edge,
            Certified_sign sigma, const Triangle& a, const Triangle& b, int axis) const {
    boost::container::static_vector<Polygon_vertex, 9> out;
    const std::size_t n = poly.size();
    boost::container::static_vector<Certified_sign, 9> sides;
    for (const auto& v : poly) {
      sides.push_back(side(e0, e1, v.point, sigma, axis));
      if (!is_certain(sides.back())) return false;
    }
    // Consistent signs add at most one vertex per clip (a convex polygon
    // crosses a line twice at most); a naive kernel's may alternate and
    // overflow the polygon: undecided then, as for an uncertain sign.
    const auto add = [&out](Polygon_vertex v) {
      if (out.size() == out.capacity()) return false;
      out.push_back(std::move(v));
      return true;
    };
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t prev = (i + n - 1) % n;
      const Certified_sign su = sides[prev], sv = sides[i];
      const Polygon_vertex& u = poly[prev];
      if (certainly(sv, Certified_sign::positive) && certainly(su, Certified_sign::negative)) {
        auto x = crossing(u.support, edge, a, b, axis);
        if (!x || !add({*x, u.support})) return false;
      }
      if (!certainly(sv, Certified_sign::negative)) {
        // A vertex on the line followed by an outside one: its edge now runs along a's edge.
        const bool leaves =
            certainly(sv, Certified_sign::zero) && certainly(sides[(i + 1) % n], Certified_sign::negative);
        if (!add({poly[i].point, leaves ? edge : poly[i].support})) return false;
      }
      if (certainly(sv, Certified_sign::negative) && certainly(su, Certified_sign::positive)) {
        auto x = crossing(u.support, edge, a, b, axis);
        if (!x || !add({*x, edge})) return false;  // the polygon now runs along a's edge
      }
    }
    poly = std::move(out);
    return true;
  }

  // The crossing of the line of polygon edge `support` with the line of a's
  // edge `edge`: an LPI of the support's line and the plane through a's edge
  // and a point off the common plane (shifted along the projection axis).
  std::optional<IP> crossing(int support, int edge, const Triangle& a, const Triangle& b, int axis) const {
    if (support < 3) {  // two edges of a meet at a vertex of a
      const int v = support == (edge + 1) % 3 ? support : edge;  // shared vertex
      return make_(a[v]);
    }
    const int s = support - 3;
    const P& s0 = b[s];
    const P& s1 = b[(s + 1) % 3];
    const P& e0 = a[edge];
    const P& e1 = a[(edge + 1) % 3];
    return make_(s0, s1, e0, e1, off_plane(e0, axis));
  }

  // e0 moved along `axis`: off the common plane, whose normal has a nonzero
  // component along the projection axis. Any move will do: by 1, or, where
  // a floating-point type absorbs that (|c| >= 2^53), to 2c, or c / 2 where
  // 2c would overflow.
  static P off_plane(const P& e0, int axis) {
    using A = internal::Point_access<P>;
    using FT = typename A::FT;
    FT c[3] = {A::x(e0), A::y(e0), A::z(e0)};
    const FT moved = FT(c[axis] + FT(1));
    if (certainly(K::compare_ft(moved, c[axis]), Certified_sign::zero)) {
      const FT doubled = FT(c[axis] * FT(2));
      c[axis] = is_finite_number(doubled) ? doubled : FT(c[axis] / FT(2));
    } else {
      c[axis] = moved;
    }
    return A::make(c[0], c[1], c[2]);
  }

  void finish_coplanar(const boost::container::static_vector<Polygon_vertex, 9>& poly, const std::array<IP, 3>& A,
                       const std::array<IP, 3>& B, Certified_sign sigma, Certified_sign sigma_b, int axis,
                       Result& r) const {
    // Distinct points only (a vertex on a clipping line can repeat). Every
    // comparison below must be decided: an uncertain one read as "different"
    // would keep a point twice, or take the wrong extreme of a segment.
    const auto undecided = [&r] { r.kind = Triangle_intersection_kind::undecided; };
    boost::container::static_vector<IP, 9> pts;
    for (const auto& v : poly) {
      bool repeated = false;
      for (const auto& q : pts) {
        const Certified_sign same = compare_(q, v.point);
        if (!is_certain(same)) return undecided();
        repeated = repeated || certainly(same, Certified_sign::zero);
      }
      if (!repeated) pts.push_back(v.point);
    }
    if (pts.empty()) {
      r.kind = Triangle_intersection_kind::disjoint;
      return;
    }
    if (pts.size() > r.points.capacity()) return undecided();  // more than two triangles' overlap can have: inconsistent signs
    // Locations (and the input vertex as the representative of a vertex).
    boost::container::static_vector<std::array<Triangle_location, 2>, 9> locs;
    for (auto& p : pts) {
      const auto la_ = locate(A, p, sigma, axis), lb_ = locate(B, p, sigma_b, axis);
      if (!la_ || !lb_) return undecided();
      const Triangle_location la = *la_, lb = *lb_;
      if (la.kind == Triangle_location::Kind::vertex) p = A[la.index];
      else if (lb.kind == Triangle_location::Kind::vertex) p = B[lb.index];
      locs.push_back({la, lb});
    }
    bool collinear = true;
    for (std::size_t i = 2; i < pts.size() && collinear; ++i) {
      const Certified_sign o = orient2_(pts[0], pts[1], pts[i], axis);
      if (!is_certain(o)) return undecided();
      collinear = certainly(o, Certified_sign::zero);
    }
    if (pts.size() >= 3 && !collinear) {
      r.kind = Triangle_intersection_kind::coplanar_overlap;
      for (std::size_t i = 0; i < pts.size(); ++i) r.points.push_back(pts[i]), r.locations.push_back(locs[i]);
      return;
    }
    // A point or a segment: its extreme points along the line.
    std::size_t lo = 0, hi = 0;
    for (std::size_t i = 1; i < pts.size(); ++i) {
      const Certified_sign below = compare_(pts[i], pts[lo]), above = compare_(pts[i], pts[hi]);
      if (!is_certain(below) || !is_certain(above)) return undecided();
      if (certainly(below, Certified_sign::negative)) lo = i;
      if (certainly(above, Certified_sign::positive)) hi = i;
    }
    r.points.push_back(pts[lo]);
    r.locations.push_back(locs[lo]);
    if (lo == hi) {
      r.kind = is_vertex(locs[lo]) ? Triangle_intersection_kind::vertex_touch : Triangle_intersection_kind::point_touch;
      return;
    }
    r.points.push_back(pts[hi]);
    r.locations.push_back(locs[hi]);
    r.kind = Triangle_intersection_kind::edge_touch;
  }

  // Location of a point of the common plane on triangle T (orientation sigma).
  std::optional<Triangle_location> locate(const std::array<IP, 3>& T, const IP& p, Certified_sign sigma,
                                         int axis) const {
    int zeros = 0, first = -1, second = -1;
    for (int e = 0; e < 3; ++e) {
      const Certified_sign s = side(T[e], T[(e + 1) % 3], p, sigma, axis);
      if (!is_certain(s)) return std::nullopt;
      if (certainly(s, Certified_sign::zero)) {
        ++zeros;
        (first < 0 ? first : second) = e;
      }
    }
    if (zeros == 0) return Triangle_location{Triangle_location::Kind::interior, 0};
    if (zeros == 1) return Triangle_location{Triangle_location::Kind::edge, static_cast<std::uint8_t>(first)};
    // On edges first and second: their shared vertex.
    const int v = second == (first + 1) % 3 ? second : first;
    return Triangle_location{Triangle_location::Kind::vertex, static_cast<std::uint8_t>(v)};
  }

  const K& k_;
  Triangle_intersection_options o_;
  typename K::Orientation_3 orient3_;
  typename K::Construct_implicit_point_3 make_;
  typename K::Compare_xyz_3 compare_;
  typename K::Implicit_orientation_2 orient2_;
  bool degenerate_input_ = false;
};

}  // namespace internal

namespace internal {

// Fast test of Guigue and Devillers: orientations of input points only.
template <OrientationKernel_3 K>
class Triangle_overlap_test {
 public:
  using P = typename K::Point_3;
  using Triangle = std::array<P, 3>;

  explicit Triangle_overlap_test(const K& k) : orient3_(k.orientation_3_object()), k_(k) {}

  std::optional<bool> run(Triangle a, Triangle b) const {
    const auto against_a = internal::orientation_against(k_, a[0], a[1], a[2]);
    const std::array<Certified_sign, 3> sb{against_a(b[0]), against_a(b[1]), against_a(b[2])};
    if (strictly_one_side(sb)) return false;
    const auto against_b = internal::orientation_against(k_, b[0], b[1], b[2]);
    const std::array<Certified_sign, 3> sa{against_b(a[0]), against_b(a[1]), against_b(a[2])};
    if (strictly_one_side(sa)) return false;
    for (int i = 0; i < 3; ++i)
      if (!is_certain(sa[i]) || !is_certain(sb[i])) return std::nullopt;
    if (all_zero(sa)) return coplanar(a, b);
    return cuts_overlap(orient3_, a, sa, b, sb);
  }

 private:
  static bool strictly_one_side(const std::array<Certified_sign, 3>& s) {
    return s[0] == s[1] && s[1] == s[2] &&
           (certainly(s[0], Certified_sign::positive) || certainly(s[0], Certified_sign::negative));
  }
  // Coplanar triangles: closed triangles in one plane overlap unless an edge
  // line of one strictly separates the other's vertices (the 2D separating
  // axis theorem), decided in a projection where neither degenerates.
  std::optional<bool> coplanar(const Triangle& a, const Triangle& b) const {
    const auto o2 = k_.orientation_2_object();
    const auto project = [&](const P& p, int axis) {  // kept axes (axis+1)%3, (axis+2)%3
      using A = internal::Point_access<P>;
      // Braces: relgeo's Point_2 is an aggregate (clang 14 has no
      // parenthesised aggregate initialisation), CGAL's has a constructor.
      return typename K::Point_2{axis == 0 ? A::y(p) : (axis == 1 ? A::z(p) : A::x(p)),
                                 axis == 0 ? A::z(p) : (axis == 1 ? A::x(p) : A::y(p))};
    };
    for (int axis = 2; axis >= 0; --axis) {
      std::array<typename K::Point_2, 3> A, B;
      for (int i = 0; i < 3; ++i) A[i] = project(a[i], axis), B[i] = project(b[i], axis);
      const Certified_sign sa = o2(A[0], A[1], A[2]);
      if (certainly(sa, Certified_sign::zero)) continue;
      const Certified_sign sb = o2(B[0], B[1], B[2]);
      if (!is_certain(sa) || !is_certain(sb)) return std::nullopt;
      if (certainly(sb, Certified_sign::zero))
        throw Precondition_violation("do_intersect_triangles: a degenerate triangle");
      bool unknown = false;
      const auto separates = [&](const std::array<typename K::Point_2, 3>& T, Certified_sign s,
                                 const std::array<typename K::Point_2, 3>& U) {
        for (int e = 0; e < 3; ++e) {
          bool all_out = true;
          for (int v = 0; v < 3 && all_out; ++v) {
            const Certified_sign side = o2(T[e], T[(e + 1) % 3], U[v]);
            if (!is_certain(side)) unknown = true;
            all_out = side == -s;
          }
          if (all_out) return true;
        }
        return false;
      };
      if (separates(A, sa, B) || separates(B, sb, A)) return false;
      if (unknown) return std::nullopt;
      return true;
    }
    throw Precondition_violation("do_intersect_triangles: a degenerate triangle");
  }

  typename K::Orientation_3 orient3_;
  const K& k_;
};

}  // namespace internal

/// \brief Whether triangles a and b intersect (closed triangles: touching
/// counts), from orientations of the input points only (Guigue-Devillers):
/// the fast test when the intersection itself is not needed. Empty when the
/// kernel cannot decide. \pre neither triangle is degenerate.
template <OrientationKernel_3 K>
std::optional<bool> do_intersect_triangles(const std::array<typename K::Point_3, 3>& a,
                                           const std::array<typename K::Point_3, 3>& b, const K& k = K{}) {
  return internal::Triangle_overlap_test<K>(k).run(a, b);
}

/// \brief The intersection of triangles a and b (each three points of K),
/// classified, with its points and their locations on both triangles.
///
/// Requires an IntersectionKernel_3. \pre neither triangle is degenerate
/// (three collinear points: Precondition_violation when the kernel decides
/// it). Exact under kernels with exact predicates; see the file comment for
/// the fail-safe perturbation. Complexity: constant.
template <IntersectionKernel_3 K>
Triangle_intersection<K> intersect_triangles(const std::array<typename K::Point_3, 3>& a,
                                             const std::array<typename K::Point_3, 3>& b, const K& k = K{},
                                             const Triangle_intersection_options& options = {}) {
  internal::Triangle_intersector<K> intersector(k, options);
  Triangle_intersection<K> r = intersector.run(a, b);
  if (intersector.degenerate_input()) throw Precondition_violation("intersect_triangles: a degenerate triangle");
  return r;
}

}  // namespace relgeo
