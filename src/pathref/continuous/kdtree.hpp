#pragma once
/// \file kdtree.hpp
/// Points in the continuous plane and pathref's own small 2-d tree for the nearest-node query of
/// sampling planners (Cin et al. 2021, Algorithm 1 line 4, `Near`), doi:10.1155/2021/8025730.
/// Insertion-ordered (no rebalancing: RRT inserts points online, in random order), exact in the
/// sense that it returns the same node as the brute-force scan, ties included.
/// Spec: spec/cin2021-srrt.md r[cin2021.srrt.nearest]
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "pathref/geometry/vec2.hpp"

namespace pathref::continuous {

/// A point of the plane (world units, y up): the project-wide plane point (geometry/vec2.hpp).
using Vec2 = geometry::Vec2;

/// Squared Euclidean distance (b.x - a.x)^2 + (b.y - a.y)^2 in binary64, in that order of
/// operations: dx = b.x - a.x, dy = b.y - a.y, dx*dx + dy*dy. Spec: cin2021.srrt.nearest.
[[nodiscard]] inline double squared_distance(Vec2 a, Vec2 b) noexcept {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  return dx * dx + dy * dy;
}

/// The nearest point by brute force: the index k minimising (squared_distance(points[k], q), k)
/// lexicographically, i.e. the smallest index among equally near points.
/// Spec: cin2021.srrt.nearest. Pre: points non-empty (DomainError).
[[nodiscard]] std::size_t nearest_brute_force(std::span<const Vec2> points, Vec2 q);

/// A 2-d tree over points added one at a time; the splitting axis alternates x, y, x, ... with
/// depth, a point equal to the splitting coordinate goes right. nearest() returns exactly what
/// nearest_brute_force returns on the points in insertion order (same tie rule), visiting a
/// subtree only when its squared distance bound is <= the best so far (the bound is computed
/// with the same rounding and is never larger than a true squared distance in it).
/// Spec: cin2021.srrt.nearest.
class KdTree {
 public:
  /// Adds a point; its index is the number of points before it.
  void insert(Vec2 p);
  /// Pre: size() >= 1 (DomainError).
  [[nodiscard]] std::size_t nearest(Vec2 q) const;
  [[nodiscard]] std::size_t size() const noexcept { return points_.size(); }
  [[nodiscard]] const std::vector<Vec2>& points() const noexcept { return points_; }

 private:
  struct Node {
    std::int32_t left = -1;
    std::int32_t right = -1;
  };
  std::vector<Vec2> points_;
  std::vector<Node> nodes_;  ///< parallel to points_
};

}  // namespace pathref::continuous
