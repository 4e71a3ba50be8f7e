// Spec: spec/cli.md#plan-continuous (SVG).
#include "pathref/io/svg_continuous.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "pathref/core/error.hpp"
#include "pathref/io/svg.hpp"

namespace pathref::io {

using continuous::Vec2;

/// The figure: world rectangle, obstacles (and their r-inflation outline when r > 0), tree edges,
/// raw path, shortcut path, start and goal, title and legend.
std::string svg_continuous(const ContinuousScene& om, const continuous::ContinuousRun& run, Vec2 start, Vec2 goal,
                           const std::string& title) {
  const Vec2 lo = om.lower, hi = om.upper;
  require(lo.x < hi.x && lo.y < hi.y, "svg_continuous: empty world rectangle");
  const double w = hi.x - lo.x, h = hi.y - lo.y;
  const double scale = 600.0 / std::max(w, h);
  const double pw = w * scale, ph = h * scale;
  // legend entries first: the canvas is widened to the longest label (a generous 6.6 px per
  // character of the 11 px sans-serif legend font), so the legend always fits
  struct Entry {
    std::string label;
    const char* colour;
  };
  std::vector<Entry> entries{{fmt::format("tree ({} nodes)", run.tree.nodes.size()), "#9ab"}};
  if (!run.raw.empty())
    entries.push_back({fmt::format("RRT path (length {:.2f}, {} nodes)", run.raw_metrics.length, run.raw.size()), "#2a2"});
  else
    entries.push_back({"no path", "#2a2"});
  if (!run.shortcut_path.empty())
    entries.push_back({fmt::format("shortcut (length {:.2f}, {} nodes)", run.shortcut_metrics.length,
                                   run.shortcut_path.size()),
                       "#d22"});
  if (run.curve)
    entries.push_back({fmt::format("B-spline (degree {}, length {:.2f}, {})", run.curve->degree, run.curve->length,
                                   geometry::to_string(run.curve->clearance.verdict)),
                       "#15c"});
  entries.push_back({"start", "green"});
  entries.push_back({"goal", "red"});
  entries.push_back({"obstacle", "black"});
  std::size_t longest = 0;
  for (const auto& e : entries) longest = std::max(longest, e.label.size());
  const double left = 20.0, top = 40.0;
  const double legend_w = std::max(220.0, 40.0 + 6.6 * static_cast<double>(longest));
  const auto X = [&](double x) { return left + (x - lo.x) * scale; };
  const auto Y = [&](double y) { return top + (hi.y - y) * scale; };
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.2f}\" height=\"{:.2f}\" viewBox=\"0 0 {:.2f} {:.2f}\">\n",
      left + pw + legend_w, top + ph + 20.0, left + pw + legend_w, top + ph + 20.0);
  out += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out += fmt::format("<text x=\"{:.2f}\" y=\"24\" font-family=\"sans-serif\" font-size=\"14\">{}</text>\n", left,
                     xml_escape(title));
  out += fmt::format("<rect class=\"map\" x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"white\" stroke=\"black\"/>\n",
                     left, top, pw, ph);
  for (const auto& poly : om.polygons) {
    std::string pts;
    for (const Vec2& v : poly) pts += fmt::format("{}{:.2f},{:.2f}", pts.empty() ? "" : " ", X(v.x), Y(v.y));
    out += fmt::format("<polygon class=\"obstacle\" points=\"{}\" fill=\"black\"", pts);
    if (om.radius > 0.0)
      out += fmt::format(" stroke=\"#888\" stroke-opacity=\"0.5\" stroke-width=\"{:.2f}\" stroke-linejoin=\"round\"",
                         2.0 * om.radius * scale);
    out += "/>\n";
  }
  // tree edges
  std::string tree;
  for (std::size_t k = 1; k < run.tree.nodes.size(); ++k) {
    const auto p = run.tree.parent[k];
    if (p < 0) continue;
    const Vec2 a = run.tree.nodes[static_cast<std::size_t>(p)], b = run.tree.nodes[k];
    tree += fmt::format("M{:.2f},{:.2f}L{:.2f},{:.2f}", X(a.x), Y(a.y), X(b.x), Y(b.y));
  }
  if (!tree.empty())
    out += fmt::format("<path class=\"tree\" d=\"{}\" fill=\"none\" stroke=\"#9ab\" stroke-width=\"0.8\"/>\n", tree);
  const auto polyline = [&](const std::vector<Vec2>& pts, const char* cls, const char* colour, double width) {
    if (pts.size() < 2) return;
    std::string s;
    for (const Vec2& v : pts) s += fmt::format("{}{:.2f},{:.2f}", s.empty() ? "" : " ", X(v.x), Y(v.y));
    out += fmt::format("<polyline class=\"{}\" points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{:.1f}\"/>\n", cls,
                       s, colour, width);
  };
  polyline(run.raw, "raw-path", "#2a2", 2.0);
  polyline(run.shortcut_path, "shortcut-path", "#d22", 2.5);
  if (run.curve) polyline(run.curve->samples.points, "curve", "#15c", 2.5);
  out += fmt::format("<circle class=\"start\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"6\" fill=\"green\"/>\n", X(start.x), Y(start.y));
  out += fmt::format("<circle class=\"goal\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"6\" fill=\"red\"/>\n", X(goal.x), Y(goal.y));
  out += "<g class=\"legend\" font-family=\"sans-serif\" font-size=\"11\">\n";
  double ly = top + 10.0;
  for (const auto& e : entries) {
    out += fmt::format("<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"14\" height=\"4\" fill=\"{}\"/>", left + pw + 10.0, ly - 4.0,
                       e.colour);
    out += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\">{}</text>\n", left + pw + 30.0, ly, xml_escape(e.label));
    ly += 16.0;
  }
  out += "</g>\n</svg>\n";
  return out;
}


}  // namespace pathref::io
