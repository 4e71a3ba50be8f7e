#include "pathref/planners/genetic.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <utility>

#include "pathref/core/error.hpp"
#include "pathref/core/memory.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/rng/draws.hpp"

namespace pathref::genetic {

namespace {

[[noreturn]] void unknown(const char* what, std::string_view name, const char* expected) {
  throw UsageError(std::string("unknown ") + what + " '" + std::string(name) + "' (expected " +
                   expected + ")");
}

std::string_view name_of(ga::SmoothnessReading v) {
  switch (v) {
    case ga::SmoothnessReading::per_node: return "per_node";
    case ga::SmoothnessReading::per_turn: return "per_turn";
    case ga::SmoothnessReading::angle_times_penalty: return "angle_times_penalty";
    case ga::SmoothnessReading::inverse_total: return "inverse_total";
    case ga::SmoothnessReading::inverse_total_plus_one: return "inverse_total_plus_one";
  }
  return "?";
}
std::string_view name_of(ga::SafetyCount v) { return v == ga::SafetyCount::count ? "count" : "indicator"; }
std::string_view name_of(ga::SafetyAggregate v) {
  switch (v) {
    case ga::SafetyAggregate::inverse_total_plus_one:
      return "inverse_total_plus_one";
    case ga::SafetyAggregate::per_node:
      return "per_node";
    case ga::SafetyAggregate::mean:
      return "mean";
  }
  return "?";
}
std::string_view name_of(ga::SafeNode v) { return v == ga::SafeNode::one ? "one" : "skip"; }
std::string_view name_of(ga::SafetyNodes v) {
  switch (v) {
    case ga::SafetyNodes::all_but_goal: return "all_but_goal";
    case ga::SafetyNodes::all: return "all";
    case ga::SafetyNodes::interior: return "interior";
  }
  return "?";
}
std::string_view name_of(metrics::OutsideCells v) {
  return v == metrics::OutsideCells::free ? "free" : "blocked";
}
std::string_view name_of(ga::MidRounding v) {
  switch (v) {
    case ga::MidRounding::floor: return "floor";
    case ga::MidRounding::ceil: return "ceil";
    case ga::MidRounding::half_even: return "half_even";
  }
  return "?";
}
std::string_view name_of(ga::PmAtZero v) {
  return v == ga::PmAtZero::binary64 ? "binary64" : "exact_zero";
}

const grid::Grid& grid_of(const planners::Request& req) {
  if (req.grid == nullptr) throw UsageError("plan request without a grid");
  return *req.grid;
}

/// True iff candidate x is strictly better than incumbent y under result_by.
bool better(const Individual& x, const Individual& y, ResultBy by) {
  return by == ResultBy::fitness ? x.fitness > y.fitness : x.length < y.length;
}

}  // namespace

Crossover parse_crossover(std::string_view n) {
  if (n == "common_gene") return Crossover::common_gene;
  if (n == "cin") return Crossover::cin;
  throw UsageError("unknown crossover '" + std::string(n) + "' (expected common_gene or cin)");
}
std::string_view to_string(Crossover v) noexcept { return v == Crossover::common_gene ? "common_gene" : "cin"; }
Init parse_init(std::string_view n) {
  if (n == "rows") return Init::rows;
  if (n == "walk") return Init::walk;
  throw UsageError("unknown init '" + std::string(n) + "' (expected rows or walk)");
}
std::string_view to_string(Init v) noexcept { return v == Init::rows ? "rows" : "walk"; }

Fitness parse_fitness(std::string_view n) {
  if (n == "inverse_length") return Fitness::inverse_length;
  if (n == "weighted") return Fitness::weighted;
  if (n == "cin") return Fitness::cin;
  unknown("fitness", n, "inverse_length, weighted or cin");
}
std::string_view to_string(Fitness v) noexcept {
  switch (v) {
    case Fitness::inverse_length: return "inverse_length";
    case Fitness::weighted: return "weighted";
    case Fitness::cin: return "cin";
  }
  return "?";
}
Probabilities parse_probabilities(std::string_view n) {
  if (n == "fixed") return Probabilities::fixed;
  if (n == "adaptive") return Probabilities::adaptive;
  unknown("ga_probabilities", n, "adaptive or fixed");
}
std::string_view to_string(Probabilities v) noexcept {
  return v == Probabilities::fixed ? "fixed" : "adaptive";
}
Scale parse_scale(std::string_view n) {
  if (n == "printed") return Scale::printed;
  if (n == "scaled") return Scale::scaled;
  unknown("pc_reading/pm_reading", n, "printed or scaled");
}
std::string_view to_string(Scale v) noexcept { return v == Scale::printed ? "printed" : "scaled"; }
CrossoverKeep parse_crossover_keep(std::string_view n) {
  if (n == "children") return CrossoverKeep::children;
  if (n == "best_two") return CrossoverKeep::best_two;
  if (n == "best_two_fitness") return CrossoverKeep::best_two_fitness;
  unknown("crossover_keep", n, "children, best_two or best_two_fitness");
}
std::string_view to_string(CrossoverKeep v) noexcept {
  switch (v) {
    case CrossoverKeep::children: return "children";
    case CrossoverKeep::best_two: return "best_two";
    case CrossoverKeep::best_two_fitness: return "best_two_fitness";
  }
  return "?";
}
Loops parse_loops(std::string_view n) {
  if (n == "keep") return Loops::keep;
  if (n == "cut") return Loops::cut;
  unknown("loops", n, "keep or cut");
}
std::string_view to_string(Loops v) noexcept { return v == Loops::keep ? "keep" : "cut"; }
ResultBy parse_result_by(std::string_view n) {
  if (n == "fitness") return ResultBy::fitness;
  if (n == "length") return ResultBy::length;
  unknown("result_by", n, "fitness or length");
}
std::string_view to_string(ResultBy v) noexcept { return v == ResultBy::fitness ? "fitness" : "length"; }
std::string_view to_string(Origin v) noexcept {
  switch (v) {
    case Origin::init: return "init";
    case Origin::aco: return "aco";
    case Origin::crossover: return "crossover";
    case Origin::mutation: return "mutation";
  }
  return "?";
}

InitRetry parse_init_retry(std::string_view n) {
  if (n == "per_individual") return InitRetry::per_individual;
  if (n == "none") return InitRetry::none;
  unknown("init_retry", n, "per_individual or none");
}
std::string_view to_string(InitRetry v) noexcept {
  return v == InitRetry::per_individual ? "per_individual" : "none";
}
Selection parse_selection(std::string_view n) {
  if (n == "independent") return Selection::independent;
  if (n == "sorted") return Selection::sorted;
  unknown("selection", n, "independent or sorted");
}
std::string_view to_string(Selection v) noexcept {
  return v == Selection::independent ? "independent" : "sorted";
}
CrossoverPoints parse_crossover_points(std::string_view n) {
  if (n == "interior") return CrossoverPoints::interior;
  if (n == "script") return CrossoverPoints::script;
  unknown("crossover_points", n, "interior or script");
}
std::string_view to_string(CrossoverPoints v) noexcept {
  return v == CrossoverPoints::interior ? "interior" : "script";
}
Mutation parse_mutation(std::string_view n) {
  if (n == "point") return Mutation::point;
  if (n == "multidirectional") return Mutation::multidirectional;
  if (n == "segment") return Mutation::segment;
  unknown("mutation", n, "point, multidirectional or segment");
}
std::string_view to_string(Mutation v) noexcept {
  switch (v) {
    case Mutation::point: return "point";
    case Mutation::multidirectional: return "multidirectional";
    case Mutation::segment: return "segment";
  }
  return "point";
}

Config shi_ga() { return Config{}; }

Config classic_ga() {
  Config c;
  c.population = 200;
  c.generations = 50;
  c.pc = 0.8;
  c.pm = 0.2;
  c.fitness = Fitness::weighted;
  c.weights = ga::FitnessWeights{1.0, 1.0, 0.0};
  c.smoothness = ga::SmoothnessReading::inverse_total;
  c.penalties = ga::TurnPenalties{3.0, 15.0, 20.0};
  c.probabilities = Probabilities::fixed;
  c.init_reject = ga::InitReject::shift;
  c.init_retry = InitRetry::none;
  c.selection = Selection::sorted;
  c.crossover_points = CrossoverPoints::script;
  c.mutation = Mutation::segment;
  c.crossover_keep = CrossoverKeep::children;
  c.loops = Loops::keep;
  c.result_by = ResultBy::fitness;
  return c;
}

Config shi_iga() {
  Config c;
  c.fitness = Fitness::weighted;
  c.probabilities = Probabilities::adaptive;
  // spec shi2022-ga.md, Loops: under the weighted fitness a path with more nodes scores higher,
  // and with `keep` crossover children grow without bound (iga-shi seed 47 on map C exhausted
  // 22 GB). `cut` keeps every child a simple path, so the planner runs on the paper's maps.
  c.loops = Loops::cut;
  return c;
}

Config shi_iga_nomax() {
  Config c = shi_iga();
  c.pm_max = 1.0;
  return c;
}

Config cin_ga() {
  Config c;
  c.population = 50;
  c.generations = 50;
  c.fitness = Fitness::cin;
  c.weights = ga::FitnessWeights{1.0, 0.1, 0.0};
  c.pc = 0.8;
  c.pm = 0.2;
  c.init = Init::walk;
  c.crossover = Crossover::cin;
  c.crossover_keep = CrossoverKeep::best_two_fitness;
  c.mutation = Mutation::multidirectional;
  c.research = ga::Research::greedy;
  c.loops = Loops::cut;
  c.result_by = ResultBy::fitness;
  // Pinned to the chain-repair readings ga-cin was specified and characterised with (the Shi
  // planners' defaults shift / repair / inverse_total_plus_one of issue 11 are not cin2021's).
  c.init_reject = ga::InitReject::blocked;
  c.illegal_step = ga::IllegalStep::reject;
  c.smoothness = ga::SmoothnessReading::per_node;
  return c;
}

namespace {
bool uses_cin_options(const Config& c) {
  return c.fitness == Fitness::cin || c.crossover != Crossover::common_gene || c.init != Init::rows ||
         c.mutation == Mutation::multidirectional || c.crossover_keep == CrossoverKeep::best_two_fitness;
}
}  // namespace

Json to_params(const Config& c) {
  Json p = Json{
      {"population", c.population},
      {"generations", c.generations},
      {"fitness", std::string(to_string(c.fitness))},
      {"a", c.weights.a},
      {"b", c.weights.b},
      {"c", c.weights.c},
      {"smoothness", std::string(name_of(c.smoothness))},
      {"penalties", Json::array({c.penalties.up_to_45, c.penalties.up_to_90, c.penalties.above_90})},
      {"safety_aggregate", std::string(name_of(c.safety.aggregate))},
      {"safety_count", std::string(name_of(c.safety.count))},
      {"safe_node", std::string(name_of(c.safety.safe))},
      {"safety_nodes", std::string(name_of(c.safety.nodes))},
      {"outside", std::string(name_of(c.safety.outside))},
      {"ga_probabilities", std::string(to_string(c.probabilities))},
      {"pc", c.pc},
      {"pm", c.pm},
      {"pm_max", c.pm_max},
      {"pc_reading", std::string(to_string(c.pc_reading))},
      {"pm_reading", std::string(to_string(c.pm_reading))},
      {"pm_at_zero", std::string(name_of(c.pm_at_zero))},
      {"ga_i_origin", c.ga_i_origin},
      {"duplicate_gene", "drop"},
      {"mid_rounding", std::string(name_of(c.mid_rounding))},
      {"init_reject", std::string(ga::to_string(c.init_reject))},
      {"init_attempts", c.init_attempts},
      {"illegal_step", std::string(ga::to_string(c.illegal_step))},
      {"crossover_keep", std::string(to_string(c.crossover_keep))},
      {"loops", std::string(to_string(c.loops))},
      {"result_by", std::string(to_string(c.result_by))},
      {"init_retry", std::string(to_string(c.init_retry))},
      {"selection", std::string(to_string(c.selection))},
      {"crossover_points", std::string(to_string(c.crossover_points))},
      {"mutation", std::string(to_string(c.mutation))},
      {"mutation_attempts", c.mutation_attempts},
  };
  if (uses_cin_options(c)) {
    p["init"] = std::string(to_string(c.init));
    p["crossover"] = std::string(to_string(c.crossover));
    p["mutation"] = std::string(to_string(c.mutation));
    p["research"] = std::string(ga::to_string(c.research));
    p["corner_penalties"] =
        Json::array({c.corner_penalties.c135, c.corner_penalties.c90, c.corner_penalties.c45});
    p["f2_guard"] = std::string(cin::to_string(c.f2_guard));
    p["angle"] = std::string(cin::to_string(c.angle));
  }
  return p;
}

void validate(const Config& c) {
  require(c.population >= 2 && c.population <= 1000000, "population must lie in [2, 10^6]");
  require(c.generations >= 1 && c.generations <= 1000000, "generations must lie in [1, 10^6]");
  for (const double w : {c.weights.a, c.weights.b, c.weights.c})
    require(std::isfinite(w) && w >= 0.0, "the weights a, b, c must be finite and >= 0");
  for (const double p : {c.penalties.up_to_45, c.penalties.up_to_90, c.penalties.above_90})
    require(std::isfinite(p) && p > 0.0, "penalties must be finite and > 0");
  require(std::isfinite(c.pc) && c.pc >= 0.0 && c.pc <= 1.0, "pc must lie in [0, 1]");
  require(std::isfinite(c.pm) && c.pm >= 0.0 && c.pm <= 1.0, "pm must lie in [0, 1]");
  require(std::isfinite(c.pm_max) && c.pm_max > 0.0 && c.pm_max <= 1.0, "pm_max must lie in (0, 1]");
  if (c.probabilities == Probabilities::adaptive) {
    if (c.pc_reading == Scale::scaled) require(c.pc > 0.0, "pc_reading=scaled needs pc > 0");
    if (c.pm_reading == Scale::scaled) require(c.pm > 0.0, "pm_reading=scaled needs pm > 0");
  }
  require(c.ga_i_origin == 0 || c.ga_i_origin == 1, "ga_i_origin must be 0 or 1");
  require(c.init_attempts >= 1 && c.init_attempts <= 100000000, "init_attempts must lie in [1, 10^8]");
  require(std::isfinite(c.elite_fraction) && c.elite_fraction > 0.0 && c.elite_fraction <= 1.0,
          "elite_fraction must lie in (0, 1]");
  require(c.mutation_attempts >= 1 && c.mutation_attempts <= 100000000,
          "mutation_attempts must lie in [1, 10^8]");
  static_cast<void>(cin::corner_penalty(180.0, c.corner_penalties));  // cin2021.eq24's domain
}

Config from_params(const Config& base, const Json& p) {
  Config c = base;
  auto str = [&](const char* k) { return p.at(k).get<std::string>(); };
  auto num = [&](const char* k) { return p.at(k).get<double>(); };
  auto integer = [&](const char* k) { return p.at(k).get<std::int64_t>(); };
  if (p.contains("population")) c.population = integer("population");
  if (p.contains("generations")) c.generations = integer("generations");
  if (p.contains("fitness")) c.fitness = parse_fitness(str("fitness"));
  if (p.contains("a")) c.weights.a = num("a");
  if (p.contains("b")) c.weights.b = num("b");
  if (p.contains("c")) c.weights.c = num("c");
  if (p.contains("smoothness")) c.smoothness = ga::parse_smoothness_reading(str("smoothness"));
  if (p.contains("penalties")) {
    const Json& v = p.at("penalties");
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() ||
        !v[2].is_number())
      throw UsageError("penalties must be an array of three numbers [P45, P90, P180]");
    c.penalties = ga::TurnPenalties{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
  }
  if (p.contains("safety_aggregate")) c.safety.aggregate = ga::parse_safety_aggregate(str("safety_aggregate"));
  if (p.contains("safety_count")) c.safety.count = ga::parse_safety_count(str("safety_count"));
  if (p.contains("safe_node")) c.safety.safe = ga::parse_safe_node(str("safe_node"));
  if (p.contains("safety_nodes")) c.safety.nodes = ga::parse_safety_nodes(str("safety_nodes"));
  if (p.contains("outside")) c.safety.outside = metrics::parse_outside_cells(str("outside"));
  if (p.contains("ga_probabilities")) c.probabilities = parse_probabilities(str("ga_probabilities"));
  if (p.contains("pc")) c.pc = num("pc");
  if (p.contains("pm")) c.pm = num("pm");
  if (p.contains("pm_max")) c.pm_max = num("pm_max");
  if (p.contains("pc_reading")) c.pc_reading = parse_scale(str("pc_reading"));
  if (p.contains("pm_reading")) c.pm_reading = parse_scale(str("pm_reading"));
  if (p.contains("pm_at_zero")) c.pm_at_zero = ga::parse_pm_at_zero(str("pm_at_zero"));
  if (p.contains("ga_i_origin")) {
    const std::int64_t o = integer("ga_i_origin");
    require(o == 0 || o == 1, "ga_i_origin must be 0 or 1");
    c.ga_i_origin = static_cast<int>(o);
  }
  if (p.contains("duplicate_gene") && str("duplicate_gene") != "drop")
    throw UsageError("unknown duplicate_gene '" + str("duplicate_gene") + "' (expected drop)");
  if (p.contains("mid_rounding")) c.mid_rounding = ga::parse_mid_rounding(str("mid_rounding"));
  if (p.contains("init_reject")) c.init_reject = ga::parse_init_reject(str("init_reject"));
  if (p.contains("init_attempts")) c.init_attempts = integer("init_attempts");
  if (p.contains("illegal_step")) c.illegal_step = ga::parse_illegal_step(str("illegal_step"));
  if (p.contains("crossover_keep")) c.crossover_keep = parse_crossover_keep(str("crossover_keep"));
  if (p.contains("loops")) c.loops = parse_loops(str("loops"));
  if (p.contains("result_by")) c.result_by = parse_result_by(str("result_by"));
  if (p.contains("elite_fraction")) c.elite_fraction = num("elite_fraction");
  if (p.contains("init_retry")) c.init_retry = parse_init_retry(str("init_retry"));
  if (p.contains("selection")) c.selection = parse_selection(str("selection"));
  if (p.contains("crossover_points")) c.crossover_points = parse_crossover_points(str("crossover_points"));
  if (p.contains("mutation")) c.mutation = parse_mutation(str("mutation"));
  if (p.contains("mutation_attempts")) c.mutation_attempts = integer("mutation_attempts");
  if (p.contains("init")) c.init = parse_init(str("init"));
  if (p.contains("crossover")) c.crossover = parse_crossover(str("crossover"));
  if (p.contains("research")) c.research = ga::parse_research(str("research"));
  if (p.contains("corner_penalties")) {
    const Json& v = p.at("corner_penalties");
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() ||
        !v[2].is_number())
      throw UsageError("corner_penalties must be an array of three numbers [c135, c90, c45]");
    c.corner_penalties = cin::CornerPenalties{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
  }
  if (p.contains("f2_guard")) c.f2_guard = cin::parse_f2_guard(str("f2_guard"));
  if (p.contains("angle")) c.angle = cin::parse_angle_reading(str("angle"));
  validate(c);
  return c;
}

double fitness_of(const grid::Grid& g, std::span<const grid::Cell> path, const Config& c) {
  require(path.size() >= 2, "a path of one node has no fitness");
  const double f1 = ga::inverse_length(metrics::path_length(path));
  if (c.fitness == Fitness::inverse_length) return f1;
  if (c.fitness == Fitness::cin) {
    // cin2021 Eq. 26 = shi2022.eq14 with c = 0 (one function, ga::weighted_fitness)
    const double f2 = cin::smoothness_fitness(path, c.corner_penalties, c.f2_guard, c.angle);
    return ga::weighted_fitness(f1, f2, 0.0, ga::FitnessWeights{c.weights.a, c.weights.b, 0.0});
  }
  const double f2 = ga::smoothness_factor(path, c.smoothness, c.penalties);
  const double f3 = ga::safety_factor(g, path, c.safety);
  return ga::weighted_fitness(f1, f2, f3, c.weights);
}

Individual make_individual(const grid::Grid& g, std::vector<grid::Cell> path, const Config& c,
                           Origin origin, std::int64_t born) {
  Individual ind;
  ind.length = metrics::path_length(path);
  ind.fitness = fitness_of(g, path, c);
  ind.path = std::move(path);
  ind.origin = origin;
  ind.born = born;
  return ind;
}

namespace {

/// The outcome of every pair of consecutive genes of the initialisation's chains, computed on
/// first use (spec shi2022.plan.ga, "Evaluation"). Level 0 is {S}, levels 1..R the free cells of
/// the rows between, level R + 1 is {E}; the entry of (level l, cell i) -> (level l + 1, cell j)
/// is connect_chain_into's verdict on the two-gene chain [i, j]: rejected, or feasible with s
/// shifts. A chain is feasible iff each of its pairs is and the shifts add up to at most W * H.
class PairVerdicts {
 public:
  static constexpr std::int32_t unknown = -2;
  static constexpr std::int32_t rejected = -1;

