#pragma once
/// \file metrics.hpp
/// Path metrics as pure functions: length, turning angles, number of turns, OMPL smoothness,
/// safety counts (Shi Eq. 18's S_i), iterations to converge, and the path validator.
/// A path is a sequence of cells read as the polyline through the cell centres; it need not be
/// a chain of 8-neighbours. The "path domain" of spec/metrics.md: non-empty, no two consecutive
/// cells equal, |x|, |y| <= 2^25 (DomainError otherwise).
/// Spec: spec/metrics.md
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "pathref/grid/grid.hpp"

namespace pathref::metrics {

/// Largest |coordinate| in the path domain: 2^25, so squared differences sum exactly.
inline constexpr std::int64_t max_abs_coordinate = std::int64_t{1} << 25;

/// Euclidean distance between the centres of a and b: sqrt(dx^2 + dy^2), correctly rounded
/// (dx, dy exact integers). Source: Shi et al. 2022 Eq. (4), doi:10.3389/fbioe.2022.905983.
/// Spec: metrics.length, shi2022.eq4. Pre: |coordinates| <= 2^25 (DomainError). Post: >= 0; 0 iff a == b.
[[nodiscard]] double centre_distance(grid::Cell a, grid::Cell b);

/// Path length: sum of centre distances of consecutive cells, left to right.
/// Source: Shi et al. 2022 Eq. (4), (15); cin2021 Eq. (19). Spec: metrics.length, cin2021.eq19. Pre: the path domain.
/// Post: >= 0; == 0 iff one cell; for 8-neighbour chains == sum of grid::step_cost.
/// Golden: golden/metrics/metrics.length.json
[[nodiscard]] double path_length(std::span<const grid::Cell> path);

/// Turning angle at b for the polyline a -> b -> c: atan2(|u x v|, u . v), u = b - a, v = c - b.
/// Source: Shi et al. 2022 Eq. (17) (theta, the turn angle; exterior angle).
/// Spec: metrics.turn-angle. Pre: a != b, b != c, |coordinates| <= 2^25 (DomainError).
/// Post: in [0, pi]; 0 straight on, pi reversal.
[[nodiscard]] double turning_angle(grid::Cell a, grid::Cell b, grid::Cell c);

/// The turning angle (radians) at each interior node, in path order (n - 2 values; none for
/// n <= 2). Source: Shi et al. 2022 Eq. (17). Spec: metrics.turn-angle, shi2022.eq17. Pre: the path domain.
/// Post: every value in [0, pi]. Golden: golden/metrics/metrics.turn-angle.json
[[nodiscard]] std::vector<double> turning_angles(std::span<const grid::Cell> path);

/// Number of interior nodes where the direction changes (exact integer test: not
/// (cross == 0 and dot > 0)). A reversal is a turn; collinear same-direction segments are not.
/// Source: Shi et al. 2022 Tables 3-5 ("number of turns"). Spec: metrics.turns.
/// Pre: the path domain. Post: in [0, max(0, n - 2)]. Golden: golden/metrics/metrics.turns.json
[[nodiscard]] std::int64_t turn_count(std::span<const grid::Cell> path);

/// How the turning angle inside OMPL's smoothness is evaluated (spec metrics.smoothness).
enum class SmoothnessForm {
  ompl,   ///< OMPL's law-of-cosines evaluation and its guard -1 < q < 1 (U-turn adds 0); default
  angle,  ///< the exact turning angle of metrics.turn-angle (U-turn adds (2 pi / (a + b))^2)
};
/// "ompl" | "angle" -> form; UsageError otherwise. Spec: metrics.smoothness.
[[nodiscard]] SmoothnessForm parse_smoothness_form(std::string_view name);

/// OMPL's path smoothness: sum over interior nodes of (2 phi / (a + b))^2, a and b the segment
/// lengths at the node and phi its turning angle; 0 for a straight path, smaller is smoother.
/// Source: OMPL ompl::geometric::PathGeometric::smoothness() (Sucan, Moll, Kavraki 2012,
/// doi:10.1109/MRA.2012.2205651). Spec: metrics.smoothness. Pre: the path domain.
/// Post: >= 0; 0 for n <= 2. Interpretation: `form` (default ompl), see SmoothnessForm.
/// Golden: golden/metrics/metrics.smoothness.json
[[nodiscard]] double smoothness_ompl(std::span<const grid::Cell> path);
/// As above with an explicit form. Spec: metrics.smoothness.
[[nodiscard]] double smoothness_ompl(std::span<const grid::Cell> path, SmoothnessForm form);

/// How cells outside the map count in safety_counts (spec metrics.safety).
enum class OutsideCells {
  free,     ///< not counted (default: Shi counts obstacle grids of the map)
  blocked,  ///< counted as obstacles (the border is a wall)
};
/// "free" | "blocked" -> OutsideCells; UsageError otherwise. Spec: metrics.safety.
[[nodiscard]] OutsideCells parse_outside_cells(std::string_view name);

/// For each node, the number of blocked cells among its 8 neighbours (the node itself not
/// counted); cells outside the map count as free.
/// Source: Shi et al. 2022 Eq. (18) and text (S_i, obstacles in the eight neighbourhoods).
/// Spec: metrics.safety. Pre: path non-empty, no consecutive repeats, every node in bounds
/// (DomainError). Post: one value per node, each in [0, 8].
/// Golden: golden/metrics/metrics.safety.json
[[nodiscard]] std::vector<std::int64_t> safety_counts(const grid::Grid& g,
                                                      std::span<const grid::Cell> path);
/// As above with an explicit reading of outside cells. Spec: metrics.safety.
[[nodiscard]] std::vector<std::int64_t> safety_counts(const grid::Grid& g,
                                                      std::span<const grid::Cell> path,
                                                      OutsideCells outside);

/// Result of validate_path: valid, a stable reason code, and the 0-based failing node index
/// (-1 when none). Reasons: ok, empty, start_mismatch, out_of_bounds, blocked, repeated,
/// not_adjacent, corner_cut, goal_mismatch.
struct PathCheck {
  bool valid;
  std::string reason;
  std::int64_t index;
};

/// Checks that `path` is a legal plan: starts at start, ends at goal, every node in bounds and
/// free, every step an allowed move under `policy`; reports the FIRST failure in the order of
/// spec metrics.valid-path. Source: pathref (Shi et al. 2022 Sec. 3 moves).
/// Spec: metrics.valid-path, cin2021.eq16 (safety: S = p_1, G = p_n). Pre: none (never throws for any input).
/// Post: valid == (reason == "ok"). Golden: golden/metrics/metrics.valid-path.json
[[nodiscard]] PathCheck validate_path(const grid::Grid& g, std::span<const grid::Cell> path,
                                      grid::Cell start, grid::Cell goal, grid::CornerPolicy policy);

/// Whether smaller (path length) or larger (fitness) values are better.
enum class Sense {
  minimise,  ///< "min" (default)
  maximise,  ///< "max"
};
/// "min" | "max" -> Sense; UsageError otherwise. Spec: metrics.converge.
[[nodiscard]] Sense parse_sense(std::string_view name);

/// The first iteration (1-based) whose best-so-far equals the final best, i.e. the first t with
/// v_t == min_s v_s (exact equality: the best is one of the values).
/// Source: Shi et al. 2022 Sec. 5, Tables 3-4 (iterations counted from 1).
/// Spec: metrics.converge. Pre: non-empty; no NaN; no -inf; some finite value (+inf = "no path
/// in this iteration") (DomainError). Post: 1 <= t <= size; v_t == final best.
/// Golden: golden/metrics/metrics.converge.json
[[nodiscard]] std::int64_t iterations_to_converge(std::span<const double> best_per_iteration);
/// As above with an explicit sense (maximise: roles of +inf and -inf swap). Spec: metrics.converge.
[[nodiscard]] std::int64_t iterations_to_converge(std::span<const double> best_per_iteration,
                                                  Sense sense);

}  // namespace pathref::metrics
