#include "pathref/sim/random_map.hpp"

#include <cmath>
#include <string>

#include "pathref/core/error.hpp"
#include "pathref/rng/draws.hpp"
#include "pathref/rng/mt19937.hpp"

namespace pathref::sim {

RandomMap random_map(std::uint32_t seed, std::int64_t edge, double ratio) {
  require(edge >= random_map_min_edge && edge <= random_map_max_edge,
          "random map: edge must lie in [2, 1000]");
  require(std::isfinite(ratio) && ratio >= 0.0 && ratio <= 1.0,
          "random map: ratio must be a finite number in [0, 1]");
  const std::int64_t cells = edge * edge;
  const double want = std::floor(ratio * static_cast<double>(cells));
  const auto n = static_cast<std::int64_t>(want);
  const std::int64_t capacity = cells - (2 * edge - 1);
  require(n <= capacity, "random map: floor(ratio * edge^2) = " + std::to_string(n) +
                             " obstacles do not fit beside the corridor (at most " +
                             std::to_string(capacity) + ")");
  RandomMap out;
  out.grid = grid::Grid(edge, edge);
  out.start = grid::Cell{0, 0};
  out.goal = grid::Cell{edge - 1, edge - 1};
  rng::Stream stream(seed);
  std::vector<std::uint8_t> reserved(static_cast<std::size_t>(cells), 0);
  grid::Cell c = out.start;
  out.corridor.push_back(c);
  reserved[static_cast<std::size_t>(out.grid.index(c))] = 1;
  while (!(c == out.goal)) {
    const std::int64_t rx = out.goal.x - c.x;
    const std::int64_t ry = out.goal.y - c.y;
    if (rx == 0) {
      ++c.y;
    } else if (ry == 0) {
      ++c.x;
    } else {
      const double u = stream.next_double();
      const auto k = static_cast<std::int64_t>(rng::uniform_index(u, static_cast<std::size_t>(rx + ry)));
      if (k < rx) {
        ++c.x;
      } else {
        ++c.y;
      }
    }
    out.corridor.push_back(c);
    reserved[static_cast<std::size_t>(out.grid.index(c))] = 1;
  }
  std::vector<std::int64_t> candidates;
  candidates.reserve(static_cast<std::size_t>(cells));
  for (std::int64_t i = 0; i < cells; ++i)
    if (reserved[static_cast<std::size_t>(i)] == 0) candidates.push_back(i);
  const auto count = static_cast<std::int64_t>(candidates.size());
  for (std::int64_t i = 0; i < n; ++i) {
    const double u = stream.next_double();
    const auto j =
        i + static_cast<std::int64_t>(rng::uniform_index(u, static_cast<std::size_t>(count - i)));
    std::swap(candidates[static_cast<std::size_t>(i)], candidates[static_cast<std::size_t>(j)]);
    out.grid.set_blocked(out.grid.cell(candidates[static_cast<std::size_t>(i)]), true);
  }
  out.obstacles = n;
  out.draws = static_cast<std::int64_t>(stream.doubles_drawn());
  return out;
}

}  // namespace pathref::sim
