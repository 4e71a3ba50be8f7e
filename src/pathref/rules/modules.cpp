#include "pathref/rules/modules.hpp"

#include <algorithm>
#include <vector>

#include "pathref/core/error.hpp"

namespace pathref::rules {
namespace {
struct Extensions {
  std::vector<ModuleRegistration> fns;
  bool sealed = false;
};
Extensions& extensions() {
  static Extensions e;
  return e;
}
}  // namespace

void add_extension_module(ModuleRegistration fn) {
  auto& e = extensions();
  if (std::find(e.fns.begin(), e.fns.end(), fn) != e.fns.end()) return;
  if (e.sealed) throw UsageError("add_extension_module called after the rule registry was built");
  e.fns.push_back(fn);
}

void register_all_modules(Registry& r) {
  register_rng_rules(r);
  register_grid_rules(r);
  register_metrics_rules(r);
  register_search_rules(r);
  register_mecanum_rules(r);
  register_shi2022_rules(r);
  register_han_rules(r);
  register_han_sim_rules(r);
  register_ga_planner_rules(r);
  register_aco_planner_rules(r);
  register_cin2021_rules(r);
  register_cin2021_ml_rules(r);
  register_stats_rules(r);
  register_sensors2023_dwa_rules(r);
  register_curves_rules(r);
  register_sensors2023_rules(r);
  extensions().sealed = true;
  for (const ModuleRegistration fn : extensions().fns) fn(r);
}
}  // namespace pathref::rules
