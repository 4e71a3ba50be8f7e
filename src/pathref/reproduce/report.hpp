#pragma once
/// \file report.hpp
/// What the reproduction reports share: claims with their verdicts, the formatting of numbers in
/// the markdown (always derived from the reproduce.json document, so the two cannot disagree),
/// the provenance block and the planner display names.
/// Spec: spec/reproduce.md (reproduce.judge, reproduce.json, reproduce.markdown)
#include <functional>
#include <optional>
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
};
[[nodiscard]] Json claim_json(const Claim& c);

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

/// "N claims: H hold, F do not hold, U cannot be tested." and one line per verdict listing the ids.
[[nodiscard]] std::string md_verdict_summary(const Json& claims);

/// The provenance section of the markdown.
[[nodiscard]] std::string md_provenance(const Json& provenance, const std::string& out_name);

/// The per-planner results table of one map: one row per planner (marker comment
/// `<!-- results:KEY -->` before it), columns of spec reproduce.markdown.
[[nodiscard]] std::string md_results_table(const Json& results, const std::vector<std::string>& order,
                                           const std::string& key);

}  // namespace pathref::reproduce
