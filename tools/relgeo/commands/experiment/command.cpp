// tools/relgeo/experiment_command.cpp — `relgeo experiment`: runs the
// registered sections, writes DIR/<section>.json and DIR/experiment.json,
// prints the tables (or one JSON document) on stdout.
#include <algorithm>
#include <chrono>
#include <fstream>
#include <ostream>
#include <system_error>

#include "commands.h"
#include "experiment.h"
#include "relgeo/core/errors.h"

namespace relgeo::tool {

std::filesystem::path Experiment_context::section_dir() const {
  const std::filesystem::path dir = output_dir / section;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Usage_error("cannot create folder '" + dir.string() + "': " + ec.message());
  return dir;
}

std::string Experiment_context::relative(const std::filesystem::path& path) const {
  return path.lexically_relative(output_dir).generic_string();
}

std::string experiment_sections_help() {
  std::string s = "Sections (--only):\n";
  for (const auto& sec : experiment_sections) {
    const std::string name(sec.name);
    s += "  " + name + std::string(name.size() < 13 ? 13 - name.size() : 1, ' ') +
         std::string(sec.summary) + "\n";
  }
  return s;
}

void validate_section_name(const std::string& name) {
  std::string names;
  for (const auto& sec : experiment_sections) {
    if (sec.name == name) return;
    names += (names.empty() ? "" : ", ") + std::string(sec.name);
  }
  throw Usage_error("unknown experiment section '" + name + "'; sections: " + names);
}

namespace {

void write_text_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
  f.close();
  if (!f) throw Usage_error("cannot write '" + path.string() + "'");
}

}  // namespace

int run_experiment(const Experiment_options& o, std::ostream& out, std::ostream& err) {
  for (const auto& s : o.sections) validate_section_name(s);
  if (o.output.empty()) throw Usage_error("--output: empty folder name");
  const std::filesystem::path dir(o.output);
  {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
      throw Usage_error("--output: cannot create folder '" + o.output + "'" +
                        (ec ? ": " + ec.message() : std::string()));
  }
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto seconds_since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };

  Experiment_context ctx;
  ctx.output_dir = dir;
  ctx.quick = o.quick;
  ctx.workload_size = o.quick ? 10000 : 100000;
  ctx.slow_kernel_cases = o.quick ? ctx.workload_size / 10 : ctx.workload_size;
  ctx.min_timing_seconds = o.quick ? 0.002 : 0.05;

  Json all;
  all["output"] = dir.generic_string();
  all["quick"] = o.quick;
  all["workload_size"] = ctx.workload_size;
  Json sections = Json::object();
  std::vector<std::string> failures;
  bool first = true;

  for (const auto& sec : experiment_sections) {
    if (!o.sections.empty() &&
        std::find(o.sections.begin(), o.sections.end(), std::string(sec.name)) == o.sections.end())
      continue;
    ctx.section = std::string(sec.name);
    const auto section_start = Clock::now();
    ctx.progress = [&, name = ctx.section](const std::string& line) {
      if (!o.quiet)
        err << "[" << name << " " << format_fixed(seconds_since(start), 1) << "s] " << line
            << std::endl;
    };
    ctx.progress("start");
    Section_report rep = sec.run(ctx);
    const double t = seconds_since(section_start);
    Json j;
    j["section"] = ctx.section;
    j["quick"] = o.quick;
    j["workload_size"] = ctx.workload_size;
    j["time_s"] = t;
    for (auto& [k, v] : rep.json.items()) j[k] = v;
    j["failures"] = rep.failures;
    write_text_file(dir / (ctx.section + ".json"), dump_json(j) + "\n");
    ctx.progress("done in " + format_fixed(t, 1) + " s, wrote " + (dir / (ctx.section + ".json")).string());
    for (const auto& f : rep.failures) failures.push_back(ctx.section + ": " + f);

    if (o.format == Format::text) {
      if (!first) out << '\n';
      out << "== " << ctx.section << " ==\n\n" << rep.text;
      out.flush();
    }
    first = false;
    sections[ctx.section] = std::move(j);
  }
  const double total = seconds_since(start);
  all["time_s"] = total;
  all["failures"] = failures;
  Json index = all;
  index["sections"] = Json::array();
  for (auto& [k, v] : sections.items()) index["sections"].push_back(k + ".json");
  write_text_file(dir / "experiment.json", dump_json(index) + "\n");
  all["sections"] = std::move(sections);

  if (o.format == Format::json) {
    out << dump_json(all) << '\n';
  } else {
    out << "\nexperiment: " << format_fixed(total, 1) << " s; results in " << dir.generic_string()
        << "/; " << (failures.empty() ? "no failures" : std::to_string(failures.size()) + " failure(s)")
        << "\n";
  }
  for (const auto& f : failures) err << "relgeo: failure: " << f << '\n';
  return failures.empty() ? exit_success : exit_failure;
}

}  // namespace relgeo::tool
