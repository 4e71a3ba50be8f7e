// spec: sensors2023.eq9 ... eq14, sensors2023.dwa.*, sensors2023.sim.* (spec/sensors2023-dwa.md)
// Properties of the DWA rules and the fused run.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pathref/equations/dwa.hpp"
#include "pathref/geometry/clearance.hpp"
#include "pathref/sim/fused.hpp"

using namespace pathref;
using namespace pathref::dwa;

namespace {

/// A double in [lo, hi] on a 1/1024 lattice.
rc::Gen<double> gen_real(double lo, double hi) {
  const int n = static_cast<int>((hi - lo) * 1024.0);
  return rc::gen::map(rc::gen::inRange(0, n + 1), [lo](int k) { return lo + static_cast<double>(k) / 1024.0; });
}

/// A W x H map (W, H in [3, 10]) with each cell blocked with probability ~ 1/5.
rc::Gen<grid::Grid> gen_map() {
  return rc::gen::mapcat(rc::gen::pair(rc::gen::inRange(3, 11), rc::gen::inRange(3, 11)), [](std::pair<int, int> wh) {
    return rc::gen::map(rc::gen::container<std::vector<int>>(static_cast<std::size_t>(wh.first * wh.second),
                                                             rc::gen::inRange(0, 5)),
                        [wh](const std::vector<int>& bits) {
                          grid::Grid g(wh.first, wh.second);
                          for (int i = 0; i < wh.first * wh.second; ++i)
                            if (bits[static_cast<std::size_t>(i)] == 0) g.set_blocked(g.cell(i), true);
                          return g;
                        });
  });
}

}  // namespace

TEST_CASE("prop_dwa_window_within_limits") {
  rc::prop("the dynamic window lies inside V_s and contains the current velocity's reachable pairs", [] {
    Limits l;
    l.v_max = *gen_real(0.1, 3.0);
    l.w_max = *gen_real(0.1, 3.0);
    l.acc_v = *gen_real(0.0, 2.0);
    l.dec_v = *gen_real(0.0, 2.0);
    l.acc_w = *gen_real(0.0, 4.0);
    l.dec_w = *gen_real(0.0, 4.0);
    const double v_c = *gen_real(0.0, l.v_max);
    const double w_c = *gen_real(-l.w_max, l.w_max);
    const double dt = *gen_real(0.01, 0.5);
    const Window w = dynamic_window(v_c, w_c, l, dt);
    RC_ASSERT(w.v_lo <= v_c);
    RC_ASSERT(v_c <= w.v_hi);
    RC_ASSERT(w.w_lo <= w_c);
    RC_ASSERT(w_c <= w.w_hi);
    RC_ASSERT(w.v_lo >= l.v_min);
    RC_ASSERT(w.v_hi <= l.v_max);
    RC_ASSERT(w.w_lo >= -l.w_max);
    RC_ASSERT(w.w_hi <= l.w_max);
    for (const auto up : {WindowUpper::include, WindowUpper::exclude}) {
      const auto s = axis_samples(w.v_lo, w.v_hi, 0.01, up);
      RC_ASSERT(!s.empty());
      RC_ASSERT(s.front() == w.v_lo);
      RC_ASSERT(s.back() <= w.v_hi + 1e-9);
      if (up == WindowUpper::exclude && s.size() > 1) RC_ASSERT(s.back() < w.v_hi);
    }
  });
}

TEST_CASE("prop_dwa_motion_step_length") {
  rc::prop("one step moves |v| dt, turns w dt, and v = 0 stays in place", [] {
    const Pose p{*gen_real(-50, 50), *gen_real(-50, 50), *gen_real(-7, 7)};
    const double v = *gen_real(-2, 2), w = *gen_real(-3, 3), dt = *gen_real(0.01, 1.0);
    for (const auto o : {MotionOrder::heading_last, MotionOrder::heading_first}) {
      const Pose q = motion_step(p, v, w, dt, o);
      const double d = std::sqrt(((q.x - p.x) * (q.x - p.x)) + ((q.y - p.y) * (q.y - p.y)));
      RC_ASSERT(std::fabs(d - std::fabs(v * dt)) <= 1e-12 * (1.0 + std::fabs(p.x) + std::fabs(p.y)));
      RC_ASSERT(q.theta == p.theta + (w * dt));
      const Pose z = motion_step(p, 0.0, w, dt, o);
      RC_ASSERT(z.x == p.x);
      RC_ASSERT(z.y == p.y);
    }
  });
}

