#pragma once
/// \file ant_colony.hpp
/// One ant-colony engine for every ACO planner of pathref: Shi et al. 2022's Ant System (`aco`)
/// and improved ACO (`iaco-shi`, `iaco-shi-nomin`), and Han (IJACSA)'s IACO (`iaco-han`). The
/// engine composes the pure equation functions (equations/aco.hpp, aco_adaptive.hpp, corner.hpp,
/// pseudo_random.hpp) and the pinned random stream (rng/); it implements no equation itself.
/// A Config picks one implementation of each concept:
///   heuristic eta      inverse_distance (Shi Eq. 3, cin2021 Eq. 30) | goal_directed (Shi Eq. 12)
///                      | goal_inverse (cin2021 Eq. 30 alternative, 1/d_jG)
///   selection          proportional (Shi Eq. 2, Han Eq. 1) | pseudo_random (Han Eq. 4 + Eq. 5)
///   corner factor      none | han (Han Eq. 1-3, omega^gamma)
///   evaporation        constant | shi_adaptive (Shi Eq. 13, rho_min 0 = IACO*) | han_stepped (Eq. 7)
///   deposit            ant_cycle (Shi Eq. 5-7) | han_elite (Han Eq. 6)
///                      | weighted_best (cin2021 Eq. 31-34: iteration-best and global-best)
///   dead end           die | backtrack | dead_angle (cin2021 Eq. 35: table, penalty, backtrack)
/// and an optional initial pheromone (cin2021 Eq. 28, the GA-to-ACO conversion of hga-aco-cin);
/// and the run is a pure function of (request, config, the stream's state).
/// Source: Shi et al. 2022, doi:10.3389/fbioe.2022.905983, Sec. 4.1 and 4.4.1; Han (IJACSA),
/// Sec. III.A; Dorigo, Maniezzo & Colorni (1996), doi:10.1109/3477.484436 (Ant System).
/// Spec: spec/shi2022-aco.md (shi2022.plan.aco, shi2022.plan.iaco), spec/han-iaco.md
/// (han.plan.iaco, han.plan.astar), spec/cin2021-hga-aco.md (cin2021.plan.aco). The spec states the algorithm step by step and the exact
/// order of the random draws, so that a MATLAB/Python implementation replays a run draw for draw.
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "pathref/equations/aco.hpp"
#include "pathref/equations/aco_adaptive.hpp"
#include "pathref/equations/cin2021.hpp"
#include "pathref/equations/corner.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rng/mt19937.hpp"

