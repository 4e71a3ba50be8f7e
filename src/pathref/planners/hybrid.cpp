#include "pathref/planners/hybrid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/ga_operators.hpp"

namespace pathref::hybrid {

namespace {

constexpr const char* aco_prefix = "aco_";

const grid::Grid& grid_of(const planners::Request& req) {
  if (req.grid == nullptr) throw UsageError("plan request without a grid");
  return *req.grid;
}

Json prefixed(const Json& p) {
  Json out = Json::object();
  for (const auto& [k, v] : p.items()) out[aco_prefix + k] = v;
  return out;
}

/// Splits merged hybrid parameters: the "aco_" keys (prefix removed) and the rest.
std::pair<Json, Json> split(const Json& params) {
  Json aco = Json::object();
  Json rest = Json::object();
  const std::string pre = aco_prefix;
  for (const auto& [k, v] : params.items()) {
    if (k.rfind(pre, 0) == 0) {
      aco[k.substr(pre.size())] = v;
    } else {
      rest[k] = v;
    }
  }
  return {aco, rest};
}

/// The distinct ant paths, shortest first; ties keep the order of first appearance.
std::vector<const ant_colony::AntPath*> sorted_paths(const ant_colony::Run& r) {
  std::vector<const ant_colony::AntPath*> v;
  v.reserve(r.distinct_paths.size());
  for (const ant_colony::AntPath& p : r.distinct_paths) v.push_back(&p);
  std::stable_sort(v.begin(), v.end(), [](const ant_colony::AntPath* x, const ant_colony::AntPath* y) {
    return x->length < y->length;
  });
  return v;
}

Json aco_summary(const ant_colony::Run& r) {
  return Json{{"found", r.result.found},
              {"best_length", r.result.found ? Json(r.result.length) : Json(nullptr)},
              {"iterations", r.result.iterations},
              {"distinct_paths", r.distinct_paths.size()}};
}

void require_endpoints(const grid::Grid& g, const planners::Request& req) {
  require(g.in_bounds(req.start), "hybrid: start cell outside the grid");
  require(g.in_bounds(req.goal), "hybrid: goal cell outside the grid");
  require(g.free(req.start), "hybrid: start cell is blocked");
  require(g.free(req.goal), "hybrid: goal cell is blocked");
}

/// The result of the GA phase, with the colony's curves in front.
planners::Result finish(const ant_colony::Run& colony, const genetic::Evolution& ev,
                        const genetic::Config& ga, Json population, Json params,
                        rng::Stream& stream) {
  planners::Result r;
  r.found = true;
  r.path = ev.best.path;
  r.length = ev.best.length;
  r.iterations = colony.result.iterations + ga.generations;
  r.best_per_iteration = colony.result.best_per_iteration;
  r.best_per_iteration.insert(r.best_per_iteration.end(), ev.best_per_generation.begin(),
                              ev.best_per_generation.end());
  r.mean_per_iteration = colony.result.mean_per_iteration;
  r.mean_per_iteration.insert(r.mean_per_iteration.end(), ev.mean_per_generation.begin(),
                              ev.mean_per_generation.end());
  r.params_used = std::move(params);
  r.extra = std::move(population);
  r.extra["phase"] = ev.best.origin == genetic::Origin::aco ? "aco" : "ga";
  r.extra["best_origin"] = std::string(genetic::to_string(ev.best.origin));
  r.extra["best_generation"] = ev.best_generation;
  r.extra["best_fitness"] = ev.best.fitness;
  r.extra["phase_iterations"] = Json{{"aco", colony.result.iterations}, {"ga", ga.generations}};
  r.extra["aco"] = aco_summary(colony);
  r.extra["draws"] = stream.doubles_drawn();
  return r;
}

planners::Result trivial(const planners::Request& req, Json params) {
  planners::Result r;
  r.found = true;
  r.path = {req.start};
  r.params_used = std::move(params);
  r.extra = Json{{"phase", "none"}, {"draws", 0}};
  return r;
}

planners::Result not_found(const ant_colony::Run& colony, const genetic::InitOutcome& init,
                           Json params, rng::Stream& stream) {
  planners::Result r;
  r.iterations = colony.result.iterations;
  r.best_per_iteration = colony.result.best_per_iteration;
  r.mean_per_iteration = colony.result.mean_per_iteration;
  r.params_used = std::move(params);
  r.extra = genetic::population_extra(0, 0, 0, init);
  r.extra["failure"] = init.failure;
  r.extra["aco"] = aco_summary(colony);
  r.extra["draws"] = stream.doubles_drawn();
  return r;
}

}  // namespace

Fill parse_fill(std::string_view n) {
  if (n == "repeat") return Fill::repeat;
  if (n == "random") return Fill::random;
  throw UsageError("unknown fill '" + std::string(n) + "' (expected repeat or random)");
}
std::string_view to_string(Fill v) noexcept { return v == Fill::repeat ? "repeat" : "random"; }
DeletionScope parse_deletion_scope(std::string_view n) {
  if (n == "initial") return DeletionScope::initial;
  if (n == "merged") return DeletionScope::merged;
  throw UsageError("unknown deletion_scope '" + std::string(n) + "' (expected initial or merged)");
}
std::string_view to_string(DeletionScope v) noexcept {
  return v == DeletionScope::initial ? "initial" : "merged";
}

Json to_params(const TraditionalConfig& c) {
  Json p = prefixed(ant_colony::to_params(c.aco));
  const Json ga = genetic::to_params(c.ga);
  for (const auto& [k, v] : ga.items()) p[k] = v;
  p["fill"] = std::string(to_string(c.fill));
  return p;
}

Json to_params(const ImprovedConfig& c) {
  Json p = prefixed(ant_colony::to_params(c.aco));
  const Json ga = genetic::to_params(c.ga);
  for (const auto& [k, v] : ga.items()) p[k] = v;
  p["inject"] = c.inject;
  p["deletion_scope"] = std::string(to_string(c.deletion_scope));
  p["elite_fraction"] = c.ga.elite_fraction;
  return p;
}

TraditionalConfig from_params(const TraditionalConfig& base, const Json& params) {
  auto [aco, rest] = split(params);
  TraditionalConfig c = base;
  c.aco = ant_colony::from_params(base.aco, aco);
  if (rest.contains("fill")) {
    c.fill = parse_fill(rest.at("fill").get<std::string>());
    rest.erase("fill");
  }
  c.ga = genetic::from_params(base.ga, rest);
  return c;
}

ImprovedConfig from_params(const ImprovedConfig& base, const Json& params) {
  auto [aco, rest] = split(params);
  ImprovedConfig c = base;
  c.aco = ant_colony::from_params(base.aco, aco);
  if (rest.contains("inject")) {
    c.inject = rest.at("inject").get<std::int64_t>();
    require(c.inject >= 0 && c.inject <= 1000000, "inject must lie in [0, 10^6]");
    rest.erase("inject");
  }
  if (rest.contains("deletion_scope")) {
    c.deletion_scope = parse_deletion_scope(rest.at("deletion_scope").get<std::string>());
    rest.erase("deletion_scope");
  }
  c.ga = genetic::from_params(base.ga, rest);  // elite_fraction is a GA setting
  c.ga.elitist = true;
  return c;
}

Json to_params(const CinConfig& c) {
  Json p = prefixed(ant_colony::to_params(c.aco));
  const Json ga = genetic::to_params(c.ga);
  for (const auto& [k, v] : ga.items()) p[k] = v;
  p["conversion_form"] = std::string(cin::to_string(c.conversion_form));
  p["conversion"] = std::string(ant_colony::to_string(c.conversion));
  p["elite_share"] = c.elite_share;
  return p;
}

CinConfig from_params(const CinConfig& base, const Json& params) {
  auto [aco, rest] = split(params);
  CinConfig c = base;
  c.aco = ant_colony::from_params(base.aco, aco);
  if (rest.contains("conversion_form")) {
    c.conversion_form = cin::parse_conversion_form(rest.at("conversion_form").get<std::string>());
    rest.erase("conversion_form");
  }
  if (rest.contains("conversion")) {
    c.conversion = ant_colony::parse_initial_mode(rest.at("conversion").get<std::string>());
    rest.erase("conversion");
  }
  if (rest.contains("elite_share")) {
    c.elite_share = rest.at("elite_share").get<double>();
    rest.erase("elite_share");
  }
  require(std::isfinite(c.elite_share) && c.elite_share > 0.0 && c.elite_share <= 1.0,
          "elite_share must lie in (0, 1]");
  c.ga = genetic::from_params(base.ga, rest);
  return c;
}

planners::Result run_cin(const planners::Request& req, const CinConfig& c, rng::Stream& stream) {
  const grid::Grid& g = grid_of(req);
  require_endpoints(g, req);
  genetic::validate(c.ga);
  require(std::isfinite(c.elite_share) && c.elite_share > 0.0 && c.elite_share <= 1.0,
          "elite_share must lie in (0, 1]");
  Json params = to_params(c);
  if (req.start == req.goal) return trivial(req, std::move(params));
  // Phase 1: the whole optimised GA (initial population, then the generations).
  const genetic::InitOutcome init =
      genetic::initial_population(g, req.start, req.goal, req.policy, c.ga, stream, c.ga.population);
  if (!init.ok) {
    planners::Result r;
    r.params_used = std::move(params);
    r.extra = genetic::population_extra(0, 0, 0, init);
    r.extra["failure"] = init.failure;
    r.extra["draws"] = stream.doubles_drawn();
    return r;
  }
  std::vector<genetic::Individual> pop;
  pop.reserve(init.paths.size());
  for (const auto& p : init.paths)
    pop.push_back(genetic::make_individual(g, p, c.ga, genetic::Origin::init, 0));
  const auto built = static_cast<std::int64_t>(pop.size());
  Json population = genetic::population_extra(built, built, 0, init);
  genetic::Evolution ev = genetic::evolve(g, req.policy, c.ga, stream, std::move(pop), req.interrupted,
                                       req.max_memory);
  // Conversion (Eq. 28): the top elite_share of the last generation by fitness.
  std::vector<double> fit(ev.final_population.size());
  for (std::size_t s = 0; s < fit.size(); ++s) fit[s] = ev.final_population[s].fitness;
  const std::vector<std::size_t> top =
      ga::elite_indices(fit, ga::elite_count(fit.size(), c.elite_share));
  std::vector<std::vector<grid::Cell>> rows;
  rows.reserve(top.size());
  for (const std::size_t k : top) rows.push_back(ev.final_population[k].path);
  const std::vector<cin::EdgePheromone> tau_g = cin::converted_pheromone(rows, c.aco.Q, c.conversion_form);
  // Phase 2: the optimised colony from the converted pheromone.
  ant_colony::Run colony = ant_colony::run(req, c.aco, stream, tau_g, c.conversion);
  planners::Result r = std::move(colony.result);
  r.iterations = c.ga.generations + c.aco.iterations;
  std::vector<double> best = ev.best_per_generation;
  best.insert(best.end(), r.best_per_iteration.begin(), r.best_per_iteration.end());
  r.best_per_iteration = std::move(best);
  std::vector<double> mean = ev.mean_per_generation;
  mean.insert(mean.end(), r.mean_per_iteration.begin(), r.mean_per_iteration.end());
  r.mean_per_iteration = std::move(mean);
  r.params_used = std::move(params);
  Json extra = std::move(r.extra);
  extra["phase_lengths"] = Json{{"ga", c.ga.generations}, {"aco", c.aco.iterations}};
  extra["ga_best_length"] = ev.best.length;
  extra["ga_best_generation"] = ev.best_generation;
  extra["converted_rows"] = rows.size();
  extra["converted_edges"] = tau_g.size();
  for (auto it = population.begin(); it != population.end(); ++it) extra[it.key()] = it.value();
  extra["draws"] = stream.doubles_drawn();
  r.extra = std::move(extra);
  return r;
}

planners::Result run_traditional(const planners::Request& req, const TraditionalConfig& c,
                                 rng::Stream& stream) {
  const grid::Grid& g = grid_of(req);
  require_endpoints(g, req);
  genetic::validate(c.ga);
  Json params = to_params(c);
  if (req.start == req.goal) return trivial(req, std::move(params));
  // Phase 1: the colony.
  const ant_colony::Run colony = ant_colony::run(req, c.aco, stream);
  // Phase 2: the GA population from the distinct ant paths, shortest first.
  const auto sorted = sorted_paths(colony);
  const auto N = static_cast<std::size_t>(c.ga.population);
  std::vector<genetic::Individual> pop;
  pop.reserve(N);
  for (std::size_t k = 0; k < sorted.size() && pop.size() < N; ++k)
    pop.push_back(genetic::make_individual(g, sorted[k]->path, c.ga, genetic::Origin::aco, 0));
  genetic::InitOutcome init;
  std::int64_t from_init = 0;
  if (pop.size() < N && (c.fill == Fill::random || sorted.empty())) {
    const auto missing = static_cast<std::int64_t>(N - pop.size());
    init = genetic::initial_paths(g, req.start, req.goal, req.policy, c.ga, stream, missing);
    if (init.ok) {
      for (const auto& p : init.paths)
        pop.push_back(genetic::make_individual(g, p, c.ga, genetic::Origin::init, 0));
      from_init = static_cast<std::int64_t>(init.paths.size());
    } else if (sorted.empty()) {
      return not_found(colony, init, std::move(params), stream);
    }
  }
  for (std::size_t k = 0; pop.size() < N; ++k)  // fill = repeat (or random init gave up)
    pop.push_back(pop[k % sorted.size()]);
  const auto size = static_cast<std::int64_t>(pop.size());
  Json population = genetic::population_extra(size, from_init, size - from_init, init);
  const genetic::Evolution ev = genetic::evolve(g, req.policy, c.ga, stream, std::move(pop), req.interrupted,
                                       req.max_memory);
  return finish(colony, ev, c.ga, std::move(population), std::move(params), stream);
}

planners::Result run_improved(const planners::Request& req, const ImprovedConfig& c,
                              rng::Stream& stream) {
  const grid::Grid& g = grid_of(req);
  require_endpoints(g, req);
  genetic::validate(c.ga);
  Json params = to_params(c);
  if (req.start == req.goal) return trivial(req, std::move(params));
  // Steps 1-3: the improved colony; its distinct paths, shortest first.
  const ant_colony::Run colony = ant_colony::run(req, c.aco, stream);
  const auto sorted = sorted_paths(colony);
  const std::size_t K = std::min(sorted.size(), static_cast<std::size_t>(c.inject));
  // Step 4: random initial population, deletion operator, fitness.
  const genetic::InitOutcome init =
      genetic::initial_paths(g, req.start, req.goal, req.policy, c.ga, stream, c.ga.population);
  std::vector<genetic::Individual> initial;
  if (init.ok) {
    initial.reserve(init.paths.size());
    for (const auto& p : init.paths)
      initial.push_back(genetic::make_individual(g, ga::delete_redundant(g, p, req.policy), c.ga,
                                                 genetic::Origin::init, 0));
  } else if (K == 0) {
    return not_found(colony, init, std::move(params), stream);
  }
  // Step 5: the top elite_fraction of the initial population, then the injected ant paths.
  std::vector<double> fit(initial.size());
  for (std::size_t s = 0; s < initial.size(); ++s) fit[s] = initial[s].fitness;
  std::vector<genetic::Individual> pop;
  for (const std::size_t k : ga::elite_indices(fit, ga::elite_count(initial.size(), c.ga.elite_fraction)))
    pop.push_back(initial[k]);
  for (std::size_t k = 0; k < K; ++k) {
    std::vector<grid::Cell> p = sorted[k]->path;
    if (c.deletion_scope == DeletionScope::merged) p = ga::delete_redundant(g, p, req.policy);
    pop.push_back(genetic::make_individual(g, std::move(p), c.ga, genetic::Origin::aco, 0));
  }
  const auto size = static_cast<std::int64_t>(pop.size());
  const auto from_aco = static_cast<std::int64_t>(K);
  Json population = genetic::population_extra(size, size - from_aco, from_aco, init);
  // Steps 6-9: the elitist generation loop.
  const genetic::Evolution ev = genetic::evolve(g, req.policy, c.ga, stream, std::move(pop), req.interrupted,
                                       req.max_memory);
  return finish(colony, ev, c.ga, std::move(population), std::move(params), stream);
}

}  // namespace pathref::hybrid

