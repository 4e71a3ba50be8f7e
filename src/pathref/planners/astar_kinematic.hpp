#pragma once
/// \file astar_kinematic.hpp
/// The kinematic-constraint A* of Sensors 2023 (§2, Fig. 5's global part), planner
/// `astar-kinematic`: the one best-first core of search.hpp with the five-direction expansion
/// rule (Eq. 1, Table 1) and the weighted evaluation function (Eq. 2–4); then the ordinary and
/// the secondary redundancy removal (Eq. 5); then the cubic B-spline of the kept key nodes
/// (Eq. 6–8, bspline.hpp), sampled at a selectable spacing and checked against the map with the
/// shared clearance function (geometry/clearance.hpp).
///
/// API for the DWA and the reproduction (s23-dwa): call
///   sensors2023::plan_kinematic(grid, start, goal, policy, sensors2023::KinematicOptions{})
/// and use `key_nodes` (cells; their centres are (x + 0.5, y + 0.5)) as the DWA's following
/// targets and `curve.points` as the smoothed global path.
///
/// Source: Sensors 2023, 23(8), 4102, doi:10.3390/s23084102, §2.1–2.4.
/// Spec: spec/sensors2023.md r[sensors2023.plan.astar-kinematic]
#include <cstdint>
#include <string_view>
#include <vector>

#include "pathref/equations/bspline.hpp"
#include "pathref/equations/sensors2023.hpp"
#include "pathref/geometry/clearance.hpp"
#include "pathref/grid/grid.hpp"
#include "pathref/planners/planner.hpp"
#include "pathref/planners/search.hpp"

namespace pathref::sensors2023 {

/// Which redundancy removal produces the key nodes.
enum class Redundancy {
  secondary,  ///< the greedy removal with collision test AND the Eq. 5 safety test (default)
  ordinary,   ///< the greedy removal with the collision test only (the "usual first pass")
  none,       ///< every node of the A* path is a key node
};
[[nodiscard]] Redundancy parse_redundancy(std::string_view name);
[[nodiscard]] std::string_view to_string(Redundancy r) noexcept;

/// Every parameter of the planner, with the defaults of spec/sensors2023.md (plan name = value).
struct KinematicOptions {
  int directions = 5;                    ///< 5 (Table 1) or 8 (plain 8-direction search)
  int radius = 1;                        ///< obstacle-free neighbourhood radius (1 = 8-neighbourhood)
  bool fallback = true;                  ///< rerun with 8 directions when the 5-direction search fails
  WeightForm weight = WeightForm::linear;  ///< Eq. 4 weight: linear 1 + r/R, exp, none (Eq. 3)
  Redundancy redundancy = Redundancy::secondary;
  bool secondary_on_raw = true;          ///< the secondary pass reads the A* path (else the first pass's)
  int k = 4;                             ///< Eq. 5 divisions per unit length
  double ds = 1.0;                       ///< Eq. 5 safety distance (one grid edge)
  SafetyCompare safety = SafetyCompare::ge;
  int degree = 3;                        ///< B-spline degree (lowered for few key nodes)
  bspline::EndHandling end = bspline::EndHandling::repeated;
  double spacing = 0.1;                  ///< curve sampling spacing (cells)
  double inflation = 0.0;                ///< clearance verdict radius r
};

struct KinematicResult {
  /// The A* search: raw path (cells), length, expansions, generated, child_nodes (summed over
  /// both runs when the fallback ran).
  search::Outcome search;
  bool fallback_used = false;
  double start_goal_distance = 0.0;        ///< R of Eq. 4
  std::vector<grid::Cell> ordinary;        ///< after the ordinary (first) pass
  std::vector<grid::Cell> secondary;       ///< after the secondary pass
  std::vector<grid::Cell> key_nodes;       ///< the control points (per `redundancy`)
  std::int64_t turns_raw = 0;
  std::int64_t turns_ordinary = 0;
  std::int64_t turns_secondary = 0;
  std::int64_t turns_key = 0;
  double key_length = 0.0;                 ///< metrics.length of the key-node polyline
  bool has_curve = false;                  ///< false when not found or no degree fits
  int degree_used = 0;
  bspline::Samples curve;                  ///< the sampled B-spline (chord bound inside)
  double curve_length = 0.0;               ///< length of the sampled polyline (left to right)
  geometry::Clearance clearance;           ///< of the curve, tolerance chord / 2
  geometry::Clearance key_clearance;       ///< of the key-node polyline (centres), exact
};

/// Runs the global planner of Sensors 2023 (spec sensors2023.plan.astar-kinematic).
/// Source: Sensors 2023 §2.1–2.4, doi:10.3390/s23084102. Spec: sensors2023.plan.astar-kinematic
/// Pre: start, goal in bounds and free (DomainError); options in range: directions 5 or 8,
/// 1 <= radius <= 64, 1 <= k <= 1024, 0 <= ds <= 64, 1 <= degree <= 20, spacing > 0 finite,
/// inflation >= 0 finite (DomainError).
/// Golden: golden/sensors2023/sensors2023.plan.astar-kinematic.json
[[nodiscard]] KinematicResult plan_kinematic(const grid::Grid& g, grid::Cell start,
                                             grid::Cell goal, grid::CornerPolicy policy,
                                             const KinematicOptions& options);

/// The options from a planner's parameter object (the keys of the planner's defaults);
/// UsageError for a bad name or value type, DomainError for a value out of range.
[[nodiscard]] KinematicOptions options_from_json(const planners::Json& params);

/// The result as JSON (the planner's `extra`): spec/sensors2023.md "Output".
[[nodiscard]] planners::Json result_to_json(const KinematicResult& r, const KinematicOptions& o);

}  // namespace pathref::sensors2023

namespace pathref::planners {
/// Planner "astar-kinematic" (Sensors 2023 kinematic-constraint A* with redundancy removal and
/// B-spline). Spec: sensors2023.plan.astar-kinematic
[[nodiscard]] Planner make_astar_kinematic_planner();
}  // namespace pathref::planners
