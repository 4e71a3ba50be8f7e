// Exact inflation (spec/inflation.md, inflation.cell-blocked): 1,000 random simple polygons of
// 3..12 vertices on a 1024 x 1024 grid. Results: docs/performance.md, "Exact inflation".
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/geometry/inflation.hpp"
#include "pathref/rng/mt19937.hpp"

namespace {

using namespace pathref::geometry;

Decimal hundredths(long v) { return *parse_decimal(std::to_string(v) + "e-2"); }

/// Cell size 0.1 (world 102.4 x 102.4), r = 0.25 + 0.1; polygon k: centre uniform in the world,
/// m = 3 + floor(10 u) vertices at sorted angles, radii 0.3..2.3 world units (3..23 cells),
/// coordinates rounded to hundredths; polygons that are not simple after rounding are redrawn.
Scene make_scene(std::uint32_t seed) {
  pathref::rng::Stream rng(seed);
  Scene s;
  s.origin = {hundredths(0), hundredths(0)};
  s.width = s.height = 1024;
  s.cell_size = hundredths(10);
  s.radius = hundredths(25);
  s.margin = hundredths(10);
  while (s.polygons.size() < 1000) {
    const double cx = rng.next_double() * 102.4, cy = rng.next_double() * 102.4;
    const int m = 3 + static_cast<int>(rng.next_double() * 10);
    std::vector<double> ang;
    for (int i = 0; i < m; ++i) ang.push_back(rng.next_double() * 6.283185307179586);
    std::sort(ang.begin(), ang.end());
    Polygon p;
    for (double a : ang) {
      const double rad = 0.3 + 2.0 * rng.next_double();
      p.vertices.push_back({hundredths(std::lround((cx + rad * std::cos(a)) * 100)),
                            hundredths(std::lround((cy + rad * std::sin(a)) * 100))});
    }
    Scene one = s;
    one.polygons = {p};
    try {
      validate_polygons(one);
    } catch (const pathref::DomainError&) {
      continue;
    }
    s.polygons.push_back(std::move(p));
  }
  return s;
}

void BM_InflatePolygons1000on1024(benchmark::State& state) {
  const Scene s = make_scene(1);
  std::int64_t blocked = 0;
  for (auto _ : state) {
    const pathref::grid::Grid g = inflate_polygons(s);
    blocked = g.blocked_count();
    benchmark::DoNotOptimize(blocked);
  }
  std::size_t vertices = 0;
  for (const auto& p : s.polygons) vertices += p.vertices.size();
  state.counters["polygons"] = static_cast<double>(s.polygons.size());
  state.counters["vertices"] = static_cast<double>(vertices);
  state.counters["blocked_cells"] = static_cast<double>(blocked);
}
BENCHMARK(BM_InflatePolygons1000on1024)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_InflateGrid1024(benchmark::State& state) {
  const Scene s = make_scene(1);
  const pathref::grid::Grid m = inflate_polygons(s);
  for (auto _ : state) {
    const pathref::grid::Grid g = inflate_grid(m, hundredths(10), hundredths(35));
    benchmark::DoNotOptimize(g.blocked_count());
  }
}
BENCHMARK(BM_InflateGrid1024)->Unit(benchmark::kMillisecond);

}  // namespace
