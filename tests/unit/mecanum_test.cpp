// spec: mecanum.ik, mecanum.fk, mecanum.residual, mecanum.wheel-limit, mecanum.saturate, mecanum.max-speed, drive.trapezoid, drive.rotation, drive.runs, drive.corner-speeds, drive.path-time
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/vehicle/drive.hpp"
#include "pathref/vehicle/mecanum.hpp"

using namespace pathref;
using namespace pathref::vehicle;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
const Geometry geo{0.05, 0.15, 0.15};  // k = 0.3, 1/r = 20
constexpr double inf = std::numeric_limits<double>::infinity();

void check_wheels(const WheelSpeeds& w, double fl, double fr, double rl, double rr) {
  CHECK_THAT(w(0), WithinAbs(fl, 1e-12));
  CHECK_THAT(w(1), WithinAbs(fr, 1e-12));
  CHECK_THAT(w(2), WithinAbs(rl, 1e-12));
  CHECK_THAT(w(3), WithinAbs(rr, 1e-12));
}

void check_twist(const Twist& t, double vx, double vy, double omega) {
  CHECK_THAT(t.vx, WithinAbs(vx, 1e-12));
  CHECK_THAT(t.vy, WithinAbs(vy, 1e-12));
  CHECK_THAT(t.omega, WithinAbs(omega, 1e-12));
}

std::vector<grid::Cell> cells(std::initializer_list<std::pair<int, int>> xy) {
  std::vector<grid::Cell> out;
  for (const auto& [x, y] : xy) out.push_back(grid::Cell{x, y});
  return out;
}
}  // namespace

TEST_CASE("mecanum.ik: pure motions by hand", "[mecanum]") {
  check_wheels(inverse_kinematics({1.0, 0.0, 0.0}, geo), 20, 20, 20, 20);     // forward
  check_wheels(inverse_kinematics({0.0, 1.0, 0.0}, geo), -20, 20, 20, -20);   // left
  check_wheels(inverse_kinematics({0.0, 0.0, 1.0}, geo), -6, 6, -6, 6);       // ccw, k = 0.3
  check_wheels(inverse_kinematics({1.0, 1.0, 0.0}, geo), 0, 40, 40, 0);       // diagonal
  check_wheels(inverse_kinematics({0.5, -0.25, 0.5}, geo), 12, 8, 2, 18);     // combined
}

TEST_CASE("mecanum.ik: a left strafe turns FL and RR backwards", "[mecanum]") {
  // The unambiguous roller-convention check of spec/mecanum.md#conventions.
  const WheelSpeeds w = inverse_kinematics({0.0, 0.3, 0.0}, geo);
  CHECK(w(0) < 0.0);
  CHECK(w(3) < 0.0);
  CHECK(w(1) > 0.0);
  CHECK(w(2) > 0.0);
  // The matrix itself, rows FL, FR, RL, RR.
  const auto j = ik_matrix(geo);
  CHECK(j(0, 1) == -1.0);
  CHECK(j(0, 2) == -(0.15 + 0.15));
  CHECK(j(3, 2) == 0.15 + 0.15);
}

TEST_CASE("mecanum.fk: least squares equals the closed form", "[mecanum]") {
  check_twist(forward_kinematics(WheelSpeeds(12, 8, 2, 18), geo), 0.5, -0.25, 0.5);
  check_twist(forward_kinematics(WheelSpeeds(-6, 6, -6, 6), geo), 0.0, 0.0, 1.0);
  // (21,21,19,19) = forward + the fighting pattern: least squares drops the inconsistent part.
  check_twist(forward_kinematics(WheelSpeeds(21, 21, 19, 19), geo), 1.0, 0.0, 0.0);
  const WheelSpeeds w(3.0, -1.5, 7.25, 0.5);
  const Twist t = forward_kinematics(w, geo);
  const double k = geo.lx + geo.ly;
  CHECK_THAT(t.vx, WithinAbs(geo.r * (w(0) + w(1) + w(2) + w(3)) / 4.0, 1e-12));
  CHECK_THAT(t.vy, WithinAbs(geo.r * (-w(0) + w(1) + w(2) - w(3)) / 4.0, 1e-12));
  CHECK_THAT(t.omega, WithinAbs(geo.r * (-w(0) + w(1) - w(2) + w(3)) / (4.0 * k), 1e-12));
}

