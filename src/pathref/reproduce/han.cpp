#include "pathref/reproduce/han.hpp"

#include <fmt/core.h>

#include <chrono>
#include <cmath>
#include <limits>

#include "pathref/core/error.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/io/svg.hpp"
#include "pathref/reproduce/runs.hpp"
#include "pathref/reproduce/stats.hpp"
#include "pathref/sim/random_map.hpp"

namespace pathref::reproduce {

namespace {
/// Robot speed of Han §IV (1 m/s without dynamic obstacles); cells are 1 m.
constexpr double han_speed = 1.0;
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
      {"iaco-han", "iaco-han", Json{{"dead_end", "backtrack"}}, "IACO-A* (iaco-han, dead_end=backtrack)"},
      {"aco", "aco", Json{{"ants", 200}, {"iterations", 50}, {"rho", 0.6}, {"dead_end", "backtrack"}},
       "ACO (aco, Han Table I, dead_end=backtrack)"},
      {"iaco-han:goal", "iaco-han", Json{{"dead_end", "backtrack"}, {"eta", "goal_directed"}},
       "IACO-A* with η = 1/(d_ij + d_jE) (the other reading of Han's undefined η)"},
      {"astar-han", "astar-han", Json::object(), "A* (astar-han, Chebyshev)"},
      {"astar", "astar", Json::object(), "A* (astar, octile)"},
      {"iaco-han@die", "iaco-han", Json::object(), "IACO-A* (dead_end=die, the planner default)"},
      {"aco@die", "aco", Json{{"ants", 200}, {"iterations", 50}, {"rho", 0.6}},
       "ACO (Han Table I, dead_end=die, the planner default)"},
  };
  return v;
}

