// benchmark/hull/hull_benchmark.cpp — planar convex hulls: relgeo's
// graham_fortune, monotone_chain and graham_incremental under relgeo kernels,
// and, side by side, CGAL::ch_graham_andrew and CGAL::convex_hull_2 on Epick
// and Epeck (hull_benchmark_cgal.cpp).
//
// Benchmarks are named `hull/<family>/<N>/<algorithm>/<kernel>`:
//   family     uniform | circle | line (hull_benchmark.h), N = 10^5, 10^6, 10^7
//   algorithm  graham_fortune | graham_fortune_allpoints (no interior
//              prefilter) | monotone_chain | graham_incremental |
//              CGAL::ch_graham_andrew | CGAL::convex_hull_2
//   kernel     a relgeo kernel's name() ("double" = Naive_kernel<double>,
//              "failsafe<double>", "filtered", "exact") or Epick | Epeck
// Limits: Exact_kernel only N <= 10^5 (10^6 on uniform), CGAL Epeck N <= 10^6,
// graham_incremental (O(n h)) only on uniform, N <= 10^5, and only with the
// naive, failsafe and filtered kernels.
//
// One iteration computes one hull from points built beforehand (input
// preparation is not timed). Counters: hull (output size), backward_error
// (relgeo::hull_backward_error of the output, relative to M; computed once per
// benchmark outside the timed loop, inf when the output is not in convex
// position; not computed for N above --relgeo_backward_error_max_n),
// time/point (seconds per input point, with an SI prefix).
//
// After the runs:
//  * a "ratios" table per family and N: real time, time per point, ratio to
//    CGAL::ch_graham_andrew on Epick, hull size, backward error; and the
//    project's bars marked PASS or MISS:
//      graham_fortune/failsafe<double>  <= 1.25 x ch_graham_andrew/Epick  (uniform 10^6)
//      graham_fortune/filtered          <= 1.1  x ch_graham_andrew/Epick  (uniform 10^6)
//      graham_fortune/exact             <= 1.0  x ch_graham_andrew/Epeck  (uniform 10^5, 10^6)
//    each also for graham_fortune_allpoints;
//  * `sort/uniform/<N>/pdqsort_branchless|std::sort`: the sort of a copy of
//    the points alone (the largest part of a hull), in the console output;
//  * a peak-memory table: before the benchmarks run, each listed subject
//    computes the hull of the largest uniform input in a forked child process;
//    extra = peak resident memory during the hull (VmHWM, reset with
//    /proc/self/clear_refs once the input is built, after a warm-up hull of
//    4096 points has loaded the code) - resident memory before
//    it; bar: input + extra <= 2 x input, the input being the points in the
//    subject's point type.
// It is a report: the exit status is 0 whatever the ratios (1 only for a
// wrong argument or a filter matching nothing).
//
// Defaults, each unless given: --benchmark_min_time=0.3
// --benchmark_repetitions=1. Own flags (consumed before Google Benchmark sees
// the arguments):
//   --relgeo_sizes=N1,N2,...        input sizes (default 100000,1000000,10000000)
//   --relgeo_backward_error_max_n=N no backward_error above N (default: all)
//   --relgeo_memory=true|false      the peak-memory table (default true)
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <boost/sort/pdqsort/pdqsort.hpp>

#include "common/command_line.h"
#include "common/process_memory.h"
#include "hull_benchmark.h"
#include "relgeo/error/hull_backward_error.h"
#include "relgeo/hull.h"
#include "relgeo/kernel.h"

