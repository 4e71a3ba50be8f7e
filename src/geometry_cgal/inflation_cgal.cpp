// The only translation unit of pathref that includes CGAL: exact obstacle inflation
// (spec/inflation.md). Everything here works in CELL UNITS: a world point (x, y) becomes
// u = ((x - ox) / s, (y - oy) / s) as an exact rational, so cell (i, j) is the integer square
// [i, i+1] x [j, j+1] and the radius becomes r / s. The map is a similarity (scale 1/s > 0), so
// dist_world <= r  <=>  dist_cell_units <= r / s, and every comparison stays exact.
// Kernel: CGAL::Epeck (lazy exact rationals with filtered predicates); squared distances are
// compared with (r/s)^2 as exact rationals, never rounded.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/geometry/inflation.hpp"
#include "exact_decimal.hpp"

namespace pathref::geometry {

namespace {

using K = CGAL::Epeck;
using FT = K::FT;
using ET = FT::ET;
using P2 = K::Point_2;
using S2 = K::Segment_2;

using exact_detail::exact;

FT ft_int(std::int64_t v) { return FT(static_cast<double>(v)); }  // |v| <= 2^41 < 2^53: exact

/// floor of an exact rational, clamped to [lo, hi] (indices beyond the clamp never matter).
/// to_interval encloses the value; when |v| < 2^50 its width is < 1 ulp < 2^-2, so floor(lo) and
/// floor(hi) differ by at most one and the exact comparison picks the right one.
std::int64_t clamped_floor(const ET& v, std::int64_t lo, std::int64_t hi) {
  const auto iv = CGAL::to_interval(v);
  if (iv.second < static_cast<double>(lo)) return lo;
  if (iv.first >= static_cast<double>(hi) + 1.0) return hi;
  auto k = static_cast<std::int64_t>(std::floor(iv.second));
  while (ET(static_cast<long>(k)) > v) --k;  // at most a couple of steps
  return std::clamp(k, lo, hi);
}

/// A scene in cell units.
struct Prepared {
  ET r_cells;   ///< r / s
  FT r2;        ///< (r / s)^2
  std::vector<std::vector<P2>> polys;
  std::vector<std::vector<ET>> xs, ys;  ///< exact vertex coordinates (cell units)
};

Prepared prepare(const Scene& sc) {
  const ET s = exact(sc.cell_size);
  require(s > ET(0), "cell_size must be > 0");
  const ET rad = exact(sc.radius), mar = exact(sc.margin);
  require(rad >= ET(0) && mar >= ET(0), "radius and margin must be >= 0");
  Prepared p;
  p.r_cells = ET((rad + mar) / s);
  p.r2 = FT(ET(p.r_cells * p.r_cells));
  const ET ox = exact(sc.origin.x), oy = exact(sc.origin.y);
  for (const Polygon& poly : sc.polygons) {
    std::vector<P2> pts;
    std::vector<ET> xs, ys;
    for (const Point& v : poly.vertices) {
      xs.push_back(ET((exact(v.x) - ox) / s));
      ys.push_back(ET((exact(v.y) - oy) / s));
      pts.emplace_back(FT(xs.back()), FT(ys.back()));
    }
    p.polys.push_back(std::move(pts));
    p.xs.push_back(std::move(xs));
    p.ys.push_back(std::move(ys));
  }
  return p;
}

std::string poly_ptr(std::size_t k) { return "/polygons/" + std::to_string(k); }

void validate_prepared(const Prepared& p) {
  for (std::size_t k = 0; k < p.polys.size(); ++k) {
    const auto& v = p.polys[k];
    const std::size_t n = v.size();
    if (n < 3)
      throw DomainError(poly_ptr(k) + ": degenerate polygon: expected at least 3 vertices, got " + std::to_string(n));
    for (std::size_t i = 0; i < n; ++i)
      if (v[i] == v[(i + 1) % n])
        throw DomainError(poly_ptr(k) + ": degenerate polygon: vertices " + std::to_string(i) + " and " +
                          std::to_string((i + 1) % n) + " are equal (zero-length edge; do not repeat the first vertex)");
    bool all_collinear = true;
    for (std::size_t i = 2; i < n && all_collinear; ++i)
      all_collinear = CGAL::collinear(v[0], v[1], v[i]);
    if (all_collinear) throw DomainError(poly_ptr(k) + ": degenerate polygon: all vertices are collinear (zero area)");
    // Consecutive edges may only share their common vertex: a collinear reversal ("spike")
    // makes them overlap.
    for (std::size_t i = 0; i < n; ++i) {
      const P2& a = v[i];
      const P2& b = v[(i + 1) % n];
      const P2& c = v[(i + 2) % n];
      if (CGAL::collinear(a, b, c) && !CGAL::collinear_are_ordered_along_line(a, b, c))
        throw DomainError(poly_ptr(k) + ": self-intersecting polygon: edges at vertex " +
                          std::to_string((i + 1) % n) + " overlap (the boundary turns back on itself)");
    }
    if (!CGAL::is_simple_2(v.begin(), v.end(), K()))
      throw DomainError(poly_ptr(k) + ": self-intersecting polygon: two non-consecutive edges meet");
  }
}

/// The four sides of the closed unit square of cell (i, j), in cell units.
struct Square {
  FT x0, x1, y0, y1;
  S2 side[4];
  Square(std::int64_t i, std::int64_t j)
      : x0(ft_int(i)), x1(ft_int(i + 1)), y0(ft_int(j)), y1(ft_int(j + 1)) {
    const P2 a(x0, y0), b(x1, y0), c(x1, y1), d(x0, y1);
    side[0] = S2(a, b);
    side[1] = S2(b, c);
    side[2] = S2(c, d);
    side[3] = S2(d, a);
  }
  [[nodiscard]] bool contains(const P2& q) const {
    return x0 <= q.x() && q.x() <= x1 && y0 <= q.y() && q.y() <= y1;
  }
  [[nodiscard]] P2 corner() const { return P2(x0, y0); }
};

/// dist(edge, closed square)^2 <= r2, exactly.
bool edge_within(const S2& e, const Square& sq, const FT& r2) {
  if (sq.contains(e.source()) || sq.contains(e.target())) return true;
  const auto cmp = K().compare_squared_distance_2_object();
  for (const S2& f : sq.side)
    if (cmp(e, f, r2) != CGAL::LARGER) return true;
  return false;
}

/// sign(dist(square, polygon)^2 - r2) by the definition (brute force, exact).
int compare_prepared(const Prepared& p, std::size_t k, grid::Cell c) {
  const auto& v = p.polys[k];
  const Square sq(c.x, c.y);
  const auto zero = [&] { return CGAL::compare(FT(0), p.r2) == CGAL::SMALLER ? -1 : 0; };
  // distance 0: a corner of the square in the closed polygon, or a vertex of the polygon in the square
  const P2 corners[4] = {sq.side[0].source(), sq.side[1].source(), sq.side[2].source(), sq.side[3].source()};
  for (const P2& q : corners)
    if (CGAL::bounded_side_2(v.begin(), v.end(), q, K()) != CGAL::ON_UNBOUNDED_SIDE) return zero();
  for (const P2& q : v)
    if (sq.contains(q)) return zero();
  // otherwise the closest points lie on the two boundaries: min over edge pairs
  bool have = false;
  FT best;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const S2 e(v[i], v[(i + 1) % v.size()]);
    for (const S2& f : sq.side) {
      FT d = CGAL::squared_distance(e, f);
      if (!have || d < best) best = d;
      have = true;
    }
  }
  switch (CGAL::compare(best, p.r2)) {
    case CGAL::SMALLER: return -1;
    case CGAL::EQUAL: return 0;
    default: return 1;
  }
}

struct Range {
  std::int64_t lo, hi;  ///< inclusive; empty when lo > hi
};

/// Cells [i, i+1] meeting the interval [a - r, b + r]: floor(a - r) - 1 .. floor(b + r), clamped.
/// (i + 1 >= a - r  <=>  i >= ceil(a - r) - 1 >= floor(a - r) - 1: a superset, decided exactly later.)
Range cell_range(const ET& a, const ET& b, const ET& r, std::int64_t n) {
  const std::int64_t lo = clamped_floor(ET(a - r), -2, n + 1) - 1;
  const std::int64_t hi = clamped_floor(ET(b + r), -2, n + 1);
  return {std::max<std::int64_t>(lo, 0), std::min<std::int64_t>(hi, n - 1)};
}

}  // namespace

