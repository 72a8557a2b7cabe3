// tools/relgeo/commands/hull/picture.h — the SVG picture of a computed hull.
#pragma once

#include <span>
#include <string>

#include "commands/hull/facade.h"

namespace relgeo::tool {

/// Writes an SVG picture of a computed hull: the input points, the computed
/// hull polygon, the exact hull (relgeo::exact_hull) dashed, lost points
/// (input points outside conv of the computed hull: backward.moved_points) as
/// red circles, computed hull vertices that are not exact-hull vertices as
/// orange squares; fitted to a 600 x 600 viewBox, y up, with a title and a
/// legend. \throws relgeo::io::Unwritable_file.
void write_hull_svg(const std::string& path, std::span<const Point_2<double>> points, const Hull_evaluation& e,
                    const std::string& title);

}  // namespace relgeo::tool
