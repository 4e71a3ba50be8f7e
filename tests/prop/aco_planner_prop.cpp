// spec: shi2022.plan.aco, shi2022.plan.iaco, han.plan.iaco, han.plan.astar
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <set>
#include <string>
#include <vector>

#include "pathref/equations/aco.hpp"
#include "pathref/equations/aco_adaptive.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/planners/ant_colony.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/planners/search.hpp"
#include "support/generators.hpp"
#include "support/reach.hpp"

using namespace pathref;
using grid::Cell;
using grid::CornerPolicy;
using grid::Grid;

namespace {

const std::vector<std::string> colony_algos = {"aco", "iaco-shi", "iaco-shi-nomin", "iaco-han"};

/// A small map with a free start and goal (freed after drawing: no rejection), a policy, a
/// seed, one colony planner and reduced ants / iterations so that a property stays fast.
struct Scenario {
  Grid g{1, 1};
  Cell start;
  Cell goal;
  CornerPolicy policy = CornerPolicy::strict;
  std::uint32_t seed = 1;
  std::string algo;
  planners::Json params;
};

Scenario gen_scenario() {
  Scenario sc;
  sc.g = *testing::gen_grid(8, 8, 0.4);
  const auto n = sc.g.cell_count();
  sc.start = sc.g.cell(*rc::gen::inRange<std::int64_t>(0, n));
  sc.goal = sc.g.cell(*rc::gen::inRange<std::int64_t>(0, n));
  sc.g.set_blocked(sc.start, false);
  sc.g.set_blocked(sc.goal, false);
  sc.policy = *testing::gen_policy();
  sc.seed = *rc::gen::arbitrary<std::uint32_t>();
  sc.algo = *rc::gen::elementOf(colony_algos);
  sc.params = planners::Json{{"ants", *rc::gen::inRange<std::int64_t>(1, 6)},
                             {"iterations", *rc::gen::inRange<std::int64_t>(1, 6)},
                             {"dead_end", *rc::gen::element<std::string>("die", "backtrack")}};
  return sc;
}

/// Moves the goal off the start when the map has another cell (freeing it), so that properties
/// about iterations reach their assertions on small maps too (issue 17, vacuity).
void distinct_ends(Scenario& sc) {
  const auto n = sc.g.cell_count();
  if (!(sc.start == sc.goal) || n < 2) return;
  sc.goal = sc.g.cell((sc.g.index(sc.start) + 1) % n);
  sc.g.set_blocked(sc.goal, false);
}

planners::Result plan(const Scenario& sc, const std::string& algo, const planners::Json& params) {
  planners::Request req;
  req.grid = &sc.g;
  req.start = sc.start;
  req.goal = sc.goal;
  req.policy = sc.policy;
  req.seed = sc.seed;
  req.params = params;
  const planners::Planner* p = planners::find_planner(algo);
  RC_ASSERT(p != nullptr);
  return p->run(req);
}

/// Exact comparison of a + b*sqrt2 >= c + d*sqrt2 for integers (no rounding anywhere):
/// (a - c) >= (d - b) * sqrt2.
bool ge_exact(std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d) {
  const std::int64_t p = a - c;
  const std::int64_t q = d - b;
  if (q <= 0) return p >= 0 || p * p <= 2 * q * q;
  return p >= 0 && p * p >= 2 * q * q;
}

/// Reachability by breadth-first search written here from grid.corner-policy.
bool reachable(const Grid& g, Cell s, Cell t, CornerPolicy p) {
  std::vector<bool> seen(static_cast<std::size_t>(g.cell_count()), false);
  std::deque<Cell> q{s};
  seen[static_cast<std::size_t>(g.index(s))] = true;
  while (!q.empty()) {
    const Cell c = q.front();
    q.pop_front();
    if (c == t) return true;
    for (std::int64_t dy = -1; dy <= 1; ++dy)
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        const Cell m{c.x + dx, c.y + dy};
        if (!grid::step_allowed(g, c, m, p)) continue;
        const auto i = static_cast<std::size_t>(g.index(m));
        if (!seen[i]) {
          seen[i] = true;
          q.push_back(m);
        }
      }
  }
  return false;
}

}  // namespace

