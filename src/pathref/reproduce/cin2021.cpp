#include "pathref/reproduce/cin2021.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>

#include "pathref/core/error.hpp"
#include "pathref/equations/cin2021.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/io/svg.hpp"
#include "pathref/planners/search.hpp"
#include "pathref/reproduce/runs.hpp"
#include "pathref/reproduce/stats.hpp"

namespace pathref::reproduce {

namespace {

constexpr const char* hga = "hga-aco-cin";
constexpr const char* aco = "aco-cin";
constexpr const char* gan = "ga-cin";

Json rects_json(const std::vector<Rect>& r) {
  Json out = Json::array();
  for (const Rect& q : r) out.push_back(Json::array({q.x0, q.y0, q.x1, q.y1}));
  return out;
}

const std::vector<std::pair<std::string, std::vector<Rect>>>& scenario_rects() {
  // spec reproduce.cin2021.maps: the project's layouts (Figure 10 is lost), 20 x 20, rectangles
  static const std::vector<std::pair<std::string, std::vector<Rect>>> v = {
      {"s1", {{3, 3, 6, 8}, {9, 10, 14, 12}, {12, 2, 16, 6}, {4, 13, 7, 17}, {15, 14, 17, 18}}},
      {"s2",
       {{2, 2, 4, 10}, {6, 5, 12, 7}, {14, 0, 15, 9}, {7, 10, 8, 17}, {10, 12, 16, 13}, {17, 9, 18, 16},
        {2, 14, 5, 15}, {11, 16, 12, 19}}},
      {"s3",
       {{3, 9, 9, 9}, {9, 3, 9, 9}, {11, 16, 17, 16}, {17, 10, 17, 16}, {13, 2, 16, 5}, {3, 13, 6, 16},
        {12, 11, 14, 13}}},
  };
  return v;
}

/// Table 3 measurements of one run (taken from its record, however it was executed).
struct Measured {
  RunRecord rec;
  double smoothness = std::numeric_limits<double>::quiet_NaN();  ///< cin2021.eq17 of the path
  std::optional<std::int64_t> optimum_iteration;  ///< iteration of the result (phase-local)
  std::optional<std::int64_t> optimum_iteration_total;  ///< counted from the first GA generation
};

Measured measure(RunRecord rec) {
  Measured m;
  m.rec = std::move(rec);
  if (!m.rec.found) return m;
  m.smoothness = cin::smoothness_cost(m.rec.path);
  const Json& it = at_or_null(m.rec.extra, {"best_iteration"});
  const Json& gen = at_or_null(m.rec.extra, {"best_generation"});
  if (it.is_number_integer()) m.optimum_iteration = it.get<std::int64_t>();
  else if (gen.is_number_integer()) m.optimum_iteration = gen.get<std::int64_t>();
  m.optimum_iteration_total = m.optimum_iteration;
  const Json& ga_phase = at_or_null(m.rec.extra, {"phase_lengths", "ga"});
  if (ga_phase.is_number_integer() && m.optimum_iteration)
    m.optimum_iteration_total = *m.optimum_iteration + ga_phase.get<std::int64_t>();
  return m;
}

/// {"n", "mean", "std", "min", "max", "ci": {"lo", "hi"} | null}: the summary of all runs with a
/// value and the 95 % percentile bootstrap interval of their mean (stats.bootstrap_ci, n >= 2).
Json stat_json(const std::vector<double>& v, const BootstrapOptions& bo) {
  const Summary s = summarize(v);
  const auto opt = [](const std::optional<double>& x) { return x ? Json(*x) : Json(nullptr); };
  Json ci = nullptr;
  if (v.size() >= 2) {
    const Interval i = bootstrap_ci(v, BootStatistic::mean, bo);
    ci = Json{{"lo", i.lo}, {"hi", i.hi}};
  }
  return Json{{"n", s.n}, {"mean", opt(s.mean)}, {"std", opt(s.std)}, {"min", opt(s.min)}, {"max", opt(s.max)},
              {"ci", ci}};
}

/// The values of `key` of the first `count` runs (all runs when count < 0) that have one, in run order.
std::vector<double> column(const Json& runs, const char* key, std::int64_t count = -1) {
  std::vector<double> v;
  std::int64_t k = 0;
  for (const Json& r : runs) {
    if (count >= 0 && k++ >= count) break;
    if (r.contains(key) && r.at(key).is_number()) v.push_back(r.at(key).get<double>());
  }
  return v;
}

}  // namespace

grid::Grid rect_grid(std::int64_t w, std::int64_t h, const std::vector<Rect>& rects) {
  grid::Grid g(w, h);
  for (const Rect& r : rects) {
    require(0 <= r.x0 && r.x0 <= r.x1 && r.x1 < w && 0 <= r.y0 && r.y0 <= r.y1 && r.y1 < h,
            "rectangle outside the grid");
    for (std::int64_t y = r.y0; y <= r.y1; ++y)
      for (std::int64_t x = r.x0; x <= r.x1; ++x) g.set_blocked(grid::Cell{x, y}, true);
  }
  return g;
}

std::vector<CinScenario> cin2021_scenarios() {
  std::vector<CinScenario> out;
  const char* labels[] = {"Scenario 1 (5 rectangles)", "Scenario 2 (8 rectangles, narrow passages)",
                          "Scenario 3 (two concave L-traps facing the start, 3 blocks)"};
  std::size_t i = 0;
  for (const auto& [key, rects] : scenario_rects()) {
    CinScenario sc;
    sc.key = key;
    sc.label = labels[i++];
    sc.source = "pathref layout (spec reproduce.cin2021.maps): 20 x 20, rectangles " + rects_json(rects).dump();
    sc.grid = rect_grid(20, 20, rects);
    sc.start = grid::Cell{0, 0};
    sc.goal = grid::Cell{19, 19};
    out.push_back(std::move(sc));
  }
  return out;
}

const std::vector<std::string>& cin2021_planners() {
  static const std::vector<std::string> v = {hga, aco, gan};
  return v;
}
const std::vector<std::string>& cin2021_shi_planners() {
  static const std::vector<std::string> v = {"iha", "hybrid-ga-aco"};
  return v;
}

namespace {

/// The reconstructed rules (spec/index) a claim "Ck.MAP.RIVAL[@reading|/total]" rests on (attach_rules;
/// reproduce.markdown): HGA-ACO's planner, the rival's when it is cin2021's own GA or ACO (Shi's
/// planners are not reconstructions), and the metric: C1 length (Eq. 19), C4 smoothness (Eq. 17-18).
std::vector<std::string> cin2021_claim_rules(const std::string& id) {
  std::vector<std::string> r{"cin2021.plan.hga-aco"};
  const std::string base = id.substr(0, id.find_first_of("@/"));
  if (base.ends_with(".aco-cin")) r.emplace_back("cin2021.plan.aco");
  if (base.ends_with(".ga-cin")) r.emplace_back("cin2021.plan.ga");
  if (base.rfind("C1.", 0) == 0 || base.rfind("X1.", 0) == 0) r.emplace_back("cin2021.eq19");
  if (base.rfind("C4.", 0) == 0 || base.rfind("X4.", 0) == 0) {
    r.emplace_back("cin2021.eq17");
    r.emplace_back("cin2021.eq18");
  }
  return r;
}

/// "HGA-ACO", "ACO", "GA" for cin2021's planners; planner_label otherwise.
std::string cin_label(const std::string& name) {
  if (name == hga) return "HGA-ACO";
  if (name == aco) return "ACO";
  if (name == gan) return "GA";
  return planner_label(name);
}

/// A reading run beside the defaults (reproduce.cin2021.protocol "Readings").
struct Reading {
  std::string key;
  std::string param;
  std::string value;
  std::string default_text;  ///< the default it replaces, as the report names it
};
const std::vector<Reading>& readings() {
  static const std::vector<Reading> v = {
      {"any_stuck", "dead_angle_record", "any_stuck", "dead_angle_record=cul_de_sac"},
      {"goal_inverse", "eta", "goal_inverse", "eta=inverse_distance (1/d_ij)"},
  };
  return v;
}

/// A quantity of Table 3 a claim compares (reproduce.cin2021.protocol "Claims").
struct Quantity3 {
  const char* key;       ///< the run field
  const char* claim_id;  ///< C1 ... C4
  const char* text;
  const char* source;
  int decimals;
};
const std::vector<Quantity3>& quantities() {
  static const std::vector<Quantity3> v = {
      {"length", "C1", "HGA-ACO has the shortest path length", "§5.6 (Figure 10, Table 3 path length), §6", 3},
      {"wall_ms", "C2", "HGA-ACO has the shortest running time", "§5.6 (Table 3 running time), §6", 1},
      {"optimum_iteration", "C3", "HGA-ACO needs the fewest iterations to its optimum",
       "§5.6 (Table 3 optimal iteration, Figure 11), §6", 1},
      {"smoothness", "C4", "HGA-ACO's path is the smoothest", "§5.6 (Figure 10)", 3},
  };
  return v;
}

/// What every claim of one report needs: the protocol's n and the bootstrap settings.
struct Judging {
  std::int64_t n = 20;
  BootstrapOptions bo;
};

/// "HGA-ACO (a) < other (b)" on the runs' `a_key` / `b_key`: comparison_claim (Mann-Whitney U
/// decides, at n and 2n) and, beside it, the 95 % bootstrap interval of the mean difference a - b
/// (stats.bootstrap_ci, statistic mean_difference) at n and 2n. Spec: reproduce.cin2021.protocol.
Claim hga_less_claim(const std::string& id, const std::string& text, const std::string& source, const Json& a_series,
                     const char* a_key, const std::string& a_name, const Json& b_series, const char* b_key,
                     const std::string& b_name, int decimals, const Judging& jd) {
  Claim c;
  c.id = id;
  c.text = text;
  c.source = source;
  c.paper = "HGA-ACO < " + cin_label(b_name.substr(0, b_name.find('@'))) + " (Table 3's numbers are lost)";
  const Json& ra = at_or_null(a_series, {"runs"});
  const Json& rb = at_or_null(b_series, {"runs"});
  if (!a_series.value("available", false) || !b_series.value("available", false)) {
    c.verdict = Verdict::untestable;
    c.ours = "—";
    c.note = "planner '" + (a_series.value("available", false) ? b_name : a_name) + "' is not available in this build";
    return c;
  }
  const auto a_n = column(ra, a_key, jd.n), b_n = column(rb, b_key, jd.n);
  const auto a_2 = column(ra, a_key), b_2 = column(rb, b_key);
  if (a_n.empty() || b_n.empty()) {
    c.verdict = Verdict::untestable;
    c.ours = "—";
    c.note = "no run of '" + (a_n.empty() ? a_name : b_name) + "' has a value of " + a_key;
    return c;
  }
  const bool more = a_2.size() > a_n.size() || b_2.size() > b_n.size();
  comparison_claim(c, a_n, b_n, more ? std::span<const double>(a_2) : std::span<const double>(),
                   more ? std::span<const double>(b_2) : std::span<const double>(), Claimed::a_less, decimals);
  c.rule = "two-sided Mann–Whitney U test, α = 0.05, direction from U (stats.compare); 95 % bootstrap CI of the "
           "mean difference HGA − other beside it (reproduce.cin2021.protocol)";
  const auto add_ci = [&](std::span<const double> a, std::span<const double> b, std::string& ours, const char* at,
                          Verdict v) {
    if (a.size() < 2 || b.size() < 2) return;
    const Interval ci = bootstrap_two_sample_ci(a, b, BootStatistic::mean_difference, jd.bo);
    const double d = mean(a) - mean(b);
    ours += fmt::format("; difference {} [{}, {}]", fixed(d, decimals), fixed(ci.lo, decimals), fixed(ci.hi, decimals));
    c.statistics[at]["mean_difference"] = d;
    c.statistics[at]["mean_difference_ci"] = interval_json(ci);
    c.statistics[at]["bootstrap"] = Json{{"resamples", jd.bo.resamples}, {"level", jd.bo.level}, {"seed", jd.bo.seed}};
    // the rank test decides; say so where the interval of the means tells another story
    const bool ci_below = ci.hi < 0.0, ci_above = ci.lo > 0.0;
    std::string clash;
    if (v == Verdict::holds && !ci_below) clash = "the rank test is significant as claimed but the CI of the mean difference is not below 0";
    if (v == Verdict::fails && !ci_above) clash = "the rank test is significant against the claim but the CI of the mean difference is not above 0";
    if (v == Verdict::not_significant && (ci_below || ci_above))
      clash = std::string("the rank test is not significant but the CI of the mean difference lies ") +
              (ci_below ? "below" : "above") + " 0 (skewed runs)";
    if (!clash.empty()) c.note += (c.note.empty() ? "" : "; ") + std::string("at ") + at + ": " + clash;
  };
  // an iteration count of 1 means the colony never improved on its first iteration (stagnation)
  if (std::string(a_key).rfind("optimum_iteration", 0) == 0)
    for (const auto& [vals, name] : {std::pair{&a_n, a_name}, std::pair{&b_n, b_name}}) {
      if (name.rfind(gan, 0) == 0) continue;  // the GA's count is a generation
      std::size_t first = 0;
      for (const double x : *vals) first += x <= 1.0 ? 1 : 0;
      if (2 * first >= vals->size())
        c.note += (c.note.empty() ? "" : "; ") +
                  fmt::format("stagnation: {} of {}'s {} runs found their best path in iteration 1, so the count "
                              "measures stagnation, not speed", first, name, vals->size());
    }
  add_ci(a_n, b_n, c.ours, "n", c.verdict);
  if (more && c.verdict_2n) add_ci(a_2, b_2, c.ours_2n, "2n", *c.verdict_2n);
  return c;
}

}  // namespace

Json run_cin2021(const CinConfig& cfg) {
  if (cfg.runs < 2 || cfg.runs > 10000) throw UsageError("--runs must lie in [2, 10000]");
  const auto t_start = std::chrono::steady_clock::now();
  const std::int64_t runs2 = 2 * cfg.runs;  // reproduce.judge: verdicts at n and at 2n
  require(static_cast<std::uint64_t>(cfg.seed) + static_cast<std::uint64_t>(runs2) - 1 <= 4294967295ULL,
          "run_cin2021: seed + 2 runs - 1 must not exceed 4294967295");
  const Judging jd{cfg.runs, BootstrapOptions{cfg.seed, 2000, 0.95}};
  std::vector<CinScenario> maps = cin2021_scenarios();
  std::vector<std::string> shi_keys;
  for (const auto* pm : {&cfg.map_c, &cfg.map_b}) {
    if (!*pm) continue;
    CinScenario sc;
    const bool is_b = pm == &cfg.map_b;
    sc.key = is_b ? "shiB" : "shiC";
    sc.label = is_b ? "Shi map B (complex, mapB_20x20_ga.txt)" : "Shi map C (simple, mapC_20x20_winsleo_traditional.txt)";
    sc.source = (*pm)->file + " (paper orientation, spec reproduce.shi2022.maps)";
    sc.grid = oriented((*pm)->grid, Orientation::paper);
    const auto [s, g] = shi2022_endpoints(sc.grid, Orientation::paper);
    sc.start = s;
    sc.goal = g;
    shi_keys.push_back(sc.key);
    maps.push_back(std::move(sc));
  }
  Json doc;
  doc["paper"] = "cin2021";
  doc["provenance"] = provenance_json(cfg.provenance);
  Json maps_json = Json::array();
  Json results = Json::object();
  std::vector<Claim> claims, reading_claims, cross;
  for (const CinScenario& sc : maps) {
    require(sc.grid.in_bounds(sc.start) && sc.grid.free(sc.start) && sc.grid.in_bounds(sc.goal) &&
                sc.grid.free(sc.goal),
            "blocked start or goal on " + sc.key);
    const search::Outcome opt = search::dijkstra(sc.grid, sc.start, sc.goal, cfg.policy);
    if (!opt.found) throw UsageError("goal unreachable on " + sc.key);
    Json mj{{"key", sc.key}, {"label", sc.label}, {"source", sc.source},
            {"width", sc.grid.width()}, {"height", sc.grid.height()},
            {"start", Json::array({sc.start.x, sc.start.y})}, {"goal", Json::array({sc.goal.x, sc.goal.y})},
            {"optimum", metrics::path_length(opt.path)}};
    Json rows = Json::array();
    for (std::int64_t y = sc.grid.height() - 1; y >= 0; --y) {
      std::string row;
      for (std::int64_t x = 0; x < sc.grid.width(); ++x) row += sc.grid.free(grid::Cell{x, y}) ? '.' : '#';
      rows.push_back(row);
    }
    mj["grid"] = rows;
    maps_json.push_back(mj);
    std::vector<std::string> planners = cin2021_planners();
    const bool shi_map = std::find(shi_keys.begin(), shi_keys.end(), sc.key) != shi_keys.end();
    if (shi_map)
      for (const auto& s : cin2021_shi_planners()) planners.push_back(s);
    // the colony readings beside the defaults, on every map (results under "PLANNER@KEY")
    std::vector<std::pair<std::string, Json>> runs_of;  // (result key, parameter overrides)
    for (const std::string& name : planners) runs_of.emplace_back(name, Json::object());
    for (const Reading& rd : readings())
      for (const char* name : {hga, aco})
        runs_of.emplace_back(std::string(name) + "@" + rd.key,
                             Json{{(std::string(name) == hga ? "aco_" : "") + rd.param, rd.value}});
    Json per_map = Json::object();
    for (const auto& [result_key, reading_params] : runs_of) {
      const std::string name = result_key.substr(0, result_key.find('@'));
      const planners::Planner* p = available(name);
      if (p == nullptr) {
        per_map[result_key] = Json{{"available", false}, {"reason", "planner '" + name + "' is not available in this build"}};
        continue;
      }
      Json params = cfg.quick ? quick_overrides(p->defaults) : Json::object();
      for (const auto& [k, v] : reading_params.items()) params[k] = v;
      std::vector<RunRecord> recs = run_records(*p, name, params, sc.grid, sc.start, sc.goal, cfg.policy, cfg.seed,
                                                runs2, "cin2021 " + sc.key);
      Json runs = Json::array();
      Json curves = Json::array();
      Json first_path = Json::array();
      Json params_used = recs.front().params_used;
      for (std::size_t r = 0; r < recs.size(); ++r) {
        const Measured m = measure(std::move(recs[r]));
        Json rj{{"seed", m.rec.seed}, {"found", m.rec.found}, {"valid", m.rec.valid}, {"wall_ms", m.rec.wall_ms}};
        if (m.rec.found) {
          rj["length"] = m.rec.length;
          rj["turns"] = m.rec.turns;
          rj["smoothness"] = m.smoothness;
          if (m.optimum_iteration) rj["optimum_iteration"] = *m.optimum_iteration;
          if (m.optimum_iteration_total) rj["optimum_iteration_total"] = *m.optimum_iteration_total;
          if (m.rec.extra.contains("ga_best_length")) rj["ga_best_length"] = m.rec.extra.at("ga_best_length");
        }
        if (r == 0)
          for (const auto& c : m.rec.path) first_path.push_back(Json::array({c.x, c.y}));
        Json curve = Json::array();
        for (const double v : m.rec.best_per_iteration) curve.push_back(std::isfinite(v) ? Json(v) : Json(nullptr));
        curves.push_back(curve);
        runs.push_back(rj);
      }
      Json summary{{"runs", runs2}};
      std::int64_t found = 0, valid = 0;
      for (const Json& r : runs) {
        found += r.at("found").get<bool>() ? 1 : 0;
        valid += r.at("valid").get<bool>() ? 1 : 0;
      }
      summary["found"] = found;
      summary["valid"] = valid;
      for (const char* k : {"length", "wall_ms", "optimum_iteration", "optimum_iteration_total", "smoothness", "turns",
                            "ga_best_length"})
        summary[k] = stat_json(column(runs, k), jd.bo);
      // mean best-so-far curve over the runs (null where some run has no path yet)
      Json mean_curve = Json::array();
      if (!curves.empty()) {
        const std::size_t n = curves[0].size();
        for (std::size_t i = 0; i < n; ++i) {
          double s = 0.0;
          bool ok = true;
          for (const Json& c : curves) {
            if (i >= c.size() || c[i].is_null()) { ok = false; break; }
            s += c[i].get<double>();
          }
          mean_curve.push_back(ok ? Json(s / static_cast<double>(curves.size())) : Json(nullptr));
        }
      }
      per_map[result_key] = Json{{"available", true}, {"params", p->defaults}, {"overrides", params},
                                 {"params_used", params_used}, {"runs", runs}, {"summary", summary},
                                 {"mean_curve", mean_curve}, {"first_path", first_path}};
      if (cfg.progress)
        cfg.progress(fmt::format("{} {}: {} runs, {} found", sc.key, result_key, runs2, found));
    }
    results[sc.key] = per_map;
    // the claims on this map (reproduce.cin2021.protocol "Claims")
    const Json none = Json{{"available", false}};
    const auto series = [&](const std::string& k) -> const Json& { return per_map.contains(k) ? per_map.at(k) : none; };
    for (const Quantity3& q : quantities()) {
      for (const std::string& other : {std::string(aco), std::string(gan)}) {
        const std::string id = std::string(q.claim_id) + "." + sc.key + "." + other;
        const std::string text = std::string(q.text) + " (against " + cin_label(other) + ", map " + sc.key + ")";
        Claim c = hga_less_claim(id, text, q.source, series(hga), q.key, hga, series(other), q.key, other, q.decimals, jd);
        if (std::string(q.key) == "wall_ms")
          c.note += std::string(c.note.empty() ? "" : "; ") +
                    "wall-clock times of this machine (shared, loaded; see the provenance), a measurement";
        // readings of the colony: HGA-ACO@r against ACO@r (or against GA, which has no colony)
        for (const Reading& rd : readings()) {
          const std::string h = std::string(hga) + "@" + rd.key;
          const std::string o = other == aco ? std::string(aco) + "@" + rd.key : other;
          Claim alt = hga_less_claim(id + "@" + rd.key, text + ", reading `" + rd.param + "=" + rd.value + "`", q.source,
                                     series(h), q.key, h, series(o), q.key, o, q.decimals, jd);
          alt.depends_on.push_back("reading `" + rd.param + "=" + rd.value + "` (the alternative of " + id + ")");
          c.depends_on.push_back("the colony's default `" + rd.default_text + "` (alternative: " + alt.id + ")");
          reading_claims.push_back(std::move(alt));
        }
        if (std::string(q.key) == "optimum_iteration") {
          Claim alt = hga_less_claim(id + "/total", text + ", HGA-ACO's iterations counted from its first GA generation (G + t)",
                                     q.source, series(hga), "optimum_iteration_total", hga, series(other), q.key, other,
                                     q.decimals, jd);
          alt.depends_on.push_back("HGA-ACO's iteration of the optimum counted from the first GA generation (the "
                                   "alternative of " + id + ")");
          c.depends_on.push_back("HGA-ACO's iteration of the optimum counted in its ACO phase (alternative: " + alt.id + ")");
          reading_claims.push_back(std::move(alt));
        }
        claims.push_back(std::move(c));
      }
      if (shi_map)
        for (const std::string& other : cin2021_shi_planners()) {
          const std::string id = std::string("X") + (q.claim_id + 1) + "." + sc.key + "." + other;
          const std::string text = std::string(q.text) + " (against Shi's " + planner_label(other) + ", map " + sc.key + ")";
          Claim c = hga_less_claim(id, text, "neither paper (pathref's comparison of the two papers' hybrids)", series(hga),
                                   q.key, hga, series(other), q.key, other, q.decimals, jd);
          c.paper = "— (neither paper; pathref's comparison)";
          if (std::string(q.key) == "optimum_iteration")
            c.note += std::string(c.note.empty() ? "" : "; ") +
                      "Shi's hybrids report the GA generation of their result, HGA-ACO the ACO iteration: different counts";
          cross.push_back(std::move(c));
        }
    }
  }
  doc["maps"] = maps_json;
  doc["results"] = results;
  const auto to_json = [](const std::vector<Claim>& v) {
    Json a = Json::array();
    for (const Claim& c : v) a.push_back(claim_json(c));
    return a;
  };
  doc["claims"] = to_json(claims);
  doc["reading_claims"] = to_json(reading_claims);
  doc["cross_paper"] = to_json(cross);
  for (const char* k : {"claims", "reading_claims", "cross_paper"}) attach_rules_all(doc[k], cin2021_claim_rules);
  Json rd = Json::array();
  for (const Reading& r : readings())
    rd.push_back(Json{{"key", r.key}, {"param", r.param}, {"value", r.value}, {"default", r.default_text},
                      {"planners", Json::array({hga, aco})}});
  doc["protocol"] = Json{{"runs", cfg.runs},
                         {"runs_2n", runs2},
                         {"seeds", Json::array({cfg.seed, cfg.seed + static_cast<std::uint32_t>(cfg.runs) - 1})},
                         {"seeds_2n", Json::array({cfg.seed, cfg.seed + static_cast<std::uint32_t>(runs2) - 1})},
                         {"alpha", 0.05},
                         {"test", "Mann-Whitney U, two-sided (stats.compare)"},
                         {"bootstrap", Json{{"resamples", jd.bo.resamples}, {"level", jd.bo.level}, {"seed", jd.bo.seed}}},
                         {"quick", cfg.quick},
                         {"policy", std::string(grid::to_string(cfg.policy))},
                         {"readings", rd}};
  doc["provenance"]["total_wall_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  return doc;
}

namespace {

/// The claims of `list` whose verdict at n differs from that of one of their alternatives
/// (`depends_on` ids found in `alternatives`): "id: default verdict; under ALT: verdict".
std::string md_reading_changes(const Json& list, const Json& alternatives) {
  std::map<std::string, const Json*> by_id;
  for (const Json& a : alternatives) by_id[a.at("id").get<std::string>()] = &a;
  std::string s;
  int changed = 0, total = 0;
  for (const Json& c : list) {
    std::string alts;
    for (const auto& [id, a] : by_id) {
      if (id.rfind(c.at("id").get<std::string>(), 0) != 0 || id.size() == c.at("id").get<std::string>().size()) continue;
      const char next = id[c.at("id").get<std::string>().size()];
      if (next != '@' && next != '/') continue;
      ++total;
      if (a->at("verdict_text") != c.at("verdict_text")) {
        ++changed;
        alts += fmt::format("; under {}: {}", id.substr(c.at("id").get<std::string>().size()),
                            a->at("verdict_text").get<std::string>());
      }
    }
    if (!alts.empty())
      s += fmt::format("- {} †: {}{}\n", c.at("id").get<std::string>(), c.at("verdict_text").get<std::string>(), alts);
  }
  return fmt::format("{} of {} alternative verdicts differ from the default's:\n\n", changed, total) +
         (s.empty() ? std::string("- none\n") : s);
}

std::string md_changes(const Json& claims) {
  std::string s;
  for (const Json& c : claims)
    if (c.value("changed", false))
      s += fmt::format("- {}: {}\n", c.at("id").get<std::string>(), c.at("change_note").get<std::string>());
  return s.empty() ? "No verdict changes between n and 2n runs.\n" : s;
}

}  // namespace

std::string cin2021_markdown(const Json& doc, const std::string& figure_dir, const std::string& json_name) {
  const auto base_label = [](const std::string& n) -> std::string {
    if (n == hga) return "HGA-ACO (`hga-aco-cin`)";
    if (n == aco) return "ACO (`aco-cin`)";
    if (n == gan) return "GA (`ga-cin`)";
    return planner_label(n) + " (`" + n + "`)";
  };
  const auto label = [&](const std::string& n) -> std::string {
    const auto at = n.find('@');
    if (at == std::string::npos) return base_label(n);
    const std::string r = n.substr(at + 1);
    return base_label(n.substr(0, at)) + ", reading " +
           (r == "any_stuck" ? "`dead_angle_record=any_stuck`" : "`eta=goal_inverse`");
  };
  const auto ms = [](const Json& st, int d) {
    if (!st.is_object() || st.value("n", 0) == 0) return std::string("—");
    std::string out = md_number(st.at("mean"), d);
    if (!st.at("std").is_null()) out += " ± " + md_number(st.at("std"), d);
    if (st.contains("ci") && st.at("ci").is_object())
      out += " [" + md_number(st.at("ci").at("lo"), d) + ", " + md_number(st.at("ci").at("hi"), d) + "]";
    return out;
  };
  const Json& proto = doc.at("protocol");
  const auto n = proto.value("runs", std::int64_t{0});
  const auto n2 = proto.value("runs_2n", n);
  std::string md;
  md += "# Reproduction: cin2021 HGA-ACO against its ACO and GA (§5.6, Table 3)\n\n";
  md += "<!-- generated by `pathref reproduce cin2021-hga-aco`; do not edit by hand -->\n\n";
  if (proto.value("quick", false))
    md += "**QUICK RUN** (`--quick`: reduced iterations, ants and population; a smoke test, not a reproduction).\n\n";
  md += "Paper: *Computational Intelligence and Neuroscience* 2021, article 8025730, doi:10.1155/2021/8025730, "
        "§5 (spec/cin2021-hga-aco.md). Every equation of §5 is **reconstructed** (the formula images were lost); "
        "the 13 parameter values of §5.6 and every number of Table 3 are **lost**. So this report cannot compare "
        "numbers with the paper: it runs the algorithm as specified, with the **project's** parameter values "
        "(listed below; never the paper's), and judges the paper's qualitative claims. **Every verdict below rests on "
        "that reconstruction and on those parameter values**; the verdicts marked † also rest on a chosen reading "
        "whose alternative was run and is shown.\n\n";
  md += "Command: `" + doc.at("provenance").value("command", std::string()) + "`. Every number is in `" + json_name +
        "`, the figures in `" + figure_dir + "/`.\n\n";
  md += "## How the claims are judged\n\n";
  md += fmt::format(
      "Spec reproduce.cin2021.protocol with reproduce.judge and spec/stats.md, fixed before these runs. Every "
      "planner runs 2n = {} times per map (seeds {}–{}); each claim is judged on the first n = {} runs (seeds {}–{}; "
      "the headline verdict, counted in the summary) and again on all 2n, and every verdict that changes is "
      "explained. A claim \"HGA-ACO < X\" **holds** when the two-sided Mann–Whitney U test is significant at "
      "α = {} with HGA-ACO's runs lower (the direction read from U); **does not hold — the opposite is "
      "significant** when it is significant with HGA-ACO higher; otherwise **not significant**, with the observed "
      "direction. Welch's t and the 95 % percentile bootstrap CI of the mean difference HGA − X ({} resamples, seed "
      "{}) are printed beside it, never deciding; where the CI and the rank test disagree the note says so. The "
      "paper gives no numbers (Table 3 is lost), so there are no value claims. The tables summarise all 2n runs.\n\n",
      n2, proto.at("seeds_2n")[0].get<std::int64_t>(), proto.at("seeds_2n")[1].get<std::int64_t>(), n,
      proto.at("seeds")[0].get<std::int64_t>(), proto.at("seeds")[1].get<std::int64_t>(),
      md_number(proto.at("alpha"), 2), proto.at("bootstrap").at("resamples").get<std::int64_t>(),
      proto.at("bootstrap").at("seed").get<std::int64_t>());
  md += "## Maps\n\n";
  md += "Scenarios s1–s3 are built as §5.6 describes them (20 × 20 grid, 1 cm cells, black rectangles as "
        "obstacles); their layouts are pathref's (Figure 10 is lost; spec reproduce.cin2021.maps). Shi's maps B "
        "and C are the MATLAB maps of `pathref reproduce shi2022`, in the paper orientation.\n\n";
  md += md_row({"map", "source", "start", "goal", "optimum (Dijkstra, " + proto.value("policy", std::string("strict")) + ")"});
  md += md_row({"---", "---", "---", "---", "---:"});
  for (const Json& m : doc.at("maps"))
    md += md_row({m.at("label").get<std::string>(), m.at("source").get<std::string>(), m.at("start").dump(),
                  m.at("goal").dump(), md_number(m.at("optimum"), 3)});
  md += "\n## Parameters of every planner (project defaults of the lost §5.6 list, not the paper's)\n\n";
  md += "The paper's baselines ACO and GA are read as its own optimised ACO (§5.3) and GA (§5.5) run alone (the paper "
        "gives no other parameters for them). Shi's hybrids run with their registered defaults (spec/shi2022-ga.md). "
        "The parameters actually used by the first run of each series:\n\n";
  {
    std::map<std::string, bool> seen;
    for (const auto& [key, per_map] : doc.at("results").items())
      for (const auto& [name, res] : per_map.items()) {
        if (seen[name]) continue;
        seen[name] = true;
        if (!res.value("available", false)) {
          md += "- " + label(name) + ": not available in this build\n";
          continue;
        }
        md += "- " + label(name) + ": `" + res.value("params_used", res.at("params")).dump() + "`";
        if (!res.at("overrides").empty()) md += " (overrides of the defaults: `" + res.at("overrides").dump() + "`)";
        md += "\n";
      }
  }
  md += fmt::format("\n## Table 3, reproduced (all {} runs: mean ± sd [95 % bootstrap CI of the mean])\n\n", n2);
  md += "Iteration of the optimum: the generation (GA) or iteration (ACO; the ACO phase of HGA-ACO) in which the "
        "returned path was first found; \"HGA total\" counts HGA-ACO's GA generations too (G + t). Time: wall "
        "clock of one planner run (machine below). S: smoothness of Eq. (17), Σ(1 − cos θ). \"GA phase best\": the "
        "best length of HGA-ACO's own GA phase (the ACO phase returns its own best, which can be longer).\n\n";
  for (const Json& m : doc.at("maps")) {
    const std::string key = m.at("key").get<std::string>();
    md += "### " + m.at("label").get<std::string>() + "\n\n<!-- results:" + key + " -->\n";
    md += md_row({"planner", "found / valid", "length", "time (ms)", "iteration of the optimum", "HGA total iterations",
                  "S (Eq. 17)", "turns", "GA phase best"});
    md += md_row({"---", "---", "---:", "---:", "---:", "---:", "---:", "---:", "---:"});
    for (const auto& [name, res] : doc.at("results").at(key).items()) {
      if (!res.value("available", false)) {
        md += md_row({label(name), "not available in this build", "", "", "", "", "", "", ""});
        continue;
      }
      const Json& su = res.at("summary");
      const bool is_hga = name.rfind(hga, 0) == 0;
      md += md_row({label(name),
                    std::to_string(su.at("found").get<std::int64_t>()) + " / " +
                        std::to_string(su.at("valid").get<std::int64_t>()) + " of " +
                        std::to_string(su.at("runs").get<std::int64_t>()),
                    ms(su.at("length"), 2), ms(su.at("wall_ms"), 1), ms(su.at("optimum_iteration"), 1),
                    is_hga ? ms(su.at("optimum_iteration_total"), 1) : std::string("—"), ms(su.at("smoothness"), 2),
                    ms(su.at("turns"), 1), is_hga ? ms(at_or_null(su, {"ga_best_length"}), 2) : std::string("—")});
    }
    md += "\n![paths](" + figure_dir + "/" + key + "-paths.svg) ![convergence](" + figure_dir + "/" + key +
          "-convergence.svg)\n\n";
  }
  md += "## The paper's claims\n\n";
  md += "C1–C4 of §5.6 and §6, each per map and baseline (s1–s3 are the rebuilt scenarios; on Shi's maps B and C the "
        "same claims are tested on maps the paper never used).\n\n";
  md += md_verdict_summary(doc.at("claims")) + "\n";
  md += md_claims(doc.at("claims"));
  md += "\n### Verdicts that change between n and 2n runs\n\n" + md_changes(doc.at("claims"));
  md += "\n## The same claims under the alternative readings (†)\n\n";
  md += "Every claim rests on the colony's two chosen readings (spec/cin2021-hga-aco.md: the dead-angle record rule and "
        "η of Eq. 30), run here under their alternatives on every map (`@any_stuck`, `@goal_inverse`: HGA-ACO and ACO "
        "under the reading; GA has no colony and keeps its defaults), and C3 also on the count of HGA-ACO's "
        "iterations (`/total`: from its first GA generation, G + t).\n\n";
  md += md_reading_changes(doc.at("claims"), doc.at("reading_claims")) + "\n";
  md += md_verdict_summary(doc.at("reading_claims")) + "\n";
  md += md_claims(doc.at("reading_claims"));
  if (!doc.at("cross_paper").empty()) {
    md += "\n## HGA-ACO against Shi's hybrids (a comparison neither paper makes)\n\n";
    md += "Not claims of either paper and not counted with them: the same rule, HGA-ACO against Shi's IHA and "
          "traditional hybrid on Shi's maps. The X3 rows compare different counts (HGA-ACO's ACO iteration, Shi's GA "
          "generation). The X rows against IHA rest on pathref's readings of Shi's weighted fitness (Eq. 16 and Eq. 18 "
          "read as the reciprocal of 1 + the path's total penalty, decided in issue 11; under the printed per-node "
          "sums IHA prefers long paths: docs/reproduction/shi2022.md, \"The weighted fitness under its readings\").\n\n";
    md += md_verdict_summary(doc.at("cross_paper")) + "\n";
    md += md_claims(doc.at("cross_paper"));
  }
  // what the means say, in words (the verdicts are in the claims)
  {
    int shorter_than_aco = 0, shorter_than_ga = 0, maps_aco = 0, maps_ga = 0, ga_phase_shorter = 0, maps_hga = 0;
    for (const auto& [key, per_map] : doc.at("results").items()) {
      const Json& h = at_or_null(per_map, {hga, "summary", "length", "mean"});
      const Json& gp = at_or_null(per_map, {hga, "summary", "ga_best_length", "mean"});
      if (!h.is_number()) continue;
      if (gp.is_number()) {
        ++maps_hga;
        ga_phase_shorter += gp.get<double>() < h.get<double>() ? 1 : 0;
      }
      const Json& a = at_or_null(per_map, {aco, "summary", "length", "mean"});
      const Json& g = at_or_null(per_map, {gan, "summary", "length", "mean"});
      if (a.is_number()) { ++maps_aco; shorter_than_aco += h.get<double>() < a.get<double>() ? 1 : 0; }
      if (g.is_number()) { ++maps_ga; shorter_than_ga += h.get<double>() < g.get<double>() ? 1 : 0; }
    }
    md += "\n## What the means say\n\n";
    md += fmt::format("Over all {} runs, under the default readings, HGA-ACO's mean path is shorter than ACO's on {} "
                      "of {} maps and shorter than GA's on {} of {} maps; its own GA phase's mean best is shorter than "
                      "its returned (ACO phase) mean on {} of {} maps. ",
                      n2, shorter_than_aco, maps_aco, shorter_than_ga, maps_ga, ga_phase_shorter, maps_hga);
    md += "HGA-ACO returns its ACO phase's best path (§5.2, Figure 7); the GA's paths enter the colony only as "
          "initial pheromone (Eq. 28), so with the project's parameters the colony's first weighted deposits "
          "(ω_ib = N_max at t = 0) can outweigh the converted pheromone and the ACO phase need not keep the GA "
          "phase's best path. With the paper's 13 parameter values lost, whether the paper's own settings avoid "
          "this cannot be settled here.\n\n";
  }
  md += "## Provenance\n\n" + md_provenance(doc.at("provenance"), json_name);
  return md;
}

std::vector<std::pair<std::string, std::string>> cin2021_figures(const Json& doc) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const Json& m : doc.at("maps")) {
    const std::string key = m.at("key").get<std::string>();
    grid::Grid g(m.at("width").get<std::int64_t>(), m.at("height").get<std::int64_t>());
    const Json& rows = m.at("grid");
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const std::string row = rows[r].get<std::string>();
      for (std::size_t x = 0; x < row.size(); ++x)
        if (row[x] == '#')
          g.set_blocked(grid::Cell{static_cast<std::int64_t>(x), static_cast<std::int64_t>(rows.size() - 1 - r)}, true);
    }
    const grid::Cell s{m.at("start")[0].get<std::int64_t>(), m.at("start")[1].get<std::int64_t>()};
    const grid::Cell t{m.at("goal")[0].get<std::int64_t>(), m.at("goal")[1].get<std::int64_t>()};
    std::vector<io::PathLayer> layers;
    std::vector<io::Series> series;
    for (const auto& [name, res] : doc.at("results").at(key).items()) {
      if (!res.value("available", false) || name.find('@') != std::string::npos) continue;
      io::PathLayer l;
      l.label = planner_label(name);
      for (const Json& c : res.at("first_path")) l.path.push_back(grid::Cell{c[0].get<std::int64_t>(), c[1].get<std::int64_t>()});
      layers.push_back(std::move(l));
      io::Series se;
      se.label = planner_label(name);
      const Json& mc = res.at("mean_curve");
      for (std::size_t i = 0; i < mc.size(); ++i) {
        se.x.push_back(static_cast<double>(i + 1));
        se.y.push_back(mc[i].is_null() ? std::numeric_limits<double>::infinity() : mc[i].get<double>());
      }
      series.push_back(std::move(se));
    }
    out.emplace_back(key + "-paths.svg", io::svg_map(g, s, t, layers, m.at("label").get<std::string>() + ": first run's paths"));
    io::ChartOptions co;
    co.title = m.at("label").get<std::string>() + ": mean best-so-far length";
    co.x_label = "iteration (hga-aco-cin: GA generations, then ACO iterations)";
    co.y_label = "path length";
    out.emplace_back(key + "-convergence.svg", io::svg_line_chart(series, co));
  }
  return out;
}

}  // namespace pathref::reproduce
