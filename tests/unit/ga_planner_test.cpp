// spec: shi2022.op.init, shi2022.op.crossover, shi2022.op.mutation, shi2022.op.deletion,
// shi2022.op.elite, shi2022.plan.ga, shi2022.plan.iga, shi2022.plan.hybrid, shi2022.plan.iha
#include <catch2/catch.hpp>

#include <algorithm>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/ga_operators.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/io/builtin_maps.hpp"
#include "pathref/planners/genetic.hpp"
#include "pathref/planners/hybrid.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/planners/search.hpp"
#include "pathref/rules/registry.hpp"

using namespace pathref;
using grid::Cell;
using grid::CornerPolicy;
using grid::Grid;
using Path = std::vector<Cell>;

namespace {

Grid open_grid(int w, int h) { return Grid(w, h); }

planners::Result plan(const char* algo, const Grid& g, Cell s, Cell e, std::uint32_t seed,
                      planners::Json params) {
  const planners::Planner* p = planners::find_planner(algo);
  REQUIRE(p != nullptr);
  planners::Request req;
  req.grid = &g;
  req.start = s;
  req.goal = e;
  req.seed = seed;
  req.params = std::move(params);
  return p->run(req);
}

const planners::Json small_ga = {{"population", 12}, {"generations", 6}};
const planners::Json small_hybrid = {{"population", 12}, {"generations", 6}, {"aco_ants", 6},
                                     {"aco_iterations", 5}};

}  // namespace

TEST_CASE("shi2022.op.init: chain repair inserts mid-points, drops repeats, rejects obstacles") {
  const Grid free5 = open_grid(5, 5);
  // (0,0) -> (4,2): Delta 4, mid (2,1); (0,0)-(2,1) mid (1,0); then continuous.
  const Path genes{{0, 0}, {4, 2}};
  const ga::ChainRepair r = ga::connect_chain(free5, genes, CornerPolicy::strict);
  CHECK(r.feasible);
  CHECK(r.reason == "ok");
  CHECK(r.path == Path{{0, 0}, {1, 0}, {2, 1}, {3, 1}, {4, 2}});
  // ceil rounding picks the other mid-points.
  const ga::ChainRepair c =
      ga::connect_chain(free5, genes, CornerPolicy::strict, ga::MidRounding::ceil);
  CHECK(c.path == Path{{0, 0}, {1, 1}, {2, 1}, {3, 2}, {4, 2}});
  // A repeated gene is dropped.
  CHECK(ga::connect_chain(free5, Path{{0, 0}, {0, 0}, {1, 1}}, CornerPolicy::strict).path ==
        Path{{0, 0}, {1, 1}});
  // A blocked mid-point rejects the chain under init_reject = blocked; under the default shift
  // it moves to a free orthogonal neighbour; a blocked gene is rejected either way.
  Grid g = open_grid(5, 5);
  g.set_blocked(Cell{2, 1}, true);
  CHECK(ga::connect_chain(g, genes, CornerPolicy::strict, ga::MidRounding::floor,
                          ga::InitReject::blocked)
            .reason == "blocked_insert");
  CHECK(ga::connect_chain(g, genes, CornerPolicy::strict).path ==
        Path{{0, 0}, {1, 1}, {1, 2}, {2, 2}, {3, 2}, {3, 1}, {4, 2}});
  CHECK(ga::connect_chain(g, Path{{0, 0}, {2, 1}, {4, 2}}, CornerPolicy::strict).reason ==
        "blocked_gene");
  // A corner-cutting diagonal is not continuous under strict (illegal_step = repair, default):
  // the free orthogonal cell (0,1) is inserted; under reject it is an illegal step; under
  // always it is a move.
  Grid h = open_grid(3, 3);
  h.set_blocked(Cell{1, 0}, true);
  const ga::ChainRepair corner = ga::connect_chain(h, Path{{0, 0}, {1, 1}}, CornerPolicy::strict);
  CHECK(corner.feasible);
  CHECK(corner.path == Path{{0, 0}, {0, 1}, {1, 1}});
  CHECK(ga::connect_chain(h, Path{{0, 0}, {1, 1}}, CornerPolicy::strict, ga::MidRounding::floor,
                          ga::InitReject::blocked, ga::IllegalStep::reject)
            .reason == "illegal_step");
  CHECK(ga::connect_chain(h, Path{{0, 0}, {1, 1}}, CornerPolicy::always).path == Path{{0, 0}, {1, 1}});
  // Both orthogonal cells blocked: rejected under repair too.
  h.set_blocked(Cell{0, 1}, true);
  CHECK(ga::connect_chain(h, Path{{0, 0}, {1, 1}}, CornerPolicy::strict).reason == "illegal_step");
  // Under never every diagonal is repaired, horizontal cell first: (1,0) then (1,1).
  CHECK(ga::connect_chain(free5, Path{{0, 0}, {1, 1}}, CornerPolicy::never).path ==
        Path{{0, 0}, {1, 0}, {1, 1}});
  CHECK(ga::parse_illegal_step("reject") == ga::IllegalStep::reject);
  CHECK_THROWS_AS(ga::parse_illegal_step("cut"), UsageError);
  // near_obstacle rejects an inserted cell next to an obstacle.
  Grid k = open_grid(5, 5);
  k.set_blocked(Cell{2, 3}, true);
  CHECK(ga::connect_chain(k, Path{{0, 2}, {4, 2}}, CornerPolicy::strict).feasible);
  CHECK(ga::connect_chain(k, Path{{0, 2}, {4, 2}}, CornerPolicy::strict, ga::MidRounding::floor,
                          ga::InitReject::near_obstacle)
            .reason == "near_obstacle");
  CHECK_THROWS_AS(ga::connect_chain(free5, Path{{0, 0}}, CornerPolicy::strict), DomainError);
  CHECK_THROWS_AS(ga::connect_chain(free5, Path{{0, 0}, {5, 0}}, CornerPolicy::strict), DomainError);
}

