#pragma once
/// \file encounter.hpp
/// The collision test of Han's Figure 5: the robot's planned motion over a horizon against a moving
/// obstacle's RLS-predicted motion over the same horizon, classified as no intersection (go on),
/// side collision (wait) or frontal collision (A* to a local target). Plus the planar geometry it
/// needs (segment distances, written out on scalars in a pinned order) and the pieces of the
/// frontal detour (cells swept by a predicted obstacle, the local target on the global path).
/// Source: Han (IJACSA), Sec. III.B, Fig. 5 ("A, B and F": no intersection; "C and D": side;
/// frontal: local target point), Fig. 6 (IACO-A*), Fig. 8. No DOI in the local text.
/// Spec: spec/han-sim.md (han.collision.classify, han.sim.detour)
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "pathref/equations/rls.hpp"
#include "pathref/geometry/segment_distance.hpp"
#include "pathref/geometry/vec2.hpp"
#include "pathref/grid/grid.hpp"

namespace pathref::sim {

/// A point or vector in metres (map frame: x right, y up; cell (x, y) has its centre at
/// (x + 0.5, y + 0.5) with 1 m cells, rule grid.coord).
using Vec2 = geometry::Vec2;  // the project-wide plane point (geometry/vec2.hpp)

/// Centre of a cell with 1 m cells: (x + 0.5, y + 0.5). Spec: han.sim.step (grid.coord).
[[nodiscard]] Vec2 centre(grid::Cell c) noexcept;

// The planar distances of Fig. 5's test live in geometry (geometry/segment_distance.hpp), so the
// dynamic window's equations can use them without reaching up into the simulator.
using geometry::point_ray_distance;
using geometry::point_segment_distance;
using geometry::segment_distance;

/// The three outcomes of Fig. 5.
enum class Encounter { none, side, frontal };
[[nodiscard]] std::string_view to_string(Encounter e) noexcept;

/// The classification and the quantities it was decided from.
struct Classification {
  Encounter kind = Encounter::none;
  double distance = 0.0;     ///< min distance between the robot polyline and the obstacle segment
  std::int64_t piece = -1;   ///< the first robot piece attaining it (0-based)
  double cos_angle = 0.0;    ///< cos of the angle between that piece and the obstacle motion (0 if static)
  bool obstacle_static = false;  ///< the predicted segment has zero length
  /// point_ray_distance(robot[0], p, q) < clearance: the robot stands on the obstacle's whole
  /// future path (the ray from p through q, beyond the horizon). Reported for information; the
  /// simulation's decisions use the timed margins of han.sim.safety instead.
  bool robot_inside = false;
};

/// cos 135 deg = -sqrt(2)/2, the default threshold between side and frontal.
inline constexpr double default_frontal_cos = -0.70710678118654757;  // -fl(sqrt 2)/2

/// Han Fig. 5: the robot's planned polyline over the horizon (robot[0] = its position) against the
/// obstacle's predicted segment [p, q] over the same horizon. d = min over pieces k of
/// segment_distance(robot[k], robot[k+1], p, q) (first k attaining the minimum). d >= clearance:
/// none. Otherwise: frontal if the obstacle is static (p == q) or if u.v <= (frontal_cos * |u|) * |v|
/// (u = robot[k+1] - robot[k], v = q - p, dot = (u.x*v.x) + (u.y*v.y), norms sqrt((x*x) + (y*y))),
/// i.e. the motions make an angle >= 135 deg by default; else side.
/// Source: Han (IJACSA), Sec. III.B, Fig. 5. Spec: han.collision.classify.
/// Pre: robot.size() >= 2, consecutive points distinct; all finite; clearance finite > 0;
/// -1 <= frontal_cos <= 1 (DomainError).
/// Post: symmetric under mirroring both inputs about any axis; kind == none iff distance >= clearance.
/// Golden: golden/han-sim/han.collision.classify.json
[[nodiscard]] Classification classify(std::span<const Vec2> robot, Vec2 p, Vec2 q, double clearance,
                                      double frontal_cos = default_frontal_cos);

/// The cells a predicted obstacle segment [p, q] blocks for the frontal detour: every cell whose
/// centre is at distance < clearance + sqrt(2)/2 from [p, q] (the sqrt(2)/2 margin keeps every
/// chord between two free neighbouring centres at distance >= clearance from the segment).
/// Listed by increasing cell index. Source: pathref. Spec: han.sim.detour.
/// Pre: finite inputs, clearance > 0 (DomainError).
[[nodiscard]] std::vector<grid::Cell> swept_cells(const grid::Grid& g, Vec2 p, Vec2 q,
                                                  double clearance);

/// The cells an obstacle's whole future path blocks for an evasion (han.sim.evade): every cell whose
/// centre is at distance < clearance + sqrt(2)/2 from the ray from p through q
/// (point_ray_distance; p == q: the point p). Listed by increasing cell index.
/// Source: pathref. Spec: han.sim.evade. Pre: finite inputs, clearance > 0 (DomainError).
[[nodiscard]] std::vector<grid::Cell> swept_ray_cells(const grid::Grid& g, Vec2 p, Vec2 q, double clearance);

/// The local target of a frontal detour: the global-path index just after the last blocked cell at
/// or after `from` (blocked[i] for global_path[i]); `from` itself when none is blocked; -1 when the
/// goal (the last cell) is blocked. Source: Han (IJACSA), Sec. IV ("generates local target points");
/// pathref. Spec: han.sim.detour. Pre: blocked.size() == path size; 0 <= from < size (DomainError).
[[nodiscard]] std::int64_t local_target(std::span<const std::uint8_t> blocked, std::int64_t from);

/// The point at arc length L along the polyline pts[0] ... pts[m] (piece lengths
/// sqrt((dx*dx) + (dy*dy)) in order): on the piece k where acc_k <= L <= acc_k + len_k (the first
/// such), pts[k] + ((L - acc_k) / len_k) * (pts[k+1] - pts[k]) componentwise; pts[0] for L <= 0
/// and pts[m] beyond the end (and for a one-point polyline).
/// Source: pathref. Spec: han.sim.safety. Pre: pts non-empty (DomainError).
[[nodiscard]] Vec2 polyline_point(std::span<const Vec2> pts, double L);

/// The two predicted margins of han.sim.safety against one obstacle over the horizon.
struct Margins {
  double wait = 0.0;         ///< min_j |pts[0] - o(s_j)|: the robot stays where it is
  double go = 0.0;           ///< min_j |R(s_j) - o(s_j)|: the robot drives along pts from speed v0
  /// The driving robot still closes in on the obstacle at the end of the horizon: the last sampled
  /// distance |R(s_J) - o(s_J)| is smaller than the one before (false with a single sample).
  bool go_closing = false;
  std::int64_t samples = 0;  ///< number of sample times s_j
};

/// Han's rules with a time check (pathref's addition, spec han.sim.safety): sample times
/// s_j = double(j) * dt for j = 0, 1, ... while s_j <= horizon; the obstacle's predicted position
/// o(s_j) = rls::position(m, tau + s_j) (Eq. 9 with the current RLS estimate, tau the RLS clock
/// now); the robot at R(s_j) = polyline_point(pts, d_j), d_0 = 0, d_j = motion_step(v0, s_j,
/// v_max, accel).distance (han.sim.motion from the current speed, no stop); distances
/// sqrt((dx*dx) + (dy*dy)). pts is the robot's path ahead from its position pts[0], ending where it
/// would stop (the goal, a refuge) or at the end of the lookahead.
/// Source: pathref (Han, Sec. III.B, describes no timing). Spec: han.sim.safety.
/// Pre: pts non-empty, finite; dt, horizon, v_max, accel finite > 0; 0 <= v0 <= v_max; tau finite
/// (DomainError). Golden: golden/han-sim/han.sim.safety.json
[[nodiscard]] Margins safety_margins(std::span<const Vec2> pts, double v0, double v_max, double accel,
                                     double dt, double horizon, const rls::LinearMotion& m, double tau);

/// A start of the refuge search: a cell and the arc length the robot needs to reach it.
struct RefugeSource {
  grid::Cell cell;
  double cost = 0.0;
};

/// The result of find_refuge.
struct Refuge {
  bool found = false;
  std::vector<grid::Cell> path;  ///< source cell ... refuge (adjacent cells), empty if !found
  std::int64_t source = -1;      ///< index into the sources of the path's first cell
  double cost = 0.0;             ///< the source's cost plus the step costs, summed in path order
};

/// The nearest refuge (spec han.sim.evade): multi-source Dijkstra on the free cells of g under
/// `policy` (moves grid::neighbours, costs grid::step_cost), started from every source with its
/// cost (a cell listed twice keeps the lower cost, the first on ties), the queue ordered by
/// (g, cell index), a parent replaced only on a strictly smaller g; the first settled cell with
/// band[index] == 0 is the refuge. Cells of the band may be crossed.
/// Blocked sources are skipped (g is the map with the obstacles' bodies blocked, han.sim.evade).
/// Source: pathref. Spec: han.sim.evade. Pre: band.size() == cell count; sources non-empty, in
/// bounds, costs finite >= 0 (DomainError). Golden: golden/han-sim/han.sim.evade.json
[[nodiscard]] Refuge find_refuge(const grid::Grid& g, std::span<const RefugeSource> sources,
                                 std::span<const std::uint8_t> band, grid::CornerPolicy policy);

}  // namespace pathref::sim
