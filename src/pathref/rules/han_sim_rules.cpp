// JSON adapters for the han.* rules of the dynamic-obstacle part (spec/han-sim.md): random maps,
// the Fig. 5 collision classification, the speed profile, the frontal detour pieces and whole
// simulation runs. Each adapter only converts JSON to the arguments of the functions in sim/.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rules/modules.hpp"
#include "pathref/equations/rls.hpp"
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

/// han.plan.iaco-astar: input keys that are not planner parameters.
bool iaco_astar_reserved(const std::string& k) {
  return k == "grid" || k == "start" || k == "goal" || k == "seed" || k == "policy" || k == "obstacles";
}

Json curve(const std::vector<double>& v) {
  Json out = Json::array();
  for (const double x : v) out.push_back(number(x));
  return out;
}

/// han.plan.iaco-astar: the planner's static result and, with `obstacles`, the simulation of the
/// same map, endpoints, policy, seed and planner parameters with those moving obstacles.
Json iaco_astar_rule(const Json& in) {
  const planners::Planner* p = planners::find_planner("iaco-astar");
  if (p == nullptr) throw UsageError("planner iaco-astar is not registered");
  const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
  planners::Request req;
  req.grid = &g;
  req.start = grid::cell_from_json(arg(in, "start"));
  req.goal = grid::cell_from_json(arg(in, "goal"));
  req.policy = in.contains("policy") ? grid::policy_from_json(in.at("policy")) : grid::CornerPolicy::strict;
  if (in.contains("seed")) {
    const long long seed = arg_integer(in, "seed");
    if (seed < 0 || seed > 4294967295LL) throw UsageError("seed must be a 32-bit unsigned integer");
    req.seed = static_cast<std::uint32_t>(seed);
  }
  req.params = Json::object();
  for (const auto& [k, v] : in.items())
    if (!iaco_astar_reserved(k)) req.params[k] = v;
  const planners::Result r = p->run(req);
  const Json& ge = r.extra.at("global_extra");
  Json out{{"found", r.found},
           {"path", grid::path_to_json(r.path)},
           {"length", number(r.length)},
           {"iterations", r.iterations},
           {"best_per_iteration", curve(r.best_per_iteration)},
           {"global", r.extra.at("global")},
           {"draws", ge.value("draws", Json(0))},
           {"params_used", r.params_used}};
  if (in.contains("obstacles")) {
    Json scenario{{"format", "pathref-sim 1"},
                  {"map", arg(in, "grid")},
                  {"start", arg(in, "start")},
                  {"goal", arg(in, "goal")},
                  {"policy", std::string(grid::to_string(req.policy))},
                  {"seed", req.seed},
                  {"planner", Json{{"name", "iaco-astar"}, {"params", req.params}}},
                  {"obstacles", arg(in, "obstacles")}};
    out["simulation"] = sim::to_json(sim::simulate(sim::scenario_from_json(scenario, "<input>", "")), true);
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
       {"robot_inside", "bool", "robot position closer than clearance to the ray from p through q (the obstacle's whole future path)"}},
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
  r.add(Rule{
      "han.sim.safety",
      "Predicted margins of waiting and of going on against one obstacle over the horizon (pathref's timed check)",
      "pathref::sim::safety_margins, pathref::sim::polyline_point",
      {{"robot", "point[]", "the robot's path ahead, robot[0] = its position (m)"},
       {"v0", "number", "its speed now, m/s"},
       {"v_max", "number", "cruise speed"},
       {"a", "number", "acceleration"},
       {"dt", "number", "sample step, s"},
       {"horizon", "number", "H, s"},
       {"motion", "number[]", "the obstacle's RLS line [a, b, c, d] (Eq. 9)"},
       {"tau", "number", "the RLS clock now, s"}},
      {{"wait", "number", "min distance robot[0] - obstacle over the samples"},
       {"go", "number", "min distance of the robot driving along `robot` - obstacle"},
       {"go_closing", "bool", "the last sampled go distance is below the one before"},
       {"samples", "integer", "sample times j dt <= H"}},
      [](const Json& in) {
        const auto pts = points_arg(in, "robot");
        const auto m = arg_numbers(in, "motion");
        if (m.size() != 4) throw UsageError("motion must be [a, b, c, d]");
        const auto mg = sim::safety_margins(pts, arg_number(in, "v0"), arg_number(in, "v_max"), arg_number(in, "a"),
                                            arg_number(in, "dt"), arg_number(in, "horizon"),
                                            rls::LinearMotion{m[0], m[1], m[2], m[3]}, arg_number(in, "tau"));
        return Json{{"wait", number(mg.wait)}, {"go", number(mg.go)}, {"go_closing", mg.go_closing},
                    {"samples", mg.samples}};
      }});
  r.add(Rule{
      "han.sim.evade",
      "The nearest refuge: multi-source Dijkstra to the first cell outside the obstacles' bands (pathref's evasion)",
      "pathref::sim::find_refuge, pathref::sim::swept_ray_cells",
      {{"grid", "grid", "rows, top first"},
       {"sources", "array[]", "[x, y, cost] per source"},
       {"band", "cell[]", "the band's cells"},
       {"rays", "array[]", "optional: [px, py, qx, qy, clearance] per obstacle; swept_ray_cells of each join the band"},
       {"policy", "string", "corner policy (default strict)"}},
      {{"band", "cell[]", "the band used (given cells and rays), by increasing cell index"},
       {"found", "bool", "a refuge was reached"},
       {"path", "cell[]", "source ... refuge"},
       {"source", "integer", "index of the path's source (-1 if none)"},
       {"cost", "number", "the source's cost plus the steps"}},
      [](const Json& in) {
        const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
        const grid::CornerPolicy pol =
            in.contains("policy") ? grid::policy_from_json(in.at("policy")) : grid::CornerPolicy::strict;
        std::vector<sim::RefugeSource> sources;
        const Json& sv = arg(in, "sources");
        if (!sv.is_array()) throw UsageError("sources must be an array of [x, y, cost]");
        for (const Json& e : sv) {
          if (!e.is_array() || e.size() != 3 || !e[0].is_number_integer() || !e[1].is_number_integer() ||
              !e[2].is_number())
            throw UsageError("a source is [x, y, cost]");
          sources.push_back(sim::RefugeSource{grid::Cell{e[0].get<std::int64_t>(), e[1].get<std::int64_t>()},
                                              e[2].get<double>()});
        }
        std::vector<std::uint8_t> band(static_cast<std::size_t>(g.cell_count()), 0);
        for (const grid::Cell c : grid::path_from_json(arg(in, "band"))) {
          if (!g.in_bounds(c)) throw UsageError("band cells must lie in the grid");
          band[static_cast<std::size_t>(g.index(c))] = 1;
        }
        if (in.contains("rays")) {
          const Json& rv = in.at("rays");
          if (!rv.is_array()) throw UsageError("rays must be an array of [px, py, qx, qy, clearance]");
          for (const Json& e : rv) {
            if (!e.is_array() || e.size() != 5) throw UsageError("a ray is [px, py, qx, qy, clearance]");
            for (const Json& x : e)
              if (!x.is_number()) throw UsageError("a ray is [px, py, qx, qy, clearance]");
            for (const grid::Cell c : sim::swept_ray_cells(g, sim::Vec2{e[0].get<double>(), e[1].get<double>()},
                                                           sim::Vec2{e[2].get<double>(), e[3].get<double>()},
                                                           e[4].get<double>()))
              band[static_cast<std::size_t>(g.index(c))] = 1;
          }
        }
        std::vector<grid::Cell> band_cells;
        for (std::int64_t i = 0; i < g.cell_count(); ++i)
          if (band[static_cast<std::size_t>(i)] != 0) band_cells.push_back(g.cell(i));
        const auto rf = sim::find_refuge(g, sources, band, pol);
        return Json{{"band", grid::path_to_json(band_cells)}, {"found", rf.found}, {"path", grid::path_to_json(rf.path)},
                    {"source", rf.source}, {"cost", number(rf.cost)}};
      }});
  r.add(Rule{
      "han.plan.iaco-astar",
      "Planner iaco-astar (Han Fig. 6): the global planner's path (default iaco-han), and with moving obstacles the IACO-A* simulation",
      "pathref::planners::make_iaco_astar_planner",
      {{"grid", "grid", "rows, top first"},
       {"start", "cell", "start [x, y]"},
       {"goal", "cell", "goal [x, y]"},
       {"seed", "integer", "the global planner's seed (and the simulation's), default 1"},
       {"policy", "string", "corner policy (default strict)"},
       {"global", "string", "optional: the global planner (default iaco-han)"},
       {"<planner>.<name>", "any", "optional: a parameter of the global planner, e.g. iaco-han.ants"},
       {"obstacles", "object[]", "optional: moving obstacles {position, velocity, radius} (pathref-sim 1); then the run is simulated"}},
      {{"found", "bool", "the global planner found a path"},
       {"path", "cell[]", "the global path"},
       {"length", "number", "its length"},
       {"iterations", "integer", "the global planner's iterations"},
       {"best_per_iteration", "number[]", "its best-so-far curve"},
       {"global", "string", "the global planner"},
       {"draws", "integer", "doubles the global planner drew"},
       {"params_used", "object", "global and every <global>.<name> used"},
       {"simulation", "object", "with obstacles: the pathref-sim-result of han.sim.run (full)"}},
      iaco_astar_rule});
}

}  // namespace pathref::rules
