// tools/relgeo/commands/experiment/options.cpp — `relgeo experiment`'s options and help.
#include "cli/options.h"
#include "commands/experiment/command.h"

namespace relgeo::tool {

std::string experiment_help_footer() {
  return experiment_sections_help() +
         "\nWrites DIR/index.html (the report to open: headline figures first, then every section's tables "
         "and pictures), DIR/<section>.json, DIR/experiment.json (index) and pictures under DIR/<section>/ "
         "(kernels: grid_<triple>_<kernel>.png).\n"
         "Kernels section: the three 256x256 grids under every kernel; orientation_2 and "
         "orientation_3 on the standard workloads (uniform, near-degenerate, extreme "
         "magnitudes, degenerate) against exact signs; with --quick the slow kernels (exact, "
         "mpfr-*, cgal-epeck) use the first tenth of each workload.\n"
         "Hull section: graham-incremental, graham-fortune, monotone-chain under every "
         "kernel and cgal (CGAL::convex_hull_2) under the CGAL kernels, on the classroom "
         "example A1, Kettner et al.'s failure construction and near-degenerate families of "
         "1000 points (250 with --quick; 100000-point versions with the fast kernels unless "
         "--quick); status, hull size, convexity, error E, backward error, a-priori bound, "
         "time; inputs as point files in DIR/hull/inputs/, SVG pictures "
         "DIR/hull/<input>_<algorithm>_<kernel>.svg for the 9-point inputs.\n"
         "Progress lines go to stderr.\n";
}

void declare_experiment_options(CLI::App& cmd, Experiment_options& o) {
  add_value_option(cmd, "--output", o.output, "results folder (created if missing)", "DIR", "results");
  cmd.add_flag("--quick", o.quick, "small workloads (10000 cases instead of 100000)");
  cmd.add_flag("--quiet", o.quiet, "no progress lines on stderr");
  cmd.add_option("--only", o.sections, "run only this section (repeatable)")->type_name("SECTION");
  add_format_option(cmd, o.format);
}

}  // namespace relgeo::tool
