// Properties of the path-file reader of `pathref check` (spec/check.md#path-cells, #path-files).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/io/path_file.hpp"

using namespace pathref;
using io::PathFormat;
using io::RowOrigin;

namespace {
/// The numbers a writer with (format, base, origin) writes for cell c on a W x H map: the inverse
/// of spec/check.md#path-cells, written independently of path_cells.
std::vector<std::int64_t> encode(PathFormat f, grid::Cell c, std::int64_t w, std::int64_t h, std::int64_t base,
                                 RowOrigin o) {
  const std::int64_t row = o == RowOrigin::lower ? c.y : h - 1 - c.y;
  switch (f) {
    case PathFormat::xy: return {c.x + base, row + base};
    case PathFormat::rowcol: return {row + base, c.x + base};
    case PathFormat::node: return {row * w + c.x + base};
    default: return {};
  }
}
}  // namespace

TEST_CASE("path_cells: the documented examples on a 3x2 map", "[check]") {
  const auto cells = [](PathFormat f, std::vector<std::int64_t> v, std::int64_t base, RowOrigin o) {
    return io::path_cells(io::PathRecord{"t", f, std::move(v), nullptr}, 3, 2, base, o);
  };
  // spec/check.md: node 1 (defaults) is (0, 1), node 4 is (0, 0); rowcol 2 3 is (2, 0); xy 2 1 is (2, 1)
  CHECK(cells(PathFormat::node, {1, 4}, 1, RowOrigin::upper) == std::vector<grid::Cell>{{0, 1}, {0, 0}});
  CHECK(cells(PathFormat::rowcol, {2, 3}, 1, RowOrigin::upper) == std::vector<grid::Cell>{{2, 0}});
  CHECK(cells(PathFormat::xy, {2, 1}, 0, RowOrigin::lower) == std::vector<grid::Cell>{{2, 1}});
  // pathref's index i = y W + x is node with base 0, origin lower; negative numbers floor
  CHECK(cells(PathFormat::node, {0, 5, -1}, 0, RowOrigin::lower) == std::vector<grid::Cell>{{0, 0}, {2, 1}, {2, -1}});
  CHECK_THROWS_AS(io::path_cells(io::PathRecord{"t", PathFormat::xy, {0, 0}, nullptr}, 0, 2, 0, RowOrigin::lower),
                  DomainError);
}

TEST_CASE("parse_path_text: formats, detection and errors at their line and column", "[check]") {
  const auto one = [](std::string_view t, PathFormat f = PathFormat::automatic) {
    const auto r = io::parse_path_text(t, "p.txt", f, false);
    REQUIRE(r.size() == 1);
    return r[0];
  };
  CHECK(one("0 0\n1,0\n\n# c\n2 0;3 1").numbers == std::vector<std::int64_t>{0, 0, 1, 0, 2, 0, 3, 1});  // ';' ends a node
  CHECK(one("0 0\n1,0\n2 0 % c\n").numbers == std::vector<std::int64_t>{0, 0, 1, 0, 2, 0});
  CHECK(one("9\n10\n").format == PathFormat::node);
  CHECK(one("9 10 11").format == PathFormat::node);
  CHECK(one("[3 1;3 2]", PathFormat::rowcol).numbers == std::vector<std::int64_t>{3, 1, 3, 2});
  CHECK(one("  9.0000000e+00\n  1.0000000e+01\n").numbers == std::vector<std::int64_t>{9, 10});
  CHECK(one("[[0,0],[1,1]]").format == PathFormat::xy);
  CHECK(one("[4, 5.0]").numbers == std::vector<std::int64_t>{4, 5});
  const auto lines = io::parse_path_text("[[0,0]]\n\n[1,2]\n", "r.jsonl", PathFormat::automatic, true);
  REQUIRE(lines.size() == 2);
  CHECK(lines[1].name == "r.jsonl:3");
  CHECK(lines[1].format == PathFormat::node);
  const auto error_at = [](std::string_view t, PathFormat f, bool jl = false) {
    try {
      (void)io::parse_path_text(t, "p.txt", f, jl);
    } catch (const ParseError& e) {
      return std::to_string(e.line()) + (e.column() >= 1 ? ":c" : ":0");
    }
    return std::string("no error");
  };
  // the line is exact; the column is 1-based (its exact value is checked by tests/cli/check.sh)
  CHECK(error_at("0 0\n 1\n", PathFormat::automatic) == "2:c");
  CHECK(error_at("0 0\n1 x\n", PathFormat::xy) == "2:c");
  CHECK(error_at("0 0\n1 2 3\n", PathFormat::xy) == "2:c");
  CHECK(error_at("2147483649\n", PathFormat::node) == "1:c");
  CHECK(error_at("1.5\n", PathFormat::node) == "1:c");
  CHECK(error_at("", PathFormat::automatic) == "1:c");
  CHECK(error_at("[[0,0],\n\n [1,", PathFormat::automatic) == "3:c");
  CHECK(error_at("[[0,0]]\n[1,\n", PathFormat::automatic, true) == "2:c");
  CHECK(error_at("{\"format\": \"x\"}", PathFormat::automatic) == "1:c");
  CHECK(error_at("[[0,0]]", PathFormat::node) == "1:c");
}

TEST_CASE("prop_path_cells_inverts_every_writer_convention", "[check][prop]") {
  rc::prop("encode then path_cells gives the cells back, for every format, base and origin", [] {
    const auto w = *rc::gen::inRange<std::int64_t>(1, 50);
    const auto h = *rc::gen::inRange<std::int64_t>(1, 50);
    const auto n = *rc::gen::inRange<std::size_t>(1, 20);
    const auto f = *rc::gen::element(PathFormat::xy, PathFormat::rowcol, PathFormat::node);
    const auto base = *rc::gen::inRange<std::int64_t>(0, 2);
    const auto o = *rc::gen::element(RowOrigin::lower, RowOrigin::upper);
    std::vector<grid::Cell> cells;
    io::PathRecord rec{"p", f, {}, nullptr};
    std::string text;
    for (std::size_t i = 0; i < n; ++i) {
      const grid::Cell c{*rc::gen::inRange<std::int64_t>(0, w), *rc::gen::inRange<std::int64_t>(0, h)};
      cells.push_back(c);
      for (const std::int64_t v : encode(f, c, w, h, base, o)) {
        rec.numbers.push_back(v);
        text += std::to_string(v) + " ";
      }
      text += "\n";
    }
    RC_ASSERT(io::path_cells(rec, w, h, base, o) == cells);
    // and the text a writer produces reads back to the same numbers under the explicit format
    const auto back = io::parse_path_text(text, "w.txt", f, false);
    RC_ASSERT(back.size() == 1u);
    RC_ASSERT(back[0].numbers == rec.numbers);
  });
}
