// Fuzz harness: implicit points (LPI, TPI; relgeo/kernel/implicit_point.h)
// and the predicates on them under the certified kernels, against the
// independent exact oracle of test/support/implicit_oracle.h (the point by
// Gaussian elimination in GMP rationals, the predicates in integers over its
// common denominator).
//
// Input: byte 0 the kernel, then a pool of up to 10 explicit points (new
// coordinates, duplicates, points on the line or in the plane of earlier
// ones), then 4 point definitions (kind byte and indices into the pool),
// then the predicate cases (indices into the 4 points, an axis).
//
// Contract (doc/reliability.md, harness implicit_point):
//  * construction: a point that does not exist (line parallel to the plane,
//    dependent planes) is never built by a certified kernel;
//  * every definite answer of orientation_3, orientation_2 (by dropped
//    axis) and compare_xyz is the exact sign; only `uncertain` may differ;
//  * approximate_point_3 is within its stated error of the exact point;
//  * NaN and infinite coordinates give a typed error or `uncertain` (no
//    crash); the naive kernel only has to not crash.
#include <cmath>
#include <optional>

#include "fuzz_support.h"
#include "point_pool.h"
#include "relgeo/kernel.h"
#include "support/implicit_oracle.h"

namespace {

using namespace relgeo;
using namespace relgeo::fuzz;
using Coordinates = std::array<double, 3>;

template <class K>
void check(Input& in, const std::vector<Coordinates>& pool) {
  const K k;
  const std::string who = K::name();
  const auto orient3 = k.implicit_orientation_3_object();
  const auto orient2 = k.implicit_orientation_2_object();
  const auto compare = k.compare_xyz_3_object();
  const auto approximate = k.approximate_point_3_object();
  bool finite = true;
  for (const auto& c : pool) finite = finite && std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]);

  using P = typename K::Implicit_point_3;
  std::vector<std::optional<P>> pts;
  std::vector<std::optional<test::Exact_point>> exact;
  for (int i = 0; i < 4; ++i) {
    analysis::Implicit_point_definition d;
    d.kind = static_cast<Implicit_point_kind>(in.byte() % 3);
    for (auto& p : d.points) p = pool[in.below(pool.size())];
    std::optional<P> p;
    const bool built = typed_errors_only([&] { p = analysis::build_implicit_point(k, d); }, who + " construct");
    if (!built) p.reset();
    std::optional<test::Exact_point> x;
    if (finite) x = test::oracle_point(d);
    if (finite && K::is_certified) require(!p || x, who + ": built a point that does not exist");
    if (p && x && K::is_certified) {
      const Approximate_point_3 a = approximate(*p);
      const double c[3] = {a.point.x, a.point.y, a.point.z};
      for (int j = 0; j < 3; ++j) {
        if (std::isinf(a.error)) break;
        require(std::isfinite(c[j]), who + ": a finite approximation with a finite error");
        const mpq_class diff = abs(mpq_class(c[j]) - x->coordinate(j));
        require(diff <= mpq_class(a.error), who + ": the approximation is within its stated error");
      }
    }
    pts.push_back(std::move(p));
    exact.push_back(std::move(x));
  }
  const auto sound = [&](Certified_sign answer, auto&& oracle, const char* what, std::initializer_list<int> idx) {
    if (!K::is_certified || !finite || answer == Certified_sign::uncertain) return;
    for (int i : idx)
      if (!exact[i]) return;
    require(answer == oracle(), who + ": " + what + " answered wrong");
  };
  for (int cases = 0; cases < 6 && !in.empty(); ++cases) {
    const int a = in.byte() % 4, b = in.byte() % 4, c = in.byte() % 4, d = in.byte() % 4, axis = in.byte() % 3;
    if (!pts[a] || !pts[b] || !pts[c] || !pts[d]) continue;
    Certified_sign s = Certified_sign::uncertain;
    if (typed_errors_only([&] { s = orient3(*pts[a], *pts[b], *pts[c], *pts[d]); }, who + " orientation_3"))
      sound(s, [&] { return test::oracle_orientation_3(*exact[a], *exact[b], *exact[c], *exact[d]); },
            "orientation_3", {a, b, c, d});
    if (typed_errors_only([&] { s = orient2(*pts[a], *pts[b], *pts[c], axis); }, who + " orientation_2"))
      sound(s, [&] { return test::oracle_orientation_2(*exact[a], *exact[b], *exact[c], axis); }, "orientation_2",
            {a, b, c});
    if (typed_errors_only([&] { s = compare(*pts[a], *pts[b]); }, who + " compare_xyz"))
      sound(s, [&] { return test::oracle_compare_xyz(*exact[a], *exact[b]); }, "compare_xyz", {a, b});
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input in(data, size);
  const int kernel = in.byte() % 6;
  const auto pool = decode_point_pool(in, 10);
  switch (kernel) {
    case 0: check<Failsafe_kernel<double>>(in, pool); break;
    case 1: check<Failsafe_kernel<long double>>(in, pool); break;
    case 2: check<Interval_kernel>(in, pool); break;
    case 3: check<Filtered_exact_kernel>(in, pool); break;
    case 4: check<Exact_kernel>(in, pool); break;
    default: check<Naive_kernel<double>>(in, pool);
  }
  return 0;
}
