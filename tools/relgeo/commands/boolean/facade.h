// tools/relgeo/commands/boolean/facade.h — what `relgeo boolean` and the
// experiment's boolean section run: relgeo::boolean under a kernel named at
// run time (instantiated in dispatch.cpp only), and CGAL's corefinement as
// the oracle (oracle.cpp).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/boolean/boolean_types.h"
#include "render/mesh_render.h"

namespace CLI {
class App;
}  // namespace CLI

namespace relgeo::tool {

/// The kernels `boolean` accepts (those modelling IntersectionKernel_3).  [dispatch.cpp]
const std::vector<std::string>& boolean_kernel_names();
/// Throws Usage_error unless the kernel can run a Boolean.
void validate_boolean_kernel(const std::string& name);
/// union | intersection | difference | xor. \throws Usage_error otherwise.  [names.cpp]
Boolean_operation parse_boolean_operation(const std::string& name);
/// repaired | nearest. \throws Usage_error otherwise.  [names.cpp]
Output_rounding parse_output_rounding(const std::string& name);
/// --rounding repaired|nearest (boolean and csg).  [options.cpp]
void add_rounding_option(CLI::App& cmd, std::string& rounding);
/// delaunay -> true, insertion -> false. \throws Usage_error otherwise.  [names.cpp]
bool parse_delaunay_retriangulation(const std::string& name);
/// --retriangulation delaunay|insertion (boolean and csg).  [options.cpp]
void add_retriangulation_option(CLI::App& cmd, std::string& retriangulation);

/// One Boolean under one kernel: relgeo's kernel-free output (the mesh, status,
/// provenance, rounding, validation, counts, times) and what the tool adds.
struct Boolean_run : Boolean_output {
  std::string kernel, kernel_model;
  bool certified = false, exact = false;
  std::string rounding_method = "nearest";  ///< repaired | nearest, as run
  /// Exact_kernel only: self-intersecting face pairs of the result before
  /// rounding (its exact vertices); tells rounding's crossings from the
  /// Boolean's own.
  std::optional<std::size_t> exact_self_intersecting_pairs;
};
/// \throws Invalid_operand for invalid operands (with their defects), Usage_error for a kernel that cannot.
Boolean_run evaluate_boolean(const std::string& kernel, const Mesh_double& a, const Mesh_double& b, Boolean_operation op,
                             const Boolean_options& options);

/// CGAL's corefinement (Epeck) on the same operands, and how far the result
/// is from it (an empty `result`: CGAL's figures only).               [oracle.cpp]
struct Oracle_comparison {
  bool cgal_ok = false;
  double cgal_volume = 0;
  std::size_t cgal_faces = 0;
  std::optional<double> symmetric_difference_volume;  ///< |result xor CGAL's| (relgeo's exact Boolean of the two)
  double hausdorff = 0;  ///< symmetric Hausdorff distance, sampled (CGAL PMP); NaN: not manifold
};
Oracle_comparison compare_with_cgal(const Mesh_double& a, const Mesh_double& b, Boolean_operation op,
                                    const Mesh_double& result);

}  // namespace relgeo::tool
