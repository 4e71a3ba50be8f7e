// S-RRT in the continuous plane (spec/cin2021-srrt.md): exact collision checks (ties, touching,
// decimal radii that binary64 gets wrong), steering, nearest-node ties, Algorithm 1's draw
// order on a hand-checked run, Algorithm 2 on a given path.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "pathref/io/scene_json.hpp"
#include "pathref/continuous/kdtree.hpp"
#include "pathref/continuous/rrt.hpp"
#include "pathref/continuous/srrt.hpp"
#include "pathref/core/error.hpp"
#include "pathref/geometry/decimal.hpp"
#include "pathref/geometry/obstacles.hpp"
#include "pathref/geometry/scene.hpp"
#include "pathref/rng/mt19937.hpp"

using namespace pathref;
using namespace pathref::continuous;
using geometry::ObstacleMap;

namespace {

// Register the S-RRT rules (pathref_geometry) before anything builds the rule registry.
const bool srrt_rules_installed = (geometry::install_srrt_rules(), true);

geometry::Scene scene_of(const std::string& polygons_json, const char* rad = "0", const char* mar = "0",
                         int w = 10, int h = 10) {
  const std::string text = std::string("{\"format\": \"pathref-scene 1\", \"origin\": [0, 0], \"width\": ") +
                           std::to_string(w) + ", \"height\": " + std::to_string(h) +
                           ", \"cell_size\": 1, \"radius\": " + rad + ", \"margin\": " + mar +
                           ", \"polygons\": " + polygons_json + ", \"start\": [0, 0], \"goal\": [1, 0]}";
  return io::parse_scene_json(text, "t.json");
}

const char* unit_square = "[{\"vertices\": [[1, 1], [2, 1], [2, 2], [1, 2]]}]";

}  // namespace

TEST_CASE("cin2021.srrt.collision: ties at distance r collide, decimal r decided exactly") {
  const ObstacleMap m = ObstacleMap::from_scene(scene_of(unit_square, "0.25", "0.25"));  // r = 0.5
  CHECK(m.compare_segment(0, {2.5, 1.5}, {2.5, 1.5}) == 0);     // exactly r: a tie
  CHECK_FALSE(m.point_free({2.5, 1.5}));                          // ties collide (closed sets)
  CHECK(m.point_free({std::nextafter(2.5, 3.0), 1.5}));           // one ulp farther: free
  CHECK(m.compare_segment(0, {2.5, 0.0}, {2.5, 3.0}) == 0);
  CHECK_FALSE(m.segment_free({2.5, 0.0}, {2.5, 3.0}));
  CHECK(m.segment_free({std::nextafter(2.5, 3.0), 0.0}, {std::nextafter(2.5, 3.0), 3.0}));
  // r = 0.1 is not a binary64 value; the double nearest 2.1 lies above 2.1 (free), the next
  // double below it lies below 2.1 (within r: collision).
  const ObstacleMap m2 = ObstacleMap::from_scene(scene_of(unit_square, "0.1"));
  CHECK(m2.point_free({2.1, 1.5}));
  CHECK_FALSE(m2.point_free({std::nextafter(2.1, 0.0), 1.5}));
  CHECK(m2.compare_segment(0, {2.1, 1.5}, {2.1, 1.5}) == 1);
}

TEST_CASE("cin2021.srrt.collision: crossing, inside, grazing a corner, world border") {
  const ObstacleMap m = ObstacleMap::from_scene(scene_of(unit_square));  // r = 0
  CHECK_FALSE(m.segment_free({0.0, 1.5}, {3.0, 1.5}));  // crosses, both ends outside
  CHECK_FALSE(m.segment_free({1.2, 1.2}, {1.8, 1.8}));  // inside
  CHECK_FALSE(m.segment_free({1.5, 2.0}, {1.5, 3.0}));  // touches the top edge (closed set)
  CHECK_FALSE(m.segment_free({1.0, 3.0}, {3.0, 1.0}));  // through the corner (2, 2) exactly
  CHECK(m.segment_free({std::nextafter(1.0, 2.0), 3.0}, {3.0, std::nextafter(1.0, 2.0)}));  // misses it by ~1e-16
  CHECK(m.segment_free({0.0, 0.0}, {10.0, 0.5}));
  CHECK_FALSE(m.point_free({-0.5, 0.5}));                 // outside the world rectangle
  CHECK_FALSE(m.segment_free({9.0, 9.0}, {10.5, 9.0}));
  CHECK(m.point_free({10.0, 10.0}));                      // the rectangle is closed
  CHECK_THROWS_AS(m.compare_segment(1, {0, 0}, {1, 0}), DomainError);
  CHECK_THROWS_AS(m.segment_free({std::nan(""), 0}, {1, 0}), DomainError);
}

