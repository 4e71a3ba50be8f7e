#include "pathref/reproduce/shi2022.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <cmath>
#include <limits>

#include "pathref/core/error.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/io/builtin_maps.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/io/svg.hpp"
#include "pathref/reproduce/runs.hpp"

namespace pathref::reproduce {

namespace {

/// One printed number of the paper: where it is and what it is.
struct PaperNumber {
  std::string table;    ///< "Table 3"
  std::string row;      ///< the row label as printed
  std::string planner;  ///< the column, as a pathref planner name
  std::string value;    ///< as printed
  std::string stat;     ///< "length.min" | "length.mean" | "converged_at.mean" | "turns.mean" | "drive_time_s.mean"
};

/// Tables 3 (simple map), 4 (complex map) and 5 (physical 6x6 experiment) of Shi et al. 2022,
/// transcribed from ../shared/papers/000_e607a582dcb62616.txt (columns: genetic algorithm,
/// traditional genetic and ant colony hybrid, improved hybrid).
const std::vector<PaperNumber>& paper_tables() {
  static const std::vector<PaperNumber> t = {
      {"Table 3", "Optimal path length", "ga", "30.38", "length.min"},
      {"Table 3", "Optimal path length", "hybrid-ga-aco", "29.8", "length.min"},
      {"Table 3", "Optimal path length", "iha", "29.8", "length.min"},
      {"Table 3", "Average path length", "ga", "32.38", "length.mean"},
      {"Table 3", "Average path length", "hybrid-ga-aco", "31.8", "length.mean"},
      {"Table 3", "Average path length", "iha", "30.97", "length.mean"},
      {"Table 3", "Average number of iterations", "ga", "26", "converged_at.mean"},
      {"Table 3", "Average number of iterations", "hybrid-ga-aco", "24", "converged_at.mean"},
      {"Table 3", "Average number of iterations", "iha", "13", "converged_at.mean"},
      {"Table 3", "Average number of turns", "ga", "17", "turns.mean"},
      {"Table 3", "Average number of turns", "hybrid-ga-aco", "8", "turns.mean"},
      {"Table 3", "Average number of turns", "iha", "2", "turns.mean"},
      {"Table 4", "Optimal path length", "ga", "33.03", "length.min"},
      {"Table 4", "Optimal path length", "hybrid-ga-aco", "31.56", "length.min"},
      {"Table 4", "Optimal path length", "iha", "31.56", "length.min"},
      {"Table 4", "Average path length", "ga", "34.14", "length.mean"},
      {"Table 4", "Average path length", "hybrid-ga-aco", "32.38", "length.mean"},
      {"Table 4", "Average path length", "iha", "32.14", "length.mean"},
      {"Table 4", "Average number of iterations", "ga", "25", "converged_at.mean"},
      {"Table 4", "Average number of iterations", "hybrid-ga-aco", "21", "converged_at.mean"},
      {"Table 4", "Average number of iterations", "iha", "11", "converged_at.mean"},
      {"Table 4", "Average number of turns", "ga", "18", "turns.mean"},
      {"Table 4", "Average number of turns", "hybrid-ga-aco", "14", "turns.mean"},
      {"Table 4", "Average number of turns", "iha", "11", "turns.mean"},
      {"Table 5", "Average path length (m)", "ga", "8.24", "length.mean"},
      {"Table 5", "Average path length (m)", "hybrid-ga-aco", "8.24", "length.mean"},
      {"Table 5", "Average path length (m)", "iha", "7.66", "length.mean"},
      {"Table 5", "Average plan time (s)", "ga", "24", "drive_time_s.mean"},
      {"Table 5", "Average plan time (s)", "hybrid-ga-aco", "20", "drive_time_s.mean"},
      {"Table 5", "Average plan time (s)", "iha", "14", "drive_time_s.mean"},
      {"Table 5", "Average number of turns", "ga", "6", "turns.mean"},
      {"Table 5", "Average number of turns", "hybrid-ga-aco", "5", "turns.mean"},
      {"Table 5", "Average number of turns", "iha", "2", "turns.mean"},
  };
  return t;
}

/// The reductions of §6 ("Result analysis"): IHA against GA and the traditional hybrid.
struct PaperReduction {
  std::string map;      ///< "simple" | "complex"
  std::string other;    ///< planner
  std::string quantity; ///< "converged_at" | "turns"
  double percent;
  std::string printed;
};
const std::vector<PaperReduction>& paper_reductions() {
  static const std::vector<PaperReduction> r = {
      {"simple", "ga", "converged_at", 50, "50"},
      {"simple", "hybrid-ga-aco", "converged_at", 46, "46"},
      {"simple", "ga", "turns", 88, "88"},
      {"simple", "hybrid-ga-aco", "turns", 75, "75"},
      {"complex", "ga", "converged_at", 56, "56"},
      {"complex", "hybrid-ga-aco", "converged_at", 47, "47"},
      {"complex", "ga", "turns", 39, "39"},
      {"complex", "hybrid-ga-aco", "turns", 21, "21"},
  };
  return r;
}

std::string quantity_label(const std::string& q) {
  if (q == "converged_at") return "average number of iterations";
  if (q == "turns") return "average number of turns";
  return q;
}

/// Decimals used in the markdown for a statistic.
int decimals_of(const std::string& stat) {
  if (stat.rfind("length", 0) == 0) return 4;
  return 2;
}

const Json& stat_of(const Json& series, const std::string& stat) {
  const auto dot = stat.find('.');
  return at_or_null(series, {"summary", stat.substr(0, dot), stat.substr(dot + 1)});
}

/// What the claim rules need besides the results: the protocol's n (the first n runs of the 2n
/// run are the paper's protocol) and the bootstrap seed (reproduce.judge).
struct JudgeContext {
  std::int64_t n = 50;
  std::uint32_t seed = 1;
};

/// The values of `key` over the first `count` runs of a series (all runs when count < 0), skipping
/// runs without a value, in run order.
std::vector<double> values_first(const Json& series, const std::string& key, std::int64_t count) {
  std::vector<double> v;
  const Json& runs = at_or_null(series, {"runs"});
  if (!runs.is_array()) return v;
  std::int64_t k = 0;
  for (const Json& r : runs) {
    if (count >= 0 && k++ >= count) break;
    const Json& x = at_or_null(r, {key});
    if (x.is_number()) v.push_back(x.get<double>());
  }
  return v;
}

/// Why a statistic of these planners is missing: not registered, or no run found a path.
std::string unavailable_note(const Json& results, std::initializer_list<std::string> names) {
  std::string note;
  for (const auto& n : names) {
    const Json& r = at_or_null(results, {n});
    std::string why;
    if (r.is_null() || !r.value("available", false))
      why = "planner '" + n + "' is not available in this build";
    else if (at_or_null(r, {"summary", "found"}) == 0)
      why = "no run of '" + n + "' found a path";
    if (why.empty()) continue;
    if (!note.empty()) note += "; ";
    note += why;
  }
  return note;
}


Json map_json(const ProtocolMap& m, grid::Cell start, grid::Cell goal) {
  std::int64_t blocked = 0;
  for (std::int64_t i = 0; i < m.grid.cell_count(); ++i) blocked += m.grid.blocked(m.grid.cell(i)) ? 1 : 0;
  return Json{{"file", m.file},
              {"width", m.grid.width()},
              {"height", m.grid.height()},
              {"blocked", blocked},
              {"rows", grid::grid_to_json(m.grid)},
              {"start", Json::array({start.x, start.y})},
              {"goal", Json::array({goal.x, goal.y})}};
}

/// Claims of one printed table (3, 4 or 5) for the map `key` (reproduce.judge: value claims).
void table_claims(std::vector<Claim>& claims, const Json& results, const std::string& table, bool testable,
                  const std::string& untestable_reason, const JudgeContext& jc) {
  int k = 0;
  for (const PaperNumber& p : paper_tables()) {
    if (p.table != table) continue;
    ++k;
    Claim c;
    c.id = fmt::format("T{}.{}", table.substr(6), k);
    c.text = fmt::format("{}: {} = {}", planner_label(p.planner), p.row, p.value);
    c.source = fmt::format("{}, row \"{}\", column {}", table, p.row, planner_label(p.planner));
    c.paper = p.value;
    const Json& series = at_or_null(results, {p.planner});
    const auto dot = p.stat.find('.');
    const std::string key = p.stat.substr(0, dot);
    const bool is_min = p.stat.substr(dot + 1) == "min";
    const Quantity q = key == "length" ? Quantity::length
                       : key == "turns" ? Quantity::turns
                       : key == "converged_at" ? Quantity::iterations
                                               : Quantity::time;
    const BootstrapOptions bo{jc.seed, 2000, 0.95};
    const auto judge = [&](Claim& cl, const std::string& k2) {
      const auto vn = values_first(series, k2, jc.n);
      const auto v2 = values_first(series, k2, -1);
      if (vn.empty()) {
        cl.verdict = Verdict::untestable;
        cl.ours = "—";
        cl.note = unavailable_note(results, {p.planner});
        if (cl.note.empty()) cl.note = "no value (no run found a path)";
        return;
      }
      value_claim(cl, vn, v2.size() > vn.size() ? std::span<const double>(v2) : std::span<const double>(), std::stod(p.value),
                  q, Sense::lower_is_better, is_min ? BootStatistic::minimum : BootStatistic::mean, bo,
                  decimals_of(p.stat));
    };
    if (!testable) {
      c.verdict = Verdict::untestable;
      c.ours = md_number(stat_of(series, p.stat), decimals_of(p.stat));
      c.note = untestable_reason;
    } else {
      judge(c, key);
    }
    // The other reading of "iterations" for the hybrids (reproduce.converge): the whole curve.
    const bool hybrid_iter = testable && key == "converged_at" && (p.planner == "hybrid-ga-aco" || p.planner == "iha");
    if (hybrid_iter) c.depends_on.push_back("iterations counted in GA generations (reproduce.converge; alternative: " + c.id + "w)");
    claims.push_back(c);
    if (hybrid_iter) {
      Claim w;
      w.id = c.id + "w";
      w.text = c.text + " (whole-curve reading: colony iterations + GA generations)";
      w.source = c.source;
      w.paper = c.paper;
      judge(w, "converged_at_whole_curve");
      w.depends_on.push_back("iterations over the whole curve (reproduce.converge, the alternative of " + c.id + ")");
      claims.push_back(w);
    }
  }
}

void reduction_claims(std::vector<Claim>& claims, const Json& all_results, const JudgeContext& jc) {
  int k = 0;
  const BootstrapOptions bo{jc.seed, 2000, 0.95};
  for (const PaperReduction& p : paper_reductions()) {
    ++k;
    const Json& results = all_results.at(p.map);
    Claim c;
    c.id = fmt::format("R.{}", k);
    c.text = fmt::format("on the {} map IHA reduces the {} by about {} % against {}", p.map,
                         quantity_label(p.quantity), p.printed, planner_label(p.other));
    c.source = p.map == "simple" ? "§6, conclusion on Table 3 (also the abstract for the traditional hybrid)"
                                 : "§6, conclusion on Table 4 (also the abstract for the traditional hybrid)";
    c.paper = "−" + p.printed + " %";
    auto judge = [&](Claim& cl, const std::string& key) {
      const Json& other = at_or_null(results, {p.other});
      const Json& iha = at_or_null(results, {"iha"});
      const auto a_n = values_first(iha, key, jc.n), b_n = values_first(other, key, jc.n);
      const auto a_2 = values_first(iha, key, -1), b_2 = values_first(other, key, -1);
      if (a_n.empty() || b_n.empty()) {
        cl.verdict = Verdict::untestable;
        cl.ours = "—";
        cl.note = unavailable_note(results, {p.other, "iha"});
        if (cl.note.empty()) cl.note = "no value";
        return;
      }
      const bool more = a_2.size() > a_n.size() || b_2.size() > b_n.size();
      reduction_claim(cl, a_n, b_n, more ? std::span<const double>(a_2) : std::span<const double>(),
                      more ? std::span<const double>(b_2) : std::span<const double>(), p.percent, bo);
    };
    judge(c, p.quantity);
    if (p.quantity == "converged_at")
      c.depends_on.push_back("iterations counted in GA generations for the hybrids (reproduce.converge; alternative: " +
                             c.id + "w)");
    claims.push_back(c);
    if (p.quantity == "converged_at") {
      Claim w;
      w.id = c.id + "w";
      w.text = c.text + " (whole-curve reading of the iterations)";
      w.source = c.source;
      w.paper = c.paper;
      judge(w, "converged_at_whole_curve");
      w.depends_on.push_back("iterations over the whole curve (reproduce.converge, the alternative of " + c.id + ")");
      claims.push_back(w);
    }
  }
}

/// "A's `key` is smaller than B's" (direction claims, reproduce.judge: Mann-Whitney).
Claim less_claim(const std::string& id, const std::string& text, const std::string& source, const Json& results,
                 const std::string& a, const std::string& b, const std::string& key, const JudgeContext& jc) {
  Claim c;
  c.id = id;
  c.text = text;
  c.source = source;
  c.paper = planner_label(a) + " < " + planner_label(b);
  const Json& sa = at_or_null(results, {a});
  const Json& sb = at_or_null(results, {b});
  const auto a_n = values_first(sa, key, jc.n), b_n = values_first(sb, key, jc.n);
  const auto a_2 = values_first(sa, key, -1), b_2 = values_first(sb, key, -1);
  if (a_n.empty() || b_n.empty()) {
    c.ours = "—";
    c.verdict = Verdict::untestable;
    c.note = unavailable_note(results, {a, b});
    if (c.note.empty()) c.note = "no value";
    return c;
  }
  const bool more = a_2.size() > a_n.size() || b_2.size() > b_n.size();
  comparison_claim(c, a_n, b_n, more ? std::span<const double>(a_2) : std::span<const double>(),
                   more ? std::span<const double>(b_2) : std::span<const double>(), Claimed::a_less, decimals_of(key));
  return c;
}

/// Every claim of Tables 3-5, §5.1 and §6 judged on `results` (the maps' series by planner
/// name), in report order; pathref's own checks (M.1, M.2, ...) are made by the caller.
std::vector<Claim> paper_claims(const Json& results, const JudgeContext& jc) {
  std::vector<Claim> claims;
  table_claims(claims, at_or_null(results, {"simple"}), "Table 3", true, "", jc);
  table_claims(claims, results.at("complex"), "Table 4", true, "", jc);
  {
    Claim c;
    c.id = "F8.1";
    c.text = "A* makes 11 turns on the simple map";
    c.source = "§5.1, text on Figure 8";
    c.paper = "11";
    const Json& v = at_or_null(results, {"simple", "astar", "summary", "turns", "min"});
    if (v.is_number()) {
      exact_value_claim(c, v.get<double>(), 11.0, Quantity::turns, Sense::lower_is_better, 0);
      c.note = "A*'s path among equally short ones depends on its tie-breaking (spec/search.md)";
      c.depends_on.push_back("A*'s tie-breaking among equally short paths (spec/search.md), not the paper's");
    } else {
      c.ours = "—";
      c.verdict = Verdict::untestable;
      c.note = unavailable_note(at_or_null(results, {"simple"}), {"astar"});
    }
    claims.push_back(c);
  }
  reduction_claims(claims, results, jc);
  int k = 0;
  for (const std::string key : {"simple", "complex"})
    for (const std::string other : {"ga", "hybrid-ga-aco"})
      claims.push_back(less_claim(fmt::format("L.{}", ++k),
                                  fmt::format("IHA's average path length is shorter than {}'s on the {} map",
                                              planner_label(other), key),
                                  key == "simple" ? "Table 3 and §5.1 on Figure 9" : "Table 4 and §5.2 on Figure 12",
                                  at_or_null(results, {key}), "iha", other, "length", jc));
  claims.push_back(less_claim("E.1",
                              "without the lower limit ρ_min, IACO* stops improving and ends on longer paths than IACO",
                              "§5.1, trial-and-error experiment, Figure 10", at_or_null(results, {"simple"}), "iaco-shi",
                              "iaco-shi-nomin", "length", jc));
  claims.push_back(less_claim("E.2",
                              "without the upper limit P_m_max, IGA* deviates from the better path (longer final paths than IGA)",
                              "§5.1, trial-and-error experiment, Figure 10", at_or_null(results, {"simple"}), "iga-shi",
                              "iga-shi-nomax", "length", jc));
  claims.push_back(less_claim("E.3", "IHA ends on shorter paths than IACO*", "§5.1, Figure 10",
                              at_or_null(results, {"simple"}), "iha", "iaco-shi-nomin", "length", jc));
  claims.push_back(less_claim("E.4", "IHA ends on shorter paths than IGA*", "§5.1, Figure 10",
                              at_or_null(results, {"simple"}), "iha", "iga-shi-nomax", "length", jc));
  // Claims that read the traditional hybrid rest on its reconstruction (spec/shi2022-ga.md).
  for (Claim& c : claims)
    if (c.id.rfind("T5", 0) != 0 && (c.text.find("traditional hybrid") != std::string::npos))
      c.depends_on.push_back("pathref's reconstruction of the traditional hybrid (Bao et al., from Shi's description), "
                             "whose colony uses the goal-blind η = 1/d_ij (spec/shi2022-ga.md, shi2022.plan.hybrid; "
                             "the goal-directed η: reading `eta`)");
  if (results.contains("shi6x6"))
    table_claims(claims, results.at("shi6x6"), "Table 5", false,
                 "the paper's 6×6 obstacle layout is not published; pathref's shi6x6 is a reconstruction "
                 "(spec/cli.md#builtin-maps) and the plan time of the physical vehicle is not defined",
                 jc);
  return claims;
}


/// The claims that read a planner of `r`, judged again on its runs under the reading (spec
/// reproduce.shi2022.readings): `results` with each planner of r replaced by its "PLANNER@KEY"
/// series. A claim reads a planner iff removing that planner's series changes the claim.
std::vector<Claim> reading_claims(const Json& results, const ShiReading& r, const JudgeContext& jc) {
  Json view = results;
  Json removed = results;
  for (const char* key : {"simple", "complex"}) {
    if (!view.contains(key)) continue;
    for (const std::string& p : r.planners) {
      view[key][p] = at_or_null(results, {key, p + "@" + r.key});
      removed[key][p] = nullptr;
    }
  }
  view.erase("shi6x6");
  removed.erase("shi6x6");
  const std::vector<Claim> base = paper_claims(removed, jc);
  const std::vector<Claim> under = paper_claims(view, jc);
  const std::vector<Claim> orig = paper_claims([&] { Json j = results; j.erase("shi6x6"); return j; }(), jc);
  std::vector<Claim> out;
  for (std::size_t i = 0; i < under.size(); ++i) {
    const bool reads = claim_json(base[i]) != claim_json(orig[i]);
    if (!reads) continue;
    Claim c = under[i];
    c.depends_on.push_back("reading `" + r.key + "` (reproduce.shi2022.readings), the alternative of " + c.id);
    c.id += r.suffix;
    c.text += " [reading: " + r.key + "]";
    for (const std::string& p : r.planners) {  // the note names the series it read
      const std::string from = "'" + p + "'";
      const std::string to = "'" + p + "@" + r.key + "'";
      for (std::size_t at = c.note.find(from); at != std::string::npos; at = c.note.find(from, at + to.size()))
        c.note.replace(at, from.size(), to);
    }
    out.push_back(c);
  }
  return out;
}

}  // namespace

const std::vector<std::string>& shi2022_planners() {
  static const std::vector<std::string> v = {"ga", "aco", "iaco-shi", "iga-shi", "hybrid-ga-aco", "iha",
                                             "iaco-shi-nomin", "iga-shi-nomax", "astar", "dijkstra"};
  return v;
}

const std::vector<ShiReading>& shi2022_readings() {
  static const std::vector<ShiReading> v = {
      {"blocked", "b",
       "GA initialisation `init_reject = blocked`: a chain whose Eq. 9 mid-point is blocked is rejected (the literal "
       "\"eliminate\"; pathref's default before issue 11) instead of the default `shift` to a free cell of its row, "
       "as the widely copied MATLAB GA scripts do (shi2022.op.init)",
       {"ga", "iga-shi", "iga-shi-nomax", "iha"},
       Json{{"init_reject", "blocked"}}},
      {"reject", "r",
       "GA initialisation `illegal_step = reject`: a chain with a continuous diagonal pair that cuts an obstacle "
       "corner is rejected (pathref's earlier reading) instead of the default `repair`, which treats the pair as not "
       "continuous and inserts its free orthogonal cell as §4.2 step 2 does for every non-continuous pair "
       "(shi2022.op.init)",
       {"ga", "iga-shi", "iga-shi-nomax", "iha"},
       Json{{"illegal_step", "reject"}}},
      {"pernode", "p",
       "Eq. 16 read `smoothness = per_node` (fit_2 = the sum over interior nodes of 1/P, the reading of the printed "
       "sum) instead of the default `inverse_total_plus_one` (fit_2 = 1 / (1 + the total turn penalty), the classic "
       "script's 1/smoothness made finite for a turn-free path); per_node grows with the number of nodes, so it "
       "rewards longer paths (shi2022.eq16)",
       {"iga-shi", "iga-shi-nomax", "iha"},
       Json{{"smoothness", "per_node"}}},
      {"safetysum", "s",
       "Eq. 18 read `safety_aggregate = per_node` (fit_3 = the printed sum over the nodes of 1/S_i) instead of the "
       "default `inverse_total_plus_one` (fit_3 = 1 / (1 + the path's total count of obstacle neighbours), the "
       "convention of Eq. 16); the sum grows with the number of nodes and, with Table 1's c = 1 against a = 5 on "
       "1/length, makes the weighted fitness prefer long paths (shi2022.eq18)",
       {"iga-shi", "iha"},
       Json{{"safety_aggregate", "per_node"}}},
      {"length", "l",
       "`result_by = length`: the hybrids return the shortest path they evaluated, not the fittest "
       "(shi2022.plan.ga, Reading \"The result\"; default `fitness`)",
       {"hybrid-ga-aco", "iha"},
       Json{{"result_by", "length"}}},
      {"eta", "e",
       "the traditional hybrid's colony with the goal-directed η = 1/(d_ij + d_jE) (the η of Shi's IACO) instead of "
       "the goal-blind η = 1/d_ij of the plain colony it is reconstructed with (shi2022.plan.hybrid)",
       {"hybrid-ga-aco"},
       Json{{"aco_eta", "goal_directed"}}},
      {"invlen", "f",
       "IHA with `fitness = inverse_length` (Eq. 10) instead of the weighted Eq. 14–18 (shi2022.eq14): length "
       "alone, as the single GA ranks",
       {"iha"},
       Json{{"fitness", "inverse_length"}}},
  };
  return v;
}

Orientation parse_orientation(std::string_view name) {
  if (name == "paper") return Orientation::paper;
  if (name == "file") return Orientation::file;
  throw UsageError("unknown orientation '" + std::string(name) + "' (expected paper or file)");
}

std::string_view to_string(Orientation o) noexcept { return o == Orientation::paper ? "paper" : "file"; }

grid::Grid oriented(const grid::Grid& file_grid, Orientation o) {
  if (o == Orientation::file) return file_grid;
  std::vector<std::string> rows = file_grid.to_rows_top_first();
  std::reverse(rows.begin(), rows.end());
  return grid::Grid::from_rows_top_first(rows);
}

std::pair<grid::Cell, grid::Cell> shi2022_endpoints(const grid::Grid& g, Orientation o) {
  if (o == Orientation::paper) return {grid::Cell{0, 0}, grid::Cell{g.width() - 1, g.height() - 1}};
  return {grid::Cell{0, g.height() - 1}, grid::Cell{g.width() - 1, 0}};
}

Json run_shi2022(const ShiConfig& cfg) {
  require(cfg.runs >= 1 && cfg.runs <= 10000, "run_shi2022: runs must lie in [1, 10000]");
  const auto t0 = std::chrono::steady_clock::now();
  Json doc = Json::object();
  doc["format"] = "pathref-reproduce";
  doc["format_version"] = 1;
  doc["paper"] = "shi2022";
  doc["reference"] =
      "Shi, Huang, Jiang, Sun, Tong, Xie, Fang (2022). Path Planning Optimization of Intelligent Vehicle "
      "Based on Improved Genetic and Ant Colony Hybrid Algorithm. Front. Bioeng. Biotechnol. 10:905983. "
      "doi:10.3389/fbioe.2022.905983";
  const auto last_seed = static_cast<std::uint64_t>(cfg.seed) + static_cast<std::uint64_t>(cfg.runs) - 1;
  require(last_seed <= 4294967295ULL, "run_shi2022: seed + runs - 1 must not exceed 4294967295");
  const std::int64_t runs2 = 2 * cfg.runs;  // reproduce.judge: verdicts at n and at 2n
  const auto last_seed2 = static_cast<std::uint64_t>(cfg.seed) + static_cast<std::uint64_t>(runs2) - 1;
  require(last_seed2 <= 4294967295ULL, "run_shi2022: seed + 2 runs - 1 must not exceed 4294967295");
  doc["protocol"] = Json{{"runs", cfg.runs},
                         {"runs_2n", runs2},
                         {"seeds", Json::array({cfg.seed, last_seed})},
                         {"seeds_2n", Json::array({cfg.seed, last_seed2})},
                         {"bootstrap", Json{{"resamples", 2000}, {"level", 0.95}, {"seed", cfg.seed}}},
                         {"alpha", 0.05},
                         {"policy", std::string(grid::to_string(cfg.policy))},
                         {"orientation", std::string(to_string(cfg.orientation))},
                         {"quick", cfg.quick},
                         {"planners", shi2022_planners()},
                         {"deterministic_planners_runs", 1},
                         {"drive_model", "drive.path-time, Mecanum base, cell 1 m, spec/mecanum.md defaults"}};
  Json maps = Json::object();
  Json results = Json::object();
  const ProtocolMap simple{cfg.simple.file, oriented(cfg.simple.grid, cfg.orientation)};
  const ProtocolMap complex{cfg.complex.file, oriented(cfg.complex.grid, cfg.orientation)};
  const std::vector<std::pair<std::string, const ProtocolMap*>> inputs = {{"simple", &simple}, {"complex", &complex}};
  for (const auto& [key, m] : inputs) {  // every endpoint is checked before the first run
    const auto [start, goal] = shi2022_endpoints(m->grid, cfg.orientation);
    for (const auto& [what, c] : {std::pair{"start", start}, std::pair{"goal", goal}})
      if (m->grid.blocked(c))
        throw UsageError(fmt::format("{} ({}, {}) is a blocked cell of the {} map '{}'", what, c.x, c.y, key, m->file));
  }
  for (const auto& [key, m] : inputs) {
    const auto [start, goal] = shi2022_endpoints(m->grid, cfg.orientation);
    maps[key] = map_json(*m, start, goal);
    maps[key]["orientation"] = std::string(to_string(cfg.orientation));
    Json res = Json::object();
    for (const std::string& name : shi2022_planners()) {
      const bool deterministic = name == "astar" || name == "dijkstra";
      res[name] = run_series(name, Json::object(), m->grid, start, goal, cfg.policy, cfg.seed,
                             deterministic ? 1 : runs2, cfg.quick, cfg.progress, "shi2022 " + key);
    }
    for (const ShiReading& r : shi2022_readings())  // reproduce.shi2022.readings
      for (const std::string& name : r.planners)
        res[name + "@" + r.key] = run_series(name, r.params, m->grid, start, goal, cfg.policy, cfg.seed, runs2,
                                             cfg.quick, cfg.progress, "shi2022 " + key);
    results[key] = res;
  }
  // Table 5: the physical 6x6 experiment on the reconstructed built-in map shi6x6.
  {
    const io::BuiltinMap* b = io::find_builtin_map("shi6x6");
    if (b != nullptr) {
      const io::MapFile mf = io::load_builtin_map(*b);
      ProtocolMap pm{"builtin:shi6x6", mf.grid};
      const grid::Cell start = mf.start.value_or(grid::Cell{0, 0});
      const grid::Cell goal = mf.goal.value_or(grid::Cell{mf.grid.width() - 1, mf.grid.height() - 1});
      maps["shi6x6"] = map_json(pm, start, goal);
      Json res = Json::object();
      for (const std::string& name : {std::string("ga"), std::string("hybrid-ga-aco"), std::string("iha"),
                                      std::string("dijkstra")}) {
        const bool deterministic = name == "dijkstra";
        res[name] = run_series(name, Json::object(), mf.grid, start, goal, cfg.policy, cfg.seed,
                               deterministic ? 1 : runs2, cfg.quick, cfg.progress, "shi2022 shi6x6");
      }
      results["shi6x6"] = res;
    }
  }
  doc["maps"] = maps;
  doc["results"] = results;

  Json paper = Json::array();
  for (const PaperNumber& p : paper_tables())
    paper.push_back(Json{{"table", p.table}, {"row", p.row}, {"column", planner_label(p.planner)},
                         {"planner", p.planner}, {"value", p.value}, {"compared_with", p.stat}});
  doc["paper_numbers"] = paper;

  const JudgeContext jc{cfg.runs, cfg.seed};
  // pathref's own checks (reproduce.judge): they test the maps and pathref, not the paper.
  std::vector<Claim> checks;
  for (const auto& [key, printed, table] : {std::tuple{std::string("simple"), std::string("29.8"), std::string("Table 3")},
                                            std::tuple{std::string("complex"), std::string("31.56"), std::string("Table 4")}}) {
    Claim c;
    c.id = key == "simple" ? "M.1" : "M.2";
    c.text = fmt::format("the {} map is the paper's: its shortest path ({} policy) is the printed optimum {}", key,
                         grid::to_string(cfg.policy), printed);
    c.source = table + ", row \"Optimal path length\" (traditional and improved hybrid)";
    c.paper = printed;
    const Json& v = at_or_null(results, {key, "dijkstra", "summary", "length", "min"});
    c.ours = md_number(v, 4);
    if (v.is_number()) {
      c.rule = "Dijkstra's shortest length equal when rounded to the printed decimals (an exact optimum)";
      c.verdict = matches_printed(v.get<double>(), printed) ? Verdict::holds : Verdict::fails;
    } else {
      c.verdict = Verdict::untestable;
      c.note = "no shortest path (Dijkstra unavailable or goal unreachable)";
    }
    checks.push_back(c);
  }
  int kc = 0;
  for (const std::string key : {"simple", "complex"}) {
    const Json& res = at_or_null(results, {key});
    const Json& opt = at_or_null(res, {"dijkstra", "summary", "length", "min"});
    std::int64_t found = 0, valid = 0, shorter = 0;
    for (auto it = res.begin(); it != res.end(); ++it) {
      if (!it->value("available", false)) continue;
      found += at_or_null(*it, {"summary", "found"}).get<std::int64_t>();
      valid += at_or_null(*it, {"summary", "valid"}).get<std::int64_t>();
      if (opt.is_number())
        for (const double x : values_first(*it, "length", -1)) shorter += x < opt.get<double>() - 1e-9 ? 1 : 0;
    }
    Claim v;
    v.id = fmt::format("C.{}", ++kc);
    v.text = fmt::format("every path returned on the {} map is valid (metrics.valid-path, {} policy)", key,
                         grid::to_string(cfg.policy));
    v.source = "pathref";
    v.paper = "—";
    v.ours = fmt::format("{} of {} found paths valid", valid, found);
    v.rule = "all valid";
    v.verdict = valid == found ? Verdict::holds : Verdict::fails;
    checks.push_back(v);
    Claim o;
    o.id = fmt::format("C.{}", ++kc);
    o.text = fmt::format("no path on the {} map is shorter than Dijkstra's optimum", key);
    o.source = "pathref";
    o.paper = "—";
    o.ours = fmt::format("{} shorter", shorter);
    o.rule = "none shorter (an optimum is a lower bound)";
    o.verdict = opt.is_number() ? (shorter == 0 ? Verdict::holds : Verdict::fails) : Verdict::untestable;
    checks.push_back(o);
  }
  Json chj = Json::array();
  for (const Claim& c : checks) chj.push_back(claim_json(c));
  doc["checks"] = chj;

  std::vector<Claim> claims = paper_claims(results, jc);
  Json rj = Json::array();
  Json readings = Json::array();
  for (const ShiReading& r : shi2022_readings()) {
    readings.push_back(Json{{"key", r.key}, {"suffix", r.suffix}, {"label", r.label}, {"planners", r.planners},
                            {"params", r.params}});
    for (const Claim& c : reading_claims(results, r, jc)) {
      rj.push_back(claim_json(c));
      const std::string base_id = c.id.substr(0, c.id.size() - r.suffix.size());
      for (Claim& b : claims)
        if (b.id == base_id)
          b.depends_on.push_back("the default of the reading `" + r.key + "` (alternative: " + c.id + ")");
    }
  }
  Json cj = Json::array();
  for (const Claim& c : claims) cj.push_back(claim_json(c));
  doc["claims"] = cj;
  doc["protocol"]["readings"] = readings;
  doc["reading_claims"] = rj;
  Json prov = provenance_json(cfg.provenance);
  prov["total_wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  doc["provenance"] = prov;
  return doc;
}

namespace {

std::string paper_beside_table(const Json& doc, const std::string& map_key, const std::string& table) {
  const Json& results = at_or_null(doc, {"results", map_key});
  std::string s = md_row({"row (" + table + ")", "GA paper", "GA pathref", "traditional hybrid paper",
                          "traditional hybrid pathref", "IHA paper", "IHA pathref"});
  s += md_row({"---", "---:", "---:", "---:", "---:", "---:", "---:"});
  std::string row;
  std::vector<std::string> cells;
  for (const PaperNumber& p : paper_tables()) {
    if (p.table != table) continue;
    if (p.row != row) {
      if (!cells.empty()) s += md_row(cells);
      row = p.row;
      const std::string stat_desc = p.stat == "length.min"           ? "min length"
                                    : p.stat == "length.mean"        ? "mean length"
                                    : p.stat == "converged_at.mean"  ? "mean metrics.converge, GA phase for hybrids"
                                    : p.stat == "turns.mean"         ? "mean metrics.turns"
                                                                     : "mean drive time (Mecanum model)";
      cells = {p.row + " (pathref: " + stat_desc + ")"};
    }
    cells.push_back(p.value);
    cells.push_back(md_number(stat_of(at_or_null(results, {p.planner}), p.stat), decimals_of(p.stat)));
  }
  if (!cells.empty()) s += md_row(cells);
  return s;
}

std::string cell_text(const Json& c) {
  return fmt::format("({}, {})", c.at(0).get<std::int64_t>(), c.at(1).get<std::int64_t>());
}

std::vector<io::PathLayer> best_layers(const Json& results, const std::vector<std::string>& names) {
  std::vector<io::PathLayer> layers;
  for (const auto& n : names) {
    const Json& best = at_or_null(results, {n, "best"});
    if (!best.is_object()) continue;
    io::PathLayer l;
    l.label = fmt::format("{} (seed {}, length {}, {} turns)", planner_label(n), best.at("seed").get<std::int64_t>(),
                          md_number(best.at("length"), 2), best.at("turns").get<std::int64_t>());
    l.path = grid::path_from_json(best.at("path"));
    layers.push_back(l);
  }
  return layers;
}

std::vector<io::Series> curves(const Json& results, const std::vector<std::string>& names, const std::string& key,
                               const std::string& suffix) {
  std::vector<io::Series> out;
  for (const auto& n : names) {
    const Json* cp = &at_or_null(results, {n, key});
    if (cp->is_null() && key.size() > 6 && key.substr(key.size() - 6) == "_phase")
      cp = &at_or_null(results, {n, key.substr(0, key.size() - 6)});  // no phases: the whole curve
    const Json& c = *cp;
    if (!c.is_array() || c.empty()) continue;
    io::Series s;
    s.label = planner_label(n) + suffix;
    for (std::size_t i = 0; i < c.size(); ++i) {
      s.x.push_back(static_cast<double>(i + 1));
      s.y.push_back(c[i].is_number() ? c[i].get<double>() : std::numeric_limits<double>::infinity());
    }
    s.absent = "no run found a path";
    // a best-so-far curve: ring the iteration where it reaches its final value (metrics.converge)
    if (key.find("best") != std::string::npos &&
        std::any_of(s.y.begin(), s.y.end(), [](double v) { return std::isfinite(v); }))
      s.marks.push_back(static_cast<double>(metrics::iterations_to_converge(s.y)));
    out.push_back(s);
  }
  return out;
}

}  // namespace

/// Captions of the convergence charts: what the rings and the breaks mean.
constexpr const char* kConvergeNote =
    "Ring: the iteration where the mean curve reaches its final value (metrics.converge). Hybrids: their final GA phase only, as in the paper.";
constexpr const char* kGapNote =
    "A line is broken where some run had no path yet, so the mean over the runs is undefined there.";

std::vector<std::pair<std::string, std::string>> shi2022_figures(const Json& doc) {
  std::vector<std::pair<std::string, std::string>> figs;
  const std::vector<std::string> fig8 = {"ga", "hybrid-ga-aco", "iha", "astar"};
  const std::vector<std::string> fig9 = {"ga", "hybrid-ga-aco", "iha"};
  const Json& runs = at_or_null(doc, {"protocol", "runs"});
  const std::string n = runs.is_number() ? std::to_string(runs.get<std::int64_t>()) : "?";
  for (const auto& [key, fig_paths, fig_conv] :
       {std::tuple{std::string("simple"), std::string("Figure 8"), std::string("Figure 9")},
        std::tuple{std::string("complex"), std::string("Figure 11"), std::string("Figure 12")}}) {
    const Json& m = at_or_null(doc, {"maps", key});
    if (!m.is_object()) continue;
    const grid::Grid g = grid::grid_from_json(m.at("rows"));
    const Json& results = at_or_null(doc, {"results", key});
    figs.emplace_back(key + "-paths.svg",
                      io::svg_map(g, grid::cell_from_json(m.at("start")), grid::cell_from_json(m.at("goal")),
                                  best_layers(results, fig8),
                                  fmt::format("{} map ({}): best of {} runs (cf. {})", key,
                                              std::filesystem::path(m.at("file").get<std::string>()).filename().string(), n,
                                              fig_paths)));
    figs.emplace_back(key + "-convergence.svg",
                      io::svg_line_chart(curves(results, fig9, "mean_best_curve_phase", ""),
                                         io::ChartOptions{fmt::format("{} map: best length per iteration, mean of {} runs (cf. {})",
                                                                      key, n, fig_conv),
                                                          "iteration", "path length", kConvergeNote, kGapNote}));
  }
  const Json& simple = at_or_null(doc, {"results", "simple"});
  if (simple.is_object()) {
    const std::vector<std::string> fig10 = {"iaco-shi", "iaco-shi-nomin", "iga-shi", "iga-shi-nomax", "iha"};
    figs.emplace_back("trial-error.svg",
                      io::svg_line_chart(curves(simple, fig10, "mean_best_curve_phase", ""),
                                         io::ChartOptions{fmt::format("trial and error: best length, mean of {} runs (cf. Fig. 10)", n),
                                                          "iteration", "path length", kConvergeNote, kGapNote}));
    figs.emplace_back("trial-error-iteration-mean.svg",
                      io::svg_line_chart(curves(simple, fig10, "mean_iteration_curve_phase", ""),
                                         io::ChartOptions{fmt::format("trial and error: iteration mean length, mean of {} runs", n),
                                                          "iteration", "path length", "", kGapNote}));
  }
  return figs;
}

namespace {
/// Why a planner of the protocol runs with the parameters it does (printed beside them).
std::string shi_param_why(const std::string& name) {
  if (name == "ga") return "Shi's single GA with Table 1's GA parameters (registered defaults, spec/shi2022-ga.md)";
  if (name == "aco") return "the plain colony with Table 1's ACO parameters (registered defaults, spec/shi2022-aco.md)";
  if (name == "iaco-shi") return "Shi's IACO, Table 1 (spec/shi2022-aco.md)";
  if (name == "iaco-shi-nomin") return "IACO without ρ_min (Figure 10's IACO*), otherwise as IACO";
  if (name == "iga-shi") return "Shi's IGA, Table 1 (spec/shi2022-ga.md)";
  if (name == "iga-shi-nomax") return "IGA without the P_m_max cap (Figure 10's IGA*), otherwise as IGA";
  if (name == "hybrid-ga-aco")
    return "the traditional hybrid (Bao et al.) as Shi describes it — a reconstruction: a plain colony seeds a plain "
           "GA; Table 1's parameters (spec/shi2022-ga.md, shi2022.plan.hybrid)";
  if (name == "iha") return "Shi's IHA: IACO seeds IGA, Table 1 (spec/shi2022-ga.md, shi2022.plan.iha)";
  if (name == "astar" || name == "dijkstra") return "reference optimum (deterministic, one run)";
  return "registered defaults";
}

std::string params_text(const Json& p) {
  if (!p.is_object() || p.empty()) return "—";
  std::string t;
  for (auto it = p.begin(); it != p.end(); ++it)
    t += (t.empty() ? "" : ", ") + it.key() + " = " + (it.value().is_string() ? it.value().get<std::string>() : it.value().dump());
  return "`" + t + "`";
}

/// The parameters table: every planner's params_used (as the planner reports them) and why.
std::string shi_params_table(const Json& results) {
  std::string s = md_row({"planner", "parameters used (params_used of its runs)", "why these"});
  s += md_row({"---", "---", "---"});
  for (const std::string& name : shi2022_planners()) {
    const Json& r = at_or_null(results, {name});
    if (!r.value("available", false)) {
      s += md_row({"`" + name + "`", "not available in this build", shi_param_why(name)});
      continue;
    }
    s += md_row({"`" + name + "`", params_text(r.at("params_used")), shi_param_why(name)});
  }
  return s;
}

/// The GA populations the GA-based planners built (per-run `population` of reproduce.json): a
/// hybrid whose GA population holds only injected colony paths is its colony's result, and the
/// report must say so (issue 11).
std::string shi_population_table(const Json& doc) {
  std::string s;
  bool any = false;
  std::string rows = md_row({"map", "planner", "runs", "mean population", "from the §4.2 initialisation",
                             "from the colony", "runs whose initialisation was exhausted", "mean random chains tried"});
  rows += md_row({"---", "---", "---:", "---:", "---:", "---:", "---:", "---:"});
  for (const std::string key : {"simple", "complex"}) {
    const Json& res = at_or_null(doc, {"results", key});
    for (const std::string name : {"ga", "iga-shi", "iga-shi-nomax", "hybrid-ga-aco", "iha"}) {
      const Json& runs = at_or_null(res, {name, "runs"});
      if (!runs.is_array() || runs.empty()) continue;
      double size = 0, init = 0, aco = 0, chains = 0;
      std::int64_t n = 0, exhausted = 0, with_size = 0, with_chains = 0;
      for (const Json& r : runs) {
        ++n;
        const Json& p = at_or_null(r, {"population"});
        if (!p.is_object()) continue;
        if (p.contains("population_size")) {
          ++with_size;
          size += p.at("population_size").get<double>();
          init += p.value("population_init", 0.0);
          aco += p.value("population_aco", 0.0);
        }
        if (p.contains("init_chains")) {
          ++with_chains;
          chains += p.at("init_chains").get<double>();
        }
        if (p.contains("init_exhausted")) {
          const Json& e = p.at("init_exhausted");
          if (e.is_boolean() ? e.get<bool>() : (e.is_number() && e.get<double>() > 0)) ++exhausted;
        }
      }
      if (with_size == 0 && with_chains == 0) continue;
      any = true;
      auto avg = [](double v, std::int64_t k) { return k == 0 ? std::string("not reported") : fixed(v / static_cast<double>(k), 1); };
      rows += md_row({key, planner_label(name), std::to_string(n), avg(size, with_size), avg(init, with_size),
                      avg(aco, with_size), with_size == 0 ? std::string("not reported") : std::to_string(exhausted),
                      avg(chains, with_chains)});
    }
  }
  if (!any)
    return "This build's GA-based planners do not report the population they built (`population_*` in their "
           "`extra`), so the report cannot show it.\n";
  s += "Per run, the GA-based planners report how their GA population was filled (`population` of each run in the "
       "JSON; spec/shi2022-ga.md). A hybrid whose population holds only colony paths (nothing from the "
       "initialisation) is its colony's result with a GA polish, and the verdicts on it are read that way.\n\n";
  return s + rows;
}

/// The mean of results.MAP.PLANNER.summary.length.mean as text ("—" when absent).
std::string mean_length(const Json& doc, const std::string& map_key, const std::string& planner) {
  return md_number(at_or_null(doc, {"results", map_key, planner, "summary", "length", "mean"}), 2);
}

/// The readings of Eq. 16 and Eq. 18 that decide what the weighted fitness prefers (issue 11), with
/// this run's numbers: IHA against IACO (iaco-shi: the parameters of the colony IHA starts from, same
/// seeds) and IGA against the single GA, under the defaults and under the printed per-node sums.
std::string shi_weighted_note(const Json& doc) {
  std::string s = "## The weighted fitness under its readings (Eq. 14–18)\n\n";
  s += "IGA, IGA* and IHA rank individuals by the weighted fitness a·fit_1 + b·fit_2 + c·fit_3 of Eq. 14 "
       "(Table 1: a = 5, b = 4, c = 1), with fit_1 = 1/length (about 0.03 on these maps). Printed, fit_2 (Eq. 16) "
       "and fit_3 (Eq. 18) are sums over the path's nodes: they grow with the number of nodes, and with these "
       "weights they outweigh length, so the fitness prefers long paths. pathref's defaults (decided in issue 11 "
       "from the text, spec/shi2022.md shi2022.eq16 and shi2022.eq18) read both as the reciprocal of 1 + the "
       "path's total penalty (turn penalties; obstacle neighbours), which rewards no extra node. The printed sums "
       "stay selectable and are run here as the readings `pernode` (Eq. 16) and `safetysum` (Eq. 18); every "
       "verdict they change is marked † in [Claims](#claims). Mean lengths in this run:\n\n";
  s += md_row({"map", "IHA", "IHA, Eq. 18 printed sum (`safetysum`)", "IHA, Eq. 16 printed sum (`pernode`)",
               "IACO (the colony IHA starts from: same parameters, same seeds)", "IGA",
               "IGA, Eq. 18 printed sum (`safetysum`)", "GA", "IHA with `fitness = inverse_length`"});
  s += md_row({"---", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:"});
  for (const std::string key : {"simple", "complex"})
    s += md_row({key, mean_length(doc, key, "iha"), mean_length(doc, key, "iha@safetysum"),
                 mean_length(doc, key, "iha@pernode"), mean_length(doc, key, "iaco-shi"),
                 mean_length(doc, key, "iga-shi"), mean_length(doc, key, "iga-shi@safetysum"),
                 mean_length(doc, key, "ga"), mean_length(doc, key, "iha@invlen")});
  s += "\n";
  return s;
}

/// The claims whose verdict changed between n and 2n runs, with the explanation.
std::string md_changes(const Json& claims) {
  std::string s;
  for (const Json& c : claims)
    if (c.value("changed", false))
      s += fmt::format("- {}: {}\n", c.at("id").get<std::string>(), c.at("change_note").get<std::string>());
  return s.empty() ? "No verdict changes between n and 2n runs.\n" : s;
}
}  // namespace

std::string shi2022_markdown(const Json& doc, const std::string& figure_dir, const std::string& json_name) {
  std::string s;
  const Json& proto = doc.at("protocol");
  const auto runs = proto.at("runs").get<std::int64_t>();
  const auto seeds = proto.at("seeds");
  s += "# Reproduction: Shi et al. 2022 (improved GA–ACO hybrid), Tables 3–5 and Figures 8–12\n\n";
  s += "<!-- generated by `pathref reproduce shi2022`; do not edit by hand -->\n\n";
  s += doc.at("reference").get<std::string>() + "\n\n";
  if (proto.at("quick").get<bool>())
    s += "**QUICK RUN** (`--quick`: reduced iterations, ants and population; a smoke test, not a reproduction).\n\n";
  s += "## Summary\n\n" + md_verdict_summary(doc.at("claims")) +
       "\nThe verdict of each claim and the test or margin that decided it are in [Claims](#claims); the rules "
       "(spec/stats.md, spec/reproduce.md reproduce.judge) were fixed before these runs. pathref's own checks "
       "(the maps' optima, valid paths) are listed apart in [pathref's checks](#pathrefs-checks) and are not paper "
       "claims. A † marks a verdict that rests on a reconstructed or chosen reading; the claim that judges it under "
       "the alternative is named beside it.\n\n";
  if (doc.contains("checks")) {
    const std::string cs = md_verdict_summary(doc.at("checks"), true);
    s += "pathref's own " + cs.substr(0, cs.find('\n')) + "\n\n";
  }
  s += shi_weighted_note(doc);
  s += "## Protocol\n\n";
  const bool paper = proto.value("orientation", "paper") == "paper";
  s += fmt::format("- maps: simple = `{}`, complex = `{}` (0/1 matrices); start = the first cell of the file's first "
                   "row, goal = the last cell of its last row, as in the MATLAB scripts the maps come from. {} In "
                   "pathref coordinates ((0,0) lower left): start {}, goal {}. Lengths and turns do not depend on "
                   "the orientation.\n",
                   doc.at("maps").at("simple").at("file").get<std::string>(),
                   doc.at("maps").at("complex").at("file").get<std::string>(),
                   paper ? "Orientation `paper`: the file's first row is y = 0, as Shi draws the maps (S lower left, "
                           "T upper right) and numbers the cells (Figure 1A; cell index = MATLAB node number − 1)."
                         : "Orientation `file`: the file's first row is the top row (spec/formats.md), so the maps "
                           "appear flipped top to bottom against Shi's figures.",
                   cell_text(doc.at("maps").at("simple").at("start")), cell_text(doc.at("maps").at("simple").at("goal")));
  s += fmt::format("- corner policy `{}` (a diagonal step needs both orthogonal neighbours free): under it the "
                   "shortest paths are the printed optima 29.8 and 31.56 (claims M.1, M.2); under corner cutting "
                   "they would be 28.63 and 30.97.\n",
                   proto.at("policy").get<std::string>());
  const Json& seeds2 = at_or_null(proto, {"seeds_2n"});
  s += fmt::format("- the paper's protocol is n = {} runs per stochastic planner and map (seeds {}–{}); pathref ran "
                   "2n = {} (seeds {}–{}) and judges every claim on the first n and on all 2n (A* and Dijkstra: one "
                   "run). The tables below summarise all 2n runs. Every planner runs with its registered defaults "
                   "(= Table 1), listed with the reason in [Parameters](#parameters) and in `{}` under "
                   "`results.MAP.PLANNER.params_used`.\n",
                   runs, seeds[0].get<std::int64_t>(), seeds[1].get<std::int64_t>(),
                   proto.value("runs_2n", runs), seeds2.is_array() ? seeds2[0].get<std::int64_t>() : 0,
                   seeds2.is_array() ? seeds2[1].get<std::int64_t>() : 0, json_name);
  s += "- judging (spec/reproduce.md reproduce.judge, spec/stats.md): a printed value holds when the 95 % percentile "
       "bootstrap interval (2000 resamples, seeded with the first seed) of pathref's statistic lies within the "
       "paper's value ± a margin fixed per kind of quantity before any run (lengths ± 1 %, turns ± 1, iterations "
       "± 10 % (at least 1), percentages ± 5 points); entirely outside: \"does not hold — pathref better/worse\"; "
       "otherwise \"inconclusive\" with its leaning. A comparison holds when the two-sided Mann–Whitney U test is "
       "significant at α = 0.05 in the claimed direction (Welch's t printed beside it); significant the other way: "
       "\"does not hold — the opposite is significant\"; otherwise \"not significant\" with the observed direction.\n";
  s += "- per run: path length (metrics.length), turns (metrics.turns), iterations to converge (metrics.converge of "
       "the planner's best-so-far curve), validity (metrics.valid-path), drive time (drive.path-time, Mecanum base, "
       "1 m cells, spec/mecanum.md defaults: a measure of what the turns cost, not a paper quantity) and wall-clock "
       "time (a measurement of this machine, never compared).\n";
  s += "- statistics over the runs that found a path: minimum, mean, **sample** standard deviation (n − 1).\n\n";
  for (const auto& [key, table, fig] : {std::tuple{std::string("simple"), std::string("Table 3"), std::string("8, 9")},
                                        std::tuple{std::string("complex"), std::string("Table 4"), std::string("11, 12")}}) {
    s += fmt::format("## {} map — {}\n\n", key == "simple" ? "Simple" : "Complex", table);
    s += paper_beside_table(doc, key, table) + "\n";
    s += "All planners (pathref):\n\n";
    s += md_results_table(doc.at("results").at(key), shi2022_planners(), key) + "\n";
    s += fmt::format("![best paths, {} map]({}/{}-paths.svg) (cf. Figure {})\n\n", key, figure_dir, key,
                     fig.substr(0, fig.find(',')));
    s += fmt::format("![convergence, {} map]({}/{}-convergence.svg) (cf. Figure {})\n\n", key, figure_dir, key,
                     fig.substr(fig.find(' ') + 1));
  }
  s += "## Trial-and-error experiment (Figure 10)\n\n";
  s += "IACO* = `iaco-shi-nomin` (no ρ_min), IGA* = `iga-shi-nomax` (no P_m_max), on the simple map; their rows are in "
       "the simple-map table above, the claims E.1–E.4 below.\n\n";
  s += fmt::format("![trial and error]({}/trial-error.svg)\n\n![trial and error, iteration means]({}/trial-error-iteration-mean.svg)\n\n",
                   figure_dir, figure_dir);
  if (doc.contains("reading_claims")) {  // reproduce.shi2022.readings
    s += "## Readings that change the outcome\n\n";
    s += "The tables above use every planner's default reading. Where another reading named in the spec changes "
         "what the paper's claims meet, the planners concerned were run again under it (same seeds, same maps); "
         "the claims that read them are judged again below with a suffix on their ids. Nothing was tuned: each "
         "reading is one the spec names, chosen before the runs.\n\n";
    for (const Json& r : doc.at("protocol").at("readings")) {
      const std::string rkey = r.at("key").get<std::string>();
      s += fmt::format("### Reading `{}` (claim suffix `{}`)\n\n{}; `--set {}`.\n\n", rkey,
                       r.at("suffix").get<std::string>(), r.at("label").get<std::string>(),
                       [&] {
                         std::string t;
                         for (auto it = r.at("params").begin(); it != r.at("params").end(); ++it)
                           t += (t.empty() ? "" : " ") + it.key() + "=" +
                                (it.value().is_string() ? it.value().get<std::string>() : it.value().dump());
                         return t;
                       }());
      std::vector<std::string> order;
      for (const Json& p : r.at("planners")) {
        order.push_back(p.get<std::string>());
        order.push_back(p.get<std::string>() + "@" + rkey);
      }
      for (const std::string key : {"simple", "complex"})
        if (doc.at("results").contains(key))
          s += fmt::format("{} map:\n\n", key == "simple" ? "Simple" : "Complex") +
               md_results_table(doc.at("results").at(key), order, key + "-" + rkey) + "\n";
    }
    s += "Summary under the other readings: " + md_verdict_summary(doc.at("reading_claims")) + "\n";
    s += md_claims(doc.at("reading_claims")) + "\n";
  }
  if (doc.at("results").contains("shi6x6")) {
    s += "## Physical experiment — Table 5 (cannot be tested)\n\n";
    s += "The paper's 6×6 platform layout is not published. pathref's built-in `shi6x6` is a reconstruction "
         "(spec/cli.md#builtin-maps); its shortest path under the corner policy differs from the printed "
         "IHA length (7.66 m = 2 + 4√2 with 1 m cells), so it is certainly not the paper's layout. The numbers "
         "below are pathref's on the reconstruction, for orientation only; \"plan time\" is compared with the "
         "Mecanum drive-time model, which is a pathref assumption.\n\n";
    s += paper_beside_table(doc, "shi6x6", "Table 5") + "\n";
    s += md_results_table(doc.at("results").at("shi6x6"), {"ga", "hybrid-ga-aco", "iha", "dijkstra"}, "shi6x6") + "\n";
  }
  {
    std::string notes;
    for (auto it = doc.at("results").begin(); it != doc.at("results").end(); ++it)
      for (auto jt = it.value().begin(); jt != it.value().end(); ++jt) {
        const Json& r = jt.value();
        if (!r.value("available", false)) {
          notes += fmt::format("- `{}` on the {} map: {}\n", jt.key(), it.key(), r.value("reason", ""));
          continue;
        }
        const auto found = r.at("summary").at("found").get<std::int64_t>();
        const auto runs_n = r.at("summary").at("runs").get<std::int64_t>();
        if (found < runs_n) {
          std::string failures;
          for (const Json& run : r.at("runs"))
            if (run.contains("failure") && failures.find(run.at("failure").get<std::string>()) == std::string::npos)
              failures += (failures.empty() ? "" : ", ") + run.at("failure").get<std::string>();
          notes += fmt::format("- `{}` on the {} map found a path in {} of {} runs{}\n", jt.key(), it.key(), found,
                               runs_n, failures.empty() ? "" : " (planner's extra.failure: " + failures + ")");
        }
      }
    if (!notes.empty())
      s += "## Runs without a path\n\nStatistics are over the runs that found a path; a planner without any has no "
           "statistics, and the claims that need it are \"cannot be tested\".\n\n" + notes + "\n";
  }
  s += "## The GA population each planner actually built\n\n" + shi_population_table(doc) + "\n";
  s += "## Parameters\n\nEvery planner of the protocol with the parameters its runs used (simple map; the "
       "complex map's are the same) and why:\n\n";
  s += shi_params_table(at_or_null(doc, {"results", "simple"})) + "\n";
  s += "## Claims\n\n";
  s += md_claims(doc.at("claims")) + "\n";
  s += "### Verdicts that change between n and 2n runs\n\n" + md_changes(doc.at("claims")) + "\n";
  if (doc.contains("checks")) {
    s += "## pathref's checks\n\nThese test the identification of the maps and pathref itself, not the paper; they "
         "are not counted among the paper's claims.\n\n";
    s += md_claims(doc.at("checks")) + "\n";
  }
  s += "## Provenance\n\n" + md_provenance(doc.at("provenance"), json_name);
  return s;
}

}  // namespace pathref::reproduce
