// JSON adapters for the rules of spec/shi2022-ga.md: the GA operators (shi2022.op.*) and the GA
// and hybrid planners (shi2022.plan.ga, .iga, .hybrid, .iha). The planner rules run the
// registered planners, so a golden vector checks exactly what `pathref plan --algo` runs.
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/ga.hpp"
#include "pathref/equations/ga_operators.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/planners/default_policy.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rules/modules.hpp"

namespace pathref::rules {

namespace {

grid::CornerPolicy policy_of(const Json& in) {
  return (in.is_object() && in.contains("policy")) ? grid::policy_from_json(in.at("policy"))
                                                   : grid::CornerPolicy::strict;
}

std::vector<grid::Cell> path_of(const Json& in, const char* key) {
  return grid::path_from_json(arg(in, key));
}

std::size_t choice_of(const Json& in, std::size_t n) {
  const long long c = arg_integer(in, "choice");
  require(c >= 0 && static_cast<unsigned long long>(c) < n,
          "choice must index the candidate list (0 <= choice < its size)");
  return static_cast<std::size_t>(c);
}

Json numbers(const std::vector<double>& v) {
  Json out = Json::array();
  for (const double x : v) out.push_back(number(x));
  return out;
}

Json points_json(const std::vector<ga::CrossPoint>& pts) {
  Json out = Json::array();
  for (const auto& p : pts) out.push_back(Json::array({p.k, p.j}));
  return out;
}

const std::vector<Field> plan_inputs = {
    {"grid", "grid", "rows top first, '.' free, '#' blocked"},
    {"start", "cell", "start [x, y], in bounds and free"},
    {"goal", "cell", "goal [x, y], in bounds and free"},
    {"seed", "integer", "seed of the stream, 0 .. 2^32 - 1"},
    {"policy", "string", "corner policy never|strict|one|always (default strict)"},
    {"algo", "string", "the planner (rule-specific default; see spec/shi2022-ga.md)"},
    {"<parameter>", "any", "any parameter of the planner by name (population, generations, ...)"}};

const std::vector<Field> plan_outputs = {
    {"found", "bool", "a path was returned"},
    {"path", "path", "the best path, start..goal ([] when not found)"},
    {"length", "number", "its length"},
    {"iterations", "integer", "ACO iterations + GA generations run"},
    {"best_per_iteration", "number[]", "length of the best-so-far after each iteration"},
    {"mean_per_iteration", "number[]", "mean length of each iteration's paths"},
    {"best_generation", "integer", "GA generation that first held the best (0 = initial)"},
    {"best_origin", "string", "init | aco | crossover | mutation"},
    {"phase", "string", "hybrids: aco | ga, the phase that produced the best"},
    {"draws", "integer", "doubles drawn from the stream"},
    {"failure", "string", "when not found: row_blocked | init_attempts_exhausted | init_all_rejected"},
    {"init_chains", "integer", "chains drawn by the initialisation"},
    {"population_size", "integer", "individuals the generations evolved"},
    {"population_init", "integer", "of them, initialisation paths"},
    {"population_aco", "integer", "of them, ant paths"},
    {"init_built", "integer", "chains repaired into paths"},
    {"init_exhausted", "bool", "the initialisation gave up"}};

Json run_planner(const Json& in, const char* default_algo, const std::set<std::string>& algos) {
  const std::string algo = opt_string(in, "algo", default_algo);
  if (algos.count(algo) == 0) throw UsageError("algo '" + algo + "' is not covered by this rule");
  const planners::Planner* p = planners::find_planner(algo);
  if (p == nullptr) throw UsageError("planner '" + algo + "' is not registered");
  const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
  planners::Request req;
  req.grid = &g;
  req.start = grid::cell_from_json(arg(in, "start"));
  req.goal = grid::cell_from_json(arg(in, "goal"));
  req.policy = (in.is_object() && in.contains("policy")) ? grid::policy_from_json(in.at("policy"))
                                                         : planners::default_policy(algo);
  const long long seed = arg_integer(in, "seed");
  require(seed >= 0 && seed <= 4294967295LL, "seed must lie in [0, 2^32)");
  req.seed = static_cast<std::uint32_t>(seed);
  Json params = Json::object();
  for (const auto& [k, v] : in.items())
    if (k != "grid" && k != "start" && k != "goal" && k != "seed" && k != "policy" && k != "algo")
      params[k] = v;
  req.params = params;
  const planners::Result r = p->run(req);
  Json out{{"found", r.found},
           {"path", grid::path_to_json(r.path)},
           {"length", number(r.length)},
           {"iterations", r.iterations},
           {"best_per_iteration", numbers(r.best_per_iteration)},
           {"mean_per_iteration", numbers(r.mean_per_iteration)}};
  for (const char* k : {"best_generation", "best_origin", "phase", "draws", "failure", "init_chains",
                        "population_size", "population_init", "population_aco", "init_built",
                        "init_exhausted"})
    if (r.extra.contains(k)) out[k] = r.extra.at(k);
  return out;
}

}  // namespace

void register_ga_planner_rules(Registry& r) {
  r.add(Rule{
      "shi2022.op.init",
      "Initial chain repair: drop repeats, insert Eq. 9 mid-points, reject infeasible chains",
      "pathref::ga::connect_chain",
      {{"grid", "grid", "rows top first"},
       {"genes", "path", "start, one gene per row, goal (>= 2 cells, all inside the grid)"},
       {"policy", "string", "corner policy (default strict)"},
       {"mid_rounding", "string", "floor (default) | ceil | half_even"},
       {"init_reject", "string", "shift (default) | blocked | near_obstacle"},
       {"illegal_step", "string", "repair (default) | reject: a corner-cutting continuous pair"}},
      {{"feasible", "bool", "the chain became a valid path"},
       {"path", "path", "the repaired path ([] when rejected)"},
       {"reason", "string", "ok | blocked_gene | blocked_insert | near_obstacle | illegal_step"}},
      [](const Json& in) {
        const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
        const auto genes = path_of(in, "genes");
        const auto rounding = ga::parse_mid_rounding(opt_string(in, "mid_rounding", "floor"));
        const auto rej = ga::parse_init_reject(opt_string(in, "init_reject", "shift"));
        const auto ill = ga::parse_illegal_step(opt_string(in, "illegal_step", "repair"));
        const ga::ChainRepair c = ga::connect_chain(g, genes, policy_of(in), rounding, rej, ill);
        return Json{{"feasible", c.feasible}, {"path", grid::path_to_json(c.path)},
                    {"reason", c.reason}};
      }});
  r.add(Rule{
      "shi2022.op.crossover",
      "Common nodes of two paths and the single-point crossover at one of them (Fig. 3)",
      "pathref::ga::crossover_points, pathref::ga::crossover_at",
      {{"a", "path", "parent a"},
       {"b", "path", "parent b"},
       {"choice", "integer", "optional: index into points (the rng.index result)"}},
      {{"points", "integer[][]", "[k, j] per common interior node, k ascending"},
       {"first", "path", "child a[0..k] ++ b[j+1..] (with choice)"},
       {"second", "path", "child b[0..j] ++ a[k+1..] (with choice)"}},
      [](const Json& in) {
        const auto a = path_of(in, "a");
        const auto b = path_of(in, "b");
        const auto pts = ga::crossover_points(a, b);
        Json out{{"points", points_json(pts)}};
        if (in.contains("choice")) {
          const ga::Children c = ga::crossover_at(a, b, pts.at(choice_of(in, pts.size())));
          out["first"] = grid::path_to_json(c.first);
          out["second"] = grid::path_to_json(c.second);
        }
        return out;
      }});
  r.add(Rule{
      "shi2022.op.mutation",
      "Point mutation of gene k: the cells joining path[k-1] and path[k+1] (Fig. 4)",
      "pathref::ga::mutation_candidates",
      {{"grid", "grid", "rows top first"},
       {"path", "path", "the individual"},
       {"k", "integer", "the interior position 1 <= k <= n - 2"},
       {"policy", "string", "corner policy (default strict)"},
       {"choice", "integer", "optional: index into candidates (the rng.index result)"}},
      {{"candidates", "cell[]", "replacement cells in increasing cell index"},
       {"mutated", "path", "the path with gene k replaced (with choice)"}},
      [](const Json& in) {
        const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
        auto path = path_of(in, "path");
        const long long k = arg_integer(in, "k");
        require(k >= 1, "k must be an interior position");
        const auto cand =
            ga::mutation_candidates(g, path, static_cast<std::size_t>(k), policy_of(in));
        Json out{{"candidates", grid::path_to_json(cand)}};
        if (in.contains("choice")) {
          path[static_cast<std::size_t>(k)] = cand[choice_of(in, cand.size())];
          out["mutated"] = grid::path_to_json(path);
        }
        return out;
      }});
  r.add(Rule{
      "shi2022.op.deletion",
      "Deletion operator: remove p_i when p_{i-1} -> p_{i+1} is an allowed move (Fig. 6)",
      "pathref::ga::delete_redundant",
      {{"grid", "grid", "rows top first"},
       {"path", "path", "any sequence of cells inside the grid"},
       {"policy", "string", "corner policy (default strict)"}},
      {{"path", "path", "the path after deletion"},
       {"removed", "integer", "nodes removed"}},
      [](const Json& in) {
        const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
        const auto path = path_of(in, "path");
        for (const grid::Cell c : path) require(g.in_bounds(c), "a path node lies outside the grid");
        const auto out = ga::delete_redundant(g, path, policy_of(in));
        return Json{{"path", grid::path_to_json(out)},
                    {"removed", static_cast<std::int64_t>(path.size() - out.size())}};
      }});
  r.add(Rule{
      "shi2022.op.loops",
      "Loop removal: cut back to the first visit whenever a cell recurs (option loops = cut)",
      "pathref::ga::remove_loops",
      {{"path", "path", "any sequence of cells"}},
      {{"path", "path", "the path without loops"}, {"removed", "integer", "nodes removed"}},
      [](const Json& in) {
        const auto path = path_of(in, "path");
        const auto out = ga::remove_loops(path);
        return Json{{"path", grid::path_to_json(out)},
                    {"removed", static_cast<std::int64_t>(path.size() - out.size())}};
      }});
  r.add(Rule{
      "shi2022.op.elite",
      "Elite retention: indices of the top count (or top fraction) fitness values, stable",
      "pathref::ga::elite_indices, pathref::ga::elite_count",
      {{"fitness", "number[]", "fitness per individual, population order"},
       {"count", "integer", "how many to keep (or give fraction)"},
       {"fraction", "number", "keep ceil(fraction * n), in (0, 1]"}},
      {{"indices", "integer[]", "kept indices, fitness descending, ties by index"}},
      [](const Json& in) {
        const auto f = arg_numbers(in, "fitness");
        std::size_t count = 0;
        if (in.contains("fraction")) {
          count = ga::elite_count(f.size(), arg_number(in, "fraction"));
        } else {
          const long long c = arg_integer(in, "count");
          require(c >= 0, "count must be >= 0");
          count = static_cast<std::size_t>(c);
        }
        Json out = Json::array();
        for (const std::size_t i : ga::elite_indices(f, count)) out.push_back(i);
        return Json{{"indices", out}};
      }});
  r.add(Rule{"shi2022.plan.ga", "Planner ga: the single GA of Shi Sec. 4.2 (whole run)",
             "pathref::genetic::run, pathref::planners::make_ga_planner", plan_inputs, plan_outputs,
             [](const Json& in) { return run_planner(in, "ga", {"ga"}); }});
  r.add(Rule{"shi2022.plan.iga",
             "Planners iga-shi / iga-shi-nomax: the improved GA of Shi Sec. 4.4.2 (whole run)",
             "pathref::genetic::run, pathref::planners::make_iga_shi_planner", plan_inputs,
             plan_outputs,
             [](const Json& in) { return run_planner(in, "iga-shi", {"iga-shi", "iga-shi-nomax"}); }});
  r.add(Rule{"shi2022.plan.hybrid",
             "Planner hybrid-ga-aco: the traditional GA-ACO hybrid of Shi Sec. 4.3 (whole run)",
             "pathref::hybrid::run_traditional", plan_inputs, plan_outputs,
             [](const Json& in) { return run_planner(in, "hybrid-ga-aco", {"hybrid-ga-aco"}); }});
  r.add(Rule{"shi2022.plan.iha",
             "Planner iha: the improved GA-ACO hybrid of Shi Sec. 4.4.3 (whole run)",
             "pathref::hybrid::run_improved", plan_inputs, plan_outputs,
             [](const Json& in) { return run_planner(in, "iha", {"iha"}); }});
  std::vector<Field> classic_inputs = plan_inputs;
  classic_inputs[4] = {"policy", "string", "corner policy never|strict|one|always (default always)"};
  r.add(Rule{"classic.plan.ga",
             "Planner ga-classic: the classic MATLAB GA grid script's defaults (whole run)",
             "pathref::genetic::run", classic_inputs, plan_outputs,
             [](const Json& in) { return run_planner(in, "ga-classic", {"ga-classic"}); }});
}

}  // namespace pathref::rules
