#pragma once
/// \file srrt.hpp
/// The continuous planners `rrt` and `s-rrt` of Cin et al. 2021 Sec. 4 (doi:10.1155/2021/8025730):
/// Algorithm 1, then (s-rrt) Algorithm 2 and the B-spline of Eq. 12-15, with the metrics of
/// Table 2. Parameters by name (the CLI's --set), defaults, and one run.
/// Spec: spec/cin2021-srrt.md (Planners), spec/cli.md#plan-continuous
#include <cstdint>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/continuous/rrt.hpp"

namespace pathref::continuous {

using Json = nlohmann::json;

/// The continuous planners' names: "rrt", "s-rrt".
[[nodiscard]] const std::vector<std::string_view>& continuous_planner_names();
/// True iff `algo` is one of them.
[[nodiscard]] bool is_continuous_planner(std::string_view algo);
/// Every parameter of `algo` with its default (spec/cin2021-srrt.md). Pre: is_continuous_planner.
[[nodiscard]] Json continuous_defaults(std::string_view algo);
/// Algorithm 1's parameters from a merged parameter object (defaults overlaid with --set);
/// UsageError for a bad option name, DomainError for a value outside its range.
[[nodiscard]] RrtParams rrt_params(const Json& merged);

/// Path metrics of Table 2 plus clearance. Spec: cin2021.srrt.metrics.
struct PathMetrics {
  double length = 0.0;        ///< polyline_length
  std::int64_t nodes = 0;     ///< number of points
  double clearance = 0.0;     ///< min over segments of segment_clearance (+inf without obstacles)
  double turning = 0.0;       ///< total_turning: sum of heading changes (radians), a smoothness measure
};

/// Sum over interior vertices of the absolute heading change atan2(|cross|, dot) of the two
/// segments at the vertex (cross = u.x v.y - u.y v.x, dot = u.x v.x + u.y v.y, u, v the
/// segment vectors), summed left to right; zero-length segments contribute 0. 0 for < 3 points.
/// Spec: cin2021.srrt.metrics.
[[nodiscard]] double total_turning(const std::vector<Vec2>& points);
/// Metrics of a polyline (>= 1 point). Spec: cin2021.srrt.metrics.
[[nodiscard]] PathMetrics path_metrics(const CollisionChecker& map, const std::vector<Vec2>& points);

/// One run of `rrt` or `s-rrt`.
struct ContinuousRun {
  RrtResult tree;
  std::vector<Vec2> raw;                 ///< the denoised branch (empty if not found)
  std::vector<std::size_t> kept;         ///< s-rrt: indices into raw kept by Algorithm 2
  std::vector<Vec2> shortcut_path;       ///< s-rrt: raw[kept]
  PathMetrics raw_metrics;
  PathMetrics shortcut_metrics;          ///< s-rrt only
  double time_ms = 0.0;                  ///< wall clock of the whole run (not reproducible)
  Json params_used = Json::object();
};

/// Runs `algo` ("rrt" | "s-rrt") with parameters `merged` (continuous_defaults overlaid with the
/// user's) from `start` to `goal`, seed `seed`. Spec: cin2021.alg1, cin2021.alg2.
/// Pre: as rrt(); is_continuous_planner(algo) (UsageError).
[[nodiscard]] ContinuousRun run_continuous(std::string_view algo, const CollisionChecker& map, Vec2 start,
                                           Vec2 goal, const Json& merged, std::uint32_t seed);

}  // namespace pathref::continuous
