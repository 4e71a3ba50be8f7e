// spec: search.astar, search.dijkstra, search.order, search.admissible, search.h.manhattan, search.h.chebyshev, search.h.octile, search.h.euclidean
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <numbers>
#include <vector>

#include "pathref/equations/heuristics.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/planners/search.hpp"
#include "support/generators.hpp"
#include "support/reach.hpp"

using namespace pathref;
using grid::Cell;
using grid::CornerPolicy;
using grid::Grid;
using heuristics::Heuristic;

namespace pathref::heuristics {
inline void showValue(Heuristic h, std::ostream& os) { os << to_string(h); }
}  // namespace pathref::heuristics

namespace {

constexpr double u = 0x1p-53;  // unit roundoff of binary64

/// A map with a free start and goal (cells chosen uniformly, then freed: bounded by
/// construction, no RC_PRE), and a corner policy.
struct Scenario {
  Grid g{1, 1};
  Cell start;
  Cell goal;
  CornerPolicy policy = CornerPolicy::strict;
};

Scenario gen_scenario() {
  Scenario sc;
  sc.g = *testing::gen_grid(14, 14, 0.5);
  const auto n = sc.g.cell_count();
  sc.start = sc.g.cell(*rc::gen::inRange<std::int64_t>(0, n));
  sc.goal = sc.g.cell(*rc::gen::inRange<std::int64_t>(0, n));
  sc.g.set_blocked(sc.start, false);
  sc.g.set_blocked(sc.goal, false);
  sc.policy = *testing::gen_policy();
  return sc;
}

/// The consistent heuristics of the table (search.admissible) under `p`.
std::vector<Heuristic> consistent_heuristics(CornerPolicy p) {
  std::vector<Heuristic> v;
  for (const Heuristic h : {Heuristic::zero, Heuristic::manhattan, Heuristic::chebyshev,
                            Heuristic::octile, Heuristic::euclidean})
    if (heuristics::consistent(h, p)) v.push_back(h);
  return v;
}

/// Cells reachable from `start` by allowed steps: a breadth-first flood fill written here from
/// grid.corner-policy, independent of the search.
std::vector<bool> flood_fill(const Grid& g, Cell start, CornerPolicy p) {
  std::vector<bool> seen(static_cast<std::size_t>(g.cell_count()), false);
  std::deque<Cell> queue{start};
  seen[static_cast<std::size_t>(g.index(start))] = true;
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        const Cell m{c.x + dx, c.y + dy};
        if (!grid::step_allowed(g, c, m, p)) continue;
        const auto i = static_cast<std::size_t>(g.index(m));
        if (!seen[i]) {
          seen[i] = true;
          queue.push_back(m);
        }
      }
    }
  }
  return seen;
}

/// Guarantee 2 of spec/search.md: two left-to-right sums of the same k step costs (in different
/// orders) differ by at most 2 (k - 1) u L.
bool same_cost_lengths(double a, double b, std::int64_t k) {
  const double bound = 2.0 * static_cast<double>(std::max<std::int64_t>(k - 1, 0)) * u *
                       std::max(a, b);
  return std::fabs(a - b) <= bound;
}

/// Exact test of p <= q * sqrt(2) for integers p, q (no rounding anywhere).
bool le_q_sqrt2(std::int64_t p, std::int64_t q) {
  if (q >= 0) return p <= 0 || p * p <= 2 * q * q;
  return p < 0 && p * p >= 2 * q * q;
}

}  // namespace

TEST_CASE("prop_astar_length_equals_dijkstra", "[search][prop]") {
  rc::prop("consistent heuristics: same found, same step counts, lengths within 2(k-1)uL", [] {
    const Scenario sc = gen_scenario();
    const auto d = search::dijkstra(sc.g, sc.start, sc.goal, sc.policy);
    const auto ds = search::step_counts(d.path);
    for (const Heuristic h : consistent_heuristics(sc.policy)) {
      const auto a = search::astar(sc.g, sc.start, sc.goal, sc.policy, h);
      RC_ASSERT(a.found == d.found);
      RC_ASSERT(search::step_counts(a.path) == ds);
      RC_ASSERT(same_cost_lengths(a.length, d.length, ds.orthogonal + ds.diagonal));
    }
  });
}

