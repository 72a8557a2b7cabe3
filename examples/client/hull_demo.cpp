// Fortune's stable Graham scan on near-degenerate input, as a client uses it:
// 2000 points on a segment, each coordinate moved by a few ulps (so the
// segment is a ragged hull edge), above a cloud of 20000 points. The
// fail-safe kernel drops what it cannot decide; the certificate says how far
// the input must move for the output to be its exact hull, and that stays
// within the a-priori bound. Exact predicates give the exact hull, with or
// without the interior prefilter.
#include <relgeo/error.h>
#include <relgeo/hull.h>
#include <relgeo/kernel.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

int main() {
  using P = relgeo::Point_2<double>;
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> unit(0, 1);
  const P a{0.5, 0.5}, b{24.25, 17.3};
  std::vector<P> points;
  for (int i = 0; i < 2000; ++i) {  // on segment ab, moved by up to 4 ulps
    const double t = unit(random);
    auto moved = [&](double v) {
      for (int k = static_cast<int>(random() % 9) - 4; k != 0; k += k > 0 ? -1 : 1)
        v = std::nextafter(v, k > 0 ? INFINITY : -INFINITY);
      return v;
    };
    points.push_back({moved(a.x + t * (b.x - a.x)), moved(a.y + t * (b.y - a.y))});
  }
  while (points.size() < 22000) {  // a cloud clearly below the segment
    const P p{a.x + unit(random) * (b.x - a.x), a.y + unit(random) * (b.y - a.y)};
    if (p.y < a.y + (p.x - a.x) * (b.y - a.y) / (b.x - a.x) - 0.5) points.push_back(p);
  }

  const auto fortune = relgeo::graham_fortune<relgeo::Failsafe_kernel<double>>(points);
  const double certificate = relgeo::hull_backward_error(points, fortune.indices).value;
  const std::optional<double> bound =
      relgeo::graham_fortune_backward_error_bound<relgeo::Failsafe_kernel<double>>(points);
  std::printf("graham_fortune, failsafe<double>: %zu vertices, %zu of %zu tests undecided\n",
              fortune.indices.size(), fortune.uncertain_answers, fortune.predicate_calls);
  std::printf("  backward error %.3g <= a-priori bound %.3g\n", certificate, bound.value_or(NAN));

  const auto exact = relgeo::graham_fortune<relgeo::Filtered_exact_kernel>(points);
  const auto exact_all = relgeo::graham_fortune<relgeo::Filtered_exact_kernel>(
      points, {}, relgeo::Hull_options{.discard_interior = false});
  std::printf("graham_fortune, filtered: %zu vertices (the exact hull; every point scanned: %zu)\n",
              exact.indices.size(), exact_all.indices.size());

  const bool ok = bound && certificate <= *bound && exact.indices == exact_all.indices &&
                  relgeo::hull_error(points, exact.indices).value == 0;
  return ok ? 0 : 1;
}
