// Exact obstacle inflation (spec/inflation.md) and the polygon scene reader
// (spec/formats.md#polygon-scene-json): worked examples, the tie cells binary64 gets wrong, the
// bad-input catalogue.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "pathref/io/scene_json.hpp"
#include "pathref/core/error.hpp"
#include "pathref/geometry/decimal.hpp"
#include "pathref/geometry/inflation.hpp"
#include "pathref/geometry/scene.hpp"
#include "pathref/rules/registry.hpp"
#include "support/paths.hpp"

using namespace pathref;
using namespace pathref::geometry;
using grid::Cell;

// The test program is the second client of pathref_geometry's rules (the CLI's main is the
// first): register them before Catch2's main runs anything that builds the registry.
namespace {
const bool inflation_rules_installed = (install_inflation_rules(), true);

Scene scene_of(const std::string& polygons_json, const char* rad = "0", const char* mar = "0",
               int w = 6, int h = 3, const char* s = "1", const char* origin = "[0, 0]") {
  const std::string text = std::string("{\"format\": \"pathref-scene 1\", \"origin\": ") + origin +
                           ", \"width\": " + std::to_string(w) + ", \"height\": " + std::to_string(h) +
                           ", \"cell_size\": " + s + ", \"radius\": " + rad + ", \"margin\": " + mar +
                           ", \"polygons\": " + polygons_json + ", \"start\": [0, 0], \"goal\": [1, 0]}";
  return pathref::io::parse_scene_json(text, "t.json");
}

std::string parse_error(const std::string& text) {
  try {
    (void)pathref::io::parse_scene_json(text, "s.json");
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

std::string domain_error(const Scene& s) {
  try {
    (void)inflate_scene(s);
  } catch (const DomainError& e) {
    return e.what();
  }
  return "";
}

const char* const tri = R"([{"vertices": [[1.7, 1.5], [1, 1], [1, 2]]}])";
}  // namespace

TEST_CASE("inflation.decimal: numbers are read exactly from their text", "[inflation]") {
  CHECK(inflation_rules_installed);
  const auto d = parse_decimal("0.30");
  REQUIRE(d);
  CHECK(d->digits == "3");
  CHECK(d->exp10 == -1);
  CHECK(to_fraction(*d).numerator == "3");
  CHECK(to_fraction(*d).denominator == "10");
  CHECK(to_string(*parse_decimal("-1.25e-3")) == "-0.00125");
  CHECK(to_string(*parse_decimal("12e2")) == "1200");
  CHECK(*parse_decimal("-0") == Decimal{});
  CHECK_FALSE(parse_decimal("01"));
  CHECK_FALSE(parse_decimal("1."));
  CHECK_FALSE(parse_decimal(".5"));
  CHECK_FALSE(parse_decimal("1e31"));
  CHECK_FALSE(parse_decimal("1234567890123456789012345678901"));  // 31 digits
  CHECK(parse_decimal("1234567890123456789012345678900"));        // 30 significant digits
  // a double is read as its shortest round-trip text
  CHECK(to_string(*decimal_from_double_shortest(0.1 + 0.2)) == "0.30000000000000004");
  CHECK(to_string(*decimal_from_double_shortest(0.3)) == "0.3");
}

TEST_CASE("inflation.cell-blocked: tie cells at distance exactly r are blocked - binary64 gets them wrong",
          "[inflation]") {
  // r = 0.3 = 3/10 exactly; the vertex (1.7, 1.5) is at distance exactly 3/10 from the cell
  // [2,3] x [1,2] (tests/data/scenes/ties.json).
  const Scene s = scene_of(tri, "0.3", "0");
  CHECK(compare_cell_distance(s, 0, Cell{2, 1}) == 0);
  CHECK(cell_blocked(s, Cell{2, 1}));
  CHECK(inflate_polygons(s).to_rows_top_first() == std::vector<std::string>{"##....", "###...", "##...."});
  // binary64 rounds 1.7 down and 0.3 down: the computed distance exceeds the computed r
  const double r = 0.3;
  const double dist = 2.0 - 1.7;
  CHECK(dist == 0.30000000000000004);
  CHECK(dist * dist > r * r);  // a float implementation would leave (2,1) free
  // r = 0.1 + 0.2 is 3/10 exactly too (binary64: 0.30000000000000004)
  CHECK(compare_cell_distance(scene_of(tri, "0.1", "0.2"), 0, Cell{2, 1}) == 0);
  // just below the tie the cell is free; just above it is blocked
  CHECK(compare_cell_distance(scene_of(tri, "0.299999999999999999999"), 0, Cell{2, 1}) == 1);
  CHECK(compare_cell_distance(scene_of(tri, "0.300000000000000000001"), 0, Cell{2, 1}) == -1);
}

TEST_CASE("inflation.cell-blocked: touching at an edge or a corner blocks when r = 0", "[inflation]") {
  const Scene s = scene_of(R"([{"vertices": [[1, 1], [2, 1], [2, 2], [1, 2]]}])", "0", "0", 4, 4);
  CHECK(inflate_polygons(s).to_rows_top_first() == std::vector<std::string>{"....", "###.", "###.", "###."});
  CHECK(compare_cell_distance(s, 0, Cell{0, 0}) == 0);  // corner contact: distance 0 = r
  CHECK(compare_cell_distance(s, 0, Cell{3, 1}) == 1);
}

TEST_CASE("inflation.cell-blocked: the interior counts, not only the edges", "[inflation]") {
  const Scene s = scene_of(R"([{"vertices": [[-50, -50], [50, -50], [50, 50], [-50, 50]]}])", "0", "0", 5, 5);
  const grid::Grid g = inflate_polygons(s);
  CHECK(g.blocked_count() == 25);
  CHECK(cell_blocked(s, Cell{2, 2}));
}

TEST_CASE("inflation.cell-blocked: fast grid equals the definition on a non-convex sample scene", "[inflation]") {
  const Scene s = pathref::io::read_scene_file(pathref::testing::source_dir() + "/tests/data/scenes/ushape.json");
  const grid::Grid g = inflate_polygons(s);
  for (std::int64_t y = 0; y < s.height; ++y)
    for (std::int64_t x = 0; x < s.width; ++x) CHECK(g.blocked({x, y}) == cell_blocked(s, {x, y}));
  // the inside of the U stays free at its top: the U's arms are 2.4 m apart, r = 0.35
  CHECK_FALSE(g.blocked({9, 10}));
}

TEST_CASE("inflation.cell-blocked: invalid polygons are DomainErrors with a JSON pointer", "[inflation]") {
  const auto err = [](const char* polys) {
    try {
      validate_polygons(scene_of(polys));
    } catch (const DomainError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(err(R"([{"vertices": [[0, 0], [1, 1]]}])") ==
        "/polygons/0: degenerate polygon: expected at least 3 vertices, got 2");
  CHECK(err(R"([{"vertices": [[0, 0], [1, 0], [0, 1]]}, {"vertices": [[0, 0], [2, 0], [2, 2], [0, 0]]}])") ==
        "/polygons/1: degenerate polygon: vertices 3 and 0 are equal (zero-length edge; do not repeat the first vertex)");
  CHECK(err(R"([{"vertices": [[0, 0], [1, 1], [2.5, 2.5]]}])") ==
        "/polygons/0: degenerate polygon: all vertices are collinear (zero area)");
  CHECK(err(R"([{"vertices": [[0, 0], [2, 0], [2, 2], [2, 1], [0, 2]]}])") ==
        "/polygons/0: self-intersecting polygon: edges at vertex 2 overlap (the boundary turns back on itself)");
  CHECK(err(R"([{"vertices": [[0, 0], [2, 2], [2, 0], [0, 2]]}])") ==
        "/polygons/0: self-intersecting polygon: two non-consecutive edges meet");
  CHECK(err(R"([{"vertices": [[0, 0], [2, 0], [2, 2], [1, 0], [0, 2]]}])") ==
        "/polygons/0: self-intersecting polygon: two non-consecutive edges meet");
  // a straight-through vertex in the middle of a side is fine, so is a non-convex polygon
  CHECK(err(R"([{"vertices": [[0, 0], [1, 0], [2, 0], [2, 2], [1, 1], [0, 2]]}])").empty());
}

TEST_CASE("inflation.scene: start and goal catalogue", "[inflation]") {
  Scene s = scene_of(tri, "0.3", "0");
  s.start = Cell{3, 0};
  s.goal = Cell{5, 2};
  const InflatedScene ok = inflate_scene(s);
  CHECK(ok.start == Cell{3, 0});
  CHECK(ok.goal == Cell{5, 2});
  s.start = Cell{2, 1};
  CHECK(domain_error(s) == "/start: cell (2, 1) is blocked by an inflated obstacle");
  s.start = Cell{-1, 0};
  CHECK(domain_error(s) == "/start: cell (-1, 0) is outside the 6x3 map");
  s.start = Cell{3, 0};
  s.goal = Cell{6, 0};
  CHECK(domain_error(s) == "/goal: cell (6, 0) is outside the 6x3 map");
  s.goal = Cell{3, 0};
  CHECK(domain_error(s) == "/goal: equals the start cell (3, 0)");
  s.goal.reset();
  CHECK(domain_error(s) == "/goal: missing (a scene to plan on needs start and goal)");
}

TEST_CASE("inflation.grid: closed squares, exact tie at r = s = 0.3", "[inflation]") {
  const grid::Grid m = grid::Grid::from_rows_top_first({".....", ".....", "..#..", ".....", "....."});
  CHECK(inflate_grid(m, *parse_decimal("1"), *parse_decimal("0")).to_rows_top_first() ==
        std::vector<std::string>{".....", ".###.", ".###.", ".###.", "....."});
  CHECK(inflate_grid(m, *parse_decimal("0.3"), *parse_decimal("0.3")).to_rows_top_first() ==
        std::vector<std::string>{".###.", "#####", "#####", "#####", ".###."});
  CHECK(inflate_grid(m, *parse_decimal("0.3"), *parse_decimal("0.29999999999")).to_rows_top_first() ==
        std::vector<std::string>{".....", ".###.", ".###.", ".###.", "....."});
  CHECK_THROWS_AS(inflate_grid(m, *parse_decimal("0"), *parse_decimal("1")), DomainError);
}

TEST_CASE("formats.scene: reader errors carry the line, column and JSON pointer of the value", "[inflation][formats]") {
  const std::string head = R"({"format": "pathref-scene 1", "origin": [0, 0], "width": 4, "height": 4, "cell_size": 0.5, "radius": 0.2, "margin": 0, "start": [0, 0], "goal": [3, 3], )";
  CHECK(parse_error(head + R"("polygons": [{"vertices": [[0, 0], [1, 0], [1, "x"]]}]})") ==
        "s.json:1:200: /polygons/0/vertices/2/1: expected a number (at most 30 significant digits, |exponent| <= 30), got a string");
  CHECK(parse_error(head + R"("polygons": [{"vertices": [[0, 0], [1, 0], [1, 1e99]]}]})") ==
        "s.json:1:200: /polygons/0/vertices/2/1: expected a number (at most 30 significant digits, |exponent| <= 30), got 1e99");
  CHECK(parse_error(head + R"("polygons": [], "extra": 1})") ==
        "s.json:1:178: /extra: unknown key (expected one of format, name, origin, width, height, cell_size, radius, margin, polygons, start, goal)");
  CHECK(parse_error(head + R"("polygons": [{"vertices": [[0, 0]], "holes": []}]})") ==
        "s.json:1:198: /polygons/0/holes: unknown key (expected \"vertices\")");
  CHECK(parse_error(head + R"("polygons": [], "radius": 1})") .find("the key \"radius\" appears twice") != std::string::npos);
  CHECK(parse_error(R"({"format": "pathref-scene 1", "origin": [0, 0], "width": 4.0, "height": 4, "cell_size": 1, "radius": 0, "margin": 0, "polygons": [], "start": [0, 0], "goal": [1, 1]})") ==
        "s.json:1:58: /width: expected an integer in [1, 268435456], got a non-integer number");
  // width or height 0 (a JSON unsigned integer): refused at its value, not later as "start ... is
  // not free" or a DomainError without a pointer (issue 27)
  CHECK(parse_error(R"({"format": "pathref-scene 1", "origin": [0, 0], "width": 0, "height": 4, "cell_size": 1, "radius": 0, "margin": 0, "polygons": [], "start": [0, 0], "goal": [1, 1]})") ==
        "s.json:1:58: /width: expected an integer in [1, 268435456], got 0");
  CHECK(parse_error(R"({"format": "pathref-scene 1", "origin": [0, 0], "width": 4, "height": 0, "cell_size": 1, "radius": 0, "margin": 0, "polygons": [], "start": [0, 0], "goal": [1, 1]})") ==
        "s.json:1:71: /height: expected an integer in [1, 268435456], got 0");
  CHECK(parse_error(R"({"format": "pathref-scene 1", "origin": [0, 0], "width": 4, "height": 4, "cell_size": 0, "radius": 0, "margin": 0, "polygons": [], "start": [0, 0], "goal": [1, 1]})") ==
        "s.json:1:87: /cell_size: expected a number > 0, got 0");
  CHECK(parse_error(R"({"format": "pathref-scene 1", "origin": [0, 0], "width": 4, "height": 4, "cell_size": 1, "radius": -0.1, "margin": 0, "polygons": [], "start": [0, 0], "goal": [1, 1]})") ==
        "s.json:1:100: /radius: expected a number >= 0, got -0.1");
  CHECK(parse_error(R"({"format": "pathref-scene 1", "origin": [0, 0], "width": 4, "height": 4, "cell_size": 1, "radius": 0, "margin": 0, "polygons": []})") ==
        "s.json:1:1: /: missing key \"start\"");
  CHECK(parse_error("{\n  \"format\": ,\n}") .rfind("s.json:2:13: expected valid JSON", 0) == 0);
  CHECK(parse_error("[]") == "s.json:1:1: /: expected a JSON object (a pathref-scene 1), got an array");
}

TEST_CASE("formats.scene: to_scene_json round trip keeps every number exact", "[inflation][formats]") {
  const Scene s = pathref::io::read_scene_file(pathref::testing::source_dir() + "/tests/data/scenes/ushape.json");
  CHECK(pathref::io::parse_scene_json(pathref::io::to_scene_json(s), "again.json") == s);
  CHECK(to_string(s.polygons[0].vertices[0].x) == "2.3");
}

TEST_CASE("inflation rules are registered for eval and golden", "[inflation]") {
  const auto& reg = rules::registry();
  REQUIRE(reg.find("inflation.cell-blocked") != nullptr);
  REQUIRE(reg.find("inflation.grid") != nullptr);
  REQUIRE(reg.find("inflation.scene") != nullptr);
  const rules::Json in = rules::Json::parse(
      R"({"origin": [0, 0], "width": 6, "height": 3, "cell_size": 1, "radius": 0.1, "margin": 0.2,
          "polygons": [{"vertices": [[2.7, 1.5], [2, 1], [2, 2]]}]})");
  CHECK(reg.find("inflation.cell-blocked")->eval(in)["blocked"] == 7);
}