void validate_polygons(const Scene& scene) { validate_prepared(prepare(scene)); }

int compare_cell_distance(const Scene& scene, std::size_t polygon, grid::Cell cell) {
  require(polygon < scene.polygons.size(), "polygon index out of range");
  constexpr std::int64_t big = std::int64_t{1} << 40;
  require(cell.x > -big && cell.x < big && cell.y > -big && cell.y < big, "cell coordinates beyond 2^40");
  const Prepared p = prepare(scene);
  validate_prepared(p);
  return compare_prepared(p, polygon, cell);
}

bool cell_blocked(const Scene& scene, grid::Cell cell) {
  constexpr std::int64_t big = std::int64_t{1} << 40;
  require(cell.x > -big && cell.x < big && cell.y > -big && cell.y < big, "cell coordinates beyond 2^40");
  const Prepared p = prepare(scene);
  validate_prepared(p);
  for (std::size_t k = 0; k < p.polys.size(); ++k)
    if (compare_prepared(p, k, cell) <= 0) return true;
  return false;
}

grid::Grid inflate_polygons(const Scene& scene) {
  const Prepared p = prepare(scene);
  validate_prepared(p);
  grid::Grid g(scene.width, scene.height);
  const std::int64_t W = scene.width, H = scene.height;
  for (std::size_t k = 0; k < p.polys.size(); ++k) {
    const auto& v = p.polys[k];
    const auto& xs = p.xs[k];
    const auto& ys = p.ys[k];
    const std::size_t n = v.size();
    // 1. boundary pass: cells within r of an edge (per edge, over its bounding box expanded by r)
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t i2 = (i + 1) % n;
      const S2 e(v[i], v[i2]);
      const Range rx = cell_range(CGAL::min(xs[i], xs[i2]), CGAL::max(xs[i], xs[i2]), p.r_cells, W);
      const Range ry = cell_range(CGAL::min(ys[i], ys[i2]), CGAL::max(ys[i], ys[i2]), p.r_cells, H);
      for (std::int64_t y = ry.lo; y <= ry.hi; ++y)
        for (std::int64_t x = rx.lo; x <= rx.hi; ++x) {
          const grid::Cell c{x, y};
          if (g.blocked(c)) continue;
          if (edge_within(e, Square(x, y), p.r2)) g.set_blocked(c, true);
        }
    }
    // 2. interior pass: a cell farther than r from the boundary meets the polygon iff it lies
    //    inside it, decided by any one of its points (its lower-left corner).
    const ET zero(0);
    const auto [xmin, xmax] = std::minmax_element(xs.begin(), xs.end());
    const auto [ymin, ymax] = std::minmax_element(ys.begin(), ys.end());
    const Range rx = cell_range(*xmin, *xmax, zero, W);
    const Range ry = cell_range(*ymin, *ymax, zero, H);
    for (std::int64_t y = ry.lo; y <= ry.hi; ++y)
      for (std::int64_t x = rx.lo; x <= rx.hi; ++x) {
        const grid::Cell c{x, y};
        if (g.blocked(c)) continue;
        if (CGAL::bounded_side_2(v.begin(), v.end(), P2(ft_int(x), ft_int(y)), K()) != CGAL::ON_UNBOUNDED_SIDE)
          g.set_blocked(c, true);
      }
  }
  return g;
}