  /// Dense table when it has at most `max_entries` entries; otherwise enabled() is false.
  PairVerdicts(const std::vector<std::vector<grid::Cell>>& levels, std::int64_t max_entries)
      : levels_(levels) {
    std::int64_t total = 0;
    for (std::size_t l = 0; l + 1 < levels.size(); ++l) {
      offset_.push_back(total);
      total += static_cast<std::int64_t>(levels[l].size()) *
               static_cast<std::int64_t>(levels[l + 1].size());
      if (total > max_entries) {
        offset_.clear();
        return;
      }
    }
    verdict_.assign(static_cast<std::size_t>(total), unknown);
    enabled_ = true;
  }

  [[nodiscard]] bool enabled() const noexcept { return enabled_; }

  /// The verdict of pair (l, i) -> (l + 1, j): rejected, or the shifts of its repair.
  std::int32_t get(const grid::Grid& g, grid::CornerPolicy policy, const Config& c, std::size_t l,
                   std::size_t i, std::size_t j) {
    const auto e = static_cast<std::size_t>(offset_[l]) + i * levels_[l + 1].size() + j;
    std::int32_t& v = verdict_[e];
    if (v == unknown) {
      const grid::Cell pair[2] = {levels_[l][i], levels_[l + 1][j]};
      std::int64_t shifts = 0;
      const bool ok = ga::connect_chain_into(g, pair, policy, c.mid_rounding, c.init_reject,
                                             c.illegal_step, scratch_, shifts) == "ok";
      // ok implies shifts <= W * H <= 2^28 (else "insert_limit"), so it fits.
      v = ok ? static_cast<std::int32_t>(shifts) : rejected;
    }
    return v;
  }