TEST_CASE("prop_aco_paths_valid_and_not_shorter_than_dijkstra", "[aco][prop]") {
  pathref::testing::Reach found;
  rc::prop("found paths are valid, simple, length == metrics.length, >= the Dijkstra optimum", [&found] {
    const Scenario sc = gen_scenario();
    const planners::Result r = plan(sc, sc.algo, sc.params);
    const bool reach = reachable(sc.g, sc.start, sc.goal, sc.policy);
    if (!reach) RC_ASSERT(!r.found);
    if (!found.hit(r.found)) {
      RC_ASSERT(r.path.empty());
      return;
    }
    RC_ASSERT(metrics::validate_path(sc.g, r.path, sc.start, sc.goal, sc.policy).valid);
    std::set<std::int64_t> cells;
    for (const Cell& c : r.path) cells.insert(sc.g.index(c));
    RC_ASSERT(cells.size() == r.path.size());
    RC_ASSERT(r.length == metrics::path_length(r.path));
    const search::Outcome d = search::dijkstra(sc.g, sc.start, sc.goal, sc.policy);
    RC_ASSERT(d.found);
    const auto a = search::step_counts(r.path);
    const auto o = search::step_counts(d.path);
    RC_ASSERT(ge_exact(a.orthogonal, a.diagonal, o.orthogonal, o.diagonal));
  });
  pathref::testing::require_reach(found, 0.7, "found paths checked against Dijkstra");
}

TEST_CASE("prop_aco_same_seed_same_run", "[aco][prop]") {
  rc::prop("two runs with the same seed and parameters are identical, draw counts included", [] {
    const Scenario sc = gen_scenario();
    const planners::Result a = plan(sc, sc.algo, sc.params);
    const planners::Result b = plan(sc, sc.algo, sc.params);
    RC_ASSERT(a.found == b.found);
    RC_ASSERT(a.path == b.path);
    RC_ASSERT(a.length == b.length);
    RC_ASSERT(a.params_used == b.params_used);
    RC_ASSERT(a.extra.dump() == b.extra.dump());
    RC_ASSERT(a.best_per_iteration == b.best_per_iteration);
    const auto& ma = a.mean_per_iteration;
    const auto& mb = b.mean_per_iteration;
    RC_ASSERT(ma.size() == mb.size());
    for (std::size_t i = 0; i < ma.size(); ++i)
      RC_ASSERT((std::isnan(ma[i]) && std::isnan(mb[i])) || ma[i] == mb[i]);
  });
}

TEST_CASE("prop_aco_best_curve_non_increasing", "[aco][prop]") {
  pathref::testing::Reach reach;
  rc::prop("best_per_iteration is non-increasing, ends at the returned length, N entries", [&reach] {
    Scenario sc = gen_scenario();
    distinct_ends(sc);
    const planners::Result r = plan(sc, sc.algo, sc.params);
    if (!reach.hit(!(sc.start == sc.goal))) return;
    const auto& b = r.best_per_iteration;
    RC_ASSERT(static_cast<std::int64_t>(b.size()) == sc.params.at("iterations").get<std::int64_t>());
    for (std::size_t i = 1; i < b.size(); ++i) RC_ASSERT(b[i] <= b[i - 1]);
    if (r.found) {
      RC_ASSERT(b.back() == r.length);
      // the iteration best never beats the best so far, and the mean is not below it
      const auto& it = r.extra.at("iteration_best");
      for (std::size_t i = 0; i < b.size(); ++i)
        if (!it[i].is_null()) {
          RC_ASSERT(it[i].get<double>() >= b[i]);
          // mean >= iteration best up to the rounding of the left-to-right sum and the division
          // (k <= 5 ants: relative error below (k + 1) 2^-53)
          RC_ASSERT(r.mean_per_iteration[i] >= it[i].get<double>() * (1.0 - 8.0 * 0x1p-53));
        }
    } else {
      for (const double v : b) RC_ASSERT(std::isinf(v));
    }
  });
  pathref::testing::require_reach(reach, 0.5, "best curve, start != goal");
}

