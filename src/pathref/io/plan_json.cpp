#include "pathref/io/plan_json.hpp"

#include "pathref/core/version.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "pathref/core/error.hpp"
#include "pathref/equations/metrics.hpp"
#include "pathref/io/json_text.hpp"

namespace pathref::io {

namespace {

/// [x, y]
Json cell_json(grid::Cell c) { return Json::array({c.x, c.y}); }

/// A double, or null when it is not finite (JSON has no infinity or NaN).
Json number_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

Json numbers_or_null(const std::vector<double>& values) {
  Json out = Json::array();
  for (const double v : values) out.push_back(number_or_null(v));
  return out;
}

/// iterations_to_converge when the curve has a finite value and no NaN / -inf, else null.
Json converged_at(const std::vector<double>& best) {
  const bool any_finite = std::any_of(best.begin(), best.end(), [](double v) { return std::isfinite(v); });
  const bool all_ok = std::all_of(best.begin(), best.end(),
                                  [](double v) { return !std::isnan(v) && !(std::isinf(v) && v < 0.0); });
  if (best.empty() || !any_finite || !all_ok) return nullptr;
  return metrics::iterations_to_converge(std::span<const double>(best));
}

// ---- reading back ----------------------------------------------------------------------------

/// Located refusals of a plan record (json_error_at: FILE:LINE:COLUMN: /pointer: what, or
/// SOURCE: /pointer: what without text).
class PlanReader {
 public:
  PlanReader(std::string_view source, std::string_view text, std::size_t first_line)
      : source_(source), text_(text), first_line_(first_line) {}

  [[noreturn]] void fail(const std::string& ptr, const std::string& what) const {
    throw json_error_at(text_, source_, ptr, what, first_line_);
  }

  /// The member `key` of the object at `ptr`.
  const Json& field(const Json& obj, const std::string& ptr, const char* key, std::string_view expected) const {
    if (!obj.is_object()) fail(ptr, "expected an object, got " + json_kind(obj));
    const auto it = obj.find(key);
    if (it == obj.end()) fail(ptr, std::string("missing key \"") + key + "\" (expected " + std::string(expected) + ")");
    return *it;
  }

  grid::Cell cell(const Json& j, const std::string& ptr) const {
    if (!j.is_array() || j.size() != 2 || !j[0].is_number_integer() || !j[1].is_number_integer())
      fail(ptr, "expected [x, y] (two integers), got " + json_kind(j));
    return grid::Cell{j[0].get<std::int64_t>(), j[1].get<std::int64_t>()};
  }

  /// An integer >= 0 that must equal `want` (a count the record states twice).
  void agrees(const Json& j, const std::string& ptr, std::int64_t want, const std::string& why) const {
    if (!j.is_number_integer() || j.get<std::int64_t>() != want)
      fail(ptr, "expected " + std::to_string(want) + " (" + why + "), got " +
                    (j.is_number_integer() ? std::to_string(j.get<std::int64_t>()) : json_kind(j)));
  }

 private:
  std::string source_;
  std::string_view text_;
  std::size_t first_line_;
};

/// The map of a plan record: `rows` (H strings of W '.'/'#', top row first), with `width` and
/// `height` equal to W and H, and `blocked`, when present, the number of '#'.
grid::Grid plan_map(const PlanReader& rd, const Json& map) {
  const Json& rows = rd.field(map, "/map", "rows", "the grid, H strings top row first");
  if (!rows.is_array() || rows.empty()) rd.fail("/map/rows", "expected a non-empty array of strings, got " + json_kind(rows));
  const Json& width = rd.field(map, "/map", "width", "the number of characters of each row");
  const Json& height = rd.field(map, "/map", "height", "the number of rows");
  std::vector<std::string> lines;
  std::int64_t blocked = 0;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const std::string ptr = "/map/rows/" + std::to_string(r);
    if (!rows[r].is_string()) rd.fail(ptr, "expected a string of '.' and '#', got " + json_kind(rows[r]));
    const std::string& row = rows[r].get_ref<const std::string&>();
    if (row.empty() || (r > 0 && row.size() != lines[0].size()))
      rd.fail(ptr, "expected " + (r == 0 ? std::string("at least one character") : std::to_string(lines[0].size()) + " characters like row 0") +
                       ", got " + std::to_string(row.size()));
    const auto bad = row.find_first_not_of(".#");
    if (bad != std::string::npos)
      rd.fail(ptr, "expected only '.' (free) and '#' (blocked), got '" + printable(row.substr(bad, 1)) + "' at character " +
                       std::to_string(bad + 1));
    blocked += static_cast<std::int64_t>(std::count(row.begin(), row.end(), '#'));
    lines.push_back(row);
  }
  const auto w = static_cast<std::int64_t>(lines[0].size());
  const auto h = static_cast<std::int64_t>(lines.size());
  rd.agrees(width, "/map/width", w, "the length of each of /map/rows");
  rd.agrees(height, "/map/height", h, "the number of /map/rows");
  if (w > grid::Grid::max_cells / h)
    rd.fail("/map/rows", "a " + std::to_string(w) + "x" + std::to_string(h) + " grid exceeds the limit of " +
                             std::to_string(grid::Grid::max_cells) + " cells");
  if (const auto it = map.find("blocked"); it != map.end())
    rd.agrees(*it, "/map/blocked", blocked, "the number of '#' in /map/rows");
  return grid::Grid::from_rows_top_first(lines);
}

}  // namespace

