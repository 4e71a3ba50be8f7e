#include "pathref/io/path_check.hpp"

#include <fmt/core.h>

#include <cmath>

#include "pathref/core/error.hpp"
#include "pathref/geometry/clearance.hpp"
#include "pathref/planners/search.hpp"

namespace pathref::io {

namespace {

std::string cell_text(grid::Cell c) { return fmt::format("({}, {})", c.x, c.y); }

/// Why step k failed, in words (spec/check.md#verdict).
std::string explain(const metrics::PathCheck& v, const std::vector<grid::Cell>& path, const grid::Grid& g,
                    grid::Cell start, grid::Cell goal, grid::CornerPolicy policy) {
  const auto k = static_cast<std::size_t>(v.index < 0 ? 0 : v.index);
  if (v.reason == "empty") return "the path has no node";
  if (v.reason == "start_mismatch")
    return fmt::format("the first node {} is not the start {}", cell_text(path[0]), cell_text(start));
  if (v.reason == "goal_mismatch")
    return fmt::format("the last node {} is not the goal {}", cell_text(path[k]), cell_text(goal));
  if (v.reason == "out_of_bounds")
    return fmt::format("node {} {} is outside the {}x{} map", k, cell_text(path[k]), g.width(), g.height());
  if (v.reason == "blocked") return fmt::format("node {} {} is a blocked cell", k, cell_text(path[k]));
  const grid::Cell a = path[k - 1], b = path[k];
  if (v.reason == "repeated") return fmt::format("node {} repeats node {} {}", k, k - 1, cell_text(a));
  if (v.reason == "not_adjacent")
    return fmt::format("step {} -> {} (node {} to {}) is not a step to one of the 8 neighbours", cell_text(a),
                       cell_text(b), k - 1, k);
  if (v.reason == "corner_cut") {
    std::string blocked;
    for (const grid::Cell c : {grid::Cell{b.x, a.y}, grid::Cell{a.x, b.y}})
      if (!g.free(c)) blocked += (blocked.empty() ? "" : " and ") + cell_text(c);
    return fmt::format("diagonal step {} -> {} (node {} to {}) is refused by policy {}{}", cell_text(a), cell_text(b),
                       k - 1, k, grid::to_string(policy),
                       policy == grid::CornerPolicy::never ? std::string(" (no diagonal step)")
                                                           : " (it passes blocked " + blocked + ")");
  }
  return v.reason;
}

nlohmann::json number_or_null(std::optional<double> v) {
  return v && std::isfinite(*v) ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

}  // namespace

std::optional<double> optimum_length(const grid::Grid& g, grid::Cell start, grid::Cell goal, grid::CornerPolicy policy) {
  if (!g.in_bounds(start) || !g.in_bounds(goal) || !g.free(start) || !g.free(goal)) return std::nullopt;
  const auto o = search::dijkstra(g, start, goal, policy);
  return o.found ? std::optional<double>(o.length) : std::nullopt;
}

PathReport check_path(const grid::Grid& g, const std::vector<grid::Cell>& path, grid::Cell start, grid::Cell goal,
                      grid::CornerPolicy policy, std::optional<double> optimum) {
  PathReport r;
  r.check = metrics::validate_path(g, path, start, goal, policy);
  r.message = r.check.valid ? std::string("ok") : explain(r.check, path, g, start, goal, policy);
  try {  // the metrics' path domain (spec/metrics.md): else null
    r.length = metrics::path_length(path);
    r.turns = metrics::turn_count(path);
  } catch (const DomainError&) {
  }
  if (r.check.valid) {
    std::vector<geometry::Vec2> centres;
    centres.reserve(path.size());
    for (const grid::Cell p : path)
      centres.push_back({static_cast<double>(p.x) + 0.5, static_cast<double>(p.y) + 0.5});
    r.clearance = geometry::clearance(g, centres).distance;
  }
  r.optimum = optimum;
  if (r.check.valid && r.length && optimum && *optimum > 0) r.ratio = *r.length / *optimum;
  return r;
}

nlohmann::json path_report_json(const PathReport& r, const std::vector<grid::Cell>& path) {
  using Json = nlohmann::json;
  const metrics::PathCheck& v = r.check;
  Json step = nullptr;
  if (!v.valid && v.index >= 1 && (v.reason == "repeated" || v.reason == "not_adjacent" || v.reason == "corner_cut")) {
    const grid::Cell a = path[static_cast<std::size_t>(v.index) - 1], b = path[static_cast<std::size_t>(v.index)];
    step = Json{{"from", {a.x, a.y}}, {"to", {b.x, b.y}}};
  }
  return Json{{"valid", v.valid},
              {"reason", v.reason},
              {"index", v.index},
              {"step", step},
              {"message", r.message},
              {"length", number_or_null(r.length)},
              {"turns", r.turns ? Json(*r.turns) : Json(nullptr)},
              {"optimum", number_or_null(r.optimum)},
              {"ratio", number_or_null(r.ratio)},
              {"clearance", number_or_null(r.clearance)}};
}

}  // namespace pathref::io
