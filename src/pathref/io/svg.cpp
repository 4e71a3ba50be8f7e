#include "pathref/io/svg.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "pathref/core/error.hpp"

namespace pathref::io {

namespace {

/// A drawn panel before it is wrapped in an <svg> root: its size in px and its elements.
struct Panel {
  double width = 0.0;
  double height = 0.0;
  std::string body;
};

/// Line colours, in order of the paths/series (matplotlib's "tab10", readable in print).
constexpr std::array<const char*, 8> kPalette = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                                 "#9467bd", "#8c564b", "#e377c2", "#17becf"};

/// The colour of the i-th path or series.
const char* colour(std::size_t i) { return kPalette[i % kPalette.size()]; }

/// A coordinate in px with two decimals: deterministic, short, and exact enough for drawing.
std::string num(double v) { return fmt::format("{:.2f}", v); }

/// Wraps a panel in the SVG root element.
std::string wrap(const Panel& p) {
  return fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{0}\" height=\"{1}\" "
      "viewBox=\"0 0 {0} {1}\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n"
      "<rect class=\"background\" x=\"0\" y=\"0\" width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n"
      "{2}</svg>\n",
      num(p.width), num(p.height), p.body);
}

/// One legend entry: a short line (or marker) in `stroke` and the label text, at row `row`.
std::string legend_line(double x, double y, const std::string& stroke, const std::string& label) {
  return fmt::format(
      "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"3\"/>"
      "<text x=\"{}\" y=\"{}\" font-size=\"13\">{}</text>\n",
      num(x), num(y), num(x + 24.0), num(y), stroke, num(x + 30.0), num(y + 4.5),
      xml_escape(label));
}

// ---- map ------------------------------------------------------------------------------------

constexpr double kMapMargin = 30.0;    // left/right/bottom margin around the grid
constexpr double kMapTitleH = 40.0;    // space above the grid for the title
constexpr double kMapLegendMinW = 150.0;  // space right of the grid for the legend, at least
constexpr double kCharW = 7.2;            // generous width of one 13 px legend character
constexpr double kMapTarget = 560.0;   // the longer grid side is drawn about this long

/// Side of one cell in px: the longer grid side spans kMapTarget px, at most 48 px per cell.
double cell_px(const grid::Grid& g) {
  const double longest = static_cast<double>(std::max(g.width(), g.height()));
  return std::min(48.0, kMapTarget / longest);
}

/// Top-left corner of cell c in px: (0, 0) is the lower-left cell, row H-1 is drawn at the top.
std::pair<double, double> cell_corner(const grid::Grid& g, grid::Cell c, double s) {
  return {kMapMargin + static_cast<double>(c.x) * s,
          kMapTitleH + static_cast<double>(g.height() - 1 - c.y) * s};
}

/// Centre of cell c in px (paths are drawn through cell centres, as in Shi 2022 Fig. 8/11).
std::pair<double, double> cell_centre_px(const grid::Grid& g, grid::Cell c, double s) {
  const auto [x, y] = cell_corner(g, c, s);
  return {x + s / 2.0, y + s / 2.0};
}

/// The start or goal marker: a filled circle in the cell with its letter on top.
std::string endpoint_marker(const grid::Grid& g, grid::Cell c, double s, const char* cls,
                            const char* fill, const char* letter) {
  const auto [cx, cy] = cell_centre_px(g, c, s);
  const double r = std::max(2.0, s * 0.38);
  return fmt::format(
      "<g class=\"{}\"><circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\" stroke=\"black\" "
      "stroke-width=\"1\"/><text x=\"{}\" y=\"{}\" font-size=\"{}\" font-weight=\"bold\" "
      "text-anchor=\"middle\" fill=\"white\">{}</text></g>\n",
      cls, num(cx), num(cy), num(r), fill, num(cx), num(cy + r * 0.45), num(std::max(6.0, r * 1.2)),
      letter);
}

