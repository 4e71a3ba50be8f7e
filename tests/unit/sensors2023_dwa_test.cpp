// spec: sensors2023.eq9 ... eq14, sensors2023.dwa.*, sensors2023.sim.* (spec/sensors2023-dwa.md)
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/dwa.hpp"
#include "pathref/geometry/clearance.hpp"
#include "pathref/io/svg_fused.hpp"
#include "pathref/reproduce/sensors2023.hpp"
#include "pathref/sim/fused.hpp"

using namespace pathref;
using namespace pathref::dwa;

namespace {
const grid::Grid& open5() {
  static const grid::Grid g = grid::Grid::from_rows_top_first({".....", ".....", ".....", ".....", "....."});
  return g;
}
}  // namespace

TEST_CASE("sensors2023.eq9: hand values of the unicycle step") {
  const Pose p = motion_step(Pose{1.0, 2.0, 0.0}, 0.5, 0.25, 0.5);
  CHECK(p.x == 1.25);
  CHECK(p.y == 2.0);
  CHECK(p.theta == 0.125);
  // heading-first turns before moving: the same step lands elsewhere
  const Pose q = motion_step(Pose{0.0, 0.0, 0.0}, 1.0, 1.0, 0.5, MotionOrder::heading_first);
  CHECK(q.x == 0.5 * std::cos(0.5));
  CHECK(q.y == 0.5 * std::sin(0.5));
  const auto tr = predict(Pose{0.0, 0.0, 0.0}, 1.0, 0.0, 0.1, 3.0);
  REQUIRE(tr.size() == 30);
  CHECK(tr.back().x == Approx(3.0).epsilon(1e-12));
  CHECK(predicted_steps(0.3, 0.1) == 3);
  CHECK_THROWS_AS(motion_step(Pose{}, 1.0, 0.0, 0.0), DomainError);
  CHECK_THROWS_AS(predicted_steps(0.01, 1.0), DomainError);
}

TEST_CASE("sensors2023.eq10: velocity space") {
  const Window w = velocity_space(Limits{});
  CHECK(w.v_lo == 0.0);
  CHECK(w.v_hi == 1.0);
  CHECK(w.w_lo == -Limits{}.w_max);
  CHECK(w.w_hi == Limits{}.w_max);
  Limits bad;
  bad.v_min = 2.0;
  CHECK_THROWS_AS(velocity_space(bad), DomainError);
}

TEST_CASE("sensors2023.eq11: window and samples (include/exclude)") {
  Limits l;
  l.acc_v = 0.5;
  l.dec_v = 1.0;
  const Window w = dynamic_window(0.0, 0.0, l, 0.1);
  CHECK(w.v_lo == 0.0);  // clipped by v_min
  CHECK(w.v_hi == 0.05);
  const Window w2 = dynamic_window(1.0, l.w_max, l, 0.1);
  CHECK(w2.v_hi == 1.0);  // clipped by v_max
  CHECK(w2.v_lo == 0.9);
  CHECK(w2.w_hi == l.w_max);
  // 0.1 / 0.01 = 10.000000000000002: include has 11 samples, exclude 10
  CHECK(axis_samples(0.0, 0.1, 0.01, WindowUpper::include).size() == 11);
  CHECK(axis_samples(0.0, 0.1, 0.01, WindowUpper::exclude).size() == 10);
  CHECK(axis_samples(0.5, 0.5, 0.01, WindowUpper::exclude).size() == 1);
  CHECK(axis_samples(0.0, 0.015, 0.01, WindowUpper::include).size() == 2);
  CHECK_THROWS_AS(dynamic_window(2.0, 0.0, l, 0.1), DomainError);
  CHECK_THROWS_AS(axis_samples(0.0, 1.0, 0.0, WindowUpper::include), DomainError);
}

TEST_CASE("sensors2023.eq12: braking admissibility") {
  // sqrt(2 * 0.25 * 0.5) = 0.5
  CHECK(admissible(0.5, 0.0, 0.25, 0.5, 1.0));
  CHECK_FALSE(admissible(0.50001, 0.0, 0.25, 0.5, 1.0));
  // |w| <= sqrt(2 * 0.25 * 2) = 1
  CHECK_FALSE(admissible(0.1, -1.5, 0.25, 0.5, 2.0));
  CHECK(admissible(0.1, -1.5, 0.25, 0.5, 2.0, Admissible::linear));
  CHECK(admissible(9.0, 9.0, 0.0, 0.5, 2.0, Admissible::off));
  CHECK_THROWS_AS(admissible(0.1, 0.0, -0.1, 0.5, 1.0), DomainError);
}

