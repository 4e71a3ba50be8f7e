// `pathref convert` (read a map in any format, write it as pathref-grid, MovingAI or a matrix) and
// the map-reading options shared with `plan` and `scen`. Spec: spec/formats.md#cli-convert, #map-options.
#include <fmt/core.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include "commands.hpp"
#include "pathref/core/error.hpp"
#include "pathref/core/memory.hpp"
#include "geometry_cgal/scene_map.hpp"
#include "pathref/geometry/inflation.hpp"
#include "pathref/io/map_file.hpp"

namespace pathref::cli {

namespace {

/// A --max-side / --max-cells value: decimal digits only, in [1, Grid::max_cells].
std::int64_t parse_limit(const std::string& text, const char* option) {
  constexpr std::int64_t hard = grid::Grid::max_cells;
  const bool digits = !text.empty() && text.size() <= 10 && text.find_first_not_of("0123456789") == std::string::npos;
  std::int64_t v = 0;
  if (digits)
    for (const char c : text) v = v * 10 + (c - '0');
  if (!digits || v < 1 || v > hard)
    throw UsageError(fmt::format("{} expects a decimal integer from 1 to {}, got '{}'", option, hard, text));
  return v;
}

struct ConvertOptions {
  std::string input;
  std::string to;
  std::string output;
  MapReadArgs read;
};

/// `pathref convert`: exit 0 after writing the map; 2 on bad input.
int run_convert(const ConvertOptions& o) {
  const io::OutputFormat to = io::parse_output_format(o.to);
  const io::LoadedMapFile in = io::load_map_file(o.input, map_read_options(o.read));
  const io::MapFile& m = in.map;
  const std::string text = io::write_map_text(m, to);
  if (o.output.empty() || o.output == "-") {
    fmt::print("{}", text);
  } else {
    write_output_file(o.output, text);
  }
  if (to != io::OutputFormat::pathref_grid && (m.start || m.goal || !m.name.empty()))
    fmt::print(stderr, "pathref: note: the {} format has no start, goal or name; they were not written\n", o.to);
  return 0;
}

}  // namespace

void add_map_read_options(CLI::App* cmd, MapReadArgs& args) {
  cmd->add_option("--format", args.format,
                  "map format: auto (by extension, spec/formats.md#detection), pathref-grid, movingai, matrix, ros, scene")
      ->type_name("FORMAT")
      ->check(CLI::IsMember({"auto", "pathref-grid", "movingai", "matrix", "ros", "scene"}))
      ->capture_default_str();
  cmd->add_option("--swamp", args.swamp, "MovingAI 'S' (swamp) cells: free or blocked")
      ->type_name("free|blocked")
      ->check(CLI::IsMember({"free", "blocked"}))
      ->capture_default_str();
  cmd->add_option("--water", args.water, "MovingAI 'W' (water) cells: free or blocked")
      ->type_name("free|blocked")
      ->check(CLI::IsMember({"free", "blocked"}))
      ->capture_default_str();
  cmd->add_option("--unknown", args.unknown, "ROS map cells that are neither free nor occupied: blocked or free")
      ->type_name("blocked|free")
      ->check(CLI::IsMember({"blocked", "free"}))
      ->capture_default_str();
  cmd->add_option("--max-side", args.max_side, "largest width or height a map may have (default 268435456)")
      ->type_name("N");
  cmd->add_option("--max-cells", args.max_cells, "largest number of cells a map may have (default 268435456)")
      ->type_name("N");
  add_max_memory_option(cmd, args.max_memory);
}

void add_max_memory_option(CLI::App* cmd, std::string& value) {
  cmd->add_option("--max-memory", value,
                  "memory limit: a run whose estimated need exceeds it is refused before allocating "
                  "(bytes, or with K/M/G/T suffix; default 4G; spec/cli.md#memory)")
      ->type_name("SIZE");
}

std::uint64_t max_memory_of(const std::string& text) {
  return text.empty() ? memory::default_limit : memory::parse_size(text, "--max-memory");
}

io::MapReadOptions map_read_options(const MapReadArgs& args, std::uint64_t bytes_per_cell) {
  io::MapReadOptions o;
  o.format = io::parse_map_format(args.format);
  o.terrain.swamp_free = args.swamp == "free";
  o.terrain.water_free = args.water == "free";
  o.ros_unknown = io::parse_unknown_as(args.unknown);
  if (!args.max_side.empty()) o.limits.max_side = parse_limit(args.max_side, "--max-side");
  if (!args.max_cells.empty()) o.limits.max_cells = parse_limit(args.max_cells, "--max-cells");
  o.limits.max_memory = max_memory_of(args.max_memory);
  o.limits.bytes_per_cell = bytes_per_cell;
  o.scene_to_map = geometry::scene_map;  // .json: polygon scenes, inflated exactly
  return o;
}

void add_convert_command(CLI::App& app, Action& run) {
  static ConvertOptions o;
  auto* cmd = app.add_subcommand(
      "convert", "Read a map in any format and write it as pathref-grid, MovingAI, a 0/1 matrix or a MATLAB matrix");
  cmd->add_option("input", o.input, "the map file (format by extension or --format)")->type_name("FILE")->required();
  cmd->add_option("--to", o.to, "output format: pathref-grid, movingai, matrix, matlab")
      ->type_name("FORMAT")
      ->required()
      ->check(CLI::IsMember({"pathref-grid", "movingai", "matrix", "matlab"}));
  cmd->add_option("-o,--output", o.output, "write to FILE instead of standard output")->type_name("FILE");
  add_map_read_options(cmd, o.read);
  cmd->callback([&run] { run = [] { return run_convert(o); }; });
}

}  // namespace pathref::cli
