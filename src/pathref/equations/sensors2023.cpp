#include "pathref/equations/sensors2023.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "pathref/core/error.hpp"

namespace pathref::sensors2023 {

namespace {

constexpr std::int64_t coordinate_limit = std::int64_t{1} << 30;
constexpr double rad_to_deg = 57.29577951308232;  // the double nearest 180 / pi

void check_coordinates(grid::Cell c) {
  require(c.x > -coordinate_limit && c.x < coordinate_limit && c.y > -coordinate_limit &&
              c.y < coordinate_limit,
          "sensors2023: coordinates must satisfy |x|, |y| < 2^30");
}

/// The 8 moves in grid.neighbour-order (bit k).
constexpr std::array<std::array<int, 2>, 8> neighbour_moves = {
    {{-1, -1}, {0, -1}, {1, -1}, {-1, 0}, {1, 0}, {-1, 1}, {0, 1}, {1, 1}}};

}  // namespace

double goal_bearing(grid::Cell n, grid::Cell goal) {
  check_coordinates(n);
  check_coordinates(goal);
  require(!(n == goal), "sensors2023.eq1: the bearing of the goal from itself is undefined");
  const auto dx = static_cast<double>(goal.x - n.x);
  const auto dy = static_cast<double>(goal.y - n.y);
  const double theta = std::fmod((rad_to_deg * std::atan2(dx, dy)) + 360.0, 360.0);
  return theta;
}

int bearing_sector(double theta) {
  require(theta >= 0.0 && theta < 360.0, "sensors2023.eq1: the bearing must be in [0, 360)");
  int count = 0;
  for (int j = 0; j < 8; ++j)
    if (theta >= 22.5 + 45.0 * j) ++count;
  return count % 8;
}

std::array<int, 5> kept_bearings(int sector) {
  require(sector >= 0 && sector <= 7, "sensors2023.eq1: the sector must be in 0..7");
  std::array<int, 5> out{};
  for (int i = 0; i < 5; ++i) out[static_cast<std::size_t>(i)] = ((45 * sector) + 270 + 45 * i) % 360;
  std::sort(out.begin(), out.end());
  return out;
}

std::array<int, 3> abandoned_bearings(int sector) {
  require(sector >= 0 && sector <= 7, "sensors2023.eq1: the sector must be in 0..7");
  std::array<int, 3> out{};
  for (int i = 0; i < 3; ++i) out[static_cast<std::size_t>(i)] = ((45 * sector) + 135 + 45 * i) % 360;
  std::sort(out.begin(), out.end());
  return out;
}

grid::Cell bearing_move(int bearing) {
  switch (bearing) {
    case 0: return {0, 1};
    case 45: return {1, 1};
    case 90: return {1, 0};
    case 135: return {1, -1};
    case 180: return {0, -1};
    case 225: return {-1, -1};
    case 270: return {-1, 0};
    case 315: return {-1, 1};
    default: break;
  }
  throw DomainError("sensors2023.eq1: a direction bearing is one of 0, 45, ..., 315");
}

std::uint8_t bearing_mask(std::span<const int> bearings) {
  unsigned mask = 0;
  for (const int b : bearings) {
    const grid::Cell m = bearing_move(b);
    for (std::size_t k = 0; k < neighbour_moves.size(); ++k)
      if (neighbour_moves[k][0] == m.x && neighbour_moves[k][1] == m.y) mask |= (1u << k);
  }
  return static_cast<std::uint8_t>(mask);
}

bool neighbourhood_free(const grid::Grid& g, grid::Cell n, int radius) {
  require(g.in_bounds(n), "sensors2023.eq1: the node is outside the grid");
  require(radius >= 1 && radius <= 64, "sensors2023.eq1: the neighbourhood radius must be in 1..64");
  for (std::int64_t dy = -radius; dy <= radius; ++dy)
    for (std::int64_t dx = -radius; dx <= radius; ++dx) {
      if (dx == 0 && dy == 0) continue;
      const grid::Cell c{n.x + dx, n.y + dy};
      if (g.in_bounds(c) && g.blocked(c)) return false;
    }
  return true;
}

std::uint8_t child_moves(const grid::Grid& g, grid::Cell n, grid::Cell goal, int radius) {
  const bool free = neighbourhood_free(g, n, radius);
  if (n == goal || !free) return 0xFF;
  const std::array<int, 5> kept = kept_bearings(bearing_sector(goal_bearing(n, goal)));
  return bearing_mask(kept);
}

double f_basic(double g, double h) {
  require(std::isfinite(g) && g >= 0.0 && std::isfinite(h) && h >= 0.0,
          "sensors2023.eq3: g and h must be finite and >= 0");
  return g + h;
}

WeightForm parse_weight_form(std::string_view name) {
  if (name == "linear") return WeightForm::linear;
  if (name == "exp") return WeightForm::exp;
  if (name == "none") return WeightForm::none;
  throw UsageError("weight must be linear, exp or none, not '" + std::string(name) + "'");
}

std::string_view to_string(WeightForm w) noexcept {
  switch (w) {
    case WeightForm::linear: return "linear";
    case WeightForm::exp: return "exp";
    case WeightForm::none: return "none";
  }
  return "none";
}

double heuristic_weight(double r, double R, WeightForm form) {
  require(std::isfinite(r) && r >= 0.0 && std::isfinite(R) && R >= 0.0,
          "sensors2023.eq4: r and R must be finite and >= 0");
  if (form == WeightForm::none || R == 0.0) return 1.0;
  const double q = r / R;
  return form == WeightForm::linear ? 1.0 + q : std::exp(q);
}

double f_weighted(double g, double h, double r, double R, WeightForm form) {
  require(std::isfinite(g) && g >= 0.0 && std::isfinite(h) && h >= 0.0,
          "sensors2023.eq4: g and h must be finite and >= 0");
  return g + (heuristic_weight(r, R, form) * h);
}

bool segment_blocked(const grid::Grid& g, grid::Cell a, grid::Cell b) {
  require(g.in_bounds(a) && g.in_bounds(b), "sensors2023: segment end outside the grid");
  if (a == b) return g.blocked(a);  // a point: the centre lies in the open square of its cell
  // Doubled coordinates: centre of (x, y) = (2x + 1, 2y + 1); cell (x, y) = [2x, 2x+2] x [2y, 2y+2].
  const std::int64_t ax = 2 * a.x + 1;
  const std::int64_t ay = 2 * a.y + 1;
  const std::int64_t bx = 2 * b.x + 1;
  const std::int64_t by = 2 * b.y + 1;
  const std::int64_t dx = bx - ax;
  const std::int64_t dy = by - ay;
  const std::int64_t minx = std::min(ax, bx);
  const std::int64_t maxx = std::max(ax, bx);
  const std::int64_t miny = std::min(ay, by);
  const std::int64_t maxy = std::max(ay, by);
  const auto meets = [&](std::int64_t x, std::int64_t y) {
    const std::int64_t x0 = 2 * x;
    const std::int64_t y0 = 2 * y;
    if (maxx <= x0 || minx >= x0 + 2 || maxy <= y0 || miny >= y0 + 2) return false;
    bool pos = false;
    bool neg = false;
    for (const auto& [cx, cy] : {std::pair{x0, y0}, std::pair{x0 + 2, y0}, std::pair{x0, y0 + 2},
                                 std::pair{x0 + 2, y0 + 2}}) {
      const std::int64_t s = dx * (cy - ay) - dy * (cx - ax);
      pos = pos || s > 0;
      neg = neg || s < 0;
    }
    return pos && neg;
  };
  // Candidate cells: per column x, the rows the segment can reach there (one row of slack; the
  // exact test above decides).
  const std::int64_t cx0 = std::min(a.x, b.x);
  const std::int64_t cx1 = std::max(a.x, b.x);
  const std::int64_t cy0 = std::min(a.y, b.y);
  const std::int64_t cy1 = std::max(a.y, b.y);
  for (std::int64_t x = cx0; x <= cx1; ++x) {
    std::int64_t r0 = cy0;
    std::int64_t r1 = cy1;
    if (dx != 0) {
      const double xl = static_cast<double>(std::max(minx, 2 * x));
      const double xr = static_cast<double>(std::min(maxx, 2 * x + 2));
      const double slope = static_cast<double>(dy) / static_cast<double>(dx);
      const double yl = static_cast<double>(ay) + (xl - static_cast<double>(ax)) * slope;
      const double yr = static_cast<double>(ay) + (xr - static_cast<double>(ax)) * slope;
      r0 = std::max(cy0, static_cast<std::int64_t>(std::floor(std::min(yl, yr) / 2.0)) - 1);
      r1 = std::min(cy1, static_cast<std::int64_t>(std::floor(std::max(yl, yr) / 2.0)) + 1);
    }
    for (std::int64_t y = r0; y <= r1; ++y)
      if (g.blocked(grid::Cell{x, y}) && meets(x, y)) return true;
  }
  return false;
}

SafetyCompare parse_safety_compare(std::string_view name) {
  if (name == "ge") return SafetyCompare::ge;
  if (name == "gt") return SafetyCompare::gt;
  throw UsageError("safety must be ge or gt, not '" + std::string(name) + "'");
}

std::string_view to_string(SafetyCompare c) noexcept {
  return c == SafetyCompare::ge ? "ge" : "gt";
}

SafetyCheck safety_test(const grid::Grid& g, grid::Cell a, grid::Cell b, int k, double ds,
                        SafetyCompare compare) {
  require(g.in_bounds(a) && g.in_bounds(b), "sensors2023.eq5: segment end outside the grid");
  require(!(a == b), "sensors2023.eq5: the segment needs two distinct nodes");
  require(k >= 1 && k <= 1024, "sensors2023.eq5: k must be in 1..1024");
  require(std::isfinite(ds) && ds >= 0.0 && ds <= 64.0,
          "sensors2023.eq5: the safety distance must be finite, in [0, 64]");
  const std::int64_t ix = b.x - a.x;
  const std::int64_t iy = b.y - a.y;
  const auto dx = static_cast<double>(ix);
  const auto dy = static_cast<double>(iy);
  const double norm = std::sqrt(static_cast<double>(ix * ix + iy * iy));
  SafetyCheck out;
  out.divisions = static_cast<std::int64_t>(std::ceil(static_cast<double>(k) * norm));
  const auto reach = static_cast<std::int64_t>(std::ceil(ds)) + 1;
  for (std::int64_t m = 0; m <= out.divisions; ++m) {
    const double t = static_cast<double>(m) / static_cast<double>(out.divisions);
    const double qx = static_cast<double>(a.x) + (t * dx);
    const double qy = static_cast<double>(a.y) + (t * dy);
    const auto ox0 = static_cast<std::int64_t>(std::floor(qx)) - reach;
    const auto oy0 = static_cast<std::int64_t>(std::floor(qy)) - reach;
    for (std::int64_t oy = std::max<std::int64_t>(0, oy0);
         oy <= std::min(g.height() - 1, oy0 + 2 * reach + 1); ++oy)
      for (std::int64_t ox = std::max<std::int64_t>(0, ox0);
           ox <= std::min(g.width() - 1, ox0 + 2 * reach + 1); ++ox) {
        if (!g.blocked(grid::Cell{ox, oy})) continue;
        const double ex = qx - static_cast<double>(ox);
        const double ey = qy - static_cast<double>(oy);
        const double d = std::sqrt((ex * ex) + (ey * ey));
        const bool ok = compare == SafetyCompare::ge ? d >= ds : d > ds;
        if (!ok) {
          out.safe = false;
          return out;  // the first violation decides
        }
      }
  }
  return out;
}

}  // namespace pathref::sensors2023
