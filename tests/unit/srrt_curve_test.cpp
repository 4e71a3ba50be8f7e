// S-RRT's curve (spec/cin2021-srrt.md Eq. 12-15, r[cin2021.srrt.curve]) through the shared
// B-spline module, its curvature (spec/curves.md r[curves.curvature], with Eigen's unsupported
// Splines module as an oracle) and the polygon variant of the shared clearance function
// (r[curves.polygon-clearance]).
#include <catch2/catch.hpp>

#include <unsupported/Eigen/Splines>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "pathref/io/scene_json.hpp"
#include "pathref/continuous/srrt.hpp"
#include "pathref/core/error.hpp"
#include "pathref/equations/bspline.hpp"
#include "pathref/geometry/clearance.hpp"
#include "pathref/geometry/decimal.hpp"
#include "pathref/geometry/obstacles.hpp"
#include "pathref/geometry/scene.hpp"
#include "pathref/grid/grid.hpp"

using pathref::DomainError;
using pathref::UsageError;
using pathref::geometry::Vec2;
namespace bs = pathref::bspline;
namespace geo = pathref::geometry;
namespace ct = pathref::continuous;

namespace {

Eigen::Spline<double, 2, Eigen::Dynamic> eigen_spline(const bs::Curve& c) {
  Eigen::Array<double, 1, Eigen::Dynamic> knots(static_cast<Eigen::Index>(c.knots.size()));
  for (std::size_t j = 0; j < c.knots.size(); ++j) knots(static_cast<Eigen::Index>(j)) = c.knots[j];
  Eigen::Matrix<double, 2, Eigen::Dynamic> ctrl(2, static_cast<Eigen::Index>(c.control.size()));
  for (std::size_t i = 0; i < c.control.size(); ++i) {
    ctrl(0, static_cast<Eigen::Index>(i)) = c.control[i].x;
    ctrl(1, static_cast<Eigen::Index>(i)) = c.control[i].y;
  }
  return Eigen::Spline<double, 2, Eigen::Dynamic>(knots, ctrl);
}

const std::vector<Vec2> nodes = {{1, 1}, {2.5, 4}, {3, 4.5}, {7, 2}, {9, 9}, {9.5, 9.2}, {15, 3}};

geo::Scene scene_of(const std::string& polygons_json, const char* rad = "0", int w = 10, int h = 10) {
  const std::string text = std::string("{\"format\": \"pathref-scene 1\", \"origin\": [0, 0], \"width\": ") +
                           std::to_string(w) + ", \"height\": " + std::to_string(h) +
                           ", \"cell_size\": 1, \"radius\": " + rad + ", \"margin\": 0, \"polygons\": " +
                           polygons_json + ", \"start\": [0, 0], \"goal\": [1, 0]}";
  return pathref::io::parse_scene_json(text, "t.json");
}

const char* square13 = "[{\"vertices\": [[1, 1], [3, 1], [3, 3], [1, 3]]}]";

}  // namespace

TEST_CASE("cin2021.eq15: clamped and chord-length knot vectors by hand, degree lowered for few points") {
  const std::vector<Vec2> line = {{0, 0}, {1, 0}, {3, 0}, {6, 0}, {10, 0}};
  // uniform interior knots
  CHECK(bs::make_curve(line, 3, bs::EndHandling::clamped).knots ==
        std::vector<double>{0, 0, 0, 0, 1, 2, 2, 2, 2});
  // chord: t = 0, 1, 3, 6, 10, L = 10, s_1 = 1 + 3 + 6 = 10, u_4 = (2 * 10) / (3 * 10)
  const auto ch = bs::make_curve(line, 3, bs::EndHandling::clamped, bs::KnotSpacing::chord).knots;
  CHECK(ch == std::vector<double>{0, 0, 0, 0, (2.0 * 10.0) / (3.0 * 10.0), 2, 2, 2, 2});
  CHECK(bs::clamped_chord_knots(line, 3) == ch);
  // all points equal: L = 0 gives the uniform knots
  const std::vector<Vec2> same(5, Vec2{2, 2});
  CHECK(bs::clamped_chord_knots(same, 2) == bs::clamped_knots(5, 2));
  // few points: degree lowered (2 nodes: the segment; 3 nodes: a quadratic)
  CHECK(bs::degree_for(2, 3, bs::EndHandling::clamped) == 1);
  CHECK(bs::degree_for(3, 3, bs::EndHandling::clamped) == 2);
  CHECK(bs::degree_for(7, 3, bs::EndHandling::clamped) == 3);
  CHECK(bs::clamped_knots(2, 1) == std::vector<double>{0, 0, 1, 1});
  CHECK(bs::clamped_knots(3, 2) == std::vector<double>{0, 0, 0, 1, 1, 1});
  // chord knots need clamped ends; unknown names are usage errors
  CHECK_THROWS_AS(bs::make_curve(line, 3, bs::EndHandling::repeated, bs::KnotSpacing::chord), DomainError);
  CHECK_THROWS_AS(bs::parse_knot_spacing("centripetal"), UsageError);
  CHECK(bs::parse_knot_spacing("chord") == bs::KnotSpacing::chord);
  CHECK_THROWS_AS(bs::clamped_chord_knots(line, 5), DomainError);  // m < p + 1
}

