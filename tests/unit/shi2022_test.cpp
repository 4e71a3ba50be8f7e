// spec: shi2022.table1, shi2022.eq1, shi2022.eq2, shi2022.eq3, shi2022.eq4, shi2022.eq5, shi2022.eq6, shi2022.eq7, shi2022.eq8, shi2022.eq9, shi2022.eq10, shi2022.eq11, shi2022.eq12, shi2022.eq13, shi2022.eq14, shi2022.eq15, shi2022.eq16, shi2022.eq17, shi2022.eq18, shi2022.eq19, shi2022.eq20
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/aco.hpp"
#include "pathref/equations/ga.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/equations/proportional.hpp"
#include "pathref/equations/shi2022.hpp"
#include "pathref/grid/coords.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rules/registry.hpp"

using namespace pathref;
using grid::Cell;

namespace {
constexpr double pi = std::numbers::pi;
}  // namespace

TEST_CASE("shi2022.table1: the printed parameters", "[shi2022]") {
  const auto& t = shi2022::table1;
  CHECK(t.ants == 50);
  CHECK(t.aco_iterations == 100);
  CHECK(t.alpha == 1.0);
  CHECK(t.beta == 7.0);
  CHECK(t.Q == 1.0);
  CHECK(t.rho_initial == 0.9);
  CHECK(t.rho_min == 0.1);
  CHECK(t.ga_population == 200);
  CHECK(t.ga_generations == 50);
  CHECK(t.a == 5.0);
  CHECK(t.b == 4.0);
  CHECK(t.c == 1.0);
  CHECK(t.pc == 0.8);
  CHECK(t.pm == 0.1);
  CHECK(t.pm_max == 0.3);
  const ga::FitnessWeights w{};
  CHECK((w.a == t.a && w.b == t.b && w.c == t.c));
}

TEST_CASE("shi2022.table1: the IACO and IGA planners' defaults are the printed values", "[shi2022]") {
  // spec shi2022.table1: the ant colony row (m = 50, T = 100, alpha = 1, beta = 7, Q = 1,
  // rho(0) = 0.9, rho_min = 0.1) and the genetic row (200 individuals, M_g = 50, a = 5, b = 4,
  // c = 1, P_m_max = 0.3), written out here so that neither side can drift alone.
  const planners::Planner* aco = planners::find_planner("iaco-shi");
  REQUIRE(aco != nullptr);
  const planners::Json& a = aco->defaults;
  CHECK(a.at("ants") == 50);
  CHECK(a.at("iterations") == 100);
  CHECK(a.at("alpha").get<double>() == 1.0);
  CHECK(a.at("beta").get<double>() == 7.0);
  CHECK(a.at("Q").get<double>() == 1.0);
  CHECK(a.at("rho_initial").get<double>() == 0.9);
  CHECK(a.at("rho_min").get<double>() == 0.1);
  const planners::Planner* iga = planners::find_planner("iga-shi");
  REQUIRE(iga != nullptr);
  const planners::Json& g = iga->defaults;
  CHECK(g.at("population") == 200);
  CHECK(g.at("generations") == 50);
  CHECK(g.at("a").get<double>() == 5.0);
  CHECK(g.at("b").get<double>() == 4.0);
  CHECK(g.at("c").get<double>() == 1.0);
  CHECK(g.at("pm_max").get<double>() == 0.3);
}

