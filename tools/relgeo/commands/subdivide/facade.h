// tools/relgeo/commands/subdivide/facade.h — what `relgeo subdivide` and the
// experiment's subdivision section run: refinement, limit meshes, sampled
// distances to the exact limit surface and error bounds under a kernel named
// at run time (instantiated in dispatch_float.cpp and dispatch_exact.cpp
// only).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "relgeo/kernel/point.h"
#include "relgeo/mesh/triangle_mesh.h"
#include "relgeo/subdivision/loop_weights.h"

namespace relgeo::tool {

/// The kernels `subdivide` accepts (a subset of the tool's list).   [dispatch_float.cpp]
const std::vector<std::string>& subdivision_kernel_names();
/// The refinement levels `subdivide` accepts, 0..12. \throws Usage_error otherwise.  [dispatch_float.cpp]
unsigned subdivision_levels(int levels);
/// hoppe | blz. \throws Usage_error otherwise.                    [dispatch_float.cpp]
Loop_crease_rules parse_crease_rules(const std::string& name);
/// Throws Usage_error unless `name` is one of subdivision_kernel_names().
void validate_subdivision_kernel(const std::string& name);


/// One bound method summarised over the faces of a limit mesh.
struct Bound_summary {
  std::string method;               ///< basis_range | tangent_plane | direct | thesis_estimate
  double min_lower = 0, max_upper = 0;  ///< over the faces, signed distances along the face normals
  double mean_width = 0;            ///< mean of upper - lower
  double mean_tightness = 0, max_tightness = 0;  ///< max(|lower|, |upper|) / sampled max |offset|
  long tightness_faces = 0;         ///< faces with a sampled offset > 1e-9 * size (others are flat)
  long samples_outside = 0;         ///< samples outside the bound (beyond the rounding allowance)
  bool is_bound = true;             ///< false for thesis_estimate (not a bound)
};

/// What one run computes.
struct Subdivision_request {
  std::string kernel = "double";
  unsigned levels = 1;
  Loop_options options{};
  bool bounds = false;
  int samples = 8;  ///< per face side, power of two; 0: no sampling
  /// Reference samples of the exact limit surface (per face of the level-k
  /// mesh, dyadic grid of `samples`), computed elsewhere; empty: sample the
  /// surface with this run's own kernel.
  const std::vector<Point_3<double>>* reference = nullptr;
  /// Exact limit-mesh vertices for the rounding measure (empty: skipped).
  const std::vector<Point_3<double>>* exact_limit_vertices = nullptr;
  /// Reduced depths for slow kernels (exact).
  bool small_bounds = false;
};

struct Subdivision_result {
  std::string kernel, kernel_model;
  Mesh_double refined, limit;  ///< level-k control mesh and limit mesh, as doubles
  std::size_t input_edges = 0, refined_edges = 0;
  std::map<unsigned, std::size_t> valence_histogram;  ///< of the level-k mesh
  std::size_t patch_kinds[3] = {0, 0, 0};             ///< regular, regular_crease, irregular
  long samples = 0;
  double refined_distance = 0;       ///< max |S(u,v) - refined face(u,v)|
  double limit_distance = 0;         ///< max |S(u,v) - limit face(u,v)|
  double limit_normal_offset = 0;    ///< max distance of S(u,v) from the limit face's plane
  double mesh_size = 0;              ///< bounding-box diagonal of the limit mesh
  double rounding = -1;              ///< max |limit vertex - exact limit vertex| (-1: not measured)
  std::vector<Bound_summary> bounds;
  std::vector<double> face_width;    ///< per face: tangent_plane upper - lower (pictures)
  std::vector<double> face_offset;   ///< per face: sampled max |normal offset|
  double time_subdivision = 0, time_sampling = 0, time_bounds = 0;
};

/// Refines (and takes the limit mesh of) `input` under request.kernel,
/// samples the limit surface and computes the bounds. Throws relgeo::Error
/// for bad meshes, Usage_error for an unsupported kernel.
Subdivision_result run_subdivision(const Mesh_double& input, const Subdivision_request& request);

/// The points of the limit surface of `control` (relgeo::Loop_limit_surface)
/// at the parameters (faces[i], u[i], v[i]) (the point w a + u b + v c of
/// face (a, b, c) when the surface is the face), under the kernel named
/// (one of subdivision_kernel_names()), rounded to double.
/// \throws Invalid_surface_parameter for a face out of range or (u, v)
/// outside the triangle, Non_finite_input for NaN parameters or coordinates,
/// Invalid_mesh for a mesh Loop's scheme refuses, Usage_error for a kernel
/// without constructions.                [dispatch_float.cpp, dispatch_exact.cpp]
std::vector<Point_3<double>> evaluate_limit_surface(const std::string& kernel, const Mesh_double& control,
                                                    const std::vector<std::int64_t>& faces,
                                                    const std::vector<double>& u, const std::vector<double>& v,
                                                    const Loop_options& options);

/// Samples of the exact (GMP rational) limit surface of `input` over every
/// face of its level-`levels` refinement (dyadic grid `samples` per side, in
/// the order of dyadic_samples), rounded to double; and the exact limit-mesh
/// vertices.                                            [dispatch_exact.cpp]
void exact_reference(const Mesh_double& input, unsigned levels, const Loop_options& options, int samples,
                     std::vector<Point_3<double>>& surface, std::vector<Point_3<double>>& limit_vertices);

/// The dyadic sample parameters (i / n, j / n), i + j <= n.
std::vector<std::pair<double, double>> dyadic_samples(int n);

}  // namespace relgeo::tool
