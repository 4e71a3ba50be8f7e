// JSON adapters for the grid.* rules (spec/grid.md). Encoding of grids, cells and policies:
// spec/grid.md "JSON encoding" (src/pathref/grid/json_codec.hpp).
#include "pathref/core/error.hpp"
#include "pathref/grid/coords.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/grid/json_codec.hpp"
#include "pathref/rules/modules.hpp"

namespace pathref::rules {

namespace {
grid::CornerPolicy policy_arg(const Json& in) {
  return grid::parse_corner_policy(opt_string(in, "policy", "strict"));
}
}  // namespace

void register_grid_rules(Registry& r) {
  r.add(Rule{
      "grid.encoding",
      "Grid from rows of '.'/'#', first row = top row (y = H-1)",
      "pathref::grid::Grid::from_rows_top_first",
      {{"grid", "grid", "rows top first, '.' free, '#' blocked"}},
      {{"width", "integer", "W"},
       {"height", "integer", "H"},
       {"blocked", "integer[]", "indices i = y*W + x of the blocked cells, increasing"}},
      [](const Json& in) {
        const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
        Json blocked = Json::array();
        for (std::int64_t i = 0; i < g.cell_count(); ++i)
          if (g.blocked(g.cell(i))) blocked.push_back(i);
        return Json{{"width", g.width()}, {"height", g.height()}, {"blocked", blocked}};
      }});
  r.add(Rule{
      "grid.index",
      "Cell index i = y*W + x and its inverse (x, y) = (i mod W, floor(i/W))",
      "pathref::grid::cell_index",
      {{"width", "integer", "W >= 1"},
       {"height", "integer", "H >= 1"},
       {"cell", "cell", "[x, y] (give this or index)"},
       {"index", "integer", "i (give this or cell)"}},
      {{"index", "integer", "i, when cell was given"}, {"cell", "cell", "[x, y], when index was given"}},
      [](const Json& in) {
        const std::int64_t w = arg_integer(in, "width");
        const std::int64_t h = arg_integer(in, "height");
        const bool has_cell = in.contains("cell");
        if (has_cell == in.contains("index"))
          throw UsageError("grid.index needs exactly one of 'cell' and 'index'");
        if (has_cell) return Json{{"index", grid::cell_index(grid::cell_from_json(in.at("cell")), w, h)}};
        return Json{{"cell", grid::cell_to_json(grid::index_cell(arg_integer(in, "index"), w, h))}};
      }});
  r.add(Rule{
      "grid.coord",
      "Cell centre from the 0-based index: Shi Eq. 1 corrected (printed forms selectable)",
      "pathref::grid::cell_centre",
      {{"width", "integer", "W >= 1"},
       {"height", "integer", "H >= 1"},
       {"index", "integer", "0-based i in [0, W*H)"},
       {"form", "string", "corrected (default) | printed0 | printed1"}},
      {{"centre", "number[2]", "[x, y] in cell units"}},
      [](const Json& in) {
        const auto p = grid::cell_centre(arg_integer(in, "index"), arg_integer(in, "width"),
                                         arg_integer(in, "height"),
                                         grid::parse_eq1_form(opt_string(in, "form", "corrected")));
        return Json{{"centre", Json::array({number(p.x), number(p.y)})}};
      }});
  r.add(Rule{
      "grid.moves",
      "Step cost between distinct 8-neighbours: distance between centres, 1 or sqrt(2)",
      "pathref::grid::step_cost",
      {{"from", "cell", "[x, y]"}, {"to", "cell", "[x, y], an 8-neighbour of from"}},
      {{"cost", "number", "1 or sqrt(2)"}},
      [](const Json& in) {
        return Json{{"cost", number(grid::step_cost(grid::cell_from_json(arg(in, "from")),
                                                    grid::cell_from_json(arg(in, "to"))))}};
      }});
  r.add(Rule{
      "grid.corner-policy",
      "Whether the step from -> to is allowed on the grid under a corner-cutting policy",
      "pathref::grid::step_allowed",
      {{"grid", "grid", "rows top first"},
       {"from", "cell", "[x, y]"},
       {"to", "cell", "[x, y]"},
       {"policy", "string", "strict (default) | never | one | always"}},
      {{"allowed", "bool", "the step is allowed"}},
      [](const Json& in) {
        const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
        return Json{{"allowed", grid::step_allowed(g, grid::cell_from_json(arg(in, "from")),
                                                   grid::cell_from_json(arg(in, "to")),
                                                   policy_arg(in))}};
      }});
  r.add(Rule{
      "grid.neighbour-order",
      "Allowed moves out of a free cell, in increasing cell index, with their costs",
      "pathref::grid::neighbours",
      {{"grid", "grid", "rows top first"},
       {"cell", "cell", "[x, y], in bounds and free"},
       {"policy", "string", "strict (default) | never | one | always"}},
      {{"neighbours", "cell[]", "targets in canonical order"},
       {"costs", "number[]", "step costs, same order"}},
      [](const Json& in) {
        const grid::Grid g = grid::grid_from_json(arg(in, "grid"));
        const auto moves = grid::neighbours(g, grid::cell_from_json(arg(in, "cell")), policy_arg(in));
        Json cells = Json::array();
        Json costs = Json::array();
        for (const auto& m : moves) {
          cells.push_back(grid::cell_to_json(m.to));
          costs.push_back(number(m.cost));
        }
        return Json{{"neighbours", cells}, {"costs", costs}};
      }});
}

}  // namespace pathref::rules
