#include "pathref/io/svg_fused.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "pathref/io/svg.hpp"

namespace pathref::io {

std::string svg_fused(const dwa::FusedScenario& s, const dwa::FusedResult& r) {
  using dwa::Point;
  double x0 = 0.0, y0 = 0.0;
  auto x1 = static_cast<double>(s.grid.width());
  auto y1 = static_cast<double>(s.grid.height());
  auto grow = [&](Point p, double rad) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    x0 = std::min(x0, p.x - rad);
    y0 = std::min(y0, p.y - rad);
    x1 = std::max(x1, p.x + rad);
    y1 = std::max(y1, p.y + rad);
  };
  for (const auto& smp : r.samples) grow(Point{smp.pose.x, smp.pose.y}, s.dwa.radius);
  for (const auto& at : r.tracks)
    for (std::size_t i = 0; i < at.size() && i < s.moving.size(); ++i) grow(at[i], s.moving[i].r);
  const double w = x1 - x0, h = y1 - y0;
  const double scale = std::max(2.0, std::min(40.0, 800.0 / std::max(w, h)));
  const double pad = 30.0;
  auto X = [&](double x) { return pad + (x - x0) * scale; };
  auto Y = [&](double y) { return pad + (y1 - y) * scale; };
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{:.0f}\" height=\"{:.0f}\">\n",
      2.0 * pad + w * scale, 2.0 * pad + h * scale + 24.0);
  out += fmt::format("<title>{}</title>\n", xml_escape("pathref simulate (sensors2023 fused A* + following DWA, Fig. 9/13)"));
  out += fmt::format("<rect class=\"map\" x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"white\" stroke=\"black\"/>\n",
                     X(0), Y(static_cast<double>(s.grid.height())), static_cast<double>(s.grid.width()) * scale,
                     static_cast<double>(s.grid.height()) * scale);
  for (std::int64_t i = 0; i < s.grid.cell_count(); ++i) {
    const grid::Cell c = s.grid.cell(i);
    if (!s.grid.blocked(c)) continue;
    out += fmt::format("<rect class=\"obstacle\" x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"black\"/>\n",
                       X(static_cast<double>(c.x)), Y(static_cast<double>(c.y) + 1.0), scale, scale);
  }
  for (const dwa::Temporary& t : s.temporary) {
    out += fmt::format("<rect class=\"temporary\" x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"#a0a0a0\"/>\n",
                       X(static_cast<double>(t.cell.x)), Y(static_cast<double>(t.cell.y) + 1.0), scale, scale);
    out += fmt::format("<text class=\"temporary-label\" x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"9\">{:g}-{:g} s</text>\n",
                       X(static_cast<double>(t.cell.x) + 1.0) + 2.0, Y(static_cast<double>(t.cell.y) + 0.5),
                       t.appear, t.disappear);
  }
  auto polyline = [&](const char* cls, const char* colour, const char* extra, const std::vector<Point>& pts) {
    if (pts.empty()) return;
    out += fmt::format("<polyline class=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"2\"{} points=\"", cls, colour, extra);
    for (std::size_t i = 0; i < pts.size(); ++i) out += fmt::format("{}{:.2f},{:.2f}", i == 0 ? "" : " ", X(pts[i].x), Y(pts[i].y));
    out += "\"/>\n";
  };
  auto centre = [](grid::Cell c) { return Point{static_cast<double>(c.x) + 0.5, static_cast<double>(c.y) + 0.5}; };
  std::vector<Point> gp;
  for (const grid::Cell c : r.global_path) gp.push_back(centre(c));
  polyline("global-path", "#3070ff", " stroke-dasharray=\"6,4\"", gp);
  for (const grid::Cell c : r.key_nodes) {
    const Point p = centre(c);
    out += fmt::format("<rect class=\"key-node\" x=\"{:.2f}\" y=\"{:.2f}\" width=\"6\" height=\"6\" fill=\"none\" stroke=\"#3070ff\"/>\n",
                       X(p.x) - 3.0, Y(p.y) - 3.0);
  }
  std::vector<Point> track;
  for (const auto& smp : r.samples) track.push_back(Point{smp.pose.x, smp.pose.y});
  polyline("trajectory", "#0030c0", "", track);
  for (std::size_t o = 0; o < s.moving.size(); ++o) {
    std::vector<Point> tr;
    for (const auto& at : r.tracks)
      if (o < at.size()) tr.push_back(at[o]);
    polyline("obstacle-track", "#e0a000", " stroke-dasharray=\"2,3\"", tr);
    if (!tr.empty())
      out += fmt::format("<circle class=\"obstacle-end\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" fill=\"#f0c000\" stroke=\"black\"/>\n",
                         X(tr.back().x), Y(tr.back().y), s.moving[o].r * scale);
  }
  // time marks every `mark` seconds (at most 20), on the robot and on every mover (same samples)
  const double end_t = r.samples.empty() ? 0.0 : r.samples.back().t;
  double mark = 1.0;
  for (const double m : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0, 2000.0, 5000.0, 10000.0, 20000.0, 50000.0, 100000.0}) {
    mark = m;
    if (end_t / m <= 20.0) break;
  }
  std::int64_t next = 0;
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    if (r.samples[i].t + 1e-9 < static_cast<double>(next) * mark) continue;
    const double label = static_cast<double>(next) * mark;
    while (r.samples[i].t + 1e-9 >= static_cast<double>(next) * mark) ++next;
    const Point p{r.samples[i].pose.x, r.samples[i].pose.y};
    out += fmt::format("<circle class=\"time-mark\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"2\" fill=\"#0030c0\"/>\n", X(p.x), Y(p.y));
    out += fmt::format("<text class=\"time-mark-label\" x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"9\" fill=\"#0030c0\">{:g}</text>\n",
                       X(p.x) + 3.0, Y(p.y) - 3.0, label);
    if (i < r.tracks.size())
      for (const Point& q : r.tracks[i]) {
        out += fmt::format("<circle class=\"obstacle-time-mark\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"2\" fill=\"#b07000\"/>\n", X(q.x), Y(q.y));
        out += fmt::format("<text class=\"obstacle-time-mark-label\" x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"9\" fill=\"#b07000\">{:g}</text>\n",
                           X(q.x) + 3.0, Y(q.y) + 9.0, label);
      }
  }
  const Point st = centre(s.start), go = centre(s.goal);
  out += fmt::format("<polygon class=\"start\" points=\"{:.2f},{:.2f} {:.2f},{:.2f} {:.2f},{:.2f}\" fill=\"green\"/>\n", X(st.x),
                     Y(st.y) - 6.0, X(st.x) - 5.0, Y(st.y) + 4.0, X(st.x) + 5.0, Y(st.y) + 4.0);
  out += fmt::format("<circle class=\"goal\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"5\" fill=\"none\" stroke=\"red\" stroke-width=\"2\"/>\n",
                     X(go.x), Y(go.y));
  out += fmt::format("<text class=\"summary\" x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"12\">{}: time {:.1f} s, length {:.2f} m, turns {}, min clearance {:.3f} m; marks every {:g} s</text>\n",
                     pad, 2.0 * pad + h * scale + 12.0, dwa::to_string(r.outcome), r.time, r.length, r.turns,
                     r.min_clearance, mark);
  out += "</svg>\n";
  return out;
}

}  // namespace pathref::io
