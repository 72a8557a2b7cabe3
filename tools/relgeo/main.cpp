// tools/relgeo/main.cpp — the relgeo command-line tool: command-line parsing
// (CLI11), dispatch to the subcommands, exit codes (SPEC Sec. 8):
//   0 success, 1 the computation reported a failure, 2 bad input or usage
//   (one line "relgeo: error: ..." on stderr).
#include <CLI/CLI.hpp>

#include <iostream>
#include <string>
#include <vector>

#include "commands.h"
#include "kernel_names.h"
#include "png_writer.h"
#include "relgeo/core/errors.h"
#include "tool_common.h"

namespace {

using namespace relgeo::tool;

const char* const exit_codes_text =
    "Exit codes: 0 success, 1 the computation reported a failure (e.g. a certified kernel gave a "
    "wrong answer), 2 bad input or usage (one line on stderr).\n";

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
    return report_error("help: unknown command '" + topic + "'; commands: help, orient-grid, experiment");
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
