// spec: search.h.manhattan, search.h.chebyshev, search.h.octile, search.h.euclidean, search.admissible, search.order, search.astar, search.dijkstra
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/equations/heuristics.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/planners/search.hpp"
#include "support/paths.hpp"

using namespace pathref;
using grid::Cell;
using grid::CornerPolicy;
using grid::Grid;
using heuristics::Heuristic;

namespace {

constexpr double s = std::numbers::sqrt2;
constexpr double u = 0x1p-53;  // unit roundoff of binary64

std::vector<Cell> cells(std::initializer_list<std::pair<int, int>> xy) {
  std::vector<Cell> v;
  for (const auto& [x, y] : xy) v.push_back(Cell{x, y});
  return v;
}

/// |length - (a + b*sqrt2)| within the bound of spec/search.md guarantee 2: a left-to-right sum
/// of k = a + b terms is within (k - 1)*u*L of the exact sum of its terms, and the terms
/// themselves (s for sqrt2) add b*u*sqrt2; (k + 2)*u*L covers both.
bool near_exact(double length, std::int64_t a, std::int64_t b) {
  const double exact = static_cast<double>(a) + static_cast<double>(b) * s;
  const auto k = static_cast<double>(a + b);
  return std::fabs(length - exact) <= (k + 2.0) * u * exact;
}

/// Reads a 0/1 matrix (first line = top row, 1 = obstacle) as rows of '.'/'#'; nullopt when the
/// file cannot be opened. Fails the test on any other character.
std::optional<Grid> read_01_map(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::vector<std::string> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream tokens(line);
    std::string row;
    std::string t;
    while (tokens >> t) {
      REQUIRE((t == "0" || t == "1"));
      row.push_back(t == "1" ? '#' : '.');
    }
    if (!row.empty()) rows.push_back(row);
  }
  return Grid::from_rows_top_first(rows);
}

}  // namespace

TEST_CASE("search.h: hand values of the four heuristics", "[search]") {
  const Cell o{0, 0};
  CHECK(heuristics::manhattan(Cell{3, 1}, o) == 4.0);
  CHECK(heuristics::chebyshev(Cell{3, 1}, o) == 3.0);
  CHECK(heuristics::chebyshev(Cell{2, 7}, Cell{5, 1}) == 6.0);
  CHECK(heuristics::octile(Cell{3, 0}, o) == 3.0);
  CHECK(heuristics::octile(Cell{1, 1}, o) == s);
  CHECK(heuristics::octile(Cell{5, 3}, o) == 2.0 + 3.0 * s);  // the normative evaluation order
  CHECK(heuristics::euclidean(Cell{3, 4}, o) == 5.0);
  CHECK(heuristics::euclidean(Cell{1, 1}, o) == s);  // sqrt(2.0) is correctly rounded
  for (const Heuristic h : {Heuristic::zero, Heuristic::manhattan, Heuristic::chebyshev,
                            Heuristic::octile, Heuristic::euclidean}) {
    CHECK(heuristics::evaluate(h, Cell{-4, 9}, Cell{-4, 9}) == 0.0);
  }
  CHECK(heuristics::evaluate(Heuristic::zero, Cell{7, 7}, o) == 0.0);
}

TEST_CASE("search.h: coordinates at and beyond 2^30 raise DomainError", "[search]") {
  const std::int64_t lim = std::int64_t{1} << 30;
  const Cell edge{lim - 1, -(lim - 1)};
  CHECK(heuristics::manhattan(edge, Cell{-(lim - 1), lim - 1}) == 4294967292.0);
  CHECK_THROWS_AS(heuristics::manhattan(Cell{lim, 0}, Cell{0, 0}), DomainError);
  CHECK_THROWS_AS(heuristics::chebyshev(Cell{0, 0}, Cell{0, -lim}), DomainError);
  CHECK_THROWS_AS(heuristics::octile(Cell{-lim, 0}, Cell{0, 0}), DomainError);
  CHECK_THROWS_AS(heuristics::euclidean(Cell{0, lim}, Cell{0, 0}), DomainError);
  CHECK_THROWS_AS(heuristics::evaluate(Heuristic::zero, Cell{0, lim}, Cell{0, 0}), DomainError);
}

