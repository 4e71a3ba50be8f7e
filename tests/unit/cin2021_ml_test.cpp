// Unit tests of cin2021's machine-learning decision model (spec/cin2021-ml.md): hand-computed
// values for every rule, the error paths, and the shared UCI files.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "pathref/io/model_file.hpp"
#include "pathref/io/wall_following.hpp"
#include "pathref/core/error.hpp"
#include "pathref/ml/classifier.hpp"
#include "pathref/ml/folds.hpp"
#include "support/paths.hpp"

using namespace pathref::ml;
using pathref::DomainError;
using pathref::ParseError;

namespace {
Dataset make(std::size_t features, std::vector<double> x, std::vector<int> y, std::size_t classes = 4) {
  Dataset d;
  d.features = features;
  d.classes = classes;
  d.x = std::move(x);
  d.y = std::move(y);
  return d;
}
}  // namespace

TEST_CASE("cin2021.data: parses rows, CRLF and a last line without a line end", "[cin2021-ml]") {
  const Dataset d = pathref::io::parse_wall_following("1.5,2,Move-Forward\r\n0.25,3e0,Slight-Left-Turn\n4,5,Sharp-Right-Turn", "t");
  REQUIRE(d.rows() == 3);
  CHECK(d.features == 2);
  CHECK(d.y == std::vector<int>{0, 3, 2});
  CHECK(d.x == std::vector<double>{1.5, 2, 0.25, 3, 4, 5});
}

TEST_CASE("cin2021.data: bad rows are ParseErrors naming line and column", "[cin2021-ml]") {
  const auto where = [](const char* text) -> std::string {
    try {
      (void)pathref::io::parse_wall_following(text, "f.data");
    } catch (const ParseError& e) {
      return std::to_string(e.line()) + ":" + std::to_string(e.column());
    }
    return "no error";
  };
  CHECK(where("1,2,Move-Forward\n1,x,Move-Forward\n") == "2:3");         // non-number
  CHECK(where("1,2,Move-Forward\n1,2,Go-Back\n") == "2:5");              // unknown label
  CHECK(where("1,2,Move-Forward\n1,Move-Forward\n") == "2:3");           // missing column
  CHECK(where("1,2,Move-Forward\n1,2\n") == "2:4");                      // missing label column
  CHECK(where("1,2,Move-Forward\n1,2,3,Move-Forward\n") == "2:5");       // extra column
  CHECK(where("1,2,Move-Forward\n\n1,2,Move-Forward\n") == "2:1");       // empty line
  CHECK(where("") == "1:1");                                             // empty file
  CHECK(where("1e999,2,Move-Forward\n") == "1:1");                       // not finite
  CHECK(where("Move-Forward\n") == "1:1");                               // no number
}

TEST_CASE("cin2021.data: the shared 2-, 4- and 24-sensor files", "[cin2021-ml][shared]") {
  const std::string dir = pathref::testing::shared_dir() + "/data/uci-wall-following/";
  if (!std::filesystem::exists(dir + "sensor_readings_4.data")) {
    pathref::testing::skip_test(dir + " is absent (shared data)");
    return;
  }
  const Dataset d2 = pathref::io::read_wall_following(dir + "sensor_readings_2.data");
  const Dataset d4 = pathref::io::read_wall_following(dir + "sensor_readings_4.data");
  const Dataset d24 = pathref::io::read_wall_following(dir + "sensor_readings_24.data");
  CHECK(d2.features == 2);
  CHECK(d4.features == 4);
  CHECK(d24.features == 24);
  for (const Dataset* d : {&d2, &d4, &d24}) {
    REQUIRE(d->rows() == 5456);
    std::vector<int> n(4, 0);
    for (const int y : d->y) ++n[static_cast<std::size_t>(y)];
    CHECK(n == std::vector<int>{2205, 826, 2097, 328});  // README: MF, Slight-R, Sharp-R, Slight-L
  }
  CHECK(d2.y == d4.y);
  CHECK(d4.y == d24.y);
  for (std::size_t i = 0; i < d4.rows(); ++i) {
    CHECK(d2.x[2 * i] == d4.x[4 * i]);
    CHECK(d2.x[2 * i + 1] == d4.x[4 * i + 1]);
  }
}

