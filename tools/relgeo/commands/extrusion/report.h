// tools/relgeo/commands/extrusion/report.h — the extrusion check as the tool
// reports it: JSON, readable text, SVG picture.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "relgeo/curves/extrusion.h"
#include "relgeo/io/contour_json.h"
#include "relgeo/io/json.h"

namespace relgeo::tool {

/// The options `relgeo extrusion` checks a contour file with: its
/// uncertainties and the rotation error of its plane, pruning, the cap on
/// the listed problems.
Extrusion_options extrusion_options_for(const io::Contour_input& input, bool prune, std::size_t max_listed);

/// The JSON report (fields: extrusion_help_footer()).
io::Json extrusion_report_json(const io::Contour_input& in, std::string_view kernel, std::string_view algorithm,
                               const Extrusion_options& options, const Extrusion_report& r, double time_s);
/// The readable report.
std::string extrusion_report_text(const io::Contour_input& in, std::string_view kernel, std::string_view algorithm,
                                  const Extrusion_options& options, const Extrusion_report& r, double time_s);
/// The contour (curves sampled), control polygons and hulls, offending curves
/// highlighted; 640 x 640 viewBox, y up. \throws io::Unwritable_file.
void write_extrusion_svg(const std::string& path, const Bezier_contour& contour, const Extrusion_report& r,
                         const std::string& title);

}  // namespace relgeo::tool
