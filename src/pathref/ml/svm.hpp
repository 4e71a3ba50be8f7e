#pragma once
/// \file svm.hpp
/// cin2021 Eq. 2-3, the support vector machine: soft-margin C-SVC with the RBF kernel
/// K(x, z) = exp(-gamma |x - z|^2), one-vs-one over the classes. Training solves Eq. 3's dual
/// with libsvm (Chang & Lin 2011, doi:10.1145/1961189.1961199; Debian libsvm 3.24), the solver
/// scikit-learn's SVC wraps; the decision of a trained model (Eq. 2's sign(w.phi(x) + b) per pair,
/// then the vote) is our own pure function. Defaults are scikit-learn 1.2 SVC's: C = 1,
/// gamma = "scale" = 1 / (d Var(X)), tolerance 1e-3, shrinking on, 200 MB kernel cache.
/// Spec: spec/cin2021-ml.md#r[cin2021.eq2], #r[cin2021.eq3]
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "pathref/ml/data.hpp"

namespace pathref::ml {

/// SVM training parameters. gamma <= 0 selects `gamma_mode` ("scale" or "auto").
struct SvmParams {
  double c = 1.0;
  double gamma = 0.0;
  std::string gamma_mode = "scale";  ///< "scale": 1/(d Var(X)) (1 if Var = 0); "auto": 1/d
  double tolerance = 1e-3;           ///< libsvm eps (stopping tolerance of the KKT gap)
  double cache_mb = 200.0;
  bool shrinking = true;
};

/// A trained one-vs-one RBF SVM in libsvm's layout: the classes present in training in
/// increasing label order, their support vectors grouped by class, (K-1) coefficient rows and
/// one rho per pair (i < j) in the order (0,1), (0,2), ..., (1,2), ...
struct SvmModel {
  std::size_t classes = 0;           ///< label range [0, classes)
  std::size_t features = 0;
  double gamma = 0.0;
  std::vector<int> labels;           ///< the K present labels, increasing
  std::vector<std::size_t> n_sv;     ///< support vectors per present class
  std::vector<double> sv;            ///< total_sv * features, grouped by class
  std::vector<double> coef;          ///< (K-1) * total_sv: y_i alpha_i per pair, libsvm's sv_coef
  std::vector<double> rho;           ///< K(K-1)/2 values; decision = sum coef K - rho
  std::vector<std::size_t> sv_rows;  ///< training row index of each support vector
  [[nodiscard]] std::size_t total_sv() const noexcept { return sv_rows.size(); }
};

/// gamma = "scale": 1 / (d * population variance of all n*d training values) (1 when that
/// variance is 0); "auto": 1 / d. Spec: cin2021.eq3. Pre: rows >= 1 (DomainError); mode
/// "scale" or "auto" (UsageError).
[[nodiscard]] double svm_gamma(const Dataset& d, const std::string& mode);

/// Trains with libsvm's C-SVC (RBF). The rows are presented to libsvm stably sorted by label,
/// so that libsvm's class order (order of first appearance) is the increasing label order, as
/// in scikit-learn's build of libsvm. Spec: cin2021.eq3. Pre: rows >= 2, at least two classes
/// present, C > 0, gamma > 0 (or a mode), tolerance > 0 (DomainError).
[[nodiscard]] SvmModel train_svm(const Dataset& d, const SvmParams& p = {});

/// Per-pair decision values f_ij(x) = sum_{s in SV_i} coef[j-1][s] K(x, s)
/// + sum_{s in SV_j} coef[i][s] K(x, s) - rho_ij (libsvm's order of summation), with
/// K(x, s) = exp(-gamma * sum_k (x_k - s_k)^2). Spec: cin2021.eq2. Pre: x.size() == features.
[[nodiscard]] std::vector<double> svm_decision_values(const SvmModel& m, std::span<const double> x);

/// One-vs-one vote: pair (i, j) votes labels[i] if f_ij > 0, else labels[j]; the most votes
/// win, a tie goes to the smallest label. Spec: cin2021.eq2.
[[nodiscard]] int predict(const SvmModel& m, std::span<const double> x);

/// Checks the layout of a model read from JSON (sizes, increasing labels) (DomainError).
void validate(const SvmModel& m);

}  // namespace pathref::ml
