#pragma once
/// \file mecanum.hpp
/// Kinematics of a four-wheel Mecanum base (rollers at +-45 deg) and its wheel-speed limit, as
/// pure functions: inverse kinematics (body twist -> wheel speeds), forward kinematics (the
/// least-squares inverse), the residual of inconsistent wheel speeds, the wheel limit from a motor
/// rating, uniform desaturation of a twist, and the direction-dependent top speed.
/// Conventions (spec/mecanum.md#conventions): body x forward, y left, omega counter-clockwise;
/// wheel order FL, FR, RL, RR; w_i > 0 pushes the vehicle forward; rad/s at the wheel.
/// Vehicle: Shi et al. 2022, §5.3 and Table 2, doi:10.3389/fbioe.2022.905983.
/// Spec: spec/mecanum.md
#include <numbers>
#include <string_view>

#include <Eigen/Core>

namespace pathref::vehicle {

/// Wheel radius r, half wheelbase l_x, half track l_y (metres). Defaults are assumptions
/// (spec/mecanum.md, "Defaults"): a 100 mm wheel on a 0.30 m x 0.30 m contact rectangle.
struct Geometry {
  double r = 0.05;
  double lx = 0.15;
  double ly = 0.15;
};

/// A body twist: v_x, v_y in m/s, omega in rad/s (counter-clockwise positive).
struct Twist {
  double vx = 0.0;
  double vy = 0.0;
  double omega = 0.0;
};

/// Four wheel speeds in rad/s, pathref order FL, FR, RL, RR.
using WheelSpeeds = Eigen::Vector4d;

/// The 4x3 map J of spec rule mecanum.ik (rows FL, FR, RL, RR; columns v_x, v_y, omega):
/// [[1,-1,-k],[1,1,k],[1,1,-k],[1,-1,k]], k = l_x + l_y. Wheel speeds are J t / r.
/// Spec: mecanum.ik. Pre: geometry valid (r, l_x, l_y finite and > 0; DomainError).
[[nodiscard]] Eigen::Matrix<double, 4, 3> ik_matrix(const Geometry& g);

/// Inverse kinematics: w = J t / r, e.g. w_FL = (v_x - v_y - k omega) / r.
/// Source: standard Mecanum kinematics (Lynch & Park, Modern Robotics, 2017, §13.2).
/// Spec: mecanum.ik. Pre: geometry valid; twist finite; result finite (DomainError).
/// Post: forward_kinematics(inverse_kinematics(t)) == t up to rounding.
/// Interpretation: wheel order (pathref | ros2) is applied by to_wheel_order.
/// Golden: golden/mecanum/mecanum.ik.json
[[nodiscard]] WheelSpeeds inverse_kinematics(const Twist& t, const Geometry& g);

/// Forward kinematics: the least-squares twist t = argmin ||J t - r w||_2, solved with Eigen's
/// column-pivoting Householder QR of J (equal, up to rounding, to the closed form
/// v_x = r(w1+w2+w3+w4)/4, v_y = r(-w1+w2+w3-w4)/4, omega = r(-w1+w2-w3+w4)/(4k)).
/// Source: Lynch & Park 2017, §13.4 (odometry through the pseudo-inverse of the wheel map).
/// Spec: mecanum.fk. Pre: geometry valid; w finite (DomainError).
/// Golden: golden/mecanum/mecanum.fk.json
[[nodiscard]] Twist forward_kinematics(const WheelSpeeds& w, const Geometry& g);

/// The projection of w onto the wheel speeds a rigid body can produce, and the rest.
struct Residual {
  WheelSpeeds projection;  ///< IK(FK(w)) = J J^+ w
  WheelSpeeds residual;    ///< w - projection = ((w1+w2-w3-w4)/4) (1,1,-1,-1)
  double norm = 0.0;       ///< ||residual||_2 = |w1+w2-w3-w4| / 2
};

/// Splits w into its rigid-body part IK(FK(w)) and the residual w - IK(FK(w)), which is zero iff
/// some twist produces w. Independent of the geometry (up to rounding).
/// Source: pathref (orthogonal decomposition of R^4 by the columns of J).
/// Spec: mecanum.residual. Pre: geometry valid; w finite (DomainError).
/// Golden: golden/mecanum/mecanum.residual.json
[[nodiscard]] Residual kinematic_residual(const WheelSpeeds& w, const Geometry& g);

/// Where the rated speed of a gear motor is stated (spec rule mecanum.wheel-limit, "Reading").
enum class LimitAt {
  output,  ///< at the gearbox output shaft = the wheel (default reading of Shi Table 2)
  rotor,   ///< at the motor rotor; the wheel turns gear_ratio times slower
};
/// "output" | "rotor" -> LimitAt; UsageError otherwise.
[[nodiscard]] LimitAt parse_limit_at(std::string_view name);
[[nodiscard]] std::string_view to_string(LimitAt at) noexcept;

/// The M2006 P36 reduction (36:1), used only for LimitAt::rotor.
inline constexpr double m2006_gear_ratio = 36.0;
/// Shi et al. 2022 Table 2: "Maximum speed 500 rpm".
inline constexpr double shi2022_rated_rpm = 500.0;

/// Wheel speed limit in rad/s at the wheel: ((rpm * 2 pi) / 60) / g, g = 1 (output) or
/// gear_ratio (rotor). Source: Shi et al. 2022 Table 2 ("Maximum speed 500 rpm").
/// Spec: mecanum.wheel-limit. Pre: rpm finite > 0; gear_ratio finite >= 1 (DomainError).
/// Interpretation: limit_at = output (default; 500 rpm at the gearbox output = the wheel) |
/// rotor (500 rpm at the motor rotor, wheel at rpm / 36); spec/mecanum.md#conventions.
/// Golden: golden/mecanum/mecanum.wheel-limit.json
[[nodiscard]] double wheel_speed_limit(double rpm, LimitAt at, double gear_ratio);

/// The default wheel limit: 500 rpm at the output shaft, in rad/s (52.35987755982988).
inline constexpr double default_wheel_speed_limit =
    (shi2022_rated_rpm * (2.0 * std::numbers::pi)) / 60.0 / 1.0;

/// rad/s -> rpm: w * 60 / (2 pi).
[[nodiscard]] double to_rpm(double rad_per_s) noexcept;

/// Uniform scale s in (0, 1] that brings the fastest wheel to at most w_max:
/// 1 if max|w_i| <= w_max, else w_max / max|w_i| lowered ulp by ulp until fl(s * max|w_i|) <= w_max.
/// Spec: mecanum.saturate. Pre: w finite; w_max finite > 0 (DomainError).
/// Post: 0 < s <= 1 and fl(s * |w_i|) <= w_max for every i.
[[nodiscard]] double saturation_scale(const WheelSpeeds& w, double w_max);

/// A twist scaled down uniformly so no wheel exceeds the limit.
struct Saturated {
  double scale = 1.0;  ///< s in (0, 1]
  Twist twist;         ///< s * t: the same direction (ratios v_x : v_y : omega) as t
  WheelSpeeds wheels;  ///< s * IK(t): every |w_i| <= w_max exactly
  [[nodiscard]] bool saturated() const noexcept { return scale < 1.0; }
};

/// Scales t uniformly (keeping its direction) so that no wheel turns faster than w_max.
/// Source: pathref (the usual desaturation of wheel commands, applied to the twist).
/// Spec: mecanum.saturate. Pre: geometry valid; t finite; w_max finite > 0 (DomainError).
/// Golden: golden/mecanum/mecanum.saturate.json
[[nodiscard]] Saturated saturate(const Twist& t, const Geometry& g, double w_max);

/// Direction factor g(d) = (|d_x| + |d_y|) / hypot(d_x, d_y), in [1, sqrt 2]: the fastest wheel of
/// a base translating at speed V along d turns at V g(d) / r.
/// Spec: mecanum.max-speed. Pre: d finite, not (0, 0) (DomainError).
[[nodiscard]] double direction_factor(double dx, double dy);

/// Top translation speed (omega = 0) along d under the wheel limit: r w_max / g(d).
/// r w_max along a body axis, r w_max / sqrt 2 along a diagonal.
/// Source: pathref, from mecanum.ik. Spec: mecanum.max-speed. Pre: d finite, not (0, 0); r, w_max finite > 0 (DomainError).
/// Golden: golden/mecanum/mecanum.max-speed.json
[[nodiscard]] double max_translation_speed(double dx, double dy, double r, double w_max);

/// Wheel orders of spec/mecanum.md#conventions.
enum class WheelOrder {
  pathref,  ///< FL, FR, RL, RR
  ros2,     ///< FL, FR, RR, RL (ros2_controllers mecanum_drive_controller)
};
/// "pathref" | "ros2" -> WheelOrder; UsageError otherwise.
[[nodiscard]] WheelOrder parse_wheel_order(std::string_view name);

/// Pathref-ordered wheel speeds -> the given order (ros2: swaps entries 3 and 4).
/// Spec: mecanum.ik (Reading). Self-inverse: from_wheel_order is the same permutation.
[[nodiscard]] WheelSpeeds to_wheel_order(const WheelSpeeds& w, WheelOrder order) noexcept;
/// Wheel speeds in the given order -> pathref order. Spec: mecanum.fk (Reading).
[[nodiscard]] WheelSpeeds from_wheel_order(const WheelSpeeds& w, WheelOrder order) noexcept;

/// DomainError unless r, l_x, l_y are finite and > 0.
void require_geometry(const Geometry& g);

}  // namespace pathref::vehicle
