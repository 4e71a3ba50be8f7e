#pragma once
// Each subcommand of `pathref` lives in its own cmd_*.cpp and registers itself here.
// Exit codes (spec/cli.md): 0 success, 1 "no path found" / check failed, 2 bad arguments or input.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>

#include "pathref/io/map_file.hpp"

namespace pathref::cli {

/// A subcommand's body; returns the process exit code.
using Action = std::function<int()>;

/// Registers a subcommand on `app`; `run` is set to its action when the user picks it.
void add_eval_command(CLI::App& app, Action& run);
void add_golden_command(CLI::App& app, Action& run);
void add_plan_commands(CLI::App& app, Action& run);  // plan, maps
void add_drive_command(CLI::App& app, Action& run);  // drive (spec/mecanum.md#cli)
void add_scen_command(CLI::App& app, Action& run);     // scen (spec/formats.md#cli-scen)
void add_convert_command(CLI::App& app, Action& run);  // convert (spec/formats.md#cli-convert)

/// The map-reading options shared by plan, scen and convert, as given (spec/formats.md#cli-map-options).
struct MapReadArgs {
  std::string format = "auto";
  std::string swamp = "free";
  std::string water = "blocked";
  std::string unknown = "blocked";  ///< ROS maps: what unknown cells become
  std::string max_side;   ///< "" = default
  std::string max_cells;  ///< "" = default
};
/// Adds --format, --swamp, --water, --unknown, --max-side, --max-cells to `cmd` (defined in cmd_convert.cpp).
void add_map_read_options(CLI::App* cmd, MapReadArgs& args);
/// The library options for `args`; UsageError for a bad --max-side / --max-cells value.
[[nodiscard]] io::MapReadOptions map_read_options(const MapReadArgs& args);
void add_inflate_command(CLI::App& app, Action& run);  // inflate (spec/inflation.md#cli)
void add_simulate_command(CLI::App& app, Action& run);  // simulate (spec/han-sim.md#cli)
void add_reproduce_command(CLI::App& app, Action& run);  // reproduce (spec/reproduce.md)

}  // namespace pathref::cli
