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

#include "pathref/grid/grid.hpp"

namespace pathref::sim {

/// A point or vector in metres (map frame: x right, y up; cell (x, y) has its centre at
/// (x + 0.5, y + 0.5) with 1 m cells, rule grid.coord).
struct Vec2 {
  double x = 0.0;
  double y = 0.0;
  friend constexpr bool operator==(const Vec2&, const Vec2&) = default;
};

/// Centre of a cell with 1 m cells: (x + 0.5, y + 0.5). Spec: han.sim.step (grid.coord).
[[nodiscard]] Vec2 centre(grid::Cell c) noexcept;

/// Distance from p to the segment [a, b]: with d = b - a, L = (d.x*d.x) + (d.y*d.y); s = 0 if
/// L == 0, else s = clamp((((p.x - a.x)*d.x) + ((p.y - a.y)*d.y)) / L, 0, 1); q = (a.x + (s*d.x),
/// a.y + (s*d.y)); result sqrt(((p.x-q.x)*(p.x-q.x)) + ((p.y-q.y)*(p.y-q.y))).
/// Source: pathref. Spec: han.collision.classify. Pre: none (finite inputs give a finite result).
[[nodiscard]] double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) noexcept;

/// Distance from p to the ray from a through b (the obstacle's whole predicted future path): as
/// point_segment_distance but s is clamped to [0, +inf) only (b == a: the distance to a).
/// Source: pathref. Spec: han.collision.classify. Pre: none.
[[nodiscard]] double point_ray_distance(Vec2 p, Vec2 a, Vec2 b) noexcept;

/// Distance between segments [a, b] and [c, d]: 0 if they cross properly (the orientation signs
/// of c, d about ab differ strictly and those of a, b about cd too), else the minimum of
/// dist(a, cd), dist(b, cd), dist(c, ab), dist(d, ab) in that order.
/// Source: pathref. Spec: han.collision.classify.
[[nodiscard]] double segment_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) noexcept;

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
  bool robot_inside = false;     ///< point_ray_distance(robot[0], p, q) < clearance: the robot is on the obstacle's future path
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

/// The local target of a frontal detour: the global-path index just after the last blocked cell at
/// or after `from` (blocked[i] for global_path[i]); `from` itself when none is blocked; -1 when the
/// goal (the last cell) is blocked. Source: Han (IJACSA), Sec. IV ("generates local target points");
/// pathref. Spec: han.sim.detour. Pre: blocked.size() == path size; 0 <= from < size (DomainError).
[[nodiscard]] std::int64_t local_target(std::span<const std::uint8_t> blocked, std::int64_t from);

}  // namespace pathref::sim
