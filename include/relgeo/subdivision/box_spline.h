// relgeo/subdivision/box_spline.h — the regular Loop patch: the quartic
// three-direction box spline over 12 control points, its quartic triangular
// Bezier form (15 coefficients), evaluation with derivatives, and the 12-point
// nets of its four children.
//
// Parameter domain of a face (v0, v1, v2): (u, v) with u, v >= 0, u + v <= 1;
// w = 1 - u - v. The corners (0,0), (1,0), (0,1) belong to v0, v1, v2 (the
// limit positions of those vertices); the point (u, v) of the patch lies over
// w v0 + u v1 + v v2. Every number is computed in the number type FT of the
// caller, from integer tables (so exactly under GMP rationals, as enclosures
// under intervals).
//
// Control points of a regular patch: the face's vertices and the 9 vertices
// around them, in lattice coordinates (v0 = (0,0), v1 = (1,0), v2 = (0,1);
// the mesh's counter-clockwise order is the lattice's):
//
//   row y = 2:          10 (-1,2)   9 (0,2)
//   row y = 1:     11 (-1,1)   2 (0,1)   8 (1,1)
//   row y = 0:  3 (-1,0)   0 (0,0)   1 (1,0)   7 (2,0)
//   row y = -1:      4 (0,-1)   5 (1,-1)   6 (2,-1)
// (lattice edges along (1,0), (0,1) and (1,-1); the face is 0-1-2).
//
// The tables below were derived in exact rational arithmetic by
// test/subdivision/derivation/derive_box_spline_tables.py: refine a lattice
// of symbolic control points twice with Loop's regular rules, take the limit
// positions (1/2 p + 1/12 sum of the 6 neighbours) at the 15 level-2 vertices
// of the triangle, interpolate them with the quartic Bernstein basis (the
// principal lattice of degree 4 is unisolvent), and check that all 45 level-3
// limit points lie on that quartic. The Bezier corner coefficient is the limit
// mask (12 p + 2 sum) / 24; the coefficients next to a corner lie in its
// tangent plane. The child nets are Loop's regular rules read off the refined
// lattice. (The same tables appear in the literature, e.g. Lai 1992 for the
// box-spline-to-Bezier conversion; these were derived independently.)
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "relgeo/kernel/point.h"

namespace relgeo {

/// Lattice coordinates of the 12 control points of a regular patch (see the
/// file comment): points 0, 1, 2 are the face's vertices.
inline constexpr std::array<std::array<int, 2>, 12> loop_patch_lattice{
    {{0, 0}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, -1}, {2, -1}, {2, 0}, {1, 1}, {0, 2}, {-1, 2}, {-1, 1}}};

/// Powers (of w, u, v) of the 15 quartic Bernstein polynomials, in the order
/// of the Bezier coefficients: index quartic_bezier_index(j, k) for u^j v^k.
inline constexpr std::array<std::array<int, 3>, 15> quartic_bezier_powers{
    {{4, 0, 0}, {3, 1, 0}, {2, 2, 0}, {1, 3, 0}, {0, 4, 0}, {3, 0, 1}, {2, 1, 1}, {1, 2, 1}, {0, 3, 1},
     {2, 0, 2}, {1, 1, 2}, {0, 2, 2}, {1, 0, 3}, {0, 1, 3}, {0, 0, 4}}};

/// Index of the Bezier coefficient with powers (4 - j - k, j, k).
constexpr int quartic_bezier_index(int j, int k) { return 5 * k - k * (k - 1) / 2 + j; }
/// Index of the cubic Bezier coefficient with powers (3 - j - k, j, k).
constexpr int cubic_bezier_index(int j, int k) { return 4 * k - k * (k - 1) / 2 + j; }
/// Multinomial 3! / (i! j! k!) of each cubic Bernstein polynomial, in
/// cubic_bezier_index order.
inline constexpr int cubic_multinomial[10] = {1, 3, 3, 1, 3, 6, 3, 3, 3, 1};

/// Bezier coefficient c (quartic_bezier_powers order) of the regular patch =
/// sum_i loop_patch_bezier_x24[c][i] p_i / 24 (rows sum to 24).
inline constexpr int loop_patch_bezier_x24[15][12] = {
    {12, 2, 2, 2, 2, 2, 0, 0, 0, 0, 0, 2},  {12, 4, 3, 0, 1, 3, 0, 0, 0, 0, 0, 1},
    {8, 8, 4, 0, 0, 4, 0, 0, 0, 0, 0, 0},   {4, 12, 3, 0, 0, 3, 1, 0, 1, 0, 0, 0},
    {2, 12, 2, 0, 0, 2, 2, 2, 2, 0, 0, 0},  {12, 3, 4, 1, 0, 1, 0, 0, 0, 0, 0, 3},
    {10, 6, 6, 0, 0, 1, 0, 0, 0, 0, 0, 1},  {6, 10, 6, 0, 0, 1, 0, 0, 1, 0, 0, 0},
    {3, 12, 4, 0, 0, 1, 0, 1, 3, 0, 0, 0},  {8, 4, 8, 0, 0, 0, 0, 0, 0, 0, 0, 4},
    {6, 6, 10, 0, 0, 0, 0, 0, 1, 0, 0, 1},  {4, 8, 8, 0, 0, 0, 0, 0, 4, 0, 0, 0},
    {4, 3, 12, 0, 0, 0, 0, 0, 1, 0, 1, 3},  {3, 4, 12, 0, 0, 0, 0, 0, 3, 1, 0, 1},
    {2, 2, 12, 0, 0, 0, 0, 0, 2, 2, 2, 2}};

