// JSON adapters for the search rules. (Filled in by the search module.)
#include "pathref/rules/modules.hpp"

namespace pathref::rules {
void register_search_rules(Registry& /*r*/) {}
}  // namespace pathref::rules
