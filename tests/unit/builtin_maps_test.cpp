// Built-in maps (spec/cli.md#builtin-maps): each parses, matches what the spec says about it, and
// the properties it was designed for hold.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "pathref/io/builtin_maps.hpp"
#include "pathref/planners/planner.hpp"

using pathref::grid::Cell;
using pathref::grid::CornerPolicy;
using pathref::grid::Grid;
namespace io = pathref::io;

namespace {

io::MapFile load(const char* name) {
  const io::BuiltinMap* b = io::find_builtin_map(name);
  REQUIRE(b != nullptr);
  return io::load_builtin_map(*b);
}

/// Sizes of the 4-connected components of blocked cells ("obstacles"), sorted.
std::vector<int> obstacle_sizes(const Grid& g) {
  std::set<std::int64_t> seen;
  std::vector<int> sizes;
  for (std::int64_t i = 0; i < g.cell_count(); ++i) {
    if (!g.blocked(g.cell(i)) || seen.count(i)) continue;
    int n = 0;
    std::vector<Cell> stack{g.cell(i)};
    seen.insert(i);
    while (!stack.empty()) {
      const Cell c = stack.back();
      stack.pop_back();
      ++n;
      for (const Cell d : {Cell{1, 0}, Cell{-1, 0}, Cell{0, 1}, Cell{0, -1}}) {
        const Cell m{c.x + d.x, c.y + d.y};
        if (g.in_bounds(m) && g.blocked(m) && seen.insert(g.index(m)).second) stack.push_back(m);
      }
    }
    sizes.push_back(n);
  }
  std::sort(sizes.begin(), sizes.end());
  return sizes;
}

/// Whether some diagonal step between free cells is allowed under `weaker` but not `stronger`.
bool policy_matters(const Grid& g, CornerPolicy stronger, CornerPolicy weaker) {
  for (std::int64_t i = 0; i < g.cell_count(); ++i) {
    const Cell a = g.cell(i);
    for (const Cell d : {Cell{1, 1}, Cell{1, -1}}) {
      const Cell b{a.x + d.x, a.y + d.y};
      if (pathref::grid::step_allowed(g, a, b, weaker) && !pathref::grid::step_allowed(g, a, b, stronger))
        return true;
    }
  }
  return false;
}

/// Shortest start-goal length under `policy` by the registered Dijkstra planner.
double shortest(const io::MapFile& m, CornerPolicy policy) {
  const auto* dijkstra = pathref::planners::find_planner("dijkstra");
  REQUIRE(dijkstra != nullptr);
  pathref::planners::Request r;
  r.grid = &m.grid;
  r.start = *m.start;
  r.goal = *m.goal;
  r.policy = policy;
  const auto res = dijkstra->run(r);
  REQUIRE(res.found);
  return res.length;
}

}  // namespace

TEST_CASE("builtin maps: every built-in parses, is named, sorted, with free start and goal",
          "[builtin_maps]") {
  const auto& all = io::builtin_maps();
  REQUIRE(all.size() >= 2);
  for (std::size_t i = 0; i < all.size(); ++i) {
    INFO(all[i].name);
    if (i > 0) CHECK(all[i - 1].name < all[i].name);
    const io::MapFile m = io::load_builtin_map(all[i]);
    CHECK(m.name == all[i].name);
    REQUIRE(m.start.has_value());
    REQUIRE(m.goal.has_value());
    CHECK(m.grid.free(*m.start));
    CHECK(m.grid.free(*m.goal));
    CHECK(io::find_builtin_map(all[i].name) == &all[i]);
    CHECK_FALSE(all[i].description.empty());
    CHECK_FALSE(all[i].provenance.empty());
  }
  CHECK(io::find_builtin_map("no-such-map") == nullptr);
  CHECK(io::builtin_map_names() == "grid20, shi6x6");
}

TEST_CASE("builtin maps: shi6x6 is the reconstructed 6x6 of Shi 2022 sec. 5.3.2", "[builtin_maps]") {
  const io::BuiltinMap* b = io::find_builtin_map("shi6x6");
  REQUIRE(b != nullptr);
  CHECK(std::string(b->provenance).find("RECONSTRUCTED") != std::string::npos);
  const io::MapFile m = load("shi6x6");
  // What the paper states: 6x6, S lower left, T upper right, four obstacles covering five cells.
  CHECK(m.grid.width() == 6);
  CHECK(m.grid.height() == 6);
  CHECK(*m.start == Cell{0, 0});
  CHECK(*m.goal == Cell{5, 5});
  CHECK(m.grid.blocked_count() == 5);
  CHECK(obstacle_sizes(m.grid) == std::vector<int>{1, 1, 1, 2});
  // What pathref chose (spec/cli.md#builtin-maps): cells 8, 16, 19, 20, 27.
  std::vector<std::int64_t> blocked;
  for (std::int64_t i = 0; i < 36; ++i)
    if (m.grid.blocked(m.grid.cell(i))) blocked.push_back(i);
  CHECK(blocked == std::vector<std::int64_t>{8, 16, 19, 20, 27});
  // Designed property: the diagonal S-T is free, but strict forbids three of its steps.
  int strict_ok = 0;
  for (std::int64_t k = 0; k < 5; ++k) {
    const Cell a{k, k}, c{k + 1, k + 1};
    CHECK(pathref::grid::step_allowed(m.grid, a, c, CornerPolicy::one));
    strict_ok += pathref::grid::step_allowed(m.grid, a, c, CornerPolicy::strict) ? 1 : 0;
  }
  CHECK(strict_ok == 2);
  CHECK(shortest(m, CornerPolicy::never) == Approx(10.0).epsilon(1e-12));
  CHECK(shortest(m, CornerPolicy::strict) == Approx(6.0 + 2.0 * std::numbers::sqrt2).epsilon(1e-12));
  CHECK(shortest(m, CornerPolicy::one) == Approx(5.0 * std::numbers::sqrt2).epsilon(1e-12));
  CHECK(shortest(m, CornerPolicy::always) == Approx(5.0 * std::numbers::sqrt2).epsilon(1e-12));
}

TEST_CASE("builtin maps: grid20 gives another shortest length under each corner policy",
          "[builtin_maps]") {
  const io::MapFile m = load("grid20");
  CHECK(m.grid.width() == 20);
  CHECK(m.grid.height() == 20);
  CHECK(*m.start == Cell{0, 0});
  CHECK(*m.goal == Cell{19, 19});
  CHECK(m.grid.blocked_count() == 92);
  CHECK(policy_matters(m.grid, CornerPolicy::strict, CornerPolicy::one));
  CHECK(policy_matters(m.grid, CornerPolicy::one, CornerPolicy::always));
  // The values stated in spec/cli.md#builtin-maps.
  const double r2 = std::numbers::sqrt2;
  CHECK(shortest(m, CornerPolicy::never) == Approx(52.0).epsilon(1e-12));
  CHECK(shortest(m, CornerPolicy::strict) == Approx(46.0 + 3.0 * r2).epsilon(1e-12));
  CHECK(shortest(m, CornerPolicy::one) == Approx(34.0 + 9.0 * r2).epsilon(1e-12));
  CHECK(shortest(m, CornerPolicy::always) == Approx(18.0 + 10.0 * r2).epsilon(1e-12));
}
