#include "pathref/reproduce/han.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <tuple>

#include "pathref/core/error.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/io/svg.hpp"
#include "pathref/io/svg_sim.hpp"
#include "pathref/reproduce/runs.hpp"
#include "pathref/reproduce/stats.hpp"
#include "pathref/rng/mt19937.hpp"
#include "pathref/sim/motion.hpp"
#include "pathref/sim/random_map.hpp"
#include "pathref/sim/simulate.hpp"

namespace pathref::reproduce {

namespace {
/// Robot speed and acceleration of Han §IV (1 m/s; 1 m/s² after a stop); cells are 1 m.
constexpr double han_speed = 1.0;
constexpr double han_accel = 1.0;
/// The variants whose runs are also simulated with moving obstacles (reproduce.han.dynamic).
constexpr const char* dynamic_keys[] = {"iaco-han", "aco"};
}  // namespace

std::vector<std::int64_t> han_protocol_edges() {
  std::vector<std::int64_t> e;
  for (std::int64_t x = 10; x <= 100; x += 5) e.push_back(x);
  return e;
}

double han_ratio(std::int64_t k, std::int64_t maps_per_edge) {
  require(maps_per_edge >= 1 && k >= 0 && k < maps_per_edge, "han_ratio: need 0 <= k < K");
  if (maps_per_edge == 1) return 0.45;
  return 0.2 + 0.5 * static_cast<double>(k) / static_cast<double>(maps_per_edge - 1);
}

const std::vector<HanVariant>& han_variants() {
  static const std::vector<HanVariant> v = {
      {"iaco-han", "iaco-han", Json::object(),
       "IACO-A*'s global planner iaco-han with its defaults (η = 1/(d_ij + d_jE), dead_end = backtrack)", {}},
      {"aco", "aco", Json{{"ants", 200}, {"iterations", 50}, {"rho", 0.6}, {"dead_end", "backtrack"}, {"eta", "goal_directed"}},
       "ACO (aco with Han's Table I; η and dead ends read as for iaco-han)", {}},
      {"iaco-han:1/d", "iaco-han", Json{{"eta", "inverse_distance"}},
       "iaco-han with η = 1/d_ij (the former default reading); 10 m and 100 m maps only", {10, 100}},
      {"aco:1/d", "aco", Json{{"ants", 200}, {"iterations", 50}, {"rho", 0.6}, {"dead_end", "backtrack"}},
       "ACO (Table I) with η = 1/d_ij (the aco planner's own default); 10 m maps only", {10}},
      {"iaco-han@die", "iaco-han", Json{{"dead_end", "die"}},
       "iaco-han with dead_end = die (ants die in dead ends); every edge (its found counts)", {}},
      {"aco@die", "aco", Json{{"ants", 200}, {"iterations", 50}, {"rho", 0.6}, {"eta", "goal_directed"}},
       "ACO (Table I, goal-directed η) with dead_end = die (the aco planner's default); 10 m maps only", {10}},
      {"astar-han", "astar-han", Json::object(), "A* (astar-han, Chebyshev)", {}},
      {"astar", "astar", Json::object(), "A* (astar, octile)", {}},
  };
  return v;
}

namespace {

bool deterministic(const std::string& planner) { return planner == "astar" || planner == "astar-han"; }

/// Why a variant runs with the parameters it does (printed in the report's Parameters section).
std::string han_variant_why(const std::string& key) {
  if (key == "iaco-han")
    return "Han's IACO (IACO-A*'s global planner) with its registered defaults = Han's Table I #2 (α = 4, β = 8, "
           "ρ stepped, Q, q0 adaptive; spec/han-iaco.md) and the readings η = 1/(d_ij + d_jE), dead_end = backtrack";
  if (key == "aco")
    return "Han's \"traditional ACO\": Table I #1 gives only ants = 200, iterations = 50, ρ = 0.6, so α, β, Q and τ0 "
           "keep the `aco` planner's defaults, which are **Shi 2022's Table 1 values** (α = 1, β = 7, Q = 1, τ0 = 8; Han "
           "prints none for ACO); η and dead ends read as for iaco-han so that the comparison measures Han's "
           "improvements, not the readings (reproduce.han.protocol). The IACO's α = 4, β = 8 are Han's own, for the "
           "IACO only";
  if (key == "iaco-han:1/d") return "the alternative reading η = 1/d_ij (claims H.1i, H.2i)";
  if (key == "aco:1/d") return "ACO with η = 1/d_ij, the aco planner's own default (claims H.1i, H.2i)";
  if (key == "iaco-han@die") return "the alternative dead-end reading: ants die (claims H.1d, H.2d, found counts)";
  if (key == "aco@die") return "ACO with dead_end = die, the aco planner's default (claims H.1d, H.2d)";
  if (key == "astar-han") return "Han's 8-direction A* (Chebyshev): the optimum, one run";
  if (key == "astar") return "pathref's A* (octile): the optimum, one run";
  return "";
}

/// A short display name of a variant key for the notes.
std::string variant_label_short(const std::string& key) {
  if (key == "iaco-han") return "IACO-A*";
  if (key == "aco") return "ACO";
  if (key == "iaco-han:1/d") return "IACO-A* (η = 1/d)";
  if (key == "aco:1/d") return "ACO (η = 1/d)";
  if (key == "iaco-han@die") return "IACO-A* (die)";
  if (key == "aco@die") return "ACO (die)";
  return key;
}

bool runs_on(const HanVariant& v, std::int64_t edge) {
  return v.only_edges.empty() || std::find(v.only_edges.begin(), v.only_edges.end(), edge) != v.only_edges.end();
}

Json stat_json(const std::vector<double>& v) {
  const Summary s = summarize(v);
  auto o = [](const std::optional<double>& x) { return x ? num(*x) : Json(nullptr); };
  return Json{{"n", s.n}, {"mean", o(s.mean)}, {"std", o(s.std)}, {"min", o(s.min)}, {"max", o(s.max)}};
}

/// The point at arc length s along a cell path (1 m cells, centres), and the unit direction of
/// the piece it lies on (the last piece beyond the end). Spec: reproduce.han.dynamic.
struct PathPoint {
  sim::Vec2 p;
  sim::Vec2 dir;
};
PathPoint point_on_path(const std::vector<grid::Cell>& path, double s) {
  double acc = 0.0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double len = grid::step_cost(path[i], path[i + 1]);
    const sim::Vec2 a = sim::centre(path[i]);
    const sim::Vec2 b = sim::centre(path[i + 1]);
    const sim::Vec2 d{(b.x - a.x) / len, (b.y - a.y) / len};
    if (s <= acc + len || i + 2 == path.size()) {
      const double f = std::min(std::max(s - acc, 0.0), len);
      return PathPoint{sim::Vec2{a.x + (f * d.x), a.y + (f * d.y)}, d};
    }
    acc += len;
  }
  return PathPoint{sim::centre(path.front()), sim::Vec2{1.0, 0.0}};
}

}  // namespace

std::vector<sim::MovingObstacle> han_dynamic_obstacles(const std::vector<grid::Cell>& path, std::uint32_t seed) {
  require(path.size() >= 2, "han_dynamic_obstacles: the path needs two cells");
  double L = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) L += grid::step_cost(path[i - 1], path[i]);
  rng::Stream st(seed);
  std::vector<sim::MovingObstacle> out;
  // O1 (Fig. 8(b)-(c), side): crosses the path at arc f1 L, perpendicular to it, from the side
  // `side`, at the time the robot would reach that point without obstacles.
  {
    const double f = 0.2 + (0.6 * st.next_double());
    const double side = st.next_double() < 0.5 ? 1.0 : -1.0;
    const double u = 0.25 + (0.75 * st.next_double());
    const double s = f * L;
    const PathPoint x = point_on_path(path, s);
    const sim::Vec2 n{side * (-x.dir.y), side * x.dir.x};
    const double T = sim::ramp_cruise_time(s, han_speed, han_accel);
    sim::MovingObstacle o;
    o.position = sim::Vec2{x.p.x - (n.x * (u * T)), x.p.y - (n.y * (u * T))};
    o.velocity = sim::Vec2{n.x * u, n.y * u};
    out.push_back(o);
  }
  // O2 (Fig. 8(d), frontal): comes head-on along the path's direction at arc f2 L and reaches
  // that point when the robot would.
  {
    const double f = 0.5 + (0.4 * st.next_double());
    const double u = 0.25 + (0.75 * st.next_double());
    const double s = f * L;
    const PathPoint x = point_on_path(path, s);
    const double T = sim::ramp_cruise_time(s, han_speed, han_accel);
    sim::MovingObstacle o;
    o.position = sim::Vec2{x.p.x + (x.dir.x * (u * T)), x.p.y + (x.dir.y * (u * T))};
    o.velocity = sim::Vec2{-(x.dir.x * u), -(x.dir.y * u)};
    out.push_back(o);
  }
  return out;
}

