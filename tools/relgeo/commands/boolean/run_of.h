// tools/relgeo/commands/boolean/run_of.h — a Boolean_result<K> as the tool's
// Boolean_run (kernel-free). Included by the boolean dispatch*.cpp files only.
#pragma once

#include <string>

#include "commands/boolean/facade.h"
#include "relgeo/boolean/boolean_types.h"

namespace relgeo::tool {

/// The kernel's label, model name and guarantees in a run record (Boolean_run,
/// Subdivision_boolean_run).
template <class K, class Run>
void set_kernel_fields(Run& run, const std::string& kernel_label) {
  run.kernel = kernel_label;
  run.kernel_model = K::name();
  run.certified = K::is_certified;
  run.exact = K::has_exact_predicates;
}

/// `r`'s kernel-free output with the kernel's fields (not
/// exact_self_intersecting_pairs: an extra computation, left to the caller).
template <class K>
Boolean_run boolean_run_of(const Boolean_result<K>& r, const std::string& kernel_label) {
  Boolean_run run;
  static_cast<Boolean_output&>(run) = r;
  set_kernel_fields<K>(run, kernel_label);
  return run;
}

}  // namespace relgeo::tool
