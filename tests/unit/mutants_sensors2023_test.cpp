// Issue 17: hand-derived tests that kill the sensors2023 / sensors2023-dwa mutants of
// tools/mutate.d/sensors2023.json which the existing tests let survive (or only the golden
// vectors killed). Each oracle is worked out by hand in the comment next to it.
// spec: spec/sensors2023-dwa.md (sensors2023.eq13, .dwa.step, .dwa.follow, .sim.*)
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

#include "pathref/equations/dwa.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/sim/fused.hpp"

using namespace pathref;
using namespace pathref::dwa;

TEST_CASE("sensors2023.eq13: cost minimisation keeps the first candidate on a tie") {
  // two identical valid candidates: C_0 == C_1, the spec's tie rule picks candidate order's first
  Terms t;
  t.heading_deg = 90.0;
  t.abs_dtheta = 0.5;
  t.clearance = 0.5;
  t.velocity = 0.25;
  t.valid = true;
  const std::vector<Terms> two{t, t};
  const Choice c = evaluate(two, Weights{}, Evaluation::cost, 1.0);
  // C = 0.15 * 0.5 + 1 * (1 - 0.25) + 1 * (1 / 0.5) = 0.075 + 0.75 + 2
  CHECK(c.scores[0] == Approx(2.825).epsilon(1e-12));
  CHECK(c.scores[0] == c.scores[1]);
  CHECK(c.best == 0);
  // an invalid first candidate is skipped: the tie is then between 1 and 2, 1 wins
  Terms bad = t;
  bad.valid = false;
  const std::vector<Terms> three{bad, t, t};
  CHECK(evaluate(three, Weights{}, Evaluation::cost, 1.0).best == 1);
}

TEST_CASE("sensors2023.dwa.step: a candidate with clearance exactly 0 is valid (not a collision)") {
  // one row of three cells, the middle one blocked: the cell square [1, 2] x [0, 1]. The robot
  // (radius 0) stands at (1.0, 0.5), on that square's left edge: surface distance 0. With
  // v_min = v_max = 0 and w_max = 0 the window is the single pair (0, 0): the robot stays put,
  // the trajectory clearance is 0 (raw clearance >= 0: not colliding), and Eq. 12 at dist = 0 gives
  // 0 <= sqrt(0) and |0| <= sqrt(0): admissible. So the one candidate is valid and no braking.
  const grid::Grid g = grid::Grid::from_rows_top_first({".#."});
  DwaParams prm;
  prm.limits.v_min = 0.0;
  prm.limits.v_max = 0.0;
  prm.limits.w_max = 0.0;
  prm.radius = 0.0;
  const Obstacles obs{&g, {}, {}};
  const StepResult r = control_step(Pose{1.0, 0.5, 0.0}, 0.0, 0.0, Point{2.5, 0.5}, obs, prm);
  CHECK(r.candidates == 1);
  CHECK(r.valid == 1);
  CHECK(r.best == 0);
  CHECK_FALSE(r.braked);
  CHECK(point_clearance(Point{1.0, 0.5}, obs, 0.0, 1.0) == 0.0);
}

TEST_CASE("sensors2023.dwa.follow: a key node at exactly the reach distance is reached") {
  // |p - K_0| = |(1, 0) - (0, 0)| = 1 = reach: the rule is |p - K_k| <= reach, so k -> 1
  const std::vector<Point> keys{{0.0, 0.0}, {5.0, 0.0}};
  const std::vector<std::uint8_t> none{0, 0};
  FollowParams fp;
  fp.reach = 1.0;
  const FollowUpdate u = follow_update(FollowState{}, Point{1.0, 0.0}, keys, 2.0, 0.1, fp, none);
  CHECK(u.switched == 1);
  CHECK(u.state.k == 1);
  CHECK(u.state.since == 2.0);
  // just outside: no switch
  const FollowUpdate o = follow_update(FollowState{}, Point{1.0, 0.0625}, keys, 2.0, 0.1, fp, none);
  CHECK(o.switched == 0);
  CHECK(o.state.k == 0);
}

TEST_CASE("sensors2023.dwa.follow: blocked for exactly the timeout skips the key node") {
  // blocked_for 0.5 + dt 0.5 = 1.0 (exact in binary) >= blocked_timeout 1.0: skip (blocked)
  const std::vector<Point> keys{{0.5, 0.5}, {2.5, 0.5}, {4.5, 2.5}};
  const std::vector<std::uint8_t> b{0, 1, 0};
  FollowParams fp;
  fp.blocked_timeout = 1.0;
  const FollowUpdate s = follow_update(FollowState{1, 0.0, 0.5}, Point{0.5, 0.5}, keys, 1.0, 0.5, fp, b);
  CHECK(s.skipped == SkipReason::blocked);
  CHECK(s.state.k == 2);
  CHECK(s.state.blocked_for == 0.0);
  // 0.25 + 0.5 = 0.75 < 1: kept, blocked_for accumulates
  const FollowUpdate k = follow_update(FollowState{1, 0.0, 0.25}, Point{0.5, 0.5}, keys, 1.0, 0.5, fp, b);
  CHECK(k.skipped == SkipReason::none);
  CHECK(k.state.k == 1);
  CHECK(k.state.blocked_for == 0.75);
}

