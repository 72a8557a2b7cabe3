// relgeo_boolean_benchmark: relgeo::boolean under its kernels against CGAL's
// corefinement (Epick, Epeck) on the same operands, in one run.
//
// Cases: two offset 20K-triangle spheres; CGAL's elephant against a rotated
// copy; CGAL's armadillo against a 20K-triangle sphere; three models of
// CGAL's data set against moved copies (a rotor and fandisk, CAD parts, and
// a gear); a 10^6-triangle pair (two offset tori of 5 x 10^5 triangles
// each). Operations: union, intersection, difference. Each subject runs
// `--relgeo_repetitions` times (default 3); the table gives the minimum
// time, its ratio to the peer (CGAL Epick for relgeo's double kernels, CGAL
// Epeck for Exact_kernel), whether the output is a closed oriented manifold
// (checked after the timed run, for every subject: the checks are not the
// subject's work), and, measured once in a fresh process per subject, the
// peak memory above the operands. A second table gives relgeo's phase times
// (Boolean_timing) in its fastest run.
//
// The first table also gives the minor page faults of that fastest run.
//
// Flags (besides Google Benchmark's): --relgeo_large (also run Epeck and the
// exact kernel on the 10^6 pair), --relgeo_memory=false, --relgeo_repetitions=N,
// --relgeo_malloc=retain (glibc keeps freed memory mapped, for every subject:
// the runs then touch no fresh page once warm, so the times leave out what
// page faults cost on this machine; doc/boolean.md, "Page faults").
#include <malloc.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "boolean_benchmark.h"
#include "common/command_line.h"
#include "common/process_memory.h"
#include "relgeo/boolean.h"
#include "relgeo/kernel.h"
#include "relgeo/mesh/mesh_io.h"
#include "relgeo/mesh/validity.h"
#include "../../test/boolean/boolean_inputs.h"

