#include "pathref/planners/planner.hpp"
#include "pathref/planners/params_source.hpp"

#include <algorithm>

#include "pathref/core/error.hpp"
#include "pathref/planners/registry_list.hpp"

namespace pathref::planners {

void stop_if_interrupted(const Interrupt& interrupted) {
  if (interrupted && interrupted()) throw Interrupted("the run was interrupted at an iteration boundary");
}

const std::vector<Planner>& planners() {
  static const std::vector<Planner> all = [] {
    std::vector<Planner> v = all_planners();
    std::sort(v.begin(), v.end(), [](const Planner& a, const Planner& b) { return a.name < b.name; });
    return v;
  }();
  return all;
}

const Planner* find_planner(std::string_view name) {
  for (const Planner& p : planners())
    if (p.name == name) return &p;
  return nullptr;
}

std::string planner_names() {
  std::string known;
  for (const Planner& p : planners()) known += (known.empty() ? "" : ", ") + p.name;
  return known;
}

std::optional<std::pair<std::string, std::string>> first_bad_param(const Planner& p, const Json& params) {
  if (!params.is_object()) return std::nullopt;
  for (const auto& [k, v] : params.items()) {
    try {
      (void)merge_params(p.defaults, Json{{k, v}});
    } catch (const UsageError& e) {
      return std::make_pair(k, std::string(e.what()));
    }
  }
  return std::nullopt;
}

Result run_with_params_from(const Planner& p, const Request& req, const std::optional<ParamsSource>& source) {
  if (!source || req.params.empty()) return p.run(req);
  const auto located = [&](const Error& e) {
    const std::string what = source->pointer + ": the planner " + p.name + " refused its parameters: " + e.what();
    return source->line == 0 ? ParseError(source->file, what) : ParseError(source->file, source->line, source->column, what);
  };
  try {
    return p.run(req);
  } catch (const UsageError& e) {
    throw located(e);
  } catch (const DomainError& e) {
    throw located(e);
  }
}

Json merge_params(const Json& defaults, const Json& overrides) {
  Json out = defaults;
  for (const auto& [k, v] : overrides.items()) {
    if (!defaults.contains(k)) {
      std::string known;
      for (const auto& [dk, dv] : defaults.items()) known += (known.empty() ? "" : ", ") + dk;
      throw UsageError("unknown parameter '" + k + "' (known: " + (known.empty() ? "none" : known) + ")");
    }
    const Json& d = defaults.at(k);
    const bool same_kind = (d.is_number() && v.is_number() &&
                            (!d.is_number_integer() || v.is_number_integer())) ||
                           (d.type() == v.type());
    if (!same_kind)
      throw UsageError("parameter '" + k + "' must be of the same type as its default " + d.dump());
    out[k] = v;
  }
  return out;
}

}  // namespace pathref::planners
