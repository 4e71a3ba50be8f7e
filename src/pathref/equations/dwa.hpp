#pragma once
/// \file dwa.hpp
/// The dynamic window approach of sensors2023 §3 (Eq. 9-13, reconstructed; Fox, Burgard and Thrun
/// 1997) and its following heading term (Eq. 14), one small pure function per equation, plus the
/// pieces the fused simulation composes them with (clearance, key-node following, obstacles,
/// continuous-time collision test, turn counting).
/// Source: Sensors 2023, 23(8), 4102, doi:10.3390/s23084102, Sec. 3.1-3.3.
/// Spec: spec/sensors2023-dwa.md
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "pathref/grid/grid.hpp"

namespace pathref::dwa {

/// A point in metres, map frame (1 m cells, cell (x, y) = [x, x+1] x [y, y+1]).
struct Point {
  double x = 0.0;
  double y = 0.0;
  friend constexpr bool operator==(const Point&, const Point&) = default;
};

/// A pose: position in metres and heading theta in radians, counter-clockwise from +x.
struct Pose {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;
  friend constexpr bool operator==(const Pose&, const Pose&) = default;
};

inline constexpr double pi = 3.141592653589793;
inline constexpr double deg_per_rad = 57.29577951308232;  // fl(180 / fl(pi))

// ---------------------------------------------------------------- readings (spec, named options)
enum class MotionOrder { heading_last, heading_first };
enum class WindowUpper { include, exclude };
enum class Admissible { both, linear, off };
enum class HeadingWrap { on, off };
enum class Evaluation { normalised, cost };
enum class ClearanceAt { trajectory, end };

/// Parsers of the option names of spec/sensors2023-dwa.md (UsageError naming the options otherwise).
[[nodiscard]] MotionOrder parse_motion_order(std::string_view s);
[[nodiscard]] WindowUpper parse_window_upper(std::string_view s);
[[nodiscard]] Admissible parse_admissible(std::string_view s);
[[nodiscard]] HeadingWrap parse_heading_wrap(std::string_view s);
[[nodiscard]] Evaluation parse_evaluation(std::string_view s);
[[nodiscard]] ClearanceAt parse_clearance_at(std::string_view s);
[[nodiscard]] std::string_view to_string(MotionOrder v) noexcept;
[[nodiscard]] std::string_view to_string(WindowUpper v) noexcept;
[[nodiscard]] std::string_view to_string(Admissible v) noexcept;
[[nodiscard]] std::string_view to_string(HeadingWrap v) noexcept;
[[nodiscard]] std::string_view to_string(Evaluation v) noexcept;
[[nodiscard]] std::string_view to_string(ClearanceAt v) noexcept;

// ---------------------------------------------------------------- Eq. 9
/// One step of the unicycle over dt: heading_last (Eq. 9): x + ((v dt) cos th), y + ((v dt) sin th),
/// th + (w dt); heading_first (PythonRobotics): th' = th + (w dt) first, then x, y with cos/sin th'.
/// Source: sensors2023, Eq. (9) (reconstructed, grade A), doi:10.3390/s23084102.
/// Spec: sensors2023.eq9. Pre: finite inputs, dt > 0 (DomainError). Post: |step| = |v| dt up to rounding.
/// Golden: golden/sensors2023-dwa/sensors2023.eq9.json
[[nodiscard]] Pose motion_step(Pose p, double v, double w, double dt,
                               MotionOrder order = MotionOrder::heading_last);

/// Number of predicted steps N = round(horizon / dt) (half away from zero).
/// Spec: sensors2023.eq9. Pre: dt, horizon finite > 0, 1 <= N <= 10^4 (DomainError).
[[nodiscard]] std::int64_t predicted_steps(double horizon, double dt);

/// The predicted trajectory P_0 = p, P_{j+1} = motion_step(P_j, v, w, dt) for j < N; returns
/// P_1 ... P_N (N = predicted_steps(horizon, dt)).
/// Source: sensors2023, Sec. 3.1 ("predict the trajectory ... over a period of time").
/// Spec: sensors2023.eq9. Pre: as motion_step and predicted_steps (DomainError).
/// Golden: golden/sensors2023-dwa/sensors2023.eq9.json
[[nodiscard]] std::vector<Pose> predict(Pose p, double v, double w, double dt, double horizon,
                                        MotionOrder order = MotionOrder::heading_last);

// ---------------------------------------------------------------- Eq. 10, 11
/// A box of velocity pairs [v_lo, v_hi] x [w_lo, w_hi].
struct Window {
  double v_lo = 0.0;
  double v_hi = 0.0;
  double w_lo = 0.0;
  double w_hi = 0.0;
};

/// The robot's limits and the window parameters (project defaults of spec/sensors2023-dwa.md,
/// not the paper's).
struct Limits {
  double v_min = 0.0;
  double v_max = 1.0;
  double w_max = 0.6981317007977318;  ///< 40 deg/s
  double acc_v = 0.5;
  double dec_v = 0.5;
  double acc_w = 1.7453292519943295;  ///< 100 deg/s^2
  double dec_w = 1.7453292519943295;
};

/// Eq. 10: V_s = [v_min, v_max] x [-w_max, w_max].
/// Source: sensors2023, Eq. (10) (reconstructed, grade A). Spec: sensors2023.eq10.
/// Pre: finite, v_min <= v_max, w_max >= 0 (DomainError). Golden: golden/sensors2023-dwa/sensors2023.eq10.json
[[nodiscard]] Window velocity_space(const Limits& lim);

/// Eq. 11 intersected with Eq. 10: v_lo = max(v_min, v_c - (dec_v dt)), v_hi = min(v_max, v_c +
/// (acc_v dt)), w_lo = max(-w_max, w_c - (dec_w dt)), w_hi = min(w_max, w_c + (acc_w dt)).
/// Source: sensors2023, Eq. (11) (reconstructed, grade A). Spec: sensors2023.eq11.
/// Pre: limits as velocity_space, rates finite >= 0, dt > 0, v_c in [v_min, v_max], |w_c| <= w_max
/// (DomainError). Post: v_lo <= v_hi, w_lo <= w_hi, inside V_s.
/// Golden: golden/sensors2023-dwa/sensors2023.eq11.json
[[nodiscard]] Window dynamic_window(double v_c, double w_c, const Limits& lim, double dt);

/// Samples lo + (k r), k = 0 ... K, of one window axis: include: K = floor(s + 1e-9); exclude:
/// K = max(0, ceil(s - 1e-9) - 1); s = (hi - lo) / r.
/// Source: sensors2023, Sec. 3.1 ("sample multiple sets of velocities"). Spec: sensors2023.eq11.
/// Pre: lo <= hi finite, r finite > 0, K + 1 <= 10^6 (DomainError). Post: ascending, all in [lo, hi + ~1e-9 r].
[[nodiscard]] std::vector<double> axis_samples(double lo, double hi, double r, WindowUpper upper);

// ---------------------------------------------------------------- Eq. 12
/// Eq. 12: v <= sqrt((2 dist) dec_v) and |w| <= sqrt((2 dist) dec_w) (both); only the first (linear);
/// always true (off).
/// Source: sensors2023, Eq. (12) (reconstructed, grade A; Fox et al. 1997). Spec: sensors2023.eq12.
/// Pre: finite, dist >= 0, dec_v, dec_w >= 0 (DomainError). Golden: golden/sensors2023-dwa/sensors2023.eq12.json
[[nodiscard]] bool admissible(double v, double w, double dist, double dec_v, double dec_w,
                              Admissible mode = Admissible::both);

// ---------------------------------------------------------------- Eq. 14
/// wrap(a) = r - pi, r = fmod(a + pi, 2 pi), r += 2 pi if r <= 0: the angle in (-pi, pi].
/// Source: pathref. Spec: sensors2023.eq14. Pre: finite (DomainError).
[[nodiscard]] double wrap_angle(double a);

struct Heading {
  double heading_deg = 0.0;  ///< 180 - (|wrap(dtheta)| * 180/pi)
  double abs_dtheta = 0.0;   ///< |wrap(dtheta)| (rad), or |dtheta| unwrapped
};
/// Eq. 14: dtheta = theta_end - atan2(T.y - y, T.x - x); heading = 180 - (|wrap(dtheta)| (180/pi)).
/// Source: sensors2023, Eq. (14) (reconstructed, grade B). Spec: sensors2023.eq14.
/// Pre: finite (DomainError). Post: heading in [0, 180] under wrap on.
/// Golden: golden/sensors2023-dwa/sensors2023.eq14.json
[[nodiscard]] Heading heading_term(Pose end, Point target, HeadingWrap wrap = HeadingWrap::on);

// ---------------------------------------------------------------- Eq. 13
struct Weights {
  double alpha = 0.2;   ///< heading (normalised); 0.2, not the MATLAB demo's 0.05 (spec: Project defaults)
  double beta = 0.2;    ///< clearance
  double gamma = 0.1;   ///< velocity
  double k_heading = 0.15;   ///< cost: |dtheta| (rad)
  double k_clearance = 1.0;  ///< cost: 1 / d
  double k_velocity = 1.0;   ///< cost: v_max - v
};

/// The terms of one candidate.
struct Terms {
  double heading_deg = 0.0;  ///< Eq. 14
  double abs_dtheta = 0.0;   ///< Eq. 14, radians
  double clearance = 0.0;    ///< capped trajectory clearance, >= 0 for valid candidates
  double velocity = 0.0;     ///< v
  bool valid = false;        ///< not colliding and admissible (Eq. 12)
};

struct Choice {
  std::vector<double> scores;  ///< G (normalised) or C (cost); NaN for invalid candidates
  std::int64_t best = -1;      ///< index of the chosen candidate, -1 if none is valid
};

/// Eq. 13 over the valid candidates, in candidate order: normalised: G_i = ((alpha h_i/H) +
/// (beta d_i/D)) + (gamma v_i/V) (sums in order; a zero sum gives 0 terms), maximised, first on
/// ties; cost: C_i = ((k_h |dtheta_i|) + (k_v (v_max - v_i))) + (k_d (1/d_i)), minimised.
/// Source: sensors2023, Eq. (13) (reconstructed, grade A; Fox et al. 1997). Spec: sensors2023.eq13.
/// Pre: size <= 10^6; valid terms finite, clearance >= 0; velocity >= 0 (normalised); weights
/// finite >= 0; v_max finite (DomainError). Golden: golden/sensors2023-dwa/sensors2023.eq13.json
[[nodiscard]] Choice evaluate(std::span<const Terms> terms, const Weights& w, Evaluation mode,
                              double v_max);

// ---------------------------------------------------------------- clearance
/// A moving obstacle's disc at some time, with its estimated velocity (m/s; zero: static).
struct Disc {
  Point c;
  double r = 0.0;
  Point vel;
};

/// What a control step sees: the map (cells outside count as blocked), the present temporary
/// cells and the discs at their current positions.
struct Obstacles {
  const grid::Grid* grid = nullptr;
  std::span<const grid::Cell> temporary;
  std::span<const Disc> discs;
};

/// Point clearance min(cap, min_o surf(p, o) - radius), examining cells within cap + radius; each
/// disc taken at c + (tau vel) (its predicted position tau seconds ahead).
/// Source: pathref. Spec: sensors2023.dwa.clearance. Pre: finite p, tau; cap > 0 finite; radius >= 0;
/// obs.grid set; disc radii >= 0, finite velocities (DomainError).
/// Golden: golden/sensors2023-dwa/sensors2023.dwa.clearance.json
[[nodiscard]] double point_clearance(Point p, const Obstacles& obs, double radius, double cap, double tau = 0.0);

/// Trajectory clearance: min_j point_clearance(P_j, tau = (j+1) dt) over traj = P_1 ... P_N (or of
/// P_N alone, tau = N dt); dt = 0 keeps every disc where it is.
/// Source: pathref. Spec: sensors2023.dwa.clearance. Pre: traj non-empty; dt >= 0; as point_clearance.
[[nodiscard]] double trajectory_clearance(std::span<const Pose> traj, const Obstacles& obs, double radius,
                                          double cap, ClearanceAt at = ClearanceAt::trajectory, double dt = 0.0);

// ---------------------------------------------------------------- control step
struct DwaParams {
  Limits limits;
  Weights weights;
  double dt = 0.1;
  double horizon = 3.0;
  double v_res = 0.01;
  double w_res = 0.017453292519943295;  ///< 1 deg/s
  double clearance_cap = 1.0;
  double radius = 0.3;
  Evaluation evaluation = Evaluation::normalised;
  ClearanceAt clearance_at = ClearanceAt::trajectory;
  HeadingWrap heading_wrap = HeadingWrap::on;
  WindowUpper window_upper = WindowUpper::include;
  Admissible admissible = Admissible::both;
  MotionOrder motion_order = MotionOrder::heading_last;
  bool predict_movers = true;  ///< obstacle_prediction = linear (default) | static
};

struct StepResult {
  double v = 0.0;
  double w = 0.0;
  bool braked = false;
  std::int64_t candidates = 0;
  std::int64_t valid = 0;
  std::int64_t best = -1;
  double score = 0.0;  ///< the chosen candidate's score (0 when braked)
};

/// One control step (composition of Eq. 9-14): window, candidates in candidate order, predicted
/// trajectories, clearance, heading toward `target`, admissibility, evaluation; brake when no
/// candidate is valid. Source: sensors2023, Sec. 3.1-3.2. Spec: sensors2023.dwa.step.
/// Pre: as the composed rules (DomainError). Golden: golden/sensors2023-dwa/sensors2023.dwa.step.json
[[nodiscard]] StepResult control_step(Pose p, double v_c, double w_c, Point target, const Obstacles& obs,
                                      const DwaParams& prm);

// ---------------------------------------------------------------- following
/// Key nodes of a global path: its first cell, every cell where the direction of travel changes,
/// and its last cell (consecutive duplicates removed first); as cell centres.
/// Source: sensors2023, Sec. 3.3 ("Extract the key nodes in the global path"). Spec: sensors2023.dwa.follow.
/// Pre: path non-empty (DomainError).
[[nodiscard]] std::vector<grid::Cell> key_nodes(std::span<const grid::Cell> path);

/// Target points of the traditional A*+DWA fusion (reading `heading_target = waypoint`): the global
/// path's polyline through `nodes` divided segment by segment into n = max(1, ceil(L/spacing - 1e-9))
/// equal parts (L the segment length), the nodes themselves kept exactly: W = N_0, then for every
/// segment (N_i, N_{i+1}) and j = 1 .. n the point N_i + ((j/n)(N_{i+1} - N_i)) (j = n: N_{i+1}).
/// A segment of length 0 (consecutive equal nodes) adds nothing. With spacing one cell edge the
/// waypoints of a grid path are its cells' centres (diagonal steps get their midpoints).
/// Source: sensors2023, Sec. 3.3 ("the target points of path of DWA algorithm are proposed by the
/// global path"); pathref. Spec: sensors2023.dwa.follow.
/// Pre: nodes non-empty and finite, spacing finite > 0, at most 10^6 points (checked before
/// allocating) (DomainError). Golden: golden/sensors2023-dwa/sensors2023.dwa.follow.json
[[nodiscard]] std::vector<Point> path_waypoints(std::span<const Point> nodes, double spacing);

struct FollowParams {
  double reach = 1.0;
  double blocked_timeout = 3.0;
  double key_timeout = 30.0;
};
struct FollowState {
  std::int64_t k = 0;
  double since = 0.0;
  double blocked_for = 0.0;
};
enum class SkipReason { none, blocked, timeout };
[[nodiscard]] std::string_view to_string(SkipReason r) noexcept;
struct FollowUpdate {
  FollowState state;
  std::int64_t switched = 0;  ///< key nodes reached in this update
  SkipReason skipped = SkipReason::none;
};
/// The switching and skipping rule: (1) while k < m and |p - K_k| <= reach: k++, since = t,
/// blocked_for = 0; (2) if k < m: blocked_for += dt if current_blocked else 0; skip (k++, reset) if
/// blocked_for >= blocked_timeout (blocked) or t - since >= key_timeout (timeout). blocked[i] says
/// whether key node i is blocked now (only the current one after step (1) is read).
/// Source: sensors2023, Sec. 3.3; pathref. Spec: sensors2023.dwa.follow.
/// Pre: keys non-empty, blocked.size() == keys.size(), 0 <= s.k < size, finite, dt, reach,
/// timeouts > 0 (DomainError).
/// Golden: golden/sensors2023-dwa/sensors2023.dwa.follow.json
[[nodiscard]] FollowUpdate follow_update(FollowState s, Point p, std::span<const Point> keys, double t,
                                         double dt, const FollowParams& prm,
                                         std::span<const std::uint8_t> blocked);

// ---------------------------------------------------------------- obstacles, collision, turns
struct Waypoint {
  double t = 0.0;
  Point q;
};
/// Position of a moving obstacle on its timed piecewise-linear waypoints (clamped before the first
/// and after the last). Source: sensors2023, Sec. 4; pathref. Spec: sensors2023.sim.obstacles.
/// Pre: non-empty, times strictly increasing, finite (DomainError).
/// Golden: golden/sensors2023-dwa/sensors2023.sim.obstacles.json
[[nodiscard]] Point obstacle_position(std::span<const Waypoint> wps, double t);

/// A moving obstacle: disc of radius r on waypoints.
struct Mover {
  double r = 0.4;
  std::vector<Waypoint> waypoints;
};

/// The step clearance of a robot moving linearly from a (time t0) to b (time t1): the minimum over
/// the step of the surface distance minus radius to the map's blocked cells (outside = blocked),
/// the temporary cells present during the step, and the movers (split at their waypoint times);
/// capped at 10 m. Negative: a collision. Source: pathref. Spec: sensors2023.sim.collision.
/// Pre: finite, t0 < t1, radius >= 0, g set (DomainError).
/// Golden: golden/sensors2023-dwa/sensors2023.sim.collision.json
[[nodiscard]] double step_clearance(Point a, Point b, double t0, double t1, double radius,
                                    const grid::Grid& g, std::span<const grid::Cell> temporary,
                                    std::span<const Mover> movers);

/// Segment-to-closed-square distance: 0 if the segment meets the square, else the minimum of the
/// four segment-edge distances. Source: pathref. Spec: sensors2023.sim.collision.
[[nodiscard]] double segment_cell_distance(Point a, Point b, grid::Cell c) noexcept;

struct TurnParams {
  double ds = 1.0;  ///< one cell edge
  double delta = 0.04363323129985824;  ///< 2.5 deg
  double theta = 0.3490658503988659;   ///< 20 deg
};
/// Turns of a continuous track (spec sensors2023.sim.turns): resample at ds, chord headings,
/// wrapped changes; a turn is a maximal same-sign run of |change| >= delta whose sum reaches theta.
/// Source: pathref. Spec: sensors2023.sim.turns. Pre: finite, ds > 0, 0 < delta <= theta
/// (DomainError). Golden: golden/sensors2023-dwa/sensors2023.sim.turns.json
[[nodiscard]] std::int64_t count_turns(std::span<const Point> track, const TurnParams& prm);

/// Length of a polyline: sum of sqrt((dx dx) + (dy dy)) in order. Spec: sensors2023.sim.turns.
[[nodiscard]] double track_length(std::span<const Point> track) noexcept;

}  // namespace pathref::dwa
