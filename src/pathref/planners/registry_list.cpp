#include "pathref/planners/registry_list.hpp"

#include "pathref/planners/search.hpp"

namespace pathref::planners {
std::vector<Planner> all_planners() {
  std::vector<Planner> v;
  // search planners (spec/search.md): added by the search module
  v.push_back(make_astar_planner());
  v.push_back(make_dijkstra_planner());
  return v;
}
}  // namespace pathref::planners
