// Fuzz target: command-line values (`pathref plan --set KEY=VALUE`, `pathref eval RULE KEY=VALUE`,
// spec/cli.md): io::parse_cli_json_value, then the plan parameter merge planners::merge_params over
// the defaults of aco-classic, and the rule grid.index evaluated with the value as its width.
// The input is `KEY\nVALUE` (KEY: a parameter name; without a newline the key is `alpha`).
//
// INVARIANT: for every byte string t, parse_cli_json_value either returns a JSON value (depth at
// most 64), returns nullopt (the value is then the plain string), or throws pathref::UsageError
// naming the option and holding no raw control byte (never another exception, never UB, never a
// recursion deeper than 64 levels). merge_params returns the defaults with exactly the same keys,
// the set key holding the value, or throws pathref::UsageError; evaluating grid.index returns an
// object or throws a pathref::Error. A broken invariant traps (__builtin_trap).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/core/error.hpp"
#include "pathref/io/json_text.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rules/registry.hpp"

namespace {
using Json = nlohmann::json;

std::size_t depth(const Json& v) {  // iterative: the value is at most 64 deep if the layer holds
  std::size_t best = 0;
  std::vector<std::pair<const Json*, std::size_t>> stack{{&v, 0}};
  while (!stack.empty()) {
    const auto [j, d] = stack.back();
    stack.pop_back();
    if (!j->is_structured()) {
      best = std::max(best, d);
      continue;
    }
    best = std::max(best, d + 1);
    for (const Json& c : *j) stack.emplace_back(&c, d + 1);
  }
  return best;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pathref;
  const std::string_view in(reinterpret_cast<const char*>(data), size);
  const auto nl = in.find('\n');
  const std::string key(nl == std::string_view::npos ? std::string_view("alpha") : in.substr(0, nl));
  const std::string_view text = nl == std::string_view::npos ? in : in.substr(nl + 1);
  std::optional<Json> value;
  try {
    value = io::parse_cli_json_value(text, "--set " + io::printable(key, 40));
  } catch (const UsageError& e) {
    const std::string m = e.what();
    if (m.find("--set ") == std::string::npos) __builtin_trap();
    for (const char c : m)
      if (static_cast<unsigned char>(c) < 0x20) __builtin_trap();
    return 0;
  }
  const Json v = value ? std::move(*value) : Json(std::string(text));
  if (depth(v) > 64) __builtin_trap();

  const planners::Planner* p = planners::find_planner("aco-classic");
  if (p == nullptr) __builtin_trap();
  try {
    const Json merged = planners::merge_params(p->defaults, Json{{key, v}});
    if (merged.size() != p->defaults.size() || !merged.contains(key) || merged.at(key) != v) __builtin_trap();
    for (const auto& [k, d] : p->defaults.items())
      if (!merged.contains(k)) __builtin_trap();
  } catch (const UsageError&) {
  }

  const rules::Rule* rule = rules::registry().find("grid.index");
  if (rule == nullptr) __builtin_trap();
  try {
    const Json out = rules::evaluate(*rule, Json{{"width", v}, {"height", 6}, {"cell", Json::array({0, 0})}});
    if (!out.is_object()) __builtin_trap();
  } catch (const Error&) {
  }
  return 0;
}
