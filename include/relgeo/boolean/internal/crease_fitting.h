// relgeo/boolean/internal/crease_fitting.h — the optional fitting step of a
// subdivision Boolean (thesis eq. 5.4): move the control points near the
// intersection curves so that the limit positions of the result's vertices
// approach their targets (the polyhedral result's vertices: on the curves,
// the exact intersection of the limit meshes; elsewhere, the operands' own
// limit positions).
//
// Linear least squares: a vertex's limit position is its limit stencil
// (loop_masks.h, with the result's crease tags) applied to the control
// points, so with the free points x (the curve vertices and `rings` rings
// around them) and every other point fixed,
//     minimise  sum_j |L_j x + c_j - target_j|^2 + mu |x - x0|^2
// over the vertices j whose stencil touches a free point. The small pull mu
// towards the unfitted points x0 keeps the normal equations positive
// definite (a free point no stencil constrains stays put). Solved by a
// sparse Cholesky factorisation (Eigen), one solve per coordinate.
#pragma once

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

#include "relgeo/kernel/kernel_for_number.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/loop_features.h"
#include "relgeo/subdivision/loop_masks.h"
#include "relgeo/subdivision/loop_weights.h"

namespace relgeo::internal {

/// The fitted control mesh (same faces and tags), or nothing when the
/// factorisation fails. `moved` receives the number of free points.
inline std::optional<Triangle_mesh<Point_3<double>>> fit_control_points(const Triangle_mesh<Point_3<double>>& control,
                                                                       const std::vector<Point_3<double>>& target,
                                                                       const std::vector<Index>& curve, unsigned rings,
                                                                       double mu, const Loop_options& loop,
                                                                       std::size_t& moved) {
  using K = Kernel_for_number<double>::type;
  const Mesh_topology t = Mesh_topology::build(control);
  const Loop_features features = classify_loop_features(t, control.tags);
  Loop_weights<K> weights(loop);
  const std::size_t nv = control.vertices.size();
  // Free points: the curves and `rings` rings around them.
  std::vector<Index> free_index(nv, invalid_index);
  std::vector<Index> free;
  for (Index v : curve) free_index[v] = 0, free.push_back(v);
  for (unsigned r = 0, begin = 0; r < rings; ++r) {
    const std::size_t end = free.size();
    for (std::size_t i = begin; i < end; ++i)
      for (Index w : t.vertex_ring(free[i]))
        if (free_index[w] == invalid_index) free_index[w] = 0, free.push_back(w);
    begin = static_cast<unsigned>(end);
  }
  for (Index i = 0; i < free.size(); ++i) free_index[free[i]] = i;
  moved = free.size();
  // Rows: the vertices whose limit stencil reads a free point (the free
  // points and their neighbours).
  std::vector<char> is_row(nv, 0);
  std::vector<Index> rows;
  for (Index v : free) {
    if (!is_row[v]) is_row[v] = 1, rows.push_back(v);
    for (Index w : t.vertex_ring(v))
      if (!is_row[w]) is_row[w] = 1, rows.push_back(w);
  }
  Index max_valence = 6;
  for (Index v = 0; v < nv; ++v) max_valence = std::max(max_valence, t.valence(v));
  weights.reserve(max_valence + 1);
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()), 3);
  for (Index r = 0; r < rows.size(); ++r) {
    const Index j = rows[r];
    const Stencil<double> s = limit_stencil(t, features, weights, j);
    double c[3] = {target[j].x, target[j].y, target[j].z};
    for (std::size_t i = 0; i < s.vertices.size(); ++i) {
      const Index v = s.vertices[i];
      if (free_index[v] != invalid_index) {
        entries.emplace_back(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(free_index[v]), s.weights[i]);
      } else {
        const Point_3<double>& p = control.vertices[v];
        c[0] -= s.weights[i] * p.x, c[1] -= s.weights[i] * p.y, c[2] -= s.weights[i] * p.z;
      }
    }
    for (int k = 0; k < 3; ++k) rhs(static_cast<Eigen::Index>(r), k) = c[k];
  }
  Eigen::SparseMatrix<double> L(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(free.size()));
  L.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseMatrix<double> normal = L.transpose() * L;
  Eigen::MatrixXd x0(static_cast<Eigen::Index>(free.size()), 3);
  for (Index i = 0; i < free.size(); ++i) {
    const Point_3<double>& p = control.vertices[free[i]];
    x0(i, 0) = p.x, x0(i, 1) = p.y, x0(i, 2) = p.z;
  }
  Eigen::SparseMatrix<double> identity(normal.rows(), normal.cols());
  identity.setIdentity();
  normal += mu * identity;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
  if (solver.info() != Eigen::Success) return std::nullopt;
  const Eigen::MatrixXd b = L.transpose() * rhs + mu * x0;
  const Eigen::MatrixXd x = solver.solve(b);
  if (solver.info() != Eigen::Success || !x.allFinite()) return std::nullopt;
  Triangle_mesh<Point_3<double>> out = control;
  for (Index i = 0; i < free.size(); ++i) out.vertices[free[i]] = {x(i, 0), x(i, 1), x(i, 2)};
  return out;
}

}  // namespace relgeo::internal
