#include "pathref/planners/default_policy.hpp"

namespace pathref::planners {

grid::CornerPolicy default_policy(std::string_view planner_name) noexcept {
  if (planner_name == "aco-classic" || planner_name == "ga-classic") return grid::CornerPolicy::always;
  return grid::CornerPolicy::strict;
}

}  // namespace pathref::planners
