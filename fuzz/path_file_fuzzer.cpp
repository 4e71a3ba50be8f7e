// Fuzz target: the path-file reader of `pathref check` (spec/check.md#path-files) and the
// conversion to cells (spec/check.md#path-cells).
//
// INVARIANT: for every byte string t, every format and both file modes (single file, JSON lines),
// parse_path_text either returns records or throws pathref::ParseError (never another exception,
// never UB; nodes counted before they are stored). A returned record has a resolved format, 1 to
// max_path_nodes nodes (pairs for xy/rowcol/plan), every number of magnitude <= max_path_number;
// path_cells gives one cell per node under every base and origin; the record written back as
// `a b` lines (or one number a line) and read with its explicit format gives the same numbers.
// A broken invariant traps (__builtin_trap); sanitizers catch the rest.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "pathref/core/error.hpp"
#include "pathref/io/path_file.hpp"

namespace {
using namespace pathref::io;

void check_record(const PathRecord& r) {
  if (r.format == PathFormat::automatic) __builtin_trap();
  const std::size_t per = r.format == PathFormat::node ? 1 : 2;
  if (r.numbers.empty() || r.numbers.size() % per != 0 || r.numbers.size() / per > max_path_nodes) __builtin_trap();
  for (const std::int64_t v : r.numbers)
    if (v > max_path_number || v < -max_path_number) __builtin_trap();
  for (const std::int64_t base : {0, 1})
    for (const RowOrigin o : {RowOrigin::lower, RowOrigin::upper})
      if (path_cells(r, 3, 2, base, o).size() != r.numbers.size() / per) __builtin_trap();
  if (r.format == PathFormat::plan) return;
  std::string text;
  for (std::size_t i = 0; i < r.numbers.size(); i += per)
    text += per == 1 ? std::to_string(r.numbers[i]) + "\n"
                     : std::to_string(r.numbers[i]) + " " + std::to_string(r.numbers[i + 1]) + "\n";
  const auto back = parse_path_text(text, "back.txt", r.format, false);
  if (back.size() != 1 || back[0].numbers != r.numbers || back[0].format != r.format) __builtin_trap();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  for (const PathFormat f : {PathFormat::automatic, PathFormat::plan, PathFormat::xy, PathFormat::node, PathFormat::rowcol})
    for (const bool lines : {false, true}) {
      std::vector<PathRecord> rs;
      try {
        rs = parse_path_text(text, "fuzz.txt", f, lines);
      } catch (const pathref::ParseError&) {
        continue;  // rejected input: fine
      }
      if (rs.empty()) __builtin_trap();
      for (const PathRecord& r : rs) {
        if (f != PathFormat::automatic && r.format != f) __builtin_trap();
        check_record(r);
      }
    }
  return 0;
}
