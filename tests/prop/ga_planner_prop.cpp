// spec: shi2022.op.init, shi2022.op.crossover, shi2022.op.mutation, shi2022.op.deletion,
// shi2022.op.elite, shi2022.plan.ga, shi2022.plan.iga, shi2022.plan.hybrid, shi2022.plan.iha
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "pathref/equations/ga_operators.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/planners/genetic.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/planners/search.hpp"
#include "pathref/rng/draws.hpp"
#include "pathref/rng/mt19937.hpp"
#include "support/generators.hpp"
#include "support/reach.hpp"

using namespace pathref;
using grid::Cell;
using grid::CornerPolicy;
using grid::Grid;
using Path = std::vector<Cell>;

namespace {

/// A small map with start at the lower left and goal at the upper right, both freed; bounded
/// by construction (no rejection).
struct Scenario {
  Grid g{1, 1};
  Cell start;
  Cell goal;
  CornerPolicy policy = CornerPolicy::strict;
};

Scenario gen_scenario(double max_blocked) {
  Scenario sc;
  const int w = *rc::gen::inRange(2, 9);
  const int h = *rc::gen::inRange(2, 9);
  sc.g = testing::random_grid(*rc::gen::arbitrary<std::uint32_t>(), w, h, max_blocked);
  sc.start = Cell{0, 0};
  sc.goal = Cell{w - 1, h - 1};
  sc.g.set_blocked(sc.start, false);
  sc.g.set_blocked(sc.goal, false);
  sc.policy = *rc::gen::element(CornerPolicy::strict, CornerPolicy::one, CornerPolicy::always);
  return sc;
}

bool valid(const Scenario& sc, const Path& p) {
  return metrics::validate_path(sc.g, p, sc.start, sc.goal, sc.policy).valid;
}

/// Up to `count` random initial paths of the scenario (empty when the initialisation gives up).
std::vector<Path> some_paths(const Scenario& sc, std::uint32_t seed, std::int64_t count) {
  genetic::Config c = genetic::shi_ga();
  c.init_attempts = 2000;
  rng::Stream s(seed);
  genetic::InitOutcome o = genetic::initial_paths(sc.g, sc.start, sc.goal, sc.policy, c, s, count);
  return o.ok ? o.paths : std::vector<Path>{};
}

planners::Result plan(const char* algo, const Scenario& sc, std::uint32_t seed) {
  planners::Request req;
  req.grid = &sc.g;
  req.start = sc.start;
  req.goal = sc.goal;
  req.policy = sc.policy;
  req.seed = seed;
  req.params = {{"population", 8}, {"generations", 4}, {"init_attempts", 2000}};
  if (std::string(algo) == "hybrid-ga-aco" || std::string(algo) == "iha") {
    req.params["aco_ants"] = 4;
    req.params["aco_iterations"] = 3;
  }
  return planners::find_planner(algo)->run(req);
}

}  // namespace

TEST_CASE("prop: shi2022.op.init feasible chains are valid paths through their genes") {
  rc::prop("repair", [] {
    const Scenario sc = gen_scenario(0.3);
    const int m = *rc::gen::inRange(0, 4);
    Path genes{sc.start};
    for (int i = 0; i < m; ++i)
      genes.push_back(Cell{*rc::gen::inRange<std::int64_t>(0, sc.g.width()),
                           *rc::gen::inRange<std::int64_t>(0, sc.g.height())});
    genes.push_back(sc.goal);
    const ga::ChainRepair r = ga::connect_chain(sc.g, genes, sc.policy);
    RC_ASSERT(r.feasible == (r.reason == "ok"));
    if (r.feasible) {
      RC_ASSERT(valid(sc, r.path));
      // The genes reappear in order (repeats dropped).
      std::size_t at = 0;
      for (const Cell gcell : genes) {
        while (at < r.path.size() && !(r.path[at] == gcell)) ++at;
        RC_ASSERT(at < r.path.size());
      }
    }
  });
}

