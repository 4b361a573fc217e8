#pragma once

#include <CLI/CLI.hpp>
#include <functional>

#include "cli/exit_code.hpp"

namespace strata::cli {

/// What a subcommand does once the command line has been parsed; returns the exit code.
using CommandRunner = std::function<int()>;

/// Each register_* adds its subcommand to `app`; when that subcommand is chosen, parsing sets
/// `runner` to its action.
void register_slice_command(CLI::App& app, CommandRunner& runner);
void register_info_command(CLI::App& app, CommandRunner& runner);
void register_check_command(CLI::App& app, CommandRunner& runner);
void register_validate_command(CLI::App& app, CommandRunner& runner);
void register_view_command(CLI::App& app, CommandRunner& runner);
void register_serve_command(CLI::App& app, CommandRunner& runner);
void register_merge_command(CLI::App& app, CommandRunner& runner);
void register_plan_command(CLI::App& app, CommandRunner& runner);

}  // namespace strata::cli
