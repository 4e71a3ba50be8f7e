// JSON adapters for the cin2021.* rules of spec/cin2021-hga-aco.md (HGA-ACO, Eq. 16-35, the
// operators and the planners ga-cin, aco-cin, hga-aco-cin). Each adapter only converts JSON to
// the arguments of the functions (equations/, planners/) and their results back to JSON.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/aco.hpp"
#include "pathref/equations/cin2021.hpp"
#include "pathref/equations/ga.hpp"
#include "pathref/equations/ga_operators.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/equations/proportional.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rng/mt19937.hpp"
#include "pathref/rules/modules.hpp"

namespace pathref::rules {

namespace {

Json numbers(const std::vector<double>& v) {
  Json out = Json::array();
  for (const double x : v) out.push_back(number(x));
  return out;
}

grid::Cell cell_arg(const Json& in, const char* key) { return grid::cell_from_json(arg(in, key)); }
std::vector<grid::Cell> path_arg(const Json& in, const char* key) {
  return grid::path_from_json(arg(in, key));
}
grid::CornerPolicy policy_arg(const Json& in) {
  return in.contains("policy") ? grid::policy_from_json(in.at("policy")) : grid::CornerPolicy::strict;
}
double opt_num(const Json& in, const char* key, double fallback) {
  return in.contains(key) ? arg_number(in, key) : fallback;
}
cin::CornerPenalties penalties_arg(const Json& in) {
  cin::CornerPenalties p;
  if (in.contains("penalties")) {
    const std::vector<double> v = arg_numbers(in, "penalties");
    if (v.size() != 3) throw UsageError("penalties must be [c135, c90, c45]");
    p = cin::CornerPenalties{v[0], v[1], v[2]};
  }
  return p;
}

const std::vector<Field> planner_inputs = {
    {"grid", "grid", "rows top first, '.' free, '#' blocked"},
    {"start", "cell", "start [x, y], in bounds and free"},
    {"goal", "cell", "goal [x, y], in bounds and free"},
    {"seed", "integer", "seed of the run's stream, 0 .. 2^32 - 1 (default 1)"},
    {"policy", "string", "corner policy never|strict|one|always (default strict)"},
    {"<parameter>", "any", "any planner parameter by name (population, ants, research, ...)"}};
const std::vector<Field> planner_outputs = {
    {"found", "bool", "a path was found"},
    {"path", "path", "the result path, [] when not found"},
    {"length", "number", "its length (metrics.length)"},
    {"iterations", "integer", "generations / iterations run (hga: G + N_max)"},
    {"best_per_iteration", "number[]", "best-so-far length per generation / iteration (inf: none)"},
    {"best_iteration", "integer", "generation (ga) or ACO iteration (aco, hga) of the result"},
    {"dead_angle_table", "path", "cells of the dead-angle table at the end (aco, hga)"},
    {"draws", "integer", "doubles drawn from the stream"}};

Json planner_json(const std::string& algo, const Json& in) {
  const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
  const planners::Planner* p = planners::find_planner(algo);
  if (p == nullptr) throw UsageError("unknown planner '" + algo + "'");
  planners::Request req;
  req.grid = &g;
  req.start = cell_arg(in, "start");
  req.goal = cell_arg(in, "goal");
  req.policy = policy_arg(in);
  if (in.contains("seed")) {
    const long long s = arg_integer(in, "seed");
    require(s >= 0 && s <= 0xFFFFFFFFLL, "seed must be in [0, 2^32)");
    req.seed = static_cast<std::uint32_t>(s);
  }
  req.params = Json::object();
  for (const auto& [k, v] : in.items())
    if (k != "grid" && k != "start" && k != "goal" && k != "seed" && k != "policy") req.params[k] = v;
  const planners::Result r = p->run(req);
  Json best = Json::array();
  for (const double v : r.best_per_iteration) best.push_back(number(v));
  Json it = r.extra.value("best_iteration", Json(nullptr));
  if (it.is_null()) it = r.extra.value("best_generation", Json(0));
  return Json{{"found", r.found},
              {"path", grid::path_to_json(r.path)},
              {"length", number(r.length)},
              {"iterations", r.iterations},
              {"best_per_iteration", best},
              {"best_iteration", it.is_null() ? Json(0) : it},
              {"dead_angle_table", r.extra.value("dead_angle_table", Json::array())},
              {"draws", r.extra.value("draws", Json(0))}};
}

}  // namespace

void register_cin2021_rules(Registry& r) {
  r.add(Rule{"cin2021.eq16", "Safety: no segment meets an obstacle (cin2021 Eq. 16, on the grid)",
             "pathref::metrics::validate_path",
             {{"grid", "grid", "rows top first"}, {"path", "path", "the nodes"},
              {"policy", "string", "corner policy (default strict)"}},
             {{"safe", "bool", "every node free, every segment an allowed move"},
              {"reason", "string", "metrics.valid-path reason code"}},
             [](const Json& in) {
               const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
               const auto p = path_arg(in, "path");
               if (p.empty()) return Json{{"safe", false}, {"reason", "empty"}};
               const auto chk = metrics::validate_path(g, p, p.front(), p.back(), policy_arg(in));
               return Json{{"safe", chk.valid}, {"reason", chk.reason}};
             }});
  r.add(Rule{"cin2021.eq17", "Smoothness S = sum (1 - cos theta) (cin2021 Eq. 17)",
             "pathref::cin::smoothness_cost", {{"path", "path", "the nodes"}},
             {{"S", "number", "sum of 1 - cos theta over interior nodes"}}, [](const Json& in) {
               return Json{{"S", number(cin::smoothness_cost(path_arg(in, "path")))}};
             }});
  r.add(Rule{"cin2021.eq18", "cos theta of adjacent segments (cin2021 Eq. 18)",
             "pathref::cin::segment_cosine",
             {{"a", "cell", "p_i"}, {"b", "cell", "p_i+1"}, {"c", "cell", "p_i+2"}},
             {{"cos", "number", "cos of the heading change"}}, [](const Json& in) {
               return Json{{"cos", number(cin::segment_cosine(cell_arg(in, "a"), cell_arg(in, "b"),
                                                              cell_arg(in, "c")))}};
             }});
  r.add(Rule{"cin2021.eq19", "Path length L (cin2021 Eq. 19 = metrics.length)",
             "pathref::metrics::path_length", {{"path", "path", "the nodes"}},
             {{"length", "number", "sum of segment lengths, left to right"}}, [](const Json& in) {
               return Json{{"length", number(metrics::path_length(path_arg(in, "path")))}};
             }});
  r.add(Rule{"cin2021.eq20", "Length fitness f1 = 1 / L (cin2021 Eq. 20)", "pathref::ga::inverse_length",
             {{"path", "path", "the nodes (>= 2, length > 0)"}},
             {{"f1", "number", "1 / metrics.length"}}, [](const Json& in) {
               return Json{{"f1", number(ga::inverse_length(metrics::path_length(path_arg(in, "path"))))}};
             }});
  r.add(Rule{"cin2021.eq21", "Distances d1 between adjacent nodes (cin2021 Eq. 21)",
             "pathref::cin::node_distances", {{"path", "path", "the nodes"}},
             {{"d1", "number[]", "d(p_i, p_i+1)"}}, [](const Json& in) {
               return Json{{"d1", numbers(cin::node_distances(path_arg(in, "path")).d1)}};
             }});
  r.add(Rule{"cin2021.eq22", "Distances d2 between nodes two apart (cin2021 Eq. 22)",
             "pathref::cin::node_distances", {{"path", "path", "the nodes"}},
             {{"d2", "number[]", "d(p_i, p_i+2)"}}, [](const Json& in) {
               return Json{{"d2", numbers(cin::node_distances(path_arg(in, "path")).d2)}};
             }});
  r.add(Rule{"cin2021.eq23", "Included angle theta at the middle node, degrees (cin2021 Eq. 23)",
             "pathref::cin::included_angle, pathref::cin::included_angle_grid",
             {{"a", "cell", "p_i"}, {"b", "cell", "p_i+1 (the vertex)"}, {"c", "cell", "p_i+2"},
              {"angle", "string", "arccos (default) | lookup (8-neighbour steps only)"}},
             {{"theta", "number", "degrees, 180 = straight"}}, [](const Json& in) {
               const grid::Cell a = cell_arg(in, "a");
               const grid::Cell b = cell_arg(in, "b");
               const grid::Cell c = cell_arg(in, "c");
               const auto mode = cin::parse_angle_reading(opt_string(in, "angle", "arccos"));
               if (mode == cin::AngleReading::lookup)
                 return Json{{"theta", number(cin::included_angle_grid(a, b, c))}};
               const std::vector<grid::Cell> p{a, b, c};
               const cin::NodeDistances d = cin::node_distances(p);
               return Json{{"theta", number(cin::included_angle(d.d1[0], d.d1[1], d.d2[0]))}};
             }});
  r.add(Rule{"cin2021.eq24", "Corner penalty coefficient c_i (cin2021 Eq. 24)",
             "pathref::cin::corner_penalty",
             {{"theta", "number", "included angle, degrees"},
              {"penalties", "number[]", "[c135, c90, c45] (default [5, 100, 1000], not the paper's)"}},
             {{"c", "number", "the penalty"}}, [](const Json& in) {
               return Json{{"c", number(cin::corner_penalty(arg_number(in, "theta"), penalties_arg(in)))}};
             }});
  r.add(Rule{"cin2021.eq25", "Smoothness fitness f2 = 1 / (guard + sum c_i) (cin2021 Eq. 25)",
             "pathref::cin::smoothness_fitness",
             {{"path", "path", "the nodes"},
              {"penalties", "number[]", "[c135, c90, c45]"},
              {"f2_guard", "string", "one_plus (default) | epsilon"},
              {"angle", "string", "arccos (default) | lookup"}},
             {{"f2", "number", "the smoothness fitness"}}, [](const Json& in) {
               return Json{{"f2", number(cin::smoothness_fitness(
                                      path_arg(in, "path"), penalties_arg(in),
                                      cin::parse_f2_guard(opt_string(in, "f2_guard", "one_plus")),
                                      cin::parse_angle_reading(opt_string(in, "angle", "arccos"))))}};
             }});
  r.add(Rule{"cin2021.eq26", "Optimised fitness f = a f1 + b f2 (cin2021 Eq. 26)",
             "pathref::ga::weighted_fitness",
             {{"f1", "number", "length fitness"}, {"f2", "number", "smoothness fitness"},
              {"a", "number", "weight of f1"}, {"b", "number", "weight of f2"}},
             {{"f", "number", "(a f1) + (b f2)"}}, [](const Json& in) {
               const double a = arg_number(in, "a");
               const double b = arg_number(in, "b");
               return Json{{"f", number(ga::weighted_fitness(arg_number(in, "f1"), arg_number(in, "f2"),
                                                             0.0, ga::FitnessWeights{a, b, 0.0}))}};
             }});
  r.add(Rule{"cin2021.eq27", "Roulette probability P_i = f(i) / sum f (cin2021 Eq. 27)",
             "pathref::equations::proportional_probabilities",
             {{"fitness", "number[]", "f of each individual"}},
             {{"p", "number[]", "selection probabilities"}}, [](const Json& in) {
               return Json{{"p", numbers(equations::proportional_probabilities(arg_numbers(in, "fitness")))}};
             }});
  r.add(Rule{"cin2021.eq28", "GA-to-ACO initial pheromone tau(0) = tau_C + tau^G (cin2021 Eq. 28)",
             "pathref::cin::converted_pheromone, pathref::cin::conversion_delta",
             {{"rows", "path[]", "the rows of T (paths)"},
              {"Q", "number", "constant Q"},
              {"tau_C", "number", "the colony's initial value"},
              {"conversion_form", "string", "q_over_l (default) | q_d_over_l | q_over_l_d"},
              {"conversion", "string", "add (default) | replace"}},
             {{"edges", "object[]", "{from, to, tau} per converted directed edge, first appearance"}},
             [](const Json& in) {
               std::vector<std::vector<grid::Cell>> rows;
               for (const Json& row : arg(in, "rows")) rows.push_back(grid::path_from_json(row));
               const double tau_c = arg_number(in, "tau_C");
               require(std::isfinite(tau_c) && tau_c > 0.0, "tau_C must be finite and > 0");
               const auto form = cin::parse_conversion_form(opt_string(in, "conversion_form", "q_over_l"));
               const std::string mode = opt_string(in, "conversion", "add");
               if (mode != "add" && mode != "replace") throw UsageError("conversion must be add or replace");
               Json edges = Json::array();
               for (const cin::EdgePheromone& e : cin::converted_pheromone(rows, arg_number(in, "Q"), form))
                 edges.push_back(Json{{"from", Json::array({e.from.x, e.from.y})},
                                      {"to", Json::array({e.to.x, e.to.y})},
                                      {"tau", number(mode == "add" ? tau_c + e.tau : e.tau)}});
               return Json{{"edges", edges}};
             }});
  r.add(Rule{"cin2021.eq29", "Transition probability (cin2021 Eq. 29 = Shi Eq. 2)",
             "pathref::aco::transition_weights, pathref::aco::transition_probabilities",
             {{"tau", "number[]", "tau of each allowed candidate"}, {"eta", "number[]", "eta of each"},
              {"alpha", "number", "alpha"}, {"beta", "number", "beta"}},
             {{"weights", "number[]", "tau^alpha eta^beta"}, {"p", "number[]", "probabilities"}},
             [](const Json& in) {
               const auto w = aco::transition_weights(arg_numbers(in, "tau"), arg_numbers(in, "eta"),
                                                      arg_number(in, "alpha"), arg_number(in, "beta"));
               return Json{{"weights", numbers(w)},
                           {"p", numbers(equations::proportional_probabilities(w))}};
             }});
  r.add(Rule{"cin2021.eq30", "Heuristic eta = 1/d_ij (or 1/d_jG) (cin2021 Eq. 30)",
             "pathref::aco::eta_inverse_distance, pathref::aco::eta_goal_inverse",
             {{"i", "cell", "current cell"}, {"j", "cell", "candidate cell"}, {"goal", "cell", "G"},
              {"eta", "string", "inverse_distance (default) | goal_inverse"}},
             {{"eta", "number", "the heuristic"}}, [](const Json& in) {
               const std::string form = opt_string(in, "eta", "inverse_distance");
               if (form == "inverse_distance")
                 return Json{{"eta", number(aco::eta_inverse_distance(cell_arg(in, "i"), cell_arg(in, "j")))}};
               if (form == "goal_inverse")
                 return Json{{"eta", number(aco::eta_goal_inverse(cell_arg(in, "j"), cell_arg(in, "goal"), 2.0))}};
               throw UsageError("eta must be inverse_distance or goal_inverse");
             }});
  r.add(Rule{"cin2021.eq31", "Update tau = (1 - rho) tau + delta (cin2021 Eq. 31 = Shi Eq. 5)",
             "pathref::aco::pheromone_update",
             {{"tau", "number", "tau(t)"}, {"rho", "number", "evaporation"}, {"delta", "number", "increment"}},
             {{"tau", "number", "tau(t+1)"}}, [](const Json& in) {
               return Json{{"tau", number(aco::pheromone_update(arg_number(in, "tau"), arg_number(in, "rho"),
                                                                arg_number(in, "delta")))}};
             }});
  r.add(Rule{"cin2021.eq32", "Weighted iteration-best + global-best increment (cin2021 Eq. 32)",
             "pathref::cin::weighted_best_deposit",
             {{"on_ib", "bool", "edge on the iteration-best path"}, {"w_ib", "number", "omega_ib"},
              {"L_ib", "number", "its length"}, {"on_gb", "bool", "edge on the global-best path"},
              {"w_gb", "number", "omega_gb"}, {"L_gb", "number", "its length"}, {"Q", "number", "Q"}},
             {{"delta", "number", "the increment"}}, [](const Json& in) {
               const bool on_ib = arg(in, "on_ib").get<bool>();
               const bool on_gb = arg(in, "on_gb").get<bool>();
               return Json{{"delta", number(cin::weighted_best_deposit(
                                         on_ib, opt_num(in, "w_ib", 0.0), opt_num(in, "L_ib", 1.0), on_gb,
                                         opt_num(in, "w_gb", 0.0), opt_num(in, "L_gb", 1.0),
                                         arg_number(in, "Q")))}};
             }});
  r.add(Rule{"cin2021.eq33", "Moving weights omega_ib = N - t, omega_gb = t (cin2021 Eq. 33)",
             "pathref::cin::best_path_weights",
             {{"t", "integer", "0-based iteration"}, {"N", "integer", "N_max"},
              {"weight_norm", "string", "raw (default) | normalised"}},
             {{"w_ib", "number", "omega_ib"}, {"w_gb", "number", "omega_gb"}}, [](const Json& in) {
               const cin::BestWeights w = cin::best_path_weights(
                   arg_integer(in, "t"), arg_integer(in, "N"),
                   cin::parse_weight_norm(opt_string(in, "weight_norm", "raw")));
               return Json{{"w_ib", number(w.ib)}, {"w_gb", number(w.gb)}};
             }});
  r.add(Rule{"cin2021.eq34", "Poor paths: evaporation only (cin2021 Eq. 34)",
             "pathref::aco::pheromone_update",
             {{"tau", "number", "tau(t)"}, {"rho", "number", "evaporation"}},
             {{"tau", "number", "(1 - rho) tau"}}, [](const Json& in) {
               return Json{{"tau", number(aco::pheromone_update(arg_number(in, "tau"), arg_number(in, "rho"), 0.0))}};
             }});
  r.add(Rule{"cin2021.eq35", "Dead-angle penalty tau <- lambda tau (cin2021 Eq. 35)",
             "pathref::cin::dead_angle_penalty",
             {{"tau", "number", "pheromone of an edge into a deadlock point"},
              {"lambda", "number", "penalty coefficient in (0, 1)"},
              {"lambda_form", "string", "lambda (default) | one_minus"}},
             {{"tau", "number", "penalised tau"}}, [](const Json& in) {
               return Json{{"tau", number(cin::dead_angle_penalty(
                                       arg_number(in, "tau"), arg_number(in, "lambda"),
                                       cin::parse_lambda_form(opt_string(in, "lambda_form", "lambda"))))}};
             }});
  r.add(Rule{"cin2021.op.crossover", "Crossover at random cut genes with the chain repair (cin2021 Fig. 8a)",
             "pathref::ga::crossover_cut",
             {{"grid", "grid", "rows top first"}, {"a", "path", "parent a"}, {"b", "path", "parent b"},
              {"k", "integer", "cut gene of a (interior)"}, {"j", "integer", "cut gene of b (interior)"},
              {"policy", "string", "corner policy (default strict)"}},
             {{"feasible", "bool", "both repairs succeeded"},
              {"first", "path", "child a[0..k] ++ b[j+1..], repaired"},
              {"second", "path", "child b[0..j] ++ a[k+1..], repaired"}},
             [](const Json& in) {
               const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
               const long long k = arg_integer(in, "k");
               const long long j = arg_integer(in, "j");
               require(k >= 0 && j >= 0, "k, j must be >= 0");
               const ga::CutChildren c = ga::crossover_cut(g, path_arg(in, "a"), path_arg(in, "b"),
                                                           static_cast<std::size_t>(k),
                                                           static_cast<std::size_t>(j), policy_arg(in));
               return Json{{"feasible", c.feasible},
                           {"first", grid::path_to_json(c.children.first)},
                           {"second", grid::path_to_json(c.children.second)}};
             }});
  r.add(Rule{"cin2021.op.mutation", "Multidirectional mutation: mutants A and B (cin2021 Fig. 9)",
             "pathref::ga::multidirectional_mutants, pathref::ga::research_walk",
             {{"grid", "grid", "rows top first"}, {"path", "path", "the individual"},
              {"k", "integer", "mutation point (interior)"},
              {"research", "string", "greedy (default) | random"},
              {"seed", "integer", "seed of the stream the random walks draw from (default 1)"},
              {"policy", "string", "corner policy (default strict)"}},
             {{"a", "path", "mutant A ([] if its walk failed)"}, {"b", "path", "mutant B ([] if failed)"},
              {"draws", "integer", "doubles drawn"}},
             [](const Json& in) {
               const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
               const long long k = arg_integer(in, "k");
               require(k >= 0, "k must be >= 0");
               const long long seed = in.contains("seed") ? arg_integer(in, "seed") : 1;
               require(seed >= 0 && seed <= 0xFFFFFFFFLL, "seed must be in [0, 2^32)");
               rng::Stream stream(static_cast<std::uint32_t>(seed));
               const ga::Mutants m = ga::multidirectional_mutants(
                   g, path_arg(in, "path"), static_cast<std::size_t>(k), policy_arg(in),
                   ga::parse_research(opt_string(in, "research", "greedy")), stream);
               return Json{{"a", grid::path_to_json(m.a)}, {"b", grid::path_to_json(m.b)},
                           {"draws", stream.doubles_drawn()}};
             }});
  r.add(Rule{"cin2021.plan.ga", "Planner ga-cin: the optimised GA of cin2021 Sec. 5.3, whole run",
             "pathref::genetic::run", planner_inputs, planner_outputs,
             [](const Json& in) { return planner_json("ga-cin", in); }});
  r.add(Rule{"cin2021.plan.aco", "Planner aco-cin: the optimised ACO of cin2021 Sec. 5.5, whole run",
             "pathref::ant_colony::run", planner_inputs, planner_outputs,
             [](const Json& in) { return planner_json("aco-cin", in); }});
  r.add(Rule{"cin2021.plan.hga-aco", "Planner hga-aco-cin: cin2021 HGA-ACO, whole run",
             "pathref::hybrid::run_cin", planner_inputs, planner_outputs,
             [](const Json& in) { return planner_json("hga-aco-cin", in); }});
}

}  // namespace pathref::rules
