#include "pathref/vehicle/drive.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>

#include "pathref/core/error.hpp"

namespace pathref::vehicle {

namespace {

bool finite_positive(double v) { return std::isfinite(v) && v > 0.0; }
/// > 0, +inf allowed, NaN not.
bool positive_or_inf(double v) { return !std::isnan(v) && v > 0.0; }

bool is_step(grid::Cell s) {
  return s.x >= -1 && s.x <= 1 && s.y >= -1 && s.y <= 1 && (s.x != 0 || s.y != 0);
}

/// E, NE, N, NW, W, SW, S, SE -> 0..7 (counter-clockwise). Pre: is_step(s).
int direction_index(grid::Cell s) {
  static constexpr int table[3][3] = {
      // s.y = -1, 0, +1 for each s.x = -1, 0, +1
      {5, 4, 3},   // x = -1: SW, W, NW
      {6, -1, 2},  // x =  0: S, -, N
      {7, 0, 1},   // x = +1: SE, E, NE
  };
  return table[s.x + 1][s.y + 1];
}

}  // namespace

Profile trapezoid(double d, double v0, double v1, double v_max, double a) {
  require(std::isfinite(d) && d >= 0.0, "run length d must be finite and >= 0");
  require(std::isfinite(v0) && v0 >= 0.0, "start speed v0 must be finite and >= 0");
  require(std::isfinite(v1) && v1 >= 0.0, "end speed v1 must be finite and >= 0");
  require(finite_positive(a), "acceleration limit a must be finite and > 0");
  require(positive_or_inf(v_max), "speed limit V must be > 0 (may be inf)");
  require(v0 <= v_max && v1 <= v_max, "start and end speeds must not exceed the speed limit");
  const double v_hat = std::sqrt((v0 * v0 + v1 * v1) / 2.0 + a * d);
  const double v_edge = std::max(v0, v1);
  require(v_hat >= v_edge * (1.0 - 1e-12),
          "end speed not reachable within the run: |v1^2 - v0^2| > 2 a d");
  Profile p;
  p.v_peak = std::max(std::min(v_max, v_hat), v_edge);
  p.reaches_limit = p.v_peak == v_max;
  p.t_acc = (p.v_peak - v0) / a;
  p.t_dec = (p.v_peak - v1) / a;
  p.d_acc = (p.v_peak * p.v_peak - v0 * v0) / (2.0 * a);
  p.d_dec = (p.v_peak * p.v_peak - v1 * v1) / (2.0 * a);
  // A triangle has no cruise; (d - d_acc) - d_dec would only be a rounding residue there.
  p.d_cruise = p.reaches_limit ? std::max(0.0, (d - p.d_acc) - p.d_dec) : 0.0;
  p.t_cruise = p.d_cruise > 0.0 ? p.d_cruise / p.v_peak : 0.0;
  p.time = (p.t_acc + p.t_cruise) + p.t_dec;
  require(std::isfinite(p.time), "run time overflows binary64");
  return p;
}

Profile rotation_time(double angle, double omega_max, double alpha_max) {
  require(std::isfinite(angle), "rotation angle must be finite");
  require(positive_or_inf(omega_max), "yaw-rate limit must be > 0 (may be inf)");
  require(finite_positive(alpha_max), "yaw acceleration limit must be finite and > 0");
  return trapezoid(std::fabs(angle), 0.0, 0.0, omega_max, alpha_max);
}

Turn turn_angle(grid::Cell from, grid::Cell to) {
  require(is_step(from) && is_step(to), "turn directions must be 8-neighbour steps");
  const int i = direction_index(from);
  const int j = direction_index(to);
  const int diff = std::abs(i - j);
  Turn t;
  t.eighths = std::min(diff, 8 - diff);
  t.angle = static_cast<double>(t.eighths) * (std::numbers::pi / 4.0);
  const std::int64_t cross = from.x * to.y - from.y * to.x;
  t.sense = cross > 0 ? 1 : cross < 0 ? -1 : (t.eighths == 4 ? 1 : 0);
  return t;
}

Runs straight_runs(std::span<const grid::Cell> path) {
  require(!path.empty(), "a path needs at least one cell");
  for (const grid::Cell& c : path)
    require(std::llabs(c.x) <= max_abs_path_coordinate && std::llabs(c.y) <= max_abs_path_coordinate,
            "path coordinates must satisfy |x|, |y| <= 2^25");
  Runs out;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const grid::Cell s{path[k].x - path[k - 1].x, path[k].y - path[k - 1].y};
    require(is_step(s), "step " + std::to_string(k) + " of the path is not an 8-neighbour step (" +
                            std::to_string(path[k - 1].x) + "," + std::to_string(path[k - 1].y) +
                            ") -> (" + std::to_string(path[k].x) + "," +
                            std::to_string(path[k].y) + ")");
    if (!out.runs.empty() && out.runs.back().dir == s) {
      ++out.runs.back().steps;
    } else {
      if (!out.runs.empty()) out.turns.push_back(turn_angle(out.runs.back().dir, s));
      out.runs.push_back(Run{s, static_cast<std::int64_t>(k), 1, 0.0});
    }
  }
  for (Run& r : out.runs) {
    const double step_length = (r.dir.x != 0 && r.dir.y != 0) ? std::sqrt(2.0) : 1.0;
    r.length_cells = static_cast<double>(r.steps) * step_length;
  }
  return out;
}

