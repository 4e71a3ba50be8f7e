// Grid maps and line charts on the plotting layer. Spec: spec/figures.md, spec/cli.md#svg-figures.
#include "pathref/io/svg.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "pathref/core/error.hpp"
#include "pathref/io/plot.hpp"

namespace pathref::io {

namespace {

using plot::kFont;
using plot::num;

/// The longest side of a map is drawn at most this many units per cell.
constexpr double kMaxCell = 48.0;

/// figures.map-labels: the smallest k in 1, 2, 5, 10, 20, 50, ... such that labels every k cells
/// (each `label_w` wide along the axis) leave a gap of at least 4 units.
std::int64_t label_every(double cell, double label_w) {
  for (std::int64_t k = 1;; k *= 10)
    for (const std::int64_t m : {std::int64_t{1}, std::int64_t{2}, std::int64_t{5}})
      if (static_cast<double>(k * m) * cell >= label_w + 4.0) return k * m;
}

/// figures.cell-numbers: each cell's number i = y·W + x (grid.index) at its centre in grey (white on
/// obstacles), at the
/// minimum font size kFont, except the start and goal cells (their markers say S and T). UsageError
/// when the longest number does not fit a cell (wider than 0.9 of it, or kFont above 0.6 of it).
std::string cell_number_labels(const grid::Grid& g, const plot::Frame& f, std::optional<grid::Cell> start,
                               std::optional<grid::Cell> goal) {
  const std::string longest = std::to_string(g.width() * g.height() - 1);
  const double need = std::max(plot::text_width(longest) / 0.9, kFont / 0.6);
  if (f.scale < need)
    throw UsageError(fmt::format("cell numbers need cells of at least {} units for the {}-digit numbers of a {}x{} map; "
                                 "this map is drawn at {} units a cell",
                                 num(need), longest.size(), g.width(), g.height(), num(f.scale)));
  std::string b = "<g class=\"cell-numbers\" fill=\"#666666\">\n";
  for (std::int64_t y = 0; y < g.height(); ++y)
    for (std::int64_t x = 0; x < g.width(); ++x) {
      const grid::Cell c{x, y};
      if ((start && *start == c) || (goal && *goal == c)) continue;
      b += plot::text(f.X(static_cast<double>(x) + 0.5), f.Y(static_cast<double>(y) + 0.5) + 0.36 * kFont,
                      std::to_string(g.index(c)), kFont, "middle", "", g.blocked(c) ? "white" : "");
    }
  return b + "</g>\n";
}

/// Draws the map panel into `fig` at fig.y(): the grid, obstacles, grid lines, cell labels, paths
/// and endpoints; then the legend.
void map_panel(plot::Figure& fig, const grid::Grid& g, std::optional<grid::Cell> start,
               std::optional<grid::Cell> goal, const std::vector<PathLayer>& paths, const std::string& title,
               bool cell_numbers) {
  require(!start || g.in_bounds(*start), "svg_map: start outside the grid");
  require(!goal || g.in_bounds(*goal), "svg_map: goal outside the grid");
  for (const auto& layer : paths) {
    for (const auto& c : layer.path)
      require(g.in_bounds(c), "svg_map: path cell outside the grid in '" + layer.label + "'");
    for (const auto& q : layer.points)
      require(std::isfinite(q.x) && std::isfinite(q.y), "svg_map: non-finite point in '" + layer.label + "'");
  }
  fig.title(title);
  const bool small = g.width() <= 100 && g.height() <= 100;
  const double label_w = small ? plot::text_width(std::to_string(std::max(g.width(), g.height()) - 1)) : 0.0;
  const double left = small ? label_w + 6.0 : 0.0;
  const double bottom = small ? kFont + 6.0 : 0.0;
  const double avail = fig.inner_width() - left;
  const plot::Frame f = plot::fit_frame(0.0, 0.0, static_cast<double>(g.width()), static_cast<double>(g.height()),
                                        fig.inner_left() + left, fig.y(), avail, avail, kMaxCell);
  const double s = f.scale;
  const auto corner_x = [&](std::int64_t x) { return f.X(static_cast<double>(x)); };
  const auto corner_y = [&](std::int64_t y) { return f.Y(static_cast<double>(y) + 1.0); };
  const auto centre = [&](grid::Cell c) {
    return std::pair{f.X(static_cast<double>(c.x) + 0.5), f.Y(static_cast<double>(c.y) + 0.5)};
  };
  std::string b = "<g class=\"panel\">\n";
  b += fmt::format("<rect class=\"map\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"white\" "
                   "stroke=\"black\" stroke-width=\"1\"/>\n",
                   num(f.left), num(f.top), num(f.width()), num(f.height()));
  // Obstacles: one rect per blocked cell (top row first), so a reader (or a test) can count them.
  b += plot::obstacle_cells(g, f);
  if (small) {
    std::string d;
    for (std::int64_t x = 1; x < g.width(); ++x)
      d += fmt::format("M{} {}V{}", num(corner_x(x)), num(f.top), num(f.top + f.height()));
    for (std::int64_t y = 1; y < g.height(); ++y)
      d += fmt::format("M{} {}H{}", num(f.left), num(corner_y(y - 1)), num(f.left + f.width()));
    if (!d.empty())
      b += fmt::format("<path class=\"gridlines\" d=\"{}\" stroke=\"#999999\" stroke-width=\"0.5\" fill=\"none\"/>\n", d);
    // Cell coordinates along the bottom (x) and the left (y), every k-th cell.
    const std::int64_t kx = label_every(s, label_w), ky = label_every(s, kFont);
    b += "<g class=\"axis-labels\" fill=\"#444444\">\n";
    for (std::int64_t x = 0; x < g.width(); x += kx)
      b += plot::text(f.X(static_cast<double>(x) + 0.5), f.top + f.height() + kFont + 2.0, std::to_string(x), kFont,
                      "middle");
    for (std::int64_t y = 0; y < g.height(); y += ky)
      b += plot::text(f.left - 4.0, f.Y(static_cast<double>(y) + 0.5) + 0.36 * kFont, std::to_string(y), kFont, "end");
    b += "</g>\n";
  }
  if (cell_numbers) b += cell_number_labels(g, f, start, goal);
  const double stroke_w = std::clamp(s / 8.0, 1.5, 4.0);
  std::vector<plot::LegendEntry> legend;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const bool empty = paths[i].path.empty() && paths[i].points.empty();
    const std::string dash = paths[i].dashed ? "6 4" : plot::dash(i);
    legend.push_back({empty ? paths[i].label + " (no path)" : paths[i].label, plot::Swatch::line, plot::colour(i),
                      dash, empty});
    if (empty) continue;
    std::vector<std::pair<double, double>> vertices;
    for (const auto& c : paths[i].path) vertices.push_back(centre(c));
    for (const auto& q : paths[i].points)  // map point -> canvas, clamped to the drawing
      vertices.emplace_back(f.X(std::clamp(q.x, 0.0, static_cast<double>(g.width()))),
                            f.Y(std::clamp(q.y, 0.0, static_cast<double>(g.height()))));
    const double w = paths[i].markers ? stroke_w * 0.6 : stroke_w;
    b += plot::polyline(vertices, "path", plot::colour(i), w, dash,
                        fmt::format(" data-label=\"{}\"", plot::escape(paths[i].label)));
    if (paths[i].markers)
      for (const auto& [cx, cy] : vertices)
        b += fmt::format("<circle class=\"marker\" cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\" stroke=\"black\" "
                         "stroke-width=\"0.5\"/>\n",
                         num(cx), num(cy), num(std::max(2.0, s * 0.16)), plot::colour(i));
  }
  // Start and goal: a filled circle in the cell, its letter on top when it is legible (≥ kFont).
  const auto endpoint = [&](grid::Cell c, const char* cls, const char* fill, const char* letter) {
    const auto [cx, cy] = centre(c);
    const double r = std::max(3.0, s * 0.38);
    std::string m = fmt::format("<g class=\"{}\"><circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\" stroke=\"black\" "
                                "stroke-width=\"1\"/>",
                                cls, num(cx), num(cy), num(r), fill);
    if (r * 1.2 >= kFont)
      m += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"{}\" font-weight=\"bold\" text-anchor=\"middle\" "
                       "fill=\"white\">{}</text>",
                       num(cx), num(cy + r * 0.45), num(r * 1.2), letter);
    return m + "</g>\n";
  };
  if (start) b += endpoint(*start, "start", plot::kGreen, "S");
  if (goal) b += endpoint(*goal, "goal", plot::kVermillion, "T");
  b += "</g>\n";
  fig.block(b, f.height() + bottom + 4.0);
  legend.push_back({"start S", plot::Swatch::dot, plot::kGreen});
  legend.push_back({"goal T", plot::Swatch::dot, plot::kVermillion});
  legend.push_back({"obstacle", plot::Swatch::square, "black"});
  fig.legend(legend);
}

