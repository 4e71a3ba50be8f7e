#pragma once
/// \file default_policy.hpp
/// The corner policy of a run that names none (spec/grid.md grid.corner-policy, "Per-planner
/// default"): strict for every planner except the classic-MATLAB profile (aco-classic,
/// ga-classic: always, the G2D rule of the scripts they reproduce; spec/classic.md).
#include <string_view>

#include "pathref/grid/grid.hpp"

namespace pathref::planners {

/// The default corner policy of the planner named `planner_name` (any name: strict unless it is
/// one of the planners listed above). Spec: grid.corner-policy
[[nodiscard]] grid::CornerPolicy default_policy(std::string_view planner_name) noexcept;

}  // namespace pathref::planners
