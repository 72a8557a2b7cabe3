// relgeo_subdivision_boolean_benchmark: what the subdivision layer of a
// Boolean of two Loop solids costs (relgeo::subdivision_boolean, thesis Ch. 5)
// against the plain mesh Boolean (relgeo::boolean) of the same limit meshes.
//
// Operands: two offset Loop spheres, 1280-face icospheres, whose limit meshes
// have 5120, 20480 and 81920 triangles each at levels 1, 2, 3. Subjects per
// level, both under Filtered_exact_kernel with the default Boolean options
// (operand checks on):
//   subdivision_boolean  fitting, distances and validation off; its phases
//                        are reported as counters: limit_meshes, boolean and
//                        mapping (the layer: mapping, cutting, merging,
//                        tagging);
//   boolean              relgeo::boolean on the two level-k limit meshes
//                        (computed before, untimed).
// Each runs `--relgeo_repetitions` times (default 3); the table gives the
// minimum of each figure over the repetitions and the layer's time over the
// plain Boolean's (the bar: at most 1.0 at level 2).
#include <algorithm>
#include <cstdio>
#include <map>
#include <string>

#include "common/command_line.h"
#include "relgeo/boolean.h"
#include "relgeo/boolean/subdivision_boolean.h"
#include "relgeo/core/internal/stopwatch.h"
#include "relgeo/kernel/filtered_exact_kernel.h"
#include "relgeo/mesh/shapes.h"
#include "relgeo/subdivision/loop_subdivision.h"

namespace relgeo_bench {
namespace {

using Mesh = relgeo::Mesh_double;
using Kernel = relgeo::Filtered_exact_kernel;
constexpr relgeo::Boolean_operation kOp = relgeo::Boolean_operation::union_of;

const std::pair<Mesh, Mesh>& control_meshes() {
  static const std::pair<Mesh, Mesh> m{relgeo::icosphere(3), relgeo::icosphere(3, {0.5, 0.3, 0.2}, 0.9)};
  return m;
}

const std::pair<Mesh, Mesh>& limit_meshes(unsigned level) {
  static std::map<unsigned, std::pair<Mesh, Mesh>> built;
  auto it = built.find(level);
  if (it == built.end()) {
    const auto& [a, b] = control_meshes();
    it = built.emplace(level, std::pair{relgeo::loop_limit_mesh(a, level), relgeo::loop_limit_mesh(b, level)}).first;
  }
  return it->second;
}

// Minimum over the repetitions of each figure, per level.
struct Figures {
  double total = 1e300, limit_meshes = 1e300, boolean = 1e300, mapping = 1e300;  // subdivision_boolean
  double plain_boolean = 1e300;                                                 // relgeo::boolean
  std::size_t control_faces = 0, polyhedral_faces = 0, plain_faces = 0, limit_faces = 0;
  bool ok = true;
};
std::map<unsigned, Figures> figures;

void subdivision_boolean_run(benchmark::State& state, unsigned level) {
  const auto& [a, b] = control_meshes();
  relgeo::Subdivision_boolean_options options;
  options.fit = false;
  options.distance_samples = 0;
  options.validate = false;
  Figures& f = figures[level];
  for (auto _ : state) {
    const relgeo::internal::Stopwatch t0;
    const auto r = relgeo::subdivision_boolean(a, b, kOp, level, Kernel{}, options);
    const double t = t0.elapsed();
    f.total = std::min(f.total, t);
    f.limit_meshes = std::min(f.limit_meshes, r.time.limit_meshes);
    f.boolean = std::min(f.boolean, r.time.boolean);
    f.mapping = std::min(f.mapping, r.time.layer());
    f.control_faces = r.control.faces.size();
    f.polyhedral_faces = r.polyhedral.mesh.faces.size();
    f.ok = f.ok && r.ok();
    state.counters["limit_meshes_ms"] = 1e3 * r.time.limit_meshes;
    state.counters["boolean_ms"] = 1e3 * r.time.boolean;
    state.counters["mapping_ms"] = 1e3 * r.time.layer();
    if (!r.ok()) state.SkipWithError(("subdivision_boolean failed: " + r.failure).c_str());
  }
}

void plain_boolean_run(benchmark::State& state, unsigned level) {
  const auto& [a, b] = limit_meshes(level);
  Figures& f = figures[level];
  f.limit_faces = a.faces.size();
  for (auto _ : state) {
    const relgeo::internal::Stopwatch t0;
    const auto r = relgeo::boolean(a, b, kOp, Kernel{}, relgeo::Boolean_options{});
    const double t = t0.elapsed();
    f.plain_boolean = std::min(f.plain_boolean, t);
    f.plain_faces = r.mesh.faces.size();
    f.ok = f.ok && r.ok();
    if (!r.ok()) state.SkipWithError(("boolean failed: " + r.failure).c_str());
  }
}

void register_all(int repetitions) {
  for (unsigned level = 1; level <= 3; ++level) {
    const std::string prefix = "loop-spheres-1280/L" + std::to_string(level) + "/";
    // Interleaved: the two subjects of one level run one after the other.
    benchmark::RegisterBenchmark((prefix + "subdivision_boolean").c_str(),
                                 [level](benchmark::State& s) { subdivision_boolean_run(s, level); })
        ->Iterations(1)->Repetitions(repetitions)->Unit(benchmark::kMillisecond)->ReportAggregatesOnly(true);
    benchmark::RegisterBenchmark((prefix + "boolean").c_str(), [level](benchmark::State& s) {
      (void)limit_meshes(level);  // built before the timed runs
      plain_boolean_run(s, level);
    })->Iterations(1)->Repetitions(repetitions)->Unit(benchmark::kMillisecond)->ReportAggregatesOnly(true);
  }
}

void print_table() {
  std::printf("\n%-5s %10s %10s %10s %12s %12s %12s %12s %14s %13s %4s\n", "level", "limit tri", "control", "total ms",
              "limit ms", "boolean ms", "mapping ms", "plain ms", "mapping/plain", "boolean/plain", "ok");
  for (const auto& [level, f] : figures) {
    if (f.total == 1e300 || f.plain_boolean == 1e300) continue;  // one subject filtered out
    std::printf("%-5u %10zu %10zu %10.1f %12.1f %12.1f %12.1f %12.1f %14.3f %13.3f %4s\n", level, f.limit_faces,
                f.control_faces, 1e3 * f.total, 1e3 * f.limit_meshes, 1e3 * f.boolean, 1e3 * f.mapping,
                1e3 * f.plain_boolean, f.mapping / f.plain_boolean, f.boolean / f.plain_boolean, f.ok ? "yes" : "NO");
  }
}

}  // namespace
}  // namespace relgeo_bench

int main(int argc, char** argv) {
  relgeo_bench::Command_line args(argc, argv);
  const std::string reps = args.value("--relgeo_repetitions");
  args.erase("--relgeo_repetitions");
  if (!args.initialize()) return 2;
  relgeo_bench::register_all(reps.empty() ? 3 : std::stoi(reps));
  const std::size_t ran = benchmark::RunSpecifiedBenchmarks();
  relgeo_bench::print_table();
  return relgeo_bench::finish(ran, argv[0]);
}
