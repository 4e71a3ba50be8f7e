// ROS map_server YAML + PGM reader/writer: worked examples, the occupancy rule, and the catalogue
// of every error message (spec/formats.md#ros-map-yaml, #pgm, #ros-occupancy).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/io/ros_map.hpp"
#include "support/paths.hpp"

using pathref::ParseError;
using pathref::grid::Cell;
using pathref::grid::Grid;
using pathref::io::classify_pixel;
using pathref::io::load_ros_map;
using pathref::io::Occupancy;
using pathref::io::parse_pgm;
using pathref::io::parse_ros_map;
using pathref::io::parse_ros_yaml;
using pathref::io::PgmImage;
using pathref::io::RosMapMeta;
using pathref::io::RosMapMode;
using pathref::io::RosMapOptions;
using pathref::io::UnknownAs;

namespace {

const std::string data_dir = pathref::testing::source_dir() + "/tests/data/ros/";

std::string yaml_error(const std::string& text, bool lenient = false) {
  try {
    (void)parse_ros_yaml(text, "m.yaml", lenient);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

std::string pgm_error(const std::string& bytes) {
  try {
    (void)parse_pgm(bytes, "m.pgm");
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

const std::string kValid =
    "image: map.pgm\n"
    "resolution: 0.05\n"
    "origin: [-10.0, -10.0, 0.0]\n"
    "negate: 0\n"
    "occupied_thresh: 0.65\n"
    "free_thresh: 0.196\n";

/// kValid with line `from` replaced by `to`.
std::string with(const std::string& from, const std::string& to) {
  std::string s = kValid;
  const auto at = s.find(from);
  REQUIRE(at != std::string::npos);
  s.replace(at, from.size(), to);
  return s;
}

}  // namespace

TEST_CASE("ros-map: ROS 1 map_saver style P5 map (office.yaml) loads", "[ros_map]") {
  const auto m = load_ros_map(data_dir + "office.yaml");
  CHECK(m.meta.image == "office.pgm");
  CHECK(m.meta.resolution == 0.05);
  CHECK(m.meta.origin == std::array<double, 3>{-0.4, -0.25, 0.0});
  CHECK(m.meta.mode == RosMapMode::trinary);
  CHECK(m.image_path == data_dir + "office.pgm");
  const Grid& g = m.map.grid;
  REQUIRE(g.width() == 16);
  REQUIRE(g.height() == 10);
  // Image row 0 is the top (y = 9): a wall. Row 4 (y = 5) has the door at x = 7.
  CHECK(g.blocked(Cell{3, 9}));
  CHECK(g.free(Cell{3, 8}));
  CHECK(g.free(Cell{7, 5}));
  CHECK(g.blocked(Cell{7, 3}));
  // The unexplored corner (205, x >= 12, image rows 1-2 = y 8..7) is unknown -> blocked.
  CHECK(m.unknown_cells == 6);
  CHECK(g.blocked(Cell{12, 8}));
  CHECK(g.blocked(Cell{14, 7}));
  CHECK(!m.map.start);
  CHECK(m.map.name.empty());
  const auto freed = load_ros_map(data_dir + "office.yaml", RosMapOptions{UnknownAs::free, false});
  CHECK(freed.unknown_cells == 6);
  CHECK(freed.map.grid.free(Cell{12, 8}));
  CHECK(freed.map.grid.blocked_count() == g.blocked_count() - 6);
}

TEST_CASE("ros-map: load_map_file detects .yaml/.yml, honours --unknown and the limits", "[ros_map]") {
  using pathref::io::detect_map_format;
  using pathref::io::load_map_file;
  using pathref::io::MapFormat;
  using pathref::io::MapReadOptions;
  CHECK(detect_map_format("a/office.yaml", "") == MapFormat::ros);
  CHECK(detect_map_format("a/OFFICE.YML", "pathref-grid 1") == MapFormat::ros);
  CHECK(detect_map_format("a/office.txt", "image: office.pgm") == MapFormat::matrix);
  const auto direct = load_ros_map(data_dir + "office.yaml");
  const auto m = load_map_file(data_dir + "office.yaml", MapReadOptions{});
  CHECK(m.format == MapFormat::ros);
  CHECK(m.map.grid == direct.map.grid);
  MapReadOptions freed;
  freed.ros_unknown = UnknownAs::free;
  CHECK(load_map_file(data_dir + "office.yaml", freed).map.grid.blocked_count() ==
        direct.map.grid.blocked_count() - 6);
  // An explicit --format ros reads a YAML file whatever its name would say.
  MapReadOptions forced;
  forced.format = MapFormat::ros;
  CHECK(load_map_file(data_dir + "office.yaml", forced).map.grid == direct.map.grid);
  // Limits: checked on the image's size, reported at the YAML's image value (line 1, column 8).
  MapReadOptions side;
  side.limits = pathref::io::ReadLimits{15, 1000};
  CHECK_THROWS_WITH(load_map_file(data_dir + "office.yaml", side),
                    data_dir + "office.yaml:1:8: the image is a 16x10 grid, which exceeds the limit of 15 cells per side");
  MapReadOptions cells;
  cells.limits = pathref::io::ReadLimits{100, 159};
  CHECK_THROWS_WITH(load_map_file(data_dir + "office.yaml", cells),
                    data_dir + "office.yaml:1:8: the image is a 16x10 grid, which exceeds the limit of 159 cells");
  // The text entry point cannot read a two-file map.
  CHECK_THROWS_AS(pathref::io::parse_map_text("image: x.pgm", "m.yaml", MapFormat::ros, MapReadOptions{}),
                  pathref::UsageError);
}

TEST_CASE("ros-map: plain P2 map with negate 1 and maxval 15 (corridor.yaml)", "[ros_map]") {
  const auto m = load_ros_map(data_dir + "corridor.yaml");
  CHECK(m.meta.negate);
  CHECK(m.meta.origin == std::array<double, 3>{1.5, -2.0, 0.785398});
  const Grid& g = m.map.grid;
  REQUIRE(g.width() == 8);
  REQUIRE(g.height() == 5);
  CHECK(g.to_rows_top_first() == std::vector<std::string>{"########", "........", "...##...",
                                                          "........", "########"});
  CHECK(m.unknown_cells == 1);  // the 8/15 pixel: p = 0.533 between 0.25 and 0.65
}

TEST_CASE("ros.occupancy: map_server thresholds, negate, 16-bit, raw", "[ros_map]") {
  RosMapMeta meta;  // 0.65 / 0.196, trinary
  CHECK(classify_pixel(0, 255, meta) == Occupancy::occupied);    // p = 1
  CHECK(classify_pixel(254, 255, meta) == Occupancy::free);      // p = 1/255
  CHECK(classify_pixel(205, 255, meta) == Occupancy::unknown);   // p = 50/255 = 0.19608 > 0.196
  CHECK(classify_pixel(89, 255, meta) == Occupancy::occupied);   // p = 166/255 = 0.651
  CHECK(classify_pixel(90, 255, meta) == Occupancy::unknown);    // p = 165/255 = 0.647
  meta.free_thresh = 0.25;                                       // Nav2 map_saver's default
  CHECK(classify_pixel(205, 255, meta) == Occupancy::free);      // 0.196 < 0.25: Nav2 reads 205 as free
  // Equality is neither occupied nor free.
  meta.occupied_thresh = 0.5;
  meta.free_thresh = 0.5;
  CHECK(classify_pixel(1, 2, meta) == Occupancy::unknown);
  meta = RosMapMeta{};
  meta.negate = true;
  CHECK(classify_pixel(255, 255, meta) == Occupancy::occupied);
  CHECK(classify_pixel(0, 255, meta) == Occupancy::free);
  CHECK(classify_pixel(65535, 65535, meta) == Occupancy::occupied);
  meta.negate = false;
  CHECK(classify_pixel(65535, 65535, meta) == Occupancy::free);
  CHECK(classify_pixel(30000, 65535, meta) == Occupancy::unknown);  // p = 0.542
  meta.mode = RosMapMode::scale;  // same classification as trinary on a binary grid
  CHECK(classify_pixel(205, 255, meta) == Occupancy::unknown);
  meta.mode = RosMapMode::raw;
  CHECK(classify_pixel(0, 255, meta) == Occupancy::free);
  CHECK(classify_pixel(100, 255, meta) == Occupancy::occupied);
  CHECK(classify_pixel(65, 255, meta) == Occupancy::unknown);  // p = 0.65, not > 0.65
  CHECK(classify_pixel(66, 255, meta) == Occupancy::occupied);
  CHECK(classify_pixel(19, 255, meta) == Occupancy::free);
  CHECK(classify_pixel(101, 255, meta) == Occupancy::unknown);
  CHECK(classify_pixel(255, 255, meta) == Occupancy::unknown);  // -1 as an unsigned byte
  CHECK_THROWS_AS(classify_pixel(0, 15, meta), pathref::DomainError);
  CHECK_THROWS_AS(classify_pixel(16, 15, RosMapMeta{}), pathref::DomainError);
}

TEST_CASE("ros-map: YAML subset accepts quoting, comments, markers, BOM, CRLF", "[ros_map]") {
  const auto m = parse_ros_yaml(
      "\xEF\xBB\xBF# comment\r\n---\r\nimage: \"dir/a \\\"b\\\".pgm\"   # trailing\r\n"
      "resolution: 5e-2\r\norigin: [ +1 , -2.5,.5 ]\r\nnegate: False\r\noccupied_thresh: 1\r\n"
      "free_thresh: 0\r\nmode: 'scale'\r\n...\r\n# after\r\n",
      "m.yaml");
  CHECK(m.image == "dir/a \"b\".pgm");
  CHECK(m.resolution == 0.05);
  CHECK(m.origin == std::array<double, 3>{1.0, -2.5, 0.5});
  CHECK(!m.negate);
  CHECK(m.occupied_thresh == 1.0);
  CHECK(m.free_thresh == 0.0);
  CHECK(m.mode == RosMapMode::scale);
  CHECK(parse_ros_yaml(with("image: map.pgm", "image: 'it''s #1.pgm'"), "m.yaml").image == "it's #1.pgm");
  CHECK(parse_ros_yaml(with("image: map.pgm", "image: my map#1.pgm # c"), "m.yaml").image == "my map#1.pgm");
  CHECK(parse_ros_yaml(kValid + "elevation_image: e.pgm\n", "m.yaml", true) == parse_ros_yaml(kValid, "m.yaml"));
}

TEST_CASE("ros-map: catalogue of malformed YAML with exact messages", "[ros_map]") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "m.yaml:1:1: missing required key 'image' (map_server requires image, resolution, origin, "
           "negate, occupied_thresh, free_thresh)"},
      {with("negate: 0\n", ""), "m.yaml:6:1: missing required key 'negate' (map_server requires image, "
                                "resolution, origin, negate, occupied_thresh, free_thresh)"},
      {kValid + "elevation_image: e.pgm\n",
       "m.yaml:7:1: unknown key 'elevation_image' (map_server reads image, resolution, origin, negate, "
       "occupied_thresh, free_thresh, mode)"},
      {kValid + "negate: 1\n", "m.yaml:7:1: duplicate key 'negate' (first given on line 4)"},
      {"image: a\rb\n", "m.yaml:1:9: unexpected carriage return (lines must end in LF or CRLF)"},
      {"image: a\x01.pgm\n", "m.yaml:1:9: unexpected control character byte 0x01"},
      {"image: m.pgm\n  resolution: 1\n",
       "m.yaml:2:3: expected a key at column 1 (indented lines and nested mappings are not part of the "
       "accepted subset)"},
      {"%YAML 1.2\n", "m.yaml:1:1: YAML directives ('%...') are not part of the accepted subset"},
      {"image m.pgm\n", "m.yaml:1:1: expected 'key: value' (keys are plain words followed by ': ')"},
      {"image:m.pgm\n", "m.yaml:1:1: expected 'key: value' (keys are plain words followed by ': ')"},
      {"\"image\": m.pgm\n", "m.yaml:1:1: expected 'key: value' (keys are plain words followed by ': ')"},
      {"---\nimage: m.pgm\n---\n",
       "m.yaml:3:1: unexpected document start marker '---' (a map_server YAML file holds one document)"},
      {"--- x\n", "m.yaml:1:5: expected end of line after '---', got 'x'"},
      {"...\nimage: m.pgm\n", "m.yaml:2:1: expected end of file after the document end marker '...'"},
      {"image:\n", "m.yaml:1:7: expected a value after 'image:' on the same line"},
      {"image: # none\n", "m.yaml:1:8: expected a value after 'image:' on the same line"},
      {"image: ~\n", "m.yaml:1:8: expected the image file name, got null"},
      {"image: ''\n", "m.yaml:1:8: expected the image file name, got an empty string"},
      {"image: [a]\n", "m.yaml:1:8: expected the image file name, got a sequence"},
      {"image: \"m.pgm\n",
       "m.yaml:1:8: unterminated double-quoted string (quoted values must end on the same line)"},
      {"image: 'm.pgm\n",
       "m.yaml:1:8: unterminated single-quoted string (quoted values must end on the same line)"},
      {"image: \"a\\tb\"\n",
       "m.yaml:1:10: unsupported escape in a double-quoted string (only \\\\ and \\\" are accepted)"},
      {"image: \"a\" b\n", "m.yaml:1:12: expected end of line after the value of 'image', got 'b'"},
      {"image: {a: 1}\n",
       "m.yaml:1:8: unsupported YAML syntax '{' in the value of 'image' (the accepted subset has plain "
       "and quoted scalars and one-line [ ] sequences)"},
      {"image: &a m.pgm\n",
       "m.yaml:1:8: unsupported YAML syntax '&' in the value of 'image' (the accepted subset has plain "
       "and quoted scalars and one-line [ ] sequences)"},
      {"image: |\n",
       "m.yaml:1:8: unsupported YAML syntax '|' in the value of 'image' (the accepted subset has plain "
       "and quoted scalars and one-line [ ] sequences)"},
      {"image: - m.pgm\n",
       "m.yaml:1:8: unsupported YAML syntax '-' in the value of 'image' (the accepted subset has plain "
       "and quoted scalars and one-line [ ] sequences)"},
      {"image: a: b\n",
       "m.yaml:1:9: unexpected ': ' in the value of 'image' (nested mappings are not part of the "
       "accepted subset; quote the value)"},
      {with("0.05", "fine"), "m.yaml:2:13: expected resolution as a number, got 'fine'"},
      {with("0.05", "\"0.05\""), "m.yaml:2:13: expected resolution as a number, got '0.05'"},
      {with("0.05", ".inf"), "m.yaml:2:13: expected resolution as a number, got '.inf'"},
      {with("0.05", "0x10"), "m.yaml:2:13: expected resolution as a number, got '0x10'"},
      {with("0.05", "1e999"), "m.yaml:2:13: resolution '1e999' is out of the range of a binary64 number"},
      {with("0.05", "0"), "m.yaml:2:13: resolution must be greater than 0, got 0"},
      {with("0.05", "-0.05"), "m.yaml:2:13: resolution must be greater than 0, got -0.05"},
      {with("0.05", "[1]"), "m.yaml:2:13: expected resolution as a number, got a sequence"},
      {with("[-10.0, -10.0, 0.0]", "0"), "m.yaml:3:9: expected origin as a sequence [x, y, yaw], got '0'"},
      {with("[-10.0, -10.0, 0.0]", "[1, 2]"),
       "m.yaml:3:9: expected origin as a sequence of 3 numbers [x, y, yaw], got 2 items"},
      {with("[-10.0, -10.0, 0.0]", "[]"),
       "m.yaml:3:9: expected origin as a sequence of 3 numbers [x, y, yaw], got 0 items"},
      {with("[-10.0, -10.0, 0.0]", "[1, 2, 3"),
       "m.yaml:3:17: expected ']' to close the sequence of 'origin' on the same line (multi-line "
       "sequences are not part of the accepted subset)"},
      {with("[-10.0, -10.0, 0.0]", "[1, , 3]"),
       "m.yaml:3:13: expected a number in the sequence of 'origin', got ','"},
      {with("[-10.0, -10.0, 0.0]", "[1 2 3]"),
       "m.yaml:3:12: expected ',' or ']' in the sequence of 'origin', got '2'"},
      {with("[-10.0, -10.0, 0.0]", "[1, [2], 3]"),
       "m.yaml:3:13: expected a plain number in the sequence of 'origin' (nested or quoted items are "
       "not part of the accepted subset)"},
      {with("[-10.0, -10.0, 0.0]", "[1, 2, 3] x"),
       "m.yaml:3:19: expected end of line after the sequence of 'origin', got 'x'"},
      {with("[-10.0, -10.0, 0.0]", "[1, y, 3]"), "m.yaml:3:13: expected origin y as a number, got 'y'"},
      {with("negate: 0", "negate: 2"), "m.yaml:4:9: expected negate as 0, 1, true or false, got '2'"},
      {with("negate: 0", "negate: yes"), "m.yaml:4:9: expected negate as 0, 1, true or false, got 'yes'"},
      {with("0.65", "1.5"), "m.yaml:5:18: occupied_thresh must be between 0 and 1, got 1.5"},
      {with("0.196", "-0.1"), "m.yaml:6:14: free_thresh must be between 0 and 1, got -0.1"},
      {with("0.196", "0.7"), "m.yaml:6:14: free_thresh (0.7) must not be larger than occupied_thresh (0.65)"},
      {kValid + "mode: Trinary\n", "m.yaml:7:7: expected mode as trinary, scale or raw, got 'Trinary'"},
      {with("negate: 0", "negate: 1") + "mode: raw\n",
       "m.yaml:4:9: negate must be 0 in mode raw (ROS 1 map_server inverts raw values when negated, "
       "Nav2 does not; pathref does not guess)"},
      {"image: m.pgm\norigin:\n  - 0\n", "m.yaml:2:8: expected a value after 'origin:' on the same line"},
  };
  for (const auto& [text, message] : cases) {
    INFO(text);
    CHECK(yaml_error(text) == message);
  }
}

TEST_CASE("pgm: P2 and P5 with comments, 16-bit samples, whitespace rules", "[ros_map]") {
  const PgmImage a = parse_pgm(std::string("P5\n# c\n2 2\n255\n\x00\xfe\xcd\x01", 19), "a.pgm");
  CHECK(a.width == 2);
  CHECK(a.height == 2);
  CHECK(a.maxval == 255);
  CHECK(a.pixels == std::vector<std::uint16_t>{0, 254, 205, 1});
  const PgmImage b = parse_pgm(std::string("P5 2\t1\r65535\n\x01\x02\xff\xfe", 17), "b.pgm");
  CHECK(b.pixels == std::vector<std::uint16_t>{258, 65534});
  const PgmImage c = parse_pgm("P2\n#x\n2 1 #y\n15\n3 # z\n15\n\n", "c.pgm");
  CHECK(c.pixels == std::vector<std::uint16_t>{3, 15});
  const PgmImage d = parse_pgm(std::string("P5 1 1 255# comment\n\x07 \n", 22), "d.pgm");
  CHECK(d.pixels == std::vector<std::uint16_t>{7});
  CHECK(parse_pgm("P2 1 1 1 1", "e.pgm").pixels == std::vector<std::uint16_t>{1});
}

TEST_CASE("pgm: catalogue of malformed images with exact messages", "[ros_map]") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "m.pgm:1:1: expected a PGM magic number 'P2' or 'P5', got an empty file"},
      {"P6\n1 1\n255\n", "m.pgm:1:1: unsupported Netpbm format 'P6' (pathref reads the grayscale formats P2 and P5)"},
      {"\x89PNG\r\n", "m.pgm:1:1: expected a PGM magic number 'P2' or 'P5' (pathref reads only PGM images; "
                      "convert other image formats to PGM)"},
      {"P", "m.pgm:1:1: expected a PGM magic number 'P2' or 'P5' (pathref reads only PGM images; "
            "convert other image formats to PGM)"},
      {"P51 1\n", "m.pgm:1:3: expected whitespace after the magic number 'P5', got '1'"},
      {"P5\n", "m.pgm:2:1: unexpected end of file: expected the width (a decimal integer)"},
      {"P5\n-1 1\n", "m.pgm:2:1: expected the width (a decimal integer), got '-'"},
      {"P5\n0 1\n", "m.pgm:2:1: width must be between 1 and 268435456, got 0"},
      {"P5\n1 99999999999999999999\n", "m.pgm:2:3: height must be between 1 and 268435456, got 99999999999999999999"},
      {"P5\n2x 1\n", "m.pgm:2:2: expected whitespace after the width, got 'x'"},
      {"P5\n1 1\n0\n", "m.pgm:3:1: maxval must be between 1 and 65535, got 0"},
      {"P2\n1 1\n65536\n0\n", "m.pgm:3:1: maxval must be between 1 and 65535, got 65536"},
      {"P5\n16385 16384\n255\n", "m.pgm:2:1: a 16385x16384 image exceeds the limit of 268435456 cells"},
      {"P5\n1 1\n255", "m.pgm:3:4: unexpected end of file: expected one whitespace byte and the pixel data after the maxval"},
      {"P5\n4 4\n255\n\x01\x01", "m.pgm:4:1: unexpected end of file in the pixel data: expected 16 bytes (4x4 pixels, "
                                 "1 byte each) from byte offset 11, got 2"},
      {std::string("P5\n2 1\n1000\n\x00\x01\x02", 15),
       "m.pgm:4:1: unexpected end of file in the pixel data: expected 4 bytes (2x1 pixels, 2 bytes each) from "
       "byte offset 12, got 3"},
      {"P5\n2 1\n100\n\x32\x65", "m.pgm:4:1: pixel value 101 at byte offset 12 (column 2, row 1) is larger than the maxval 100"},
      {"P5\n1 1\n255\n\x07P5", "m.pgm:4:2: expected end of file after the pixel data, got 'P' at byte offset 12 (files "
                               "with more than one image are not supported)"},
      {"P2\n3 1\n255\n1 2\n", "m.pgm:5:1: unexpected end of file: expected pixel value 3 of 3"},
      {"P2\n2 2\n255\n1 2 3\n", "m.pgm:5:1: unexpected end of file: expected pixel value 4 of 4"},
      {"P2\n2 1\n15\n3 16\n", "m.pgm:4:3: pixel value 16 (column 2, row 1) is larger than the maxval 15"},
      {"P2\n2 1\n15\n3 0000001\n", "m.pgm:4:3: pixel value 0000001 (column 2, row 1) is larger than the maxval 15"},
      {"P2\n2 1\n15\n3 -1\n", "m.pgm:4:3: expected pixel value 2 of 2 (a decimal integer), got '-'"},
      {"P2\n2 1\n15\n3 1x\n", "m.pgm:4:4: expected whitespace after pixel value 2 of 2, got 'x'"},
      {"P2\n1 1\n15\n3 4\n", "m.pgm:4:3: expected end of file after the 1 pixel values"},
  };
  for (const auto& [bytes, message] : cases) {
    INFO(bytes);
    CHECK(pgm_error(bytes) == message);
  }
}