TEST_CASE("cin2021.eq7-11: metrics of a hand-computed confusion matrix", "[cin2021-ml]") {
  const std::vector<int> t{0, 0, 0, 1, 1, 2, 2, 2, 2, 3};
  const std::vector<int> p{0, 1, 0, 1, 1, 2, 0, 2, 3, 3};
  const Confusion c = confusion_matrix(t, p, 4);
  CHECK(c.counts == std::vector<std::int64_t>{2, 1, 0, 0, 0, 2, 0, 0, 1, 0, 2, 1, 0, 0, 0, 1});
  CHECK(accuracy(c) == 0.7);
  CHECK(precision_per_class(c) == std::vector<double>{2.0 / 3.0, 2.0 / 3.0, 1.0, 0.5});
  CHECK(recall_per_class(c) == std::vector<double>{2.0 / 3.0, 1.0, 0.5, 1.0});
  CHECK(precision(c, Average::macro) == Approx((2.0 / 3 + 2.0 / 3 + 1 + 0.5) / 4).epsilon(1e-15));
  CHECK(recall(c, Average::weighted) == Approx((2.0 / 3 * 3 + 1 * 2 + 0.5 * 4 + 1) / 10).epsilon(1e-15));
  CHECK(precision(c, Average::micro) == 0.7);
  CHECK(recall(c, Average::micro) == 0.7);
  CHECK(f1(c, Average::micro) == Approx(0.7).epsilon(1e-15));
  // per-class F1 = 2PR/(P+R): 2/3, 0.8, 2/3, 2/3
  CHECK(f1(c, Average::macro) == Approx((2.0 / 3 + 0.8 + 2.0 / 3 + 2.0 / 3) / 4).epsilon(1e-15));
  // Gorodkin: s = 10, c = 7, t = (3,2,4,1), p = (3,3,2,2): (70 - 25) / sqrt((100 - 30)(100 - 26))
  CHECK(mcc(c) == 45.0 / std::sqrt(5180.0));
  // zero denominators: class 3 never predicted, class 1 never true
  const Confusion z = confusion_matrix(std::vector<int>{0, 0, 3}, std::vector<int>{0, 1, 0}, 4);
  CHECK(precision_per_class(z) == std::vector<double>{0.5, 0.0, 0.0, 0.0});
  CHECK(recall_per_class(z) == std::vector<double>{0.5, 0.0, 0.0, 0.0});
  CHECK(mcc(confusion_matrix(std::vector<int>{1, 1}, std::vector<int>{1, 1}, 4)) == 0.0);  // one class: 0/0 := 0
  CHECK_THROWS_AS(confusion_matrix(std::vector<int>{}, std::vector<int>{}, 4), DomainError);
  CHECK_THROWS_AS(confusion_matrix(std::vector<int>{4}, std::vector<int>{0}, 4), DomainError);
  CHECK_THROWS_AS(precision(c, Average::none), DomainError);
}

TEST_CASE("cin2021.folds: stratified k-fold equals scikit-learn's on hand examples", "[cin2021-ml]") {
  // Values from scikit-learn 1.2.1 StratifiedKFold(k).split, checked by hand against the spec.
  CHECK(stratified_kfold(std::vector<int>{0, 0, 0, 0, 1, 1, 1, 0, 1, 0}, 3) ==
        std::vector<int>{0, 0, 1, 1, 0, 0, 1, 2, 2, 2});
  CHECK(stratified_kfold(std::vector<int>{2, 2, 0, 1, 0, 2, 1, 1, 0, 3, 3, 2}, 2) ==
        std::vector<int>{0, 0, 0, 0, 0, 1, 1, 1, 1, 0, 1, 1});
  CHECK_THROWS_AS(stratified_kfold(std::vector<int>{0, 1, 2}, 2), DomainError);  // k > every class count
  CHECK_THROWS_AS(stratified_kfold(std::vector<int>{0, 0}, 1), DomainError);
  pathref::rng::Stream s(1);
  const auto h = holdout_split(10, 0.3, s);
  CHECK(std::count(h.begin(), h.end(), true) == 3);
  pathref::rng::Stream s2(1);
  CHECK(holdout_split(5456, 0.7, s2).size() == 5456);
  pathref::rng::Stream s3(1);
  const auto h2 = holdout_split(5456, 0.7, s3);
  CHECK(std::count(h2.begin(), h2.end(), true) == 3820);  // the paper's 3820 test rows
  CHECK_THROWS_AS(holdout_split(10, 0.0, s), DomainError);
  CHECK_THROWS_AS(holdout_split(1, 0.5, s), DomainError);
}