TEST_CASE("shi2022.eq1: the three forms written out", "[shi2022]") {
  const rules::Rule* rule = rules::registry().find("shi2022.eq1");
  REQUIRE(rule != nullptr);
  // spec shi2022.eq1 written out on the 6x6 map (N = W = 6): corrected x = (i mod W) + 0.5,
  // y = floor(i / W) + 0.5; printed x = mod(s, N) + 0.5, y = ceil(s / N) - 0.5 with s = i
  // (printed0) or s = i + 1 (printed1); ceil(s / N) = (s + N - 1) div N for s >= 0.
  for (std::int64_t i = 0; i < 36; ++i) {
    const auto eval = [&](const char* form) {
      return rule->eval({{"i", i}, {"width", 6}, {"height", 6}, {"form", form}});
    };
    const rules::Json c = eval("corrected");
    CHECK(c.at("x").get<double>() == static_cast<double>(i % 6) + 0.5);
    CHECK(c.at("y").get<double>() == static_cast<double>(i / 6) + 0.5);
    for (const std::int64_t base : {0, 1}) {
      const std::int64_t s = i + base;
      const rules::Json p = eval(base == 0 ? "printed0" : "printed1");
      CHECK(p.at("x").get<double>() == static_cast<double>(s % 6) + 0.5);
      CHECK(p.at("y").get<double>() == static_cast<double>((s + 5) / 6) - 0.5);
    }
  }
  CHECK_THROWS_AS(rule->eval({{"i", 36}, {"width", 6}, {"height", 6}}), DomainError);
  // Hand-derived values of the corrected form (x, y) = (i mod W + 1/2, floor(i / W) + 1/2) on the
  // 6x6 map (an oracle independent of grid::cell_centre, issue 17): i = 0 -> (0.5, 0.5),
  // i = 7 -> (1.5, 1.5), i = 35 -> (5.5, 5.5), i = 11 -> (5.5, 1.5).
  const std::int64_t is[] = {0, 7, 35, 11};
  const double xs[] = {0.5, 1.5, 5.5, 5.5}, ys[] = {0.5, 1.5, 5.5, 1.5};
  for (std::size_t k = 0; k < 4; ++k) {
    const rules::Json out = rule->eval({{"i", is[k]}, {"width", 6}, {"height", 6}, {"form", "corrected"}});
    CHECK(out.at("x").get<double>() == xs[k]);
    CHECK(out.at("y").get<double>() == ys[k]);
  }
}

TEST_CASE("shi2022.eq2: weights, probabilities and the optional corner factor", "[shi2022]") {
  const std::vector<double> tau{0.5, 1.5};
  const std::vector<double> eta{2.0, 0.25};
  const auto w = aco::transition_weights(tau, eta, 2.0, 1.0);
  REQUIRE(w.size() == 2);
  CHECK(w[0] == 0.5);
  CHECK(w[1] == 0.5625);
  const auto p = aco::transition_probabilities(tau, eta, 2.0, 1.0);
  CHECK(p[0] == 0.5 / 1.0625);
  CHECK(p[1] == 0.5625 / 1.0625);
  // Han Eq. 1: an extra factor omega^gamma per candidate (2 for gentle, 1 for sharp corners).
  const std::vector<double> omega{2.0, 1.0};
  const auto wc = aco::transition_weights(tau, eta, 2.0, 1.0, aco::CornerFactor{omega, 1.0});
  CHECK(wc[0] == 1.0);
  CHECK(wc[1] == 0.5625);
  const auto wc0 = aco::transition_weights(tau, eta, 2.0, 1.0, aco::CornerFactor{omega, 0.0});
  CHECK(wc0 == std::vector<double>{0.5, 0.5625});  // gamma = 0: omega^0 = 1, Shi's rule by hand
  const std::vector<double> short_omega{1.0};
  CHECK_THROWS_AS(aco::transition_weights(tau, eta, 2.0, 1.0, aco::CornerFactor{short_omega, 1.0}),
                  DomainError);
}

TEST_CASE("shi2022.eq2: an empty allowed set or zero weights are a DomainError", "[shi2022]") {
  const std::vector<double> none;
  const std::vector<double> zeros{0.0, 0.0};
  const std::vector<double> ones{1.0, 1.0};
  CHECK_THROWS_AS(aco::transition_probabilities(none, none, 1.0, 7.0), DomainError);
  CHECK_THROWS_AS(aco::transition_probabilities(zeros, ones, 1.0, 7.0), DomainError);
  CHECK_THROWS_AS(equations::proportional_probabilities(none), DomainError);
  CHECK_THROWS_AS(equations::proportional_probabilities(zeros), DomainError);
  const std::vector<double> huge{1e308, 1e308};
  CHECK_THROWS_AS(equations::proportional_probabilities(huge), DomainError);  // sum overflows
}