TEST_CASE("sensors2023.eq13: normalised maximisation and cost minimisation") {
  std::vector<Terms> t(3);
  t[0] = Terms{90.0, 1.5707963267948966, 1.0, 0.0, true};
  t[1] = Terms{180.0, 0.0, 0.5, 0.5, true};
  t[2] = Terms{180.0, 0.0, 1.0, 1.0, false};  // invalid: ignored
  Weights w05;
  w05.alpha = 0.05;
  const Choice c = evaluate(t, w05, Evaluation::normalised, 1.0);
  // H = 270, D = 1.5, V = 0.5; G0 = 0.05/3 + 0.2*(2/3) + 0; G1 = 0.05*(2/3) + 0.2/3 + 0.1
  CHECK(c.scores[0] == Approx((0.05 / 3.0) + (0.2 * 2.0 / 3.0)));
  CHECK(c.scores[1] == Approx((0.05 * 2.0 / 3.0) + (0.2 / 3.0) + 0.1));
  CHECK(std::isnan(c.scores[2]));
  CHECK(c.best == 1);
  const Choice k = evaluate(t, Weights{}, Evaluation::cost, 1.0);
  // C0 = 0.15 * pi/2 + 1 + 1 = 2.2356; C1 = 0 + 0.5 + 2 = 2.5
  CHECK(k.best == 0);
  CHECK(k.scores[1] == 2.5);
  std::vector<Terms> none(2);
  CHECK(evaluate(none, Weights{}, Evaluation::normalised, 1.0).best == -1);
  // ties: the first in candidate order
  std::vector<Terms> tie(2, Terms{10.0, 0.1, 0.5, 0.2, true});
  CHECK(evaluate(tie, Weights{}, Evaluation::normalised, 1.0).best == 0);
  Weights neg;
  neg.alpha = -1.0;
  CHECK_THROWS_AS(evaluate(t, neg, Evaluation::normalised, 1.0), DomainError);
}

TEST_CASE("sensors2023.eq14: following heading term, wrapped and unwrapped") {
  CHECK(heading_term(Pose{0.0, 0.0, 0.0}, Point{1.0, 0.0}).heading_deg == 180.0);
  CHECK(heading_term(Pose{0.0, 0.0, pi / 2.0}, Point{1.0, 0.0}).heading_deg == Approx(90.0));
  // facing the target after a full turn: wrapped 180, unwrapped 180 - 360
  const Pose turned{0.0, 0.0, 2.0 * pi};
  CHECK(heading_term(turned, Point{1.0, 0.0}).heading_deg == Approx(180.0));
  CHECK(heading_term(turned, Point{1.0, 0.0}, HeadingWrap::off).heading_deg == Approx(-180.0));
  CHECK(wrap_angle(pi) == pi);
  CHECK(wrap_angle(-pi) == pi);
  CHECK(wrap_angle(3.0 * pi / 2.0) == Approx(-pi / 2.0));
}