TEST_CASE("cin2021.eq1: Gaussian and multinomial NB on hand examples", "[cin2021-ml]") {
  const Dataset g = make(1, {0, 2, 10, 14}, {0, 0, 1, 1}, 2);
  const GaussianNb m = fit_gaussian_nb(g, 0.0);
  CHECK(m.mean == std::vector<double>{1, 12});
  CHECK(m.var == std::vector<double>{1, 4});
  const auto jll = joint_log_likelihood(m, std::vector<double>{5});
  CHECK(jll[0] == Approx(std::log(0.5) - 0.5 * std::log(2 * std::numbers::pi) - 8.0).epsilon(1e-15));
  CHECK(jll[1] == Approx(std::log(0.5) - 0.5 * std::log(8 * std::numbers::pi) - 49.0 / 8.0).epsilon(1e-15));
  CHECK(predict(m, std::vector<double>{5}) == 1);
  // var_smoothing: epsilon = 1e-9 * population variance of the column (mean 6.5: 131/4 = 32.75)
  CHECK(fit_gaussian_nb(g).epsilon == 1e-9 * 32.75);
  const MultinomialNb b = fit_multinomial_nb(make(2, {1, 3, 2, 2, 5, 0}, {0, 0, 1}, 2));
  CHECK(b.feature_log_prob[0] == Approx(std::log(0.4)).epsilon(1e-15));
  CHECK(b.feature_log_prob[3] == Approx(std::log(1.0 / 7.0)).epsilon(1e-15));
  CHECK(predict(b, std::vector<double>{0, 1}) == 0);
  CHECK(predict(b, std::vector<double>{1, 0}) == 1);
  CHECK_THROWS_AS(fit_multinomial_nb(make(1, {-1, 2}, {0, 1}, 2)), DomainError);
  CHECK_THROWS_AS(fit_multinomial_nb(make(1, {1, 2}, {0, 1}, 2), 0.0), DomainError);
  CHECK_THROWS_AS(fit_gaussian_nb(make(1, {1, 1}, {0, 1}, 2), 0.0), DomainError);  // zero variance
}

TEST_CASE("cin2021.eq4-5: Euclidean and weighted Euclidean distance", "[cin2021-ml]") {
  CHECK(euclidean(std::vector<double>{0, 0}, std::vector<double>{3, 4}) == 5.0);
  CHECK(weighted_euclidean(std::vector<double>{0, 0}, std::vector<double>{3, 4}, std::vector<double>{4, 0.25}) ==
        std::sqrt(40.0));
  CHECK_THROWS_AS(euclidean(std::vector<double>{0}, std::vector<double>{0, 1}), DomainError);
  CHECK_THROWS_AS(weighted_euclidean(std::vector<double>{0}, std::vector<double>{1}, std::vector<double>{-1}),
                  DomainError);
}

TEST_CASE("cin2021.knn: a distance tie at the k-th neighbour goes to the lower row", "[cin2021-ml]") {
  Knn m{2, KnnVote::uniform, {}, make(1, {0, 1, -1, 2}, {0, 1, 2, 1}, 4)};
  const KnnResult r = knn_query(m, std::vector<double>{0});
  CHECK(r.neighbours == std::vector<std::size_t>{0, 1});
  CHECK(r.distance_tie);
  CHECK(r.label == 0);  // one vote each for 0 and 1: the smallest class
  m.k = 3;
  const KnnResult r3 = knn_query(m, std::vector<double>{0});
  CHECK_FALSE(r3.distance_tie);
  CHECK(r3.label == 0);
  m.k = 4;
  CHECK(knn_query(m, std::vector<double>{1.9}).label == 1);
  // distance vote: 1/d weights; a neighbour at d = 0 takes the whole vote
  CHECK(knn_vote(std::vector<int>{2, 1, 1}, std::vector<double>{1, 3, 3}, 3, KnnVote::distance) == 2);
  CHECK(knn_vote(std::vector<int>{2, 1, 1}, std::vector<double>{1, 1.5, 3}, 3, KnnVote::distance) == 1);
  CHECK(knn_vote(std::vector<int>{2, 1, 1}, std::vector<double>{0, 0.5, 0.5}, 3, KnnVote::distance) == 2);
  m.k = 5;
  CHECK_THROWS_AS(knn_query(m, std::vector<double>{0}), DomainError);
}

