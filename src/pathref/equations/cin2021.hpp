#pragma once
/// \file cin2021.hpp
/// The equations of HGA-ACO (cin2021 §5, Computational Intelligence and Neuroscience 2021,
/// article 8025730, doi:10.1155/2021/8025730) that no earlier paper's function already serves:
/// the path model's cos theta and smoothness (Eq. 17-18), the GA's node distances, included angle,
/// corner penalty and smoothness fitness (Eq. 21-25), the GA-to-ACO pheromone conversion
/// (Eq. 28), the goal heuristic 1/d_jG (Eq. 30 alternative), the weighted iteration-best /
/// global-best deposit and its moving weights (Eq. 32-33) and the dead-angle penalty (Eq. 35).
/// Every equation is RECONSTRUCTED (the paper's formula images were lost); the spec names the
/// reading and its alternatives. Shared concepts (length, 1/L, a f1 + b f2, roulette, transition
/// rule, 1/d_ij, the update) are the functions of metrics.hpp, ga.hpp, proportional.hpp, aco.hpp.
/// Spec: spec/cin2021-hga-aco.md
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "pathref/grid/grid.hpp"

namespace pathref::cin {

/// cos theta of the two segments a -> b -> c (theta = heading change): the integer dot product
/// of u = b - a and v = c - b, converted to binary64, divided by (|u| * |v|), each |.| a
/// metrics::centre_distance; exactly 1 (-1) when u and v are collinear in the same (opposite)
/// direction (u x v == 0, decided in integers).
/// Source: cin2021 Eq. (18), Sec. 5.1, doi:10.1155/2021/8025730 (reconstructed, grade C).
/// Spec: cin2021.eq18
/// Pre: a != b, b != c, |coordinates| <= 2^25 (DomainError). Post: in [-1, 1]; 1 iff straight on.
/// Golden: golden/cin2021-hga-aco/cin2021.eq18.json
[[nodiscard]] double segment_cosine(grid::Cell a, grid::Cell b, grid::Cell c);

/// Smoothness S(P) = sum over interior nodes of (1 - cos theta_i), cos from segment_cosine,
/// added left to right from 0.
/// Source: cin2021 Eq. (17), Sec. 5.1, doi:10.1155/2021/8025730 (reconstructed, grade C).
/// Spec: cin2021.eq17
/// Pre: no consecutive repeated cells, |coordinates| <= 2^25 (DomainError).
/// Post: 0 <= S <= 2 (n - 2); 0 for n <= 2. Golden: golden/cin2021-hga-aco/cin2021.eq17.json
[[nodiscard]] double smoothness_cost(std::span<const grid::Cell> path);

/// The distances of Eq. (21) and (22).
struct NodeDistances {
  std::vector<double> d1;  ///< d(p_i, p_{i+1}), i = 0..n-2
  std::vector<double> d2;  ///< d(p_i, p_{i+2}), i = 0..n-3
};
/// d1 and d2 of a path (metrics::centre_distance each).
/// Source: cin2021 Eq. (21)-(22), Sec. 5.3.1, doi:10.1155/2021/8025730 (grade A).
/// Spec: cin2021.eq21, cin2021.eq22
/// Pre: |coordinates| <= 2^25 (DomainError). Post: |d1| = max(0, n - 1), |d2| = max(0, n - 2).
/// Golden: golden/cin2021-hga-aco/cin2021.eq21.json, golden/cin2021-hga-aco/cin2021.eq22.json
[[nodiscard]] NodeDistances node_distances(std::span<const grid::Cell> path);

/// How Eq. (23) gets theta (spec cin2021.eq23 "Reading", option `angle`).
enum class AngleReading {
  arccos,  ///< law of cosines on d1, d2 (default)
  lookup,  ///< exact grid lookup from the two steps
};
[[nodiscard]] AngleReading parse_angle_reading(std::string_view name);
[[nodiscard]] std::string_view to_string(AngleReading v) noexcept;

/// Included angle (degrees) at the middle node from the law of cosines, argument clamped to
/// [-1, 1]: num = ((d1a*d1a) + (d1b*d1b)) - (d2*d2), den = (2*d1a)*d1b,
/// theta = acos(clamp(num/den)) * (180/pi). 180 means straight.
/// Source: cin2021 Eq. (23), Sec. 5.3.1, doi:10.1155/2021/8025730 (reconstructed, grade B).
/// Spec: cin2021.eq23
/// Pre: d1a, d1b finite > 0; d2 finite >= 0 (DomainError). Post: in [0, 180].
/// Golden: golden/cin2021-hga-aco/cin2021.eq23.json
[[nodiscard]] double included_angle(double d1a, double d1b, double d2);

/// Included angle (degrees, exact: 0, 45, 90, 135 or 180) at b of two 8-neighbour steps
/// a -> b -> c, decided in integers (180 minus the heading change).
/// Source: cin2021 Eq. (23) "determined by d1 and d2" on the grid (reading `lookup`).
/// Spec: cin2021.eq23
/// Pre: a -> b and b -> c are steps between distinct 8-neighbours (DomainError).
/// Post: equals the penalty class of included_angle on the same nodes (property).
[[nodiscard]] double included_angle_grid(grid::Cell a, grid::Cell b, grid::Cell c);

/// The corner penalties of Eq. (24) (defaults: Shi 2022's 5, 100, 1000 in interior-angle terms;
/// NOT the paper's values, which are lost).
struct CornerPenalties {
  double c135 = 5.0;
  double c90 = 100.0;
  double c45 = 1000.0;
};

/// Tolerance (degrees) of the classes of Eq. (24), absorbing the rounding of the arccos reading.
inline constexpr double angle_epsilon_deg = 1e-3;

/// Corner penalty c_i of Eq. (24): 0 for theta >= 180 - eps, c135 for [135 - eps, 180 - eps),
/// c90 for [90 - eps, 135 - eps), c45 below 90 - eps (eps = angle_epsilon_deg).
/// Source: cin2021 Eq. (24), Sec. 5.3.1, doi:10.1155/2021/8025730 (reconstructed, grade C).
/// Spec: cin2021.eq24
/// Pre: theta finite in [0, 180 + eps]; 0 <= c135 <= c90 <= c45 finite (DomainError).
/// Golden: golden/cin2021-hga-aco/cin2021.eq24.json
[[nodiscard]] double corner_penalty(double theta_deg, CornerPenalties p = CornerPenalties{});

/// The guard of Eq. (25) against a zero penalty sum (option `f2_guard`).
enum class F2Guard {
  one_plus,  ///< 1 / (1 + sum c) (default)
  epsilon,   ///< 1 / (1e-3 + sum c)
};
[[nodiscard]] F2Guard parse_f2_guard(std::string_view name);
[[nodiscard]] std::string_view to_string(F2Guard v) noexcept;

/// Smoothness fitness f2 of Eq. (25): 1 / (guard + sum_i c_i), c_i = corner_penalty of the angle
/// at each interior node (included_angle of node_distances, or included_angle_grid), summed left
/// to right from 0.
/// Source: cin2021 Eq. (25), Sec. 5.3.1, doi:10.1155/2021/8025730 (reconstructed, grade B).
/// Spec: cin2021.eq25
/// Pre: n >= 2, no consecutive repeats, penalties as corner_penalty (DomainError).
/// Post: in (0, 1] under one_plus; 1 for a straight path. Golden: golden/cin2021-hga-aco/cin2021.eq25.json
[[nodiscard]] double smoothness_fitness(std::span<const grid::Cell> path, CornerPenalties p = CornerPenalties{},
                                        F2Guard guard = F2Guard::one_plus,
                                        AngleReading angle = AngleReading::arccos);

/// Which term Eq. (28) adds per converted edge (option `conversion_form`).
enum class ConversionForm {
  q_over_l,    ///< Q / L_k (default)
  q_d_over_l,  ///< Q d_ij / L_k
  q_over_l_d,  ///< Q / (L_k d_ij)
};
[[nodiscard]] ConversionForm parse_conversion_form(std::string_view name);
[[nodiscard]] std::string_view to_string(ConversionForm v) noexcept;

/// The per-row term Delta tau^k_ij of Eq. (28): Q / L, (Q * d) / L or Q / (L * d).
/// Source: cin2021 Eq. (28), Sec. 5.4, doi:10.1155/2021/8025730 (reconstructed, grade C).
/// Spec: cin2021.eq28
/// Pre: Q, L, d finite > 0 (DomainError). Golden: golden/cin2021-hga-aco/cin2021.eq28.json
[[nodiscard]] double conversion_delta(ConversionForm form, double Q, double L, double d);

/// One directed edge with its converted pheromone tau^G.
struct EdgePheromone {
  grid::Cell from;
  grid::Cell to;
  double tau = 0.0;
};

/// tau^G of Eq. (28) over the rows of T: for each row k (in order) and each distinct directed step
/// (p_r, p_{r+1}) of it (first use only), tau^G(edge) += conversion_delta(form, Q, L_k, d_edge),
/// L_k = metrics::path_length of the row; edges in order of first appearance. The colony sets
/// tau(0) = tau_C + tau^G (conversion `add`) or tau^G (`replace`) on these edges.
/// Source: cin2021 Eq. (28), Sec. 5.4 steps (1)-(4), doi:10.1155/2021/8025730.
/// Spec: cin2021.eq28
/// Pre: Q finite > 0; every row >= 2 cells without consecutive repeats (DomainError).
/// Post: every tau > 0; one entry per distinct directed edge.
[[nodiscard]] std::vector<EdgePheromone> converted_pheromone(
    std::span<const std::vector<grid::Cell>> rows, double Q,
    ConversionForm form = ConversionForm::q_over_l);

/// Increment of Eq. (32): (on_ib ? w_ib * (Q / L_ib) : 0) + (on_gb ? w_gb * (Q / L_gb) : 0).
/// Source: cin2021 Eq. (32), Sec. 5.5.1, doi:10.1155/2021/8025730 (reconstructed, grade C).
/// Spec: cin2021.eq32
/// Pre: w finite >= 0, Q finite > 0, L finite > 0 for each term whose indicator is set
/// (DomainError). Post: >= 0. Golden: golden/cin2021-hga-aco/cin2021.eq32.json
[[nodiscard]] double weighted_best_deposit(bool on_ib, double w_ib, double L_ib, bool on_gb,
                                           double w_gb, double L_gb, double Q);

/// Option `weight_norm` of Eq. (33).
enum class WeightNorm {
  raw,         ///< omega_ib = N - t, omega_gb = t (default)
  normalised,  ///< both divided by N
};
[[nodiscard]] WeightNorm parse_weight_norm(std::string_view name);
[[nodiscard]] std::string_view to_string(WeightNorm v) noexcept;

/// The weights of Eq. (33).
struct BestWeights {
  double ib = 0.0;
  double gb = 0.0;
};
/// omega_ib = N - t, omega_gb = t (raw) or both / N (normalised), t = 0..N-1.
/// Source: cin2021 Eq. (33), Sec. 5.5.1, doi:10.1155/2021/8025730 (reconstructed, grade C).
/// Spec: cin2021.eq33
/// Pre: 1 <= N <= 10^6, 0 <= t < N (DomainError). Post: ib + gb == N (raw) or 1 up to rounding.
/// Golden: golden/cin2021-hga-aco/cin2021.eq33.json
[[nodiscard]] BestWeights best_path_weights(std::int64_t t, std::int64_t N,
                                            WeightNorm norm = WeightNorm::raw);

/// Option `lambda_form` of Eq. (35).
enum class LambdaForm {
  lambda,     ///< tau <- lambda tau (default)
  one_minus,  ///< tau <- (1 - lambda) tau
};
[[nodiscard]] LambdaForm parse_lambda_form(std::string_view name);
[[nodiscard]] std::string_view to_string(LambdaForm v) noexcept;

/// Dead-angle penalty of Eq. (35): lambda * tau (or (1 - lambda) * tau).
/// Source: cin2021 Eq. (35), Sec. 5.5.2, doi:10.1155/2021/8025730 (reconstructed, grade B).
/// Spec: cin2021.eq35
/// Pre: 0 < lambda < 1; tau finite >= 0 (DomainError). Post: 0 <= result <= tau.
/// Golden: golden/cin2021-hga-aco/cin2021.eq35.json
[[nodiscard]] double dead_angle_penalty(double tau, double lambda, LambdaForm form = LambdaForm::lambda);

}  // namespace pathref::cin
