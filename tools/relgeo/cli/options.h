// tools/relgeo/cli/options.h — how a command is registered and the option
// blocks every command shares (CLI11). Each commands/<command>/options.cpp
// declares its options with these helpers; main.cpp registers each command in
// one line (add_command).
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "cli/text.h"

namespace relgeo::tool {

/// Runs a parsed command on the streams; returns the exit code.
using Command_runner = std::function<int(Streams)>;

/// --format json|text (default text).
void add_format_option(CLI::App& cmd, Format& format);

/// --kernel KERNEL. `default_kernel` empty: the command decides what no
/// kernel means (said in `help`).
void add_kernel_option(CLI::App& cmd, std::string& kernel, std::string_view default_kernel, std::string_view help = {});

/// `--FLAG FILE` and the positional FILE (FLAG without dashes, e.g. "input"),
/// both filling `file`. \throws Usage_error (while parsing) when both are given.
void add_file_operand(CLI::App& cmd, std::string& file, const std::string& flag, const std::string& help);

/// `name VALUE` filling `value`: the help text, the value's name in it
/// (`type`, e.g. "N") and the default it shows (`shown_default`: what the
/// command uses when the option is absent). Returns the option for checks.
template <class T>
CLI::Option* add_value_option(CLI::App& cmd, const std::string& name, T& value, const std::string& help,
                              const std::string& type, const std::string& shown_default) {
  return cmd.add_option(name, value, help)->type_name(type)->default_str(shown_default);
}

/// --FLAG FILE for an output picture/report (empty: none).
void add_output_option(CLI::App& cmd, std::string& file, const std::string& flag, const std::string& help);

/// A registered command: its CLI11 subcommand and what runs it once parsed.
struct Registered_command {
  CLI::App* cmd;
  Command_runner run;
};

/// Adds the subcommand `name` (one-line summary, help footer; a footer that
/// does not explain its own exit codes gets the common paragraph), lets
/// `declare` put its options on it, bound to an Options object that lives as
/// long as the runner, and returns the runner calling `run(options, streams)`.
template <class Options>
Registered_command add_command(CLI::App& app, const std::string& name, const std::string& summary,
                               const std::string& footer, void (*declare)(CLI::App&, Options&),
                               int (*run)(const Options&, Streams)) {
  CLI::App* cmd = app.add_subcommand(name, summary);
  const bool own_exit_codes = footer.find("Exit codes:") != std::string::npos;
  cmd->footer(own_exit_codes ? footer : footer + (footer.ends_with('\n') ? "" : "\n") + exit_codes_text);
  auto options = std::make_shared<Options>();
  declare(*cmd, *options);
  return {cmd, [options, run](Streams io) { return run(*options, io); }};
}

}  // namespace relgeo::tool