TEST_CASE("search.h: names parse and unknown names are UsageErrors", "[search]") {
  for (const char* name : {"zero", "manhattan", "chebyshev", "octile", "euclidean"})
    CHECK(heuristics::to_string(heuristics::parse_heuristic(name)) == name);
  CHECK_THROWS_AS(heuristics::parse_heuristic("Octile"), UsageError);
  CHECK_THROWS_AS(heuristics::parse_heuristic(""), UsageError);
}

TEST_CASE("search.admissible: the table of spec/search.md", "[search]") {
  // Rows: zero, manhattan, chebyshev, octile, euclidean; columns: never, strict, one, always.
  const Heuristic hs[] = {Heuristic::zero, Heuristic::manhattan, Heuristic::chebyshev,
                          Heuristic::octile, Heuristic::euclidean};
  const CornerPolicy ps[] = {CornerPolicy::never, CornerPolicy::strict, CornerPolicy::one,
                             CornerPolicy::always};
  const bool table[5][4] = {{true, true, true, true},
                            {true, false, false, false},
                            {true, true, true, true},
                            {true, true, true, true},
                            {true, true, true, true}};
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 4; ++j) {
      INFO(heuristics::to_string(hs[i]) << " / " << grid::to_string(ps[j]));
      CHECK(heuristics::admissible(hs[i], ps[j]) == table[i][j]);
      CHECK(heuristics::consistent(hs[i], ps[j]) == table[i][j]);
    }
  }
}

TEST_CASE("search.order: f, then h, then index", "[search]") {
  using search::OpenKey;
  CHECK(search::precedes(OpenKey{1.0, 5.0, 9}, OpenKey{2.0, 0.0, 0}));
  CHECK(search::precedes(OpenKey{3.0, 1.0, 7}, OpenKey{3.0, 2.0, 0}));
  CHECK(search::precedes(OpenKey{3.0, 1.0, 3}, OpenKey{3.0, 1.0, 4}));
  CHECK_FALSE(search::precedes(OpenKey{3.0, 1.0, 4}, OpenKey{3.0, 1.0, 4}));
  // Ties are ties of the doubles: one ulp apart is not a tie.
  CHECK(search::precedes(OpenKey{2.0 + s, 2.0, 9}, OpenKey{std::nextafter(2.0 + s, 4.0), 0.0, 0}));
}

TEST_CASE("search.astar: worked example of the spec (free 3x2, two shortest paths)", "[search]") {
  const Grid g = Grid::from_rows_top_first({"...", "..."});
  const auto a = search::astar(g, Cell{0, 0}, Cell{2, 1}, CornerPolicy::strict, Heuristic::octile);
  const auto d = search::dijkstra(g, Cell{0, 0}, Cell{2, 1}, CornerPolicy::strict);
  REQUIRE(a.found);
  REQUIRE(d.found);
  CHECK(a.path == cells({{0, 0}, {1, 1}, {2, 1}}));
  CHECK(a.expansions == 3);
  CHECK(d.path == cells({{0, 0}, {1, 0}, {2, 1}}));
  CHECK(d.expansions == 6);
  CHECK(a.length == 1.0 + s);  // fl(s + 1) == fl(1 + s): addition is commutative
  CHECK(d.length == 1.0 + s);
}

TEST_CASE("search.astar: start equal to goal", "[search]") {
  const Grid g = Grid::from_rows_top_first({"...", ".#."});
  const auto r = search::astar(g, Cell{2, 1}, Cell{2, 1}, CornerPolicy::strict, Heuristic::octile);
  CHECK(r.found);
  CHECK(r.path == cells({{2, 1}}));
  CHECK(r.length == 0.0);
  CHECK(r.expansions == 1);
}

TEST_CASE("search.astar: start or goal blocked or outside raise DomainError", "[search]") {
  const Grid g = Grid::from_rows_top_first({"#.", ".."});  // (0,1) blocked
  for (const Heuristic h : {Heuristic::octile, Heuristic::zero}) {
    CHECK_THROWS_AS(search::astar(g, Cell{0, 1}, Cell{1, 0}, CornerPolicy::strict, h), DomainError);
    CHECK_THROWS_AS(search::astar(g, Cell{1, 0}, Cell{0, 1}, CornerPolicy::strict, h), DomainError);
    CHECK_THROWS_AS(search::astar(g, Cell{-1, 0}, Cell{1, 0}, CornerPolicy::strict, h), DomainError);
    CHECK_THROWS_AS(search::astar(g, Cell{1, 0}, Cell{2, 0}, CornerPolicy::strict, h), DomainError);
  }
  CHECK_THROWS_AS(search::dijkstra(g, Cell{0, 0}, Cell{0, 2}, CornerPolicy::always), DomainError);
}