TEST_CASE("sensors2023.dwa.clearance: cells, temporary cells, discs, cap") {
  const grid::Grid g = grid::Grid::from_rows_top_first({"...", ".#.", "..."});
  const Obstacles obs{&g, {}, {}};
  CHECK(geometry::point_box_distance(geometry::Vec2{0.5, 0.5}, 1.0, 1.0, 2.0, 2.0) == Approx(std::sqrt(0.5)));
  // (1.5, 0.75) is 0.25 below the blocked cell (1, 1): 0.25 - 0.3
  CHECK(point_clearance(Point{1.5, 0.75}, obs, 0.3, 1.0) == Approx(-0.05));
  CHECK(point_clearance(Point{1.5, 1.5}, obs, 0.3, 1.0) == -0.3);
  const std::vector<grid::Cell> temp{grid::Cell{0, 0}};
  const std::vector<Disc> discs{Disc{Point{2.5, 2.5}, 0.2, {}}};
  const grid::Grid& o = open5();
  const Obstacles obs2{&o, temp, discs};
  CHECK(point_clearance(Point{2.5, 1.5}, obs2, 0.3, 10.0) == Approx(0.5));  // disc: 1 - 0.2 - 0.3
  CHECK(point_clearance(Point{2.5, 2.5}, Obstacles{&o, {}, {}}, 0.0, 1.0) == 1.0);  // capped
  const std::vector<Pose> tr{Pose{2.5, 1.5, 0.0}, Pose{2.5, 2.5, 0.0}};
  CHECK(trajectory_clearance(tr, obs2, 0.3, 10.0) < 0.0);
  CHECK(trajectory_clearance(std::vector<Pose>{tr[0]}, obs2, 0.3, 10.0, ClearanceAt::end) == Approx(0.5));
  // a disc predicted tau seconds ahead along its velocity (obstacle_prediction = linear)
  const std::vector<Disc> moving{Disc{Point{2.5, 4.5}, 0.2, Point{0.0, -1.0}}};
  CHECK(point_clearance(Point{2.5, 1.5}, Obstacles{&o, {}, moving}, 0.3, 10.0, 2.0) == Approx(0.5));
  CHECK(trajectory_clearance(tr, Obstacles{&o, {}, moving}, 0.3, 10.0, ClearanceAt::trajectory, 1.0) ==
        Approx(-0.5));  // P_1 at tau 1 (disc at y 3.5: 1.5), P_2 at tau 2 (disc at y 2.5, on it: -0.5)
  CHECK_THROWS_AS(point_clearance(Point{0.0, 0.0}, obs, 0.3, 0.0), DomainError);
}

TEST_CASE("sensors2023.dwa.step: straight corridor and braking") {
  std::vector<std::string> rows(3, std::string(12, '.'));
  rows[0] = std::string(12, '#');
  rows[2] = std::string(12, '#');
  const grid::Grid g = grid::Grid::from_rows_top_first(rows);
  DwaParams prm;
  const StepResult s = control_step(Pose{1.5, 1.5, 0.0}, 0.0, 0.0, Point{10.5, 1.5}, Obstacles{&g, {}, {}}, prm);
  CHECK_FALSE(s.braked);
  CHECK(s.v > 0.0);  // accelerates toward the target down the corridor
  CHECK(std::fabs(s.w) < 0.1);
  // facing a wall 0.4 m ahead at full speed: every forward trajectory collides -> brake
  std::vector<std::string> rows2{"....#", "....#", "....#"};
  const grid::Grid g2 = grid::Grid::from_rows_top_first(rows2);
  const StepResult b = control_step(Pose{3.6, 1.5, 0.0}, 1.0, 0.0, Point{10.0, 1.5}, Obstacles{&g2, {}, {}}, prm);
  CHECK(b.braked);
  CHECK(b.v == Approx(0.95));
  CHECK(b.valid == 0);
}

TEST_CASE("sensors2023.dwa.follow: switching, blocked skip and timeout") {
  const std::vector<grid::Cell> path{{0, 0}, {1, 0}, {2, 0}, {3, 1}, {4, 2}, {4, 3}};
  const auto keys = key_nodes(path);
  REQUIRE(keys.size() == 4);  // (0,0), the turn (2,0), the turn (4,2), (4,3); (3,1) continues the diagonal
  CHECK(keys[1] == grid::Cell{2, 0});
  CHECK(keys[2] == grid::Cell{4, 2});
  const std::vector<Point> k{{0.5, 0.5}, {2.5, 0.5}, {4.5, 2.5}};
  const std::vector<std::uint8_t> free3{0, 0, 0};
  FollowParams fp;
  const FollowUpdate u = follow_update(FollowState{}, Point{0.5, 0.5}, k, 0.0, 0.1, fp, free3);
  CHECK(u.state.k == 1);
  CHECK(u.switched == 1);
  // the goal is never skipped, intermediate key nodes are
  const std::vector<std::uint8_t> b{0, 1, 0};
  FollowState st{1, 0.0, 2.95};
  const FollowUpdate s = follow_update(st, Point{0.5, 0.5}, k, 1.0, 0.1, fp, b);
  CHECK(s.skipped == SkipReason::blocked);
  CHECK(s.state.k == 2);
  const FollowUpdate t = follow_update(FollowState{1, 0.0, 0.0}, Point{0.5, 0.5}, k, 30.0, 0.1, fp, free3);
  CHECK(t.skipped == SkipReason::timeout);
  const FollowUpdate g = follow_update(FollowState{2, 0.0, 0.0}, Point{0.5, 0.5}, k, 1e4, 0.1, fp, std::vector<std::uint8_t>{1, 1, 1});
  CHECK(g.state.k == 2);
  CHECK(g.skipped == SkipReason::none);
}

