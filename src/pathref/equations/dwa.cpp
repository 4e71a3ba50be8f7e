// sensors2023 Eq. 9-14 and the pieces of the fused simulation. Spec: spec/sensors2023-dwa.md.
#include "pathref/equations/dwa.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "pathref/core/error.hpp"
#include "pathref/geometry/clearance.hpp"
#include "pathref/geometry/segment_distance.hpp"

namespace pathref::dwa {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double coord_limit = 1e9;
constexpr double collision_scan = 10.0;

bool finite(double v) noexcept { return std::isfinite(v); }

void require_point(Point p, const char* what) {
  require(finite(p.x) && finite(p.y) && std::fabs(p.x) <= coord_limit && std::fabs(p.y) <= coord_limit,
          std::string(what) + ": coordinates must be finite with |value| <= 1e9");
}

template <class E>
E parse_option(std::string_view s, std::initializer_list<std::pair<std::string_view, E>> table,
               const char* name) {
  std::string names;
  for (const auto& [k, v] : table) {
    if (k == s) return v;
    names += names.empty() ? std::string(k) : ", " + std::string(k);
  }
  throw UsageError(std::string(name) + " must be one of " + names + ", got '" + std::string(s) + "'");
}

geometry::Vec2 vec(Point p) noexcept { return geometry::Vec2{p.x, p.y}; }

}  // namespace

MotionOrder parse_motion_order(std::string_view s) {
  return parse_option<MotionOrder>(s, {{"heading-last", MotionOrder::heading_last},
                                       {"heading-first", MotionOrder::heading_first}}, "motion_order");
}
WindowUpper parse_window_upper(std::string_view s) {
  return parse_option<WindowUpper>(s, {{"include", WindowUpper::include}, {"exclude", WindowUpper::exclude}},
                                   "window_upper");
}
Admissible parse_admissible(std::string_view s) {
  return parse_option<Admissible>(
      s, {{"both", Admissible::both}, {"linear", Admissible::linear}, {"off", Admissible::off}}, "admissible");
}
HeadingWrap parse_heading_wrap(std::string_view s) {
  return parse_option<HeadingWrap>(s, {{"on", HeadingWrap::on}, {"off", HeadingWrap::off}}, "heading_wrap");
}
Evaluation parse_evaluation(std::string_view s) {
  return parse_option<Evaluation>(s, {{"normalised", Evaluation::normalised}, {"cost", Evaluation::cost}},
                                  "evaluation");
}
ClearanceAt parse_clearance_at(std::string_view s) {
  return parse_option<ClearanceAt>(s, {{"trajectory", ClearanceAt::trajectory}, {"end", ClearanceAt::end}},
                                   "clearance_at");
}
std::string_view to_string(MotionOrder v) noexcept {
  return v == MotionOrder::heading_last ? "heading-last" : "heading-first";
}
std::string_view to_string(WindowUpper v) noexcept { return v == WindowUpper::include ? "include" : "exclude"; }
std::string_view to_string(Admissible v) noexcept {
  return v == Admissible::both ? "both" : v == Admissible::linear ? "linear" : "off";
}
std::string_view to_string(HeadingWrap v) noexcept { return v == HeadingWrap::on ? "on" : "off"; }
std::string_view to_string(Evaluation v) noexcept { return v == Evaluation::normalised ? "normalised" : "cost"; }
std::string_view to_string(ClearanceAt v) noexcept { return v == ClearanceAt::trajectory ? "trajectory" : "end"; }
std::string_view to_string(SkipReason r) noexcept {
  return r == SkipReason::none ? "none" : r == SkipReason::blocked ? "blocked" : "timeout";
}

// ---------------------------------------------------------------- Eq. 9

Pose motion_step(Pose p, double v, double w, double dt, MotionOrder order) {
  require(finite(p.x) && finite(p.y) && finite(p.theta) && finite(v) && finite(w),
          "sensors2023.eq9: pose and velocities must be finite");
  require(finite(dt) && dt > 0.0, "sensors2023.eq9: dt must be finite and > 0");
  const double ds = v * dt;
  Pose q;
  if (order == MotionOrder::heading_last) {
    q.x = p.x + (ds * std::cos(p.theta));
    q.y = p.y + (ds * std::sin(p.theta));
    q.theta = p.theta + (w * dt);
  } else {
    q.theta = p.theta + (w * dt);
    q.x = p.x + (ds * std::cos(q.theta));
    q.y = p.y + (ds * std::sin(q.theta));
  }
  return q;
}

