#include "pathref/planners/registry_list.hpp"

#include "pathref/planners/search.hpp"
#include "pathref/planners/astar_kinematic.hpp"
#include "pathref/planners/ant_colony.hpp"
#include "pathref/planners/genetic.hpp"
#include "pathref/planners/hybrid.hpp"
#include "pathref/planners/iaco_astar.hpp"

namespace pathref::planners {
std::vector<Planner> all_planners() {
  std::vector<Planner> v;
  // search planners (spec/search.md): added by the search module
  v.push_back(make_astar_planner());
  v.push_back(make_dijkstra_planner());
  // kinematic-constraint A* (spec/sensors2023.md): the search core with an expansion rule
  v.push_back(make_astar_kinematic_planner());
  // ant-colony planners (spec/shi2022-aco.md, spec/han-iaco.md): added by the ACO module
  v.push_back(make_aco_planner());
  v.push_back(make_aco_classic_planner());
  v.push_back(make_iaco_shi_planner());
  v.push_back(make_iaco_shi_nomin_planner());
  v.push_back(make_iaco_han_planner());
  v.push_back(make_astar_han_planner());
  // genetic planners and GA-ACO hybrids (spec/shi2022-ga.md): added by the GA module
  v.push_back(make_ga_planner());
  v.push_back(make_iga_shi_planner());
  v.push_back(make_iga_shi_nomax_planner());
  v.push_back(make_hybrid_ga_aco_planner());
  v.push_back(make_iha_planner());
  v.push_back(make_ga_classic_planner());
  // cin2021 HGA-ACO planners (spec/cin2021-hga-aco.md)
  v.push_back(make_ga_cin_planner());
  v.push_back(make_aco_cin_planner());
  v.push_back(make_hga_aco_cin_planner());
  // IACO-A* (spec/han-sim.md): added by the simulation module
  // (its parameters are those of the planners above, as <planner>.<name>)
  v.push_back(make_iaco_astar_planner(v));
  return v;
}
}  // namespace pathref::planners