TEST_CASE("search.astar: an unreachable goal reports found = false", "[search]") {
  const Grid g = Grid::from_rows_top_first({"..#..", "..#..", "..#..", "..#..", "..#.."});
  for (const CornerPolicy p :
       {CornerPolicy::never, CornerPolicy::strict, CornerPolicy::one, CornerPolicy::always}) {
    for (const Heuristic h : {Heuristic::octile, Heuristic::manhattan, Heuristic::zero}) {
      const auto r = search::astar(g, Cell{0, 0}, Cell{4, 4}, p, h);
      CHECK_FALSE(r.found);
      CHECK(r.path.empty());
      CHECK(r.length == 0.0);
      CHECK(r.expansions == 10);  // the start's component: columns 0 and 1
    }
  }
}

TEST_CASE("search.astar: diagonal squeeze per corner policy", "[search]") {
  const Grid both = Grid::from_rows_top_first({".#", "#."});
  const Grid one = Grid::from_rows_top_first({"..", "#."});
  const Cell a{0, 1};
  const Cell b{1, 0};
  CHECK_FALSE(search::dijkstra(both, a, b, CornerPolicy::strict).found);
  CHECK_FALSE(search::dijkstra(both, a, b, CornerPolicy::one).found);
  CHECK(search::dijkstra(both, a, b, CornerPolicy::always).length == s);
  CHECK(search::dijkstra(one, a, b, CornerPolicy::never).length == 2.0);
  CHECK(search::dijkstra(one, a, b, CornerPolicy::strict).length == 2.0);
  CHECK(search::dijkstra(one, a, b, CornerPolicy::one).length == s);
  CHECK(search::dijkstra(one, a, b, CornerPolicy::always).length == s);
}

TEST_CASE("search.astar: manhattan under strict can return a longer path (spec example)", "[search]") {
  const Grid g = Grid::from_rows_top_first({"...", "...", ".#.", "..."});
  const auto m = search::astar(g, Cell{2, 0}, Cell{0, 3}, CornerPolicy::strict, Heuristic::manhattan);
  const auto o = search::astar(g, Cell{2, 0}, Cell{0, 3}, CornerPolicy::strict, Heuristic::octile);
  CHECK(m.path == cells({{2, 0}, {1, 0}, {0, 0}, {0, 1}, {0, 2}, {0, 3}}));
  CHECK(m.length == 5.0);
  CHECK(m.expansions == 6);
  CHECK(search::step_counts(o.path) == search::StepCounts{3, 1});
  CHECK(m.length <= s * o.length);  // guarantee 4
}

TEST_CASE("search.astar: length is metrics.length of the path, bit for bit", "[search]") {
  const Grid g = Grid::from_rows_top_first({".....", ".....", "####.", ".....", "....."});
  for (const CornerPolicy p :
       {CornerPolicy::never, CornerPolicy::strict, CornerPolicy::one, CornerPolicy::always}) {
    const auto r = search::astar(g, Cell{0, 0}, Cell{0, 4}, p, Heuristic::octile);
    REQUIRE(r.found);
    CHECK(r.length == metrics::path_length(r.path));
    const auto check = metrics::validate_path(g, r.path, Cell{0, 0}, Cell{0, 4}, p);
    CHECK(check.valid);
  }
}

TEST_CASE("search.astar: step_counts rejects non-adjacent cells", "[search]") {
  const auto ok = cells({{0, 0}, {1, 1}, {2, 1}, {2, 2}});
  CHECK(search::step_counts(ok) == search::StepCounts{2, 1});
  CHECK(search::step_counts({}) == search::StepCounts{0, 0});
  const auto jump = cells({{0, 0}, {2, 0}});
  CHECK_THROWS_AS(search::step_counts(jump), DomainError);
  const auto repeat = cells({{0, 0}, {0, 0}});
  CHECK_THROWS_AS(search::step_counts(repeat), DomainError);
}

