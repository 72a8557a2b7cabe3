// relgeo/curves/convex_separation.h — exact, certified-rounding distances
// between the convex hulls of small double point sets: the margins of the
// extruded-object conditions (thesis Sec. 3.4.1).
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "relgeo/core/dyadic.h"
#include "relgeo/core/rounding.h"
#include "relgeo/error/convex_polygon.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/kernel/point.h"

namespace relgeo {

/// A signed distance, exact: `side` +1 (apart), 0 (touching) or -1
/// (overlapping); `squared` is the squared distance when apart and the
/// squared penetration depth when overlapping (0 when touching).
struct Signed_distance {
  int side = 1;
  mpq_class squared = 0;

  /// The signed value rounded toward -inf: never larger than the exact one
  /// (a margin must never be overstated).
  double lower() const {
    if (side > 0) return sqrt_rational(squared, Rounding::downward);
    if (side < 0) return -sqrt_rational(squared, Rounding::upward);
    return 0.0;
  }
  /// The signed value rounded toward +inf.
  double upper() const {
    if (side > 0) return sqrt_rational(squared, Rounding::upward);
    if (side < 0) return -sqrt_rational(squared, Rounding::downward);
    return 0.0;
  }
};

namespace internal {

inline mpq_class dot(const mpq_class& nx, const mpq_class& ny, const Point_2<double>& p) {
  return nx * p.x + ny * p.y;
}

/// Proper crossing of segments pq and rs (exact orientations, all four nonzero
/// and of opposite signs in pairs).
inline bool segments_cross_properly(const Point_2<double>& p, const Point_2<double>& q,
                                    const Point_2<double>& r, const Point_2<double>& s) {
  const auto o = Filtered_exact_kernel().orientation_2_object();
  const int a = to_int(o(p, q, r)), b = to_int(o(p, q, s)), c = to_int(o(r, s, p)), d = to_int(o(r, s, q));
  return a * b < 0 && c * d < 0;
}

/// Squared distance from p to segment ab in double (the exact formula of
/// internal::squared_distance_to_segment evaluated in floating point).
inline double approx_squared_distance_to_segment(const Point_2<double>& p, const Point_2<double>& a,
                                                 const Point_2<double>& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, wx = p.x - a.x, wy = p.y - a.y;
  const double len2 = dx * dx + dy * dy, dot = wx * dx + wy * dy;
  if (len2 == 0 || dot <= 0) return wx * wx + wy * wy;
  if (dot >= len2) {
    const double ex = p.x - b.x, ey = p.y - b.y;
    return ex * ex + ey * ey;
  }
  const double cross = wx * dy - wy * dx;
  return cross * cross / len2;
}

/// \brief min over the segments (p_i, q_i) of the exact squared distance to
/// them, computing exactly only the segments a double filter cannot rule out.
///
/// With C the largest |coordinate| involved, every intermediate of the double
/// evaluation is bounded by a small multiple of C (|w|, |d| <= 2C) and carries
/// at most a few roundings, so each approximate squared distance is within
/// 1600 u C^2 < 2^-40 C^2 of the exact one (also where a rounding picks the
/// wrong branch of the piecewise formula: near a branch boundary the branches
/// differ by dot^2 / len2 = O(u^2 C^2)). Segments whose approximation exceeds
/// the smallest approximation by more than 2 * 2^-40 C^2 cannot attain the
/// minimum. Outside 2^-400 <= C <= 2^400 (where squares could underflow or
/// overflow) every segment is computed exactly.
/// Exact squared distances in integers: every coordinate involved is scaled
/// by the same power of two 2^-emin (emin = the smallest exponent of the
/// lowest set bit over the nonzero coordinates), which makes it an integer;
/// a squared distance is then a fraction num / den of integers (no gcd), and
/// two of them compare by cross-multiplication.
class Scaled_squared_distances {
 public:
  explicit Scaled_squared_distances(std::span<const Point_2<double>> points) {
    emin_ = 0;
    bool any = false;
    for (const auto& p : points)
      for (double v : {p.x, p.y}) {
        const Binary_parts b = binary_parts(v);  // v = mantissa 2^exponent
        if (b.mantissa == 0) continue;
        emin_ = any ? std::min(emin_, b.exponent) : b.exponent;
        any = true;
      }
  }
  /// v * 2^-emin as an integer. \pre v is one of the coordinates given (or 0).
  void load(mpz_class& z, double v) const {
    const Binary_parts b = binary_parts(v);
    set_mpz(z.get_mpz_t(), b.mantissa);
    if (b.mantissa != 0 && b.exponent > emin_)
      mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), static_cast<mp_bitcnt_t>(b.exponent - emin_));
  }
  /// Squared distance from p to segment ab as num / den (in units of 2^(2 emin)).
  void squared_distance_to_segment(const Point_2<double>& p, const Point_2<double>& a, const Point_2<double>& b,
                                   mpz_class& num, mpz_class& den) {
    load(px_, p.x), load(py_, p.y), load(ax_, a.x), load(ay_, a.y), load(bx_, b.x), load(by_, b.y);
    dx_ = bx_ - ax_, dy_ = by_ - ay_, wx_ = px_ - ax_, wy_ = py_ - ay_;
    len2_ = dx_ * dx_ + dy_ * dy_;
    dot_ = wx_ * dx_ + wy_ * dy_;
    den = 1;
    if (sgn(len2_) == 0 || sgn(dot_) <= 0) {
      num = wx_ * wx_ + wy_ * wy_;
    } else if (dot_ >= len2_) {
      wx_ = px_ - bx_, wy_ = py_ - by_;
      num = wx_ * wx_ + wy_ * wy_;
    } else {
      cross_ = wx_ * dy_ - wy_ * dx_;
      num = cross_ * cross_;
      den = len2_;
    }
  }
  /// num / den as the rational it stands for.
  mpq_class value(const mpz_class& num, const mpz_class& den) const {
    mpq_class q(num, den);
    q.canonicalize();
    if (emin_ > 0) mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(2 * emin_));
    else if (emin_ < 0) mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-2 * emin_));
    return q;
  }

 private:
  int emin_ = 0;
  mpz_class px_, py_, ax_, ay_, bx_, by_, dx_, dy_, wx_, wy_, len2_, dot_, cross_;
};

