#include "pathref/grid/coords.hpp"

#include <string>

#include "pathref/core/error.hpp"

namespace pathref::grid {

Eq1Form parse_eq1_form(std::string_view name) {
  if (name == "corrected") return Eq1Form::corrected;
  if (name == "printed0") return Eq1Form::printed0;
  if (name == "printed1") return Eq1Form::printed1;
  throw UsageError("unknown Eq. 1 form '" + std::string(name) +
                   "' (expected corrected, printed0 or printed1)");
}

std::string_view to_string(Eq1Form form) noexcept {
  switch (form) {
    case Eq1Form::corrected: return "corrected";
    case Eq1Form::printed0: return "printed0";
    case Eq1Form::printed1: return "printed1";
  }
  return "corrected";
}

namespace {
/// ceil(k / n) for k >= 0, n >= 1, in integer arithmetic.
std::int64_t ceil_div(std::int64_t k, std::int64_t n) { return (k + n - 1) / n; }
}  // namespace

Point cell_centre(std::int64_t i, std::int64_t width, std::int64_t height, Eq1Form form) {
  require(width >= 1 && height >= 1, "grid width and height must be at least 1");
  require(width <= Grid::max_cells / height, "grid has more cells than Grid::max_cells");
  require(i >= 0 && i < width * height, "cell index outside [0, W*H)");
  // Every integer below is < 2^29, so the conversions and the + 0.5 are exact.
  switch (form) {
    case Eq1Form::corrected:
      return Point{static_cast<double>(i % width) + 0.5, static_cast<double>(i / width) + 0.5};
    case Eq1Form::printed0:
      return Point{static_cast<double>(i % width) + 0.5,
                   static_cast<double>(ceil_div(i, width)) - 0.5};
    case Eq1Form::printed1: {
      const std::int64_t k = i + 1;
      return Point{static_cast<double>(k % width) + 0.5,
                   static_cast<double>(ceil_div(k, width)) - 0.5};
    }
  }
  throw UsageError("unknown Eq. 1 form");
}

Point cell_centre(Cell c) {
  constexpr std::int64_t limit = std::int64_t{1} << 51;
  require(c.x >= -limit && c.x <= limit && c.y >= -limit && c.y <= limit,
          "cell coordinates beyond 2^51 have no exact centre");
  return Point{static_cast<double>(c.x) + 0.5, static_cast<double>(c.y) + 0.5};
}

}  // namespace pathref::grid
