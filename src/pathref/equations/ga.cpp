#include "pathref/equations/ga.hpp"

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/heuristics.hpp"

namespace pathref::ga {

namespace {

bool finite_nonneg(double v) { return std::isfinite(v) && v >= 0.0; }

constexpr std::int64_t coordinate_limit = std::int64_t{1} << 30;
constexpr std::int64_t max_generations_limit = std::int64_t{1} << 31;
constexpr double half_pi = std::numbers::pi / 2.0;  // exact halving of the binary64 pi

/// int[s / 2] for s >= 0 under the given rounding.
std::int64_t half(std::int64_t s, MidRounding r) {
  switch (r) {
    case MidRounding::floor:
      return s / 2;
    case MidRounding::ceil:
      return (s + 1) / 2;
    case MidRounding::half_even:
      return (s % 4 == 1) ? s / 2 : (s + 1) / 2;  // s/2 = k + 0.5 rounds to the even of k, k+1
  }
  throw UsageError("unknown mid-point rounding");
}

double penalty_of(TurnBand b, const TurnPenalties& p) {
  switch (b) {
    case TurnBand::straight:
      return 1.0;
    case TurnBand::up_to_45:
      return p.up_to_45;
    case TurnBand::up_to_90:
      return p.up_to_90;
    case TurnBand::above_90:
      return p.above_90;
  }
  throw UsageError("unknown turn band");
}

void require_generations(std::int64_t i, std::int64_t max_generations) {
  require(max_generations >= 1 && max_generations <= max_generations_limit,
          "M_g must lie in [1, 2^31]");
  require(i >= 0 && i <= max_generations, "i must lie in [0, M_g]");
}

}  // namespace

std::int64_t continuity_delta(grid::Cell a, grid::Cell b) {
  // heuristics::chebyshev checks |coordinates| < 2^30 and is exact as a double there.
  return static_cast<std::int64_t>(heuristics::chebyshev(a, b));
}

bool is_continuous(grid::Cell a, grid::Cell b) { return continuity_delta(a, b) == 1; }

MidRounding parse_mid_rounding(std::string_view name) {
  if (name == "floor") return MidRounding::floor;
  if (name == "ceil") return MidRounding::ceil;
  if (name == "half_even") return MidRounding::half_even;
  throw UsageError("unknown mid-point rounding '" + std::string(name) +
                   "' (expected floor, ceil or half_even)");
}

MidNumber parse_mid_number(std::string_view name) {
  if (name == "row_major") return MidNumber::row_major;
  if (name == "printed_sum") return MidNumber::printed_sum;
  throw UsageError("unknown mid-point number '" + std::string(name) +
                   "' (expected row_major or printed_sum)");
}

grid::Cell insertion_cell(grid::Cell a, grid::Cell b, MidRounding rounding) {
  for (const grid::Cell c : {a, b})
    require(c.x >= 0 && c.y >= 0 && c.x < coordinate_limit && c.y < coordinate_limit,
            "mid-point insertion needs coordinates in [0, 2^30)");
  return grid::Cell{half(a.x + b.x, rounding), half(a.y + b.y, rounding)};
}

std::int64_t insertion_number(grid::Cell a, grid::Cell b, std::int64_t width, std::int64_t height,
                              MidRounding rounding, MidNumber form) {
  // cell_index checks W, H and bounds; check a and b first so the message names them.
  (void)grid::cell_index(a, width, height);
  (void)grid::cell_index(b, width, height);
  const grid::Cell m = insertion_cell(a, b, rounding);
  if (form == MidNumber::printed_sum) return m.x + m.y;
  return grid::cell_index(m, width, height);
}

double inverse_length(double length) {
  require(std::isfinite(length) && length > 0.0, "length must be finite and > 0");
  return 1.0 / length;
}

double weighted_fitness(double fit1, double fit2, double fit3, FitnessWeights w) {
  require(finite_nonneg(w.a) && finite_nonneg(w.b) && finite_nonneg(w.c),
          "the weights a, b, c must be finite and >= 0");
  require(finite_nonneg(fit1) && finite_nonneg(fit2) && finite_nonneg(fit3),
          "fit_1, fit_2, fit_3 must be finite and >= 0");
  const double s = ((w.a * fit1) + (w.b * fit2)) + (w.c * fit3);
  require(std::isfinite(s), "the weighted fitness overflows");
  return s;
}

TurnBand turn_band(grid::Cell a, grid::Cell b, grid::Cell c) {
  for (const grid::Cell p : {a, b, c})
    require(std::llabs(p.x) <= metrics::max_abs_coordinate &&
                std::llabs(p.y) <= metrics::max_abs_coordinate,
            "coordinates must satisfy |x|, |y| <= 2^25");
  require(!(a == b) && !(b == c), "a turning angle needs two non-zero segments");
  const std::int64_t ux = b.x - a.x;
  const std::int64_t uy = b.y - a.y;
  const std::int64_t vx = c.x - b.x;
  const std::int64_t vy = c.y - b.y;
  const std::int64_t dot = ux * vx + uy * vy;      // |.| <= 2 * 2^52: exact
  const std::int64_t cross = ux * vy - uy * vx;    // idem
  const std::int64_t abs_cross = cross < 0 ? -cross : cross;
  if (dot < 0) return TurnBand::above_90;
  if (dot == 0) return TurnBand::up_to_90;
  if (cross == 0) return TurnBand::straight;
  return abs_cross <= dot ? TurnBand::up_to_45 : TurnBand::up_to_90;
}

SmoothnessReading parse_smoothness_reading(std::string_view name) {
  if (name == "per_node") return SmoothnessReading::per_node;
  if (name == "per_turn") return SmoothnessReading::per_turn;
  if (name == "angle_times_penalty") return SmoothnessReading::angle_times_penalty;
  if (name == "inverse_total") return SmoothnessReading::inverse_total;
  if (name == "inverse_total_plus_one") return SmoothnessReading::inverse_total_plus_one;
  throw UsageError("unknown smoothness reading '" + std::string(name) +
                   "' (expected per_node, per_turn, angle_times_penalty, inverse_total or "
                   "inverse_total_plus_one)");
}

double smoothness_factor(std::span<const grid::Cell> path, SmoothnessReading reading,
                         TurnPenalties penalties) {
  for (const double p : {penalties.up_to_45, penalties.up_to_90, penalties.above_90})
    require(std::isfinite(p) && p > 0.0, "turn penalties must be finite and > 0");
  const std::vector<double> theta = metrics::turning_angles(path);  // checks the path domain
  double sum = 0.0;
  std::int64_t turns = 0;
  for (std::size_t k = 1; k + 1 < path.size(); ++k) {
    const TurnBand band = turn_band(path[k - 1], path[k], path[k + 1]);
    const double p = penalty_of(band, penalties);
    const bool straight = band == TurnBand::straight;
    if (!straight) ++turns;
    switch (reading) {
      case SmoothnessReading::per_node:
        sum += 1.0 / p;
        break;
      case SmoothnessReading::per_turn:
        if (!straight) sum += 1.0 / p;
        break;
      case SmoothnessReading::angle_times_penalty:
        if (!straight) sum += 1.0 / (p * theta[k - 1]);
        break;
      case SmoothnessReading::inverse_total:
      case SmoothnessReading::inverse_total_plus_one:
        if (!straight) sum += p;
        break;
    }
  }
  if (reading == SmoothnessReading::inverse_total_plus_one) {
    const double total = 1.0 + sum;  // 1 + (P_1 + P_2 + ...), the penalties added left to right
    require(std::isfinite(total), "the total penalty overflows");
    return 1.0 / total;
  }
  if (reading == SmoothnessReading::inverse_total) {
    require(turns > 0,
            "smoothness = inverse_total: a path without turns has total penalty 0 and 1/0 is "
            "undefined (the classic MATLAB GA script fails there too); "
            "smoothness = inverse_total_plus_one is defined for every path");
    require(std::isfinite(sum), "the total penalty overflows");
    return 1.0 / sum;
  }
  require(std::isfinite(sum), "the smoothness factor overflows");
  return sum;
}

SafetyCount parse_safety_count(std::string_view name) {
  if (name == "count") return SafetyCount::count;
  if (name == "indicator") return SafetyCount::indicator;
  throw UsageError("unknown safety count '" + std::string(name) + "' (expected count or indicator)");
}

SafetyAggregate parse_safety_aggregate(std::string_view name) {
  if (name == "inverse_total_plus_one") return SafetyAggregate::inverse_total_plus_one;
  if (name == "per_node") return SafetyAggregate::per_node;
  if (name == "mean") return SafetyAggregate::mean;
  throw UsageError("unknown safety aggregate '" + std::string(name) +
                   "' (expected inverse_total_plus_one, per_node or mean)");
}

SafeNode parse_safe_node(std::string_view name) {
  if (name == "one") return SafeNode::one;
  if (name == "skip") return SafeNode::skip;
  throw UsageError("unknown safe-node reading '" + std::string(name) + "' (expected one or skip)");
}

SafetyNodes parse_safety_nodes(std::string_view name) {
  if (name == "all_but_goal") return SafetyNodes::all_but_goal;
  if (name == "all") return SafetyNodes::all;
  if (name == "interior") return SafetyNodes::interior;
  throw UsageError("unknown safety nodes '" + std::string(name) +
                   "' (expected all_but_goal, all or interior)");
}

double safety_factor(const grid::Grid& g, std::span<const grid::Cell> path, SafetyOptions options) {
  const std::vector<std::int64_t> s = metrics::safety_counts(g, path, options.outside);
  const std::size_t n = s.size();
  std::size_t first = 0;
  std::size_t end = n;  // one past the last node summed
  switch (options.nodes) {
    case SafetyNodes::all_but_goal:
      end = n - 1;
      break;
    case SafetyNodes::all:
      break;
    case SafetyNodes::interior:
      first = 1;
      end = n >= 1 ? n - 1 : 0;
      break;
  }
  const auto hazard = [&](std::size_t k) {
    return options.count == SafetyCount::count ? s[k] : (s[k] > 0 ? std::int64_t{1} : std::int64_t{0});
  };
  if (options.aggregate == SafetyAggregate::inverse_total_plus_one) {
    std::int64_t total = 0;  // at most 8 per node: exact for any path that fits in memory
    for (std::size_t k = first; k < end; ++k) total += hazard(k);
    return 1.0 / static_cast<double>(1 + total);
  }
  double sum = 0.0;
  for (std::size_t k = first; k < end; ++k) {
    const std::int64_t S = options.safe == SafeNode::one ? 1 + hazard(k) : hazard(k);
    if (S == 0) continue;  // only under SafeNode::skip: a safe node adds nothing
    sum += 1.0 / static_cast<double>(S);
  }
  if (options.aggregate == SafetyAggregate::mean)
    return end > first ? sum / static_cast<double>(end - first) : 0.0;
  return sum;
}

double adaptive_pc(std::int64_t i, std::int64_t max_generations, double scale) {
  require_generations(i, max_generations);
  require(std::isfinite(scale) && scale > 0.0 && scale <= 1.0, "scale must lie in (0, 1]");
  const double r = static_cast<double>(i) / static_cast<double>(max_generations + i);
  return scale * std::cos(half_pi * r);
}

PmAtZero parse_pm_at_zero(std::string_view name) {
  if (name == "binary64") return PmAtZero::binary64;
  if (name == "exact_zero") return PmAtZero::exact_zero;
  throw UsageError("unknown P_m(0) reading '" + std::string(name) +
                   "' (expected binary64 or exact_zero)");
}

double adaptive_pm(std::int64_t i, std::int64_t max_generations, double pm_max, double scale,
                   PmAtZero at_zero) {
  require_generations(i, max_generations);
  require(std::isfinite(pm_max) && pm_max > 0.0 && pm_max <= 1.0, "P_m_max must lie in (0, 1]");
  require(std::isfinite(scale) && scale > 0.0 && scale <= 1.0, "scale must lie in (0, 1]");
  double m = 0.0;
  if (!(i == 0 && at_zero == PmAtZero::exact_zero)) {
    const double r = static_cast<double>(max_generations - i) / static_cast<double>(max_generations + i);
    m = scale * std::cos(half_pi * r);
  }
  return m < pm_max ? m : pm_max;
}

}  // namespace pathref::ga
