#pragma once
/// \file grid.hpp
/// The grid model shared by every planner: a W x H occupancy grid, cells (x, y) 0-based with
/// (0, 0) at the lower left, cell index i = y * W + x (Shi et al. 2022, Figure 1A numbering).
/// Spec: spec/grid.md (grid.encoding, grid.index, grid.coord, grid.moves, grid.corner-policy,
/// grid.neighbour-order)
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
/// Spec: grid.corner-policy.
[[nodiscard]] CornerPolicy parse_corner_policy(std::string_view name);
[[nodiscard]] std::string_view to_string(CornerPolicy policy) noexcept;

/// Cell index i = y * W + x on a W x H grid (Shi et al. 2022 Figure 1A numbering, 0-based:
/// left to right, bottom to top). Source: Shi et al. 2022 Sec. 3, doi:10.3389/fbioe.2022.905983.
/// Spec: grid.index. Pre: W, H >= 1, W * H <= Grid::max_cells, 0 <= x < W, 0 <= y < H
/// (DomainError). Post: 0 <= i < W * H. Golden: golden/grid/grid.index.json
[[nodiscard]] std::int64_t cell_index(Cell c, std::int64_t width, std::int64_t height);

/// Inverse of cell_index: (i mod W, floor(i / W)). Spec: grid.index.
/// Pre: W, H >= 1, W * H <= Grid::max_cells, 0 <= i < W * H (DomainError).
/// Post: cell_index(index_cell(i, W, H), W, H) == i. Golden: golden/grid/grid.index.json
[[nodiscard]] Cell index_cell(std::int64_t i, std::int64_t width, std::int64_t height);

/// A W x H occupancy grid. Immutable after construction except through set_blocked.
class Grid {
 public:
  /// All cells free. Pre: width >= 1, height >= 1, width * height <= max_cells (DomainError).
  Grid(std::int64_t width, std::int64_t height);

  /// From rows of '.' (free) and '#' (blocked), the FIRST string being the TOP row, as a map
  /// is drawn: row r is y = H - 1 - r.
  /// Source: pathref JSON encoding; Shi et al. 2022 Figure 1A origin at the lower left.
  /// Spec: grid.encoding. Pre: rows non-empty, all the same length >= 1, only '.' and '#',
  /// W * H <= max_cells (DomainError). Golden: golden/grid/grid.encoding.json
  [[nodiscard]] static Grid from_rows_top_first(const std::vector<std::string>& rows);
  /// Inverse of from_rows_top_first.
  [[nodiscard]] std::vector<std::string> to_rows_top_first() const;

  [[nodiscard]] std::int64_t width() const noexcept { return width_; }
  [[nodiscard]] std::int64_t height() const noexcept { return height_; }
  [[nodiscard]] std::int64_t cell_count() const noexcept { return width_ * height_; }

  [[nodiscard]] bool in_bounds(Cell c) const noexcept {
    return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_;
  }
  /// Cell index i = y * W + x: cell_index(c, W, H). Spec: grid.index.
  /// Pre: in_bounds(c) (DomainError). Post: 0 <= i < W * H.
  /// (Inline: the planners' inner loops call it; the dimensions were checked on construction.)
  [[nodiscard]] std::int64_t index(Cell c) const {
    if (!in_bounds(c)) [[unlikely]] throw_cell_outside();
    return c.y * width_ + c.x;
  }
  /// Inverse of index: index_cell(i, W, H) = (i mod W, floor(i / W)). Spec: grid.index.
  /// Pre: 0 <= i < W * H (DomainError). Post: index(cell(i)) == i.
  [[nodiscard]] Cell cell(std::int64_t i) const {
    if (i < 0 || i >= width_ * height_) [[unlikely]] throw_index_outside();
    return Cell{i % width_, i / width_};
  }

  /// True for a blocked cell. Pre: in_bounds(c) (DomainError).
  [[nodiscard]] bool blocked(Cell c) const { return blocked_[static_cast<std::size_t>(index(c))] != 0; }
  /// In bounds and not blocked. Never throws: out-of-bounds cells are simply not free.
  [[nodiscard]] bool free(Cell c) const noexcept {
    return in_bounds(c) && blocked_[static_cast<std::size_t>(c.y * width_ + c.x)] == 0;
  }
  void set_blocked(Cell c, bool is_blocked);
  [[nodiscard]] std::int64_t blocked_count() const noexcept;

  friend bool operator==(const Grid&, const Grid&) = default;

  /// Largest number of cells a Grid may hold (2^28): checked before allocating.
  static constexpr std::int64_t max_cells = std::int64_t{1} << 28;

 private:
  /// The DomainErrors of index and cell (the messages of cell_index and index_cell).
  [[noreturn]] static void throw_cell_outside();
  [[noreturn]] static void throw_index_outside();

  std::int64_t width_;
  std::int64_t height_;
  std::vector<std::uint8_t> blocked_;
};

/// One allowed move out of a cell: the target and its cost (1 or sqrt(2)).
struct Move {
  Cell to;
  double cost;
};

/// Whether the single step a -> b is allowed: b is one of a's 8 neighbours, both are in bounds
/// and free, and a diagonal step satisfies `policy` about the two orthogonal cells it passes
/// between (a cell outside the map counts as not free).
/// Source: Shi et al. 2022 Sec. 3 (8-neighbourhood; corner rule unstated); MovingAI rule = strict.
/// Spec: grid.corner-policy. Pre: none (never throws). Golden: golden/grid/grid.corner-policy.json
[[nodiscard]] bool step_allowed(const Grid& g, Cell a, Cell b, CornerPolicy policy) noexcept;

/// Cost of a step between 8-neighbours: the distance between centres, 1 or sqrt(2).
/// Source: Shi et al. 2022 Sec. 3 and Eq. (4). Spec: grid.moves.
/// Pre: a and b are distinct 8-neighbours (DomainError). Post: 1.0 or std::numbers::sqrt2.
/// Golden: golden/grid/grid.moves.json
[[nodiscard]] double step_cost(Cell a, Cell b);

/// The allowed moves out of `c`, in canonical order: increasing cell index. Every random choice
/// among neighbours indexes into this order.
/// Spec: grid.neighbour-order. Pre: g.free(c) (DomainError). Post: targets strictly increasing
/// in cell index, each step_allowed; costs as step_cost. Golden: golden/grid/grid.neighbour-order.json
[[nodiscard]] std::vector<Move> neighbours(const Grid& g, Cell c, CornerPolicy policy);

}  // namespace pathref::grid
