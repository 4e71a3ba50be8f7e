// Fuzz target: MovingAI .scen reader, the agreement tolerance and the map checks
// (spec/formats.md#movingai-scen, #scen-agreement).
//
// INVARIANT: for every byte string t, parse_movingai_scen(t) either returns a ScenFile f or
// throws pathref::ParseError (never another exception, never UB). When it returns: f has at least
// one scenario; version is 0 or 1; width/height are present exactly in version 1 and then contain
// start and goal; start != goal; every optimal length is finite and >= 0 with a finite tolerance
// > 0 for every writer precision 0..17, and agrees with itself; check_scenario_on_map against a
// fixed 6x4 map either returns or throws ParseError.
// A broken invariant traps (__builtin_trap); sanitizers catch the rest.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "pathref/core/error.hpp"
#include "pathref/io/movingai.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pathref::io;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::optional<ScenFile> f;
  try {
    f = parse_movingai_scen(text, "fuzz.scen");
  } catch (const pathref::ParseError&) {
    return 0;  // rejected input: fine
  }
  if (f->scenarios.empty() || (f->version != 0 && f->version != 1)) __builtin_trap();
  static const pathref::grid::Grid g =
      pathref::grid::Grid::from_rows_top_first({"..#...", "......", ".#....", "......"});
  for (const Scenario& s : f->scenarios) {
    if (s.width.has_value() != (f->version == 1) || s.height.has_value() != (f->version == 1)) __builtin_trap();
    if (s.width && (s.start_x.value >= s.width->value || s.goal_y.value >= s.height->value)) __builtin_trap();
    if (s.start_x.value == s.goal_x.value && s.start_y.value == s.goal_y.value) __builtin_trap();
    if (!std::isfinite(s.optimal.value) || s.optimal.value < 0) __builtin_trap();
    for (int p = 0; p <= 17; ++p) {
      const double u = agreement_tolerance(s.optimal, p);
      if (!std::isfinite(u) && u != HUGE_VAL) __builtin_trap();
      if (!(u >= 0)) __builtin_trap();
    }
    if (!lengths_agree(s.optimal.value, s.optimal, agreement_tolerance(s.optimal, 6))) __builtin_trap();
    try {
      check_scenario_on_map(s, g, "six.map", "fuzz.scen");
    } catch (const pathref::ParseError&) {
    }
  }
  return 0;
}
