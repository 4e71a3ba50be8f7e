// spec: metrics.length, metrics.turn-angle, metrics.turns, metrics.smoothness, metrics.safety, metrics.converge, metrics.valid-path
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <vector>

#include "pathref/equations/metrics.hpp"
#include "pathref/grid/grid.hpp"
#include "support/generators.hpp"

using namespace pathref;
using grid::Cell;
using Path = std::vector<Cell>;

namespace {
/// A random walk of at least `min_cells` cells on a random grid (discarded otherwise).
struct Walk {
  grid::Grid g;
  grid::CornerPolicy policy;
  Path path;
};
Walk gen_walk_case(std::size_t min_cells) {
  auto g = *testing::gen_grid(10, 10, 0.4);
  const auto policy = *testing::gen_policy();
  auto path = *testing::gen_walk(g, policy, 30);
  RC_PRE(path.size() >= min_cells);
  return Walk{std::move(g), policy, std::move(path)};
}

/// Any polyline of small cells with no consecutive repeats.
Path gen_polyline() {
  const auto n = *rc::gen::inRange<std::size_t>(1, 12);
  Path p;
  while (p.size() < n) {
    const Cell c{*rc::gen::inRange<std::int64_t>(-6, 7), *rc::gen::inRange<std::int64_t>(-6, 7)};
    if (p.empty() || !(p.back() == c)) p.push_back(c);
  }
  return p;
}

Path reversed(Path p) {
  std::reverse(p.begin(), p.end());
  return p;
}
}  // namespace

TEST_CASE("prop_length_is_sum_of_step_costs", "[metrics][prop]") {
  rc::prop("on 8-neighbour walks, length == left-to-right sum of step_cost (bit for bit)", [] {
    const auto w = gen_walk_case(1);
    double sum = 0.0;
    for (std::size_t k = 1; k < w.path.size(); ++k) sum += grid::step_cost(w.path[k - 1], w.path[k]);
    RC_ASSERT(metrics::path_length(w.path) == sum);
  });
}

TEST_CASE("prop_length_invariant_under_reversal", "[metrics][prop]") {
  rc::prop("length(reverse(p)) == length(p) up to summation order", [] {
    const Path p = gen_polyline();
    const double a = metrics::path_length(p);
    const double b = metrics::path_length(reversed(p));
    // Same terms, opposite summation order: each of the n-1 additions rounds once, so the two
    // sums differ by at most 2 (n-1) eps times the total.
    const double bound = 2.0 * static_cast<double>(p.size()) * std::numeric_limits<double>::epsilon() * a;
    RC_ASSERT(std::fabs(a - b) <= bound);
    RC_ASSERT(a >= 0.0);
    RC_ASSERT((a == 0.0) == (p.size() == 1));
  });
}

TEST_CASE("prop_turn_count_invariant_under_reversal", "[metrics][prop]") {
  rc::prop("turns and turning angles are the same backwards", [] {
    const Path p = gen_polyline();
    RC_ASSERT(metrics::turn_count(p) == metrics::turn_count(reversed(p)));
    auto fwd = metrics::turning_angles(p);
    const auto bwd = metrics::turning_angles(reversed(p));
    std::reverse(fwd.begin(), fwd.end());
    RC_ASSERT(fwd == bwd);  // |u x v| and u.v are unchanged by reversal: identical atan2 inputs
  });
}

TEST_CASE("prop_straight_paths_have_no_turns", "[metrics][prop]") {
  rc::prop("p_k = p_0 + k d: 0 turns, all angles 0, smoothness 0 in both forms", [] {
    const auto dx = *rc::gen::inRange<std::int64_t>(-3, 4);
    const auto dy = *rc::gen::inRange<std::int64_t>(-3, 4);
    RC_PRE(dx != 0 || dy != 0);
    const auto n = *rc::gen::inRange<std::int64_t>(1, 20);
    const Cell p0{*rc::gen::inRange<std::int64_t>(-50, 50), *rc::gen::inRange<std::int64_t>(-50, 50)};
    Path p;
    for (std::int64_t k = 0; k < n; ++k) p.push_back(Cell{p0.x + k * dx, p0.y + k * dy});
    RC_ASSERT(metrics::turn_count(p) == 0);
    for (const double a : metrics::turning_angles(p)) RC_ASSERT(a == 0.0);
    RC_ASSERT(metrics::smoothness_ompl(p, metrics::SmoothnessForm::angle) == 0.0);
    // OMPL's form can leave a rounding artefact (spec metrics.smoothness), but only a tiny one.
    RC_ASSERT(metrics::smoothness_ompl(p) < 1e-12);
    if (std::max(std::llabs(dx), std::llabs(dy)) == 1) RC_ASSERT(metrics::smoothness_ompl(p) == 0.0);
  });
}

TEST_CASE("prop_turning_angles_in_0_pi", "[metrics][prop]") {
  rc::prop("n-2 angles in [0, pi]; angle > 0 exactly at the counted turns", [] {
    const Path p = gen_polyline();
    const auto angles = metrics::turning_angles(p);
    RC_ASSERT(angles.size() == (p.size() >= 2 ? p.size() - 2 : 0));
    std::int64_t positive = 0;
    for (const double a : angles) {
      RC_ASSERT(a >= 0.0);
      RC_ASSERT(a <= std::numbers::pi);
      if (a > 0.0) ++positive;
    }
    RC_ASSERT(positive == metrics::turn_count(p));
  });
}

