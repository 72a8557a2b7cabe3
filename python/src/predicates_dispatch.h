// python/src/predicates_dispatch.h — orientation signs of many point tuples
// under a kernel named at run time. The kernels are instantiated in
// predicates_dispatch.cpp only (the tool's compile firewall,
// tools/relgeo/kernels/dispatch.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace relgeo::python {

/// Row i of an (n, d) array of doubles with any strides, counted in elements
/// (numpy's broadcasting gives a stride of 0).
struct Coordinate_rows {
  const double* data = nullptr;
  std::ptrdiff_t row_stride = 0, column_stride = 0;

  double operator()(std::size_t row, int column) const {
    return data[static_cast<std::ptrdiff_t>(row) * row_stride + column * column_stride];
  }
};

/// out[i] = orientation_2(p[i], q[i], r[i]) under `kernel` as its Certified_sign
/// value (-1, 0, 1; 2 = uncertain), i < n.
/// \throws Usage_error for an unknown kernel, Non_finite_input naming the
///   first triple with a NaN or infinite coordinate (out is then partly written).
void orientation_2_signs(std::string_view kernel, Coordinate_rows p, Coordinate_rows q, Coordinate_rows r,
                         std::size_t n, std::int8_t* out);

/// out[i] = orientation_3(p[i], q[i], r[i], s[i]) under `kernel`; the same throws.
void orientation_3_signs(std::string_view kernel, Coordinate_rows p, Coordinate_rows q, Coordinate_rows r,
                         Coordinate_rows s, std::size_t n, std::int8_t* out);

}  // namespace relgeo::python
