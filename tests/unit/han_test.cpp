// spec: han.params, han.eq1, han.eq2, han.eq3, han.eq4, han.eq5, han.eq6, han.eq7, han.eq8, han.eq9, han.eq10, han.eq11, han.eq12, han.eq13, han.eq14, han.eq15
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "pathref/core/error.hpp"
#include "pathref/equations/aco.hpp"
#include "pathref/equations/aco_adaptive.hpp"
#include "pathref/equations/corner.hpp"
#include "pathref/equations/han.hpp"
#include "pathref/equations/heuristics.hpp"
#include "pathref/equations/pseudo_random.hpp"
#include "pathref/equations/rls.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/rules/registry.hpp"

using namespace pathref;
using grid::Cell;

TEST_CASE("han.params: printed values and pathref's choices", "[han]") {
  const auto& p = han::params;
  CHECK(p.ants == 50);
  CHECK(p.max_cycles == 50);
  CHECK(p.alpha == 4.0);
  CHECK(p.beta == 8.0);
  CHECK(p.rho_initial == 0.7);
  CHECK(p.gamma == 1.0);
  CHECK(p.omega_i == 0.5);
  CHECK(p.epsilon == 1.0);
  CHECK(p.h == 1.0);
  CHECK(p.tau_min == 0.01);
  CHECK(p.Q == 1.0);
  CHECK(p.tau_initial == 1.0);
  CHECK(p.a == 1.0);
  CHECK(p.b == 5.0);
  CHECK(p.rho_min == 0.1);
  CHECK(p.lambda == 0.95);
  CHECK(p.rls_init_samples == 2);
  // The choices are inside the domains of the rules that use them.
  CHECK(aco::adaptive_q0(p.epsilon, 0, p.max_cycles) <= 1.0);
  CHECK_NOTHROW(corner::corner_heuristic(p.omega_i, 2));
}

TEST_CASE("han.params: the iaco-han planner's defaults are the printed values and the choices", "[han]") {
  // spec han.params: the planner runs with the printed alpha, beta, rho, ants and cycles and with
  // pathref's documented choices; the literal values here, so neither side can drift alone.
  const planners::Planner* planner = planners::find_planner("iaco-han");
  REQUIRE(planner != nullptr);
  const planners::Json& d = planner->defaults;
  CHECK(d.at("ants") == 50);
  CHECK(d.at("iterations") == 50);
  CHECK(d.at("alpha").get<double>() == 4.0);
  CHECK(d.at("beta").get<double>() == 8.0);
  CHECK(d.at("rho").get<double>() == 0.7);
  CHECK(d.at("gamma").get<double>() == 1.0);
  CHECK(d.at("omega_i").get<double>() == 0.5);
  CHECK(d.at("epsilon").get<double>() == 1.0);
  CHECK(d.at("h").get<double>() == 1.0);
  CHECK(d.at("Q").get<double>() == 1.0);
  CHECK(d.at("tau0").get<double>() == 1.0);
  CHECK(d.at("tau_min").get<double>() == 0.01);
  CHECK(d.at("a").get<double>() == 1.0);
  CHECK(d.at("b").get<double>() == 5.0);
  CHECK(d.at("rho_min").get<double>() == 0.1);
}

TEST_CASE("han.eq1: the rule is Shi's transition rule with the corner factor", "[han]") {
  const rules::Rule* rule = rules::registry().find("han.eq1");
  REQUIRE(rule != nullptr);
  // By hand (spec han.eq1, w_j = tau_j^alpha eta_j^beta omega_j^gamma, p_j = w_j / sum w), powers
  // of two so every product is exact: alpha = 4, beta = 8, gamma = 1,
  // w = (1 * 1 * 1, 2^-4 * 2^-8 * 2^-1, 16 * 1 * 1) = (1, 2^-13, 16), sum = 17 + 2^-13 (exact).
  const std::vector<double> tau{1.0, 0.5, 2.0};
  const std::vector<double> eta{1.0, 0.5, 1.0};
  const std::vector<double> omega{1.0, 0.5, 1.0};
  const double tiny = std::ldexp(1.0, -13);
  const double w[3] = {1.0, tiny, 16.0};
  const double sum = 17.0 + tiny;
  const rules::Json out = rule->eval(
      {{"tau", tau}, {"eta", eta}, {"omega", omega}, {"alpha", 4}, {"beta", 8}, {"gamma", 1}});
  for (std::size_t r = 0; r < 3; ++r) {
    CHECK(out.at("weights").at(r).get<double>() == w[r]);
    CHECK(out.at("p").at(r).get<double>() == Approx(w[r] / sum).epsilon(1e-15));
  }
  // gamma = 0 is Shi's Eq. 2: the middle weight loses its omega = 1/2, 2^-12.
  const rules::Json shi = rule->eval(
      {{"tau", tau}, {"eta", eta}, {"omega", omega}, {"alpha", 4}, {"beta", 8}, {"gamma", 0}});
  CHECK(shi.at("weights").at(0).get<double>() == 1.0);
  CHECK(shi.at("weights").at(1).get<double>() == std::ldexp(1.0, -12));
  CHECK(shi.at("weights").at(2).get<double>() == 16.0);
  CHECK_THROWS_AS(rule->eval({{"tau", std::vector<double>{}}, {"eta", std::vector<double>{}},
                              {"omega", std::vector<double>{}}, {"alpha", 4}, {"beta", 8},
                              {"gamma", 1}}),
                  DomainError);
}

