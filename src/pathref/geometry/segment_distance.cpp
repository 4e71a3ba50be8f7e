// Planar distances (han.collision.classify): scalars in a pinned order.
#include "pathref/geometry/segment_distance.hpp"

#include <cmath>

namespace pathref::geometry {

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

}  // namespace pathref::geometry
