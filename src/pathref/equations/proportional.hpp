#pragma once
/// \file proportional.hpp
/// Proportional (roulette-wheel) probabilities p_k = w_k / sum(w): the normalisation shared by an
/// ant's transition rule (Shi 2022 Eq. 2, Han Eq. 1) and the GA's roulette selection (Shi 2022
/// Eq. 11). The random draw itself is rng::roulette, which takes the same unnormalised weights.
/// Spec: spec/shi2022.md (shi2022.eq2, shi2022.eq11)
#include <span>
#include <vector>

namespace pathref::equations {

/// Probabilities proportional to non-negative weights: p_k = w_k / S with
/// S = w_0 + w_1 + ... + w_{n-1} accumulated left to right in binary64, then one division per k.
/// Source: Shi et al. 2022, Eq. (2) (the denominator over allowed_k) and Eq. (11)
/// (p_i = F_i / sum F_i), doi:10.3389/fbioe.2022.905983.
/// Spec: shi2022.eq2, shi2022.eq11, cin2021.eq27 (roulette P_i = f(i) / sum f), cin2021.eq29
/// Pre: weights non-empty, every w_k finite and >= 0, S > 0 and finite (DomainError otherwise:
/// an empty allowed set, a dead end, is the caller's case to handle, never a silent guess).
/// Post: p.size() == weights.size(); 0 <= p_k <= 1; p_k == 0 when w_k == 0; without underflow
/// |sum_k p_k - 1| <= 2 n 2^-53 (n = number of weights), the sum taken left to right.
/// Golden: golden/shi2022/shi2022.eq2.json, golden/shi2022/shi2022.eq11.json
[[nodiscard]] std::vector<double> proportional_probabilities(std::span<const double> weights);

}  // namespace pathref::equations
