// Fuzz target: the "pathref-sim 2" scenario parser and, for small scenarios, the fused run
// (spec/sensors2023-dwa.md, sensors2023.sim.run).
//
// INVARIANT: for every byte string t, parse_fused_scenario(t) either returns a FusedScenario s or
// throws pathref::ParseError (or a UsageError for a map file it cannot read; never another
// exception, never UB). When it returns: start and goal are free cells of the map, the path (if
// any) runs from start to goal over free cells, every mover has 1..1000 waypoints with strictly
// increasing times, every temporary cell is inside the map with appear < disappear. For a small
// scenario (at most 64 cells, at most 60 steps, at most 400 candidate pairs per window) the run
// ends with one outcome after at most t_max/dt + 1 steps, with min_clearance < 0 iff it collided.
// A broken invariant traps (__builtin_trap); sanitizers catch the rest.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "pathref/core/error.hpp"
#include "pathref/sim/fused.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pathref;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::optional<dwa::FusedScenario> s;
  try {
    s = dwa::parse_fused_scenario(text, "fuzz.json", "/nonexistent-fuzz-dir");
  } catch (const ParseError&) {
    return 0;
  } catch (const UsageError&) {
    return 0;  // a map file name that cannot be read
  }
  if (!s->grid.free(s->start) || !s->grid.free(s->goal)) __builtin_trap();
  if (!s->path.empty() && (!(s->path.front() == s->start) || !(s->path.back() == s->goal))) __builtin_trap();
  for (const auto& c : s->path)
    if (!s->grid.free(c)) __builtin_trap();
  for (const auto& m : s->moving) {
    if (m.waypoints.empty() || m.waypoints.size() > 1000) __builtin_trap();
    for (std::size_t i = 1; i < m.waypoints.size(); ++i)
      if (!(m.waypoints[i].t > m.waypoints[i - 1].t)) __builtin_trap();
  }
  for (const auto& t : s->temporary)
    if (!s->grid.in_bounds(t.cell) || !(t.appear < t.disappear)) __builtin_trap();
  const auto& d = s->dwa;
  const double nv = std::floor(((d.limits.acc_v + d.limits.dec_v) * d.dt) / d.v_res) + 2.0;
  const double nw = std::floor(((d.limits.acc_w + d.limits.dec_w) * d.dt) / d.w_res) + 2.0;
  if (s->grid.cell_count() > 64 || s->t_max / d.dt > 60.0 || nv * nw > 400.0 || std::round(d.horizon / d.dt) > 20.0)
    return 0;
  dwa::FusedResult r;
  try {
    r = dwa::simulate_fused(*s);
  } catch (const UsageError&) {
    return 0;  // unknown planner
  } catch (const DomainError&) {
    return 0;  // e.g. a robot driven beyond the coordinate limits
  }
  if (r.global_found && r.steps > static_cast<std::int64_t>(std::ceil(s->t_max / d.dt)) + 1) __builtin_trap();
  if (r.global_found && ((r.outcome == dwa::Outcome::collided) != (r.min_clearance < 0.0))) __builtin_trap();
  return 0;
}