 private:
  const std::vector<std::vector<grid::Cell>>& levels_;
  std::vector<std::int64_t> offset_;
  std::vector<std::int32_t> verdict_;
  std::vector<grid::Cell> scratch_;
  bool enabled_ = false;
};

}  // namespace

std::pair<Individual, Individual> keep_two(Individual a, Individual b, Individual c1, Individual c2,
                                          CrossoverKeep by) {
  if (by == CrossoverKeep::children) return {std::move(c1), std::move(c2)};
  std::vector<Individual> four;
  four.reserve(4);
  four.push_back(std::move(a));
  four.push_back(std::move(b));
  four.push_back(std::move(c1));
  four.push_back(std::move(c2));
  if (by == CrossoverKeep::best_two_fitness)
    std::stable_sort(four.begin(), four.end(),
                     [](const Individual& x, const Individual& y) { return x.fitness > y.fitness; });
  else
    std::stable_sort(four.begin(), four.end(),
                     [](const Individual& x, const Individual& y) { return x.length < y.length; });
  return {std::move(four[0]), std::move(four[1])};
}

InitOutcome initial_paths(const grid::Grid& g, grid::Cell start, grid::Cell goal,
                          grid::CornerPolicy policy, const Config& c, rng::Stream& stream,
                          std::int64_t count) {
  require(g.in_bounds(start) && g.in_bounds(goal), "GA: start or goal outside the grid");
  require(g.free(start) && g.free(goal), "GA: start or goal blocked");
  require(!(start == goal), "GA: start == goal has no initial chain");
  InitOutcome out;
  // The levels of a chain: S, the free cells of each row strictly between start and goal (from
  // the start's side, x ascending; spec "Initialisation"), E.
  std::vector<std::vector<grid::Cell>> levels{{start}};
  const std::int64_t step = goal.y > start.y ? 1 : -1;
  if (goal.y != start.y)
    for (std::int64_t y = start.y + step; y != goal.y; y += step) {
      std::vector<grid::Cell>& row = levels.emplace_back();
      for (std::int64_t x = 0; x < g.width(); ++x)
        if (g.free(grid::Cell{x, y})) row.push_back(grid::Cell{x, y});
      if (row.empty()) {
        out.failure = "row_blocked";
        return out;
      }
    }
  levels.push_back({goal});
  const std::size_t L = levels.size();
  PairVerdicts verdicts(levels, init_verdict_max_entries);
  std::vector<std::size_t> pick(L, 0);  // the chosen cell of each level (S and E: 0)
  std::vector<grid::Cell> genes(L);
  std::vector<grid::Cell> chain;  // connect_chain_into's buffer, reused by every chain
  for (std::int64_t a = 0; a < count; ++a) {
    bool done = false;
    const std::int64_t attempts = c.init_retry == InitRetry::none ? 1 : c.init_attempts;
    for (std::int64_t attempt = 0; attempt < attempts && !done; ++attempt) {
      if (stream.tracing()) stream.set_context(fmt::format("initial chain {} attempt {}", a, attempt));
      for (std::size_t l = 1; l + 1 < L; ++l)
        pick[l] = rng::uniform_index(stream.next_double("ga initial chain: a free cell of the level (rng.index)"), levels[l].size());
      ++out.chains;
      bool feasible = true;
      if (verdicts.enabled()) {
        std::int64_t shifts = 0;
        for (std::size_t l = 0; l + 1 < L && feasible; ++l) {
          const std::int32_t v = verdicts.get(g, policy, c, l, pick[l], pick[l + 1]);
          if (v == PairVerdicts::rejected)
            feasible = false;
          else
            shifts += v;
        }
        feasible = feasible && shifts <= g.cell_count();
      }
      if (!feasible) continue;
      for (std::size_t l = 0; l < L; ++l) genes[l] = levels[l][pick[l]];
      const std::string_view reason =
          ga::connect_chain_into(g, genes, policy, c.mid_rounding, c.init_reject, c.illegal_step,
                                 chain);
      if (reason == "ok") {
        out.paths.push_back(chain);
        done = true;
      } else if (verdicts.enabled()) {
        throw std::logic_error("GA initialisation: the pair verdicts accepted a chain that "
                               "connect_chain rejects (" + std::string(reason) + ")");
      }
    }
    if (!done && c.init_retry == InitRetry::per_individual) {
      out.failure = "init_attempts_exhausted";
      return out;
    }
  }
  if (out.paths.empty()) {  // init_retry = none and every chain rejected
    out.failure = "init_all_rejected";
    return out;
  }
  out.ok = true;
  return out;
}

Json population_extra(std::int64_t size, std::int64_t from_init, std::int64_t from_aco,
                      const InitOutcome& init) {
  return Json{{"population_size", size},
              {"population_init", from_init},
              {"population_aco", from_aco},
              {"init_built", static_cast<std::int64_t>(init.paths.size())},
              {"init_exhausted", init.failure == "init_attempts_exhausted"},
              {"init_chains", init.chains}};
}

InitOutcome initial_walks(const grid::Grid& g, grid::Cell start, grid::Cell goal,
                          grid::CornerPolicy policy, rng::Stream& stream, std::int64_t count) {
  require(g.in_bounds(start) && g.in_bounds(goal), "GA: start or goal outside the grid");
  require(g.free(start) && g.free(goal), "GA: start or goal blocked");
  require(!(start == goal), "GA: start == goal has no initial walk");
  InitOutcome out;
  for (std::int64_t a = 0; a < count; ++a) {
    ga::Walk w = ga::research_walk(g, start, goal, {}, policy, ga::Research::random, stream, true);
    ++out.chains;
    if (!w.ok) {
      out.failure = "unreachable";
      return out;
    }
    out.paths.push_back(std::move(w.cells));
  }
  out.ok = true;
  return out;
}

InitOutcome initial_population(const grid::Grid& g, grid::Cell start, grid::Cell goal,
                               grid::CornerPolicy policy, const Config& c, rng::Stream& stream,
                               std::int64_t count) {
  return c.init == Init::walk ? initial_walks(g, start, goal, policy, stream, count)
                              : initial_paths(g, start, goal, policy, c, stream, count);
}

std::uint64_t memory_estimate(std::int64_t cells, std::span<const Individual> a, std::span<const Individual> b) {
  std::uint64_t need = memory::times(static_cast<std::uint64_t>(cells < 0 ? 0 : cells), bytes_per_cell);
  for (const auto* v : {&a, &b})
    for (const Individual& ind : *v) need = memory::plus(need, memory::times(ind.path.capacity(), bytes_per_path_cell));
  return need;
}

void memory_check(const grid::Grid& g, std::span<const Individual> a, std::span<const Individual> b,
                  std::uint64_t max_memory, std::string_view when) {
  const std::uint64_t need = memory_estimate(g.cell_count(), a, b);
  if (need <= max_memory) return;
  memory::require_within(need, max_memory,
                         fmt::format("the GA on a {}x{} grid, with its stored paths {}", g.width(), g.height(), when));
}

Evolution evolve(const grid::Grid& g, grid::CornerPolicy policy, const Config& c,
                 rng::Stream& stream, std::vector<Individual> pop, const planners::Interrupt& interrupted,
                 std::uint64_t max_memory) {
  require(!pop.empty(), "GA: empty population");
  Evolution ev;
  ev.best = pop.front();
  for (const Individual& ind : pop)
    if (better(ind, ev.best, c.result_by)) ev.best = ind;
  const std::size_t S = pop.size();
  std::vector<double> fit(S);
  std::vector<Individual> pool;
  pool.reserve(S);
  for (std::int64_t i = 1; i <= c.generations; ++i) {
    planners::stop_if_interrupted(interrupted);
    // Probabilities of this generation (Table 1 or Eq. 19-20).
    double pc = c.pc;
    double pm = c.pm;
    if (c.probabilities == Probabilities::adaptive) {
      const std::int64_t ii = c.ga_i_origin == 1 ? i : i - 1;
      pc = ga::adaptive_pc(ii, c.generations, c.pc_reading == Scale::scaled ? c.pc : 1.0);
      pm = ga::adaptive_pm(ii, c.generations, c.pm_max, c.pm_reading == Scale::scaled ? c.pm : 1.0,
                           c.pm_at_zero);
    }
    // Step 2: roulette selection (Eq. 11), S draws.
    for (std::size_t s = 0; s < S; ++s) fit[s] = pop[s].fitness;
    pool.clear();
    if (stream.tracing()) stream.set_context(fmt::format("generation {} selection", i));
    if (c.selection == Selection::independent) {
      for (std::size_t s = 0; s < S; ++s) pool.push_back(pop[rng::roulette(fit, stream.next_double("ga selection roulette (rng.roulette)"))]);
    } else {  // sorted: S draws, ascending, then the roulette of each (the classic script)
      std::vector<double> us(S);
      for (double& u : us) u = stream.next_double("ga selection roulette, sorted draws (rng.roulette)");
      std::sort(us.begin(), us.end());
      for (const double u : us) pool.push_back(pop[rng::roulette(fit, u)]);
    }
    // Step 3: crossover of the pairs (2p, 2p + 1).
    for (std::size_t p = 0; p + 1 < S; p += 2) {
      if (stream.tracing()) stream.set_context(fmt::format("generation {} pair {}", i, p / 2));
      if (!rng::bernoulli(stream.next_double("ga crossover test u < pc (rng.bernoulli)"), pc)) continue;
      const bool script = c.crossover_points == CrossoverPoints::script;
      const std::vector<ga::CrossPoint> pts =
          script ? ga::crossover_points_any(pool[p].path, pool[p + 1].path)
                 : ga::crossover_points(pool[p].path, pool[p + 1].path);
      ga::Children ch;
      if (!pts.empty()) {
        const double u = stream.next_double("ga crossover point");
        const ga::CrossPoint pt = pts[script ? ga::round_choice(u, pts.size())
                                             : rng::uniform_index(u, pts.size())];
        ch = ga::crossover_at(pool[p].path, pool[p + 1].path, pt);
      } else {
        // cin2021.op.crossover, Figure 8a: random interior cut genes, chains repaired
        const std::size_t na = pool[p].path.size();
        const std::size_t nb = pool[p + 1].path.size();
        if (c.crossover != Crossover::cin || na < 3 || nb < 3) continue;
        const std::size_t k = 1 + rng::uniform_index(stream.next_double("ga crossover cut gene, parent a (cin2021.op.crossover)"), na - 2);
        const std::size_t j = 1 + rng::uniform_index(stream.next_double("ga crossover cut gene, parent b (cin2021.op.crossover)"), nb - 2);
        ga::CutChildren cut = ga::crossover_cut(g, pool[p].path, pool[p + 1].path, k, j, policy,
                                                c.mid_rounding, c.init_reject, c.illegal_step);
        if (!cut.feasible) continue;
        ch = std::move(cut.children);
      }
      if (c.loops == Loops::cut) {
        ch.first = ga::remove_loops(ch.first);
        ch.second = ga::remove_loops(ch.second);
      }
      // Under loops = keep a child can be longer than both parents, and the weighted fitness
      // selects long paths (spec shi2022.plan.ga, Loops): stop with a clear error long before
      // memory runs out (a simple path has at most W*H nodes).
      const auto limit = static_cast<std::size_t>(64 * g.cell_count());
      require(ch.first.size() <= limit && ch.second.size() <= limit,
              "a crossover child has more than 64 x (map cells) nodes: with loops = keep the paths "
              "grow without bound (spec shi2022-ga.md, Loops); use loops = cut");
      Individual c1 = make_individual(g, std::move(ch.first), c, Origin::crossover, i);
      Individual c2 = make_individual(g, std::move(ch.second), c, Origin::crossover, i);
      auto kept = keep_two(std::move(pool[p]), std::move(pool[p + 1]), std::move(c1), std::move(c2),
                           c.crossover_keep);
      pool[p] = std::move(kept.first);
      pool[p + 1] = std::move(kept.second);
    }
    // IHA step 7: elite retention over parents ++ children, keeping the population size.
    // (pop is not read again in this generation: its individuals are moved, not copied.)
    if (c.elitist) {
      std::vector<Individual> merged = std::move(pop);
      merged.insert(merged.end(), std::make_move_iterator(pool.begin()),
                    std::make_move_iterator(pool.end()));
      std::vector<double> mf(merged.size());
      for (std::size_t s = 0; s < merged.size(); ++s) mf[s] = merged[s].fitness;
      const std::vector<std::size_t> keep = ga::elite_indices(mf, S);  // distinct indices
      pool.clear();
      for (const std::size_t k : keep) pool.push_back(std::move(merged[k]));
    }
    // Step 4: mutation of each individual.
    for (std::size_t a = 0; a < S; ++a) {
      if (stream.tracing()) stream.set_context(fmt::format("generation {} individual {}", i, a));
      if (!rng::bernoulli(stream.next_double("ga mutation test u < pm (rng.bernoulli)"), pm)) continue;
      const std::size_t n = pool[a].path.size();
      if (n < 3) continue;
      if (c.mutation == Mutation::segment) {
        // The classic script: two positions round(u (n - 3)) + 1, sorted; the genes between
        // are replaced by the repair of their outer neighbours; redrawn while it rejects.
        for (std::int64_t t = 0; t < c.mutation_attempts; ++t) {
          const std::size_t k1 = 1 + ga::round_choice(stream.next_double("ga segment mutation, first position"), n - 2);
          const std::size_t k2 = 1 + ga::round_choice(stream.next_double("ga segment mutation, second position"), n - 2);
          auto mutated = ga::segment_mutation(g, pool[a].path, std::min(k1, k2), std::max(k1, k2),
                                              policy, c.mid_rounding, c.init_reject, c.illegal_step);
          if (!mutated) continue;
          if (c.loops == Loops::cut) *mutated = ga::remove_loops(*mutated);
          pool[a] = make_individual(g, std::move(*mutated), c, Origin::mutation, i);
          break;
        }
        continue;
      }
      const std::size_t k = 1 + rng::uniform_index(stream.next_double("ga mutation gene (rng.index)"), n - 2);
      if (c.mutation == Mutation::multidirectional) {
        // cin2021.op.mutation: mutant A (towards S) then B (from G); the fitter replaces.
        ga::Mutants mu = ga::multidirectional_mutants(g, pool[a].path, k, policy, c.research, stream);
        if (mu.a.empty() && mu.b.empty()) continue;
        if (mu.a.empty()) {
          pool[a] = make_individual(g, std::move(mu.b), c, Origin::mutation, i);
        } else if (mu.b.empty()) {
          pool[a] = make_individual(g, std::move(mu.a), c, Origin::mutation, i);
        } else {
          Individual A = make_individual(g, std::move(mu.a), c, Origin::mutation, i);
          Individual B = make_individual(g, std::move(mu.b), c, Origin::mutation, i);
          pool[a] = B.fitness > A.fitness ? std::move(B) : std::move(A);
        }
        continue;
      }
      const std::vector<grid::Cell> cand = ga::mutation_candidates(g, pool[a].path, k, policy);
      if (cand.empty()) continue;
      std::vector<grid::Cell> path = std::move(pool[a].path);  // pool[a] is replaced below
      path[k] = cand[rng::uniform_index(stream.next_double("ga mutation: the new cell among the candidates (rng.index)"), cand.size())];
      if (c.loops == Loops::cut) path = ga::remove_loops(path);
      pool[a] = make_individual(g, std::move(path), c, Origin::mutation, i);
    }
    pop.swap(pool);
    memory_check(g, pop, pool, max_memory, fmt::format("after generation {}", i));
    // Step 5: record.
    double sum = 0.0;
    for (const Individual& ind : pop) {
      if (better(ind, ev.best, c.result_by)) {
        ev.best = ind;
        ev.best_generation = i;
      }
      sum += ind.length;
    }
    ev.best_per_generation.push_back(ev.best.length);
    ev.mean_per_generation.push_back(sum / static_cast<double>(S));
  }
  ev.final_population = std::move(pop);
  return ev;
}

planners::Result run(const planners::Request& req, const Config& c, rng::Stream& stream) {
  const grid::Grid& g = grid_of(req);
  validate(c);
  require(g.in_bounds(req.start), "GA: start cell outside the grid");
  require(g.in_bounds(req.goal), "GA: goal cell outside the grid");
  require(g.free(req.start), "GA: start cell is blocked");
  require(g.free(req.goal), "GA: goal cell is blocked");
  planners::Result r;
  r.params_used = to_params(c);
  if (req.start == req.goal) {
    r.found = true;
    r.path = {req.start};
    r.extra = Json{{"best_generation", 0}, {"best_origin", "init"}, {"draws", 0}, {"init_chains", 0}};
    return r;
  }
  const InitOutcome init = initial_population(g, req.start, req.goal, req.policy, c, stream, c.population);
  if (!init.ok) {
    r.extra = population_extra(0, 0, 0, init);
    r.extra["failure"] = init.failure;
    r.extra["draws"] = stream.doubles_drawn();
    return r;
  }
  std::vector<Individual> pop;
  pop.reserve(init.paths.size());
  for (const auto& p : init.paths) pop.push_back(make_individual(g, p, c, Origin::init, 0));
  memory_check(g, pop, {}, req.max_memory, "of the initial population");
  Evolution ev = evolve(g, req.policy, c, stream, std::move(pop), req.interrupted, req.max_memory);
  r.found = true;
  r.path = ev.best.path;
  r.length = ev.best.length;
  r.iterations = c.generations;
  r.best_per_iteration = std::move(ev.best_per_generation);
  r.mean_per_iteration = std::move(ev.mean_per_generation);
  const auto built = static_cast<std::int64_t>(init.paths.size());
  r.extra = population_extra(built, built, 0, init);
  r.extra["best_generation"] = ev.best_generation;
  r.extra["best_origin"] = std::string(to_string(ev.best.origin));
  r.extra["best_fitness"] = ev.best.fitness;
  r.extra["draws"] = stream.doubles_drawn();
  return r;
}

}  // namespace pathref::genetic

