#include "pathref/sim/motion.hpp"

#include <cmath>

#include "pathref/core/error.hpp"

namespace pathref::sim {

MotionStep motion_step(double v0, double dt, double v_max, double a, double remaining) {
  require(std::isfinite(dt) && dt > 0.0, "motion_step: dt must be finite and > 0");
  require(std::isfinite(v_max) && v_max > 0.0, "motion_step: v_max must be finite and > 0");
  require(std::isfinite(a) && a > 0.0, "motion_step: a must be finite and > 0");
  require(std::isfinite(v0) && v0 >= 0.0 && v0 <= v_max, "motion_step: v0 must lie in [0, v_max]");
  require(!std::isnan(remaining) && remaining >= 0.0, "motion_step: remaining must be >= 0");
  const double t_a = (v_max - v0) / a;
  const double d_a = (v0 * t_a) + ((a * (t_a * t_a)) / 2.0);
  MotionStep out;
  if (dt <= t_a) {
    out.distance = (v0 * dt) + ((a * (dt * dt)) / 2.0);
    out.v_end = v0 + (a * dt);
  } else {
    out.distance = d_a + (v_max * (dt - t_a));
    out.v_end = v_max;
  }
  out.time = dt;
  if (out.distance >= remaining) {
    out.arrived = true;
    out.distance = remaining;
    if (remaining == 0.0) {
      out.time = 0.0;
      out.v_end = v0;
    } else if (remaining <= d_a) {
      const double tau = (2.0 * remaining) / (v0 + std::sqrt((v0 * v0) + ((2.0 * a) * remaining)));
      out.time = tau;
      out.v_end = v0 + (a * tau);
    } else {
      out.time = t_a + ((remaining - d_a) / v_max);
      out.v_end = v_max;
    }
  }
  return out;
}

double ramp_cruise_time(double length, double v_max, double a) {
  require(std::isfinite(length) && length >= 0.0, "ramp_cruise_time: length must be finite and >= 0");
  require(std::isfinite(v_max) && v_max > 0.0, "ramp_cruise_time: v_max must be finite and > 0");
  require(std::isfinite(a) && a > 0.0, "ramp_cruise_time: a must be finite and > 0");
  const double d_a = (v_max * v_max) / (2.0 * a);
  if (length <= d_a) return std::sqrt((2.0 * length) / a);
  return (v_max / a) + ((length - d_a) / v_max);
}

}  // namespace pathref::sim
