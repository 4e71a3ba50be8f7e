#include "pathref/ml/knn.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "pathref/core/error.hpp"

namespace pathref::ml {

double euclidean(std::span<const double> x, std::span<const double> y) {
  require(x.size() == y.size() && !x.empty(), "euclidean: vectors must have equal length >= 1");
  double s = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    require(std::isfinite(x[i]) && std::isfinite(y[i]), "euclidean: non-finite value");
    const double e = x[i] - y[i];
    s += e * e;
  }
  return std::sqrt(s);
}

double weighted_euclidean(std::span<const double> x, std::span<const double> y,
                          std::span<const double> w) {
  require(x.size() == y.size() && x.size() == w.size() && !x.empty(),
          "weighted_euclidean: x, y and w must have equal length >= 1");
  double s = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    require(std::isfinite(x[i]) && std::isfinite(y[i]), "weighted_euclidean: non-finite value");
    require(std::isfinite(w[i]) && w[i] >= 0.0, "weighted_euclidean: weights must be finite and >= 0");
    const double e = x[i] - y[i];
    s += w[i] * (e * e);
  }
  return std::sqrt(s);
}

KnnVote parse_knn_vote(std::string_view name) {
  if (name == "uniform") return KnnVote::uniform;
  if (name == "distance") return KnnVote::distance;
  throw UsageError("unknown KNN vote '" + std::string(name) + "' (uniform, distance)");
}

std::string_view to_string(KnnVote v) noexcept {
  return v == KnnVote::uniform ? "uniform" : "distance";
}

int knn_vote(std::span<const int> labels, std::span<const double> distances, std::size_t classes,
             KnnVote vote) {
  require(!labels.empty() && labels.size() == distances.size(),
          "knn_vote: labels and distances must have equal length >= 1");
  require(classes >= 1, "knn_vote: classes must be >= 1");
  bool any_zero = false;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    require(labels[i] >= 0 && static_cast<std::size_t>(labels[i]) < classes,
            "knn_vote: label outside [0, classes)");
    require(std::isfinite(distances[i]) && distances[i] >= 0.0, "knn_vote: distances must be >= 0");
    any_zero = any_zero || distances[i] == 0.0;
  }
  std::vector<double> votes(classes, 0.0);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    double w = 1.0;
    if (vote == KnnVote::distance) w = any_zero ? (distances[i] == 0.0 ? 1.0 : 0.0) : 1.0 / distances[i];
    votes[static_cast<std::size_t>(labels[i])] += w;
  }
  std::size_t best = 0;
  for (std::size_t c = 1; c < classes; ++c)
    if (votes[c] > votes[best]) best = c;
  return static_cast<int>(best);
}

std::optional<std::size_t> first_overflow(std::span<const double> squared_distances) {
  for (std::size_t i = 0; i < squared_distances.size(); ++i)
    if (!std::isfinite(squared_distances[i])) return i;
  return std::nullopt;
}

KnnResult knn_query(const Knn& m, std::span<const double> x) {
  const Dataset& t = m.train;
  const std::size_t n = t.rows();
  const std::size_t f = t.features;
  require(m.k >= 1 && m.k <= n, "KNN: k must be in [1, training rows]");
  require(x.size() == f, "KNN: the sample has the wrong number of features");
  require(m.weights.empty() || m.weights.size() == f, "KNN: one weight per feature");
  for (const double w : m.weights) require(std::isfinite(w) && w >= 0.0, "KNN: weights must be >= 0");
  for (const double v : x) require(std::isfinite(v), "KNN: non-finite feature value");
  std::vector<double> d2(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double* r = t.x.data() + i * f;
    double s = 0.0;
    if (m.weights.empty()) {
      for (std::size_t j = 0; j < f; ++j) {
        const double e = x[j] - r[j];
        s += e * e;
      }
    } else {
      for (std::size_t j = 0; j < f; ++j) {
        const double e = x[j] - r[j];
        s += m.weights[j] * (e * e);
      }
    }
    d2[i] = s;
  }
  if (const auto row = first_overflow(d2))
    throw DomainError("KNN: the squared distance from the sample to training row " + std::to_string(*row) +
                      " overflows a double (each w_j (x_j - t_j)^2 and their sum must stay below 1.8e308, so "
                      "|x_j - t_j| below about 1.3e154 at weight 1): the sample is outside the model's domain");
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  const auto less = [&](std::size_t a, std::size_t b) {
    return d2[a] < d2[b] || (d2[a] == d2[b] && a < b);
  };
  std::nth_element(idx.begin(), idx.begin() + static_cast<std::ptrdiff_t>(m.k - 1), idx.end(), less);
  std::sort(idx.begin(), idx.begin() + static_cast<std::ptrdiff_t>(m.k), less);
  KnnResult r;
  r.neighbours.assign(idx.begin(), idx.begin() + static_cast<std::ptrdiff_t>(m.k));
  const double kth = d2[r.neighbours.back()];
  for (std::size_t i = m.k; i < n && !r.distance_tie; ++i) r.distance_tie = d2[idx[i]] == kth;
  std::vector<int> labels(m.k);
  std::vector<double> dist(m.k);
  for (std::size_t i = 0; i < m.k; ++i) {
    labels[i] = t.y[r.neighbours[i]];
    dist[i] = std::sqrt(d2[r.neighbours[i]]);
  }
  r.label = knn_vote(labels, dist, t.classes, m.vote);
  return r;
}

int predict(const Knn& m, std::span<const double> x) { return knn_query(m, x).label; }

}  // namespace pathref::ml
