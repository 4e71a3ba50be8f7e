// `pathref reproduce cin2021-srrt` (spec/reproduce.md r[reproduce.cin2021-srrt.scenes],
// r[reproduce.cin2021-srrt.protocol]): Cin et al. 2021 Sec. 4.3, RRT vs S-RRT.
// Lives in pathref_geometry because it needs ObstacleMap's exact collision test; CGAL-free itself.
#include <fmt/core.h>

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "pathref/io/scene_json.hpp"
#include "pathref/continuous/srrt.hpp"
#include "pathref/core/error.hpp"
#include "pathref/geometry/obstacles.hpp"
#include "pathref/geometry/scene.hpp"
#include "pathref/io/svg.hpp"
#include "pathref/io/svg_continuous.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/reproduce/cin2021_srrt.hpp"
#include "pathref/reproduce/stats.hpp"

namespace pathref::reproduce {

namespace {

using continuous::Vec2;

std::string scene_text(const std::string& name, const std::vector<std::array<int, 4>>& rects) {
  std::string polys;
  for (const auto& r : rects)
    polys += fmt::format("{}{{\"vertices\": [[{}, {}], [{}, {}], [{}, {}], [{}, {}]]}}", polys.empty() ? "" : ", ", r[0],
                         r[2], r[1], r[2], r[1], r[3], r[0], r[3]);
  return fmt::format(
      "{{\"format\": \"pathref-scene 1\", \"name\": \"{}\", \"origin\": [0, 0], \"width\": 20, \"height\": 20, "
      "\"cell_size\": 1, \"radius\": 0, \"margin\": 0, \"polygons\": [{}], \"start\": [1, 1], \"goal\": [18, 18]}}\n",
      name, polys);
}

/// One series of the protocol: key, label, planner, overrides (reproduce.cin2021-srrt.protocol).
struct SeriesSpec {
  std::string key;
  std::string label;
  std::string algo;
  Json overrides;
};
const std::vector<SeriesSpec>& series_specs() {
  static const std::vector<SeriesSpec> s{
      {"s-rrt", "S-RRT", "s-rrt", Json::object()},
      {"rrt", "RRT (traditional, no goal bias)", "rrt", Json{{"variant", "plain"}}},
      {"rrt-alg1", "RRT (Algorithm 1 alone)", "rrt", Json::object()},
      {"s-rrt@gt", "S-RRT, bias=gt", "s-rrt", Json{{"bias", "gt"}}},
      {"rrt-alg1@gt", "RRT (Algorithm 1 alone), bias=gt", "rrt", Json{{"bias", "gt"}}},
  };
  return s;
}

Json fin(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

/// True iff every segment of `pts` is free.
bool path_free(const geometry::ObstacleMap& map, const std::vector<Vec2>& pts) {
  for (std::size_t i = 1; i < pts.size(); ++i)
    if (!map.segment_free(pts[i - 1], pts[i])) return false;
  return pts.empty() || map.point_free(pts.front());
}

/// The record of one run (reproduce.cin2021-srrt.protocol "Quantities").
Json run_record(const continuous::ContinuousRun& r, std::uint32_t seed, bool srrt, bool valid) {
  Json j{{"seed", seed},
         {"found", r.tree.found},
         {"iterations", r.tree.iterations},
         {"tree_size", r.tree.nodes.size()},
         {"time_ms", r.time_ms}};
  if (!r.tree.found) return j;
  const continuous::PathMetrics& m = srrt ? r.shortcut_metrics : r.raw_metrics;
  j["length"] = m.length;
  j["nodes"] = m.nodes;
  j["turning"] = m.turning;
  j["clearance"] = fin(m.clearance);
  j["valid"] = valid;
  if (srrt) {
    j["raw_length"] = r.raw_metrics.length;
    j["raw_nodes"] = r.raw_metrics.nodes;
    if (r.curve) {
      const continuous::CurveResult& c = *r.curve;
      j["curve_length"] = c.length;
      j["curve_turning"] = continuous::total_turning(c.samples.points);
      j["curve_max_curvature"] = fin(c.max_curvature);
      j["curve_degree"] = c.degree;
      j["curve_clearance"] = fin(c.clearance.distance);
      j["curve_verdict"] = std::string(geometry::to_string(c.clearance.verdict));
      j["curve_ms"] = r.curve_ms;
    }
  }
  return j;
}

/// Values of `key` of the found runs among the first `limit` runs (null values skipped).
std::vector<double> column(const Json& runs, const std::string& key, std::size_t limit) {
  std::vector<double> out;
  for (std::size_t i = 0; i < limit && i < runs.size(); ++i)
    if (runs[i].at("found").get<bool>() && runs[i].contains(key) && runs[i].at(key).is_number())
      out.push_back(runs[i].at(key).get<double>());
  return out;
}

/// The claimed quantities: id part, claim text, source, S-RRT's key (default reading), RRT's key,
/// S-RRT's key under srrt_path = nodes ("" when the reading does not change it), decimals.
struct Quantity4 {
  const char* id;
  const char* what;
  const char* source;
  const char* srrt_key;
  const char* rrt_key;
  const char* srrt_nodes_key;
  int decimals;
};
constexpr Quantity4 kQuantities[] = {
    {"length", "a shorter path", "§4.3, Table 2 (path length; values lost)", "curve_length", "length", "length", 4},
    {"nodes", "fewer path nodes", "§4.3, Table 2 (path nodes; values lost)", "nodes", "nodes", "", 2},
    {"smooth", "a smoother path (less total turning, rad)", "§4.3 (\"the paths are smoother\"), Figure 5",
     "curve_turning", "turning", "turning", 4},
    {"time", "a shorter running time (ms)", "Table 2 (running time; values lost), §6 (\"improve the search efficiency\")",
     "time_ms", "time_ms", "", 3},
};

/// One reading of the comparison (suffix of the claim id).
struct Reading {
  std::string suffix;  ///< "" (default), "@alg1", "@gt", "@alg1+gt", "@nodes"
  std::string srrt;    ///< S-RRT's series
  std::string rrt;     ///< RRT's series
  bool nodes = false;  ///< srrt_path = nodes
  std::string words;   ///< what it is
};
const std::vector<Reading>& readings() {
  static const std::vector<Reading> r{
      {"", "s-rrt", "rrt", false, "default readings: RRT = traditional RRT, bias = lt, S-RRT's path = its curve"},
      {"@alg1", "s-rrt", "rrt-alg1", false, "RRT = Algorithm 1 alone"},
      {"@gt", "s-rrt@gt", "rrt", false, "bias = gt (S-RRT's goal branch taken when p > P_g)"},
      {"@alg1+gt", "s-rrt@gt", "rrt-alg1@gt", false, "RRT = Algorithm 1 alone and bias = gt"},
      {"@nodes", "s-rrt", "rrt", true, "S-RRT's path = its kept nodes (Algorithm 2's polyline), not the curve"},
  };
  return r;
}

Claim srrt_claim(const std::string& scene, const Quantity4& q, const Reading& rd, const Json& per_series,
                 std::size_t n) {
  Claim c;
  c.id = scene + "." + q.id + rd.suffix;
  const Json& a = per_series.at(rd.srrt);
  const Json& b = per_series.at(rd.rrt);
  c.text = fmt::format("scene {}: {} gives {} than {}{}", scene, a.at("label").get<std::string>(), q.what,
                       b.at("label").get<std::string>(), rd.suffix.empty() ? "" : " [reading " + rd.suffix.substr(1) + "]");
  c.source = q.source;
  c.paper = "S-RRT < RRT (Table 2's numbers are lost)";
  const std::string a_key = rd.nodes ? q.srrt_nodes_key : q.srrt_key;
  const auto& ra = a.at("runs");
  const auto& rb = b.at("runs");
  comparison_claim(c, column(ra, a_key, n), column(rb, q.rrt_key, n), column(ra, a_key, 2 * n),
                   column(rb, q.rrt_key, 2 * n), Claimed::a_less, q.decimals);
  c.rule += fmt::format("; S-RRT's `{}` vs RRT's `{}` over the runs that found a path", a_key, q.rrt_key);
  if (std::string(q.id) == "time")
    c.note = "wall-clock times of this machine: not reproducible bit for bit; S-RRT's time is Algorithms 1 + 2 "
             "(its curve and pathref's check of it are timed apart as curve_ms)";
  if (rd.suffix.empty()) {
    std::string alts;
    for (const Reading& o : readings())
      if (!o.suffix.empty() && (!o.nodes || q.srrt_nodes_key[0] != '\0')) alts += (alts.empty() ? "" : ", ") + c.id + o.suffix;
    c.depends_on.push_back(std::string("readings RRT = traditional RRT, bias = lt") +
                           (q.srrt_nodes_key[0] != '\0' ? ", S-RRT's path = its curve" : "") + " (alternatives: " + alts + ")");
    c.depends_on.push_back("scenes rebuilt by pathref (Figure 5's are lost)");
  } else {
    c.depends_on.push_back("reading " + rd.words + " (the alternative of " + scene + "." + q.id + ")");
  }
  return c;
}

/// Counts per value of a string field over the found runs (first `limit`).
Json count_field(const Json& runs, const char* key, std::size_t limit) {
  std::map<std::string, std::int64_t> m;
  for (std::size_t i = 0; i < limit && i < runs.size(); ++i)
    if (runs[i].at("found").get<bool>() && runs[i].contains(key)) ++m[runs[i].at(key).get<std::string>()];
  Json j = Json::object();
  for (const auto& [k, v] : m) j[k] = v;
  return j;
}

Claim check_claim(const std::string& id, const std::string& text, bool ok, const std::string& ours) {
  Claim c;
  c.id = id;
  c.text = text;
  c.source = "pathref";
  c.paper = "—";
  c.ours = ours;
  c.rule = "holds iff true for every run (reproduce.cin2021-srrt.protocol, checks)";
  c.verdict = ok ? Verdict::holds : Verdict::fails;
  return c;
}

}  // namespace

std::vector<SrrtScene> cin2021_srrt_scenes() {
  const Vec2 s{1.5, 1.5}, g{18.5, 18.5};
  return {
      {"A", "three separate blocks between start and goal",
       scene_text("cin2021-srrt-A", {{4, 8, 3, 9}, {10, 14, 10, 16}, {13, 18, 2, 7}}), s, g},
      {"B", "two long walls from opposite sides (an S-shaped passage)",
       scene_text("cin2021-srrt-B", {{6, 8, 0, 14}, {12, 14, 6, 20}}), s, g},
      {"C", "eight scattered rectangles (cluttered)",
       scene_text("cin2021-srrt-C", {{3, 5, 3, 7}, {7, 10, 1, 4}, {7, 9, 7, 12}, {11, 14, 4, 7}, {12, 16, 9, 11},
                                     {3, 6, 10, 13}, {9, 12, 14, 17}, {15, 17, 13, 18}}),
       s, g},
  };
}

SrrtReproduction reproduce_cin2021_srrt(const SrrtReproduceOptions& o) {
  require(o.runs >= 2 && o.runs <= 1000, "cin2021-srrt: runs must be in [2, 1000]");
  require(static_cast<std::uint64_t>(o.seed) + 2 * static_cast<std::uint64_t>(o.runs) - 1 <= 4294967295ULL,
          "cin2021-srrt: seed + 2 runs - 1 must not exceed 4294967295");
  const auto t_start = std::chrono::steady_clock::now();
  const auto n = static_cast<std::size_t>(o.runs);
  const std::size_t n2 = 2 * n;
  SrrtReproduction out;
  Json scenes = Json::array(), claims = Json::array(), reading_claims = Json::array();
  bool all_valid = true, same_tree_lt = true, same_tree_gt = true;
  std::int64_t checked_paths = 0;
  Json protocol_series = Json::object();
  for (const SrrtScene& sc : cin2021_srrt_scenes()) {
    const geometry::Scene scene = io::parse_scene_json(sc.scene_json, "scene-" + sc.id + ".json");
    const geometry::ObstacleMap map = geometry::ObstacleMap::from_scene(scene);
    out.files.emplace_back("scene-" + sc.id + ".json", sc.scene_json);
    Json per_series = Json::object();
    for (const SeriesSpec& p : series_specs()) {
      const Json merged = planners::merge_params(continuous::continuous_defaults(p.algo), p.overrides);
      const bool srrt = p.algo == "s-rrt";
      Json runs = Json::array();
      for (std::size_t i = 0; i < n2; ++i) {
        const auto seed = static_cast<std::uint32_t>(o.seed + i);
        const continuous::ContinuousRun r = continuous::run_continuous(p.algo, map, sc.start, sc.goal, merged, seed);
        bool valid = true;
        if (r.tree.found) {
          valid = path_free(map, r.raw) && (!srrt || path_free(map, r.shortcut_path));
          ++checked_paths;
          all_valid = all_valid && valid;
        }
        runs.push_back(run_record(r, seed, srrt, valid));
      }
      Json summary = Json::object();
      std::vector<std::string> keys{"length", "nodes", "turning", "clearance", "time_ms", "tree_size", "iterations"};
      if (srrt)
        for (const char* k : {"curve_length", "curve_turning", "curve_max_curvature", "curve_clearance", "curve_ms"})
          keys.emplace_back(k);
      std::size_t found_n = 0, found_2n = 0;
      for (std::size_t i = 0; i < n2; ++i)
        if (runs[i].at("found").get<bool>()) (i < n ? found_n : found_2n) += 1;
      for (const auto& k : keys) summary[k] = summary_stats_json(summarize(column(runs, k, n)));
      Json s{{"label", p.label},
             {"algo", p.algo},
             {"requested", p.overrides},
             {"params_used", merged},
             {"found_n", found_n},
             {"found_2n", found_n + found_2n},
             {"summary_n", summary},
             {"runs", runs}};
      if (srrt) s["curve_verdicts_n"] = count_field(runs, "curve_verdict", n);
      per_series[p.key] = std::move(s);
      protocol_series[p.key] = Json{{"label", p.label}, {"algo", p.algo}, {"requested", p.overrides}};
      if (o.progress)
        o.progress(fmt::format("cin2021-srrt scene {}: {} x{} done ({} of the first {} found a path)", sc.id, p.key, n2,
                               found_n, n));
    }
    for (std::size_t i = 0; i < n2; ++i) {
      const auto same = [&](const char* a, const char* b) {
        const Json& x = per_series[a]["runs"][i];
        const Json& y = per_series[b]["runs"][i];
        return x["found"] == y["found"] && x["tree_size"] == y["tree_size"] && x["iterations"] == y["iterations"];
      };
      same_tree_lt = same_tree_lt && same("s-rrt", "rrt-alg1");
      same_tree_gt = same_tree_gt && same("s-rrt@gt", "rrt-alg1@gt");
    }
    for (const Quantity4& q : kQuantities)
      for (const Reading& rd : readings()) {
        if (rd.nodes && q.srrt_nodes_key[0] == '\0') continue;
        const Claim c = srrt_claim(sc.id, q, rd, per_series, n);
        (rd.suffix.empty() ? claims : reading_claims).push_back(claim_json(c));
      }
    scenes.push_back(Json{{"id", sc.id},
                          {"description", sc.description},
                          {"file", "scene-" + sc.id + ".json"},
                          {"scene", Json::parse(sc.scene_json)},
                          {"start", Json::array({sc.start.x, sc.start.y})},
                          {"goal", Json::array({sc.goal.x, sc.goal.y})},
                          {"series", per_series}});
  }
  Json checks = Json::array();
  checks.push_back(claim_json(check_claim("K.1", "every returned path (RRT's branch, S-RRT's kept nodes) is collision-free under the exact test",
                                          all_valid, fmt::format("{} paths checked", checked_paths))));
  checks.push_back(claim_json(check_claim("K.2", "`s-rrt` and `rrt-alg1` grow the same tree for every seed and scene",
                                          same_tree_lt, same_tree_lt ? "same tree size and iterations on every run" : "a run differs")));
  checks.push_back(claim_json(check_claim("K.3", "`s-rrt@gt` and `rrt-alg1@gt` grow the same tree for every seed and scene",
                                          same_tree_gt, same_tree_gt ? "same tree size and iterations on every run" : "a run differs")));
  Json readings_json = Json::array();
  for (const Reading& rd : readings())
    readings_json.push_back(Json{{"suffix", rd.suffix}, {"srrt", rd.srrt}, {"rrt", rd.rrt}, {"srrt_path", rd.nodes ? "nodes" : "curve"},
                                 {"description", rd.words}});
  out.doc = Json{{"format", "pathref-reproduce"},
                 {"format_version", 1},
                 {"paper", "cin2021"},
                 {"experiment", "cin2021-srrt"},
                 {"reference", "Cin et al. 2021, Computational Intelligence and Neuroscience, article 8025730, Sec. 4.3, "
                               "doi:10.1155/2021/8025730"},
                 {"protocol", Json{{"world", "[0, 20] x [0, 20], axis-aligned rectangles, r = 0 (a point robot)"},
                                   {"delta", 1.7},
                                   {"goal_probability", 0.6},
                                   {"runs_n", n},
                                   {"runs_2n", n2},
                                   {"seed", o.seed},
                                   {"seeds", fmt::format("run i uses seed {} + i, i = 0 .. {}, for every series and scene",
                                                         o.seed, n2 - 1)},
                                   {"series", protocol_series},
                                   {"readings", readings_json},
                                   {"scenes_rebuilt", true}}},
                 {"provenance", provenance_json(o.provenance)},
                 {"scenes", scenes},
                 {"claims", claims},
                 {"reading_claims", reading_claims},
                 {"checks", checks}};
  // Every verdict rests on the reconstructed S-RRT (attach_rules; reproduce.markdown).
  const auto srrt_rules = [](const std::string&) {
    return std::vector<std::string>{"cin2021.srrt.collision", "cin2021.srrt.nearest", "cin2021.srrt.steer",
                                    "cin2021.alg1", "cin2021.alg2", "cin2021.srrt.metrics"};
  };
  for (const char* k : {"claims", "reading_claims", "checks"}) attach_rules_all(out.doc[k], srrt_rules);
  out.doc["provenance"]["total_wall_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  for (auto& f : cin2021_srrt_figures(out.doc)) out.files.push_back(std::move(f));
  return out;
}

std::vector<std::pair<std::string, std::string>> cin2021_srrt_figures(const Json& doc) {
  std::vector<std::pair<std::string, std::string>> out;
  // Each scene's first S-RRT and RRT run, run again from its recorded seed (deterministic).
  for (const SrrtScene& sc : cin2021_srrt_scenes()) {
    const Json* scene_doc = nullptr;
    for (const Json& s : doc.at("scenes"))
      if (s.at("id").get<std::string>() == sc.id) scene_doc = &s;
    if (scene_doc == nullptr) continue;
    const geometry::Scene scene = io::parse_scene_json(sc.scene_json, "scene-" + sc.id + ".json");
    const geometry::ObstacleMap map = geometry::ObstacleMap::from_scene(scene);
    const io::ContinuousScene cs{map.polygons(), map.radius(), map.lower(), map.upper()};
    for (const SeriesSpec& p : series_specs()) {
      if (p.key != "s-rrt" && p.key != "rrt") continue;
      const Json& runs = scene_doc->at("series").at(p.key).at("runs");
      if (runs.empty()) continue;
      const auto seed = runs[0].at("seed").get<std::uint32_t>();
      const Json merged = planners::merge_params(continuous::continuous_defaults(p.algo), p.overrides);
      const continuous::ContinuousRun r = continuous::run_continuous(p.algo, map, sc.start, sc.goal, merged, seed);
      out.emplace_back(fmt::format("{}-{}.svg", sc.id, p.key),
                       io::svg_continuous(cs, r, sc.start, sc.goal, fmt::format("scene {}: {}, seed {}", sc.id, p.label, seed)));
    }
  }
  const auto n = doc.at("protocol").at("runs_n").get<std::size_t>();
  // Figure 6's analogue: per run, S-RRT and RRT on every scene (first n runs; gaps where no path).
  struct Fig {
    const char* file;
    const char* srrt_key;
    const char* rrt_key;
    const char* title;
    const char* y;
  };
  for (const Fig& f : {Fig{"length.svg", "curve_length", "length", "Figure 6 analogue: path length per run (S-RRT: its curve)", "length"},
                       Fig{"nodes.svg", "nodes", "nodes", "Figure 6 analogue: path nodes per run", "nodes"},
                       Fig{"time.svg", "time_ms", "time_ms", "running time per run (ms, this machine)", "time (ms)"}}) {
    std::vector<io::Series> series;
    for (const Json& s : doc.at("scenes"))
      for (const auto& [key, field] : {std::pair<const char*, const char*>{"s-rrt", f.srrt_key}, {"rrt", f.rrt_key}}) {
        io::Series se{fmt::format("{} {}", s.at("id").get<std::string>(), std::string(key) == "s-rrt" ? "S-RRT" : "RRT"), {}, {}};
        const Json& runs = s.at("series").at(key).at("runs");
        for (std::size_t i = 0; i < n; ++i) {
          se.x.push_back(static_cast<double>(i + 1));
          se.y.push_back(runs[i].at("found").get<bool>() && runs[i].contains(field) && runs[i].at(field).is_number()
                             ? runs[i].at(field).get<double>()
                             : std::numeric_limits<double>::quiet_NaN());
        }
        series.push_back(std::move(se));
      }
    out.emplace_back(f.file, io::svg_line_chart(series, io::ChartOptions{f.title, "run", f.y, "",
                                                                         "A line is broken at runs that found no path."}));
  }
  return out;
}

namespace {

std::string stat_cell(const Json& st, int d) {
  if (!st.is_object() || !st["mean"].is_number()) return "—";
  return fmt::format("{} ± {} [{}, {}]", md_number(st["mean"], d), md_number(st["std"], d), md_number(st["min"], d),
                     md_number(st["max"], d));
}

}  // namespace

std::string cin2021_srrt_markdown(const Json& doc, const std::string& figure_dir, const std::string& json_name) {
  const Json& pr = doc.at("protocol");
  const auto n = pr.at("runs_n").get<std::int64_t>();
  std::string s;
  s += "# Reproduction: Cin et al. 2021, S-RRT against RRT (§4.3)\n\n";
  s += "Paper: *Computational Intelligence and Neuroscience* 2021, article 8025730, §4.3 and Table 2, "
       "doi:10.1155/2021/8025730 (spec/cin2021-srrt.md; protocol: spec/reproduce.md "
       "r[reproduce.cin2021-srrt.scenes], r[reproduce.cin2021-srrt.protocol]). Command: `" +
       doc.at("provenance").value("command", std::string()) + "`.\n\n";
  if (n < 20)
    s += fmt::format("**QUICK RUN ({} runs per series and scene, not the paper's 20): its numbers are not a "
                     "reproduction.**\n\n", n);
  s += "**What the paper gives**: a 20 × 20 state space with black rectangles as obstacles, fixed step δ = 1.7, "
       "probability threshold P_g = 0.6, 3 scenarios × 20 runs, RRT against S-RRT; the claims: S-RRT's path is "
       "shorter, has fewer nodes and is smoother (§4.3), and the search is more efficient (§6). **Lost**: the "
       "scenes of Figure 5 and every number of Table 2 (path length, path nodes, running time), so no printed value "
       "can be compared: only the four qualitative claims are judged.\n\n";
  s += fmt::format(
      "**What pathref did**: the three scenes are **rebuilt by pathref** as the text describes (black axis-aligned "
      "rectangles in [0, 20]², a point robot, start (1.5, 1.5), goal (18.5, 18.5)); they are not the paper's. Every "
      "series ran 2n = {} times per scene with seeds {} … {} (run i uses seed {} + i in every series, so S-RRT and "
      "*RRT (Algorithm 1 alone)* grow the same tree and differ only by Algorithm 2 and the curve); each claim is "
      "judged on the first n = {} runs (the paper's protocol, the headline verdict) and on all 2n by the two-sided "
      "Mann–Whitney U test at α = 0.05 with the direction read from U (Welch's t beside it; "
      "docs/reproduction/README.md \"How a claim is judged\"). Three choices the text leaves open are readings, "
      "fixed before the runs, and every verdict is marked † and judged again under each alternative: the paper's "
      "\"RRT\" (default the traditional RRT without goal bias; alternative Algorithm 1 alone, `@alg1`), the lost "
      "direction of Algorithm 1's goal-bias test (default `bias=lt`: the goal with probability P_g; alternative "
      "`bias=gt`, `@gt`), and what S-RRT's path is (default its B-spline curve of Eq. 12–15; alternative the kept "
      "nodes of Algorithm 2, `@nodes`). Smoothness is measured as the total turning (the sum of heading changes, "
      "rad) of the path; for the curve, of its samples at spacing 0.05 (its total absolute curvature within the "
      "sampling).\n\n",
      pr.at("runs_2n").get<std::int64_t>(), pr.at("seed").get<std::int64_t>(),
      pr.at("seed").get<std::int64_t>() + pr.at("runs_2n").get<std::int64_t>() - 1, pr.at("seed").get<std::int64_t>(),
      n);
  s += "## Verdicts (default readings)\n\n" + md_verdict_summary(doc.at("claims")) + "\n";
  s += "## Findings\n\n";
  {
    std::string enters, trees;
    for (const Json& sc : doc.at("scenes")) {
      const auto id = sc.at("id").get<std::string>();
      const Json& v = sc.at("series").at("s-rrt").at("curve_verdicts_n");
      const Json& cl = sc.at("series").at("s-rrt").at("summary_n").at("curve_clearance");
      enters += fmt::format("{}{}: {} of {} (minimum clearance {})", enters.empty() ? "" : "; ", id,
                            v.value("enters", std::int64_t{0}), sc.at("series").at("s-rrt").at("found_n").get<std::int64_t>(),
                            md_number(cl["min"], 4));
      trees += fmt::format("{}{}: {} (S-RRT = Algorithm 1) vs {} (traditional RRT)", trees.empty() ? "" : "; ", id,
                           md_number(sc.at("series").at("s-rrt").at("summary_n").at("tree_size")["mean"], 1),
                           md_number(sc.at("series").at("rrt").at("summary_n").at("tree_size")["mean"], 1));
    }
    s += "- **S-RRT's curve cuts obstacle corners.** Runs whose Eq. 12–15 curve enters an obstacle (clearance verdict "
         "`enters`, r = 0), per scene: " + enters + ". Algorithm 2 keeps the nodes where the path wraps an obstacle's "
         "corner, and a clamped B-spline does not pass through its interior control points: it cuts the corner of its "
         "control polygon, on the obstacle's side. The kept nodes themselves are collision-free (K.1). The paper does "
         "not check its curve; a user who needs a collision-free curve plans with a radius or margin (r > 0) or sets "
         "`repair=true` (pathref's re-insertion, spec/cin2021-srrt.md r[cin2021.srrt.curve]).\n";
    s += "- **Search effort.** Mean tree size (nodes) to the first solution: " + trees + ". With `near=sample` the goal "
         "bias steers the node nearest the *random* point towards the goal, so it need not shrink the tree much, and "
         "S-RRT adds Algorithm 2's visibility checks to the same tree (`variant=ompl`, the nearest-to-target ordering, "
         "grows far smaller trees: docs/performance.md). Tree sizes are machine-independent (same seeds, same numbers "
         "anywhere); the running times are not.\n";
    const Json& la = at_or_null(doc, {"provenance", "load_average"});
    s += "- **Running times** are sub-millisecond wall-clock times of one machine" +
         (la.is_string() ? " (load average " + la.get<std::string>() + " at the start: other builds were running)" : std::string()) +
         "; single runs of several ms are scheduling delays, so the time verdicts are the least robust of this "
         "report: compare them across the readings and between n and 2n below.\n\n";
  }
  s += "## Scenes (rebuilt by pathref)\n\n";
  s += md_row({"scene", "what", "rectangles [x₀, x₁] × [y₀, y₁]", "file"});
  s += md_row({"---", "---", "---", "---"});
  for (const Json& sc : doc.at("scenes")) {
    std::string rects;
    for (const Json& p : sc.at("scene").at("polygons")) {
      const Json& v = p.at("vertices");
      rects += fmt::format("{}[{}, {}]×[{}, {}]", rects.empty() ? "" : ", ", v[0][0].dump(), v[2][0].dump(),
                           v[0][1].dump(), v[2][1].dump());
    }
    s += md_row({sc.at("id").get<std::string>(), sc.at("description").get<std::string>(), rects,
                 fmt::format("[{0}/{1}]({0}/{1})", figure_dir, sc.at("file").get<std::string>())});
  }
  s += fmt::format("\nReplay any run: `pathref plan --map {}/scene-A.json --algo s-rrt --seed S` (the scene's start "
                   "and goal cells have the protocol's endpoints as centres; add `--set variant=plain` with "
                   "`--algo rrt` for the traditional RRT).\n\n",
                   figure_dir);
  s += "Figure 5's analogue (run 0 of each scene: the tree, the raw branch, S-RRT's kept nodes and its curve):\n\n";
  for (const Json& sc : doc.at("scenes")) {
    const auto id = sc.at("id").get<std::string>();
    s += fmt::format("![scene {0}, S-RRT]({1}/{0}-s-rrt.svg) ![scene {0}, RRT]({1}/{0}-rrt.svg)\n", id, figure_dir);
  }
  s += fmt::format("\nFigure 6's analogue (per run): ![length]({0}/length.svg) ![nodes]({0}/nodes.svg) "
                   "![time]({0}/time.svg)\n\n",
                   figure_dir);
  s += fmt::format("## Results (first n = {} runs per scene: mean ± sd [min, max] over the runs that found a path)\n\n", n);
  s += "Length, nodes and turning are those of the series' path: RRT's denoised branch, S-RRT's kept nodes (its "
       "curve is in the next table). Time: Algorithm 1 (+ Algorithm 2 for S-RRT), ms on this machine.\n\n";
  for (const Json& sc : doc.at("scenes")) {
    s += fmt::format("<!-- results:{} -->\n", sc.at("id").get<std::string>());
    s += md_row({"scene", "series", "found (n / 2n)", "length", "nodes", "turning (rad)", "clearance", "time (ms)",
                 "tree size"});
    s += md_row({"---", "---", "---", "---", "---", "---", "---", "---", "---"});
    for (const auto& [key, se] : sc.at("series").items()) {
      (void)key;
      const Json& sm = se.at("summary_n");
      s += md_row({sc.at("id").get<std::string>(), se.at("label").get<std::string>(),
                   fmt::format("{}/{} · {}/{}", se.at("found_n").get<std::int64_t>(), n,
                               se.at("found_2n").get<std::int64_t>(), 2 * n),
                   stat_cell(sm["length"], 4), stat_cell(sm["nodes"], 2), stat_cell(sm["turning"], 4),
                   stat_cell(sm["clearance"], 4), stat_cell(sm["time_ms"], 3), stat_cell(sm["tree_size"], 1)});
    }
    s += "\n";
  }
  s += "## S-RRT's curve (Eq. 12–15, as `pathref plan --algo s-rrt` reports it)\n\n";
  s += "Clamped cubic B-spline over the kept nodes (degree lowered for fewer than 4 nodes), uniform knots, sampled at "
       "spacing 0.05; length of the samples' polyline, total turning of the samples, max |curvature| at the samples, "
       "the exact clearance of the samples (r = 0) and its verdict (clear / enters: the curve cuts an obstacle's "
       "corner / undetermined within the sampling tolerance). The paper does not check its curve; the repair is off "
       "(spec/cin2021-srrt.md r[cin2021.srrt.curve]).\n\n";
  s += md_row({"scene", "series", "curve length", "curve turning (rad)", "max curvature", "clearance", "verdicts",
               "curve + check (ms)"});
  s += md_row({"---", "---", "---", "---", "---", "---", "---", "---"});
  for (const Json& sc : doc.at("scenes"))
    for (const char* key : {"s-rrt", "s-rrt@gt"}) {
      const Json& se = sc.at("series").at(key);
      const Json& sm = se.at("summary_n");
      std::string verdicts;
      for (const auto& [v, c] : se.at("curve_verdicts_n").items())
        verdicts += fmt::format("{}{} {}", verdicts.empty() ? "" : ", ", c.get<std::int64_t>(), v);
      s += md_row({sc.at("id").get<std::string>(), se.at("label").get<std::string>(), stat_cell(sm["curve_length"], 4),
                   stat_cell(sm["curve_turning"], 4), stat_cell(sm["curve_max_curvature"], 3),
                   stat_cell(sm["curve_clearance"], 4), verdicts.empty() ? "—" : verdicts, stat_cell(sm["curve_ms"], 3)});
    }
  s += "\n## Claims (default readings)\n\n";
  s += md_claims(doc.at("claims"));
  s += "\n### Verdicts that change between n and 2n runs\n\n";
  std::string changes;
  for (const Json& c : doc.at("claims"))
    if (c.value("changed", false))
      changes += fmt::format("- {}: {}\n", c.at("id").get<std::string>(), c.at("change_note").get<std::string>());
  s += changes.empty() ? "No verdict of a default claim changes between n and 2n runs.\n" : changes;
  s += "\n## The claims under the alternative readings\n\n";
  s += "Each default claim († above) judged again under each alternative reading (verdict at n; the full rows "
       "follow). `@alg1`: RRT = Algorithm 1 alone (same trees as S-RRT); `@gt`: bias = gt for S-RRT; `@alg1+gt`: "
       "both; `@nodes`: S-RRT's path = its kept nodes.\n\n";
  std::map<std::string, const Json*> by_id;
  for (const Json& c : doc.at("reading_claims")) by_id[c.at("id").get<std::string>()] = &c;
  s += md_row({"claim", "default", "@alg1", "@gt", "@alg1+gt", "@nodes"});
  s += md_row({"---", "---", "---", "---", "---", "---"});
  for (const Json& c : doc.at("claims")) {
    const auto id = c.at("id").get<std::string>();
    std::vector<std::string> row{id, c.at("verdict_text").get<std::string>()};
    for (const char* suf : {"@alg1", "@gt", "@alg1+gt", "@nodes"}) {
      const auto it = by_id.find(id + suf);
      row.push_back(it == by_id.end() ? "—" : it->second->at("verdict_text").get<std::string>());
    }
    s += md_row(row);
  }
  s += "\n" + md_verdict_summary(doc.at("reading_claims")) + "\n";
  s += md_claims(doc.at("reading_claims"));
  s += "\n## pathref's checks (not the paper's claims)\n\n";
  s += md_verdict_summary(doc.at("checks"), true) + "\n";
  s += md_claims(doc.at("checks"));
  s += "\n## Parameters\n\n";
  s += "Every series runs with the defaults of spec/cin2021-srrt.md (δ = 1.7 and P_g = 0.6 of §4.3; max_iterations "
       "20000 because N is lost) and the overrides below; nothing was tuned.\n\n";
  const Json& first = doc.at("scenes").at(0).at("series");
  for (const auto& [key, se] : first.items()) {
    std::string params;
    for (const auto& [k, v] : se.at("params_used").items())
      params += (params.empty() ? "" : " ") + k + "=" + (v.is_string() ? v.get<std::string>() : v.dump());
    s += fmt::format("- `{}` ({}): `{}` {} (overrides: `{}`)\n", key, se.at("label").get<std::string>(),
                     se.at("algo").get<std::string>(), params, se.at("requested").dump());
  }
  s += "\n## Provenance\n\n" + md_provenance(doc.at("provenance"), json_name);
  return s;
}

}  // namespace pathref::reproduce
