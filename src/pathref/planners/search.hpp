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
#include <functional>
#include <memory>
#include <span>
#include <string_view>
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
  /// Child generations: pairs (expanded cell, move) whose target is in bounds, free, not closed
  /// and reachable by an allowed step (the g of the target is evaluated). spec/search.md
  /// "Expansion rules and child counts".
  std::int64_t generated = 0;
  /// Child nodes: distinct cells put into OPEN for the first time (the start excluded) -- the
  /// grey cells of Sensors 2023 Fig. 6 (spec/search.md "Expansion rules and child counts").
  std::int64_t child_nodes = 0;
};

/// Reusable search state (spec/search.md "Reusing the search state"): per-cell g, parent and a
/// generation-stamped open/closed mark, sized once to the largest grid searched and never cleared
/// between searches (a new search increments the generation, which makes every old mark stale),
/// plus the open list's storage and the allowed-move mask of each cell of the grid and policy
/// last searched (dropped when a search brings another grid or policy). A Workspace carries no result from one search to the next: a
/// search with a reused Workspace returns exactly what the same search with a fresh one returns
/// (property prop_workspace_reuse_is_invisible). It is not tied to one grid. Not thread-safe: one
/// Workspace per thread. Source: pathref. Spec: search.astar
class Workspace {
 public:
  Workspace();
  ~Workspace();
  Workspace(Workspace&&) noexcept;
  Workspace& operator=(Workspace&&) noexcept;
  Workspace(const Workspace&) = delete;
  Workspace& operator=(const Workspace&) = delete;
  /// Cells the per-cell arrays currently hold (0 before the first search).
  [[nodiscard]] std::size_t capacity() const noexcept;
  /// Bytes the workspace holds (per-cell arrays and open-list storage), for reports.
  [[nodiscard]] std::size_t bytes() const noexcept;
  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
  friend Impl& access(Workspace& w) noexcept;
};

/// Bytes per grid cell of one search (spec/search.md "Memory"): the per-cell g, parent and mark
/// (16), the move-mask cache (2), the workspace's copy of the grid the masks belong to (1) and
/// the grid searched (1). The open list (24 bytes per entry, 16 for Dijkstra) comes on top: one
/// entry per generated improvement, not estimated.
inline constexpr std::uint64_t bytes_per_cell = 20;
/// cells x bytes_per_cell (saturating): what the astar, dijkstra and astar-kinematic planners
/// check against Request::max_memory before their per-cell arrays are allocated (UsageError
/// naming the estimate and the limit). Spec: search.astar
[[nodiscard]] std::uint64_t memory_estimate(std::int64_t cells) noexcept;
/// UsageError when memory_estimate(g.cell_count()) > req.max_memory, naming `planner`, the
/// estimate and the limit. Spec: search.astar
void require_memory(const planners::Request& req, const grid::Grid& g, std::string_view planner);

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
/// astar with a reused Workspace: the same Outcome, bit for bit, without per-call allocation
/// once `ws` has grown to the grid's size. Spec: search.astar
[[nodiscard]] Outcome astar(Workspace& ws, const grid::Grid& g, grid::Cell start, grid::Cell goal,
                            grid::CornerPolicy policy, heuristics::Heuristic h);

/// A node-expansion rule for the one best-first core (spec/search.md "Expansion rules and child
/// counts"): which of the
/// 8 moves an expanded cell generates, and the key of a generated child. astar() is this core
/// with all 8 moves, h = heuristics::evaluate and f = g + h; planners such as sensors2023's
/// kinematic A* plug their rule in here instead of writing a second A*.
struct ExpansionRule {
  /// Bit k (k = 0 .. 7, the moves in grid.neighbour-order: (-1,-1), (0,-1), (1,-1), (-1,0),
  /// (1,0), (-1,1), (0,1), (1,1)) set = the move is generated from `cell`. Called once per
  /// expansion. Empty = all 8.
  std::function<std::uint8_t(grid::Cell cell)> moves;
  /// h(n) of a generated child (the tie-break key). Required.
  std::function<double(grid::Cell n)> h;
  /// f(n) from g(n) and h(n). Empty = fl(g + h).
  std::function<double(double g, double h, grid::Cell n)> f;
};

/// The best-first search of astar() under an expansion rule: the same open-list order
/// (search.order on (f, h, index)), the same lazy deletion, no reopening, parents replaced only
/// on a strictly smaller g; only the generated moves and the key differ.
/// Source: Hart, Nilsson & Raphael (1968); Sensors 2023 §2.1–2.2, doi:10.3390/s23084102.
/// Spec: search.astar (spec/search.md "Expansion rules and child counts")
/// Pre: as astar; rule.h set (UsageError). Post: as astar when the rule generates all 8 moves
/// and f = g + h with h = heuristics::evaluate(H) (identical path and counts).
[[nodiscard]] Outcome best_first(const grid::Grid& g, grid::Cell start, grid::Cell goal,
                                 grid::CornerPolicy policy, const ExpansionRule& rule);
/// best_first with a reused Workspace (same Outcome). Spec: search.astar
[[nodiscard]] Outcome best_first(Workspace& ws, const grid::Grid& g, grid::Cell start,
                                 grid::Cell goal, grid::CornerPolicy policy,
                                 const ExpansionRule& rule);

/// Dijkstra's algorithm: exactly astar(..., Heuristic::zero), key (g, 0, index).
/// Source: Dijkstra (1959), doi:10.1007/BF01386390.
/// Spec: search.dijkstra. Pre: as astar. Post: found iff reachable; a shortest path.
/// Golden: golden/search/search.dijkstra.json
[[nodiscard]] Outcome dijkstra(const grid::Grid& g, grid::Cell start, grid::Cell goal,
                               grid::CornerPolicy policy);
/// dijkstra with a reused Workspace (same Outcome). Spec: search.dijkstra
[[nodiscard]] Outcome dijkstra(Workspace& ws, const grid::Grid& g, grid::Cell start,
                               grid::Cell goal, grid::CornerPolicy policy);

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
