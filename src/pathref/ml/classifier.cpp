#include "pathref/ml/classifier.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
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

// ---- model file -------------------------------------------------------------------------

namespace {

Json tree_json(const Tree& t) {
  Json feature = Json::array(), threshold = Json::array(), left = Json::array(), right = Json::array();
  Json tied = Json::array();
  for (std::size_t i = 0; i < t.nodes.size(); ++i)
    if (t.nodes[i].tied) tied.push_back(i);
  for (const auto& n : t.nodes) {
    feature.push_back(n.feature);
    threshold.push_back(n.threshold);
    left.push_back(n.left);
    right.push_back(n.right);
  }
  return Json{{"feature", feature}, {"threshold", threshold}, {"left", left}, {"right", right},
              {"value", t.value}, {"tied_splits", t.tied_splits}, {"tied", tied}};
}

Tree tree_from(const Json& j, std::size_t classes, std::size_t features) {
  Tree t;
  t.classes = classes;
  t.features = features;
  const auto feature = j.at("feature").get<std::vector<int>>();
  const auto threshold = j.at("threshold").get<std::vector<double>>();
  const auto left = j.at("left").get<std::vector<int>>();
  const auto right = j.at("right").get<std::vector<int>>();
  t.value = j.at("value").get<std::vector<double>>();
  if (feature.size() != threshold.size() || feature.size() != left.size() || feature.size() != right.size())
    throw DomainError("tree: feature, threshold, left and right must have one entry per node");
  for (std::size_t i = 0; i < feature.size(); ++i)
    t.nodes.push_back(Tree::Node{feature[i], threshold[i], left[i], right[i]});
  if (j.contains("tied_splits")) t.tied_splits = j.at("tied_splits").get<std::size_t>();
  if (j.contains("tied"))
    for (const Json& i : j.at("tied")) {
      const auto n = i.get<std::size_t>();
      if (n >= t.nodes.size()) throw DomainError("tree: tied node index out of range");
      t.nodes[n].tied = true;
    }
  validate(t);
  return t;
}

Json model_body(const Model& m) {
  return std::visit(
      [&](const auto& mm) -> Json {
        using T = std::decay_t<decltype(mm)>;
        if constexpr (std::is_same_v<T, GaussianNb>) {
          return Json{{"count", mm.count}, {"epsilon", mm.epsilon}, {"mean", mm.mean}, {"var", mm.var}};
        } else if constexpr (std::is_same_v<T, MultinomialNb>) {
          return Json{{"count", mm.count}, {"feature_log_prob", mm.feature_log_prob}};
        } else if constexpr (std::is_same_v<T, SvmModel>) {
          return Json{{"gamma", mm.gamma}, {"labels", mm.labels}, {"n_sv", mm.n_sv}, {"sv", mm.sv},
                      {"coef", mm.coef}, {"rho", mm.rho}, {"sv_rows", mm.sv_rows}};
        } else if constexpr (std::is_same_v<T, Knn>) {
          return Json{{"x", mm.train.x}, {"y", mm.train.y}};
        } else if constexpr (std::is_same_v<T, Forest>) {
          Json trees = Json::array();
          for (const Tree& t : mm.trees) trees.push_back(tree_json(t));
          return Json{{"max_features", mm.params.max_features}, {"trees", trees}};
        } else {
          return tree_json(mm);
        }
      },
      m.model);
}

}  // namespace

Json to_json(const Model& m) {
  Json labels = Json::array();
  for (std::size_t c = 0; c < m.classes && c < wall_following_labels.size(); ++c)
    labels.push_back(std::string(wall_following_labels[c]));
  return Json{{"format", "pathref-ml-model"}, {"version", 1}, {"kind", to_string(m.kind)},
              {"features", m.features}, {"classes", m.classes}, {"labels", labels},
              {"params", m.params.to_json(m.kind)}, {"model", model_body(m)}};
}

