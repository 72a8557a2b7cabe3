// relgeo/io/contour_json.h — the contour of an extruded object (thesis Sec.
// 3.4.1) from JSON, as `relgeo extrusion` reads it. Needs nlohmann-json
// (relgeo::io).
//
// A JSON object with
//   "degree": v and "points": [[x, y], ...]   a closed chain of M v points:
//                                             curve m has the control points
//                                             m v .. m v + v (mod M v)
//   or "curves": [[[x, y], ...], ...]         each curve's control points; the
//                                             last point of curve m equals the
//                                             first of curve m+1 (mod M)
// Points may be [x, y, z]: then "direction": [dx, dy, dz] is required, the
// points must lie on one plane orthogonal to d (within the uncertainty) and
// are rotated by the Q carrying d to the z axis (relgeo::project_along).
// Optional: "heights": [l1, l2] (l1 < l2), "uncertainty" (relative, default
// 1e-3), "absolute_uncertainty" (default 0), "name", "comment".
// Errors (io/errors.h): not JSON, a missing or mistyped field, an unknown
// field: Parse_error; a NaN or infinite number (1e999): Non_finite_input; an
// open contour, a degree below 1, points off the plane: Invalid_input.
#pragma once

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "relgeo/curves/contour.h"
#include "relgeo/io/json.h"
#include "relgeo/io/text_file.h"

namespace relgeo::io {

/// A contour read from JSON, with what the file says about it.
struct Contour_input {
  std::string source;                          ///< file name (or "<stdin>")
  std::optional<Bezier_contour> contour;       ///< always set by read_contour_json
  bool three_d = false;                        ///< the points were [x, y, z]
  std::optional<Plane_projection> projection;  ///< 3D input: the rotation applied
  std::optional<std::pair<double, double>> heights;
  double relative_uncertainty = 1e-3;
  double absolute_uncertainty = 0;
};

/// Uncertainties that replace the file's (e.g. from the command line).
struct Contour_overrides {
  std::optional<double> relative_uncertainty;
  std::optional<double> absolute_uncertainty;
};

namespace internal {

class Contour_reader {
 public:
  Contour_reader(const Json& j, std::string source) : j_(j), source_(std::move(source)) {}

  Contour_input read(const Contour_overrides& overrides) {
    check_fields();
    in_.source = source_;
    read_uncertainties(overrides);
    read_heights();
    const std::vector<std::vector<Point_3<double>>> curves = j_.contains("points") ? chain_curves() : listed_curves();
    project(curves);
    return std::move(in_);
  }

 private:
  [[noreturn]] void fail(const std::string& message) const { throw Parse_error(source_, 0, message); }
  [[noreturn]] void invalid(const std::string& message) const { throw Invalid_input(source_ + ": " + message); }

  double number(const Json& v, const std::string& what) const {
    if (!v.is_number()) fail(what + ": expected a number, got " + v.dump());
    const double x = v.get<double>();
    if (!std::isfinite(x)) throw Non_finite_input(source_ + ": " + what + ": not a finite number");
    return x;
  }

  /// [x, y] or [x, y, z]; the first point fixes the dimension.
  Point_3<double> point(const Json& v, const std::string& what) {
    if (!v.is_array() || (v.size() != 2 && v.size() != 3))
      fail(what + ": expected [x, y] or [x, y, z], got " + v.dump());
    const int d = static_cast<int>(v.size());
    if (dim_ == 0) dim_ = d;
    if (d != dim_)
      fail(what + ": " + std::to_string(d) + " coordinates, but earlier points have " + std::to_string(dim_));
    return {number(v[0], what), number(v[1], what), d == 3 ? number(v[2], what) : 0.0};
  }

