// `pathref eval RULE key=value ...` and `pathref eval --list`: ask the reference for any rule.
#include <fmt/core.h>

#include <string>
#include <vector>

#include "commands.hpp"
#include "pathref/core/error.hpp"
#include "pathref/core/version.hpp"
#include "pathref/rules/registry.hpp"

namespace pathref::cli {

namespace {

/// key=value: the value is parsed as JSON when it parses (numbers, arrays, true/false, objects),
/// otherwise taken as a plain string (so `policy=strict` needs no quotes).
rules::Json parse_assignments(const std::vector<std::string>& assignments) {
  rules::Json input = rules::Json::object();
  for (const std::string& a : assignments) {
    const auto eq = a.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError("expected key=value, got '" + a + "'");
    const std::string key = a.substr(0, eq);
    const std::string text = a.substr(eq + 1);
    if (input.contains(key)) throw UsageError("input '" + key + "' given more than once");
    rules::Json value = rules::Json::parse(text, nullptr, /*allow_exceptions=*/false);
    input[key] = value.is_discarded() ? rules::Json(text) : value;
  }
  return input;
}

/// UsageError when `input` has a key that is not one of the rule's inputs (spec/cli.md#eval):
/// a misspelt key must never be ignored in favour of the default.
void reject_unknown_inputs(const rules::Rule& rule, const rules::Json& input) {
  // A placeholder input (`<parameter>`: any planner parameter, checked by the planner itself
  // against its defaults, planners::merge_params) admits every key.
  for (const auto& f : rule.inputs)
    if (!f.name.empty() && f.name.front() == '<') return;
  for (const auto& [key, value] : input.items()) {
    bool known = false;
    for (const auto& f : rule.inputs) known = known || f.name == key;
    if (known) continue;
    std::string names;
    for (const auto& f : rule.inputs) names += (names.empty() ? "" : ", ") + f.name;
    throw UsageError("rule " + rule.id + " has no input '" + key + "' (its inputs: " +
                     (names.empty() ? std::string("none") : names) + ")");
  }
}

/// A reconstructed rule (cin2021, sensors2023) carries "grade" and "reconstructed": true
/// (spec/index/*.json; docs/versioning.md#confidence-grades); a paper's own equation carries neither.
void add_grade(rules::Json& doc, const std::string& id) {
  if (const auto g = reconstruction_grade(id)) {
    doc["grade"] = std::string(1, *g);
    doc["reconstructed"] = true;
  }
}

/// "  [grade B, reconstructed]" for a reconstructed rule, "" otherwise (the text of eval --list).
std::string grade_tag(const std::string& id) {
  const auto g = reconstruction_grade(id);
  return g ? fmt::format("  [grade {}, reconstructed]", *g) : std::string();
}

rules::Json fields_json(const std::vector<rules::Field>& fields) {
  rules::Json a = rules::Json::array();
  for (const auto& f : fields) a.push_back({{"name", f.name}, {"type", f.type}, {"doc", f.doc}});
  return a;
}

}  // namespace

rules::Json rule_list_json() {
  rules::Json list = rules::Json::array();
  for (const auto& r : rules::registry().all()) {
    rules::Json entry{{"id", r.id},
                      {"summary", r.summary},
                      {"function", r.function},
                      {"inputs", fields_json(r.inputs)},
                      {"outputs", fields_json(r.outputs)}};
    add_grade(entry, r.id);
    list.push_back(std::move(entry));
  }
  rules::Json doc{{"format", "pathref-rules"}, {"format_version", 1}, {"rules", list}};
  stamp_version(doc);
  return doc;
}

void add_eval_command(CLI::App& app, Action& run) {
  auto* cmd = app.add_subcommand("eval", "Evaluate one spec rule at the given inputs; prints JSON");
  static std::string rule_id;
  static std::vector<std::string> assignments;
  static bool list = false;
  static bool json = false;
  cmd->add_flag("--list", list, "List every rule with its inputs and outputs");
  cmd->add_flag("--json", json, "with --list: print the list as one JSON object (spec/cli.md#eval)");
  cmd->add_option("rule", rule_id, "Rule id, e.g. grid.coord");
  cmd->add_option("inputs", assignments, "key=value inputs (values are JSON or plain strings)");
  cmd->callback([&run] {
    run = [] {
      const auto& reg = rules::registry();
      if (json && !list) throw UsageError("--json goes with --list (pathref eval always prints JSON)");
      if (list && json) {
        fmt::print("{}\n", rule_list_json().dump(2));
        return 0;
      }
      if (list) {
        for (const auto& r : reg.all()) {
          fmt::print("{}{}  {}\n", r.id, grade_tag(r.id), r.summary);
          for (const auto& f : r.inputs) fmt::print("    in  {} : {} - {}\n", f.name, f.type, f.doc);
          for (const auto& f : r.outputs) fmt::print("    out {} : {} - {}\n", f.name, f.type, f.doc);
        }
        return 0;
      }
      if (rule_id.empty()) throw UsageError("eval needs a RULE (see pathref eval --list)");
      const rules::Rule* rule = reg.find(rule_id);
      if (rule == nullptr)
        throw UsageError("unknown rule '" + rule_id + "' (see pathref eval --list)");
      const rules::Json input = parse_assignments(assignments);
      reject_unknown_inputs(*rule, input);
      const rules::Json out = rule->eval(input);
      rules::Json doc{{"rule", rule->id}, {"input", input}, {"output", out}};
      add_grade(doc, rule->id);
      stamp_version(doc);
      fmt::print("{}\n", doc.dump(2));
      return 0;
    };
  });
}

}  // namespace pathref::cli
