// spec: grid.encoding, grid.index, grid.coord, grid.moves, grid.corner-policy, grid.neighbour-order
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "pathref/grid/coords.hpp"
#include "pathref/grid/grid.hpp"
#include "support/generators.hpp"

using namespace pathref;
using grid::Cell;
using grid::CornerPolicy;
using grid::Eq1Form;

namespace {
constexpr std::array<CornerPolicy, 4> kNested{CornerPolicy::never, CornerPolicy::strict,
                                              CornerPolicy::one, CornerPolicy::always};

/// A cell of g drawn uniformly by index.
Cell any_cell(const grid::Grid& g) {
  return g.cell(*rc::gen::inRange<std::int64_t>(0, g.cell_count()));
}
}  // namespace

TEST_CASE("prop_index_cell_inverse", "[grid][prop]") {
  rc::prop("index_cell and cell_index are inverse bijections", [] {
    const auto w = *rc::gen::inRange<std::int64_t>(1, 5000);
    const auto h = *rc::gen::inRange<std::int64_t>(1, 5000);
    const Cell c{*rc::gen::inRange<std::int64_t>(0, w), *rc::gen::inRange<std::int64_t>(0, h)};
    const auto i = grid::cell_index(c, w, h);
    RC_ASSERT(i >= 0);
    RC_ASSERT(i < w * h);
    RC_ASSERT(grid::index_cell(i, w, h) == c);
    const auto j = *rc::gen::inRange<std::int64_t>(0, w * h);
    RC_ASSERT(grid::cell_index(grid::index_cell(j, w, h), w, h) == j);
  });
}

TEST_CASE("prop_coord_inverts_index", "[grid][prop]") {
  rc::prop("corrected centre of cell i is (x + 0.5, y + 0.5) and floors back to the cell", [] {
    const auto w = *rc::gen::inRange<std::int64_t>(1, 5000);
    const auto h = *rc::gen::inRange<std::int64_t>(1, 5000);
    const auto i = *rc::gen::inRange<std::int64_t>(0, w * h);
    const Cell c = grid::index_cell(i, w, h);
    const auto p = grid::cell_centre(i, w, h);
    RC_ASSERT(p == grid::cell_centre(c));
    RC_ASSERT(p.x == static_cast<double>(c.x) + 0.5);
    RC_ASSERT(p.y == static_cast<double>(c.y) + 0.5);
    const auto fx = static_cast<std::int64_t>(std::floor(p.x));
    const auto fy = static_cast<std::int64_t>(std::floor(p.y));
    RC_ASSERT(grid::cell_index(Cell{fx, fy}, w, h) == i);
  });
}

TEST_CASE("prop_printed_eq1_errors_are_exactly_as_stated", "[grid][prop]") {
  rc::prop("printed0 is wrong only in y, exactly on column 0; printed1 only in x", [] {
    const auto w = *rc::gen::inRange<std::int64_t>(1, 300);
    const auto h = *rc::gen::inRange<std::int64_t>(1, 300);
    const auto i = *rc::gen::inRange<std::int64_t>(0, w * h);
    const auto ok = grid::cell_centre(i, w, h, Eq1Form::corrected);
    const auto p0 = grid::cell_centre(i, w, h, Eq1Form::printed0);
    const auto p1 = grid::cell_centre(i, w, h, Eq1Form::printed1);
    RC_ASSERT(p0.x == ok.x);
    RC_ASSERT((p0.y == ok.y) == (i % w != 0));
    if (i % w == 0) RC_ASSERT(p0.y == ok.y - 1.0);
    RC_ASSERT(p1.y == ok.y);
    // x one column right, wrapping the last column to 0.5 (no change only when W = 1).
    const double shifted = static_cast<double>((i % w + 1) % w) + 0.5;
    RC_ASSERT(p1.x == shifted);
    RC_ASSERT((p1.x == ok.x) == (w == 1));
  });
}

TEST_CASE("prop_grid_rows_round_trip", "[grid][prop]") {
  rc::prop("from_rows_top_first(to_rows_top_first(g)) == g", [] {
    const auto g = *testing::gen_grid(12, 12, 0.6);
    RC_ASSERT(grid::Grid::from_rows_top_first(g.to_rows_top_first()) == g);
  });
}

TEST_CASE("prop_step_cost_is_one_or_sqrt2", "[grid][prop]") {
  rc::prop("cost 1 for orthogonal, sqrt(2) for diagonal steps, symmetric", [] {
    const Cell a{*rc::gen::inRange<std::int64_t>(-1000, 1000), *rc::gen::inRange<std::int64_t>(-1000, 1000)};
    const auto dx = *rc::gen::inRange<std::int64_t>(-1, 2);
    const auto dy = *rc::gen::inRange<std::int64_t>(-1, 2);
    RC_PRE(dx != 0 || dy != 0);
    const Cell b{a.x + dx, a.y + dy};
    const double c = grid::step_cost(a, b);
    RC_ASSERT(c == ((dx != 0 && dy != 0) ? std::numbers::sqrt2 : 1.0));
    RC_ASSERT(grid::step_cost(b, a) == c);
  });
}

