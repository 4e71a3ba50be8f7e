#include "support/generators.hpp"

#include <cmath>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/rng/draws.hpp"
#include "pathref/rng/mt19937.hpp"

namespace pathref::grid {
void showValue(const Cell& c, std::ostream& os) { os << "(" << c.x << ", " << c.y << ")"; }
void showValue(CornerPolicy p, std::ostream& os) { os << to_string(p); }
void showValue(const Grid& g, std::ostream& os) {
  os << g.width() << "x" << g.height();
  for (const auto& row : g.to_rows_top_first()) os << "\n  " << row;
}
}  // namespace pathref::grid

namespace pathref::testing {

rc::Gen<grid::Grid> gen_grid(int max_w, int max_h, double max_blocked_fraction) {
  require(max_w >= 1 && max_h >= 1, "gen_grid: max_w and max_h must be at least 1");
  require(max_blocked_fraction >= 0.0 && max_blocked_fraction <= 1.0,
          "gen_grid: max_blocked_fraction must lie in [0, 1]");
  const int max_permille = static_cast<int>(std::floor(max_blocked_fraction * 1000.0));
  return rc::gen::exec([=]() {
    const auto w = *rc::gen::inRange<int>(1, max_w + 1);
    const auto h = *rc::gen::inRange<int>(1, max_h + 1);
    const auto permille = *rc::gen::inRange<int>(0, max_permille + 1);
    // One value in [0, 1000) per cell; blocked when it falls in the top `permille` values, so
    // shrinking (towards 0) frees cells.
    const auto draws = *rc::gen::container<std::vector<int>>(
        static_cast<std::size_t>(w) * static_cast<std::size_t>(h), rc::gen::inRange<int>(0, 1000));
    grid::Grid g(w, h);
    for (std::int64_t i = 0; i < g.cell_count(); ++i) {
      if (draws[static_cast<std::size_t>(i)] >= 1000 - permille) g.set_blocked(g.cell(i), true);
    }
    return g;
  });
}

rc::Gen<grid::CornerPolicy> gen_policy() {
  return rc::gen::element(grid::CornerPolicy::never, grid::CornerPolicy::strict,
                          grid::CornerPolicy::one, grid::CornerPolicy::always);
}

rc::Gen<std::vector<grid::Cell>> gen_walk(const grid::Grid& g, grid::CornerPolicy policy,
                                          int max_steps) {
  require(max_steps >= 0, "gen_walk: max_steps must be >= 0");
  std::vector<grid::Cell> free_cells;
  for (std::int64_t i = 0; i < g.cell_count(); ++i)
    if (g.free(g.cell(i))) free_cells.push_back(g.cell(i));
  return rc::gen::exec([g, policy, max_steps, free_cells]() {
    std::vector<grid::Cell> path;
    if (free_cells.empty()) return path;
    path.push_back(free_cells[*rc::gen::inRange<std::size_t>(0, free_cells.size())]);
    const int steps = *rc::gen::inRange(0, max_steps + 1);
    for (int s = 0; s < steps; ++s) {
      const auto moves = grid::neighbours(g, path.back(), policy);
      if (moves.empty()) break;
      path.push_back(moves[*rc::gen::inRange<std::size_t>(0, moves.size())].to);
    }
    return path;
  });
}

grid::Grid random_grid(std::uint32_t seed, int w, int h, double blocked_fraction) {
  require(w >= 1 && h >= 1, "random_grid: w and h must be at least 1");
  require(blocked_fraction >= 0.0 && blocked_fraction <= 1.0,
          "random_grid: blocked_fraction must lie in [0, 1]");
  grid::Grid g(w, h);
  rng::Stream stream(seed);
  for (std::int64_t i = 0; i < g.cell_count(); ++i) {
    if (rng::bernoulli(stream.next_double(), blocked_fraction)) g.set_blocked(g.cell(i), true);
  }
  return g;
}

}  // namespace pathref::testing
