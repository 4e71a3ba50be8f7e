// `pathref eval RULE key=value ...` and `pathref eval --list`: ask the reference for any rule.
#include <fmt/core.h>

#include <string>
#include <vector>

#include "commands.hpp"
#include "pathref/io/json_text.hpp"
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
    std::optional<rules::Json> value = io::parse_cli_json_value(text, "input '" + key + "'");
    input[key] = value ? std::move(*value) : rules::Json(text);
  }
  return input;
}

/// "  [grade B, reconstructed]" for a reconstructed rule, "" otherwise (the text of eval --list).
std::string grade_tag(const std::string& id) {
  const auto g = reconstruction_grade(id);
  return g ? fmt::format("  [grade {}, reconstructed]", *g) : std::string();
}

}  // namespace

rules::Json rule_list_json() {
  rules::Json doc = rules::rule_list_json();
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
      rules::Json doc = rules::evaluate(*rule, input);
      stamp_version(doc);
      fmt::print("{}\n", doc.dump(2));
      return 0;
    };
  });
}

}  // namespace pathref::cli