namespace pathref::ant_colony {

using Json = planners::Json;

/// eta of the transition rule. Spec: shi2022.plan.aco ("Components").
enum class Eta {
  inverse_distance,  ///< 1 / d_ij (Shi Eq. 3; aco::eta_inverse_distance)
  goal_directed,     ///< 1 / (d_ij + d_jE) (Shi Eq. 12; aco::eta_goal_directed)
  goal_inverse,      ///< 1 / d_jE, eta_goal at E (aco::eta_goal_inverse): the classic script's
                     ///< eta (eta_goal 100), cin2021 Eq. 30's alternative d_GG := 1/2 (eta_goal 2)
};
/// How an ant picks its next cell.
enum class Selection {
  proportional,   ///< rng::roulette on the Eq. 2 / Eq. 1 weights, one draw per move
  pseudo_random,  ///< Han Eq. 4 with q0 of Eq. 5: draw q, then (maybe) u
};
/// The extra factor omega^gamma of Han Eq. 1.
enum class Corner {
  none,  ///< Shi: weights tau^alpha eta^beta
  han,   ///< Han Eq. 1-3: weights (tau^alpha eta^beta) omega^gamma
};
/// Which rho the pheromone update uses in each iteration.
enum class Evaporation {
  constant,      ///< rho(t) = rho for every t (Ant System)
  shi_adaptive,  ///< Shi Eq. 13 (aco::adaptive_rho) with floor rho_min (0: IACO*)
  han_stepped,   ///< Han Eq. 7 (aco::stepped_rho)
};
/// How the surviving ants' paths update tau.
enum class Deposit {
  ant_cycle,  ///< Shi Eq. 5-7: tau = (1 - rho) tau + sum_k Q / L_k
  han_elite,  ///< Han Eq. 6: as ant_cycle, plus the elite bonus, floored at tau_min
  weighted_best,  ///< cin2021 Eq. 31-34: iteration-best and global-best deposits, weights N - t, t
};
/// An ant with no allowed neighbour (spec/shi2022.md "Options for the planners", `dead_end`).
enum class DeadEnd {
  die,        ///< the ant stops; its path is discarded and it deposits nothing
  backtrack,  ///< the ant steps back (the dead end stays tabu); out of the start it dies
  dead_angle, ///< cin2021 Sec. 5.5.2: record the cell in the dead-angle table, penalise the
              ///< edges into it (Eq. 35), then backtrack; stuck at the start it dies
};
/// cin2021 dead-angle table: whether table cells leave the allowed sets (option `dead_angle`).
enum class DeadAngle {
  exclude,        ///< never visited again (default; the paper's "will not go to any deadlock point")
  penalise_only,  ///< only the Eq. 35 penalty; the cells stay allowed
};
/// Han Eq. 4: when the roulette draw u is taken (spec/han.md options, `draw_u`).
enum class DrawU {
  lazy,    ///< only when q > q0
  always,  ///< on every move, right after q
};
/// Han Eq. 6: which edges get the elite bonus (spec han.eq6, `bonus_edges`).
enum class BonusEdges {
  best_path,  ///< the edges of this iteration's best ant's path
  all_edges,  ///< every edge
};
/// Han Eq. 7: whether the rho of iteration t (from iteration t's spread) is used in iteration
/// t's own pheromone update or only from iteration t + 1 on (spec han.plan.iaco, `rho_timing`).
enum class RhoTiming {
  next,     ///< iteration t updates with rho(t-1) (iteration 1 with the printed rho(0) = 0.7);
            ///< rho(t) from iteration t's spread is used from iteration t + 1 (default)
  current,  ///< rho(t) = stepped_rho(rho(t-1), ...) is computed first and used in iteration t
};

[[nodiscard]] Eta parse_eta(std::string_view name);
[[nodiscard]] std::string_view to_string(Eta v) noexcept;
[[nodiscard]] DeadEnd parse_dead_end(std::string_view name);
[[nodiscard]] std::string_view to_string(DeadEnd v) noexcept;
[[nodiscard]] DrawU parse_draw_u(std::string_view name);
[[nodiscard]] std::string_view to_string(DrawU v) noexcept;
[[nodiscard]] BonusEdges parse_bonus_edges(std::string_view name);
[[nodiscard]] std::string_view to_string(BonusEdges v) noexcept;
/// cin2021 dead-angle table: which deadlock points are recorded (option `dead_angle_record`).
enum class DeadAngleRecord {
  cul_de_sac,  ///< a stuck cell with at most one allowed move into a cell outside the table
               ///< (a dead end of the map itself, e.g. the bottom of a concave trap; default)
  any_stuck,   ///< every cell where an ant is stuck, also when only its own tabu cells surround it
};
[[nodiscard]] DeadAngleRecord parse_dead_angle_record(std::string_view name);
[[nodiscard]] std::string_view to_string(DeadAngleRecord v) noexcept;
[[nodiscard]] DeadAngle parse_dead_angle(std::string_view name);
[[nodiscard]] std::string_view to_string(DeadAngle v) noexcept;
[[nodiscard]] RhoTiming parse_rho_timing(std::string_view name);
[[nodiscard]] std::string_view to_string(RhoTiming v) noexcept;

/// Every setting of one ACO run. The defaults here are Shi's Ant System with Table 1 values
/// (`aco`); shi_aco(), shi_iaco(), shi_iaco_nomin() and han_iaco() give each planner's defaults.
struct Config {
  // ---- components ----
  Eta eta = Eta::inverse_distance;
  Selection selection = Selection::proportional;
  Corner corner = Corner::none;
  Evaporation evaporation = Evaporation::constant;
  Deposit deposit = Deposit::ant_cycle;
  DeadEnd dead_end = DeadEnd::die;

