// tools/relgeo/commands/boolean/subdivision_facade.h — what `relgeo boolean
// --levels K` and the experiment's subdivision-boolean section run:
// relgeo::subdivision_boolean under a kernel named at run time (instantiated
// in dispatch_subdivision.cpp only, over the kernels `boolean` accepts), and
// the finer limit mesh of a result for pictures.
#pragma once

#include <string>
#include <vector>

#include "commands/boolean/facade.h"
#include "relgeo/boolean/subdivision_boolean_types.h"

namespace relgeo::tool {

/// One Boolean of two Loop subdivision solids under one kernel: the
/// library's kernel-free output, the kernel's fields and the polyhedral
/// result as a Boolean_run. A run that has not succeeded (the default: one
/// that was refused) is `failed`.
struct Subdivision_boolean_run : Subdivision_boolean_output {
  Subdivision_boolean_run() { status = Status::failed; }

  std::string kernel, kernel_model;
  bool certified = false, exact = false;
  /// The Boolean of the two limit meshes at `level` (its
  /// exact_self_intersecting_pairs is not computed here).
  Boolean_run polyhedral = not_run();

 private:
  // A run that did not reach the polyhedral Boolean has none.
  static Boolean_run not_run() {
    Boolean_run r;
    r.status = Boolean_output::Status::failed;
    return r;
  }
};

/// relgeo::subdivision_boolean(a, b, op, levels, K, options) for the kernel
/// named `kernel` (one of boolean_kernel_names()).
/// \throws Invalid_operand for invalid operands, Usage_error for a kernel that cannot.
Subdivision_boolean_run evaluate_subdivision_boolean(const std::string& kernel, const Mesh_double& a,
                                                     const Mesh_double& b, Boolean_operation op, unsigned levels,
                                                     const Subdivision_boolean_options& options);

/// The limit mesh of a Loop control mesh `levels` levels finer (doubles), its
/// crease and corner tags refined with it: what the pictures show.
Mesh_double finer_limit_mesh(const Mesh_double& control, unsigned levels, const Loop_options& loop);

}  // namespace relgeo::tool
