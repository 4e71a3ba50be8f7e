// Properties of cin2021's machine-learning decision model (spec/cin2021-ml.md).
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "pathref/io/wall_following.hpp"
#include "pathref/core/error.hpp"
#include "pathref/ml/classifier.hpp"
#include "pathref/ml/folds.hpp"

using namespace pathref::ml;

namespace {
rc::Gen<std::vector<int>> labels(int classes, std::size_t lo, std::size_t hi) {
  return rc::gen::mapcat(rc::gen::inRange(lo, hi), [classes](std::size_t n) {
    return rc::gen::container<std::vector<int>>(n, rc::gen::inRange(0, classes));
  });
}
/// A small data set with values on a 1/8 grid (exactly representable, ties frequent).
Dataset small_dataset(std::size_t rows, std::size_t features, int classes) {
  Dataset d;
  d.features = features;
  d.classes = static_cast<std::size_t>(classes);
  d.x = *rc::gen::container<std::vector<double>>(rows * features,
                                                  rc::gen::map(rc::gen::inRange(0, 40), [](int v) { return v / 8.0; }));
  d.y = *rc::gen::container<std::vector<int>>(rows, rc::gen::inRange(0, classes));
  return d;
}
}  // namespace

TEST_CASE("prop_cin2021_folds_partition_and_stratify", "[cin2021-ml][prop]") {
  rc::prop("every sample in one fold; each class spread over the folds within one", [] {
    const std::vector<int> y = *labels(4, 2, 60);
    const std::size_t k = *rc::gen::inRange<std::size_t>(2, 6);
    std::vector<std::size_t> count(4, 0);
    for (const int v : y) ++count[static_cast<std::size_t>(v)];
    RC_PRE(k <= y.size() && *std::max_element(count.begin(), count.end()) >= k);
    const bool shuffled = *rc::gen::arbitrary<bool>();
    pathref::rng::Stream s(*rc::gen::arbitrary<std::uint32_t>());
    const std::vector<int> f = shuffled ? stratified_kfold_shuffled(y, k, s) : stratified_kfold(y, k);
    RC_ASSERT(f.size() == y.size());
    for (int c = 0; c < 4; ++c) {
      std::vector<int> per(k, 0);
      for (std::size_t i = 0; i < y.size(); ++i) {
        RC_ASSERT(f[i] >= 0 && static_cast<std::size_t>(f[i]) < k);
        if (y[i] == c) ++per[static_cast<std::size_t>(f[i])];
      }
      RC_ASSERT(*std::max_element(per.begin(), per.end()) - *std::min_element(per.begin(), per.end()) <= 1);
    }
    // fold sizes differ by at most one
    std::vector<int> size(k, 0);
    for (const int v : f) ++size[static_cast<std::size_t>(v)];
    RC_ASSERT(*std::max_element(size.begin(), size.end()) - *std::min_element(size.begin(), size.end()) <= 1);
  });
}

TEST_CASE("prop_cin2021_metrics_bounds_and_micro_is_accuracy", "[cin2021-ml][prop]") {
  rc::prop("metrics in range, micro averages = accuracy, MCC symmetric, perfect predictions score 1", [] {
    const std::vector<int> t = *labels(4, 1, 80);
    std::vector<int> p = *rc::gen::container<std::vector<int>>(t.size(), rc::gen::inRange(0, 4));
    const Scores s = score(t, p, 4);
    RC_ASSERT(s.accuracy >= 0.0 && s.accuracy <= 1.0);
    RC_ASSERT(s.precision_micro == s.accuracy);
    RC_ASSERT(s.recall_micro == s.accuracy);
    RC_ASSERT(std::abs(s.f1_micro - s.accuracy) <= 1e-15);
    for (const double v : {s.precision_macro, s.recall_macro, s.f1_macro, s.precision_weighted, s.recall_weighted, s.f1_weighted})
      RC_ASSERT(v >= 0.0 && v <= 1.0);
    RC_ASSERT(s.mcc >= -1.0 - 1e-15 && s.mcc <= 1.0 + 1e-15);
    RC_ASSERT(mcc(confusion_matrix(p, t, 4)) == s.mcc);  // swapping truth and prediction
    const Scores perfect = score(t, t, 4);
    RC_ASSERT(perfect.accuracy == 1.0);
    std::set<int> present(t.begin(), t.end());
    RC_ASSERT(perfect.mcc == (present.size() > 1 ? 1.0 : 0.0));
    RC_ASSERT(perfect.recall_weighted == 1.0);
  });
}

