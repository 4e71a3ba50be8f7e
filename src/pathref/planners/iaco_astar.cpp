#include "pathref/planners/iaco_astar.hpp"

#include <algorithm>
#include <string>
#include <string_view>

#include "pathref/core/error.hpp"

namespace pathref::planners {

namespace {
constexpr std::string_view self_name = "iaco-astar";
constexpr std::string_view default_global = "iaco-han";
}  // namespace

std::string global_param_name(std::string_view planner, std::string_view param) {
  return std::string(planner) + "." + std::string(param);
}

Planner make_iaco_astar_planner(std::span<const Planner> others) {
  Planner p;
  p.name = std::string(self_name);
  p.description =
      "Han (IJACSA) Fig. 6 IACO-A*: global path of the planner `global` (default iaco-han; its "
      "parameters as `<planner>.<name>`); moving obstacles via `pathref simulate`, spec/han-sim.md";
  p.defaults = Json{{"global", std::string(default_global)}};
  for (const Planner& o : others) {
    if (o.name == self_name) continue;
    p.bytes_per_cell = std::max(p.bytes_per_cell, o.bytes_per_cell);  // the largest global planner's
    for (const auto& [k, v] : o.defaults.items()) p.defaults[global_param_name(o.name, k)] = v;
  }
  p.run = [defaults = p.defaults](const Request& req) {
    const Json params = merge_params(defaults, req.params);
    const std::string name = params.at("global").get<std::string>();
    if (name == self_name) throw UsageError("iaco-astar: global must name another planner");
    const Planner* g = find_planner(name);
    if (g == nullptr) throw UsageError("iaco-astar: unknown global planner '" + name + "'");
    const std::string prefix = name + ".";
    Request inner = req;
    inner.params = Json::object();
    for (const auto& [k, v] : req.params.items()) {
      if (k == "global") continue;
      if (k.compare(0, prefix.size(), prefix) != 0)
        throw UsageError("iaco-astar: parameter '" + k + "' does not belong to the global planner '" + name +
                         "' (its parameters are named " + prefix + "<name>)");
      inner.params[k.substr(prefix.size())] = v;
    }
    Result r = g->run(inner);
    Json used = Json{{"global", name}};
    for (const auto& [k, v] : r.params_used.items()) used[global_param_name(name, k)] = v;
    r.params_used = std::move(used);
    r.extra = Json{{"global", name}, {"global_extra", r.extra}, {"dynamic", "pathref simulate"}};
    return r;
  };
  return p;
}

}  // namespace pathref::planners
