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
  for (const sim::Sample& q : r.trajectory) {
    if (q.state != sim::RobotState::wait) continue;
    out += fmt::format("<circle class=\"wait\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"{:.2f}\" fill=\"none\" stroke=\"orange\"/>\n",
                       X(q.p.x), Y(q.p.y), s.robot_radius * scale);
  }
  const sim::Vec2 st = sim::centre(s.start), go = sim::centre(s.goal);
  out += fmt::format("<circle class=\"start\" cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"5\" fill=\"green\"/>\n", X(st.x), Y(st.y));
  out += fmt::format("<text class=\"goal\" x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"16\" fill=\"red\" text-anchor=\"middle\">x</text>\n",
                     X(go.x), Y(go.y) + 5.0);
  out += fmt::format("<text class=\"summary\" x=\"{:.2f}\" y=\"{:.2f}\" font-size=\"12\">time {:.3f} s, distance {:.3f} m, waits {}, replans {}, collisions {}</text>\n",
                     pad, 2.0 * pad + h * scale + 10.0, r.time, r.distance, r.waits.size(), r.replans.size(), r.collisions.size());
  out += "</svg>\n";
  return out;
}

}  // namespace pathref::io
