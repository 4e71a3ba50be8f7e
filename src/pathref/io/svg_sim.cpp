// Han's simulation figure on the plotting layer. Spec: spec/han-sim.md#cli, spec/figures.md.
#include "pathref/io/svg_sim.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "pathref/io/plot.hpp"

namespace pathref::io {

std::string svg_simulation(const sim::Scenario& s, const sim::SimResult& r) {
  using plot::num;
  // The view: the map and everything drawn (tracks may leave the map), so all fits the canvas.
  plot::Extent ext;
  ext.add(0.0, 0.0);
  ext.add(static_cast<double>(s.grid.width()), static_cast<double>(s.grid.height()));
  for (const sim::Sample& q : r.trajectory) ext.add(q.p.x, q.p.y, s.robot_radius);
  for (std::size_t o = 0; o < r.obstacle_tracks.size(); ++o)
    for (const sim::Vec2& p : r.obstacle_tracks[o])
      ext.add(p.x, p.y, o < s.obstacles.size() ? s.obstacles[o].radius : 0.0);
  plot::Figure fig;
  fig.title("Simulation of IACO-A* with moving obstacles (cf. Han, Fig. 8)");
  const plot::Frame f = plot::fit_frame(ext.x0, ext.y0, ext.x1, ext.y1, fig.inner_left(), fig.y() + 4.0,
                                        fig.inner_width(), 1.2 * fig.inner_width(), 40.0);
  const auto P = [&](sim::Vec2 p) { return std::pair{f.X(p.x), f.Y(p.y)}; };
  const auto cells = [&](const std::vector<grid::Cell>& cs) {
    std::vector<std::pair<double, double>> v;
    for (const grid::Cell c : cs) v.push_back(P(sim::centre(c)));
    return v;
  };
  std::string b = fmt::format("<title>{}</title>\n", plot::escape("pathref simulate (Han IACO-A*, Fig. 8)"));
  b += fmt::format("<rect class=\"map\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"white\" stroke=\"black\"/>\n",
                   num(f.X(0.0)), num(f.Y(static_cast<double>(s.grid.height()))),
                   num(static_cast<double>(s.grid.width()) * f.scale), num(static_cast<double>(s.grid.height()) * f.scale));
  b += plot::obstacle_cells(s.grid, f);
  std::vector<plot::LegendEntry> legend;
  if (!r.global_path.empty()) {
    b += plot::polyline(cells(r.global_path), "global-path", plot::kGrey, 2.0, "6 4");
    legend.push_back({"global path", plot::Swatch::line, plot::kGrey, "6 4"});
  }
  for (const sim::Replan& p : r.replans)
    if (!p.detour.empty()) b += plot::polyline(cells(p.detour), "detour", plot::kSky, 2.0, "2 2");
  if (!r.replans.empty()) legend.push_back({"local detour", plot::Swatch::line, plot::kSky, "2 2"});
  std::vector<std::pair<double, double>> traj;
  for (const sim::Sample& q : r.trajectory) traj.push_back(P(q.p));
  if (!traj.empty()) b += plot::polyline(traj, "trajectory", plot::kGreen, 2.5);
  legend.push_back({traj.empty() ? "robot — no trajectory" : "robot", plot::Swatch::line, plot::kGreen, "", traj.empty()});
  for (const sim::Evasion& e : r.evasions)
    if (!e.path.empty()) b += plot::polyline(cells(e.path), "evasion", plot::kPurple, 2.0, "4 2");
  if (!r.evasions.empty()) legend.push_back({"evasion", plot::Swatch::line, plot::kPurple, "4 2"});

  plot::LabelPlacer labels(plot::Box{0.0, fig.y(), fig.width(), f.top + f.height() + 8.0});
  std::string label_svg;
  for (std::size_t o = 0; o < r.obstacle_tracks.size(); ++o) {
    if (r.obstacle_tracks[o].empty()) continue;
    std::vector<std::pair<double, double>> t;
    for (const sim::Vec2& p : r.obstacle_tracks[o]) t.push_back(P(p));
    b += plot::polyline(t, "obstacle-track", "black", 1.5, "1 3");
    const auto [x, y] = t.front();
    const double rad = (o < s.obstacles.size() ? s.obstacles[o].radius : 0.0) * f.scale;
    b += fmt::format("<circle class=\"obstacle-start\" cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"none\" stroke=\"black\"/>\n",
                     num(x), num(y), num(rad));
    labels.reserve(plot::Box{x - rad, y - rad, x + rad, y + rad});
    label_svg += labels.place(x, y, fmt::format("O{}", o + 1), rad + 2.0, "obstacle-label", "black");
  }
  if (!r.obstacle_tracks.empty())
    legend.push_back({"moving obstacle (start ring)", plot::Swatch::line, "black", "1 3"});
  // figures.waits: one marker per wait, at the place of the wait, labelled with its duration;
  // consecutive waits less than a robot diameter apart share one marker ("N waits, T s").
  struct WaitMark {
    sim::Vec2 p;
    double total = 0.0;
    int count = 0;
  };
  std::vector<WaitMark> wait_marks;
  for (const sim::Wait& wt : r.waits) {
    const auto at = std::find_if(r.trajectory.begin(), r.trajectory.end(), [&](const sim::Sample& q) { return q.t == wt.start; });
    if (at == r.trajectory.end()) continue;
    if (!wait_marks.empty()) {
      const sim::Vec2 d{at->p.x - wait_marks.back().p.x, at->p.y - wait_marks.back().p.y};
      if (d.x * d.x + d.y * d.y < 4.0 * s.robot_radius * s.robot_radius) {
        wait_marks.back().total += wt.end - wt.start;
        wait_marks.back().count += 1;
        continue;
      }
    }
    wait_marks.push_back({at->p, wt.end - wt.start, 1});
  }
  const double wait_r = std::max(4.0, s.robot_radius * f.scale);
  for (const WaitMark& w : wait_marks) {  // every ring first, so no label covers a later ring
    const auto [x, y] = P(w.p);
    b += fmt::format("<circle class=\"wait\" cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"2\"/>\n",
                     num(x), num(y), num(wait_r), plot::kOrange);
    labels.reserve(plot::Box{x - wait_r, y - wait_r, x + wait_r, y + wait_r});
  }
  for (const WaitMark& w : wait_marks) {
    const auto [x, y] = P(w.p);
    label_svg += labels.place(x, y,
                              w.count == 1 ? fmt::format("wait {:.1f} s", w.total)
                                           : fmt::format("{} waits, {:.1f} s", w.count, w.total),
                              wait_r + 2.0, "wait-label", "#A06000");
  }
  if (!r.waits.empty()) legend.push_back({"wait (duration)", plot::Swatch::ring, plot::kOrange});
  // figures.time-marks: on the robot's trajectory and on every obstacle's track at the same samples,
  // so equal labels are simultaneous; a wait's marks share one dot labelled "first-last".
  const double end_t = r.trajectory.empty() ? 0.0 : r.trajectory.back().t;
  const double mark = plot::mark_step(end_t);
  std::vector<double> times;
  for (const sim::Sample& q : r.trajectory) times.push_back(q.t);
  const auto marks = plot::mark_samples(times, mark);
  std::vector<double> mark_times;
  for (const auto& m : marks) mark_times.push_back(m.second);
  const auto at_marks = [&](const auto& point_of) {
    std::vector<std::pair<double, double>> v;
    for (const auto& m : marks) v.push_back(P(point_of(m.first)));
    return v;
  };
  b += plot::time_marks(at_marks([&](std::size_t i) { return r.trajectory[i].p; }), mark_times, "time-mark", "#006048",
                        labels, label_svg);
  for (std::size_t o = 0; o < r.obstacle_tracks.size(); ++o)
    if (r.obstacle_tracks[o].size() == r.trajectory.size())
      b += plot::time_marks(at_marks([&](std::size_t i) { return r.obstacle_tracks[o][i]; }), mark_times,
                            "obstacle-time-mark", "black", labels, label_svg);
  const auto [sx, sy] = P(sim::centre(s.start));
  const auto [gx, gy] = P(sim::centre(s.goal));
  b += fmt::format("<circle class=\"start\" cx=\"{}\" cy=\"{}\" r=\"6\" fill=\"{}\" stroke=\"black\"/>\n", num(sx), num(sy),
                   plot::kGreen);
  b += fmt::format("<path class=\"goal\" d=\"M{} {}L{} {}M{} {}L{} {}\" stroke=\"{}\" stroke-width=\"3\"/>\n", num(gx - 6.0),
                   num(gy - 6.0), num(gx + 6.0), num(gy + 6.0), num(gx + 6.0), num(gy - 6.0), num(gx - 6.0), num(gy + 6.0),
                   plot::kVermillion);
  fig.block(b + label_svg, f.height() + 8.0);
  legend.push_back({"time mark (s)", plot::Swatch::dot, "#006048"});
  legend.push_back({"start", plot::Swatch::dot, plot::kGreen});
  legend.push_back({"goal", plot::Swatch::cross, plot::kVermillion});
  legend.push_back({"obstacle", plot::Swatch::square, "black"});
  fig.legend(legend);
  fig.caption(fmt::format("time {:.3f} s, distance {:.3f} m, waits {}, replans {}, evasions {}, collisions {}.", r.time,
                          r.distance, r.waits.size(), r.replans.size(), r.evasions.size(), r.collisions.size()),
              "summary");
  fig.caption(fmt::format("time marks every {:g} s; labels where they fit", mark), "summary");
  return fig.svg();
}

}  // namespace pathref::io
