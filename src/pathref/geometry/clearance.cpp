#include "pathref/geometry/clearance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pathref/core/error.hpp"

namespace pathref::geometry {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

bool finite(Vec2 p) noexcept { return std::isfinite(p.x) && std::isfinite(p.y); }

double point_segment(Vec2 p, Vec2 a, Vec2 b) noexcept {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double len2 = (dx * dx) + (dy * dy);
  double s = 0.0;
  if (len2 > 0.0) s = std::clamp((((p.x - a.x) * dx) + ((p.y - a.y) * dy)) / len2, 0.0, 1.0);
  const double qx = a.x + (s * dx);
  const double qy = a.y + (s * dy);
  return std::sqrt(((p.x - qx) * (p.x - qx)) + ((p.y - qy) * (p.y - qy)));
}

/// Liang–Barsky: does the closed segment meet the closed box?
bool segment_meets_box(Vec2 a, Vec2 b, double x0, double y0, double x1, double y1) noexcept {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {a.x - x0, x1 - a.x, a.y - y0, y1 - a.y};
  double t0 = 0.0;
  double t1 = 1.0;
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0.0) {
      if (q[k] < 0.0) return false;
      continue;
    }
    const double t = q[k] / p[k];
    if (p[k] < 0.0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
  }
  return t0 <= t1;
}

double box_distance(Vec2 a, Vec2 b, double x0, double y0, double x1, double y1) noexcept {
  if (segment_meets_box(a, b, x0, y0, x1, y1)) return 0.0;
  double d = std::min(point_box_distance(a, x0, y0, x1, y1), point_box_distance(b, x0, y0, x1, y1));
  d = std::min(d, point_segment(Vec2{x0, y0}, a, b));
  d = std::min(d, point_segment(Vec2{x1, y0}, a, b));
  d = std::min(d, point_segment(Vec2{x0, y1}, a, b));
  d = std::min(d, point_segment(Vec2{x1, y1}, a, b));
  return d;
}

/// Distance from a point to the outside of [0, W] x [0, H] (0 if the point is not inside).
double border_point(Vec2 p, double w, double h) noexcept {
  return std::max(0.0, std::min({p.x, w - p.x, p.y, h - p.y}));
}

/// Least distance from segment [a, b] to a blocked cell, not looking beyond `cap`
/// (returns >= cap, possibly +inf, when no cell is nearer than cap).
double segment_cells(const grid::Grid& g, Vec2 a, Vec2 b, double cap) {
  const double minx = std::min(a.x, b.x);
  const double maxx = std::max(a.x, b.x);
  const double miny = std::min(a.y, b.y);
  const double maxy = std::max(a.y, b.y);
  const auto W = g.width();
  const auto H = g.height();
  // Clamp the bbox cells into a safe integer range first (points may lie far off the map).
  const auto cell_of = [](double v, std::int64_t n) {
    if (v < -1.0) return std::int64_t{-1};
    if (v > static_cast<double>(n)) return n;
    return static_cast<std::int64_t>(std::floor(v));
  };
  const std::int64_t cx0 = cell_of(minx, W);
  const std::int64_t cx1 = cell_of(maxx, W);
  const std::int64_t cy0 = cell_of(miny, H);
  const std::int64_t cy1 = cell_of(maxy, H);
  double best = inf;
  for (std::int64_t r = 1;; r *= 2) {
    const std::int64_t x0 = std::max<std::int64_t>(0, cx0 - r);
    const std::int64_t x1 = std::min<std::int64_t>(W - 1, cx1 + r);
    const std::int64_t y0 = std::max<std::int64_t>(0, cy0 - r);
    const std::int64_t y1 = std::min<std::int64_t>(H - 1, cy1 + r);
    for (std::int64_t y = y0; y <= y1; ++y)
      for (std::int64_t x = x0; x <= x1; ++x)
        if (g.blocked(grid::Cell{x, y})) {
          const auto fx = static_cast<double>(x);
          const auto fy = static_cast<double>(y);
          best = std::min(best, box_distance(a, b, fx, fy, fx + 1.0, fy + 1.0));
        }
    // Every cell outside the window is at least r away from the segment's bounding box.
    const bool whole = x0 == 0 && y0 == 0 && x1 == W - 1 && y1 == H - 1;
    if (best <= static_cast<double>(r) || whole || static_cast<double>(r) >= cap) return best;
  }
}

}  // namespace

std::string_view to_string(ClearanceVerdict v) noexcept {
  switch (v) {
    case ClearanceVerdict::clear: return "clear";
    case ClearanceVerdict::enters: return "enters";
    case ClearanceVerdict::undetermined: return "undetermined";
  }
  return "undetermined";
}

