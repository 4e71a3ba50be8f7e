#pragma once
/// \file map_file.hpp
/// Reading any map format pathref knows (pathref-grid 1, MovingAI `.map`, 0/1 matrices, ROS
/// map_server YAML + PGM), chosen
/// by the file's extension or given explicitly, plus what the format readers share: the read
/// limits, the MovingAI terrain choice, and the line splitting of spec/formats.md#line-endings.
/// Spec: spec/formats.md#map-files (detection, limits, options), #movingai-map, #matrix, #ros-map.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "pathref/core/memory.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/io/grid_text.hpp"
#include "pathref/io/ros_map.hpp"

namespace pathref::io {

/// Limits a reader checks BEFORE it allocates the grid (spec/formats.md#limits). The defaults are
/// the grid's own hard limit; callers (the CLI's --max-side/--max-cells, the fuzzers) may lower
/// them. Pre: 1 <= max_side <= Grid::max_cells, 1 <= max_cells <= Grid::max_cells.
struct ReadLimits {
  std::int64_t max_side = grid::Grid::max_cells;   ///< largest width or height
  std::int64_t max_cells = grid::Grid::max_cells;  ///< largest width * height
  /// The memory limit (spec/cli.md#memory, --max-memory) and the bytes per cell the caller will
  /// need once the map is read (the grid's 1 byte, or a planner's Planner::bytes_per_cell): a
  /// reader whose input can declare more cells than its text holds (a polygon scene's world)
  /// refuses W x H x bytes_per_cell > max_memory before allocating the grid (UsageError naming
  /// the estimate and the limit). Text grid formats are bounded by their text (>= 1 byte per cell).
  std::uint64_t max_memory = memory::default_limit;
  std::uint64_t bytes_per_cell = 1;
};

/// Checks that `limits` are within [1, Grid::max_cells]; UsageError naming the bad one.
void check_limits(const ReadLimits& limits);

/// How the MovingAI terrain letters `S` (swamp) and `W` (water) are read. MovingAI: swamp is
/// "passable from regular terrain", water "traversable, but not passable from terrain"; pathref
/// has one kind of free cell, so each is either free or blocked. Defaults: S free, W blocked
/// (the benchmark's convention). Spec: spec/formats.md#movingai-terrain.
struct MovingAiTerrain {
  bool swamp_free = true;
  bool water_free = false;
};

/// The map formats. `automatic` means: decide by the file name (detect_map_format).
enum class MapFormat { automatic, pathref_grid, movingai, matrix, ros, scene };

/// "auto" | "pathref-grid" | "movingai" | "matrix" | "ros" | "scene" -> format; UsageError otherwise.
[[nodiscard]] MapFormat parse_map_format(std::string_view name);
/// The inverse of parse_map_format.
[[nodiscard]] std::string_view to_string(MapFormat format) noexcept;

/// The format of a map file from its name and its first bytes (spec/formats.md#detection):
/// `.map` -> movingai; `.m` and `.csv` -> matrix; `.yaml` and `.yml` -> ros (map_server YAML);
/// `.json` -> scene (pathref-scene 1 polygons, inflated);
/// any other name -> pathref_grid when the text
/// starts with "pathref-grid", movingai when it starts with "type", else matrix.
/// Never returns automatic. Pre: none.
[[nodiscard]] MapFormat detect_map_format(std::string_view path, std::string_view head);

/// Options of load_map_file / parse_map_text.
struct MapReadOptions {
  MapFormat format = MapFormat::automatic;
  MovingAiTerrain terrain;
  ReadLimits limits;
  /// ROS maps: what unknown cells become (spec/formats.md#ros-occupancy; default blocked).
  UnknownAs ros_unknown = UnknownAs::blocked;
  /// Polygon scenes: turns a scene file's text into a map (the exact inflation of
  /// spec/inflation.md lives in pathref_geometry, which links CGAL; the CLI installs it). Empty:
  /// a scene is a UsageError saying so. Pre: none.
  /// It receives the limits and must check them before allocating the grid.
  std::function<MapFile(std::string_view text, const std::string& filename, const ReadLimits& limits)> scene_to_map;
};

/// A map read from a file, with the format it was read as.
struct LoadedMapFile {
  MapFile map;
  MapFormat format = MapFormat::pathref_grid;
};

/// Parses `text` as `format` (not automatic: DomainError; not ros, which is two files: UsageError
/// pointing to load_map_file / parse_ros_map). ParseError (naming `filename`) for any
/// deviation from that format's grammar or the limits. pathref-grid's own reader checks its fixed
/// limit of Grid::max_cells before allocating and bounds memory by the text size; lower `limits`
/// are then checked on its result and reported at the width in its `size` line.
[[nodiscard]] MapFile parse_map_text(std::string_view text, std::string_view filename,
                                     MapFormat format, const MapReadOptions& options);

/// Reads a whole text file. UsageError `cannot read WHAT 'F': REASON` when it does not exist, is
/// not a regular file or cannot be opened, and `WHAT 'F' has N bytes, more than the limit of
/// 1073741824` when larger than max_map_file_bytes (checked before reading).
/// `what` is e.g. "map file" or "scenario file".
[[nodiscard]] std::string read_text_file(const std::string& path, std::string_view what);

/// Reads a map file in the given or detected format (spec/formats.md#map-files). A `.scen` file
/// is refused with a UsageError pointing to `pathref scen`. A ROS map is read with load_ros_map
/// (the image is resolved against the YAML's directory); the limits are then checked on its size
/// and a map over them is a ParseError at the YAML's `image` value.
[[nodiscard]] LoadedMapFile load_map_file(const std::string& path, const MapReadOptions& options);

/// The output formats of `pathref convert` (spec/formats.md#cli-convert).
enum class OutputFormat { pathref_grid, movingai, matrix, matlab };
/// "pathref-grid" | "movingai" | "matrix" | "matlab" -> format; UsageError otherwise.
[[nodiscard]] OutputFormat parse_output_format(std::string_view name);
/// Writes `map` in `format`. Only pathref-grid keeps the name, start and goal.
[[nodiscard]] std::string write_map_text(const MapFile& map, OutputFormat format);

namespace text {

/// One physical line: its bytes without the line ending and its 1-based number.
struct Line {
  std::string_view text;
  std::size_t number = 0;
};

/// Splits text into lines (spec/formats.md#line-endings): LF or CRLF end a line, the last line
/// needs no ending, any other CR is a ParseError `unexpected carriage return (lines must end in
/// LF or CRLF)` at the CR.
[[nodiscard]] std::vector<Line> split_lines(std::string_view text, const std::string& file);

/// A byte for an error message: 'c' for printable ASCII (0x20..0x7e), else `byte 0xNN`.
[[nodiscard]] std::string describe_byte(char c);

/// Space or tab.
[[nodiscard]] constexpr bool is_blank_char(char c) noexcept { return c == ' ' || c == '\t'; }

/// True when text starts with the UTF-8 byte-order mark EF BB BF.
[[nodiscard]] bool has_bom(std::string_view text) noexcept;

/// The 1-based line number for "end of file": last line + 1 (1 for an empty text).
[[nodiscard]] std::size_t eof_line(const std::vector<Line>& lines) noexcept;

}  // namespace text

}  // namespace pathref::io
