// python/src/predicates_dispatch.cpp — the orientation loops under every
// kernel of the tool's list (CGAL Epeck included).
#include "predicates_dispatch.h"

#include <algorithm>
#include <array>
#include <bit>
#include <string>
#include <tuple>
#include <type_traits>

#include "kernels/cgal_kernels.h"
#include "kernels/dispatch.h"
#include "relgeo/core/certified_sign.h"
#include "relgeo/core/errors.h"
#include "relgeo/core/interval.h"

namespace relgeo::python {

namespace {

/// Kernels answer NaN inputs in their own ways (the naive ones with a sign,
/// the exact one cannot convert them): every tuple with a NaN or infinite
/// coordinate is refused, whatever the kernel. The check runs on blocks small
/// enough to stay in the L1 cache for the predicates that follow, without a
/// branch per coordinate: a test per tuple inside the predicate loop, or a
/// pass of its own over the whole arrays, each cost more than the double
/// kernel's predicate itself (5.8 and 5.1 against 2.3 ns per call).
constexpr std::size_t block_size = 256;

/// Certified kernels that hold NaN and infinite coordinates (floating-point
/// and interval coordinates: failsafe, interval, filtered, CGAL Epick) answer
/// `uncertain` for every tuple with one, never a sign
/// (test/kernel/bad_input_test.cpp). Under them a block is checked only when
/// one of its answers is `uncertain`, after the predicates: the same tuple is
/// refused, and the common block, all certain, costs no check.
template <class K>
constexpr bool non_finite_answers_uncertain =
    K::is_certified && (std::is_floating_point_v<typename K::FT> || std::is_same_v<typename K::FT, Interval>);

/// The rule of every check below, in integer operations (branch-free; no
/// floating-point operation, so no exception flag or trap on a signalling
/// NaN): one more than an all-ones exponent carries into the sign bit, so
/// the sign bit of `special(v)` is set exactly when v is NaN or infinite;
/// or-ed over many values, it tells whether any is.
constexpr std::uint64_t sign_bit = 0x8000000000000000;
inline std::uint64_t special(double v) {
  constexpr std::uint64_t exponent = 0x7ff0000000000000, exponent_one = 0x0010000000000000;
  return (std::bit_cast<std::uint64_t>(v) & exponent) + exponent_one;
}

/// special() or-ed over the coordinates of tuple i.
template <int Dimension, class... Rows>
std::uint64_t special_bits(std::size_t i, const Rows&... rows) {
  std::uint64_t bits = 0;
  for (int j = 0; j < Dimension; ++j) bits = (bits | ... | special(rows(i, j)));
  return bits;
}

template <int Dimension, class... Rows>
bool finite_tuple(std::size_t i, const Rows&... rows) {
  return (special_bits<Dimension>(i, rows...) & sign_bit) == 0;
}

/// Whether count doubles from v are all finite: one pass that vectorises
/// (x86-64's baseline SSE2 has no 64-bit compare, but adds, ands and ors of
/// 64-bit lanes).
bool all_finite(const double* v, std::size_t count) {
  std::uint64_t bits = 0;
  for (std::size_t k = 0; k < count; ++k) bits |= special(v[k]);
  return (bits & sign_bit) == 0;
}

/// Whether rows [begin, end) of `rows` are finite.
template <int Dimension>
bool rows_finite(const Coordinate_rows& rows, std::size_t begin, std::size_t end) {
  if (rows.row_stride == 0) return finite_tuple<Dimension>(0, rows);  // broadcast: one row
  if (rows.column_stride == 1 && rows.row_stride == Dimension)
    return all_finite(rows.data + begin * Dimension, (end - begin) * Dimension);
  bool finite = true;
  for (std::size_t i = begin; i < end; ++i) finite &= finite_tuple<Dimension>(i, rows);
  return finite;
}

/// Throws Non_finite_input naming the first tuple of [begin, end) with a NaN
/// or infinite coordinate.
template <int Dimension, class... Rows>
void require_finite_tuples(const char* who, std::size_t begin, std::size_t end, const Rows&... rows) {
  if ((rows_finite<Dimension>(rows, begin, end) && ...)) return;
  for (std::size_t i = begin; i < end; ++i)
    if (!finite_tuple<Dimension>(i, rows...))
      throw Non_finite_input(std::string(who) + ": tuple " + std::to_string(i) + " has a NaN or infinite coordinate");
}

/// Rows of a C-contiguous (n, Dimension) array: the strides known to the
/// compiler (numpy's default layout; with the integer finiteness check,
/// 0.5-0.8 ns per triple less on orient2d, doc/python.md).
template <int Dimension>
struct Contiguous_rows {
  const double* data;
  double operator()(std::size_t row, int column) const { return data[row * Dimension + column]; }
};

template <int Dimension>
bool contiguous(const Coordinate_rows& rows) {
  return rows.row_stride == Dimension && rows.column_stride == 1;
}

/// out[i] = the orientation of the i-th tuple of `rows` (2 or 3 rows of
/// Dimension coordinates), in blocks whose coordinates are checked finite
/// first (`checked`: the same rows as numpy gave them).
template <int Dimension, class K, class... Rows>
void orientation_loop(const K& k, const char* who, const std::array<Coordinate_rows, sizeof...(Rows)>& checked,
                      std::size_t n, std::int8_t* out, const Rows&... rows) {
  const auto orientation = [&] {
    if constexpr (Dimension == 2)
      return k.orientation_2_object();
    else
      return k.orientation_3_object();
  }();
  const auto point = [&](const auto& row, std::size_t i) {
    if constexpr (Dimension == 2)
      return k.construct_point_2_object()(row(i, 0), row(i, 1));
    else
      return k.construct_point_3_object()(row(i, 0), row(i, 1), row(i, 2));
  };
  const auto require_finite = [&](std::size_t begin, std::size_t end) {
    std::apply([&](const auto&... c) { require_finite_tuples<Dimension>(who, begin, end, c...); }, checked);
  };
  for (std::size_t begin = 0; begin < n; begin += block_size) {
    const std::size_t end = std::min(n, begin + block_size);
    if constexpr (non_finite_answers_uncertain<K>) {
      bool uncertain = false;
      for (std::size_t i = begin; i < end; ++i) {
        const Certified_sign s = orientation(point(rows, i)...);
        uncertain |= s == Certified_sign::uncertain;
        out[i] = static_cast<std::int8_t>(s);
      }
      if (uncertain) require_finite(begin, end);
    } else if constexpr (std::is_floating_point_v<typename K::FT>) {
      // The naive kernels answer anything on NaN, harmlessly: the tuples'
      // exponent bits are collected as they are read, and a block with a
      // non-finite coordinate is refused before its answers are returned.
      std::uint64_t special = 0;
      for (std::size_t i = begin; i < end; ++i) {
        special |= special_bits<Dimension>(i, rows...);
        out[i] = static_cast<std::int8_t>(orientation(point(rows, i)...));
      }
      if (special & sign_bit) require_finite(begin, end);
    } else {
      // The others may refuse a NaN themselves, with their own message: checked first.
      require_finite(begin, end);
      for (std::size_t i = begin; i < end; ++i) out[i] = static_cast<std::int8_t>(orientation(point(rows, i)...));
    }
  }
}

/// orientation_loop under the kernel named `kernel`, on C-contiguous rows
/// when every array is one.
template <int Dimension, class... Rows>
void orientation_signs(std::string_view kernel, const char* who, std::size_t n, std::int8_t* out, const Rows&... rows) {
  const std::array<Coordinate_rows, sizeof...(Rows)> checked{rows...};
  tool::with_kernel(kernel, [&]<class K>(const K& k) {
    if ((contiguous<Dimension>(rows) && ...))
      orientation_loop<Dimension>(k, who, checked, n, out, Contiguous_rows<Dimension>{rows.data}...);
    else
      orientation_loop<Dimension>(k, who, checked, n, out, rows...);
  });
}

}  // namespace

void orientation_2_signs(std::string_view kernel, Coordinate_rows p, Coordinate_rows q, Coordinate_rows r,
                         std::size_t n, std::int8_t* out) {
  orientation_signs<2>(kernel, "orient2d", n, out, p, q, r);
}

void orientation_3_signs(std::string_view kernel, Coordinate_rows p, Coordinate_rows q, Coordinate_rows r,
                         Coordinate_rows s, std::size_t n, std::int8_t* out) {
  orientation_signs<3>(kernel, "orient3d", n, out, p, q, r, s);
}

}  // namespace relgeo::python
