#pragma once
/// \file coords.hpp
/// Cell-centre coordinates: Shi et al. 2022 Eq. (1), corrected (the printed equation is wrong
/// under either numbering of i; see spec/grid.md r[grid.coord]).
/// Spec: grid.coord, shi2022.eq1 (the same function, indexed under both rules)
#include <cstdint>
#include <string_view>

#include "pathref/grid/grid.hpp"

namespace pathref::grid {

/// A point in map coordinates (cell units; the map spans [0, W] x [0, H]).
struct Point {
  double x = 0.0;
  double y = 0.0;
  friend constexpr bool operator==(const Point&, const Point&) = default;
};

/// Which reading of Shi Eq. (1) to evaluate. Only `corrected` is used by planners; the printed
/// forms exist so that code transcribing the paper literally can be compared.
enum class Eq1Form {
  corrected,  ///< x = (i mod W) + 0.5, y = floor(i / W) + 0.5 (the default)
  printed0,   ///< x = mod(i, W) + 0.5, y = ceil(i / W) - 0.5, with pathref's 0-based i
  printed1,   ///< the same printed formula with the 1-based sequence number k = i + 1
};

/// "corrected" | "printed0" | "printed1" -> form; UsageError on anything else. Spec: grid.coord.
[[nodiscard]] Eq1Form parse_eq1_form(std::string_view name);
[[nodiscard]] std::string_view to_string(Eq1Form form) noexcept;

/// Centre of the cell with 0-based index i on a W x H grid.
/// Source: Shi et al. 2022, Eq. (1), Sec. 3, doi:10.3389/fbioe.2022.905983 (N read as W).
/// Spec: grid.coord. Pre: width >= 1, height >= 1, width * height <= Grid::max_cells,
/// 0 <= i < width * height (DomainError).
/// Post (corrected): result == (x + 0.5, y + 0.5) for (x, y) = Grid::cell(i); all values exact.
/// Interpretation: `form` selects the printed (erroneous) readings, see Eq1Form.
/// Golden: golden/grid/grid.coord.json
[[nodiscard]] Point cell_centre(std::int64_t i, std::int64_t width, std::int64_t height,
                                Eq1Form form = Eq1Form::corrected);

/// Centre of cell c: (c.x + 0.5, c.y + 0.5) (grid.coord, corrected form, by cell).
/// Spec: grid.coord. Pre: |c.x|, |c.y| <= 2^51 so the result is exact (DomainError).
[[nodiscard]] Point cell_centre(Cell c);

}  // namespace pathref::grid
