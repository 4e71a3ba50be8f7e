#pragma once
/// \file cin2021.hpp
/// `pathref reproduce cin2021-hga-aco`: the HGA-ACO experiment of cin2021 §5.6
/// (doi:10.1155/2021/8025730): HGA-ACO against its own ACO and GA on three 20 x 20 grids with
/// rectangular obstacles (built as §5.6 describes them; Figure 10's layouts are lost), Table 3's
/// columns (path length, running time, iteration of the optimum) with spread and confidence
/// intervals, the paper's qualitative claims judged statistically, and the same three planners
/// (with Shi et al. 2022's hybrids beside them) on Shi's maps B and C. The document
/// (reproduce.json) is computed by run_cin2021; markdown and figures are pure functions of it.
/// Spec: spec/cin2021-hga-aco.md (reproduce.cin2021.maps, reproduce.cin2021.protocol)
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/grid/grid.hpp"
#include "pathref/reproduce/report.hpp"
#include "pathref/reproduce/shi2022.hpp"

namespace pathref::reproduce {

/// An axis-parallel rectangle of blocked cells, corners inclusive.
struct Rect {
  std::int64_t x0, y0, x1, y1;
};

/// One scenario of the protocol: a key ("s1"), a label, the grid, start and goal, and where the
/// map comes from.
struct CinScenario {
  std::string key;
  std::string label;
  std::string source;
  grid::Grid grid{1, 1};
  grid::Cell start;
  grid::Cell goal;
};

/// The three 20 x 20 scenarios of reproduce.cin2021.maps (rectangles listed in the spec), start
/// (0, 0), goal (19, 19). Spec: reproduce.cin2021.maps.
[[nodiscard]] std::vector<CinScenario> cin2021_scenarios();

/// A W x H grid with the rectangles blocked. Pre: every rectangle inside (DomainError).
[[nodiscard]] grid::Grid rect_grid(std::int64_t w, std::int64_t h, const std::vector<Rect>& rects);

struct CinConfig {
  std::optional<ProtocolMap> map_b;  ///< Shi's complex map (matlab-maps/mapB_20x20_ga.txt)
  std::optional<ProtocolMap> map_c;  ///< Shi's simple map (matlab-maps/mapC_20x20_winsleo_traditional.txt)
  std::int64_t runs = 20;            ///< runs per planner per map, seeds seed .. seed + runs - 1
  std::uint32_t seed = 1;
  bool quick = false;
  grid::CornerPolicy policy = grid::CornerPolicy::strict;
  Provenance provenance;
  Progress progress;
};

/// The planners of the protocol (hga-aco-cin, aco-cin, ga-cin) and, on Shi's maps only, Shi's
/// hybrids (iha, hybrid-ga-aco). Spec: reproduce.cin2021.protocol.
[[nodiscard]] const std::vector<std::string>& cin2021_planners();
[[nodiscard]] const std::vector<std::string>& cin2021_shi_planners();

/// Runs the protocol and returns reproduce.json. Spec: reproduce.cin2021.protocol.
/// Pre: runs in [2, 10000] (UsageError).
[[nodiscard]] Json run_cin2021(const CinConfig& config);

/// docs/reproduction/cin2021-hga-aco.md from the document.
[[nodiscard]] std::string cin2021_markdown(const Json& doc, const std::string& figure_dir,
                                           const std::string& json_name);

/// The SVG figures (file name, SVG text): per map the first run's paths (Figure 10) and the mean
/// best-so-far curves (Figure 11).
[[nodiscard]] std::vector<std::pair<std::string, std::string>> cin2021_figures(const Json& doc);

}  // namespace pathref::reproduce