std::int64_t predicted_steps(double horizon, double dt) {
  require(finite(dt) && dt > 0.0 && finite(horizon) && horizon > 0.0,
          "sensors2023.eq9: horizon and dt must be finite and > 0");
  const double n = std::round(horizon / dt);
  require(n >= 1.0 && n <= 10000.0, "sensors2023.eq9: round(horizon / dt) must be in [1, 10000]");
  return static_cast<std::int64_t>(n);
}

std::vector<Pose> predict(Pose p, double v, double w, double dt, double horizon, MotionOrder order) {
  const std::int64_t n = predicted_steps(horizon, dt);
  std::vector<Pose> out;
  out.reserve(static_cast<std::size_t>(n));
  for (std::int64_t j = 0; j < n; ++j) {
    p = motion_step(p, v, w, dt, order);
    out.push_back(p);
  }
  return out;
}

// ---------------------------------------------------------------- Eq. 10, 11

Window velocity_space(const Limits& lim) {
  require(finite(lim.v_min) && finite(lim.v_max) && finite(lim.w_max),
          "sensors2023.eq10: limits must be finite");
  require(lim.v_min <= lim.v_max, "sensors2023.eq10: v_min must be <= v_max");
  require(lim.w_max >= 0.0, "sensors2023.eq10: w_max must be >= 0");
  return Window{lim.v_min, lim.v_max, -lim.w_max, lim.w_max};
}

Window dynamic_window(double v_c, double w_c, const Limits& lim, double dt) {
  const Window s = velocity_space(lim);
  require(finite(lim.acc_v) && finite(lim.dec_v) && finite(lim.acc_w) && finite(lim.dec_w) && lim.acc_v >= 0.0 &&
              lim.dec_v >= 0.0 && lim.acc_w >= 0.0 && lim.dec_w >= 0.0,
          "sensors2023.eq11: accelerations must be finite and >= 0");
  require(finite(dt) && dt > 0.0, "sensors2023.eq11: dt must be finite and > 0");
  require(finite(v_c) && v_c >= lim.v_min && v_c <= lim.v_max, "sensors2023.eq11: v_c must lie in [v_min, v_max]");
  require(finite(w_c) && std::fabs(w_c) <= lim.w_max, "sensors2023.eq11: |w_c| must be <= w_max");
  Window d;
  d.v_lo = std::max(s.v_lo, v_c - (lim.dec_v * dt));
  d.v_hi = std::min(s.v_hi, v_c + (lim.acc_v * dt));
  d.w_lo = std::max(s.w_lo, w_c - (lim.dec_w * dt));
  d.w_hi = std::min(s.w_hi, w_c + (lim.acc_w * dt));
  return d;
}

std::vector<double> axis_samples(double lo, double hi, double r, WindowUpper upper) {
  require(finite(lo) && finite(hi) && lo <= hi, "sensors2023.eq11: window edges must be finite with lo <= hi");
  require(finite(r) && r > 0.0, "sensors2023.eq11: resolution must be finite and > 0");
  const double s = (hi - lo) / r;
  require(s <= 1e6, "sensors2023.eq11: at most 10^6 samples per axis");
  double k_max = 0.0;
  if (upper == WindowUpper::include) {
    k_max = std::floor(s + 1e-9);
  } else {
    k_max = std::max(0.0, std::ceil(s - 1e-9) - 1.0);
  }
  const auto k_count = static_cast<std::int64_t>(k_max) + 1;
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(k_count));
  for (std::int64_t k = 0; k < k_count; ++k) out.push_back(lo + (static_cast<double>(k) * r));
  return out;
}

// ---------------------------------------------------------------- Eq. 12