/// Whether point i of a series is drawn (both coordinates finite, and positive on a log axis).
bool drawable(const Series& s, std::size_t i, bool log) {
  return std::isfinite(s.x[i]) && std::isfinite(s.y[i]) && (!log || s.y[i] > 0.0);
}

/// The plot area of a chart in `fig` below its title: left padding from the y label line and the
/// widest y tick label, right padding `right`, height 0.62 × width (figures.chart).
struct Area {
  double x0, top, pw, ph;
  /// Baseline of the x axis label (below the tick labels).
  [[nodiscard]] double x_label_y() const { return top + ph + 8.0 + kFont + plot::kLineEm * kFont; }
};

Area plot_area(const plot::Figure& fig, const plot::Scale& ys, double right) {
  double ytick_w = 0.0;
  for (const double v : ys.ticks) ytick_w = std::max(ytick_w, plot::text_width(ys.label(v)));
  const double left = plot::kLineEm * kFont + ytick_w + 10.0;
  const double pw = fig.inner_width() - left - right;
  return {fig.inner_left() + left, fig.y() + kFont / 2.0, pw, 0.62 * pw};
}

/// The frame of area `a`, the y ticks with grid lines and their labels, and the rotated y label.
std::string y_axis(const plot::Figure& fig, const Area& a, const plot::Scale& ys, const std::string& label) {
  std::string b = fmt::format("<rect class=\"plot-area\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" "
                              "stroke=\"black\" stroke-width=\"1\"/>\n",
                              num(a.x0), num(a.top), num(a.pw), num(a.ph));
  b += "<g class=\"yticks\">\n";
  for (const double v : ys.ticks) {
    const double y = ys.map(v, a.top + a.ph, a.top);
    b += fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"black\"/>"
                     "<line x1=\"{2}\" y1=\"{1}\" x2=\"{3}\" y2=\"{1}\" stroke=\"#dddddd\"/>",
                     num(a.x0 - 5.0), num(y), num(a.x0), num(a.x0 + a.pw)) +
         plot::text(a.x0 - 8.0, y + 0.36 * kFont, ys.label(v), kFont, "end");
  }
  b += "</g>\n";
  const double ly = a.top + a.ph / 2.0, lx = fig.inner_left() + kFont;
  b += fmt::format("<text class=\"y-label\" x=\"{0}\" y=\"{1}\" font-size=\"{2}\" text-anchor=\"middle\" "
                   "transform=\"rotate(-90 {0} {1})\">{3}</text>\n",
                   num(lx), num(ly), kFont, plot::escape(label));
  return b;
}

