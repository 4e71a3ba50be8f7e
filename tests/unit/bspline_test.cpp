// Unit tests of the B-spline module (spec/curves.md, spec/sensors2023.md eq6-eq8, a1-a3),
// including Eigen's unsupported Splines module as an independent oracle.
#include <catch2/catch.hpp>

#include <unsupported/Eigen/Splines>

#include <cmath>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/bspline.hpp"

using pathref::DomainError;
using pathref::UsageError;
using pathref::geometry::Vec2;
namespace bs = pathref::bspline;

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

const std::vector<Vec2> zigzag = {{0, 0}, {1, 2}, {3, 1}, {4, 4}, {6, 3}, {7, 6}, {9, 5}};

}  // namespace

TEST_CASE("curves.knots: uniform and clamped knot vectors by hand") {
  CHECK(bs::uniform_knots(4, 3) == std::vector<double>{0, 1, 2, 3, 4, 5, 6, 7});
  CHECK(bs::clamped_knots(4, 3) == std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1});
  CHECK(bs::clamped_knots(6, 3) == std::vector<double>{0, 0, 0, 0, 1, 2, 3, 3, 3, 3});
  CHECK(bs::clamped_knots(3, 2) == std::vector<double>{0, 0, 0, 1, 1, 1});
  CHECK_THROWS_AS(bs::uniform_knots(3, 3), DomainError);
  CHECK_THROWS_AS(bs::clamped_knots(5, 0), DomainError);
  CHECK_THROWS_AS(bs::parse_end_handling("open"), UsageError);
  const std::vector<Vec2> two = {{0, 0}, {4, 2}};
  const auto cp = bs::control_polygon(two, 3, bs::EndHandling::repeated);
  REQUIRE(cp.size() == 6);
  CHECK(cp[0] == Vec2{0, 0});
  CHECK(cp[2] == Vec2{0, 0});
  CHECK(cp[3] == Vec2{4, 2});
  CHECK(cp[5] == Vec2{4, 2});
  // lowering the degree for few points
  CHECK(bs::degree_for(2, 3, bs::EndHandling::clamped) == 1);
  CHECK(bs::degree_for(3, 3, bs::EndHandling::clamped) == 2);
  CHECK(bs::degree_for(4, 3, bs::EndHandling::clamped) == 3);
  CHECK(bs::degree_for(2, 3, bs::EndHandling::repeated) == 3);
  CHECK(bs::degree_for(1, 3, bs::EndHandling::repeated) == 3);
  CHECK_THROWS_AS(bs::degree_for(1, 3, bs::EndHandling::none), DomainError);
  CHECK_THROWS_AS(bs::degree_for(1, 1, bs::EndHandling::repeated), DomainError);
}

TEST_CASE("sensors2023.a3: the cubic basis by hand and = A2 = Eq. 8 weights") {
  const auto f0 = bs::uniform_cubic_basis(0.0);
  CHECK(f0[0] == 1.0 / 6.0);
  CHECK(f0[1] == 4.0 / 6.0);
  CHECK(f0[2] == 1.0 / 6.0);
  CHECK(f0[3] == 0.0);
  const auto fh = bs::uniform_cubic_basis(0.5);  // 1/48, 23/48, 23/48, 1/48
  CHECK(fh[0] == 1.0 / 48.0);
  CHECK(fh[1] == 23.0 / 48.0);
  CHECK(fh[2] == 23.0 / 48.0);
  CHECK(fh[3] == 1.0 / 48.0);
  for (double t : {0.0, 0.125, 0.25, 0.5, 0.75, 1.0}) {
    const auto f = bs::uniform_cubic_basis(t);
    for (std::size_t j = 0; j < 4; ++j)
      CHECK(bs::uniform_basis(static_cast<int>(j), 3, t) == Approx(f[j]).margin(1e-15));
  }
  CHECK_THROWS_AS(bs::uniform_cubic_basis(1.5), DomainError);
  CHECK_THROWS_AS(bs::uniform_basis(4, 3, 0.5), DomainError);
}

