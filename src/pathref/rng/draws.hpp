#pragma once
/// \file draws.hpp
/// Every random decision of pathref, defined from one uniform double u in [0, 1) drawn from
/// rng::Stream. These are pure functions: the draw is an argument (Wycheproof's `rnd` lesson),
/// so golden vectors can pin a decision without pinning a generator.
/// Spec: spec/rng.md
#include <cmath>
#include <cstddef>
#include <span>

namespace pathref::rng {

namespace detail {
/// The DomainErrors of uniform_index (out of line: they are never on the hot path).
[[noreturn]] void throw_not_unit();
[[noreturn]] void throw_empty_range();
}  // namespace detail

/// Integer in [0, n) from u: floor(u * n).
/// Spec: rng.index. Pre: n >= 1, 0 <= u < 1 (DomainError otherwise).
/// Post: result in [0, n). Golden: golden/rng/rng.index.json
/// (Inline: the GA initialisation calls it once per gene.)
[[nodiscard]] inline std::size_t uniform_index(double u, std::size_t n) {
  if (!(std::isfinite(u) && u >= 0.0 && u < 1.0)) [[unlikely]] detail::throw_not_unit();
  if (n < 1) [[unlikely]] detail::throw_empty_range();
  // floor(u * n): u * n >= 0, so the truncating conversion is the floor (no libm call); a
  // product that rounds up to 2^64 (n near 2^64) would not convert, and clamps like below.
  const double x = u * static_cast<double>(n);
  if (x >= 0x1p64) return n - 1;
  const auto k = static_cast<std::size_t>(x);
  // u < 1 but u * n can round up to n for huge n; clamp keeps the post-condition.
  return k < n ? k : n - 1;
}

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
