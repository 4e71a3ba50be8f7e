// Properties of the sensors2023 global planner (spec/sensors2023.md) and of the search core's
// expansion rules (spec/search.md "Expansion rules and child counts").
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <vector>

#include "pathref/equations/heuristics.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/equations/sensors2023.hpp"
#include "pathref/planners/astar_kinematic.hpp"
#include "pathref/planners/search.hpp"
#include "support/generators.hpp"
#include "support/reach.hpp"

using pathref::grid::Cell;
using pathref::grid::Grid;
namespace s23 = pathref::sensors2023;
namespace hs = pathref::heuristics;

namespace {

struct Scene {
  Grid g;
  Cell start;
  Cell goal;
};

/// A random grid with a free start and goal (drawn inside the generator body).
Scene draw_scene(int max_w, int max_h, double density) {
  Grid g = *pathref::testing::gen_grid(max_w, max_h, density);
  const Cell s{*rc::gen::inRange<std::int64_t>(0, g.width()), *rc::gen::inRange<std::int64_t>(0, g.height())};
  const Cell e{*rc::gen::inRange<std::int64_t>(0, g.width()), *rc::gen::inRange<std::int64_t>(0, g.height())};
  g.set_blocked(s, false);
  g.set_blocked(e, false);
  return Scene{g, s, e};
}

double cx(std::int64_t v) { return static_cast<double>(v) + 0.5; }

/// Oracle for the collision test: dense points of the segment strictly inside a blocked square.
bool dense_blocked(const Grid& g, Cell a, Cell b) {
  const int K = 4000;
  for (int k = 0; k <= K; ++k) {
    const double x = cx(a.x) + static_cast<double>(b.x - a.x) * (static_cast<double>(k) / K);
    const double y = cx(a.y) + static_cast<double>(b.y - a.y) * (static_cast<double>(k) / K);
    const double fx = std::floor(x);
    const double fy = std::floor(y);
    if (x == fx || y == fy) continue;  // on a grid line: not strictly inside any cell
    const Cell c{static_cast<std::int64_t>(fx), static_cast<std::int64_t>(fy)};
    if (g.in_bounds(c) && g.blocked(c)) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("prop_best_first_with_plain_rule_is_astar") {
  rc::prop("best_first with all moves and f = g + h returns astar's path and counts", [] {
    const auto sc = draw_scene(12, 12, 0.35);
    const auto policy = *pathref::testing::gen_policy();
    const auto h = *rc::gen::element(hs::Heuristic::octile, hs::Heuristic::euclidean,
                                     hs::Heuristic::manhattan, hs::Heuristic::zero);
    pathref::search::ExpansionRule rule;
    rule.h = [&](Cell n) { return hs::evaluate(h, n, sc.goal); };
    const auto a = pathref::search::astar(sc.g, sc.start, sc.goal, policy, h);
    const auto b = pathref::search::best_first(sc.g, sc.start, sc.goal, policy, rule);
    RC_ASSERT(a.found == b.found);
    RC_ASSERT(a.path == b.path);
    RC_ASSERT(a.length == b.length);
    RC_ASSERT(a.expansions == b.expansions);
    RC_ASSERT(a.generated == b.generated);
    RC_ASSERT(a.child_nodes == b.child_nodes);
    RC_ASSERT(a.child_nodes <= a.generated);
  });
}

TEST_CASE("prop_sensors2023_five_directions_face_the_goal") {
  rc::prop("the 5 kept moves are within 90 degrees of the goal bearing; the abandoned ones beyond", [] {
    const Cell n{*rc::gen::inRange(-50, 51), *rc::gen::inRange(-50, 51)};
    const Cell g{*rc::gen::inRange(-50, 51), *rc::gen::inRange(-50, 51)};
    RC_PRE(!(n == g));
    const double theta = s23::goal_bearing(n, g);
    const int s = s23::bearing_sector(theta);
    const auto diff = [&](int b) {
      double d = std::fmod(std::abs(theta - b), 360.0);
      return std::min(d, 360.0 - d);
    };
    for (int b : s23::kept_bearings(s)) RC_ASSERT(diff(b) <= 112.5);
    for (int b : s23::abandoned_bearings(s)) RC_ASSERT(diff(b) >= 112.5);
    // the centre direction is the nearest of the 8 to the bearing
    RC_ASSERT(diff(45 * s) <= 22.5);
    RC_ASSERT(std::popcount(static_cast<unsigned>(s23::bearing_mask(s23::kept_bearings(s)))) == 5);
  });
}

TEST_CASE("prop_sensors2023_segment_blocked_matches_dense_sampling") {
  rc::prop("the exact collision test agrees with dense sampling of the segment's interior points", [] {
    const auto g = *pathref::testing::gen_grid(10, 10, 0.3);
    const Cell a{*rc::gen::inRange<std::int64_t>(0, g.width()), *rc::gen::inRange<std::int64_t>(0, g.height())};
    const Cell b{*rc::gen::inRange<std::int64_t>(0, g.width()), *rc::gen::inRange<std::int64_t>(0, g.height())};
    RC_ASSERT(s23::segment_blocked(g, a, b) == dense_blocked(g, a, b));
  });
}

TEST_CASE("prop_sensors2023_planner_invariants") {
  pathref::testing::Reach found;
  rc::prop("found iff reachable; key nodes are a subsequence with the same ends; shortcuts pass "
           "their tests; the curve starts and ends at the end centres", [&found] {
    const auto sc = draw_scene(14, 14, 0.3);
    const auto policy = *pathref::testing::gen_policy();
    s23::KinematicOptions o;
    o.weight = *rc::gen::element(s23::WeightForm::linear, s23::WeightForm::exp, s23::WeightForm::none);
    o.directions = *rc::gen::element(5, 8);
    o.safety = *rc::gen::element(s23::SafetyCompare::ge, s23::SafetyCompare::gt);
    o.end = *rc::gen::element(pathref::bspline::EndHandling::repeated,
                              pathref::bspline::EndHandling::clamped);
    o.spacing = 0.25;
    const auto r = s23::plan_kinematic(sc.g, sc.start, sc.goal, policy, o);
    const auto d = pathref::search::dijkstra(sc.g, sc.start, sc.goal, policy);
    RC_ASSERT(r.search.found == d.found);
    RC_CLASSIFY(r.fallback_used, "fallback");
    if (!found.hit(r.search.found)) return;
    RC_ASSERT(pathref::metrics::validate_path(sc.g, r.search.path, sc.start, sc.goal, policy).valid);
    RC_ASSERT(r.search.length >= d.length - 1e-9);  // the weighted search is not shorter
    const auto& raw = r.search.path;
    for (const auto* keys : {&r.ordinary, &r.secondary}) {
      RC_ASSERT(keys->front() == raw.front());
      RC_ASSERT(keys->back() == raw.back());
      std::size_t pos = 0;
      for (std::size_t i = 0; i < keys->size(); ++i) {
        while (pos < raw.size() && !(raw[pos] == (*keys)[i])) ++pos;
        RC_ASSERT(pos < raw.size());  // a subsequence of the raw path
        if (i + 1 < keys->size()) {
          std::size_t next = pos + 1;
          while (next < raw.size() && !(raw[next] == (*keys)[i + 1])) ++next;
          RC_ASSERT(next < raw.size());
          if (next > pos + 1) {  // a real shortcut: it passed its tests
            RC_ASSERT(!s23::segment_blocked(sc.g, raw[pos], raw[next]));
            if (keys == &r.secondary)
              RC_ASSERT(s23::safety_test(sc.g, raw[pos], raw[next], o.k, o.ds, o.safety).safe);
          }
        }
      }
    }
    if (r.key_nodes.size() == 1 && o.end == pathref::bspline::EndHandling::clamped) {
      RC_ASSERT(!r.has_curve);  // start == goal: one key node, no clamped curve (curves.knots)
      return;
    }
    RC_ASSERT(r.has_curve);
    const auto& p = r.curve.points;
    RC_ASSERT(std::abs(p.front().x - cx(sc.start.x)) <= 1e-12);
    RC_ASSERT(std::abs(p.front().y - cx(sc.start.y)) <= 1e-12);
    RC_ASSERT(std::abs(p.back().x - cx(sc.goal.x)) <= 1e-12);
    RC_ASSERT(std::abs(p.back().y - cx(sc.goal.y)) <= 1e-12);
    RC_ASSERT(r.clearance.lower <= r.clearance.upper);
  });
  pathref::testing::require_reach(found, 0.7, "paths found, key nodes and curve checked");
}

TEST_CASE("prop_sensors2023_five_directions_generate_no_more_children_per_expansion") {
  rc::prop("each expansion generates at most 5 children in free neighbourhoods", [] {
    const auto sc = draw_scene(12, 12, 0.2);
    pathref::search::ExpansionRule rule;
    std::int64_t reduced = 0;
    rule.moves = [&](Cell c) {
      const auto m = s23::child_moves(sc.g, c, sc.goal, 1);
      if (std::popcount(static_cast<unsigned>(m)) == 5) ++reduced;
      return m;
    };
    rule.h = [&](Cell n) { return hs::euclidean(n, sc.goal); };
    const auto five = pathref::search::best_first(sc.g, sc.start, sc.goal, pathref::grid::CornerPolicy::strict, rule);
    RC_ASSERT(five.generated <= 8 * five.expansions - 3 * reduced);
  });
}