TEST_CASE("prop: shi2022.op.deletion never lengthens a path and keeps it valid") {
  rc::prop("deletion", [] {
    const Scenario sc0 = gen_scenario(0.35);
    const Path walk = *testing::gen_walk(sc0.g, sc0.policy, 30);
    RC_PRE(walk.size() >= 1);
    Scenario sc = sc0;
    sc.start = walk.front();
    sc.goal = walk.back();
    const Path d = ga::delete_redundant(sc.g, walk, sc.policy);
    RC_ASSERT(valid(sc, walk));
    RC_ASSERT(valid(sc, d));
    RC_ASSERT(metrics::path_length(d) <= metrics::path_length(walk));
    RC_ASSERT((d.size() < walk.size()) == (metrics::path_length(d) < metrics::path_length(walk)));
    RC_ASSERT(ga::delete_redundant(sc.g, d, sc.policy) == d);
  });
}

TEST_CASE("prop: shi2022.op.loops leaves a simple valid path, never longer") {
  rc::prop("loops", [] {
    const Scenario sc0 = gen_scenario(0.35);
    const Path walk = *testing::gen_walk(sc0.g, sc0.policy, 40);
    RC_PRE(walk.size() >= 1);
    Scenario sc = sc0;
    sc.start = walk.front();
    sc.goal = walk.back();
    const Path d = ga::remove_loops(walk);
    RC_ASSERT(valid(sc, d));
    RC_ASSERT(metrics::path_length(d) <= metrics::path_length(walk));
    for (std::size_t i = 0; i < d.size(); ++i)
      for (std::size_t j = i + 1; j < d.size(); ++j) RC_ASSERT(!(d[i] == d[j]));
    RC_ASSERT(ga::remove_loops(d) == d);
  });
}

TEST_CASE("prop: shi2022.op.elite never loses the best") {
  rc::prop("elite", [] {
    const auto raw = *rc::gen::nonEmpty(rc::gen::container<std::vector<int>>(rc::gen::inRange(-50, 50)));
    std::vector<double> f;
    for (const int v : raw) f.push_back(static_cast<double>(v) / 4.0);
    const auto count = static_cast<std::size_t>(*rc::gen::inRange<std::size_t>(1, f.size() + 1));
    const std::vector<std::size_t> keep = ga::elite_indices(f, count);
    RC_ASSERT(keep.size() == count);
    const auto best = static_cast<std::size_t>(std::max_element(f.begin(), f.end(), [](double a, double b) { return a < b; }) - f.begin());
    RC_ASSERT(keep.front() == best);
    const double lowest_kept = f[keep.back()];
    for (std::size_t i = 0; i < f.size(); ++i)
      if (f[i] > lowest_kept) RC_ASSERT(std::find(keep.begin(), keep.end(), i) != keep.end());
    for (std::size_t i = 1; i < keep.size(); ++i) RC_ASSERT(f[keep[i - 1]] >= f[keep[i]]);
  });
}

TEST_CASE("prop: shi2022.op.crossover and shi2022.op.mutation children are valid paths") {
  // Vacuity (issue 17): about a third of the generated maps give no two initial paths; the
  // property must still reach its assertions in at least 40 % of the cases (measured: about 2/3).
  pathref::testing::Reach reach;
  rc::prop("children", [&reach] {
    const Scenario sc = gen_scenario(0.25);
    const std::vector<Path> ps = some_paths(sc, *rc::gen::arbitrary<std::uint32_t>(), 2);
    RC_TAG(ps.size() >= 2 ? "two paths" : "initialisation gave up");
    if (!reach.hit(ps.size() >= 2)) return;  // the initialisation gave up on this map
    for (const ga::CrossPoint pt : ga::crossover_points(ps[0], ps[1])) {
      const ga::Children c = ga::crossover_at(ps[0], ps[1], pt);
      RC_ASSERT(valid(sc, c.first));
      RC_ASSERT(valid(sc, c.second));
      RC_ASSERT(c.first.size() + c.second.size() == ps[0].size() + ps[1].size());
    }
    for (std::size_t k = 1; k + 1 < ps[0].size(); ++k)
      for (const Cell c : ga::mutation_candidates(sc.g, ps[0], k, sc.policy)) {
        Path m = ps[0];
        m[k] = c;
        RC_ASSERT(valid(sc, m));
      }
  });
  pathref::testing::require_reach(reach, 0.4, "crossover/mutation children");
}

