// Unit tests of the sensors2023 global planner (spec/sensors2023.md eq1-eq5 and the planner).
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/heuristics.hpp"
#include "pathref/equations/sensors2023.hpp"
#include "pathref/planners/astar_kinematic.hpp"
#include "pathref/planners/search.hpp"
#include "support/generators.hpp"

using pathref::DomainError;
using pathref::grid::Cell;
using pathref::grid::CornerPolicy;
using pathref::grid::Grid;
namespace s23 = pathref::sensors2023;

TEST_CASE("sensors2023.eq1: every row of Table 1 and its exact boundaries") {
  // Table 1 (spec/sensors2023.md): kept bearings per row.
  const std::vector<std::array<int, 5>> keep = {
      {0, 45, 90, 270, 315},   {0, 45, 90, 135, 315},   {0, 45, 90, 135, 180},
      {45, 90, 135, 180, 225}, {90, 135, 180, 225, 270}, {135, 180, 225, 270, 315},
      {0, 180, 225, 270, 315}, {0, 45, 225, 270, 315}};
  const std::vector<std::array<int, 3>> abandon = {{135, 180, 225}, {180, 225, 270}, {225, 270, 315},
                                                   {0, 270, 315},   {0, 45, 315},    {0, 45, 90},
                                                   {45, 90, 135},   {90, 135, 180}};
  for (int s = 0; s < 8; ++s) {
    CHECK(s23::kept_bearings(s) == keep[static_cast<std::size_t>(s)]);
    CHECK(s23::abandoned_bearings(s) == abandon[static_cast<std::size_t>(s)]);
    // the row's interval [22.5 + 45 (s - 1), 22.5 + 45 s): both ends, and just inside
    const double lo = s == 0 ? 337.5 : 22.5 + 45.0 * (s - 1);
    const double hi = s == 0 ? 22.5 : 22.5 + 45.0 * s;
    CHECK(s23::bearing_sector(lo) == s);
    CHECK(s23::bearing_sector(std::nextafter(hi, 0.0)) == s);
    CHECK(s23::bearing_sector(hi == 360.0 ? 0.0 : hi) == (s + 1) % 8);
  }
  CHECK(s23::bearing_sector(0.0) == 0);
  CHECK(s23::bearing_sector(std::nextafter(360.0, 0.0)) == 0);
  CHECK_THROWS_AS(s23::bearing_sector(360.0), DomainError);
  CHECK_THROWS_AS(s23::bearing_sector(-1e-300), DomainError);
  // Eq. 1 on cells: clockwise from +Y
  CHECK(s23::goal_bearing({0, 0}, {0, 5}) == 0.0);
  CHECK(s23::goal_bearing({0, 0}, {5, 0}) == 90.0);
  CHECK(s23::goal_bearing({0, 0}, {0, -5}) == Approx(180.0).margin(1e-12));
  CHECK(s23::goal_bearing({0, 0}, {-5, 0}) == 270.0);
  CHECK(s23::goal_bearing({0, 0}, {3, 3}) == 45.0);
  // the paper's 5-direction test (6,7) -> (17,16): theta = atan2(11, 9) from +Y = 50.7 deg, row 1
  CHECK(s23::bearing_sector(s23::goal_bearing({6, 7}, {17, 16})) == 1);
  CHECK_THROWS_AS(s23::goal_bearing({1, 1}, {1, 1}), DomainError);
}

TEST_CASE("sensors2023.eq1: the reduction applies only in an obstacle-free neighbourhood") {
  Grid g = Grid::from_rows_top_first({".....", ".....", ".....", ".....", "#...."});
  // (2,2): 8-neighbourhood free -> 5 directions towards the goal (4,4): sector 1 (45 deg)
  const auto m = s23::child_moves(g, {2, 2}, {4, 4}, 1);
  CHECK(m == s23::bearing_mask(s23::kept_bearings(1)));
  CHECK(std::popcount(static_cast<unsigned>(m)) == 5);
  // radius 2 sees the blocked (0,0): all 8
  CHECK(s23::child_moves(g, {2, 2}, {4, 4}, 2) == 0xFF);
  CHECK(s23::neighbourhood_free(g, {1, 1}, 1) == false);
  // at the map's edge, off-map cells are not obstacles
  CHECK(s23::neighbourhood_free(g, {4, 4}, 1) == true);
  CHECK(s23::child_moves(g, {4, 4}, {4, 4}, 1) == 0xFF);  // the goal itself
}

TEST_CASE("sensors2023.eq4: weights linear, exp and none") {
  CHECK(s23::heuristic_weight(5.0, 10.0, s23::WeightForm::linear) == 1.5);
  CHECK(s23::heuristic_weight(0.0, 10.0, s23::WeightForm::linear) == 1.0);
  CHECK(s23::heuristic_weight(5.0, 10.0, s23::WeightForm::exp) == std::exp(0.5));
  CHECK(s23::heuristic_weight(5.0, 10.0, s23::WeightForm::none) == 1.0);
  CHECK(s23::heuristic_weight(5.0, 0.0, s23::WeightForm::linear) == 1.0);
  CHECK(s23::f_weighted(2.0, 4.0, 4.0, 8.0, s23::WeightForm::linear) == 8.0);
  CHECK(s23::f_basic(2.0, 4.0) == 6.0);
  CHECK_THROWS_AS(s23::f_weighted(-1.0, 4.0, 4.0, 8.0, s23::WeightForm::linear), DomainError);
  CHECK_THROWS_AS(s23::parse_weight_form("square"), pathref::UsageError);
}

