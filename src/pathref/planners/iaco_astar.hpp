#pragma once
/// \file iaco_astar.hpp
/// Planner "iaco-astar", Han's IACO-A* fusion (Figure 6): its static result is the global path of
/// the underlying planner (default "iaco-han"; param "global"), i.e. the path the robot follows
/// when no moving obstacle interferes; `pathref simulate` runs the dynamic part (simulate.hpp).
/// Source: Han (IJACSA), Sec. III.B, Fig. 6. Spec: spec/han-sim.md (han.plan.iaco-astar)
#include <span>

#include "pathref/planners/planner.hpp"

namespace pathref::planners {

/// Planner "iaco-astar". Parameters: "global" (default "iaco-han") names the registered planner
/// giving the global path; every parameter k of every planner P in `others` is settable as
/// "P.k" (e.g. "iaco-han.dead_end"), and only those of the selected global planner may be set.
/// params_used = {"global": name} plus "name.k" for every parameter the global planner reports;
/// extra: {"global": name, "global_extra": ..., "dynamic": "pathref simulate"}.
/// Source: Han (IJACSA), Fig. 6. Spec: han.plan.iaco-astar.
/// Pre: the global planner is registered (looked up by name at run time) and is not iaco-astar;
/// a set "P.k" has P == global (UsageError otherwise).
/// Golden: golden/han-sim/han.plan.iaco-astar.json
[[nodiscard]] Planner make_iaco_astar_planner(std::span<const Planner> others);

/// The parameter name of global-planner parameter `param` of planner `planner`: "planner.param".
/// Spec: han.plan.iaco-astar.
[[nodiscard]] std::string global_param_name(std::string_view planner, std::string_view param);

}  // namespace pathref::planners
