// relgeo/boolean/subdivision_boolean.h — Booleans of two Loop subdivision
// solids whose result is again a subdivision solid (thesis Sec. 5.3-5.4,
// SPEC Sec. 5b). Needs Eigen (the fitting): link relgeo::eigen.
//
// The steps (Subdivision_boolean_timing names them):
//  1. limit meshes   each control mesh refined k times (with its creases)
//                    and pushed to its limit positions (loop_subdivision.h);
//  2. boolean        the exact Boolean of the two limit meshes under the
//                    caller's kernel: the polyhedral result, with each
//                    vertex's exact place (vertex, edge or face) on each
//                    limit mesh;
//  3. mapping        the same places on the level-k control meshes (same
//                    connectivity) give the control points; the faces the
//                    curves cross are cut as the Boolean cut their limit
//                    faces (an exact constrained retriangulation, so the
//                    thesis' quadrisection of badly crossed faces is not
//                    needed to keep the cut valid: such faces are counted);
//                    the kept parts are merged along the curves (a curve
//                    vertex at the mean of its two operands' control points)
//                    and the curves are tagged as creases, with the
//                    operands' own creases and corners: the subdivision
//                    result;
//  4. fitting        (optional, eq. 5.4) control points near the curves
//                    moved by least squares so the result's limit positions
//                    approach the polyhedral result (crease_fitting.h); kept
//                    only when the measured distance is smaller;
//  5. distance       the result's limit surface (exact evaluation,
//                    limit_evaluation.h) sampled against the polyhedral
//                    result, both ways;
//  6. validation     validate_subdivision_solid (subdivision_validation.h).
//
// Arithmetic. The limit meshes are computed in double (a few units in the
// last place from the exact limit positions of the double control points);
// the polyhedral Boolean is then exact on those doubles under exact kernels.
// The mapping and the fitting are constructions in double; the distances
// are measurements; the validation is certified as its header says.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "relgeo/boolean/internal/control_mapping.h"
#include "relgeo/boolean/internal/crease_fitting.h"
#include "relgeo/boolean/mesh_boolean.h"
#include "relgeo/boolean/subdivision_boolean_types.h"
#include "relgeo/boolean/subdivision_validation.h"
#include "relgeo/core/fp_environment.h"
#include "relgeo/core/internal/stopwatch.h"
#include "relgeo/kernel/compiled_kernels.h"
#include "relgeo/kernel/concepts.h"
#include "relgeo/mesh/point_mesh_distance.h"
#include "relgeo/mesh/validity.h"
#include "relgeo/subdivision/limit_evaluation.h"
#include "relgeo/subdivision/loop_subdivision.h"

