#pragma once
/// \file segment_distance.hpp
/// Planar distances between points, segments and rays, written out on scalars in a pinned order
/// (bit-reproducible with -ffp-contract=off). Used by Han's collision test (Fig. 5,
/// han.collision.classify) and sensors2023's dynamic-window clearance (sensors2023.dwa.*).
/// Source: pathref. Spec: spec/han-sim.md (han.collision.classify).
#include "pathref/geometry/vec2.hpp"

namespace pathref::geometry {

/// Distance from p to the segment [a, b]: with d = b - a, L = (d.x*d.x) + (d.y*d.y); s = 0 if
/// L == 0, else s = clamp((((p.x - a.x)*d.x) + ((p.y - a.y)*d.y)) / L, 0, 1); q = (a.x + (s*d.x),
/// a.y + (s*d.y)); result sqrt(((p.x-q.x)*(p.x-q.x)) + ((p.y-q.y)*(p.y-q.y))).
/// Source: pathref. Spec: han.collision.classify. Pre: none (finite inputs give a finite result).
[[nodiscard]] double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) noexcept;

/// Distance from p to the ray from a through b (the obstacle's whole predicted future path): as
/// point_segment_distance but s is clamped to [0, +inf) only (b == a: the distance to a).
/// Source: pathref. Spec: han.collision.classify. Pre: none.
[[nodiscard]] double point_ray_distance(Vec2 p, Vec2 a, Vec2 b) noexcept;

/// Distance between segments [a, b] and [c, d]: 0 if they cross properly (the orientation signs
/// of c, d about ab differ strictly and those of a, b about cd too), else the minimum of
/// dist(a, cd), dist(b, cd), dist(c, ab), dist(d, ab) in that order.
/// Source: pathref. Spec: han.collision.classify.
[[nodiscard]] double segment_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 d) noexcept;

}  // namespace pathref::geometry
