// tools/relgeo/commands/subdivide/run_with.h — the kernel-templated body of
// run_subdivision and the two halves of the subdivision kernels, instantiated
// in dispatch_float.cpp (double-valued kernels) and dispatch_exact.cpp
// (intervals, rationals, MPFR), so the two compile in parallel. Include it
// only there.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "commands/subdivide/facade.h"
#include "kernels/dispatch.h"
#include "relgeo/core/internal/stopwatch.h"
#include "relgeo/kernel/vector_3.h"
#include "relgeo/mesh/mesh_topology.h"
#include "relgeo/subdivision.h"

namespace relgeo::tool {

/// The subdivision kernels with float, double or long double coordinates
/// (naive, failsafe, filtered): dispatch_float.cpp.
struct Subdivision_float_kernels {
  template <class K>
  static constexpr bool check() {
    if constexpr (is_cgal_kernel_v<K>) return false;  // no CGAL type is completed here
    else return std::is_floating_point_v<typename K::FT>;
  }
  template <class K>
  static constexpr bool admits = check<K>();
};

/// The interval, rational and MPFR (53 and 113 bits) kernels: dispatch_exact.cpp.
struct Subdivision_exact_kernels {
  template <class K>
  static constexpr bool check() {
    if constexpr (is_cgal_kernel_v<K> || mpfr_bits_v<K> > 0) return mpfr_bits_v<K> == 53 || mpfr_bits_v<K> == 113;
    else return !std::is_floating_point_v<typename K::FT>;
  }
  template <class K>
  static constexpr bool admits = check<K>();
};

/// The exact half of the dispatch (dispatch_exact.cpp); false when the
/// kernel is not one of its kernels.
bool run_subdivision_exact_kernels(const Mesh_double& input, const Subdivision_request& request,
                                   Subdivision_result& result);
/// The exact half of evaluate_limit_surface's dispatch (dispatch_exact.cpp);
/// false when the kernel is not one of its kernels.
bool evaluate_limit_surface_exact_kernels(const std::string& kernel, const Mesh_double& control,
                                          const std::vector<std::int64_t>& faces, const std::vector<double>& u,
                                          const std::vector<double>& v, const Loop_options& options,
                                          std::vector<Point_3<double>>& points);

namespace subdivision_detail {

template <class P>
Point_3<double> to_double(const P& p) {
  using A = internal::Point_access<P>;
  return {internal::coordinate_to_double(A::x(p)), internal::coordinate_to_double(A::y(p)),
          internal::coordinate_to_double(A::z(p))};
}
template <class P>
Mesh_double to_double_mesh(const Triangle_mesh<P>& m) {
  Mesh_double r;
  r.vertices.reserve(m.vertices.size());
  for (const P& p : m.vertices) r.vertices.push_back(to_double(p));
  r.faces = m.faces;
  r.tags = m.tags;
  return r;
}

using internal::cross;
using internal::difference;
using internal::dot;
inline double norm(const Point_3<double>& a) { return std::sqrt(dot(a, a)); }
/// The point (u, v) of face f of m (w v0 + u v1 + v v2).
inline Point_3<double> face_point(const Mesh_double& m, Index f, double u, double v) {
  const auto& a = m.vertices[m.faces[f][0]];
  const auto& b = m.vertices[m.faces[f][1]];
  const auto& c = m.vertices[m.faces[f][2]];
  const double w = 1 - u - v;
  return {w * a.x + u * b.x + v * c.x, w * a.y + u * b.y + v * c.y, w * a.z + u * b.z + v * c.z};
}

/// `input` in the kernel's points.
template <class K>
Triangle_mesh<typename K::Point_3> kernel_mesh(const Mesh_double& input) {
  const auto cp = K().construct_point_3_object();
  Triangle_mesh<typename K::Point_3> m;
  m.vertices.reserve(input.vertices.size());
  for (const auto& p : input.vertices) m.vertices.push_back(cp(p.x, p.y, p.z));
  m.faces = input.faces;
  m.tags = input.tags;
  return m;
}

}  // namespace subdivision_detail

/// evaluate_limit_surface (facade.h) under K.
template <class K>
std::vector<Point_3<double>> evaluate_limit_surface_with(const Mesh_double& control,
                                                         const std::vector<std::int64_t>& faces,
                                                         const std::vector<double>& u, const std::vector<double>& v,
                                                         const Loop_options& options) {
  using namespace subdivision_detail;
  const Loop_limit_surface<K> surface(kernel_mesh<K>(control), options);
  std::vector<Point_3<double>> points;
  points.reserve(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (faces[i] < 0 || static_cast<std::uint64_t>(faces[i]) >= surface.number_of_faces())
      throw Invalid_surface_parameter("Loop limit surface: face " + std::to_string(faces[i]) + " out of range (" +
                                      std::to_string(surface.number_of_faces()) + " faces)");
    points.push_back(to_double(surface.evaluate(static_cast<Index>(faces[i]), u[i], v[i])));
  }
  return points;
}

template <class K>
Subdivision_result run_subdivision_with(const Mesh_double& input, const Subdivision_request& rq) {
  using namespace subdivision_detail;
  using P = typename K::Point_3;
  using FT = typename K::FT;
  Subdivision_result res;
  res.kernel = find_kernel(rq.kernel).label();
  res.kernel_model = K::name();
  const Triangle_mesh<P> m = kernel_mesh<K>(input);

  internal::Stopwatch clock;
  Loop_subdivider<K> subdivider(rq.options);
  const Triangle_mesh<P> R = subdivider.refine(m, rq.levels);
  const Triangle_mesh<P> L = subdivider.limit_mesh(m, rq.levels);
  res.time_subdivision = clock.elapsed();
  res.refined = to_double_mesh(R);
  res.limit = to_double_mesh(L);

  res.input_edges = Mesh_topology::build(input).number_of_edges();
  const Mesh_topology rt = Mesh_topology::build(res.refined);
  res.refined_edges = rt.number_of_edges();
  for (Index v = 0; v < res.refined.vertices.size(); ++v) ++res.valence_histogram[rt.valence(v)];
  {
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (const auto& p : res.limit.vertices) {
      const double c[3] = {p.x, p.y, p.z};
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
    }
    res.mesh_size = res.limit.vertices.empty() ? 0 : std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  }
  if (rq.exact_limit_vertices) {
    res.rounding = 0;
    for (std::size_t v = 0; v < res.limit.vertices.size(); ++v)
      res.rounding = std::max(res.rounding, norm(difference(res.limit.vertices[v], (*rq.exact_limit_vertices)[v])));
  }

  // Sampling: distances of the refined and the limit mesh to the limit surface.
  clock.restart();
  const Loop_limit_surface<K> surface(R, rq.options);
  const std::size_t nf = R.faces.size();
  for (Index f = 0; f < nf; ++f) ++res.patch_kinds[int(surface.patch_kind(f))];
  const auto grid = rq.samples > 0 ? dyadic_samples(rq.samples) : std::vector<std::pair<double, double>>{};
  std::vector<double> height(nf * grid.size());  // signed distance from the limit face's plane
  res.face_offset.assign(nf, 0);
  for (Index f = 0; f < nf && !grid.empty(); ++f) {
    const auto& q = res.limit.vertices;
    const Point_3<double> n =
        cross(difference(q[L.faces[f][1]], q[L.faces[f][0]]), difference(q[L.faces[f][2]], q[L.faces[f][0]]));
    const double len = norm(n);
    for (std::size_t i = 0; i < grid.size(); ++i) {
      const auto [u, v] = grid[i];
      const Point_3<double> s =
          rq.reference ? (*rq.reference)[f * grid.size() + i] : to_double(surface.evaluate(f, u, v));
      ++res.samples;
      res.refined_distance = std::max(res.refined_distance, norm(difference(s, face_point(res.refined, f, u, v))));
      res.limit_distance = std::max(res.limit_distance, norm(difference(s, face_point(res.limit, f, u, v))));
      const double h = len > 0 ? dot(difference(s, q[L.faces[f][0]]), n) / len : 0;
      height[f * grid.size() + i] = h;
      res.face_offset[f] = std::max(res.face_offset[f], std::abs(h));
      res.limit_normal_offset = std::max(res.limit_normal_offset, std::abs(h));
    }
  }
  res.time_sampling = clock.elapsed();

  if (!rq.bounds) return res;
  clock.restart();
  Loop_bound_options bo;
  if (rq.small_bounds) bo = Loop_bound_options{.irregular_depth = 2, .regular_depth = 1, .universal_depth = 3};
  const Loop_limit_mesh_bounds<K> b = Loop_error_bounds<K>(rq.options, bo).compute(m, rq.levels);
  res.time_bounds = clock.elapsed();
  const double tol = 1e-13 * (1 + res.mesh_size);  // rounding of the double sample heights
  const auto summarise = [&](const std::string& name, auto&& bound_of, bool is_bound) {
    Bound_summary s;
    s.method = name;
    s.is_bound = is_bound;
    s.min_lower = INFINITY, s.max_upper = -INFINITY;
    double width = 0;
    std::size_t counted = 0;
    for (Index f = 0; f < nf; ++f) {
      if (b.degenerate[f]) continue;
      const auto [lo, hi] = bound_of(f);
      s.min_lower = std::min(s.min_lower, lo), s.max_upper = std::max(s.max_upper, hi);
      width += hi - lo, ++counted;
      for (std::size_t i = 0; i < grid.size(); ++i) {
        const double h = height[f * grid.size() + i];
        if (h < lo - tol || h > hi + tol) ++s.samples_outside;
      }
      if (!grid.empty() && res.face_offset[f] > 1e-9 * res.mesh_size) {
        const double t = std::max(std::abs(lo), std::abs(hi)) / res.face_offset[f];
        s.mean_tightness += t, s.max_tightness = std::max(s.max_tightness, t), ++s.tightness_faces;
      }
    }
    if (counted == 0) s.min_lower = s.max_upper = 0;
    s.mean_width = counted ? width / double(counted) : 0;
    if (s.tightness_faces) s.mean_tightness /= double(s.tightness_faces);
    res.bounds.push_back(s);
  };
  const auto of = [](const std::vector<Loop_face_bound<FT>>& v) {
    return [&v](Index f) { return std::pair{v[f].lower_distance, v[f].upper_distance}; };
  };
  summarise("basis_range", of(b.basis_range), true);
  summarise("tangent_plane", of(b.tangent_plane), true);
  summarise("direct", of(b.direct), true);
  summarise("thesis_estimate", [&](Index f) { return b.thesis_estimate[f]; }, false);
  res.face_width.assign(nf, 0);
  for (Index f = 0; f < nf; ++f)
    if (!b.degenerate[f]) res.face_width[f] = b.tangent_plane[f].upper_distance - b.tangent_plane[f].lower_distance;
  return res;
}

}  // namespace relgeo::tool
