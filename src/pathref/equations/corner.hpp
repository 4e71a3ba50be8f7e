#pragma once
/// \file corner.hpp
/// The corner heuristic of Han (IJACSA): the turning cost T of a move (Eq. 3) and the corner
/// factor omega_ij it gives (Eq. 2), which multiplies an ant's transition weight as omega^gamma
/// (Eq. 1, aco::CornerFactor). Angles are decided in exact integer arithmetic on cell
/// coordinates; no trigonometry is involved, so T and omega are exact.
/// Spec: spec/han.md (han.eq2, han.eq3)
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "pathref/grid/grid.hpp"

namespace pathref::corner {

/// How Eq. (2) "omega_ij = omega_i T" and the theta of Eq. (3) are read together
/// (spec han.eq2, "Reading").
enum class OmegaForm {
  multiply,  ///< reading A (default): theta = heading change, omega = omega_i * T
  divide,    ///< reading B: theta = interior angle at the current cell, omega = omega_i / T
};
/// "multiply" | "divide" -> OmegaForm; UsageError otherwise. Spec: han.eq2.
[[nodiscard]] OmegaForm parse_omega_form(std::string_view name);

/// Which case of Eq. (3) owns theta = 90 degrees, printed in both.
enum class At90 {
  two,  ///< theta = 90 degrees gives T = 2 (default: the first printed case, closed at 90)
  one,  ///< theta = 90 degrees gives T = 1 (the second printed case, closed at 90)
};
/// "two" | "one" -> At90; UsageError otherwise. Spec: han.eq3.
[[nodiscard]] At90 parse_at90(std::string_view name);

/// Turning cost T of Eq. (3) for the move cur -> next of an ant that arrived at cur from prev.
/// With u = cur - prev, v = next - cur (integers): the heading change theta satisfies
/// theta <= 90 deg iff u.v >= 0, and the interior angle phi = 180 deg - theta satisfies
/// phi <= 90 deg iff u.v <= 0. T = 2 if the reading's angle is < 90 deg, or = 90 deg with
/// At90::two; T = 1 otherwise. First move (no prev): the ant goes "straight on" (theta = 0,
/// phi = 180 deg), i.e. T = 2 under multiply and T = 1 under divide; every candidate of the first
/// move gets the same T, so this choice cancels in Eq. (1) and Eq. (4).
/// Source: Han (IJACSA), Eq. (3) and Fig. 1, Sec. III.A.
/// Spec: han.eq3
/// Pre: prev != cur (when given), cur != next, |coordinates| <= 2^25 (DomainError).
/// Post: 1 or 2.
/// Interpretation: OmegaForm (which angle theta is; default multiply = heading change),
/// At90 (default two).
/// Golden: golden/han/han.eq3.json
[[nodiscard]] int turning_cost(std::optional<grid::Cell> prev, grid::Cell cur, grid::Cell next,
                               OmegaForm form = OmegaForm::multiply, At90 at90 = At90::two);

/// Corner heuristic omega_ij of Eq. (2): omega_i * T (multiply) or omega_i / T (divide), with T
/// from Eq. (3); both are exact in binary64 for T in {1, 2}.
/// Source: Han (IJACSA), Eq. (2), Sec. III.A: "omega_i is an adjustable parameter with a value
/// range of (0,1); T represents the turning cost".
/// Spec: han.eq2
/// Pre: 0 < omega_i < 1; T in {1, 2} (DomainError).
/// Post: omega in {omega_i, 2 omega_i} (multiply) or {omega_i / 2, omega_i} (divide); > 0.
/// Interpretation: OmegaForm (default multiply).
/// Golden: golden/han/han.eq2.json
[[nodiscard]] double corner_heuristic(double omega_i, int T, OmegaForm form = OmegaForm::multiply);

/// Eq. (2)-(3) for every allowed candidate of one move, in the caller's (canonical neighbour)
/// order: corner_heuristic(omega_i, turning_cost(prev, cur, candidate)). The result is the
/// `omega` of aco::CornerFactor for Eq. (1) and Eq. (4).
/// Source: Han (IJACSA), Eq. (1)-(3), Sec. III.A.
/// Spec: han.eq2
/// Pre: as turning_cost for each candidate and corner_heuristic (DomainError).
/// Post: one omega per candidate.
/// Golden: golden/han/han.eq2.json
[[nodiscard]] std::vector<double> corner_factors(std::optional<grid::Cell> prev, grid::Cell cur,
                                                 std::span<const grid::Cell> candidates,
                                                 double omega_i,
                                                 OmegaForm form = OmegaForm::multiply,
                                                 At90 at90 = At90::two);

}  // namespace pathref::corner
