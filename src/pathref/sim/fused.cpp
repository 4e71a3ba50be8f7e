// The fused system of sensors2023 (global path + following DWA) and its scenario format
// "pathref-sim 2". Spec: spec/sensors2023-dwa.md (sensors2023.sim.run).
#include "pathref/sim/fused.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "pathref/core/error.hpp"
#include "pathref/io/json_reader.hpp"
#include "pathref/io/json_text.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/sim/simulate.hpp"

namespace pathref::dwa {

namespace {

/// The scenario reader: io::JsonReader plus the format's cells and option names.
class Reader : public io::JsonReader {
 public:
  using io::JsonReader::JsonReader;

  [[nodiscard]] grid::Cell cell(const Json& v, const std::string& ptr) const {
    if (!v.is_array() || v.size() != 2) fail(ptr, "expected a cell [x, y] (two integers), got " + kind(v));
    return grid::Cell{integer(v[0], ptr + "/0", 0, 1000000), integer(v[1], ptr + "/1", 0, 1000000)};
  }
  /// An option name through the rule's parser; the UsageError becomes a ParseError here.
  template <class F>
  auto option(const Json& v, const std::string& ptr, F parse) const {
    const std::string s = string(v, ptr);
    try {
      return parse(s);
    } catch (const UsageError& e) {
      fail(ptr, e.what());
    }
  }
};

using io::find;

DwaParams read_dwa(const Reader& rd, const Json& o, const std::string& ptr, DwaParams p, HeadingTarget* target) {
  rd.keys(o, ptr, {"dt", "horizon", "v_min", "v_max", "w_max", "acc_v", "dec_v", "acc_w", "dec_w", "v_res", "w_res",
                   "alpha", "beta", "gamma", "k_heading", "k_clearance", "k_velocity", "clearance_cap",
                   "evaluation", "clearance_at", "heading_wrap", "window_upper", "admissible", "motion_order",
                   "heading_target", "obstacle_prediction"});
  auto num = [&](const char* key, double& dst, double lo, double hi, bool open) {
    if (const Json* v = find(o, key)) dst = rd.number(*v, ptr + "/" + key, lo, hi, open);
  };
  num("dt", p.dt, 1e-3, 1.0, false);
  num("horizon", p.horizon, 0.0, 60.0, true);
  num("v_min", p.limits.v_min, -100.0, 100.0, false);
  num("v_max", p.limits.v_max, -100.0, 100.0, false);
  num("w_max", p.limits.w_max, 0.0, 100.0, false);
  num("acc_v", p.limits.acc_v, 0.0, 1000.0, false);
  num("dec_v", p.limits.dec_v, 0.0, 1000.0, false);
  num("acc_w", p.limits.acc_w, 0.0, 1000.0, false);
  num("dec_w", p.limits.dec_w, 0.0, 1000.0, false);
  num("v_res", p.v_res, 0.0, 100.0, true);
  num("w_res", p.w_res, 0.0, 100.0, true);
  num("alpha", p.weights.alpha, 0.0, 1e6, false);
  num("beta", p.weights.beta, 0.0, 1e6, false);
  num("gamma", p.weights.gamma, 0.0, 1e6, false);
  num("k_heading", p.weights.k_heading, 0.0, 1e6, false);
  num("k_clearance", p.weights.k_clearance, 0.0, 1e6, false);
  num("k_velocity", p.weights.k_velocity, 0.0, 1e6, false);
  num("clearance_cap", p.clearance_cap, 0.0, 100.0, true);
  if (p.limits.v_min > p.limits.v_max) rd.fail(ptr + "/v_min", "expected v_min <= v_max");
  if (std::round(p.horizon / p.dt) < 1.0 || std::round(p.horizon / p.dt) > 10000.0)
    rd.fail(ptr + "/horizon", "expected round(horizon / dt) in [1, 10000]");
  // at most 10^6 candidate pairs: (2 acc dt / res + 1) per axis bounds the window's samples
  const double nv = std::floor(((p.limits.acc_v + p.limits.dec_v) * p.dt) / p.v_res) + 2.0;
  const double nw = std::floor(((p.limits.acc_w + p.limits.dec_w) * p.dt) / p.w_res) + 2.0;
  if (nv * nw > 1e6) rd.fail(ptr + "/v_res", "expected at most 10^6 candidate pairs per window (coarser resolutions)");
  if (const Json* v = find(o, "evaluation")) p.evaluation = rd.option(*v, ptr + "/evaluation", parse_evaluation);
  if (const Json* v = find(o, "clearance_at")) p.clearance_at = rd.option(*v, ptr + "/clearance_at", parse_clearance_at);
  if (const Json* v = find(o, "heading_wrap")) p.heading_wrap = rd.option(*v, ptr + "/heading_wrap", parse_heading_wrap);
  if (const Json* v = find(o, "window_upper")) p.window_upper = rd.option(*v, ptr + "/window_upper", parse_window_upper);
  if (const Json* v = find(o, "admissible")) p.admissible = rd.option(*v, ptr + "/admissible", parse_admissible);
  if (const Json* v = find(o, "motion_order")) p.motion_order = rd.option(*v, ptr + "/motion_order", parse_motion_order);
  if (const Json* v = find(o, "obstacle_prediction")) {
    const std::string s = rd.string(*v, ptr + "/obstacle_prediction");
    if (s != "linear" && s != "static")
      rd.fail(ptr + "/obstacle_prediction", "expected \"linear\" or \"static\", got \"" + s + "\"");
    p.predict_movers = s == "linear";
  }
  if (const Json* v = find(o, "heading_target")) {
    const std::string s = rd.string(*v, ptr + "/heading_target");
    if (s != "key-node" && s != "waypoint" && s != "goal")
      rd.fail(ptr + "/heading_target", "expected \"key-node\", \"waypoint\" or \"goal\", got \"" + io::printable(s) + "\"");
    if (target != nullptr)
      *target = s == "goal" ? HeadingTarget::goal : s == "waypoint" ? HeadingTarget::waypoint : HeadingTarget::key_node;
  }
  return p;
}

FusedScenario read_scenario(const Reader& rd, const Json& doc, const std::string& base_dir) {
  rd.keys(doc, "", {"format", "map", "start", "goal", "policy", "path", "planner", "seed", "heading0", "t_max", "dwa",
                    "robot", "follow", "stall", "turns", "moving", "temporary", "comment"});
  FusedScenario s;
  const Json* fmtv = find(doc, "format");
  if (fmtv == nullptr) rd.fail("", "missing key /format (expected \"pathref-sim 2\")");
  if (rd.string(*fmtv, "/format") != "pathref-sim 2") rd.fail("/format", "expected \"pathref-sim 2\"");
  const Json* mapv = find(doc, "map");
  if (mapv == nullptr) rd.fail("", "missing key /map (expected rows or a map file name)");
  std::optional<grid::Cell> fstart, fgoal;
  if (mapv->is_string()) {
    const std::string name = mapv->get<std::string>();
    std::filesystem::path fp(name);
    if (fp.is_relative() && !base_dir.empty()) fp = std::filesystem::path(base_dir) / fp;
    io::MapReadOptions opt;
    opt.limits.max_cells = 1000000;
    opt.limits.max_side = 1000000;
    // A map file that cannot be read as a grid (missing, unreadable, a polygon scene) is reported at
    // this file's /map; the map file's own syntax errors keep their own file, line and column.
    io::LoadedMapFile loaded = [&] {
      try {
        return io::load_map_file(fp.string(), opt);
      } catch (const UsageError& e) {
        rd.fail("/map", e.what());
      }
    }();
    s.grid = std::move(loaded.map.grid);
    fstart = loaded.map.start;
    fgoal = loaded.map.goal;
  } else if (mapv->is_array()) {
    if (mapv->empty() || mapv->size() > 1000) rd.fail("/map", "expected 1 to 1000 rows");
    std::vector<std::string> rows;
    for (std::size_t i = 0; i < mapv->size(); ++i) {
      const std::string r = rd.string((*mapv)[i], "/map/" + std::to_string(i));
      if (r.empty() || r.size() > 1000 || r.find_first_not_of(".#") != std::string::npos ||
          (!rows.empty() && r.size() != rows.front().size()))
        rd.fail("/map/" + std::to_string(i), "expected a row of 1 to 1000 '.' or '#', all rows of equal length");
      rows.push_back(r);
    }
    s.grid = grid::Grid::from_rows_top_first(rows);
  } else {
    rd.fail("/map", "expected rows (an array of strings) or a map file name, got " + Reader::kind(*mapv));
  }
  auto read_end = [&](const char* key, std::optional<grid::Cell> dflt) {
    const std::string ptr = std::string("/") + key;
    grid::Cell c;
    if (const Json* v = find(doc, key)) {
      c = rd.cell(*v, ptr);
    } else if (dflt) {
      c = *dflt;
    } else {
      rd.fail("", "missing key " + ptr + " (expected a cell [x, y])");
    }
    if (!s.grid.free(c)) rd.fail(ptr, "expected a free cell inside the map");
    return c;
  };
  s.start = read_end("start", fstart);
  s.goal = read_end("goal", fgoal);
  if (const Json* v = find(doc, "policy")) {
    const std::string p = rd.string(*v, "/policy");
    try {
      s.policy = grid::parse_corner_policy(p);
    } catch (const Error& e) {
      rd.fail("/policy", e.what());
    }
  }
  if (const Json* v = find(doc, "path")) {
    if (!v->is_array() || v->empty() || v->size() > 1000000) rd.fail("/path", "expected 1 to 10^6 cells");
    for (std::size_t i = 0; i < v->size(); ++i) {
      const std::string ptr = "/path/" + std::to_string(i);
      const grid::Cell c = rd.cell((*v)[i], ptr);
      if (!s.grid.free(c)) rd.fail(ptr, "expected a free cell inside the map");
      s.path.push_back(c);
    }
    if (!(s.path.front() == s.start) || !(s.path.back() == s.goal))
      rd.fail("/path", "expected a path from start to goal");
  }
  if (const Json* v = find(doc, "planner")) {
    if (v->is_string()) {
      s.planner = v->get<std::string>();
      sim::check_planner(rd, s.planner, s.planner_params, "/planner");
    } else {
      rd.keys(*v, "/planner", {"name", "params"});
      const Json* n = find(*v, "name");
      if (n == nullptr) rd.fail("/planner", "missing key name");
      s.planner = rd.string(*n, "/planner/name");
      if (const Json* p = find(*v, "params")) {
        if (!p->is_object()) rd.fail("/planner/params", "expected an object");
        s.planner_params = *p;
      }
      sim::check_planner(rd, s.planner, s.planner_params, "/planner/name");
    }
  }
  if (const Json* v = find(doc, "seed")) s.seed = static_cast<std::uint32_t>(rd.integer(*v, "/seed", 0, 4294967295LL));
  if (const Json* v = find(doc, "heading0")) s.heading0 = rd.number(*v, "/heading0", -1e3, 1e3);
  if (const Json* v = find(doc, "dwa")) s.dwa = read_dwa(rd, *v, "/dwa", s.dwa, &s.heading_target);
  if (const Json* v = find(doc, "t_max")) s.t_max = rd.number(*v, "/t_max", 0.0, 1e5, true);
  if (s.t_max / s.dwa.dt > max_fused_steps) rd.fail("/t_max", "expected t_max / dt <= 10^6");
  if (const Json* v = find(doc, "robot")) {
    rd.keys(*v, "/robot", {"radius"});
    if (const Json* r = find(*v, "radius")) s.dwa.radius = rd.number(*r, "/robot/radius", 0.0, 10.0);
  }
  if (const Json* v = find(doc, "follow")) {
    rd.keys(*v, "/follow", {"reach", "goal_reach", "blocked_margin", "blocked_timeout", "key_timeout", "waypoint_spacing"});
    if (const Json* r = find(*v, "reach")) s.follow.reach = rd.number(*r, "/follow/reach", 0.0, 100.0, true);
    if (const Json* r = find(*v, "goal_reach")) s.goal_reach = rd.number(*r, "/follow/goal_reach", 0.0, 100.0, true);
    if (const Json* r = find(*v, "blocked_margin"))
      s.blocked_margin = rd.number(*r, "/follow/blocked_margin", 0.0, 100.0);
    if (const Json* r = find(*v, "blocked_timeout"))
      s.follow.blocked_timeout = rd.number(*r, "/follow/blocked_timeout", 0.0, 1e5, true);
    if (const Json* r = find(*v, "key_timeout"))
      s.follow.key_timeout = rd.number(*r, "/follow/key_timeout", 0.0, 1e5, true);
    if (const Json* r = find(*v, "waypoint_spacing"))
      s.waypoint_spacing = rd.number(*r, "/follow/waypoint_spacing", 0.01, 100.0);
  }
  if (const Json* v = find(doc, "stall")) {
    rd.keys(*v, "/stall", {"window", "distance"});
    if (const Json* r = find(*v, "window")) s.stall_window = rd.number(*r, "/stall/window", 0.0, 1e5, true);
    if (const Json* r = find(*v, "distance")) s.stall_distance = rd.number(*r, "/stall/distance", 0.0, 100.0);
  }
  if (const Json* v = find(doc, "turns")) {
    rd.keys(*v, "/turns", {"ds", "delta_deg", "theta_deg"});
    if (const Json* r = find(*v, "ds")) s.turns.ds = rd.number(*r, "/turns/ds", 0.0, 100.0, true);
    if (const Json* r = find(*v, "delta_deg"))
      s.turns.delta = rd.number(*r, "/turns/delta_deg", 0.0, 180.0, true) / deg_per_rad;
    if (const Json* r = find(*v, "theta_deg"))
      s.turns.theta = rd.number(*r, "/turns/theta_deg", 0.0, 3600.0, true) / deg_per_rad;
    if (s.turns.delta > s.turns.theta) rd.fail("/turns/delta_deg", "expected delta_deg <= theta_deg");
  }
  if (const Json* v = find(doc, "moving")) {
    if (!v->is_array() || v->size() > max_fused_movers) rd.fail("/moving", "expected an array of at most 64 obstacles");
    for (std::size_t i = 0; i < v->size(); ++i) {
      const std::string ptr = "/moving/" + std::to_string(i);
      const Json& o = (*v)[i];
      rd.keys(o, ptr, {"radius", "waypoints"});
      Mover m;
      if (const Json* r = find(o, "radius")) m.r = rd.number(*r, ptr + "/radius", 0.0, 10.0);
      const Json* w = find(o, "waypoints");
      if (w == nullptr) rd.fail(ptr, "missing key waypoints (expected [[t, x, y], ...])");
      if (!w->is_array() || w->empty() || w->size() > max_fused_waypoints)
        rd.fail(ptr + "/waypoints", "expected 1 to 1000 waypoints [t, x, y]");
      for (std::size_t j = 0; j < w->size(); ++j) {
        const std::string wp = ptr + "/waypoints/" + std::to_string(j);
        const Json& a = (*w)[j];
        if (!a.is_array() || a.size() != 3) rd.fail(wp, "expected [t, x, y]");
        Waypoint q{rd.number(a[0], wp + "/0", -1e6, 1e6), Point{rd.number(a[1], wp + "/1", -1e6, 1e6),
                                                                rd.number(a[2], wp + "/2", -1e6, 1e6)}};
        if (!m.waypoints.empty() && !(q.t > m.waypoints.back().t)) rd.fail(wp + "/0", "expected times increasing strictly");
        m.waypoints.push_back(q);
      }
      s.moving.push_back(std::move(m));
    }
  }
  if (const Json* v = find(doc, "temporary")) {
    if (!v->is_array() || v->size() > max_fused_temporary)
      rd.fail("/temporary", "expected an array of at most 4096 temporary cells");
    for (std::size_t i = 0; i < v->size(); ++i) {
      const std::string ptr = "/temporary/" + std::to_string(i);
      const Json& o = (*v)[i];
      rd.keys(o, ptr, {"cell", "appear", "disappear"});
      Temporary tc;
      const Json* c = find(o, "cell");
      if (c == nullptr) rd.fail(ptr, "missing key cell");
      tc.cell = rd.cell(*c, ptr + "/cell");
      if (!s.grid.in_bounds(tc.cell)) rd.fail(ptr + "/cell", "expected a cell inside the map");
      tc.appear = 0.0;
      tc.disappear = 1e5;
      if (const Json* a = find(o, "appear")) tc.appear = rd.number(*a, ptr + "/appear", 0.0, 1e5);
      if (const Json* d = find(o, "disappear")) tc.disappear = rd.number(*d, ptr + "/disappear", 0.0, 1e5);
      if (!(tc.appear < tc.disappear)) rd.fail(ptr + "/disappear", "expected appear < disappear");
      s.temporary.push_back(tc);
    }
  }
  return s;
}

double dist(Point a, Point b) {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return std::sqrt((dx * dx) + (dy * dy));
}

Point centre_of(grid::Cell c) { return Point{static_cast<double>(c.x) + 0.5, static_cast<double>(c.y) + 0.5}; }

}  // namespace

std::string scenario_format(std::string_view text) {
  try {
    const Json doc = io::parse_json_text(text, "");
    if (doc.is_object()) {
      const auto it = doc.find("format");
      if (it != doc.end() && it->is_string()) return it->get<std::string>();
    }
  } catch (const std::exception&) {
  }
  return {};
}

FusedScenario parse_fused_scenario(std::string_view text, std::string_view file, const std::string& base_dir) {
  const Json doc = io::parse_json_text(text, file);
  const Reader rd(file, text);
  FusedScenario s = read_scenario(rd, doc, base_dir);
  if (!s.planner_params.empty()) {
    // Where the parameters were written, for the planner's located refusals at run time.
    planners::ParamsSource at{std::string(file), 0, 0, "/planner/params"};
    if (!text.empty()) std::tie(at.line, at.column) = io::line_column(text, io::pointer_offset(text, at.pointer));
    s.planner_params_at = at;
  }
  return s;
}

FusedScenario fused_scenario_from_json(const Json& doc, std::string_view file) {
  const Reader rd(file, {});
  return read_scenario(rd, doc, "");
}

DwaParams dwa_params_from_json(const Json& block, DwaParams base, HeadingTarget* heading_target) {
  const Reader rd("<eval>", {});
  return read_dwa(rd, block, "/dwa", base, heading_target);
}

std::string_view to_string(HeadingTarget h) noexcept {
  switch (h) {
    case HeadingTarget::key_node: return "key-node";
    case HeadingTarget::waypoint: return "waypoint";
    case HeadingTarget::goal: return "goal";
  }
  return "key-node";
}

std::string_view to_string(Outcome o) noexcept {
  switch (o) {
    case Outcome::reached: return "reached";
    case Outcome::collided: return "collided";
    case Outcome::stalled: return "stalled";
    case Outcome::timed_out: return "timed_out";
    case Outcome::no_global_path: return "no_global_path";
  }
  return "timed_out";
}

FusedGlobal fused_global_path(const FusedScenario& s) {
  require(s.grid.free(s.start) && s.grid.free(s.goal), "sensors2023.sim.run: start and goal must be free cells");
  FusedGlobal g;
  if (!s.path.empty()) {
    require(s.path.front() == s.start && s.path.back() == s.goal, "sensors2023.sim.run: the path must run from start to goal");
    for (const grid::Cell& c : s.path) require(s.grid.free(c), "sensors2023.sim.run: path cells must be free");
    g.found = true;
    g.path = s.path;
  } else {
    const planners::Planner* p = planners::find_planner(s.planner);
    if (p == nullptr) throw UsageError("simulate: unknown planner '" + s.planner + "' for the global path");
    planners::Request req;
    req.grid = &s.grid;
    req.start = s.start;
    req.goal = s.goal;
    req.policy = s.policy;
    req.seed = s.seed;
    req.params = s.planner_params;
    const planners::Result r = planners::run_with_params_from(*p, req, s.planner_params_at);
    g.found = r.found && !r.path.empty();
    g.path = r.path;
  }
  if (g.found) g.keys = key_nodes(g.path);
  return g;
}

FusedResult simulate_fused(const FusedScenario& s) {
  require(std::isfinite(s.t_max) && s.t_max > 0.0 && s.t_max / s.dwa.dt <= max_fused_steps,
          "sensors2023.sim.run: need 0 < t_max, t_max / dt <= 10^6");
  require(s.goal_reach > 0.0 && s.blocked_margin >= 0.0 && s.stall_window > 0.0 && s.stall_distance >= 0.0,
          "sensors2023.sim.run: bad follow or stall parameters");
  FusedResult res;
  const FusedGlobal g = fused_global_path(s);
  res.global_found = g.found;
  res.global_path = g.path;
  res.key_nodes = g.keys;
  if (!g.found) {
    res.outcome = Outcome::no_global_path;
    return res;
  }
  // the target points the follow rule switches through: the key nodes, or under
  // heading_target = waypoint the global path's waypoints (path_waypoints of the key nodes)
  std::vector<Point> keys;
  for (const grid::Cell& c : g.keys) keys.push_back(centre_of(c));
  const Point goal = centre_of(s.goal);
  const double dt = s.dwa.dt;
  Pose pose{keys.front().x, keys.front().y, 0.0};
  if (s.heading0) {
    pose.theta = *s.heading0;
  } else if (keys.size() > 1) {
    pose.theta = std::atan2(keys[1].y - keys[0].y, keys[1].x - keys[0].x);
  }
  if (s.heading_target == HeadingTarget::waypoint) keys = path_waypoints(keys, s.waypoint_spacing);
  double v = 0.0, w = 0.0;
  FollowState fs;
  const auto stall_n = static_cast<std::int64_t>(std::llround(s.stall_window / dt));
  std::vector<Point> track;
  std::vector<grid::Cell> present;
  std::vector<Disc> discs;
  std::vector<std::uint8_t> blocked(keys.size(), 0);
  res.min_clearance = 10.0;
  for (std::int64_t k = 0;; ++k) {
    const double t = static_cast<double>(k) * dt;
    const Point p{pose.x, pose.y};
    res.samples.push_back(FusedSample{t, pose, v, w, fs.k});
    track.push_back(p);
    std::vector<Point> at;
    for (const Mover& m : s.moving) at.push_back(obstacle_position(m.waypoints, t));
    res.tracks.push_back(at);
    res.time = t;
    // 1. goal test
    if (dist(p, goal) <= s.goal_reach) {
      res.outcome = Outcome::reached;
      break;
    }
    // obstacles at time t
    present.clear();
    for (const Temporary& tc : s.temporary)
      if (tc.appear <= t && t < tc.disappear) present.push_back(tc.cell);
    discs.clear();
    for (std::size_t i = 0; i < s.moving.size(); ++i) {
      // velocity estimated from the last two observations (t - dt, t); zero at t = 0
      Point vel{0.0, 0.0};
      if (k > 0) {
        const Point before = obstacle_position(s.moving[i].waypoints, static_cast<double>(k - 1) * dt);
        vel = Point{(at[i].x - before.x) / dt, (at[i].y - before.y) / dt};
      }
      discs.push_back(Disc{at[i], s.moving[i].r, vel});
    }
    const Obstacles obs{&s.grid, present, discs};
    // 2. follow update
    for (std::size_t i = 0; i < keys.size(); ++i)
      blocked[i] = point_clearance(keys[i], obs, s.dwa.radius, s.blocked_margin + 1.0) < s.blocked_margin ? 1 : 0;
    const FollowUpdate fu = follow_update(fs, p, keys, t, dt, s.follow, blocked);
    if (fu.skipped != SkipReason::none) res.skips.push_back(Skip{t, fs.k + fu.switched, fu.skipped});
    fs = fu.state;
    res.samples.back().key = fs.k;
    // 3. stall, 4. time
    if (k >= stall_n && stall_n > 0 &&
        dist(p, track[static_cast<std::size_t>(k - stall_n)]) < s.stall_distance) {
      res.outcome = Outcome::stalled;
      break;
    }
    if (t >= s.t_max) {
      res.outcome = Outcome::timed_out;
      break;
    }
    // 5. control step
    const Point target = s.heading_target == HeadingTarget::goal ? goal : keys[static_cast<std::size_t>(fs.k)];
    const StepResult st = control_step(pose, v, w, target, obs, s.dwa);
    res.braked_steps += st.braked ? 1 : 0;
    v = st.v;
    w = st.w;
    res.samples.back().v = v;
    res.samples.back().w = w;
    // 6. move and collision test over [t, t + dt]
    const Pose next = motion_step(pose, v, w, dt, s.dwa.motion_order);
    const double t1 = static_cast<double>(k + 1) * dt;
    present.clear();
    for (const Temporary& tc : s.temporary)
      if (tc.appear < t1 && tc.disappear > t) present.push_back(tc.cell);
    const double clr = step_clearance(p, Point{next.x, next.y}, t, t1, s.dwa.radius, s.grid, present, s.moving);
    res.min_clearance = std::min(res.min_clearance, clr);
    res.length = res.length + dist(p, Point{next.x, next.y});
    pose = next;
    ++res.steps;
    if (clr < 0.0) {
      res.outcome = Outcome::collided;
      res.collision_clearance = clr;
      res.time = t1;
      res.samples.push_back(FusedSample{t1, pose, v, w, fs.k});
      track.push_back(Point{pose.x, pose.y});
      std::vector<Point> at1;
      for (const Mover& m : s.moving) at1.push_back(obstacle_position(m.waypoints, t1));
      res.tracks.push_back(at1);
      break;
    }
  }
  res.turns = count_turns(track, s.turns);
  return res;
}

Json to_json(const FusedResult& r, bool full) {
  auto cells = [](const std::vector<grid::Cell>& cs) {
    Json a = Json::array();
    for (const grid::Cell& c : cs) a.push_back(Json::array({c.x, c.y}));
    return a;
  };
  Json j{{"format", "pathref-sim-result 2"},
         {"outcome", std::string(to_string(r.outcome))},
         {"global_found", r.global_found},
         {"global_path", cells(r.global_path)},
         {"key_nodes", cells(r.key_nodes)},
         {"time", r.time},
         {"length", r.length},
         {"min_clearance", r.min_clearance},
         {"turns", r.turns},
         {"steps", r.steps},
         {"braked_steps", r.braked_steps}};
  Json skips = Json::array();
  for (const Skip& s : r.skips) skips.push_back(Json{{"t", s.t}, {"key", s.key}, {"reason", std::string(to_string(s.reason))}});
  j["skips"] = skips;
  if (r.outcome == Outcome::collided) j["collision_clearance"] = r.collision_clearance;
  if (full) {
    Json samples = Json::array();
    for (const FusedSample& s : r.samples)
      samples.push_back(Json::array({s.t, s.pose.x, s.pose.y, s.pose.theta, s.v, s.w, s.key}));
    j["samples"] = samples;
    j["samples_columns"] = Json::array({"t", "x", "y", "theta", "v", "w", "key"});
    Json tracks = Json::array();
    for (const auto& at : r.tracks) {
      Json row = Json::array();
      for (const Point& p : at) row.push_back(Json::array({p.x, p.y}));
      tracks.push_back(row);
    }
    j["tracks"] = tracks;
  }
  return j;
}

Json params_json(const FusedScenario& s) {
  const DwaParams& d = s.dwa;
  return Json{{"planner", s.path.empty() ? s.planner : std::string("given path")},
              {"policy", std::string(grid::to_string(s.policy))},
              {"seed", s.seed},
              {"t_max", s.t_max},
              {"dwa",
               {{"dt", d.dt},
                {"horizon", d.horizon},
                {"v_min", d.limits.v_min},
                {"v_max", d.limits.v_max},
                {"w_max", d.limits.w_max},
                {"acc_v", d.limits.acc_v},
                {"dec_v", d.limits.dec_v},
                {"acc_w", d.limits.acc_w},
                {"dec_w", d.limits.dec_w},
                {"v_res", d.v_res},
                {"w_res", d.w_res},
                {"alpha", d.weights.alpha},
                {"beta", d.weights.beta},
                {"gamma", d.weights.gamma},
                {"k_heading", d.weights.k_heading},
                {"k_clearance", d.weights.k_clearance},
                {"k_velocity", d.weights.k_velocity},
                {"clearance_cap", d.clearance_cap},
                {"evaluation", std::string(to_string(d.evaluation))},
                {"clearance_at", std::string(to_string(d.clearance_at))},
                {"heading_wrap", std::string(to_string(d.heading_wrap))},
                {"window_upper", std::string(to_string(d.window_upper))},
                {"admissible", std::string(to_string(d.admissible))},
                {"motion_order", std::string(to_string(d.motion_order))},
                {"heading_target", std::string(to_string(s.heading_target))},
                {"obstacle_prediction", d.predict_movers ? "linear" : "static"}}},
              {"robot", {{"radius", d.radius}}},
              {"follow",
               {{"reach", s.follow.reach},
                {"goal_reach", s.goal_reach},
                {"blocked_margin", s.blocked_margin},
                {"blocked_timeout", s.follow.blocked_timeout},
                {"key_timeout", s.follow.key_timeout},
                {"waypoint_spacing", s.waypoint_spacing}}},
              {"stall", {{"window", s.stall_window}, {"distance", s.stall_distance}}},
              {"turns", {{"ds", s.turns.ds}, {"delta_deg", s.turns.delta * deg_per_rad}, {"theta_deg", s.turns.theta * deg_per_rad}}}};
}

}  // namespace pathref::dwa
