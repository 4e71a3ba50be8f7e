#include "pathref/rules/modules.hpp"

namespace pathref::rules {
void register_all_modules(Registry& r) {
  register_rng_rules(r);
  register_grid_rules(r);
  register_metrics_rules(r);
  register_search_rules(r);
  register_mecanum_rules(r);
  register_shi2022_rules(r);
}
}  // namespace pathref::rules
