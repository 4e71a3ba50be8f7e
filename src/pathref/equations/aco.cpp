#include "pathref/equations/aco.hpp"

#include <cmath>
#include <string>

#include "pathref/core/error.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/equations/proportional.hpp"

namespace pathref::aco {

namespace {
bool finite_nonneg(double v) { return std::isfinite(v) && v >= 0.0; }
}  // namespace

void transition_weights_into(std::span<const double> tau, std::span<const double> eta_pow,
                             double alpha, std::optional<CornerFactor> corner,
                             std::vector<double>& out) {
  require(!tau.empty(), "transition weights need at least one allowed candidate");
  require(tau.size() == eta_pow.size(), "tau and eta must have one value per candidate");
  require(finite_nonneg(alpha), "alpha and beta must be finite and >= 0");
  if (corner) {
    require(corner->omega.size() == tau.size(), "omega must have one value per candidate");
    require(finite_nonneg(corner->gamma), "gamma must be finite and >= 0");
  }
  out.resize(tau.size());
  for (std::size_t j = 0; j < tau.size(); ++j) {
    require(finite_nonneg(tau[j]), "tau must be finite and >= 0");
    require(eta_pow[j] >= 0.0, "eta must be finite and >= 0");
    // pow(tau, 1) is tau exactly for any pow with an error below one ulp (a faithful result
    // must be the exact value when that is representable), so alpha = 1 skips the call and
    // gives the same double (spec shi2022.eq2, "Evaluation").
    double v = (alpha == 1.0 ? tau[j] : std::pow(tau[j], alpha)) * eta_pow[j];
    if (corner) {
      require(finite_nonneg(corner->omega[j]), "omega must be finite and >= 0");
      v = v * std::pow(corner->omega[j], corner->gamma);
    }
    require(std::isfinite(v), "a transition weight overflows");
    out[j] = v;
  }
}

std::vector<double> transition_weights(std::span<const double> tau, std::span<const double> eta,
                                       double alpha, double beta,
                                       std::optional<CornerFactor> corner) {
  require(finite_nonneg(alpha) && finite_nonneg(beta), "alpha and beta must be finite and >= 0");
  std::vector<double> eta_pow;
  eta_pow.reserve(eta.size());
  for (const double e : eta) {
    require(finite_nonneg(e), "eta must be finite and >= 0");
    eta_pow.push_back(std::pow(e, beta));
  }
  std::vector<double> w;
  transition_weights_into(tau, eta_pow, alpha, corner, w);
  return w;
}

std::vector<double> transition_probabilities(std::span<const double> tau,
                                             std::span<const double> eta, double alpha,
                                             double beta, std::optional<CornerFactor> corner) {
  const std::vector<double> w = transition_weights(tau, eta, alpha, beta, corner);
  return equations::proportional_probabilities(w);
}

double eta_inverse_distance(grid::Cell i, grid::Cell j) {
  require(!(i == j), "eta needs a move: the next cell j must differ from the current cell i");
  return 1.0 / metrics::centre_distance(i, j);
}

double eta_goal_directed(grid::Cell i, grid::Cell j, grid::Cell goal) {
  require(!(i == j), "eta needs a move: the next cell j must differ from the current cell i");
  const double d_ij = metrics::centre_distance(i, j);
  const double d_je = metrics::centre_distance(j, goal);
  return 1.0 / (d_ij + d_je);
}

double eta_goal_inverse(grid::Cell j, grid::Cell goal, double at_goal) {
  require(std::isfinite(at_goal) && at_goal > 0.0, "the goal's eta must be finite and > 0");
  const double d = metrics::centre_distance(j, goal);  // checks the coordinates
  if (j == goal) return at_goal;
  return 1.0 / d;
}

double pheromone_update(double tau, double rho, double delta) {
  require(finite_nonneg(tau), "tau must be finite and >= 0");
  require(std::isfinite(rho) && rho > 0.0 && rho < 1.0, "rho must lie in (0, 1)");
  require(finite_nonneg(delta), "delta must be finite and >= 0");
  const double kept = (1.0 - rho) * tau;
  const double next = kept + delta;
  require(std::isfinite(next), "the updated pheromone overflows");
  return next;
}

double total_deposit(std::span<const double> per_ant) {
  double total = 0.0;
  for (const double d : per_ant) {
    require(finite_nonneg(d), "every deposit must be finite and >= 0");
    total += d;
  }
  require(std::isfinite(total), "the total deposit overflows");
  return total;
}

double ant_cycle_deposit(double Q, double L) {
  require(std::isfinite(Q) && Q > 0.0, "Q must be finite and > 0");
  require(std::isfinite(L) && L > 0.0, "L_k must be finite and > 0");
  return Q / L;
}

EdgeSense parse_edge_sense(std::string_view name) {
  if (name == "directed") return EdgeSense::directed;
  if (name == "undirected") return EdgeSense::undirected;
  throw UsageError("unknown edge sense '" + std::string(name) + "' (expected directed or undirected)");
}

EdgeRepeats parse_edge_repeats(std::string_view name) {
  if (name == "once") return EdgeRepeats::once;
  if (name == "per_traversal") return EdgeRepeats::per_traversal;
  throw UsageError("unknown edge repeats '" + std::string(name) +
                   "' (expected once or per_traversal)");
}

double edge_deposit(std::span<const grid::Cell> path, grid::Cell from, grid::Cell to, double Q,
                    EdgeSense sense, EdgeRepeats repeats) {
  require(!(from == to), "an edge joins two different cells");
  require(std::isfinite(Q) && Q > 0.0, "Q must be finite and > 0");
  const double L = metrics::path_length(path);  // checks the path domain
  require(path.size() >= 2, "an ant's path needs at least two nodes (L_k > 0)");
  std::int64_t count = 0;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const bool forward = path[k - 1] == from && path[k] == to;
    const bool backward = path[k - 1] == to && path[k] == from;
    if (forward || (sense == EdgeSense::undirected && backward)) ++count;
  }
  if (count == 0) return 0.0;
  const double unit = ant_cycle_deposit(Q, L);
  if (repeats == EdgeRepeats::once) return unit;
  return static_cast<double>(count) * unit;
}

