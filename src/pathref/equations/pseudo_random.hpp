#pragma once
/// \file pseudo_random.hpp
/// The pseudo-random proportional rule of Han (IJACSA) Eq. (4): with probability q0 the ant
/// takes the candidate of largest weight tau^alpha eta^beta omega^gamma (exploitation), otherwise
/// it draws by roulette on the same weights (Eq. 1). Both draws are explicit arguments, so the
/// choice is a pure function (spec/rng.md).
/// Spec: spec/han.md (han.eq4)
#include <cstddef>
#include <span>

namespace pathref::aco {

/// How a move of Eq. (4) was decided.
enum class ChoiceMode {
  argmax,    ///< q <= q0: the largest weight
  roulette,  ///< q > q0: rng::roulette on the weights with draw u
};

/// The result of Eq. (4): the chosen candidate's position in the allowed list, and the branch.
struct PseudoRandomChoice {
  std::size_t index = 0;
  ChoiceMode mode = ChoiceMode::argmax;
};

/// Position of the largest weight; ties go to the lowest position, i.e. (with the canonical
/// neighbour order of grid.neighbour-order) to the candidate with the lowest cell index.
/// Weights are compared exactly (no tolerance).
/// Source: Han (IJACSA), Eq. (4), first case "arg max [tau]^alpha [eta]^beta [omega]^gamma".
/// Spec: han.eq4
/// Pre: weights non-empty, finite, >= 0, and at least one > 0 (DomainError).
/// Post: weights[result] > 0 and weights[result] >= weights[k] for every k, with
/// weights[k] < weights[result] for every k < result.
/// Golden: golden/han/han.eq4.json
[[nodiscard]] std::size_t argmax_weight(std::span<const double> weights);

/// Eq. (4): if q <= q0 the argmax (argmax_weight), else rng::roulette(weights, u). u is not used
/// when q <= q0 (whether the planner draws it anyway is its option `draw_u`).
/// Source: Han (IJACSA), Eq. (4), Sec. III.A: "q is a uniformly distributed random variable in
/// the range of [0,1], and q0 is the threshold corresponding to the deterministic selection".
/// Spec: han.eq4
/// Pre: as argmax_weight; 0 <= q < 1 and 0 <= u < 1 (draws of rng.res53); 0 <= q0 <= 1
/// (DomainError).
/// Post: weights[index] > 0.
/// Golden: golden/han/han.eq4.json
[[nodiscard]] PseudoRandomChoice pseudo_random_choice(std::span<const double> weights, double q,
                                                      double q0, double u);

}  // namespace pathref::aco
