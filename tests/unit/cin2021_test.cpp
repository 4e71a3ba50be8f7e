// spec: cin2021.eq16 ... cin2021.eq35, cin2021.op.*, cin2021.plan.* (spec/cin2021-hga-aco.md)
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/cin2021.hpp"
#include "pathref/equations/ga_operators.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/planners/planner.hpp"

using namespace pathref;
using grid::Cell;

namespace {

grid::Grid rows(const std::vector<std::string>& r) {
  grid::Grid g(static_cast<std::int64_t>(r[0].size()), static_cast<std::int64_t>(r.size()));
  for (std::size_t i = 0; i < r.size(); ++i)
    for (std::size_t x = 0; x < r[i].size(); ++x)
      if (r[i][x] == '#')
        g.set_blocked(Cell{static_cast<std::int64_t>(x), static_cast<std::int64_t>(r.size() - 1 - i)}, true);
  return g;
}

const std::vector<std::string> trap = {"..........", "..........", "...#####..", ".......#..", ".......#..",
                                       ".......#..", "...#####..", "..........", "..........", ".........."};

planners::Result run(const std::string& algo, const grid::Grid& g, Cell s, Cell t, std::uint32_t seed,
                     planners::Json params) {
  planners::Request req;
  req.grid = &g;
  req.start = s;
  req.goal = t;
  req.seed = seed;
  req.params = std::move(params);
  return planners::find_planner(algo)->run(req);
}

}  // namespace

TEST_CASE("cin2021.eq18: collinear segments give exactly +-1", "[cin2021]") {
  CHECK(cin::segment_cosine(Cell{0, 0}, Cell{1, 1}, Cell{2, 2}) == 1.0);
  CHECK(cin::segment_cosine(Cell{0, 0}, Cell{1, 1}, Cell{0, 0}) == -1.0);
  CHECK(cin::segment_cosine(Cell{0, 0}, Cell{1, 0}, Cell{1, 1}) == 0.0);
  CHECK(cin::smoothness_cost(std::vector<Cell>{{0, 0}, {1, 0}, {1, 1}}) == 1.0);
  CHECK_THROWS_AS(cin::segment_cosine(Cell{0, 0}, Cell{0, 0}, Cell{1, 1}), DomainError);
}

TEST_CASE("cin2021.eq24: penalty classes with the arccos tolerance", "[cin2021]") {
  // the straight diagonal under arccos is a hair below 180 degrees: still class 0
  const double t = cin::included_angle(std::sqrt(2.0), std::sqrt(2.0), std::sqrt(8.0));
  CHECK(t <= 180.0);
  CHECK(t > 180.0 - cin::angle_epsilon_deg);
  CHECK(cin::corner_penalty(t) == 0.0);
  CHECK(cin::corner_penalty(180.0 - 1.2e-6) == 0.0);  // arccos of -1 + 2^-52
  CHECK(cin::corner_penalty(135.0) == 5.0);
  CHECK(cin::corner_penalty(90.0) == 100.0);
  CHECK(cin::corner_penalty(45.0) == 1000.0);
  CHECK_THROWS_AS(cin::corner_penalty(181.0), DomainError);
  CHECK(cin::smoothness_fitness(std::vector<Cell>{{0, 0}, {1, 0}, {2, 0}}) == 1.0);
  CHECK(cin::smoothness_fitness(std::vector<Cell>{{0, 0}, {1, 0}, {2, 0}}, cin::CornerPenalties{},
                                cin::F2Guard::epsilon) == 1.0 / 1e-3);
}

TEST_CASE("cin2021.eq28: a shared edge sums both rows, a row adds once", "[cin2021]") {
  const std::vector<std::vector<Cell>> r{{{0, 0}, {1, 0}, {2, 0}}, {{0, 0}, {1, 0}, {1, 1}}};
  const auto e = cin::converted_pheromone(r, 1.0);
  REQUIRE(e.size() == 3);
  CHECK(e[0].tau == 1.0);  // 1/2 + 1/2
  CHECK(e[1].tau == 0.5);
  CHECK(e[2].tau == 0.5);
  CHECK(cin::conversion_delta(cin::ConversionForm::q_d_over_l, 2.0, 4.0, 1.0) == 0.5);
  CHECK(cin::conversion_delta(cin::ConversionForm::q_over_l_d, 2.0, 4.0, 2.0) == 0.25);
  CHECK_THROWS_AS(cin::converted_pheromone(r, 0.0), DomainError);
}