TEST_CASE("planners: astar and dijkstra are registered and fill the Result", "[search]") {
  const Grid g = Grid::from_rows_top_first({"...", "..."});
  const planners::Planner* astar = planners::find_planner("astar");
  const planners::Planner* dijkstra = planners::find_planner("dijkstra");
  REQUIRE(astar != nullptr);
  REQUIRE(dijkstra != nullptr);
  planners::Request req;
  req.grid = &g;
  req.start = Cell{0, 0};
  req.goal = Cell{2, 1};
  req.policy = CornerPolicy::strict;

  const planners::Result ra = astar->run(req);
  CHECK(ra.found);
  CHECK(ra.path == cells({{0, 0}, {1, 1}, {2, 1}}));
  CHECK(ra.expansions == 3);
  CHECK(ra.params_used == planners::Json{{"heuristic", "octile"}});
  CHECK(ra.extra.at("admissible") == true);

  req.params = planners::Json{{"heuristic", "manhattan"}};
  const planners::Result rm = astar->run(req);
  CHECK(rm.params_used.at("heuristic") == "manhattan");
  CHECK(rm.extra.at("admissible") == false);
  CHECK(rm.extra.at("consistent") == false);

  req.params = planners::Json{{"heuristic", "cosine"}};
  CHECK_THROWS_AS(astar->run(req), UsageError);
  req.params = planners::Json{{"weight", 2}};
  CHECK_THROWS_AS(astar->run(req), UsageError);

  req.params = planners::Json::object();
  const planners::Result rd = dijkstra->run(req);
  CHECK(rd.path == cells({{0, 0}, {1, 0}, {2, 1}}));
  CHECK(rd.expansions == 6);
  CHECK(rd.params_used == planners::Json::object());

  planners::Request empty;
  CHECK_THROWS_AS(dijkstra->run(empty), UsageError);
}

TEST_CASE("search.astar: MATLAB 20x20 maps B and C (shared data)", "[search][data]") {
  const std::string dir = pathref::testing::shared_dir() + "/data/matlab-maps/";
  const auto map_b = read_01_map(dir + "mapB_20x20_ga.txt");
  const auto map_c = read_01_map(dir + "mapC_20x20_winsleo_traditional.txt");
  if (!map_b || !map_c) {
    pathref::testing::skip_test("the MATLAB maps are not at " + dir + " (shared data absent)");
    return;
  }
  REQUIRE(map_b->width() == 20);
  REQUIRE(map_b->height() == 20);
  REQUIRE(map_c->width() == 20);
  REQUIRE(map_c->height() == 20);
  // start = top-left of the matrix, goal = bottom-right, in lower-left coordinates.
  const Cell start{0, 19};
  const Cell goal{19, 0};
  struct Case {
    const Grid* g;
    const char* name;
    CornerPolicy policy;
    std::int64_t orthogonal;
    std::int64_t diagonal;
    double printed;  // the README's value, 6 decimals
  };
  const Case cases[] = {
      {&*map_b, "B", CornerPolicy::strict, 16, 11, 31.556349},
      {&*map_c, "C", CornerPolicy::strict, 10, 14, 29.798990},
      {&*map_b, "B", CornerPolicy::always, 14, 12, 30.970563},
      {&*map_c, "C", CornerPolicy::always, 6, 16, 28.627417},
      // The README: "at least one orthogonal free" gives the full-corner-cutting values.
      {&*map_b, "B", CornerPolicy::one, 14, 12, 30.970563},
      {&*map_c, "C", CornerPolicy::one, 6, 16, 28.627417},
  };
  for (const Case& c : cases) {
    for (const Heuristic h : {Heuristic::octile, Heuristic::chebyshev, Heuristic::zero}) {
      INFO("map " << c.name << ", " << grid::to_string(c.policy) << ", "
                  << heuristics::to_string(h));
      const auto r = search::astar(*c.g, start, goal, c.policy, h);
      REQUIRE(r.found);
      CHECK(search::step_counts(r.path) == search::StepCounts{c.orthogonal, c.diagonal});
      CHECK(near_exact(r.length, c.orthogonal, c.diagonal));
      CHECK(std::fabs(r.length - c.printed) <= 5e-7);  // README rounds to 6 decimals
      CHECK(metrics::validate_path(*c.g, r.path, start, goal, c.policy).valid);
    }
  }
}
