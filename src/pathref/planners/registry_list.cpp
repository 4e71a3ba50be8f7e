#include "pathref/planners/registry_list.hpp"

namespace pathref::planners {
std::vector<Planner> all_planners() {
  std::vector<Planner> v;
  // search planners (spec/search.md): added by the search module
  return v;
}
}  // namespace pathref::planners