TEST_CASE("shi2022.eq3 eq4 eq12: distances and heuristics between cell centres", "[shi2022]") {
  CHECK(metrics::centre_distance(Cell{0, 0}, Cell{3, 4}) == 5.0);
  CHECK(aco::eta_inverse_distance(Cell{0, 0}, Cell{1, 0}) == 1.0);
  CHECK(aco::eta_inverse_distance(Cell{0, 0}, Cell{1, 1}) == 1.0 / std::numbers::sqrt2);
  // Not sqrt(0.5): the division of 1 by the rounded sqrt2 is one ulp lower.
  CHECK(aco::eta_inverse_distance(Cell{0, 0}, Cell{1, 1}) < std::sqrt(0.5));
  CHECK(aco::eta_goal_directed(Cell{4, 5}, Cell{5, 5}, Cell{5, 5}) == 1.0);
  CHECK(aco::eta_goal_directed(Cell{0, 0}, Cell{1, 0}, Cell{4, 4}) == 1.0 / 6.0);
  CHECK_THROWS_AS(aco::eta_inverse_distance(Cell{2, 2}, Cell{2, 2}), DomainError);
  CHECK_THROWS_AS(aco::eta_goal_directed(Cell{2, 2}, Cell{2, 2}, Cell{5, 5}), DomainError);
}

TEST_CASE("shi2022.eq5 eq6 eq7: evaporation, total deposit and the ant-cycle deposit", "[shi2022]") {
  CHECK(aco::pheromone_update(1.0, 0.9, 0.0) == 1.0 - 0.9);
  CHECK(aco::pheromone_update(1.0, 0.9, 0.0) != 0.1);
  CHECK(aco::pheromone_update(2.0, 0.25, 0.5) == 2.0);
  CHECK_THROWS_AS(aco::pheromone_update(1.0, 0.0, 0.0), DomainError);
  CHECK_THROWS_AS(aco::pheromone_update(1.0, 1.0, 0.0), DomainError);

  const std::vector<double> big_first{1e16, 1.0, 1.0};
  const std::vector<double> big_last{1.0, 1.0, 1e16};
  CHECK(aco::total_deposit(big_first) == 1e16);
  CHECK(aco::total_deposit(big_last) == 1e16 + 2.0);
  CHECK(aco::total_deposit(std::vector<double>{}) == 0.0);

  const std::vector<Cell> path{{0, 0}, {1, 0}, {0, 0}, {1, 0}, {2, 0}};
  using aco::EdgeRepeats;
  using aco::EdgeSense;
  CHECK(aco::edge_deposit(path, {0, 0}, {1, 0}, 1.0) == 0.25);
  CHECK(aco::edge_deposit(path, {0, 0}, {1, 0}, 1.0, EdgeSense::directed,
                          EdgeRepeats::per_traversal) == 0.5);
  CHECK(aco::edge_deposit(path, {1, 0}, {0, 0}, 1.0, EdgeSense::undirected,
                          EdgeRepeats::per_traversal) == 0.75);
  CHECK(aco::edge_deposit(path, {2, 0}, {1, 0}, 1.0) == 0.0);
  CHECK(aco::edge_deposit(path, {2, 0}, {1, 0}, 1.0, EdgeSense::undirected) == 0.25);
  CHECK(aco::ant_cycle_deposit(1.0, 4.0) == 0.25);
  const std::vector<Cell> one{{0, 0}};
  CHECK_THROWS_AS(aco::edge_deposit(one, {0, 0}, {1, 0}, 1.0), DomainError);
  CHECK_THROWS_AS(aco::ant_cycle_deposit(1.0, 0.0), DomainError);
}

TEST_CASE("shi2022.eq8 eq9: continuity and mid-point insertion", "[shi2022]") {
  CHECK(ga::continuity_delta(Cell{1, 0}, Cell{5, 1}) == 4);
  CHECK(ga::is_continuous(Cell{0, 0}, Cell{1, 1}));
  CHECK_FALSE(ga::is_continuous(Cell{3, 3}, Cell{3, 3}));
  using ga::MidNumber;
  using ga::MidRounding;
  CHECK(ga::insertion_cell(Cell{0, 0}, Cell{3, 5}) == Cell{1, 2});
  CHECK(ga::insertion_cell(Cell{0, 0}, Cell{3, 5}, MidRounding::ceil) == Cell{2, 3});
  CHECK(ga::insertion_cell(Cell{0, 0}, Cell{3, 5}, MidRounding::half_even) == Cell{2, 2});
  CHECK(ga::insertion_cell(Cell{0, 3}, Cell{5, 4}, MidRounding::half_even) == Cell{2, 4});
  CHECK(ga::insertion_number(Cell{0, 0}, Cell{3, 5}, 6, 6) == 13);
  CHECK(ga::insertion_number(Cell{0, 0}, Cell{3, 5}, 6, 6, MidRounding::floor,
                             MidNumber::printed_sum) == 3);
  // The printed x' + y' gives two different cells the same number.
  CHECK(ga::insertion_number(Cell{0, 0}, Cell{2, 0}, 6, 6, MidRounding::floor,
                             MidNumber::printed_sum) ==
        ga::insertion_number(Cell{0, 0}, Cell{0, 2}, 6, 6, MidRounding::floor,
                             MidNumber::printed_sum));
  CHECK_THROWS_AS(ga::insertion_number(Cell{6, 0}, Cell{0, 0}, 6, 6), DomainError);
  CHECK_THROWS_AS(ga::insertion_cell(Cell{-1, 0}, Cell{0, 0}), DomainError);
}

