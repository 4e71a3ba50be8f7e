#pragma once
/// \file inflation.hpp
/// Exact obstacle inflation (Shi et al. 2022, Sec. 3 "Build map", doi:10.3389/fbioe.2022.905983:
/// "the obstacles are expanded ... The expanded size of the obstacles is the sum of the radius of
/// the intelligent vehicle and the safe reserved distance, so that the intelligent vehicle can be
/// regarded as a particle").
/// CGAL-free header. The functions are implemented with CGAL's exact kernel (Epeck) in the
/// separate library pathref_geometry (target pathref::geometry); link it to use them.
/// Spec: spec/inflation.md
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "pathref/geometry/scene.hpp"
#include "pathref/grid/grid.hpp"

namespace pathref::geometry {

/// Checks that every polygon of the scene is simple and non-degenerate: at least 3 vertices, no
/// two consecutive vertices equal (the last and first included), not all vertices collinear
/// (non-zero area), and no two edges meet except consecutive edges at their shared vertex.
/// Spec: inflation.cell-blocked (Domain). Throws DomainError naming the polygon as a JSON pointer
/// ("/polygons/3: ...") and the defect. Golden: golden/inflation/inflation.cell-blocked.json
void validate_polygons(const Scene& scene);

/// Sign of dist(C, P)^2 - r^2 for the closed square C of `cell` and the closed polygonal region P
/// = scene.polygons[polygon] (interior and boundary), r = radius + margin, computed exactly:
/// -1 (closer than r), 0 (exactly r: a tie), +1 (farther). Cells outside the grid are allowed.
/// Spec: inflation.cell-blocked. Pre: validate_polygons(scene) passes, polygon < size (DomainError).
[[nodiscard]] int compare_cell_distance(const Scene& scene, std::size_t polygon, grid::Cell cell);

/// The rule itself, by its definition: the cell's closed square is within distance r of some
/// obstacle polygon, i.e. meets the Minkowski sum of the polygon and the closed disc of radius
/// r (dist^2 <= r^2, exact). Brute force over every polygon and every edge pair.
/// Source: Shi et al. 2022 Sec. 3. Spec: inflation.cell-blocked. Pre: validate_polygons(scene).
[[nodiscard]] bool cell_blocked(const Scene& scene, grid::Cell cell);

/// The W x H grid (y up, (0,0) at the lower left, origin = the world's lower-left corner) whose
/// blocked cells are exactly those with cell_blocked(scene, c), computed per polygon over the
/// cells of its bounding box expanded by r only (same exact predicates, same result).
/// Source: Shi et al. 2022 Sec. 3. Spec: inflation.cell-blocked. Pre: validate_polygons(scene)
/// (checked; DomainError). Golden: golden/inflation/inflation.cell-blocked.json
[[nodiscard]] grid::Grid inflate_polygons(const Scene& scene);

/// Grid-level inflation for maps without polygons: cell c is blocked iff its closed square lies
/// within distance r of the closed square of some blocked cell of `map` (cells of size s), the
/// same exact closed-set rule: s^2 (gx^2 + gy^2) <= r^2 with gx = max(0, |dx| - 1),
/// gy = max(0, |dy| - 1). Note that r = 0 already blocks the 8 neighbours (touching squares).
/// Spec: inflation.grid. Pre: s > 0, r >= 0 (DomainError). Golden: golden/inflation/inflation.grid.json
[[nodiscard]] grid::Grid inflate_grid(const grid::Grid& map, const Decimal& cell_size, const Decimal& r);

/// A scene turned into a planning problem.
struct InflatedScene {
  grid::Grid grid;
  grid::Cell start;
  grid::Cell goal;
};

/// inflate_polygons, then the start/goal preconditions of spec/inflation.md: start and goal
/// given, inside the grid, not blocked, and distinct. Spec: inflation.scene.
/// Throws DomainError ("/start: ...", "/goal: ..."). Golden: golden/inflation/inflation.scene.json
[[nodiscard]] InflatedScene inflate_scene(const Scene& scene);

/// UsageError `FILE: the scene's WxH world (B bytes per cell...) needs an estimated N bytes ...,
/// more than the memory limit of L bytes ...` when width x height x bytes_per_cell exceeds
/// `max_memory` (spec/formats.md#limits, spec/cli.md#memory): called before the raster is
/// allocated by scene_map and by `pathref inflate`. bytes_per_cell 0 counts as 1 (the raster).
void require_raster_memory(const Scene& scene, const std::string& filename, std::uint64_t max_memory,
                           std::uint64_t bytes_per_cell);

/// inflate_scene with its DomainErrors prefixed by `filename: ` (the CLI's `inflate`). Spec: inflation.scene.
[[nodiscard]] InflatedScene inflate_scene_file(const Scene& scene, const std::string& filename);

/// Makes the inflation.* rules available to `pathref eval`, the golden runner and
/// `pathref golden regenerate` (adds them to the rule registry through
/// rules::add_extension_module). Idempotent; call before the first rules::registry().
void install_inflation_rules();

}  // namespace pathref::geometry
