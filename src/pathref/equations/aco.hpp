#pragma once
/// \file aco.hpp
/// Ant colony optimisation equations as pure functions: transition weights and probabilities,
/// the distance heuristics eta = 1/d and eta = 1/(d_ij + d_jE), pheromone evaporation plus
/// deposit, the ant-cycle deposit Q/L_k, and the adaptive evaporation factor. ACO planners and the
/// GA-ACO hybrids compose these; randomness enters only through rng::roulette on the weights.
/// Distances are between cell centres, i.e. between cells (metrics::centre_distance).
/// Spec: spec/shi2022.md (shi2022.eq2, eq3, eq5, eq6, eq7, eq12, eq13)
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "pathref/grid/grid.hpp"

namespace pathref::aco {

/// An extra per-candidate factor omega_j^gamma multiplying the weight tau^alpha eta^beta, for
/// transition rules that add a third heuristic (Han, IJACSA, Eq. 1: corner heuristic omega).
/// `omega` has one value per candidate, in the same order as tau and eta.
struct CornerFactor {
  std::span<const double> omega;
  double gamma = 1.0;
};

/// Unnormalised transition weights w_j = tau_j^alpha * eta_j^beta (* omega_j^gamma), one per
/// allowed candidate j, in the caller's (canonical neighbour) order. Evaluated as
/// (pow(tau, alpha) * pow(eta, beta)) * pow(omega, gamma) in binary64; pow(0, 0) = 1.
/// Source: Shi et al. 2022, Eq. (2) numerator, Sec. 4.1, doi:10.3389/fbioe.2022.905983;
/// with `corner`, Han (IJACSA) Eq. (1); cin2021 Eq. (29), doi:10.1155/2021/8025730.
/// Spec: shi2022.eq2, cin2021.eq29
/// Pre: tau, eta (and omega) non-empty and of equal size; every value finite and >= 0;
/// alpha, beta (gamma) finite and >= 0; every weight finite (DomainError).
/// Post: one weight per candidate, each finite and >= 0.
/// Golden: golden/shi2022/shi2022.eq2.json
[[nodiscard]] std::vector<double> transition_weights(std::span<const double> tau,
                                                     std::span<const double> eta, double alpha,
                                                     double beta,
                                                     std::optional<CornerFactor> corner = std::nullopt);

/// transition_weights with the heuristic powers given: w_j = tau_j^alpha * eta_pow_j
/// (* omega_j^gamma), evaluated as (pow(tau, alpha) * eta_pow) * pow(omega, gamma) into `out`
/// (resized; no allocation once its capacity suffices). With eta_pow_j = pow(eta_j, beta) the
/// weights are the doubles of transition_weights bit for bit (transition_weights is this
/// function after computing those powers). It exists because eta depends only on the move and
/// the goal, so a colony computes pow(eta, beta) once per (cell, direction) instead of per move.
/// Source: Shi et al. 2022, Eq. (2) numerator, doi:10.3389/fbioe.2022.905983; Han (IJACSA) Eq. (1).
/// Spec: shi2022.eq2
/// Pre: tau non-empty, eta_pow (and omega) of its size; tau, omega finite and >= 0, eta_pow >= 0;
/// alpha (gamma) finite and >= 0; every weight finite (DomainError).
void transition_weights_into(std::span<const double> tau, std::span<const double> eta_pow,
                             double alpha, std::optional<CornerFactor> corner,
                             std::vector<double>& out);

/// Transition probabilities P_ij = w_j / sum_s w_s over the allowed set (Eq. 2):
/// equations::proportional_probabilities(transition_weights(...)).
/// Source: Shi et al. 2022, Eq. (2), Sec. 4.1, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq2, cin2021.eq29
/// Pre: as transition_weights; the weights sum to a positive finite value (DomainError; an
/// empty allowed set, a dead end, is a DomainError: the dead-end policy is the planner's).
/// Post: p_j in [0, 1], |sum p - 1| <= 2 n 2^-53. The ant's draw is rng::roulette on the
/// weights, not on these probabilities (spec shi2022.eq2, "Draw").
/// Golden: golden/shi2022/shi2022.eq2.json
[[nodiscard]] std::vector<double> transition_probabilities(
    std::span<const double> tau, std::span<const double> eta, double alpha, double beta,
    std::optional<CornerFactor> corner = std::nullopt);

/// Distance heuristic eta_ij = 1 / d_ij, d_ij the Euclidean distance between the centres of the
/// current cell i and the candidate j (metrics::centre_distance, Eq. 4).
/// Source: Shi et al. 2022, Eq. (3)-(4), Sec. 4.1, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq3, cin2021.eq30
/// Pre: i != j; |coordinates| <= 2^25 (DomainError).
/// Post: 0 < eta; eta = 1 for an orthogonal step, 1/sqrt2 (rounded) for a diagonal one.
/// Golden: golden/shi2022/shi2022.eq3.json
[[nodiscard]] double eta_inverse_distance(grid::Cell i, grid::Cell j);

/// Goal-directed heuristic eta_ij = 1 / (d_ij + d_jE), evaluated as 1.0 / (d_ij + d_jE), E the
/// goal cell. Source: Shi et al. 2022, Eq. (12), Sec. 4.4.1, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq12
/// Pre: i != j; |coordinates| <= 2^25 (DomainError). j == goal is allowed (d_jE = 0).
/// Post: 0 < eta_goal_directed(i, j, E) <= eta_inverse_distance(i, j), equal iff j == E.
/// Golden: golden/shi2022/shi2022.eq12.json
[[nodiscard]] double eta_goal_directed(grid::Cell i, grid::Cell j, grid::Cell goal);

/// Goal-only heuristic eta_j = 1 / d_jE (the Euclidean distance from the centre of the candidate
/// cell j to the goal's, metrics::centre_distance), evaluated 1.0 / d_jE; at the goal itself
/// (d = 0) eta is the given constant `at_goal`. Depends on j only, not on the current cell.
/// One function for two rules: the classic MATLAB ant-colony script's eta (Eta(E) = 100,
/// at_goal = 100, planner aco-classic) and cin2021 Eq. (30)'s alternative reading
/// `eta = goal_inverse` (d_GG := 1/2, i.e. at_goal = 2, planners aco-cin / hga-aco-cin).
/// Source: the classic ACO grid script (../shared/data/matlab-maps/README.txt, yiqun2.m);
/// cin2021 Eq. (30), Sec. 5.5.1, doi:10.1155/2021/8025730.
/// Spec: classic.plan.aco, cin2021.eq30
/// Pre: |coordinates| <= 2^25; at_goal finite > 0 (DomainError).
/// Post: > 0; = at_goal iff j == goal; strictly decreasing in d_jE elsewhere.
/// Golden: golden/classic/classic.plan.aco.json (through the planner),
/// golden/cin2021-hga-aco/cin2021.eq30.json
[[nodiscard]] double eta_goal_inverse(grid::Cell j, grid::Cell goal, double at_goal);

/// Pheromone update tau(t+1) = (1 - rho) tau(t) + delta, evaluated as ((1 - rho) * tau) + delta.
/// Source: Shi et al. 2022, Eq. (5), Sec. 4.1, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq5, cin2021.eq31, cin2021.eq34 (delta = 0)
/// Pre: tau finite >= 0; 0 < rho < 1; delta finite >= 0; result finite (DomainError).
/// Post: result >= (1 - rho) tau; result == (1 - rho) * tau when delta == 0; > 0 when tau > 0.
/// Golden: golden/shi2022/shi2022.eq5.json
[[nodiscard]] double pheromone_update(double tau, double rho, double delta);

/// Total deposit on one edge, delta_ij = sum over ants k = 1..m of delta_ij^k, accumulated left
/// to right in ant order. Source: Shi et al. 2022, Eq. (6), doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq6
/// Pre: every deposit finite >= 0; the sum finite (DomainError). No ants: 0.
/// Post: >= 0; >= every single deposit.
/// Golden: golden/shi2022/shi2022.eq6.json
[[nodiscard]] double total_deposit(std::span<const double> per_ant);

/// The ant-cycle deposit Q / L_k of ant k (L_k the length of its path, metrics::path_length).
/// Source: Shi et al. 2022, Eq. (7), Sec. 4.1, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq7
/// Pre: Q finite > 0; L finite > 0 (DomainError).
/// Golden: golden/shi2022/shi2022.eq7.json
[[nodiscard]] double ant_cycle_deposit(double Q, double L);

/// Whether pheromone edges are directed (tau_ij != tau_ji) or shared by both directions.
enum class EdgeSense {
  directed,    ///< a step i -> j deposits on (i, j) only (default)
  undirected,  ///< a step i -> j deposits on (i, j) and (j, i)
};
/// "directed" | "undirected" -> EdgeSense; UsageError otherwise. Spec: shi2022.eq7.
[[nodiscard]] EdgeSense parse_edge_sense(std::string_view name);

/// How often an ant whose path uses an edge several times deposits on it.
enum class EdgeRepeats {
  once,           ///< Q/L_k once if the ant "goes by" the edge at all (default, as printed)
  per_traversal,  ///< (number of traversals) * (Q/L_k)
};
/// "once" | "per_traversal" -> EdgeRepeats; UsageError otherwise. Spec: shi2022.eq7.
[[nodiscard]] EdgeRepeats parse_edge_repeats(std::string_view name);

/// Eq. (7) for one ant and one edge (from, to): Q / L_k if the ant's path goes by the edge,
/// else 0, with L_k = metrics::path_length(path). The multiplicity is 1 (`once`) or the number of
/// traversals (`per_traversal`, evaluated count * (Q / L_k)).
/// Source: Shi et al. 2022, Eq. (7), Sec. 4.1, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq7
/// Pre: the metrics path domain with at least 2 nodes; from != to; Q finite > 0 (DomainError).
/// Post: 0 or a positive multiple of Q / L_k.
/// Interpretation: EdgeSense (default directed), EdgeRepeats (default once).
/// Golden: golden/shi2022/shi2022.eq7.json
[[nodiscard]] double edge_deposit(std::span<const grid::Cell> path, grid::Cell from, grid::Cell to,
                                  double Q, EdgeSense sense = EdgeSense::directed,
                                  EdgeRepeats repeats = EdgeRepeats::once);

/// How the printed Eq. (13) is read (spec shi2022.eq13, "Reading").
enum class RhoReading {
  factor,     ///< rho(t+1) = v if v > rho_min else rho_min, v = T/(T+t) * e^-(1-rho(t)) * rho(t) (default)
  condition,  ///< rho(t+1) = T/(T+t) * e^-(1-rho(t)) if rho(t) > rho_min else rho_min
  clamp,      ///< rho(t+1) = w if w > rho_min else rho_min, w = T/(T+t) * e^-(1-rho(t))
};
/// "factor" | "condition" | "clamp" -> RhoReading; UsageError otherwise. Spec: shi2022.eq13.
[[nodiscard]] RhoReading parse_rho_reading(std::string_view name);

/// Adaptive evaporation factor rho(t+1) from rho(t). In binary64: a = double(T) / double(T + t),
/// b = 1.0 / exp(1.0 - rho), then v = (a * b) * rho (factor) or a * b (condition, clamp).
/// Source: Shi et al. 2022, Eq. (13), Sec. 4.4.1, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq13
/// Pre: 1 <= T <= 2^31; 0 <= t <= T; 0 < rho < 1; 0 <= rho_min < 1 (DomainError).
/// Post (factor): rho_min <= result; result <= max(rho, rho_min); result < 1.
/// Interpretation: RhoReading (default factor). rho_min = 0 gives the paper's IACO* (no floor).
/// Golden: golden/shi2022/shi2022.eq13.json
[[nodiscard]] double adaptive_rho(double rho, std::int64_t t, std::int64_t T, double rho_min,
                                  RhoReading reading = RhoReading::factor);

/// Elite term of Han (IJACSA) Eq. (6), h (L_a - L_n) / L_n, evaluated (h * (L_a - L_n)) / L_n:
/// positive when this iteration's best L_n beat the best before it L_a, negative when it did not.
/// Source: Han (IJACSA), Eq. (6), Sec. III.A ("L_a and L_n are the optimal values in the
/// iteration history and the optimal values in this iteration"; the second "L_n", "the adjustable
/// coefficient", is h).
/// Spec: han.eq6
/// Pre: h finite >= 0; L_a, L_n finite > 0 (DomainError). In the first iteration there is no
/// history: the planner passes L_a = L_n (bonus 0).
/// Post: sign(L_a - L_n) (or 0 when h == 0); exactly 0 when L_a == L_n.
/// Golden: golden/han/han.eq6.json
[[nodiscard]] double elite_bonus(double h, double L_a, double L_n);

/// Han (IJACSA) Eq. (6) on one edge: tau(t+n) = max(((1 - rho) tau + delta) + bonus, tau_min),
/// where ((1 - rho) tau + delta) is pheromone_update (Shi Eq. 5) and bonus is elite_bonus on the
/// edges of this iteration's best path and 0 elsewhere (the planner's choice of edges; spec
/// han.eq6). The floor tau_min keeps tau positive when the bonus is negative.
/// Source: Han (IJACSA), Eq. (6), Sec. III.A.
/// Spec: han.eq6
/// Pre: as pheromone_update; bonus finite; tau_min finite > 0 (DomainError).
/// Post: result >= tau_min > 0; equals max(pheromone_update(tau, rho, delta), tau_min) when
/// bonus == 0.
/// Golden: golden/han/han.eq6.json
[[nodiscard]] double pheromone_update_elite(double tau, double rho, double delta, double bonus,
                                            double tau_min);

}  // namespace pathref::aco
