// spec: grid.encoding, grid.index, grid.coord, grid.moves, grid.corner-policy, grid.neighbour-order
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/core/error.hpp"
#include "pathref/grid/coords.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/rng/draws.hpp"
#include "pathref/rng/mt19937.hpp"
#include "support/generators.hpp"

using namespace pathref;
using grid::Cell;
using grid::CornerPolicy;
using grid::Eq1Form;
using grid::Point;

TEST_CASE("grid.encoding: the first row is the top row", "[grid]") {
  const auto g = grid::Grid::from_rows_top_first({"..#", "#.."});
  CHECK(g.width() == 3);
  CHECK(g.height() == 2);
  CHECK(g.blocked(Cell{2, 1}));  // top row, last column
  CHECK(g.blocked(Cell{0, 0}));  // bottom row, first column
  CHECK_FALSE(g.blocked(Cell{0, 1}));
  CHECK(g.blocked_count() == 2);
  CHECK(g.to_rows_top_first() == std::vector<std::string>{"..#", "#.."});
  CHECK_THROWS_AS(grid::Grid::from_rows_top_first({"..", "."}), DomainError);
  CHECK_THROWS_AS(grid::Grid::from_rows_top_first({".x"}), DomainError);
  CHECK_THROWS_AS(grid::Grid::from_rows_top_first({}), DomainError);
  CHECK_THROWS_AS(grid::Grid::from_rows_top_first({""}), DomainError);
}

