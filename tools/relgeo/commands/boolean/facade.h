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

namespace relgeo::tool {

/// The kernels `boolean` accepts (those modelling IntersectionKernel_3).  [dispatch.cpp]
const std::vector<std::string>& boolean_kernel_names();
/// Throws Usage_error unless the kernel can run a Boolean.
void validate_boolean_kernel(const std::string& name);
/// union | intersection | difference | xor. \throws Usage_error otherwise.
Boolean_operation parse_boolean_operation(const std::string& name);

/// Checks of a mesh: combinatorial and geometric figures of the output.
struct Mesh_checks {
  bool closed = false, manifold = false, oriented = false, no_degenerate_faces = false;
  std::size_t boundary_edges = 0, non_manifold_edges = 0, non_manifold_vertices = 0, degenerate_faces = 0;
  long euler_characteristic = 0;
  std::size_t components = 0;
  double volume = 0;  ///< signed, of the doubles (positive: outward)
  std::optional<std::size_t> self_intersecting_pairs;  ///< exact test on the doubles (when asked)
};
Mesh_checks check_output(const Mesh_double& m, bool self_intersections);

/// One Boolean under one kernel.
struct Boolean_run {
  std::string kernel, kernel_model;
  bool certified = false, exact = false;
  bool ok = false;
  std::string failure;
  std::vector<std::pair<Index, Index>> undecided_pairs;
  Mesh_double output;
  double rounding_error = 0;
  std::size_t perturbations = 0;
  double largest_perturbation = 0;
  std::vector<Face_origin> provenance;
  Boolean_counts counts;
  Boolean_timing time;
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
  double hausdorff = 0;  ///< symmetric Hausdorff distance, sampled (CGAL PMP)
};
Oracle_comparison compare_with_cgal(const Mesh_double& a, const Mesh_double& b, Boolean_operation op,
                                    const Mesh_double& result);

}  // namespace relgeo::tool