double point_box_distance(Vec2 p, double x0, double y0, double x1, double y1) noexcept {
  const double dx = std::max({x0 - p.x, 0.0, p.x - x1});
  const double dy = std::max({y0 - p.y, 0.0, p.y - y1});
  return std::sqrt((dx * dx) + (dy * dy));
}

double segment_box_distance(Vec2 a, Vec2 b, double x0, double y0, double x1, double y1) {
  require(finite(a) && finite(b) && std::isfinite(x0) && std::isfinite(y0) && std::isfinite(x1) &&
              std::isfinite(y1),
          "clearance: coordinates must be finite");
  require(x0 <= x1 && y0 <= y1, "clearance: box needs x0 <= x1 and y0 <= y1");
  return box_distance(a, b, x0, y0, x1, y1);
}

namespace {

/// The shared part of curves.clearance and curves.polygon-clearance: checks, the exact polyline
/// distance from `segment_distance(a, b, cap)` (the segment's distance, or any value >= cap when
/// it is >= cap), the bounds from `point_distance(p, cap)` and the verdict.
template <class SegmentDistance, class PointDistance>
Clearance clearance_of(std::span<const Vec2> points, const ClearanceOptions& options,
                       const SegmentDistance& segment_distance, const PointDistance& point_distance) {
  require(!points.empty(), "clearance: no points");
  for (const Vec2& p : points) require(finite(p), "clearance: points must be finite");
  require(std::isfinite(options.inflation) && options.inflation >= 0.0,
          "clearance: inflation must be finite and >= 0");
  require(std::isfinite(options.tolerance) && options.tolerance >= 0.0,
          "clearance: tolerance must be finite and >= 0");
  Clearance out;
  out.distance = inf;
  // Segments (a single point: the point itself).
  const std::size_t pieces = points.size() == 1 ? 1 : points.size() - 1;
  for (std::size_t s = 0; s < pieces; ++s) {
    const Vec2 a = points[s];
    const Vec2 b = points.size() == 1 ? points[s] : points[s + 1];
    const double d = segment_distance(a, b, out.distance);
    if (d < out.distance) {
      out.distance = d;
      out.segment = static_cast<std::int64_t>(s);
    }
  }
  if (options.tolerance == 0.0) {
    out.lower = out.distance;
    out.upper = out.distance;
  } else {
    out.lower = std::max(0.0, out.distance - options.tolerance);
    double up = inf;
    for (const Vec2& p : points) up = std::min(up, point_distance(p, up));
    out.upper = up;
  }
  if (out.upper <= options.inflation) {
    out.verdict = ClearanceVerdict::enters;
  } else if (out.lower > options.inflation) {
    out.verdict = ClearanceVerdict::clear;
  } else {
    out.verdict = ClearanceVerdict::undetermined;
  }
  return out;
}

/// Distance from a point to the outside of [lo, hi] (0 if the point is not inside).
double border_rect(Vec2 p, Vec2 lo, Vec2 hi) noexcept {
  return std::max(0.0, std::min({p.x - lo.x, hi.x - p.x, p.y - lo.y, hi.y - p.y}));
}

}  // namespace

Clearance clearance(const grid::Grid& g, std::span<const Vec2> points,
                    const ClearanceOptions& options) {
  const auto w = static_cast<double>(g.width());
  const auto h = static_cast<double>(g.height());
  const auto segment_distance = [&](Vec2 a, Vec2 b, double cap) {
    double d = inf;
    if (options.border) d = std::min(border_point(a, w, h), border_point(b, w, h));
    return std::min(d, segment_cells(g, a, b, std::min(d, cap)));
  };
  const auto point_distance = [&](Vec2 p, double cap) {
    double d = options.border ? border_point(p, w, h) : inf;
    return std::min(d, segment_cells(g, p, p, std::min(cap, d)));
  };
  return clearance_of(points, options, segment_distance, point_distance);
}

Clearance clearance(const CollisionChecker& map, std::span<const Vec2> points,
                    const ClearanceOptions& options) {
  const Vec2 lo = map.lower();
  const Vec2 hi = map.upper();
  const auto segment_distance = [&](Vec2 a, Vec2 b, double /*cap*/) {
    double d = inf;
    if (options.border) d = std::min(border_rect(a, lo, hi), border_rect(b, lo, hi));
    return std::min(d, map.segment_clearance(a, b));
  };
  const auto point_distance = [&](Vec2 p, double /*cap*/) {
    const double d = options.border ? border_rect(p, lo, hi) : inf;
    return std::min(d, map.segment_clearance(p, p));
  };
  return clearance_of(points, options, segment_distance, point_distance);
}

}  // namespace pathref::geometry
