#include "pathref/ml/forest.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <utility>

#include "pathref/core/error.hpp"
#include "pathref/rng/draws.hpp"

namespace pathref::ml {

double gini(std::span<const double> counts) {
  require(!counts.empty(), "gini: no classes");
  double n = 0.0;
  for (const double c : counts) {
    require(std::isfinite(c) && c >= 0.0, "gini: counts must be finite and >= 0");
    n += c;
  }
  require(n > 0.0, "gini: the counts sum to 0");
  double s = 0.0;
  for (const double c : counts) {
    const double p = c / n;
    s += p * p;
  }
  return 1.0 - s;
}

SplitScore split_score(std::span<const std::int64_t> left, std::span<const std::int64_t> right) {
  require(left.size() == right.size() && !left.empty(), "split_score: equal class counts >= 1");
  __extension__ using I = __int128;
  I nl = 0, nr = 0, sl = 0, sr = 0;
  for (std::size_t c = 0; c < left.size(); ++c) {
    require(left[c] >= 0 && right[c] >= 0, "split_score: counts must be >= 0");
    nl += left[c];
    nr += right[c];
    sl += static_cast<I>(left[c]) * left[c];
    sr += static_cast<I>(right[c]) * right[c];
  }
  require(nl > 0 && nr > 0, "split_score: both sides must be non-empty");
  return SplitScore{sl * nr + sr * nl, nl * nr};
}

int compare(const SplitScore& a, const SplitScore& b) {
  const auto l = a.num * b.den;
  const auto r = b.num * a.den;
  return l < r ? -1 : (l > r ? 1 : 0);
}

namespace {

struct Task {
  std::vector<std::size_t> rows;
  int parent = -1;
  bool is_left = false;
};

}  // namespace

Tree grow_tree(const Dataset& d, std::span<const std::int64_t> weights, const TreeParams& p,
               rng::Stream* stream) {
  const std::size_t n = d.rows();
  const std::size_t f = d.features;
  const std::size_t k = d.classes;
  require(n >= 1 && f >= 1 && k >= 1, "grow_tree: no training rows");
  require(weights.size() == n, "grow_tree: one weight per row");
  require(p.max_features <= f, "grow_tree: max_features must not exceed the features");
  require((stream != nullptr) == (p.max_features > 0),
          "grow_tree: a stream is needed exactly when max_features > 0");
  for (const int y : d.y) require(y >= 0 && static_cast<std::size_t>(y) < k, "grow_tree: label outside [0, classes)");
  for (const auto w : weights) require(w >= 0, "grow_tree: weights must be >= 0");
  for (const double v : d.x) require(std::isfinite(v), "grow_tree: non-finite feature value");

  Tree t;
  t.classes = k;
  t.features = f;
  std::vector<Task> stack;
  {
    Task root;
    for (std::size_t i = 0; i < n; ++i)
      if (weights[i] > 0) root.rows.push_back(i);
    require(!root.rows.empty(), "grow_tree: every weight is 0");
    stack.push_back(std::move(root));
  }
  std::vector<std::pair<double, std::size_t>> sorted;
  std::vector<std::int64_t> left(k), total(k), right(k);
  std::vector<std::size_t> pool;
  while (!stack.empty()) {
    Task task = std::move(stack.back());
    stack.pop_back();
    const int id = static_cast<int>(t.nodes.size());
    t.nodes.push_back(Tree::Node{});
    if (task.parent >= 0) {
      auto& par = t.nodes[static_cast<std::size_t>(task.parent)];
      (task.is_left ? par.left : par.right) = id;
    }
    std::fill(total.begin(), total.end(), 0);
    for (const std::size_t i : task.rows) total[static_cast<std::size_t>(d.y[i])] += weights[i];
    for (std::size_t c = 0; c < k; ++c) t.value.push_back(static_cast<double>(total[c]));
    std::size_t present = 0;
    for (std::size_t c = 0; c < k; ++c) if (total[c] > 0) ++present;
    if (present <= 1 || task.rows.size() < 2) continue;

    // candidate features
    std::vector<std::size_t> candidates;
    const auto constant = [&](std::size_t j) {
      const double v0 = d.x[task.rows.front() * f + j];
      for (const std::size_t i : task.rows)
        if (d.x[i * f + j] != v0) return false;
      return true;
    };
    if (p.max_features == 0) {
      for (std::size_t j = 0; j < f; ++j)
        if (!constant(j)) candidates.push_back(j);
    } else {
      pool.resize(f);
      std::iota(pool.begin(), pool.end(), std::size_t{0});
      while (!pool.empty() && candidates.size() < p.max_features) {
        const std::size_t r = rng::uniform_index(stream->next_double(), pool.size());
        const std::size_t j = pool[r];
        pool[r] = pool.back();
        pool.pop_back();
        if (!constant(j)) candidates.push_back(j);
      }
    }
    if (candidates.empty()) continue;

    bool have = false;
    bool tied = false;
    SplitScore best;
    int best_feature = -1;
    double best_threshold = 0.0;
    for (const std::size_t j : candidates) {
      // (value, row) pairs sorted by value then row: the order of equal values is irrelevant to
      // the splits (they lie between distinct values only) but fixed for reproducibility.
      sorted.clear();
      for (const std::size_t i : task.rows) sorted.emplace_back(d.x[i * f + j], i);
      std::sort(sorted.begin(), sorted.end());
      std::fill(left.begin(), left.end(), std::int64_t{0});
      for (std::size_t q = 1; q < sorted.size(); ++q) {
        left[static_cast<std::size_t>(d.y[sorted[q - 1].second])] += weights[sorted[q - 1].second];
        const double a = sorted[q - 1].first;
        const double b = sorted[q].first;
        if (!(a < b)) continue;
        for (std::size_t c = 0; c < k; ++c) right[c] = total[c] - left[c];
        const SplitScore s = split_score(left, right);
        const int cmp = have ? compare(s, best) : 1;
        if (cmp > 0) {
          have = true;
          tied = false;
          best = s;
          best_feature = static_cast<int>(j);
          double th = a / 2.0 + b / 2.0;
          if (th == b) th = a;
          best_threshold = th;
        } else if (cmp == 0) {
          tied = true;
        }
      }
    }
    if (!have) continue;
    if (tied) ++t.tied_splits;
    auto& node = t.nodes[static_cast<std::size_t>(id)];
    node.feature = best_feature;
    node.threshold = best_threshold;
    node.tied = tied;
    Task l, r;
    l.parent = r.parent = id;
    l.is_left = true;
    for (const std::size_t i : task.rows)
      (d.x[i * f + static_cast<std::size_t>(best_feature)] <= best_threshold ? l.rows : r.rows).push_back(i);
    stack.push_back(std::move(r));
    stack.push_back(std::move(l));
  }
  return t;
}

void validate(const Tree& t) {
  require(t.classes >= 1 && t.features >= 1, "tree: classes and features must be >= 1");
  require(!t.nodes.empty(), "tree: no nodes");
  require(t.value.size() == t.nodes.size() * t.classes, "tree: value must have nodes * classes entries");
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    const auto& nd = t.nodes[i];
    if (nd.feature < 0) {
      require(nd.feature == -1 && nd.left == -1 && nd.right == -1, "tree: a leaf has feature = left = right = -1");
      double s = 0.0;
      for (std::size_t c = 0; c < t.classes; ++c) {
        const double v = t.value[i * t.classes + c];
        require(std::isfinite(v) && v >= 0.0, "tree: counts must be finite and >= 0");
        s += v;
      }
      require(s > 0.0, "tree: a leaf must hold a positive count");
    } else {
      require(static_cast<std::size_t>(nd.feature) < t.features, "tree: feature out of range");
      require(std::isfinite(nd.threshold), "tree: non-finite threshold");
      require(nd.left > static_cast<int>(i) && nd.right > static_cast<int>(i) &&
                  static_cast<std::size_t>(nd.left) < t.nodes.size() &&
                  static_cast<std::size_t>(nd.right) < t.nodes.size(),
              "tree: children must come after their parent and be in range");
    }
  }
}