/// Control point i of child c = sum_j loop_patch_child_x16[c][i][j] p_j / 16.
/// Children as in Loop_subdivider's numbering: face (v0, v1, v2) with new
/// vertices m_i on edge (v_i, v_i+1) has children 0: (v0, m0, m2),
/// 1: (v1, m1, m0), 2: (v2, m2, m1), 3: (m0, m1, m2), each with its own
/// lattice as in the file comment.
inline constexpr int loop_patch_child_x16[4][12][12] = {
    {{10, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 1}, {6, 6, 2, 0, 0, 2, 0, 0, 0, 0, 0, 0},
     {6, 2, 6, 0, 0, 0, 0, 0, 0, 0, 0, 2},  {6, 0, 0, 6, 2, 0, 0, 0, 0, 0, 0, 2},
     {6, 0, 0, 2, 6, 2, 0, 0, 0, 0, 0, 0},  {6, 2, 0, 0, 2, 6, 0, 0, 0, 0, 0, 0},
     {2, 6, 0, 0, 0, 6, 2, 0, 0, 0, 0, 0},  {1, 10, 1, 0, 0, 1, 1, 1, 1, 0, 0, 0},
     {2, 6, 6, 0, 0, 0, 0, 0, 2, 0, 0, 0},  {1, 1, 10, 0, 0, 0, 0, 0, 1, 1, 1, 1},
     {2, 0, 6, 0, 0, 0, 0, 0, 0, 0, 2, 6},  {6, 0, 2, 2, 0, 0, 0, 0, 0, 0, 0, 6}},
    {{1, 10, 1, 0, 0, 1, 1, 1, 1, 0, 0, 0}, {2, 6, 6, 0, 0, 0, 0, 0, 2, 0, 0, 0},
     {6, 6, 2, 0, 0, 2, 0, 0, 0, 0, 0, 0},  {0, 6, 0, 0, 0, 2, 6, 2, 0, 0, 0, 0},
     {0, 6, 0, 0, 0, 0, 2, 6, 2, 0, 0, 0},  {0, 6, 2, 0, 0, 0, 0, 2, 6, 0, 0, 0},
     {0, 2, 6, 0, 0, 0, 0, 0, 6, 2, 0, 0},  {1, 1, 10, 0, 0, 0, 0, 0, 1, 1, 1, 1},
     {6, 2, 6, 0, 0, 0, 0, 0, 0, 0, 0, 2},  {10, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 1},
     {6, 2, 0, 0, 2, 6, 0, 0, 0, 0, 0, 0},  {2, 6, 0, 0, 0, 6, 2, 0, 0, 0, 0, 0}},
    {{1, 1, 10, 0, 0, 0, 0, 0, 1, 1, 1, 1}, {6, 2, 6, 0, 0, 0, 0, 0, 0, 0, 0, 2},
     {2, 6, 6, 0, 0, 0, 0, 0, 2, 0, 0, 0},  {0, 0, 6, 0, 0, 0, 0, 0, 2, 6, 2, 0},
     {0, 0, 6, 0, 0, 0, 0, 0, 0, 2, 6, 2},  {2, 0, 6, 0, 0, 0, 0, 0, 0, 0, 2, 6},
     {6, 0, 2, 2, 0, 0, 0, 0, 0, 0, 0, 6},  {10, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 1},
     {6, 6, 2, 0, 0, 2, 0, 0, 0, 0, 0, 0},  {1, 10, 1, 0, 0, 1, 1, 1, 1, 0, 0, 0},
     {0, 6, 2, 0, 0, 0, 0, 2, 6, 0, 0, 0},  {0, 2, 6, 0, 0, 0, 0, 0, 6, 2, 0, 0}},
    {{6, 6, 2, 0, 0, 2, 0, 0, 0, 0, 0, 0},  {2, 6, 6, 0, 0, 0, 0, 0, 2, 0, 0, 0},
     {6, 2, 6, 0, 0, 0, 0, 0, 0, 0, 0, 2},  {6, 2, 0, 0, 2, 6, 0, 0, 0, 0, 0, 0},
     {2, 6, 0, 0, 0, 6, 2, 0, 0, 0, 0, 0},  {1, 10, 1, 0, 0, 1, 1, 1, 1, 0, 0, 0},
     {0, 6, 2, 0, 0, 0, 0, 2, 6, 0, 0, 0},  {0, 2, 6, 0, 0, 0, 0, 0, 6, 2, 0, 0},
     {1, 1, 10, 0, 0, 0, 0, 0, 1, 1, 1, 1}, {2, 0, 6, 0, 0, 0, 0, 0, 0, 0, 2, 6},
     {6, 0, 2, 2, 0, 0, 0, 0, 0, 0, 0, 6},  {10, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 1}}};

