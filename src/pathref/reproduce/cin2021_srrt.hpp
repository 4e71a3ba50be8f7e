#pragma once
/// \file cin2021_srrt.hpp
/// `pathref reproduce cin2021-srrt`: Cin et al. 2021 Sec. 4.3 (doi:10.1155/2021/8025730): a
/// 20 x 20 state space with black rectangles, delta = 1.7, P_g = 0.6, 3 scenarios x 20 runs, RRT
/// vs S-RRT (path length, path nodes, running time; Table 2 lost). The paper's scenes are lost:
/// the three scenes here are pathref's, rebuilt as the text describes (the report says so).
/// Declared CGAL-free; implemented in pathref_geometry (src/geometry_cgal/srrt_reproduce.cpp,
/// itself CGAL-free) because it needs the exact collision test of ObstacleMap.
/// Spec: spec/reproduce.md r[reproduce.cin2021-srrt.scenes], r[reproduce.cin2021-srrt.protocol]
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/continuous/kdtree.hpp"
#include "pathref/reproduce/report.hpp"

namespace pathref::reproduce {

/// One scene of the protocol: a pathref-scene 1 text and its world start and goal.
struct SrrtScene {
  std::string id;           ///< "A", "B", "C"
  std::string description;  ///< what it is
  std::string scene_json;   ///< pathref-scene 1 (r = 0: the paper's robot is a point in the state space)
  continuous::Vec2 start;   ///< the centre of the scene's start cell
  continuous::Vec2 goal;    ///< the centre of the scene's goal cell
};
/// The three scenes (pathref's construction). Spec: reproduce.cin2021-srrt.scenes.
[[nodiscard]] std::vector<SrrtScene> cin2021_srrt_scenes();

/// Options of one reproduction.
struct SrrtReproduceOptions {
  std::int64_t runs = 20;   ///< n per scene and series (the paper's 20); 2n are run
  std::uint32_t seed = 1;   ///< run i (0-based) uses seed + i, the same for every series
  Provenance provenance;
  Progress progress;
};

/// The reproduction: the document (reproduce.json), the figures and the scene files
/// (file name -> text, written beside reproduce.json).
struct SrrtReproduction {
  Json doc;
  std::vector<std::pair<std::string, std::string>> files;
};
/// Runs every series on every scene 2n times and judges the claims at n and 2n.
/// Spec: reproduce.cin2021-srrt.protocol. Pre: 2 <= runs <= 1000, seed + 2 runs - 1 < 2^32
/// (DomainError).
[[nodiscard]] SrrtReproduction reproduce_cin2021_srrt(const SrrtReproduceOptions& options);

/// The figures from the document: each scene's first S-RRT and RRT run (run again from its recorded
/// seed; the runs are deterministic) and the per-run charts (length, nodes, time) of the first n
/// runs. Used by the reproduction and by `reproduce cin2021-srrt --redraw`.
[[nodiscard]] std::vector<std::pair<std::string, std::string>> cin2021_srrt_figures(const Json& doc);

/// The markdown report from the document alone (`json_name`: the JSON's path relative to the
/// report, `figure_dir`: the figures' directory relative to it). Spec: reproduce.markdown.
[[nodiscard]] std::string cin2021_srrt_markdown(const Json& doc, const std::string& figure_dir,
                                                const std::string& json_name);

}  // namespace pathref::reproduce
