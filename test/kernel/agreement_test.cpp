// Differential tests between kernels on the same literal inputs (STYLE rule 13):
// where the arithmetic is the same the answers must agree bit for bit; where a
// kernel is known to fail (Kettner's grids) the failure must be reproduced.
#include <CGAL/Simple_cartesian.h>
#include <gtest/gtest.h>

#include "relgeo/analysis/orientation_grid.h"
#include "relgeo/kernel.h"
#include "relgeo/kernel/cgal_kernel.h"
#include "support/exact_oracle.h"
#include "support/soundness_data.h"

namespace relgeo {
namespace {

using test::Input_precision;
using test::soundness_data;

TEST(Agreement, NaiveDoubleIsBitForBitCgalSimpleCartesian) {
  // Same expression, same rounding (-ffp-contract=off): same sign everywhere,
  // including the wrong ones.
  using SC = CGAL::Simple_cartesian<double>;
  const auto& d = soundness_data(Input_precision::binary64);
  const Naive_kernel<double> naive;
  std::size_t differ = 0;
  for (const auto& c : d.orientation_2.cases) {
    const auto ours = analysis::orientation_2_of(c, naive);
    const auto cgal = CGAL::orientation(SC::Point_2(c.px, c.py), SC::Point_2(c.qx, c.qy), SC::Point_2(c.rx, c.ry));
    differ += static_cast<int>(ours) != static_cast<int>(cgal);
  }
  for (const auto& c : d.orientation_3.cases) {
    const auto& v = c.c;
    const auto ours = analysis::orientation_3_of(c, naive);
    const auto cgal = CGAL::orientation(SC::Point_3(v[0], v[1], v[2]), SC::Point_3(v[3], v[4], v[5]),
                                        SC::Point_3(v[6], v[7], v[8]), SC::Point_3(v[9], v[10], v[11]));
    differ += static_cast<int>(ours) != static_cast<int>(cgal);
  }
  EXPECT_EQ(differ, 0u);
}

TEST(Agreement, Mpfr53IsNaiveDoubleAwayFromUnderflowAndOverflow) {
  // MPFR with 53 bits rounds like binary64; only its wider exponent range differs.
  const auto& d = soundness_data(Input_precision::binary64);
  const Naive_kernel<double> naive;
  const Mpfr_kernel<53> mpfr;
  std::size_t compared = 0, differ = 0;
  for (std::size_t f = 0; f < d.orientation_2.family.size(); ++f) {
    if (d.orientation_2.family[f] == "extreme-magnitudes") continue;
    for (std::size_t i = d.orientation_2.begin[f]; i < d.orientation_2.begin[f + 1]; i += 7) {
      const auto& c = d.orientation_2.cases[i];
      differ += analysis::orientation_2_of(c, naive) != analysis::orientation_2_of(c, mpfr);
      ++compared;
    }
  }
  EXPECT_GT(compared, d.orientation_2.cases.size() / 20);  // every 7th case of 5 of 7 families
  EXPECT_EQ(differ, 0u);
}

TEST(Agreement, NaiveDoubleReproducesKettnersGridFailures) {
  // Kettner et al., Figs. 2-4: on every grid naive double gives wrong signs of
  // all three kinds. The expected tally is computed here without relgeo's
  // kernels: CGAL's Simple_cartesian<double> evaluates the same expression
  // (bit for bit, test above) and the mpq oracle of test/support gives the
  // exact sign (relgeo's grid evaluation takes its exact signs from
  // Exact_kernel: they must agree with the oracle too).
  using SC = CGAL::Simple_cartesian<double>;
  for (const auto& triple : analysis::kettner_grid_triples()) {
    const auto r = analysis::evaluate_orientation_grid<Naive_kernel<double>>(triple);
    const auto cases = analysis::grid_cases(triple);
    ASSERT_EQ(r.exact.size(), cases.size());
    analysis::Sign_tally expected;
    std::size_t exact_differs = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const auto& c = cases[i];
      const Certified_sign exact = test::oracle_orientation_2(c);
      exact_differs += r.exact[i] != exact;
      const int cgal = CGAL::orientation(SC::Point_2(c.px, c.py), SC::Point_2(c.qx, c.qy), SC::Point_2(c.rx, c.ry));
      expected.add(exact, sign_of(cgal));
    }
    EXPECT_EQ(exact_differs, 0u) << "grid " << triple.name;
    EXPECT_EQ(r.tally.wrong(), expected.wrong()) << "grid " << triple.name;
    EXPECT_EQ(r.tally.inversions, expected.inversions) << "grid " << triple.name;
    EXPECT_EQ(r.tally.plus_to_zero, expected.plus_to_zero) << "grid " << triple.name;
    EXPECT_EQ(r.tally.minus_to_zero, expected.minus_to_zero) << "grid " << triple.name;
    EXPECT_EQ(r.tally.zero_to_sign, expected.zero_to_sign) << "grid " << triple.name;
    // The grids are hard: 16-30% of the cells are wrong (measured), with
    // inversions and both kinds of false zero; at least 10% must be.
    EXPECT_GE(r.tally.wrong(), cases.size() / 10) << "grid " << triple.name;
    EXPECT_GT(r.tally.inversions, 0u);
    EXPECT_GT(r.tally.plus_to_zero, 0u);
    EXPECT_GT(r.tally.minus_to_zero, 0u);
    const auto f = analysis::evaluate_orientation_grid<Filtered_exact_kernel>(triple);
    EXPECT_EQ(f.tally.wrong() + f.tally.uncertain, 0u);
    const auto l = analysis::evaluate_orientation_grid<Naive_kernel<long double>>(triple);
    EXPECT_EQ(l.tally.wrong(), 0u) << "64-bit significands resolve the double grid";
  }
}

}  // namespace
}  // namespace relgeo
