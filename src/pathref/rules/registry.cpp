#include "pathref/rules/registry.hpp"

#include <algorithm>
#include <cmath>

#include "pathref/core/error.hpp"
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

}  // namespace pathref::rules