TEST_CASE("prop_dwa_heading_in_range") {
  rc::prop("wrap lands in (-pi, pi] and differs by a multiple of 2 pi; the wrapped heading is in [0, 180]", [] {
    const double a = *gen_real(-40, 40);
    const double r = wrap_angle(a);
    RC_ASSERT(r > -pi);
    RC_ASSERT(r <= pi);
    const double k = (a - r) / (2.0 * pi);
    RC_ASSERT(std::fabs(k - std::round(k)) < 1e-9);
    const Pose e{*gen_real(-10, 10), *gen_real(-10, 10), a};
    const Point t{*gen_real(-10, 10), *gen_real(-10, 10)};
    const Heading h = heading_term(e, t);
    RC_ASSERT(h.heading_deg >= 0.0);
    RC_ASSERT(h.heading_deg <= 180.0);
    // unwrapped is never above wrapped
    RC_ASSERT(heading_term(e, t, HeadingWrap::off).heading_deg <= h.heading_deg + 1e-9);
  });
}

TEST_CASE("prop_dwa_evaluate_picks_extreme") {
  rc::prop("the choice has the extreme score of the valid candidates; scaling the weights keeps it", [] {
    const int n = *rc::gen::inRange(1, 30);
    std::vector<Terms> ts;
    for (int i = 0; i < n; ++i)
      ts.push_back(Terms{*gen_real(0, 180), *gen_real(0, 3), *gen_real(0, 2), *gen_real(0, 1), *rc::gen::arbitrary<bool>()});
    for (const auto mode : {Evaluation::normalised, Evaluation::cost}) {
      const Choice c = evaluate(ts, Weights{}, mode, 1.0);
      const bool any = std::any_of(ts.begin(), ts.end(), [](const Terms& t) { return t.valid; });
      RC_ASSERT((c.best >= 0) == any);
      if (c.best < 0) continue;
      RC_ASSERT(ts[static_cast<std::size_t>(c.best)].valid);
      for (std::size_t i = 0; i < ts.size(); ++i) {
        if (!ts[i].valid) {
          RC_ASSERT(std::isnan(c.scores[i]));
          continue;
        }
        if (mode == Evaluation::normalised) RC_ASSERT(c.scores[i] <= c.scores[static_cast<std::size_t>(c.best)]);
        else RC_ASSERT(c.scores[i] >= c.scores[static_cast<std::size_t>(c.best)]);
      }
      Weights w2;
      w2.alpha *= 4.0;
      w2.beta *= 4.0;
      w2.gamma *= 4.0;
      w2.k_heading *= 4.0;
      w2.k_clearance *= 4.0;
      w2.k_velocity *= 4.0;
      RC_ASSERT(evaluate(ts, w2, mode, 1.0).best == c.best);  // exact: scaling by 4 is exact
    }
  });
}

TEST_CASE("prop_dwa_clearance_is_brute_force") {
  rc::prop("point clearance = min(cap, min over every blocked cell (and the outside) - radius)", [] {
    const grid::Grid g = *gen_map();
    const Point p{*gen_real(-1.0, static_cast<double>(g.width()) + 1.0), *gen_real(-1.0, static_cast<double>(g.height()) + 1.0)};
    const double radius = *gen_real(0.0, 0.5), cap = *gen_real(0.1, 3.0);
    double m = 1e300;
    for (std::int64_t y = -6; y < g.height() + 6; ++y)
      for (std::int64_t x = -6; x < g.width() + 6; ++x)
        if (!g.free(grid::Cell{x, y})) m = std::min(m, geometry::point_box_distance(geometry::Vec2{p.x, p.y}, static_cast<double>(x), static_cast<double>(y),
                                                                   static_cast<double>(x) + 1.0, static_cast<double>(y) + 1.0));
    const double c = point_clearance(p, Obstacles{&g, {}, {}}, radius, cap);
    RC_ASSERT(c == std::min(cap, m - radius));
  });
}

