#pragma once
/// \file motion.hpp
/// The robot's speed profile of Han's simulation, one time step at a time: cruise at v_max = 1 m/s,
/// and after a stop (and at the start) accelerate at a = 1 m/s^2 back to v_max; stops (a wait, the
/// goal) are immediate, as the paper describes no braking.
/// Source: Han (IJACSA), Sec. IV: "The robot is set to move forward at a constant speed of 1m/s
/// when no DO is encountered. After encountering obstacles and temporarily stationary, it first
/// accelerates to 1m/s at an acceleration of 1m/s^2, and then continues to move at a constant
/// speed." No DOI in the local text.
/// Spec: spec/han-sim.md (han.sim.motion)
#include <limits>

namespace pathref::sim {

/// One step of the speed profile.
struct MotionStep {
  double distance = 0.0;  ///< ds: arc length advanced in this step
  double v_end = 0.0;     ///< speed at the end of the step (at arrival if arrived)
  double time = 0.0;      ///< time used: dt, or the arrival time within the step
  bool arrived = false;   ///< the remaining distance was reached in this step
};

/// One step of length dt from speed v0 with acceleration a up to v_max, stopping at `remaining`.
/// With t_a = (v_max - v0) / a and d_a = (v0 * t_a) + ((a * (t_a * t_a)) / 2):
/// dt <= t_a: ds = (v0 * dt) + ((a * (dt * dt)) / 2), v = v0 + (a * dt);
/// else ds = d_a + (v_max * (dt - t_a)), v = v_max.
/// If ds >= remaining: arrived, ds = remaining, and the time within the step is
/// tau = (2 * remaining) / (v0 + sqrt((v0 * v0) + ((2 * a) * remaining))) when remaining <= d_a
/// (v = v0 + (a * tau)), else t_a + ((remaining - d_a) / v_max) (v = v_max); remaining == 0
/// gives tau = 0, v = v0.
/// Source: Han (IJACSA), Sec. IV (1 m/s, 1 m/s^2). Spec: han.sim.motion.
/// Pre: dt, v_max, a finite > 0; 0 <= v0 <= v_max; remaining >= 0, not NaN, may be +inf (DomainError).
/// Post: v_end <= v_max; v_end - v0 <= a * time (up to rounding); distance <= remaining.
/// Golden: golden/han-sim/han.sim.motion.json
[[nodiscard]] MotionStep motion_step(double v0, double dt, double v_max, double a,
                                     double remaining = std::numeric_limits<double>::infinity());

/// The time to drive a path of length L from rest under this profile without stops:
/// sqrt(2 L / a) if L <= v_max^2 / (2a), else v_max / a + (L - v_max^2 / (2a)) / v_max.
/// Source: pathref (closed form of han.sim.motion summed over a run). Spec: han.sim.motion.
/// Pre: L finite >= 0; v_max, a finite > 0 (DomainError).
[[nodiscard]] double ramp_cruise_time(double length, double v_max, double a);

}  // namespace pathref::sim