/// Parameters of a point of a face in its child c (the child containing it:
/// c = 0 when w >= 1/2, 1 when u >= 1/2, 2 when v >= 1/2, else 3):
///   child 0: (2u, 2v)   child 1: (2v, 2w)   child 2: (2w, 2u)
///   child 3: (1 - 2w, 1 - 2u)
/// Each map preserves orientation (Jacobian determinant 4), so normals
/// computed in a child point the same way.
inline constexpr int loop_child_jacobian[4][2][2] = {
    {{2, 0}, {0, 2}}, {{0, 2}, {-2, -2}}, {{-2, -2}, {2, 0}}, {{2, 2}, {-2, 0}}};

namespace internal {

/// sum_i table[i] * p[i] over n entries, in FT (table entries are small ints).
template <class FT, std::size_t N>
FT integer_combination(const int (&table)[N], const FT* p, std::size_t stride = 1) {
  FT r(0);
  for (std::size_t i = 0; i < N; ++i)
    if (table[i] != 0) r = FT(r + FT(FT(table[i]) * p[i * stride]));
  return r;
}

}  // namespace internal

/// The 15 Bezier coefficients of one coordinate of a regular patch, times 24
/// (divide by 24, or multiply by the exact 1/24 of the caller's number type).
/// `p` holds the 12 control values with the given stride.
template <class FT>
std::array<FT, 15> loop_patch_bezier_times_24(const FT* p, std::size_t stride = 1) {
  std::array<FT, 15> b;
  for (int c = 0; c < 15; ++c) b[c] = internal::integer_combination(loop_patch_bezier_x24[c], p, stride);
  return b;
}

/// The 12 control values of child c times 16.
template <class FT>
std::array<FT, 12> loop_patch_child_times_16(const FT* p, int child, std::size_t stride = 1) {
  std::array<FT, 12> r;
  for (int i = 0; i < 12; ++i) r[i] = internal::integer_combination(loop_patch_child_x16[child][i], p, stride);
  return r;
}

/// Value and first derivatives of a quartic triangular Bezier patch at (u, v).
template <class V>
struct Bezier_jet {
  V position, du, dv;
};

/// The 15 Bernstein values B_c(u, v) (quartic, w = 1 - u - v given).
template <class FT>
std::array<FT, 15> quartic_bernstein(const FT& w, const FT& u, const FT& v) {
  static constexpr int multinomial[15] = {1, 4, 6, 4, 1, 4, 12, 12, 4, 6, 12, 6, 4, 4, 1};
  std::array<FT, 5> pw, pu, pv;
  pw[0] = pu[0] = pv[0] = FT(1);
  for (int i = 1; i < 5; ++i) pw[i] = FT(pw[i - 1] * w), pu[i] = FT(pu[i - 1] * u), pv[i] = FT(pv[i - 1] * v);
  std::array<FT, 15> b;
  for (int c = 0; c < 15; ++c) {
    const auto& e = quartic_bezier_powers[c];
    b[c] = FT(FT(FT(multinomial[c]) * pw[e[0]]) * FT(pu[e[1]] * pv[e[2]]));
  }
  return b;
}

/// The 10 cubic Bernstein values (order cubic_bezier_index).
template <class FT>
std::array<FT, 10> cubic_bernstein(const FT& w, const FT& u, const FT& v) {
  std::array<FT, 4> pw, pu, pv;
  pw[0] = pu[0] = pv[0] = FT(1);
  for (int i = 1; i < 4; ++i) pw[i] = FT(pw[i - 1] * w), pu[i] = FT(pu[i - 1] * u), pv[i] = FT(pv[i - 1] * v);
  std::array<FT, 10> b;
  int c = 0;
  for (int k = 0; k <= 3; ++k)
    for (int j = 0; j + k <= 3; ++j, ++c) b[c] = FT(FT(FT(cubic_multinomial[c]) * pw[3 - j - k]) * FT(pu[j] * pv[k]));
  return b;
}

