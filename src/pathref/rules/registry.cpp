#include "pathref/rules/registry.hpp"

#include <algorithm>
#include <cmath>

#include "pathref/core/error.hpp"
#include "pathref/core/version.hpp"
#include "pathref/rules/modules.hpp"

namespace pathref::rules {

void Registry::add(Rule rule) {
  if (find(rule.id) != nullptr) throw UsageError("rule registered twice: " + rule.id);
  rules_.push_back(std::move(rule));
  std::sort(rules_.begin(), rules_.end(),
            [](const Rule& a, const Rule& b) { return a.id < b.id; });
}

const Rule* Registry::find(std::string_view id) const {
  for (const Rule& r : rules_)
    if (r.id == id) return &r;
  return nullptr;
}

const Registry& registry() {
  static const Registry instance = [] {
    Registry r;
    register_all_modules(r);
    return r;
  }();
  return instance;
}

const Json& arg(const Json& input, const char* key) {
  if (!input.is_object() || !input.contains(key))
    throw UsageError(std::string("missing input '") + key + "'");
  return input.at(key);
}

double arg_number(const Json& input, const char* key) {
  const Json& v = arg(input, key);
  if (v.is_number()) return v.get<double>();
  if (v.is_string()) {
    const auto s = v.get<std::string>();
    if (s == "inf") return INFINITY;
    if (s == "-inf") return -INFINITY;
    if (s == "nan") return NAN;
  }
  throw UsageError(std::string("input '") + key + "' must be a number");
}

long long arg_integer(const Json& input, const char* key) {
  const Json& v = arg(input, key);
  if (v.is_number_integer()) return v.get<long long>();
  throw UsageError(std::string("input '") + key + "' must be an integer");
}

std::string arg_string(const Json& input, const char* key) {
  const Json& v = arg(input, key);
  if (v.is_string()) return v.get<std::string>();
  throw UsageError(std::string("input '") + key + "' must be a string");
}

std::string opt_string(const Json& input, const char* key, const char* fallback) {
  if (input.is_object() && input.contains(key)) return arg_string(input, key);
  return fallback;
}

std::vector<double> arg_numbers(const Json& input, const char* key) {
  const Json& v = arg(input, key);
  if (!v.is_array()) throw UsageError(std::string("input '") + key + "' must be an array");
  std::vector<double> out;
  out.reserve(v.size());
  for (const Json& e : v) {
    if (!e.is_number()) throw UsageError(std::string("input '") + key + "' must hold numbers");
    out.push_back(e.get<double>());
  }
  return out;
}

Json number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return v;
}

void check_inputs(const Rule& rule, const Json& input) {
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

void add_grade(Json& doc, const std::string& id) {
  if (const auto g = reconstruction_grade(id)) {
    doc["grade"] = std::string(1, *g);
    doc["reconstructed"] = true;
  }
}

Json evaluate(const Rule& rule, const Json& input) {
  check_inputs(rule, input);
  Json doc{{"rule", rule.id}, {"input", input}, {"output", rule.eval(input)}};
  add_grade(doc, rule.id);
  return doc;
}

namespace {
Json fields_json(const std::vector<Field>& fields) {
  Json a = Json::array();
  for (const auto& f : fields) a.push_back({{"name", f.name}, {"type", f.type}, {"doc", f.doc}});
  return a;
}
}  // namespace

Json rule_list_json() {
  Json list = Json::array();
  for (const auto& r : registry().all()) {
    Json entry{{"id", r.id},
               {"summary", r.summary},
               {"function", r.function},
               {"inputs", fields_json(r.inputs)},
               {"outputs", fields_json(r.outputs)}};
    add_grade(entry, r.id);
    list.push_back(std::move(entry));
  }
  return Json{{"format", "pathref-rules"}, {"format_version", 1}, {"rules", list}};
}

}  // namespace pathref::rules
