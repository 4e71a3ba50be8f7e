// spec: han.maps.random, han.collision.classify, han.sim.motion, han.sim.detour, han.sim.run,
// han.sim.scenario-format, han.plan.iaco-astar (spec/han-sim.md)
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/sim/encounter.hpp"
#include "pathref/sim/motion.hpp"
#include "pathref/sim/random_map.hpp"
#include "pathref/sim/simulate.hpp"

using namespace pathref;
using sim::Vec2;

namespace {
std::string data(const std::string& name) { return std::string(PATHREF_SOURCE_DIR) + "/tests/data/sim/" + name; }
std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
sim::Scenario load(const std::string& name) {
  return sim::parse_scenario(slurp(data(name)), name, std::string(PATHREF_SOURCE_DIR) + "/tests/data/sim");
}
std::string parse_error(const std::string& text) {
  try {
    (void)sim::parse_scenario(text, "s.json", "");
  } catch (const ParseError& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST_CASE("han.maps.random: corridor, obstacle count and draws", "[han-sim]") {
  const auto m = sim::random_map(7, 10, 0.2);
  CHECK(m.grid.width() == 10);
  CHECK(m.grid.blocked_count() == 20);
  CHECK(m.corridor.size() == 19);
  CHECK(m.corridor.front() == grid::Cell{0, 0});
  CHECK(m.corridor.back() == grid::Cell{9, 9});
  for (const auto c : m.corridor) CHECK(m.grid.free(c));
  // 18 corridor steps with both directions open until one is exhausted, plus one draw per obstacle.
  CHECK(m.draws >= 20 + 9);
  CHECK(m.draws <= 20 + 18);
  CHECK(sim::random_map(7, 10, 0.2).grid == m.grid);
  CHECK_FALSE(sim::random_map(8, 10, 0.2).grid == m.grid);
  CHECK(sim::is_protocol_edge(10));
  CHECK(sim::is_protocol_edge(100));
  CHECK_FALSE(sim::is_protocol_edge(12));
  CHECK_THROWS_AS(sim::random_map(1, 10, 0.9), DomainError);
  CHECK_THROWS_AS(sim::random_map(1, 1, 0.0), DomainError);
  CHECK_THROWS_AS(sim::random_map(1, 10, std::nan("")), DomainError);
}

TEST_CASE("han.collision.classify: the cases of Figure 5", "[han-sim]") {
  const std::vector<Vec2> robot{{0, 0}, {4, 0}};
  const double c = 0.85;
  CHECK(sim::classify(robot, {2, 2}, {2, 1}, c).kind == sim::Encounter::none);
  const auto side = sim::classify(robot, {2, 2}, {2, 0.5}, c);
  CHECK(side.kind == sim::Encounter::side);
  CHECK(side.distance == 0.5);
  const auto head = sim::classify(robot, {6, 0.25}, {3, 0.25}, c);
  CHECK(head.kind == sim::Encounter::frontal);
  CHECK(head.cos_angle == -1.0);
  CHECK(sim::classify(robot, {2, 0.5}, {2, 0.5}, c).kind == sim::Encounter::frontal);
  // An obstacle moving the same way ahead of the robot: side (wait for it to move on).
  CHECK(sim::classify(robot, {2, 0.2}, {3, 0.2}, c).kind == sim::Encounter::side);
  // frontal_cos = -1 makes only exactly opposite motions frontal.
  CHECK(sim::classify(robot, {5, 1}, {1, -1}, c, -1.0).kind == sim::Encounter::side);
  CHECK_THROWS_AS(sim::classify(std::vector<Vec2>{{0, 0}}, {2, 2}, {2, 1}, c), DomainError);
  CHECK_THROWS_AS(sim::classify(robot, {2, 2}, {2, 1}, 0.0), DomainError);
  CHECK(sim::segment_distance({0, 0}, {2, 2}, {0, 2}, {2, 0}) == 0.0);
  CHECK(sim::point_ray_distance({5, 0}, {0, 1}, {1, 1}) == 1.0);
  CHECK(sim::point_segment_distance({5, 0}, {0, 1}, {1, 1}) == std::sqrt(17.0));
}

TEST_CASE("han.sim.motion: ramp from rest, cruise, arrival within a step", "[han-sim]") {
  auto m = sim::motion_step(0.0, 0.125, 1.0, 1.0);
  CHECK(m.distance == 0.0078125);
  CHECK(m.v_end == 0.125);
  CHECK_FALSE(m.arrived);
  m = sim::motion_step(0.9375, 0.125, 1.0, 1.0);
  CHECK(m.distance == 0.123046875);
  CHECK(m.v_end == 1.0);
  m = sim::motion_step(1.0, 0.125, 1.0, 1.0, 0.0625);
  CHECK(m.arrived);
  CHECK(m.time == 0.0625);
  CHECK(sim::ramp_cruise_time(9.0, 1.0, 1.0) == 9.5);
  CHECK(sim::ramp_cruise_time(0.5, 1.0, 1.0) == 1.0);
  CHECK_THROWS_AS(sim::motion_step(1.5, 0.125, 1.0, 1.0), DomainError);
  CHECK_THROWS_AS(sim::motion_step(0.0, 0.0, 1.0, 1.0), DomainError);
}

TEST_CASE("han.sim.detour: swept cells and the local target", "[han-sim]") {
  const grid::Grid g(12, 5);
  const auto cells = sim::swept_cells(g, {9.4375, 2.5}, {7.9375, 2.5}, 0.85);
  CHECK(cells.size() == 13);
  const std::vector<std::uint8_t> flags{0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 0};
  CHECK(sim::local_target(flags, 4) == 11);
  CHECK(sim::local_target(flags, 11) == 11);
  const std::vector<std::uint8_t> goal_blocked{0, 0, 1};
  CHECK(sim::local_target(goal_blocked, 0) == -1);
  CHECK_THROWS_AS(sim::local_target(flags, 12), DomainError);
}

TEST_CASE("han.sim.run: scripted none, side and frontal encounters", "[han-sim]") {
  const auto none = sim::simulate(load("none.json"));
  CHECK(none.reached_goal);
  CHECK(none.collisions.empty());
  CHECK(none.waits.empty());
  CHECK(none.replans.empty());
  CHECK(none.time == 9.5);  // ramp_cruise_time(9 m)
  CHECK(none.distance == 9.0);

  const auto side = sim::simulate(load("side.json"));
  CHECK(side.reached_goal);
  CHECK(side.collisions.empty());
  REQUIRE(side.waits.size() == 1);
  CHECK(side.waits[0].start == 4.75);  // hand: first t with 5.5 - t < 0.85 on the 1/8 s grid
  CHECK(side.waits[0].end == 9.375);   // hand: first t with 1.5 - (10 - t) >= 0.85
  CHECK(side.time == 16.625);          // 9.375 + ramp_cruise_time(6.75 m) = 9.375 + 7.25
  CHECK(side.replans.empty());

  const auto frontal = sim::simulate(load("frontal.json"));
  CHECK(frontal.reached_goal);
  CHECK(frontal.collisions.empty());
  CHECK(frontal.waits.empty());
  REQUIRE(frontal.replans.size() == 1);
  CHECK(frontal.replans[0].t == 4.125);
  CHECK(frontal.replans[0].from == grid::Cell{4, 2});
  CHECK(frontal.replans[0].target == grid::Cell{11, 2});
  CHECK(frontal.distance > 11.0);
}

TEST_CASE("han.sim.run: a head-on obstacle hits a robot that ignores it", "[han-sim]") {
  // The same frontal scenario with a clearance margin that cannot be met in time (horizon tiny):
  // the test proves the collision detector can fire.
  auto s = load("frontal.json");
  s.horizon = 0.0625;
  s.margin = 0.0;
  const auto r = sim::simulate(s);
  CHECK_FALSE(r.collisions.empty());
}

TEST_CASE("han.sim.scenario-format: errors name the JSON pointer", "[han-sim]") {
  CHECK(parse_error("{") .find("s.json:1:") != std::string::npos);
  CHECK(parse_error(R"({"format": "pathref-sim 2"})").find("/format") != std::string::npos);
  const std::string base = R"({"format": "pathref-sim 1", "map": ["...."], "start": [0, 0], "goal": [3, 0], )";
  CHECK(parse_error(base + R"("obstacles": [{"position": [1, 2]}]})").find("/obstacles/0/velocity: missing") !=
        std::string::npos);
  CHECK(parse_error(base + R"("dt": -1})").find("/dt: expected a number in") != std::string::npos);
  CHECK(parse_error(base + R"("speed": 1})").find("/speed: unknown key") != std::string::npos);
  CHECK(parse_error(R"({"format": "pathref-sim 1", "map": ["..", "."], "start": [0, 0], "goal": [1, 0]})")
            .find("/map/1") != std::string::npos);
  CHECK(parse_error(R"({"format": "pathref-sim 1", "map": [".#"], "start": [0, 0], "goal": [1, 0]})")
            .find("/goal: on a blocked cell") != std::string::npos);
  const auto ok = sim::parse_scenario(base + R"("seed": 5, "noise": 0.1})", "s.json", "");
  CHECK(ok.seed == 5);
  CHECK(ok.noise == 0.1);
  CHECK(ok.planner == "iaco-han");
}

TEST_CASE("han.plan.iaco-astar: the static result is the global planner's path", "[han-sim]") {
  const planners::Planner* p = planners::find_planner("iaco-astar");
  REQUIRE(p != nullptr);
  const planners::Planner* a = planners::find_planner("astar");
  REQUIRE(a != nullptr);
  const auto m = sim::random_map(3, 15, 0.3);
  planners::Request req;
  req.grid = &m.grid;
  req.start = m.start;
  req.goal = m.goal;
  req.params = planners::Json{{"global", "astar"}};
  const auto r = p->run(req);
  req.params = planners::Json::object();
  const auto ra = a->run(req);
  CHECK(r.found);
  CHECK(r.path == ra.path);
  CHECK(r.extra.at("global") == "astar");
  req.params = planners::Json{{"global", "iaco-astar"}};
  CHECK_THROWS_AS(p->run(req), UsageError);
  req.params = planners::Json{{"global", "no-such-planner"}};
  CHECK_THROWS_AS(p->run(req), UsageError);
}
