#pragma once
/// \file runner.hpp
/// The generic golden-vector runner (spec/golden-format.md): checks the library against every
/// golden file through the rule registry, and regenerates expected values on request.
#include <filesystem>
#include <string>
#include <vector>
#include <string_view>

#include <nlohmann/json.hpp>

namespace pathref::golden {

using Json = nlohmann::json;

enum class Status { pass, fail, skipped };

struct CaseResult {
  std::string file;
  std::string rule;
  long long tc_id = 0;
  Status status = Status::pass;
  std::string message;  ///< why it failed or was skipped
};

struct Report {
  std::vector<CaseResult> cases;
  [[nodiscard]] std::size_t count(Status s) const;
};

/// The input a rule sees for one test: group params, then the test's input over them, then the
/// interpretation options (note "param" := chosen option).
[[nodiscard]] Json compose_input(const Json& doc, const Json& group, const Json& test);

/// Tolerant comparison of an expected value with an actual one (numbers within
/// max(abs, rel*|expected|); integers, strings, booleans exactly; arrays/objects recursively).
/// Returns an empty string on match, else a description of the first difference.
[[nodiscard]] std::string compare(const Json& expected, const Json& actual, const Json& tolerance,
                                  const std::string& where = "");

/// Judges one answer to a test (spec/golden-format.md, "Result semantics"): `actual` is the rule's
/// outputs, or {"error": KIND, "message": ...} when it raised. Returns "" when the answer passes
/// (an `invalid` test: the same error kind; otherwise no error and outputs matching `expected`
/// under the test's or else the group's tolerance), else what differs. Used by the library runner
/// and by `pathref conform` (spec/conform.md).
[[nodiscard]] std::string judge(const Json& group, const Json& test, const Json& actual);

/// Every golden file under `dir` (recursively, *.json outside schema/), sorted. UsageError when
/// `dir` is not a directory or holds no such file (0 vectors never pass).
[[nodiscard]] std::vector<std::filesystem::path> golden_files(const std::filesystem::path& dir);

/// Reads one golden file through the JSON layer (io::parse_json_text: depth, size, duplicate keys,
/// BOM) and checks its shape with check_document_shape before any vector runs.
[[nodiscard]] Json read_document(const std::filesystem::path& path);

/// The schema constraints the runner relies on (spec/golden-format.md#runner-checks): `rule` a
/// string; `testGroups` a non-empty array; each group a `tolerance` {abs >= 0, rel >= 0[, ulps >= 0]}
/// and a non-empty `tests`; each test an integer `tcId` >= 1, `result` one of valid / invalid /
/// acceptable, an `expected`, and a test `tolerance` as a group's; `numberOfTests`, when present,
/// equal to the number of tests. A ParseError `FILE:LINE:COLUMN: POINTER: what was expected` at the
/// offending value (`text`: the file's JSON text; empty for a document that came from no file).
void check_document_shape(const Json& doc, const std::string& file, std::string_view text);

/// Checks one parsed golden document. `file` is only used in messages.
[[nodiscard]] Report check_document(const Json& doc, const std::string& file);
/// Checks every *.json file under `dir` (recursively), skipping schema/.
[[nodiscard]] Report check_directory(const std::filesystem::path& dir);

/// Recomputes expected values of a document with the library (see spec/golden-format.md,
/// "Regeneration"): fills every null `expected`, rewrites characterization groups, and
/// verifies (never rewrites) hand- and paper-provenance groups. Throws pathref::Error when a
/// verified group disagrees. Returns the new document.
[[nodiscard]] Json regenerate_document(const Json& doc, const std::string& file);

/// Canonical text of a golden document: byte for byte Python's
/// `json.dumps(doc, indent=2, sort_keys=True, ensure_ascii=False) + "\n"` (floats as Python's
/// repr: shortest round-trip digits), which tools/golden-lint requires (spec/golden-format.md).
[[nodiscard]] std::string canonical_text(const Json& doc);

}  // namespace pathref::golden
