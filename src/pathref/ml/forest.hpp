#pragma once
/// \file forest.hpp
/// cin2021 Eq. 6, the random forest: CART trees (Breiman et al. 1984) grown on bootstrap
/// samples with floor(sqrt(d)) candidate features per split, combined by a majority vote
/// H(x) = argmax_c sum_t 1[h_t(x) = c] (Eq. 6 as printed) or by averaged class probabilities
/// (scikit-learn's RandomForestClassifier). doi:10.1155/2021/8025730, §3.1, Eq. (6).
/// Every random decision is a draw of rng::Stream in the order spec/cin2021-ml.md states.
/// Spec: spec/cin2021-ml.md#r[cin2021.gini], #r[cin2021.eq6]
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "pathref/ml/data.hpp"
#include "pathref/rng/mt19937.hpp"

namespace pathref::ml {

/// A binary decision tree in preorder: node 0 is the root; an internal node sends x to `left`
/// when x[feature] <= threshold, else to `right`; a leaf has feature = -1. `value` holds the
/// (bootstrap-weighted) training class counts of every node, nodes * classes.
struct Tree {
  struct Node {
    int feature = -1;
    double threshold = 0.0;
    int left = -1, right = -1;
    bool tied = false;  ///< another candidate split scored exactly as this one
  };
  std::size_t classes = 0, features = 0;
  std::vector<Node> nodes;
  std::vector<double> value;
  std::size_t tied_splits = 0;  ///< nodes where another split of a different partition scored equally
};

/// Gini impurity of class counts: 1 - sum_c (n_c / n)^2. Spec: cin2021.gini.
/// Pre: counts >= 0, n = sum > 0 (DomainError).
[[nodiscard]] double gini(std::span<const double> counts);

/// The split score CART maximises (equivalent to the largest Gini decrease): for integer
/// class counts L (left) and R (right), S = sum_c L_c^2 / |L| + sum_c R_c^2 / |R|; the
/// impurity decrease is (S - sum_c N_c^2 / N) / N for N = |L| + |R|. Returned as the exact
/// fraction (numerator, denominator) = (sum L_c^2 |R| + sum R_c^2 |L|, |L| |R|).
/// Spec: cin2021.gini. Pre: |L| > 0, |R| > 0, counts >= 0 (DomainError).
struct SplitScore {
  __extension__ __int128 num = 0;
  __extension__ __int128 den = 1;
};
[[nodiscard]] SplitScore split_score(std::span<const std::int64_t> left,
                                     std::span<const std::int64_t> right);
/// -1, 0, +1 as a < b, a == b, a > b (exact rational comparison). Spec: cin2021.gini.
[[nodiscard]] int compare(const SplitScore& a, const SplitScore& b);

/// Tree growth parameters.
struct TreeParams {
  std::size_t max_features = 0;  ///< candidate features per split; 0 = all, in order 0..d-1
};

/// Grows a CART classification tree (Gini) on rows with integer weights (bootstrap counts;
/// rows with weight 0 are absent). A node is a leaf when it is pure, holds fewer than 2 rows,
/// or every candidate feature is constant in it. Otherwise candidate features are taken in
/// order 0..d-1 (max_features = 0) or drawn (see below), and for each the rows are sorted by the
/// feature; a candidate split lies between consecutive distinct values a < b, threshold
/// a/2 + b/2 (a if that rounds to b), left = {x <= threshold}. The split with the largest exact
/// split_score wins, even with zero decrease; an equal score keeps the earlier candidate
/// (earlier feature in candidate order, then smaller threshold), and an equal score of a
/// different partition is counted in tied_splits. Children are grown left first (preorder).
/// Draws (max_features = m > 0, stream given): at each node that is not a leaf by purity or
/// size, features are drawn without replacement, j = uniform_index(u, |pool|) from the pool
/// (initially 0..d-1; the drawn entry is replaced by the pool's last and the pool shrinks), a
/// feature constant in the node does not count, until m non-constant features are drawn or the
/// pool is empty. Spec: cin2021.gini. Pre: weights.size() == rows, labels in range,
/// max_features <= d, stream != nullptr iff max_features > 0 (DomainError).
[[nodiscard]] Tree grow_tree(const Dataset& d, std::span<const std::int64_t> weights,
                             const TreeParams& p, rng::Stream* stream);

/// Index of the leaf x reaches. Spec: cin2021.eq6. Pre: x.size() == features.
[[nodiscard]] std::size_t leaf_of(const Tree& t, std::span<const double> x);
/// True iff the path of x crosses a node whose split was chosen among exactly equal scores
/// (where another implementation may legitimately split differently). Spec: cin2021.gini.
[[nodiscard]] bool passes_tied_split(const Tree& t, std::span<const double> x);
/// The tree's class: first largest count of the leaf. Spec: cin2021.eq6.
[[nodiscard]] int predict(const Tree& t, std::span<const double> x);

/// How the trees are combined.
enum class ForestVote {
  majority,  ///< Eq. 6 as printed: each tree votes its class; most votes win, tie -> smallest class
  mean_proba,  ///< scikit-learn: average of the trees' leaf class proportions, first largest
};
[[nodiscard]] ForestVote parse_forest_vote(std::string_view name);
[[nodiscard]] std::string_view to_string(ForestVote v) noexcept;

struct ForestParams {
  std::size_t trees = 100;
  std::size_t max_features = 0;  ///< 0 = floor(sqrt(d)) (at least 1)
  bool bootstrap = true;
  ForestVote vote = ForestVote::majority;
};

struct Forest {
  ForestParams params;
  std::vector<Tree> trees;
};

/// Grows `trees` trees from one stream: for each tree in turn, n bootstrap draws
/// (row = uniform_index(u, n), weights = multiplicities; no draws without bootstrap), then the
/// tree's split draws in preorder. Spec: cin2021.eq6. Pre: trees >= 1, rows >= 1 (DomainError).
[[nodiscard]] Forest grow_forest(const Dataset& d, const ForestParams& p, rng::Stream& stream);

/// Combines per-tree leaf class counts (trees * classes, one row per tree) by `vote`.
/// Spec: cin2021.eq6. Pre: rows non-empty, counts >= 0 with a positive sum per tree (DomainError).
[[nodiscard]] int combine_votes(std::span<const double> leaf_counts, std::size_t classes, ForestVote vote);
[[nodiscard]] int predict(const Forest& f, std::span<const double> x);

/// Checks a tree read from JSON (children in range and after their parent, counts) (DomainError).
void validate(const Tree& t);

}  // namespace pathref::ml