/// \brief min over the segments (p_i, q_i) of the exact squared distance from
/// p to them, computing exactly only the segments a double filter cannot rule
/// out.
///
/// With C the largest |coordinate| involved, every intermediate of the double
/// evaluation is bounded by a small multiple of C (|w|, |d| <= 2C) and carries
/// at most a few roundings, so each approximate squared distance is within
/// 1600 u C^2 < 2^-40 C^2 of the exact one (also where a rounding picks the
/// wrong branch of the piecewise formula: near a branch boundary the branches
/// differ by dot^2 / len2 = O(u^2 C^2)). Segments whose approximation exceeds
/// the smallest approximation by more than 2 * 2^-40 C^2 cannot attain the
/// minimum. Outside 2^-400 <= C <= 2^400 (where squares could underflow or
/// overflow) every segment is computed exactly. The exact values are
/// computed in scaled integers (Scaled_squared_distances).
template <class Segments>
mpq_class min_squared_distance(const Point_2<double>& p, const Segments& segments, double C) {
  const bool filter = C >= 0x1p-400 && C <= 0x1p400;
  std::vector<double> approx;
  double best_approx = std::numeric_limits<double>::infinity();
  if (filter) {
    approx.reserve(segments.size());
    for (const auto& [a, b] : segments) {
      approx.push_back(approx_squared_distance_to_segment(p, a, b));
      best_approx = std::min(best_approx, approx.back());
    }
  }
  const double slack = 2 * 0x1p-40 * C * C;
  std::vector<Point_2<double>> involved{p};
  std::vector<std::size_t> candidates;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (filter && approx[i] > best_approx + slack) continue;
    candidates.push_back(i);
    involved.push_back(segments[i].first), involved.push_back(segments[i].second);
  }
  Scaled_squared_distances exact(involved);
  mpz_class num, den, best_num, best_den;
  bool have = false;
  for (std::size_t i : candidates) {
    exact.squared_distance_to_segment(p, segments[i].first, segments[i].second, num, den);
    if (!have || num * best_den < best_num * den) best_num = num, best_den = den, have = true;
  }
  return exact.value(best_num, best_den);
}

