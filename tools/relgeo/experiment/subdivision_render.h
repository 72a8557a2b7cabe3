// tools/relgeo/experiment/subdivision_render.h — a small orthographic renderer for the
// pictures of the subdivision experiment: flat shading, z-buffer, optional
// wire frame, optional colour per face from a value (bound widths).
#pragma once

#include <string>
#include <vector>

#include "commands/subdivide/facade.h"
#include "relgeo/io/png.h"

namespace relgeo::tool {

struct Render_options {
  int width = 520, height = 520;
  double azimuth_deg = 35, elevation_deg = 25;  ///< view direction
  bool wire = false;                            ///< draw the edges
  /// Per face values coloured on a logarithmic blue-green-yellow-red scale
  /// from value_min to value_max (empty: grey).
  std::vector<double> face_values;
  double value_min = 0, value_max = 1;
  std::string legend;  ///< drawn as a colour bar at the bottom when values are given
};

/// The picture of a triangle mesh. `frame` (optional) fixes the view box so
/// several meshes render at the same scale.
io::Image render_mesh(const Mesh_double& mesh, const Render_options& options, const Mesh_double* frame = nullptr);

}  // namespace relgeo::tool
