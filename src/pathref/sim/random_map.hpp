#pragma once
/// \file random_map.hpp
/// The random maps of Han's experimental protocol: square maps of edge 10 m to 100 m in 5 m steps
/// with 1 m cells, a static-obstacle ratio of 20 % to 70 %, start at the lower-left corner, goal at
/// the upper-right corner, connected by construction (a random monotone corridor is kept free).
/// Source: Han (IJACSA), Sec. IV ("the minimum size of the tested grid is 10 m x 10 m, with a
/// maximum size of 100 m x 100 m, with a grid growth step of 5 m"; "the proportion of static
/// obstacle grids ... within the range of 20% to 70%"). No DOI in the local text.
/// Spec: spec/han-sim.md (han.maps.random)
#include <cstdint>
#include <vector>

#include "pathref/grid/grid.hpp"

namespace pathref::sim {

/// A generated map with its start, goal, the free corridor and the number of draws consumed.
struct RandomMap {
  grid::Grid grid{1, 1};
  grid::Cell start;
  grid::Cell goal;
  std::vector<grid::Cell> corridor;  ///< the monotone 4-connected start -> goal corridor kept free
  std::int64_t obstacles = 0;        ///< blocked cells = floor(ratio * edge^2)
  std::int64_t draws = 0;            ///< doubles drawn from rng::Stream(seed)
};

/// Smallest and largest edge accepted by random_map (the protocol's are 10 and 100, step 5).
inline constexpr std::int64_t random_map_min_edge = 2;
inline constexpr std::int64_t random_map_max_edge = 1000;

/// True iff `edge` is one of the protocol's edges 10, 15, ..., 100 (Han Sec. IV).
/// Spec: han.maps.random
[[nodiscard]] constexpr bool is_protocol_edge(std::int64_t edge) noexcept {
  return edge >= 10 && edge <= 100 && edge % 5 == 0;
}

/// A random edge x edge map (1 m cells) from the pinned stream rng::Stream(seed). Draw order:
/// (1) the corridor from (0,0) to (E-1,E-1): at each cell with r_x > 0 and r_y > 0 cells left in
/// each direction, one draw u, k = rng.index(u, r_x + r_y), step +x iff k < r_x, else +y (no draw
/// when one direction is exhausted): every monotone lattice path equally likely;
/// (2) n = floor(ratio * E^2) obstacles among the cells off the corridor, listed by increasing
/// cell index: partial Fisher-Yates, for i = 0 .. n-1 one draw u, j = i + rng.index(u, N - i),
/// swap entries i and j, block entry i.
/// Source: Han (IJACSA), Sec. IV (protocol); pathref (generator). Spec: han.maps.random.
/// Pre: 2 <= edge <= 1000; ratio finite in [0, 1]; n <= E^2 - (2E - 1) (DomainError).
/// Post: start (0,0) and goal (E-1,E-1) free and 4-connected (so connected under every corner
/// policy); blocked_count == floor(ratio * E^2). Golden: golden/han-sim/han.maps.random.json
[[nodiscard]] RandomMap random_map(std::uint32_t seed, std::int64_t edge, double ratio);

}  // namespace pathref::sim
