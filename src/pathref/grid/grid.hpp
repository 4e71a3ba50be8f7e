#pragma once
/// \file grid.hpp
/// The grid model shared by every planner: a W x H occupancy grid, cells (x, y) 0-based with
/// (0, 0) at the lower left, cell index i = y * W + x (Shi et al. 2022, Figure 1A numbering).
/// Spec: spec/grid.md (grid.model, grid.index, grid.moves, grid.corner-policy, grid.neighbour-order)
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pathref::grid {

/// A cell by its column x (0 = left) and row y (0 = bottom).
struct Cell {
  std::int64_t x = 0;
  std::int64_t y = 0;
  friend constexpr bool operator==(const Cell&, const Cell&) = default;
};

/// Which diagonal moves are allowed, given the two orthogonal cells the move passes between.
/// Spec: grid.corner-policy.
enum class CornerPolicy {
  never,   ///< no diagonal moves at all (4-connected)
  strict,  ///< diagonal needs both orthogonal neighbours free (MovingAI rule; the default)
  one,     ///< diagonal needs at least one orthogonal neighbour free
  always,  ///< diagonal allowed whatever the orthogonal neighbours are (MATLAB G2D rule)
};

/// "never" | "strict" | "one" | "always" -> policy; UsageError on anything else.
[[nodiscard]] CornerPolicy parse_corner_policy(std::string_view name);
[[nodiscard]] std::string_view to_string(CornerPolicy policy) noexcept;

/// A W x H occupancy grid. Immutable after construction except through set_blocked.
class Grid {
 public:
  /// All cells free. Pre: width >= 1, height >= 1, width * height <= max_cells (DomainError).
  Grid(std::int64_t width, std::int64_t height);

  /// From rows of '.' (free) and '#' (blocked), the FIRST string being the TOP row, as a map
  /// is drawn. Pre: rows non-empty, all the same length, only '.' and '#' (DomainError).
  [[nodiscard]] static Grid from_rows_top_first(const std::vector<std::string>& rows);
  /// Inverse of from_rows_top_first.
  [[nodiscard]] std::vector<std::string> to_rows_top_first() const;

  [[nodiscard]] std::int64_t width() const noexcept { return width_; }
  [[nodiscard]] std::int64_t height() const noexcept { return height_; }
  [[nodiscard]] std::int64_t cell_count() const noexcept { return width_ * height_; }

  [[nodiscard]] bool in_bounds(Cell c) const noexcept {
    return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_;
  }
  /// i = y * W + x. Pre: in_bounds(c) (DomainError).
  [[nodiscard]] std::int64_t index(Cell c) const;
  /// Inverse of index. Pre: 0 <= i < W * H (DomainError).
  [[nodiscard]] Cell cell(std::int64_t i) const;

  /// True for a blocked cell. Pre: in_bounds(c).
  [[nodiscard]] bool blocked(Cell c) const;
  /// In bounds and not blocked. Never throws: out-of-bounds cells are simply not free.
  [[nodiscard]] bool free(Cell c) const noexcept;
  void set_blocked(Cell c, bool is_blocked);
  [[nodiscard]] std::int64_t blocked_count() const noexcept;

  friend bool operator==(const Grid&, const Grid&) = default;

  /// Largest number of cells a Grid may hold (2^28): checked before allocating.
  static constexpr std::int64_t max_cells = std::int64_t{1} << 28;

 private:
  std::int64_t width_;
  std::int64_t height_;
  std::vector<std::uint8_t> blocked_;
};

/// One allowed move out of a cell: the target and its cost (1 or sqrt(2)).
struct Move {
  Cell to;
  double cost;
};

/// Whether the single step a -> b is allowed: b is one of a's 8 neighbours, both are free, and
/// a diagonal step satisfies `policy`. Spec: grid.moves, grid.corner-policy.
[[nodiscard]] bool step_allowed(const Grid& g, Cell a, Cell b, CornerPolicy policy) noexcept;

/// Cost of a step between 8-neighbours: the distance between centres, 1 or sqrt(2).
/// Spec: grid.moves. Pre: a and b are distinct 8-neighbours (DomainError).
[[nodiscard]] double step_cost(Cell a, Cell b);

/// The allowed moves out of `c`, in canonical order: increasing cell index (spec rule
/// grid.neighbour-order). Every random choice among neighbours indexes into this order.
/// Pre: g.free(c) (DomainError).
[[nodiscard]] std::vector<Move> neighbours(const Grid& g, Cell c, CornerPolicy policy);

}  // namespace pathref::grid