Json plan_to_json(const PlanRecord& run, const grid::Grid& g) {
  const planners::Result& r = run.result;
  Json path = Json::array();
  for (const auto& c : r.path) path.push_back(cell_json(c));
  const std::span<const grid::Cell> cells(r.path);
  Json turns = nullptr;
  Json length = nullptr;
  if (r.found && !r.path.empty()) {
    turns = metrics::turn_count(cells);
    length = number_or_null(r.length);
  }
  const metrics::PathCheck check = metrics::validate_path(g, cells, run.start, run.goal, run.policy);

  Json map = {{"source", run.map.kind},
              {"name", run.map.name},
              {"file", run.map.file ? Json(*run.map.file) : Json(nullptr)},
              {"width", g.width()},
              {"height", g.height()},
              {"blocked", g.blocked_count()},
              {"rows", g.to_rows_top_first()}};
  return Json{{"format", "pathref-plan"},
              {"format_version", 1},
              {"pathref_version", std::string(pathref::version())},
              {"golden_set_version", std::string(pathref::golden_set_version())},
              {"algo", run.algo},
              {"seed", run.seed},
              {"policy", std::string(grid::to_string(run.policy))},
              {"params", run.params},
              {"map", std::move(map)},
              {"start", cell_json(run.start)},
              {"goal", cell_json(run.goal)},
              {"found", r.found},
              {"path", std::move(path)},
              {"length", std::move(length)},
              {"turns", std::move(turns)},
              {"valid", r.found && check.valid},
              {"validation", r.found ? check.reason : std::string("not_found")},
              {"expansions", r.expansions},
              {"iterations", r.iterations},
              {"best_per_iteration", numbers_or_null(r.best_per_iteration)},
              {"mean_per_iteration", numbers_or_null(r.mean_per_iteration)},
              {"converged_at", converged_at(r.best_per_iteration)},
              {"extra", r.extra}};
}

PlanJsonView plan_from_json(const Json& doc, std::string_view source, std::string_view text, std::size_t first_line) {
  const PlanReader rd(source, text, first_line);
  const Json& format = rd.field(doc, "", "format", "\"pathref-plan\"");
  if (format != "pathref-plan") rd.fail("/format", "expected \"pathref-plan\"");
  const Json& version = rd.field(doc, "", "format_version", "1");
  if (version != 1) rd.fail("/format_version", "expected 1 (a grid plan record; version 2 records are continuous plans)");
  const Json& algo = rd.field(doc, "", "algo", "a string");
  if (!algo.is_string()) rd.fail("/algo", "expected a string, got " + json_kind(algo));
  const Json& policy = rd.field(doc, "", "policy", "never, strict, one or always");
  grid::CornerPolicy corner = grid::CornerPolicy::strict;
  try {
    if (!policy.is_string()) throw UsageError("");
    corner = grid::parse_corner_policy(policy.get<std::string>());
  } catch (const UsageError&) {
    rd.fail("/policy", "expected never, strict, one or always");
  }
  const Json& found = rd.field(doc, "", "found", "true or false");
  if (!found.is_boolean()) rd.fail("/found", "expected true or false, got " + json_kind(found));
  PlanJsonView v{algo.get<std::string>(),
                 corner,
                 plan_map(rd, rd.field(doc, "", "map", "the map object")),
                 rd.cell(rd.field(doc, "", "start", "[x, y]"), "/start"),
                 rd.cell(rd.field(doc, "", "goal", "[x, y]"), "/goal"),
                 found.get<bool>(),
                 {}};
  const Json& path = rd.field(doc, "", "path", "an array of [x, y]");
  if (!path.is_array()) rd.fail("/path", "expected an array of [x, y], got " + json_kind(path));
  for (std::size_t i = 0; i < path.size(); ++i) v.path.push_back(rd.cell(path[i], "/path/" + std::to_string(i)));
  return v;
}

}  // namespace pathref::io