grid::Grid inflate_grid(const grid::Grid& map, const Decimal& cell_size, const Decimal& r) {
  const ET s = exact(cell_size), rr = exact(r);
  require(s > ET(0), "cell_size must be > 0");
  require(rr >= ET(0), "r must be >= 0");
  const ET q = ET((rr / s) * (rr / s));  // gaps (gx, gy) in cells allowed iff gx^2 + gy^2 <= q
  const std::int64_t W = map.width(), H = map.height();
  const std::int64_t span = std::max(W, H);
  // hmax[gy] = largest gx in [0, span] with gx^2 + gy^2 <= q, or -1 when none.
  std::vector<std::int64_t> hmax;
  for (std::int64_t gy = 0; gy <= span; ++gy) {
    const ET gy2(static_cast<long>(gy * gy));
    if (gy2 > q) break;
    const auto est = static_cast<std::int64_t>(std::floor(std::sqrt(std::max(0.0, CGAL::to_double(ET(q - gy2))))));
    std::int64_t gx = std::min(est + 1, span);
    while (gx >= 0 && ET(static_cast<long>(gx * gx)) + gy2 > q) --gx;
    hmax.push_back(gx);
  }
  // prefix counts of blocked cells per row
  std::vector<std::int32_t> pre(static_cast<std::size_t>((W + 1) * H), 0);
  auto at = [&](std::int64_t x, std::int64_t y) -> std::int32_t& {
    return pre[static_cast<std::size_t>(y * (W + 1) + x)];
  };
  for (std::int64_t y = 0; y < H; ++y)
    for (std::int64_t x = 0; x < W; ++x) at(x + 1, y) = at(x, y) + (map.blocked({x, y}) ? 1 : 0);
  grid::Grid out(W, H);
  const auto reach = static_cast<std::int64_t>(hmax.size());  // |dy| <= reach allowed (gy = |dy|-1 < size)
  for (std::int64_t y = 0; y < H; ++y)
    for (std::int64_t dy = -reach; dy <= reach; ++dy) {
      const std::int64_t by = y + dy;
      if (by < 0 || by >= H) continue;
      const std::int64_t gy = std::max<std::int64_t>(0, (dy < 0 ? -dy : dy) - 1);
      const std::int64_t h = hmax[static_cast<std::size_t>(gy)] + 1;  // |dx| <= h
      for (std::int64_t x = 0; x < W; ++x) {
        if (out.blocked({x, y})) continue;
        const std::int64_t a = std::max<std::int64_t>(0, x - h), b = std::min<std::int64_t>(W - 1, x + h);
        if (at(b + 1, by) - at(a, by) > 0) out.set_blocked({x, y}, true);
      }
    }
  return out;
}

InflatedScene inflate_scene(const Scene& scene) {
  grid::Grid g = inflate_polygons(scene);
  const auto check = [&](const std::optional<grid::Cell>& c, const char* ptr) {
    if (!c) throw DomainError(std::string(ptr) + ": missing (a scene to plan on needs start and goal)");
    if (!g.in_bounds(*c))
      throw DomainError(std::string(ptr) + ": cell (" + std::to_string(c->x) + ", " + std::to_string(c->y) +
                        ") is outside the " + std::to_string(g.width()) + "x" + std::to_string(g.height()) + " map");
    if (g.blocked(*c))
      throw DomainError(std::string(ptr) + ": cell (" + std::to_string(c->x) + ", " + std::to_string(c->y) +
                        ") is blocked by an inflated obstacle");
    return *c;
  };
  const grid::Cell s = check(scene.start, "/start");
  const grid::Cell t = check(scene.goal, "/goal");
  if (s == t) throw DomainError("/goal: equals the start cell (" + std::to_string(s.x) + ", " + std::to_string(s.y) + ")");
  return {std::move(g), s, t};
}

}  // namespace pathref::geometry
