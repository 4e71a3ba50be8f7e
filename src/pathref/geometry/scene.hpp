#pragma once
/// \file scene.hpp
/// Polygon scenes ("pathref-scene 1", JSON): a world rectangle of W x H square cells of exact
/// size s with its lower-left corner at an exact origin, obstacle polygons (simple, non-convex
/// allowed) with exact decimal vertices, the robot radius and safety margin (Shi et al. 2022,
/// Sec. 3: obstacles are expanded by radius + safety distance), and the start and goal cells.
/// This header and its parser are CGAL-free; the geometry (inflation.hpp) lives in the separate
/// library pathref_geometry.
/// Spec: spec/formats.md#polygon-scene-json (grammar, limits, errors), spec/inflation.md
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

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

/// What the reader demands of the object.
enum class SceneKeys {
  file,      ///< a scene file: "format" and "start"/"goal" required
  geometry,  ///< a rule input: "format", "start", "goal" optional
};

/// Parses scene JSON text. Numbers are read exactly from their text (0.3 = 3/10).
/// Throws ParseError(filename, line, column, what) for invalid JSON (line/column of the
/// offending byte) and ParseError(filename, 0, 0, "<JSON pointer>: expected ...") for a value of
/// the wrong type, a missing or unknown key, a number outside its range or the limits.
/// Geometric preconditions (simple polygons, start/goal placement) are NOT checked here: they are
/// DomainErrors of the inflation rules (spec/inflation.md).
[[nodiscard]] Scene parse_scene_json(std::string_view text, std::string_view filename);

/// Reads a scene from an already parsed JSON object (rule inputs, `pathref eval`): the same
/// checks as parse_scene_json; a JSON number stored as a double is read as the decimal of its
/// shortest round-trip text (exact for <= 15 significant digits, spec/formats.md).
[[nodiscard]] Scene scene_from_json(const nlohmann::json& object, std::string_view filename,
                                    SceneKeys keys);

/// The scene as JSON text with numbers written exactly (decimal notation); reading it back with
/// parse_scene_json gives an equal Scene.
[[nodiscard]] std::string to_scene_json(const Scene& scene);

/// Reads a whole file and parses it. UsageError when it cannot be opened, is not a regular file
/// or is larger than max_scene_file_bytes (checked before reading).
[[nodiscard]] Scene read_scene_file(const std::string& path);

}  // namespace pathref::geometry
