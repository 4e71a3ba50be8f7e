#pragma once
/// \file shi2022.hpp
/// `pathref reproduce shi2022`: the simulation protocol of Shi et al. 2022 §5
/// (doi:10.3389/fbioe.2022.905983) on a simple and a complex 20x20 map, Tables 3-5 and
/// Figures 8-12, with pathref's numbers beside the paper's and a verdict per claim.
/// The document (reproduce.json) is computed by run_shi2022; the markdown and the SVG figures are
/// pure functions of that document. Spec: spec/reproduce.md (reproduce.shi2022.*)
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/grid/grid.hpp"
#include "pathref/reproduce/report.hpp"

namespace pathref::reproduce {

/// A map given to the protocol: its file (as given) and its grid as read (first file row on top).
struct ProtocolMap {
  std::string file;
  grid::Grid grid{1, 1};
};

/// How the matrix of a map file is placed on pathref's grid (reproduce.shi2022.maps).
enum class Orientation {
  paper,  ///< the file's first row at y = 0 (Shi's Figure 1A frame; MATLAB node n = cell index + 1)
  file,   ///< as spec/formats.md reads it: the file's first row at the top, y = H - 1
};
/// "paper" | "file" -> Orientation; UsageError otherwise.
[[nodiscard]] Orientation parse_orientation(std::string_view name);
[[nodiscard]] std::string_view to_string(Orientation o) noexcept;

/// The grid of `file_grid` (as read, first file row on top) placed in `o`: for paper, flipped
/// top to bottom (y -> H - 1 - y). Spec: reproduce.shi2022.maps.
[[nodiscard]] grid::Grid oriented(const grid::Grid& file_grid, Orientation o);

struct ShiConfig {
  ProtocolMap simple;
  ProtocolMap complex;
  std::int64_t runs = 50;      ///< runs per planner per map, seeds seed .. seed + runs - 1
  std::uint32_t seed = 1;
  bool quick = false;          ///< reproduce.quick overrides
  grid::CornerPolicy policy = grid::CornerPolicy::strict;
  Orientation orientation = Orientation::paper;
  Provenance provenance;
  Progress progress;
};

/// The planners of the protocol, in report order. Spec: reproduce.shi2022.protocol.
[[nodiscard]] const std::vector<std::string>& shi2022_planners();

/// A spec reading that changes the outcome (spec reproduce.shi2022.readings): the planners it
/// concerns are run a second time with `params`; their results are stored under
/// "PLANNER@KEY" and the claims that read them are judged again with `suffix` on their ids.
struct ShiReading {
  std::string key;                    ///< "shift": results key suffix, "ga@shift"
  std::string suffix;                 ///< claim id suffix, "s": "T4.1s"
  std::string label;                  ///< the reading in words, for the report
  std::vector<std::string> planners;  ///< the planners run under it, in report order
  Json params;                        ///< the --set overrides that select it
};

/// The readings of reproduce.shi2022.readings, in report order.
[[nodiscard]] const std::vector<ShiReading>& shi2022_readings();

/// The endpoints of the MATLAB scripts on a W x H map: start = the first cell of the file's first
/// row, goal = the last cell of its last row: (0, 0) and (W-1, H-1) in the paper orientation,
/// (0, H-1) and (W-1, 0) in the file orientation. Spec: reproduce.shi2022.maps.
[[nodiscard]] std::pair<grid::Cell, grid::Cell> shi2022_endpoints(const grid::Grid& g, Orientation o);

/// Runs the whole protocol and returns the reproduce.json document. UsageError when an endpoint
/// is blocked; planners not registered are recorded as unavailable (never an error).
/// Spec: reproduce.shi2022.protocol. Pre: runs in [1, 10000].
[[nodiscard]] Json run_shi2022(const ShiConfig& config);

/// docs/reproduction/shi2022.md from the document. Spec: reproduce.markdown.
[[nodiscard]] std::string shi2022_markdown(const Json& doc, const std::string& figure_dir,
                                           const std::string& json_name);

/// The SVG figures (file name, SVG text) from the document. Spec: reproduce.shi2022.figures.
[[nodiscard]] std::vector<std::pair<std::string, std::string>> shi2022_figures(const Json& doc);

}  // namespace pathref::reproduce
