#pragma once
/// \file collision.hpp
/// What a continuous planner asks of the map (cin2021 S-RRT, Computational Intelligence and
/// Neuroscience 2021, doi:10.1155/2021/8025730; spec r[cin2021.srrt.collision]). Geometry owns
/// the interface (layer 1, docs/architecture.md#layers) so that the clearance of
/// geometry/clearance.hpp and the exact checker geometry::ObstacleMap need nothing from the
/// planners above; continuous::CollisionChecker names the same class.
#include "pathref/geometry/vec2.hpp"

namespace pathref::geometry {

/// Implementations must be exact or conservative; ObstacleMap is exact.
class CollisionChecker {
 public:
  virtual ~CollisionChecker() = default;
  /// True iff the point lies in the world rectangle and outside every inflated obstacle.
  [[nodiscard]] virtual bool point_free(Vec2 p) const = 0;
  /// True iff every point of the closed segment [a, b] is free (a == b: point_free(a)).
  [[nodiscard]] virtual bool segment_free(Vec2 a, Vec2 b) const = 0;
  /// The world rectangle: sampling region of Algorithm 1 (xmin < xmax, ymin < ymax).
  [[nodiscard]] virtual Vec2 lower() const = 0;
  [[nodiscard]] virtual Vec2 upper() const = 0;
  /// Distance from the closed segment to the nearest obstacle (without the inflation r; +inf
  /// without obstacles), for reports. Spec: cin2021.srrt.metrics.
  [[nodiscard]] virtual double segment_clearance(Vec2 a, Vec2 b) const = 0;
  /// The inflation radius r (robot radius + margin) rounded to a double: a point within r of an
  /// obstacle is not free. For reports and the smoothed curve's verdict (spec cin2021.srrt.curve).
  [[nodiscard]] virtual double inflation() const = 0;
};

}  // namespace pathref::geometry
