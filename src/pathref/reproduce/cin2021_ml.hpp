#pragma once
/// \file cin2021_ml.hpp
/// `pathref reproduce cin2021-ml`: cin2021 §3.3's two protocols (hold-out, Fig. 3; tenfold
/// cross-validation, Fig. 4) with pathref's five classifiers on the UCI 4-sensor data, each of the
/// paper's ten accuracies beside pathref's and scikit-learn's, under both readings of the split
/// (1636/3820 as stated, and swapped), and the evidence for which split the authors used.
/// Spec: spec/cin2021-ml.md#reproduction, spec/reproduce.md
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "pathref/reproduce/report.hpp"

namespace pathref::reproduce {

struct Cin2021MlConfig {
  std::string data_file;     ///< sensor_readings_4.data
  int seeds = 10;            ///< hold-out splits per reading
  std::uint32_t first_seed = 1;
  Json sklearn;              ///< tools/reproduce/cin2021_ml_sklearn.py output, or null
  Provenance provenance;
  Progress progress;
  bool quick = false;        ///< RF with 10 trees only, for a smoke test
};

/// Runs both protocols; returns the reproduce.json document (claims, results, evidence).
[[nodiscard]] Json run_cin2021_ml(const Cin2021MlConfig& cfg);
/// The markdown report, every number taken from `doc`.
[[nodiscard]] std::string cin2021_ml_markdown(const Json& doc, const std::string& json_name);
/// Figures like the paper's Figs. 3-4 (bar charts of the accuracies): (file name, SVG text).
[[nodiscard]] std::vector<std::pair<std::string, std::string>> cin2021_ml_figures(const Json& doc);

}  // namespace pathref::reproduce