  // ---- colony (Shi Table 1) ----
  std::int64_t ants = 50;         ///< m >= 1
  std::int64_t iterations = 100;  ///< T (Shi Eq. 13) = N_max (Han Eq. 5) >= 1
  double alpha = 1.0;             ///< exponent of tau, >= 0
  double beta = 7.0;              ///< exponent of eta, >= 0
  double Q = 1.0;                 ///< deposit constant of Eq. 7, > 0
  double tau0 = 8.0;              ///< initial pheromone on every edge, > 0
  aco::EdgeSense edge_sense = aco::EdgeSense::directed;
  double eta_goal = 100.0;  ///< eta at the goal under Eta::goal_inverse (the classic script's 100)

  // ---- evaporation ----
  double rho = 0.9;      ///< constant: rho; shi_adaptive: rho_initial; han_stepped: rho(0)
  double rho_min = 0.1;  ///< floor of Eq. 13 / Eq. 7 (0 allowed for shi_adaptive: IACO*)
  aco::RhoReading rho_reading = aco::RhoReading::factor;  ///< Shi Eq. 13 reading
  int rho_t_origin = 1;                                    ///< Shi Eq. 13 numbering: 1 or 0
  double a = 1.0;  ///< Han Eq. 7 lower spread constant (cell sides)
  double b = 5.0;  ///< Han Eq. 7 upper spread constant (cell sides)
  aco::SpreadReference spread_reference = aco::SpreadReference::iteration_worst;
  RhoTiming rho_timing = RhoTiming::next;

  // ---- Han corner factor (Eq. 1-3) ----
  double gamma = 1.0;
  double omega_i = 0.5;
  corner::OmegaForm omega_form = corner::OmegaForm::multiply;
  corner::At90 at90 = corner::At90::two;

  // ---- Han pseudo-random proportional rule (Eq. 4-5) ----
  double epsilon = 1.0;
  int q0_origin = 1;  ///< N_c of the first iteration: 1 or 0
  DrawU draw_u = DrawU::lazy;

  // ---- Han elite deposit (Eq. 6) ----
  double h = 1.0;
  double tau_min = 0.01;
  BonusEdges bonus_edges = BonusEdges::best_path;

  // ---- cin2021 weighted best deposit (Eq. 31-34) ----
  cin::WeightNorm weight_norm = cin::WeightNorm::raw;
  bool tau_bounds = false;   ///< clamp tau to [tau_lower, tau_upper] after each update
  double tau_lower = 0.001;
  double tau_upper = 100.0;