bool admissible(double v, double w, double dist, double dec_v, double dec_w, Admissible mode) {
  require(finite(v) && finite(w) && finite(dist) && finite(dec_v) && finite(dec_w),
          "sensors2023.eq12: inputs must be finite");
  require(dist >= 0.0, "sensors2023.eq12: dist must be >= 0 (a negative clearance is a collision)");
  require(dec_v >= 0.0 && dec_w >= 0.0, "sensors2023.eq12: decelerations must be >= 0");
  if (mode == Admissible::off) return true;
  const bool lin = v <= std::sqrt((2.0 * dist) * dec_v);
  if (mode == Admissible::linear) return lin;
  return lin && std::fabs(w) <= std::sqrt((2.0 * dist) * dec_w);
}

// ---------------------------------------------------------------- Eq. 14

double wrap_angle(double a) {
  require(finite(a), "sensors2023.eq14: angle must be finite");
  double r = std::fmod(a + pi, 2.0 * pi);
  if (r <= 0.0) r = r + (2.0 * pi);
  return r - pi;
}

Heading heading_term(Pose end, Point target, HeadingWrap wrap) {
  require(finite(end.x) && finite(end.y) && finite(end.theta) && finite(target.x) && finite(target.y),
          "sensors2023.eq14: inputs must be finite");
  const double bearing = std::atan2(target.y - end.y, target.x - end.x);
  const double d = end.theta - bearing;
  const double a = std::fabs(wrap == HeadingWrap::on ? wrap_angle(d) : d);
  return Heading{180.0 - (a * deg_per_rad), a};
}

// ---------------------------------------------------------------- Eq. 13

Choice evaluate(std::span<const Terms> terms, const Weights& w, Evaluation mode, double v_max) {
  require(terms.size() <= 1000000, "sensors2023.eq13: at most 10^6 candidates");
  const double ws[6] = {w.alpha, w.beta, w.gamma, w.k_heading, w.k_clearance, w.k_velocity};
  for (const double x : ws) require(finite(x) && x >= 0.0, "sensors2023.eq13: weights must be finite and >= 0");
  require(finite(v_max), "sensors2023.eq13: v_max must be finite");
  for (const Terms& t : terms) {
    if (!t.valid) continue;
    require(finite(t.heading_deg) && finite(t.abs_dtheta) && finite(t.clearance) && finite(t.velocity),
            "sensors2023.eq13: terms of valid candidates must be finite");
    require(t.clearance >= 0.0, "sensors2023.eq13: clearance of a valid candidate must be >= 0");
    if (mode == Evaluation::normalised)
      require(t.velocity >= 0.0, "sensors2023.eq13: normalised velocity terms must be >= 0");
  }
  Choice c;
  c.scores.assign(terms.size(), std::numeric_limits<double>::quiet_NaN());
  if (mode == Evaluation::normalised) {
    double hs = 0.0, ds = 0.0, vs = 0.0;
    for (const Terms& t : terms) {
      if (!t.valid) continue;
      hs = hs + t.heading_deg;
      ds = ds + t.clearance;
      vs = vs + t.velocity;
    }
    for (std::size_t i = 0; i < terms.size(); ++i) {
      const Terms& t = terms[i];
      if (!t.valid) continue;
      const double hb = hs == 0.0 ? 0.0 : t.heading_deg / hs;
      const double db = ds == 0.0 ? 0.0 : t.clearance / ds;
      const double vb = vs == 0.0 ? 0.0 : t.velocity / vs;
      const double g = ((w.alpha * hb) + (w.beta * db)) + (w.gamma * vb);
      c.scores[i] = g;
      if (c.best < 0 || g > c.scores[static_cast<std::size_t>(c.best)]) c.best = static_cast<std::int64_t>(i);
    }
  } else {
    for (std::size_t i = 0; i < terms.size(); ++i) {
      const Terms& t = terms[i];
      if (!t.valid) continue;
      const double inv = t.clearance == 0.0 ? inf : 1.0 / t.clearance;
      const double cost = ((w.k_heading * t.abs_dtheta) + (w.k_velocity * (v_max - t.velocity))) + (w.k_clearance * inv);
      c.scores[i] = cost;
      if (c.best < 0 || cost < c.scores[static_cast<std::size_t>(c.best)]) c.best = static_cast<std::int64_t>(i);
    }
  }
  return c;
}