TEST_CASE("prop_paths_valid_under_policy", "[search][prop]") {
  pathref::testing::Reach found;
  rc::prop("every found path passes metrics.valid-path; length == metrics.length bit for bit", [&found] {
    const Scenario sc = gen_scenario();
    const auto h = *rc::gen::element(Heuristic::zero, Heuristic::manhattan, Heuristic::chebyshev,
                                     Heuristic::octile, Heuristic::euclidean);
    const auto r = search::astar(sc.g, sc.start, sc.goal, sc.policy, h);
    if (!found.hit(r.found)) {
      RC_ASSERT(r.path.empty());
      RC_ASSERT(r.length == 0.0);
      return;
    }
    const auto check = metrics::validate_path(sc.g, r.path, sc.start, sc.goal, sc.policy);
    RC_ASSERT(check.valid);
    RC_ASSERT(r.length == metrics::path_length(r.path));
  });
  pathref::testing::require_reach(found, 0.7, "found paths validated");
}

TEST_CASE("prop_astar_expands_no_more_than_dijkstra", "[search][prop]") {
  rc::prop("consistent h with h >= 1 off the goal: expansions(A*) <= expansions(Dijkstra)", [] {
    const Scenario sc = gen_scenario();
    const auto d = search::dijkstra(sc.g, sc.start, sc.goal, sc.policy);
    for (const Heuristic h : consistent_heuristics(sc.policy)) {
      if (h == Heuristic::zero) continue;
      const auto a = search::astar(sc.g, sc.start, sc.goal, sc.policy, h);
      RC_ASSERT(a.expansions <= d.expansions);
      if (!d.found) RC_ASSERT(a.expansions == d.expansions);  // both close the whole component
    }
  });
}

TEST_CASE("prop_found_agrees_with_flood_fill", "[search][prop]") {
  // Random maps leave the goal unreachable in about 2 % of cases only; in a third of the cases the
  // goal is walled in on purpose (its 8 neighbours blocked, unless the start is one of them), so
  // the unreachable branch runs in at least 10 % of the cases (require_reach below).
  pathref::testing::Reach unreachable_cases;
  rc::prop("found iff reachable; unreachable: empty path, expansions = component size", [&unreachable_cases] {
    Scenario sc = gen_scenario();
    if (*rc::gen::inRange(0, 3) == 0 && !(sc.start == sc.goal)) {
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx) {
          const Cell c{sc.goal.x + dx, sc.goal.y + dy};
          if ((dx != 0 || dy != 0) && sc.g.in_bounds(c) && !(c == sc.start)) sc.g.set_blocked(c, true);
        }
    }
    const auto seen = flood_fill(sc.g, sc.start, sc.policy);
    const bool reachable = seen[static_cast<std::size_t>(sc.g.index(sc.goal))];
    const auto component = std::count(seen.begin(), seen.end(), true);
    RC_CLASSIFY(!reachable, "unreachable");
    unreachable_cases.hit(!reachable);
    for (const Heuristic h : {Heuristic::zero, Heuristic::manhattan, Heuristic::chebyshev,
                              Heuristic::octile, Heuristic::euclidean}) {
      const auto r = search::astar(sc.g, sc.start, sc.goal, sc.policy, h);
      RC_ASSERT(r.found == reachable);
      RC_ASSERT(r.expansions <= component);
      if (!reachable) {
        RC_ASSERT(r.path.empty());
        RC_ASSERT(r.length == 0.0);
        RC_ASSERT(r.expansions == component);
      }
    }
  });
  pathref::testing::require_reach(unreachable_cases, 0.1, "unreachable goals");
}

