#pragma once
/// \file classifier.hpp
/// The five classifiers of cin2021 §3 (MNB, GNB, SVM, KNN, RF) and a single CART tree behind
/// one interface: train, predict, save/load as versioned JSON ("pathref-ml-model", version 1),
/// and evaluation by cross-validation or hold-out. doi:10.1155/2021/8025730, §3.
/// Spec: spec/cin2021-ml.md (sections "Classifiers" and "Model file")
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathref/ml/data.hpp"
#include "pathref/ml/forest.hpp"
#include "pathref/ml/knn.hpp"
#include "pathref/ml/metrics.hpp"
#include "pathref/ml/naive_bayes.hpp"
#include "pathref/ml/svm.hpp"

namespace pathref::ml {

enum class Kind { mnb, gnb, svm, knn, rf, tree };
/// "mnb" | "gnb" | "svm" | "knn" | "rf" | "tree" (UsageError otherwise).
[[nodiscard]] Kind parse_kind(std::string_view name);
[[nodiscard]] std::string_view to_string(Kind k) noexcept;
/// The paper's five, in the order of its Figs. 3-4: RF, KNN, SVM, GNB, MNB.
[[nodiscard]] std::vector<Kind> paper_classifiers();

/// Every parameter of every classifier, defaulted to scikit-learn 1.2's defaults.
struct Params {
  double var_smoothing = 1e-9;  ///< GNB
  double alpha = 1.0;           ///< MNB (Lidstone; 1 = Laplace)
  SvmParams svm;                ///< SVM: C, gamma, tolerance, cache, shrinking
  std::size_t k = 5;            ///< KNN
  KnnVote knn_vote = KnnVote::uniform;
  std::vector<double> knn_weights;  ///< Eq. 5 per-feature weights; empty = Eq. 4
  ForestParams forest;          ///< RF: trees 100, sqrt features, bootstrap, vote
  std::uint32_t seed = 0;       ///< RF: the stream rng::Stream(seed) of each fit
  /// name=value setter for the CLI (`--set`): var_smoothing, alpha, C, gamma (number, scale,
  /// auto), tol, cache_mb, shrinking (0/1), k, knn_vote, knn_weights (w1:w2:...), trees,
  /// max_features, bootstrap (0/1), forest_vote (majority, mean-proba), seed. UsageError on an
  /// unknown name or a malformed value.
  void set(std::string_view name, std::string_view value);
  /// The parameters of `kind` as JSON (what the CLI prints and saves).
  [[nodiscard]] nlohmann::json to_json(Kind kind) const;
};

using ModelVariant = std::variant<MultinomialNb, GaussianNb, SvmModel, Knn, Forest, Tree>;

struct Model {
  Kind kind = Kind::gnb;
  Params params;
  ModelVariant model;
  std::size_t features = 0;
  std::size_t classes = 0;
};

/// Trains `kind` on `d` (RF: draws from rng::Stream(params.seed); tree: all features in order,
/// no draws). Spec: cin2021.eq1 / eq3 / knn / eq6 / gini by kind.
[[nodiscard]] Model train(Kind kind, const Dataset& d, const Params& params);
/// The class of one sample. Pre: x.size() == features (DomainError).
[[nodiscard]] int predict(const Model& m, std::span<const double> x);
/// Classes of every row of `d`.
[[nodiscard]] std::vector<int> predict_all(const Model& m, const Dataset& d);

// The model file (io::to_json, io::model_from_json, io::parse_model, io::read_model_file) is
// io's: pathref/io/model_file.hpp (docs/architecture.md#layers).

/// Predictions of cross-validation: for every fold f, train on the rows with fold != f and
/// predict the rows with fold == f; returns one prediction per row. Spec: cin2021.folds.
[[nodiscard]] std::vector<int> cross_val_predict(Kind kind, const Dataset& d, std::span<const int> folds,
                                                 const Params& params);

/// Indices of rows where `mask` is `value`.
[[nodiscard]] std::vector<std::size_t> rows_where(const std::vector<bool>& mask, bool value);

}  // namespace pathref::ml