TEST_CASE("mecanum.residual: the fighting pattern is the whole residual", "[mecanum]") {
  const Residual a = kinematic_residual(WheelSpeeds(10, 10, -10, -10), geo);
  check_wheels(a.projection, 0, 0, 0, 0);
  check_wheels(a.residual, 10, 10, -10, -10);
  CHECK_THAT(a.norm, WithinAbs(20.0, 1e-12));
  const Residual b = kinematic_residual(WheelSpeeds(1, 2, 3, 4), geo);
  check_wheels(b.projection, 2, 3, 2, 3);
  CHECK_THAT(b.norm, WithinAbs(2.0, 1e-12));
  const Residual c = kinematic_residual(inverse_kinematics({0.5, -0.25, 0.5}, geo), geo);
  CHECK_THAT(c.norm, WithinAbs(0.0, 1e-12));
}

TEST_CASE("mecanum.wheel-limit: Table 2 readings", "[mecanum]") {
  CHECK(wheel_speed_limit(500.0, LimitAt::output, 36.0) == default_wheel_speed_limit);
  CHECK_THAT(default_wheel_speed_limit, WithinRel(50.0 * std::numbers::pi / 3.0, 1e-15));
  CHECK_THAT(wheel_speed_limit(500.0, LimitAt::rotor, 36.0),
             WithinRel(50.0 * std::numbers::pi / 108.0, 1e-15));
  CHECK(parse_limit_at("rotor") == LimitAt::rotor);
  CHECK(to_string(LimitAt::output) == "output");
  CHECK_THROWS_AS(parse_limit_at("wheel"), UsageError);
  CHECK_THAT(to_rpm(default_wheel_speed_limit), WithinRel(500.0, 1e-15));
}

TEST_CASE("mecanum.saturate: keeps direction and lands on the limit", "[mecanum]") {
  const Saturated s = saturate({1.0, 0.0, 1.0}, geo, 20.0);  // wheels (14, 26, 14, 26)
  CHECK(s.saturated());
  CHECK_THAT(s.scale, WithinRel(10.0 / 13.0, 1e-15));
  CHECK(s.twist.vx == s.scale * 1.0);
  CHECK(s.twist.omega == s.scale * 1.0);
  CHECK(s.twist.vy == 0.0);
  CHECK(s.wheels.cwiseAbs().maxCoeff() <= 20.0);
  const Saturated none = saturate({0.5, 0.0, 0.0}, geo, 20.0);
  CHECK_FALSE(none.saturated());
  CHECK(none.twist.vx == 0.5);
  // The ulp correction: fl(13/51.54) * 51.54 rounds above 13.
  const Saturated u = saturate({2.577, 0.0, 0.0}, geo, 13.0);
  CHECK(u.wheels.cwiseAbs().maxCoeff() <= 13.0);
  CHECK(u.scale < 13.0 / (2.577 / 0.05));
}

TEST_CASE("mecanum.max-speed: axis and diagonal", "[mecanum]") {
  CHECK_THAT(max_translation_speed(1.0, 0.0, 0.05, 20.0), WithinRel(1.0, 1e-15));
  CHECK_THAT(max_translation_speed(1.0, -1.0, 0.05, 20.0), WithinRel(1.0 / std::sqrt(2.0), 1e-15));
  CHECK_THAT(direction_factor(3.0, 4.0), WithinRel(1.4, 1e-15));
  // Saturating a very fast translation lands on the direction's top speed.
  const Saturated s = saturate({100.0, 100.0, 0.0}, geo, 20.0);
  CHECK_THAT(std::hypot(s.twist.vx, s.twist.vy),
             WithinRel(max_translation_speed(1.0, 1.0, geo.r, 20.0), 1e-12));
}

