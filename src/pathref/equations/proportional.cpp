#include "pathref/equations/proportional.hpp"

#include <cmath>

#include "pathref/core/error.hpp"

namespace pathref::equations {

std::vector<double> proportional_probabilities(std::span<const double> weights) {
  require(!weights.empty(), "proportional probabilities need at least one weight (empty set)");
  double total = 0.0;
  for (const double w : weights) {
    require(std::isfinite(w) && w >= 0.0, "weights must be finite and >= 0");
    total += w;
  }
  require(std::isfinite(total), "the sum of the weights overflows");
  require(total > 0.0, "the weights sum to 0: no candidate can be chosen");
  std::vector<double> p;
  p.reserve(weights.size());
  for (const double w : weights) p.push_back(w / total);
  return p;
}

}  // namespace pathref::equations