TEST_CASE("cin2021.srrt.collision: grid cells are closed unit squares, diagonal gaps collide") {
  const grid::Grid g = grid::Grid::from_rows_top_first({"....", ".#..", "..#.", "...."});
  // rows top first: (1,2) and (2,1) blocked; they touch at the corner (2, 2)
  const ObstacleMap m = ObstacleMap::from_grid(g, geometry::decimal_from_integer(0));
  CHECK(m.polygon_count() == 2);
  CHECK(m.lower() == Vec2{0.0, 0.0});
  CHECK(m.upper() == Vec2{4.0, 4.0});
  CHECK_FALSE(m.segment_free({0.5, 0.5}, {3.5, 3.5}));  // y = x meets both squares only at their shared corner (2, 2)
  CHECK(m.segment_free({0.5, 0.5}, {3.5, 0.5}));
  CHECK_FALSE(m.point_free({1.5, 2.5}));
  CHECK(m.point_free({0.5, 0.5}));
  CHECK(m.point_distance({0.5, 2.5}) == 0.5);
}

TEST_CASE("cin2021.srrt.steer: clip and fixed readings") {
  CHECK(steer({0, 0}, {3, 4}, 1.0) == Vec2{0.2 * 3, 0.2 * 4});
  CHECK(steer({0, 0}, {3, 4}, 5.0) == Vec2{3, 4});           // d = delta: the target
  CHECK(steer({0, 0}, {3, 4}, 10.0) == Vec2{3, 4});          // clip
  CHECK(steer({0, 0}, {3, 4}, 10.0, false) == Vec2{6, 8});   // fixed: overshoots
  CHECK(steer({1, 1}, {1, 1}, 1.7) == Vec2{1, 1});           // zero distance
  CHECK_THROWS_AS(steer({0, 0}, {1, 0}, 0.0), DomainError);
  CHECK_THROWS_AS(steer({0, 0}, {1, 0}, std::nan("")), DomainError);
}

TEST_CASE("cin2021.srrt.nearest: the oldest of equally near nodes") {
  KdTree t;
  for (const Vec2 p : {Vec2{2, 0}, Vec2{0, 2}, Vec2{-2, 0}, Vec2{0, -2}, Vec2{2, 0}}) t.insert(p);
  CHECK(t.nearest({0, 0}) == 0);   // four at distance 2: index 0
  CHECK(t.nearest({1, 1}) == 0);   // (2,0) and (0,2) tie at sqrt 2: index 0
  CHECK(t.nearest({-1, 1}) == 1);  // (0,2) and (-2,0) tie: index 1
  CHECK(t.nearest({3, 0}) == 0);   // duplicate point 4: the older one
  CHECK(nearest_brute_force(t.points(), {-1, -1}) == 2);
  CHECK(t.nearest({-1, -1}) == 2);
  const KdTree empty;
  CHECK_THROWS_AS(empty.nearest({0, 0}), DomainError);
}

