#pragma once
/// \file plot.hpp
/// The plotting layer every pathref figure is drawn with (maps, charts, simulations, bar charts):
/// the canvas and its root element (viewBox, font stack, white background), text measurement,
/// wrapped left-aligned titles and captions, legends below the data area, nice and log axes, the
/// Okabe–Ito palette with dash patterns, a world-to-canvas frame and a label placer that keeps
/// labels inside the canvas and off each other. Figure code composes these and repeats no layout
/// arithmetic of its own. Spec: spec/figures.md (rules figures.*).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pathref/grid/grid.hpp"

namespace pathref::io::plot {

/// figures.canvas: every figure is this many user units wide (a 252 pt column at 2 units per pt);
/// its height follows from its content.
inline constexpr double kWidth = 504.0;
/// figures.text: the smallest font size, 14 units = 7 pt at column width; titles are larger.
inline constexpr double kFont = 14.0;
inline constexpr double kTitleFont = 16.0;
/// figures.font: the font stack declared on every root element.
inline constexpr const char* kFontStack = "DejaVu Sans, Helvetica, Arial, sans-serif";
/// figures.text-width: estimated advance of one character, in em (DejaVu Sans, the widest of the
/// stack, averages about 0.55 em over mixed text and 0.64 em over digits; 0.66 is conservative).
inline constexpr double kCharEm = 0.66;
/// Line height in em, and the outer margin of every figure in units.
inline constexpr double kLineEm = 1.3;
inline constexpr double kMargin = 10.0;

/// Number of characters (UTF-8 code points) of `utf8`.
[[nodiscard]] std::size_t glyphs(std::string_view utf8);
/// figures.text-width: the estimated width of `text` at font size `size`: glyphs × size × kCharEm.
[[nodiscard]] double text_width(std::string_view text, double size = kFont);
/// The lines of `text` broken at spaces so that each is at most `max_width` wide (a word longer
/// than a line is cut between characters). Empty text gives no lines.
[[nodiscard]] std::vector<std::string> wrap(std::string_view text, double size, double max_width);
/// figures.title: `text` with every path-like word replaced by its last component
/// ("../shared/data/a.map" -> "a.map"), so a title never shows a file path. A word is path-like
/// when it contains '/' and starts with "/", "./" or "../", or has two or more '/', or its last
/// component has an extension ("maps/a.map"); "1/d" and "km/h" are kept.
[[nodiscard]] std::string strip_paths(std::string_view text);
/// A coordinate with two decimals (deterministic, short).
[[nodiscard]] std::string num(double v);
/// Escapes & < > " ' for XML text and attribute values.
[[nodiscard]] std::string escape(std::string_view text);

/// figures.colours: the i-th colour of the Okabe–Ito palette (colour-blind safe), cycling; black
/// is reserved for obstacles and is not in the cycle.
[[nodiscard]] const char* colour(std::size_t i);
/// figures.colours: the i-th dash pattern ("" = solid), so series differ in greyscale too.
[[nodiscard]] const char* dash(std::size_t i);
/// Named colours of the palette for fixed roles (start, goal, ...).
inline constexpr const char* kOrange = "#E69F00";
inline constexpr const char* kSky = "#56B4E9";
inline constexpr const char* kGreen = "#009E73";
inline constexpr const char* kYellow = "#F0E442";
inline constexpr const char* kBlue = "#0072B2";
inline constexpr const char* kVermillion = "#D55E00";
inline constexpr const char* kPurple = "#CC79A7";
inline constexpr const char* kGrey = "#999999";

/// A text element, `anchor` start|middle|end, optional class and fill.
[[nodiscard]] std::string text(double x, double y, std::string_view s, double size = kFont,
                               std::string_view anchor = "start", std::string_view cls = "",
                               std::string_view fill = "");
/// A polyline through `pts` (canvas units) with the given stroke, width and dash pattern.
[[nodiscard]] std::string polyline(const std::vector<std::pair<double, double>>& pts,
                                   std::string_view cls, std::string_view stroke, double width,
                                   std::string_view dasharray = "", std::string_view extra = "");

/// An axis-aligned box in canvas units.
struct Box {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
  [[nodiscard]] bool overlaps(const Box& o) const;
  [[nodiscard]] bool inside(const Box& o) const;
};

/// figures.axes: an axis range with its ticks. Linear: a "nice" step (1, 2 or 5 × 10^k, about
/// five intervals); with `pad` (y axes) over the data range widened by 5 % on each side and then
/// outwards to whole steps, so no data point lies on the frame; without (x axes) exactly the data
/// range, ticks at the whole steps inside it. Log: decades (with 2 and 5 between when the range
/// spans at most two decades).
struct Scale {
  double lo = 0.0, hi = 1.0;
  bool log = false;
  std::vector<double> ticks;
  int decimals = 0;
  /// Position of v on [p0, p1] (p0 at lo).
  [[nodiscard]] double map(double v, double p0, double p1) const;
  /// The tick label of v.
  [[nodiscard]] std::string label(double v) const;
};
[[nodiscard]] Scale linear_scale(double lo, double hi, bool pad = true);
/// Pre: 0 < lo <= hi.
[[nodiscard]] Scale log_scale(double lo, double hi);
/// figures.log: whether values in [lo, hi] are drawn on a log axis: all positive and hi ≥ 20 lo
/// (on a linear axis the smallest would sit in the bottom 5 % of the range).
[[nodiscard]] bool wants_log(double lo, double hi);

/// figures.labels: places short labels next to anchor points so that every label lies inside the
/// canvas and overlaps no label or reserved box placed before; a label that fits nowhere is
/// dropped (its point is still drawn by the caller).
class LabelPlacer {
 public:
  explicit LabelPlacer(Box canvas) : canvas_(canvas) {}
  /// Reserve a box (e.g. a marker) that later labels avoid.
  void reserve(const Box& b) { taken_.push_back(b); }
  /// Tries right-above, right-below, left-above, left-below, above, below of (x, y) at distance
  /// `gap`, then at gap + 0.7 size (past a marker ring; further out a label would be ambiguous);
  /// returns the <text> element, or "" when no position fits.
  [[nodiscard]] std::string place(double x, double y, std::string_view label, double gap,
                                  std::string_view cls, std::string_view fill, double size = kFont);

