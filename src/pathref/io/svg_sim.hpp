#pragma once
/// \file svg_sim.hpp
/// The SVG of a simulation run, as Han's Figure 8: the grid map, the planned global path (dashed),
/// the robot's executed trajectory (green), each moving obstacle's track (black, dotted) with its
/// start marked, one orange circle per wait interval labelled with its duration, the local detours
/// (blue) and evasions (purple), and time marks along the robot's and the obstacles' tracks (every
/// 1 s, or 2, 5, 10, ... s for long runs, so that at most 20 are labelled per track).
/// Deterministic text (fixed decimals). Source: Han (IJACSA), Fig. 8. Spec: spec/han-sim.md#cli
#include <string>

#include "pathref/sim/simulate.hpp"

namespace pathref::io {

/// The figure of a run of scenario `s` with result `r` (r.trajectory and r.obstacle_tracks used).
[[nodiscard]] std::string svg_simulation(const sim::Scenario& s, const sim::SimResult& r);

}  // namespace pathref::io