TEST_CASE("cin2021.eq32-33: weights move from the iteration best to the global best", "[cin2021]") {
  CHECK(cin::best_path_weights(0, 50).ib == 50.0);
  CHECK(cin::best_path_weights(0, 50).gb == 0.0);
  CHECK(cin::best_path_weights(49, 50).gb == 49.0);
  CHECK(cin::best_path_weights(1, 4, cin::WeightNorm::normalised).ib == 0.75);
  CHECK(cin::weighted_best_deposit(true, 3.0, 4.0, true, 1.0, 2.0, 1.0) == 1.25);
  CHECK(cin::weighted_best_deposit(false, 0.0, 0.0, false, 0.0, 0.0, 1.0) == 0.0);
  CHECK(cin::dead_angle_penalty(2.0, 0.5) == 1.0);
  CHECK_THROWS_AS(cin::dead_angle_penalty(2.0, 1.0), DomainError);
}

TEST_CASE("cin2021.op.crossover: cut genes repaired by the chain repair", "[cin2021]") {
  const grid::Grid g(6, 6);
  const std::vector<Cell> a{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 1}};
  const std::vector<Cell> b{{0, 0}, {0, 1}, {0, 2}, {1, 2}, {2, 2}, {3, 2}, {4, 1}};
  const ga::CutChildren c = ga::crossover_cut(g, a, b, 1, 4, grid::CornerPolicy::strict);
  REQUIRE(c.feasible);
  // a[0..1] ++ b[5..] = (0,0) (1,0) | (3,2) (4,1): the gap (1,0) -> (3,2) gets the mid-point (2,1)
  CHECK(c.children.first == std::vector<Cell>{{0, 0}, {1, 0}, {2, 1}, {3, 2}, {4, 1}});
  CHECK_THROWS_AS(ga::crossover_cut(g, a, b, 0, 1, grid::CornerPolicy::strict), DomainError);
}

TEST_CASE("cin2021.op.mutation: greedy walks head for their targets", "[cin2021]") {
  const grid::Grid g(5, 5);
  const std::vector<Cell> p{{0, 0}, {0, 1}, {0, 2}, {1, 3}, {2, 3}, {3, 3}, {4, 4}};
  rng::Stream st(1);
  const ga::Mutants m = ga::multidirectional_mutants(g, p, 3, grid::CornerPolicy::strict,
                                                     ga::Research::greedy, st);
  CHECK(st.doubles_drawn() == 0);
  // A: from (1,3) to (0,0) avoiding (2,3) (3,3) (4,4): (1,2) (0,1)? greedy: (1,2) is nearer...
  REQUIRE(!m.a.empty());
  CHECK(m.a.front() == Cell{0, 0});
  CHECK(m.a.back() == Cell{4, 4});
  REQUIRE(!m.b.empty());
  CHECK(m.b.front() == Cell{0, 0});
  CHECK(m.b.back() == Cell{4, 4});
  CHECK(m.a.size() <= p.size());
}

TEST_CASE("cin2021 planners: registered with the spec's default parameters", "[cin2021]") {
  const auto* ga = planners::find_planner("ga-cin");
  const auto* aco = planners::find_planner("aco-cin");
  const auto* hga = planners::find_planner("hga-aco-cin");
  REQUIRE(ga != nullptr);
  REQUIRE(aco != nullptr);
  REQUIRE(hga != nullptr);
  // the 13 lost parameters (spec "The 13 lost parameters": project defaults, not the paper's)
  CHECK(ga->defaults.at("population") == 50);
  CHECK(ga->defaults.at("generations") == 50);
  CHECK(ga->defaults.at("pc") == 0.8);
  CHECK(ga->defaults.at("pm") == 0.2);
  CHECK(ga->defaults.at("a") == 1.0);
  CHECK(ga->defaults.at("b") == 0.1);
  CHECK(aco->defaults.at("ants") == 30);
  CHECK(aco->defaults.at("iterations") == 50);
  CHECK(aco->defaults.at("alpha") == 1.0);
  CHECK(aco->defaults.at("beta") == 2.0);
  CHECK(aco->defaults.at("rho") == 0.3);
  CHECK(aco->defaults.at("Q") == 1.0);
  CHECK(aco->defaults.at("lambda") == 0.5);
  CHECK(aco->defaults.at("tau0") == 0.1);
  CHECK(aco->defaults.at("tau_bounds") == "off");
  CHECK(aco->defaults.at("dead_end") == "dead_angle");
  CHECK(ga->defaults.at("mutation") == "multidirectional");
  CHECK(hga->defaults.at("aco_ants") == 30);
  CHECK(hga->defaults.at("elite_share") == 0.2);
  CHECK(hga->defaults.at("conversion_form") == "q_over_l");
  // Shi's planners keep their own defaults (no cin default leaks into them): the mutation option
  // is shared since the classic profile (point | multidirectional | segment), Shi's is `point`
  CHECK(planners::find_planner("ga")->defaults.at("mutation") == "point");
  CHECK(!planners::find_planner("ga")->defaults.contains("crossover"));
  CHECK(!planners::find_planner("aco")->defaults.contains("lambda"));
}

