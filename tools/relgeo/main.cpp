// tools/relgeo/main.cpp — the relgeo command-line tool: command-line parsing
// (CLI11), dispatch to the subcommands, exit codes (SPEC Sec. 8):
//   0 success, 1 the computation reported a failure, 2 bad input or usage
//   (one line "relgeo: error: ..." on stderr).
#include <CLI/CLI.hpp>

#include <iostream>
#include <string>
#include <vector>

#include "commands.h"
#include "hull_runs.h"
#include "kernel_names.h"
#include "linear_curves_commands.h"
#include "subdivision_commands.h"
#include "png_writer.h"
#include "relgeo/core/errors.h"
#include "tool_common.h"

namespace {

using namespace relgeo::tool;

const char* const exit_codes_text =
    "Exit codes: 0 success, 1 the computation reported a failure (e.g. a certified kernel gave a "
    "wrong answer, a hull algorithm detected non-termination), 2 bad input or usage (one line on "
    "stderr).\n";

/// --format json|text on a subcommand.
void add_format_option(CLI::App& cmd, std::string& format) {
  cmd.add_option("--format", format, "output format on stdout: text (default) or json")
      ->check(CLI::IsMember({"json", "text"}))
      ->default_str("text");
}

Format to_format(const std::string& s) { return s == "json" ? Format::json : Format::text; }

std::string grid_triples_text() {
  return "Grid triples (--triple, Kettner et al. Figs. 2-4):\n"
         "  a  p = (0.5, 0.5), q = (12, 12), r = (24, 24)\n"
         "  b  p = (0.50000000000002531, 0.5000000000000171), q = (17.300000000000001, "
         "17.300000000000001), r = (24.00000000000005, 24.000000000000053)\n"
         "  c  p = (0.5, 0.5), q = (8.8000000000000007, 8.8000000000000007), r = (12.1, 12.1)\n";
}

int report_error(const std::string& message) {
  std::cerr << "relgeo: error: " << one_line(message) << '\n';
  return exit_usage;
}

int run(int argc, char** argv) {
  CLI::App app{"relgeo — reliable computation in geometric modeling: run relgeo's algorithms "
               "under a kernel of your choice and compare kernels.",
               "relgeo"};
  app.require_subcommand(0, 1);
  app.footer(kernel_help_text() +
             "\nRun 'relgeo help COMMAND' (or 'relgeo COMMAND --help') for a command's options.\n" +
             exit_codes_text);

  // `help` is parsed by hand below (CLI11 would take `relgeo help experiment`
  // for two subcommands); it is registered for the listing only.
  auto* help_cmd = app.add_subcommand("help", "print help: the commands and kernels, or one command's options");
  std::string help_topic;
  help_cmd->add_option("command", help_topic, "the command to describe");

  // ---- orient-grid -------------------------------------------------------
  Orient_grid_options grid;
  std::string grid_format = "text";
  auto* og = app.add_subcommand(
      "orient-grid",
      "orientation(p(X,Y), q, r) on a grid of points one ulp apart (Kettner et al.), under a "
      "kernel, against the exact sign");
  og->add_option("--p", grid.p, "the base point p; cell (X, Y) is p + (X, Y) * 2^-53")->type_name("X,Y");
  og->add_option("--q", grid.q, "the point q")->type_name("X,Y");
  og->add_option("--r", grid.r, "the point r")->type_name("X,Y");
  og->add_option("--triple", grid.triple, "the p, q, r of Kettner et al.'s grids (instead of --p --q --r)")
      ->check(CLI::IsMember({"a", "b", "c"}));
  og->add_option("--kernel", grid.kernel, "the kernel (listed by 'relgeo help')")
      ->required()
      ->type_name("KERNEL");
  og->add_option("--size", grid.size, "cells per side, 1..4096")
      ->check(CLI::Range(1, 4096))
      ->default_str("256");
  og->add_option("--png", grid.png, "write the grid as a PNG picture to this file")->type_name("FILE");
  og->add_option("--scale", grid.scale, "pixels per cell in the picture, 1..16")
      ->check(CLI::Range(1, 16))
      ->default_str("2");
  add_format_option(*og, grid_format);
  og->footer(std::string("Coordinates are decimal literals, correctly rounded to double; NaN "
                         "and infinities are refused.\n") +
             grid_triples_text() + "\nPicture (--png): " + orientation_grid_legend + ".\n" +
             "\nJSON fields: kernel, kernel_model, certified, [triple], p, q, r, size, cells, "
             "wrong (= plus_to_zero + minus_to_zero + zero_to_sign + inversions), plus_to_zero, "
             "minus_to_zero, zero_to_sign, inversions, uncertain (never counted as wrong), "
             "correct, status, failure, [png].\n" +
             exit_codes_text);

  // ---- hull ----------------------------------------------------------------
  Hull_command_options hull;
  std::string hull_format = "text";
  auto* hu = app.add_subcommand(
      "hull",
      "planar convex hull of a point file under an algorithm and a kernel, with its error, "
      "backward-error certificate and a-priori bound");
  hu->add_option("--algorithm", hull.algorithm,
                 "graham-incremental, graham-fortune, monotone-chain or cgal")
      ->required()
      ->type_name("ALGORITHM");
  hu->add_option("--kernel", hull.kernel, "the kernel (listed by 'relgeo help')")
      ->required()
      ->type_name("KERNEL");
  hu->add_option("--input", hull.input, "the point file, '-' for standard input")
      ->required()
      ->type_name("FILE");
  hu->add_flag("--all-points", hull.all_points,
               "graham-fortune, monotone-chain: scan every point, without first dropping the points "
               "certified to lie inside the polygon of 8 extreme points (same exact hull, same bound)");
  hu->add_option("--svg", hull.svg,
                 "write a picture: input points, computed and exact hull, lost points")
      ->type_name("FILE");
  add_format_option(*hu, hull_format);
  hu->footer(hull_algorithms_help() +
             "\nPoint file: one point per line, two numbers separated by blanks or a comma; '#' "
             "starts a comment; blank lines are ignored. Decimal literals are correctly rounded "
             "to double; NaN, infinities, garbage and lines with one or three numbers are refused "
             "(exit 2, naming the line). An empty file gives an empty hull.\n"
             "\nMeasures (exact arithmetic, M = largest |coordinate| of the input):\n"
             "  convex          the hull, read as a polygon in the order returned, is simple,\n"
             "                  strictly convex and counterclockwise (exact check)\n"
             "  error           E of eq. (3.2): Hausdorff distance between the exact hull and the "
             "computed one, / M; inf when not convex\n"
             "  backward_error  relative perturbation after which the computed hull is exact: the "
             "largest distance of an input point outside it, / M; inf when not convex\n"
             "  backward_error_bound  graham-fortune's a-priori bound under the kernel (null when "
             "the kernel gives none, or for the other algorithms)\n"
             "\nJSON fields: algorithm, kernel, kernel_model, certified, n, status (ok|failed), "
             "failure, hull_size, hull_indices (0-based, CCW, from the lexicographically smallest "
             "vertex), hull ([x, y], 17 digits), convex, error, backward_error, "
             "backward_error_bound, coordinate_bound, moved_points (number of input points outside "
             "the hull), worst_point, uncertain_answers, predicate_calls (null for cgal), time_s "
             "(algorithm only), input, [svg].\n"
             "SVG: computed hull blue, exact hull dashed green, lost points red circles, computed "
             "vertices that are not exact-hull vertices orange squares; y up.\n" +
             exit_codes_text);

  // ---- linsolve (linear_curves_commands.h) ---------------------------------
  Linsolve_options lin;
  std::string lin_format = "text";
  auto* ls = app.add_subcommand(
      "linsolve",
      "solve A x = b by Gaussian elimination (no, partial, complete pivoting) or Eigen's LU in a "
      "scalar of your choice: normwise and componentwise backward error, forward error, condition");
  ls->add_option("--input", lin.input, "the matrix file ([A | b], one row per line), '-' for standard input")
      ->type_name("FILE");
  ls->add_option("--example", lin.example, "a built-in system instead of --input: thesis")->type_name("NAME");
  ls->add_option("--hilbert", lin.hilbert, "the N x N Hilbert system (b = H * ones) in double, instead of --input")
      ->check(CLI::Range(1, 500))
      ->type_name("N");
  ls->add_option("--method", lin.method, "none, partial (default), complete, eigen-partial, eigen-full")
      ->type_name("METHOD");
  ls->add_option("--scalar", lin.scalar, "the arithmetic: float, double (default), long-double, mpfr-BITS, rational")
      ->type_name("SCALAR");
  ls->add_option("--exact-limit", lin.exact_limit,
                 "compute the exact solution (forward error) for n <= this (default 100)")
      ->type_name("N");
  add_format_option(*ls, lin_format);
  ls->footer(linsolve_help_footer());

  // ---- extrusion (linear_curves_commands.h) --------------------------------
  Extrusion_command_options extr;
  std::string extr_format = "text";
  auto* et = app.add_subcommand(
      "extrusion",
      "certified well-formedness of an extruded object (thesis Sec. 3.4.1): the three sufficient "
      "conditions as hull problems under a kernel and an algorithm, with margins and a verdict");
  et->add_option("--input", extr.input, "the contour (JSON), '-' for standard input")
      ->required()
      ->type_name("FILE");
  et->add_option("--kernel", extr.kernel, "the kernel (listed by 'relgeo help'; default failsafe)")
      ->type_name("KERNEL");
  et->add_option("--algorithm", extr.algorithm,
                 "the hull algorithm: graham-fortune (default), monotone-chain, graham-incremental, cgal")
      ->type_name("ALGORITHM");
  et->add_option("--uncertainty", extr.uncertainty,
                 "relative input uncertainty (default: the file's, else 1e-3)")
      ->check(CLI::NonNegativeNumber)
      ->type_name("DELTA");
  et->add_option("--absolute-uncertainty", extr.absolute_uncertainty,
                 "absolute input uncertainty added to every control point (default: the file's, else 0)")
      ->check(CLI::NonNegativeNumber)
      ->type_name("EPS");
  et->add_flag("--no-prune", extr.no_prune, "condition 3 on every non-adjacent pair (quadratic)");
  et->add_option("--svg", extr.svg, "write a picture of the contour, its control hulls and offending curves")
      ->type_name("FILE");
  et->add_option("--max-listed", extr.max_listed, "offending problems listed (default 50)")->type_name("N");
  add_format_option(*et, extr_format);
  et->footer(extrusion_help_footer());

  // ---- subdivide (subdivision_commands.h) ----------------------------------
  Subdivide_options sd;
  std::string sd_format = "text";
  auto* sv = app.add_subcommand(
      "subdivide",
      "Loop subdivision of a mesh file under a kernel: refined or limit mesh, its distance to the exact "
      "limit surface, and (--bounds) error bounds of the limit mesh (thesis Sec. 5.4.1)");
  sv->add_option("--levels", sd.levels, "refinement levels, 0..12")->required()->type_name("K");
  sv->add_flag("--limit", sd.limit, "write the limit mesh (vertices at their limit positions)");
  sv->add_flag("--bounds", sd.bounds, "compute the per-face error bounds of the limit mesh");
  sv->add_option("--kernel", sd.kernel, "the kernel (default double; see below)")->type_name("KERNEL");
  sv->add_option("--input", sd.input, "the mesh file, '-' for OFF on standard input")->required()->type_name("FILE");
  sv->add_option("--tags", sd.tags, "crease/corner tag file")->type_name("FILE");
  sv->add_option("--output", sd.output, "the mesh file to write (.off, .obj, .ply, .stl)")->required()->type_name("FILE");
  sv->add_option("--report", sd.report, "also write the JSON report to this file")->type_name("FILE");
  sv->add_option("--rules", sd.rules, "crease rules: hoppe (default) or blz")->type_name("RULES");
  sv->add_option("--samples", sd.samples, "sample grid per face side for the distances (power of two, default 8; 0: none)")
      ->type_name("N");
  add_format_option(*sv, sd_format);
  sv->footer(subdivide_help_footer());

  // ---- experiment ----------------------------------------------------------
  Experiment_options exp;
  std::string exp_format = "text";
  auto* ex = app.add_subcommand(
      "experiment",
      "the kernel-comparison suite: tables on stdout, JSON and pictures in a results folder");
  ex->add_option("--output", exp.output, "results folder (created if missing)")
      ->type_name("DIR")
      ->default_str("results");
  ex->add_flag("--quick", exp.quick, "small workloads (10000 cases instead of 100000)");
  ex->add_flag("--quiet", exp.quiet, "no progress lines on stderr");
  ex->add_option("--only", exp.sections, "run only this section (repeatable)")->type_name("SECTION");
  add_format_option(*ex, exp_format);
  ex->footer(experiment_sections_help() +
             "\nWrites DIR/<section>.json, DIR/experiment.json (index) and pictures under "
             "DIR/<section>/ (kernels: grid_<triple>_<kernel>.png).\n"
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
             "Progress lines go to stderr.\n" + exit_codes_text);

  if (argc >= 2 && std::string(argv[1]) == "help") {
    if (argc > 3) return report_error("help: at most one command name");
    if (argc == 2) {
      std::cout << app.help();
      return exit_success;
    }
    const std::string topic = argv[2];
    for (CLI::App* sub : app.get_subcommands({}))
      if (sub->get_name() == topic) {
        std::cout << sub->help("relgeo");
        return exit_success;
      }
    return report_error("help: unknown command '" + topic + "'; commands: help, orient-grid, hull, linsolve, extrusion, subdivide, experiment");
  }

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

  if (og->parsed()) {
    grid.format = to_format(grid_format);
    return run_orient_grid(grid, std::cout, std::cerr);
  }
  if (hu->parsed()) {
    hull.format = to_format(hull_format);
    return run_hull_command(hull, std::cin, std::cout, std::cerr);
  }
  if (ls->parsed()) {
    lin.format = to_format(lin_format);
    return run_linsolve_command(lin, std::cin, std::cout, std::cerr);
  }
  if (et->parsed()) {
    extr.format = to_format(extr_format);
    return run_extrusion_command(extr, std::cin, std::cout, std::cerr);
  }
  if (sv->parsed()) {
    sd.format = to_format(sd_format);
    return run_subdivide_command(sd, std::cin, std::cout, std::cerr);
  }
  if (ex->parsed()) {
    exp.format = to_format(exp_format);
    return run_experiment(exp, std::cout, std::cerr);
  }
  std::cout << app.help();  // no subcommand
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