TEST_CASE("shi2022.eq10 eq11 eq14 eq15: length fitness, roulette probability, weighted fitness",
          "[shi2022]") {
  CHECK(ga::inverse_length(4.0) == 0.25);
  CHECK_THROWS_AS(ga::inverse_length(0.0), DomainError);
  CHECK_THROWS_AS(ga::inverse_length(INFINITY), DomainError);
  const std::vector<double> f{0.0, 1.0, 3.0};
  CHECK(equations::proportional_probabilities(f) == std::vector<double>{0.0, 0.25, 0.75});
  CHECK(ga::weighted_fitness(0.25, 2.0, 3.0) == 12.25);
  CHECK(ga::weighted_fitness(0.1, 0.2, 0.3, ga::FitnessWeights{1.0, 1.0, 1.0}) == (0.1 + 0.2) + 0.3);
  CHECK_THROWS_AS(ga::weighted_fitness(0.25, -1.0, 3.0), DomainError);
}

TEST_CASE("shi2022.eq13: the three readings with T = 100, rho(0) = 0.9, rho_min = 0.1", "[shi2022]") {
  using aco::RhoReading;
  double f = 0.9;
  double c = 0.9;
  double c_min = 1.0;
  for (std::int64_t t = 0; t < 100; ++t) {
    const double next = aco::adaptive_rho(f, t, 100, 0.1);
    CHECK(next <= f);
    CHECK(next >= 0.1);
    if (t == 5) CHECK(next == 0.1);   // the floor acts from rho(6) on
    if (t == 4) CHECK(next > 0.1);    // rho(5) ~ 0.125
    f = next;
    c = aco::adaptive_rho(c, t, 100, 0.1, RhoReading::condition);
    c_min = std::min(c_min, c);
    if (t == 0) CHECK(c > 0.9);  // condition: rho first increases
  }
  CHECK(c_min > 0.5 * std::exp(-1.0));  // condition: rho_min = 0.1 never acts
  // IACO*: no floor, rho collapses.
  double r = 0.9;
  for (std::int64_t t = 0; t < 100; ++t) r = aco::adaptive_rho(r, t, 100, 0.0);
  CHECK(r < 1e-50);
  CHECK(r > 0.0);
  CHECK_THROWS_AS(aco::adaptive_rho(0.5, 101, 100, 0.1), DomainError);
  CHECK_THROWS_AS(aco::adaptive_rho(1.0, 0, 100, 0.1), DomainError);
}

TEST_CASE("shi2022.eq16: the smoothness readings on the spec's example paths", "[shi2022]") {
  using ga::SmoothnessReading;
  const std::vector<Cell> A{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}};
  const std::vector<Cell> B{{0, 0}, {1, 0}, {2, 0}, {3, 1}, {4, 2}};
  const std::vector<Cell> C{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}};
  const std::vector<Cell> E{{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}};
  const double a = ga::smoothness_factor(A, SmoothnessReading::per_node);
  const double b = ga::smoothness_factor(B, SmoothnessReading::per_node);
  const double c = ga::smoothness_factor(C, SmoothnessReading::per_node);
  const double e = ga::smoothness_factor(E, SmoothnessReading::per_node);
  CHECK(a == 3.0);
  CHECK((a > b && b > c && c > e));  // per_node ranks fewer and gentler turns higher
  // The default, inverse_total_plus_one: 1 / (1 + total penalty); 1 without turns.
  CHECK(ga::smoothness_factor(A) == 1.0);
  CHECK(ga::smoothness_factor(B) == 1.0 / 6.0);
  CHECK(ga::smoothness_factor(C) == 1.0 / 101.0);
  CHECK(ga::smoothness_factor(E) == 1.0 / 301.0);
  CHECK(ga::smoothness_factor(std::vector<Cell>{{0, 0}, {1, 0}}) == 1.0);
  CHECK(ga::smoothness_factor(A, SmoothnessReading::per_turn) == 0.0);
  CHECK(ga::smoothness_factor(A, SmoothnessReading::angle_times_penalty) == 0.0);
  CHECK(ga::smoothness_factor(B, SmoothnessReading::angle_times_penalty) ==
        1.0 / (5.0 * std::atan2(1.0, 1.0)));
  CHECK_THROWS_AS(ga::smoothness_factor(A, SmoothnessReading::inverse_total), DomainError);
  CHECK(ga::smoothness_factor(B, SmoothnessReading::inverse_total) == 0.2);
  CHECK_THROWS_AS(ga::smoothness_factor(B, SmoothnessReading::per_node, ga::TurnPenalties{5, 0, 1000}),
                  DomainError);
}

