#pragma once
/// \file curves_rules.hpp
/// JSON helpers for rules on plane points (geometry::Vec2 as [x, y]), shared by the adapters of
/// curves.*, sensors2023.* and later continuous planners. Spec: spec/curves.md
#include <span>
#include <vector>

#include "pathref/geometry/vec2.hpp"
#include "pathref/rules/registry.hpp"

namespace pathref::rules {
/// [x, y] -> point; UsageError naming `what` otherwise.
[[nodiscard]] geometry::Vec2 point_from_json(const Json& v, const char* what);
/// input[key] as an array of [x, y]; UsageError otherwise.
[[nodiscard]] std::vector<geometry::Vec2> points_arg(const Json& input, const char* key);
[[nodiscard]] Json point_json(geometry::Vec2 p);
[[nodiscard]] Json points_json(std::span<const geometry::Vec2> pts);
}  // namespace pathref::rules
