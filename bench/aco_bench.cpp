// One whole run of the ant-colony planners aco and iaco-shi with Table 1 defaults (50 ants,
// 100 iterations) and of iaco-han with Han's parameters (50 ants, 50 cycles), on the built-in
// 20x20 map grid20 (start and goal of the map file, policy strict, seed 1).
// spec: shi2022.plan.aco, shi2022.plan.iaco, han.plan.iaco. Figures: docs/performance.md
// ("Ant-colony planners"). The counters report the run's best length and draws, so every
// figure can be reproduced with `pathref plan --builtin grid20 --algo NAME --seed 1`.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>

#include "pathref/io/builtin_maps.hpp"
#include "pathref/planners/planner.hpp"

namespace {

void run_planner(benchmark::State& state, const char* algo) {
  const pathref::io::MapFile m =
      pathref::io::load_builtin_map(*pathref::io::find_builtin_map("grid20"));
  pathref::planners::Request req;
  req.grid = &m.grid;
  req.start = m.start.value();
  req.goal = m.goal.value();
  req.seed = 1;
  const pathref::planners::Planner* p = pathref::planners::find_planner(algo);
  double length = 0.0;
  double draws = 0.0;
  for (auto _ : state) {
    const pathref::planners::Result r = p->run(req);
    benchmark::DoNotOptimize(r.length);
    length = r.length;
    draws = r.extra.at("draws").get<double>();
  }
  state.counters["length"] = length;
  state.counters["draws"] = draws;
}

void BM_aco_grid20(benchmark::State& state) { run_planner(state, "aco"); }
void BM_iaco_shi_grid20(benchmark::State& state) { run_planner(state, "iaco-shi"); }
void BM_iaco_han_grid20(benchmark::State& state) { run_planner(state, "iaco-han"); }

}  // namespace

BENCHMARK(BM_aco_grid20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_iaco_shi_grid20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_iaco_han_grid20)->Unit(benchmark::kMillisecond);
