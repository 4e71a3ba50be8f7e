// One whole run of the GA planners (ga, iga-shi) and the hybrids (hybrid-ga-aco, iha) with
// Table 1 defaults (population 200, 50 generations; 50 ants x 100 iterations for the colonies)
// on 20x20 maps, corner to corner, policy strict, seed 1.
// spec: shi2022.plan.ga, shi2022.plan.iga, shi2022.plan.hybrid, shi2022.plan.iha.
// Figures: docs/performance.md ("GA planners and hybrids").
//
// Maps: cell i (increasing index) of a 20x20 grid is blocked iff rng::bernoulli(u_i, p), u_i the
// (i+1)-th double of rng::Stream(7) (the random_grid rule of tests/support), then (0,0) and
// (19,19) are freed. "sparse": p = 0.03 (the Sec. 4.2 initialisation finds feasible chains);
// "dense": p = 0.15 (it does not, with the default init_reject = blocked: the GA runs use
// init_reject = shift there, the hybrids their defaults). The counters report found, the length
// and the draws, so a run can be reproduced with `pathref plan`. The *_cut variants set
// loops = cut (spec shi2022.op.loops): with the weighted fitness and loops kept, paths grow
// without bound (BM_iha_sparse takes tens of seconds; spec/shi2022-ga.md, "Loops").
#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>

#include "pathref/grid/grid.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rng/draws.hpp"
#include "pathref/rng/mt19937.hpp"

namespace {

using pathref::grid::Cell;
using pathref::grid::Grid;

constexpr std::int64_t side = 20;

Grid make_map(double p) {
  Grid m(side, side);
  pathref::rng::Stream stream(7);
  for (std::int64_t i = 0; i < m.cell_count(); ++i)
    if (pathref::rng::bernoulli(stream.next_double(), p)) m.set_blocked(m.cell(i), true);
  m.set_blocked(Cell{0, 0}, false);
  m.set_blocked(Cell{side - 1, side - 1}, false);
  return m;
}

const Grid& bench_map(bool dense) {
  static const Grid sparse_map = make_map(0.03);
  static const Grid dense_map = make_map(0.15);
  return dense ? dense_map : sparse_map;
}

void run_planner(benchmark::State& state, const char* algo, bool dense,
                 const pathref::planners::Json& params) {
  const pathref::planners::Planner* p = pathref::planners::find_planner(algo);
  pathref::planners::Request req;
  req.grid = &bench_map(dense);
  req.start = Cell{0, 0};
  req.goal = Cell{side - 1, side - 1};
  req.seed = 1;
  req.params = params;
  pathref::planners::Result r;
  for (auto _ : state) {
    r = p->run(req);
    benchmark::DoNotOptimize(r.length);
  }
  state.counters["found"] = r.found ? 1.0 : 0.0;
  state.counters["length"] = r.length;
  state.counters["draws"] = r.extra.contains("draws") ? r.extra.at("draws").get<double>() : -1.0;
}

const pathref::planners::Json none = pathref::planners::Json::object();
const pathref::planners::Json shift = {{"init_reject", "shift"}};
const pathref::planners::Json cut = {{"loops", "cut"}};

void BM_ga_sparse(benchmark::State& s) { run_planner(s, "ga", false, none); }
void BM_iga_shi_sparse(benchmark::State& s) { run_planner(s, "iga-shi", false, none); }
void BM_ga_dense_shift(benchmark::State& s) { run_planner(s, "ga", true, shift); }
void BM_iga_shi_dense_shift(benchmark::State& s) { run_planner(s, "iga-shi", true, shift); }
void BM_hybrid_ga_aco_dense(benchmark::State& s) { run_planner(s, "hybrid-ga-aco", true, none); }
void BM_iha_dense(benchmark::State& s) { run_planner(s, "iha", true, none); }
void BM_iha_sparse(benchmark::State& s) { run_planner(s, "iha", false, none); }
void BM_iga_shi_sparse_cut(benchmark::State& s) { run_planner(s, "iga-shi", false, cut); }
void BM_iha_sparse_cut(benchmark::State& s) { run_planner(s, "iha", false, cut); }

}  // namespace

BENCHMARK(BM_ga_sparse)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_iga_shi_sparse)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ga_dense_shift)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_iga_shi_dense_shift)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_hybrid_ga_aco_dense)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_iha_dense)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_iha_sparse)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_iga_shi_sparse_cut)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_iha_sparse_cut)->Unit(benchmark::kMillisecond);