/// Squared penetration depth of two intersecting convex polygons (strictly
/// convex CCW vertex lists): the smallest overlap of their projections over
/// the edge normals of both (the edges of the Minkowski difference A - B are
/// parallel to edges of A or of B, so the minimum over these axes is the
/// minimum translation distance). 0 when no axis exists (two equal points).
inline mpq_class squared_penetration_depth(std::span<const Point_2<double>> a,
                                           std::span<const Point_2<double>> b) {
  std::optional<mpq_class> best;
  auto axis_of = [&](std::span<const Point_2<double>> poly) {
    if (poly.size() < 2) return;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Point_2<double>& p = poly[i];
      const Point_2<double>& q = poly[(i + 1) % poly.size()];
      const mpq_class nx = -(mpq_class(q.y) - mpq_class(p.y)), ny = mpq_class(q.x) - mpq_class(p.x);
      const mpq_class len2 = nx * nx + ny * ny;
      if (sgn(len2) == 0) continue;
      mpq_class amin = dot(nx, ny, a[0]), amax = amin, bmin = dot(nx, ny, b[0]), bmax = bmin;
      for (const auto& v : a) {
        const mpq_class t = dot(nx, ny, v);
        if (t < amin) amin = t;
        if (t > amax) amax = t;
      }
      for (const auto& v : b) {
        const mpq_class t = dot(nx, ny, v);
        if (t < bmin) bmin = t;
        if (t > bmax) bmax = t;
      }
      mpq_class overlap = std::min(mpq_class(amax - bmin), mpq_class(bmax - amin));
      if (sgn(overlap) < 0) overlap = 0;  // separated along this axis (not for intersecting input)
      const mpq_class d2 = overlap * overlap / len2;
      if (!best || d2 < *best) best = d2;
    }
  };
  axis_of(a);
  axis_of(b);
  return best ? *best : mpq_class(0);
}

}  // namespace internal

/// \brief Signed distance from p to conv(points), exactly: +distance outside,
/// 0 on the boundary, -(distance to the boundary) inside. The hull is
/// computed exactly (relgeo::exact_hull); a hull of 1 or 2 points has no
/// inside.
/// \throws Invalid_input for an empty point set.
inline Signed_distance signed_distance_to_hull(std::span<const Point_2<double>> points,
                                               const Point_2<double>& p) {
  if (points.empty()) throw Invalid_input("signed_distance_to_hull: empty point set");
  const std::vector<Point_2<double>> h = exact_hull(points);
  Signed_distance r;
  switch (locate(h, p)) {
    case Polygon_side::outside: {
      r.side = 1;
      std::vector<std::pair<Point_2<double>, Point_2<double>>> edges;
      for (std::size_t i = 0; i < h.size(); ++i) edges.emplace_back(h[i], h[(i + 1) % h.size()]);
      const Point_2<double> pp[1] = {p};
      r.squared = internal::min_squared_distance(p, edges, std::max(coordinate_bound(h), coordinate_bound(pp)));
      return r;
    }
    case Polygon_side::boundary:
      r.side = 0;
      return r;
    case Polygon_side::inside: break;
  }
  r.side = -1;
  std::optional<mpq_class> best;
  for (std::size_t i = 0; i < h.size(); ++i) {  // h.size() >= 3 here
    const Point_2<double>& a = h[i];
    const Point_2<double>& b = h[(i + 1) % h.size()];
    const mpq_class dx = mpq_class(b.x) - a.x, dy = mpq_class(b.y) - a.y;
    const mpq_class wx = mpq_class(p.x) - a.x, wy = mpq_class(p.y) - a.y;
    const mpq_class cross = dx * wy - dy * wx;
    const mpq_class d2 = cross * cross / (dx * dx + dy * dy);
    if (!best || d2 < *best) best = d2;
  }
  r.squared = *best;
  return r;
}

