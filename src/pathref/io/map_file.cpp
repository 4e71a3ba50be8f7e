#include "pathref/io/map_file.hpp"

#include "pathref/io/input_file.hpp"

#include <fmt/core.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <utility>
#include <system_error>

#include "pathref/core/error.hpp"
#include "pathref/io/json_text.hpp"
#include "pathref/io/matrix.hpp"
#include "pathref/io/movingai.hpp"

namespace pathref::io {

namespace text {

std::vector<Line> split_lines(std::string_view text, const std::string& file) {
  std::vector<Line> lines;
  std::size_t start = 0;
  std::size_t number = 1;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    const bool terminated = end != std::string_view::npos;
    if (!terminated) end = text.size();
    std::size_t content_end = end;
    if (terminated && content_end > start && text[content_end - 1] == '\r') --content_end;
    const std::string_view content = text.substr(start, content_end - start);
    const std::size_t cr = content.find('\r');
    if (cr != std::string_view::npos)
      throw ParseError(file, number, cr + 1, "unexpected carriage return (lines must end in LF or CRLF)");
    lines.push_back(Line{content, number});
    start = terminated ? end + 1 : end;
    ++number;
  }
  return lines;
}

std::string describe_byte(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u >= 0x20 && u < 0x7f) return fmt::format("'{}'", c);
  return fmt::format("byte 0x{:02x}", static_cast<unsigned>(u));
}

bool has_bom(std::string_view text) noexcept { return text.substr(0, 3) == "\xEF\xBB\xBF"; }

std::size_t eof_line(const std::vector<Line>& lines) noexcept {
  return lines.empty() ? 1 : lines.back().number + 1;
}

}  // namespace text

void check_limits(const ReadLimits& limits) {
  constexpr std::int64_t hard = grid::Grid::max_cells;
  if (limits.max_side < 1 || limits.max_side > hard)
    throw UsageError(fmt::format("the side limit must be between 1 and {}, got {}", hard, limits.max_side));
  if (limits.max_cells < 1 || limits.max_cells > hard)
    throw UsageError(fmt::format("the cell limit must be between 1 and {}, got {}", hard, limits.max_cells));
}

MapFormat parse_map_format(std::string_view name) {
  if (name == "auto") return MapFormat::automatic;
  if (name == "pathref-grid") return MapFormat::pathref_grid;
  if (name == "movingai") return MapFormat::movingai;
  if (name == "matrix") return MapFormat::matrix;
  if (name == "ros") return MapFormat::ros;
  if (name == "scene") return MapFormat::scene;
  throw UsageError(
      fmt::format("unknown map format '{}' (known: auto, pathref-grid, movingai, matrix, ros, scene)", name));
}

std::string_view to_string(MapFormat format) noexcept {
  switch (format) {
    case MapFormat::automatic: return "auto";
    case MapFormat::pathref_grid: return "pathref-grid";
    case MapFormat::movingai: return "movingai";
    case MapFormat::matrix: return "matrix";
    case MapFormat::ros: return "ros";
    case MapFormat::scene: return "scene";
  }
  return "auto";
}

