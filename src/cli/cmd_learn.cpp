// `pathref learn` (train and evaluate cin2021's classifiers on the UCI wall-following data by
// cross-validation or hold-out) and `pathref classify` (decide a movement with a saved model).
// Spec: spec/cin2021-ml.md#cli.
#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "pathref/io/model_file.hpp"
#include "pathref/io/wall_following.hpp"
#include "pathref/io/json_text.hpp"
#include "pathref/io/map_file.hpp"
#include "pathref/core/error.hpp"
#include "pathref/ml/classifier.hpp"
#include "pathref/ml/folds.hpp"

namespace pathref::cli {
namespace {

using Json = nlohmann::json;
using namespace pathref::ml;

/// `doc` with pathref_version and golden_set_version set (docs/versioning.md).
Json stamped(Json doc) {
  stamp_version(doc);
  return doc;
}

struct LearnOptions {
  std::string data;
  std::string classifiers = "all";
  std::string cv;
  std::string holdout;
  bool shuffle = false;
  std::string seed = "0";
  std::vector<std::string> set;
  bool json = false;
  std::string predictions;
  std::string save_model;
  std::string only_folds;
};

struct ClassifyOptions {
  std::string model;
  std::vector<std::string> values;
  bool json = false;
};

std::uint32_t parse_seed(const std::string& s) {
  if (s.empty() || s.size() > 10 || s.find_first_not_of("0123456789") != std::string::npos)
    throw UsageError("--seed expects a decimal integer from 0 to 4294967295, got '" + s + "'");
  const unsigned long long v = std::stoull(s);
  if (v > 4294967295ULL) throw UsageError("--seed expects a decimal integer from 0 to 4294967295, got '" + s + "'");
  return static_cast<std::uint32_t>(v);
}

std::vector<Kind> parse_kinds(const std::string& list) {
  if (list == "all") return paper_classifiers();
  std::vector<Kind> out;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(parse_kind(item));
  if (out.empty()) throw UsageError("--classifier expects all or a comma-separated list of mnb, gnb, svm, knn, rf, tree");
  return out;
}

Params parse_params(const std::vector<std::string>& sets, std::uint32_t seed) {
  Params p;
  p.seed = seed;
  for (const std::string& s : sets) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0) throw UsageError("--set expects name=value, got '" + s + "'");
    p.set(std::string_view(s).substr(0, eq), std::string_view(s).substr(eq + 1));
  }
  return p;
}

Json scores_json(const Scores& s) {
  Json cm = Json::array();
  for (std::size_t t = 0; t < s.confusion.classes; ++t) {
    Json row = Json::array();
    for (std::size_t p = 0; p < s.confusion.classes; ++p) row.push_back(s.confusion.at(t, p));
    cm.push_back(row);
  }
  return Json{{"confusion", cm},
              {"accuracy", s.accuracy},
              {"precision", {{"macro", s.precision_macro}, {"weighted", s.precision_weighted}, {"micro", s.precision_micro}, {"per_class", s.precision_class}}},
              {"recall", {{"macro", s.recall_macro}, {"weighted", s.recall_weighted}, {"micro", s.recall_micro}, {"per_class", s.recall_class}}},
              {"f1", {{"macro", s.f1_macro}, {"weighted", s.f1_weighted}, {"micro", s.f1_micro}, {"per_class", s.f1_class}}},
              {"mcc", s.mcc}};
}

void print_scores(const Scores& s) {
  fmt::print("  confusion matrix (rows: true class, columns: predicted class)\n");
  fmt::print("  {:>20}", "");
  for (std::size_t p = 0; p < s.confusion.classes; ++p) fmt::print(" {:>8}", p);
  fmt::print("\n");
  for (std::size_t t = 0; t < s.confusion.classes; ++t) {
    fmt::print("  {:>17} {:>2}", t < wall_following_labels.size() ? wall_following_labels[t] : "", t);
    for (std::size_t p = 0; p < s.confusion.classes; ++p) fmt::print(" {:>8}", s.confusion.at(t, p));
    fmt::print("\n");
  }
  fmt::print("  accuracy (Eq. 7)     {:.6f}\n", s.accuracy);
  fmt::print("  precision (Eq. 8)    macro {:.6f}  weighted {:.6f}  micro {:.6f}\n", s.precision_macro, s.precision_weighted, s.precision_micro);
  fmt::print("  recall (Eq. 9)       macro {:.6f}  weighted {:.6f}  micro {:.6f}\n", s.recall_macro, s.recall_weighted, s.recall_micro);
  fmt::print("  F1 (Eq. 10)          macro {:.6f}  weighted {:.6f}  micro {:.6f}\n", s.f1_macro, s.f1_weighted, s.f1_micro);
  fmt::print("  MCC (Eq. 11, Gorodkin) {:.6f}\n", s.mcc);
}