TEST_CASE("prop_dijkstra_is_astar_with_zero_heuristic", "[search][prop]") {
  rc::prop("dijkstra == astar(zero): same path, length bits, expansions", [] {
    const Scenario sc = gen_scenario();
    const auto d = search::dijkstra(sc.g, sc.start, sc.goal, sc.policy);
    const auto z = search::astar(sc.g, sc.start, sc.goal, sc.policy, Heuristic::zero);
    RC_ASSERT(d.found == z.found);
    RC_ASSERT(d.path == z.path);
    RC_ASSERT(d.length == z.length);
    RC_ASSERT(d.expansions == z.expansions);
  });
}

TEST_CASE("prop_manhattan_within_sqrt2_of_shortest", "[search][prop]") {
  pathref::testing::Reach found;
  rc::prop("A*-manhattan under any policy: exact cost <= sqrt2 * shortest (guarantee 4)", [&found] {
    const Scenario sc = gen_scenario();
    const auto d = search::dijkstra(sc.g, sc.start, sc.goal, sc.policy);
    const auto m = search::astar(sc.g, sc.start, sc.goal, sc.policy, Heuristic::manhattan);
    RC_ASSERT(m.found == d.found);
    if (!found.hit(d.found)) return;
    const auto ms = search::step_counts(m.path);
    const auto ds = search::step_counts(d.path);
    // a + b sqrt2 <= sqrt2 (a' + b' sqrt2) = 2b' + a' sqrt2  <=>  a - 2b' <= (a' - b) sqrt2
    RC_ASSERT(le_q_sqrt2(ms.orthogonal - 2 * ds.diagonal, ds.orthogonal - ms.diagonal));
    // and never shorter than the shortest: a' + b' sqrt2 <= a + b sqrt2
    RC_ASSERT(le_q_sqrt2(ds.orthogonal - ms.orthogonal, ms.diagonal - ds.diagonal));
  });
  pathref::testing::require_reach(found, 0.7, "goals found, costs compared");
}

TEST_CASE("prop_heuristic_lower_bound_and_consistency", "[search][prop]") {
  rc::prop("admissible pairs: h(start) <= shortest; consistent pairs: h(n) <= c + h(n')", [] {
    const Scenario sc = gen_scenario();
    const auto d = search::dijkstra(sc.g, sc.start, sc.goal, sc.policy);
    for (const Heuristic h : consistent_heuristics(sc.policy)) {
      RC_ASSERT(heuristics::admissible(h, sc.policy));
      const double hs = heuristics::evaluate(h, sc.start, sc.goal);
      if (d.found) {
        // Exact h <= exact d*; each double is within (k + 3) u of its exact value (d: k-term
        // sum and the constant s; h: at most 3 roundings), so allow 2 (k + 3) u d.
        const auto k = static_cast<double>(d.path.size());
        RC_ASSERT(hs <= d.length + 2.0 * (k + 3.0) * u * d.length);
      }
      // Consistency along every allowed step out of the start (exact statement; the doubles
      // may violate it by a few ulps, spec "Rounding").
      if (sc.g.free(sc.start)) {
        for (const auto& mv : grid::neighbours(sc.g, sc.start, sc.policy)) {
          const double rhs = mv.cost + heuristics::evaluate(h, mv.to, sc.goal);
          RC_ASSERT(hs <= rhs + 8.0 * u * rhs);
        }
      }
    }
  });
}

