#pragma once
/// \file svg.hpp
/// SVG figures like the papers' (Shi et al. 2022, Figures 8/11: grid maps with black obstacle
/// cells, paths through cell centres, start lower left; Figures 9/12: convergence curves, best
/// path length per iteration, one line per algorithm, with a legend).
/// Output is self-contained SVG 1.1 text (no scripts, no external fonts or images), deterministic
/// for the same input (numbers printed with a fixed number of decimals).
/// Spec: spec/cli.md#svg-figures
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pathref/geometry/vec2.hpp"
#include "pathref/grid/grid.hpp"

namespace pathref::io {

/// One line of a chart: points (x[i], y[i]). Pre: x.size() == y.size() (DomainError).
/// Non-finite y values (e.g. "no solution yet" = +inf) are skipped: the line is broken there.
struct Series {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;
};

struct ChartOptions {
  std::string title;
  std::string x_label;
  std::string y_label;
};

/// A line chart with axes, ticks, axis labels, title and a legend listing every series label.
/// Each series is drawn as one <polyline> per unbroken run of finite points (class "series").
/// An empty series list, or series without finite points, gives a chart with axes and legend only.
[[nodiscard]] std::string svg_line_chart(const std::vector<Series>& series, const ChartOptions& opt);

/// One path drawn on a map: a polyline through the centres of its cells, in the legend as `label`;
/// or, when `points` is non-empty, a polyline through those map points (continuous paths such as
/// a sampled B-spline: map units, cell (x, y) = [x, x+1] x [y, y+1]). `markers` draws a dot on
/// every vertex (key nodes); `dashed` a dashed line.
struct PathLayer {
  std::string label;
  std::vector<grid::Cell> path;
  std::vector<geometry::Vec2> points = {};
  bool markers = false;
  bool dashed = false;
};

/// The grid map: a white <rect class="map"> for the whole grid, one black <rect class="obstacle">
/// per blocked cell, grid lines (a single <path class="gridlines">, only when W and H <= 100),
/// cell coordinate labels along the bottom and left edges (<g class="axis-labels">, same limit),
/// (0,0) drawn at the LOWER left, the start ("S", green) and goal ("T", red) markers when given,
/// each non-empty path as one <polyline class="path"> through cell centres, a legend
/// (<g class="legend">) with one entry per path label plus "start"/"goal"/"obstacle", and the title.
/// Pre: start/goal, when given, and every path cell are in bounds (DomainError).
[[nodiscard]] std::string svg_map(const grid::Grid& g, std::optional<grid::Cell> start,
                                  std::optional<grid::Cell> goal,
                                  const std::vector<PathLayer>& paths, const std::string& title);

/// Map (left) and convergence chart (right) side by side in one figure, as `pathref plan --svg`
/// writes for iterative planners. Both panels have the same content as svg_map / svg_line_chart,
/// each inside a translated <g class="panel">.
[[nodiscard]] std::string svg_map_and_chart(const grid::Grid& g, std::optional<grid::Cell> start,
                                            std::optional<grid::Cell> goal,
                                            const std::vector<PathLayer>& paths,
                                            const std::string& map_title,
                                            const std::vector<Series>& series,
                                            const ChartOptions& chart);

/// Escapes & < > " ' for XML text and attribute values.
[[nodiscard]] std::string xml_escape(std::string_view text);

}  // namespace pathref::io