 private:
  Box canvas_;
  std::vector<Box> taken_;
};

/// A legend swatch.
enum class Swatch { line, square, box, dot, ring, triangle, cross };
/// figures.legend: one legend entry. `absent`: the series drew nothing; it is listed with a grey
/// swatch and its label (which says why, e.g. "GA — no feasible run").
struct LegendEntry {
  std::string label;
  Swatch kind = Swatch::line;
  std::string colour = "black";
  std::string dasharray = {};
  bool absent = false;
};

/// A world rectangle [x0, x1] × [y0, y1] (y up) drawn in a canvas box with equal scale on both
/// axes, the longer side filling the box.
struct Frame {
  double x0 = 0.0, y0 = 0.0, x1 = 1.0, y1 = 1.0;  ///< world
  double left = 0.0, top = 0.0, scale = 1.0;     ///< canvas position and units per world unit
  [[nodiscard]] double X(double x) const { return left + (x - x0) * scale; }
  [[nodiscard]] double Y(double y) const { return top + (y1 - y) * scale; }
  [[nodiscard]] double width() const { return (x1 - x0) * scale; }
  [[nodiscard]] double height() const { return (y1 - y0) * scale; }
};
/// The frame of world box [x0,x1]×[y0,y1] in a canvas area `w` wide starting at (left, top), at
/// most `max_scale` units per world unit and at most `max_h` tall. Pre: x0 < x1, y0 < y1.
[[nodiscard]] Frame fit_frame(double x0, double y0, double x1, double y1, double left, double top,
                              double w, double max_h, double max_scale);

/// figures.time-marks: the interval of time marks for a run of `end_t` seconds: the first of
/// 1, 2, 5, 10, 20, 50, ... s that gives at most `max_marks` marks.
[[nodiscard]] double mark_step(double end_t, double max_marks = 20.0);

/// figures.time-marks: the marks of samples at `times` (ascending) every `step` seconds: for each
/// mark time k·step, the first sample at or after it (1e-9 s tolerance); returns (sample index,
/// mark time) pairs, one per sample (several mark times falling on one sample keep the first).
[[nodiscard]] std::vector<std::pair<std::size_t, double>> mark_samples(const std::vector<double>& times, double step);

/// figures.time-marks: a dot (<circle class="CLS">) at each canvas point with its time as label
/// (class "CLS-label", placed by `placer`, dropped when it fits nowhere); consecutive marks at the
/// same point share one dot labelled "first-last". Labels are appended to `labels` (drawn last).
[[nodiscard]] std::string time_marks(const std::vector<std::pair<double, double>>& pts, const std::vector<double>& times,
                                     std::string_view cls, std::string_view colour, LabelPlacer& placer,
                                     std::string& labels);

/// A world box that grows to hold points (with a radius); starts empty.
struct Extent {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
  bool empty = true;
  void add(double x, double y, double r = 0.0);
};

/// One black <rect class="obstacle"> per blocked cell of `g` (cell (x, y) = [x, x+1] × [y, y+1]).
[[nodiscard]] std::string obstacle_cells(const grid::Grid& g, const Frame& f);

/// A figure under construction: content is appended top to bottom; the width is fixed.
class Figure {
 public:
  explicit Figure(double width = kWidth) : width_(width), y_(kMargin) {}
  [[nodiscard]] double width() const { return width_; }
  /// The current bottom of the content (where the next block starts).
  [[nodiscard]] double y() const { return y_; }
  [[nodiscard]] double inner_left() const { return kMargin; }
  [[nodiscard]] double inner_width() const { return width_ - 2.0 * kMargin; }
  /// figures.title: the title, paths stripped, left-aligned and wrapped to the width
  /// (one <text class="title"> per line).
  void title(std::string_view t);
  /// figures.legend: the entries flowed in rows across the width below the data area
  /// (<g class="legend">); an entry too long for a row wraps its label.
  void legend(const std::vector<LegendEntry>& entries);
  /// figures.caption: a note below, wrapped (<text class="caption">).
  void caption(std::string_view t, std::string_view cls = "caption");
  /// Appends drawn elements occupying `height` units from y().
  void block(std::string_view elements, double height);
  /// Appends elements without moving y() (e.g. drawn over an existing block).
  void add(std::string_view elements) { body_ += elements; }
  /// Adds vertical space.
  void skip(double dy) { y_ += dy; }
  /// The SVG document: root with width, height, viewBox and font-family; white background.
  [[nodiscard]] std::string svg() const;

 private:
  double width_;
  double y_;
  std::string body_;
};

/// figures.legend: the swatch of `e` in a 28 × 14 box with top-left (x, y).
[[nodiscard]] std::string swatch(const LegendEntry& e, double x, double y);

}  // namespace pathref::io::plot
