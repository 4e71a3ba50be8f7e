#pragma once
/// \file generators.hpp
/// Shared test generators (RapidCheck) and a seeded random-grid builder for unit tests.
/// Include as `#include "support/generators.hpp"`.
/// Spec: spec/grid.md (grid model, corner policies); random_grid uses spec rule rng.bernoulli.
#include <rapidcheck.h>

#include <cstdint>
#include <ostream>
#include <vector>

#include "pathref/grid/grid.hpp"

namespace pathref::grid {
// RapidCheck prints counterexamples through showValue (found by ADL).
/// Cell as "(x, y)".
void showValue(const Cell& c, std::ostream& os);
/// Policy by its name ("never", "strict", "one", "always").
void showValue(CornerPolicy p, std::ostream& os);
/// Grid as "WxH" followed by its rows top first ('.' free, '#' blocked), one per line.
void showValue(const Grid& g, std::ostream& os);
}  // namespace pathref::grid

namespace pathref::testing {

/// A grid of width in [1, max_w] and height in [1, max_h]. A blocked fraction p is drawn in
/// [0, max_blocked_fraction] (steps of 1/1000); each cell is then blocked with probability ~p.
/// Shrinks towards smaller grids and free cells. Pre: max_w >= 1, max_h >= 1,
/// 0 <= max_blocked_fraction <= 1 (DomainError).
[[nodiscard]] rc::Gen<grid::Grid> gen_grid(int max_w, int max_h, double max_blocked_fraction);

/// One of the four corner policies (never, strict, one, always); shrinks towards `never`.
[[nodiscard]] rc::Gen<grid::CornerPolicy> gen_policy();

/// A random walk on `g` under `policy`: a start drawn among the free cells, then up to
/// `max_steps` steps, each to a neighbour drawn from grid::neighbours (so every step is allowed);
/// the walk stops early at a cell without neighbours. Walks may reverse and revisit cells.
/// Returns an empty path when `g` has no free cell. Pre: max_steps >= 0 (DomainError).
[[nodiscard]] rc::Gen<std::vector<grid::Cell>> gen_walk(const grid::Grid& g,
                                                        grid::CornerPolicy policy, int max_steps);

/// A w x h grid whose cell i (increasing cell index i = y*w + x) is blocked iff
/// rng::bernoulli(u_i, blocked_fraction), u_i being the (i+1)-th double of rng::Stream(seed):
/// exactly one draw per cell. Pre: w >= 1, h >= 1, 0 <= blocked_fraction <= 1 (DomainError).
[[nodiscard]] grid::Grid random_grid(std::uint32_t seed, int w, int h, double blocked_fraction);

}  // namespace pathref::testing
