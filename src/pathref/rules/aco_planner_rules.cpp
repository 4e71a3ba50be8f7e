// JSON adapters for the whole-run ant-colony planner rules (spec/shi2022-aco.md,
// spec/han-iaco.md): shi2022.plan.aco, shi2022.plan.iaco, han.plan.iaco, han.plan.astar.
// Each adapter runs the registered planner exactly as `pathref plan --algo NAME` does.
#include <cmath>
#include <limits>
#include <string>

#include "pathref/core/error.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/planners/default_policy.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rules/modules.hpp"

namespace pathref::rules {

namespace {

/// Input keys that are not planner parameters.
bool reserved(const std::string& k) {
  return k == "grid" || k == "start" || k == "goal" || k == "seed" || k == "policy" || k == "algo";
}

Json numbers(const Json& values) {
  Json out = Json::array();
  for (const Json& v : values) out.push_back(v.is_null() ? number(std::numeric_limits<double>::infinity()) : v);
  return out;
}

Json numbers(const std::vector<double>& values) {
  Json out = Json::array();
  for (const double v : values) out.push_back(number(v));
  return out;
}

planners::Result run_planner(const std::string& algo, const Json& in, const grid::Grid& g) {
  const planners::Planner* p = planners::find_planner(algo);
  if (p == nullptr) throw UsageError("unknown planner '" + algo + "'");
  planners::Request req;
  req.grid = &g;
  req.start = grid::cell_from_json(arg(in, "start"));
  req.goal = grid::cell_from_json(arg(in, "goal"));
  req.policy = (in.contains("policy")) ? grid::policy_from_json(in.at("policy"))
                                       : planners::default_policy(algo);
  if (in.contains("seed")) {
    const long long s = arg_integer(in, "seed");
    require(s >= 0 && s <= 0xFFFFFFFFLL, "seed must be in [0, 2^32)");
    req.seed = static_cast<std::uint32_t>(s);
  }
  req.params = Json::object();
  for (const auto& [k, v] : in.items()) {
    if (reserved(k)) continue;
    // Golden INTERPRETATION options are strings; the iteration-origin options are integers on
    // the CLI (--set rho_t_origin=0): the adapter maps "0" / "1" to 0 / 1.
    if ((k == "rho_t_origin" || k == "q0_origin") && v.is_string()) {
      const std::string o = v.get<std::string>();
      if (o != "0" && o != "1") throw UsageError(k + " must be 0 or 1");
      req.params[k] = o == "1" ? 1 : 0;
    } else {
      req.params[k] = v;
    }
  }
  return p->run(req);
}

Json colony_json(const planners::Result& r) {
  Json out{{"found", r.found},
           {"path", grid::path_to_json(r.path)},
           {"length", number(r.length)},
           {"iterations", r.iterations},
           {"best_per_iteration", numbers(r.best_per_iteration)},
           {"mean_per_iteration", numbers(r.mean_per_iteration)},
           {"best_iteration", r.extra.value("best_iteration", Json(nullptr)).is_null()
                                  ? Json(0)
                                  : r.extra.at("best_iteration")},
           {"dead_ants_per_iteration", r.extra.value("dead_ants_per_iteration", Json::array())},
           {"rho_per_iteration", r.extra.value("rho_per_iteration", Json::array())},
           {"draws", r.extra.value("draws", Json(0))}};
  if (r.extra.contains("q0_per_iteration")) out["q0_per_iteration"] = r.extra.at("q0_per_iteration");
  if (r.extra.contains("iteration_best")) out["iteration_best"] = numbers(r.extra.at("iteration_best"));
  return out;
}

const std::vector<Field> colony_inputs = {
    {"grid", "grid", "rows top first, '.' free, '#' blocked"},
    {"start", "cell", "start [x, y], in bounds and free"},
    {"goal", "cell", "goal [x, y], in bounds and free"},
    {"seed", "integer", "seed of the run's stream, 0 .. 2^32 - 1 (default 1)"},
    {"policy", "string", "corner policy never|strict|one|always (default strict)"},
    {"<parameter>", "any", "any planner parameter by name (ants, iterations, dead_end, ...)"}};

const std::vector<Field> colony_outputs = {
    {"found", "bool", "some ant reached the goal"},
    {"path", "path", "best path of the run, [] when not found"},
    {"length", "number", "its length (metrics.length); 0 when not found"},
    {"iterations", "integer", "iterations run"},
    {"best_per_iteration", "number[]", "best-so-far length after each iteration (inf: none yet)"},
    {"mean_per_iteration", "number[]", "mean length of the surviving ants (nan: none survived)"},
    {"best_iteration", "integer", "iteration in which the best was found (0: not found)"},
    {"dead_ants_per_iteration", "integer[]", "ants that died in each iteration"},
    {"rho_per_iteration", "number[]", "rho used in each iteration's pheromone update"},
    {"draws", "integer", "doubles drawn from the stream"},
    {"q0_per_iteration", "number[]", "q0 of Eq. 5 per iteration (iaco-han only)"},
    {"iteration_best", "number[]", "best length of each iteration (inf: no survivor)"}};

}  // namespace

void register_aco_planner_rules(Registry& r) {
  r.add(Rule{"shi2022.plan.aco",
             "Planner aco: Shi 2022 Sec. 4.1 Ant System (Eq. 2-7), whole run",
             "pathref::ant_colony::run",
             colony_inputs,
             colony_outputs,
             [](const Json& in) {
               const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
               return colony_json(run_planner("aco", in, g));
             }});
  std::vector<Field> classic_inputs = colony_inputs;
  classic_inputs[4] = {"policy", "string", "corner policy never|strict|one|always (default always)"};
  r.add(Rule{"classic.plan.aco",
             "Planner aco-classic: the classic MATLAB ACO grid script's defaults, whole run",
             "pathref::ant_colony::run",
             classic_inputs,
             colony_outputs,
             [](const Json& in) {
               const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
               return colony_json(run_planner("aco-classic", in, g));
             }});
  std::vector<Field> iaco_inputs = colony_inputs;
  iaco_inputs.push_back({"algo", "string", "iaco-shi (default) | iaco-shi-nomin (IACO*)"});
  r.add(Rule{"shi2022.plan.iaco",
             "Planners iaco-shi / iaco-shi-nomin: Shi 2022 Sec. 4.4.1 (Eq. 12, 13), whole run",
             "pathref::ant_colony::run",
             iaco_inputs,
             colony_outputs,
             [](const Json& in) {
               const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
               const std::string algo = opt_string(in, "algo", "iaco-shi");
               if (algo != "iaco-shi" && algo != "iaco-shi-nomin")
                 throw UsageError("algo must be iaco-shi or iaco-shi-nomin");
               return colony_json(run_planner(algo, in, g));
             }});
  r.add(Rule{"han.plan.iaco",
             "Planner iaco-han: Han (IJACSA) Eq. 1-7, whole run",
             "pathref::ant_colony::run",
             colony_inputs,
             colony_outputs,
             [](const Json& in) {
               const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
               return colony_json(run_planner("iaco-han", in, g));
             }});
  r.add(Rule{"han.plan.astar",
             "Planner astar-han: 8-direction A* with the Chebyshev heuristic (Han Eq. 8)",
             "pathref::planners::make_astar_han_planner",
             {{"grid", "grid", "rows top first"},
              {"start", "cell", "start [x, y]"},
              {"goal", "cell", "goal [x, y]"},
              {"policy", "string", "corner policy (default strict)"},
              {"h_form", "string", "chebyshev (default) | octile"}},
             {{"found", "bool", "goal reached"},
              {"path", "path", "start..goal, [] when not found"},
              {"length", "number", "path cost"},
              {"expansions", "integer", "cells closed"}},
             [](const Json& in) {
               const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
               const planners::Result res = run_planner("astar-han", in, g);
               return Json{{"found", res.found},
                           {"path", grid::path_to_json(res.path)},
                           {"length", number(res.length)},
                           {"expansions", res.expansions}};
             }});
}

}  // namespace pathref::rules