// ---------------------------------------------------------------- clearance

namespace {

void require_obstacles(const Obstacles& obs, double radius, double cap) {
  require(obs.grid != nullptr, "sensors2023.dwa.clearance: no map");
  require(finite(cap) && cap > 0.0, "sensors2023.dwa.clearance: cap must be finite and > 0");
  require(finite(radius) && radius >= 0.0, "sensors2023.dwa.clearance: radius must be finite and >= 0");
  for (const Disc& d : obs.discs)
    require(finite(d.c.x) && finite(d.c.y) && finite(d.r) && d.r >= 0.0 && finite(d.vel.x) && finite(d.vel.y),
            "sensors2023.dwa.clearance: discs must be finite with radius >= 0");
}

// Surface distance of p to the closed cell square [c.x, c.x + 1] x [c.y, c.y + 1]: the shared
// point-to-box distance of curves.clearance (geometry/clearance.hpp), one function for both.
double cell_surface(Point p, grid::Cell c) noexcept {
  const auto x0 = static_cast<double>(c.x);
  const auto y0 = static_cast<double>(c.y);
  return geometry::point_box_distance(geometry::Vec2{p.x, p.y}, x0, y0, x0 + 1.0, y0 + 1.0);
}

// point_clearance without the checks (the caller checked the obstacles once).
double clearance_unchecked(Point p, const Obstacles& obs, double radius, double cap, double tau) {
  const double reach = cap + radius;
  const auto x0 = static_cast<std::int64_t>(std::floor(p.x - reach));
  const auto x1 = static_cast<std::int64_t>(std::floor(p.x + reach));
  const auto y0 = static_cast<std::int64_t>(std::floor(p.y - reach));
  const auto y1 = static_cast<std::int64_t>(std::floor(p.y + reach));
  double m = inf;
  const grid::Grid& g = *obs.grid;
  for (std::int64_t y = y0; y <= y1; ++y)
    for (std::int64_t x = x0; x <= x1; ++x) {
      const grid::Cell c{x, y};
      if (g.free(c)) continue;
      m = std::min(m, cell_surface(p, c));
    }
  for (const grid::Cell& c : obs.temporary) m = std::min(m, cell_surface(p, c));
  for (const Disc& d : obs.discs) {
    const double dx = p.x - (d.c.x + (tau * d.vel.x));
    const double dy = p.y - (d.c.y + (tau * d.vel.y));
    m = std::min(m, std::sqrt((dx * dx) + (dy * dy)) - d.r);
  }
  return std::min(cap, m - radius);
}

}  // namespace

double point_clearance(Point p, const Obstacles& obs, double radius, double cap, double tau) {
  require_point(p, "sensors2023.dwa.clearance");
  require(finite(tau), "sensors2023.dwa.clearance: tau must be finite");
  require_obstacles(obs, radius, cap);
  return clearance_unchecked(p, obs, radius, cap, tau);
}

double trajectory_clearance(std::span<const Pose> traj, const Obstacles& obs, double radius, double cap,
                            ClearanceAt at, double dt) {
  require(!traj.empty(), "sensors2023.dwa.clearance: empty trajectory");
  require(finite(dt) && dt >= 0.0, "sensors2023.dwa.clearance: dt must be finite and >= 0");
  require_obstacles(obs, radius, cap);
  for (const Pose& p : traj) require_point(Point{p.x, p.y}, "sensors2023.dwa.clearance");
  const auto n = traj.size();
  if (at == ClearanceAt::end)
    return clearance_unchecked(Point{traj.back().x, traj.back().y}, obs, radius, cap, static_cast<double>(n) * dt);
  double m = inf;
  for (std::size_t j = 0; j < n; ++j)
    m = std::min(m, clearance_unchecked(Point{traj[j].x, traj[j].y}, obs, radius, cap, static_cast<double>(j + 1) * dt));
  return m;
}

// ---------------------------------------------------------------- control step