namespace relgeo_hull_bench {

// ---- inputs ---------------------------------------------------------------------

namespace {
double uniform01(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1p-53; }
double ulps(double v, int k) {
  const double dir = k > 0 ? std::numeric_limits<double>::infinity()
                           : -std::numeric_limits<double>::infinity();
  for (int i = 0; i < std::abs(k); ++i) v = std::nextafter(v, dir);
  return v;
}
}  // namespace

Input make_input(const std::string& family, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  Input in{family + "/" + std::to_string(n) + "/" + std::to_string(seed), {}};
  auto& pts = in.points;
  pts.reserve(n);
  if (family == "uniform") {
    for (std::size_t i = 0; i < n; ++i) pts.push_back({2 * uniform01(g) - 1, 2 * uniform01(g) - 1});
  } else if (family == "circle") {
    for (std::size_t i = 0; i < n; ++i) {
      const double t = 2 * uniform01(g) - 1, d = 1 + t * t;
      const double x = (1 - t * t) / d, y = 2 * t / d;
      pts.push_back({i % 2 ? -x : x, y});
    }
  } else if (family == "line") {
    const double ax = 0.5, ay = 0.5, bx = 24.25, by = 17.3;
    for (std::size_t i = 0; i < n; ++i) {
      const double t = uniform01(g);
      const int kx = static_cast<int>(g() % 9) - 4, ky = static_cast<int>(g() % 9) - 4;
      pts.push_back({ulps(ax + t * (bx - ax), kx), ulps(ay + t * (by - ay), ky)});
    }
  } else {
    throw std::invalid_argument("unknown family " + family);
  }
  return in;
}

// ---- relgeo's subjects ----------------------------------------------------------------

namespace {

// graham_fortune_allpoints: graham_fortune with Hull_options::discard_interior
// = false, the scan over every point as the thesis states it (the default
// drops certainly interior points first, which CGAL's ch_graham_andrew does
// not; CGAL's convex_hull_2 does, with its own Akl-Toussaint step).
enum class Algorithm { graham_fortune, graham_fortune_allpoints, monotone_chain, graham_incremental };

const char* algorithm_name(Algorithm a) {
  switch (a) {
    case Algorithm::graham_fortune: return "graham_fortune";
    case Algorithm::graham_fortune_allpoints: return "graham_fortune_allpoints";
    case Algorithm::monotone_chain: return "monotone_chain";
    case Algorithm::graham_incremental: return "graham_incremental";
  }
  return "?";
}

template <class K>
Subject relgeo_subject(Algorithm algorithm, std::function<bool(const std::string&, std::size_t)> runs) {
  using P = typename K::Point_2;
  using Points = std::vector<P>;
  auto slot = std::make_shared<Prepared_slot<Points>>();
  auto build = [](const std::vector<relgeo::Point_2<double>>& in) {
    const auto construct = K().construct_point_2_object();
    Points v;
    v.reserve(in.size());
    for (const auto& p : in) v.push_back(construct(p.x, p.y));
    return v;
  };
  auto compute = [algorithm](const Points& pts) {
    const std::span<const P> s(pts);
    switch (algorithm) {
      case Algorithm::graham_fortune: return relgeo::graham_fortune<K>(s);
      case Algorithm::graham_fortune_allpoints:
        return relgeo::graham_fortune<K>(s, K{}, relgeo::Hull_options{.discard_interior = false});
      case Algorithm::monotone_chain: return relgeo::monotone_chain<K>(s);
      default: return relgeo::graham_incremental<K>(s);
    }
  };
  using Result = relgeo::Hull_result<P>;
  Subject s;
  s.algorithm = algorithm_name(algorithm);
  s.kernel = K::name();
  s.runs = std::move(runs);
  s.bench = [slot, build, compute](benchmark::State& state, const Input& in) {
    const Points& pts = slot->get(in, build);
    time_hull(state, pts, compute, [](const Result& r) { return r.indices.size(); });
  };
  s.hull_indices = [slot, build, compute](const Input& in) {
    return compute(slot->get(in, build)).indices;
  };
  s.memory_probe = [build, compute](std::size_t n, std::size_t* input_bytes) {
    auto pts = std::make_shared<Points>();
    if constexpr (std::is_same_v<P, relgeo::Point_2<double>>) {
      *pts = std::move(make_input("uniform", n, 1).points);  // the input itself: no copy
    } else {
      const Input in = make_input("uniform", n, 1);
      *pts = build(in.points);
    }
    *input_bytes = pts->size() * sizeof(P);
    return std::function<std::size_t()>([pts, compute] { return compute(*pts).indices.size(); });
  };
  s.release = [slot] { slot->release(); };
  return s;
}

}  // namespace

std::vector<Subject> relgeo_subjects() {
  using namespace relgeo;
  auto everywhere = [](const std::string&, std::size_t) { return true; };
  auto exact_sizes = [](const std::string& family, std::size_t n) {
    return n <= (family == "uniform" ? kExactMaxN : std::size_t{100000});
  };
  auto incremental_sizes = [](const std::string& family, std::size_t n) {
    return family == "uniform" && n <= kIncrementalMaxN;
  };
  std::vector<Subject> s;
  for (Algorithm a : {Algorithm::graham_fortune, Algorithm::graham_fortune_allpoints, Algorithm::monotone_chain}) {
    s.push_back(relgeo_subject<Naive_kernel<double>>(a, everywhere));
    s.push_back(relgeo_subject<Failsafe_kernel<double>>(a, everywhere));
    s.push_back(relgeo_subject<Filtered_exact_kernel>(a, everywhere));
    s.push_back(relgeo_subject<Exact_kernel>(a, exact_sizes));
  }
  s.push_back(relgeo_subject<Naive_kernel<double>>(Algorithm::graham_incremental, incremental_sizes));
  s.push_back(relgeo_subject<Failsafe_kernel<double>>(Algorithm::graham_incremental, incremental_sizes));
  s.push_back(relgeo_subject<Filtered_exact_kernel>(Algorithm::graham_incremental, incremental_sizes));
  return s;
}

namespace {

// ---- the inputs of the running benchmarks --------------------------------------------

/// One input at a time (three of 10^7 points would be half a gigabyte).
class Input_cache {
 public:
  const Input& get(const std::string& family, std::size_t n) {
    if (!input_ || family_ != family || n_ != n) {
      input_.reset();
      input_ = std::make_unique<Input>(make_input(family, n, seed(family)));
      family_ = family, n_ = n;
    }
    return *input_;  // its key names it for the subjects' caches
  }
  static std::uint64_t seed(const std::string& family) {
    return family == "uniform" ? 1 : family == "circle" ? 2 : 3;
  }

