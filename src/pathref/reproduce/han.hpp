#pragma once
/// \file han.hpp
/// `pathref reproduce han`: Han (IJACSA) §IV on seeded random maps (han.maps.random): iterations to
/// converge, minimum path length and its standard deviation on 10 m maps, and path length and time
/// against the map edge (10 m to 100 m in 5 m steps), with pathref's numbers beside the paper's and a
/// verdict per claim. The markdown and the SVG charts are pure functions of the document.
/// Spec: spec/reproduce.md (reproduce.han.*)
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/grid/grid.hpp"
#include "pathref/reproduce/report.hpp"
#include "pathref/sim/simulate.hpp"

namespace pathref::reproduce {

struct HanConfig {
  std::vector<std::int64_t> edges;  ///< map edges in cells (= m); default 10, 15, ..., 100
  std::int64_t maps_per_edge = 3;   ///< K maps per edge, obstacle ratios evenly spaced in [0.2, 0.7]
  std::int64_t runs = 50;           ///< runs per planner on each 10 m map (Figures 10, 11)
  std::int64_t sweep_runs = 3;      ///< runs per planner on each map of the other edges (Figure 12)
  std::uint32_t seed = 1;
  bool quick = false;
  grid::CornerPolicy policy = grid::CornerPolicy::strict;
  Provenance provenance;
  Progress progress;
};

/// The protocol's edges 10, 15, ..., 100. Spec: reproduce.han.maps.
[[nodiscard]] std::vector<std::int64_t> han_protocol_edges();

/// Obstacle ratio of map k of K on an edge: 0.2 + 0.5 k / (K - 1), and 0.45 for K = 1.
/// Spec: reproduce.han.maps. Pre: 0 <= k < K, K >= 1 (DomainError).
[[nodiscard]] double han_ratio(std::int64_t k, std::int64_t maps_per_edge);

/// The planner variants of the protocol: (key, planner name, parameter overrides), in report
/// order. Spec: reproduce.han.protocol.
struct HanVariant {
  std::string key;
  std::string planner;
  nlohmann::json params;
  std::string label;
  std::vector<std::int64_t> only_edges;  ///< run only on maps of these edges; empty: every edge
};
[[nodiscard]] const std::vector<HanVariant>& han_variants();

/// The two scripted moving obstacles of a dynamic run (reproduce.han.dynamic) on the cell path
/// `path` (1 m cells), drawn from rng::Stream(seed) in this order: O1 (side) arc fraction
/// f1 = 0.2 + 0.6 u, side = +1 if u < 0.5 else -1, speed 0.25 + 0.75 u; O2 (frontal) fraction
/// f2 = 0.5 + 0.4 u, speed 0.25 + 0.75 u. O1 crosses the path at arc f1 L perpendicular to its piece
/// (normal side * (-d.y, d.x)), O2 comes towards the robot along the piece's direction d at arc
/// f2 L; each starts speed * T away from its point, T = sim::ramp_cruise_time(f L, 1, 1), so it
/// reaches the point when the robot would without obstacles. Radius 0.3 m.
/// Source: Han (IJACSA) Sec. IV ("two DO ... initial positions appear randomly"), Fig. 8; the
/// placement is pathref's. Spec: reproduce.han.dynamic. Pre: path.size() >= 2 (DomainError).
[[nodiscard]] std::vector<sim::MovingObstacle> han_dynamic_obstacles(const std::vector<grid::Cell>& path,
                                                                     std::uint32_t seed);

/// Runs the protocol and returns the reproduce.json document. Spec: reproduce.han.protocol.
/// Pre: edges non-empty, each in [2, 1000]; maps_per_edge in [1, 100]; runs, sweep_runs in
/// [1, 10000] (DomainError).
[[nodiscard]] nlohmann::json run_han(const HanConfig& config);

/// docs/reproduction/han.md from the document. Spec: reproduce.markdown.
[[nodiscard]] std::string han_markdown(const nlohmann::json& doc, const std::string& figure_dir,
                                       const std::string& json_name);

/// The SVG charts (file name, SVG text). Spec: reproduce.han.figures.
[[nodiscard]] std::vector<std::pair<std::string, std::string>> han_figures(const nlohmann::json& doc);

}  // namespace pathref::reproduce
