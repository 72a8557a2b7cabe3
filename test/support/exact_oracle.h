// test/support/exact_oracle.h — exact signs computed independently of relgeo's
// kernels: GMP rationals and *different* formulas (expanded products, a triple
// product), so an error in relgeo's determinant code cannot hide in the oracle.
#pragma once

#include <gmpxx.h>

#include <array>

#include "relgeo/analysis/predicate_workloads.h"
#include "relgeo/core/certified_sign.h"
#include "relgeo/core/interval.h"

namespace relgeo::test {

Certified_sign oracle_orientation_2(const analysis::Orientation_2_case& c);
Certified_sign oracle_orientation_3(const analysis::Orientation_3_case& c);
/// CGAL's 3-argument coplanar orientation of (p, q, r) (first non-degenerate
/// projection xy, yz, xz), exactly.
Certified_sign oracle_coplanar_orientation_3(const std::array<double, 9>& pqr);
/// Lexicographic comparison of (x1, y1) and (x2, y2), exactly.
Certified_sign oracle_compare_xy(double x1, double y1, double x2, double y2);
/// Whether interval i contains v (an infinite end bounds everything on its
/// side; a NaN end claims nothing, so it passes).
bool encloses(const Interval& i, const mpq_class& v);

}  // namespace relgeo::test
