// relgeo/analysis/implicit_workloads.h — families of predicate inputs on
// implicit (LPI and TPI) points, from random to exactly degenerate, shared by
// the soundness tests, the benchmarks and the experiment.
//
// A workload is a pool of point definitions (explicit points and the
// doubles that define LPI and TPI points) and predicate cases that index
// into it, so each kernel builds each point once. Deterministic for a seed.
// The degenerate families are built with exact double arithmetic (small
// integers times powers of two), so their zeros are exact zeros:
//  * random          uniform coordinates in [-1, 1];
//  * on-plane        an LPI point against its own plane and line (exact zeros), the
//                    same with one defining coordinate moved by a few ulps, and
//                    against the double nearest to it (compare: a few ulps apart);
//  * same-point      one crossing of two lines reached as different LPIs, and the
//                    crossing point itself (compare: zero);
//  * collinear       LPIs of lines of one plane with another plane: collinear points
//                    (orientation_2 zero in every projection, orientation_3 zero);
//  * near-parallel   lines almost parallel to the plane (tiny W, far points);
//  * tpi-point       three planes through one input point, and planes through points
//                    a few ulps from it;
//  * magnitudes      the random family scaled by 2^-700, 2^-300, 2^300, 2^600;
//  * subnormal       coordinates that are subnormal doubles of either sign
//                    (small multiples of 2^-1074 .. 2^-1040) or dyadics near 1,
//                    mixed in one point: differences of opposite subnormals,
//                    which denormals-are-zero reads as 0 (a DAZ finding).
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "relgeo/analysis/predicate_workloads.h"
#include "relgeo/core/dyadic.h"
#include "relgeo/core/rounding.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/implicit_point.h"

namespace relgeo::analysis {

/// How a point of a workload is defined: its kind and 1, 5 or 9 points.
struct Implicit_point_definition {
  Implicit_point_kind kind = Implicit_point_kind::explicit_point;
  std::array<std::array<double, 3>, 9> points{};
};

/// The point a definition describes, built by kernel K (empty when K
/// refuses it: the point does not exist, or K cannot certify that it does).
template <IntersectionKernel_3 K>
std::optional<typename K::Implicit_point_3> build_implicit_point(const K& k, const Implicit_point_definition& d) {
  const auto point = k.construct_point_3_object();
  const auto make = k.construct_implicit_point_3_object();
  const auto e = [&](int j) { return point(d.points[j][0], d.points[j][1], d.points[j][2]); };
  switch (d.kind) {
    case Implicit_point_kind::explicit_point: return make(e(0));
    case Implicit_point_kind::lpi: return make(e(0), e(1), e(2), e(3), e(4));
    default: return make(e(0), e(1), e(2), e(3), e(4), e(5), e(6), e(7), e(8));
  }
}

struct Implicit_orientation_3_case {
  std::array<std::uint32_t, 4> p;
};
struct Implicit_orientation_2_case {
  std::array<std::uint32_t, 3> p;
  int dropped_axis;
};
struct Implicit_compare_case {
  std::array<std::uint32_t, 2> p;
};

struct Implicit_workload {
  std::string name;
  std::vector<Implicit_point_definition> points;
  std::vector<Implicit_orientation_3_case> orientation_3;
  std::vector<Implicit_orientation_2_case> orientation_2;
  std::vector<Implicit_compare_case> compare;
};

namespace internal_workloads {

using Vec = std::array<double, 3>;

class Implicit_builder {
 public:
  Implicit_builder(std::string name, std::uint64_t seed) : rng_(seed) { w_.name = std::move(name); }

  std::uint32_t add_explicit(const Vec& p) {
    Implicit_point_definition d;
    d.points[0] = p;
    return add(d);
  }
  std::uint32_t add_lpi(const Vec& p, const Vec& q, const Vec& r, const Vec& s, const Vec& t) {
    Implicit_point_definition d{Implicit_point_kind::lpi, {p, q, r, s, t}};
    return add(d);
  }
  std::uint32_t add_tpi(const std::array<Vec, 9>& v) {
    Implicit_point_definition d{Implicit_point_kind::tpi, {}};
    for (int i = 0; i < 9; ++i) d.points[i] = v[i];
    return add(d);
  }
  void orientation_3(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    w_.orientation_3.push_back({{a, b, c, d}});
  }
  void orientation_2(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    w_.orientation_2.push_back({{a, b, c}, small_int(rng_, 0, 2)});
  }
  void compare(std::uint32_t a, std::uint32_t b) { w_.compare.push_back({{a, b}}); }