namespace {

bool deterministic(const std::string& planner) { return planner == "astar" || planner == "astar-han"; }

/// Aggregate of one variant over the maps of one edge.
Json aggregate(const std::vector<const Json*>& series) {
  std::vector<double> mins, means, stds, conv, wall;
  std::int64_t runs = 0, found = 0, maps_found = 0;
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
    for (const double c : run_values(*s, "converged_at")) conv.push_back(c);
    for (const double w : run_values(*s, "wall_ms")) wall.push_back(w);
  }
  auto m = [](const std::vector<double>& v) { return v.empty() ? Json(nullptr) : num(mean(v)); };
  Json out{{"available", available},
           {"maps", series.size()},
           {"maps_found", maps_found},
           {"runs", runs},
           {"found", found},
           {"min_length", m(mins)},
           {"mean_length", m(means)},
           {"std_length", m(stds)},
           {"converged_at", m(conv)},
           {"wall_ms", m(wall)}};
  // Travel time without dynamic obstacles: the minimum length at 1 m/s (defined only when every
  // map of the edge has a path, like min_length's comparison).
  out["travel_time_s"] = (maps_found == static_cast<std::int64_t>(series.size()) && !mins.empty())
                             ? num(mean(mins) / han_speed)
                             : Json(nullptr);
  if (maps_found != static_cast<std::int64_t>(series.size())) out["min_length"] = nullptr;
  return out;
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
    variants.push_back(Json{{"key", v.key}, {"planner", v.planner}, {"params", v.params}, {"label", v.label}});
  const std::int64_t n_maps = static_cast<std::int64_t>(cfg.edges.size()) * cfg.maps_per_edge;
  const std::uint64_t max_runs = static_cast<std::uint64_t>(std::max(cfg.runs, cfg.sweep_runs));
  require(static_cast<std::uint64_t>(cfg.seed) + static_cast<std::uint64_t>(n_maps) <= 4294967296ULL &&
              static_cast<std::uint64_t>(cfg.seed) + max_runs <= 4294967296ULL,
          "run_han: seed + number of maps (or runs) - 1 must not exceed 4294967295");
  doc["protocol"] = Json{{"edges", cfg.edges},
                         {"maps_per_edge", cfg.maps_per_edge},
                         {"runs_10m", cfg.runs},
                         {"sweep_runs", cfg.sweep_runs},
                         {"seed", cfg.seed},
                         {"map_seeds", Json::array({cfg.seed, static_cast<std::uint64_t>(cfg.seed) + static_cast<std::uint64_t>(n_maps) - 1})},
                         {"policy", std::string(grid::to_string(cfg.policy))},
                         {"quick", cfg.quick},
                         {"variants", variants},
                         {"speed_m_per_s", han_speed},
                         {"cell_m", 1.0}};
  Json maps = Json::array();
  Json edges = Json::array();
  std::int64_t j = 0;
  for (const auto edge : cfg.edges) {
    std::vector<std::vector<const Json*>> per_variant(han_variants().size());
    const std::int64_t runs = edge == 10 ? cfg.runs : cfg.sweep_runs;
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
      const std::string ctx = fmt::format("han edge {} map {} (ratio {})", edge, k + 1, fixed(ratio, 2));
      for (const auto& v : han_variants())
        res[v.key] = run_series(v.planner, v.params, rm.grid, rm.start, rm.goal, cfg.policy, cfg.seed,
                                deterministic(v.planner) ? 1 : runs, cfg.quick, cfg.progress, ctx);
      // Keep the document small: per-run records stay everywhere; the best run's path and curves and
      // the mean iteration curve only on the 10 m maps (every run can be replayed from its seed).
      if (edge != 10)
        for (auto it = res.begin(); it != res.end(); ++it) {
          if (it->contains("best") && it->at("best").is_object())
            for (const char* field : {"path", "best_per_iteration", "mean_per_iteration"}) (*it)["best"].erase(field);
          it->erase("mean_iteration_curve");
        }
      mj["results"] = res;
      maps.push_back(mj);
    }
    for (std::size_t m = first_map; m < maps.size(); ++m)
      for (std::size_t vi = 0; vi < han_variants().size(); ++vi)
        per_variant[vi].push_back(&maps[m].at("results").at(han_variants()[vi].key));
    Json ej{{"edge", edge}, {"runs", runs}};
    Json agg = Json::object();
    for (std::size_t vi = 0; vi < han_variants().size(); ++vi) agg[han_variants()[vi].key] = aggregate(per_variant[vi]);
    ej["variants"] = agg;
    edges.push_back(ej);
  }
  doc["maps"] = maps;
  doc["edges"] = edges;

  // Claims.
  std::vector<Claim> claims;
  const Json* e10 = nullptr;
  const Json* e100 = nullptr;
  for (const Json& e : doc["edges"]) {
    if (e.at("edge").get<std::int64_t>() == 10) e10 = &e;
    if (e.at("edge").get<std::int64_t>() == 100) e100 = &e;
  }
  auto less = [](const std::string& id, const std::string& text, const std::string& source, const std::string& paper,
                 const Json* edge, const std::string& field, int decimals, const std::string& missing,
                 const std::string& ka = "iaco-han", const std::string& kb = "aco") {
    Claim c;
    c.id = id;
    c.text = text;
    c.source = source;
    c.paper = paper;
    if (edge == nullptr) {
      c.ours = "—";
      c.verdict = Verdict::untestable;
      c.note = missing;
      return c;
    }
    const Json& a = at_or_null(*edge, {"variants", ka, field});
    const Json& b = at_or_null(*edge, {"variants", kb, field});
    c.ours = md_number(a, decimals) + " vs " + md_number(b, decimals);
    if (!a.is_number() || !b.is_number()) {
      c.verdict = Verdict::untestable;
      c.note = "undefined for a planner (not available, or no path on some map)";
      return c;
    }
    c.rule = "IACO-A* strictly smaller (mean over the edge's maps)";
    c.verdict = a.get<double>() < b.get<double>() ? Verdict::holds : Verdict::fails;
    return c;
  };
  const std::string no10 = "no 10 m maps in this run (--edges)";
  const std::string no100 = "no 100 m maps in this run (--quick or --edges)";
  claims.push_back(less("H.1", "IACO-A* converges in fewer iterations than ACO (10 m map)",
                        "§IV, Fig. 10; abstract", "8 vs 37", e10, "converged_at", 2, no10));
  claims.push_back(less("H.2", "IACO-A*'s minimum path length after convergence is shorter than ACO's (10 m map)",
                        "§IV, Fig. 10; abstract", "13.24 m vs 17.82 m", e10, "min_length", 4, no10));
  claims.push_back(less("H.3", "IACO-A*'s minimum planning length has a smaller standard deviation than ACO's (10 m map)",
                        "§IV, Fig. 11", "0.82 m vs 1.24 m", e10, "std_length", 4, no10));
  claims.push_back(less("H.4", "at edge 100 m IACO-A*'s minimum planning length is shorter than ACO's",
                        "§IV, Fig. 12(a); abstract", "49 m vs 104 m", e100, "min_length", 4, no100));
  for (const auto& [id, text, field, d] :
       {std::tuple{std::string("H.1d"), std::string("as H.1 under the planners' default dead_end = die"), std::string("converged_at"), 2},
        std::tuple{std::string("H.2d"), std::string("as H.2 under dead_end = die"), std::string("min_length"), 4},
        std::tuple{std::string("H.3d"), std::string("as H.3 under dead_end = die"), std::string("std_length"), 4}}) {
    Claim c = less(id, text, "§IV, Figs. 10, 11 (the other dead-end reading, reproduce.han.protocol)",
                   id == "H.1d" ? "8 vs 37" : id == "H.2d" ? "13.24 m vs 17.82 m" : "0.82 m vs 1.24 m", e10, field, d,
                   no10, "iaco-han@die", "aco@die");
    claims.push_back(c);
  }
  {
    Claim c = less("H.5", "at edge 100 m IACO-A*'s total moving time is shorter than ACO's",
                   "§IV, Fig. 12(b); abstract", "49 s vs 142 s", e100, "travel_time_s", 2, no100);
    c.note = (c.note.empty() ? "" : c.note + "; ") +
             std::string("time = minimum length / 1 m/s without dynamic obstacles (waits and the 1 m/s² restarts "
                         "of §IV are not simulated here; `pathref simulate` runs them)");
    claims.push_back(c);
  }
  for (const auto& [id, text, field, d] :
       {std::tuple{std::string("H.1g"), std::string("as H.1 with η = 1/(d_ij + d_jE)"), std::string("converged_at"), 2},
        std::tuple{std::string("H.2g"), std::string("as H.2 with η = 1/(d_ij + d_jE)"), std::string("min_length"), 4},
        std::tuple{std::string("H.3g"), std::string("as H.3 with η = 1/(d_ij + d_jE)"), std::string("std_length"), 4}})
    claims.push_back(less(id, text, "§IV, Figs. 10, 11 (the other reading of η, reproduce.han.protocol)",
                          id == "H.1g" ? "8 vs 37" : id == "H.2g" ? "13.24 m vs 17.82 m" : "0.82 m vs 1.24 m", e10,
                          field, d, no10, "iaco-han:goal", "aco"));
  claims.push_back(less("H.4g", "as H.4 with η = 1/(d_ij + d_jE)", "§IV, Fig. 12(a) (the other reading of η)",
                        "49 m vs 104 m", e100, "min_length", 4, no100, "iaco-han:goal", "aco"));
  for (const std::string ka : {"iaco-han", "iaco-han:goal"}) {
    Claim c;
    c.id = ka == "iaco-han" ? "H.6" : "H.6g";
    c.text = ka == "iaco-han" ? "regardless of the map size, IACO-A*'s minimum path length is smaller than ACO's"
                              : "as H.6 with η = 1/(d_ij + d_jE)";
    c.source = "§IV, Fig. 12; conclusion";
    c.paper = "at every edge";
    std::int64_t tested = 0, ok = 0;
    std::string failed;
    for (const Json& e : doc["edges"]) {
      const Json& a = at_or_null(e, {"variants", ka, "min_length"});
      const Json& b = at_or_null(e, {"variants", "aco", "min_length"});
      if (!a.is_number() || !b.is_number()) continue;
      ++tested;
      if (a.get<double>() < b.get<double>()) ++ok;
      else failed += (failed.empty() ? "" : ", ") + std::to_string(e.at("edge").get<std::int64_t>());
    }
    c.ours = fmt::format("smaller at {} of {} edges", ok, tested);
    if (tested == 0) {
      c.verdict = Verdict::untestable;
      c.note = "no edge where both planners found paths on every map";
    } else {
      c.rule = "strictly smaller at every edge where both are defined";
      c.verdict = ok == tested ? Verdict::holds : Verdict::fails;
      if (!failed.empty()) c.note = "not smaller at edge(s) " + failed;
    }
    claims.push_back(c);
  }
  // The printed absolute numbers: maps not published.
  const std::vector<std::tuple<std::string, std::string, std::string, const Json*, std::string, int>> absolute = {
      {"A.1", "IACO-A* converges after 8 iterations, ACO after 37", "8, 37", e10, "converged_at", 2},
      {"A.2", "minimum path lengths after convergence 13.24 m (IACO-A*), 17.82 m (ACO)", "13.24, 17.82", e10,
       "min_length", 4},
      {"A.3", "standard deviations of the minimum planning length 0.82 m (IACO-A*), 1.24 m (ACO)", "0.82, 1.24", e10,
       "std_length", 4},
      {"A.4", "at edge 100 m: minimum planning length 49 m (IACO-A*), 104 m (ACO)", "49, 104", e100, "min_length", 4},
      {"A.5", "at edge 100 m: total moving time 49 s (IACO-A*), 142 s (ACO)", "49, 142", e100, "travel_time_s", 2},
  };
  for (const auto& [id, text, paper, edge, field, d] : absolute) {
    Claim c;
    c.id = id;
    c.text = text;
    c.source = id == "A.3" ? "§IV, Fig. 11" : (id == "A.1" || id == "A.2") ? "§IV, Fig. 10; abstract" : "§IV, Fig. 12; abstract";
    c.paper = paper;
    c.ours = edge == nullptr ? "—"
                             : md_number(at_or_null(*edge, {"variants", "iaco-han", field}), d) + ", " +
                                   md_number(at_or_null(*edge, {"variants", "aco", field}), d);
    c.verdict = Verdict::untestable;
    c.note = "the paper's random maps (and their start, goal and dynamic obstacles) are not published; only the "
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

std::vector<io::Series> edge_series(const Json& doc, const std::vector<std::pair<std::string, std::string>>& what) {
  std::vector<io::Series> out;
  for (const auto& [key, field] : what) {
    io::Series s;
    s.label = key == "iaco-han"        ? "IACO-A*, η = 1/d"
              : key == "iaco-han:goal" ? "IACO-A*, η = 1/(d + d_goal)"
              : key == "aco"           ? "ACO (Table I)"
              : key == "astar-han"     ? "A* (optimum)"
                                       : key;
    for (const Json& e : doc.at("edges")) {
      s.x.push_back(e.at("edge").get<double>());
      const Json& y = at_or_null(e, {"variants", key, field});
      s.y.push_back(y.is_number() ? y.get<double>() : std::numeric_limits<double>::infinity());
    }
    out.push_back(s);
  }
  return out;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> han_figures(const Json& doc) {
  std::vector<std::pair<std::string, std::string>> figs;
  figs.emplace_back("length-vs-edge.svg",
                    io::svg_line_chart(edge_series(doc, {{"iaco-han", "min_length"}, {"iaco-han:goal", "min_length"},
                                                         {"aco", "min_length"}, {"astar-han", "min_length"}}),
                                       io::ChartOptions{"minimum path length against map edge (cf. Fig. 12(a))",
                                                        "map edge (m)", "minimum path length (m)"}));
  figs.emplace_back("time-vs-edge.svg",
                    io::svg_line_chart(edge_series(doc, {{"iaco-han", "travel_time_s"}, {"aco", "travel_time_s"},
                                                         {"astar-han", "travel_time_s"}}),
                                       io::ChartOptions{"moving time at 1 m/s, no moving obstacles (cf. Fig. 12(b))",
                                                        "map edge (m)", "moving time (s)"}));
  figs.emplace_back("planning-time-vs-edge.svg",
                    io::svg_line_chart(edge_series(doc, {{"iaco-han", "wall_ms"}, {"aco", "wall_ms"},
                                                         {"astar-han", "wall_ms"}}),
                                       io::ChartOptions{"planner wall-clock time per run (a measurement)",
                                                        "map edge (m)", "wall time (ms)"}));
  // Convergence on the 10 m maps (cf. Fig. 10): mean best-so-far of the first 10 m map.
  for (const Json& m : doc.at("maps")) {
    if (m.at("edge").get<std::int64_t>() != 10) continue;
    std::vector<io::Series> series;
    for (const std::string key : {"iaco-han", "iaco-han:goal", "aco"}) {
      const Json& c = at_or_null(m, {"results", key, "mean_best_curve"});
      if (!c.is_array()) continue;
      io::Series s;
      s.label = key == "iaco-han" ? "IACO-A*, η = 1/d" : key == "aco" ? "ACO" : "IACO-A*, η = 1/(d + d_goal)";
      for (std::size_t i = 0; i < c.size(); ++i) {
        s.x.push_back(static_cast<double>(i + 1));
        s.y.push_back(c[i].is_number() ? c[i].get<double>() : std::numeric_limits<double>::infinity());
      }
      series.push_back(s);
    }
    figs.emplace_back("convergence-10m.svg",
                      io::svg_line_chart(series, io::ChartOptions{fmt::format("10 m map (ratio {}, seed {}): best length (cf. Fig. 10)",
                                                                              fixed(m.at("ratio").get<double>(), 2),
                                                                              m.at("map_seed").get<std::int64_t>()),
                                                                  "iteration", "path length (m)"}));
    std::vector<io::PathLayer> layers;
    for (const std::string key : {"iaco-han", "iaco-han:goal", "aco", "astar-han"}) {
      const Json& best = at_or_null(m, {"results", key, "best"});
      if (!best.is_object() || !best.contains("path")) continue;
      layers.push_back(io::PathLayer{fmt::format("{} (length {})", key == "iaco-han:goal" ? "IACO-A*, η = 1/(d + d_goal)" : key == "iaco-han" ? "IACO-A*, η = 1/d" : planner_label(key),
                                                 md_number(best.at("length"), 2)),
                                     grid::path_from_json(best.at("path"))});
    }
    figs.emplace_back("paths-10m.svg",
                      io::svg_map(grid::grid_from_json(m.at("rows")), grid::cell_from_json(m.at("start")),
                                  grid::cell_from_json(m.at("goal")), layers,
                                  "10 m random map: best paths (cf. Fig. 7)"));
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
  s += fmt::format("- runs: {} per stochastic planner on each 10 m map (Figures 10, 11), {} on each map of the other "
                   "edges (Figure 12); run seeds {} + r; A* once. Corner policy `{}`.\n",
                   p.at("runs_10m").get<std::int64_t>(), p.at("sweep_runs").get<std::int64_t>(),
                   p.at("seed").get<std::int64_t>(), p.at("policy").get<std::string>());
  s += "- planners (the exact parameters are in the JSON, `maps[i].results.KEY.params_used`):\n";
  for (const Json& v : p.at("variants"))
    s += fmt::format("  - `{}`: {} — overrides {}\n", v.at("key").get<std::string>(), v.at("label").get<std::string>(),
                     v.at("params").dump());
  s += "- IACO-A* without moving obstacles is its global planner `iaco-han` (the registered `iaco-astar` returns the "
       "same path); the dynamic-obstacle part is not part of this reproduction.\n";
  s += "- statistics: per map, the minimum / mean / **sample** standard deviation (n − 1) of the lengths of the runs "
       "that found a path; per edge, the mean over its maps (minimum length only when every map has a path); "
       "iterations to converge = metrics.converge, pooled over the edge's runs; moving time = minimum length / "
       "1 m/s.\n\n";
  s += "## 10 m maps (Figures 10, 11)\n\n";
  s += md_row({"map", "ratio", "map seed", "variant", "runs", "found", "min length", "mean length", "std length",
               "mean iter. to converge", "A* length"});
  s += md_row({"---", "---:", "---:", "---", "---:", "---:", "---:", "---:", "---:", "---:", "---:"});
  int mi = 0;
  for (const Json& m : doc.at("maps")) {
    ++mi;
    if (m.at("edge").get<std::int64_t>() != 10) continue;
    for (const auto& v : han_variants()) {
      if (v.planner == "astar" || v.planner == "astar-han") continue;
      const Json& r = m.at("results").at(v.key);
      if (!r.value("available", false)) {
        s += md_row({std::to_string(mi), fixed(m.at("ratio").get<double>(), 2), std::to_string(m.at("map_seed").get<std::int64_t>()),
                     "`" + v.key + "`", "not available", "", "", "", "", "", ""});
        continue;
      }
      const Json& sm = r.at("summary");
      s += md_row({std::to_string(mi), fixed(m.at("ratio").get<double>(), 2),
                   std::to_string(m.at("map_seed").get<std::int64_t>()), "`" + v.key + "`",
                   std::to_string(sm.at("runs").get<std::int64_t>()), std::to_string(sm.at("found").get<std::int64_t>()),
                   md_number(sm.at("length").at("min"), 4), md_number(sm.at("length").at("mean"), 4),
                   md_number(sm.at("length").at("std"), 4), md_number(sm.at("converged_at").at("mean"), 2),
                   md_number(at_or_null(m, {"results", "astar-han", "summary", "length", "min"}), 4)});
    }
  }
  s += fmt::format("\n![convergence on a 10 m map]({0}/convergence-10m.svg)\n\n![paths on a 10 m map]({0}/paths-10m.svg)\n\n",
                   figure_dir);
  s += "## Path length and time against the map edge (Figure 12)\n\n<!-- results:edges -->\n";
  s += md_row({"edge (m)", "IACO-A* min length", "ACO min length", "A* length", "IACO-A* moving time (s)",
               "ACO moving time (s)", "IACO-A* found", "ACO found", "IACO-A* found (die)", "ACO found (die)",
               "IACO-A* iter.", "ACO iter.", "IACO-A* wall (ms)", "ACO wall (ms)", "IACO-A* goal η min length",
               "IACO-A* goal η iter."});
  s += md_row({"---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:",
               "---:", "---:", "---:"});
  for (const Json& e : doc.at("edges")) {
    const Json& v = e.at("variants");
    auto found = [&](const std::string& k) {
      return fmt::format("{}/{}", v.at(k).at("found").get<std::int64_t>(), v.at(k).at("runs").get<std::int64_t>());
    };
    s += md_row({std::to_string(e.at("edge").get<std::int64_t>()), md_number(v.at("iaco-han").at("min_length"), 4),
                 md_number(v.at("aco").at("min_length"), 4), md_number(v.at("astar-han").at("min_length"), 4),
                 md_number(v.at("iaco-han").at("travel_time_s"), 2), md_number(v.at("aco").at("travel_time_s"), 2),
                 found("iaco-han"), found("aco"), found("iaco-han@die"), found("aco@die"),
                 md_number(v.at("iaco-han").at("converged_at"), 2), md_number(v.at("aco").at("converged_at"), 2),
                 md_number(v.at("iaco-han").at("wall_ms"), 1), md_number(v.at("aco").at("wall_ms"), 1),
                 md_number(v.at("iaco-han:goal").at("min_length"), 4),
                 md_number(v.at("iaco-han:goal").at("converged_at"), 2)});
  }
  s += fmt::format("\n![length against edge]({0}/length-vs-edge.svg)\n\n![time against edge]({0}/time-vs-edge.svg)\n\n"
                   "![planning time against edge]({0}/planning-time-vs-edge.svg)\n\n",
                   figure_dir);
  s += "## Claims\n\n" + md_claims(doc.at("claims")) + "\n";
  s += "## Provenance\n\n" + md_provenance(doc.at("provenance"), json_name);
  return s;
}

}  // namespace pathref::reproduce
