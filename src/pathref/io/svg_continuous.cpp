// Spec: spec/cli.md#plan-continuous (SVG).
#include "pathref/io/svg_continuous.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "pathref/core/error.hpp"
#include "pathref/io/plot.hpp"

namespace pathref::io {

using continuous::Vec2;

/// The figure: world rectangle, obstacles (and their r-inflation outline when r > 0), tree edges,
/// raw path, shortcut path, start and goal, title and legend.
std::string svg_continuous(const ContinuousScene& om, const continuous::ContinuousRun& run, Vec2 start, Vec2 goal,
                           const std::string& title) {
  using plot::num;
  const Vec2 lo = om.lower, hi = om.upper;
  require(lo.x < hi.x && lo.y < hi.y, "svg_continuous: empty world rectangle");
  plot::Figure fig;
  fig.title(title);
  const plot::Frame f = plot::fit_frame(lo.x, lo.y, hi.x, hi.y, fig.inner_left(), fig.y() + 4.0, fig.inner_width(),
                                        1.2 * fig.inner_width(), 1e9);
  const auto pts = [&](const std::vector<Vec2>& v) {
    std::vector<std::pair<double, double>> out;
    for (const Vec2& q : v) out.emplace_back(f.X(q.x), f.Y(q.y));
    return out;
  };
  std::string b = fmt::format("<rect class=\"map\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"white\" "
                              "stroke=\"black\"/>\n",
                              num(f.left), num(f.top), num(f.width()), num(f.height()));
  // Everything is clipped to the world rectangle (an r-outline may reach past it).
  b += fmt::format("<clipPath id=\"world\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath>\n"
                   "<g clip-path=\"url(#world)\">\n",
                   num(f.left), num(f.top), num(f.width()), num(f.height()));
  for (const auto& poly : om.polygons) {
    std::string p;
    for (const auto& [x, y] : pts(poly)) p += fmt::format("{}{},{}", p.empty() ? "" : " ", num(x), num(y));
    b += fmt::format("<polygon class=\"obstacle\" points=\"{}\" fill=\"black\"", p);
    if (om.radius > 0.0)
      b += fmt::format(" stroke=\"#888888\" stroke-opacity=\"0.5\" stroke-width=\"{}\" stroke-linejoin=\"round\"",
                       num(2.0 * om.radius * f.scale));
    b += "/>\n";
  }
  std::vector<plot::LegendEntry> legend;
  std::string tree;
  for (std::size_t k = 1; k < run.tree.nodes.size(); ++k) {
    const auto p = run.tree.parent[k];
    if (p < 0) continue;
    const Vec2 a = run.tree.nodes[static_cast<std::size_t>(p)], c = run.tree.nodes[k];
    tree += fmt::format("M{},{}L{},{}", num(f.X(a.x)), num(f.Y(a.y)), num(f.X(c.x)), num(f.Y(c.y)));
  }
  if (!tree.empty())
    b += fmt::format("<path class=\"tree\" d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"0.8\"/>\n", tree,
                     plot::kSky);
  legend.push_back({fmt::format("tree ({} nodes)", run.tree.nodes.size()), plot::Swatch::line, plot::kSky});
  if (run.raw.size() >= 2) b += plot::polyline(pts(run.raw), "raw-path", plot::kGreen, 2.0, "8 4");
  legend.push_back({run.raw.empty() ? std::string("RRT path — none found")
                                    : fmt::format("RRT path (length {:.2f}, {} nodes)", run.raw_metrics.length, run.raw.size()),
                    plot::Swatch::line, plot::kGreen, "8 4", run.raw.empty()});
  if (run.shortcut_path.size() >= 2) {
    b += plot::polyline(pts(run.shortcut_path), "shortcut-path", plot::kVermillion, 2.5);
    legend.push_back({fmt::format("shortcut (length {:.2f}, {} nodes)", run.shortcut_metrics.length, run.shortcut_path.size()),
                      plot::Swatch::line, plot::kVermillion});
  }
  if (run.curve) {
    if (run.curve->samples.points.size() >= 2)
      b += plot::polyline(pts(run.curve->samples.points), "curve", plot::kBlue, 2.5, "2 3");
    legend.push_back({fmt::format("B-spline (degree {}, length {:.2f}, {})", run.curve->degree, run.curve->length,
                                  geometry::to_string(run.curve->clearance.verdict)),
                      plot::Swatch::line, plot::kBlue, "2 3"});
  }
  b += fmt::format("<circle class=\"start\" cx=\"{}\" cy=\"{}\" r=\"6\" fill=\"{}\" stroke=\"black\"/>\n",
                   num(f.X(start.x)), num(f.Y(start.y)), plot::kGreen);
  b += fmt::format("<circle class=\"goal\" cx=\"{}\" cy=\"{}\" r=\"6\" fill=\"{}\" stroke=\"black\"/>\n",
                   num(f.X(goal.x)), num(f.Y(goal.y)), plot::kVermillion);
  b += "</g>\n";
  fig.block(b, f.height() + 8.0);
  legend.push_back({"start", plot::Swatch::dot, plot::kGreen});
  legend.push_back({"goal", plot::Swatch::dot, plot::kVermillion});
  legend.push_back({"obstacle", plot::Swatch::square, "black"});
  fig.legend(legend);
  return fig.svg();
}

}  // namespace pathref::io
