// tools/relgeo/main.cpp — the relgeo command-line tool: one registration per
// command (its options: commands/<command>/options.cpp), `help`, exit codes
// (SPEC Sec. 8):
//   0 success, 1 the computation reported a failure, 2 bad input or usage
//   (one line "relgeo: error: ..." on stderr).
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "cli/options.h"
#include "commands/commands.h"
#include "kernels/registry.h"
#include "relgeo/core/errors.h"

namespace {

using namespace relgeo::tool;

int report_error(const std::string& message) {
  std::cerr << "relgeo: error: " << one_line(message) << '\n';
  return exit_usage;
}

/// `relgeo help [COMMAND]`, parsed by hand (CLI11 would take `relgeo help
/// experiment` for two subcommands).
int run_help(CLI::App& app, int argc, char** argv) {
  if (argc > 3) return report_error("help: at most one command name");
  if (argc == 2) {
    std::cout << app.help();
    return exit_success;
  }
  const std::string topic = argv[2];
  std::string names;
  for (CLI::App* sub : app.get_subcommands({})) {
    if (sub->get_name() == topic) {
      std::cout << sub->help("relgeo");
      return exit_success;
    }
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  return report_error("help: unknown command '" + topic + "'; commands: " + names);
}

int run(int argc, char** argv) {
  CLI::App app{"relgeo — reliable computation in geometric modeling: run relgeo's algorithms "
               "under a kernel of your choice and compare kernels.",
               "relgeo"};
  app.require_subcommand(0, 1);
  app.footer(kernel_help_text() +
             "\nInputs can be given positionally: relgeo hull points.txt, relgeo subdivide mesh.off [out.off], "
             "relgeo linsolve system.txt, relgeo extrusion contour.json, relgeo join model.json --mesh a.off "
             "('-': standard input). Every flag has "
             "a default except the inputs; 'relgeo help COMMAND' (or 'relgeo COMMAND --help') lists a command's "
             "options with their defaults. Manual: doc/tool.md.\n" +
             exit_codes_text);
  app.add_subcommand("help", "print help: the commands and kernels, or one command's options")
      ->add_option("command", "the command to describe");

  const Registered_command commands[] = {
      add_command(app, "orient-grid",
                  "orientation(p(X,Y), q, r) on a grid of points one ulp apart (Kettner et al.), under one kernel "
                  "or the standard kernels side by side, against the exact sign",
                  orient_grid_help_footer(), &declare_orient_grid_options, &run_orient_grid),
      add_command(app, "hull",
                  "planar convex hull of a point file under an algorithm and a kernel, with its error, "
                  "backward-error certificate and a-priori bound",
                  hull_help_footer(), &declare_hull_options, &run_hull_command),
      add_command(app, "linsolve",
                  "solve A x = b by Gaussian elimination (no, partial, complete pivoting) or Eigen's LU in a "
                  "scalar of your choice: normwise and componentwise backward error, forward error, condition",
                  linsolve_help_footer(), &declare_linsolve_options, &run_linsolve_command),
      add_command(app, "extrusion",
                  "certified well-formedness of an extruded object (thesis Sec. 3.4.1): the three sufficient "
                  "conditions as hull problems under a kernel and an algorithm, with margins and a verdict",
                  extrusion_help_footer(), &declare_extrusion_options, &run_extrusion_command),
      add_command(app, "subdivide",
                  "Loop subdivision of a mesh file under a kernel: refined or limit mesh, its distance to the "
                  "exact limit surface, and (--bounds) error bounds of the limit mesh (thesis Sec. 5.4.1)",
                  subdivide_help_footer(), &declare_subdivide_options, &run_subdivide_command),
      add_command(app, "join",
                  "join mesh patches to the trimmed faces of a surface model (JSON, STEP, IGES): the Whitney "
                  "joiner, naive sewing or OpenCASCADE, with errors before/after and certified flip counts "
                  "(thesis Ch. 4)",
                  join_help_footer(), &declare_join_options, &run_join_command),
      add_command(app, "boolean",
                  "the Boolean (union, intersection, difference, xor) of two closed triangle meshes under a "
                  "kernel: exact under the filtered and exact kernels, validated, optionally against CGAL's",
                  boolean_help_footer(), &declare_boolean_options, &run_boolean_command),
      add_command(app, "csg",
                  "a CSG tree of mesh files (JSON: unions, intersections, differences) evaluated with the exact "
                  "Boolean, every intermediate result a valid solid in doubles, reported step by step",
                  csg_help_footer(), &declare_csg_options, &run_csg_command),
      add_command(app, "experiment",
                  "the kernel-comparison suite: tables on stdout; JSON, pictures and index.html in a results "
                  "folder",
                  experiment_help_footer(), &declare_experiment_options, &run_experiment),
  };

  if (argc >= 2 && std::string(argv[1]) == "help") return run_help(app, argc, argv);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return exit_success;
  } catch (const CLI::CallForAllHelp&) {
    std::cout << app.help("", CLI::AppFormatMode::All);
    return exit_success;
  } catch (const CLI::ParseError& e) {
    return report_error(e.what());
  }
  for (const Registered_command& c : commands)
    if (c.cmd->parsed()) return c.run(Streams{std::cin, std::cout, std::cerr});
  std::cout << app.help();  // no command
  return exit_success;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const Usage_error& e) {
    return report_error(e.what());
  } catch (const relgeo::Error& e) {
    if (e.code() == relgeo::Error_code::computation_failure) {
      std::cerr << "relgeo: failure: " << one_line(e.what()) << '\n';
      return exit_failure;
    }
    return report_error(e.what());
  } catch (const std::exception& e) {
    std::cerr << "relgeo: internal error: " << one_line(e.what()) << '\n';
    return exit_failure;
  }
}