StepResult control_step(Pose p, double v_c, double w_c, Point target, const Obstacles& obs, const DwaParams& prm) {
  const Window win = dynamic_window(v_c, w_c, prm.limits, prm.dt);
  const std::vector<double> vs = axis_samples(win.v_lo, win.v_hi, prm.v_res, prm.window_upper);
  const std::vector<double> ws = axis_samples(win.w_lo, win.w_hi, prm.w_res, prm.window_upper);
  require(vs.size() * ws.size() <= 1000000, "sensors2023.dwa.step: at most 10^6 candidates");
  const std::int64_t n = predicted_steps(prm.horizon, prm.dt);
  require_obstacles(obs, prm.radius, prm.clearance_cap);
  require_point(Point{p.x, p.y}, "sensors2023.dwa.step");
  require(finite(p.theta), "sensors2023.dwa.step: heading must be finite");
  require_point(target, "sensors2023.dwa.step target");
  std::vector<Terms> terms;
  terms.reserve(vs.size() * ws.size());
  // The headings theta_j of a trajectory depend on w only, so their cosines and sines are computed
  // once per w and shared by every v (the same doubles motion_step computes: identical results).
  const auto nn = static_cast<std::size_t>(n);
  std::vector<double> cs(ws.size() * nn), sn(ws.size() * nn), th_end(ws.size());
  for (std::size_t iw = 0; iw < ws.size(); ++iw) {
    double th = p.theta;
    for (std::size_t j = 0; j < nn; ++j) {
      const double next = th + (ws[iw] * prm.dt);
      const double use = prm.motion_order == MotionOrder::heading_last ? th : next;
      cs[(iw * nn) + j] = std::cos(use);
      sn[(iw * nn) + j] = std::sin(use);
      th = next;
    }
    th_end[iw] = th;
  }
  for (const double v : vs)
    for (std::size_t iw = 0; iw < ws.size(); ++iw) {
      const double w = ws[iw];
      // predict + trajectory_clearance + heading_term, fused (same operations as motion_step, no allocation).
      Pose q = p;
      double clr = inf;
      const double ds = v * prm.dt;
      for (std::size_t j = 0; j < nn; ++j) {
        q.x = q.x + (ds * cs[(iw * nn) + j]);
        q.y = q.y + (ds * sn[(iw * nn) + j]);
        if (j + 1 == nn) q.theta = th_end[iw];
        require_point(Point{q.x, q.y}, "sensors2023.dwa.step");
        if (prm.clearance_at == ClearanceAt::trajectory || j + 1 == nn)
          clr = std::min(clr, clearance_unchecked(Point{q.x, q.y}, obs, prm.radius, prm.clearance_cap,
                                                  prm.predict_movers ? static_cast<double>(j + 1) * prm.dt : 0.0));
      }
      Terms t;
      const Heading h = heading_term(q, target, prm.heading_wrap);
      t.heading_deg = h.heading_deg;
      t.abs_dtheta = h.abs_dtheta;
      t.velocity = v;
      t.clearance = clr;
      t.valid = clr >= 0.0 && admissible(v, w, clr, prm.limits.dec_v, prm.limits.dec_w, prm.admissible);
      if (!t.valid) t.clearance = std::max(0.0, clr);
      terms.push_back(t);
    }
  const Choice ch = evaluate(terms, prm.weights, prm.evaluation, prm.limits.v_max);
  StepResult r;
  r.candidates = static_cast<std::int64_t>(terms.size());
  for (const Terms& t : terms) r.valid += t.valid ? 1 : 0;
  r.best = ch.best;
  if (ch.best >= 0) {
    const auto b = static_cast<std::size_t>(ch.best);
    r.v = vs[b / ws.size()];
    r.w = ws[b % ws.size()];
    r.score = ch.scores[b];
  } else {
    const Limits& l = prm.limits;
    r.braked = true;
    r.v = std::max(l.v_min, v_c - (l.dec_v * prm.dt));
    r.w = w_c >= 0.0 ? std::max(0.0, w_c - (l.dec_w * prm.dt)) : std::min(0.0, w_c + (l.dec_w * prm.dt));
  }
  return r;
}

// ---------------------------------------------------------------- following

