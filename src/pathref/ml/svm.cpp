#include "pathref/ml/svm.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

#include <libsvm/svm.h>

#include "pathref/core/error.hpp"

namespace pathref::ml {
namespace {
void quiet(const char*) {}
}  // namespace

double svm_gamma(const Dataset& d, const std::string& mode) {
  require(d.rows() >= 1 && d.features >= 1, "svm_gamma: no training rows");
  if (mode == "auto") return 1.0 / static_cast<double>(d.features);
  if (mode != "scale") throw UsageError("unknown gamma mode '" + mode + "' (scale, auto, or a number > 0)");
  double s = 0.0;
  for (const double v : d.x) s += v;
  const double mu = s / static_cast<double>(d.x.size());
  double q = 0.0;
  for (const double v : d.x) q += (v - mu) * (v - mu);
  const double var = q / static_cast<double>(d.x.size());
  return var != 0.0 ? 1.0 / (static_cast<double>(d.features) * var) : 1.0;
}

SvmModel train_svm(const Dataset& d, const SvmParams& p) {
  require(d.rows() >= 2 && d.features >= 1, "SVM: at least two training rows");
  require(std::isfinite(p.c) && p.c > 0.0, "SVM: C must be > 0");
  require(std::isfinite(p.tolerance) && p.tolerance > 0.0, "SVM: tolerance must be > 0");
  require(std::isfinite(p.cache_mb) && p.cache_mb > 0.0, "SVM: cache size must be > 0");
  for (const int y : d.y)
    require(y >= 0 && static_cast<std::size_t>(y) < d.classes, "SVM: label outside [0, classes)");
  for (const double v : d.x) require(std::isfinite(v), "SVM: non-finite feature value");
  const double gamma = p.gamma > 0.0 ? p.gamma : svm_gamma(d, p.gamma_mode);
  require(std::isfinite(gamma) && gamma > 0.0, "SVM: gamma must be > 0");
  const std::size_t n = d.rows();
  const std::size_t f = d.features;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return d.y[a] < d.y[b]; });
  require(d.y[order.front()] != d.y[order.back()], "SVM: at least two classes must be present");

  std::vector<svm_node> nodes(n * (f + 1));
  std::vector<svm_node*> rows(n);
  std::vector<double> labels(n);
  for (std::size_t r = 0; r < n; ++r) {
    const std::size_t i = order[r];
    svm_node* row = nodes.data() + r * (f + 1);
    for (std::size_t j = 0; j < f; ++j) row[j] = svm_node{static_cast<int>(j + 1), d.x[i * f + j]};
    row[f] = svm_node{-1, 0.0};
    rows[r] = row;
    labels[r] = static_cast<double>(d.y[i]);
  }
  svm_problem prob{};
  prob.l = static_cast<int>(n);
  prob.y = labels.data();
  prob.x = rows.data();
  svm_parameter par{};
  par.svm_type = C_SVC;
  par.kernel_type = RBF;
  par.degree = 3;
  par.gamma = gamma;
  par.coef0 = 0.0;
  par.cache_size = p.cache_mb;
  par.eps = p.tolerance;
  par.C = p.c;
  par.nr_weight = 0;
  par.weight_label = nullptr;
  par.weight = nullptr;
  par.nu = 0.5;
  par.p = 0.1;
  par.shrinking = p.shrinking ? 1 : 0;
  par.probability = 0;
  if (const char* err = svm_check_parameter(&prob, &par)) throw DomainError(std::string("libsvm: ") + err);
  svm_set_print_string_function(&quiet);
  svm_model* raw = svm_train(&prob, &par);
  if (raw == nullptr) throw DomainError("libsvm: training failed");
  const auto free_model = [](svm_model* m) { svm_free_and_destroy_model(&m); };
  const std::unique_ptr<svm_model, decltype(free_model)> model(raw, free_model);

  SvmModel m;
  m.classes = d.classes;
  m.features = f;
  m.gamma = gamma;
  const auto k = static_cast<std::size_t>(model->nr_class);
  const auto l = static_cast<std::size_t>(model->l);
  for (std::size_t c = 0; c < k; ++c) {
    m.labels.push_back(model->label[c]);
    m.n_sv.push_back(static_cast<std::size_t>(model->nSV[c]));
  }
  require(std::is_sorted(m.labels.begin(), m.labels.end()), "libsvm: unexpected class order");
  m.sv.assign(l * f, 0.0);
  for (std::size_t s = 0; s < l; ++s) {
    // sv_indices are 1-based positions in the problem as presented (sorted order)
    const auto pos = static_cast<std::size_t>(model->sv_indices[s] - 1);
    m.sv_rows.push_back(order[pos]);
    for (const svm_node* node = model->SV[s]; node->index != -1; ++node)
      m.sv[s * f + static_cast<std::size_t>(node->index - 1)] = node->value;
  }
  m.coef.assign((k - 1) * l, 0.0);
  for (std::size_t r = 0; r + 1 < k; ++r)
    for (std::size_t s = 0; s < l; ++s) m.coef[r * l + s] = model->sv_coef[r][s];
  for (std::size_t q = 0; q < k * (k - 1) / 2; ++q) m.rho.push_back(model->rho[q]);
  return m;
}

