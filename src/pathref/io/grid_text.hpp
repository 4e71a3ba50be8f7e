#pragma once
/// \file grid_text.hpp
/// pathref's own grid text format, version 1 ("pathref-grid 1"): a versioned header, `#` comment
/// lines, `size W H`, optional `name`, `start X Y`, `goal X Y`, then the line `map` and H rows of
/// '.' (free) and '#' (blocked), the first row being the top row (y = H-1).
/// Spec: spec/formats.md#pathref-grid-1 (grammar, every error message, limits, line endings).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "pathref/grid/grid.hpp"

namespace pathref::io {

/// A map as read from a file: the grid plus what the file says about it.
struct MapFile {
  grid::Grid grid;
  std::optional<grid::Cell> start;  ///< from `start X Y`, if given
  std::optional<grid::Cell> goal;   ///< from `goal X Y`, if given
  std::string name;                 ///< from `name ...`, empty if not given

  /// Same grid, start, goal and name.
  friend bool operator==(const MapFile&, const MapFile&) = default;
};

/// Largest map file the CLI reads (bytes): a max_cells map with its newlines fits comfortably.
inline constexpr std::uintmax_t max_map_file_bytes = std::uintmax_t{1} << 30;

/// Parses pathref-grid version 1 text. `filename` is used only in error messages.
/// Throws ParseError(filename, line, column, what was expected) for any deviation from the
/// grammar of spec/formats.md. Width and height must each be in [1, Grid::max_cells] and
/// W * H <= Grid::max_cells; the grid is allocated only after all H rows have been checked, so
/// the memory used is bounded by the size of `text`.
[[nodiscard]] MapFile parse_grid_text(std::string_view text, std::string_view filename);

/// Writes `map` as pathref-grid 1 text (LF line endings, final newline, no comments) such that
/// parse_grid_text(to_grid_text(m), f) == m. Pre (DomainError): start/goal, when given, are
/// free cells of the grid; the name has no control characters (bytes < 0x20 or 0x7f) and no
/// leading or trailing space or tab.
[[nodiscard]] std::string to_grid_text(const MapFile& map);

/// Reads a whole file and parses it with parse_grid_text. UsageError when the file cannot be
/// opened, is not a regular file, or is larger than max_map_file_bytes (checked before reading).
[[nodiscard]] MapFile read_grid_file(const std::string& path);

}  // namespace pathref::io
