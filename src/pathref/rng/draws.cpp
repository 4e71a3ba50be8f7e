#include "pathref/rng/draws.hpp"

#include <cmath>

#include "pathref/core/error.hpp"

namespace pathref::rng {

namespace {
void require_unit(double u) {
  require(std::isfinite(u) && u >= 0.0 && u < 1.0, "u must lie in [0, 1)");
}
}  // namespace

namespace detail {
void throw_not_unit() { throw DomainError("u must lie in [0, 1)"); }
void throw_empty_range() { throw DomainError("n must be at least 1"); }
}  // namespace detail

std::size_t roulette(std::span<const double> weights, double u) {
  require_unit(u);
  require(!weights.empty(), "roulette needs at least one weight");
  double total = 0.0;
  for (const double w : weights) {
    require(std::isfinite(w) && w >= 0.0, "roulette weights must be finite and >= 0");
    total += w;
  }
  require(total > 0.0 && std::isfinite(total), "roulette weights must have a positive finite sum");
  const double target = u * total;
  double cumsum = 0.0;
  std::size_t last_positive = 0;
  for (std::size_t k = 0; k < weights.size(); ++k) {
    cumsum += weights[k];
    if (weights[k] > 0.0) {
      last_positive = k;
      if (cumsum >= target) return k;
    }
  }
  // Unreachable: cumsum after the last element equals total >= u * total. Kept for safety.
  return last_positive;
}

bool bernoulli(double u, double p) {
  require_unit(u);
  require(std::isfinite(p) && p >= 0.0 && p <= 1.0, "p must lie in [0, 1]");
  return u < p;
}

}  // namespace pathref::rng
