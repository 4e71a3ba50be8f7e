#pragma once
// Each subcommand of `pathref` lives in its own cmd_*.cpp and registers itself here.
// Exit codes (spec/cli.md): 0 success, 1 "no path found" / check failed, 2 bad arguments or input.
#include <CLI/CLI.hpp>
#include <functional>

namespace pathref::cli {

/// A subcommand's body; returns the process exit code.
using Action = std::function<int()>;

/// Registers a subcommand on `app`; `run` is set to its action when the user picks it.
void add_eval_command(CLI::App& app, Action& run);
void add_golden_command(CLI::App& app, Action& run);
void add_plan_commands(CLI::App& app, Action& run);  // plan, maps
void add_drive_command(CLI::App& app, Action& run);  // drive (spec/mecanum.md#cli)
void add_inflate_command(CLI::App& app, Action& run);  // inflate (spec/inflation.md#cli)

}  // namespace pathref::cli