TEST_CASE("sensors2023.dwa.follow: waypoints of the global path (heading_target = waypoint)") {
  // a grid path's key nodes, spacing one cell edge: the straight run gives its cells, the diagonal
  // run of 2 steps (2.83 m) gets ceil(2.83) = 3 equal parts
  const std::vector<Point> nodes{{0.5, 0.5}, {3.5, 0.5}, {5.5, 2.5}};
  const std::vector<Point> w = path_waypoints(nodes, 1.0);
  REQUIRE(w.size() == 7);
  CHECK(w[1].x == 1.5);
  CHECK(w[3].x == 3.5);
  CHECK(w[4].x == 3.5 + ((1.0 / 3.0) * 2.0));
  CHECK(w[6].x == 5.5);
  CHECK(w[6].y == 2.5);
  // a repeated node adds nothing; a single node is its own list
  CHECK(path_waypoints(std::vector<Point>{{1.0, 1.0}, {1.0, 1.0}}, 1.0).size() == 1);
  CHECK_THROWS_AS(path_waypoints(std::vector<Point>{}, 1.0), DomainError);
  CHECK_THROWS_AS(path_waypoints(nodes, 0.0), DomainError);
  CHECK_THROWS_AS(path_waypoints(nodes, std::nan("")), DomainError);
  CHECK_THROWS_AS(path_waypoints(nodes, 1e-6), DomainError);  // 4.2e6 points > 10^6
}

TEST_CASE("sensors2023.sim.run: the traditional DWA on the rebuilt scene (heading_target waypoint vs goal)") {
  // Issue 12: under the final-goal reading the paper's baseline stalls on the rebuilt 21 x 21 scene
  // (3.01 m in 29.9 s); under the default reading (waypoints of the global path) it follows the
  // A* path to the goal, as the paper's Table 2 row 3 and Fig. 13 show it doing.
  FusedScenario sc;
  sc.grid = grid::Grid::from_rows_top_first(reproduce::sensors2023_scene_rows());
  sc.start = grid::Cell{4, 3};
  sc.goal = grid::Cell{17, 16};
  sc.planner = "astar";
  sc.heading_target = HeadingTarget::waypoint;
  const FusedResult w = simulate_fused(sc);
  CHECK(w.outcome == Outcome::reached);
  CHECK(w.length < 1.1 * 20.7);  // astar's path is 20.7 m on this map
  CHECK(w.min_clearance >= 0.0);
  sc.heading_target = HeadingTarget::goal;
  const FusedResult g = simulate_fused(sc);
  CHECK(g.outcome == Outcome::stalled);
  CHECK(g.length < 4.0);
}

TEST_CASE("reproduce sensors2023: a missing or non-numeric value is an error, never 0") {
  const nlohmann::json o{{"child_nodes", 66}, {"turns_raw", nullptr}, {"name", "S8"}};
  CHECK(reproduce::sensors2023_required_number(o, "S8", "child_nodes") == 66.0);
  CHECK_THROWS_AS(reproduce::sensors2023_required_number(o, "S8", "generated"), DomainError);
  CHECK_THROWS_AS(reproduce::sensors2023_required_number(o, "S8", "turns_raw"), DomainError);
  CHECK_THROWS_AS(reproduce::sensors2023_required_number(o, "S8", "name"), DomainError);
  CHECK_THROWS_AS(reproduce::sensors2023_required_number(nlohmann::json::array(), "S8", "child_nodes"), DomainError);
  try {
    (void)reproduce::sensors2023_required_number(o, "scene.S8", "name");
    FAIL("no error");
  } catch (const DomainError& e) {
    CHECK(std::string(e.what()).find("scene.S8.name is not a number") != std::string::npos);
  }
}

