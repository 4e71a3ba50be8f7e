// JSON adapters for the mecanum.* and drive.* rules (spec/mecanum.md).
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/rules/modules.hpp"
#include "pathref/vehicle/drive.hpp"
#include "pathref/vehicle/mecanum.hpp"

namespace pathref::rules {

namespace {

using vehicle::Geometry;
using vehicle::Twist;
using vehicle::WheelSpeeds;

double opt_number(const Json& in, const char* key, double fallback) {
  return in.contains(key) ? arg_number(in, key) : fallback;
}

/// A list of numbers where an element may also be "inf" (for speed limits).
std::vector<double> numbers_or_inf(const Json& in, const char* key) {
  const Json& v = arg(in, key);
  if (!v.is_array()) throw UsageError(std::string("input '") + key + "' must be an array");
  std::vector<double> out;
  for (const Json& e : v) {
    if (e.is_number()) {
      out.push_back(e.get<double>());
    } else if (e == "inf") {
      out.push_back(std::numeric_limits<double>::infinity());
    } else {
      throw UsageError(std::string("input '") + key + "' must hold numbers or \"inf\"");
    }
  }
  return out;
}

Geometry geometry_arg(const Json& in) {
  return Geometry{arg_number(in, "r"), arg_number(in, "lx"), arg_number(in, "ly")};
}

Twist twist_arg(const Json& in) {
  return Twist{arg_number(in, "vx"), arg_number(in, "vy"), arg_number(in, "omega")};
}

WheelSpeeds wheels_arg(const Json& in) {
  const std::vector<double> w = arg_numbers(in, "w");
  if (w.size() != 4) throw UsageError("input 'w' must hold exactly four wheel speeds");
  return WheelSpeeds(w[0], w[1], w[2], w[3]);
}

Json to_json(const WheelSpeeds& w) {
  Json a = Json::array();
  for (Eigen::Index i = 0; i < 4; ++i) a.push_back(number(w(i)));
  return a;
}

Json profile_json(const vehicle::Profile& p) {
  return Json{{"time", number(p.time)},         {"v_peak", number(p.v_peak)},
              {"t_acc", number(p.t_acc)},       {"t_cruise", number(p.t_cruise)},
              {"t_dec", number(p.t_dec)},       {"d_acc", number(p.d_acc)},
              {"d_cruise", number(p.d_cruise)}, {"d_dec", number(p.d_dec)},
              {"shape", p.reaches_limit ? "trapezoid" : "triangle"}};
}

const std::vector<Field> geometry_fields = {
    {"r", "number", "wheel radius, m (> 0)"},
    {"lx", "number", "half wheelbase, centre to axle along x, m (> 0)"},
    {"ly", "number", "half track, centre to wheel mid-plane along y, m (> 0)"}};

std::vector<Field> with_geometry(std::vector<Field> fields) {
  fields.insert(fields.end(), geometry_fields.begin(), geometry_fields.end());
  return fields;
}

}  // namespace

void register_mecanum_rules(Registry& r) {
  r.add(Rule{
      "mecanum.ik",
      "Mecanum inverse kinematics: body twist -> four wheel speeds, w = J t / r",
      "pathref::vehicle::inverse_kinematics",
      with_geometry({{"vx", "number", "forward speed, m/s"},
                     {"vy", "number", "leftward speed, m/s"},
                     {"omega", "number", "yaw rate, rad/s, counter-clockwise"},
                     {"wheel_order", "string", "pathref (FL,FR,RL,RR; default) | ros2 (FL,FR,RR,RL)"}}),
      {{"w", "number[4]", "wheel speeds, rad/s, in wheel_order"},
       {"rpm", "number[4]", "the same in rpm"}},
      [](const Json& in) {
        const auto order = vehicle::parse_wheel_order(opt_string(in, "wheel_order", "pathref"));
        const WheelSpeeds w =
            vehicle::to_wheel_order(vehicle::inverse_kinematics(twist_arg(in), geometry_arg(in)), order);
        Json rpm = Json::array();
        for (Eigen::Index i = 0; i < 4; ++i) rpm.push_back(number(vehicle::to_rpm(w(i))));
        return Json{{"w", to_json(w)}, {"rpm", rpm}};
      }});
  r.add(Rule{
      "mecanum.fk",
      "Mecanum forward kinematics: least-squares twist from four wheel speeds",
      "pathref::vehicle::forward_kinematics",
      with_geometry({{"w", "number[4]", "wheel speeds, rad/s, in wheel_order"},
                     {"wheel_order", "string", "pathref (default) | ros2"}}),
      {{"vx", "number", "m/s"}, {"vy", "number", "m/s"}, {"omega", "number", "rad/s"}},
      [](const Json& in) {
        const auto order = vehicle::parse_wheel_order(opt_string(in, "wheel_order", "pathref"));
        const Twist t = vehicle::forward_kinematics(
            vehicle::from_wheel_order(wheels_arg(in), order), geometry_arg(in));
        return Json{{"vx", number(t.vx)}, {"vy", number(t.vy)}, {"omega", number(t.omega)}};
      }});
  r.add(Rule{
      "mecanum.residual",
      "Projection IK(FK(w)) of four wheel speeds onto rigid-body motions, and the residual",
      "pathref::vehicle::kinematic_residual",
      with_geometry({{"w", "number[4]", "wheel speeds, rad/s, FL,FR,RL,RR"}}),
      {{"projection", "number[4]", "IK(FK(w)), rad/s"},
       {"residual", "number[4]", "w - IK(FK(w)), rad/s"},
       {"norm", "number", "Euclidean norm of the residual = |w1+w2-w3-w4|/2"}},
      [](const Json& in) {
        const auto res = vehicle::kinematic_residual(wheels_arg(in), geometry_arg(in));
        return Json{{"projection", to_json(res.projection)},
                    {"residual", to_json(res.residual)},
                    {"norm", number(res.norm)}};
      }});
  r.add(Rule{
      "mecanum.wheel-limit",
      "Wheel speed limit (rad/s at the wheel) from a gear motor's rated rpm",
      "pathref::vehicle::wheel_speed_limit",
      {{"rpm", "number", "rated speed, rpm (Shi 2022 Table 2: 500)"},
       {"limit_at", "string", "output (default: at the gearbox output = wheel) | rotor"},
       {"gear_ratio", "number", "rotor : output speed ratio, used for rotor (default 36)"}},
      {{"w_max", "number", "wheel speed limit, rad/s"}, {"wheel_rpm", "number", "the same in rpm"}},
      [](const Json& in) {
        const auto at = vehicle::parse_limit_at(opt_string(in, "limit_at", "output"));
        const double rpm = arg_number(in, "rpm");
        const double ratio = opt_number(in, "gear_ratio", vehicle::m2006_gear_ratio);
        const double w = vehicle::wheel_speed_limit(rpm, at, ratio);
        // Spec: the wheel rpm is n / g (not a round trip through rad/s).
        const double wheel_rpm = at == vehicle::LimitAt::output ? rpm : rpm / ratio;
        return Json{{"w_max", number(w)}, {"wheel_rpm", number(wheel_rpm)}};
      }});
  r.add(Rule{
      "mecanum.saturate",
      "Twist scaled down uniformly so that no wheel exceeds the wheel speed limit",
      "pathref::vehicle::saturate",
      with_geometry({{"vx", "number", "m/s"},
                     {"vy", "number", "m/s"},
                     {"omega", "number", "rad/s"},
                     {"w_max", "number", "wheel speed limit, rad/s (> 0)"}}),
      {{"scale", "number", "s in (0,1]"},
       {"vx", "number", "s*vx"},
       {"vy", "number", "s*vy"},
       {"omega", "number", "s*omega"},
       {"w", "number[4]", "s*IK(t), rad/s, FL,FR,RL,RR"},
       {"saturated", "bool", "s < 1"}},
      [](const Json& in) {
        const auto s = vehicle::saturate(twist_arg(in), geometry_arg(in), arg_number(in, "w_max"));
        return Json{{"scale", number(s.scale)},          {"vx", number(s.twist.vx)},
                    {"vy", number(s.twist.vy)},          {"omega", number(s.twist.omega)},
                    {"w", to_json(s.wheels)},            {"saturated", s.saturated()}};
      }});
  r.add(Rule{
      "mecanum.max-speed",
      "Top translation speed of a Mecanum base along a direction: r w_max / g(d)",
      "pathref::vehicle::max_translation_speed",
      {{"dx", "number", "direction x (body frame)"},
       {"dy", "number", "direction y"},
       {"r", "number", "wheel radius, m"},
       {"w_max", "number", "wheel speed limit, rad/s"}},
      {{"v_max", "number", "top speed, m/s"},
       {"factor", "number", "g(d) = (|dx|+|dy|)/hypot(dx,dy)"}},
      [](const Json& in) {
        const double dx = arg_number(in, "dx");
        const double dy = arg_number(in, "dy");
        const double v = vehicle::max_translation_speed(dx, dy, arg_number(in, "r"), arg_number(in, "w_max"));
        return Json{{"v_max", number(v)}, {"factor", number(vehicle::direction_factor(dx, dy))}};
      }});
  r.add(Rule{
      "drive.trapezoid",
      "Time of a straight run from v0 to v1 under speed limit V and acceleration limit a",
      "pathref::vehicle::trapezoid",
      {{"d", "number", "run length (>= 0)"},
       {"v0", "number", "start speed"},
       {"v1", "number", "end speed"},
       {"v_max", "number", "speed limit V (> 0, may be \"inf\")"},
       {"a", "number", "acceleration limit (> 0)"}},
      {{"time", "number", "T"},
       {"v_peak", "number", "peak speed"},
       {"t_acc", "number", ""}, {"t_cruise", "number", ""}, {"t_dec", "number", ""},
       {"d_acc", "number", ""}, {"d_cruise", "number", ""}, {"d_dec", "number", ""},
       {"shape", "string", "trapezoid (V reached) | triangle"}},
      [](const Json& in) {
        return profile_json(vehicle::trapezoid(arg_number(in, "d"), arg_number(in, "v0"),
                                               arg_number(in, "v1"), arg_number(in, "v_max"),
                                               arg_number(in, "a")));
      }});
  r.add(Rule{
      "drive.rotation",
      "Time to rotate on the spot by an angle, rest to rest, under yaw-rate and yaw-acceleration limits",
      "pathref::vehicle::rotation_time",
      {{"angle", "number", "radians (either sign)"},
       {"omega_max", "number", "yaw-rate limit, rad/s (> 0, may be \"inf\")"},
       {"alpha_max", "number", "yaw acceleration limit, rad/s^2 (> 0)"}},
      {{"time", "number", "s"},
       {"v_peak", "number", "peak yaw rate, rad/s"},
       {"t_acc", "number", ""}, {"t_cruise", "number", ""}, {"t_dec", "number", ""},
       {"shape", "string", "trapezoid | triangle"}},
      [](const Json& in) {
        return profile_json(vehicle::rotation_time(arg_number(in, "angle"), arg_number(in, "omega_max"),
                                                   arg_number(in, "alpha_max")));
      }});
  r.add(Rule{
      "drive.runs",
      "Decomposition of a path of 8-neighbour steps into maximal straight runs and turns",
      "pathref::vehicle::straight_runs",
      {{"path", "path", "cells [[x,y],...]"}},
      {{"runs", "object[]", "{dir:[dx,dy], first_step, steps, length (cells)}"},
       {"turns", "integer", "number of joints between runs"},
       {"angles", "number[]", "turning angle at each joint, radians"},
       {"eighths", "integer[]", "45-degree steps at each joint (1..4)"},
       {"senses", "integer[]", "+1 left (and reversal), -1 right"}},
      [](const Json& in) {
        const auto path = grid::path_from_json(arg(in, "path"));
        const auto rs = vehicle::straight_runs(path);
        Json runs = Json::array();
        for (const auto& run : rs.runs)
          runs.push_back(Json{{"dir", Json::array({run.dir.x, run.dir.y})},
                              {"first_step", run.first_step},
                              {"steps", run.steps},
                              {"length", number(run.length_cells)}});
        Json angles = Json::array(), eighths = Json::array(), senses = Json::array();
        for (const auto& t : rs.turns) {
          angles.push_back(number(t.angle));
          eighths.push_back(t.eighths);
          senses.push_back(t.sense);
        }
        return Json{{"runs", runs},
                    {"turns", static_cast<long long>(rs.turns.size())},
                    {"angles", angles},
                    {"eighths", eighths},
                    {"senses", senses}};
      }});
  r.add(Rule{
      "drive.corner-speeds",
      "Joint speeds of consecutive runs: targets min(v_c,V_j,V_j+1), forward then backward pass",
      "pathref::vehicle::corner_speeds",
      {{"lengths", "number[]", "run lengths d_j (> 0), m"},
       {"v_max", "number[]", "run speed limits V_j (> 0, may be \"inf\")"},
       {"a_max", "number[]", "run acceleration limits A_j (> 0)"},
       {"corner_speed", "number", "target speed at every joint v_c (>= 0)"}},
      {{"speeds", "number[]", "u_0 .. u_m (u_0 = u_m = 0)"}},
      [](const Json& in) {
        const auto u = vehicle::corner_speeds(arg_numbers(in, "lengths"), numbers_or_inf(in, "v_max"),
                                              arg_numbers(in, "a_max"), arg_number(in, "corner_speed"));
        Json out = Json::array();
        for (double x : u) out.push_back(number(x));
        return Json{{"speeds", out}};
      }});
  r.add(Rule{
      "drive.path-time",
      "Time, distance and turns to drive a grid path with a Mecanum or a differential-drive base",
      "pathref::vehicle::path_time",
      {{"path", "path", "cells [[x,y],...], 8-neighbour steps"},
       {"cell", "number", "cell size, m (> 0)"},
       {"base", "string", "mecanum | diff"},
       {"r", "number", "wheel radius, m (default 0.05)"},
       {"lx", "number", "half wheelbase, m (default 0.15)"},
       {"ly", "number", "half track, m (default 0.15)"},
       {"w_max", "number", "wheel speed limit, rad/s (default 500 rpm = 52.3598...)"},
       {"a_max", "number", "acceleration limit at each wheel rim, m/s^2 (default 1)"},
       {"v_cap", "number", "body speed cap, m/s (default \"inf\")"},
       {"corner_speed", "number", "Mecanum speed at each turn, m/s (default 0)"},
       {"half_track", "number", "differential drive half track b, m (default: ly)"},
       {"yaw_rate_cap", "number", "differential drive yaw-rate cap, rad/s (default \"inf\")"}},
      {{"time", "number", "total time, s"},
       {"distance", "number", "m"},
       {"turns", "integer", "joints between runs"},
       {"run_time", "number", "s"},
       {"rotate_time", "number", "s (0 for mecanum)"},
       {"runs", "object[]", "{distance, v_limit, a_limit, v_start, v_end, v_peak, time}"},
       {"joints", "object[]", "{angle, time} (time 0 for mecanum)"}},
      [](const Json& in) {
        const auto path = grid::path_from_json(arg(in, "path"));
        const auto base = vehicle::parse_base(arg_string(in, "base"));
        vehicle::DriveParams p;
        p.geometry = Geometry{opt_number(in, "r", p.geometry.r), opt_number(in, "lx", p.geometry.lx),
                              opt_number(in, "ly", p.geometry.ly)};
        p.wheel_speed_max = opt_number(in, "w_max", p.wheel_speed_max);
        p.accel = opt_number(in, "a_max", p.accel);
        p.speed_cap = opt_number(in, "v_cap", p.speed_cap);
        p.corner_speed = opt_number(in, "corner_speed", p.corner_speed);
        p.half_track = opt_number(in, "half_track", p.geometry.ly);
        p.yaw_rate_cap = opt_number(in, "yaw_rate_cap", p.yaw_rate_cap);
        const auto pt = vehicle::path_time(path, arg_number(in, "cell"), base, p);
        Json runs = Json::array();
        for (const auto& rt : pt.runs)
          runs.push_back(Json{{"distance", number(rt.distance)},
                              {"v_limit", number(rt.v_limit)},
                              {"a_limit", number(rt.a_limit)},
                              {"v_start", number(rt.v_start)},
                              {"v_end", number(rt.v_end)},
                              {"v_peak", number(rt.profile.v_peak)},
                              {"time", number(rt.profile.time)}});
        Json joints = Json::array();
        for (const auto& tt : pt.joints)
          joints.push_back(Json{{"angle", number(tt.turn.angle)}, {"time", number(tt.profile.time)}});
        return Json{{"time", number(pt.time)},         {"distance", number(pt.distance)},
                    {"turns", pt.turns},               {"run_time", number(pt.run_time)},
                    {"rotate_time", number(pt.rotate_time)}, {"runs", runs},
                    {"joints", joints}};
      }});
}

}  // namespace pathref::rules
