#pragma once
/// \file heuristics.hpp
/// The A* heuristics on cell coordinates (distance between cell centres = difference of cell
/// coordinates), and the table saying which of them are admissible / consistent under which
/// corner policy. Pure functions of two cells: no grid, no state.
/// Spec: spec/search.md (search.h.manhattan, search.h.chebyshev, search.h.octile,
/// search.h.euclidean, search.admissible)
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string_view>

#include "pathref/core/error.hpp"
#include "pathref/grid/grid.hpp"

namespace pathref::heuristics {

/// Largest |coordinate| a heuristic accepts (exclusive): 2^30. Every cell of a Grid is far inside
/// (W*H <= 2^28); the bound keeps dx^2 + dy^2 inside a signed 64-bit integer.
inline constexpr std::int64_t coordinate_limit = std::int64_t{1} << 30;

namespace detail {
/// |n - g| per axis, after checking the shared domain of every heuristic (DomainError).
/// (The heuristics are inline: the search core evaluates one per generated child.)
struct Delta {
  std::int64_t dx;  ///< |n_x - g_x|
  std::int64_t dy;  ///< |n_y - g_y|
};
[[nodiscard]] constexpr bool coordinate_ok(std::int64_t v) noexcept {
  return v > -coordinate_limit && v < coordinate_limit;
}
[[nodiscard]] inline Delta delta(grid::Cell n, grid::Cell g) {
  require(coordinate_ok(n.x) && coordinate_ok(n.y) && coordinate_ok(g.x) && coordinate_ok(g.y),
          "heuristic: cell coordinates must satisfy |x|, |y| < 2^30");
  const std::int64_t dx = n.x - g.x;
  const std::int64_t dy = n.y - g.y;
  return Delta{dx < 0 ? -dx : dx, dy < 0 ? -dy : dy};
}
}  // namespace detail

/// Manhattan (L1) distance |n_x - g_x| + |n_y - g_y|, exact as a double.
/// Source: pathref (classic A* heuristic; Hart, Nilsson & Raphael 1968, doi:10.1109/TSSC.1968.300136).
/// Spec: search.h.manhattan
/// Pre: |x|, |y| < 2^30 for both cells (DomainError).
/// Post: a non-negative integer value; 0 iff n == g.
/// Golden: golden/search/search.h.manhattan.json
[[nodiscard]] inline double manhattan(grid::Cell n, grid::Cell g) {
  const detail::Delta d = detail::delta(n, g);
  return static_cast<double>(d.dx + d.dy);  // < 2^32: exact
}

/// Chebyshev (L-infinity) distance max(|n_x - g_x|, |n_y - g_y|), exact as a double.
/// Source: Han (IJACSA), Eq. (8) "h(n) = max(|n_x - g_x|, |n_y - g_y|)" for 8-direction A*.
/// Spec: search.h.chebyshev (the function rule han.eq8 indexes).
/// Pre: |x|, |y| < 2^30 for both cells (DomainError).
/// Post: a non-negative integer value; 0 iff n == g.
/// Golden: golden/search/search.h.chebyshev.json
[[nodiscard]] inline double chebyshev(grid::Cell n, grid::Cell g) {
  const detail::Delta d = detail::delta(n, g);
  return static_cast<double>(std::max(d.dx, d.dy));  // exact
}

/// Octile distance (M - m) + sqrt2 * m with M = max(dx, dy), m = min(dx, dy): the shortest
/// 8-connected path length on an obstacle-free grid. Evaluated as
/// double(M - m) + (sqrt2 * double(m)), sqrt2 = std::numbers::sqrt2, in that order.
/// Source: pathref (standard octile distance); spec/search.md says why this rounding form.
/// Spec: search.h.octile
/// Pre: |x|, |y| < 2^30 for both cells (DomainError).
/// Post: >= 0; 0 iff n == g; exact when m == 0.
/// Golden: golden/search/search.h.octile.json
[[nodiscard]] inline double octile(grid::Cell n, grid::Cell g) {
  const detail::Delta d = detail::delta(n, g);
  const std::int64_t big = std::max(d.dx, d.dy);
  const std::int64_t small = std::min(d.dx, d.dy);
  // (M - m) orthogonal steps plus m diagonal steps; the order of operations is normative.
  const double diagonal = std::numbers::sqrt2 * static_cast<double>(small);
  return static_cast<double>(big - small) + diagonal;
}

/// Euclidean distance sqrt(double(dx^2 + dy^2)); dx^2 + dy^2 in exact 64-bit integer arithmetic,
/// converted to double by round-to-nearest, then the correctly rounded IEEE square root.
/// Source: pathref (straight-line distance between cell centres); Sensors 2023 Eq. (2),
/// doi:10.3390/s23084102 (the same function serves both rules).
/// Spec: search.h.euclidean, sensors2023.eq2
/// Pre: |x|, |y| < 2^30 for both cells (DomainError).
/// Post: >= 0; 0 iff n == g; correctly rounded whenever dx^2 + dy^2 < 2^53.
/// Golden: golden/search/search.h.euclidean.json
[[nodiscard]] inline double euclidean(grid::Cell n, grid::Cell g) {
  const detail::Delta d = detail::delta(n, g);
  const std::int64_t squared = d.dx * d.dx + d.dy * d.dy;  // < 2^63: no overflow
  return std::sqrt(static_cast<double>(squared));
}

/// The heuristics a search can use. `zero` (h = 0) turns A* into Dijkstra's algorithm.
enum class Heuristic { zero, manhattan, chebyshev, octile, euclidean };

/// "zero" | "manhattan" | "chebyshev" | "octile" | "euclidean" -> Heuristic; UsageError otherwise.
[[nodiscard]] Heuristic parse_heuristic(std::string_view name);
[[nodiscard]] std::string_view to_string(Heuristic h) noexcept;

/// h(n) for goal g: dispatches to the functions above (0 for zero).
/// Source: pathref. Spec: search.astar (the heuristic parameter).
/// Pre: as the functions above (DomainError).
[[nodiscard]] inline double evaluate(Heuristic h, grid::Cell n, grid::Cell g) {
  switch (h) {
    case Heuristic::zero:
      (void)detail::delta(n, g);  // same domain as the others
      return 0.0;
    case Heuristic::manhattan: return manhattan(n, g);
    case Heuristic::chebyshev: return chebyshev(n, g);
    case Heuristic::octile: return octile(n, g);
    case Heuristic::euclidean: return euclidean(n, g);
  }
  throw UsageError("unknown heuristic");
}

/// Whether h never exceeds the exact shortest-path cost to the goal on every map under `policy`.
/// false only for manhattan under strict, one and always (a single free diagonal step costs
/// sqrt2 < 2). Source: definition of Hart, Nilsson & Raphael (1968); table: pathref.
/// Spec: search.admissible. Golden: golden/search/search.admissible.json
[[nodiscard]] bool admissible(Heuristic h, grid::CornerPolicy policy) noexcept;

/// Whether h(n) <= c(n, n') + h(n') for every allowed step n -> n' under `policy` (in exact
/// arithmetic; spec/search.md explains the rounding). Same table as admissible() here.
/// Source: definition of Hart, Nilsson & Raphael (1968); table: pathref. Spec: search.admissible. Golden: golden/search/search.admissible.json
[[nodiscard]] bool consistent(Heuristic h, grid::CornerPolicy policy) noexcept;

}  // namespace pathref::heuristics