TEST_CASE("sensors2023.sim.obstacles: waypoints") {
  const std::vector<Waypoint> w{{1.0, {0.0, 0.0}}, {3.0, {2.0, 4.0}}};
  CHECK(obstacle_position(w, 0.0) == Point{0.0, 0.0});
  CHECK(obstacle_position(w, 2.0) == Point{1.0, 2.0});
  CHECK(obstacle_position(w, 9.0) == Point{2.0, 4.0});
  const std::vector<Waypoint> bad{{1.0, {0.0, 0.0}}, {1.0, {2.0, 4.0}}};
  CHECK_THROWS_AS(obstacle_position(bad, 0.0), DomainError);
}

TEST_CASE("sensors2023.sim.collision: crossing mover and cells") {
  const grid::Grid& g = open5();
  // robot (0.5, 2.5) -> (1.5, 2.5) over [0, 1]; mover crosses its path at t = 0.5 at x = 1
  const std::vector<Mover> m{Mover{0.2, {{0.0, {1.0, 4.0}}, {1.0, {1.0, 1.0}}}}};
  // at t = 0.5 the mover is at (1, 2.5) and the robot at (1, 2.5): distance 0
  CHECK(step_clearance(Point{0.5, 2.5}, Point{1.5, 2.5}, 0.0, 1.0, 0.3, g, {}, m) < 0.0);
  // sampled only at the ends (t = 0, 1) the distances are 1.58 and 1.58: no collision seen
  const std::vector<Mover> far{Mover{0.2, {{0.0, {4.0, 4.0}}}}};
  CHECK(step_clearance(Point{0.5, 2.5}, Point{1.5, 2.5}, 0.0, 1.0, 0.3, g, {}, far) > 0.0);
  const std::vector<grid::Cell> temp{grid::Cell{2, 2}};
  CHECK(step_clearance(Point{0.5, 2.5}, Point{1.9, 2.5}, 0.0, 1.0, 0.3, g, temp, {}) < 0.0);
  CHECK(segment_cell_distance(Point{0.0, 0.5}, Point{3.0, 0.5}, grid::Cell{1, 0}) == 0.0);
  CHECK(segment_cell_distance(Point{0.0, 2.5}, Point{3.0, 2.5}, grid::Cell{1, 0}) == 1.5);
}

TEST_CASE("sensors2023.sim.turns: grid corners and smooth curves") {
  const TurnParams tp;
  CHECK(count_turns(std::vector<Point>{{0, 0}, {5, 0}}, tp) == 0);
  CHECK(count_turns(std::vector<Point>{{0, 0}, {5, 0}, {5, 5}}, tp) == 1);
  CHECK(count_turns(std::vector<Point>{{0, 0}, {5, 0}, {10, 5}, {10, 10}}, tp) == 2);
  CHECK(count_turns(std::vector<Point>{{0, 0}, {5, 0}, {5, 5}, {0, 5}}, tp) == 2);
  // a smooth quarter circle of radius 2, 90 points: one turn
  std::vector<Point> arc;
  for (int i = 0; i <= 90; ++i) {
    const double a = (static_cast<double>(i) * pi) / 180.0;
    arc.push_back(Point{2.0 * std::sin(a), 2.0 - (2.0 * std::cos(a))});
  }
  CHECK(count_turns(arc, tp) == 1);
  // a wobble of 1 degree: no turn
  CHECK(count_turns(std::vector<Point>{{0, 0}, {2, 0}, {4, 0.03}, {6, 0.0}}, tp) == 0);
  CHECK(track_length(std::vector<Point>{{0, 0}, {3, 4}}) == 5.0);
}

namespace {
std::string corridor_scenario(const std::string& extra) {
  return R"({"format": "pathref-sim 2", "map": ["...........", "...........", "..........."],
    "start": [0, 1], "goal": [10, 1], "path": [[0, 1], [10, 1]], "t_max": 60)" + extra + "}";
}
}  // namespace

