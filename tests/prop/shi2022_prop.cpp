// spec: shi2022.eq2, shi2022.eq3, shi2022.eq5, shi2022.eq8, shi2022.eq9, shi2022.eq10, shi2022.eq11, shi2022.eq12, shi2022.eq13, shi2022.eq15, shi2022.eq16, shi2022.eq17, shi2022.eq18, shi2022.eq19, shi2022.eq20
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/aco.hpp"
#include "pathref/equations/ga.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/equations/proportional.hpp"
#include "support/generators.hpp"

using namespace pathref;
using grid::Cell;

namespace {

/// A cell with coordinates in [lo, hi).
rc::Gen<Cell> gen_cell(std::int64_t lo, std::int64_t hi) {
  return rc::gen::map(rc::gen::pair(rc::gen::inRange(lo, hi), rc::gen::inRange(lo, hi)),
                      [](const std::pair<std::int64_t, std::int64_t>& p) { return Cell{p.first, p.second}; });
}

/// A 8-connected walk of 1..max_n nodes from a cell in [0, 20)^2 (no consecutive repeats;
/// revisits and reversals allowed).
rc::Gen<std::vector<Cell>> gen_walk(int max_n) {
  return rc::gen::exec([max_n] {
    const auto n = *rc::gen::inRange(1, max_n + 1);
    std::vector<Cell> p{*gen_cell(0, 20)};
    static constexpr std::int64_t dx[8] = {-1, 0, 1, -1, 1, -1, 0, 1};
    static constexpr std::int64_t dy[8] = {-1, -1, -1, 0, 0, 1, 1, 1};
    for (int k = 1; k < n; ++k) {
      const auto d = static_cast<std::size_t>(*rc::gen::inRange(0, 8));
      p.push_back(Cell{p.back().x + dx[d], p.back().y + dy[d]});
    }
    return p;
  });
}

/// Non-negative weights that are multiples of 1/8 in [0, 4], or a wide-range positive double.
rc::Gen<double> gen_weight() {
  return rc::gen::oneOf(
      rc::gen::map(rc::gen::inRange(0, 33), [](int k) { return static_cast<double>(k) / 8.0; }),
      rc::gen::map(rc::gen::inRange(-300, 300), [](int e) { return std::ldexp(1.3, e); }));
}

/// min_n..max_n-1 cells of g (any cells, not necessarily adjacent), no two consecutive equal:
/// each next cell is drawn among the cell_count - 1 others, so no rejection loop is needed
/// (a rejection loop never ends once RapidCheck shrinks every draw to the same value).
/// Pre: g.cell_count() >= 2.
rc::Gen<std::vector<Cell>> gen_nodes_in(const grid::Grid& g, int min_n, int max_n) {
  return rc::gen::exec([g, min_n, max_n] {
    const std::int64_t cells = g.cell_count();
    const auto n = *rc::gen::inRange(min_n, max_n);
    std::int64_t i = *rc::gen::inRange<std::int64_t>(0, cells);
    std::vector<Cell> p{g.cell(i)};
    for (int k = 1; k < n; ++k) {
      i = (i + 1 + *rc::gen::inRange<std::int64_t>(0, cells - 1)) % cells;
      p.push_back(g.cell(i));
    }
    return p;
  });
}

}  // namespace

TEST_CASE("prop_transition_weights_into_is_the_formula_bit_for_bit", "[shi2022][prop]") {
  // Oracle: pow(tau, alpha) * pow(eta, beta) [* pow(omega, gamma)] written out here, against the
  // precomputed-power form the colonies use (alpha = 1 skips pow there, never here).
  rc::prop("transition_weights_into(tau, pow(eta, beta)) == the formula", [] {
    const auto n = *rc::gen::inRange<std::size_t>(1, 9);
    const auto tau = *rc::gen::container<std::vector<double>>(n, gen_weight());
    const auto eta = *rc::gen::container<std::vector<double>>(n, gen_weight());
    const auto omega = *rc::gen::container<std::vector<double>>(n, gen_weight());
    const double alpha = *rc::gen::element(0.0, 1.0, 2.0, 4.0, 0.5);
    const double beta = *rc::gen::element(0.0, 1.0, 7.0, 8.0);
    const bool corner = *rc::gen::arbitrary<bool>();
    const double gamma = *rc::gen::element(0.0, 1.0, 2.0);
    std::vector<double> want(n);
    bool finite = true;
    for (std::size_t j = 0; j < n; ++j) {
      want[j] = std::pow(tau[j], alpha) * std::pow(eta[j], beta);
      if (corner) want[j] = want[j] * std::pow(omega[j], gamma);
      finite = finite && std::isfinite(want[j]);
    }
    RC_PRE(finite);
    std::vector<double> eta_pow(n);
    for (std::size_t j = 0; j < n; ++j) eta_pow[j] = std::pow(eta[j], beta);
    std::vector<double> got{42.0};  // a stale scratch buffer is overwritten, not appended to
    const std::optional<aco::CornerFactor> cf =
        corner ? std::optional<aco::CornerFactor>(aco::CornerFactor{omega, gamma}) : std::nullopt;
    aco::transition_weights_into(tau, eta_pow, alpha, cf, got);
    RC_ASSERT(got == want);
    RC_ASSERT(aco::transition_weights(tau, eta, alpha, beta, cf) == want);
  });
}