TEST_CASE("prop_cin2021_tree_fits_distinct_training_rows", "[cin2021-ml][prop]") {
  rc::prop("a full CART tree classifies every training row whose features no other class shares", [] {
    const Dataset d = small_dataset(*rc::gen::inRange<std::size_t>(2, 25), *rc::gen::inRange<std::size_t>(1, 4), 3);
    const std::vector<std::int64_t> w(d.rows(), 1);
    const Tree t = grow_tree(d, w, TreeParams{0}, nullptr);
    validate(t);
    for (std::size_t i = 0; i < d.rows(); ++i) {
      bool conflict = false;
      for (std::size_t j = 0; j < d.rows(); ++j)
        conflict = conflict || (d.y[j] != d.y[i] && std::equal(d.row(i).begin(), d.row(i).end(), d.row(j).begin()));
      if (!conflict) RC_ASSERT(predict(t, d.row(i)) == d.y[i]);
    }
    // leaves hold the node's counts: the root's counts are the class totals
    for (std::size_t c = 0; c < 3; ++c)
      RC_ASSERT(t.value[c] == static_cast<double>(std::count(d.y.begin(), d.y.end(), static_cast<int>(c))));
  });
}

TEST_CASE("prop_cin2021_knn_k1_returns_own_label", "[cin2021-ml][prop]") {
  rc::prop("k = 1 at a training row returns the label of the first row with those features", [] {
    const Dataset d = small_dataset(*rc::gen::inRange<std::size_t>(1, 30), 2, 4);
    const Knn m{1, KnnVote::uniform, {}, d};
    const std::size_t i = *rc::gen::inRange<std::size_t>(0, d.rows());
    std::size_t first = i;
    for (std::size_t j = 0; j < d.rows(); ++j)
      if (std::equal(d.row(j).begin(), d.row(j).end(), d.row(i).begin())) {
        first = j;
        break;
      }
    RC_ASSERT(predict(m, d.row(i)) == d.y[first]);
    RC_ASSERT(euclidean(d.row(i), d.row(first)) == 0.0);
  });
}

TEST_CASE("prop_cin2021_data_text_round_trip", "[cin2021-ml][prop]") {
  rc::prop("printing rows with %.17g and a label, then parsing, gives the rows back", [] {
    const Dataset d = small_dataset(*rc::gen::inRange<std::size_t>(1, 20), *rc::gen::inRange<std::size_t>(1, 6), 4);
    std::string text;
    const bool crlf = *rc::gen::arbitrary<bool>();
    for (std::size_t i = 0; i < d.rows(); ++i) {
      for (const double v : d.row(i)) {
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.17g,", v);
        text += buf;
      }
      text += std::string(wall_following_labels[static_cast<std::size_t>(d.y[i])]) + (crlf ? "\r\n" : "\n");
    }
    const Dataset r = pathref::io::parse_wall_following(text, "rt");
    RC_ASSERT(r.x == d.x);
    RC_ASSERT(r.y == d.y);
    RC_ASSERT(r.features == d.features);
  });
}

TEST_CASE("prop_cin2021_classifiers_predict_present_classes", "[cin2021-ml][prop]") {
  rc::prop("every classifier returns a class that occurs in the training data, and GNB/KNN/tree are deterministic", [] {
    Dataset d = small_dataset(*rc::gen::inRange<std::size_t>(6, 20), 2, 4);
    d.y[0] = 0;
    d.y[1] = 1;  // two classes at least (SVM)
    Params p;
    p.k = 3;
    p.forest.trees = 3;
    p.seed = *rc::gen::arbitrary<std::uint32_t>();
    const std::set<int> present(d.y.begin(), d.y.end());
    const std::vector<double> q = {*rc::gen::inRange(0, 40) / 8.0, *rc::gen::inRange(0, 40) / 8.0};
    for (const Kind k : {Kind::mnb, Kind::gnb, Kind::knn, Kind::rf, Kind::tree, Kind::svm}) {
      bool ok = true;
      Model m;
      try {
        m = train(k, d, p);
      } catch (const pathref::DomainError&) {
        // only GNB may refuse: every column constant gives epsilon = 0 and a zero variance
        RC_ASSERT(k == Kind::gnb);
        ok = false;
      }
      if (!ok) continue;
      const int c = predict(m, q);
      RC_ASSERT(present.count(c) == 1);
      RC_ASSERT(predict(train(k, d, p), q) == c);  // same seed, same model
    }
  });
}
