// relgeo/hull/hull_result.h — what every planar convex-hull algorithm returns.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace relgeo {

/// Whether the algorithm produced a hull or detected its own failure.
enum class Hull_status { ok, failed };

/// The hull as a counterclockwise sequence of input indices and their points,
/// starting at the lexicographically smallest vertex; points on a hull edge are
/// not vertices and among equal points the smallest index is reported. With
/// exact predicates every relgeo algorithm returns exactly this sequence; with
/// other kernels the sequence is what the algorithm computed (the error
/// measures of relgeo/error/ say how good it is).
template <class Point>
struct Hull_result {
  Hull_status status = Hull_status::ok;
  std::string failure;                ///< why it failed ("non-termination", ...); empty when ok
  std::vector<std::size_t> indices;   ///< into the input range
  std::vector<Point> points;          ///< the input points at `indices`
  std::size_t predicate_calls = 0;    ///< orientation tests evaluated
  std::size_t uncertain_answers = 0;  ///< of which the kernel could not decide

  bool ok() const { return status == Hull_status::ok; }
};

/// Options of the sorting hull algorithms (graham_fortune, monotone_chain).
struct Hull_options {
  /// Akl-Toussaint prefilter: before sorting, drop every point the kernel
  /// *certifies* to lie strictly left of each edge of the polygon through the
  /// extreme points in the 8 directions of the axes and diagonals. Such a
  /// point is strictly inside the hull of input points that are kept, so the
  /// exact hull is unchanged, and a fail-safe output within distance d of
  /// every kept point is within d of it too (the bound of
  /// graham_fortune_backward_error_bound still holds). Applies to relgeo
  /// points of float, double or long double under a certified kernel (and so
  /// to Exact_kernel on doubles); otherwise nothing is dropped. Set false to
  /// run the scan on every point, as the thesis states it.
  bool discard_interior = true;
};

}  // namespace relgeo
