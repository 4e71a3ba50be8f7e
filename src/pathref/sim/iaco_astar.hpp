#pragma once
/// \file iaco_astar.hpp
/// Planner "iaco-astar", Han's IACO-A* fusion (Figure 6): its static result is the global path of
/// the underlying planner (default "iaco-han"; param "global"), i.e. the path the robot follows
/// when no moving obstacle interferes; `pathref simulate` runs the dynamic part (simulate.hpp).
/// Source: Han (IJACSA), Sec. III.B, Fig. 6. Spec: spec/han-sim.md (han.plan.iaco-astar)
#include "pathref/planners/planner.hpp"

namespace pathref::planners {

/// Planner "iaco-astar": param "global" (default "iaco-han") names the registered planner giving
/// the global path; extra: {"global": name, "dynamic": "pathref simulate"}.
/// Source: Han (IJACSA), Fig. 6. Spec: han.plan.iaco-astar.
/// Pre: the global planner is registered and is not iaco-astar itself (UsageError).
[[nodiscard]] Planner make_iaco_astar_planner();

}  // namespace pathref::planners
