// tools/relgeo/extrusion_runs.h — the extruded-object checker under a kernel
// and a hull algorithm chosen at run time, its input format (JSON), its
// report (JSON, text) and picture (SVG).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "json_output.h"
#include "relgeo/curves/contour.h"
#include "relgeo/curves/extrusion.h"

namespace relgeo::tool {

/// A parsed contour description (format: extrusion_help_footer()).
struct Extrusion_input {
  std::string source;
  std::optional<Bezier_contour> contour;  ///< always set by parse_extrusion_input
  bool three_d = false;
  std::optional<Plane_projection> projection;  ///< 3D input
  std::optional<std::pair<double, double>> heights;
  double relative_uncertainty = 1e-3;
  double absolute_uncertainty = 0;
};

/// Parses the JSON text; `relative` / `absolute` (>= 0) override the file's
/// uncertainties (they also set the tolerance of the plane check of 3D input).
/// \throws Usage_error naming `source` and the field.
Extrusion_input parse_extrusion_input(const std::string& text, const std::string& source,
                                      std::optional<double> relative = std::nullopt,
                                      std::optional<double> absolute = std::nullopt);

/// Runs check_extrusion under `kernel` with `algorithm` (names of `relgeo
/// hull`; `cgal` only with cgal-* kernels), timed (fastest of repeated runs
/// until min_seconds).   [extrusion_eval.cpp]
Extrusion_report run_extrusion(std::string_view algorithm, std::string_view kernel, const Bezier_contour& contour,
                               const Extrusion_options& options, double* time_s, double min_seconds = 0);

/// The JSON report (fields: extrusion_help_footer()).
Json extrusion_report_json(const Extrusion_input& in, std::string_view kernel, std::string_view algorithm,
                           const Extrusion_options& options, const Extrusion_report& r, double time_s);
/// The readable report.
std::string extrusion_report_text(const Extrusion_input& in, std::string_view kernel, std::string_view algorithm,
                                  const Extrusion_options& options, const Extrusion_report& r, double time_s);
/// The contour (curves sampled), control polygons and hulls, offending curves
/// highlighted; 640 x 640 viewBox, y up. \throws Usage_error when unwritable.
void write_extrusion_svg(const std::string& path, const Bezier_contour& contour, const Extrusion_report& r,
                         const std::string& title);

/// A measure as JSON ("inf"/"-inf" strings for infinities) and as text.
Json extrusion_measure_json(double v);
std::string extrusion_measure_text(double v);

}  // namespace relgeo::tool
