// spec: han.maps.random, han.collision.classify, han.sim.motion, han.sim.detour, han.sim.run,
// han.sim.scenario-format, han.sim.safety, han.sim.evade, han.plan.iaco-astar (spec/han-sim.md)
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/rls.hpp"
#include "pathref/io/svg_sim.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/sim/encounter.hpp"
#include "pathref/planners/iaco_astar.hpp"
#include "pathref/sim/motion.hpp"
#include "pathref/sim/random_map.hpp"
#include "pathref/sim/simulate.hpp"
#include "support/paths.hpp"

using namespace pathref;
using sim::Vec2;

namespace {
std::string data(const std::string& name) { return pathref::testing::source_dir() + "/tests/data/sim/" + name; }
std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
sim::Scenario load(const std::string& name) {
  return sim::parse_scenario(slurp(data(name)), name, pathref::testing::source_dir() + "/tests/data/sim");
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
  // The same frontal scenario with a horizon of 1/16 s and no margin (a nearly blind robot, outside
  // the conditions of the guarantee): the test proves the collision detector can fire.
  auto s = load("frontal.json");
  s.horizon = 0.0625;
  s.margin = 0.0;
  const auto r = sim::simulate(s);
  CHECK_FALSE(r.collisions.empty());
}

TEST_CASE("han.sim.run: a frontal detour rejoins the global path inside it", "[han-sim]") {
  // tests/data/sim/frontal_rejoin.json (golden han.sim.run tcId 7): the swept global cells at
  // t = 4.125 are (6,2) ... (10,2), so the local target is (11,2), global index 11 of 0 ... 19.
  const auto r = sim::simulate(load("frontal_rejoin.json"));
  CHECK(r.reached_goal);
  CHECK(r.collisions.empty());
  REQUIRE(r.replans.size() == 1);
  const auto& p = r.replans[0];
  CHECK(p.t == 4.125);
  CHECK(p.from == grid::Cell{4, 2});
  CHECK(p.target == grid::Cell{11, 2});
  CHECK(p.target_index == 11);
  CHECK(p.target_index + 1 < static_cast<std::int64_t>(r.global_path.size()));  // an interior point
  CHECK(p.detour.back() == p.target);
  // After the detour the robot drives the rest of the global path: its samples beyond x = 11.5
  // all lie on y = 2.5, and it ends at the goal's centre.
  bool left_path = false;
  for (const auto& q : r.trajectory) {
    if (q.t > p.t && q.p.y != 2.5) left_path = true;
    if (q.p.x > 11.5) CHECK(q.p.y == 2.5);
  }
  CHECK(left_path);
  CHECK(r.trajectory.back().p == Vec2{19.5, 2.5});
  // the sum of the steps' ds in binary64: within a few hundred roundings of 19 + 2 sqrt 2
  CHECK(r.distance == Approx(19.0 + 2.0 * std::sqrt(2.0)).epsilon(1e-12));
}

TEST_CASE("han.sim.run: overtaking from behind and head-on without a detour", "[han-sim]") {
  // Overtaking at 2 m/s from 4 m behind: under the earlier rules (side + robot on the obstacle's
  // ray -> drive on) the obstacle hit the robot from behind in 10 steps, and in deadend.json and
  // room.json the robot drove on into the head-on obstacle (7 collision steps each, none flagged;
  // replayed with tools/crosscheck/rules/han_sim.py of commit 35ae60f). Now waiting and driving
  // on are both predicted to collide, so the robot steps aside (han.sim.evade).
  const auto o = sim::simulate(load("overtake.json"));
  CHECK(o.reached_goal);
  CHECK(o.collisions.empty());
  REQUIRE_FALSE(o.evasions.empty());
  CHECK(o.evasions[0].t == 0.125);
  CHECK(o.evasions[0].refuge == grid::Cell{0, 2});
  CHECK(o.unavoidable.empty());
  bool evading = false;
  for (const auto& q : o.trajectory) evading = evading || q.state == sim::RobotState::evade;
  CHECK(evading);
  // Head-on in a dead-end corridor one cell wide: no detour, no refuge at the end; the rules must
  // say so before the collision, and every collision is reported outside the guarantee.
  const auto d = sim::simulate(load("deadend.json"));
  REQUIRE_FALSE(d.collisions.empty());
  REQUIRE_FALSE(d.unavoidable.empty());
  CHECK(d.unavoidable.front().t <= d.collisions.front().t);
  bool trapped = false;
  for (const auto& u : d.unavoidable) trapped = trapped || u.reason == "trapped";
  CHECK(trapped);
  for (const auto& c : d.collisions) CHECK(c.outside_guarantee == "unavoidable");
  CHECK(sim::to_json(d, false).at("unexplained_collisions") == 0);
  // The same head-on encounter in a corridor that opens into a room behind the robot: the robot
  // retreats to a refuge in the room and lets the obstacle pass.
  const auto m = sim::simulate(load("room.json"));
  CHECK(m.reached_goal);
  CHECK(m.collisions.empty());
  CHECK(m.unavoidable.empty());
  CHECK_FALSE(m.evasions.empty());
}

TEST_CASE("han.sim.safety: hand margins at the sample times", "[han-sim]") {
  // golden han.sim.safety tcIds 2 and 4: head-on from rest, and a corner.
  const std::vector<Vec2> line{{0, 0}, {10, 0}};
  const auto h = sim::safety_margins(line, 0.0, 1.0, 1.0, 0.5, 1.0, rls::LinearMotion{-1.0, 5.0, 0.0, 0.0}, 0.0);
  CHECK(h.wait == 4.0);
  CHECK(h.go == 3.5);
  CHECK(h.go_closing);
  CHECK(h.samples == 3);
  const std::vector<Vec2> corner{{0, 0}, {1, 0}, {1, 1}};
  const auto c = sim::safety_margins(corner, 1.0, 1.0, 1.0, 0.75, 1.5, rls::LinearMotion{0.0, 1.0, 0.0, 1.0}, 0.0);
  CHECK(c.wait == std::sqrt(2.0));
  CHECK(c.go == 0.5);
  CHECK(sim::polyline_point(corner, 1.5) == Vec2{1.0, 0.5});
  CHECK(sim::polyline_point(corner, 5.0) == Vec2{1.0, 1.0});
  CHECK(sim::polyline_point(corner, -1.0) == Vec2{0.0, 0.0});
  CHECK_THROWS_AS(sim::safety_margins(line, 2.0, 1.0, 1.0, 0.5, 1.0, rls::LinearMotion{}, 0.0), DomainError);
  CHECK_THROWS_AS(sim::polyline_point(std::vector<Vec2>{}, 1.0), DomainError);
}

TEST_CASE("han.sim.evade: the nearest refuge", "[han-sim]") {
  // golden han.sim.evade tcIds 1-3.
  const grid::Grid g(5, 3);
  std::vector<std::uint8_t> band(15, 0);
  for (const int x : {1, 2, 3}) band[static_cast<std::size_t>(5 + x)] = 1;
  const std::vector<sim::RefugeSource> src{{grid::Cell{2, 1}, 0.0}};
  const auto r = sim::find_refuge(g, src, band, grid::CornerPolicy::strict);
  REQUIRE(r.found);
  CHECK(r.path == std::vector<grid::Cell>{{2, 1}, {2, 0}});
  CHECK(r.cost == 1.0);
  CHECK(r.source == 0);
  const grid::Grid line(3, 1);
  const std::vector<std::uint8_t> all{1, 1, 1};
  const std::vector<sim::RefugeSource> mid{{grid::Cell{1, 0}, 0.0}};
  const auto none = sim::find_refuge(line, mid, all, grid::CornerPolicy::strict);
  CHECK_FALSE(none.found);
  CHECK(none.path.empty());
  CHECK_THROWS_AS(sim::find_refuge(line, std::vector<sim::RefugeSource>{}, all, grid::CornerPolicy::strict), DomainError);
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

TEST_CASE("han.plan.iaco-astar: the global planner's parameters as <planner>.<name>", "[han-sim]") {
  const planners::Planner* p = planners::find_planner("iaco-astar");
  const planners::Planner* h = planners::find_planner("iaco-han");
  REQUIRE(p != nullptr);
  REQUIRE(h != nullptr);
  // Every parameter of every other planner is declared with its default (so that `plan --set`
  // validates it before the run), e.g. iaco-han.dead_end and astar.heuristic.
  CHECK(p->defaults.at("global") == "iaco-han");
  CHECK(p->defaults.at("iaco-han.dead_end") == h->defaults.at("dead_end"));
  CHECK(p->defaults.at("astar.heuristic") == "octile");
  CHECK_FALSE(p->defaults.contains("dead_end"));
  CHECK(planners::global_param_name("iaco-han", "ants") == "iaco-han.ants");
  const auto m = sim::random_map(3, 10, 0.3);
  planners::Request req;
  req.grid = &m.grid;
  req.start = m.start;
  req.goal = m.goal;
  req.seed = 5;
  req.params = planners::Json{{"iaco-han.dead_end", "die"}, {"iaco-han.ants", 7}, {"iaco-han.iterations", 4}};
  const auto r = p->run(req);
  planners::Request inner = req;
  inner.params = planners::Json{{"dead_end", "die"}, {"ants", 7}, {"iterations", 4}};
  const auto g = h->run(inner);
  // The same run as iaco-han with the unprefixed parameters, and the parameters used printed back
  // with the prefix (every one of iaco-han's).
  CHECK(r.found == g.found);
  CHECK(r.path == g.path);
  CHECK(r.best_per_iteration == g.best_per_iteration);
  CHECK(r.extra.at("global_extra").at("draws") == g.extra.at("draws"));
  CHECK(r.params_used.at("global") == "iaco-han");
  CHECK(r.params_used.at("iaco-han.dead_end") == "die");
  CHECK(r.params_used.at("iaco-han.ants") == 7);
  CHECK(r.params_used.size() == g.params_used.size() + 1);
  // A parameter of a planner that is not the global one, or an unprefixed one, is refused.
  req.params = planners::Json{{"astar.heuristic", "chebyshev"}};
  CHECK_THROWS_AS(p->run(req), UsageError);
  req.params = planners::Json{{"dead_end", "die"}};
  CHECK_THROWS_AS(p->run(req), UsageError);
  // Another global planner takes its own prefixed parameters.
  req.params = planners::Json{{"global", "astar"}, {"astar.heuristic", "chebyshev"}};
  const auto a = p->run(req);
  CHECK(a.params_used.at("astar.heuristic") == "chebyshev");
}

namespace {
std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}
}  // namespace

TEST_CASE("han.sim.run: the SVG has one wait marker per wait and time marks", "[han-sim]") {
  // spec/han-sim.md, CLI: one orange circle per wait interval with its duration (the side trace
  // waits once, 4.75 s to 9.375 s, i.e. 37 steps: formerly 37 identical circles), and a time mark
  // every 1 s on the robot's and the obstacle's tracks (arrival 16.625 s: marks 0, 1, ..., 16).
  const sim::Scenario s = load("side.json");
  const auto r = sim::simulate(s);
  const std::string svg = io::svg_simulation(s, r);
  CHECK(count(svg, "class=\"wait\"") == 1);
  CHECK(count(svg, ">wait 4.6 s</text>") == 1);
  // the robot stands still from 4.75 s to 9.375 s: its marks 5 ... 9 share one dot "5-9"
  CHECK(count(svg, "class=\"time-mark\"") == 13);
  CHECK(count(svg, ">5-9</text>") == 1);
  CHECK(count(svg, "class=\"obstacle-time-mark\"") == 17);
  CHECK(svg.find(">16</text>") != std::string::npos);
  CHECK(svg.find("time marks every 1 s") != std::string::npos);
  // The dead-end run (about 22 s): marks every 2 s; the overtaking run draws its evasion.
  const sim::Scenario d = load("deadend.json");
  const std::string dsvg = io::svg_simulation(d, sim::simulate(d));
  CHECK(dsvg.find("time marks every 2 s") != std::string::npos);
  const sim::Scenario o = load("overtake.json");
  CHECK(count(io::svg_simulation(o, sim::simulate(o)), "class=\"evasion\"") == 1);
}