Panel map_panel(const grid::Grid& g, std::optional<grid::Cell> start,
                std::optional<grid::Cell> goal, const std::vector<PathLayer>& paths,
                const std::string& title) {
  require(!start || g.in_bounds(*start), "svg_map: start outside the grid");
  require(!goal || g.in_bounds(*goal), "svg_map: goal outside the grid");
  for (const auto& layer : paths) {
    for (const auto& c : layer.path)
      require(g.in_bounds(c), "svg_map: path cell outside the grid in '" + layer.label + "'");
    for (const auto& q : layer.points)
      require(std::isfinite(q.x) && std::isfinite(q.y),
              "svg_map: non-finite point in '" + layer.label + "'");
  }

  const double s = cell_px(g);
  const double gw = static_cast<double>(g.width()) * s;
  const double gh = static_cast<double>(g.height()) * s;
  std::size_t longest = 8;  // "obstacle"
  for (const auto& layer : paths)  // the legend text, " (no path)" appended for an empty path
    longest = std::max(longest, layer.label.size() + (layer.path.empty() && layer.points.empty() ? 10 : 0));
  Panel p;
  p.width = kMapMargin + gw + kMapMargin + std::max(kMapLegendMinW, 40.0 + kCharW * static_cast<double>(longest));
  p.height = std::max(kMapTitleH + gh + kMapMargin, kMapTitleH + 30.0 + 22.0 * static_cast<double>(paths.size() + 3));
  std::string& b = p.body;
  b += fmt::format("<text class=\"title\" x=\"{}\" y=\"26\" font-size=\"16\" text-anchor=\"middle\">{}</text>\n",
                   num(kMapMargin + gw / 2.0), xml_escape(title));
  b += fmt::format("<rect class=\"map\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"white\" "
                   "stroke=\"black\" stroke-width=\"1\"/>\n",
                   num(kMapMargin), num(kMapTitleH), num(gw), num(gh));
  // Obstacles: one rect per blocked cell, so a reader (or a test) can count them.
  for (std::int64_t y = g.height() - 1; y >= 0; --y)
    for (std::int64_t x = 0; x < g.width(); ++x)
      if (g.blocked(grid::Cell{x, y})) {
        const auto [px, py] = cell_corner(g, grid::Cell{x, y}, s);
        b += fmt::format("<rect class=\"obstacle\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"black\"/>\n",
                         num(px), num(py), num(s), num(s));
      }
  if (g.width() <= 100 && g.height() <= 100) {
    std::string d;
    for (std::int64_t x = 1; x < g.width(); ++x)
      d += fmt::format("M{} {}V{}", num(kMapMargin + static_cast<double>(x) * s), num(kMapTitleH),
                       num(kMapTitleH + gh));
    for (std::int64_t y = 1; y < g.height(); ++y)
      d += fmt::format("M{} {}H{}", num(kMapMargin), num(kMapTitleH + static_cast<double>(y) * s),
                       num(kMapMargin + gw));
    if (!d.empty())
      b += fmt::format("<path class=\"gridlines\" d=\"{}\" stroke=\"#999999\" stroke-width=\"0.5\" fill=\"none\"/>\n", d);
  }
  if (g.width() <= 100 && g.height() <= 100) {
    // Cell coordinates along the bottom (x) and the left (y): every cell up to 20, else every 5th.
    const auto every = [](std::int64_t n) { return n <= 20 ? std::int64_t{1} : std::int64_t{5}; };
    b += "<g class=\"axis-labels\" font-size=\"10\" fill=\"#555555\">\n";
    for (std::int64_t x = 0; x < g.width(); x += every(g.width()))
      b += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n",
                       num(kMapMargin + (static_cast<double>(x) + 0.5) * s), num(kMapTitleH + gh + 13.0), x);
    for (std::int64_t y = 0; y < g.height(); y += every(g.height()))
      b += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>\n", num(kMapMargin - 4.0),
                       num(kMapTitleH + (static_cast<double>(g.height() - 1 - y) + 0.5) * s + 3.5), y);
    b += "</g>\n";
  }
  const double stroke_w = std::clamp(s / 8.0, 1.0, 4.0);
  for (std::size_t i = 0; i < paths.size(); ++i) {
    if (paths[i].path.empty() && paths[i].points.empty()) continue;
    std::vector<std::pair<double, double>> vertices;
    for (const auto& c : paths[i].path) vertices.push_back(cell_centre_px(g, c, s));
    for (const auto& q : paths[i].points)  // map point -> px: y up, clamped to the drawing
      vertices.emplace_back(kMapMargin + std::clamp(q.x, -1.0, static_cast<double>(g.width()) + 1.0) * s,
                            kMapTitleH + (static_cast<double>(g.height()) -
                                          std::clamp(q.y, -1.0, static_cast<double>(g.height()) + 1.0)) * s);
    std::string pts;
    for (const auto& [cx, cy] : vertices) {
      if (!pts.empty()) pts += ' ';
      pts += fmt::format("{},{}", num(cx), num(cy));
    }
    const double w = paths[i].markers ? stroke_w * 0.6 : stroke_w;
    b += fmt::format("<polyline class=\"path\" data-label=\"{}\" points=\"{}\" fill=\"none\" stroke=\"{}\" "
                     "stroke-width=\"{}\" stroke-linejoin=\"round\" stroke-linecap=\"round\"{}/>\n",
                     xml_escape(paths[i].label), pts, colour(i), num(w),
                     paths[i].dashed ? fmt::format(" stroke-dasharray=\"{} {}\"", num(2.5 * w), num(2.0 * w)) : "");
    if (paths[i].markers)
      for (const auto& [cx, cy] : vertices)
        b += fmt::format("<circle class=\"marker\" cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\" stroke=\"black\" "
                         "stroke-width=\"0.5\"/>\n", num(cx), num(cy), num(std::max(2.0, s * 0.16)), colour(i));
  }
  if (start) b += endpoint_marker(g, *start, s, "start", "#2ca02c", "S");
  if (goal) b += endpoint_marker(g, *goal, s, "goal", "#d62728", "T");

  const double lx = kMapMargin + gw + kMapMargin;
  double ly = kMapTitleH + 12.0;
  b += "<g class=\"legend\">\n";
  for (std::size_t i = 0; i < paths.size(); ++i, ly += 22.0)
    b += legend_line(lx, ly, colour(i),
                     paths[i].path.empty() && paths[i].points.empty() ? paths[i].label + " (no path)"
                                                                     : paths[i].label);
  b += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"7\" fill=\"#2ca02c\" stroke=\"black\"/>"
                   "<text x=\"{}\" y=\"{}\" font-size=\"13\">start S</text>\n",
                   num(lx + 12.0), num(ly), num(lx + 30.0), num(ly + 4.5));
  ly += 22.0;
  b += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"7\" fill=\"#d62728\" stroke=\"black\"/>"
                   "<text x=\"{}\" y=\"{}\" font-size=\"13\">goal T</text>\n",
                   num(lx + 12.0), num(ly), num(lx + 30.0), num(ly + 4.5));
  ly += 22.0;
  b += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"14\" height=\"14\" fill=\"black\"/>"
                   "<text x=\"{}\" y=\"{}\" font-size=\"13\">obstacle</text>\n",
                   num(lx + 5.0), num(ly - 7.0), num(lx + 30.0), num(ly + 4.5));
  b += "</g>\n";
  return p;
}