TEST_CASE("sensors2023.eq5: collision test and equal-division safety test by hand") {
  // 5x5, one blocked cell (2,2)
  const Grid g = Grid::from_rows_top_first({".....", ".....", "..#..", ".....", "....."});
  CHECK(s23::segment_blocked(g, {0, 0}, {4, 4}));       // through the centre
  CHECK_FALSE(s23::segment_blocked(g, {1, 1}, {1, 3}));  // beside it
  CHECK_FALSE(s23::segment_blocked(g, {1, 3}, {3, 4}));  // (1.5,3.5)-(3.5,4.5): passes above
  // (0,1) -> (3,4) touches the corner (2,3)? line y = x + 1 in centres: (0.5,1.5)-(3.5,4.5)
  // passes through (2, 3), the top-left corner of cell (2,2): touching is not a collision
  CHECK_FALSE(s23::segment_blocked(g, {0, 1}, {3, 4}));
  // ... but the safety test refuses it: (2, 3) is sqrt(0.5) from the centre (2.5, 2.5) < 1
  const auto tight = s23::safety_test(g, {0, 1}, {3, 4}, 4, 1.0, s23::SafetyCompare::ge);
  CHECK_FALSE(tight.safe);
  CHECK(tight.divisions == static_cast<std::int64_t>(std::ceil(4.0 * std::sqrt(18.0))));
  // a segment exactly one edge from the centre passes with ge, fails with gt
  CHECK(s23::safety_test(g, {0, 1}, {4, 1}, 4, 1.0, s23::SafetyCompare::ge).safe);
  CHECK_FALSE(s23::safety_test(g, {0, 1}, {4, 1}, 4, 1.0, s23::SafetyCompare::gt).safe);
  CHECK_THROWS_AS(s23::safety_test(g, {1, 1}, {1, 1}, 4, 1.0, s23::SafetyCompare::ge), DomainError);
  CHECK_THROWS_AS(s23::safety_test(g, {1, 1}, {1, 2}, 0, 1.0, s23::SafetyCompare::ge), DomainError);
}

TEST_CASE("sensors2023.plan.astar-kinematic: plain settings equal astar with the Euclidean h") {
  const Grid g = Grid::from_rows_top_first({"..........", "..##...#..", "..##...#..", "......##..",
                                            ".#........", ".#...###..", "..........", "...#......"});
  s23::KinematicOptions o;
  o.directions = 8;
  o.weight = s23::WeightForm::none;
  o.redundancy = s23::Redundancy::none;
  for (const auto policy : {CornerPolicy::never, CornerPolicy::strict, CornerPolicy::one, CornerPolicy::always}) {
    const auto k = s23::plan_kinematic(g, {0, 0}, {9, 7}, policy, o);
    const auto a = pathref::search::astar(g, {0, 0}, {9, 7}, policy, pathref::heuristics::Heuristic::euclidean);
    CHECK(k.search.path == a.path);
    CHECK(k.search.expansions == a.expansions);
    CHECK(k.search.generated == a.generated);
    CHECK(k.search.child_nodes == a.child_nodes);
    CHECK(k.key_nodes == a.path);
  }
}

TEST_CASE("sensors2023.plan.astar-kinematic: fallback finds the paths the 5 directions miss") {
  // Over fixed random maps (tests/support random_grid, seeds 1..150, 20x20, 10 % and 35 %
  // blocked): with fallback=full the planner finds a path iff one exists; where the literal
  // 5-direction search (fallback=none) succeeds, both agree and the fallback does not run; where
  // it fails on a reachable goal, the fallback runs and costs more expansions.
  int literal_missed = 0;
  for (const double density : {0.10, 0.35}) {
    for (std::uint32_t seed = 1; seed <= 150; ++seed) {
      Grid g = pathref::testing::random_grid(seed, 20, 20, density);
      g.set_blocked({0, 0}, false);
      g.set_blocked({19, 19}, false);
      const auto a = pathref::search::astar(g, {0, 0}, {19, 19}, CornerPolicy::strict,
                                            pathref::heuristics::Heuristic::euclidean);
      s23::KinematicOptions o;
      o.fallback = false;
      const auto lit = s23::plan_kinematic(g, {0, 0}, {19, 19}, CornerPolicy::strict, o);
      o.fallback = true;
      const auto fb = s23::plan_kinematic(g, {0, 0}, {19, 19}, CornerPolicy::strict, o);
      CHECK(fb.search.found == a.found);
      if (lit.search.found) {
        CHECK_FALSE(fb.fallback_used);
        CHECK(fb.search.path == lit.search.path);
        CHECK(fb.search.expansions == lit.search.expansions);
      } else if (a.found) {
        ++literal_missed;
        CHECK(fb.fallback_used);
        CHECK(fb.search.expansions > lit.search.expansions);
      } else {
        CHECK(fb.fallback_used);  // unreachable: the fallback ran and also failed
        CHECK_FALSE(fb.search.found);
      }
    }
  }
  // Not asserted (either count is legitimate): on these maps the literal 5-direction search
  // missed no reachable goal (the Python probe of the crosscheck agrees), printed for the record.
  WARN("maps where the literal 5-direction search missed a reachable goal: " << literal_missed);
}

TEST_CASE("sensors2023.eq2: the Euclidean h is search.h.euclidean, one function") {
  CHECK(pathref::heuristics::euclidean({0, 0}, {3, 4}) == 5.0);
  CHECK(pathref::heuristics::euclidean({6, 7}, {17, 16}) == std::sqrt(202.0));
  CHECK(pathref::heuristics::evaluate(pathref::heuristics::Heuristic::euclidean, {6, 7}, {17, 16}) ==
        pathref::heuristics::euclidean({6, 7}, {17, 16}));
}