  void check_fields() const {
    if (!j_.is_object()) fail("expected a JSON object");
    static const std::set<std::string, std::less<>> known = {
        "degree", "points", "curves", "direction", "heights", "uncertainty", "absolute_uncertainty", "name", "comment"};
    for (auto it = j_.begin(); it != j_.end(); ++it)
      if (!known.count(it.key())) fail("unknown field \"" + it.key() + "\"");
    if (j_.contains("points") == j_.contains("curves")) fail("give either \"points\" (with \"degree\") or \"curves\"");
  }

  void read_uncertainties(const Contour_overrides& o) {
    for (auto [key, value] : {std::pair{"uncertainty", &in_.relative_uncertainty},
                              std::pair{"absolute_uncertainty", &in_.absolute_uncertainty}}) {
      if (!j_.contains(key)) continue;
      *value = number(j_[key], key);
      if (*value < 0) invalid(std::string(key) + " must be >= 0");
    }
    if (o.relative_uncertainty) in_.relative_uncertainty = *o.relative_uncertainty;
    if (o.absolute_uncertainty) in_.absolute_uncertainty = *o.absolute_uncertainty;
  }

  void read_heights() {
    if (!j_.contains("heights")) return;
    const Json& h = j_["heights"];
    if (!h.is_array() || h.size() != 2) fail("heights: expected [l1, l2]");
    const double l1 = number(h[0], "heights"), l2 = number(h[1], "heights");
    if (!(l1 < l2)) invalid("heights: l1 < l2 required");
    in_.heights = std::pair{l1, l2};
  }

  /// "degree" and "points": a closed chain cut into curves of that degree.
  std::vector<std::vector<Point_3<double>>> chain_curves() {
    if (!j_.contains("degree") || !j_["degree"].is_number_integer()) fail("\"points\" needs an integer \"degree\"");
    const long long v = j_["degree"].get<long long>();
    if (v < 1) invalid("degree " + std::to_string(v) + ": the degree must be at least 1");
    const Json& pts = j_["points"];
    if (!pts.is_array() || pts.empty()) fail("points: expected a non-empty array of points");
    std::vector<Point_3<double>> chain;
    for (std::size_t i = 0; i < pts.size(); ++i) chain.push_back(point(pts[i], "points[" + std::to_string(i) + "]"));
    const auto deg = static_cast<std::size_t>(v);
    if (chain.size() % deg != 0)
      invalid(std::to_string(chain.size()) + " points do not form a closed chain of degree-" + std::to_string(deg) +
              " curves (need a multiple of " + std::to_string(deg) + ")");
    std::vector<std::vector<Point_3<double>>> curves(chain.size() / deg);
    for (std::size_t m = 0; m < curves.size(); ++m)
      for (std::size_t i = 0; i <= deg; ++i) curves[m].push_back(chain[(m * deg + i) % chain.size()]);
    return curves;
  }

  /// "curves": each curve's control points; consecutive curves must meet.
  std::vector<std::vector<Point_3<double>>> listed_curves() {
    if (j_.contains("degree")) fail("\"degree\" goes with \"points\", not with \"curves\"");
    const Json& cs = j_["curves"];
    if (!cs.is_array() || cs.empty()) fail("curves: expected a non-empty array of curves");
    std::vector<std::vector<Point_3<double>>> curves(cs.size());
    for (std::size_t m = 0; m < cs.size(); ++m) {
      const std::string w = "curves[" + std::to_string(m) + "]";
      if (!cs[m].is_array()) fail(w + ": expected an array of control points");
      if (cs[m].size() < 2)
        invalid(w + ": degree " + std::to_string(static_cast<long>(cs[m].size()) - 1) +
                "; a curve needs at least 2 control points (degree >= 1)");
      for (std::size_t i = 0; i < cs[m].size(); ++i) curves[m].push_back(point(cs[m][i], w + "[" + std::to_string(i) + "]"));
    }
    for (std::size_t m = 0; m < curves.size(); ++m) {
      const auto& a = curves[m].back();
      const auto& b = curves[(m + 1) % curves.size()].front();
      if (!(a == b))
        invalid("the contour is not closed: curve " + std::to_string(m) + " ends at " + text(a) + " but curve " +
                std::to_string((m + 1) % curves.size()) + " starts at " + text(b));
    }
    return curves;
  }