TEST_CASE("prop: GA planners return valid paths, replay by seed, never beat Dijkstra") {
  rc::prop("planners", [] {
    const Scenario sc = gen_scenario(0.25);
    const auto seed = *rc::gen::arbitrary<std::uint32_t>();
    const char* algo = *rc::gen::element("ga", "iga-shi", "iga-shi-nomax", "hybrid-ga-aco", "iha");
    const planners::Result r = plan(algo, sc, seed);
    RC_TAG(r.found ? "found" : "not found");
    const search::Outcome opt = search::dijkstra(sc.g, sc.start, sc.goal, sc.policy);
    if (r.found) {
      RC_ASSERT(valid(sc, r.path));
      RC_ASSERT(r.length == metrics::path_length(r.path));
      RC_ASSERT(opt.found);
      RC_ASSERT(r.length >= opt.length * (1.0 - 1e-12));
    } else {
      RC_ASSERT(r.path.empty());
    }
    const planners::Result again = plan(algo, sc, seed);
    RC_ASSERT(again.found == r.found);
    RC_ASSERT(again.path == r.path);
    RC_ASSERT(again.best_per_iteration == r.best_per_iteration);
    RC_ASSERT(again.extra == r.extra);
  });
}

namespace {

/// spec shi2022.plan.ga step 2 written out literally, as the oracle of initial_paths: every chain
/// drawn gene by gene and repaired whole by ga::connect_chain (no pair verdicts).
genetic::InitOutcome literal_init(const Grid& g, Cell start, Cell goal, CornerPolicy policy,
                                  const genetic::Config& c, rng::Stream& stream,
                                  std::int64_t count) {
  genetic::InitOutcome out;
  std::vector<std::vector<std::int64_t>> rows;  // F_y of each row between, in row order
  const std::int64_t step = goal.y > start.y ? 1 : -1;
  for (std::int64_t y = start.y + step; goal.y != start.y && y != goal.y; y += step) {
    rows.emplace_back();
    for (std::int64_t x = 0; x < g.width(); ++x)
      if (g.free(Cell{x, y})) rows.back().push_back(x);
    if (rows.back().empty()) {
      out.failure = "row_blocked";
      return out;
    }
  }
  for (std::int64_t a = 0; a < count; ++a) {
    bool done = false;
    for (std::int64_t t = 0; t < c.init_attempts && !done; ++t) {
      Path genes{start};
      for (std::size_t r = 0; r < rows.size(); ++r) {
        const std::int64_t y = start.y + step * static_cast<std::int64_t>(r + 1);
        genes.push_back(Cell{rows[r][rng::uniform_index(stream.next_double(), rows[r].size())], y});
      }
      genes.push_back(goal);
      ++out.chains;
      const ga::ChainRepair rep =
          ga::connect_chain(g, genes, policy, c.mid_rounding, c.init_reject, c.illegal_step);
      if (rep.feasible) {
        out.paths.push_back(rep.path);
        done = true;
      }
    }
    if (!done) {
      out.failure = "init_attempts_exhausted";
      return out;
    }
  }
  out.ok = true;
  return out;
}

/// initial_paths and literal_init from the same seed: same outcome, paths, chains and draws.
void check_init_equals_literal(const Grid& g, Cell start, Cell goal, CornerPolicy policy,
                               const genetic::Config& c, std::uint32_t seed, std::int64_t count) {
  rng::Stream s1(seed);
  rng::Stream s2(seed);
  const genetic::InitOutcome got = genetic::initial_paths(g, start, goal, policy, c, s1, count);
  const genetic::InitOutcome want = literal_init(g, start, goal, policy, c, s2, count);
  RC_ASSERT(got.ok == want.ok);
  RC_ASSERT(got.failure == want.failure);
  RC_ASSERT(got.chains == want.chains);
  RC_ASSERT(got.paths == want.paths);
  RC_ASSERT(s1.doubles_drawn() == s2.doubles_drawn());
  RC_ASSERT(s1.next_double() == s2.next_double());
  RC_TAG(got.ok ? "ok" : got.failure);
}

}  // namespace

