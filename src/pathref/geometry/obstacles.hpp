#pragma once
/// \file obstacles.hpp
/// Exact collision checking for planners in the continuous plane (Cin et al. 2021 S-RRT, Sec. 4,
/// doi:10.1155/2021/8025730; the obstacles inflated by robot radius + margin as in Shi et al.
/// 2022 Sec. 3): a point or a segment is free iff it lies in the world rectangle and its exact
/// Euclidean distance to every closed obstacle polygon is > r. No sampling at a resolution.
/// CGAL-free header; implemented with CGAL's Epeck kernel in pathref_geometry
/// (src/geometry_cgal/obstacles_cgal.cpp), the only translation unit that includes CGAL for it.
/// Spec: spec/cin2021-srrt.md r[cin2021.srrt.collision]
#include <cstddef>
#include <memory>
#include <vector>

#include "pathref/geometry/collision.hpp"
#include "pathref/geometry/scene.hpp"
#include "pathref/grid/grid.hpp"

namespace pathref::geometry {

// Vec2 is geometry::Vec2 (geometry/vec2.hpp); continuous::Vec2 is the same type.

/// Obstacle polygons (exact vertices) with an exact inflation radius r, in a world rectangle.
/// Immutable; copies share the prepared geometry.
class ObstacleMap final : public CollisionChecker {
 public:
  /// The scene's polygons (validate_polygons runs: DomainError for degenerate or self-intersecting
  /// ones), r = radius + margin, world [ox, ox + W s] x [oy, oy + H s].
  [[nodiscard]] static ObstacleMap from_scene(const Scene& scene);
  /// A grid map: each blocked cell (x, y) is the closed square [x, x+1] x [y, y+1] (cell units,
  /// origin 0; horizontal runs of blocked cells are merged into one rectangle, which changes no
  /// distance), world [0, W] x [0, H], r = `radius` (exact decimal >= 0, DomainError otherwise).
  [[nodiscard]] static ObstacleMap from_grid(const grid::Grid& map, const Decimal& radius);

  /// Sign of dist(segment [a, b], polygon k)^2 - r^2, exact: -1 closer than r, 0 exactly r,
  /// +1 farther. a == b is a point. Spec: cin2021.srrt.collision. Pre: k < polygon_count(),
  /// finite coordinates (DomainError).
  [[nodiscard]] int compare_segment(std::size_t k, Vec2 a, Vec2 b) const;
  /// In the closed world rectangle and compare_segment(k, p, p) > 0 for every k.
  /// Spec: cin2021.srrt.collision.
  [[nodiscard]] bool point_free(Vec2 p) const override;
  /// Both endpoints in the world rectangle (it is convex) and compare_segment(k, a, b) > 0 for
  /// every k; candidates are found through a bucket grid over the r-expanded edge boxes (exact:
  /// a box test only ever skips edges farther than r). Spec: cin2021.srrt.collision.
  [[nodiscard]] bool segment_free(Vec2 a, Vec2 b) const override;
  /// Exact minimum distance from p to the obstacles (closed polygons, without r), rounded to the
  /// nearest double; +inf without obstacles. For reports (clearance of the raw and shortcut paths).
  [[nodiscard]] double point_distance(Vec2 p) const;
  /// Exact minimum distance from the segment to the obstacles, rounded; +inf without obstacles.
  [[nodiscard]] double segment_distance(Vec2 a, Vec2 b) const;
  /// segment_distance (the CollisionChecker interface). Spec: cin2021.srrt.metrics.
  [[nodiscard]] double segment_clearance(Vec2 a, Vec2 b) const override { return segment_distance(a, b); }
  [[nodiscard]] Vec2 lower() const override;
  [[nodiscard]] Vec2 upper() const override;
  [[nodiscard]] std::size_t polygon_count() const;
  /// The polygons' vertices rounded to doubles (drawing only).
  [[nodiscard]] const std::vector<std::vector<Vec2>>& polygons() const;
  /// r rounded to a double (reports only).
  [[nodiscard]] double radius() const;
  /// radius() (the CollisionChecker interface). Spec: cin2021.srrt.curve.
  [[nodiscard]] double inflation() const override { return radius(); }

  struct Impl;

 private:
  explicit ObstacleMap(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
  std::shared_ptr<const Impl> impl_;
};

/// Makes the cin2021 S-RRT rules (cin2021.srrt.*, cin2021.alg1, cin2021.alg2) available to
/// `pathref eval`, the golden runner and `pathref golden regenerate` (rules::add_extension_module).
/// Idempotent; call before the first rules::registry().
void install_srrt_rules();

}  // namespace pathref::geometry