std::vector<grid::Cell> key_nodes(std::span<const grid::Cell> path) {
  require(!path.empty(), "sensors2023.dwa.follow: empty path");
  std::vector<grid::Cell> p;
  for (const grid::Cell& c : path)
    if (p.empty() || !(p.back() == c)) p.push_back(c);
  std::vector<grid::Cell> out{p.front()};
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const std::int64_t ax = p[i].x - p[i - 1].x, ay = p[i].y - p[i - 1].y;
    const std::int64_t bx = p[i + 1].x - p[i].x, by = p[i + 1].y - p[i].y;
    // same direction iff the cross product is 0 and the dot product > 0
    const bool straight = (ax * by - ay * bx) == 0 && (ax * bx + ay * by) > 0;
    if (!straight) out.push_back(p[i]);
  }
  if (p.size() > 1) out.push_back(p.back());
  return out;
}

std::vector<Point> path_waypoints(std::span<const Point> nodes, double spacing) {
  require(!nodes.empty(), "sensors2023.dwa.follow: waypoints of an empty path");
  require(finite(spacing) && spacing > 0.0, "sensors2023.dwa.follow: waypoint spacing must be finite and > 0");
  for (const Point& q : nodes) require(finite(q.x) && finite(q.y), "sensors2023.dwa.follow: path nodes must be finite");
  // the part counts first, so the limit is checked before allocating
  std::vector<std::int64_t> parts(nodes.size(), 0);
  double total = 1.0;
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    const double dx = nodes[i + 1].x - nodes[i].x, dy = nodes[i + 1].y - nodes[i].y;
    const double len = std::sqrt((dx * dx) + (dy * dy));
    if (len == 0.0) continue;
    const double n = std::max(1.0, std::ceil((len / spacing) - 1e-9));
    require(total + n <= 1e6, "sensors2023.dwa.follow: at most 10^6 waypoints");
    total = total + n;
    parts[i] = static_cast<std::int64_t>(n);
  }
  std::vector<Point> out;
  out.reserve(static_cast<std::size_t>(total));
  out.push_back(nodes.front());
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    const Point a = nodes[i], b = nodes[i + 1];
    const std::int64_t n = parts[i];
    for (std::int64_t j = 1; j < n; ++j) {
      const double f = static_cast<double>(j) / static_cast<double>(n);
      out.push_back(Point{a.x + (f * (b.x - a.x)), a.y + (f * (b.y - a.y))});
    }
    if (n > 0) out.push_back(b);
  }
  return out;
}

FollowUpdate follow_update(FollowState s, Point p, std::span<const Point> keys, double t, double dt,
                           const FollowParams& prm, std::span<const std::uint8_t> blocked) {
  require(!keys.empty() && blocked.size() == keys.size(), "sensors2023.dwa.follow: keys non-empty, one blocked flag each");
  const auto m = static_cast<std::int64_t>(keys.size()) - 1;
  require(s.k >= 0 && s.k <= m, "sensors2023.dwa.follow: key index out of range");
  require(finite(p.x) && finite(p.y) && finite(t) && finite(s.since) && finite(s.blocked_for),
          "sensors2023.dwa.follow: inputs must be finite");
  require(finite(dt) && dt > 0.0 && finite(prm.reach) && prm.reach > 0.0 && finite(prm.blocked_timeout) &&
              prm.blocked_timeout > 0.0 && finite(prm.key_timeout) && prm.key_timeout > 0.0,
          "sensors2023.dwa.follow: dt, reach and timeouts must be finite and > 0");
  FollowUpdate u;
  u.state = s;
  FollowState& st = u.state;
  while (st.k < m) {
    const Point k = keys[static_cast<std::size_t>(st.k)];
    const double dx = p.x - k.x, dy = p.y - k.y;
    if (std::sqrt((dx * dx) + (dy * dy)) > prm.reach) break;
    ++st.k;
    st.since = t;
    st.blocked_for = 0.0;
    ++u.switched;
  }
  if (st.k < m) {
    st.blocked_for = blocked[static_cast<std::size_t>(st.k)] != 0 ? st.blocked_for + dt : 0.0;
    SkipReason why = SkipReason::none;
    if (st.blocked_for >= prm.blocked_timeout) why = SkipReason::blocked;
    else if (t - st.since >= prm.key_timeout) why = SkipReason::timeout;
    if (why != SkipReason::none) {
      ++st.k;
      st.since = t;
      st.blocked_for = 0.0;
      u.skipped = why;
    }
  }
  return u;
}

