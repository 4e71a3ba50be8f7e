// pathref-grid 1 reader/writer: worked examples and the catalogue of every error message
// (spec/formats.md#pathref-grid-1, "Errors").
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/io/grid_text.hpp"
#include "support/paths.hpp"

using pathref::ParseError;
using pathref::grid::Cell;
using pathref::grid::Grid;
using pathref::io::MapFile;
using pathref::io::parse_grid_text;
using pathref::io::to_grid_text;

namespace {

/// The message of the ParseError that parsing `text` throws ("" if it parses).
std::string parse_error(const std::string& text) {
  try {
    (void)parse_grid_text(text, "m.txt");
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("grid-text: the spec example parses, first row is the top", "[grid_text]") {
  const std::string text =
      "pathref-grid 1\n"
      "# a comment\n"
      "\n"
      "name demo map\n"
      "size 4 3\n"
      "start 0 0\n"
      "goal 2 2\n"
      "map\n"
      "...#\n"
      ".#..\n"
      "....\n";
  const MapFile m = parse_grid_text(text, "demo.txt");
  CHECK(m.grid.width() == 4);
  CHECK(m.grid.height() == 3);
  CHECK(m.name == "demo map");
  REQUIRE(m.start.has_value());
  REQUIRE(m.goal.has_value());
  CHECK(*m.start == Cell{0, 0});
  CHECK(*m.goal == Cell{2, 2});
  CHECK(m.grid.blocked(Cell{3, 2}));  // top row, last column
  CHECK(m.grid.blocked(Cell{1, 1}));
  CHECK(m.grid.blocked_count() == 2);
}

TEST_CASE("grid-text: writer output is the canonical form", "[grid_text]") {
  MapFile m{Grid::from_rows_top_first({"..#", "#.."}), Cell{1, 0}, Cell{0, 1}, "two rows"};
  CHECK(to_grid_text(m) ==
        "pathref-grid 1\nname two rows\nsize 3 2\nstart 1 0\ngoal 0 1\nmap\n..#\n#..\n");
  m.name.clear();
  m.start.reset();
  m.goal.reset();
  CHECK(to_grid_text(m) == "pathref-grid 1\nsize 3 2\nmap\n..#\n#..\n");
}

TEST_CASE("grid-text: optional parts, any header order, CRLF, blanks", "[grid_text]") {
  const MapFile a = parse_grid_text("pathref-grid 1\nsize 2 1\nmap\n.#\n", "a");
  CHECK_FALSE(a.start.has_value());
  CHECK_FALSE(a.goal.has_value());
  CHECK(a.name.empty());
  // goal before size, tabs and extra blanks between words, CRLF endings, no final newline,
  // trailing blank lines after the rows.
  const MapFile b = parse_grid_text(
      "pathref-grid 1\r\n  goal\t0 0 \r\n   # indented comment\r\nsize  2\t1\r\nmap\r\n.#\r\n\r\n \t", "b");
  CHECK(b.grid == a.grid);
  CHECK(*b.goal == Cell{0, 0});
  // A name keeps inner blanks, loses the separating and trailing ones.
  CHECK(parse_grid_text("pathref-grid 1\nname \t a  b \t\nsize 1 1\nmap\n.", "c").name == "a  b");
}

TEST_CASE("grid-text: catalogue of malformed inputs with their exact messages", "[grid_text]") {
  struct Case {
    const char* input;
    const char* message;
  };
  const std::vector<Case> cases = {
      {"", "m.txt:1:1: expected 'pathref-grid 1' as the first line, got an empty file"},
      {"\xEF\xBB\xBFpathref-grid 1\n",
       "m.txt:1:1: expected 'pathref-grid 1' as the first line, got a UTF-8 byte-order mark "
       "(save the file without it)"},
      {"pathref-map 1\n", "m.txt:1:1: expected 'pathref-grid 1' as the first line"},
      {" pathref-grid 1\n", "m.txt:1:1: expected 'pathref-grid 1' as the first line"},
      {"pathref-grid\n", "m.txt:1:13: expected the format version after 'pathref-grid'"},
      {"pathref-grid 2\n", "m.txt:1:14: unsupported format version '2' (this reader reads version 1)"},
      {"pathref-grid 1 x\n", "m.txt:1:16: expected end of line after 'pathref-grid 1'"},
      {"pathref-grid 1\rsize 1 1\n",
       "m.txt:1:15: unexpected carriage return (lines must end in LF or CRLF)"},
      {"pathref-grid 1\nsize 1 1\nmap\n.\r\r\n",
       "m.txt:4:2: unexpected carriage return (lines must end in LF or CRLF)"},
      {"pathref-grid 1\n", "m.txt:2:1: unexpected end of file: expected the 'map' line"},
      {"pathref-grid 1\nsize 2 2\n", "m.txt:3:1: unexpected end of file: expected the 'map' line"},
      {"pathref-grid 1\nmap\n", "m.txt:2:1: expected a 'size W H' line before 'map'"},
      {"pathref-grid 1\nsize 2 2\nmap x\n", "m.txt:3:5: expected end of line after 'map'"},
      {"pathref-grid 1\nsize\n", "m.txt:2:5: expected width (a decimal integer)"},
      {"pathref-grid 1\nsize 3\n", "m.txt:2:7: expected height (a decimal integer)"},
      {"pathref-grid 1\nsize 3 x\n", "m.txt:2:8: expected height as a decimal integer, got 'x'"},
      {"pathref-grid 1\nsize -3 3\n", "m.txt:2:6: expected width as a decimal integer, got '-3'"},
      {"pathref-grid 1\nsize +3 3\n", "m.txt:2:6: expected width as a decimal integer, got '+3'"},
      {"pathref-grid 1\nsize 0 3\n", "m.txt:2:6: width must be between 1 and 268435456, got 0"},
      {"pathref-grid 1\nsize 3 268435457\n",
       "m.txt:2:8: height must be between 1 and 268435456, got 268435457"},
      {"pathref-grid 1\nsize 99999999999999999999 1\n",
       "m.txt:2:6: width must be between 1 and 268435456, got 99999999999999999999"},
      {"pathref-grid 1\nsize 3 3 3\n", "m.txt:2:10: expected end of line after 'size W H'"},
      {"pathref-grid 1\nsize 16384 16385\nmap\n",
       "m.txt:2:6: a 16384x16385 grid exceeds the limit of 268435456 cells"},
      {"pathref-grid 1\nsize 2 2\n  size 2 2\n",
       "m.txt:3:3: duplicate 'size' line (first given on line 2)"},
      {"pathref-grid 1\nstart 1 0\ngoal 1 0\nsize 2 1\nmap\n..\n",
       "m.txt:3:6: goal (1, 0) is the start cell (given on line 2): start and goal must differ"},
      {"pathref-grid 1\nstart 0 0\nstart 0 0\n",
       "m.txt:3:1: duplicate 'start' line (first given on line 2)"},
      {"pathref-grid 1\ngoal 0 0\ngoal 1 1\n", "m.txt:3:1: duplicate 'goal' line (first given on line 2)"},
      {"pathref-grid 1\nname a\nname b\n", "m.txt:3:1: duplicate 'name' line (first given on line 2)"},
      {"pathref-grid 1\nstart 1\n", "m.txt:2:8: expected start y (a decimal integer)"},
      {"pathref-grid 1\ngoal a 1\n", "m.txt:2:6: expected goal x as a decimal integer, got 'a'"},
      {"pathref-grid 1\nstart 1 2 3\n", "m.txt:2:11: expected end of line after 'start X Y'"},
      {"pathref-grid 1\ngoal 1 2 3\n", "m.txt:2:10: expected end of line after 'goal X Y'"},
      {"pathref-grid 1\nstart 268435456 0\n",
       "m.txt:2:7: start x must be between 0 and 268435455, got 268435456"},
      {"pathref-grid 1\nname   \n", "m.txt:2:8: expected a name after 'name'"},
      {"pathref-grid 1\nname a\x01z\n",
       "m.txt:2:7: expected a name without control characters, got byte 0x01"},
      {"pathref-grid 1\nwidth 3\n",
       "m.txt:2:1: unknown keyword 'width' (expected size, start, goal, name, map or a # comment)"},
      {"pathref-grid 1\nsize 3 2\nstart 3 0\nmap\n",
       "m.txt:3:7: start (3, 0) is outside the 3x2 grid (x must be < 3, y < 2)"},
      {"pathref-grid 1\nsize 3 2\ngoal 0 2\nmap\n",
       "m.txt:3:6: goal (0, 2) is outside the 3x2 grid (x must be < 3, y < 2)"},
      {"pathref-grid 1\nsize 3 2\nmap\n...\n", "m.txt:5:1: unexpected end of file: expected map row 2 of 2"},
      {"pathref-grid 1\nsize 3 2\nmap\n", "m.txt:4:1: unexpected end of file: expected map row 1 of 2"},
      {"pathref-grid 1\nsize 3 2\nmap\n...\n.x.\n", "m.txt:5:2: expected '.' (free) or '#' (blocked), got 'x'"},
      {"pathref-grid 1\nsize 3 2\nmap\n...\n.\t.\n",
       "m.txt:5:2: expected '.' (free) or '#' (blocked), got byte 0x09"},
      {"pathref-grid 1\nsize 3 2\nmap\n...\n. .\n", "m.txt:5:2: expected '.' (free) or '#' (blocked), got ' '"},
      {"pathref-grid 1\nsize 3 2\nmap\n..\n...\n", "m.txt:4:3: expected 3 cells in map row 1, got 2"},
      {"pathref-grid 1\nsize 3 2\nmap\n...\n\n", "m.txt:5:1: expected 3 cells in map row 2, got 0"},
      {"pathref-grid 1\nsize 3 2\nmap\n...\n.... \n", "m.txt:5:4: expected end of map row 2 after 3 cells"},
      {"pathref-grid 1\nsize 3 2\nmap\n...\n...\n...\n", "m.txt:6:1: expected end of file after the 2 map rows"},
      {"pathref-grid 1\nsize 3 2\nmap\n...\n...\n# note\n",
       "m.txt:6:1: expected end of file after the 2 map rows"},
      {"pathref-grid 1\nsize 3 2\nstart 1 1\nmap\n.#.\n...\n", "m.txt:3:7: start (1, 1) is a blocked cell"},
      {"pathref-grid 1\nsize 3 2\ngoal 2 0\nmap\n...\n..#\n", "m.txt:3:6: goal (2, 0) is a blocked cell"},
  };
  for (const Case& c : cases) {
    INFO("input: " << c.input);
    CHECK(parse_error(c.input) == c.message);
  }
}

TEST_CASE("grid-text: ParseError carries file, line and column", "[grid_text]") {
  try {
    (void)parse_grid_text("pathref-grid 1\nsize 3 2\nmap\n...\n.x.\n", "maps/x.txt");
    FAIL("expected a ParseError");
  } catch (const ParseError& e) {
    CHECK(e.file() == "maps/x.txt");
    CHECK(e.line() == 5);
    CHECK(e.column() == 2);
    CHECK(e.kind() == "ParseError");
  }
}

TEST_CASE("grid-text: a huge size with few rows fails fast without allocating", "[grid_text]") {
  // 268435456 cells would need 256 MiB; the reader checks the rows (here: none) first.
  CHECK(parse_error("pathref-grid 1\nsize 268435456 1\nmap\n") ==
        "m.txt:4:1: unexpected end of file: expected map row 1 of 1");
  CHECK(parse_error("pathref-grid 1\nsize 1 268435456\nmap\n.\n") ==
        "m.txt:5:1: unexpected end of file: expected map row 2 of 268435456");
}

TEST_CASE("grid-text: the writer refuses what the reader would reject", "[grid_text]") {
  const Grid g = Grid::from_rows_top_first({".#"});
  CHECK_THROWS_AS(to_grid_text(MapFile{g, Cell{1, 0}, std::nullopt, ""}), pathref::DomainError);
  CHECK_THROWS_AS(to_grid_text(MapFile{g, std::nullopt, Cell{2, 0}, ""}), pathref::DomainError);
  CHECK_THROWS_AS(to_grid_text(MapFile{g, std::nullopt, std::nullopt, " lead"}), pathref::DomainError);
  CHECK_THROWS_AS(to_grid_text(MapFile{g, std::nullopt, std::nullopt, "trail\t"}), pathref::DomainError);
  CHECK_THROWS_AS(to_grid_text(MapFile{g, std::nullopt, std::nullopt, "new\nline"}), pathref::DomainError);
  const Grid two = Grid::from_rows_top_first({".."});
  CHECK_THROWS_AS(to_grid_text(MapFile{two, Cell{1, 0}, Cell{1, 0}, ""}), pathref::DomainError);
  // The accepted neighbour of those cases: written, then read back unchanged.
  const MapFile ok{two, Cell{0, 0}, Cell{1, 0}, "caf\xC3\xA9 # 1"};
  const MapFile back = parse_grid_text(to_grid_text(ok), "roundtrip.txt");
  CHECK(back.grid == two);
  CHECK(back.start == ok.start);
  CHECK(back.goal == ok.goal);
  CHECK(back.name == ok.name);
}

TEST_CASE("grid-text: read_grid_file reads a file and names it in errors", "[grid_text]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "pathref_grid_text_test";
  fs::create_directories(dir);
  const fs::path good = dir / "good.txt";
  const fs::path bad = dir / "bad.txt";
  std::ofstream(good) << "pathref-grid 1\nsize 2 1\nmap\n.#\n";
  std::ofstream(bad) << "pathref-grid 1\nsize 2 1\nmap\n.x\n";
  CHECK(pathref::io::read_grid_file(good.string()).grid.blocked(Cell{1, 0}));
  try {
    (void)pathref::io::read_grid_file(bad.string());
    FAIL("expected a ParseError");
  } catch (const ParseError& e) {
    CHECK(std::string(e.what()) == bad.string() + ":4:2: expected '.' (free) or '#' (blocked), got 'x'");
  }
  CHECK_THROWS_AS(pathref::io::read_grid_file((dir / "missing.txt").string()), pathref::UsageError);
  CHECK_THROWS_AS(pathref::io::read_grid_file(dir.string()), pathref::UsageError);
  fs::remove_all(dir);
}

TEST_CASE("grid-text: the shipped sample tests/data/grid/office.grid reads and round-trips", "[grid_text]") {
  const MapFile m = pathref::io::read_grid_file(pathref::testing::source_dir() + "/tests/data/grid/office.grid");
  CHECK(m.name == "office-floor");
  CHECK(m.grid.width() == 32);
  CHECK(m.grid.height() == 12);
  CHECK(m.start == Cell{1, 1});
  CHECK(m.goal == Cell{30, 10});
  CHECK(m.grid.blocked(Cell{0, 0}));   // the border
  CHECK(m.grid.blocked(Cell{10, 10}));  // the wall of the left room, second row from the top
  CHECK_FALSE(m.grid.blocked(Cell{10, 6}));  // its door
  const std::string canonical = to_grid_text(m);
  CHECK(parse_grid_text(canonical, "rt") == m);
  CHECK(to_grid_text(parse_grid_text(canonical, "rt")) == canonical);
}
