// Model files of `pathref learn --save-model` / `classify --model` (spec/cin2021-ml.md#model-file).
#include "pathref/io/model_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "pathref/core/error.hpp"
#include "pathref/io/input_file.hpp"
#include "pathref/io/json_reader.hpp"
#include "pathref/io/json_text.hpp"

namespace pathref::io {

using namespace pathref::ml;  // the model types this file writes and reads
using Json = nlohmann::json;

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

/// The model file reader (spec/cin2021-ml.md#model-file): JsonReader plus arrays of numbers
/// and integers; every refusal is `FILE:LINE:COLUMN: /pointer: expected ...`.
class ModelReader : public JsonReader {
 public:
  using JsonReader::JsonReader;

  /// An array of finite numbers.
  [[nodiscard]] std::vector<double> numbers(const Json& v, const std::string& ptr, double lo = -max_value,
                                            double hi = max_value) const {
    const Json& a = array(v, ptr, max_values);
    std::vector<double> out;
    out.reserve(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) out.push_back(number(a[i], ptr + "/" + std::to_string(i), lo, hi));
    return out;
  }

  /// An array of integers in [lo, hi], as T.
  template <class T>
  [[nodiscard]] std::vector<T> integers(const Json& v, const std::string& ptr, std::int64_t lo, std::int64_t hi) const {
    const Json& a = array(v, ptr, max_values);
    std::vector<T> out;
    out.reserve(a.size());
    for (std::size_t i = 0; i < a.size(); ++i)
      out.push_back(static_cast<T>(integer(a[i], ptr + "/" + std::to_string(i), lo, hi)));
    return out;
  }

  /// Fails at `ptr` unless `n` == `want` ("expected WANT values (WHY), got N").
  void size_is(std::size_t n, std::size_t want, const std::string& ptr, const std::string& why) const {
    if (n != want)
      fail(ptr, "expected " + std::to_string(want) + " values (" + why + "), got " + std::to_string(n));
  }

  /// The string at `ptr`, which must be one of `allowed` (the input is quoted through printable).
  [[nodiscard]] std::string one_of(const Json& v, const std::string& ptr, std::initializer_list<const char*> allowed) const {
    const std::string s = string(v, ptr);
    std::string list;
    for (const char* a : allowed) {
      if (s == a) return s;
      list += std::string(list.empty() ? "" : ", ") + a;
    }
    fail(ptr, "expected one of " + list + ", got \"" + printable(s) + "\"");
  }