  // ---- cin2021 dead-angle table (Eq. 35) ----
  double lambda = 0.5;
  cin::LambdaForm lambda_form = cin::LambdaForm::lambda;
  DeadAngle dead_angle = DeadAngle::exclude;
  DeadAngleRecord dead_angle_record = DeadAngleRecord::cul_de_sac;
};

/// Defaults of planner `aco`: the Config defaults above (Table 1; tau0 = 8, rho = 0.9).
/// Spec: shi2022.plan.aco
[[nodiscard]] Config shi_aco();
/// Defaults of planner `iaco-shi` (spec shi2022.plan.iaco): eta = goal_directed,
/// evaporation = shi_adaptive, rho = rho_initial = 0.9, rho_min = 0.1. Spec: shi2022.plan.iaco
[[nodiscard]] Config shi_iaco();
/// Defaults of planner `iaco-shi-nomin` (IACO*): shi_iaco() with rho_min = 0.
/// Spec: shi2022.plan.iaco
[[nodiscard]] Config shi_iaco_nomin();
/// Defaults of planner `aco-classic` (spec classic.plan.aco): the classic MATLAB ACO script's
/// eta = goal_inverse (eta_goal 100), tau0 8, rho 0.3, Q 1, alpha 1, beta 7, 100 iterations of 50
/// ants, edge_sense undirected, dead_end die, evaporation constant, deposit ant_cycle.
/// Spec: classic.plan.aco
[[nodiscard]] Config classic_aco();
/// Defaults of planner `iaco-han` (spec han.plan.iaco): 50 ants, 50 cycles, alpha 4, beta 8,
/// rho(0) 0.7, eta goal_directed, dead_end backtrack (the readings of han.plan.iaco),
/// selection pseudo_random, corner han, evaporation han_stepped, deposit han_elite,
/// and the chosen constants of han.params (gamma, omega_i, epsilon, h, Q, tau0 = 1, tau_min,
/// a, b, rho_min). Spec: han.plan.iaco
[[nodiscard]] Config han_iaco();
/// Defaults of planner `aco-cin` (spec cin2021.plan.aco): 30 ants, 50 iterations, alpha 1,
/// beta 2, rho 0.3, Q 1, tau0 (tau_C) 0.1, eta inverse_distance, deposit weighted_best,
/// dead_end dead_angle with lambda 0.5 -- the project's defaults of the lost Sec. 5.6
/// parameters, not the paper's. Spec: cin2021.plan.aco
[[nodiscard]] Config cin_aco();

/// The planner parameters (names as in the spec's parameter tables) of `base`'s components:
/// only the settings that the components of `base` use are listed, so that params_used lists
/// every value used and nothing else.
[[nodiscard]] Json to_params(const Config& base);
/// `base` with the values of `params` (a merge_params result of to_params(base)); UsageError for
/// an unknown option name, DomainError for a value outside its domain (e.g. ants < 1).
[[nodiscard]] Config from_params(const Config& base, const Json& params);

/// One distinct path found by some ant in some iteration (a surviving ant's path start..goal).
struct AntPath {
  std::vector<grid::Cell> path;
  double length = 0.0;               ///< metrics::path_length
  std::int64_t first_iteration = 0;  ///< 1-based iteration in which it was first found
  std::int64_t first_ant = 0;        ///< 0-based ant that found it first
  std::int64_t last_iteration = 0;   ///< last iteration in which some ant walked it
  std::int64_t count = 0;            ///< how many (iteration, ant) pairs walked it
};

/// What run() returns.
struct Run {
  /// The planner result: best path (best-so-far over the run, earliest on ties), its length,
  /// iterations, best_per_iteration (best-so-far after each iteration; +inf before the first
  /// path: JSON null), mean_per_iteration (mean over that iteration's surviving ants; NaN when
  /// none survived: JSON null), params_used (to_params of the config) and extra (per-iteration
  /// rho, dead ants, iteration best/worst, q0 for Han; best_iteration, best_ant, draws).
  planners::Result result;
  /// Every distinct surviving-ant path, in order of first appearance (iteration ascending, ant
  /// ascending). The IHA hybrid injects these (e.g. the shortest few that are not the best)
  /// into the GA population.
  std::vector<AntPath> distinct_paths;
};

/// Bytes per grid cell of a colony run, before its paths (spec shi2022.plan.aco, "Memory"): the
/// move masks (1), the pheromone of the 8 direction slots (8 x 8), the eta^beta cache (2 x 8),
/// the tabu and dead-angle flags (1 + 1) and the grid planned on (1).
inline constexpr std::uint64_t bytes_per_cell = 84;
/// The colony's need before its paths: cells x bytes_per_cell (saturating). run() refuses with a
/// UsageError naming it when it exceeds req.max_memory, before allocating, and counts the ants'
/// walks and stored paths against the same limit as they grow. Spec: shi2022.plan.aco
[[nodiscard]] std::uint64_t memory_estimate(std::int64_t cells) noexcept;

/// Runs the colony on req.grid from req.start to req.goal under req.policy, drawing from
/// `stream` (the caller seeds it; run() never creates, copies or reseeds a stream, and consumes
/// exactly the draws the spec lists). req.params and req.seed are ignored: `config` is used as
/// given (a planner builds it with from_params; a hybrid builds it directly).
/// Source: Shi et al. 2022 Sec. 4.1, 4.4.1; Han (IJACSA) Sec. III.A.
/// Spec: shi2022.plan.aco, shi2022.plan.iaco, han.plan.iaco, cin2021.plan.aco
/// Pre: req.grid set (UsageError); start, goal in bounds and free (DomainError); the config in
/// its domain (DomainError: ants, iterations >= 1; alpha, beta >= 0; Q, tau0 > 0; 0 < rho < 1;
/// 0 <= rho_min < 1; ...).
/// Post: found iff some ant reached the goal; then the path is valid under req.policy (metrics
/// validate_path), simple (no repeated cell) and length = metrics::path_length(path);
/// best_per_iteration non-increasing; start == goal gives the one-cell path, no iteration and
/// no draw.
[[nodiscard]] Run run(const planners::Request& req, const Config& config, rng::Stream& stream);

/// How an initial pheromone list combines with tau0 (cin2021.eq28 option `conversion`).
enum class InitialMode {
  add,      ///< tau(0) = tau0 + tau^G on the listed edges (default)
  replace,  ///< tau(0) = tau^G on the listed edges
};
[[nodiscard]] InitialMode parse_initial_mode(std::string_view name);
[[nodiscard]] std::string_view to_string(InitialMode v) noexcept;

/// run() starting from tau0 on every edge except the listed directed edges, which start at
/// tau0 + e.tau (add) or e.tau (replace); an edge between cells that are not 8-neighbours is a
/// DomainError. The draws are those of run(). hga-aco-cin passes the GA conversion of
/// cin2021 Eq. 28 (cin::converted_pheromone). Spec: cin2021.plan.aco, cin2021.plan.hga-aco
[[nodiscard]] Run run(const planners::Request& req, const Config& config, rng::Stream& stream,
                      std::span<const cin::EdgePheromone> initial, InitialMode mode);

}  // namespace pathref::ant_colony

