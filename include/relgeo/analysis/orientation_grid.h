// relgeo/analysis/orientation_grid.h — Kettner et al.'s orientation grids:
// orientation(p(X,Y), q, r) on a size x size grid of points one ulp apart,
// under a kernel, against the exact sign (SPEC Sec. 3.1, `relgeo orient-grid`).
#pragma once

#include <string>
#include <vector>

#include "relgeo/analysis/predicate_workloads.h"
#include "relgeo/analysis/sign_tally.h"
#include "relgeo/core/errors.h"
#include "relgeo/kernel/concepts.h"

namespace relgeo::analysis {

struct Orientation_grid_result {
  std::string kernel;
  Orientation_grid_triple triple;
  int size = 0;
  std::vector<Certified_sign> answers;  ///< row-major, row = Y
  std::vector<Certified_sign> exact;
  Sign_tally tally;
};

/// Evaluates the grid of `triple` under kernel k. \pre 1 <= size <= 4096 and
/// the coordinates of the triple are finite (Invalid_input otherwise).
template <OrientationKernel_2 K>
Orientation_grid_result evaluate_orientation_grid(const Orientation_grid_triple& triple,
                                                  int size = 256, const K& k = K{}) {
  if (size < 1 || size > 4096) throw Invalid_input("orientation grid: size must be in [1, 4096]");
  for (double v : {triple.px, triple.py, triple.qx, triple.qy, triple.rx, triple.ry})
    if (!std::isfinite(v)) throw Non_finite_input("orientation grid: coordinate is NaN or infinite");
  Orientation_grid_result r{K::name(), triple, size, {}, {}, {}};
  const std::vector<Orientation_2_case> cases = grid_cases(triple, size);
  r.exact = exact_signs<Orientation_2_case>(cases);
  r.answers.reserve(cases.size());
  for (const auto& c : cases) r.answers.push_back(orientation_2_of(c, k));
  for (std::size_t i = 0; i < cases.size(); ++i) r.tally.add(r.exact[i], r.answers[i]);
  return r;
}

}  // namespace relgeo::analysis
