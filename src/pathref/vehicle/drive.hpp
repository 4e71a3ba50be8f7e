#pragma once
/// \file drive.hpp
/// The time to drive a grid path with a Mecanum base (translates in any direction, never rotates)
/// or a differential-drive base (stops and rotates on the spot at every turn), both under wheel
/// speed and acceleration limits: trapezoidal/triangular speed profile per straight run, joint
/// speeds by a forward-backward pass, rotation time in angle. Pure functions.
/// Makes the turn counts of Shi et al. 2022 (Tables 3-5, doi:10.3389/fbioe.2022.905983)
/// measurable in seconds for the vehicle of their §5.3.
/// Spec: spec/mecanum.md (drive.*)
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

#include "pathref/grid/grid.hpp"
#include "pathref/vehicle/mecanum.hpp"

namespace pathref::vehicle {

/// One rest-to-rest (or speed-to-speed) motion along a line under a speed and an acceleration
/// limit: accelerate, cruise, brake.
struct Profile {
  double time = 0.0;      ///< T = (t_acc + t_cruise) + t_dec
  double v_peak = 0.0;    ///< v_p: the top speed reached
  double t_acc = 0.0;
  double t_cruise = 0.0;
  double t_dec = 0.0;
  double d_acc = 0.0;
  double d_cruise = 0.0;
  double d_dec = 0.0;
  bool reaches_limit = false;  ///< v_p == V ("trapezoid"); false: "triangle"
};

/// Time of a straight run of length d from speed v0 to speed v1 under speed limit v_max (may be
/// +inf) and acceleration limit a: v_p = max(min(V, sqrt((v0 v0 + v1 v1)/2 + a d)), v0, v1),
/// T = ((v_p - v0)/a + d_cruise/v_p) + (v_p - v1)/a.
/// Source: pathref (time-optimal bang-coast-bang profile). Spec: drive.trapezoid.
/// Pre: d, v0, v1 finite >= 0; a finite > 0; v_max > 0; v0, v1 <= v_max; v1 reachable from v0
/// within d (|v1^2 - v0^2| <= 2 a d up to a relative 1e-12); T finite (DomainError).
/// Post: T >= 0; d_acc + d_cruise + d_dec == d up to rounding. Golden: golden/mecanum/drive.trapezoid.json
[[nodiscard]] Profile trapezoid(double d, double v0, double v1, double v_max, double a);

/// Time to rotate on the spot by `angle` (radians, either sign) from rest to rest, yaw-rate limit
/// omega_max (may be +inf), yaw acceleration limit alpha_max: trapezoid(|angle|, 0, 0, ...).
/// Source: pathref. Spec: drive.rotation. Pre: angle finite; omega_max > 0; alpha_max finite > 0 (DomainError).
/// Golden: golden/mecanum/drive.rotation.json
[[nodiscard]] Profile rotation_time(double angle, double omega_max, double alpha_max);

/// A maximal sequence of consecutive steps with the same step vector.
struct Run {
  grid::Cell dir;                 ///< the step vector, components in {-1, 0, 1}
  std::int64_t first_step = 0;    ///< index k of its first step s_k = p_k - p_{k-1} (1-based)
  std::int64_t steps = 0;         ///< n_j >= 1
  double length_cells = 0.0;      ///< n_j * 1 or n_j * sqrt(2)
};

/// The joint between two consecutive runs.
struct Turn {
  int eighths = 0;     ///< q: number of 45-degree steps between the directions, 0..4
  double angle = 0.0;  ///< q * fl(pi/4), radians
  int sense = 0;       ///< +1 left (counter-clockwise; also a reversal), -1 right, 0 straight on
};

/// The angle and sense of the turn from step vector `from` to step vector `to`.
/// Spec: drive.runs. Pre: both are 8-neighbour steps (components in {-1,0,1}, not (0,0)) (DomainError).
[[nodiscard]] Turn turn_angle(grid::Cell from, grid::Cell to);

struct Runs {
  std::vector<Run> runs;    ///< in path order; empty for a one-cell path
  std::vector<Turn> turns;  ///< runs.size() - 1 joints (none for at most one run)
};

/// Decomposes a path of 8-neighbour steps into maximal straight runs and the turns between them.
/// Source: pathref. Spec: drive.runs. Pre: path non-empty; every step an 8-neighbour step (no repeated cell, no
/// jump); |x|, |y| <= 2^25 (DomainError naming the step). Post: turns.size() ==
/// max(0, runs.size() - 1) == metrics::turn_count(path) for such paths.
/// Golden: golden/mecanum/drive.runs.json
[[nodiscard]] Runs straight_runs(std::span<const grid::Cell> path);

/// Largest |coordinate| accepted by straight_runs (spec/metrics.md path domain): 2^25.
inline constexpr std::int64_t max_abs_path_coordinate = std::int64_t{1} << 25;

/// Joint speeds u_0 .. u_m (u_0 = u_m = 0) for runs of lengths d_j, speed limits V_j, acceleration
/// limits A_j and a target corner speed v_c: targets min(v_c, V_j, V_{j+1}), then a forward pass
/// u_j = min(u_j, sqrt(u_{j-1}^2 + 2 A_j d_j)) and a backward pass
/// u_j = min(u_j, sqrt(u_{j+1}^2 + 2 A_{j+1} d_{j+1})).
/// Source: pathref (forward-backward pass of speed planning). Spec: drive.corner-speeds. Pre: m >= 1 equal-length lists; d_j finite > 0; V_j > 0;
/// A_j finite > 0; v_c finite >= 0 (DomainError). Golden: golden/mecanum/drive.corner-speeds.json
[[nodiscard]] std::vector<double> corner_speeds(std::span<const double> lengths,
                                                std::span<const double> v_max,
                                                std::span<const double> accel, double corner_speed);

/// The two bases of spec drive.path-time.
enum class Base {
  mecanum,  ///< translates in any direction, never rotates
  diff,     ///< differential drive: stops and rotates on the spot at each turn
};
/// "mecanum" | "diff" -> Base; UsageError otherwise.
[[nodiscard]] Base parse_base(std::string_view name);
[[nodiscard]] std::string_view to_string(Base base) noexcept;

/// Every parameter of the driving model; defaults of spec/mecanum.md ("Defaults").
struct DriveParams {
  Geometry geometry;                                    ///< r, l_x, l_y (assumptions)
  double wheel_speed_max = default_wheel_speed_limit;   ///< w-bar, rad/s at the wheel (500 rpm)
  double accel = 1.0;          ///< a: acceleration limit at each wheel rim, m/s^2 (assumption)
  double speed_cap = std::numeric_limits<double>::infinity();     ///< v_cap, m/s
  double corner_speed = 0.0;   ///< v_c, Mecanum only, m/s (0: full stop at every turn)
  double half_track = 0.15;    ///< b, differential drive, m (= l_y by default)
  double yaw_rate_cap = std::numeric_limits<double>::infinity();  ///< Omega_cap, diff, rad/s
};

/// One run as driven.
struct RunTiming {
  Run run;
  double distance = 0.0;  ///< d_j = L_j * c, metres
  double v_limit = 0.0;   ///< V_j
  double a_limit = 0.0;   ///< A_j
  double v_start = 0.0;   ///< u_{j-1}
  double v_end = 0.0;     ///< u_j
  Profile profile;
};

/// One joint as driven (the differential drive's rotation; zero profile for Mecanum).
struct TurnTiming {
  Turn turn;
  Profile profile;
};

struct PathTime {
  Base base = Base::mecanum;
  double time = 0.0;         ///< total, summed in driving order
  double distance = 0.0;     ///< sum of d_j
  std::int64_t turns = 0;    ///< runs - 1 (0 for one cell)
  double run_time = 0.0;     ///< sum of run times
  double rotate_time = 0.0;  ///< sum of rotation times (0 for Mecanum)
  double yaw_rate_limit = 0.0;   ///< Omega (diff), 0 for Mecanum
  double yaw_accel_limit = 0.0;  ///< A_psi = a / b (diff), 0 for Mecanum
  std::vector<RunTiming> runs;
  std::vector<TurnTiming> joints;
};

/// The time, distance and turns to drive `path` (cells of size `cell` metres) with `base`.
/// Mecanum: V_j = min(v_cap, r w / g_j), A_j = a / g_j, joint speeds by corner_speeds with v_c.
/// Diff: V_j = min(v_cap, r w), A_j = a, stops at every joint and rotates by the turning angle with
/// Omega = min(Omega_cap, r w / b), A_psi = a / b; T = t_1 + rho_1 + t_2 + ... .
/// Source: pathref; vehicle of Shi et al. 2022 §5.3, Table 2. Spec: drive.path-time. Pre: path as straight_runs; cell finite > 0; parameters as the spec's
/// Domain (DomainError). Golden: golden/mecanum/drive.path-time.json
[[nodiscard]] PathTime path_time(std::span<const grid::Cell> path, double cell, Base base,
                                 const DriveParams& params);

/// A breakpoint of the piecewise-linear speed schedule: at time t the body twist (vx, vy, omega)
/// and the wheel speeds (rad/s; Mecanum FL, FR, RL, RR; diff left, right). Between consecutive
/// knots every quantity changes linearly. Two knots share a time where the direction changes.
struct Knot {
  double t = 0.0;
  double speed = 0.0;  ///< |(vx, vy)|, m/s
  double vx = 0.0;     ///< grid +x (Mecanum: world = body frame) / forward (diff)
  double vy = 0.0;
  double omega = 0.0;
  std::vector<double> wheels;
};

/// The wheel-speed schedule of a driven path, for the CLI and the speed-profile chart. Knots at
/// every phase boundary of every run and rotation (zero-length phases skipped); the last knot's
/// t equals pt.time. Spec: drive.path-time (outputs). Pre: pt from path_time with `params`.
[[nodiscard]] std::vector<Knot> schedule(const PathTime& pt, const DriveParams& params);

}  // namespace pathref::vehicle
