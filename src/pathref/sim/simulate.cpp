#include "pathref/sim/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "pathref/core/error.hpp"
#include "pathref/io/json_reader.hpp"
#include "pathref/io/json_text.hpp"
#include "pathref/equations/heuristics.hpp"
#include "pathref/equations/rls.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/planners/search.hpp"
#include "pathref/rng/mt19937.hpp"
#include "pathref/sim/motion.hpp"
#include "pathref/sim/random_map.hpp"

namespace pathref::sim {

// ---------------------------------------------------------------------------------------------
// Scenario parsing (han.sim.scenario-format)

namespace {

/// The scenario reader: io::JsonReader plus the format's points and cells.
class Reader : public io::JsonReader {
 public:
  using io::JsonReader::JsonReader;

  [[nodiscard]] Vec2 point(const Json& v, const std::string& ptr, double bound) const {
    if (!v.is_array() || v.size() != 2) fail(ptr, "expected [x, y] (an array of two numbers), got " + kind(v));
    return Vec2{number(v[0], ptr + "/0", -bound, bound, false), number(v[1], ptr + "/1", -bound, bound, false)};
  }

  [[nodiscard]] grid::Cell cell(const Json& v, const std::string& ptr) const {
    if (!v.is_array() || v.size() != 2) fail(ptr, "expected a cell [x, y] (two integers), got " + kind(v));
    return grid::Cell{integer(v[0], ptr + "/0", 0, 1000000), integer(v[1], ptr + "/1", 0, 1000000)};
  }
};

using io::find;

/// "(x, y)" of a cell, for messages.
[[nodiscard]] std::string cell_text(grid::Cell c) {
  return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")";
}

/// A scenario's given path (han.sim.scenario-format): it runs from start to goal and every step
/// is allowed under the corner policy (grid::step_allowed), each refusal at /path/N.
void check_given_path(const io::JsonReader& rd, const Scenario& s) {
  const std::size_t n = s.path.size();
  if (!(s.path.front() == s.start))
    rd.fail("/path/0", "expected the start " + cell_text(s.start) + ", got " + cell_text(s.path.front()));
  for (std::size_t i = 1; i < n; ++i)
    if (!grid::step_allowed(s.grid, s.path[i - 1], s.path[i], s.policy))
      rd.fail("/path/" + std::to_string(i),
              "expected a free cell one step from " + cell_text(s.path[i - 1]) + " allowed under the corner policy " +
                  std::string(grid::to_string(s.policy)) + ", got " + cell_text(s.path[i]));
  if (!(s.path.back() == s.goal))
    rd.fail("/path/" + std::to_string(n - 1), "expected the goal " + cell_text(s.goal) + " as the last cell, got " +
                                                  cell_text(s.path.back()));
}

}  // namespace

void check_planner(const io::JsonReader& rd, const std::string& name, const Json& params,
                   const std::string& name_ptr) {
  const planners::Planner* p = planners::find_planner(name);
  if (p == nullptr)
    rd.fail(name_ptr, "expected a planner name (" + planners::planner_names() + "), got \"" + io::printable(name) + "\"");
  if (const auto bad = planners::first_bad_param(*p, params))
    rd.fail(io::JsonReader::child("/planner/params", bad->first), "expected a parameter of " + name + ": " + bad->second);
}

namespace {
Scenario read_scenario(const Json& doc, std::string_view file, std::string_view text, const std::string& base_dir);
}  // namespace

Scenario scenario_from_json(const Json& doc, std::string_view file, const std::string& base_dir) {
  return read_scenario(doc, file, {}, base_dir);
}

namespace {
/// scenario_from_json with the file's text at hand for line and column (parse_scenario).
Scenario read_scenario(const Json& doc, std::string_view file, std::string_view text, const std::string& base_dir) {
  const Reader rd(file, text);
  rd.keys(doc, "", {"format", "map", "start", "goal", "policy", "path", "planner", "seed", "dt",
                    "horizon", "robot", "margin", "noise", "t_max", "lambda", "frontal_cos",
                    "obstacles", "comment"});
  Scenario s;
  const Json* fmtv = find(doc, "format");
  if (fmtv == nullptr) rd.fail("/format", "missing (expected \"pathref-sim 1\")");
  if (rd.string(*fmtv, "/format") != "pathref-sim 1")
    rd.fail("/format", "expected \"pathref-sim 1\", got \"" + io::printable(fmtv->get<std::string>()) + "\"");
  // --- map
  const Json* mapv = find(doc, "map");
  if (mapv == nullptr) rd.fail("/map", "missing (expected a map file name, rows or {\"random\": ...})");
  std::optional<grid::Cell> map_start, map_goal;
  if (mapv->is_string()) {
    const std::string name = mapv->get<std::string>();
    std::filesystem::path p(name);
    if (p.is_relative() && !base_dir.empty()) p = std::filesystem::path(base_dir) / p;
    io::MapReadOptions opt;
    opt.limits.max_cells = max_sim_cells;
    opt.limits.max_side = max_sim_cells;
    // A map file that cannot be read as a grid (missing, unreadable, a polygon scene) is reported at
    // this file's /map; the map file's own syntax errors keep their own file, line and column.
    io::LoadedMapFile loaded = [&] {
      try {
        return io::load_map_file(p.string(), opt);
      } catch (const UsageError& e) {
        rd.fail("/map", e.what());
      }
    }();
    s.grid = std::move(loaded.map.grid);
    map_start = loaded.map.start;
    map_goal = loaded.map.goal;
  } else if (mapv->is_array()) {
    const auto h = static_cast<std::int64_t>(mapv->size());
    if (h < 1 || h > 1000) rd.fail("/map", "expected 1 to 1000 rows, got " + std::to_string(h));
    std::vector<std::string> rows;
    for (std::size_t r = 0; r < mapv->size(); ++r) {
      const std::string ptr = "/map/" + std::to_string(r);
      const std::string row = rd.string((*mapv)[r], ptr);
      if (row.empty() || row.size() > 1000) rd.fail(ptr, "expected a row of 1 to 1000 characters");
      if (r > 0 && row.size() != rows[0].size())
        rd.fail(ptr, "expected " + std::to_string(rows[0].size()) + " characters like row 0, got " +
                         std::to_string(row.size()));
      const auto bad = row.find_first_not_of(".#");
      if (bad != std::string::npos)
        rd.fail(ptr, "expected only '.' (free) and '#' (blocked), got '" + row.substr(bad, 1) +
                         "' at column " + std::to_string(bad + 1));
      rows.push_back(row);
    }
    if (static_cast<std::int64_t>(rows[0].size()) * h > max_sim_cells)
      rd.fail("/map", "more than " + std::to_string(max_sim_cells) + " cells");
    s.grid = grid::Grid::from_rows_top_first(rows);
  } else if (mapv->is_object()) {
    rd.keys(*mapv, "/map", {"random"});
    const Json* rv = find(*mapv, "random");
    if (rv == nullptr) rd.fail("/map/random", "missing (expected {\"seed\", \"edge\", \"ratio\"})");
    rd.keys(*rv, "/map/random", {"seed", "edge", "ratio"});
    for (const char* k : {"seed", "edge", "ratio"})
      if (find(*rv, k) == nullptr) rd.fail(std::string("/map/random/") + k, "missing");
    const auto seed = rd.integer(rv->at("seed"), "/map/random/seed", 0, 4294967295LL);
    const auto edge = rd.integer(rv->at("edge"), "/map/random/edge", random_map_min_edge, random_map_max_edge);
    const double ratio = rd.number(rv->at("ratio"), "/map/random/ratio", 0.0, 1.0, false);
    try {
      auto m = random_map(static_cast<std::uint32_t>(seed), edge, ratio);
      s.grid = std::move(m.grid);
      map_start = m.start;
      map_goal = m.goal;
    } catch (const DomainError& e) {
      rd.fail("/map/random", e.what());
    }
  } else {
    rd.fail("/map", "expected a map file name, an array of rows or {\"random\": ...}, got " + Reader::kind(*mapv));
  }
  // --- start, goal
  auto endpoint = [&](const char* key, const std::optional<grid::Cell>& fallback) {
    const std::string ptr = std::string("/") + key;
    grid::Cell c;
    if (const Json* v = find(doc, key)) {
      c = rd.cell(*v, ptr);
    } else if (fallback) {
      c = *fallback;
    } else {
      rd.fail(ptr, "missing (the map gives none)");
    }
    if (!s.grid.in_bounds(c)) rd.fail(ptr, "outside the map");
    if (s.grid.blocked(c)) rd.fail(ptr, "on a blocked cell");
    return c;
  };
  s.start = endpoint("start", map_start);
  s.goal = endpoint("goal", map_goal);
  if (const Json* v = find(doc, "policy")) {
    try {
      s.policy = grid::parse_corner_policy(rd.string(*v, "/policy"));
    } catch (const UsageError&) {
      rd.fail("/policy", "expected never, strict, one or always, got \"" + io::printable(v->get<std::string>()) + "\"");
    }
  }
  if (const Json* v = find(doc, "path")) {
    if (!v->is_array() || v->empty() || v->size() > static_cast<std::size_t>(max_sim_cells))
      rd.fail("/path", "expected a non-empty array of cells");
    for (std::size_t i = 0; i < v->size(); ++i) s.path.push_back(rd.cell((*v)[i], "/path/" + std::to_string(i)));
    check_given_path(rd, s);
  }
  if (const Json* v = find(doc, "planner")) {
    if (v->is_string()) {
      s.planner = v->get<std::string>();
      check_planner(rd, s.planner, s.planner_params, "/planner");
    } else {
      rd.keys(*v, "/planner", {"name", "params"});
      const Json* n = find(*v, "name");
      if (n == nullptr) rd.fail("/planner/name", "missing");
      s.planner = rd.string(*n, "/planner/name");
      if (const Json* p = find(*v, "params")) {
        if (!p->is_object()) rd.fail("/planner/params", "expected an object, got " + Reader::kind(*p));
        s.planner_params = *p;
      }
      check_planner(rd, s.planner, s.planner_params, "/planner/name");
    }
  }
  if (const Json* v = find(doc, "seed")) s.seed = static_cast<std::uint32_t>(rd.integer(*v, "/seed", 0, 4294967295LL));
  if (const Json* v = find(doc, "dt")) s.dt = rd.number(*v, "/dt", 1.0 / 1024.0, 1.0, false);
  if (const Json* v = find(doc, "horizon")) s.horizon = rd.number(*v, "/horizon", 0.0, 100.0, true);
  if (const Json* v = find(doc, "robot")) {
    rd.keys(*v, "/robot", {"radius", "speed", "accel"});
    if (const Json* r = find(*v, "radius")) s.robot_radius = rd.number(*r, "/robot/radius", 0.0, 10.0, true);
    if (const Json* r = find(*v, "speed")) s.speed = rd.number(*r, "/robot/speed", 0.0, 100.0, true);
    if (const Json* r = find(*v, "accel")) s.accel = rd.number(*r, "/robot/accel", 0.0, 100.0, true);
  }
  if (const Json* v = find(doc, "margin")) s.margin = rd.number(*v, "/margin", 0.0, 10.0, false);
  if (const Json* v = find(doc, "noise")) s.noise = rd.number(*v, "/noise", 0.0, 10.0, false);
  if (const Json* v = find(doc, "t_max")) s.t_max = rd.number(*v, "/t_max", 0.0, 100000.0, true);
  if (const Json* v = find(doc, "lambda")) s.lambda = rd.number(*v, "/lambda", 0.0, 1.0, true);
  if (const Json* v = find(doc, "frontal_cos")) s.frontal_cos = rd.number(*v, "/frontal_cos", -1.0, 1.0, false);
  if (std::ceil(s.t_max / s.dt) > static_cast<double>(max_sim_steps))
    rd.fail("/t_max", "t_max / dt must not exceed " + std::to_string(max_sim_steps) + " steps");
  if (const Json* v = find(doc, "obstacles")) {
    if (!v->is_array()) rd.fail("/obstacles", "expected an array, got " + Reader::kind(*v));
    if (v->size() > max_sim_obstacles)
      rd.fail("/obstacles", "at most " + std::to_string(max_sim_obstacles) + " obstacles, got " + std::to_string(v->size()));
    for (std::size_t i = 0; i < v->size(); ++i) {
      const std::string ptr = "/obstacles/" + std::to_string(i);
      const Json& o = (*v)[i];
      rd.keys(o, ptr, {"position", "velocity", "radius"});
      MovingObstacle m;
      for (const char* k : {"position", "velocity"})
        if (find(o, k) == nullptr) rd.fail(ptr + "/" + k, "missing (expected [x, y])");
      m.position = rd.point(o.at("position"), ptr + "/position", 1e6);
      m.velocity = rd.point(o.at("velocity"), ptr + "/velocity", 100.0);
      if (const Json* r = find(o, "radius")) m.radius = rd.number(*r, ptr + "/radius", 0.0, 10.0, true);
      s.obstacles.push_back(m);
    }
  }
  return s;
}
}  // namespace

Scenario parse_scenario(std::string_view text, std::string_view file, const std::string& base_dir) {
  const Json doc = io::parse_json_text(text, file);
  Scenario s = read_scenario(doc, file, text, base_dir);
  if (!s.planner_params.empty()) {
    // Where the parameters were written, for the planner's located refusals at run time.
    planners::ParamsSource at{std::string(file), 0, 0, "/planner/params"};
    if (!text.empty()) std::tie(at.line, at.column) = io::line_column(text, io::pointer_offset(text, at.pointer));
    s.planner_params_at = at;
  }
  return s;
}

// ---------------------------------------------------------------------------------------------
// The run

std::string_view to_string(RobotState s) noexcept {
  switch (s) {
    case RobotState::move: return "move";
    case RobotState::wait: return "wait";
    case RobotState::evade: return "evade";
    case RobotState::arrive: return "arrive";
  }
  return "move";
}

namespace {

double path_length(const std::vector<grid::Cell>& p) {
  double len = 0.0;
  for (std::size_t i = 1; i < p.size(); ++i) len += grid::step_cost(p[i - 1], p[i]);
  return len;
}

/// The robot's plan: cells (adjacent), the global index of each (-1 on a detour or evasion), where
/// the robot is (on the piece seg -> seg+1 at arc offset off, 0 <= off < piece length), and the
/// cell where it stops: the last (the goal), or the refuge of an evasion (han.sim.evade).
struct Plan {
  std::vector<grid::Cell> cells;
  std::vector<std::int64_t> gidx;
  std::size_t seg = 0;
  double off = 0.0;
  std::size_t stop = 0;