 private:
  std::unique_ptr<Input> input_;
  std::string family_;
  std::size_t n_ = 0;
};

/// Backward errors, computed once per benchmark; identical outputs on one
/// input share a computation.
class Backward_errors {
 public:
  double get(const std::string& benchmark, const Input& in, const Subject& s) {
    if (auto it = by_name_.find(benchmark); it != by_name_.end()) return it->second;
    std::vector<std::size_t> idx = s.hull_indices(in);
    const auto key = std::make_pair(in.key, std::move(idx));
    auto it = by_output_.find(key);
    if (it == by_output_.end())
      it = by_output_.emplace(key, relgeo::hull_backward_error(in.points, key.second).value).first;
    if (by_output_.size() > 64) {  // keep memory bounded (outputs of 10^7 indices)
      const double v = it->second;
      by_output_.clear();
      it = by_output_.emplace(key, v).first;
    }
    return by_name_[benchmark] = it->second;
  }

 private:
  std::map<std::string, double> by_name_;
  std::map<std::pair<std::string, std::vector<std::size_t>>, double> by_output_;
};

// ---- ratio table --------------------------------------------------------------------

constexpr const char* kReference = "CGAL::ch_graham_andrew/Epick";

struct Bar {
  std::string family;
  std::size_t n;
  std::string subject, reference;
  double limit;
};
const std::vector<Bar>& bars() {
  static const std::vector<Bar> b{
      {"uniform", 1000000, "graham_fortune/failsafe<double>", kReference, 1.25},
      {"uniform", 1000000, "graham_fortune/filtered", kReference, 1.1},
      {"uniform", 100000, "graham_fortune/exact", "CGAL::ch_graham_andrew/Epeck", 1.0},
      {"uniform", 1000000, "graham_fortune/exact", "CGAL::ch_graham_andrew/Epeck", 1.0},
      // The same bars for the scan over every point (no prefilter).
      {"uniform", 1000000, "graham_fortune_allpoints/failsafe<double>", kReference, 1.25},
      {"uniform", 1000000, "graham_fortune_allpoints/filtered", kReference, 1.1},
      {"uniform", 100000, "graham_fortune_allpoints/exact", "CGAL::ch_graham_andrew/Epeck", 1.0},
      {"uniform", 1000000, "graham_fortune_allpoints/exact", "CGAL::ch_graham_andrew/Epeck", 1.0},
  };
  return b;
}

/// Forwards to the display reporter and keeps every run's times and counters.
class Ratio_reporter : public benchmark::BenchmarkReporter {
 public:
  explicit Ratio_reporter(std::unique_ptr<benchmark::BenchmarkReporter> inner)
      : inner_(std::move(inner)) {}
  bool ReportContext(const Context& c) override { return inner_->ReportContext(c); }
  void ReportRuns(const std::vector<Run>& runs) override {
    inner_->ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.run_type != Run::RT_Iteration || r.error_occurred || r.iterations <= 0) continue;
      Entry& e = entries_[r.run_name.function_name];
      e.real_ms.push_back(1e3 * relgeo_bench::to_seconds(r.GetAdjustedRealTime(), r.time_unit));
      e.cpu_ms.push_back(1e3 * relgeo_bench::to_seconds(r.GetAdjustedCPUTime(), r.time_unit));
      if (auto c = r.counters.find("hull"); c != r.counters.end()) e.hull = c->second.value;
      if (auto c = r.counters.find("backward_error"); c != r.counters.end()) e.backward = c->second.value;
    }
  }
  void Finalize() override { inner_->Finalize(); }
  void print(std::ostream& out, const std::vector<std::string>& order) const;

