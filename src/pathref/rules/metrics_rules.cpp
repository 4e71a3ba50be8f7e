// JSON adapters for the metrics.* rules (spec/metrics.md). Grids, cells and paths are encoded as
// in spec/grid.md "JSON encoding" (src/pathref/grid/json_codec.hpp).
#include "pathref/core/error.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/rules/modules.hpp"

namespace pathref::rules {

namespace {
std::vector<grid::Cell> path_arg(const Json& in) { return grid::path_from_json(arg(in, "path")); }
}  // namespace

void register_metrics_rules(Registry& r) {
  r.add(Rule{
      "metrics.length",
      "Path length: sum of distances between consecutive cell centres",
      "pathref::metrics::path_length",
      {{"path", "cell[]", "non-empty, no consecutive repeats"}},
      {{"length", "number", "sum of segment lengths, left to right"}},
      [](const Json& in) { return Json{{"length", number(metrics::path_length(path_arg(in)))}}; }});
  r.add(Rule{
      "metrics.turn-angle",
      "Turning angle atan2(|u x v|, u.v) at each interior node, radians in [0, pi]",
      "pathref::metrics::turning_angles",
      {{"path", "cell[]", "non-empty, no consecutive repeats"}},
      {{"angles", "number[]", "one per interior node (n-2 values)"}},
      [](const Json& in) {
        Json out = Json::array();
        for (const double a : metrics::turning_angles(path_arg(in))) out.push_back(number(a));
        return Json{{"angles", out}};
      }});
  r.add(Rule{
      "metrics.turns",
      "Number of interior nodes where the direction changes",
      "pathref::metrics::turn_count",
      {{"path", "cell[]", "non-empty, no consecutive repeats"}},
      {{"turns", "integer", "number of turns"}},
      [](const Json& in) { return Json{{"turns", metrics::turn_count(path_arg(in))}}; }});
  r.add(Rule{
      "metrics.smoothness",
      "OMPL smoothness: sum of (2 phi / (a + b))^2 over interior nodes",
      "pathref::metrics::smoothness_ompl",
      {{"path", "cell[]", "non-empty, no consecutive repeats"},
       {"form", "string", "ompl (default) | angle"}},
      {{"smoothness", "number", ">= 0, 0 for a straight path"}},
      [](const Json& in) {
        const auto form = metrics::parse_smoothness_form(opt_string(in, "form", "ompl"));
        return Json{{"smoothness", number(metrics::smoothness_ompl(path_arg(in), form))}};
      }});
  r.add(Rule{
      "metrics.safety",
      "Per node: number of blocked cells among its 8 neighbours",
      "pathref::metrics::safety_counts",
      {{"grid", "grid", "rows top first"},
       {"path", "cell[]", "nodes in bounds, no consecutive repeats"},
       {"outside", "string", "free (default) | blocked: how cells outside the map count"}},
      {{"counts", "integer[]", "one per node, each in [0, 8]"}},
      [](const Json& in) {
        const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
        const auto outside = metrics::parse_outside_cells(opt_string(in, "outside", "free"));
        return Json{{"counts", metrics::safety_counts(g, path_arg(in), outside)}};
      }});
  r.add(Rule{
      "metrics.converge",
      "First iteration (1-based) whose best-so-far equals the final best",
      "pathref::metrics::iterations_to_converge",
      {{"values", "number[]", "value per iteration (\"inf\" = no path found)"},
       {"sense", "string", "min (default) | max"}},
      {{"iteration", "integer", "1-based"}},
      [](const Json& in) {
        const Json& v = arg(in, "values");
        if (!v.is_array()) throw UsageError("input 'values' must be an array");
        std::vector<double> values;
        values.reserve(v.size());
        Json one = Json::object();
        for (const Json& e : v) {
          one["v"] = e;
          values.push_back(arg_number(one, "v"));
        }
        const auto sense = metrics::parse_sense(opt_string(in, "sense", "min"));
        return Json{{"iteration", metrics::iterations_to_converge(values, sense)}};
      }});
  r.add(Rule{
      "metrics.valid-path",
      "Path validator: start, goal, in bounds, free, allowed steps; first failure reported",
      "pathref::metrics::validate_path",
      {{"grid", "grid", "rows top first"},
       {"path", "cell[]", "the path to check"},
       {"start", "cell", "[x, y]"},
       {"goal", "cell", "[x, y]"},
       {"policy", "string", "strict (default) | never | one | always"}},
      {{"valid", "bool", "reason == ok"},
       {"reason", "string",
        "ok | empty | start_mismatch | out_of_bounds | blocked | repeated | not_adjacent | "
        "corner_cut | goal_mismatch"},
       {"index", "integer", "0-based failing node, -1 when none"}},
      [](const Json& in) {
        const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
        const auto check = metrics::validate_path(
            g, path_arg(in), grid::cell_from_json(arg(in, "start")),
            grid::cell_from_json(arg(in, "goal")),
            grid::parse_corner_policy(opt_string(in, "policy", "strict")));
        return Json{{"valid", check.valid}, {"reason", check.reason}, {"index", check.index}};
      }});
}

}  // namespace pathref::rules
