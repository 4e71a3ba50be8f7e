// A polygon scene read as a map: parse, limits before allocating, exact inflation, errors that
// name the file. CGAL-free itself (the inflation is in inflation_cgal.cpp); it lives in
// pathref_geometry because it calls inflate_scene.
// Spec: spec/formats.md#polygon-scene-json ("As a map"), spec/inflation.md (inflation.scene).
#include <fmt/core.h>

#include <algorithm>
#include <string>

#include "pathref/io/scene_json.hpp"
#include "pathref/core/error.hpp"
#include "pathref/core/memory.hpp"
#include "geometry_cgal/scene_map.hpp"
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

void require_raster_memory(const Scene& scene, const std::string& filename, std::uint64_t max_memory,
                           std::uint64_t bytes_per_cell) {
  const auto cells = static_cast<std::uint64_t>(scene.width) * static_cast<std::uint64_t>(scene.height);
  memory::require_within(memory::times(cells, std::max<std::uint64_t>(bytes_per_cell, 1)), max_memory,
                         fmt::format("{}: the scene's {}x{} world ({} bytes per cell{})", filename, scene.width,
                                     scene.height, std::max<std::uint64_t>(bytes_per_cell, 1),
                                     bytes_per_cell > 1 ? ", the grid and the planner's state" : ": its raster"));
}

io::MapFile scene_map(std::string_view text, const std::string& filename, const io::ReadLimits& limits) {
  io::check_limits(limits);
  const Scene scene = io::parse_scene_json(text, filename);
  const std::int64_t w = scene.width;
  const std::int64_t h = scene.height;
  if (w > limits.max_side || h > limits.max_side)
    throw io::json_error_at(text, filename, w > limits.max_side ? "/width" : "/height",
                            fmt::format("a {}x{} grid exceeds the limit of {} cells per side", w, h, limits.max_side));
  if (w > limits.max_cells / h)
    throw io::json_error_at(text, filename, "/width",
                            fmt::format("a {}x{} grid exceeds the limit of {} cells", w, h, limits.max_cells));
  // spec/formats.md#limits: a scene of a few hundred bytes can declare a 2^28-cell world; its
  // raster (and the run on it) is estimated before the grid is allocated.
  require_raster_memory(scene, filename, limits.max_memory, limits.bytes_per_cell);
  InflatedScene inf = inflate_scene_file(scene, filename);
  return io::MapFile{std::move(inf.grid), inf.start, inf.goal, scene.name};
}

}  // namespace pathref::geometry