 private:
  struct Entry {
    std::vector<double> real_ms, cpu_ms;
    double hull = 0, backward = std::numeric_limits<double>::quiet_NaN();
  };
  std::unique_ptr<benchmark::BenchmarkReporter> inner_;
  std::map<std::string, Entry> entries_;
};

std::string fixed(double v, int decimals) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << v;
  return s.str();
}
std::string ms_text(double ms) { return fixed(ms, ms < 10 ? 3 : ms < 1000 ? 1 : 0); }
std::string backward_text(double v) {
  if (std::isnan(v)) return "-";
  if (std::isinf(v)) return "inf";
  if (v == 0) return "0";
  std::ostringstream s;
  s << std::setprecision(2) << v;
  return s.str();
}

void Ratio_reporter::print(std::ostream& out, const std::vector<std::string>& order) const {
  // group "hull/<family>/<N>" -> rows
  struct Row {
    std::string subject;
    double real, cpu, hull, backward;
  };
  std::vector<std::pair<std::string, std::vector<Row>>> groups;
  for (const std::string& name : order) {
    const auto it = entries_.find(name);
    if (it == entries_.end()) continue;
    std::size_t slash = 0;
    for (int k = 0; k < 3 && slash != std::string::npos; ++k) slash = name.find('/', slash + 1);
    if (slash == std::string::npos) continue;
    const std::string group = name.substr(0, slash), subject = name.substr(slash + 1);
    auto g = std::find_if(groups.begin(), groups.end(), [&](const auto& x) { return x.first == group; });
    if (g == groups.end()) g = groups.insert(groups.end(), {group, {}});
    g->second.push_back({subject, relgeo_bench::median(it->second.real_ms), relgeo_bench::median(it->second.cpu_ms),
                         it->second.hull, it->second.backward});
  }
  if (groups.empty()) return;
  out << "\nratios: real time of one hull (median of the repetitions), time per input point, and "
         "the ratio to " << kReference << ";\n"
      << "  backward_error = relgeo::hull_backward_error of the output / M (inf: not convex; -: "
         "not computed); real/cpu > 1.05 means the process waited for the CPU.\n";
  std::vector<std::string> bar_lines;
  for (const auto& [group, rows] : groups) {
    const std::string rest = group.substr(group.find('/') + 1);
    const std::string family = rest.substr(0, rest.find('/'));
    const std::size_t n = std::stoull(rest.substr(rest.find('/') + 1));
    auto find = [&](const std::string& s) -> const Row* {
      for (const Row& r : rows)
        if (r.subject == s) return &r;
      return nullptr;
    };
    const Row* ref = find(kReference);
    out << '\n' << std::left << std::setw(44) << group << std::right << std::setw(11) << "ms"
        << std::setw(11) << "cpu ms" << std::setw(10) << "ns/point" << std::setw(9) << "/Epick"
        << std::setw(10) << "hull" << std::setw(12) << "backward" << "   bar\n";
    for (const Row& r : rows) {
      out << "  " << std::left << std::setw(42) << r.subject << std::right << std::setw(11)
          << ms_text(r.real) << std::setw(11) << ms_text(r.cpu) << std::setw(10)
          << fixed(r.real * 1e6 / double(n), 1) << std::setw(9)
          << (ref ? fixed(r.real / ref->real, 3) : std::string("n/a")) << std::setw(10)
          << static_cast<long long>(r.hull) << std::setw(12) << backward_text(r.backward);
      for (const Bar& b : bars()) {
        if (b.family != family || b.n != n || b.subject != r.subject) continue;
        const Row* bref = find(b.reference);
        std::ostringstream line;
        line << "<= " << fixed(b.limit, 2) << "x " << b.reference << ": ";
        if (!bref) {
          line << "n/a (reference not run)";
        } else {
          const double q = r.real / bref->real, qc = r.cpu / bref->cpu;
          line << (q <= b.limit ? "PASS" : "MISS") << " (" << fixed(q, 3) << "; cpu " << fixed(qc, 3)
               << ")";
        }
        out << "   " << line.str();
        bar_lines.push_back(group + " " + r.subject + " " + line.str());
      }
      if (r.real > 1.05 * r.cpu) out << "   real/cpu " << fixed(r.real / r.cpu, 2);
      out << '\n';
    }
  }
  if (!bar_lines.empty()) {
    out << "\nbars:\n";
    for (const auto& l : bar_lines) out << "  " << l << '\n';
  }
}

