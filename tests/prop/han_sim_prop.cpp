// spec: han.sim.run, han.sim.step, han.sim.motion, han.collision.classify, han.maps.random, han.eq15
// Properties of Han's dynamic-obstacle simulation (spec/han-sim.md, "Properties").
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "pathref/equations/rls.hpp"
#include "pathref/planners/search.hpp"
#include "pathref/sim/encounter.hpp"
#include "pathref/sim/motion.hpp"
#include "pathref/sim/random_map.hpp"
#include "pathref/sim/simulate.hpp"
#include "pathref/vehicle/drive.hpp"

using namespace pathref;
using sim::Vec2;

namespace {

/// A uniform double in [lo, hi] on a grid of 1/1024 steps (no rejection).
rc::Gen<double> gen_real(double lo, double hi) {
  const int n = static_cast<int>((hi - lo) * 1024.0);
  return rc::gen::map(rc::gen::inRange(0, n + 1),
                      [lo](int k) { return lo + static_cast<double>(k) / 1024.0; });
}

/// The kinds of encounter of the guarantee's property (spec han.sim.run, "Properties").
enum class Kind { crossing, head_on, overtaking };

/// The corridor scenario where the rules apply (spec han.sim.run, "Properties"): an empty W x 9 map,
/// the straight global path along y = 4.5, one obstacle that either crosses the path (side: from
/// 3 to 6 m beside it, speed u in [0.25, 1] m/s, heading within +-0.5 u of perpendicular), comes
/// head-on (frontal: starting between 3u + 6 m and W - 3 m, lateral offset <= 0.4 m) or overtakes
/// from behind (1.25 to 2 m/s, starting 4 to 8 m behind the start, lateral offset <= 0.4 m).
/// a, b, h in [0, 1] are independent draws: a the position along the path, b the distance or the
/// offset, h the heading (crossing) or the speed (overtaking).
sim::Scenario corridor_scenario(int W, Kind kind, double u, double a, double b, double h, int sign, double noise) {
  sim::Scenario s;
  s.grid = grid::Grid(W, 9);
  s.start = {0, 4};
  s.goal = {W - 1, 4};
  for (int x = 0; x < W; ++x) s.path.push_back({x, 4});
  sim::MovingObstacle o;
  switch (kind) {
    case Kind::crossing: {
      const double xc = 5.5 + a * static_cast<double>(W - 9);
      const double d = 3.0 + 3.0 * b;
      o.position = {xc, 4.5 + static_cast<double>(sign) * d};
      o.velocity = {(h - 0.5) * u, -static_cast<double>(sign) * u};
      break;
    }
    case Kind::head_on: {
      const double lo = 3.0 * u + 6.0;
      const double x0 = lo + a * (static_cast<double>(W) - 3.0 - lo);
      o.position = {x0, 4.5 + 0.8 * (b - 0.5)};
      o.velocity = {-u, 0.0};
      break;
    }
    case Kind::overtaking: {
      const double behind = 4.0 + 4.0 * a;
      o.position = {0.5 - behind, 4.5 + 0.8 * (b - 0.5)};
      o.velocity = {1.25 + 0.75 * h, 0.0};
      break;
    }
  }
  s.obstacles.push_back(o);
  s.noise = noise;
  s.t_max = 200.0;
  return s;
}

/// A coordinate on the 1/8 lattice in [-8, 8].
rc::Gen<double> gen_coord() {
  return rc::gen::map(rc::gen::inRange(-64, 65), [](int k) { return static_cast<double>(k) / 8.0; });
}

/// Inside a property: a robot polyline of 2-4 vertices drawn from `coord`, no two consecutive
/// vertices equal.
std::vector<Vec2> draw_polyline(const rc::Gen<double>& coord) {
  const int n = *rc::gen::inRange(2, 5);
  std::vector<Vec2> robot;
  for (int i = 0; i < n; ++i) {
    Vec2 v{*coord, *coord};
    if (!robot.empty() && v == robot.back()) v.x += 0.125;
    robot.push_back(v);
  }
  return robot;
}

}  // namespace