void validate(const SvmModel& m) {
  const std::size_t k = m.labels.size();
  require(m.features >= 1 && m.classes >= 2, "SVM model: features >= 1 and classes >= 2");
  require(k >= 2 && k <= m.classes, "SVM model: 2 <= present classes <= classes");
  require(std::isfinite(m.gamma) && m.gamma > 0.0, "SVM model: gamma must be > 0");
  for (std::size_t i = 0; i < k; ++i) {
    require(m.labels[i] >= 0 && static_cast<std::size_t>(m.labels[i]) < m.classes,
            "SVM model: label outside [0, classes)");
    require(i == 0 || m.labels[i - 1] < m.labels[i], "SVM model: labels must increase");
  }
  require(m.n_sv.size() == k, "SVM model: one n_sv per present class");
  const std::size_t l = std::accumulate(m.n_sv.begin(), m.n_sv.end(), std::size_t{0});
  require(m.sv_rows.size() == l, "SVM model: sv_rows must have sum(n_sv) entries");
  require(m.sv.size() == l * m.features, "SVM model: sv must have sum(n_sv) * features values");
  require(m.coef.size() == (k - 1) * l, "SVM model: coef must have (K-1) * sum(n_sv) values");
  require(m.rho.size() == k * (k - 1) / 2, "SVM model: rho must have K(K-1)/2 values");
  for (const double v : m.sv) require(std::isfinite(v), "SVM model: non-finite support vector");
  for (const double v : m.coef) require(std::isfinite(v), "SVM model: non-finite coefficient");
  for (const double v : m.rho) require(std::isfinite(v), "SVM model: non-finite rho");
}

std::vector<double> svm_decision_values(const SvmModel& m, std::span<const double> x) {
  require(x.size() == m.features, "SVM: the sample has the wrong number of features");
  for (const double v : x) require(std::isfinite(v), "SVM: non-finite feature value");
  const std::size_t k = m.labels.size();
  const std::size_t l = m.total_sv();
  const std::size_t f = m.features;
  std::vector<double> kv(l);
  for (std::size_t s = 0; s < l; ++s) {
    double q = 0.0;
    for (std::size_t j = 0; j < f; ++j) {
      const double e = x[j] - m.sv[s * f + j];
      q += e * e;
    }
    kv[s] = std::exp(-m.gamma * q);
  }
  std::vector<std::size_t> start(k, 0);
  for (std::size_t c = 1; c < k; ++c) start[c] = start[c - 1] + m.n_sv[c - 1];
  std::vector<double> dec;
  dec.reserve(k * (k - 1) / 2);
  std::size_t pair = 0;
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = i + 1; j < k; ++j, ++pair) {
      double sum = 0.0;
      const double* coef1 = m.coef.data() + (j - 1) * l;
      const double* coef2 = m.coef.data() + i * l;
      for (std::size_t s = 0; s < m.n_sv[i]; ++s) sum += coef1[start[i] + s] * kv[start[i] + s];
      for (std::size_t s = 0; s < m.n_sv[j]; ++s) sum += coef2[start[j] + s] * kv[start[j] + s];
      sum -= m.rho[pair];
      dec.push_back(sum);
    }
  return dec;
}

int predict(const SvmModel& m, std::span<const double> x) {
  const std::vector<double> dec = svm_decision_values(m, x);
  const std::size_t k = m.labels.size();
  std::vector<int> votes(k, 0);
  std::size_t pair = 0;
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = i + 1; j < k; ++j, ++pair) ++votes[dec[pair] > 0.0 ? i : j];
  std::size_t best = 0;
  for (std::size_t c = 1; c < k; ++c)
    if (votes[c] > votes[best]) best = c;
  return m.labels[best];
}

}  // namespace pathref::ml