TEST_CASE("prop_transition_probabilities_non_negative_and_sum_to_one", "[shi2022][prop]") {
  rc::prop("p_r >= 0 and |sum p - 1| <= 2 n 2^-53", [] {
    const auto n = *rc::gen::inRange<std::size_t>(1, 9);
    const auto tau = *rc::gen::container<std::vector<double>>(n, gen_weight());
    const auto eta = *rc::gen::container<std::vector<double>>(
        n, rc::gen::map(rc::gen::inRange(1, 64), [](int k) { return 1.0 / static_cast<double>(k); }));
    const double alpha = *rc::gen::element(0.0, 1.0, 2.0);
    const double beta = *rc::gen::element(0.0, 1.0, 7.0);
    double total = 0.0;
    for (double t : tau) total += t;
    RC_PRE(total > 0.0 || alpha == 0.0);
    std::vector<double> w;
    try {
      w = aco::transition_weights(tau, eta, alpha, beta);
    } catch (const DomainError&) {
      RC_DISCARD("weight overflow");
    }
    double wsum = 0.0;
    for (double x : w) wsum += x;
    RC_PRE(wsum > 0.0 && std::isfinite(wsum) && wsum > 1e-290);  // no underflow in the quotients
    const auto p = aco::transition_probabilities(tau, eta, alpha, beta);
    RC_ASSERT(p.size() == n);
    double s = 0.0;
    for (std::size_t r = 0; r < n; ++r) {
      RC_ASSERT(p[r] >= 0.0);
      RC_ASSERT(p[r] <= 1.0);
      if (w[r] == 0.0) RC_ASSERT(p[r] == 0.0);
      s += p[r];
    }
    RC_ASSERT(std::fabs(s - 1.0) <= 2.0 * static_cast<double>(n) * 0x1p-53);
  });
}

TEST_CASE("prop_selection_probabilities_follow_fitness_order", "[shi2022][prop]") {
  rc::prop("F_a <= F_b implies p_a <= p_b (Eq. 11)", [] {
    const auto f = *rc::gen::nonEmpty(rc::gen::container<std::vector<double>>(gen_weight()));
    double total = 0.0;
    for (double x : f) total += x;
    RC_PRE(total > 0.0 && std::isfinite(total));
    const auto p = equations::proportional_probabilities(f);
    for (std::size_t a = 0; a < f.size(); ++a)
      for (std::size_t b = 0; b < f.size(); ++b)
        if (f[a] <= f[b]) RC_ASSERT(p[a] <= p[b]);
  });
}

TEST_CASE("prop_goal_directed_eta_at_most_inverse_distance", "[shi2022][prop]") {
  rc::prop("eta(12) <= eta(3), equal iff j == E", [] {
    const Cell i = *gen_cell(-50, 50);
    const Cell j = *gen_cell(-50, 50);
    const Cell e = *gen_cell(-50, 50);
    RC_PRE(!(i == j));
    const double e12 = aco::eta_goal_directed(i, j, e);
    const double e3 = aco::eta_inverse_distance(i, j);
    RC_ASSERT(e12 > 0.0);
    RC_ASSERT(e12 <= e3);
    if (j == e) RC_ASSERT(e12 == e3);
  });
}

TEST_CASE("prop_pheromone_update_keeps_tau_positive_and_is_pure_evaporation_without_deposit",
          "[shi2022][prop]") {
  rc::prop("tau > 0, rho in (0,1): tau' > 0; delta = 0: tau' == (1 - rho) * tau", [] {
    const double tau = std::ldexp(1.0 + *rc::gen::inRange(0, 1024) / 1024.0, *rc::gen::inRange(-900, 900));
    const double rho = *rc::gen::inRange(1, 1024) / 1024.0;
    const double delta = *rc::gen::element(0.0, 0.25, 1.0, 3.5);
    const double next = aco::pheromone_update(tau, rho, delta);
    RC_ASSERT(next > 0.0);
    RC_ASSERT(next >= (1.0 - rho) * tau);
    RC_ASSERT(aco::pheromone_update(tau, rho, 0.0) == (1.0 - rho) * tau);
  });
}