TEST_CASE("prop_heuristics_are_ordered", "[search][prop]") {
  rc::prop("chebyshev <= euclidean <= octile <= manhattan (euclidean <= octile up to 4 ulps)", [] {
    const Cell n{*rc::gen::inRange<std::int64_t>(-3000, 3000), *rc::gen::inRange<std::int64_t>(-3000, 3000)};
    const Cell g{*rc::gen::inRange<std::int64_t>(-3000, 3000), *rc::gen::inRange<std::int64_t>(-3000, 3000)};
    const double c = heuristics::chebyshev(n, g);
    const double e = heuristics::euclidean(n, g);
    const double o = heuristics::octile(n, g);
    const double m = heuristics::manhattan(n, g);
    RC_ASSERT(c <= e);  // sqrt is monotone and exact on perfect squares
    RC_ASSERT(e <= o + 4.0 * u * o);  // equal in exact arithmetic when dx == dy, or one is 0
    RC_ASSERT(o <= m);  // fl(s*m) <= 2m, and rounding is monotone
    RC_ASSERT((c == 0.0) == (n == g));
    RC_ASSERT(heuristics::octile(n, g) == heuristics::octile(g, n));
  });
}

TEST_CASE("prop_order_is_a_strict_total_order", "[search][prop]") {
  rc::prop("irreflexive, asymmetric, total on distinct indices, transitive", [] {
    // Small value sets force ties on f and h.
    const auto key = [] {
      return search::OpenKey{*rc::gen::element(0.0, 1.0, std::numbers::sqrt2, 2.0),
                             *rc::gen::element(0.0, 1.0, 2.0),
                             *rc::gen::inRange<std::int64_t>(0, 4)};
    };
    const auto a = key();
    const auto b = key();
    const auto c = key();
    RC_ASSERT(!search::precedes(a, a));
    RC_ASSERT(!(search::precedes(a, b) && search::precedes(b, a)));
    if (a.index != b.index) RC_ASSERT(search::precedes(a, b) || search::precedes(b, a));
    if (search::precedes(a, b) && search::precedes(b, c)) RC_ASSERT(search::precedes(a, c));
  });
}

namespace {

/// The normative procedure of search.astar written literally (OPEN as a list scanned for the key
/// that precedes all others, CLOSED as a set, neighbours by grid::step_allowed in
/// grid.neighbour-order), with the child counts of spec/search.md: the oracle for the library's
/// optimised core (workspace, generation marks, heap, move masks).
search::Outcome literal_search(const Grid& g, Cell start, Cell goal, CornerPolicy p, Heuristic h) {
  const auto n = static_cast<std::size_t>(g.cell_count());
  std::vector<double> gv(n, 0.0);
  std::vector<std::int64_t> parent(n, -1);
  std::vector<bool> open(n, false), closed(n, false), seen(n, false);
  std::vector<std::int64_t> open_list{g.index(start)};
  open[static_cast<std::size_t>(g.index(start))] = true;
  seen[static_cast<std::size_t>(g.index(start))] = true;
  search::Outcome out;
  const auto key = [&](std::int64_t i) {
    const double hv = heuristics::evaluate(h, g.cell(i), goal);
    return search::OpenKey{gv[static_cast<std::size_t>(i)] + hv, hv, i};
  };
  while (!open_list.empty()) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < open_list.size(); ++k)
      if (search::precedes(key(open_list[k]), key(open_list[best]))) best = k;
    const std::int64_t i = open_list[best];
    open_list.erase(open_list.begin() + static_cast<std::ptrdiff_t>(best));
    const auto ui = static_cast<std::size_t>(i);
    open[ui] = false;
    closed[ui] = true;
    ++out.expansions;
    if (i == g.index(goal)) {
      out.found = true;
      out.length = gv[ui];
      for (std::int64_t j = i; j != -1; j = parent[static_cast<std::size_t>(j)]) out.path.push_back(g.cell(j));
      std::reverse(out.path.begin(), out.path.end());
      return out;
    }
    const Cell c = g.cell(i);
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        const Cell m{c.x + dx, c.y + dy};
        if (!grid::step_allowed(g, c, m, p)) continue;
        const auto mi = static_cast<std::size_t>(g.index(m));
        if (closed[mi]) continue;
        ++out.generated;
        const double g_new = gv[ui] + grid::step_cost(c, m);
        if (!open[mi] || g_new < gv[mi]) {
          if (!seen[mi]) ++out.child_nodes;
          seen[mi] = true;
          gv[mi] = g_new;
          parent[mi] = i;
          if (!open[mi]) open_list.push_back(static_cast<std::int64_t>(mi));
          open[mi] = true;
        }
      }
    }
  }
  return out;
}

