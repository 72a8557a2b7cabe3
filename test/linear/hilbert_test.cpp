// Hilbert matrices (thesis Sec. 3.2): a stable method has a tiny backward
// error and a large forward error (the problem is ill conditioned), and the
// precision needed for a given forward accuracy grows like log2(kappa).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "relgeo/linear.h"
#include "relgeo_fixtures/linear/test_problems.h"

namespace relgeo::test {
namespace {

TEST(Hilbert, SmallBackwardErrorLargeForwardErrorInDouble) {
  const double u = 0x1p-53;
  double previous_kappa = 0;
  std::printf("  n  kappa(stored)   eta(partial)  omega(partial)  forward(partial)  forward(complete)\n");
  for (int n = 2; n <= 14; ++n) {
    const auto s = stored_hilbert_system<double>(n);
    const Linear_reference ref(s.a, s.b);
    ASSERT_TRUE(ref.condition().exact);
    const auto p = measure_solution(ref, gaussian_elimination<double>(s.a, s.b, Pivoting::partial));
    const auto c = measure_solution(ref, gaussian_elimination<double>(s.a, s.b, Pivoting::complete));
    std::printf("%3d  %12.3e  %12.3e  %12.3e  %14.3e  %14.3e\n", n, ref.condition().value,
                p.normwise_backward_error, p.componentwise_backward_error, *p.forward_error, *c.forward_error);
    // Stable: backward error at the level of u, for every n.
    EXPECT_LE(p.normwise_backward_error, 2 * u) << n;
    EXPECT_LE(c.normwise_backward_error, 2 * u) << n;
    EXPECT_LE(p.componentwise_backward_error, 4 * u) << n;
    // Perturbation bound: forward <= 2 kappa eta / (1 - kappa eta) when kappa eta < 1.
    for (const auto* e : {&p, &c}) {
      const double ke = ref.condition().value * e->normwise_backward_error;
      if (ke < 0.5) {
        EXPECT_LE(*e->forward_error, 2 * ke / (1 - ke) * (1 + 1e-9)) << n;
      }
    }
    // Ill conditioning: kappa grows by more than 10x per step up to n = 12.
    if (n <= 12) {
      EXPECT_GT(ref.condition().value, 10 * previous_kappa) << n;
    }
    previous_kappa = ref.condition().value;
    if (n >= 11) {
      EXPECT_GT(*p.forward_error, 1e-4) << "large forward error at n=" << n;
    }
    if (n <= 4) {
      EXPECT_LT(*p.forward_error, 1e-11) << n;
    }
  }
}

// Smallest precision among the sweep that solves the *exact* Hilbert system
// (data correctly rounded to Bits, exact solution ones) to forward error <= target.
template <int Bits>
double forward_error_at(const Linear_reference& ref, const Linear_system<mpq_class>& h) {
  using S = Mpfr_number<Bits>;
  const Dense_vector<S> x =
      gaussian_elimination<S>(from_rational_matrix<S>(h.a), from_rational_vector<S>(h.b), Pivoting::partial);
  return *measure_solution(ref, x).forward_error;
}

template <int... Bits>
int bits_needed(const Linear_reference& ref, const Linear_system<mpq_class>& h, double target,
                std::integer_sequence<int, Bits...>) {
  int found = -1;
  ((found < 0 && forward_error_at<Bits>(ref, h) <= target ? (found = Bits) : 0), ...);
  return found;
}

TEST(Hilbert, PrecisionNeededForAForwardAccuracy) {
  using Sweep = std::integer_sequence<int, 24, 32, 40, 48, 53, 64, 80, 96, 113, 128, 160>;
  const double target = 1e-6;
  int previous = 0;
  for (int n = 2; n <= 14; ++n) {
    const auto h = hilbert_system(n);
    const Linear_reference ref(h.a, h.b);
    const int bits = bits_needed(ref, h, target, Sweep{});
    const double predicted = std::log2(ref.condition().value / target);
    std::printf("n=%2d  kappa=%.3e  log2(kappa/1e-6)=%5.1f  bits needed=%d\n", n, ref.condition().value,
                predicted, bits);
    ASSERT_GT(bits, 0) << "160 bits not enough at n=" << n;
    EXPECT_GE(bits, previous) << "monotone in n";
    // Rule of thumb: forward ~ kappa 2^-bits, so bits ~ log2(kappa / target);
    // the sweep's granularity and the constant allow some slack.
    EXPECT_GE(bits + 8, predicted) << n;
    EXPECT_LE(bits, predicted + 24) << n;
    previous = bits;
  }
  EXPECT_GT(previous, 53) << "n = 14 needs more than double precision";
}

}  // namespace
}  // namespace relgeo::test
