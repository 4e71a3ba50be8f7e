#pragma once
/// \file knn.hpp
/// cin2021 Eq. 4-5, k-nearest neighbours: Euclidean and weighted Euclidean distance, the k
/// nearest training rows and their vote. doi:10.1155/2021/8025730, §3.1, Eqs. (4)-(5).
/// Defaults are scikit-learn 1.2's KNeighborsClassifier (k = 5, uniform vote, Euclidean).
/// Spec: spec/cin2021-ml.md#r[cin2021.eq4], #r[cin2021.eq5], #r[cin2021.knn]
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "pathref/ml/data.hpp"

namespace pathref::ml {

/// Eq. 4: sqrt(sum_i (x_i - y_i)^2), the sum left to right.
/// Spec: cin2021.eq4. Pre: equal lengths >= 1, finite values (DomainError).
[[nodiscard]] double euclidean(std::span<const double> x, std::span<const double> y);

/// Eq. 5: sqrt(sum_i w_i (x_i - y_i)^2), the sum left to right, w_i (x_i - y_i)^2 computed as
/// w_i * ((x_i - y_i) * (x_i - y_i)). Spec: cin2021.eq5. Pre: equal lengths >= 1, finite values,
/// every w_i >= 0 (DomainError).
[[nodiscard]] double weighted_euclidean(std::span<const double> x, std::span<const double> y,
                                        std::span<const double> w);

/// How the k neighbours vote.
enum class KnnVote {
  uniform,   ///< one vote each (scikit-learn weights='uniform'; default)
  distance,  ///< weight 1/d; if any neighbour is at d = 0, those weigh 1 and the others 0
};
[[nodiscard]] KnnVote parse_knn_vote(std::string_view name);
[[nodiscard]] std::string_view to_string(KnnVote v) noexcept;

/// A KNN "model": the training rows and the parameters.
struct Knn {
  std::size_t k = 5;
  KnnVote vote = KnnVote::uniform;
  std::vector<double> weights;  ///< per-feature w_i of Eq. 5; empty = Eq. 4 (all 1)
  Dataset train;
};

/// The outcome of one query.
struct KnnResult {
  int label = 0;
  std::vector<std::size_t> neighbours;  ///< training row indices, nearest first
  bool distance_tie = false;  ///< a row outside the k has the same distance as the k-th
};

/// The index of the first squared distance that is not finite (an overflow of Eq. 4/5's sum:
/// +inf, or NaN from 0 * inf at a zero weight), or nullopt. Spec: cin2021.knn (domain).
[[nodiscard]] std::optional<std::size_t> first_overflow(std::span<const double> squared_distances);

/// The k nearest training rows of x, ordered by (squared distance, training row index): the
/// lower row index wins a distance tie, also at the k-th place. Votes per class (uniform or
/// distance weights summed nearest first); the class with the most votes wins, a vote tie goes
/// to the smallest class index. Spec: cin2021.knn.
/// Pre: 1 <= k <= training rows, x.size() == features, weights empty or one >= 0 per feature,
/// every squared distance finite (no overflow, first_overflow; DomainError naming the row).
[[nodiscard]] KnnResult knn_query(const Knn& m, std::span<const double> x);
[[nodiscard]] int predict(const Knn& m, std::span<const double> x);

/// The KNN vote alone over given neighbour labels and distances (nearest first).
/// Spec: cin2021.knn. Pre: labels in [0, classes), equal lengths >= 1, distances >= 0 (DomainError).
[[nodiscard]] int knn_vote(std::span<const int> labels, std::span<const double> distances,
                           std::size_t classes, KnnVote vote);

}  // namespace pathref::ml
