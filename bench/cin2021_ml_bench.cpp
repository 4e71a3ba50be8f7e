// cin2021's ML decision model on the UCI wall-following data (5,456 rows, 4 features):
// training time of each classifier on all rows, the 10-fold evaluation (stratified, unshuffled),
// and the latency of classifying one sample (the model is meant for real-time obstacle avoidance).
// spec: cin2021.eq1-eq6, cin2021.folds. Figures: docs/performance.md ("cin2021 ML decision model").
// Reads ../shared/data/uci-wall-following/sensor_readings_4.data; skips when it is absent.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "pathref/io/wall_following.hpp"
#include "pathref/ml/classifier.hpp"
#include "pathref/ml/folds.hpp"

namespace {

using namespace pathref::ml;

const std::string data_path = std::string(PATHREF_SHARED_DIR) + "/data/uci-wall-following/sensor_readings_4.data";

const Dataset* data() {
  static const Dataset* d = std::filesystem::exists(data_path) ? new Dataset(pathref::io::read_wall_following(data_path)) : nullptr;
  return d;
}

Params params_for(Kind k, int trees) {
  Params p;
  if (k == Kind::rf) p.forest.trees = static_cast<std::size_t>(trees);
  return p;
}

void BM_Train(benchmark::State& state, Kind k) {
  const Dataset* d = data();
  if (d == nullptr) {
    state.SkipWithError(("shared data absent: " + data_path).c_str());
    return;
  }
  const Params p = params_for(k, static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(train(k, *d, p));
  state.counters["rows"] = static_cast<double>(d->rows());
}

void BM_TenFold(benchmark::State& state, Kind k) {
  const Dataset* d = data();
  if (d == nullptr) {
    state.SkipWithError(("shared data absent: " + data_path).c_str());
    return;
  }
  const Params p = params_for(k, static_cast<int>(state.range(0)));
  const std::vector<int> folds = stratified_kfold(d->y, 10);
  double acc = 0;
  for (auto _ : state) {
    const auto pred = cross_val_predict(k, *d, folds, p);
    acc = score(d->y, pred, d->classes).accuracy;
  }
  state.counters["accuracy"] = acc;
}

void BM_Classify(benchmark::State& state, Kind k) {
  const Dataset* d = data();
  if (d == nullptr) {
    state.SkipWithError(("shared data absent: " + data_path).c_str());
    return;
  }
  const Model m = train(k, *d, params_for(k, static_cast<int>(state.range(0))));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(predict(m, d->row(i)));
    i = (i + 97) % d->rows();
  }
}

}  // namespace

#define PATHREF_ML_BENCH(kind, arg)                                                                  \
  BENCHMARK_CAPTURE(BM_Train, kind, Kind::kind)->Arg(arg)->Unit(benchmark::kMillisecond);            \
  BENCHMARK_CAPTURE(BM_TenFold, kind, Kind::kind)->Arg(arg)->Unit(benchmark::kMillisecond)->Iterations(1); \
  BENCHMARK_CAPTURE(BM_Classify, kind, Kind::kind)->Arg(arg)->Unit(benchmark::kMicrosecond);

PATHREF_ML_BENCH(gnb, 0)
PATHREF_ML_BENCH(mnb, 0)
PATHREF_ML_BENCH(knn, 0)
PATHREF_ML_BENCH(svm, 0)
PATHREF_ML_BENCH(tree, 0)
PATHREF_ML_BENCH(rf, 100)
