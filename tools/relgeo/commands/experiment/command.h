// tools/relgeo/commands/experiment/command.h — `relgeo experiment`.
#pragma once

#include <string>
#include <vector>

#include "cli/text.h"

namespace CLI {
class App;
}  // namespace CLI

namespace relgeo::tool {

struct Experiment_options {
  std::string output = "results";
  bool quick = false;
  bool quiet = false;                 ///< no progress lines on stderr
  std::vector<std::string> sections;  ///< empty: all
  Format format = Format::text;
};

int run_experiment(const Experiment_options& options, Streams io);

/// "name  summary" lines of the experiment sections, for the help text.
std::string experiment_sections_help();
/// The text of `relgeo help experiment` below the options.
std::string experiment_help_footer();

/// Declares the options on the subcommand.         [options.cpp]
void declare_experiment_options(CLI::App& cmd, Experiment_options& options);

}  // namespace relgeo::tool