// ---- peak memory -----------------------------------------------------------------------

struct Memory_figure {
  std::size_t input_bytes = 0, baseline = 0, peak = 0, hull = 0;
  bool reset_ok = false, ok = false;
};

/// In a forked child: build the subject's input, reset the peak RSS, compute
/// the hull once, report the peak.
Memory_figure measure_memory(const Subject& s, std::size_t n) {
  Memory_figure m;
  int fds[2];
  if (pipe(fds) != 0) return m;
  std::cout.flush();
  const pid_t pid = fork();
  if (pid < 0) return m;
  if (pid == 0) {
    close(fds[0]);
    Memory_figure c;
    {  // warm-up on a small input: code pages loaded on first use are not the hull's memory
      std::size_t small_bytes = 0;
      (void)s.memory_probe(std::min<std::size_t>(n, 4096), &small_bytes)();
    }
    auto run = s.memory_probe(n, &c.input_bytes);
    {
      std::ofstream clear("/proc/self/clear_refs");
      clear << "5" << std::flush;  // resets VmHWM to the current RSS
      c.reset_ok = static_cast<bool>(clear);
    }
    c.baseline = relgeo_bench::proc_status_bytes("VmRSS");
    c.hull = run();
    c.peak = relgeo_bench::proc_status_bytes("VmHWM");
    c.ok = true;
    const ssize_t w = write(fds[1], &c, sizeof c);
    _exit(w == static_cast<ssize_t>(sizeof c) ? 0 : 1);
  }
  close(fds[1]);
  const ssize_t r = read(fds[0], &m, sizeof m);
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (r != static_cast<ssize_t>(sizeof m)) m.ok = false;
  return m;
}

