#pragma once
/// \file clearance.hpp
/// The one clearance function of every continuous planner (sensors2023's B-spline, cin2021's
/// S-RRT curve, the DWA's trajectories): the Euclidean distance from a polyline (or from the
/// samples of a curve, with the sampler's proven chord bound) to the obstacles of a grid map,
/// each blocked cell being the closed unit square [x, x + 1] x [y, y + 1], and, optionally, the
/// outside of the map. Whether the path enters the obstacles inflated by a radius r follows.
///
/// Method (exact, not sampling): the distance between a segment and a closed axis-aligned
/// square is 0 if they intersect (Liang–Barsky clipping), else the least of the distances from
/// the segment's two end points to the square and from the square's four corners to the segment
/// (two disjoint convex sets are nearest at a vertex of one of them). The distance of the
/// polyline is the least over its segments; each segment's nearest cell is found in a window
/// around the segment grown until it holds a cell no farther than the window's margin, which
/// no cell outside the window can beat. Evaluated in binary64: the only roundings are those of
/// the few products, sums and one sqrt per candidate (a few ulps of the distance).
/// The polygon variant (cin2021's S-RRT on pathref-scene maps) takes each segment's distance from
/// the continuous map (geometry::ObstacleMap: exact with CGAL, rounded to the nearest double) and
/// shares the bounds and the verdict with the grid variant.
/// Source: pathref (neither sensors2023 nor cin2021 checks its smoothed curve against the map).
/// Spec: spec/curves.md r[curves.clearance], r[curves.polygon-clearance]
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "pathref/geometry/vec2.hpp"
#include "pathref/grid/grid.hpp"

#include "pathref/geometry/collision.hpp"

namespace pathref::geometry {

/// Options of curves.clearance.
struct ClearanceOptions {
  /// r >= 0: the obstacles are inflated by r (robot radius + margin); the path enters them
  /// where its distance is <= r.
  double inflation = 0.0;
  /// tau >= 0: the polyline's vertices are samples of a curve, and every curve point lies within
  /// tau of a sample (bspline::Samples::chord / 2); 0 = the polyline is the path itself.
  double tolerance = 0.0;
  /// The outside of the map [0, W] x [0, H] counts as an obstacle (default); false = only cells.
  bool border = true;
};

/// Whether the path enters the inflated obstacles.
enum class ClearanceVerdict {
  clear,         ///< certainly not: lower > r
  enters,        ///< certainly: upper <= r (a point of the path is within r of an obstacle)
  undetermined,  ///< lower <= r < upper: sample the curve more densely (tolerance > 0 only)
};
[[nodiscard]] std::string_view to_string(ClearanceVerdict v) noexcept;

struct Clearance {
  /// Exact distance from the polyline (all its segments) to the obstacles; +inf when there is
  /// no obstacle at all (no blocked cell and border = false).
  double distance = 0.0;
  /// Bounds on the clearance of the path: tolerance = 0: lower = upper = distance. tolerance > 0:
  /// lower = max(0, distance - tolerance), upper = the least distance of a vertex (a sample,
  /// which lies on the curve).
  double lower = 0.0;
  double upper = 0.0;
  ClearanceVerdict verdict = ClearanceVerdict::clear;
  /// The first segment (0-based; the vertex for a single point) attaining `distance`; -1 if +inf.
  std::int64_t segment = -1;
};

/// Distance from the point p to the closed box [x0, x1] x [y0, y1]: sqrt((dx dx) + (dy dy)) with
/// dx = max(x0 - p.x, 0, p.x - x1), dy likewise (0 inside or on the boundary). The point case of
/// segment_box_distance (which uses it for the segment's end points) and the surface distance of
/// a point to a cell of the DWA's clearance (the cell [c.x, c.x + 1] x [c.y, c.y + 1]): one
/// function for both. Source: pathref. Spec: curves.clearance, sensors2023.dwa.clearance.
/// Pre: finite inputs, x0 <= x1, y0 <= y1 (not checked: called per predicted point and cell;
/// callers check their inputs). Post: >= 0.
[[nodiscard]] double point_box_distance(Vec2 p, double x0, double y0, double x1, double y1) noexcept;

/// Distance from the segment [a, b] to the closed square [x0, x1] x [y0, y1] (method above).
/// Source: pathref. Spec: curves.clearance. Pre: finite inputs, x0 <= x1, y0 <= y1
/// (DomainError). Post: >= 0; 0 iff they intersect.
[[nodiscard]] double segment_box_distance(Vec2 a, Vec2 b, double x0, double y0, double x1,
                                          double y1);

/// The clearance of the polyline `points` on grid `g` (method above).
/// Source: pathref. Spec: curves.clearance.
/// Pre: points non-empty and finite; inflation and tolerance finite and >= 0 (DomainError).
/// Post: 0 <= lower <= distance <= upper (tolerance 0: all equal).
/// Golden: golden/curves/curves.clearance.json
[[nodiscard]] Clearance clearance(const grid::Grid& g, std::span<const Vec2> points,
                                  const ClearanceOptions& options = {});

/// The clearance of the polyline `points` against the obstacles of a continuous map (polygons):
/// the distance of segment [a, b] is map.segment_clearance(a, b) (ObstacleMap: the exact
/// distance to the closed polygons, without r, rounded to the nearest double; +inf without
/// obstacles); with `border` the outside of the world rectangle [lower, upper] counts as an
/// obstacle (distance of a point max(0, min(x - lo.x, hi.x - x, y - lo.y, hi.y - y))). The
/// bounds (lower, upper with the tolerance), the verdict against `inflation` and `segment` are
/// those of the grid variant (the same code). Source: pathref. Spec: curves.polygon-clearance.
/// Pre: as the grid variant (DomainError). Post: 0 <= lower <= distance <= upper.
/// Golden: golden/curves/curves.polygon-clearance.json
[[nodiscard]] Clearance clearance(const CollisionChecker& map,
                                  std::span<const Vec2> points,
                                  const ClearanceOptions& options = {});

}  // namespace pathref::geometry