TEST_CASE("mecanum: wheel order conversion to ros2", "[mecanum]") {
  const WheelSpeeds w(1, 2, 3, 4);
  const WheelSpeeds ros = to_wheel_order(w, WheelOrder::ros2);
  check_wheels(ros, 1, 2, 4, 3);
  check_wheels(from_wheel_order(ros, WheelOrder::ros2), 1, 2, 3, 4);
  check_wheels(to_wheel_order(w, WheelOrder::pathref), 1, 2, 3, 4);
  CHECK(parse_wheel_order("ros2") == WheelOrder::ros2);
  CHECK_THROWS_AS(parse_wheel_order("wpilib"), UsageError);
}

TEST_CASE("mecanum: preconditions raise DomainError", "[mecanum]") {
  CHECK_THROWS_AS(inverse_kinematics({1, 0, 0}, Geometry{0.0, 0.15, 0.15}), DomainError);
  CHECK_THROWS_AS(inverse_kinematics({1, 0, 0}, Geometry{0.05, -1.0, 0.15}), DomainError);
  CHECK_THROWS_AS(inverse_kinematics({NAN, 0, 0}, geo), DomainError);
  CHECK_THROWS_AS(inverse_kinematics({1e308, 0, 0}, geo), DomainError);  // overflow
  CHECK_THROWS_AS(forward_kinematics(WheelSpeeds(inf, 0, 0, 0), geo), DomainError);
  CHECK_THROWS_AS(wheel_speed_limit(0.0, LimitAt::output, 36.0), DomainError);
  CHECK_THROWS_AS(wheel_speed_limit(500.0, LimitAt::rotor, 0.5), DomainError);
  CHECK_THROWS_AS(saturate({1, 0, 0}, geo, 0.0), DomainError);
  CHECK_THROWS_AS(saturate({1, 0, 0}, geo, inf), DomainError);
  CHECK_THROWS_AS(direction_factor(0.0, 0.0), DomainError);
  CHECK_THROWS_AS(max_translation_speed(1.0, 0.0, 0.0, 20.0), DomainError);
}

TEST_CASE("drive.trapezoid: trapezoid and triangle by hand", "[drive]") {
  const Profile t = trapezoid(2.0, 0.0, 0.0, 1.0, 1.0);
  CHECK(t.time == 3.0);
  CHECK(t.reaches_limit);
  CHECK(t.d_cruise == 1.0);
  const Profile tri = trapezoid(0.5, 0.0, 0.0, 1.0, 1.0);
  CHECK_FALSE(tri.reaches_limit);
  CHECK_THAT(tri.time, WithinRel(std::sqrt(2.0), 1e-15));
  const Profile corner = trapezoid(2.0, 0.0, 0.5, 1.0, 1.0);
  CHECK_THAT(corner.time, WithinRel(2.625, 1e-15));
  CHECK(trapezoid(0.0, 0.0, 0.0, 1.0, 1.0).time == 0.0);
  CHECK_THAT(trapezoid(2.0, 0.0, 0.0, inf, 2.0).time, WithinRel(2.0, 1e-15));
  CHECK_THROWS_AS(trapezoid(0.4, 0.0, 1.0, 2.0, 1.0), DomainError);  // v1 unreachable
  CHECK_THROWS_AS(trapezoid(1.0, 2.0, 0.0, 1.0, 1.0), DomainError);  // v0 > V
  CHECK_THROWS_AS(trapezoid(1.0, 0.0, 0.0, 1.0, 0.0), DomainError);
  CHECK_THROWS_AS(trapezoid(-1.0, 0.0, 0.0, 1.0, 1.0), DomainError);
}

