// Properties of the B-spline module (spec/curves.md, spec/sensors2023.md eq6-eq8, a1-a3).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "pathref/equations/bspline.hpp"

using pathref::geometry::Vec2;
namespace bs = pathref::bspline;

namespace {

/// Control points on a lattice of quarter units in [-64, 64] (exact doubles).
rc::Gen<std::vector<Vec2>> gen_points(int min_n, int max_n) {
  return rc::gen::mapcat(rc::gen::inRange(min_n, max_n + 1), [](int n) {
    return rc::gen::container<std::vector<Vec2>>(
        static_cast<std::size_t>(n), rc::gen::map(rc::gen::pair(rc::gen::inRange(-256, 257),
                                                                rc::gen::inRange(-256, 257)),
                                                  [](std::pair<int, int> q) {
                                                    return Vec2{q.first / 4.0, q.second / 4.0};
                                                  }));
  });
}

rc::Gen<bs::EndHandling> gen_end() {
  return rc::gen::element(bs::EndHandling::clamped, bs::EndHandling::repeated,
                          bs::EndHandling::none);
}

/// u in the domain, drawn on a grid of 1/1024 of the domain, both ends included.
double gen_u(const bs::Curve& c) {
  const auto d = bs::domain(c);
  const int k = *rc::gen::inRange(0, 1025);
  return k == 1024 ? d[1] : d[0] + (d[1] - d[0]) * k / 1024.0;
}

/// Is p in the convex hull of pts (within eps)? For every direction normal to an edge of the
/// hull... simpler and exact enough: p is in the hull iff for every direction v among 256 sampled
/// directions, v.p <= max_j v.pts_j + eps (a necessary condition; tight for small polygons).
bool in_hull(Vec2 p, const std::vector<Vec2>& pts, double eps) {
  for (int k = 0; k < 256; ++k) {
    const double a = 2.0 * M_PI * k / 256.0;
    const double vx = std::cos(a);
    const double vy = std::sin(a);
    double mx = -1e300;
    for (const Vec2& q : pts) mx = std::max(mx, vx * q.x + vy * q.y);
    if (vx * p.x + vy * p.y > mx + eps) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("prop_bspline_partition_of_unity") {
  rc::prop("the basis sums to 1, each value in [0, 1], at most p + 1 non-zero", [] {
    const int p = *rc::gen::inRange(1, 7);
    const auto end = *gen_end();
    const auto pts = *gen_points(p + 1, 12);
    const bs::Curve c = bs::make_curve(pts, p, end);
    const double u = gen_u(c);
    const auto n = bs::basis_functions(c.knots, p, c.control.size(), u);
    double sum = 0.0;
    int nonzero = 0;
    for (double v : n) {
      RC_ASSERT(v >= -1e-15);
      RC_ASSERT(v <= 1.0 + 1e-15);
      sum += v;
      nonzero += v != 0.0 ? 1 : 0;
    }
    RC_ASSERT(std::abs(sum - 1.0) <= 1e-13);
    RC_ASSERT(nonzero <= p + 1);
  });
}

TEST_CASE("prop_bspline_in_convex_hull") {
  rc::prop("P(u) lies in the convex hull of the p + 1 control points of u's span", [] {
    const int p = *rc::gen::inRange(1, 6);
    const auto end = *gen_end();
    const auto pts = *gen_points(p + 1, 10);
    const bs::Curve c = bs::make_curve(pts, p, end);
    const double u = gen_u(c);
    const auto k = bs::span_index(c.knots, p, c.control.size(), u);
    const std::vector<Vec2> local(c.control.begin() + static_cast<std::ptrdiff_t>(k) - p,
                                  c.control.begin() + static_cast<std::ptrdiff_t>(k) + 1);
    RC_ASSERT(in_hull(bs::evaluate(c, u), local, 1e-9));
  });
}

TEST_CASE("prop_bspline_endpoint_interpolation") {
  rc::prop("clamped and repeated curves start at the first point and end at the last", [] {
    const int p = *rc::gen::inRange(1, 6);
    const auto end = *rc::gen::element(bs::EndHandling::clamped, bs::EndHandling::repeated);
    const auto pts = *gen_points(end == bs::EndHandling::clamped ? p + 1 : 2, 10);
    const bs::Curve c = bs::make_curve(pts, p, end);
    const auto d = bs::domain(c);
    const Vec2 a = bs::evaluate(c, d[0]);
    const Vec2 b = bs::evaluate(c, d[1]);
    RC_ASSERT(std::abs(a.x - pts.front().x) <= 1e-12);
    RC_ASSERT(std::abs(a.y - pts.front().y) <= 1e-12);
    RC_ASSERT(std::abs(b.x - pts.back().x) <= 1e-12);
    RC_ASSERT(std::abs(b.y - pts.back().y) <= 1e-12);
  });
}

TEST_CASE("prop_bspline_none_misses_endpoints") {
  // The variant that promises nothing: for a cubic, the curve starts at (P0 + 4 P1 + P2) / 6.
  rc::prop("end handling none starts at (P0 + 4 P1 + P2) / 6 for p = 3", [] {
    const auto pts = *gen_points(4, 10);
    const bs::Curve c = bs::make_curve(pts, 3, bs::EndHandling::none);
    const Vec2 a = bs::evaluate(c, bs::domain(c)[0]);
    RC_ASSERT(std::abs(a.x - (pts[0].x + 4 * pts[1].x + pts[2].x) / 6.0) <= 1e-12);
    RC_ASSERT(std::abs(a.y - (pts[0].y + 4 * pts[1].y + pts[2].y) / 6.0) <= 1e-12);
  });
}

TEST_CASE("prop_bspline_matrix_form_equals_cox_de_boor") {
  rc::prop("uniform knots: Eq. 8 and A1 on segment s equal Eq. 6 at u = p + s + t", [] {
    const int p = *rc::gen::inRange(1, 7);
    const auto pts = *gen_points(p + 1, 12);
    const bs::Curve c{p, bs::uniform_knots(pts.size(), p), pts};
    const int segs = static_cast<int>(pts.size()) - p;
    const int s = *rc::gen::inRange(0, segs);
    const double t = *rc::gen::inRange(0, 257) / 256.0;
    const Vec2 ref = bs::evaluate(c, p + s + t);
    const std::vector<Vec2> window(pts.begin() + s, pts.begin() + s + p + 1);
    const Vec2 a1 = bs::uniform_segment(window, t);
    RC_ASSERT(std::abs(a1.x - ref.x) <= 1e-9);
    RC_ASSERT(std::abs(a1.y - ref.y) <= 1e-9);
    if (p == 3) {
      const Vec2 m = bs::cubic_matrix_segment(window[0], window[1], window[2], window[3], t);
      RC_ASSERT(std::abs(m.x - ref.x) <= 1e-12);
      RC_ASSERT(std::abs(m.y - ref.y) <= 1e-12);
      const auto f = bs::uniform_cubic_basis(t);
      for (std::size_t j = 0; j < 4; ++j)
        RC_ASSERT(std::abs(f[j] - bs::uniform_basis(static_cast<int>(j), 3, t)) <= 1e-15);
    }
  });
}

TEST_CASE("prop_bspline_sample_chord_bound") {
  rc::prop("samples: consecutive chord <= spacing; a dense check of the curve stays within "
           "chord / 2 of a sample", [] {
    const int p = *rc::gen::inRange(1, 5);
    const auto end = *gen_end();
    const auto pts = *gen_points(p + 1, 8);
    const bs::Curve c = bs::make_curve(pts, p, end);
    const double spacing = *rc::gen::element(0.25, 0.5, 1.0, 3.0);
    const auto s = bs::sample(c, spacing);
    RC_ASSERT(s.chord <= spacing);
    for (std::size_t i = 1; i < s.points.size(); ++i)
      RC_ASSERT(std::hypot(s.points[i].x - s.points[i - 1].x, s.points[i].y - s.points[i - 1].y) <=
                s.chord * (1 + 1e-12) + 1e-12);
    const auto d = bs::domain(c);
    for (int k = 0; k <= 200; ++k) {
      const double u = k == 200 ? d[1] : d[0] + (d[1] - d[0]) * k / 200.0;
      const Vec2 q = bs::evaluate(c, u);
      double best = 1e300;
      for (const Vec2& v : s.points) best = std::min(best, std::hypot(q.x - v.x, q.y - v.y));
      RC_ASSERT(best <= s.chord / 2 * (1 + 1e-12) + 1e-12);
    }
  });
}