/// Rows whose prediction rests on a tie another implementation may break otherwise: KNN rows
/// with a distance tie at the k-th neighbour, tree rows whose path crosses a tied split.
bool tie_flag(const Model& m, std::span<const double> x) {
  if (const auto* k = std::get_if<Knn>(&m.model)) return knn_query(*k, x).distance_tie;
  if (const auto* t = std::get_if<Tree>(&m.model)) return passes_tied_split(*t, x);
  return false;
}

int run_learn(const LearnOptions& o) {
  if (o.cv.empty() == o.holdout.empty()) throw UsageError("give exactly one of --cv K and --holdout FRACTION");
  const std::uint32_t seed = parse_seed(o.seed);
  const Params params = parse_params(o.set, seed);
  const std::vector<Kind> kinds = parse_kinds(o.classifiers);
  const Dataset d = io::read_wall_following(o.data);
  Json protocol;
  std::vector<int> folds;  // cv: fold per row; holdout: 1 = test, 0 = train
  if (!o.cv.empty()) {
    if (o.cv.find_first_not_of("0123456789") != std::string::npos || o.cv.size() > 6)
      throw UsageError("--cv expects an integer k >= 2, got '" + o.cv + "'");
    const auto k = static_cast<std::size_t>(std::stoul(o.cv));
    if (k < 2) throw UsageError("--cv expects an integer k >= 2, got '" + o.cv + "'");
    if (o.shuffle) {
      rng::Stream s(seed);
      folds = stratified_kfold_shuffled(d.y, k, s);
    } else {
      folds = stratified_kfold(d.y, k);
    }
    protocol = Json{{"kind", "stratified-kfold"}, {"k", k}, {"shuffle", o.shuffle},
                    {"fold_rule", o.shuffle ? "scikit-learn StratifiedKFold allocation, blocks shuffled by rng::Stream(seed)"
                                            : "scikit-learn StratifiedKFold(n_splits=k, shuffle=False), identical folds"}};
    if (o.shuffle) protocol["seed"] = seed;
  } else {
    double frac = 0.0;
    try {
      std::size_t used = 0;
      frac = std::stod(o.holdout, &used);
      if (used != o.holdout.size()) throw UsageError("");
    } catch (const std::exception&) {
      throw UsageError("--holdout expects the test fraction in (0, 1), got '" + o.holdout + "'");
    }
    if (!(frac > 0.0 && frac < 1.0)) throw UsageError("--holdout expects the test fraction in (0, 1), got '" + o.holdout + "'");
    rng::Stream s(seed);
    const std::vector<bool> test = holdout_split(d.rows(), frac, s);
    folds.assign(d.rows(), 0);
    std::size_t n_test = 0;
    for (std::size_t i = 0; i < d.rows(); ++i)
      if (test[i]) { folds[i] = 1; ++n_test; }
    protocol = Json{{"kind", "holdout"}, {"test_fraction", frac}, {"seed", seed},
                    {"test_rows", n_test}, {"train_rows", d.rows() - n_test}};
  }
  std::vector<int> only;
  if (!o.only_folds.empty()) {
    if (o.cv.empty()) throw UsageError("--only-folds needs --cv");
    std::stringstream in(o.only_folds);
    std::string item;
    const int k = *std::max_element(folds.begin(), folds.end()) + 1;
    while (std::getline(in, item, ',')) {
      if (item.empty() || item.size() > 6 || item.find_first_not_of("0123456789") != std::string::npos || std::stoi(item) >= k)
        throw UsageError("--only-folds expects fold numbers from 0 to " + std::to_string(k - 1) + ", got '" + item + "'");
      only.push_back(std::stoi(item));
    }
    protocol["only_folds"] = only;
  }
  Json doc{{"data", {{"file", o.data}, {"rows", d.rows()}, {"features", d.features}, {"classes", d.classes}}},
           {"protocol", protocol}, {"results", Json::array()}};
  Json preds{{"folds", folds}, {"y", d.y}, {"protocol", protocol}, {"classifiers", Json::object()}};
  if (!o.json) {
    fmt::print("pathref learn: {} ({} rows, {} features, {} classes)\n", o.data, d.rows(), d.features, d.classes);
    fmt::print("protocol: {}\n", protocol.dump());
  }
  for (const Kind kind : kinds) {
    std::vector<int> pred(d.rows(), -1);
    std::vector<int> tie(d.rows(), 0);
    std::vector<int> y_true, y_pred;
    std::size_t tied_nodes = 0;
    const int n_parts = o.cv.empty() ? 1 : *std::max_element(folds.begin(), folds.end()) + 1;
    for (int f = 0; f < n_parts; ++f) {
      if (!only.empty() && std::find(only.begin(), only.end(), f) == only.end()) continue;
      const int test_id = o.cv.empty() ? 1 : f;
      std::vector<std::size_t> train_rows;
      for (std::size_t i = 0; i < d.rows(); ++i)
        if (folds[i] != test_id) train_rows.push_back(i);
      const Model m = train(kind, subset(d, train_rows), params);
      if (const auto* t = std::get_if<Tree>(&m.model)) tied_nodes += t->tied_splits;
      if (!o.save_model.empty() && f == 0 && o.cv.empty()) write_output_file(o.save_model, stamped(io::to_json(m)).dump() + "\n");
      for (std::size_t i = 0; i < d.rows(); ++i)
        if (folds[i] == test_id) {
          pred[i] = predict(m, d.row(i));
          if (!o.predictions.empty()) tie[i] = tie_flag(m, d.row(i)) ? 1 : 0;
        }
    }
    for (std::size_t i = 0; i < d.rows(); ++i)
      if (pred[i] >= 0) {
        y_true.push_back(d.y[i]);
        y_pred.push_back(pred[i]);
      }
    const Scores s = score(y_true, y_pred, d.classes);
    Json r{{"classifier", to_string(kind)}, {"params", params.to_json(kind)}, {"scores", scores_json(s)}};
    if (kind == Kind::tree) r["tied_splits"] = tied_nodes;
    doc["results"].push_back(r);
    preds["classifiers"][std::string(to_string(kind))] = Json{{"pred", pred}, {"tie", tie}};
    if (!o.json) {
      fmt::print("\nclassifier {}  parameters {}\n", to_string(kind), params.to_json(kind).dump());
      print_scores(s);
    }
  }
  if (!o.save_model.empty() && !o.cv.empty()) {
    // with --cv the saved model is trained on every row (the last classifier given)
    write_output_file(o.save_model, stamped(io::to_json(train(kinds.back(), d, params))).dump() + "\n");
  }
  stamp_version(doc);
  stamp_version(preds);
  if (!o.predictions.empty()) write_output_file(o.predictions, preds.dump() + "\n");
  if (o.json) fmt::print("{}\n", doc.dump(1));
  return 0;
}