TEST_CASE("cin2021.alg1: draw order of the paper variant, written out") {
  // Empty 10 x 10 world, start (1, 1), goal (9, 9), delta 1.7, P_g 0.6, bias lt, near sample.
  const ObstacleMap m = ObstacleMap::from_scene(scene_of("[]"));
  RrtParams p;
  p.max_iterations = 3;
  rng::Stream s(5);
  const RrtResult r = rrt(m, {1, 1}, {9, 9}, p, s);
  // Replay by hand: per iteration u1, u2 (sample), then u3 (the bias test).
  rng::Stream d(5);
  std::vector<Vec2> nodes{{1, 1}};
  for (int i = 0; i < 3; ++i) {
    const double u1 = d.next_double(), u2 = d.next_double();
    const Vec2 x_rand{0.0 + u1 * 10.0, 0.0 + u2 * 10.0};
    const std::size_t near = nearest_brute_force(nodes, x_rand);
    const double u3 = d.next_double();
    const Vec2 target = u3 < 0.6 ? Vec2{9, 9} : x_rand;
    nodes.push_back(steer(nodes[near], target, 1.7));
  }
  REQUIRE(r.nodes.size() == 4);
  CHECK(r.nodes == nodes);
  CHECK(r.draws == 9);
  CHECK(r.iterations == 3);
  CHECK_FALSE(r.found);
  // Same seed, same tree.
  rng::Stream s2(5);
  CHECK(rrt(m, {1, 1}, {9, 9}, p, s2).nodes == r.nodes);
}

TEST_CASE("cin2021.alg1: the goal test adds the goal within delta over a free edge") {
  const ObstacleMap m = ObstacleMap::from_scene(scene_of("[]"));
  RrtParams p;
  rng::Stream s(1);
  const RrtResult r = rrt(m, {1, 1}, {2, 2}, p, s);  // the root is within 1.7 of the goal
  CHECK(r.found);
  CHECK(r.iterations == 0);
  CHECK(r.draws == 0);
  CHECK(r.path == std::vector<std::size_t>{0, 1});
  rng::Stream s3(1);
  CHECK_THROWS_AS(rrt(m, {1, 1}, {1, 1}, p, s3), DomainError);
  const ObstacleMap blocked = ObstacleMap::from_scene(scene_of(unit_square));
  CHECK_THROWS_AS(rrt(blocked, {1.5, 1.5}, {5, 5}, p, s3), DomainError);
}

TEST_CASE("cin2021.alg2: greedy reverse shortcut on a given path") {
  // A wall x in [4, 5], y in [0, 6]; the path goes around its top.
  const ObstacleMap m = ObstacleMap::from_scene(scene_of("[{\"vertices\": [[4, 0], [5, 0], [5, 6], [4, 6]]}]"));
  const std::vector<Vec2> path{{1, 1}, {2, 3}, {3, 6}, {4, 7}, {5, 7}, {6, 6}, {7, 3}, {8, 1}};
  const std::vector<std::size_t> kept = shortcut(m, path);
  // From (1,1): (8,1),(7,3),(6,6),(5,7) blocked by the wall; (4,7) visible. From (4,7): (8,1)? the
  // segment passes x = 5 at y = 5.5 < 6: blocked; (7,3) passes x = 5 at y = 17/3 < 6: blocked;
  // (6,6): free. From (6,6): (8,1) free.
  CHECK(kept == std::vector<std::size_t>{0, 3, 5, 7});
  std::vector<Vec2> out;
  for (const auto k : kept) out.push_back(path[k]);
  CHECK(polyline_length(out) <= polyline_length(path));
  CHECK(shortcut(m, {{1, 1}}) == std::vector<std::size_t>{0});
  CHECK_THROWS_AS(shortcut(m, {{3, 3}, {6, 3}}), DomainError);  // not a free path
  CHECK(branch({-1, 0, 1, 1, 3}, 4) == std::vector<std::size_t>{0, 1, 3, 4});
  CHECK_THROWS_AS(branch({-1, 2, 0}, 1), DomainError);
}

TEST_CASE("cin2021.srrt.metrics: length, nodes, clearance") {
  const ObstacleMap m = ObstacleMap::from_scene(scene_of(unit_square));
  const PathMetrics pm = path_metrics(m, {{0, 0}, {4, 0}, {4, 4}});
  CHECK(pm.length == 8.0);
  CHECK(pm.nodes == 3);
  CHECK(pm.clearance == 1.0);  // y = 0 is 1 below the square [1,2]^2; x = 4 is 2 to its right
  CHECK(path_metrics(m, {{0, 0}, {3, 4}}).clearance == 0.0);  // y = 4x/3 crosses the square
  const ObstacleMap none = ObstacleMap::from_scene(scene_of("[]"));
  CHECK(std::isinf(path_metrics(none, {{0, 0}, {1, 1}}).clearance));
}
