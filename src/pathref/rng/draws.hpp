#pragma once
/// \file draws.hpp
/// Every random decision of pathref, defined from one uniform double u in [0, 1) drawn from
/// rng::Stream. These are pure functions: the draw is an argument (Wycheproof's `rnd` lesson),
/// so golden vectors can pin a decision without pinning a generator.
/// Spec: spec/rng.md
#include <cstddef>
#include <span>

namespace pathref::rng {

/// Integer in [0, n) from u: floor(u * n).
/// Spec: rng.index. Pre: n >= 1, 0 <= u < 1 (DomainError otherwise).
/// Post: result in [0, n). Golden: golden/rng/rng.index.json
[[nodiscard]] std::size_t uniform_index(double u, std::size_t n);

/// Roulette-wheel choice over non-negative weights in canonical order: the first k with
/// w_k > 0 and cumsum_k >= u * sum(w), where cumsum and sum are accumulated left to right in
/// double (MATLAB's `find(cumsum(P) >= rand, 1)` with unnormalised P).
/// Spec: rng.roulette. Pre: weights non-empty, finite, >= 0, sum > 0; 0 <= u < 1.
/// Post: w[result] > 0. Golden: golden/rng/rng.roulette.json
[[nodiscard]] std::size_t roulette(std::span<const double> weights, double u);

/// Bernoulli(p) from u: u < p.
/// Spec: rng.bernoulli. Pre: 0 <= p <= 1, 0 <= u < 1. Golden: golden/rng/rng.bernoulli.json
[[nodiscard]] bool bernoulli(double u, double p);

}  // namespace pathref::rng