std::vector<const Subject*> memory_subjects(const std::vector<Subject>& subjects) {
  std::vector<const Subject*> probe;
  for (const Subject& s : subjects) {
    const std::string id = s.algorithm + "/" + s.kernel;
    if (id == "graham_fortune/double" || id == "graham_fortune/failsafe<double>" ||
        id == "graham_fortune/filtered" || id == "graham_fortune_allpoints/failsafe<double>" ||
        id == "monotone_chain/failsafe<double>" ||
        id == "CGAL::ch_graham_andrew/Epick" || id == "CGAL::convex_hull_2/Epick")
      probe.push_back(&s);
  }
  return probe;
}

void print_memory(std::ostream& out, const std::vector<const Subject*>& subjects,
                  const std::vector<Memory_figure>& figures, std::size_t n) {
  out << "\npeak memory: one hull of " << n
      << " uniform points, each subject in a child process forked before the benchmarks ran;\n"
         "  input = the points in the subject's point type; extra = VmHWM during the hull - VmRSS "
         "before it (the peak is reset with\n  /proc/self/clear_refs once the input is built, after a 4096-point warm-up hull); "
         "peak = input + extra. Bar: peak <= 2 x input (i.e. extra <= input).\n\n";
  out << std::left << std::setw(42) << "subject" << std::right << std::setw(11) << "input MB"
      << std::setw(11) << "extra MB" << std::setw(11) << "peak MB" << std::setw(13) << "extra/input"
      << std::setw(12) << "peak/input" << "   bar\n";
  for (std::size_t i = 0; i < subjects.size(); ++i) {
    const Subject* s = subjects[i];
    const Memory_figure& m = figures[i];
    out << "  " << std::left << std::setw(40) << (s->algorithm + "/" + s->kernel) << std::right;
    if (!m.ok || m.input_bytes == 0) {
      out << "  (measurement failed)\n";
      continue;
    }
    const double mb = 1.0 / (1024 * 1024);
    const double extra = std::max(0.0, double(m.peak) - double(m.baseline));
    const double peak = double(m.input_bytes) + extra;
    const double q = peak / double(m.input_bytes);
    out << std::setw(11) << fixed(m.input_bytes * mb, 1) << std::setw(11) << fixed(extra * mb, 1)
        << std::setw(11) << fixed(peak * mb, 1) << std::setw(13) << fixed(extra / double(m.input_bytes), 3)
        << std::setw(12) << fixed(q, 3) << "   <= 2x input: " << (q <= 2.0 ? "PASS" : "MISS");
    if (!m.reset_ok) out << " (peak not reset: includes building the input)";
    out << '\n';
  }
}

// ---- command line ---------------------------------------------------------------------

bool parse_size(const std::string& s, std::size_t& out) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);  // accepts 1e6
  if (s.empty() || *end != '\0' || !(v >= 1) || v > 1e9 || v != std::floor(v)) return false;
  out = static_cast<std::size_t>(v);
  return true;
}

}  // namespace
}  // namespace relgeo_hull_bench

