// Fuzz target: draw traces of `pathref trace-diff` (spec/rng.md#draw-traces): io::parse_trace,
// which reads each line through io::parse_json_text, and rng::first_divergence.
//
// INVARIANT: for every byte string t, parse_trace(t) either returns a TraceFile or throws
// pathref::ParseError (never another exception, never UB, never a recursion deeper than the JSON
// layer's 64 levels) whose message holds no raw control byte. A returned trace has draws numbered
// 0, 1, 2, ... with u in [0, 1); written back as `{"i": I, "u": U}` lines (U with 17 significant
// digits) it reads to the same doubles; it agrees with itself (first_divergence = nullopt) and,
// when it has a draw, differs from itself without its last draw at exactly that draw. A broken
// invariant traps (__builtin_trap); sanitizers catch the rest.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "pathref/core/error.hpp"
#include "pathref/io/trace_file.hpp"
#include "pathref/rng/trace.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pathref;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  io::TraceFile t;
  try {
    t = io::parse_trace(text, "fuzz.jsonl");
  } catch (const ParseError& e) {
    for (const char c : std::string(e.what()))
      if (static_cast<unsigned char>(c) < 0x20) __builtin_trap();
    return 0;
  }
  std::string back;
  for (std::size_t i = 0; i < t.draws.size(); ++i) {
    const rng::Draw& d = t.draws[i];
    if (d.index != i || !(d.value >= 0.0 && d.value < 1.0)) __builtin_trap();
    char line[96];
    std::snprintf(line, sizeof line, "{\"i\": %zu, \"u\": %.17g}\n", i, d.value);
    back += line;
  }
  const io::TraceFile again = io::parse_trace(back, "back.jsonl");
  if (again.draws.size() != t.draws.size()) __builtin_trap();
  for (std::size_t i = 0; i < t.draws.size(); ++i)
    if (again.draws[i].value != t.draws[i].value) __builtin_trap();
  if (rng::first_divergence(t.draws, again.draws).has_value()) __builtin_trap();
  if (!t.draws.empty()) {
    auto shorter = t.draws;
    shorter.pop_back();
    const auto at = rng::first_divergence(t.draws, shorter);
    if (!at || *at != shorter.size()) __builtin_trap();
  }
  return 0;
}
