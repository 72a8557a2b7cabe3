// relgeo/kernel/cgal_kernel.h — any CGAL kernel as a relgeo kernel.
//
// Needs CGAL (link relgeo::cgal). Include the CGAL kernel header you use
// yourself; this header includes none of the heavy ones.
#pragma once

#include <CGAL/Algebraic_structure_traits.h>
#include <CGAL/Kernel/global_functions.h>

#include <bit>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>

#include "relgeo/core/errors.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/core/certified_sign.h"
#include "relgeo/core/floating_point.h"
#include "relgeo/kernel/implicit_point.h"
#include "relgeo/kernel/internal/implicit_cgal.h"
#include "relgeo/kernel/internal/semi_static_filter.h"

namespace CGAL {
class Epick;
class Epeck;
template <class FT>
struct Simple_cartesian;
}  // namespace CGAL

namespace relgeo {
namespace internal {

/// Whether the floating-point environment CGAL's predicates depend on is the
/// default one. On x86-64 with SSE2 math, doubles are computed in SSE
/// registers and CGAL sets the rounding of its intervals in MXCSR
/// (CGAL/FPU.h), so MXCSR alone decides (rounding, FTZ, DAZ): one register
/// read instead of is_default_fp_environment()'s two (MXCSR and the x87
/// control word; each read is microcoded on AMD EPYC). Elsewhere the full test.
inline bool cgal_environment_is_default() noexcept {
#if defined(__x86_64__) && defined(__SSE2_MATH__)
  return (__builtin_ia32_stmxcsr() & 0xE040u) == 0;
#else
  return is_default_fp_environment();
#endif
}

template <class CK>
inline constexpr bool cgal_has_exact_constructions =
    std::is_same_v<typename CGAL::Algebraic_structure_traits<typename CK::FT>::Is_exact, CGAL::Tag_true>;

/// No implicit points (a CGAL kernel without exact constructions).
struct No_implicit_points {};

}  // namespace internal

/// \concept CgalKernel
/// A CGAL kernel (CGAL's Kernel concept, the part relgeo's adapter uses):
/// its number type, points and orientation predicates.
template <class K>
concept CgalKernel = requires {
  typename K::FT;
  typename K::Point_2;
  typename K::Point_3;
  typename K::Orientation_2;
  typename K::Orientation_3;
  typename K::Compare_xy_2;
  typename K::Coplanar_orientation_3;
};

// Constrained by a static_assert in its body, not in its head: the tool and
// the tests name Cgal_kernel<CGAL::Epick> where Epick is only declared (a
// constraint in the head is checked when the name is formed).
template <class K>
class Cgal_kernel;

namespace internal {
/// Kernels with exact constructions (Epeck) model IntersectionKernel_3
/// through their own lazy exact constructions (implicit_cgal.h).
template <class CK>
using Cgal_implicit_base = std::conditional_t<cgal_has_exact_constructions<CK>,
                                              Implicit_kernel_base<Cgal_implicit_policy<Cgal_kernel<CK>, CK>>,
                                              No_implicit_points>;
}  // namespace internal

namespace internal {
// The name() of Cgal_kernel<K>: "cgal", or the short name of a kernel
// relgeo knows (declared above, so these need no CGAL header).
template <class K>
struct Cgal_kernel_name {
  static std::string get() { return "cgal"; }
};
template <>
struct Cgal_kernel_name<CGAL::Simple_cartesian<double>> {
  static std::string get() { return "cgal-sc-double"; }
};
template <>
struct Cgal_kernel_name<CGAL::Epick> {
  static std::string get() { return "cgal-epick"; }
};
template <>
struct Cgal_kernel_name<CGAL::Epeck> {
  static std::string get() { return "cgal-epeck"; }
};
}  // namespace internal

/// \brief Adapter turning a CGAL kernel K (Simple_cartesian<double>, Epick,
/// Epeck, ...) into a relgeo kernel: the same predicates, answers mapped to
/// Certified_sign. For peer comparison and for clients who already hold CGAL
/// points.
///
/// A kernel is certified when it has filtered (exact) predicates or an exact
/// number type; its predicates then run in the default floating-point
/// environment whatever the caller set (core/fp_environment.h). For certified kernels with double coordinates (Epick), points
/// with NaN or infinite coordinates give `uncertain` (CGAL's exact fallback
/// cannot convert them); kernels with exact constructions refuse such points
/// at construction (Non_finite_input).
///
/// Kernels with exact constructions (Epeck) also model IntersectionKernel_3:
/// an implicit point is a CGAL point constructed in the kernel's lazy exact
/// number type, the predicates CGAL's own on it (internal/implicit_cgal.h).
template <class K>
class Cgal_kernel : public internal::Cgal_implicit_base<K> {
  static_assert(CgalKernel<K>, "Cgal_kernel<K>: K must be a CGAL kernel (concept CgalKernel)");
  using Base_ft = typename K::FT;
  static constexpr bool ft_is_exact = internal::cgal_has_exact_constructions<K>;

