#include "pathref/equations/pseudo_random.hpp"

#include <cmath>

#include "pathref/core/error.hpp"
#include "pathref/rng/draws.hpp"

namespace pathref::aco {

std::size_t argmax_weight(std::span<const double> weights) {
  require(!weights.empty(), "argmax needs at least one allowed candidate (empty set)");
  std::size_t best = 0;
  for (std::size_t k = 0; k < weights.size(); ++k) {
    require(std::isfinite(weights[k]) && weights[k] >= 0.0, "weights must be finite and >= 0");
    if (weights[k] > weights[best]) best = k;
  }
  require(weights[best] > 0.0, "every weight is 0: no candidate can be chosen");
  return best;
}

PseudoRandomChoice pseudo_random_choice(std::span<const double> weights, double q, double q0,
                                        double u) {
  require(std::isfinite(q) && q >= 0.0 && q < 1.0, "q must lie in [0, 1)");
  require(std::isfinite(u) && u >= 0.0 && u < 1.0, "u must lie in [0, 1)");
  require(std::isfinite(q0) && q0 >= 0.0 && q0 <= 1.0, "q0 must lie in [0, 1]");
  const std::size_t best = argmax_weight(weights);  // validates the weights in both branches
  if (q <= q0) return PseudoRandomChoice{best, ChoiceMode::argmax};
  return PseudoRandomChoice{rng::roulette(weights, u), ChoiceMode::roulette};
}

}  // namespace pathref::aco