Model model_from_json(const Json& j, const std::string& source) {
  try {
    if (!j.is_object() || j.value("format", "") != "pathref-ml-model")
      throw ParseError(source, 1, 1, "a pathref model file ({\"format\": \"pathref-ml-model\", ...})");
    if (!j.contains("version") || !j.at("version").is_number_integer() || j.at("version").get<int>() != 1)
      throw ParseError(source, 1, 1, "model file version 1");
    Model m;
    m.kind = parse_kind(j.at("kind").get<std::string>());
    m.features = j.at("features").get<std::size_t>();
    m.classes = j.at("classes").get<std::size_t>();
    if (m.features < 1 || m.features > 64 || m.classes < 1 || m.classes > 64)
      throw DomainError("features and classes must be in [1, 64]");
    const Json& p = j.at("params");
    const Json& b = j.at("model");
    const std::size_t f = m.features, k = m.classes;
    const auto need = [](bool ok, const char* what) { if (!ok) throw DomainError(what); };
    switch (m.kind) {
      case Kind::gnb: {
        GaussianNb g;
        g.classes = k;
        g.features = f;
        g.var_smoothing = p.at("var_smoothing").get<double>();
        m.params.var_smoothing = g.var_smoothing;
        g.epsilon = b.at("epsilon").get<double>();
        g.count = b.at("count").get<std::vector<std::int64_t>>();
        g.mean = b.at("mean").get<std::vector<double>>();
        g.var = b.at("var").get<std::vector<double>>();
        need(g.count.size() == k && g.mean.size() == k * f && g.var.size() == k * f, "GNB: sizes");
        std::int64_t n = 0;
        for (const auto c : g.count) { need(c >= 0, "GNB: counts >= 0"); n += c; }
        need(n > 0, "GNB: no training rows");
        for (std::size_t c = 0; c < k; ++c)
          for (std::size_t q = 0; q < f; ++q)
            if (g.count[c] > 0) {
              need(std::isfinite(g.var[c * f + q]) && g.var[c * f + q] > 0.0, "GNB: variances > 0");
              need(std::isfinite(g.mean[c * f + q]), "GNB: finite means");
            }
        g.log_prior.assign(k, -INFINITY);
        for (std::size_t c = 0; c < k; ++c)
          if (g.count[c] > 0) g.log_prior[c] = std::log(static_cast<double>(g.count[c]) / static_cast<double>(n));
        m.model = std::move(g);
        break;
      }
      case Kind::mnb: {
        MultinomialNb g;
        g.classes = k;
        g.features = f;
        g.alpha = p.at("alpha").get<double>();
        m.params.alpha = g.alpha;
        g.count = b.at("count").get<std::vector<std::int64_t>>();
        g.feature_log_prob = b.at("feature_log_prob").get<std::vector<double>>();
        need(g.count.size() == k && g.feature_log_prob.size() == k * f, "MNB: sizes");
        std::int64_t n = 0;
        for (const auto c : g.count) { need(c >= 0, "MNB: counts >= 0"); n += c; }
        need(n > 0, "MNB: no training rows");
        for (const double v : g.feature_log_prob) need(std::isfinite(v) && v <= 0.0, "MNB: log probabilities <= 0");
        g.log_prior.assign(k, -INFINITY);
        const double log_n = std::log(static_cast<double>(n));
        for (std::size_t c = 0; c < k; ++c)
          if (g.count[c] > 0) g.log_prior[c] = std::log(static_cast<double>(g.count[c])) - log_n;
        m.model = std::move(g);
        break;
      }
      case Kind::svm: {
        SvmModel s;
        s.classes = k;
        s.features = f;
        s.gamma = b.at("gamma").get<double>();
        s.labels = b.at("labels").get<std::vector<int>>();
        s.n_sv = b.at("n_sv").get<std::vector<std::size_t>>();
        s.sv = b.at("sv").get<std::vector<double>>();
        s.coef = b.at("coef").get<std::vector<double>>();
        s.rho = b.at("rho").get<std::vector<double>>();
        s.sv_rows = b.at("sv_rows").get<std::vector<std::size_t>>();
        validate(s);
        m.params.svm.c = p.at("C").get<double>();
        m.params.svm.gamma = s.gamma;
        m.model = std::move(s);
        break;
      }
      case Kind::knn: {
        Knn n;
        n.k = p.at("k").get<std::size_t>();
        n.vote = parse_knn_vote(p.at("knn_vote").get<std::string>());
        n.weights = p.at("knn_weights").get<std::vector<double>>();
        n.train.features = f;
        n.train.classes = k;
        n.train.x = b.at("x").get<std::vector<double>>();
        n.train.y = b.at("y").get<std::vector<int>>();
        need(n.train.x.size() == n.train.y.size() * f, "KNN: x must have rows * features values");
        need(n.k >= 1 && n.k <= n.train.rows(), "KNN: k in [1, rows]");
        need(n.weights.empty() || n.weights.size() == f, "KNN: one weight per feature");
        for (const double w : n.weights) need(std::isfinite(w) && w >= 0.0, "KNN: weights >= 0");
        for (const double v : n.train.x) need(std::isfinite(v), "KNN: finite values");
        for (const int y : n.train.y) need(y >= 0 && static_cast<std::size_t>(y) < k, "KNN: labels in range");
        m.params.k = n.k;
        m.params.knn_vote = n.vote;
        m.params.knn_weights = n.weights;
        m.model = std::move(n);
        break;
      }
      case Kind::rf: {
        Forest fo;
        fo.params.trees = p.at("trees").get<std::size_t>();
        fo.params.vote = parse_forest_vote(p.at("forest_vote").get<std::string>());
        fo.params.bootstrap = p.at("bootstrap").get<bool>();
        fo.params.max_features = b.at("max_features").get<std::size_t>();
        for (const Json& t : b.at("trees")) fo.trees.push_back(tree_from(t, k, f));
        need(!fo.trees.empty() && fo.trees.size() == fo.params.trees, "RF: 'trees' trees");
        m.params.forest = fo.params;
        m.params.seed = p.at("seed").get<std::uint32_t>();
        m.model = std::move(fo);
        break;
      }
      case Kind::tree: m.model = tree_from(b, k, f); break;
    }
    return m;
  } catch (const ParseError&) {
    throw;
  } catch (const Error& e) {
    throw ParseError(source, 1, 1, std::string("a valid model: ") + e.what());
  } catch (const nlohmann::json::exception& e) {
    throw ParseError(source, 1, 1, std::string("a valid model: ") + e.what());
  }
}

}  // namespace pathref::ml
