#pragma once
/// \file registry.hpp
/// Binds every spec rule id to the pure function that implements it, through a JSON adapter.
/// One table serves `pathref eval`, the golden runner and `pathref golden regenerate`, so the
/// three can never disagree about what a rule computes. The functions themselves live in
/// equations/, grid/, planners/ ...; an adapter only converts JSON <-> arguments.
/// Spec: spec/README.md#rules, spec/golden-format.md
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace pathref::rules {

using Json = nlohmann::json;

/// One named input or output of a rule, as `pathref eval --list` shows it.
struct Field {
  std::string name;
  std::string type;  ///< "number", "integer", "bool", "string", "cell" ([x,y]), "grid" (rows), ...
  std::string doc;
};

/// A spec rule as the library exposes it.
struct Rule {
  std::string id;        ///< stable spec id, e.g. "grid.coord"
  std::string summary;   ///< one line
  std::string function;  ///< qualified C++ name of the implementing function(s)
  std::vector<Field> inputs;
  std::vector<Field> outputs;
  /// Evaluates the rule. `input` is the test's input merged over its group's params, plus the
  /// interpretation options by note name. Throws pathref::Error subclasses on bad input.
  std::function<Json(const Json& input)> eval;
};

class Registry {
 public:
  void add(Rule rule);
  /// nullptr if unknown.
  [[nodiscard]] const Rule* find(std::string_view id) const;
  [[nodiscard]] const std::vector<Rule>& all() const noexcept { return rules_; }

 private:
  std::vector<Rule> rules_;
};

/// The registry of every rule the library implements (built once, sorted by id).
[[nodiscard]] const Registry& registry();

/// UsageError when `input` has a key that is not one of the rule's inputs, naming the valid ones
/// (spec/cli.md#eval): a misspelt key must never be ignored in favour of the default. A rule with
/// a placeholder input (`<parameter>`, checked by the planner itself) admits every key.
void check_inputs(const Rule& rule, const Json& input);

/// Sets "grade" (A/B/C) and "reconstructed": true on `doc` when `id` is a reconstructed rule
/// (spec/index; docs/versioning.md#confidence-grades); leaves it unchanged otherwise.
void add_grade(Json& doc, const std::string& id);

/// One evaluation as `pathref eval RULE` and `pathref.eval` report it (spec/cli.md#eval): checks
/// `input` (check_inputs), runs the rule and returns {"rule", "input", "output"} plus the grade of a
/// reconstructed rule (add_grade), without the version stamp the CLI adds.
[[nodiscard]] Json evaluate(const Rule& rule, const Json& input);

/// Every rule with its inputs and outputs (and grade): the "pathref-rules" v1 object of
/// `pathref eval --list --json` and `pathref.rules()` (spec/cli.md#eval), without the version
/// stamp the CLI adds.
[[nodiscard]] Json rule_list_json();

// ---- JSON argument helpers for adapters (throw UsageError naming the missing/bad key) ----
[[nodiscard]] const Json& arg(const Json& input, const char* key);
[[nodiscard]] double arg_number(const Json& input, const char* key);
[[nodiscard]] long long arg_integer(const Json& input, const char* key);
[[nodiscard]] std::string arg_string(const Json& input, const char* key);
/// The string option `key`, or `fallback` when absent.
[[nodiscard]] std::string opt_string(const Json& input, const char* key, const char* fallback);
[[nodiscard]] std::vector<double> arg_numbers(const Json& input, const char* key);
/// A double as JSON: finite values as numbers, non-finite ones as "inf", "-inf", "nan".
[[nodiscard]] Json number(double v);

}  // namespace pathref::rules
