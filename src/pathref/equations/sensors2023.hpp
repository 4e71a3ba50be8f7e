#pragma once
/// \file sensors2023.hpp
/// The global planner's equations of Sensors 2023, 23(8), 4102 ("Dynamic Path Planning of AGV
/// Based on Kinematical Constraint A* Algorithm and Following DWA Fusion Algorithms"),
/// doi:10.3390/s23084102, §2.1–2.3: the goal bearing and the five child directions (Eq. 1,
/// Table 1), the Euclidean heuristic and the (weighted) evaluation function (Eq. 2–4), and the
/// equal-division safety test of the secondary redundancy removal (Eq. 5), with the collision
/// test of the ordinary removal and the greedy removal driver. The B-spline (Eq. 6–8, A1–A3) is
/// the project's B-spline module (bspline.hpp). Every equation was lost in extraction and is
/// reconstructed (../shared/papers/equations-004-astar-dwa.md).
/// Spec: spec/sensors2023.md
#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "pathref/grid/grid.hpp"

namespace pathref::sensors2023 {

/// Eq. (1): the bearing of the goal from n, in degrees clockwise from +Y, in [0, 360):
/// fmod((180 / pi) * atan2(x_g - x_n, y_g - y_n) + 360, 360), evaluated as written with
/// 180 / pi = 57.29577951308232 (the double nearest), atan2 of the exact integer differences.
/// Source: Sensors 2023 Eq. (1), §2.1 ("angle with Y circumference"). Spec: sensors2023.eq1.
/// Pre: n != goal; |coordinates| < 2^30 (DomainError). Post: in [0, 360).
/// Golden: golden/sensors2023/sensors2023.eq1.json
[[nodiscard]] double goal_bearing(grid::Cell n, grid::Cell goal);

/// Table 1: the row (sector) s in 0..7 of a bearing: s = 0 for [337.5, 360) and [0, 22.5),
/// else the s with 22.5 + 45 (s - 1) <= theta < 22.5 + 45 s; decided by exact comparisons with
/// the representable boundaries 22.5 + 45 j (half-open intervals [a, b)).
/// Source: Sensors 2023 Table 1. Spec: sensors2023.eq1.
/// Pre: 0 <= theta < 360 (DomainError). Golden: golden/sensors2023/sensors2023.eq1.json
[[nodiscard]] int bearing_sector(double theta_degrees);

/// The 5 kept directions of a sector, as bearings in degrees ascending: the 5 within +-90 degrees
/// of the centre c = 45 s (000T .. 315T); the 3 abandoned are c + 135, c + 180, c + 225.
/// Source: Sensors 2023 Table 1. Spec: sensors2023.eq1. Pre: 0 <= s <= 7 (DomainError).
[[nodiscard]] std::array<int, 5> kept_bearings(int sector);
[[nodiscard]] std::array<int, 3> abandoned_bearings(int sector);

/// The move (dx, dy) of a direction bearing: 0 -> (0, 1), 45 -> (1, 1), 90 -> (1, 0), ...,
/// 315 -> (-1, 1). Spec: sensors2023.eq1. Pre: bearing in {0, 45, ..., 315} (DomainError).
[[nodiscard]] grid::Cell bearing_move(int bearing);

/// The bitmask of moves (bit k = the k-th move of grid.neighbour-order, as
/// search::ExpansionRule) of a set of bearings. Spec: sensors2023.eq1.
[[nodiscard]] std::uint8_t bearing_mask(std::span<const int> bearings);

/// True iff no cell within Chebyshev distance `radius` of n (n excluded) is blocked; cells
/// outside the map are not obstacles (their moves are simply not possible).
/// Source: Sensors 2023 §2.1 ("with the node as the center, there is no obstacle to this
/// region"); the region's size is not given: radius 1 (the 8-neighbourhood) by default.
/// Spec: sensors2023.eq1. Pre: g.in_bounds(n), 1 <= radius <= 64 (DomainError).
[[nodiscard]] bool neighbourhood_free(const grid::Grid& g, grid::Cell n, int radius);

/// The moves the kinematic A* generates from n: all 8 if n == goal or the neighbourhood of
/// `radius` holds an obstacle, else the 5 kept directions of the goal's sector (Eq. 1, Table 1).
/// Source: Sensors 2023 Eq. (1), Table 1, §2.1. Spec: sensors2023.eq1.
/// Pre: as neighbourhood_free. Post: 8 bits or the 5 bits of kept_bearings(sector).
/// Golden: golden/sensors2023/sensors2023.eq1.json
[[nodiscard]] std::uint8_t child_moves(const grid::Grid& g, grid::Cell n, grid::Cell goal,
                                       int radius);

/// Eq. (3): the basic evaluation function f = fl(g + h). Source: Sensors 2023 Eq. (3).
/// Spec: sensors2023.eq3. Pre: g, h finite and >= 0 (DomainError).
/// Golden: golden/sensors2023/sensors2023.eq3.json
[[nodiscard]] double f_basic(double g, double h);

/// How the weight of h in Eq. (4) is formed.
enum class WeightForm {
  linear,  ///< w = 1 + r / R (the default; the common form in this literature)
  exp,     ///< w = e^{r / R}
  none,    ///< w = 1: Eq. (3), the plain A* of the ablation
};
/// "linear" | "exp" | "none" -> form; UsageError otherwise. Spec: sensors2023.eq4.
[[nodiscard]] WeightForm parse_weight_form(std::string_view name);
[[nodiscard]] std::string_view to_string(WeightForm w) noexcept;

/// The weight of h in Eq. (4): linear fl(1 + fl(r / R)), exp std::exp(fl(r / R)), none 1; with
/// R = 0 (start == goal) the weight is 1.
/// Source: Sensors 2023 Eq. (4), §2.2 ("increase the ratio of h(n) in f(n)"). Spec: sensors2023.eq4.
/// Pre: r, R finite and >= 0 (DomainError).
[[nodiscard]] double heuristic_weight(double r, double R, WeightForm form);

/// Eq. (4): f = fl(g + fl(w * h)) with w = heuristic_weight(r, R, form).
/// Source: Sensors 2023 Eq. (4). Spec: sensors2023.eq4.
/// Pre: g, h, r, R finite and >= 0 (DomainError). Golden: golden/sensors2023/sensors2023.eq4.json
[[nodiscard]] double f_weighted(double g, double h, double r, double R, WeightForm form);

/// Whether the segment between the centres of a and b meets the interior of a blocked cell
/// (the collision test of the ordinary redundancy removal). Exact: in doubled integer
/// coordinates, a cell's open square and the closed segment are disjoint iff the x ranges, the
/// y ranges or the segment's line separate them (every corner on one closed side).
/// Touching a cell's corner or edge is not a collision -- which is why the ordinary removal can
/// leave paths "tangent to the vertices of the obstacles" (§2.3).
/// Source: Sensors 2023 §2.3 (ordinary removal "with collision detection"). Spec: sensors2023.eq5.
/// a == b: whether a is blocked (its centre lies in its open square).
/// Pre: a, b in bounds (DomainError).
[[nodiscard]] bool segment_blocked(const grid::Grid& g, grid::Cell a, grid::Cell b);

/// The strictness of the safety test of Eq. (5).
enum class SafetyCompare {
  ge,  ///< every distance >= d_s passes (default)
  gt,  ///< every distance > d_s passes (the text's "greater than", literally)
};
[[nodiscard]] SafetyCompare parse_safety_compare(std::string_view name);
[[nodiscard]] std::string_view to_string(SafetyCompare c) noexcept;

/// What the equal-division test found.
struct SafetyCheck {
  bool safe = true;            ///< every division point keeps the safety distance
  std::int64_t divisions = 0;  ///< N = ceil(k ||b - a||)
};

/// Eq. (5): N = ceil(fl(k * ||b - a||)), Q_m = a + fl(m / N) (b - a) (each coordinate
/// fl(a + fl(t * d))), m = 0 .. N, in cell coordinates (centres differ by (1/2, 1/2), which
/// cancels); the shortcut a -> b is safe iff for every m and every blocked cell o,
/// sqrt((Q_m,x - o_x)^2 + (Q_m,y - o_y)^2) >= d_s (ge) or > d_s (gt).
/// Source: Sensors 2023 Eq. (5), §2.3 (the safety distance is one grid edge). Spec: sensors2023.eq5.
/// Pre: a != b in bounds; 1 <= k <= 1024; d_s finite and >= 0 (DomainError).
/// Golden: golden/sensors2023/sensors2023.eq5.json
[[nodiscard]] SafetyCheck safety_test(const grid::Grid& g, grid::Cell a, grid::Cell b, int k,
                                      double ds, SafetyCompare compare);

/// The greedy redundancy removal of §2.3: anchor a = the first node; the candidate b runs from
/// the last node back towards a and the first b for which `allowed(a, b)` is true (the
/// shortcut is allowed) -- or the node right after a, always -- is kept and becomes the anchor;
/// until the last node is kept. Returns the kept nodes, first and last included.
/// Source: Sensors 2023 §2.3. Spec: sensors2023.plan.astar-kinematic (redundancy removal).
/// Pre: path non-empty (DomainError).
template <class Allowed>
[[nodiscard]] std::vector<grid::Cell> greedy_removal(std::span<const grid::Cell> path,
                                                     Allowed allowed);

}  // namespace pathref::sensors2023

// ---- template definition ----
#include "pathref/core/error.hpp"

namespace pathref::sensors2023 {
template <class Allowed>
std::vector<grid::Cell> greedy_removal(std::span<const grid::Cell> path, Allowed allowed) {
  require(!path.empty(), "greedy_removal: empty path");
  std::vector<grid::Cell> kept{path.front()};
  std::size_t a = 0;
  const std::size_t last = path.size() - 1;
  while (a < last) {
    std::size_t b = last;
    while (b > a + 1 && !allowed(path[a], path[b])) --b;
    kept.push_back(path[b]);
    a = b;
  }
  return kept;
}
}  // namespace pathref::sensors2023