namespace pathref::planners {

Planner make_hybrid_ga_aco_planner() {
  Planner p;
  p.name = "hybrid-ga-aco";
  p.description =
      "traditional GA-ACO hybrid (Shi et al. 2022 Sec. 4.3, Fig. 5; Bao et al. 2021): Ant System, "
      "then a GA seeded with the ant paths, spec/shi2022-ga.md";
  const hybrid::TraditionalConfig base;
  p.defaults = hybrid::to_params(base);
  p.bytes_per_cell = ant_colony::bytes_per_cell;  // the colony's per-cell state; the GA's is less
  p.run = [defaults = p.defaults, base](const Request& req) {
    const Json params = merge_params(defaults, req.params);
    const hybrid::TraditionalConfig c = hybrid::from_params(base, params);
    rng::Stream stream(req.seed);
    stream.set_trace(req.trace);
    return hybrid::run_traditional(req, c, stream);
  };
  return p;
}

Planner make_hga_aco_cin_planner() {
  Planner p;
  p.name = "hga-aco-cin";
  p.description =
      "HGA-ACO of cin2021 Sec. 5 (optimised GA, Eq. 28 pheromone conversion, optimised ACO with "
      "weighted best deposits and the dead-angle table), spec/cin2021-hga-aco.md";
  const hybrid::CinConfig base;
  p.defaults = hybrid::to_params(base);
  p.bytes_per_cell = ant_colony::bytes_per_cell;  // the colony's per-cell state; the GA's is less
  p.run = [defaults = p.defaults, base](const Request& req) {
    const Json params = merge_params(defaults, req.params);
    const hybrid::CinConfig c = hybrid::from_params(base, params);
    rng::Stream stream(req.seed);
    stream.set_trace(req.trace);
    planners::Result r = hybrid::run_cin(req, c, stream);
    r.extra["seed"] = req.seed;
    return r;
  };
  return p;
}

Planner make_iha_planner() {
  Planner p;
  p.name = "iha";
  p.description =
      "improved GA-ACO hybrid IHA (Shi et al. 2022 Sec. 4.4.3 steps 1-9: IACO paths injected, "
      "deletion operator, elite retention, adaptive Pc/Pm), spec/shi2022-ga.md";
  const hybrid::ImprovedConfig base;
  p.defaults = hybrid::to_params(base);
  p.bytes_per_cell = ant_colony::bytes_per_cell;  // the colony's per-cell state; the GA's is less
  p.run = [defaults = p.defaults, base](const Request& req) {
    const Json params = merge_params(defaults, req.params);
    const hybrid::ImprovedConfig c = hybrid::from_params(base, params);
    rng::Stream stream(req.seed);
    stream.set_trace(req.trace);
    return hybrid::run_improved(req, c, stream);
  };
  return p;
}

}  // namespace pathref::planners