TEST_CASE("prop_dwa_step_clearance_below_endpoints") {
  rc::prop("the continuous step clearance is <= the point clearance at both ends (cells and movers)", [] {
    const grid::Grid g = *gen_map();
    const double W = static_cast<double>(g.width()), H = static_cast<double>(g.height());
    const Point a{*gen_real(0, W), *gen_real(0, H)};
    const Point b{a.x + *gen_real(-1, 1), a.y + *gen_real(-1, 1)};
    const Mover m{*gen_real(0.1, 0.5), {{0.0, {*gen_real(0, W), *gen_real(0, H)}}, {1.0, {*gen_real(0, W), *gen_real(0, H)}}}};
    const std::vector<Mover> ms{m};
    const double radius = 0.3;
    const double s = step_clearance(a, b, 0.0, 1.0, radius, g, {}, ms);
    for (const auto& [pt, t] : {std::pair{a, 0.0}, std::pair{b, 1.0}}) {
      const std::vector<Disc> d{Disc{obstacle_position(m.waypoints, t), m.r, {}}};
      RC_ASSERT(s <= point_clearance(pt, Obstacles{&g, {}, d}, radius, 10.0) + 1e-12);
    }
  });
}

TEST_CASE("prop_dwa_turns_of_polyline") {
  rc::prop("a straight track has no turn; a track made of k long legs at >= 45 deg has k - 1 turns", [] {
    const double dir = *gen_real(-3.1, 3.1);
    const int legs = *rc::gen::inRange(1, 6);
    std::vector<Point> tr{{0.0, 0.0}};
    double h = dir;
    int sign = 1;
    for (int i = 0; i < legs; ++i) {
      const double len = *gen_real(3.0, 6.0);
      tr.push_back(Point{tr.back().x + (len * std::cos(h)), tr.back().y + (len * std::sin(h))});
      h += sign * *gen_real(0.8, 2.0);  // 46..115 degrees, alternating sides
      sign = -sign;
    }
    RC_ASSERT(count_turns(tr, TurnParams{}) == legs - 1);
  });
}

TEST_CASE("prop_fused_run_ends_with_one_outcome") {
  rc::prop("every fused run ends within t_max / dt + 1 steps, and never inside an obstacle unless collided", [] {
    const int W = *rc::gen::inRange(4, 9);
    std::string row(static_cast<std::size_t>(W), '.');
    std::vector<std::string> rows(4, row);
    const int bx = *rc::gen::inRange(1, W - 1);
    const int by = *rc::gen::inRange(0, 4);
    rows[static_cast<std::size_t>(3 - by)][static_cast<std::size_t>(bx)] = '#';
    nlohmann::json sc{{"format", "pathref-sim 2"}, {"map", rows}, {"start", {0, 0}}, {"goal", {W - 1, 3}},
                      {"t_max", 8.0}, {"dwa", {{"dt", 0.2}, {"horizon", 1.0}, {"v_res", 0.05}, {"w_res", 0.1},
                                               {"heading_target", *rc::gen::element<std::string>("key-node", "waypoint", "goal")}}},
                      {"moving", nlohmann::json::array({nlohmann::json{{"radius", 0.3},
                                                                       {"waypoints", {{0.0, *gen_real(0, W), *gen_real(0, 4)},
                                                                                      {4.0, *gen_real(0, W), *gen_real(0, 4)}}}}})}};
    const FusedScenario s = fused_scenario_from_json(sc, "prop");
    const FusedResult r = simulate_fused(s);
    RC_ASSERT(r.global_found);
    RC_ASSERT(r.steps <= static_cast<std::int64_t>(std::ceil(8.0 / 0.2)) + 1);
    RC_ASSERT(r.samples.size() == r.tracks.size());
    if (r.outcome != Outcome::collided) RC_ASSERT(r.min_clearance >= 0.0);
    else RC_ASSERT(r.min_clearance < 0.0);
    if (r.outcome == Outcome::reached) {
      const double dx = r.samples.back().pose.x - (static_cast<double>(W - 1) + 0.5);
      const double dy = r.samples.back().pose.y - 3.5;
      RC_ASSERT(std::sqrt((dx * dx) + (dy * dy)) <= s.goal_reach);
    }
  });
}

