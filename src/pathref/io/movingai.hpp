#pragma once
/// \file movingai.hpp
/// The MovingAI grid benchmark formats (N. Sturtevant, "Benchmarks for Grid-Based Pathfinding",
/// IEEE TCIAIG 4(2), 2012, doi:10.1109/TCIAIG.2012.2197681; https://movingai.com/benchmarks/):
/// `.map` files (`type octile`, `height H`, `width W`, `map`, H rows of terrain letters) and
/// `.scen` scenario files (version 1 with 9 columns, version 0 with 7).
/// MovingAI puts (0, 0) at the UPPER left (x = column, y = row counted downwards); pathref at the
/// lower left. The map reader converts (first text row = top row = pathref y = H - 1); scenario
/// coordinates stay in the file's convention and are converted with from_movingai / to_movingai.
/// Spec: spec/formats.md#movingai-map, #movingai-scen, #scen-agreement.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pathref/grid/grid.hpp"
#include "pathref/io/grid_text.hpp"
#include "pathref/io/map_file.hpp"

namespace pathref::io {

/// Parses a MovingAI `.map` text. `.` and `G` are free; `@`, `O`, `T` blocked; `S` and `W` as
/// `terrain` says. The result has no start, goal or name. ParseError(filename, line, column,
/// what was expected) for any deviation from spec/formats.md#movingai-map; width, height and
/// W * H are checked against `limits` and all H rows are checked before the grid is allocated.
[[nodiscard]] MapFile parse_movingai_map(std::string_view text, std::string_view filename,
                                         const MovingAiTerrain& terrain = {},
                                         const ReadLimits& limits = {});

/// Writes the grid as a MovingAI `.map`: `type octile`, `height H`, `width W`, `map`, then the
/// rows top first with `.` (free) and `@` (blocked), each line ending in LF.
/// Post: parse_movingai_map(to_movingai_map(g), f).grid == g.
[[nodiscard]] std::string to_movingai_map(const grid::Grid& g);

/// MovingAI cell (x = column, y = row from the top) -> pathref cell (x, H - 1 - y).
/// Pre: none (pure arithmetic; bounds are the caller's concern).
[[nodiscard]] constexpr grid::Cell from_movingai(std::int64_t x, std::int64_t y,
                                                 std::int64_t height) noexcept {
  return grid::Cell{x, height - 1 - y};
}
/// pathref cell -> MovingAI (x, H - 1 - y); the inverse of from_movingai.
[[nodiscard]] constexpr grid::Cell to_movingai(grid::Cell c, std::int64_t height) noexcept {
  return grid::Cell{c.x, height - 1 - c.y};
}

/// An optimal length as printed in a scenario file, with the tolerance derived from its text.
/// Spec: spec/formats.md#scen-agreement.
struct PrintedLength {
  std::string text;          ///< exactly as in the file
  double value = 0.0;        ///< the double nearest the decimal value of `text`
  int last_digit_exponent = 0;  ///< q: the last printed digit is worth 10^q
  int significant_digits = 0;   ///< s: digits from the first non-zero one to the last printed
};

/// Parses `text` = 1*DIGIT ["." 1*DIGIT] [("e" / "E") ["+" / "-"] 1*3DIGIT] (the `length`
/// rule of spec/formats.md#movingai-scen); nullopt when `text` does not match, has more than 40
/// mantissa digits, or its value is not finite.
[[nodiscard]] std::optional<PrintedLength> parse_printed_length(std::string_view text);

/// The agreement tolerance of a printed length: U = 10^(q - max(0, P - s)) where P =
/// `writer_digits` (the significant digits the writer printed before it dropped trailing zeros;
/// 6 for the MovingAI files; 0 = take the printed digits literally). Pre: 0 <= writer_digits <= 17.
/// Spec: scen-agreement.
[[nodiscard]] double agreement_tolerance(const PrintedLength& length, int writer_digits);

/// True iff |computed - printed.value| <= tolerance, evaluated in binary64. Spec: scen-agreement.
[[nodiscard]] bool lengths_agree(double computed, const PrintedLength& printed, double tolerance) noexcept;

/// A value read from a scenario line with where it was written.
struct ScenField {
  std::int64_t value = 0;
  std::size_t column = 0;
};

/// One scenario line. Coordinates are in the FILE's convention: (0, 0) upper left, y down.
struct Scenario {
  std::size_t line = 0;      ///< 1-based line number in the scenario file
  std::int64_t bucket = 0;
  std::string map;           ///< the map column as written
  std::size_t map_column = 0;
  std::optional<ScenField> width;   ///< version 1 only
  std::optional<ScenField> height;  ///< version 1 only
  ScenField start_x, start_y, goal_x, goal_y;
  PrintedLength optimal;
  std::size_t optimal_column = 0;
};

/// A parsed scenario file.
struct ScenFile {
  int version = 1;  ///< 1 (`version 1` / `version 1.0`) or 0 (no version line, `version 0`, `version 0.0`)
  std::vector<Scenario> scenarios;  ///< in file order, at least one
};

/// Parses a `.scen` text (spec/formats.md#movingai-scen). Checks every line's syntax and ranges,
/// that start and goal lie inside the line's width x height (version 1) and differ. Checks that
/// need the map (its size, blocked cells) are scenario_map_errors'. ParseError otherwise.
/// `limits.max_side` bounds width and height.
[[nodiscard]] ScenFile parse_movingai_scen(std::string_view text, std::string_view filename,
                                           const ReadLimits& limits = {});

/// Checks scenario `s` of scenario file `filename` against the map it runs on (`g`, named
/// `map_name` in messages): the line's width/height equal the map's (version 1; pathref does not
/// scale maps), start and goal inside the map (version 0) and free. Throws the ParseError of
/// spec/formats.md#movingai-scen (at the scenario line) for the first failing check.
void check_scenario_on_map(const Scenario& s, const grid::Grid& g, std::string_view map_name,
                           std::string_view filename);

}  // namespace pathref::io
