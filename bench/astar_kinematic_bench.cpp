// The kinematic-constraint A* of Sensors 2023 (planner astar-kinematic) against pathref's own A*
// on the six MovingAI maps of ../shared/data/movingai (skipped where absent).
// spec: sensors2023.plan.astar-kinematic, search.astar. Figures: docs/performance.md
// ("Kinematic A* on the MovingAI maps").
//
// Queries: from each map's .scen file, the 20 scenarios at positions floor(i * n / 20),
// i = 0..19, of the file's n lines (spread over all buckets), corner policy strict (MovingAI's
// rule). One benchmark iteration runs all 20 queries; the time per query is the iteration time
// divided by 20. Counters: expansions, generated children and child nodes
// summed over the 20 queries, the number found.
//
// Variants: astar-octile (`astar`, the project's default A*), astar-euclidean (`astar
// heuristic=euclidean`, the paper's plain A* of Eq. 2-3), kinematic-search (the search of
// astar-kinematic only: 5 directions + weight linear + fallback), kinematic-full (plan_kinematic
// with the defaults: search, ordinary and secondary removal, B-spline sampled at 0.1, clearance).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "pathref/equations/heuristics.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/io/movingai.hpp"
#include "pathref/planners/astar_kinematic.hpp"
#include "pathref/planners/search.hpp"

namespace {

using pathref::grid::Cell;
using pathref::grid::CornerPolicy;
using pathref::grid::Grid;
namespace fs = std::filesystem;

const char* const kMaps[] = {"8room_000", "arena", "den312d", "lak303d", "maze512-1-0", "random512-10-0"};
constexpr std::size_t kQueries = 20;

struct Query {
  Cell start;
  Cell goal;
};

struct BenchMap {
  bool present = false;
  Grid grid{1, 1};
  std::vector<Query> queries;
};

const BenchMap& bench_map(std::size_t which) {
  static std::map<std::size_t, BenchMap> cache;
  auto it = cache.find(which);
  if (it != cache.end()) return it->second;
  BenchMap m;
  const fs::path dir = fs::path(PATHREF_SHARED_DIR) / "data" / "movingai";
  const fs::path map_path = dir / (std::string(kMaps[which]) + ".map");
  const fs::path scen_path = dir / (std::string(kMaps[which]) + ".map.scen");
  if (fs::exists(map_path) && fs::exists(scen_path)) {
    const auto map_text = pathref::io::read_text_file(map_path.string(), "map");
    const auto scen_text = pathref::io::read_text_file(scen_path.string(), "scenarios");
    m.grid = pathref::io::parse_movingai_map(map_text, map_path.string()).grid;
    const auto scen = pathref::io::parse_movingai_scen(scen_text, scen_path.string());
    const std::size_t n = scen.scenarios.size();
    const auto h = m.grid.height();
    for (std::size_t i = 0; i < kQueries; ++i) {
      const auto& s = scen.scenarios[i * n / kQueries];
      m.queries.push_back(Query{pathref::io::from_movingai(s.start_x.value, s.start_y.value, h),
                                pathref::io::from_movingai(s.goal_x.value, s.goal_y.value, h)});
    }
    m.present = true;
  }
  return cache.emplace(which, std::move(m)).first->second;
}

enum class Variant { astar_octile, astar_euclidean, kinematic_search, kinematic_full };

void run(benchmark::State& state, Variant v) {
  const auto which = static_cast<std::size_t>(state.range(0));
  const BenchMap& m = bench_map(which);
  if (!m.present) {
    state.SkipWithError((std::string("../shared/data/movingai/") + kMaps[which] +
                         ".map(.scen) absent: skipped")
                            .c_str());
    return;
  }
  pathref::sensors2023::KinematicOptions full;
  std::int64_t expansions = 0;
  std::int64_t generated = 0;
  std::int64_t children = 0;
  std::int64_t found = 0;
  for (auto _ : state) {
    expansions = generated = children = found = 0;
    for (const Query& q : m.queries) {
      pathref::search::Outcome o;
      switch (v) {
        case Variant::astar_octile:
          o = pathref::search::astar(m.grid, q.start, q.goal, CornerPolicy::strict,
                                     pathref::heuristics::Heuristic::octile);
          break;
        case Variant::astar_euclidean:
          o = pathref::search::astar(m.grid, q.start, q.goal, CornerPolicy::strict,
                                     pathref::heuristics::Heuristic::euclidean);
          break;
        case Variant::kinematic_search: {
          // the search alone: plan_kinematic's first step, through the same core and rule
          const double R = pathref::heuristics::euclidean(q.start, q.goal);
          pathref::search::ExpansionRule rule;
          rule.moves = [&](Cell c) { return pathref::sensors2023::child_moves(m.grid, c, q.goal, 1); };
          rule.h = [&](Cell n) { return pathref::heuristics::euclidean(n, q.goal); };
          rule.f = [&](double g, double h, Cell) {
            return pathref::sensors2023::f_weighted(g, h, h, R, pathref::sensors2023::WeightForm::linear);
          };
          o = pathref::search::best_first(m.grid, q.start, q.goal, CornerPolicy::strict, rule);
          if (!o.found) {  // the fallback of the planner
            rule.moves = nullptr;
            pathref::search::Outcome f = pathref::search::best_first(m.grid, q.start, q.goal, CornerPolicy::strict, rule);
            f.expansions += o.expansions;
            f.generated += o.generated;
            f.child_nodes += o.child_nodes;
            o = std::move(f);
          }
          break;
        }
        case Variant::kinematic_full:
          o = pathref::sensors2023::plan_kinematic(m.grid, q.start, q.goal, CornerPolicy::strict, full).search;
          break;
      }
      expansions += o.expansions;
      generated += o.generated;
      children += o.child_nodes;
      found += o.found ? 1 : 0;
      benchmark::DoNotOptimize(o.length);
    }
  }
  state.counters["expansions"] = static_cast<double>(expansions);
  state.counters["generated"] = static_cast<double>(generated);
  state.counters["child_nodes"] = static_cast<double>(children);
  state.counters["found"] = static_cast<double>(found);
  state.SetLabel(kMaps[which]);
}

void BM_AStarOctile(benchmark::State& s) { run(s, Variant::astar_octile); }
void BM_AStarEuclidean(benchmark::State& s) { run(s, Variant::astar_euclidean); }
void BM_KinematicSearch(benchmark::State& s) { run(s, Variant::kinematic_search); }
void BM_KinematicFull(benchmark::State& s) { run(s, Variant::kinematic_full); }

}  // namespace

BENCHMARK(BM_AStarOctile)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AStarEuclidean)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_KinematicSearch)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_KinematicFull)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);
