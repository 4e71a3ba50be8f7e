// Fuzz target: polygon scene reader and writer (spec/formats.md#polygon-scene-json).
//
// INVARIANT: for every byte string t, parse_scene_json(t) either returns a Scene s or throws
// pathref::ParseError (never another exception, never UB, memory bounded by |t|). When it
// returns, to_scene_json(s) does not throw and parse_scene_json(to_scene_json(s)) == s (every
// number survives exactly). A broken invariant traps; sanitizers catch the rest.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "pathref/io/scene_json.hpp"
#include "pathref/core/error.hpp"
#include "pathref/geometry/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::optional<pathref::geometry::Scene> s;
  try {
    s = pathref::io::parse_scene_json(text, "fuzz.json");
  } catch (const pathref::ParseError&) {
    return 0;
  }
  const std::string canonical = pathref::io::to_scene_json(*s);
  const pathref::geometry::Scene again = pathref::io::parse_scene_json(canonical, "canonical.json");
  if (!(again == *s)) __builtin_trap();
  return 0;
}
