// One DWA control step at the project defaults (window resolution 0.01 m/s x 1 deg/s, 3 s
// horizon of 30 steps) and one whole fused run on the rebuilt 21 x 21 scene of sensors2023
// (moving and temporary obstacles). spec: sensors2023.dwa.step, sensors2023.sim.run.
// Figures: docs/performance.md ("DWA").
//
// The control step is taken from the scene's start pose (4.5, 3.5) at cruise (v = 0.5 m/s,
// w = 0), the target the second key node, with the scene's moving disc at its t = 0 position:
// 11 x 21 = 231 candidate pairs, each predicted over 30 steps with a clearance of every pose.
#include <benchmark/benchmark.h>

#include <cmath>

#include "pathref/equations/dwa.hpp"
#include "pathref/reproduce/sensors2023.hpp"
#include "pathref/sim/fused.hpp"

namespace {

using namespace pathref;

const grid::Grid& scene() {
  static const grid::Grid g = grid::Grid::from_rows_top_first(reproduce::sensors2023_scene_rows());
  return g;
}

void BM_DwaControlStep(benchmark::State& state) {
  const dwa::DwaParams prm;
  const std::vector<dwa::Disc> discs{dwa::Disc{dwa::Point{11.5, 0.5}, 0.4, {}}};
  const dwa::Obstacles obs{&scene(), {}, discs};
  std::int64_t candidates = 0;
  for (auto _ : state) {
    const dwa::StepResult r =
        dwa::control_step(dwa::Pose{4.5, 3.5, 0.3}, 0.5, 0.0, dwa::Point{6.5, 5.5}, obs, prm);
    candidates = r.candidates;
    benchmark::DoNotOptimize(r);
  }
  state.counters["candidates"] = static_cast<double>(candidates);
  state.counters["steps_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_DwaControlStep)->Unit(benchmark::kMicrosecond);

void BM_FusedRunScene(benchmark::State& state) {
  dwa::FusedScenario s;
  s.grid = scene();
  s.start = grid::Cell{4, 3};
  s.goal = grid::Cell{17, 16};
  s.moving.push_back(dwa::Mover{0.4, {{0.0, {11.5, 0.5}}, {10.0, {9.5, 4.5}}}});
  s.temporary.push_back(dwa::Temporary{grid::Cell{14, 15}, 0.0, 40.0});
  std::int64_t steps = 0;
  for (auto _ : state) {
    const dwa::FusedResult r = dwa::simulate_fused(s);
    steps = r.steps;
    benchmark::DoNotOptimize(r);
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["steps_per_s"] =
      benchmark::Counter(static_cast<double>(steps) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FusedRunScene)->Unit(benchmark::kMillisecond);

}  // namespace
