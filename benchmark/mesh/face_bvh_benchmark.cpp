// relgeo_mesh_benchmark: the broad phase of the mesh Booleans and the exact
// self-intersection test, relgeo against CGAL in one run.
//  * pairs/<case>/<subject>: every pair (face of A, face of B) whose boxes
//    overlap, from the two meshes to the list of pairs (boxes, hierarchy or
//    sweep, search): relgeo's Face_bvh (1 and 2 threads) against CGAL's
//    box_intersection_d (the sweep of CGAL's corefinement, with its cutoff)
//    and CGAL's AABB_tree (built on A, one box query per face of B); and
//    relgeo's hierarchy on B alone, searched with A's face boxes (the mesh
//    Boolean's broad phase, which keeps one hierarchy: peak memory);
//  * self_pairs/<mesh>/<subject>: the same within one mesh (f < g):
//    Face_bvh against box_self_intersection_d (cutoff of CGAL's
//    self_intersections);
//  * self_intersections/<mesh>/<subject>: the exact self-intersection test,
//    relgeo::self_intersections (Filtered_exact_kernel) against
//    CGAL::Polygon_mesh_processing::self_intersections over Epick, and
//    relgeo::check_solid (every check of check_mesh, then the test with the
//    embedded-star certificate for neighbouring faces);
//  * validate_solid/<mesh>/relgeo filtered: the whole validation report
//    (no peer; for scale);
//  * volume/<mesh>/<subject>: the signed volume, relgeo's exact sum (the
//    validation's, internal/exact_volume.h) against
//    CGAL::Polygon_mesh_processing::volume over Epick (a double sum, not
//    exact) and over Epeck made exact (CGAL::exact; not on the 10^6-face case);
//  * read_off/<mesh>/<subject>, write_off/<mesh>/<subject>: mesh A as an
//    ASCII OFF file (both read the file relgeo's writer made; both write
//    doubles that read back exactly: CGAL with 17 digits), relgeo::read_mesh
//    / write_mesh against CGAL::IO's read_polygon_soup / write_polygon_soup
//    (not on the 10^6-face case).
// Each subject is measured 5 times (3 on the 10^6-face case); the table at the
// end gives the minimum of the repetitions and its ratio to the CGAL peer
// (box_intersection_d, box_self_intersection_d, PMP self_intersections, each
// on one thread). The counter `pairs` is the number found: the same for
// every subject of a case.
#include "face_bvh_benchmark.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <vector>

#include "common/command_line.h"
#include "mesh/solid_fixtures.h"
#include "relgeo/mesh/face_bvh.h"
#include "relgeo/mesh/internal/exact_volume.h"
#include "relgeo/mesh/mesh_io.h"
#include "relgeo/mesh/self_intersection.h"
#include "relgeo/mesh/solid_validation.h"

namespace relgeo_bench {

std::vector<std::string> case_names() {
  std::vector<std::string> names{"spheres-20k"};
  if (std::ifstream(std::string(RELGEO_CGAL_MESH_DIR) + "/elephant.off").good()) names.push_back("elephant");
  names.push_back("spheres-1m");
  return names;
}

std::string off_file(const std::string& case_name) {
  static std::map<std::string, std::string> written;
  if (const auto it = written.find(case_name); it != written.end()) return it->second;
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "relgeo_mesh_benchmark";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / (case_name + ".off")).string();
  relgeo::write_mesh(path, mesh_pair_case(case_name).a);
  return written[case_name] = path;
}

const Mesh_pair_case& mesh_pair_case(const std::string& name) {
  static std::map<std::string, Mesh_pair_case> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  Mesh_pair_case c{name, {}, {}};
  if (name == "spheres-20k" || name == "spheres-1m") {
    c.a = relgeo_test::cube_sphere(name == "spheres-20k" ? 41 : 289);
    c.b = relgeo_test::translated(c.a, 0.5, 0.37, 0.23);
  } else if (name == "elephant") {
    c.a = relgeo::read_mesh(std::string(RELGEO_CGAL_MESH_DIR) + "/elephant.off");
    c.b = relgeo_test::rotated(c.a, 0.5, {1, 2, 3}, relgeo_test::box_centre(c.a));
  } else {
    throw std::invalid_argument("no mesh pair case " + name);
  }
  return cache.emplace(name, std::move(c)).first->second;
}

