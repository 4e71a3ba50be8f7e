#pragma once
/// \file scene.hpp
/// Polygon scenes ("pathref-scene 1", JSON): a world rectangle of W x H square cells of exact
/// size s with its lower-left corner at an exact origin, obstacle polygons (simple, non-convex
/// allowed) with exact decimal vertices, the robot radius and safety margin (Shi et al. 2022,
/// Sec. 3: obstacles are expanded by radius + safety distance), and the start and goal cells.
/// This header is CGAL-free (its reader is io/scene_json.hpp); the geometry (inflation.hpp) lives in the separate
/// library pathref_geometry.
/// Spec: spec/formats.md#polygon-scene-json (grammar, limits, errors), spec/inflation.md
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pathref/geometry/decimal.hpp"
#include "pathref/grid/grid.hpp"

namespace pathref::geometry {

/// A point with exact decimal coordinates (world units, y up).
struct Point {
  Decimal x;
  Decimal y;
  friend bool operator==(const Point&, const Point&) = default;
};

/// A closed polygonal region: the vertex cycle (either orientation) and its interior.
struct Polygon {
  std::vector<Point> vertices;
  friend bool operator==(const Polygon&, const Polygon&) = default;
};

/// A polygon scene as read from a file. Cell (x, y) is the closed square
/// [ox + x s, ox + (x+1) s] x [oy + y s, oy + (y+1) s].
struct Scene {
  Point origin;                 ///< lower-left corner of the world rectangle
  std::int64_t width = 1;       ///< W, cells along x
  std::int64_t height = 1;      ///< H, cells along y
  Decimal cell_size;            ///< s > 0
  Decimal radius;               ///< robot radius >= 0
  Decimal margin;               ///< safety margin >= 0; r = radius + margin
  std::vector<Polygon> polygons;
  std::optional<grid::Cell> start;
  std::optional<grid::Cell> goal;
  std::string name;
  friend bool operator==(const Scene&, const Scene&) = default;
};

/// Scene limits, checked while reading, before anything proportional to them is allocated
/// (spec/formats.md "Polygon scene (JSON)", limits).
inline constexpr std::size_t max_scene_polygons = 100000;
inline constexpr std::size_t max_polygon_vertices = 100000;
inline constexpr std::size_t max_scene_vertices = 1000000;
inline constexpr std::uintmax_t max_scene_file_bytes = std::uintmax_t{64} << 20;

// Reading and writing scene files is io's (pathref/io/scene_json.hpp: io::parse_scene_json,
// io::scene_from_json, io::to_scene_json, io::read_scene_file; docs/architecture.md#layers).
// Before 0.3.0 they were declared here, in namespace geometry.

}  // namespace pathref::geometry
