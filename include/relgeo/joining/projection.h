// relgeo/joining/projection.h — closest points on a NURBS surface: a point X
// in space to its parameters (u,v) and its height eta along the unit normal,
// X = F(u,v) + eta n(u,v) (thesis Sec. 4.2; Sec. 4.3.2 steps 1 and 2).
//
// Method. Starting points come from a grid of surface samples (4 per knot
// span and direction, at least 16, at most 128) held in a kd-tree. From a
// start, a damped Newton iteration (Levenberg-Marquardt on the full Hessian
// of |F - X|^2 / 2, solved with Eigen) converges to a local minimum of the
// distance. The result is accepted only when it is unique: every sample
// within distance d* + h of X (d* the distance found, h the largest distance
// between neighbouring samples) that is not next to the solution in (u,v)
// starts another iteration, and a second minimum not farther than
// d* (1 + uniqueness_ratio) is a Projection_error (not_unique); so is a point
// on the concave side beyond focal_ratio times the radius of curvature
// (eta k_i >= focal_ratio for a principal curvature k_i: there the projection
// is ill-conditioned and, at 1, no longer locally unique). A minimum beyond the domain extended by `extrapolation`
// of each parameter range is outside_domain; an iteration that does not
// converge is no_convergence.
//
// Needs Eigen (link relgeo::eigen).
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <queue>
#include <span>
#include <string>
#include <vector>

#include "relgeo/core/errors.h"
#include "relgeo/core/floating_point.h"
#include "relgeo/joining/internal/point_tree.h"
#include "relgeo/joining/joining_errors.h"
#include "relgeo/kernel/point.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/surfaces/nurbs_surface.h"

namespace relgeo {

/// Options of Surface_projector (defaults in brackets).
struct Projection_options {
  /// Starting samples per knot span and direction [4], clamped to
  /// [min_samples, max_samples] per direction [16, 128].
  int samples_per_span = 4;
  int min_samples = 16;
  int max_samples = 128;
  /// How far beyond the parameter domain a solution may lie, as a fraction of
  /// each parameter range [0.05]: the end spans' polynomials are used there
  /// (a mesh vertex may stick out a little beyond a patch's edge).
  double extrapolation = 0.05;
  /// Newton iterations per start [60].
  int max_iterations = 60;
  /// A second local minimum not farther than d* (1 + ratio) makes the
  /// projection ambiguous [1e-6].
  double uniqueness_ratio = 1e-6;
  /// Largest eta k_i accepted (k_i a principal curvature, signed along the
  /// normal: the concave side) [0.5].
  double focal_ratio = 0.5;
};

/// The projection of a point: parameters, signed height along the unit
/// normal Su x Sv / |Su x Sv|, distance |eta|, Newton iterations spent.
struct Surface_projection {
  Point_2<double> uv;
  double height = 0;
  int iterations = 0;
};

/// \brief Projects points onto one NURBS surface (thread-safe after
/// construction: project() is const).
class Surface_projector {
 public:
  static constexpr std::size_t no_index = std::numeric_limits<std::size_t>::max();