std::size_t leaf_of(const Tree& t, std::span<const double> x) {
  require(x.size() == t.features, "tree: the sample has the wrong number of features");
  std::size_t i = 0;
  for (std::size_t steps = 0; steps <= t.nodes.size(); ++steps) {
    const auto& nd = t.nodes[i];
    if (nd.feature < 0) return i;
    i = static_cast<std::size_t>(x[static_cast<std::size_t>(nd.feature)] <= nd.threshold ? nd.left : nd.right);
  }
  throw DomainError("tree: cycle");
}

bool passes_tied_split(const Tree& t, std::span<const double> x) {
  require(x.size() == t.features, "tree: the sample has the wrong number of features");
  std::size_t i = 0;
  for (std::size_t steps = 0; steps <= t.nodes.size(); ++steps) {
    const auto& nd = t.nodes[i];
    if (nd.feature < 0) return false;
    if (nd.tied) return true;
    i = static_cast<std::size_t>(x[static_cast<std::size_t>(nd.feature)] <= nd.threshold ? nd.left : nd.right);
  }
  throw DomainError("tree: cycle");
}

int predict(const Tree& t, std::span<const double> x) {
  const std::size_t leaf = leaf_of(t, x);
  const double* v = t.value.data() + leaf * t.classes;
  std::size_t best = 0;
  for (std::size_t c = 1; c < t.classes; ++c)
    if (v[c] > v[best]) best = c;
  return static_cast<int>(best);
}