// ---------------------------------------------------------------- obstacles, collision, turns

Point obstacle_position(std::span<const Waypoint> wps, double t) {
  require(!wps.empty(), "sensors2023.sim.obstacles: no waypoints");
  require(finite(t), "sensors2023.sim.obstacles: t must be finite");
  for (std::size_t i = 0; i < wps.size(); ++i) {
    require(finite(wps[i].t) && finite(wps[i].q.x) && finite(wps[i].q.y), "sensors2023.sim.obstacles: finite waypoints");
    if (i > 0) require(wps[i].t > wps[i - 1].t, "sensors2023.sim.obstacles: waypoint times must increase strictly");
  }
  if (t <= wps.front().t) return wps.front().q;
  if (t >= wps.back().t) return wps.back().q;
  std::size_t i = 0;
  while (!(t < wps[i + 1].t)) ++i;
  const Waypoint& a = wps[i];
  const Waypoint& b = wps[i + 1];
  const double f = (t - a.t) / (b.t - a.t);
  return Point{a.q.x + (f * (b.q.x - a.q.x)), a.q.y + (f * (b.q.y - a.q.y))};
}

double segment_cell_distance(Point a, Point b, grid::Cell c) noexcept {
  const double x0 = static_cast<double>(c.x), y0 = static_cast<double>(c.y);
  const double x1 = x0 + 1.0, y1 = y0 + 1.0;
  auto inside = [&](Point p) { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; };
  if (inside(a) || inside(b)) return 0.0;
  const geometry::Vec2 A = vec(a), B = vec(b);
  const geometry::Vec2 c00{x0, y0}, c10{x1, y0}, c11{x1, y1}, c01{x0, y1};
  double m = geometry::segment_distance(A, B, c00, c10);
  m = std::min(m, geometry::segment_distance(A, B, c10, c11));
  m = std::min(m, geometry::segment_distance(A, B, c11, c01));
  m = std::min(m, geometry::segment_distance(A, B, c01, c00));
  return m;
}

double step_clearance(Point a, Point b, double t0, double t1, double radius, const grid::Grid& g,
                      std::span<const grid::Cell> temporary, std::span<const Mover> movers) {
  require_point(a, "sensors2023.sim.collision");
  require_point(b, "sensors2023.sim.collision");
  require(finite(t0) && finite(t1) && t0 < t1, "sensors2023.sim.collision: need finite t0 < t1");
  require(finite(radius) && radius >= 0.0, "sensors2023.sim.collision: radius must be finite and >= 0");
  const double reach = collision_scan;
  double m = inf;
  const auto x0 = static_cast<std::int64_t>(std::floor(std::min(a.x, b.x) - reach));
  const auto x1 = static_cast<std::int64_t>(std::floor(std::max(a.x, b.x) + reach));
  const auto y0 = static_cast<std::int64_t>(std::floor(std::min(a.y, b.y) - reach));
  const auto y1 = static_cast<std::int64_t>(std::floor(std::max(a.y, b.y) + reach));
  for (std::int64_t y = y0; y <= y1; ++y)
    for (std::int64_t x = x0; x <= x1; ++x) {
      const grid::Cell c{x, y};
      if (g.free(c)) continue;
      m = std::min(m, segment_cell_distance(a, b, c));
    }
  for (const grid::Cell& c : temporary) m = std::min(m, segment_cell_distance(a, b, c));
  m = m - radius;
  for (const Mover& mv : movers) {
    require(finite(mv.r) && mv.r >= 0.0, "sensors2023.sim.collision: mover radius must be finite and >= 0");
    std::vector<double> cuts{t0};
    for (const Waypoint& w : mv.waypoints)
      if (w.t > t0 && w.t < t1) cuts.push_back(w.t);
    cuts.push_back(t1);
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const double s0 = cuts[i], s1 = cuts[i + 1];
      const double f0 = (s0 - t0) / (t1 - t0), f1 = (s1 - t0) / (t1 - t0);
      const Point r0{a.x + (f0 * (b.x - a.x)), a.y + (f0 * (b.y - a.y))};
      const Point r1{a.x + (f1 * (b.x - a.x)), a.y + (f1 * (b.y - a.y))};
      const Point o0 = obstacle_position(mv.waypoints, s0);
      const Point o1 = obstacle_position(mv.waypoints, s1);
      const double dax = r0.x - o0.x, day = r0.y - o0.y;
      const double ex = (r1.x - o1.x) - dax, ey = (r1.y - o1.y) - day;
      const double L = (ex * ex) + (ey * ey);
      double s = 0.0;
      if (L > 0.0) s = std::clamp(-((dax * ex) + (day * ey)) / L, 0.0, 1.0);
      const double qx = dax + (s * ex), qy = day + (s * ey);
      m = std::min(m, (std::sqrt((qx * qx) + (qy * qy)) - mv.r) - radius);
    }
  }
  return std::min(m, collision_scan);
}

