#pragma once
/// \file folds.hpp
/// How cin2021 §3.3 splits the 5,456 rows: a hold-out split ("1636 training samples and 3820 test
/// samples") and tenfold cross-validation. Stratified k-fold assigns folds exactly as
/// scikit-learn's StratifiedKFold(n_splits=k, shuffle=False) does, so the folds are identical;
/// the shuffled variant and the hold-out draw from rng::Stream in a spec'd order.
/// Spec: spec/cin2021-ml.md#r[cin2021.folds]
#include <cstddef>
#include <span>
#include <vector>

#include "pathref/rng/mt19937.hpp"

namespace pathref::ml {

/// Test fold (in [0, k)) of every sample, scikit-learn's StratifiedKFold without shuffling:
/// classes are renumbered by first appearance in y; the sorted encoded labels are dealt round
/// robin to the folds (sample i of the sorted list to fold i mod k), giving a[f][c] samples of
/// class c in fold f; then, class by class, the samples of class c in data order get fold 0
/// a[0][c] times, fold 1 a[1][c] times, ... (contiguous blocks).
/// Spec: cin2021.folds. Pre: k >= 2, k <= n, every label >= 0, k <= the largest class count
/// (DomainError; scikit-learn raises the same, and only warns when a smaller class has < k).
[[nodiscard]] std::vector<int> stratified_kfold(std::span<const int> y, std::size_t k);

/// As stratified_kfold, then each class's block of fold numbers is shuffled (class by class in
/// first-appearance order) by Fisher-Yates from the back: for i = m-1 down to 1, j =
/// rng::uniform_index(u, i + 1) with u the next double of `stream`, swap(i, j).
/// Spec: cin2021.folds (shuffle=true). Pre: as stratified_kfold.
[[nodiscard]] std::vector<int> stratified_kfold_shuffled(std::span<const int> y, std::size_t k,
                                                         rng::Stream& stream);

/// Hold-out split: n_test = ceil(test_fraction * n) (as scikit-learn's train_test_split), the
/// permutation of 0..n-1 by Fisher-Yates from the back (as above) with draws from `stream`, the
/// first n_test entries of the permutation are the test rows. Returns true for test rows.
/// Spec: cin2021.folds (holdout). Pre: 0 < test_fraction < 1, 1 <= n_test <= n - 1 (DomainError).
[[nodiscard]] std::vector<bool> holdout_split(std::size_t n, double test_fraction,
                                              rng::Stream& stream);

/// Fisher-Yates from the back over `v` with draws from `stream` (helper of the two above).
/// Spec: cin2021.folds.
void shuffle_in_place(std::span<int> v, rng::Stream& stream);

}  // namespace pathref::ml
