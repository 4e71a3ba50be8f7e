#include "pathref/vehicle/mecanum.hpp"

#include <cmath>
#include <string>

#include <Eigen/QR>

#include "pathref/core/error.hpp"

namespace pathref::vehicle {

namespace {
bool finite_positive(double v) { return std::isfinite(v) && v > 0.0; }

void require_finite_twist(const Twist& t) {
  require(std::isfinite(t.vx) && std::isfinite(t.vy) && std::isfinite(t.omega),
          "twist components must be finite");
}

void require_finite_wheels(const WheelSpeeds& w) {
  require(w.allFinite(), "wheel speeds must be finite");
}
}  // namespace

void require_geometry(const Geometry& g) {
  require(finite_positive(g.r), "wheel radius r must be finite and > 0");
  require(finite_positive(g.lx), "half wheelbase lx must be finite and > 0");
  require(finite_positive(g.ly), "half track ly must be finite and > 0");
}

Eigen::Matrix<double, 4, 3> ik_matrix(const Geometry& g) {
  require_geometry(g);
  const double k = g.lx + g.ly;
  Eigen::Matrix<double, 4, 3> j;
  j << 1.0, -1.0, -k,  //  FL
      1.0, 1.0, k,     //  FR
      1.0, 1.0, -k,    //  RL
      1.0, -1.0, k;    //  RR
  return j;
}

WheelSpeeds inverse_kinematics(const Twist& t, const Geometry& g) {
  require_finite_twist(t);
  const Eigen::Matrix<double, 4, 3> j = ik_matrix(g);
  WheelSpeeds w;
  // Row by row, left to right, then / r (spec mecanum.ik): no reliance on Eigen's product order.
  for (Eigen::Index i = 0; i < 4; ++i)
    w(i) = ((j(i, 0) * t.vx + j(i, 1) * t.vy) + j(i, 2) * t.omega) / g.r;
  require(w.allFinite(), "wheel speeds overflow binary64");
  return w;
}

Twist forward_kinematics(const WheelSpeeds& w, const Geometry& g) {
  require_finite_wheels(w);
  const Eigen::Matrix<double, 4, 3> j = ik_matrix(g);
  const Eigen::Vector4d rim = g.r * w;  // rim speeds r w_i (m/s)
  require(rim.allFinite(), "rim speeds r*w overflow binary64");
  const Eigen::Vector3d t = j.colPivHouseholderQr().solve(rim);
  require(t.allFinite(), "twist overflows binary64");
  return Twist{t(0), t(1), t(2)};
}

Residual kinematic_residual(const WheelSpeeds& w, const Geometry& g) {
  Residual out;
  out.projection = inverse_kinematics(forward_kinematics(w, g), g);
  out.residual = w - out.projection;
  double sum_sq = 0.0;
  for (Eigen::Index i = 0; i < 4; ++i) sum_sq += out.residual(i) * out.residual(i);
  out.norm = std::sqrt(sum_sq);
  return out;
}

LimitAt parse_limit_at(std::string_view name) {
  if (name == "output") return LimitAt::output;
  if (name == "rotor") return LimitAt::rotor;
  throw UsageError("unknown limit_at '" + std::string(name) + "' (expected output or rotor)");
}

std::string_view to_string(LimitAt at) noexcept {
  return at == LimitAt::output ? "output" : "rotor";
}

double wheel_speed_limit(double rpm, LimitAt at, double gear_ratio) {
  require(finite_positive(rpm), "rated speed (rpm) must be finite and > 0");
  require(std::isfinite(gear_ratio) && gear_ratio >= 1.0, "gear ratio must be finite and >= 1");
  const double g = at == LimitAt::output ? 1.0 : gear_ratio;
  return (rpm * (2.0 * std::numbers::pi)) / 60.0 / g;
}

double to_rpm(double rad_per_s) noexcept { return rad_per_s * 60.0 / (2.0 * std::numbers::pi); }

double saturation_scale(const WheelSpeeds& w, double w_max) {
  require_finite_wheels(w);
  require(finite_positive(w_max), "wheel speed limit must be finite and > 0");
  const double m = w.cwiseAbs().maxCoeff();
  if (m <= w_max) return 1.0;
  double s = w_max / m;
  // fl(w_max / m) * m can round above w_max by an ulp; step s down until the bound holds.
  while (s * m > w_max) s = std::nextafter(s, 0.0);
  require(s > 0.0, "saturation scale underflows: wheel limit negligible against the wheel speeds");
  return s;
}

Saturated saturate(const Twist& t, const Geometry& g, double w_max) {
  const WheelSpeeds w = inverse_kinematics(t, g);
  Saturated out;
  out.scale = saturation_scale(w, w_max);
  out.twist = Twist{out.scale * t.vx, out.scale * t.vy, out.scale * t.omega};
  out.wheels = out.scale * w;
  return out;
}

double direction_factor(double dx, double dy) {
  require(std::isfinite(dx) && std::isfinite(dy), "direction must be finite");
  require(dx != 0.0 || dy != 0.0, "direction must not be the zero vector");
  return (std::fabs(dx) + std::fabs(dy)) / std::hypot(dx, dy);
}

double max_translation_speed(double dx, double dy, double r, double w_max) {
  require(finite_positive(r), "wheel radius r must be finite and > 0");
  require(finite_positive(w_max), "wheel speed limit must be finite and > 0");
  return r * w_max / direction_factor(dx, dy);
}

WheelOrder parse_wheel_order(std::string_view name) {
  if (name == "pathref") return WheelOrder::pathref;
  if (name == "ros2") return WheelOrder::ros2;
  throw UsageError("unknown wheel_order '" + std::string(name) + "' (expected pathref or ros2)");
}

WheelSpeeds to_wheel_order(const WheelSpeeds& w, WheelOrder order) noexcept {
  if (order == WheelOrder::pathref) return w;
  return WheelSpeeds(w(0), w(1), w(3), w(2));
}

WheelSpeeds from_wheel_order(const WheelSpeeds& w, WheelOrder order) noexcept {
  return to_wheel_order(w, order);  // a transposition is its own inverse
}

}  // namespace pathref::vehicle