TEST_CASE("shi2022.op.crossover: common interior nodes and the two children") {
  const Path a{{0, 0}, {1, 0}, {2, 1}, {3, 1}, {4, 2}};
  const Path b{{0, 0}, {1, 1}, {2, 1}, {3, 2}, {4, 2}};
  const auto pts = ga::crossover_points(a, b);
  REQUIRE(pts == std::vector<ga::CrossPoint>{{2, 2}});
  const ga::Children c = ga::crossover_at(a, b, pts[0]);
  CHECK(c.first == Path{{0, 0}, {1, 0}, {2, 1}, {3, 2}, {4, 2}});
  CHECK(c.second == Path{{0, 0}, {1, 1}, {2, 1}, {3, 1}, {4, 2}});
  // Start and goal are not crossover points; two-node paths have none.
  CHECK(ga::crossover_points(Path{{0, 0}, {1, 1}}, Path{{0, 0}, {1, 1}}).empty());
  CHECK_THROWS_AS(ga::crossover_at(a, b, ga::CrossPoint{1, 1}), DomainError);
}

TEST_CASE("shi2022.op.mutation: candidates adjacent to both neighbours, increasing index") {
  const Grid g = open_grid(4, 4);
  const Path p{{0, 0}, {1, 0}, {2, 0}};
  // Neighbours of (0,0) that reach (2,0) in one move, without (1,0) itself: (1,1).
  CHECK(ga::mutation_candidates(g, p, 1, CornerPolicy::strict) == Path{{1, 1}});
  const Path q{{0, 0}, {1, 1}, {2, 2}};
  // Cells adjacent to (0,0) and (2,2) other than (1,1): none. Under strict, (0,1)/(1,0) are not
  // adjacent to (2,2).
  CHECK(ga::mutation_candidates(g, q, 1, CornerPolicy::strict).empty());
  const Path r{{0, 0}, {1, 0}, {1, 1}};
  CHECK(ga::mutation_candidates(g, r, 1, CornerPolicy::strict) == Path{{0, 1}});
  CHECK_THROWS_AS(ga::mutation_candidates(g, p, 0, CornerPolicy::strict), DomainError);
  CHECK_THROWS_AS(ga::mutation_candidates(g, p, 2, CornerPolicy::strict), DomainError);
}

