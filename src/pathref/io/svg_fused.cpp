// The fused-run figure (sensors2023 Fig. 9/13) on the plotting layer. Spec: spec/figures.md.
#include "pathref/io/svg_fused.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "pathref/io/plot.hpp"

namespace pathref::io {

std::string svg_fused(const dwa::FusedScenario& s, const dwa::FusedResult& r) {
  using dwa::Point;
  using plot::num;
  plot::Extent ext;
  ext.add(0.0, 0.0);
  ext.add(static_cast<double>(s.grid.width()), static_cast<double>(s.grid.height()));
  for (const auto& smp : r.samples) ext.add(smp.pose.x, smp.pose.y, s.dwa.radius);
  for (const auto& at : r.tracks)
    for (std::size_t i = 0; i < at.size() && i < s.moving.size(); ++i) ext.add(at[i].x, at[i].y, s.moving[i].r);
  plot::Figure fig;
  fig.title("Fused A* + following DWA run (cf. sensors2023, Figs. 9 and 13)");
  const plot::Frame f = plot::fit_frame(ext.x0, ext.y0, ext.x1, ext.y1, fig.inner_left(), fig.y() + 4.0,
                                        fig.inner_width(), 1.2 * fig.inner_width(), 40.0);
  const auto P = [&](Point p) { return std::pair{f.X(p.x), f.Y(p.y)}; };
  const auto centre = [](grid::Cell c) { return Point{static_cast<double>(c.x) + 0.5, static_cast<double>(c.y) + 0.5}; };
  std::string b = fmt::format("<title>{}</title>\n",
                              plot::escape("pathref simulate (sensors2023 fused A* + following DWA, Fig. 9/13)"));
  b += fmt::format("<rect class=\"map\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"white\" stroke=\"black\"/>\n",
                   num(f.X(0.0)), num(f.Y(static_cast<double>(s.grid.height()))),
                   num(static_cast<double>(s.grid.width()) * f.scale), num(static_cast<double>(s.grid.height()) * f.scale));
  b += plot::obstacle_cells(s.grid, f);
  plot::LabelPlacer labels(plot::Box{0.0, fig.y(), fig.width(), f.top + f.height() + 8.0});
  std::string label_svg;
  std::vector<plot::LegendEntry> legend;
  for (const dwa::Temporary& t : s.temporary) {
    const double x = f.X(static_cast<double>(t.cell.x)), y = f.Y(static_cast<double>(t.cell.y) + 1.0);
    b += fmt::format("<rect class=\"temporary\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#A0A0A0\"/>\n", num(x),
                     num(y), num(f.scale), num(f.scale));
    labels.reserve(plot::Box{x, y, x + f.scale, y + f.scale});
  }
  for (const dwa::Temporary& t : s.temporary)
    label_svg += labels.place(f.X(static_cast<double>(t.cell.x) + 0.5), f.Y(static_cast<double>(t.cell.y) + 0.5),
                              fmt::format("{:g}-{:g} s", t.appear, t.disappear), f.scale / 2.0 + 1.0,
                              "temporary-label", "#505050");
  if (!s.temporary.empty()) legend.push_back({"temporary obstacle (present s)", plot::Swatch::square, "#A0A0A0"});
  std::vector<std::pair<double, double>> gp;
  for (const grid::Cell c : r.global_path) gp.push_back(P(centre(c)));
  if (!gp.empty()) {
    b += plot::polyline(gp, "global-path", plot::kSky, 2.0, "6 4");
    legend.push_back({"global path", plot::Swatch::line, plot::kSky, "6 4"});
  } else {
    legend.push_back({"global path — none found", plot::Swatch::line, plot::kSky, "6 4", true});
  }
  for (const grid::Cell c : r.key_nodes) {
    const auto [x, y] = P(centre(c));
    b += fmt::format("<rect class=\"key-node\" x=\"{}\" y=\"{}\" width=\"7\" height=\"7\" fill=\"none\" stroke=\"{}\" "
                     "stroke-width=\"1.5\"/>\n",
                     num(x - 3.5), num(y - 3.5), plot::kBlue);
  }
  if (!r.key_nodes.empty()) legend.push_back({"key node", plot::Swatch::box, plot::kBlue});
  std::vector<std::pair<double, double>> track;
  for (const auto& smp : r.samples) track.push_back(P(Point{smp.pose.x, smp.pose.y}));
  if (!track.empty()) b += plot::polyline(track, "trajectory", plot::kBlue, 2.5);
  legend.push_back({"robot", plot::Swatch::line, plot::kBlue});
  for (std::size_t o = 0; o < s.moving.size(); ++o) {
    std::vector<std::pair<double, double>> tr;
    for (const auto& at : r.tracks)
      if (o < at.size()) tr.push_back(P(at[o]));
    if (tr.empty()) continue;
    b += plot::polyline(tr, "obstacle-track", "black", 1.5, "1 3");
    b += fmt::format("<circle class=\"obstacle-end\" cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\" stroke=\"black\"/>\n",
                     num(tr.back().first), num(tr.back().second), num(s.moving[o].r * f.scale), plot::kYellow);
  }
  if (!s.moving.empty()) legend.push_back({"moving obstacle (end: yellow)", plot::Swatch::line, "black", "1 3"});
  // time marks on the robot and on every mover (the same samples, so equal labels are simultaneous)
  const double end_t = r.samples.empty() ? 0.0 : r.samples.back().t;
  const double mark = plot::mark_step(end_t);
  std::vector<double> times;
  for (const auto& smp : r.samples) times.push_back(smp.t);
  const auto marks = plot::mark_samples(times, mark);
  std::vector<double> mark_times;
  std::vector<std::pair<double, double>> robot;
  for (const auto& [i, t] : marks) {
    mark_times.push_back(t);
    robot.push_back(P(Point{r.samples[i].pose.x, r.samples[i].pose.y}));
  }
  b += plot::time_marks(robot, mark_times, "time-mark", plot::kBlue, labels, label_svg);
  for (std::size_t o = 0; o < s.moving.size(); ++o) {
    std::vector<std::pair<double, double>> pts;
    std::vector<double> ts;
    for (const auto& [i, t] : marks)
      if (i < r.tracks.size() && o < r.tracks[i].size()) {
        pts.push_back(P(r.tracks[i][o]));
        ts.push_back(t);
      }
    b += plot::time_marks(pts, ts, "obstacle-time-mark", "black", labels, label_svg);
  }
  const auto [sx, sy] = P(centre(s.start));
  const auto [gx, gy] = P(centre(s.goal));
  b += fmt::format("<polygon class=\"start\" points=\"{},{} {},{} {},{}\" fill=\"{}\"/>\n", num(sx), num(sy - 7.0),
                   num(sx - 6.0), num(sy + 5.0), num(sx + 6.0), num(sy + 5.0), plot::kGreen);
  b += fmt::format("<circle class=\"goal\" cx=\"{}\" cy=\"{}\" r=\"6\" fill=\"none\" stroke=\"{}\" stroke-width=\"2.5\"/>\n",
                   num(gx), num(gy), plot::kVermillion);
  fig.block(b + label_svg, f.height() + 8.0);
  legend.push_back({"time mark (s)", plot::Swatch::dot, plot::kBlue});
  legend.push_back({"start", plot::Swatch::triangle, plot::kGreen});
  legend.push_back({"goal", plot::Swatch::ring, plot::kVermillion});
  legend.push_back({"obstacle", plot::Swatch::square, "black"});
  fig.legend(legend);
  fig.caption(fmt::format("{}: time {:.1f} s, length {:.2f} m, turns {}, min clearance {:.3f} m; marks every {:g} s",
                          dwa::to_string(r.outcome), r.time, r.length, r.turns, r.min_clearance, mark),
              "summary");
  return fig.svg();
}

}  // namespace pathref::io
