#include "pathref/equations/aco_adaptive.hpp"

#include <cmath>
#include <string>

#include "pathref/core/error.hpp"

namespace pathref::aco {

double adaptive_q0(double epsilon, std::int64_t N_c, std::int64_t N_max) {
  require(N_max >= 1 && N_max <= (std::int64_t{1} << 31), "N_max must lie in [1, 2^31]");
  require(N_c >= 0 && N_c <= N_max, "N_c must lie in [0, N_max]");
  require(std::isfinite(epsilon) && epsilon > 0.0, "epsilon must be finite and > 0");
  const double r = static_cast<double>(N_max - N_c) / static_cast<double>(N_max);
  const double q0 = epsilon * (0.2 + (r * 0.7));
  require(q0 <= 1.0, "q0 exceeds 1: epsilon is too large (epsilon <= 1 is always fine)");
  return q0;
}

SpreadReference parse_spread_reference(std::string_view name) {
  if (name == "iteration_worst") return SpreadReference::iteration_worst;
  if (name == "history_best") return SpreadReference::history_best;
  throw UsageError("unknown Eq. 7 spread reference '" + std::string(name) +
                   "' (expected iteration_worst or history_best)");
}

double stepped_rho(double rho_prev, double L_ref, double L_n, double a, double b, double rho_min,
                   SpreadReference ref) {
  require(std::isfinite(rho_prev) && rho_prev > 0.0 && rho_prev < 1.0,
          "rho(t-1) must lie in (0, 1)");
  require(std::isfinite(rho_min) && rho_min >= 0.0 && rho_min < 1.0, "rho_min must lie in [0, 1)");
  require(std::isfinite(a) && std::isfinite(b) && a >= 0.0 && a < b, "need 0 <= a < b, finite");
  require(std::isfinite(L_ref) && L_ref > 0.0 && std::isfinite(L_n) && L_n > 0.0,
          "path lengths must be finite and > 0");
  if (ref == SpreadReference::iteration_worst)
    require(L_ref >= L_n, "the iteration's worst length L_A must be >= its best length L_n");
  const double d = L_ref - L_n;
  const double f = d > b ? 0.9 : (d > a ? 0.8 : 0.7);
  const double v = f * rho_prev;
  const double next = v > rho_min ? v : rho_min;
  require(next > 0.0, "rho underflows to 0");
  return next;
}

}  // namespace pathref::aco
