#pragma once
/// \file report.hpp
/// What the reproduction reports share: claims with their verdicts, the formatting of numbers in
/// the markdown (always derived from the reproduce.json document, so the two cannot disagree),
/// the provenance block and the planner display names.
/// Spec: spec/reproduce.md (reproduce.judge, reproduce.json, reproduce.markdown)
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/reproduce/stats.hpp"

namespace pathref::reproduce {

using Json = nlohmann::json;

/// Who ran a reproduction, how and where; recorded in the JSON and the markdown.
struct Provenance {
  std::string command;     ///< the exact command line
  std::string build_type;  ///< CMAKE_BUILD_TYPE of the binary
  std::string date_utc;    ///< ISO 8601, UTC
  std::string machine;     ///< uname -srm, CPU model, cores
  std::string pathref_version;
  int jobs = 1;                    ///< --jobs: threads that ran the runs (reproduce.execution)
  std::string execution = "run";   ///< "run" (here) | "merge" (runs done by --emit-jobs commands)
};
[[nodiscard]] Json provenance_json(const Provenance& p);

/// Progress callback (one line per step, to stderr in the CLI); may be empty.
using Progress = std::function<void(const std::string&)>;

/// One claim of a paper with pathref's answer. `paper` is the printed text ("29.8", "-46 %",
/// "IHA < GA"), `ours` pathref's value as printed in the report (derived from the JSON numbers),
/// `rule` how the verdict was decided.
struct Claim {
  std::string id;
  std::string text;
  std::string source;  ///< table/row/column or section of the paper
  std::string paper;
  std::string ours;
  std::string rule;
  Verdict verdict = Verdict::untestable;
  std::string note;
  // Issue 11 (reproduce.judge): the verdict's direction, the verdict on all 2n runs, the statistics
  // that decided both, and the readings/reconstructions the verdict rests on.
  Direction direction = Direction::none;
  std::optional<Verdict> verdict_2n{};  ///< nullopt: not judged at 2n (deterministic or untestable)
  Direction direction_2n = Direction::none;
  std::string ours_2n{};
  Json statistics = nullptr;          ///< {"n": value_json | comparison_json, "2n": ...}
  std::vector<std::string> depends_on{};  ///< e.g. "reading converge=ga_phase (alternative: T3.8w)"
};
/// The reconstructed rules a claim's verdict rests on (cin2021, sensors2023: equations lost in
/// extraction, graded A/B/C in spec/index; docs/versioning.md#confidence-grades): sets the claim's
/// "rules" to [{"id", "grade"}] and its "grade" to the lowest of them (C below B below A). Every id
/// must be a graded rule (std::logic_error otherwise: a report that names a wrong rule is a bug).
/// Spec: reproduce.markdown.
void attach_rules(Json& claim, const std::vector<std::string>& rule_ids);
/// attach_rules(c, rules_for(c["id"])) for every claim of the array `claims`.
void attach_rules_all(Json& claims, const std::function<std::vector<std::string>(const std::string& id)>& rules_for);

/// {"id", "text", "source", "paper", "ours", "rule", "verdict" (to_string), "direction",
/// "verdict_text", "at_2n": {"verdict", "direction", "verdict_text", "ours"} | null, "changed",
/// "change_note", "statistics", "depends_on", "note"}. Spec: reproduce.json.
[[nodiscard]] Json claim_json(const Claim& c);

/// Why a verdict changed between n and 2n runs, in words ("" when it did not). Spec: reproduce.markdown.
[[nodiscard]] std::string verdict_change_note(Verdict at_n, Direction dir_n, Verdict at_2n, Direction dir_2n);

/// Judges a claimed value on the first n runs and on all 2n (reproduce.judge): assess_value with
/// `statistic` on each (n >= 2 each, else the claim is untestable), writes c.ours / c.ours_2n
/// ("mean 30.1234 [29.9, 30.3]" with `decimals`), verdicts, directions, statistics, rule.
/// `runs_2n` may be empty (not judged at 2n). Spec: reproduce.judge, stats.equivalence.
void value_claim(Claim& c, std::span<const double> runs_n, std::span<const double> runs_2n, double paper,
                 Quantity quantity, Sense sense, BootStatistic statistic, const BootstrapOptions& options,
                 int decimals);
/// A claimed value computed exactly (a deterministic planner): assess_exact_value. Spec: reproduce.judge.
void exact_value_claim(Claim& c, double x, double paper, Quantity quantity, Sense sense, int decimals);
/// "a reduces Q by about P % against b": bootstrap_two_sample_ci(a, b, reduction_percent) at n and
/// 2n, quantity percent, higher is better. Untestable when a sample has < 2 values or b has a value
/// <= 0. Spec: reproduce.judge.
void reduction_claim(Claim& c, std::span<const double> a_n, std::span<const double> b_n,
                     std::span<const double> a_2n, std::span<const double> b_2n, double paper_percent,
                     const BootstrapOptions& options);
/// "A < B" (or "A > B") on the runs: compare_samples at n and at 2n (Mann-Whitney decides, Welch
/// printed). Untestable when a sample is empty. Spec: reproduce.judge, stats.compare.
void comparison_claim(Claim& c, std::span<const double> a_n, std::span<const double> b_n,
                      std::span<const double> a_2n, std::span<const double> b_2n, Claimed claim, int decimals);

/// {"n", "mean", "std", "min", "max"} of a Summary (null where undefined). Spec: reproduce.json.
[[nodiscard]] Json summary_stats_json(const Summary& s);
/// [lo, hi]. Spec: reproduce.json.
[[nodiscard]] Json interval_json(const Interval& ci);
/// {"verdict": to_string(v), "direction": to_string(d), "text": verdict_text(v, d)}.
[[nodiscard]] Json judgement_json(const Judgement& j);
/// A claimed value's statistics: {"kind": "value", "summary", "statistic", "ci", "level",
/// "resamples", "seed", "paper", "quantity", "margin", "band": [P - m, P + m], "judgement"}.
/// Spec: stats.equivalence, reproduce.json.
[[nodiscard]] Json value_json(const ValueAssessment& v, const BootstrapOptions& options);
/// A comparison's statistics: {"kind": "comparison", "claim": "a_less" | "a_greater", "alpha",
/// "a", "b" (summaries), "test": "Mann-Whitney U (two-sided)", "mann_whitney": {"u_a", "u_b",
/// "exact", "z", "p"}, "welch": {"mean_difference", "t", "df", "p"} | null, "judgement"}.
/// Spec: stats.compare, reproduce.json.
[[nodiscard]] Json comparison_json(const ComparisonAssessment& c);

/// A number of the JSON document for the markdown: fixed(v, decimals), or "—" when null/absent.
/// Spec: reproduce.markdown.
[[nodiscard]] std::string md_number(const Json& v, int decimals);

/// doc[path...] or null when any key is missing. Pre: none.
[[nodiscard]] const Json& at_or_null(const Json& doc, std::initializer_list<std::string_view> path);

/// Display name of a planner in the reports ("iha" -> "IHA"); the name itself when unknown.
[[nodiscard]] std::string planner_label(std::string_view name);

/// "| a | b |" from cells.
[[nodiscard]] std::string md_row(const std::vector<std::string>& cells);

/// The claims table (one row per claim) of the markdown.
[[nodiscard]] std::string md_claims(const Json& claims);

/// "N claims: H hold, F do not hold, S not significant, I inconclusive, U cannot be tested." and
/// one line per verdict listing the ids (the verdicts at n; then the claims whose verdict changes
/// at 2n).
/// With `checks` = true the same for pathref's own checks ("N checks: ...", no n/2n wording).
[[nodiscard]] std::string md_verdict_summary(const Json& claims, bool checks = false);

/// The provenance section of the markdown.
[[nodiscard]] std::string md_provenance(const Json& provenance, const std::string& out_name);

/// The per-planner results table of one map: one row per planner (marker comment
/// `<!-- results:KEY -->` before it), columns of spec reproduce.markdown.
[[nodiscard]] std::string md_results_table(const Json& results, const std::vector<std::string>& order,
                                           const std::string& key);

}  // namespace pathref::reproduce
