// Fuzz target: exact inflation of polygon scenes (spec/inflation.md).
// pathref-fuzz-libs: pathref_geometry
//
// INVARIANT: for every scene text that parses, with at most 64x64 cells, 64 vertices in all and
// cells x vertices <= 4096 (larger scenes are skipped to keep executions fast: the brute-force
// oracle and the r + 1 pass are per (cell, edge), and a 20x61 scene with 11 vertices and r/s = 10
// took 10 s under ASan+UBSan, the smoke run's -timeout), inflate_scene either returns or throws
// pathref::DomainError (invalid polygon, bad start/goal); never another exception, never UB.
// When inflate_polygons returns, the cells checked (all of them up to 64 cells, else every k-th
// cell index, k = ceil(W*H / 64)) agree with the brute-force definition cell_blocked, and
// inflating with r + 1 blocks a superset of all cells (monotone in r).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "pathref/io/scene_json.hpp"
#include "pathref/core/error.hpp"
#include "pathref/geometry/inflation.hpp"
#include "pathref/geometry/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace g = pathref::geometry;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::optional<g::Scene> s;
  try {
    s = pathref::io::parse_scene_json(text, "fuzz.json");
  } catch (const pathref::ParseError&) {
    return 0;
  }
  std::size_t vertices = 0;
  for (const auto& p : s->polygons) vertices += p.vertices.size();
  if (s->width > 64 || s->height > 64 || vertices > 64) return 0;
  if (s->width * s->height * static_cast<std::int64_t>(vertices) > 4096) return 0;
  try {
    (void)g::inflate_scene(*s);
  } catch (const pathref::DomainError&) {
  }
  std::optional<pathref::grid::Grid> grid;
  try {
    grid = g::inflate_polygons(*s);
  } catch (const pathref::DomainError&) {
    return 0;  // invalid polygon
  }
  // The brute-force oracle costs ~1 ms per cell (normal build; ~16x under ASan+UBSan), so it
  // checks at most 64 cells: all of them on small grids, else every k-th cell index
  // (k = ceil(cells / 64)), a different subset for each grid size.
  const std::int64_t cells = s->width * s->height;
  const std::int64_t stride = (cells + 63) / 64;
  for (std::int64_t i = 0; i < cells; i += stride) {
    const pathref::grid::Cell c = grid->cell(i);
    if (grid->blocked(c) != g::cell_blocked(*s, c)) __builtin_trap();
  }
  g::Scene wider = *s;
  if (auto one = g::parse_decimal("1"); one && wider.margin.is_zero()) {
    wider.margin = *one;
    const pathref::grid::Grid w = g::inflate_polygons(wider);
    for (std::int64_t y = 0; y < s->height; ++y)
      for (std::int64_t x = 0; x < s->width; ++x)
        if (grid->blocked({x, y}) && !w.blocked({x, y})) __builtin_trap();
  }
  return 0;
}
