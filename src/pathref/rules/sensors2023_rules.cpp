// JSON adapters for the sensors2023 global-planner rules eq1-eq5 and the planner
// (spec/sensors2023.md). The B-spline rules eq6-eq8, a1-a3 are in curves_rules.cpp.
#include <string>

#include "pathref/core/error.hpp"
#include "pathref/equations/heuristics.hpp"
#include "pathref/equations/sensors2023.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/planners/astar_kinematic.hpp"
#include "pathref/rules/modules.hpp"

namespace pathref::rules {

namespace {

std::string label(int bearing) {
  std::string s = std::to_string(bearing);
  while (s.size() < 3) s = "0" + s;
  return s + "T";
}

template <std::size_t N>
Json labels(const std::array<int, N>& b) {
  Json a = Json::array();
  for (int x : b) a.push_back(label(x));
  return a;
}

Json mask_labels(std::uint8_t mask) {
  Json a = Json::array();
  for (int b = 0; b < 360; b += 45) {
    const std::array<int, 1> one{b};
    if ((sensors2023::bearing_mask(one) & mask) != 0) a.push_back(label(b));
  }
  return a;
}

int small_int(const Json& in, const char* key) {
  const long long v = arg_integer(in, key);
  if (v < -1000000 || v > 1000000) throw DomainError(std::string(key) + " out of range");
  return static_cast<int>(v);
}

grid::CornerPolicy policy_arg(const Json& in) {
  return (in.is_object() && in.contains("policy")) ? grid::policy_from_json(in.at("policy"))
                                                   : grid::CornerPolicy::strict;
}

}  // namespace

void register_sensors2023_rules(Registry& r) {
  r.add(Rule{
      "sensors2023.eq1",
      "Goal bearing (Eq. 1), Table 1 sector, the 5 kept and 3 abandoned child directions",
      "pathref::sensors2023::goal_bearing, bearing_sector, kept_bearings, child_moves",
      {{"theta", "number", "a bearing in [0, 360) (or n and goal)"},
       {"n", "cell", "the current node"},
       {"goal", "cell", "the goal"},
       {"grid", "grid", "optional: then moves is the set actually generated at n"},
       {"radius", "integer", "neighbourhood radius (default 1)"}},
      {{"theta", "number", "the bearing (when n, goal given)"},
       {"sector", "integer", "Table 1 row 0..7"},
       {"keep", "string[]", "kept directions, e.g. 000T"},
       {"abandon", "string[]", "abandoned directions"},
       {"reduced", "bool", "the neighbourhood is obstacle-free (grid given)"},
       {"moves", "string[]", "the directions generated at n (grid given)"}},
      [](const Json& in) {
        Json out = Json::object();
        double theta = 0.0;
        if (in.contains("theta")) {
          theta = arg_number(in, "theta");
        } else {
          theta = sensors2023::goal_bearing(grid::cell_from_json(arg(in, "n")),
                                            grid::cell_from_json(arg(in, "goal")));
          out["theta"] = number(theta);
        }
        const int s = sensors2023::bearing_sector(theta);
        out["sector"] = s;
        out["keep"] = labels(sensors2023::kept_bearings(s));
        out["abandon"] = labels(sensors2023::abandoned_bearings(s));
        if (in.contains("grid")) {
          const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
          const grid::Cell n = grid::cell_from_json(arg(in, "n"));
          const int radius = in.contains("radius") ? small_int(in, "radius") : 1;
          out["reduced"] = sensors2023::neighbourhood_free(g, n, radius);
          out["moves"] = mask_labels(
              sensors2023::child_moves(g, n, grid::cell_from_json(arg(in, "goal")), radius));
        }
        return out;
      }});
  r.add(Rule{"sensors2023.eq2",
             "Euclidean heuristic h(n) (Eq. 2) = search.h.euclidean",
             "pathref::heuristics::euclidean",
             {{"n", "cell", "the node"}, {"goal", "cell", "the goal"}},
             {{"h", "number", "the Euclidean distance between the cells"}},
             [](const Json& in) {
               return Json{{"h", number(heuristics::euclidean(grid::cell_from_json(arg(in, "n")),
                                                              grid::cell_from_json(arg(in, "goal"))))}};
             }});
  r.add(Rule{"sensors2023.eq3",
             "Basic evaluation function f = g + h (Eq. 3)",
             "pathref::sensors2023::f_basic",
             {{"g", "number", ">= 0"}, {"h", "number", ">= 0"}},
             {{"f", "number", "g + h"}},
             [](const Json& in) {
               return Json{{"f", number(sensors2023::f_basic(arg_number(in, "g"), arg_number(in, "h")))}};
             }});
  r.add(Rule{"sensors2023.eq4",
             "Weighted evaluation function f = g + w h, w = 1 + r/R | e^{r/R} | 1 (Eq. 4)",
             "pathref::sensors2023::f_weighted",
             {{"g", "number", ">= 0"},
              {"h", "number", ">= 0"},
              {"r", "number", "distance from n to the goal"},
              {"R", "number", "distance from the start to the goal"},
              {"weight", "string", "linear (default) | exp | none"}},
             {{"f", "number", "the evaluation"}, {"w", "number", "the weight of h"}},
             [](const Json& in) {
               const auto form = sensors2023::parse_weight_form(opt_string(in, "weight", "linear"));
               const double rr = arg_number(in, "r");
               const double RR = arg_number(in, "R");
               return Json{{"f", number(sensors2023::f_weighted(arg_number(in, "g"), arg_number(in, "h"),
                                                                rr, RR, form))},
                           {"w", number(sensors2023::heuristic_weight(rr, RR, form))}};
             }});
  r.add(Rule{"sensors2023.eq5",
             "Equal-division safety test of a shortcut a -> b (Eq. 5) and the collision test",
             "pathref::sensors2023::safety_test, pathref::sensors2023::segment_blocked",
             {{"grid", "grid", "rows top first"},
              {"a", "cell", "first node"},
              {"b", "cell", "second node"},
              {"k", "integer", "divisions per unit length (default 4)"},
              {"ds", "number", "safety distance (default 1)"},
              {"safety", "string", "ge (default) | gt"}},
             {{"safe", "bool", "every division point keeps ds from every obstacle centre"},
              {"divisions", "integer", "N = ceil(k |b - a|)"},
              {"blocked", "bool", "the segment meets the interior of a blocked cell"}},
             [](const Json& in) {
               const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
               const grid::Cell a = grid::cell_from_json(arg(in, "a"));
               const grid::Cell b = grid::cell_from_json(arg(in, "b"));
               const int k = in.contains("k") ? small_int(in, "k") : 4;
               const double ds = in.contains("ds") ? arg_number(in, "ds") : 1.0;
               const auto cmp = sensors2023::parse_safety_compare(opt_string(in, "safety", "ge"));
               const auto s = sensors2023::safety_test(g, a, b, k, ds, cmp);
               return Json{{"safe", s.safe},
                           {"divisions", s.divisions},
                           {"blocked", sensors2023::segment_blocked(g, a, b)}};
             }});
  r.add(Rule{"sensors2023.plan.astar-kinematic",
             "Kinematic-constraint A* (Eq. 1-5), ordinary and secondary removal, B-spline (Eq. 6-8)",
             "pathref::sensors2023::plan_kinematic",
             {{"grid", "grid", "rows top first"},
              {"start", "cell", "start"},
              {"goal", "cell", "goal"},
              {"policy", "string", "corner policy (default strict)"},
              {"params", "object", "planner parameters (spec/sensors2023.md), defaults otherwise"}},
             {{"found", "bool", "goal reached"},
              {"path", "path", "the A* path"},
              {"length", "number", "g(goal)"},
              {"extra", "object", "the planner's output (spec 'Output'), curve points included"}},
             [](const Json& in) {
               const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
               const planners::Planner p = planners::make_astar_kinematic_planner();
               const Json params = in.contains("params") ? arg(in, "params") : Json::object();
               if (!params.is_object()) throw UsageError("input 'params' must be an object");
               const sensors2023::KinematicOptions o =
                   sensors2023::options_from_json(planners::merge_params(p.defaults, params));
               const auto res = sensors2023::plan_kinematic(g, grid::cell_from_json(arg(in, "start")),
                                                            grid::cell_from_json(arg(in, "goal")),
                                                            policy_arg(in), o);
               return Json{{"found", res.search.found},
                           {"path", grid::path_to_json(res.search.path)},
                           {"length", number(res.search.length)},
                           {"extra", sensors2023::result_to_json(res, o)}};
             }});
}

}  // namespace pathref::rules
