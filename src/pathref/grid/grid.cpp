#include "pathref/grid/grid.hpp"

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "pathref/core/error.hpp"

namespace pathref::grid {

CornerPolicy parse_corner_policy(std::string_view name) {
  if (name == "never") return CornerPolicy::never;
  if (name == "strict") return CornerPolicy::strict;
  if (name == "one") return CornerPolicy::one;
  if (name == "always") return CornerPolicy::always;
  throw UsageError("unknown corner policy '" + std::string(name) +
                   "' (expected never, strict, one or always)");
}

std::string_view to_string(CornerPolicy policy) noexcept {
  switch (policy) {
    case CornerPolicy::never: return "never";
    case CornerPolicy::strict: return "strict";
    case CornerPolicy::one: return "one";
    case CornerPolicy::always: return "always";
  }
  return "strict";
}

namespace {
void require_dimensions(std::int64_t width, std::int64_t height) {
  require(width >= 1 && height >= 1, "grid width and height must be at least 1");
  require(width <= Grid::max_cells / height, "grid has more cells than Grid::max_cells");
}
}  // namespace

std::int64_t cell_index(Cell c, std::int64_t width, std::int64_t height) {
  require_dimensions(width, height);
  require(c.x >= 0 && c.y >= 0 && c.x < width && c.y < height, "cell outside the grid");
  return c.y * width + c.x;
}

Cell index_cell(std::int64_t i, std::int64_t width, std::int64_t height) {
  require_dimensions(width, height);
  require(i >= 0 && i < width * height, "cell index outside [0, W*H)");
  return Cell{i % width, i / width};
}

Grid::Grid(std::int64_t width, std::int64_t height) : width_(width), height_(height) {
  require_dimensions(width, height);
  blocked_.assign(static_cast<std::size_t>(width * height), 0);
}

Grid Grid::from_rows_top_first(const std::vector<std::string>& rows) {
  require(!rows.empty(), "a grid needs at least one row");
  const auto w = static_cast<std::int64_t>(rows.front().size());
  Grid g(w, static_cast<std::int64_t>(rows.size()));
  const auto h = g.height();
  for (std::int64_t r = 0; r < h; ++r) {
    const std::string& row = rows[static_cast<std::size_t>(r)];
    require(static_cast<std::int64_t>(row.size()) == w, "all rows must have the same length");
    for (std::int64_t x = 0; x < w; ++x) {
      const char ch = row[static_cast<std::size_t>(x)];
      require(ch == '.' || ch == '#', "grid rows may contain only '.' and '#'");
      g.set_blocked(Cell{x, h - 1 - r}, ch == '#');
    }
  }
  return g;
}

std::vector<std::string> Grid::to_rows_top_first() const {
  std::vector<std::string> rows;
  rows.reserve(static_cast<std::size_t>(height_));
  for (std::int64_t y = height_ - 1; y >= 0; --y) {
    std::string row;
    row.reserve(static_cast<std::size_t>(width_));
    for (std::int64_t x = 0; x < width_; ++x) row.push_back(blocked(Cell{x, y}) ? '#' : '.');
    rows.push_back(std::move(row));
  }
  return rows;
}

void Grid::throw_cell_outside() { throw DomainError("cell outside the grid"); }

void Grid::throw_index_outside() { throw DomainError("cell index outside [0, W*H)"); }

void Grid::set_blocked(Cell c, bool is_blocked) {
  blocked_[static_cast<std::size_t>(index(c))] = is_blocked ? 1 : 0;
}

std::int64_t Grid::blocked_count() const noexcept {
  std::int64_t n = 0;
  for (const auto b : blocked_) n += b;
  return n;
}

bool step_allowed(const Grid& g, Cell a, Cell b, CornerPolicy policy) noexcept {
  const std::int64_t dx = b.x - a.x;
  const std::int64_t dy = b.y - a.y;
  if ((dx == 0 && dy == 0) || std::llabs(dx) > 1 || std::llabs(dy) > 1) return false;
  if (!g.free(a) || !g.free(b)) return false;
  if (dx == 0 || dy == 0) return true;
  const bool side1 = g.free(Cell{a.x + dx, a.y});
  const bool side2 = g.free(Cell{a.x, a.y + dy});
  switch (policy) {
    case CornerPolicy::never: return false;
    case CornerPolicy::strict: return side1 && side2;
    case CornerPolicy::one: return side1 || side2;
    case CornerPolicy::always: return true;
  }
  return false;
}

double step_cost(Cell a, Cell b) {
  const std::int64_t dx = std::llabs(b.x - a.x);
  const std::int64_t dy = std::llabs(b.y - a.y);
  require(dx <= 1 && dy <= 1 && dx + dy >= 1, "step_cost needs two distinct 8-neighbours");
  return (dx + dy == 2) ? std::numbers::sqrt2 : 1.0;
}

std::vector<Move> neighbours(const Grid& g, Cell c, CornerPolicy policy) {
  require(g.free(c), "neighbours of a blocked or out-of-bounds cell");
  std::vector<Move> out;
  out.reserve(8);
  // Rows bottom to top, columns left to right: this is increasing cell index.
  for (std::int64_t dy = -1; dy <= 1; ++dy) {
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      const Cell n{c.x + dx, c.y + dy};
      if (step_allowed(g, c, n, policy)) out.push_back(Move{n, step_cost(c, n)});
    }
  }
  return out;
}

}  // namespace pathref::grid