/// True when conv(a) and conv(b) share a point (exact: a vertex of one in the
/// other, or two edges crossing properly — complete for convex polygons,
/// segments and points).
inline bool hulls_intersect(std::span<const Point_2<double>> a_hull, std::span<const Point_2<double>> b_hull) {
  for (const auto& v : a_hull)
    if (locate(b_hull, v) != Polygon_side::outside) return true;
  for (const auto& v : b_hull)
    if (locate(a_hull, v) != Polygon_side::outside) return true;
  if (a_hull.size() < 2 || b_hull.size() < 2) return false;
  for (std::size_t i = 0; i < a_hull.size(); ++i)
    for (std::size_t j = 0; j < b_hull.size(); ++j)
      if (internal::segments_cross_properly(a_hull[i], a_hull[(i + 1) % a_hull.size()], b_hull[j],
                                            b_hull[(j + 1) % b_hull.size()]))
        return true;
  return false;
}

inline Signed_distance separation_of_hulls(std::span<const Point_2<double>> ha, std::span<const Point_2<double>> hb);

/// \brief The signed separation of conv(a) and conv(b), exactly: the distance
/// between them when disjoint; when they intersect, minus the penetration
/// depth, i.e. the length of the shortest translation that separates them
/// (0 when they merely touch; positive also for two crossing segments, which
/// have no interior but cannot be separated by an arbitrarily small move).
/// \throws Invalid_input for an empty point set.
/// Complexity: O(h_a h_b) exact operations on the hull sizes.

inline Signed_distance hull_separation(std::span<const Point_2<double>> a, std::span<const Point_2<double>> b) {
  if (a.empty() || b.empty()) throw Invalid_input("hull_separation: empty point set");
  return separation_of_hulls(exact_hull(a), exact_hull(b));
}

/// hull_separation for hulls already in relgeo::exact_hull's form (strictly
/// convex, counterclockwise; 1 or 2 vertices for degenerate ones), e.g. to
/// compute the hull of each set once and compare many pairs.
/// \pre both non-empty and in that form (not checked).
inline Signed_distance separation_of_hulls(std::span<const Point_2<double>> ha, std::span<const Point_2<double>> hb) {
  Signed_distance r;
  // Disjoint bounding boxes (exact comparisons of doubles): no intersection test needed.
  auto box = [](std::span<const Point_2<double>> h) {
    std::array<double, 4> bx{h[0].x, h[0].y, h[0].x, h[0].y};
    for (const auto& p : h)
      bx[0] = std::min(bx[0], p.x), bx[1] = std::min(bx[1], p.y), bx[2] = std::max(bx[2], p.x), bx[3] = std::max(bx[3], p.y);
    return bx;
  };
  const auto ba = box(ha), bb = box(hb);
  const bool boxes_apart = ba[2] < bb[0] || bb[2] < ba[0] || ba[3] < bb[1] || bb[3] < ba[1];
  if (!boxes_apart && hulls_intersect(ha, hb)) {
    r.squared = internal::squared_penetration_depth(ha, hb);
    r.side = sgn(r.squared) > 0 ? -1 : 0;
    return r;
  }
  // The distance between disjoint convex polygons is attained between a
  // vertex of one and an edge (or vertex) of the other.
  const double C = std::max(coordinate_bound(ha), coordinate_bound(hb));
  std::optional<mpq_class> best;
  auto vertex_to_edges = [&](std::span<const Point_2<double>> p, std::span<const Point_2<double>> poly) {
    std::vector<std::pair<Point_2<double>, Point_2<double>>> edges;
    for (std::size_t i = 0; i < poly.size(); ++i) edges.emplace_back(poly[i], poly[(i + 1) % poly.size()]);
    for (const auto& v : p) {
      mpq_class d2 = internal::min_squared_distance(v, edges, C);
      if (!best || d2 < *best) best = std::move(d2);
    }
  };
  vertex_to_edges(ha, hb);
  vertex_to_edges(hb, ha);
  r.side = 1;
  r.squared = *best;
  return r;
}

}  // namespace relgeo