 public:
  using Cgal = K;
  using FT = Base_ft;
  using Point_2 = typename K::Point_2;
  using Point_3 = typename K::Point_3;

  static std::string name() { return internal::Cgal_kernel_name<K>::get(); }
  static constexpr bool has_exact_predicates = bool(K::Has_filtered_predicates) || ft_is_exact;
  static constexpr bool has_exact_constructions = ft_is_exact;
  static constexpr bool is_certified = has_exact_predicates;
  static constexpr double unit_roundoff = ft_is_exact ? 0.0 : unit_roundoff_v<double>;
  static constexpr std::optional<double> orientation_2_error_bound =
      has_exact_predicates ? std::optional<double>(0.0)
      : std::is_same_v<FT, double>
          ? std::optional<double>(internal::Orientation_filter_constants<double>::eps_2)
          : std::nullopt;
  static constexpr std::optional<double> orientation_3_error_bound =
      has_exact_predicates ? std::optional<double>(0.0)
      : std::is_same_v<FT, double>
          ? std::optional<double>(internal::Orientation_filter_constants<double>::eps_3)
          : std::nullopt;

  struct Construct_point_2 {
    Point_2 operator()(double x, double y) const {
      if constexpr (has_exact_constructions)
        if (!all_finite(x, y)) throw Non_finite_input(name() + ": coordinate is NaN or infinite");
      return Point_2(x, y);
    }
  };
  struct Construct_point_3 {
    Point_3 operator()(double x, double y, double z) const {
      if constexpr (has_exact_constructions)
        if (!all_finite(x, y, z))
          throw Non_finite_input(name() + ": coordinate is NaN or infinite");
      return Point_3(x, y, z);
    }
  };
  /// The sign of a - b (NumberComparisonKernel_3): exact for CGAL's number
  /// types, uncertain when a double is NaN.
  static Certified_sign compare_ft(const FT& a, const FT& b) {
    if constexpr (std::is_same_v<FT, double>)
      if (std::isnan(a) || std::isnan(b)) return Certified_sign::uncertain;
    return from_cgal(CGAL::compare(a, b));
  }
  struct Orientation_2 {
    Certified_sign operator()(const Point_2& p, const Point_2& q, const Point_2& r) const {
      return guarded([&] { return from_cgal(typename K::Orientation_2()(p, q, r)); }, p, q, r);
    }
  };
  struct Orientation_3 {
    Certified_sign operator()(const Point_3& p, const Point_3& q, const Point_3& r,
                              const Point_3& s) const {
      return guarded([&] { return from_cgal(typename K::Orientation_3()(p, q, r, s)); }, p, q, r, s);
    }
  };
  struct Compare_xy_2 {
    Certified_sign operator()(const Point_2& p, const Point_2& q) const {
      return guarded([&] { return from_cgal(typename K::Compare_xy_2()(p, q)); }, p, q);
    }
  };
  /// Same contract as relgeo's own Coplanar_orientation_3 (kernel_base.h).
  struct Coplanar_orientation_3 {
    Certified_sign operator()(const Point_3& p, const Point_3& q, const Point_3& r) const {
      return guarded([&] { return from_cgal(typename K::Coplanar_orientation_3()(p, q, r)); }, p, q, r);
    }
    Certified_sign operator()(const Point_3& p, const Point_3& q, const Point_3& r,
                              const Point_3& s) const {
      const Certified_sign pqr =
          guarded([&] { return from_cgal(typename K::Coplanar_orientation_3()(p, q, r)); }, p, q, r, s);
      if (!is_certain(pqr)) return pqr;
      if (certainly(pqr, Certified_sign::zero))
        throw Precondition_violation("coplanar_orientation(p,q,r,s): p, q, r are collinear");
      return guarded([&] { return from_cgal(typename K::Coplanar_orientation_3()(p, q, r, s)); }, p, q, r, s);
    }
  };

