// `pathref inflate SCENE.json [-o FILE] [--svg FILE]` (spec/inflation.md#cli): reads a polygon
// scene, inflates its obstacles exactly (inflation.scene) and writes the grid map as
// pathref-grid 1 text (stdout without --out), ready for `pathref plan --map FILE`.
#include <fmt/core.h>

#include <fstream>
#include <string>

#include "commands.hpp"
#include "pathref/io/scene_json.hpp"
#include "pathref/core/error.hpp"
#include "pathref/geometry/inflation.hpp"
#include "pathref/geometry/scene.hpp"
#include "pathref/io/grid_text.hpp"
#include "pathref/io/svg.hpp"

namespace pathref::cli {

void add_inflate_command(CLI::App& app, Action& run) {
  auto* cmd = app.add_subcommand(
      "inflate",
      "Inflate the polygons of a scene (pathref-scene 1 JSON) by radius + margin, exactly, into a "
      "grid map (pathref-grid 1)");
  static std::string scene_path, out_path, svg_path;
  cmd->add_option("scene", scene_path, "scene file (JSON, spec/formats.md#polygon-scene-json)")->required();
  cmd->add_option("-o,--output,--out", out_path,
                  "write the grid map to FILE instead of stdout (-o/--output as in convert; --out kept as an alias)")
      ->type_name("FILE");
  cmd->add_option("--svg", svg_path, "also write an SVG figure of the inflated map");
  static std::string max_memory;
  add_max_memory_option(cmd, max_memory);
  cmd->callback([&run] {
    run = [] {
      const std::uint64_t limit = max_memory_of(max_memory);
      const geometry::Scene scene = io::read_scene_file(scene_path);
      // spec/inflation.md#cli: the raster (1 byte per cell) and its text (1 byte per cell) are
      // estimated before either is allocated.
      geometry::require_raster_memory(scene, scene_path, limit, 2);
      geometry::InflatedScene inf = geometry::inflate_scene_file(scene, scene_path);
      const io::MapFile map{std::move(inf.grid), inf.start, inf.goal, scene.name};  // moved, not copied
      const std::string text = io::to_grid_text(map);
      if (out_path.empty()) {
        fmt::print("{}", text);
      } else {
        write_output_file(out_path, text);
      }
      if (!svg_path.empty()) {
        const std::string title = fmt::format(
            "{} inflated by r = {} + {} ({} of {} cells blocked)",
            scene.name.empty() ? std::string("scene") : scene.name, geometry::to_string(scene.radius),
            geometry::to_string(scene.margin), map.grid.blocked_count(), map.grid.cell_count());
        write_figure(svg_path, io::svg_map(map.grid, inf.start, inf.goal, {}, title));
      }
      return 0;
    };
  });
}

}  // namespace pathref::cli