std::vector<double> corner_speeds(std::span<const double> lengths, std::span<const double> v_max,
                                  std::span<const double> accel, double corner_speed) {
  const std::size_t m = lengths.size();
  require(m >= 1, "corner speeds need at least one run");
  require(v_max.size() == m && accel.size() == m,
          "lengths, speed limits and acceleration limits must have equal lengths");
  for (std::size_t j = 0; j < m; ++j) {
    require(finite_positive(lengths[j]), "run lengths must be finite and > 0");
    require(positive_or_inf(v_max[j]), "run speed limits must be > 0 (may be inf)");
    require(finite_positive(accel[j]), "run acceleration limits must be finite and > 0");
  }
  require(std::isfinite(corner_speed) && corner_speed >= 0.0,
          "corner speed must be finite and >= 0");
  // u[j] is the speed at the joint after run j (1-based runs); u[0] = u[m] = 0.
  std::vector<double> u(m + 1, 0.0);
  for (std::size_t j = 1; j < m; ++j)
    u[j] = std::min(corner_speed, std::min(v_max[j - 1], v_max[j]));
  for (std::size_t j = 1; j < m; ++j)  // run j is lengths[j - 1]
    u[j] = std::min(u[j], std::sqrt(u[j - 1] * u[j - 1] + 2.0 * accel[j - 1] * lengths[j - 1]));
  for (std::size_t j = m - 1; j >= 1; --j)  // run j + 1 is lengths[j]
    u[j] = std::min(u[j], std::sqrt(u[j + 1] * u[j + 1] + 2.0 * accel[j] * lengths[j]));
  return u;
}

Base parse_base(std::string_view name) {
  if (name == "mecanum") return Base::mecanum;
  if (name == "diff") return Base::diff;
  throw UsageError("unknown base '" + std::string(name) + "' (expected mecanum or diff)");
}

std::string_view to_string(Base base) noexcept {
  return base == Base::mecanum ? "mecanum" : "diff";
}

PathTime path_time(std::span<const grid::Cell> path, double cell, Base base,
                   const DriveParams& params) {
  require(finite_positive(cell), "cell size must be finite and > 0");
  require_geometry(params.geometry);
  require(finite_positive(params.wheel_speed_max), "wheel speed limit must be finite and > 0");
  require(finite_positive(params.accel), "acceleration limit must be finite and > 0");
  require(positive_or_inf(params.speed_cap), "speed cap must be > 0 (may be inf)");
  require(std::isfinite(params.corner_speed) && params.corner_speed >= 0.0,
          "corner speed must be finite and >= 0");
  require(finite_positive(params.half_track), "half track b must be finite and > 0");
  require(positive_or_inf(params.yaw_rate_cap), "yaw-rate cap must be > 0 (may be inf)");

  const Runs rs = straight_runs(path);
  const double r = params.geometry.r;
  const double w = params.wheel_speed_max;
  PathTime out;
  out.base = base;
  out.turns = static_cast<std::int64_t>(rs.turns.size());
  if (base == Base::diff) {
    out.yaw_rate_limit = std::min(params.yaw_rate_cap, r * w / params.half_track);
    out.yaw_accel_limit = params.accel / params.half_track;
  }
  if (rs.runs.empty()) return out;

  const std::size_t m = rs.runs.size();
  std::vector<double> d(m), v_lim(m), a_lim(m);
  for (std::size_t j = 0; j < m; ++j) {
    const Run& run = rs.runs[j];
    d[j] = run.length_cells * cell;
    require(std::isfinite(d[j]), "run distance overflows binary64");
    if (base == Base::mecanum) {
      const double g = direction_factor(static_cast<double>(run.dir.x), static_cast<double>(run.dir.y));
      v_lim[j] = std::min(params.speed_cap,
                          max_translation_speed(static_cast<double>(run.dir.x),
                                                static_cast<double>(run.dir.y), r, w));
      a_lim[j] = params.accel / g;
    } else {
      v_lim[j] = std::min(params.speed_cap, r * w);
      a_lim[j] = params.accel;
    }
  }
  const std::vector<double> u = base == Base::mecanum
                                    ? corner_speeds(d, v_lim, a_lim, params.corner_speed)
                                    : std::vector<double>(m + 1, 0.0);
  for (std::size_t j = 0; j < m; ++j) {
    RunTiming rt;
    rt.run = rs.runs[j];
    rt.distance = d[j];
    rt.v_limit = v_lim[j];
    rt.a_limit = a_lim[j];
    rt.v_start = u[j];
    rt.v_end = u[j + 1];
    rt.profile = trapezoid(d[j], u[j], u[j + 1], v_lim[j], a_lim[j]);
    out.distance += rt.distance;
    out.run_time += rt.profile.time;
    out.time += rt.profile.time;
    out.runs.push_back(rt);
    if (j + 1 < m) {
      TurnTiming tt;
      tt.turn = rs.turns[j];
      if (base == Base::diff) {
        tt.profile = rotation_time(tt.turn.angle, out.yaw_rate_limit, out.yaw_accel_limit);
        out.rotate_time += tt.profile.time;
        out.time += tt.profile.time;
      }
      out.joints.push_back(tt);
    }
  }
  return out;
}