/// A quartic triangular Bezier patch in 3D (coefficients in
/// quartic_bezier_powers order).
template <class FT>
using Quartic_bezier_patch = std::array<Point_3<FT>, 15>;

/// Evaluates a quartic Bezier patch at (u, v), w = 1 - u - v.
template <class FT>
Point_3<FT> evaluate_quartic_bezier(const Quartic_bezier_patch<FT>& b, const FT& u, const FT& v) {
  const FT w = FT(FT(FT(1) - u) - v);
  const std::array<FT, 15> B = quartic_bernstein(w, u, v);
  Point_3<FT> r{FT(0), FT(0), FT(0)};
  for (int c = 0; c < 15; ++c) {
    r.x = FT(r.x + FT(B[c] * b[c].x));
    r.y = FT(r.y + FT(B[c] * b[c].y));
    r.z = FT(r.z + FT(B[c] * b[c].z));
  }
  return r;
}

/// Position and the partial derivatives d/du, d/dv (w = 1 - u - v) of a
/// quartic Bezier patch: d/du = 4 sum_{|c|=3} (b_{c+e_u} - b_{c+e_w}) B^3_c.
template <class FT>
Bezier_jet<Point_3<FT>> evaluate_quartic_bezier_jet(const Quartic_bezier_patch<FT>& b, const FT& u, const FT& v) {
  const FT w = FT(FT(FT(1) - u) - v);
  Bezier_jet<Point_3<FT>> r;
  r.position = evaluate_quartic_bezier(b, u, v);
  const std::array<FT, 10> B = cubic_bernstein(w, u, v);
  Point_3<FT> du{FT(0), FT(0), FT(0)}, dv{FT(0), FT(0), FT(0)};
  int c = 0;
  for (int k = 0; k <= 3; ++k)
    for (int j = 0; j + k <= 3; ++j, ++c) {
      const Point_3<FT>& bw = b[quartic_bezier_index(j, k)];
      const Point_3<FT>& bu = b[quartic_bezier_index(j + 1, k)];
      const Point_3<FT>& bv = b[quartic_bezier_index(j, k + 1)];
      du.x = FT(du.x + FT(B[c] * FT(bu.x - bw.x)));
      du.y = FT(du.y + FT(B[c] * FT(bu.y - bw.y)));
      du.z = FT(du.z + FT(B[c] * FT(bu.z - bw.z)));
      dv.x = FT(dv.x + FT(B[c] * FT(bv.x - bw.x)));
      dv.y = FT(dv.y + FT(B[c] * FT(bv.y - bw.y)));
      dv.z = FT(dv.z + FT(B[c] * FT(bv.z - bw.z)));
    }
  const FT four(4);
  r.du = Point_3<FT>{FT(four * du.x), FT(four * du.y), FT(four * du.z)};
  r.dv = Point_3<FT>{FT(four * dv.x), FT(four * dv.y), FT(four * dv.z)};
  return r;
}

/// The values at (u, v) (w = 1 - u - v given) of the 12 box-spline functions
/// of a regular patch, times 24: sum_c B_c(u, v) loop_patch_bezier_x24[c][i].
template <class FT>
std::array<FT, 12> loop_patch_basis_times_24(const FT& w, const FT& u, const FT& v) {
  const std::array<FT, 15> B = quartic_bernstein(w, u, v);
  std::array<FT, 12> r;
  for (int i = 0; i < 12; ++i) {
    r[i] = FT(0);
    for (int c = 0; c < 15; ++c) {
      if constexpr (std::is_arithmetic_v<FT>) r[i] += B[c] * FT(loop_patch_bezier_x24[c][i]);
      else if (loop_patch_bezier_x24[c][i] != 0) r[i] = FT(r[i] + FT(B[c] * FT(loop_patch_bezier_x24[c][i])));
    }
  }
  return r;
}

/// The Bezier form of a regular patch from its 12 control points (ghost
/// points of crease patches already resolved), each coefficient the table's
/// combination times `one_24` (the caller's 1/24 in FT: exact for rationals,
/// an enclosure for intervals).
template <class FT>
Quartic_bezier_patch<FT> loop_patch_to_bezier(const std::array<Point_3<FT>, 12>& p, const FT& one_24) {
  std::array<FT, 12> x, y, z;
  for (int i = 0; i < 12; ++i) x[i] = p[i].x, y[i] = p[i].y, z[i] = p[i].z;
  const auto bx = loop_patch_bezier_times_24(x.data()), by = loop_patch_bezier_times_24(y.data()),
             bz = loop_patch_bezier_times_24(z.data());
  Quartic_bezier_patch<FT> b;
  for (int c = 0; c < 15; ++c) b[c] = Point_3<FT>{FT(bx[c] * one_24), FT(by[c] * one_24), FT(bz[c] * one_24)};
  return b;
}

}  // namespace relgeo
