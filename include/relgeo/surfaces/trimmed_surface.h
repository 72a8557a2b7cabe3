// relgeo/surfaces/trimmed_surface.h — trimmed patches: a NURBS surface
// restricted to the region of its (u,v) domain bounded by trim loops, and the
// certified point-in-domain test.
//
// A trim loop is a closed chain of trim curves (polylines or NURBS curves in
// (u,v)); the outer loop runs counter-clockwise, holes clockwise (the
// constructor reorients loops given the other way). Each trim curve may name
// the model edge it lies on (Surface_model, surface_model.h): two faces that
// name the same edge meet along it.
//
// The domain test works on the loops flattened to polylines (chordal
// tolerance in (u,v), Trim_options): its answer is certified for that polygon
// (the kernel's orientation_2 decides every side test; comparisons of
// coordinates are exact), which is the domain every algorithm of relgeo uses.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "relgeo/core/certified_sign.h"
#include "relgeo/core/floating_point.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/kernel/point.h"
#include "relgeo/surfaces/nurbs_curve.h"
#include "relgeo/surfaces/nurbs_surface.h"
#include "relgeo/surfaces/surface_errors.h"

namespace relgeo {

/// A curve of a trim loop: its geometry in (u,v), the direction in which the
/// loop traverses it, and the model edge it lies on (-1: none).
struct Trim_curve {
  std::variant<std::vector<Point_2<double>>, Nurbs_curve_2<double>> geometry;
  /// The loop runs from the curve's end to its start.
  bool reversed = false;
  /// Index of the model edge (Surface_model::edges) this curve bounds, -1 if none.
  int edge = -1;

  bool is_polyline() const { return geometry.index() == 0; }
  /// First and last point in loop direction.
  Point_2<double> start() const { return reversed ? natural_end() : natural_start(); }
  Point_2<double> end() const { return reversed ? natural_start() : natural_end(); }

  /// The curve as a polyline in loop direction: a polyline as it is; a NURBS
  /// curve sampled by recursive bisection of each knot span until the chord
  /// deviates by at most `tolerance` (at the midpoint) and at least
  /// `min_segments_per_span` segments per span.
  std::vector<Point_2<double>> flatten(double tolerance, int min_segments_per_span = 4) const {
    std::vector<Point_2<double>> out;
    if (is_polyline()) {
      out = std::get<0>(geometry);
    } else {
      const auto& c = std::get<1>(geometry);
      const auto& U = c.knots();
      const std::size_t n = c.number_of_control_points();
      out.push_back(c.evaluate(U[c.degree()]));
      for (std::size_t k = static_cast<std::size_t>(c.degree()); k < n; ++k) {
        if (!(U[k] < U[k + 1])) continue;
        for (int s = 0; s < min_segments_per_span; ++s) {
          const double a = U[k] + (U[k + 1] - U[k]) * s / min_segments_per_span;
          const double b = s + 1 == min_segments_per_span ? U[k + 1] : U[k] + (U[k + 1] - U[k]) * (s + 1) / min_segments_per_span;
          refine(c, a, c.evaluate(a), b, c.evaluate(b), tolerance, 0, out);
        }
      }
    }
    if (reversed) std::reverse(out.begin(), out.end());
    return out;
  }

