#include "pathref/ml/folds.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "pathref/core/error.hpp"
#include "pathref/rng/draws.hpp"

namespace pathref::ml {
namespace {

struct Encoded {
  std::vector<std::size_t> code;  // per sample, class in order of first appearance
  std::size_t classes = 0;
};

Encoded encode_by_appearance(std::span<const int> y) {
  Encoded e;
  e.code.resize(y.size());
  std::vector<int> seen;
  for (std::size_t i = 0; i < y.size(); ++i) {
    require(y[i] >= 0, "stratified_kfold: labels must be >= 0");
    const auto it = std::find(seen.begin(), seen.end(), y[i]);
    if (it == seen.end()) {
      e.code[i] = seen.size();
      seen.push_back(y[i]);
    } else {
      e.code[i] = static_cast<std::size_t>(it - seen.begin());
    }
  }
  e.classes = seen.size();
  return e;
}

std::vector<int> assign(std::span<const int> y, std::size_t k, rng::Stream* stream) {
  require(k >= 2, "stratified_kfold: k must be >= 2");
  require(k <= y.size(), "stratified_kfold: k must not exceed the number of samples");
  const Encoded e = encode_by_appearance(y);
  std::vector<std::size_t> count(e.classes, 0);
  for (const auto c : e.code) ++count[c];
  require(*std::max_element(count.begin(), count.end()) >= k,
          "stratified_kfold: k exceeds the number of members of every class");
  // Round robin over the sorted encoded labels: position p of the sorted list goes to fold p % k.
  std::vector<std::vector<std::size_t>> alloc(k, std::vector<std::size_t>(e.classes, 0));
  std::size_t p = 0;
  for (std::size_t c = 0; c < e.classes; ++c)
    for (std::size_t m = 0; m < count[c]; ++m, ++p) ++alloc[p % k][c];
  std::vector<int> fold(y.size(), 0);
  for (std::size_t c = 0; c < e.classes; ++c) {
    std::vector<int> block;
    block.reserve(count[c]);
    for (std::size_t f = 0; f < k; ++f)
      for (std::size_t m = 0; m < alloc[f][c]; ++m) block.push_back(static_cast<int>(f));
    if (stream != nullptr) shuffle_in_place(block, *stream);
    std::size_t b = 0;
    for (std::size_t i = 0; i < y.size(); ++i)
      if (e.code[i] == c) fold[i] = block[b++];
  }
  return fold;
}

}  // namespace

void shuffle_in_place(std::span<int> v, rng::Stream& stream) {
  for (std::size_t i = v.size(); i-- > 1;) {
    const std::size_t j = rng::uniform_index(stream.next_double(), i + 1);
    std::swap(v[i], v[j]);
  }
}

std::vector<int> stratified_kfold(std::span<const int> y, std::size_t k) {
  return assign(y, k, nullptr);
}

std::vector<int> stratified_kfold_shuffled(std::span<const int> y, std::size_t k,
                                           rng::Stream& stream) {
  return assign(y, k, &stream);
}

std::vector<bool> holdout_split(std::size_t n, double test_fraction, rng::Stream& stream) {
  require(std::isfinite(test_fraction) && test_fraction > 0.0 && test_fraction < 1.0,
          "holdout_split: test_fraction must be in (0, 1)");
  const double t = std::ceil(test_fraction * static_cast<double>(n));
  require(t >= 1.0 && t <= static_cast<double>(n) - 1.0,
          "holdout_split: the test and the training part must each hold at least one row");
  const auto n_test = static_cast<std::size_t>(t);
  std::vector<int> perm(n);
  std::iota(perm.begin(), perm.end(), 0);
  shuffle_in_place(perm, stream);
  std::vector<bool> test(n, false);
  for (std::size_t i = 0; i < n_test; ++i) test[static_cast<std::size_t>(perm[i])] = true;
  return test;
}

}  // namespace pathref::ml