TEST_CASE("sensors2023.sim.obstacles: interpolation on a later segment uses that segment's times") {
  // (0, (0, 0)), (1, (1, 0)), (3, (1, 4)): at t = 2, segment 1, f = (2 - 1) / (3 - 1) = 0.5
  // -> (1, 0) + 0.5 * ((1, 4) - (1, 0)) = (1, 2); at t = 1.5, f = 0.25 -> (1, 1)
  const std::vector<Waypoint> w{{0.0, {0.0, 0.0}}, {1.0, {1.0, 0.0}}, {3.0, {1.0, 4.0}}};
  CHECK(obstacle_position(w, 2.0) == Point{1.0, 2.0});
  CHECK(obstacle_position(w, 1.5) == Point{1.0, 1.0});
  CHECK(obstacle_position(w, 0.5) == Point{0.5, 0.0});
  CHECK(obstacle_position(w, 1.0) == Point{1.0, 0.0});
}

TEST_CASE("sensors2023.sim.collision: a mover turning inside the step is followed through its waypoint") {
  // 5 x 5 open map (outside = blocked), robot (radius 0) standing at (2.5, 2.5) over [0, 1].
  // The mover (radius 0) goes (0.5, 2.5) -> (2.5, 2.5) over [0, 0.5] and back over [0.5, 1]: at
  // t = 0.5 it is on the robot, so the step clearance is exactly 0. Its end positions alone
  // ((0.5, 2.5) at t = 0 and t = 1) are 2 away: a step test that ignored the waypoint at t = 0.5
  // would report min(2, 2.5 to the map's outside) = 2.
  const grid::Grid g = grid::Grid::from_rows_top_first({".....", ".....", ".....", ".....", "....."});
  const std::vector<Mover> m{Mover{0.0, {{0.0, {0.5, 2.5}}, {0.5, {2.5, 2.5}}, {1.0, {0.5, 2.5}}}}};
  CHECK(step_clearance(Point{2.5, 2.5}, Point{2.5, 2.5}, 0.0, 1.0, 0.0, g, {}, m) == 0.0);
  // the map alone: 2.5 to the outside cells
  CHECK(step_clearance(Point{2.5, 2.5}, Point{2.5, 2.5}, 0.0, 1.0, 0.0, g, {}, {}) == 2.5);
}

TEST_CASE("sensors2023.sim.turns: a run whose summed change equals theta exactly is a turn") {
  // track (0,0) -> (3,0) -> (3,3), ds = 1: resampled (0,0) (1,0) (2,0) (3,0) (3,1) (3,2) (3,3)
  // (all exact); chord headings 0, 0, 0, pi/2, pi/2, pi/2: one change d = wrap(atan2(1, 0) - 0)
  // (pi/2 up to rounding), then zeros. With theta = d the run's |sum| = theta: the spec counts
  // a run whose sum reaches theta (>=), so 1 turn; with theta one ulp above, 0 turns.
  const double d = wrap_angle(std::atan2(1.0, 0.0) - 0.0);
  CHECK(d == Approx(1.5707963267948966).epsilon(1e-15));
  const std::vector<Point> track{{0.0, 0.0}, {3.0, 0.0}, {3.0, 3.0}};
  TurnParams p;
  p.ds = 1.0;
  p.delta = 0.1;
  p.theta = d;
  CHECK(count_turns(track, p) == 1);
  p.theta = std::nextafter(d, 4.0);
  CHECK(count_turns(track, p) == 0);
}

namespace {
// A 3 x 3 open map (outside = blocked), start (1, 1), goal (1, 2), a robot that cannot move
// (v_min = v_max = 0, w_max = 0: the window is the single pair (0, 0)) and dt = 0.1.
FusedScenario still_robot() {
  FusedScenario s;
  s.grid = grid::Grid::from_rows_top_first({"...", "...", "..."});
  s.start = grid::Cell{1, 1};
  s.goal = grid::Cell{1, 2};
  s.dwa.limits.v_min = 0.0;
  s.dwa.limits.v_max = 0.0;
  s.dwa.limits.w_max = 0.0;
  s.dwa.dt = 0.1;
  return s;
}
}  // namespace