  explicit Surface_projector(Nurbs_surface<double> surface, const Projection_options& options = {})
      : surface_(std::move(surface)), options_(options) {
    const auto [u0, u1] = surface_.domain_u();
    const auto [v0, v1] = surface_.domain_v();
    lo_ = {u0 - options_.extrapolation * (u1 - u0), v0 - options_.extrapolation * (v1 - v0)};
    hi_ = {u1 + options_.extrapolation * (u1 - u0), v1 + options_.extrapolation * (v1 - v0)};
    range_ = {u1 - u0, v1 - v0};
    const auto count = [&](int p, const std::vector<double>& U, std::size_t n) {
      int spans = 0;
      for (std::size_t k = static_cast<std::size_t>(p); k < n; ++k) spans += U[k] < U[k + 1];
      return std::clamp(options_.samples_per_span * spans, options_.min_samples, options_.max_samples);
    };
    nu_ = count(surface_.degree_u(), surface_.knots_u(), surface_.count_u());
    nv_ = count(surface_.degree_v(), surface_.knots_v(), surface_.count_v());
    std::vector<std::array<double, 3>> pts;
    for (int i = 0; i <= nu_; ++i)
      for (int j = 0; j <= nv_; ++j) {
        const Point_2<double> uv = sample_uv(i, j);
        const Point_3<double> p = surface_.evaluate(uv.x, uv.y);
        if (!all_finite(p.x, p.y, p.z)) throw Degenerate_surface("Surface_projector: the surface is not finite");
        pts.push_back({p.x, p.y, p.z});
      }
    double lo[3] = {pts[0][0], pts[0][1], pts[0][2]}, hi[3] = {lo[0], lo[1], lo[2]};
    for (const auto& p : pts)
      for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
    scale_ = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    for (int i = 0; i <= nu_; ++i)
      for (int j = 0; j <= nv_; ++j) {
        const auto& p = pts[static_cast<std::size_t>(i * (nv_ + 1) + j)];
        if (i < nu_) spacing_ = std::max(spacing_, distance(p, pts[static_cast<std::size_t>((i + 1) * (nv_ + 1) + j)]));
        if (j < nv_) spacing_ = std::max(spacing_, distance(p, pts[static_cast<std::size_t>(i * (nv_ + 1) + j + 1)]));
      }
    tree_ = internal::Point_tree<3>(std::move(pts));
  }

  const Nurbs_surface<double>& surface() const { return surface_; }
  const Projection_options& options() const { return options_; }
  /// Diagonal of the surface's bounding box (length scale of tolerances).
  double scale() const { return scale_; }

  /// F(uv) + height * n(uv). \throws Degenerate_surface where n is undefined.
  Point_3<double> lift(const Point_2<double>& uv, double height) const {
    const Surface_derivatives<double> d = surface_.derivatives(uv.x, uv.y, 1);
    const Vector_3<double> n = unit_normal(d);
    return {d.point.x + height * n[0], d.point.y + height * n[1], d.point.z + height * n[2]};
  }

  /// \brief The unique closest point of x on the surface.
  /// \param hint parameters near the expected answer (a neighbour's), or none.
  /// \param index the caller's index of x, reported in a Projection_error.
  /// \throws Projection_error, Degenerate_surface (no normal at the solution),
  /// Non_finite_input.
  Surface_projection project(const Point_3<double>& x, std::optional<Point_2<double>> hint = std::nullopt,
                             std::size_t index = no_index) const {
    if (!all_finite(x.x, x.y, x.z))
      throw Non_finite_input("Surface_projector: point " + index_name(index) + "is not finite");
    std::vector<Local_minimum> minima;
    const auto run = [&](Point_2<double> start) {
      if (auto m = newton(x, start)) minima.push_back(*m);
    };
    if (hint) run(*hint);
    if (!hint || minima.empty() || minima.front().failed)
      for (const auto& [d2, i] : tree_.nearest({x.x, x.y, x.z}, 3)) run(sample_uv_of(i));
    const Local_minimum* best = nullptr;
    for (const auto& m : minima)
      if (!m.failed && (!best || m.distance < best->distance)) best = &m;
    if (!best) {
      const bool outside = std::any_of(minima.begin(), minima.end(), [](const Local_minimum& m) { return m.outside; });
      throw Projection_error(outside ? Projection_failure::outside_domain : Projection_failure::no_convergence,
                             "projection of point " + index_name(index) +
                                 (outside ? "leaves the surface's domain" : "does not converge"),
                             index);
    }
    // Other minima near enough to compete: from every sample within reach
    // that is not next to the solution in (u,v).
    Local_minimum chosen = *best;
    const double reach = chosen.distance * (1 + options_.uniqueness_ratio) + spacing_ + 1e-12 * scale_;
    const double du = 2.5 * (hi_.x - lo_.x) / nu_, dv = 2.5 * (hi_.y - lo_.y) / nv_;
    std::vector<std::uint32_t> far;
    tree_.for_each_within({x.x, x.y, x.z}, reach, [&](std::uint32_t i) {
      const Point_2<double> s = sample_uv_of(i);
      if (std::abs(s.x - chosen.uv.x) > du || std::abs(s.y - chosen.uv.y) > dv) far.push_back(i);
    });
    for (std::uint32_t i : far) {
      const auto m = newton(x, sample_uv_of(i));
      if (!m || m->failed) continue;
      if (same_point(*m, chosen)) continue;
      if (m->distance < chosen.distance * (1 - options_.uniqueness_ratio) - 1e-12 * scale_) {
        chosen = *m;  // the first one was a farther local minimum
        continue;
      }
      if (m->distance <= chosen.distance * (1 + options_.uniqueness_ratio) + 1e-12 * scale_)
        throw Projection_error(Projection_failure::not_unique,
                               "projection of point " + index_name(index) + "is not unique: (" +
                                   std::to_string(chosen.uv.x) + ", " + std::to_string(chosen.uv.y) + ") and (" +
                                   std::to_string(m->uv.x) + ", " + std::to_string(m->uv.y) + ") are equally close",
                               index);
    }
    if (chosen.outside)
      throw Projection_error(Projection_failure::outside_domain,
                             "projection of point " + index_name(index) + "leaves the surface's domain", index);
    return finish(x, chosen, index);
  }