TEST_CASE("shi2022.op.deletion: detours replaced by one move, never longer") {
  const Grid g = open_grid(5, 5);
  const Path p{{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {3, 3}};
  const Path d = ga::delete_redundant(g, p, CornerPolicy::strict);
  CHECK(d == Path{{0, 0}, {1, 1}, {2, 2}, {3, 3}});
  CHECK(metrics::path_length(d) < metrics::path_length(p));
  CHECK(ga::delete_redundant(g, d, CornerPolicy::strict) == d);
  // Under never the diagonal shortcut is not a move: nothing removed.
  CHECK(ga::delete_redundant(g, p, CornerPolicy::never) == p);
  // A corner around an obstacle stays under strict.
  Grid h = open_grid(3, 3);
  h.set_blocked(Cell{1, 0}, true);
  const Path around{{0, 0}, {0, 1}, {1, 1}};
  CHECK(ga::delete_redundant(h, around, CornerPolicy::strict) == around);
  CHECK(ga::delete_redundant(h, around, CornerPolicy::one) == Path{{0, 0}, {1, 1}});
}

TEST_CASE("shi2022.op.loops: closed loops cut back to the first visit") {
  CHECK(ga::remove_loops(Path{{0, 0}, {1, 1}, {1, 2}, {2, 2}, {1, 1}, {2, 1}}) ==
        Path{{0, 0}, {1, 1}, {2, 1}});
  CHECK(ga::remove_loops(Path{{0, 0}, {1, 0}, {1, 1}, {2, 1}, {1, 1}, {1, 0}, {2, 0}}) ==
        Path{{0, 0}, {1, 0}, {2, 0}});
  const Path simple{{0, 0}, {1, 1}, {2, 1}};
  CHECK(ga::remove_loops(simple) == simple);
  CHECK(ga::remove_loops(Path{}).empty());
}

TEST_CASE("shi2022.op.elite: top count by fitness, ties by index") {
  const std::vector<double> f{1.0, 3.0, 2.0, 3.0, 0.5};
  CHECK(ga::elite_indices(f, 3) == std::vector<std::size_t>{1, 3, 2});
  CHECK(ga::elite_indices(f, 0).empty());
  CHECK(ga::elite_count(5, 0.5) == 3);
  CHECK(ga::elite_count(200, 0.5) == 100);
  CHECK(ga::elite_count(1, 0.01) == 1);
  CHECK_THROWS_AS(ga::elite_indices(f, 6), DomainError);
  CHECK_THROWS_AS(ga::elite_count(4, 0.0), DomainError);
  const std::vector<double> bad{1.0, std::nan("")};
  CHECK_THROWS_AS(ga::elite_indices(bad, 1), DomainError);
}

TEST_CASE("shi2022.plan.ga: runs on shi6x6, lists every parameter, rejects bad input") {
  const io::MapFile m = io::load_builtin_map(*io::find_builtin_map("shi6x6"));
  const Grid& g = m.grid;
  const planners::Result r = plan("ga", g, Cell{0, 0}, Cell{5, 5}, 7, small_ga);
  REQUIRE(r.found);
  CHECK(metrics::validate_path(g, r.path, Cell{0, 0}, Cell{5, 5}, CornerPolicy::strict).valid);
  CHECK(r.length == metrics::path_length(r.path));
  CHECK(r.best_per_iteration.size() == 6);
  CHECK(r.mean_per_iteration.size() == 6);
  CHECK(r.iterations == 6);
  CHECK(r.params_used.at("population") == 12);
  CHECK(r.params_used.at("pc") == 0.8);
  CHECK(r.params_used.at("pm") == 0.1);
  CHECK(r.params_used.at("ga_probabilities") == "fixed");
  CHECK(r.params_used.at("fitness") == "inverse_length");
  CHECK(r.extra.contains("draws"));
  // The same seed replays the run; the best-so-far under inverse_length never increases.
  const planners::Result again = plan("ga", g, Cell{0, 0}, Cell{5, 5}, 7, small_ga);
  CHECK(again.path == r.path);
  CHECK(again.best_per_iteration == r.best_per_iteration);
  for (std::size_t i = 1; i < r.best_per_iteration.size(); ++i)
    CHECK(r.best_per_iteration[i] <= r.best_per_iteration[i - 1]);
  // Bad input.
  CHECK_THROWS_AS(plan("ga", g, Cell{0, 0}, Cell{5, 5}, 1, {{"nope", 1}}), UsageError);
  CHECK_THROWS_AS(plan("ga", g, Cell{0, 0}, Cell{5, 5}, 1, {{"population", 1}}), DomainError);
  CHECK_THROWS_AS(plan("ga", g, Cell{0, 0}, Cell{5, 5}, 1, {{"pc", 1.5}}), DomainError);
  CHECK_THROWS_AS(plan("ga", g, Cell{0, 0}, Cell{5, 5}, 1, {{"crossover_keep", "x"}}), UsageError);
  CHECK_THROWS_AS(plan("ga", g, Cell{0, 0}, Cell{6, 5}, 1, small_ga), DomainError);
  CHECK_THROWS_AS(plan("ga", g, Cell{0, 0}, Cell{3, 4}, 1, small_ga), DomainError);  // blocked
  // start == goal: the one-cell path, no draw.
  const planners::Result same = plan("ga", g, Cell{0, 0}, Cell{0, 0}, 1, small_ga);
  CHECK(same.found);
  CHECK(same.path == Path{{0, 0}});
  CHECK(same.extra.at("draws") == 0);
}

TEST_CASE("shi2022.plan.ga: an unreachable goal reports the failure, not a crash") {
  Grid g = open_grid(5, 5);
  for (std::int64_t x = 0; x < 5; ++x) g.set_blocked(Cell{x, 2}, true);
  const planners::Result r = plan("ga", g, Cell{0, 0}, Cell{4, 4}, 3, small_ga);
  CHECK_FALSE(r.found);
  CHECK(r.path.empty());
  CHECK(r.extra.at("failure") == "row_blocked");
  CHECK(r.extra.at("draws") == 0);
  // Enclosed goal with free cells on every row: attempts are exhausted.
  Grid h = open_grid(5, 5);
  for (const Cell c : {Cell{3, 3}, Cell{4, 3}, Cell{3, 4}}) h.set_blocked(c, true);
  const planners::Result q =
      plan("ga", h, Cell{0, 0}, Cell{4, 4}, 3, {{"population", 4}, {"init_attempts", 20}});
  CHECK_FALSE(q.found);
  CHECK(q.extra.at("failure") == "init_attempts_exhausted");
  CHECK(q.extra.at("init_chains") == 20);
}

TEST_CASE("shi2022.plan.iga: weighted fitness and adaptive probabilities - IGA* has no cap") {
  const io::MapFile m = io::load_builtin_map(*io::find_builtin_map("shi6x6"));
  const planners::Result r = plan("iga-shi", m.grid, Cell{0, 0}, Cell{5, 5}, 11, small_ga);
  REQUIRE(r.found);
  CHECK(metrics::validate_path(m.grid, r.path, Cell{0, 0}, Cell{5, 5}, CornerPolicy::strict).valid);
  CHECK(r.params_used.at("fitness") == "weighted");
  CHECK(r.params_used.at("ga_probabilities") == "adaptive");
  CHECK(r.params_used.at("pm_max") == 0.3);
  const planners::Result s = plan("iga-shi-nomax", m.grid, Cell{0, 0}, Cell{5, 5}, 11, small_ga);
  REQUIRE(s.found);
  CHECK(s.params_used.at("pm_max") == 1.0);
  // The reported best fitness is Eq. 14 written out, ((a fit1) + (b fit2)) + (c fit3) with
  // Table 1's a = 5, b = 4, c = 1, over the factors of Eq. 15, 16 and 18 evaluated by their own
  // rules under the readings the run reports (not through the planner's fitness function).
  const planners::Json& u = r.params_used;
  CHECK(u.at("a").get<double>() == 5.0);
  CHECK(u.at("b").get<double>() == 4.0);
  CHECK(u.at("c").get<double>() == 1.0);
  planners::Json path = planners::Json::array();
  for (const Cell& cell : r.path) path.push_back({cell.x, cell.y});
  const rules::Registry& reg = rules::registry();
  const double fit1 = 1.0 / metrics::path_length(r.path);
  const double fit2 = reg.find("shi2022.eq16")
                          ->eval({{"path", path}, {"penalties", u.at("penalties")}, {"smoothness", u.at("smoothness")}})
                          .at("fit2")
                          .get<double>();
  const double fit3 = reg.find("shi2022.eq18")
                          ->eval({{"grid", grid::grid_to_json(m.grid)},
                                  {"path", path},
                                  {"safety_aggregate", u.at("safety_aggregate")},
                                  {"safety_count", u.at("safety_count")},
                                  {"safe_node", u.at("safe_node")},
                                  {"safety_nodes", u.at("safety_nodes")},
                                  {"outside", u.at("outside")}})
                          .at("fit3")
                          .get<double>();
  CHECK(fit2 != fit3);  // otherwise swapping the two factors would go unnoticed
  CHECK(r.extra.at("best_fitness").get<double>() == ((5.0 * fit1) + (4.0 * fit2)) + (1.0 * fit3));
}

TEST_CASE("shi2022.plan.hybrid: colony then GA, curves of both phases, phase reported") {
  const io::MapFile m = io::load_builtin_map(*io::find_builtin_map("shi6x6"));
  const planners::Result r = plan("hybrid-ga-aco", m.grid, Cell{0, 0}, Cell{5, 5}, 5, small_hybrid);
  REQUIRE(r.found);
  CHECK(metrics::validate_path(m.grid, r.path, Cell{0, 0}, Cell{5, 5}, CornerPolicy::strict).valid);
  CHECK(r.iterations == 5 + 6);
  CHECK(r.best_per_iteration.size() == 11);
  const std::string phase = r.extra.at("phase").get<std::string>();
  CHECK((phase == "aco" || phase == "ga"));
  CHECK(r.params_used.contains("aco_ants"));
  CHECK(r.params_used.contains("fill"));
  // The GA part starts from the colony's paths: never worse than the colony's best.
  const double colony_best = r.extra.at("aco").at("best_length").get<double>();
  CHECK(r.length <= colony_best);
  CHECK_THROWS_AS(plan("hybrid-ga-aco", m.grid, Cell{0, 0}, Cell{5, 5}, 5, {{"fill", "x"}}),
                  UsageError);
  CHECK_THROWS_AS(plan("hybrid-ga-aco", m.grid, Cell{0, 0}, Cell{5, 5}, 5, {{"aco_ants", 0}}),
                  DomainError);
}

TEST_CASE("shi2022.plan.iha: injected ant paths, deletion, elite retention, phase reported") {
  const io::MapFile m = io::load_builtin_map(*io::find_builtin_map("shi6x6"));
  planners::Json p = small_hybrid;
  p["result_by"] = "length";
  const planners::Result r = plan("iha", m.grid, Cell{0, 0}, Cell{5, 5}, 9, p);
  REQUIRE(r.found);
  CHECK(metrics::validate_path(m.grid, r.path, Cell{0, 0}, Cell{5, 5}, CornerPolicy::strict).valid);
  CHECK(r.best_per_iteration.size() == 11);
  CHECK(r.params_used.at("inject") == 10);
  CHECK(r.params_used.at("elite_fraction") == 0.5);
  CHECK(r.params_used.at("aco_eta") == "goal_directed");
  // The colony's best is injected, so by length the IHA is never worse than its colony.
  CHECK(r.length <= r.extra.at("aco").at("best_length").get<double>());
  // Under result_by = length the returned path is the shortest of the run: its length is the
  // curve's last best-so-far value and the minimum of every recorded value (elite retention
  // itself: "prop: shi2022.op.elite never loses the best").
  REQUIRE_FALSE(r.best_per_iteration.empty());
  CHECK(r.length == r.best_per_iteration.back());
  CHECK(r.length == *std::min_element(r.best_per_iteration.begin(), r.best_per_iteration.end()));
  const search::Outcome opt = search::dijkstra(m.grid, Cell{0, 0}, Cell{5, 5}, CornerPolicy::strict);
  CHECK(r.length >= opt.length * (1.0 - 1e-12));
  CHECK_THROWS_AS(plan("iha", m.grid, Cell{0, 0}, Cell{5, 5}, 9, {{"inject", -1}}), DomainError);
  CHECK_THROWS_AS(plan("iha", m.grid, Cell{0, 0}, Cell{5, 5}, 9, {{"deletion_scope", "x"}}),
                  UsageError);
}