TEST_CASE("sensors2023.eq8: matrix form of a straight control polygon is the straight line") {
  // P_j = (j, 2j): the uniform cubic reproduces linear functions, P(t) = (1 + t, 2 + 2t).
  for (double t : {0.0, 0.25, 0.5, 1.0}) {
    const Vec2 p = bs::cubic_matrix_segment({0, 0}, {1, 2}, {2, 4}, {3, 6}, t);
    CHECK(p.x == Approx(1.0 + t).margin(1e-15));
    CHECK(p.y == Approx(2.0 + 2.0 * t).margin(1e-15));
  }
}

TEST_CASE("sensors2023.eq6: evaluation agrees with Eigen's Splines module (oracle)") {
  for (const auto end : {bs::EndHandling::clamped, bs::EndHandling::repeated, bs::EndHandling::none}) {
    for (int p = 1; p <= 5; ++p) {
      const bs::Curve c = bs::make_curve(zigzag, p, end);
      const auto spline = eigen_spline(c);
      const auto dom = bs::domain(c);
      for (int s = 0; s <= 64; ++s) {
        const double u = dom[0] + (dom[1] - dom[0]) * s / 64.0;
        const Vec2 mine = bs::evaluate(c, u);
        const Eigen::Vector2d theirs = spline(u);
        INFO("end " << bs::to_string(end) << " p " << p << " u " << u);
        CHECK(mine.x == Approx(theirs.x()).margin(1e-12));
        CHECK(mine.y == Approx(theirs.y()).margin(1e-12));
      }
    }
  }
}

TEST_CASE("sensors2023.eq7: basis functions agree with Eigen's BasisFunctions (oracle)") {
  const bs::Curve c = bs::make_curve(zigzag, 3, bs::EndHandling::clamped);
  const auto spline = eigen_spline(c);
  for (int s = 0; s <= 40; ++s) {
    const double u = 4.0 * s / 40.0;
    const auto all = bs::basis_functions(c.knots, 3, c.control.size(), u);
    const auto k = static_cast<Eigen::Index>(bs::span_index(c.knots, 3, c.control.size(), u));
    CHECK(spline.span(u) == k);
    const auto theirs = spline.basisFunctions(u);
    for (Eigen::Index r = 0; r <= 3; ++r)
      CHECK(all[static_cast<std::size_t>(k - 3 + r)] == Approx(theirs(r)).margin(1e-14));
  }
  // hand: clamped cubic on 4 points is the Bezier curve: N = Bernstein polynomials at u = 1/2
  const auto b = bs::basis_functions(bs::clamped_knots(4, 3), 3, 4, 0.5);
  const std::vector<double> bernstein = {0.125, 0.375, 0.375, 0.125};
  for (std::size_t i = 0; i < 4; ++i) CHECK(b[i] == Approx(bernstein[i]).margin(1e-16));
  CHECK_THROWS_AS(bs::basis_functions(bs::clamped_knots(4, 3), 3, 4, 1.0001), DomainError);
}

TEST_CASE("curves.sample: chord bound holds and the ends are the curve's ends") {
  const bs::Curve c = bs::make_curve(zigzag, 3, bs::EndHandling::repeated);
  for (double spacing : {2.0, 0.5, 0.1}) {
    const auto s = bs::sample(c, spacing);
    REQUIRE(s.points.size() == s.params.size());
    CHECK(s.chord <= spacing);
    CHECK(s.points.front().x == Approx(zigzag.front().x).margin(1e-14));
    CHECK(s.points.front().y == Approx(zigzag.front().y).margin(1e-14));
    CHECK(s.points.back().x == Approx(zigzag.back().x).margin(1e-14));
    CHECK(s.points.back().y == Approx(zigzag.back().y).margin(1e-14));
    for (std::size_t i = 1; i < s.points.size(); ++i) {
      CHECK(s.params[i] > s.params[i - 1]);
      CHECK(std::hypot(s.points[i].x - s.points[i - 1].x, s.points[i].y - s.points[i - 1].y) <=
            s.chord * (1 + 1e-12) + 1e-12);
    }
  }
  CHECK_THROWS_AS(bs::sample(c, 0.0), DomainError);
  CHECK_THROWS_AS(bs::sample(c, 1e-12), DomainError);  // more than max_samples
}
