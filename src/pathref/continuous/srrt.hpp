#pragma once
/// \file srrt.hpp
/// The continuous planners `rrt` and `s-rrt` of Cin et al. 2021 Sec. 4 (doi:10.1155/2021/8025730):
/// Algorithm 1, then (s-rrt) Algorithm 2 and the B-spline of Eq. 12-15, with the metrics of
/// Table 2. Parameters by name (the CLI's --set), defaults, and one run.
/// Spec: spec/cin2021-srrt.md (Planners), spec/cli.md#plan-continuous
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/continuous/rrt.hpp"
#include "pathref/equations/bspline.hpp"
#include "pathref/geometry/clearance.hpp"

namespace pathref::rng {
class Trace;  // rng/trace.hpp
}  // namespace pathref::rng

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

/// Parameters of S-RRT's curve (Eq. 12-15) and of its check and repair (spec
/// r[cin2021.srrt.curve]; `pathref plan --algo s-rrt --set name=value`).
struct CurveParams {
  int degree = 3;                                         ///< `degree`: requested degree k (1..20)
  bspline::KnotSpacing knots = bspline::KnotSpacing::uniform;  ///< `knots`: uniform | chord
  double spacing = 0.05;                                  ///< `spacing`: sample spacing (world units, > 0)
  bool repair = false;                                    ///< `repair`: re-insert and re-smooth (off: the paper)
};

/// The smoothed curve of S-RRT and what pathref checks of it.
struct CurveResult {
  int degree = 0;                        ///< degree used (degree_for: lowered for few points)
  bspline::Curve curve;                  ///< clamped B-spline over raw[kept]
  bspline::Samples samples;              ///< curves.sample at `spacing`
  std::vector<std::size_t> kept;         ///< control points: indices into the raw path (after repair)
  std::vector<std::size_t> inserted;     ///< raw indices re-inserted by the repair, in order
  geometry::Clearance clearance;         ///< curves.polygon-clearance of the samples, tau = chord / 2, r = inflation
  double length = 0.0;                   ///< polyline_length of the samples (<= the arc length)
  double max_curvature = 0.0;            ///< max |curves.curvature| over the sample parameters
  std::string repair = "off";            ///< off | clear (the final curve is clear) | stuck (no node left to re-insert)
};

/// Parses the curve parameters `degree`, `knots`, `spacing`, `repair` of a merged parameter
/// object (UsageError for a bad name or type, DomainError for a value out of range).
[[nodiscard]] CurveParams curve_params(const Json& merged);

/// The clamped B-spline (Eq. 12-15) over raw[kept] and its check (spec r[cin2021.srrt.curve]):
/// degree = degree_for(|kept|, params.degree, clamped); knots by params.knots; samples at
/// params.spacing; clearance against `map` with inflation map.inflation(), tolerance chord / 2,
/// border off (the curve lies in the convex hull of its control points, inside the world
/// rectangle); max |curvature| at the sample parameters. With params.repair, while the verdict
/// is not `clear`: u = the parameter of the first sample of the segment attaining the distance,
/// k = span_index(u); among the raw indices i with kept[k - degree] < i < kept[k] that are not
/// kept, re-insert the one whose point is nearest to that sample (squared distance, the smallest
/// index on ties) and rebuild; none left: repair = stuck. Source: Cin et al. 2021 Eq. 12-15
/// (curve); pathref (check, repair). Spec: cin2021.srrt.curve.
/// Pre: raw has >= 2 points; kept strictly increasing, kept.front() = 0, kept.back() = |raw| - 1
/// (DomainError). Golden: golden/cin2021-srrt/cin2021.srrt.curve.json
[[nodiscard]] CurveResult smooth_path(const CollisionChecker& map, const std::vector<Vec2>& raw,
                                      const std::vector<std::size_t>& kept, const CurveParams& params);

/// One run of `rrt` or `s-rrt`.
struct ContinuousRun {
  RrtResult tree;
  std::vector<Vec2> raw;                 ///< the denoised branch (empty if not found)
  std::vector<std::size_t> kept;         ///< s-rrt: indices into raw kept by Algorithm 2
  std::vector<Vec2> shortcut_path;       ///< s-rrt: raw[kept]
  PathMetrics raw_metrics;
  PathMetrics shortcut_metrics;          ///< s-rrt only
  std::optional<CurveResult> curve;      ///< s-rrt with smooth=true and a path: Eq. 12-15
  double time_ms = 0.0;                  ///< wall clock of Algorithms 1 and 2 (not reproducible)
  double curve_ms = 0.0;                 ///< wall clock of the curve, its check and repair
  Json params_used = Json::object();
};

/// Runs `algo` ("rrt" | "s-rrt") with parameters `merged` (continuous_defaults overlaid with the
/// user's) from `start` to `goal`, seed `seed`; `trace` (optional, not owned) records every draw
/// (spec/rng.md#draw-traces). Spec: cin2021.alg1, cin2021.alg2.
/// Pre: as rrt(); is_continuous_planner(algo) (UsageError).
[[nodiscard]] ContinuousRun run_continuous(std::string_view algo, const CollisionChecker& map, Vec2 start,
                                           Vec2 goal, const Json& merged, std::uint32_t seed,
                                           rng::Trace* trace = nullptr);

}  // namespace pathref::continuous
