// benchmark/kernel/predicate_benchmark.cpp — throughput of orientation_2 and
// orientation_3 for every relgeo kernel and, side by side, CGAL's own functors.
//
// Benchmarks are named `<predicate>/<family>/<subject>`:
//   predicate  orientation_2 | orientation_3
//   family     uniform | near-collinear (2D) | uniform | near-coplanar (3D),
//              kDefaultCases cases of relgeo::analysis's generators
//   subject    a relgeo kernel's name() ("double", "failsafe<double>",
//              "filtered", "cgal-epick" = relgeo's Cgal_kernel adapter ...), or
//              "CGAL::<kernel>" for a CGAL functor used directly.
// One benchmark iteration evaluates the whole batch; `time/call` and
// `items_per_second` are per predicate call (CPU time), the ratio table printed
// at the end uses real time per call.
//
// After the runs a "ratios" table divides, for every family, each subject's
// time by that of Naive_kernel<double> ("double") and of CGAL::Epick's own
// functor, and marks the project's throughput bars PASS or MISS. It is a
// report: the exit status is 0 whatever the ratios (1 only when the filter
// matched no benchmark or an argument is not understood).
//
// Defaults: --benchmark_min_time=0.2 unless given; --relgeo_cases=N sets the
// number of queries per family (default 32768, see predicate_benchmark.h for
// why not fewer). Any Google Benchmark flag works (--benchmark_filter, --benchmark_repetitions: the table then uses the
// median, --benchmark_format=json: the table goes to stderr).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "predicate_benchmark.h"
#include "relgeo/kernel.h"

namespace relgeo_bench {

std::vector<Subject> relgeo_subjects() {
  using namespace relgeo;
  return {
      relgeo_subject<Naive_kernel<float>>(),
      relgeo_subject<Naive_kernel<double>>(),
      relgeo_subject<Naive_kernel<long double>>(),
      relgeo_subject<Failsafe_kernel<double>>(),
      relgeo_subject<Interval_kernel>(),
      relgeo_subject<Filtered_exact_kernel>(),
      relgeo_subject<Exact_kernel>(),
      relgeo_subject<Mpfr_kernel<53>>(),
      relgeo_subject<Mpfr_kernel<106>>(),
  };
}

namespace {

constexpr const char* kNaiveDouble = "double";
constexpr const char* kEpick = "CGAL::Epick";

/// A throughput bar of the project: time(subject) / time(reference) <= limit.
struct Bar {
  std::string predicate, family, subject, reference;
  double limit;
};
const std::vector<Bar>& bars() {
  static const std::vector<Bar> b{
      {"orientation_2", "uniform", "failsafe<double>", kNaiveDouble, 1.3},
      {"orientation_2", "near-collinear", "failsafe<double>", kNaiveDouble, 1.3},
      {"orientation_2", "uniform", "filtered", kEpick, 1.0},
      {"orientation_2", "near-collinear", "filtered", kEpick, 2.0},
  };
  return b;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

double to_ns(double t, benchmark::TimeUnit unit) {
  switch (unit) {
    case benchmark::kNanosecond: return t;
    case benchmark::kMicrosecond: return t * 1e3;
    case benchmark::kMillisecond: return t * 1e6;
    case benchmark::kSecond: return t * 1e9;
  }
  return t;
}

/// Display reporter that forwards everything to the reporter it wraps and
/// keeps the real and CPU time per call of every run, for the ratio table.
class Ratio_reporter : public benchmark::BenchmarkReporter {
 public:
  Ratio_reporter(std::unique_ptr<benchmark::BenchmarkReporter> inner, std::size_t calls_per_iteration)
      : inner_(std::move(inner)), calls_(static_cast<double>(calls_per_iteration)) {}

  bool ReportContext(const Context& context) override { return inner_->ReportContext(context); }
  void ReportRuns(const std::vector<Run>& runs) override {
    inner_->ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.run_type != Run::RT_Iteration || r.error_occurred || r.iterations <= 0) continue;
      const std::string& name = r.run_name.function_name;
      auto it = std::find_if(entries_.begin(), entries_.end(),
                             [&](const Entry& e) { return e.name == name; });
      if (it == entries_.end()) it = entries_.insert(entries_.end(), Entry{name, {}, {}});
      it->real_ns.push_back(to_ns(r.GetAdjustedRealTime(), r.time_unit) / calls_);
      it->cpu_ns.push_back(to_ns(r.GetAdjustedCPUTime(), r.time_unit) / calls_);
    }
  }
  void Finalize() override { inner_->Finalize(); }