TEST_CASE("cin2021.eq3: libsvm on a two-point problem matches the closed form", "[cin2021-ml]") {
  // x1 = 0 (class 0), x2 = 1 (class 1), gamma = 1, C = 10: both are free support vectors with
  // alpha = 1 / (1 - e^-1), coefficients (+alpha, -alpha) and rho = 0. libsvm caches the kernel
  // in single precision, hence 1e-6.
  SvmParams p;
  p.c = 10;
  p.gamma = 1;
  p.tolerance = 1e-12;
  const SvmModel m = train_svm(make(1, {0, 1}, {0, 1}, 2), p);
  REQUIRE(m.labels == std::vector<int>{0, 1});
  REQUIRE(m.n_sv == std::vector<std::size_t>{1, 1});
  const double a = 1.0 / (1.0 - std::exp(-1.0));
  CHECK(m.coef[0] == Approx(a).epsilon(1e-6));
  CHECK(m.coef[1] == Approx(-a).epsilon(1e-6));
  CHECK(std::abs(m.rho[0]) < 1e-6);
  // with C = 1 < alpha both are bounded: coefficients (+1, -1)
  p.c = 1;
  const SvmModel b = train_svm(make(1, {0, 1}, {0, 1}, 2), p);
  CHECK(b.coef[0] == 1.0);
  CHECK(b.coef[1] == -1.0);
  CHECK_THROWS_AS(train_svm(make(1, {0, 1}, {1, 1}, 2), p), DomainError);  // one class
  CHECK(svm_gamma(make(2, {0, 0, 2, 2}, {0, 1}, 2), "scale") == 0.5);      // 1 / (2 * Var = 1)
  CHECK(svm_gamma(make(2, {1, 1, 1, 1}, {0, 1}, 2), "scale") == 1.0);
  CHECK(svm_gamma(make(4, {0, 0, 0, 0}, {0}, 2), "auto") == 0.25);
}

TEST_CASE("cin2021.eq2: SVM one-vs-one decision of a hand model", "[cin2021-ml]") {
  // three classes, one support vector each at 0, 1, 2 (gamma = ln 2 -> K = 2^-d^2);
  // pair (0,1): coef sv0 = +1 (row 0), sv1 = -1 (row 0); pair (0,2): sv0 +1 (row 1), sv2 -1 (row 0);
  // pair (1,2): sv1 +1 (row 1), sv2 -1 (row 1); rho = 0.
  SvmModel m;
  m.classes = 3;
  m.features = 1;
  m.gamma = std::log(2.0);
  m.labels = {0, 1, 2};
  m.n_sv = {1, 1, 1};
  m.sv = {0, 1, 2};
  m.sv_rows = {0, 1, 2};
  m.coef = {1, -1, -1, 1, 1, -1};
  m.rho = {0, 0, 0};
  validate(m);
  const auto dec = svm_decision_values(m, std::vector<double>{1.0});
  CHECK(dec[0] == Approx(0.5 - 1.0).epsilon(1e-15));
  CHECK(dec[1] == Approx(0.5 - 0.5).margin(1e-15));
  CHECK(dec[2] == Approx(1.0 - 0.5).epsilon(1e-15));
  CHECK(predict(m, std::vector<double>{1.0}) == 1);
  CHECK(predict(m, std::vector<double>{-3.0}) == 0);
  CHECK(predict(m, std::vector<double>{5.0}) == 2);
  m.rho = {0, 0};
  CHECK_THROWS_AS(validate(m), DomainError);
}