  [[nodiscard]] bool at_end() const { return seg + 1 >= cells.size(); }
  [[nodiscard]] bool at_stop() const { return seg >= stop; }
  [[nodiscard]] double piece(std::size_t i) const { return grid::step_cost(cells[i], cells[i + 1]); }
  [[nodiscard]] Vec2 at(std::size_t i, double f) const {
    const Vec2 a = centre(cells[i]);
    if (f == 0.0) return a;
    const Vec2 b = centre(cells[i + 1]);
    const double r = f / piece(i);
    return Vec2{a.x + (r * (b.x - a.x)), a.y + (r * (b.y - a.y))};
  }
  [[nodiscard]] Vec2 position() const { return at_end() ? centre(cells.back()) : at(seg, off); }
  /// Arc length from the robot to cell `last` (>= seg) along the plan.
  [[nodiscard]] double remaining_to(std::size_t last) const {
    if (seg >= last) return 0.0;
    double r = piece(seg) - off;
    for (std::size_t j = seg + 1; j < last; ++j) r += piece(j);
    return r;
  }
  [[nodiscard]] double remaining() const { return remaining_to(cells.size() - 1); }
  /// han.sim.step: the polyline from the robot over arc length L along the plan, truncated at cell
  /// `last` (the goal for the classification, the stop cell for the safety margins).
  [[nodiscard]] std::vector<Vec2> lookahead(double L, std::size_t last) const {
    std::vector<Vec2> pts{position()};
    if (seg >= last) return pts;
    double acc = piece(seg) - off;
    if (acc >= L) {
      pts.push_back(at(seg, off + L));
      return pts;
    }
    pts.push_back(centre(cells[seg + 1]));
    for (std::size_t j = seg + 1; j < last; ++j) {
      const double len = piece(j);
      if (acc + len >= L) {
        pts.push_back(at(j, L - acc));
        return pts;
      }
      acc += len;
      pts.push_back(centre(cells[j + 1]));
    }
    return pts;
  }
  [[nodiscard]] std::vector<Vec2> lookahead(double L) const { return lookahead(L, cells.size() - 1); }
  void advance(double ds) {
    while (ds > 0.0 && !at_end()) {
      const double r = piece(seg) - off;
      if (ds < r) {
        off += ds;
        ds = 0.0;
      } else {
        ds -= r;
        ++seg;
        off = 0.0;
      }
    }
  }
};

struct Tracker {
  std::int64_t samples = 0;
  double t0 = 0.0, x0 = 0.0, y0 = 0.0;
  rls::Estimate est;
};

Vec2 true_position(const MovingObstacle& o, double t) {
  return Vec2{o.position.x + (o.velocity.x * t), o.position.y + (o.velocity.y * t)};
}

/// Distance at closest approach of two points moving linearly over one step (relative motion).
double closest_approach(Vec2 p0, Vec2 p1, Vec2 o0, Vec2 o1) {
  const Vec2 d0{p0.x - o0.x, p0.y - o0.y};
  const Vec2 d1{p1.x - o1.x, p1.y - o1.y};
  return point_segment_distance(Vec2{0.0, 0.0}, d0, d1);
}

}  // namespace

GlobalPath global_path(const Scenario& s) {
  require(s.grid.in_bounds(s.start) && s.grid.free(s.start), "simulate: start must be a free cell of the map");
  require(s.grid.in_bounds(s.goal) && s.grid.free(s.goal), "simulate: goal must be a free cell of the map");
  GlobalPath out;
  if (!s.path.empty()) {
    require(s.path.front() == s.start && s.path.back() == s.goal,
            "simulate: the given path must run from start to goal");
    for (std::size_t i = 1; i < s.path.size(); ++i)
      require(grid::step_allowed(s.grid, s.path[i - 1], s.path[i], s.policy),
              "simulate: the given path has a step not allowed under the corner policy (step " +
                  std::to_string(i) + ")");
    out.found = true;
    out.path = s.path;
    out.length = path_length(s.path);
    return out;
  }
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
  out.found = r.found;
  out.path = r.path;
  out.length = r.found ? path_length(r.path) : 0.0;
  return out;
}

SimResult simulate(const Scenario& s) {
  require(std::isfinite(s.dt) && s.dt > 0.0, "simulate: dt must be > 0");
  require(std::isfinite(s.horizon) && s.horizon > 0.0, "simulate: horizon must be > 0");
  require(std::isfinite(s.t_max) && s.t_max > 0.0, "simulate: t_max must be > 0");
  require(std::ceil(s.t_max / s.dt) <= static_cast<double>(max_sim_steps), "simulate: too many steps");
  require(s.robot_radius > 0.0 && s.margin >= 0.0 && s.noise >= 0.0, "simulate: bad radius, margin or noise");
  require(s.obstacles.size() <= max_sim_obstacles, "simulate: too many obstacles");
  SimResult res;
  const GlobalPath gp = global_path(s);
  res.global_found = gp.found;
  res.global_path = gp.path;
  res.global_length = gp.length;
  if (!gp.found) return res;

  Plan plan;
  plan.cells = gp.path;
  for (std::size_t i = 0; i < gp.path.size(); ++i) plan.gidx.push_back(static_cast<std::int64_t>(i));
  plan.stop = plan.cells.size() - 1;
  const std::size_t n_obs = s.obstacles.size();
  std::vector<Tracker> trackers(n_obs);
  res.obstacle_tracks.assign(n_obs, {});
  rng::Stream noise_stream(s.seed);
  const double look = s.speed * s.horizon;
  double v = 0.0;
  bool waiting = false;
  bool evading = false;  // han.sim.evade: driving to the refuge plan.cells[plan.stop]
  Wait current_wait;
  // Observations before this step's (for the "unobserved" collisions of han.sim.run).
  std::vector<std::int64_t> samples_at_step(n_obs, 0);

  auto record = [&](double t, RobotState st) {
    res.trajectory.push_back(Sample{t, plan.position(), v, st});
    for (std::size_t o = 0; o < n_obs; ++o) res.obstacle_tracks[o].push_back(true_position(s.obstacles[o], t));
  };
  auto clearance_of = [&](std::size_t o) { return (s.robot_radius + s.obstacles[o].radius) + s.margin; };
  // Ground-truth collision check of one motion p0 -> p1 over [ta, tb] (han.sim.step, step 6).
  auto check = [&](double t_step, Vec2 p0, Vec2 p1, double ta, double tb) {
    for (std::size_t o = 0; o < n_obs; ++o) {
      const double d = closest_approach(p0, p1, true_position(s.obstacles[o], ta), true_position(s.obstacles[o], tb));
      if (d < s.robot_radius + s.obstacles[o].radius)
        res.collisions.push_back(Collision{t_step, static_cast<std::int64_t>(o), d,
                                           samples_at_step[o] < 2 ? "unobserved" : ""});
    }
  };

  if (plan.at_end()) {
    res.reached_goal = true;
    record(0.0, RobotState::arrive);
    return res;
  }

  for (std::int64_t k = 0;; ++k) {
    const double t = static_cast<double>(k) * s.dt;
    if (t >= s.t_max) {
      res.time = t;
      if (waiting) {
        current_wait.end = t;
        res.waits.push_back(current_wait);
        res.wait_time += t - current_wait.start;
      }
      break;
    }
    // 1. observe (and draw the noise) -------------------------------------------------------
    for (std::size_t o = 0; o < n_obs; ++o) {
      Vec2 z = true_position(s.obstacles[o], t);
      if (s.noise > 0.0) {
        const double ux = noise_stream.next_double();
        const double uy = noise_stream.next_double();
        z.x = z.x + (((2.0 * ux) - 1.0) * s.noise);
        z.y = z.y + (((2.0 * uy) - 1.0) * s.noise);
      }
      Tracker& tr = trackers[o];
      ++tr.samples;
      if (tr.samples == 1) {
        tr.t0 = t;
        tr.x0 = z.x;
        tr.y0 = z.y;
      } else if (tr.samples == 2) {
        const double ts[2] = {0.0, t - tr.t0};
        const double xs[2] = {tr.x0, z.x};
        const double ys[2] = {tr.y0, z.y};
        tr.est = rls::rls_init(ts, xs, ys, s.lambda);
      } else {
        tr.est = rls::rls_step(tr.est, t - tr.t0, z.x, z.y, s.lambda);
      }
      samples_at_step[o] = tr.samples;
    }
    // 2. classify every predicted obstacle against the lookahead ------------------------------
    const std::vector<Vec2> ahead = plan.lookahead(look);
    std::vector<std::int64_t> frontal, side, conflicting;
    std::vector<std::pair<Vec2, Vec2>> predicted(n_obs);
    std::vector<rls::LinearMotion> motion(n_obs);
    std::vector<double> clock(n_obs, 0.0);
    for (std::size_t o = 0; o < n_obs; ++o) {
      const Tracker& tr = trackers[o];
      if (tr.samples < 2) continue;
      motion[o] = rls::LinearMotion{tr.est.A(0), tr.est.A(1), tr.est.B(0), tr.est.B(1)};
      clock[o] = t - tr.t0;
      const rls::Position a = rls::position(motion[o], clock[o]);
      const rls::Position b = rls::position(motion[o], clock[o] + s.horizon);
      predicted[o] = {Vec2{a.x, a.y}, Vec2{b.x, b.y}};
      const Classification c =
          classify(ahead, predicted[o].first, predicted[o].second, clearance_of(o), s.frontal_cos);
      const auto id = static_cast<std::int64_t>(o);
      if (c.kind == Encounter::none) continue;
      (c.kind == Encounter::frontal ? frontal : side).push_back(id);
      conflicting.push_back(id);
    }
    // han.sim.safety: are waiting / driving on predicted clear of every conflicting obstacle?
    // slack = the worst margin minus the clearance over the conflicting obstacles (>= 0: clear);
    // escapes = driving on is clear and no obstacle is still closing in at the horizon's end.
    struct Prediction {
      double wait_slack = std::numeric_limits<double>::infinity();
      double go_slack = std::numeric_limits<double>::infinity();
      bool closing = false;
    };
    auto predict = [&] {
      const std::vector<Vec2> pts = plan.lookahead(look, plan.stop);
      Prediction pr;
      for (const std::int64_t o : conflicting) {
        const auto uo = static_cast<std::size_t>(o);
        const Margins mg = safety_margins(pts, v, s.speed, s.accel, s.dt, s.horizon, motion[uo], clock[uo]);
        pr.wait_slack = std::min(pr.wait_slack, mg.wait - clearance_of(uo));
        pr.go_slack = std::min(pr.go_slack, mg.go - clearance_of(uo));
        pr.closing = pr.closing || mg.go_closing;
      }
      return pr;
    };
    // The first plan cell the robot reaches (the next one when between cells) and the global index
    // of the first plan cell at or after it that lies on the global path.
    auto plan_start = [&] { return plan.off > 0.0 ? plan.seg + 1 : plan.seg; };
    auto global_from = [&](std::size_t ps) {
      std::int64_t from = -1;
      for (std::size_t i = ps; i < plan.cells.size() && from < 0; ++i) from = plan.gidx[i];
      return from;
    };
    auto band_of_conflicts = [&] {
      grid::Grid blocked = s.grid;
      for (const std::int64_t o : conflicting) {
        const auto uo = static_cast<std::size_t>(o);
        for (const grid::Cell c : swept_cells(s.grid, predicted[uo].first, predicted[uo].second, clearance_of(uo)))
          blocked.set_blocked(c, true);
      }
      return blocked;
    };
    // 3. decide --------------------------------------------------------------------------------
    bool wait_now = false;
    bool evade_now = false;
    if (evading) {
      if (conflicting.empty()) {
        evading = false;  // the lookahead is clear: drive on through the refuge without stopping
        plan.stop = plan.cells.size() - 1;
      } else if (predict().go_slack < 0.0) {
        evade_now = true;
      }
    } else if (!conflicting.empty()) {
      bool replanned = false;
      if (!frontal.empty()) {
        ++res.frontal_decisions;
        const std::size_t ps = plan_start();
        const grid::Cell from_cell = plan.cells[ps];
        const std::int64_t from = global_from(ps);
        const grid::Grid blocked = band_of_conflicts();
        std::vector<std::uint8_t> flags(gp.path.size(), 0);
        for (std::size_t i = 0; i < gp.path.size(); ++i) flags[i] = blocked.blocked(gp.path[i]) ? 1 : 0;
        const std::int64_t target = from >= 0 ? local_target(flags, from) : -1;
        if (target >= 0 && !blocked.blocked(from_cell)) {
          const grid::Cell tcell = gp.path[static_cast<std::size_t>(target)];
          if (!(tcell == from_cell)) {
            const search::Outcome a = search::astar(blocked, from_cell, tcell, s.policy, heuristics::Heuristic::chebyshev);
            if (a.found) {
              Plan np;
              if (plan.off > 0.0) {
                np.cells.push_back(plan.cells[plan.seg]);
                np.gidx.push_back(plan.gidx[plan.seg]);
              }
              for (std::size_t i = 0; i + 1 < a.path.size(); ++i) {
                np.cells.push_back(a.path[i]);
                np.gidx.push_back(-1);
              }
              for (std::size_t i = static_cast<std::size_t>(target); i < gp.path.size(); ++i) {
                np.cells.push_back(gp.path[i]);
                np.gidx.push_back(static_cast<std::int64_t>(i));
              }
              np.seg = 0;
              np.off = plan.off;
              np.stop = np.cells.size() - 1;
              plan = std::move(np);
              res.replans.push_back(Replan{t, from_cell, tcell, target, a.path, frontal});
              replanned = true;
            }
          }
        }
      }
      if (!replanned) {
        const Prediction pr = predict();
        if (pr.wait_slack >= 0.0) wait_now = true;                     // the paper's side rule (and no detour)
        else if (pr.go_slack < 0.0 || pr.closing) evade_now = true;  // else drive on if that escapes
      }
    }
    if (evade_now) {
      // han.sim.evade: the nearest cell off every conflicting obstacle's future path (the band of
      // its ray), from either end of the robot's piece.
      std::vector<std::uint8_t> band(static_cast<std::size_t>(s.grid.cell_count()), 0);
      for (const std::int64_t o : conflicting) {
        const auto uo = static_cast<std::size_t>(o);
        for (const grid::Cell c : swept_ray_cells(s.grid, predicted[uo].first, predicted[uo].second, clearance_of(uo)))
          if (s.grid.free(c)) band[static_cast<std::size_t>(s.grid.index(c))] = 1;
      }
      std::vector<RefugeSource> sources;
      if (plan.off > 0.0) {
        sources.push_back(RefugeSource{plan.cells[plan.seg], plan.off});
        sources.push_back(RefugeSource{plan.cells[plan.seg + 1], plan.piece(plan.seg) - plan.off});
      } else {
        sources.push_back(RefugeSource{plan.cells[plan.seg], 0.0});
      }
      // The obstacles' bodies now are not crossed: cells whose centre is closer than
      // r_robot + r_obstacle to the predicted position p (a robot there would touch the obstacle).
      grid::Grid bodies = s.grid;
      for (const std::int64_t o : conflicting) {
        const auto uo = static_cast<std::size_t>(o);
        const double touch = s.robot_radius + s.obstacles[uo].radius;
        for (std::int64_t i = 0; i < s.grid.cell_count(); ++i) {
          const grid::Cell c = s.grid.cell(i);
          if (point_segment_distance(centre(c), predicted[uo].first, predicted[uo].first) < touch)
            bodies.set_blocked(c, true);
        }
      }
      const Refuge rf = find_refuge(bodies, sources, band, s.policy);
      if (rf.found && evading && rf.path.back() == plan.cells[plan.stop]) {
        // Still the nearest refuge: keep driving to it, although it is predicted to be late.
        res.unavoidable.push_back(Unavoidable{t, conflicting, "late"});
      } else if (rf.found) {
        const bool was_evading = evading;
        const std::int64_t from = global_from(plan_start());
        const grid::Cell target = gp.path[static_cast<std::size_t>(from)];
        const grid::Cell refuge = rf.path.back();
        const bool refuge_is_goal = refuge == gp.path.back();
        std::vector<grid::Cell> rejoin{refuge};
        if (!refuge_is_goal && !(refuge == target)) {
          const search::Outcome a = search::astar(s.grid, refuge, target, s.policy, heuristics::Heuristic::chebyshev);
          require(a.found, "simulate: no way back from the refuge to the global path");
          rejoin = a.path;
        }
        Plan np;
        double off = 0.0;
        if (plan.off > 0.0) {
          // The other end of the robot's piece first, so that the robot starts on that piece.
          const bool back = rf.source == 0;
          const std::size_t other = back ? plan.seg + 1 : plan.seg;
          np.cells.push_back(plan.cells[other]);
          np.gidx.push_back(plan.gidx[other]);
          off = back ? plan.piece(plan.seg) - plan.off : plan.off;
        }
        const bool reverses = plan.off > 0.0 && rf.source == 0;
        const std::size_t src_cell = plan.off > 0.0 ? (rf.source == 0 ? plan.seg : plan.seg + 1) : plan.seg;
        for (std::size_t i = 0; i < rf.path.size(); ++i) {
          np.cells.push_back(rf.path[i]);
          np.gidx.push_back(i == 0 ? plan.gidx[src_cell] : -1);
        }
        np.stop = np.cells.size() - 1;
        if (refuge_is_goal) {
          np.gidx.back() = static_cast<std::int64_t>(gp.path.size()) - 1;
        } else {
          for (std::size_t i = 1; i < rejoin.size(); ++i) {
            np.cells.push_back(rejoin[i]);
            np.gidx.push_back(-1);
          }
          np.gidx.back() = from;  // the rejoin's last cell (or the refuge itself) is global cell `from`
          for (std::size_t i = static_cast<std::size_t>(from) + 1; i < gp.path.size(); ++i) {
            np.cells.push_back(gp.path[i]);
            np.gidx.push_back(static_cast<std::int64_t>(i));
          }
        }
        np.seg = 0;
        np.off = off;
        plan = std::move(np);
        evading = true;
        // A new evasion, or one that turns back on the robot's piece, starts with a stop
        // (han.sim.motion: stops are immediate); a changed refuge ahead keeps the speed.
        if (!was_evading || reverses) v = 0.0;
        res.evasions.push_back(Evasion{t, rf.path.front(), refuge, rf.path, refuge_is_goal ? refuge : target,
                                       refuge_is_goal ? static_cast<std::int64_t>(gp.path.size()) - 1 : from,
                                       conflicting});
        if (predict().go_slack < 0.0) res.unavoidable.push_back(Unavoidable{t, conflicting, "late"});
      } else {
        res.unavoidable.push_back(Unavoidable{t, conflicting, "trapped"});
        const Prediction pr = predict();
        wait_now = pr.wait_slack >= pr.go_slack;  // the larger predicted slack; waiting on ties
      }
    }
    // 4. act -----------------------------------------------------------------------------------
    const Vec2 p0 = plan.position();
    const double t_next = static_cast<double>(k + 1) * s.dt;
    if (wait_now) {
      if (!waiting) {
        waiting = true;
        current_wait = Wait{t, t, conflicting};
      }
      ++res.wait_steps;
      v = 0.0;
      record(t, RobotState::wait);
      check(t, p0, p0, t, t_next);
      continue;
    }
    if (waiting) {
      waiting = false;
      current_wait.end = t;
      res.waits.push_back(current_wait);
      res.wait_time += t - current_wait.start;
    }
    record(t, evading ? RobotState::evade : RobotState::move);
    const MotionStep m = motion_step(v, s.dt, s.speed, s.accel, plan.remaining_to(plan.stop));
    plan.advance(m.distance);
    const bool at_goal = m.arrived && plan.stop + 1 == plan.cells.size();
    if (m.arrived) {
      plan.seg = plan.stop;
      plan.off = 0.0;
    }
    res.distance += m.distance;
    v = m.v_end;
    const double t1 = t + m.time;
    const Vec2 p1 = plan.position();
    check(t, p0, p1, t, t1);
    if (at_goal) {
      res.reached_goal = true;
      res.time = t1;
      record(t1, RobotState::arrive);
      res.steps = k + 1;
      break;
    }
    if (m.arrived) {  // at the refuge: stop there for the rest of the step
      evading = false;
      v = 0.0;
      plan.stop = plan.cells.size() - 1;
      check(t, p1, p1, t1, t_next);
    }
  }
  if (!res.reached_goal) res.steps = static_cast<std::int64_t>(std::ceil(res.time / s.dt));
  res.noise_draws = static_cast<std::int64_t>(noise_stream.doubles_drawn());
  for (const Tracker& tr : trackers)
    res.estimates.push_back(tr.samples >= 2 ? std::vector<double>{tr.est.A(0), tr.est.A(1), tr.est.B(0), tr.est.B(1)}
                                            : std::vector<double>{0.0, 0.0, 0.0, 0.0});
  // han.sim.run: collisions that an Unavoidable record foresaw are outside the guarantee.
  for (Collision& c : res.collisions) {
    if (!c.outside_guarantee.empty()) continue;
    for (const Unavoidable& u : res.unavoidable) {
      if (u.t > c.t || c.t - u.t > s.horizon) continue;
      bool named = false;
      for (const std::int64_t o : u.obstacles) named = named || o == c.obstacle;
      if (named) {
        c.outside_guarantee = "unavoidable";
        break;
      }
    }
  }
  return res;
}

Json to_json(const SimResult& r, bool full) {
  auto pt = [](Vec2 p) { return Json::array({p.x, p.y}); };
  auto ids = [](const std::vector<std::int64_t>& v) {
    Json a = Json::array();
    for (const auto i : v) a.push_back(i);
    return a;
  };
  Json waits = Json::array();
  for (const Wait& w : r.waits)
    waits.push_back({{"start", w.start}, {"end", w.end}, {"duration", w.end - w.start}, {"obstacles", ids(w.obstacles)}});
  Json replans = Json::array();
  for (const Replan& p : r.replans)
    replans.push_back({{"t", p.t}, {"from", grid::cell_to_json(p.from)}, {"target", grid::cell_to_json(p.target)},
                       {"target_index", p.target_index}, {"detour", grid::path_to_json(p.detour)},
                       {"obstacles", ids(p.obstacles)}});
  Json evasions = Json::array();
  for (const Evasion& e : r.evasions)
    evasions.push_back({{"t", e.t}, {"from", grid::cell_to_json(e.from)}, {"refuge", grid::cell_to_json(e.refuge)},
                        {"path", grid::path_to_json(e.path)}, {"target", grid::cell_to_json(e.target)},
                        {"target_index", e.target_index}, {"obstacles", ids(e.obstacles)}});
  Json unavoidable = Json::array();
  for (const Unavoidable& u : r.unavoidable)
    unavoidable.push_back({{"t", u.t}, {"obstacles", ids(u.obstacles)}, {"reason", u.reason}});
  Json cols = Json::array();
  std::int64_t unexplained = 0;
  for (const Collision& c : r.collisions) {
    cols.push_back({{"t", c.t},
                    {"obstacle", c.obstacle},
                    {"distance", c.distance},
                    {"outside_guarantee", c.outside_guarantee.empty() ? Json(false) : Json(c.outside_guarantee)}});
    if (c.outside_guarantee.empty()) ++unexplained;
  }
  Json out{{"format", "pathref-sim-result"},
           {"global_found", r.global_found},
           {"global_path", grid::path_to_json(r.global_path)},
           {"global_length", r.global_length},
           {"reached_goal", r.reached_goal},
           {"collided", !r.collisions.empty()},
           {"collisions", cols},
           {"unexplained_collisions", unexplained},
           {"time", r.time},
           {"distance", r.distance},
           {"wait_time", r.wait_time},
           {"waits", waits},
           {"replans", replans},
           {"evasions", evasions},
           {"unavoidable", unavoidable},
           {"steps", r.steps},
           {"noise_draws", r.noise_draws},
           {"estimates", r.estimates}};
  if (full) {
    Json traj = Json::array();
    for (const Sample& s : r.trajectory) traj.push_back(Json::array({s.t, s.p.x, s.p.y, s.v, std::string(to_string(s.state))}));
    out["trajectory"] = traj;
    Json tracks = Json::array();
    for (const auto& tr : r.obstacle_tracks) {
      Json a = Json::array();
      for (const Vec2 p : tr) a.push_back(pt(p));
      tracks.push_back(a);
    }
    out["obstacle_tracks"] = tracks;
  }
  return out;
}

}  // namespace pathref::sim