  void print_ratios(std::ostream& out) const;

 private:
  struct Entry {
    std::string name;
    std::vector<double> real_ns, cpu_ns;
  };
  struct Row {
    std::string subject;
    double real_ns, cpu_ns;
    std::size_t samples;
  };
  std::unique_ptr<benchmark::BenchmarkReporter> inner_;
  double calls_;
  std::vector<Entry> entries_;  // in run order
};

void Ratio_reporter::print_ratios(std::ostream& out) const {
  // Group "<predicate>/<family>/<subject>" by "<predicate>/<family>", in run order.
  std::vector<std::pair<std::string, std::vector<Row>>> groups;
  for (const Entry& e : entries_) {
    const auto a = e.name.find('/');
    const auto b = a == std::string::npos ? a : e.name.find('/', a + 1);
    if (b == std::string::npos) continue;
    const std::string group = e.name.substr(0, b), subject = e.name.substr(b + 1);
    auto g = std::find_if(groups.begin(), groups.end(),
                          [&](const auto& x) { return x.first == group; });
    if (g == groups.end()) g = groups.insert(groups.end(), {group, {}});
    g->second.push_back({subject, median(e.real_ns), median(e.cpu_ns), e.real_ns.size()});
  }
  if (groups.empty()) return;

  const auto flags = out.flags();
  const auto precision = out.precision();
  out << "\nratios: real time per predicate call (median of " << entries_.front().real_ns.size()
      << " run(s) each), divided by that of Naive_kernel<double> (\"" << kNaiveDouble
      << "\") and of CGAL::Epick's own functor (\"" << kEpick << "\")\n";
  out << "  subject names: relgeo kernels by name(), cgal-* = relgeo's Cgal_kernel adapter, "
         "CGAL::* = CGAL's functor used directly\n";
  for (const auto& [group, rows] : groups) {
    const auto find = [&](const char* s) -> const Row* {
      for (const Row& r : rows)
        if (r.subject == s) return &r;
      return nullptr;
    };
    const Row* naive = find(kNaiveDouble);
    const Row* epick = find(kEpick);
    const std::string predicate = group.substr(0, group.find('/'));
    const std::string family = group.substr(group.find('/') + 1);
    out << '\n'
        << std::left << std::setw(36) << group << std::right << std::setw(11) << "ns/call"
        << std::setw(11) << "cpu ns" << std::setw(11) << "/double" << std::setw(11) << "/Epick"
        << "   bar\n";
    for (const Row& r : rows) {
      out << "  " << std::left << std::setw(34) << r.subject << std::right << std::fixed;
      const auto ns = [&](double v) {
        out << std::setw(11) << std::setprecision(v < 100 ? 2 : v < 10000 ? 1 : 0) << v;
      };
      const auto ratio = [&](const Row* ref) {
        if (ref)
          out << std::setw(11) << std::setprecision(r.real_ns / ref->real_ns < 100 ? 3 : 0)
              << r.real_ns / ref->real_ns;
        else
          out << std::setw(11) << "n/a";
      };
      ns(r.real_ns);
      ns(r.cpu_ns);
      ratio(naive);
      ratio(epick);
      for (const Bar& bar : bars()) {
        if (bar.predicate != predicate || bar.family != family || bar.subject != r.subject)
          continue;
        const Row* ref = bar.reference == kNaiveDouble ? naive : epick;
        out << "   <= " << std::setprecision(1) << bar.limit << "x " << bar.reference << ": ";
        if (!ref)
          out << "n/a (reference not run)";
        else
          out << (r.real_ns / ref->real_ns <= bar.limit ? "PASS" : "MISS");
      }
      // Real time well above CPU time: the process was descheduled (machine busy).
      if (r.real_ns > 1.05 * r.cpu_ns) out << "   (real/cpu " << std::setprecision(2)
                                           << r.real_ns / r.cpu_ns << ": busy machine?)";
      out << '\n';
    }
  }
  out.flags(flags);
  out.precision(precision);
}

/// The display reporter --benchmark_format asks for (console or json), with
/// colour only on a terminal.
std::unique_ptr<benchmark::BenchmarkReporter> make_display_reporter(const std::string& format) {
  if (format == "json") return std::make_unique<benchmark::JSONReporter>();
  if (format == "csv")  // deprecated by Google Benchmark: not offered here
    std::cerr << "relgeo_predicate_benchmark: --benchmark_format=csv unsupported, using console\n";
  const bool color = isatty(STDOUT_FILENO) && std::getenv("TERM") &&
                     std::strcmp(std::getenv("TERM"), "dumb") != 0;
  return std::make_unique<benchmark::ConsoleReporter>(
      color ? benchmark::ConsoleReporter::OO_ColorTabular : benchmark::ConsoleReporter::OO_Tabular);
}

bool has_flag(const std::vector<char*>& args, const char* flag) {
  const std::size_t n = std::strlen(flag);
  return std::any_of(args.begin(), args.end(), [&](const char* a) {
    return std::strncmp(a, flag, n) == 0 && (a[n] == '=' || a[n] == '\0');
  });
}
std::string flag_value(const std::vector<char*>& args, const char* flag) {
  const std::size_t n = std::strlen(flag);
  std::string v;
  for (const char* a : args)
    if (std::strncmp(a, flag, n) == 0 && a[n] == '=') v = a + n + 1;
  return v;
}

}  // namespace
}  // namespace relgeo_bench