TEST_CASE("cin2021.plan.aco: the dead-angle table fills the concave trap", "[cin2021]") {
  // a one-cell-wide spur (3,1)-(3,2) off the corridor y = 0: under cul_de_sac exactly its two
  // cells are recorded, the bottom of the trap first
  const grid::Grid spur = rows({"###.###", "###.###", "......."});
  const auto s = run("aco-cin", spur, Cell{0, 0}, Cell{6, 0}, 3, planners::Json{{"ants", 10}, {"iterations", 5}});
  REQUIRE(s.found);
  CHECK(s.extra.at("dead_angle_table") == planners::Json::parse("[[3,2],[3,1]]"));
  CHECK(s.path == std::vector<Cell>{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}, {6, 0}});
  // the three-row pocket of the trap has no cul-de-sac; any_stuck records where ants got stuck
  const grid::Grid g = rows(trap);
  const auto r = run("aco-cin", g, Cell{0, 5}, Cell{9, 5}, 3,
                     planners::Json{{"ants", 10}, {"iterations", 5}, {"dead_angle_record", "any_stuck"}});
  REQUIRE(r.found);
  const auto& table = r.extra.at("dead_angle_table");
  CHECK(!table.empty());
  // under cul_de_sac every recorded cell had at most one exit outside the table when recorded
  for (const auto& c : table) {
    const Cell cell{c.at(0).get<std::int64_t>(), c.at(1).get<std::int64_t>()};
    CHECK(!(cell == Cell{0, 5}));
  }
  CHECK(r.extra.at("deadlocks").get<std::int64_t>() >= static_cast<std::int64_t>(table.size()));
}

TEST_CASE("cin2021.plan.hga-aco: the GA phase is the ga-cin run, then the colony", "[cin2021]") {
  const grid::Grid g = rows(trap);
  const planners::Json ga_p{{"population", 10}, {"generations", 4}};
  const auto ga = run("ga-cin", g, Cell{0, 5}, Cell{9, 5}, 11, ga_p);
  planners::Json h = ga_p;
  h["aco_ants"] = 5;
  h["aco_iterations"] = 3;
  const auto hga = run("hga-aco-cin", g, Cell{0, 5}, Cell{9, 5}, 11, h);
  REQUIRE(ga.found);
  REQUIRE(hga.found);
  REQUIRE(hga.best_per_iteration.size() == 7);
  for (std::size_t i = 0; i < 4; ++i) CHECK(hga.best_per_iteration[i] == ga.best_per_iteration[i]);
  CHECK(hga.extra.at("ga_best_length").get<double>() == ga.length);
  CHECK(hga.extra.at("draws").get<std::uint64_t>() > ga.extra.at("draws").get<std::uint64_t>());
  CHECK(hga.extra.at("converted_rows") == 2);  // ceil(0.2 * 10)
}

TEST_CASE("cin2021 planners: bad requests are clear errors", "[cin2021]") {
  const grid::Grid g = rows(trap);
  CHECK_THROWS_AS(run("aco-cin", g, Cell{3, 3}, Cell{9, 5}, 1, planners::Json::object()), DomainError);
  CHECK_THROWS_AS(run("aco-cin", g, Cell{0, 0}, Cell{9, 5}, 1, planners::Json{{"lambda", 1.5}}), DomainError);
  CHECK_THROWS_AS(run("aco-cin", g, Cell{0, 0}, Cell{9, 5}, 1, planners::Json{{"dead_angle", "x"}}), UsageError);
  CHECK_THROWS_AS(run("ga-cin", g, Cell{0, 0}, Cell{9, 5}, 1, planners::Json{{"research", "x"}}), UsageError);
  CHECK_THROWS_AS(run("hga-aco-cin", g, Cell{0, 0}, Cell{9, 5}, 1, planners::Json{{"elite_share", 0.0}}),
                  DomainError);
}