int main(int argc, char** argv) {
  using namespace relgeo_hull_bench;
  relgeo_bench::Command_line args(argc, argv);

  // Own flags.
  std::vector<std::size_t> sizes = {100000, 1000000, 10000000};
  std::size_t backward_max_n = static_cast<std::size_t>(-1);
  bool memory = true;
  if (args.has("--relgeo_sizes")) {
    sizes.clear();
    std::stringstream list(args.value("--relgeo_sizes"));
    std::string item;
    while (std::getline(list, item, ',')) {
      std::size_t n = 0;
      if (!parse_size(item, n)) {
        std::cerr << "relgeo_hull_benchmark: --relgeo_sizes needs sizes like 100000,1e6\n";
        return 1;
      }
      sizes.push_back(n);
    }
    if (sizes.empty()) {
      std::cerr << "relgeo_hull_benchmark: --relgeo_sizes is empty\n";
      return 1;
    }
    args.erase("--relgeo_sizes");
  }
  if (args.has("--relgeo_backward_error_max_n")) {
    if (!parse_size(args.value("--relgeo_backward_error_max_n"), backward_max_n)) {
      std::cerr << "relgeo_hull_benchmark: --relgeo_backward_error_max_n needs a size\n";
      return 1;
    }
    args.erase("--relgeo_backward_error_max_n");
  }
  if (args.has("--relgeo_memory")) {
    const std::string v = args.value("--relgeo_memory");
    if (v != "true" && v != "false") {
      std::cerr << "relgeo_hull_benchmark: --relgeo_memory=true|false\n";
      return 1;
    }
    memory = v == "true";
    args.erase("--relgeo_memory");
  }
  args.set_measuring_defaults("0.3", "1");
  const std::string format = args.value("--benchmark_format");
  if (!args.initialize()) return 1;

  std::vector<Subject> subjects = relgeo_subjects();
  for (Subject& s : cgal_subjects()) subjects.push_back(std::move(s));

  // Peak memory first, while this process is small (children share its pages).
  const std::size_t memory_n = *std::max_element(sizes.begin(), sizes.end());
  const std::vector<const Subject*> memory_probe = memory ? memory_subjects(subjects)
                                                          : std::vector<const Subject*>{};
  std::vector<Memory_figure> memory_figures;
  for (const Subject* s : memory_probe) memory_figures.push_back(measure_memory(*s, memory_n));

  Input_cache inputs;
  Backward_errors backward;
  std::vector<std::string> names;
  for (std::size_t n : sizes)
    for (const std::string family : {"uniform", "circle", "line"})
      for (const Subject& s : subjects) {
        if (!s.runs(family, n)) continue;
        names.push_back("hull/" + family + "/" + std::to_string(n) + "/" + s.algorithm + "/" + s.kernel);
        benchmark::RegisterBenchmark(
            names.back().c_str(),
            [&, &s = s, family = std::string(family), n, name = names.back()](benchmark::State& st) {
              const Input& in = inputs.get(family, n);
              s.bench(st, in);
              if (n <= backward_max_n)
                st.counters["backward_error"] =
                    backward.get(name, in, s);
            })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
      }
  // The largest part of a hull alone: a copy of the points sorted
  // lexicographically, by Boost's pdqsort_branchless with a branch-free "less"
  // as relgeo's hulls do, and by std::sort as CGAL's ch_graham_andrew does.
  for (std::size_t n : sizes)
    for (const bool pdq : {true, false})
      benchmark::RegisterBenchmark(
          ("sort/uniform/" + std::to_string(n) + (pdq ? "/pdqsort_branchless" : "/std::sort")).c_str(),
          [&inputs, n, pdq](benchmark::State& st) {
            using P = relgeo::Point_2<double>;
            const std::vector<P>& points = inputs.get("uniform", n).points;
            for (auto _ : st) {
              std::vector<P> copy(points);
              if (pdq)
                boost::sort::pdqsort_branchless(copy.begin(), copy.end(), [](const P& a, const P& b) {
                  return (a.x < b.x) | ((a.x == b.x) & (a.y < b.y));
                });
              else
                std::sort(copy.begin(), copy.end(),
                          [](const P& a, const P& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
              benchmark::DoNotOptimize(copy.data());
            }
          })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();

  Ratio_reporter reporter(relgeo_bench::make_display_reporter(format, "relgeo_hull_benchmark"));
  const std::size_t ran = benchmark::RunSpecifiedBenchmarks(&reporter);
  for (const Subject& s : subjects) s.release();
  std::ostream& table = format == "json" ? std::cerr : std::cout;
  reporter.print(table, names);

  if (memory) print_memory(table, memory_probe, memory_figures, memory_n);
  return relgeo_bench::finish(ran, "relgeo_hull_benchmark");
}
