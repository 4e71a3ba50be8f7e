#include "pathref/ml/naive_bayes.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "pathref/core/error.hpp"

namespace pathref::ml {
namespace {
constexpr double neg_inf = -std::numeric_limits<double>::infinity();

void require_data(const Dataset& d) {
  require(d.rows() >= 1 && d.features >= 1, "naive Bayes: no training rows");
  require(d.classes >= 1, "naive Bayes: classes must be >= 1");
  require(d.x.size() == d.rows() * d.features, "naive Bayes: x must hold rows * features values");
  for (const int y : d.y)
    require(y >= 0 && static_cast<std::size_t>(y) < d.classes, "naive Bayes: label outside [0, classes)");
  for (const double v : d.x) require(std::isfinite(v), "naive Bayes: non-finite feature value");
}

std::vector<std::int64_t> class_counts(const Dataset& d) {
  std::vector<std::int64_t> n(d.classes, 0);
  for (const int y : d.y) ++n[static_cast<std::size_t>(y)];
  return n;
}
}  // namespace

int argmax_first(std::span<const double> v) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < v.size(); ++i)
    if (v[i] > v[best]) best = i;
  return static_cast<int>(best);
}

GaussianNb fit_gaussian_nb(const Dataset& d, double var_smoothing) {
  require_data(d);
  require(std::isfinite(var_smoothing) && var_smoothing >= 0.0,
          "GaussianNB: var_smoothing must be finite and >= 0");
  const std::size_t n = d.rows();
  const std::size_t f = d.features;
  GaussianNb m;
  m.classes = d.classes;
  m.features = f;
  m.var_smoothing = var_smoothing;
  // epsilon: largest population variance of a column, times var_smoothing
  double max_var = 0.0;
  for (std::size_t j = 0; j < f; ++j) {
    double s = 0.0;
    for (std::size_t i = 0; i < n; ++i) s += d.x[i * f + j];
    const double mu = s / static_cast<double>(n);
    double q = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double e = d.x[i * f + j] - mu;
      q += e * e;
    }
    const double v = q / static_cast<double>(n);
    if (j == 0 || v > max_var) max_var = v;
  }
  m.epsilon = var_smoothing * max_var;
  m.count = class_counts(d);
  m.log_prior.assign(m.classes, neg_inf);
  m.mean.assign(m.classes * f, 0.0);
  m.var.assign(m.classes * f, 0.0);
  for (std::size_t c = 0; c < m.classes; ++c) {
    if (m.count[c] == 0) continue;
    const double nc = static_cast<double>(m.count[c]);
    m.log_prior[c] = std::log(nc / static_cast<double>(n));
    for (std::size_t j = 0; j < f; ++j) {
      double s = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        if (static_cast<std::size_t>(d.y[i]) == c) s += d.x[i * f + j];
      const double mu = s / nc;
      double q = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        if (static_cast<std::size_t>(d.y[i]) == c) {
          const double e = d.x[i * f + j] - mu;
          q += e * e;
        }
      m.mean[c * f + j] = mu;
      m.var[c * f + j] = q / nc + m.epsilon;
      require(m.var[c * f + j] > 0.0,
              "GaussianNB: a class variance is 0 and var_smoothing adds nothing (epsilon = 0)");
    }
  }
  return m;
}

std::vector<double> joint_log_likelihood(const GaussianNb& m, std::span<const double> x) {
  require(x.size() == m.features, "GaussianNB: the sample has the wrong number of features");
  std::vector<double> jll(m.classes, neg_inf);
  for (std::size_t c = 0; c < m.classes; ++c) {
    if (m.count[c] == 0) continue;
    double a = 0.0;
    for (std::size_t j = 0; j < m.features; ++j)
      a += std::log(2.0 * std::numbers::pi * m.var[c * m.features + j]);
    double b = 0.0;
    for (std::size_t j = 0; j < m.features; ++j) {
      const double e = x[j] - m.mean[c * m.features + j];
      b += e * e / m.var[c * m.features + j];
    }
    jll[c] = m.log_prior[c] + (-0.5 * a - 0.5 * b);
  }
  return jll;
}

int predict(const GaussianNb& m, std::span<const double> x) {
  return argmax_first(joint_log_likelihood(m, x));
}

MultinomialNb fit_multinomial_nb(const Dataset& d, double alpha) {
  require_data(d);
  require(std::isfinite(alpha) && alpha > 0.0, "MultinomialNB: alpha must be finite and > 0");
  for (const double v : d.x) require(v >= 0.0, "MultinomialNB: features must be >= 0 (counts)");
  const std::size_t n = d.rows();
  const std::size_t f = d.features;
  MultinomialNb m;
  m.classes = d.classes;
  m.features = f;
  m.alpha = alpha;
  m.count = class_counts(d);
  m.log_prior.assign(m.classes, neg_inf);
  m.feature_log_prob.assign(m.classes * f, 0.0);
  std::vector<double> fc(m.classes * f, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<std::size_t>(d.y[i]);
    for (std::size_t j = 0; j < f; ++j) fc[c * f + j] += d.x[i * f + j];
  }
  const double log_n = std::log(static_cast<double>(n));
  for (std::size_t c = 0; c < m.classes; ++c) {
    if (m.count[c] > 0) m.log_prior[c] = std::log(static_cast<double>(m.count[c])) - log_n;
    double total = 0.0;
    for (std::size_t j = 0; j < f; ++j) total += fc[c * f + j] + alpha;
    const double log_total = std::log(total);
    for (std::size_t j = 0; j < f; ++j)
      m.feature_log_prob[c * f + j] = std::log(fc[c * f + j] + alpha) - log_total;
  }
  return m;
}

std::vector<double> joint_log_likelihood(const MultinomialNb& m, std::span<const double> x) {
  require(x.size() == m.features, "MultinomialNB: the sample has the wrong number of features");
  for (const double v : x) require(std::isfinite(v) && v >= 0.0, "MultinomialNB: features must be >= 0");
  std::vector<double> jll(m.classes, neg_inf);
  for (std::size_t c = 0; c < m.classes; ++c) {
    if (m.count[c] == 0) continue;
    double s = 0.0;
    for (std::size_t j = 0; j < m.features; ++j) s += x[j] * m.feature_log_prob[c * m.features + j];
    jll[c] = s + m.log_prior[c];
  }
  return jll;
}

int predict(const MultinomialNb& m, std::span<const double> x) {
  return argmax_first(joint_log_likelihood(m, x));
}

}  // namespace pathref::ml