TEST_CASE("prop_adaptive_rho_non_increasing_and_never_below_rho_min", "[shi2022][prop]") {
  rc::prop("factor reading: rho_min <= rho(t+1) <= rho(t) along a whole run", [] {
    const auto T = *rc::gen::inRange<std::int64_t>(1, 500);
    const double rho_min = *rc::gen::inRange(0, 100) / 128.0;
    double rho = *rc::gen::inRange(1, 1024) / 1024.0;
    RC_PRE(rho >= rho_min);
    for (std::int64_t t = 0; t < T; ++t) {
      const double next = aco::adaptive_rho(rho, t, T, rho_min);
      RC_ASSERT(next <= rho);
      RC_ASSERT(next >= rho_min);
      RC_ASSERT(next < 1.0);
      if (next == 0.0) break;  // rho_min = 0 can underflow to 0 after many steps
      rho = next;
    }
  });
}

TEST_CASE("prop_pc_in_unit_interval_and_decreasing", "[shi2022][prop]") {
  rc::prop("0 < P_c <= 1, strictly decreasing in i (M_g <= 10^4)", [] {
    const auto mg = *rc::gen::inRange<std::int64_t>(1, 10001);
    const auto i = *rc::gen::inRange<std::int64_t>(0, mg);
    const double a = ga::adaptive_pc(i, mg);
    const double b = ga::adaptive_pc(i + 1, mg);
    RC_ASSERT(a > 0.0);
    RC_ASSERT(a <= 1.0);
    RC_ASSERT(b < a);
    RC_ASSERT(b >= std::cos(std::numbers::pi / 4.0) - 1e-15);
  });
}

TEST_CASE("prop_pm_at_most_pm_max_and_non_decreasing", "[shi2022][prop]") {
  rc::prop("0 <= P_m <= P_m_max, non-decreasing in i", [] {
    const auto mg = *rc::gen::inRange<std::int64_t>(1, 10001);
    const auto i = *rc::gen::inRange<std::int64_t>(0, mg);
    const double cap = *rc::gen::inRange(1, 1025) / 1024.0;
    const auto at_zero = *rc::gen::element(ga::PmAtZero::binary64, ga::PmAtZero::exact_zero);
    const double a = ga::adaptive_pm(i, mg, cap, 1.0, at_zero);
    const double b = ga::adaptive_pm(i + 1, mg, cap, 1.0, at_zero);
    RC_ASSERT(a >= 0.0);
    RC_ASSERT(a <= cap);
    RC_ASSERT(b >= a);
  });
}

TEST_CASE("prop_continuity_exactly_for_8_neighbours", "[shi2022][prop]") {
  rc::prop("Delta == 1 iff b is one of the 8 neighbours of a", [] {
    const Cell a = *gen_cell(-20, 20);
    const Cell b = *gen_cell(-20, 20);
    const bool neighbour = !(a == b) && std::llabs(a.x - b.x) <= 1 && std::llabs(a.y - b.y) <= 1;
    RC_ASSERT(ga::is_continuous(a, b) == neighbour);
    RC_ASSERT((ga::continuity_delta(a, b) == 0) == (a == b));
  });
}

TEST_CASE("prop_insertion_in_bounding_box", "[shi2022][prop]") {
  rc::prop("mid-point in the bounding box; differs from both ends when Delta >= 2", [] {
    const Cell a = *gen_cell(0, 40);
    const Cell b = *gen_cell(0, 40);
    const auto rounding =
        *rc::gen::element(ga::MidRounding::floor, ga::MidRounding::ceil, ga::MidRounding::half_even);
    const Cell m = ga::insertion_cell(a, b, rounding);
    RC_ASSERT(m.x >= std::min(a.x, b.x));
    RC_ASSERT(m.x <= std::max(a.x, b.x));
    RC_ASSERT(m.y >= std::min(a.y, b.y));
    RC_ASSERT(m.y <= std::max(a.y, b.y));
    if (ga::continuity_delta(a, b) >= 2) {
      RC_ASSERT(!(m == a));
      RC_ASSERT(!(m == b));
    }
    const std::int64_t n = ga::insertion_number(a, b, 40, 40, rounding);
    RC_ASSERT(grid::index_cell(n, 40, 40) == m);
  });
}

