// Properties of exact inflation (spec/inflation.md): brute force, r = 0, monotonicity,
// translation by whole cells, grid rule = polygon rule, and binary64 disagreeing only near r.
// Scenes use coordinates in hundredths, so the test can decide "meets" with exact int64 maths.
#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/geometry/inflation.hpp"
#include "support/reach.hpp"

using namespace pathref;
using namespace pathref::geometry;
using grid::Cell;

namespace {

using I = std::int64_t;
struct IP {
  I x, y;
};

/// A scene in hundredths: cell (x,y) = [ox + x s, ox + (x+1) s] x [oy + y s, ...] / 100.
struct IScene {
  I ox = 0, oy = 0, s = 100, r = 0;
  I w = 1, h = 1;
  std::vector<std::vector<IP>> polys;
};

/// RapidCheck prints counterexamples with this (found by ADL).
[[maybe_unused]] void showValue(const IScene& is, std::ostream& os) {
  os << "origin (" << is.ox << ", " << is.oy << ")/100, cell " << is.s << "/100, " << is.w << "x" << is.h
     << ", r " << is.r << "/100, polygons (hundredths):";
  for (const auto& p : is.polys) {
    os << " [";
    for (const IP& v : p) os << " (" << v.x << "," << v.y << ")";
    os << " ]";
  }
}

Decimal hundredths(I v) { return *parse_decimal(std::to_string(v) + "e-2"); }

Scene to_scene(const IScene& is, I r_override = -1) {
  Scene s;
  s.origin = {hundredths(is.ox), hundredths(is.oy)};
  s.width = is.w;
  s.height = is.h;
  s.cell_size = hundredths(is.s);
  s.radius = hundredths(r_override >= 0 ? r_override : is.r);
  s.margin = Decimal{};
  for (const auto& p : is.polys) {
    Polygon q;
    for (const IP& v : p) q.vertices.push_back({hundredths(v.x), hundredths(v.y)});
    s.polygons.push_back(q);
  }
  return s;
}

bool valid(const Scene& s) {
  try {
    validate_polygons(s);
    return true;
  } catch (const DomainError&) {
    return false;
  }
}

rc::Gen<IScene> gen_scene() {
  return rc::gen::exec([] {
    IScene is;
    is.s = *rc::gen::element<I>(100, 50, 30, 25, 10, 170, 7);
    is.ox = *rc::gen::inRange<I>(-100, 101);
    is.oy = *rc::gen::inRange<I>(-100, 101);
    is.w = *rc::gen::inRange<I>(1, 7);
    is.h = *rc::gen::inRange<I>(1, 7);
    is.r = *rc::gen::element<I>(0, 0, 10, 25, 30, 50, 100, 150, *rc::gen::inRange<I>(0, 200));
    const I span = std::max(is.w, is.h) * is.s;
    const int n = *rc::gen::inRange(1, 3);
    for (int k = 0; k < n; ++k) {
      const int m = *rc::gen::inRange(3, 7);
      const I cx = is.ox + *rc::gen::inRange<I>(-span / 4, span + span / 4 + 1);
      const I cy = is.oy + *rc::gen::inRange<I>(-span / 4, span + span / 4 + 1);
      // star-shaped around (cx, cy): sorted angles, integer radii (validated afterwards)
      std::vector<int> ang;
      for (int i = 0; i < m; ++i) ang.push_back(*rc::gen::inRange(0, 360));
      std::sort(ang.begin(), ang.end());
      std::vector<IP> p;
      for (int a : ang) {
        const double rad = static_cast<double>(*rc::gen::inRange<I>(5, span / 2 + 10));
        const double t = a * 3.141592653589793 / 180.0;
        p.push_back({cx + static_cast<I>(std::lround(rad * std::cos(t))),
                     cy + static_cast<I>(std::lround(rad * std::sin(t)))});
      }
      is.polys.push_back(p);
    }
    return is;
  });
}

// ---- exact integer "meets" (closed sets), independent of the library --------------------------
int orient(IP a, IP b, IP c) {
  const I v = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  return (v > 0) - (v < 0);
}
bool on_seg(IP p, IP a, IP b) {
  return orient(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}
bool seg_meet(IP a, IP b, IP c, IP d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return on_seg(c, a, b) || on_seg(d, a, b) || on_seg(a, c, d) || on_seg(b, c, d);
}
bool in_poly_closed(IP p, const std::vector<IP>& v) {
  bool in = false;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const IP a = v[i], b = v[(i + 1) % v.size()];
    if (on_seg(p, a, b)) return true;
    if ((a.y > p.y) != (b.y > p.y)) {
      // x-crossing > p.x  <=>  sign test without division
      const I num = (p.y - a.y) * (b.x - a.x), den = b.y - a.y;
      const I lhs = a.x * den + num, rhs = p.x * den;
      if (den > 0 ? lhs > rhs : lhs < rhs) in = !in;
    }
  }
  return in;
}
bool meets(const IScene& is, const std::vector<IP>& v, I x, I y) {
  const I x0 = is.ox + x * is.s, y0 = is.oy + y * is.s, x1 = x0 + is.s, y1 = y0 + is.s;
  const IP c[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  for (const IP& q : c)
    if (in_poly_closed(q, v)) return true;
  for (const IP& q : v)
    if (x0 <= q.x && q.x <= x1 && y0 <= q.y && q.y <= y1) return true;
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int j = 0; j < 4; ++j)
      if (seg_meet(v[i], v[(i + 1) % v.size()], c[j], c[(j + 1) % 4])) return true;
  return false;
}

// ---- a binary64 variant of the rule (what a float implementation would compute) ----------------
struct DP {
  double x, y;
};
double pseg2(DP p, DP a, DP b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  double t = ((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy);
  t = std::clamp(t, 0.0, 1.0);
  const double qx = a.x + t * dx - p.x, qy = a.y + t * dy - p.y;
  return qx * qx + qy * qy;
}
double fcross(DP a, DP b, DP c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }
/// Proper crossing of segments ab and cd in binary64 (touching cases are caught by the distances).
bool fcrosses(DP a, DP b, DP c, DP d) {
  const double o1 = fcross(a, b, c), o2 = fcross(a, b, d), o3 = fcross(c, d, a), o4 = fcross(c, d, b);
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}
bool float_blocked(const Scene& s, const std::vector<std::vector<DP>>& polys, double r, I x, I y) {
  const double ox = std::stod(to_string(s.origin.x)), oy = std::stod(to_string(s.origin.y));
  const double cs = std::stod(to_string(s.cell_size));
  const double x0 = ox + static_cast<double>(x) * cs, y0 = oy + static_cast<double>(y) * cs;
  const double x1 = ox + static_cast<double>(x + 1) * cs, y1 = oy + static_cast<double>(y + 1) * cs;
  const DP c[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  for (const auto& v : polys) {
    double best = INFINITY;
    for (const DP& q : c) {  // ray casting
      bool in = false;
      for (std::size_t i = 0; i < v.size(); ++i) {
        const DP a = v[i], b = v[(i + 1) % v.size()];
        if ((a.y > q.y) != (b.y > q.y) && a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y) > q.x) in = !in;
      }
      if (in) best = 0;
    }
    for (const DP& q : v)
      if (x0 <= q.x && q.x <= x1 && y0 <= q.y && q.y <= y1) best = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const DP a = v[i], b = v[(i + 1) % v.size()];
      for (int j = 0; j < 4; ++j) {
        const DP p = c[j], q = c[(j + 1) % 4];
        if (fcrosses(a, b, p, q)) best = 0;  // an edge through the square, no vertex inside
        best = std::min({best, pseg2(a, p, q), pseg2(b, p, q), pseg2(p, a, b), pseg2(q, a, b)});
      }
    }
    if (best <= r * r) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("prop_inflation_equals_brute_force", "[inflation][prop]") {
  rc::prop("inflate_polygons == cell_blocked for every cell", [] {
    const IScene is = *gen_scene();
    const Scene s = to_scene(is);
    RC_PRE(valid(s));
    const grid::Grid g = inflate_polygons(s);
    for (I y = -1; y <= is.h; ++y)
      for (I x = -1; x <= is.w; ++x)
        if (g.in_bounds({x, y})) RC_ASSERT(g.blocked({x, y}) == cell_blocked(s, {x, y}));
  });
}

TEST_CASE("prop_inflation_r0_blocks_exactly_the_cells_met", "[inflation][prop]") {
  rc::prop("r = 0: blocked iff the closed square meets a closed polygon (integer check)", [] {
    IScene is = *gen_scene();
    is.r = 0;
    const Scene s = to_scene(is);
    RC_PRE(valid(s));
    const grid::Grid g = inflate_polygons(s);
    for (I y = 0; y < is.h; ++y)
      for (I x = 0; x < is.w; ++x) {
        bool m = false;
        for (const auto& p : is.polys) m = m || meets(is, p, x, y);
        RC_ASSERT(g.blocked({x, y}) == m);
      }
  });
}

TEST_CASE("prop_inflation_monotone_in_r", "[inflation][prop]") {
  rc::prop("r1 <= r2 => blocked(r1) subset of blocked(r2)", [] {
    const IScene is = *gen_scene();
    const I r2 = is.r + *rc::gen::inRange<I>(0, 120);
    const Scene a = to_scene(is), b = to_scene(is, r2);
    RC_PRE(valid(a));
    const grid::Grid ga = inflate_polygons(a), gb = inflate_polygons(b);
    for (I y = 0; y < is.h; ++y)
      for (I x = 0; x < is.w; ++x)
        if (ga.blocked({x, y})) RC_ASSERT(gb.blocked({x, y}));
  });
}

TEST_CASE("prop_inflation_translation_by_whole_cells", "[inflation][prop]") {
  rc::prop("moving the polygons by (k s, l s) moves the blocked cells by (k, l)", [] {
    const IScene is = *gen_scene();
    const I k = *rc::gen::inRange<I>(-3, 4), l = *rc::gen::inRange<I>(-3, 4);
    IScene moved = is;
    for (auto& p : moved.polys)
      for (IP& v : p) {
        v.x += k * is.s;
        v.y += l * is.s;
      }
    const Scene a = to_scene(is), b = to_scene(moved);
    RC_PRE(valid(a));
    const grid::Grid ga = inflate_polygons(a), gb = inflate_polygons(b);
    for (I y = 0; y < is.h; ++y)
      for (I x = 0; x < is.w; ++x)
        if (gb.in_bounds({x + k, y + l})) RC_ASSERT(ga.blocked({x, y}) == gb.blocked({x + k, y + l}));
  });
}

TEST_CASE("prop_inflation_float_differs_only_near_r", "[inflation][prop]") {
  static int disagreements = 0;
  static int ties = 0;
  // Random scenes hit a tie (a cell at exact distance r) only now and then; in half of the cases a
  // triangle is added whose nearest point lies exactly r to the right of the middle of the last
  // column's bottom cell, so the tie branch is reached on purpose (require_reach below).
  pathref::testing::Reach tie_cases;
  rc::prop("a binary64 variant disagrees only on cells whose exact distance is within 1e-9 of r", [&tie_cases] {
    IScene is = *gen_scene();
    if (*rc::gen::arbitrary<bool>()) {
      const IP v{is.ox + is.w * is.s + is.r, is.oy + is.s / 2};
      is.polys.push_back({v, IP{v.x + 10, v.y - 5}, IP{v.x + 10, v.y + 5}});
    }
    const Scene s = to_scene(is);
    RC_PRE(valid(s));
    std::vector<std::vector<DP>> dp;
    for (const auto& p : s.polygons) {
      std::vector<DP> q;
      for (const Point& v : p.vertices) q.push_back({std::stod(to_string(v.x)), std::stod(to_string(v.y))});
      dp.push_back(q);
    }
    const double r = std::stod(to_string(s.radius));
    const grid::Grid g = inflate_polygons(s);
    // r +- 1e-9 as exact decimals (r is in hundredths: r*10^7 +- 1 in units of 1e-9)
    Scene lo = s, hi = s;
    lo.radius = *parse_decimal(std::to_string(is.r * 10000000 - 1) + "e-9");
    hi.radius = *parse_decimal(std::to_string(is.r * 10000000 + 1) + "e-9");
    bool case_tie = false;
    for (I y = 0; y < is.h; ++y)
      for (I x = 0; x < is.w; ++x) {
        bool tie = false;
        for (std::size_t k = 0; k < s.polygons.size(); ++k) tie = tie || compare_cell_distance(s, k, {x, y}) == 0;
        if (tie) ++ties;
        case_tie = case_tie || tie;
        if (float_blocked(s, dp, r, x, y) == g.blocked({x, y})) continue;
        ++disagreements;
        // exact distance in [r - 1e-9, r + 1e-9] for the deciding polygon(s)
        bool near = false;
        for (std::size_t k = 0; k < s.polygons.size(); ++k) {
          const bool above_lo = is.r == 0 || compare_cell_distance(lo, k, {x, y}) >= 0;
          const bool below_hi = compare_cell_distance(hi, k, {x, y}) <= 0;
          near = near || (above_lo && below_hi);
        }
        RC_ASSERT(near);
      }
    tie_cases.hit(case_tie);
  });
  // binary64 mistakes stay rare (printed, not asserted); the case below pins one deterministically.
  INFO("ties " << ties << ", binary64 disagreements " << disagreements);
  pathref::testing::require_reach(tie_cases, 0.2, "scenes with a cell at distance exactly r");
}

TEST_CASE("inflation: a constructed tie exists and binary64 decides it wrongly", "[inflation]") {
  // Cell (0,0) = [0, 0.1]^2; the square [0.4, 0.5] x [0, 0.1] lies exactly r = 0.3 to its right.
  // Exact: distance 0.3 = r, a tie, so the cell is blocked (spec/inflation.md: closed disc).
  // binary64: 0.4 - 0.1 = 0.30000000000000004 and its square exceeds fl(0.3 * 0.3), so free.
  IScene is;
  is.s = 10;
  is.w = 1;
  is.h = 1;
  is.r = 30;
  is.polys = {{{40, 0}, {50, 0}, {50, 10}, {40, 10}}};
  const Scene s = to_scene(is);
  REQUIRE(valid(s));
  std::vector<std::vector<DP>> dp{{{0.4, 0.0}, {0.5, 0.0}, {0.5, 0.1}, {0.4, 0.1}}};
  CHECK(compare_cell_distance(s, 0, {0, 0}) == 0);
  CHECK(inflate_polygons(s).blocked({0, 0}));
  CHECK_FALSE(float_blocked(s, dp, 0.3, 0, 0));
  // one hundredth less and the exact rule frees the cell too: the tie is decided by <=, not by luck
  const Scene smaller = to_scene(is, 29);
  CHECK(compare_cell_distance(smaller, 0, {0, 0}) > 0);
  CHECK_FALSE(inflate_polygons(smaller).blocked({0, 0}));
}

TEST_CASE("prop_inflation_grid_equals_polygon_rule", "[inflation][prop]") {
  rc::prop("inflate_grid == inflate_polygons with each blocked cell as a square polygon", [] {
    const I w = *rc::gen::inRange<I>(1, 8), h = *rc::gen::inRange<I>(1, 8);
    const I s = *rc::gen::element<I>(100, 30, 25, 7);
    const I r = *rc::gen::inRange<I>(0, 3 * s);
    grid::Grid m(w, h);
    IScene is;
    is.w = w;
    is.h = h;
    is.s = s;
    is.r = r;
    for (I y = 0; y < h; ++y)
      for (I x = 0; x < w; ++x)
        if (*rc::gen::inRange(0, 10) == 0) {
          m.set_blocked({x, y}, true);
          is.polys.push_back({{x * s, y * s}, {(x + 1) * s, y * s}, {(x + 1) * s, (y + 1) * s}, {x * s, (y + 1) * s}});
        }
    RC_ASSERT(inflate_grid(m, hundredths(s), hundredths(r)) == inflate_polygons(to_scene(is)));
  });
}
