#pragma once
/// \file fused.hpp
/// The fused system of sensors2023 §3.3 (Fig. 5): a global grid path, its key nodes, and the
/// following DWA (Eq. 9-14) driving a unicycle among static cells, temporary cells (appear /
/// disappear times) and moving discs on scripted timed waypoints, with a continuous-time collision
/// test. Scenario files of format "pathref-sim 2" (`pathref simulate` dispatches on the format;
/// "pathref-sim 1" files are Han's simulation, simulate.hpp).
/// Source: Sensors 2023, 23(8), 4102, doi:10.3390/s23084102, Sec. 3.3, 4 (Fig. 9, 13).
/// Spec: spec/sensors2023-dwa.md (sensors2023.sim.run, sensors2023.sim.obstacles,
/// sensors2023.sim.collision, sensors2023.sim.turns, sensors2023.dwa.follow)
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/equations/dwa.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/planners/params_source.hpp"

namespace pathref::dwa {

using Json = nlohmann::json;

/// A temporary static obstacle: the cell is present for t in [appear, disappear).
struct Temporary {
  grid::Cell cell;
  double appear = 0.0;
  double disappear = 0.0;
};

/// What the DWA's heading term (Eq. 14) aims at (spec sensors2023.sim.run, reading `heading_target`):
/// `key_node` the current key node (the following DWA, the paper's improvement); `waypoint` the
/// current waypoint of the global path at spacing `waypoint_spacing` (the traditional A*+DWA
/// fusion, the default reading of "traditional DWA"); `goal` the final goal throughout (the
/// literal traditional DWA, reading `traditional_dwa = final_goal`).
enum class HeadingTarget { key_node, waypoint, goal };
[[nodiscard]] std::string_view to_string(HeadingTarget h) noexcept;

/// Every input of a fused run (spec sensors2023.sim.run lists the keys and the project defaults).
struct FusedScenario {
  grid::Grid grid{1, 1};
  grid::Cell start;
  grid::Cell goal;
  grid::CornerPolicy policy = grid::CornerPolicy::strict;
  std::vector<grid::Cell> path;  ///< explicit global path (key nodes or adjacent cells); empty: planner
  std::string planner = "astar";
  Json planner_params = Json::object();
  /// Where planner_params were written (parse_fused_scenario), for the planner's refusals at run time.
  std::optional<planners::ParamsSource> planner_params_at;
  std::uint32_t seed = 1;
  std::optional<double> heading0;
  double t_max = 300.0;
  DwaParams dwa;
  HeadingTarget heading_target = HeadingTarget::key_node;
  FollowParams follow;
  double waypoint_spacing = 1.0;  ///< follow.waypoint_spacing (heading_target = waypoint), m
  double goal_reach = 0.5;
  double blocked_margin = 0.2;
  double stall_window = 10.0;
  double stall_distance = 0.1;
  TurnParams turns;
  std::vector<Mover> moving;
  std::vector<Temporary> temporary;
};

inline constexpr std::size_t max_fused_movers = 64;
inline constexpr std::size_t max_fused_waypoints = 1000;
inline constexpr std::size_t max_fused_temporary = 4096;
inline constexpr double max_fused_steps = 1000000.0;

/// Parses a "pathref-sim 2" scenario; ParseError(file, line, column, "<JSON pointer>: expected ...")
/// with the position of the offending value (or of the object missing a key). `base_dir` resolves
/// a map file name. Spec: sensors2023.sim.run (scenario format).
[[nodiscard]] FusedScenario parse_fused_scenario(std::string_view text, std::string_view file,
                                                 const std::string& base_dir);

/// A scenario given as a parsed JSON object (map as rows; a map file name is resolved against the
/// current directory); ParseError(file, 0, 0, ...). Spec: sensors2023.sim.run (scenario format).
[[nodiscard]] FusedScenario fused_scenario_from_json(const Json& doc, std::string_view file);

/// Parses a "dwa" block (the keys of the scenario's `dwa` object) over `base`; for `pathref eval`.
/// Spec: sensors2023.sim.run. Throws ParseError("<eval>", 0, 0, ...) on a bad key or value.
[[nodiscard]] DwaParams dwa_params_from_json(const Json& block, DwaParams base,
                                             HeadingTarget* heading_target = nullptr);

/// The "format" value of a scenario text ("" when absent or not JSON): lets the CLI dispatch.
[[nodiscard]] std::string scenario_format(std::string_view text);

enum class Outcome { reached, collided, stalled, timed_out, no_global_path };
[[nodiscard]] std::string_view to_string(Outcome o) noexcept;

struct FusedSample {
  double t = 0.0;
  Pose pose;
  double v = 0.0;
  double w = 0.0;
  std::int64_t key = 0;  ///< index into the run's target points (key nodes, or waypoints)
};

struct Skip {
  double t = 0.0;
  std::int64_t key = 0;
  SkipReason reason = SkipReason::none;
};

struct FusedResult {
  Outcome outcome = Outcome::timed_out;
  bool global_found = false;
  std::vector<grid::Cell> global_path;
  std::vector<grid::Cell> key_nodes;
  std::vector<FusedSample> samples;  ///< at every step start (and the final state)
  std::vector<std::vector<Point>> tracks;  ///< movers' positions at the sample times
  std::vector<Skip> skips;
  double time = 0.0;           ///< time of the outcome (arrival time when reached)
  double length = 0.0;         ///< driven length
  double min_clearance = 0.0;  ///< minimum step clearance (capped at 10 m)
  std::int64_t turns = 0;
  std::int64_t steps = 0;
  std::int64_t braked_steps = 0;
  double collision_clearance = 0.0;  ///< the step clearance of the colliding step
};

/// The global path of the scenario (its `path`, validated, or the planner's) and its key nodes.
/// Spec: sensors2023.sim.run, sensors2023.dwa.follow.
struct FusedGlobal {
  bool found = false;
  std::vector<grid::Cell> path;
  std::vector<grid::Cell> keys;
};
[[nodiscard]] FusedGlobal fused_global_path(const FusedScenario& s);

/// Runs the fused system (spec sensors2023.sim.run): goal test, follow update, stall and time
/// tests, control step, move, step clearance; one outcome after at most t_max/dt + 1 steps.
/// Source: sensors2023, Sec. 3.3, Fig. 5; pathref. Spec: sensors2023.sim.run.
/// Pre: start, goal free; the path (if given) from start to goal inside the map; the planner (if
/// used) registered (UsageError). Post: deterministic in the scenario.
/// Golden: golden/sensors2023-dwa/sensors2023.sim.run.json
[[nodiscard]] FusedResult simulate_fused(const FusedScenario& s);

/// The result as JSON (format "pathref-sim-result 2"); `full` adds the samples and tracks.
/// Spec: sensors2023.sim.run.
[[nodiscard]] Json to_json(const FusedResult& r, bool full);

/// Every parameter a run used, as JSON (printed by the CLI and the reproduction).
/// Spec: sensors2023.sim.run.
[[nodiscard]] Json params_json(const FusedScenario& s);

}  // namespace pathref::dwa
