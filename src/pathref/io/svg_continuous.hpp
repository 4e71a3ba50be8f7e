#pragma once
/// \file svg_continuous.hpp
/// The figure of a continuous planner's run (`pathref plan --algo rrt | s-rrt --svg`, the
/// cin2021-srrt reproduction): world rectangle, obstacle polygons (with their r-inflation outline),
/// the tree, the raw path, the shortcut path, start, goal, title and legend, like the paper's
/// Figure 5 (Cin et al. 2021, doi:10.1155/2021/8025730). Deterministic SVG 1.1 text.
/// Spec: spec/cli.md#plan-continuous (SVG)
#include <string>
#include <vector>

#include "pathref/continuous/srrt.hpp"

namespace pathref::io {

/// What the figure draws of the map (CGAL-free: polygons rounded to doubles).
struct ContinuousScene {
  std::vector<std::vector<continuous::Vec2>> polygons;
  double radius = 0.0;  ///< r, drawn as a grey outline of width 2r
  continuous::Vec2 lower, upper;  ///< world rectangle, lower < upper
};

/// The figure, 600 px on the longer side plus a legend. Pre: lower < upper (DomainError).
[[nodiscard]] std::string svg_continuous(const ContinuousScene& scene, const continuous::ContinuousRun& run,
                                         continuous::Vec2 start, continuous::Vec2 goal, const std::string& title);

}  // namespace pathref::io
