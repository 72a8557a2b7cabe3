// relgeo_chain_benchmark — the three 24-step CSG chains of
// test/boolean/boolean_chains.h (a drilled sphere, fused spheres, a slab with
// boxes), each operation on the result of the last, side by side in one run:
//   relgeo csg            relgeo::csg, Filtered_exact_kernel, the defaults
//                         (constrained Delaunay faces, repaired rounding)
//   relgeo csg insertion  the same with the insertion order's triangulation
//                         (Boolean_options::delaunay_retriangulation = false)
//   relgeo nearest        relgeo::boolean step by step, nearest rounding
//   relgeo nearest insertion   nearest rounding of the insertion order's
//                         triangulation: the engine before issue 28
//   CGAL Epick            corefine_and_compute_* on Surface_mesh<Epick>
//   CGAL Epeck            the same on Surface_mesh<Epeck> (kept exact in memory)
// and, over the chains' first --exact_steps steps (default 6; exact
// intermediates cost more with every step), the rows "(N steps)":
//   relgeo csg            as above
//   relgeo csg exact      relgeo::csg with Csg_intermediates::exact under
//                         Exact_kernel (GMP rationals), the root rounded once
//   relgeo csg exact Epeck  the same under Cgal_kernel<CGAL::Epeck>
//   CGAL Epeck            as above
// A chain stops at a step that fails or refuses its operand. Counters: steps
// completed, the final face count, its smallest angle (degrees) and faces
// with an angle under one degree, and whether the final mesh is a valid
// solid (relgeo's exact validation, outside the timing); the exact rows'
// label lists each step's coordinate size in bits (Exact_kernel) and time.
// The "(N steps)" rows also give volume_error: the exact volume of their
// final mesh against that of the chain's exact result (relgeo's exact chain
// under Exact_kernel, computed once, outside the timing), relative.
// Usage: relgeo_chain_benchmark [--levels=N] [--exact_steps=N]
// [google-benchmark flags].
// --export_chains=DIR writes each chain's operands as DIR/FAMILY.json
// ({"start": MESH, "steps": [{"op", "mesh": MESH}]}, MESH = {"v": [x, y, z,
// ...], "f": [i, j, k, ...]}) and exits: the input of manifold_chains.mjs,
// which runs the same chains with Manifold's WebAssembly build.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <string>

#include "boolean/boolean_chains.h"
#include "relgeo/boolean.h"
#include "relgeo/kernel/cgal_kernel.h"
#include "relgeo/mesh/cgal_conversion.h"
#include "relgeo/mesh/solid_validation.h"
#include "relgeo_fixtures/peers/cgal_corefinement.h"