benchmark::internal::Benchmark* register_subject(const std::string& name,
                                                 void (*f)(benchmark::State&, const std::string&),
                                                 const std::string& case_name) {
  return benchmark::RegisterBenchmark(name.c_str(), f, case_name)
      ->Repetitions(case_name == "spheres-1m" ? 3 : 5)
      ->Unit(benchmark::kMillisecond)
      ->ComputeStatistics("min", [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); })
      ->ReportAggregatesOnly(false);
}

namespace {

template <int Threads>
void relgeo_pairs(benchmark::State& state, const std::string& case_name) {
  const Mesh_pair_case& c = mesh_pair_case(case_name);
  const relgeo::Face_bvh_options options{.threads = Threads};
  std::size_t pairs = 0;
  for (auto _ : state) {
    const relgeo::Face_bvh a(c.a, options), b(c.b, options);
    const auto found = a.overlapping_pairs(b, Threads);
    pairs = found.size();
    benchmark::DoNotOptimize(found.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs);
}

// One hierarchy, on B, searched with A's face boxes.
void relgeo_pairs_with_boxes(benchmark::State& state, const std::string& case_name) {
  const Mesh_pair_case& c = mesh_pair_case(case_name);
  std::size_t pairs = 0;
  for (auto _ : state) {
    const relgeo::Face_bvh b(c.b);
    const auto found = b.overlapping_pairs_with_boxes(relgeo::face_boxes(c.a));
    pairs = found.size();
    benchmark::DoNotOptimize(found.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs);
}

template <int Threads>
void relgeo_self_pairs(benchmark::State& state, const std::string& case_name) {
  const Mesh& m = mesh_pair_case(case_name).a;
  const relgeo::Face_bvh_options options{.threads = Threads};
  std::size_t pairs = 0;
  for (auto _ : state) {
    const relgeo::Face_bvh a(m, options);
    const auto found = a.overlapping_pairs(Threads);
    pairs = found.size();
    benchmark::DoNotOptimize(found.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs);
}

template <int Threads>
void relgeo_self_intersections(benchmark::State& state, const std::string& case_name) {
  const Mesh& m = mesh_pair_case(case_name).a;
  std::size_t pairs = 0;
  for (auto _ : state) {
    const auto found = relgeo::find_self_intersections(m, {.threads = Threads});
    pairs = found.pairs.size();
    benchmark::DoNotOptimize(found.pairs.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs);
}

// check_solid: every check of check_mesh, then the self-intersection test
// with the embedded-star certificate for neighbouring faces.
void relgeo_check_solid(benchmark::State& state, const std::string& case_name) {
  const Mesh& m = mesh_pair_case(case_name).a;
  std::size_t pairs = 0;
  for (auto _ : state) {
    const relgeo::Mesh_report r = relgeo::check_solid(m);
    pairs = r.count(relgeo::Mesh_defect::self_intersection);
    benchmark::DoNotOptimize(r.issues.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs);
}

void relgeo_validate(benchmark::State& state, const std::string& case_name) {
  const Mesh& m = mesh_pair_case(case_name).a;
  std::size_t pairs = 0;
  for (auto _ : state) {
    const relgeo::Solid_report r = relgeo::validate_solid(m, {.exact_volume_string = false});
    pairs = r.self_intersection_free.count;
    benchmark::DoNotOptimize(r.volume.value);
  }
  state.counters["pairs"] = static_cast<double>(pairs);
}

void relgeo_volume(benchmark::State& state, const std::string& case_name) {
  const Mesh& m = mesh_pair_case(case_name).a;
  const std::vector<relgeo::Index> one_component(m.faces.size(), 0);
  for (auto _ : state) {
    const relgeo::internal::Signed_volumes v = relgeo::internal::signed_volumes(m, one_component, 1, 1);
    benchmark::DoNotOptimize(v.value[0]);
  }
}

void relgeo_read_off(benchmark::State& state, const std::string& case_name) {
  const std::string path = off_file(case_name);
  for (auto _ : state) {
    const Mesh m = relgeo::read_mesh(path);
    benchmark::DoNotOptimize(m.faces.data());
  }
}

void relgeo_write_off(benchmark::State& state, const std::string& case_name) {
  const Mesh& m = mesh_pair_case(case_name).a;
  const std::string path = off_file(case_name) + ".out.off";
  for (auto _ : state) relgeo::write_mesh(path, m);
}

// The table: per group, the minimum time and its ratio to the CGAL peer.
class Ratio_reporter : public Collecting_reporter {
 public:
  void Finalize() override {
    ConsoleReporter::Finalize();
    std::printf("\n%-58s %10s %10s %10s %10s\n", "subject (minimum of the repetitions)", "ms", "cpu ms", "vs CGAL",
                "pairs");
    for (const auto& [name, best] : best_) {
      const std::string group = name.substr(0, name.rfind('/'));
      const std::string kind = group.substr(0, group.find('/'));
      const std::string peer = kind == "pairs"                               ? "CGAL box_intersection_d"
                               : kind == "self_pairs"                        ? "CGAL box_self_intersection_d"
                               : kind == "read_off" || kind == "write_off" ? "CGAL IO"
                                                                             : "CGAL PMP Epick";
      const auto it = best_.find(group + "/" + peer);
      const std::string ratio = it == best_.end() ? "-" : std::to_string(best.ms / it->second.ms).substr(0, 5);
      std::printf("%-58s %10.3f %10.3f %10s %10.0f\n", name.c_str(), best.ms, best.cpu_ms, ratio.c_str(), best.pairs);
    }
    std::printf("(ms: wall clock, the ratio's basis; cpu ms: the main thread's CPU time, comparable on a loaded\n"
                " machine for one-thread subjects only)\n");
  }
  std::size_t ran() const { return best_.size(); }

 protected:
  void collect(const Run& r) override {
    const double ms = to_seconds(r.GetAdjustedRealTime(), r.time_unit) * 1e3;
    const double cpu_ms = to_seconds(r.GetAdjustedCPUTime(), r.time_unit) * 1e3;
    const double pairs = r.counters.count("pairs") ? r.counters.at("pairs").value : -1;
    auto [it, fresh] = best_.emplace(r.run_name.function_name, Best{ms, cpu_ms, pairs});
    if (!fresh) it->second.ms = std::min(it->second.ms, ms), it->second.cpu_ms = std::min(it->second.cpu_ms, cpu_ms);
  }

 private:
  struct Best {
    double ms, cpu_ms, pairs;
  };
  std::map<std::string, Best> best_;
};

// relgeo and CGAL registered alternately (run in this order unless
// --benchmark_enable_random_interleaving shuffles them).
void register_subjects() {
  for (const std::string& c : case_names()) {
    register_subject("pairs/" + c + "/relgeo Face_bvh", relgeo_pairs<1>, c);
    register_cgal_subjects("pairs", c, 1);
    register_subject("pairs/" + c + "/relgeo Face_bvh on B, A's boxes", relgeo_pairs_with_boxes, c);
    register_subject("pairs/" + c + "/relgeo Face_bvh 2 threads", relgeo_pairs<2>, c);
    register_cgal_subjects("pairs", c, 2);
    register_subject("self_pairs/" + c + "/relgeo Face_bvh", relgeo_self_pairs<1>, c);
    register_cgal_subjects("self_pairs", c, 1);
    register_subject("self_pairs/" + c + "/relgeo Face_bvh 2 threads", relgeo_self_pairs<2>, c);
    register_cgal_subjects("self_pairs", c, 2);
    register_subject("self_intersections/" + c + "/relgeo filtered", relgeo_self_intersections<1>, c);
    register_cgal_subjects("self_intersections", c, 1);
    register_subject("self_intersections/" + c + "/relgeo check_solid (all checks)", relgeo_check_solid, c);
    register_subject("self_intersections/" + c + "/relgeo filtered 2 threads", relgeo_self_intersections<2>, c);
    register_cgal_subjects("self_intersections", c, 2);
    register_subject("validate_solid/" + c + "/relgeo filtered", relgeo_validate, c);
    register_subject("volume/" + c + "/relgeo exact", relgeo_volume, c);
    register_cgal_subjects("volume", c, 1);
    if (c == "spheres-1m") continue;
    register_subject("read_off/" + c + "/relgeo read_mesh", relgeo_read_off, c);
    register_cgal_subjects("read_off", c, 1);
    register_subject("write_off/" + c + "/relgeo write_mesh", relgeo_write_off, c);
    register_cgal_subjects("write_off", c, 1);
  }
}

}  // namespace
}  // namespace relgeo_bench

int main(int argc, char** argv) {
  relgeo_bench::Command_line args(argc, argv);
  if (!args.initialize()) return 2;
  relgeo_bench::register_subjects();
  relgeo_bench::Ratio_reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  return relgeo_bench::finish(reporter.ran(), argv[0]);
}