  /// Projects a sequence in order, each point starting from the previous
  /// solution (a polyline: boundary samples). \throws as project().
  std::vector<Surface_projection> project_polyline(std::span<const Point_3<double>> points) const {
    std::vector<Surface_projection> out;
    std::optional<Point_2<double>> hint;
    for (std::size_t i = 0; i < points.size(); ++i) {
      out.push_back(project(points[i], hint, i));
      hint = out.back().uv;
    }
    return out;
  }

  /// Projects every vertex of a mesh, each (after the first of its connected
  /// component) starting from an already projected neighbour's solution
  /// (breadth-first order). \throws Projection_error naming the vertex.
  template <class P>
  std::vector<Surface_projection> project_mesh(const Triangle_mesh<P>& m) const {
    const std::size_t n = m.vertices.size();
    std::vector<std::vector<Index>> adjacent(n);
    for (const Triangle& t : m.faces)
      for (int k = 0; k < 3; ++k)
        if (t[k] < n && t[(k + 1) % 3] < n) adjacent[t[k]].push_back(t[(k + 1) % 3]), adjacent[t[(k + 1) % 3]].push_back(t[k]);
    std::vector<Surface_projection> out(n);
    std::vector<char> done(n, 0);
    for (Index s = 0; s < n; ++s) {
      if (done[s]) continue;
      std::queue<std::pair<Index, Index>> queue;  // (vertex, projected neighbour or invalid)
      queue.push({s, invalid_index});
      done[s] = 1;
      while (!queue.empty()) {
        const auto [v, parent] = queue.front();
        queue.pop();
        const auto hint = parent == invalid_index ? std::nullopt : std::optional<Point_2<double>>(out[parent].uv);
        out[v] = project(m.vertices[v], hint, v);
        for (Index w : adjacent[v])
          if (!done[w]) done[w] = 1, queue.push({w, v});
      }
    }
    return out;
  }

 private:
  struct Local_minimum {
    Point_2<double> uv;
    double distance = 0;
    int iterations = 0;
    bool outside = false;  // stuck at the extended domain's border
    bool failed = false;   // no convergence
  };

  static double distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  }
  static std::string index_name(std::size_t index) {
    return index == no_index ? std::string() : std::to_string(index) + " ";
  }
  Point_2<double> sample_uv(int i, int j) const {
    const auto [u0, u1] = surface_.domain_u();
    const auto [v0, v1] = surface_.domain_v();
    return {i == nu_ ? u1 : u0 + (u1 - u0) * i / nu_, j == nv_ ? v1 : v0 + (v1 - v0) * j / nv_};
  }
  Point_2<double> sample_uv_of(std::uint32_t k) const {
    return sample_uv(static_cast<int>(k) / (nv_ + 1), static_cast<int>(k) % (nv_ + 1));
  }
  bool same_point(const Local_minimum& a, const Local_minimum& b) const {
    return std::abs(a.uv.x - b.uv.x) <= 1e-7 * range_.x && std::abs(a.uv.y - b.uv.y) <= 1e-7 * range_.y;
  }

