#include "pathref/ml/metrics.hpp"

#include <cmath>
#include <string>

#include "pathref/core/error.hpp"

namespace pathref::ml {

__extension__ typedef __int128 int128;

std::int64_t Confusion::total() const noexcept {
  std::int64_t s = 0;
  for (const auto v : counts) s += v;
  return s;
}

Confusion confusion_matrix(std::span<const int> y_true, std::span<const int> y_pred,
                           std::size_t classes) {
  require(classes >= 1, "confusion_matrix: classes must be >= 1");
  require(y_true.size() == y_pred.size(), "confusion_matrix: y_true and y_pred differ in length");
  require(!y_true.empty(), "confusion_matrix: no samples");
  Confusion c{classes, std::vector<std::int64_t>(classes * classes, 0)};
  for (std::size_t i = 0; i < y_true.size(); ++i) {
    const int t = y_true[i];
    const int p = y_pred[i];
    require(t >= 0 && static_cast<std::size_t>(t) < classes && p >= 0 &&
                static_cast<std::size_t>(p) < classes,
            "confusion_matrix: label outside [0, classes)");
    ++c.counts[static_cast<std::size_t>(t) * classes + static_cast<std::size_t>(p)];
  }
  return c;
}

namespace {
void require_total(const Confusion& c) {
  require(c.classes >= 1 && c.counts.size() == c.classes * c.classes,
          "metrics: confusion matrix must be K x K, K >= 1");
  for (const auto v : c.counts) require(v >= 0, "metrics: negative count");
  require(c.total() >= 1, "metrics: confusion matrix has no samples");
}
std::int64_t tp(const Confusion& c, std::size_t k) { return c.at(k, k); }
std::int64_t pred_sum(const Confusion& c, std::size_t k) {
  std::int64_t s = 0;
  for (std::size_t t = 0; t < c.classes; ++t) s += c.at(t, k);
  return s;
}
std::int64_t true_sum(const Confusion& c, std::size_t k) {
  std::int64_t s = 0;
  for (std::size_t p = 0; p < c.classes; ++p) s += c.at(k, p);
  return s;
}
double ratio(std::int64_t num, std::int64_t den) {
  return den == 0 ? 0.0 : static_cast<double>(num) / static_cast<double>(den);
}
double f1_of(double p, double r) {
  const double den = p + r;
  return den == 0.0 ? 0.0 : 2.0 * p * r / den;
}
double average(const Confusion& c, const std::vector<double>& per_class, Average a) {
  if (a == Average::macro) {
    double s = 0.0;
    for (const double v : per_class) s += v;
    return s / static_cast<double>(per_class.size());
  }
  // weighted by true counts
  double s = 0.0;
  double w = 0.0;
  for (std::size_t k = 0; k < c.classes; ++k) {
    const double n = static_cast<double>(true_sum(c, k));
    s += per_class[k] * n;
    w += n;
  }
  return w == 0.0 ? 0.0 : s / w;
}
double micro_ratio(const Confusion& c, bool use_pred) {
  std::int64_t num = 0;
  std::int64_t den = 0;
  for (std::size_t k = 0; k < c.classes; ++k) {
    num += tp(c, k);
    den += use_pred ? pred_sum(c, k) : true_sum(c, k);
  }
  return ratio(num, den);
}
}  // namespace

double accuracy(const Confusion& c) {
  require_total(c);
  std::int64_t t = 0;
  for (std::size_t k = 0; k < c.classes; ++k) t += tp(c, k);
  return static_cast<double>(t) / static_cast<double>(c.total());
}

Average parse_average(std::string_view name) {
  if (name == "none") return Average::none;
  if (name == "macro") return Average::macro;
  if (name == "weighted") return Average::weighted;
  if (name == "micro") return Average::micro;
  throw UsageError("unknown average '" + std::string(name) + "' (none, macro, weighted, micro)");
}

std::string_view to_string(Average a) noexcept {
  switch (a) {
    case Average::none: return "none";
    case Average::macro: return "macro";
    case Average::weighted: return "weighted";
    case Average::micro: return "micro";
  }
  return "none";
}

std::vector<double> precision_per_class(const Confusion& c) {
  require_total(c);
  std::vector<double> out(c.classes);
  for (std::size_t k = 0; k < c.classes; ++k) out[k] = ratio(tp(c, k), pred_sum(c, k));
  return out;
}

std::vector<double> recall_per_class(const Confusion& c) {
  require_total(c);
  std::vector<double> out(c.classes);
  for (std::size_t k = 0; k < c.classes; ++k) out[k] = ratio(tp(c, k), true_sum(c, k));
  return out;
}

std::vector<double> f1_per_class(const Confusion& c) {
  const auto p = precision_per_class(c);
  const auto r = recall_per_class(c);
  std::vector<double> out(c.classes);
  for (std::size_t k = 0; k < c.classes; ++k) out[k] = f1_of(p[k], r[k]);
  return out;
}

double precision(const Confusion& c, Average a) {
  require(a != Average::none, "precision: average 'none' has no single value");
  if (a == Average::micro) {
    require_total(c);
    return micro_ratio(c, true);
  }
  return average(c, precision_per_class(c), a);
}

double recall(const Confusion& c, Average a) {
  require(a != Average::none, "recall: average 'none' has no single value");
  if (a == Average::micro) {
    require_total(c);
    return micro_ratio(c, false);
  }
  return average(c, recall_per_class(c), a);
}

double f1(const Confusion& c, Average a) {
  require(a != Average::none, "f1: average 'none' has no single value");
  if (a == Average::micro) {
    require_total(c);
    return f1_of(micro_ratio(c, true), micro_ratio(c, false));
  }
  return average(c, f1_per_class(c), a);
}

double mcc(const Confusion& c) {
  require_total(c);
  using I = int128;
  const I s = c.total();
  I correct = 0;
  I pt = 0;
  I pp = 0;
  I tt = 0;
  for (std::size_t k = 0; k < c.classes; ++k) {
    const I t = true_sum(c, k);
    const I p = pred_sum(c, k);
    correct += tp(c, k);
    pt += p * t;
    pp += p * p;
    tt += t * t;
  }
  const I cov_tp = correct * s - pt;
  const I cov_pp = s * s - pp;
  const I cov_tt = s * s - tt;
  const I den = cov_tt * cov_pp;
  if (den == 0) return 0.0;
  return static_cast<double>(cov_tp) / std::sqrt(static_cast<double>(den));
}

Scores score(std::span<const int> y_true, std::span<const int> y_pred, std::size_t classes) {
  Scores s;
  s.confusion = confusion_matrix(y_true, y_pred, classes);
  const Confusion& c = s.confusion;
  s.accuracy = accuracy(c);
  s.precision_macro = precision(c, Average::macro);
  s.recall_macro = recall(c, Average::macro);
  s.f1_macro = f1(c, Average::macro);
  s.precision_weighted = precision(c, Average::weighted);
  s.recall_weighted = recall(c, Average::weighted);
  s.f1_weighted = f1(c, Average::weighted);
  s.precision_micro = precision(c, Average::micro);
  s.recall_micro = recall(c, Average::micro);
  s.f1_micro = f1(c, Average::micro);
  s.mcc = mcc(c);
  s.precision_class = precision_per_class(c);
  s.recall_class = recall_per_class(c);
  s.f1_class = f1_per_class(c);
  return s;
}

}  // namespace pathref::ml
