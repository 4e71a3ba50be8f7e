#include "pathref/sim/encounter.hpp"

#include <cmath>
#include <numbers>

#include "pathref/core/error.hpp"

namespace pathref::sim {

Vec2 centre(grid::Cell c) noexcept {
  return Vec2{static_cast<double>(c.x) + 0.5, static_cast<double>(c.y) + 0.5};
}

namespace {
double projected_distance(Vec2 p, Vec2 a, Vec2 b, bool clamp_end) noexcept {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double len2 = (dx * dx) + (dy * dy);
  double s = 0.0;
  if (len2 != 0.0) {
    s = (((p.x - a.x) * dx) + ((p.y - a.y) * dy)) / len2;
    if (s < 0.0) s = 0.0;
    if (clamp_end && s > 1.0) s = 1.0;
  }
  const double qx = a.x + (s * dx);
  const double qy = a.y + (s * dy);
  const double ex = p.x - qx;
  const double ey = p.y - qy;
  return std::sqrt((ex * ex) + (ey * ey));
}
}  // namespace

double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) noexcept { return projected_distance(p, a, b, true); }

double point_ray_distance(Vec2 p, Vec2 a, Vec2 b) noexcept { return projected_distance(p, a, b, false); }

namespace {
double orient(Vec2 a, Vec2 b, Vec2 c) noexcept {
  return ((b.x - a.x) * (c.y - a.y)) - ((b.y - a.y) * (c.x - a.x));
}
bool opposite(double s, double t) noexcept { return (s > 0.0 && t < 0.0) || (s < 0.0 && t > 0.0); }
bool finite(Vec2 v) noexcept { return std::isfinite(v.x) && std::isfinite(v.y); }
}  // namespace

double segment_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) noexcept {
  if (opposite(orient(a, b, c), orient(a, b, d)) && opposite(orient(c, d, a), orient(c, d, b)))
    return 0.0;
  double m = point_segment_distance(a, c, d);
  const double m2 = point_segment_distance(b, c, d);
  if (m2 < m) m = m2;
  const double m3 = point_segment_distance(c, a, b);
  if (m3 < m) m = m3;
  const double m4 = point_segment_distance(d, a, b);
  if (m4 < m) m = m4;
  return m;
}

std::string_view to_string(Encounter e) noexcept {
  switch (e) {
    case Encounter::none: return "none";
    case Encounter::side: return "side";
    case Encounter::frontal: return "frontal";
  }
  return "none";
}

Classification classify(std::span<const Vec2> robot, Vec2 p, Vec2 q, double clearance,
                        double frontal_cos) {
  require(robot.size() >= 2, "classify: the robot polyline needs at least two points");
  for (std::size_t k = 0; k < robot.size(); ++k) {
    require(finite(robot[k]), "classify: robot points must be finite");
    if (k > 0) require(!(robot[k] == robot[k - 1]), "classify: consecutive robot points must differ");
  }
  require(finite(p) && finite(q), "classify: obstacle points must be finite");
  require(std::isfinite(clearance) && clearance > 0.0, "classify: clearance must be finite and > 0");
  require(frontal_cos >= -1.0 && frontal_cos <= 1.0, "classify: frontal_cos must lie in [-1, 1]");
  Classification out;
  out.distance = segment_distance(robot[0], robot[1], p, q);
  out.piece = 0;
  for (std::size_t k = 1; k + 1 < robot.size(); ++k) {
    const double dk = segment_distance(robot[k], robot[k + 1], p, q);
    if (dk < out.distance) {
      out.distance = dk;
      out.piece = static_cast<std::int64_t>(k);
    }
  }
  out.obstacle_static = (p == q);
  out.robot_inside = point_ray_distance(robot[0], p, q) < clearance;
  const auto k = static_cast<std::size_t>(out.piece);
  const double ux = robot[k + 1].x - robot[k].x;
  const double uy = robot[k + 1].y - robot[k].y;
  const double vx = q.x - p.x;
  const double vy = q.y - p.y;
  if (!out.obstacle_static) {
    const double dot = (ux * vx) + (uy * vy);
    const double nu = std::sqrt((ux * ux) + (uy * uy));
    const double nv = std::sqrt((vx * vx) + (vy * vy));
    out.cos_angle = dot / (nu * nv);
    if (out.distance >= clearance) {
      out.kind = Encounter::none;
    } else {
      out.kind = dot <= ((frontal_cos * nu) * nv) ? Encounter::frontal : Encounter::side;
    }
  } else {
    out.kind = out.distance >= clearance ? Encounter::none : Encounter::frontal;
  }
  return out;
}

std::vector<grid::Cell> swept_cells(const grid::Grid& g, Vec2 p, Vec2 q, double clearance) {
  require(finite(p) && finite(q), "swept_cells: obstacle points must be finite");
  require(std::isfinite(clearance) && clearance > 0.0, "swept_cells: clearance must be finite and > 0");
  const double reach = clearance + (std::numbers::sqrt2 / 2.0);
  std::vector<grid::Cell> out;
  for (std::int64_t i = 0; i < g.cell_count(); ++i) {
    const grid::Cell c = g.cell(i);
    if (point_segment_distance(centre(c), p, q) < reach) out.push_back(c);
  }
  return out;
}

std::int64_t local_target(std::span<const std::uint8_t> blocked, std::int64_t from) {
  const auto n = static_cast<std::int64_t>(blocked.size());
  require(from >= 0 && from < n, "local_target: from must index the global path");
  std::int64_t last = -1;
  for (std::int64_t i = from; i < n; ++i)
    if (blocked[static_cast<std::size_t>(i)] != 0) last = i;
  if (last < 0) return from;
  if (last + 1 >= n) return -1;
  return last + 1;
}

}  // namespace pathref::sim
