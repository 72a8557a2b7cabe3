// test/support/soundness_data.h — the large predicate input sets of the
// soundness suites, built once per test binary, with their exact signs.
//
// Sizes (scale 1): orientation_2 1.0e6 cases (4 workloads x 201000 plus the
// three 256x256 Kettner grids), orientation_3 1.0e6, coplanar orientation
// 1.0e6, compare_xy 1.0e6. The environment variable RELGEO_TEST_SCALE (e.g.
// 0.05 in sanitizer builds) scales the workloads; the grids are always full.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "relgeo/analysis/predicate_workloads.h"
#include "relgeo/core/certified_sign.h"

namespace relgeo::test {

template <class Case>
struct Labelled_cases {
  std::vector<std::string> family;   // one entry per family
  std::vector<std::size_t> begin;    // family f covers [begin[f], begin[f+1])
  std::vector<Case> cases;
  std::vector<Certified_sign> exact;
};

struct Coplanar_case {
  std::array<double, 9> c;  // p q r
};
struct Compare_case {
  double x1, y1, x2, y2;
};

/// How input coordinates reach a kernel: as doubles, or first rounded to float
/// (for the float kernels, so the oracle sees the same coordinates they do).
enum class Input_precision { binary64, binary32 };

struct Soundness_data {
  Labelled_cases<analysis::Orientation_2_case> orientation_2;
  Labelled_cases<analysis::Orientation_3_case> orientation_3;
  Labelled_cases<Coplanar_case> coplanar;
  Labelled_cases<Compare_case> compare_xy;
};

/// The shared data for inputs of the given precision (built on first use).
const Soundness_data& soundness_data(Input_precision precision);

/// RELGEO_TEST_SCALE, default 1.
double test_scale();

}  // namespace relgeo::test
