// spec: metrics.length, metrics.turn-angle, metrics.turns, metrics.smoothness, metrics.safety, metrics.converge, metrics.valid-path
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/grid/grid.hpp"

using namespace pathref;
using grid::Cell;
using grid::CornerPolicy;
using Path = std::vector<Cell>;

namespace {
constexpr double pi = std::numbers::pi;
constexpr double sqrt2 = std::numbers::sqrt2;
}  // namespace

TEST_CASE("metrics.length: hand values", "[metrics]") {
  CHECK(metrics::path_length(Path{{3, 3}}) == 0.0);
  CHECK(metrics::path_length(Path{{0, 0}, {1, 0}, {2, 0}, {3, 0}}) == 3.0);
  CHECK(metrics::path_length(Path{{0, 0}, {1, 1}}) == sqrt2);
  CHECK(metrics::path_length(Path{{0, 0}, {1, 1}, {2, 1}}) == sqrt2 + 1.0);  // left to right
  CHECK(metrics::path_length(Path{{0, 0}, {3, 4}, {3, 0}}) == 9.0);          // polyline, 5 + 4
  CHECK(metrics::centre_distance(Cell{33554432, 0}, Cell{-33554432, 0}) == 67108864.0);
}

TEST_CASE("metrics.turn-angle: the five grid turn angles", "[metrics]") {
  // Exact doubles are expected: atan2 of (0|1, -1|0|1) returns the nearest double of
  // 0, pi/4, pi/2, 3pi/4, pi in glibc; a 1-ulp margin covers other C libraries.
  const auto near = [](double got, double want) {
    return std::fabs(got - want) <= 2.0 * std::numeric_limits<double>::epsilon() * want;
  };
  CHECK(metrics::turning_angle(Cell{0, 0}, Cell{1, 0}, Cell{2, 0}) == 0.0);
  CHECK(near(metrics::turning_angle(Cell{0, 0}, Cell{1, 0}, Cell{2, 1}), pi / 4));
  CHECK(near(metrics::turning_angle(Cell{0, 0}, Cell{1, 0}, Cell{1, 1}), pi / 2));
  CHECK(near(metrics::turning_angle(Cell{0, 0}, Cell{1, 0}, Cell{1, -1}), pi / 2));
  CHECK(near(metrics::turning_angle(Cell{0, 0}, Cell{1, 0}, Cell{0, 1}), 3 * pi / 4));
  CHECK(near(metrics::turning_angle(Cell{0, 0}, Cell{1, 0}, Cell{0, 0}), pi));
  CHECK(metrics::turning_angles(Path{{0, 0}, {1, 1}}).empty());
  CHECK(metrics::turning_angles(Path{{0, 0}, {1, 0}, {2, 1}, {2, 2}}).size() == 2);
}

TEST_CASE("metrics.turns: staircase, U-turn and collinear segments", "[metrics]") {
  CHECK(metrics::turn_count(Path{{0, 0}}) == 0);
  CHECK(metrics::turn_count(Path{{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}}) == 3);
  CHECK(metrics::turn_count(Path{{0, 0}, {1, 0}, {0, 0}}) == 1);
  CHECK(metrics::turn_count(Path{{0, 0}, {1, 0}, {3, 0}}) == 0);
  CHECK(metrics::turn_count(Path{{0, 0}, {2, 0}, {1, 0}}) == 1);
}

TEST_CASE("metrics.smoothness: OMPL's guard scores a U-turn as smooth", "[metrics]") {
  using metrics::SmoothnessForm;
  const Path uturn{{0, 0}, {1, 0}, {0, 0}};
  CHECK(metrics::smoothness_ompl(uturn) == 0.0);
  CHECK(metrics::smoothness_ompl(uturn, SmoothnessForm::angle) == Approx(pi * pi).epsilon(1e-15));
  const Path right{{0, 0}, {1, 0}, {1, 1}};
  // OMPL's law-of-cosines evaluation is a few ulps from (pi/2)^2 (see golden tolerance).
  CHECK(metrics::smoothness_ompl(right) == Approx(pi * pi / 4).epsilon(1e-13));
  CHECK(metrics::smoothness_ompl(Path{{0, 0}, {1, 1}, {2, 2}}) == 0.0);
  // Rounding artefact kept by the OMPL form, absent from the exact-angle form.
  const Path collinear{{0, 0}, {1, 1}, {3, 3}};
  CHECK(metrics::smoothness_ompl(collinear) > 0.0);
  CHECK(metrics::smoothness_ompl(collinear) < 1e-15);
  CHECK(metrics::smoothness_ompl(collinear, SmoothnessForm::angle) == 0.0);
  CHECK(metrics::parse_smoothness_form("angle") == SmoothnessForm::angle);
  CHECK_THROWS_AS(metrics::parse_smoothness_form("exact"), UsageError);
}

