#pragma once
/// \file data.hpp
/// The UCI Wall-Following Robot Navigation data (Freire et al. 2009, doi:10.24432/C57C8W) as
/// cin2021 §3 uses it: rows of simplified distances (2 or 4 columns) or the 24 raw ultrasound
/// readings, then a movement label. Labels are encoded as the paper preprocesses them:
/// Move-Forward = 0, Slight-Right-Turn = 1, Sharp-Right-Turn = 2, Slight-Left-Turn = 3.
/// Spec: spec/cin2021-ml.md#data (grammar, limits, every error).
#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace pathref::ml {

/// Number of movement classes of the wall-following task.
inline constexpr std::size_t wall_following_classes = 4;

/// The class names in label order (index = the paper's label value).
inline constexpr std::array<std::string_view, wall_following_classes> wall_following_labels = {
    "Move-Forward", "Slight-Right-Turn", "Sharp-Right-Turn", "Slight-Left-Turn"};

/// A labelled data set: `rows` samples of `features` doubles each, row-major, and one label in
/// [0, classes) per row.
struct Dataset {
  std::size_t features = 0;
  std::size_t classes = wall_following_classes;
  std::vector<double> x;    ///< rows * features values, row-major
  std::vector<int> y;       ///< rows labels
  [[nodiscard]] std::size_t rows() const noexcept { return y.size(); }
  [[nodiscard]] std::span<const double> row(std::size_t i) const noexcept {
    return {x.data() + i * features, features};
  }
};

// Reading the UCI text is io's (pathref/io/wall_following.hpp: io::parse_wall_following,
// io::read_wall_following, io::DataLimits; docs/architecture.md#layers). Before 0.3.0 they were
// declared here, in namespace ml.

/// The rows `indices` of `d`, in that order.
[[nodiscard]] Dataset subset(const Dataset& d, std::span<const std::size_t> indices);

}  // namespace pathref::ml