TEST_CASE("drive.rotation: quarter turn", "[drive]") {
  const Profile r = rotation_time(std::numbers::pi / 2.0, 10.0, 10.0);
  CHECK_FALSE(r.reaches_limit);
  CHECK_THAT(r.time, WithinRel(2.0 * std::sqrt(std::numbers::pi / 20.0), 1e-15));
  CHECK(rotation_time(-1.0, 2.0, 3.0).time == rotation_time(1.0, 2.0, 3.0).time);
  CHECK_THAT(rotation_time(std::numbers::pi, 1.0, 2.0).time, WithinRel(std::numbers::pi + 0.5, 1e-15));
  CHECK_THROWS_AS(rotation_time(1.0, 1.0, 0.0), DomainError);
}

TEST_CASE("drive.runs: Table 5-like path", "[drive]") {
  const auto path = cells({{0, 0}, {1, 0}, {2, 1}, {3, 2}, {4, 3}, {5, 4}, {5, 5}});
  const Runs rs = straight_runs(path);
  REQUIRE(rs.runs.size() == 3);
  CHECK(rs.runs[1].dir == grid::Cell{1, 1});
  CHECK(rs.runs[1].steps == 4);
  CHECK(rs.runs[1].first_step == 2);
  CHECK(rs.runs[1].length_cells == 4.0 * std::sqrt(2.0));
  REQUIRE(rs.turns.size() == 2);
  CHECK(rs.turns[0].eighths == 1);
  CHECK(rs.turns[0].sense == 1);
  CHECK(rs.turns[0].angle == std::numbers::pi / 4.0);
  CHECK(straight_runs(cells({{7, 7}})).runs.empty());
  CHECK(turn_angle({0, 1}, {1, 0}).sense == -1);
  CHECK(turn_angle({1, 0}, {-1, 0}).eighths == 4);
  CHECK_THROWS_AS(straight_runs(cells({{0, 0}, {2, 0}})), DomainError);
  CHECK_THROWS_AS(straight_runs(cells({{0, 0}, {0, 0}})), DomainError);
  CHECK_THROWS_AS(straight_runs(std::vector<grid::Cell>{}), DomainError);
}

TEST_CASE("drive.corner-speeds: backward pass", "[drive]") {
  const std::vector<double> d{2.0, 2.0, 0.08};
  const std::vector<double> v{1.0, 1.0, 1.0};
  const std::vector<double> a{1.0, 1.0, 1.0};
  const auto u = corner_speeds(d, v, a, 1.0);
  REQUIRE(u.size() == 4);
  CHECK(u[0] == 0.0);
  CHECK(u[1] == 1.0);
  CHECK_THAT(u[2], WithinRel(0.4, 1e-15));
  CHECK(u[3] == 0.0);
  const std::vector<double> one{1.0};
  CHECK(corner_speeds(one, one, one, 5.0) == std::vector<double>{0.0, 0.0});
  const std::vector<double> none;
  CHECK_THROWS_AS(corner_speeds(none, none, none, 0.0), DomainError);
}

TEST_CASE("drive.path-time: straight path equal on both bases", "[drive]") {
  DriveParams p;
  p.wheel_speed_max = 20.0;
  p.half_track = 0.1;
  const auto straight = cells({{0, 0}, {1, 0}, {2, 0}, {3, 0}});
  const PathTime m = path_time(straight, 1.0, Base::mecanum, p);
  const PathTime d = path_time(straight, 1.0, Base::diff, p);
  CHECK(m.time == d.time);
  CHECK_THAT(m.time, WithinRel(4.0, 1e-15));
  const auto l = cells({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}});
  const PathTime ml = path_time(l, 1.0, Base::mecanum, p);
  const PathTime dl = path_time(l, 1.0, Base::diff, p);
  CHECK_THAT(ml.time, WithinRel(6.0, 1e-15));
  CHECK_THAT(dl.time, WithinRel(6.0 + 2.0 * std::sqrt(std::numbers::pi / 20.0), 1e-15));
  CHECK(dl.turns == 1);
  CHECK(dl.rotate_time > 0.0);
  CHECK(ml.rotate_time == 0.0);
}