TEST_CASE("cin2021.eq12: the clamped curve starts at the start, ends at the goal, agrees with Eigen (oracle)") {
  for (const auto ks : {bs::KnotSpacing::uniform, bs::KnotSpacing::chord}) {
    for (int p = 1; p <= 5; ++p) {
      const bs::Curve c = bs::make_curve(nodes, p, bs::EndHandling::clamped, ks);
      const auto dom = bs::domain(c);
      CHECK(bs::evaluate(c, dom[0]) == nodes.front());
      CHECK(bs::evaluate(c, dom[1]) == nodes.back());
      const auto spline = eigen_spline(c);
      for (int s = 0; s <= 64; ++s) {
        const double u = dom[0] + (dom[1] - dom[0]) * s / 64.0;
        const Vec2 mine = bs::evaluate(c, u);
        const Eigen::Vector2d theirs = spline(u);
        INFO("knots " << bs::to_string(ks) << " p " << p << " u " << u);
        CHECK(mine.x == Approx(theirs.x()).margin(1e-12));
        CHECK(mine.y == Approx(theirs.y()).margin(1e-12));
      }
    }
  }
  // two nodes: the straight segment, uniformly parametrised
  const std::vector<Vec2> two = {{0, 0}, {4, 2}};
  const bs::Curve seg = bs::make_curve(two, bs::degree_for(2, 3, bs::EndHandling::clamped), bs::EndHandling::clamped);
  CHECK(bs::evaluate(seg, 0.25) == Vec2{1.0, 0.5});
}

TEST_CASE("cin2021.eq13: exactly one degree-0 basis function is 1, closed at the right end") {
  const auto U = bs::clamped_knots(7, 3);  // 0 0 0 0 1 2 3 4 4 4 4
  CHECK(bs::span_index(U, 3, 7, 0.0) == 3u);
  CHECK(bs::span_index(U, 3, 7, 0.5) == 3u);
  CHECK(bs::span_index(U, 3, 7, 1.0) == 4u);  // [u_4, u_5) = [1, 2)
  CHECK(bs::span_index(U, 3, 7, 3.999) == 6u);
  CHECK(bs::span_index(U, 3, 7, 4.0) == 6u);  // u_m: the last non-empty span, taken closed
  CHECK_THROWS_AS(bs::span_index(U, 3, 7, -0.001), DomainError);
  CHECK_THROWS_AS(bs::span_index(U, 3, 7, 4.001), DomainError);
}

TEST_CASE("cin2021.eq14: Cox-de Boor on chord-length knots agrees with Eigen's BasisFunctions (oracle)") {
  const bs::Curve c = bs::make_curve(nodes, 3, bs::EndHandling::clamped, bs::KnotSpacing::chord);
  const auto spline = eigen_spline(c);
  const auto dom = bs::domain(c);
  for (int s = 0; s <= 40; ++s) {
    const double u = dom[0] + (dom[1] - dom[0]) * s / 40.0;
    const auto all = bs::basis_functions(c.knots, 3, c.control.size(), u);
    const auto k = static_cast<Eigen::Index>(bs::span_index(c.knots, 3, c.control.size(), u));
    if (s < 40) CHECK(spline.span(u) == k);
    double sum = 0.0;
    for (double v : all) sum += v;
    CHECK(sum == Approx(1.0).margin(1e-14));
    const auto theirs = spline.basisFunctions(u);
    for (Eigen::Index r = 0; r <= 3; ++r)
      CHECK(all[static_cast<std::size_t>(k - 3 + r)] == Approx(theirs(r)).margin(1e-13));
  }
}