namespace {

using namespace relgeo;
using relgeo::test::Boolean_chain;
using relgeo::test::Chain_family;

int sphere_levels = 3;
int exact_steps = 6;

struct Chain_outcome {
  int steps = 0;
  Mesh_double mesh;
  std::string label = {};  // per step: coordinate bits and seconds (exact intermediates)
};

// The smallest interior angle of face t, in degrees.
double smallest_angle(const Mesh_double& m, const Triangle& t) {
  double best = 180;
  for (int i = 0; i < 3; ++i) {
    const auto& p = m.vertices[t[i]];
    const auto& q = m.vertices[t[(i + 1) % 3]];
    const auto& r = m.vertices[t[(i + 2) % 3]];
    const double ux = q.x - p.x, uy = q.y - p.y, uz = q.z - p.z, vx = r.x - p.x, vy = r.y - p.y, vz = r.z - p.z;
    const double cross = std::hypot(uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx);
    best = std::min(best, std::atan2(cross, ux * vx + uy * vy + uz * vz) * 180 / 3.14159265358979323846);
  }
  return best;
}

void report(benchmark::State& state, const Chain_outcome& o) {
  double smallest = o.mesh.faces.empty() ? 0 : 180;
  std::size_t needles = 0;
  for (const Triangle& t : o.mesh.faces) {
    const double a = smallest_angle(o.mesh, t);
    smallest = std::min(smallest, a);
    needles += a < 1;
  }
  state.counters["steps"] = o.steps;
  state.counters["faces"] = static_cast<double>(o.mesh.faces.size());
  state.counters["min_angle_deg"] = smallest;
  state.counters["under_1deg"] = static_cast<double>(needles);
  state.counters["valid"] = !o.mesh.faces.empty() && validate_solid(o.mesh).is_valid_solid();
}

template <bool Delaunay>
Chain_outcome run_csg(const Boolean_chain& c) {
  Csg_options options;
  options.boolean.delaunay_retriangulation = Delaunay;
  const Csg_result r = csg(relgeo::test::csg_tree(c), Filtered_exact_kernel{}, options);
  return {static_cast<int>(std::count_if(r.steps.begin(), r.steps.end(), [](const Csg_step& s) { return s.ok; })),
          r.mesh};
}

template <class K>
Chain_outcome run_csg_exact(const Boolean_chain& c) {
  Csg_options options;
  options.intermediates = Csg_intermediates::exact;
  const Csg_result r = csg(relgeo::test::csg_tree(c), K{}, options);
  Chain_outcome o{static_cast<int>(std::count_if(r.steps.begin(), r.steps.end(), [](const Csg_step& s) { return s.ok; })),
                  r.ok() ? r.mesh : Mesh_double{}};
  char buf[64];
  for (const Csg_step& s : r.steps) {
    if (!o.label.empty()) o.label += ", ";
    if (s.coordinate_bits) std::snprintf(buf, sizeof buf, "%zu bits %.2f s", s.coordinate_bits, s.seconds);
    else std::snprintf(buf, sizeof buf, "%.2f s", s.seconds);
    o.label += buf;
  }
  return o;
}

template <bool Delaunay>
Chain_outcome run_nearest(const Boolean_chain& c) {
  Chain_outcome o{0, c.start};
  Boolean_options options;
  options.rounding = Output_rounding::nearest;
  options.delaunay_retriangulation = Delaunay;
  for (const auto& [op, m] : c.steps) {
    try {
      auto r = boolean(o.mesh, m, op, Filtered_exact_kernel{}, options);
      if (!r.ok()) break;
      o.mesh.vertices = std::move(r.mesh.vertices);
      o.mesh.faces = std::move(r.mesh.faces);
      ++o.steps;
    } catch (const Invalid_operand&) {
      break;  // the last output crosses itself
    }
  }
  return o;
}

template <class K>
Chain_outcome run_cgal(const Boolean_chain& c) {
  using Surface = CGAL::Surface_mesh<typename K::Point_3>;
  Surface current = to_surface_mesh<typename K::Point_3>(c.start);
  int steps = 0;
  for (const auto& [op, m] : c.steps) {
    Surface operand = to_surface_mesh<typename K::Point_3>(m), out;
    bool ok = false;
    try {
      ok = peers::cgal_corefine_and_compute(current, operand, op, out);
    } catch (const std::exception&) {
      ok = false;  // a self-intersecting operand
    }
    if (!ok) break;
    current = std::move(out);
    ++steps;
  }
  return {steps, from_surface_mesh<Point_3<double>>(current)};
}

template <class P>
mpq_class exact_volume(const Triangle_mesh<P>& m) {
  return mpq_class(validate_solid(m, typename Kernel_for_point<Certified_kernel_for_number, P>::type{},
                                  Solid_validation_options{.exact_volume_string = true})
                       .volume.exact_value);
}

// The exact volume of the chain's exact result: each step on the last
// step's exact mesh, nothing rounded (once per family).
const mpq_class& exact_chain_volume(Chain_family family, const Boolean_chain& c) {
  static std::map<Chain_family, mpq_class> volumes;
  if (const auto it = volumes.find(family); it != volumes.end()) return it->second;
  const Exact_kernel k;
  const Boolean_options nearest{.rounding = Output_rounding::nearest, .validate_output = false};
  auto exact = exact_operand(c.start, k);
  for (const auto& [op, m] : c.steps) exact = boolean(exact, exact_operand(m, k), op, k, nearest).exact_mesh();
  return volumes[family] = exact_volume(exact);
}

template <Chain_outcome (*Run)(const Boolean_chain&), bool Short = false>
void chain(benchmark::State& state, Chain_family family) {
  const Boolean_chain c = relgeo::test::make_chain(family, Short ? exact_steps : 24, 7, sphere_levels);
  Chain_outcome o;
  for (auto _ : state) o = Run(c);
  report(state, o);
  if (!o.label.empty()) state.SetLabel(o.label);
  if (Short && o.steps == exact_steps) {
    const mpq_class& v = exact_chain_volume(family, c);
    state.counters["volume_error"] = mpq_class(abs(exact_volume(o.mesh) - v) / abs(v)).get_d();
  }
}

void register_all() {
  for (Chain_family f : {Chain_family::drilled_sphere, Chain_family::fused_spheres, Chain_family::slab_and_boxes}) {
    const std::string name = std::string(to_string(f));
    for (auto [subject, fn] : std::initializer_list<std::pair<const char*, void (*)(benchmark::State&, Chain_family)>>{
             {"relgeo csg", &chain<&run_csg<true>>},
             {"relgeo csg insertion", &chain<&run_csg<false>>},
             {"relgeo nearest", &chain<&run_nearest<true>>},
             {"relgeo nearest insertion", &chain<&run_nearest<false>>},
             {"CGAL Epick", &chain<&run_cgal<CGAL::Epick>>},
             {"CGAL Epeck", &chain<&run_cgal<CGAL::Epeck>>}})
      benchmark::RegisterBenchmark((name + "/" + subject).c_str(), fn, f)->Unit(benchmark::kSecond)->Iterations(1);
    const std::string steps = " (" + std::to_string(exact_steps) + " steps)";
    for (auto [subject, fn] : std::initializer_list<std::pair<const char*, void (*)(benchmark::State&, Chain_family)>>{
             {"relgeo csg", &chain<&run_csg<true>, true>},
             {"relgeo csg exact", &chain<&run_csg_exact<Exact_kernel>, true>},
             {"relgeo csg exact Epeck", &chain<&run_csg_exact<Cgal_kernel<CGAL::Epeck>>, true>},
             {"CGAL Epeck", &chain<&run_cgal<CGAL::Epeck>, true>}})
      benchmark::RegisterBenchmark((name + "/" + subject + steps).c_str(), fn, f)
          ->Unit(benchmark::kSecond)
          ->Iterations(1);
  }
}

void write_mesh_json(std::ofstream& out, const Mesh_double& m) {
  out << "{\"v\":[";
  for (std::size_t i = 0; i < m.vertices.size(); ++i)
    out << (i ? "," : "") << m.vertices[i].x << ',' << m.vertices[i].y << ',' << m.vertices[i].z;
  out << "],\"f\":[";
  for (std::size_t i = 0; i < m.faces.size(); ++i)
    out << (i ? "," : "") << m.faces[i][0] << ',' << m.faces[i][1] << ',' << m.faces[i][2];
  out << "]}";
}

int export_chains(const std::string& dir) {
  for (Chain_family f : {Chain_family::drilled_sphere, Chain_family::fused_spheres, Chain_family::slab_and_boxes}) {
    const Boolean_chain c = relgeo::test::make_chain(f, 24, 7, sphere_levels);
    const std::string path = dir + "/" + std::string(to_string(f)) + ".json";
    std::ofstream out(path);
    out.precision(17);
    out << "{\"start\":";
    write_mesh_json(out, c.start);
    out << ",\"steps\":[";
    for (std::size_t i = 0; i < c.steps.size(); ++i) {
      out << (i ? "," : "") << "{\"op\":\"" << to_string(c.steps[i].first) << "\",\"mesh\":";
      write_mesh_json(out, c.steps[i].second);
      out << "}";
    }
    out << "]}\n";
    if (!out) {
      std::fprintf(stderr, "cannot write %s\n", path.c_str());
      return 1;
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], "--levels=", 9) == 0) sphere_levels = std::atoi(argv[i] + 9);
    else if (std::strncmp(argv[i], "--exact_steps=", 14) == 0) exact_steps = std::atoi(argv[i] + 14);
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], "--export_chains=", 16) == 0) return export_chains(argv[i] + 16);
  benchmark::Initialize(&argc, argv);
  register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
