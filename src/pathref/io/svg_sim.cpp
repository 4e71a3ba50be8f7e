#include "pathref/io/svg_sim.hpp"

#include <fmt/core.h>

#include <algorithm>

#include "pathref/io/svg.hpp"

namespace pathref::io {

std::string svg_simulation(const sim::Scenario& s, const sim::SimResult& r) {
  const auto w = static_cast<double>(s.grid.width());
  const auto h = static_cast<double>(s.grid.height());
  const double scale = std::max(4.0, std::min(40.0, 800.0 / std::max(w, h)));
  const double pad = 30.0;
  auto X = [&](double x) { return pad + x * scale; };
  auto Y = [&](double y) { return pad + (h - y) * scale; };
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{:.0f}\" height=\"{:.0f}\">\n",
      2.0 * pad + w * scale, 2.0 * pad + h * scale + 20.0);
  out += fmt::format("<title>{}</title>\n", xml_escape("pathref simulate (Han IACO-A*, Fig. 8)"));
  out += fmt::format("<rect class=\"map\" x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"white\" stroke=\"black\"/>\n",
                     X(0), Y(h), w * scale, h * scale);
  for (std::int64_t i = 0; i < s.grid.cell_count(); ++i) {
    const grid::Cell c = s.grid.cell(i);
    if (!s.grid.blocked(c)) continue;
    out += fmt::format("<rect class=\"obstacle\" x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"#3060c0\"/>\n",
                       X(static_cast<double>(c.x)), Y(static_cast<double>(c.y) + 1.0), scale, scale);
  }
  auto polyline = [&](const char* cls, const char* colour, const char* dash, const auto& pts) {
    if (pts.empty()) return;
    out += fmt::format("<polyline class=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"2\"{} points=\"", cls, colour, dash);
    for (std::size_t i = 0; i < pts.size(); ++i)
      out += fmt::format("{}{:.2f},{:.2f}", i == 0 ? "" : " ", X(pts[i].x), Y(pts[i].y));
    out += "\"/>\n";
  };
  std::vector<sim::Vec2> g;
  for (const grid::Cell c : r.global_path) g.push_back(sim::centre(c));
  polyline("global-path", "#606060", " stroke-dasharray=\"6,4\"", g);
  for (const sim::Replan& p : r.replans) {
    std::vector<sim::Vec2> d;
    for (const grid::Cell c : p.detour) d.push_back(sim::centre(c));
    polyline("detour", "#2080ff", " stroke-dasharray=\"2,2\"", d);
  }
  std::vector<sim::Vec2> traj;
  for (const sim::Sample& q : r.trajectory) traj.push_back(q.p);
  polyline("trajectory", "#10a010", "", traj);
  for (std::size_t o = 0; o < r.obstacle_tracks.size(); ++o) {
    polyline("obstacle-track", "black", " stroke-dasharray=\"1,3\"", r.obstacle_tracks[o]);
    if (!r.obstacle_tracks[o].empty()) {
      const sim::Vec2 p = r.obstacle_tracks[o].front();
      out += fmt::format("<text class=\"obstacle-label\" x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"12\">O{}</text>\n",
                         X(p.x) + 4.0, Y(p.y) - 4.0, o + 1);
      out += fmt::format("<circle class=\"obstacle-start\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" fill=\"none\" stroke=\"black\"/>\n",
                         X(p.x), Y(p.y), s.obstacles[o].radius * scale);
    }
  }
  for (const sim::Evasion& e : r.evasions) {
    std::vector<sim::Vec2> d;
    for (const grid::Cell c : e.path) d.push_back(sim::centre(c));
    polyline("evasion", "#a040c0", " stroke-dasharray=\"4,2\"", d);
  }
  // One marker per wait interval, at the place of the wait, labelled with its duration.
  for (const sim::Wait& wt : r.waits) {
    const sim::Sample* at = nullptr;
    for (const sim::Sample& q : r.trajectory)
      if (q.t == wt.start) {
        at = &q;
        break;
      }
    if (at == nullptr) continue;
    out += fmt::format("<circle class=\"wait\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" fill=\"none\" stroke=\"orange\" stroke-width=\"2\"/>\n",
                       X(at->p.x), Y(at->p.y), s.robot_radius * scale);
    out += fmt::format("<text class=\"wait-label\" x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"11\" fill=\"#c06000\">wait {:.1f} s</text>\n",
                       X(at->p.x) + s.robot_radius * scale + 3.0, Y(at->p.y) + 4.0, wt.end - wt.start);
  }
  // Time marks: every `mark` seconds (1 s up to 20 s of run, else 2, 5, 10, 20, 50, ... so that at
  // most 20 are labelled), at the first sample at or after each mark time, on the robot's
  // trajectory and on every obstacle's track (the same samples, so equal labels are simultaneous).
  const double end_t = r.trajectory.empty() ? 0.0 : r.trajectory.back().t;
  double mark = 1.0;
  for (const double m : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0, 1000.0, 2000.0, 5000.0}) {
    mark = m;
    if (end_t / m <= 20.0) break;
  }
  std::vector<std::size_t> marked;
  std::vector<double> mark_times;
  {
    std::int64_t next = 0;
    for (std::size_t i = 0; i < r.trajectory.size(); ++i) {
      if (r.trajectory[i].t >= static_cast<double>(next) * mark) {
        marked.push_back(i);
        mark_times.push_back(static_cast<double>(next) * mark);
        while (r.trajectory[i].t >= static_cast<double>(next) * mark) ++next;
      }
    }
  }
  // Consecutive marks at the same place (a wait) share one dot, labelled "first-last".
  auto time_marks = [&](const char* cls, const char* colour, const auto& point_of) {
    for (std::size_t k = 0; k < marked.size();) {
      const sim::Vec2 p = point_of(marked[k]);
      std::size_t j = k + 1;
      while (j < marked.size() && point_of(marked[j]) == p) ++j;
      const std::string label = j == k + 1 ? fmt::format("{:g}", mark_times[k])
                                           : fmt::format("{:g}-{:g}", mark_times[k], mark_times[j - 1]);
      out += fmt::format("<circle class=\"{}\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"2\" fill=\"{}\"/>\n", cls, X(p.x), Y(p.y), colour);
      out += fmt::format("<text class=\"{}-label\" x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"9\" fill=\"{}\">{}</text>\n", cls,
                         X(p.x) + 3.0, Y(p.y) - 3.0, colour, label);
      k = j;
    }
  };
  time_marks("time-mark", "#107010", [&](std::size_t i) { return r.trajectory[i].p; });
  for (std::size_t o = 0; o < r.obstacle_tracks.size(); ++o)
    if (r.obstacle_tracks[o].size() == r.trajectory.size())
      time_marks("obstacle-time-mark", "black", [&](std::size_t i) { return r.obstacle_tracks[o][i]; });
  const sim::Vec2 st = sim::centre(s.start), go = sim::centre(s.goal);
  out += fmt::format("<circle class=\"start\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"5\" fill=\"green\"/>\n", X(st.x), Y(st.y));
  out += fmt::format("<text class=\"goal\" x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"16\" fill=\"red\" text-anchor=\"middle\">x</text>\n",
                     X(go.x), Y(go.y) + 5.0);
  out += fmt::format("<text class=\"summary\" x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"12\">time {:.3f} s, distance {:.3f} m, waits {}, replans {}, evasions {}, collisions {}; time marks every {:g} s</text>\n",
                     pad, 2.0 * pad + h * scale + 10.0, r.time, r.distance, r.waits.size(), r.replans.size(),
                     r.evasions.size(), r.collisions.size(), mark);
  out += "</svg>\n";
  return out;
}

}  // namespace pathref::io
