// Fuzz target: 0/1 matrix reader (plain rows and MATLAB `G=[...]`) and its two writers
// (spec/formats.md#matrix).
//
// INVARIANT: for every byte string t, parse_matrix(t) either returns a MapFile m or throws
// pathref::ParseError (never another exception, never UB, memory bounded by a multiple of |t|).
// When it returns: m has no start, goal or name; both writers' texts read back to the same grid
// and are fixed points of read-then-write; reading t under the small limits {8 per side, 32
// cells} gives the same grid when it fits them and throws ParseError otherwise.
// A broken invariant traps (__builtin_trap); sanitizers catch the rest.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "pathref/core/error.hpp"
#include "pathref/io/matrix.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pathref::io;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::optional<MapFile> m;
  try {
    m = parse_matrix(text, "fuzz.m");
  } catch (const pathref::ParseError&) {
    return 0;  // rejected input: fine
  }
  if (m->start || m->goal || !m->name.empty()) __builtin_trap();
  const std::string plain = to_matrix_text(m->grid);
  const std::string matlab = to_matlab_text(m->grid);
  const MapFile a = parse_matrix(plain, "plain.txt");
  const MapFile b = parse_matrix(matlab, "matlab.m");
  if (!(a.grid == m->grid) || !(b.grid == m->grid)) __builtin_trap();
  if (to_matrix_text(a.grid) != plain || to_matlab_text(b.grid) != matlab) __builtin_trap();
  const bool fits = m->grid.width() <= 8 && m->grid.height() <= 8 && m->grid.cell_count() <= 32;
  try {
    const MapFile limited = parse_matrix(text, "fuzz.m", ReadLimits{8, 32});
    if (!fits || !(limited.grid == m->grid)) __builtin_trap();
  } catch (const pathref::ParseError&) {
    if (fits) __builtin_trap();
  }
  return 0;
}