TEST_CASE("curves.curvature: derivatives agree with Eigen's Splines derivatives (oracle)") {
  for (const auto ks : {bs::KnotSpacing::uniform, bs::KnotSpacing::chord}) {
    for (int p = 1; p <= 5; ++p) {
      const bs::Curve c = bs::make_curve(nodes, p, bs::EndHandling::clamped, ks);
      const auto spline = eigen_spline(c);
      const auto dom = bs::domain(c);
      for (int s = 0; s < 64; ++s) {  // interior of spans: Eigen's span choice equals ours below u_m
        const double u = dom[0] + (dom[1] - dom[0]) * (s + 0.37) / 64.0;
        const auto d = bs::derivatives(c, u);
        const auto e = spline.derivatives(u, 2);
        INFO("knots " << bs::to_string(ks) << " p " << p << " u " << u);
        CHECK(d.first.x == Approx(e(0, 1)).margin(1e-10));
        CHECK(d.first.y == Approx(e(1, 1)).margin(1e-10));
        // Eigen returns min(p, order) + 1 columns: for p = 1 there is no column 2 (reading it is
        // out of bounds); the second derivative of a piecewise-linear curve is 0 inside a span.
        if (p >= 2) {
          CHECK(d.second.x == Approx(e(0, 2)).margin(1e-9));
          CHECK(d.second.y == Approx(e(1, 2)).margin(1e-9));
        } else {
          REQUIRE(e.cols() == 2);
          CHECK(d.second.x == 0.0);
          CHECK(d.second.y == 0.0);
        }
      }
    }
  }
}

TEST_CASE("curves.curvature: a quadratic arc, a straight line and a cusp by hand") {
  // clamped quadratic on 3 points = Bezier: P(t) = (2t, 2t(1 - t)), P' = (2, 2 - 4t), P'' = (0, -4)
  const std::vector<Vec2> arc = {{0, 0}, {1, 1}, {2, 0}};
  const bs::Curve c = bs::make_curve(arc, 2, bs::EndHandling::clamped);
  const auto d = bs::derivatives(c, 0.25);
  CHECK(d.point == Vec2{0.5, 0.375});
  CHECK(d.first == Vec2{2.0, 1.0});
  CHECK(d.second == Vec2{0.0, -4.0});
  CHECK(bs::curvature(c, 0.5) == -1.0);  // -8 / (4 sqrt 4): turning right
  CHECK(bs::curvature(c, 0.0) == Approx(-8.0 / std::pow(8.0, 1.5)).epsilon(1e-15));
  const std::vector<Vec2> straight = {{0, 0}, {1, 1}, {3, 3}, {4, 4}};
  for (double u : {0.0, 0.3, 1.0}) CHECK(bs::curvature(bs::make_curve(straight, 3, bs::EndHandling::clamped), u) == 0.0);
  // P(t) = 2t(1 - t) (1, 0): P'(1/2) = 0, no tangent: +inf
  const std::vector<Vec2> back = {{0, 0}, {1, 0}, {0, 0}};
  CHECK(bs::curvature(bs::make_curve(back, 2, bs::EndHandling::clamped), 0.5) ==
        std::numeric_limits<double>::infinity());
  // degree 1: no second derivative
  CHECK(bs::derivatives(bs::make_curve(arc, 1, bs::EndHandling::clamped), 0.5).second == Vec2{0.0, 0.0});
  CHECK_THROWS_AS(bs::curvature(c, 1.5), DomainError);
}