ForestVote parse_forest_vote(std::string_view name) {
  if (name == "majority") return ForestVote::majority;
  if (name == "mean-proba") return ForestVote::mean_proba;
  throw UsageError("unknown forest vote '" + std::string(name) + "' (majority, mean-proba)");
}

std::string_view to_string(ForestVote v) noexcept {
  return v == ForestVote::majority ? "majority" : "mean-proba";
}

Forest grow_forest(const Dataset& d, const ForestParams& p, rng::Stream& stream) {
  require(p.trees >= 1, "forest: trees must be >= 1");
  require(d.rows() >= 1 && d.features >= 1, "forest: no training rows");
  require(p.max_features <= d.features, "forest: max_features must not exceed the features");
  Forest forest;
  forest.params = p;
  if (forest.params.max_features == 0)
    forest.params.max_features =
        std::max<std::size_t>(1, static_cast<std::size_t>(std::sqrt(static_cast<double>(d.features))));
  const std::size_t n = d.rows();
  std::vector<std::int64_t> w(n, 1);
  for (std::size_t t = 0; t < p.trees; ++t) {
    if (p.bootstrap) {
      std::fill(w.begin(), w.end(), std::int64_t{0});
      for (std::size_t i = 0; i < n; ++i) ++w[rng::uniform_index(stream.next_double(), n)];
    }
    forest.trees.push_back(grow_tree(d, w, TreeParams{forest.params.max_features}, &stream));
  }
  return forest;
}

int combine_votes(std::span<const double> leaf_counts, std::size_t classes, ForestVote vote) {
  require(classes >= 1 && !leaf_counts.empty() && leaf_counts.size() % classes == 0,
          "combine_votes: trees * classes counts");
  const std::size_t trees = leaf_counts.size() / classes;
  std::vector<double> acc(classes, 0.0);
  for (std::size_t t = 0; t < trees; ++t) {
    const double* v = leaf_counts.data() + t * classes;
    double s = 0.0;
    std::size_t best = 0;
    for (std::size_t c = 0; c < classes; ++c) {
      require(std::isfinite(v[c]) && v[c] >= 0.0, "combine_votes: counts must be finite and >= 0");
      s += v[c];
      if (v[c] > v[best]) best = c;
    }
    require(s > 0.0, "combine_votes: a tree's counts sum to 0");
    if (vote == ForestVote::majority) {
      acc[best] += 1.0;
    } else {
      for (std::size_t c = 0; c < classes; ++c) acc[c] += v[c] / s;
    }
  }
  std::size_t best = 0;
  for (std::size_t c = 1; c < classes; ++c)
    if (acc[c] > acc[best]) best = c;
  return static_cast<int>(best);
}

int predict(const Forest& f, std::span<const double> x) {
  require(!f.trees.empty(), "forest: no trees");
  const std::size_t k = f.trees.front().classes;
  std::vector<double> counts;
  counts.reserve(f.trees.size() * k);
  for (const Tree& t : f.trees) {
    const std::size_t leaf = leaf_of(t, x);
    counts.insert(counts.end(), t.value.begin() + static_cast<std::ptrdiff_t>(leaf * k),
                  t.value.begin() + static_cast<std::ptrdiff_t>((leaf + 1) * k));
  }
  return combine_votes(counts, k, f.params.vote);
}

}  // namespace pathref::ml