namespace {

/// One dynamic run: the run's path simulated with the two obstacles of its seed.
Json dynamic_run(const grid::Grid& g, grid::Cell start, grid::Cell goal, grid::CornerPolicy policy,
                 const RunRecord& r) {
  Json j{{"seed", r.seed}};
  if (!r.found || r.path.size() < 2) {
    j["simulated"] = false;
    return j;
  }
  sim::Scenario sc;
  sc.grid = g;
  sc.start = start;
  sc.goal = goal;
  sc.policy = policy;
  sc.path = r.path;
  sc.seed = r.seed;
  sc.obstacles = han_dynamic_obstacles(r.path, r.seed);
  const sim::SimResult res = sim::simulate(sc);
  std::int64_t unexplained = 0;
  for (const sim::Collision& c : res.collisions) unexplained += c.outside_guarantee.empty() ? 1 : 0;
  Json obs = Json::array();
  for (const auto& o : sc.obstacles)
    obs.push_back(Json{{"position", Json::array({o.position.x, o.position.y})},
                       {"velocity", Json::array({o.velocity.x, o.velocity.y})},
                       {"radius", o.radius}});
  j["simulated"] = true;
  j["obstacles"] = obs;
  j["planned_length"] = num(r.length);
  j["reached_goal"] = res.reached_goal;
  j["collision_steps"] = res.collisions.size();
  j["unexplained_collisions"] = unexplained;
  j["distance"] = num(res.distance);
  j["time"] = num(res.time);
  j["waits"] = res.waits.size();
  j["wait_time"] = num(res.wait_time);
  j["replans"] = res.replans.size();
  j["evasions"] = res.evasions.size();
  j["unavoidable"] = res.unavoidable.size();
  return j;
}

/// Summary of one planner's dynamic runs on one map: statistics over the runs that reached the
/// goal without a collision.
Json dynamic_summary(const Json& runs) {
  std::vector<double> dist, time, waits, replans, evasions;
  std::int64_t simulated = 0, reached = 0, collided = 0, unexplained = 0;
  for (const Json& r : runs) {
    if (!r.at("simulated").get<bool>()) continue;
    ++simulated;
    const bool col = r.at("collision_steps").get<std::int64_t>() > 0;
    collided += col ? 1 : 0;
    unexplained += r.at("unexplained_collisions").get<std::int64_t>();
    if (!r.at("reached_goal").get<bool>()) continue;
    ++reached;
    if (col) continue;
    dist.push_back(r.at("distance").get<double>());
    time.push_back(r.at("time").get<double>());
    waits.push_back(static_cast<double>(r.at("waits").get<std::int64_t>()));
    replans.push_back(static_cast<double>(r.at("replans").get<std::int64_t>()));
    evasions.push_back(static_cast<double>(r.at("evasions").get<std::int64_t>()));
  }
  return Json{{"simulated", simulated},   {"reached", reached},           {"collided", collided},
              {"unexplained_collisions", unexplained},
              {"distance", stat_json(dist)}, {"time", stat_json(time)},   {"waits", stat_json(waits)},
              {"replans", stat_json(replans)}, {"evasions", stat_json(evasions)}};
}

/// Aggregate of one variant over the maps of one edge (spec reproduce.han.protocol, "Per edge").
Json aggregate(const std::vector<const Json*>& series) {
  std::vector<double> mins, means, stds, conv, wall;
  std::int64_t runs = 0, found = 0, maps_found = 0, conv_one = 0;
  bool available = true;
  for (const Json* s : series) {
    if (!s->value("available", false)) {
      available = false;
      continue;
    }
    const Json& sm = s->at("summary");
    runs += sm.at("runs").get<std::int64_t>();
    found += sm.at("found").get<std::int64_t>();
    if (sm.at("length").at("min").is_number()) {
      ++maps_found;
      mins.push_back(sm.at("length").at("min").get<double>());
      means.push_back(sm.at("length").at("mean").get<double>());
    }
    if (sm.at("length").at("std").is_number()) stds.push_back(sm.at("length").at("std").get<double>());
    for (const double c : run_values(*s, "converged_at")) {
      conv.push_back(c);
      conv_one += c == 1.0 ? 1 : 0;
    }
    for (const double w : run_values(*s, "wall_ms")) wall.push_back(w);
  }
  auto m = [](const std::vector<double>& v) { return v.empty() ? Json(nullptr) : num(mean(v)); };
  const bool all_maps = maps_found == static_cast<std::int64_t>(series.size());
  return Json{{"available", available},
              {"maps", series.size()},
              {"maps_found", maps_found},
              {"runs", runs},
              {"found", found},
              {"min_length", all_maps ? m(mins) : Json(nullptr)},
              {"mean_length", m(means)},
              {"std_length", m(stds)},
              {"converged_at", m(conv)},
              {"converged_at_1", conv_one},
              {"converged_runs", conv.size()},
              {"wall_ms", m(wall)}};
}

/// Aggregate of one planner's dynamic runs over the maps of one edge.
Json aggregate_dynamic(const std::vector<const Json*>& summaries) {
  std::vector<double> dmin, dstd, tmin, tmean, waits, replans, evasions;
  std::int64_t simulated = 0, reached = 0, collided = 0, unexplained = 0, maps_ok = 0;
  for (const Json* s : summaries) {
    simulated += s->at("simulated").get<std::int64_t>();
    reached += s->at("reached").get<std::int64_t>();
    collided += s->at("collided").get<std::int64_t>();
    unexplained += s->at("unexplained_collisions").get<std::int64_t>();
    const Json& d = s->at("distance");
    if (d.at("min").is_number()) {
      ++maps_ok;
      dmin.push_back(d.at("min").get<double>());
      tmin.push_back(s->at("time").at("min").get<double>());
      tmean.push_back(s->at("time").at("mean").get<double>());
      waits.push_back(s->at("waits").at("mean").get<double>());
      replans.push_back(s->at("replans").at("mean").get<double>());
      evasions.push_back(s->at("evasions").at("mean").get<double>());
    }
    if (d.at("std").is_number()) dstd.push_back(d.at("std").get<double>());
  }
  const bool all_maps = maps_ok == static_cast<std::int64_t>(summaries.size()) && maps_ok > 0;
  auto m = [](const std::vector<double>& v) { return v.empty() ? Json(nullptr) : num(mean(v)); };
  return Json{{"simulated", simulated},
              {"reached", reached},
              {"collided", collided},
              {"unexplained_collisions", unexplained},
              {"min_distance", all_maps ? m(dmin) : Json(nullptr)},
              {"std_distance", m(dstd)},
              {"min_time", all_maps ? m(tmin) : Json(nullptr)},
              {"mean_time", m(tmean)},
              {"waits", m(waits)},
              {"replans", m(replans)},
              {"evasions", m(evasions)}};
}

/// root[path...] or a null value when a key is missing.
const Json& lookup(const Json& root, const std::vector<std::string>& path) {
  static const Json null_value;
  const Json* at = &root;
  for (const std::string& k : path) {
    if (!at->is_object() || !at->contains(k)) return null_value;
    at = &at->at(k);
  }
  return *at;
}

/// Whether every found run of every stochastic variant on the map has the A* (astar-han) length:
/// the map leaves the planners no choice (reproduce.han.protocol, "Degenerate maps").
bool map_degenerate(const Json& results) {
  const Json& a = at_or_null(results, {"astar-han", "summary", "length", "min"});
  if (!a.is_number()) return false;
  const double opt = a.get<double>();
  for (const auto& v : han_variants()) {
    if (deterministic(v.planner) || !results.contains(v.key)) continue;
    const Json& r = results.at(v.key);
    if (!r.value("available", false)) return false;
    for (const double x : run_values(r, "length"))
      if (x != opt) return false;
  }
  return true;
}

/// The values of `key` of `variant`'s runs on the maps of `edge`, pooled in map order, the first
/// `count` runs of each map (all when count < 0) that have a value (reproduce.judge).
std::vector<double> pooled_runs(const Json& maps, std::int64_t edge, const std::string& variant, const std::string& key,
                                std::int64_t count) {
  std::vector<double> out;
  for (const Json& m : maps) {
    if (m.at("edge").get<std::int64_t>() != edge) continue;
    const Json& runs = at_or_null(m, {"results", variant, "runs"});
    if (!runs.is_array()) continue;
    std::int64_t k = 0;
    for (const Json& r : runs) {
      if (count >= 0 && k++ >= count) break;
      const Json& x = at_or_null(r, {key});
      if (x.is_number()) out.push_back(x.get<double>());
    }
  }
  return out;
}

/// As pooled_runs for the runs with moving obstacles that reached the goal without a collision;
/// with `residuals`, each map's values minus their mean on that map (the within-map spread).
std::vector<double> pooled_dynamic(const Json& maps, std::int64_t edge, const std::string& variant, const std::string& key,
                                   std::int64_t count, bool residuals) {
  std::vector<double> out;
  for (const Json& m : maps) {
    if (m.at("edge").get<std::int64_t>() != edge) continue;
    const Json& runs = at_or_null(m, {"dynamic", variant, "runs"});
    if (!runs.is_array()) continue;
    std::vector<double> v;
    std::int64_t k = 0;
    for (const Json& r : runs) {
      if (count >= 0 && k++ >= count) break;
      if (!r.value("simulated", false) || !r.value("reached_goal", false) || r.value("collision_steps", 0) > 0) continue;
      const Json& x = at_or_null(r, {key});
      if (x.is_number()) v.push_back(x.get<double>());
    }
    if (residuals && !v.empty()) {
      const double mu = mean(v);
      for (double& x : v) x -= mu;
    }
    out.insert(out.end(), v.begin(), v.end());
  }
  return out;
}

/// Share of runs (all 2n) of `variant` on the edge's maps whose best path was found in iteration 1.
double stagnation_share(const Json& maps, std::int64_t edge, const std::string& variant) {
  const auto v = pooled_runs(maps, edge, variant, "converged_at", -1);
  if (v.empty()) return 0.0;
  double ones = 0.0;
  for (const double x : v) ones += x == 1.0 ? 1.0 : 0.0;
  return ones / static_cast<double>(v.size());
}

}  // namespace

