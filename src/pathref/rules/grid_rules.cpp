// JSON adapters for the grid rules. (Filled in by the grid module.)
#include "pathref/rules/modules.hpp"

namespace pathref::rules {
void register_grid_rules(Registry& /*r*/) {}
}  // namespace pathref::rules