TEST_CASE("curves.polygon-clearance: a segment past a square, a curve cutting a corner, the border") {
  const auto m = geo::ObstacleMap::from_scene(scene_of(square13));
  const std::vector<Vec2> below = {{0.5, 0.5}, {3.5, 0.5}};
  auto c = geo::clearance(m, below, {0.0, 0.0, false});
  CHECK(c.distance == 0.5);
  CHECK(c.lower == 0.5);
  CHECK(c.upper == 0.5);
  CHECK(c.verdict == geo::ClearanceVerdict::clear);
  CHECK(c.segment == 0);
  // with the border (world [0, 10]^2): 0.5 from the bottom edge as well
  CHECK(geo::clearance(m, below, {0.0, 0.0, true}).distance == 0.5);
  const std::vector<Vec2> low = {{0.5, 0.25}, {3.5, 0.25}};
  CHECK(geo::clearance(m, low, {0.0, 0.0, true}).distance == 0.25);
  CHECK(geo::clearance(m, low, {0.0, 0.0, false}).distance == 0.75);
  // inflation: r = 0.5 is touched (ties enter), r just below is clear
  CHECK(geo::clearance(m, below, {0.5, 0.0, false}).verdict == geo::ClearanceVerdict::enters);
  CHECK(geo::clearance(m, below, {std::nextafter(0.5, 0.0), 0.0, false}).verdict == geo::ClearanceVerdict::clear);
  // a polyline through the square: 0, enters, the crossing segment reported
  const std::vector<Vec2> through = {{0.5, 0.5}, {0.5, 2.0}, {2.0, 2.0}, {5.0, 2.0}};
  c = geo::clearance(m, through, {0.0, 0.0, false});
  CHECK(c.distance == 0.0);
  CHECK(c.segment == 1);  // (0.5, 2) -> (2, 2) enters the square first
  CHECK(c.verdict == geo::ClearanceVerdict::enters);
  // tolerance: undetermined between the bounds
  c = geo::clearance(m, below, {0.45, 0.1, false});
  CHECK(c.lower == Approx(0.4).margin(1e-15));
  CHECK(c.verdict == geo::ClearanceVerdict::undetermined);
  // no obstacles, no border: +inf
  const auto empty = geo::ObstacleMap::from_scene(scene_of("[]"));
  CHECK(geo::clearance(empty, below, {0.0, 0.0, false}).distance == std::numeric_limits<double>::infinity());
  CHECK(geo::clearance(empty, below, {0.0, 0.0, false}).segment == -1);
  CHECK_THROWS_AS(geo::clearance(m, std::vector<Vec2>{}, {}), DomainError);
  CHECK_THROWS_AS(geo::clearance(m, below, {-1.0, 0.0, false}), DomainError);
  // the same obstacles as grid cells: the grid variant agrees
  const auto g = pathref::grid::Grid::from_rows_top_first({"..........", "..........", "..........", "..........",
                                                 "..........", "..........", "..........", ".##.......",
                                                 ".##.......", ".........."});
  const auto gm = geo::ObstacleMap::from_grid(g, geo::decimal_from_integer(0));
  for (const auto& pl : {below, low, through}) {
    const auto a = geo::clearance(gm, pl, {0.0, 0.0, true});
    const auto b = geo::clearance(g, pl, {0.0, 0.0, true});
    CHECK(a.distance == Approx(b.distance).margin(1e-15));
    CHECK(a.segment == b.segment);
  }
}

TEST_CASE("cin2021.srrt.curve: the curve cuts a corner, the repair re-inserts the corner node") {
  const auto m = geo::ObstacleMap::from_scene(scene_of(square13));
  // Algorithm 2's kept nodes around the square's lower-right corner: 0 -> 2 -> 4 -> 5
  const std::vector<Vec2> raw = {{0.5, 0.5}, {2.0, 0.5}, {3.5, 0.5}, {3.5, 2.0}, {3.5, 3.5}, {2.0, 3.5}};
  const std::vector<std::size_t> kept = {0, 2, 4, 5};
  ct::CurveParams p;
  CHECK_FALSE(p.repair);  // off by default: the paper's method as printed
  auto r = ct::smooth_path(m, raw, kept, p);
  CHECK(r.degree == 3);
  CHECK(r.repair == "off");
  CHECK(r.kept == kept);
  CHECK(r.samples.points.front() == raw.front());
  CHECK(r.samples.points.back() == raw.back());
  CHECK(r.clearance.verdict == geo::ClearanceVerdict::enters);  // the cubic cuts into [1, 3]^2
  CHECK(r.max_curvature > 0.0);
  p.repair = true;
  r = ct::smooth_path(m, raw, kept, p);
  CHECK(r.repair == "clear");
  CHECK(r.inserted == std::vector<std::size_t>{1, 3});
  CHECK(r.kept == std::vector<std::size_t>{0, 1, 2, 3, 4, 5});
  CHECK(r.clearance.verdict == geo::ClearanceVerdict::clear);
  CHECK(r.clearance.lower > 0.2);
  // a corner hugged at 0.05 with no removed node to re-insert: stuck, still reported
  const std::vector<Vec2> hug = {{0.5, 0.95}, {3.05, 0.95}, {3.05, 3.5}};
  r = ct::smooth_path(m, hug, {0, 1, 2}, p);
  CHECK(r.repair == "stuck");
  CHECK(r.clearance.verdict != geo::ClearanceVerdict::clear);
  // domain
  CHECK_THROWS_AS(ct::smooth_path(m, raw, {0, 2, 4}, p), DomainError);
  CHECK_THROWS_AS(ct::smooth_path(m, raw, {0, 2, 2, 5}, p), DomainError);
  CHECK_THROWS_AS(ct::curve_params(nlohmann::json{{"degree", 0}}), DomainError);
  CHECK_THROWS_AS(ct::curve_params(nlohmann::json{{"spacing", 0.0}}), DomainError);
  CHECK_THROWS_AS(ct::curve_params(nlohmann::json{{"knots", "centripetal"}}), UsageError);
}
