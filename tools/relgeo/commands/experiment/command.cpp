// tools/relgeo/commands/experiment/command.cpp — `relgeo experiment`: runs
// the registered sections, writes DIR/<section>.json, DIR/experiment.json and
// DIR/index.html, prints the tables (or one JSON document) on stdout.
#include "commands/experiment/command.h"

#include <algorithm>
#include <ostream>
#include <system_error>

#include "commands/experiment/html_report.h"
#include "experiment/section.h"
#include "relgeo/core/internal/stopwatch.h"
#include "relgeo/io/text_file.h"

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

namespace {

using io::Json;

void validate_section_name(const std::string& name) {
  std::string names;
  for (const auto& sec : experiment_sections) {
    if (sec.name == name) return;
    names += (names.empty() ? "" : ", ") + std::string(sec.name);
  }
  throw Usage_error("unknown experiment section '" + name + "'; sections: " + names);
}

void write_text_file(const std::filesystem::path& path, const std::string& text) {
  io::write_text_file(path.string(), text, "results file");
}

}  // namespace

int run_experiment(const Experiment_options& o, Streams io) {
  std::ostream& out = io.out;
  std::ostream& err = io.err;
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
  const internal::Stopwatch start;

  Experiment_context ctx;
  ctx.output_dir = dir;
  ctx.quick = o.quick;
  ctx.workload_size = o.quick ? 10000 : 100000;
  ctx.slow_kernel_cases = o.quick ? ctx.workload_size / 10 : ctx.workload_size;
  ctx.min_timing_seconds = o.quick ? 0.002 : 0.05;

  Json all{{"output", dir.generic_string()}, {"quick", o.quick}, {"workload_size", ctx.workload_size}};
  Json sections = Json::object();
  std::vector<std::string> failures;
  bool first = true;
  std::vector<Html_section> html;

  for (const auto& sec : experiment_sections) {
    if (!o.sections.empty() &&
        std::find(o.sections.begin(), o.sections.end(), std::string(sec.name)) == o.sections.end())
      continue;
    ctx.section = std::string(sec.name);
    const internal::Stopwatch section_start;
    ctx.progress = [&, name = ctx.section](const std::string& line) {
      if (!o.quiet)
        err << "[" << name << " " << format_fixed(start.elapsed(), 1) << "s] " << line
            << std::endl;
    };
    ctx.progress("start");
    Section_report rep = sec.run(ctx);
    const double t = section_start.elapsed();
    Json j{{"section", ctx.section}, {"quick", o.quick}, {"workload_size", ctx.workload_size}, {"time_s", t}};
    for (auto& [k, v] : rep.json.items()) j[k] = v;
    j["failures"] = rep.failures;
    write_text_file(dir / (ctx.section + ".json"), io::dump_json(j) + "\n");
    ctx.progress("done in " + format_fixed(t, 1) + " s, wrote " + (dir / (ctx.section + ".json")).string());
    for (const auto& f : rep.failures) failures.push_back(ctx.section + ": " + f);

    if (o.format == Format::text) {
      if (!first) out << '\n';
      out << "== " << ctx.section << " ==\n\n" << rep.text;
      out.flush();
    }
    first = false;
    sections[ctx.section] = std::move(j);
    html.push_back({ctx.section, std::string(sec.summary), t, std::move(rep)});
  }
  const double total = start.elapsed();
  all["time_s"] = total;
  all["failures"] = failures;
  Json index = all;
  index["sections"] = Json::array();
  for (auto& [k, v] : sections.items()) index["sections"].push_back(k + ".json");
  write_text_file(dir / "experiment.json", io::dump_json(index) + "\n");
  const Html_run run{o.quick, ctx.workload_size, total, failures};
  write_text_file(dir / "index.html", html_report(run, html));
  all["sections"] = std::move(sections);

  if (o.format == Format::json) {
    out << io::dump_json(all) << '\n';
  } else {
    out << "\nexperiment: " << format_fixed(total, 1) << " s; results in " << dir.generic_string()
        << "/ (open " << (dir / "index.html").generic_string() << "); "
        << (failures.empty() ? "no failures" : std::to_string(failures.size()) + " failure(s)")
        << "\n";
  }
  for (const auto& f : failures) err << "relgeo: failure: " << f << '\n';
  return failures.empty() ? exit_success : exit_failure;
}

}  // namespace relgeo::tool
