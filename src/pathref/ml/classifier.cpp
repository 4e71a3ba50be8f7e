#include "pathref/ml/classifier.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "pathref/core/error.hpp"

namespace pathref::ml {

using Json = nlohmann::json;

Kind parse_kind(std::string_view name) {
  if (name == "mnb") return Kind::mnb;
  if (name == "gnb") return Kind::gnb;
  if (name == "svm") return Kind::svm;
  if (name == "knn") return Kind::knn;
  if (name == "rf") return Kind::rf;
  if (name == "tree") return Kind::tree;
  throw UsageError("unknown classifier '" + std::string(name) + "' (mnb, gnb, svm, knn, rf, tree)");
}

std::string_view to_string(Kind k) noexcept {
  switch (k) {
    case Kind::mnb: return "mnb";
    case Kind::gnb: return "gnb";
    case Kind::svm: return "svm";
    case Kind::knn: return "knn";
    case Kind::rf: return "rf";
    case Kind::tree: return "tree";
  }
  return "gnb";
}

std::vector<Kind> paper_classifiers() { return {Kind::rf, Kind::knn, Kind::svm, Kind::gnb, Kind::mnb}; }

namespace {

double to_double(std::string_view name, std::string_view v) {
  double out = 0.0;
  const auto r = std::from_chars(v.data(), v.data() + v.size(), out);
  if (r.ec != std::errc() || r.ptr != v.data() + v.size() || !std::isfinite(out))
    throw UsageError("parameter " + std::string(name) + ": '" + std::string(v) + "' is not a finite number");
  return out;
}

std::size_t to_size(std::string_view name, std::string_view v) {
  std::size_t out = 0;
  const auto r = std::from_chars(v.data(), v.data() + v.size(), out);
  if (r.ec != std::errc() || r.ptr != v.data() + v.size())
    throw UsageError("parameter " + std::string(name) + ": '" + std::string(v) + "' is not a non-negative integer");
  return out;
}

bool to_bool(std::string_view name, std::string_view v) {
  if (v == "1" || v == "true") return true;
  if (v == "0" || v == "false") return false;
  throw UsageError("parameter " + std::string(name) + ": '" + std::string(v) + "' is not 0/1");
}

}  // namespace

void Params::set(std::string_view name, std::string_view value) {
  if (name == "var_smoothing") var_smoothing = to_double(name, value);
  else if (name == "alpha") alpha = to_double(name, value);
  else if (name == "C") svm.c = to_double(name, value);
  else if (name == "gamma") {
    if (value == "scale" || value == "auto") {
      svm.gamma = 0.0;
      svm.gamma_mode = std::string(value);
    } else {
      svm.gamma = to_double(name, value);
      if (!(svm.gamma > 0.0)) throw UsageError("parameter gamma must be > 0, scale or auto");
    }
  } else if (name == "tol") svm.tolerance = to_double(name, value);
  else if (name == "cache_mb") svm.cache_mb = to_double(name, value);
  else if (name == "shrinking") svm.shrinking = to_bool(name, value);
  else if (name == "k") k = to_size(name, value);
  else if (name == "knn_vote") knn_vote = parse_knn_vote(value);
  else if (name == "knn_weights") {
    knn_weights.clear();
    std::size_t start = 0;
    while (true) {
      const std::size_t colon = value.find(':', start);
      knn_weights.push_back(to_double(name, value.substr(start, colon == std::string_view::npos ? value.npos : colon - start)));
      if (colon == std::string_view::npos) break;
      start = colon + 1;
    }
  } else if (name == "trees") forest.trees = to_size(name, value);
  else if (name == "max_features") forest.max_features = to_size(name, value);
  else if (name == "bootstrap") forest.bootstrap = to_bool(name, value);
  else if (name == "forest_vote") forest.vote = parse_forest_vote(value);
  else if (name == "seed") {
    const std::size_t s = to_size(name, value);
    if (s > 0xFFFFFFFFULL) throw UsageError("parameter seed must be < 2^32");
    seed = static_cast<std::uint32_t>(s);
  } else {
    throw UsageError("unknown parameter '" + std::string(name) +
                     "' (var_smoothing, alpha, C, gamma, tol, cache_mb, shrinking, k, knn_vote, "
                     "knn_weights, trees, max_features, bootstrap, forest_vote, seed)");
  }
}

Json Params::to_json(Kind kind) const {
  switch (kind) {
    case Kind::gnb: return Json{{"var_smoothing", var_smoothing}};
    case Kind::mnb: return Json{{"alpha", alpha}, {"fit_prior", true}};
    case Kind::svm:
      return Json{{"kernel", "rbf"}, {"C", svm.c},
                  {"gamma", svm.gamma > 0.0 ? Json(svm.gamma) : Json(svm.gamma_mode)},
                  {"tol", svm.tolerance}, {"cache_mb", svm.cache_mb}, {"shrinking", svm.shrinking},
                  {"multiclass", "one-vs-one"}};
    case Kind::knn:
      return Json{{"k", k}, {"knn_vote", to_string(knn_vote)},
                  {"metric", knn_weights.empty() ? "euclidean (Eq. 4)" : "weighted euclidean (Eq. 5)"},
                  {"knn_weights", knn_weights}, {"distance_tie", "lower training row index"},
                  {"vote_tie", "smallest class"}};
    case Kind::rf:
      return Json{{"trees", forest.trees},
                  {"max_features", forest.max_features == 0 ? Json("sqrt") : Json(forest.max_features)},
                  {"bootstrap", forest.bootstrap}, {"forest_vote", to_string(forest.vote)},
                  {"criterion", "gini"}, {"seed", seed}};
    case Kind::tree:
      return Json{{"criterion", "gini"}, {"max_features", "all, in order"}, {"max_depth", nullptr}};
  }
  return Json::object();
}

Model train(Kind kind, const Dataset& d, const Params& params) {
  Model m;
  m.kind = kind;
  m.params = params;
  m.features = d.features;
  m.classes = d.classes;
  switch (kind) {
    case Kind::mnb: m.model = fit_multinomial_nb(d, params.alpha); break;
    case Kind::gnb: m.model = fit_gaussian_nb(d, params.var_smoothing); break;
    case Kind::svm: m.model = train_svm(d, params.svm); break;
    case Kind::knn: {
      Knn k{params.k, params.knn_vote, params.knn_weights, d};
      require(k.k >= 1 && k.k <= d.rows(), "KNN: k must be in [1, training rows]");
      require(k.weights.empty() || k.weights.size() == d.features, "KNN: one weight per feature");
      m.model = std::move(k);
      break;
    }
    case Kind::rf: {
      rng::Stream s(params.seed);
      m.model = grow_forest(d, params.forest, s);
      break;
    }
    case Kind::tree: {
      const std::vector<std::int64_t> w(d.rows(), 1);
      m.model = grow_tree(d, w, TreeParams{0}, nullptr);
      break;
    }
  }
  return m;
}

int predict(const Model& m, std::span<const double> x) {
  return std::visit([&](const auto& mm) { return predict(mm, x); }, m.model);
}

std::vector<int> predict_all(const Model& m, const Dataset& d) {
  std::vector<int> out(d.rows());
  for (std::size_t i = 0; i < d.rows(); ++i) out[i] = predict(m, d.row(i));
  return out;
}

std::vector<std::size_t> rows_where(const std::vector<bool>& mask, bool value) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < mask.size(); ++i)
    if (mask[i] == value) out.push_back(i);
  return out;
}

std::vector<int> cross_val_predict(Kind kind, const Dataset& d, std::span<const int> folds,
                                   const Params& params) {
  require(folds.size() == d.rows(), "cross_val_predict: one fold per row");
  const int k = folds.empty() ? 0 : *std::max_element(folds.begin(), folds.end()) + 1;
  std::vector<int> out(d.rows(), -1);
  for (int f = 0; f < k; ++f) {
    std::vector<std::size_t> train_rows, test_rows;
    for (std::size_t i = 0; i < d.rows(); ++i) (folds[i] == f ? test_rows : train_rows).push_back(i);
    if (test_rows.empty()) continue;
    const Model m = train(kind, subset(d, train_rows), params);
    for (const std::size_t i : test_rows) out[i] = predict(m, d.row(i));
  }
  return out;
}

// The model file (to_json, model_from_json, parse_model, read_model_file) is io's:
// src/pathref/io/model_file.cpp (docs/architecture.md#layers).

}  // namespace pathref::ml