  std::string text(const Point_3<double>& p) const {
    std::string s = "(";  // appended piecewise: GCC 12 warns (-Wrestrict) on "(" + std::string&&
    s += format_17(p.x);
    s += ", ";
    s += format_17(p.y);
    if (dim_ == 3) s += ", " + format_17(p.z);
    return s + ")";
  }

  Point_3<double> direction() const {
    const Json& d = j_["direction"];
    if (!d.is_array() || d.size() != 3) fail("direction: expected [dx, dy, dz]");
    return {number(d[0], "direction"), number(d[1], "direction"), number(d[2], "direction")};
  }

  /// 3D input: rotated to the plane orthogonal to the direction (with the
  /// points' norms as scales); 2D input: taken as it is.
  void project(const std::vector<std::vector<Point_3<double>>>& curves) {
    in_.three_d = dim_ == 3;
    std::vector<std::vector<Point_2<double>>> planar(curves.size());
    std::vector<std::vector<double>> scales(curves.size());
    if (in_.three_d) {
      if (!j_.contains("direction")) fail("3D points need \"direction\": [dx, dy, dz]");
      std::vector<Point_3<double>> all;
      for (const auto& c : curves) all.insert(all.end(), c.begin(), c.end());
      try {
        in_.projection = project_along(all, direction());
      } catch (const Non_finite_input& e) {
        throw Non_finite_input(source_ + ": " + e.what());
      } catch (const Invalid_input& e) {
        invalid(e.what());
      }
      check_plane(*in_.projection);
      std::size_t k = 0;
      for (std::size_t m = 0; m < curves.size(); ++m)
        for (std::size_t i = 0; i < curves[m].size(); ++i, ++k) {
          planar[m].push_back(in_.projection->points[k]);
          scales[m].push_back(in_.projection->norms[k]);
        }
    } else {
      if (j_.contains("direction")) {
        const Point_3<double> d = direction();
        if (d.x != 0 || d.y != 0 || d.z == 0)
          invalid("2D points lie in the xy plane: the direction must be (0, 0, +-1); give 3D points for another direction");
      }
      for (std::size_t m = 0; m < curves.size(); ++m)
        for (const auto& p : curves[m]) planar[m].push_back({p.x, p.y});
    }
    try {
      in_.contour = Bezier_contour::from_curves(planar);
    } catch (const Invalid_input& e) {
      invalid(e.what());
    }
    if (in_.three_d) in_.contour->set_scales(scales);
  }

  void check_plane(const Plane_projection& p) const {
    const double max_norm = p.norms.empty() ? 0.0 : *std::max_element(p.norms.begin(), p.norms.end());
    const double tolerance = in_.relative_uncertainty * max_norm + in_.absolute_uncertainty;
    if (p.height_max - p.height_min > tolerance)
      invalid("the points are not on one plane orthogonal to the direction: d.x ranges over [" + format_17(p.height_min) +
              ", " + format_17(p.height_max) + "], more than the uncertainty " + format_17(tolerance) + " allows");
  }

  const Json& j_;
  std::string source_;
  Contour_input in_;
  int dim_ = 0;
};

}  // namespace internal

/// The contour described by the JSON text; `source` names it in errors.
inline Contour_input parse_contour_json(std::string_view text, const std::string& source,
                                        const Contour_overrides& overrides = {}) {
  const Json j = parse_json(text, source);
  return internal::Contour_reader(j, source).read(overrides);
}

/// The contour of the JSON file `path`.
inline Contour_input read_contour_json(const std::string& path, const Contour_overrides& overrides = {}) {
  return parse_contour_json(read_text_file(path, "contour file"), path, overrides);
}

}  // namespace relgeo::io
