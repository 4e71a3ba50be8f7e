#pragma once
/// \file metrics.hpp
/// cin2021 Eq. 7-11: the "comprehensive evaluation index" of a K-class classifier, as pure
/// functions of a confusion matrix. Wang et al., "Mobile robot path planning ... ML, S-RRT and
/// HGA-ACO", Computational Intelligence and Neuroscience 2021, article 8025730,
/// doi:10.1155/2021/8025730, §3.3. The binary formulas of the paper are extended to K classes
/// one-vs-rest per class and averaged (macro, weighted or micro), and MCC in Gorodkin's
/// multi-class form, exactly as scikit-learn 1.2 computes them (spec/cin2021-ml.md).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace pathref::ml {

/// A K x K confusion matrix: count(true class i, predicted class j) at (i, j).
struct Confusion {
  std::size_t classes = 0;
  std::vector<std::int64_t> counts;  ///< row-major, classes * classes
  [[nodiscard]] std::int64_t at(std::size_t t, std::size_t p) const noexcept {
    return counts[t * classes + p];
  }
  [[nodiscard]] std::int64_t total() const noexcept;
};

/// Confusion matrix of predictions against true labels.
/// Spec: cin2021.eq7. Pre: classes >= 1, equal lengths >= 1, every label in [0, classes)
/// (DomainError).
[[nodiscard]] Confusion confusion_matrix(std::span<const int> y_true, std::span<const int> y_pred,
                                         std::size_t classes);

/// Eq. 7 accuracy: trace / total (for K classes (TP+TN)/(TP+TN+FP+FN) summed one-vs-rest
/// reduces to this). Spec: cin2021.eq7. Pre: total >= 1 (DomainError).
[[nodiscard]] double accuracy(const Confusion& c);

/// How per-class values are combined.
enum class Average { none, macro, weighted, micro };
/// "none" | "macro" | "weighted" | "micro" (UsageError otherwise).
[[nodiscard]] Average parse_average(std::string_view name);
[[nodiscard]] std::string_view to_string(Average a) noexcept;

/// Per-class precision TP_k / (TP_k + FP_k), 0 where the denominator is 0 (class never
/// predicted). Spec: cin2021.eq8.
[[nodiscard]] std::vector<double> precision_per_class(const Confusion& c);
/// Per-class recall TP_k / (TP_k + FN_k), 0 where the class has no true sample. Spec: cin2021.eq9.
[[nodiscard]] std::vector<double> recall_per_class(const Confusion& c);
/// Per-class F1 (2 P_k) R_k / (P_k + R_k), 0 where P_k + R_k = 0. Spec: cin2021.eq10.
[[nodiscard]] std::vector<double> f1_per_class(const Confusion& c);

/// Averaged precision: macro = mean over the K classes; weighted = sum_k P_k n_k / sum_k n_k
/// with n_k the true count (0 when sum n_k = 0); micro = sum TP / sum (TP+FP) (= accuracy).
/// Spec: cin2021.eq8. Pre: total >= 1, average != none (DomainError).
[[nodiscard]] double precision(const Confusion& c, Average average);
/// Averaged recall (as precision). Spec: cin2021.eq9.
[[nodiscard]] double recall(const Confusion& c, Average average);
/// Averaged F1: macro/weighted average the per-class F1 (not F1 of the averages); micro =
/// F1 of micro precision and recall. Spec: cin2021.eq10.
[[nodiscard]] double f1(const Confusion& c, Average average);

/// Eq. 11 Matthews correlation, multi-class (Gorodkin 2004, doi:10.1016/j.compbiolchem.2004.09.006):
/// (c s - sum_k p_k t_k) / sqrt((s^2 - sum p_k^2)(s^2 - sum t_k^2)), c = trace, s = total,
/// t_k true counts, p_k predicted counts; 0 when the denominator is 0. Equals Eq. 11 as printed
/// for K = 2. Spec: cin2021.eq11. Pre: total >= 1 (DomainError).
[[nodiscard]] double mcc(const Confusion& c);

/// Every metric at once (what `pathref learn` prints).
struct Scores {
  Confusion confusion;
  double accuracy = 0;
  double precision_macro = 0, recall_macro = 0, f1_macro = 0;
  double precision_weighted = 0, recall_weighted = 0, f1_weighted = 0;
  double precision_micro = 0, recall_micro = 0, f1_micro = 0;
  double mcc = 0;
  std::vector<double> precision_class, recall_class, f1_class;
};
[[nodiscard]] Scores score(std::span<const int> y_true, std::span<const int> y_pred,
                           std::size_t classes);

}  // namespace pathref::ml