 private:
  Point_2<double> natural_start() const {
    if (is_polyline()) return std::get<0>(geometry).front();
    const auto& c = std::get<1>(geometry);
    return c.evaluate(c.domain().first);
  }
  Point_2<double> natural_end() const {
    if (is_polyline()) return std::get<0>(geometry).back();
    const auto& c = std::get<1>(geometry);
    return c.evaluate(c.domain().second);
  }
  // Appends the points after pa up to pb.
  static void refine(const Nurbs_curve_2<double>& c, double a, const Point_2<double>& pa, double b,
                     const Point_2<double>& pb, double tol, int depth, std::vector<Point_2<double>>& out) {
    const double m = 0.5 * (a + b);
    const Point_2<double> pm = c.evaluate(m);
    const double ex = pm.x - 0.5 * (pa.x + pb.x), ey = pm.y - 0.5 * (pa.y + pb.y);
    if (depth < 30 && std::sqrt(ex * ex + ey * ey) > tol) {
      refine(c, a, pa, m, pm, tol, depth + 1, out);
      refine(c, m, pm, b, pb, tol, depth + 1, out);
    } else {
      out.push_back(pb);
    }
  }
};

/// A closed chain of trim curves.
struct Trim_loop {
  std::vector<Trim_curve> curves;
};

/// How trim loops are checked and flattened.
struct Trim_options {
  /// Largest gap between consecutive curves of a loop, relative to the
  /// diagonal of the surface's parameter domain (Open_trim_loop above it).
  double closure_tolerance = 1e-7;
  /// Chordal tolerance of flattened NURBS trim curves, relative to that diagonal.
  double flattening_tolerance = 1e-4;
};

/// Where a point lies with respect to a trimmed domain.
enum class Domain_location { inside, on_boundary, outside, uncertain };

/// \brief A trimmed NURBS patch: the surface, its outer loop and holes.
///
/// The constructor checks the loops (closed within Trim_options::
/// closure_tolerance, at least three distinct points each: Open_trim_loop),
/// flattens them (domain_polygon) and orients them (outer counter-clockwise,
/// holes clockwise, by the sign of their area). `reversed` records that the
/// face's outward normal is -(Su x Sv) (B-rep faces used reversed).
class Trimmed_surface {
 public:
  Trimmed_surface() = default;
  Trimmed_surface(Nurbs_surface<double> surface, Trim_loop outer, std::vector<Trim_loop> inner = {},
                  bool reversed = false, const Trim_options& options = {})
      : surface_(std::move(surface)), outer_(std::move(outer)), inner_(std::move(inner)), reversed_(reversed),
        options_(options) {
    const auto [u0, u1] = surface_.domain_u();
    const auto [v0, v1] = surface_.domain_v();
    scale_ = std::hypot(u1 - u0, v1 - v0);
    polygon_.push_back(prepare(outer_, true, "outer trim loop"));
    for (std::size_t k = 0; k < inner_.size(); ++k)
      polygon_.push_back(prepare(inner_[k], false, "inner trim loop " + std::to_string(k)));
  }

  /// The untrimmed patch: the whole parameter rectangle as a polyline loop.
  static Trimmed_surface untrimmed(Nurbs_surface<double> surface, bool reversed = false) {
    const auto [u0, u1] = surface.domain_u();
    const auto [v0, v1] = surface.domain_v();
    Trim_loop loop;
    const Point_2<double> c[4] = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};
    for (int i = 0; i < 4; ++i) loop.curves.push_back({std::vector<Point_2<double>>{c[i], c[(i + 1) % 4]}, false, -1});
    return Trimmed_surface(std::move(surface), std::move(loop), {}, reversed);
  }

  const Nurbs_surface<double>& surface() const { return surface_; }
  const Trim_loop& outer_loop() const { return outer_; }
  const std::vector<Trim_loop>& inner_loops() const { return inner_; }
  bool reversed() const { return reversed_; }
  const Trim_options& options() const { return options_; }
  /// Diagonal of the parameter domain (the length scale of tolerances in (u,v)).
  double parameter_scale() const { return scale_; }

  /// The flattened loops: [0] the outer loop (counter-clockwise), then the
  /// holes (clockwise); each closed implicitly (last point != first).
  const std::vector<std::vector<Point_2<double>>>& domain_polygon() const { return polygon_; }

  /// \brief Where (u,v) lies relative to the flattened domain, decided by the
  /// winding number with K's certified orientation_2: `uncertain` only when
  /// K cannot decide a side test the answer depends on.
  /// \tparam K a relgeo kernel (OrientationKernel_2).
  template <OrientationKernel_2 K>
  Domain_location locate(const Point_2<double>& p, const K& k = K{}) const {
    int winding = 0;
    for (const auto& loop : polygon_) {
      const auto w = winding_number(loop, p, k);
      if (!w) return Domain_location::uncertain;
      if (*w == on_boundary_code) return Domain_location::on_boundary;
      winding += *w;
    }
    return winding != 0 ? Domain_location::inside : Domain_location::outside;
  }