Json run_han(const HanConfig& cfg) {
  require(!cfg.edges.empty(), "run_han: no edges");
  for (const auto e : cfg.edges) require(e >= 2 && e <= 1000, "run_han: edges must lie in [2, 1000]");
  require(cfg.maps_per_edge >= 1 && cfg.maps_per_edge <= 100, "run_han: maps per edge must lie in [1, 100]");
  require(cfg.runs >= 1 && cfg.runs <= 10000 && cfg.sweep_runs >= 1 && cfg.sweep_runs <= 10000,
          "run_han: runs must lie in [1, 10000]");
  const auto t0 = std::chrono::steady_clock::now();
  Json doc = Json::object();
  doc["format"] = "pathref-reproduce";
  doc["format_version"] = 1;
  doc["paper"] = "han";
  doc["reference"] =
      "Jinli Han. Application of Improved Ant Colony Algorithm Integrating Adaptive Parameter Configuration in "
      "Robot Mobile Path Design. IJACSA (seed 003 of ../shared/papers; no DOI in the local text)";
  Json variants = Json::array();
  for (const auto& v : han_variants())
    variants.push_back(Json{{"key", v.key}, {"planner", v.planner}, {"params", v.params}, {"label", v.label},
                            {"only_edges", v.only_edges}});
  const std::int64_t n_maps = static_cast<std::int64_t>(cfg.edges.size()) * cfg.maps_per_edge;
  const std::uint64_t max_runs = static_cast<std::uint64_t>(std::max(cfg.runs, cfg.sweep_runs));
  require(static_cast<std::uint64_t>(cfg.seed) + static_cast<std::uint64_t>(n_maps) <= 4294967296ULL &&
              static_cast<std::uint64_t>(cfg.seed) + 2 * max_runs <= 4294967296ULL,
          "run_han: seed + number of maps (or runs) - 1 must not exceed 4294967295");
  Json dyn_keys = Json::array();
  for (const char* k : dynamic_keys) dyn_keys.push_back(k);
  doc["protocol"] = Json{{"edges", cfg.edges},
                         {"maps_per_edge", cfg.maps_per_edge},
                         {"runs_10m", cfg.runs},
                         {"sweep_runs", cfg.sweep_runs},
                         {"runs_10m_2n", 2 * cfg.runs},
                         {"sweep_runs_2n", 2 * cfg.sweep_runs},
                         {"alpha", 0.05},
                         {"bootstrap", Json{{"resamples", 2000}, {"level", 0.95}, {"seed", cfg.seed}}},
                         {"seed", cfg.seed},
                         {"map_seeds", Json::array({cfg.seed, static_cast<std::uint64_t>(cfg.seed) + static_cast<std::uint64_t>(n_maps) - 1})},
                         {"policy", std::string(grid::to_string(cfg.policy))},
                         {"quick", cfg.quick},
                         {"variants", variants},
                         {"dynamic_variants", dyn_keys},
                         {"dynamic_obstacles", 2},
                         {"simulation", "han.sim.run defaults: dt 0.125 s, horizon 3 s, radii 0.3 m, margin 0.25 m, "
                                        "lambda 0.95, no noise, t_max 600 s"},
                         {"speed_m_per_s", han_speed},
                         {"accel_m_per_s2", han_accel},
                         {"cell_m", 1.0}};
  Json maps = Json::array();
  Json edges = Json::array();
  std::int64_t j = 0;
  for (const auto edge : cfg.edges) {
    const std::int64_t runs_n = edge == 10 ? cfg.runs : cfg.sweep_runs;
    const std::int64_t runs = 2 * runs_n;  // reproduce.judge: verdicts at n and at 2n
    const std::size_t first_map = maps.size();
    for (std::int64_t k = 0; k < cfg.maps_per_edge; ++k, ++j) {
      const double ratio = han_ratio(k, cfg.maps_per_edge);
      const auto map_seed = static_cast<std::uint32_t>(static_cast<std::uint64_t>(cfg.seed) + static_cast<std::uint64_t>(j));
      const sim::RandomMap rm = sim::random_map(map_seed, edge, ratio);
      Json mj{{"edge", edge},
              {"ratio", ratio},
              {"map_seed", map_seed},
              {"obstacles", rm.obstacles},
              {"start", Json::array({rm.start.x, rm.start.y})},
              {"goal", Json::array({rm.goal.x, rm.goal.y})},
              {"rows", grid::grid_to_json(rm.grid)}};
      Json res = Json::object();
      Json dyn = Json::object();
      const std::string ctx = fmt::format("han edge {} map {} (ratio {})", edge, k + 1, fixed(ratio, 2));
      for (const auto& v : han_variants()) {
        if (!runs_on(v, edge)) continue;
        const bool is_dynamic = std::find_if(std::begin(dynamic_keys), std::end(dynamic_keys),
                                             [&](const char* d) { return v.key == d; }) != std::end(dynamic_keys);
        std::vector<RunRecord> records;
        res[v.key] = run_series(v.planner, v.params, rm.grid, rm.start, rm.goal, cfg.policy, cfg.seed,
                                deterministic(v.planner) ? 1 : runs, cfg.quick, cfg.progress, ctx,
                                is_dynamic ? &records : nullptr);
        if (!is_dynamic) continue;
        const auto td = std::chrono::steady_clock::now();
        std::vector<Json> dv(records.size());
        parallel_for(records.size(), [&](std::size_t i) { dv[i] = dynamic_run(rm.grid, rm.start, rm.goal, cfg.policy, records[i]); });
        Json druns = Json::array();
        for (Json& d : dv) druns.push_back(std::move(d));
        dyn[v.key] = Json{{"runs", druns}, {"summary", dynamic_summary(druns)}};
        if (cfg.progress)
          cfg.progress(fmt::format("{}: {} with moving obstacles x{} simulated in {:.1f} s", ctx, v.key, druns.size(),
                                   std::chrono::duration<double>(std::chrono::steady_clock::now() - td).count()));
      }
      mj["degenerate"] = map_degenerate(res);
      // Keep the document small: per-run records stay everywhere; the best run's path and curves and
      // the mean iteration curve only on the 10 m maps (every run can be replayed from its seed).
      if (edge != 10)
        for (auto it = res.begin(); it != res.end(); ++it) {
          if (it->contains("best") && it->at("best").is_object())
            for (const char* field : {"path", "best_per_iteration", "mean_per_iteration"}) (*it)["best"].erase(field);
          it->erase("mean_iteration_curve");
        }
      mj["results"] = res;
      mj["dynamic"] = dyn;
      maps.push_back(mj);
    }
    Json ej{{"edge", edge}, {"runs", runs}, {"runs_n", runs_n}};
    Json agg = Json::object();
    for (const auto& v : han_variants()) {
      if (!runs_on(v, edge)) continue;
      std::vector<const Json*> per;
      for (std::size_t m = first_map; m < maps.size(); ++m) per.push_back(&maps[m].at("results").at(v.key));
      agg[v.key] = aggregate(per);
    }
    Json dagg = Json::object();
    for (const char* key : dynamic_keys) {
      std::vector<const Json*> per;
      for (std::size_t m = first_map; m < maps.size(); ++m)
        if (maps[m].at("dynamic").contains(key)) per.push_back(&maps[m].at("dynamic").at(key).at("summary"));
      dagg[key] = aggregate_dynamic(per);
    }
    std::int64_t degenerate = 0;
    for (std::size_t m = first_map; m < maps.size(); ++m) degenerate += maps[m].at("degenerate").get<bool>() ? 1 : 0;
    ej["variants"] = agg;
    ej["dynamic"] = dagg;
    ej["degenerate_maps"] = degenerate;
    edges.push_back(ej);
  }
  doc["maps"] = maps;
  doc["edges"] = edges;

  // Claims (spec reproduce.han.protocol, "Claims").
  std::vector<Claim> claims;
  const Json* e10 = nullptr;
  const Json* e100 = nullptr;
  for (const Json& e : doc["edges"]) {
    if (e.at("edge").get<std::int64_t>() == 10) e10 = &e;
    if (e.at("edge").get<std::int64_t>() == 100) e100 = &e;
  }
  const Json& all_maps = doc["maps"];
  const std::int64_t n10 = cfg.runs;
  const std::int64_t n_sweep = cfg.sweep_runs;
  const BootstrapOptions bo{cfg.seed, 2000, 0.95};
  const std::string no10 = "no 10 m maps in this run (--edges)";
  const std::string no100 = "no 100 m maps in this run (--quick or --edges)";
  const std::string pooled_note =
      "runs pooled over the edge's maps (each map contributes its runs; the maps of one edge differ in obstacle ratio)";
  const std::string dyn_note =
      "with moving obstacles: each run's path driven by han.sim.run with the two scripted obstacles of "
      "reproduce.han.dynamic; distance = the executed (detoured) path, over the runs that reached the goal without a "
      "collision";
  const std::string minima_note =
      "the paper compares minima, extreme values that more runs can only lower; pathref tests whether IACO-A*'s "
      "values are smaller (Mann–Whitney on every run) and prints the per-edge minima beside it: ";
  auto stagnation_note = [&](Claim& c, std::int64_t edge, const std::string& a, const std::string& b) {
    const double sa = stagnation_share(all_maps, edge, a);
    const double sb = stagnation_share(all_maps, edge, b);
    if (sa >= 0.5 || sb >= 0.5) {
      const std::string d = fmt::format(
          "stagnation: {} % of {} runs and {} % of {} runs found their best path in iteration 1 and never improved "
          "(spec/han.md \"Stagnation\"); a verdict on iterations or lengths here describes where the colony stopped, "
          "not how it converged",
          fixed(100.0 * sa, 0), variant_label_short(a), fixed(100.0 * sb, 0), variant_label_short(b));
      c.note += (c.note.empty() ? "" : "; ") + d;
    }
  };
  auto has_edge = [&](std::int64_t edge) {
    for (const Json& e : doc["edges"])
      if (e.at("edge").get<std::int64_t>() == edge) return true;
    return false;
  };
  // "A < B" on pooled run values (static: results; dynamic: runs with moving obstacles).
  auto compare = [&](const std::string& id, const std::string& text, const std::string& source, const std::string& paper,
                     std::int64_t edge, const std::string& a, const std::string& b, const std::string& key, bool dynamic,
                     int decimals, const std::string& missing, const std::string& note) {
    Claim c;
    c.id = id;
    c.text = text;
    c.source = source;
    c.paper = paper;
    c.note = note;
    if (!has_edge(edge)) {
      c.ours = "—";
      c.verdict = Verdict::untestable;
      c.note = missing + (note.empty() ? "" : "; " + note);
      return c;
    }
    const std::int64_t n = edge == 10 ? n10 : n_sweep;
    auto get = [&](const std::string& v, std::int64_t count) {
      return dynamic ? pooled_dynamic(all_maps, edge, v, key, count, false) : pooled_runs(all_maps, edge, v, key, count);
    };
    const auto a_n = get(a, n), b_n = get(b, n), a_2 = get(a, -1), b_2 = get(b, -1);
    if (a_n.empty() || b_n.empty()) {
      c.ours = "—";
      c.verdict = Verdict::untestable;
      c.note = "no runs with a value for a planner" + (note.empty() ? std::string() : "; " + note);
      return c;
    }
    comparison_claim(c, a_n, b_n, a_2, b_2, Claimed::a_less, decimals);
    c.rule += "; " + pooled_note;
    return c;
  };
  {
    Claim c = compare("H.1", "IACO-A* converges in fewer iterations than ACO (10 m map)", "§IV, Fig. 10; abstract",
                      "8 vs 37", 10, "iaco-han", "aco", "converged_at", false, 2, no10,
                      "the global planners' iterations (reproduce.converge); in IACO-A* the moving obstacles appear "
                      "only after the global path is planned (Fig. 6), so they cannot change these iterations (assumed)");
    stagnation_note(c, 10, "iaco-han", "aco");
    c.depends_on.push_back("η = 1/(d_ij + d_jE) for both colonies (spec/han.md; alternative: H.1i)");
    c.depends_on.push_back("dead_end = backtrack (alternative: H.1d)");
    claims.push_back(c);
  }
  auto minima = [&](std::int64_t edge, const char* what) {
    for (const Json& e : doc["edges"])
      if (e.at("edge").get<std::int64_t>() == edge)
        return fmt::format("{} {} vs {}", what, md_number(at_or_null(e, {"dynamic", "iaco-han", "min_distance"}), 2),
                           md_number(at_or_null(e, {"dynamic", "aco", "min_distance"}), 2));
    return std::string("—");
  };
  {
    Claim c = compare("H.2",
                      "IACO-A*'s minimum path length after convergence is shorter than ACO's (10 m map, with moving obstacles)",
                      "§IV, Fig. 10; abstract", "13.24 m vs 17.82 m", 10, "iaco-han", "aco", "distance", true, 4, no10,
                      dyn_note + "; " + minima_note + minima(10, "mean per-map minimum distance"));
    stagnation_note(c, 10, "iaco-han", "aco");
    c.depends_on.push_back("the scripted moving obstacles (reproduce.han.dynamic, assumed)");
    claims.push_back(c);
  }
  {  // H.3: spread within maps, bootstrap interval of sd(a) - sd(b) on the per-map residuals
    Claim c;
    c.id = "H.3";
    c.text = "IACO-A*'s minimum planning length has a smaller standard deviation than ACO's (10 m map, with moving obstacles)";
    c.source = "§IV, Fig. 11";
    c.paper = "0.82 m vs 1.24 m";
    if (!has_edge(10)) {
      c.ours = "—";
      c.verdict = Verdict::untestable;
      c.note = no10;
    } else {
      auto judge = [&](std::int64_t count, std::string& ours, Verdict& v, Direction& d, Json& st) {
        const auto a = pooled_dynamic(all_maps, 10, "iaco-han", "distance", count, true);
        const auto b = pooled_dynamic(all_maps, 10, "aco", "distance", count, true);
        if (a.size() < 2 || b.size() < 2) return false;
        const Interval ci = bootstrap_two_sample_ci(a, b, BootStatistic::sd_difference, bo);
        const Judgement jd = judge_interval_comparison(ci, Claimed::a_less);
        ours = fmt::format("within-map sd {} vs {}; difference {} [{}, {}]", fixed(sample_std(a), 4),
                           fixed(sample_std(b), 4), fixed(sample_std(a) - sample_std(b), 4), fixed(ci.lo, 4),
                           fixed(ci.hi, 4));
        v = jd.verdict;
        d = jd.direction;
        st = Json{{"kind", "comparison"},
                  {"statistic", "sd_difference of per-map residuals"},
                  {"ci", interval_json(ci)},
                  {"level", bo.level},
                  {"resamples", bo.resamples},
                  {"seed", bo.seed},
                  {"a", summary_stats_json(summarize(a))},
                  {"b", summary_stats_json(summarize(b))},
                  {"judgement", judgement_json(jd)}};
        return true;
      };
      Json st_n, st_2;
      if (!judge(n10, c.ours, c.verdict, c.direction, st_n)) {
        c.ours = "—";
        c.verdict = Verdict::untestable;
        c.note = "fewer than 2 collision-free runs of a planner";
      } else {
        c.rule = "95 % bootstrap interval of sd(IACO-A*) − sd(ACO) entirely below 0 (stats.compare, interval form), "
                 "the distances taken relative to each map's mean so that the differences between maps do not count";
        c.statistics = Json{{"n", st_n}, {"2n", nullptr}};
        Verdict v2 = Verdict::untestable;
        Direction d2 = Direction::none;
        if (judge(-1, c.ours_2n, v2, d2, st_2)) {
          c.verdict_2n = v2;
          c.direction_2n = d2;
          c.statistics["2n"] = st_2;
        }
        c.note = dyn_note;
      }
      stagnation_note(c, 10, "iaco-han", "aco");
      c.depends_on.push_back("the scripted moving obstacles (reproduce.han.dynamic, assumed)");
    }
    claims.push_back(c);
  }
  {
    Claim c = compare("H.4", "at edge 100 m IACO-A*'s minimum planning length is shorter than ACO's (with moving obstacles)",
                      "§IV, Fig. 12(a); abstract", "49 m vs 104 m", 100, "iaco-han", "aco", "distance", true, 4, no100,
                      dyn_note + "; " + minima_note + minima(100, "mean per-map minimum distance"));
    c.depends_on.push_back("the scripted moving obstacles (reproduce.han.dynamic, assumed)");
    claims.push_back(c);
  }
  {
    Claim c = compare("H.5", "at edge 100 m IACO-A*'s total moving time is shorter than ACO's (with moving obstacles)",
                      "§IV, Fig. 12(b); abstract", "49 s vs 142 s", 100, "iaco-han", "aco", "time", true, 2, no100,
                      "time = the simulated arrival time (1 m/s, 1 m/s² after every stop, waits and detours included), "
                      "not length / speed; " + minima_note.substr(0, minima_note.size() - 2));
    c.depends_on.push_back("the scripted moving obstacles and the speed profile (reproduce.han.dynamic, assumed)");
    claims.push_back(c);
  }
  {
    Claim c;
    c.id = "H.6";
    c.text = "regardless of the map size, IACO-A*'s minimum path length is smaller than ACO's (with moving obstacles)";
    c.source = "§IV, Fig. 12; conclusion";
    c.paper = "at every edge";
    std::vector<std::string> held, opposite, undecided;
    std::vector<std::string> held2, opposite2, undecided2;
    bool all_as_claimed = true, all_as_claimed2 = true;
    Json per_edge = Json::array();
    for (const Json& e : doc["edges"]) {
      const auto edge = e.at("edge").get<std::int64_t>();
      const std::int64_t n = edge == 10 ? n10 : n_sweep;
      const auto a_n = pooled_dynamic(all_maps, edge, "iaco-han", "distance", n, false);
      const auto b_n = pooled_dynamic(all_maps, edge, "aco", "distance", n, false);
      const auto a_2 = pooled_dynamic(all_maps, edge, "iaco-han", "distance", -1, false);
      const auto b_2 = pooled_dynamic(all_maps, edge, "aco", "distance", -1, false);
      if (a_n.empty() || b_n.empty()) continue;
      const auto x = compare_samples(a_n, b_n, Claimed::a_less);
      const std::string es = std::to_string(edge);
      (x.judgement.verdict == Verdict::holds ? held : x.judgement.verdict == Verdict::fails ? opposite : undecided).push_back(es);
      all_as_claimed = all_as_claimed && x.judgement.direction == Direction::as_claimed;
      Json ej{{"edge", edge}, {"n", comparison_json(x)}, {"2n", nullptr}};
      if (!a_2.empty() && !b_2.empty()) {
        const auto y = compare_samples(a_2, b_2, Claimed::a_less);
        (y.judgement.verdict == Verdict::holds ? held2 : y.judgement.verdict == Verdict::fails ? opposite2 : undecided2)
            .push_back(es);
        all_as_claimed2 = all_as_claimed2 && y.judgement.direction == Direction::as_claimed;
        ej["2n"] = comparison_json(y);
      }
      per_edge.push_back(ej);
    }
    auto join = [](const std::vector<std::string>& v) {
      std::string t;
      for (const auto& x : v) t += (t.empty() ? "" : ", ") + x;
      return t.empty() ? std::string("none") : t;
    };
    auto verdict_of = [&](const std::vector<std::string>& h, const std::vector<std::string>& o,
                          const std::vector<std::string>& u, bool as_claimed, Verdict& v, Direction& d) {
      if (!o.empty()) {
        v = Verdict::fails;
        d = Direction::opposite;
      } else if (u.empty() && !h.empty()) {
        v = Verdict::holds;
        d = Direction::as_claimed;
      } else {
        v = Verdict::not_significant;
        d = as_claimed ? Direction::as_claimed : Direction::equal;
      }
    };
    const std::size_t tested = held.size() + opposite.size() + undecided.size();
    if (tested == 0) {
      c.ours = "—";
      c.verdict = Verdict::untestable;
      c.note = "no edge where both planners have collision-free runs";
    } else {
      verdict_of(held, opposite, undecided, all_as_claimed, c.verdict, c.direction);
      c.ours = fmt::format("significantly smaller at edges {}; significantly larger at {}; not significant at {}",
                           join(held), join(opposite), join(undecided));
      if (held2.size() + opposite2.size() + undecided2.size() > 0) {
        Verdict v2 = Verdict::untestable;
        Direction d2 = Direction::none;
        verdict_of(held2, opposite2, undecided2, all_as_claimed2, v2, d2);
        c.verdict_2n = v2;
        c.direction_2n = d2;
        c.ours_2n = fmt::format("significantly smaller at edges {}; significantly larger at {}; not significant at {}",
                                join(held2), join(opposite2), join(undecided2));
      }
      c.rule = "at every edge the two-sided Mann–Whitney test (α = 0.05) on the driven distances pooled over the "
               "edge's maps; holds iff significant as claimed at every edge, does not hold iff significantly "
               "opposite at some edge, otherwise not significant";
      c.statistics = Json{{"per_edge", per_edge}};
      c.note = dyn_note;
    }
    c.depends_on.push_back("the scripted moving obstacles (reproduce.han.dynamic, assumed)");
    claims.push_back(c);
  }
  {
    Claim c = compare("F7.1", "without moving obstacles, IACO-A*'s planned path is shorter than ACO's (10 m map)",
                      "§IV, Fig. 7; conclusion", "7.95 m vs 12.64 m", 10, "iaco-han", "aco", "length", false, 4, no10,
                      "the global planners' paths (IACO-A* follows its global path when nothing moves)");
    stagnation_note(c, 10, "iaco-han", "aco");
    c.depends_on.push_back("η = 1/(d_ij + d_jE) for both colonies (alternative: H.2i)");
    c.depends_on.push_back("dead_end = backtrack (alternative: H.2d)");
    claims.push_back(c);
  }
  // The other readings (static planners, 10 m): eta = 1/d_ij for both colonies; ants that die.
  for (const auto& [id, text, source, paper, a, b, key, d] :
       std::vector<std::tuple<std::string, std::string, std::string, std::string, std::string, std::string, std::string, int>>{
           {"H.1i", "as H.1 with η = 1/d_ij for both colonies", "§IV, Fig. 10 (the other reading of η)", "8 vs 37",
            "iaco-han:1/d", "aco:1/d", "converged_at", 2},
           {"H.2i", "as F7.1 (planned length, 10 m) with η = 1/d_ij for both colonies",
            "§IV, Figs. 7, 10 (the other reading of η)", "13.24 m vs 17.82 m", "iaco-han:1/d", "aco:1/d", "length", 4},
           {"H.1d", "as H.1 with dead_end = die for both colonies", "§IV, Fig. 10 (the other dead-end reading)", "8 vs 37",
            "iaco-han@die", "aco@die", "converged_at", 2},
           {"H.2d", "as F7.1 (planned length, 10 m) with dead_end = die for both colonies",
            "§IV, Figs. 7, 10 (the other dead-end reading)", "13.24 m vs 17.82 m", "iaco-han@die", "aco@die", "length", 4}}) {
    Claim c = compare(id, text, source, paper, 10, a, b, key, false, d, no10, "");
    stagnation_note(c, 10, a, b);
    c.depends_on.push_back(id.back() == 'i' ? "reading η = 1/d_ij (the alternative of H.1/F7.1)"
                                            : "reading dead_end = die (the alternative of H.1/F7.1)");
    claims.push_back(c);
  }
  // The printed absolute numbers: maps not published.
  const std::vector<std::tuple<std::string, std::string, std::string, const Json*, std::vector<std::string>, int>> absolute = {
      {"A.1", "IACO-A* converges after 8 iterations, ACO after 37", "8, 37", e10, {"variants", "converged_at"}, 2},
      {"A.2", "minimum path lengths after convergence 13.24 m (IACO-A*), 17.82 m (ACO)", "13.24, 17.82", e10,
       {"dynamic", "min_distance"}, 4},
      {"A.3", "standard deviations of the minimum planning length 0.82 m (IACO-A*), 1.24 m (ACO)", "0.82, 1.24", e10,
       {"dynamic", "std_distance"}, 4},
      {"A.4", "at edge 100 m: minimum planning length 49 m (IACO-A*), 104 m (ACO)", "49, 104", e100,
       {"dynamic", "min_distance"}, 4},
      {"A.5", "at edge 100 m: total moving time 49 s (IACO-A*), 142 s (ACO)", "49, 142", e100, {"dynamic", "min_time"}, 2},
  };
  for (const auto& [id, text, paper, edge, where, d] : absolute) {
    Claim c;
    c.id = id;
    c.text = text;
    c.source = id == "A.3" ? "§IV, Fig. 11" : (id == "A.1" || id == "A.2") ? "§IV, Fig. 10; abstract" : "§IV, Fig. 12; abstract";
    c.paper = paper;
    auto value = [&, &wh = where, dd = d, ed = edge](const std::string& key) {
      return ed == nullptr ? std::string("—") : md_number(lookup(*ed, {wh[0], key, wh[1]}), dd);
    };
    c.ours = edge == nullptr ? "—" : value("iaco-han") + ", " + value("aco");
    c.verdict = Verdict::untestable;
    c.note = "the paper's random maps (and their start, goal and moving obstacles) are not published; only the "
             "comparisons (H.*) are tested";
    if (id == "A.4")
      c.note += fmt::format("; with start and goal in opposite corners (this protocol) no path on a 100×100 grid "
                            "is shorter than 99·√2 = {} m, so the paper's endpoints must have been closer",
                            fixed(99.0 * std::sqrt(2.0), 2));
    claims.push_back(c);
  }
  Json cj = Json::array();
  for (const Claim& c : claims) cj.push_back(claim_json(c));
  doc["claims"] = cj;
  Json prov = provenance_json(cfg.provenance);
  prov["total_wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  doc["provenance"] = prov;
  return doc;
}

namespace {

std::string variant_label(const std::string& key) {
  if (key == "iaco-han") return "IACO-A* (iaco-han)";
  if (key == "aco") return "ACO (Table I)";
  if (key == "iaco-han:1/d") return "IACO-A*, η = 1/d";
  if (key == "aco:1/d") return "ACO, η = 1/d";
  if (key == "astar-han") return "A* (optimum)";
  return key;
}

io::Series edge_line(const Json& doc, const std::string& label, std::initializer_list<std::string_view> path) {
  io::Series s;
  s.label = label;
  for (const Json& e : doc.at("edges")) {
    s.x.push_back(e.at("edge").get<double>());
    const Json& y = at_or_null(e, path);
    s.y.push_back(y.is_number() ? y.get<double>() : std::numeric_limits<double>::infinity());
  }
  return s;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> han_figures(const Json& doc) {
  std::vector<std::pair<std::string, std::string>> figs;
  // Fig. 12(a): the driven lengths of both planners and A*'s optimum. The planned lengths differ
  // from the driven ones by at most the amount printed in the caption (they would hide under them),
  // and η = 1/d, run on the 10 m and 100 m maps only, is listed in the caption (its 100 m length
  // would squash every other series).
  {
    const io::Series iaco = edge_line(doc, "IACO-A*, driven with moving obstacles", {"dynamic", "iaco-han", "min_distance"});
    const io::Series aco = edge_line(doc, "ACO, driven with moving obstacles", {"dynamic", "aco", "min_distance"});
    const io::Series iaco_plan = edge_line(doc, "", {"variants", "iaco-han", "min_length"});
    const io::Series aco_plan = edge_line(doc, "", {"variants", "aco", "min_length"});
    const io::Series inv = edge_line(doc, "", {"variants", "iaco-han:1/d", "min_length"});
    double gap = 0.0;
    for (std::size_t i = 0; i < iaco.y.size(); ++i)
      for (const auto& [a, b] : {std::pair{iaco.y[i], iaco_plan.y[i]}, std::pair{aco.y[i], aco_plan.y[i]}})
        if (std::isfinite(a) && std::isfinite(b)) gap = std::max(gap, std::abs(a - b));
    std::string inv_text;
    for (std::size_t i = 0; i < inv.y.size(); ++i)
      if (std::isfinite(inv.y[i]))
        inv_text += fmt::format("{}{:g} m: {:.1f} m", inv_text.empty() ? "" : ", ", inv.x[i], inv.y[i]);
    io::ChartOptions opt{"minimum path length against map edge (cf. Fig. 12(a))", "map edge (m)", "minimum path length (m)"};
    opt.y_scale = io::YScale::linear;
    opt.caption = fmt::format("Planned minima (no moving obstacles) differ from the driven ones by at most {:.2f} m. "
                              "IACO-A* with η = 1/d (not drawn): {}.",
                              gap, inv_text.empty() ? "not run" : inv_text);
    figs.emplace_back("length-vs-edge.svg",
                      io::svg_line_chart({iaco, aco, edge_line(doc, "A* (optimum)", {"variants", "astar-han", "min_length"})}, opt));
  }
  figs.emplace_back(
      "time-vs-edge.svg",
      io::svg_line_chart({edge_line(doc, "IACO-A*", {"dynamic", "iaco-han", "min_time"}),
                          edge_line(doc, "ACO", {"dynamic", "aco", "min_time"})},
                         io::ChartOptions{"simulated moving time with two moving obstacles (cf. Fig. 12(b))",
                                          "map edge (m)", "minimum moving time (s)"}));
  figs.emplace_back(
      "planning-time-vs-edge.svg",
      io::svg_line_chart({edge_line(doc, "IACO-A* (iaco-han)", {"variants", "iaco-han", "wall_ms"}),
                          edge_line(doc, "ACO (Table I)", {"variants", "aco", "wall_ms"}),
                          edge_line(doc, "A* (astar-han)", {"variants", "astar-han", "wall_ms"})},
                         io::ChartOptions{"planner wall-clock time per run (a measurement)", "map edge (m)",
                                          "wall time (ms)"}));
  // Convergence on the first 10 m map (cf. Fig. 10): mean best-so-far.
  for (const Json& m : doc.at("maps")) {
    if (m.at("edge").get<std::int64_t>() != 10) continue;
    std::vector<io::Series> series;
    for (const std::string key : {"iaco-han", "aco", "iaco-han:1/d", "aco:1/d"}) {
      const Json& c = at_or_null(m, {"results", key, "mean_best_curve"});
      if (!c.is_array()) continue;
      io::Series s;
      s.label = variant_label(key);
      for (std::size_t i = 0; i < c.size(); ++i) {
        s.x.push_back(static_cast<double>(i + 1));
        s.y.push_back(c[i].is_number() ? c[i].get<double>() : std::numeric_limits<double>::infinity());
      }
      series.push_back(s);
    }
    figs.emplace_back("convergence-10m.svg",
                      io::svg_line_chart(series, io::ChartOptions{fmt::format("10 m map (ratio {}, seed {}): mean best length (cf. Fig. 10)",
                                                                              fixed(m.at("ratio").get<double>(), 2),
                                                                              m.at("map_seed").get<std::int64_t>()),
                                                                  "iteration", "path length (m)"}));
    std::vector<io::PathLayer> layers;
    for (const std::string key : {"iaco-han", "aco", "iaco-han:1/d", "astar-han"}) {
      const Json& best = at_or_null(m, {"results", key, "best"});
      if (!best.is_object() || !best.contains("path")) continue;
      layers.push_back(io::PathLayer{fmt::format("{} (length {})", variant_label(key), md_number(best.at("length"), 2)),
                                     grid::path_from_json(best.at("path"))});
    }
    const grid::Grid g = grid::grid_from_json(m.at("rows"));
    const grid::Cell start = grid::cell_from_json(m.at("start"));
    const grid::Cell goal = grid::cell_from_json(m.at("goal"));
    figs.emplace_back("paths-10m.svg", io::svg_map(g, start, goal, layers, "10 m random map: best paths (cf. Fig. 7)"));
    // The IACO-A* run of the best seed with its two moving obstacles (cf. Fig. 8), re-simulated
    // from the document (the path is the best run's, the obstacles those recorded for its seed).
    const Json& best = at_or_null(m, {"results", "iaco-han", "best"});
    const Json& druns = at_or_null(m, {"dynamic", "iaco-han", "runs"});
    if (best.is_object() && best.contains("path") && druns.is_array()) {
      for (const Json& r : druns) {
        if (r.at("seed") != best.at("seed") || !r.at("simulated").get<bool>()) continue;
        sim::Scenario sc;
        sc.grid = g;
        sc.start = start;
        sc.goal = goal;
        sc.policy = grid::parse_corner_policy(doc.at("protocol").at("policy").get<std::string>());
        sc.path = grid::path_from_json(best.at("path"));
        for (const Json& o : r.at("obstacles")) {
          sim::MovingObstacle mo;
          mo.position = sim::Vec2{o.at("position")[0].get<double>(), o.at("position")[1].get<double>()};
          mo.velocity = sim::Vec2{o.at("velocity")[0].get<double>(), o.at("velocity")[1].get<double>()};
          mo.radius = o.at("radius").get<double>();
          sc.obstacles.push_back(mo);
        }
        figs.emplace_back("dynamic-10m.svg", io::svg_simulation(sc, sim::simulate(sc)));
        break;
      }
    }
    break;
  }
  return figs;
}

std::string han_markdown(const Json& doc, const std::string& figure_dir, const std::string& json_name) {
  std::string s;
  const Json& p = doc.at("protocol");
  s += "# Reproduction: Han (IJACSA), improved ACO and IACO-A* on random grid maps\n\n";
  s += "<!-- generated by `pathref reproduce han`; do not edit by hand -->\n\n";
  s += doc.at("reference").get<std::string>() + "\n\n";
  if (p.at("quick").get<bool>())
    s += "**QUICK RUN** (`--quick`: two small edges, reduced ants and iterations; a smoke test, not a reproduction).\n\n";
  s += "## Summary\n\n" + md_verdict_summary(doc.at("claims")) +
       "\nSee [Claims](#claims) for each verdict and its rule; protocol: spec/reproduce.md.\n\n";
  s += "## Protocol\n\n";
  s += fmt::format("- maps: `sim::random_map` (rule han.maps.random): square, 1 m cells, start (0,0), goal "
                   "(E−1,E−1), a random monotone corridor kept free; edges {}; {} map(s) per edge with obstacle "
                   "ratios evenly spaced in [0.2, 0.7]; map j (in edge order, then ratio) has seed {} + j.\n",
                   p.at("edges").dump(), p.at("maps_per_edge").get<std::int64_t>(), p.at("seed").get<std::int64_t>());
  s += fmt::format("- runs: the protocol's n = {} per stochastic planner on each 10 m map (Figures 10, 11) and n = {} on "
                   "each map of the other edges (Figure 12); pathref ran 2n ({} and {}), run seeds {} + r, and judges "
                   "every claim on the first n runs of each map and on all 2n; the tables summarise all 2n. A* once. "
                   "Corner policy `{}`.\n",
                   p.at("runs_10m").get<std::int64_t>(), p.at("sweep_runs").get<std::int64_t>(),
                   p.value("runs_10m_2n", std::int64_t{0}), p.value("sweep_runs_2n", std::int64_t{0}),
                   p.at("seed").get<std::int64_t>(), p.at("policy").get<std::string>());
  s += "- judging (spec/reproduce.md reproduce.judge, spec/stats.md, fixed before these runs): every claim of Han is "
       "a comparison of IACO-A* with ACO; it holds when the two-sided Mann–Whitney U test on the runs pooled over the "
       "edge's maps is significant at α = 0.05 in the claimed direction (Welch's t printed beside it), \"does not hold "
       "— the opposite is significant\" when it is significant the other way, else \"not significant\" with the "
       "observed direction. Han compares minima and a standard deviation of unpublished runs; minima are extreme "
       "values that more runs can only lower, so pathref tests the whole distribution of the runs and prints the "
       "minima beside it; the standard-deviation claim H.3 uses the 95 % bootstrap interval of sd(IACO-A*) − sd(ACO) "
       "of the distances relative to each map's mean.\n";
  s += "- planners (the exact parameters are in the JSON, `maps[i].results.KEY.params_used`):\n";
  for (const Json& v : p.at("variants"))
    s += fmt::format("  - `{}`: {} — overrides {}\n", v.at("key").get<std::string>(), v.at("label").get<std::string>(),
                     v.at("params").dump());
  s += "- **with moving obstacles** (the paper's protocol for Figs. 10–12: \"two DO in the grid map, and their initial "
       "positions appear randomly\"; reproduce.han.dynamic): every run of `iaco-han` (IACO-A*: its global path, then "
       "the A* and wait rules of han.sim.run) and of `aco` (the paper's ACO \"avoids O1 and O2 with the same movement "
       "mode\") is driven by `pathref simulate`'s rules with two scripted obstacles drawn from the run's seed: O1 "
       "crosses the path perpendicular to it at a random arc fraction in [0.2, 0.8] (Fig. 8(b)–(c), a side "
       "encounter), O2 comes head-on along the path at a random fraction in [0.5, 0.9] (Fig. 8(d), frontal), each at "
       "0.25–1 m/s and timed to reach its point when the robot would without obstacles. " +
       p.at("simulation").get<std::string>() +
       ". **Assumed** (the paper gives no speeds, directions or timing of its obstacles): placing them on the path so "
       "that every run meets one side and one frontal encounter, as in Fig. 8; uniformly random obstacles would "
       "rarely meet the robot on large maps.\n";
  s += "- statistics: per map, the minimum / mean / **sample** standard deviation (n − 1) of the runs (planned "
       "lengths over the runs that found a path; driven distances and times over the simulated runs that reached the "
       "goal without a collision); **per edge, the mean over its maps** of those per-map values (a minimum only when "
       "every map has one); **iterations to converge: the mean over all runs of the edge's maps, pooled** "
       "(reproduce.converge); moving time: the simulated arrival time.\n\n";

  // Findings.
  s += "## Findings\n\n";
  for (const Json& e : doc.at("edges")) {
    if (e.at("edge").get<std::int64_t>() != 10) continue;
    const Json& v = e.at("variants");
    auto frac = [&](const std::string& k) {
      if (!v.contains(k)) return std::string("—");
      return fmt::format("{} of {}", v.at(k).at("converged_at_1").get<std::int64_t>(),
                         v.at(k).at("converged_runs").get<std::int64_t>());
    };
    s += fmt::format("- **Stagnation** (spec/han.md, \"Stagnation\"): on the 10 m maps the best path of `iaco-han` "
                     "is found in iteration 1 and never improved in {} runs (η = 1/d_ij: {}; ACO: {}). This follows "
                     "from the printed α = 4 with τ ranging from τ_min = 0.01 to about 25 and q0 ≈ 0.9 in the first "
                     "iterations (Eq. 5): one iteration's trail dominates every later choice; the pheromone update "
                     "itself is as specified and replayed by the crosscheck.\n",
                     frac("iaco-han"), frac("iaco-han:1/d"), frac("aco"));
  }
  for (const Json& e : doc.at("edges")) {
    const auto E = e.at("edge").get<std::int64_t>();
    if (E != 10 && E != 100) continue;
    s += fmt::format("- **η** at edge {} m: planned minimum length {} (η = 1/(d_ij + d_jE), the default since this "
                     "revision) against {} (η = 1/d_ij, the former default) and {} (A*): with η = 1/d_ij the "
                     "first, nearly greedy iteration walks a compass order with no pull towards the goal "
                     "(spec/han.md, \"Why η = 1/(d_ij + d_jE)\").\n",
                     E, md_number(at_or_null(e, {"variants", "iaco-han", "min_length"}), 2),
                     md_number(at_or_null(e, {"variants", "iaco-han:1/d", "min_length"}), 2),
                     md_number(at_or_null(e, {"variants", "astar-han", "min_length"}), 2));
  }
  {
    // The densest maps (ratio 0.70): how much choice the corridor generator leaves.
    std::int64_t deg = 0, n70 = 0, deg70 = 0, maps = 0;
    double worst_gap = 0.0, worst_std = 0.0;
    for (const Json& m : doc.at("maps")) {
      ++maps;
      const bool d = m.at("degenerate").get<bool>();
      deg += d ? 1 : 0;
      if (m.at("ratio").get<double>() < 0.69) continue;
      ++n70;
      deg70 += d ? 1 : 0;
      const Json& a = at_or_null(m, {"results", "astar-han", "summary", "length", "min"});
      for (const char* k : {"iaco-han", "aco"}) {
        const Json& mn = at_or_null(m, {"results", k, "summary", "length", "min"});
        const Json& sd = at_or_null(m, {"results", k, "summary", "length", "std"});
        if (mn.is_number() && a.is_number()) worst_gap = std::max(worst_gap, mn.get<double>() - a.get<double>());
        if (sd.is_number()) worst_std = std::max(worst_std, sd.get<double>());
      }
    }
    s += fmt::format("- **Degenerate 70 % maps**: with ⌊0.7·E²⌋ obstacles only E² − ⌊0.7·E²⌋ − (2E − 1) free cells "
                     "remain off the corridor (11 of 100 at E = 10, 28 % of the cells at E = 100), below the "
                     "percolation threshold, so they form small pockets and the corridor is essentially the only "
                     "route. On the {} maps of ratio 0.70 the minimum planned lengths of `iaco-han` and `aco` exceed "
                     "A*'s by at most {} m and their per-map standard deviations are at most {} m; {} of them (and "
                     "{} of all {} maps) are fully degenerate: every run of every colony has the A* length, standard "
                     "deviation 0 (column `degenerate`). They are not removed: they enter the per-edge means with "
                     "weight 1/K like every map, which pulls the mean standard deviations towards 0 and dilutes the "
                     "differences between planners by that weight.\n",
                     n70, fixed(worst_gap, 4), fixed(worst_std, 4), deg70, deg, maps);
  }
  s += "- **Moving time** is simulated (waits, 1 m/s² restarts and detours included), so it is no longer the minimum "
       "length divided by 1 m/s.\n\n";

  s += "## 10 m maps (Figures 10, 11)\n\n";
  s += "Planned paths (global planners, no moving obstacles):\n\n";
  s += md_row({"map", "ratio", "map seed", "degenerate", "variant", "runs", "found", "min length", "mean length", "std length",
               "mean iter. to converge", "A* length"});
  s += md_row({"---", "---:", "---:", "---", "---", "---:", "---:", "---:", "---:", "---:", "---:", "---:"});
  int mi = 0;
  for (const Json& m : doc.at("maps")) {
    ++mi;
    if (m.at("edge").get<std::int64_t>() != 10) continue;
    for (const auto& v : han_variants()) {
      if (deterministic(v.planner) || !m.at("results").contains(v.key)) continue;
      const Json& r = m.at("results").at(v.key);
      const std::string deg = m.at("degenerate").get<bool>() ? "yes" : "no";
      if (!r.value("available", false)) {
        s += md_row({std::to_string(mi), fixed(m.at("ratio").get<double>(), 2),
                     std::to_string(m.at("map_seed").get<std::int64_t>()), deg, "`" + v.key + "`", "not available", "",
                     "", "", "", "", ""});
        continue;
      }
      const Json& sm = r.at("summary");
      s += md_row({std::to_string(mi), fixed(m.at("ratio").get<double>(), 2),
                   std::to_string(m.at("map_seed").get<std::int64_t>()), deg, "`" + v.key + "`",
                   std::to_string(sm.at("runs").get<std::int64_t>()), std::to_string(sm.at("found").get<std::int64_t>()),
                   md_number(sm.at("length").at("min"), 4), md_number(sm.at("length").at("mean"), 4),
                   md_number(sm.at("length").at("std"), 4), md_number(sm.at("converged_at").at("mean"), 2),
                   md_number(at_or_null(m, {"results", "astar-han", "summary", "length", "min"}), 4)});
    }
  }
  s += "\nWith two moving obstacles (every run's path driven by the simulation):\n\n";
  s += md_row({"map", "ratio", "planner", "simulated", "reached", "runs with a collision", "unexplained collisions",
               "min distance", "mean distance", "std distance", "min time (s)", "mean waits", "mean replans",
               "mean evasions"});
  s += md_row({"---", "---:", "---", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:"});
  mi = 0;
  for (const Json& m : doc.at("maps")) {
    ++mi;
    if (m.at("edge").get<std::int64_t>() != 10) continue;
    for (const auto& [key, d] : m.at("dynamic").items()) {
      const Json& sm = d.at("summary");
      s += md_row({std::to_string(mi), fixed(m.at("ratio").get<double>(), 2), "`" + key + "`",
                   std::to_string(sm.at("simulated").get<std::int64_t>()), std::to_string(sm.at("reached").get<std::int64_t>()),
                   std::to_string(sm.at("collided").get<std::int64_t>()),
                   std::to_string(sm.at("unexplained_collisions").get<std::int64_t>()),
                   md_number(sm.at("distance").at("min"), 4), md_number(sm.at("distance").at("mean"), 4),
                   md_number(sm.at("distance").at("std"), 4), md_number(sm.at("time").at("min"), 2),
                   md_number(sm.at("waits").at("mean"), 2), md_number(sm.at("replans").at("mean"), 2),
                   md_number(sm.at("evasions").at("mean"), 2)});
    }
  }
  s += fmt::format("\n![convergence on a 10 m map]({0}/convergence-10m.svg)\n\n![paths on a 10 m map]({0}/paths-10m.svg)\n\n"
                   "![IACO-A* with two moving obstacles on a 10 m map]({0}/dynamic-10m.svg)\n\n",
                   figure_dir);
  s += "## Path length and time against the map edge (Figure 12)\n\n";
  s += "Planned paths (no moving obstacles; means over the edge's maps, iterations pooled over its runs):\n\n"
       "<!-- results:edges -->\n";
  s += md_row({"edge (m)", "degenerate maps", "IACO-A* min length", "ACO min length", "A* length", "IACO-A* η=1/d min length",
               "ACO η=1/d min length", "IACO-A* found", "ACO found", "IACO-A* found (die)", "ACO found (die)",
               "IACO-A* iter.", "ACO iter.", "IACO-A* wall (ms)", "ACO wall (ms)"});
  s += md_row({"---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:",
               "---:", "---:"});
  for (const Json& e : doc.at("edges")) {
    const Json& v = e.at("variants");
    auto found = [&](const std::string& k) {
      if (!v.contains(k)) return std::string("—");
      return fmt::format("{}/{}", v.at(k).at("found").get<std::int64_t>(), v.at(k).at("runs").get<std::int64_t>());
    };
    s += md_row({std::to_string(e.at("edge").get<std::int64_t>()),
                 fmt::format("{}/{}", e.at("degenerate_maps").get<std::int64_t>(), v.at("iaco-han").at("maps").get<std::int64_t>()),
                 md_number(v.at("iaco-han").at("min_length"), 4), md_number(v.at("aco").at("min_length"), 4),
                 md_number(v.at("astar-han").at("min_length"), 4), md_number(at_or_null(v, {"iaco-han:1/d", "min_length"}), 4),
                 md_number(at_or_null(v, {"aco:1/d", "min_length"}), 4), found("iaco-han"), found("aco"), found("iaco-han@die"),
                 found("aco@die"), md_number(v.at("iaco-han").at("converged_at"), 2),
                 md_number(v.at("aco").at("converged_at"), 2), md_number(v.at("iaco-han").at("wall_ms"), 1),
                 md_number(v.at("aco").at("wall_ms"), 1)});
  }
  s += "\nWith two moving obstacles (means over the edge's maps of the per-map values; collision-free runs that "
       "reached the goal):\n\n<!-- results:dynamic -->\n";
  s += md_row({"edge (m)", "IACO-A* min distance", "ACO min distance", "IACO-A* min time (s)", "ACO min time (s)",
               "IACO-A* reached", "ACO reached", "IACO-A* runs with a collision", "ACO runs with a collision",
               "unexplained collisions", "IACO-A* waits", "IACO-A* replans", "IACO-A* evasions"});
  s += md_row({"---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:"});
  for (const Json& e : doc.at("edges")) {
    const Json& a = e.at("dynamic").at("iaco-han");
    const Json& b = e.at("dynamic").at("aco");
    s += md_row({std::to_string(e.at("edge").get<std::int64_t>()), md_number(a.at("min_distance"), 4),
                 md_number(b.at("min_distance"), 4), md_number(a.at("min_time"), 2), md_number(b.at("min_time"), 2),
                 fmt::format("{}/{}", a.at("reached").get<std::int64_t>(), a.at("simulated").get<std::int64_t>()),
                 fmt::format("{}/{}", b.at("reached").get<std::int64_t>(), b.at("simulated").get<std::int64_t>()),
                 std::to_string(a.at("collided").get<std::int64_t>()), std::to_string(b.at("collided").get<std::int64_t>()),
                 std::to_string(a.at("unexplained_collisions").get<std::int64_t>() +
                                b.at("unexplained_collisions").get<std::int64_t>()),
                 md_number(a.at("waits"), 2), md_number(a.at("replans"), 2), md_number(a.at("evasions"), 2)});
  }
  s += fmt::format("\n![length against edge]({0}/length-vs-edge.svg)\n\n![time against edge]({0}/time-vs-edge.svg)\n\n"
                   "![planning time against edge]({0}/planning-time-vs-edge.svg)\n\n",
                   figure_dir);
  s += "## Parameters\n\nEvery variant with the parameters its runs used (first 10 m map) and why:\n\n";
  s += md_row({"variant", "parameters used (params_used)", "why these"});
  s += md_row({"---", "---", "---"});
  {
    const Json* first10 = nullptr;
    for (const Json& m : doc.at("maps"))
      if (m.at("edge").get<std::int64_t>() == 10) {
        first10 = &m;
        break;
      }
    for (const auto& v : han_variants()) {
      const Json& r = first10 == nullptr ? Json() : at_or_null(*first10, {"results", v.key});
      std::string used = "—";
      if (r.is_object() && r.value("available", false)) {
        used.clear();
        const Json& pu = r.at("params_used");
        for (auto it = pu.begin(); it != pu.end(); ++it)
          used += (used.empty() ? "" : ", ") + it.key() + " = " +
                  (it.value().is_string() ? it.value().get<std::string>() : it.value().dump());
        used = "`" + used + "`";
      }
      s += md_row({"`" + v.key + "`", used, han_variant_why(v.key)});
    }
  }
  s += "\n";
  s += "## Claims\n\n" + md_claims(doc.at("claims")) + "\n";
  {
    std::string ch;
    for (const Json& c : doc.at("claims"))
      if (c.value("changed", false))
        ch += fmt::format("- {}: {}\n", c.at("id").get<std::string>(), c.at("change_note").get<std::string>());
    s += "### Verdicts that change between n and 2n runs\n\n" + (ch.empty() ? std::string("No verdict changes between n and 2n runs.\n") : ch) + "\n";
  }
  s += "## Provenance\n\n" + md_provenance(doc.at("provenance"), json_name);
  return s;
}

}  // namespace pathref::reproduce
