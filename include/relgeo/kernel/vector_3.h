// relgeo/kernel/vector_3.h — differences, dot and cross products of
// 3-vectors, written once: relgeo::Point_3<NT> read as a vector, and
// std::array<NT, D> (the spline code's vectors and plain double triples).
//
// On points every difference and product is a named NT temporary (no
// expression template escapes, as in internal/determinants.h); in doubles
// that is the plain formula, evaluated in the same order.
#pragma once

#include <array>
#include <cstddef>

#include "relgeo/kernel/point.h"

namespace relgeo::internal {

/// a - b.
template <class NT>
Point_3<NT> difference(const Point_3<NT>& a, const Point_3<NT>& b) {
  return {NT(a.x - b.x), NT(a.y - b.y), NT(a.z - b.z)};
}
template <class NT>
Point_3<NT> cross(const Point_3<NT>& a, const Point_3<NT>& b) {
  return {NT(NT(a.y * b.z) - NT(a.z * b.y)), NT(NT(a.z * b.x) - NT(a.x * b.z)), NT(NT(a.x * b.y) - NT(a.y * b.x))};
}
template <class NT>
NT dot(const Point_3<NT>& a, const Point_3<NT>& b) {
  return NT(NT(NT(a.x * b.x) + NT(a.y * b.y)) + NT(a.z * b.z));
}

template <class NT, std::size_t D>
NT dot(const std::array<NT, D>& a, const std::array<NT, D>& b) {
  NT s = a[0] * b[0];
  for (std::size_t i = 1; i < D; ++i) s += a[i] * b[i];
  return s;
}
template <class NT>
std::array<NT, 3> cross(const std::array<NT, 3>& a, const std::array<NT, 3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace relgeo::internal