namespace {

/// Appends the knots of one profile starting at t0: start, end of acceleration, end of cruise,
/// end (phases of zero duration skipped). `make` maps (t, signed speed) to a knot.
template <class Make>
void profile_knots(std::vector<Knot>& out, double t0, double v0, double v1, const Profile& p,
                   double t_end, Make make) {
  out.push_back(make(t0, v0));
  const double t_a = t0 + p.t_acc;
  if (p.t_acc > 0.0) out.push_back(make(t_a, p.v_peak));
  if (p.t_cruise > 0.0) out.push_back(make(t_a + p.t_cruise, p.v_peak));
  out.push_back(make(t_end, v1));
}

}  // namespace

std::vector<Knot> schedule(const PathTime& pt, const DriveParams& params) {
  std::vector<Knot> out;
  const Geometry& g = params.geometry;
  double t = 0.0;
  if (pt.runs.empty()) {
    Knot k;
    k.wheels.assign(pt.base == Base::mecanum ? 4 : 2, 0.0);
    out.push_back(k);
    return out;
  }
  for (std::size_t j = 0; j < pt.runs.size(); ++j) {
    const RunTiming& rt = pt.runs[j];
    const double dx = static_cast<double>(rt.run.dir.x);
    const double dy = static_cast<double>(rt.run.dir.y);
    const double n = std::hypot(dx, dy);
    const double t_end = t + rt.profile.time;
    if (pt.base == Base::mecanum) {
      profile_knots(out, t, rt.v_start, rt.v_end, rt.profile, t_end, [&](double tk, double v) {
        Knot k;
        k.t = tk;
        k.speed = v;
        k.vx = v * (dx / n);
        k.vy = v * (dy / n);
        const WheelSpeeds ws = inverse_kinematics(Twist{k.vx, k.vy, 0.0}, g);
        k.wheels.assign(ws.data(), ws.data() + 4);
        return k;
      });
    } else {
      profile_knots(out, t, rt.v_start, rt.v_end, rt.profile, t_end, [&](double tk, double v) {
        Knot k;
        k.t = tk;
        k.speed = v;
        k.vx = v;
        k.wheels = {v / g.r, v / g.r};
        return k;
      });
    }
    t = t_end;
    if (j < pt.joints.size() && pt.base == Base::diff) {
      const TurnTiming& tt = pt.joints[j];
      const double sense = static_cast<double>(tt.turn.sense);
      const double b = params.half_track;
      const double t_rot_end = t + tt.profile.time;
      profile_knots(out, t, 0.0, 0.0, tt.profile, t_rot_end, [&](double tk, double yaw) {
        Knot k;
        k.t = tk;
        k.omega = sense * yaw;
        k.wheels = {(0.0 - b * k.omega) / g.r, (0.0 + b * k.omega) / g.r};
        return k;
      });
      t = t_rot_end;
    }
  }
  return out;
}

}  // namespace pathref::vehicle
