// tools/relgeo/experiment/section.h — the framework of `relgeo experiment`.
//
// The experiment is a list of sections run in order. A section is one
// function: it receives the context (output folder, size of the run, a
// progress callback), writes its pictures under `ctx.section_dir()`, and
// returns its report: a JSON document (written to DIR/<name>.json by the
// framework), its notes, tables and pictures (printed on stdout as text and
// laid out in DIR/index.html), and its headline figures (first on the HTML
// page). Failures it lists (e.g. a soundness violation) make the tool exit
// with 1 after every section ran.
//
// To add a section:
//   1. write `Section_report my_section(const Experiment_context&)` in
//      experiment/<name>.cpp (and add the file to CMakeLists.txt),
//   2. declare it below and add one line to `experiment_sections`.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cli/text.h"
#include "relgeo/io/json.h"

namespace relgeo::tool {

struct Experiment_context {
  std::filesystem::path output_dir;  ///< DIR (exists)
  std::string section;               ///< name of the running section
  bool quick = false;                ///< --quick: smaller workloads
  std::size_t workload_size = 100000;  ///< cases per workload (10000 with --quick)
  /// Slow kernels (Kernel_entry::slow: exact, mpfr-*, cgal-epeck) use only the
  /// first this many cases of each workload: all of them in the default run
  /// (it fits in well under a minute), a tenth with --quick.
  std::size_t slow_kernel_cases = 100000;
  double min_timing_seconds = 0.05;  ///< repeat timed loops at least this long
  std::function<void(const std::string&)> progress;  ///< one progress line (stderr)

  /// DIR/<section>/, created on first use: where the section's pictures go.
  std::filesystem::path section_dir() const;
  /// `path` relative to DIR (for references inside the JSON files).
  std::string relative(const std::filesystem::path& path) const;
};

/// A picture a section wrote, for the HTML report.
struct Picture {
  std::string file;     ///< relative to DIR (Experiment_context::relative)
  std::string caption;  ///< short: the kernel, the run
};

/// One piece of a section's report, in order: a note, a table or a gallery.
struct Report_block {
  std::string note;                   ///< text (line breaks kept)
  std::optional<Text_table> table;
  std::string gallery_title;          ///< with `pictures`
  std::vector<Picture> pictures;
};

/// A figure worth reading first: "label: value".
struct Headline {
  std::string label, value;
};

struct Section_report {
  io::Json json;                      ///< the section's numbers (DIR/<section>.json)
  std::string text;                   ///< notes and tables for stdout (--format text)
  std::vector<Report_block> blocks;   ///< the same notes and tables, and the pictures (index.html)
  std::vector<Headline> headlines;    ///< first on the HTML page
  std::vector<std::string> failures;  ///< one line each; non-empty -> exit 1

  /// A note: printed as it is, shown as a paragraph.
  void add_note(const std::string& note) {
    text += note;
    blocks.push_back({note, std::nullopt, {}, {}});
  }
  /// A table: printed aligned (followed by a blank line), shown as an HTML table.
  void add_table(const Text_table& table) {
    text += table.str() + "\n";
    blocks.push_back({{}, table, {}, {}});
  }
  /// Pictures: on the HTML page only (stdout names their folder in a note).
  void add_gallery(const std::string& title, std::vector<Picture> pictures) {
    if (!pictures.empty()) blocks.push_back({{}, std::nullopt, title, std::move(pictures)});
  }
  void add_headline(const std::string& label, const std::string& value) { headlines.push_back({label, value}); }
  /// The usual close of a part of a section: its note, its table, and its
  /// numbers as json[key].
  void add_part(const std::string& note, const Text_table& table, const std::string& key, io::Json numbers) {
    add_note(note);
    add_table(table);
    json[key] = std::move(numbers);
  }
};

using Section_function = Section_report (*)(const Experiment_context&);

struct Experiment_section {
  std::string_view name;
  std::string_view summary;  ///< one line for `relgeo help experiment`
  Section_function run;
};

// ---- the sections ------------------------------------------------------------
/// Kernel comparison: Kettner grids and predicate workloads under every kernel.
Section_report kernels_section(const Experiment_context& ctx);  // experiment/kernels.cpp

/// Planar convex hulls: every algorithm under every kernel on the classroom
/// example, Kettner et al.'s construction and near-degenerate families.
Section_report hull_section(const Experiment_context& ctx);  // experiment/hull.cpp

/// Linear equations (thesis Sec. 3.2): the thesis' example, Hilbert matrices,
/// precision sweeps, relgeo's elimination against Eigen's LU.
Section_report linear_section(const Experiment_context& ctx);  // experiment/linear.cpp

/// Extruded objects (thesis Sec. 3.4.1): certified well-formedness of contours
/// under every kernel and hull algorithm, and the checker's scaling.
Section_report extrusion_section(const Experiment_context& ctx);  // experiment/extrusion.cpp

/// Loop subdivision (thesis Sec. 5.2, 5.4.1): distances of control and limit
/// meshes to the exact limit surface per level and kernel, error bounds.
Section_report subdivision_section(const Experiment_context& ctx);  // experiment/subdivision.cpp

/// Joining mesh patches to trimmed NURBS faces (thesis Ch. 4): naive sewing
/// against the Whitney joiner, errors before/after, certified fold counts.
Section_report joining_section(const Experiment_context& ctx);  // experiment/joining.cpp

/// Mesh Booleans (thesis Ch. 5): everyday cases under every kernel, validated
/// and compared with CGAL's corefinement on Epeck.
Section_report boolean_section(const Experiment_context& ctx);  // experiment/boolean.cpp

/// Booleans of Loop subdivision solids (thesis Ch. 5): levels 0..3 under the
/// certified kernels, the distance of the limit surface to the polyhedral
/// result before and after fitting, the validation, pictures.
Section_report subdivision_boolean_section(const Experiment_context& ctx);  // experiment/subdivision_boolean.cpp

/// Every section, in run order.
inline constexpr Experiment_section experiment_sections[] = {
    {"kernels", "orientation grids and predicate workloads under every kernel: wrong answers, "
                "uncertain rate, time per predicate",
     &kernels_section},
    {"hull", "convex hulls of the classroom example and near-degenerate inputs, every algorithm "
             "under every kernel: hull, convexity, error E, backward error, a-priori bound, time",
     &hull_section},
    {"linear", "linear equations: the thesis' example, Hilbert matrices (backward vs forward error, "
               "precision needed), Gaussian elimination vs Eigen's LU",
     &linear_section},
    {"extrusion", "extruded objects: the three sufficient conditions with certified margins on good "
                  "and bad contours, every kernel and hull algorithm, scaling to 10^5 curves",
     &extrusion_section},
    {"subdivision", "Loop subdivision: distance of control and limit meshes to the exact limit surface "
                    "per level 0..4 and kernel, error bounds (soundness, tightness), pictures",
     &subdivision_section},
    {"joining", "joining mesh patches to trimmed NURBS faces: naive midpoint sewing vs the Whitney joiner, "
                "absolute and normal-vector errors before/after, certified flipped triangles, (u,v) pictures",
     &joining_section},
    {"boolean", "mesh Booleans: general position, shared faces and edges, nested and identical operands under "
                "every kernel: validity, volume against CGAL's corefinement (Epeck), time, pictures",
     &boolean_section},
    {"subdivision-boolean", "Booleans of Loop subdivision solids at levels 0..3 under the certified kernels: distance "
                            "of the limit surface to the polyhedral result (fitted and not), its decay, validation, "
                            "times, pictures",
     &subdivision_boolean_section},
};

}  // namespace relgeo::tool
