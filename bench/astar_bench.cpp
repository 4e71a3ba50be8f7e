// A* (octile, chebyshev) and Dijkstra on 256x256 random maps, corner to corner, policy strict.
// spec: search.astar, search.dijkstra. Figures: docs/performance.md ("A* and Dijkstra").
//
// Maps: cell i (increasing index) is blocked iff rng::bernoulli(u_i, p), u_i the (i+1)-th double
// of rng::Stream(seed) -- the random_grid rule of tests/support -- then (0,0) and (255,255) are
// freed. The seed is the first one >= 1 whose corners are connected under `strict` (checked
// once, untimed); the counters report it with the run's expansions and length, so every figure
// can be reproduced exactly (`pathref` gives the same search for the same map).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <map>
#include <utility>

#include "pathref/grid/grid.hpp"
#include "pathref/planners/search.hpp"
#include "pathref/rng/draws.hpp"
#include "pathref/rng/mt19937.hpp"

namespace {

using pathref::grid::Cell;
using pathref::grid::CornerPolicy;
using pathref::grid::Grid;
using pathref::heuristics::Heuristic;

constexpr std::int64_t side = 256;
const Cell start{0, 0};
const Cell goal{side - 1, side - 1};

Grid random_map(std::uint32_t seed, double blocked_fraction) {
  Grid g(side, side);
  pathref::rng::Stream stream(seed);
  for (std::int64_t i = 0; i < g.cell_count(); ++i)
    if (pathref::rng::bernoulli(stream.next_double(), blocked_fraction))
      g.set_blocked(g.cell(i), true);
  g.set_blocked(start, false);
  g.set_blocked(goal, false);
  return g;
}

struct BenchMap {
  Grid grid{1, 1};
  std::uint32_t seed = 0;
  bool connected = false;
};

/// The map for a blocked fraction in percent, built once per process.
const BenchMap& bench_map(std::int64_t percent) {
  static std::map<std::int64_t, BenchMap> cache;
  auto it = cache.find(percent);
  if (it != cache.end()) return it->second;
  const double p = static_cast<double>(percent) / 100.0;
  BenchMap m;
  for (std::uint32_t seed = 1; seed <= 1000; ++seed) {
    Grid g = random_map(seed, p);
    if (pathref::search::dijkstra(g, start, goal, CornerPolicy::strict).found) {
      m = BenchMap{std::move(g), seed, true};
      break;
    }
  }
  if (!m.connected) m = BenchMap{random_map(1, p), 1, false};  // reported through "found" = 0
  return cache.emplace(percent, std::move(m)).first->second;
}

/// One plan per iteration; with `reuse`, through one search::Workspace kept across iterations
/// (spec/search.md "Reusing the search state"), else with the per-call allocation.
void run(benchmark::State& state, Heuristic h, bool reuse = false) {
  const BenchMap& m = bench_map(state.range(0));
  pathref::search::Outcome last;
  pathref::search::Workspace ws;
  for (auto _ : state) {
    last = reuse ? pathref::search::astar(ws, m.grid, start, goal, CornerPolicy::strict, h)
                 : pathref::search::astar(m.grid, start, goal, CornerPolicy::strict, h);
    benchmark::DoNotOptimize(last.length);
  }
  state.counters["seed"] = static_cast<double>(m.seed);
  state.counters["found"] = last.found ? 1.0 : 0.0;
  state.counters["expansions"] = static_cast<double>(last.expansions);
  state.counters["length"] = last.length;
  state.counters["exp_per_s"] = benchmark::Counter(static_cast<double>(last.expansions),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

void BM_AStarOctileStrict(benchmark::State& state) { run(state, Heuristic::octile); }
void BM_AStarChebyshevStrict(benchmark::State& state) { run(state, Heuristic::chebyshev); }
void BM_DijkstraStrict(benchmark::State& state) { run(state, Heuristic::zero); }
void BM_AStarOctileStrictReused(benchmark::State& state) { run(state, Heuristic::octile, true); }
void BM_DijkstraStrictReused(benchmark::State& state) { run(state, Heuristic::zero, true); }

}  // namespace

BENCHMARK(BM_AStarOctileStrict)->ArgName("blocked_pct")->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_AStarChebyshevStrict)->ArgName("blocked_pct")->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DijkstraStrict)->ArgName("blocked_pct")->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_AStarOctileStrictReused)->ArgName("blocked_pct")->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DijkstraStrictReused)->ArgName("blocked_pct")->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
