#pragma once
/// \file json_codec.hpp
/// The JSON encoding of grids, cells, paths and corner policies shared by every module's rule
/// adapters and golden vectors (spec/grid.md, "JSON encoding"):
///   grid   = array of strings, FIRST = TOP row, '.' free, '#' blocked
///   cell   = [x, y] (JSON integers)
///   path   = array of cells
///   policy = "never" | "strict" | "one" | "always"
/// A value of the wrong JSON shape is a UsageError (a malformed request); a well-formed value
/// outside the domain (ragged rows, other characters) is a DomainError from Grid.
/// Spec: grid.encoding
#include <span>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/grid/grid.hpp"

namespace pathref::grid {

/// Rows top first -> Grid (Grid::from_rows_top_first). UsageError unless an array of strings.
/// Spec: grid.encoding.
[[nodiscard]] Grid grid_from_json(const nlohmann::json& rows);
/// Grid -> rows top first (Grid::to_rows_top_first).
[[nodiscard]] nlohmann::json grid_to_json(const Grid& g);

/// [x, y] -> Cell. UsageError unless an array of exactly two JSON integers.
[[nodiscard]] Cell cell_from_json(const nlohmann::json& v);
[[nodiscard]] nlohmann::json cell_to_json(Cell c);

/// [[x, y], ...] -> cells. UsageError unless an array of cells (may be empty).
[[nodiscard]] std::vector<Cell> path_from_json(const nlohmann::json& v);
[[nodiscard]] nlohmann::json path_to_json(std::span<const Cell> path);

/// Policy name -> CornerPolicy (parse_corner_policy). UsageError unless a known name string.
[[nodiscard]] CornerPolicy policy_from_json(const nlohmann::json& v);

}  // namespace pathref::grid