TEST_CASE("prop_backtracking_ants_never_die_when_goal_reachable", "[aco][prop]") {
  pathref::testing::Reach counted;
  rc::prop("dead_end = backtrack: a tour is a depth-first search, so it reaches a reachable goal", [&counted] {
    Scenario sc = gen_scenario();
    distinct_ends(sc);
    sc.params["dead_end"] = "backtrack";
    const planners::Result r = plan(sc, sc.algo, sc.params);
    if (!counted.hit(!(sc.start == sc.goal))) return;
    const bool reach = reachable(sc.g, sc.start, sc.goal, sc.policy);
    for (const auto& d : r.extra.at("dead_ants_per_iteration"))
      RC_ASSERT(d.get<std::int64_t>() == (reach ? 0 : sc.params.at("ants").get<std::int64_t>()));
  });
  pathref::testing::require_reach(counted, 0.5, "dead ants counted, start != goal");
}

TEST_CASE("prop_iaco_shi_rho_follows_eq13", "[aco][prop]") {
  // The oracle is Eq. (13) written out here (spec shi2022.eq13, factor reading, binary64 in the
  // spec's order): rho(t) = max((T / (T + t')) * (1 / e^(1 - rho(t-1))) * rho(t-1), rho_min), t' =
  // t - 1 + rho_t_origin — not aco::adaptive_rho, the function the planner calls.
  pathref::testing::Reach reach;
  rc::prop("rho_per_iteration = Eq. 13 iterated from rho_initial (shi2022.eq13)", [&reach] {
    Scenario sc = gen_scenario();
    distinct_ends(sc);
    const bool nomin = *rc::gen::arbitrary<bool>();
    const auto origin = *rc::gen::inRange<std::int64_t>(0, 2);
    const auto N = *rc::gen::inRange<std::int64_t>(1, 12);
    sc.params = planners::Json{{"ants", 1}, {"iterations", N}, {"rho_t_origin", origin}};
    const planners::Result r = plan(sc, nomin ? "iaco-shi-nomin" : "iaco-shi", sc.params);
    if (!reach.hit(!(sc.start == sc.goal))) return;
    const double rho_min = nomin ? 0.0 : 0.1;
    double rho = 0.9;
    const auto& got = r.extra.at("rho_per_iteration");
    RC_ASSERT(static_cast<std::int64_t>(got.size()) == N);
    for (std::int64_t t = 1; t <= N; ++t) {
      RC_ASSERT(got[static_cast<std::size_t>(t - 1)].get<double>() == rho);
      const double T = static_cast<double>(N);
      const double tt = static_cast<double>(t - 1 + origin);
      const double v = ((T / (T + tt)) * (1.0 / std::exp(1.0 - rho))) * rho;
      rho = v > rho_min ? v : rho_min;
    }
  });
  pathref::testing::require_reach(reach, 0.6, "shi2022.eq13 per iteration");
}

TEST_CASE("prop_iaco_han_q0_and_rho_follow_eq5_eq7", "[aco][prop]") {
  // The q0 oracle is Eq. (5) written out here (spec han.eq5, epsilon = 1, N_c = t):
  // q0 = 1 * (0.2 + ((N - t) / N) * 0.7) — not aco::adaptive_q0, the function the planner calls.
  pathref::testing::Reach reach;
  rc::prop("q0 per iteration = Eq. 5; rho in [rho_min, 0.7], non-increasing", [&reach] {
    Scenario sc = gen_scenario();
    distinct_ends(sc);
    sc.params.erase("dead_end");
    const planners::Result r = plan(sc, "iaco-han", sc.params);
    if (!reach.hit(!(sc.start == sc.goal))) return;
    const auto N = sc.params.at("iterations").get<std::int64_t>();
    const auto& q0 = r.extra.at("q0_per_iteration");
    const auto& rho = r.extra.at("rho_per_iteration");
    for (std::int64_t t = 1; t <= N; ++t) {
      const double share_left = static_cast<double>(N - t) / static_cast<double>(N);
      RC_ASSERT(q0[static_cast<std::size_t>(t - 1)].get<double>() == 1.0 * (0.2 + (share_left * 0.7)));
      const double v = rho[static_cast<std::size_t>(t - 1)].get<double>();
      RC_ASSERT(v >= 0.1);
      RC_ASSERT(v <= 0.7);
      if (t > 1) RC_ASSERT(v <= rho[static_cast<std::size_t>(t - 2)].get<double>());
    }
    RC_ASSERT(rho[0].get<double>() == 0.7);  // rho_timing = next: the printed rho(0) first
  });
  pathref::testing::require_reach(reach, 0.6, "han.eq5 / han.eq7 per iteration");
}

