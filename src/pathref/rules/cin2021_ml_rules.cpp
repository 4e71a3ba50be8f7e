// JSON adapters for the cin2021.* rules of the machine-learning decision model
// (spec/cin2021-ml.md): data, Eq. 1-11, knn, gini, folds.
#include <cmath>
#include <string>
#include <vector>

#include "pathref/io/wall_following.hpp"
#include "pathref/core/error.hpp"
#include "pathref/ml/classifier.hpp"
#include "pathref/ml/folds.hpp"
#include "pathref/rules/modules.hpp"

namespace pathref::rules {
namespace {

using namespace pathref::ml;

std::size_t arg_size(const Json& in, const char* key) {
  const long long v = arg_integer(in, key);
  if (v < 0) throw DomainError(std::string(key) + " must be >= 0");
  return static_cast<std::size_t>(v);
}

std::vector<int> arg_ints(const Json& in, const char* key) {
  const Json& v = arg(in, key);
  if (!v.is_array()) throw UsageError(std::string("input '") + key + "' must be an array of integers");
  std::vector<int> out;
  for (const Json& e : v) {
    if (!e.is_number_integer()) throw UsageError(std::string("input '") + key + "' must hold integers");
    const auto x = e.get<long long>();
    if (x < -1000000 || x > 1000000) throw DomainError(std::string(key) + ": value out of range");
    out.push_back(static_cast<int>(x));
  }
  return out;
}

/// Rows of numbers ([[...], ...]) as a Dataset with labels from `ykey` (may be absent).
Dataset arg_dataset(const Json& in, const char* xkey, const char* ykey, std::size_t classes) {
  const Json& rows = arg(in, xkey);
  if (!rows.is_array() || rows.empty()) throw UsageError(std::string("input '") + xkey + "' must be a non-empty array of rows");
  Dataset d;
  d.classes = classes;
  for (const Json& r : rows) {
    if (!r.is_array() || r.empty()) throw UsageError(std::string("input '") + xkey + "' rows must be non-empty arrays");
    if (d.features == 0) d.features = r.size();
    if (r.size() != d.features) throw DomainError(std::string(xkey) + ": rows of different lengths");
    for (const Json& v : r) {
      if (!v.is_number()) throw UsageError(std::string("input '") + xkey + "' must hold numbers");
      d.x.push_back(v.get<double>());
    }
  }
  if (ykey != nullptr) {
    d.y = arg_ints(in, ykey);
    if (d.y.size() != rows.size()) throw DomainError(std::string(ykey) + " must have one label per row");
  } else {
    d.y.assign(rows.size(), 0);
  }
  return d;
}

Json numbers(const std::vector<double>& v) {
  Json a = Json::array();
  for (const double x : v) a.push_back(number(x));
  return a;
}

Json rows_json(const std::vector<double>& flat, std::size_t cols) {
  Json a = Json::array();
  for (std::size_t i = 0; cols > 0 && i < flat.size() / cols; ++i)
    a.push_back(numbers(std::vector<double>(flat.begin() + static_cast<std::ptrdiff_t>(i * cols),
                                            flat.begin() + static_cast<std::ptrdiff_t>((i + 1) * cols))));
  return a;
}

std::vector<double> flat_rows(const Json& in, const char* key, std::size_t cols) {
  std::vector<double> out;
  const Json& rows = arg(in, key);
  if (!rows.is_array()) throw UsageError(std::string("input '") + key + "' must be an array of rows");
  for (const Json& r : rows) {
    if (!r.is_array() || r.size() != cols) throw DomainError(std::string(key) + ": every row must have " + std::to_string(cols) + " values");
    for (const Json& v : r) {
      if (!v.is_number()) throw UsageError(std::string("input '") + key + "' must hold numbers");
      out.push_back(v.get<double>());
    }
  }
  return out;
}

Tree tree_arg(const Json& t, std::size_t classes, std::size_t features) {
  Tree tree;
  tree.classes = classes;
  tree.features = features;
  const std::vector<int> feature = arg_ints(t, "feature");
  const std::vector<double> threshold = arg_numbers(t, "threshold");
  const std::vector<int> left = arg_ints(t, "left");
  const std::vector<int> right = arg_ints(t, "right");
  if (feature.size() != threshold.size() || feature.size() != left.size() || feature.size() != right.size())
    throw DomainError("tree: feature, threshold, left, right need one entry per node");
  for (std::size_t i = 0; i < feature.size(); ++i) tree.nodes.push_back(Tree::Node{feature[i], threshold[i], left[i], right[i]});
  tree.value = flat_rows(t, "value", classes);
  validate(tree);
  return tree;
}

Json confusion_json(const Confusion& c) {
  Json a = Json::array();
  for (std::size_t t = 0; t < c.classes; ++t) {
    Json r = Json::array();
    for (std::size_t p = 0; p < c.classes; ++p) r.push_back(c.at(t, p));
    a.push_back(r);
  }
  return a;
}

Confusion confusion_arg(const Json& in) {
  return confusion_matrix(arg_ints(in, "y_true"), arg_ints(in, "y_pred"), arg_size(in, "classes"));
}

const std::vector<Field> metric_inputs = {
    {"y_true", "integer[]", "true labels in [0, classes)"},
    {"y_pred", "integer[]", "predicted labels in [0, classes)"},
    {"classes", "integer", "K >= 1"}};
const std::vector<Field> averaged_outputs = {
    {"per_class", "number[K]", "the value of each class"},
    {"macro", "number", "mean over the K classes"},
    {"weighted", "number", "weighted by the true counts"},
    {"micro", "number", "from the summed counts"}};

}  // namespace

void register_cin2021_ml_rules(Registry& r) {
  r.add(Rule{"cin2021.data", "UCI wall-following rows 'v1,...,vd,LABEL' -> features and labels (0..3)",
             "pathref::io::parse_wall_following",
             {{"text", "string", "the file's text"}},
             {{"rows", "integer", ""}, {"features", "integer", "d"}, {"x", "number[][]", "rows x d"},
              {"y", "integer[]", "Move-Forward 0, Slight-Right-Turn 1, Sharp-Right-Turn 2, Slight-Left-Turn 3"}},
             [](const Json& in) {
               const Dataset d = io::parse_wall_following(arg_string(in, "text"), "input");
               return Json{{"rows", d.rows()}, {"features", d.features}, {"x", rows_json(d.x, d.features)}, {"y", d.y}};
             }});
  r.add(Rule{"cin2021.eq1", "Naive Bayes (Eq. 1): Gaussian or multinomial joint log-likelihood and class",
             "pathref::ml::fit_gaussian_nb, pathref::ml::fit_multinomial_nb, pathref::ml::joint_log_likelihood",
             {{"likelihood", "string", "gaussian | multinomial"},
              {"x", "number[][]", "training rows"}, {"y", "integer[]", "training labels"},
              {"classes", "integer", "K"}, {"query", "number[]", "the sample"},
              {"var_smoothing", "number", "GNB (default 1e-9)"}, {"alpha", "number", "MNB (default 1)"}},
             {{"jll", "number[K]", "joint log-likelihood per class (-inf: class absent)"}, {"class", "integer", "first argmax"}},
             [](const Json& in) {
               const Dataset d = arg_dataset(in, "x", "y", arg_size(in, "classes"));
               const std::vector<double> q = arg_numbers(in, "query");
               const std::string lik = arg_string(in, "likelihood");
               std::vector<double> jll;
               if (lik == "gaussian") {
                 jll = joint_log_likelihood(fit_gaussian_nb(d, in.contains("var_smoothing") ? arg_number(in, "var_smoothing") : 1e-9), q);
               } else if (lik == "multinomial") {
                 jll = joint_log_likelihood(fit_multinomial_nb(d, in.contains("alpha") ? arg_number(in, "alpha") : 1.0), q);
               } else {
                 throw UsageError("likelihood must be gaussian or multinomial");
               }
               return Json{{"jll", numbers(jll)}, {"class", argmax_first(jll)}};
             }});
  r.add(Rule{"cin2021.eq2", "SVM decision (Eq. 2): RBF one-vs-one decision values and vote of a given model",
             "pathref::ml::svm_decision_values, pathref::ml::predict",
             {{"classes", "integer", "K"}, {"gamma", "number", "> 0"}, {"labels", "integer[]", "present labels, increasing"},
              {"n_sv", "integer[]", "support vectors per present class"}, {"sv", "number[][]", "support vectors grouped by class"},
              {"coef", "number[][]", "(K-1) rows of sum(n_sv) coefficients"}, {"rho", "number[]", "one per pair"},
              {"query", "number[]", "the sample"}},
             {{"decision", "number[]", "f_p per pair (0,1),(0,2),...,(1,2),..."}, {"class", "integer", "winner of the vote"}},
             [](const Json& in) {
               SvmModel m;
               m.classes = arg_size(in, "classes");
               m.gamma = arg_number(in, "gamma");
               m.labels = arg_ints(in, "labels");
               for (const int v : arg_ints(in, "n_sv")) {
                 if (v < 0) throw DomainError("n_sv must be >= 0");
                 m.n_sv.push_back(static_cast<std::size_t>(v));
               }
               const Json& sv = arg(in, "sv");
               m.features = sv.is_array() && !sv.empty() && sv[0].is_array() ? sv[0].size() : 0;
               m.sv = flat_rows(in, "sv", m.features);
               std::size_t l = 0;
               for (const auto n : m.n_sv) l += n;
               m.coef = flat_rows(in, "coef", l);
               m.rho = arg_numbers(in, "rho");
               for (std::size_t s = 0; s < l; ++s) m.sv_rows.push_back(s);
               validate(m);
               const std::vector<double> q = arg_numbers(in, "query");
               return Json{{"decision", numbers(svm_decision_values(m, q))}, {"class", predict(m, q)}};
             }});
  r.add(Rule{"cin2021.eq3", "SVM training (Eq. 3): the soft-margin RBF dual solved by libsvm",
             "pathref::ml::train_svm, pathref::ml::svm_gamma",
             {{"x", "number[][]", "training rows"}, {"y", "integer[]", "labels"}, {"classes", "integer", "K"},
              {"C", "number", "> 0 (default 1)"}, {"gamma", "number|string", "> 0, scale (default) or auto"},
              {"tol", "number", "stopping tolerance (default 1e-3)"}},
             {{"gamma", "number", "the gamma used"}, {"labels", "integer[]", ""}, {"n_sv", "integer[]", ""},
              {"sv_rows", "integer[]", "training rows of the support vectors"}, {"coef", "number[][]", "y_i alpha_i"},
              {"rho", "number[]", "-b per pair"}},
             [](const Json& in) {
               const Dataset d = arg_dataset(in, "x", "y", arg_size(in, "classes"));
               SvmParams p;
               if (in.contains("C")) p.c = arg_number(in, "C");
               if (in.contains("tol")) p.tolerance = arg_number(in, "tol");
               if (in.contains("gamma")) {
                 if (in.at("gamma").is_string()) p.gamma_mode = in.at("gamma").get<std::string>();
                 else p.gamma = arg_number(in, "gamma");
               }
               const SvmModel m = train_svm(d, p);
               return Json{{"gamma", number(m.gamma)}, {"labels", m.labels}, {"n_sv", m.n_sv}, {"sv_rows", m.sv_rows},
                           {"coef", rows_json(m.coef, m.total_sv())}, {"rho", numbers(m.rho)}};
             }});
  r.add(Rule{"cin2021.eq4", "Euclidean distance (Eq. 4)", "pathref::ml::euclidean",
             {{"x", "number[]", ""}, {"y", "number[]", "same length"}}, {{"d", "number", ""}},
             [](const Json& in) { return Json{{"d", number(euclidean(arg_numbers(in, "x"), arg_numbers(in, "y")))}}; }});
  r.add(Rule{"cin2021.eq5", "Weighted Euclidean distance (Eq. 5)", "pathref::ml::weighted_euclidean",
             {{"x", "number[]", ""}, {"y", "number[]", "same length"}, {"w", "number[]", "per-feature weights >= 0"}},
             {{"d", "number", ""}},
             [](const Json& in) {
               return Json{{"d", number(weighted_euclidean(arg_numbers(in, "x"), arg_numbers(in, "y"), arg_numbers(in, "w")))}};
             }});
  r.add(Rule{"cin2021.knn", "k nearest neighbours (ties to the lower row) and their vote (ties to the smallest class)",
             "pathref::ml::knn_query, pathref::ml::knn_vote",
             {{"x", "number[][]", "training rows"}, {"y", "integer[]", "labels"}, {"classes", "integer", "K"},
              {"k", "integer", "1..rows"}, {"query", "number[]", ""}, {"w", "number[]", "optional Eq. 5 weights"},
              {"knn_vote", "string", "uniform (default) | distance"}},
             {{"neighbours", "integer[]", "row indices, nearest first"}, {"distance_tie", "bool", "tie at the k-th place"},
              {"class", "integer", ""}},
             [](const Json& in) {
               Knn m;
               m.train = arg_dataset(in, "x", "y", arg_size(in, "classes"));
               m.k = arg_size(in, "k");
               if (in.contains("w")) m.weights = arg_numbers(in, "w");
               m.vote = parse_knn_vote(opt_string(in, "knn_vote", "uniform"));
               const KnnResult res = knn_query(m, arg_numbers(in, "query"));
               return Json{{"neighbours", res.neighbours}, {"distance_tie", res.distance_tie}, {"class", res.label}};
             }});
  r.add(Rule{"cin2021.gini", "Gini impurity, and a CART tree grown on all features (exact split scores, ties counted)",
             "pathref::ml::gini, pathref::ml::grow_tree",
             {{"op", "string", "impurity | tree"}, {"counts", "number[]", "impurity: class counts"},
              {"x", "number[][]", "tree: training rows"}, {"y", "integer[]", "tree: labels"}, {"classes", "integer", "tree: K"},
              {"weights", "integer[]", "tree: row weights (default 1)"}},
             {{"gini", "number", "impurity"}, {"feature", "integer[]", "tree, preorder; -1 = leaf"}, {"threshold", "number[]", ""},
              {"left", "integer[]", ""}, {"right", "integer[]", ""}, {"value", "number[][]", "class counts per node"},
              {"tied_splits", "integer", ""}},
             [](const Json& in) {
               const std::string op = arg_string(in, "op");
               if (op == "impurity") return Json{{"gini", number(gini(arg_numbers(in, "counts")))}};
               if (op != "tree") throw UsageError("op must be impurity or tree");
               const Dataset d = arg_dataset(in, "x", "y", arg_size(in, "classes"));
               std::vector<std::int64_t> w(d.rows(), 1);
               if (in.contains("weights")) {
                 const auto wi = arg_ints(in, "weights");
                 if (wi.size() != d.rows()) throw DomainError("weights: one per row");
                 for (std::size_t i = 0; i < wi.size(); ++i) w[i] = wi[i];
               }
               const Tree t = grow_tree(d, w, TreeParams{0}, nullptr);
               Json f = Json::array(), th = Json::array(), l = Json::array(), rr = Json::array();
               for (const auto& n : t.nodes) {
                 f.push_back(n.feature);
                 th.push_back(number(n.threshold));
                 l.push_back(n.left);
                 rr.push_back(n.right);
               }
               return Json{{"feature", f}, {"threshold", th}, {"left", l}, {"right", rr},
                           {"value", rows_json(t.value, t.classes)}, {"tied_splits", t.tied_splits}};
             }});
  r.add(Rule{"cin2021.eq6", "Random forest (Eq. 6): the vote of given trees (majority or mean probability), or a seeded forest",
             "pathref::ml::combine_votes, pathref::ml::grow_forest",
             {{"op", "string", "vote | grow"}, {"classes", "integer", "K"},
              {"trees", "object[]", "vote: {feature, threshold, left, right, value}"}, {"query", "number[]", "vote: the sample"},
              {"x", "number[][]", "grow: training rows"}, {"y", "integer[]", "grow: labels"},
              {"n_trees", "integer", "grow: T"}, {"seed", "integer", "grow: rng::Stream seed"},
              {"forest_vote", "string", "majority (default, Eq. 6 as printed) | mean-proba"}},
             {{"class", "integer", "vote: the forest's class"}, {"tree_classes", "integer[]", "vote: each tree's class"},
              {"trees", "object[]", "grow: feature/threshold/value per tree"}, {"draws", "integer", "grow: doubles drawn"}},
             [](const Json& in) {
               const std::string op = arg_string(in, "op");
               const std::size_t k = arg_size(in, "classes");
               const ForestVote vote = parse_forest_vote(opt_string(in, "forest_vote", "majority"));
               if (op == "vote") {
                 const std::vector<double> q = arg_numbers(in, "query");
                 const Json& ts = arg(in, "trees");
                 if (!ts.is_array() || ts.empty()) throw DomainError("trees: at least one tree");
                 std::vector<double> counts;
                 Json classes = Json::array();
                 for (const Json& tj : ts) {
                   const Tree t = tree_arg(tj, k, q.size());
                   const std::size_t leaf = leaf_of(t, q);
                   counts.insert(counts.end(), t.value.begin() + static_cast<std::ptrdiff_t>(leaf * k),
                                 t.value.begin() + static_cast<std::ptrdiff_t>((leaf + 1) * k));
                   classes.push_back(predict(t, q));
                 }
                 return Json{{"class", combine_votes(counts, k, vote)}, {"tree_classes", classes}};
               }
               if (op != "grow") throw UsageError("op must be vote or grow");
               const Dataset d = arg_dataset(in, "x", "y", k);
               ForestParams p;
               p.trees = arg_size(in, "n_trees");
               if (p.trees > 50) throw DomainError("n_trees: at most 50 in a vector");
               p.vote = vote;
               const long long seed = arg_integer(in, "seed");
               if (seed < 0 || seed > 4294967295LL) throw DomainError("seed must be in [0, 2^32)");
               rng::Stream s(static_cast<std::uint32_t>(seed));
               const Forest f = grow_forest(d, p, s);
               Json trees = Json::array();
               for (const Tree& t : f.trees) {
                 Json fe = Json::array(), th = Json::array();
                 for (const auto& n : t.nodes) {
                   fe.push_back(n.feature);
                   th.push_back(number(n.threshold));
                 }
                 trees.push_back(Json{{"feature", fe}, {"threshold", th}, {"value", rows_json(t.value, t.classes)}});
               }
               return Json{{"trees", trees}, {"draws", s.doubles_drawn()}};
             }});
  r.add(Rule{"cin2021.eq7", "Confusion matrix and accuracy (Eq. 7)", "pathref::ml::confusion_matrix, pathref::ml::accuracy",
             metric_inputs, {{"confusion", "integer[K][K]", "row = true class"}, {"accuracy", "number", ""}},
             [](const Json& in) {
               const Confusion c = confusion_arg(in);
               return Json{{"confusion", confusion_json(c)}, {"accuracy", number(accuracy(c))}};
             }});
  r.add(Rule{"cin2021.eq8", "Precision (Eq. 8): per class, macro, weighted, micro", "pathref::ml::precision",
             metric_inputs, averaged_outputs, [](const Json& in) {
               const Confusion c = confusion_arg(in);
               return Json{{"per_class", numbers(precision_per_class(c))}, {"macro", number(precision(c, Average::macro))},
                           {"weighted", number(precision(c, Average::weighted))}, {"micro", number(precision(c, Average::micro))}};
             }});
  r.add(Rule{"cin2021.eq9", "Recall (Eq. 9): per class, macro, weighted, micro", "pathref::ml::recall",
             metric_inputs, averaged_outputs, [](const Json& in) {
               const Confusion c = confusion_arg(in);
               return Json{{"per_class", numbers(recall_per_class(c))}, {"macro", number(recall(c, Average::macro))},
                           {"weighted", number(recall(c, Average::weighted))}, {"micro", number(recall(c, Average::micro))}};
             }});
  r.add(Rule{"cin2021.eq10", "F1 (Eq. 10): per class, macro, weighted, micro", "pathref::ml::f1",
             metric_inputs, averaged_outputs, [](const Json& in) {
               const Confusion c = confusion_arg(in);
               return Json{{"per_class", numbers(f1_per_class(c))}, {"macro", number(f1(c, Average::macro))},
                           {"weighted", number(f1(c, Average::weighted))}, {"micro", number(f1(c, Average::micro))}};
             }});
  r.add(Rule{"cin2021.eq11", "Matthews correlation coefficient (Eq. 11), multi-class (Gorodkin)", "pathref::ml::mcc",
             metric_inputs, {{"mcc", "number", "in [-1, 1]; 0 when the denominator is 0"}},
             [](const Json& in) { return Json{{"mcc", number(mcc(confusion_arg(in)))}}; }});
  r.add(Rule{"cin2021.folds", "Stratified k-fold (as scikit-learn, unshuffled or shuffled by rng::Stream) and the hold-out split",
             "pathref::ml::stratified_kfold, pathref::ml::stratified_kfold_shuffled, pathref::ml::holdout_split",
             {{"mode", "string", "stratified | shuffled | holdout"}, {"y", "integer[]", "labels (stratified, shuffled)"},
              {"k", "integer", "folds"}, {"n", "integer", "holdout: rows"}, {"test_fraction", "number", "holdout"},
              {"seed", "integer", "shuffled, holdout"}},
             {{"folds", "integer[]", "test fold per sample"}, {"test", "bool[]", "holdout: test rows"}, {"draws", "integer", ""}},
             [](const Json& in) {
               const std::string mode = arg_string(in, "mode");
               const auto seed_of = [&]() {
                 const long long s = arg_integer(in, "seed");
                 if (s < 0 || s > 4294967295LL) throw DomainError("seed must be in [0, 2^32)");
                 return static_cast<std::uint32_t>(s);
               };
               if (mode == "stratified") return Json{{"folds", stratified_kfold(arg_ints(in, "y"), arg_size(in, "k"))}};
               if (mode == "shuffled") {
                 rng::Stream s(seed_of());
                 const auto f = stratified_kfold_shuffled(arg_ints(in, "y"), arg_size(in, "k"), s);
                 return Json{{"folds", f}, {"draws", s.doubles_drawn()}};
               }
               if (mode == "holdout") {
                 const std::size_t n = arg_size(in, "n");
                 if (n > 100000) throw DomainError("n: at most 100000 in a vector");
                 rng::Stream s(seed_of());
                 const auto t = holdout_split(n, arg_number(in, "test_fraction"), s);
                 return Json{{"test", std::vector<bool>(t.begin(), t.end())}, {"draws", s.doubles_drawn()}};
               }
               throw UsageError("mode must be stratified, shuffled or holdout");
             }});
}

}  // namespace pathref::rules