TEST_CASE("han.eq2 eq3: turning cost and corner heuristic of the 8 directions", "[han]") {
  using corner::At90;
  using corner::OmegaForm;
  const Cell prev{0, 1}, cur{1, 1};
  // next cells turning by 0, 45, 90, 135, 180 degrees (heading change).
  const std::vector<Cell> next{{2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  const int multiply_two[5] = {2, 2, 2, 1, 1};
  const int multiply_one[5] = {2, 2, 1, 1, 1};
  const int divide_two[5] = {1, 1, 2, 2, 2};
  const int divide_one[5] = {1, 1, 1, 2, 2};
  for (std::size_t k = 0; k < 5; ++k) {
    CHECK(corner::turning_cost(prev, cur, next[k]) == multiply_two[k]);
    CHECK(corner::turning_cost(prev, cur, next[k], OmegaForm::multiply, At90::one) == multiply_one[k]);
    CHECK(corner::turning_cost(prev, cur, next[k], OmegaForm::divide, At90::two) == divide_two[k]);
    CHECK(corner::turning_cost(prev, cur, next[k], OmegaForm::divide, At90::one) == divide_one[k]);
  }
  // First move: straight on under either reading.
  CHECK(corner::turning_cost(std::nullopt, cur, Cell{2, 2}) == 2);
  CHECK(corner::turning_cost(std::nullopt, cur, Cell{2, 2}, OmegaForm::divide) == 1);
  // Eq. 2 values.
  CHECK(corner::corner_heuristic(0.5, 2) == 1.0);
  CHECK(corner::corner_heuristic(0.5, 1) == 0.5);
  CHECK(corner::corner_heuristic(0.5, 2, OmegaForm::divide) == 0.25);
  // corner_factors composes both, in candidate order; multiply+two and divide+one are the same
  // behaviour up to the factor 2 on every candidate.
  const auto a = corner::corner_factors(prev, cur, next, 0.5);
  const auto b = corner::corner_factors(prev, cur, next, 0.5, OmegaForm::divide, At90::one);
  REQUIRE(a.size() == 5);
  for (std::size_t k = 0; k < 5; ++k) {
    CHECK(a[k] == (multiply_two[k] == 2 ? 1.0 : 0.5));
    CHECK(a[k] == 2.0 * b[k]);
  }
  CHECK_THROWS_AS(corner::turning_cost(prev, cur, cur), DomainError);
  CHECK_THROWS_AS(corner::turning_cost(cur, cur, next[0]), DomainError);
  CHECK_THROWS_AS(corner::corner_heuristic(1.0, 2), DomainError);
  CHECK_THROWS_AS(corner::corner_heuristic(0.5, 3), DomainError);
  CHECK_THROWS_AS(corner::parse_omega_form("power"), UsageError);
}

TEST_CASE("han.eq4: argmax with lowest-index ties, roulette otherwise", "[han]") {
  const std::vector<double> w{1.0, 3.0, 3.0, 2.0};
  CHECK(aco::argmax_weight(w) == 1);
  auto c = aco::pseudo_random_choice(w, 0.5, 0.5, 0.99);
  CHECK(c.index == 1);
  CHECK(c.mode == aco::ChoiceMode::argmax);
  c = aco::pseudo_random_choice(w, 0.75, 0.5, 0.5);
  CHECK(c.index == 2);  // S = 9, target 4.5, C = 1, 4, 7
  CHECK(c.mode == aco::ChoiceMode::roulette);
  const std::vector<double> z{0.0, 0.0};
  CHECK_THROWS_AS(aco::argmax_weight(z), DomainError);
  CHECK_THROWS_AS(aco::pseudo_random_choice(w, 1.0, 0.5, 0.1), DomainError);
  CHECK_THROWS_AS(aco::pseudo_random_choice(w, 0.1, 1.5, 0.1), DomainError);
}

TEST_CASE("han.eq5: q0 falls from fl(0.2 + 0.7) to 0.2", "[han]") {
  CHECK(aco::adaptive_q0(1.0, 0, 50) == 0.2 + 0.7);
  CHECK(aco::adaptive_q0(1.0, 0, 50) == 0.8999999999999999);
  CHECK(aco::adaptive_q0(1.0, 50, 50) == 0.2);
  CHECK(aco::adaptive_q0(0.5, 50, 50) == 0.1);
  CHECK(aco::adaptive_q0(1.0, 25, 50) == 0.2 + 0.5 * 0.7);
  CHECK_THROWS_AS(aco::adaptive_q0(1.0, 51, 50), DomainError);
  CHECK_THROWS_AS(aco::adaptive_q0(0.0, 0, 50), DomainError);
  CHECK_THROWS_AS(aco::adaptive_q0(1.25, 0, 50), DomainError);
}

TEST_CASE("han.eq6: elite bonus on the best path, floor tau_min", "[han]") {
  CHECK(aco::elite_bonus(1.0, 12.0, 8.0) == 0.5);
  CHECK(aco::elite_bonus(1.0, 8.0, 10.0) == -0.2);
  CHECK(aco::elite_bonus(0.0, 8.0, 10.0) == 0.0);
  CHECK(aco::pheromone_update_elite(1.0, 0.5, 0.25, 0.5, 0.01) == 1.25);
  CHECK(aco::pheromone_update_elite(1.0, 0.5, 0.25, 0.0, 0.01) ==
        aco::pheromone_update(1.0, 0.5, 0.25));
  CHECK(aco::pheromone_update_elite(0.0625, 0.5, 0.0, -0.5, 0.01) == 0.01);
  CHECK_THROWS_AS(aco::pheromone_update_elite(1.0, 0.5, 0.25, 0.5, 0.0), DomainError);
  CHECK_THROWS_AS(aco::elite_bonus(1.0, 8.0, 0.0), DomainError);
  CHECK_THROWS_AS(aco::elite_bonus(-1.0, 8.0, 10.0), DomainError);
}

TEST_CASE("han.eq7: stepped rho with closed upper boundaries and floor", "[han]") {
  CHECK(aco::stepped_rho(0.5, 20.0, 10.0, 1.0, 5.0, 0.1) == 0.9 * 0.5);
  CHECK(aco::stepped_rho(0.5, 15.0, 10.0, 1.0, 5.0, 0.1) == 0.8 * 0.5);  // d = b
  CHECK(aco::stepped_rho(0.5, 11.0, 10.0, 1.0, 5.0, 0.1) == 0.7 * 0.5);  // d = a
  CHECK(aco::stepped_rho(0.125, 10.0, 10.0, 1.0, 5.0, 0.1) == 0.1);
  CHECK_THROWS_AS(aco::stepped_rho(0.5, 8.0, 10.0, 1.0, 5.0, 0.1), DomainError);
  CHECK(aco::stepped_rho(0.5, 8.0, 10.0, 1.0, 5.0, 0.1, aco::SpreadReference::history_best) ==
        0.7 * 0.5);
  CHECK_THROWS_AS(aco::stepped_rho(0.5, 20.0, 10.0, 5.0, 5.0, 0.1), DomainError);
  CHECK_THROWS_AS(aco::stepped_rho(0.5, 20.0, 10.0, 1.0, 5.0, 1.0), DomainError);
  // Fifty stagnating iterations from rho(0) = 0.7 end on the floor.
  double rho = han::params.rho_initial;
  for (int t = 0; t < 50; ++t) rho = aco::stepped_rho(rho, 10.0, 10.0, 1.0, 5.0, 0.1);
  CHECK(rho == 0.1);
}

TEST_CASE("han.eq8: the Chebyshev distance written out, admissible under every corner policy",
          "[han]") {
  const rules::Rule* rule = rules::registry().find("han.eq8");
  REQUIRE(rule != nullptr);
  for (std::int64_t x = -3; x <= 3; ++x)
    for (std::int64_t y = -3; y <= 3; ++y) {
      const Cell n{x, y}, g{1, -2};
      // Eq. 8 written out: h = max(|x_n - x_g|, |y_n - y_g|); the octile form
      // (M - m) + sqrt2 * m in the order spec/search.md fixes (M, m the larger and smaller delta).
      const std::int64_t dx = x > g.x ? x - g.x : g.x - x;
      const std::int64_t dy = y > g.y ? y - g.y : g.y - y;
      const std::int64_t big = dx > dy ? dx : dy, small = dx > dy ? dy : dx;
      CHECK(rule->eval({{"n", {n.x, n.y}}, {"g", {g.x, g.y}}}).at("h").get<double>() ==
            static_cast<double>(big));
      CHECK(rule->eval({{"n", {n.x, n.y}}, {"g", {g.x, g.y}}, {"h_form", "octile"}}).at("h").get<double>() ==
            static_cast<double>(big - small) + (1.4142135623730951 * static_cast<double>(small)));
    }
  for (const auto policy : {grid::CornerPolicy::never, grid::CornerPolicy::strict,
                            grid::CornerPolicy::one, grid::CornerPolicy::always}) {
    CHECK(heuristics::admissible(heuristics::Heuristic::chebyshev, policy));
    CHECK(heuristics::consistent(heuristics::Heuristic::chebyshev, policy));
  }
}

TEST_CASE("han.eq9 eq10 eq11: motion model and regressor matrix", "[han]") {
  const rls::Position p = rls::position(rls::LinearMotion{2.0, 1.0, -0.5, 3.0}, 4.0);
  CHECK(p.x == 9.0);
  CHECK(p.y == 1.0);
  const std::vector<double> t{0.0, 1.0, 2.0, 3.0};
  const auto X = rls::stacked(t, Eigen::Vector2d(2.0, 1.0));
  CHECK(X == std::vector<double>{1.0, 3.0, 5.0, 7.0});
  const auto T = rls::regressor_matrix(t);
  REQUIRE(T.rows() == 4);
  for (Eigen::Index l = 0; l < 4; ++l) {
    CHECK(T(l, 0) == t[static_cast<std::size_t>(l)]);
    CHECK(T(l, 1) == 1.0);
  }
  // Eq. 10 is the matrix product T_n A_m.
  const Eigen::VectorXd prod = T * Eigen::Vector2d(2.0, 1.0);
  for (Eigen::Index l = 0; l < 4; ++l) CHECK(prod(l) == X[static_cast<std::size_t>(l)]);
  CHECK_THROWS_AS(rls::regressor_matrix(std::vector<double>{}), DomainError);
}

TEST_CASE("han.eq12 eq13 eq14: residuals and the weighted cost", "[han]") {
  const std::vector<double> t{0.0, 1.0, 2.0};
  const std::vector<double> x{1.0, 3.5, 5.0};
  CHECK(rls::residuals(t, x, Eigen::Vector2d(2.0, 1.0)) == std::vector<double>{0.0, 0.5, 0.0});
  CHECK(rls::weighted_cost(std::vector<double>{1.0, 2.0, 3.0}, 0.5) == 11.25);
  CHECK(rls::weighted_cost(std::vector<double>{1.0, 2.0, 3.0}, 1.0) == 14.0);
  CHECK_THROWS_AS(rls::weighted_cost(std::vector<double>{1.0}, 0.0), DomainError);
  CHECK_THROWS_AS(rls::residuals(t, std::vector<double>{1.0}, Eigen::Vector2d(2.0, 1.0)),
                  DomainError);
}

TEST_CASE("han.eq15: recursive least squares, hand example and domain", "[han]") {
  // Init on t = 0, 1 (lambda = 1): P = [[2, -1], [-1, 1]], A = [2, 1]; one step at t = 2 with
  // g = [3, -1], 1 + s = 6, K = [0.5, -1/6]; the sample is on the line, so A stays [2, 1].
  const std::vector<double> t{0.0, 1.0, 2.0};
  const std::vector<double> x{1.0, 3.0, 5.0};
  const std::vector<double> y{2.0, 2.0, 2.0};
  const auto init = rls::rls_init(std::span(t).first(2), std::span(x).first(2),
                                  std::span(y).first(2), 1.0);
  CHECK(init.P(0, 0) == 2.0);
  CHECK(init.P(0, 1) == -1.0);
  CHECK(init.P(1, 1) == 1.0);
  CHECK(init.A == Eigen::Vector2d(2.0, 1.0));
  const Eigen::Matrix2d Ps = rls::scaled_covariance(init.P, 1.0);
  const Eigen::Vector2d K = rls::rls_gain(Ps, 2.0);
  CHECK(K(0) == 0.5);
  CHECK(K(1) == -1.0 / 6.0);
  const auto e = rls::rls_estimate(t, x, y, 1.0);
  CHECK(e.A == Eigen::Vector2d(2.0, 1.0));
  CHECK(e.B == Eigen::Vector2d(0.0, 2.0));
  CHECK(e.P(0, 0) == 0.5);
  CHECK(e.P(0, 1) == -0.5);
  // Eq. 15 as printed: P / lambda.
  CHECK(rls::scaled_covariance(init.P, 0.5)(0, 0) == 4.0);
  const std::vector<double> bad_t{0.0, 2.0, 1.0};
  CHECK_THROWS_AS(rls::rls_estimate(bad_t, x, y, 1.0), DomainError);
  CHECK_THROWS_AS(rls::rls_estimate(t, x, y, 0.0), DomainError);
  CHECK_THROWS_AS(rls::rls_estimate(t, x, y, 1.0, 4), DomainError);
  CHECK_THROWS_AS(rls::rls_estimate(t, x, y, 1.0, 1), DomainError);
  CHECK_THROWS_AS(rls::parse_init_weights("printed"), UsageError);
}
