// Properties of the shared clearance function (spec/curves.md r[curves.clearance]).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "pathref/equations/bspline.hpp"
#include "pathref/geometry/clearance.hpp"
#include "support/generators.hpp"

using pathref::geometry::Vec2;
namespace geo = pathref::geometry;
namespace bs = pathref::bspline;

namespace {

rc::Gen<std::vector<Vec2>> gen_polyline(const pathref::grid::Grid& g, int max_n) {
  const int w = static_cast<int>(g.width());
  const int h = static_cast<int>(g.height());
  return rc::gen::mapcat(rc::gen::inRange(1, max_n + 1), [w, h](int n) {
    return rc::gen::container<std::vector<Vec2>>(
        static_cast<std::size_t>(n),
        rc::gen::map(rc::gen::pair(rc::gen::inRange(-8, 8 * w + 9), rc::gen::inRange(-8, 8 * h + 9)),
                     [](std::pair<int, int> q) { return Vec2{q.first / 8.0, q.second / 8.0}; }));
  });
}

double point_box(Vec2 p, double x0, double y0, double x1, double y1) {
  const double dx = std::max({x0 - p.x, 0.0, p.x - x1});
  const double dy = std::max({y0 - p.y, 0.0, p.y - y1});
  return std::sqrt(dx * dx + dy * dy);
}

/// Oracle: distance of one point to the blocked squares and the border, by brute force.
double point_obstacles(const pathref::grid::Grid& g, Vec2 p, bool border) {
  double d = std::numeric_limits<double>::infinity();
  const double w = static_cast<double>(g.width());
  const double h = static_cast<double>(g.height());
  if (border) d = std::max(0.0, std::min({p.x, w - p.x, p.y, h - p.y}));
  for (std::int64_t y = 0; y < g.height(); ++y)
    for (std::int64_t x = 0; x < g.width(); ++x)
      if (g.blocked({x, y}))
        d = std::min(d, point_box(p, double(x), double(y), double(x) + 1, double(y) + 1));
  return d;
}

}  // namespace

TEST_CASE("prop_clearance_equals_brute_force_over_all_cells") {
  rc::prop("the windowed search finds the same distance as every cell and the border", [] {
    const auto g = *pathref::testing::gen_grid(12, 12, 0.4);
    const auto pts = *gen_polyline(g, 5);
    const bool border = *rc::gen::arbitrary<bool>();
    const auto c = geo::clearance(g, pts, {0.0, 0.0, border});
    double d = std::numeric_limits<double>::infinity();
    const double w = static_cast<double>(g.width());
    const double h = static_cast<double>(g.height());
    const std::size_t pieces = pts.size() == 1 ? 1 : pts.size() - 1;
    for (std::size_t s = 0; s < pieces; ++s) {
      const Vec2 a = pts[s];
      const Vec2 b = pts.size() == 1 ? pts[s] : pts[s + 1];
      if (border) {
        for (const Vec2 q : {a, b}) d = std::min(d, std::max(0.0, std::min({q.x, w - q.x, q.y, h - q.y})));
      }
      for (std::int64_t y = 0; y < g.height(); ++y)
        for (std::int64_t x = 0; x < g.width(); ++x)
          if (g.blocked({x, y}))
            d = std::min(d, geo::segment_box_distance(a, b, double(x), double(y), double(x) + 1,
                                                      double(y) + 1));
    }
    RC_ASSERT(c.distance == d);
    RC_ASSERT(c.lower == c.distance);
    RC_ASSERT(c.upper == c.distance);
  });
}

TEST_CASE("prop_clearance_segment_box_matches_dense_sampling") {
  rc::prop("segment-square distance: <= every sampled point's distance, and within "
           "length / (2K) of the least", [] {
    const auto q = [] { return *rc::gen::inRange(-40, 41) / 8.0; };
    const Vec2 a{q(), q()};
    const Vec2 b{q(), q()};
    const double x0 = *rc::gen::inRange(-16, 17) / 8.0;
    const double y0 = *rc::gen::inRange(-16, 17) / 8.0;
    const double x1 = x0 + *rc::gen::inRange(0, 17) / 8.0;
    const double y1 = y0 + *rc::gen::inRange(0, 17) / 8.0;
    const double d = geo::segment_box_distance(a, b, x0, y0, x1, y1);
    const int K = 2000;
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= K; ++k) {
      const Vec2 p{a.x + (b.x - a.x) * k / K, a.y + (b.y - a.y) * k / K};
      const double pd = point_box(p, x0, y0, x1, y1);
      RC_ASSERT(d <= pd + 1e-12);
      best = std::min(best, pd);
    }
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    RC_ASSERT(best <= d + len / (2.0 * K) + 1e-12);
  });
}

TEST_CASE("prop_clearance_curve_bounds_hold") {
  rc::prop("for sampled curves: lower <= the true clearance of dense curve points, and upper is "
           "attained by a curve point", [] {
    const auto g = *pathref::testing::gen_grid(10, 10, 0.3);
    const auto pts = *gen_polyline(g, 6);
    const int p = bs::degree_for(pts.size(), 3, bs::EndHandling::repeated);
    const bs::Curve c = bs::make_curve(pts, p, bs::EndHandling::repeated);
    const auto s = bs::sample(c, 0.5);
    const double r = *rc::gen::element(0.0, 0.25, 0.5);
    const auto cl = geo::clearance(g, s.points, {r, s.chord / 2, true});
    RC_ASSERT(cl.lower <= cl.distance);
    RC_ASSERT(cl.distance <= cl.upper);
    const auto dom = bs::domain(c);
    double truth = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= 300; ++k) {
      const double u = k == 300 ? dom[1] : dom[0] + (dom[1] - dom[0]) * k / 300.0;
      truth = std::min(truth, point_obstacles(g, bs::evaluate(c, u), true));
    }
    RC_ASSERT(cl.lower <= truth + 1e-12);
    double at_samples = std::numeric_limits<double>::infinity();
    for (const Vec2& v : s.points) at_samples = std::min(at_samples, point_obstacles(g, v, true));
    RC_ASSERT(cl.upper == at_samples);
    if (cl.verdict == geo::ClearanceVerdict::enters) RC_ASSERT(at_samples <= r);
    if (cl.verdict == geo::ClearanceVerdict::clear) RC_ASSERT(truth > r - 1e-12);
  });
}
