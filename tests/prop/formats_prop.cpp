// Properties of the MovingAI and matrix readers/writers and the format-detecting loader
// (spec/formats.md#movingai-map, #matrix, #map-files): write-then-read round trips on random
// grids, CRLF invariance, and "parse or ParseError, nothing else" on corrupted text.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <string>

#include "pathref/core/error.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/io/matrix.hpp"
#include "pathref/io/movingai.hpp"
#include "support/generators.hpp"
#include "support/reach.hpp"

using pathref::grid::Grid;
using namespace pathref::io;

namespace {

std::string to_crlf(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\n') out += '\r';
    out += c;
  }
  return out;
}

/// Parses `text` with `parse`; RC-fails unless it succeeds or throws a ParseError whose position
/// lies within the text (line <= number of lines + 1, column >= 1). On success the grid must be a
/// well-formed map: written with `write` and parsed again it is the same grid. Returns whether
/// the text was rejected (the callers count both outcomes: issue 17, no "parses or throws" only).
template <class Parse, class Write>
bool parse_or_parse_error(const std::string& text, Parse parse, Write write) {
  std::size_t lines = 1;
  for (const char c : text) lines += c == '\n' ? 1 : 0;
  try {
    const MapFile m = parse(text);
    RC_ASSERT(m.grid.width() >= 1);
    RC_ASSERT(m.grid.height() >= 1);
    RC_ASSERT(parse(write(m.grid)).grid == m.grid);
    return false;
  } catch (const pathref::ParseError& e) {
    RC_ASSERT(e.file() == "bad");
    RC_ASSERT(e.line() >= 1);
    RC_ASSERT(e.line() <= lines + 1);
    RC_ASSERT(e.column() >= 1);
    return true;
  }
}

/// `text` with one byte replaced from `alphabet`, or cut at a random position.
std::string corrupt(const std::string& text, const std::string& alphabet) {
  std::string bad = text;
  const auto pos = *rc::gen::inRange<std::size_t>(0, text.size());
  if (*rc::gen::arbitrary<bool>())
    bad[pos] = *rc::gen::elementOf(alphabet);
  else
    bad.resize(pos);
  return bad;
}

}  // namespace

TEST_CASE("formats prop: MovingAI write then read gives the same grid", "[movingai][prop]") {
  rc::prop("parse_movingai_map(to_movingai_map(g)) == g, also with CRLF", [] {
    const Grid g = *pathref::testing::gen_grid(30, 30, 0.6);
    const std::string text = to_movingai_map(g);
    RC_ASSERT(parse_movingai_map(text, "rt").grid == g);
    RC_ASSERT(parse_movingai_map(to_crlf(text), "crlf").grid == g);
    RC_ASSERT(to_movingai_map(parse_movingai_map(text, "rt").grid) == text);  // canonical form
  });
}

TEST_CASE("formats prop: MovingAI terrain letters map to free/blocked as specified", "[movingai][prop]") {
  rc::prop("each letter is free or blocked per the terrain option", [] {
    const Grid g = *pathref::testing::gen_grid(20, 20, 0.6);
    const bool swamp_free = *rc::gen::arbitrary<bool>();
    const bool water_free = *rc::gen::arbitrary<bool>();
    // Re-spell every cell with a random letter of its class.
    std::string free_letters = ".G";
    std::string blocked_letters = "@OT";
    (swamp_free ? free_letters : blocked_letters) += 'S';
    (water_free ? free_letters : blocked_letters) += 'W';
    std::string text = to_movingai_map(g);
    const std::size_t body = text.find("map\n") + 4;
    for (std::size_t i = body; i < text.size(); ++i) {
      if (text[i] == '.') text[i] = *rc::gen::elementOf(free_letters);
      else if (text[i] == '@') text[i] = *rc::gen::elementOf(blocked_letters);
    }
    RC_ASSERT(parse_movingai_map(text, "t", MovingAiTerrain{swamp_free, water_free}).grid == g);
  });
}

TEST_CASE("formats prop: matrix write then read gives the same grid (plain and MATLAB)", "[matrix][prop]") {
  rc::prop("parse_matrix(to_matrix_text(g)) == parse_matrix(to_matlab_text(g)) == g", [] {
    const Grid g = *pathref::testing::gen_grid(30, 30, 0.6);
    RC_ASSERT(parse_matrix(to_matrix_text(g), "plain").grid == g);
    RC_ASSERT(parse_matrix(to_matlab_text(g), "matlab").grid == g);
    RC_ASSERT(parse_matrix(to_crlf(to_matlab_text(g)), "crlf").grid == g);
    RC_ASSERT(to_matrix_text(parse_matrix(to_matrix_text(g), "p").grid) == to_matrix_text(g));
  });
}