  /// Winding number of the closed polygon `loop` around p (on_boundary_code
  /// when p lies on it; empty when K cannot decide).
  template <OrientationKernel_2 K>
  static std::optional<int> winding_number(const std::vector<Point_2<double>>& loop, const Point_2<double>& p,
                                           const K& k) {
    const auto orient = k.orientation_2_object();
    const auto pt = k.construct_point_2_object();
    const auto kp = pt(p.x, p.y);
    int w = 0;
    const std::size_t n = loop.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point_2<double>& a = loop[i];
      const Point_2<double>& b = loop[(i + 1) % n];
      const bool a_below = !(a.y > p.y), b_below = !(b.y > p.y);  // y <= p.y
      const bool in_y_range = std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
      const bool in_x_range = std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x);
      // An edge outside p's y range or entirely left of p neither contains p
      // nor crosses the ray from p toward +x.
      if (!in_y_range || p.x > std::max(a.x, b.x)) continue;
      // p at a vertex: decided here, exactly (a kernel without exact
      // predicates could not certify the zero orientation of (a, b, a)).
      if ((p.x == a.x && p.y == a.y) || (p.x == b.x && p.y == b.y)) return on_boundary_code;
      const Certified_sign o = orient(pt(a.x, a.y), pt(b.x, b.y), kp);
      if (!is_certain(o)) return std::nullopt;
      if (certainly(o, Certified_sign::zero) && in_x_range && in_y_range) return on_boundary_code;
      if (a_below && !b_below && certainly(o, Certified_sign::positive))
        ++w;  // upward crossing, p left of ab
      else if (!a_below && b_below && certainly(o, Certified_sign::negative))
        --w;  // downward crossing, p right of ab
    }
    return w;
  }
  static constexpr int on_boundary_code = std::numeric_limits<int>::min();

 private:
  std::vector<Point_2<double>> prepare(Trim_loop& loop, bool outer, const std::string& what) {
    if (loop.curves.empty()) throw Open_trim_loop(what + ": no curve");
    const double gap_tolerance = options_.closure_tolerance * scale_;
    std::vector<Point_2<double>> poly;
    for (std::size_t i = 0; i < loop.curves.size(); ++i) {
      const Trim_curve& c = loop.curves[i];
      if (c.is_polyline()) {
        const auto& pl = std::get<0>(c.geometry);
        if (pl.size() < 2) throw Open_trim_loop(what + ": curve " + std::to_string(i) + " has fewer than 2 points");
        for (const auto& q : pl)
          if (!all_finite(q.x, q.y)) throw Non_finite_input(what + ": curve " + std::to_string(i) + " has a non-finite point");
      }
      const Trim_curve& next = loop.curves[(i + 1) % loop.curves.size()];
      const Point_2<double> e = c.end(), s = next.start();
      const double gap = std::hypot(e.x - s.x, e.y - s.y);
      if (!(gap <= gap_tolerance))
        throw Open_trim_loop(what + ": curve " + std::to_string(i) + " ends " + std::to_string(gap) +
                             " away from the start of the next (tolerance " + std::to_string(gap_tolerance) + ")");
      std::vector<Point_2<double>> piece = c.flatten(options_.flattening_tolerance * scale_);
      for (std::size_t j = 0; j + 1 < piece.size(); ++j) append_distinct(poly, piece[j]);  // end = next start
    }
    while (poly.size() > 1 && poly.back().x == poly.front().x && poly.back().y == poly.front().y) poly.pop_back();
    if (poly.size() < 3) throw Open_trim_loop(what + ": fewer than 3 distinct points");
    const bool ccw = signed_area(poly) > 0;
    if (ccw != outer) {
      std::reverse(poly.begin(), poly.end());
      std::reverse(loop.curves.begin(), loop.curves.end());
      for (Trim_curve& c : loop.curves) c.reversed = !c.reversed;
    }
    return poly;
  }
  static void append_distinct(std::vector<Point_2<double>>& poly, const Point_2<double>& q) {
    if (poly.empty() || poly.back().x != q.x || poly.back().y != q.y) poly.push_back(q);
  }
  static double signed_area(const std::vector<Point_2<double>>& poly) {
    double a = 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const auto& p = poly[i];
      const auto& q = poly[(i + 1) % poly.size()];
      a += (p.x - q.x) * (p.y + q.y);
    }
    return 0.5 * a;  // sum of (x_i - x_i+1)(y_i + y_i+1) = sum of x_i y_i+1 - x_i+1 y_i
  }

  Nurbs_surface<double> surface_;
  Trim_loop outer_;
  std::vector<Trim_loop> inner_;
  bool reversed_ = false;
  Trim_options options_;
  double scale_ = 1;
  std::vector<std::vector<Point_2<double>>> polygon_;
};

}  // namespace relgeo
