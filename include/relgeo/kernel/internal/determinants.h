// relgeo/kernel/internal/determinants.h — the one source of each predicate's
// arithmetic (STYLE rule 5): every relgeo kernel evaluates exactly these
// expressions, in its own number type.
//
// orientation_2 uses pivot p: (qx-px)(ry-py) - (qy-py)(rx-px), the form of
// Kettner et al. and of CGAL's orientationC2. orientation_3 uses CGAL's
// cofactor order (CGAL/determinant.h), so the naive double kernel agrees bit
// for bit with CGAL::Simple_cartesian<double>. Compile with -ffp-contract=off:
// a fused multiply-add changes the rounding and breaks that agreement.
#pragma once

namespace relgeo::internal {

/// The value of the 2D orientation determinant of p, q, r in number type FT.
template <class FT>
FT orientation_2_determinant(const FT& px, const FT& py, const FT& qx, const FT& qy,
                             const FT& rx, const FT& ry) {
  const FT a = qx - px;  // explicit FT temporaries: no expression templates escape
  const FT b = ry - py;
  const FT c = qy - py;
  const FT d = rx - px;
  const FT ab = a * b;
  const FT cd = c * d;
  return FT(ab - cd);
}

/// The cofactors of the 3D orientation determinant that do not depend on s
/// (the minors of q - p and r - p), and the determinant from them: one
/// plane (p, q, r) against several points s with the operations of
/// orientation_3_determinant, in its order (the same value, bit for bit).
template <class FT>
struct Orientation_3_minors {
  FT px, py, pz, m01, m02, m12;
  [[gnu::always_inline]] Orientation_3_minors(const FT& px_, const FT& py_, const FT& pz_, const FT& qx, const FT& qy,
                                              const FT& qz, const FT& rx, const FT& ry, const FT& rz)
      : px(px_), py(py_), pz(pz_) {
    const FT a00 = qx - px, a01 = rx - px;
    const FT a10 = qy - py, a11 = ry - py;
    const FT a20 = qz - pz, a21 = rz - pz;
    m01 = FT(a00 * a11) - FT(a10 * a01);
    m02 = FT(a00 * a21) - FT(a20 * a01);
    m12 = FT(a10 * a21) - FT(a20 * a11);
  }
  [[gnu::always_inline]] FT determinant(const FT& sx, const FT& sy, const FT& sz) const {
    const FT a02 = sx - px, a12 = sy - py, a22 = sz - pz;
    const FT t = FT(m01 * a22) - FT(m02 * a12);
    return FT(t + FT(m12 * a02));
  }
};

/// The value of the 3D orientation determinant of p, q, r, s in number type FT
/// (positive when s lies on the positive side of the plane pqr, i.e. pqrs is a
/// positively oriented tetrahedron, as in CGAL).
template <class FT>
FT orientation_3_determinant(const FT& px, const FT& py, const FT& pz, const FT& qx,
                             const FT& qy, const FT& qz, const FT& rx, const FT& ry,
                             const FT& rz, const FT& sx, const FT& sy, const FT& sz) {
  return Orientation_3_minors<FT>(px, py, pz, qx, qy, qz, rx, ry, rz).determinant(sx, sy, sz);
}

}  // namespace relgeo::internal
