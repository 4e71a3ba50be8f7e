#include "pathref/grid/json_codec.hpp"

#include <cstdint>
#include <string>

#include "pathref/core/error.hpp"

namespace pathref::grid {

Grid grid_from_json(const nlohmann::json& rows) {
  if (!rows.is_array()) throw UsageError("a grid must be an array of row strings (top row first)");
  std::vector<std::string> text;
  text.reserve(rows.size());
  for (const auto& r : rows) {
    if (!r.is_string()) throw UsageError("a grid row must be a string of '.' and '#'");
    text.push_back(r.get<std::string>());
  }
  return Grid::from_rows_top_first(text);
}

nlohmann::json grid_to_json(const Grid& g) { return nlohmann::json(g.to_rows_top_first()); }

Cell cell_from_json(const nlohmann::json& v) {
  if (!v.is_array() || v.size() != 2 || !v[0].is_number_integer() || !v[1].is_number_integer())
    throw UsageError("a cell must be [x, y] with two integers, got " + v.dump());
  for (const auto& e : v) {
    if (e.is_number_unsigned() && e.get<std::uint64_t>() > static_cast<std::uint64_t>(INT64_MAX))
      throw UsageError("cell coordinate does not fit in a signed 64-bit integer: " + v.dump());
  }
  return Cell{v[0].get<std::int64_t>(), v[1].get<std::int64_t>()};
}

nlohmann::json cell_to_json(Cell c) { return nlohmann::json::array({c.x, c.y}); }

std::vector<Cell> path_from_json(const nlohmann::json& v) {
  if (!v.is_array()) throw UsageError("a path must be an array of [x, y] cells");
  std::vector<Cell> out;
  out.reserve(v.size());
  for (const auto& c : v) out.push_back(cell_from_json(c));
  return out;
}

nlohmann::json path_to_json(std::span<const Cell> path) {
  nlohmann::json out = nlohmann::json::array();
  for (const Cell& c : path) out.push_back(cell_to_json(c));
  return out;
}

CornerPolicy policy_from_json(const nlohmann::json& v) {
  if (!v.is_string()) throw UsageError("a corner policy must be a string");
  return parse_corner_policy(v.get<std::string>());
}

}  // namespace pathref::grid