  // Damped Newton from `start` (Levenberg-Marquardt: H + lambda diag(J^T J)).
  std::optional<Local_minimum> newton(const Point_3<double>& x, Point_2<double> uv) const {
    uv.x = std::clamp(uv.x, lo_.x, hi_.x), uv.y = std::clamp(uv.y, lo_.y, hi_.y);
    double lambda = 1e-6;
    Surface_derivatives<double> d = surface_.derivatives(uv.x, uv.y, 2);
    Vector_3<double> r{d.point.x - x.x, d.point.y - x.y, d.point.z - x.z};
    double f = internal::dot<double, 3>(r, r);
    Local_minimum result;
    for (int it = 1; it <= options_.max_iterations; ++it) {
      const double gu = internal::dot<double, 3>(d.du, r), gv = internal::dot<double, 3>(d.dv, r);
      const double E = internal::dot<double, 3>(d.du, d.du), F = internal::dot<double, 3>(d.du, d.dv),
                   G = internal::dot<double, 3>(d.dv, d.dv);
      const double rn = std::sqrt(f);
      // First-order optimality: r orthogonal to both tangents, up to an angle
      // of 1e-12 and to the rounding error of F itself (r vanishes for a
      // point on the surface).
      const double slack = 1e-14 * rn + 2e-15 * scale_;
      // At the extended domain's border, a gradient pushing outward is the
      // border's reaction (projected gradient): the minimum is beyond it.
      const double pu = blocked(uv.x, lo_.x, hi_.x, gu) ? 0.0 : gu, pv = blocked(uv.y, lo_.y, hi_.y, gv) ? 0.0 : gv;
      if (std::abs(pu) <= slack * std::sqrt(E) && std::abs(pv) <= slack * std::sqrt(G)) {
        result.uv = uv, result.distance = rn, result.iterations = it;
        result.outside = pu != gu || pv != gv;
        return result;
      }
      Eigen::Matrix2d H;
      H << E + internal::dot<double, 3>(r, d.duu), F + internal::dot<double, 3>(r, d.duv),
          F + internal::dot<double, 3>(r, d.duv), G + internal::dot<double, 3>(r, d.dvv);
      const Eigen::Vector2d g(gu, gv);
      bool accepted = false;
      for (int attempt = 0; attempt < 30 && !accepted; ++attempt, lambda *= 10) {
        Eigen::Matrix2d A = H;
        A(0, 0) += lambda * E, A(1, 1) += lambda * G;
        const Eigen::LDLT<Eigen::Matrix2d> ldlt(A);
        if (ldlt.info() != Eigen::Success || !ldlt.isPositive() || (ldlt.vectorD().array() <= 0).any()) continue;
        const Eigen::Vector2d step = ldlt.solve(-g);
        Point_2<double> next{std::clamp(uv.x + step(0), lo_.x, hi_.x), std::clamp(uv.y + step(1), lo_.y, hi_.y)};
        if (next.x == uv.x && next.y == uv.y) {  // no move possible: at the border or at the limit of precision
          result.uv = uv, result.distance = rn, result.iterations = it;
          result.outside = outside(uv);
          result.failed = !result.outside && !nearly_stationary(gu, gv, E, G, rn);
          return result;
        }
        const Surface_derivatives<double> dn = surface_.derivatives(next.x, next.y, 2);
        const Vector_3<double> rn2{dn.point.x - x.x, dn.point.y - x.y, dn.point.z - x.z};
        const double fn = internal::dot<double, 3>(rn2, rn2);
        if (fn <= f) {
          uv = next, d = dn, r = rn2, f = fn;
          lambda = std::max(lambda / 100, 1e-12);
          accepted = true;
        }
      }
      if (!accepted) {  // no descent at any damping: a minimum to rounding accuracy
        result.uv = uv, result.distance = std::sqrt(f), result.iterations = it;
        result.outside = outside(uv);
        result.failed = !result.outside && !nearly_stationary(gu, gv, E, G, std::sqrt(f));
        return result;
      }
    }
    result.uv = uv, result.distance = std::sqrt(f), result.iterations = options_.max_iterations;
    result.outside = outside(uv);
    result.failed = !result.outside;
    return result;
  }
  // The minimisation of f along x is blocked by the border at x: x sits on
  // it and the descent direction -g points outward.
  static bool blocked(double x, double lo, double hi, double g) { return (x <= lo && g > 0) || (x >= hi && g < 0); }
  // A weaker optimality test for iterations stopped by rounding.
  bool nearly_stationary(double gu, double gv, double E, double G, double rn) const {
    const double slack = 1e-9 * rn + 1e-12 * scale_;
    return std::abs(gu) <= slack * std::sqrt(E) && std::abs(gv) <= slack * std::sqrt(G);
  }
  bool outside(const Point_2<double>& uv) const {
    const double eu = 1e-12 * range_.x, ev = 1e-12 * range_.y;
    return uv.x <= lo_.x + eu || uv.x >= hi_.x - eu || uv.y <= lo_.y + ev || uv.y >= hi_.y - ev;
  }

