// relgeo/kernel/internal/orientation_against.h — orientation_3 of several
// points against one plane: a triangle's corners against another's plane,
// the first test of every triangle pair.
#pragma once

namespace relgeo::internal {

/// orientation_3(a, b, c, s) for several points s: the kernel's test
/// against one plane when it has one (Filtered_exact_kernel's
/// Orientation_3_against_plane: its filter's minors of a, b, c computed
/// once, the same answers), else its orientation_3.
template <class K>
auto orientation_against(const K& k, const typename K::Point_3& a, const typename K::Point_3& b,
                         const typename K::Point_3& c) {
  if constexpr (requires { typename K::Orientation_3_against_plane; }) {
    (void)k;
    return typename K::Orientation_3_against_plane(a, b, c);
  } else {
    return [orient = k.orientation_3_object(), &a, &b, &c](const typename K::Point_3& s) { return orient(a, b, c, s); };
  }
}

}  // namespace relgeo::internal
