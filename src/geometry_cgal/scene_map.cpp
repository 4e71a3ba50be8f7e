// A polygon scene read as a map: parse, limits before allocating, exact inflation, errors that
// name the file. CGAL-free itself (the inflation is in inflation_cgal.cpp); it lives in
// pathref_geometry because it calls inflate_scene.
// Spec: spec/formats.md#polygon-scene-json ("As a map"), spec/inflation.md (inflation.scene).
#include <fmt/core.h>

#include <string>

#include "pathref/core/error.hpp"
#include "pathref/geometry/inflation.hpp"
#include "pathref/io/json_text.hpp"
#include "pathref/io/map_file.hpp"

namespace pathref::geometry {

InflatedScene inflate_scene_file(const Scene& scene, const std::string& filename) {
  try {
    return inflate_scene(scene);
  } catch (const DomainError& e) {
    throw DomainError(filename + ": " + e.what());
  }
}

io::MapFile scene_map(std::string_view text, const std::string& filename, const io::ReadLimits& limits) {
  io::check_limits(limits);
  const Scene scene = parse_scene_json(text, filename);
  const std::int64_t w = scene.width;
  const std::int64_t h = scene.height;
  if (w > limits.max_side || h > limits.max_side)
    throw io::json_error_at(text, filename, w > limits.max_side ? "/width" : "/height",
                            fmt::format("a {}x{} grid exceeds the limit of {} cells per side", w, h, limits.max_side));
  if (w > limits.max_cells / h)
    throw io::json_error_at(text, filename, "/width",
                            fmt::format("a {}x{} grid exceeds the limit of {} cells", w, h, limits.max_cells));
  InflatedScene inf = inflate_scene_file(scene, filename);
  return io::MapFile{std::move(inf.grid), inf.start, inf.goal, scene.name};
}

}  // namespace pathref::geometry
