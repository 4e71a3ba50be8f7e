#pragma once
/// \file path_check.hpp
/// The checker of `pathref check` and `pathref.check` (Python): the verdict on one path produced
/// elsewhere — valid, or the first invalid step and why in words — and its metrics: length,
/// turns, the optimum (Dijkstra under the same corner policy), the ratio and the clearance.
/// Spec: spec/check.md#verdict, #metrics (metrics.valid-path, metrics.length, metrics.turns,
/// search.dijkstra, geometry clearance).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/equations/metrics.hpp"
#include "pathref/grid/grid.hpp"

namespace pathref::io {

/// What check reports for one path.
struct PathReport {
  metrics::PathCheck check;         ///< metrics.valid-path: valid, reason, index of the first failure
  std::string message;              ///< "ok", or the failure in words (spec/check.md#verdict)
  std::optional<double> length;     ///< metrics.length (null outside its path domain)
  std::optional<std::int64_t> turns;  ///< metrics.turns
  std::optional<double> optimum;    ///< Dijkstra's length start -> goal, same policy (null: unreachable)
  std::optional<double> ratio;      ///< length / optimum for a valid path with optimum > 0
  std::optional<double> clearance;  ///< cell units, valid paths only
};

/// The shortest length from start to goal under `policy` (search.dijkstra), nullopt when the goal
/// is unreachable or an endpoint is outside the map or blocked.
[[nodiscard]] std::optional<double> optimum_length(const grid::Grid& g, grid::Cell start, grid::Cell goal,
                                                   grid::CornerPolicy policy);

/// Checks `path` on `g` from `start` to `goal` under `policy`. `optimum` is optimum_length(g,
/// start, goal, policy), passed in so that a caller checking many paths computes it once.
/// Never throws for any path (a bad path is a verdict, not an error).
[[nodiscard]] PathReport check_path(const grid::Grid& g, const std::vector<grid::Cell>& path, grid::Cell start,
                                    grid::Cell goal, grid::CornerPolicy policy, std::optional<double> optimum);

/// The verdict and metric members of spec/check.md#check-json: valid, reason, index, step (the
/// failing step {from, to} or null), message, length, turns, optimum, ratio, clearance.
[[nodiscard]] nlohmann::json path_report_json(const PathReport& r, const std::vector<grid::Cell>& path);

}  // namespace pathref::io
