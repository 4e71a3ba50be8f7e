// Properties of the continuous planners (spec/cin2021-srrt.md): the k-d tree equals brute force
// (ties included); the exact collision test agrees with an independent binary64 distance oracle
// wherever that oracle is sure; steering; every RRT tree edge is free and at most delta long;
// Algorithm 2 is never longer and never invalid.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pathref/io/scene_json.hpp"
#include "pathref/continuous/kdtree.hpp"
#include "pathref/continuous/rrt.hpp"
#include "pathref/continuous/srrt.hpp"
#include "pathref/geometry/obstacles.hpp"
#include "pathref/geometry/scene.hpp"
#include "pathref/rng/mt19937.hpp"
#include "support/reach.hpp"

using namespace pathref;
using namespace pathref::continuous;
using geometry::ObstacleMap;

namespace {

/// Axis-aligned rectangles with integer-quarter corners in a 12 x 12 world, r in {0, 0.1, 0.25}.
struct RectScene {
  std::vector<std::array<int, 4>> rects;  ///< x0, y0, x1, y1 in quarters
  int r_choice = 0;
};

rc::Gen<RectScene> gen_rect_scene(int max_rects) {
  return rc::gen::exec([max_rects] {
    RectScene s;
    const int n = *rc::gen::inRange(0, max_rects + 1);
    for (int i = 0; i < n; ++i) {
      const int x0 = *rc::gen::inRange(0, 44), y0 = *rc::gen::inRange(0, 44);
      const int w = *rc::gen::inRange(1, 12), h = *rc::gen::inRange(1, 12);
      s.rects.push_back({x0, y0, std::min(48, x0 + w), std::min(48, y0 + h)});
    }
    s.r_choice = *rc::gen::inRange(0, 3);
    return s;
  });
}

const char* r_text(int c) { return c == 0 ? "0" : c == 1 ? "0.1" : "0.25"; }
double r_value(int c) { return c == 0 ? 0.0 : c == 1 ? 0.1 : 0.25; }

geometry::Scene to_scene(const RectScene& rs) {
  std::string polys = "[";
  for (std::size_t i = 0; i < rs.rects.size(); ++i) {
    const auto& r = rs.rects[i];
    const auto q = [](int v) { return std::to_string(v / 4) + "." + std::to_string((v % 4) * 25); };
    polys += std::string(i ? ", " : "") + "{\"vertices\": [[" + q(r[0]) + ", " + q(r[1]) + "], [" + q(r[2]) + ", " +
             q(r[1]) + "], [" + q(r[2]) + ", " + q(r[3]) + "], [" + q(r[0]) + ", " + q(r[3]) + "]]}";
  }
  polys += "]";
  const std::string text = std::string("{\"format\": \"pathref-scene 1\", \"origin\": [0, 0], \"width\": 12, "
                                       "\"height\": 12, \"cell_size\": 1, \"radius\": ") +
                           r_text(rs.r_choice) + ", \"margin\": 0, \"polygons\": " + polys +
                           ", \"start\": [0, 0], \"goal\": [1, 0]}";
  return io::parse_scene_json(text, "p.json");
}

/// Independent oracle in binary64: distance from segment [a, b] to the closed axis-aligned
/// rectangle, by sampling nothing: 0 if they intersect (Liang-Barsky clip), else the minimum of
/// the four point-segment distances between endpoints and sides.
double pt_seg(Vec2 p, Vec2 a, Vec2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double L = dx * dx + dy * dy;
  double t = L == 0.0 ? 0.0 : ((p.x - a.x) * dx + (p.y - a.y) * dy) / L;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(a.x + t * dx - p.x, a.y + t * dy - p.y);
}
double seg_rect_distance(Vec2 a, Vec2 b, double x0, double y0, double x1, double y1) {
  // clip
  double t0 = 0.0, t1 = 1.0;
  const double dx = b.x - a.x, dy = b.y - a.y;
  bool hit = true;
  const auto clip = [&](double p, double q) {
    if (p == 0.0) {
      if (q < 0.0) hit = false;
      return;
    }
    const double t = q / p;
    if (p < 0.0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
  };
  clip(-dx, a.x - x0);
  clip(dx, x1 - a.x);
  clip(-dy, a.y - y0);
  clip(dy, y1 - a.y);
  if (hit && t0 <= t1) return 0.0;
  const Vec2 c[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  double d = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i) {
    d = std::min(d, pt_seg(c[i], a, b));
    d = std::min(d, pt_seg(i % 2 ? a : b, c[i], c[(i + 1) % 4]));
    d = std::min(d, pt_seg(i % 2 ? b : a, c[i], c[(i + 1) % 4]));
  }
  return d;
}

rc::Gen<Vec2> gen_point() {
  return rc::gen::map(rc::gen::pair(rc::gen::inRange(0, 12001), rc::gen::inRange(0, 12001)),
                      [](std::pair<int, int> p) { return Vec2{p.first / 1000.0, p.second / 1000.0}; });
}

}  // namespace

TEST_CASE("prop_kdtree_equals_brute_force") {
  rc::prop("KdTree::nearest == nearest_brute_force, ties included", [] {
    // coarse coordinates make exact ties and duplicates common
    const auto pts = *rc::gen::nonEmpty(rc::gen::container<std::vector<std::pair<int, int>>>(
        rc::gen::pair(rc::gen::inRange(-6, 7), rc::gen::inRange(-6, 7))));
    KdTree t;
    std::vector<Vec2> v;
    for (const auto& [x, y] : pts) {
      t.insert({x * 0.5, y * 0.5});
      v.push_back({x * 0.5, y * 0.5});
    }
    for (int k = 0; k < 20; ++k) {
      const Vec2 q{*rc::gen::inRange(-16, 17) * 0.25, *rc::gen::inRange(-16, 17) * 0.25};
      RC_ASSERT(t.nearest(q) == nearest_brute_force(v, q));
    }
  });
}

TEST_CASE("prop_collision_agrees_with_float_oracle") {
  rc::prop("segment_free is decided as the binary64 distance says wherever it is 1e-9 from r", [] {
    const RectScene rs = *gen_rect_scene(6);
    const ObstacleMap m = ObstacleMap::from_scene(to_scene(rs));
    const double r = r_value(rs.r_choice);
    for (int k = 0; k < 10; ++k) {
      const Vec2 a = *gen_point(), b = *gen_point();
      double d = std::numeric_limits<double>::infinity();
      for (const auto& q : rs.rects)
        d = std::min(d, seg_rect_distance(a, b, q[0] / 4.0, q[1] / 4.0, q[2] / 4.0, q[3] / 4.0));
      const bool free = m.segment_free(a, b);
      if (d > r + 1e-9) RC_ASSERT(free);
      if (d < r - 1e-9) RC_ASSERT(!free);
      if (std::isfinite(d)) RC_ASSERT(std::abs(m.segment_distance(a, b) - d) <= 1e-9);
    }
  });
}

TEST_CASE("prop_steer_step_and_direction") {
  rc::prop("steer moves at most delta towards the target, exactly delta when farther (clip)", [] {
    const Vec2 n = *gen_point(), t = *gen_point();
    const double delta = *rc::gen::inRange(1, 5000) / 1000.0;
    const Vec2 x = steer(n, t, delta);
    const double d = std::sqrt(squared_distance(n, t));
    if (d <= delta) {
      RC_ASSERT(x == t);
    } else {
      RC_ASSERT(std::abs(std::sqrt(squared_distance(n, x)) - delta) <= 1e-12 * (1.0 + delta));
      // collinear and on the target's side
      const double cross = (x.x - n.x) * (t.y - n.y) - (x.y - n.y) * (t.x - n.x);
      RC_ASSERT(std::abs(cross) <= 1e-9 * (1.0 + d * delta));
      RC_ASSERT((x.x - n.x) * (t.x - n.x) + (x.y - n.y) * (t.y - n.y) > 0.0);
    }
  });
}

TEST_CASE("prop_rrt_tree_valid_and_shortcut_never_longer") {
  pathref::testing::Reach found;
  rc::prop("every tree edge is free and <= delta; Algorithm 2 keeps 0..m, free, never longer", [&found] {
    const RectScene rs = *gen_rect_scene(5);
    const ObstacleMap m = ObstacleMap::from_scene(to_scene(rs));
    const Vec2 s = *gen_point(), g = *gen_point();
    RC_PRE(m.point_free(s) && m.point_free(g) && !(s == g));
    RrtParams p;
    p.max_iterations = 1500;
    p.variant = *rc::gen::element(RrtVariant::paper, RrtVariant::plain, RrtVariant::ompl);
    p.near = *rc::gen::element(NearTo::sample, NearTo::target);
    p.bias = *rc::gen::element(BiasBranch::lt, BiasBranch::gt);
    const auto seed = *rc::gen::inRange<std::uint32_t>(0, 1000000);
    rng::Stream st(seed);
    const RrtResult r = rrt(m, s, g, p, st);
    RC_ASSERT(r.nodes.front() == s);
    for (std::size_t k = 1; k < r.nodes.size(); ++k) {
      const auto par = r.parent[k];
      RC_ASSERT(par >= 0 && static_cast<std::size_t>(par) < k);
      const Vec2 a = r.nodes[static_cast<std::size_t>(par)];
      RC_ASSERT(m.segment_free(a, r.nodes[k]));
      RC_ASSERT(squared_distance(a, r.nodes[k]) <= p.delta * p.delta * (1.0 + 1e-12));
    }
    rng::Stream st2(seed);
    RC_ASSERT(rrt(m, s, g, p, st2).nodes == r.nodes);  // deterministic
    RC_TAG(r.found ? "found" : "not found");
    if (!found.hit(r.found)) return;
    RC_ASSERT(r.nodes[r.path.back()] == g);
    std::vector<Vec2> raw;
    for (const auto k : r.path) raw.push_back(r.nodes[k]);
    const auto kept = shortcut(m, raw);
    RC_ASSERT(kept.front() == 0u);
    RC_ASSERT(kept.back() == raw.size() - 1);
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < kept.size(); ++i) {
      if (i > 0) RC_ASSERT(kept[i] > kept[i - 1]);
      out.push_back(raw[kept[i]]);
      if (i > 0) RC_ASSERT(m.segment_free(out[i - 1], out[i]));
    }
    RC_ASSERT(polyline_length(out) <= polyline_length(raw) * (1.0 + 1e-12));
  });
  pathref::testing::require_reach(found, 0.7, "RRT found the goal, Algorithm 2 checked");
}
