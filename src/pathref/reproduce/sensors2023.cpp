// `pathref reproduce sensors2023`. Spec: spec/sensors2023-dwa.md (section "Reproduction").
#include "pathref/reproduce/sensors2023.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <string>

#include "pathref/core/error.hpp"
#include "pathref/io/svg.hpp"
#include "pathref/io/svg_fused.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/reproduce/runs.hpp"
#include "pathref/reproduce/stats.hpp"
#include "pathref/rng/draws.hpp"
#include "pathref/rng/mt19937.hpp"
#include "pathref/sim/encounter.hpp"

namespace pathref::reproduce {

namespace {

using dwa::FusedResult;
using dwa::FusedScenario;
using dwa::Outcome;
using dwa::Point;

constexpr grid::Cell scene_start{4, 3};
constexpr grid::Cell scene_goal{17, 16};

/// An arm of the comparison: the global planner and what the DWA's heading aims at.
struct Arm {
  std::string key;
  std::string label;
  std::string planner;  ///< registered name
  dwa::HeadingTarget target = dwa::HeadingTarget::key_node;  ///< waypoint: the traditional DWA (default reading)
  bool raw_path = false; ///< astar-kinematic: hand the DWA its raw A* path instead of its key nodes
  bool static_only = false; ///< run on the static maps only (the alternative readings of the baseline)
};

/// The arms (spec sensors2023-dwa.md "Reproduction"). T and K use the default reading of
/// "traditional DWA" (traditional_dwa = waypoint); Tg and Kg are the same arms under the
/// alternative traditional_dwa = final_goal, run on the static maps (the claims that rest on the
/// reading are judged there) and on the scene.
std::vector<Arm> arms() {
  using dwa::HeadingTarget;
  std::vector<Arm> a{{"T", "traditional A* + traditional DWA", "astar", HeadingTarget::waypoint},
                     {"F", "traditional A* + following DWA", "astar", HeadingTarget::key_node}};
  if (planners::find_planner("astar-kinematic") != nullptr) {
    a.push_back(Arm{"K", "kinematic A* + traditional DWA", "astar-kinematic", HeadingTarget::waypoint});
    a.push_back(Arm{"KF", "kinematic A* + following DWA (the paper's fusion)", "astar-kinematic", HeadingTarget::key_node});
    a.push_back(Arm{"KFt", "kinematic A* (raw path) + following DWA: the alternative reading of KF, reported, not judged",
                    "astar-kinematic", HeadingTarget::key_node, true});
    a.push_back(Arm{"Tg", "arm T under traditional_dwa = final_goal (heading at the final goal): the alternative reading, static only",
                    "astar", HeadingTarget::goal, false, true});
    a.push_back(Arm{"Kg", "arm K under traditional_dwa = final_goal: the alternative reading, static only", "astar-kinematic",
                    HeadingTarget::goal, false, true});
  }
  return a;
}

/// The scene's scripted obstacles (spec sensors2023-dwa.md#reproduction).
dwa::Mover scene_mover() { return dwa::Mover{0.4, {{0.0, {11.5, 0.5}}, {10.0, {9.5, 4.5}}}}; }
dwa::Temporary scene_temporary() { return dwa::Temporary{grid::Cell{14, 15}, 0.0, 40.0}; }

/// One run of a registered planner on (g, s, t) with parameter overrides.
planners::Result plan(const std::string& name, const grid::Grid& g, grid::Cell s, grid::Cell t,
                      const Json& params = Json::object()) {
  const planners::Planner* p = planners::find_planner(name);
  require(p != nullptr, "reproduce sensors2023: planner '" + name + "' is not registered");
  planners::Request req;
  req.grid = &g;
  req.start = s;
  req.goal = t;
  req.params = params;
  return p->run(req);
}

/// The key nodes of astar-kinematic (its defaults: the secondary-removal result) as cells; empty
/// when it finds no path.
std::vector<grid::Cell> kinematic_key_nodes(const grid::Grid& g, grid::Cell s, grid::Cell t) {
  const planners::Result r = plan("astar-kinematic", g, s, t);
  std::vector<grid::Cell> out;
  if (!r.found || !r.extra.contains("key_nodes")) return out;
  for (const Json& c : r.extra.at("key_nodes")) out.push_back(grid::Cell{c.at(0).get<std::int64_t>(), c.at(1).get<std::int64_t>()});
  return out;
}

/// The scenario of an arm (spec "Reproduction"): arms T and F let the fused run plan with `astar`
/// (key nodes = the path's turning cells); arms K and KF hand it the kinematic A*'s key nodes
/// (after secondary redundancy removal) as the global path.
FusedScenario base_scenario(const grid::Grid& g, grid::Cell s, grid::Cell t, const Arm& arm) {
  FusedScenario sc;
  sc.grid = g;
  sc.start = s;
  sc.goal = t;
  sc.planner = arm.planner;
  sc.heading_target = arm.target;
  if (arm.planner == "astar-kinematic" && !arm.raw_path) sc.path = kinematic_key_nodes(g, s, t);
  return sc;
}

/// Mean distance of the samples to the global path polyline (cell centres).
double mean_deviation(const FusedResult& r) {
  if (r.global_path.size() < 2 || r.samples.empty()) return 0.0;
  std::vector<sim::Vec2> gp;
  for (const grid::Cell c : r.global_path) gp.push_back(sim::centre(c));
  double s = 0.0;
  for (const auto& smp : r.samples) {
    double m = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 1 < gp.size(); ++i)
      m = std::min(m, sim::point_segment_distance(sim::Vec2{smp.pose.x, smp.pose.y}, gp[i], gp[i + 1]));
    s = s + m;
  }
  return s / static_cast<double>(r.samples.size());
}

/// Sample standard deviation of the commanded v and w over a run (0 for fewer than 2 samples).
std::pair<double, double> fluctuation(const FusedResult& r) {
  std::vector<double> v, w;
  for (const auto& smp : r.samples) {
    v.push_back(smp.v);
    w.push_back(smp.w);
  }
  if (v.size() < 2) return {0.0, 0.0};
  return {sample_std(v), sample_std(w)};
}

/// Turns of the global grid path (cells where the direction changes).
std::int64_t grid_turns(const std::vector<grid::Cell>& p) {
  const auto k = dwa::key_nodes(p);
  return k.size() >= 2 ? static_cast<std::int64_t>(k.size()) - 2 : 0;
}

Json run_json(const FusedScenario& sc, const FusedResult& r, double wall_s) {
  const auto [sv, sw] = fluctuation(r);
  // deceleration: mean commanded v where the point clearance is small vs large
  double v_near = 0.0, v_far = 0.0;
  std::int64_t n_near = 0, n_far = 0;
  std::vector<grid::Cell> none;
  for (const auto& smp : r.samples) {
    std::vector<dwa::Disc> discs;
    for (const auto& m : sc.moving) discs.push_back(dwa::Disc{dwa::obstacle_position(m.waypoints, smp.t), m.r, {}});
    std::vector<grid::Cell> present;
    for (const auto& t : sc.temporary)
      if (t.appear <= smp.t && smp.t < t.disappear) present.push_back(t.cell);
    const double c = dwa::point_clearance(Point{smp.pose.x, smp.pose.y}, dwa::Obstacles{&sc.grid, present, discs},
                                          sc.dwa.radius, sc.dwa.clearance_cap);
    if (c < 0.25) {
      v_near = v_near + smp.v;
      ++n_near;
    } else if (c >= sc.dwa.clearance_cap) {
      v_far = v_far + smp.v;
      ++n_far;
    }
  }
  Json j{{"outcome", std::string(dwa::to_string(r.outcome))},
         {"time", r.time},
         {"length", r.length},
         {"turns", r.turns},
         {"grid_turns", r.global_found ? grid_turns(r.global_path) : 0},
         {"min_clearance", r.min_clearance},
         {"steps", r.steps},
         {"braked_steps", r.braked_steps},
         {"skips", r.skips.size()},
         {"deviation", mean_deviation(r)},
         {"sd_v", sv},
         {"sd_w", sw},
         {"v_near", n_near > 0 ? Json(v_near / static_cast<double>(n_near)) : Json(nullptr)},
         {"v_far", n_far > 0 ? Json(v_far / static_cast<double>(n_far)) : Json(nullptr)},
         {"end_v", r.samples.empty() ? 0.0 : r.samples.back().v},
         {"end_w", r.samples.empty() ? 0.0 : r.samples.back().w},
         {"wall_s", wall_s},
         {"global_cells", r.global_path.size()},
         {"key_nodes", r.key_nodes.size()}};
  return j;
}

struct Timed {
  FusedResult r;
  double wall_s = 0.0;
};

Timed run_timed(const FusedScenario& sc) {
  const auto t0 = std::chrono::steady_clock::now();
  Timed t{dwa::simulate_fused(sc), 0.0};
  t.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return t;
}

/// The dynamic obstacles of a random map's run (spec "Reproduction"): a mover crossing the global
/// path at the cell half-way along it, perpendicular to the path there, 0.5 m/s, reaching the
/// crossing at the time the robot would at 0.5 m/s, then going on for 6 m; a temporary cell on the
/// key node three quarters along the key nodes (not the goal) for 0 <= t < 20 s.
void add_random_dynamics(FusedScenario& sc, const std::vector<grid::Cell>& path, bool mixed) {
  if (path.size() < 3) return;
  const std::size_t mid = path.size() / 2;
  const sim::Vec2 a = sim::centre(path[mid - 1]), b = sim::centre(path[mid]);
  double dx = b.x - a.x, dy = b.y - a.y;
  const double n = std::sqrt((dx * dx) + (dy * dy));
  dx = dx / n;
  dy = dy / n;
  double arc = 0.0;
  for (std::size_t i = 1; i <= mid; ++i) arc = arc + grid::step_cost(path[i - 1], path[i]);
  const double t_cross = arc / 0.5;
  const Point c{b.x, b.y};
  const Point from{c.x - (dy * (0.5 * t_cross)), c.y + (dx * (0.5 * t_cross))};
  const Point to{c.x + (dy * 6.0), c.y - (dx * 6.0)};
  sc.moving.push_back(dwa::Mover{0.4, {{0.0, from}, {t_cross, c}, {t_cross + 12.0, to}}});
  if (mixed) {
    const auto keys = dwa::key_nodes(path);
    if (keys.size() >= 3) {
      const std::size_t k = std::min(keys.size() - 2, std::max<std::size_t>(1, (3 * (keys.size() - 1)) / 4));
      sc.temporary.push_back(dwa::Temporary{keys[k], 0.0, 20.0});
    }
  }
}

Json scenario_summary(const FusedScenario& sc) {
  Json mv = Json::array();
  for (const auto& m : sc.moving) {
    Json w = Json::array();
    for (const auto& p : m.waypoints) w.push_back(Json::array({p.t, p.q.x, p.q.y}));
    mv.push_back(Json{{"radius", m.r}, {"waypoints", w}});
  }
  Json tp = Json::array();
  for (const auto& t : sc.temporary)
    tp.push_back(Json{{"cell", Json::array({t.cell.x, t.cell.y})}, {"appear", t.appear}, {"disappear", t.disappear}});
  return Json{{"start", Json::array({sc.start.x, sc.start.y})}, {"goal", Json::array({sc.goal.x, sc.goal.y})},
              {"moving", mv}, {"temporary", tp}};
}

std::vector<std::pair<std::string, FusedScenario>> scene_scenarios(const grid::Grid& g, const Arm& arm) {
  std::vector<std::pair<std::string, FusedScenario>> out;
  FusedScenario st = base_scenario(g, scene_start, scene_goal, arm);
  out.emplace_back("static", st);
  FusedScenario dy = st;
  dy.moving.push_back(scene_mover());
  out.emplace_back("dynamic", dy);
  FusedScenario mx = dy;
  mx.temporary.push_back(scene_temporary());
  out.emplace_back("mixed", mx);
  return out;
}

}  // namespace

