// test/support/implicit_oracle.h — exact signs of predicates on implicit
// points, computed independently of relgeo's implicit-point code: the exact
// point is found by Gaussian elimination in GMP rationals (not relgeo's
// homogeneous formulas) and kept over one common denominator, and the
// predicates are evaluated on it with the formulas of exact_oracle.cpp
// (triple product, expanded 2D orientation) in GMP integers.
#pragma once

#include <gmpxx.h>

#include <array>
#include <optional>

#include "relgeo/analysis/implicit_workloads.h"
#include "relgeo/core/certified_sign.h"

namespace relgeo::test {

/// An exact point (x, y, z) = (X, Y, Z) / W with integers and W > 0. One
/// denominator for the three coordinates: the predicates then compute in
/// integers, without the gcd that every rational operation pays (the
/// oracle's time was mostly GMP's gcd).
struct Exact_point {
  std::array<mpz_class, 3> numerators;  // X, Y, Z
  mpz_class denominator;                // W > 0
  /// The coordinate `axis` as a rational (canonical).
  mpq_class coordinate(int axis) const;
};

/// The exact point, or nullopt when it does not exist (line parallel to the
/// plane, dependent planes).
std::optional<Exact_point> oracle_point(const analysis::Implicit_point_definition& d);

Certified_sign oracle_orientation_3(const Exact_point& a, const Exact_point& b, const Exact_point& c,
                                    const Exact_point& d);
/// Orientation of the projections dropping `axis` (kept axes (axis+1)%3, (axis+2)%3).
Certified_sign oracle_orientation_2(const Exact_point& a, const Exact_point& b, const Exact_point& c, int axis);
/// Lexicographic comparison of (x, y, z).
Certified_sign oracle_compare_xyz(const Exact_point& a, const Exact_point& b);

}  // namespace relgeo::test
