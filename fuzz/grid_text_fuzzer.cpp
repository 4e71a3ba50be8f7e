// Fuzz target: pathref-grid 1 reader and writer (spec/formats.md#pathref-grid-1).
//
// INVARIANT: for every byte string t, parse_grid_text(t) either returns a MapFile m or throws
// pathref::ParseError (never another exception, never UB, memory bounded by |t|). When it
// returns, the canonical text c = to_grid_text(m) does not throw, parse_grid_text(c) == m, and
// to_grid_text(parse_grid_text(c)) == c (the writer's output is a fixed point).
// A broken invariant traps (__builtin_trap); sanitizers catch the rest.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "pathref/core/error.hpp"
#include "pathref/io/grid_text.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::optional<pathref::io::MapFile> m;
  try {
    m = pathref::io::parse_grid_text(text, "fuzz.txt");
  } catch (const pathref::ParseError&) {
    return 0;  // rejected input: fine
  }
  // Any other exception escapes and aborts the run: a finding.
  const std::string canonical = pathref::io::to_grid_text(*m);
  const pathref::io::MapFile again = pathref::io::parse_grid_text(canonical, "canonical.txt");
  if (!(again == *m)) __builtin_trap();
  if (pathref::io::to_grid_text(again) != canonical) __builtin_trap();
  return 0;
}