TEST_CASE("shi2022.eq17: exact bands where the printed law of cosines rounds", "[shi2022]") {
  // The printed Eq. 17 on a straight diagonal run, in binary64: cos(theta) just below 1.
  const double a2 = 2.0;
  const double b2 = 2.0;
  const double c2 = 8.0;
  const double cos_theta = -((b2 + a2 - c2) / (2.0 * std::sqrt(b2) * std::sqrt(a2)));
  CHECK(cos_theta < 1.0);
  CHECK(std::acos(cos_theta) > 0.0);  // ~2.1e-8 rad: would land in the 0 < theta <= 45 band
  CHECK(ga::turn_band(Cell{0, 0}, Cell{1, 1}, Cell{2, 2}) == ga::TurnBand::straight);
  CHECK(metrics::turning_angle(Cell{0, 0}, Cell{1, 1}, Cell{2, 2}) == 0.0);
  CHECK(ga::turn_band(Cell{0, 0}, Cell{2, 0}, Cell{3, 1}) == ga::TurnBand::up_to_45);
  CHECK(ga::turn_band(Cell{0, 0}, Cell{1, 0}, Cell{1, 1}) == ga::TurnBand::up_to_90);
  CHECK(ga::turn_band(Cell{0, 0}, Cell{1, 0}, Cell{0, 0}) == ga::TurnBand::above_90);
  CHECK(metrics::turning_angle(Cell{0, 0}, Cell{1, 0}, Cell{0, 0}) == pi);
  CHECK_THROWS_AS(ga::turn_band(Cell{0, 0}, Cell{0, 0}, Cell{1, 1}), DomainError);
}

TEST_CASE("shi2022.eq18: safety readings on a map with an obstacle", "[shi2022]") {
  const grid::Grid g = grid::Grid::from_rows_top_first({".....", ".....", "..#..", ".....", "....."});
  // Row y = 1 runs below the obstacle (2,2): blocked-neighbour counts [0, 1, 1, 1, 0].
  const std::vector<Cell> row1{{0, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 1}};
  // Default inverse_total_plus_one: T = 0 + 1 + 1 + 1 over every node but the goal.
  CHECK(ga::safety_factor(g, row1) == 0.25);
  ga::SafetyOptions per_node;
  per_node.aggregate = ga::SafetyAggregate::per_node;
  CHECK(ga::safety_factor(g, row1, per_node) == 2.5);  // 1/1 + 1/2 + 1/2 + 1/2, as printed
  ga::SafetyOptions all = per_node;
  all.nodes = ga::SafetyNodes::all;
  CHECK(ga::safety_factor(g, row1, all) == 3.5);
  ga::SafetyOptions skip = per_node;
  skip.safe = ga::SafeNode::skip;
  CHECK(ga::safety_factor(g, row1, skip) == 3.0);
  ga::SafetyOptions mean;
  mean.aggregate = ga::SafetyAggregate::mean;
  CHECK(ga::safety_factor(g, row1, mean) == 0.625);  // 2.5 / 4
  // The default does not reward nodes: a detour over the obstacle (counts 0,1,1,1,1,1) scores
  // 1/6 < 1/4, while the printed per_node sum rewards it (1 + 5 * 1/2 = 3.5 > 2.5).
  const std::vector<Cell> detour{{0, 1}, {1, 2}, {1, 3}, {2, 3}, {3, 3}, {3, 2}, {4, 1}};
  CHECK(ga::safety_factor(g, detour) == 1.0 / 6.0);
  CHECK(ga::safety_factor(g, detour, per_node) == 3.5);
  // A path touching no obstacle scores 1 under the default, whatever its length.
  const std::vector<Cell> row0{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}};
  CHECK(ga::safety_factor(g, row0) == 1.0);
  const std::vector<Cell> outside{{4, 0}, {5, 0}};
  CHECK_THROWS_AS(ga::safety_factor(g, outside), DomainError);
  CHECK(ga::parse_safety_aggregate("per_node") == ga::SafetyAggregate::per_node);
  CHECK(ga::parse_safety_aggregate("mean") == ga::SafetyAggregate::mean);
  CHECK(ga::parse_safety_aggregate("inverse_total_plus_one") == ga::SafetyAggregate::inverse_total_plus_one);
  CHECK_THROWS_AS(ga::parse_safety_aggregate("sum"), UsageError);
}