namespace relgeo {

/// \brief Measures the distance between the limit surface of a Loop control
/// mesh and a triangle mesh: (n + 1)(n + 2) / 2 exact limit evaluations per
/// control face against the mesh, and the mesh's vertices and face centres
/// against the control mesh's limit mesh two levels finer.
/// \throws like Loop_limit_surface for a control mesh Loop's rules refuse.
inline Surface_distance limit_surface_distance(const Triangle_mesh<Point_3<double>>& control,
                                               const Triangle_mesh<Point_3<double>>& mesh, unsigned n,
                                               const Loop_options& loop = {}) {
  using K = Kernel_for_number<double>::type;
  Surface_distance d;
  if (n == 0) return d;
  const Loop_limit_surface<K> surface(control, loop);
  const Point_mesh_distance to_mesh(mesh);
  double largest = 0, sum = 0;
  for (Index f = 0; f < control.faces.size(); ++f)
    for (unsigned i = 0; i <= n; ++i)
      for (unsigned j = 0; i + j <= n; ++j) {
        const double x = to_mesh(surface.evaluate(f, double(i) / n, double(j) / n));
        largest = std::max(largest, x), sum += x, ++d.samples;
      }
  d.limit_to_polyhedral = largest;
  d.mean = d.samples ? sum / static_cast<double>(d.samples) : 0;
  const Triangle_mesh<Point_3<double>> fine = loop_limit_mesh<K>(control, 2, loop);
  const Point_mesh_distance to_limit(fine);
  double back = 0;
  for (const auto& v : mesh.vertices) back = std::max(back, to_limit(v));
  for (const Triangle& t : mesh.faces) {
    const Point_3<double>&a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    back = std::max(back, to_limit({(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3}));
  }
  d.polyhedral_to_limit = back;
  return d;
}

namespace internal {

// A control operand refused before any work: not a closed, oriented,
// finite 2-manifold with valid tags (what Loop's rules and a solid need).
inline void check_control_operand(const Triangle_mesh<Point_3<double>>& m, const char* name) {
  Mesh_report report = check_mesh<Filtered_exact_kernel>(m);
  if (!report.is_valid()) throw Invalid_operand(name, std::move(report.issues));
  require_no_faces_sharing_two_edges(Mesh_topology::build(m), "subdivision Boolean");
}

inline Operand_at_level operand_at_level(const Triangle_mesh<Point_3<double>>& m, unsigned level, const Loop_options& loop) {
  using K = Kernel_for_number<double>::type;
  Loop_subdivider<K> sub(loop);
  Operand_at_level o;
  o.control = sub.refine(m, level);
  o.limit = o.control;
  o.limit.vertices = sub.limit_positions(o.control);
  return o;
}

}  // namespace internal

/// \brief The Boolean `op` of the Loop subdivision solids bounded by control
/// meshes `s` and `s2` (with their crease and corner tags), computed on their
/// limit meshes at level `levels` under kernel K; the result is a Loop
/// control mesh with the intersection curves tagged as creases (steps: see
/// the file comment).
///
/// The symmetric difference is refused (Invalid_input): it is two solids
/// touching along the curves, a non-manifold surface that no Loop control
/// mesh represents; compute A - B and B - A instead.
/// \throws Invalid_operand when a control mesh is not a closed, oriented,
/// finite 2-manifold with valid tags (operand "A" or "B"), or when a limit
/// mesh cannot be a Boolean operand (e.g. it self-intersects: operand
/// "A (limit mesh at level k)"), before any other work.
/// A kernel that cannot decide the polyhedral Boolean (fail-safe, interval)
/// gives a failed result naming the undecided pairs (result.polyhedral).
template <IntersectionKernel_3 K = Filtered_exact_kernel>
Subdivision_boolean_result<K> subdivision_boolean(const Triangle_mesh<Point_3<double>>& s,
                                                  const Triangle_mesh<Point_3<double>>& s2, Boolean_operation op,
                                                  unsigned levels, const K& k = K{},
                                                  const Subdivision_boolean_options& options = {}) {
  if (op == Boolean_operation::symmetric_difference)
    throw Invalid_input("subdivision_boolean: the symmetric difference touches itself along the curves (not a "
                        "manifold: no Loop control mesh represents it); compute A - B and B - A separately");
  // Under a certified kernel the result does not depend on the caller's
  // floating-point environment: the limit meshes, the mapping and the fitting
  // compute in doubles, here in the default environment (the Boolean and the
  // validation hold their own scopes).
  const Default_fp_environment_if<K::is_certified> environment;
  Subdivision_boolean_result<K> r;
  r.level = levels;
  internal::Stopwatch clock;
  if (options.mesh.check_operands) {
    internal::check_control_operand(s, "A");
    internal::check_control_operand(s2, "B");
  }
  const std::array<internal::Operand_at_level, 2> at{internal::operand_at_level(s, levels, options.loop),
                                                     internal::operand_at_level(s2, levels, options.loop)};
  r.time.limit_meshes = clock.lap();
  try {
    r.polyhedral = boolean(at[0].limit, at[1].limit, op, k, options.mesh);
  } catch (const Invalid_operand& e) {
    throw Invalid_operand(e.operand() + " (limit mesh at level " + std::to_string(levels) + ")", e.issues());
  }
  r.time.boolean = clock.lap();
  if (!r.polyhedral.ok()) {
    r.status = Subdivision_boolean_result<K>::Status::failed;
    r.failure = "polyhedral Boolean: " + r.polyhedral.failure;
    return r;
  }
  const auto& where = r.polyhedral.vertex_locations;
  r.unfitted = internal::merged_control_mesh(r.polyhedral.mesh, r.polyhedral.provenance, where, {&at[0], &at[1]},
                                             r.curve_vertices);
  r.counts.curve_vertices = r.curve_vertices.size();
  r.counts.curve_edges = r.polyhedral.mesh.tags.creases().size();
  for (int m = 0; m < 2; ++m) r.counts.bad_faces[m] = internal::count_bad_faces(at[m], m, r.curve_vertices, where);
  r.control = r.unfitted;
  r.time.mapping = clock.lap();
  try {
    r.distance_to_polyhedral =
        limit_surface_distance(r.unfitted, r.polyhedral.mesh, options.distance_samples, options.loop);
    r.time.distance = clock.lap();
    if (options.fit && !r.curve_vertices.empty()) {
      const auto fitted = internal::fit_control_points(r.unfitted, r.polyhedral.mesh.vertices, r.curve_vertices,
                                                       options.fit_rings, options.fit_regularisation, options.loop,
                                                       r.counts.fitted_vertices);
      r.time.fitting = clock.lap();
      if (fitted) {
        r.distance_to_polyhedral_fitted =
            limit_surface_distance(*fitted, r.polyhedral.mesh, options.distance_samples, options.loop);
        // Never worse than without fitting: without a measurement, keep it off.
        const bool better = r.distance_to_polyhedral_fitted.measured() &&
                            r.distance_to_polyhedral_fitted.hausdorff() < r.distance_to_polyhedral.hausdorff();
        if (better) r.control = *fitted, r.fitted = true;
      }
      r.time.distance += clock.lap();
    }
  } catch (const Invalid_input& e) {  // Loop's rules refuse the merged mesh (two faces sharing two edges)
    r.status = Subdivision_boolean_result<K>::Status::failed;
    r.failure = std::string("subdivision result: ") + e.what();
  }
  if (options.validate) r.validation = validate_subdivision_solid(r.control, options.loop, options.validation);
  r.time.validation = clock.lap();
  return r;
}

// The instances relgeo::compiled makes when it is built with Eigen
// (src/compiled/subdivision_boolean.cpp; RELGEO_COMPILED_SUBDIVISION_BOOLEAN).
#define RELGEO_SUBDIVISION_BOOLEAN_INSTANCE(PREFIX, K)                                                  \
  PREFIX Subdivision_boolean_result<K> subdivision_boolean<K>(const Triangle_mesh<Point_3<double>>&,      \
                                                              const Triangle_mesh<Point_3<double>>&,      \
                                                              Boolean_operation, unsigned, const K&,      \
                                                              const Subdivision_boolean_options&);
#if defined(RELGEO_COMPILED_SUBDIVISION_BOOLEAN) && RELGEO_COMPILED_SUBDIVISION_BOOLEAN
RELGEO_COMPILED_KERNELS(RELGEO_SUBDIVISION_BOOLEAN_INSTANCE, extern template)
#endif

}  // namespace relgeo