TEST_CASE("prop_neighbours_equal_the_corner_policy_written_out", "[grid][prop]") {
  // Oracle independent of grid::step_allowed (which grid::neighbours calls): spec grid.corner-policy
  // and grid.neighbour-order written out over the 8 offsets in the spec's order, with "free" read
  // from in_bounds and blocked only; costs 1 and sqrt(2) (grid.moves).
  rc::prop("neighbours == brute force over the 8 offsets", [] {
    const auto g = *testing::gen_grid(10, 10, 0.5);
    const auto policy = *testing::gen_policy();
    const Cell c = any_cell(g);
    RC_PRE(g.free(c));
    const auto f = [&](Cell o) { return g.in_bounds(o) && !g.blocked(o); };
    const std::array<std::array<std::int64_t, 2>, 8> order{
        {{-1, -1}, {0, -1}, {1, -1}, {-1, 0}, {1, 0}, {-1, 1}, {0, 1}, {1, 1}}};
    std::vector<grid::Move> want;
    for (const auto& [dx, dy] : order) {
      const Cell b{c.x + dx, c.y + dy};
      if (!f(b)) continue;
      bool ok = true;
      if (dx != 0 && dy != 0) {
        const bool o1 = f(Cell{c.x + dx, c.y});
        const bool o2 = f(Cell{c.x, c.y + dy});
        ok = policy == CornerPolicy::never    ? false
             : policy == CornerPolicy::strict ? (o1 && o2)
             : policy == CornerPolicy::one    ? (o1 || o2)
                                              : true;
      }
      if (ok) want.push_back(grid::Move{b, dx != 0 && dy != 0 ? std::sqrt(2.0) : 1.0});
    }
    const auto got = grid::neighbours(g, c, policy);
    RC_ASSERT(got.size() == want.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
      RC_ASSERT(got[k].to == want[k].to);
      RC_ASSERT(got[k].cost == want[k].cost);
    }
  });
}

TEST_CASE("prop_neighbours_sorted_by_index", "[grid][prop]") {
  rc::prop("targets strictly increasing in cell index, costs = step_cost", [] {
    const auto g = *testing::gen_grid(10, 10, 0.5);
    const auto policy = *testing::gen_policy();
    const Cell c = any_cell(g);
    RC_PRE(g.free(c));
    const auto n = grid::neighbours(g, c, policy);
    for (std::size_t k = 0; k < n.size(); ++k) {
      RC_ASSERT(n[k].cost == grid::step_cost(c, n[k].to));
      if (k > 0) RC_ASSERT(g.index(n[k - 1].to) < g.index(n[k].to));
    }
  });
}

TEST_CASE("prop_neighbours_are_exactly_the_allowed_steps", "[grid][prop]") {
  rc::prop("b in N(c) iff step_allowed(c, b) over the 3x3 block", [] {
    const auto g = *testing::gen_grid(10, 10, 0.5);
    const auto policy = *testing::gen_policy();
    const Cell c = any_cell(g);
    RC_PRE(g.free(c));
    const auto n = grid::neighbours(g, c, policy);
    std::size_t allowed = 0;
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        const Cell b{c.x + dx, c.y + dy};
        const bool listed = std::any_of(n.begin(), n.end(), [&](const grid::Move& m) { return m.to == b; });
        RC_ASSERT(listed == grid::step_allowed(g, c, b, policy));
        if (listed) ++allowed;
      }
    }
    RC_ASSERT(allowed == n.size());
  });
}

TEST_CASE("prop_neighbours_symmetric", "[grid][prop]") {
  rc::prop("b in N(a) iff a in N(b)", [] {
    const auto g = *testing::gen_grid(10, 10, 0.5);
    const auto policy = *testing::gen_policy();
    const Cell a = any_cell(g);
    RC_PRE(g.free(a));
    for (const auto& m : grid::neighbours(g, a, policy)) {
      const auto back = grid::neighbours(g, m.to, policy);
      RC_ASSERT(std::any_of(back.begin(), back.end(), [&](const grid::Move& k) { return k.to == a; }));
    }
    // and the converse for every free 8-neighbour
    for (std::int64_t dy = -1; dy <= 1; ++dy)
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        const Cell b{a.x + dx, a.y + dy};
        RC_ASSERT(grid::step_allowed(g, a, b, policy) == grid::step_allowed(g, b, a, policy));
      }
  });
}

TEST_CASE("prop_neighbours_monotone_in_policy", "[grid][prop]") {
  rc::prop("N_never within N_strict within N_one within N_always", [] {
    const auto g = *testing::gen_grid(10, 10, 0.5);
    const Cell c = any_cell(g);
    RC_PRE(g.free(c));
    for (std::size_t p = 0; p + 1 < kNested.size(); ++p) {
      const auto smaller = grid::neighbours(g, c, kNested[p]);
      const auto larger = grid::neighbours(g, c, kNested[p + 1]);
      RC_ASSERT(smaller.size() <= larger.size());
      for (const auto& m : smaller)
        RC_ASSERT(std::any_of(larger.begin(), larger.end(), [&](const grid::Move& k) { return k.to == m.to; }));
    }
    // `never` is the 4-neighbourhood: only orthogonal steps.
    for (const auto& m : grid::neighbours(g, c, CornerPolicy::never)) RC_ASSERT(m.cost == 1.0);
  });
}
