#include "pathref/sim/iaco_astar.hpp"

#include <string>

#include "pathref/core/error.hpp"

namespace pathref::planners {

Planner make_iaco_astar_planner() {
  Planner p;
  p.name = "iaco-astar";
  p.description =
      "Han (IJACSA) Fig. 6 IACO-A*: global path of an ant-colony planner; moving obstacles via `pathref simulate`";
  p.defaults = Json{{"global", "iaco-han"}};
  p.run = [defaults = p.defaults](const Request& req) {
    const Json params = merge_params(defaults, req.params);
    const std::string name = params.at("global").get<std::string>();
    if (name == "iaco-astar") throw UsageError("iaco-astar: global must name another planner");
    const Planner* g = find_planner(name);
    if (g == nullptr) throw UsageError("iaco-astar: unknown global planner '" + name + "'");
    Request inner = req;
    inner.params = Json::object();
    Result r = g->run(inner);
    r.params_used = Json{{"global", name}, {"global_params", r.params_used}};
    r.extra = Json{{"global", name}, {"global_extra", r.extra}, {"dynamic", "pathref simulate"}};
    return r;
  };
  return p;
}

}  // namespace pathref::planners
