// JSON adapters for the sensors2023 DWA rules (spec/sensors2023-dwa.md): Eq. 9-14, the clearance,
// the control step, key-node following, obstacles, the collision test, turns and the fused run.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/dwa.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/rules/modules.hpp"
#include "pathref/sim/fused.hpp"

namespace pathref::rules {

namespace {

using namespace pathref::dwa;

double opt_num(const Json& in, const char* key, double fallback) {
  return in.contains(key) ? arg_number(in, key) : fallback;
}

/// Numbers where an element may also be "inf", "-inf" or "nan" (to reach the DomainErrors).
std::vector<double> numbers_ext(const Json& in, const char* key) {
  const Json& a = arg(in, key);
  if (!a.is_array()) throw UsageError(std::string("input '") + key + "' must be an array");
  std::vector<double> out;
  for (const Json& e : a) {
    if (e.is_number()) out.push_back(e.get<double>());
    else if (e == "inf") out.push_back(std::numeric_limits<double>::infinity());
    else if (e == "-inf") out.push_back(-std::numeric_limits<double>::infinity());
    else if (e == "nan") out.push_back(std::numeric_limits<double>::quiet_NaN());
    else throw UsageError(std::string("input '") + key + "' must hold numbers");
  }
  return out;
}

Pose pose_arg(const Json& in, const char* key) {
  const std::vector<double> v = numbers_ext(in, key);
  if (v.size() != 3) throw UsageError(std::string("input '") + key + "' must be [x, y, theta]");
  return Pose{v[0], v[1], v[2]};
}

Point point_arg(const Json& in, const char* key) {
  const std::vector<double> v = arg_numbers(in, key);
  if (v.size() != 2) throw UsageError(std::string("input '") + key + "' must be [x, y]");
  return Point{v[0], v[1]};
}

Point point_of(const Json& v, const char* what) {
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
    throw UsageError(std::string(what) + " must be [x, y]");
  return Point{v[0].get<double>(), v[1].get<double>()};
}

Json pose_json(Pose p) { return Json::array({number(p.x), number(p.y), number(p.theta)}); }

Limits limits_arg(const Json& in) {
  Limits l;
  l.v_min = opt_num(in, "v_min", l.v_min);
  l.v_max = opt_num(in, "v_max", l.v_max);
  l.w_max = opt_num(in, "w_max", l.w_max);
  l.acc_v = opt_num(in, "acc_v", l.acc_v);
  l.dec_v = opt_num(in, "dec_v", l.dec_v);
  l.acc_w = opt_num(in, "acc_w", l.acc_w);
  l.dec_w = opt_num(in, "dec_w", l.dec_w);
  return l;
}

std::vector<grid::Cell> cells_arg(const Json& in, const char* key) {
  if (!in.contains(key)) return {};
  return grid::path_from_json(arg(in, key));
}

std::vector<Disc> discs_arg(const Json& in) {
  std::vector<Disc> out;
  if (!in.contains("discs")) return out;
  const Json& a = arg(in, "discs");
  if (!a.is_array()) throw UsageError("input 'discs' must be an array of {\"c\": [x, y], \"r\": r}");
  for (const Json& d : a) {
    if (!d.is_object() || !d.contains("c") || !d.contains("r") || !d["r"].is_number())
      throw UsageError("a disc must be {\"c\": [x, y], \"r\": r}");
    Point vel{0.0, 0.0};
    if (d.contains("vel")) vel = point_of(d["vel"], "disc velocity");
    out.push_back(Disc{point_of(d["c"], "disc centre"), d["r"].get<double>(), vel});
  }
  return out;
}

std::vector<Waypoint> waypoints_of(const Json& a) {
  if (!a.is_array()) throw UsageError("waypoints must be an array of [t, x, y]");
  std::vector<Waypoint> out;
  for (const Json& w : a) {
    if (!w.is_array() || w.size() != 3 || !w[0].is_number() || !w[1].is_number() || !w[2].is_number())
      throw UsageError("a waypoint must be [t, x, y]");
    out.push_back(Waypoint{w[0].get<double>(), Point{w[1].get<double>(), w[2].get<double>()}});
  }
  return out;
}

std::vector<Mover> movers_arg(const Json& in) {
  std::vector<Mover> out;
  if (!in.contains("movers")) return out;
  const Json& a = arg(in, "movers");
  if (!a.is_array()) throw UsageError("input 'movers' must be an array of {\"r\", \"waypoints\"}");
  for (const Json& m : a) {
    if (!m.is_object() || !m.contains("r") || !m["r"].is_number() || !m.contains("waypoints"))
      throw UsageError("a mover must be {\"r\": r, \"waypoints\": [[t, x, y], ...]}");
    out.push_back(Mover{m["r"].get<double>(), waypoints_of(m["waypoints"])});
  }
  return out;
}

Json numbers_json(const std::vector<double>& v) {
  Json a = Json::array();
  for (const double x : v) a.push_back(number(x));
  return a;
}

}  // namespace

void register_sensors2023_dwa_rules(Registry& r) {
  r.add(Rule{
      "sensors2023.eq9",
      "Unicycle motion over one step dt (Eq. 9) and the predicted trajectory over the horizon",
      "pathref::dwa::motion_step, pathref::dwa::predict",
      {{"pose", "number[3]", "[x, y, theta] (m, m, rad)"},
       {"v", "number", "linear velocity, m/s"},
       {"w", "number", "angular velocity, rad/s"},
       {"dt", "number", "step, s (> 0)"},
       {"horizon", "number", "optional: prediction time, s; adds the trajectory of round(horizon/dt) steps"},
       {"motion_order", "string", "heading-last (default, Eq. 9) | heading-first (PythonRobotics)"}},
      {{"pose", "number[3]", "the pose after one step"},
       {"trajectory", "number[3][]", "with horizon: P_1 ... P_N"}},
      [](const Json& in) {
        const MotionOrder o = parse_motion_order(opt_string(in, "motion_order", "heading-last"));
        const Pose p = pose_arg(in, "pose");
        const double v = arg_number(in, "v"), w = arg_number(in, "w"), dt = arg_number(in, "dt");
        Json out{{"pose", pose_json(motion_step(p, v, w, dt, o))}};
        if (in.contains("horizon")) {
          Json t = Json::array();
          for (const Pose& q : predict(p, v, w, dt, arg_number(in, "horizon"), o)) t.push_back(pose_json(q));
          out["trajectory"] = t;
        }
        return out;
      }});
  r.add(Rule{
      "sensors2023.eq10",
      "Velocity space V_s = [v_min, v_max] x [-w_max, w_max] (Eq. 10)",
      "pathref::dwa::velocity_space",
      {{"v_min", "number", "m/s"}, {"v_max", "number", "m/s"}, {"w_max", "number", "rad/s (>= 0)"}},
      {{"v_lo", "number", ""}, {"v_hi", "number", ""}, {"w_lo", "number", ""}, {"w_hi", "number", ""}},
      [](const Json& in) {
        Limits l;
        l.v_min = arg_number(in, "v_min");
        l.v_max = arg_number(in, "v_max");
        l.w_max = arg_number(in, "w_max");
        const Window w = velocity_space(l);
        return Json{{"v_lo", number(w.v_lo)}, {"v_hi", number(w.v_hi)}, {"w_lo", number(w.w_lo)}, {"w_hi", number(w.w_hi)}};
      }});
  r.add(Rule{
      "sensors2023.eq11",
      "Dynamic window V_d intersected with V_s (Eq. 11) and its sampled velocities",
      "pathref::dwa::dynamic_window, pathref::dwa::axis_samples",
      {{"v_c", "number", "current v"}, {"w_c", "number", "current w"},
       {"v_min", "number", "optional (default 0)"}, {"v_max", "number", "optional (1.0)"},
       {"w_max", "number", "optional (40 deg/s)"}, {"acc_v", "number", "optional (0.5)"},
       {"dec_v", "number", "optional (0.5)"}, {"acc_w", "number", "optional (100 deg/s^2)"},
       {"dec_w", "number", "optional (100 deg/s^2)"}, {"dt", "number", "s"},
       {"v_res", "number", "optional: resolution of v samples"}, {"w_res", "number", "optional: of w samples"},
       {"window_upper", "string", "include (default) | exclude"}},
      {{"v_lo", "number", ""}, {"v_hi", "number", ""}, {"w_lo", "number", ""}, {"w_hi", "number", ""},
       {"v_samples", "number[]", "with v_res"}, {"w_samples", "number[]", "with w_res"}},
      [](const Json& in) {
        const WindowUpper up = parse_window_upper(opt_string(in, "window_upper", "include"));
        const Window w = dynamic_window(arg_number(in, "v_c"), arg_number(in, "w_c"), limits_arg(in), arg_number(in, "dt"));
        Json out{{"v_lo", number(w.v_lo)}, {"v_hi", number(w.v_hi)}, {"w_lo", number(w.w_lo)}, {"w_hi", number(w.w_hi)}};
        if (in.contains("v_res")) out["v_samples"] = numbers_json(axis_samples(w.v_lo, w.v_hi, arg_number(in, "v_res"), up));
        if (in.contains("w_res")) out["w_samples"] = numbers_json(axis_samples(w.w_lo, w.w_hi, arg_number(in, "w_res"), up));
        return out;
      }});
  r.add(Rule{
      "sensors2023.eq12",
      "Braking-distance admissibility: v <= sqrt(2 dist dec_v) and |w| <= sqrt(2 dist dec_w) (Eq. 12)",
      "pathref::dwa::admissible",
      {{"v", "number", "m/s"}, {"w", "number", "rad/s"}, {"dist", "number", "clearance, m (>= 0)"},
       {"dec_v", "number", "m/s^2"}, {"dec_w", "number", "rad/s^2"},
       {"admissible", "string", "both (default) | linear | off"}},
      {{"admissible", "bool", ""}},
      [](const Json& in) {
        const Admissible m = parse_admissible(opt_string(in, "admissible", "both"));
        return Json{{"admissible", admissible(arg_number(in, "v"), arg_number(in, "w"), arg_number(in, "dist"),
                                              arg_number(in, "dec_v"), arg_number(in, "dec_w"), m)}};
      }});
  r.add(Rule{
      "sensors2023.eq13",
      "Evaluation G = sigma(alpha heading + beta dist + gamma velocity) over the valid candidates, and the choice (Eq. 13)",
      "pathref::dwa::evaluate",
      {{"candidates", "object[]", "{heading (deg), dtheta (|rad|), clearance (m), velocity (m/s), valid (bool)}"},
       {"alpha", "number", "optional (0.2)"}, {"beta", "number", "optional (0.2)"}, {"gamma", "number", "optional (0.1)"},
       {"k_heading", "number", "optional (0.15)"}, {"k_clearance", "number", "optional (1.0)"},
       {"k_velocity", "number", "optional (1.0)"}, {"v_max", "number", "optional (1.0), for cost"},
       {"evaluation", "string", "normalised (default) | cost"}},
      {{"scores", "number[]", "G or C; \"nan\" for invalid candidates"}, {"best", "integer", "chosen index, -1 if none"}},
      [](const Json& in) {
        const Evaluation e = parse_evaluation(opt_string(in, "evaluation", "normalised"));
        Weights w;
        w.alpha = opt_num(in, "alpha", w.alpha);
        w.beta = opt_num(in, "beta", w.beta);
        w.gamma = opt_num(in, "gamma", w.gamma);
        w.k_heading = opt_num(in, "k_heading", w.k_heading);
        w.k_clearance = opt_num(in, "k_clearance", w.k_clearance);
        w.k_velocity = opt_num(in, "k_velocity", w.k_velocity);
        const Json& a = arg(in, "candidates");
        if (!a.is_array()) throw UsageError("input 'candidates' must be an array");
        std::vector<Terms> ts;
        for (const Json& c : a) {
          Terms t;
          t.heading_deg = arg_number(c, "heading");
          t.abs_dtheta = arg_number(c, "dtheta");
          t.clearance = arg_number(c, "clearance");
          t.velocity = arg_number(c, "velocity");
          const Json& v = arg(c, "valid");
          if (!v.is_boolean()) throw UsageError("'valid' must be a bool");
          t.valid = v.get<bool>();
          ts.push_back(t);
        }
        const Choice ch = evaluate(ts, w, e, opt_num(in, "v_max", 1.0));
        return Json{{"scores", numbers_json(ch.scores)}, {"best", ch.best}};
      }});
  r.add(Rule{
      "sensors2023.eq14",
      "Following heading term: 180 - |wrap(theta_end - bearing to the current key node)| in degrees (Eq. 14)",
      "pathref::dwa::heading_term, pathref::dwa::wrap_angle",
      {{"pose", "number[3]", "end pose of the predicted trajectory [x, y, theta]"},
       {"target", "number[2]", "the current key node (or the goal), m"},
       {"heading_wrap", "string", "on (default) | off (the MATLAB demo's unwrapped difference)"}},
      {{"heading", "number", "degrees"}, {"dtheta", "number", "|wrap(dtheta)|, rad"}},
      [](const Json& in) {
        const HeadingWrap wr = parse_heading_wrap(opt_string(in, "heading_wrap", "on"));
        const Heading h = heading_term(pose_arg(in, "pose"), point_arg(in, "target"), wr);
        return Json{{"heading", number(h.heading_deg)}, {"dtheta", number(h.abs_dtheta)}};
      }});
  r.add(Rule{
      "sensors2023.dwa.clearance",
      "Clearance of a point / a predicted trajectory: min(cap, surface distance to cells and discs - robot radius)",
      "pathref::dwa::point_clearance, pathref::dwa::trajectory_clearance, pathref::geometry::point_box_distance",
      {{"grid", "grid", "rows, top first (cells outside count as blocked)"},
       {"points", "number[2][]", "the trajectory P_1 ... P_N (one point: a point clearance)"},
       {"radius", "number", "robot radius, m"}, {"cap", "number", "clearance cap, m"},
       {"temporary", "cell[]", "optional: present temporary cells"},
       {"discs", "object[]", "optional: {c: [x, y], r, vel: [vx, vy] (optional)}"},
       {"dt", "number", "optional: step of the trajectory's poses (discs move by vel (j+1) dt); 0 default"},
       {"clearance_at", "string", "trajectory (default) | end"}},
      {{"clearance", "number", "m (negative: collision)"}, {"point_clearances", "number[]", "per point"}},
      [](const Json& in) {
        const ClearanceAt at = parse_clearance_at(opt_string(in, "clearance_at", "trajectory"));
        const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
        const std::vector<grid::Cell> temp = cells_arg(in, "temporary");
        const std::vector<Disc> discs = discs_arg(in);
        const Obstacles obs{&g, temp, discs};
        const Json& a = arg(in, "points");
        if (!a.is_array()) throw UsageError("input 'points' must be an array of [x, y]");
        std::vector<Pose> traj;
        Json pcs = Json::array();
        const double radius = arg_number(in, "radius"), cap = arg_number(in, "cap");
        const double dt = opt_num(in, "dt", 0.0);
        for (const Json& p : a) {
          const Point q = point_of(p, "a point");
          traj.push_back(Pose{q.x, q.y, 0.0});
          pcs.push_back(number(point_clearance(q, obs, radius, cap, static_cast<double>(traj.size()) * dt)));
        }
        return Json{{"clearance", number(trajectory_clearance(traj, obs, radius, cap, at, dt))}, {"point_clearances", pcs}};
      }});
  r.add(Rule{
      "sensors2023.dwa.step",
      "One DWA control step: window, candidates, predicted trajectories, clearance, heading to the target, Eq. 12, Eq. 13",
      "pathref::dwa::control_step",
      {{"grid", "grid", "rows, top first"},
       {"pose", "number[3]", "[x, y, theta]"}, {"v_c", "number", ""}, {"w_c", "number", ""},
       {"target", "number[2]", "current key node"},
       {"temporary", "cell[]", "optional"}, {"discs", "object[]", "optional {c, r}"},
       {"dwa", "object", "optional: the scenario's dwa block (project defaults otherwise)"},
       {"radius", "number", "optional robot radius (0.3)"}},
      {{"v", "number", ""}, {"w", "number", ""}, {"braked", "bool", ""}, {"candidates", "integer", ""},
       {"valid", "integer", ""}, {"best", "integer", ""}, {"score", "number", ""}},
      [](const Json& in) {
        const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
        const std::vector<grid::Cell> temp = cells_arg(in, "temporary");
        const std::vector<Disc> discs = discs_arg(in);
        DwaParams prm;
        if (in.contains("dwa")) prm = dwa_params_from_json(arg(in, "dwa"), prm);
        prm.radius = opt_num(in, "radius", prm.radius);
        const StepResult s = control_step(pose_arg(in, "pose"), arg_number(in, "v_c"), arg_number(in, "w_c"),
                                          point_arg(in, "target"), Obstacles{&g, temp, discs}, prm);
        return Json{{"v", number(s.v)}, {"w", number(s.w)}, {"braked", s.braked}, {"candidates", s.candidates},
                    {"valid", s.valid}, {"best", s.best}, {"score", number(s.score)}};
      }});
  r.add(Rule{
      "sensors2023.dwa.follow",
      "Key nodes of a path (turning cells) and the switching / skipping rule of the current key node",
      "pathref::dwa::follow_update, pathref::dwa::key_nodes, pathref::dwa::path_waypoints",
      {{"path", "cell[]", "optional: a global path; outputs its key nodes"},
       {"waypoints_of", "number[2][]", "optional: path nodes (m); outputs their waypoints (heading_target = waypoint)"},
       {"spacing", "number", "optional (1.0): waypoint spacing"},
       {"keys", "number[2][]", "key node points (m)"}, {"blocked", "bool[]", "per key node"},
       {"k", "integer", "current key index"}, {"since", "number", ""}, {"blocked_for", "number", ""},
       {"p", "number[2]", "robot position"}, {"t", "number", "now"}, {"dt", "number", ""},
       {"reach", "number", "optional (1.0)"}, {"blocked_timeout", "number", "optional (3)"},
       {"key_timeout", "number", "optional (30)"}},
      {{"key_nodes", "cell[]", "with path"}, {"waypoints", "number[2][]", "with waypoints_of"}, {"k", "integer", ""}, {"since", "number", ""},
       {"blocked_for", "number", ""}, {"switched", "integer", ""}, {"skipped", "string", "none | blocked | timeout"}},
      [](const Json& in) {
        Json out = Json::object();
        if (in.contains("path")) out["key_nodes"] = grid::path_to_json(key_nodes(grid::path_from_json(arg(in, "path"))));
        if (in.contains("waypoints_of")) {
          std::vector<Point> nodes;
          for (const Json& q : arg(in, "waypoints_of")) nodes.push_back(point_of(q, "a path node"));
          Json w = Json::array();
          for (const Point& q : path_waypoints(nodes, opt_num(in, "spacing", 1.0))) w.push_back(Json::array({number(q.x), number(q.y)}));
          out["waypoints"] = w;
        }
        if (in.contains("keys")) {
          std::vector<Point> keys;
          for (const Json& k : arg(in, "keys")) keys.push_back(point_of(k, "a key node"));
          std::vector<std::uint8_t> bl;
          for (const Json& b : arg(in, "blocked")) {
            if (!b.is_boolean()) throw UsageError("'blocked' must hold bools");
            bl.push_back(b.get<bool>() ? 1 : 0);
          }
          FollowParams fp;
          fp.reach = opt_num(in, "reach", fp.reach);
          fp.blocked_timeout = opt_num(in, "blocked_timeout", fp.blocked_timeout);
          fp.key_timeout = opt_num(in, "key_timeout", fp.key_timeout);
          const FollowState st{arg_integer(in, "k"), arg_number(in, "since"), arg_number(in, "blocked_for")};
          const FollowUpdate u = follow_update(st, point_arg(in, "p"), keys, arg_number(in, "t"), arg_number(in, "dt"), fp, bl);
          out["k"] = u.state.k;
          out["since"] = number(u.state.since);
          out["blocked_for"] = number(u.state.blocked_for);
          out["switched"] = u.switched;
          out["skipped"] = std::string(to_string(u.skipped));
        }
        return out;
      }});
  r.add(Rule{
      "sensors2023.sim.obstacles",
      "Position of a moving obstacle on timed piecewise-linear waypoints (clamped at the ends)",
      "pathref::dwa::obstacle_position",
      {{"waypoints", "number[3][]", "[t, x, y], t strictly increasing"}, {"t", "number", "time, s"}},
      {{"position", "number[2]", ""}},
      [](const Json& in) {
        const Point p = obstacle_position(waypoints_of(arg(in, "waypoints")), arg_number(in, "t"));
        return Json{{"position", Json::array({number(p.x), number(p.y)})}};
      }});
  r.add(Rule{
      "sensors2023.sim.collision",
      "Continuous-time step clearance of the robot disc moving a -> b over [t0, t1] vs cells and moving discs",
      "pathref::dwa::step_clearance, pathref::dwa::segment_cell_distance",
      {{"grid", "grid", "rows, top first"}, {"a", "number[2]", ""}, {"b", "number[2]", ""},
       {"t0", "number", ""}, {"t1", "number", ""}, {"radius", "number", "robot radius"},
       {"temporary", "cell[]", "optional: temporary cells present during the step"},
       {"movers", "object[]", "optional: {r, waypoints}"}},
      {{"clearance", "number", "m (capped at 10)"}, {"collides", "bool", "clearance < 0"}},
      [](const Json& in) {
        const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
        const std::vector<grid::Cell> temp = cells_arg(in, "temporary");
        const std::vector<Mover> movers = movers_arg(in);
        const double c = step_clearance(point_arg(in, "a"), point_arg(in, "b"), arg_number(in, "t0"),
                                        arg_number(in, "t1"), arg_number(in, "radius"), g, temp, movers);
        return Json{{"clearance", number(c)}, {"collides", c < 0.0}};
      }});
  r.add(Rule{
      "sensors2023.sim.turns",
      "Turns of a continuous track: same-sign runs of heading changes >= delta summing to >= theta (resampled at ds)",
      "pathref::dwa::count_turns, pathref::dwa::track_length",
      {{"track", "number[2][]", "positions"}, {"ds", "number", "optional (1.0 m)"},
       {"delta_deg", "number", "optional (2.5)"}, {"theta_deg", "number", "optional (20)"}},
      {{"turns", "integer", ""}, {"length", "number", "m"}},
      [](const Json& in) {
        std::vector<Point> tr;
        for (const Json& p : arg(in, "track")) tr.push_back(point_of(p, "a track point"));
        TurnParams tp;
        tp.ds = opt_num(in, "ds", tp.ds);
        if (in.contains("delta_deg")) tp.delta = arg_number(in, "delta_deg") / deg_per_rad;
        if (in.contains("theta_deg")) tp.theta = arg_number(in, "theta_deg") / deg_per_rad;
        return Json{{"turns", count_turns(tr, tp)}, {"length", number(track_length(tr))}};
      }});
  r.add(Rule{
      "sensors2023.sim.run",
      "The fused run of a pathref-sim 2 scenario: global path, key nodes, following DWA, moving and temporary obstacles",
      "pathref::dwa::simulate_fused",
      {{"scenario", "object", "a pathref-sim 2 scenario with the map as rows"}},
      {{"outcome", "string", "reached | collided | stalled | timed_out | no_global_path"},
       {"time", "number", ""}, {"length", "number", ""}, {"min_clearance", "number", ""},
       {"turns", "integer", ""}, {"steps", "integer", ""}, {"braked_steps", "integer", ""},
       {"key_nodes", "cell[]", ""}, {"skips", "object[]", ""}, {"end", "number[3]", "final pose"}},
      [](const Json& in) {
        const FusedScenario s = fused_scenario_from_json(arg(in, "scenario"), "<eval>");
        const FusedResult res = simulate_fused(s);
        Json j = to_json(res, false);
        Json out{{"outcome", j["outcome"]}, {"time", number(res.time)}, {"length", number(res.length)},
                 {"min_clearance", number(res.min_clearance)}, {"turns", res.turns}, {"steps", res.steps},
                 {"braked_steps", res.braked_steps}, {"key_nodes", j["key_nodes"]}, {"skips", j["skips"]},
                 {"end", pose_json(res.samples.empty() ? Pose{} : res.samples.back().pose)}};
        return out;
      }});
}

}  // namespace pathref::rules