const std::vector<std::string>& sensors2023_scene_rows() {
  // y = 20 (top) ... y = 0 (bottom); blocks: (7-9, 6-8), (12-14, 2-4), (2-4, 8-11), (11-12, 9-13),
  // (15-18, 9-10), (6-8, 13-16), (14-15, 17-19), (18-19, 2-5), (3-5, 17-18): 80 cells (18.1 %).
  static const std::vector<std::string> rows = [] {
    std::vector<std::string> r(21, std::string(21, '.'));
    auto block = [&](int x0, int x1, int y0, int y1) {
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) r[static_cast<std::size_t>(20 - y)][static_cast<std::size_t>(x)] = '#';
    };
    block(7, 9, 6, 8);
    block(12, 14, 2, 4);
    block(2, 4, 8, 11);
    block(11, 12, 9, 13);
    block(15, 18, 9, 10);
    block(6, 8, 13, 16);
    block(14, 15, 17, 19);
    block(18, 19, 2, 5);
    block(3, 5, 17, 18);
    return r;
  }();
  return rows;
}

grid::Grid sensors2023_random_map(std::uint32_t seed, std::int64_t edge, double density, grid::Cell start,
                                  grid::Cell goal) {
  require(edge >= 5 && edge <= 200, "sensors2023_random_map: edge must be in [5, 200]");
  require(std::isfinite(density) && density >= 0.0 && density <= 0.6, "sensors2023_random_map: density in [0, 0.6]");
  grid::Grid g(edge, edge);
  require(g.in_bounds(start) && g.in_bounds(goal), "sensors2023_random_map: start and goal inside the map");
  auto near = [](grid::Cell a, grid::Cell b) { return std::abs(a.x - b.x) <= 1 && std::abs(a.y - b.y) <= 1; };
  std::vector<std::int64_t> cand;
  for (std::int64_t i = 0; i < g.cell_count(); ++i) {
    const grid::Cell c = g.cell(i);
    if (!near(c, start) && !near(c, goal)) cand.push_back(i);
  }
  const auto n = std::min<std::int64_t>(static_cast<std::int64_t>(std::floor(density * static_cast<double>(edge * edge))),
                                        static_cast<std::int64_t>(cand.size()));
  rng::Stream s(seed);
  for (std::int64_t i = 0; i < n; ++i) {
    const auto left = static_cast<std::int64_t>(cand.size()) - i;
    const std::int64_t j = i + static_cast<std::int64_t>(rng::uniform_index(s.next_double(), static_cast<std::uint64_t>(left)));
    std::swap(cand[static_cast<std::size_t>(i)], cand[static_cast<std::size_t>(j)]);
    g.set_blocked(g.cell(cand[static_cast<std::size_t>(i)]), true);
  }
  return g;
}

