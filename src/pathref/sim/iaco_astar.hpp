#pragma once
/// \file iaco_astar.hpp
/// Forwarding header, kept for one minor version (0.3.x; CHANGELOG): the planner "iaco-astar"
/// moved to pathref/planners/iaco_astar.hpp (issue 28, the layer order of docs/architecture.md).
#include "pathref/planners/iaco_astar.hpp"