  std::mt19937_64& rng() { return rng_; }
  Vec random_point(double scale = 1) {
    return {scale * uniform(rng_, -1, 1), scale * uniform(rng_, -1, 1), scale * uniform(rng_, -1, 1)};
  }
  /// A dyadic point: integers below 2^bits times 2^-bits (exact sums of a few).
  Vec dyadic_point(int bits) {
    const auto c = [&] {
      return std::ldexp(static_cast<double>(static_cast<std::int64_t>(rng_() >> (64 - bits)) -
                                            (std::int64_t{1} << (bits - 1))),
                        -bits);
    };
    return {c(), c(), c()};
  }
  Vec small_vector() {
    Vec v;
    do v = {double(small_int(rng_, -7, 7)), double(small_int(rng_, -7, 7)), double(small_int(rng_, -7, 7))};
    while (v[0] == 0 && v[1] == 0 && v[2] == 0);
    return v;
  }
  std::uint32_t random_index() { return static_cast<std::uint32_t>(rng_() % w_.points.size()); }
  std::size_t cases() const { return w_.orientation_3.size() + w_.orientation_2.size() + w_.compare.size(); }
  Implicit_workload take() { return std::move(w_); }

 private:
  std::uint32_t add(const Implicit_point_definition& d) {
    w_.points.push_back(d);
    return static_cast<std::uint32_t>(w_.points.size() - 1);
  }
  std::mt19937_64 rng_;
  Implicit_workload w_;
};

inline Vec plus(const Vec& a, const Vec& b, double k = 1) { return {a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]}; }
inline Vec moved(Vec v, int axis, int ulps) {
  v[axis] = moved_by_ulps(v[axis], ulps);
  return v;
}
inline int nonzero_ulps(std::mt19937_64& g) {
  const int k = small_int(g, 1, 4);
  return (g() & 1) ? k : -k;
}

/// The double nearest to each coordinate of LPI(p, q; r, s, t), computed
/// exactly (for the near-miss comparisons; not an oracle).
inline Vec nearest_lpi(const Vec& p, const Vec& q, const Vec& r, const Vec& s, const Vec& t) {
  std::array<mpq_class, 3> P, A, E1, E2, RP;
  for (int i = 0; i < 3; ++i) {
    P[i] = exact_rational(p[i]);
    A[i] = exact_rational(q[i]) - P[i];
    E1[i] = exact_rational(s[i]) - exact_rational(r[i]);
    E2[i] = exact_rational(t[i]) - exact_rational(r[i]);
    RP[i] = exact_rational(r[i]) - P[i];
  }
  const std::array<mpq_class, 3> n{E1[1] * E2[2] - E1[2] * E2[1], E1[2] * E2[0] - E1[0] * E2[2],
                                   E1[0] * E2[1] - E1[1] * E2[0]};
  const mpq_class w = n[0] * A[0] + n[1] * A[1] + n[2] * A[2];
  const mpq_class lambda = (n[0] * RP[0] + n[1] * RP[1] + n[2] * RP[2]) / w;
  Vec out;
  for (int i = 0; i < 3; ++i) out[i] = round_rational<double>(mpq_class(P[i] + lambda * A[i]));
  return out;
}

// ---- the families (file comment) ----------------------------------------------
/// A pool of `points` random points (explicit, LPI, TPI in turn, each from
/// `point()`), then random cases on it until there are `cases`.
template <class Point>
void add_random_pool_and_cases(Implicit_builder& b, std::size_t points, std::size_t cases, Point&& point) {
  for (std::size_t i = 0; i < points; ++i) {
    switch (i % 3) {
      case 0: b.add_explicit(point()); break;
      case 1: b.add_lpi(point(), point(), point(), point(), point()); break;
      default: {
        std::array<Vec, 9> v;
        for (auto& x : v) x = point();
        b.add_tpi(v);
      }
    }
  }
  while (b.cases() < cases) {
    b.orientation_3(b.random_index(), b.random_index(), b.random_index(), b.random_index());
    b.orientation_2(b.random_index(), b.random_index(), b.random_index());
    b.compare(b.random_index(), b.random_index());
  }
}

inline Implicit_workload random_family(const std::string& name, double scale, std::uint64_t seed, std::size_t cases) {
  Implicit_builder b(name, seed);
  add_random_pool_and_cases(b, std::max<std::size_t>(64, cases / 8), cases, [&] { return b.random_point(scale); });
  return b.take();
}

inline Implicit_workload on_plane_family(std::size_t cases, std::uint64_t seed) {
  Implicit_builder b("on-plane", seed);
  while (b.cases() < cases) {
    const Vec p = b.random_point(), q = b.random_point(), r = b.random_point(), s = b.random_point(),
              t = b.random_point(), c = b.random_point();
    const std::uint32_t L = b.add_lpi(p, q, r, s, t);
    const std::uint32_t P = b.add_explicit(p), Q = b.add_explicit(q), R = b.add_explicit(r),
                        S = b.add_explicit(s), T = b.add_explicit(t), C = b.add_explicit(c);
    const int k = nonzero_ulps(b.rng());
    const std::uint32_t R2 = b.add_explicit(moved(r, small_int(b.rng(), 0, 2), k));
    const std::uint32_t P2 = b.add_explicit(moved(p, small_int(b.rng(), 0, 2), k));
    const std::uint32_t N = b.add_explicit(nearest_lpi(p, q, r, s, t));
    b.orientation_3(R, S, T, L);   // zero: on its plane
    b.orientation_3(L, R, S, T);   // zero, the implicit point first
    b.orientation_3(P, Q, C, L);   // zero: on its line
    b.orientation_3(R2, S, T, L);  // a few ulps off
    b.orientation_3(P2, Q, C, L);
    b.orientation_2(P, Q, L);  // zero: collinear in every projection
    b.orientation_2(L, P2, Q);
    b.compare(L, N);  // a few ulps apart, or equal
    b.compare(L, P);
  }
  return b.take();
}

/// Lines pq and rs cross exactly at X.
inline Implicit_workload same_point_family(std::size_t cases, std::uint64_t seed) {
  Implicit_builder b("same-point", seed);
  while (b.cases() < cases) {
    const Vec X = b.dyadic_point(40);
    const Vec d1 = b.small_vector(), d2 = b.small_vector();
    if (d1[0] * d2[1] == d1[1] * d2[0] && d1[1] * d2[2] == d1[2] * d2[1] && d1[0] * d2[2] == d1[2] * d2[0])
      continue;  // parallel directions
    const double a = small_int(b.rng(), 1, 5), c = small_int(b.rng(), 1, 5);
    const Vec p = plus(X, d1, -a), q = plus(X, d1, c), r = plus(X, d2, -c), s = plus(X, d2, a);
    const Vec t = b.random_point(), t2 = b.random_point(), u = b.random_point();
    const std::uint32_t L1 = b.add_lpi(p, q, r, s, t), L2 = b.add_lpi(p, q, r, s, t2),
                        L3 = b.add_lpi(r, s, p, q, u);
    const std::uint32_t XP = b.add_explicit(X), P = b.add_explicit(p), Q = b.add_explicit(q),
                        R = b.add_explicit(r), U = b.add_explicit(u);
    b.compare(L1, L2);
    b.compare(L1, L3);
    b.compare(L3, XP);
    b.orientation_3(P, Q, R, L3);  // zero: X lies in the plane of the two lines
    b.orientation_3(L1, L2, P, U);  // zero: two equal points
    b.orientation_3(P, R, U, L1);   // X, p, r span the plane of the lines: nonzero in general
    b.orientation_2(L1, P, R);  // X, p, r: a triangle of the crossing lines (nonzero unless degenerate)
    b.orientation_2(L2, L3, P);  // zero: two equal points
  }
  return b.take();
}

/// Lines of the plane ABC crossing the plane rst.
inline Implicit_workload collinear_family(std::size_t cases, std::uint64_t seed) {
  Implicit_builder b("collinear", seed);
  while (b.cases() < cases) {
    const Vec A = b.dyadic_point(30), B = plus(A, b.small_vector()), C = plus(A, b.small_vector());
    const Vec r = b.random_point(), s = b.random_point(), t = b.random_point();
    std::array<std::uint32_t, 3> L{};
    for (auto& l : L) {
      const double a1 = small_int(b.rng(), -3, 3), b1 = small_int(b.rng(), -3, 3);
      const double a2 = small_int(b.rng(), -3, 3), b2 = small_int(b.rng(), -3, 3);
      const Vec p = plus(plus(A, plus(B, A, -1), a1), plus(C, A, -1), b1);
      const Vec q = plus(plus(A, plus(B, A, -1), a2), plus(C, A, -1), b2);
      l = b.add_lpi(p, q, r, s, t);
    }
    const std::uint32_t PA = b.add_explicit(A), PB = b.add_explicit(B), PR = b.add_explicit(r);
    b.orientation_2(L[0], L[1], L[2]);
    b.orientation_3(L[0], L[1], L[2], PR);  // zero: collinear
    b.orientation_3(L[0], L[1], PA, PB);    // zero: all in plane ABC
    b.compare(L[0], L[1]);
  }
  return b.take();
}

inline Implicit_workload near_parallel_family(std::size_t cases, std::uint64_t seed) {
  Implicit_builder b("near-parallel", seed);
  while (b.cases() < cases) {
    const Vec r = b.random_point(), s = b.random_point(), t = b.random_point(), p = b.random_point();
    const Vec q = moved(plus(p, plus(s, r, -1)), small_int(b.rng(), 0, 2), nonzero_ulps(b.rng()));
    const std::uint32_t L = b.add_lpi(p, q, r, s, t);
    const std::uint32_t P = b.add_explicit(p), Q = b.add_explicit(q), R = b.add_explicit(r),
                        S = b.add_explicit(s), T = b.add_explicit(t), C = b.add_explicit(b.random_point());
    b.orientation_3(R, S, T, L);
    b.orientation_3(P, Q, C, L);
    b.orientation_3(R, S, C, L);
    b.orientation_2(P, Q, L);
    b.compare(L, C);
  }
  return b.take();
}

/// Three planes through one point a (or a few ulps from it).
inline Implicit_workload tpi_point_family(std::size_t cases, std::uint64_t seed) {
  Implicit_builder b("tpi-point", seed);
  while (b.cases() < cases) {
    const Vec a = b.random_point();
    std::array<Vec, 9> v;
    for (int i = 0; i < 3; ++i) v[3 * i] = a, v[3 * i + 1] = b.random_point(), v[3 * i + 2] = b.random_point();
    const std::uint32_t T = b.add_tpi(v);
    std::array<Vec, 9> w = v;
    w[6] = moved(a, small_int(b.rng(), 0, 2), nonzero_ulps(b.rng()));
    const std::uint32_t T2 = b.add_tpi(w);
    const std::uint32_t A = b.add_explicit(a), B = b.add_explicit(v[1]), C = b.add_explicit(v[2]),
                        D = b.add_explicit(b.random_point());
    b.compare(T, A);
    b.compare(T2, A);
    b.orientation_3(A, B, C, T);   // zero: T = a
    b.orientation_3(A, B, C, T2);  // a few ulps off the plane, or on it
    b.orientation_3(B, C, D, T);
    b.orientation_2(T, B, A);  // zero: T = a
  }
  return b.take();
}

/// Points on axis-aligned planes and lines (the faces and edges of CAD
/// parts), where coordinates agree exactly: line pq (random) meets two
/// different planes axis = c, so L1 and L3 are one point from two
/// constructions; line p2q2 shares coordinate `axis` (c, c a few ulps off,
/// or -c when c = 0) and, in half the cases, a second one; T has one plane
/// axis = c. c is a random coordinate, a subnormal (distinct subnormals are
/// equal to a caller who set denormals-are-zero) or zero.
inline Implicit_workload axis_aligned_family(std::size_t cases, std::uint64_t seed) {
  Implicit_builder b("axis-aligned", seed);
  std::mt19937_64& g = b.rng();
  while (b.cases() < cases) {
    const int axis = small_int(g, 0, 2), other = (axis + small_int(g, 1, 2)) % 3;
    const int kind = small_int(g, 0, 3);
    const double c = kind == 0   ? std::ldexp(static_cast<double>(small_int(g, 1, 7)), -1074)
                     : kind == 1 ? 0.0
                                 : uniform(g, -1, 1);
    const auto on_plane = [&](double value, int a) {
      Vec v = b.random_point();
      v[a] = value;
      return v;
    };
    const double c2 = kind == 1 && (g() & 1) ? -c : (g() & 1) ? c : moved_by_ulps(c, nonzero_ulps(g));
    const Vec p = b.random_point(), q = b.random_point();
    const Vec r = on_plane(c, axis), s = on_plane(c, axis), t = on_plane(c, axis);
    const Vec r3 = on_plane(c, axis), s3 = on_plane(c, axis), t3 = on_plane(c, axis);
    Vec p2 = on_plane(c2, axis), q2 = on_plane(c2, axis);
    if (g() & 1) q2[other] = p2[other];  // a line parallel to the third axis
    const std::uint32_t L1 = b.add_lpi(p, q, r, s, t), L3 = b.add_lpi(p, q, r3, s3, t3);
    const std::uint32_t L2 = b.add_lpi(p2, q2, b.random_point(), b.random_point(), b.random_point());
    const std::uint32_t L4 = b.add_lpi(p2, q2, b.random_point(), b.random_point(), b.random_point());
    std::array<Vec, 9> planes;
    for (auto& v : planes) v = b.random_point();
    const int aligned = small_int(g, 0, 2);
    for (int i = 0; i < 3; ++i) planes[3 * aligned + i][axis] = c;
    const std::uint32_t T = b.add_tpi(planes);
    Vec near = nearest_lpi(p, q, r, s, t);
    near[axis] = c;
    if (g() & 1) near = moved(near, other, nonzero_ulps(g));
    const std::uint32_t N = b.add_explicit(near), R = b.add_explicit(r), S = b.add_explicit(s), T3 = b.add_explicit(t3),
                        P2 = b.add_explicit(p2);
    // Seven compares and three of each orientation per round, so that every
    // tenth case (the floating-point environment test) meets each kind.
    b.compare(L1, L3);  // zero: one point
    b.compare(L1, L2);  // equal in `axis` when c2 = c
    b.compare(L2, L4);  // equal in `axis` (and `other`): the order along the line
    b.compare(L1, N);   // equal in `axis`, an ulp apart or equal in the others
    b.compare(T, L1);
    b.compare(L2, P2);
    b.compare(L3, L2);
    b.orientation_3(R, S, T3, L1);   // zero: on the plane axis = c
    b.orientation_3(L1, L3, R, S);   // zero: two equal points
    b.orientation_3(L2, L4, P2, N);  // zero: three points of one line
    b.orientation_2(L1, L3, P2);     // zero: two equal points
    b.orientation_2(L2, L4, P2);     // zero: one line
    b.orientation_2(L1, L2, N);
  }
  return b.take();
}

/// Each coordinate a small multiple of a subnormal power of two, or
/// 1 + k 2^-52. An eighth of the cases: exact arithmetic on 2^-1074 scales is
/// about 20x slower than on the others (the oracle, GMP, Epeck).
inline Implicit_workload subnormal_family(std::size_t cases, std::uint64_t seed) {
  Implicit_builder b("subnormal", seed);
  const std::size_t subnormal_cases = std::max<std::size_t>(64, cases / 8);
  const auto coordinate = [&b] {
    std::mt19937_64& g = b.rng();
    if (g() % 3 == 0) return 1.0 + small_int(g, -8, 8) * 0x1p-52;
    return std::ldexp(static_cast<double>(small_int(g, -7, 7)), small_int(g, -1074, -1040));
  };
  add_random_pool_and_cases(b, std::max<std::size_t>(64, subnormal_cases / 8), subnormal_cases,
                            [&] { return Vec{coordinate(), coordinate(), coordinate()}; });
  return b.take();
}

}  // namespace internal_workloads

/// The implicit-point workloads, each with about `cases` predicate cases.
inline std::vector<Implicit_workload> implicit_workloads(std::size_t cases, std::uint64_t seed = 1) {
  using namespace internal_workloads;
  std::vector<Implicit_workload> out;
  out.push_back(random_family("random", 1, seed, cases));
  out.push_back(on_plane_family(cases, seed + 1));
  out.push_back(same_point_family(cases, seed + 2));
  out.push_back(collinear_family(cases, seed + 3));
  out.push_back(near_parallel_family(cases, seed + 4));
  out.push_back(tpi_point_family(cases, seed + 5));
  const int exponents[] = {-700, -300, 300, 600};
  for (int i = 0; i < 4; ++i)
    out.push_back(random_family("magnitudes 2^" + std::to_string(exponents[i]), std::ldexp(1.0, exponents[i]),
                                seed + 10 + i, cases));
  out.push_back(subnormal_family(cases, seed + 20));
  out.push_back(axis_aligned_family(cases / 2, seed + 21));
  return out;
}

}  // namespace relgeo::analysis
