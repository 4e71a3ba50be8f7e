#include "pathref/equations/heuristics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "pathref/core/error.hpp"

namespace pathref::heuristics {

// manhattan, chebyshev, octile, euclidean and evaluate are inline in the header.

Heuristic parse_heuristic(std::string_view name) {
  if (name == "zero") return Heuristic::zero;
  if (name == "manhattan") return Heuristic::manhattan;
  if (name == "chebyshev") return Heuristic::chebyshev;
  if (name == "octile") return Heuristic::octile;
  if (name == "euclidean") return Heuristic::euclidean;
  throw UsageError("unknown heuristic '" + std::string(name) +
                   "' (expected octile, chebyshev, euclidean, manhattan or zero)");
}

std::string_view to_string(Heuristic h) noexcept {
  switch (h) {
    case Heuristic::zero: return "zero";
    case Heuristic::manhattan: return "manhattan";
    case Heuristic::chebyshev: return "chebyshev";
    case Heuristic::octile: return "octile";
    case Heuristic::euclidean: return "euclidean";
  }
  return "octile";
}

bool admissible(Heuristic h, grid::CornerPolicy policy) noexcept {
  // Manhattan is the free-space 4-connected distance: a lower bound only without diagonals.
  return h != Heuristic::manhattan || policy == grid::CornerPolicy::never;
}

bool consistent(Heuristic h, grid::CornerPolicy policy) noexcept {
  // Every heuristic here is a metric d with d(n, n') <= c(n, n') on each allowed step, except
  // manhattan across a diagonal step (2 > sqrt2); see spec/search.md, search.admissible.
  return admissible(h, policy);
}

}  // namespace pathref::heuristics
