#pragma once
/// \file search.hpp
/// Dijkstra's algorithm and A* on the grid: one best-first search parameterised by the heuristic,
/// with a total, state-only open-list order (f, h, cell index), no reopening of closed cells and
/// parents replaced only on a strictly smaller g. Every run is a pure function of
/// (grid, start, goal, policy, heuristic).
/// Source: Hart, Nilsson & Raphael (1968), doi:10.1109/TSSC.1968.300136 (A*);
/// Dijkstra (1959), doi:10.1007/BF01386390; Han (IJACSA) Eq. (8) for 8-direction A* with the
/// Chebyshev heuristic.
/// Spec: spec/search.md (search.order, search.astar, search.dijkstra)
#include <cstdint>
#include <span>
#include <vector>

#include "pathref/equations/heuristics.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/planners/planner.hpp"

namespace pathref::search {

/// The key of an open cell: f = g + h (one double addition), h, and the cell index.
struct OpenKey {
  double f = 0.0;
  double h = 0.0;
  std::int64_t index = 0;
};

/// True iff key a is selected before key b: lexicographic (f, h, index), each ascending, with
/// exact comparison of the doubles. A strict total order on keys with distinct indices.
/// Source: pathref. Spec: search.order
/// Pre: f and h are not NaN (never violated by the search: g and h are finite).
/// Golden: golden/search/search.order.json
[[nodiscard]] constexpr bool precedes(const OpenKey& a, const OpenKey& b) noexcept {
  if (a.f < b.f) return true;
  if (b.f < a.f) return false;
  if (a.h < b.h) return true;
  if (b.h < a.h) return false;
  return a.index < b.index;
}

/// What one search returns.
struct Outcome {
  bool found = false;             ///< goal reached
  std::vector<grid::Cell> path;   ///< start ... goal; empty when !found
  double length = 0.0;            ///< g(goal) = left-to-right sum of the step costs; 0 when !found
  std::int64_t expansions = 0;    ///< cells moved from OPEN to CLOSED, the goal included
};

/// A* from start to goal under `policy` with heuristic `h` (spec rule search.astar).
/// Source: Hart, Nilsson & Raphael (1968), doi:10.1109/TSSC.1968.300136; Han (IJACSA) Eq. (8).
/// Spec: search.astar, search.order
/// Pre: start and goal in bounds and free (DomainError naming which).
/// Post: found iff goal is reachable from start under policy; the path is valid under policy;
///   with a consistent heuristic (search.admissible) the path is a shortest path (exactly, on
///   maps of at most 2^16 cells: spec/search.md "Rounding"); with manhattan under a diagonal
///   policy its cost is at most sqrt2 times the shortest.
/// Golden: golden/search/search.astar.json
[[nodiscard]] Outcome astar(const grid::Grid& g, grid::Cell start, grid::Cell goal,
                            grid::CornerPolicy policy, heuristics::Heuristic h);

/// Dijkstra's algorithm: exactly astar(..., Heuristic::zero), key (g, 0, index).
/// Source: Dijkstra (1959), doi:10.1007/BF01386390.
/// Spec: search.dijkstra. Pre: as astar. Post: found iff reachable; a shortest path.
/// Golden: golden/search/search.dijkstra.json
[[nodiscard]] Outcome dijkstra(const grid::Grid& g, grid::Cell start, grid::Cell goal,
                               grid::CornerPolicy policy);

/// Number of orthogonal and diagonal steps of a path (its exact cost is orthogonal +
/// diagonal * sqrt(2)). Source: pathref. Spec: search.astar (output "steps").
/// Pre: consecutive cells are distinct 8-neighbours (DomainError).
struct StepCounts {
  std::int64_t orthogonal = 0;
  std::int64_t diagonal = 0;
  friend constexpr bool operator==(const StepCounts&, const StepCounts&) = default;
};
[[nodiscard]] StepCounts step_counts(std::span<const grid::Cell> path);

}  // namespace pathref::search

namespace pathref::planners {

/// Planner "astar": param "heuristic" = "octile" (default) | "chebyshev" | "euclidean" |
/// "manhattan" | "zero". extra: {"admissible", "consistent"} of the heuristic under the policy.
/// Spec: search.astar
[[nodiscard]] Planner make_astar_planner();

/// Planner "dijkstra": no parameters. Spec: search.dijkstra
[[nodiscard]] Planner make_dijkstra_planner();

}  // namespace pathref::planners
