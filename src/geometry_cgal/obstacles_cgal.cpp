// Exact collision checks of points and segments against inflated obstacle polygons for the
// continuous planners (spec/cin2021-srrt.md r[cin2021.srrt.collision]). The only translation unit
// of pathref_geometry that includes CGAL for them (inflation has its own).
// Kernel: CGAL::Epeck. Query points are doubles (exact in Epeck), polygon vertices and r are exact
// rationals from their decimal text; every decision is an exact sign of dist^2 - r^2. Double
// boxes around the edges (enlarged by an upper bound of r and rounded outwards) only select
// candidate edges: an edge whose box misses the segment's box is farther than r from it.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "exact_decimal.hpp"
#include "pathref/core/error.hpp"
#include "pathref/geometry/inflation.hpp"
#include "pathref/geometry/obstacles.hpp"

namespace pathref::geometry {

namespace {
using K = CGAL::Epeck;
using FT = K::FT;
using ET = FT::ET;
using P2 = K::Point_2;
using S2 = K::Segment_2;
using exact_detail::exact;

struct Box {
  double x0, y0, x1, y1;
  [[nodiscard]] bool meets(const Box& o) const noexcept {
    return !(o.x1 < x0 || x1 < o.x0 || o.y1 < y0 || y1 < o.y0);
  }
};

double down(double v) { return std::nextafter(v, -std::numeric_limits<double>::infinity()); }
double up(double v) { return std::nextafter(v, std::numeric_limits<double>::infinity()); }

/// A box that encloses the exact segment, enlarged by at least r in every direction.
Box enclosing(const P2& a, const P2& b, double r_up) {
  const auto ax = CGAL::to_interval(a.x()), ay = CGAL::to_interval(a.y());
  const auto bx = CGAL::to_interval(b.x()), by = CGAL::to_interval(b.y());
  return Box{down(std::min(ax.first, bx.first) - r_up), down(std::min(ay.first, by.first) - r_up),
             up(std::max(ax.second, bx.second) + r_up), up(std::max(ay.second, by.second) + r_up)};
}

/// The double nearest to an exact rational: to_interval encloses v within one ulp, the exact
/// comparison picks the nearer end. A value exactly halfway between two doubles (54 significant
/// bits) goes to the lower one, where IEEE round-to-nearest-even might pick the upper.
double nearest_double(const ET& v) {
  const auto iv = CGAL::to_interval(v);
  if (iv.first == iv.second) return iv.first;
  const ET lo(iv.first), hi(iv.second);
  return ET(v - lo) <= ET(hi - v) ? iv.first : iv.second;
}

void check_finite(Vec2 p) {
  if (!(std::isfinite(p.x) && std::isfinite(p.y))) throw DomainError("collision: point coordinates must be finite");
}
}  // namespace

struct ObstacleMap::Impl {
  FT r2;
  double r_approx = 0.0;
  double r_up = 0.0;  ///< >= r
  Vec2 lo, hi;
  std::vector<std::vector<P2>> polys;
  std::vector<std::vector<Vec2>> approx;
  std::vector<Box> poly_box;  ///< encloses the polygon (not enlarged)
  struct Edge {
    std::uint32_t poly;
    S2 seg;
    Box box;  ///< enlarged by r
  };
  std::vector<Edge> edges;
  // Bucket grid over the world rectangle: edges by enlarged box, polygons by box.
  std::int64_t nx = 1, ny = 1;
  double bx0 = 0, by0 = 0, bw = 1, bh = 1;
  std::vector<std::vector<std::uint32_t>> edge_buckets, poly_buckets;

  /// Bucket index along one axis, clamped to [0, n - 1] (boxes may reach outside the world).
  [[nodiscard]] static std::int64_t bucket(double v, double v0, double w, std::int64_t n) {
    const double f = std::floor((v - v0) / w);
    if (!(f >= 0.0)) return 0;
    if (f >= static_cast<double>(n - 1)) return n - 1;
    return static_cast<std::int64_t>(f);
  }
  [[nodiscard]] std::int64_t col(double x) const { return bucket(x, bx0, bw, nx); }
  [[nodiscard]] std::int64_t row(double y) const { return bucket(y, by0, bh, ny); }