TEST_CASE("prop_han_sim_no_collision_where_rules_apply", "[han-sim][prop]") {
  rc::prop("one crossing, head-on or overtaking obstacle on the corridor: goal reached, no collision, limits kept", [] {
    const int W = *rc::gen::inRange(14, 21);
    const Kind kind = *rc::gen::element(Kind::crossing, Kind::head_on, Kind::overtaking);
    const double u = *gen_real(0.25, 1.0);
    const double a = *gen_real(0.0, 1.0);
    const double b = *gen_real(0.0, 1.0);
    const double h = *gen_real(0.0, 1.0);
    const int sign = *rc::gen::element(-1, 1);
    const double noise = *rc::gen::element(0.0, 0.02);
    RC_TAG(kind == Kind::crossing ? "crossing" : kind == Kind::head_on ? "head-on" : "overtaking");
    sim::Scenario s = corridor_scenario(W, kind, u, a, b, h, sign, noise);
    s.seed = *rc::gen::inRange<std::uint32_t>(0, 1000);
    const auto r = sim::simulate(s);
    RC_ASSERT(r.reached_goal);
    RC_ASSERT(r.collisions.empty());
    // Speed <= v_max and speed increase <= a * dt per step (stops are immediate by spec).
    for (std::size_t k = 1; k < r.trajectory.size(); ++k) {
      const auto& p = r.trajectory[k - 1];
      const auto& q = r.trajectory[k];
      const double dt = q.t - p.t;
      RC_ASSERT(q.v <= s.speed);
      RC_ASSERT(q.v - p.v <= s.accel * dt * (1.0 + 1e-12));
      const double dx = q.p.x - p.p.x, dy = q.p.y - p.p.y;
      RC_ASSERT(std::sqrt(dx * dx + dy * dy) <= s.speed * dt * (1.0 + 1e-9));
    }
  });
}

TEST_CASE("prop_han_sim_without_obstacles_is_the_global_path", "[han-sim][prop]") {
  rc::prop("no moving obstacle: distance = global length, time = ramp-cruise time, no wait or replan", [] {
    const std::int64_t edge = *rc::gen::inRange<std::int64_t>(4, 21);
    const double ratio = *rc::gen::element(0.0, 0.2, 0.3, 0.4);
    const auto seed = *rc::gen::inRange<std::uint32_t>(0, 100000);
    const auto m = sim::random_map(seed, edge, ratio);
    sim::Scenario s;
    s.grid = m.grid;
    s.start = m.start;
    s.goal = m.goal;
    s.planner = "astar";
    s.planner_params = planners::Json{{"heuristic", "chebyshev"}};
    s.dt = *rc::gen::element(0.125, 0.1, 0.25, 0.5);
    const auto r = sim::simulate(s);
    RC_ASSERT(r.global_found);
    RC_ASSERT(r.reached_goal);
    RC_ASSERT(r.waits.empty());
    RC_ASSERT(r.replans.empty());
    const double L = r.global_length;
    // Tolerances: sums of at most ~300 steps of ds, each one rounding: 1e-12 relative is 10^3 ulps.
    RC_ASSERT(std::fabs(r.distance - L) <= 1e-12 * L);
    const double T = sim::ramp_cruise_time(L, 1.0, 1.0);
    RC_ASSERT(std::fabs(r.time - T) <= 1e-12 * T + 1e-12);
    // The closed form agrees with the foundation's trapezoid (drive.trapezoid) ending at full speed.
    const double v1 = std::min(1.0, std::sqrt(2.0 * L));
    RC_ASSERT(std::fabs(vehicle::trapezoid(L, 0.0, v1, 1.0, 1.0).time - T) <= 1e-12 * T + 1e-12);
    // Every sample lies on the global path polyline.
    for (const auto& q : r.trajectory) {
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i + 1 < r.global_path.size(); ++i)
        best = std::min(best, sim::point_segment_distance(q.p, sim::centre(r.global_path[i]),
                                                          sim::centre(r.global_path[i + 1])));
      RC_ASSERT(best <= 1e-12);
    }
  });
}

TEST_CASE("prop_han_maps_random_connected_with_ratio", "[han-sim][prop]") {
  rc::prop("protocol edges and ratios: floor(ratio E^2) obstacles, start and goal 4-connected", [] {
    const std::int64_t edge = 5 * *rc::gen::inRange<std::int64_t>(2, 21);
    const double ratio = *gen_real(0.2, 0.7);
    const auto seed = *rc::gen::arbitrary<std::uint32_t>();
    const auto m = sim::random_map(seed, edge, ratio);
    RC_ASSERT(sim::is_protocol_edge(edge));
    RC_ASSERT(m.grid.blocked_count() == static_cast<std::int64_t>(std::floor(ratio * static_cast<double>(edge * edge))));
    // The realised ratio lies in (ratio - 1/E^2, ratio]: count <= ratio E^2 < count + 1.
    const double want = ratio * static_cast<double>(edge * edge);
    const auto count = static_cast<double>(m.grid.blocked_count());
    RC_ASSERT(count <= want);
    RC_ASSERT(want < count + 1.0);
    RC_ASSERT(m.grid.free(m.start));
    RC_ASSERT(m.grid.free(m.goal));
    const auto o = search::dijkstra(m.grid, m.start, m.goal, grid::CornerPolicy::never);
    RC_ASSERT(o.found);
  });
}

