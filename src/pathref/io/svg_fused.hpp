#pragma once
/// \file svg_fused.hpp
/// The figure of a fused run (sensors2023 Fig. 9 and 13): the map (black obstacle cells), the
/// temporary obstacles (grey, with their times), the global path (blue dashed) and its key nodes,
/// the robot's track (blue solid) with time marks, the moving obstacles' tracks (orange) with the
/// same time marks and their end positions, start (triangle) and goal (circle). The view is the
/// bounding box of the map and of everything drawn, so the figure fits inside its canvas.
/// Spec: spec/sensors2023-dwa.md (sensors2023.sim.run), spec/cli.md#svg-figures
#include <string>

#include "pathref/sim/fused.hpp"

namespace pathref::io {

/// The figure of the fused run `r` of scenario `s`.
[[nodiscard]] std::string svg_fused(const dwa::FusedScenario& s, const dwa::FusedResult& r);

}  // namespace pathref::io
