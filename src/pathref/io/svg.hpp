#pragma once
/// \file svg.hpp
/// SVG figures like the papers' (Shi et al. 2022, Figures 8/11: grid maps with black obstacle
/// cells, paths through cell centres, start lower left; Figures 9/12: convergence curves, best
/// path length per iteration, one line per algorithm, with a legend).
/// Output is self-contained SVG 1.1 text (no scripts, no external fonts or images), deterministic
/// for the same input (numbers printed with a fixed number of decimals).
/// Spec: spec/cli.md#svg-figures
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pathref/geometry/vec2.hpp"
#include "pathref/grid/grid.hpp"

namespace pathref::io {

/// One line of a chart: points (x[i], y[i]). Pre: x.size() == y.size() (DomainError).
/// Non-finite y values (e.g. "no solution yet" = +inf) are skipped: the line is broken there.
/// `absent`: why the series may have no finite point (shown in the legend then, e.g. "no feasible
/// run"; default "no finite value"). `marks`: x values marked on the line with a ring (e.g. the
/// iteration where a run converged).
struct Series {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;
  std::string absent = {};
  std::vector<double> marks = {};
};

/// y axis: automatic (log when plot::wants_log), or forced.
enum class YScale { automatic, linear, log };

/// `caption`: a note printed under the legend. `gap_note`: what a break in a line means (printed
/// when some series has one; default "a line is broken where its value is undefined").
struct ChartOptions {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::string caption = {};
  std::string gap_note = {};
  YScale y_scale = YScale::automatic;
};

/// A line chart (spec/figures.md): axes with nice ticks (log when one series dwarfs the rest,
/// "(log scale)" added to the y label), axis labels, a left-aligned title and, below the data, a
/// legend listing every series; a series without finite points is listed as absent with its
/// reason. Each series is drawn as one <polyline class="series"> per unbroken run of finite points.
[[nodiscard]] std::string svg_line_chart(const std::vector<Series>& series, const ChartOptions& opt);

/// A grouped bar chart: one group per `groups` entry, one bar per series in `bars` (bars[k].y[g] is
/// the value of series k in group g; x unused; the first series grey, the others in the palette),
/// each value printed above its bar (with fewer decimals when needed to fit); y from 0 to `y_max` (ticks every tenth), or to
/// the data's nice maximum when y_max is NaN. Title, axis, legend below and caption as
/// svg_line_chart.
struct BarChart {
  std::string title;
  std::string y_label;
  std::vector<std::string> groups;
  std::vector<Series> bars;
  double y_max = std::numeric_limits<double>::quiet_NaN();
  int value_decimals = 1;
  std::string caption = {};
};
[[nodiscard]] std::string svg_bar_chart(const BarChart& chart);

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
/// cell coordinate labels along the bottom and left edges (<g class="axis-labels">, same limit,
/// every k-th cell so the labels do not touch), (0,0) drawn at the LOWER left, the start ("S",
/// green) and goal ("T", vermillion) markers when given, each non-empty path as one
/// <polyline class="path"> through cell centres (Okabe–Ito colour and dash pattern per path), the
/// title above and a legend (<g class="legend">) below with one entry per path label plus
/// "start"/"goal"/"obstacle".
/// With `cell_numbers` (figures.cell-numbers, as Shi's Fig. 1A), every cell but the start and the
/// goal also shows its number i = y·W + x (rule grid.index) in grey; UsageError when the map's cells
/// are too small for the longest number at the minimum font size (the message names the limit).
/// Pre: start/goal, when given, and every path cell are in bounds (DomainError).
[[nodiscard]] std::string svg_map(const grid::Grid& g, std::optional<grid::Cell> start,
                                  std::optional<grid::Cell> goal,
                                  const std::vector<PathLayer>& paths, const std::string& title,
                                  bool cell_numbers = false);

/// Map (top) and convergence chart (below) in one column-wide figure, as `pathref plan --svg`
/// writes for iterative planners. Both panels have the same content as svg_map / svg_line_chart,
/// each inside a <g class="panel">.
[[nodiscard]] std::string svg_map_and_chart(const grid::Grid& g, std::optional<grid::Cell> start,
                                            std::optional<grid::Cell> goal,
                                            const std::vector<PathLayer>& paths,
                                            const std::string& map_title,
                                            const std::vector<Series>& series,
                                            const ChartOptions& chart, bool cell_numbers = false);

/// Escapes & < > " ' for XML text and attribute values.
[[nodiscard]] std::string xml_escape(std::string_view text);

}  // namespace pathref::io
