// JSON adapters for the han.* rules of the dynamic-obstacle part (spec/han-sim.md): random maps,
// the Fig. 5 collision classification, the speed profile, the frontal detour pieces and whole
// simulation runs. Each adapter only converts JSON to the arguments of the functions in sim/.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/rules/modules.hpp"
#include "pathref/sim/encounter.hpp"
#include "pathref/sim/motion.hpp"
#include "pathref/sim/random_map.hpp"
#include "pathref/sim/simulate.hpp"

namespace pathref::rules {

namespace {

sim::Vec2 point_arg(const Json& in, const char* key) {
  const auto v = arg_numbers(in, key);
  if (v.size() != 2) throw UsageError(std::string(key) + " must be a point [x, y]");
  return sim::Vec2{v[0], v[1]};
}

std::vector<sim::Vec2> points_arg(const Json& in, const char* key) {
  const Json& a = arg(in, key);
  if (!a.is_array()) throw UsageError(std::string(key) + " must be an array of points [x, y]");
  std::vector<sim::Vec2> out;
  for (const Json& p : a) {
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
      throw UsageError(std::string(key) + " must be an array of points [x, y]");
    out.push_back(sim::Vec2{p[0].get<double>(), p[1].get<double>()});
  }
  return out;
}

}  // namespace

void register_han_sim_rules(Registry& r) {
  r.add(Rule{
      "han.maps.random",
      "Random map of Han's protocol: edge E (1 m cells), floor(ratio E^2) obstacles off a random monotone corridor (Han Sec. IV)",
      "pathref::sim::random_map",
      {{"seed", "integer", "seed of rng::Stream"},
       {"edge", "integer", "edge E in cells (protocol: 10, 15, ..., 100)"},
       {"ratio", "number", "obstacle ratio in [0, 1] (protocol: 0.2 to 0.7)"}},
      {{"grid", "grid", "rows, top first"},
       {"start", "cell", "(0, 0)"},
       {"goal", "cell", "(E-1, E-1)"},
       {"corridor", "cell[]", "the free monotone corridor"},
       {"obstacles", "integer", "floor(ratio E^2)"},
       {"draws", "integer", "doubles drawn"}},
      [](const Json& in) {
        const long long seed = arg_integer(in, "seed");
        if (seed < 0 || seed > 4294967295LL) throw UsageError("seed must be a 32-bit unsigned integer");
        const auto m = sim::random_map(static_cast<std::uint32_t>(seed), arg_integer(in, "edge"),
                                       arg_number(in, "ratio"));
        return Json{{"grid", grid::grid_to_json(m.grid)},
                    {"start", grid::cell_to_json(m.start)},
                    {"goal", grid::cell_to_json(m.goal)},
                    {"corridor", grid::path_to_json(m.corridor)},
                    {"obstacles", m.obstacles},
                    {"draws", m.draws}};
      }});
  r.add(Rule{
      "han.collision.classify",
      "Fig. 5 collision test: robot polyline vs predicted obstacle segment -> none / side / frontal (Han Sec. III.B)",
      "pathref::sim::classify",
      {{"robot", "point[]", "the robot's planned polyline over the horizon, robot[0] = its position (m)"},
       {"p", "point", "obstacle's predicted position now (m)"},
       {"q", "point", "obstacle's predicted position at the horizon (m)"},
       {"clearance", "number", "(r_robot + r_obstacle) + margin > 0 (m)"},
       {"frontal_cos", "number", "optional: cosine of the side/frontal angle (default -sqrt(2)/2, 135 deg)"}},
      {{"kind", "string", "none | side | frontal"},
       {"distance", "number", "minimum distance polyline - segment"},
       {"piece", "integer", "first robot piece attaining it"},
       {"cos_angle", "number", "cosine of the angle between that piece and the obstacle motion (0 if static)"},
       {"robot_inside", "bool", "robot position closer than clearance to the segment"}},
      [](const Json& in) {
        const auto robot = points_arg(in, "robot");
        const double fc = in.contains("frontal_cos") ? arg_number(in, "frontal_cos") : sim::default_frontal_cos;
        const auto c = sim::classify(robot, point_arg(in, "p"), point_arg(in, "q"), arg_number(in, "clearance"), fc);
        return Json{{"kind", std::string(sim::to_string(c.kind))},
                    {"distance", number(c.distance)},
                    {"piece", c.piece},
                    {"cos_angle", number(c.cos_angle)},
                    {"robot_inside", c.robot_inside}};
      }});
  r.add(Rule{
      "han.sim.motion",
      "One time step of the speed profile: accelerate at a to v_max, cruise, stop at the remaining distance (Han Sec. IV)",
      "pathref::sim::motion_step, pathref::sim::ramp_cruise_time",
      {{"v0", "number", "speed at the start of the step, m/s"},
       {"dt", "number", "step, s"},
       {"v_max", "number", "cruise speed (paper: 1 m/s)"},
       {"a", "number", "acceleration (paper: 1 m/s^2)"},
       {"remaining", "number", "optional: distance left to the goal (default inf)"}},
      {{"distance", "number", "ds"}, {"v_end", "number", "speed at the end"},
       {"time", "number", "time used (dt or the arrival time)"}, {"arrived", "bool", "goal reached"},
       {"ramp_cruise_time", "number", "time to drive `remaining` from rest (only when remaining is finite)"}},
      [](const Json& in) {
        const double rem = in.contains("remaining") ? arg_number(in, "remaining") : std::numeric_limits<double>::infinity();
        const auto m = sim::motion_step(arg_number(in, "v0"), arg_number(in, "dt"), arg_number(in, "v_max"),
                                        arg_number(in, "a"), rem);
        Json out{{"distance", number(m.distance)}, {"v_end", number(m.v_end)}, {"time", number(m.time)},
                 {"arrived", m.arrived}};
        if (std::isfinite(rem))
          out["ramp_cruise_time"] = number(sim::ramp_cruise_time(rem, arg_number(in, "v_max"), arg_number(in, "a")));
        return out;
      }});
  r.add(Rule{
      "han.sim.detour",
      "Frontal detour pieces: cells swept by a predicted obstacle, and the local target on the global path (Han Sec. IV)",
      "pathref::sim::swept_cells, pathref::sim::local_target",
      {{"grid", "grid", "rows, top first"},
       {"p", "point", "predicted position now"},
       {"q", "point", "predicted position at the horizon"},
       {"clearance", "number", "(r_robot + r_obstacle) + margin"},
       {"path", "cell[]", "the global path"},
       {"from", "integer", "index of the first global cell ahead of the robot"}},
      {{"swept", "cell[]", "cells with centre closer than clearance + sqrt(2)/2 to [p, q]"},
       {"target", "integer", "local target index, -1 if the goal is swept"}},
      [](const Json& in) {
        const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
        const auto cells = sim::swept_cells(g, point_arg(in, "p"), point_arg(in, "q"), arg_number(in, "clearance"));
        const auto path = grid::path_from_json(arg(in, "path"));
        std::vector<std::uint8_t> flags(path.size(), 0);
        for (std::size_t i = 0; i < path.size(); ++i)
          for (const auto& c : cells) flags[i] = static_cast<std::uint8_t>(flags[i] | (c == path[i] ? 1 : 0));
        return Json{{"swept", grid::path_to_json(cells)},
                    {"target", sim::local_target(flags, arg_integer(in, "from"))}};
      }});
  r.add(Rule{
      "han.sim.run",
      "Whole IACO-A* simulation run of a scenario (pathref-sim 1): trajectory summary, waits, replans, collisions (Han Fig. 5-6, 8)",
      "pathref::sim::simulate",
      {{"scenario", "object", "a pathref-sim 1 scenario with an inline map"}},
      {{"reached_goal", "bool", ""}, {"collided", "bool", ""}, {"time", "number", "s"},
       {"distance", "number", "m"}, {"wait_time", "number", "s"}, {"waits", "object[]", ""},
       {"replans", "object[]", ""}, {"steps", "integer", ""}, {"global_path", "cell[]", ""},
       {"trajectory", "array[]", "[t, x, y, v, state] per step"}},
      [](const Json& in) {
        const sim::Scenario s = sim::scenario_from_json(arg(in, "scenario"), "<input>", "");
        return sim::to_json(sim::simulate(s), true);
      }});
}

}  // namespace pathref::rules