TEST_CASE("ros-map: raw mode needs maxval 255 - file errors point at the YAML", "[ros_map]") {
  const std::string yaml = kValid + "mode: raw\n";
  try {
    (void)parse_ros_map(yaml, "m.yaml", "P2\n1 1\n100\n50\n", "m.pgm");
    FAIL("no error");
  } catch (const ParseError& e) {
    CHECK(std::string(e.what()) == "m.pgm:3:1: mode raw needs an 8-bit image with maxval 255, got maxval 100");
  }
  const auto raw = parse_ros_map(yaml, "m.yaml", "P2\n4 1\n255\n0 100 50 255\n", "m.pgm");
  CHECK(raw.map.grid.to_rows_top_first() == std::vector<std::string>{".###"});
  CHECK(raw.unknown_cells == 2);

  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "pathref_ros_map_test";
  fs::create_directories(dir);
  {
    std::ofstream(dir / "lost.yaml") << with("map.pgm", "missing.pgm");
  }
  try {
    (void)load_ros_map((dir / "lost.yaml").string());
    FAIL("no error");
  } catch (const ParseError& e) {
    CHECK(e.line() == 1);
    CHECK(e.column() == 8);
    INFO(e.what());
    CHECK(std::string(e.what()).find("cannot read image file '" + (dir / "missing.pgm").string() +
                                     "': No such file or directory") != std::string::npos);
  }
  CHECK_THROWS_AS(load_ros_map((dir / "nope.yaml").string()), pathref::UsageError);
  CHECK_THROWS_AS(load_ros_map(dir.string()), pathref::UsageError);
  fs::remove_all(dir);
}