void chart_panel(plot::Figure& fig, const std::vector<Series>& series, const ChartOptions& opt) {
  double xmin = std::numeric_limits<double>::infinity(), xmax = -xmin, ymin = xmin, ymax = -xmin;
  bool gaps = false;
  for (const auto& s : series) {
    require(s.x.size() == s.y.size(), "svg_line_chart: series '" + s.label + "' has x and y of different lengths");
    bool seen = false, broken = false;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!drawable(s, i, false)) {
        broken = seen;
        continue;
      }
      if (broken) gaps = true;
      seen = true;
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
  const bool log = opt.y_scale == YScale::log ? ymin > 0.0
                                              : opt.y_scale == YScale::automatic && plot::wants_log(ymin, ymax);
  const plot::Scale xs = plot::linear_scale(xmin, xmax, false);
  const plot::Scale ys = log ? plot::log_scale(ymin, ymax) : plot::linear_scale(ymin, ymax);
  fig.title(opt.title);
  const Area a = plot_area(fig, ys, plot::text_width(xs.label(xs.ticks.back())) / 2.0 + 2.0);
  const double x0 = a.x0, pw = a.pw, top = a.top, ph = a.ph;
  const auto px = [&](double v) { return xs.map(v, x0, x0 + pw); };
  const auto py = [&](double v) { return ys.map(v, top + ph, top); };
  std::string b = "<g class=\"panel\">\n" + y_axis(fig, a, ys, log ? opt.y_label + " (log scale)" : opt.y_label);
  b += "<g class=\"xticks\">\n";
  for (const double v : xs.ticks)
    b += fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"black\"/>", num(px(v)),
                     num(top + ph), num(top + ph + 5.0)) +
         plot::text(px(v), top + ph + 6.0 + kFont, xs.label(v), kFont, "middle");
  b += "</g>\n";
  const double xlabel_y = a.x_label_y();
  b += plot::text(x0 + pw / 2.0, xlabel_y, opt.x_label, kFont, "middle", "x-label");
  std::vector<plot::LegendEntry> legend;
  for (std::size_t k = 0; k < series.size(); ++k) {
    const Series& s = series[k];
    std::vector<std::pair<double, double>> run;
    bool any = false;
    auto flush = [&] {
      if (run.size() == 1)  // a lone point would be invisible as a polyline: mark it
        b += fmt::format("<circle class=\"point\" cx=\"{}\" cy=\"{}\" r=\"3.5\" fill=\"{}\"/>\n", num(run[0].first),
                         num(run[0].second), plot::colour(k));
      if (!run.empty())
        b += plot::polyline(run, "series", plot::colour(k), 2.0, plot::dash(k),
                            fmt::format(" data-label=\"{}\"", plot::escape(s.label)));
      run.clear();
    };
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!drawable(s, i, log)) {
        flush();
        continue;
      }
      any = true;
      run.emplace_back(px(s.x[i]), py(s.y[i]));
    }
    flush();
    for (const double m : s.marks)
      for (std::size_t i = 0; i < s.x.size(); ++i)
        if (s.x[i] == m && drawable(s, i, log))
          b += fmt::format("<circle class=\"mark\" cx=\"{}\" cy=\"{}\" r=\"5\" fill=\"none\" stroke=\"{}\" "
                           "stroke-width=\"1.5\"/>\n",
                           num(px(s.x[i])), num(py(s.y[i])), plot::colour(k));
    legend.push_back({any ? s.label : s.label + " — " + (s.absent.empty() ? "no finite value" : s.absent),
                      plot::Swatch::line, plot::colour(k), plot::dash(k), !any});
  }
  b += "</g>\n";
  fig.block(b, xlabel_y - fig.y() + 6.0);
  fig.legend(legend);
  if (gaps) fig.caption(opt.gap_note.empty() ? "A line is broken where its value is undefined." : opt.gap_note);
  if (!opt.caption.empty()) fig.caption(opt.caption);
}