  void build(ET r, ET x0, ET y0, ET x1, ET y1) {
    r2 = FT(ET(r * r));
    r_approx = nearest_double(r);
    r_up = up(CGAL::to_interval(r).second);
    lo = Vec2{nearest_double(x0), nearest_double(y0)};
    hi = Vec2{nearest_double(x1), nearest_double(y1)};
    for (std::size_t k = 0; k < polys.size(); ++k) {
      const auto& v = polys[k];
      std::vector<Vec2> ap;
      Box pb{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
             -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
      for (std::size_t i = 0; i < v.size(); ++i) {
        ap.push_back(Vec2{CGAL::to_double(v[i].x()), CGAL::to_double(v[i].y())});
        const Box eb = enclosing(v[i], v[i], 0.0);
        pb = Box{std::min(pb.x0, eb.x0), std::min(pb.y0, eb.y0), std::max(pb.x1, eb.x1), std::max(pb.y1, eb.y1)};
        const P2& a = v[i];
        const P2& b = v[(i + 1) % v.size()];
        edges.push_back(Edge{static_cast<std::uint32_t>(k), S2(a, b), enclosing(a, b, r_up)});
      }
      approx.push_back(std::move(ap));
      poly_box.push_back(pb);
    }
    // Buckets: about 2 per edge along each side's square root, at most 256 x 256.
    const auto side = static_cast<std::int64_t>(std::ceil(std::sqrt(static_cast<double>(edges.size())) * 2.0));
    nx = ny = std::clamp<std::int64_t>(side, 1, 256);
    bx0 = lo.x;
    by0 = lo.y;
    bw = std::max((hi.x - lo.x) / static_cast<double>(nx), 1e-300);
    bh = std::max((hi.y - lo.y) / static_cast<double>(ny), 1e-300);
    edge_buckets.assign(static_cast<std::size_t>(nx * ny), {});
    poly_buckets.assign(static_cast<std::size_t>(nx * ny), {});
    const auto put = [&](std::vector<std::vector<std::uint32_t>>& buckets, const Box& b, std::uint32_t id) {
      for (std::int64_t j = row(b.y0); j <= row(b.y1); ++j)
        for (std::int64_t i = col(b.x0); i <= col(b.x1); ++i) buckets[static_cast<std::size_t>(j * nx + i)].push_back(id);
    };
    for (std::size_t e = 0; e < edges.size(); ++e) put(edge_buckets, edges[e].box, static_cast<std::uint32_t>(e));
    for (std::size_t k = 0; k < poly_box.size(); ++k) put(poly_buckets, poly_box[k], static_cast<std::uint32_t>(k));
  }

  [[nodiscard]] bool in_world(Vec2 p) const noexcept {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y;
  }

  /// dist(segment, polygon k)^2 <= r^2 (exact), or 0-distance inside test.
  [[nodiscard]] bool inside(std::size_t k, const P2& p) const {
    const auto& v = polys[k];
    return CGAL::bounded_side_2(v.begin(), v.end(), p, K()) != CGAL::ON_UNBOUNDED_SIDE;
  }
  [[nodiscard]] CGAL::Comparison_result cmp_edge(const Edge& e, const P2& a, const P2& b, bool point) const {
    if (point) return K().compare_squared_distance_2_object()(a, e.seg, r2);
    return K().compare_squared_distance_2_object()(S2(a, b), e.seg, r2);
  }
};

ObstacleMap ObstacleMap::from_scene(const Scene& scene) {
  validate_polygons(scene);
  auto impl = std::make_shared<Impl>();
  const ET s = exact(scene.cell_size);
  require(s > ET(0), "cell_size must be > 0");
  const ET rad = exact(scene.radius), mar = exact(scene.margin);
  require(rad >= ET(0) && mar >= ET(0), "radius and margin must be >= 0");
  const ET ox = exact(scene.origin.x), oy = exact(scene.origin.y);
  for (const Polygon& poly : scene.polygons) {
    std::vector<P2> pts;
    for (const Point& v : poly.vertices) pts.emplace_back(FT(exact(v.x)), FT(exact(v.y)));
    impl->polys.push_back(std::move(pts));
  }
  const ET x1 = ox + s * ET(static_cast<double>(scene.width));
  const ET y1 = oy + s * ET(static_cast<double>(scene.height));
  impl->build(ET(rad + mar), ox, oy, x1, y1);
  return ObstacleMap(std::move(impl));
}

ObstacleMap ObstacleMap::from_grid(const grid::Grid& map, const Decimal& radius) {
  require(!radius.negative, "radius must be >= 0");
  auto impl = std::make_shared<Impl>();
  for (std::int64_t y = 0; y < map.height(); ++y) {
    std::int64_t x = 0;
    while (x < map.width()) {
      if (!map.blocked(grid::Cell{x, y})) {
        ++x;
        continue;
      }
      const std::int64_t x0 = x;
      while (x < map.width() && map.blocked(grid::Cell{x, y})) ++x;
      const FT a(static_cast<double>(x0)), b(static_cast<double>(x)), c(static_cast<double>(y)),
          d(static_cast<double>(y + 1));
      impl->polys.push_back({P2(a, c), P2(b, c), P2(b, d), P2(a, d)});
    }
  }
  impl->build(exact(radius), ET(0), ET(0), ET(static_cast<double>(map.width())),
              ET(static_cast<double>(map.height())));
  return ObstacleMap(std::move(impl));
}

int ObstacleMap::compare_segment(std::size_t k, Vec2 a, Vec2 b) const {
  check_finite(a);
  check_finite(b);
  const Impl& m = *impl_;
  require(k < m.polys.size(), "compare_segment: polygon index out of range");
  const P2 pa(a.x, a.y), pb(b.x, b.y);
  if (m.inside(k, pa)) return m.r2 == FT(0) ? 0 : -1;  // distance 0 vs r
  const bool point = a == b;
  int best = 1;
  for (const auto& e : m.edges) {
    if (e.poly != k) continue;
    const auto c = m.cmp_edge(e, pa, pb, point);
    if (c == CGAL::SMALLER) return -1;
    if (c == CGAL::EQUAL) best = 0;
  }
  return best;
}

bool ObstacleMap::segment_free(Vec2 a, Vec2 b) const {
  check_finite(a);
  check_finite(b);
  const Impl& m = *impl_;
  if (!m.in_world(a) || !m.in_world(b)) return false;
  if (m.polys.empty()) return true;
  const Box sb{std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
  std::vector<std::uint32_t> cand;
  for (std::int64_t j = m.row(sb.y0); j <= m.row(sb.y1); ++j)
    for (std::int64_t i = m.col(sb.x0); i <= m.col(sb.x1); ++i)
      for (const std::uint32_t e : m.edge_buckets[static_cast<std::size_t>(j * m.nx + i)])
        if (m.edges[e].box.meets(sb)) cand.push_back(e);
  std::sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  const P2 pa(a.x, a.y), pb(b.x, b.y);
  const bool point = a == b;
  for (const std::uint32_t e : cand)
    if (m.cmp_edge(m.edges[e], pa, pb, point) != CGAL::LARGER) return false;
  // No edge within r: the segment is either outside every polygon or inside one (then a is).
  for (const std::uint32_t k : m.poly_buckets[static_cast<std::size_t>(m.row(a.y) * m.nx + m.col(a.x))]) {
    const Box& pbx = m.poly_box[k];
    if (a.x < pbx.x0 || a.x > pbx.x1 || a.y < pbx.y0 || a.y > pbx.y1) continue;
    if (m.inside(k, pa)) return false;
  }
  return true;
}

bool ObstacleMap::point_free(Vec2 p) const { return segment_free(p, p); }

double ObstacleMap::segment_distance(Vec2 a, Vec2 b) const {
  check_finite(a);
  check_finite(b);
  const Impl& m = *impl_;
  if (m.polys.empty()) return std::numeric_limits<double>::infinity();
  const P2 pa(a.x, a.y), pb(b.x, b.y);
  for (std::size_t k = 0; k < m.polys.size(); ++k)
    if (m.inside(k, pa)) return 0.0;
  const bool point = a == b;
  FT best = -1;
  for (const auto& e : m.edges) {
    const FT d2 = point ? CGAL::squared_distance(pa, e.seg) : CGAL::squared_distance(S2(pa, pb), e.seg);
    if (best < FT(0) || d2 < best) best = d2;
  }
  return std::sqrt(nearest_double(best.exact()));
}

double ObstacleMap::point_distance(Vec2 p) const { return segment_distance(p, p); }
Vec2 ObstacleMap::lower() const { return impl_->lo; }
Vec2 ObstacleMap::upper() const { return impl_->hi; }
std::size_t ObstacleMap::polygon_count() const { return impl_->polys.size(); }
const std::vector<std::vector<Vec2>>& ObstacleMap::polygons() const { return impl_->approx; }
double ObstacleMap::radius() const { return impl_->r_approx; }

}  // namespace pathref::geometry
