#pragma once
// Each subcommand of `pathref` lives in its own cmd_*.cpp and registers itself here.
// Exit codes (spec/cli.md): 0 success, 1 "no path found" / check failed, 2 bad arguments or input.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>

#include "pathref/grid/grid.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/io/plan_json.hpp"

namespace pathref::rng {
class Trace;  // rng/trace.hpp
}  // namespace pathref::rng

namespace pathref::cli {

/// A subcommand's body; returns the process exit code.
using Action = std::function<int()>;

/// Registers a subcommand on `app`; `run` is set to its action when the user picks it.
void add_eval_command(CLI::App& app, Action& run);
/// `pathref eval --list --json`: every rule with its inputs and outputs (spec/cli.md#eval).
[[nodiscard]] nlohmann::json rule_list_json();
void add_golden_command(CLI::App& app, Action& run);
void add_check_command(CLI::App& app, Action& run);    // check (spec/check.md)
void add_conform_command(CLI::App& app, Action& run);  // conform (spec/conform.md)
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
  std::string max_memory;  ///< "" = default (memory::default_limit; spec/cli.md#memory)
};
/// Adds --format, --swamp, --water, --unknown, --max-side, --max-cells, --max-memory to `cmd`
/// (defined in cmd_convert.cpp).
void add_map_read_options(CLI::App* cmd, MapReadArgs& args);
/// The library options for `args`; UsageError for a bad --max-side / --max-cells / --max-memory
/// value. `bytes_per_cell`: what the command needs per map cell once it is read (the grid's 1, or
/// the planner's Planner::bytes_per_cell), checked by readers before allocating (ReadLimits).
[[nodiscard]] io::MapReadOptions map_read_options(const MapReadArgs& args, std::uint64_t bytes_per_cell = 1);
/// Adds `--max-memory SIZE` (spec/cli.md#memory) to `cmd`, storing the text in `value`; the
/// commands without the map-reading options (inflate, golden, simulate) use it. Defined in cmd_convert.cpp.
void add_max_memory_option(CLI::App* cmd, std::string& value);
/// The limit of a --max-memory text ("" = memory::default_limit); UsageError for a bad value.
[[nodiscard]] std::uint64_t max_memory_of(const std::string& text);
void add_inflate_command(CLI::App& app, Action& run);  // inflate (spec/inflation.md#cli)
void add_simulate_command(CLI::App& app, Action& run);  // simulate (spec/han-sim.md#cli)
void add_reproduce_command(CLI::App& app, Action& run);  // reproduce (spec/reproduce.md)
void add_learn_commands(CLI::App& app, Action& run);  // learn, classify (spec/cin2021-ml.md#cli)
/// `reproduce cin2021-ml` (spec/cin2021-ml.md#reproduction), added to the reproduce command.
void add_reproduce_cin2021_ml(CLI::App* reproduce, Action& run);

/// Writes `text` to the file `path` (binary), creating missing parent folders; UsageError
/// `cannot write 'F': REASON` when it cannot (spec/cli.md#output-files). Defined in output.cpp.
void write_output_file(const std::string& path, const std::string& text);

/// Writes a figure: the SVG text as write_output_file, or, when `path` ends in ".pdf" (any case),
/// the PDF rendered by rsvg-convert (Debian librsvg2-bin) — UsageError `cannot write 'F': PDF
/// output needs rsvg-convert ...` when it is not on PATH (spec/figures.md#pdf). Defined in output.cpp.
void write_figure(const std::string& path, const std::string& svg);

/// Sets "pathref_version" and "golden_set_version" on the JSON object `doc` (every JSON document
/// pathref prints or writes carries both: docs/versioning.md). Defined in output.cpp.
void stamp_version(nlohmann::json& doc);

/// Writes the draw trace of a run of `algo` with `seed` and parameters `params` to `path`
/// (spec/rng.md#draw-traces). Defined in cmd_trace.cpp.
void write_trace_file(const std::string& path, const rng::Trace& trace, std::uint32_t seed, const std::string& algo,
                      const nlohmann::json& params);
void add_trace_diff_command(CLI::App& app, Action& run);  // trace-diff (spec/rng.md#draw-traces)

/// The map of a run and where it came from.
struct RunMap {
  io::MapFile map;
  io::MapSource source;
};
/// The map of `--map FILE` or `--builtin NAME` (exactly one non-empty; UsageError otherwise, and
/// for an unknown built-in). Defined in cmd_plan.cpp (spec/cli.md#plan).
[[nodiscard]] RunMap load_run_map(const std::string& map_file, const std::string& builtin, const MapReadArgs& read,
                                  std::uint64_t bytes_per_cell = 1);

/// What a corner policy allows, in words (the `policy` line of plan and check). Defined in cmd_plan.cpp.
[[nodiscard]] const char* policy_meaning(grid::CornerPolicy p);

/// "X,Y" with X and Y non-negative decimal integers (at most 18 digits) -> Cell; UsageError
/// naming `option` otherwise (spec/cli.md#plan, values). Defined in cmd_plan.cpp.
[[nodiscard]] grid::Cell parse_cell_arg(const std::string& text, const char* option);

/// `pathref plan` for the continuous planners (rrt, s-rrt), as parsed by cmd_plan.cpp
/// (spec/cli.md#plan-continuous). Defined in cmd_plan_continuous.cpp.
struct ContinuousPlanArgs {
  std::string map_file;
  std::string builtin;
  std::string algo;
  std::optional<std::string> start, goal;        ///< cells (their centres)
  std::optional<std::string> start_xy, goal_xy;  ///< world coordinates
  std::uint32_t seed = 1;
  bool policy_given = false;
  nlohmann::json overrides = nlohmann::json::object();
  bool json = false;
  std::string json_out;
  std::string svg;
  std::string trace;  ///< --trace FILE
  MapReadArgs read;
};
/// Runs it: exit 0 when a path was found, 1 when not.
[[nodiscard]] int run_continuous_plan(const ContinuousPlanArgs& args);

}  // namespace pathref::cli