TEST_CASE("prop_fit1_is_inverse_length", "[shi2022][prop]") {
  rc::prop("fit_1 == 1.0 / path_length, exactly", [] {
    const auto path = *gen_walk(30);
    RC_PRE(path.size() >= 2);
    const double L = metrics::path_length(path);
    RC_ASSERT(ga::inverse_length(L) == 1.0 / L);
    RC_ASSERT(ga::inverse_length(L) > 0.0);
  });
}

TEST_CASE("prop_fitness_factors_positive", "[shi2022][prop]") {
  rc::prop("default readings: fit_1, fit_2 (n >= 3), fit_3 (n >= 2) > 0; fit > 0", [] {
    const grid::Grid g = testing::random_grid(*rc::gen::arbitrary<std::uint32_t>(),
                                              *rc::gen::inRange(1, 11), *rc::gen::inRange(2, 11), 0.5);
    const auto path = *gen_nodes_in(g, 2, 12);
    const double f1 = ga::inverse_length(metrics::path_length(path));
    const double f2n = ga::smoothness_factor(path, ga::SmoothnessReading::per_node);
    const double f2 = ga::smoothness_factor(path);  // inverse_total_plus_one
    const double f3 = ga::safety_factor(g, path);
    RC_ASSERT(f1 > 0.0);
    if (path.size() >= 3) RC_ASSERT(f2n > 0.0);
    RC_ASSERT(f2n <= static_cast<double>(path.size() - 2));
    RC_ASSERT(f2 > 0.0);
    RC_ASSERT(f2 <= 1.0);
    RC_ASSERT(f3 > 0.0);
    RC_ASSERT(f3 <= 1.0);  // inverse_total_plus_one
    ga::SafetyOptions per_node;
    per_node.aggregate = ga::SafetyAggregate::per_node;
    const double f3n = ga::safety_factor(g, path, per_node);
    RC_ASSERT(f3n > 0.0);
    RC_ASSERT(f3n <= static_cast<double>(path.size() - 1));
    RC_ASSERT(ga::weighted_fitness(f1, f2, f3) > 0.0);
  });
}

TEST_CASE("prop_turn_band_agrees_with_turning_angle", "[shi2022][prop]") {
  rc::prop("the exact band is the band of atan2's theta against 45 and 90 degrees", [] {
    const Cell a = *gen_cell(-8, 8);
    const Cell b = *gen_cell(-8, 8);
    const Cell c = *gen_cell(-8, 8);
    RC_PRE(!(a == b) && !(b == c));
    const double th = metrics::turning_angle(a, b, c);
    const ga::TurnBand band = ga::turn_band(a, b, c);
    const double q = std::numbers::pi / 4.0;
    const double h = std::numbers::pi / 2.0;
    // atan2 is exact at 0, pi/4 (|y| == x), pi/2 (x == 0) and pi, so the comparison is exact.
    switch (band) {
      case ga::TurnBand::straight:
        RC_ASSERT(th == 0.0);
        break;
      case ga::TurnBand::up_to_45:
        RC_ASSERT(th > 0.0);
        RC_ASSERT(th <= q);
        break;
      case ga::TurnBand::up_to_90:
        RC_ASSERT(th > q);
        RC_ASSERT(th <= h);
        break;
      case ga::TurnBand::above_90:
        RC_ASSERT(th > h);
        RC_ASSERT(th <= std::numbers::pi);
        break;
    }
  });
}

TEST_CASE("prop_smoothness_inverse_total_plus_one_orders_by_total_penalty", "[shi2022][prop]") {
  rc::prop("1/(1 + T): 1 iff turn-free; else 1/(1 + 1/inverse_total) up to rounding, < 1", [] {
    const auto path = *gen_walk(25);
    const double f2 = ga::smoothness_factor(path);
    RC_ASSERT(f2 > 0.0);
    RC_ASSERT(f2 <= 1.0);
    if (metrics::turn_count(path) == 0) {
      RC_ASSERT(f2 == 1.0);
    } else {
      const double total = 1.0 / ga::smoothness_factor(path, ga::SmoothnessReading::inverse_total);
      RC_ASSERT(f2 < 1.0);
      RC_ASSERT(std::abs(f2 - 1.0 / (1.0 + total)) <= 1e-12 * f2);
    }
  });
}