/// The sensor distances of `classify`: every argument that is not one of its options, in order
/// (spec/cin2021-ml.md#cli), so negative values such as -0.5, -.5 or -inf are values, never
/// options. An argument starting with "--" is an unknown option.
[[nodiscard]] std::vector<double> parse_sensor_values(const std::vector<std::string>& args) {
  std::vector<double> x;
  for (const std::string& v : args) {
    if (v.rfind("--", 0) == 0)
      throw UsageError("classify: unknown option '" + io::printable(v) + "' (options: --model FILE, --json)");
    try {
      std::size_t used = 0;
      const double d = std::stod(v, &used);
      if (used != v.size() || !std::isfinite(d)) throw UsageError("");
      x.push_back(d);
    } catch (const std::exception&) {
      throw UsageError("sensor distance '" + io::printable(v) + "' is not a finite number");
    }
  }
  return x;
}

int run_classify(const ClassifyOptions& o) {
  const Model m = io::read_model_file(o.model);
  const std::vector<double> x = parse_sensor_values(o.values);
  if (x.size() != m.features)
    throw UsageError(fmt::format("the model expects {} sensor distances, got {}", m.features, x.size()));
  const int c = [&] {
    try {
      return predict(m, x);
    } catch (const DomainError& e) {
      throw UsageError(std::string("classify: the sensor distances are outside the model's domain: ") + e.what());
    }
  }();
  const std::string name = static_cast<std::size_t>(c) < wall_following_labels.size()
                               ? std::string(wall_following_labels[static_cast<std::size_t>(c)]) : std::to_string(c);
  if (o.json) {
    fmt::print("{}\n", stamped(Json{{"class", c}, {"label", name}, {"classifier", to_string(m.kind)}, {"input", x}}).dump());
  } else {
    fmt::print("{} {}\n", c, name);
  }
  return 0;
}

}  // namespace

