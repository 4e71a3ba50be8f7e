#include "pathref/equations/metrics.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>

#include "pathref/core/error.hpp"

namespace pathref::metrics {

namespace {

void require_coordinates(grid::Cell c) {
  require(std::llabs(c.x) <= max_abs_coordinate && std::llabs(c.y) <= max_abs_coordinate,
          "cell coordinates must satisfy |x|, |y| <= 2^25");
}

/// Items 1-2 of the path domain: non-empty, no two consecutive cells equal.
void require_path_shape(std::span<const grid::Cell> path) {
  require(!path.empty(), "a path needs at least one cell");
  for (std::size_t k = 1; k < path.size(); ++k)
    require(!(path[k] == path[k - 1]), "a path must not repeat a cell consecutively");
}

/// The whole path domain (items 1-3).
void require_path(std::span<const grid::Cell> path) {
  require(!path.empty(), "a path needs at least one cell");
  for (const grid::Cell& c : path) require_coordinates(c);
  require_path_shape(path);
}

struct Vec {
  std::int64_t x;
  std::int64_t y;
};
Vec diff(grid::Cell from, grid::Cell to) { return Vec{to.x - from.x, to.y - from.y}; }
/// |u|, |v| <= 2^26 per component, so the products and the sums are exact in int64.
std::int64_t cross(Vec u, Vec v) { return u.x * v.y - u.y * v.x; }
std::int64_t dot(Vec u, Vec v) { return u.x * v.x + u.y * v.y; }

}  // namespace

double centre_distance(grid::Cell a, grid::Cell b) {
  require_coordinates(a);
  require_coordinates(b);
  const auto dx = static_cast<double>(b.x - a.x);
  const auto dy = static_cast<double>(b.y - a.y);
  return std::sqrt(dx * dx + dy * dy);
}

double path_length(std::span<const grid::Cell> path) {
  require_path(path);
  double total = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k) total += centre_distance(path[k - 1], path[k]);
  return total;
}

double turning_angle(grid::Cell a, grid::Cell b, grid::Cell c) {
  require_coordinates(a);
  require_coordinates(b);
  require_coordinates(c);
  require(!(a == b) && !(b == c), "a turning angle needs two non-zero segments");
  const Vec u = diff(a, b);
  const Vec v = diff(b, c);
  return std::atan2(static_cast<double>(std::llabs(cross(u, v))), static_cast<double>(dot(u, v)));
}

std::vector<double> turning_angles(std::span<const grid::Cell> path) {
  require_path(path);
  std::vector<double> out;
  if (path.size() < 3) return out;
  out.reserve(path.size() - 2);
  for (std::size_t k = 1; k + 1 < path.size(); ++k)
    out.push_back(turning_angle(path[k - 1], path[k], path[k + 1]));
  return out;
}

std::int64_t turn_count(std::span<const grid::Cell> path) {
  require_path(path);
  std::int64_t turns = 0;
  for (std::size_t k = 1; k + 1 < path.size(); ++k) {
    const Vec u = diff(path[k - 1], path[k]);
    const Vec v = diff(path[k], path[k + 1]);
    const bool straight_on = cross(u, v) == 0 && dot(u, v) > 0;
    if (!straight_on) ++turns;
  }
  return turns;
}

SmoothnessForm parse_smoothness_form(std::string_view name) {
  if (name == "ompl") return SmoothnessForm::ompl;
  if (name == "angle") return SmoothnessForm::angle;
  throw UsageError("unknown smoothness form '" + std::string(name) + "' (expected ompl or angle)");
}

double smoothness_ompl(std::span<const grid::Cell> path) {
  return smoothness_ompl(path, SmoothnessForm::ompl);
}

double smoothness_ompl(std::span<const grid::Cell> path, SmoothnessForm form) {
  require_path(path);
  double s = 0.0;
  for (std::size_t k = 1; k + 1 < path.size(); ++k) {
    const double a = centre_distance(path[k - 1], path[k]);
    const double b = centre_distance(path[k], path[k + 1]);
    double phi = 0.0;
    if (form == SmoothnessForm::ompl) {
      const double c = centre_distance(path[k - 1], path[k + 1]);
      // OMPL's evaluation order: ((a*a + b*b) - c*c) / ((2*a)*b); term only inside (-1, 1).
      const double q = (a * a + b * b - c * c) / (2.0 * a * b);
      if (!(q > -1.0 && q < 1.0)) continue;
      phi = std::numbers::pi - std::acos(q);
    } else {
      phi = turning_angle(path[k - 1], path[k], path[k + 1]);
    }
    const double kappa = 2.0 * phi / (a + b);
    s += kappa * kappa;
  }
  return s;
}

