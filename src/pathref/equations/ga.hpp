#pragma once
/// \file ga.hpp
/// Genetic-algorithm equations for grid path planning as pure functions: the continuity test and
/// mid-point insertion of the initial population, the length fitness 1/length, the weighted
/// multi-objective fitness with its smoothness and safety factors, and the adaptive crossover and
/// mutation probabilities. GA planners and the GA-ACO hybrids compose these; roulette selection
/// is equations::proportional_probabilities (Eq. 11) with the draw rng::roulette.
/// Spec: spec/shi2022.md (shi2022.eq8, eq9, eq10, eq14, eq15, eq16, eq17, eq18, eq19, eq20)
#include <cstdint>
#include <span>
#include <string_view>

#include "pathref/equations/metrics.hpp"
#include "pathref/grid/grid.hpp"

namespace pathref::ga {

/// Continuity measure Delta = max(|x_{i+1} - x_i|, |y_{i+1} - y_i|) of two consecutive genes:
/// the Chebyshev distance (heuristics::chebyshev, rule search.h.chebyshev), as an integer.
/// Source: Shi et al. 2022, Eq. (8), Sec. 4.2, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq8
/// Pre: |coordinates| < 2^30 (DomainError). Post: >= 0; 0 iff a == b.
/// Golden: golden/shi2022/shi2022.eq8.json
[[nodiscard]] std::int64_t continuity_delta(grid::Cell a, grid::Cell b);

/// The continuity test of Eq. (8): Delta == 1, i.e. b is one of the 8 neighbours of a.
/// Delta == 0 (the same cell twice) is not continuous. Spec: shi2022.eq8.
/// Pre: as continuity_delta. Golden: golden/shi2022/shi2022.eq8.json
[[nodiscard]] bool is_continuous(grid::Cell a, grid::Cell b);

/// How "int" of Eq. (9) rounds the mean of two non-negative integer coordinates, which is an
/// integer or an integer + 1/2 (spec shi2022.eq9).
enum class MidRounding {
  floor,      ///< floor((a + b) / 2) (default; MATLAB floor and fix, C integer division)
  ceil,       ///< ceil((a + b) / 2); equals MATLAB round and C round (half away from zero) here
  half_even,  ///< ties to even (NumPy round, Python round)
};
/// "floor" | "ceil" | "half_even" -> MidRounding; UsageError otherwise. Spec: shi2022.eq9.
[[nodiscard]] MidRounding parse_mid_rounding(std::string_view name);

/// What P'_i of Eq. (9) is (spec shi2022.eq9).
enum class MidNumber {
  row_major,    ///< the cell number y' * W + x' of rule grid.index (default)
  printed_sum,  ///< x' + y' as printed (not a cell number; for comparison only)
};
/// "row_major" | "printed_sum" -> MidNumber; UsageError otherwise. Spec: shi2022.eq9.
[[nodiscard]] MidNumber parse_mid_number(std::string_view name);

/// The inserted cell (x', y') = (int[(x_a + x_b) / 2], int[(y_a + y_b) / 2]) between two
/// non-continuous genes, in exact integer arithmetic.
/// Source: Shi et al. 2022, Eq. (9), Sec. 4.2, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq9
/// Pre: 0 <= coordinates < 2^30 (DomainError).
/// Post: min(a, b) <= result <= max(a, b) coordinate-wise (in the bounding box); when
/// continuity_delta(a, b) >= 2 the result differs from both a and b.
/// Interpretation: MidRounding (default floor).
/// Golden: golden/shi2022/shi2022.eq9.json
[[nodiscard]] grid::Cell insertion_cell(grid::Cell a, grid::Cell b,
                                        MidRounding rounding = MidRounding::floor);

/// P'_i of Eq. (9): the number of insertion_cell(a, b) on a W x H grid.
/// Spec: shi2022.eq9
/// Pre: a, b inside the W x H grid; W, H >= 1, W * H <= grid::Grid::max_cells (DomainError).
/// Post (row_major): 0 <= result < W * H and grid::index_cell(result) == insertion_cell(a, b).
/// Interpretation: MidRounding (default floor), MidNumber (default row_major).
/// Golden: golden/shi2022/shi2022.eq9.json
[[nodiscard]] std::int64_t insertion_number(grid::Cell a, grid::Cell b, std::int64_t width,
                                            std::int64_t height,
                                            MidRounding rounding = MidRounding::floor,
                                            MidNumber form = MidNumber::row_major);

/// Length fitness fit = 1 / length (Eq. 10), which is also the length factor fit_1 (Eq. 15);
/// length = metrics::path_length of the path. Evaluated as 1.0 / length.
/// Source: Shi et al. 2022, Eq. (10), Sec. 4.2 and Eq. (15), Sec. 4.4.2,
/// doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq10, shi2022.eq15, cin2021.eq20 (f1 of cin2021 Eq. 20, doi:10.1155/2021/8025730)
/// Pre: length finite and > 0 (DomainError; a one-node path has no fitness).
/// Post: > 0; strictly decreasing in length.
/// Golden: golden/shi2022/shi2022.eq10.json, golden/shi2022/shi2022.eq15.json
[[nodiscard]] double inverse_length(double length);

/// The weights a, b, c of Eq. (14); defaults from Table 1.
struct FitnessWeights {
  double a = 5.0;
  double b = 4.0;
  double c = 1.0;
};

/// Weighted fitness fit = a fit_1 + b fit_2 + c fit_3, evaluated ((a*f1) + (b*f2)) + (c*f3).
/// Source: Shi et al. 2022, Eq. (14), Sec. 4.4.2, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq14, cin2021.eq26 (f = a f1 + b f2 is this function with c = 0)
/// Pre: a, b, c, fit_1, fit_2, fit_3 finite and >= 0; result finite (DomainError).
/// Post: >= 0; non-decreasing in each factor.
/// Golden: golden/shi2022/shi2022.eq14.json
[[nodiscard]] double weighted_fitness(double fit1, double fit2, double fit3,
                                      FitnessWeights w = FitnessWeights{});

/// The turning-angle band of an interior node, from the paper's penalty classes.
enum class TurnBand {
  straight = 0,  ///< theta = 0
  up_to_45 = 1,  ///< 0 < theta <= 45 degrees
  up_to_90 = 2,  ///< 45 < theta <= 90 degrees
  above_90 = 3,  ///< 90 < theta <= 180 degrees (a reversal, theta = 180, included)
};

/// Band of the turning angle theta at b on a -> b -> c (theta as metrics::turning_angle), decided
/// in exact integer arithmetic from u = b - a, v = c - b: straight iff u x v == 0 and u . v > 0;
/// up_to_45 iff u . v > 0 and |u x v| <= u . v (and not straight); up_to_90 iff u . v >= 0
/// (otherwise); above_90 iff u . v < 0.
/// Source: Shi et al. 2022, text after Eq. (17), Sec. 4.4.2, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq17
/// Pre: a != b, b != c, |coordinates| <= 2^25 (DomainError).
/// Golden: golden/shi2022/shi2022.eq17.json
[[nodiscard]] TurnBand turn_band(grid::Cell a, grid::Cell b, grid::Cell c);

/// The penalties of the three turning bands (Sec. 4.4.2: 5, 100 and 1000).
struct TurnPenalties {
  double up_to_45 = 5.0;
  double up_to_90 = 100.0;
  double above_90 = 1000.0;
};

/// How the penalties enter fit_2 = sum 1/theta (spec shi2022.eq16, "Reading").
enum class SmoothnessReading {
  per_node,             ///< sum over interior nodes of 1/P, P = 1 straight, else the band's penalty
  per_turn,             ///< sum over turning nodes of 1/P (straight nodes add 0)
  angle_times_penalty,  ///< sum over turning nodes of 1/(P * theta), theta in radians
  inverse_total,        ///< 1 / (sum over turning nodes of P); DomainError for a turn-free path
  inverse_total_plus_one,  ///< 1 / (1 + sum over turning nodes of P); 1 for a turn-free path
                           ///< (the planners' default, spec shi2022.eq16 "Reading")
};
/// "per_node" | "per_turn" | "angle_times_penalty" | "inverse_total" | "inverse_total_plus_one"
/// -> SmoothnessReading; UsageError otherwise. Spec: shi2022.eq16.
[[nodiscard]] SmoothnessReading parse_smoothness_reading(std::string_view name);

/// Smoothness factor fit_2 of a path (Eq. 16), from the turning bands (turn_band) and, for
/// angle_times_penalty, the turning angles (metrics::turning_angle). Terms are added left to right
/// over the interior nodes k = 1..n-2; each term is evaluated 1.0 / P (resp. 1.0 / (P * theta)).
/// Source: Shi et al. 2022, Eq. (16)-(17) and the penalty text, Sec. 4.4.2,
/// doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq16
/// Pre: the metrics path domain; penalties finite and > 0 (DomainError); inverse_total needs at
/// least one turn (DomainError).
/// Post (per_node): 0 <= fit_2 <= n - 2; > 0 when n >= 3; each straight node adds exactly 1.
/// Post (inverse_total_plus_one): 0 < fit_2 <= 1, == 1 iff the path has no turn; strictly
/// decreasing in the total penalty.
/// Interpretation: SmoothnessReading (default inverse_total_plus_one).
/// Golden: golden/shi2022/shi2022.eq16.json
[[nodiscard]] double smoothness_factor(std::span<const grid::Cell> path,
                                       SmoothnessReading reading = SmoothnessReading::inverse_total_plus_one,
                                       TurnPenalties penalties = TurnPenalties{});

/// What S_i of Eq. (18) counts (spec shi2022.eq18).
enum class SafetyCount {
  count,      ///< the number of blocked 8-neighbours (default)
  indicator,  ///< 1 if any 8-neighbour is blocked, else 0
};
/// What a node with no blocked neighbour contributes (spec shi2022.eq18).
enum class SafeNode {
  one,   ///< S_i = 1 + (count or indicator), so a safe node adds 1/1 = 1 (default)
  skip,  ///< S_i = count or indicator; a safe node (S_i = 0) adds nothing
};
/// Which path nodes p_0..p_{n-1} the sum of Eq. (18) covers (spec shi2022.eq18).
enum class SafetyNodes {
  all_but_goal,  ///< i = 1..n-1 of the 1-based p_1..p_n: every node but the goal (default)
  all,           ///< every node
  interior,      ///< every node but the start and the goal
};
/// How the per-node hazards of Eq. (18) combine into fit_3 (spec shi2022.eq18, "Which aggregate").
enum class SafetyAggregate {
  inverse_total_plus_one,  ///< 1 / (1 + sum of the hazard counts); 1 for a path touching no obstacle
                           ///< (the planners' default since issue 11, the convention of Eq. 16)
  per_node,                ///< sum of 1/S_i over the nodes, as printed (grows with the node count)
  mean,                    ///< the per_node sum divided by the number of nodes summed
};
/// Parsers; UsageError on unknown names. Spec: shi2022.eq18.
[[nodiscard]] SafetyAggregate parse_safety_aggregate(std::string_view name);
[[nodiscard]] SafetyCount parse_safety_count(std::string_view name);
[[nodiscard]] SafeNode parse_safe_node(std::string_view name);
[[nodiscard]] SafetyNodes parse_safety_nodes(std::string_view name);

/// The readings of Eq. (18) together; the defaults are pathref's reading.
struct SafetyOptions {
  SafetyAggregate aggregate = SafetyAggregate::inverse_total_plus_one;
  SafetyCount count = SafetyCount::count;
  SafeNode safe = SafeNode::one;
  SafetyNodes nodes = SafetyNodes::all_but_goal;
  metrics::OutsideCells outside = metrics::OutsideCells::free;
};

/// Safety factor fit_3 of Eq. (18) over the selected nodes, from the per-node counts s_k of
/// metrics::safety_counts (or their 0/1 indicator). Default (SafetyAggregate::inverse_total_plus_one):
/// fit_3 = 1.0 / (1 + T) with the integer total T = sum_k s_k. per_node (as printed):
/// fit_3 = sum_k 1.0 / S_k added left to right, S_k = 1 + s_k (SafeNode::one) or s_k (skip, a node
/// with S_k = 0 adds nothing). mean: that sum divided by the number of nodes summed (0 if none).
/// Source: Shi et al. 2022, Eq. (18) and the text after it, Sec. 4.4.2,
/// doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq18
/// Pre: path non-empty, no consecutive repeats, every node inside g (DomainError).
/// Post (default): 0 < fit_3 <= 1, == 1 iff no summed node has a blocked neighbour, strictly
/// decreasing in T; adding a node never increases it. Post (per_node, SafeNode::one): each term in
/// [1/9, 1]; fit_3 > 0 when n >= 2. Post (mean, SafeNode::one): fit_3 in [1/9, 1] when n >= 2.
/// Interpretation: SafetyAggregate, SafetyCount, SafeNode (per_node and mean only), SafetyNodes,
/// metrics::OutsideCells.
/// Golden: golden/shi2022/shi2022.eq18.json
[[nodiscard]] double safety_factor(const grid::Grid& g, std::span<const grid::Cell> path,
                                   SafetyOptions options = SafetyOptions{});

/// Adaptive crossover probability P_c(i) = scale * cos((pi/2) * i / (M_g + i)), evaluated
/// r = double(i) / double(M_g + i), c = cos(half_pi * r), scale * c, half_pi = pi / 2 in binary64.
/// scale = 1 is the printed Eq. (19); scale = Table 1's P_c = 0.8 is the reading `scaled`.
/// Source: Shi et al. 2022, Eq. (19), Sec. 4.4.2, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq19
/// Pre: 1 <= M_g <= 2^31; 0 <= i <= M_g; 0 < scale <= 1 (DomainError).
/// Post: scale * cos(pi/4) <= P_c <= scale (up to rounding); P_c(0) == scale; non-increasing in i.
/// Golden: golden/shi2022/shi2022.eq19.json
[[nodiscard]] double adaptive_pc(std::int64_t i, std::int64_t max_generations, double scale = 1.0);

/// The value of Eq. (20) at i = 0, where the exact value cos(pi/2) = 0 (spec shi2022.eq20).
enum class PmAtZero {
  binary64,    ///< cos(half_pi) in binary64 = 6.123233995736766e-17, as MATLAB/NumPy give (default)
  exact_zero,  ///< 0 exactly
};
/// "binary64" | "exact_zero" -> PmAtZero; UsageError otherwise. Spec: shi2022.eq20.
[[nodiscard]] PmAtZero parse_pm_at_zero(std::string_view name);

/// Adaptive mutation probability of Eq. (20): m = scale * cos((pi/2) * (M_g - i) / (M_g + i))
/// (r = double(M_g - i) / double(M_g + i), m = scale * cos(half_pi * r)); P_m = m if m < P_m_max,
/// else P_m_max. scale = 1 is the printed form; 0.1 (Table 1's P_m) the reading `scaled`.
/// Source: Shi et al. 2022, Eq. (20), Sec. 4.4.2, doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq20
/// Pre: 1 <= M_g <= 2^31; 0 <= i <= M_g; 0 < pm_max <= 1; 0 < scale <= 1 (DomainError).
/// Post: 0 <= P_m <= pm_max; non-decreasing in i.
/// Interpretation: PmAtZero (default binary64).
/// Golden: golden/shi2022/shi2022.eq20.json
[[nodiscard]] double adaptive_pm(std::int64_t i, std::int64_t max_generations, double pm_max,
                                 double scale = 1.0, PmAtZero at_zero = PmAtZero::binary64);

}  // namespace pathref::ga
