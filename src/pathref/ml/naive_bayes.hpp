#pragma once
/// \file naive_bayes.hpp
/// cin2021 Eq. 1, naive Bayes: yhat = argmax_c log P(c) + sum_i log P(x_i | c), features
/// conditionally independent given the class. Two likelihoods, as the paper's GNB and MNB, with
/// scikit-learn 1.2's estimators and defaults (GaussianNB var_smoothing = 1e-9, MultinomialNB
/// alpha = 1, fit_prior = true). doi:10.1155/2021/8025730, §3.1, Eq. (1).
/// Spec: spec/cin2021-ml.md#r[cin2021.eq1]
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "pathref/ml/data.hpp"

namespace pathref::ml {

/// Index of the first largest value (ties -> the smallest class index); -inf entries are never
/// chosen unless all are -inf (then 0). Spec: cin2021.eq1 (argmax rule shared by every classifier).
[[nodiscard]] int argmax_first(std::span<const double> v);

/// A fitted Gaussian naive Bayes model.
struct GaussianNb {
  std::size_t classes = 0, features = 0;
  double var_smoothing = 1e-9;
  double epsilon = 0;                ///< var_smoothing * max_j Var(x_j) over the training rows
  std::vector<std::int64_t> count;   ///< training rows per class
  std::vector<double> log_prior;     ///< log(count_c / n); -inf for an absent class
  std::vector<double> mean, var;     ///< classes * features; var includes epsilon
};

/// Fits GNB: mean_cj = sum_{i in c} x_ij / n_c; var_cj = sum_{i in c} (x_ij - mean_cj)^2 / n_c
/// + epsilon, epsilon = var_smoothing * max_j (population variance of column j); prior n_c / n.
/// Sums left to right over rows in data order. Spec: cin2021.eq1 (likelihood=gaussian).
/// Pre: rows >= 1, var_smoothing >= 0 finite, every label in [0, classes), and epsilon > 0 or
/// every class variance > 0 (DomainError).
[[nodiscard]] GaussianNb fit_gaussian_nb(const Dataset& d, double var_smoothing = 1e-9);

/// Joint log-likelihood per class: log P(c) - 1/2 sum_j log(2 pi var_cj)
///   - 1/2 sum_j (x_j - mean_cj)^2 / var_cj (-inf for a class without training rows).
/// Spec: cin2021.eq1. Pre: x.size() == features (DomainError).
[[nodiscard]] std::vector<double> joint_log_likelihood(const GaussianNb& m, std::span<const double> x);
/// argmax_first of the joint log-likelihood. Spec: cin2021.eq1.
[[nodiscard]] int predict(const GaussianNb& m, std::span<const double> x);

/// A fitted multinomial naive Bayes model.
struct MultinomialNb {
  std::size_t classes = 0, features = 0;
  double alpha = 1.0;
  std::vector<std::int64_t> count;
  std::vector<double> log_prior;     ///< log n_c - log n; -inf for an absent class
  std::vector<double> feature_log_prob;  ///< classes * features
};

/// Fits MNB: N_cj = sum_{i in c} x_ij; log theta_cj = log(N_cj + alpha) - log(sum_j (N_cj + alpha))
/// (sum left to right over j); log P(c) = log n_c - log n. Spec: cin2021.eq1 (likelihood=multinomial).
/// Pre: rows >= 1, every x >= 0 (the multinomial likelihood needs counts), alpha > 0 finite
/// (DomainError).
[[nodiscard]] MultinomialNb fit_multinomial_nb(const Dataset& d, double alpha = 1.0);
/// sum_j x_j log theta_cj (left to right) + log P(c). Spec: cin2021.eq1.
/// Pre: x.size() == features, x >= 0 (DomainError).
[[nodiscard]] std::vector<double> joint_log_likelihood(const MultinomialNb& m, std::span<const double> x);
[[nodiscard]] int predict(const MultinomialNb& m, std::span<const double> x);

}  // namespace pathref::ml