namespace {

constexpr grid::Cell children_start{6, 7};  ///< the paper's 5-direction test (6, 7) -> (17, 16)
const char* const conditions[3] = {"static", "dynamic", "mixed"};

/// The global planner's outputs on one map (spec "Reproduction", "Global planner"): S8, S5, SK
/// and astar.
Json global_json(const grid::Grid& g, grid::Cell s, grid::Cell t) {
  Json j = Json::object();
  const auto counts = [](const planners::Result& r) {
    return Json{{"found", r.found},
                {"child_nodes", r.extra.value("child_nodes", std::int64_t{0})},
                {"generated", r.extra.value("generated", std::int64_t{0})},
                {"expansions", r.extra.value("expansions", std::int64_t{0})}};
  };
  j["S8"] = counts(plan("astar-kinematic", g, s, t, Json{{"directions", 8}, {"weight", "none"}, {"redundancy", "none"}}));
  j["S5"] = counts(plan("astar-kinematic", g, s, t, Json{{"directions", 5}, {"weight", "none"}, {"redundancy", "none"}}));
  const planners::Result k = plan("astar-kinematic", g, s, t);
  Json sk = counts(k);
  if (k.found) {
    for (const char* f : {"turns_raw", "turns_ordinary", "turns_secondary", "turns_key"}) sk[f] = k.extra.at(f);
    sk["key_length"] = k.extra.at("key_length");
    sk["path_length"] = k.length;
    sk["curve_length"] = k.extra.contains("curve") ? k.extra.at("curve").at("length") : Json(nullptr);
    sk["key_nodes"] = k.extra.at("key_nodes");
  }
  j["SK"] = sk;
  const planners::Result a = plan("astar", g, s, t);
  j["astar"] = Json{{"found", a.found}, {"length", a.length}, {"expansions", a.expansions}};
  return j;
}

/// Pairs (a_i, b_i) of a claim over the first `count` maps: a = the improved arm's value, b = the
/// baseline's; maps where `get` gives nothing are skipped, maps with b <= 0 counted and skipped.
struct Pairs {
  std::vector<double> a, b;
  std::int64_t skipped_zero = 0;
  std::int64_t maps = 0;
};
using PairGetter = std::function<std::optional<std::pair<double, double>>(const Json& map)>;

Pairs collect(const std::vector<Json>& maps, std::size_t count, const PairGetter& get) {
  Pairs p;
  for (std::size_t i = 0; i < count && i < maps.size(); ++i) {
    ++p.maps;
    const auto v = get(maps[i]);
    if (!v) continue;
    if (!(v->second > 0.0)) {
      ++p.skipped_zero;
      continue;
    }
    p.a.push_back(v->first);
    p.b.push_back(v->second);
  }
  return p;
}

/// Getter of metric `key` of arms `to` (a) and `from` (b) in condition `cond`, both reached.
PairGetter arm_pair(const std::string& cond, const std::string& from, const std::string& to, const std::string& key) {
  return [=](const Json& m) -> std::optional<std::pair<double, double>> {
    const Json& ra = m.at(cond).at(to);
    const Json& rb = m.at(cond).at(from);
    if (ra.at("outcome") != "reached" || rb.at("outcome") != "reached") return std::nullopt;
    return std::pair{ra.at(key).get<double>(), rb.at(key).get<double>()};
  };
}

/// Getter of global-planner fields: a = global[to_planner][to_key], b = global[from_planner][from_key].
PairGetter global_pair(const std::string& from_p, const std::string& from_k, const std::string& to_p,
                       const std::string& to_k) {
  return [=](const Json& m) -> std::optional<std::pair<double, double>> {
    const Json& g = m.at("global");
    const Json& va = g.at(to_p).contains(to_k) ? g.at(to_p).at(to_k) : Json(nullptr);
    const Json& vb = g.at(from_p).contains(from_k) ? g.at(from_p).at(from_k) : Json(nullptr);
    if (!va.is_number() || !vb.is_number()) return std::nullopt;
    return std::pair{va.get<double>(), vb.get<double>()};
  };
}

/// The paired statistics of spec "Reproduction": means, sds, the reduction 100 (mean b - mean a) /
/// mean b with its paired bootstrap interval, the paired interval of mean(a) - mean(b) and its
/// direction (judge_interval_comparison, claimed a < b), maps lower / higher.
Json paired_stats(const Pairs& p, const BootstrapOptions& o) {
  Json j{{"n", p.a.size()}, {"maps", p.maps}, {"skipped_zero_baseline", p.skipped_zero}};
  if (p.a.empty()) return j;
  const Summary sa = summarize(p.a), sb = summarize(p.b);
  j["a"] = summary_stats_json(sa);
  j["b"] = summary_stats_json(sb);
  j["reduction_percent"] = reduction_percent(*sb.mean, *sa.mean);
  std::int64_t lower = 0, higher = 0;
  for (std::size_t i = 0; i < p.a.size(); ++i) {
    lower += p.a[i] < p.b[i] ? 1 : 0;
    higher += p.a[i] > p.b[i] ? 1 : 0;
  }
  j["maps_lower"] = lower;
  j["maps_higher"] = higher;
  if (p.a.size() < 2) return j;
  const Interval red = bootstrap_paired_ci(p.a, p.b, BootStatistic::reduction_percent, o);
  const Interval dif = bootstrap_paired_ci(p.a, p.b, BootStatistic::mean_difference, o);
  j["reduction_ci"] = interval_json(red);
  j["difference_ci"] = interval_json(dif);
  j["direction"] = judgement_json(judge_interval_comparison(dif, Claimed::a_less));
  j["bootstrap"] = Json{{"paired", true}, {"seed", o.seed}, {"resamples", o.resamples}, {"level", o.level}};
  return j;
}

/// The direction of a paired difference in words (judge_interval_comparison, claimed a < b).
std::string direction_words(const Json& st) {
  if (!st.contains("direction")) return "—";
  const std::string v = st.at("direction").at("verdict").get<std::string>();
  if (v == "holds") return "lower as claimed (interval of the difference below 0)";
  if (v == "does not hold") return "higher: the opposite (interval above 0)";
  return "not significant (interval contains 0)";
}

std::string paired_text(const Json& st) {
  if (!st.contains("reduction_ci"))
    return st.value("n", std::size_t{0}) == 0 ? "—" : fmt::format("{} % (n = {})", fixed(st.at("reduction_percent").get<double>(), 1),
                                                                   st.at("n").get<std::size_t>());
  return fmt::format("{} % [{}, {}] ({} → {}; n = {}, lower on {}, higher on {}; direction: {})",
                     fixed(st.at("reduction_percent").get<double>(), 1), fixed(st.at("reduction_ci").at(0).get<double>(), 1),
                     fixed(st.at("reduction_ci").at(1).get<double>(), 1), fixed(st.at("b").at("mean").get<double>(), 2),
                     fixed(st.at("a").at("mean").get<double>(), 2), st.at("n").get<std::size_t>(),
                     st.at("maps_lower").get<std::int64_t>(), st.at("maps_higher").get<std::int64_t>(), direction_words(st));
}

/// A "reduces by P %" claim on paired maps (spec "Reproduction"): paired bootstrap interval of the
/// reduction within P +- 5 points, at n and at 2n maps.
/// The reconstructed rules (spec/index) each claim's verdict rests on (attach_rules; reproduce.markdown):
/// the child-node claims on the search (Eq. 1-3, Eq. 4 for the whole improved search), the
/// redundancy and global-length claims on the kinematic planner (Eq. 1-5), the curve on the
/// B-spline (Eq. 6-8, A1-A3), and every Table 2-4 claim on the planner, the DWA and the simulation.
std::vector<std::string> sensors2023_claim_rules(const std::string& id) {
  const std::vector<std::string> search{"sensors2023.eq1", "sensors2023.eq2", "sensors2023.eq3"};
  auto with = [](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const auto planner = with(search, {"sensors2023.eq4", "sensors2023.eq5", "sensors2023.plan.astar-kinematic"});
  const std::vector<std::string> curve{"sensors2023.eq6", "sensors2023.eq7", "sensors2023.eq8",
                                       "sensors2023.a1",  "sensors2023.a2",  "sensors2023.a3"};
  if (id == "s23.children" || id == "s23.children.scene") return search;
  if (id == "s23.children.full") return with(search, {"sensors2023.eq4"});
  if (id.rfind("s23.redundancy", 0) == 0 || id == "s23.global.length") return planner;
  if (id == "s23.global.length.curve") return with(planner, curve);
  return with(planner, {"sensors2023.eq9", "sensors2023.eq10", "sensors2023.eq11", "sensors2023.eq12",
                        "sensors2023.eq13", "sensors2023.eq14", "sensors2023.dwa.clearance", "sensors2023.dwa.step",
                        "sensors2023.dwa.follow", "sensors2023.sim.obstacles", "sensors2023.sim.collision",
                        "sensors2023.sim.turns", "sensors2023.sim.run"});
}

Claim paired_reduction_claim(Claim c, const Pairs& pn, const Pairs& p2n, double paper, const BootstrapOptions& o) {
  const double m = equivalence_margin(Quantity::percent, paper);
  c.paper = fmt::format("{} %", paper);
  c.rule = fmt::format("paired 95 % bootstrap interval (over maps) of the reduction of the means within {} ± {} points "
                       "(percent margin, stats.margin); direction by the paired interval of the mean difference",
                       paper, fixed(m, 0));
  const auto judge = [&](const Pairs& p, Verdict& v, Direction& d, std::string& ours) {
    const Json st = paired_stats(p, o);
    ours = paired_text(st);
    if (p.a.size() < 2) {
      v = Verdict::untestable;
      d = Direction::none;
      return st;
    }
    const Judgement j = judge_equivalence(Interval{st.at("reduction_ci").at(0).get<double>(), st.at("reduction_ci").at(1).get<double>()},
                                          paper, m, Sense::higher_is_better);
    v = j.verdict;
    d = j.direction;
    return st;
  };
  Verdict v = Verdict::untestable;
  Direction d = Direction::none;
  const Json sn = judge(pn, v, d, c.ours);
  c.verdict = v;
  c.direction = d;
  c.statistics = Json{{"n", sn}, {"2n", nullptr}, {"paper", paper}, {"margin", m}};
  if (pn.a.size() < 2) {
    c.note += (c.note.empty() ? "" : "; ") +
              fmt::format("cannot be tested: {} of {} maps give a pair (both arms reached the goal, baseline > 0)", pn.a.size(), pn.maps);
    return c;
  }
  if (p2n.a.size() >= 2) {
    Verdict v2 = Verdict::untestable;
    Direction d2 = Direction::none;
    c.statistics["2n"] = judge(p2n, v2, d2, c.ours_2n);
    c.verdict_2n = v2;
    c.direction_2n = d2;
  }
  if (pn.skipped_zero > 0 || p2n.skipped_zero > 0)
    c.note += (c.note.empty() ? "" : "; ") + fmt::format("{} (n) / {} (2n) maps left out: baseline value 0", pn.skipped_zero, p2n.skipped_zero);
  return c;
}

/// A reduction on the one scene (deterministic planners): the exact value within P +- 5 points.
Claim exact_reduction_claim(Claim c, double from, double to, double paper) {
  c.paper = fmt::format("{} %", paper);
  if (!(from > 0.0)) {
    c.verdict = Verdict::untestable;
    c.ours = "—";
    c.note += (c.note.empty() ? "" : "; ") + std::string("the baseline is 0 on the scene");
    return c;
  }
  exact_value_claim(c, reduction_percent(from, to), paper, Quantity::percent, Sense::higher_is_better, 1);
  c.ours = fmt::format("{} % ({} → {})", c.ours, fixed(from, 2), fixed(to, 2));
  return c;
}

/// "a is smaller than b" on paired maps: the paired bootstrap interval of mean(a) - mean(b)
/// judged by judge_interval_comparison (claimed a < b).
Judgement smaller_judgement(const Pairs& p, const BootstrapOptions& o, Json& st) {
  st = paired_stats(p, o);
  if (p.a.size() < 2) return {Verdict::untestable, Direction::none};
  return judge_interval_comparison(
      Interval{st.at("difference_ci").at(0).get<double>(), st.at("difference_ci").at(1).get<double>()}, Claimed::a_less);
}

Json rate_of(const std::vector<Json>& maps, std::size_t count, const std::string& cond, const std::string& arm,
             const std::string& outcome) {
  std::int64_t n = 0, k = 0;
  for (std::size_t i = 0; i < count && i < maps.size(); ++i) {
    ++n;
    k += maps[i].at(cond).at(arm).at("outcome") == outcome ? 1 : 0;
  }
  return Json{{"n", n}, {"count", k}, {"rate", n > 0 ? static_cast<double>(k) / static_cast<double>(n) : 0.0}};
}

/// Outcome counts and mean +- sd of length, time, turns of the reached runs, per condition and
/// arm, over the first `count` maps.
Json arm_summary(const std::vector<Json>& maps, std::size_t count, const std::vector<Arm>& as) {
  Json out = Json::object();
  for (const char* cond : conditions)
    for (const Arm& a : as) {
      if (a.static_only && std::string(cond) != "static") continue;
      Json o = Json::object();
      for (const std::string oc : {"reached", "collided", "stalled", "timed_out", "no_global_path"})
        o[oc] = rate_of(maps, count, cond, a.key, oc);
      std::vector<double> len, tim, tur;
      for (std::size_t i = 0; i < count && i < maps.size(); ++i) {
        const Json& r = maps[i].at(cond).at(a.key);
        if (r.at("outcome") != "reached") continue;
        len.push_back(r.at("length").get<double>());
        tim.push_back(r.at("time").get<double>());
        tur.push_back(static_cast<double>(r.at("turns").get<std::int64_t>()));
      }
      out[cond][a.key] = Json{{"outcomes", o},
                              {"length", summary_stats_json(summarize(len))},
                              {"time", summary_stats_json(summarize(tim))},
                              {"turns", summary_stats_json(summarize(tur))}};
    }
  return out;
}

/// The global planner's per-map quantities, mean +- sd over the first `count` maps.
Json global_summary(const std::vector<Json>& maps, std::size_t count) {
  Json out = Json::object();
  const std::vector<std::pair<std::string, std::string>> fields{
      {"S8", "child_nodes"}, {"S5", "child_nodes"}, {"SK", "child_nodes"}, {"SK", "turns_raw"},
      {"SK", "turns_ordinary"}, {"SK", "turns_key"}, {"SK", "key_length"}, {"SK", "curve_length"},
      {"astar", "length"}};
  for (const auto& [pl, f] : fields) {
    std::vector<double> v;
    for (std::size_t i = 0; i < count && i < maps.size(); ++i) {
      const Json& g = maps[i].at("global").at(pl);
      if (g.contains(f) && g.at(f).is_number()) v.push_back(g.at(f).get<double>());
    }
    out[pl + "." + f] = summary_stats_json(summarize(v));
  }
  return out;
}

}  // namespace

double sensors2023_required_number(const Json& object, const std::string& where, const std::string& key) {
  if (!object.is_object() || !object.contains(key))
    throw DomainError("reproduce sensors2023: " + where + "." + key + " is missing");
  const Json& v = object.at(key);
  if (!v.is_number()) throw DomainError("reproduce sensors2023: " + where + "." + key + " is not a number (got " + v.dump() + ")");
  return v.get<double>();
}

Json run_sensors2023(const Sensors2023Config& cfg) {
  require(cfg.maps >= 1 && cfg.maps <= 10000, "reproduce sensors2023: maps in [1, 10000]");
  const auto t_start = std::chrono::steady_clock::now();
  std::mutex say_mutex;
  auto say = [&](const std::string& s) {
    const std::lock_guard<std::mutex> lock(say_mutex);
    if (cfg.progress) cfg.progress(s);
  };
  const std::vector<Arm> as = arms();
  const bool kin = as.size() > 2;
  require(kin, "reproduce sensors2023: the kinematic A* (astar-kinematic) must be registered");
  const std::string paper_arm = "KF";
  const BootstrapOptions boot{cfg.seed, 2000, 0.95};
  Json doc;
  doc["paper"] = "sensors2023";
  doc["provenance"] = provenance_json(cfg.provenance);
  // scene
  const grid::Grid scene = grid::Grid::from_rows_top_first(sensors2023_scene_rows());
  std::int64_t blocked = 0;
  for (std::int64_t i = 0; i < scene.cell_count(); ++i) blocked += scene.blocked(scene.cell(i)) ? 1 : 0;
  const double density = static_cast<double>(blocked) / static_cast<double>(scene.cell_count());
  Json arms_j = Json::array();
  for (const Arm& a : as) {
    const planners::Planner* pl = planners::find_planner(a.planner);
    const FusedScenario sc = base_scenario(scene, scene_start, scene_goal, a);
    Json dwa_params = dwa::params_json(sc);
    dwa_params.erase("path");
    arms_j.push_back(Json{{"key", a.key}, {"label", a.label}, {"planner", a.planner},
                          {"planner_parameters", pl != nullptr ? pl->defaults : Json(nullptr)},
                          {"global_path", a.planner == "astar-kinematic" && !a.raw_path
                                              ? "the planner's key nodes (secondary redundancy removal)"
                                              : "the planner's path (key nodes = its turning cells)"},
                          {"heading_target", std::string(dwa::to_string(a.target))},
                          {"simulation_parameters", dwa_params}});
  }
  doc["arms"] = arms_j;
  doc["kinematic_astar_available"] = kin;
  doc["parameters"] = arms_j.at(3).at("simulation_parameters");
  Json sc_j{{"rows", sensors2023_scene_rows()}, {"blocked", blocked}, {"density", density}};
  Json scene_runs = Json::object();
  for (const Arm& a : as)
    for (const auto& [name, sc] : scene_scenarios(scene, a)) {
      const Timed t = run_timed(sc);
      scene_runs[name][a.key] = run_json(sc, t.r, t.wall_s);
      if (a.key == as[0].key) sc_j["scenarios"][name] = scenario_summary(sc);
      say(fmt::format("scene {} {}: {} in {:.1f} s, {:.2f} m, {} turns", name, a.key, dwa::to_string(t.r.outcome),
                      t.r.time, t.r.length, t.r.turns));
    }
  sc_j["runs"] = scene_runs;
  sc_j["global"] = Json{{"children_test", global_json(scene, children_start, scene_goal)},
                        {"redundancy_test", global_json(scene, scene_start, scene_goal)}};
  // the scene's mixed run of the paper's fusion (KF) under each named alternative reading
  Json readings = Json::array();
  const std::vector<std::pair<std::string, std::string>> alts{
      {"alpha", "0.05"},          {"evaluation", "cost"},        {"obstacle_prediction", "static"},
      {"clearance_at", "end"},    {"heading_wrap", "off"},       {"window_upper", "exclude"},
      {"admissible", "linear"},   {"admissible", "off"},         {"motion_order", "heading-first"}};
  for (const auto& [key, value] : alts) {
    FusedScenario sc = scene_scenarios(scene, as[3])[2].second;
    Json block = Json::object();
    if (key == "alpha") block[key] = 0.05;
    else block[key] = value;
    sc.dwa = dwa::dwa_params_from_json(block, sc.dwa);
    const Timed t = run_timed(sc);
    Json rj = run_json(sc, t.r, t.wall_s);
    rj["reading"] = key + " = " + value;
    readings.push_back(rj);
    say(fmt::format("scene mixed KF, {} = {}: {}", key, value, dwa::to_string(t.r.outcome)));
  }
  sc_j["readings"] = readings;
  doc["scene"] = sc_j;

  // random maps: 2M of them, generated in seed order, then run on the --jobs threads
  const std::int64_t n_maps = cfg.quick ? std::min<std::int64_t>(cfg.maps, 4) : cfg.maps;
  const auto total = static_cast<std::size_t>(2 * n_maps);
  Json rnd = Json::object();
  rnd["edge"] = 21;
  rnd["density"] = density;
  rnd["start"] = Json::array({scene_start.x, scene_start.y});
  rnd["goal"] = Json::array({scene_goal.x, scene_goal.y});
  rnd["n"] = n_maps;
  rnd["2n"] = total;
  std::vector<grid::Grid> grids;
  std::vector<std::vector<grid::Cell>> astar_paths;
  Json seeds = Json::array();
  std::int64_t rejected = 0;
  std::uint32_t seed = cfg.seed;
  for (std::size_t m = 0; m < total; ++m) {
    for (int tries = 0;; ++tries) {
      require(tries < 1000, "reproduce sensors2023: no connected random map in 1000 seeds");
      grid::Grid g = sensors2023_random_map(seed, 21, density, scene_start, scene_goal);
      const planners::Result r = plan("astar", g, scene_start, scene_goal);
      ++seed;
      if (r.found) {
        grids.push_back(std::move(g));
        astar_paths.push_back(r.path);
        break;
      }
      ++rejected;
    }
    seeds.push_back(seed - 1);
  }
  std::vector<Json> maps(total);
  parallel_for(total, [&](std::size_t m) {
    const grid::Grid& g = grids[m];
    Json rec = Json::object();
    rec["seed"] = seeds.at(m);
    rec["global"] = global_json(g, scene_start, scene_goal);
    for (const char* cond : conditions) {
      Json row = Json::object();
      for (const Arm& a : as) {
        if (a.static_only && std::string(cond) != "static") continue;
        FusedScenario sc = base_scenario(g, scene_start, scene_goal, a);
        if (std::string(cond) != "static") add_random_dynamics(sc, astar_paths[m], std::string(cond) == "mixed");
        const Timed t = run_timed(sc);
        row[a.key] = run_json(sc, t.r, t.wall_s);
      }
      rec[cond] = row;
    }
    std::string line = fmt::format("random map {}/{} (seed {}):", m + 1, total, seeds.at(m).get<std::uint32_t>());
    for (const char* cond : conditions)
      for (const auto& [k, r] : rec[cond].items()) line += fmt::format(" {} {} {};", cond, k, r["outcome"].get<std::string>());
    say(line);
    maps[m] = std::move(rec);
  });
  rnd["seeds"] = seeds;
  rnd["rejected_unconnected"] = rejected;
  rnd["maps"] = maps;
  const auto n = static_cast<std::size_t>(n_maps);
  rnd["summary"] = Json{{"n", arm_summary(maps, n, as)}, {"2n", arm_summary(maps, total, as)}};
  rnd["global_summary"] = Json{{"n", global_summary(maps, n)}, {"2n", global_summary(maps, total)}};
  // the paired comparisons (ablations and Table 2) of every condition
  const std::vector<std::pair<std::string, std::string>> comparisons{{"T", "F"},  {"T", "K"},   {"K", "KF"},
                                                                     {"F", "KF"}, {"T", "KF"},  {"F", "KFt"},
                                                                     {"KFt", "KF"}};
  // the baselines under the alternative reading traditional_dwa = final_goal (static maps only)
  const std::vector<std::pair<std::string, std::string>> static_comparisons{{"Tg", "T"}, {"Kg", "K"}, {"Tg", "F"},
                                                                            {"Tg", "KF"}, {"Kg", "KF"}};
  Json paired_j = Json::object();
  for (const auto& [from, to] : static_comparisons)
    for (const std::string metric : {"length", "time", "turns", "deviation", "sd_v", "sd_w"}) {
      const PairGetter get = arm_pair("static", from, to, metric);
      paired_j["static"][to + "_vs_" + from][metric] =
          Json{{"n", paired_stats(collect(maps, n, get), boot)}, {"2n", paired_stats(collect(maps, total, get), boot)}};
    }
  for (const char* cond : conditions)
    for (const auto& [from, to] : comparisons)
      for (const std::string metric : {"length", "time", "turns", "deviation", "sd_v", "sd_w"}) {
        const PairGetter get = arm_pair(cond, from, to, metric);
        paired_j[cond][to + "_vs_" + from][metric] =
            Json{{"n", paired_stats(collect(maps, n, get), boot)}, {"2n", paired_stats(collect(maps, total, get), boot)}};
      }
  rnd["paired"] = paired_j;
  doc["random"] = rnd;

  // ---- claims (spec sensors2023-dwa.md "Reproduction": fixed before the first run)
  Json claims = Json::array();
  const std::string dwa_reading =
      "reading of \"traditional DWA\" = traditional_dwa=waypoint, the heading aims at the current waypoint of the global path "
      "(sensors2023-dwa Reproduction; alternative traditional_dwa=final_goal, heading at the final goal: arms Tg and Kg, its "
      "verdict in the note)";
  // the verdict of a claim under the alternative reading, for its note
  const auto alt_note = [](const std::string& ours, Verdict v, Direction d) {
    return "under the alternative traditional_dwa=final_goal: " + ours + ", " + verdict_text(v, d);
  };
  const std::string kf_reading =
      "reading: arms K and KF follow the kinematic A*'s key nodes after secondary redundancy removal (alternative: the turning "
      "cells of its raw A* path)";
  auto pair_claim = [&](const std::string& id, const std::string& text, const std::string& source, double paper,
                        const PairGetter& get, std::vector<std::string> deps, const std::string& note,
                        const PairGetter& alt = nullptr) {
    Claim c;
    c.id = id;
    c.text = text;
    c.source = source;
    c.note = note;
    c.depends_on = std::move(deps);
    Claim judged = paired_reduction_claim(c, collect(maps, n, get), collect(maps, total, get), paper, boot);
    if (alt) {
      const Claim a = paired_reduction_claim(c, collect(maps, n, alt), collect(maps, total, alt), paper, boot);
      judged.note += (judged.note.empty() ? "" : "; ") + alt_note(a.ours, a.verdict, a.direction);
    }
    claims.push_back(claim_json(judged));
  };
  auto scene_claim = [&](const std::string& id, const std::string& text, const std::string& source, double paper, double from,
                         double to, std::vector<std::string> deps, const std::string& note) {
    Claim c;
    c.id = id;
    c.text = text;
    c.source = source;
    c.note = note;
    c.depends_on = std::move(deps);
    claims.push_back(claim_json(exact_reduction_claim(c, from, to, paper)));
  };
  const Json& gs = sc_j["global"];
  // a missing or non-numeric scene value is an error, never a silent 0 (rule 8)
  const auto num = [](const Json& j, const char* k) { return sensors2023_required_number(j, "scene.global result", k); };
  // global planner: child nodes (Fig. 6)
  pair_claim("s23.children", "5-direction search: 7.6 % fewer child nodes than 8-direction search", "§4, Fig. 6", 7.6,
             global_pair("S8", "child_nodes", "S5", "child_nodes"),
             {"reading of \"5-direction search\" = node optimisation alone, S5 = directions=5 weight=none vs S8 = directions=8 "
              "weight=none (alternative: the whole improved search SK, claim s23.children.full)"},
             "random maps, (4, 3) -> (17, 16); child nodes = spec/search.md \"child counts\"");
  scene_claim("s23.children.scene", "the 5-direction test (6, 7) -> (17, 16): 7.6 % fewer child nodes", "§4, Fig. 6", 7.6,
              num(gs.at("children_test").at("S8"), "child_nodes"), num(gs.at("children_test").at("S5"), "child_nodes"),
              {"the rebuilt scene, not the paper's lost map"}, "one deterministic run on the rebuilt scene");
  pair_claim("s23.children.full", "the improved search (5 directions + weighted h, SK): 7.6 % fewer child nodes than S8",
             "§4, Fig. 6 (alternative reading)", 7.6, global_pair("S8", "child_nodes", "SK", "child_nodes"),
             {"alternative reading of s23.children (SK = the defaults directions=5 weight=linear)"}, "random maps");
  // global planner: redundancy removal (Fig. 7)
  pair_claim("s23.redundancy", "secondary redundancy removal: 66.7 % fewer turns", "§4, Fig. 7", 66.7,
             global_pair("SK", "turns_raw", "SK", "turns_key"),
             {"reading of \"not removed\" = the raw A* path of SK (alternative: after the ordinary first pass, claim "
              "s23.redundancy.secondary_only)"},
             "random maps, (4, 3) -> (17, 16); turns = metrics.turns");
  scene_claim("s23.redundancy.scene", "the redundancy test (4, 3) -> (17, 16): 66.7 % fewer turns", "§4, Fig. 7", 66.7,
              num(gs.at("redundancy_test").at("SK"), "turns_raw"), num(gs.at("redundancy_test").at("SK"), "turns_key"),
              {"the rebuilt scene, not the paper's lost map"}, "one deterministic run on the rebuilt scene");
  pair_claim("s23.redundancy.secondary_only", "the secondary pass alone: 66.7 % fewer turns than the ordinary first pass",
             "§4, Fig. 7 (alternative reading)", 66.7, global_pair("SK", "turns_ordinary", "SK", "turns_key"),
             {"alternative reading of s23.redundancy"}, "random maps");
  pair_claim("s23.global.length", "improved A*: global path length reduced by 3.571 %", "§4 (text after Table 2)", 3.571,
             global_pair("astar", "length", "SK", "key_length"),
             {"reading of \"global path\" = the key-node polyline of SK against astar's grid path (alternative: the B-spline "
              "curve, claim s23.global.length.curve)"},
             "random maps");
  pair_claim("s23.global.length.curve", "improved A*: global path (B-spline curve) length reduced by 3.571 %",
             "§4 (alternative reading)", 3.571, global_pair("astar", "length", "SK", "curve_length"),
             {"alternative reading of s23.global.length"}, "random maps");
  // Table 2 rows 1-2 (T vs K) and rows 3-4 (T vs KF)
  const std::vector<std::string> t2_deps{dwa_reading, kf_reading};
  std::vector<std::string> rows12_deps = t2_deps;
  rows12_deps.push_back("reading of rows 1-2's \"DWA\" = the traditional DWA, i.e. T vs K (alternative: the following DWA, F vs KF, in the "
                        "paired table)");
  pair_claim("s23.t2.rows12.length", "improved A* + DWA vs traditional A* + DWA: 10.5 % shorter (35.39 -> 31.68 m)",
             "Table 2 rows 1-2", 10.5, arm_pair("static", "T", "K", "length"), rows12_deps, "random static maps, arms T and K",
             arm_pair("static", "Tg", "Kg", "length"));
  pair_claim("s23.t2.rows12.turns", "improved A* + DWA: 15.4 % fewer turns (13 -> 11)", "Table 2 rows 1-2", 15.4,
             arm_pair("static", "T", "K", "turns"), rows12_deps, "turns of the driven track (sensors2023.sim.turns)",
             arm_pair("static", "Tg", "Kg", "turns"));
  pair_claim("s23.t2.rows12.time", "improved A* + DWA: 4.0 % less time (125 -> 120 s)", "Table 2 rows 1-2", 4.0,
             arm_pair("static", "T", "K", "time"), rows12_deps, "ratios, not seconds: the parameters are pathref's",
             arm_pair("static", "Tg", "Kg", "time"));
  pair_claim("s23.t2.length", "fusion vs traditional A* + traditional DWA: 3.6 % shorter path", "Table 2 rows 3-4, abstract", 3.6,
             arm_pair("static", "T", "KF", "length"), t2_deps, "random static maps, arms T and KF",
             arm_pair("static", "Tg", "KF", "length"));
  pair_claim("s23.t2.time", "fusion vs traditional: 6.7 % less time", "Table 2 rows 3-4, abstract", 6.7,
             arm_pair("static", "T", "KF", "time"), t2_deps, "ratios, not seconds: the parameters are pathref's",
             arm_pair("static", "Tg", "KF", "time"));
  pair_claim("s23.t2.turns", "fusion vs traditional: 25 % fewer turns", "Table 2 rows 3-4, abstract", 25.0,
             arm_pair("static", "T", "KF", "turns"), t2_deps, "turns of the driven track (sensors2023.sim.turns)",
             arm_pair("static", "Tg", "KF", "turns"));
  pair_claim("s23.ablation.dwa.time", "improved DWA alone: local path time reduced by 50 %", "§4 (text; matches no row of Table 2)",
             50.0, arm_pair("static", "T", "F", "time"), {dwa_reading},
             "ablation: traditional A* in both arms, heading target the current waypoint (T) vs key node (F)",
             arm_pair("static", "Tg", "F", "time"));
  // closer / fluctuation (T vs F): paired interval of the mean difference
  {
    Claim c;
    c.id = "s23.closer";
    c.text = "the local path is closer to the global path (following DWA)";
    c.source = "abstract, §5";
    c.paper = "F < T";
    c.rule = "paired 95 % bootstrap interval of mean(F) − mean(T) of the mean distance to the global path: below 0 holds, above 0 "
             "does not hold (stats.compare, interval rule)";
    c.depends_on = {dwa_reading};
    c.note = "random static maps where both arms reached the goal";
    Json sn, s2;
    const Judgement jn = smaller_judgement(collect(maps, n, arm_pair("static", "T", "F", "deviation")), boot, sn);
    const Judgement j2 = smaller_judgement(collect(maps, total, arm_pair("static", "T", "F", "deviation")), boot, s2);
    c.verdict = jn.verdict;
    c.direction = jn.direction;
    const auto txt = [](const Json& st) {
      return st.contains("difference_ci") ? fmt::format("{} m (T) → {} m (F), difference [{}, {}], n = {}", fixed(st["b"]["mean"].get<double>(), 3),
                                                        fixed(st["a"]["mean"].get<double>(), 3), fixed(st["difference_ci"][0].get<double>(), 3),
                                                        fixed(st["difference_ci"][1].get<double>(), 3), st["n"].get<std::size_t>())
                                          : std::string("—");
    };
    c.ours = txt(sn);
    if (jn.verdict != Verdict::untestable && j2.verdict != Verdict::untestable) {
      c.verdict_2n = j2.verdict;
      c.direction_2n = j2.direction;
      c.ours_2n = txt(s2);
    }
    c.statistics = Json{{"n", sn}, {"2n", s2}};
    {
      Json sa;
      const Judgement ja = smaller_judgement(collect(maps, n, arm_pair("static", "Tg", "F", "deviation")), boot, sa);
      c.note += "; " + alt_note(txt(sa) + " (Tg → F)", ja.verdict, ja.direction);
    }
    claims.push_back(claim_json(c));
  }
  {
    Claim c;
    c.id = "s23.fluctuation";
    c.text = "improved DWA: smaller linear and angular velocity fluctuation";
    c.source = "Figs. 10-11, §5";
    c.paper = "sd(v), sd(ω): F < T";
    c.rule = "paired 95 % bootstrap intervals of mean(F) − mean(T) of the run's sd of v and of ω: holds iff both below 0, does not "
             "hold iff either above 0, else not significant";
    c.depends_on = {dwa_reading};
    c.note = "random static maps where both arms reached the goal";
    const auto judge = [&](std::size_t count, Json& st, std::string& ours, const std::string& base = "T") {
      Json sv, sw;
      const Judgement jv = smaller_judgement(collect(maps, count, arm_pair("static", base, "F", "sd_v")), boot, sv);
      const Judgement jw = smaller_judgement(collect(maps, count, arm_pair("static", base, "F", "sd_w")), boot, sw);
      st = Json{{"sd_v", sv}, {"sd_w", sw}};
      if (jv.verdict == Verdict::untestable) {
        ours = "—";
        return Judgement{Verdict::untestable, Direction::none};
      }
      ours = fmt::format("sd v {} → {} ({}), sd ω {} → {} ({}) (T → F, n = {})", fixed(sv["b"]["mean"].get<double>(), 3),
                         fixed(sv["a"]["mean"].get<double>(), 3), direction_words(sv), fixed(sw["b"]["mean"].get<double>(), 3),
                         fixed(sw["a"]["mean"].get<double>(), 3), direction_words(sw), sv["n"].get<std::size_t>());
      if (base != "T") ours += " (baseline " + base + ")";
      if (jv.verdict == Verdict::holds && jw.verdict == Verdict::holds) return Judgement{Verdict::holds, Direction::as_claimed};
      if (jv.verdict == Verdict::fails || jw.verdict == Verdict::fails) return Judgement{Verdict::fails, Direction::opposite};
      // direction of the pair: as claimed when neither leans opposite, opposite when neither leans
      // as claimed, otherwise mixed (Direction::none, said in the note)
      const auto leans = [](Direction d) { return d == Direction::as_claimed ? 1 : d == Direction::opposite ? -1 : 0; };
      const int lv = leans(jv.direction), lw = leans(jw.direction);
      if (lv >= 0 && lw >= 0 && lv + lw > 0) return Judgement{Verdict::not_significant, Direction::as_claimed};
      if (lv <= 0 && lw <= 0 && lv + lw < 0) return Judgement{Verdict::not_significant, Direction::opposite};
      if (lv * lw < 0) ours += " — v and ω lean in opposite directions (\"no difference\" = mixed)";
      return Judgement{Verdict::not_significant, Direction::none};
    };
    Json sn, s2;
    const Judgement jn = judge(n, sn, c.ours);
    std::string o2;
    const Judgement j2 = judge(total, s2, o2);
    c.verdict = jn.verdict;
    c.direction = jn.direction;
    if (jn.verdict != Verdict::untestable && j2.verdict != Verdict::untestable) {
      c.verdict_2n = j2.verdict;
      c.direction_2n = j2.direction;
      c.ours_2n = o2;
    }
    c.statistics = Json{{"n", sn}, {"2n", s2}};
    {
      Json sa;
      std::string oa;
      const Judgement ja = judge(n, sa, oa, "Tg");
      c.note += "; " + alt_note(oa, ja.verdict, ja.direction);
    }
    claims.push_back(claim_json(c));
  }
  // Table 3 / Table 4 (the fusion arm), at n and at 2n maps
  const Json& sum = rnd["summary"];
  auto rule_claim = [&](const std::string& id, const std::string& text, const std::string& source, const std::string& paper,
                        const std::string& rule, const std::function<std::pair<Verdict, std::string>(std::size_t, const Json&)>& f,
                        std::vector<std::string> deps, const std::string& note) {
    Claim c;
    c.id = id;
    c.text = text;
    c.source = source;
    c.paper = paper;
    c.rule = rule;
    c.note = note;
    c.depends_on = std::move(deps);
    const auto [vn, on] = f(n, sum["n"]);
    const auto [v2, o2] = f(total, sum["2n"]);
    c.verdict = vn;
    c.ours = on;
    c.direction = vn == Verdict::holds ? Direction::none : vn == Verdict::fails ? Direction::pathref_worse : Direction::none;
    if (vn != Verdict::untestable && v2 != Verdict::untestable) {
      c.verdict_2n = v2;
      c.direction_2n = v2 == Verdict::fails ? Direction::pathref_worse : Direction::none;
      c.ours_2n = o2;
    }
    claims.push_back(claim_json(c));
  };
  for (const std::string cond : {"dynamic", "mixed"}) {
    const std::string scene_out = scene_runs[cond][paper_arm]["outcome"].get<std::string>();
    rule_claim("s23.t3." + cond,
               "the fusion reaches the goal among " + std::string(cond == "dynamic" ? "a moving obstacle" : "moving and temporary obstacles"),
               cond == "dynamic" ? "Table 3 row 1, Fig. 9" : "Table 3 row 2, Fig. 13",
               cond == "dynamic" ? "19.93 m, 3 turns, 59.6 s" : "20.2 m, 4 turns, 60.2 s",
               "the scene run reaches the goal and >= 90 % of the random runs do, with no collision",
               [&, cond](std::size_t, const Json& s) {
                 const Json& o = s[cond][paper_arm]["outcomes"];
                 const double reached = o["reached"]["rate"].get<double>();
                 const std::int64_t coll = o["collided"]["count"].get<std::int64_t>();
                 return std::pair{scene_out == "reached" && reached >= 0.9 && coll == 0 ? Verdict::holds : Verdict::fails,
                                  fmt::format("scene: {}; random maps: {:.0f} % of {} reached, {} collisions (arm {})", scene_out, 100.0 * reached,
                                              o["reached"]["n"].get<std::int64_t>(), coll, paper_arm)};
               },
               {kf_reading}, "");
  }
  rule_claim("s23.t4.dynamic", "hybrid: dynamic obstacle avoidance (T)", "Table 4", "T", "no run of the fusion collides",
             [&](std::size_t, const Json& s) {
               std::int64_t coll = 0, nn = 0;
               for (const std::string cond : {"dynamic", "mixed"}) {
                 coll += s[cond][paper_arm]["outcomes"]["collided"]["count"].get<std::int64_t>();
                 nn += s[cond][paper_arm]["outcomes"]["collided"]["n"].get<std::int64_t>();
               }
               return std::pair{coll == 0 ? Verdict::holds : Verdict::fails, fmt::format("{} collisions in {} runs with obstacles", coll, nn)};
             },
             {}, "property over the random dynamic and mixed runs");
  rule_claim("s23.t4.deceleration", "hybrid: deceleration obstacle avoidance (T)", "Table 4", "T",
             "the mean commanded speed near obstacles (clearance < 0.25 m) is below the one in the open (Eq. 12 at work)",
             [&](std::size_t count, const Json&) {
               double near = 0.0, far = 0.0;
               std::int64_t nn = 0, nf = 0;
               for (std::size_t i = 0; i < count; ++i) {
                 const Json& r = maps[i]["static"][paper_arm];
                 if (!r["v_near"].is_null()) {
                   near = near + r["v_near"].get<double>();
                   ++nn;
                 }
                 if (!r["v_far"].is_null()) {
                   far = far + r["v_far"].get<double>();
                   ++nf;
                 }
               }
               if (nn == 0 || nf == 0) return std::pair{Verdict::untestable, std::string("—")};
               const double a = near / static_cast<double>(nn), b = far / static_cast<double>(nf);
               return std::pair{a < b ? Verdict::holds : Verdict::fails,
                                fmt::format("mean v {:.3f} m/s near obstacles vs {:.3f} m/s in the open", a, b)};
             },
             {}, "random static maps");
  rule_claim("s23.t4.local", "hybrid: local optimality (T) — the DWA no longer falls into local minima", "Table 4, §3.3", "T",
             "the fusion reaches the goal on >= 95 % of the random static maps and at least as often as arm T",
             [&](std::size_t, const Json& s) {
               const double rf = s["static"][paper_arm]["outcomes"]["reached"]["rate"].get<double>();
               const double rt = s["static"]["T"]["outcomes"]["reached"]["rate"].get<double>();
               const double rg = s["static"]["Tg"]["outcomes"]["reached"]["rate"].get<double>();
               const auto verdict = [&](double base) { return rf >= 0.95 && rf >= base ? Verdict::holds : Verdict::fails; };
               return std::pair{verdict(rt),
                                fmt::format("reached {:.0f} % (arm {}) vs {:.0f} % (arm T); under the alternative "
                                            "traditional_dwa=final_goal: vs {:.0f} % (arm Tg), {}",
                                            100.0 * rf, paper_arm, 100.0 * rt, 100.0 * rg,
                                            verdict(rg) == Verdict::holds ? "holds" : "does not hold")};
             },
             {dwa_reading}, "random static maps");
  rule_claim("s23.t4.smooth", "hybrid: smooth path (T)", "Table 4", "T", "the driven track has fewer turns than the global grid path on average",
             [&](std::size_t count, const Json&) {
               double tr = 0.0, gt = 0.0;
               std::int64_t k = 0;
               for (std::size_t i = 0; i < count; ++i) {
                 const Json& r = maps[i]["static"][paper_arm];
                 if (r["outcome"] != "reached") continue;
                 tr = tr + static_cast<double>(r["turns"].get<std::int64_t>());
                 gt = gt + static_cast<double>(maps[i]["global"]["SK"].value("turns_raw", std::int64_t{0}));
                 ++k;
               }
               if (k == 0) return std::pair{Verdict::untestable, std::string("—")};
               return std::pair{tr < gt ? Verdict::holds : Verdict::fails,
                                fmt::format("mean turns {:.2f} of the driven track vs {:.2f} of the kinematic A*'s grid path (n = {})",
                                            tr / static_cast<double>(k), gt / static_cast<double>(k), k)};
             },
             {}, "turns of the track by sensors2023.sim.turns");
  attach_rules_all(claims, sensors2023_claim_rules);
  doc["claims"] = claims;
  doc["provenance"]["total_wall_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  return doc;
}

std::vector<std::pair<std::string, std::string>> sensors2023_figures(const Json& doc) {
  (void)doc;
  std::vector<std::pair<std::string, std::string>> out;
  const grid::Grid scene = grid::Grid::from_rows_top_first(sensors2023_scene_rows());
  for (const Arm& a : arms())
    for (const auto& [name, sc] : scene_scenarios(scene, a)) {
      const FusedResult r = dwa::simulate_fused(sc);
      out.emplace_back(fmt::format("scene-{}-{}.svg", name, a.key), io::svg_fused(sc, r));
    }
  // the global planner on the scene: the 5-direction test (S8 and S5 paths) and the redundancy
  // test (SK's raw path, key nodes and B-spline curve)
  {
    const Json p8{{"directions", 8}, {"weight", "none"}, {"redundancy", "none"}};
    const Json p5{{"directions", 5}, {"weight", "none"}, {"redundancy", "none"}};
    const planners::Result r8 = plan("astar-kinematic", scene, children_start, scene_goal, p8);
    const planners::Result r5 = plan("astar-kinematic", scene, children_start, scene_goal, p5);
    std::vector<io::PathLayer> layers;
    layers.push_back(io::PathLayer{fmt::format("8 directions (S8): {} child nodes", r8.extra.value("child_nodes", std::int64_t{0})), r8.path});
    io::PathLayer l5{fmt::format("5 directions (S5): {} child nodes", r5.extra.value("child_nodes", std::int64_t{0})), r5.path};
    l5.dashed = true;
    layers.push_back(std::move(l5));
    out.emplace_back("global-children.svg", io::svg_map(scene, children_start, scene_goal, layers,
                                                        "5-direction test (6, 7) -> (17, 16), rebuilt scene"));
  }
  {
    const planners::Result k = plan("astar-kinematic", scene, scene_start, scene_goal);
    std::vector<io::PathLayer> layers;
    layers.push_back(io::PathLayer{fmt::format("A* path of SK ({} turns)", k.extra.value("turns_raw", std::int64_t{0})), k.path});
    if (k.found) {
      io::PathLayer keys{fmt::format("key nodes after secondary removal ({} turns)", k.extra.value("turns_key", std::int64_t{0})), {}};
      for (const Json& c : k.extra.at("key_nodes")) keys.path.push_back(grid::Cell{c.at(0).get<std::int64_t>(), c.at(1).get<std::int64_t>()});
      keys.markers = true;
      keys.dashed = true;
      layers.push_back(std::move(keys));
      if (k.extra.contains("curve")) {
        io::PathLayer curve{"cubic B-spline of the key nodes", {}};
        for (const Json& q : k.extra.at("curve").at("points"))
          curve.points.push_back(geometry::Vec2{q.at(0).get<double>(), q.at(1).get<double>()});
        layers.push_back(std::move(curve));
      }
    }
    out.emplace_back("global-redundancy.svg", io::svg_map(scene, scene_start, scene_goal, layers,
                                                          "redundancy test (4, 3) -> (17, 16), rebuilt scene"));
  }
  return out;
}

std::string sensors2023_markdown(const Json& doc, const std::string& figure_dir, const std::string& json_name) {
  std::string md;
  const Json& rnd = doc.at("random");
  md += "# Reproduction: Sensors 2023, 23(8), 4102 — kinematic A* + following DWA (sensors2023)\n\n";
  md += "Generated by `pathref reproduce sensors2023` from `" + json_name +
        "`; every number below is read from that file. Spec: spec/sensors2023-dwa.md (section Reproduction), "
        "spec/sensors2023.md (the kinematic A*), spec/stats.md (the statistics).\n\n";
  md += "**What this is and is not.** The paper's maps and every DWA parameter are lost (the local text "
        "has no figures' data and no parameter table). The scene below is **rebuilt by pathref** from the "
        "coordinates the text gives (start (4, 3), goal (17, 16), the 5-direction test's start (6, 7), the moving "
        "obstacle's end (9, 4), the temporary obstacle (14, 15)); it is not the paper's map. The DWA runs with pathref's "
        "project defaults (spec/sensors2023-dwa.md, 'Project defaults', fixed before any experiment), so Table 2's "
        "seconds cannot be compared: the report compares ratios. No verdict rests on the one hand-made map: every "
        "comparison is made on seeded random 21 x 21 maps of the scene's density, " +
        std::to_string(rnd.at("n").get<std::int64_t>()) + " maps (n, the headline verdicts) and " +
        std::to_string(rnd.at("2n").get<std::int64_t>()) + " maps (2n, the check that a verdict does not flip).\n\n";
  md += "## How a claim is judged here\n\n"
        "- **\"X reduces Q by P %\"** (a = the improved arm's value, b = the baseline's, on the same maps; for the DWA arms "
        "only maps where both reached the goal): pathref's value is the reduction of the means 100 (mean b − mean a) / mean b; "
        "its 95 % interval is the **paired** seeded percentile bootstrap over maps (stats.bootstrap_ci, paired, 2000 "
        "resamples, seed = --seed). The claim **holds** iff the interval lies within P ± 5 points (stats.margin, percent), "
        "**does not hold** iff it lies entirely outside (pathref better = a larger reduction), otherwise **inconclusive**. "
        "The direction is tested beside it by the paired interval of mean(a) − mean(b) (\"difference as claimed\" iff it lies "
        "below 0, stats.compare's interval rule).\n"
        "- A reduction on the **one scene** (deterministic planners) is an exact value, judged against the same band.\n"
        "- **\"Smaller / closer\"**: the paired interval of mean(F) − mean(T); below 0 holds, above 0 does not hold.\n"
        "- **Table 3 and Table 4**: the rates and properties stated in each row.\n"
        "- Every verdict is given at n and at 2n maps; changes are listed under the claims. A † marks a verdict that "
        "rests on a chosen reading; the rule column names the alternative.\n\n";
  md += "## Arms and their parameters\n\n| key | arm | global planner | global path handed to the DWA | DWA heading target |\n|---|---|---|---|---|\n";
  for (const Json& a : doc.at("arms"))
    md += md_row({a.at("key").get<std::string>(), a.at("label").get<std::string>(), "`" + a.at("planner").get<std::string>() + "`",
                  a.at("global_path").get<std::string>(), a.at("heading_target").get<std::string>()});
  md += "\nPlanner parameters (the registered defaults; the global-planner claims also run `astar-kinematic` as S8 = "
        "`directions=8 weight=none redundancy=none` and S5 = `directions=5 weight=none redundancy=none`; SK = the defaults):\n\n";
  for (const Json& a : doc.at("arms"))
    if (a.at("key") == "T" || a.at("key") == "K")
      md += "- `" + a.at("planner").get<std::string>() + "`: `" + a.at("planner_parameters").dump() + "`\n";
  md += "\nSimulation and DWA parameters (pathref's project defaults, not the paper's; identical in every arm except "
        "`heading_target`):\n\n```json\n" + doc.at("parameters").dump(1) + "\n```\n";
  md += "\n## Claims\n\n" + md_claims(doc.at("claims")) + "\n" + md_verdict_summary(doc.at("claims")) + "\n";
  md += "Change notes (n → 2n):\n\n";
  bool any = false;
  for (const Json& c : doc.at("claims"))
    if (c.value("changed", false)) {
      md += "- " + c.at("id").get<std::string>() + ": " + c.at("change_note").get<std::string>() + "\n";
      any = true;
    }
  if (!any) md += "- none: every verdict at 2n maps equals the one at n maps.\n";
  // global planner
  const Json& gl = doc.at("scene").at("global");
  md += "\n## The global planner (kinematic A*) on the scene and the random maps\n\n"
        "| test | search | child nodes | generated | expansions | turns raw | turns ordinary | turns key nodes | key-node length | curve length |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& [test, label] : {std::pair{"children_test", "(6, 7) → (17, 16)"}, std::pair{"redundancy_test", "(4, 3) → (17, 16)"}})
    for (const std::string srch : {"S8", "S5", "SK"}) {
      const Json& r = gl.at(test).at(srch);
      md += md_row({label, srch, std::to_string(r.at("child_nodes").get<std::int64_t>()), std::to_string(r.at("generated").get<std::int64_t>()),
                    std::to_string(r.at("expansions").get<std::int64_t>()), md_number(r.value("turns_raw", Json()), 0),
                    md_number(r.value("turns_ordinary", Json()), 0), md_number(r.value("turns_key", Json()), 0),
                    md_number(r.value("key_length", Json()), 3), md_number(r.value("curve_length", Json()), 3)});
    }
  md += "\nRandom maps, mean ± sd (n | 2n maps):\n\n| quantity | n | 2n |\n|---|---|---|\n";
  for (const auto& [k, v] : rnd.at("global_summary").at("n").items()) {
    const Json& w = rnd.at("global_summary").at("2n").at(k);
    md += md_row({"`" + k + "`", md_number(v.at("mean"), 2) + " ± " + md_number(v.at("std"), 2),
                  md_number(w.at("mean"), 2) + " ± " + md_number(w.at("std"), 2)});
  }
  // scene
  md += "\n## The scene (rebuilt, 21 x 21, " + md_number(doc.at("scene").at("density"), 3) + " density)\n\n```\n";
  for (const Json& r : doc.at("scene").at("rows")) md += r.get<std::string>() + "\n";
  md += "```\n\nScripted obstacles (dynamic: the moving disc; mixed: plus the temporary cell):\n\n```json\n" +
        doc.at("scene").at("scenarios").at("mixed").dump() + "\n```\n\n";
  md += "| scene run | arm | outcome | time (s) | length (m) | turns | global-path turns | min clearance (m) | skips |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string cond : {"static", "dynamic", "mixed"})
    for (const Json& a : doc.at("arms")) {
      const std::string k = a.at("key").get<std::string>();
      const Json& r = doc.at("scene").at("runs").at(cond).at(k);
      md += md_row({cond, k, r.at("outcome").get<std::string>(), md_number(r.at("time"), 1), md_number(r.at("length"), 2),
                    std::to_string(r.at("turns").get<std::int64_t>()), std::to_string(r.at("grid_turns").get<std::int64_t>()),
                    md_number(r.at("min_clearance"), 3), std::to_string(r.at("skips").get<std::int64_t>())});
    }
  md += "\nThe scene's mixed run of the fusion (arm KF) under each named alternative reading (everything else at the defaults):\n\n"
        "| reading | outcome | time (s) | length (m) | turns | min clearance (m) |\n|---|---|---|---|---|---|\n";
  for (const Json& r : doc.at("scene").at("readings"))
    md += md_row({"`" + r.at("reading").get<std::string>() + "`", r.at("outcome").get<std::string>(), md_number(r.at("time"), 1),
                  md_number(r.at("length"), 2), std::to_string(r.at("turns").get<std::int64_t>()), md_number(r.at("min_clearance"), 3)});
  md += "\nPaper, Table 2 (21 x 21): traditional A* + DWA 35.39 m, 13 turns, 125 s; improved A* + DWA 31.68 m, 11 turns, 120 s; "
        "traditional A* + traditional DWA 20.72 m, 4 turns, 64.5 s; improved A* + improved DWA 19.98 m, 3 turns, 60.2 s. "
        "Table 3: dynamic obstacle 19.93 m, 3 turns, 59.6 s; mixed 20.2 m, 4 turns, 60.2 s.\n\n";
  md += "Figures: ";
  for (const Json& a : doc.at("arms"))
    for (const std::string cond : {"static", "dynamic", "mixed"}) {
      const std::string f = "scene-" + cond + "-" + a.at("key").get<std::string>() + ".svg";
      md += "[" + f + "](" + figure_dir + "/" + f + ") ";
    }
  md += "\n\n![5-direction test](" + figure_dir + "/global-children.svg) ![redundancy test](" + figure_dir + "/global-redundancy.svg)";
  md += "\n\n![mixed, arm KF (the paper's fusion)](" + figure_dir + "/scene-mixed-KF.svg)\n";
  // random maps
  md += "\n## Random maps\n\n" + std::to_string(rnd.at("seeds").size()) + " maps, 21 x 21, density " + md_number(rnd.at("density"), 3) +
        ", start (4, 3), goal (17, 16), start and goal neighbourhoods free, seeds " + rnd.at("seeds").dump() + " (" +
        std::to_string(rnd.at("rejected_unconnected").get<std::int64_t>()) +
        " seeds skipped: no A* path). Dynamic: one disc (r 0.4 m, 0.5 m/s) crossing the global path half-way, timed to meet the "
        "robot there; mixed: plus a temporary cell on a key node for 0–20 s.\n\n";
  for (const std::string half : {"n", "2n"}) {
    md += "Outcomes and means ± sd of the reached runs, " + half + " = " + std::to_string(rnd.at(half).get<std::int64_t>()) + " maps:\n\n";
    md += "| condition | arm | reached | collided | stalled | timed out | length (m) | time (s) | turns |\n|---|---|---|---|---|---|---|---|---|\n";
    for (const std::string cond : {"static", "dynamic", "mixed"})
      for (const Json& a : doc.at("arms")) {
        const std::string k = a.at("key").get<std::string>();
        if (!rnd.at("summary").at(half).at(cond).contains(k)) continue;  // static-only arms
        const Json& s = rnd.at("summary").at(half).at(cond).at(k);
        auto ms = [&](const char* m, int d) { return md_number(s.at(m).at("mean"), d) + " ± " + md_number(s.at(m).at("std"), d); };
        const Json& o = s.at("outcomes");
        md += md_row({cond, k, std::to_string(o.at("reached").at("count").get<std::int64_t>()),
                      std::to_string(o.at("collided").at("count").get<std::int64_t>()),
                      std::to_string(o.at("stalled").at("count").get<std::int64_t>()),
                      std::to_string(o.at("timed_out").at("count").get<std::int64_t>()), ms("length", 2), ms("time", 1), ms("turns", 2)});
      }
    md += "\n";
  }
  // why runs fail (spec "Reproduction", "Why runs stall"): outcomes of the runs that did not reach
  // the goal, and how many of the stalled ones ended standing still (v = w = 0: a DWA local minimum)
  md += "Runs that did not reach the goal, first n maps (stalled = moved < 0.1 m in 10 s; *standing* = the last commanded "
        "v and ω are the window's zero sample (below half a resolution), the DWA's own choice among valid candidates: a local minimum of Eq. 13, see spec/sensors2023-dwa.md "
        "\"Why runs stall\"):\n\n| condition | arm | not reached | stalled | of which standing | collided | timed out |\n|---|---|---|---|---|---|---|\n";
  for (const std::string cond : {"static", "dynamic", "mixed"})
    for (const Json& a : doc.at("arms")) {
      const std::string k = a.at("key").get<std::string>();
      std::int64_t nr = 0, st = 0, standing = 0, co = 0, to = 0;
      bool ran = false;
      for (std::size_t i = 0; i < static_cast<std::size_t>(rnd.at("n").get<std::int64_t>()); ++i) {
        const Json& m = rnd.at("maps").at(i);
        if (!m.at(cond).contains(k)) continue;
        ran = true;
        const Json& r = m.at(cond).at(k);
        const std::string o = r.at("outcome").get<std::string>();
        if (o == "reached") continue;
        ++nr;
        st += o == "stalled" ? 1 : 0;
        // the window's zero sample: |v| and |w| below half a resolution (w's zero sample carries the
        // rounding of lo + k r, ~1e-14)
        const Json& dp = doc.at("parameters").at("dwa");
        standing += o == "stalled" && std::abs(r.at("end_v").get<double>()) < 0.5 * dp.at("v_res").get<double>() &&
                            std::abs(r.at("end_w").get<double>()) < 0.5 * dp.at("w_res").get<double>()
                        ? 1
                        : 0;
        co += o == "collided" ? 1 : 0;
        to += o == "timed_out" ? 1 : 0;
      }
      if (ran)
        md += md_row({cond, k, std::to_string(nr), std::to_string(st), std::to_string(standing), std::to_string(co), std::to_string(to)});
    }
  md += "\n";
  md += "Paired comparisons (the ablations: each improvement on its own; maps where both arms reached the goal; reduction of "
        "the means of `to` against `from` with its paired 95 % bootstrap interval; direction = the paired interval of the mean "
        "difference; lower / higher = maps where `to` is lower / higher):\n\n";
  md += "| condition | to vs from | metric | n: pairs | n: from → to | n: reduction % [95 % CI] | n: direction | n: lower / higher | 2n: pairs | 2n: reduction % [95 % CI] | 2n: direction |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string cond : {"static", "dynamic", "mixed"})
    for (const auto& [cmp, pj] : rnd.at("paired").at(cond).items())
      for (const auto& [metric, p] : pj.items()) {
        const Json& a = p.at("n");
        const Json& b = p.at("2n");
        auto red = [](const Json& x) {
          if (!x.contains("reduction_percent")) return std::string("—");
          std::string t = md_number(x.at("reduction_percent"), 1);
          if (x.contains("reduction_ci")) t += " [" + md_number(x.at("reduction_ci").at(0), 1) + ", " + md_number(x.at("reduction_ci").at(1), 1) + "]";
          return t;
        };
        auto dir = [](const Json& x) { return direction_words(x); };
        md += md_row({cond, cmp, metric, std::to_string(a.at("n").get<std::int64_t>()),
                      a.contains("b") ? md_number(a.at("b").at("mean"), 3) + " → " + md_number(a.at("a").at("mean"), 3) : "—", red(a), dir(a),
                      a.contains("maps_lower") ? std::to_string(a.at("maps_lower").get<std::int64_t>()) + " / " +
                                                     std::to_string(a.at("maps_higher").get<std::int64_t>())
                                               : "—",
                      std::to_string(b.at("n").get<std::int64_t>()), red(b), dir(b)});
      }
  md += "\n" + md_provenance(doc.at("provenance"), json_name) + "\n";
  return md;
}

}  // namespace pathref::reproduce
