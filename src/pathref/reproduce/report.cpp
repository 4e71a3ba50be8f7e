#include "pathref/reproduce/report.hpp"

#include "pathref/core/version.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

namespace pathref::reproduce {

Json provenance_json(const Provenance& p) {
  return Json{{"command", p.command},
              {"build_type", p.build_type},
              {"date_utc", p.date_utc},
              {"machine", p.machine},
              {"pathref_version", p.pathref_version},
              {"golden_set_version", std::string(pathref::golden_set_version())},
              {"jobs", p.jobs},
              {"execution", p.execution}};
}

Json claim_json(const Claim& c) {
  Json at2 = nullptr;
  std::string change;
  if (c.verdict_2n) {
    at2 = Json{{"verdict", std::string(to_string(*c.verdict_2n))},
               {"direction", std::string(to_string(c.direction_2n))},
               {"verdict_text", verdict_text(*c.verdict_2n, c.direction_2n)},
               {"ours", c.ours_2n}};
    change = verdict_change_note(c.verdict, c.direction, *c.verdict_2n, c.direction_2n);
  }
  return Json{{"id", c.id},
              {"text", c.text},
              {"source", c.source},
              {"paper", c.paper},
              {"ours", c.ours},
              {"rule", c.rule},
              {"verdict", std::string(to_string(c.verdict))},
              {"direction", std::string(to_string(c.direction))},
              {"verdict_text", verdict_text(c.verdict, c.direction)},
              {"at_2n", at2},
              {"changed", !change.empty()},
              {"change_note", change},
              {"statistics", c.statistics},
              {"depends_on", c.depends_on},
              {"note", c.note}};
}

void attach_rules(Json& claim, const std::vector<std::string>& rule_ids) {
  Json rules = Json::array();
  char lowest = 'A';
  for (const std::string& id : rule_ids) {
    const auto g = reconstruction_grade(id);
    if (!g) throw std::logic_error("attach_rules: '" + id + "' is not a graded (reconstructed) rule in spec/index");
    lowest = std::max(lowest, *g);  // 'C' > 'B' > 'A': the lowest confidence
    rules.push_back(Json{{"id", id}, {"grade", std::string(1, *g)}});
  }
  if (rule_ids.empty()) throw std::logic_error("attach_rules: claim " + claim.value("id", std::string()) + " names no rule");
  claim["rules"] = rules;
  claim["grade"] = std::string(1, lowest);
}

void attach_rules_all(Json& claims, const std::function<std::vector<std::string>(const std::string& id)>& rules_for) {
  for (Json& c : claims) attach_rules(c, rules_for(c.at("id").get<std::string>()));
}

std::string verdict_change_note(Verdict at_n, Direction dir_n, Verdict at_2n, Direction dir_2n) {
  if (at_n == at_2n && dir_n == dir_2n) return "";
  const bool decided_n = at_n == Verdict::holds || at_n == Verdict::fails;
  const bool decided_2n = at_2n == Verdict::holds || at_2n == Verdict::fails;
  const std::string from = verdict_text(at_n, dir_n);
  const std::string to = verdict_text(at_2n, dir_2n);
  if (!decided_n && decided_2n)
    return fmt::format("{} at n, {} at 2n: more runs narrowed the interval (or sharpened the test) until it "
                       "decided; the 2n verdict is the better-supported one",
                       from, to);
  if (decided_n && !decided_2n)
    return fmt::format("{} at n, {} at 2n: the n-run verdict rested on an interval (or p value) close to the "
                       "edge; the n + 1 … 2n runs moved the estimate back across it — treat the claim as "
                       "undecided",
                       from, to);
  if (decided_n && decided_2n)
    return fmt::format("{} at n, {} at 2n: the estimate moved across the margin between the two halves of the "
                       "runs — the claim is not stable and should be read as undecided",
                       from, to);
  return fmt::format("{} at n, {} at 2n: undecided both times; only the leaning changed", from, to);
}

namespace {
std::string interval_text(const Interval& ci, int decimals) {
  return fmt::format("[{}, {}]", fixed(ci.lo, decimals), fixed(ci.hi, decimals));
}
std::string value_text(const ValueAssessment& v, int decimals) {
  const bool exact = v.summary.n == 1;
  const double point = v.statistic == BootStatistic::minimum ? *v.summary.min : *v.summary.mean;
  if (exact) return fixed(point, decimals);
  return fmt::format("{} {} {}", v.statistic == BootStatistic::minimum ? "min" : "mean", fixed(point, decimals),
                     interval_text(v.ci, decimals));
}
std::string margin_rule(const ValueAssessment& v, int decimals) {
  return fmt::format("95 % bootstrap interval of the {} within {} ± {} ({} margin, stats.margin)",
                     to_string(v.statistic), fixed(v.paper, decimals), fixed(v.margin, decimals + 1),
                     to_string(v.quantity));
}
}  // namespace

void value_claim(Claim& c, std::span<const double> runs_n, std::span<const double> runs_2n, double paper,
                 Quantity quantity, Sense sense, BootStatistic statistic, const BootstrapOptions& options,
                 int decimals) {
  if (runs_n.size() < 2) {
    c.verdict = Verdict::untestable;
    c.ours = runs_n.empty() ? "—" : fixed(runs_n[0], decimals);
    if (c.note.empty()) c.note = fmt::format("{} run(s) with a value: an interval needs 2", runs_n.size());
    return;
  }
  const ValueAssessment v = assess_value(runs_n, paper, quantity, sense, options, statistic);
  c.ours = value_text(v, decimals);
  c.rule = margin_rule(v, decimals);
  c.verdict = v.judgement.verdict;
  c.direction = v.judgement.direction;
  c.statistics = Json{{"n", value_json(v, options)}, {"2n", nullptr}};
  if (runs_2n.size() >= 2) {
    const ValueAssessment w = assess_value(runs_2n, paper, quantity, sense, options, statistic);
    c.ours_2n = value_text(w, decimals);
    c.verdict_2n = w.judgement.verdict;
    c.direction_2n = w.judgement.direction;
    c.statistics["2n"] = value_json(w, options);
  }
}

void exact_value_claim(Claim& c, double x, double paper, Quantity quantity, Sense sense, int decimals) {
  const ValueAssessment v = assess_exact_value(x, paper, quantity, sense);
  c.ours = fixed(x, decimals);
  c.rule = fmt::format("exact value (one deterministic run) within {} ± {} ({} margin, stats.margin)",
                       fixed(paper, decimals), fixed(v.margin, decimals + 1), to_string(quantity));
  c.verdict = v.judgement.verdict;
  c.direction = v.judgement.direction;
  c.statistics = Json{{"n", value_json(v, BootstrapOptions{})}, {"2n", nullptr}};
}

void reduction_claim(Claim& c, std::span<const double> a_n, std::span<const double> b_n, std::span<const double> a_2n,
                     std::span<const double> b_2n, double paper_percent, const BootstrapOptions& options) {
  auto usable = [](std::span<const double> a, std::span<const double> b) {
    if (a.size() < 2 || b.size() < 2) return false;
    for (const double v : b)
      if (!(v > 0.0)) return false;
    return true;
  };
  auto assess = [&](std::span<const double> a, std::span<const double> b, std::string& ours) {
    const double point = reduction_percent(mean(b), mean(a));
    const Interval ci = bootstrap_two_sample_ci(a, b, BootStatistic::reduction_percent, options);
    const double m = equivalence_margin(Quantity::percent, paper_percent);
    const Judgement j = judge_equivalence(ci, paper_percent, m, Sense::higher_is_better);
    ours = fmt::format("{} % {} ({} → {})", fixed(point, 1), interval_text(ci, 1), fixed(mean(b), 2), fixed(mean(a), 2));
    return std::tuple{j, Json{{"kind", "value"},
                              {"statistic", "reduction_percent"},
                              {"point", point},
                              {"ci", interval_json(ci)},
                              {"level", options.level},
                              {"resamples", options.resamples},
                              {"seed", options.seed},
                              {"paper", paper_percent},
                              {"quantity", "percent"},
                              {"margin", m},
                              {"band", Json::array({paper_percent - m, paper_percent + m})},
                              {"a", summary_stats_json(summarize(a))},
                              {"b", summary_stats_json(summarize(b))},
                              {"judgement", judgement_json(j)}}};
  };
  if (!usable(a_n, b_n)) {
    c.verdict = Verdict::untestable;
    c.ours = "—";
    if (c.note.empty()) c.note = "fewer than 2 runs with a value, or a value of the other planner <= 0";
    return;
  }
  const auto [j, js] = assess(a_n, b_n, c.ours);
  c.verdict = j.verdict;
  c.direction = j.direction;
  c.rule = fmt::format("95 % bootstrap interval of the reduction 100·(other − IHA)/other of the means within "
                       "{} ± 5 points (percent margin, stats.margin)",
                       fixed(paper_percent, 0));
  c.statistics = Json{{"n", js}, {"2n", nullptr}};
  if (usable(a_2n, b_2n)) {
    const auto [j2, js2] = assess(a_2n, b_2n, c.ours_2n);
    c.verdict_2n = j2.verdict;
    c.direction_2n = j2.direction;
    c.statistics["2n"] = js2;
  }
}

void comparison_claim(Claim& c, std::span<const double> a_n, std::span<const double> b_n, std::span<const double> a_2n,
                      std::span<const double> b_2n, Claimed claim, int decimals) {
  auto text = [&](const ComparisonAssessment& x) {
    std::string t = fmt::format("{} vs {}; Mann–Whitney p = {}", x.a.mean ? fixed(*x.a.mean, decimals) : "—",
                                x.b.mean ? fixed(*x.b.mean, decimals) : "—", fmt::format("{:.3g}", x.mann_whitney.p));
    if (x.welch) t += fmt::format("; Welch t = {}, p = {}", fmt::format("{:.3g}", x.welch->t), fmt::format("{:.3g}", x.welch->p));
    return t;
  };
  if (a_n.empty() || b_n.empty()) {
    c.verdict = Verdict::untestable;
    c.ours = "—";
    if (c.note.empty()) c.note = "no runs with a value";
    return;
  }
  const ComparisonAssessment x = compare_samples(a_n, b_n, claim);
  c.ours = text(x);
  c.rule = "two-sided Mann–Whitney U test, α = 0.05, direction from U (stats.compare); means shown";
  c.verdict = x.judgement.verdict;
  c.direction = x.judgement.direction;
  c.statistics = Json{{"n", comparison_json(x)}, {"2n", nullptr}};
  if (!a_2n.empty() && !b_2n.empty()) {
    const ComparisonAssessment y = compare_samples(a_2n, b_2n, claim);
    c.ours_2n = text(y);
    c.verdict_2n = y.judgement.verdict;
    c.direction_2n = y.judgement.direction;
    c.statistics["2n"] = comparison_json(y);
  }
}

namespace {
Json opt_num(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? Json(*v) : Json(nullptr);
}
Json fin(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }
}  // namespace

Json summary_stats_json(const Summary& s) {
  return Json{{"n", s.n}, {"mean", opt_num(s.mean)}, {"std", opt_num(s.std)}, {"min", opt_num(s.min)},
              {"max", opt_num(s.max)}};
}

Json interval_json(const Interval& ci) { return Json::array({fin(ci.lo), fin(ci.hi)}); }

Json judgement_json(const Judgement& j) {
  return Json{{"verdict", std::string(to_string(j.verdict))},
              {"direction", std::string(to_string(j.direction))},
              {"text", verdict_text(j.verdict, j.direction)}};
}

Json value_json(const ValueAssessment& v, const BootstrapOptions& options) {
  const bool exact = v.summary.n == 1;
  return Json{{"kind", "value"},
              {"summary", summary_stats_json(v.summary)},
              {"statistic", std::string(to_string(v.statistic))},
              {"ci", interval_json(v.ci)},
              {"ci_method", exact ? "exact (one deterministic run)" : "percentile bootstrap"},
              {"level", exact ? Json(nullptr) : Json(options.level)},
              {"resamples", exact ? Json(nullptr) : Json(options.resamples)},
              {"seed", exact ? Json(nullptr) : Json(options.seed)},
              {"paper", fin(v.paper)},
              {"quantity", std::string(to_string(v.quantity))},
              {"margin", fin(v.margin)},
              {"band", Json::array({fin(v.paper - v.margin), fin(v.paper + v.margin)})},
              {"judgement", judgement_json(v.judgement)}};
}

Json comparison_json(const ComparisonAssessment& c) {
  Json w = nullptr;
  if (c.welch)
    w = Json{{"mean_difference", fin(c.welch->mean_difference)}, {"t", fin(c.welch->t)},
             {"df", opt_num(c.welch->df)}, {"p", fin(c.welch->p)}};
  return Json{{"kind", "comparison"},
              {"claim", c.claim == Claimed::a_less ? "a_less" : "a_greater"},
              {"alpha", c.alpha},
              {"a", summary_stats_json(c.a)},
              {"b", summary_stats_json(c.b)},
              {"test", "Mann-Whitney U (two-sided)"},
              {"mann_whitney", Json{{"u_a", c.mann_whitney.u_a},
                                    {"u_b", c.mann_whitney.u_b},
                                    {"exact", c.mann_whitney.exact},
                                    {"z", opt_num(c.mann_whitney.z)},
                                    {"p", fin(c.mann_whitney.p)}}},
              {"welch", w},
              {"judgement", judgement_json(c.judgement)}};
}

std::string md_number(const Json& v, int decimals) {
  if (!v.is_number()) return "—";
  return fixed(v.get<double>(), decimals);
}

const Json& at_or_null(const Json& doc, std::initializer_list<std::string_view> path) {
  static const Json null_json = nullptr;
  const Json* cur = &doc;
  for (const std::string_view key : path) {
    if (!cur->is_object()) return null_json;
    const auto it = cur->find(std::string(key));
    if (it == cur->end()) return null_json;
    cur = &*it;
  }
  return *cur;
}

std::string planner_label(std::string_view name) {
  static const std::map<std::string, std::string, std::less<>> labels = {
      {"ga", "GA"},
      {"aco", "ACO"},
      {"iaco-shi", "IACO"},
      {"iaco-shi-nomin", "IACO*"},
      {"iga-shi", "IGA"},
      {"iga-shi-nomax", "IGA*"},
      {"hybrid-ga-aco", "traditional hybrid"},
      {"iha", "IHA"},
      {"astar", "A*"},
      {"dijkstra", "Dijkstra"},
      {"iaco-han", "IACO-A* (iaco-han)"},
      {"astar-han", "A* (Han, Chebyshev)"},
  };
  const auto it = labels.find(name);
  return it == labels.end() ? std::string(name) : it->second;
}

std::string md_row(const std::vector<std::string>& cells) {
  std::string s = "|";
  for (const auto& c : cells) s += " " + c + " |";
  return s + "\n";
}

namespace {

/// The grade cell of a claim: "C (r1, r2)" naming the rules at the lowest grade, or "" when ungraded.
std::string md_grade(const Json& c) {
  const Json& g = at_or_null(c, {"grade"});
  if (!g.is_string()) return "";
  std::string at_lowest;
  for (const Json& r : c.at("rules"))
    if (r.at("grade") == g) at_lowest += (at_lowest.empty() ? "" : ", ") + r.at("id").get<std::string>();
  return g.get<std::string>() + " (" + at_lowest + ")";
}

}  // namespace

std::string md_claims(const Json& claims) {
  // A table of a reconstructed paper's claims (cin2021, sensors2023) has a grade column.
  bool graded = false;
  for (const Json& c : claims) graded = graded || at_or_null(c, {"grade"}).is_string();
  std::vector<std::string> head{"id", "claim", "source", "paper", "pathref (n runs)", "verdict at n", "verdict at 2n",
                                "decided by / note"};
  if (graded) head.insert(head.begin() + 1, "grade ‡");
  std::string s = md_row(head);
  s += md_row(std::vector<std::string>(head.size(), "---"));
  for (const Json& c : claims) {
    const std::string text = c.value("verdict_text", c.at("verdict").get<std::string>());
    const std::string v = c.at("verdict").get<std::string>();
    const std::string verdict = (v == "holds" || v == "does not hold") ? "**" + text + "**" : text;
    std::string at2 = "—";
    const Json& a2 = at_or_null(c, {"at_2n"});
    if (a2.is_object()) {
      at2 = a2.value("verdict_text", std::string());
      if (c.value("changed", false)) at2 = "**changed:** " + at2;
    }
    std::string rule = c.at("rule").get<std::string>();
    const std::string note = c.at("note").get<std::string>();
    if (!note.empty()) rule += rule.empty() ? note : "; " + note;
    std::string id = c.at("id").get<std::string>();
    const Json& deps = at_or_null(c, {"depends_on"});
    if (deps.is_array() && !deps.empty()) {
      id += " †";
      std::string d;
      for (const Json& x : deps) d += (d.empty() ? "" : "; ") + x.get<std::string>();
      rule += (rule.empty() ? "" : "; ") + std::string("† depends on ") + d;
    }
    std::vector<std::string> row{id, c.at("text").get<std::string>(), c.at("source").get<std::string>(),
                                 c.at("paper").get<std::string>(), c.at("ours").get<std::string>(), verdict, at2, rule};
    if (graded) row.insert(row.begin() + 1, md_grade(c));
    s += md_row(row);
  }
  if (graded)
    s += "\n‡ grade: the lowest confidence grade (A, B or C; spec/index) of the reconstructed rules this verdict rests "
         "on, and those rules: the paper's equations were lost in extraction, so the verdict judges pathref's "
         "reconstruction, not the printed equation (docs/versioning.md#confidence-grades).\n";
  return s;
}

std::string md_verdict_summary(const Json& claims, bool checks) {
  constexpr std::size_t K = 5;
  std::vector<std::string> ids[K];
  const char* names[K] = {"holds", "does not hold", "not significant", "inconclusive", "cannot be tested"};
  std::vector<std::string> changed;
  for (const Json& c : claims) {
    const auto v = c.at("verdict").get<std::string>();
    std::string id = c.at("id").get<std::string>();
    const std::string dir = c.value("direction", std::string("none"));
    const std::string shown = (v == "does not hold" || v == "not significant" || v == "inconclusive") && dir != "none"
                                  ? id + " (" + dir + ")"
                                  : id;
    for (std::size_t k = 0; k < K; ++k)
      if (v == names[k]) ids[k].push_back(shown);
    if (c.value("changed", false)) changed.push_back(id);
  }
  std::string s = fmt::format(
      "{} {}: {} hold, {} do not hold, {} not significant, {} inconclusive, {} cannot be tested.\n\n", claims.size(),
      checks ? "checks" : "claims (verdicts on the protocol's n runs)", ids[0].size(), ids[1].size(), ids[2].size(),
      ids[3].size(), ids[4].size());
  for (std::size_t k = 0; k < K; ++k) {
    std::string list;
    for (const auto& id : ids[k]) list += (list.empty() ? "" : ", ") + id;
    s += fmt::format("- {}: {}\n", names[k], list.empty() ? "—" : list);
  }
  std::string list;
  for (const auto& id : changed) list += (list.empty() ? "" : ", ") + id;
  s += fmt::format("- verdict changes between n and 2n runs: {}\n", list.empty() ? "none" : list);
  return s;
}

std::string md_provenance(const Json& p, const std::string& out_name) {
  std::string s;
  s += fmt::format("- command: `{}`\n", p.value("command", ""));
  const std::string golden = p.value("golden_set_version", "");
  s += fmt::format("- pathref {}{}, build type {}\n", p.value("pathref_version", ""),
                   golden.empty() ? std::string() : " (golden vectors " + golden + ")", p.value("build_type", ""));
  s += fmt::format("- date (UTC): {}\n", p.value("date_utc", ""));
  s += fmt::format("- machine: {}\n", p.value("machine", ""));
  if (p.contains("total_wall_s") && p.at("total_wall_s").is_number())
    s += fmt::format("- total wall-clock time of the reproduction: {} s\n",
                     fixed(p.at("total_wall_s").get<double>(), 1));
  const auto jobs = p.value("jobs", 1);
  if (p.value("execution", std::string("run")) == "merge")
    s += "- execution: the runs were done by the commands of `--emit-jobs` and merged with `--merge` "
         "(reproduce.execution); the wall times were measured on the machines that ran them\n";
  else
    s += fmt::format("- execution: {} (reproduce.execution); wall times (ms) are measurements of this machine{}, "
                     "never compared with the papers\n",
                     jobs == 1 ? std::string("one thread") : fmt::format("{} parallel jobs (threads)", jobs),
                     jobs == 1 ? std::string("") : fmt::format(" measured under {} parallel jobs", jobs));
  s += fmt::format("- every number of this page, every parameter and every seed: `{}`\n", out_name);
  return s;
}

std::string md_results_table(const Json& results, const std::vector<std::string>& order,
                             const std::string& key) {
  std::string s = fmt::format("<!-- results:{} -->\n", key);
  s += md_row({"planner", "runs", "found", "valid", "best length", "mean length", "std length",
               "mean turns", "std turns", "min turns", "mean iter. to converge", "std iter.",
               "mean iter. (whole curve)", "mean drive time (s)", "mean wall time (ms)"});
  s += md_row({"---", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:", "---:",
               "---:", "---:", "---:", "---:"});
  for (const std::string& name : order) {
    const Json& r = at_or_null(results, {name});
    if (r.is_null() || !r.value("available", false)) {
      s += md_row({"`" + name + "`", "not available in this build", "", "", "", "", "", "", "", "",
                   "", "", "", "", ""});
      continue;
    }
    const Json& sm = r.at("summary");
    s += md_row({"`" + name + "`", std::to_string(sm.at("runs").get<std::int64_t>()),
                 std::to_string(sm.at("found").get<std::int64_t>()),
                 std::to_string(sm.at("valid").get<std::int64_t>()),
                 md_number(sm.at("length").at("min"), 4), md_number(sm.at("length").at("mean"), 4),
                 md_number(sm.at("length").at("std"), 4), md_number(sm.at("turns").at("mean"), 2),
                 md_number(sm.at("turns").at("std"), 2), md_number(sm.at("turns").at("min"), 0),
                 md_number(sm.at("converged_at").at("mean"), 2),
                 md_number(sm.at("converged_at").at("std"), 2),
                 md_number(sm.at("converged_at_whole_curve").at("mean"), 2),
                 md_number(sm.at("drive_time_s").at("mean"), 2),
                 md_number(sm.at("wall_ms").at("mean"), 1)});
  }
  return s;
}

}  // namespace pathref::reproduce
