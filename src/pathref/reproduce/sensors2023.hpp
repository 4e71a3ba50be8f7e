#pragma once
/// \file sensors2023.hpp
/// `pathref reproduce sensors2023`: the fused A* + following DWA of Sensors 2023, 23(8), 4102
/// (doi:10.3390/s23084102) on the paper's scenes as far as its text fixes them (a hand-built
/// 21 x 21 map: the lost maps are rebuilt, not recovered) and on seeded random maps of the same
/// size and density; Table 2 (as ratios), Table 3, Table 4's feature claims as properties, the
/// ablations, with pathref's number beside the paper's and a verdict per claim.
/// Spec: spec/sensors2023-dwa.md (section "Reproduction")
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/grid/grid.hpp"
#include "pathref/reproduce/report.hpp"
#include "pathref/sim/fused.hpp"

namespace pathref::reproduce {

struct Sensors2023Config {
  std::int64_t maps = 30;  ///< n: the claims are judged on n random maps and on all 2n
  std::uint32_t seed = 1;  ///< first random-map seed (unconnected maps skipped); also the bootstrap seed
  bool quick = false;
  Provenance provenance;
  Progress progress;
};

/// The hand-built 21 x 21 scene (rows, top first): the paper's maps are lost; this one is built so
/// that the text's coordinates are free and meaningful (start (4, 3), goal (17, 16), the moving
/// obstacle's end (9, 4) and the temporary obstacle (14, 15) near the global path).
/// Spec: sensors2023-dwa.md#reproduction.
[[nodiscard]] const std::vector<std::string>& sensors2023_scene_rows();

/// A random E x E map with floor(density E^2) blocked cells, start and goal and their
/// 8-neighbourhoods kept free: cells drawn by partial Fisher-Yates over the other cells in index
/// order with rng::Stream(seed) (rng.index); used only if astar finds a path (the caller tries
/// the next seed otherwise). Spec: sensors2023-dwa.md#reproduction. Pre: 5 <= E <= 200, density in
/// [0, 0.6], start and goal in the map (DomainError).
[[nodiscard]] grid::Grid sensors2023_random_map(std::uint32_t seed, std::int64_t edge, double density,
                                                grid::Cell start, grid::Cell goal);

/// The number `object[key]` of a result document, for the claims (spec sensors2023-dwa.md
/// "Reproduction": a claim is never judged on a guessed value). `where` names the object in the
/// message. Throws DomainError("reproduce sensors2023: <where>.<key> is missing" / "... is not a
/// number (got <json>)") when `object` is not an object, lacks `key` or holds no number there.
[[nodiscard]] double sensors2023_required_number(const nlohmann::json& object, const std::string& where,
                                                 const std::string& key);

/// Runs the protocol and returns the reproduce.json document: the scene, the global planner's
/// claims, 2n random maps simulated on reproduce::current_execution().jobs threads (results do not
/// depend on the thread count), the claims judged at n and 2n maps with the statistics of
/// spec/stats.md (paired bootstrap over maps). Spec: sensors2023-dwa.md#reproduction.
/// Pre: 1 <= maps <= 10000 and astar-kinematic registered (DomainError).
[[nodiscard]] nlohmann::json run_sensors2023(const Sensors2023Config& config);

/// docs/reproduction/sensors2023.md from the document.
[[nodiscard]] std::string sensors2023_markdown(const nlohmann::json& doc, const std::string& figure_dir,
                                               const std::string& json_name);

/// The figures (file name, SVG text): the scene runs.
[[nodiscard]] std::vector<std::pair<std::string, std::string>> sensors2023_figures(const nlohmann::json& doc);

}  // namespace pathref::reproduce