TEST_CASE("prop: shi2022.op.init corner repair accepts every chain rejection accepts, unchanged") {
  // illegal_step = repair differs from reject only where reject gives up ("illegal_step"): a
  // chain that reject repairs meets no disallowed continuous pair, so repair makes the same path.
  // A chain that only repair accepts is a valid path through its genes.
  rc::prop("repair extends reject", [] {
    const Scenario sc = gen_scenario(0.35);
    const int m = *rc::gen::inRange(0, 4);
    Path genes{sc.start};
    for (int i = 0; i < m; ++i)
      genes.push_back(Cell{*rc::gen::inRange<std::int64_t>(0, sc.g.width()),
                           *rc::gen::inRange<std::int64_t>(0, sc.g.height())});
    genes.push_back(sc.goal);
    const auto rej = *rc::gen::element(ga::InitReject::blocked, ga::InitReject::shift);
    const ga::ChainRepair lit =
        ga::connect_chain(sc.g, genes, sc.policy, ga::MidRounding::floor, rej, ga::IllegalStep::reject);
    const ga::ChainRepair rep =
        ga::connect_chain(sc.g, genes, sc.policy, ga::MidRounding::floor, rej, ga::IllegalStep::repair);
    if (lit.feasible) {
      RC_ASSERT(rep.feasible);
      RC_ASSERT(rep.path == lit.path);
    } else if (lit.reason != "illegal_step") {
      RC_ASSERT(rep.reason == lit.reason);  // a blocked gene or insert is found before any corner
    }
    if (rep.feasible) RC_ASSERT(valid(sc, rep.path));
    RC_TAG(lit.feasible ? "both" : (rep.feasible ? "repair only" : "neither"));
  });
}

TEST_CASE("prop: shi2022.plan.ga initialisation by pair verdicts equals repairing whole chains") {
  rc::prop("initial_paths == the literal step 2", [] {
    const int w = *rc::gen::inRange(1, 10);
    const int h = *rc::gen::inRange(1, 10);
    RC_PRE(w * h >= 2);
    Grid g = testing::random_grid(*rc::gen::arbitrary<std::uint32_t>(), w, h,
                                  *rc::gen::element(0.0, 0.1, 0.25, 0.4));
    // start and goal: two different cells (the goal's index skips the start's).
    const std::int64_t n = g.cell_count();
    const auto si = *rc::gen::inRange<std::int64_t>(0, n);
    auto gi = *rc::gen::inRange<std::int64_t>(0, n - 1);
    if (gi >= si) ++gi;
    const Cell start = g.cell(si);
    const Cell goal = g.cell(gi);
    g.set_blocked(start, false);
    g.set_blocked(goal, false);
    genetic::Config c = genetic::shi_ga();
    c.init_reject = *rc::gen::element(ga::InitReject::blocked, ga::InitReject::near_obstacle,
                                      ga::InitReject::shift);
    c.mid_rounding = *rc::gen::element(ga::MidRounding::floor, ga::MidRounding::ceil,
                                       ga::MidRounding::half_even);
    c.init_attempts = *rc::gen::inRange<std::int64_t>(1, 300);
    c.illegal_step = *rc::gen::element(ga::IllegalStep::repair, ga::IllegalStep::reject);
    const CornerPolicy policy = *testing::gen_policy();
    const auto count = *rc::gen::inRange<std::int64_t>(1, 5);
    check_init_equals_literal(g, start, goal, policy, c, *rc::gen::arbitrary<std::uint32_t>(), count);
    RC_TAG(c.init_reject == ga::InitReject::shift ? "shift" : "no shift");
  });
}

