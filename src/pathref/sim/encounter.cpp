#include "pathref/sim/encounter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>
#include <tuple>

#include "pathref/sim/motion.hpp"

#include "pathref/core/error.hpp"

namespace pathref::sim {

Vec2 centre(grid::Cell c) noexcept {
  return Vec2{static_cast<double>(c.x) + 0.5, static_cast<double>(c.y) + 0.5};
}

namespace {
bool finite(Vec2 v) noexcept { return std::isfinite(v.x) && std::isfinite(v.y); }
}  // namespace

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

std::vector<grid::Cell> swept_ray_cells(const grid::Grid& g, Vec2 p, Vec2 q, double clearance) {
  require(finite(p) && finite(q), "swept_ray_cells: obstacle points must be finite");
  require(std::isfinite(clearance) && clearance > 0.0, "swept_ray_cells: clearance must be finite and > 0");
  const double reach = clearance + (std::numbers::sqrt2 / 2.0);
  std::vector<grid::Cell> out;
  for (std::int64_t i = 0; i < g.cell_count(); ++i) {
    const grid::Cell c = g.cell(i);
    if (point_ray_distance(centre(c), p, q) < reach) out.push_back(c);
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

Vec2 polyline_point(std::span<const Vec2> pts, double L) {
  require(!pts.empty(), "polyline_point: the polyline needs a point");
  if (L <= 0.0 || pts.size() == 1) return pts.front();
  double acc = 0.0;
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    const double dx = pts[k + 1].x - pts[k].x;
    const double dy = pts[k + 1].y - pts[k].y;
    const double len = std::sqrt((dx * dx) + (dy * dy));
    if (L <= acc + len) {
      if (len == 0.0) return pts[k];
      const double f = (L - acc) / len;
      return Vec2{pts[k].x + (f * dx), pts[k].y + (f * dy)};
    }
    acc += len;
  }
  return pts.back();
}

Margins safety_margins(std::span<const Vec2> pts, double v0, double v_max, double accel, double dt,
                       double horizon, const rls::LinearMotion& m, double tau) {
  require(!pts.empty(), "safety_margins: the robot path needs a point");
  for (const Vec2 p : pts) require(finite(p), "safety_margins: robot points must be finite");
  require(std::isfinite(dt) && dt > 0.0, "safety_margins: dt must be finite and > 0");
  require(std::isfinite(horizon) && horizon > 0.0, "safety_margins: horizon must be finite and > 0");
  require(std::isfinite(tau), "safety_margins: tau must be finite");
  require(std::isfinite(v_max) && v_max > 0.0 && std::isfinite(accel) && accel > 0.0,
          "safety_margins: v_max and accel must be finite and > 0");
  require(std::isfinite(v0) && v0 >= 0.0 && v0 <= v_max, "safety_margins: v0 must lie in [0, v_max]");
  Margins out;
  out.wait = std::numeric_limits<double>::infinity();
  out.go = std::numeric_limits<double>::infinity();
  double prev_g = std::numeric_limits<double>::infinity();
  for (std::int64_t j = 0;; ++j) {
    const double s = static_cast<double>(j) * dt;
    if (s > horizon) break;
    const rls::Position o = rls::position(m, tau + s);
    const double d = j == 0 ? 0.0 : motion_step(v0, s, v_max, accel).distance;
    const Vec2 r = polyline_point(pts, d);
    const double wx = pts.front().x - o.x, wy = pts.front().y - o.y;
    const double gx = r.x - o.x, gy = r.y - o.y;
    const double w = std::sqrt((wx * wx) + (wy * wy));
    const double g = std::sqrt((gx * gx) + (gy * gy));
    if (w < out.wait) out.wait = w;
    if (g < out.go) out.go = g;
    out.go_closing = j > 0 && g < prev_g;
    prev_g = g;
    ++out.samples;
  }
  return out;
}

Refuge find_refuge(const grid::Grid& g, std::span<const RefugeSource> sources,
                   std::span<const std::uint8_t> band, grid::CornerPolicy policy) {
  require(static_cast<std::int64_t>(band.size()) == g.cell_count(), "find_refuge: one band flag per cell");
  require(!sources.empty(), "find_refuge: at least one source");
  const auto n = static_cast<std::size_t>(g.cell_count());
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> dist(n, inf);
  std::vector<std::int64_t> parent(n, -1);
  std::vector<std::int64_t> src(n, -1);
  std::vector<std::uint8_t> done(n, 0);
  using Key = std::tuple<double, std::int64_t>;
  std::priority_queue<Key, std::vector<Key>, std::greater<>> open;
  for (std::size_t i = 0; i < sources.size(); ++i) {
    const RefugeSource& s = sources[i];
    require(g.in_bounds(s.cell), "find_refuge: sources must lie in the grid");
    require(std::isfinite(s.cost) && s.cost >= 0.0, "find_refuge: source costs must be finite and >= 0");
    if (!g.free(s.cell)) continue;  // a blocked source (e.g. inside an obstacle's body) is skipped
    const auto k = static_cast<std::size_t>(g.index(s.cell));
    if (s.cost < dist[k]) {
      dist[k] = s.cost;
      src[k] = static_cast<std::int64_t>(i);
      open.emplace(s.cost, static_cast<std::int64_t>(k));
    }
  }
  Refuge out;
  while (!open.empty()) {
    const auto [d, u] = open.top();
    open.pop();
    const auto uu = static_cast<std::size_t>(u);
    if (done[uu] != 0 || d > dist[uu]) continue;
    done[uu] = 1;
    if (band[uu] == 0) {
      out.found = true;
      out.cost = d;
      out.source = src[uu];
      for (std::int64_t c = u; c >= 0; c = parent[static_cast<std::size_t>(c)]) out.path.push_back(g.cell(c));
      std::reverse(out.path.begin(), out.path.end());
      return out;
    }
    for (const grid::Move& mv : grid::neighbours(g, g.cell(u), policy)) {
      const auto v = static_cast<std::size_t>(g.index(mv.to));
      if (done[v] != 0) continue;
      const double nd = d + mv.cost;
      if (nd < dist[v]) {
        dist[v] = nd;
        parent[v] = u;
        src[v] = src[uu];
        open.emplace(nd, static_cast<std::int64_t>(v));
      }
    }
  }
  return out;
}

}  // namespace pathref::sim