TEST_CASE("sensors2023.sim.run: a step with clearance exactly 0 is no collision and the stall fires at k = stall_n") {
  // robot radius 1.5 at the centre (1.5, 1.5): the map's outside cells are 1.5 away, so every step
  // clearance is 1.5 - 1.5 = 0 exactly: not < 0, no collision (the spec: a step collides when its
  // clearance is < 0). The robot never moves: stall_n = llround(1.0 / 0.1) = 10, and at k = 10
  // (t = 1.0) |p - p_0| = 0 < 0.1: stalled after 10 steps.
  FusedScenario s = still_robot();
  s.dwa.radius = 1.5;
  s.stall_window = 1.0;
  const FusedResult r = simulate_fused(s);
  CHECK(r.outcome == Outcome::stalled);
  CHECK(r.steps == 10);
  CHECK(r.time == 1.0);
  CHECK(r.min_clearance == 0.0);
}

TEST_CASE("sensors2023.sim.run: the run times out at t = t_max exactly") {
  // same still robot (radius 0.3, no stall within the run): the time test t >= t_max fires at
  // k = 10, t = 10 * 0.1 = 1.0 = t_max, after 10 steps
  FusedScenario s = still_robot();
  s.t_max = 1.0;
  s.stall_window = 10.0;
  const FusedResult r = simulate_fused(s);
  CHECK(r.outcome == Outcome::timed_out);
  CHECK(r.steps == 10);
  CHECK(r.time == 1.0);
}

TEST_CASE("sensors2023.sim.run: a goal exactly goal_reach away is reached at once") {
  // start (0, 0), goal (2, 0) on an open 3 x 1 row: centres (0.5, 0.5) and (2.5, 0.5), 2 apart;
  // goal_reach = 2: the goal test |p - goal| <= goal_reach holds at t = 0, before any step
  FusedScenario s;
  s.grid = grid::Grid::from_rows_top_first({"..."});
  s.start = grid::Cell{0, 0};
  s.goal = grid::Cell{2, 0};
  s.goal_reach = 2.0;
  const FusedResult r = simulate_fused(s);
  CHECK(r.outcome == Outcome::reached);
  CHECK(r.steps == 0);
  CHECK(r.time == 0.0);
}

TEST_CASE("sensors2023.eq12: the angular bound admits |w| equal to sqrt(2 dist dec_w)") {
  // dist = 0.25, dec_w = 2: sqrt(2 * 0.25 * 2) = sqrt(1) = 1 exactly; |w| = 1 <= 1 is admissible
  // (v = 0 <= sqrt(2 * 0.25 * 1) passes the linear part)
  CHECK(admissible(0.0, 1.0, 0.25, 1.0, 2.0, Admissible::both));
  CHECK(admissible(0.0, -1.0, 0.25, 1.0, 2.0, Admissible::both));
  CHECK_FALSE(admissible(0.0, 1.0 + 1e-12, 0.25, 1.0, 2.0, Admissible::both));
  // the linear bound alone ignores w
  CHECK(admissible(0.0, 5.0, 0.25, 1.0, 2.0, Admissible::linear));
}

TEST_CASE("sensors2023.dwa.clearance: a disc is taken at its predicted position c + tau vel") {
  // open 7 x 7 map (outside = blocked, 3.5 from the centre point), p = (3.5, 3.5), radius 0,
  // cap 10; a disc of radius 0 at (1.5, 3.5) moving (1, 0) m/s: at tau = 1 it is at (2.5, 3.5),
  // 1 away; at tau = 0 at (1.5, 3.5), 2 away; at tau = 2 on p itself, 0
  const grid::Grid g = grid::Grid::from_rows_top_first(
      {".......", ".......", ".......", ".......", ".......", ".......", "......."});
  const std::vector<Disc> d{Disc{Point{1.5, 3.5}, 0.0, Point{1.0, 0.0}}};
  const Obstacles obs{&g, {}, d};
  CHECK(point_clearance(Point{3.5, 3.5}, obs, 0.0, 10.0, 1.0) == 1.0);
  CHECK(point_clearance(Point{3.5, 3.5}, obs, 0.0, 10.0, 0.0) == 2.0);
  CHECK(point_clearance(Point{3.5, 3.5}, obs, 0.0, 10.0, 2.0) == 0.0);
  // the same with a vertical velocity (0, -1): at tau = 1.5 the disc is at (1.5, 2), |(2, 1.5)| = 2.5
  const std::vector<Disc> v{Disc{Point{1.5, 3.5}, 0.0, Point{0.0, -1.0}}};
  CHECK(point_clearance(Point{3.5, 3.5}, Obstacles{&g, {}, v}, 0.0, 10.0, 1.5) == 2.5);
}
