// Fuzz target: MovingAI .map reader and writer (spec/formats.md#movingai-map).
//
// INVARIANT: for every byte string t, parse_movingai_map(t) either returns a MapFile m or throws
// pathref::ParseError (never another exception, never UB, memory bounded by a multiple of |t|).
// When it returns: m has no start, goal or name; the writer's text c = to_movingai_map(m.grid)
// reads back to the same grid and is a fixed point of read-then-write; reading t with S and W
// both free blocks no more cells than the default reading; and reading t under the small limits
// {8 per side, 32 cells} either gives the same grid (when it fits them) or throws ParseError.
// A broken invariant traps (__builtin_trap); sanitizers catch the rest.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "pathref/core/error.hpp"
#include "pathref/io/movingai.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pathref::io;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::optional<MapFile> m;
  try {
    m = parse_movingai_map(text, "fuzz.map");
  } catch (const pathref::ParseError&) {
    return 0;  // rejected input: fine
  }
  if (m->start || m->goal || !m->name.empty()) __builtin_trap();
  const std::string canonical = to_movingai_map(m->grid);
  const MapFile again = parse_movingai_map(canonical, "canonical.map");
  if (!(again.grid == m->grid)) __builtin_trap();
  if (to_movingai_map(again.grid) != canonical) __builtin_trap();
  const MapFile open = parse_movingai_map(text, "fuzz.map", MovingAiTerrain{true, true});
  if (open.grid.blocked_count() > m->grid.blocked_count()) __builtin_trap();
  const ReadLimits small{8, 32};
  const bool fits = m->grid.width() <= 8 && m->grid.height() <= 8 && m->grid.cell_count() <= 32;
  try {
    const MapFile limited = parse_movingai_map(text, "fuzz.map", {}, small);
    if (!fits || !(limited.grid == m->grid)) __builtin_trap();
  } catch (const pathref::ParseError&) {
    if (fits) __builtin_trap();
  }
  return 0;
}