namespace relgeo_bench {

bool closed_oriented_manifold(const Mesh& m) {
  const relgeo::Mesh_report r = relgeo::check_mesh<relgeo::Filtered_exact_kernel>(m, {.check_collinear_faces = false});
  return r.is_closed() && r.is_manifold() && r.is_consistently_oriented();
}
double volume(const Mesh& m) { return relgeo::test::volume(m); }

namespace {

Mesh data_mesh(const char* name) {
  return relgeo::read_mesh(std::string(RELGEO_CGAL_MESH_DIR) + "/" + name);
}
// The box of m's vertices: lower corner, then upper corner.
std::array<double, 6> box(const Mesh& m) {
  std::array<double, 6> b{1e300, 1e300, 1e300, -1e300, -1e300, -1e300};
  for (const auto& p : m.vertices) {
    const double c[3] = {p.x, p.y, p.z};
    for (int i = 0; i < 3; ++i) b[i] = std::min(b[i], c[i]), b[3 + i] = std::max(b[3 + i], c[i]);
  }
  return b;
}
// m scaled to fit the box of `like` and moved by `shift` (in units of its size).
Mesh fitted(const Mesh& m, const Mesh& like, double shift) {
  const auto bm = box(m), bl = box(like);
  const double sm = std::max({bm[3] - bm[0], bm[4] - bm[1], bm[5] - bm[2]});
  const double sl = std::max({bl[3] - bl[0], bl[4] - bl[1], bl[5] - bl[2]});
  Mesh r = m;
  for (auto& p : r.vertices) {
    p.x = (p.x - (bm[0] + bm[3]) / 2) * sl / sm * 0.6 + (bl[0] + bl[3]) / 2 + shift * sl;
    p.y = (p.y - (bm[1] + bm[4]) / 2) * sl / sm * 0.6 + (bl[1] + bl[4]) / 2;
    p.z = (p.z - (bm[2] + bm[5]) / 2) * sl / sm * 0.6 + (bl[2] + bl[5]) / 2;
  }
  return r;
}
// A model of CGAL's data set against a copy rotated by 0.5 rad about z,
// tilted by 0.3 and moved by a tenth of its size: the operands of
// BooleanCgalOracle.CgalDataSetAgainstMovedCopies.
std::pair<Mesh, Mesh> against_moved_copy(const char* name) {
  const Mesh m = data_mesh(name);
  const auto b = box(m);
  const double size = std::max({b[3] - b[0], b[4] - b[1], b[5] - b[2]});
  return {m, relgeo::rigidly_moved(m, 0.5, 0.3, {0.1 * size, 0.05 * size, 0.02 * size})};
}

}  // namespace

const std::vector<Boolean_case>& boolean_cases() {
  using namespace relgeo::test;
  static const std::vector<Boolean_case> cases{
      {"spheres-20K", [] { return std::pair{icosphere(5), icosphere(5, {0.5, 0.3, 0.2}, 0.9)}; }, false},
      {"elephant-rotated", [] {
         const Mesh e = data_mesh("elephant.off");
         return std::pair{e, rigidly_moved(e, 0.5, 0.3, {0.02, 0.01, 0.005})};
       }, false},
      {"armadillo-sphere", [] {
         const Mesh a = data_mesh("armadillo.off");
         return std::pair{a, fitted(icosphere(5), a, 0.1)};
       }, false},
      // Parts with axis-aligned faces and edges, and a gear with slivers:
      // where the narrow phase met exactly equal coordinates (doc/boolean.md,
      // "Where the time goes").
      {"rotor-moved", [] { return against_moved_copy("rotor_small.off"); }, false},
      {"fandisk-moved", [] { return against_moved_copy("fandisk.off"); }, false},
      {"pinion-moved", [] { return against_moved_copy("pinion.off"); }, false},
      {"tori-1M", [] { return std::pair{torus(1, 0.4, 500, 500), torus(1, 0.4, 500, 500, {0.3, 0.2, 0.1})}; }, true},
  };
  return cases;
}

const std::pair<Mesh, Mesh>& operands(const std::string& name) {
  static std::map<std::string, std::pair<Mesh, Mesh>> built;
  auto it = built.find(name);
  if (it != built.end()) return it->second;
  for (const auto& c : boolean_cases())
    if (c.name == name) return built[name] = c.build();
  static const std::pair<Mesh, Mesh> none;
  return none;
}

namespace {

// `before_issue_28`: the insertion order's triangulation and nearest
// rounding (what the Boolean did before its output was made valid in
// doubles), to measure what the Delaunay faces and the repair cost.
// `validate`: the output's validation report on, as relgeo::boolean's
// defaults have it (CGAL's corefinement has none; the other subjects leave
// it off).
template <class K>
Timed_run relgeo_run(const Mesh& a, const Mesh& b, relgeo::Boolean_operation op, bool checks, int threads = 1,
                     bool before_issue_28 = false, bool validate = false) {
  return [&a, &b, op, checks, threads, before_issue_28, validate]() -> Inspect {
    auto r = std::make_shared<relgeo::Boolean_result<K>>(relgeo::boolean(
        a, b, op, K{},
        {.check_operands = checks,
         .check_self_intersections = checks,
         .rounding = before_issue_28 ? relgeo::Output_rounding::nearest : relgeo::Output_rounding::repaired,
         .delaunay_retriangulation = !before_issue_28,
         .validate_output = validate,
         .threads = threads}));
    return [r] {
      return Run_outcome{r->mesh.faces.size(), r->ok() && closed_oriented_manifold(r->mesh), volume(r->mesh), r->time};
    };
  };
}

std::vector<Subject> subjects() {
  std::vector<Subject> s{
      {"relgeo filtered", [](const Mesh& a, const Mesh& b, relgeo::Boolean_operation op) {
         return relgeo_run<relgeo::Filtered_exact_kernel>(a, b, op, true);
       }, false, "CGAL::corefine Epick"},
      {"relgeo filtered, defaults", [](const Mesh& a, const Mesh& b, relgeo::Boolean_operation op) {
         return relgeo_run<relgeo::Filtered_exact_kernel>(a, b, op, true, 1, false, true);
       }, false, "CGAL::corefine Epick"},
      {"relgeo filtered, no operand check", [](const Mesh& a, const Mesh& b, relgeo::Boolean_operation op) {
         return relgeo_run<relgeo::Filtered_exact_kernel>(a, b, op, false);
       }, false, "CGAL::corefine Epick"},
      {"relgeo filtered, insertion + nearest", [](const Mesh& a, const Mesh& b, relgeo::Boolean_operation op) {
         return relgeo_run<relgeo::Filtered_exact_kernel>(a, b, op, true, 1, true);
       }, false, "relgeo filtered"},
#if defined(RELGEO_HAS_TBB) && RELGEO_HAS_TBB
      // The operand checks, the broad and the narrow phase, the
      // retriangulation and (with the defaults) the output's validation on
      // 2 threads (TBB); the rest of the Boolean is serial.
      {"relgeo filtered, 2 threads", [](const Mesh& a, const Mesh& b, relgeo::Boolean_operation op) {
         return relgeo_run<relgeo::Filtered_exact_kernel>(a, b, op, true, 2);
       }, false, "CGAL::corefine Epick"},
      {"relgeo filtered, defaults, 2 threads", [](const Mesh& a, const Mesh& b, relgeo::Boolean_operation op) {
         return relgeo_run<relgeo::Filtered_exact_kernel>(a, b, op, true, 2, false, true);
       }, false, "CGAL::corefine Epick"},
#endif
      {"relgeo exact", [](const Mesh& a, const Mesh& b, relgeo::Boolean_operation op) {
         return relgeo_run<relgeo::Exact_kernel>(a, b, op, true);
       }, true, "CGAL::corefine Epeck"},
  };
  for (auto& c : cgal_subjects()) s.push_back(std::move(c));
  return s;
}

constexpr relgeo::Boolean_operation kOps[] = {relgeo::Boolean_operation::union_of,
                                              relgeo::Boolean_operation::intersection,
                                              relgeo::Boolean_operation::difference};

struct Key {
  std::string c, op, subject;
  auto operator<=>(const Key&) const = default;
};
struct Figure {
  double seconds = 1e300;
  long faults = -1;  // minor page faults of the fastest run
  Run_outcome outcome;
  std::optional<double> peak_mb;  // absent: not measured (--relgeo_memory=false); negative: the probe failed
};
std::map<Key, Figure> figures;


// Peak resident memory of one subject's run above what its prepared
// operands use, measured in a fresh process: this program run again with
// the --relgeo_memory_probe_* flags (probe_memory below). A forked child
// would inherit the heap the earlier subjects left, whose free pages its
// small allocations refill: the figure then depended on which subjects ran
// before (up to 2 MB on the 20K-sphere case), not only on the subject.
double peak_memory_mb(const std::string& case_name, relgeo::Boolean_operation op, const std::string& subject) {
  const std::string flags[] = {"--relgeo_memory_probe_case=" + case_name,
                               "--relgeo_memory_probe_op=" + std::string(relgeo::to_string(op)),
                               "--relgeo_memory_probe_subject=" + subject};
  char* argv[] = {const_cast<char*>("/proc/self/exe"), const_cast<char*>(flags[0].c_str()),
                  const_cast<char*>(flags[1].c_str()), const_cast<char*>(flags[2].c_str()), nullptr};
  int fds[2];
  if (pipe(fds) != 0) return -1;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  close(fds[1]);
  std::string out;
  char buffer[256];
  for (ssize_t n; spawned == 0 && (n = read(fds[0], buffer, sizeof buffer)) > 0;) out.append(buffer, std::size_t(n));
  close(fds[0]);
  int status = 0;
  if (spawned != 0 || waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return -1;
  return std::strtod(out.c_str(), nullptr);
}

// The probe: prepares the subject's operands (not counted), then runs it
// once and prints the peak resident memory above that, in MB. Blocks of 64
// KB and more are mapped afresh and unmapped when freed, so that the peak
// counts the pages the run touches, not what free heap the preparation left
// (with the default threshold, one subject's figure moved by 30 MB between
// runs on the 10^6 pair).
int probe_memory(const std::string& case_name, const std::string& op_name, const std::string& subject_name) {
  const auto& [a, b] = operands(case_name);
  const relgeo::Boolean_operation* op = nullptr;
  for (const auto& o : kOps)
    if (op_name == relgeo::to_string(o)) op = &o;
  const std::vector<Subject> all = subjects();
  const auto s = std::find_if(all.begin(), all.end(), [&](const Subject& x) { return x.name == subject_name; });
  if (a.faces.empty() || !op || s == all.end()) return 1;
  mallopt(M_MMAP_THRESHOLD, 64 * 1024);
  const Timed_run run = s->prepare(a, b, *op);
  malloc_trim(0);
  {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5" << std::flush;  // VmHWM := VmRSS
  }
  const double before = static_cast<double>(proc_status_bytes("VmRSS"));
  const Inspect output = run();  // kept until the peak is read
  const double extra = (static_cast<double>(proc_status_bytes("VmHWM")) - before) / 1048576.0;
  std::printf("%.6f\n", extra);
  return 0;
}

void register_all(int repetitions, bool large, bool memory) {
  for (const auto& c : boolean_cases())
    for (relgeo::Boolean_operation op : kOps)
      for (const Subject& s : subjects()) {
        if (c.large && s.exact && !large) continue;
        const std::string name = c.name + "/" + std::string(relgeo::to_string(op)) + "/" + s.name;
        benchmark::RegisterBenchmark(name.c_str(), [c, op, s, memory](benchmark::State& state) {
          const auto& [a, b] = operands(c.name);
          if (a.faces.empty()) {
            state.SkipWithError("operands not available (CGAL's data set?)");
            return;
          }
          Figure& f = figures[{c.name, std::string(relgeo::to_string(op)), s.name}];
          for (auto _ : state) {
            state.PauseTiming();
            const auto run = s.prepare(a, b, op);
            state.ResumeTiming();
            const long faults_before = minor_page_faults();
            const auto t0 = std::chrono::steady_clock::now();
            const Inspect output = run();
            const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            const long faults = minor_page_faults() - faults_before;
            state.PauseTiming();
            if (t < f.seconds) f.seconds = t, f.faults = faults, f.outcome = output();
            state.ResumeTiming();
          }
          if (memory && !f.peak_mb) f.peak_mb = peak_memory_mb(c.name, op, s.name);
        })->Iterations(1)->Repetitions(repetitions)->Unit(benchmark::kMillisecond)->ReportAggregatesOnly(true);
      }
}

void print_table() {
  std::printf("\n%-18s %-13s %-36s %10s %8s %6s %9s %8s %8s\n", "case", "operation", "subject", "min ms", "ratio",
              "valid", "faces", "peak MB", "faults");
  for (const auto& [k, f] : figures) {
    std::string peer;
    for (const Subject& s : subjects())
      if (s.name == k.subject) peer = s.peer;
    const auto p = figures.find({k.c, k.op, peer});
    const double ratio = p == figures.end() ? 1.0 : f.seconds / p->second.seconds;
    char peak[32] = "-";
    if (f.peak_mb && *f.peak_mb < 0) std::snprintf(peak, sizeof peak, "FAILED");
    else if (f.peak_mb) std::snprintf(peak, sizeof peak, "%.1f", *f.peak_mb);
    std::printf("%-18s %-13s %-36s %10.1f %8.3f %6s %9zu %8s %8ld\n", k.c.c_str(), k.op.c_str(), k.subject.c_str(),
                1e3 * f.seconds, ratio, f.outcome.valid ? "yes" : "NO", f.outcome.faces, peak, f.faults);
  }
  // Where relgeo's time went, in its fastest run (Boolean_timing).
  std::printf("\n%-18s %-13s %-36s %7s %7s %7s %7s %7s %7s %7s %7s\n", "case", "operation", "subject (phases, ms)",
              "check", "broad", "narrow", "retri", "label", "assembl", "round", "valid");
  for (const auto& [k, f] : figures) {
    if (!f.outcome.phases) continue;
    const relgeo::Boolean_timing& t = *f.outcome.phases;
    std::printf("%-18s %-13s %-36s %7.1f %7.1f %7.1f %7.1f %7.1f %7.1f %7.1f %7.1f\n", k.c.c_str(), k.op.c_str(),
                k.subject.c_str(), 1e3 * t.check, 1e3 * t.broad_phase, 1e3 * t.narrow_phase, 1e3 * t.retriangulation,
                1e3 * t.labelling, 1e3 * t.assembly, 1e3 * t.rounding, 1e3 * t.validation);
  }
}

}  // namespace
}  // namespace relgeo_bench

int main(int argc, char** argv) {
  relgeo_bench::Command_line args(argc, argv);
  if (args.has("--relgeo_memory_probe_case"))  // a subject's memory, in a process of its own
    return relgeo_bench::probe_memory(args.value("--relgeo_memory_probe_case"), args.value("--relgeo_memory_probe_op"),
                                      args.value("--relgeo_memory_probe_subject"));
  const bool large = args.has("--relgeo_large");
  const bool memory = args.value("--relgeo_memory") != "false";
  const std::string reps = args.value("--relgeo_repetitions");
  const std::string malloc_mode = args.value("--relgeo_malloc");
  args.erase("--relgeo_large");
  args.erase("--relgeo_memory");
  args.erase("--relgeo_repetitions");
  args.erase("--relgeo_malloc");
  if (malloc_mode == "retain") {
    // The largest mmap threshold glibc takes (blocks below it come from
    // the heap), and a heap top that is never given back.
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
    std::printf("glibc malloc keeps freed memory (--relgeo_malloc=retain): no subject pays for page faults once warm\n");
  } else if (!malloc_mode.empty() && malloc_mode != "default") {
    std::fprintf(stderr, "--relgeo_malloc takes default or retain, not '%s'\n", malloc_mode.c_str());
    return 2;
  }
  if (!args.initialize()) return 2;
  relgeo_bench::register_all(reps.empty() ? 3 : std::stoi(reps), large, memory);
  const std::size_t ran = benchmark::RunSpecifiedBenchmarks();
  relgeo_bench::print_table();
  return relgeo_bench::finish(ran, argv[0]);
}
