// benchmark/common/command_line.h — what the mains of relgeo's benchmark
// suites share: the argument list (the suite's own flags read and removed,
// its defaults added, the rest handed to Google Benchmark), the display
// reporter, and the statistics of their summary tables.
#pragma once

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <list>
#include <memory>
#include <string>
#include <vector>

namespace relgeo_bench {

/// argv as an editable list. A flag is "--name" or "--name=value".
class Command_line {
 public:
  Command_line(int argc, char** argv) : args_(argv, argv + argc) {}

  bool has(const char* flag) const {
    return std::any_of(args_.begin() + 1, args_.end(), [&](const char* a) { return matches(a, flag); });
  }
  /// The value of the last "--flag=value" ("" if none).
  std::string value(const char* flag) const {
    const std::size_t n = std::strlen(flag);
    std::string v;
    for (auto it = args_.begin() + 1; it != args_.end(); ++it)
      if (std::strncmp(*it, flag, n) == 0 && (*it)[n] == '=') v = *it + n + 1;
    return v;
  }
  /// Removes every occurrence (the suite's own flags, before Initialize).
  void erase(const char* flag) {
    args_.erase(std::remove_if(args_.begin() + 1, args_.end(), [&](const char* a) { return matches(a, flag); }),
                args_.end());
  }
  /// Adds "--flag=value" unless the flag was given.
  void set_default(const char* flag, const std::string& value) {
    if (has(flag)) return;
    owned_.push_back(std::string(flag) + "=" + value);
    args_.insert(args_.begin() + 1, owned_.back().data());
  }
  /// The suite's measuring defaults (--benchmark_min_time in seconds, and
  /// --benchmark_repetitions when given), unless the caller set them.
  void set_measuring_defaults(const char* min_time, const char* repetitions = nullptr) {
    set_default("--benchmark_min_time", min_time);
    if (repetitions) set_default("--benchmark_repetitions", repetitions);
  }
  /// benchmark::Initialize on the list; false (after Google Benchmark's
  /// message) when an argument is not recognised.
  bool initialize() {
    int n = static_cast<int>(args_.size());
    args_.push_back(nullptr);  // argv[argc] == nullptr, as Initialize may expect
    benchmark::Initialize(&n, args_.data());
    const bool ok = !benchmark::ReportUnrecognizedArguments(n, args_.data());
    args_.resize(static_cast<std::size_t>(n));
    return ok;
  }

 private:
  static bool matches(const char* a, const char* flag) {
    const std::size_t n = std::strlen(flag);
    return std::strncmp(a, flag, n) == 0 && (a[n] == '=' || a[n] == '\0');
  }
  std::vector<char*> args_;
  std::list<std::string> owned_;  // the added arguments (stable addresses)
};

/// Tabular console output, in colour only on a terminal.
inline benchmark::ConsoleReporter::OutputOptions console_options() {
  const char* term = std::getenv("TERM");
  const bool color = isatty(STDOUT_FILENO) && term && std::strcmp(term, "dumb") != 0;
  return color ? benchmark::ConsoleReporter::OO_ColorTabular : benchmark::ConsoleReporter::OO_Tabular;
}

/// Google Benchmark's console reporter or, for --benchmark_format=json, its
/// JSON reporter.
inline std::unique_ptr<benchmark::BenchmarkReporter> make_display_reporter(const std::string& format,
                                                                          const char* program) {
  if (format == "json") return std::make_unique<benchmark::JSONReporter>();
  if (format == "csv")  // deprecated by Google Benchmark: not offered here
    std::cerr << program << ": --benchmark_format=csv unsupported, using console\n";
  return std::make_unique<benchmark::ConsoleReporter>(console_options());
}

/// The console output, and collect() called on every measured run (not the
/// aggregates of repetitions, not runs that reported an error): the base of
/// the suites whose summary table is built from their runs.
class Collecting_reporter : public benchmark::ConsoleReporter {
 public:
  Collecting_reporter() : ConsoleReporter(console_options()) {}
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs)
      if (r.run_type == Run::RT_Iteration && !r.error_occurred && r.iterations > 0) collect(r);
  }

 protected:
  virtual void collect(const Run& run) = 0;
};

/// Ends a main: shuts Google Benchmark down and returns the exit status, 1
/// (with a message on stderr) when no benchmark matched the filter.
inline int finish(std::size_t ran, const char* program) {
  benchmark::Shutdown();
  if (ran > 0) return 0;
  std::cerr << program << ": no benchmark matched the filter\n";
  return 1;
}

inline double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/// A time in Google Benchmark's unit, in seconds.
inline double to_seconds(double t, benchmark::TimeUnit unit) {
  switch (unit) {
    case benchmark::kNanosecond: return t * 1e-9;
    case benchmark::kMicrosecond: return t * 1e-6;
    case benchmark::kMillisecond: return t * 1e-3;
    case benchmark::kSecond: return t;
  }
  return t;
}

}  // namespace relgeo_bench