int main(int argc, char** argv) {
  using namespace relgeo_bench;
  namespace ra = relgeo::analysis;

  // Default minimum time per benchmark (Google Benchmark's own is 0.5 s, which
  // makes the 60 benchmarks take over a minute).
  std::vector<char*> args(argv, argv + argc);
  std::string default_min_time = "--benchmark_min_time=0.2";
  if (!has_flag(args, "--benchmark_min_time")) args.insert(args.begin() + 1, default_min_time.data());
  const std::string format = flag_value(args, "--benchmark_format");
  // Our own flag, consumed before Google Benchmark sees the arguments.
  std::size_t cases = kDefaultCases;
  if (has_flag(args, "--relgeo_cases")) {
    const std::string v = flag_value(args, "--relgeo_cases");
    char* end = nullptr;
    const unsigned long long c = std::strtoull(v.c_str(), &end, 10);
    if (v.empty() || *end != '\0' || c == 0) {
      std::cerr << "relgeo_predicate_benchmark: --relgeo_cases needs a positive integer\n";
      return 1;
    }
    cases = static_cast<std::size_t>(c);
    args.erase(std::remove_if(args.begin() + 1, args.end(),
                              [](const char* a) { return std::strncmp(a, "--relgeo_cases", 14) == 0; }),
               args.end());
  }
  int n = static_cast<int>(args.size());
  args.push_back(nullptr);
  benchmark::Initialize(&n, args.data());
  if (benchmark::ReportUnrecognizedArguments(n, args.data())) return 1;

  // Inputs: the same seeds as relgeo::analysis::standard_workloads_2/3.
  const std::vector<Workload<Orientation_2_case>> families_2{
      ra::uniform_2(cases, 1), ra::near_collinear_2(cases, 2)};
  const std::vector<Workload<Orientation_3_case>> families_3{
      ra::uniform_3(cases, 11), ra::near_coplanar_3(cases, 12)};

  std::vector<Subject> subjects = relgeo_subjects();
  for (auto&& list : {cgal_subjects(), cgal_epeck_subjects()})
    subjects.insert(subjects.end(), list.begin(), list.end());

  for (const auto& w : families_2)
    for (const Subject& s : subjects)
      benchmark::RegisterBenchmark(("orientation_2/" + w.name + "/" + s.name).c_str(),
                                   [fn = s.orientation_2, &w](benchmark::State& st) { fn(st, w); })
          ->Unit(benchmark::kMicrosecond);
  for (const auto& w : families_3)
    for (const Subject& s : subjects)
      benchmark::RegisterBenchmark(("orientation_3/" + w.name + "/" + s.name).c_str(),
                                   [fn = s.orientation_3, &w](benchmark::State& st) { fn(st, w); })
          ->Unit(benchmark::kMicrosecond);

  Ratio_reporter reporter(make_display_reporter(format), cases);
  const std::size_t ran = benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_ratios(format == "json" ? std::cerr : std::cout);
  benchmark::Shutdown();
  for (const Subject& s : subjects) s.release();
  if (ran == 0) {
    std::cerr << "relgeo_predicate_benchmark: no benchmark matched the filter\n";
    return 1;
  }
  return 0;
}