TEST_CASE("shi2022.plan.ga: initialisation without the pair table (wide map) equals the literal step 2") {
  // Corner to corner on 300 x h there are h - 2 rows between, so 300 + (h - 3) * 300 * 300 + 300
  // gene pairs: 300 x 16 (1 170 600) is above init_verdict_max_entries, so initial_paths repairs
  // every chain whole; 300 x 12 (810 600) keeps the table.
  for (const int h : {16, 12}) {
    const std::int64_t pairs = std::int64_t{600} + (h - 3) * std::int64_t{300 * 300};
    REQUIRE((pairs > genetic::init_verdict_max_entries) == (h == 16));
    for (const ga::InitReject rej : {ga::InitReject::blocked, ga::InitReject::shift}) {
      Grid g = testing::random_grid(11, 300, h, 0.003);
      g.set_blocked(Cell{0, 0}, false);
      g.set_blocked(Cell{299, h - 1}, false);
      genetic::Config c = genetic::shi_ga();
      c.init_reject = rej;
      c.illegal_step = ga::IllegalStep::reject;  // keeps rejected chains in play on this open map
      c.init_attempts = 500;
      rng::Stream s1(3);
      rng::Stream s2(3);
      const genetic::InitOutcome got =
          genetic::initial_paths(g, Cell{0, 0}, Cell{299, h - 1}, CornerPolicy::strict, c, s1, 3);
      const genetic::InitOutcome want =
          literal_init(g, Cell{0, 0}, Cell{299, h - 1}, CornerPolicy::strict, c, s2, 3);
      CHECK(got.ok == want.ok);
      CHECK(got.failure == want.failure);
      CHECK(got.chains == want.chains);
      CHECK(got.paths == want.paths);
      CHECK(s1.doubles_drawn() == s2.doubles_drawn());
      CHECK(want.ok);          // three accepted chains ...
      CHECK(want.chains > 3);  // ... and rejected ones: the comparison covers both
    }
  }
}

TEST_CASE("prop: shi2022.op.crossover points are those of the written-out scan, short or long") {
  // crossover_points is defined on any cell sequences. Cells drawn from a 5 x 5 square repeat
  // often; with up to 400 nodes, (n_a - 2)(n_b - 2) runs from 0 to ~160 000, on both sides of
  // ga::crossover_scan_limit (scan vs table of first positions).
  const auto gen_sequence = [] {
    const auto n = *rc::gen::element<std::size_t>(0, 3, 40, 150, 400);
    Path p(n);
    for (Cell& c : p)
      c = Cell{*rc::gen::inRange<std::int64_t>(0, 5), *rc::gen::inRange<std::int64_t>(0, 5)};
    return p;
  };
  rc::prop("crossover_points == the definition", [&] {
    const Path a = gen_sequence();
    const Path b = gen_sequence();
    std::vector<ga::CrossPoint> want;
    for (std::size_t k = 1; k + 1 < a.size(); ++k)
      for (std::size_t j = 1; j + 1 < b.size(); ++j)
        if (a[k] == b[j]) {
          want.push_back(ga::CrossPoint{k, j});
          break;
        }
    const bool long_parents = a.size() >= 3 && b.size() >= 3 &&
                              (a.size() - 2) * (b.size() - 2) > ga::crossover_scan_limit;
    RC_TAG(long_parents ? "table" : "scan");
    RC_ASSERT(ga::crossover_points(a, b) == want);
  });
}
