#include "pathref/io/plan_json.hpp"

#include "pathref/core/version.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "pathref/core/error.hpp"
#include "pathref/equations/metrics.hpp"

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

const Json& field(const Json& obj, const char* key, std::string_view source) {
  if (!obj.is_object() || !obj.contains(key))
    throw UsageError(std::string(source) + ": plan JSON has no field '" + key + "'");
  return obj.at(key);
}

grid::Cell cell_from(const Json& j, const std::string& what, std::string_view source) {
  if (!j.is_array() || j.size() != 2 || !j[0].is_number_integer() || !j[1].is_number_integer())
    throw UsageError(std::string(source) + ": plan JSON field '" + what + "' must be [x, y] integers");
  return grid::Cell{j[0].get<std::int64_t>(), j[1].get<std::int64_t>()};
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

PlanJsonView plan_from_json(const Json& doc, std::string_view source) {
  if (field(doc, "format", source) != "pathref-plan" || field(doc, "format_version", source) != 1)
    throw UsageError(std::string(source) + ": not a pathref-plan version 1 object");
  const Json& map = field(doc, "map", source);
  const Json& rows = field(map, "rows", source);
  if (!rows.is_array() || rows.empty())
    throw UsageError(std::string(source) + ": plan JSON field 'map.rows' must be a non-empty array");
  std::vector<std::string> lines;
  for (const Json& row : rows) {
    if (!row.is_string()) throw UsageError(std::string(source) + ": 'map.rows' must hold strings");
    lines.push_back(row.get<std::string>());
  }
  const Json& algo = field(doc, "algo", source);
  const Json& policy = field(doc, "policy", source);
  const Json& found = field(doc, "found", source);
  if (!algo.is_string() || !policy.is_string() || !found.is_boolean())
    throw UsageError(std::string(source) + ": 'algo' and 'policy' must be strings, 'found' a boolean");
  PlanJsonView v{algo.get<std::string>(),
                 grid::parse_corner_policy(policy.get<std::string>()),
                 grid::Grid::from_rows_top_first(lines),
                 cell_from(field(doc, "start", source), "start", source),
                 cell_from(field(doc, "goal", source), "goal", source),
                 found.get<bool>(),
                 {}};
  const Json& path = field(doc, "path", source);
  if (!path.is_array()) throw UsageError(std::string(source) + ": 'path' must be an array");
  for (std::size_t i = 0; i < path.size(); ++i)
    v.path.push_back(cell_from(path[i], "path[" + std::to_string(i) + "]", source));
  return v;
}

}  // namespace pathref::io