TEST_CASE("prop_smoothness_forms_agree_without_uturns", "[metrics][prop]") {
  rc::prop("on 8-neighbour walks without reversals, ompl and angle forms agree to rounding", [] {
    const auto w = gen_walk_case(3);
    bool uturn = false;
    for (std::size_t k = 1; k + 1 < w.path.size(); ++k) uturn = uturn || w.path[k - 1] == w.path[k + 1];
    const double s_ompl = metrics::smoothness_ompl(w.path);
    const double s_angle = metrics::smoothness_ompl(w.path, metrics::SmoothnessForm::angle);
    RC_ASSERT(s_ompl >= 0.0);
    RC_ASSERT(s_angle >= s_ompl - 1e-12 * s_angle);  // a U-turn only ever adds to 'angle'
    // Per node the two phi differ by a few ulps (law of cosines vs atan2): 1e-12 relative
    // bounds the accumulated difference over <= 30 nodes with a wide margin.
    if (!uturn) RC_ASSERT(std::fabs(s_ompl - s_angle) <= 1e-12 * std::max(1.0, s_angle));
  });
}

TEST_CASE("prop_safety_counts_in_range", "[metrics][prop]") {
  rc::prop("counts in [0, 8]; the wall reading adds exactly the outside neighbours", [] {
    const auto w = gen_walk_case(1);
    const auto free_reading = metrics::safety_counts(w.g, w.path);
    const auto wall_reading = metrics::safety_counts(w.g, w.path, metrics::OutsideCells::blocked);
    RC_ASSERT(free_reading.size() == w.path.size());
    for (std::size_t k = 0; k < w.path.size(); ++k) {
      const Cell c = w.path[k];
      std::int64_t outside = 0;
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx)
          if ((dx != 0 || dy != 0) && !w.g.in_bounds(Cell{c.x + dx, c.y + dy})) ++outside;
      RC_ASSERT(free_reading[k] >= 0);
      RC_ASSERT(free_reading[k] + outside <= 8);
      RC_ASSERT(wall_reading[k] == free_reading[k] + outside);
    }
    const grid::Grid empty(w.g.width(), w.g.height());
    for (const auto n : metrics::safety_counts(empty, w.path)) RC_ASSERT(n == 0);
  });
}

TEST_CASE("prop_validate_accepts_neighbour_chains", "[metrics][prop]") {
  rc::prop("a walk built from neighbours() is valid from its first to its last cell", [] {
    const auto w = gen_walk_case(1);
    const auto r = metrics::validate_path(w.g, w.path, w.path.front(), w.path.back(), w.policy);
    RC_ASSERT(r.valid);
    RC_ASSERT(r.reason == "ok");
    RC_ASSERT(r.index == -1);
  });
}

TEST_CASE("prop_validate_rejects_blocked_cell", "[metrics][prop]") {
  rc::prop("blocking a cell of a valid walk makes it invalid at or before that cell", [] {
    auto w = gen_walk_case(2);
    const auto k = *rc::gen::inRange<std::size_t>(0, w.path.size());
    const Cell victim = w.path[k];
    w.g.set_blocked(victim, true);
    const auto first = static_cast<std::int64_t>(
        std::find(w.path.begin(), w.path.end(), victim) - w.path.begin());
    const auto r = metrics::validate_path(w.g, w.path, w.path.front(), w.path.back(), w.policy);
    RC_ASSERT(!r.valid);
    RC_ASSERT(r.index <= first);
    // An earlier diagonal step may now cut the new obstacle's corner; otherwise the blocked
    // node itself is reported.
    RC_ASSERT(r.reason == "blocked" || r.reason == "corner_cut");
    if (r.reason == "blocked") RC_ASSERT(r.index == first);
  });
}

TEST_CASE("prop_converge_at_first_occurrence_of_final_best", "[metrics][prop]") {
  rc::prop("1 <= t <= T, v_t is the final best, no earlier value reaches it", [] {
    const auto ints = *rc::gen::nonEmpty(rc::gen::container<std::vector<int>>(rc::gen::inRange(0, 12)));
    std::vector<double> v;
    for (const int x : ints) v.push_back(x == 11 ? std::numeric_limits<double>::infinity() : x);
    RC_PRE(std::any_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); }));
    const auto t = metrics::iterations_to_converge(v);
    RC_ASSERT(t >= 1);
    RC_ASSERT(t <= static_cast<std::int64_t>(v.size()));
    const double best = *std::min_element(v.begin(), v.end());
    RC_ASSERT(v[static_cast<std::size_t>(t - 1)] == best);
    for (std::int64_t s = 1; s < t; ++s) RC_ASSERT(v[static_cast<std::size_t>(s - 1)] > best);
    // The best-so-far series converges at the same iteration.
    std::vector<double> running(v.size());
    std::partial_sum(v.begin(), v.end(), running.begin(), [](double a, double b) { return std::min(a, b); });
    RC_ASSERT(metrics::iterations_to_converge(running) == t);
  });
}
