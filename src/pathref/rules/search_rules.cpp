// JSON adapters for the search.* rules (spec/search.md).
#include <string>

#include "pathref/core/error.hpp"
#include "pathref/equations/heuristics.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/planners/search.hpp"
#include "pathref/rules/modules.hpp"

namespace pathref::rules {

namespace {

using HeuristicFn = double (*)(grid::Cell, grid::Cell);

Rule heuristic_rule(const char* id, const char* summary, const char* function, HeuristicFn fn) {
  return Rule{id,
              summary,
              function,
              {{"n", "cell", "the cell [x, y] the heuristic is evaluated at"},
               {"goal", "cell", "the goal cell [x, y]"}},
              {{"h", "number", "the heuristic value"}},
              [fn](const Json& in) {
                return Json{{"h", number(fn(grid::cell_from_json(arg(in, "n")),
                                            grid::cell_from_json(arg(in, "goal"))))}};
              }};
}

search::OpenKey key_arg(const Json& in, const char* name) {
  const Json& k = arg(in, name);
  if (!k.is_object()) throw UsageError(std::string("input '") + name + "' must be {f, h, index}");
  return search::OpenKey{arg_number(k, "f"), arg_number(k, "h"), arg_integer(k, "index")};
}

Json outcome_json(const search::Outcome& o) {
  const search::StepCounts s = search::step_counts(o.path);
  return Json{{"found", o.found},
              {"path", grid::path_to_json(o.path)},
              {"length", number(o.length)},
              {"expansions", o.expansions},
              {"steps", Json::array({s.orthogonal, s.diagonal})}};
}

const std::vector<Field> run_inputs_common = {
    {"grid", "grid", "rows top first, '.' free, '#' blocked"},
    {"start", "cell", "start [x, y], in bounds and free"},
    {"goal", "cell", "goal [x, y], in bounds and free"},
    {"policy", "string", "corner policy never|strict|one|always (default strict)"}};

const std::vector<Field> run_outputs = {
    {"found", "bool", "goal reached"},
    {"path", "path", "start..goal, [] when not found"},
    {"length", "number", "g(goal), the left-to-right sum of step costs; 0 when not found"},
    {"expansions", "integer", "cells moved from OPEN to CLOSED, the goal included"},
    {"steps", "integer[]", "[orthogonal, diagonal] step counts of the path"}};

grid::CornerPolicy policy_arg(const Json& in) {
  return (in.is_object() && in.contains("policy")) ? grid::policy_from_json(in.at("policy"))
                                                   : grid::CornerPolicy::strict;
}

}  // namespace

void register_search_rules(Registry& r) {
  r.add(heuristic_rule("search.h.manhattan", "Manhattan distance |dx| + |dy| between cells",
                       "pathref::heuristics::manhattan", &heuristics::manhattan));
  r.add(heuristic_rule("search.h.chebyshev",
                       "Chebyshev distance max(|dx|, |dy|) between cells (Han Eq. 8)",
                       "pathref::heuristics::chebyshev", &heuristics::chebyshev));
  r.add(heuristic_rule("search.h.octile", "Octile distance (M - m) + sqrt2*m between cells",
                       "pathref::heuristics::octile", &heuristics::octile));
  r.add(heuristic_rule("search.h.euclidean", "Euclidean distance sqrt(dx^2 + dy^2) between cells",
                       "pathref::heuristics::euclidean", &heuristics::euclidean));
  r.add(Rule{
      "search.admissible",
      "Whether a heuristic is admissible / consistent under a corner policy",
      "pathref::heuristics::admissible, pathref::heuristics::consistent",
      {{"heuristic", "string", "zero|manhattan|chebyshev|octile|euclidean"},
       {"policy", "string", "never|strict|one|always"}},
      {{"admissible", "bool", "h <= exact shortest cost on every map"},
       {"consistent", "bool", "h(n) <= c(n,n') + h(n') on every allowed step"}},
      [](const Json& in) {
        const auto h = heuristics::parse_heuristic(arg_string(in, "heuristic"));
        const auto p = grid::policy_from_json(arg(in, "policy"));
        return Json{{"admissible", heuristics::admissible(h, p)},
                    {"consistent", heuristics::consistent(h, p)}};
      }});
  r.add(Rule{
      "search.order",
      "Open-list order: a before b iff (f, h, index) is lexicographically smaller",
      "pathref::search::precedes",
      {{"a", "object", "{f, h, index}"}, {"b", "object", "{f, h, index}"}},
      {{"precedes", "bool", "a is selected before b"}},
      [](const Json& in) {
        return Json{{"precedes", search::precedes(key_arg(in, "a"), key_arg(in, "b"))}};
      }});

  std::vector<Field> astar_inputs = run_inputs_common;
  astar_inputs.push_back(
      {"heuristic", "string", "octile (default) | chebyshev | euclidean | manhattan | zero"});
  r.add(Rule{"search.astar",
             "A* on the grid: tie-break (f, h, index), no reopening, strict-improvement parents",
             "pathref::search::astar",
             astar_inputs,
             run_outputs,
             [](const Json& in) {
               const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
               const auto h = heuristics::parse_heuristic(opt_string(in, "heuristic", "octile"));
               return outcome_json(search::astar(g, grid::cell_from_json(arg(in, "start")),
                                                 grid::cell_from_json(arg(in, "goal")),
                                                 policy_arg(in), h));
             }});
  r.add(Rule{"search.dijkstra",
             "Dijkstra on the grid: A* with h = 0, tie-break (g, index)",
             "pathref::search::dijkstra",
             run_inputs_common,
             run_outputs,
             [](const Json& in) {
               const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
               return outcome_json(search::dijkstra(g, grid::cell_from_json(arg(in, "start")),
                                                    grid::cell_from_json(arg(in, "goal")),
                                                    policy_arg(in)));
             }});
}

}  // namespace pathref::rules