TEST_CASE("prop_han_classify_mirror_symmetric", "[han-sim][prop]") {
  rc::prop("mirroring robot and obstacle about x = 0, y = 0 or y = x keeps kind, distance and piece", [] {
    const auto coord = gen_coord();
    const std::vector<Vec2> robot = draw_polyline(coord);
    const Vec2 p{*coord, *coord}, q{*coord, *coord};
    const double c = *rc::gen::element(0.5, 0.85, 2.0);
    const auto base = sim::classify(robot, p, q, c);
    for (int m = 0; m < 3; ++m) {
      auto f = [m](Vec2 v) { return m == 0 ? Vec2{-v.x, v.y} : m == 1 ? Vec2{v.x, -v.y} : Vec2{v.y, v.x}; };
      std::vector<Vec2> rr;
      for (const Vec2 v : robot) rr.push_back(f(v));
      const auto k = sim::classify(rr, f(p), f(q), c);
      RC_ASSERT(k.kind == base.kind);
      RC_ASSERT(k.distance == base.distance);
      RC_ASSERT(k.piece == base.piece);
      RC_ASSERT(k.robot_inside == base.robot_inside);
    }
  });
}

TEST_CASE("prop_han_rls_prediction_exact_on_linear_obstacles", "[han-sim][prop]") {
  rc::prop("noise-free linear motion sampled every dt: the prediction at t + 3 is within the bound of spec han.sim.run", [] {
    const double x0 = *gen_real(-20.0, 20.0), y0 = *gen_real(-20.0, 20.0);
    const double vx = *gen_real(-2.0, 2.0), vy = *gen_real(-2.0, 2.0);
    const double dt = *rc::gen::element(0.125, 0.1, 0.25);
    const int n = *rc::gen::inRange(2, 400);
    const double lambda = 0.95;
    std::vector<double> t, x, y;
    for (int k = 0; k < n; ++k) {
      const double tk = static_cast<double>(k) * dt;
      t.push_back(tk);
      x.push_back(x0 + vx * tk);
      y.push_back(y0 + vy * tk);
    }
    const auto e = rls::rls_estimate(t, x, y, lambda);
    const double tp = t.back() + 3.0;
    const auto p = rls::position(rls::LinearMotion{e.A(0), e.A(1), e.B(0), e.B(1)}, tp);
    // spec han.sim.run, "RLS prediction on noise-free linear motion": 16 eps max(S, 1) A with
    // A = 1 + |tp - tbar| / sigma over the weights lambda^(n-1-l) (the extrapolation's gain).
    double sw = 0.0, swt = 0.0;
    for (int k = 0; k < n; ++k) {
      const double w = std::pow(lambda, n - 1 - k);
      sw += w;
      swt += w * t[static_cast<std::size_t>(k)];
    }
    const double tbar = swt / sw;
    double var = 0.0;
    for (int k = 0; k < n; ++k) {
      const double d = t[static_cast<std::size_t>(k)] - tbar;
      var += std::pow(lambda, n - 1 - k) * d * d;
    }
    const double amplification = 1.0 + std::fabs(tp - tbar) / std::sqrt(var / sw);
    const double scale = std::max(std::fabs(x0), std::fabs(y0)) + std::max(std::fabs(vx), std::fabs(vy)) * tp;
    const double tol = 16.0 * 0x1p-52 * std::max(scale, 1.0) * amplification;
    RC_ASSERT(std::fabs(p.x - (x0 + vx * tp)) <= tol);
    RC_ASSERT(std::fabs(p.y - (y0 + vy * tp)) <= tol);
  });
}

TEST_CASE("prop_han_safety_margins_not_below_spatial_distance", "[han-sim][prop]") {
  rc::prop("timed margins >= spatial distances: wait >= dist(R0, [o_0, o_J]), go >= classify's D", [] {
    const auto coord = gen_coord();
    const std::vector<Vec2> robot = draw_polyline(coord);
    const rls::LinearMotion m{*coord / 4.0, *coord, *coord / 4.0, *coord};
    const double tau = *rc::gen::element(0.0, 1.5, 10.0);
    const double dt = *rc::gen::element(0.125, 0.25, 0.5);
    const double H = *rc::gen::element(1.0, 3.0);
    const double v0 = *rc::gen::element(0.0, 0.5, 1.0);
    const auto mg = sim::safety_margins(robot, v0, 1.0, 1.0, dt, H, m, tau);
    // the last sample time s_J = J dt <= H
    const double sJ = static_cast<double>(mg.samples - 1) * dt;
    const auto o0 = rls::position(m, tau);
    const auto oJ = rls::position(m, tau + sJ);
    const Vec2 p{o0.x, o0.y}, q{oJ.x, oJ.y};
    const double tol = 1e-9;  // rounding of the sampled points against the exact segment
    RC_ASSERT(mg.wait >= sim::point_segment_distance(robot.front(), p, q) - tol);
    const auto c = sim::classify(robot, p, q, 1.0);
    RC_ASSERT(mg.go >= c.distance - tol);
    const double dx = robot.front().x - p.x, dy = robot.front().y - p.y;
    RC_ASSERT(mg.wait <= std::sqrt(dx * dx + dy * dy));
    RC_ASSERT(mg.go <= std::sqrt(dx * dx + dy * dy));
  });
}