  Construct_point_2 construct_point_2_object() const { return {}; }
  Construct_point_3 construct_point_3_object() const { return {}; }
  Orientation_2 orientation_2_object() const { return {}; }
  Orientation_3 orientation_3_object() const { return {}; }
  Compare_xy_2 compare_xy_2_object() const { return {}; }
  Coplanar_orientation_3 coplanar_orientation_3_object() const { return {}; }

 private:
  // CGAL's filters assume round to nearest without FTZ/DAZ (measured: under
  // denormals-are-zero Epick answers `zero` for nearly every orientation of
  // subnormal coordinates), and its exact fallback cannot convert a NaN or
  // an infinity. So a certified kernel calls CGAL's predicate directly only
  // when the environment is the default one and the coordinates are finite,
  // tested together with one branch; otherwise, out of line, it answers
  // `uncertain` for non-finite coordinates and evaluates the predicate in the
  // default environment (core/fp_environment.h). The fast path costs one read
  // of MXCSR and a test of the coordinates' exponent bits (see
  // cgal_environment_is_default below).
  template <class F, class... P>
  static Certified_sign guarded(const F& f, const P&... points) {
    if constexpr (!is_certified) {
      return f();
    } else {
      // `&` of both tests, not `&&`: no branch between them (on ints: clang
      // warns about `&` on bools).
      const int fast =
          static_cast<int>(internal::cgal_environment_is_default()) & static_cast<int>(all_finite_points(points...));
      if (fast) [[likely]]
        return f();
      return guarded_slow(f, points...);
    }
  }
  template <class F, class... P>
  [[gnu::noinline]] static Certified_sign guarded_slow(const F& f, const P&... points) {
    if (!all_finite_points(points...)) return Certified_sign::uncertain;
    const Default_fp_environment environment;
    return f();
  }
  template <class S>
  static Certified_sign from_cgal(S s) {
    return static_cast<Certified_sign>(static_cast<int>(s));
  }
  // Certified kernels with inexact (double) coordinates cannot decide on
  // non-finite coordinates; the others either lie anyway (naive) or cannot
  // hold them. Branch-free: a double is NaN or infinite when its exponent
  // field is all ones, and then adding 1 to that field carries into bit 63
  // (two integer operations per coordinate, the results or-ed).
  static constexpr bool checks_finiteness =
      is_certified && !has_exact_constructions && std::is_same_v<FT, double>;
  static std::uint64_t non_finite_bits(double v) {
    constexpr std::uint64_t exponent = 0x7FF0000000000000ull;
    return (std::bit_cast<std::uint64_t>(v) & exponent) + 0x0010000000000000ull;
  }
  static std::uint64_t non_finite_bits(const Point_2& p) {
    if constexpr (checks_finiteness) return non_finite_bits(p.x()) | non_finite_bits(p.y());
    else return 0;
  }
  static std::uint64_t non_finite_bits(const Point_3& p) {
    if constexpr (checks_finiteness) return non_finite_bits(p.x()) | non_finite_bits(p.y()) | non_finite_bits(p.z());
    else return 0;
  }
  template <class... P>
  static bool all_finite_points(const P&... points) {
    if constexpr (!checks_finiteness) {
      return true;
    } else {
#if defined(__SSE2__)
      // The same carry test on two coordinates at a time (orientation_3 of
      // Epick: 1.07x CGAL's own functor on uniform input, against 1.11-1.12x
      // one coordinate at a time).
      const __m128i exponent = _mm_set1_epi64x(0x7FF0000000000000ll);
      const __m128i one = _mm_set1_epi64x(0x0010000000000000ll);
      __m128i any = _mm_setzero_si128();
      const auto add = [&](double a, double b) {
        const __m128i v = _mm_castpd_si128(_mm_set_pd(b, a));
        any = _mm_or_si128(any, _mm_add_epi64(_mm_and_si128(v, exponent), one));
      };
      (add(points.x(), points.y()), ...);
      if constexpr ((std::is_same_v<P, Point_3> && ...)) {
        const double z[] = {points.z()..., 0.0};  // padded to pairs
        for (std::size_t i = 0; i < sizeof...(P); i += 2) add(z[i], z[i + 1]);
      }
      return _mm_movemask_pd(_mm_castsi128_pd(any)) == 0;
#else
      return ((non_finite_bits(points) | ...) >> 63) == 0;
#endif
    }
  }
};

}  // namespace relgeo
