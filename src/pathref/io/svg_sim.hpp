#pragma once
/// \file svg_sim.hpp
/// The SVG of a simulation run, as Han's Figure 8: the grid map, the planned global path (dashed),
/// the robot's executed trajectory (green), each moving obstacle's track (black, dotted) with its
/// start marked, the places where the robot waited (orange circles) and the local detours (blue).
/// Deterministic text (fixed decimals). Source: Han (IJACSA), Fig. 8. Spec: spec/han-sim.md#cli
#include <string>

#include "pathref/sim/simulate.hpp"

namespace pathref::io {

/// The figure of a run of scenario `s` with result `r` (r.trajectory and r.obstacle_tracks used).
[[nodiscard]] std::string svg_simulation(const sim::Scenario& s, const sim::SimResult& r);

}  // namespace pathref::io
