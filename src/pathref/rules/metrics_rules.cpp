// JSON adapters for the metrics rules. (Filled in by the metrics module.)
#include "pathref/rules/modules.hpp"

namespace pathref::rules {
void register_metrics_rules(Registry& /*r*/) {}
}  // namespace pathref::rules
