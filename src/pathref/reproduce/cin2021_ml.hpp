#pragma once
/// \file cin2021_ml.hpp
/// `pathref reproduce cin2021-ml`: cin2021 §3.3's two protocols (hold-out, Fig. 3; tenfold
/// cross-validation, Fig. 4) with pathref's five classifiers on the UCI 4-sensor data, each of the
/// paper's ten accuracies beside pathref's and scikit-learn's, under both readings of the split
/// (1636/3820 as stated, and swapped), and the evidence for which split the authors used.
/// Spec: spec/cin2021-ml.md#reproduction, spec/reproduce.md
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pathref/reproduce/report.hpp"

namespace pathref::reproduce {

struct Cin2021MlConfig {
  std::string data_file;     ///< sensor_readings_4.data
  int seeds = 10;            ///< n: hold-out splits per reading and forest seeds (2n are run; verdicts at n and 2n)
  std::uint32_t first_seed = 1;
  Json sklearn;              ///< tools/reproduce/cin2021_ml_sklearn.py output, or null
  Provenance provenance;
  Progress progress;
  bool quick = false;        ///< RF with 10 trees only, for a smoke test
};

/// The post-hoc reading of a tenfold number, shown beside the verdict and never deciding: |value -
/// printed| < one unit of the printed number's last digit (10^-decimals). Chosen after seeing the
/// results (MNB's 58.376 against the printed 58.3), so it is disclosed as such.
/// Spec: reproduce.cin2021-ml.judge. Pre: as printed_decimals, value finite.
[[nodiscard]] bool within_last_digit(double value, std::string_view printed);

/// A tenfold number of a deterministic classifier (fixed folds identical to the paper's, so
/// there is no sampling noise): judge_printed(accuracy_pct, printed, higher is better), `ours`
/// with the value, how it prints and the signed difference in percentage points, the post-hoc
/// within_last_digit reading in the note and the statistics. Spec: reproduce.cin2021-ml.judge.
[[nodiscard]] Claim tenfold_printed_claim(const std::string& id, const std::string& text, double accuracy_pct,
                                          const std::string& printed);

/// Runs both protocols; returns the reproduce.json document (claims, results, evidence).
[[nodiscard]] Json run_cin2021_ml(const Cin2021MlConfig& cfg);
/// The markdown report, every number taken from `doc`.
[[nodiscard]] std::string cin2021_ml_markdown(const Json& doc, const std::string& json_name);
/// Figures like the paper's Figs. 3-4 (bar charts of the accuracies): (file name, SVG text).
[[nodiscard]] std::vector<std::pair<std::string, std::string>> cin2021_ml_figures(const Json& doc);

}  // namespace pathref::reproduce
