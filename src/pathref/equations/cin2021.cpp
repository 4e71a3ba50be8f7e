#include "pathref/equations/cin2021.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "pathref/core/error.hpp"
#include "pathref/equations/metrics.hpp"

namespace pathref::cin {

namespace {
constexpr std::int64_t max_coord = metrics::max_abs_coordinate;
void check_coord(grid::Cell c) {
  require(std::llabs(c.x) <= max_coord && std::llabs(c.y) <= max_coord,
          "coordinates must satisfy |x|, |y| <= 2^25");
}
}  // namespace

double segment_cosine(grid::Cell a, grid::Cell b, grid::Cell c) {
  check_coord(a);
  check_coord(b);
  check_coord(c);
  require(!(a == b) && !(b == c), "cos theta needs two non-degenerate segments (a != b != c)");
  const std::int64_t ux = b.x - a.x;
  const std::int64_t uy = b.y - a.y;
  const std::int64_t vx = c.x - b.x;
  const std::int64_t vy = c.y - b.y;
  const std::int64_t idot = ux * vx + uy * vy;
  if (ux * vy - uy * vx == 0) return idot > 0 ? 1.0 : -1.0;  // collinear: exact
  const double den = metrics::centre_distance(a, b) * metrics::centre_distance(b, c);
  return static_cast<double>(idot) / den;
}

double smoothness_cost(std::span<const grid::Cell> path) {
  double s = 0.0;
  for (std::size_t i = 0; i + 2 < path.size(); ++i)
    s += 1.0 - segment_cosine(path[i], path[i + 1], path[i + 2]);
  if (path.size() == 2) {
    check_coord(path[0]);
    check_coord(path[1]);
    require(!(path[0] == path[1]), "consecutive repeated cells");
  }
  return s;
}

NodeDistances node_distances(std::span<const grid::Cell> path) {
  NodeDistances out;
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    out.d1.push_back(metrics::centre_distance(path[i], path[i + 1]));
  for (std::size_t i = 0; i + 2 < path.size(); ++i)
    out.d2.push_back(metrics::centre_distance(path[i], path[i + 2]));
  for (const grid::Cell c : path) check_coord(c);
  return out;
}

AngleReading parse_angle_reading(std::string_view name) {
  if (name == "arccos") return AngleReading::arccos;
  if (name == "lookup") return AngleReading::lookup;
  throw UsageError("angle must be arccos or lookup, not '" + std::string(name) + "'");
}
std::string_view to_string(AngleReading v) noexcept {
  return v == AngleReading::arccos ? "arccos" : "lookup";
}

double included_angle(double d1a, double d1b, double d2) {
  require(std::isfinite(d1a) && d1a > 0.0 && std::isfinite(d1b) && d1b > 0.0,
          "included angle: d1 values must be finite and > 0");
  require(std::isfinite(d2) && d2 >= 0.0, "included angle: d2 must be finite and >= 0");
  const double num = ((d1a * d1a) + (d1b * d1b)) - (d2 * d2);
  const double den = (2.0 * d1a) * d1b;
  const double c = std::clamp(num / den, -1.0, 1.0);
  return std::acos(c) * (180.0 / std::numbers::pi);
}

double included_angle_grid(grid::Cell a, grid::Cell b, grid::Cell c) {
  const std::int64_t ux = b.x - a.x;
  const std::int64_t uy = b.y - a.y;
  const std::int64_t vx = c.x - b.x;
  const std::int64_t vy = c.y - b.y;
  const auto step = [](std::int64_t dx, std::int64_t dy) {
    return std::llabs(dx) <= 1 && std::llabs(dy) <= 1 && (dx != 0 || dy != 0);
  };
  require(step(ux, uy) && step(vx, vy), "grid included angle needs two 8-neighbour steps");
  const std::int64_t dot = ux * vx + uy * vy;
  const std::int64_t cross = ux * vy - uy * vx;
  if (dot > 0) return cross == 0 ? 180.0 : 135.0;
  if (dot == 0) return 90.0;
  return cross == 0 ? 0.0 : 45.0;
}

double corner_penalty(double theta, CornerPenalties p) {
  constexpr double eps = angle_epsilon_deg;
  require(std::isfinite(theta) && theta >= 0.0 && theta <= 180.0 + eps,
          "corner penalty: theta must lie in [0, 180] degrees");
  require(std::isfinite(p.c135) && std::isfinite(p.c90) && std::isfinite(p.c45) && p.c135 >= 0.0 &&
              p.c135 <= p.c90 && p.c90 <= p.c45,
          "corner penalties must be finite with 0 <= c135 <= c90 <= c45");
  if (theta >= 180.0 - eps) return 0.0;
  if (theta >= 135.0 - eps) return p.c135;
  if (theta >= 90.0 - eps) return p.c90;
  return p.c45;
}

F2Guard parse_f2_guard(std::string_view name) {
  if (name == "one_plus") return F2Guard::one_plus;
  if (name == "epsilon") return F2Guard::epsilon;
  throw UsageError("f2_guard must be one_plus or epsilon, not '" + std::string(name) + "'");
}
std::string_view to_string(F2Guard v) noexcept { return v == F2Guard::one_plus ? "one_plus" : "epsilon"; }

double smoothness_fitness(std::span<const grid::Cell> path, CornerPenalties p, F2Guard guard,
                          AngleReading angle) {
  require(path.size() >= 2, "smoothness fitness needs a path of >= 2 nodes");
  static_cast<void>(corner_penalty(180.0, p));  // the penalties' domain, also for short paths
  const NodeDistances d = node_distances(path);
  for (const double x : d.d1) require(x > 0.0, "smoothness fitness: consecutive repeated cells");
  double sum = 0.0;
  for (std::size_t i = 0; i + 2 < path.size(); ++i) {
    const double theta = angle == AngleReading::arccos
                             ? included_angle(d.d1[i], d.d1[i + 1], d.d2[i])
                             : included_angle_grid(path[i], path[i + 1], path[i + 2]);
    sum += corner_penalty(theta, p);
  }
  const double base = guard == F2Guard::one_plus ? 1.0 : 1e-3;
  return 1.0 / (base + sum);
}

ConversionForm parse_conversion_form(std::string_view name) {
  if (name == "q_over_l") return ConversionForm::q_over_l;
  if (name == "q_d_over_l") return ConversionForm::q_d_over_l;
  if (name == "q_over_l_d") return ConversionForm::q_over_l_d;
  throw UsageError("conversion_form must be q_over_l, q_d_over_l or q_over_l_d, not '" +
                   std::string(name) + "'");
}
std::string_view to_string(ConversionForm v) noexcept {
  switch (v) {
    case ConversionForm::q_over_l: return "q_over_l";
    case ConversionForm::q_d_over_l: return "q_d_over_l";
    case ConversionForm::q_over_l_d: return "q_over_l_d";
  }
  return "q_over_l";
}

double conversion_delta(ConversionForm form, double Q, double L, double d) {
  require(std::isfinite(Q) && Q > 0.0, "conversion: Q must be finite and > 0");
  require(std::isfinite(L) && L > 0.0, "conversion: L_k must be finite and > 0");
  require(std::isfinite(d) && d > 0.0, "conversion: d_ij must be finite and > 0");
  switch (form) {
    case ConversionForm::q_over_l: return Q / L;
    case ConversionForm::q_d_over_l: return (Q * d) / L;
    case ConversionForm::q_over_l_d: return Q / (L * d);
  }
  return Q / L;
}

std::vector<EdgePheromone> converted_pheromone(std::span<const std::vector<grid::Cell>> rows,
                                               double Q, ConversionForm form) {
  require(std::isfinite(Q) && Q > 0.0, "conversion: Q must be finite and > 0");
  std::vector<EdgePheromone> out;
  std::map<std::pair<std::pair<std::int64_t, std::int64_t>, std::pair<std::int64_t, std::int64_t>>,
           std::size_t>
      where;
  for (const auto& row : rows) {
    require(row.size() >= 2, "conversion: every row needs >= 2 cells");
    const double L = metrics::path_length(row);
    std::set<std::size_t> used;  // edges this row already added to
    for (std::size_t r = 0; r + 1 < row.size(); ++r) {
      require(!(row[r] == row[r + 1]), "conversion: consecutive repeated cells");
      const auto key = std::make_pair(std::make_pair(row[r].x, row[r].y),
                                      std::make_pair(row[r + 1].x, row[r + 1].y));
      auto [it, inserted] = where.try_emplace(key, out.size());
      if (inserted) out.push_back(EdgePheromone{row[r], row[r + 1], 0.0});
      if (!used.insert(it->second).second) continue;
      const double d = metrics::centre_distance(row[r], row[r + 1]);
      out[it->second].tau += conversion_delta(form, Q, L, d);
    }
  }
  return out;
}

double weighted_best_deposit(bool on_ib, double w_ib, double L_ib, bool on_gb, double w_gb,
                             double L_gb, double Q) {
  require(std::isfinite(Q) && Q > 0.0, "deposit: Q must be finite and > 0");
  double term_ib = 0.0;
  double term_gb = 0.0;
  if (on_ib) {
    require(std::isfinite(w_ib) && w_ib >= 0.0, "deposit: omega_ib must be finite and >= 0");
    require(std::isfinite(L_ib) && L_ib > 0.0, "deposit: L_ib must be finite and > 0");
    term_ib = w_ib * (Q / L_ib);
  }
  if (on_gb) {
    require(std::isfinite(w_gb) && w_gb >= 0.0, "deposit: omega_gb must be finite and >= 0");
    require(std::isfinite(L_gb) && L_gb > 0.0, "deposit: L_gb must be finite and > 0");
    term_gb = w_gb * (Q / L_gb);
  }
  return term_ib + term_gb;
}

WeightNorm parse_weight_norm(std::string_view name) {
  if (name == "raw") return WeightNorm::raw;
  if (name == "normalised") return WeightNorm::normalised;
  throw UsageError("weight_norm must be raw or normalised, not '" + std::string(name) + "'");
}
std::string_view to_string(WeightNorm v) noexcept { return v == WeightNorm::raw ? "raw" : "normalised"; }

BestWeights best_path_weights(std::int64_t t, std::int64_t N, WeightNorm norm) {
  require(N >= 1 && N <= 1000000, "weights: N_max must lie in [1, 10^6]");
  require(t >= 0 && t < N, "weights: t must lie in [0, N_max)");
  BestWeights w{static_cast<double>(N - t), static_cast<double>(t)};
  if (norm == WeightNorm::normalised) {
    w.ib /= static_cast<double>(N);
    w.gb /= static_cast<double>(N);
  }
  return w;
}

LambdaForm parse_lambda_form(std::string_view name) {
  if (name == "lambda") return LambdaForm::lambda;
  if (name == "one_minus") return LambdaForm::one_minus;
  throw UsageError("lambda_form must be lambda or one_minus, not '" + std::string(name) + "'");
}
std::string_view to_string(LambdaForm v) noexcept { return v == LambdaForm::lambda ? "lambda" : "one_minus"; }

double dead_angle_penalty(double tau, double lambda, LambdaForm form) {
  require(std::isfinite(lambda) && lambda > 0.0 && lambda < 1.0, "lambda must lie in (0, 1)");
  require(std::isfinite(tau) && tau >= 0.0, "dead-angle penalty: tau must be finite and >= 0");
  return form == LambdaForm::lambda ? lambda * tau : (1.0 - lambda) * tau;
}

}  // namespace pathref::cin