bool same_outcome(const search::Outcome& a, const search::Outcome& b) {
  return a.found == b.found && a.path == b.path && a.length == b.length && a.expansions == b.expansions &&
         a.generated == b.generated && a.child_nodes == b.child_nodes;
}

}  // namespace

TEST_CASE("prop_search_is_the_literal_procedure", "[search][prop]") {
  rc::prop("astar/dijkstra = search.astar's procedure written literally: path, length, counts", [] {
    const Scenario sc = gen_scenario();
    const auto h = *rc::gen::element(Heuristic::zero, Heuristic::manhattan, Heuristic::chebyshev,
                                     Heuristic::octile, Heuristic::euclidean);
    const auto want = literal_search(sc.g, sc.start, sc.goal, sc.policy, h);
    RC_ASSERT(same_outcome(search::astar(sc.g, sc.start, sc.goal, sc.policy, h), want));
    if (h == Heuristic::zero) RC_ASSERT(same_outcome(search::dijkstra(sc.g, sc.start, sc.goal, sc.policy), want));
  });
}

TEST_CASE("prop_workspace_reuse_is_invisible", "[search][prop]") {
  rc::prop("searches through one reused Workspace (maps of several sizes) = searches with fresh state", [] {
    search::Workspace ws;
    const int runs = *rc::gen::inRange(2, 6);
    for (int r = 0; r < runs; ++r) {
      const Scenario sc = gen_scenario();
      const auto h = *rc::gen::element(Heuristic::zero, Heuristic::manhattan, Heuristic::chebyshev,
                                       Heuristic::octile, Heuristic::euclidean);
      RC_ASSERT(same_outcome(search::astar(ws, sc.g, sc.start, sc.goal, sc.policy, h),
                             search::astar(sc.g, sc.start, sc.goal, sc.policy, h)));
      RC_ASSERT(same_outcome(search::dijkstra(ws, sc.g, sc.start, sc.goal, sc.policy),
                             search::dijkstra(sc.g, sc.start, sc.goal, sc.policy)));
      search::ExpansionRule rule;
      const std::uint8_t mask = *rc::gen::arbitrary<std::uint8_t>();
      rule.moves = [mask](Cell) { return mask; };
      rule.h = [&](Cell c) { return heuristics::octile(c, sc.goal); };
      RC_ASSERT(same_outcome(search::best_first(ws, sc.g, sc.start, sc.goal, sc.policy, rule),
                             search::best_first(sc.g, sc.start, sc.goal, sc.policy, rule)));
    }
    RC_ASSERT(ws.capacity() > 0);
  });
}

TEST_CASE("prop_move_mask_cache_follows_the_grid", "[search][prop]") {
  rc::prop("a reused Workspace after a cell of the same grid changes, or the policy does, = the literal procedure", [] {
    search::Workspace ws;
    Scenario sc = gen_scenario();
    const int runs = *rc::gen::inRange(2, 8);
    for (int r = 0; r < runs; ++r) {
      const auto h = *rc::gen::element(Heuristic::zero, Heuristic::octile, Heuristic::manhattan);
      RC_ASSERT(same_outcome(search::astar(ws, sc.g, sc.start, sc.goal, sc.policy, h),
                             literal_search(sc.g, sc.start, sc.goal, sc.policy, h)));
      // Next: one cell flipped (start and goal stay free), or another policy, or both.
      if (*rc::gen::arbitrary<bool>()) {
        const Cell c = sc.g.cell(*rc::gen::inRange<std::int64_t>(0, sc.g.cell_count()));
        if (c != sc.start && c != sc.goal) sc.g.set_blocked(c, !sc.g.blocked(c));
      }
      if (*rc::gen::arbitrary<bool>()) sc.policy = *testing::gen_policy();
    }
  });
}
