// benchmark/boolean/boolean_benchmark.h — the cases and subjects of the mesh
// Boolean benchmark, shared by its translation units (relgeo's in
// boolean_benchmark.cpp, CGAL's corefinement in boolean_benchmark_cgal.cpp:
// the corefinement headers cost a minute to compile).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "relgeo/boolean/boolean_types.h"
#include "relgeo/kernel/point.h"
#include "relgeo/mesh/triangle_mesh.h"

namespace relgeo_bench {

using Mesh = relgeo::Triangle_mesh<relgeo::Point_3<double>>;

/// The operands of one case (built on first use).
struct Boolean_case {
  std::string name;
  std::function<std::pair<Mesh, Mesh>()> build;
  bool large = false;  ///< exact kernels and Epeck are not run on it by default
};
const std::vector<Boolean_case>& boolean_cases();
const std::pair<Mesh, Mesh>& operands(const std::string& case_name);

/// What one run gives back: output size and whether it is a closed oriented manifold.
struct Run_outcome {
  std::size_t faces = 0;
  bool valid = false;
  double volume = 0;
  std::optional<relgeo::Boolean_timing> phases;  ///< relgeo's phase times (none for CGAL's subjects)
};

/// The timed run of a subject: the Boolean alone. It returns how to inspect
/// its output (untimed, outside the memory probe: the checks of the output
/// are not the subject's work).
using Inspect = std::function<Run_outcome()>;
using Timed_run = std::function<Inspect()>;

/// One subject: a name ("relgeo filtered", "CGAL::corefine Epick"...) and
/// its preparation (untimed: e.g. CGAL's Surface_mesh built from the
/// operands), which returns the timed run.
struct Subject {
  std::string name;
  std::function<Timed_run(const Mesh&, const Mesh&, relgeo::Boolean_operation)> prepare;
  bool exact = false;  ///< exact arithmetic (compared with CGAL Epeck), skipped on large cases
  std::string peer;    ///< the subject its ratio is taken against
};
std::vector<Subject> cgal_subjects();

/// Closed, oriented 2-manifold (combinatorial check of the output).
bool closed_oriented_manifold(const Mesh& m);
double volume(const Mesh& m);

}  // namespace relgeo_bench
