// relgeo/kernel/concepts.h — what a geometric kernel is, as C++20 concepts.
//
// A kernel is a traits class in CGAL's style: nested number and point types,
// predicate and construction functors fetched through `*_object()` factories,
// and static metadata. Every predicate answers a relgeo::Certified_sign.
// relgeo's models: Naive_kernel<T>, Failsafe_kernel<T>, Interval_kernel,
// Filtered_exact_kernel, Exact_kernel, Mpfr_kernel<Bits>, Cgal_kernel<K>.
// See doc/kernels.md for which to choose.
#pragma once

#include <concepts>
#include <optional>
#include <string>
#include <type_traits>

#include "relgeo/core/certified_sign.h"
#include "relgeo/kernel/implicit_point.h"

namespace relgeo {

/// \concept KernelProperties
/// Static metadata of a kernel:
///  * `name()` — a short self-explaining name ("double", "failsafe<double>"...);
///  * `unit_roundoff` — u of its floating-point arithmetic (0 when exact);
///  * `is_certified` — the soundness rule holds: a definite answer is the exact sign;
///  * `has_exact_predicates`, `has_exact_constructions`;
///  * `orientation_2_error_bound`, `orientation_3_error_bound` — eps with
///    |computed determinant - exact| <= eps * Mx * My (* Mz) (the a-priori
///    constant algorithms use to state their backward-error bound; 0 when
///    exact, empty when there is no a-priori constant).
template <class K>
concept KernelProperties = requires {
  { K::name() } -> std::convertible_to<std::string>;
  { K::unit_roundoff } -> std::convertible_to<double>;
  { K::is_certified } -> std::convertible_to<bool>;
  { K::has_exact_predicates } -> std::convertible_to<bool>;
  { K::has_exact_constructions } -> std::convertible_to<bool>;
  { K::orientation_2_error_bound } -> std::convertible_to<std::optional<double>>;
  { K::orientation_3_error_bound } -> std::convertible_to<std::optional<double>>;
};

/// \concept OrientationKernel_2
/// Planar points with certified orientation and lexicographic comparison, and
/// points built from double coordinates. Enough for planar convex hulls.
template <class K>
concept OrientationKernel_2 =
    std::copyable<typename K::Point_2> &&
    requires(const K& k, const typename K::Point_2& p) {
      typename K::FT;
      { k.orientation_2_object()(p, p, p) } -> std::same_as<Certified_sign>;
      { k.compare_xy_2_object()(p, p) } -> std::same_as<Certified_sign>;
      { k.construct_point_2_object()(0.0, 0.0) } -> std::same_as<typename K::Point_2>;
    };

/// \concept OrientationKernel_3
/// Space points with certified orientation and in-plane (coplanar)
/// orientation, as the triangle-triangle intersection test needs.
template <class K>
concept OrientationKernel_3 =
    std::copyable<typename K::Point_3> &&
    requires(const K& k, const typename K::Point_3& p) {
      { k.orientation_3_object()(p, p, p, p) } -> std::same_as<Certified_sign>;
      { k.coplanar_orientation_3_object()(p, p, p) } -> std::same_as<Certified_sign>;
      { k.coplanar_orientation_3_object()(p, p, p, p) } -> std::same_as<Certified_sign>;
      { k.construct_point_3_object()(0.0, 0.0, 0.0) } -> std::same_as<typename K::Point_3>;
    };

/// \concept Kernel
/// A complete relgeo kernel: metadata, 2D and 3D predicates.
template <class K>
concept Kernel = KernelProperties<K> && OrientationKernel_2<K> && OrientationKernel_3<K>;

/// \concept ConstructionKernel_3
/// Metadata and space points whose coordinates are numbers of K::FT with
/// its field operations: what constructions in K's numbers need (Loop's
/// rules build each new point as a weighted sum of old ones).
template <class K>
concept ConstructionKernel_3 =
    KernelProperties<K> && std::copyable<typename K::Point_3> && requires(const typename K::FT& a) {
      { a + a } -> std::convertible_to<typename K::FT>;
      { a * a } -> std::convertible_to<typename K::FT>;
      { a / a } -> std::convertible_to<typename K::FT>;
    };

/// \concept KernelOrDefault
/// The kernel template argument of a function that also runs without one:
/// `void` (the default, which picks the kernel for the mesh's point type:
/// documented at each function) or a Kernel.
template <class K>
concept KernelOrDefault = std::is_void_v<K> || Kernel<K>;

/// \concept NumberComparisonKernel_3
/// Certified comparison of two numbers of K::FT (`K::compare_ft(a, b)`: the
/// sign of a - b; `uncertain` when K cannot tell), the construction a
/// predicate needs when it moves a point off a plane by a number it built.
template <class K>
concept NumberComparisonKernel_3 = OrientationKernel_3<K> && requires(const typename K::FT& a) {
  { K::compare_ft(a, a) } -> std::same_as<Certified_sign>;
};

/// \concept IntersectionKernel_3
/// A Kernel with implicit points (kernel/implicit_point.h): `Implicit_point_3`,
/// an input point or an LPI/TPI point kept by what defines it, cheap to
/// copy; its construction (optional: empty when the kernel cannot certify
/// that the point exists) and the predicates on any mix of explicit and
/// implicit points — orientation_3, the orientation of a projection dropping
/// one axis, CGAL's coplanar orientation, lexicographic comparison (`zero`:
/// the same point) — and a double approximation with an error bound. The
/// soundness rule applies unchanged; and the comparison of numbers
/// (NumberComparisonKernel_3). What the triangle intersection and the
/// Booleans need.
template <class K>
concept IntersectionKernel_3 =
    Kernel<K> && NumberComparisonKernel_3<K> && std::copyable<typename K::Implicit_point_3> &&
    requires(const K& k, const typename K::Point_3& p, const typename K::Implicit_point_3& i) {
      { k.construct_implicit_point_3_object()(p) } -> std::same_as<typename K::Implicit_point_3>;
      { k.construct_implicit_point_3_object()(p, p, p, p, p) } -> std::same_as<std::optional<typename K::Implicit_point_3>>;
      { k.construct_implicit_point_3_object()(p, p, p, p, p, p, p, p, p) }
          -> std::same_as<std::optional<typename K::Implicit_point_3>>;
      { k.implicit_orientation_3_object()(i, i, i, i) } -> std::same_as<Certified_sign>;
      { k.implicit_orientation_2_object()(i, i, i, 0) } -> std::same_as<Certified_sign>;
      { k.implicit_coplanar_orientation_3_object()(i, i, i) } -> std::same_as<Certified_sign>;
      { k.implicit_coplanar_orientation_3_object()(i, i, i, i) } -> std::same_as<Certified_sign>;
      { k.compare_xyz_3_object()(i, i) } -> std::same_as<Certified_sign>;
      { k.approximate_point_3_object()(i) } -> std::same_as<Approximate_point_3>;
    };

}  // namespace relgeo
