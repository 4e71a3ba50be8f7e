#include "pathref/continuous/kdtree.hpp"

#include <limits>

#include "pathref/core/error.hpp"

namespace pathref::continuous {

std::size_t nearest_brute_force(std::span<const Vec2> points, Vec2 q) {
  require(!points.empty(), "nearest: the tree has no node");
  std::size_t best = 0;
  double best_d2 = squared_distance(points[0], q);
  for (std::size_t k = 1; k < points.size(); ++k) {
    const double d2 = squared_distance(points[k], q);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = k;
    }
  }
  return best;
}

void KdTree::insert(Vec2 p) {
  const auto idx = static_cast<std::int32_t>(points_.size());
  points_.push_back(p);
  nodes_.push_back(Node{});
  if (idx == 0) return;
  std::int32_t cur = 0;
  int axis = 0;
  for (;;) {
    const Vec2& c = points_[static_cast<std::size_t>(cur)];
    const bool right = axis == 0 ? p.x >= c.x : p.y >= c.y;
    Node& n = nodes_[static_cast<std::size_t>(cur)];
    std::int32_t& next = right ? n.right : n.left;
    if (next < 0) {
      next = idx;
      return;
    }
    cur = next;
    axis ^= 1;
  }
}

std::size_t KdTree::nearest(Vec2 q) const {
  require(!points_.empty(), "nearest: the tree has no node");
  std::size_t best = 0;
  double best_d2 = std::numeric_limits<double>::infinity();
  // Explicit stack of (node, axis, bound): bound is a lower bound on the squared distance from q
  // to every point of the subtree (0 for the near side).
  struct Item {
    std::int32_t node;
    int axis;
    double bound;
  };
  std::vector<Item> stack;
  stack.reserve(64);
  stack.push_back({0, 0, 0.0});
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    if (it.bound > best_d2) continue;
    const auto k = static_cast<std::size_t>(it.node);
    const Vec2& c = points_[k];
    const double d2 = squared_distance(c, q);
    if (d2 < best_d2 || (d2 == best_d2 && k < best)) {
      best_d2 = d2;
      best = k;
    }
    const double diff = it.axis == 0 ? q.x - c.x : q.y - c.y;
    const Node& n = nodes_[k];
    // The far side's points are at least |diff| away along the axis: q left of c (diff < 0):
    // right-subtree points have coordinate >= c > q; q at or right of c: left-subtree points have
    // coordinate < c <= q. Rounding is monotone, so fl(|p - q|) >= fl(|c - q|) = |diff| and the
    // bound diff^2 never exceeds a computed squared distance in that subtree.
    const std::int32_t near = diff < 0.0 ? n.left : n.right;
    const std::int32_t far = diff < 0.0 ? n.right : n.left;
    const double far_b = diff * diff;
    if (far >= 0) stack.push_back({far, it.axis ^ 1, far_b});
    if (near >= 0) stack.push_back({near, it.axis ^ 1, 0.0});
  }
  return best;
}

}  // namespace pathref::continuous