TEST_CASE("cin2021.gini: exact split scores, thresholds and ties", "[cin2021-ml]") {
  CHECK(gini(std::vector<double>{1, 1}) == 0.5);
  CHECK(gini(std::vector<double>{3, 0, 0}) == 0.0);
  CHECK_THROWS_AS(gini(std::vector<double>{0, 0}), DomainError);
  // S = (4 + 0)/2 + (1 + 1)/2 = 3 as the fraction (4*2 + 2*2) / 4
  const SplitScore s = split_score(std::vector<std::int64_t>{2, 0}, std::vector<std::int64_t>{1, 1});
  CHECK(compare(s, SplitScore{3, 1}) == 0);
  CHECK(compare(s, SplitScore{5, 2}) == 1);
  const std::vector<std::int64_t> w4(4, 1);
  const Tree t = grow_tree(make(1, {1, 2, 3, 4}, {0, 0, 1, 1}, 2), w4, TreeParams{0}, nullptr);
  REQUIRE(t.nodes.size() == 3);
  CHECK(t.nodes[0].feature == 0);
  CHECK(t.nodes[0].threshold == 2.5);
  CHECK(t.tied_splits == 0);
  // two identical columns: feature 0 wins the exact tie, which is counted
  const Tree u = grow_tree(make(2, {1, 1, 2, 2, 3, 3, 4, 4}, {0, 0, 1, 1}, 2), w4, TreeParams{0}, nullptr);
  CHECK(u.nodes[0].feature == 0);
  CHECK(u.tied_splits == 1);
  CHECK(passes_tied_split(u, std::vector<double>{1, 1}));
  CHECK(predict(u, std::vector<double>{1.2, 9}) == 0);
  CHECK(predict(u, std::vector<double>{3.2, 0}) == 1);
}

TEST_CASE("cin2021.eq6: majority vote and averaged probabilities can disagree", "[cin2021-ml]") {
  const std::vector<double> leaves{10, 0, 4, 6, 4, 6};
  CHECK(combine_votes(leaves, 2, ForestVote::majority) == 1);    // 2 of 3 trees say class 1
  CHECK(combine_votes(leaves, 2, ForestVote::mean_proba) == 0);  // mean P(0) = (1 + .4 + .4)/3 = .6
  CHECK(combine_votes(std::vector<double>{1, 0, 0, 1}, 2, ForestVote::majority) == 0);  // vote tie
  CHECK_THROWS_AS(combine_votes(std::vector<double>{0, 0}, 2, ForestVote::majority), DomainError);
  // a seeded forest is replayable draw for draw
  const Dataset d = make(2, {0, 0, 1, 0, 0, 1, 1, 1, 2, 2, 3, 1}, {0, 1, 1, 0, 2, 2}, 3);
  ForestParams p;
  p.trees = 5;
  pathref::rng::Stream a(7), b(7);
  const Forest fa = grow_forest(d, p, a);
  const Forest fb = grow_forest(d, p, b);
  CHECK(a.doubles_drawn() == b.doubles_drawn());
  CHECK(a.doubles_drawn() >= 5 * 6);  // at least the bootstrap draws
  for (std::size_t i = 0; i < 5; ++i) CHECK(fa.trees[i].value == fb.trees[i].value);
}

TEST_CASE("cin2021 model file: every classifier round-trips through JSON", "[cin2021-ml]") {
  const Dataset d = make(2, {0.5, 1, 1, 0.25, 2, 2, 3, 1, 0.75, 3, 2.5, 0.5, 1.5, 1.5, 4, 4}, {0, 1, 2, 3, 0, 1, 2, 3}, 4);
  Params p;
  p.k = 3;
  p.forest.trees = 3;
  for (const Kind k : {Kind::mnb, Kind::gnb, Kind::svm, Kind::knn, Kind::rf, Kind::tree}) {
    INFO(to_string(k));
    const Model m = train(k, d, p);
    const Model r = pathref::io::model_from_json(nlohmann::json::parse(pathref::io::to_json(m).dump()), "m.json");
    for (std::size_t i = 0; i < d.rows(); ++i) CHECK(predict(r, d.row(i)) == predict(m, d.row(i)));
  }
  nlohmann::json bad = pathref::io::to_json(train(Kind::gnb, d, p));
  bad["version"] = 2;
  CHECK_THROWS_AS(pathref::io::model_from_json(bad, "m.json"), ParseError);
  bad["version"] = 1;
  bad["model"]["var"][0] = -1.0;
  CHECK_THROWS_AS(pathref::io::model_from_json(bad, "m.json"), ParseError);
}
