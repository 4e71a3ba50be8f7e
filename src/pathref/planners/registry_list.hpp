#pragma once
/// \file registry_list.hpp
/// The list of planners. Each planner module provides a `Planner make_<name>_planner()`-style
/// function; add it to all_planners() in registry_list.cpp.
#include <vector>

#include "pathref/planners/planner.hpp"

namespace pathref::planners {
[[nodiscard]] std::vector<Planner> all_planners();
}  // namespace pathref::planners
