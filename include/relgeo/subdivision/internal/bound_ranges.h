// relgeo/subdivision/internal/bound_ranges.h — enclosures of the values a
// limit surface takes over a face, for the error bounds: Bezier hulls of
// regular (sub-)patches refined a few times, the hull of the control values
// of what local subdivision leaves irregular; min and max that stay
// enclosures under intervals.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "relgeo/core/number_traits.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/box_spline.h"
#include "relgeo/subdivision/internal/local_patch.h"
#include "relgeo/subdivision/internal/loop_rules.h"
#include "relgeo/subdivision/internal/patch_classification.h"
#include "relgeo/subdivision/loop_patch_kind.h"
#include "relgeo/subdivision/loop_weights.h"

namespace relgeo::internal {

/// min and max that stay enclosures for intervals (Interval's min and max).
template <class FT>
FT min_of(const FT& a, const FT& b) {
  if constexpr (is_interval_v<FT>) return min(a, b);
  else return b < a ? b : a;
}
template <class FT>
FT max_of(const FT& a, const FT& b) {
  if constexpr (is_interval_v<FT>) return max(a, b);
  else return a < b ? b : a;
}
/// a <= b possibly (exactly for exact types; with a relative tolerance for
/// floating point, where excluding a candidate by rounding would be unsound
/// and including one only loosens).
template <class FT>
bool possibly_le(const FT& a, const FT& b, double tol) {
  if constexpr (is_interval_v<FT>) return lower_double(a) <= upper_double(b);
  else if constexpr (std::is_floating_point_v<FT>) return a <= b + tol;
  else return !(b < a);
}

/// out[r * dim + d] = (sum_i table[r][i] net[i * dim + d]) * scale for every
/// row r: the loop over the dims innermost and contiguous (vectorised), the
/// same operations in the same order for each dim as integer_combination.
template <class FT, std::size_t Rows>
void combine_rows(const int (&table)[Rows][12], const FT* net, std::size_t dim, const FT& scale, FT* out) {
  for (std::size_t r = 0; r < Rows; ++r) {
    FT* o = out + r * dim;
    std::fill(o, o + dim, FT(0));
    for (std::size_t i = 0; i < 12; ++i) {
      if (table[r][i] == 0) continue;
      const FT t(table[r][i]);
      const FT* x = net + i * dim;
      for (std::size_t d = 0; d < dim; ++d) o[d] = o[d] + t * x[d];
    }
    for (std::size_t d = 0; d < dim; ++d) o[d] = o[d] * scale;
  }
}

/// The scratch net_ranges_by_rows needs: 12 x dim values per level of
/// refinement, then 15 x dim for the Bezier coefficients.
inline std::size_t net_ranges_scratch_size(std::size_t dim, unsigned depth) {
  return (12 * std::size_t(depth) + 15) * dim;
}

/// The recursion of regular_net_ranges a row at a time: each refinement and
/// each Bezier coefficient computed for every dim at once, with the buffers
/// of every level allocated once (`scratch`: net_ranges_scratch_size
/// values). For each dim, the same operations in the same order as one value at
/// a time, and the values compared in the same order. (One value at a time
/// took half the time of the failsafe bounds of the stress run over CGAL's
/// data set.)
template <class FT>
void net_ranges_by_rows(const FT* net, std::size_t dim, unsigned depth, const FT& one_24, const FT& one_16, FT* scratch,
                        std::vector<FT>& lo, std::vector<FT>& hi, std::vector<bool>& have) {
  if (depth == 0) {
    combine_rows(loop_patch_bezier_x24, net, dim, one_24, scratch);
    for (std::size_t d = 0; d < dim; ++d) {
      if (!have[d]) lo[d] = hi[d] = scratch[d];
      have[d] = true;
    }
    for (std::size_t c = 0; c < 15; ++c)
      for (std::size_t d = 0; d < dim; ++d) {
        const FT& x = scratch[c * dim + d];
        lo[d] = min_of(lo[d], x);
        hi[d] = max_of(hi[d], x);
      }
    return;
  }
  for (int c = 0; c < 4; ++c) {
    combine_rows(loop_patch_child_x16[c], net, dim, one_16, scratch);
    net_ranges_by_rows(scratch, dim, depth - 1, one_24, one_16, scratch + 12 * dim, lo, hi, have);
  }
}

/// regular_net_ranges in rationals: the net over one common denominator W,
/// so that refinement and Bezier coefficients are integer sums (the recursion
/// on integers, with 1 for 1/16 and 1/24, keeps each child times 16 and each
/// coefficient times 24). Every value of the recursion is then
/// N / (W 24 16^depth) with one positive denominator: ranges compare
/// numerators, and only the final min and max become rationals. (Rational
/// arithmetic reduces every sum by a gcd: three quarters of the exact error
/// bounds' time went there.)
inline void rational_net_ranges(const std::vector<mpq_class>& net, std::size_t dim, unsigned depth,
                                std::vector<mpq_class>& lo, std::vector<mpq_class>& hi, std::vector<bool>& have) {
  mpz_class w = 1;
  for (const mpq_class& x : net) mpz_lcm(w.get_mpz_t(), w.get_mpz_t(), x.get_den_mpz_t());
  std::vector<mpz_class> numerators(net.size());
  for (std::size_t i = 0; i < net.size(); ++i) {
    mpz_divexact(numerators[i].get_mpz_t(), w.get_mpz_t(), net[i].get_den_mpz_t());
    numerators[i] *= net[i].get_num();
  }
  std::vector<mpz_class> ilo(dim), ihi(dim);
  std::vector<bool> ihave(dim, false);
  const mpz_class one = 1;
  std::vector<mpz_class> scratch(net_ranges_scratch_size(dim, depth));
  net_ranges_by_rows(numerators.data(), dim, depth, one, one, scratch.data(), ilo, ihi, ihave);
  mpz_class denominator = w * 24;
  denominator <<= 4 * depth;
  for (std::size_t d = 0; d < dim; ++d) {
    if (!ihave[d]) continue;
    mpq_class a(ilo[d], denominator), b(ihi[d], denominator);
    a.canonicalize(), b.canonicalize();
    lo[d] = have[d] ? min_of(lo[d], a) : a;
    hi[d] = have[d] ? max_of(hi[d], b) : b;
    have[d] = true;
  }
}

/// Adds the ranges over the Bezier nets of a regular patch (12 x dim values,
/// row-major) refined `depth` times to lo/hi (per dim).
template <class FT>
void regular_net_ranges(const std::vector<FT>& net, std::size_t dim, unsigned depth, const FT& one_24, const FT& one_16,
                        std::vector<FT>& lo, std::vector<FT>& hi, std::vector<bool>& have) {
  if constexpr (std::is_same_v<FT, mpq_class>) {
    rational_net_ranges(net, dim, depth, lo, hi, have);
  } else {
    std::vector<FT> scratch(net_ranges_scratch_size(dim, depth));
    net_ranges_by_rows(net.data(), dim, depth, one_24, one_16, scratch.data(), lo, hi, have);
  }
}

/// The vertices whose values the limit over face f depends on: the vertices
/// of the faces around each corner of f, except, at a crease vertex or
/// corner, the faces of its other sectors (crease rules never look across a
/// crease). The limit over f is a convex combination of these values (Loop's
/// weights are nonnegative and the children's sets are built from them).
inline std::vector<Index> influence_vertices(const Mesh_topology& t, const Loop_rule_data& d, Index f) {
  std::vector<Index> out;
  const auto add_face = [&](Index g) {
    for (Index v : t.faces()[g])
      if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
  };
  for (int k = 0; k < 3; ++k) {
    const Index h = 3 * f + Index(k), a = t.source(h);
    if (!d.special(a)) {
      t.for_each_outgoing(a, [&](Index g) { add_face(Mesh_topology::face(g)); });
      continue;
    }
    Index first = h;  // clockwise to the crease half-edge starting the sector
    for (Index guard = 0; guard <= t.number_of_incident_faces(a) && !d.crease[first]; ++guard)
      first = Mesh_topology::next(t.opposite(first));
    Index g = first;
    for (Index guard = 0; guard < t.number_of_incident_faces(a) && g != invalid_index; ++guard) {
      add_face(Mesh_topology::face(g));
      g = t.ccw_outgoing(g);
      if (g == invalid_index || d.crease[g]) break;
    }
  }
  return out;
}

/// Ranges (per dim) of the limit of a local patch's values over its face 0:
/// Bezier hulls of regular sub-patches, hull of the control values of the
/// irregular sub-patch left after irregular_depth steps.
template <class K>
void local_patch_ranges(const Loop_local_patch<typename K::FT>& P, const Loop_weights<K>& w,
                        unsigned irregular_depth, unsigned regular_depth, const typename K::FT& one_24,
                        const typename K::FT& one_16, std::vector<typename K::FT>& lo,
                        std::vector<typename K::FT>& hi, std::vector<bool>& have) {
  using FT = typename K::FT;
  const std::size_t dim = P.dim;
  const Mesh_topology t = local_topology(P);
  std::array<Patch_slot, 12> s;
  if (classify_loop_patch(t, P.rules, w.options(), 0, &s) != Loop_patch_kind::irregular) {
    const std::vector<FT> net = patch_net<FT>(s, dim, [&](Index x) { return P.value(x); });
    regular_net_ranges(net, dim, regular_depth, one_24, one_16, lo, hi, have);
    return;
  }
  if (irregular_depth == 0) {
    for (Index v : influence_vertices(t, P.rules, 0))
      for (std::size_t d = 0; d < dim; ++d) {
        const FT& x = P.value(v)[d];
        lo[d] = have[d] ? min_of(lo[d], x) : x;
        hi[d] = have[d] ? max_of(hi[d], x) : x;
        have[d] = true;
      }
    return;
  }
  const auto children = refine_local_patch<K>(P, t, w, 0xFu);
  for (const auto& c : children)
    local_patch_ranges<K>(c, w, irregular_depth - 1, regular_depth, one_24, one_16, lo, hi, have);
}

}  // namespace relgeo::internal
