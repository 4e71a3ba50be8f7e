#pragma once
/// \file simulate.hpp
/// Han's dynamic-obstacle simulation (IACO-A*, Figure 6): a deterministic time-stepped run of a
/// robot following a global path among static obstacles and moving obstacles on linear paths. The
/// robot observes every obstacle at every step, predicts it with recursive least squares (Han
/// Eq. 9-15, rls.hpp) and classifies each encounter with Figure 5 (encounter.hpp): no intersection
/// -> go on; side -> wait until the predicted paths no longer cross; frontal -> A* (Chebyshev
/// heuristic, Eq. 8) to a local target on the global path beyond the obstacle, then rejoin it.
/// Source: Han (IJACSA), Sec. III.B (Fig. 5, Fig. 6), Sec. IV (1 m/s, 1 m/s^2; Fig. 8).
/// Spec: spec/han-sim.md (han.sim.scenario-format, han.sim.step, han.sim.wait, han.sim.detour,
/// han.sim.run)
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/grid/grid.hpp"
#include "pathref/io/json_reader.hpp"
#include "pathref/planners/params_source.hpp"
#include "pathref/sim/encounter.hpp"

namespace pathref::sim {

using Json = nlohmann::json;

/// A moving obstacle: position p(t) = position + velocity * t (t in s from the start), a disc.
struct MovingObstacle {
  Vec2 position;
  Vec2 velocity;
  double radius = 0.3;
};

/// Every input of a run (spec han.sim.scenario-format lists the JSON keys and defaults).
struct Scenario {
  grid::Grid grid{1, 1};
  grid::Cell start;
  grid::Cell goal;
  grid::CornerPolicy policy = grid::CornerPolicy::strict;
  std::vector<grid::Cell> path;      ///< explicit global path; empty: from `planner`
  std::string planner = "iaco-han";  ///< registered planner giving the global path
  Json planner_params = Json::object();
  /// Where planner_params were written (parse_scenario), for the planner's refusals at run time.
  std::optional<planners::ParamsSource> planner_params_at;
  std::uint32_t seed = 1;            ///< the planner's seed and the noise stream's
  double dt = 0.125;                 ///< time step, s
  double horizon = 3.0;              ///< prediction horizon H, s
  double speed = 1.0;                ///< v_max, m/s (paper)
  double accel = 1.0;                ///< a, m/s^2 (paper)
  double robot_radius = 0.3;         ///< m
  double margin = 0.25;              ///< added to the radii for predicted conflicts, m
  double noise = 0.0;                ///< observation noise half-width, m (uniform)
  double t_max = 600.0;              ///< give up after this time, s
  double lambda = 0.95;              ///< RLS forgetting factor (han.params)
  double frontal_cos = default_frontal_cos;
  std::vector<MovingObstacle> obstacles;
};

/// Largest sizes a scenario may ask for (checked before allocating).
inline constexpr std::int64_t max_sim_cells = 1000000;
inline constexpr std::size_t max_sim_obstacles = 64;
inline constexpr std::int64_t max_sim_steps = 1000000;

/// Parses a scenario object (format "pathref-sim 1"). `base_dir` resolves a map file name; `file`
/// names the source in errors. ParseError(file, 0, 0, "<JSON pointer>: expected ...") for a
/// missing, unknown or ill-typed key or a value outside its range. Spec: han.sim.scenario-format.
[[nodiscard]] Scenario scenario_from_json(const Json& doc, std::string_view file,
                                          const std::string& base_dir);

/// Parses scenario text: invalid JSON is a ParseError at the line and column of the offending
/// byte; then scenario_from_json. Spec: han.sim.scenario-format.
[[nodiscard]] Scenario parse_scenario(std::string_view text, std::string_view file,
                                      const std::string& base_dir);

/// The global planner of a scenario (pathref-sim 1 and 2): `name` a registered planner (refused at
/// `name_ptr`, /planner or /planner/name) and every key of `params` one it takes with a value of
/// its default's type (refused at /planner/params/KEY). Values a planner refuses only when it runs
/// (a number out of its range) are reported by the run, with the planner's message.
void check_planner(const io::JsonReader& rd, const std::string& name, const Json& params, const std::string& name_ptr);

/// The robot's state in one trajectory sample: moving on its plan, waiting, moving on an evasion
/// plan towards a refuge (han.sim.evade), or arrived at the goal.
enum class RobotState { move, wait, evade, arrive };
[[nodiscard]] std::string_view to_string(RobotState s) noexcept;

struct Sample {
  double t = 0.0;
  Vec2 p;
  double v = 0.0;
  RobotState state = RobotState::move;
};

struct Wait {
  double start = 0.0;
  double end = 0.0;  ///< time the robot moved again (or the run ended)
  std::vector<std::int64_t> obstacles;  ///< side encounters at the start of the wait
};

struct Replan {
  double t = 0.0;
  grid::Cell from;
  grid::Cell target;              ///< the local target on the global path
  std::int64_t target_index = 0;  ///< its index in the global path
  std::vector<grid::Cell> detour; ///< the A* path from `from` to `target`
  std::vector<std::int64_t> obstacles;  ///< frontal encounters that caused it
};

/// An evasion (han.sim.evade): the robot leaves the predicted bands for the nearest refuge.
struct Evasion {
  double t = 0.0;
  grid::Cell from;                  ///< the first cell of the refuge path (a cell of the robot's piece)
  grid::Cell refuge;                ///< the nearest cell outside every conflicting band
  std::vector<grid::Cell> path;     ///< from ... refuge
  grid::Cell target;                ///< where the plan rejoins the global path
  std::int64_t target_index = 0;    ///< its index in the global path
  std::vector<std::int64_t> obstacles;  ///< the conflicting obstacles
};

/// A step in which no action is predicted safe (han.sim.safety): outside the rules' guarantee.
struct Unavoidable {
  double t = 0.0;
  std::vector<std::int64_t> obstacles;  ///< the conflicting obstacles
  std::string reason;  ///< "trapped": no refuge reachable; "late": the refuge is not reached in time
};

struct Collision {
  double t = 0.0;  ///< start of the step in which it happened
  std::int64_t obstacle = 0;
  double distance = 0.0;
  /// Outside the guarantee of han.sim.run: "unavoidable" (an Unavoidable naming this obstacle in
  /// [t - horizon, t]), "unobserved" (the obstacle had fewer than two observations, so no
  /// prediction), or "" (inside the guarantee: the rules should have prevented it).
  std::string outside_guarantee;
};

struct SimResult {
  bool global_found = false;
  std::vector<grid::Cell> global_path;
  double global_length = 0.0;
  std::vector<Sample> trajectory;                ///< one sample per step start, and the arrival
  std::vector<std::vector<Vec2>> obstacle_tracks;  ///< true positions at each sample time
  std::vector<Wait> waits;
  std::vector<Replan> replans;
  std::vector<Evasion> evasions;
  std::vector<Unavoidable> unavoidable;
  std::vector<Collision> collisions;
  std::int64_t wait_steps = 0;         ///< steps spent waiting
  std::int64_t frontal_decisions = 0;  ///< frontal encounters seen (replans or blocked waits)
  double distance = 0.0;  ///< arc length driven (sum of the steps' ds)
  double time = 0.0;      ///< arrival time (or t_max)
  double wait_time = 0.0; ///< sum of the waits
  bool reached_goal = false;
  std::int64_t steps = 0;
  std::int64_t noise_draws = 0;
  /// The last RLS estimate [a, b, c, d] of each obstacle (Eq. 9; zeros before two observations).
  std::vector<std::vector<double>> estimates;
};

/// Runs the scenario (spec han.sim.step: the order of a step; han.sim.wait; han.sim.detour).
/// Source: Han (IJACSA), Sec. III.B, Fig. 5-6, Sec. IV. Spec: han.sim.run, han.sim.step,
/// han.sim.wait, han.sim.detour.
/// Pre: start, goal in bounds and free; the path (if given) valid under the policy from start
/// to goal; the planner (if used) registered (UsageError otherwise).
/// Post: deterministic in the scenario. Golden: golden/han-sim/han.sim.run.json
[[nodiscard]] SimResult simulate(const Scenario& s);

/// The result as JSON (format "pathref-sim-result"); `full` adds trajectory and tracks.
/// Spec: han.sim.run (outputs). Golden: golden/han-sim/han.sim.run.json
[[nodiscard]] Json to_json(const SimResult& r, bool full);

/// The global path of the scenario: `path` if given (validated), else the planner's.
/// Spec: han.plan.iaco-astar. Pre: as simulate.
struct GlobalPath {
  bool found = false;
  std::vector<grid::Cell> path;
  double length = 0.0;
};
[[nodiscard]] GlobalPath global_path(const Scenario& s);

}  // namespace pathref::sim
