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

/// Table 3 measurements of one run.
struct Measured {
  RunRecord rec;
  double smoothness = std::numeric_limits<double>::quiet_NaN();  ///< cin2021.eq17 of the path
  std::optional<std::int64_t> optimum_iteration;  ///< iteration of the result (phase-local)
  std::optional<std::int64_t> optimum_iteration_total;  ///< counted from the first GA generation
};

Measured measure(const planners::Planner& p, const CinScenario& sc, grid::CornerPolicy policy,
                 std::uint32_t seed, const Json& params) {
  Measured m;
  m.rec = run_once(p, sc.grid, sc.start, sc.goal, policy, seed, params);
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

Json stat_json(const std::vector<double>& v) {
  const Summary s = summarize(v);
  const auto opt = [](const std::optional<double>& x) { return x ? Json(*x) : Json(nullptr); };
  return Json{{"n", s.n}, {"mean", opt(s.mean)}, {"std", opt(s.std)}, {"min", opt(s.min)}, {"max", opt(s.max)}};
}

std::vector<double> column(const Json& runs, const char* key) {
  std::vector<double> v;
  for (const Json& r : runs)
    if (r.contains(key) && r.at(key).is_number()) v.push_back(r.at(key).get<double>());
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

Json comparison(const std::string& map, const std::string& quantity, const std::string& a_name,
                const std::vector<double>& a, const std::string& b_name, const std::vector<double>& b) {
  Json c{{"map", map}, {"quantity", quantity}, {"a", a_name}, {"b", b_name}};
  if (a.size() < 2 || b.size() < 2) {
    c["note"] = "fewer than 2 runs with a value";
    return c;
  }
  c["mean_a"] = mean(a);
  c["mean_b"] = mean(b);
  c["mean_difference"] = mean(a) - mean(b);
  const auto t = welch_t(a, b);
  c["welch_t"] = t ? Json(*t) : Json(nullptr);
  return c;
}

/// The claims of reproduce.cin2021.protocol, one per (claim, map, other planner), from the
/// comparisons of the default reading.
Json make_claims(const Json& comparisons) {
  Json claims = Json::array();
  struct Q {
    const char* quantity;
    const char* id;
    const char* text;
    const char* source;
  };
  const Q qs[] = {
      {"length", "C1", "HGA-ACO has the shortest path length", "§5.6 (Figure 10, Table 3 path length), §6"},
      {"wall_ms", "C2", "HGA-ACO has the shortest running time", "§5.6 (Table 3 running time), §6"},
      {"optimum_iteration", "C3", "HGA-ACO needs the fewest iterations to its optimum",
       "§5.6 (Table 3 optimal iteration, Figure 11), §6"},
      {"smoothness", "C4", "HGA-ACO's path is the smoothest", "§5.6 (Figure 10)"},
  };
  for (const Q& q : qs)
    for (const Json& c : comparisons) {
      if (c.at("quantity") != q.quantity || c.contains("reading")) continue;
      const std::string other = c.at("b").get<std::string>();
      const std::string map = c.at("map").get<std::string>();
      Claim cl;
      cl.id = std::string(q.id) + "." + map + "." + other;
      cl.text = std::string(q.text) + " (against " + other + ", map " + map + ")";
      cl.source = q.source;
      cl.paper = "HGA-ACO < " + other + " (Table 3's numbers are lost)";
      cl.ours = c.contains("mean_difference")
                    ? "mean difference " + fixed(c.at("mean_difference").get<double>(), 3)
                    : std::string("—");
      cl.rule = "two-sided Mann-Whitney U at alpha = 0.05 with the observed direction; bootstrap 95 % CI "
                "of the mean difference reported (spec reproduce.cin2021.protocol)";
      cl.verdict = Verdict::untestable;
      cl.note = "the statistics module (bootstrap CI, Mann-Whitney) is not on main yet; the means and "
                "Welch's t are in the comparisons";
      claims.push_back(claim_json(cl));
    }
  return claims;
}

}  // namespace

Json run_cin2021(const CinConfig& cfg) {
  if (cfg.runs < 2 || cfg.runs > 10000) throw UsageError("--runs must lie in [2, 10000]");
  const auto t_start = std::chrono::steady_clock::now();
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
  Json comparisons = Json::array();
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
    // readings that change the outcome (spec reproduce.cin2021.protocol "Readings"): the colony
    // planners again on the three scenarios, results under "PLANNER@KEY"
    struct Reading { std::string key; std::string param; std::string value; };
    const std::vector<Reading> readings = {{"any_stuck", "dead_angle_record", "any_stuck"},
                                           {"goal_inverse", "eta", "goal_inverse"}};
    std::vector<std::pair<std::string, Json>> runs_of;  // (result key, parameter overrides)
    for (const std::string& name : planners) runs_of.emplace_back(name, Json::object());
    if (!shi_map)
      for (const Reading& rd : readings)
        for (const char* name : {hga, aco})
          runs_of.emplace_back(std::string(name) + "@" + rd.key,
                               Json{{(std::string(name) == hga ? "aco_" : "") + rd.param, rd.value}});
    Json per_map = Json::object();
    for (const auto& [result_key, reading_params] : runs_of) {
      const std::string name = result_key.substr(0, result_key.find('@'));
      const planners::Planner* p = available(name);
      if (p == nullptr) {
        per_map[result_key] = Json{{"available", false}};
        continue;
      }
      Json params = cfg.quick ? quick_overrides(p->defaults) : Json::object();
      for (const auto& [k, v] : reading_params.items()) params[k] = v;
      Json runs = Json::array();
      Json curves = Json::array();
      Json first_path = Json::array();
      for (std::int64_t r = 0; r < cfg.runs; ++r) {
        const auto seed = static_cast<std::uint32_t>(cfg.seed + static_cast<std::uint32_t>(r));
        const Measured m = measure(*p, sc, cfg.policy, seed, params);
        Json rj{{"seed", seed}, {"found", m.rec.found}, {"valid", m.rec.valid}, {"wall_ms", m.rec.wall_ms}};
        if (m.rec.found) {
          rj["length"] = m.rec.length;
          rj["turns"] = m.rec.turns;
          rj["smoothness"] = m.smoothness;
          if (m.optimum_iteration) rj["optimum_iteration"] = *m.optimum_iteration;
          if (m.optimum_iteration_total) rj["optimum_iteration_total"] = *m.optimum_iteration_total;
        }
        if (r == 0) {
          for (const auto& c : m.rec.path) first_path.push_back(Json::array({c.x, c.y}));
        }
        Json curve = Json::array();
        for (const double v : m.rec.best_per_iteration) curve.push_back(std::isfinite(v) ? Json(v) : Json(nullptr));
        curves.push_back(curve);
        runs.push_back(rj);
      }
      Json summary{{"runs", cfg.runs}};
      std::int64_t found = 0, valid = 0;
      for (const Json& r : runs) {
        found += r.at("found").get<bool>() ? 1 : 0;
        valid += r.at("valid").get<bool>() ? 1 : 0;
      }
      summary["found"] = found;
      summary["valid"] = valid;
      for (const char* k : {"length", "wall_ms", "optimum_iteration", "optimum_iteration_total", "smoothness", "turns"})
        summary[k] = stat_json(column(runs, k));
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
                           {"runs", runs}, {"summary", summary}, {"mean_curve", mean_curve},
                           {"first_path", first_path}};
      if (cfg.progress)
        cfg.progress(fmt::format("{} {}: {} runs, {} found", sc.key, result_key, cfg.runs, found));
    }
    results[sc.key] = per_map;
    // comparisons HGA-ACO vs ACO and vs GA (and vs Shi's hybrids on Shi's maps)
    std::vector<std::string> others = {aco, gan};
    if (shi_map) others.insert(others.end(), cin2021_shi_planners().begin(), cin2021_shi_planners().end());
    if (per_map.contains(hga) && per_map[hga].value("available", false))
      for (const auto& o : others) {
        if (!per_map.contains(o) || !per_map[o].value("available", false)) continue;
        for (const char* q : {"length", "wall_ms", "optimum_iteration", "smoothness"})
          comparisons.push_back(comparison(sc.key, q, hga, column(per_map[hga]["runs"], q), o,
                                           column(per_map[o]["runs"], q)));
      }
    // under each reading: HGA-ACO@r against ACO@r and against GA (length), reading-dependent
    for (const Reading& rd : readings) {
      const std::string h = std::string(hga) + "@" + rd.key;
      const std::string a = std::string(aco) + "@" + rd.key;
      if (!per_map.contains(h) || !per_map.contains(a)) continue;
      for (const std::string& o : {a, std::string(gan)}) {
        Json c = comparison(sc.key, "length", h, column(per_map[h]["runs"], "length"), o,
                            column(per_map[o]["runs"], "length"));
        c["reading"] = rd.param + "=" + rd.value;
        comparisons.push_back(c);
      }
    }
  }
  doc["maps"] = maps_json;
  doc["results"] = results;
  doc["comparisons"] = comparisons;
  doc["claims"] = make_claims(comparisons);
  doc["provenance"]["total_wall_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  doc["protocol"] = Json{{"runs", cfg.runs}, {"seed", cfg.seed}, {"quick", cfg.quick},
                         {"policy", std::string(grid::to_string(cfg.policy))}};
  return doc;
}

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
  std::string md;
  md += "# Reproduction: cin2021 HGA-ACO against its ACO and GA (§5.6, Table 3)\n\n";
  md += "Paper: *Computational Intelligence and Neuroscience* 2021, article 8025730, doi:10.1155/2021/8025730, "
        "§5 (spec/cin2021-hga-aco.md). Every equation of §5 is **reconstructed** (the formula images were lost); "
        "the 13 parameter values of §5.6 and every number of Table 3 are **lost**. So this report cannot compare "
        "numbers with the paper: it runs the algorithm as specified, with the **project's** parameter values "
        "(listed below; never the paper's), and judges the paper's qualitative claims.\n\n";
  md += "Command: `" + doc.at("provenance").value("command", std::string()) + "`. Every number is in `" + json_name +
        "`, the figures in `" + figure_dir + "/`.\n\n";
  md += "## Maps\n\n";
  md += "Scenarios s1–s3 are built as §5.6 describes them (20 × 20 grid, 1 cm cells, black rectangles as "
        "obstacles); their layouts are pathref's (Figure 10 is lost; spec reproduce.cin2021.maps). Shi's maps B "
        "and C are the MATLAB maps of `pathref reproduce shi2022`, in the paper orientation.\n\n";
  md += md_row({"map", "source", "start", "goal", "optimum (Dijkstra, strict)"});
  md += md_row({"---", "---", "---", "---", "---:"});
  for (const Json& m : doc.at("maps"))
    md += md_row({m.at("label").get<std::string>(), m.at("source").get<std::string>(), m.at("start").dump(),
                  m.at("goal").dump(), md_number(m.at("optimum"), 3)});
  md += "\n## Parameters (project defaults of the lost §5.6 list, not the paper's)\n\n";
  const Json& r0 = doc.at("results").begin().value();
  for (const auto& [name, res] : r0.items()) {
    if (!res.value("available", false) || name.find('@') != std::string::npos) continue;
    md += "- " + label(name) + ": `" + res.at("params").dump() + "`";
    if (!res.at("overrides").empty()) md += " with overrides `" + res.at("overrides").dump() + "`";
    md += "\n";
  }
  md += "\n## Table 3, reproduced (mean ± sd [95 % bootstrap CI of the mean])\n\n";
  md += "Iteration of the optimum: the generation (GA) or iteration (ACO; the ACO phase of HGA-ACO) in which the "
        "returned path was first found; \"HGA total\" counts HGA-ACO's GA generations too (G + t). Time: wall "
        "clock of one planner run (machine below). S: smoothness of Eq. (17), Σ(1 − cos θ).\n\n";
  for (const Json& m : doc.at("maps")) {
    const std::string key = m.at("key").get<std::string>();
    md += "### " + m.at("label").get<std::string>() + "\n\n<!-- results:" + key + " -->\n";
    md += md_row({"planner", "found / valid", "length", "time (ms)", "iteration of the optimum", "HGA total iterations",
                  "S (Eq. 17)", "turns"});
    md += md_row({"---", "---", "---:", "---:", "---:", "---:", "---:", "---:"});
    for (const auto& [name, res] : doc.at("results").at(key).items()) {
      if (!res.value("available", false)) {
        md += md_row({label(name), "not available in this build", "", "", "", "", "", ""});
        continue;
      }
      const Json& su = res.at("summary");
      md += md_row({label(name),
                    std::to_string(su.at("found").get<std::int64_t>()) + " / " +
                        std::to_string(su.at("valid").get<std::int64_t>()) + " of " +
                        std::to_string(su.at("runs").get<std::int64_t>()),
                    ms(su.at("length"), 2), ms(su.at("wall_ms"), 1), ms(su.at("optimum_iteration"), 1),
                    name == hga ? ms(su.at("optimum_iteration_total"), 1) : std::string("—"),
                    ms(su.at("smoothness"), 2), ms(su.at("turns"), 1)});
    }
    md += "\n![paths](" + figure_dir + "/" + key + "-paths.svg) ![convergence](" + figure_dir + "/" + key +
          "-convergence.svg)\n\n";
  }
  // what the means say, in words (the verdicts are in the claims)
  {
    int shorter_than_aco = 0, shorter_than_ga = 0, maps_aco = 0, maps_ga = 0;
    for (const Json& c : doc.at("comparisons")) {
      if (c.contains("reading") || c.at("quantity") != "length" || !c.contains("mean_difference")) continue;
      const bool shorter = c.at("mean_difference").get<double>() < 0.0;
      if (c.at("b") == aco) { ++maps_aco; shorter_than_aco += shorter ? 1 : 0; }
      if (c.at("b") == gan) { ++maps_ga; shorter_than_ga += shorter ? 1 : 0; }
    }
    md += "## What the means say\n\n";
    md += fmt::format("Under the default reading HGA-ACO's mean path is shorter than ACO's on {} of {} maps and "
                      "shorter than GA's on {} of {} maps. ", shorter_than_aco, maps_aco, shorter_than_ga, maps_ga);
    md += "HGA-ACO returns its ACO phase's best path (§5.2, Figure 7); the GA's paths enter the colony only as "
          "initial pheromone (Eq. 28), so with the project's parameters the colony's first weighted deposits "
          "(ω_ib = N_max at t = 0) outweigh the converted pheromone and the ACO phase need not keep the GA "
          "phase's best path: HGA-ACO can end longer than its own GA phase (`ga_best_length` in the planner's "
          "extra). The paper claims the opposite order; with its 13 parameter values lost this cannot be "
          "settled here. See the readings rows for how the dead-angle record rule and η change the colony.\n\n";
  }
  md += "## Comparisons\n\n";
  md += md_row({"map", "quantity", "reading", "HGA-ACO vs", "mean difference (HGA − other)", "95 % CI", "test", "p",
                "verdict on \"HGA-ACO lower\""});
  md += md_row({"---", "---", "---", "---", "---:", "---", "---", "---:", "---"});
  for (const Json& c : doc.at("comparisons")) {
    md += md_row({c.at("map").get<std::string>(), c.at("quantity").get<std::string>(),
                  c.value("reading", std::string("default")), c.at("b").get<std::string>(),
                  md_number(c.value("mean_difference", Json(nullptr)), 3),
                  c.contains("ci") ? "[" + md_number(c.at("ci").at("lo"), 3) + ", " + md_number(c.at("ci").at("hi"), 3) + "]"
                                   : std::string("—"),
                  c.value("test", std::string("—")), md_number(c.value("p", Json(nullptr)), 4),
                  c.value("verdict_text", std::string("—"))});
  }
  md += "\n## Claims\n\n";
  md += md_claims(doc.at("claims"));
  md += "\n" + md_verdict_summary(doc.at("claims")) + "\n";
  md += md_provenance(doc.at("provenance"), json_name);
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
