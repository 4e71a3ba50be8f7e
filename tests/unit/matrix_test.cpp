// 0/1 matrix reader/writers (plain rows and MATLAB `G=[...]`): worked examples, the catalogue of
// every error message, the samples in tests/data and the shared MATLAB maps
// (spec/formats.md#matrix).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/io/matrix.hpp"
#include "pathref/planners/search.hpp"
#include "support/paths.hpp"

using pathref::ParseError;
using pathref::grid::Cell;
using pathref::grid::Grid;
using namespace pathref::io;

namespace {

std::string matrix_error(const std::string& text, const ReadLimits& limits = {}) {
  try {
    (void)parse_matrix(text, "g.m", limits);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("matrix: plain rows and MATLAB forms read the same grid - first row is the top", "[matrix]") {
  const Grid want = Grid::from_rows_top_first({"..#", "#.."});
  CHECK(parse_matrix("0 0 1\n1 0 0\n", "a").grid == want);
  CHECK(parse_matrix("% map\n\n  0\t0  1 \n1,0 , 0 % trailing\n\n", "b").grid == want);
  CHECK(parse_matrix("G=[0 0 1;1 0 0];", "c").grid == want);
  CHECK(parse_matrix("G = [0 0 1\n     1 0 0]", "d").grid == want);
  CHECK(parse_matrix("% comment\nmap_1 = [ 0, 0, 1 ; ... continued\n 1 0 0 ; ] ; % end\n\n% more\n", "e").grid ==
        want);
  CHECK(parse_matrix("G=[0 0 ...\n1\n1 0 0]", "f").grid == want);
  CHECK(parse_matrix("[0 0 1;;\n\n;1 0 0]", "g").grid == want);  // empty rows are no rows (MATLAB)
  CHECK(parse_matrix("G=[0 0 1 % first row\n1 0 0];", "h").grid == want);
  CHECK(parse_matrix("0 0 1\r\n1 0 0\r\n", "crlf").grid == want);
  const MapFile m = parse_matrix("1\n", "one");
  CHECK(m.grid.blocked(Cell{0, 0}));
  CHECK_FALSE(m.start.has_value());
}

TEST_CASE("matrix: writers", "[matrix]") {
  const Grid g = Grid::from_rows_top_first({"..#", "#.."});
  CHECK(to_matrix_text(g) == "0 0 1\n1 0 0\n");
  CHECK(to_matlab_text(g) == "G = [0 0 1\n     1 0 0];\n");
  CHECK(parse_matrix(to_matrix_text(g), "rt").grid == g);
  CHECK(parse_matrix(to_matlab_text(g), "rt").grid == g);
}

TEST_CASE("matrix: catalogue of malformed matrices with their exact messages", "[matrix]") {
  struct Case {
    std::string input;
    const char* message;
  };
  const std::vector<Case> cases = {
      {"", "g.m:1:1: expected a matrix of 0s and 1s (plain rows or NAME = [...]), got an empty file"},
      {"\xEF\xBB\xBF" "0 1\n",
       "g.m:1:1: expected a matrix of 0s and 1s (plain rows or NAME = [...]), got a UTF-8 byte-order mark "
       "(save the file without it)"},
      {"% only a comment\n\n",
       "g.m:3:1: unexpected end of file: expected a matrix of 0s and 1s (plain rows or NAME = [...])"},
      {"0 2 1\n", "g.m:1:3: expected 0 (free) or 1 (obstacle), got '2'"},
      {"0 1.0\n", "g.m:1:3: expected 0 (free) or 1 (obstacle), got '1.0'"},
      {"0 -1\n", "g.m:1:3: expected 0 (free) or 1 (obstacle), got '-1'"},
      {"0 01\n", "g.m:1:3: expected 0 (free) or 1 (obstacle), got '01'"},
      {"0 1;\n", "g.m:1:3: expected 0 (free) or 1 (obstacle), got '1;'"},
      {"0 \xC3\xA9\n", "g.m:1:3: expected 0 (free) or 1 (obstacle), got byte 0xc3"},
      {"0 1\x01\n", "g.m:1:4: expected 0 (free) or 1 (obstacle), got byte 0x01"},
      {",0 1\n", "g.m:1:1: expected 0 (free) or 1 (obstacle), got ','"},
      {"0,,1\n", "g.m:1:3: expected 0 (free) or 1 (obstacle), got ','"},
      {"0 1,\n", "g.m:1:4: expected a value after ','"},
      {"0 1 0\n0 1\n", "g.m:2:4: expected 3 values in row 2 (as many as row 1), got 2"},
      {"0 1\n0 1 0\n", "g.m:2:5: expected end of row 2 after 2 values (as many as row 1)"},
      {"0 1\n\n0 1\n",
       "g.m:3:1: expected end of file after the 1 matrix rows (a blank line ended the matrix on line 2)"},
      {"0 1\r1 0\n", "g.m:1:4: unexpected carriage return (lines must end in LF or CRLF)"},
      {"%{\nblock\n%}\n0 1\n", "g.m:1:1: block comments (%{ ... %}) are not supported; start each comment line with %"},
      {"G [0 1]\n", "g.m:1:3: expected '=' after 'G'"},
      {"G\n", "g.m:1:2: expected '=' after 'G'"},
      {"G = zeros(20);\n", "g.m:1:5: expected '[' after 'G ='"},
      {"G = [0 1; 1 0]'\n", "g.m:1:15: expected ';', a % comment or end of line after ']'"},
      {"G = [0 1; 1 0]; H = 1;\n", "g.m:1:17: expected ';', a % comment or end of line after ']'"},
      {"G = [0 1; 1 0];\nH = [1];\n", "g.m:2:1: expected end of file after the matrix (one assignment per file)"},
      {"G = [];\n", "g.m:1:6: expected at least one row of 0s and 1s before ']'"},
      {"G = [0 1;\n1 0\n", "g.m:3:1: unexpected end of file: expected ']' to close the '[' of line 1"},
      {"G = [0 1; 1 0 1]\n", "g.m:1:15: expected end of row 2 after 2 values (as many as row 1)"},
      {"G = [0 1 0; 1 0]\n", "g.m:1:16: expected 3 values in row 2 (as many as row 1), got 2"},
      {"G = [0 1, ; 1 0]\n", "g.m:1:9: expected a value after ','"},
      {"G = [0 1,\n1 0]\n", "g.m:1:9: expected a value after ','"},
      {"G = [0 x]\n", "g.m:1:8: expected 0 (free) or 1 (obstacle), got 'x'"},
      {"G = [[0 1]]\n", "g.m:1:6: expected 0 (free) or 1 (obstacle), got '[0'"},
      {"G = [0 1\n%{\n1 0]\n", "g.m:2:1: block comments (%{ ... %}) are not supported; start each comment line with %"},
  };
  for (const Case& c : cases) {
    INFO("input: " << c.input);
    CHECK(matrix_error(c.input) == c.message);
  }
}

TEST_CASE("matrix: limits are checked while reading, before the grid exists", "[matrix]") {
  const ReadLimits small{3, 6};
  CHECK(matrix_error("0 0 0 0\n", small) == "g.m:1:7: row 1 has more than 3 values (the limit on the width)");
  CHECK(matrix_error("0\n0\n0\n0\n", small) == "g.m:4:1: more than 3 rows (the limit on the height)");
  CHECK(matrix_error("0 0 0\n0 0 0\n0 0 0\n", small) ==
        "g.m:3:1: a matrix of 3 columns and 3 rows exceeds the limit of 6 cells");
  CHECK(matrix_error("0 0 0\n", ReadLimits{10, 2}) ==
        "g.m:1:5: a matrix of 3 columns and 1 rows exceeds the limit of 2 cells");
  CHECK(matrix_error("G=[0 0;0 0;0 0;0 0]", small) == "g.m:1:16: more than 3 rows (the limit on the height)");
}

TEST_CASE("matrix: the samples in tests/data read the same map and round-trip", "[matrix][samples]") {
  const std::string dir = pathref::testing::source_dir() + "/tests/data/matrix/";
  const LoadedMapFile m = load_map_file(dir + "warehouse.m", {});
  const LoadedMapFile t = load_map_file(dir + "warehouse.txt", {});
  CHECK(m.format == MapFormat::matrix);
  CHECK(t.format == MapFormat::matrix);
  CHECK(m.map.grid == t.map.grid);
  CHECK(m.map.grid.width() == 12);
  CHECK(m.map.grid.height() == 9);
  CHECK(m.map.grid.blocked_count() == 32);
  CHECK(m.map.grid.blocked(Cell{0, 4}));  // matrix row 5, column 1
  CHECK(parse_matrix(to_matrix_text(m.map.grid), "rt").grid == m.map.grid);
  CHECK(parse_matrix(to_matlab_text(m.map.grid), "rt").grid == m.map.grid);
}

TEST_CASE("matrix: shared MATLAB maps B and C give the published strict-policy optima",
          "[matrix][shared]") {
  const std::string dir = pathref::testing::shared_dir() + "/data/matlab-maps/";
  if (!std::filesystem::exists(dir)) {
    pathref::testing::skip_test(dir + " is absent (shared data)");
    return;
  }
  struct Expect {
    const char* file;
    double length;
    double exact;
  };
  for (const Expect& e : {Expect{"mapC_20x20_winsleo_traditional.txt", 29.798990, 10 + 14 * std::numbers::sqrt2},
                          Expect{"mapB_20x20_ga.txt", 31.556349, 16 + 11 * std::numbers::sqrt2}}) {
    INFO(e.file);
    const LoadedMapFile lm = load_map_file(dir + e.file, {});
    const Grid& g = lm.map.grid;
    REQUIRE(g.width() == 20);
    REQUIRE(g.height() == 20);
    // Start = top-left cell of the matrix, goal = bottom-right cell.
    const auto out = pathref::search::astar(g, Cell{0, g.height() - 1}, Cell{g.width() - 1, 0},
                                            pathref::grid::CornerPolicy::strict,
                                            pathref::heuristics::Heuristic::octile);
    REQUIRE(out.found);
    CHECK(std::abs(out.length - e.length) <= 5e-7);
    CHECK(std::abs(out.length - e.exact) <= 1e-12);
  }
}