TEST_CASE("prop_smoothness_per_node_each_term_in_unit_interval", "[shi2022][prop]") {
  rc::prop("per_node: 0 <= fit_2 <= n - 2; a straight walk scores exactly n - 2", [] {
    const auto path = *gen_walk(25);
    const double f2 = ga::smoothness_factor(path, ga::SmoothnessReading::per_node);
    const double interior = path.size() >= 2 ? static_cast<double>(path.size() - 2) : 0.0;
    RC_ASSERT(f2 >= 0.0);
    RC_ASSERT(f2 <= interior);
    if (metrics::turn_count(path) == 0) RC_ASSERT(f2 == interior);
    else RC_ASSERT(f2 < interior);
  });
}

TEST_CASE("prop_safety_never_increases_with_an_extra_obstacle", "[shi2022][prop]") {
  rc::prop("blocking one more cell off the path never raises fit_3 (defaults)", [] {
    grid::Grid g = testing::random_grid(*rc::gen::arbitrary<std::uint32_t>(), *rc::gen::inRange(2, 9),
                                        *rc::gen::inRange(2, 9), 0.3);
    const auto path = *gen_nodes_in(g, 2, 8);
    const Cell extra{*rc::gen::inRange<std::int64_t>(0, g.width()),
                     *rc::gen::inRange<std::int64_t>(0, g.height())};
    RC_PRE(std::find(path.begin(), path.end(), extra) == path.end());
    const double before = ga::safety_factor(g, path);
    g.set_blocked(extra, true);
    RC_ASSERT(ga::safety_factor(g, path) <= before);
  });
}

namespace {
/// Blocked 8-neighbours of c counted here from Grid::free (outside cells free): the oracle for
/// Eq. 18, independent of metrics::safety_counts.
std::int64_t blocked_around(const grid::Grid& g, Cell c) {
  std::int64_t n = 0;
  for (std::int64_t dy = -1; dy <= 1; ++dy)
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      const Cell q{c.x + dx, c.y + dy};
      if ((dx != 0 || dy != 0) && g.in_bounds(q) && !g.free(q)) ++n;
    }
  return n;
}
}  // namespace

TEST_CASE("prop_safety_default_is_one_over_one_plus_the_total_hazard", "[shi2022][prop]") {
  rc::prop("default fit_3 == 1 / (1 + blocked neighbours of every node but the goal); mean == per_node / (n - 1)",
           [] {
             const grid::Grid g = testing::random_grid(*rc::gen::arbitrary<std::uint32_t>(),
                                                       *rc::gen::inRange(2, 9), *rc::gen::inRange(2, 9), 0.4);
             const auto path = *gen_nodes_in(g, 2, 10);
             std::int64_t total = 0;
             double sum = 0.0;
             for (std::size_t k = 0; k + 1 < path.size(); ++k) {
               total += blocked_around(g, path[k]);
               sum += 1.0 / static_cast<double>(1 + blocked_around(g, path[k]));
             }
             RC_ASSERT(ga::safety_factor(g, path) == 1.0 / static_cast<double>(1 + total));
             RC_ASSERT((ga::safety_factor(g, path) == 1.0) == (total == 0));
             ga::SafetyOptions o;
             o.aggregate = ga::SafetyAggregate::per_node;
             RC_ASSERT(ga::safety_factor(g, path, o) == sum);
             o.aggregate = ga::SafetyAggregate::mean;
             const double mean = ga::safety_factor(g, path, o);
             RC_ASSERT(mean == sum / static_cast<double>(path.size() - 1));
             RC_ASSERT(mean >= 1.0 / 9.0);
             RC_ASSERT(mean <= 1.0);
           });
}

TEST_CASE("prop_safety_default_never_rewards_an_extra_node", "[shi2022][prop]") {
  rc::prop("inserting a node before the goal never raises the default fit_3 (per_node: raises it)", [] {
    const grid::Grid g = testing::random_grid(*rc::gen::arbitrary<std::uint32_t>(), *rc::gen::inRange(2, 9),
                                              *rc::gen::inRange(2, 9), 0.4);
    const auto path = *gen_nodes_in(g, 2, 10);
    const Cell extra{*rc::gen::inRange<std::int64_t>(0, g.width()), *rc::gen::inRange<std::int64_t>(0, g.height())};
    RC_PRE(!(extra == path[path.size() - 2]) && !(extra == path.back()));
    auto longer = path;
    longer.insert(longer.end() - 1, extra);
    RC_ASSERT(ga::safety_factor(g, longer) <= ga::safety_factor(g, path));
    ga::SafetyOptions per_node;
    per_node.aggregate = ga::SafetyAggregate::per_node;
    RC_ASSERT(ga::safety_factor(g, longer, per_node) > ga::safety_factor(g, path, per_node));
  });
}
