#include "pathref/equations/heuristics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "pathref/core/error.hpp"

namespace pathref::heuristics {

namespace {

struct Delta {
  std::int64_t dx;  ///< |n_x - g_x|
  std::int64_t dy;  ///< |n_y - g_y|
};

bool coordinate_ok(std::int64_t v) noexcept {
  return v > -coordinate_limit && v < coordinate_limit;
}

/// |n - g| per axis, after checking the shared domain of every heuristic.
Delta delta(grid::Cell n, grid::Cell g) {
  require(coordinate_ok(n.x) && coordinate_ok(n.y) && coordinate_ok(g.x) && coordinate_ok(g.y),
          "heuristic: cell coordinates must satisfy |x|, |y| < 2^30");
  const std::int64_t dx = n.x - g.x;
  const std::int64_t dy = n.y - g.y;
  return Delta{dx < 0 ? -dx : dx, dy < 0 ? -dy : dy};
}

}  // namespace

double manhattan(grid::Cell n, grid::Cell g) {
  const Delta d = delta(n, g);
  return static_cast<double>(d.dx + d.dy);  // < 2^32: exact
}

double chebyshev(grid::Cell n, grid::Cell g) {
  const Delta d = delta(n, g);
  return static_cast<double>(std::max(d.dx, d.dy));  // exact
}

double octile(grid::Cell n, grid::Cell g) {
  const Delta d = delta(n, g);
  const std::int64_t big = std::max(d.dx, d.dy);
  const std::int64_t small = std::min(d.dx, d.dy);
  // (M - m) orthogonal steps plus m diagonal steps; the order of operations is normative.
  const double diagonal = std::numbers::sqrt2 * static_cast<double>(small);
  return static_cast<double>(big - small) + diagonal;
}

double euclidean(grid::Cell n, grid::Cell g) {
  const Delta d = delta(n, g);
  const std::int64_t squared = d.dx * d.dx + d.dy * d.dy;  // < 2^63: no overflow
  return std::sqrt(static_cast<double>(squared));
}

Heuristic parse_heuristic(std::string_view name) {
  if (name == "zero") return Heuristic::zero;
  if (name == "manhattan") return Heuristic::manhattan;
  if (name == "chebyshev") return Heuristic::chebyshev;
  if (name == "octile") return Heuristic::octile;
  if (name == "euclidean") return Heuristic::euclidean;
  throw UsageError("unknown heuristic '" + std::string(name) +
                   "' (expected octile, chebyshev, euclidean, manhattan or zero)");
}

std::string_view to_string(Heuristic h) noexcept {
  switch (h) {
    case Heuristic::zero: return "zero";
    case Heuristic::manhattan: return "manhattan";
    case Heuristic::chebyshev: return "chebyshev";
    case Heuristic::octile: return "octile";
    case Heuristic::euclidean: return "euclidean";
  }
  return "octile";
}

double evaluate(Heuristic h, grid::Cell n, grid::Cell g) {
  switch (h) {
    case Heuristic::zero:
      (void)delta(n, g);  // same domain as the others
      return 0.0;
    case Heuristic::manhattan: return manhattan(n, g);
    case Heuristic::chebyshev: return chebyshev(n, g);
    case Heuristic::octile: return octile(n, g);
    case Heuristic::euclidean: return euclidean(n, g);
  }
  throw UsageError("unknown heuristic");
}

bool admissible(Heuristic h, grid::CornerPolicy policy) noexcept {
  // Manhattan is the free-space 4-connected distance: a lower bound only without diagonals.
  return h != Heuristic::manhattan || policy == grid::CornerPolicy::never;
}

bool consistent(Heuristic h, grid::CornerPolicy policy) noexcept {
  // Every heuristic here is a metric d with d(n, n') <= c(n, n') on each allowed step, except
  // manhattan across a diagonal step (2 > sqrt2); see spec/search.md, search.admissible.
  return admissible(h, policy);
}

}  // namespace pathref::heuristics