OutsideCells parse_outside_cells(std::string_view name) {
  if (name == "free") return OutsideCells::free;
  if (name == "blocked") return OutsideCells::blocked;
  throw UsageError("unknown outside-cells reading '" + std::string(name) +
                   "' (expected free or blocked)");
}

std::vector<std::int64_t> safety_counts(const grid::Grid& g, std::span<const grid::Cell> path) {
  return safety_counts(g, path, OutsideCells::free);
}

std::vector<std::int64_t> safety_counts(const grid::Grid& g, std::span<const grid::Cell> path,
                                        OutsideCells outside) {
  require_path_shape(path);
  for (const grid::Cell& c : path) require(g.in_bounds(c), "safety_counts: node outside the grid");
  std::vector<std::int64_t> out;
  out.reserve(path.size());
  for (const grid::Cell& c : path) {
    std::int64_t n = 0;
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0) continue;
        const grid::Cell q{c.x + dx, c.y + dy};
        if (g.in_bounds(q)) {
          if (g.blocked(q)) ++n;
        } else if (outside == OutsideCells::blocked) {
          ++n;
        }
      }
    }
    out.push_back(n);
  }
  return out;
}

PathCheck validate_path(const grid::Grid& g, std::span<const grid::Cell> path, grid::Cell start,
                        grid::Cell goal, grid::CornerPolicy policy) {
  if (path.empty()) return PathCheck{false, "empty", -1};
  if (!(path.front() == start)) return PathCheck{false, "start_mismatch", 0};
  for (std::size_t k = 0; k < path.size(); ++k) {
    const auto at = static_cast<std::int64_t>(k);
    const grid::Cell c = path[k];
    if (!g.in_bounds(c)) return PathCheck{false, "out_of_bounds", at};
    if (g.blocked(c)) return PathCheck{false, "blocked", at};
    if (k == 0) continue;
    const grid::Cell p = path[k - 1];  // in bounds and free: checked at k - 1
    if (c == p) return PathCheck{false, "repeated", at};
    if (std::llabs(c.x - p.x) > 1 || std::llabs(c.y - p.y) > 1)
      return PathCheck{false, "not_adjacent", at};
    if (!grid::step_allowed(g, p, c, policy)) return PathCheck{false, "corner_cut", at};
  }
  if (!(path.back() == goal))
    return PathCheck{false, "goal_mismatch", static_cast<std::int64_t>(path.size()) - 1};
  return PathCheck{true, "ok", -1};
}

Sense parse_sense(std::string_view name) {
  if (name == "min") return Sense::minimise;
  if (name == "max") return Sense::maximise;
  throw UsageError("unknown sense '" + std::string(name) + "' (expected min or max)");
}

std::int64_t iterations_to_converge(std::span<const double> best_per_iteration) {
  return iterations_to_converge(best_per_iteration, Sense::minimise);
}

std::int64_t iterations_to_converge(std::span<const double> best_per_iteration, Sense sense) {
  require(!best_per_iteration.empty(), "iterations_to_converge needs at least one iteration");
  // "no path" marker and the forbidden infinity, by sense.
  const double inf = std::numeric_limits<double>::infinity();
  const double none = sense == Sense::minimise ? inf : -inf;
  double best = none;
  for (const double v : best_per_iteration) {
    require(!std::isnan(v), "iteration values must not be NaN");
    require(!std::isinf(v) || v == none,
            sense == Sense::minimise ? "iteration values must not be -inf when minimising"
                                     : "iteration values must not be +inf when maximising");
    if (sense == Sense::minimise ? v < best : v > best) best = v;
  }
  require(std::isfinite(best), "no iteration recorded a finite value (no path was ever found)");
  for (std::size_t t = 0; t < best_per_iteration.size(); ++t)
    if (best_per_iteration[t] == best) return static_cast<std::int64_t>(t) + 1;
  throw DomainError("unreachable: the best value is one of the values");
}

}  // namespace pathref::metrics
