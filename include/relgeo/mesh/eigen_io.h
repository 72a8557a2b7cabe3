// relgeo/mesh/eigen_io.h — Eigen V/F matrices (libigl's convention: V is
// #V by 3, F is #F by 3, rows counter-clockwise) in and out.
//
// The only mesh header that includes Eigen (link Eigen3::Eigen).
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <utility>

#include "relgeo/core/errors.h"
#include "relgeo/kernel/point_access.h"
#include "relgeo/mesh/mesh_errors.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo {

/// A mesh with relgeo::Point_3<Scalar> points from V (#V x 3) and F (#F x 3,
/// 0-based). \throws Invalid_input when a matrix has not 3 columns,
/// Invalid_mesh (index_out_of_range) for negative or too large indices.
template <class DerivedV, class DerivedF>
Triangle_mesh<Point_3<typename DerivedV::Scalar>> from_eigen(const Eigen::MatrixBase<DerivedV>& V,
                                                             const Eigen::MatrixBase<DerivedF>& F) {
  using S = typename DerivedV::Scalar;
  if (V.cols() != 3 || F.cols() != 3)
    throw Invalid_input("from_eigen: V and F must have 3 columns (V is " + std::to_string(V.rows()) + "x" +
                        std::to_string(V.cols()) + ", F is " + std::to_string(F.rows()) + "x" +
                        std::to_string(F.cols()) + ")");
  Triangle_mesh<Point_3<S>> m;
  m.vertices.reserve(static_cast<std::size_t>(V.rows()));
  for (Eigen::Index i = 0; i < V.rows(); ++i) m.vertices.push_back({V(i, 0), V(i, 1), V(i, 2)});
  std::vector<Mesh_issue> issues;
  m.faces.reserve(static_cast<std::size_t>(F.rows()));
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    Triangle t;
    for (int k = 0; k < 3; ++k) {
      const auto i = F(f, k);
      if (i < 0 || static_cast<std::size_t>(i) >= m.vertices.size())
        issues.push_back({Mesh_defect::index_out_of_range, {static_cast<Index>(f), static_cast<Index>(i)}});
      t[k] = static_cast<Index>(i);
    }
    m.faces.push_back(t);
  }
  if (!issues.empty()) throw Invalid_mesh("from_eigen", std::move(issues));
  return m;
}

/// V (#V x 3, coordinates converted to double) and F (#F x 3).
template <class P>
std::pair<Eigen::MatrixXd, Eigen::MatrixXi> to_eigen(const Triangle_mesh<P>& m) {
  using A = internal::Point_access<P>;
  Eigen::MatrixXd V(static_cast<Eigen::Index>(m.vertices.size()), 3);
  Eigen::MatrixXi F(static_cast<Eigen::Index>(m.faces.size()), 3);
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const Eigen::Index r = static_cast<Eigen::Index>(i);
    V(r, 0) = internal::coordinate_to_double(A::x(m.vertices[i]));
    V(r, 1) = internal::coordinate_to_double(A::y(m.vertices[i]));
    V(r, 2) = internal::coordinate_to_double(A::z(m.vertices[i]));
  }
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    for (int k = 0; k < 3; ++k) F(static_cast<Eigen::Index>(f), k) = static_cast<int>(m.faces[f][k]);
  return {std::move(V), std::move(F)};
}

}  // namespace relgeo