void bar_panel(plot::Figure& fig, const BarChart& c) {
  double lo = 0.0, hi = c.y_max;
  if (!std::isfinite(hi)) {
    hi = 0.0;
    for (const auto& s : c.bars)
      for (const double v : s.y)
        if (std::isfinite(v)) hi = std::max(hi, v);
  }
  plot::Scale ys = plot::linear_scale(lo, hi);
  if (std::isfinite(c.y_max)) {  // a fixed range (e.g. 0-100 %): ticks every tenth
    ys.lo = lo;
    ys.hi = c.y_max;
    ys.ticks.clear();
    for (int t = 0; t <= 10; ++t) ys.ticks.push_back(c.y_max * t / 10.0);
  }
  fig.title(c.title);
  fig.skip(kFont + 2.0);  // room for the values above the tallest bars
  const Area a = plot_area(fig, ys, 2.0);
  std::string b = "<g class=\"panel\">\n" + y_axis(fig, a, ys, c.y_label);
  const double gw = a.pw / static_cast<double>(std::max<std::size_t>(1, c.groups.size()));
  const double bw = 0.84 * gw / static_cast<double>(std::max<std::size_t>(1, c.bars.size()));
  const auto py = [&](double v) { return ys.map(v, a.top + a.ph, a.top); };
  std::vector<plot::LegendEntry> legend;
  for (std::size_t k = 0; k < c.bars.size(); ++k) {
    const char* fill = k == 0 ? plot::kGrey : plot::colour(k - 1);
    legend.push_back({c.bars[k].label, plot::Swatch::square, fill});
    for (std::size_t gi = 0; gi < c.groups.size() && gi < c.bars[k].y.size(); ++gi) {
      const double v = c.bars[k].y[gi];
      if (!std::isfinite(v)) continue;
      const double x = a.x0 + gw * (static_cast<double>(gi) + 0.08) + bw * static_cast<double>(k);
      b += fmt::format("<rect class=\"bar\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\"/>\n", num(x + 1.0),
                       num(py(v)), num(bw - 2.0), num(a.top + a.ph - py(v)), fill);
      // the value above its bar, with fewer decimals when needed to fit its width; else none
      for (int d = c.value_decimals; d >= 0; --d) {
        const std::string label = fmt::format("{:.{}f}", v, d);
        if (plot::text_width(label) > bw + 4.0) continue;
        b += plot::text(x + bw / 2.0, py(v) - 3.0, label, kFont, "middle", "value");
        break;
      }
    }
  }
  for (std::size_t gi = 0; gi < c.groups.size(); ++gi)
    b += plot::text(a.x0 + gw * (static_cast<double>(gi) + 0.5), a.top + a.ph + 6.0 + kFont, c.groups[gi], kFont, "middle");
  b += "</g>\n";
  fig.block(b, a.top + a.ph + 12.0 + kFont - fig.y());
  fig.legend(legend);
  if (!c.caption.empty()) fig.caption(c.caption);
}

}  // namespace

std::string svg_bar_chart(const BarChart& c) {
  plot::Figure fig;
  bar_panel(fig, c);
  return fig.svg();
}

std::string xml_escape(std::string_view text) { return plot::escape(text); }

std::string svg_line_chart(const std::vector<Series>& series, const ChartOptions& opt) {
  plot::Figure fig;
  chart_panel(fig, series, opt);
  return fig.svg();
}

std::string svg_map(const grid::Grid& g, std::optional<grid::Cell> start, std::optional<grid::Cell> goal,
                    const std::vector<PathLayer>& paths, const std::string& title, bool cell_numbers) {
  plot::Figure fig;
  map_panel(fig, g, start, goal, paths, title, cell_numbers);
  return fig.svg();
}

std::string svg_map_and_chart(const grid::Grid& g, std::optional<grid::Cell> start,
                              std::optional<grid::Cell> goal, const std::vector<PathLayer>& paths,
                              const std::string& map_title, const std::vector<Series>& series,
                              const ChartOptions& chart, bool cell_numbers) {
  plot::Figure fig;
  map_panel(fig, g, start, goal, paths, map_title, cell_numbers);
  fig.skip(12.0);
  chart_panel(fig, series, chart);
  return fig.svg();
}

}  // namespace pathref::io