RhoReading parse_rho_reading(std::string_view name) {
  if (name == "factor") return RhoReading::factor;
  if (name == "condition") return RhoReading::condition;
  if (name == "clamp") return RhoReading::clamp;
  throw UsageError("unknown Eq. 13 reading '" + std::string(name) +
                   "' (expected factor, condition or clamp)");
}

double adaptive_rho(double rho, std::int64_t t, std::int64_t T, double rho_min,
                    RhoReading reading) {
  require(T >= 1 && T <= (std::int64_t{1} << 31), "T must lie in [1, 2^31]");
  require(t >= 0 && t <= T, "t must lie in [0, T]");
  require(std::isfinite(rho) && rho > 0.0 && rho < 1.0, "rho(t) must lie in (0, 1)");
  require(std::isfinite(rho_min) && rho_min >= 0.0 && rho_min < 1.0, "rho_min must lie in [0, 1)");
  const double a = static_cast<double>(T) / static_cast<double>(T + t);
  const double b = 1.0 / std::exp(1.0 - rho);
  switch (reading) {
    case RhoReading::factor: {
      const double v = (a * b) * rho;
      return v > rho_min ? v : rho_min;
    }
    case RhoReading::condition:
      return rho > rho_min ? a * b : rho_min;
    case RhoReading::clamp: {
      const double w = a * b;
      return w > rho_min ? w : rho_min;
    }
  }
  throw UsageError("unknown Eq. 13 reading");
}

double elite_bonus(double h, double L_a, double L_n) {
  require(std::isfinite(h) && h >= 0.0, "h must be finite and >= 0");
  require(std::isfinite(L_a) && L_a > 0.0, "L_a must be finite and > 0");
  require(std::isfinite(L_n) && L_n > 0.0, "L_n must be finite and > 0");
  return (h * (L_a - L_n)) / L_n;
}

double pheromone_update_elite(double tau, double rho, double delta, double bonus,
                              double tau_min) {
  require(std::isfinite(bonus), "the elite bonus must be finite");
  require(std::isfinite(tau_min) && tau_min > 0.0, "tau_min must be finite and > 0");
  const double v = pheromone_update(tau, rho, delta) + bonus;
  require(std::isfinite(v), "the updated pheromone overflows");
  return v > tau_min ? v : tau_min;
}

}  // namespace pathref::aco
