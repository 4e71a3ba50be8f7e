// One whole run of cin2021's HGA-ACO (hga-aco-cin) with its default parameters (the project's
// values of the 13 lost Sec. 5.6 parameters: GA 50 x 50 generations, colony 30 ants x 50
// iterations), and of its two phases alone: ga-cin with the same seed IS the GA phase (the same
// draws; test "cin2021.plan.hga-aco: the GA phase is the ga-cin run, then the colony"), so the
// ACO phase's share is hga-aco-cin minus ga-cin. aco-cin alone (uniform tau_C) is the paper's
// ACO baseline. spec: cin2021.plan.ga, cin2021.plan.aco, cin2021.plan.hga-aco.
// Figures: docs/performance.md ("cin2021 HGA-ACO").
//
// Maps: "20x20" is scenario s3 of reproduce.cin2021.maps (two concave traps, corner to corner);
// "64x64" blocks cell i iff rng::bernoulli(u_i, 0.15) with u_i the (i+1)-th double of
// rng::Stream(7), start (0,0) and goal (63,63) freed. Policy strict, seed 1. Counters: found,
// length, draws (replay with `pathref plan`).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>

#include "pathref/grid/grid.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/reproduce/cin2021.hpp"
#include "pathref/rng/draws.hpp"
#include "pathref/rng/mt19937.hpp"

namespace {

using pathref::grid::Cell;
using pathref::grid::Grid;

Grid random_map(std::int64_t side, double p) {
  Grid m(side, side);
  pathref::rng::Stream stream(7);
  for (std::int64_t i = 0; i < m.cell_count(); ++i)
    if (pathref::rng::bernoulli(stream.next_double(), p)) m.set_blocked(m.cell(i), true);
  m.set_blocked(Cell{0, 0}, false);
  m.set_blocked(Cell{side - 1, side - 1}, false);
  return m;
}

const Grid& bench_map(bool large) {
  static const Grid s3 = pathref::reproduce::cin2021_scenarios().at(2).grid;
  static const Grid big = random_map(64, 0.15);
  return large ? big : s3;
}

void run_planner(benchmark::State& state, const char* algo, bool large) {
  const pathref::planners::Planner* p = pathref::planners::find_planner(algo);
  const Grid& g = bench_map(large);
  pathref::planners::Request req;
  req.grid = &g;
  req.start = Cell{0, 0};
  req.goal = Cell{g.width() - 1, g.height() - 1};
  req.seed = 1;
  req.params = pathref::planners::Json::object();
  pathref::planners::Result r;
  for (auto _ : state) {
    r = p->run(req);
    benchmark::DoNotOptimize(r.length);
  }
  state.counters["found"] = r.found ? 1 : 0;
  state.counters["length"] = r.length;
  state.counters["draws"] = r.extra.value("draws", 0.0);
}

void BM_hga_aco_cin_20(benchmark::State& s) { run_planner(s, "hga-aco-cin", false); }
void BM_ga_cin_20(benchmark::State& s) { run_planner(s, "ga-cin", false); }
void BM_aco_cin_20(benchmark::State& s) { run_planner(s, "aco-cin", false); }
void BM_hga_aco_cin_64(benchmark::State& s) { run_planner(s, "hga-aco-cin", true); }
void BM_ga_cin_64(benchmark::State& s) { run_planner(s, "ga-cin", true); }
void BM_aco_cin_64(benchmark::State& s) { run_planner(s, "aco-cin", true); }

}  // namespace

BENCHMARK(BM_hga_aco_cin_20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ga_cin_20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_aco_cin_20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_hga_aco_cin_64)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ga_cin_64)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_aco_cin_64)->Unit(benchmark::kMillisecond);