void add_learn_commands(CLI::App& app, Action& run) {
  static LearnOptions learn;
  static ClassifyOptions classify;
  auto* l = app.add_subcommand("learn", "Train and evaluate cin2021's obstacle-avoidance classifiers (MNB, GNB, SVM, KNN, RF) "
                                        "on the UCI wall-following data (spec/cin2021-ml.md)");
  l->add_option("--data", learn.data, "sensor_readings_{2,4,24}.data")->required()->type_name("FILE");
  l->add_option("--classifier", learn.classifiers, "all (rf,knn,svm,gnb,mnb) or a list of mnb,gnb,svm,knn,rf,tree")
      ->type_name("LIST")->capture_default_str();
  l->add_option("--cv", learn.cv, "stratified k-fold cross-validation (folds as scikit-learn's StratifiedKFold)")->type_name("K");
  l->add_option("--holdout", learn.holdout, "hold-out with this test fraction (the paper's stated 1636/3820 split is 0.7, the swapped one 0.3)")
      ->type_name("FRACTION");
  l->add_flag("--shuffle", learn.shuffle, "with --cv: shuffle each class's fold blocks with rng::Stream(seed)");
  l->add_option("--seed", learn.seed, "seed of the hold-out split, the shuffled folds and the forest")->type_name("N")->capture_default_str();
  l->add_option("--set", learn.set, "classifier parameter name=value (var_smoothing, alpha, C, gamma, tol, k, knn_vote, knn_weights, trees, max_features, bootstrap, forest_vote, ...)")
      ->type_name("NAME=VALUE");
  l->add_flag("--json", learn.json, "print the results as JSON");
  l->add_option("--predictions", learn.predictions, "write folds, labels and every prediction (with tie flags) as JSON")->type_name("FILE");
  l->add_option("--only-folds", learn.only_folds, "with --cv: evaluate only these folds (e.g. 0,5); metrics cover their rows")
      ->type_name("LIST");
  l->add_option("--save-model", learn.save_model, "write the model (hold-out: trained on the training rows; --cv: on all rows) as JSON")
      ->type_name("FILE");
  l->callback([&run] { run = [] { return run_learn(learn); }; });

  auto* c = app.add_subcommand("classify", "Decide the movement for given sensor distances with a saved model (pathref learn --save-model)");
  c->add_option("--model", classify.model, "model file (JSON, format pathref-ml-model version 1)")->required()->type_name("FILE");
  c->add_flag("--json", classify.json, "print the decision as JSON");
  // The sensor distances are every other argument, in order (parse_sensor_values): CLI11 would
  // take a value such as -inf or -.5 for an option, so they are collected as extras instead.
  c->allow_extras(true);
  c->footer("VALUES: the sensor distances, in the data file's column order (every argument that is not an "
            "option; negative values such as -0.5 or -.5 are values)");
  c->callback([&run, c] {
    classify.values = c->remaining();
    run = [] { return run_classify(classify); };
  });
}

}  // namespace pathref::cli