TEST_CASE("ros-map: writer writes map_saver files that read back", "[ros_map]") {
  const Grid g = Grid::from_rows_top_first({"#..", "..#"});
  const auto files = pathref::io::to_ros_map(g, 0.05, {-1.5, 2.0, 0.1}, "m.pgm");
  CHECK(files.yaml ==
        "image: \"m.pgm\"\nmode: trinary\nresolution: 0.05\norigin: [-1.5, 2, 0.1]\nnegate: 0\n"
        "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  CHECK(files.pgm == std::string("P5\n3 2\n255\n\x00\xfe\xfe\xfe\xfe\x00", 17));
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "pathref_ros_map_writer_test";
  fs::create_directories(dir);
  pathref::io::write_ros_map((dir / "out.yaml").string(), g, 0.05, {-1.5, 2.0, 0.1});
  const auto back = load_ros_map((dir / "out.yaml").string());
  CHECK(back.map.grid == g);
  CHECK(back.meta.image == "out.pgm");
  CHECK(back.unknown_cells == 0);
  fs::remove_all(dir);
  CHECK_THROWS_AS(pathref::io::to_ros_map(g, 0.0, {0, 0, 0}, "m.pgm"), pathref::DomainError);
  CHECK_THROWS_AS(pathref::io::to_ros_map(g, 1.0, {0, 0, 0}, "a\nb.pgm"), pathref::DomainError);
}