TEST_CASE("drive.path-time: bad base is a UsageError, bad cell a DomainError", "[drive]") {
  CHECK_THROWS_AS(parse_base("tank"), UsageError);
  CHECK(parse_base("diff") == Base::diff);
  CHECK(to_string(Base::mecanum) == "mecanum");
  const auto straight = cells({{0, 0}, {1, 0}});
  CHECK_THROWS_AS(path_time(straight, 0.0, Base::mecanum, DriveParams{}), DomainError);
  DriveParams p;
  p.corner_speed = -1.0;
  CHECK_THROWS_AS(path_time(straight, 1.0, Base::mecanum, p), DomainError);
}

TEST_CASE("drive.path-time: schedule integrates to the distance and ends at the total time", "[drive]") {
  DriveParams p;
  p.corner_speed = 0.4;
  const auto path = cells({{0, 0}, {1, 0}, {2, 1}, {3, 2}, {4, 3}, {5, 4}, {5, 5}});
  for (const Base base : {Base::mecanum, Base::diff}) {
    const PathTime pt = path_time(path, 1.0, base, p);
    const std::vector<Knot> ks = schedule(pt, p);
    REQUIRE(ks.size() >= 2);
    CHECK(ks.front().t == 0.0);
    CHECK(ks.back().t == pt.time);
    double dist = 0.0;
    for (std::size_t i = 1; i < ks.size(); ++i) {
      CHECK(ks[i].t >= ks[i - 1].t);
      dist += (ks[i].t - ks[i - 1].t) * (ks[i].speed + ks[i - 1].speed) / 2.0;
    }
    CHECK_THAT(dist, WithinRel(pt.distance, 1e-9));
    for (const Knot& k : ks) {
      CHECK(k.wheels.size() == (base == Base::mecanum ? 4U : 2U));
      for (double w : k.wheels) CHECK(std::fabs(w) <= p.wheel_speed_max * (1.0 + 1e-12));
    }
  }
}

TEST_CASE("drive.path-time: with a corner speed a longer axis run can shorten a Mecanum path", "[drive]") {
  // 39 diagonal steps then 1 (resp. 2) axis steps, cell 0.01 m, r w_max = 1 m/s, a = 1, v_c = 10.
  // The joint speed is capped by braking on the last run, sqrt(2 * 1 * d2): 0.1414 resp. 0.2 m/s;
  // the faster joint saves more on the long diagonal run than the extra 0.01 m costs. Documented in
  // spec drive.path-time ("Consequences"); with v_c = 0 the time grows with every run's length.
  DriveParams p;
  p.wheel_speed_max = 20.0;
  p.corner_speed = 10.0;
  std::vector<grid::Cell> shorter{{0, 0}};
  for (int i = 0; i < 39; ++i) shorter.push_back({shorter.back().x + 1, shorter.back().y + 1});
  std::vector<grid::Cell> longer = shorter;
  shorter.push_back({shorter.back().x + 1, shorter.back().y});
  longer.push_back({longer.back().x + 1, longer.back().y});
  longer.push_back({longer.back().x + 1, longer.back().y});
  const double t_short = path_time(shorter, 0.01, Base::mecanum, p).time;
  const double t_long = path_time(longer, 0.01, Base::mecanum, p).time;
  CHECK_THAT(t_short, WithinRel(1.7302757382371412, 1e-12));
  CHECK_THAT(t_long, WithinRel(1.728234315152864, 1e-12));
  CHECK(t_long < t_short);
  p.corner_speed = 0.0;
  CHECK(path_time(longer, 0.01, Base::mecanum, p).time > path_time(shorter, 0.01, Base::mecanum, p).time);
}
