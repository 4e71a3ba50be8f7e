#include "pathref/equations/corner.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "pathref/core/error.hpp"

namespace pathref::corner {

namespace {
constexpr std::int64_t coord_limit = std::int64_t{1} << 25;
bool coord_ok(grid::Cell c) {
  return std::abs(c.x) <= coord_limit && std::abs(c.y) <= coord_limit;
}
}  // namespace

OmegaForm parse_omega_form(std::string_view name) {
  if (name == "multiply") return OmegaForm::multiply;
  if (name == "divide") return OmegaForm::divide;
  throw UsageError("unknown Eq. 2 omega form '" + std::string(name) +
                   "' (expected multiply or divide)");
}

At90 parse_at90(std::string_view name) {
  if (name == "two") return At90::two;
  if (name == "one") return At90::one;
  throw UsageError("unknown Eq. 3 boundary '" + std::string(name) + "' (expected two or one)");
}

int turning_cost(std::optional<grid::Cell> prev, grid::Cell cur, grid::Cell next, OmegaForm form,
                 At90 at90) {
  require(coord_ok(cur) && coord_ok(next), "coordinates must satisfy |x|, |y| <= 2^25");
  require(!(cur == next), "a move needs next != cur");
  // dot = u.v with u = cur - prev, v = next - cur; the first move counts as straight on (dot > 0).
  std::int64_t dot = 1;
  if (prev) {
    require(coord_ok(*prev), "coordinates must satisfy |x|, |y| <= 2^25");
    require(!(*prev == cur), "the previous cell must differ from the current cell");
    dot = (cur.x - prev->x) * (next.x - cur.x) + (cur.y - prev->y) * (next.y - cur.y);
  }
  // The angle the reading uses: below 90 deg (sign s > 0), exactly 90 deg (s = 0), above (s < 0).
  const std::int64_t s = form == OmegaForm::multiply ? dot : -dot;
  if (s > 0) return 2;
  if (s == 0) return at90 == At90::two ? 2 : 1;
  return 1;
}

double corner_heuristic(double omega_i, int T, OmegaForm form) {
  require(std::isfinite(omega_i) && omega_i > 0.0 && omega_i < 1.0, "omega_i must lie in (0, 1)");
  require(T == 1 || T == 2, "the turning cost T must be 1 or 2");
  const double t = static_cast<double>(T);
  return form == OmegaForm::multiply ? omega_i * t : omega_i / t;
}

std::vector<double> corner_factors(std::optional<grid::Cell> prev, grid::Cell cur,
                                   std::span<const grid::Cell> candidates, double omega_i,
                                   OmegaForm form, At90 at90) {
  std::vector<double> omega;
  omega.reserve(candidates.size());
  for (const grid::Cell& next : candidates)
    omega.push_back(corner_heuristic(omega_i, turning_cost(prev, cur, next, form, at90), form));
  return omega;
}

}  // namespace pathref::corner
