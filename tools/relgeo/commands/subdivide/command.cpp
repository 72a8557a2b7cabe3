// tools/relgeo/commands/subdivide/command.cpp — `relgeo subdivide`: Loop refinement or
// the limit mesh of a mesh file under a kernel, with the sampled distance of
// the limit mesh to the exact limit surface and (--bounds) the error bounds
// of thesis Sec. 5.4.1.
#include "commands/subdivide/command.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>

#include "cli/text.h"
#include "commands/subdivide/facade.h"
#include "commands/subdivide/report.h"
#include "relgeo/io/json.h"
#include "relgeo/io/text_file.h"
#include "relgeo/mesh/mesh_io.h"

namespace relgeo::tool {

namespace {

using io::Json;

std::string g3(double v) { return measure_text(v, 3); }

}  // namespace

std::string subdivide_help_footer() {
  const std::string kernels = comma_list(subdivision_kernel_names());
  return "Input: a triangle mesh (OFF, OBJ, PLY or STL by extension; '-' reads OFF from standard input), "
         "edge- and vertex-manifold and consistently oriented (open meshes: boundary = crease). --tags "
         "reads crease edges and corners ('crease a b', 'corner v', 0-based). Bad, unreadable or "
         "non-manifold input: exit 2 with one line on stderr.\n"
         "Kernels: " + kernels + " (refinement uses constructions only: double, failsafe and filtered give "
         "identical meshes; exact uses GMP rationals, exact weights at valences 3, 4, 6).\n"
         "Output: the mesh refined --levels times (--limit: its limit mesh, every vertex at its limit "
         "position), coordinates rounded to double.\n"
         "Measures (--samples N per face side, a power of two, default 8; 0 disables): the limit surface "
         "is evaluated exactly (box splines, local subdivision) at the dyadic points of every face of "
         "the level-K mesh; refined_distance and limit_distance are the largest |S(u,v) - M(u,v)| "
         "(parametric: the point (u,v) of the mesh face), limit_normal_offset the largest distance of "
         "S(u,v) from the plane of its limit-mesh face.\n"
         "--bounds: per face of the limit mesh, lower/upper offsets along the face normal enclosing the "
         "limit surface (thesis eqs. 5.6-5.14): basis_range (nodal-function ranges), tangent_plane (the "
         "tangent-plane construction with rigorous ranges), direct (hull of the height itself), and "
         "thesis_estimate (the construction as printed; not a bound). Summaries: extreme offsets, mean "
         "width, tightness = max(|lower|, |upper|) / sampled max offset (mean, max), samples outside "
         "(beyond 1e-13 x mesh size).\n"
         "JSON fields: command, kernel, kernel_model, levels, limit, rules, weights, input {file, "
         "vertices, faces, edges, creases, corners}, output {file, vertices, faces, edges}, "
         "valence_histogram, patch_kinds {regular, regular_crease, irregular}, samples_per_face, "
         "samples, distance {refined_mesh, limit_mesh, limit_normal_offset, mesh_size}, bounds [...], "
         "time_s {subdivision, sampling, bounds}, status.\n"
         "Defaults: --levels 1 --kernel double --rules hoppe --samples 8; the mesh files may be given "
         "positionally (relgeo subdivide IN [OUT]); without an output file: IN_L<K>.off (IN_L<K>_limit.off with "
         "--limit) in the current folder, keeping IN's extension (stdin: subdivided_L<K>.off).\n"
         "Exit codes: 0 success, 1 a bound is violated by a sample (a library bug), 2 bad input or usage.\n";
}

std::string default_subdivide_output(const Subdivide_options& o) {
  const std::string suffix = "_L" + std::to_string(o.levels) + (o.limit ? "_limit" : "");
  if (o.input.empty() || o.input == "-") return "subdivided" + suffix + ".off";
  const std::filesystem::path in(o.input);
  const std::string ext = in.extension().empty() ? std::string(".off") : in.extension().string();
  return in.stem().string() + suffix + ext;
}

int run_subdivide_command(const Subdivide_options& options, Streams io) {
  std::istream& in = io.in;
  std::ostream& out = io.out;
  std::ostream& err = io.err;
  Subdivide_options o = options;
  if (o.input.empty()) throw Usage_error("no mesh file: give it as 'relgeo subdivide FILE' or --input FILE ('-': OFF on standard input)");
  if (o.output.empty()) o.output = default_subdivide_output(o);
  const unsigned levels = subdivision_levels(o.levels);
  if (o.samples < 0 || o.samples > 256 || (o.samples & (o.samples - 1)) != 0)
    throw Usage_error("--samples must be 0 or a power of two up to 256");
  validate_subdivision_kernel(o.kernel);
  const Loop_crease_rules rules = parse_crease_rules(o.rules);
  // Read (stdin: OFF through a temporary file, CGAL's reader wants a path).
  std::string path = o.input;
  std::filesystem::path tmp;
  if (o.input == "-") {
    tmp = std::filesystem::temp_directory_path() / ("relgeo_subdivide_" + std::to_string(::getpid()) + ".off");
    io::write_text_file(tmp.string(), io::read_text_stream(in), "temporary file");
    path = tmp.string();
  }
  Mesh_double mesh;
  try {
    mesh = read_mesh(path, Read_options{.tags_path = o.tags});
  } catch (...) {
    if (!tmp.empty()) std::filesystem::remove(tmp);
    throw;
  }
  if (!tmp.empty()) std::filesystem::remove(tmp);

  Subdivision_request rq;
  rq.kernel = o.kernel;
  rq.levels = levels;
  rq.options.crease_rules = rules;
  rq.bounds = o.bounds;
  rq.samples = o.samples;
  const Subdivision_result r = run_subdivision(mesh, rq);
  const Mesh_double& result = o.limit ? r.limit : r.refined;
  write_mesh(o.output, result);

  Json hist = Json::object();
  for (const auto& [v, c] : r.valence_histogram) hist[std::to_string(v)] = c;
  Json jb = Json::array();
  long violations = 0;
  for (const auto& b : r.bounds) {
    jb.push_back(bound_json(b));
    if (b.is_bound) violations += b.samples_outside;
  }
  const Json j{
      {"command", "subdivide"},
      {"kernel", r.kernel},
      {"kernel_model", r.kernel_model},
      {"levels", o.levels},
      {"limit", o.limit},
      {"rules", o.rules},
      {"weights", "loop"},
      {"input",
       {{"file", o.input},
        {"vertices", mesh.vertices.size()},
        {"faces", mesh.faces.size()},
        {"edges", r.input_edges},
        {"creases", mesh.tags.creases().size()},
        {"corners", mesh.tags.corners().size()}}},
      {"output",
       {{"file", o.output},
        {"vertices", result.vertices.size()},
        {"faces", result.faces.size()},
        {"edges", r.refined_edges}}},
      {"valence_histogram", hist},
      {"patch_kinds",
       {{"regular", r.patch_kinds[0]}, {"regular_crease", r.patch_kinds[1]}, {"irregular", r.patch_kinds[2]}}},
      {"samples_per_face", o.samples ? (o.samples + 1) * (o.samples + 2) / 2 : 0},
      {"samples", r.samples},
      {"distance",
       {{"refined_mesh", r.refined_distance},
        {"limit_mesh", r.limit_distance},
        {"limit_normal_offset", r.limit_normal_offset},
        {"mesh_size", r.mesh_size}}},
      {"bounds", jb},
      {"time_s", {{"subdivision", r.time_subdivision}, {"sampling", r.time_sampling}, {"bounds", r.time_bounds}}},
      {"status", violations ? "failed" : "ok"}};
  if (!o.report.empty()) io::write_text_file(o.report, io::dump_json(j) + "\n", "report");
  if (o.format == Format::json) {
    out << io::dump_json(j) << '\n';
  } else {
    std::ostringstream s;
    s << "kernel            " << r.kernel << " (" << r.kernel_model << ")\n";
    s << "rules             " << o.rules << ", " << o.levels << " level(s)" << (o.limit ? ", limit mesh" : "") << "\n";
    s << "input             " << mesh.vertices.size() << " vertices, " << mesh.faces.size() << " faces, "
      << r.input_edges << " edges, " << mesh.tags.creases().size() << " creases, " << mesh.tags.corners().size()
      << " corners\n";
    s << "output            " << result.vertices.size() << " vertices, " << result.faces.size() << " faces -> "
      << o.output << "\n";
    s << "valences          ";
    for (const auto& [v, c] : r.valence_histogram) s << v << ":" << c << " ";
    s << "\npatches           " << r.patch_kinds[0] << " regular, " << r.patch_kinds[1] << " regular crease, "
      << r.patch_kinds[2] << " irregular\n";
    if (o.samples) {
      s << "samples           " << r.samples << " (" << (o.samples + 1) * (o.samples + 2) / 2 << " per face)\n";
      s << "distance          refined mesh " << g3(r.refined_distance) << ", limit mesh " << g3(r.limit_distance)
        << ", limit normal offset " << g3(r.limit_normal_offset) << " (mesh size " << g3(r.mesh_size) << ")\n";
    }
    if (!r.bounds.empty()) {
      Text_table t({"bound", "min lower", "max upper", "mean width", "tightness mean", "max", "outside"});
      for (const auto& b : r.bounds)
        t.add_row({b.method + (b.is_bound ? "" : " (not a bound)"), g3(b.min_lower), g3(b.max_upper), g3(b.mean_width),
                   format_fixed(b.mean_tightness, 2), format_fixed(b.max_tightness, 2), std::to_string(b.samples_outside)});
      s << t.str();
    }
    s << "time              subdivision " << format_fixed(r.time_subdivision, 3) << " s, sampling "
      << format_fixed(r.time_sampling, 3) << " s, bounds " << format_fixed(r.time_bounds, 3) << " s\n";
    s << "status            " << (violations ? "failed" : "ok") << "\n";
    out << s.str();
  }
  if (violations) {
    err << "relgeo: failure: " << violations << " sample(s) of the limit surface lie outside a bound\n";
    return exit_failure;
  }
  return exit_success;
}

}  // namespace relgeo::tool