double track_length(std::span<const Point> track) noexcept {
  double L = 0.0;
  for (std::size_t i = 1; i < track.size(); ++i) {
    const double dx = track[i].x - track[i - 1].x, dy = track[i].y - track[i - 1].y;
    L = L + std::sqrt((dx * dx) + (dy * dy));
  }
  return L;
}

std::int64_t count_turns(std::span<const Point> track, const TurnParams& prm) {
  require(finite(prm.ds) && prm.ds > 0.0, "sensors2023.sim.turns: ds must be finite and > 0");
  require(finite(prm.delta) && finite(prm.theta) && prm.delta > 0.0 && prm.delta <= prm.theta,
          "sensors2023.sim.turns: need 0 < delta <= theta");
  for (const Point& p : track) require(finite(p.x) && finite(p.y), "sensors2023.sim.turns: finite track");
  // drop zero-length segments
  std::vector<Point> pts;
  for (const Point& p : track)
    if (pts.empty() || !(pts.back() == p)) pts.push_back(p);
  if (pts.size() < 2) return 0;
  // resample at s = i * ds (forward walk)
  std::vector<Point> rs;
  double acc = 0.0;
  std::size_t k = 0;
  double len = std::sqrt(((pts[1].x - pts[0].x) * (pts[1].x - pts[0].x)) + ((pts[1].y - pts[0].y) * (pts[1].y - pts[0].y)));
  for (std::int64_t i = 0;; ++i) {
    const double s = static_cast<double>(i) * prm.ds;
    while (s > acc + len && k + 2 < pts.size()) {
      acc = acc + len;
      ++k;
      const double dx = pts[k + 1].x - pts[k].x, dy = pts[k + 1].y - pts[k].y;
      len = std::sqrt((dx * dx) + (dy * dy));
    }
    if (s > acc + len) break;
    const double f = (s - acc) / len;
    rs.push_back(Point{pts[k].x + (f * (pts[k + 1].x - pts[k].x)), pts[k].y + (f * (pts[k + 1].y - pts[k].y))});
    require(rs.size() <= 10000000, "sensors2023.sim.turns: at most 10^7 resampled points");
  }
  if (rs.size() < 3) return 0;
  std::int64_t turns = 0;
  double sum = 0.0;
  int sign = 0;
  auto close = [&] {
    if (sign != 0 && std::fabs(sum) >= prm.theta) ++turns;
    sign = 0;
    sum = 0.0;
  };
  double prev = std::atan2(rs[1].y - rs[0].y, rs[1].x - rs[0].x);
  for (std::size_t i = 2; i < rs.size(); ++i) {
    const double h = std::atan2(rs[i].y - rs[i - 1].y, rs[i].x - rs[i - 1].x);
    const double d = wrap_angle(h - prev);
    prev = h;
    if (std::fabs(d) >= prm.delta) {
      const int sg = d > 0.0 ? 1 : -1;
      if (sign == sg) {
        sum = sum + d;
      } else {
        close();
        sign = sg;
        sum = d;
      }
    } else {
      close();
    }
  }
  close();
  return turns;
}

}  // namespace pathref::dwa
