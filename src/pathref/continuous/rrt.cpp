#include "pathref/continuous/rrt.hpp"

#include <cmath>
#include <string>

#include "pathref/core/error.hpp"
#include "pathref/rng/mt19937.hpp"

namespace pathref::continuous {

Vec2 steer(Vec2 near, Vec2 target, double delta, bool clip) {
  if (!(std::isfinite(delta) && delta > 0.0)) throw DomainError("steer: delta must be > 0 and finite");
  const double dx = target.x - near.x;
  const double dy = target.y - near.y;
  const double d = std::sqrt(dx * dx + dy * dy);
  if (d == 0.0) return near;
  if (clip && d <= delta) return target;
  const double s = delta / d;
  return Vec2{near.x + s * dx, near.y + s * dy};
}

namespace {
template <class E>
E parse_option(std::string_view s, const char* key, std::initializer_list<std::pair<const char*, E>> options) {
  std::string allowed;
  for (const auto& [name, value] : options) {
    if (s == name) return value;
    allowed += (allowed.empty() ? "" : ", ") + std::string(name);
  }
  throw UsageError(std::string(key) + " must be one of " + allowed + ", got '" + std::string(s) + "'");
}
}  // namespace

BiasBranch parse_bias(std::string_view s) {
  return parse_option<BiasBranch>(s, "bias", {{"lt", BiasBranch::lt}, {"gt", BiasBranch::gt}});
}
NearTo parse_near(std::string_view s) {
  return parse_option<NearTo>(s, "near", {{"sample", NearTo::sample}, {"target", NearTo::target}});
}
RrtVariant parse_variant(std::string_view s) {
  return parse_option<RrtVariant>(
      s, "variant", {{"paper", RrtVariant::paper}, {"plain", RrtVariant::plain}, {"ompl", RrtVariant::ompl}});
}
SampleMode parse_sample(std::string_view s) {
  return parse_option<SampleMode>(s, "sample", {{"rect", SampleMode::rect}, {"free", SampleMode::free}});
}
std::string_view to_string(BiasBranch b) noexcept { return b == BiasBranch::lt ? "lt" : "gt"; }
std::string_view to_string(NearTo n) noexcept { return n == NearTo::sample ? "sample" : "target"; }
std::string_view to_string(RrtVariant v) noexcept {
  return v == RrtVariant::paper ? "paper" : v == RrtVariant::plain ? "plain" : "ompl";
}
std::string_view to_string(SampleMode m) noexcept { return m == SampleMode::rect ? "rect" : "free"; }

namespace {

/// Tree under construction: nodes, parents, the k-d tree over the nodes.
struct Tree {
  KdTree kd;
  std::vector<std::int64_t> parent;
  std::size_t add(Vec2 p, std::int64_t par) {
    kd.insert(p);
    parent.push_back(par);
    return kd.size() - 1;
  }
};

}  // namespace

RrtResult rrt(const CollisionChecker& map, Vec2 start, Vec2 goal, const RrtParams& params, rng::Stream& stream) {
  const double delta = params.delta;
  if (!(std::isfinite(delta) && delta > 0.0)) throw DomainError("rrt: delta must be > 0 and finite");
  if (!(params.goal_probability >= 0.0 && params.goal_probability <= 1.0))
    throw DomainError("rrt: goal_probability must be in [0, 1]");
  if (params.max_iterations < 0) throw DomainError("rrt: max_iterations must be >= 0");
  if (params.max_rejections < 1) throw DomainError("rrt: max_rejections must be >= 1");
  if (!map.point_free(start)) throw DomainError("rrt: the start is not free (outside the world or in an obstacle)");
  if (!map.point_free(goal)) throw DomainError("rrt: the goal is not free (outside the world or in an obstacle)");
  if (start == goal) throw DomainError("rrt: start and goal are the same point");
  const Vec2 lo = map.lower();
  const Vec2 hi = map.upper();
  const double wx = hi.x - lo.x;
  const double wy = hi.y - lo.y;
  const double delta2 = delta * delta;
  const std::uint64_t draws0 = stream.doubles_drawn();

  RrtResult out;
  Tree t;
  t.add(start, -1);

  // The goal test on node k: within delta of the goal and a free final edge.
  const auto reaches_goal = [&](std::size_t k) {
    const Vec2 p = t.kd.points()[k];
    if (p == goal) return true;  // the node is the goal itself (no duplicate node)
    if (squared_distance(p, goal) <= delta2 && map.segment_free(p, goal)) {
      t.add(goal, static_cast<std::int64_t>(k));
      return true;
    }
    return false;
  };
  const auto sample = [&]() {
    for (std::int64_t tries = 0;; ++tries) {
      const double u1 = stream.next_double("rrt sample x");
      const double u2 = stream.next_double("rrt sample y");
      const Vec2 x{lo.x + u1 * wx, lo.y + u2 * wy};
      if (params.sample == SampleMode::rect || map.point_free(x)) return x;
      if (tries + 1 >= params.max_rejections)
        throw DomainError("rrt: sample=free drew " + std::to_string(params.max_rejections) +
                          " points in obstacles in a row (is the free space empty?)");
    }
  };
  const auto goal_chosen = [&](double p) {
    return params.bias == BiasBranch::lt ? p < params.goal_probability : p > params.goal_probability;
  };

  bool found = reaches_goal(0);
  while (!found && out.iterations < params.max_iterations) {
    ++out.iterations;
    if (stream.tracing()) stream.set_context("iteration " + std::to_string(out.iterations));
    Vec2 target;
    std::size_t near = 0;
    switch (params.variant) {
      case RrtVariant::paper: {
        const Vec2 x_rand = sample();
        if (params.near == NearTo::sample) near = t.kd.nearest(x_rand);
        const double p = stream.next_double("rrt goal-bias test (cin2021.alg1)");
        target = goal_chosen(p) ? goal : x_rand;
        if (params.near == NearTo::target) near = t.kd.nearest(target);
        break;
      }
      case RrtVariant::plain: {
        target = sample();
        near = t.kd.nearest(target);
        break;
      }
      case RrtVariant::ompl: {
        const double p = stream.next_double("rrt goal-bias test (cin2021.alg1)");
        target = goal_chosen(p) ? goal : sample();
        near = t.kd.nearest(target);
        break;
      }
    }
    const Vec2 x_near = t.kd.points()[near];
    const Vec2 x_new = steer(x_near, target, delta, params.clip);
    if (x_new == x_near) continue;  // zero step: no edge
    if (!map.segment_free(x_near, x_new)) {
      ++out.rejected_edges;
      continue;
    }
    const std::size_t k = t.add(x_new, static_cast<std::int64_t>(near));
    found = reaches_goal(k);
  }
  out.found = found;
  out.nodes = t.kd.points();
  out.parent = std::move(t.parent);
  out.draws = stream.doubles_drawn() - draws0;
  if (found) out.path = branch(out.parent, out.nodes.size() - 1);
  return out;
}

std::vector<std::size_t> branch(const std::vector<std::int64_t>& parent, std::size_t leaf) {
  require(leaf < parent.size(), "branch: leaf index out of range");
  require(!parent.empty() && parent[0] == -1, "branch: parent[0] must be -1 (the root)");
  std::vector<std::size_t> out;
  std::size_t k = leaf;
  for (;;) {
    out.push_back(k);
    if (k == 0) break;
    const std::int64_t p = parent[k];
    require(p >= 0 && static_cast<std::size_t>(p) < k, "branch: parent links must point to earlier nodes");
    k = static_cast<std::size_t>(p);
  }
  return {out.rbegin(), out.rend()};
}

std::vector<std::size_t> shortcut(const CollisionChecker& map, const std::vector<Vec2>& path) {
  require(!path.empty(), "shortcut: empty path");
  const std::size_t m = path.size() - 1;
  std::vector<std::size_t> out{0};
  std::size_t s = 0;
  while (s != m) {
    std::size_t c = m;
    while (!map.segment_free(path[s], path[c])) {
      --c;
      if (c == s)
        throw DomainError("shortcut: segment " + std::to_string(s) + "-" + std::to_string(s + 1) +
                          " of the input path is not free (not a valid tree branch)");
    }
    out.push_back(c);
    s = c;
  }
  return out;
}

double polyline_length(const std::vector<Vec2>& points) {
  double len = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) len += std::sqrt(squared_distance(points[i - 1], points[i]));
  return len;
}

}  // namespace pathref::continuous
