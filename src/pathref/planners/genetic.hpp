#pragma once
/// \file genetic.hpp
/// One genetic-algorithm engine for the GA planners of Shi et al. 2022: the single GA (`ga`,
/// Sec. 4.2), the improved GA (`iga-shi`, `iga-shi-nomax` = IGA*, Sec. 4.4.2) and the GA phases
/// of the two hybrids (planners/hybrid.hpp). The engine composes the pure equations of
/// equations/ga.hpp (Eq. 8-10, 14-20), the operators of equations/ga_operators.hpp (chain repair,
/// crossover, mutation, deletion, elite retention) and the pinned random stream; it implements no
/// equation itself.
/// Source: Shi et al. 2022, doi:10.3389/fbioe.2022.905983, Sec. 4.2, 4.4.2, 4.4.3.
/// Spec: spec/shi2022-ga.md (shi2022.plan.ga, shi2022.plan.iga). The spec states each step and
/// the exact order of the random draws, so that a MATLAB/Python implementation replays a run.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pathref/equations/cin2021.hpp"
#include "pathref/equations/ga.hpp"
#include "pathref/equations/ga_operators.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rng/mt19937.hpp"

namespace pathref::genetic {

using planners::Json;

/// Which fitness ranks the individuals (option `fitness`).
enum class Fitness {
  inverse_length,  ///< Eq. 10: 1 / length (single GA)
  weighted,        ///< Eq. 14-18: a fit1 + b fit2 + c fit3 (improved GA)
  cin,             ///< cin2021 Eq. 20-26: a f1 + b f2, f2 of the corner penalties (ga-cin)
};
/// Option `ga_probabilities` of spec/shi2022.md "Options for the planners".
enum class Probabilities {
  fixed,     ///< P_c, P_m of Table 1 in every generation
  adaptive,  ///< P_c(i), P_m(i) of Eq. 19-20
};
/// Readings `pc_reading` / `pm_reading` of shi2022.eq19 / eq20.
enum class Scale {
  printed,  ///< scale 1 (the printed equation)
  scaled,   ///< scale = Table 1's P_c (resp. P_m)
};
/// Option `crossover_keep` (spec shi2022.plan.ga step 3).
enum class CrossoverKeep {
  children,  ///< both children replace the parents (Figure 3)
  best_two,  ///< the two shortest of (parent a, parent b, child 1, child 2), ties in that order
  best_two_fitness,  ///< the two fittest of (a, b, c1, c2), ties in that order (cin2021.op.crossover)
};
/// Option `crossover`: what happens to a pair without a common gene.
enum class Crossover {
  common_gene,  ///< no crossover (Shi Figure 3: only at a common node)
  cin,          ///< random cut genes and the chain repair (cin2021 Figure 8a, ga::crossover_cut)
};
/// Option `init`: how the initial population is made.
enum class Init {
  rows,  ///< Shi Sec. 4.2: one random free cell per row, chains repaired (initial_paths)
  walk,  ///< cin2021 (pathref reading): random depth-first walks S -> G (initial_walks)
};
/// Option `loops` (spec shi2022.plan.ga step 5): what happens to a child that visits a cell twice.
enum class Loops {
  keep,  ///< kept as it is (a valid path; the paper is silent)
  cut,   ///< ga::remove_loops is applied to every child of crossover and mutation
};
/// Option `result_by`: which individual is "the best" reported.
enum class ResultBy {
  fitness,  ///< the largest fitness ever evaluated (earliest on ties)
  length,   ///< the shortest path ever evaluated (earliest on ties)
};
/// Option `init_retry` (spec shi2022.plan.ga step 2, classic.plan.ga).
enum class InitRetry {
  per_individual,  ///< Shi: draw chains until one repairs, up to init_attempts per individual
  none,            ///< the classic script: one chain per individual; rejected chains are dropped
                   ///< and the population is the survivors
};
/// Option `selection` (step 5.2).
enum class Selection {
  independent,  ///< N roulette draws, pool slot s from the s-th draw (Eq. 11)
  sorted,       ///< the classic script: N draws sorted ascending, then the roulette of each
};
/// Option `crossover_points` (step 5.3).
enum class CrossoverPoints {
  interior,  ///< shi2022.op.crossover's points, choice rng.index (Figure 3)
  script,    ///< the classic script: interior k of a whose cell is anywhere in b, j its first
             ///< position in b; choice round(u * (P - 1)) (classic.plan.ga)
};
/// Option `mutation` (step 5.5).
enum class Mutation {
  point,             ///< Shi Figure 4: one gene replaced by a candidate (shi2022.op.mutation)
  multidirectional,  ///< cin2021 Figure 9: mutants A and B re-searched, the fitter kept
  segment,  ///< the classic script: the genes between two random positions are replaced by the
            ///< chain repair of their outer neighbours, redrawn until it repairs
};

/// Where an individual was made (reported as `best_origin`).
enum class Origin { init, aco, crossover, mutation };

[[nodiscard]] Fitness parse_fitness(std::string_view name);
[[nodiscard]] std::string_view to_string(Fitness v) noexcept;
[[nodiscard]] Probabilities parse_probabilities(std::string_view name);
[[nodiscard]] std::string_view to_string(Probabilities v) noexcept;
[[nodiscard]] Scale parse_scale(std::string_view name);
[[nodiscard]] std::string_view to_string(Scale v) noexcept;
[[nodiscard]] CrossoverKeep parse_crossover_keep(std::string_view name);
[[nodiscard]] std::string_view to_string(CrossoverKeep v) noexcept;
[[nodiscard]] Loops parse_loops(std::string_view name);
[[nodiscard]] std::string_view to_string(Loops v) noexcept;
[[nodiscard]] ResultBy parse_result_by(std::string_view name);
[[nodiscard]] std::string_view to_string(ResultBy v) noexcept;
[[nodiscard]] std::string_view to_string(Origin v) noexcept;
[[nodiscard]] InitRetry parse_init_retry(std::string_view name);
[[nodiscard]] std::string_view to_string(InitRetry v) noexcept;
[[nodiscard]] Selection parse_selection(std::string_view name);
[[nodiscard]] std::string_view to_string(Selection v) noexcept;
[[nodiscard]] CrossoverPoints parse_crossover_points(std::string_view name);
[[nodiscard]] std::string_view to_string(CrossoverPoints v) noexcept;
[[nodiscard]] Crossover parse_crossover(std::string_view name);
[[nodiscard]] std::string_view to_string(Crossover v) noexcept;
[[nodiscard]] Init parse_init(std::string_view name);
[[nodiscard]] std::string_view to_string(Init v) noexcept;
[[nodiscard]] Mutation parse_mutation(std::string_view name);
[[nodiscard]] std::string_view to_string(Mutation v) noexcept;

/// Every setting of one GA run. Defaults: the single GA with Table 1 values (planner `ga`).
struct Config {
  std::int64_t population = 200;  ///< N (Table 1), >= 2
  std::int64_t generations = 50;  ///< M_g (Table 1), >= 1
  Fitness fitness = Fitness::inverse_length;
  ga::FitnessWeights weights{};  ///< a, b, c (Table 1: 5, 4, 1)
  ga::SmoothnessReading smoothness = ga::SmoothnessReading::inverse_total_plus_one;
  ga::TurnPenalties penalties{};  ///< 5, 100, 1000
  ga::SafetyOptions safety{};
  Probabilities probabilities = Probabilities::fixed;
  double pc = 0.8;      ///< fixed P_c; the scale of Eq. 19 under pc_reading = scaled
  double pm = 0.1;      ///< fixed P_m; the scale of Eq. 20 under pm_reading = scaled
  double pm_max = 0.3;  ///< cap of Eq. 20 (1 = no cap: IGA*)
  Scale pc_reading = Scale::printed;
  Scale pm_reading = Scale::printed;
  ga::PmAtZero pm_at_zero = ga::PmAtZero::binary64;
  int ga_i_origin = 1;  ///< generation numbering of Eq. 19-20: 1 or 0
  ga::MidRounding mid_rounding = ga::MidRounding::floor;
  ga::InitReject init_reject = ga::InitReject::shift;  ///< blocked before issue 11
  std::int64_t init_attempts = 100000;  ///< chains drawn per individual before giving up, >= 1
  ga::IllegalStep illegal_step = ga::IllegalStep::repair;  ///< a corner-cutting continuous pair
  CrossoverKeep crossover_keep = CrossoverKeep::children;
  Loops loops = Loops::keep;
  ResultBy result_by = ResultBy::fitness;
  /// IHA step 7 (spec shi2022.plan.iha): after crossover, keep the top elite_fraction of
  /// parents ++ children. false for the single and improved GA.
  bool elitist = false;
  double elite_fraction = 0.5;
  // ---- the classic-MATLAB profile (spec/classic.md, classic.plan.ga); Shi's by default ----
  InitRetry init_retry = InitRetry::per_individual;
  Selection selection = Selection::independent;
  CrossoverPoints crossover_points = CrossoverPoints::interior;
  Mutation mutation = Mutation::point;
  std::int64_t mutation_attempts = 100000;  ///< segment mutation: position pairs tried, >= 1
  // ---- cin2021 options (spec/cin2021-hga-aco.md); listed by to_params when any is not Shi's ----
  Init init = Init::rows;
  Crossover crossover = Crossover::common_gene;
  ga::Research research = ga::Research::greedy;
  cin::CornerPenalties corner_penalties{};  ///< c135, c90, c45 of cin2021 Eq. 24
  cin::F2Guard f2_guard = cin::F2Guard::one_plus;
  cin::AngleReading angle = cin::AngleReading::arccos;
};

/// Defaults of planner `ga` (spec shi2022.plan.ga): the Config defaults.
[[nodiscard]] Config shi_ga();
/// Defaults of planner `iga-shi` (spec shi2022.plan.iga): fitness weighted, probabilities adaptive.
[[nodiscard]] Config shi_iga();
/// Defaults of planner `iga-shi-nomax` (IGA*): shi_iga() with pm_max = 1 (Eq. 20 never caps).
[[nodiscard]] Config shi_iga_nomax();
/// Defaults of planner `ga-classic` (spec classic.plan.ga): the classic MATLAB GA script's
/// N = 200, 50 generations, pc 0.8, pm 0.2, fitness 1/length + 1/(total turn penalty)
/// (weighted, a = b = 1, c = 0, smoothness inverse_total, penalties 3/15/20), init_reject shift,
/// init_retry none, selection sorted, crossover_points script, mutation segment.
/// Spec: classic.plan.ga
[[nodiscard]] Config classic_ga();
/// Defaults of planner `ga-cin` (spec cin2021.plan.ga): fitness cin (a = 1, b = 0.1), crossover
/// cin with crossover_keep best_two_fitness, mutation multidirectional (research greedy), loops
/// cut, population 50, generations 50, pc 0.8, pm 0.2 -- the project's defaults of the lost
/// Sec. 5.6 parameters, not the paper's. Spec: cin2021.plan.ga
[[nodiscard]] Config cin_ga();

/// The planner parameters of a config (names of spec/shi2022-ga.md "Parameters"); every setting
/// is listed. `elitist` is not a parameter (it is fixed by the planner).
[[nodiscard]] Json to_params(const Config& c);
/// `base` with the values of `params` (a merge_params result of to_params(base)); UsageError for
/// an unknown option name, DomainError for a value outside its domain.
[[nodiscard]] Config from_params(const Config& base, const Json& params);
/// DomainError unless every numeric setting is in its domain (spec "Parameters").
void validate(const Config& c);

/// One member of the population.
struct Individual {
  std::vector<grid::Cell> path;
  double length = 0.0;   ///< metrics::path_length
  double fitness = 0.0;  ///< the config's fitness
  Origin origin = Origin::init;
  std::int64_t born = 0;  ///< generation in which it was made (0 = initial population)
};

/// The fitness of a path under the config: Eq. 10 or Eq. 14 (with Eq. 15, 16, 18).
/// Spec: shi2022.plan.ga, shi2022.plan.iga (step "Fitness"). Pre: >= 2 nodes (DomainError).
[[nodiscard]] double fitness_of(const grid::Grid& g, std::span<const grid::Cell> path,
                                const Config& c);

/// An individual with its length and fitness computed.
[[nodiscard]] Individual make_individual(const grid::Grid& g, std::vector<grid::Cell> path,
                                         const Config& c, Origin origin, std::int64_t born);

/// The crossover's "keep" step for one pair: `children` returns (c1, c2); `best_two` the two
/// shortest of (a, b, c1, c2) and `best_two_fitness` the two fittest (cin2021.op.crossover: "select
/// the best individuals from the parent and offspring"), both by a stable sort (ties in the order
/// a, b, c1, c2). Spec: shi2022.plan.ga (step 3), cin2021.op.crossover.
/// Post (best_two_fitness): max(fitness of the result) == max(fitness of the four): the pair's
/// best is never lost.
[[nodiscard]] std::pair<Individual, Individual> keep_two(Individual a, Individual b, Individual c1,
                                                         Individual c2, CrossoverKeep by);

/// What initial_paths returns.
struct InitOutcome {
  bool ok = false;
  std::string failure;  ///< "" | "row_blocked" | "init_attempts_exhausted"
  std::vector<std::vector<grid::Cell>> paths;
  std::int64_t chains = 0;  ///< chains drawn (accepted + rejected)
};

/// Largest number of gene pairs for which initial_paths keeps a table of pair verdicts (spec
/// shi2022.plan.ga, "Evaluation"): 2^20 entries of 4 bytes. With R rows between start and goal
/// the table has at most 2W + (R - 1) * W^2 entries: 6 840 on a 20 x 20 map corner to corner,
/// 249 984 on 64 x 64; maps above the limit repair every chain whole, as the rule is written.
/// Either way the outcome and the draws are the same.
inline constexpr std::int64_t init_verdict_max_entries = std::int64_t{1} << 20;

/// `count` random initial paths (Sec. 4.2 steps 1-3; spec shi2022.plan.ga "Initialisation"): per
/// individual, up to init_attempts chains (one draw per intermediate row), each repaired by
/// ga::connect_chain; stops at the first individual whose attempts are exhausted. A chain is
/// decided pair by pair from a table of pair verdicts filled on first use, and repaired whole only
/// when every pair passes (spec "Evaluation": the same outcome, chains and draws as repairing
/// every chain whole).
/// Spec: shi2022.plan.ga. Pre: start != goal, both in bounds and free (DomainError).
[[nodiscard]] InitOutcome initial_paths(const grid::Grid& g, grid::Cell start, grid::Cell goal,
                                        grid::CornerPolicy policy, const Config& c,
                                        rng::Stream& stream, std::int64_t count);

/// The population disclosure every GA-based planner puts in Result::extra (spec shi2022.plan.ga
/// step 6, "Population"): `population_size` (individuals the generations evolve),
/// `population_init` (of them, paths of the Sec. 4.2 initialisation), `population_aco` (of them,
/// ant paths, repeats counted), `init_built` (chains the initialisation repaired into paths),
/// `init_exhausted` (it gave up: init_attempts chains of one individual rejected), `init_chains`
/// (chains drawn). Spec: shi2022.plan.ga, shi2022.plan.hybrid, shi2022.plan.iha.
[[nodiscard]] Json population_extra(std::int64_t size, std::int64_t from_init, std::int64_t from_aco,
                                    const InitOutcome& init);
/// `count` initial paths by random depth-first walks (option init = walk, spec cin2021.plan.ga
/// "Initialisation"): individual a = ga::research_walk(start -> goal, nothing avoided, random,
/// backtrack) drawing from `stream`; failure "unreachable" when a walk fails (then every walk
/// would). Spec: cin2021.plan.ga. Pre: start != goal, both in bounds and free (DomainError).
[[nodiscard]] InitOutcome initial_walks(const grid::Grid& g, grid::Cell start, grid::Cell goal,
                                        grid::CornerPolicy policy, rng::Stream& stream,
                                        std::int64_t count);

/// initial_paths or initial_walks by c.init. Spec: shi2022.plan.ga, cin2021.plan.ga.
[[nodiscard]] InitOutcome initial_population(const grid::Grid& g, grid::Cell start, grid::Cell goal,
                                             grid::CornerPolicy policy, const Config& c,
                                             rng::Stream& stream, std::int64_t count);

/// What evolve returns.
struct Evolution {
  Individual best;                          ///< best by result_by over generations 0..M_g
  std::int64_t best_generation = 0;         ///< generation that first held it (0 = initial)
  std::vector<double> best_per_generation;  ///< length of the best-so-far after generation i
  std::vector<double> mean_per_generation;  ///< mean length of the population after generation i
  std::vector<Individual> final_population;  ///< the population after the last generation
};

/// The generation loop (spec shi2022.plan.ga steps 2-5; with c.elitist, shi2022.plan.iha steps
/// 5-9) from the given population, drawing from `stream`.
/// Spec: shi2022.plan.ga, shi2022.plan.iga, shi2022.plan.iha.
/// Pre: population non-empty, every path valid from start to goal (not checked), c validated.
/// `interrupted` is asked before every generation (planners::Request::interrupted). The stored
/// paths are counted against `max_memory` after every generation (memory_check; UsageError naming
/// the estimate and the limit; spec shi2022.plan.ga "Memory").
[[nodiscard]] Evolution evolve(const grid::Grid& g, grid::CornerPolicy policy, const Config& c,
                               rng::Stream& stream, std::vector<Individual> population,
                               const planners::Interrupt& interrupted = {},
                               std::uint64_t max_memory = memory::default_limit);

/// Bytes per grid cell of a GA run before its paths (spec shi2022.plan.ga "Memory"): the grid (1)
/// and the closed flags of a random walk (1).
inline constexpr std::uint64_t bytes_per_cell = 2;
/// Bytes per stored path cell (a grid::Cell of two 64-bit coordinates).
inline constexpr std::uint64_t bytes_per_path_cell = 16;
/// cells x bytes_per_cell plus bytes_per_path_cell for every cell of capacity the stored paths
/// hold (saturating). Spec: shi2022.plan.ga
[[nodiscard]] std::uint64_t memory_estimate(std::int64_t cells, std::span<const Individual> a,
                                            std::span<const Individual> b = {});
/// UsageError when memory_estimate(...) > max_memory, naming both; `when` says at which point
/// of the run ("after generation 7"). Spec: shi2022.plan.ga
void memory_check(const grid::Grid& g, std::span<const Individual> a, std::span<const Individual> b,
                  std::uint64_t max_memory, std::string_view when);

/// A whole single-GA / improved-GA / ga-cin run (spec shi2022.plan.ga / shi2022.plan.iga /
/// cin2021.plan.ga): initial population, then evolve. Result.extra: best_generation,
/// best_origin, draws, init_chains, failure (when !found).
/// Spec: shi2022.plan.ga, shi2022.plan.iga, cin2021.plan.ga
/// Pre: req.grid set (UsageError); start, goal in bounds and free (DomainError).
/// Post: found => path valid under req.policy, length = metrics::path_length(path).
[[nodiscard]] planners::Result run(const planners::Request& req, const Config& c,
                                   rng::Stream& stream);

}  // namespace pathref::genetic

namespace pathref::planners {

/// Planner "ga": Shi et al. 2022 Sec. 4.2 single GA. Spec: shi2022.plan.ga
[[nodiscard]] Planner make_ga_planner();
/// Planner "iga-shi": Shi et al. 2022 Sec. 4.4.2 improved GA. Spec: shi2022.plan.iga
[[nodiscard]] Planner make_iga_shi_planner();
/// Planner "iga-shi-nomax": IGA* (no P_m_max cap). Spec: shi2022.plan.iga
[[nodiscard]] Planner make_iga_shi_nomax_planner();
/// Planner "ga-classic": the classic MATLAB GA grid script's defaults, default corner policy
/// always. Spec: classic.plan.ga
[[nodiscard]] Planner make_ga_classic_planner();
/// Planner "ga-cin": the optimised GA of cin2021 Sec. 5.3 (Eq. 20-27, Figures 8-9).
/// Spec: cin2021.plan.ga
[[nodiscard]] Planner make_ga_cin_planner();

}  // namespace pathref::planners