namespace {

/// The extension of a path's file name, lower-cased, with its dot ("" when none).
std::string extension_of(std::string_view path) {
  const auto slash = path.find_last_of('/');
  const std::string_view name = slash == std::string_view::npos ? path : path.substr(slash + 1);
  const auto dot = name.find_last_of('.');
  if (dot == std::string_view::npos || dot == 0) return "";
  std::string ext(name.substr(dot));
  for (char& c : ext)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return ext;
}

/// True when `text` starts with `word` followed by a blank, a line end or the end of the text.
bool starts_with_word(std::string_view text, std::string_view word) {
  if (text.substr(0, word.size()) != word) return false;
  if (text.size() == word.size()) return true;
  const char c = text[word.size()];
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

/// The line and column of the width in the first `size` line of pathref-grid text (1:1 if none).
std::pair<std::size_t, std::size_t> size_position(std::string_view text_in) {
  std::size_t number = 1;
  std::size_t start = 0;
  while (start <= text_in.size()) {
    std::size_t end = text_in.find('\n', start);
    if (end == std::string_view::npos) end = text_in.size();
    const std::string_view line = text_in.substr(start, end - start);
    std::size_t i = 0;
    while (i < line.size() && text::is_blank_char(line[i])) ++i;
    if (line.substr(i, 4) == "size" && i + 4 < line.size() && text::is_blank_char(line[i + 4])) {
      i += 4;
      while (i < line.size() && text::is_blank_char(line[i])) ++i;
      return {number, i + 1};
    }
    if (end == text_in.size()) break;
    start = end + 1;
    ++number;
  }
  return {1, 1};
}

}  // namespace

MapFormat detect_map_format(std::string_view path, std::string_view head) {
  const std::string ext = extension_of(path);
  if (ext == ".map") return MapFormat::movingai;
  if (ext == ".m" || ext == ".csv") return MapFormat::matrix;
  if (ext == ".yaml" || ext == ".yml") return MapFormat::ros;
  if (ext == ".json") return MapFormat::scene;
  if (starts_with_word(head, "pathref-grid")) return MapFormat::pathref_grid;
  if (starts_with_word(head, "type")) return MapFormat::movingai;
  return MapFormat::matrix;
}

MapFile parse_map_text(std::string_view text_in, std::string_view filename, MapFormat format,
                       const MapReadOptions& options) {
  check_limits(options.limits);
  switch (format) {
    case MapFormat::movingai: return parse_movingai_map(text_in, filename, options.terrain, options.limits);
    case MapFormat::matrix: return parse_matrix(text_in, filename, options.limits);
    case MapFormat::pathref_grid: {
      MapFile m = parse_grid_text(text_in, filename);
      const std::int64_t w = m.grid.width();
      const std::int64_t h = m.grid.height();
      if (w > options.limits.max_side || h > options.limits.max_side || w > options.limits.max_cells / h) {
        const auto [line, column] = size_position(text_in);
        throw ParseError(std::string(filename), line, column,
                         w > options.limits.max_side || h > options.limits.max_side
                             ? fmt::format("a {}x{} grid exceeds the limit of {} cells per side", w, h,
                                           options.limits.max_side)
                             : fmt::format("a {}x{} grid exceeds the limit of {} cells", w, h,
                                           options.limits.max_cells));
      }
      return m;
    }
    case MapFormat::ros:
      throw UsageError(fmt::format("'{}': a ROS map is a YAML file and its image; read it with load_map_file "
                                   "(pathref plan --map FILE.yaml) or parse_ros_map", filename));
    case MapFormat::scene: {
      if (!options.scene_to_map)
        throw UsageError(fmt::format("'{0}' is a polygon scene (pathref-scene 1), which cannot be read as a grid "
                                     "map here: inflate it into one first (pathref inflate {0} -o MAP.grid) and "
                                     "give MAP.grid instead",
                                     printable(filename)));
      return options.scene_to_map(text_in, std::string(filename), options.limits);
    }
    case MapFormat::automatic: break;
  }
  throw DomainError("parse_map_text: the format must not be 'auto'");
}

std::string read_text_file(const std::string& path, std::string_view what) {
  return read_input_file(path, what, max_map_file_bytes);
}

LoadedMapFile load_map_file(const std::string& path, const MapReadOptions& options) {
  check_limits(options.limits);
  if (options.format == MapFormat::automatic && extension_of(path) == ".scen")
    throw UsageError(fmt::format("'{}' is a MovingAI scenario file, not a map: run it with pathref scen", path));
  if (options.format == MapFormat::automatic && (extension_of(path) == ".pgm" || extension_of(path) == ".pnm"))
    throw UsageError(fmt::format("'{}' is an image: a ROS map is read through its YAML file, which names the image "
                                 "and gives its resolution and thresholds (pass --map FILE.yaml)",
                                 path));
  if (options.format == MapFormat::ros ||
      (options.format == MapFormat::automatic && detect_map_format(path, "") == MapFormat::ros)) {
    RosMapOptions ros;
    ros.unknown = options.ros_unknown;
    RosMap r = load_ros_map(path, ros);
    const std::int64_t w = r.map.grid.width();
    const std::int64_t h = r.map.grid.height();
    if (w > options.limits.max_side || h > options.limits.max_side)
      throw ParseError(path, r.meta.image_line, r.meta.image_column,
                       fmt::format("the image is a {}x{} grid, which exceeds the limit of {} cells per side", w, h,
                                   options.limits.max_side));
    if (w > options.limits.max_cells / h)
      throw ParseError(path, r.meta.image_line, r.meta.image_column,
                       fmt::format("the image is a {}x{} grid, which exceeds the limit of {} cells", w, h,
                                   options.limits.max_cells));
    return LoadedMapFile{std::move(r.map), MapFormat::ros};
  }
  const std::string text_in = read_text_file(path, "map file");
  const MapFormat format =
      options.format == MapFormat::automatic ? detect_map_format(path, text_in) : options.format;
  return LoadedMapFile{parse_map_text(text_in, path, format, options), format};
}

OutputFormat parse_output_format(std::string_view name) {
  if (name == "pathref-grid") return OutputFormat::pathref_grid;
  if (name == "movingai") return OutputFormat::movingai;
  if (name == "matrix") return OutputFormat::matrix;
  if (name == "matlab") return OutputFormat::matlab;
  throw UsageError(fmt::format("unknown output format '{}' (known: pathref-grid, movingai, matrix, matlab)", name));
}

std::string write_map_text(const MapFile& map, OutputFormat format) {
  switch (format) {
    case OutputFormat::pathref_grid: return to_grid_text(map);
    case OutputFormat::movingai: return to_movingai_map(map.grid);
    case OutputFormat::matrix: return to_matrix_text(map.grid);
    case OutputFormat::matlab: return to_matlab_text(map.grid);
  }
  throw DomainError("write_map_text: unknown output format");
}

}  // namespace pathref::io
