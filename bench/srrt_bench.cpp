// Continuous planners (spec/cin2021-srrt.md): the exact segment check, Algorithm 1's samples per
// second and time to the first solution on a cluttered 100 x 100 scene with 100 polygons.
// Results: docs/performance.md, "S-RRT in the continuous plane".
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "pathref/continuous/rrt.hpp"
#include "pathref/geometry/decimal.hpp"
#include "pathref/geometry/obstacles.hpp"
#include "pathref/geometry/scene.hpp"
#include "pathref/rng/mt19937.hpp"

namespace {

using namespace pathref;
using continuous::Vec2;

geometry::Decimal hundredths(long v) { return *geometry::parse_decimal(std::to_string(v) + "e-2"); }

/// 100 x 100 world (cell size 1), r = 0.2 + 0.1; 100 convex polygons (5-gons on a circle of radius
/// 1.5..4, centres uniform in [5, 95]^2, coordinates rounded to hundredths, overlaps allowed);
/// start (1, 1) and goal (99, 99) are kept free by leaving the corner boxes empty.
geometry::Scene cluttered(std::uint32_t seed) {
  rng::Stream rs(seed);
  geometry::Scene s;
  s.origin = {hundredths(0), hundredths(0)};
  s.width = s.height = 100;
  s.cell_size = hundredths(100);
  s.radius = hundredths(20);
  s.margin = hundredths(10);
  while (s.polygons.size() < 100) {
    const double cx = 5.0 + 90.0 * rs.next_double(), cy = 5.0 + 90.0 * rs.next_double();
    const double rad = 1.5 + 2.5 * rs.next_double(), phase = rs.next_double();
    geometry::Polygon p;
    for (int i = 0; i < 5; ++i) {
      const double a = 6.283185307179586 * (phase + i / 5.0);
      p.vertices.push_back({hundredths(std::lround((cx + rad * std::cos(a)) * 100)),
                            hundredths(std::lround((cy + rad * std::sin(a)) * 100))});
    }
    s.polygons.push_back(std::move(p));
  }
  return s;
}

const geometry::ObstacleMap& world() {
  static const geometry::ObstacleMap m = geometry::ObstacleMap::from_scene(cluttered(7));
  return m;
}

/// One exact segment check of length delta = 1.7 at a random place and heading (the RRT edge).
void BM_segment_check(benchmark::State& state) {
  const auto& m = world();
  rng::Stream rs(1);
  std::vector<std::pair<Vec2, Vec2>> segs;
  for (int i = 0; i < 4096; ++i) {
    const Vec2 a{100.0 * rs.next_double(), 100.0 * rs.next_double()};
    const double t = 6.283185307179586 * rs.next_double();
    segs.push_back({a, Vec2{a.x + 1.7 * std::cos(t), a.y + 1.7 * std::sin(t)}});
  }
  std::size_t i = 0, free = 0;
  for (auto _ : state) {
    const auto& [a, b] = segs[i++ & 4095u];
    free += m.segment_free(a, b) ? std::size_t{1} : std::size_t{0};
  }
  benchmark::DoNotOptimize(free);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}
BENCHMARK(BM_segment_check);

/// A long segment (the shortcut's checks): corner to corner.
void BM_segment_check_long(benchmark::State& state) {
  const auto& m = world();
  bool f = false;
  for (auto _ : state) f ^= m.segment_free({1.0, 1.0}, {99.0, 99.0});
  benchmark::DoNotOptimize(f);
}
BENCHMARK(BM_segment_check_long);

/// Algorithm 1 (defaults: delta 1.7, P_g 0.6, bias lt, near sample) from (1, 1) to (99, 99) until
/// the first solution; seeds vary per iteration. Reports samples/s and the mean samples.
void BM_rrt_first_solution(benchmark::State& state) {
  const auto& m = world();
  continuous::RrtParams p;
  p.variant = static_cast<continuous::RrtVariant>(state.range(0));
  p.max_iterations = 200000;
  std::uint32_t seed = 1;
  std::int64_t samples = 0, found = 0, nodes = 0;
  for (auto _ : state) {
    rng::Stream rs(seed++);
    const auto r = continuous::rrt(m, {1.0, 1.0}, {99.0, 99.0}, p, rs);
    samples += r.iterations;
    nodes += static_cast<std::int64_t>(r.nodes.size());
    found += r.found ? 1 : 0;
  }
  state.SetItemsProcessed(samples);
  state.counters["samples/run"] = benchmark::Counter(static_cast<double>(samples) / static_cast<double>(state.iterations()));
  state.counters["nodes/run"] = benchmark::Counter(static_cast<double>(nodes) / static_cast<double>(state.iterations()));
  state.counters["found"] = benchmark::Counter(static_cast<double>(found) / static_cast<double>(state.iterations()));
}
BENCHMARK(BM_rrt_first_solution)->Arg(0)->Arg(1)->Arg(2)->ArgName("variant(paper,plain,ompl)")->Unit(benchmark::kMillisecond);

}  // namespace