  Surface_projection finish(const Point_3<double>& x, const Local_minimum& m, std::size_t index) const {
    const Surface_derivatives<double> d = surface_.derivatives(m.uv.x, m.uv.y, 2);
    const Vector_3<double> nd = normal_direction(d);
    const double len = std::sqrt(internal::dot<double, 3>(nd, nd));
    const double E = internal::dot<double, 3>(d.du, d.du), F = internal::dot<double, 3>(d.du, d.dv),
                 G = internal::dot<double, 3>(d.dv, d.dv);
    if (!(len > 1e-10 * std::sqrt(E * G)))
      throw Degenerate_surface("projection of point " + index_name(index) + "lands where Su x Sv vanishes (u = " +
                               std::to_string(m.uv.x) + ", v = " + std::to_string(m.uv.y) + ")");
    const Vector_3<double> n{nd[0] / len, nd[1] / len, nd[2] / len};
    const double height = (x.x - d.point.x) * n[0] + (x.y - d.point.y) * n[1] + (x.z - d.point.z) * n[2];
    // Signed principal curvatures k1, k2 (eigenvalues of I^-1 II, II along
    // n): the squared distance to x has Hessian I - height II, which loses
    // definiteness where height k_i reaches 1 (x at a focal point, on the
    // concave side).
    const double L = internal::dot<double, 3>(d.duu, n), M = internal::dot<double, 3>(d.duv, n),
                 N = internal::dot<double, 3>(d.dvv, n);
    const double det_i = E * G - F * F;
    const double half_trace = 0.5 * (E * N - 2 * F * M + G * L) / det_i;  // (k1 + k2) / 2
    const double gauss = (L * N - M * M) / det_i;                          // k1 k2
    const double disc = std::sqrt(std::max(0.0, half_trace * half_trace - gauss));
    const double focal = std::max(height * (half_trace + disc), height * (half_trace - disc));
    if (focal >= options_.focal_ratio)
      throw Projection_error(Projection_failure::not_unique,
                             "projection of point " + index_name(index) + "is ill-conditioned: height * curvature = " +
                                 std::to_string(focal) + " >= " + std::to_string(options_.focal_ratio),
                             index);
    return {m.uv, height, m.iterations};
  }

  Nurbs_surface<double> surface_;
  Projection_options options_;
  Point_2<double> lo_, hi_, range_;
  int nu_ = 16, nv_ = 16;
  double scale_ = 1, spacing_ = 0;
  internal::Point_tree<3> tree_;
};

}  // namespace relgeo