TEST_CASE("prop_distinct_paths_are_valid_and_contain_the_best", "[aco][prop]") {
  pathref::testing::Reach reach;
  rc::prop("ant_colony::run: distinct surviving paths, valid, counts sum to the survivors", [&reach] {
    Scenario sc = gen_scenario();
    distinct_ends(sc);
    planners::Request req;
    req.grid = &sc.g;
    req.start = sc.start;
    req.goal = sc.goal;
    req.policy = sc.policy;
    ant_colony::Config cfg = ant_colony::shi_iaco();
    cfg.ants = sc.params.at("ants").get<std::int64_t>();
    cfg.iterations = sc.params.at("iterations").get<std::int64_t>();
    rng::Stream stream(sc.seed);
    const ant_colony::Run run = ant_colony::run(req, cfg, stream);
    if (!reach.hit(!(sc.start == sc.goal))) return;
    std::int64_t survivors = 0;
    for (const auto& d : run.result.extra.at("dead_ants_per_iteration"))
      survivors += cfg.ants - d.get<std::int64_t>();
    std::int64_t counted = 0;
    std::set<std::vector<std::int64_t>> seen;
    bool has_best = false;
    for (const auto& ap : run.distinct_paths) {
      RC_ASSERT(metrics::validate_path(sc.g, ap.path, sc.start, sc.goal, sc.policy).valid);
      RC_ASSERT(ap.length == metrics::path_length(ap.path));
      RC_ASSERT(ap.first_iteration <= ap.last_iteration);
      std::vector<std::int64_t> key;
      for (const Cell& c : ap.path) key.push_back(sc.g.index(c));
      RC_ASSERT(seen.insert(key).second);
      counted += ap.count;
      has_best = has_best || ap.path == run.result.path;
    }
    RC_ASSERT(counted == survivors);
    RC_ASSERT(has_best == run.result.found);
    RC_ASSERT(stream.doubles_drawn() == run.result.extra.at("draws").get<std::uint64_t>());
  });
  pathref::testing::require_reach(reach, 0.45, "distinct paths, start != goal");
}

TEST_CASE("prop_astar_han_equals_dijkstra", "[aco][prop]") {
  pathref::testing::Reach found;
  rc::prop("astar-han (Chebyshev, admissible under every policy) finds Dijkstra's cost", [&found] {
    Scenario sc;
    sc.g = *testing::gen_grid(14, 14, 0.5);
    const auto n = sc.g.cell_count();
    sc.start = sc.g.cell(*rc::gen::inRange<std::int64_t>(0, n));
    sc.goal = sc.g.cell(*rc::gen::inRange<std::int64_t>(0, n));
    sc.g.set_blocked(sc.start, false);
    sc.g.set_blocked(sc.goal, false);
    sc.policy = *testing::gen_policy();
    const planners::Result a = plan(sc, "astar-han", planners::Json::object());
    const search::Outcome d = search::dijkstra(sc.g, sc.start, sc.goal, sc.policy);
    RC_ASSERT(a.found == d.found);
    if (!found.hit(a.found)) return;
    RC_ASSERT(metrics::validate_path(sc.g, a.path, sc.start, sc.goal, sc.policy).valid);
    RC_ASSERT(search::step_counts(a.path) == search::step_counts(d.path));
  });
  pathref::testing::require_reach(found, 0.7, "astar-han paths found");
}