TEST_CASE("shi2022.eq19 eq20: P_c and P_m at i = 0, M_g/2, M_g with M_g = 50", "[shi2022]") {
  CHECK(ga::adaptive_pc(0, 50) == 1.0);
  CHECK(ga::adaptive_pc(25, 50) == Approx(std::sqrt(3.0) / 2.0).epsilon(1e-15));
  CHECK(ga::adaptive_pc(50, 50) == Approx(std::sqrt(0.5)).epsilon(1e-15));
  CHECK(ga::adaptive_pc(0, 50, 0.8) == 0.8);
  const double pm0 = ga::adaptive_pm(0, 50, 0.3);
  CHECK(pm0 > 0.0);
  CHECK(pm0 < 1e-16);  // cos of the rounded pi/2, ~6.1e-17
  CHECK(ga::adaptive_pm(0, 50, 0.3, 1.0, ga::PmAtZero::exact_zero) == 0.0);
  CHECK(ga::adaptive_pm(5, 50, 0.3) < 0.3);
  CHECK(ga::adaptive_pm(6, 50, 0.3) == 0.3);  // the cap acts from i = 6
  CHECK(ga::adaptive_pm(25, 50, 0.3) == 0.3);
  CHECK(ga::adaptive_pm(50, 50, 0.3) == 0.3);
  CHECK(ga::adaptive_pm(50, 50, 0.3, 0.1) == 0.1);  // scaled: the cap never acts
  CHECK_THROWS_AS(ga::adaptive_pc(51, 50), DomainError);
  CHECK_THROWS_AS(ga::adaptive_pm(3, 50, 0.0), DomainError);
}

TEST_CASE("shi2022: reading names parse, unknown names are a UsageError", "[shi2022]") {
  CHECK(aco::parse_rho_reading("clamp") == aco::RhoReading::clamp);
  CHECK(aco::parse_edge_sense("undirected") == aco::EdgeSense::undirected);
  CHECK(aco::parse_edge_repeats("per_traversal") == aco::EdgeRepeats::per_traversal);
  CHECK(ga::parse_mid_rounding("half_even") == ga::MidRounding::half_even);
  CHECK(ga::parse_mid_number("printed_sum") == ga::MidNumber::printed_sum);
  CHECK(ga::parse_smoothness_reading("inverse_total") == ga::SmoothnessReading::inverse_total);
  CHECK(ga::parse_safety_count("indicator") == ga::SafetyCount::indicator);
  CHECK(ga::parse_safe_node("skip") == ga::SafeNode::skip);
  CHECK(ga::parse_safety_nodes("interior") == ga::SafetyNodes::interior);
  CHECK(ga::parse_pm_at_zero("exact_zero") == ga::PmAtZero::exact_zero);
  CHECK_THROWS_AS(aco::parse_rho_reading("product"), UsageError);
  CHECK_THROWS_AS(ga::parse_mid_rounding("round"), UsageError);
  CHECK_THROWS_AS(ga::parse_smoothness_reading(""), UsageError);
  const rules::Rule* eq19 = rules::registry().find("shi2022.eq19");
  REQUIRE(eq19 != nullptr);
  CHECK_THROWS_AS(eq19->eval({{"i", 1}, {"M_g", 50}, {"pc_reading", "initial"}}), UsageError);
}