// ---- chart ----------------------------------------------------------------------------------

constexpr double kChartW = 640.0;
constexpr double kChartH = 420.0;
constexpr double kPlotLeft = 75.0;
constexpr double kPlotRight = 20.0;
constexpr double kPlotTop = 45.0;
constexpr double kPlotBottom = 55.0;

/// Tick positions for [lo, hi]: a "nice" step (1, 2 or 5 times a power of ten) giving about five
/// intervals, the range widened outwards to whole steps. Returns {first, step, count}.
struct Ticks {
  double first;
  double step;
  int count;
  int decimals;  ///< decimals needed to print the step exactly
};

Ticks nice_ticks(double lo, double hi) {
  if (!(hi > lo)) {  // a flat line: widen symmetrically so it sits mid-height
    const double pad = lo == 0.0 ? 1.0 : std::abs(lo) * 0.1;
    lo -= pad;
    hi += pad;
  }
  const double raw = (hi - lo) / 5.0;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double norm = raw / mag;
  const double step = (norm <= 1.0 ? 1.0 : norm <= 2.0 ? 2.0 : norm <= 5.0 ? 5.0 : 10.0) * mag;
  const double first = std::floor(lo / step) * step;
  const double last = std::ceil(hi / step) * step;
  const int count = static_cast<int>(std::lround((last - first) / step)) + 1;
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  return {first, step, count, decimals};
}

