#pragma once
/// \file path_file.hpp
/// Paths written by other programs, as `pathref check` reads them (spec/check.md#path-files):
/// pathref-plan JSON, a JSON list of [x, y], x y lines, MATLAB 1-based node numbers (row-major,
/// first matrix row on top, as the classic scripts number cells) and MATLAB [row, col] pairs,
/// with the index base and the row origin spelled out. Reading (parse_path_text) and the
/// conversion to cells (path_cells) are separate, because node numbers and rows need the map.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/grid/grid.hpp"

namespace pathref::io {

/// How the numbers of a path file name cells (spec/check.md#path-formats).
enum class PathFormat {
  automatic,  ///< decide from the text (spec/check.md#path-detection)
  plan,       ///< a pathref-plan JSON object (its `path`, map, start, goal, policy)
  xy,         ///< (x, y) pairs: column, row
  node,       ///< node numbers, row-major
  rowcol,     ///< (row, col) pairs, MATLAB's G(row, col)
};
/// "auto" | "plan" | "xy" | "node" | "rowcol" -> PathFormat; UsageError otherwise.
[[nodiscard]] PathFormat parse_path_format(std::string_view name);
[[nodiscard]] std::string_view to_string(PathFormat format) noexcept;

/// Where row 0 (or y = 0) of a path file is: the bottom row (pathref, spec/grid.md) or the top
/// row (a matrix's first row, images).
enum class RowOrigin { lower, upper };
/// "lower" | "upper" -> RowOrigin; UsageError otherwise.
[[nodiscard]] RowOrigin parse_row_origin(std::string_view name);
[[nodiscard]] std::string_view to_string(RowOrigin origin) noexcept;

/// Largest number of nodes of one path and largest |number| in a path file (checked while
/// reading, before storing).
inline constexpr std::size_t max_path_nodes = std::size_t{1} << 24;
inline constexpr std::int64_t max_path_number = std::int64_t{1} << 31;

/// One path as read, before conversion to cells.
struct PathRecord {
  std::string name;    ///< the file, or FILE:LINE for a line of a JSON-lines file
  PathFormat format;   ///< never automatic
  /// xy and rowcol: the pairs, flattened (a0, b0, a1, b1, ...); node: one number per node;
  /// plan: the path's x, y pairs.
  std::vector<std::int64_t> numbers;
  nlohmann::json plan;  ///< plan: the whole object; null otherwise
};

/// Reads the path(s) of `text` (spec/check.md#path-files). `json_lines`: every non-blank line is
/// one path (a JSON array or a pathref-plan object). ParseError `FILE:LINE:COLUMN: ...` for
/// malformed text (a number that is not an integer or exceeds max_path_number, a line with the
/// wrong count of numbers, more than max_path_nodes nodes, no node at all, invalid JSON).
[[nodiscard]] std::vector<PathRecord> parse_path_text(std::string_view text, std::string_view file,
                                                      PathFormat format, bool json_lines);

/// The cells of a record on a width x height map (spec/check.md#path-cells), with b = `base`:
/// xy (a, c): (a - b, c - b) for origin lower, (a - b, H - 1 - (c - b)) for upper;
/// rowcol (r, c): (c - b, r - b) for lower, (c - b, H - 1 - (r - b)) for upper;
/// node n: k = n - b, row = floor(k / W), (k - row W, row) for lower, (k - row W, H - 1 - row)
/// for upper; plan: (x, y) as written. Cells outside the map are kept (the validator reports
/// them). Pre: width, height >= 1 (DomainError).
[[nodiscard]] std::vector<grid::Cell> path_cells(const PathRecord& record, std::int64_t width,
                                                 std::int64_t height, std::int64_t base, RowOrigin origin);

}  // namespace pathref::io