namespace pathref::planners {

namespace {

Planner make(const char* name, const char* description, const genetic::Config& base) {
  Planner p;
  p.name = name;
  p.description = description;
  p.defaults = genetic::to_params(base);
  p.bytes_per_cell = genetic::bytes_per_cell;
  p.run = [defaults = p.defaults, base](const Request& req) {
    const Json params = merge_params(defaults, req.params);
    const genetic::Config c = genetic::from_params(base, params);
    rng::Stream stream(req.seed);
    stream.set_trace(req.trace);
    return genetic::run(req, c, stream);
  };
  return p;
}

}  // namespace

Planner make_ga_planner() {
  return make("ga",
              "single genetic algorithm (Shi et al. 2022 Sec. 4.2: Eq. 8-11, Fig. 3-4), "
              "spec/shi2022-ga.md",
              genetic::shi_ga());
}

Planner make_iga_shi_planner() {
  return make("iga-shi",
              "improved GA (Shi et al. 2022 Sec. 4.4.2: Eq. 14-20 fitness, adaptive Pc/Pm), "
              "spec/shi2022-ga.md",
              genetic::shi_iga());
}

Planner make_ga_classic_planner() {
  return make("ga-classic",
              "the classic MATLAB GA grid script (one free cell per row, its continuity repair, "
              "fitness 1/length + 1/smoothness, segment mutation; NP 200, 50 generations, pc 0.8, "
              "pm 0.2; corner policy always by default), spec/classic.md",
              genetic::classic_ga());
}

Planner make_ga_cin_planner() {
  return make("ga-cin",
              "optimised GA of cin2021 Sec. 5.3 (Eq. 20-27: a f1 + b f2 with corner penalties, "
              "cut-gene crossover, multidirectional mutation), spec/cin2021-hga-aco.md",
              genetic::cin_ga());
}

Planner make_iga_shi_nomax_planner() {
  return make("iga-shi-nomax",
              "IGA* of Shi et al. 2022 Sec. 5.1: iga-shi without the P_m_max cap (pm_max = 1), "
              "spec/shi2022-ga.md",
              genetic::shi_iga_nomax());
}

}  // namespace pathref::planners