/// Whether point i of a series is drawn (both coordinates finite).
bool drawable(const Series& s, std::size_t i) { return std::isfinite(s.x[i]) && std::isfinite(s.y[i]); }

Panel chart_panel(const std::vector<Series>& series, const ChartOptions& opt) {
  double xmin = std::numeric_limits<double>::infinity();
  double xmax = -xmin;
  double ymin = xmin;
  double ymax = -xmin;
  for (const auto& s : series) {
    require(s.x.size() == s.y.size(), "svg_line_chart: series '" + s.label + "' has x and y of different lengths");
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (drawable(s, i)) {
        xmin = std::min(xmin, s.x[i]);
        xmax = std::max(xmax, s.x[i]);
        ymin = std::min(ymin, s.y[i]);
        ymax = std::max(ymax, s.y[i]);
      }
  }
  if (!std::isfinite(xmin)) {  // nothing to draw: axes over [0, 1] x [0, 1]
    xmin = 0.0;
    xmax = 1.0;
    ymin = 0.0;
    ymax = 1.0;
  }
  const Ticks xt = nice_ticks(xmin, xmax);
  const Ticks yt = nice_ticks(ymin, ymax);
  const double x0 = xt.first;
  const double x1 = xt.first + xt.step * (xt.count - 1);
  const double y0 = yt.first;
  const double y1 = yt.first + yt.step * (yt.count - 1);
  const double pw = kChartW - kPlotLeft - kPlotRight;
  const double ph = kChartH - kPlotTop - kPlotBottom;
  auto px = [&](double v) { return kPlotLeft + (v - x0) / (x1 - x0) * pw; };
  auto py = [&](double v) { return kPlotTop + (y1 - v) / (y1 - y0) * ph; };

  Panel p{kChartW, kChartH, {}};
  std::string& b = p.body;
  b += fmt::format("<text class=\"title\" x=\"{}\" y=\"26\" font-size=\"16\" text-anchor=\"middle\">{}</text>\n",
                   num(kPlotLeft + pw / 2.0), xml_escape(opt.title));
  b += fmt::format("<rect class=\"plot-area\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" "
                   "stroke=\"black\" stroke-width=\"1\"/>\n",
                   num(kPlotLeft), num(kPlotTop), num(pw), num(ph));
  b += "<g class=\"xticks\" font-size=\"12\" text-anchor=\"middle\">\n";
  for (int i = 0; i < xt.count; ++i) {
    const double v = xt.first + xt.step * i;
    b += fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"black\"/>"
                     "<text x=\"{0}\" y=\"{3}\">{4:.{5}f}</text>\n",
                     num(px(v)), num(kPlotTop + ph), num(kPlotTop + ph + 5.0), num(kPlotTop + ph + 19.0),
                     v, xt.decimals);
  }
  b += "</g>\n<g class=\"yticks\" font-size=\"12\" text-anchor=\"end\">\n";
  for (int i = 0; i < yt.count; ++i) {
    const double v = yt.first + yt.step * i;
    b += fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"black\"/>"
                     "<line x1=\"{2}\" y1=\"{1}\" x2=\"{3}\" y2=\"{1}\" stroke=\"#dddddd\"/>"
                     "<text x=\"{4}\" y=\"{5}\">{6:.{7}f}</text>\n",
                     num(kPlotLeft - 5.0), num(py(v)), num(kPlotLeft), num(kPlotLeft + pw),
                     num(kPlotLeft - 8.0), num(py(v) + 4.0), v, yt.decimals);
  }
  b += "</g>\n";
  b += fmt::format("<text class=\"x-label\" x=\"{}\" y=\"{}\" font-size=\"13\" text-anchor=\"middle\">{}</text>\n",
                   num(kPlotLeft + pw / 2.0), num(kChartH - 12.0), xml_escape(opt.x_label));
  b += fmt::format("<text class=\"y-label\" x=\"{0}\" y=\"{1}\" font-size=\"13\" text-anchor=\"middle\" "
                   "transform=\"rotate(-90 {0} {1})\">{2}</text>\n",
                   num(18.0), num(kPlotTop + ph / 2.0), xml_escape(opt.y_label));

  for (std::size_t k = 0; k < series.size(); ++k) {
    const Series& s = series[k];
    std::string pts;
    std::size_t run = 0;
    auto flush = [&] {
      if (run == 1) {  // a lone point would be invisible as a polyline: mark it
        const auto comma = pts.find(',');
        b += fmt::format("<circle class=\"point\" cx=\"{}\" cy=\"{}\" r=\"3\" fill=\"{}\"/>\n",
                         pts.substr(0, comma), pts.substr(comma + 1), colour(k));
      }
      if (run >= 1)
        b += fmt::format("<polyline class=\"series\" data-label=\"{}\" points=\"{}\" fill=\"none\" "
                         "stroke=\"{}\" stroke-width=\"2\"/>\n",
                         xml_escape(s.label), pts, colour(k));
      pts.clear();
      run = 0;
    };
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!drawable(s, i)) {
        flush();
        continue;
      }
      if (!pts.empty()) pts += ' ';
      pts += fmt::format("{},{}", num(px(s.x[i])), num(py(s.y[i])));
      ++run;
    }
    flush();
  }

  // Legend in the upper right of the plot area, on a white box, as in Shi 2022 Fig. 9/12.
  if (!series.empty()) {
    std::size_t longest = 0;
    for (const auto& s : series) longest = std::max(longest, s.label.size());
    const double lw = 44.0 + kCharW * static_cast<double>(longest);
    const double lh = 10.0 + 20.0 * static_cast<double>(series.size());
    const double lx = kPlotLeft + pw - lw - 8.0;
    const double ly = kPlotTop + 8.0;
    b += fmt::format("<g class=\"legend\">\n<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"white\" "
                     "fill-opacity=\"0.9\" stroke=\"#888888\"/>\n",
                     num(lx), num(ly), num(lw), num(lh));
    for (std::size_t k = 0; k < series.size(); ++k)
      b += legend_line(lx + 8.0, ly + 15.0 + 20.0 * static_cast<double>(k), colour(k), series[k].label);
    b += "</g>\n";
  }
  return p;
}

}  // namespace

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string svg_line_chart(const std::vector<Series>& series, const ChartOptions& opt) {
  return wrap(chart_panel(series, opt));
}

std::string svg_map(const grid::Grid& g, std::optional<grid::Cell> start,
                    std::optional<grid::Cell> goal, const std::vector<PathLayer>& paths,
                    const std::string& title) {
  return wrap(map_panel(g, start, goal, paths, title));
}

std::string svg_map_and_chart(const grid::Grid& g, std::optional<grid::Cell> start,
                              std::optional<grid::Cell> goal, const std::vector<PathLayer>& paths,
                              const std::string& map_title, const std::vector<Series>& series,
                              const ChartOptions& chart) {
  const Panel left = map_panel(g, start, goal, paths, map_title);
  const Panel right = chart_panel(series, chart);
  Panel both{left.width + right.width, std::max(left.height, right.height), {}};
  both.body = "<g class=\"panel\">\n" + left.body + "</g>\n" +
              fmt::format("<g class=\"panel\" transform=\"translate({} 0)\">\n", num(left.width)) +
              right.body + "</g>\n";
  return wrap(both);
}

}  // namespace pathref::io