TEST_CASE("grid.encoding: JSON codec shapes and round trip", "[grid]") {
  using nlohmann::json;
  const auto g = grid::grid_from_json(json::parse(R"(["#.", ".."])"));
  CHECK(g.blocked(Cell{0, 1}));
  CHECK(grid::grid_to_json(g) == json::parse(R"(["#.", ".."])"));
  CHECK(grid::cell_from_json(json::parse("[3, -4]")) == Cell{3, -4});
  CHECK(grid::cell_to_json(Cell{3, -4}) == json::parse("[3, -4]"));
  const std::vector<Cell> path{{0, 0}, {1, 1}};
  CHECK(grid::path_from_json(grid::path_to_json(path)) == path);
  CHECK(grid::policy_from_json(json("one")) == CornerPolicy::one);
  // Wrong JSON shapes are malformed requests (UsageError), not domain errors.
  CHECK_THROWS_AS(grid::grid_from_json(json::parse(R"("..")")), UsageError);
  CHECK_THROWS_AS(grid::grid_from_json(json::parse(R"([1])")), UsageError);
  CHECK_THROWS_AS(grid::cell_from_json(json::parse("[1]")), UsageError);
  CHECK_THROWS_AS(grid::cell_from_json(json::parse("[1.5, 2]")), UsageError);
  CHECK_THROWS_AS(grid::cell_from_json(json::parse("[18446744073709551615, 0]")), UsageError);
  CHECK_THROWS_AS(grid::path_from_json(json::parse("[[0, 0], 3]")), UsageError);
  CHECK_THROWS_AS(grid::policy_from_json(json("diagonal")), UsageError);
  // Well-formed but outside the domain: DomainError.
  CHECK_THROWS_AS(grid::grid_from_json(json::parse(R"(["..", "."])")), DomainError);
}

TEST_CASE("grid.index: Shi Figure 1A numbering, S = 0 and T = 35 on 6x6", "[grid]") {
  CHECK(grid::cell_index(Cell{0, 0}, 6, 6) == 0);
  CHECK(grid::cell_index(Cell{5, 5}, 6, 6) == 35);
  CHECK(grid::cell_index(Cell{0, 1}, 6, 6) == 6);  // left to right, then bottom to top
  CHECK(grid::index_cell(11, 4, 3) == Cell{3, 2});
  const grid::Grid g(4, 3);
  CHECK(g.index(Cell{3, 2}) == 11);
  CHECK(g.cell(4) == Cell{0, 1});
  CHECK_THROWS_AS(grid::cell_index(Cell{4, 0}, 4, 3), DomainError);
  CHECK_THROWS_AS(grid::cell_index(Cell{0, -1}, 4, 3), DomainError);
  CHECK_THROWS_AS(grid::index_cell(12, 4, 3), DomainError);
  CHECK_THROWS_AS(grid::index_cell(0, 16384, 16385), DomainError);
  CHECK(grid::index_cell(268435455, 16384, 16384) == Cell{16383, 16383});
}

TEST_CASE("grid.coord: printed Eq. 1 erratum", "[grid]") {
  // Corrected: the centre of (x, y) is (x + 0.5, y + 0.5).
  CHECK(grid::cell_centre(0, 6, 6) == Point{0.5, 0.5});
  CHECK(grid::cell_centre(6, 6, 6) == Point{0.5, 1.5});
  CHECK(grid::cell_centre(35, 6, 6) == Point{5.5, 5.5});
  CHECK(grid::cell_centre(Cell{3, 2}) == Point{3.5, 2.5});
  // Printed, 0-based i: y = ceil(0/6) - 0.5 = -0.5 lies below the map; column 0 is a row low.
  CHECK(grid::cell_centre(0, 6, 6, Eq1Form::printed0) == Point{0.5, -0.5});
  CHECK(grid::cell_centre(6, 6, 6, Eq1Form::printed0) == Point{0.5, 0.5});
  CHECK(grid::cell_centre(7, 6, 6, Eq1Form::printed0) == Point{1.5, 1.5});  // right off column 0
  // Printed, 1-based k = i + 1: x is one column right and the last column wraps to 0.5.
  CHECK(grid::cell_centre(0, 6, 6, Eq1Form::printed1) == Point{1.5, 0.5});
  CHECK(grid::cell_centre(5, 6, 6, Eq1Form::printed1) == Point{0.5, 0.5});
  CHECK(grid::cell_centre(35, 6, 6, Eq1Form::printed1) == Point{0.5, 5.5});
  CHECK(grid::parse_eq1_form("printed1") == Eq1Form::printed1);
  CHECK_THROWS_AS(grid::parse_eq1_form("printed"), UsageError);
  CHECK_THROWS_AS(grid::cell_centre(36, 6, 6), DomainError);
  CHECK_THROWS_AS(grid::cell_centre(-1, 6, 6), DomainError);
  CHECK_THROWS_AS(grid::cell_centre(Cell{std::int64_t{1} << 52, 0}), DomainError);
}

TEST_CASE("grid.moves: step costs are 1 and sqrt(2)", "[grid]") {
  CHECK(grid::step_cost(Cell{2, 2}, Cell{3, 2}) == 1.0);
  CHECK(grid::step_cost(Cell{2, 2}, Cell{2, 1}) == 1.0);
  CHECK(grid::step_cost(Cell{2, 2}, Cell{1, 3}) == std::numbers::sqrt2);
  CHECK(std::numbers::sqrt2 == std::sqrt(2.0));  // the constant is the correctly rounded sqrt
  CHECK_THROWS_AS(grid::step_cost(Cell{0, 0}, Cell{0, 0}), DomainError);
  CHECK_THROWS_AS(grid::step_cost(Cell{0, 0}, Cell{2, 0}), DomainError);
}

TEST_CASE("grid.corner-policy: the four policies at a pinch point", "[grid]") {
  // (0,0) blocked: the diagonal (1,0) -> (0,1) passes between (0,0) (blocked) and (1,1) (free).
  const auto g = grid::Grid::from_rows_top_first({"..", "#."});
  const Cell a{1, 0}, b{0, 1};
  CHECK_FALSE(grid::step_allowed(g, a, b, CornerPolicy::never));
  CHECK_FALSE(grid::step_allowed(g, a, b, CornerPolicy::strict));
  CHECK(grid::step_allowed(g, a, b, CornerPolicy::one));
  CHECK(grid::step_allowed(g, a, b, CornerPolicy::always));
  // Both orthogonal cells blocked: only `always` allows it.
  const auto h = grid::Grid::from_rows_top_first({"#.", ".#"});
  CHECK_FALSE(grid::step_allowed(h, Cell{0, 0}, Cell{1, 1}, CornerPolicy::one));
  CHECK(grid::step_allowed(h, Cell{0, 0}, Cell{1, 1}, CornerPolicy::always));
  // Never a step: blocked target, out of bounds, same cell, non-neighbour.
  CHECK_FALSE(grid::step_allowed(g, a, Cell{0, 0}, CornerPolicy::always));
  CHECK_FALSE(grid::step_allowed(g, a, Cell{2, 0}, CornerPolicy::always));
  CHECK_FALSE(grid::step_allowed(g, a, a, CornerPolicy::always));
  CHECK_FALSE(grid::step_allowed(grid::Grid(3, 1), Cell{0, 0}, Cell{2, 0}, CornerPolicy::always));
  CHECK(grid::parse_corner_policy("never") == CornerPolicy::never);
  CHECK(grid::to_string(CornerPolicy::one) == "one");
  CHECK_THROWS_AS(grid::parse_corner_policy("Strict"), UsageError);
}

TEST_CASE("grid.neighbour-order: increasing cell index", "[grid]") {
  const grid::Grid g(3, 3);
  const auto n = grid::neighbours(g, Cell{1, 1}, CornerPolicy::strict);
  const std::vector<Cell> expected{{0, 0}, {1, 0}, {2, 0}, {0, 1}, {2, 1}, {0, 2}, {1, 2}, {2, 2}};
  REQUIRE(n.size() == expected.size());
  for (std::size_t k = 0; k < n.size(); ++k) {
    CHECK(n[k].to == expected[k]);
    CHECK(n[k].cost == grid::step_cost(Cell{1, 1}, expected[k]));
  }
  const auto blocked = grid::Grid::from_rows_top_first({"...", "...", ".#."});
  const auto m = grid::neighbours(blocked, Cell{1, 1}, CornerPolicy::strict);
  REQUIRE(m.size() == 5);
  CHECK(m.front().to == Cell{0, 1});
  CHECK_THROWS_AS(grid::neighbours(blocked, Cell{1, 0}, CornerPolicy::strict), DomainError);
  CHECK_THROWS_AS(grid::neighbours(blocked, Cell{-1, 0}, CornerPolicy::strict), DomainError);
}

TEST_CASE("random_grid: one Bernoulli draw per cell in index order", "[grid][support]") {
  const auto g = testing::random_grid(42, 5, 4, 0.3);
  REQUIRE(g.width() == 5);
  REQUIRE(g.height() == 4);
  rng::Stream s(42);
  for (std::int64_t i = 0; i < g.cell_count(); ++i)
    CHECK(g.blocked(g.cell(i)) == rng::bernoulli(s.next_double(), 0.3));
  CHECK(testing::random_grid(7, 6, 6, 0.0).blocked_count() == 0);
  CHECK(testing::random_grid(7, 6, 6, 1.0).blocked_count() == 36);
  CHECK(testing::random_grid(42, 5, 4, 0.3) == g);
  CHECK_THROWS_AS(testing::random_grid(1, 0, 4, 0.3), DomainError);
  CHECK_THROWS_AS(testing::random_grid(1, 4, 4, 1.5), DomainError);
}
