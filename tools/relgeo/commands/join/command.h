// tools/relgeo/commands/join/command.h — `relgeo join`: mesh patches joined
// to the trimmed faces of a surface model (thesis Ch. 4; relgeo/joining).
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "cli/text.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace CLI {
class App;
}  // namespace CLI

namespace relgeo::tool {

struct Join_tool_options {
  std::string surface;               ///< .json (relgeo-surface-model), .step/.stp/.iges/.igs with OpenCASCADE
  std::vector<std::string> meshes;   ///< one mesh patch per face, in face order (OFF, OBJ, PLY, STL)
  /// Per mesh, its triangles when given in memory (the Python module): then
  /// `meshes` only names it. Empty: every mesh is read from its file.
  std::vector<std::optional<Mesh_double>> mesh_data;
  std::vector<std::string> curves;   ///< edge-curve files (JSON), optional
  std::string output;                ///< the joined mesh; empty: default_join_output
  std::string report;                ///< JSON report file, empty for none
  std::string svg;                   ///< (u,v) picture of every face, empty for none
  std::string method = "whitney";    ///< whitney | naive | occt
  std::string kernel = "filtered";   ///< the certified checks' kernel
  // Error criteria: the result fails (exit 1) when an error after joining exceeds them.
  double max_absolute_error = std::numeric_limits<double>::infinity();
  double max_normal_error = std::numeric_limits<double>::infinity();
  // Joiner parameters.
  bool no_edge_curves = false;       ///< case 2 everywhere: median polylines, not the edges' curves
  int layers = 1;                    ///< rings of peripheral triangles removed
  double min_angle = 0;              ///< Ruppert's angle bound in the external region (degrees; 0: 20.7)
  double slope_margin = 0x1p-30;     ///< L = L* (1 + margin)
  double extrapolation = 0.05;       ///< projection may leave the domain by this fraction of it
  Format format = Format::text;
};

int run_join_command(const Join_tool_options& options, Streams io);

/// The output file when none is given: the surface file's name with
/// "_joined.off" in the current folder (part.step -> part_joined.off).
std::string default_join_output(const Join_tool_options& options);

/// The text of `relgeo help join` below the options.
std::string join_help_footer();

/// Declares the options on the subcommand.         [options.cpp]
void declare_join_options(CLI::App& cmd, Join_tool_options& options);

}  // namespace relgeo::tool
