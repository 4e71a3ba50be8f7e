#pragma once
/// \file vec2.hpp
/// A point or vector of the plane in binary64: the one type every continuous-geometry function
/// of pathref uses (B-spline control points and samples, clearance, the simulations).
/// Map frame: x right, y up; on a grid with unit cells, cell (x, y) is the closed square
/// [x, x + 1] x [y, y + 1] with centre (x + 0.5, y + 0.5) (rule grid.coord).
/// Spec: spec/grid.md (grid.coord), spec/sensors2023.md (sensors2023.clearance)
namespace pathref::geometry {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;
  friend constexpr bool operator==(const Vec2&, const Vec2&) = default;
};

}  // namespace pathref::geometry