namespace pathref::planners {

/// Planner "aco": Shi et al. 2022 Sec. 4.1 Ant System. Spec: shi2022.plan.aco
[[nodiscard]] Planner make_aco_planner();
/// Planner "iaco-shi": Shi et al. 2022 Sec. 4.4.1 (Eq. 12, Eq. 13). Spec: shi2022.plan.iaco
[[nodiscard]] Planner make_iaco_shi_planner();
/// Planner "iaco-shi-nomin": IACO* (no rho_min). Spec: shi2022.plan.iaco
[[nodiscard]] Planner make_iaco_shi_nomin_planner();
/// Planner "aco-classic": the classic MATLAB ACO grid script's defaults, default corner policy
/// always. Spec: classic.plan.aco
[[nodiscard]] Planner make_aco_classic_planner();
/// Planner "iaco-han": Han (IJACSA) Eq. 1-7. Spec: han.plan.iaco
[[nodiscard]] Planner make_iaco_han_planner();
/// Planner "aco-cin": the optimised ACO of cin2021 Sec. 5.5 (Eq. 29-35). Spec: cin2021.plan.aco
[[nodiscard]] Planner make_aco_cin_planner();
/// Planner "astar-han": 8-direction A* (search::astar) with the Chebyshev heuristic of Han
/// Eq. 8; param h_form = "chebyshev" (default) | "octile" (the reading of han.eq8). No draws.
/// Source: Han (IJACSA) Sec. III.B, Eq. (8). Spec: han.plan.astar
/// Post: the length equals Dijkstra's (Chebyshev is admissible under every corner policy).
[[nodiscard]] Planner make_astar_han_planner();

}  // namespace pathref::planners
