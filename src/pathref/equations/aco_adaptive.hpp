#pragma once
/// \file aco_adaptive.hpp
/// Adaptive ACO parameters of Han (IJACSA): the exploitation threshold q0 that falls linearly
/// over the iterations (Eq. 5) and the stepped evaporation factor rho (Eq. 7). Pure functions of
/// the iteration counters and path lengths; the planner keeps the state.
/// Spec: spec/han.md (han.eq5, han.eq7)
#include <cstdint>
#include <string_view>

namespace pathref::aco {

/// Eq. (5): q0 = epsilon * (0.2 + ((N_max - N_c) / N_max) * 0.7), evaluated in binary64 as
/// r = double(N_max - N_c) / double(N_max); q0 = epsilon * (0.2 + (r * 0.7)).
/// Source: Han (IJACSA), Eq. (5), Sec. III.A: "epsilon is the adjustment coefficient; N_max, N_c
/// serves as the maximum quantity of iterations and the current quantity of iterations".
/// Spec: han.eq5
/// Pre: 1 <= N_max <= 2^31; 0 <= N_c <= N_max; epsilon finite > 0; the result <= 1 (DomainError;
/// epsilon <= 1 always satisfies the last).
/// Post: fl(0.2 epsilon) <= q0 <= fl(0.9 epsilon); non-increasing in N_c; q0 = fl(0.2 epsilon)
/// at N_c = N_max and fl(epsilon * fl(0.2 + 0.7)) (= 0.8999999999999999 for epsilon = 1) at
/// N_c = 0.
/// Golden: golden/han/han.eq5.json
[[nodiscard]] double adaptive_q0(double epsilon, std::int64_t N_c, std::int64_t N_max);

/// Which length Eq. (7) subtracts L_n from (spec han.eq7, "Reading").
enum class SpreadReference {
  iteration_worst,  ///< L_A = the worst (longest) length of this iteration (default; the prose)
  history_best,     ///< L_a = the best length before this iteration (the printed symbol)
};
/// "iteration_worst" | "history_best" -> SpreadReference; UsageError otherwise. Spec: han.eq7.
[[nodiscard]] SpreadReference parse_spread_reference(std::string_view name);

/// Eq. (7), stepped evaporation: with d = L_ref - L_n (binary64),
/// f = 0.9 if d > b, 0.8 if a < d <= b, 0.7 if d <= a; rho(t) = max(f * rho(t-1), rho_min).
/// Source: Han (IJACSA), Eq. (7), Sec. III.A: "L_A is the worst case path in the current
/// calculation result; a and b are two constants".
/// Spec: han.eq7
/// Pre: 0 < rho_prev < 1; 0 <= rho_min < 1; a, b finite, 0 <= a < b; L_ref, L_n finite > 0;
/// with iteration_worst, L_ref >= L_n (the worst is not shorter than the best) (DomainError).
/// Post: rho_min <= result <= max(0.9 rho_prev, rho_min) < 1; result > 0 (DomainError on
/// underflow to 0, which needs rho_prev < 2^-1021).
/// Interpretation: SpreadReference (default iteration_worst).
/// Golden: golden/han/han.eq7.json
[[nodiscard]] double stepped_rho(double rho_prev, double L_ref, double L_n, double a, double b,
                                 double rho_min,
                                 SpreadReference ref = SpreadReference::iteration_worst);

}  // namespace pathref::aco
