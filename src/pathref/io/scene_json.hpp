#pragma once
/// \file scene_json.hpp
/// Reading and writing polygon scenes ("pathref-scene 1", JSON) through the one JSON reading
/// layer (spec/formats.md#polygon-scene-json, #json). The scene itself is geometry::Scene
/// (geometry/scene.hpp); its file format is io's (docs/architecture.md#layers).
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "pathref/geometry/scene.hpp"

namespace pathref::io {

using geometry::Point;
using geometry::Polygon;
using geometry::Scene;

/// What the reader demands of the object.
enum class SceneKeys {
  file,      ///< a scene file: "format" and "start"/"goal" required
  geometry,  ///< a rule input: "format", "start", "goal" optional
};

/// Parses scene JSON text. Numbers are read exactly from their text (0.3 = 3/10).
/// Throws ParseError(filename, line, column, what) for invalid JSON (line/column of the
/// offending byte) and ParseError `FILE:LINE:COLUMN: <JSON pointer>: expected ...` at the value for a value of
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

}  // namespace pathref::io