TEST_CASE("formats prop: convert between all formats keeps the grid", "[map_file][prop]") {
  rc::prop("write in A, detect/read, write in B, read: same grid", [] {
    const Grid g = *pathref::testing::gen_grid(25, 25, 0.6);
    const MapFile m{g, std::nullopt, std::nullopt, ""};
    const auto a = *rc::gen::element(OutputFormat::pathref_grid, OutputFormat::movingai, OutputFormat::matrix,
                                     OutputFormat::matlab);
    const std::string text = write_map_text(m, a);
    const MapFormat detected = detect_map_format("x.txt", text);  // content rule for .txt
    const MapFile back = parse_map_text(text, "x.txt", detected, MapReadOptions{});
    RC_ASSERT(back.grid == g);
  });
}

TEST_CASE("formats prop: corrupted or truncated text parses or throws ParseError, nothing else",
          "[movingai][matrix][prop]") {
  // Both branches must run: at least 20 % of the corrupted texts rejected and 5 % accepted (and
  // then well-formed, see parse_or_parse_error).
  pathref::testing::Reach rejected, accepted;
  rc::prop("one byte changed or the text cut", [&rejected, &accepted] {
    const Grid g = *pathref::testing::gen_grid(12, 12, 0.6);
    const ReadLimits limits{64, 4096};
    const auto record = [&](bool r) {
      rejected.hit(r);
      accepted.hit(!r);
    };
    record(parse_or_parse_error(
        corrupt(to_movingai_map(g), ".@GSWOTx#\r\n\t 0123456789-"),
        [&](const std::string& t) { return parse_movingai_map(t, "bad", {}, limits); },
        [](const Grid& x) { return to_movingai_map(x); }));
    record(parse_or_parse_error(corrupt(to_matrix_text(g), "01 ,;\r\n\t%.[]x2"),
                                [&](const std::string& t) { return parse_matrix(t, "bad", limits); },
                                [](const Grid& x) { return to_matrix_text(x); }));
    record(parse_or_parse_error(corrupt(to_matlab_text(g), "01 ,;\r\n\t%.[]=Gx2"),
                                [&](const std::string& t) { return parse_matrix(t, "bad", limits); },
                                [](const Grid& x) { return to_matlab_text(x); }));
  });
  pathref::testing::require_reach(rejected, 0.2, "corrupted texts rejected with a ParseError");
  pathref::testing::require_reach(accepted, 0.05, "corrupted texts still accepted");
}

TEST_CASE("formats prop: scenario lines written from random cells parse back", "[movingai][scen][prop]") {
  rc::prop("parse_movingai_scen reads the columns as written", [] {
    const auto w = *rc::gen::inRange<std::int64_t>(1, 1000);
    const auto h = *rc::gen::inRange<std::int64_t>(1, 1000);
    RC_PRE(w * h >= 2);
    const auto sx = *rc::gen::inRange<std::int64_t>(0, w);
    const auto sy = *rc::gen::inRange<std::int64_t>(0, h);
    const auto gx = *rc::gen::inRange<std::int64_t>(0, w);
    const auto gy = *rc::gen::inRange<std::int64_t>(0, h);
    RC_PRE(sx != gx || sy != gy);
    const auto ip = *rc::gen::inRange(0, 100000);
    const auto fp = *rc::gen::inRange(0, 100000);
    const std::string len = std::to_string(ip) + "." + std::to_string(fp);
    const std::string line = "3\tmaps/x.map\t" + std::to_string(w) + "\t" + std::to_string(h) + "\t" +
                             std::to_string(sx) + "\t" + std::to_string(sy) + "\t" + std::to_string(gx) + "\t" +
                             std::to_string(gy) + "\t" + len + "\n";
    const ScenFile f = parse_movingai_scen("version 1\n" + line, "p.scen");
    RC_ASSERT(f.scenarios.size() == 1U);
    const Scenario& s = f.scenarios[0];
    RC_ASSERT(s.width->value == w);
    RC_ASSERT(s.height->value == h);
    RC_ASSERT(s.start_x.value == sx);
    RC_ASSERT(s.start_y.value == sy);
    RC_ASSERT(s.goal_x.value == gx);
    RC_ASSERT(s.goal_y.value == gy);
    RC_ASSERT(s.optimal.text == len);
    RC_ASSERT(s.optimal.last_digit_exponent == -static_cast<int>(std::to_string(fp).size()));
  });
}