TEST_CASE("sensors2023.sim.run: fused run reaches goal, collides, stalls, times out") {
  const FusedResult r = simulate_fused(parse_fused_scenario(corridor_scenario(""), "c.json", ""));
  CHECK(r.outcome == Outcome::reached);
  CHECK(r.length > 9.0);
  CHECK(r.length < 10.5);
  CHECK(r.turns == 0);
  CHECK(r.min_clearance > 0.0);
  CHECK(r.samples.back().t == r.time);
  // a mover driving into the robot from behind faster than it can flee: collided
  const FusedResult c = simulate_fused(parse_fused_scenario(
      corridor_scenario(R"(, "moving": [{"radius": 0.4, "waypoints": [[0, 0.5, 1.5], [4, 10.5, 1.5]]}])"), "c.json", ""));
  CHECK(c.outcome == Outcome::collided);
  CHECK(c.collision_clearance < 0.0);
  // a temporary wall across the corridor for ever: stalled in front of it
  const FusedResult s = simulate_fused(parse_fused_scenario(
      corridor_scenario(R"(, "temporary": [{"cell": [5, 0], "appear": 0, "disappear": 1000}, {"cell": [5, 1], "appear": 0, "disappear": 1000}, {"cell": [5, 2], "appear": 0, "disappear": 1000}])"),
      "c.json", ""));
  CHECK(s.outcome == Outcome::stalled);
  CHECK(s.min_clearance >= 0.0);
  // too little time: timed out
  const FusedResult t = simulate_fused(parse_fused_scenario(
      R"({"format": "pathref-sim 2", "map": ["...........", "...........", "..........."],
          "start": [0, 1], "goal": [10, 1], "path": [[0, 1], [10, 1]], "t_max": 2})", "c.json", ""));
  CHECK(t.outcome == Outcome::timed_out);
  CHECK(t.time == Approx(2.0));
  const std::string svg = io::svg_fused(parse_fused_scenario(corridor_scenario(""), "c.json", ""), r);
  CHECK(svg.find("class=\"trajectory\"") != std::string::npos);
}

TEST_CASE("sensors2023.sim.run: scenario parse errors with line and column") {
  try {
    (void)parse_fused_scenario(
        "{\"format\": \"pathref-sim 2\", \"start\": [0, 0], \"goal\": [2, 0],\n \"map\": [\"...\"],\n  \"t_max\": -1}", "f.json", "");
    FAIL("no error");
  } catch (const ParseError& e) {
    CHECK(e.line() == 3);
    CHECK(e.column() == 12);
    CHECK(std::string(e.what()).find("/t_max") != std::string::npos);
  }
  try {
    (void)parse_fused_scenario("{\"format\": \"pathref-sim 2\", \"map\": [\"...\"], \"start\": [0, 0],\n \"goal\": [2, 0], \"dwa\": {\"evaluation\": \"best\"}}",
                               "f.json", "");
    FAIL("no error");
  } catch (const ParseError& e) {
    CHECK(e.line() == 2);
    CHECK(std::string(e.what()).find("normalised") != std::string::npos);
  }
  CHECK_THROWS_AS(parse_fused_scenario("{\"format\": \"pathref-sim 2\"", "f.json", ""), ParseError);
  // heading_target: the three readings, anything else an error naming them
  const FusedScenario ws = parse_fused_scenario(
      R"({"format": "pathref-sim 2", "map": ["..."], "start": [0, 0], "goal": [2, 0], "dwa": {"heading_target": "waypoint"},
          "follow": {"waypoint_spacing": 0.5}})", "f.json", "");
  CHECK(ws.heading_target == HeadingTarget::waypoint);
  CHECK(ws.waypoint_spacing == 0.5);
  CHECK(params_json(ws).at("dwa").at("heading_target") == "waypoint");
  try {
    (void)parse_fused_scenario(R"({"format": "pathref-sim 2", "map": ["..."], "start": [0, 0], "goal": [2, 0], "dwa": {"heading_target": "next"}})",
                               "f.json", "");
    FAIL("no error");
  } catch (const ParseError& e) {
    CHECK(std::string(e.what()).find("\"waypoint\"") != std::string::npos);
  }
  CHECK_THROWS_AS(parse_fused_scenario(R"({"format": "pathref-sim 2", "map": ["..."], "start": [0, 0], "goal": [2, 0], "follow": {"waypoint_spacing": 0}})",
                                       "f.json", ""), ParseError);
  CHECK_THROWS_AS(parse_fused_scenario(R"({"format": "pathref-sim 2", "map": ["..."], "start": [0, 0], "goal": [2, 0], "bogus": 1})", "f.json", ""), ParseError);
  CHECK(scenario_format(R"({"format": "pathref-sim 1"})") == "pathref-sim 1");
  CHECK(scenario_format("not json").empty());
}
