// Fuzz harness: the planar hull algorithms (graham_incremental,
// graham_fortune, monotone_chain) under every kernel on arbitrary point sets;
// layout of the input and the contract in hull_harness.h.
#include "hull_harness.h"
#include "relgeo/kernel.h"

namespace relgeo::fuzz {
// hull_fuzzer_cgal.cpp: the CGAL kernels (their own translation unit).
void check_hull_cgal(int kernel, std::span<const Point_2<double>> input, Hull_algorithm a, const Hull_options& o);
constexpr int cgal_kernels = 3;
}  // namespace relgeo::fuzz

namespace {

using namespace relgeo;
using namespace relgeo::fuzz;

constexpr std::size_t max_points = 4096;

std::vector<Point_2<double>> decode_points(Input& in) {
  std::vector<Point_2<double>> p;
  const auto earlier = [&]() -> const Point_2<double>& { return p[in.below(p.size())]; };
  while (!in.empty() && p.size() < max_points) {
    const std::uint8_t op = in.byte();
    switch (p.empty() ? 0 : op % 8) {
      case 1: p.push_back(earlier()); break;  // duplicate
      case 2: {                               // on the line through two earlier points
        const auto a = earlier(), b = earlier();
        const double t = static_cast<double>(static_cast<std::int8_t>(in.byte())) / 16.0;
        p.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
        break;
      }
      case 3: {  // a run of collinear points between two earlier ones
        const auto a = earlier(), b = earlier();
        const int n = 2 + in.byte() % 30;
        for (int i = 1; i < n; ++i) {
          const double t = static_cast<double>(i) / n;
          p.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
        }
        break;
      }
      case 4: {  // an earlier point moved by a few ulps
        auto a = earlier();
        const int dx = static_cast<std::int8_t>(in.byte()) % 4, dy = static_cast<std::int8_t>(in.byte()) % 4;
        for (int i = 0; i < std::abs(dx); ++i) a.x = std::nextafter(a.x, dx > 0 ? INFINITY : -INFINITY);
        for (int i = 0; i < std::abs(dy); ++i) a.y = std::nextafter(a.y, dy > 0 ? INFINITY : -INFINITY);
        p.push_back(a);
        break;
      }
      case 5: {  // a cloud of 1100 points between earlier ones (runs the prefilter)
        if (p.size() > 64) break;
        const auto a = earlier(), b = earlier();
        const std::uint32_t seed = in.u32();
        for (std::uint32_t i = 0; i < 1100; ++i) {
          const std::uint32_t h = (i + seed) * 2654435761u;
          const double s = (h & 0xffff) / 65536.0, t = (h >> 16) / 65536.0;
          p.push_back({a.x + s * (b.x - a.x), a.y + t * (b.y - a.y)});
        }
        break;
      }
      default: {
        const double x = in.coordinate();
        p.push_back({x, in.coordinate()});
      }
    }
  }
  return p;
}

template <class K>
void check(const std::vector<Point_2<double>>& p, Hull_algorithm a, const Hull_options& o) {
  check_hull<K>(p, a, o);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input in(data, size);
  const int kernel = in.byte() % (13 + cgal_kernels);
  const std::uint8_t mode = in.byte();
  const auto algorithm = static_cast<Hull_algorithm>(mode % 3);
  const Hull_options options{.discard_interior = (mode & 0x80) == 0};
  const auto p = decode_points(in);
  switch (kernel) {
    case 0: check<Naive_kernel<float>>(p, algorithm, options); break;
    case 1: check<Naive_kernel<double>>(p, algorithm, options); break;
    case 2: check<Naive_kernel<long double>>(p, algorithm, options); break;
    case 3: check<Failsafe_kernel<float>>(p, algorithm, options); break;
    case 4: check<Failsafe_kernel<double>>(p, algorithm, options); break;
    case 5: check<Failsafe_kernel<long double>>(p, algorithm, options); break;
    case 6: check<Interval_kernel>(p, algorithm, options); break;
    case 7: check<Filtered_exact_kernel>(p, algorithm, options); break;
    case 8: check<Exact_kernel>(p, algorithm, options); break;
    case 9: check<Mpfr_kernel<11>>(p, algorithm, options); break;
    case 10: check<Mpfr_kernel<53>>(p, algorithm, options); break;
    case 11: check<Mpfr_kernel<113>>(p, algorithm, options); break;
    case 12: check<Mpfr_kernel<256>>(p, algorithm, options); break;
    default: check_hull_cgal(kernel - 13, p, algorithm, options);
  }
  return 0;
}