TEST_CASE("metrics.safety: counts and the border reading", "[metrics]") {
  const auto g = grid::Grid::from_rows_top_first({"#..", "...", "..#"});
  const Path p{{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}};
  CHECK(metrics::safety_counts(g, p) == std::vector<std::int64_t>{0, 1, 2, 1, 0});
  CHECK(metrics::safety_counts(g, p, metrics::OutsideCells::blocked) ==
        std::vector<std::int64_t>{5, 4, 2, 4, 5});
  CHECK_THROWS_AS(metrics::safety_counts(g, Path{{3, 0}}), DomainError);
  CHECK_THROWS_AS(metrics::parse_outside_cells("wall"), UsageError);
}

TEST_CASE("metrics.converge: first 1-based iteration of the final best", "[metrics]") {
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(metrics::iterations_to_converge(std::vector<double>{5.0}) == 1);
  CHECK(metrics::iterations_to_converge(std::vector<double>{10, 7, 9, 7, 8}) == 2);
  CHECK(metrics::iterations_to_converge(std::vector<double>{inf, inf, 12, 11, 11}) == 4);
  CHECK(metrics::iterations_to_converge(std::vector<double>{1, 3, 2, 3}, metrics::Sense::maximise) == 2);
  CHECK_THROWS_AS(metrics::iterations_to_converge(std::vector<double>{}), DomainError);
  CHECK_THROWS_AS(metrics::iterations_to_converge(std::vector<double>{inf, inf}), DomainError);
  CHECK_THROWS_AS(metrics::iterations_to_converge(std::vector<double>{-inf, 1}), DomainError);
  CHECK_THROWS_AS(metrics::iterations_to_converge(std::vector<double>{1, std::nan("")}), DomainError);
  CHECK_THROWS_AS(metrics::iterations_to_converge(std::vector<double>{inf, 1}, metrics::Sense::maximise),
                  DomainError);
  CHECK_THROWS_AS(metrics::parse_sense("minimum"), UsageError);
}

TEST_CASE("metrics.valid-path: each reason code", "[metrics]") {
  const auto g = grid::Grid::from_rows_top_first({"....", ".#..", "...."});
  const Cell s{0, 0}, t{3, 2};
  const auto check = [&](const Path& p, const char* reason, std::int64_t index,
                         CornerPolicy policy = CornerPolicy::strict) {
    const auto r = metrics::validate_path(g, p, s, t, policy);
    CHECK(r.reason == reason);
    CHECK(r.index == index);
    CHECK(r.valid == (r.reason == "ok"));
  };
  check(Path{{0, 0}, {1, 0}, {2, 0}, {3, 1}, {3, 2}}, "ok", -1);
  check(Path{}, "empty", -1);
  check(Path{{1, 0}, {2, 0}}, "start_mismatch", 0);
  check(Path{{0, 0}, {-1, 0}}, "out_of_bounds", 1);
  check(Path{{0, 0}, {1, 1}}, "blocked", 1);
  check(Path{{0, 0}, {0, 0}}, "repeated", 1);
  check(Path{{0, 0}, {2, 0}}, "not_adjacent", 1);
  check(Path{{0, 0}, {0, 1}, {1, 2}, {2, 2}, {3, 2}}, "corner_cut", 2);
  check(Path{{0, 0}, {0, 1}, {1, 2}, {2, 2}, {3, 2}}, "ok", -1, CornerPolicy::one);
  check(Path{{0, 0}, {1, 0}, {2, 0}, {3, 1}, {3, 2}}, "corner_cut", 3, CornerPolicy::never);
  check(Path{{0, 0}, {1, 0}, {2, 0}}, "goal_mismatch", 2);
  // extreme coordinates are reported, never overflowed
  const Cell far{std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max()};
  CHECK(metrics::validate_path(g, Path{s, far}, s, far, CornerPolicy::strict).reason == "out_of_bounds");
}

TEST_CASE("metrics: path-domain preconditions raise DomainError", "[metrics]") {
  const Path empty;
  const Path repeated{{0, 0}, {1, 0}, {1, 0}};
  const Path too_far{{33554433, 0}, {0, 0}};
  for (const Path* p : {&empty, &repeated, &too_far}) {
    CHECK_THROWS_AS(metrics::path_length(*p), DomainError);
    CHECK_THROWS_AS(metrics::turning_angles(*p), DomainError);
    CHECK_THROWS_AS(metrics::turn_count(*p), DomainError);
    CHECK_THROWS_AS(metrics::smoothness_ompl(*p), DomainError);
  }
  const grid::Grid g(3, 3);
  CHECK_THROWS_AS(metrics::safety_counts(g, empty), DomainError);
  CHECK_THROWS_AS(metrics::safety_counts(g, repeated), DomainError);
  CHECK_THROWS_AS(metrics::turning_angle(Cell{0, 0}, Cell{0, 0}, Cell{1, 0}), DomainError);
}
