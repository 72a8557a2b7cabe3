// python/src/predicates_dispatch.cpp — the orientation loops under every
// kernel of the tool's list (CGAL Epeck included).
#include "predicates_dispatch.h"

#include <cmath>
#include <string>

#include "kernels/cgal_kernels.h"
#include "kernels/dispatch.h"
#include "relgeo/core/errors.h"

namespace relgeo::python {

namespace {

/// Kernels answer NaN inputs in their own ways (the naive ones with a sign):
/// refuse them before any kernel sees them.
template <int Dimension, class... Rows>
bool finite_tuple(std::size_t i, const Rows&... rows) {
  bool finite = true;
  for (int j = 0; j < Dimension; ++j) finite = (finite && ... && std::isfinite(rows(i, j)));
  return finite;
}

[[noreturn]] void throw_non_finite(const char* who, std::size_t i) {
  throw Non_finite_input(std::string(who) + ": tuple " + std::to_string(i) + " has a NaN or infinite coordinate");
}

}  // namespace

void orientation_2_signs(std::string_view kernel, Coordinate_rows p, Coordinate_rows q, Coordinate_rows r,
                         std::size_t n, std::int8_t* out) {
  tool::with_kernel(kernel, [&]<class K>(const K& k) {
    const auto point = k.construct_point_2_object();
    const auto orientation = k.orientation_2_object();
    for (std::size_t i = 0; i < n; ++i) {
      if (!finite_tuple<2>(i, p, q, r)) throw_non_finite("orient2d", i);
      out[i] = static_cast<std::int8_t>(
          orientation(point(p(i, 0), p(i, 1)), point(q(i, 0), q(i, 1)), point(r(i, 0), r(i, 1))));
    }
  });
}

void orientation_3_signs(std::string_view kernel, Coordinate_rows p, Coordinate_rows q, Coordinate_rows r,
                         Coordinate_rows s, std::size_t n, std::int8_t* out) {
  tool::with_kernel(kernel, [&]<class K>(const K& k) {
    const auto point = k.construct_point_3_object();
    const auto orientation = k.orientation_3_object();
    for (std::size_t i = 0; i < n; ++i) {
      if (!finite_tuple<3>(i, p, q, r, s)) throw_non_finite("orient3d", i);
      out[i] =
          static_cast<std::int8_t>(orientation(point(p(i, 0), p(i, 1), p(i, 2)), point(q(i, 0), q(i, 1), q(i, 2)),
                                               point(r(i, 0), r(i, 1), r(i, 2)), point(s(i, 0), s(i, 1), s(i, 2))));
    }
  });
}

}  // namespace relgeo::python
