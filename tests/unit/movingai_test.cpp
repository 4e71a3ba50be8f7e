// MovingAI .map/.scen readers and writer, the scenario agreement rule and the format-detecting
// loader: worked examples and the catalogue of every error message
// (spec/formats.md#movingai-map, #movingai-scen, #scen-agreement, #map-files).
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/io/movingai.hpp"
#include "pathref/planners/search.hpp"
#include "support/paths.hpp"

using pathref::ParseError;
using pathref::grid::Cell;
using pathref::grid::Grid;
using namespace pathref::io;

namespace {

/// The message of the ParseError that parsing `text` as a .map throws ("" if it parses).
std::string map_error(const std::string& text, const ReadLimits& limits = {}) {
  try {
    (void)parse_movingai_map(text, "m.map", {}, limits);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

/// The message of the ParseError that parsing `text` as a .scen throws ("" if it parses).
std::string scen_error(const std::string& text) {
  try {
    (void)parse_movingai_scen(text, "s.scen");
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

const std::string sample_map =
    "type octile\n"
    "height 3\n"
    "width 5\n"
    "map\n"
    ".G@OT\n"
    "SW...\n"
    ".....\n";

}  // namespace

TEST_CASE("movingai: the example map parses - first row is the top, (0,0) upper left -> lower left",
          "[movingai]") {
  const MapFile m = parse_movingai_map(sample_map, "m.map");
  CHECK(m.grid.width() == 5);
  CHECK(m.grid.height() == 3);
  CHECK_FALSE(m.start.has_value());
  CHECK(m.name.empty());
  // Top text row is pathref y = 2: '.', 'G' free; '@', 'O', 'T' blocked.
  CHECK(m.grid.free(Cell{0, 2}));
  CHECK(m.grid.free(Cell{1, 2}));
  CHECK(m.grid.blocked(Cell{2, 2}));
  CHECK(m.grid.blocked(Cell{3, 2}));
  CHECK(m.grid.blocked(Cell{4, 2}));
  // Second row: S free, W blocked by default.
  CHECK(m.grid.free(Cell{0, 1}));
  CHECK(m.grid.blocked(Cell{1, 1}));
  CHECK(m.grid.blocked_count() == 4);
  // MovingAI (x, y) = (4, 0) is the upper-right cell = pathref (4, 2), and back.
  CHECK(from_movingai(4, 0, 3) == Cell{4, 2});
  CHECK(to_movingai(Cell{4, 2}, 3) == Cell{4, 0});
  CHECK(to_movingai(from_movingai(1, 2, 3), 3) == Cell{1, 2});
}

TEST_CASE("movingai: S and W follow the terrain option", "[movingai]") {
  const MapFile a = parse_movingai_map(sample_map, "m.map", MovingAiTerrain{false, true});
  CHECK(a.grid.blocked(Cell{0, 1}));  // S blocked
  CHECK(a.grid.free(Cell{1, 1}));     // W free
  const MapFile b = parse_movingai_map(sample_map, "m.map", MovingAiTerrain{true, true});
  CHECK(b.grid.blocked_count() == 3);
}

TEST_CASE("movingai: writer output, CRLF, width before height, blanks", "[movingai]") {
  const Grid g = Grid::from_rows_top_first({"..#", "#.."});
  CHECK(to_movingai_map(g) == "type octile\nheight 2\nwidth 3\nmap\n..@\n@..\n");
  CHECK(parse_movingai_map(to_movingai_map(g), "w").grid == g);
  const std::string crlf = "type octile\r\nwidth 3\r\nheight  2 \r\nmap\r\n..@\r\n@..\r\n\r\n";
  CHECK(parse_movingai_map(crlf, "c").grid == g);
  CHECK(parse_movingai_map("type\toctile\nheight 2\nwidth 3\nmap\n..T\nO..", "t").grid == g);
}

TEST_CASE("movingai: catalogue of malformed maps with their exact messages", "[movingai]") {
  struct Case {
    std::string input;
    const char* message;
  };
  const std::string head = "type octile\nheight 2\nwidth 3\nmap\n";
  const std::vector<Case> cases = {
      {"", "m.map:1:1: expected 'type octile' as the first line, got an empty file"},
      {"\xEF\xBB\xBFtype octile\n",
       "m.map:1:1: expected 'type octile' as the first line, got a UTF-8 byte-order mark (save the file "
       "without it)"},
      {"height 2\n", "m.map:1:1: expected 'type octile' as the first line"},
      {"type\n", "m.map:1:5: expected the map type after 'type'"},
      {"type tile\n", "m.map:1:6: unsupported map type 'tile' (this reader reads 'type octile')"},
      {"type \xC3\xA9\n", "m.map:1:6: expected the map type 'octile', got byte 0xc3"},
      {"type octile x\n", "m.map:1:13: expected end of line after 'type octile'"},
      {"type octile\n", "m.map:2:1: unexpected end of file: expected 'height H' or 'width W'"},
      {"type octile\nheight 2\n", "m.map:3:1: unexpected end of file: expected 'width W'"},
      {"type octile\nwidth 2\n", "m.map:3:1: unexpected end of file: expected 'height H'"},
      {"type octile\n\n", "m.map:2:1: expected 'height H' or 'width W', got an empty line"},
      {"type octile\nsize 2 2\n", "m.map:2:1: expected 'height H' or 'width W', got 'size'"},
      {"type octile\nheight 2\nheight 2\n", "m.map:3:1: duplicate 'height' line (first given on line 2)"},
      {"type octile\nheight\n", "m.map:2:7: expected height (a decimal integer)"},
      {"type octile\nheight -2\n", "m.map:2:8: expected height as a decimal integer, got '-2'"},
      {"type octile\nheight 0\n", "m.map:2:8: height must be between 1 and 268435456, got '0'"},
      {"type octile\nheight 99999999999999999999\n",
       "m.map:2:8: height must be between 1 and 268435456, got '99999999999999999999'"},
      {"type octile\nheight 2 3\n", "m.map:2:10: expected end of line after 'height H'"},
      {"type octile\nheight 2\nwidth 3x\n", "m.map:3:7: expected width as a decimal integer, got '3x'"},
      {"type octile\nheight 65536\nwidth 65536\n",
       "m.map:3:7: a 65536x65536 map exceeds the limit of 268435456 cells"},
      {"type octile\nheight 2\nwidth 3\n", "m.map:4:1: unexpected end of file: expected the 'map' line"},
      {"type octile\nheight 2\nwidth 3\nmaps\n", "m.map:4:1: expected 'map' after the height and width lines"},
      {"type octile\nheight 2\nwidth 3\nmap x\n", "m.map:4:5: expected end of line after 'map'"},
      {head, "m.map:5:1: unexpected end of file: expected map row 1 of 2"},
      {head + "...\n", "m.map:6:1: unexpected end of file: expected map row 2 of 2"},
      {head + "..\n...\n", "m.map:5:3: expected 3 cells in map row 1, got 2"},
      {head + "....\n...\n", "m.map:5:4: expected end of map row 1 after 3 cells"},
      {head + "...\n.#.\n", "m.map:6:2: expected a MovingAI terrain letter (. G S W @ O T), got '#'"},
      {head + "...\n. .\n", "m.map:6:2: expected a MovingAI terrain letter (. G S W @ O T), got ' '"},
      {head + "...\n.\xC3\xA9\n", "m.map:6:2: expected a MovingAI terrain letter (. G S W @ O T), got byte 0xc3"},
      {head + "...\n..\t\n", "m.map:6:3: expected a MovingAI terrain letter (. G S W @ O T), got byte 0x09"},
      {head + "...\n...\n...\n", "m.map:7:1: expected end of file after the 2 map rows"},
      {head + "...\r...\n", "m.map:5:4: unexpected carriage return (lines must end in LF or CRLF)"},
      {head + "...\n...\r\r\n", "m.map:6:4: unexpected carriage return (lines must end in LF or CRLF)"},
  };
  for (const Case& c : cases) {
    INFO("input: " << c.input);
    CHECK(map_error(c.input) == c.message);
  }
}

TEST_CASE("movingai: lowered limits are checked before the rows", "[movingai]") {
  const ReadLimits small{100, 1000};
  CHECK(map_error("type octile\nheight 101\nwidth 1\nmap\n", small) ==
        "m.map:2:8: height must be between 1 and 100, got '101'");
  CHECK(map_error("type octile\nheight 100\nwidth 11\nmap\n", small) ==
        "m.map:3:7: a 11x100 map exceeds the limit of 1000 cells");
  // A header claiming a huge map fails at its first missing row, without allocating it.
  CHECK(map_error("type octile\nheight 16384\nwidth 16384\nmap\n") ==
        "m.map:5:1: unexpected end of file: expected map row 1 of 16384");
  CHECK_THROWS_AS(parse_movingai_map(sample_map, "m", {}, ReadLimits{0, 10}), pathref::UsageError);
}

TEST_CASE("scen: printed lengths and the agreement tolerance", "[movingai][scen]") {
  const auto p = parse_printed_length("3.41421");
  REQUIRE(p.has_value());
  CHECK(p->value == 3.41421);
  CHECK(p->last_digit_exponent == -5);
  CHECK(p->significant_digits == 6);
  CHECK(agreement_tolerance(*p, 6) == 1e-5);
  CHECK(agreement_tolerance(*p, 0) == 1e-5);
  // %g dropped trailing zeros: "100.77" stands for 100.770 -> one unit is 0.001, not 0.01.
  const auto q = parse_printed_length("100.77");
  REQUIRE(q.has_value());
  CHECK(q->significant_digits == 5);
  CHECK(agreement_tolerance(*q, 6) == 0.001);
  CHECK(agreement_tolerance(*q, 0) == 0.01);
  CHECK(lengths_agree(100.76955262170047, *q, agreement_tolerance(*q, 6)));  // 72 + 26 sqrt2 - ...
  // An integer such as "4786" or "1" means 4786.00 / 1.00000.
  const auto one = parse_printed_length("1");
  REQUIRE(one.has_value());
  CHECK(agreement_tolerance(*one, 6) == 1e-5);
  CHECK_FALSE(lengths_agree(1.4142135623730951, *one, agreement_tolerance(*one, 6)));
  CHECK(lengths_agree(1.0, *one, agreement_tolerance(*one, 6)));
  CHECK(agreement_tolerance(*parse_printed_length("4786"), 6) == 0.01);
  // Exponent form (lengths of 10^6 and more printed by %g).
  const auto e = parse_printed_length("1.23457e+06");
  REQUIRE(e.has_value());
  CHECK(e->value == 1234570.0);
  CHECK(agreement_tolerance(*e, 6) == 10.0);
  CHECK(parse_printed_length("0.5")->significant_digits == 1);
  for (const char* bad : {"", "x", "-1", "+1", "1.", ".5", "1e", "1e1234", "1,5", "inf", "nan", "1.0.0", "0x10",
                          " 1", "1e+", "12345678901234567890123456789012345678901"})
    CHECK_FALSE(parse_printed_length(bad).has_value());
  // Just outside and just inside one unit.
  const auto t = parse_printed_length("10.2426");
  CHECK(lengths_agree(10.24269, *t, 1e-4));
  CHECK_FALSE(lengths_agree(10.24271, *t, 1e-4));
}

TEST_CASE("scen: version 1 and version 0 files parse", "[movingai][scen]") {
  const ScenFile v1 = parse_movingai_scen(
      "version 1\n0\tmaps/dao/m.map\t5\t3\t0\t2\t4\t1\t4.41421\n\n1 m.map 5 3 1 2 4 2 3\n", "s.scen");
  CHECK(v1.version == 1);
  REQUIRE(v1.scenarios.size() == 2);
  const Scenario& s = v1.scenarios[0];
  CHECK(s.line == 2);
  CHECK(s.map == "maps/dao/m.map");
  CHECK(s.width->value == 5);
  CHECK(s.height->value == 3);
  CHECK(s.start_x.value == 0);
  CHECK(s.start_y.value == 2);
  CHECK(s.goal_x.value == 4);
  CHECK(s.goal_y.value == 1);
  CHECK(s.optimal.text == "4.41421");
  CHECK(v1.scenarios[1].line == 4);
  CHECK(parse_movingai_scen("version 1.0\r\n0 m 5 3 0 2 4 1 4.41421\r\n", "s").version == 1);
  const ScenFile v0 = parse_movingai_scen("0\tm.map\t0\t2\t4\t1\t4.41421\n", "s.scen");
  CHECK(v0.version == 0);
  CHECK_FALSE(v0.scenarios[0].width.has_value());
  CHECK(parse_movingai_scen("version 0\n0 m 0 2 4 1 4.41421\n", "s").version == 0);
}

TEST_CASE("scen: catalogue of malformed scenario files with their exact messages", "[movingai][scen]") {
  struct Case {
    std::string input;
    const char* message;
  };
  const std::string v = "version 1\n";
  const std::vector<Case> cases = {
      {"", "s.scen:1:1: expected a 'version 1' line or a scenario line, got an empty file"},
      {"\xEF\xBB\xBFversion 1\n",
       "s.scen:1:1: expected a 'version 1' line or a scenario line, got a UTF-8 byte-order mark (save the "
       "file without it)"},
      {"version\n", "s.scen:1:8: expected the scenario version after 'version'"},
      {"version 2\n", "s.scen:1:9: unsupported scenario version '2' (this reader reads 1, 1.0, 0 and 0.0)"},
      {"version 1 x\n", "s.scen:1:11: expected end of line after 'version 1'"},
      {v, "s.scen:2:1: unexpected end of file: expected a scenario line"},
      {v + "\n  \n", "s.scen:4:1: unexpected end of file: expected a scenario line"},
      {v + "0\tm.map\t5\t3\t0\t2\t4\n", "s.scen:2:18: expected the goal y (field 8 of 9)"},
      {v + "0 m.map 5 3 0 2 4 1 4.41421 x\n",
       "s.scen:2:29: expected end of line after the optimal length (field 9)"},
      {"0 m.map 5 3 0 2 4 1 4.41421\n",
       "s.scen:1:19: expected end of line after 7 fields (a file without a version line is version 0: "
       "bucket, map, start x, start y, goal x, goal y, optimal length); a file with width and height "
       "columns needs 'version 1' as its first line"},
      {"0 m.map 0 2 4\n", "s.scen:1:14: expected the goal y (field 6 of 7)"},
      {v + "x m 5 3 0 2 4 1 4.41421\n", "s.scen:2:1: expected bucket as a decimal integer, got 'x'"},
      {v + "0 m -5 3 0 2 4 1 4.41421\n", "s.scen:2:5: expected width as a decimal integer, got '-5'"},
      {v + "0 m 0 3 0 2 4 1 4.41421\n", "s.scen:2:5: width must be between 1 and 268435456, got '0'"},
      {v + "0 m 5 999999999999 0 2 4 1 4.41421\n",
       "s.scen:2:7: height must be between 1 and 268435456, got '999999999999'"},
      {v + "0 m 5 3 0 2 4 1.5 4.41421\n", "s.scen:2:15: expected goal y as a decimal integer, got '1.5'"},
      {v + "0 m 5 3 0 \xC3\xA9 4 1 4.41421\n", "s.scen:2:11: expected start y as a decimal integer, got byte 0xc3"},
      {v + "0 m 5 3 0 2 4 1 -4.4\n",
       "s.scen:2:17: expected the optimal length as a decimal number such as 3.41421, got '-4.4'"},
      {v + "0 m 5 3 0 2 4 1 4,41\n",
       "s.scen:2:17: expected the optimal length as a decimal number such as 3.41421, got '4,41'"},
      {v + "0 m 5 3 5 2 4 1 4.41421\n",
       "s.scen:2:9: start (5, 2) is outside the 5x3 map of this line (x must be < 5, y < 3)"},
      {v + "0 m 5 3 0 2 4 3 4.41421\n",
       "s.scen:2:13: goal (4, 3) is outside the 5x3 map of this line (x must be < 5, y < 3)"},
      {v + "0 m 5 3 1 1 1 1 0\n", "s.scen:2:9: start (1, 1) equals the goal (a scenario needs two different cells)"},
      {v + "0 m\x01 5 3 0 2 4 1 4.41421\n",
       "s.scen:2:4: expected a map file name without control characters, got byte 0x01"},
      {v + "0 m 5 3 0 2 4 1 4.41421\r\r\n", "s.scen:2:24: unexpected carriage return (lines must end in LF or CRLF)"},
  };
  for (const Case& c : cases) {
    INFO("input: " << c.input);
    CHECK(scen_error(c.input) == c.message);
  }
}

TEST_CASE("scen: checks against the map (size, inside, blocked)", "[movingai][scen]") {
  const Grid g = parse_movingai_map(sample_map, "m.map").grid;  // 5x3, (2,0) '@' in file coordinates
  const auto error = [&](const std::string& line) -> std::string {
    const ScenFile f = parse_movingai_scen(line, "s.scen");
    try {
      check_scenario_on_map(f.scenarios.at(0), g, "m.map", "s.scen");
    } catch (const ParseError& e) {
      return e.what();
    }
    return "";
  };
  CHECK(error("version 1\n0 m 5 3 0 2 4 1 4.41421\n").empty());
  CHECK(error("version 1\n0 m 6 3 0 2 4 1 4.41421\n") ==
        "s.scen:2:5: the map m.map is 5x3 but this line says 6x3 (pathref does not scale maps)");
  CHECK(error("version 1\n0 m 5 3 2 0 4 1 4.41421\n") == "s.scen:2:9: start (2, 0) is a blocked cell of m.map");
  CHECK(error("version 1\n0 m 5 3 0 2 1 1 4.41421\n") == "s.scen:2:13: goal (1, 1) is a blocked cell of m.map");
  CHECK(error("0 m 0 2 5 1 4.41421\n") ==
        "s.scen:1:9: goal (5, 1) is outside the 5x3 map m.map (x must be < 5, y < 3)");
  CHECK(error("0 m 0 2 0 0 2\n").empty());
}

TEST_CASE("map files: format detection, loading, writing", "[movingai][map_file]") {
  CHECK(detect_map_format("a/b.map", "") == MapFormat::movingai);
  CHECK(detect_map_format("a/B.MAP", "pathref-grid 1") == MapFormat::movingai);
  CHECK(detect_map_format("x.m", "type octile") == MapFormat::matrix);
  CHECK(detect_map_format("x.csv", "") == MapFormat::matrix);
  CHECK(detect_map_format("x.txt", "pathref-grid 1\n") == MapFormat::pathref_grid);
  CHECK(detect_map_format("x", "type octile\r\n") == MapFormat::movingai);
  CHECK(detect_map_format("x.txt", "0 1\n") == MapFormat::matrix);
  CHECK(detect_map_format("x.txt", "pathref-gridx") == MapFormat::matrix);
  CHECK(parse_map_format("movingai") == MapFormat::movingai);
  CHECK(to_string(MapFormat::pathref_grid) == "pathref-grid");
  CHECK_THROWS_WITH(parse_map_format("png"),
                    "unknown map format 'png' (known: auto, pathref-grid, movingai, matrix, ros, scene)");
  CHECK_THROWS_WITH(load_map_file("/nonexistent/x.map", {}), "cannot read map file '/nonexistent/x.map': No such file or directory");
  CHECK_THROWS_WITH(load_map_file("t.scen", {}),
                    "'t.scen' is a MovingAI scenario file, not a map: run it with pathref scen");
  // pathref-grid under lowered limits: reported at the width of its size line.
  MapReadOptions o;
  o.limits = ReadLimits{3, 100};
  CHECK_THROWS_WITH(parse_map_text("pathref-grid 1\n# c\n size 4 1\nmap\n....\n", "g.txt", MapFormat::pathref_grid, o),
                    "g.txt:3:7: a 4x1 grid exceeds the limit of 3 cells per side");
  const MapFile m{Grid::from_rows_top_first({".#", ".."}), Cell{0, 0}, Cell{1, 0}, "n"};
  CHECK(write_map_text(m, OutputFormat::pathref_grid) == to_grid_text(m));
  CHECK(write_map_text(m, OutputFormat::movingai) == "type octile\nheight 2\nwidth 2\nmap\n.@\n..\n");
  CHECK(write_map_text(m, OutputFormat::matrix) == "0 1\n0 0\n");
  CHECK(write_map_text(m, OutputFormat::matlab) == "G = [0 1\n     0 0];\n");
}

TEST_CASE("movingai: the samples in tests/data read, round-trip and agree with their scenarios",
          "[movingai][scen][samples]") {
  const std::string dir = pathref::testing::source_dir() + "/tests/data/movingai/";
  const LoadedMapFile lm = load_map_file(dir + "rooms40x30.map", {});
  CHECK(lm.format == MapFormat::movingai);
  const Grid& g = lm.map.grid;
  CHECK(g.width() == 40);
  CHECK(g.height() == 30);
  CHECK(parse_movingai_map(to_movingai_map(g), "rt").grid == g);
  for (const char* name : {"rooms40x30.map.scen", "rooms40x30-v0.scen"}) {
    INFO(name);
    const std::string path = dir + name;
    const ScenFile f = parse_movingai_scen(read_text_file(path, "scenario file"), path);
    REQUIRE(f.scenarios.size() >= 10);
    for (const Scenario& s : f.scenarios) {
      check_scenario_on_map(s, g, "rooms40x30.map", path);
      const auto out = pathref::search::astar(g, from_movingai(s.start_x.value, s.start_y.value, 30),
                                              from_movingai(s.goal_x.value, s.goal_y.value, 30),
                                              pathref::grid::CornerPolicy::strict,
                                              pathref::heuristics::Heuristic::octile);
      INFO("line " << s.line << " optimal " << s.optimal.text << " astar " << out.length);
      REQUIRE(out.found);
      CHECK(lengths_agree(out.length, s.optimal, agreement_tolerance(s.optimal, 6)));
    }
  }
}