  static constexpr std::size_t max_values = std::size_t{1} << 24;
  static constexpr double max_value = std::numeric_limits<double>::max();
  static constexpr std::int64_t max_int = std::numeric_limits<int>::max();
};

/// A tree of a model file at `ptr` (a tree model's /model, or /model/trees/N of a forest).
Tree tree_from(const ModelReader& rd, const Json& j, const std::string& ptr, std::size_t classes, std::size_t features) {
  Tree t;
  t.classes = classes;
  t.features = features;
  const auto at = [&](const char* key, std::string_view expected) -> const Json& {
    return rd.need(j, ptr, key, expected);
  };
  const auto feature = rd.integers<int>(at("feature", "one feature index per node, -1 at a leaf"), ptr + "/feature", -1,
                                        static_cast<std::int64_t>(features) - 1);
  const std::size_t n = feature.size();
  const auto threshold = rd.numbers(at("threshold", "one threshold per node"), ptr + "/threshold");
  rd.size_is(threshold.size(), n, ptr + "/threshold", "one per node, as feature");
  const auto left = rd.integers<int>(at("left", "one child index per node, -1 at a leaf"), ptr + "/left", -1,
                                     ModelReader::max_int);
  rd.size_is(left.size(), n, ptr + "/left", "one per node, as feature");
  const auto right = rd.integers<int>(at("right", "one child index per node, -1 at a leaf"), ptr + "/right", -1,
                                      ModelReader::max_int);
  rd.size_is(right.size(), n, ptr + "/right", "one per node, as feature");
  t.value = rd.numbers(at("value", "nodes * classes counts"), ptr + "/value", 0.0, ModelReader::max_value);
  rd.size_is(t.value.size(), n * classes, ptr + "/value", "nodes * classes");
  for (std::size_t i = 0; i < n; ++i) t.nodes.push_back(Tree::Node{feature[i], threshold[i], left[i], right[i]});
  if (const Json* v = find(j, "tied_splits"))
    t.tied_splits = static_cast<std::size_t>(rd.integer(*v, ptr + "/tied_splits", 0, ModelReader::max_int));
  if (const Json* v = find(j, "tied")) {
    const auto tied = rd.integers<std::size_t>(*v, ptr + "/tied", 0, static_cast<std::int64_t>(n) - 1);
    for (const std::size_t i : tied) t.nodes[i].tied = true;
  }
  try {
    validate(t);
  } catch (const DomainError& e) {
    rd.fail(ptr, std::string("expected a valid tree (") + e.what() + ")");
  }
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

namespace {

/// model_from_json with the file's text at hand for line and column (parse_model).
Model read_model(const Json& j, const std::string& source, std::string_view text) {
  const ModelReader rd(source, text);
  if (!j.is_object())
    rd.fail("", "expected a pathref model file (an object {\"format\": \"pathref-ml-model\", ...}), got " +
                    ModelReader::kind(j));
  const std::string format = rd.string(rd.need(j, "", "format", "\"pathref-ml-model\""), "/format");
  if (format != "pathref-ml-model")
    rd.fail("/format", "expected \"pathref-ml-model\", got \"" + printable(format) + "\"");
  const Json& version = rd.need(j, "", "version", "1");
  if (version != 1)
    rd.fail("/version", "expected 1 (this reader reads model file version 1), got " +
                            (version.is_number() ? version.dump() : ModelReader::kind(version)));
  Model m;
  m.kind = parse_kind(rd.one_of(rd.need(j, "", "kind", "mnb, gnb, svm, knn, rf or tree"), "/kind",
                                {"mnb", "gnb", "svm", "knn", "rf", "tree"}));
  m.features = static_cast<std::size_t>(rd.integer(rd.need(j, "", "features", "an integer in [1, 64]"), "/features", 1, 64));
  m.classes = static_cast<std::size_t>(rd.integer(rd.need(j, "", "classes", "an integer in [1, 64]"), "/classes", 1, 64));
  const Json& p = rd.need(j, "", "params", "the classifier's parameters");
  if (!p.is_object()) rd.fail("/params", "expected an object, got " + ModelReader::kind(p));
  const Json& b = rd.need(j, "", "model", "the fitted state");
  if (!b.is_object()) rd.fail("/model", "expected an object, got " + ModelReader::kind(b));
  const std::size_t f = m.features, k = m.classes;
  const auto param = [&](const char* key, std::string_view expected) -> const Json& {
    return rd.need(p, "/params", key, expected);
  };
  const auto body = [&](const char* key, std::string_view expected) -> const Json& {
    return rd.need(b, "/model", key, expected);
  };
  /// Class counts: k integers >= 0 with a positive sum.
  const auto counts = [&]() {
    auto c = rd.integers<std::int64_t>(body("count", "training rows per class"), "/model/count", 0,
                                       std::int64_t{1} << 53);
    rd.size_is(c.size(), k, "/model/count", "one per class");
    std::int64_t n = 0;
    for (const auto x : c) n += x;
    if (n == 0) rd.fail("/model/count", "expected at least one training row (a positive count)");
    return c;
  };
  const double big = ModelReader::max_value;
  switch (m.kind) {
    case Kind::gnb: {
      GaussianNb g;
      g.classes = k;
      g.features = f;
      g.var_smoothing = rd.number(param("var_smoothing", "a number"), "/params/var_smoothing", -big, big);
      m.params.var_smoothing = g.var_smoothing;
      g.epsilon = rd.number(body("epsilon", "a number"), "/model/epsilon", -big, big);
      g.count = counts();
      g.mean = rd.numbers(body("mean", "classes * features means"), "/model/mean");
      rd.size_is(g.mean.size(), k * f, "/model/mean", "classes * features");
      g.var = rd.numbers(body("var", "classes * features variances"), "/model/var");
      rd.size_is(g.var.size(), k * f, "/model/var", "classes * features");
      for (std::size_t c = 0; c < k; ++c)
        for (std::size_t q = 0; q < f; ++q)
          if (g.count[c] > 0 && !(g.var[c * f + q] > 0.0))
            rd.fail("/model/var/" + std::to_string(c * f + q),
                    "expected a variance > 0 (class " + std::to_string(c) + " has training rows), got " +
                        ModelReader::fmt(g.var[c * f + q]));
      const double n = static_cast<double>(std::accumulate(g.count.begin(), g.count.end(), std::int64_t{0}));
      g.log_prior.assign(k, -INFINITY);
      for (std::size_t c = 0; c < k; ++c)
        if (g.count[c] > 0) g.log_prior[c] = std::log(static_cast<double>(g.count[c]) / n);
      m.model = std::move(g);
      break;
    }
    case Kind::mnb: {
      MultinomialNb g;
      g.classes = k;
      g.features = f;
      g.alpha = rd.number(param("alpha", "a number"), "/params/alpha", -big, big);
      m.params.alpha = g.alpha;
      g.count = counts();
      g.feature_log_prob = rd.numbers(body("feature_log_prob", "classes * features log probabilities <= 0"),
                                      "/model/feature_log_prob", -big, 0.0);
      rd.size_is(g.feature_log_prob.size(), k * f, "/model/feature_log_prob", "classes * features");
      const double log_n =
          std::log(static_cast<double>(std::accumulate(g.count.begin(), g.count.end(), std::int64_t{0})));
      g.log_prior.assign(k, -INFINITY);
      for (std::size_t c = 0; c < k; ++c)
        if (g.count[c] > 0) g.log_prior[c] = std::log(static_cast<double>(g.count[c])) - log_n;
      m.model = std::move(g);
      break;
    }
    case Kind::svm: {
      SvmModel s;
      s.classes = k;
      s.features = f;
      s.gamma = rd.number(body("gamma", "a number > 0"), "/model/gamma", 0.0, big, true);
      s.labels = rd.integers<int>(body("labels", "the classes present, increasing"), "/model/labels", 0,
                                  static_cast<std::int64_t>(k) - 1);
      s.n_sv = rd.integers<std::size_t>(body("n_sv", "support vectors per present class"), "/model/n_sv", 0,
                                        ModelReader::max_int);
      s.sv = rd.numbers(body("sv", "the support vectors, sum(n_sv) * features values"), "/model/sv");
      s.coef = rd.numbers(body("coef", "(K-1) * sum(n_sv) coefficients"), "/model/coef");
      s.rho = rd.numbers(body("rho", "K(K-1)/2 intercepts"), "/model/rho");
      s.sv_rows = rd.integers<std::size_t>(body("sv_rows", "the training row of each support vector"),
                                           "/model/sv_rows", 0, std::int64_t{1} << 53);
      try {
        validate(s);
      } catch (const DomainError& e) {
        rd.fail("/model", std::string("expected a consistent SVM model (") + e.what() + ")");
      }
      m.params.svm.c = rd.number(param("C", "a number"), "/params/C", -big, big);
      m.params.svm.gamma = s.gamma;
      m.model = std::move(s);
      break;
    }
    case Kind::knn: {
      Knn n;
      n.train.features = f;
      n.train.classes = k;
      n.train.y = rd.integers<int>(body("y", "the class of each training row"), "/model/y", 0,
                                   static_cast<std::int64_t>(k) - 1);
      if (n.train.y.empty()) rd.fail("/model/y", "expected at least one training row");
      n.train.x = rd.numbers(body("x", "rows * features training values"), "/model/x");
      rd.size_is(n.train.x.size(), n.train.y.size() * f, "/model/x", "rows of /model/y * features");
      n.k = static_cast<std::size_t>(rd.integer(param("k", "an integer in [1, training rows]"), "/params/k", 1,
                                                static_cast<std::int64_t>(n.train.y.size())));
      n.vote = parse_knn_vote(rd.one_of(param("knn_vote", "uniform or distance"), "/params/knn_vote", {"uniform", "distance"}));
      n.weights = rd.numbers(param("knn_weights", "[] or one weight >= 0 per feature"), "/params/knn_weights", 0.0, big);
      if (!n.weights.empty()) rd.size_is(n.weights.size(), f, "/params/knn_weights", "[] or one per feature");
      m.params.k = n.k;
      m.params.knn_vote = n.vote;
      m.params.knn_weights = n.weights;
      m.model = std::move(n);
      break;
    }
    case Kind::rf: {
      Forest fo;
      fo.params.trees = static_cast<std::size_t>(rd.integer(param("trees", "an integer >= 1"), "/params/trees", 1, 1000000));
      fo.params.vote = parse_forest_vote(
          rd.one_of(param("forest_vote", "majority or mean-proba"), "/params/forest_vote", {"majority", "mean-proba"}));
      fo.params.bootstrap = rd.boolean(param("bootstrap", "true or false"), "/params/bootstrap");
      m.params.seed = static_cast<std::uint32_t>(rd.integer(param("seed", "an integer in [0, 4294967295]"), "/params/seed", 0, 4294967295LL));
      fo.params.max_features = static_cast<std::size_t>(
          rd.integer(body("max_features", "an integer in [0, features]"), "/model/max_features", 0, static_cast<std::int64_t>(f)));
      const Json& trees = rd.array(body("trees", "the forest's trees"), "/model/trees", 1000000);
      rd.size_is(trees.size(), fo.params.trees, "/model/trees", "one tree per /params/trees");
      for (std::size_t i = 0; i < trees.size(); ++i)
        fo.trees.push_back(tree_from(rd, trees[i], "/model/trees/" + std::to_string(i), k, f));
      m.params.forest = fo.params;
      m.model = std::move(fo);
      break;
    }
    case Kind::tree: m.model = tree_from(rd, b, "/model", k, f); break;
  }
  return m;
}

}  // namespace

Model model_from_json(const Json& j, const std::string& source) { return read_model(j, source, {}); }

Model parse_model(std::string_view text, const std::string& source) {
  const Json j = parse_json_text(text, source);
  return read_model(j, source, text);
}

Model read_model_file(const std::string& path) {
  return parse_model(read_input_file(path, "model file", document_limits.max_bytes), path);
}

}  // namespace pathref::io