TEST_CASE("prop_dwa_waypoints_cover_the_path") {
  rc::prop("waypoints: start with N_0, end with N_m, contain every node, consecutive ones at most the spacing apart", [] {
    const int m = *rc::gen::inRange(1, 6);
    std::vector<Point> nodes;
    for (int i = 0; i < m; ++i) nodes.push_back(Point{*gen_real(-10, 10), *gen_real(-10, 10)});
    const double s = *gen_real(0.1, 3.0);
    const std::vector<Point> w = path_waypoints(nodes, s);
    RC_ASSERT(w.front().x == nodes.front().x);
    RC_ASSERT(w.front().y == nodes.front().y);
    RC_ASSERT(w.back().x == nodes.back().x);
    RC_ASSERT(w.back().y == nodes.back().y);
    std::size_t j = 0;  // every node appears, in order
    for (const Point& q : nodes) {
      while (j < w.size() && !(w[j].x == q.x && w[j].y == q.y)) ++j;
      RC_ASSERT(j < w.size());
    }
    for (std::size_t i = 1; i < w.size(); ++i) {
      const double dx = w[i].x - w[i - 1].x, dy = w[i].y - w[i - 1].y;
      RC_ASSERT(std::sqrt((dx * dx) + (dy * dy)) <= s * (1.0 + 1e-9));
    }
  });
}

TEST_CASE("prop_dwa_step_is_composition") {
  rc::prop("control_step equals Eq. 9-14 composed literally (predict, clearance, heading, Eq. 12, Eq. 13)", [] {
    const grid::Grid g = *gen_map();
    const double W = static_cast<double>(g.width()), H = static_cast<double>(g.height());
    const Pose p{*gen_real(0, W), *gen_real(0, H), *gen_real(-4, 4)};
    DwaParams prm;
    prm.horizon = 1.0;
    prm.v_res = 0.02;
    prm.w_res = 0.05;
    prm.motion_order = *rc::gen::element(MotionOrder::heading_last, MotionOrder::heading_first);
    prm.evaluation = *rc::gen::element(Evaluation::normalised, Evaluation::cost);
    prm.clearance_at = *rc::gen::element(ClearanceAt::trajectory, ClearanceAt::end);
    const double v_c = *gen_real(0.0, 1.0);
    const double w_c = *gen_real(-0.6, 0.6);
    const Point target{*gen_real(0, W), *gen_real(0, H)};
    const std::vector<Disc> discs{Disc{Point{*gen_real(0, W), *gen_real(0, H)}, 0.3, Point{*gen_real(-1, 1), *gen_real(-1, 1)}}};
    const Obstacles obs{&g, {}, discs};
    const StepResult r = control_step(p, v_c, w_c, target, obs, prm);
    const Window win = dynamic_window(v_c, w_c, prm.limits, prm.dt);
    const auto vs = axis_samples(win.v_lo, win.v_hi, prm.v_res, prm.window_upper);
    const auto ws = axis_samples(win.w_lo, win.w_hi, prm.w_res, prm.window_upper);
    std::vector<Terms> ts;
    for (const double v : vs)
      for (const double w : ws) {
        const auto traj = predict(p, v, w, prm.dt, prm.horizon, prm.motion_order);
        const double c = trajectory_clearance(traj, obs, prm.radius, prm.clearance_cap, prm.clearance_at, prm.dt);
        const Heading h = heading_term(traj.back(), target, prm.heading_wrap);
        Terms t{h.heading_deg, h.abs_dtheta, c, v, false};
        t.valid = c >= 0.0 && admissible(v, w, c, prm.limits.dec_v, prm.limits.dec_w, prm.admissible);
        if (!t.valid) t.clearance = std::max(0.0, c);
        ts.push_back(t);
      }
    const Choice ch = evaluate(ts, prm.weights, prm.evaluation, prm.limits.v_max);
    RC_ASSERT(r.best == ch.best);
    RC_ASSERT(r.candidates == static_cast<std::int64_t>(ts.size()));
    if (ch.best >= 0) {
      RC_ASSERT(r.v == vs[static_cast<std::size_t>(ch.best) / ws.size()]);
      RC_ASSERT(r.w == ws[static_cast<std::size_t>(ch.best) % ws.size()]);
      RC_ASSERT(r.score == ch.scores[static_cast<std::size_t>(ch.best)]);
    } else {
      RC_ASSERT(r.braked);
    }
  });
}
